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

echo
echo "== The same FL2 and FL11 read from an Argyll .sp (CGATS) file"
"$LX" spd --format csv "$here/spd/fl2_fl11_argyll.sp" | cut -d, -f2,6,7,10,11

echo
echo "== Colour rendering (CIE 13.3 Ra, R9; TM-30 Rf, Rg) and melanopic DER of the CIE illuminants"
"$LX" spd --metrics cri_ra,cri_r9,tm30_rf,tm30_rg,melanopic_der --format csv "$here/spd/cie_illuminants.csv" | cut -d, -f2,17-
"$LX" spd --metrics cri_ra,cri_r9,tm30_rf,tm30_rg,melanopic_der --format csv "$here/spd/led_batch.csv" | tail -n +2 | cut -d, -f2,17-

echo
echo "== Lighting calculations: a 1000 lm lamp 2 m away at 30 deg; a 25 deg spot; a disk and a panel"
"$LX" point --flux 1000lm --distance 2m --angle 30deg --format csv
"$LX" spot --flux 800lm --beam-angle 25deg --angle 10deg --distance 2.5m --format csv
"$LX" disk --luminance 1000cd/m2 --radius 0.5m --distance 1m --offset 0.8m --format csv
"$LX" rect --luminance 3000cd/m2 --width 0.6m --length 1.2m --distance 2m --at centre --format csv
"$LX" solve --illuminance 500lx --intensity 2000cd --format csv

echo
echo "== Luminaires: the project's own samples (written by 'luxcalc ies --write' from analytic models)"
"$LX" ies --format csv "$here/ies/point_isotropic_1000lm.ies" "$here/ies/downlight_lambert_1000lm.ies" \
  "$here/ies/spot_warn_30deg_800lm.ies" | cut -d, -f1-7
echo
echo "== A grid: the Lambertian downlight at 2.8 m over a 4 m x 4 m work plane at 0.8 m"
"$LX" grid --ies "$here/ies/downlight_lambert_1000lm.ies" --at 2,2,2.8 --plane z=0.8 --area 0:4,0:4 \
    --spacing 0.1 --summary --png "$out/grid_downlight.png"
echo "(plot: $out/grid_downlight.png)"

echo
echo "== Scenes: only the effects each scene needs (issue 8); the grids' PNGs go to $out/"
for s in office street facade spectral; do
  echo "-- $s: the plan"
  "$LX" scene --explain "$here/scenes/$s.scene" | sed -n '/^effects:/,/^work:/p' | sed '$d'
  "$LX" scene --png "$out" "$here/scenes/$s.scene"
done

echo
echo "== A room: the office downlights in a 6 x 4 x 2.8 m room with a desk and a partition; shadows"
echo "   and interreflection (samples/scenes/office_room.scene), its plan, the receivers, the faces"
"$LX" scene --explain "$here/scenes/office_room.scene"
"$LX" scene --png "$out" "$here/scenes/office_room.scene"
"$LX" scene --surfaces --format csv "$here/scenes/office_room.scene" | cut -d, -f1-5

echo
echo "== Daylight (issue 21): a side-lit office, two clear-glazed windows, the CIE overcast sky"
"$LX" scene --explain "$here/scenes/daylight_room.scene" -o "$out/daylight_room_explain.txt"
sed -n '/^effects:/,/^pairs:/p' "$out/daylight_room_explain.txt" | sed '$d'
sed -n '/^daylight:/,$p' "$out/daylight_room_explain.txt"
"$LX" scene --png "$out" "$here/scenes/daylight_room.scene"

echo
echo "== Radiance fields: irradiance from a lat-long sky with a sun (samples/envmaps/sky_sun.exr)"
for m in sh9 fast brute; do
  "$LX" irradiance "$here/envmaps/sky_sun.exr" --normal 0,0,1 --method $m --backend cpu --format csv | tail -n 1 | cut -d, -f1-6
done
echo "   (a horizontal receiver: sh9 rings around the sun; fast = brute, the exact sum)"
"$LX" irradiance "$here/envmaps/sky_sun.exr" -o "$out/sky_irradiance.exr" --png "$out/sky_irradiance.png"
"$LX" luminance-map "$here/envmaps/sky_sun.exr" --png "$out/sky_luminance.png" --format csv
echo "   wrote $out/sky_irradiance.exr, $out/sky_irradiance.png, $out/sky_luminance.png"

echo
echo "== The deliverable: a small office checked against its requirements (EN 12464-1, EN 1838), its"
echo "   energy (EN 15193-1) and the PDF report (samples/deliverable/office.scene)"
"$LX" scene --check "$here/deliverable/office.scene"
"$LX" scene --energy "$here/deliverable/office.scene" | tail -n 1
"$LX" report "$here/deliverable/office.scene" -o "$out/office_report.pdf" --project "Example office, 2nd floor"
