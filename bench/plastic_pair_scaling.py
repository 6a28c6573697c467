#!/usr/bin/python3
"""Two unequal elastic-perfectly-plastic spheres against the sphere on the
wall at the same v / v_y: does the pair's epsilon follow the wall's law?

DEM codes apply a contact law with the pair's effective radius
R* = R1 R2 / (R1 + R2), mass m* = m1 m2 / (m1 + m2) and modulus E*
(E / (2 (1 - nu^2)) for two bodies of one material); Thornton's model as
LIGGGHTS computes it (dem/liggghts_thornton.txt) gives an epsilon that
depends on v / v_y alone, v_y the speed of first yield of these effective
parameters. For two half-spaces of one material this holds exactly: both
carry the same pressure, so the pair is the wall impact of a body of radius
2 R* and mass 2 m* at half the speed. This bench checks it on the finite
spheres: for each v / v_y a convergence study of the sphere of
params/sweep_plastic_sphere.prm (R = 1, nu = 0.3, Y = 0.002 E*) on the
rigid wall, and one of that sphere hitting a sphere of radius
--partner-radius of the same material at the relative speed (v / v_y)
times the pair's v_y, each on meshes graded for its measured contact as in
that sweep,

    v_y,pair / v_y,wall = (E*_wall / E*_pair)^2 sqrt((R*^3 / m*) / (R^3 / m))

(Hertz's contact at the peak pressure of first yield, which is the same
for both: each body of the pair sees the wall's pressure field). Prints
both epsilons with their bars, their difference and the combined bar.

usage: bench/plastic_pair_scaling.py [--ratios 3 10 30] [--partner-radius 2]
       [--levels 3] [--ranks 2] [--work DIR]
About 10 minutes on 2 ranks with the defaults.
"""
import argparse
import csv
import math
import os
import sys
import tempfile

from diskimpact_run import (PLASTIC_SPHERE_YIELD_SPEED as WALL_YIELD_SPEED,
                            PLASTIC_SPHERE_YIELD_STRESS, plastic_sphere_prm,
                            run_diskimpact)


def pair_yield_speed(partner_radius):
    """v_y,pair / c of the unit sphere and a sphere of @p partner_radius of
    the same material (relative speed)."""
    def mass(radius):
        return radius ** 3              # 4 pi rho / 3 cancels

    r_eff = partner_radius / (1. + partner_radius)
    m_eff = mass(1.) * mass(partner_radius) / (mass(1.) + mass(partner_radius))
    return (WALL_YIELD_SPEED * 2. ** 2 *
            math.sqrt((r_eff ** 3 / m_eff) / (1. / mass(1.))))


def study_prm(directory, speed, levels, partner_radius):
    """The convergence study at @p speed; with a partner sphere if
    @p partner_radius > 0."""
    text = plastic_sphere_prm(
        directory, 1,
        f"  set Velocity = {speed:.10g}\n"
        "  set Elements across contact = 6\n"
        "  set Grading = 0.6\n"
        "  set Grade for measured contact = true\n"
        "  set Output interval = 0\n",
        "  set Time step fraction = 0.01\n", task="impact convergence")
    text += f"subsection Impact convergence\n  set Mesh levels = {levels}\nend\n"
    if partner_radius > 0:
        text += ("subsection Partner\n  set Kind = body\n"
                 f"  set Radius = {partner_radius:g}\n"
                 "  subsection Material\n    set Poisson ratio = 0.3\n"
                 f"    set Yield stress = {PLASTIC_SPHERE_YIELD_STRESS}\n"
                 "  end\nend\n")
    return text


def run_study(work, name, speed, args, partner_radius=0.):
    """epsilon and its bar from a convergence study, and its wall time."""
    directory = os.path.join(work, name)
    prm = directory + ".prm"
    with open(prm, "w") as f:
        f.write(study_prm(directory, speed, args.levels, partner_radius))
    seconds = run_diskimpact(prm, args.ranks)
    with open(os.path.join(directory, "epsilon_estimate.csv"),
              newline="") as f:
        total = [r for r in csv.DictReader(f) if r["factor"] == "total"][0]
    return float(total["limit"]), float(total["error"]), seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--ratios", type=float, nargs="+",
                        default=[3., 10., 30.], help="v / v_y")
    parser.add_argument("--partner-radius", type=float, default=2.,
                        help="the partner's radius / R (default 2)")
    parser.add_argument("--levels", type=int, default=3,
                        help="mesh levels of each study (default 3)")
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--work", help="keep the runs here")
    args = parser.parse_args()
    if args.partner_radius <= 0:
        sys.exit("plastic_pair_scaling.py: --partner-radius must be > 0")
    pair_vy = pair_yield_speed(args.partner_radius)
    print(f"v_y / c: wall {WALL_YIELD_SPEED:.6e}, pair (R2 = "
          f"{args.partner_radius:g} R) {pair_vy:.6e} (ratio "
          f"{pair_vy / WALL_YIELD_SPEED:.6f})")
    print("| v/v_y | wall ε | bar | pair ε | bar | pair − wall | "
          "combined bar | wall, pair [s] |")
    print("|---|---|---|---|---|---|---|---|")
    worst = 0.
    with tempfile.TemporaryDirectory() as scratch:
        work = os.path.abspath(args.work) if args.work else scratch
        os.makedirs(work, exist_ok=True)
        for u in args.ratios:
            wall = run_study(work, f"wall_{u:g}", u * WALL_YIELD_SPEED, args)
            pair = run_study(work, f"pair_{u:g}", u * pair_vy, args,
                             args.partner_radius)
            difference = pair[0] - wall[0]
            bar = wall[1] + pair[1]
            worst = max(worst, abs(difference) / bar)
            print(f"| {u:g} | {wall[0]:.6f} | {wall[1]:.1e} | {pair[0]:.6f} "
                  f"| {pair[1]:.1e} | {difference:+.1e} | {bar:.1e} | "
                  f"{wall[2]:.0f}, {pair[2]:.0f} |", flush=True)
    verdict = "within" if worst <= 1. else "beyond"
    print(f"largest |pair - wall| / combined bar: {worst:.2f} ({verdict} "
          "the bars)")
    return 0 if worst <= 1. else 1


if __name__ == "__main__":
    sys.exit(main())
