#!/usr/bin/python3
"""Assertions on the tables of task 'reference models' (the tolerances are
justified in reference_<model>.prm).

usage: check_reference_models.py output/reference_<model>.csv
"""
import csv
import math
import sys
from collections import defaultdict

path = sys.argv[1]
rows = [{k: float(v) if v not in ("", "nan") else math.nan
         for k, v in r.items()} for r in csv.DictReader(open(path))]
checks = []


def check(name, value, ok):
    checks.append((name, value, ok))


if "alpha" in rows[0]:  # disk
    by_v = defaultdict(dict)
    for r in rows:
        by_v[r["velocity"]][r["alpha"]] = r
        check(f"force end >= overlap end, v = {r['velocity']}, alpha = "
              f"{r['alpha']}", r["epsilon_ode"] - r["epsilon_ode_overlap"],
              r["epsilon_ode"] >= r["epsilon_ode_overlap"])
    for v, runs in by_v.items():
        alphas = sorted(runs)
        for column, order in (("epsilon_first_order", 2),
                              ("epsilon_second_order", 3)):
            errors = [abs(runs[a][column] - runs[a]["epsilon_ode_overlap"])
                      for a in alphas]
            observed = (math.log(errors[-1] / errors[0])
                        / math.log(alphas[-1] / alphas[0]))
            check(f"order of {column} at v = {v}", observed,
                  abs(observed - order) <= 0.35)
elif "damping_ratio" in rows[0]:  # dashpot
    for r in rows:
        check(f"eq. 21 - ODE at beta/omega0 = {r['damping_ratio']}",
              r["epsilon"] - r["epsilon_ode"],
              abs(r["epsilon"] - r["epsilon_ode"]) <= 1e-10)
        check(f"overlap end <= force end at {r['damping_ratio']}",
              r["epsilon_overlap_criterion"],
              r["epsilon_overlap_criterion"] <= r["epsilon"]
              and (r["damping_ratio"] < 1 or r["epsilon_overlap_criterion"] == 0))
else:  # spheres
    a5 = 0.117
    for r in rows:
        u = r["scaled_velocity"]
        if u > 0.2:
            continue
        bound = 2 * a5 * u**5
        error = abs(r["epsilon_series"] - r["epsilon_ode_overlap"])
        check(f"series eq. 32 - ODE at u = {u:.4f} (bound {bound:.1e})",
              error, error <= bound)
        printed = abs(r["epsilon_series_printed"] - r["epsilon_ode_overlap"])
        check(f"printed a3, a4 miss the ODE at u = {u:.4f}", printed,
              printed > bound)
        check(f"Pade verified closer than printed at u = {u:.4f}",
              abs(r["epsilon_pade"] - r["epsilon_ode_overlap"]),
              abs(r["epsilon_pade"] - r["epsilon_ode_overlap"])
              < abs(r["epsilon_pade_printed"] - r["epsilon_ode_overlap"]))

failed = [c for c in checks if not c[2]]
for name, value, ok in checks:
    print(f"{'ok  ' if ok else 'FAIL'} {name}: {value:.3e}")
if not checks or failed:
    sys.exit(1)
