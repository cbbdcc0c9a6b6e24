# lighting.sh - CLI cases for point, spot, disk, rect, convert and solve (the csv columns of
# CLI.md "Lighting calculations"). Reference values: closed forms named in each comment.
. tests/cli/lib.sh
# 1000 lm isotropic at 2 m, 30 deg: (1000/4pi) cos30 / 4 = 17.2290279819 lx (issue 4)
run point --flux 1000lm --distance 2m --angle 30deg --format csv
expect_rc 0 "point runs"; expect_out_match '^flux_lm,intensity_cd,illuminance_lx' "point csv header"
expect_field 1 illuminance_lx 17.2290279819 1e-9 "point 17.229028 lx"
# bare angle is degrees, bare distance metres
run point --flux 1000 --distance 2 --angle 30 --format csv
expect_field 1 illuminance_lx 17.2290279819 1e-9 "bare numbers: m and deg"
# 8 ft = 2.4384 m; I = 100 cd: E = 100 / 5.94579456 = 16.8186100261 lx
run point --intensity 100cd --distance 8ft --format csv
expect_field 1 illuminance_lx 16.8186100261 1e-9 "feet"
run point --flux 1000 --distance 3lm
expect_rc 1 "mismatched unit is a usage error"; expect_err_match "distance.*'lm'" "names option and unit"
run point --flux 1000 --distance 0
expect_rc 2 "distance 0 is an input error"
run point --flux 10W
expect_rc 1 "W without efficacy refused"; expect_err_match "efficacy" "asks for an efficacy"
# 10 W at 100 lm/W = 1000 lm
run point --flux 10W --efficacy 100lm/W --distance 2 --angle 30 --format csv
expect_field 1 illuminance_lx 17.2290279819 1e-9 "W with --efficacy"
run point --flux 1000 --angle 120deg --format csv
expect_field 1 illuminance_lx 0 0 "back-facing receiver gets 0"
# Warn S = 1 (Lambertian), F = pi: peak 1 cd, at 60 deg 0.5 cd, at 1 m normal: 0.5 lx
run spot --flux 3.141592653589793 --exponent 1 --angle 60 --format csv
expect_out_match '^peak_intensity_cd,intensity_cd,illuminance_lx' "spot csv header"
expect_field 1 intensity_cd 0.5 1e-12 "spot S=1 at 60 deg"
run spot --flux 1000 --exponent 1e6 --angle 90deg --format csv
expect_field 1 intensity_cd 0 0 "spot S=1e6 at 90 deg is 0, not NaN"
# the flux in a cone of a Warn lobe: F (1 - cos^(S+1) A); S = 1 at 60 deg: 3/4 of 800 lm
run spot --flux 800lm --exponent 1 --cone 60deg --format csv
expect_field 1 cone_flux_lm 600 1e-9 "spot --cone: 600 lm of 800 within 60 deg (S = 1)"
expect_field 1 cone_fraction 0.75 1e-12 "spot --cone: fraction 3/4"
run spot --flux 800lm --exponent 1 --cone 200deg --format csv
expect_rc 2 "spot --cone beyond 180 deg is refused"
# disk L=1000, R=0.5, h=1: 200 pi = 628.3185307 lx; point = 250 pi, error 0.25
run disk --luminance 1000cd/m2 --radius 0.5m --distance 1m --format csv
expect_out_match '^illuminance_lx,point_illuminance_lx,point_error' "disk csv header"
expect_field 1 illuminance_lx 628.3185307 1e-6 "disk on axis 628.3185 lx"
expect_field 1 point_error 0.25 1e-12 "disk point error R^2/h^2"
run disk --luminance 1000 --radius 0.5 --distance 5 --model exact --format csv
expect_field 1 point_error 0.01 1e-12 "disk at 5 D: 1.000 %"
# auto (the default) reports the closed form at any distance: at 5 D, 10 D (pi L R^2 / (h^2 + R^2))
run disk --luminance 1000 --radius 0.5 --distance 5 --format csv
expect_field 1 illuminance_lx 31.10487775831479 1e-9 "disk at 5 D: exact by default (250 pi / 25.25 lx)"
expect_out_match '^[^,]*,[^,]*,[^,]*,[^,]*,exact,1,' "disk at 5 D: model exact, near_field 1"
run disk --luminance 1000 --radius 0.5 --distance 10 --format csv
expect_field 1 illuminance_lx 7.834395644862326 1e-9 "disk at 10 D: exact (250 pi / 100.25 lx)"
expect_field 1 point_error 0.0025 1e-12 "disk at 10 D: point error 0.25 %"
run disk --luminance 1000 --radius 0.5 --distance 10 --model point --format csv
expect_field 1 illuminance_lx 7.853981633974483 1e-9 "--model point: the point model (250 pi / 100 lx)"
expect_out_match '^[^,]*,[^,]*,[^,]*,[^,]*,point,' "--model point: model point"
# the coplanar limit: pi L on the disk, pi L / 2 on the rim, 0 outside
run disk --luminance 1000 --radius 0.5 --distance 0 --offset 0.2 --format csv
expect_rc 0 "disk --distance 0 is the coplanar limit"
expect_field 1 illuminance_lx 3141.5926535897932 1e-12 "on the disk: pi L"
run disk --luminance 1000 --radius 0.5 --distance 0 --offset 0.5 --format csv
expect_field 1 illuminance_lx 1570.7963267948966 1e-12 "on the rim: pi L / 2"
run disk --luminance 1000 --radius 0.5 --distance 0 --offset 2 --format csv
expect_field 1 illuminance_lx 0 0 "outside: 0"
run rect --luminance 4 --width 1 --length 2 --distance 0 --at corner --format csv
expect_field 1 illuminance_lx 3.14159265358979 1e-12 "rect corner, coplanar: pi L / 4"
run disk --luminance 1000 --radius 0.5 --distance -1 --format csv
expect_rc 2 "a negative distance is refused"
# square at 5 side, centre: 1.33245778 % (60-digit decimal evaluation of Howell B-3)
run rect --luminance 1 --width 1 --length 1 --distance 5 --at centre --format csv
expect_field 1 point_error 0.0133245778057 1e-12 "square at 5 side: 1.3325 %"
# corner of a large rectangle at tiny height: pi L / 4
run rect --luminance 4 --width 1000 --length 1000 --distance 1mm --at corner --format csv
expect_field 1 illuminance_lx 3.14159265 1e-5 "corner at h -> 0: pi L / 4"
# 46 fc = 46/0.3048^2 lx = 495.13987917 lx
run convert 46 fc --format csv
expect_out_match '^unit,value' "convert csv header"
expect_out_match '^lx,495.139879' "46 fc in lx"
# 1 fL = 3.42625909964 cd/m2
run convert 1fL --format csv
expect_out_match '^cd/m2,3.42625909963539' "fL in cd/m2"
run convert 10W --efficacy 300lm/W --format csv
expect_out_match "^lm,3000," "10 W at 300 lm/W is 3000 lm"
run convert 10 W --format csv
if printf '%s\n' "$out" | grep -q '^lm,'; then notok "no efficacy: no lm" "$out"; else ok "no efficacy: no lm"; fi
run solve --illuminance 500lx --intensity 2000cd --format csv
expect_out_match '^distance_m' "solve distance header"; expect_field 1 distance_m 2 1e-12 "sqrt(2000/500) = 2 m"
run solve --illuminance 500lx --distance 2m --format csv
expect_field 1 intensity_cd 2000 1e-9 "E d^2 = 2000 cd"
expect_field 1 flux_lm 25132.741228718 1e-6 "4 pi 2000 lm"
run solve --illuminance 500 --reflectance 0.8 --format csv
expect_field 1 luminance_cd_m2 127.32395447 1e-7 "rho E / pi"
run point --help
expect_rc 0 "help"; expect_out_match "example" "help has an example"

