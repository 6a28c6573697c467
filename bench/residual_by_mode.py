#!/usr/bin/python3
"""Split what a smooth fit in v leaves of the modal expansion's epsilon(v)
among the disk's modes. After the collision the disk keeps
1 - epsilon^2 of its kinetic energy in vibration, so a change dE_k of mode
k's energy fraction moves epsilon by -dE_k / (2 epsilon). For every mode
listed at every speed in modal_expansion_modes.csv, that part of its energy
is fitted like epsilon (degree 6 in v); the script prints each mode's share
of epsilon's residual (least-squares factor), its correlation with it, and
the same for the sum over these modes (docs/theory/impact-accuracy.md, "ε on
one mesh: the rough part").

usage: bench/residual_by_mode.py DIRECTORY [--fit-degree 6] [--most 10]
       (DIRECTORY: the output of a 'modal expansion impact' run of one
        potential stiffness and one mode count, 'Number of listed modes' = 100)
"""
import argparse
import collections
import csv
import os
import sys

import numpy as np

from residual_correlation import read_table, residual


def read_rows(path):
    try:
        with open(path, newline="") as f:
            return list(csv.DictReader(f))
    except OSError as error:
        sys.exit(f"residual_by_mode: cannot read {path}: {error.strerror}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("directory")
    parser.add_argument("--fit-degree", type=int, default=6)
    parser.add_argument("--most", type=int, default=10,
                        help="modes printed, largest share first")
    args = parser.parse_args()
    epsilon = read_table(os.path.join(args.directory, "modal_expansion.csv"))
    speeds = np.array(sorted(epsilon))
    if len(speeds) < args.fit_degree + 2:
        sys.exit(f"residual_by_mode: {len(speeds)} speeds are too few")
    eps = np.array([epsilon[v] for v in speeds])
    energies = collections.defaultdict(dict)
    for r in read_rows(os.path.join(args.directory, "modal_expansion_modes.csv")):
        label = f"({r['n']}, {r['l']}) {r['family']}, omega {float(r['omega']):.3f}"
        energies[label][round(float(r["velocity"]), 9)] = float(r["energy_fraction"])

    target = residual(epsilon, speeds, args.fit_degree)
    parts = {label: -residual(e, speeds, args.fit_degree) / (2. * eps)
             for label, e in energies.items() if all(v in e for v in speeds)}
    if not parts:
        sys.exit("residual_by_mode: no mode is listed at every speed")
    share = {label: p @ target / (target @ target) for label, p in parts.items()}
    total = sum(parts.values())
    print(f"{len(speeds)} speeds; epsilon's residual rms {target.std():.2e}; "
          f"{len(parts)} modes listed at every speed: together a share "
          f"{total @ target / (target @ target):.2f}, correlation "
          f"{np.corrcoef(total, target)[0, 1]:+.2f}")
    for label in sorted(share, key=lambda k: -abs(share[k]))[:args.most]:
        print(f"  mode {label}: share {share[label]:+.3f}, correlation "
              f"{np.corrcoef(parts[label], target)[0, 1]:+.2f}")


if __name__ == "__main__":
    main()
