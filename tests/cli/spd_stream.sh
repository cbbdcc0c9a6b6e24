# spd_stream.sh - `luxcalc spd` on rows-layout CSV through the streamed path (src/cli/spd_stream.c):
# the same numbers as the in-memory batch path, a bad row skips the file whole (-o untouched,
# the other files still printed), standard input and pipes, bounded memory on a large input
# (a 512 MB FIFO and a 256 MB file: peak resident size measured by the kernel), the progress bar.
. tests/cli/lib.sh

# N rows of smooth spectra at 360-830 nm, %.6g, named s0, s1, ...; or (cols) the same spectra as
# columns, one value column each, which the general reader reads into memory
gen_rows() { # N FILE [cols]
  awk -v n="$1" -v cols="${3:-}" 'function v(i, x) { return (0.5 + (i % 7) / 7) * exp(-0.5 * ((x - (420 + (i * 37) % 360)) / (20 + (i * 13) % 90)) ^ 2) + 0.3 * exp(-0.5 * ((x - 600) / 60) ^ 2) + 0.02 }
    BEGIN { if (cols) { printf "nm"; for (i = 0; i < n; i++) printf ",s%d", i; printf "\n";
        for (j = 0; j < 471; j++) { printf "%d", 360 + j; for (i = 0; i < n; i++) printf ",%.6g", v(i, 360 + j); printf "\n" } exit }
      printf "id"; for (j = 0; j < 471; j++) printf ",%d", 360 + j; printf "\n";
      for (i = 0; i < n; i++) { printf "s%d", i; for (j = 0; j < 471; j++) printf ",%.6g", v(i, 360 + j); printf "\n" } }' > "$2"
}
spoil() { # FILE LINE OUT: the 200th value of that line made bad
  awk -F, -v OFS=, -v l="$2" 'NR == l { $201 = "0.5x" } { print }' "$1" > "$3"
}

gen_rows 2000 "$T/rows.csv"
gen_rows 2000 "$T/cols.csv" cols
run spd --format csv "$T/rows.csv" -o "$T/stream.csv"
expect_rc 0 "2000 rows streamed"
"$LUXCALC" spd --format csv "$T/cols.csv" > "$T/cols_out.csv"
# the file column differs; every other cell must be the same text (the same batch arithmetic)
if cut -d, -f2- "$T/stream.csv" | cmp -s - "$(cut -d, -f2- "$T/cols_out.csv" > "$T/c2"; echo "$T/c2")"; then
  ok "streamed rows = the same spectra read as columns, cell for cell"
else notok "stream vs columns" "$(cut -d, -f2- "$T/stream.csv" | diff - "$T/c2" | head -4)"; fi
n=$(wc -l < "$T/stream.csv")
if [ "$n" -eq 2001 ]; then ok "a header and 2000 rows"; else notok "stream rows" "$n lines"; fi

# a bad value on row 1500 (line 1502): the general reader's message, the file skipped whole,
# -o left as it was, and another good file in the same run still printed
spoil "$T/rows.csv" 1502 "$T/bad.csv"
echo "keep me" > "$T/kept.csv"
run spd --format csv "$T/bad.csv" -o "$T/kept.csv"
expect_rc 2 "a bad row: exit 2"
expect_err_match "bad.csv:1502: " "the message names the file and line 1502"
if [ "$(cat "$T/kept.csv")" = "keep me" ]; then ok "-o untouched by a bad file"; else notok "-o untouched" "$(head -c 200 "$T/kept.csv")"; fi
if ls "$T"/kept.csv.tmp* >/dev/null 2>&1; then notok "no temporary file left" "$(ls "$T")"; else ok "no temporary file left"; fi
run spd --format csv "$T/rows.csv" "$T/bad.csv" "$T/rows.csv" -o "$T/two.csv"
expect_rc 2 "good, bad, good: exit 2"
n=$(wc -l < "$T/two.csv")
if [ "$n" -eq 4001 ]; then ok "the good files' rows, none of the bad one's"; else notok "good, bad, good" "$n lines"; fi
run spd --format csv "$T/rows.csv" "$T/bad.csv"
n=$(printf '%s\n' "$out" | wc -l)
if [ "$n" -eq 2001 ]; then ok "standard output: none of the bad file's rows"; else notok "stdout good, bad" "$n lines"; fi

# standard input and a pipe over 8 MB: streamed from the pipe (the file column says "-")
{ cat "$T/rows.csv"; tail -n 500 "$T/rows.csv"; } > "$T/big.csv"
"$LUXCALC" spd --format csv "$T/big.csv" > "$T/big_file.csv"
cat "$T/big.csv" | "$LUXCALC" spd --format csv - > "$T/big_pipe.csv"; rc=$?
expect_rc 0 "a 10 MB pipe on standard input"
if cut -d, -f2- "$T/big_pipe.csv" | cmp -s - "$(cut -d, -f2- "$T/big_file.csv" > "$T/b2"; echo "$T/b2")"; then
  ok "streamed from a pipe = streamed from the file"
