#!/bin/bash
# epsilon(v) of free disks of finite thickness H beside the plane-stress
# and plane-strain disks (nu = 0.3), each point a convergence study, one
# after the other (docs/validation/free-thick-disks.md; about 40 minutes
# on 2 cores with 24 GB):
# - 3D: the quarter y >= 0, 0 <= z <= H/2 with free faces, Q2, penalty
#   kappa = 100, energy-conserving steps, 'Graded mesh = conforming' (the
#   graded section extruded through layers graded toward the face); level
#   0 has 4 elements across the largest contact half-width (grading 0.6,
#   dt = t_c,est / 100), level 1 halves every size and the step (the bar:
#   three times their difference). The study runs on one rank, so its
#   levels run one after the other and level 1 has all the memory. Where
#   level 1 exceeds this machine's memory, level 0 alone is run (on 2
#   ranks) and reported without a bar;
# - 2D: the half disk in plane stress and in plane strain with the same
#   parameters (the same section mesh) and one level more, on 2 ranks.
# Speeds v/c with c = sqrt(E / rho) (the plane-stress unit; the
# plane-strain runs get the same physical speed). Prints a Markdown table
# of epsilon +- bar per speed and model, and each 3D study's finest DoFs,
# peak memory and wall time; writes the table as CSV to the file given
# with --csv.
#
# usage: bench/free_disk_restitution.sh [--thickness "0.1 0.25 0.5 1 2"]
#            [--speeds "0.003 0.01 0.03 0.1 0.3"] [--csv FILE] [--work DIR]
#        (build first; --work keeps the runs in DIR, else a temporary
#        directory is removed)
set -euo pipefail
cd "$(dirname "$0")/.."
thicknesses="0.1 0.25 0.5 1 2"
speeds="0.003 0.01 0.03 0.1 0.3"
csv=""
work=""
while [ $# -gt 0 ]; do
  case "$1" in
    --thickness) thicknesses="$2"; shift 2 ;;
    --speeds) speeds="$2"; shift 2 ;;
    --csv) csv="$2"; shift 2 ;;
    --work) work="$2"; shift 2 ;;
    *) echo "free_disk_restitution.sh: unknown option $1" >&2; exit 1 ;;
  esac
done
if [ -z "$work" ]; then
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
else
  mkdir -p "$work"
  work=$(cd "$work" && pwd)
fi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
study() {  # study NAME V MODEL LEVELS [H] [RANKS]: one convergence study
           # (LEVELS 1: one impact)
  local name=$1 v=$2 model=$3 levels=$4 h=${5:-} ranks=${6:-2}
  local geometry="  set Domain = half disk"
  [ -z "$h" ] || geometry="  set Dimension = 3
  set Thickness = $h
  set Faces = free"
  [ "$model" = "plane stress" ] ||
    v=$(awk "BEGIN { printf \"%.10g\", $v * sqrt(1 - 0.3 * 0.3) }")
  cat > "$work/$name.prm" <<PRM
set Task             = $([ "$levels" = 1 ] && echo impact || echo impact convergence)
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
  set Graded mesh             = conforming
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
  mpirun -np "$ranks" build/diskimpact "$work/$name.prm" > "$work/$name.log" 2>&1 ||
    { cat "$work/$name.log" >&2; return 1; }
  echo $(( ($(date +%s%N) - start) / 1000000 )) > "$work/$name.ms"
}
for v in $speeds; do
  study "stress_$v" "$v" "plane stress" 3
  study "strain_$v" "$v" "plane strain" 3
  for h in $thicknesses; do
    study "solid_${h}_$v" "$v" "plane stress" 2 "$h" 1 ||
      { grep -q "memory holds" "$work/solid_${h}_$v.log" &&
        study "solid_${h}_$v" "$v" "plane stress" 1 "$h"; }
  done
done
python3 - "$work" "$csv" "$thicknesses" "$speeds" <<'PY'
import csv, re, sys
work, out, thicknesses, speeds = sys.argv[1], sys.argv[2], sys.argv[3].split(), sys.argv[4].split()
def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))
def estimate(name):
    log = open(f"{work}/{name}.log").read()
    memory = re.search(r"peak memory (\d+)", log).group(1)
    seconds = int(open(f"{work}/{name}.ms").read()) / 1000
    if "Convergence study" not in log:  # level 0 alone: no bar
        epsilon = float(re.search(r"epsilon = ([0-9.]+)", log).group(1))
        dofs = int(re.search(r"DoFs (\d+)", log).group(1))
        return epsilon, float("nan"), dofs, memory, seconds
    total = [r for r in read(f"{work}/{name}/epsilon_estimate.csv") if r["factor"] == "total"][0]
    runs = read(f"{work}/{name}/impact_convergence.csv")
    return (float(total["limit"]), float(total["error"]), max(int(r["n_dofs"]) for r in runs),
            memory, seconds)
def show(e, b):
    return f"{e:.6f} ± {b:.1e}" if b == b else f"{e:.6f} (level 0)"
models = ["plane stress"] + [f"H = {h} R" for h in thicknesses] + ["plane strain"]
names = lambda v: [f"stress_{v}"] + [f"solid_{h}_{v}" for h in thicknesses] + [f"strain_{v}"]
rows = []
print("| v/c | " + " | ".join(models) + " |")
print("|---" * (len(models) + 1) + "|")
for v in speeds:
    values = [estimate(n) for n in names(v)]
    print(f"| {v} | " + " | ".join(show(e, b) for e, b, *_ in values) + " |")
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
