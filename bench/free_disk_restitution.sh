#!/bin/bash
# epsilon(v) of free disks of finite thickness H beside the plane-stress
# and plane-strain disks (nu = 0.3), each point a convergence study on 2
# MPI ranks, one after the other:
# - 3D: the quarter y >= 0, 0 <= z <= H/2 with free faces, Q2, penalty
#   kappa = 100, energy-conserving steps; level 0 has 4 elements across the
#   largest contact half-width (grading 0.6, dt = t_c,est / 100), level 1
#   halves every size and the step (the bar: three times their difference);
# - 2D: the half disk in plane stress and in plane strain with the same
#   parameters and one level more.
# Speeds v/c with c = sqrt(E / rho) (the plane-stress unit; the
# plane-strain runs get the same physical speed). Prints a Markdown table
# of epsilon +- bar per speed and model, and each 3D study's finest DoFs,
# peak memory and wall time; writes the table as CSV to the file given
# with --csv.
#
# usage: bench/free_disk_restitution.sh [--thickness "0.1 0.25 0.5 1 2"]
#            [--speeds "0.003 0.01 0.03 0.1 0.3"] [--csv FILE]   (build first)
set -euo pipefail
cd "$(dirname "$0")/.."
thicknesses="0.1 0.25 0.5 1 2"
speeds="0.003 0.01 0.03 0.1 0.3"
csv=""
while [ $# -gt 0 ]; do
  case "$1" in
    --thickness) thicknesses="$2"; shift 2 ;;
    --speeds) speeds="$2"; shift 2 ;;
    --csv) csv="$2"; shift 2 ;;
    *) echo "free_disk_restitution.sh: unknown option $1" >&2; exit 1 ;;
  esac
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
study() {  # study NAME V MODEL LEVELS [H]: one convergence study
  local name=$1 v=$2 model=$3 levels=$4 h=${5:-}
  local geometry="  set Domain = half disk"
  [ -z "$h" ] || geometry="  set Dimension = 3
  set Thickness = $h
  set Faces = free"
  [ "$model" = "plane stress" ] ||
    v=$(awk "BEGIN { printf \"%.10g\", $v * sqrt(1 - 0.3 * 0.3) }")
  cat > "$work/$name.prm" <<PRM
set Task             = impact convergence
set Output directory = $work/$name
subsection Geometry
$geometry
  set Global refinements = 0
end
subsection Material
  set Plane model   = $model
  set Poisson ratio = 0.3
end
subsection Finite element
  set Degree = 2
end
subsection Contact
  set Penalty factor = 100
end
subsection Impact
  set Velocity                = $v
  set Elements across contact = 4
  set Grading                 = 0.6
end
subsection Time stepping
  set Scheme             = energy conserving
  set Time step fraction = 0.01
end
subsection Impact convergence
  set Mesh levels = $levels
end
PRM
  local start
  start=$(date +%s%N)
  mpirun -np 2 build/diskimpact "$work/$name.prm" > "$work/$name.log"
  echo $(( ($(date +%s%N) - start) / 1000000 )) > "$work/$name.ms"
}
for v in $speeds; do
  study "stress_$v" "$v" "plane stress" 3
  study "strain_$v" "$v" "plane strain" 3
  for h in $thicknesses; do
    study "solid_${h}_$v" "$v" "plane stress" 2 "$h"
  done
done
python3 - "$work" "$csv" "$thicknesses" "$speeds" <<'PY'
import csv, re, sys
work, out, thicknesses, speeds = sys.argv[1], sys.argv[2], sys.argv[3].split(), sys.argv[4].split()
def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))
def estimate(name):
    total = [r for r in read(f"{work}/{name}/epsilon_estimate.csv") if r["factor"] == "total"][0]
    runs = read(f"{work}/{name}/impact_convergence.csv")
    memory = re.search(r"peak memory (\d+) MB", open(f"{work}/{name}.log").read()).group(1)
    return (float(total["limit"]), float(total["error"]), max(int(r["n_dofs"]) for r in runs),
            memory, int(open(f"{work}/{name}.ms").read()) / 1000)
models = ["plane stress"] + [f"H = {h} R" for h in thicknesses] + ["plane strain"]
names = lambda v: [f"stress_{v}"] + [f"solid_{h}_{v}" for h in thicknesses] + [f"strain_{v}"]
rows = []
print("| v/c | " + " | ".join(models) + " |")
print("|---" * (len(models) + 1) + "|")
for v in speeds:
    values = [estimate(n) for n in names(v)]
    print(f"| {v} | " + " | ".join(f"{e:.6f} ± {b:.1e}" for e, b, *_ in values) + " |")
    for model, (e, b, dofs, memory, seconds) in zip(models, values):
        rows.append({"v": v, "model": model, "epsilon": e, "bar": b, "dofs": dofs,
                     "memory_mb": memory, "seconds": seconds})
print()
for row in rows:
    if row["model"].startswith("H"):
        print(f"v = {row['v']} c, {row['model']}: {row['dofs']} DoFs, "
              f"{row['memory_mb']} MB, {row['seconds']:.0f} s")
if out:
    with open(out, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
PY
