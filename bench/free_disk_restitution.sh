#!/bin/bash
# epsilon(v) of free disks of finite thickness H beside the plane-stress
# and plane-strain disks (nu = 0.3), each point a convergence study, one
# after the other (docs/validation/free-thick-disks.md; about two and a
# half hours on 2 cores with 24 GB):
# - 3D: the quarter y >= 0, 0 <= z <= H/2 with free faces, Q2, penalty
#   kappa = 100, energy-conserving steps, 'Graded mesh = conforming' (the
#   graded section extruded through layers graded toward the face); level
#   0 has 4 elements across the largest contact half-width (grading 0.6,
#   dt = t_c,est / 100), level 1 halves every size and the step (the bar:
#   three times their difference). The study runs on one rank, so its
#   levels run one after the other and level 1 has all the memory. Where
#   level 1 exceeds this machine's memory, it is run in two parts: the
#   section refined with the time step (and so the penalty k = kappa E2 / h
#   with them; level 0's layers, 'Layer refinement = -1'), and the layers
#   refined alone (level 0's section and step, 'Layer refinement = 1').
#   Level 1's change |d| is about |d_s| + |d_z| (their changes from level
#   0), and level 0 is within |d| of level 1, whose bar is 3 |d|: the
#   point is level 0 with the bar 4 (|d_s| + |d_z|), marked "parts". Where
#   a part exceeds the memory as well, level 0 is shown alone, without a
#   bar; --parts runs every 3D point in parts and also its whole level 1,
#   and prints the two side by side (the check of |d| against
#   |d_s| + |d_z|);
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
#            [--parts]
#        (build first; --work keeps the runs in DIR, else a temporary
#        directory is removed; run again with the same DIR, the bench
#        reuses every run there that finished with the same parameters,
#        so a killed bench resumes where it stopped)
set -euo pipefail
cd "$(dirname "$0")/.."
thicknesses="0.1 0.25 0.5 1 2"
speeds="0.003 0.01 0.03 0.1 0.3"
csv=""
work=""
parts=0
while [ $# -gt 0 ]; do
  case "$1" in
    --thickness) thicknesses="$2"; shift 2 ;;
    --speeds) speeds="$2"; shift 2 ;;
    --csv) csv="$2"; shift 2 ;;
    --work) work="$2"; shift 2 ;;
    --parts) parts=1; shift ;;
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
study() {  # study NAME V MODEL LEVELS [H] [RANKS] [PART]: one convergence
           # study (LEVELS 1: one impact; PART section or layers: that
           # part of level 1 alone)
  local name=$1 v=$2 model=$3 levels=$4 h=${5:-} ranks=${6:-2} part=${7:-}
  local refinements=0 across=4 grading=0.6 layers=0 fraction=0.01
  case "$part" in
    section) refinements=1 across=8 grading=0.3 layers=-1 fraction=0.005 ;;
    layers) layers=1 ;;
  esac
  local geometry="  set Domain = half disk"
  [ -z "$h" ] || geometry="  set Dimension = 3
  set Thickness = $h
  set Faces = free"
  [ "$model" = "plane stress" ] ||
    v=$(awk "BEGIN { printf \"%.10g\", $v * sqrt(1 - 0.3 * 0.3) }")
  cat > "$work/$name.prm.new" <<PRM
set Task             = $([ "$levels" = 1 ] && echo impact || echo impact convergence)
set Output directory = $work/$name
subsection Geometry
$geometry
  set Global refinements = $refinements
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
  set Elements across contact = $across
  set Grading                 = $grading
  set Graded mesh             = conforming
$([ -z "$h" ] || echo "  set Layer refinement      = $layers")
end
subsection Time stepping
  set Scheme             = energy conserving
  set Time step fraction = $fraction
end
subsection Impact convergence
  set Mesh levels = $levels
end
PRM
  # a run that finished with these parameters (its wall time written) is
  # kept, any other one is run afresh
  if [ -f "$work/$name.ms" ] && cmp -s "$work/$name.prm.new" "$work/$name.prm"; then
    rm "$work/$name.prm.new"
    echo "free_disk_restitution.sh: $name done before, kept" >&2
    return 0
  fi
  mv "$work/$name.prm.new" "$work/$name.prm"
  rm -f "$work/$name.ms"
  local start
  start=$(date +%s%N)
  mpirun -np "$ranks" build/diskimpact "$work/$name.prm" > "$work/$name.log" 2>&1 ||
    { cat "$work/$name.log" >&2; return 1; }
  echo $(( ($(date +%s%N) - start) / 1000000 )) > "$work/$name.ms"
}
refused() {  # refused NAME: whether run NAME was refused for the memory
  grep -q "memory holds" "$work/$1.log"
}
in_parts() {  # in_parts NAME V H: level 0 and the two parts of level 1
  local name=$1 v=$2 h=$3 part
  study "$name" "$v" "plane stress" 1 "$h" || return 1
  for part in section layers; do
    # one rank: the part has all the memory
    study "${name}_$part" "$v" "plane stress" 1 "$h" 1 "$part" ||
      { refused "${name}_$part" && rm -f "$work/${name}_$part.ms" && return 0; }
  done
}
for v in $speeds; do
  study "stress_$v" "$v" "plane stress" 3
  study "strain_$v" "$v" "plane strain" 3
  for h in $thicknesses; do
    if [ $parts = 1 ]; then
      in_parts "parts_${h}_$v" "$v" "$h"
      study "solid_${h}_$v" "$v" "plane stress" 2 "$h" 1 ||
        { refused "solid_${h}_$v" && rm -f "$work/solid_${h}_$v.ms"; }
    else
      study "solid_${h}_$v" "$v" "plane stress" 2 "$h" 1 ||
        { refused "solid_${h}_$v" && in_parts "solid_${h}_$v" "$v" "$h"; }
    fi
  done
