#!/usr/bin/python3
"""restitution.csv's epsilon equals summary.csv's to a tolerance.

usage: compare_sweep_impact.py restitution.csv summary.csv TOL
"""
import csv
import sys

sweep = next(csv.DictReader(open(sys.argv[1], newline="")))
impact = next(csv.DictReader(open(sys.argv[2], newline="")))
difference = abs(float(sweep["epsilon"]) - float(impact["epsilon"]))
print(f"sweep epsilon {sweep['epsilon']}, impact epsilon {impact['epsilon']}, "
      f"difference {difference:.2e}")
sys.exit(0 if difference <= float(sys.argv[3]) else 1)
