#!/usr/bin/python3
"""Plot what a smooth fit in v leaves of epsilon(v) for several scans of
bench/fixed_mesh_scan.py (its -o tables), one curve each.

usage: bench/plot_fixed_mesh_scans.py OUT.png LABEL=scan.csv [LABEL=scan.csv ...]
           [--fit-degree 6]
"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("output")
    parser.add_argument("scans", nargs="+", metavar="LABEL=CSV")
    parser.add_argument("--fit-degree", type=int, default=6)
    args = parser.parse_args()
    fig, ax = plt.subplots(figsize=(7, 3.6))
    for item in args.scans:
        label, path = item.rsplit("=", 1)
        rows = list(csv.DictReader(open(path, newline="")))
        v = np.array([float(r["velocity"]) for r in rows])
        eps = np.array([float(r["epsilon"]) for r in rows])
        residual = eps - np.polynomial.Polynomial.fit(v, eps, args.fit_degree)(v)
        ax.plot(v, residual * 1e5, ".-", ms=3, lw=0.8,
                label=f"{label} (rms {residual.std():.1e})")
    ax.axhline(0., color="grey", lw=0.5)
    ax.set_xlabel("v / c")
    ax.set_ylabel(f"ε − degree-{args.fit_degree} fit  [1e-5]")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.output, dpi=110)


if __name__ == "__main__":
    main()
