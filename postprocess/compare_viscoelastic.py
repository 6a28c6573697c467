#!/usr/bin/python3
"""FE Kelvin-Voigt epsilon (task 'sweep' with 'Relaxation times', alpha = 0
the elastic reference) against the 1-DOF reduced models (task 'reference
models', model disk): prints per (v, alpha) the FE epsilon with its error
bar, the ODE's (force end), eq. 80, the difference, the bound of issue 5
(2e-3 plus the elastic vibration loss 1 - eps_el), and the viscous loss of
each (FE: eps_el - eps_FE; ODE: 1 - eps_ODE) with their ratio.

usage: compare_viscoelastic.py restitution.csv reference_disk.csv
"""
import csv
import math
import sys


def number(text):
    return float(text) if text not in ("", "nan") else math.nan


fe = list(csv.DictReader(open(sys.argv[1])))
ref = list(csv.DictReader(open(sys.argv[2])))
key = lambda r: (round(number(r["velocity"]), 9), round(number(r["alpha"]), 9))
elastic = {round(number(r["velocity"]), 9): r for r in fe
           if number(r["alpha"]) == 0}
model = {key(r): r for r in ref}
print("| v/c | α | ε_FE | error | ε_ODE | eq. 80 | ε_FE − ε_ODE | 2e-3 + (1 − ε_el) "
      "| viscous loss FE | ODE | ratio |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for r in sorted(fe, key=key):
    v, alpha = key(r)
    if alpha == 0 or key(r) not in model or v not in elastic:
        continue
    eps, err = number(r["epsilon"]), number(r["epsilon_error"])
    eps_el = number(elastic[v]["epsilon"])
    ode = number(model[key(r)]["epsilon_ode"])
    eq80 = number(model[key(r)]["epsilon_second_order"])
    loss_fe, loss_ode = eps_el - eps, 1 - ode
    bound = 2e-3 + (1 - eps_el)
    print(f"| {v:g} | {alpha:g} | {eps:.5f} | {err:.1e} | {ode:.5f} | "
          f"{eq80:.5f} | {eps - ode:+.5f} | {bound:.5f} | {loss_fe:.5f} | "
          f"{loss_ode:.5f} | {loss_fe / loss_ode:.3f} |")
