#!/bin/bash
# Impact benchmark: params/impact.prm (v = 0.1 c) and the same at v = 0.01 c;
# prints factorizations per run, time per step, and a step's cost in units
# of one solve with the factorized effective matrix (one pair of triangular
# solves).
#
# usage: bench/impact_benchmark.sh    (build first)
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for v in 0.1 0.01; do
  sed -e "s|output/impact|$work/out_$v|" -e "s|set Velocity .*=.*|set Velocity = $v|" \
      -e "s|set Output interval .*=.*|set Output interval = 0|" params/impact.prm > "$work/$v.prm"
  start=$(date +%s%N)
  build/diskimpact "$work/$v.prm" > "$work/log_$v"
  end=$(date +%s%N)
  echo "v = $v c: whole run $(( (end - start) / 1000000 )) ms"
  grep -E "DoFs|epsilon|energy error|time stepping" "$work/log_$v"
done
