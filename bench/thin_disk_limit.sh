#!/bin/bash
# A thin free disk against the plane-stress disk (nu = 0.3) as its
# thickness H -> 0, on 2 MPI ranks, one run after the other:
# - modes: the 2D half disk in plane stress (Q4, 2 global refinements) and
#   the free disk in 3D, the quarter y >= 0, 0 <= z <= H/2, on the same
#   section mesh extruded, at H/R = 0.2, 0.1, 0.05, 0.025. Prints a Markdown
#   table of D = omega_3D / omega_ps - 1 against the exact plane-stress
#   frequencies, the observed order from the three thinnest disks and, for
#   the radial mode, the coefficient a of D = a H^2 + b H^4 against the
#   Rayleigh quotient of the faces' inertia
#   (tests/regression/check_thin_disk_limit.py);
# - impact at v = 0.1 c (penalty kappa = 100, Q2, 4 elements across the
#   contact, grading 0.6, dt = t_c,est / 100): the half disk in plane stress
#   and the free disk at H/R = 0.4 ... 0.025 on the same section mesh.
#   Prints a Markdown table of epsilon, delta_max and the contact time with
#   their differences from plane stress; then the difference in epsilon at
#   H = 0.05 R on the section mesh one level finer (8 elements across,
#   grading 0.3, one global refinement, half the time step; 180,756 DoFs,
#   5.8 GB).
# About 6 minutes on 2 cores.
#
# usage: bench/thin_disk_limit.sh    (build first)
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
modes=(0.2 0.1 0.05 0.025)
impacts=(0.4 0.2 0.1 0.05 0.025)
geometry() {  # geometry H: the lines of subsection Geometry (H empty: 2D)
  if [ -z "$1" ]; then
    printf '  set Domain = half disk\n'
  else
    printf '  set Dimension = 3\n  set Domain = half disk\n'
    printf '  set Thickness = %s\n  set Faces = free\n' "$1"
  fi
}
modal_prm() {  # modal_prm NAME H
  cat > "$work/$1.prm" <<PRM
set Task             = modal analysis
set Output directory = $work/$1
subsection Geometry
$(geometry "$2")
  set Global refinements = 2
end
subsection Material
  set Plane model   = plane stress
  set Poisson ratio = 0.3
end
subsection Finite element
  set Degree = 4
end
subsection Modal analysis
  set Number of modes = 10
end
PRM
}
impact_prm() {  # impact_prm NAME H [LEVEL]: LEVEL 1 halves sizes and step
  local level=${3:-0}
  cat > "$work/$1.prm" <<PRM
set Task             = impact
set Output directory = $work/$1
subsection Geometry
$(geometry "$2")
  set Global refinements = $level
end
subsection Material
  set Plane model   = plane stress
  set Poisson ratio = 0.3
end
subsection Contact
  set Penalty factor = 100
end
subsection Impact
  set Velocity                = 0.1
  set Elements across contact = $((4 << level))
  set Grading                 = $(awk "BEGIN { print 0.6 / 2 ^ $level }")
  set Output interval         = 0
end
subsection Time stepping
  set Scheme             = energy conserving
  set Time step fraction = $(awk "BEGIN { print 0.01 / 2 ^ $level }")
end
PRM
}
run() { mpirun -np 2 build/diskimpact "$work/$1.prm" > "$work/$1.log"; }

modal_prm modes_plane ""
run modes_plane
solid=()
for h in "${modes[@]}"; do
  modal_prm "modes_$h" "$h"
  run "modes_$h"
  solid+=("$h" "$work/modes_$h/modes.csv")
done
echo "Modes: D = omega_3D / omega_plane_stress - 1 (exact plane-stress omega, units sqrt(E/rho)/R)"
echo
python3 tests/regression/check_thin_disk_limit.py "$work/modes_plane/modes.csv" \
  "${solid[@]}" --poisson 0.3 --exact --markdown
echo
impact_prm impact_plane ""
run impact_plane
for h in "${impacts[@]}"; do
  impact_prm "impact_$h" "$h"
  run "impact_$h"
done
echo "Impact at v = 0.1 c: the free disk against plane stress on the same section mesh"
echo
python3 - "$work" "${impacts[@]}" <<'PY'
import csv, sys
work, thicknesses = sys.argv[1], sys.argv[2:]
def summary(name):
    with open(f"{work}/{name}/summary.csv", newline="") as f:
        row = next(csv.DictReader(f))
    return {k: float(row[k]) for k in ("epsilon", "delta_max", "contact_time", "n_dofs")}
plane = summary("impact_plane")
print("| H/R | ε | ε − ε_ps | δ_max / δ_ps − 1 | t_c / t_ps − 1 | DoFs |")
print("|---|---|---|---|---|---|")
for h in thicknesses:
    s = summary(f"impact_{h}")
    print(f"| {h} | {s['epsilon']:.8f} | {s['epsilon'] - plane['epsilon']:+.2e} | "
          f"{s['delta_max'] / plane['delta_max'] - 1:+.2e} | "
          f"{s['contact_time'] / plane['contact_time'] - 1:+.2e} | {int(s['n_dofs'])} |")
print(f"| plane stress | {plane['epsilon']:.8f} | | | | {int(plane['n_dofs'])} |")
PY
impact_prm fine_plane "" 1
impact_prm fine_0.05 0.05 1
run fine_plane
run fine_0.05
echo
python3 - "$work" <<'PY'
import csv, sys
def epsilon(name):
    with open(f"{sys.argv[1]}/{name}/summary.csv", newline="") as f:
        return float(next(csv.DictReader(f))["epsilon"])
coarse = epsilon("impact_0.05") - epsilon("impact_plane")
fine = epsilon("fine_0.05") - epsilon("fine_plane")
print(f"H = 0.05 R: epsilon - epsilon_ps = {coarse:+.2e} (4 elements across), "
      f"{fine:+.2e} (8 elements across): ratio {coarse / fine:.2f}")
PY
