#!/usr/bin/python3
"""Plots of task 'quasistatic contact' results.

usage: plot_contact_law.py OUTPUT_DIR [--c-com C] [--c-diameter C]

Writes OUTPUT_DIR/contact_law.png (delta/R against P/(pi E2 R): FE points
for both compressions, the printed law with C = -1 - nu2 and the laws with
the given, measured constants) and OUTPUT_DIR/pressure_profile.png (pressure
against y / a_Hertz for each load, beside Hertz's ellipse).
"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def main():
    p = argparse.ArgumentParser()
    p.add_argument("output_dir")
    p.add_argument("--c-com", type=float, help="measured C for delta_com")
    p.add_argument("--c-diameter", type=float, default=-1.0,
                   help="C for delta_diameter (default -1)")
    a = p.parse_args()

    rows = list(csv.DictReader(open(a.output_dir + "/contact_law.csv")))
    load = np.array([float(r["load"]) for r in rows])
    d_com = np.array([float(r["delta_com"]) for r in rows])
    d_diam = np.array([float(r["delta_diameter"]) for r in rows])
    nu2 = float(rows[0]["poisson_ratio_2d"])
    x = np.logspace(np.log10(load.min()) - 0.3, np.log10(load.max()) + 0.3, 200)
    law = lambda c: x * (np.log(4 / x) + c)

    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    ax[0].loglog(load, d_com, "o", label="FE: centre-of-mass approach")
    ax[0].loglog(load, d_diam, "s", mfc="none", label="FE: diameter shortening")
    ax[0].loglog(x, law(-1 - nu2), "k--", lw=1,
                 label=f"printed: C = -1 - nu2 = {-1 - nu2:.3f}")
    if a.c_com is not None:
        ax[0].loglog(x, law(a.c_com), "C0-", lw=1, label=f"C_com = {a.c_com:.4f}")
    ax[0].loglog(x, law(a.c_diameter), "C1-", lw=1,
                 label=f"C_diameter = {a.c_diameter:.4f}")
    ax[0].set_xlabel("P / (pi E2 R)")
    ax[0].set_ylabel("delta / R")
    ax[0].legend(fontsize=8)
    ax[0].set_title(f"contact law, nu2 = {nu2:.4f}")
    # the relative difference, where the constants show
    ax[1].semilogx(load, d_com / load - np.log(4 / load), "o", label="C_com (FE)")
    ax[1].semilogx(load, d_diam / load - np.log(4 / load), "s", mfc="none",
                   label="C_diameter (FE)")
    ax[1].axhline(-1 - nu2, color="k", ls="--", lw=1, label="printed -1 - nu2")
    ax[1].set_xlabel("P / (pi E2 R)")
    ax[1].set_ylabel("(delta/R) / load - ln(4 / load)")
    ax[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(a.output_dir + "/contact_law.png", dpi=120)

    prof = list(csv.DictReader(open(a.output_dir + "/pressure_profile.csv")))
    fig, ax = plt.subplots(figsize=(6, 4.2))
    for value in sorted({float(r["load"]) for r in prof}):
        sel = [r for r in prof if float(r["load"]) == value]
        a_h = 2 * np.sqrt(value)
        y = np.array([float(r["y"]) for r in sel]) / a_h
        pr = np.array([float(r["pressure"]) for r in sel]) * np.pi * a_h / 2
        ax.plot(y, pr, ".", ms=3, label=f"load {value:.0e}")
    t = np.linspace(0, 1, 200)
    ax.plot(t, np.sqrt(1 - t**2), "k-", lw=1, label="Hertz")
    ax.set_xlabel("y / a_Hertz")
    ax.set_ylabel("p / p0_Hertz")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(a.output_dir + "/pressure_profile.png", dpi=120)
    print("wrote", a.output_dir + "/contact_law.png and pressure_profile.png")


if __name__ == "__main__":
    main()
