#!/usr/bin/python3
"""Two modes.csv files have the same frequencies to a relative tolerance.

usage: compare_frequencies.py A/modes.csv B/modes.csv RTOL
"""
import csv
import sys


def omegas(path):
    with open(path, newline="") as f:
        return [(r["family"], float(r["omega"])) for r in csv.DictReader(f)]


a, b, rtol = omegas(sys.argv[1]), omegas(sys.argv[2]), float(sys.argv[3])
if len(a) != len(b):
    sys.exit(f"FAIL: {len(a)} modes vs {len(b)}")
worst = max(abs(x - y) / y for (fa, x), (fb, y) in zip(a, b) if fa != "rigid")
print(f"largest relative frequency difference {worst:.3e} (bound {rtol:.0e})")
sys.exit(0 if worst <= rtol else "FAIL")
