# abi.sh - the ABI policy of luxcalc.h, checked on the build: the shared library exports exactly the
# symbols of src/luxcalc.exports, which are exactly the LX_API functions of the header (so a new
# public function is a deliberate line in the list, and nothing internal leaks out); its soname is
# libluxcalc.so.MAJOR with MAJOR the header's LX_VERSION_MAJOR.
. tests/cli/lib.sh
B=$LX_BUILD_DIR
so=$B/libluxcalc.so.0
grep -v '^#' src/luxcalc.exports | sort >"$T/list"
if [ -n "$(grep -v '^#' src/luxcalc.exports | sort -c 2>&1)" ] || [ -n "$(uniq -d "$T/list")" ]; then
  notok "luxcalc.exports is sorted without duplicates" "$(uniq -d "$T/list" | head -3)"
else ok "luxcalc.exports is sorted without duplicates"; fi
# the header: every LX_API declaration's name (declarations may span lines)
awk '/^LX_API/ {s = $0; while (s !~ /;/ && (getline l) > 0) s = s " " l; print s}' src/luxcalc.h |
  sed -n 's/^LX_API[^(]*[^a-z0-9_]\(lx_[a-z0-9_]*\) *(.*/\1/p' | sort -u >"$T/header"
if cmp -s "$T/list" "$T/header"; then ok "luxcalc.exports = the LX_API functions of luxcalc.h ($(wc -l <"$T/list"))"
else notok "luxcalc.exports = the header's LX_API functions" "$(diff "$T/list" "$T/header" | grep '^[<>]' | head -10 | tr '\n' ' ')"; fi
if [ -e "$so" ] && command -v nm >/dev/null 2>&1; then
  nm -D --defined-only "$so" | awk '{print $3}' | sort >"$T/nm"
  if cmp -s "$T/list" "$T/nm"; then ok "libluxcalc.so exports exactly luxcalc.exports"
  else notok "libluxcalc.so exports exactly luxcalc.exports" "$(diff "$T/list" "$T/nm" | grep '^[<>]' | head -10 | tr '\n' ' ')"; fi
else
  skip "exported symbols" "no $so or no nm"
fi
major=$(sed -n 's/^#define LX_VERSION_MAJOR \([0-9]*\)$/\1/p' src/luxcalc.h)
if [ -e "$so" ] && command -v objdump >/dev/null 2>&1; then
  got=$(objdump -p "$so" | awk '$1 == "SONAME" {print $2}')
  if [ "$got" = "libluxcalc.so.$major" ]; then ok "soname libluxcalc.so.$major follows LX_VERSION_MAJOR"
  else notok "soname follows LX_VERSION_MAJOR" "soname '$got', LX_VERSION_MAJOR $major"; fi
else
  skip "soname" "no $so or no objdump"
fi
exit 0
