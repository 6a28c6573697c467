#!/usr/bin/python3
"""Assertions on summary.csv of an oblique impact on the whole disk.

usage: check_oblique.py summary.csv --frictionless HEADON/summary.csv TOL
       check_oblique.py summary.csv --sliding TOL [--balances TOL]
       check_oblique.py summary.csv --spin-kept TOL [--balances TOL]

--frictionless: on a frictionless wall the motion along it changes nothing:
  epsilon, the contact time and delta_max are the head-on run's (same normal
  speed) to TOL, v_t and the spin are unchanged to TOL (relative to v_n).
--sliding: the contact point slides throughout (its tangential velocity
  keeps its sign), so rigid-body impulse theory with the computed epsilon
  gives v_t' = v_t - mu (1 + epsilon) v_n, to TOL v_n.
--spin-kept: on a frictionless wall the spin changes by at most TOL of
  itself.
--balances: energy (with the friction work), normal, tangential and angular
  impulse errors at most TOL.
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
    slides = s["v_contact_initial"] * s["v_contact_final"] > 0
    failed |= not slides
    print(f"contact point {s['v_contact_initial']:.6g} -> "
          f"{s['v_contact_final']:.6g}: "
          f"{'slides throughout' if slides else 'FAIL: it stopped sliding'}")
if args.spin_kept is not None:
    print(f"spin: {s['spin_initial']:.10g} -> {s['spin_final']:.10g}")
    check("spin change / spin", s["spin_final"] / s["spin_initial"] - 1,
          args.spin_kept)
if args.balances is not None:
    for name in ("energy_error", "impulse_error", "tangential_impulse_error",
                 "angular_impulse_error"):
        check(name, s[name], args.balances)
sys.exit(1 if failed else 0)
