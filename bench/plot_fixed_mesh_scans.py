#!/usr/bin/python3
"""Plot what a smooth fit in v leaves of epsilon(v) for several scans of
bench/fixed_mesh_scan.py (its -o tables), one curve each; with --nodes, one
panel per scan, with a vertical line where one more edge node joins the
contact (its contact_dofs column grows).

usage: bench/plot_fixed_mesh_scans.py OUT.png LABEL=scan.csv [LABEL=scan.csv ...]
           [--fit-degree 6] [--nodes]
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
    parser.add_argument("--nodes", action="store_true",
                        help="one panel per scan, marking where a node joins")
    args = parser.parse_args()
    panels = len(args.scans) if args.nodes else 1
    fig, axes = plt.subplots(panels, 1, sharex=True, squeeze=False,
                             figsize=(7, 3.6 if panels == 1 else 1.9 * panels))
    for i, item in enumerate(args.scans):
        ax = axes[i if args.nodes else 0][0]
        label, path = item.rsplit("=", 1)
        rows = list(csv.DictReader(open(path, newline="")))
        v = np.array([float(r["velocity"]) for r in rows])
        eps = np.array([float(r["epsilon"]) for r in rows])
        residual = eps - np.polynomial.Polynomial.fit(v, eps, args.fit_degree)(v)
        ax.plot(v, residual * 1e5, ".-", ms=3, lw=0.8,
                label=f"{label} (rms {residual.std():.1e})")
        if args.nodes:
            touched = np.array([int(r["contact_dofs"]) for r in rows])
            for k in np.flatnonzero(np.diff(touched)):
                ax.axvline(0.5 * (v[k] + v[k + 1]), color="tab:red", lw=0.6)
    for (ax,) in axes:
        ax.axhline(0., color="grey", lw=0.5)
        ax.set_ylabel("ε − fit  [1e-5]" if args.nodes
                      else f"ε − degree-{args.fit_degree} fit  [1e-5]")
        ax.legend(fontsize=8, loc="upper left" if args.nodes else "best")
    axes[-1][0].set_xlabel("v / c")
    fig.tight_layout()
    fig.savefig(args.output, dpi=110)


if __name__ == "__main__":
    main()
