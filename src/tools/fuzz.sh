#!/bin/sh
# fuzz.sh - builds and runs the libFuzzer targets tests/fuzz/fuzz_*.c for SECONDS each (run by
# `make fuzz FUZZ_SECONDS=N [FUZZ_TARGETS="spd ies"] [FUZZ_JOBS=2]`). Corpora grow in
# build-fuzz/corpus/TARGET; crashing inputs land in build-fuzz/crashes/TARGET: copy each into
# tests/fuzz/regressions/TARGET/ once fixed (test_fuzz replays them in `make test`).
# FUZZ_JOBS targets run at once (default 1), each under `nice -n 10`.
# Usage: sh src/tools/fuzz.sh SECONDS [TARGET...]
set -u
secs=${1:-60}; [ $# -gt 0 ] && shift
jobs=${FUZZ_JOBS:-1}
B=build-fuzz
targets=${*:-$(ls tests/fuzz/fuzz_*.c | sed 's|tests/fuzz/fuzz_\(.*\)\.c|\1|')}
command -v clang >/dev/null || { echo "fuzz: clang is needed (apt-get install clang libclang-rt-dev)" >&2; exit 1; }
san="-fsanitize=address,undefined -fno-sanitize-recover=undefined"
make -s BUILD=$B CC=clang LX_OPENCL=0 CFLAGS="-O1 -g -fsanitize=fuzzer-no-link $san" $B/libluxcalc.a $B/libs.txt || exit 1
libs=$(cat $B/libs.txt)
seeds_for() {
  case $1 in
    spd) echo samples/spd tests/data/spd tests/bad/spd ;;
    batch) echo samples/batch samples/spd tests/data/spd tests/bad/spd ;;
    ies) echo samples/ies samples/scenes/ies tests/data/ies tests/bad/ies ${LX_SHARED_DIR:-../shared}/ies ;;
    scene) echo samples/scenes tests/data/scenes tests/bad/scene ;;
    exr) echo samples/envmaps tests/bad/exr tests/data/exr ;;
    instruments) echo tests/data/instruments/good tests/data/instruments/bad ${LX_SHARED_DIR:-../shared}/spectra/instruments ;;
  esac
  echo tests/fuzz/seeds/$1
}
for t in $targets; do
  mkdir -p $B/corpus/$t $B/crashes/$t
  clang -std=c11 -O1 -g -fsanitize=fuzzer $san -DLX_FUZZ_MAIN -D_POSIX_C_SOURCE=200809L -Isrc \
    -o $B/fuzz_$t tests/fuzz/fuzz_$t.c $B/libluxcalc.a $libs || exit 1
done
# one target: SECONDS of fuzzing, then one summary line (also kept in build-fuzz/fuzz_TARGET.summary)
run_one() {
  t=$1
  dirs=""
  for d in $(seeds_for $t) tests/fuzz/regressions/$t; do [ -d "$d" ] && dirs="$dirs $d"; done
  log=$B/fuzz_$t.log
  start=$(date +%s)
  nice -n 10 $B/fuzz_$t -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
    -artifact_prefix=$B/crashes/$t/ -print_final_stats=1 $B/corpus/$t $dirs >$log 2>&1
  rc=$?
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' $log | tail -n 1)
  crashes=$(ls $B/crashes/$t | wc -l)
  echo "fuzz: $t: $(( $(date +%s) - start ))s, ${execs:-?} executions, corpus $(ls $B/corpus/$t | wc -l), findings $crashes (exit $rc; log $log)" |
    tee $B/fuzz_$t.summary
  [ "$crashes" -eq 0 ] && [ "$rc" -eq 0 ]
}
status=0
running=0
pids=""
for t in $targets; do
  run_one $t &
  pids="$pids $!"
  running=$((running + 1))
  if [ $running -ge $jobs ]; then
    for p in $pids; do wait $p || status=1; done
    pids=""; running=0
  fi
done
for p in $pids; do wait $p || status=1; done
exit $status
