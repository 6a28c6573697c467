#!/usr/bin/python3
"""Plots of one impact (task 'impact').

usage: plot_impact.py OUTPUT_DIR

Writes OUTPUT_DIR/impact.png: the energy history (kinetic, translational,
strain, contact, total) and the contact force against time.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

directory = sys.argv[1]
rows = list(csv.DictReader(open(directory + "/impact.csv")))
col = lambda name: np.array([float(r[name]) for r in rows])
t = col("time")
summary = next(csv.DictReader(open(directory + "/summary.csv")))

fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
for name in ("energy_kinetic", "energy_translational", "energy_strain",
             "energy_contact", "energy_total"):
    ax[0].plot(t, col(name), label=name.replace("energy_", ""))
ax[0].set_xlabel("t c / R")
ax[0].set_ylabel("energy")
ax[0].legend(fontsize=8)
ax[0].set_title(f"v = {float(summary['velocity']):g} c, "
                f"epsilon = {float(summary['epsilon']):.5f}, "
                f"energy error {float(summary['energy_error']):.1e}")
ax[1].plot(t, col("contact_force"), ".-", ms=2)
ax[1].axvline(float(summary["contact_time"]), color="k", ls="--", lw=1,
              label="end of contact")
ax[1].set_xlabel("t c / R")
ax[1].set_ylabel("contact force / (E2 R)")
ax[1].legend(fontsize=8)
fig.tight_layout()
fig.savefig(directory + "/impact.png", dpi=120)
print("wrote", directory + "/impact.png")
