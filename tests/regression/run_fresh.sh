#!/bin/bash
# Run a command in a working directory without results of an earlier run:
# removes ./output first (a sweep would otherwise resume from it).
# usage: run_fresh.sh COMMAND [ARGS...]
rm -rf output
exec "$@"
