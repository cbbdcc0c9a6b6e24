# daylight.sh - CLI cases for `luxcalc sky`, daylight scenes ([sky] cie/perez, [sun]), UGR at
# observers (`scene --glare`) and `luxcalc ugr`.
. tests/cli/lib.sh
PI=3.141592653589793

# a uniform CIE sky (type 5) written as EXR: the map's horizontal illuminance is pi Lz
run sky --type cie --number 5 --zenith-luminance 1000cd/m2 --sun-altitude 30deg --sun-azimuth 180deg \
    --size 256x128 -o "$T/s5.exr" --format csv
expect_rc 0 "sky type 5 writes an EXR"
expect_field 1 diffuse_horizontal_lx 3141.592653589793 1e-6 "type 5: Dv = pi Lz"
run irradiance "$T/s5.exr" --normal 0,0,1 --method fast --format csv
expect_field 1 illuminance_lx 3141.5927 0.05 "irradiance reads the sky map as luminance: E = pi Lz"
run irradiance "$T/s5.exr" --normal 1,0,0 --method fast --format csv
expect_field 1 illuminance_lx 1570.796 2 "vertical under the uniform sky: pi Lz / 2 (pixels cut by the horizon of n)"

# the CIE clear sky with the sun by date (SPA): the map carries the sky and the sun
run sky --type cie --number 12 --zenith-luminance 6000cd/m2 --date 2003-10-17 --time 12:30:30 --timezone -7 \
    --latitude 39.742476deg --longitude -105.1786deg --sun-illuminance 80000lx --size 512x256 -o "$T/s12.exr" --format csv
expect_rc 0 "sky type 12 with the sun by date"
expect_field 1 sun_altitude_deg 39.888 0.01 "SPA sun altitude (90 - 50.112 at 1013 mbar / 15 C)"
eg=$(printf '%s\n' "$out" | awk -F, 'NR==2{print $7}')
run irradiance "$T/s12.exr" --normal 0,0,1 --method fast --format csv
expect_field 1 illuminance_lx "$eg" "$(awk -v e="$eg" 'BEGIN{print e*2e-3}')" "map E_h = Dv + Evn sin(altitude) within 0.2 %"

# Perez from irradiance
run sky --type perez --direct-normal 600W/m2 --diffuse-horizontal 150W/m2 --sun-altitude 35deg --sun-azimuth 180deg \
    --day-of-year 172 --format csv
