#!/usr/bin/python3
"""Assertions on summary.csv of task 'impact'.

usage: check_impact.py summary.csv [--epsilon E TOL] [--energy TOL]
       [--impulse TOL] [--one-dof TOL] [--factorizations N]
       [--solves-per-step MAX] [--one-dof-epsilon TOL]
       [--one-dof-unloading TOL [--ramirez-law-off MIN]]
       [--plastic-balance TOL]
"""
import argparse
import csv
import os
import sys

p = argparse.ArgumentParser()
p.add_argument("summary")
p.add_argument("--epsilon", nargs=2, type=float, metavar=("VALUE", "TOL"))
p.add_argument("--energy", type=float, help="bound on energy_error")
p.add_argument("--impulse", type=float, help="bound on impulse_error")
p.add_argument("--one-dof", type=float,
               help="relative bound on contact time and delta_max vs the 1-DOF model")
p.add_argument("--one-dof-epsilon", type=float,
               help="bound on |epsilon - one_dof_epsilon| (viscoelastic)")
p.add_argument("--one-dof-unloading", type=float,
               help="bound on |epsilon - one_dof_epsilon_unloading| "
                    "(viscoelastic, the tension-free unloading law)")
p.add_argument("--ramirez-law-off", type=float,
               help="lower bound on |epsilon - one_dof_epsilon|: the case "
                    "tells the two laws apart")
p.add_argument("--factorizations", type=int)
p.add_argument("--solves-per-step", type=float,
               help="bound on triangular_solves / steps (solves with the "
                    "factorized matrix per time step)")
p.add_argument("--plastic-balance", type=float,
               help="bound on |epsilon^2 + plastic_work + vibration_fraction "
                    "(+ viscous work) - 1|: an elastic-plastic impact's "
                    "energy after it, from the rebound velocity, the "
                    "quadrature points' plastic work and the body's "
                    "vibration, and plastic_work > 0; a viscoelastic body's "
                    "viscous work from the last row of impact.csv beside "
                    "summary.csv (energy_dissipated over the first row's "
                    "energy_total)")
a = p.parse_args()
s = next(csv.DictReader(open(a.summary, newline="")))
checks = []
if a.epsilon:
    checks.append(("epsilon", float(s["epsilon"]),
                   abs(float(s["epsilon"]) - a.epsilon[0]) <= a.epsilon[1]))
if a.plastic_balance is not None:
    eps, plastic = float(s["epsilon"]), float(s["plastic_work"])
    history = os.path.join(os.path.dirname(a.summary), "impact.csv")
    viscous = 0.0
    if os.path.exists(history):
        rows = list(csv.DictReader(open(history, newline="")))
        viscous = (float(rows[-1]["energy_dissipated"]) /
                   float(rows[0]["energy_total"]))
    balance = eps ** 2 + plastic + viscous + float(s["vibration_fraction"]) - 1
    checks.append(("plastic balance", balance,
                   abs(balance) <= a.plastic_balance and plastic > 0))
if a.energy is not None:
    checks.append(("energy_error", float(s["energy_error"]),
                   float(s["energy_error"]) <= a.energy))
if a.impulse is not None:
    checks.append(("impulse_error", float(s["impulse_error"]),
                   float(s["impulse_error"]) <= a.impulse))
if a.one_dof is not None:
    for fe, ref in (("contact_time", "one_dof_contact_time"),
                    ("delta_max", "one_dof_delta_max")):
        rel = float(s[fe]) / float(s[ref]) - 1
        checks.append((fe + " / 1-DOF - 1", rel, abs(rel) <= a.one_dof))
if a.one_dof_epsilon is not None:
    diff = float(s["epsilon"]) - float(s["one_dof_epsilon"])
    checks.append(("epsilon - 1-DOF epsilon", diff,
                   abs(diff) <= a.one_dof_epsilon))
if a.one_dof_unloading is not None:
    diff = float(s["epsilon"]) - float(s["one_dof_epsilon_unloading"])
    checks.append(("epsilon - 1-DOF unloading law", diff,
                   abs(diff) <= a.one_dof_unloading))
if a.ramirez_law_off is not None:
    diff = float(s["epsilon"]) - float(s["one_dof_epsilon"])
    checks.append(("epsilon - 1-DOF law of Ramírez et al. (must exceed)", diff,
                   abs(diff) >= a.ramirez_law_off))
if a.factorizations is not None:
    checks.append(("factorizations", int(s["factorizations"]),
                   int(s["factorizations"]) == a.factorizations))
if a.solves_per_step is not None:
    ratio = int(s["triangular_solves"]) / int(s["steps"])
    checks.append(("triangular_solves / steps", ratio,
                   ratio <= a.solves_per_step))
failures = 0
for name, value, ok in checks:
    failures += not ok
    print(f"{name:28s} {value: .6g} {'ok' if ok else 'FAIL'}")
sys.exit(1 if failures else 0)