# --spd: the efficacy of a measured spectrum converts W to lm. A flat 1 W/nm spectrum from 380 to
# 780 nm at 5 nm has a luminous efficacy of radiation of 182.457480537 lm/W (colour-science 0.4.7,
# colour.luminous_efficacy): 10 W of it are 1824.5748 lm. luxcalc sums Y by the CIE 015 rule at the
# data's 5 nm, colour-science by its own interpolation: they agree to 1e-5 relative.
awk 'BEGIN { print "wavelength_nm,flat"; for (l = 380; l <= 780; l += 5) print l ",1" }' > "$T/flat.csv"
run convert 10W --spd "$T/flat.csv" --format csv
expect_rc 0 "convert with --spd"
lm=$(printf '%s\n' "$out" | awk -F, '$1=="lm" {print $2}')
if awk -v v="$lm" 'BEGIN { d = v - 1824.57480537; if (d < 0) d = -d; exit !(v != "" && d < 1824.57 * 1e-5) }'; then
  ok "10 W of a flat spectrum = 1824.575 lm (colour-science LER)"; else notok "--spd efficacy" "lm = '$lm': $out"; fi
run point --flux 10W --spd "$T/flat.csv" --distance 2m --format csv
expect_rc 0 "point with a radiometric flux and --spd"
run point --flux 10W --distance 2m
expect_rc 1 "a radiometric flux without --spd or --efficacy is refused"
