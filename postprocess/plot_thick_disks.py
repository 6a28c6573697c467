#!/usr/bin/python3
"""epsilon(v) of free disks of finite thickness beside the plane-stress and
plane-strain disks, from the table bench/free_disk_restitution.sh writes
(--csv): the loss 1 - epsilon against v/c, and each disk's departure from
plane stress, epsilon - epsilon_ps, with the plane-strain disk's for scale. Points without a bar (level 0 alone) are
drawn hollow. Prints the table (epsilon +- bar per speed and model) in
Markdown.

usage: plot_thick_disks.py TABLE.csv [-o thick_disks.png]
"""
import argparse
import csv
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

p = argparse.ArgumentParser()
p.add_argument("table")
p.add_argument("-o", "--output", default="thick_disks.png")
a = p.parse_args()

rows = list(csv.DictReader(open(a.table)))
for r in rows:
    r["v"], r["epsilon"], r["bar"] = float(r["v"]), float(r["epsilon"]), float(r["bar"])
models = list(dict.fromkeys(r["model"] for r in rows))
speeds = sorted({r["v"] for r in rows})
value = {(r["model"], r["v"]): r for r in rows}
stress = {v: value[("plane stress", v)] for v in speeds}

def shown(r):
    if math.isnan(r["bar"]):
        return f"{r['epsilon']:.6f} (level 0)"
    return (f"{r['epsilon']:.6f} ± {r['bar']:.1e}"
            + (" (parts)" if r.get("how") == "parts" else ""))


print("| v/c | " + " | ".join(models) + " |")
print("|---" * (len(models) + 1) + "|")
for v in speeds:
    print(f"| {v:g} | " + " | ".join(shown(value[(m, v)]) if (m, v) in value else ""
                                     for m in models) + " |")

fig, (loss, departure) = plt.subplots(1, 2, figsize=(11, 4.4))
for i, model in enumerate(models):
    sel = [value[(model, v)] for v in speeds if (model, v) in value]
    color = "k" if model.startswith("plane") else f"C{i}"
    style = "--" if model == "plane strain" else "-"
    v = [r["v"] for r in sel]
    bars = [0. if math.isnan(r["bar"]) else r["bar"] for r in sel]
    loss.errorbar(v, [1 - r["epsilon"] for r in sel], yerr=bars, fmt=style,
                  color=color, capsize=3, label=model)
    shift = [r["epsilon"] - stress[r["v"]]["epsilon"] for r in sel]
    shift_bars = [b + (0. if math.isnan(stress[r["v"]]["bar"]) else stress[r["v"]]["bar"])
                  for b, r in zip(bars, sel)]
    if model != "plane stress":
        departure.errorbar(v, shift, yerr=shift_bars, fmt=style, color=color,
                           capsize=3, label=model)
    for r in sel:
        hollow = math.isnan(r["bar"])
        for ax, y in ((loss, 1 - r["epsilon"]),
                      (departure, r["epsilon"] - stress[r["v"]]["epsilon"])):
            if ax is departure and model == "plane stress":
                continue
            ax.plot(r["v"], y, "o", ms=5, color=color,
                    mfc="white" if hollow else color)
loss.set_xscale("log")
loss.set_yscale("log")
loss.set_xlabel("v / c,  c = sqrt(E / rho)")
loss.set_ylabel("1 - epsilon")
loss.set_title("loss of a free disk on a rigid wall, nu = 0.3")
departure.set_xscale("log")
departure.axhline(0., color="k", lw=0.8)
departure.set_xlabel("v / c")
departure.set_ylabel("epsilon - epsilon (plane stress)")
departure.set_title("departure from the plane-stress disk")
for ax in (loss, departure):
    ax.grid(True, which="both", alpha=0.3)
loss.legend(fontsize=8)
departure.legend(fontsize=8)
fig.tight_layout()
fig.savefig(a.output, dpi=130)
print(f"wrote {a.output}")
