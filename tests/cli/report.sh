# report.sh - `luxcalc spd --report DIR`: one PNG per spectrum (names sanitised, repeated names kept
# apart), PNG signature and
# size, the refusal path (CRI undefined: still a report), --input-format f32 refused, atomic
# failure on an unusable DIR; and the progress bar (nothing on a non-terminal stderr; a bar on a
# pseudo-terminal through util-linux `script`, skipped when it is missing).
. tests/cli/lib.sh
S=samples/spd/cie_illuminants.csv   # A, D65, FL2, FL11

png_sig() { od -An -tx1 -N8 "$1" | tr -d ' \n'; }
# width and height from the IHDR chunk (bytes 16-23, big-endian)
png_size() { od -An -tu1 -j16 -N8 "$1" | awk '{print $1*16777216+$2*65536+$3*256+$4 "x" $5*16777216+$6*65536+$7*256+$8}'; }

run spd --report "$T/rep" --format csv "$S"
expect_rc 0 "report exits 0"
expect_out_match '^cie_illuminants.csv,FL11,|FL11' "results still printed with --report"
n=$(ls "$T/rep" | grep -v '_tm30\.png$' | grep -c '\.png$'); nt=$(ls "$T/rep" | grep -c '_tm30\.png$')
if [ "$n" -eq 4 ] && [ "$nt" -eq 4 ]; then ok "one report and one TM-30 page per spectrum"; else notok "one report and one TM-30 page per spectrum" "$n + $nt files: $(ls "$T/rep")"; fi
# the TM-30 page (IES TM-30-20 calculator layout): 1200x1080, the bins' bar colours and arrow
# colours in it (pixels read with tests/tools/pngpx)
px=${LX_BUILD_DIR:-build}/tests/pngpx
f="$T/rep/cie_illuminants_FL2_tm30.png"
if [ "$(png_size "$f")" = 1200x1080 ]; then ok "TM-30 page is 1200x1080"; else notok "TM-30 page is 1200x1080" "$(png_size "$f")"; fi
if [ -x "$px" ]; then
  bars=0; for c in A35C60 CC765E 61B290 708AB2; do [ "$("$px" "$f" count $c 1)" -gt 300 ] && bars=$((bars + 1)); done
  if [ "$bars" -eq 4 ]; then ok "hue-bin bars in the calculator's colours (bins 1, 2, 8, 12)"; else notok "hue-bin bar colours" "$bars of 4 colours found"; fi
  heads=$("$px" "$f" count E62828 12 0 100 620 800)
  if [ "$heads" -gt 15 ]; then ok "bin 1's arrow in its colour ($heads pixels)"; else notok "bin 1's arrow" "$heads pixels"; fi
else
  skip "TM-30 page pixels" "no $px"
fi
for s in A D65 FL2 FL11; do
  f="$T/rep/cie_illuminants_$s.png"
  if [ -f "$f" ] && [ "$(png_sig "$f")" = 89504e470d0a1a0a ]; then ok "$s report is a PNG"; else notok "$s report is a PNG" "missing or bad signature"; fi
done
sz=$(png_size "$T/rep/cie_illuminants_FL2.png")
if [ "$sz" = 1200x880 ]; then ok "report is 1200x880"; else notok "report is 1200x880" "$sz"; fi
bytes=$(wc -c < "$T/rep/cie_illuminants_FL2.png")
if [ "$bytes" -gt 20000 ] && [ "$bytes" -lt 400000 ]; then ok "report size plausible"; else notok "report size plausible" "$bytes bytes"; fi
if ls -a "$T/rep" | grep -q 'tmp'; then notok "no temporary files left" "$(ls -a "$T/rep")"; else ok "no temporary files left"; fi

# names are sanitised; an unnamed spectrum takes its index
printf 'wavelength_nm,my lamp/1,\n' > "$T/odd name.csv"
for l in $(seq 380 5 780); do printf '%s,1,%s\n' "$l" "$((l % 7 + 1))" >> "$T/odd name.csv"; done
run spd --report "$T/rep2" "$T/odd name.csv"
expect_rc 0 "odd names exit 0"
if [ -f "$T/rep2/odd_name_my_lamp_1.png" ] && [ "$(ls "$T/rep2" | grep -vc _tm30)" -eq 2 ]; then ok "names sanitised"
else notok "names sanitised" "$(ls "$T/rep2")"; fi

# names that repeat (two columns "lamp", and "a b" / "a_b" which reduce to one name): one file each
printf 'wavelength_nm,lamp,lamp,a b,a_b\n' > "$T/same.csv"
for l in $(seq 380 5 780); do printf '%s,1,2,%s,1\n' "$l" "$((l % 7 + 1))" >> "$T/same.csv"; done
run spd --report "$T/rep6" --diagram uv "$T/same.csv"
expect_rc 0 "repeated names exit 0"
if [ "$(ls "$T/rep6" | grep -v _tm30 | tr '\n' ' ')" = "same_a_b.png same_a_b_2.png same_lamp.png same_lamp_2.png " ]; then ok "one file per spectrum when names repeat"
else notok "one file per spectrum when names repeat" "$(ls "$T/rep6")"; fi
run spd --report "$T/rep6" --diagram lab "$T/same.csv"
expect_rc 1 "--diagram takes xy or uv"

