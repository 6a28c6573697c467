#!/bin/bash
# The time-integration choices of docs/theory/impact-method.md at v = 0.1 c
# (2 global refinements, 12 elements across the contact, kappa = 100):
# epsilon for dt = tau/100, tau/200, tau/400 with the energy-conserving
# midpoint rule (consistent mass), with mass redistribution, and with
# generalized-alpha (rho_inf = 0.8, redistributed mass), and the space-time
# sequence used by the convergence study.
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for f in 0.01 0.005 0.0025; do
  echo "consistent, fraction $f: $(bench/impact_case.sh $work/c$f 0.1 2 12 0.3 100 $f)"
  echo "redistributed, fraction $f: $(bench/impact_case.sh $work/r$f 0.1 2 12 0.3 100 $f 'set Contact mass = redistributed')"
  echo "generalized alpha 0.8, fraction $f: $(bench/impact_case.sh $work/g$f 0.1 2 12 0.3 100 $f 'set Scheme = generalized alpha' 'set Spectral radius = 0.8' 'set Contact mass = redistributed')"
done
for level in "1 6 0.6 0.02" "2 12 0.3 0.01" "3 24 0.15 0.005"; do
  set -- $level
  echo "mesh and dt: $1 refinements, $2 elements: $(bench/impact_case.sh $work/s$1 0.1 $1 $2 $3 100 $4)"
done
