#!/usr/bin/env python3
"""Compare an impact of an elastic-plastic body solved with 'Plastic solver'
= Newton (summary.csv) with the same impact solved by the fixed point: the
physical results agree to the plastic iteration's tolerance, and Newton did
use its tangent and took fewer plastic iterations.

Usage: check_plastic_solvers.py NEWTON_SUMMARY FIXED_POINT_SUMMARY TOL
"""
import argparse
import csv
import sys


def read_row(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if len(rows) != 1:
        sys.exit(f"{path}: expected one row, found {len(rows)}")
    return rows[0]


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("newton")
    p.add_argument("fixed_point")
    p.add_argument("tol", type=float)
    args = p.parse_args()
    newton, fixed = read_row(args.newton), read_row(args.fixed_point)
    failures = []
    for column in ("epsilon", "plastic_work", "delta_max", "vibration_fraction"):
        a, b = float(newton[column]), float(fixed[column])
        difference = abs(a - b) / abs(b)
        print(f"{column}: Newton {a:.10g}, fixed point {b:.10g}, "
              f"relative difference {difference:.2e}")
        if not difference <= args.tol:
            failures.append(f"{column} differs by {difference:.2e} > {args.tol}")
    tangents = int(newton["tangent_factorizations"])
    iterations = int(newton["plastic_iterations"])
    fixed_iterations = int(fixed["plastic_iterations"])
    print(f"plastic iterations: Newton {iterations} ({tangents} tangents), "
          f"fixed point {fixed_iterations} "
          f"({int(fixed['tangent_factorizations'])} tangents)")
    if tangents == 0:
        failures.append("Newton factorized no tangent")
    if int(fixed["tangent_factorizations"]) != 0:
        failures.append("the fixed point factorized a tangent")
    if not iterations < fixed_iterations:
        failures.append("Newton took no fewer plastic iterations")
    if failures:
        sys.exit("FAILED: " + "; ".join(failures))
    print("OK")


if __name__ == "__main__":
    main()
