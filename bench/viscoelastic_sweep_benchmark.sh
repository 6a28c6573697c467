#!/bin/bash
# A 5-speed Kelvin-Voigt sweep with error bars (tau = 0.05 R/c, alpha =
# 0.05) on 2 MPI ranks, with the settings of params/sweep.prm (its mesh
# levels and target error), beside the elastic 7-speed sweep of
# params/sweep.prm. Prints
# the wall times and the rows.
#
# usage: bench/viscoelastic_sweep_benchmark.sh    (build first)
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
sed -e "s|output/sweep_plane_stress|$work/viscous|" \
    -e "s|set Velocities .*|set Velocities = 0.005, 0.01, 0.02, 0.05, 0.1\n  set Relaxation times = 0.05|" \
    params/sweep.prm > "$work/viscous.prm"
start=$(date +%s%N)
mpirun -np 2 build/diskimpact "$work/viscous.prm" | tail -6
echo "5-speed viscoelastic sweep with error bars, 2 ranks: $(( ($(date +%s%N) - start) / 1000000 )) ms"
sed -e "s|output/sweep_plane_stress|$work/elastic|" params/sweep.prm > "$work/elastic.prm"
start=$(date +%s%N)
mpirun -np 2 build/diskimpact "$work/elastic.prm" | tail -8
echo "7-speed elastic sweep with error bars, 2 ranks: $(( ($(date +%s%N) - start) / 1000000 )) ms"
