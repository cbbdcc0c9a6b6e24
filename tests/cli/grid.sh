# grid.sh - CLI cases for `luxcalc ies` and `luxcalc grid` (closed forms derived in the comments).
. tests/cli/lib.sh
S=samples/ies
run ies --format csv $S/point_isotropic_1000lm.ies
expect_rc 0 "ies reads the project's isotropic sample"
expect_out_match '^file,format,lumens,max_intensity_cd,beam_angle_deg,field_angle_deg,symmetry' "ies csv columns (CLI.md)"
# a constant table integrates exactly: 4 pi x 1000 / (4 pi) = 1000 lm; peak 1000 / (4 pi) = 79.5774715 cd
expect_field 1 lumens 1000 1e-9 "isotropic sample: 1000 lm"
expect_field 1 max_intensity_cd 79.57747154594767 1e-9 "isotropic sample: peak F / 4 pi"
run ies --format csv $S/spot_warn_30deg_800lm.ies
# the sample was written for a 30 deg beam (50 % points of cos^S)
expect_field 1 beam_angle_deg 30 0.01 "Warn sample: 30 deg beam"
run ies --write "$T/w.ies" --model warn --exponent 10 --flux 1000lm
expect_rc 0 "ies --write from a model"
run ies --format csv "$T/w.ies"
# (S+1)/(2 pi) F = 11000 / (2 pi) = 1750.7043740108 cd
expect_field 1 max_intensity_cd 1750.7043740108 1e-6 "written Warn peak (S+1) F / 2 pi"
run ies tests/data/ies/bad/negative_cd.ies
expect_rc 2 "negative candela is an input error"
expect_err_match 'negative_cd.ies:9: negative candela' "the error names file and line"
run ies tests/data/ies/bad/truncated.ies $S/point_isotropic_1000lm.ies --format csv
expect_rc 2 "a bad file in a batch gives exit 2"
expect_out_match 'point_isotropic_1000lm.ies' "the good file is still printed"
run grid --ies $S/point_isotropic_1000lm.ies --at 0,0,2 --plane z=0 --area 0:1,0:0 --points 2x1
expect_rc 0 "grid runs"
expect_out_match '^x,y,z,illuminance_lx' "grid csv header"
# E = I h / d^3: (0,0,0): 79.5774715 x 2 / 8 = 19.8943679; (1,0,0): 79.5774715 x 2 / 5^1.5 = 14.2352509
expect_field 1 illuminance_lx 19.894367886486918 1e-9 "grid point under the source"
expect_field 2 illuminance_lx 14.235250868343543 1e-9 "grid point 1 m aside"
expect_err_match '^E_avg,E_min,E_max,U0' "summary on stderr"
run grid --ies $S/point_isotropic_1000lm.ies --at 0,0,2 --plane z=0 --area 0:1,0:0 --points 2x1 --summary
# E_avg = (19.8943679 + 14.2352509) / 2 = 17.0648094; U0 = 14.2352509 / 17.0648094
expect_field 1 E_avg 17.064809377415231 1e-9 "summary E_avg"
expect_field 1 U0 0.83418751147513 1e-9 "summary U0"
run grid --ies $S/point_isotropic_1000lm.ies --at 0,0,2 --plane z=0 --area 0:1,0:1 --spacing 0.5 --summary --backend opencl
case $(opencl_state) in
  device) expect_rc 0 "grid on OpenCL (table interpolation)" ;;
  off) expect_rc 2 "grid --backend opencl in a build without OpenCL is an input error"
       expect_err_match '^luxcalc: grid: .*no OpenCL' "grid --backend opencl names the missing OpenCL" ;;
  *) skip "grid on OpenCL (table interpolation)" "no OpenCL device" ;;
