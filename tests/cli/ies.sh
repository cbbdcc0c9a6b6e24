# ies.sh - `luxcalc ies`: a file that is neither LM-63 nor EULUMDAT says so (bytes escaped); the
# summary's opening shape (round openings as a positive diameter), light output ratio, input watts
# and efficacy; the writer: a converted file keeps its test, laboratory, date, lamp and catalogue
# fields (long values in [MORE] lines), a model's file carries real metadata and clean angles, and
# --write x.ldt is refused (the writer writes LM-63-2002 only).
. tests/cli/lib.sh
SH=${LX_SHARED_DIR:-../shared}/ies

# (binary files are refused before this, by the reader: tests/cli/bounded.sh)
printf 'caf\351 lamp data\177 v2\nformat: custom\nrows: 3\n' > "$T/zip.ies"
run ies "$T/zip.ies"
expect_rc 2 "neither format: an input error"
expect_err_match 'neither IES LM-63 .* nor EULUMDAT' "neither format: says so"
expect_err_match 'begins "caf\\xE9 lamp data\\x7F v2"' "non-printable bytes escaped"

run ies --write "$T/x.ldt" --model point --flux 1000lm
expect_rc 1 "--write x.ldt is refused"
expect_err_match 'writes IES LM-63-2002, not EULUMDAT' "the refusal says why"
[ -e "$T/x.ldt" ] && notok "nothing written for x.ldt" "found" || ok "nothing written for x.ldt"

# a model: real metadata (SOURCE_DATE_EPOCH sets the issue date for reproducible files), clean angles
SOURCE_DATE_EPOCH=0 run ies --write "$T/m.ies" --model warn --beam 10deg --flux 800lm --step 0.1deg
expect_rc 0 "ies --write from a model"
if grep -q '^\[ISSUEDATE\] 1970-01-01' "$T/m.ies"; then ok "model: an issue date"; else notok "model: an issue date" "$(grep ISSUEDATE "$T/m.ies")"; fi
if grep -q '^\[ISSUEDATE\] none' "$T/m.ies"; then notok "no [ISSUEDATE] none" "found"; else ok "no [ISSUEDATE] none"; fi
if grep -q '^\[TEST\] computed by luxcalc' "$T/m.ies" && grep -q '^\[LAMP\] Warn spotlight' "$T/m.ies"; then ok "model: test and lamp say what it is"
else notok "model: test and lamp say what it is" "$(head -8 "$T/m.ies")"; fi
if grep -q '0000000000000' "$T/m.ies"; then notok "clean angles" "$(grep -m1 '0000000000000' "$T/m.ies")"; else ok "clean angles"; fi
if grep -q '^0 0.1 0.2 0.3 0.4 0.5 0.6 0.7 0.8 0.9' "$T/m.ies"; then ok "angles 0.1 deg apart as written by hand"; else notok "angles 0.1 deg apart" "$(sed -n 14p "$T/m.ies")"; fi
if grep -q '^\[_ABSOLUTELUMENS\] 800' "$T/m.ies"; then ok "800 lm, not 8e+02"; else notok "800 lm" "$(grep ABSOLUTE "$T/m.ies")"; fi
# the sample's opening: a 0.3 m square panel
run ies --format csv samples/ies/downlight_lambert_1000lm.ies
expect_out_match ',rectangle,0\.3,0\.3,0,' "sample panel: a 0.3 m square rectangle"

if [ -f "$SH/02_rab_boa2_quadrant.ies" ]; then
  run ies --write "$T/c.ies" "$SH/02_rab_boa2_quadrant.ies"
  expect_rc 0 "convert a third-party file"
  for k in '[TEST] ITL84772' '[TESTLAB] INDEPENDENT TESTING LABORATORIES, INC.' '[ISSUEDATE] 06/02/15' \
           '[MANUFAC] RAB LIGHTING INC.' '[LUMCAT] BOA2-10D10+BOA2LED-40N / BOA2P-10D10-40N-S (TRIMLESS RECESSED / PENDENT)'; do
    if grep -qF "$k" "$T/c.ies"; then ok "converted file keeps $k"; else notok "converted file keeps $k" "$(head -12 "$T/c.ies")"; fi
  done
  if grep -q '^\[MORE\] ' "$T/c.ies" && [ "$(awk '{ if (length($0) > 256) n++ } END { print n + 0 }' "$T/c.ies")" -eq 0 ]; then
    ok "a long description goes on in [MORE] lines under 256 characters"; else notok "[MORE] lines" "$(grep -c MORE "$T/c.ies")"; fi
  a=$("$LUXCALC" ies --format csv "$SH/02_rab_boa2_quadrant.ies" | awk -F, 'NR==2{print $3}')
  b=$("$LUXCALC" ies --format csv "$T/c.ies" | awk -F, 'NR==2{print $3}')
  if awk -v a="$a" -v b="$b" 'BEGIN{d=a-b; if(d<0)d=-d; exit !(d <= 1e-9*a)}'; then ok "the converted file has the same flux"; else notok "same flux" "$a vs $b"; fi
else
  skip "converted file keeps its fields" "no $SH (LX_SHARED_DIR)"
fi
if [ -f "$SH/01_rab_dled6r8y_axial.ies" ]; then
  # its opening is written -0.1385 x -0.1385 (LM-63: negative equal width and length: round)
  run ies --format csv "$SH/01_rab_dled6r8y_axial.ies"
  expect_out_match ',round,0\.13' "negative width and length: a round opening"
  expect_field 1 diameter_m 0.138 0.001 "with a positive diameter"
  expect_field 1 width_m 0.138 0.001 "and no negative width"
  expect_field 1 input_watts 8.64 0 "input watts"
  expect_out_match ',RAB LIGHTING, INC\.,DLED6R8Y$|"RAB LIGHTING, INC\.",DLED6R8Y$' "manufacturer and catalogue number"
else
  skip "round openings" "no $SH (LX_SHARED_DIR)"
fi
if [ -f "$SH/11_ledalite_examp1_iesna95_2lamp.ies" ]; then
  # relative photometry: 2 lamps x 2900 lm; LOR = lumens / 5800, efficacy = lumens / 63.7 W
  run ies --format csv "$SH/11_ledalite_examp1_iesna95_2lamp.ies"
  l=$(printf '%s\n' "$out" | awk -F, 'NR==2{print $3}')
  expect_field 1 lor "$(awk -v l="$l" 'BEGIN{printf "%.15g", l / 5800}')" 1e-12 "LOR of a relative file"
  expect_field 1 efficacy_lm_per_W "$(awk -v l="$l" 'BEGIN{printf "%.15g", l / 63.7}')" 1e-9 "lm/W from the input watts"
else
  skip "LOR" "no $SH (LX_SHARED_DIR)"
fi