expect_rc 0 "perez sky"
expect_field 1 diffuse_horizontal_lx 21022.329669493913 1e-6 "perez Dv (tests/ref/perez_ref.py)"
expect_field 1 sun_normal_lx 58156.639908585057 1e-6 "perez Evn (tests/ref/perez_ref.py)"
run sky --type cie --number 12 --zenith-luminance 1000cd/m2
expect_rc 1 "no sun is a usage error"
run sky --type cie --number 16 --zenith-luminance 1000cd/m2 --sun-altitude 30deg --sun-azimuth 0deg
expect_rc 2 "sky number 16 is refused (a value out of range: exit 2)"
expect_err_match '^luxcalc: sky: --number: 16 is out of range \(1 to 15\)$' "sky number 16: the range"
run sky --type cie --number twelve --zenith-luminance 1000cd/m2 --sun-altitude 30deg --sun-azimuth 0deg
expect_rc 1 "sky number 'twelve' is a usage error"
# values out of range are refused with exit 2 (README "Exit status"), never computed as another value:
# 2003-02-30 was taken as 2003-03-02, a 95 deg sun as an 85 deg one on the other side
SITE="--date 2003-10-17 --time 12:30 --timezone -7 --latitude 39.74deg --longitude -105.18deg"
for bad in "--latitude 91deg|latitude" "--time 25:61|hour" "--timezone 99|timezone" "--date 2003-02-30|day 30 out of range \\(2003-02 has 28 days\\)"; do
  opt=${bad%%|*}; what=${bad#*|}
  # shellcheck disable=SC2086
  run sky --type cie --number 12 --zenith-luminance 6000cd/m2 --size 16x8 $SITE $opt
  expect_rc 2 "sky $opt: exit 2"
  expect_err_match "^luxcalc: sky: sun position: $what" "sky $opt: names what is out of range"
done
run sky --type cie --number 12 --zenith-luminance 6000cd/m2 --size 16x8 --sun-altitude 95deg --sun-azimuth 180deg
expect_rc 2 "sky --sun-altitude 95deg: exit 2"
expect_err_match '^luxcalc: sky: --sun-altitude: 95deg is out of range \(-90 to 90 deg\)$' "sky --sun-altitude 95deg says the range"
run sky --type cie --number 12 --zenith-luminance 6000cd/m2 --size 16x8 --sun-altitude 90deg --sun-azimuth 180deg --format csv
expect_rc 0 "sky --sun-altitude 90deg: the zenith is in range"

# a scene: CIE sky 12 and the sun; the sun on a south-facing wall adds Evn cos
cat > "$T/day.scene" <<'SC'
[sky]
type = cie
number = 12
luminance = 6000 cd/m2
[sun]
altitude = 30 deg
azimuth = 180 deg
illuminance = 80000 lx
[receiver roof]
type = point
position = 0, 0, 0 m
[receiver south]
type = point
position = 0, 0, 0 m
normal = 0, -1, 0
[receiver north]
type = point
position = 0, 0, 0 m
normal = 0, 1, 0
SC
run scene "$T/day.scene" --format csv
expect_rc 0 "daylight scene"
run sky --type cie --number 12 --zenith-luminance 6000cd/m2 --sun-altitude 30deg --sun-azimuth 180deg --format csv
dv=$(printf '%s\n' "$out" | awk -F, 'NR==2{print $5}')
run scene "$T/day.scene" --format csv
expect_field 1 illuminance_lx "$(awk -v d="$dv" 'BEGIN{printf "%.17g", d + 40000}')" 1e-6 "roof: Dv + Evn sin 30"
s=$(printf '%s\n' "$out" | awk -F, 'NR==3{print $5}'); n=$(printf '%s\n' "$out" | awk -F, 'NR==4{print $5}')
if awk -v s="$s" -v n="$n" -v dv="$dv" 'BEGIN{d=s-n-80000*cos(3.141592653589793/6); exit !(d > 0 && d < dv)}'; then
  ok "south wall gets the sun (Evn cos 30) and the brighter half of the sky"
else notok "south wall gets the sun" "south $s north $n"; fi
run scene "$T/day.scene" --explain
expect_out_match 'environment +on +CIE general \(type 12\) sky and the sun' "explain names the sky and the sun"

# errors name the file and line
printf '[sky]\ntype = cie\nluminance = 100 cd/m2\n[receiver r]\ntype = point\nposition = 0,0,0 m\n' > "$T/bad1.scene"
run scene "$T/bad1.scene"
expect_rc 2 "cie sky without number"
expect_err_match "bad1.scene:1: \[sky\]: a cie sky needs 'number'" "names [sky]'s line"
printf '[sky]\ntype = cie\nnumber = 12\nluminance = 100 cd/m2\n[receiver r]\ntype = point\nposition = 0,0,0 m\n' > "$T/bad2.scene"
run scene "$T/bad2.scene"
expect_err_match "depends on the sun's position" "sun-dependent type without [sun]"
printf '[sun]\ndate = 2024-13-01\ntime = 12:00\ntimezone = 1\nlatitude = 50 deg\nlongitude = 8 deg\nilluminance = 1 lx\n[receiver r]\ntype = point\nposition = 0,0,0 m\n' > "$T/bad3.scene"
run scene "$T/bad3.scene"
expect_rc 2 "a bad date"
expect_err_match "bad3.scene:1: \[sun\]: sun position: month" "names the field"

# UGR at an observer
cat > "$T/glare.scene" <<'SC'
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
run scene "$T/glare.scene" --glare --format csv
expect_rc 0 "scene --glare"
expect_out_match '^observer,luminaire,luminance_cd_m2,solid_angle_sr,sigma_deg,tau_deg,position_index,term,background_cd_m2,ugr' "glare csv header"
# by hand: d^2 = 9 + 2.56, omega = 0.36 (1.6 / d) / d^2, sigma = acos(3 / d), tau = 0
expect_field 1 solid_angle_sr "$(awk 'BEGIN{d2=11.56; d=sqrt(d2); printf "%.17g", 0.36*1.6/d/d2}')" 1e-12 "omega = A cos / d^2"
expect_field 1 ugr "$(awk 'BEGIN{d2=11.56; d=sqrt(d2); w=0.36*1.6/d/d2; s=atan2(1.6,3)*180/3.141592653589793;
  p=exp((35.2-1.22)*1e-3*s + 21e-5*s*s); printf "%.17g", 8*log(0.25/30*16e6*w/(p*p))/log(10)}')" 1e-9 "UGR by hand"

