#!/usr/bin/python3
"""The result files of task 'impact' agree with each other and with physics.

- impact.h5 holds the time series of impact.csv, the summary, the mode
  energies and the final state;
- the vibration energy found in the projected modes after the impact is at
  most the energy the translation lost, 1 - epsilon^2 (the modes are
  M-orthonormal, so their energies add);
- the mode carrying most energy during the collision is (n, l) = (TOP);
- with --revolved (a sphere's 'Revolved view'), impact_3d.pvd lists the
  times of impact.pvd and every file it names is there, with its pieces.

usage: check_impact_outputs.py OUTPUT_DIR --top N L [--revolved]
"""
import argparse
import csv
import math
import os
import re
import sys

import h5py
import numpy


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("directory")
    parser.add_argument("--top", type=int, nargs=2, required=True)
    parser.add_argument("--revolved", action="store_true")
    args = parser.parse_args()

    series = list(csv.DictReader(open(f"{args.directory}/impact.csv")))
    summary = next(csv.DictReader(open(f"{args.directory}/summary.csv")))
    modes = list(csv.DictReader(open(f"{args.directory}/mode_energies.csv")))
    ok = True
    with h5py.File(f"{args.directory}/impact.h5", "r") as f:
        for name in ("time", "v_com", "contact_force", "energy_total"):
            column = numpy.array([float(row[name]) for row in series])
            if not numpy.array_equal(column, f["time_series"][name][:]):
                print(f"FAIL: impact.h5 time_series/{name} differs from impact.csv")
                ok = False
        if f["summary"]["epsilon"][0] != float(summary["epsilon"]):
            print("FAIL: impact.h5 summary/epsilon differs from summary.csv")
            ok = False
        n_dofs = int(summary["n_dofs"])
        for name in ("displacement", "velocity"):
            if f["final_state"][name].shape != (n_dofs,):
                print(f"FAIL: final_state/{name} has not {n_dofs} entries")
                ok = False
        if len(f["mode_energies"]["energy_fraction"]) != len(modes):
            print("FAIL: impact.h5 mode_energies differs from mode_energies.csv")
            ok = False

    epsilon = float(summary["epsilon"])
    lost = 1.0 - epsilon**2
    in_modes = sum(float(row["energy_fraction"]) for row in modes)
    print(f"1 - epsilon^2 = {lost:.6f}, in the {len(modes)} modes: {in_modes:.6f}")
    if in_modes > lost * (1 + 1e-6):
        print("FAIL: the modes hold more energy than the translation lost")
        ok = False
    top = max(modes, key=lambda row: float(row["average_energy_fraction"]))
    print(f"largest average energy: ({top['n']},{top['l']}) "
          f"{float(top['average_energy_fraction']):.4f}")
    if (int(top["n"]), int(top["l"])) != tuple(args.top):
        print(f"FAIL: expected ({args.top[0]},{args.top[1]}) on top")
        ok = False
    if args.revolved:
        ok = check_revolved_view(args.directory) and ok
    print("OK" if ok else "FAILED")
    sys.exit(0 if ok else 1)


def pvd_records(filename):
    """(time, file) of each DataSet of a .pvd collection."""
    text = open(filename).read()
    return [(float(t), f) for t, f in re.findall(
        r'timestep="([^"]+)"[^>]*file="([^"]+)"', text)]


def check_revolved_view(directory):
    """impact_3d.pvd: the times of impact.pvd, and its files complete."""
    flat = pvd_records(f"{directory}/impact.pvd")
    revolved = pvd_records(f"{directory}/impact_3d.pvd")
    ok = [t for t, _ in flat] == [t for t, _ in revolved] and len(flat) > 1
    if not ok:
        print("FAIL: impact_3d.pvd does not list the times of impact.pvd")
    for _, name in revolved:
        path = os.path.join(directory, name)
        pieces = re.findall(r'Source="([^"]+)"', open(path).read())
        missing = [piece for piece in pieces
                   if not os.path.getsize(os.path.join(directory, piece))]
        text = open(path).read()
        for field in ("displacement", "stress", "hoop_stress"):
            if f'Name="{field}"' not in text:
                print(f"FAIL: {name} has no field {field}")
                ok = False
        if not pieces or missing:
            print(f"FAIL: {name} misses pieces {missing}")
            ok = False
    print(f"revolved view: {len(revolved)} states")
    return ok


if __name__ == "__main__":
    main()
