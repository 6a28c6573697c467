#!/usr/bin/python3
"""Plot the energy in the leading elastic modes of an impact beside Gerl & Zippelius' Table 1.

Usage: plot_mode_energies.py OUTPUT_DIR|FILE.csv [-o mode_energies.png] [--count 10]
                             [--linear] [--nu2 NU2] [--velocity V] [--stiffness S]

Reads OUTPUT_DIR/mode_energies.csv (columns rank, n, l, family, omega,
energy_fraction, average_energy_fraction; fractions of the initial kinetic
energy) and takes the modes with the largest average_energy_fraction (the
energy averaged over the collision), or with the largest energy_fraction (the
energy after the collision) if the file has no average. Rows of family
"rigid" or without (n, l) are left out. Writes OUTPUT_DIR/mode_energies.png:
per mode (n,l) two bars (average during, and after, the collision) beside the
values of Table 1 of Gerl & Zippelius (wall stiffness s = 500, v = 0.1c, nu = 0.33,
1600 modes), and prints both side by side.

A CSV file may be given instead of the directory, e.g.
modal_expansion_modes.csv of task 'modal expansion impact' (one block of rows
per poisson_ratio_2d, velocity, potential_stiffness): --nu2, --velocity and
--stiffness pick
the block.
"""
import argparse
import csv
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.patches import Patch

# Gerl & Zippelius 1999 (Gerl & Zippelius), Table 1: the ten modes with the largest average
# fraction of the energy during the collision, s = 500, v_i = 0.1c,
# 1600 modes. Columns: rank, n, l, average energy, energy after collision.
GERL_ZIPPELIUS_TABLE_1 = [
    (1, 2, 0, 0.1594843, 0.0513636),
    (2, 3, 0, 0.0480930, 0.0234695),
    (3, 0, 0, 0.0231257, 0.0089346),
    (4, 4, 0, 0.0220028, 0.0038760),
    (5, 0, 1, 0.0128242, 0.0003144),
    (6, 5, 0, 0.0114396, 0.0027244),
    (7, 1, 1, 0.0110218, 0.0002610),
    (8, 1, 0, 0.0066413, 0.0002548),
    (9, 6, 0, 0.0059540, 0.0021365),
    (10, 0, 2, 0.0048560, 0.0000279),
]

AVERAGE_COLOUR = "tab:blue"
AFTER_COLOUR = "tab:orange"


def to_float(text):
    """Convert a CSV field to float; empty or missing fields become None."""
    text = (text or "").strip()
    return float(text) if text else None


def read_modes(path, where):
    """Return the labelled elastic modes as dicts, and whether averages exist;
    only rows whose columns match @p where (column -> value) if given."""
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        has_average = "average_energy_fraction" in (reader.fieldnames or [])
        modes = []
        for row in reader:
            if any(column in row and abs(float(row[column]) - value) > 1e-9
                   for column, value in where.items()):
                continue
            family = row["family"].strip()
            if family == "rigid" or not row["n"].strip() or not row["l"].strip():
                continue
            modes.append({
                "n": int(row["n"]),
                "l": int(row["l"]),
                "family": family,
                "omega": to_float(row["omega"]),
                "average": to_float(row.get("average_energy_fraction")),
                "after": to_float(row["energy_fraction"]),
            })
    return modes, has_average


def leading_modes(modes, key, count):
    """The @p count modes with the largest value of @p key (missing last)."""
    def value(mode):
        return mode[key] if mode[key] is not None else -math.inf
    return sorted(modes, key=value, reverse=True)[:count]


def table_1_by_label():
    """Gerl & Zippelius' Table 1 as {(n, l): (rank, average, after)}."""
    return {(n, l): (rank, average, after) for rank, n, l, average, after in GERL_ZIPPELIUS_TABLE_1}


def number(value, width=10):
    """A fraction for the text table; blank if missing."""
    return f"{value:{width}.7f}" if value is not None else " " * width