# luxcalc ugr on a real EULUMDAT file (../shared; skipped when absent)
if [ -f "${LX_SHARED_DIR:-../shared}/ies/ldt/avad_srl_isym4.ldt" ]; then
  run ugr "${LX_SHARED_DIR:-../shared}/ies/ldt/avad_srl_isym4.ldt" --format csv
  expect_rc 0 "ugr table"
  expect_out_match '^x_H,y_H,cross_70_50_20,' "ugr csv header"
  expect_field 11 cross_70_50_20 20.6 0.3 "4H x 8H, 70/50/20 crosswise (eulumdat-ugr 1.0.2: 20.6)"
  rows=$(printf '%s\n' "$out" | wc -l)
  if [ "$rows" -eq 20 ]; then ok "19 rooms"; else notok "19 rooms" "$rows lines"; fi
else
  skip "ugr table" "../shared/ies/ldt not present"
fi
run ugr
expect_rc 1 "ugr without a file"
# the table format: the matrix of data sheets (CIE 190:2010 Table 2 layout); every cell the csv's
# value to one decimal, in the csv's order (rooms down, crosswise then endwise across)
run ugr samples/ies/downlight_lambert_1000lm.ies --format csv
expect_rc 0 "ugr csv, sample downlight"
printf '%s\n' "$out" | awk -F, 'NR > 1 { for (i = 3; i <= 12; i++) printf "%.1f ", $i + 0; print "" }' >"$T/ugr_csv"
run ugr samples/ies/downlight_lambert_1000lm.ies
expect_rc 0 "ugr matrix"
expect_out_match '^  ceiling +0\.70 +0\.70 +0\.50 +0\.50 +0\.30 +0\.70 +0\.70 +0\.50 +0\.50 +0\.30$' "reflectances over the ten columns"
expect_out_match '^  floor cavity +0\.20( +0\.20){9}$' "floor cavity line"
expect_out_match '^room size +X +Y +viewed crosswise +viewed endwise$' "column heads"
expect_out_match '^ +2H +2H( +[0-9]+\.[0-9]){10}$' "first room: X and Y, ten values to one decimal"
expect_out_match '^ +12H +4H( +[0-9]+\.[0-9]){10}$' "12H group starts with its X"
printf '%s\n' "$out" | awk '/^ +[0-9]+H/ && NF >= 11 { for (i = NF - 9; i <= NF; i++) printf "%s ", $i; print "" }' >"$T/ugr_tab"
if [ "$(wc -l <"$T/ugr_tab")" -eq 19 ] && cmp -s "$T/ugr_csv" "$T/ugr_tab"; then ok "19 room lines, each cell the csv value rounded"
else notok "19 room lines, each cell the csv value rounded" "$(diff "$T/ugr_csv" "$T/ugr_tab" | head -4)"; fi
if printf '%s\n' "$out" | grep -q '0000'; then notok "no long-form padding" "$out"; else ok "no long-form padding (26.7000)"; fi