else notok "pipe vs file" "$(cut -d, -f2- "$T/big_pipe.csv" | diff - "$T/b2" | head -4)"; fi
spoil "$T/big.csv" 2402 "$T/bigbad.csv"
cat "$T/bigbad.csv" | "$LUXCALC" spd --format csv - > "$T/out" 2> "$T/err"; rc=$?; err=$(cat "$T/err")
expect_rc 2 "a bad row late in a pipe: exit 2"
expect_err_match "^luxcalc: spd: -:2402: " "the pipe's message names line 2402"
if [ -s "$T/out" ]; then notok "nothing printed for the bad pipe" "$(head -c 200 "$T/out")"; else ok "nothing printed for the bad pipe"; fi
# a small pipe goes to the general reader whole, as before
head -c 20000 "$T/rows.csv" | awk 'NR < 4' > "$T/small.csv"
cat "$T/small.csv" | "$LUXCALC" spd --format csv - > "$T/small_pipe.csv"
"$LUXCALC" spd --format csv "$T/small.csv" | cut -d, -f2- > "$T/s2"
if cut -d, -f2- "$T/small_pipe.csv" | cmp -s - "$T/s2"; then ok "a small pipe: the general reader"; else notok "small pipe" "differs"; fi

# bounded memory: peak resident size of the whole process on large inputs (512 MB through a FIFO,
# printed to standard output, so its rows are held then spilled to a temporary file; a 256 MB file
# with -o, its map released behind the reader); python3 measures the child (getrusage)
if [ -n "${LX_UNDER_VALGRIND:-}" ]; then
  skip "bounded memory" "under valgrind the peak resident size is valgrind's (and 768 MB take minutes)"
elif command -v python3 >/dev/null 2>&1 && command -v mkfifo >/dev/null 2>&1; then
  python3 - "$LUXCALC" "$T" > "$T/mem" 2>&1 <<'PY'
import os, resource, subprocess, sys, threading
lux, tmp = sys.argv[1], sys.argv[2]
hdr = ("id," + ",".join(str(360 + j) for j in range(471)) + "\n").encode()
rows = []
for i in range(200):
    a, w = 420 + (i * 37) % 360, 20 + (i * 13) % 90
    import math
    vals = ["%.6g" % (0.6 * math.exp(-0.5 * ((360 + j - a) / w) ** 2) + 0.02) for j in range(471)]
    rows.append(("r%d," % i + ",".join(vals) + "\n").encode())
block = b"".join(rows)
def write_to(f, nbytes):
    f.write(hdr)
    done = 0
    while done < nbytes:
        f.write(block)
        done += len(block)
    return done // len(block) * len(rows)
def peak_mb(args, feed=None):
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    p = subprocess.Popen(args, stdout=open(os.path.join(tmp, "mem_out.csv"), "wb"), stderr=subprocess.PIPE)
    if feed: feed()
    _, err = p.communicate()
    peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    return p.returncode, peak / 1024, err.decode()
fifo = os.path.join(tmp, "fifo.csv")
os.mkfifo(fifo)
n = [0]
def feeder():
    with open(fifo, "wb") as f:
        n[0] = write_to(f, 512 << 20)
t = threading.Thread(target=feeder)
t.start()
rc, mb, err = peak_mb([lux, "spd", "--format", "csv", fifo])
t.join()
lines = sum(1 for _ in open(os.path.join(tmp, "mem_out.csv"), "rb"))
print("fifo", rc, "%.0f" % mb, lines - 1, n[0], err.strip()[:200])
big = os.path.join(tmp, "big256.csv")
with open(big, "wb") as f:
    m = write_to(f, 256 << 20)
out = os.path.join(tmp, "o256.csv")
rc, mb, err = peak_mb([lux, "spd", "--format", "csv", big, "-o", out])
lines = sum(1 for _ in open(out, "rb"))
print("file", rc, "%.0f" % mb, lines - 1, m, err.strip()[:200])
os.unlink(big); os.unlink(out)
PY
  while read -r what prc mb got want rest; do
    case "$what" in fifo|file) ;; *) continue ;; esac
    if [ "$prc" = 0 ] && [ "$got" = "$want" ]; then ok "$what: every row of a large input ($got)"; else notok "$what rows" "rc $prc, $got of $want rows $rest"; fi
    if [ "$mb" -lt 200 ]; then ok "$what: peak resident $mb MB < 200 MB"; else notok "$what memory" "peak resident $mb MB"; fi
  done < "$T/mem"
  grep -q '^fifo' "$T/mem" || notok "memory measurement" "$(head -5 "$T/mem")"
else
  skip "bounded memory" "needs python3 and mkfifo"
fi

# the progress bar: on a terminal (a pseudo-terminal from python3), bytes, rate and time left;
# nothing with -q, nothing when stderr is not a terminal
if command -v python3 >/dev/null 2>&1; then
  python3 - "$LUXCALC" "$T/big.csv" > "$T/bar" 2>&1 <<'PY'
import os, pty, subprocess, sys
lux, f = sys.argv[1], sys.argv[2]
for quiet in (0, 1):
    m, s = pty.openpty()
    args = [lux, "spd", "--format", "csv", f] + (["-q"] if quiet else [])
    env = dict(os.environ, NO_COLOR="1")
    p = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=s, env=env)
    os.close(s)
    data = b""
    while True:
        try:
            c = os.read(m, 4096)
        except OSError:
            break
        if not c: break
        data += c
    p.wait()
    print("quiet" if quiet else "bar", repr(data.decode(errors="replace")))
PY
  if grep -q "^bar .*MB of .*MB/s" "$T/bar"; then ok "a progress bar with bytes and rate on a terminal"; else notok "progress bar" "$(head -c 300 "$T/bar")"; fi
  if grep -q "^quiet ''" "$T/bar"; then ok "no bar with -q"; else notok "no bar with -q" "$(grep quiet "$T/bar" | head -c 200)"; fi
else
  skip "progress bar" "needs python3 (a pseudo-terminal)"
fi
run spd --format csv "$T/big.csv"
if [ -z "$err" ]; then ok "no bar when stderr is not a terminal"; else notok "no bar off a terminal" "$(printf '%s' "$err" | head -c 200)"; fi
