#!/usr/bin/python3
"""Compare what a smooth fit in v leaves of epsilon(v) in several tables with
what it leaves in the first one, the reference. A table is a -o table of
bench/fixed_mesh_scan.py or a modal_expansion.csv of one potential stiffness
and one mode count (the 'modal expansion impact' task); both have the columns
velocity and epsilon. On the speeds that all tables share, each table's
residual from a degree-6 fit in v is compared with the reference's: their
correlation, the reference's shape's amplitude in it (the least-squares
factor) and the rms left once that shape is removed
(docs/theory/impact-accuracy.md, "ε on one mesh: the rough part").

usage: bench/residual_correlation.py REFERENCE.csv TABLE.csv [TABLE.csv ...]
           [--fit-degree 6]
"""
import argparse
import csv
import sys

import numpy as np


def read_table(path):
    """Speeds (rounded to 1e-9, so that tables can be matched) and epsilon."""
    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as error:
        sys.exit(f"residual_correlation: cannot read {path}: {error.strerror}")
    if not rows or not {"velocity", "epsilon"} <= set(rows[0]):
        sys.exit(f"residual_correlation: {path} has no rows with the columns "
                 "velocity and epsilon")
    for column in ("potential_stiffness", "n_modes"):
        if column in rows[0] and len({r[column] for r in rows}) > 1:
            sys.exit(f"residual_correlation: {path} holds several values of "
                     f"{column}; give a table of one")
    return {round(float(r["velocity"]), 9): float(r["epsilon"]) for r in rows}


def residual(table, speeds, degree):
    eps = np.array([table[v] for v in speeds])
    return eps - np.polynomial.Polynomial.fit(speeds, eps, degree)(speeds)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("reference")
    parser.add_argument("tables", nargs="+")
    parser.add_argument("--fit-degree", type=int, default=6)
    args = parser.parse_args()
    tables = [read_table(p) for p in [args.reference] + args.tables]
    speeds = np.array(sorted(set.intersection(*(set(t) for t in tables))))
    if len(speeds) < args.fit_degree + 2:
        sys.exit(f"residual_correlation: the tables share {len(speeds)} speeds, "
                 f"too few for a degree-{args.fit_degree} fit")
    reference = residual(tables[0], speeds, args.fit_degree)
    print(f"{len(speeds)} common speeds {speeds[0]:.9g} ... {speeds[-1]:.9g}; "
          f"reference {args.reference}: residual rms {reference.std():.2e}")
    for path, table in zip(args.tables, tables[1:]):
        r = residual(table, speeds, args.fit_degree)
        amplitude = r @ reference / (reference @ reference)
        print(f"  {path}: residual rms {r.std():.2e}, correlation "
              f"{np.corrcoef(r, reference)[0, 1]:+.2f}, amplitude of the "
              f"reference's shape {amplitude:+.2f}, rms without it "
              f"{(r - amplitude * reference).std():.2e}")


if __name__ == "__main__":
    main()
