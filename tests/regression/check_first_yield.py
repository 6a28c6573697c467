#!/usr/bin/python3
"""Where the body first yields, on contact_law.csv of task 'quasistatic contact'.

usage: check_first_yield.py contact_law.csv COEFFICIENT LINE_TOL

Every row: p0/Y at first yield (the finite elements' largest von Mises
stress against Hertz's p0) within COEFFICIENT a/R (relative) of Hertz's
half-space, the finite body's difference being of order a/R, and its
depth within 0.05 a; with two rows or more, the straight line through them
in a/R reaches the half-space's p0/Y at a = 0 within LINE_TOL (relative).
"""
import csv
import sys

path, coefficient, line_tol = (sys.argv[1], float(sys.argv[2]),
                               float(sys.argv[3]))
rows = list(csv.DictReader(open(path, newline="")))
failures = 0
points = []
for r in rows:
    a = float(r["hertz_half_width"])
    ratio = float(r["first_yield_pressure_ratio"])
    hertz = float(r["first_yield_pressure_ratio_hertz"])
    depth, hertz_depth = (float(r["first_yield_depth"]),
                          float(r["first_yield_depth_hertz"]))
    points.append((a, ratio))
    ok = (abs(ratio / hertz - 1) <= coefficient * a and
          abs(depth - hertz_depth) <= 0.05)
    failures += not ok
    print(f"a/R = {a:.4f}: p0/Y = {ratio:.5f} (Hertz {hertz:.5f}, "
          f"{ratio / hertz - 1:+.2e}), depth {depth:.3f} a (Hertz "
          f"{hertz_depth:.3f} a) {'ok' if ok else 'FAILED'}")
if len(points) >= 2:
    (a1, r1), (a2, r2) = points[0], points[-1]
    intercept = r1 - a1 * (r2 - r1) / (a2 - a1)
    ok = abs(intercept / hertz - 1) <= line_tol
    failures += not ok
    print(f"line through the rows at a = 0: p0/Y = {intercept:.5f} "
          f"({intercept / hertz - 1:+.2e}) {'ok' if ok else 'FAILED'}")
sys.exit(1 if failures else 0)
