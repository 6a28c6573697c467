#!/usr/bin/python3
"""A study with 'Largest time step halvings' = 1: after two mesh levels and
the split run it halved the time step of both levels once (the time step's
part d_t of the last difference at least half the mesh's part d_h, the
bar 3 (|d_t| + |d_h|) above the target) instead of adding a mesh level;
epsilon is the finest run, its bar 3 (|d_t| + |d_h|) from the halved runs,
and FINER (the next level of both, computed independently) lies inside.

usage: check_time_halving.py OUTPUT_DIR TARGET FINER
"""
import csv
import os
import sys

directory, target, finer = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
runs = list(csv.DictReader(open(os.path.join(directory, "impact_convergence.csv"))))


def epsilon(factor, level, halvings):
    found = [float(r["epsilon"]) for r in runs if r["factor"] == factor
             and int(r["level"]) == level and int(r["time_halvings"]) == halvings]
    return found[0] if len(found) == 1 else None


base = epsilon("base", 0, 0)
first = (epsilon("mesh", 1, 0), epsilon("split", 1, 0))
halved = (epsilon("mesh", 1, 1), epsilon("split", 1, 1))
rows = list(csv.DictReader(open(os.path.join(directory, "epsilon_estimate.csv"))))
total = next(r for r in rows if r["factor"] == "total")
reported, bar = float(total["limit"]), float(total["error"])
ok = len(runs) == 5 and None not in (base,) + first + halved
if ok:
    d_t, d_h = first[1] - base, first[0] - first[1]
    print(f"two levels: d_t = {d_t:.2e}, d_h = {d_h:.2e}, bar {3 * (abs(d_t) + abs(d_h)):.2e}")
    ok &= 3 * (abs(d_t) + abs(d_h)) > target and abs(d_t) >= abs(d_h) / 2
    d_t, d_h = halved[1] - first[1], halved[0] - halved[1]
    expected = 3 * (abs(d_t) + abs(d_h))
    print(f"halved once: d_t = {d_t:.2e}, d_h = {d_h:.2e}, bar {expected:.2e}; "
          f"reported {reported:.8f} +- {bar:.2e}; finer {finer:.8f}, "
          f"{abs(finer - reported):.2e} away")
    ok &= reported == halved[0]
    ok &= abs(bar - expected) <= 1e-9 * expected and bar <= target
    ok &= abs(finer - reported) <= bar
print("OK" if ok else "FAIL")
sys.exit(0 if ok else 1)
