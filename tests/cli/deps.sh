# deps.sh - the build tracks what its outputs depend on: `make -n -W FILE` (what make would do had
# FILE changed; nothing is touched or built) must rebuild the generated objects when a private header,
# a kernel or a data table changes, and a test binary when a header or source file it includes changes
# (test_fuzz includes the fuzz harnesses).
. tests/cli/lib.sh
B=$LX_BUILD_DIR
if [ ! -f "$B/obj/tables/lx_tables.o" ] || [ ! -f Makefile ] || ! command -v make >/dev/null 2>&1; then
  skip "dependency tracking" "no objects under $B/obj (or no make)"
  exit 0
fi
unset MAKEFLAGS MFLAGS MAKELEVEL
# would FILE TARGET NAME: a change of FILE rebuilds TARGET
would() {
  if make -n -W "$1" BUILD="$B" "$2" 2>"$T/make.err" | grep -q -- "-o $2 "; then ok "$3"
  else notok "$3" "make -n -W $1 $2 does not rebuild it $(head -c 300 "$T/make.err")"; fi
}
would src/core/core_private.h "$B/obj/tables/lx_tables.o" "core_private.h rebuilds lx_tables.o"
would src/core/core_private.h "$B/obj/core/lx_kernels.o" "core_private.h rebuilds lx_kernels.o"
would src/luxcalc.h "$B/obj/tables/lx_tables.o" "luxcalc.h rebuilds lx_tables.o"
would kernels/grid.cl "$B/obj/core/lx_kernels.o" "a kernel rebuilds lx_kernels.o"
would "$(ls src/data/*.csv | head -n 1)" "$B/obj/tables/lx_tables.o" "a data table rebuilds lx_tables.o"
would src/tools/lxgen.c "$B/obj/tables/lx_tables.o" "the generator rebuilds lx_tables.o"
for h in tests/fuzz/*.c; do would "$h" "$B/tests/test_fuzz" "$(basename "$h") rebuilds test_fuzz"; done
would tests/lx_test.h "$B/tests/test_units" "lx_test.h rebuilds test_units"
exit 0
