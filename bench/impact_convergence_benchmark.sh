#!/bin/bash
# Time to an epsilon with error bar: the convergence study at v = 0.1 c
# (params/impact_convergence.prm, its runs on 2 MPI ranks) and the 7-speed
# sweep with a study at every point (params/sweep.prm on 2 MPI ranks).
# Prints the wall times and the results.
#
# usage: bench/impact_convergence_benchmark.sh    (build first)
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
sed -e "s|output/impact_convergence|$work/study|" params/impact_convergence.prm > "$work/study.prm"
start=$(date +%s%N)
mpirun -np 2 build/diskimpact "$work/study.prm" | grep -E "epsilon ="
echo "one epsilon with error bar: $(( ($(date +%s%N) - start) / 1000000 )) ms"
sed -e "s|output/sweep_plane_stress|$work/sweep|" params/sweep.prm > "$work/sweep.prm"
start=$(date +%s%N)
mpirun -np 2 build/diskimpact "$work/sweep.prm" | tail -7
echo "7-speed sweep with error bars, 2 ranks: $(( ($(date +%s%N) - start) / 1000000 )) ms"
