#!/usr/bin/python3
"""The restitution law of a body in 3D against the 2D model's (the sphere's
axisymmetric model): the same velocities, and at every one the two
epsilons agree within the sum of their error bars.

usage: check_restitution_3d_vs_2d.py SOLID/restitution_law.csv
                                     PLANE/restitution_law.csv
"""
import csv
import sys


def rows(path):
    with open(path, newline="") as f:
        return {float(r["velocity"]): r for r in csv.DictReader(f)}


solid, plane = rows(sys.argv[1]), rows(sys.argv[2])
failed = sorted(solid) != sorted(plane)
if failed:
    print(f"FAIL: velocities {sorted(solid)} against {sorted(plane)}")
for v in sorted(set(solid) & set(plane)):
    e3, e2 = float(solid[v]["epsilon"]), float(plane[v]["epsilon"])
    bar = float(solid[v]["epsilon_error"]) + float(plane[v]["epsilon_error"])
    ok = abs(e3 - e2) <= bar
    failed |= not ok
    print(f"v = {v:g}: epsilon 3D {e3:.8f}, 2D {e2:.8f}, difference "
          f"{abs(e3 - e2):.2e} (combined bar {bar:.2e}) "
          f"{'ok' if ok else 'FAIL'}")
sys.exit(1 if failed else 0)
