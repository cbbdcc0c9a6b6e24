# instruments.sh - `luxcalc spd` on spectra as instruments write them: every real export of
# $LX_SHARED_DIR/spectra/instruments (skipped when absent) with the instrument's own results beside
# luxcalc's, the synthetic file of each layout (tests/data/instruments/good, "Sample #1" in each),
# each bad variant (tests/data/instruments/bad_expected.txt), --skip-bad-rows, units, the reader
# options, --input-format, and the PAR / hazard / binning columns on the batch path.
. tests/cli/lib.sh
D=tests/data/instruments
I=${LX_SHARED_DIR:-../shared}/spectra/instruments
re_escape() { printf '%s' "$1" | sed 's/[][\.*^$+?(){}|/]/\\&/g'; }
col() { # col NAME: the values of csv column NAME, one per line
  printf '%s\n' "$out" | python3 -c 'import csv,sys
r=list(csv.DictReader(sys.stdin))
for x in r: print(x[sys.argv[1]])' "$1" 2>/dev/null
}
have_py=0; python3 -c 'import csv, json' 2>/dev/null && have_py=1

# ---- the real exports: format by content, the rows SOURCES.md describes ----
if [ -d "$I" ]; then
  for spec in "ocean_optics_flame_spectrometer.txt oceanview 1" "RANDOM_001_02._3262K.csv sekonic 2" \
              "uprtek.xls.txt uprtek 1" "ESPD2021_0104_231446.xls uprtek 1" "Fluorescent.spdx tm27 1" \
              "X-Rite_Digital_Colour_Checker.txt cgats 10" "avantes-avaspec-e-irrad.csv avantes 1" \
              "oo-spectrum.OVIrrad oceanview 1" "oo-spectrum-comma.SSIrrad oceanview 1" \
              "licor-li180-irrad.txt uprtek 1" "irr_820_1941.IRR spectrawiz 1" "avasoft8.txt avantes 4" \
              "example121.sp cgats 1" "CRT.ccss cgats 14"; do
    set -- $spec
    run spd --format csv "$I/$1"
    expect_rc 0 "$1 reads"
    n=$(printf '%s\n' "$out" | tail -n +2 | wc -l)
    [ "$n" -eq "$3" ] && ok "$1: $3 spectra" || notok "$1: $3 spectra" "$n rows: $out"
    if [ $have_py = 1 ]; then
      run spd --format json "$I/$1"
      f=$(printf '%s' "$out" | python3 -c 'import json,sys
d=json.load(sys.stdin); d=d if isinstance(d,list) else [d]; print(d[0]["instrument"]["format"])' 2>&1)
      [ "$f" = "$2" ] && ok "$1: json instrument format $2" || notok "$1: json instrument format $2" "$f"
    else
      skip "$1: json instrument format" "python3 is not installed"
    fi
  done
  # the instrument's own results beside luxcalc's (UPRtek: mW/m2/nm converted, so Y is the meter's LUX)
  run spd --metrics vendor --format csv "$I/uprtek.xls.txt"
  expect_rc 0 "uprtek --metrics vendor"
  expect_field 1 Y 695.1549 0.01 "uprtek: Y is the meter's LUX (695.1549 lx) within 10 ppm"
  expect_field 1 vendor_illuminance_lx 695.154907 0 "uprtek: vendor_illuminance_lx"
  expect_field 1 vendor_cct_K 5198 0 "uprtek: vendor_cct_K"
  expect_field 1 cct_K 5198 2 "uprtek: luxcalc's CCT within 2 K of the meter's"
  expect_field 1 vendor_cri_ra 92.956993 0 "uprtek: vendor_cri_ra"
  expect_field 1 vendor_cri_r15 88.615669 0 "uprtek: vendor_cri_r15"
  run spd --metrics vendor,par --format csv "$I/licor-li180-irrad.txt"
  expect_field 1 vendor_ppfd_umol_m2_s 129.87944 0 "licor: vendor PPFD"
  expect_field 1 par_ppfd 129.88 0.5 "licor: luxcalc's PPFD within 0.4 % of the meter's"
  run spd --metrics vendor --format csv "$I/RANDOM_001_02._3262K.csv"
  expect_field 2 vendor_cct_K 3262 0 "sekonic: vendor_cct_K"
  expect_field 2 Y 30.1 0.05 "sekonic: Y (W/m2/nm as exported) is the meter's 30.1 lx"
  expect_field 2 vendor_cri_r9 31.2 0 "sekonic: vendor_cri_r9"
  run spd --metrics vendor --format csv "$I/Fluorescent.spdx"
  if [ $have_py = 1 ]; then
    v=$(col vendor_cct_K)
    [ -z "$v" ] && ok "tm27: no vendor results, empty columns" || notok "tm27: no vendor results, empty columns" "'$v'"
  else
    skip "tm27: no vendor results" "python3 is not installed"
  fi
else
  skip "real instrument exports" "$I is absent"
fi

# ---- the synthetic layouts: "Sample #1" in each ----
for f in excel.csv excel_semicolon.csv preamble.csv micrometres.csv micrometres_header.csv angstrom.csv rows_hash.csv \
         oceanview.txt sekonic.csv uprtek.xls tm27.spdx avasoft.csv avasoft8.txt cgats_hash.cgats; do
  run spd --format csv "$D/good/$f"
  expect_rc 0 "good/$f reads"
  expect_out_match "^$(re_escape "$D/good/$f"),Sample #1( \(5 nm\)|\.txt)?," "good/$f: the spectrum 'Sample #1'"
done
# the same spectrum (A) in every layout: X and Y identical to the last digit where units agree
a=$("$LUXCALC" spd --format csv "$D/good/excel.csv" | sed -n 2p | cut -d, -f3-12)
for f in excel_semicolon.csv preamble.csv micrometres.csv micrometres_header.csv angstrom.csv rows_hash.csv oceanview.txt \
         spectrasuite.SSIrrad tm27.spdx spectrawiz.IRR avasoft8.txt cgats_hash.cgats; do
  b=$("$LUXCALC" spd --format csv "$D/good/$f" 2>/dev/null | sed -n 2p | cut -d, -f3-12)
  [ -n "$a" ] && [ "$a" = "$b" ] && ok "good/$f: same X..ler as excel.csv" || notok "good/$f: same X..ler as excel.csv" "$a / $b"
done

# ---- bad variants: FILE:LINE: what, exit 2, and a batch goes on ----
for f in "$D"/bad/*; do
  b=$(basename "$f")
  exp=$(awk -F'\t' -v f="$b" '$1 == f { print $2 "\t" $3 }' "$D/bad_expected.txt")
  if [ -z "$exp" ]; then notok "bad/$b" "no entry in bad_expected.txt"; continue; fi
  line=${exp%%"	"*}; frag=${exp#*"	"}
  run spd "$f" --format csv
  expect_rc 2 "bad/$b exits 2"
  expect_err_match "^luxcalc: spd: $(re_escape "$f"):$line: " "bad/$b names line $line"
  if printf '%s\n' "$err" | grep -Fq -- "$frag"; then ok "bad/$b says '$frag'"; else notok "bad/$b says '$frag'" "$err"; fi
done
run spd --format csv "$D/good/uprtek.xls" "$D/bad/oceanview_count.txt" "$D/good/tm27.spdx"
expect_rc 2 "a batch with a bad export exits 2"
expect_out_match "uprtek.xls,Sample #1," "the batch prints the export before the bad one"
expect_out_match "tm27.spdx,Sample #1," "the batch prints the export after the bad one"
expect_err_match "oceanview_count.txt:3: the header gives 5 pixels" "the batch reports the bad export"

# ---- --skip-bad-rows ----
run spd --format csv "$D/good/skip_bad_rows.csv"
expect_rc 2 "bad rows: the file is refused without --skip-bad-rows"
expect_err_match "skip_bad_rows.csv:3: value is not a number" "bad rows: the first bad row is named"
run spd --skip-bad-rows --format csv "$D/good/skip_bad_rows.csv" "$D/good/excel.csv"
expect_rc 2 "--skip-bad-rows: exit status 2"
expect_out_match "skip_bad_rows.csv,Sample #1," "--skip-bad-rows: the rest of the file is computed"
expect_out_match "excel.csv,Sample #1," "--skip-bad-rows: the next file too"
for l in 3 5 6 8; do expect_err_match "skip_bad_rows.csv:$l: bad row skipped: " "--skip-bad-rows: reports line $l"; done
expect_err_match "skip_bad_rows.csv: 4 bad rows skipped" "--skip-bad-rows: the count"
# 100000 rows with one bad row: reported, the rest read
awk 'BEGIN { print "nm,A"; for (i = 0; i < 100000; i++) printf "%.4f,%s\n", 380 + i * 0.004, (i == 5000 ? "x" : "1") }' > "$T/big.csv"
run spd --skip-bad-rows --format csv "$T/big.csv"
expect_rc 2 "100000 rows, one bad: exit 2"
expect_err_match "big.csv:5002: bad row skipped: value is not a number: 'x'" "100000 rows, one bad: the row is named"
expect_out_match "big.csv,A," "100000 rows, one bad: the spectrum is computed"

# ---- units ----
run spd -v --format csv "$D/good/micrometres.csv"
expect_err_match "every wavelength is below 10: read as micrometres" "-v says micrometres were found from the range"
run spd --wavelength-unit nm --format csv "$D/good/micrometres.csv"
expect_rc 2 "--wavelength-unit nm keeps 0.38-0.4 nm: no luminous content, exit 2"
expect_err_match "warning: .*micrometres.csv:1: spectrum 'Sample #1' \(0.38-0.4 nm\) has no overlap with 360-830 nm" \
  "a spectrum outside 360-830 nm is warned about"
expect_err_match "micrometres.csv:1: spectrum 'Sample #1': x is undefined" "... and its undefined chromaticity reported"
run spd -q --wavelength-unit nm --format csv "$D/good/micrometres.csv"
printf '%s\n' "$err" | grep -q warning && notok "-q silences the warning" "$err" || ok "-q silences the warning"
run spd -v --format csv "$D/good/uprtek.xls"
expect_err_match "values in W/m2/nm \(UPRtek export: mW/m2/nm\), converted" "-v says the UPRtek values were converted"
run spd --unit W/nm --format csv "$D/good/uprtek.xls"
expect_err_match "warning: its format gives values in W/m2/nm" "--unit against the format's unit is warned about"

# ---- reader options ----
run spd --columns nm,"Sample #1" --format csv "$D/good/columns_pick.csv"
expect_rc 0 "--columns by name"
expect_out_match "columns_pick.csv,Sample #1,133.600313715," "--columns: the named column"
run spd --columns 2,4,5 --format csv "$D/good/columns_pick.csv"
expect_out_match "columns_pick.csv,Lamp B," "--columns by number"
run spd --columns nm,Nope --format csv "$D/good/columns_pick.csv"
expect_rc 2 "--columns with an unknown name exits 2"
expect_err_match "no column 'Nope'" "--columns names the unknown column"
run spd --skip-lines 4 --format json "$D/good/preamble.csv"
expect_rc 0 "--skip-lines"
if [ $have_py = 1 ]; then
  n=$(printf '%s' "$out" | python3 -c 'import json,sys; print(len(json.load(sys.stdin)[0]["instrument"]["fields"]))')
  [ "$n" = 0 ] && ok "--skip-lines: the preamble's fields are skipped" || notok "--skip-lines: the preamble's fields are skipped" "$n"
  run spd --format json "$D/good/preamble.csv"
  v=$(printf '%s' "$out" | python3 -c 'import json,sys; print(json.load(sys.stdin)[0]["instrument"]["fields"]["Operator"])')
  [ "$v" = "Sample #1 tester" ] && ok "json: the preamble's fields" || notok "json: the preamble's fields" "$v"
else
  skip "--skip-lines fields" "python3 is not installed"
fi
run spd --input-format sekonic --format csv "$D/good/excel.csv"
expect_rc 2 "--input-format forces a layout"
expect_err_match "excel.csv:9: no 'Spectral Data NNN\[nm\],value' rows" "--input-format: the forced reader's error"
run spd --input-format xlsx "$D/good/excel.csv"
expect_rc 1 "--input-format with an unknown name is a usage error"
run spd --input-format columns --format csv "$D/good/excel.csv"
expect_rc 0 "--input-format columns"
run spd --skip-lines x "$D/good/excel.csv"
expect_rc 1 "--skip-lines x is a usage error"
run spd --wavelength-unit furlong "$D/good/excel.csv"
expect_rc 1 "--wavelength-unit furlong is a usage error"

# ---- the old failures of issue 19, now read ----
printf 'nm,A,B,,\n380,1,2,,\n385,1,2,,\n,,,,\n' > "$T/trailing.csv"
run spd --format csv "$T/trailing.csv"
expect_rc 0 "Excel's trailing ,, columns and rows"
printf 'id,380,385,390,395\nSample #1,1,2,3,4\n' > "$T/rows_hash.csv"
run spd --format csv "$T/rows_hash.csv"
expect_out_match ",Sample #1," "a rows-layout name 'Sample #1' is not cut at '#'"

# ---- PAR, hazard and binning: the batch path agrees with the per-spectrum path ----
awk 'BEGIN { printf "id"; for (l = 380; l <= 780; l += 5) printf ",%d", l; print "";
  for (i = 0; i < 1100; i++) { printf "s%d", i; T = 2200 + 4 * i;
    for (l = 380; l <= 780; l += 5) { x = 1.4388e7 / (l * T); printf ",%.9g", 1e17 / (l ^ 5 * (exp(x) - 1)) } print "" } }' > "$T/many.csv"
head -n 11 "$T/many.csv" > "$T/few.csv"
M=par,hazard,binning
run spd --metrics $M --unit W/m2/nm --format csv "$T/many.csv"
expect_rc 0 "batch path with --metrics $M"
big=$(printf '%s\n' "$out" | sed -n 2,11p)
run spd --metrics $M --unit W/m2/nm --format csv "$T/few.csv"
small=$(printf '%s\n' "$out" | sed -n 2,11p)
hdr=$(printf '%s\n' "$out" | head -n 1)
r=$(printf '%s\n%s\n' "$small" "$big" | awk -F, -v h="$hdr" 'BEGIN { n = split(h, H, ",") }
  NR <= 10 { for (i = 1; i <= NF; i++) a[NR, i] = $i; next }
  { for (i = 3; i <= NF; i++) { if (H[i] == "method") continue; x = a[NR - 10, i]; y = $i;
      if (x == y) continue; if (x + 0 != x || y + 0 != y) { print H[i] ": " x " / " y; exit }
      d = x - y; if (d < 0) d = -d; s = (x < 0 ? -x : x); if (d > 1e-9 * s + 1e-12) { print H[i] ": " x " / " y; exit } } }')
[ -z "$r" ] && ok "batch and per-spectrum rows agree (1e-9) in every --metrics $M column" ||
  notok "batch and per-spectrum rows agree (1e-9) in every --metrics $M column" "$r"
expect_out_match "not covered" "380-780 nm data: thermal and UV hazards are 'not covered'"
run spd --metrics par --photoperiod 16 --unit W/m2/nm --format csv "$T/few.csv"
if [ $have_py = 1 ]; then
  p=$(printf '%s\n' "$out" | python3 -c 'import csv,sys
r=list(csv.DictReader(sys.stdin))[0]; print("%.12g" % (float(r["par_dli_mol_m2_d"]) / float(r["par_ppfd"])))' 2>/dev/null)
  [ "$p" = "0.0576" ] && ok "DLI = PPFD * 3600 * 16 / 1e6" || notok "DLI = PPFD * 3600 * 16 / 1e6" "$p"
else
  skip "DLI = PPFD * 3600 * 16 / 1e6" "python3 is not installed"
fi
run spd --metrics hazard --subtense 0.011 --unit W/sr/m2/nm --format csv "$T/few.csv"
expect_out_match ",exempt,L_B," "radiance: the risk group from L_B (L_R not covered by 380-780 nm data)"
# in table format "not covered" is a word, not a value: no unit after it (numbers keep theirs)
run spd --metrics hazard --subtense 0.011 --unit W/sr/m2/nm "$T/few.csv"
expect_out_match '^hazard_thermal +not covered$' "table: 'not covered' without a unit"
expect_out_match '^hazard_blue +[0-9.e+-]+ W/\(sr m2\)$' "table: a covered hazard keeps its unit"
# the source's size decides the blue-light limit and the basis says which, with the size assumed
run spd --metrics hazard --unit W/m2/nm --format csv "$T/few.csv"
expect_out_match ',exempt,E_B \(small source assumed\),,' "irradiance without --subtense: E_B, a small source assumed"
run spd --metrics hazard --unit W/m2/nm --subtense 0.1 --format csv "$T/few.csv"
expect_out_match ',exempt,L_B \(E_B/Omega\),0.1,' "irradiance with --subtense 0.1: L_B = E_B / Omega, the subtense printed"
run spd --metrics hazard --unit W/m2/nm --subtense 0.6deg --format csv "$T/few.csv"
expect_out_match ',exempt,E_B,0.010471975511965976,' "irradiance with --subtense 0.6deg (below 0.011 rad): E_B"
if [ -f "$I/licor-li180-irrad.txt" ]; then
  # E_B = 5.881 W m-2: RG2 as a small source (1 < E_B <= 400); as a 0.1 rad source L_B = 5.881 / 7.851e-3 sr
  # = 749 W m-2 sr-1: RG1 (100 < L_B <= 1e4; IEC 62471:2006 Table 6.1)
  run spd --metrics hazard --format csv "$I/licor-li180-irrad.txt"
  expect_out_match ',RG2,E_B \(small source assumed\),,' "LI-180 without --subtense: RG2 from E_B, small source assumed"
  run spd --metrics hazard --subtense 0.1 --format csv "$I/licor-li180-irrad.txt"
  expect_out_match ',RG1,L_B \(E_B/Omega\),0.1,' "LI-180 with --subtense 0.1: RG1 from L_B = E_B / Omega"
else
  skip "LI-180 risk group and --subtense" "$I is absent"
fi
run spd --metrics hazard --unit W/sr/m2/nm --format csv "$D/good/excel.csv"
expect_out_match ',,,"blue,thermal,actinic_uv,uva"$' "380-400 nm data: no hazard is covered, no risk group"
