#!/usr/bin/python3
"""Loading and unloading of an elastic-plastic sphere or plane-strain disk
(task 'quasistatic contact', von Mises, perfectly plastic, nu = 0.3)
refined to an error bar, on 2 MPI ranks.

For each largest load F/F_y (F_y Hertz's load of first yield, which
tests/regression/hertz_yield.py derives) the script runs the mesh sequence
of the impact convergence study: level l has 'Global refinements' + l and
'Elements across contact' x 2^l (the penalty stiffness kappa E2 / h grows
with it), and the second level again with twice the load steps (backward
Euler in the load: the path's error is of first order in the step, and
hardly depends on the mesh). It prints
per level and per quantity: the largest approach delta_max, the residual
indentation delta_res (centre of mass, at load 0), delta_res / delta_max,
the plastic work's share of the work done on the body, and the contact
half-width at the largest load (a / a_Hertz). The value is the finest
level's, its bar the grid convergence index of the impact study's rule
without extrapolation (docs/theory/impact-method.md): 3 |d| / (r - 1) for a
monotone sequence with 1 < r <= 4, else 3 max |d| (expected order 1),
plus the load-step difference (first order: the error of the finer path).

usage: bench/plastic_indentation.py [--body sphere|plane-strain]
           [--yield-strain Y/E] [--overloads 10,100] [--steps 40]
           [--levels 3] [--ranks 2]    (build first; ~30 minutes)
"""
import argparse
import csv
import math
import os
import sys
import tempfile

from diskimpact_run import run_diskimpact

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests",
                                "regression"))
from hertz_yield import first_yield_pressure_ratio  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--body", default="sphere",
                    choices=["sphere", "plane-strain"])
parser.add_argument("--yield-strain", type=float, default=0.002,
                    help="Y / E")
parser.add_argument("--overloads", default="10,100",
                    help="largest loads over the load of first yield")
parser.add_argument("--steps", type=int, default=40)
parser.add_argument("--levels", type=int, default=3)
parser.add_argument("--ranks", type=int, default=2)
parser.add_argument("--global-refinements", type=int, default=2)
parser.add_argument("--elements", type=int, default=10,
                    help="elements across the contact on the first level")
args = parser.parse_args()

nu = 0.3
ratio, _ = first_yield_pressure_ratio(args.body, nu)
p0 = ratio * args.yield_strain * (1 - nu * nu)  # over E* or E2
if args.body == "sphere":
    load_yield = math.pi ** 2 * p0 ** 3 / 6
else:
    load_yield = p0 ** 2


def hertz_half_width(load):
    if args.body == "sphere":
        return (3 * math.pi * load / 4) ** (1 / 3)
    return 2 * math.sqrt(load)


def run(work, load, level, steps):
    geometry = ("  set Body = sphere" if args.body == "sphere" else
                "  set Domain = half disk")
    plane = "" if args.body == "sphere" else "  set Plane model = plane strain"
    directory = os.path.join(work, f"l{load:.6e}_{level}_{steps}")
    prm = directory + ".prm"
    with open(prm, "w") as f:
        f.write(f"""set Task = quasistatic contact
set Output directory = {directory}
subsection Geometry
{geometry}
  set Global refinements = {args.global_refinements + level}
end
subsection Material
{plane}
  set Poisson ratio = {nu}
  set Yield stress = {args.yield_strain}
end
subsection Finite element
  set Degree = 2
end
subsection Contact
  set Penalty factor = 400
end
subsection Quasistatic contact
  set Loads = {load:.10e}
  set Elements across contact = {args.elements * 2 ** level}
  set Indentation steps = {steps}
  set Newton tolerance = 1e-9
end
""")
    seconds = run_diskimpact(prm, args.ranks)
    summary = next(csv.DictReader(
        open(os.path.join(directory, "indentation_summary.csv"))))
    rows = list(csv.DictReader(
        open(os.path.join(directory, "indentation.csv"))))
    top = max(rows, key=lambda r: float(r["load"]))
    delta_max = float(summary["delta_max"])
    residual = float(summary["residual_delta_com"])
    return {"delta_max": delta_max,
            "delta_res": residual,
            "delta_res/delta_max": residual / delta_max,
            "plastic work share": float(summary["plastic_work_fraction"]),
            "a/a_Hertz": float(top["half_width"]) / hertz_half_width(load),
            "dofs": int(summary["n_dofs"]),
            "seconds": seconds}


def bar(values):
    """The impact study's rule without extrapolation, expected order 1."""
    d = [b - a for a, b in zip(values, values[1:])]
    if len(d) >= 2 and d[-1] != 0 and d[-2] * d[-1] > 0:
        r = d[-2] / d[-1]
        if 1 < r <= 4:
            return 3 * abs(d[-1]) / (r - 1)
    return 3 * max(abs(x) for x in d[-2:])


quantities = ["delta_max", "delta_res", "delta_res/delta_max",
              "plastic work share", "a/a_Hertz"]
print(f"{args.body}, nu = {nu}, Y = {args.yield_strain} E, perfectly "
      f"plastic; Hertz's contact first yields at load {load_yield:.6e} "
      f"(p0/Y = {ratio:.5f}); {args.steps} load steps up and down")
with tempfile.TemporaryDirectory() as work:
    for overload in [float(x) for x in args.overloads.split(",")]:
        load = overload * load_yield
        levels = [run(work, load, level, args.steps)
                  for level in range(args.levels)]
        steps = run(work, load, 1, 2 * args.steps)
        print(f"\nF/F_y = {overload:g} (load {load:.6e}, a_Hertz/R = "
              f"{hertz_half_width(load):.4f})\n")
        print("| level | DoFs | " + " | ".join(quantities) + " | wall s |")
        print("|---" * (len(quantities) + 3) + "|")
        for level, result in enumerate(levels):
            print(f"| {level} | {result['dofs']} | " +
                  " | ".join(f"{result[q]:.6g}" for q in quantities) +
                  f" | {result['seconds']:.1f} |")
        print(f"| 1, {2 * args.steps} steps | {steps['dofs']} | " +
              " | ".join(f"{steps[q]:.6g}" for q in quantities) +
              f" | {steps['seconds']:.1f} |")
        print()
        for q in quantities:
            values = [result[q] for result in levels]
            mesh = bar(values)
            step = abs(steps[q] - values[1])
            print(f"{q}: {values[-1]:.5g} ± {mesh + step:.2g} (mesh "
                  f"{mesh:.2g}, load steps {step:.2g})")
