# bad_inputs.sh - the bad-input corpus (issue 10): every file of tests/bad/ (see tests/bad/expected.tsv)
# gives its exit status and a message "luxcalc: COMMAND: FILE:LINE: what" within 10 s and 1 GiB of
# address space; then cases made here at run time: 1e6 columns, 10 MB lines, a directory, an unreadable
# file (skipped as root: root reads anything), a FIFO with a writer and one without.
. tests/cli/lib.sh
B=tests/bad
MEM_KB=1048576
re_escape() { printf '%s' "$1" | sed 's/[][\.*^$+?(){}|/]/\\&/g'; }
# sanitizer and valgrind builds reserve far more address space than they use: no memory bound there
if sh -c 'ulimit -v "$1" && "$2" --version' sh $MEM_KB "$LUXCALC" >/dev/null 2>&1; then memlim=$MEM_KB; else memlim=unlimited
  skip "memory bound (ulimit -v)" "this luxcalc cannot run under ulimit -v (sanitizer build?)"; fi
# bounded COMMAND ARGS...: run with a 10 s (x LX_TEST_SLOW, lib.sh) and 1 GiB bound; sets $out, $err, $rc, $ms
tmax=$((10 * slow))
bounded() {
  t0=$(date +%s%N)
  (ulimit -v $memlim; exec timeout $tmax "$LUXCALC" "$@") >"$T/out" 2>"$T/err"; rc=$?
  ms=$(( ($(date +%s%N) - t0) / 1000000 ))
  out=$(head -c 4096 "$T/out"); err=$(head -c 4096 "$T/err")
}
# check NAME EXIT FILE LINE FRAGMENT COMMAND: the last run exited EXIT, named FILE (and LINE unless '-')
check() {
  if [ "$rc" -eq 124 ]; then notok "$1" "timed out after $tmax s"; return; fi
  expect_rc "$2" "$1 exits $2"
  if [ "$4" = - ]; then pat="^luxcalc: $6: $(re_escape "$3"): "; else pat="^luxcalc: $6: $(re_escape "$3"):$4: "; fi
  expect_err_match "$pat" "$1 names ${3##*/}${4:+ line $4}"
  if printf '%s\n' "$err" | grep -Fq -- "$5"; then ok "$1 says '$5'"; else notok "$1 says '$5'" "stderr: $err"; fi
  nb=$(wc -c <"$T/err")
  [ "$nb" -lt 2048 ] && ok "$1 message is short ($nb bytes)" || notok "$1 message is short" "$nb bytes of stderr"
}

