#!/bin/sh
# run.sh - runs every cmocka test binary and the CLI cases, then prints one closing line
# "tests: N passed, N failed, N skipped". Usage: sh tests/run.sh BUILD_DIR TEST_BIN...
# LX_TEST_JOBS=N (default 1) runs N of them at a time (xargs -P; make valgrind uses 2); their
# outputs are still printed whole and in order. LX_TEST_CLI=0 runs the C binaries alone (make
# test-nofp64).
build=$1; shift
export LX_BUILD_DIR="$build"
jobs=${LX_TEST_JOBS:-1}
W=$(mktemp -d "${TMPDIR:-/tmp}/lxtest.XXXXXX")
trap 'rm -rf "$W"' EXIT
# the work list: one line "INDEX KIND PATH" per binary (bin) and CLI case (cli), in report order
i=0
for t in "$@"; do i=$((i + 1)); echo "$i bin $t"; done >"$W/list"
if [ "${LX_TEST_CLI:-1}" != 0 ]; then
  for c in tests/cli/*.sh; do
    [ "$c" = tests/cli/lib.sh ] || [ ! -f "$c" ] && continue
    i=$((i + 1)); echo "$i cli $c"
  done >>"$W/list"
fi
# one job: its output to W/INDEX.out, its exit status to W/INDEX.rc, its wall time (s) to W/INDEX.s
run_one() {
  t0=$(date +%s)
  if [ "$2" = bin ]; then "$3" </dev/null >"$W/$1.out" 2>&1
  else LUXCALC="$build/luxcalc" sh "$3" </dev/null >"$W/$1.out" 2>&1; fi
  echo $? >"$W/$1.rc"
  echo $(($(date +%s) - t0)) >"$W/$1.s"
}
passed=0; failed=0; skipped=0; bad=""
# adds a finished job to the totals and prints its report
report() {
  rc=$(cat "$W/$1.rc"); name=$(basename "$3"); secs=$(cat "$W/$1.s")
  if [ "$2" = bin ]; then
    cat "$W/$1.out"
    echo "[ TIME ] $name: $secs s"
    p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' "$W/$1.out" | tail -n 1)
    f=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' "$W/$1.out" | tail -n 1)
    s=$(sed -n 's/^\[  SKIPPED \] \([0-9]*\) test.*/\1/p' "$W/$1.out" | tail -n 1)
    passed=$((passed + ${p:-0})); failed=$((failed + ${f:-0})); skipped=$((skipped + ${s:-0}))
    if [ "$rc" -ne 0 ]; then
      bad="$bad $name"
      [ -z "$f" ] && failed=$((failed + 1))   # crashed before cmocka's summary
    fi
  else
    n=$(grep -c '^ok ' "$W/$1.out"); nf=$(grep -c '^not ok ' "$W/$1.out"); ns=$(grep -c '^skip ' "$W/$1.out")
    grep '^skip ' "$W/$1.out" | sed "s|^|$name: |"
    grep '^not ok ' "$W/$1.out" | sed "s|^|$name: |"
    passed=$((passed + n)); failed=$((failed + nf)); skipped=$((skipped + ns))
    if [ "$rc" -ne 0 ] && [ "$nf" -eq 0 ]; then failed=$((failed + 1)); bad="$bad $name"; fi
    echo "[ CLI ] $name: $n passed, $nf failed, $ns skipped ($secs s)"
    [ "$nf" -gt 0 ] && bad="$bad $name"
  fi
}
if [ "$jobs" -gt 1 ]; then
  export W build
  xargs -P "$jobs" -L 1 sh -c '  # run_one, in the shell xargs starts
    t0=$(date +%s)
    if [ "$2" = bin ]; then "$3" </dev/null >"$W/$1.out" 2>&1
    else LUXCALC="$build/luxcalc" sh "$3" </dev/null >"$W/$1.out" 2>&1; fi
    echo $? >"$W/$1.rc"
    echo $(($(date +%s) - t0)) >"$W/$1.s"' sh <"$W/list"
  while read -r idx kind path; do report "$idx" "$kind" "$path"; done <"$W/list"
else
  while read -r idx kind path; do run_one "$idx" "$kind" "$path"; report "$idx" "$kind" "$path"; done <"$W/list"
fi
[ -n "$bad" ] && echo "failing:$bad"
echo "tests: $passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ] && [ -z "$bad" ]
