#!/bin/bash
# Modal analysis benchmark: for a few (degree, refinement) pairs, the number
# of DoFs, assembly and eigensolver wall times, the whole run's wall time and
# the largest relative error of the first 20 elastic modes (full disk, plane
# strain E = 1, nu = 0.3). Then the acceptance run, params/modal.prm,
# repeated 3 times.
#
# usage: bench/modal_benchmark.sh [RANKS]    (default 2; build first)
set -euo pipefail
cd "$(dirname "$0")/.."
ranks=${1:-2}
exe=$PWD/build/diskimpact
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

max_error() { # largest |relative_error| of the first 20 elastic modes
  /usr/bin/python3 -c '
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["family"] != "rigid"]
print("%.2e" % max(abs(float(r["relative_error"])) for r in rows[:20]))' "$1"
}
section() { grep -E "^\| $1 " "$2" | awk -F'|' '{gsub(/ /,"",$4); print $4}'; }

run() { # run PRM LOG: wall seconds of the whole run, mpirun included
  local start end
  start=$(date +%s%N)
  mpirun -np "$ranks" "$exe" "$1" > "$2" 2>&1
  end=$(date +%s%N)
  printf "%d.%03d" $(( (end - start) / 1000000000 )) $(( (end - start) / 1000000 % 1000 ))
}

echo "modal analysis, $ranks MPI rank(s), first 20 elastic modes"
printf "%6s %5s %8s %10s %12s %9s %12s\n" degree refs DoFs assembly eigensolver run_total max_error
for pair in "2 4" "3 3" "3 4" "4 2" "4 3"; do
  set -- $pair
  cat > "$work/case.prm" <<PRM
set Output directory = $work/out
subsection Geometry
  set Global refinements = $2
end
subsection Finite element
  set Degree = $1
end
subsection Modal analysis
  set Number of modes = 20
end
PRM
  total=$(run "$work/case.prm" "$work/log")
  dofs=$(grep -oE "[0-9]+ DoFs" "$work/log" | cut -d' ' -f1)
  printf "%6s %5s %8s %10s %12s %8.2fs %12s\n" "$1" "$2" "$dofs" \
    "$(section assembly "$work/log")" "$(section eigensolver "$work/log")" \
    "$total" "$(max_error "$work/out/modes.csv")"
done

echo
echo "acceptance run: mpirun -np $ranks build/diskimpact params/modal.prm"
sed "s|output/modal|$work/accept|" params/modal.prm > "$work/accept.prm"
for i in 1 2 3; do
  total=$(run "$work/accept.prm" "$work/log")
  printf "  run %d: %.2f s wall, eigensolver %s, max error of the first 20 elastic modes %s\n" \
    "$i" "$total" "$(section eigensolver "$work/log")" "$(max_error "$work/accept/modes.csv")"
done
