#!/usr/bin/python3
"""Which discretization error makes the convergence of epsilon irregular?

One impact (plane stress nu = 0.33, v = 0.1c, half disk, Q2), refined in
one discretization parameter at a time from a coarse base (1 global
refinement, 6 elements across the contact, grading 0.6, penalty factor 100,
time step fraction 0.01):

  time step        Delta t halved, everything else fixed (penalty law)
  time step, exp.  the same with the smooth exponential wall law, alpha = 100
  time step, red.  the same with the penalty law and mass redistribution
                   (the contact edge without inertia)
  penalty          kappa doubled at a time step fine enough for it
  far field        one more global refinement (the contact zone's mesh fixed)
  contact mesh     the elements across the contact doubled (k = kappa E2/h
                   grows with them)
  end margin       the time run after the force returned to zero
  Newton tolerance the contact Newton's stopping tolerance, at a fine step

For each: epsilon, the differences of successive values and the observed
orders p = log2(d_{i-1}/d_i) (clean convergence: the same p along the
sequence). Writes the table as CSV and, with --plot, the figure of
docs/theory/impact-accuracy.md.

usage: bench/error_sources.py [-o error_sources.csv] [--plot PNG]
                              [--only NAME ...]
       (build first; about 2 minutes on one core)
"""
import argparse
import csv
import math
import os
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "diskimpact")

BASE = {
    "Geometry": {"Domain": "half disk", "Global refinements": "1"},
    "Material": {"Plane model": "plane stress", "Poisson ratio": "0.33"},
    "Contact": {"Penalty factor": "100"},
    "Impact": {"Velocity": "0.1", "Elements across contact": "6",
               "Grading": "0.6", "Number of projected modes": "0",
               "Output interval": "0"},
    "Time stepping": {"Time step fraction": "0.01"},
}

FRACTIONS = [0.02, 0.01, 0.005, 0.0025, 0.00125, 0.000625]
# name: (the entry refined, its values, the entries set beside it)
SEQUENCES = {
    "time step": ("Time stepping/Time step fraction", FRACTIONS, {}),
    "time step, exponential law": (
        "Time stepping/Time step fraction", FRACTIONS,
        {"Contact/Law": "exponential", "Contact/Potential stiffness": 100}),
    "time step, redistributed mass": (
        "Time stepping/Time step fraction", FRACTIONS,
        {"Time stepping/Contact mass": "redistributed"}),
    "penalty": ("Contact/Penalty factor", [50, 100, 200, 400, 800],
                {"Time stepping/Time step fraction": 0.00125}),
    "far field": ("Geometry/Global refinements", [0, 1, 2, 3, 4],
                  {"Time stepping/Time step fraction": 0.0025}),
    "contact mesh": ("Impact/Elements across contact", [6, 12, 24, 48],
                     {"Time stepping/Time step fraction": 0.0025}),
    "end margin": ("Impact/Margin", [0.1, 0.2, 0.4, 0.8],
                   {"Time stepping/Time step fraction": 0.0025}),
    "Newton tolerance": ("Time stepping/Newton tolerance",
                         [1e-10, 1e-11, 1e-12, 1e-13, 1e-14],
                         {"Time stepping/Time step fraction": 0.000625}),
}


def run(overrides):
    """Epsilon and wall time of one impact with @p overrides of BASE."""
    sections = {s: dict(e) for s, e in BASE.items()}
    for key, value in overrides.items():
        section, entry = key.split("/")
        sections.setdefault(section, {})[entry] = str(value)
    with tempfile.TemporaryDirectory() as work:
        text = f"set Task = impact\nset Output directory = {work}/out\n"
        for section, entries in sections.items():
            text += f"subsection {section}\n"
            text += "".join(f"  set {e} = {v}\n" for e, v in entries.items())
            text += "end\n"
        with open(os.path.join(work, "run.prm"), "w") as f:
            f.write(text)
        start = time.time()
        result = subprocess.run([EXE, os.path.join(work, "run.prm")],
                                capture_output=True, text=True)
        if result.returncode != 0:
            sys.exit(f"error_sources: {overrides}: {result.stderr.strip()}")
        with open(os.path.join(work, "out", "summary.csv")) as f:
            row = next(csv.DictReader(f))
        return float(row["epsilon"]), int(row["n_dofs"]), time.time() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-o", "--output", default="error_sources.csv")
    parser.add_argument("--plot", help="PNG of the differences and orders")
    parser.add_argument("--only", nargs="+", choices=list(SEQUENCES),
                        metavar="NAME", help="run only these sequences")
    args = parser.parse_args()
    rows = []
    for name, (entry, parameters, fixed) in SEQUENCES.items():
        if args.only and name not in args.only:
            continue
        values = []
        for level, parameter in enumerate(parameters):
            epsilon, dofs, seconds = run({**fixed, entry: parameter})
            values.append(epsilon)
            d = values[-1] - values[-2] if level > 0 else math.nan
            d_before = values[-2] - values[-3] if level > 1 else math.nan
            order = (math.log2(abs(d_before / d))
                     if level > 1 and d != 0 and d_before / d > 0
                     else math.nan)
            rows.append({"sequence": name, "level": level,
                         "parameter": parameter,
                         "n_dofs": dofs, "epsilon": f"{epsilon:.9f}",
                         "difference": "" if level == 0 else f"{d:.3e}",
                         "observed_order": "" if math.isnan(order)
                         else f"{order:.2f}",
                         "wall_time": f"{seconds:.1f}"})
            print(f"{name:28s} {rows[-1]['parameter']!s:>9} "
                  f"eps = {epsilon:.9f}  d = {rows[-1]['difference']:>10}  "
                  f"p = {rows[-1]['observed_order']:>5}  ({seconds:.1f} s)",
                  flush=True)
    with open(args.output, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    if args.plot:
        plot(rows, args.plot)


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for index, name in enumerate(SEQUENCES):
        colour = colours[index % len(colours)]
        mine = [r for r in rows if r["sequence"] == name and r["difference"]
                and abs(float(r["difference"])) > 1e-10]
        if not mine:
            left.plot([], [], " ", label=f"{name}: |d| < 1e-10")
            continue
        levels = [r["level"] for r in mine]
        left.semilogy(levels, [abs(float(r["difference"])) for r in mine],
                      "o-", color=colour, label=name)
        signs = [float(r["difference"]) < 0 for r in mine]
        left.semilogy([l for l, s in zip(levels, signs) if s],
                      [abs(float(r["difference"]))
                       for r, s in zip(mine, signs) if s],
                      "kx", ms=8)
        ordered = [r for r in mine if r["observed_order"]]
        right.plot([r["level"] for r in ordered],
                   [float(r["observed_order"]) for r in ordered], "o-",
                   color=colour, label=name)
    left.set_ylim(1e-7, 3e-3)
    left.set_xlabel("refinement level (parameter halved, doubled)")
    left.set_ylabel("|ε_i − ε_{i−1}|  (× : negative)")
    left.legend(fontsize=8)
    right.axhspan(1.75, 2.25, color="0.9")
    right.axhspan(0.75, 1.25, color="0.9")
    right.set_ylim(-3, 5)
    right.legend(fontsize=8)
    right.set_xlabel("refinement level")
    right.set_ylabel("observed order log2(d_{i−1}/d_i)")
    fig.suptitle("ε at v = 0.1c, plane stress ν = 0.33: one error source "
                 "at a time")
    fig.tight_layout()
    fig.savefig(path, dpi=90)


if __name__ == "__main__":
    main()
