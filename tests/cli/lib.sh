# lib.sh - helpers for CLI test cases (sourced). Each check prints "ok NAME" or "not ok NAME: why".
# $LUXCALC is the binary under test. Usage in a case file:
#   . tests/cli/lib.sh
#   run spd samples/spd/cie_a.csv --format csv     # sets $out, $err, $rc
#   expect_rc 0 "A parses"; expect_out_match '^file,spectrum,X' "csv header"
T=$(mktemp -d "${TMPDIR:-/tmp}/lxcli.XXXXXX")
trap 'rm -rf "$T"' EXIT
run() {
  "$LUXCALC" "$@" >"$T/out" 2>"$T/err"; rc=$?
  out=$(cat "$T/out"); err=$(cat "$T/err")
}
run_stdin() { # run_stdin FILE ARGS...: feeds FILE on standard input
  f=$1; shift
  "$LUXCALC" "$@" <"$f" >"$T/out" 2>"$T/err"; rc=$?
  out=$(cat "$T/out"); err=$(cat "$T/err")
}
ok() { echo "ok $1"; }
notok() { echo "not ok $1: $2"; }
skip() { echo "skip $1: $2"; } # a check this machine cannot make: counted as skipped, never passed
# slow: how much slower than natively luxcalc runs here (LX_TEST_SLOW; make valgrind sets 20, make asan 3): the
# cases' time bounds are multiplied by it
slow=${LX_TEST_SLOW:-1}
# opencl_state: "device" (OpenCL built in and at least one device), "none" (built in, no device) or
# "off" (a build with LX_OPENCL=0), from `luxcalc devices`
opencl_state() {
  "$LUXCALC" devices --format csv >"$T/devices" 2>"$T/devices.err"
  if grep -q 'built with LX_OPENCL=0' "$T/devices.err"; then echo off
  elif awk 'END { exit !(NR > 1) }' "$T/devices"; then echo device
  else echo none; fi
}
expect_rc() { if [ "$rc" -eq "$1" ]; then ok "$2"; else notok "$2" "exit $rc, expected $1; stderr: $err"; fi; }
expect_out_match() { if printf '%s\n' "$out" | grep -Eq -- "$1"; then ok "$2"; else notok "$2" "stdout does not match /$1/: $out"; fi; }
expect_err_match() { if printf '%s\n' "$err" | grep -Eq -- "$1"; then ok "$2"; else notok "$2" "stderr does not match /$1/: $err"; fi; }
expect_out_empty() { if [ -z "$out" ]; then ok "$1"; else notok "$1" "stdout not empty: $out"; fi; }
# expect_field ROW COLUMN_NAME VALUE TOL NAME: csv output, ROW counted from 1 after the header
expect_field() {
  v=$(printf '%s\n' "$out" | awk -F, -v row="$1" -v col="$2" 'NR==1{for(i=1;i<=NF;i++) if($i==col) c=i} NR==row+1{print $c}')
  if awk -v a="$v" -v b="$3" -v t="$4" 'BEGIN{d=a-b; if(d<0)d=-d; exit !(a!="" && d<=t)}'; then ok "$5"
  else notok "$5" "$2 = '$v', expected $3 +- $4"; fi
}
