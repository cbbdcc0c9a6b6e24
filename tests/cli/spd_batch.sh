# spd_batch.sh - the batch paths of `luxcalc spd`: --backend, raw float32 input, parity with the
# per-spectrum reference path (1e-9 relative in double, 1e-6 for float32 input).
. tests/cli/lib.sh
S=samples/spd/led_batch.csv

# compare two csv outputs column by column (numeric columns 3-15) within a relative tolerance
same_within() { # FILE_A FILE_B REL NAME
  if awk -F, -v rel="$3" 'NR==FNR {a[FNR]=$0; next}
      FNR>1 { n=split(a[FNR], x, ","); split($0, y, ",");
              for (i=3; i<=15; i++) { if (x[i]=="" && y[i]=="") continue;
                d=x[i]-y[i]; if (d<0) d=-d; m=x[i]<0?-x[i]:x[i]; if (d > rel*m + 1e-300) { print "row " FNR " col " i ": " x[i] " vs " y[i]; bad=1 } } }
      END { exit bad }' "$1" "$2" >"$T/diff"; then ok "$4"; else notok "$4" "$(head -3 "$T/diff")"; fi
}

"$LUXCALC" spd --format csv $S > "$T/ref.csv"
"$LUXCALC" spd --backend cpu --format csv $S > "$T/cpu.csv"; rc=$?
expect_rc 0 "--backend cpu"
same_within "$T/ref.csv" "$T/cpu.csv" 1e-9 "batch CPU path = per-spectrum path (1e-9 relative)"
n=$(wc -l < "$T/cpu.csv")
if [ "$n" -eq 5 ]; then ok "batch path prints every spectrum"; else notok "batch rows" "$n lines"; fi

if "$LUXCALC" devices --format csv 2>/dev/null | awk 'END { exit !(NR > 1) }'; then
  POCL_CACHE_DIR=${POCL_CACHE_DIR:-$T} "$LUXCALC" spd --backend opencl --format csv $S > "$T/cl.csv"; rc=$?
  expect_rc 0 "--backend opencl"
  same_within "$T/ref.csv" "$T/cl.csv" 1e-9 "OpenCL batch = CPU reference (1e-9 relative)"
else
  skip "--backend opencl" "no OpenCL platform"
fi
run spd --backend gpu $S
expect_rc 1 "--backend gpu is a usage error"

# raw float32: the same spectra written by python as little-endian float32 rows
python3 - "$S" "$T/led.f32" <<'PY'
import struct, sys
rows = [l.rstrip('\n').split(',') for l in open(sys.argv[1]) if not l.startswith('#')]
with open(sys.argv[2], 'wb') as f:
    for r in rows[1:]:
        f.write(struct.pack('<%df' % (len(r) - 1), *[float(x) for x in r[1:]]))
PY
run spd --input-format f32 --grid 380:780:1 --format csv "$T/led.f32"
expect_rc 0 "f32 input"
printf '%s\n' "$out" > "$T/f32.csv"
same_within "$T/ref.csv" "$T/f32.csv" 1e-6 "f32 input = text input within float rounding (1e-6)"
expect_out_match "^$T/led.f32,4," "f32 spectra are named by index"
head -c 1000 "$T/led.f32" > "$T/short.f32"
run spd --input-format f32 --grid 380:780:1 "$T/short.f32"
expect_rc 2 "f32 file of a partial spectrum"
expect_err_match "not a whole number of spectra" "f32 size error says why"
run spd --input-format f32 --grid 380:780:7 "$T/led.f32"
expect_rc 1 "--grid that is not whole steps"
run spd --input-format f32 "$T/led.f32"
expect_rc 1 "f32 without --grid"
