#!/usr/bin/python3
"""Maw, Barber & Fawcett's oblique impact of an elastic sphere, computed here.

An elastic sphere (Poisson ratio nu, moment of inertia 2/5 m R^2) hits a
rigid wall with the normal speed v_n and the contact point's tangential
speed v_cp, Coulomb friction mu. Maw, Barber & Fawcett's assumptions:
- the normal contact is Hertz's, elastic (no loss: epsilon = 1);
- the tangential tractions do not change the pressure, and the tangential
  compliance is the half-space's with the directions averaged: a traction
  tau(x) displaces the surface by (2 - nu) / (4 pi G) int tau / |x - x'|,
  which is the normal problem's kernel with E* replaced by 4 G / (2 - nu);
- the contact is divided into N annuli of uniform traction (the influence
  of each on the others through the uniform-disk solution with complete
  elliptic integrals, Johnson's Contact Mechanics eqs. 3.31-3.32); each
  annulus sticks, or slips at mu times its Hertz pressure against its slip,
  and carries its slip as history (Mindlin & Deresiewicz), from the time it
  enters the contact (with no traction) to the time it leaves.
Per time step the rigid-body motion moves the contact point by v_cp dt; the
tractions follow from the annuli's stick and slip (an active-set
iteration); their sum changes v_t and the spin. Prints, per normalised
incidence psi1 = 2 v_cp / (mu (1 + epsilon) v_n) (epsilon = 1 here), the
normalised rebound psi2 and the contact point's restitution beta; with
--compare CSV ... (diskimpact's restitution.csv of task 'sweep' over
'Angles of incidence', or summary.csv of task 'impact', the sphere in 3D)
at their psi1, beside diskimpact's psi2 and the difference. Maw, Barber & Fawcett's own normalisation
Psi = 2 (1 - nu) / (2 - nu) psi is printed too.

usage: bench/mbf_sphere.py --nu 0.3 [--mu 0.1] [--annuli 40]
                           [--steps 4000] [--psi1 1 2 ...]
                           [--compare CSV ...] [--stiffness-factor 1]

--stiffness-factor F scales the contact's tangential stiffness (G* -> F G*):
how far the outcome moves with the tangential-to-normal stiffness ratio.
"""
import argparse
import csv
import math

import numpy as np
from scipy.special import ellipe, ellipk

K = 0.4  # the sphere's I / (m R^2)


def disk_displacement(r, c):
    """Surface displacement at radius r of a unit uniform load on the disk
    of radius c, times pi E* / 4 (Johnson, eqs. 3.31-3.32)."""
    if c <= 0.0:
        return 0.0
    if r <= c:
        return c * ellipe((r / c) ** 2)
    m = (c / r) ** 2
    return r * (ellipe(m) - (1.0 - m) * ellipk(m))


def influence(edges):
    """Displacement at each annulus' mid-radius per unit traction on each
    annulus, times pi G* / 4 (G* = 4 G / (2 - nu) for tangential loads)."""
    mid = 0.5 * (edges[1:] + edges[:-1])
    n = len(mid)
    matrix = np.empty((n, n))
    for i, r in enumerate(mid):
        for j in range(n):
            matrix[i, j] = (disk_displacement(r, edges[j + 1])
                            - disk_displacement(r, edges[j]))
    return mid, matrix


def impact(nu, mu, psi1, annuli, steps, stiffness_factor=1.0):
    """psi2 and beta of one impact at the normalised incidence psi1; the
    tangential stiffness times stiffness_factor (1: the half-space's)."""
    # Units: R = 1, m = 1, E* = 1, v_n = 1 (the outcome depends on psi1,
    # nu and mu alone).
    e_star, v_n = 1.0, 1.0
    young = e_star * (1.0 - nu**2)
    shear = young / (2.0 * (1.0 + nu))
    g_star = 4.0 * shear / (2.0 - nu) * stiffness_factor
    # Hertz: m d'' = -(4/3) E* d^1.5; largest approach and contact time.
    delta_max = (15.0 / 16.0 * v_n**2 / e_star) ** 0.4
    t_contact = 2.94328 * delta_max / v_n
    a_max = math.sqrt(delta_max)
    edges = np.linspace(0.0, a_max * 1.0001, annuli + 1)
    mid, matrix = influence(edges)
    compliance = matrix * 4.0 / (math.pi * g_star)
    area = math.pi * (edges[1:] ** 2 - edges[:-1] ** 2)
    v_cp0 = psi1 * mu * v_n  # psi1 = 2 v_cp / (mu (1 + 1) v_n)
    v_t, omega, shift = v_cp0, 0.0, 0.0   # shift: the contact point's
    slip = np.zeros(annuli)               # motion; each annulus' slip
    tau = np.zeros(annuli)
    touching = np.zeros(annuli, dtype=bool)
    delta, v = 0.0, v_n
    dt = 1.2 * t_contact / steps
    for _ in range(steps):
        # The normal motion (velocity Verlet on Hertz's force).
        force = 4.0 / 3.0 * e_star * max(delta, 0.0) ** 1.5
        v_half = v - 0.5 * dt * force
        delta += dt * v_half
        force = 4.0 / 3.0 * e_star * max(delta, 0.0) ** 1.5
        v = v_half - 0.5 * dt * force
        if delta <= 0.0 and v < 0.0:
            break
        a = math.sqrt(max(delta, 0.0))
        pressure = np.where(mid < a, 2.0 * a / math.pi *
                            np.sqrt(np.clip(1.0 - (mid / max(a, 1e-300))**2,
                                            0.0, None)), 0.0)
        # The contact point moves with the body (v_t - omega R); a surface
        # point's displacement relative to the wall is shift + u.
        shift += dt * (v_t - omega)
        inside = mid < a
        entering = inside & ~touching
        # An annulus enters sticking, without traction: its slip is the
        # relative displacement it has now.
        u_now = compliance @ tau
        slip[entering] = shift + u_now[entering]
        slip[~inside] = 0.0
        touching = inside
        tau = solve_tractions(compliance, inside, pressure * mu, shift, slip)
        slip_new = shift + compliance @ tau
        slip[inside] = slip_new[inside]
        q = float(area @ tau)
        v_t += dt * q
        omega -= dt * q / K
    v_cp1 = v_t - omega
    return v_cp1 / (mu * v_n), -v_cp1 / v_cp0


