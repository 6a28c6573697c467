#!/usr/bin/python3
"""The constants C_com and C_diameter of the contact law
delta = P/(pi E2) [ln(4 pi R E2 / P) + C] as the load goes to zero, with
error bars, against the exact constants C_com = -2 ln 2 - (1 + nu2)/4 and
C_diameter = -1 (docs/theory/disk-contact-constants.md).

First it checks the derivation numerically (the stress field is traction
free and in equilibrium, the displacement field has its strain, and the
quadratures of the mean and contact displacements give the constants).

Then, for each material, it runs diskimpact (task 'quasistatic contact') at
two loads x and 4x chosen so that the Hertz half-width a is exactly 1.5 n
contact elements (n = 'Elements across contact'): the contact edge sits on
a mesh node for every n, and the mesh error is a smooth function of n instead
of oscillating with the edge's position inside an element (up to 1e-4 at
n = 32 otherwise). Runs: n = 16 and 32 at grading 0.075 with penalty factors
kappa = 400, 1600, 6400, and n = 16 at grading 0.0375 (kappa = 6400, load x).

Reported: the value at n = 32, grading 0.075, extrapolated linearly in
1/kappa to kappa -> infinity and linearly in the load to x -> 0 (the drift is
C(x) = C(0) + 3.8x). Its uncertainty is the sum of
  mesh:    |value(n = 32) - value(n = 16)|,
  grading: |C(grading 0.0375) - C(grading 0.075)| at n = 16,
  penalty: the largest residual of the 1/kappa fits,
  load:    the size of the x -> 0 extrapolation itself.
The far field needs no extra run: at grading <= 0.075 one more global
refinement gives the same mesh. Newton tolerance 1e-9 (the default 1e-10
can lie below the round-off of the residual with 1e5 DoFs and kappa = 6400;
C changes by 1e-12 between the two).

usage: contact_constant_study.py [--diskimpact build/diskimpact] [-o DIR]
                                 [--derivation-only]
"""
import argparse
import csv
import math
import os
import subprocess
import time

import numpy as np
from scipy import integrate

MATERIALS = [("plane strain", 0.0), ("plane strain", 0.1), ("plane strain", 0.2),
             ("plane strain", 0.3), ("plane strain", 0.45), ("plane stress", 0.33)]
KAPPAS = [400.0, 1600.0, 6400.0]
MESHES = [16, 32]          # elements across the contact half-width
GRADING = 0.075            # growth of the element size away from the contact
FINE_GRADING = 0.0375      # the grading check
TARGET_LOAD = 1e-6         # x = P/(pi E2 R) near which the loads are chosen
CONSTANTS = ("C_com", "C_diameter")

# The numerical entries of every run of the study (also used by
# two_body_constant_study.py).
NUMERICS = """subsection Finite element
  set Degree = 2
end
subsection Contact
  set Penalty factor = {kappa}
end
subsection Quasistatic contact
  set Loads = {loads}
  set Elements across contact = {n_across}
  set Grading = {grading}
  set Newton tolerance = 1e-9
end
"""
PRM = """set Task = quasistatic contact
set Output directory = {out}
subsection Geometry
  set Domain = half disk
  set Global refinements = 2
end
subsection Material
  set Plane model = {model}
  set Poisson ratio = {nu}
end
""" + NUMERICS


def exact_constants(nu2):
    """The derived constants (docs/theory/disk-contact-constants.md)."""
    return {"C_com": -2.0 * math.log(2.0) - (1.0 + nu2) / 4.0, "C_diameter": -1.0}


# --- the derivation, checked numerically ----------------------------------
# Units R = E2 = P = 1, origin at the contact point A, centre (1, 0), far end
# of the diameter B = (2, 0); body force 1/pi per area toward the wall (-x).

def _stress(x, y):
    """Flamant's point force at A + uniform tension 1/(2 pi) + the
    body-force field (rho g / 2)[[xi, y], [y, -xi]], xi = x - 1."""
    r, th = math.hypot(x, y), math.atan2(y, x)
    e = np.array([math.cos(th), math.sin(th)])
    s = -(2 / math.pi) * math.cos(th) / r * np.outer(e, e)
    s += np.eye(2) / (2 * math.pi)
    s += np.array([[x - 1, y], [y, 1 - x]]) / (2 * math.pi)
    return s


def _smooth_displacement(x, y, nu):
    c = (1 + nu) / (2 * math.pi)
    return np.array([(1 - nu) * (x - 1) / (2 * math.pi) + c * ((x - 1) ** 2 + 3 * y * y) / 2,
                     (1 - nu) * y / (2 * math.pi) - c * (x - 1) * y])


