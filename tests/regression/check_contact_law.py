#!/usr/bin/python3
"""Assertions on contact_law.csv of task 'quasistatic contact'.

usage: check_contact_law.py contact_law.csv C_COM C_DIAMETER TOL
       check_contact_law.py contact_law.csv D0_COM,D1_COM D0_DIAM,D1_DIAM TOL

Every row: |C_com - C_COM| <= TOL, |C_diameter - C_DIAMETER| <= TOL (a
disk), or for a sphere |D - (D0 + D1 ln(a_Hertz/R))| <= TOL for D_com and
D_diameter; half-width within 0.5 % of Hertz (loads <= 1e-3), force balance
within 1e-6, at most 20 Newton iterations.
"""
import csv
import math
import sys


def reference(text):
    """A constant 'C', or 'D0,D1' for D0 + D1 ln(a/R)."""
    parts = [float(v) for v in text.split(",")]
    return lambda a: parts[0] + (parts[1] * math.log(a) if len(parts) > 1 else 0)


path, tol = sys.argv[1], float(sys.argv[4])
expected_com, expected_diameter = reference(sys.argv[2]), reference(sys.argv[3])
failures = 0
for r in csv.DictReader(open(path, newline="")):
    load = float(r["load"])
    symbol = "D" if "D_com" in r else "C"
    com, diameter = float(r[symbol + "_com"]), float(r[symbol + "_diameter"])
    a = float(r["hertz_half_width"])
    checks = [
        (symbol + "_com", com, abs(com - expected_com(a)) <= tol),
        (symbol + "_diameter", diameter,
         abs(diameter - expected_diameter(a)) <= tol),
        ("a/a_Hertz - 1", float(r["half_width"]) / float(r["hertz_half_width"]) - 1,
         load > 1e-3 or abs(float(r["half_width"]) / float(r["hertz_half_width"]) - 1) <= 5e-3),
        ("force balance", float(r["force_balance_error"]),
         abs(float(r["force_balance_error"])) <= 1e-6),
        ("Newton iterations", int(r["newton_iterations"]),
         int(r["newton_iterations"]) <= 20),
    ]
    for name, value, ok in checks:
        failures += not ok
        print(f"load {load:.1e} {name:18s} {value: .6g} {'ok' if ok else 'FAIL'}")
sys.exit(1 if failures else 0)
