#!/usr/bin/python3
"""Plot the eigenfrequencies of the elastic disk against the angular order n.

Usage: plot_modes.py OUTPUT_DIR/modes.csv [-o modes.png]

Upper panel (cf. Fig. 3 of Gerl & Zippelius): angular frequency omega versus
angular order n, analytic values as open circles and finite-element values as
crosses, coloured by mode family. Rigid-body modes are left out.
Lower panel: |relative error| of each elastic mode versus its index.
"""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.lines import Line2D
from matplotlib.ticker import MaxNLocator

FAMILY_COLOURS = {"radial": "tab:blue", "torsional": "tab:red", "mixed": "tab:green"}


def to_float(text):
    """Convert a CSV field to float; empty fields become None."""
    text = text.strip()
    return float(text) if text else None


def read_modes(path):
    """Return the elastic (non-rigid) modes as a list of dicts."""
    modes = []
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            family = row["family"].strip()
            if family == "rigid":
                continue
            modes.append({
                "index": int(row["index"]),
                "omega": float(row["omega"]),
                "n": int(row["n"]),
                "family": family,
                "omega_exact": to_float(row["omega_exact"]),
                "relative_error": to_float(row["relative_error"]),
            })
    return modes


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("csv", help="modes.csv written by diskimpact")
    parser.add_argument("-o", "--output", help="output PNG (default: modes.png next to the CSV)")
    args = parser.parse_args()
    output = args.output or os.path.join(os.path.dirname(args.csv), "modes.png")

    modes = read_modes(args.csv)
    errors = [abs(m["relative_error"]) for m in modes if m["relative_error"] is not None]
    max_error = f"{max(errors):.2e}" if errors else "n/a"

    fig, (ax_freq, ax_err) = plt.subplots(2, 1, figsize=(7, 8),
                                          gridspec_kw={"height_ratios": [2, 1]})
    for m in modes:
        colour = FAMILY_COLOURS.get(m["family"], "tab:gray")
        if m["omega_exact"] is not None:
            ax_freq.plot(m["n"], m["omega_exact"], "o", mfc="none", mec=colour, ms=8)
        ax_freq.plot(m["n"], m["omega"], "x", color=colour, ms=5)
        # Zero errors cannot be shown on a log axis.
        if m["relative_error"]:
            ax_err.plot(m["index"], abs(m["relative_error"]), "o", color=colour, ms=4)

    families = [f for f in FAMILY_COLOURS if any(m["family"] == f for m in modes)]
    handles = [Line2D([], [], ls="none", marker="s", color=FAMILY_COLOURS[f], label=f)
               for f in families]
    handles += [Line2D([], [], ls="none", marker="o", mfc="none", mec="k", label="analytic"),
                Line2D([], [], ls="none", marker="x", color="k", label="finite element")]
    ax_freq.legend(handles=handles, loc="upper left")
    ax_freq.set_xlabel("angular order $n$")
    ax_freq.set_ylabel(r"angular frequency $\omega$")
    ax_freq.set_title(f"{len(modes)} elastic modes, max |relative error| = {max_error}")
    ax_freq.xaxis.set_major_locator(MaxNLocator(integer=True))
    ax_freq.grid(alpha=0.3)

    ax_err.set_yscale("log")
    ax_err.set_xlabel("mode index")
    ax_err.set_ylabel("|relative error|")
    ax_err.grid(alpha=0.3, which="both")

    fig.tight_layout()
    fig.savefig(output, dpi=150)
    print(f"wrote {output}")


if __name__ == "__main__":
    main()