# openings (issue 21 part B): a 1 x 1 m roof opening at the centre of a 4 x 4 x 3 m room's ceiling
cat > "$T/roof.scene" <<'SC'
[scene]
patch_size = 0.6 m
[room r]
size = 4, 4, 3 m
[opening R]
corner = 1.5, 1.5, 3 m
edge1 = 1, 0, 0 m
edge2 = 0, 1, 0 m
[sky]
type = overcast
luminance = 1000 cd/m2
[receiver c]
type = point
position = 2, 2, 0 m
SC
run scene "$T/roof.scene" --format csv
expect_rc 0 "scene with an opening"
expect_out_match '^receiver,x,y,z,illuminance_lx,direct_lx,indirect_lx,daylight_lx,daylight_factor,sky_component,externally_reflected,internally_reflected$' "daylight columns"
# the overcast sky under a centred square roof light (tests/ref/daylight_ref.py: 0.1065100376709822 Lz)
expect_field 1 sky_component "$(awk -v p=$PI 'BEGIN{printf "%.17g", 100*0.1065100376709822/(7*p/9)}')" 1e-10 "sky component: the overcast sky through a roof opening"
run scene "$T/roof.scene" --explain --format json
expect_out_match '"daylight": true' "explain: daylight on"
expect_out_match '"environment": false' "explain: the sky reaches the room through the opening only"
expect_out_match '"daylight": \{"daylight_factor": true, "closed_form": true' "explain: the daylight block"
run scene "$T/roof.scene" --explain
expect_out_match 'daylight +on +traditional CIE overcast sky' "explain text: the daylight reason"
sed 's/^corner = 1.5, 1.5, 3 m/corner = 1.5, 1.5, 2.5 m/' "$T/roof.scene" >"$T/bad_open.scene"
run scene "$T/bad_open.scene"
expect_rc 2 "an opening off every face"
expect_err_match "bad_open.scene:5: opening 'R' is not on a face of a room" "names the opening's line"
# UGR's background from the room when the observer has none: Lb = E_ind / pi
cat > "$T/glare_room.scene" <<'SC'
[scene]
patch_size = 0.5 m
[room r]
size = 6, 4, 3 m
[luminaire panel]
type = rect
position = 4, 2, 2.95 m
luminance = 6000 cd/m2
width = 0.6 m
length = 0.6 m
[observer eye]
position = 0.5, 2, 1.2 m
view = 1, 0, 0
[receiver eye]
type = point
position = 0.5, 2, 1.2 m
normal = 1, 0, 0
SC
run scene "$T/glare_room.scene" --format csv
eind=$(printf '%s\n' "$out" | awk -F, 'NR==2{print $7}')
run scene "$T/glare_room.scene" --glare --format csv
expect_rc 0 "glare with the background from the room"
expect_field 1 background_cd_m2 "$(awk -v e="$eind" -v p=$PI 'BEGIN{printf "%.17g", e/p}')" 1e-9 "Lb = E_ind / pi at the eye"
run bench --help
expect_out_match 'daylight' "bench lists the daylight topic"

