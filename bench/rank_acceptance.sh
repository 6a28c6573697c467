#!/bin/bash
# Every shipped parameter file (or those given) on 1 and on N MPI ranks
# (default 2; more ranks than cores are oversubscribed): each result table of
# the N-rank run must hold the 1-rank numbers to a relative 1e-6
# (tests/regression/compare_tables.py). The studies and sweeps share whole
# runs out among the ranks and give the same numbers; a single run
# distributed over the ranks sums in another order, and its Newton
# tolerances (1e-13 of the largest approach in an impact, 1e-10 of the load
# in quasistatic contact) bound what that moves. Measured on 3 ranks: up to
# 4.1e-9 in an impact (a contact half-width), 8.2e-8 in quasistatic contact
# (the largest overlap, a difference of two displacements some 1e4 times
# larger than it). Left out: wall times; the balance errors (energy_error,
# impulse_error, momentum_error, force_balance_error), round-off near zero
# (1e-13 in an impact, up to 1e-8 in quasistatic contact); Newton iteration
# counts, which round-off can change by one or two; and the errors and
# observed orders of modal convergence studies, whose finest levels are
# resolved to 1e-14. Mode tables compare their frequencies
# (tests/regression/compare_frequencies.py), rigid modes left out.
# Prints per file both wall times and each table's largest difference.
#
# usage: bench/rank_acceptance.sh [--ranks N] [params/FILE.prm ...]
#        (build first; all of params/ on 1 and 3 ranks: 32 minutes on
#        2 cores)
set -uo pipefail
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
n_ranks=2
if [ "${1:-}" = --ranks ]; then
  n_ranks=$2
  shift 2
fi
files=("$@")
[ ${#files[@]} -eq 0 ] && files=(params/*.prm)
tolerance=1e-6

# compare_table ONE_RANK.csv N_RANKS.csv: the comparison's one-line result;
# fails if the tables differ.
compare_table() {
  case $(basename "$1") in
    modes.csv | torsional_modes.csv)
      /usr/bin/python3 tests/regression/compare_frequencies.py "$1" "$2" $tolerance ;;
    modal_convergence.csv)
      /usr/bin/python3 tests/regression/compare_tables.py "$1" "$2" $tolerance \
        --ignore relative_error,observed_order ;;
    *)
      /usr/bin/python3 tests/regression/compare_tables.py "$1" "$2" $tolerance \
        --ignore energy_error,impulse_error,momentum_error,force_balance_error,newton_iterations ;;
  esac
}

failures=0
for prm in "${files[@]}"; do
  name=$(basename "$prm" .prm)
  line="$name:"
  for ranks in 1 $n_ranks; do
    dir="$work/$name-$ranks"
    mkdir -p "$dir"
    sed -e "s|^\( *set Output directory *=\).*|\1 $dir/out|" "$prm" > "$dir/run.prm"
    # relative mesh files and includes resolve from the repository root
    start=$(date +%s%N)
    if ! mpirun -q --oversubscribe -np $ranks build/diskimpact "$dir/run.prm" > "$dir/log" 2>&1; then
      echo "$line $ranks rank(s) FAILED: $(tail -1 "$dir/log")"
      failures=$((failures + 1))
      continue 2
    fi
    line="$line $ranks rank(s) $(( ($(date +%s%N) - start) / 1000000 )) ms,"
  done
  echo "$line"
  for csv in "$work/$name-1/out"/*.csv; do
    table=$(basename "$csv")
    if result=$(compare_table "$csv" "$work/$name-$n_ranks/out/$table" 2>&1); then
      echo "  $table: same ($(echo "$result" | head -1))"
    else
      echo "  $table: DIFFERS ($(echo "$result" | head -1))"
      failures=$((failures + 1))
    fi
  done
done
echo "$failures failure(s)"
[ $failures -eq 0 ]
