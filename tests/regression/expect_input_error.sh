#!/bin/bash
# A bad input is refused: non-zero exit, exactly one line on standard error
# containing EXPECTED, and no output directory. With --run (a run that
# fails one of its physical checks) the directory may hold used_parameters.*
# and its lock, but no result.
# usage: expect_input_error.sh DISKIMPACT PRM EXPECTED OUTPUT_DIR [--run]
diskimpact=$1 prm=$2 expected=$3 output_dir=$4 mode=$5
rm -rf "$output_dir"
stderr=$("$diskimpact" "$prm" 2>&1 >/dev/null)
status=$?
echo "exit code $status, stderr: $stderr"
[ $status -ne 0 ] || { echo "FAIL: exit code 0"; exit 1; }
[ "$(printf '%s\n' "$stderr" | wc -l)" -eq 1 ] || { echo "FAIL: not one line"; exit 1; }
printf '%s' "$stderr" | grep -qF -- "$expected" || { echo "FAIL: message lacks '$expected'"; exit 1; }
if [ "$mode" = --run ]; then
  left=$(find "$output_dir" -type f ! -name 'used_parameters.*' ! -name '.diskimpact.lock' 2>/dev/null)
  [ -z "$left" ] || { echo "FAIL: results left behind: $left"; exit 1; }
else
  [ ! -e "$output_dir" ] || { echo "FAIL: $output_dir was created"; exit 1; }
fi
echo OK
