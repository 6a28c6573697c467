#!/usr/bin/python3
"""epsilon of the elastic-perfectly-plastic sphere far above its speed of
first yield, and the local exponent d ln(epsilon) / d ln(v) (Johnson's fully
plastic impact: -1/4).

The sphere of params/sweep_plastic_sphere.prm (nu = 0.3, Y = 0.002 E*,
penalty factor 100, v_y = 9.22133e-7 c), axisymmetric, Q2, with the
resolution of that sweep's second level: the element size a_H / 12 at the
contact (a_H Hertz's contact radius at the speed), grading 0.3, steps of
t_c / 200. A plastic contact is wider than Hertz's, so each speed runs
three times:
  1. the mesh graded for Hertz's contact (12 elements across a_H), which
     measures the largest contact half-width a_max;
  2. the mesh graded for a_max with the same element size at the contact
     (the result);
  3. run 2 with steps of t_c / 400.
Printed per speed: epsilon of run 2, its differences to runs 1 and 3 (the
mesh's and the time step's effect), the local exponent from the previous
speed, the mean contact pressure F_max / (pi a^2) at the largest force over
Y, a_max and delta_max over R, the largest equivalent plastic strain and
the plastic work over E(0).

usage: bench/plastic_high_speed.py [--speeds 100,300,1000] [--ranks 2]
       (build first; about 15 minutes on 2 cores)
"""
import argparse
import csv
import math
import os
import tempfile

from diskimpact_run import (PLASTIC_SPHERE_YIELD_SPEED, plastic_sphere_prm,
                            run_diskimpact)

parser = argparse.ArgumentParser()
parser.add_argument("--speeds", default="100,300,1000",
                    help="impact speeds over the speed of first yield")
parser.add_argument("--ranks", type=int, default=2)
args = parser.parse_args()

YIELD_STRAIN = 0.002               # Y / E*
ELEMENTS_ACROSS_HERTZ = 12


def impact(work, name, speed, elements, graded_half_width=0.0,
           step_fraction=0.005):
    """One impact; returns its summary row and the rows of impact.csv."""
    directory = os.path.join(work, name)
    prm = directory + ".prm"
    graded = (f"  set Graded half-width = {graded_half_width:.6g}\n"
              if graded_half_width > 0.0 else "")
    with open(prm, "w") as f:
        f.write(plastic_sphere_prm(
            directory, 2,
            f"  set Velocity = {speed:.6e}\n"
            f"  set Elements across contact = {elements}\n{graded}"
            "  set Grading = 0.3\n  set Output interval = 0\n",
            f"  set Time step fraction = {step_fraction}\n"))
    run_diskimpact(prm, args.ranks)
    summary = next(csv.DictReader(open(os.path.join(directory,
                                                    "summary.csv"))))
    history = list(csv.DictReader(open(os.path.join(directory,
                                                    "impact.csv"))))
    return summary, history


def mean_pressure_over_yield(history):
    """F / (pi a^2) at the largest force, over Y (forces in E* R^2)."""
    peak = max(history, key=lambda r: float(r["contact_force"]))
    a = float(peak["contact_half_width"])
    return float(peak["contact_force"]) / (math.pi * a * a) / YIELD_STRAIN


print(f"{'v/v_y':>6} {'epsilon':>10} {'Hertz mesh':>10} {'dt/2':>9} "
      f"{'exponent':>8} {'p_m/Y':>6} {'a_max/R':>8} {'d_max/R':>9} "
      f"{'alpha_max':>9} {'W_p/E0':>7}")
previous = None
with tempfile.TemporaryDirectory() as work:
    for over in [float(s) for s in args.speeds.split(",")]:
        speed = over * PLASTIC_SPHERE_YIELD_SPEED
        hertz, history = impact(work, f"v{over:g}_hertz", speed,
                                ELEMENTS_ACROSS_HERTZ)
        a_hertz = math.sqrt(float(hertz["one_dof_delta_max"]))
        a_max = max(float(r["contact_half_width"]) for r in history)
        # The same element size at the contact, an even count across a_max.
        elements = 2 * max(2, round(ELEMENTS_ACROSS_HERTZ * a_max / a_hertz
                                    / 2))
        graded, history = impact(work, f"v{over:g}", speed, elements, a_max)
        halved, _ = impact(work, f"v{over:g}_dt", speed, elements, a_max,
                           0.0025)
        eps = float(graded["epsilon"])
        exponent = ("" if previous is None else
                    f"{math.log(eps / previous[1]) / math.log(over / previous[0]):8.3f}")
        print(f"{over:6g} {eps:10.6f} "
              f"{float(hertz['epsilon']) - eps:+10.1e} "
              f"{float(halved['epsilon']) - eps:+9.1e} {exponent:>8} "
              f"{mean_pressure_over_yield(history):6.3f} {a_max:8.4f} "
              f"{float(graded['delta_max']):9.6f} "
              f"{float(graded['plastic_strain_max']):9.4f} "
              f"{float(graded['plastic_work']):7.4f}", flush=True)
        previous = (over, eps)
