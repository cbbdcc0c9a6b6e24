#!/bin/sh
# demo.sh - the main job on the shipped samples (run by `make demo`): colorimetry of the sample
# spectra, a blackbody written by luxcalc itself, and whatever later sections add.
# Usage: sh samples/demo.sh PATH/TO/luxcalc
set -e
LX=${1:-build/luxcalc}
here=$(dirname "$0")
out=${LX_DEMO_OUT:-build/demo}
mkdir -p "$out"

echo "== Spectra: CIE illuminants (5 nm tables), colorimetry with the default method"
"$LX" spd --format csv "$here/spd/cie_illuminants.csv" | cut -d, -f2-11

echo
echo "== A blackbody at 2856 K written by 'luxcalc blackbody', read back (CCT should be 2856 K)"
"$LX" blackbody --temperature 2856K -o "$out/blackbody_2856K.csv"
"$LX" spd --unit W/sr/m2/nm "$out/blackbody_2856K.csv"

echo
echo "== LED-like spectra in the rows layout (one spectrum per row), W/nm"
"$LX" spd --unit W/nm --format csv "$here/spd/led_batch.csv" | cut -d, -f2,4,6,7,10,11,12,14

echo
echo "== A 532 nm laser line sampled every 0.1 nm: exact (default) vs linear1nm"
"$LX" spd --unit W/nm --format csv "$here/spd/laser_532nm.csv" | cut -d, -f2,4,12,16
"$LX" spd --unit W/nm --method linear1nm --format csv "$here/spd/laser_532nm.csv" | tail -n 1 | cut -d, -f2,4,12,16
