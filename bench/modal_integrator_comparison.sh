#!/bin/bash
# The two integrators of the modal-expansion model
# (docs/theory/modal-expansion-model.md)
# against the time step: epsilon, energy error and steps at v = 0.1 c,
# nu2 = 0.33 for (N, alpha) = (20, 100) and (100, 500), RK4 in the
# interaction picture and the Strang splitting at 5 ... 160 steps per
# period of the fastest motion; the reference is RK4 at 1280.
#
# usage: bench/modal_integrator_comparison.sh    (build first)
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run() { # N alpha integrator steps -> "epsilon energy_error steps wall_time"
  cat > "$work/run.prm" <<PRM
set Task = modal expansion impact
set Output directory = $work/out
subsection Material
  set Plane model = plane stress
  set Poisson ratio = 0.33
end
subsection Modal expansion
  set Velocities = 0.1
  set Potential stiffnesses = $2
  set Mode counts = $1
  set Integrator = $3
  set Steps per period = $4
  set Number of listed modes = 0
end
PRM
  build/diskimpact "$work/run.prm" > /dev/null
  tail -1 "$work/out/modal_expansion.csv" | awk -F, '{print $5, $8, $10, $11}'
}
for case in "20 100" "100 500"; do
  set -- $case
  reference=$(run $1 $2 "runge kutta" 1280 | cut -d' ' -f1)
  echo "N = $1, alpha = $2: reference epsilon (RK4, 1280 steps per period) = $reference"
  echo "steps/period  integrator   |d epsilon|  max dH/H   steps  time [s]"
  for steps in 5 10 20 40 80 160; do
    for integrator in splitting "runge kutta"; do
      read -r epsilon energy n time < <(run $1 $2 "$integrator" $steps)
      awk -v s=$steps -v i="$integrator" -v e=$epsilon -v r=$reference \
          -v h=$energy -v n=$n -v t=$time \
          'BEGIN { d = e - r; if (d < 0) d = -d;
                   printf "%12d  %-11s  %10.1e  %9.1e  %6d  %8.3f\n", s, i, d, h, n, t }'
    done
  done
done
