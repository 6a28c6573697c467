#!/usr/bin/python3
"""Assertions on task 'modal expansion impact' against an FE impact with the
same wall potential (tolerances justified in modal_expansion_small.prm).

usage: check_modal_vs_fe.py output FE_SUMMARY_CSV [--agree TOL] [--energy TOL]
"""
import argparse
import csv
import math
import sys

p = argparse.ArgumentParser()
p.add_argument("directory")
p.add_argument("fe_summary")
p.add_argument("--agree", type=float, default=2e-3)
p.add_argument("--energy", type=float, default=1e-6)
a = p.parse_args()
runs = list(csv.DictReader(open(a.directory + "/modal_expansion.csv")))
fits = [r for r in csv.DictReader(open(a.directory + "/modal_extrapolation.csv"))
        if r["limit"] == "modes"]
fe = next(csv.DictReader(open(a.fe_summary)))
checks = []
for r in runs:
    error = float(r["energy_error"])
    checks.append((f"modal energy error, N = {r['n_modes']}", error, error <= a.energy))
limit, bar = float(fits[0]["epsilon"]), float(fits[0]["error"])
epsilon_fe = float(fe["epsilon"])
print(f"modal N -> infinity: {limit:.6f} +- {bar:.1e}; FE: {epsilon_fe:.6f}")
checks.append(("error bar of the N extrapolation", bar,
               math.isfinite(bar) and bar <= a.agree))
checks.append(("|eps_modal - eps_FE|", abs(limit - epsilon_fe),
               abs(limit - epsilon_fe) <= a.agree))
for name, value, ok in checks:
    print(f"{'ok  ' if ok else 'FAIL'} {name}: {value:.3e}")
sys.exit(0 if all(ok for _, _, ok in checks) else 1)