def _displacement(x, y, nu):
    r, th = math.hypot(x, y), math.atan2(y, x)
    flamant = -np.array([2 * math.log(r) + (1 + nu) * math.sin(th) ** 2,
                         (1 - nu) * th - (1 + nu) * math.sin(th) * math.cos(th)]) / math.pi
    return flamant + _smooth_displacement(x, y, nu)


def derivation_check(nu2_values=(0.0, 0.33, 9 / 11)):
    """Largest defects of the field and the constants by quadrature."""
    traction = max(np.abs(_stress(1 + math.cos(p), math.sin(p))
                          @ np.array([math.cos(p), math.sin(p)])).max()
                   for p in np.linspace(-3.1, 3.1, 25))
    h = 1e-4

    def d(f, x, y, i):
        dx, dy = (h, 0) if i == 0 else (0, h)
        return (8 * (f(x + dx, y + dy) - f(x - dx, y - dy))
                - f(x + 2 * dx, y + 2 * dy) + f(x - 2 * dx, y - 2 * dy)) / (12 * h)

    equilibrium = hooke = 0.0
    rows = []
    for nu in nu2_values:
        for x, y in ((0.5, 0.2), (1.3, -0.4), (1.8, 0.1), (0.2, 0.05)):
            div = np.array([d(lambda a, b: _stress(a, b)[0, 0], x, y, 0)
                            + d(lambda a, b: _stress(a, b)[0, 1], x, y, 1),
                            d(lambda a, b: _stress(a, b)[0, 1], x, y, 0)
                            + d(lambda a, b: _stress(a, b)[1, 1], x, y, 1)])
            equilibrium = max(equilibrium, np.abs(div - [1 / math.pi, 0]).max())
            gx = d(lambda a, b: _displacement(a, b, nu), x, y, 0)
            gy = d(lambda a, b: _displacement(a, b, nu), x, y, 1)
            s = _stress(x, y)
            strain = (1 + nu) * s - nu * np.trace(s) * np.eye(2)
            hooke = max(hooke, abs(gx[0] - strain[0, 0]), abs(gy[1] - strain[1, 1]),
                        abs((gx[1] + gy[0]) / 2 - strain[0, 1]))
        # area mean of u_x, polar coordinates about A (u_x ~ ln r there)
        mean = integrate.dblquad(
            lambda r, th: r * _displacement(r * math.cos(th), r * math.sin(th), nu)[0],
            -math.pi / 2, math.pi / 2, 0, lambda th: 2 * math.cos(th),
            epsabs=1e-13, epsrel=1e-13)[0] / math.pi
        u_b = _displacement(2.0, 0.0, nu)[0]
        a = 1e-3  # Hertz half-width; the half-plane surface displacement
        u_a = 2 * integrate.quad(
            lambda t: 2 / (math.pi * a * a) * math.sqrt(a * a - t * t)
            * -(2 * math.log(t) + 1 + nu) / math.pi, 0, a, epsabs=1e-14, limit=200)[0]
        u_a += _smooth_displacement(0.0, 0.0, nu)[0]
        law = 2 * math.log(4 / a)
        rows.append((nu, math.pi * (u_a - mean) - law, math.pi * (u_a - u_b) - law,
                     _displacement(1.0, 0.0, nu)[0] - mean))
    return traction, equilibrium, hooke, rows


# --- the FE study ----------------------------------------------------------

def run(exe, work, loads, **p):
    name = "_".join(str(v).replace(" ", "") for v in p.values())
    out = os.path.join(work, name)
    prm = out + ".prm"
    with open(prm, "w") as f:
        f.write(PRM.format(out=out, loads=", ".join(repr(x) for x in loads), **p))
    subprocess.run([exe, prm], check=True, stdout=subprocess.DEVNULL)
    rows = list(csv.DictReader(open(os.path.join(out, "contact_law.csv"))))
    return [dict(C_com=float(r["C_com"]), C_diameter=float(r["C_diameter"]),
                 nu2=float(r["poisson_ratio_2d"]),
                 a_over_h=float(r["hertz_half_width"]) / float(r["h_contact"]))
            for r in rows]


def node_loads(exe, work):
    """Two loads x, 4x near TARGET_LOAD with a = 1.5 n h_contact exactly."""
    probe = run(exe, work, [TARGET_LOAD], model="plane strain", nu=0.3,
                kappa=KAPPAS[0], n_across=MESHES[0], grading=0.3)[0]
    h = 2.0 * math.sqrt(TARGET_LOAD) / probe["a_over_h"]  # h_contact / R
    x = (1.5 * MESHES[0] * h / 2.0) ** 2
    return [x, 4.0 * x]


