#!/bin/bash
# The FE impact at low speed (plane stress nu = 0.33, kappa = 400) against
# the 1-DOF log-law model and Rayleigh's model with vibration feedback
# (params/reference_rayleigh.prm): v = 0.01 ... 1e-6 c on two meshes
# (3 refinements, 12 elements, tau/200; 4 refinements, 24 elements,
# tau/400). Prints the table of docs/validation/elastic-disk-restitution.md,
# "The low-speed limit".
# About 12 min on one core.
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
velocities="0.01 0.001 0.0001 0.00001 0.000001"
sed "s|output/reference|$work/rayleigh|" params/reference_rayleigh.prm \
  > "$work/rayleigh.prm"
build/diskimpact "$work/rayleigh.prm" > "$work/rayleigh.log"
for v in $velocities; do
  bench/impact_case.sh "$work/coarse_$v" "$v" 3 12 0.3 400 0.005 > /dev/null
  bench/impact_case.sh "$work/fine_$v" "$v" 4 24 0.3 400 0.0025 > /dev/null
done
/usr/bin/python3 - "$work" $velocities <<'EOP'
import csv, math, sys
work, velocities = sys.argv[1], sys.argv[2:]
# Empty cells (a column a model or a wall run leaves blank) read as NaN.
number = lambda x: float(x) if x else math.nan
model = [{k: number(x) for k, x in r.items()}
         for r in csv.DictReader(open(f"{work}/rayleigh/reference_rayleigh.csv"))]
print("| v/c | mesh | contact time FE | vs 1-DOF | vs feedback | "
      "delta_max FE | vs 1-DOF | vs feedback | epsilon FE | feedback "
      "(N range) |")
print("|---|---|---|---|---|---|---|---|---|---|")
for v in velocities:
    rows = sorted((r for r in model if abs(r["velocity"] / float(v) - 1) < 1e-9
                   and not math.isnan(r["epsilon_feedback"])),
                  key=lambda r: r["modes"])
    ref = rows[-1]
    eps = [r["epsilon_feedback"] for r in rows]
    for mesh in ("coarse", "fine"):
        s = {k: number(x) for k, x in
             next(csv.DictReader(open(f"{work}/{mesh}_{v}/summary.csv"))).items()}
        rel = lambda a, b: f"{100 * (a / b - 1):+.2f} %"
        print(f"| {v} | {'3 ref., 12 el.' if mesh == 'coarse' else '4 ref., 24 el.'}"
              f" | {s['contact_time']:.4f} | {rel(s['contact_time'], s['one_dof_contact_time'])}"
              f" | {rel(s['contact_time'], ref['contact_time_feedback'])}"
              f" | {s['delta_max']:.5g} | {rel(s['delta_max'], s['one_dof_delta_max'])}"
              f" | {rel(s['delta_max'], ref['delta_max_feedback'])}"
              f" | {s['epsilon']:.5f} | {ref['epsilon_feedback']:.5f} (N = {int(ref['modes'])};"
              f" {min(eps):.5f}-{max(eps):.5f}) |")
EOP
