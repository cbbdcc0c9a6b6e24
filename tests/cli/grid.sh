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
