#!/usr/bin/python3
"""The constants C_com and C_diameter of the contact law
delta = P/(pi E2) [ln(4 pi R E2 / P) + C] as the load goes to zero, with
error bars from penalty, mesh and load convergence.

For each material it runs diskimpact (task 'quasistatic contact') with
penalty factors kappa = 100, 400, 1600 and extrapolates C linearly in
1/kappa (the penalty error is proportional to 1/kappa); it does so with 16
and 32 elements across the contact half-width, at loads 1e-6 and 1e-5, and
once more with one more global refinement (far field). Reported: the
kappa -> infinity value at 32 elements and load 1e-6; its uncertainty is the
sum of |32 - 16 elements|, |load 1e-6 - 1e-5|, |far field refined - not| and
the largest residual of the 1/kappa fits.

usage: contact_constant_study.py [--diskimpact build/diskimpact] [-o DIR]
"""
import argparse
import csv
import os
import subprocess

import numpy as np

MATERIALS = [("plane strain", 0.0), ("plane strain", 0.1), ("plane strain", 0.2),
             ("plane strain", 0.3), ("plane strain", 0.45), ("plane stress", 0.33)]
KAPPAS = [100.0, 400.0, 1600.0]
LOADS = [1e-6, 1e-5]

PRM = """set Task = quasistatic contact
set Output directory = {out}
subsection Geometry
  set Domain = half disk
  set Global refinements = {refinements}
end
subsection Material
  set Plane model = {model}
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
  set Elements across contact = {n_across}
end
"""


def run(exe, work, **p):
    name = "_".join(str(v).replace(" ", "") for v in p.values())
    out = os.path.join(work, name)
    prm = out + ".prm"
    with open(prm, "w") as f:
        f.write(PRM.format(out=out, loads=", ".join(map(str, LOADS)), **p))
    subprocess.run([exe, prm], check=True, stdout=subprocess.DEVNULL)
    rows = list(csv.DictReader(open(os.path.join(out, "contact_law.csv"))))
    return {float(r["load"]): (float(r["C_com"]), float(r["C_diameter"]),
                               float(r["poisson_ratio_2d"])) for r in rows}


def extrapolate(values):
    """C(kappa) = C_inf + b / kappa by least squares; (C_inf, max residual)."""
    x = 1.0 / np.array(KAPPAS)
    b, c_inf = np.polyfit(x, values, 1)
    return c_inf, np.max(np.abs(values - (c_inf + b * x)))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--diskimpact", default="build/diskimpact")
    parser.add_argument("-o", "--output", default="output/contact_constants")
    a = parser.parse_args()
    os.makedirs(a.output, exist_ok=True)
    exe = os.path.abspath(a.diskimpact)

    table = []
    for model, nu in MATERIALS:
        runs = {(n, k): run(exe, a.output, model=model, nu=nu, kappa=k,
                            n_across=n, refinements=2)
                for n in (16, 32) for k in KAPPAS}
        far = run(exe, a.output, model=model, nu=nu, kappa=KAPPAS[1],
                  n_across=16, refinements=3)
        nu2 = runs[(32, KAPPAS[0])][LOADS[0]][2]
        for which, name in ((0, "C_com"), (1, "C_diameter")):
            fit = {(n, load): extrapolate(np.array(
                       [runs[(n, k)][load][which] for k in KAPPAS]))
                   for n in (16, 32) for load in LOADS}
            value, residual = fit[(32, LOADS[0])]
            mesh = abs(value - fit[(16, LOADS[0])][0])
            load = abs(value - fit[(32, LOADS[1])][0])
            far_field = abs(far[LOADS[0]][which] - runs[(16, KAPPAS[1])][LOADS[0]][which])
            fit_residual = max(r for _, r in fit.values())
            error = mesh + load + far_field + fit_residual
            slope = [runs[(32, k)][LOADS[0]][which] for k in KAPPAS]
            table.append(dict(model=model, nu=nu, nu2=nu2, constant=name,
                              value=value, uncertainty=error, mesh=mesh,
                              load=load, far_field=far_field,
                              fit_residual=fit_residual,
                              kappa_100=slope[0], kappa_400=slope[1],
                              kappa_1600=slope[2], printed=-1 - nu2))
            print(f"{model:12s} nu={nu:<5} nu2={nu2:.4f} {name:10s} "
                  f"{value:+.5f} +- {error:.1e} (mesh {mesh:.1e}, load {load:.1e}, "
                  f"far field {far_field:.1e}, 1/kappa fit {fit_residual:.1e}; "
                  f"kappa 100/400/1600: {slope[0]:+.5f} {slope[1]:+.5f} "
                  f"{slope[2]:+.5f}); printed -1-nu2 = {-1 - nu2:+.5f}",
                  flush=True)

    path = os.path.join(a.output, "contact_constants.csv")
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(table[0]))
        w.writeheader()
        w.writerows(table)
    print("wrote", path)


if __name__ == "__main__":
    main()
