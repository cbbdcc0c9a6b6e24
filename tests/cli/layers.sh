# layers.sh - the library's layers depend downwards only (README "Development"): core < tables <
# spectral < {colour, lighting, radiance, radiosity} < scene < plot < cli. Two checks: every #include of a
# layer's private header comes from that layer or a higher one (siblings never include each other),
# and every lx_ / lx__ symbol an object file uses is defined in its own layer or a lower one (nm on
# the objects of the build under test). The CLI includes only the public header and its own.
. tests/cli/lib.sh
rank() {
  case $1 in
    core) echo 0 ;; tables) echo 1 ;; spectral) echo 2 ;; colour|lighting|radiance|radiosity) echo 3 ;;
    scene) echo 4 ;; plot) echo 5 ;; cli) echo 6 ;; *) echo -1 ;;
  esac
}
# may FROM depend on TO?
allowed() {
  [ "$1" = "$2" ] && return 0
  rf=$(rank "$1"); rt=$(rank "$2")
  [ "$rt" -ge 0 ] && [ "$rt" -lt "$rf" ]
}
layers="core tables spectral colour lighting radiance radiosity scene plot"

# 1. includes
bad=""
for L in $layers cli; do
  for f in $(find src/$L -name '*.[ch]'); do
    for inc in $(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/p' "$f"); do
      case $inc in
        luxcalc.h) continue ;;
        */*) to=${inc%%/*} ;;
        *) [ -f "$(dirname "$f")/$inc" ] && continue; bad="$bad $f:$inc(not found beside it)"; continue ;;
      esac
      if [ "$L" = cli ]; then [ "$to" = cli ] || bad="$bad $f:$inc"; continue; fi
      allowed "$L" "$to" || bad="$bad $f:$inc"
    done
  done
done
[ -z "$bad" ] && ok "every #include points down the layers" || notok "every #include points down the layers" "$bad"

# 2. symbols: the defining layer of every lx_ / lx__ symbol, then each object's undefined ones
obj=$LX_BUILD_DIR/obj
if [ -d "$obj/core" ] && command -v nm >/dev/null 2>&1; then
  defs=$T/defs
  for L in $layers; do
    for o in "$obj/$L"/*.o; do nm --defined-only -g "$o" | awk -v L="$L" '$3 ~ /^lx_/ {print $3, L}'; done
  done | sort -u >"$defs"
  bad=""
  for L in $layers cli; do
    for o in $(find "$obj/$L" -name '*.o'); do
      for s in $(nm -u "$o" | awk '$2 ~ /^lx_/ {print $2}'); do
        to=$(awk -v s="$s" '$1 == s {print $2; exit}' "$defs")
        [ -n "$to" ] || { bad="$bad $(basename "$o"):$s(undefined)"; continue; }
        allowed "$L" "$to" || bad="$bad $L/$(basename "$o")->$to:$s"
      done
    done
  done
  [ -z "$bad" ] && ok "every object uses only its own and lower layers' symbols" ||
    notok "every object uses only its own and lower layers' symbols" "$bad"
else
  skip "layer symbols" "no objects under $obj or no nm"
fi
exit 0