done
python3 - "$work" "$csv" "$thicknesses" "$speeds" "$parts" <<'PY'
import csv, os, re, sys
work, out = sys.argv[1], sys.argv[2]
thicknesses, speeds, parts = sys.argv[3].split(), sys.argv[4].split(), sys.argv[5] == "1"
PARTS = ("section", "layers")
def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))
def cost(name):
    """Peak memory [MB] and wall time [s] of run NAME."""
    log = open(f"{work}/{name}.log").read()
    return (float(re.search(r"peak memory ([0-9.]+)", log).group(1)),
            int(open(f"{work}/{name}.ms").read()) / 1000)
def single(name):
    """epsilon, DoFs, peak memory [MB] and wall time [s] of one impact."""
    summary = read(f"{work}/{name}/summary.csv")[0]
    return (float(summary["epsilon"]), int(summary["n_dofs"]), *cost(name))
def estimate(name):
    """epsilon, bar, finest DoFs, peak memory, seconds and how: 'study'
    (two levels), 'parts' (level 1 in parts) or 'level 0' (no bar)."""
    if "Convergence study" in open(f"{work}/{name}.log").read():
        total = [r for r in read(f"{work}/{name}/epsilon_estimate.csv") if r["factor"] == "total"][0]
        runs = read(f"{work}/{name}/impact_convergence.csv")
        return (float(total["limit"]), float(total["error"]),
                max(int(r["n_dofs"]) for r in runs), *cost(name), "study")
    epsilon, dofs, memory, seconds = single(name)
    names = [f"{name}_{part}" for part in PARTS]
    if not all(os.path.exists(f"{work}/{n}.ms") for n in names):
        return epsilon, float("nan"), dofs, memory, seconds, "level 0"
    runs = [single(n) for n in names]
    changes = [abs(r[0] - epsilon) for r in runs]
    return (epsilon, 4 * sum(changes),
            max(r[1] for r in runs), max(r[2] for r in runs),
            seconds + sum(r[3] for r in runs), "parts")
def show(e, b, how):
    if how == "level 0":
        return f"{e:.6f} (level 0)"
    return f"{e:.6f} ± {b:.1e}" + (" (parts)" if how == "parts" else "")
solid = "parts" if parts else "solid"
models = ["plane stress"] + [f"H = {h} R" for h in thicknesses] + ["plane strain"]
names = lambda v: [f"stress_{v}"] + [f"{solid}_{h}_{v}" for h in thicknesses] + [f"strain_{v}"]
rows = []
print("| v/c | " + " | ".join(models) + " |")
print("|---" * (len(models) + 1) + "|")
for v in speeds:
    values = [estimate(n) for n in names(v)]
    print(f"| {v} | " + " | ".join(show(e, b, how) for e, b, *_, how in values) + " |")
    for model, (e, b, dofs, memory, seconds, how) in zip(models, values):
        rows.append({"v": v, "model": model, "epsilon": e, "bar": b, "how": how,
                     "dofs": dofs, "memory_mb": round(memory), "seconds": seconds})
print()
for row in rows:
    if row["model"].startswith("H"):
        print(f"v = {row['v']} c, {row['model']} ({row['how']}): {row['dofs']} DoFs, "
              f"{row['memory_mb']} MB, {row['seconds']:.0f} s")
if parts:
    # level 1 in parts against the whole level 1, where that ran
    print("\n| v/c | H/R | level 0 ± bar (parts) | level 1 ± bar | \\|d\\| "
          "| \\|d_s\\| + \\|d_z\\| |")
    print("|---|---|---|---|---|---|")
    for v in speeds:
        for h in thicknesses:
            name = f"solid_{h}_{v}"
            if not os.path.exists(f"{work}/{name}/impact_convergence.csv"):
                continue
            runs = {r["factor"]: float(r["epsilon"])
                    for r in read(f"{work}/{name}/impact_convergence.csv")}
            e, b, *_ = estimate(f"parts_{h}_{v}")
            d = runs["mesh"] - runs["base"]
            print(f"| {v} | {h} | {e:.8f} ± {b:.1e} | {runs['mesh']:.8f} ± "
                  f"{3 * abs(d):.1e} | {abs(d):.2e} | {b / 4:.2e} |")
if out:
    with open(out, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
PY