esac
# near field: the sample's 0.3 m x 0.3 m Lambertian panel (1000 lm, L = 1000 / (pi 0.09) cd/m2) 0.3 m
# above the point (0.71 x its diagonal). Howell B-3, four corner rectangles X = Y = 0.15 / 0.3 = 0.5:
# F = 4 / (2 pi) [2 X / sqrt(1 + X^2) atan(X / sqrt(1 + X^2))], E = pi L F = 2660.62745 lx; bound
# 2e-4 relative (0.53 lx): the refinement tolerance 1e-4 plus the 1 deg table's interpolation of cos.
run grid --ies $S/downlight_lambert_1000lm.ies --at 0,0,0.3 --plane z=0 --area 0:0,0:0 --points 1x1
expect_field 1 illuminance_lx 2660.6274495641505 0.53 "near field converges to the exact rectangle"
# the point model: L A / h^2 = 1000 / pi / 0.09 = 3536.77651 lx (the +33 % the near field removes)
run grid --ies $S/downlight_lambert_1000lm.ies --at 0,0,0.3 --plane z=0 --area 0:0,0:0 --points 1x1 --model point
expect_field 1 illuminance_lx 3536.7765131532296 1e-6 "point model under the panel"
run grid --ies $S/point_isotropic_1000lm.ies --at 0,0,2 --plane w=0 --area 0:1,0:1 --spacing 0.5
expect_rc 1 "a bad --plane is a usage error"
# --table-rows: the table path at fewer rows (an isotropic table is constant: still exact)
run grid --ies $S/point_isotropic_1000lm.ies --at 0,0,2 --plane z=0 --area 0:1,0:0 --points 2x1 --table-rows 64
expect_rc 0 "grid --table-rows runs"
expect_field 2 illuminance_lx 14.235250868343543 1e-6 "table of 64 rows, isotropic: E = I h / d^3"
run grid --ies $S/point_isotropic_1000lm.ies --at 0,0,2 --plane z=0 --area 0:1,0:0 --points 2x1 --table-rows 1
expect_rc 1 "--table-rows 1 is a usage error"
run grid --ies $S/point_isotropic_1000lm.ies --at 0,0,2 --plane z=0 --area 0:1,0:0 --points 2x1 --table-rows 64 --interp smooth
expect_rc 1 "--table-rows with another --interp is a usage error"

