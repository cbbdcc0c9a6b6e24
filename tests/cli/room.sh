# room.sh - CLI cases for rooms (CLI.md "Scenes: Rooms"): direct_lx and indirect_lx beside
# illuminance_lx, --surfaces, the occlusion and interreflection effects in --explain, errors with
# file and line. Reference values: closed forms named in each comment.
. tests/cli/lib.sh
S=$T/box.scene
# a closed 4 x 3 x 2.5 m room, reflectance 0.5 everywhere (S = 59 m2), an isotropic 1000 lm source:
# the area-weighted mean indirect illuminance over the faces is rho Phi / (S (1 - rho)) = 16.949152542 lx
cat >"$S" <<'EOF'
[scene]
interreflection_tolerance = 1e-4
patch_size = 0.5 m
[room box]
size = 4, 3, 2.5 m
ceiling = 0.5
walls = 0.5
floor = 0.5
[luminaire lamp]
type = point
position = 1.5, 1.2, 1.4 m
flux = 1000 lm
[receiver p]
type = point
position = 2.5 m, 1.5 m, 0.8 m
EOF
run scene "$S" --format csv
expect_rc 0 "room scene runs"
expect_out_match '^receiver,x,y,z,illuminance_lx,direct_lx,indirect_lx$' "csv: direct_lx and indirect_lx beside illuminance_lx"
# the direct part is the point law: 1000 / (4 pi) / d^2 cos, d^2 = 1.45, cos = 0.6 / sqrt(1.45)
expect_field 1 direct_lx 27.3457213 1e-6 "direct_lx: the inverse-square and cosine law"
t=$(printf '%s\n' "$out" | awk -F, 'NR==2{d=$5-($6+$7); if(d<0)d=-d; print (d<1e-9*$5)}')
[ "$t" = 1 ] && ok "illuminance_lx = direct_lx + indirect_lx" || notok "illuminance_lx = direct_lx + indirect_lx" "$out"
run scene "$S" --surfaces --format csv
expect_rc 0 "--surfaces runs"
expect_out_match '^surface,area_m2,direct_lx,indirect_lx,illuminance_lx,luminance_cd_m2,reflectance$' "--surfaces csv header (CLI.md)"
expect_out_match '^box\.floor,12(\.0*[0-9]*)?,' "the floor row with its area"
n=$(printf '%s\n' "$out" | tail -n +2 | wc -l)
[ "$n" -eq 6 ] && ok "one row per room face" || notok "one row per room face" "$n rows"
m=$(printf '%s\n' "$out" | awk -F, 'NR>1{a+=$2; s+=$2*$4} END{printf "%.9f", s/a}')
if awk -v m="$m" 'BEGIN{d=m-16.949152542; if(d<0)d=-d; exit !(d < 16.95e-4)}'; then ok "flux balance: mean indirect rho Phi / (S (1 - rho))"
else notok "flux balance: mean indirect rho Phi / (S (1 - rho))" "$m"; fi
run scene "$S" --surfaces --format json
expect_rc 0 "--surfaces json"
if command -v python3 >/dev/null 2>&1; then
  if printf '%s\n' "$out" | python3 -c 'import json,sys; d=json.load(sys.stdin); assert len(d) == 6 and d[0]["surface"] == "box.floor"'; then
    ok "--surfaces json parses"; else notok "--surfaces json parses" "$out"; fi
else
  skip "--surfaces json parses" "no python3"
