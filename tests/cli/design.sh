# design.sh - CLI cases of the deliverable (README "The deliverable"): maintained values and how
# every output says so, the errors of its keys with file and line. Reference values: closed forms
# in each comment.
. tests/cli/lib.sh
# 400 cd at 2 m: 100 lx new; maintained 100 x 0.8 + 100 x 0.5 = 130 lx
run scene tests/data/design/mf.scene --format csv
expect_rc 0 "maintained scene runs"
expect_out_match '^receiver,x,y,z,illuminance_lx,values$' "csv says which values: a values column"
expect_field 1 illuminance_lx 130 1e-12 "maintained: 100 x 0.8 + 100 x 0.5 lx"
expect_out_match ',maintained$' "csv rows say maintained"
run scene tests/data/design/mf.scene
expect_out_match '^values +maintained \(MF 0\.5 to 0\.8\)$' "table: the values row names the factors"
run scene tests/data/scenes/point.scene
expect_out_match '^values +new \(no maintenance factor\)$' "table: new values said so"
run scene tests/data/design/mf.scene --explain
expect_out_match '^values: maintained \(MF 0\.5 to 0\.8\)$' "--explain: the values line"
expect_out_match '^  b +MF 0\.5$' "--explain: each luminaire's factor"
run scene tests/data/design/mf.scene --explain --format json
expect_out_match '"values": "maintained \(MF 0\.5 to 0\.8\)"' "--explain json: values"
run scene tests/data/design/bad_mf.scene
expect_rc 2 "MF outside (0, 1]: input error"
expect_err_match '^luxcalc: scene: tests/data/design/bad_mf.scene:6: maintenance_factor: must be greater than 0 and at most 1 \(got 1\.25\)' "MF error names file and line"
# cylindrical illuminance: I = 1000 / (4 pi) cd, h = 2 m, d = sqrt(2^2 + 1.8^2) m:
# E_z = I h / (pi d^3) = 2.60053324213; E_sz facing the source 5.20106648427; E_h = I 1.8 / d^3
run scene tests/data/design/cylinder.scene --format csv
expect_out_match '^receiver,x,y,z,illuminance_lx,cylindrical_lx,semicylindrical_lx,modelling$' "cylinder columns"
expect_field 1 cylindrical_lx 2.60053324213 1e-10 "E_z of a point source: I h / (pi d^3)"
expect_field 1 semicylindrical_lx 5.20106648427 1e-10 "E_sz facing the source: 2 I h / (pi d^3)"
expect_field 1 modelling 0.353677651315 1e-10 "modelling E_z / E_h = h / (pi 1.8)"
run scene tests/data/design/cylinder.scene
expect_out_match '^modelling_min +0\.354$' "table: modelling to 3 decimals"
# the check against typed requirements: E_m met, U0 0.99 not
run scene tests/data/design/check.scene --check
expect_rc 0 "--check runs"
expect_out_match '^office +desk +E_m +>= 50\.00 lx +60\.08 lx +pass$' "check line: E_m met"
expect_out_match '^office +desk +U_0 +>= 0\.990 +0\.944 +FAIL$' "check line: U0 not met"
expect_out_match '^checks: 1 of 2 pass; values maintained \(MF 0\.8\)$' "closing count and values"
run scene tests/data/design/check.scene --check --format csv
expect_out_match '^requirement,target,quantity,operation,comparison,required,value,unit,pass,reference,line$' "check csv header"
expect_out_match '^office,desk,U_0,normal,at_least,0\.99,0\.[0-9]+,,fail,typed for the test,25$' "check csv row with its line"
run scene tests/data/design/bad_req.scene --check
expect_rc 2 "a requirement for a quantity not computed: input error"
expect_err_match '^luxcalc: scene: tests/data/design/bad_req.scene:15: requirement .office.: cylindrical_illuminance is not computed' "names file and line"
# EN 15193-1 LENI against the hand computation in energy.scene's header
run scene tests/data/design/energy.scene --energy --format csv
expect_rc 0 "--energy runs"
expect_field 1 lighting_kWh 168.6825 1e-10 "W_L = P_n F_C F_O (t_D F_D + t_N) / 1000"
expect_field 1 parasitic_kWh 48.82 1e-10 "W_P = (P_pc (t_y - t_D - t_N) + P_em t_em) / 1000"
expect_field 1 leni_kWh_m2_a 9.0626041667 1e-9 "LENI = W / A"
run scene tests/data/scenes/point.scene --energy
expect_rc 2 "--energy without [energy]: input error"
expect_err_match 'no \[energy\] section' "says what is missing"
# the PDF report: pages, text and figures read back with poppler-utils (make deps installs it)
run report tests/data/design/report.scene
expect_rc 1 "report without -o: usage error"
run report tests/data/design/report.scene -o "$T/no_such_dir/r.pdf"
if [ "$rc" -ne 0 ] && [ ! -e "$T/no_such_dir/r.pdf" ]; then ok "report into a missing directory fails and leaves nothing"
else notok "report into a missing directory" "rc $rc"; fi
if command -v pdftotext >/dev/null 2>&1 && command -v pdfinfo >/dev/null 2>&1 && command -v pdfimages >/dev/null 2>&1; then
  run report tests/data/design/report.scene -o "$T/r.pdf" --project "Test project" --author "T. Ester"
  expect_rc 0 "report writes a PDF"
  pages=$(pdfinfo "$T/r.pdf" 2>/dev/null | awk '/^Pages:/ {print $2}')
  if [ "${pages:-0}" -ge 8 ]; then ok "report: $pages pages"; else notok "report pages" "${pages:-none}"; fi
  if pdfinfo "$T/r.pdf" | grep -q '^Author: *T. Ester'; then ok "report: the PDF's author"; else notok "report: author" "$(pdfinfo "$T/r.pdf")"; fi
  out=$(pdftotext -layout "$T/r.pdf" - 2>/dev/null)
  for s in 'Report test room' 'Test project' 'Lighting design report' 'maintained values \(maintenance factor 0\.8\)' \
           '1 Luminaire schedule and maintenance' 'downlight_lambert_1000lm\.ies' '2 Rooms' 'Room r: 4 m x 3 m x 2\.8 m' \
           '3 Areas and calculation surfaces' 'Illuminance on desk \(z = 0\.75 m\)' 'desk\.surrounding' \
           '4 Checks against the requirements' '5 Glare \(UGR\)' 'CIE 190:2010 UGR table: downlight_lambert_1000lm\.ies' \
           '6 Emergency lighting \(EN 1838\)' 'direct light only' '7 Energy \(EN 15193-1\)' 'LENI' \
           '8 Method and accuracy' 'near-field tolerance'; do
    expect_out_match "$s" "report text: $s"
  done
  # the check lines carry the values --check computes (4 significant digits in the report)
  v=$("$LUXCALC" scene tests/data/design/report.scene --check --format csv | awk -F, '$3 == "E_m" {printf "%.4g", $7}')
  expect_out_match "task +desk +E_m +>= 300\.0 lx +$v lx +FAIL" "report: the E_m check line with --check's value ($v lx)"
  expect_out_match 'escape +way +E_min \(emergency\) +>= 0\.5000 lx +[0-9.]+ lx +pass' "report: the emergency check"
  # figures: one false-colour field per grid receiver (the task area, 4 walls, the ceiling)
  n=$(pdfimages -list "$T/r.pdf" 2>/dev/null | awk 'NR > 2' | wc -l)
  if [ "$n" -eq 6 ]; then ok "report: 6 isolux plots (pdfimages)"; else notok "report: isolux plots" "$n images"; fi
