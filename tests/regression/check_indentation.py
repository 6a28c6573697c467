#!/usr/bin/python3
"""Checks of task 'quasistatic contact' for an elastic-plastic body, on its
indentation.csv and indentation_summary.csv.

usage: check_indentation.py OUTPUT_DIR [--energy TOL]
           [--yield {sphere|plane-strain|plane-stress} Y_OVER_E {below|above}
            MARGIN]

--energy: the path's energy identity, |work of the body force - work of the
  support - elastic energy - plastic work| <= TOL times the largest work,
  at every step.
--yield: the load of first yield derived here independently of diskimpact
  (hertz_yield.py: p0/Y from Hertz's stress field; nu = 0.3, E = 1;
  sphere: load P/(pi E* R^2) = pi^2 (p0/E*)^3 / 6; disk: P/(pi E2 R) =
  (p0/E2)^2, E2 = E/(1 - nu^2) in plane strain, E in plane stress).
  'below': the largest load must lie at least MARGIN below it, the body stay elastic (no plastic work), the residual
  indentation vanish (below 1e-9 of the largest approach) and the loading
  point's approach less the penalty's penetration agree with the elastic
  contact law within 5e-5: the
  sphere's Hertz approach plus D P/(E* R), D = -0.5321 - 0.0330 ln(a/R)
  (docs/validation/sphere-contact-law.md), the disk's
  delta = x (ln(4/x) + C) R, C = -2 ln 2 - (1 + nu2)/4 (Gerl & Zippelius
  1999). 5e-5 is the elastic contact tests' tolerance 3e-3 on D at
  a/R = 0.01, as a share of the approach (D (4/3) a/R). 'above': the
  largest load at least MARGIN above it and the body yielded.
"""
import argparse
import csv
import math
import sys

from hertz_yield import first_yield_pressure_ratio

parser = argparse.ArgumentParser()
parser.add_argument("directory")
parser.add_argument("--energy", type=float)
parser.add_argument("--yield", dest="yield_check", nargs=4)
args = parser.parse_args()

rows = list(csv.DictReader(open(f"{args.directory}/indentation.csv",
                                newline="")))
summary = next(csv.DictReader(
    open(f"{args.directory}/indentation_summary.csv", newline="")))
failures = 0


def report(ok, text):
    global failures
    failures += not ok
    print(f"{text}: {'ok' if ok else 'FAILED'}")


if args.energy is not None:
    worst = max(abs(float(r["energy_error"])) for r in rows)
    report(worst <= args.energy,
           f"energy identity: largest error {worst:.2e} (tolerance "
           f"{args.energy:.0e})")

if args.yield_check:
    body, y_over_e, side, margin = args.yield_check
    nu = 0.3
    ratio, _ = first_yield_pressure_ratio(body, nu)
    # Over E* or E2.
    p0 = ratio * float(y_over_e) * (1 if body == "plane-stress" else
                                    1 - nu * nu)
    if body == "sphere":
        load_yield = math.pi ** 2 * p0 ** 3 / 6
    else:
        load_yield = p0 ** 2
    largest = float(summary["largest_load"])
    work = float(summary["plastic_work"])
    print(f"{body}: Hertz's contact first yields at load {load_yield:.6e} "
          f"(p0/Y = {ratio:.5f}); largest load {largest / load_yield:.4f} "
          f"of it, plastic work {work:.3e}")
    if side == "below":
        report(largest <= (1 - float(margin)) * load_yield,
               "the largest load lies below first yield by the margin")
        report(work == 0.0, "no plastic work")
        residual = abs(float(summary["residual_delta_com"]))
        report(residual <= 1e-9 * float(summary["delta_max"]),
               f"residual indentation {residual:.2e} R vanishes")
        top = max(rows, key=lambda r: float(r["load"]))
        # The approach of hard contact: less the penalty's penetration.
        x = float(top["load"])
        delta = float(top["delta_com"]) - float(top["penetration"])
        if body == "sphere":
            a = (3 * math.pi * x / 4) ** (1 / 3)
            delta_hertz = (9 * math.pi ** 2 * x ** 2 / 16) ** (1 / 3)
            law = delta_hertz + math.pi * x * (-0.5321 - 0.0330 * math.log(a))
        else:
            nu2 = nu if body == "plane-stress" else nu / (1 - nu)
            law = x * (math.log(4 / x) - 2 * math.log(2) - (1 + nu2) / 4)
        report(abs(delta / law - 1) <= 5e-5,
               f"loading point's approach {delta:.8e} R against the elastic "
               f"law's {law:.8e} R ({delta / law - 1:.1e})")
    else:
        report(largest >= (1 + float(margin)) * load_yield,
               "the largest load lies above first yield by the margin")
        report(work > 0.0, "the body yielded")
sys.exit(1 if failures else 0)
