#!/usr/bin/python3
"""Assertions on summary.csv of an oblique impact on the whole disk or sphere.

usage: check_oblique.py summary.csv --frictionless HEADON/summary.csv TOL
       check_oblique.py summary.csv --sliding TOL [--balances TOL]
       check_oblique.py summary.csv --spin-kept TOL [--balances TOL]
       check_oblique.py summary.csv --tangential-restitution TOL
                        --spin-with-arm impact.csv TOL [--inertia-factor K]
                        [--balances TOL] [--energy TOL]

--frictionless: on a frictionless wall the motion along it changes nothing:
  epsilon, the contact time and delta_max are the head-on run's (same normal
  speed) to TOL, v_t and the spin are unchanged to TOL (relative to v_n).
--sliding: the contact point slides throughout (its tangential velocity
  keeps its sign), so rigid-body impulse theory with the computed epsilon
  gives v_t' = v_t - mu (1 + epsilon) v_n, to TOL v_n.
--spin-kept: on a frictionless wall the spin changes by at most TOL of
  itself.
--tangential-restitution: the contact point slides throughout, and the
  tangential restitution v_t' / v_t is rigid-body sliding's
  1 - mu (1 + epsilon) v_n / v_t to TOL (a sphere's points off the plane of
  incidence also slip across it, so its friction along the plane falls a
  little short of mu times the pressure).
--spin-with-arm: in sliding the friction mu F_n acts on the centre through
  the arm R - delta(t) (delta the approach of the centre to the wall, from
  impact.csv); the spin after, omega0 + mu (1 + epsilon) v_n / (k R) times
  the F_n-weighted mean of 1 - delta / R, to TOL of itself. k = I / (m R^2):
  --inertia-factor, 1/2 the disk (default), 2/5 the sphere.
--balances: energy (with the friction work), normal, tangential and angular
  impulse errors at most TOL; --energy: a bound of its own for the energy.
"""
import argparse
import csv
import math
import sys

p = argparse.ArgumentParser()
p.add_argument("summary")
p.add_argument("--frictionless", nargs=2, metavar=("HEADON", "TOL"))
p.add_argument("--sliding", type=float)
p.add_argument("--spin-kept", type=float)
p.add_argument("--balances", type=float)
p.add_argument("--energy", type=float)
p.add_argument("--tangential-restitution", type=float)
p.add_argument("--spin-with-arm", nargs=2, metavar=("IMPACT_CSV", "TOL"))
p.add_argument("--inertia-factor", type=float, default=0.5)
args = p.parse_args()


def read(path):
    with open(path, newline="") as f:
        return {k: float(v) if v else math.nan
                for k, v in next(csv.DictReader(f)).items()}


s = read(args.summary)
v_n = s["velocity"] * math.cos(math.radians(s["angle"]))
failed = False


def check(name, value, bound):
    global failed
    ok = abs(value) <= bound
    failed |= not ok
    print(f"{name}: {value:.3e} (bound {bound:g}) {'ok' if ok else 'FAIL'}")


def check_slides_throughout():
    """The contact point's tangential velocity keeps its sign."""
    global failed
    slides = s["v_contact_initial"] * s["v_contact_final"] > 0
    failed |= not slides
    print(f"contact point {s['v_contact_initial']:.6g} -> "
          f"{s['v_contact_final']:.6g}: "
          f"{'slides throughout' if slides else 'FAIL: it stopped sliding'}")


if args.frictionless:
    h = read(args.frictionless[0])
    tol = float(args.frictionless[1])
    for name in ("epsilon", "contact_time", "delta_max"):
        check(f"{name} - head-on's (relative)", s[name] / h[name] - 1, tol)
    check("v_t change / v_n",
          (s["v_tangential_final"] - s["v_tangential_initial"]) / v_n, tol)
    check("spin change R / v_n", (s["spin_final"] - s["spin_initial"]) / v_n,
          tol)
if args.sliding is not None:
    mu, eps = s["friction"], s["epsilon"]
    rigid = s["v_tangential_initial"] - mu * (1 + eps) * v_n
    print(f"v_t: {s['v_tangential_initial']:.10f} -> "
          f"{s['v_tangential_final']:.10f}, rigid-body sliding {rigid:.10f}")
    check("v_t - rigid-body sliding (/ v_n)",
          (s["v_tangential_final"] - rigid) / v_n, args.sliding)
    check_slides_throughout()
if args.tangential_restitution is not None:
    mu, eps = s["friction"], s["epsilon"]
    v_t = s["v_tangential_initial"]
    rigid = 1 - mu * (1 + eps) * v_n / v_t
    print(f"tangential restitution {s['tangential_restitution']:.8f}, "
          f"rigid-body sliding {rigid:.8f}")
    check("e_t - rigid-body sliding", s["tangential_restitution"] - rigid,
          args.tangential_restitution)
    check_slides_throughout()
if args.spin_with_arm:
    with open(args.spin_with_arm[0], newline="") as f:
        rows = list(csv.DictReader(f))
    # The trapezoidal rule over the records: F_n and the arm 1 - delta / R.
    t = [float(r["time"]) for r in rows]
    force = [float(r["contact_force"]) for r in rows]
    arm = [1 + float(r["x_com"]) for r in rows]  # x_com in R (no SI units)

    def integral(values):
        return sum(0.5 * (t[i + 1] - t[i]) * (values[i + 1] + values[i])
                   for i in range(len(t) - 1))

    mean_arm = integral([f * a for f, a in zip(force, arm)]) / integral(force)
    k, mu, eps = args.inertia_factor, s["friction"], s["epsilon"]
    rigid = s["spin_initial"] + mu * (1 + eps) * v_n / k
    print(f"spin {s['spin_final']:.8f}: rigid-body sliding {rigid:.8f} "
          f"(ratio {s['spin_final'] / rigid:.5f}), mean arm "
          f"{mean_arm:.5f} R")
    check("spin / (rigid-body sliding x arm) - 1",
          s["spin_final"] / (rigid * mean_arm) - 1,
          float(args.spin_with_arm[1]))
if args.spin_kept is not None:
    print(f"spin: {s['spin_initial']:.10g} -> {s['spin_final']:.10g}")
    check("spin change / spin", s["spin_final"] / s["spin_initial"] - 1,
          args.spin_kept)
if args.balances is not None:
    for name in ("energy_error", "impulse_error", "tangential_impulse_error",
                 "angular_impulse_error"):
        bound = (args.energy if name == "energy_error" and
                 args.energy is not None else args.balances)
        check(name, s[name], bound)
sys.exit(1 if failed else 0)
