#!/usr/bin/env python3
"""Check an impact run with 'Grade for measured contact' (summary.csv)
against the same impact on the mesh graded for Hertz's half-width: its mesh
is graded for that run's largest contact half-width, which is wider than
Hertz's; it has more DoFs; and its own largest half-width lies within two
of its contact elements of the width it is graded for.

Usage: check_measured_grading.py MEASURED_SUMMARY HERTZ_SUMMARY ELEMENTS
(ELEMENTS: 'Elements across contact' of the Hertz-graded run)
"""
import argparse
import sys

from check_plastic_solvers import read_row


def read_numbers(path):
    """The one row of summary.csv @p path, its filled columns as numbers."""
    return {k: float(v) for k, v in read_row(path).items() if v != ""}


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("measured")
    p.add_argument("hertz")
    p.add_argument("elements", type=int)
    args = p.parse_args()
    measured, hertz = read_numbers(args.measured), read_numbers(args.hertz)
    a_hertz = hertz["graded_half_width"]
    a_max = hertz["contact_half_width_max"]
    graded = measured["graded_half_width"]
    # The element count of the measured grading (the nearest even one).
    elements = 2 * max(2, round(0.5 * args.elements * a_max / a_hertz))
    failures = []
    if abs(graded - a_max) > 1e-12 * a_max:
        failures.append(f"graded for {graded:.12g} R, not the Hertz-graded "
                        f"run's largest half-width {a_max:.12g} R")
    if not a_max > 1.05 * a_hertz:
        failures.append(f"the plastic contact ({a_max:.6g} R) is not wider "
                        f"than Hertz's ({a_hertz:.6g} R)")
    if not measured["n_dofs"] > hertz["n_dofs"]:
        failures.append(f"{measured['n_dofs']:.0f} DoFs, not more than the "
                        f"Hertz-graded mesh's {hertz['n_dofs']:.0f}")
    own = measured["contact_half_width_max"]
    if abs(own - graded) > 2. * graded / elements:
        failures.append(f"largest half-width {own:.6g} R, more than two "
                        f"elements ({elements} across) from {graded:.6g} R")
    print(f"Hertz {a_hertz:.6g} R, measured {a_max:.6g} R "
          f"({a_max / a_hertz:.4f} times), {elements} elements; on the "
          f"regraded mesh {own:.6g} R; DoFs {hertz['n_dofs']:.0f} -> "
          f"{measured['n_dofs']:.0f}; epsilon {hertz['epsilon']:.8f} -> "
          f"{measured['epsilon']:.8f}")
    if failures:
        sys.exit("\n".join(failures))


if __name__ == "__main__":
    main()
