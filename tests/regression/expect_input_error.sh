#!/bin/bash
# A bad input is refused: non-zero exit, exactly one line on standard error
# containing EXPECTED, and no output directory.
# usage: expect_input_error.sh DISKIMPACT PRM EXPECTED OUTPUT_DIR
diskimpact=$1 prm=$2 expected=$3 output_dir=$4
rm -rf "$output_dir"
stderr=$("$diskimpact" "$prm" 2>&1 >/dev/null)
status=$?
echo "exit code $status, stderr: $stderr"
[ $status -ne 0 ] || { echo "FAIL: exit code 0"; exit 1; }
[ "$(printf '%s\n' "$stderr" | wc -l)" -eq 1 ] || { echo "FAIL: not one line"; exit 1; }
printf '%s' "$stderr" | grep -qF -- "$expected" || { echo "FAIL: message lacks '$expected'"; exit 1; }
[ ! -e "$output_dir" ] || { echo "FAIL: $output_dir was created"; exit 1; }
echo OK