# scene --png: the plan drawn on the plots (walls, the window, the desk, the partition) and, where
# the scene defines the daylight factor, its own plot DIR/SCENE_RECEIVER_df.png; pixels read back
# with tests/tools/pngpx (the colours of lx_outline_kind in luxcalc.h)
cat > "$T/side.scene" <<'SC'
[room office]
size = 6, 4, 3 m
[opening window]
corner = 1, 0, 0.9 m
edge1 = 2, 0, 0 m
edge2 = 0, 0, 1.5 m
glazing = clear
[obstruction desk]
min = 3, 2, 0 m
max = 4.6, 2.8, 0.72 m
reflectance = 0.3
[surface partition]
corner = 5, 0.5, 0 m
edge1 = 0, 1.5, 0 m
edge2 = 0, 0, 1.6 m
reflectance = 0.4
[sky]
type = overcast
luminance = 10000 cd/m2
[receiver wp]
type = grid
x = 0.5 m, 5.5 m
y = 0.5 m, 3.5 m
z = 0.85 m
spacing = 0.5 m
[effects]
interreflection = off
SC
px=${LX_BUILD_DIR:-build}/tests/pngpx
run scene "$T/side.scene" --png "$T/plans"
expect_rc 0 "scene --png with daylight"
expect_err_match "wrote .*/side_wp_df\.png" "the daylight-factor plot is written and named"
if [ -x "$px" ] && [ -f "$T/plans/side_wp.png" ] && [ -f "$T/plans/side_wp_df.png" ]; then
  for f in side_wp side_wp_df; do
    wall=$("$px" "$T/plans/$f.png" box 37373e 2); win=$("$px" "$T/plans/$f.png" box 96d7fa 2)
    part=$("$px" "$T/plans/$f.png" box 7a4a1e 2)
    set -- $wall; wx0=${1:-0}; wy0=${2:-0}; wx1=${3:-0}; wy1=${4:-0}; wn=${5:-0}
    set -- $win; nx0=${1:-0}; ny1=${4:-0}; nn=${5:-0}
    set -- $part; pn=${5:-0}
    if [ "$wn" -gt 1000 ] && [ $((wx1 - wx0)) -gt 400 ] && [ $((wy1 - wy0)) -gt 200 ]; then ok "$f: the walls drawn around the room"
    else notok "$f: walls" "wall colour box '$wall'"; fi
    # the window: in the south wall (the bottom edge of the room, y = 0), from x = 1 m to 3 m
    if [ "$nn" -gt 100 ] && [ $((wy1 - ny1)) -le 4 ] && [ "$nx0" -gt "$wx0" ]; then ok "$f: the window on the south wall"
    else notok "$f: window" "window box '$win', walls '$wall'"; fi
    if [ "$pn" -gt 50 ]; then ok "$f: the partition drawn"; else notok "$f: partition" "'$part'"; fi
  done
else
  skip "plan pixels" "no $px or no plots"
fi
run scene samples/scenes/office.scene --png "$T/plans2"
if [ -f "$T/plans2/office_desk.png" ] && [ ! -e "$T/plans2/office_desk_df.png" ]; then ok "no daylight-factor plot without daylight"
else notok "no df plot without daylight" "$(ls "$T/plans2")"; fi

# luminance-map of a sky with the sun: the range is the sky's, the sun disc above it in the top
# colour (red), so the sky spans the palette (green and yellow in it, not all blue); --range
# puts everything back in
run sky --type cie --number 12 --zenith-luminance 6000cd/m2 --sun-altitude 40deg --sun-azimuth 180deg \
  --sun-illuminance 80000lx --size 512x256 -o "$T/sunsky.exr"
expect_rc 0 "a sky with the sun"
run luminance-map "$T/sunsky.exr" --png "$T/sunsky.png"
expect_rc 0 "luminance-map of the sky with the sun"
if [ -x "$px" ] && [ -f "$T/sunsky.png" ]; then
  green=$("$px" "$T/sunsky.png" count 26cc26 40 0 0 530 400); red=$("$px" "$T/sunsky.png" count d9000d 10 0 0 530 400)
  if [ "$green" -gt 3000 ]; then ok "the sky spans the palette ($green green pixels)"; else notok "the sky spans the palette" "$green green pixels"; fi
  if [ "$red" -ge 1 ] && [ "$red" -le 20 ]; then ok "the sun disc in the top colour ($red pixels)"; else notok "the sun in the top colour" "$red red pixels"; fi
  run luminance-map "$T/sunsky.exr" --png "$T/sunsky_all.png" --range 1000:1e9
  green=$("$px" "$T/sunsky_all.png" count 26cc26 40 0 0 530 400)
  if [ "$green" -lt 3000 ]; then ok "--range 1000:1e9 keeps the sun in the range"; else notok "--range keeps the sun" "$green green pixels"; fi
else
  skip "sky false colour pixels" "no $px"
fi
