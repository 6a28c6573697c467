#!/usr/bin/python3
"""Assertions on contact_law.csv of task 'quasistatic contact' with a
partner body (docs/validation/two-bodies.md).

usage: check_pair_contact_law.py contact_law.csv TOL

Every row: the pair's constant against the derived C_eff, each body's
constant (from its share of the approach) against its wall constant, all
within TOL; the approach equal to the sum of the shares and the overlap on
the axis (to 2 % of the overlap: the deepest overlap is at the quadrature
point nearest the axis); half-width within 0.5 % of the pair's Hertz a;
force balance within 1e-6; at most 20 Newton iterations.
"""
import csv
import sys

path, tol = sys.argv[1], float(sys.argv[2])
failures = 0
for r in csv.DictReader(open(path, newline="")):
    v = {k: float(x) for k, x in r.items()}
    symbol = "D" if "D_pair" in r else "C"
    overlap = v["approach"] - v["share_body"] - v["share_partner"]
    width = v["half_width"] / v["hertz_half_width"] - 1
    checks = [
        (f"{symbol}_pair - {symbol}_eff", v[symbol + "_pair"] - v[symbol + "_eff"]),
        (f"{symbol}_body - wall", v[symbol + "_body"] - v[symbol + "_body_wall"]),
        (f"{symbol}_partner - wall",
         v[symbol + "_partner"] - v[symbol + "_partner_wall"]),
    ]
    results = [(name, value, abs(value) <= tol) for name, value in checks]
    results += [
        ("axis overlap / penetration - 1", overlap / v["penetration"] - 1,
         abs(overlap / v["penetration"] - 1) <= 0.02),
        ("a/a_Hertz - 1", width, abs(width) <= 5e-3),
        ("force balance", v["force_balance_error"], abs(v["force_balance_error"]) <= 1e-6),
        ("Newton iterations", v["newton_iterations"], v["newton_iterations"] <= 20),
    ]
    for name, value, ok in results:
        failures += not ok
        print(f"load {v['load']:.1e} {name:30s} {value: .6g} {'ok' if ok else 'FAIL'}")
sys.exit(1 if failures else 0)
