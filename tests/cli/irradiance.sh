# irradiance.sh - CLI cases for `luxcalc irradiance` and `luxcalc luminance-map` on the sample maps.
. tests/cli/lib.sh
M=samples/envmaps
PI=3.141592653589793

# furnace (radiance 1): E = pi for any normal, every method (the pixels the horizon crosses exact)
for m in sh9 brute fast auto; do
  run irradiance $M/furnace.exr --normal 0.3,-0.2,0.9 --method $m --format csv
  expect_rc 0 "furnace $m runs"
  expect_field 1 irradiance $PI 1e-12 "furnace $m: E = pi"
done
run irradiance $M/furnace.exr --normal 0,0,1 --format csv
expect_out_match '^nx,ny,nz,irradiance,illuminance_lx,method' "csv header"
expect_out_match ',fast(,|$)' "the default for one normal is the exact fast method"
expect_field 1 irradiance $PI 1e-12 "furnace exact by default"
# illuminance = 179 lm/W x E for radiance maps (Radiance white efficacy), or --efficacy
expect_field 1 illuminance_lx 562.34510 1e-4 "illuminance with 179 lm/W"
run irradiance $M/furnace.exr --normal 0,0,1 --efficacy 683 --format csv
expect_field 1 illuminance_lx 2145.7078 1e-3 "illuminance with --efficacy 683 (683 pi)"
# the case: a sun, a downward normal. fast 116.418 lx (brute the same); SH9 -23.7 lx, with
# warnings (negative; a dominant small source)
run irradiance $M/sky_sun.exr --normal 0,0,-1 --format csv
expect_field 1 illuminance_lx 116.41799374466669 1e-9 "sky_sun, normal down: 116.418 lx by default"
if [ -z "$err" ]; then ok "the exact default warns of nothing"; else notok "the exact default warns of nothing" "$err"; fi
run irradiance $M/sky_sun.exr --normal 0,0,-1 --method sh9 --format csv
expect_field 1 illuminance_lx -23.69501220398835 1e-6 "SH9 gives -23.7 lx there"
expect_err_match 'warning: SH9 gives a negative illuminance \(-23.695 lx\)' "SH9 warns of its negative result"
expect_err_match 'warning: SH9 is approximate and this map has a dominant small source: 70.6 % of its power is in 57 pixels' "SH9 warns of the sun: what fraction in how few pixels"
# a map output: auto takes SH9 when fast would cost more than 10 x as much, and says so (the
# furnace: SH9 is exact for a constant map, E = pi x 179 lm/W everywhere)
run irradiance $M/furnace.exr -o "$T/Eauto.exr"
expect_rc 0 "auto irradiance map written"
expect_err_match 'note: SH9 \(approximate\) for this map: the exact method \(--method fast\) would cost about [0-9]+ times as much' "auto says when it takes SH9"
run luminance-map "$T/Eauto.exr" --format csv
expect_field 1 min 562.34510064 1e-6 "auto's SH9 map of the furnace: 179 pi everywhere"
# ... but where SH9 goes negative (the sun rings: -25.6 lx at worst on this map) auto runs the exact
# method after all: the map's minimum is the exact 116.42 lx of the downward normal (fast = brute
# above), and no note or warning is printed
run irradiance $M/sky_sun.exr -o "$T/Eauto2.exr"
expect_rc 0 "auto irradiance map of sky_sun written"
if [ -z "$err" ]; then ok "auto on sky_sun: exact, no SH9 note"; else notok "auto on sky_sun: exact, no SH9 note" "$err"; fi
run luminance-map "$T/Eauto2.exr" --format csv
expect_field 1 min 116.4218 1e-4 "auto on sky_sun: no negative illuminance, the exact minimum"
# half-lit: E(+z) = pi, E(-z) = 0, E(+x) = pi/2 (pi (1 + n_z) / 2)
run irradiance $M/half_lit.exr --normal 1,0,0 --format csv
expect_field 1 irradiance 1.5707963267948966 1e-12 "half-lit E(+x) = pi/2"
run irradiance $M/half_lit.exr --normal 1,0,0 --method sh9 --format csv
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

# -o names OpenEXR output: a picture's name is refused (no EXR bytes in a .png); the preview has a
# legend (lx) and takes --scale; luminance-map on the irradiance map it wrote speaks of illuminance
run irradiance samples/envmaps/furnace.exr -o "$T/out.png"
expect_rc 1 "-o out.png is refused"
expect_err_match 'OUT is written as OpenEXR; name it .exr' "the refusal says why"
[ -e "$T/out.png" ] && notok "nothing written at out.png" "found" || ok "nothing written at out.png"
run irradiance samples/envmaps/furnace.exr -o "$T/E.exr" --png "$T/E.png" --scale linear
expect_rc 0 "irradiance --png --scale linear"
run irradiance samples/envmaps/furnace.exr -o "$T/E.exr" --png "$T/E.png" --scale cubic
expect_rc 1 "--scale takes log or linear"
run luminance-map "$T/E.exr" --format csv
expect_rc 0 "luminance-map of an irradiance map"
run luminance-map "$T/E.exr"
expect_out_match '^min +[0-9.e+-]+ lx$' "an irradiance map's statistics are illuminances (lx)"
run luminance-map samples/envmaps/furnace.exr
expect_out_match '^min +[0-9.e+-]+ cd/m2$' "a radiance map's are luminances (cd/m2)"
