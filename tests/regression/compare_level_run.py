#!/usr/bin/python3
"""One run of a convergence study (impact_convergence.csv) equals a plain
impact run of the parameters it should have (summary.csv): the same number
of DoFs and time step, and epsilon to TOL.

usage: compare_level_run.py impact_convergence.csv FACTOR LEVEL HALVINGS summary.csv TOL
"""
import csv
import sys

table, factor, level, halvings, summary, tol = sys.argv[1:7]
runs = [r for r in csv.DictReader(open(table, newline=""))
        if r["factor"] == factor and r["level"] == level
        and r["time_halvings"] == halvings]
impact = next(csv.DictReader(open(summary, newline="")))
ok = len(runs) == 1
if ok:
    run = runs[0]
    difference = abs(float(run["epsilon"]) - float(impact["epsilon"]))
    print(f"study {factor} {level}+{halvings}: {run['n_dofs']} DoFs, dt "
          f"{run['time_step']}, epsilon {run['epsilon']}")
    print(f"plain impact: {impact['n_dofs']} DoFs, dt {impact['time_step']}, "
          f"epsilon {impact['epsilon']}; difference {difference:.2e}")
    ok = (run["n_dofs"] == impact["n_dofs"] and
          abs(float(run["time_step"]) - float(impact["time_step"]))
          <= 1e-12 * float(impact["time_step"]) and difference <= float(tol))
print("OK" if ok else "FAIL")
sys.exit(0 if ok else 1)
