# output.sh - how results go out, on every command: the table format rounds each quantity to its
# meaningful digits (x, y 5 decimals; CCT 0.1 K; Duv 1e-5; CRI and TM-30 0.1; lx, cd, lm 4
# significant digits; U0 3 decimals) while csv, tsv and json keep every digit; --precision N;
# --units imperial (fc, ft, fL) and unit lists; write errors (a full disk, a closed stdout)
# reported with the system's reason and exit 3, nothing half-written; one style of "unknown
# option" for every command; "--distance 2 m" as two arguments; echoed inputs as given.
. tests/cli/lib.sh

# ---- the table format: the digits of each quantity ----
run spd --metrics cri,tm30 samples/spd/cie_illuminants.csv
expect_rc 0 "spd table"
expect_out_match '^x +0\.44758$' "x to 5 decimals (A: 0.447576)"
expect_out_match '^y +0\.40745$' "y to 5 decimals"
expect_out_match '^cct_K +2855\.[0-9] K$' "CCT to 0.1 K"
expect_out_match '^duv +-?0\.0000[0-9]$' "Duv to 1e-5"
expect_out_match '^cri_ra +100\.0$' "CRI to 0.1"
expect_out_match '^tm30_rf +[0-9]+\.[0-9]$' "TM-30 to 0.1"
run spd --format csv --metrics cri samples/spd/cie_illuminants.csv
expect_out_match '^samples/spd/cie_illuminants.csv,A,[0-9.]+,[0-9.]+,[0-9.]+,0\.447[0-9]{10,},' "csv keeps every digit"
run point --flux 1000lm --distance 2m --angle 30deg
# E = 1000 / (4 pi) cos 30 / 4 = 17.229027981931 lx; I = 79.5774715 cd
expect_out_match '^illuminance_lx +17\.23 lx$' "lux to 4 significant digits"
expect_out_match '^intensity_cd +79\.58 cd$' "candela to 4 significant digits"
expect_out_match '^angle_deg +30 deg$' "the echoed angle as given"
run solve --illuminance 300lx --distance 3m --beam-angle 30deg --format csv
expect_out_match ',30$' "solve echoes --beam-angle 30deg as 30, not 29.999999999999996"
# ratios, UGR, areas and percentages (README "Tables"): reflectance 0.200, not 0.200000; UGR to 0.1;
# an area to 1e-3 without padding; a uniformity that is not zero never prints as 0.000
run scene --surfaces samples/scenes/office_room.scene
expect_out_match '^reflectance +0\.200$' "reflectance to 3 decimals"
expect_out_match '^area_m2 +24 m2$' "an area to 1e-3, trailing zeros dropped (24, not 24.0000)"
cat >"$T/glare.scene" <<'SC'
[luminaire p1]
type = rect
position = 0, 3, 2.8 m
luminance = 4000 cd/m2
width = 0.6 m
length = 0.6 m
[receiver r]
type = point
position = 0, 0, 0 m
[observer eye]
position = 0, 0, 1.2 m
view = 0, 1, 0
background_luminance = 30 cd/m2
SC
run scene "$T/glare.scene" --glare
expect_out_match '^ugr +18\.5$' "UGR to 0.1 (18.549)"
expect_out_match '^position_index +3\.063$' "the position index to 3 decimals"
expect_out_match '^solid_angle_sr +0\.01465 sr$' "a solid angle to 4 significant digits"
run grid --ies samples/ies/spot_warn_30deg_800lm.ies --at 0,0,3 --plane z=0 --area 0:10,0:10 --spacing 1 --summary --format table
expect_out_match '^uniformity_u0 +[1-9]\.[0-9]e-[0-9]+$' "a tiny U0 keeps 2 significant digits, not 0.000"
if printf '%s\n' "$out" | grep -q ' 0\.000$'; then notok "no ratio printed as 0.000" "$out"; else ok "no ratio printed as 0.000"; fi
run point --flux 1000lm --distance 2m --angle 30deg --precision 7
expect_out_match '^illuminance_lx +17\.22903 lx$' "--precision 7"
run point --flux 1000lm --distance 2m --angle 30deg --precision 0
expect_rc 1 "--precision 0 is a usage error"
run point --flux 1000lm --distance 2m --angle 30deg --format json
expect_out_match '"angle_deg": 30[,}]' "json echoes 30, not 29.999999999999996"
expect_out_match '"illuminance_lx": 17.229027981931004' "json keeps every digit"
run point --flux 1000lm --distance 2m --format tsv
if [ "$(printf '%s\n' "$out" | head -n 1)" = "$(printf 'flux_lm\tintensity_cd\tilluminance_lx\tdistance_m\tangle_deg')" ]; then ok "tsv header"
else notok "tsv header" "$out"; fi
expect_out_match "$(printf '^1000\t79.57747154594767\t')" "tsv keeps every digit"