def kappa_fit(values):
    """C(kappa) = C_inf + b / kappa by least squares: (C_inf, max residual)."""
    t = 1.0 / np.array(KAPPAS)
    b, c_inf = np.polyfit(t, values, 1)
    return c_inf, float(np.max(np.abs(values - (c_inf + b * t))))



def error_budget(runs, fine, name):
    """(value, parts) of the constant `name` from the runs of a study:
    runs[(n, kappa)] the rows at the two loads x and 4x per mesh and penalty,
    fine the row at the finer grading. value: 1/kappa fit per mesh and load,
    linear in the load to x -> 0, finest mesh; parts: its error bar's terms
    (mesh, grading, penalty fit, load extrapolation)."""
    fits = {(n, i): kappa_fit(np.array([runs[(n, k)][i][name] for k in KAPPAS]))
            for n in MESHES for i in range(2)}
    # linear in the load: C(0) = C(x) - (C(4x) - C(x)) / 3
    limit = {n: fits[(n, 0)][0] - (fits[(n, 1)][0] - fits[(n, 0)][0]) / 3.0
             for n in MESHES}
    value = limit[MESHES[-1]]
    return value, dict(
        mesh=abs(value - limit[MESHES[0]]),
        grading=abs(fine[name] - runs[(MESHES[0], KAPPAS[-1])][0][name]),
        penalty=max(r for _, r in fits.values()),
        load=abs(value - fits[(MESHES[-1], 0)][0]))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--diskimpact", default="build/diskimpact")
    parser.add_argument("-o", "--output", default="output/contact_constants")
    parser.add_argument("--derivation-only", action="store_true")
    a = parser.parse_args()
    start = time.time()

    traction, equilibrium, hooke, rows = derivation_check()
    print(f"derivation: traction on the circle {traction:.1e}, equilibrium "
          f"{equilibrium:.1e}, Hooke {hooke:.1e} (largest defects)")
    for nu2, c_com, c_dia, centre in rows:
        exact = exact_constants(nu2)
        print(f"  nu2 = {nu2:.4f}: quadrature C_com = {c_com:+.12f} "
              f"(exact {exact['C_com']:+.12f}), C_diameter = {c_dia:+.12f}; "
              f"u_x(centre) - mean u_x = {centre:+.1e} P/E2")
    if a.derivation_only:
        return

    os.makedirs(a.output, exist_ok=True)
    exe = os.path.abspath(a.diskimpact)
    loads = node_loads(exe, a.output)
    print(f"loads x = {loads[0]:.6e}, {loads[1]:.6e} (a = 1.5 n h_contact)")

    table = []
    for model, nu in MATERIALS:
        runs = {(n, k): run(exe, a.output, loads, model=model, nu=nu, kappa=k,
                            n_across=n, grading=GRADING)
                for n in MESHES for k in KAPPAS}
        fine = run(exe, a.output, loads[:1], model=model, nu=nu, kappa=KAPPAS[-1],
                   n_across=MESHES[0], grading=FINE_GRADING)[0]
        nu2 = runs[(MESHES[0], KAPPAS[0])][0]["nu2"]
        node = max(abs(r["a_over_h"] - 1.5 * n) for (n, _), rs in runs.items() for r in rs)
        if node > 1e-3:
            print(f"warning: a/h_contact differs from 1.5 n by {node:.1e}: the "
                  "contact edge is not on a node, the mesh term is unreliable")
        exact = exact_constants(nu2)
        for name in CONSTANTS:
            value, parts = error_budget(runs, fine, name)
            mesh, grading, penalty, load = (parts[k] for k in
                                            ("mesh", "grading", "penalty", "load"))
            error = sum(parts.values())
            table.append(dict(model=model, nu=nu, nu2=nu2, constant=name,
                              value=value, uncertainty=error, exact=exact[name],
                              deviation=value - exact[name], **parts,
                              a_over_h_offset=node))
            print(f"{model:12s} nu={nu:<5} nu2={nu2:.4f} {name:10s} "
                  f"{value:+.6f} +- {error:.1e} (mesh {mesh:.1e}, grading "
                  f"{grading:.1e}, 1/kappa fit {penalty:.1e}, load {load:.1e}); "
                  f"exact {exact[name]:+.6f}, difference {value - exact[name]:+.1e}",
                  flush=True)

    path = os.path.join(a.output, "contact_constants.csv")
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(table[0]))
        w.writeheader()
        w.writerows(table)
    print(f"wrote {path} ({time.time() - start:.0f} s)")


if __name__ == "__main__":
    main()
