# readme.sh - the README and tests/fuzz/README.md name only what exists: every path under src/,
# tests/, kernels/ or samples/ they mention (a glob must match at least one file; names with an
# upper-case placeholder such as NAME, TARGET or TOPIC are patterns, not files), every relative
# [link](file) resolves, and every [link](#anchor) names a heading of the README (GitHub's rule:
# lower case, punctuation dropped, spaces to hyphens).
. tests/cli/lib.sh
docs="README.md tests/fuzz/README.md"
for d in $docs; do
  [ -f "$d" ] || { notok "readme: $d" "missing"; continue; }
  dir=$(dirname "$d")
  # paths: preceded by start of line, a space, a backtick, ( or [ (not a URL or a longer path)
  grep -oE '(^|[][ `(])(src|tests|kernels|samples)/[A-Za-z0-9_.*/+-]*' "$d" | sed 's/^[][ `(]//' |
    sed 's/[.,:;)]*$//' | sort -u >"$T/paths"
  bad=""
  while read -r p; do
    case $p in *[A-Z][A-Z]*) continue ;; esac           # NAME, TARGET, TOPIC, CMD: a pattern
    case $p in samples/bench/*.md) continue ;;          # written by `make bench` (topics: luxcalc bench --help)
    esac
    # shellcheck disable=SC2086
    set -- $p
    if [ -e "$1" ]; then :; else bad="$bad $p"; fi
  done <"$T/paths"
  if [ -z "$bad" ]; then ok "readme: every path $d names exists ($(wc -l <"$T/paths") paths)"
  else notok "readme: paths in $d" "missing:$bad"; fi
  # relative links to files
  grep -oE '\]\([^)#[:space:]]+' "$d" | sed 's/^](//' | grep -vE '^(https?|mailto):' | sort -u >"$T/links"
  bad=""
  while read -r l; do
    case $l in samples/bench/*.md) continue ;; esac     # written by `make bench`: checked below
    [ -e "$dir/$l" ] || bad="$bad $l"
  done <"$T/links"
  if [ -z "$bad" ]; then ok "readme: every file link in $d resolves ($(wc -l <"$T/links") links)"
  else notok "readme: links in $d" "missing:$bad"; fi
done
# samples/bench/TOPIC.md links: TOPIC must be one `luxcalc bench` knows
"$LUXCALC" bench --help >"$T/bench" 2>&1
bad=""
for f in $(grep -ohE 'samples/bench/[a-z_]+\.md' $docs | sort -u); do
  topic=$(basename "$f" .md)
  grep -qE "^  $topic " "$T/bench" || bad="$bad $topic"
done
if [ -z "$bad" ]; then ok "readme: every samples/bench/TOPIC.md named is a bench topic"
else notok "readme: bench topics" "not in luxcalc bench --help:$bad"; fi
# anchors of the README's own links
grep -E '^#{1,6} ' README.md | sed -E 's/^#+ //' | tr 'A-Z' 'a-z' |
  sed -E 's/[^a-z0-9 _-]//g; s/ /-/g' | sort -u >"$T/anchors"
grep -oE '\]\(#[^)]+\)' README.md | sed -E 's/^]\(#//; s/\)$//' | sort -u >"$T/used"
bad=$(comm -23 "$T/used" "$T/anchors" | tr '\n' ' ')
if [ -z "$bad" ]; then ok "readme: every #anchor names a heading ($(wc -l <"$T/used") anchors)"
else notok "readme: anchors" "no heading for: $bad"; fi
# the command reference is what src/tools/mkcmdref.sh prints today (the devices example aside: it
# names this machine's devices); not under valgrind (slow) or without OpenCL (other output)
if [ "$slow" -gt 1 ] || [ "$(opencl_state)" = off ]; then
  skip "readme: command reference current" "valgrind or LX_OPENCL=0 build"
else
  nodev() { awk '/^\*\*`devices`\*\*/ { d = 1; next } d && /^\*\*`/ { d = 0 } !d'; }
  awk '/<!-- section: commands -->/, /<!-- end: commands -->/' README.md | nodev >"$T/ref_readme"
  sh src/tools/mkcmdref.sh "$LUXCALC" 2>&1 | nodev >"$T/ref_now"
  if cmp -s "$T/ref_readme" "$T/ref_now"; then ok "readme: command reference is mkcmdref.sh's output"
  else notok "readme: command reference" "differs from sh src/tools/mkcmdref.sh (paste its output): $(diff "$T/ref_readme" "$T/ref_now" | head -n 6)"; fi
fi
exit 0
