#!/bin/bash
# Peer comparison with CalculiX in 3D: the same sphere impact (nu = 0.3,
# v = 0.1 c, the quarter sphere y >= 0, z >= 0 with its planes of symmetry,
# on a rigid wall) computed by CalculiX's ccx (10-node tetrahedra) and by
# build/diskimpact (Dimension = 3) at several settings, one after the other
# on one core each; a reference epsilon with its bar from diskimpact's
# convergence study params/impact_convergence_sphere_3d.prm at 0.1 c (about
# 3 minutes; --reference EPS BAR skips it). Prints each code's epsilon,
# error against the reference, DoFs, steps and wall time, the cheapest
# diskimpact setting whose error is at most CalculiX's and the wall time
# ratio CalculiX / diskimpact there (acceptance: >= 30), and the wall time
# of each part. About 4 minutes with the defaults.
# Installs calculix-ccx and gmsh with apt-get if ccx or gmsh is missing,
# needs a built build/diskimpact, then runs bench/peer_calculix_3d.py with
# the arguments given here (e.g. --hmin 0.05 --hmax 0.25
# --steps-per-contact 100).
# Usage: bench/peer_calculix_3d.sh [options of bench/peer_calculix_3d.py]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

missing=()
command -v ccx >/dev/null 2>&1 || missing+=(calculix-ccx)
command -v gmsh >/dev/null 2>&1 || missing+=(gmsh)
if [ ${#missing[@]} -gt 0 ]; then
    sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    $sudo apt-get update
    $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y \
        "${missing[@]}"
fi

[ -x build/diskimpact ] || {
    echo "peer_calculix_3d.sh: build/diskimpact not found; build first" >&2
    exit 1
}

exec python3 bench/peer_calculix_3d.py "$@"
