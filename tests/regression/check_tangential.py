#!/usr/bin/python3
"""Assertions on tangential_law.csv of task 'tangential contact'.

usage: check_tangential.py tangential_law.csv [--theory TOL] [--stick TOL]
                           [--equilibrium TOL]

--theory TOL: every row's contact_displacement (the rigid motion at the
  contact point) within TOL relative of theory_displacement (Cattaneo's
  disk, Mindlin's sphere).
--stick TOL: every row's stick_radius within TOL of theory_stick_radius
  (both over Hertz's a).
--equilibrium TOL: every row's equilibrium_error (|K u - f - E_C P| / |f|)
  at most TOL.
Also: the displacement grows with the load, and the stick zone shrinks.
"""
import argparse
import csv
import sys

parser = argparse.ArgumentParser()
parser.add_argument("table")
parser.add_argument("--theory", type=float)
parser.add_argument("--stick", type=float)
parser.add_argument("--equilibrium", type=float)
args = parser.parse_args()

rows = list(csv.DictReader(open(args.table, newline="")))
failures = 0 if rows else 1


def check(name, value, ok):
    global failures
    failures += not ok
    print(f"{name:44s} {value: .6g} {'ok' if ok else 'FAIL'}")


previous = None
for r in rows:
    q = float(r["tangential_load"])
    label = f"load {float(r['load']):.1e} q {q:.3f}"
    fe, theory = float(r["contact_displacement"]), float(r["theory_displacement"])
    if args.theory is not None:
        check(f"{label} displacement/theory - 1", fe / theory - 1,
              abs(fe / theory - 1) <= args.theory)
    if args.stick is not None:
        stick = float(r["stick_radius"]) - float(r["theory_stick_radius"])
        check(f"{label} stick radius - theory", stick, abs(stick) <= args.stick)
    if args.equilibrium is not None:
        error = float(r["equilibrium_error"])
        check(f"{label} equilibrium error", error, error <= args.equilibrium)
    if previous is not None and previous["load"] == r["load"]:
        check(f"{label} displacement grows", fe,
              fe > float(previous["contact_displacement"]))
        check(f"{label} stick zone shrinks", float(r["stick_radius"]),
              float(r["stick_radius"]) <= float(previous["stick_radius"]))
    previous = r
sys.exit(1 if failures else 0)
