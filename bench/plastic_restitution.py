#!/usr/bin/python3
"""epsilon(v/v_y) of an elastic-perfectly-plastic sphere against Thornton's
model and Johnson's (v/v_y)^(-1/4), from a sweep's restitution.csv.

usage: plastic_restitution.py restitution.csv --yield-strain Y/E* [--nu 0.3]
       [--markdown] [--plot epsilon.png]

v_y: the speed at which Hertz's peak pressure reaches p0/Y = 1.6128 Y (at
nu = 0.3; computed here from Johnson's axis field), the speed of first yield
(docs/theory/first-yield.md).

Thornton's model (J. Appl. Mech. 64, 1997): Hertz's F = (4/3) E* R^(1/2)
delta^(3/2) up to the limiting pressure p_y at delta_y, then
F = F_y + pi p_y R (delta - delta_y); unloading by Hertz's law with the
radius R_p = (4 E* / (3 F_max)) ((2 F_max + F_y) / (2 pi p_y))^(3/2) from
delta_max to delta_p. Here p_y is the pressure of first yield, so Thornton's
v_y is the sphere's. The script computes its epsilon twice: from the force
law (the work of loading = m v^2 / 2 gives delta_max, the work returned on
unloading = (8/15) E* R_p^(1/2) (delta_max - delta_p)^(5/2) gives epsilon^2)
and from Thornton's closed form, and stops if the two differ by more than
1e-9.

Printed per point: the speed in m/s (for the table of a run with Units =
SI, whose restitution.h5 holds the speed unit), v/v_y, epsilon and its bar,
Thornton's epsilon, the local exponent d ln(epsilon) / d ln(v) between
neighbouring points (Johnson: -1/4 when the impact is fully plastic), the
plastic work / E(0), and the largest contact force over Thornton's at the
same speed. --plot draws epsilon(v) with its bars beside Thornton's model
and a line of slope -1/4 (Johnson) through the fastest point.
"""
import argparse
import csv
import math
import os
import sys

from scipy.optimize import brentq, minimize_scalar

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "postprocess"))
from plot_restitution import speed_unit  # noqa: E402

p = argparse.ArgumentParser()
p.add_argument("table")
p.add_argument("--yield-strain", type=float, required=True,
               help="Y / E*, E* = E / (1 - nu^2)")
p.add_argument("--nu", type=float, default=0.3)
p.add_argument("--markdown", action="store_true")
p.add_argument("--plot", help="draw epsilon(v) into this PNG file")
a = p.parse_args()
nu = a.nu


def axis_von_mises(s):
    sigma_r = -((1 + nu) * (1 - s * math.atan(1 / s)) - 0.5 / (1 + s * s))
    return abs(sigma_r + 1 / (1 + s * s))


peak = minimize_scalar(lambda s: -axis_von_mises(s), bounds=(0.05, 2.0),
                       method="bounded", options={"xatol": 1e-10})
ratio = 1 / axis_von_mises(peak.x)
# Units R = E* = rho = 1: c = sqrt(E*/rho), m = 4 pi / 3.
p_y = ratio * a.yield_strain
mass = 4 * math.pi / 3
delta_y = (math.pi * p_y / 2) ** 2
F_y = 4 / 3 * delta_y ** 1.5
W_y = 8 / 15 * delta_y ** 2.5
v_y = math.sqrt(2 * W_y / mass)


def thornton_loading(v):
    """delta_max and F_max of Thornton's force law at speed v >= v_y."""
    energy = 0.5 * mass * v * v
    k = math.pi * p_y
    d = (-F_y + math.sqrt(F_y ** 2 + 2 * k * (energy - W_y))) / k
    return delta_y + d, F_y + k * d


def thornton_from_force_law(v):
    """epsilon of Thornton's force law at speed v >= v_y."""
    energy = 0.5 * mass * v * v
    # W(delta) = W_y + F_y (d - d_y) + pi p_y (d - d_y)^2 / 2.
    k = math.pi * p_y
    d = (-F_y + math.sqrt(F_y ** 2 + 2 * k * (energy - W_y))) / k
    F_max = F_y + k * d
    R_p = 4 / (3 * F_max) * ((2 * F_max + F_y) / (2 * math.pi * p_y)) ** 1.5
    # Unloading: F_max = (4/3) R_p^(1/2) (delta_max - delta_p)^(3/2).
    depth = (3 * F_max / (4 * math.sqrt(R_p))) ** (2 / 3)
    returned = 8 / 15 * math.sqrt(R_p) * depth ** 2.5
    return math.sqrt(returned / energy)


