#!/usr/bin/python3
"""The finite-size correction of Hertz's law for a sphere pressed on a rigid
wall by a uniform body force (docs/theory/sphere-finite-size.md).

Hertz's half-space theory gives the approach delta_H = a^2 / R,
a^3 = 3 P R / (4 E*). A finite sphere adds a term of relative order a/R;
diskimpact (task 'quasistatic contact', Body = sphere) reports it as

    D = (delta - delta_H) E* R / P

for the approach of the centre of mass (D_com) and the shortening of the
axial diameter (D_diameter). D is not constant: it drifts with ln(a/R), the
signature of the curvature of the surface around the contact (the
Boussinesq stresses of the contact force, ~P/rho^2, load the curved surface
with tractions ~P/(rho R), which displace the contact region by
~P/(E R) ln(R/a)). The script fits

    D(a) = D0 + D1 ln(a/R)

over a/R = 0.0025, 0.005, 0.01, 0.02 for each Poisson ratio, both with D1
free and with D1 fixed at its derived value
(docs/theory/sphere-finite-size.md)

    D1 = -(1 - 2 nu)^2 / (2 pi (1 - nu)),

which leaves D0 the only fitted constant.

Per material, runs at n = 16 and 32 elements across the contact radius
(grading 0.3) with penalty factors kappa = 400 and 1600, and one run at
n = 16 with grading 0.15 (kappa = 1600). Reported: D at n = 32 extrapolated
linearly in 1/kappa, fitted; each fitted constant's uncertainty is the sum of
  mesh:    its change between n = 16 and n = 32 (both extrapolated in kappa),
  grading: its change between grading 0.3 and 0.15 at n = 16, kappa = 1600,
  penalty: the size of the 1/kappa extrapolation at n = 32,
  form:    its change when a term linear in a/R is added to the fit.
Newton tolerance 1e-9 (1e-10 lies below the residual's round-off at the
smallest load).

usage: sphere_contact_study.py [--diskimpact build/diskimpact] [-o DIR]
                               [--poisson-ratios 0,0.3,0.45]
"""
import argparse
import csv
import math
import os
import re
import subprocess
import time

import numpy as np

CONTACT_RADII = [0.0025, 0.005, 0.01, 0.02]   # a / R
CONSTANTS = ("D_com", "D_diameter")

PRM = """set Task = quasistatic contact
set Output directory = {out}
subsection Geometry
  set Body = sphere
  set Global refinements = 2
end
subsection Material
  set Poisson ratio = {nu}
end
subsection Finite element
  set Degree = 2
end
subsection Contact
  set Penalty factor = {kappa}
end
subsection Quasistatic contact
  set Loads = {loads}
  set Elements across contact = {n}
  set Grading = {grading}
  set Newton tolerance = 1e-9
end
"""


def load_of(radius):
    """x = P / (pi E* R^2) of Hertz's contact radius a / R."""
    return 4.0 * radius ** 3 / (3.0 * math.pi)


