#!/usr/bin/python3
"""A thin free disk's in-plane modes against the plane-stress disk's.

A disk of thickness H with free faces is in plane stress as H -> 0. Its
in-plane modes differ from the plane-stress ones by the inertia of the
faces' motion u_z = -nu / (1 - nu) z div u (the shear it causes is relaxed by
an in-plane correction at higher order), so

    omega(H) / omega_ps - 1 = a H^2 + O(H^4),

and for a radial mode u = J1(k r) e_r (k J0(k R) = (1 - nu) J1(k R)) the
Rayleigh quotient gives

    a = -(nu / (1 - nu))^2 k^2 / 24 * int J0(kr)^2 r dr / int J1(kr)^2 r dr

(integrals over 0 <= r <= R). The 3D runs use the plane run's section mesh, extruded, at thicknesses that
halve (H, H/2, H/4, ...), so the in-plane discretization largely drops out
of D(H) = omega_3D(H) / omega_2D - 1; with --exact the reference is the
exact plane-stress frequency instead (omega_exact of the plane run).

Checks, for every elastic mode whose D changes by more than 1e-5 between the
last three disks' first two (the discrete limit's own small change with H,
about 1e-7 on a coarse section mesh, is then negligible): the observed order
p = log2((D(4h) - D(2h)) / (D(2h) - D(h))) of the three thinnest, which
needs no limit, within TOLERANCE of 2; for every radial mode, a from the
two thinnest disks (a H^2 + b H^4 through both) within RELATIVE of the
Rayleigh quotient's. --markdown prints the same as a Markdown table.

usage: check_thin_disk_limit.py PLANE/modes.csv H1 A/modes.csv H2 B/modes.csv
                                H3 C/modes.csv [H4 D/modes.csv ...]
                                --poisson NU [--order-tolerance 0.1]
                                [--relative 0.01] [--exact] [--markdown]
"""
import argparse
import csv
import math
import sys

from scipy.integrate import quad
from scipy.optimize import brentq
from scipy.special import j0, j1

p = argparse.ArgumentParser()
p.add_argument("plane")
p.add_argument("solid", nargs="+")
p.add_argument("--poisson", type=float, required=True)
p.add_argument("--order-tolerance", type=float, default=0.1)
p.add_argument("--relative", type=float, default=0.01)
p.add_argument("--exact", action="store_true")
p.add_argument("--markdown", action="store_true")
args = p.parse_args()
nu = args.poisson


def modes(path):
    with open(path, newline="") as f:
        return [r for r in csv.DictReader(f) if r["family"] != "rigid"]


def radial_k(overtone):
    """k R of the overtone-th radial mode of the plane-stress disk."""
    roots, step, k = [], 0.05, 0.5
    f = lambda k: k * j0(k) - (1. - nu) * j1(k)
    while len(roots) <= overtone:
        if f(k) * f(k + step) < 0.:
            roots.append(brentq(f, k, k + step))
        k += step
    return roots[overtone]


def rayleigh_coefficient(k):
    ratio = (quad(lambda r: j0(k * r) ** 2 * r, 0., 1.)[0] /
             quad(lambda r: j1(k * r) ** 2 * r, 0., 1.)[0])
    return -(nu / (1. - nu)) ** 2 * k * k / 24. * ratio


plane = modes(args.plane)
thickness = [float(h) for h in args.solid[0::2]]
solids = [modes(path) for path in args.solid[1::2]]
if (len(args.solid) % 2 or len(thickness) < 3 or
        any(a != 2. * b for a, b in zip(thickness, thickness[1:]))):
    sys.exit("FAIL: give three or more thicknesses that halve, each with "
             "its modes.csv")
failed = False
if args.markdown:
    print("| mode | ω plane stress | " +
          " | ".join(f"D, H = {h:g} R" for h in thickness) +
          " | order | a | a, Rayleigh |")
    print("|---" * (len(thickness) + 5) + "|")
for i, mode in enumerate(plane):
    if any(len(s) <= i for s in solids):
        print(f"FAIL: fewer 3D modes than plane ones ({i})")
        failed = True
        break
    omega = float(mode["omega_exact" if args.exact else "omega"])
    d = [float(s[i]["omega"]) / omega - 1. for s in solids]
    name = f"n = {mode['n']}, l = {mode['l']} ({mode['family']})"
    line = f"{name}: D = " + ", ".join(f"{x:.4e}" for x in d)
    order = a = reference = None
    if abs(d[-3] - d[-2]) > 1e-5:
        order = math.log2((d[-3] - d[-2]) / (d[-2] - d[-1]))
        ok = abs(order - 2.) <= args.order_tolerance
        failed |= not ok
        line += (f"; order {order:.4f} (2 +- {args.order_tolerance}) "
                 f"{'ok' if ok else 'FAIL'}")
    if mode["family"] == "radial":
        h = thickness[-1]
        a = (16. * d[-1] - d[-2]) / (12. * h * h)
        k = radial_k(int(mode["l"]))
        exact = float(mode["omega_exact"])
        if abs(k / math.sqrt(1. - nu * nu) / exact - 1.) > 1e-8:
            sys.exit(f"FAIL: {name}: the root k R = {k} is not this mode")
        reference = rayleigh_coefficient(k)
        ok = abs(a / reference - 1.) <= args.relative
        failed |= not ok
        line += (f"; a = {a:.6f}, Rayleigh {reference:.6f}: "
                 f"{abs(a / reference - 1.):.2e} (bound {args.relative}) "
                 f"{'ok' if ok else 'FAIL'}")
    if args.markdown:
        fmt = lambda x, f: "" if x is None else format(x, f)
        print(f"| ({mode['n']}, {mode['l']}) | {omega:.7f} | " +
              " | ".join(f"{x:.3e}" for x in d) +
              f" | {fmt(order, '.3f')} | {fmt(a, '.6f')} | "
              f"{fmt(reference, '.6f')} |")
    else:
        print(line)
sys.exit(1 if failed else 0)