def thornton_closed_form(v):
    r = v_y / v
    return (math.sqrt(6 * math.sqrt(3) / 5) * math.sqrt(1 - r * r / 6) *
            (r / (r + 2 * math.sqrt(6 / 5 - r * r / 5))) ** 0.25)


rows = [r for r in csv.DictReader(open(a.table, newline=""))
        if r.get("status", "done") == "done"]
points = sorted((float(r["velocity"]) / v_y, float(r["epsilon"]),
                 float(r["epsilon_error"] or "nan"),
                 float(r["plastic_work"] or "nan"),
                 float(r["force_max"])) for r in rows)
print(f"p0/Y at first yield {ratio:.5f}; v_y = {v_y:.6e} c "
      f"(Y/E* = {a.yield_strain})")
failures = 0
lines = []
for i, (x, eps, err, work, force) in enumerate(points):
    force_ratio = float("nan")
    if x > 1:
        force_ratio = force / thornton_loading(x * v_y)[1]
        t1, t2 = thornton_from_force_law(x * v_y), thornton_closed_form(x * v_y)
        if abs(t1 - t2) > 1e-9:
            failures += 1
            print(f"Thornton's closed form {t2} differs from its force law "
                  f"{t1} at v/v_y = {x}")
    else:
        t1 = 1.0
    slope = ""
    if i > 0:
        x0, e0 = points[i - 1][0], points[i - 1][1]
        slope = f"{math.log(eps / e0) / math.log(x / x0):+.3f}"
    lines.append((x, eps, err, t1, slope, work, force_ratio))
# Below v_y Thornton's force is Hertz's: no ratio is shown.
lines = [line[:-1] + ("" if math.isnan(line[-1]) else f"{line[-1]:.3f}",)
         for line in lines]
unit = speed_unit(a.table)
si = unit is not None
if si:
    print(f"v_y = {v_y * unit:.4g} m/s")
if a.markdown:
    print("| " + ("v [m/s] | " if si else "") + "v/v_y | ε | bar | Thornton "
          "| exponent | plastic work / E(0) | F_max / Thornton's |")
    print("|---" * (8 if si else 7) + "|")
    for x, eps, err, t, slope, work, fr in lines:
        speed = f"{x * v_y * unit:.3g} | " if si else ""
        print(f"| {speed}{x:.3g} | {eps:.5f} | {err:.1e} | {t:.4f} | "
              f"{slope} | {work:.4f} | {fr} |")
else:
    print(("v [m/s]  " if si else "") + " v/v_y   epsilon     bar      "
          "Thornton  exponent  plastic work  F_max/Thornton")
    for x, eps, err, t, slope, work, fr in lines:
        speed = f"{x * v_y * unit:7.3g}  " if si else ""
        print(f"{speed}{x:6.3g}  {eps:.5f}  {err:8.1e}  {t:.4f}   "
              f"{slope:>7}  {work:.4f}        {fr:>5}")


def plot(path):
    """epsilon(v) with bars, Thornton's model and Johnson's slope."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    scale = v_y * unit if si else 1.0
    x = [point[0] * scale for point in points]
    fig, ax = plt.subplots(figsize=(6, 4.2))
    ax.errorbar(x, [point[1] for point in points],
                yerr=[point[2] for point in points], fmt="o-", capsize=3,
                ms=4, label="finite elements")
    lo, hi = math.log(min(points)[0]), math.log(max(points)[0])
    curve = [math.exp(lo + (hi - lo) * k / 200) for k in range(201)]
    ax.plot([u * scale for u in curve],
            [thornton_closed_form(u * v_y) if u > 1 else 1.0 for u in curve],
            "--", label=f"Thornton, p_y = {ratio:.4g} Y (first yield)")
    last = max(points)
    johnson = [u for u in curve if u >= last[0] / 10]
    ax.plot([u * scale for u in johnson],
            [last[1] * (u / last[0]) ** -0.25 for u in johnson], ":",
            label="slope -1/4 (Johnson)")
    ax.axvline(scale, color="grey", lw=0.8, label="v_y, first yield")
    ax.set_xscale("log")
    ax.set_xlabel("v_i [m/s]" if si else "v_i / v_y")
    ax.set_ylabel("epsilon")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    print("wrote", path)


if a.plot:
    plot(a.plot)
sys.exit(1 if failures else 0)
