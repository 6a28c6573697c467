#!/usr/bin/python3
"""A study with 'Separate time step error': the reported bar is the larger of
the mesh sequence's fallback and 3 (|d_t| + |d_h|), the last mesh difference
split by the "split" run (the coarser mesh with the finer time step); here
the split bar must be the larger one (the parts cancel) and contain FINER,
epsilon of the next mesh level, computed independently.

usage: check_split_bar.py OUTPUT_DIR FINER
"""
import csv
import os
import sys

directory, finer = sys.argv[1], float(sys.argv[2])
runs = list(csv.DictReader(open(os.path.join(directory, "impact_convergence.csv"))))
mesh = [float(r["epsilon"]) for r in runs if r["factor"] in ("base", "mesh")]
split = [float(r["epsilon"]) for r in runs
         if r["factor"] == "split" and int(r["level"]) == len(mesh) - 1]
rows = list(csv.DictReader(open(os.path.join(directory, "epsilon_estimate.csv"))))
total = next(r for r in rows if r["factor"] == "total")
epsilon, reported = float(total["limit"]), float(total["error"])
ok = len(mesh) == 2 and len(split) == 1
if ok:
    d = mesh[1] - mesh[0]
    d_t, d_h = split[0] - mesh[0], mesh[1] - split[0]
    fallback = 3 * abs(d)
    apart = 3 * (abs(d_t) + abs(d_h))
    print(f"d = {d:.2e} (bar {fallback:.2e}); d_t = {d_t:.2e}, d_h = {d_h:.2e} "
          f"(bar {apart:.2e}); reported {epsilon:.8f} +- {reported:.2e}; "
          f"finer level {finer:.8f}, {abs(finer - epsilon):.2e} away")
    ok &= abs(reported - max(fallback, apart)) <= 1e-9 * reported
    ok &= apart > fallback
    ok &= abs(finer - epsilon) <= reported
print("OK" if ok else "FAIL")
sys.exit(0 if ok else 1)
