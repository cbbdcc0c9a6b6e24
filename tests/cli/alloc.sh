# alloc.sh - the library allocates only through the lx__alloc family (src/core/alloc.c): no direct
# malloc, calloc, realloc, aligned_alloc, strdup or free in src/ outside alloc.c, the CLI (src/cli,
# written against the public header) and the build tools (src/tools). Comments are not code: a line
# whose text starts with "*" or "/*" is skipped, as is everything after "/*" or "//" on a line. So that
# every allocation can be made to fail in the out-of-memory test (tests/test_nomem.c) and every size
# is checked for overflow.
. tests/cli/lib.sh
bad=$(find src -path src/cli -prune -o -path src/tools -prune -o -name '*.[ch]' -print | sort |
  grep -v '^src/core/alloc\.c$' | while read -r f; do
    awk -v f="$f" '
      { s = $0; sub(/\/\*.*/, "", s); sub(/\/\/.*/, "", s) }
      s ~ /^[ \t]*\*/ { next }
      s ~ /(^|[^A-Za-z0-9_.>])(malloc|calloc|realloc|aligned_alloc|posix_memalign|strdup|strndup|free)[ \t]*\(/ {
        printf " %s:%d", f, NR }
    ' "$f"
  done)
[ -z "$bad" ] && ok "the library allocates only through lx__alloc and friends" ||
  notok "the library allocates only through lx__alloc and friends" "direct calls at$bad (use lx__alloc, lx__alloc_n, lx__calloc, lx__realloc_n, lx__strdup, lx__free: src/core/core_private.h)"
exit 0
