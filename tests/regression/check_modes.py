#!/usr/bin/python3
"""Assertions on the result files of task 'modal analysis'.

usage: check_modes.py OUTPUT_DIR [--rigid N] [--orientations 1|2]
                      [--max-error E] [--first K] [--analytic-order]
                      [--z-parity] [--torsional]

--torsional checks a sphere's torsional_modes.csv (against
torsional_analytic_modes.csv; z-parity (-1)^(n-1)) instead of modes.csv.
"""
import argparse
import csv
import sys


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("output_dir")
    p.add_argument("--rigid", type=int, help="expected number of rigid modes")
    p.add_argument("--orientations", type=int, choices=(1, 2),
                   help="times each n >= 1 label must appear")
    p.add_argument("--max-error", type=float,
                   help="bound on |omega/omega_exact - 1| of elastic modes")
    p.add_argument("--first", type=int,
                   help="apply --max-error to the first K elastic modes only")
    p.add_argument("--analytic-order", action="store_true",
                   help="labels must follow analytic_modes.csv")
    p.add_argument("--z-parity", action="store_true",
                   help="sphere: the measured z_parity of each elastic mode "
                   "must be (-1)^n")
    p.add_argument("--torsional", action="store_true",
                   help="check torsional_modes.csv (sphere) instead")
    a = p.parse_args()

    prefix = "torsional_" if a.torsional else ""
    modes = read(a.output_dir + f"/{prefix}modes.csv")
    failures = []
    rigid = [m for m in modes if m["family"] == "rigid"]
    elastic = [m for m in modes if m["family"] != "rigid"]
    if modes[: len(rigid)] != rigid:
        failures.append("rigid modes are not the lowest")
    if a.rigid is not None and len(rigid) != a.rigid:
        failures.append(f"{len(rigid)} rigid modes, expected {a.rigid}")

    label = lambda m: (m["n"], m["l"], m["family"])
    if a.orientations:
        labels = [label(m) for m in elastic]
        for lab in set(labels):
            want = 1 if lab[0] == "0" else a.orientations
            # the highest label may lack its partner
            if labels.count(lab) != want and lab != labels[-1]:
                failures.append(f"label {lab} appears {labels.count(lab)} "
                                f"times, expected {want}")

    if a.max_error is not None:
        checked = elastic[: a.first] if a.first else elastic
        worst = max(abs(float(m["relative_error"])) for m in checked)
        print(f"largest |relative error| of {len(checked)} elastic modes: "
              f"{worst:.3e} (bound {a.max_error:.1e})")
        if not worst <= a.max_error:
            failures.append(f"relative error {worst:.3e} > {a.max_error:.1e}")

    if a.analytic_order:
        analytic = read(a.output_dir + f"/{prefix}analytic_modes.csv")
        if len(analytic) < len(elastic):
            failures.append(f"{len(analytic)} analytic modes for "
                            f"{len(elastic)} computed ones")
        for i, (m, ref) in enumerate(zip(elastic, analytic)):
            if label(m) != label(ref):
                failures.append(f"elastic mode {i}: label {label(m)}, "
                                f"analytic ordering has {label(ref)}")

    if a.z_parity:
        for i, m in enumerate(elastic):
            # spheroidal u_r ~ P_n: (-1)^n; torsional u_phi ~ P_n^1: (-1)^(n-1)
            even = (int(m["n"]) + (1 if a.torsional else 0)) % 2 == 0
            want = "even" if even else "odd"
            if m.get("z_parity") != want:
                failures.append(f"elastic mode {i} {label(m)}: z_parity "
                                f"{m.get('z_parity')}, expected {want}")

    for f in failures:
        print("FAIL:", f)
    if not failures:
        print(f"OK: {len(rigid)} rigid + {len(elastic)} elastic modes")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