def print_table(leading, paper):
    """Our leading modes beside Gerl & Zippelius' values for the same (n, l)."""
    print(f"{'':31s}{'ours':>22s}   | {'Gerl & Zippelius' Table 1':>28s}")
    print(f"{'rank':>4s} {'(n,l)':>6s} {'family':>10s} {'omega':>8s}"
          f" {'average':>10s} {'after':>10s}   | {'rank':>6s} {'average':>10s} {'after':>10s}")
    for i, mode in enumerate(leading, 1):
        label = f"({mode['n']},{mode['l']})"
        paper_rank, paper_average, paper_after = paper.get((mode["n"], mode["l"]), ("", None, None))
        omega = f"{mode['omega']:8.4f}" if mode["omega"] is not None else " " * 8
        print(f"{i:4d} {label:>6s} {mode['family']:>10s} {omega}"
              f" {number(mode['average'])} {number(mode['after'])}   |"
              f" {paper_rank!s:>6s} {number(paper_average)} {number(paper_after)}")
    ours = {(m["n"], m["l"]) for m in leading}
    missing = [row for row in GERL_ZIPPELIUS_TABLE_1 if (row[1], row[2]) not in ours]
    for rank, n, l, average, after in missing:
        label = f"({n},{l})"
        print(f"{'-':>4s} {label:>6s} {'':>10s} {'':>8s} {'':>10s} {'':>10s}   |"
              f" {rank:6d} {number(average)} {number(after)}")


def plot(leading, paper, output, linear, title):
    """Bars per mode: ours (solid) and Gerl & Zippelius' (hatched), average and after."""
    labels = [(m["n"], m["l"]) for m in leading]
    labels += [(n, l) for _, n, l, _, _ in GERL_ZIPPELIUS_TABLE_1 if (n, l) not in labels]
    ours = {(m["n"], m["l"]): m for m in leading}
    width = 0.2
    fig, ax = plt.subplots(figsize=(max(8, 0.75 * len(labels)), 4.8))
    for x, label in enumerate(labels):
        mode = ours.get(label, {})
        _, paper_average, paper_after = paper.get(label, (None, None, None))
        bars = [(mode.get("average"), AVERAGE_COLOUR, None),
                (mode.get("after"), AFTER_COLOUR, None),
                (paper_average, AVERAGE_COLOUR, "//"),
                (paper_after, AFTER_COLOUR, "//")]
        for k, (value, colour, hatch) in enumerate(bars):
            if value is None or (not linear and value <= 0):
                continue
            ax.bar(x + (k - 1.5) * width, value, width,
                   color="white" if hatch else colour,
                   edgecolor=colour, hatch=hatch)
    ax.set_xticks(range(len(labels)))
    ax.set_xticklabels([f"({n},{l})" for n, l in labels])
    ax.set_xlabel("mode (n,l): our leading modes, then Gerl & Zippelius' other ones")
    ax.set_ylabel("fraction of the initial kinetic energy")
    if not linear:
        ax.set_yscale("log")
    ax.legend(handles=[
        Patch(color=AVERAGE_COLOUR, label="average during collision"),
        Patch(color=AFTER_COLOUR, label="after collision"),
        Patch(facecolor="white", edgecolor="k", hatch="//",
              label="Gerl & Zippelius' Table 1 (s = 500, v = 0.1c, 1600 modes)"),
    ], fontsize=8)
    ax.set_title(title, fontsize=10)
    ax.grid(alpha=0.3, axis="y", which="both")
    fig.tight_layout()
    fig.savefig(output, dpi=150)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("directory",
                        help="output directory holding mode_energies.csv, or a CSV file")
    parser.add_argument("--nu2", type=float)
    parser.add_argument("--velocity", type=float)
    parser.add_argument("--stiffness", type=float,
                        help="the wall potential's stiffness s (column potential_stiffness)")
    parser.add_argument("-o", "--output",
                        help="output PNG (default: mode_energies.png in the directory)")
    parser.add_argument("--count", type=int, default=10, help="number of modes (default 10)")
    parser.add_argument("--linear", action="store_true", help="linear instead of log energy axis")
    args = parser.parse_args()
    is_file = args.directory.endswith(".csv")
    folder = os.path.dirname(args.directory) if is_file else args.directory
    output = args.output or os.path.join(folder, "mode_energies.png")
    where = {column: value for column, value in (("poisson_ratio_2d", args.nu2),
                                                 ("velocity", args.velocity),
                                                 ("potential_stiffness", args.stiffness))
             if value is not None}
    source = args.directory if is_file else os.path.join(args.directory, "mode_energies.csv")
    modes, has_average = read_modes(source, where)
    key = "average" if has_average else "after"
    leading = leading_modes(modes, key, args.count)
    ranked_by = "average during collision" if has_average else "energy after collision"
    print(f"{len(leading)} of {len(modes)} elastic modes, ranked by {ranked_by}")
    print_table(leading, table_1_by_label())
    plot(leading, table_1_by_label(), output, args.linear,
         f"{len(leading)} leading modes by {ranked_by} (solid) beside Gerl & Zippelius' Table 1 (hatched)")
    print(f"wrote {output}")


if __name__ == "__main__":
    main()
