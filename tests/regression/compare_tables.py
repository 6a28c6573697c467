#!/usr/bin/python3
"""Two result tables (CSV) of the same run on different numbers of MPI ranks
hold the same numbers: every numeric column, or the columns given, agree to
a tolerance relative to max(|a|, |b|, floor).

usage: compare_tables.py A.csv B.csv TOL [--columns c1,c2,...]
                         [--ignore c1,c2,...] [--floor F]
The timing columns (wall_time) are ignored always.
"""
import argparse
import csv
import math
import sys


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


p = argparse.ArgumentParser()
p.add_argument("a")
p.add_argument("b")
p.add_argument("tol", type=float)
p.add_argument("--columns", default="")
p.add_argument("--ignore", default="")
p.add_argument("--floor", type=float, default=1e-300)
args = p.parse_args()

a, b = rows(args.a), rows(args.b)
if len(a) != len(b) or not a:
    sys.exit(f"FAIL: {len(a)} rows against {len(b)}")
columns = args.columns.split(",") if args.columns else list(a[0])
ignored = set(args.ignore.split(",")) | {"wall_time"}
worst, where = 0., None
for i, (ra, rb) in enumerate(zip(a, b)):
    for c in columns:
        if c in ignored:
            continue
        x, y = number(ra[c]), number(rb[c])
        if x is None or y is None:
            if ra[c] != rb[c]:
                sys.exit(f"FAIL: row {i}, {c}: '{ra[c]}' against '{rb[c]}'")
            continue
        if x == y or (math.isnan(x) and math.isnan(y)):
            continue  # equal, infinities included
        d = abs(x - y) / max(abs(x), abs(y), args.floor)
        if not d <= worst:
            worst, where = d, (i, c, x, y)
print(f"{len(a)} rows, largest relative difference {worst:.2e} "
      f"(bound {args.tol:.0e})" + (f" at row {where[0]}, {where[1]}: "
                                   f"{where[2]!r} against {where[3]!r}"
                                   if where else ""))
sys.exit(0 if worst <= args.tol else "FAIL")
