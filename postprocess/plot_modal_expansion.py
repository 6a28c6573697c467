#!/usr/bin/python3
"""The modal-expansion model (task 'modal expansion impact') and its
extrapolations beside the FE penalty results (task 'sweep'):

1. epsilon(v) for each nu2: the modal expansion extrapolated to all modes
   and hard contact (modal_extrapolation.csv, rows 'stiffness'), the FE
   penalty sweeps (restitution.csv), and the value read from Gerl & Zippelius'
   Fig. 1 (0.65 at nu2 = 0.9, v = 0.3c);
2. epsilon against 1/sqrt(N) for each stiffness s of the wall potential
   with the N fits, at one (nu2, v);
3. the N limits against 1/s with the fit in 1/s, at the same (nu2, v).

usage: plot_modal_expansion.py DIR [--fe restitution.csv ...]
           [--nu2 0.33] [--velocity 0.1] [-o modal_expansion.png]
DIR holds modal_expansion.csv and modal_extrapolation.csv.
"""
import argparse
import csv
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

GERL_ZIPPELIUS_FIG_1 = [(0.9, 0.3, 0.65)]  # (nu2, v/c, epsilon) readable from Fig. 1


def read(path):
    """The rows of a CSV file, numbers as floats; the potential's stiffness
    as "s" (column potential_stiffness, or alpha in older tables)."""
    rows = [{k: (float(v) if v else math.nan) if k != "limit" else v
             for k, v in r.items()}
            for r in csv.DictReader(open(path))]
    for r in rows:
        r["s"] = r.get("potential_stiffness", r.get("alpha"))
    return rows


p = argparse.ArgumentParser()
p.add_argument("directory")
p.add_argument("--fe", nargs="*", default=[])
p.add_argument("--nu2", type=float, default=0.33)
p.add_argument("--velocity", type=float, default=0.1)
p.add_argument("-o", "--output", default="modal_expansion.png")
a = p.parse_args()
runs = read(os.path.join(a.directory, "modal_expansion.csv"))
fits = read(os.path.join(a.directory, "modal_extrapolation.csv"))
close = lambda x, y: abs(x - y) < 1e-9

fig, axes = plt.subplots(1, 3, figsize=(14, 4.2))
ax = axes[0]
for nu2 in sorted({r["poisson_ratio_2d"] for r in fits}):
    hard = sorted((r["velocity"], r["epsilon"], r["error"]) for r in fits
                  if r["limit"] == "stiffness" and close(r["poisson_ratio_2d"], nu2))
    if hard:
        v, eps, err = zip(*hard)
        ax.errorbar(v, eps, yerr=err, fmt="o-", capsize=3, ms=4,
                    label=f"modal expansion, s, N -> inf, nu2 = {nu2:g}")
for path in a.fe:
    rows = list(csv.DictReader(open(path)))
    for nu2 in sorted({float(r["poisson_ratio_2d"]) for r in rows}):
        sel = sorted((float(r["velocity"]), float(r["epsilon"]),
                      float(r["epsilon_error"] or 0.0)) for r in rows
                     if close(float(r["poisson_ratio_2d"]), nu2) and r["epsilon"])
        v, eps, err = zip(*sel)
        ax.errorbar(v, eps, yerr=err, fmt="s--", capsize=3, ms=4,
                    label=f"FE penalty, nu2 = {nu2:g}")
for nu2, v, eps in GERL_ZIPPELIUS_FIG_1:
    ax.plot([v], [eps], "k*", ms=10, label=f"Gerl & Zippelius 1999 Fig. 1, nu2 = {nu2:g}")
ax.set_xlabel("v_i / c")
ax.set_ylabel("epsilon")
ax.legend(fontsize=7)

ax = axes[1]
case = [r for r in runs if close(r["poisson_ratio_2d"], a.nu2)
        and close(r["velocity"], a.velocity)]
for s in sorted({r["s"] for r in case}):
    pts = sorted((1 / math.sqrt(r["n_modes"]), r["epsilon"]) for r in case
                 if close(r["s"], s))
    line = ax.plot(*zip(*pts), "o", ms=4, label=f"s = {s:g}")[0]
    fit = [r for r in fits if r["limit"] == "modes" and close(r["s"], s)
           and close(r["poisson_ratio_2d"], a.nu2) and close(r["velocity"], a.velocity)]
    if fit:
        x = [0, max(x for x, _ in pts)]
        ax.plot(x, [fit[0]["epsilon"] + fit[0]["slope"] * xi for xi in x], "-",
                color=line.get_color(), lw=0.8)
ax.set_xlabel("1 / sqrt(N)")
ax.set_ylabel("epsilon")
ax.set_title(f"nu2 = {a.nu2:g}, v = {a.velocity:g} c: N -> infinity")
ax.legend(fontsize=7)

ax = axes[2]
limits = sorted((1 / r["s"], r["epsilon"], r["error"]) for r in fits
                if r["limit"] == "modes" and close(r["poisson_ratio_2d"], a.nu2)
                and close(r["velocity"], a.velocity))
if limits:
    x, eps, err = zip(*limits)
    ax.errorbar(x, eps, yerr=err, fmt="o", capsize=3, ms=4, label="N -> infinity")
    hard = [r for r in fits if r["limit"] == "stiffness"
            and close(r["poisson_ratio_2d"], a.nu2) and close(r["velocity"], a.velocity)]
    if hard:
        xs = [0, max(x)]
        ax.plot(xs, [hard[0]["epsilon"] + hard[0]["slope"] * xi for xi in xs], "-",
                lw=0.8, label="fit, s -> infinity")
        ax.errorbar([0], [hard[0]["epsilon"]], yerr=[hard[0]["error"]], fmt="*",
                    ms=9, capsize=3)
ax.set_xlabel("1 / s")
ax.set_ylabel("epsilon")
ax.set_title("hard contact: s -> infinity")
ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(a.output, dpi=120)
print("wrote", a.output)
