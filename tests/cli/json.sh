# json.sh - every command that prints results gives json that parses (python3 -m json.tool), and
# csv with one header line, so the output pipes into jq or pandas.
. tests/cli/lib.sh
S=samples/spd/cie_illuminants.csv
check() { # NAME ARGS...: runs luxcalc ARGS --format json, then csv
  name=$1; shift
  "$LUXCALC" "$@" --format json >"$T/j" 2>"$T/e"; rc=$?
  if [ $rc -eq 0 ] && python3 -m json.tool "$T/j" >/dev/null 2>&1; then ok "$name: json parses"
  else notok "$name: json" "exit $rc: $(head -c 300 "$T/j") $(head -c 300 "$T/e")"; fi
  "$LUXCALC" "$@" --format csv >"$T/c" 2>"$T/e"; rc=$?
  if [ $rc -eq 0 ] && python3 - "$T/c" <<'PY' 2>"$T/pe"
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
assert len(rows) >= 2, "no data row"
assert all(len(r) == len(rows[0]) for r in rows), "ragged csv"
PY
  then ok "$name: csv is rectangular"; else notok "$name: csv" "exit $rc: $(cat "$T/pe") $(head -c 200 "$T/c")"; fi
}
check spd spd $S
check spd-one spd samples/spd/laser_532nm.csv
check blackbody blackbody --temperature 3000K --range 380:780:10
check daylight daylight --cct 5000
check point point --flux 1000lm --distance 2m
check spot spot --flux 800lm --exponent 20 --angle 10deg --distance 3m
check disk disk --luminance 1000cd/m2 --radius 0.5m --distance 1m
check rect rect --luminance 1000cd/m2 --width 1m --length 2m --distance 2m
check convert convert 46 fc
check solve solve --illuminance 500lx --intensity 2000cd
check ies ies samples/ies/spot_warn_30deg_800lm.ies
check grid grid --ies samples/ies/spot_warn_30deg_800lm.ies --at 1,1,3 --plane z=0 --area 0:2,0:2 --spacing 0.5
if [ "$(opencl_state)" = device ]; then check devices devices
else
  # no device: the json is an empty array and the csv its header alone (devices.sh checks both)
  skip "devices: json and csv rows" "no OpenCL device"
fi
