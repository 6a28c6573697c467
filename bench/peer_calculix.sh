#!/bin/bash
# Peer comparison with CalculiX: the same disk impact (plane strain,
# nu = 0.3, v = 0.1 c, half disk on a rigid wall) computed by CalculiX's ccx
# and by build/diskimpact at several settings, one after the other on one
# core each; a reference epsilon with its bar from diskimpact's convergence
# study with the exact contact constraint (about 5 minutes; --reference EPS
# BAR skips it). Prints each code's epsilon, error against the reference,
# DoFs, steps and wall time, the cheapest diskimpact setting whose error is
# at most CalculiX's and the wall time ratio CalculiX / diskimpact there
# (acceptance: >= 30). About 5 minutes with the defaults.
# Installs calculix-ccx and gmsh with apt-get if ccx or gmsh is missing,
# needs a built build/diskimpact, then runs bench/peer_calculix.py with the
# arguments given here (e.g. --hmin 0.01 --hmax 0.1 --steps-per-contact 200).
# Usage: bench/peer_calculix.sh [options of bench/peer_calculix.py]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

if ! command -v ccx >/dev/null 2>&1 || ! command -v gmsh >/dev/null 2>&1; then
    if [ "$(id -u)" -eq 0 ]; then
        SUDO=""
    else
        SUDO="sudo"
    fi
    $SUDO apt-get update
    $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y \
        calculix-ccx gmsh
fi

if [ ! -x build/diskimpact ]; then
    echo "peer_calculix.sh: build/diskimpact not found; build first" >&2
    exit 1
fi

exec python3 bench/peer_calculix.py "$@"