# ---- grid options of the plots issue ----
P=$S/point_isotropic_1000lm.ies   # I = 1000 / (4 pi) = 79.5774715 cd
# --at takes units like every option: 200 cm, and a unit after the last value for all three
run grid --ies $P --at 0,0,200cm --plane z=0 --area 0:1,0:0 --points 2x1
expect_field 1 illuminance_lx 19.894367886486918 1e-9 "--at with a unit on one value"
run grid --ies $P --at 0,0,6.561679790026246ft --plane z=0 --area 0:1,0:0 --points 2x1
expect_field 1 illuminance_lx 19.894367886486918 1e-9 "--at in feet (6.5617 ft = 2 m)"
run grid --ies $P --at "0,0,2 m" --plane z=0 --area 0:3.280839895013123,0:0ft --points 2x1
expect_field 2 illuminance_lx 14.235250868343543 1e-9 "--at and --area with the unit after the last value"
run grid --ies $P --at 0,0,2lm --plane z=0 --area 0:1,0:0 --points 2x1
expect_rc 1 "--at with a unit of another quantity is a usage error"
expect_err_match "--at: unit 'lm' is a luminous flux, not a length" "the message names the option and the unit"
# the summary: CLI.md's names first, then the names scenes use and E_min / E_max
# (E_min / E_max = 14.2352509 / 19.8943679 = 0.715541753)
run grid --ies $P --at 0,0,2 --plane z=0 --area 0:1,0:0 --points 2x1 --summary
expect_out_match '^E_avg,E_min,E_max,U0,illuminance_avg_lx,illuminance_min_lx,illuminance_max_lx,uniformity_u0,uniformity_min_max$' "summary columns"
expect_field 1 uniformity_min_max 0.71554175279993270 1e-12 "E_min / E_max"
expect_field 1 illuminance_avg_lx 17.064809377415231 1e-9 "illuminance_avg_lx = E_avg"
run grid --ies $P --at 0,0,2 --plane z=0 --area 0:1,0:0 --points 2x1 --summary --format table
expect_out_match '^uniformity_u0 +0\.834$' "table summary: U0 to 3 decimals"
expect_out_match '^illuminance_avg_lx +17\.06 lx$' "table summary: lux to 4 significant digits"
run grid --ies $P --at 0,0,2 --plane z=0 --area 0:1,0:0 --points 2x1 --format json
expect_err_match '"uniformity_min_max": 0.7155417527999327' "the summary on stderr in the chosen format (json)"
# cell centres (EN 12464-1, DIALux): 4 m x 3 m at 1 m spacing is 4 x 3 cells, points 0.5 m inside
run grid --ies $P --at 2,1.5,2 --plane z=0 --area 0:4,0:3 --spacing 1 --points-at centres
expect_field 1 x 0.5 0 "first centre x = s/2"
expect_field 1 y 0.5 0 "first centre y = s/2"
expect_field 12 x 3.5 0 "last centre x = 4 - s/2"
n=$(printf '%s\n' "$out" | wc -l)
if [ "$n" -eq 13 ]; then ok "4 x 3 cells give 12 points"; else notok "4 x 3 cells give 12 points" "$n lines"; fi
# a spacing that does not divide the side: ceil(4 / 1.5) = 3 cells of 4/3 m, centres at 2/3, 2, 10/3
run grid --ies $P --at 2,1.5,2 --plane z=0 --area 0:4,0:0 --spacing 1.5 --points-at centres
expect_field 2 x 2 1e-12 "cells no larger than the spacing: the middle centre"
expect_field 3 x 3.3333333333333335 1e-12 "the last centre 4 - (4/3)/2"
# a plane facing away from the luminaire: zeros, and a warning that says why
run grid --ies $P --at 0,0,-2 --plane z=0 --area 0:1,0:1 --spacing 1 --summary
expect_rc 0 "a plane facing away still runs"
expect_err_match 'warning: the plane faces away from every luminaire' "facing away: a warning"
run grid --ies $P --at 0,0,-2 --plane z=0 --area 0:1,0:1 --spacing 1 --summary --normal 0,0,-1
expect_field 1 E_max 19.894367886486918 1e-9 "with --normal towards it, the closed form again"
if printf '%s\n' "$err" | grep -q warning; then notok "no warning when lit" "$err"; else ok "no warning when lit"; fi
# the table format prints the grid as a grid: a heading, a row of x, one row per y (highest first)
run grid --ies $P --at 0,0,2 --plane z=0 --area 0:1,0:1 --spacing 1 --format table
expect_out_match '^illuminance \(lx\) on z = 0 m: rows y \(m\), columns x \(m\)$' "grid table heading"
expect_out_match '^y \\ x +0 +1$' "grid table: the x coordinates"
expect_out_match '^ *1 +14\.24 +10\.83$' "grid table: the row y = 1 first, 4 significant digits (I h / 6^1.5)"
expect_out_match '^ *0 +19\.89 +14\.24$' "grid table: the row y = 0 last"
# imperial output: fc and ft (1 lx = 0.09290304 fc; 1 m = 3.2808399 ft), the csv names follow
run grid --ies $P --at 0,0,2 --plane z=0 --area 0:1,0:0 --points 2x1 --units imperial
expect_out_match '^x,y,z,illuminance_fc$' "imperial csv header"
expect_field 1 illuminance_fc 1.8482472555330098 1e-12 "19.8943679 lx in fc"
expect_field 2 x 3.280839895013123 1e-12 "1 m in ft"
# grid --scene: the luminaires of a scene file on a plane of the flags (point.scene: 400 cd at 2 m)
run grid --scene tests/data/scenes/point.scene --plane z=0 --area 0:1,0:0 --points 2x1
expect_rc 0 "grid --scene runs"
# E = I h / d^3: 400 x 2 / 8 = 100 lx; 1 m aside 400 x 2 / 5^1.5 = 71.5541753
expect_field 1 illuminance_lx 100 1e-9 "grid --scene: under the lamp"
expect_field 2 illuminance_lx 71.55417527999327 1e-9 "grid --scene: 1 m aside"
run grid --scene tests/data/scenes/point.scene --summary
expect_rc 1 "grid --scene without a plane needs the scene's one grid"
expect_err_match 'the scene has 0 grid receivers' "the message says why"
run scene samples/scenes/office.scene --format csv
desk=$(printf '%s\n' "$out" | awk -F, '$1=="desk"{s+=$5; n++} END {printf "%.17g", s/n}')
run grid --scene samples/scenes/office.scene --summary
expect_rc 0 "grid --scene uses the scene's one grid"
expect_field 1 E_avg "$desk" 1e-9 "the same desk average as luxcalc scene"
run grid --ies $P --scene tests/data/scenes/point.scene --plane z=0 --area 0:1,0:0 --points 2x1
expect_rc 1 "--ies and --scene together are a usage error"
# a luminaire closer to a point than double arithmetic resolves (d^2 below DBL_MIN: 1.5e-154 m) is
# refused with the point named, as 1e-155 m always was: 1e-162 m gave 0 lx (d^2 underflowed to 0)
for z in 1e-155 1e-162 1e-300; do
  run grid --ies samples/ies/point_isotropic_1000lm.ies --at 0,0,$z --plane z=0 --area 0:0,0:0 --points 1x1 --format csv
  expect_rc 2 "a luminaire $z m above a point: exit 2"
  expect_err_match "luminaire 1 is $z m from point 1 \(0, 0, 0 m\), closer than double arithmetic resolves" "$z m: the distance and the point named"
done
run grid --ies samples/ies/point_isotropic_1000lm.ies --at 0,0,0 --plane z=0 --area 0:1,0:0 --points 2x1 --format csv
expect_rc 2 "a luminaire on a grid point: exit 2"
expect_err_match "luminaire 1 sits on point 1 \(0, 0, 0 m\): a point source's illuminance there is undefined" "on the point: undefined"
# below the plane (behind every receiver) it gives 0 lx, as it should
run grid --ies samples/ies/point_isotropic_1000lm.ies --at 0,0,-1e-162 --plane z=0 --area 0:0,0:0 --points 1x1 --format csv
expect_rc 0 "a luminaire 1e-162 m behind the receivers: 0 lx"
expect_field 1 illuminance_lx 0 0 "behind the receivers: 0 lx"
