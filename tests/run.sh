#!/bin/sh
# run.sh - runs every cmocka test binary and the CLI cases, then prints one closing line
# "tests: N passed, N failed, N skipped". Usage: sh tests/run.sh BUILD_DIR TEST_BIN...
build=$1; shift
export LX_BUILD_DIR="$build"
passed=0; failed=0; skipped=0; bad=""
log=$(mktemp "${TMPDIR:-/tmp}/lxtest.XXXXXX")
for t in "$@"; do
  "$t" >"$log" 2>&1; rc=$?
  cat "$log"
  p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' "$log" | tail -n 1)
  f=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' "$log" | tail -n 1)
  s=$(sed -n 's/^\[  SKIPPED \] \([0-9]*\) test.*/\1/p' "$log" | tail -n 1)
  passed=$((passed + ${p:-0})); failed=$((failed + ${f:-0})); skipped=$((skipped + ${s:-0}))
  if [ "$rc" -ne 0 ]; then
    bad="$bad $(basename "$t")"
    [ -z "$f" ] && failed=$((failed + 1))   # crashed before cmocka's summary
  fi
done
rm -f "$log"
# CLI cases: tests/cli/*.sh, each a small script using the functions of tests/cli/lib.sh
for c in tests/cli/*.sh; do
  [ "$c" = tests/cli/lib.sh ] && continue
  [ -f "$c" ] || continue
  out=$(LUXCALC="$build/luxcalc" sh "$c" 2>&1); rc=$?
  n=$(printf '%s\n' "$out" | grep -c '^ok ')
  nf=$(printf '%s\n' "$out" | grep -c '^not ok ')
  ns=$(printf '%s\n' "$out" | grep -c '^skip ')
  printf '%s\n' "$out" | grep '^skip ' | sed "s|^|$(basename "$c"): |"
  printf '%s\n' "$out" | grep '^not ok ' | sed "s|^|$(basename "$c"): |"
  passed=$((passed + n)); failed=$((failed + nf)); skipped=$((skipped + ns))
  if [ "$rc" -ne 0 ] && [ "$nf" -eq 0 ]; then failed=$((failed + 1)); bad="$bad $(basename "$c")"; fi
  echo "[ CLI ] $(basename "$c"): $n passed, $nf failed, $ns skipped"
  [ "$nf" -gt 0 ] && bad="$bad $(basename "$c")"
done
[ -n "$bad" ] && echo "failing:$bad"
echo "tests: $passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ] && [ -z "$bad" ]
