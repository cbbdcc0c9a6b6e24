# spd_bad.sh - `luxcalc spd` on bad input: every file in tests/data/spd/bad/ exits 2 with
# "luxcalc: spd: FILE:LINE: what" (line and fragment from tests/data/spd/bad_expected.txt), a batch
# with a bad file in the middle still prints the good ones, missing files and directories, stdin.
. tests/cli/lib.sh
D=tests/data/spd
re_escape() { printf '%s' "$1" | sed 's/[][\.*^$+?(){}|/]/\\&/g'; }

# LX_BAD_SAMPLE=K (make valgrind): every K-th file only, the rest reported as one skip
K=${LX_BAD_SAMPLE:-1}; k=0; sampled_out=0
for f in "$D"/bad/*; do
  k=$((k + 1))
  if [ $(((k - 1) % K)) -ne 0 ]; then sampled_out=$((sampled_out + 1)); continue; fi
  b=$(basename "$f")
  exp=$(awk -F'\t' -v f="$b" '$1 == f { print $2 "\t" $3 }' "$D/bad_expected.txt")
  if [ -z "$exp" ]; then notok "bad/$b" "no entry in bad_expected.txt"; continue; fi
  line=${exp%%"	"*}; frag=${exp#*"	"}
  run spd "$f" --format csv
  expect_rc 2 "bad/$b exits 2"
  expect_err_match "^luxcalc: spd: $(re_escape "$f"):$line: " "bad/$b names line $line"
  if printf '%s\n' "$err" | grep -Fq -- "$frag"; then ok "bad/$b says '$frag'"
  else notok "bad/$b says '$frag'" "stderr: $err"; fi
  # no result row (at most the csv header line)
  [ "$(printf '%s\n' "$out" | grep -c "$b")" -eq 0 ] && ok "bad/$b prints no result row" ||
    notok "bad/$b prints no result row" "stdout: $out"
done

[ "$sampled_out" -gt 0 ] && skip "bad-file sample" "$sampled_out of $k files of $D/bad not run here (LX_BAD_SAMPLE=$K)"

# a batch: good, bad, good -> both good files' rows, the bad one on stderr, exit 2
run spd "$D/good/plain.csv" "$D/bad/dup_wavelength.csv" "$D/good/tab.tsv" --format csv
expect_rc 2 "batch with a bad file exits 2"
expect_out_match "^$(re_escape "$D/good/plain.csv"),A," "batch prints the first good file (A)"
expect_out_match "^$(re_escape "$D/good/plain.csv"),B," "batch prints the first good file (B)"
expect_out_match "^$(re_escape "$D/good/tab.tsv"),A," "batch prints the good file after the bad one"
expect_err_match "^luxcalc: spd: $(re_escape "$D/bad/dup_wavelength.csv"):4: duplicate wavelength" "batch reports the bad file"
n=$(printf '%s\n' "$out" | grep -c "dup_wavelength")
[ "$n" -eq 0 ] && ok "batch prints no row for the bad file" || notok "batch prints no row for the bad file" "$out"
# plain.csv and tab.tsv hold the same data: every column after the file name is identical
a=$(printf '%s\n' "$out" | grep "^$D/good/plain.csv," | cut -d, -f2-)
b=$(printf '%s\n' "$out" | grep "^$D/good/tab.tsv," | cut -d, -f2-)
[ -n "$a" ] && [ "$a" = "$b" ] && ok "csv and tab variants print identical results" ||
  notok "csv and tab variants print identical results" "$a / $b"

# files that cannot be read: exit 2, the message names the file
run spd "$D/no_such_file.csv"
expect_rc 2 "missing file exits 2"
expect_err_match "^luxcalc: spd: $(re_escape "$D/no_such_file.csv"): cannot open" "missing file is named"
run spd "$D/good"
expect_rc 2 "directory exits 2"
expect_err_match "^luxcalc: spd: $(re_escape "$D/good"): cannot read: is a directory" "directory is named"

# standard input, and a CGATS file read the same as the csv
run_stdin "$D/good/crlf.csv" spd - --format csv
expect_rc 0 "stdin reads"
expect_out_match '^-,A,' "stdin rows are labelled -"
run spd "$D/good/plain.csv" "$D/good/argyll.sp" "$D/good/rows.csv" --format csv
expect_rc 0 "csv, Argyll .sp and rows layout read"
a=$(printf '%s\n' "$out" | grep "^$D/good/plain.csv," | cut -d, -f2-)
b=$(printf '%s\n' "$out" | grep "^$D/good/argyll.sp," | cut -d, -f2-)
c=$(printf '%s\n' "$out" | grep "^$D/good/rows.csv," | cut -d, -f2-)
[ -n "$a" ] && [ "$a" = "$b" ] && [ "$a" = "$c" ] && ok "csv, CGATS and rows layout print identical results" ||
  notok "csv, CGATS and rows layout print identical results" "$a / $b / $c"
