#!/usr/bin/python3
"""epsilon(v) of Kelvin-Voigt disks: FE points with error bars (task 'sweep'
with 'Relaxation times') beside the reduced models of task 'reference
models' (model disk): the 1-DOF ODE and Schwager's eqs. 56 and 80; one
panel per alpha, the elastic FE epsilon (alpha = 0) in each. Optionally the
linear dashpot epsilon(beta/omega0) with both end criteria (model dashpot)
and the viscoelastic spheres' epsilon(g/g*): ODE, series and Pade (model
spheres).

usage: plot_viscoelastic.py restitution.csv reference_disk.csv
           [--dashpot reference_dashpot.csv] [--spheres reference_spheres.csv]
           [-o viscoelastic.png]
"""
import argparse
import csv
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def read(path):
    return list(csv.DictReader(open(path)))


def number(text):
    return float(text) if text not in ("", "nan") else math.nan


p = argparse.ArgumentParser()
p.add_argument("restitution")
p.add_argument("reference")
p.add_argument("--dashpot")
p.add_argument("--spheres")
p.add_argument("-o", "--output", default="viscoelastic.png")
a = p.parse_args()

fe = read(a.restitution)
ref = read(a.reference)
alphas = sorted({round(number(r["alpha"]), 6) for r in fe} - {0.0})
elastic = sorted((number(r["velocity"]), number(r["epsilon"]))
                 for r in fe if number(r["alpha"]) == 0.0)

extra = [x for x in (a.dashpot, a.spheres) if x]
panels = len(alphas) + len(extra)
fig, axes = plt.subplots(1, panels, figsize=(4.2 * panels, 4.0), squeeze=False)
for ax, alpha in zip(axes[0], alphas):
    rows = sorted((r for r in fe if abs(number(r["alpha"]) - alpha) < 1e-9),
                  key=lambda r: number(r["velocity"]))
    ax.errorbar([number(r["velocity"]) for r in rows],
                [number(r["epsilon"]) for r in rows],
                yerr=[0 if math.isnan(number(r["epsilon_error"]))
                      else number(r["epsilon_error"]) for r in rows],
                fmt="o", capsize=3, ms=4, label="FE Kelvin-Voigt")
    if elastic:
        ax.plot(*zip(*elastic), "s:", ms=3, color="gray",
                label="FE elastic")
    model = sorted((r for r in ref if abs(number(r["alpha"]) - alpha) < 1e-9),
                   key=lambda r: number(r["velocity"]))
    v = [number(r["velocity"]) for r in model]
    for column, style, label in (("epsilon_ode", "-", "1-DOF ODE"),
                                 ("epsilon_first_order", "-.", "eq. 56"),
                                 ("epsilon_second_order", "--", "eq. 80")):
        if model and column in model[0]:
            ax.plot(v, [number(r[column]) for r in model], style,
                    label=label)
    # the two losses added: the ODE's viscous loss plus the FE's vibration
    # loss (1 - eps_el) at the same speed
    el = dict(elastic)
    sums = [(x, number(r["epsilon_ode"]) - (1 - el[x])) for x, r in
            zip(v, model) if x in el]
    if sums:
        ax.plot(*zip(*sums), ":", color="black",
                label="ODE - (1 - FE elastic)")
    ax.set_xscale("log")
    ax.set_xlabel("v_i / c")
    ax.set_ylabel("epsilon")
    ax.set_title(f"alpha = {alpha:g}")
    ax.legend(fontsize=7)

if a.dashpot:
    ax = axes[0][len(alphas)]
    rows = read(a.dashpot)
    ratio = [number(r["damping_ratio"]) for r in rows]
    ax.plot(ratio, [number(r["epsilon"]) for r in rows], "o-",
            label="force returns to zero (eq. 21)")
    ax.plot(ratio, [number(r["epsilon_overlap_criterion"]) for r in rows],
            "s--", label="overlap returns to zero")
    ax.set_xscale("log")
    ax.set_xlabel("beta / omega0")
    ax.set_ylabel("epsilon")
    ax.set_title("linear dashpot")
    ax.legend(fontsize=7)

if a.spheres:
    ax = axes[0][-1]
    rows = read(a.spheres)
    ratio = [number(r["velocity_ratio"]) for r in rows]
    for column, style, label in (
            ("epsilon_ode", "o-", "ODE, force end"),
            ("epsilon_ode_overlap", "s-", "ODE, overlap end"),
            ("epsilon_series", ":", "series eq. 32"),
            ("epsilon_pade", "--", "Pade eq. 35"),
            ("epsilon_pade_printed", "-.", "Pade, printed a3, a4")):
        ax.plot(ratio, [number(r[column]) for r in rows], style, ms=3,
                label=label)
    ax.set_xscale("log")
    ax.set_ylim(0, 1.05)
    ax.set_xlabel("g / g*")
    ax.set_ylabel("epsilon")
    ax.set_title("viscoelastic spheres")
    ax.legend(fontsize=7)

fig.tight_layout()
fig.savefig(a.output, dpi=120)
print("wrote", a.output)
