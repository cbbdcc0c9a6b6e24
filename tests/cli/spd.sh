# spd.sh - CLI cases for `luxcalc spd`, `blackbody` and `daylight` (run by tests/run.sh).
. tests/cli/lib.sh
S=samples/spd

run spd --format csv $S/cie_illuminants.csv
expect_rc 0 "spd csv exits 0"
expect_out_match '^file,spectrum,X,Y,Z,x,y,u_prime,v_prime,cct_K,duv,ler_lm_per_W,scotopic_Y,sp_ratio' "csv columns as CLI.md fixes them"
# CIE 015:2018: D65 (0.31271, 0.32902), A (0.44757, 0.40745); the sample holds 380-780 nm at 5 nm
expect_field 2 x 0.31271 0.00005 "D65 x (CIE 015)"
expect_field 2 y 0.32902 0.00005 "D65 y (CIE 015)"
expect_field 1 x 0.44757 0.00005 "A x (CIE 015)"
expect_field 1 y 0.40745 0.00005 "A y (CIE 015)"

# a blackbody written by luxcalc reads back at its own temperature (Planck round trip)
run blackbody --temperature 2856K -o "$T/bb.csv"
expect_rc 0 "blackbody -o"
run spd --format csv "$T/bb.csv"
expect_field 1 cct_K 2856 0.1 "blackbody 2856 K: CCT round trip"
expect_field 1 duv 0 0.000001 "blackbody: Duv 0"
run blackbody --temperature 1e6 --range 360:830:5 --format csv
expect_rc 0 "blackbody at 1e6 K"
expect_out_match '^360,[0-9]' "blackbody 1e6 K: finite values"
run blackbody --temperature 1 --format csv
expect_out_match '^360,0$' "blackbody 1 K underflows to 0, not NaN"
run blackbody --temperature -5
expect_rc 1 "blackbody: negative temperature is a usage error"
expect_err_match '^luxcalc: blackbody: --temperature' "blackbody: message names the option"

# CIE daylight at 6504 K has CCT ~6504 K (D65) and Duv ~ +0.0032
run daylight --cct 6504 -o "$T/d65.csv"
run spd --format csv "$T/d65.csv"
expect_field 1 cct_K 6504 3 "daylight 6504 K: CCT"
run daylight --cct 3000
expect_rc 2 "daylight below 4000 K is an input error"

# standard input, json
run_stdin $S/laser_532nm.csv spd --unit W/nm --format json -
expect_rc 0 "stdin with -"
if printf '%s\n' "$out" | python3 -m json.tool >/dev/null 2>&1; then ok "json parses"; else notok "json parses" "$out"; fi
expect_out_match '"cct_K": null' "json: CCT of a laser line is null"
expect_out_match '"method": "exact"' "0.1 nm data integrates with exact"

# table format shows units
run spd --unit W/nm $S/laser_532nm.csv
expect_out_match '^Y +60\.44[0-9]* lm$' "table shows lm for W/nm"

# usage errors exit 1
run spd --observer 5 $S/cie_illuminants.csv
expect_rc 1 "bad observer"
run spd --method fast $S/cie_illuminants.csv
expect_rc 1 "bad method"
run spd
expect_rc 1 "no input file"
run spd --frobnicate $S/cie_illuminants.csv
expect_rc 1 "unknown option"
run spd --help
expect_rc 0 "help"
expect_out_match 'example' "help has an example"

# -o is atomic: an existing file survives a failed run; a missing file is exit 2
echo "precious" > "$T/keep.csv"
run spd -o "$T/keep.csv" "$T/missing.csv"
expect_rc 2 "missing input"
expect_err_match "^luxcalc: spd: $T/missing.csv" "missing input is named"
if [ "$(cat "$T/keep.csv")" = precious ]; then ok "output untouched on failure"; else notok "output untouched on failure" "$(cat "$T/keep.csv")"; fi
run spd -o "$T/keep.csv" --format csv $S/cie_illuminants.csv
expect_rc 0 "-o success"
if grep -q '^file,spectrum' "$T/keep.csv" && [ -z "$(ls "$T" | grep tmp)" ]; then ok "-o replaced the file, no temporary left"; else notok "-o" "$(ls "$T")"; fi
run spd -o /nonexistent-dir/x.csv $S/cie_illuminants.csv
expect_rc 2 "-o into a missing directory"

# the Argyll .sp sample holds FL2 and FL11: the same results as the CIE columns of the csv sample
run spd --format csv samples/spd/fl2_fl11_argyll.sp
a=$(printf '%s\n' "$out" | cut -d, -f2- | sed -n 2,3p)
run spd --format csv samples/spd/cie_illuminants.csv
b=$(printf '%s\n' "$out" | cut -d, -f2- | sed -n 4,5p)
if [ -n "$a" ] && [ "$a" = "$b" ]; then ok "Argyll .sp sample = csv sample, bit for bit"; else notok "Argyll .sp sample" "$a / $b"; fi
# values near the bottom of the double range: a flat 1e-320 (subnormal, 2024 x 2^-1074) has the
# chromaticity of a flat 1 (scale-free; it moved by 1.5e-5), and CRI and TM-30 (they were NaN)
printf 'nm,one,tiny\n' >"$T/sub.csv"
awk 'BEGIN { for (l = 380; l <= 780; l += 5) print l ",1,1e-320" }' >>"$T/sub.csv"
run spd --metrics cri,tm30 --format csv "$T/sub.csv"
expect_rc 0 "flat 1e-320: exit 0"
r=$(printf '%s\n' "$out" | awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
  { for (k in c) v[NR, k] = $c[k] }
  END { bad = ""; n = split("x y u_prime v_prime cct_K cri_ra tm30_rf tm30_rg", q, " ");
    for (i = 1; i <= n; i++) { a = v[2, q[i]]; b = v[3, q[i]]; d = a - b; if (d < 0) d = -d;
      if (a == "" || b == "" || d > 1e-9 * (a < 0 ? -a : a)) bad = bad " " q[i] ":" a "/" b }
    print bad }')
[ -z "$r" ] && ok "flat 1e-320: xy, CCT, CRI and TM-30 of a flat 1 (1e-9)" || notok "flat 1e-320: the flat 1's values" "$r"