fi
# --explain: the new effects and the solve's account
run scene "$S" --explain --format json
expect_rc 0 "explain json"
expect_out_match '"occlusion": false, "interreflection": true' "effects: occlusion off (nothing blocks inside a box), interreflection on"
expect_out_match '"interreflection": \{"patches": [0-9]+' "explain json: the solve's account"
run scene samples/scenes/office_room.scene --explain
expect_rc 0 "office_room explain"
expect_out_match '^  occlusion +on ' "office_room: occlusion on (a desk and a partition)"
expect_out_match '^  interreflection on ' "office_room: interreflection on"
expect_out_match '^  estimate +rho ' "explain prints the flux-balance estimate"
expect_out_match '^  measured +indirect share ' "explain prints the measured indirect share"
# forcing interreflection off gives the direct light only, and --surfaces then says why not
printf '[effects]\ninterreflection = off\n' >>"$S"
run scene "$S" --format csv
expect_out_match '^receiver,x,y,z,illuminance_lx$' "interreflection off: no direct/indirect columns"
expect_field 1 illuminance_lx 27.3457213 1e-6 "interreflection off: the direct light"
run scene "$S" --surfaces
expect_rc 2 "--surfaces without interreflection: input error"
expect_err_match 'interreflection is off' "--surfaces says why"
# errors name file and line
printf '[room r]\nsize = 4, 4, 3 m\nwalls = 1\n' >"$T/bad1.scene"
run scene "$T/bad1.scene"
expect_rc 2 "reflectance 1: input error"
expect_err_match "^luxcalc: scene: .*bad1.scene:3: walls: a reflectance must be at least 0 and below 1" "reflectance error names file and line"
printf '[room r]\nsize = 4, 4, 3 m\n[luminaire l]\ntype = point\nposition = 5, 1, 2 m\nflux = 1 lm\n[receiver p]\ntype = point\nposition = 1 m, 1 m, 1 m\n' >"$T/bad2.scene"
run scene "$T/bad2.scene"
expect_rc 2 "luminaire outside the room: input error"
expect_err_match "bad2.scene:3: luminaire 'l' at 5, 1, 2 m is outside every room" "outside-room error names file and line"
printf '[scene]\ninterreflection_tolerance = 1e-4\n[room r]\nsize = 10, 10, 3 m\n[luminaire l]\ntype = point\nposition = 1, 1, 2 m\nflux = 1 lm\n[receiver p]\ntype = point\nposition = 1 m, 1 m, 1 m\n' >"$T/bad3.scene"
export LX_ROOM_MEMORY_MB=1
run scene "$T/bad3.scene"
unset LX_ROOM_MEMORY_MB
expect_rc 2 "beyond the memory bound: input error"
expect_err_match "bad3.scene:2: interreflection needs [0-9]+ patches .* allows [0-9]+" "the memory bound says how many"
# a room whose every reflectance is 0, with a black box: no light can be reflected, so the planner
# leaves interreflection off (and says why), the result is the direct light alone
# (1000 / (4 pi) cos / d^2, d^2 = 15.39, cos = 1.7 / sqrt(15.39): 2.2406866550 lx), and forcing it on is an error
cat >"$T/black.scene" <<'EOF2'
[room black]
size = 4, 4, 3 m
ceiling = 0
walls = 0
floor = 0
[obstruction box]
min = 1, 1, 0 m
max = 2, 2, 1 m
reflectance = 0
[luminaire l]
type = point
position = 3, 3, 2.5 m
flux = 1000 lm
[receiver p]
type = point
position = 0.5 m, 0.5 m, 0.8 m
EOF2
run scene "$T/black.scene" --explain
expect_rc 0 "black room: explain"
expect_out_match '^  interreflection off every reflectance is 0' "black room: interreflection off, every reflectance 0"
run scene "$T/black.scene" --format csv
expect_out_match '^receiver,x,y,z,illuminance_lx$' "black room: direct light only (no indirect columns)"
expect_field 1 illuminance_lx 2.2406866550 1e-9 "black room: the inverse-square and cosine law"
printf '[effects]\ninterreflection = on\n' | cat - "$T/black.scene" >"$T/black_on.scene"
run scene "$T/black_on.scene"
expect_rc 2 "black room, interreflection forced on: input error"
expect_err_match "black_on.scene:2: interreflection forced on, but every reflectance .* is 0" "forced on names file and line"
