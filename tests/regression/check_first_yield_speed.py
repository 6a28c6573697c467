#!/usr/bin/python3
"""The speed at which an impact first yields, on restitution.csv of a sweep.

usage: check_first_yield_speed.py restitution.csv {sphere|plane-strain}
       YIELD_STRAIN TOLERANCE

The speed of first yield v_y is derived here independently of diskimpact:
Hertz's contact (the sphere's axis field, Johnson 1985 eq. 3.45; the
half-plane's field on its axis, McEwen 1949, with sigma_yy = nu (sigma_xx +
sigma_zz) in plane strain) gives p0/Y at first yield by maximizing the von
Mises stress over the depth; the impact's energy balance m v^2 / 2 = work of
the contact force up to that p0 gives v_y (the sphere's Hertz law; the
disk's d = x [ln(4/x) + C_com], C_com = -2 ln 2 - (1 + nu2)/4, integrated
numerically). YIELD_STRAIN is Y/E* (sphere) or Y/E2 (disk), nu = 0.3.

Every row slower than (1 - TOLERANCE) v_y must do no plastic work, every
row faster than (1 + TOLERANCE) v_y some, and the sweep must bracket v_y
within TOLERANCE from both sides: the finite elements' first plastic point
lies within TOLERANCE of v_y.
"""
import csv
import math
import sys

from scipy.integrate import quad

from hertz_yield import first_yield_pressure_ratio

path, body, yield_strain, tolerance = (sys.argv[1], sys.argv[2],
                                       float(sys.argv[3]), float(sys.argv[4]))
nu = 0.3

ratio, depth = first_yield_pressure_ratio(body, nu)
p0 = ratio * yield_strain  # over E* or E2
if body == "sphere":
    # F = (4/3) sqrt(R) delta^{3/2}, m = 4 pi / 3 (R = E* = rho = 1);
    # delta_y = (pi p0 / 2)^2.
    delta = (math.pi * p0 / 2) ** 2
    work = quad(lambda d: 4 / 3 * d ** 1.5, 0, delta)[0]
    mass = 4 * math.pi / 3
else:
    # P = pi x, delta = d(x) (R = E2 = rho = 1), m = pi; x_y = p0^2.
    nu2 = nu / (1 - nu)
    c_com = -2 * math.log(2) - (1 + nu2) / 4
    x_y = p0 ** 2
    work = quad(lambda x: math.pi * x * (math.log(4 / x) + c_com - 1),
                0, x_y)[0]
    mass = math.pi
v_y = math.sqrt(2 * work / mass)
print(f"{body}: first yield at p0/Y = {ratio:.5f}, depth {depth:.4f} a; "
      f"v_y = {v_y:.6e} c")

failures = 0
below = above = False
for r in csv.DictReader(open(path, newline="")):
    v, work = float(r["velocity"]), float(r["plastic_work"])
    ratio_v = v / v_y
    plastic = work > 0
    ok = (plastic if ratio_v > 1 + tolerance else
          not plastic if ratio_v < 1 - tolerance else True)
    below |= not plastic and ratio_v >= 1 - tolerance
    above |= plastic and ratio_v <= 1 + tolerance
    failures += not ok
    print(f"v = {ratio_v:.4f} v_y: plastic work {work:.3e} E(0) "
          f"{'ok' if ok else 'FAILED'}")
if not (below and above):
    failures += 1
    print(f"FAILED: the rows do not bracket the first plastic point within "
          f"{tolerance} of v_y")
sys.exit(1 if failures else 0)
