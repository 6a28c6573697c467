#!/bin/bash
# A disk of thickness R with its faces held at u_z = 0 in 3D against the
# plane-strain disk in 2D (nu = 0.3, v = 0.1 c): the convergence study of
# params/impact_convergence_disk_3d_held.prm (two mesh levels) and the same
# parameters on the 2D half disk with one level more, each on 2 MPI ranks.
# Prints a Markdown table: epsilon +- bar of both, their difference over the
# combined bars, and at the 3D study's finest level (the same elements
# across the contact, grading and time step) both epsilon, contact times
# and delta_max; the 3D study's finest DoFs, peak memory and wall time.
#
# usage: bench/disk_3d_held_vs_plane_strain.sh    (build first)
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
sed -e "s|output/impact_convergence_disk_3d_held|$work/solid|" \
    params/impact_convergence_disk_3d_held.prm > "$work/solid.prm"
sed -e "s|  set Dimension          = 3|  set Domain             = half disk|" \
    -e "/Thickness/d" -e "/Faces/d" -e "s|Mesh levels = 2|Mesh levels = 3|" \
    -e "s|$work/solid|$work/plane|" "$work/solid.prm" > "$work/plane.prm"
for name in solid plane; do
  start=$(date +%s%N)
  mpirun -np 2 build/diskimpact "$work/$name.prm" > "$work/$name.log"
  echo $(( ($(date +%s%N) - start) / 1000000 )) > "$work/$name.ms"
done
python3 - "$work" <<'PY'
import csv, re, sys
work = sys.argv[1]
def table(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))
def study(name):
    d = f"{work}/{name}"
    total = [r for r in table(f"{d}/epsilon_estimate.csv") if r["factor"] == "total"][0]
    runs = {(r["factor"], int(r["level"])): r for r in table(f"{d}/impact_convergence.csv")}
    memory = re.search(r"peak memory (\d+) MB", open(f"{d}.log").read()).group(1)
    return (float(total["limit"]), float(total["error"]), runs[("mesh", 1)],
            int(open(f"{d}.ms").read()) / 1000, memory)
e3, b3, f3, w3, m3 = study("solid")
e2, b2, f2, _, _ = study("plane")
rel = lambda k: float(f3[k]) / float(f2[k]) - 1
print("| model | ε ± bar | ε, level 1 | t_c, level 1 | δ_max, level 1 |")
print("|---|---|---|---|---|")
print(f"| 3D, faces held | {e3:.7f} ± {b3:.1e} | {float(f3['epsilon']):.7f} | "
      f"{float(f3['contact_time']):.5f} | {float(f3['delta_max']):.6f} |")
print(f"| 2D plane strain | {e2:.7f} ± {b2:.1e} | {float(f2['epsilon']):.7f} | "
      f"{float(f2['contact_time']):.5f} | {float(f2['delta_max']):.6f} |")
print()
print(f"|Δε| / (bar3 + bar2) = {abs(e3 - e2) / (b3 + b2):.2f}; level 1: Δε = "
      f"{float(f3['epsilon']) - float(f2['epsilon']):+.1e}, Δt_c = "
      f"{rel('contact_time'):+.2%}, Δδ_max = {rel('delta_max'):+.3%}; 3D: "
      f"{f3['n_dofs']} DoFs, {m3} MB, {w3:.0f} s")
PY
