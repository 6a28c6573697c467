#!/bin/bash
# The two epsilon(v) curves with error bars at 20 speeds, v/c = 0.005 ... 0.3
# (geometric): plane stress nu = 0.33 (params/sweep.prm) and plane strain
# nu2 = 0.9 (params/sweep_plane_strain.prm), each a sweep on 2 MPI ranks with
# a convergence study at every speed. Prints each sweep's wall time, the sum
# of its points' run times, its largest error bar and how many bars exceed
# 1e-3. First it prints this machine's speed as the time of one solve with
# the factorized matrix of the standard impact (params/impact.prm, one rank):
# the curves' time is mostly such solves, and it differs between machines.
#
# usage: bench/restitution_curves.sh    (build first)
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
speeds=$(/usr/bin/python3 -c "print(', '.join(f'{0.005 * 60 ** (i / 19):.6g}' for i in range(20)))")
sed -e "s|output/impact|$work/impact|" -e "s|set Output interval .*=.*|set Output interval = 0|" \
    -e "s|^\( *set Velocity *=.*\)|\1\n  set Number of projected modes = 0|" params/impact.prm > "$work/impact.prm"
build/diskimpact "$work/impact.prm" | /usr/bin/python3 -c '
import re, sys
log = sys.stdin.read()
dofs = re.search(r"DoFs (\d+)", log).group(1)
solve = re.search(r"\(one: ([0-9.e+-]+) ms\)", log).group(1)
print(f"this machine: one solve of the standard impact (params/impact.prm, {dofs} DoFs) "
      f"takes {float(solve):.3f} ms")'
for prm in params/sweep.prm params/sweep_plane_strain.prm; do
  name=$(basename "$prm" .prm)
  sed -e "s|^set Output directory.*|set Output directory = $work/$name|" \
      -e "s|^\( *set Velocities *=\).*|\1 $speeds|" "$prm" > "$work/$name.prm"
  start=$(date +%s%N)
  mpirun -np 2 build/diskimpact "$work/$name.prm" > "$work/$name.log"
  ms=$(( ($(date +%s%N) - start) / 1000000 ))
  /usr/bin/python3 - "$work/$name/restitution.csv" "$name" "$ms" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
bars = [float(r["epsilon_error"]) for r in rows]
runs = sum(float(r["wall_time"]) for r in rows)
print(f"{sys.argv[2]}: {len(rows)} speeds in {int(sys.argv[3]) / 1000:.1f} s on 2 ranks "
      f"(the points' run times sum to {runs:.1f} s); "
      f"largest bar {max(bars):.2e}; {sum(b > 1e-3 for b in bars)} bars above 1e-3")
for r in rows:
    print(f"  v/c = {float(r['velocity']):.5g}: {float(r['epsilon']):.6f} +- {float(r['epsilon_error']):.1e}")
PY
done
