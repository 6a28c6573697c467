#!/usr/bin/python3
"""A sweep with 'Graded half-width' runs every speed on one mesh (one DoF
count in its restitution.csv); the same sweep without it has a mesh per
speed (more than one DoF count).

usage: check_one_mesh.py ONE_MESH.csv PER_SPEED.csv
"""
import csv
import sys


def dof_counts(path):
    return sorted({int(row["n_dofs"]) for row in csv.DictReader(open(path, newline=""))})


one, per_speed = dof_counts(sys.argv[1]), dof_counts(sys.argv[2])
print(f"DoF counts with 'Graded half-width': {one}; without: {per_speed}")
sys.exit(0 if len(one) == 1 and len(per_speed) > 1 else 1)
