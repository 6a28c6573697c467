#!/bin/bash
# The sphere in 3D against the axisymmetric model (nu = 0.3) at
# v/c = 0.01, 0.03, 0.1 (or the speeds given), each study on 2 MPI ranks, one
# after the other:
# - 3D: the convergence study of params/impact_convergence_sphere_3d.prm
#   (the quarter sphere, two mesh levels);
# - axisymmetric, reference: the study of params/sweep_sphere.prm at the
#   speed (three mesh levels), whose epsilon +- bar the 3D one is compared
#   with;
# - axisymmetric, same levels: the 3D study's parameters on the meridian,
#   whose finest level (the same elements across the contact, grading and
#   time step) gives the contact time and delta_max to compare.
# Prints a Markdown table: epsilon +- bar of both, their difference over the
# combined bars, the 3D bar over the loss 1 - epsilon, the relative
# differences in contact time and delta_max, the 3D study's finest DoFs,
# peak memory and wall time.
#
# usage: bench/sphere_3d_vs_axisymmetric.sh [v/c ...]    (build first)
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
speeds=("$@")
[ ${#speeds[@]} -gt 0 ] || speeds=(0.01 0.03 0.1)
run() {  # run NAME: NAME.prm on 2 ranks, its log and wall time
  local start
  start=$(date +%s%N)
  mpirun -np 2 build/diskimpact "$work/$1.prm" > "$work/$1.log"
  echo $(( ($(date +%s%N) - start) / 1000000 )) > "$work/$1.ms"
}
for v in "${speeds[@]}"; do
  sed -e "s|output/impact_convergence_sphere_3d|$work/solid_$v|" \
      -e "s|Velocity                = 0.01|Velocity                = $v|" \
      params/impact_convergence_sphere_3d.prm > "$work/solid_$v.prm"
  sed -e "s|Dimension          = 3|Dimension          = 2|" \
      -e "s|$work/solid_$v|$work/same_$v|" "$work/solid_$v.prm" > "$work/same_$v.prm"
  sed -e "s|set Task             = sweep|set Task             = impact convergence|" \
      -e "s|output/sweep_sphere|$work/reference_$v|" \
      -e "s|set Velocities .*|set Velocity = $v|" \
      -e "/Convergence study per point/d" \
      params/sweep_sphere.prm > "$work/reference_$v.prm"
  for name in solid same reference; do run "${name}_$v"; done
done
python3 - "$work" "${speeds[@]}" <<'PY'
import csv, re, sys
work, speeds = sys.argv[1], sys.argv[2:]
def table(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))
def study(name, v):
    d = f"{work}/{name}_{v}"
    total = [r for r in table(f"{d}/epsilon_estimate.csv") if r["factor"] == "total"][0]
    runs = {(r["factor"], int(r["level"])): r for r in table(f"{d}/impact_convergence.csv")}
    memory = re.search(r"peak memory (\d+) MB", open(f"{d}.log").read()).group(1)
    return (float(total["limit"]), float(total["error"]), runs,
            int(open(f"{d}.ms").read()) / 1000, memory)
print("| v/c | ε 3D ± bar | ε axisymmetric ± bar | \\|Δε\\| / (bar₃ + bar₂) "
      "| bar₃ / (1 − ε) | Δt_c | Δδ_max | 3D DoFs | 3D memory | 3D wall time |")
print("|---|---|---|---|---|---|---|---|---|---|")
for v in speeds:
    e3, b3, r3, w3, m3 = study("solid", v)
    e2, b2, _, _, _ = study("reference", v)
    _, _, same, _, _ = study("same", v)
    f3, f2 = r3[("mesh", 1)], same[("mesh", 1)]
    rel = lambda k: float(f3[k]) / float(f2[k]) - 1
    print(f"| {v} | {e3:.7f} ± {b3:.1e} | {e2:.7f} ± {b2:.1e} | "
          f"{abs(e3 - e2) / (b3 + b2):.2f} | {b3 / (1 - e3):.3f} | "
          f"{rel('contact_time'):+.2%} | {rel('delta_max'):+.2%} | "
          f"{f3['n_dofs']} | {m3} MB | {w3:.0f} s |")
PY
