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