# the committed corpus. LX_BAD_SAMPLE=K (make valgrind) runs a sample of it: the file on every K-th
# line of expected.tsv, and the first file of each format so that every reader runs; the files left
# out are reported as one skip (make test and make asan run them all)
K=${LX_BAD_SAMPLE:-1}
n=0; sampled_out=0; formats=" "
while IFS='	' read -r cmd file code line frag; do
  case $cmd in '#'*|'') continue ;; esac
  [ -f "$B/$file" ] || { notok "$file" "listed in expected.tsv but missing"; continue; }
  n=$((n + 1))
  fmt=${file%%/*}
  if [ $(((n - 1) % K)) -ne 0 ] && case $formats in *" $fmt "*) true ;; *) false ;; esac; then
    sampled_out=$((sampled_out + 1)); continue
  fi
  formats="$formats$fmt "
  bounded "$cmd" "$B/$file"
  check "bad/$file" "$code" "$B/$file" "$line" "$frag" "$cmd"
done <"$B/expected.tsv"
[ "$sampled_out" -gt 0 ] && skip "corpus sample" "$sampled_out of $n corpus files not run here (LX_BAD_SAMPLE=$K)"
files=$(find "$B/ies" "$B/ldt" "$B/spd" "$B/scene" "$B/exr" -type f | wc -l)
[ "$n" -eq "$files" ] && [ "$n" -ge 60 ] && ok "every corpus file is listed ($n files)" ||
  notok "every corpus file is listed" "$n listed, $files files"
# the controls: the files the truncations were cut from read cleanly
for f in reference.ies reference.ldt; do bounded ies "$B/good/$f"; expect_rc 0 "good/$f reads"; done
bounded scene "$B/good/reference.scene"; expect_rc 0 "good/reference.scene reads"

# made at run time: big files are not committed
G=$T/gen
mkdir -p "$G"
awk 'BEGIN { printf "nm,v\n500,1"; for (i = 1; i < 1000000; i++) printf ",1"; printf "\n" }' >"$G/cols_1e6.csv"
bounded spd "$G/cols_1e6.csv"
check "1e6 columns" 2 "$G/cols_1e6.csv" 2 "row has 1000001 fields, expected 2" spd
awk 'BEGIN { printf "id"; for (i = 0; i < 1000000; i++) printf ",%.4f", 380 + i * 1e-4; printf "\nA,1,2\n" }' >"$G/rows_1e6.csv"
bounded spd "$G/rows_1e6.csv"
check "1e6 wavelength columns" 2 "$G/rows_1e6.csv" 2 "row has 3 fields, expected 1000001" spd
{ cat "$B/good/reference.ies"; awk 'BEGIN { for (i = 0; i < 1000000; i++) printf "1 "; printf "\n" }'; } >"$G/ies_1e6.ies"
bounded ies "$G/ies_1e6.ies"
check "1e6 numbers after an IES table" 2 "$G/ies_1e6.ies" 15 "1000000 numbers more than the counts" ies
big() { awk -v c="$1" 'BEGIN { s = c; while (length(s) < 10000000) s = s s; printf "%s", substr(s, 1, 10000000) }'; }
{ printf 'nm,v\n500,1\n510,'; big 1; printf '\n520,1\n'; } >"$G/digits_10mb.csv"
bounded spd "$G/digits_10mb.csv"
check "a 10 MB number" 2 "$G/digits_10mb.csv" 3 "out of range" spd
{ printf 'nm,v\n500,1\n510,'; big a; printf '\n'; } >"$G/alpha_10mb.csv"
bounded spd "$G/alpha_10mb.csv"
check "a 10 MB word" 2 "$G/alpha_10mb.csv" 3 "value is not a number" spd
{ printf '# '; big x; printf '\nnm,v\n500,1\n510,2\n'; } >"$G/comment_10mb.csv"
bounded spd "$G/comment_10mb.csv" --format csv
expect_rc 0 "a 10 MB comment line is read"
expect_out_match "comment_10mb.csv,v," "a 10 MB comment line: the spectrum after it is computed"
{ printf '[scene]\ntitle = '; big x; printf '\n'; } >"$G/line_10mb.scene"
bounded scene "$G/line_10mb.scene"
check "a 10 MB scene line" 2 "$G/line_10mb.scene" 2 "line too long" scene
{ head -n 2 "$B/good/reference.ies"; printf '[MANUFAC] '; big m; printf '\n'; tail -n +4 "$B/good/reference.ies"; } >"$G/keyword_10mb.ies"
bounded ies "$G/keyword_10mb.ies"
expect_rc 0 "a 10 MB IES keyword line is read"

# a directory instead of a file
for c in spd ies scene luminance-map; do
  bounded $c "$B"
  case $c in luminance-map) frag="not a regular file" ;; *) frag="is a directory" ;; esac
  check "$c: a directory" 2 "$B" - "$frag" $c
done
# an unreadable file
cp "$B/good/reference.ies" "$G/unreadable.ies"
chmod 000 "$G/unreadable.ies"
if [ "$(id -u)" = 0 ]; then
  skip "unreadable file" "running as root, which reads any file"
else
  bounded ies "$G/unreadable.ies"
  check "an unreadable file" 2 "$G/unreadable.ies" - "Permission denied" ies
fi
chmod 644 "$G/unreadable.ies"

# a FIFO: without a writer it is an error after LX_FIFO_WAIT_S; with one it is read like a file
mkfifo "$G/fifo" 2>/dev/null || { notok "FIFO" "mkfifo failed"; exit 0; }
for c in spd ies scene; do
  LX_FIFO_WAIT_S=1 bounded $c "$G/fifo"
  frag="a FIFO with no data after 1 s"
  check "$c: a FIFO without a writer" 2 "$G/fifo" - "$frag" $c
  [ "$ms" -lt $((5000 * slow)) ] && ok "$c: a FIFO without a writer fails in ${ms} ms" || notok "$c: FIFO wait bounded" "${ms} ms"
done
( printf 'nm,v\n500,1\n510,2\n520,1\n' >"$G/fifo" ) &
wpid=$!
bounded spd "$G/fifo" --format csv
expect_rc 0 "a FIFO with a writer is read"
expect_out_match "fifo,v," "a FIFO with a writer: its spectrum is computed"
kill $wpid 2>/dev/null; wait $wpid 2>/dev/null
( cat "$B/good/reference.ies" >"$G/fifo" ) &
wpid=$!
bounded ies "$G/fifo" --format csv
expect_rc 0 "a FIFO with an IES writer is read"
kill $wpid 2>/dev/null; wait $wpid 2>/dev/null
bounded luminance-map "$G/fifo"
check "luminance-map: a FIFO" 2 "$G/fifo" - "not a regular file" luminance-map
exit 0
