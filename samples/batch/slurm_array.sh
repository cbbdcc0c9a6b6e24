#!/bin/sh
# slurm_array.sh - the same split as split_run_merge.sh, run as a Slurm job array: one task per
# chunk, each on its own node or core. Submit after splitting into chunks/chunk_0000.csv ...:
#   sbatch --array=0-$((N-1)) samples/batch/slurm_array.sh
# then merge results/chunk_*.csv as split_run_merge.sh does (one header, rows in chunk order).
#SBATCH --job-name=luxcalc-spd
#SBATCH --cpus-per-task=2
#SBATCH --time=00:30:00
set -eu
i=$(printf '%04d' "${SLURM_ARRAY_TASK_ID:?run under sbatch --array}")
mkdir -p results
luxcalc spd --format csv -o "results/chunk_$i.csv" "chunks/chunk_$i.csv"
