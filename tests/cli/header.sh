# header.sh - the public header compiles as C99 and C11 with -Wpedantic, and as C++.
. tests/cli/lib.sh
printf '#include "luxcalc.h"\nint main(void) { return lx_version() == 0; }\n' > "$T/h.c"
for std in c99 c11; do
  if cc -std=$std -Wall -Wextra -Wpedantic -Werror -Isrc -fsyntax-only "$T/h.c" 2>"$T/err"; then ok "header is $std clean"; else notok "header $std" "$(cat "$T/err")"; fi
done
cp "$T/h.c" "$T/h.cpp"
if command -v c++ >/dev/null 2>&1; then
  if c++ -std=c++11 -Wall -Wextra -Wpedantic -Werror -Isrc -fsyntax-only "$T/h.cpp" 2>"$T/err"; then ok "header compiles as C++"; else notok "header C++" "$(cat "$T/err")"; fi
else
  skip "header compiles as C++" "no c++ compiler"
fi
