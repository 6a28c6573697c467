#!/bin/bash
# Installs the DEM codes used by bench/dem_collision.py if they are missing
# (Debian packages liggghts -> /usr/bin/liggghts and lammps -> /usr/bin/lmp;
# with --yade also yade -> /usr/bin/yade, a larger install) and prints the
# paths of the binaries.
#
# usage: bench/dem_check_deps.sh [--yade]
set -euo pipefail

codes=(liggghts lmp)
[ "${1:-}" = "--yade" ] && codes+=(yade)
missing=()
command -v liggghts >/dev/null || missing+=(liggghts)
command -v lmp >/dev/null || missing+=(lammps)
if [ "${1:-}" = "--yade" ] && ! command -v yade >/dev/null; then
    missing+=(yade)
fi

if [ ${#missing[@]} -gt 0 ]; then
    sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    echo "installing ${missing[*]}"
    $sudo apt-get update || echo "apt-get update failed, trying the cached lists"
    $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y "${missing[@]}"
fi

for exe in "${codes[@]}"; do
    path=$(command -v $exe) || { echo "error: $exe still missing" >&2; exit 1; }
    echo "$exe: $path"
done
