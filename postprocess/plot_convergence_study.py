#!/usr/bin/python3
"""Plot an impact convergence study: epsilon per level with its error bar.

usage: plot_convergence_study.py OUTPUT_DIR [-o FILE.png]

OUTPUT_DIR is the output of task 'impact convergence' (impact_convergence.csv,
epsilon_estimate.csv). One panel per refined factor (mesh, time step,
penalty): epsilon of each level (level 0 is the base run), the factor's
limit with its error bar as a band, and in the mesh panel the split runs
(the last level's coarser mesh at its time step) as open squares. The title
gives the study's result, epsilon = limit +- error, and whether the bar is
the verified Richardson estimate (clean) or the fallback, with the reason
read from the differences. Default PNG: OUTPUT_DIR/impact_convergence.png.
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

FACTORS = ("mesh", "time step", "penalty")


def read_rows(path):
    try:
        with open(path, newline="") as f:
            return list(csv.DictReader(f))
    except OSError as error:
        sys.exit(f"plot_convergence_study: cannot read {path}: {error.strerror}")


def number(text):
    return float(text) if text not in ("", "nan") else float("nan")


def sequence(runs, factor):
    """The factor's sequence, (level, epsilon, time halvings) of the base run
    and of the factor's runs, the run with the most time-step halvings at
    each level (a study that halves the step replaces a level's run); and
    the replaced runs."""
    rows = sorted((int(r["level"]), int(r["time_halvings"]), number(r["epsilon"]))
                  for r in runs if r["factor"] in ("base", factor))
    latest = {level: (level, eps, halvings) for level, halvings, eps in rows}
    kept = sorted(latest.values())
    replaced = [(level, eps, halvings) for level, halvings, eps in rows
                if (level, eps, halvings) not in kept]
    return kept, replaced


def why_fallback(epsilons):
    """The first reason, from the differences, why a sequence is not clean."""
    d = [b - a for a, b in zip(epsilons, epsilons[1:])]
    if len(d) >= 2 and d[-1] * d[-2] < 0:
        return f"the last two differences change sign ({d[-2]:.2e}, {d[-1]:.2e})"
    if len(d) >= 2 and abs(d[-1]) >= abs(d[-2]):
        return f"the last difference ({d[-1]:.2e}) is not smaller than the one before"
    if len(epsilons) < 5:
        return f"{len(epsilons)} levels; a verified order needs 5"
    return "the orders of the last level triples disagree or differ from the expected"


def title(estimates, runs):
    total = next((e for e in estimates if e["factor"] == "total"), None)
    if total is None:
        sys.exit("plot_convergence_study: epsilon_estimate.csv has no row 'total'")
    text = f"epsilon = {number(total['limit']):.8f} +- {number(total['error']):.2e}"
    mesh = next((e for e in estimates if e["factor"] == "mesh"), None)
    if mesh is None:
        return (text + "\none mesh level: no error bar; the time-step and "
                "penalty sequences are diagnostics, not added to it")
    if mesh["clean"] == "1":
        return (text + f"\nclean: observed order {number(mesh['observed_order']):.2f}"
                f" (scatter {number(mesh['order_scatter']):.2f}), Richardson's bar")
    levels = [e for _, e, _ in sequence(runs, "mesh")[0]]
    return text + "\nfallback bar: " + why_fallback(levels)


def plot_factor(ax, runs, estimate, factor):
    points, replaced = sequence(runs, factor)
    levels = [p[0] for p in points]
    epsilons = [p[1] for p in points]
    ax.plot(levels, epsilons, "o-", color="C0", label=f"{factor} levels")
    if replaced:
        ax.plot([p[0] for p in replaced], [p[1] for p in replaced], "x",
                color="0.5", label="replaced by a halved time step")
    for level, eps, halvings in points:
        if halvings:
            ax.annotate(f"dt/2^{halvings}", (level, eps), textcoords="offset points",
                        xytext=(4, 4), fontsize=7)
    if factor == "mesh":
        split = sorted((int(r["level"]), number(r["epsilon"]))
                       for r in runs if r["factor"] == "split")
        if split:
            ax.plot(*zip(*split), "s", mfc="none", color="C2",
                    label="split (coarser mesh, finer step)")
    if estimate is not None:
        limit, error = number(estimate["limit"]), number(estimate["error"])
        ax.axhline(limit, color="C3", lw=1, label=f"limit {limit:.8f}")
        ax.axhspan(limit - error, limit + error, color="C3", alpha=0.15,
                   label=f"error bar +- {error:.2e}")
    if estimate is not None and estimate.get("clean") == "1":
        ax.set_title(f"{factor}: clean, order {number(estimate['observed_order']):.2f}",
                     fontsize=9)
    elif factor != "mesh" and estimate is not None:
        ax.set_title(f"{factor} (diagnostic): not clean", fontsize=9)
    ax.set_xticks(levels)
    ax.set_xlabel(f"{factor} level")
    ax.set_ylabel("epsilon")
    ax.ticklabel_format(axis="y", useOffset=False)
    ax.legend(fontsize=7)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("output_dir", help="output of task 'impact convergence'")
    parser.add_argument("-o", "--output", help="PNG to write (default "
                        "OUTPUT_DIR/impact_convergence.png)")
    args = parser.parse_args()
    runs = read_rows(os.path.join(args.output_dir, "impact_convergence.csv"))
    estimates = read_rows(os.path.join(args.output_dir, "epsilon_estimate.csv"))
    if not runs or "factor" not in runs[0]:
        sys.exit("plot_convergence_study: impact_convergence.csv has no runs")
    factors = [f for f in FACTORS if any(r["factor"] == f for r in runs)]
    if not factors:
        sys.exit("plot_convergence_study: the study refined nothing (one level)")
    fig, axes = plt.subplots(1, len(factors), figsize=(5.2 * len(factors), 4.4),
                             squeeze=False)
    for ax, factor in zip(axes[0], factors):
        # The mesh sequence carries the study's result (row 'total'); the
        # others are diagnostics with their own limits.
        name = "total" if factor == "mesh" else factor
        estimate = next((e for e in estimates if e["factor"] == name), None)
        plot_factor(ax, runs, estimate, factor)
    fig.suptitle(title(estimates, runs), fontsize=9)
    fig.tight_layout()
    output = args.output or os.path.join(args.output_dir, "impact_convergence.png")
    fig.savefig(output, dpi=120)
    print(f"plot_convergence_study: {output}")


if __name__ == "__main__":
    main()
