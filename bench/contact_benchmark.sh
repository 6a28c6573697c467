#!/bin/bash
# Quasistatic contact benchmark: the 7-load sweep of params/quasistatic_contact.prm
# (one Poisson ratio), its wall time, and per load the DoFs and Newton
# iterations.
#
# usage: bench/contact_benchmark.sh [RANKS]    (default 1; build first)
set -euo pipefail
cd "$(dirname "$0")/.."
ranks=${1:-1}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sed "s|output/quasistatic_contact|$work/out|" params/quasistatic_contact.prm > "$work/sweep.prm"
start=$(date +%s%N)
mpirun -np "$ranks" build/diskimpact "$work/sweep.prm" > "$work/log" 2>&1
end=$(date +%s%N)
grep -A8 "C_com" "$work/log" | head -8
printf "7-load sweep on %d rank(s): %d.%03d s wall (start-up included)\n" "$ranks" \
  $(( (end - start) / 1000000000 )) $(( (end - start) / 1000000 % 1000 ))
