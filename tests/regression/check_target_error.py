#!/usr/bin/python3
"""A study with 'Target error' ran the fewest mesh levels whose bar meets it.

Recomputes the mesh sequence's bar after each level from impact_convergence.csv
with the fallback rule (docs/theory/impact-method.md), and requires: the
study stopped at the first level count whose bar is <= TARGET (or at
LARGEST), it ran more than the MINIMUM levels it starts with, and
epsilon_estimate.csv reports that bar.

usage: check_target_error.py OUTPUT_DIR TARGET MINIMUM LARGEST
"""
import csv
import math
import os
import sys

directory, target = sys.argv[1], float(sys.argv[2])
minimum, largest = int(sys.argv[3]), int(sys.argv[4])
runs = list(csv.DictReader(open(os.path.join(directory, "impact_convergence.csv"))))
mesh = [float(r["epsilon"]) for r in runs if r["factor"] in ("base", "mesh")]
rows = list(csv.DictReader(open(os.path.join(directory, "epsilon_estimate.csv"))))
reported = float(next(r for r in rows if r["factor"] == "total")["error"])


def fallback(values):
    """The bar of an unverified mesh sequence (ratio 2, expected order 1)."""
    d2 = values[-1] - values[-2]
    d1 = values[-2] - values[-3] if len(values) > 2 else 0.0
    if len(values) > 2 and d2 != 0 and d1 / d2 > 1:
        q = d1 / d2
        p = math.log2(q)
        return 3 * abs(d2) / (1 if p > 2 else q - 1)
    return 3 * max(abs(d1), abs(d2))


bars = [fallback(mesh[:n]) for n in range(2, len(mesh) + 1)]
print("levels", len(mesh), "bars", " ".join(f"{b:.2e}" for b in bars),
      f"reported {reported:.2e}, target {target:.1e}")
ok = len(mesh) > minimum
ok &= all(b > target for b in bars[:-1])
ok &= bars[-1] <= target or len(mesh) == largest
ok &= math.isclose(bars[-1], reported, rel_tol=1e-9)
print("OK" if ok else "FAIL")
sys.exit(0 if ok else 1)
