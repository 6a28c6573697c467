#!/usr/bin/python3
"""restitution.csv's epsilon equals summary.csv's to a tolerance, and
restitution.h5 holds the same table.

usage: compare_sweep_impact.py restitution.csv summary.csv TOL
"""
import csv
import os
import sys

import h5py

sweep = next(csv.DictReader(open(sys.argv[1], newline="")))
impact = next(csv.DictReader(open(sys.argv[2], newline="")))
difference = abs(float(sweep["epsilon"]) - float(impact["epsilon"]))
print(f"sweep epsilon {sweep['epsilon']}, impact epsilon {impact['epsilon']}, "
      f"difference {difference:.2e}")
with h5py.File(os.path.splitext(sys.argv[1])[0] + ".h5", "r") as f:
    h5_epsilon = f["restitution"]["epsilon"][0]
print(f"restitution.h5 epsilon {h5_epsilon!r}")
same = h5_epsilon == float(sweep["epsilon"])
sys.exit(0 if difference <= float(sys.argv[3]) and same else 1)
