# install.sh - `make install` to a temporary prefix gives a library that a program finds with
# pkg-config, builds against and runs with no file from the source tree; `make uninstall` removes it.
. tests/cli/lib.sh
B=$(dirname "$LUXCALC")
P="$T/prefix"
# make install needs the build itself; make valgrind's wrapper dir holds none (building one there
# would replace its valgrind wrappers with plain binaries for the cases that run after this one)
if [ ! -d "$B/obj" ]; then skip "make install" "$B is not a build dir (valgrind wrappers)"; exit 0; fi
if make -s BUILD="$B" install PREFIX="$P" >"$T/make.log" 2>&1; then ok "make install PREFIX=tmp"; else notok "make install" "$(tail -5 "$T/make.log")"; fi
for f in bin/luxcalc include/luxcalc.h lib/libluxcalc.a lib/libluxcalc.so.0 lib/pkgconfig/luxcalc.pc \
         share/man/man1/luxcalc.1 share/man/man3/luxcalc.3 share/bash-completion/completions/luxcalc; do
  if [ -e "$P/$f" ]; then ok "installed $f"; else notok "installed $f" "missing"; fi
done
if [ "$(readlink "$P/lib/libluxcalc.so.0")" != "" ] && objdump -p "$P/lib/libluxcalc.so.0" 2>/dev/null | grep -q 'SONAME *libluxcalc.so.0'; then
  ok "versioned soname libluxcalc.so.0"; else notok "soname" "$(objdump -p "$P/lib/libluxcalc.so.0" 2>&1 | grep SONAME)"; fi
# build the embedding example outside the tree, against the installed copy only
mkdir -p "$T/app" && cp samples/embed/*.c "$T/app/"
export PKG_CONFIG_PATH="$P/lib/pkgconfig"
if (cd "$T/app" && cc -std=c11 -Wall -o spectrum spectrum.c $(pkg-config --cflags --libs luxcalc) $(cat "$OLDPWD/$B/libs.txt")) 2>"$T/cc.err"; then
  ok "embed example builds with pkg-config --cflags --libs luxcalc"; else notok "embed build" "$(cat "$T/cc.err")"; fi
cp samples/spd/cie_illuminants.csv "$T/app/"
out=$(cd "$T/app" && LD_LIBRARY_PATH="$P/lib" ./spectrum cie_illuminants.csv 2>&1)
if printf '%s\n' "$out" | grep -Eq '^D65: x=0\.3127[12] '; then ok "installed library runs the example"; else notok "installed run" "$out"; fi
# the installed binary runs from anywhere (tables and kernels are embedded)
out=$(cd "$T" && LD_LIBRARY_PATH="$P/lib" "$P/bin/luxcalc" --version)
if printf '%s\n' "$out" | grep -Eq '^luxcalc [0-9]+\.[0-9]+\.[0-9]+$'; then ok "installed luxcalc --version"; else notok "installed --version" "$out"; fi
if bash -n "$P/share/bash-completion/completions/luxcalc" 2>"$T/bash.err"; then ok "completion script parses"; else notok "completion" "$(cat "$T/bash.err")"; fi
if grep -q '^\.SS spd' "$P/share/man/man1/luxcalc.1" && grep -q 'lx_spd_colorimetry' "$P/share/man/man3/luxcalc.3"; then ok "man pages cover commands and API"; else notok "man pages" "missing sections"; fi
make -s BUILD="$B" uninstall PREFIX="$P" >/dev/null 2>&1
left=$(find "$P" -type f -o -type l)
if [ -z "$left" ]; then ok "make uninstall removes every file"; else notok "uninstall" "$left"; fi
