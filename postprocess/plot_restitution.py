#!/usr/bin/python3
"""epsilon(v) with error bars from one or more restitution.csv files
(task 'sweep').

usage: plot_restitution.py restitution.csv [more.csv ...] [-o epsilon.png]
"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

p = argparse.ArgumentParser()
p.add_argument("files", nargs="+")
p.add_argument("-o", "--output", default="epsilon.png")
a = p.parse_args()

fig, ax = plt.subplots(figsize=(6, 4.2))
for path in a.files:
    rows = list(csv.DictReader(open(path)))
    for nu2 in sorted({r["poisson_ratio_2d"] for r in rows}):
        sel = [r for r in rows if r["poisson_ratio_2d"] == nu2]
        v = [float(r["velocity"]) for r in sel]
        eps = [float(r["epsilon"]) for r in sel]
        err = [float(r["epsilon_error"]) if r["epsilon_error"] not in ("", "nan")
               else 0.0 for r in sel]
        ax.errorbar(v, eps, yerr=err, fmt="o-", capsize=3, ms=4,
                    label=f"FE, nu2 = {float(nu2):.2f}")
ax.set_xscale("log")
ax.set_xlabel("v_i / c")
ax.set_ylabel("epsilon")
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(a.output, dpi=120)
print("wrote", a.output)