# ---- --units: imperial output, unit lists, feet in ----
run point --flux 1000lm --distance 2m --angle 30deg --units imperial --format csv
expect_out_match '^flux_lm,intensity_cd,illuminance_fc,distance_ft,angle_deg$' "imperial names: _fc, _ft"
# 17.229028 lx x 0.09290304 = 1.6006291 fc; 2 m / 0.3048 = 6.5616798 ft
expect_field 1 illuminance_fc 1.6006290757664554 1e-12 "lx in fc"
expect_field 1 distance_ft 6.561679790026246 1e-12 "m in ft"
run point --flux 1000lm --distance 6.561679790026246ft --units imperial
expect_out_match '^distance_ft +6\.562 ft$' "feet in, feet out"
run luminance-map samples/envmaps/furnace.exr --units imperial
# furnace: radiance 1 W/(sr m2) x 179 lm/W = 179 cd/m2 = 179 x 0.3048^2 pi fL = 52.24 fL
expect_out_match '^mean +52\.24 fL$' "luminance in fL"
run luminance-map samples/envmaps/furnace.exr --units imperial,cd/ft2
expect_out_match '^mean +16\.63 cd/ft2$' "a unit list: luminance in cd/ft2 (179 x 0.3048^2)"
run luminance-map samples/envmaps/furnace.exr --units luminance
expect_rc 0 "a command's own --units (luminance-map: auto|radiance|luminance) still works"

# ---- "--distance 2 m" as two arguments, as the documentation writes it ----
run point --flux 1000 lm --distance 2 m --angle 30 deg --format csv
expect_field 1 illuminance_lx 17.229027981931004 1e-12 "--distance 2 m with a space"

# ---- write errors: exit 3 with the system's reason, nothing half-written ----
if [ -w /dev/full ]; then
  run point --flux 1000lm -o /dev/full
  expect_rc 3 "-o /dev/full: exit 3"
  expect_err_match '^luxcalc: point: /dev/full: No space left on device$' "-o /dev/full: the reason"
  if [ -c /dev/full ]; then ok "/dev/full stays a device"; else notok "/dev/full stays a device" "replaced"; fi
  "$LUXCALC" spd samples/spd/cie_illuminants.csv >/dev/full 2>"$T/err"; rc=$?; err=$(cat "$T/err")
  expect_rc 3 "stdout on a full disk: exit 3"
  expect_err_match '^luxcalc: spd: stdout: No space left on device$' "stdout full: the reason"
  "$LUXCALC" grid --ies samples/ies/point_isotropic_1000lm.ies --at 0,0,2 --plane z=0 --area 0:1,0:1 --spacing 0.5 \
    --png /dev/full --summary >"$T/out" 2>"$T/err"; rc=$?; err=$(cat "$T/err")
  expect_rc 3 "--png /dev/full: exit 3"
  expect_err_match 'grid: /dev/full: No space left on device' "--png on a full disk: the reason"
else
  skip "write errors on /dev/full" "no writable /dev/full"
fi
"$LUXCALC" point --flux 1000lm >&- 2>"$T/err"; rc=$?; err=$(cat "$T/err")
expect_rc 3 "a closed stdout: exit 3"
expect_err_match '^luxcalc: point: stdout: Bad file descriptor$' "a closed stdout: the reason"
"$LUXCALC" grid --ies samples/ies/point_isotropic_1000lm.ies --at 0,0,2 --plane z=0 --area 0:1,0:1 --spacing 0.5 \
  --png "$T/c.png" >&- 2>"$T/err"; rc=$?
expect_rc 3 "a closed stdout while a PNG is written: exit 3"
if [ "$(head -c 4 "$T/c.png" | od -An -c | tr -d ' ')" = '211PNG' ]; then ok "the PNG is not mixed with the results"
else notok "the PNG is not mixed with the results" "$(head -c 16 "$T/c.png" | od -c | head -2)"; fi
if [ -w /dev/full ]; then
  # an existing output is replaced only on success
  ln -sf /dev/full "$T/full"
  run point --flux 1000lm -o "$T/full"
  expect_rc 3 "-o through a link to /dev/full: exit 3"
fi

# ---- unknown options: one style everywhere ----
for c in spd blackbody daylight point spot disk rect convert solve ies grid irradiance luminance-map scene devices bench sky ugr; do
  "$LUXCALC" $c --bogus >"$T/out" 2>"$T/err"; rc=$?
  if [ "$rc" -eq 1 ] && [ "$(cat "$T/err")" = "luxcalc: $c: unknown option '--bogus' (see luxcalc $c --help)" ]; then ok "$c: unknown option"
  else notok "$c: unknown option" "exit $rc: $(cat "$T/err")"; fi
done
run grid --ies
expect_rc 1 "an option without its value"
expect_err_match "^luxcalc: grid: option '--ies' needs a value \(see luxcalc grid --help\)$" "a missing value: one line"

# ---- -v logs the backend decision of auto (the measured break-even, src/core/backend.c) ----
if [ -n "${LX_BACKEND:-}" ] && [ "$LX_BACKEND" != auto ]; then
  skip "-v shows auto's backend decision" "LX_BACKEND=$LX_BACKEND decides before auto does"
else
  run -v grid --ies samples/ies/point_isotropic_1000lm.ies --at 0,0,3 --plane z=0 --area -1:1,-1:1 --points 4x4 --interp table --backend auto --format csv
  expect_rc 0 "grid -v: runs"
  expect_err_match "^luxcalc: grid: info: grid: backend auto: .*(break-even|no OpenCL|a CPU|unavailable)" "-v shows auto's backend decision"
fi
