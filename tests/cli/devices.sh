# devices.sh - `luxcalc devices`: lists OpenCL devices (or none, without failing), csv/json, help.
. tests/cli/lib.sh
run devices --help
expect_rc 0 "devices --help"
expect_out_match 'example' "devices --help has an example"
run devices --format csv
expect_rc 0 "devices runs with or without OpenCL"
expect_out_match '^platform,device,platform_name,device_name,type,compute_units,global_mem_MiB,max_alloc_MiB,fp64,version,default$' "devices csv header"
rows=$(printf '%s\n' "$out" | tail -n +2 | grep -c .)
if [ "$rows" -eq 0 ]; then
  expect_err_match 'no OpenCL' "no platform is reported on stderr"
else
  n=$(printf '%s\n' "$out" | tail -n +2 | grep -c ',yes$')
  if [ "$n" -eq 1 ]; then ok "exactly one default device"; else notok "exactly one default device" "$n defaults"; fi
fi
run devices --format json
expect_rc 0 "devices json"
expect_out_match '^\[' "devices json is an array"
run devices --format xml
expect_rc 1 "bad --format is a usage error"
run bench --sizes 0
expect_rc 1 "bench: bad --sizes is a usage error"
run bench nosuchtopic
expect_rc 1 "bench: unknown topic is a usage error"
expect_err_match 'unknown topic' "bench names the unknown topic"
