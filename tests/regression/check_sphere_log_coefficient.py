#!/usr/bin/python3
"""The logarithm of a finite sphere's contact law against its derivation.

D = (delta - delta_H) E* R / P drifts with ln(a/R); the first-order
curvature correction of Boussinesq's field gives the coefficient
D1 = -(1 - 2 nu)^2 / (2 pi (1 - nu)) (docs/theory/sphere-finite-size.md),
for the centre of mass and the diameter alike. Fits D = D0 + D1 ln(a/R) by
least squares over the rows of contact_law.csv (a/R = hertz_half_width) and
requires |D1_fitted - D1_derived| <= TOL for D_com and D_diameter.

usage: check_sphere_log_coefficient.py contact_law.csv NU TOL
"""
import csv
import math
import sys

import numpy as np


def main():
    path, nu, tol = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if len(rows) < 2:
        sys.exit(f"{path}: {len(rows)} loads, the fit needs at least 2")
    log_a = np.log([float(r["hertz_half_width"]) for r in rows])
    derived = -(1.0 - 2.0 * nu) ** 2 / (2.0 * math.pi * (1.0 - nu))
    ok = True
    for column in ("D_com", "D_diameter"):
        values = np.array([float(r[column]) for r in rows])
        slope = np.polyfit(log_a, values, 1)[0]
        good = abs(slope - derived) <= tol
        ok = ok and good
        print(f"{column}: D1 fitted {slope:.5f}, derived {derived:.5f}, "
              f"difference {slope - derived:+.2e} (tolerance {tol:g}) "
              f"{'ok' if good else 'FAIL'}")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
