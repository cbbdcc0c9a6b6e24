#!/bin/sh
# valgrind.sh - the whole test suite (every cmocka binary and every CLI case of tests/cli) under
# valgrind memcheck, run by `make valgrind`: an error or a definite/indirect leak in any run fails it
# (exit 99 from valgrind). tests/valgrind.supp holds the loader's and the OpenCL stack's own noise.
# Two jobs at a time (LX_TEST_JOBS, default 2), and a sample of the bad-input corpora
# (LX_BAD_SAMPLE, default 3: every third file and the first of each format; make test and make asan
# read them all). The CLI cases run luxcalc and tests/luxcalc-faults through valgrind wrappers.
# Usage: sh src/tools/valgrind.sh BUILD_DIR TEST_BIN...
set -u
B=$1; shift
command -v valgrind >/dev/null || { echo "valgrind: not installed (apt-get install valgrind)" >&2; exit 1; }
V="valgrind --quiet --error-exitcode=99 --leak-check=full --show-leak-kinds=definite,indirect"
V="$V --errors-for-leak-kinds=definite,indirect --suppressions=$(pwd)/tests/valgrind.supp --num-callers=30"
W=$B/vg
rm -rf "$W"; mkdir -p "$W/tests"
# wrappers with the binaries' names: run.sh and the CLI cases run these
for t in "$@"; do
  printf '#!/bin/sh\nexec %s %s "$@"\n' "$V" "$(pwd)/$t" >"$W/tests/${t##*/}"
  chmod +x "$W/tests/${t##*/}"
done
printf '#!/bin/sh\nexec %s %s "$@"\n' "$V" "$(pwd)/$B/luxcalc" >"$W/luxcalc"
chmod +x "$W/luxcalc"
if [ -x "$B/tests/luxcalc-faults" ]; then # the CLI with OpenCL fault injection (tests/cli/faults.sh)
  printf '#!/bin/sh\nexec %s %s "$@"\n' "$V" "$(pwd)/$B/tests/luxcalc-faults" >"$W/tests/luxcalc-faults"
  chmod +x "$W/tests/luxcalc-faults"
fi
for f in libluxcalc.a libluxcalc.so libluxcalc.so.0 libs.txt gen; do [ -e "$B/$f" ] && ln -s "$(pwd)/$B/$f" "$W/$f"; done
start=$(date +%s)
# LX_UNDER_VALGRIND: the cases that time or measure a process (its peak memory is valgrind's) skip
# those checks; LX_DTOA_COUNT: 1e5 doubles for the number printer instead of 1e6
LX_UNDER_VALGRIND=1 LX_DTOA_COUNT=${LX_DTOA_COUNT:-1e5} \
LX_TEST_JOBS=${LX_TEST_JOBS:-2} LX_BAD_SAMPLE=${LX_BAD_SAMPLE:-3} \
  sh tests/run.sh "$W" $(for t in "$@"; do echo "$W/tests/${t##*/}"; done) >"$W/run.log" 2>&1
rc=$?
# the suite's own closing line ("tests: N passed, N failed, N skipped") stays the last line
sed '$d' "$W/run.log"
echo "valgrind: the suite took $(( $(date +%s) - start )) s"
tail -n 1 "$W/run.log"
exit $rc