def solve_tractions(compliance, inside, bound, shift, slip):
    """Tractions of the annuli in contact: stick (the relative displacement
    shift + u_i stays slip_i) or slip at the bound against the slip's
    increment; an active set."""
    n = len(bound)
    idx = np.flatnonzero(inside)
    tau = np.zeros(n)
    if idx.size == 0:
        return tau
    sliding = {}  # annulus -> sign of its traction
    for _ in range(4 * idx.size + 10):
        stick = [i for i in idx if i not in sliding]
        tau[:] = 0.0
        for i, s in sliding.items():
            tau[i] = s * bound[i]
        if stick:
            c = compliance[np.ix_(stick, stick)]
            rhs = slip[stick] - shift
            if sliding:
                rhs -= compliance[np.ix_(stick, list(sliding))] @ \
                    np.array([tau[i] for i in sliding])
            tau[stick] = np.linalg.solve(c, rhs)
        changed = False
        for i in stick:  # a sticking annulus beyond its bound slips
            if abs(tau[i]) > bound[i] * (1.0 + 1e-12):
                sliding[i] = math.copysign(1.0, tau[i])
                changed = True
        u = compliance @ tau
        for i, s in list(sliding.items()):  # a slipping one whose slip
            increment = (shift + u[i]) - slip[i]  # would run along its
            if increment * s > 0.0:              # traction sticks again
                del sliding[i]
                changed = True
        if not changed:
            return tau
    return tau


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--nu", type=float, required=True)
    p.add_argument("--mu", type=float, default=0.1)
    p.add_argument("--annuli", type=int, default=40)
    p.add_argument("--steps", type=int, default=4000)
    p.add_argument("--psi1", type=float, nargs="+")
    p.add_argument("--compare", nargs="+", metavar="CSV")
    p.add_argument("--stiffness-factor", type=float, default=1.0,
                   help="the tangential stiffness relative to the "
                   "half-space's (its tangential-to-normal ratio); 1 is "
                   "Maw, Barber & Fawcett's model")
    args = p.parse_args()
    chi = 2.0 * (1.0 - args.nu) / (2.0 - args.nu)
    rows = []
    for path in args.compare or []:
        with open(path, newline="") as f:
            for r in csv.DictReader(f):
                if r.get("status", "done") == "done":
                    rows.append((float(r["psi_incident"]),
                                 float(r["psi_rebound"]),
                                 float(r["contact_point_restitution"])))
    if not rows:
        rows = [(x, math.nan, math.nan) for x in
                (args.psi1 or [0.5, 1, 2, 3, 4, 5, 6, 7, 8, 10, 14, 20])]
    print(f"nu = {args.nu}, mu = {args.mu}, {args.annuli} annuli, "
          f"{args.steps} steps; Psi = {chi:.4f} psi"
          + (f"; tangential stiffness x {args.stiffness_factor}"
             if args.stiffness_factor != 1.0 else ""))
    print("| psi1 | Psi1 | psi2 MBF | Psi2 MBF | beta MBF | psi2 diskimpact "
          "| Psi2 diskimpact | beta diskimpact | Delta Psi2 |")
    print("|---|---|---|---|---|---|---|---|---|")
    worst = 0.0
    for psi1, psi2_fe, beta_fe in rows:
        psi2, beta = impact(args.nu, args.mu, psi1, args.annuli, args.steps,
                            args.stiffness_factor)
        diff = chi * (psi2_fe - psi2)
        if math.isfinite(diff):
            worst = max(worst, abs(diff))
        print(f"| {psi1:.3f} | {chi * psi1:.3f} | {psi2:.3f} | "
              f"{chi * psi2:.3f} | {beta:.4f} | {psi2_fe:.3f} | "
              f"{chi * psi2_fe:.3f} | {beta_fe:.4f} | {diff:+.3f} |")
    if args.compare:
        print(f"largest |Delta Psi2| = {worst:.3f}")


if __name__ == "__main__":
    main()