def run(diskimpact, directory, nu, kappa, n, grading):
    """D_com and D_diameter (arrays over CONTACT_RADII) of one run, and the
    derived D0 of both (printed by the run,
    docs/theory/sphere-finite-size.md)."""
    name = f"nu{nu}_k{kappa:g}_n{n}_g{grading}"
    out = os.path.join(directory, name)
    prm = os.path.join(directory, name + ".prm")
    with open(prm, "w") as f:
        f.write(PRM.format(out=out, nu=nu, kappa=kappa, n=n, grading=grading,
                           loads=", ".join(f"{load_of(a):.16e}"
                                           for a in CONTACT_RADII)))
    log = subprocess.run([diskimpact, prm], check=True, capture_output=True,
                         text=True).stdout
    with open(os.path.join(out, "contact_law.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    rows.sort(key=lambda r: float(r["load"]))
    values = {c: np.array([float(r[c]) for r in rows]) for c in CONSTANTS}
    line = re.search(r"D0 = (\S+) \(com\), (\S+) \(diameter\)", log)
    values["derived"] = {"D_com": float(line.group(1)),
                         "D_diameter": float(line.group(2))}
    return values


def derived_log_coefficient(nu):
    """D1 of the first-order curvature correction of Boussinesq's field."""
    return -(1.0 - 2.0 * nu) ** 2 / (2.0 * math.pi * (1.0 - nu))


def fit(values, with_linear=False, fixed_log=None):
    """(D0, D1) of D = D0 + D1 ln(a/R) [+ D2 a/R], least squares; with
    fixed_log, D1 is that value and only D0 [and D2] are fitted."""
    a = np.array(CONTACT_RADII)
    if fixed_log is not None:
        values = values - fixed_log * np.log(a)
    columns = ([np.ones_like(a)] + ([] if fixed_log is not None
                                    else [np.log(a)])
               + ([a] if with_linear else []))
    coefficients = np.linalg.lstsq(np.column_stack(columns), values,
                                   rcond=None)[0]
    if fixed_log is not None:
        return np.array([coefficients[0], fixed_log])
    return coefficients[:2]


def extrapolated(coarse, fine):
    """Linear in 1/kappa from kappa = 400 and 1600 to kappa -> infinity."""
    return fine + (fine - coarse) / 3.0


def study(diskimpact, directory, nu):
    runs = {(k, n, g): run(diskimpact, directory, nu, k, n, g)
            for k, n, g in [(400, 16, 0.3), (1600, 16, 0.3), (400, 32, 0.3),
                            (1600, 32, 0.3), (1600, 16, 0.15)]}
    result = {}
    derived = runs[(400, 16, 0.3)]["derived"]
    for c in CONSTANTS:
        best = extrapolated(runs[(400, 32, 0.3)][c], runs[(1600, 32, 0.3)][c])
        coarse = extrapolated(runs[(400, 16, 0.3)][c], runs[(1600, 16, 0.3)][c])
        # the bar of D itself at each a: mesh, grading and penalty parts
        bar = (np.abs(best - coarse)
               + np.abs(runs[(1600, 16, 0.15)][c] - runs[(1600, 16, 0.3)][c])
               + np.abs(best - runs[(1600, 32, 0.3)][c]))
        for fixed in (None, derived_log_coefficient(nu)):
            def fitted(values, with_linear=False):
                return fit(values, with_linear, fixed)
            value = fitted(best)
            parts = {
                "mesh": np.abs(value - fitted(coarse)),
                "grading": np.abs(fitted(runs[(1600, 16, 0.15)][c])
                                  - fitted(runs[(1600, 16, 0.3)][c])),
                "penalty": np.abs(value - fitted(runs[(1600, 32, 0.3)][c])),
                "form": np.abs(value - fitted(best, with_linear=True)),
            }
            residual = best - (value[0] + value[1] * np.log(CONTACT_RADII))
            result[(c, fixed is not None)] = (value, sum(parts.values()),
                                              parts, best, residual, bar,
                                              derived[c])
    return result


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--diskimpact", default="build/diskimpact")
    p.add_argument("-o", "--output", default="output/sphere_contact_study")
    p.add_argument("--poisson-ratios", default="0,0.3,0.45")
    a = p.parse_args()
    os.makedirs(a.output, exist_ok=True)
    start = time.time()
    table = []
    for nu in [float(v) for v in a.poisson_ratios.split(",")]:
        result = study(os.path.abspath(a.diskimpact), a.output, nu)
        print(f"nu = {nu:4.2f}  derived D1 = "
              f"{derived_log_coefficient(nu): .5f}")
        for (c, fixed), (value, error, parts, best, residual, bar,
                         closed_form) in result.items():
            label = "D1 derived" if fixed else "D1 fitted "
            print(f"  {c:10s} {label}  D0 = {value[0]: .4f} +- "
                  f"{error[0]:.4f}   D1 = {value[1]: .5f}" +
                  ("" if fixed else f" +- {error[1]:.5f}"))
            if fixed:
                print(f"    derived D0 = {closed_form: .6f}: measured - "
                      f"derived = {value[0] - closed_form: .1e}")
            print("    error parts (D0, D1): " + ", ".join(
                f"{k} {v[0]:.1e} {v[1]:.1e}" for k, v in parts.items())
                + "; fit residuals " + ", ".join(f"{v:.1e}" for v in residual))
            if not fixed:
                print("    D(a/R = " + ", ".join(f"{r:g}" for r in
                                                CONTACT_RADII)
                      + ") = " + ", ".join(f"{v:.5f}" for v in best)
                      + " +- " + ", ".join(f"{v:.1e}" for v in bar)
                      + " (relative " + ", ".join(
                          f"{b / abs(v):.1%}" for b, v in zip(bar, best))
                      + ")")
            table.append([nu, c, "derived" if fixed else "fitted", value[0],
                          error[0], value[1], 0.0 if fixed else error[1],
                          closed_form])
    with open(os.path.join(a.output, "sphere_contact_constants.csv"), "w",
              newline="") as f:
        w = csv.writer(f)
        w.writerow(["poisson_ratio", "constant", "D1_source", "D0",
                    "D0_error", "D1", "D1_error", "D0_derived"])
        w.writerows(table)
    print(f"wrote {a.output}/sphere_contact_constants.csv "
          f"({time.time() - start:.0f} s)")


if __name__ == "__main__":
    main()
