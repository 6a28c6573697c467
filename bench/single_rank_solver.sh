#!/bin/bash
# The direct solver of a single-rank impact (every run of a convergence study
# or sweep is one): PETSc's own Cholesky of the matrix in 2x2 blocks ordered
# by AMD (the default), of the scalar matrix with nested dissection and with
# quotient minimum degree, MUMPS and CHOLMOD, chosen through PETSC_OPTIONS, on four sizes of the standard impact (plane stress,
# nu = 0.33, v = 0.1c, no output). Prints each run's wall time, time stepping,
# cost per step, one solve with the factors, and epsilon (identical across
# solvers to rounding).
#
# usage: bench/single_rank_solver.sh [REPEATS]    (build first; default 1)
set -euo pipefail
cd "$(dirname "$0")/.."
repeats=${1:-1}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# name degree refinements elements-across grading time-step-fraction
cases=("Q3-9814 3 1 8 0.3 0.005"
       "Q3-35602 3 2 16 0.15 0.0025"
       "Q2-49666 2 5 6 0.6 0.01"
       "Q4-62834 4 2 16 0.15 0.0025")
solvers=("" "-pc_factor_mat_ordering_type nd" "-pc_factor_mat_ordering_type qmd"
         "-pc_factor_mat_solver_type mumps" "-pc_factor_mat_solver_type cholmod")
labels=("blocks" "petsc nd" "petsc qmd" "mumps" "cholmod")

printf '%-9s %-9s %8s %9s %9s %9s %11s\n' case solver "wall[s]" "steps[s]" \
  "step[ms]" "solve[ms]" epsilon
for c in "${cases[@]}"; do
  read -r name degree ref el grading fraction <<< "$c"
  for repeat in $(seq "$repeats"); do
    for i in "${!solvers[@]}"; do
      start=$(date +%s%N)
      PETSC_OPTIONS="${solvers[$i]}" DEGREE=$degree bench/impact_case.sh \
        "$work/$name" 0.1 "$ref" "$el" "$grading" 100 "$fraction" > /dev/null
      wall=$(( ($(date +%s%N) - start) / 1000000 ))
      read -r stepping per_step solve <<< "$(sed -n \
        's/.*time stepping: \([0-9.e-]*\) s, \([0-9.e-]*\) ms per step.*one: \([0-9.e-]*\) ms.*/\1 \2 \3/p' \
        "$work/$name/log")"
      epsilon=$(sed -n 's/^ *epsilon = \([0-9.]*\).*/\1/p' "$work/$name/log")
      printf '%-9s %-9s %8.2f %9.2f %9.2f %9.2f %11s\n' "$name" \
        "${labels[$i]}" "$(echo "$wall / 1000" | bc -l)" "$stepping" \
        "$per_step" "$solve" "$epsilon"
    done
  done
done
