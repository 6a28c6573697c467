#!/usr/bin/python3
"""Assertions on modes.csv of task 'modal analysis' with 'Dimension = 3'
(the whole sphere): six rigid modes first; every elastic mode labelled,
each multiplet of degree n with its 2n + 1 modes next to each other; the
multiplets in the order of Lamb's frequencies; the torsional frequencies
the roots of Lamb's equation (n - 1) j_n(xi) - xi j_{n+1}(xi) = 0,
xi = omega R / c_T, found here with scipy; every relative error to Lamb's
frequency below a bound; the mode shapes written (modes.pvd).

usage: check_solid_modes.py OUTPUT_DIR --max-error E [--c-t C] [--radius R]
"""
import argparse
import csv
import os
import sys

from scipy.optimize import brentq
from scipy.special import spherical_jn


def torsional_roots(n, xi_max):
    """Lamb's torsional roots of degree n below xi_max (xi = 0 excluded)."""
    f = lambda x: (n - 1) * spherical_jn(n, x) - x * spherical_jn(n + 1, x)
    roots, step, x = [], 1e-3, 1e-3
    while x < xi_max:
        if f(x) * f(x + step) < 0:
            roots.append(brentq(f, x, x + step, xtol=1e-14))
        x += step
    return roots


def main():
    p = argparse.ArgumentParser()
    p.add_argument("output_dir")
    p.add_argument("--max-error", type=float, required=True)
    p.add_argument("--c-t", type=float, default=(1 / (2 * 1.3)) ** 0.5,
                   help="transverse wave speed (default: E = rho = 1, nu = 0.3)")
    p.add_argument("--radius", type=float, default=1.)
    a = p.parse_args()

    with open(a.output_dir + "/modes.csv", newline="") as f:
        modes = list(csv.DictReader(f))
    failures = []
    if not os.path.exists(a.output_dir + "/modes.pvd"):
        failures.append("no modes.pvd (the mode shapes)")
    rigid = [m for m in modes if m["family"] == "rigid"]
    if len(rigid) != 6 or modes[:6] != rigid:
        failures.append(f"{len(rigid)} rigid modes, not the six lowest")
    elastic = modes[len(rigid):]
    i = 0
    previous_exact = 0.
    worst = 0.
    overtones = {}
    while i < len(elastic):
        m = elastic[i]
        if m["family"] == "unlabelled":
            failures.append(f"mode {m['index']} is not labelled")
            i += 1
            continue
        n, multiplicity = int(m["n"]), int(m["multiplicity"])
        if multiplicity != 2 * n + 1:
            failures.append(f"mode {m['index']}: multiplicity {multiplicity}, "
                            f"degree {n}")
        group = elastic[i:i + multiplicity]
        if any((g["n"], g["l"], g["family"]) != (m["n"], m["l"], m["family"])
               for g in group) or len(group) != multiplicity:
            failures.append(f"multiplet of mode {m['index']} is not contiguous")
        key = (m["family"], n)
        if int(m["l"]) != overtones.get(key, 0):
            failures.append(f"mode {m['index']}: overtone {m['l']}, expected "
                            f"{overtones.get(key, 0)}")
        overtones[key] = overtones.get(key, 0) + 1
        exact = float(m["omega_exact"])
        if exact < previous_exact:
            failures.append(f"mode {m['index']}: out of Lamb's order")
        previous_exact = exact
        if m["family"] == "torsional":
            xi = torsional_roots(n, exact * a.radius / a.c_t + 1.)
            mine = xi[int(m["l"])] * a.c_t / a.radius
            if abs(mine / exact - 1) > 1e-10:
                failures.append(f"mode {m['index']}: Lamb's torsional omega "
                                f"{mine:.12g} here, {exact:.12g} in modes.csv")
        for g in group:
            worst = max(worst, abs(float(g["relative_error"])))
        i += multiplicity
    print(f"{len(elastic)} elastic modes in {sum(overtones.values())} "
          f"multiplets; largest |relative error| {worst:.3e} "
          f"(bound {a.max_error:.1e})")
    if not worst <= a.max_error:
        failures.append(f"relative error {worst:.3e} > {a.max_error:.1e}")
    for failure in failures:
        print("FAIL:", failure)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
