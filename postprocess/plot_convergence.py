#!/usr/bin/python3
"""Plot the convergence of the modal frequencies under mesh refinement.

Usage: plot_convergence.py OUTPUT_DIR/modal_convergence.csv [-o convergence.png]

Log-log plot of |relative error| versus mesh size h: one colour per polynomial
degree k, one thin line per mode, and a dashed reference slope h^(2k) per
degree. Prints, per degree, the median observed order on the finest level.
"""
import argparse
import csv
import os
import statistics
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def to_float(text):
    """Convert a CSV field to float; empty fields become None."""
    text = text.strip()
    return float(text) if text else None


def read_rows(path):
    """Return the rows that have a relative error, with numeric fields converted."""
    rows = []
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            error = to_float(row["relative_error"])
            if error is None:
                continue
            rows.append({
                "degree": int(row["degree"]),
                "refinements": int(row["refinements"]),
                "h": float(row["h"]),
                "mode": row["mode"].strip(),
                "error": abs(error),
                "order": to_float(row["observed_order"]),
            })
    return rows


def print_table(rows):
    """Print the median observed order on the finest level of each degree."""
    print(f"{'degree':>6} {'refinements':>11} {'h':>10} {'modes':>5} {'median order':>12} {'2k':>3}")
    for k in sorted({r["degree"] for r in rows}):
        finest = max(r["refinements"] for r in rows if r["degree"] == k)
        level = [r for r in rows if r["degree"] == k and r["refinements"] == finest]
        orders = [r["order"] for r in level if r["order"] is not None]
        median = f"{statistics.median(orders):.2f}" if orders else "n/a"
        print(f"{k:>6} {finest:>11} {level[0]['h']:>10.3g} {len(level):>5} {median:>12} {2 * k:>3}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("csv", help="modal_convergence.csv written by diskimpact")
    parser.add_argument("-o", "--output",
                        help="output PNG (default: convergence.png next to the CSV)")
    args = parser.parse_args()
    output = args.output or os.path.join(os.path.dirname(args.csv), "convergence.png")

    rows = read_rows(args.csv)
    print_table(rows)

    # Group the points into one curve per (degree, mode).
    curves = defaultdict(list)
    for r in rows:
        if r["error"] > 0:  # zero errors cannot be shown on a log axis
            curves[(r["degree"], r["mode"])].append((r["h"], r["error"]))

    fig, ax = plt.subplots(figsize=(7, 5.5))
    degrees = sorted({k for k, _ in curves})
    for i, k in enumerate(degrees):
        colour = f"C{i}"
        for (degree, _), points in curves.items():
            if degree == k:
                h, error = zip(*sorted(points))
                ax.loglog(h, error, "-", color=colour, lw=0.6, alpha=0.6)
        # Reference slope h^(2k), anchored at the median error on the coarsest mesh.
        points = [p for (degree, _), c in curves.items() if degree == k for p in c]
        h_min, h_max = min(p[0] for p in points), max(p[0] for p in points)
        e0 = statistics.median(e for h, e in points if h == h_max)
        h_ref = [h_min, h_max]
        ax.loglog(h_ref, [e0 * (h / h_max) ** (2 * k) for h in h_ref], "--", color=colour,
                  lw=1.5, label=f"degree {k}")
        h_mid = (h_min * h_max) ** 0.5
        ax.annotate(f"2k = {2 * k}", (h_mid, e0 * (h_mid / h_max) ** (2 * k)), color=colour,
                    textcoords="offset points", xytext=(-4, 4), ha="right", va="bottom")

    ax.set_xlabel("mesh size $h$")
    ax.set_ylabel("|relative error| of $\\omega$")
    ax.set_title("Modal convergence (thin: modes, dashed: $h^{2k}$)")
    ax.grid(alpha=0.3, which="both")
    ax.legend()
    fig.tight_layout()
    fig.savefig(output, dpi=150)
    print(f"wrote {output}")


if __name__ == "__main__":
    main()
