# scene.sh - CLI cases for `luxcalc scene` (CLI.md "Scenes"): results as csv, the plan as
# json, errors with file and line, exit codes, -o and --png. Reference values: closed forms named
# in each comment.
. tests/cli/lib.sh
# tests/data/scenes/point.scene: 400 cd at 2 m: E = 400 / 4 = 100 lx; tilted 60 deg: 50 lx;
# luminance of the reflectance-0.5 floor: 0.5 * 100 / pi = 15.9154943092 cd/m2
run scene tests/data/scenes/point.scene --format csv
expect_rc 0 "point scene runs"
expect_out_match '^receiver,x,y,z,illuminance_lx,luminance_cd_m2$' "csv header"
expect_field 1 illuminance_lx 100 1e-12 "inverse square: 100 lx"
expect_field 2 illuminance_lx 50 1e-12 "cosine law: 50 lx"
expect_field 1 luminance_cd_m2 15.9154943092 1e-9 "Lambertian luminance rho E / pi"
# the plan: json with the effects CLI.md names, and why
run scene tests/data/scenes/point.scene --explain --format json
expect_rc 0 "explain json runs"
expect_out_match '"effects": \{"inverse_square": true, "cosine": true, "spot_falloff": false, "goniometric": false, "near_field": false, "spectral": false, "environment": false' "effects of a point scene"
expect_out_match '"spectral": "no spectral output asked' "reason for spectral"
expect_out_match '"measured": \{"point_evaluations": 2, "spot_evaluations": 0, "goniometric_lookups": 0, "nearfield_pairs": 0, "nearfield_subdivisions": 0, "environment_evaluations": 0, "environment_samples": 0, "spectra_integrated": 0' "measured work"
if command -v python3 >/dev/null 2>&1; then
  if printf '%s\n' "$out" | python3 -c 'import json,sys; d=json.load(sys.stdin); assert set(["inverse_square","cosine","spot_falloff","goniometric","near_field","spectral","environment"]) <= set(d["effects"]) and set(d["effects"]) == set(d["reasons"])'; then ok "explain json parses"; else notok "explain json parses" "$out"; fi
fi
run scene samples/scenes/office.scene --explain
expect_rc 0 "office explain"
expect_out_match '^  goniometric +on' "office: goniometric on"
expect_out_match '^  near_field +on .*integrated \(point-model error estimated over 1e-05' "office: near field where the point model misses 1e-5"
expect_out_match 'dl1 -> desk: [0-9]+ of 117 points near field' "office: costly pairs listed"
expect_out_match '^  dl1 +desk +1 +0.5 +0.5 +0.75 +[0-9.e-]+ +area: estimated error over tolerance' "office: each pair's estimate and decision"
run scene samples/scenes/street.scene --explain --format json
expect_out_match '"near_field": true' "street: some pairs near"
expect_out_match '"path": "point", "why": "point: estimated error within tolerance"' "street: far pairs keep the point model"
expect_out_match '"path": "area", "why": "area: ' "street: near pairs integrated"
# errors: file and line, exit 2; usage errors exit 1
run scene tests/data/scenes/bad_key.scene
expect_rc 2 "unknown key is an input error"
expect_err_match "^luxcalc: scene: tests/data/scenes/bad_key.scene:6: unknown key 'colour'" "error names file and line"
run scene
expect_rc 1 "no file: usage error"
run scene tests/data/scenes/point.scene --format yaml
expect_rc 1 "bad format: usage error"
run scene tests/data/scenes/no_such.scene
expect_rc 2 "missing file: input error"
# -o writes the file, --png draws the grids
run scene samples/scenes/office.scene --format csv -o "$T/office.csv" --png "$T"
expect_rc 0 "-o and --png"
if [ "$(wc -l < "$T/office.csv")" -eq 119 ]; then ok "-o: header + 118 points"; else notok "-o: header + 118 points" "$(wc -l < "$T/office.csv") lines"; fi
if head -c 8 "$T/office_desk.png" | od -An -c | grep -q 'P   N   G'; then ok "--png wrote a PNG"; else notok "--png wrote a PNG" "no $T/office_desk.png"; fi

# --contributions in the table format: each luminaire's mean over the receiver; no sky column
# without a sky, one with it
run scene tests/data/scenes/point.scene --contributions
expect_rc 0 "--contributions in the table format"
expect_out_match '^E_lamp_avg_lx +100\.0 lx$' "the lamp's part: 400 cd / (2 m)^2 = 100 lx"
expect_out_match '^uniformity_min_max +1\.000$' "E_min / E_max in the scene summary"
if printf '%s\n' "$out" | grep -q 'E_sky'; then notok "no sky column without a sky" "$out"; else ok "no sky column without a sky"; fi
run scene tests/data/scenes/point.scene --contributions --format csv
expect_out_match '^receiver,x,y,z,illuminance_lx,luminance_cd_m2,E_lamp_lx$' "csv contributions without a sky column"
run scene samples/scenes/facade.scene --contributions --format csv
expect_out_match ',E_sky_lx$' "a scene with a sky has the sky column"
# a point source closer than double arithmetic resolves: the vector scaled by 2^600 (exact), so 1e-10 cd
# at 1e-155 m is 1e-10 / 1e-310 = 1e300 lx exactly (it was 1.0000000000000047e300: d^2 subnormal), and
# 400 cd at 1e-162 m (1e-322 m2, 4e324 lx) an overflow error, not the 0 lx of an underflowed d^2
sed -e 's/0 m, 0 m, 2 m/0 m, 0 m, 1e-155 m/' -e 's/intensity = 400 cd/intensity = 1e-10 cd/' tests/data/scenes/point.scene >"$T/near.scene"
run scene "$T/near.scene" --format csv
expect_rc 0 "1e-10 cd at 1e-155 m computes"
expect_field 1 illuminance_lx 1e300 0 "1e-10 cd at 1e-155 m: exactly 1e300 lx"
expect_field 2 illuminance_lx 5e299 1e285 "and cos 60 deg of it on the tilted receiver"
sed -e 's/0 m, 0 m, 2 m/0 m, 0 m, 1e-162 m/' tests/data/scenes/point.scene >"$T/near2.scene"
run scene "$T/near2.scene" --format csv
expect_rc 2 "400 cd at 1e-162 m: exit 2"
expect_err_match "near2.scene:[0-9]+: receiver 'floor', point 1 \(0, 0, 0 m\): illuminance_lx is infinite from luminaire 'lamp'" "1e-162 m: the receiver and the luminaire named"
sed -e 's/0 m, 0 m, 2 m/0 m, 0 m, 0 m/' tests/data/scenes/point.scene >"$T/near3.scene"
run scene "$T/near3.scene" --format csv
expect_rc 2 "a point source on the receiver point: exit 2"
expect_err_match "illuminance_lx is NaN from luminaire 'lamp'.*a point source sits on the point" "on the point: undefined"