else
  skip "the PDF report's pages, text and figures" "no pdftotext, pdfinfo or pdfimages (Debian poppler-utils; make deps installs it)"
fi
# a task area outside its room: file and line, exit 2
run scene tests/data/design/bad_task.scene
expect_rc 2 "a task area outside the room: input error"
expect_err_match "^luxcalc: scene: tests/data/design/bad_task.scene:10: area 'desk': the task area \(x 3 to 4.5 m, y 1 to 2 m, z 0.75 m\) reaches outside room 'r'" "names file and line"
# emergency operation from the command line: the exit luminaire alone (150 lm, MF 0.8, 2.7 m up at
# x 2 m on the route's line): at (0.6, 2.5, 0) m, d^2 = 1.4^2 + 2.7^2: E = 0.8 (150 / 4 pi) 2.7 / d^3
run scene tests/data/design/report.scene --emergency --format csv
expect_rc 0 "--emergency runs"
v=$(printf '%s\n' "$out" | awk -F, '$1 == "way" && $2 == "0.6" {print $5}')
if awk -v a="$v" 'BEGIN { d2 = 1.4 * 1.4 + 2.7 * 2.7; e = 0.8 * 150 / (4 * 3.14159265358979) * 2.7 / (d2 * sqrt(d2)); d = a - e; if (d < 0) d = -d; exit !(a != "" && d < 1e-12) }'
then ok "--emergency: the route's first point against the closed form"; else notok "--emergency closed form" "got '$v'"; fi
run scene tests/data/design/report.scene --emergency --explain
expect_out_match '^  interreflection off \[forced\] emergency lighting \(EN 1838\): direct light only' "--emergency --explain: why interreflection is off"
expect_out_match '^operation: emergency \(EN 1838\)' "--emergency --explain: the operation"
