# embed.sh - the embedding example in samples/embed builds against the library and runs.
. tests/cli/lib.sh
B=$(dirname "$LUXCALC")
if cc -std=c11 -Wall -Wextra -Isrc -o "$T/spectrum" samples/embed/spectrum.c "$B/libluxcalc.a" $(cat "$B/libs.txt") 2>"$T/cc.err"; then
  ok "samples/embed/spectrum.c compiles against libluxcalc.a"
else
  notok "samples/embed/spectrum.c compiles" "$(cat "$T/cc.err")"
fi
out=$("$T/spectrum" samples/spd/cie_illuminants.csv 2>&1)
# CIE 015:2018: D65 x = 0.31271, y = 0.32902 (the 380-780 nm sample data gives 0.31272, 0.32903)
if printf '%s\n' "$out" | grep -Eq '^D65: x=0\.3127[12] y=0\.3290[23] '; then ok "embed example prints D65"; else notok "embed example prints D65" "$out"; fi
# the README's C program, extracted from its "## The C API" section: it compiles, prints the first
# spectrum's CCT, and on a missing or malformed file prints the library's message and exits 2 (it
# used set->spd[0] after a failed read before, and crashed)
awk '/^## The C API/{s=1} s && /^```c$/{c=1; next} c && /^```$/{exit} c' README.md >"$T/readme_example.c"
if [ -s "$T/readme_example.c" ] &&
   cc -std=c11 -Wall -Wextra -Werror -Isrc -o "$T/readme_example" "$T/readme_example.c" "$B/libluxcalc.a" $(cat "$B/libs.txt") 2>"$T/cc2.err"; then
  ok "README C example compiles (-Wall -Wextra -Werror)"
else
  notok "README C example compiles" "$(cat "$T/cc2.err")"
fi
out=$("$T/readme_example" samples/spd/cie_illuminants.csv 2>&1); rc=$?
# CIE illuminant A: 2856 K on the Planckian locus (CIE 015:2018), Duv 0 to 1e-4
if [ "$rc" -eq 0 ] && printf '%s\n' "$out" | grep -Eq '^A: CCT 285[56] K, Duv -?0\.000[01]$'; then ok "README example: illuminant A"
else notok "README example: illuminant A" "exit $rc: $out"; fi
out=$("$T/readme_example" "$T/no_such_file.csv" 2>&1); rc=$?
if [ "$rc" -eq 2 ] && printf '%s\n' "$out" | grep -q 'no_such_file.csv'; then ok "README example: a missing file is a message and exit 2"
else notok "README example: a missing file is a message and exit 2" "exit $rc: $out"; fi
printf 'nm,a\n380,1\nabc,2\n' >"$T/bad.csv"
out=$("$T/readme_example" "$T/bad.csv" 2>&1); rc=$?
if [ "$rc" -eq 2 ] && printf '%s\n' "$out" | grep -q 'bad.csv:3'; then ok "README example: a malformed file names its line, exit 2"
else notok "README example: a malformed file names its line, exit 2" "exit $rc: $out"; fi
