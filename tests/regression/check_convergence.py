#!/usr/bin/python3
"""The observed orders of a modal_convergence.csv on its finest level are
within +-TOL of 2k for every degree k. Errors below FLOOR are round-off
(docs/validation/free-disk-modes.md: Q3 errors stop following h^6 near 1e-13)
and are not judged; at least 3 modes per degree must be judged.

usage: check_convergence.py modal_convergence.csv TOL FLOOR
"""
import csv
import sys
from collections import defaultdict

rows = list(csv.DictReader(open(sys.argv[1], newline="")))
tol, floor = float(sys.argv[2]), float(sys.argv[3])
judged = defaultdict(int)
finest = defaultdict(int)
for r in rows:
    finest[r["degree"]] = max(finest[r["degree"]], int(r["refinements"]))
failures = 0
for r in rows:
    k = int(r["degree"])
    if int(r["refinements"]) != finest[r["degree"]]:
        continue
    order, error = float(r["observed_order"]), float(r["relative_error"])
    if abs(error) < floor:
        verdict = "below round-off floor, not judged"
    else:
        judged[k] += 1
        ok = abs(order - 2 * k) <= tol
        failures += not ok
        verdict = "ok" if ok else "FAIL"
    print(f"Q{k} mode {r['mode']:>2} ({r['n']},{r['l']},{r['family']}): "
          f"error {error:.2e} order {order:.2f} {verdict}")
for k in finest:
    if judged[int(k)] < 3:
        print(f"FAIL: only {judged[int(k)]} modes judged for Q{k}")
        failures += 1
sys.exit(1 if failures else 0)
