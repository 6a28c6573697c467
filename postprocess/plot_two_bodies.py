#!/usr/bin/python3
"""epsilon(v) of two colliding bodies with error bars, one curve per
partner radius (task 'sweep' with 'Kind = body' in subsection Partner), and
its table (docs/guide/two-bodies.md).

With --wall, a sweep of the single body on the wall: its epsilon at v is
drawn at the relative speed 2v (identical bodies meeting at 2v are the
body on the wall at v), and its rows are printed beside the identical
pair's at the matching speeds.

usage: plot_two_bodies.py restitution.csv [more.csv ...] [--wall WALL.csv]
                          [--label LABEL ...] [-o two_bodies.png]
"""
import argparse
import csv
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def rows_of(path):
    rows = [r for r in csv.DictReader(open(path)) if r.get("status", "done") == "done"]
    return [{k: (float(v) if v not in ("", "nan") and k != "status" else
                 (math.nan if k != "status" else v)) for k, v in r.items()} for r in rows]


def error(r):
    return 0.0 if math.isnan(r["epsilon_error"]) else r["epsilon_error"]


p = argparse.ArgumentParser()
p.add_argument("files", nargs="+")
p.add_argument("--label", nargs="*", default=[],
               help="a label per file, put before R2/R1 of each curve")
p.add_argument("--wall", help="restitution.csv of the body on the wall")
p.add_argument("-o", "--output", default="two_bodies.png")
a = p.parse_args()

fig, ax = plt.subplots(figsize=(6.4, 4.4))
print("| case | R2/R1 | v/c (relative) | epsilon | error | contact time [R/c] | delta_max [R] |")
print("|---|---|---|---|---|---|---|")
for i, path in enumerate(a.files):
    rows = rows_of(path)
    for radius in sorted({r["partner_radius"] for r in rows}, reverse=True):
        sel = sorted((r for r in rows if r["partner_radius"] == radius),
                     key=lambda r: r["velocity"])
        label = f"R2/R1 = {radius:g}"
        if i < len(a.label) and a.label[i]:
            label = f"{a.label[i]}, {label}"
        ax.errorbar([r["velocity"] for r in sel], [r["epsilon"] for r in sel],
                    yerr=[error(r) for r in sel], fmt="o-", capsize=3, ms=4,
                    label=label)
        for r in sel:
            print(f"| {label} | {radius:g} | {r['velocity']:g} | {r['epsilon']:.5f} | "
                  f"{error(r):.1e} | {r['contact_time']:.4f} | {r['delta_max']:.5f} |")
if a.wall:
    wall = sorted(rows_of(a.wall), key=lambda r: r["velocity"])
    ax.errorbar([2 * r["velocity"] for r in wall], [r["epsilon"] for r in wall],
                yerr=[error(r) for r in wall], fmt="k^", mfc="none", capsize=3,
                ms=8, label="one disk on the wall at v/2")
    print()
    print("| wall v/c | epsilon | error | contact time [R/c] | 2 delta_max [R] |")
    print("|---|---|---|---|---|")
    for r in wall:
        print(f"| {r['velocity']:g} | {r['epsilon']:.5f} | {error(r):.1e} | "
              f"{r['contact_time']:.4f} | {2 * r['delta_max']:.5f} |")
ax.set_xscale("log")
ax.set_xlabel("relative speed v / c")
ax.set_ylabel("epsilon")
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(a.output, dpi=110)
print("wrote", a.output)
