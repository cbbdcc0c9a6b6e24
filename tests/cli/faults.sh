# faults.sh - atomic output under faults (issue 10): a long batch writing -o FILE is killed with SIGTERM,
# SIGINT and SIGHUP mid-run; a run fails on bad input; a run cannot create its temporary file. Each
# time the existing FILE must be untouched and no temporary file left behind; a run that succeeds
# replaces FILE.
. tests/cli/lib.sh
D=$T/batch
mkdir -p "$D"
src=samples/spd/cie_illuminants.csv
i=0
while [ $i -lt 3000 ]; do cp "$src" "$D/s$i.csv"; i=$((i + 1)); done
OUT=$T/dest/result.csv
mkdir -p "$T/dest"
leftovers() { ls "$T/dest" | grep -v '^result.csv$' | tr '\n' ' '; }
reset_out() { printf 'previous contents\n' >"$OUT"; }
untouched() { # NAME
  if [ "$(cat "$OUT")" = "previous contents" ]; then ok "$1: the existing output is untouched"
  else notok "$1: the existing output is untouched" "now: $(head -c 200 "$OUT")"; fi
  l=$(leftovers)
  [ -z "$l" ] && ok "$1: no temporary file left" || notok "$1: no temporary file left" "$l"
}

# a long batch (3000 files, every metric: seconds), killed once its temporary file holds rows. A
# non-interactive shell starts background jobs with SIGINT ignored (and nohup ignores SIGHUP), and
# luxcalc rightly keeps ignored what its parent ignored: env --default-signal (coreutils >= 8.31)
# gives the job the defaults back
if env --default-signal=INT,TERM,HUP true 2>/dev/null; then dflt="env --default-signal=INT,TERM,HUP"; sigs="TERM INT HUP"
else dflt=""; sigs="TERM"; skip "SIGINT and SIGHUP cases" "no env --default-signal"; fi
for sig in $sigs; do
  reset_out
  $dflt "$LUXCALC" spd "$D/*.csv" --metrics all --format csv -o "$OUT" >/dev/null 2>"$T/err" &
  pid=$!
  n=0
  while [ $n -lt 600 ]; do # up to 60 s for the first rows to reach the temporary file
    tmp=$(ls "$T"/dest/result.csv.tmp* 2>/dev/null | head -n 1)
    [ -n "$tmp" ] && [ -s "$tmp" ] && break
    kill -0 $pid 2>/dev/null || break
    sleep 0.1; n=$((n + 1))
  done
  if kill -0 $pid 2>/dev/null && [ -n "$tmp" ]; then
    ok "SIG$sig: the batch is writing its temporary file ($(wc -c <"$tmp") bytes so far)"
    kill -$sig $pid
    wait $pid 2>/dev/null; rc=$?
    [ $rc -gt 128 ] && ok "SIG$sig: the batch stopped (exit $rc)" || notok "SIG$sig: the batch stopped" "exit $rc"
    untouched "SIG$sig mid-run"
  else
    wait $pid
    notok "SIG$sig: the batch was still running with a temporary file" "it finished or never wrote one"
  fi
done
# a SIGINT that the parent ignores (nohup-like) is not taken over: the batch finishes and replaces FILE
reset_out
(trap '' INT; exec "$LUXCALC" spd "$D/s1*.csv" --format csv -o "$OUT" >/dev/null 2>&1) &
pid=$!
sleep 0.2
kill -INT $pid 2>/dev/null
wait $pid; rc=$?
[ $rc -eq 0 ] && grep -q '^file,spectrum' "$OUT" && ok "an ignored SIGINT stays ignored (the run completes)" ||
  notok "an ignored SIGINT stays ignored" "exit $rc"

# a failure: bad input, exit 2, nothing replaced
reset_out
run ies tests/bad/ies/ies_num_nan.ies --format csv -o "$OUT"
expect_rc 2 "bad input with -o exits 2"
untouched "bad input"
# a failure to create the temporary file (its directory is missing)
run spd "$src" --format csv -o "$T/no_such_dir/result.csv"
expect_rc 2 "-o into a missing directory exits 2"
expect_err_match "cannot create" "-o into a missing directory says it cannot create the file"
[ ! -e "$T/no_such_dir" ] && ok "-o into a missing directory creates nothing" || notok "-o into a missing directory creates nothing" ""
# success replaces the file, and leaves nothing else
reset_out
run spd "$src" --format csv -o "$OUT"
expect_rc 0 "a good run with -o exits 0"
grep -q '^file,spectrum,X' "$OUT" && ok "a good run replaces the output" || notok "a good run replaces the output" "$(head -c 200 "$OUT")"
l=$(leftovers)
[ -z "$l" ] && ok "a good run leaves no temporary file" || notok "a good run leaves no temporary file" "$l"

# OpenCL faults through the CLI (LX_CL_FAULT, see tests/test_faults.c for the library): --backend opencl
# gives exit 3 and names the call; auto (made to pick OpenCL) logs the fall-back with -v and prints the
# CPU's own numbers
# (the fault hooks exist only in the test build of the library: tests/luxcalc-faults)
if [ "$("$LUXCALC" devices 2>/dev/null | grep -c '^device_name')" -gt 0 ]; then
  run spd "$src" --backend cpu --format csv
  cpu_out=$out
  LX_CL_FAULT=clGetPlatformIDs run spd "$src" --backend opencl --format csv
  expect_rc 0 "the shipped luxcalc has no fault hooks (LX_CL_FAULT does nothing)"
  LUXCALC=$LX_BUILD_DIR/tests/luxcalc-faults
  for fault in clGetPlatformIDs clBuildProgram clCreateBuffer clEnqueueNDRangeKernel clFinish; do
    LX_CL_FAULT=$fault run spd "$src" --backend opencl --format csv
    expect_rc 3 "$fault: --backend opencl exits 3"
    case $fault in clGetPlatformIDs) what="no OpenCL platform" ;; *) what=$fault ;; esac
    expect_err_match "^luxcalc: spd: .*$what" "$fault: --backend opencl names the failure"
    LX_CL_FAULT=$fault LX_AUTO_BREAK_EVEN=0 run spd "$src" --backend auto --format csv -v
    expect_rc 0 "$fault: --backend auto still succeeds"
    expect_err_match "falling back to the CPU path" "$fault: --backend auto logs the fall-back"
    [ "$out" = "$cpu_out" ] && ok "$fault: --backend auto prints the CPU's numbers" ||
      notok "$fault: --backend auto prints the CPU's numbers" "differs"
  done
else
  skip "OpenCL faults through the CLI" "no OpenCL device"
fi
exit 0
