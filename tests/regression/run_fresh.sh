#!/bin/bash
# Run a command in a working directory without results of an earlier run:
# removes ./output first (a sweep would otherwise resume from it) and runs
# with ./tmp as TMPDIR.
# usage: run_fresh.sh COMMAND [ARGS...]
rm -rf output
# Open MPI gives every run without mpirun the same session directory below
# TMPDIR, which the first to finish removes: a TMPDIR of the case's own keeps
# the cases that ctest runs side by side apart.
mkdir -p tmp
export TMPDIR="$PWD/tmp"
exec "$@"
