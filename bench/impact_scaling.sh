#!/bin/bash
# Strong scaling of one large impact: params/impact.prm with more global
# refinements (default 5), no VTU output and no mode projection, on 1 and
# on 2 MPI ranks. Prints DoFs, steps, wall time per run, the speed-up and
# the difference of epsilon between the runs (the same to 1e-10).
#
# usage: bench/impact_scaling.sh [GLOBAL_REFINEMENTS]    (build first)
set -euo pipefail
cd "$(dirname "$0")/.."
refinements=${1:-5}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
declare -A seconds epsilon
for ranks in 1 2; do
  sed -e "s|output/impact|$work/out_$ranks|" \
      -e "s|set Global refinements .*=.*|set Global refinements = $refinements|" \
      -e "s|set Output interval .*=.*|set Output interval = 0\n  set Number of projected modes = 0|" \
      params/impact.prm > "$work/$ranks.prm"
  start=$(date +%s%N)
  mpirun -q -np "$ranks" build/diskimpact "$work/$ranks.prm" > "$work/log_$ranks"
  end=$(date +%s%N)
  seconds[$ranks]=$(awk -v ns=$(( end - start )) 'BEGIN { printf "%.2f", ns / 1e9 }')
  epsilon[$ranks]=$(/usr/bin/python3 -c "import csv; print(next(csv.DictReader(open('$work/out_$ranks/summary.csv')))['epsilon'])")
  echo "$ranks rank(s): wall time ${seconds[$ranks]} s, epsilon = ${epsilon[$ranks]}"
  grep -E "DoFs|time stepping" "$work/log_$ranks" | sed 's/^/  /'
done
awk -v t1="${seconds[1]}" -v t2="${seconds[2]}" -v e1="${epsilon[1]}" -v e2="${epsilon[2]}" \
  'BEGIN { d = e1 - e2; if (d < 0) d = -d;
           printf "speed-up 1 -> 2 ranks: %.2f (parallel efficiency %.0f %%); |epsilon_1 - epsilon_2| = %.1e\n",
                  t1 / t2, 50 * t1 / t2, d }'
