#!/bin/sh
# split_run_merge.sh - for batches that outgrow one machine (or one process): split a rows-layout
# spectral CSV (header of wavelengths, one spectrum per row) into chunks that keep the header, run
# `luxcalc spd` on each chunk in parallel (GNU parallel when installed, else xargs -P), and merge
# the csv results with one header. The same chunks can go to a cluster job array (see
# slurm_array.sh beside this file).
# Usage: sh samples/batch/split_run_merge.sh INPUT.csv CHUNKS JOBS OUTPUT.csv [LUXCALC]
set -eu
in=$1; chunks=$2; jobs=$3; out=$4; lx=${5:-luxcalc}
work=$(mktemp -d "${TMPDIR:-/tmp}/lxsplit.XXXXXX")
trap 'rm -rf "$work"' EXIT INT TERM
# 1. split: comment lines dropped, the header repeated in every chunk
awk -v n="$chunks" -v dir="$work" '
  /^#/ || /^[ \t\r]*$/ { next }
  !hdr { hdr = $0; next }
  { rows[++m] = $0 }
  END { per = int((m + n - 1) / n); for (c = 0; c * per < m; c++) {
          f = sprintf("%s/chunk_%04d.csv", dir, c); print hdr > f
          for (i = c * per + 1; i <= m && i <= (c + 1) * per; i++) print rows[i] > f
          close(f) } }' "$in"
# 2. run: one luxcalc per chunk, `jobs` at a time (each writes its own csv atomically)
ls "$work"/chunk_*.csv > "$work/list"
if command -v parallel >/dev/null 2>&1; then
  parallel -j "$jobs" "$lx" spd --format csv -o {}.out {} < "$work/list"
else
  xargs -P "$jobs" -I{} "$lx" spd --format csv -o {}.out {} < "$work/list"
fi
# 3. merge: the first chunk's header, every chunk's rows, in chunk order; the file column names the
# chunk, so rewrite it to the input's name
first=1
for f in $(sort "$work/list"); do
  o=$f.out
  [ -f "$o" ] || { echo "split_run_merge: $f failed" >&2; exit 2; }
  if [ $first = 1 ]; then head -n 1 "$o"; first=0; fi
  tail -n +2 "$o" | sed "s|^[^,]*,|$in,|"
done > "$out.tmp"
mv "$out.tmp" "$out"
