#!/bin/bash
# FE Kelvin-Voigt impacts against the 1-DOF ODE
# (docs/validation/viscoelastic-disk.md):
# plane stress nu = 0.33, 2 refinements, 12 elements across the contact,
# kappa = 100, dt = tau/200, at v = 0.01 c and 0.005 c for tau = alpha =
# 0, 0.02, 0.05, 0.1 (E2 = rho = R = 1). Prints epsilon and the ODE's.
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for v in 0.01 0.005; do
  for tau in 0 0.02 0.05 0.1; do
    echo "v = $v c, tau = $tau: $(TAU=$tau bench/impact_case.sh $work/v${v}_$tau $v 2 12 0.3 100 0.005)"
  done
done
