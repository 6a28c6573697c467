#!/bin/bash
# An elastic-perfectly-plastic sphere in 3D (the quarter sphere) against the
# axisymmetric model of the same impact: the meshes and time step of
# regressions impact_sphere_3d and impact_sphere_3d_axisymmetric (nu = 0.3,
# v = 0.01 c) with Y = 0.036 E = 0.0328 E*, whose speed of first yield is
# about 0.001 c (docs/theory/first-yield.md). Prints each run's epsilon,
# plastic work and balances (check_impact.py: energy and plastic balance to
# 1e-6), then the comparison of check_3d_vs_2d.py with the bounds of the
# elastic 3D validation (epsilon within 20 % of the loss, contact time and
# delta_max within 0.5 %).
#
# usage: bench/plastic_sphere_3d.sh    (build first; about 1.5 minutes)
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for body in impact_sphere_3d impact_sphere_3d_axisymmetric; do
  mkdir -p "$work/$body"
  sed 's/^  set Poisson ratio = 0.3$/  set Poisson ratio = 0.3\n  set Yield stress  = 0.03604/' \
    "tests/regression/$body.prm" > "$work/$body.prm"
  grep -q "Yield stress" "$work/$body.prm"
  (cd "$work/$body" && "$OLDPWD/build/diskimpact" "../$body.prm" |
     grep -E "DoFs|epsilon =|plastic work|time stepping")
  /usr/bin/python3 tests/regression/check_impact.py \
    "$work/$body/output/summary.csv" --energy 1e-6 --plastic-balance 1e-6
done
/usr/bin/python3 tests/regression/check_3d_vs_2d.py \
  "$work/impact_sphere_3d/output/summary.csv" \
  "$work/impact_sphere_3d_axisymmetric/output/summary.csv" \
  --loss-share 0.2 --relative 0.005
