#!/usr/bin/python3
"""The two plastic solvers of an impact side by side: 'Plastic solver' =
fixed point (the elastic factorization, Anderson's acceleration) and Newton
(the consistent tangent, refactorized when the plastic zone changes), one
after the other on the same machine and ranks.

The body is the elastic-perfectly-plastic sphere of
params/impact_convergence_plastic_sphere.prm (nu = 0.3, Y = 0.002 E*,
penalty factor 100), on the mesh of its finest level (16 elements across
Hertz's contact) with 0.005 of the contact time per step, at 10 and 100
times the speed of first yield. Printed per run: epsilon, the plastic work,
the plastic iterations, the factorizations (the tangent's among them), the
solves with a factorized matrix and the wall time; then epsilon's
difference between the two solvers (both stop at 'Plastic tolerance' 1e-6
of f_p) and the ratio of their times.

usage: bench/plastic_solvers.py [--ranks 2] [--speeds 10,100]
       (build first; about 3 minutes on 2 cores)
"""
import argparse
import csv
import os
import tempfile

from diskimpact_run import (PLASTIC_SPHERE_YIELD_SPEED, plastic_sphere_prm,
                            run_diskimpact)

parser = argparse.ArgumentParser()
parser.add_argument("--ranks", type=int, default=2)
parser.add_argument("--speeds", default="10,100",
                    help="impact speeds over the speed of first yield")
parser.add_argument("--elements", type=int, default=16,
                    help="elements across Hertz's contact")
args = parser.parse_args()


def run(work, over, solver):
    directory = os.path.join(work, f"v{over}_{solver.replace(' ', '_')}")
    prm = directory + ".prm"
    with open(prm, "w") as f:
        f.write(plastic_sphere_prm(
            directory, 1,
            f"  set Velocity = {over * PLASTIC_SPHERE_YIELD_SPEED:.6e}\n"
            f"  set Elements across contact = {args.elements}\n"
            "  set Grading = 0.6\n",
            "  set Time step fraction = 0.005\n"
            f"  set Plastic solver = {solver}\n"))
    seconds = run_diskimpact(prm, args.ranks)
    row = next(csv.DictReader(open(os.path.join(directory, "summary.csv"))))
    row["seconds"] = seconds
    return row


print(f"{'v/v_y':>6} {'solver':>12} {'DoFs':>6} {'epsilon':>11} "
      f"{'W_p/E0':>9} {'plastic it.':>11} {'fact. (tangent)':>15} "
      f"{'solves':>7} {'wall [s]':>8}")
with tempfile.TemporaryDirectory() as work:
    for over in [float(s) for s in args.speeds.split(",")]:
        rows = {}
        for solver in ["fixed point", "Newton"]:
            r = run(work, over, solver)
            rows[solver] = r
            print(f"{over:6g} {solver:>12} {r['n_dofs']:>6} "
                  f"{float(r['epsilon']):11.8f} "
                  f"{float(r['plastic_work']):9.6f} "
                  f"{r['plastic_iterations']:>11} "
                  f"{r['factorizations'] + ' (' + r['tangent_factorizations'] + ')':>15} "
                  f"{r['triangular_solves']:>7} {r['seconds']:8.1f}",
                  flush=True)
        a, b = rows["fixed point"], rows["Newton"]
        print(f"{'':6} epsilon: Newton - fixed point = "
              f"{float(b['epsilon']) - float(a['epsilon']):.2e}; "
              f"time Newton / fixed point = {b['seconds'] / a['seconds']:.2f}")
