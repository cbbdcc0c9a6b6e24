# batch_split.sh - samples/batch/split_run_merge.sh gives the same rows as one luxcalc run.
. tests/cli/lib.sh
S=samples/spd/led_batch.csv
"$LUXCALC" spd --format csv "$S" > "$T/one.csv"
sh samples/batch/split_run_merge.sh "$S" 3 2 "$T/merged.csv" "$LUXCALC" 2>"$T/err"; rc=$?
expect_rc 0 "split, run in parallel, merge"
if cmp -s "$T/one.csv" "$T/merged.csv"; then ok "merged csv = single run, byte for byte"; else notok "merged csv" "$(diff "$T/one.csv" "$T/merged.csv" | head -5)"; fi
