#!/usr/bin/python3
"""epsilon(v) with error bars from one or more restitution.csv files
(tasks 'sweep' and 'restitution law').

usage: plot_restitution.py restitution.csv [more.csv ...] [-o epsilon.png]

Beside a table of task 'restitution law' for a plastic sphere, its
restitution_law.json holds Thornton's and Luding's models fitted to it
(docs/theory/thornton-model.md, docs/theory/luding-model.md); their
epsilon(v) is drawn too.

Speeds are drawn as v/c, or in m/s for the tables of SI runs (Units = SI):
their restitution.h5 beside the CSV holds the speed unit c in m/s (root
attribute speed_unit_m_per_s). Tables of both kinds cannot share a plot.
"""
import argparse
import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def speed_unit(csv_path):
    """c in m/s if the table is an SI run's, else None."""
    h5_path = os.path.join(os.path.dirname(csv_path) or ".", "restitution.h5")
    if not os.path.exists(h5_path):
        return None
    import h5py
    with h5py.File(h5_path, "r") as f:
        value = f.attrs.get("speed_unit_m_per_s")
    return float(value) if value is not None else None


def thornton_epsilon(u):
    """epsilon of LIGGGHTS' thornton_ning at v/v_y = u
    (docs/theory/thornton-model.md)."""
    if u <= 1.0:
        return 1.0
    x_m = 1.0 + (math.sqrt(1.2 * u * u - 0.2) - 1.0) / 1.5
    f_m = 1.0 + 1.5 * (x_m - 1.0)
    x_p = max(x_m ** 1.5 - f_m, 0.0) ** (2.0 / 3.0)
    returned = (f_m - x_m ** 1.5) * (x_m - x_p) + 0.4 * (x_m ** 2.5 - x_p ** 2.5)
    return math.sqrt(returned / (0.4 * u * u))


def luding_epsilon(x, a):
    """epsilon of Yade's LudingMat at v/v_p = x with kp/k1 = 1 + a
    (docs/theory/luding-model.md)."""
    return (1.0 + a * x) ** -0.5 if x <= 1.0 else \
        math.sqrt(1.0 - a / ((1.0 + a) * x * x))


def plastic_fits(csv_path):
    """restitution_law.json's Thornton and Luding fits beside the table
    (None where absent)."""
    path = os.path.join(os.path.dirname(csv_path) or ".", "restitution_law.json")
    if not os.path.exists(path):
        return None, None
    law = json.load(open(path))
    return law.get("thornton_fit"), law.get("luding_fit")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("files", nargs="+")
    p.add_argument("-o", "--output", default="epsilon.png")
    a = p.parse_args()

    units = [speed_unit(path) for path in a.files]
    if len({u is None for u in units}) > 1:
        sys.exit("plot_restitution: SI and dimensionless tables cannot share a plot")
    si = units[0] is not None
    fig, ax = plt.subplots(figsize=(6, 4.2))
    for path, c in zip(a.files, units):
        rows = list(csv.DictReader(open(path)))
        for nu2 in sorted({r["poisson_ratio_2d"] for r in rows}):
            sel = [r for r in rows if r["poisson_ratio_2d"] == nu2
                   and r["epsilon"] not in ("", "nan")]
            v = [float(r["velocity"]) * (c if si else 1.0) for r in sel]
            eps = [float(r["epsilon"]) for r in sel]
            err = [float(r["epsilon_error"]) if r["epsilon_error"] not in ("", "nan")
                   else 0.0 for r in sel]
            ax.errorbar(v, eps, yerr=err, fmt="o-", capsize=3, ms=4,
                        label=f"FE, nu2 = {float(nu2):.2f}")
        fit, luding = plastic_fits(path)
        if fit and v:
            scale = c if si else 1.0
            lo, hi = math.log(min(v)), math.log(max(v))
            curve = [math.exp(lo + (hi - lo) * k / 200) for k in range(201)]
            ax.plot(curve, [thornton_epsilon(x / (fit["yield_speed"] * scale))
                            for x in curve], "--",
                    label="Thornton (LIGGGHTS thornton_ning), p_y = "
                          f"{fit['limiting_pressure_over_yield_stress']:.3g} Y")
        if luding and v:
            a_l = luding["stiffness_ratio"] - 1.0
            ax.plot(curve, [luding_epsilon(x / (luding["plastic_speed"] * scale),
                                           a_l) for x in curve], ":",
                    label="Luding (Yade LudingMat), kp/k1 = "
                          f"{luding['stiffness_ratio']:.3g}")
    ax.set_xscale("log")
    ax.set_xlabel("v_i [m/s]" if si else "v_i / c")
    ax.set_ylabel("epsilon")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(a.output, dpi=120)
    print("wrote", a.output)


if __name__ == "__main__":
    main()
