#!/bin/bash
# Every shipped parameter file (or those given) on 1 and on 2 MPI ranks:
# each result table of the 2-rank run must hold the 1-rank numbers to a
# relative 1e-9 (tests/regression/compare_tables.py; wall times ignored, and
# the balance errors, which are round-off of size 1e-13 and differ in their
# last digits with the order of the sums: energy_error, impulse_error,
# force_balance_error).
# Prints per file: both wall times and the comparison of each CSV.
#
# usage: bench/two_rank_acceptance.sh [params/FILE.prm ...]   (build first)
# All of params/ takes hours (the plane-strain and viscoelastic sweeps).
set -uo pipefail
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
files=("$@")
[ ${#files[@]} -eq 0 ] && files=(params/*.prm)
failures=0
for prm in "${files[@]}"; do
  name=$(basename "$prm" .prm)
  out=$(sed -n 's/^ *set Output directory *= *//p' "$prm")
  line="$name:"
  for ranks in 1 2; do
    dir="$work/$name-$ranks"
    mkdir -p "$dir"
    sed -e "s|^\( *set Output directory *=\).*|\1 $dir/out|" "$prm" > "$dir/run.prm"
    # relative mesh files and includes resolve from the repository root
    start=$(date +%s%N)
    if ! mpirun -q -np $ranks build/diskimpact "$dir/run.prm" > "$dir/log" 2>&1; then
      line="$line $ranks rank(s) FAILED: $(tail -1 "$dir/log")"
      failures=$((failures + 1))
      continue 2
    fi
    line="$line $ranks rank(s) $(( ($(date +%s%N) - start) / 1000000 )) ms,"
  done
  for csv in "$work/$name-1/out"/*.csv; do
    table=$(basename "$csv")
    if result=$(/usr/bin/python3 tests/regression/compare_tables.py \
                 "$csv" "$work/$name-2/out/$table" 1e-9 \
                 --ignore energy_error,impulse_error,force_balance_error 2>&1); then
      line="$line $table same;"
    else
      line="$line $table DIFFERS ($(echo "$result" | tail -1));"
      failures=$((failures + 1))
    fi
  done
  echo "$line"
done
echo "$failures failure(s)"
[ $failures -eq 0 ]
