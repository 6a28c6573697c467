#!/usr/bin/python3
"""Assertions on contact_law.csv of task 'quasistatic contact'.

usage: check_contact_law.py contact_law.csv C_COM C_DIAMETER TOL

Every row: |C_com - C_COM| <= TOL, |C_diameter - C_DIAMETER| <= TOL,
half-width within 0.5 % of Hertz (loads <= 1e-3), force balance within
1e-6, at most 20 Newton iterations.
"""
import csv
import sys

path, c_com, c_diameter, tol = sys.argv[1], *map(float, sys.argv[2:5])
failures = 0
for r in csv.DictReader(open(path, newline="")):
    load = float(r["load"])
    checks = [
        ("C_com", float(r["C_com"]), abs(float(r["C_com"]) - c_com) <= tol),
        ("C_diameter", float(r["C_diameter"]),
         abs(float(r["C_diameter"]) - c_diameter) <= tol),
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
