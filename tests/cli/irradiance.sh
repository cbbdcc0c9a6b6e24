# irradiance.sh - CLI cases for `luxcalc irradiance` and `luxcalc luminance-map` on the sample maps.
. tests/cli/lib.sh
M=samples/envmaps
PI=3.141592653589793

# furnace (radiance 1): E = pi for any normal, every method
for m in sh9 brute fast; do
  run irradiance $M/furnace.exr --normal 0.3,-0.2,0.9 --method $m --format csv
  expect_rc 0 "furnace $m runs"
  expect_field 1 irradiance $PI 4e-3 "furnace $m: E = pi (O(dtheta^2) at 64x32 for brute/fast)"
done
run irradiance $M/furnace.exr --normal 0,0,1 --format csv
expect_out_match '^nx,ny,nz,irradiance,illuminance_lx,method' "csv header"
expect_field 1 irradiance $PI 1e-12 "furnace sh9 exact"
# illuminance = 179 lm/W x E for radiance maps (Radiance white efficacy), or --efficacy
expect_field 1 illuminance_lx 562.34510 1e-4 "illuminance with 179 lm/W"
run irradiance $M/furnace.exr --normal 0,0,1 --efficacy 683 --format csv
expect_field 1 illuminance_lx 2145.7078 1e-3 "illuminance with --efficacy 683 (683 pi)"
# half-lit: E(+z) = pi, E(-z) = 0, E(+x) = pi/2 (pi (1 + n_z) / 2)
run irradiance $M/half_lit.exr --normal 1,0,0 --format csv
expect_field 1 irradiance 1.5707963267948966 1e-12 "half-lit sh9 E(+x) = pi/2"
run irradiance $M/half_lit.exr --normal 0,0,-1 --method fast --format csv
expect_field 1 irradiance 0 1e-12 "half-lit fast E(-z) = 0"
run irradiance $M/half_lit.exr --normal 0,0,1 --method brute --backend cpu --format csv
expect_field 1 irradiance $PI 1e-9 "half-lit brute E(+z) = pi (no pixel straddles)"
# brute and fast agree on the sky with a sun
run irradiance $M/sky_sun.exr --normal 0.2,0.5,0.8 --method brute --backend cpu --format csv
eb=$(printf '%s\n' "$out" | awk -F, 'NR==2{print $4}')
run irradiance $M/sky_sun.exr --normal 0.2,0.5,0.8 --method fast --format csv
expect_field 1 irradiance "$eb" 1e-9 "fast = brute on sky_sun"
# maps: EXR out, PNG preview
run irradiance $M/sky_sun.exr -o "$T/E.exr" --png "$T/E.png" --size 32x16 --method fast
expect_rc 0 "irradiance map written"
if [ -s "$T/E.exr" ] && [ -s "$T/E.png" ]; then ok "EXR and PNG exist"; else notok "EXR and PNG exist" "missing"; fi
run luminance-map "$T/E.exr" --format csv
expect_field 1 width 32 0 "output has --size width"
run luminance-map $M/furnace.exr --format csv --png "$T/L.png"
expect_out_match '^min,max,mean,median' "luminance-map csv header"
expect_field 1 median 179 1e-9 "furnace luminance 179 cd/m2"
if [ -s "$T/L.png" ]; then ok "false-colour PNG exists"; else notok "false-colour PNG exists" "missing"; fi
# errors
run irradiance $M/nothere.exr --normal 0,0,1
expect_rc 2 "missing input: exit 2"
expect_err_match '^luxcalc: irradiance: .*nothere.exr' "error names the file"
run irradiance $M/furnace.exr
expect_rc 1 "no -o and no --normal: exit 1"
run irradiance $M/furnace.exr --normal 0,0
expect_rc 1 "bad --normal: exit 1"
run irradiance $M/furnace.exr --method magic --normal 0,0,1
expect_rc 1 "bad --method: exit 1"
printf 'not an exr' > "$T/bad.exr"
run luminance-map "$T/bad.exr"
expect_rc 2 "malformed EXR: exit 2"
run irradiance --help
expect_out_match 'example' "help has an example"
# cube maps: samples/envmaps/cube_px.exr is an 8 x 48 OpenEXR cube map (envmap cube), radiance 1 on
# the file's +X face and 0 elsewhere (written by lx_envmap_create_cube + lx_envmap_write_exr). The +X face
# looks towards luxcalc's +y (README "cube maps"): E(+y) = its projected solid angle sqrt(2) acos(1/3)
for m in brute fast; do
  run irradiance $M/cube_px.exr --normal 0,1,0 --method $m --format csv
  expect_field 1 irradiance 1.7408395027342065 1e-12 "cube +X face, $m: E(+y) = sqrt(2) acos(1/3)"
done
run irradiance $M/cube_px.exr --normal 0,-1,0 --method fast --format csv
expect_field 1 irradiance 0 1e-12 "cube +X face: E(-y) = 0"
run irradiance $M/cube_px.exr -o "$T/Ecube.exr"
expect_rc 0 "cube irradiance map written"
run luminance-map "$T/Ecube.exr" --format csv
expect_field 1 height 48 0 "output is a cube map of the same layout (8 x 48)"
run irradiance $M/cube_px.exr -o "$T/Ecube.exr" --size 16x8
expect_rc 1 "cube input with a non N x 6N --size: exit 1"
