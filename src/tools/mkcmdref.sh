#!/bin/sh
# writes the README's command reference: one example of every command with its output
LX=${1:-build/luxcalc}
cd "$(dirname "$0")/../.."
ex() { # TITLE CMD...
  title=$1; shift
  echo "**\`$title\`**"
  echo
  echo '```'
  echo "\$ luxcalc $*"
  "$LX" "$@" 2>&1 | head -n ${LINES_MAX:-14} | cut -c1-160
  echo '```'
  echo
}
echo "<!-- section: commands -->"
echo "## Every command, with an example and its output"
echo
echo "Generated from the shipped samples (\`sh src/tools/mkcmdref.sh\`); csv where the full output is one row."
echo
LINES_MAX=20 ex "spd" spd --metrics cri_ra,cri_r9,tm30_rf,tm30_rg,melanopic_der samples/spd/led_batch.csv
LINES_MAX=18 ex "spd --uncertainty" spd --uncertainty '1%+scale=2%+shift=0.2nm' --uncertainty-method gum --metrics cri_ra samples/spd/lamp.csv
ex "blackbody" blackbody --temperature 2856K --range 380:780:100
ex "daylight" daylight --cct 6504 --range 400:700:100
ex "point" point --flux 1000lm --distance 2m --angle 30deg
ex "spot" spot --flux 800lm --beam-angle 25deg --angle 10deg --distance 2.5m
ex "disk" disk --luminance 1000cd/m2 --radius 0.5m --distance 1m
ex "rect" rect --luminance 3000cd/m2 --width 0.6m --length 1.2m --distance 2m --at centre
ex "convert" convert 46 fc --format csv
ex "solve" solve --illuminance 500lx --intensity 2000cd
ex "ies" ies --format csv samples/ies/spot_warn_30deg_800lm.ies
ex "grid" grid --ies samples/ies/spot_warn_30deg_800lm.ies --at 2,1.5,2.8 --plane z=0.8 --area 0:4,0:3 --spacing 1 --format csv
ex "grid" grid --ies samples/ies/spot_warn_30deg_800lm.ies --at 2,1.5,2.8 --plane z=0.8 --area 0:4,0:3 --spacing 1 --points-at centres --format table
ex "irradiance" irradiance samples/envmaps/sky_sun.exr --normal 0,0,1 --method fast --format csv
ex "luminance-map" luminance-map samples/envmaps/sky_sun.exr --format csv
ex "sky" sky --type cie --number 12 --zenith-luminance 6000cd/m2 --sun-altitude 40deg --sun-azimuth 180deg --sun-illuminance 80000lx --format csv
LINES_MAX=30 ex "ugr" ugr samples/ies/downlight_lambert_1000lm.ies
LINES_MAX=20 ex "scene" scene samples/scenes/spectral.scene
ex "devices" devices --format csv
topics=$("$LX" bench --help 2>&1 | awk '/^topics:/ { on = 1; next } on && NF { printf "%s%s", sep, $1; sep = "|" }')
echo "**\`bench\`**: \`luxcalc bench [$topics]\` prints the measured tables as markdown (a run takes"
echo "minutes; \`make bench\` runs all topics and writes each to \`samples/bench/TOPIC.md\`, dated, the CPU"
echo "named: the files the sections above link)."
echo
echo "<!-- end: commands -->"
