#!/bin/bash
# FE impact against the 1-DOF log-law model (docs/impact.md, "The 1-DOF
# limit"): plane stress nu = 0.33, kappa = 400, at v = 0.01 c on two meshes
# and at v = 0.001 c. About 1.5 min.
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "v = 0.01 c, 3 refinements, 12 elements, tau/200: $(bench/impact_case.sh $work/a 0.01 3 12 0.3 400 0.005)"
echo "v = 0.01 c, 4 refinements, 24 elements, tau/400: $(bench/impact_case.sh $work/b 0.01 4 24 0.3 400 0.0025)"
echo "v = 0.001 c, 3 refinements, 12 elements, tau/200: $(bench/impact_case.sh $work/c 0.001 3 12 0.3 400 0.005)"