# CRI undefined (a 532 nm laser, Duv far beyond 0.05): the report is written, with the reason
run spd --report "$T/rep3" samples/spd/laser_532nm.csv
expect_rc 0 "laser report exits 0"
if [ -f "$T/rep3/laser_532nm_laser_532nm.png" ]; then ok "report for a spectrum without CRI"; else notok "report for a spectrum without CRI" "$(ls "$T/rep3")"; fi
if [ ! -e "$T/rep3/laser_532nm_laser_532nm_tm30.png" ]; then ok "no TM-30 page where TM-30 is undefined"; else notok "no TM-30 page for a laser" "$(ls "$T/rep3")"; fi

# the batch path (forced by --backend) still writes one report per spectrum
run spd --backend cpu --report "$T/rep4" "$S"
n=$(ls "$T/rep4" 2>/dev/null | grep -v _tm30 | grep -c '\.png$')
if [ "$rc" -eq 0 ] && [ "$n" -eq 4 ]; then ok "reports with --backend"; else notok "reports with --backend" "rc $rc, $n files"; fi

# refused with raw float32 input
run spd --input-format f32 --grid 380:780:5 --report "$T/rep5" /dev/null
expect_rc 1 "--report with f32 is a usage error"
expect_err_match 'report is not available with --input-format f32' "f32 refusal names the reason"

# DIR unusable: a regular file, or below one: exit 2, nothing written
: > "$T/plain"
run spd --report "$T/plain" "$S"
expect_rc 2 "DIR that is a file: exit 2"
expect_err_match 'not a directory' "DIR that is a file: message"
run spd --report "$T/plain/sub" "$S"
expect_rc 2 "DIR below a file: exit 2"
if [ ! -s "$T/plain" ] && [ ! -e "$T/plain/sub" ]; then ok "nothing written for an unusable DIR"; else notok "nothing written for an unusable DIR" "found output"; fi
# a read-only DIR (meaningless for root, who may write anyway)
if [ "$(id -u)" != 0 ]; then
  mkdir "$T/ro" && chmod 555 "$T/ro"
  run spd --report "$T/ro" "$S"
  expect_rc 2 "read-only DIR: exit 2"
  if [ -z "$(ls -A "$T/ro")" ]; then ok "read-only DIR stays empty"; else notok "read-only DIR stays empty" "$(ls -A "$T/ro")"; fi
  chmod 755 "$T/ro"
fi

# progress bar: 300 spectra take the per-spectrum path with a bar, but stderr is not a terminal here
{ printf 'wavelength_nm'; i=1; while [ $i -le 300 ]; do printf ',s%d' $i; i=$((i+1)); done; printf '\n'
  for l in $(seq 380 10 780); do printf '%s' "$l"; i=1; while [ $i -le 300 ]; do printf ',%d' $(((l + i) % 13 + 1)); i=$((i+1)); done; printf '\n'; done
} > "$T/many.csv"
run spd --method exact --format csv "$T/many.csv"
expect_rc 0 "300 spectra exit 0"
if [ -z "$err" ]; then ok "no progress output when stderr is not a terminal"; else notok "no progress output when stderr is not a terminal" "$err"; fi
if command -v script >/dev/null 2>&1 && script -qc true /dev/null >/dev/null 2>&1; then
  # stdout to a file, stderr (the pseudo-terminal) captured by script's typescript
  NO_COLOR=1 script -qc "'$LUXCALC' spd --method exact --format csv '$T/many.csv' > '$T/pty_out'" "$T/typescript" >/dev/null 2>&1
  if grep -q '\[#*-*\] *[0-9.]*%' "$T/typescript" && grep -q '100.0%' "$T/typescript"; then ok "progress bar on a terminal"
  else notok "progress bar on a terminal" "$(cat "$T/typescript" | tr '\r' '\n' | tail -n 3)"; fi
  if grep -q "$(printf '\033')" "$T/typescript"; then notok "NO_COLOR: no escape codes" "escape found"; else ok "NO_COLOR: no escape codes"; fi
  script -qc "'$LUXCALC' spd -q --method exact --format csv '$T/many.csv' > '$T/pty_out'" "$T/typescript2" >/dev/null 2>&1
  if grep -q '%' "$T/typescript2"; then notok "-q: no progress bar" "$(cat "$T/typescript2")"; else ok "-q: no progress bar"; fi
  if [ "$(wc -l < "$T/pty_out")" -eq 301 ]; then ok "results intact with a bar"; else notok "results intact with a bar" "$(wc -l < "$T/pty_out") lines"; fi
else
  skip "progress bar on a terminal" "no util-linux script"
fi
