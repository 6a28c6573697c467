#!/usr/bin/python3
"""epsilon(v) on one mesh: the standard impact (plane stress nu = 0.33, half
disk, Q2, 1 global refinement; the penalty law with factor 100 or as given,
the exponential law with stiffness 100, or the exact constraint) at many
nearby speeds, all on the mesh graded for one fixed half-width ('Graded
half-width'), so that only the speed changes. Mesh level L is that of the convergence study
(params/impact_convergence.prm): 6 * 2^L elements across the contact,
grading 0.6 / 2^L, time step fraction 0.01 / 2^L unless --fraction is given.

A smooth polynomial in v is fitted to epsilon(v); what it leaves is the
part of the discretization error that is not smooth in the data. Prints
the residual's rms and largest value, the point-to-point scatter (the rms
of the third differences over sqrt(20), the standard deviation of
independent noise) and the largest jump between neighbouring speeds beyond
the fitted trend (docs/theory/impact-accuracy.md, "ε on one mesh: the rough
part").
Each run also reports how many DoFs its contact was condensed on (every DoF
of the edge the contact ever reached); the speeds where that number grows,
where the contact zone's largest extent reaches one more node of the edge,
are printed, with the residual's largest Fourier components and the share
of its power at the period of those nodes.

usage: bench/fixed_mesh_scan.py --speeds 0.06 0.14 0.001 [--level 0]
           [--law penalty] [--penalty-factor 100] [--fraction F] [--scheme S]
           [--degree 2]
           [--fit-degree 6] [--graded-half-width 0.45] [--print] [--jobs 2]
           [-o scan.csv]
"""
import argparse
import concurrent.futures
import csv
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

CASE = """set Task = impact
set Output directory = {out}
subsection Geometry
  set Domain             = half disk
  set Global refinements = 1
end
subsection Material
  set Plane model   = plane stress
  set Poisson ratio = 0.33
end
subsection Finite element
  set Degree = {degree}
end
subsection Contact
  set Law                 = {law}
  set Penalty factor      = {kappa}
  set Potential stiffness = 100
end
subsection Impact
  set Velocity                = {v}
  set Elements across contact = {across}
  set Grading                 = {grading}
  set Graded half-width       = {width}
  set Output interval         = 0
  set Number of projected modes = 0
end
subsection Time stepping
  set Scheme             = {scheme}
  set Time step fraction = {fraction}
end
"""


def run(v, args, work):
    out = os.path.join(work, f"{v:.9f}")
    os.makedirs(out)
    prm = os.path.join(out, "case.prm")
    with open(prm, "w") as f:
        f.write(CASE.format(out=out, v=f"{v:.12g}", law=args.law,
                            fraction=args.fraction, width=args.graded_half_width,
                            across=6 << args.level,
                            grading=0.6 / (1 << args.level),
                            scheme=args.scheme, kappa=args.penalty_factor,
                            degree=args.degree))
    log = subprocess.run([args.diskimpact, prm], check=True,
                         stdout=subprocess.PIPE, text=True).stdout
    with open(os.path.join(out, "summary.csv")) as f:
        row = next(csv.DictReader(f))
    touched = re.search(r"(\d+) contact DoFs condensed", log)
    return (v, float(row["epsilon"]), int(row["n_dofs"]),
            int(touched.group(1)) if touched else 0)


def print_residual_periods(v, residual, touched):
    """The residual's three largest Fourier components over the evenly
    spaced speeds (period and share of the power), the mean speed interval
    between two edge nodes joining the contact, and the share of the power
    within 1.5 harmonics of that interval: near 1 if each node's joining
    makes the oscillation, near 0 if not."""
    power = np.abs(np.fft.rfft(residual - residual.mean())) ** 2
    harmonic = np.arange(len(power))
    span = (v[-1] - v[0]) * len(v) / (len(v) - 1)
    largest = [k for k in np.argsort(power)[::-1] if k > 0][:3]
    print("  largest Fourier components of the residual: " +
          ", ".join(f"period {span / k:.3g} c ({power[k] / power.sum():.2f})"
                    for k in largest))
    joins = v[1:][np.diff(touched) != 0]
    if len(joins) < 2:
        return
    period = np.diff(joins).mean()
    if period < 2. * (v[1] - v[0]):
        print(f"  one edge node per {period:.3g} c on average: shorter than two "
              "speed steps, so its share of the residual is not resolved")
        return
    near = np.abs(harmonic - span / period) <= 1.5
    print(f"  one edge node per {period:.3g} c on average; share of the residual's "
          f"power within 1.5 harmonics of that period: {power[near].sum() / power.sum():.2f}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--speeds", nargs=3, type=float, required=True,
                        metavar=("FIRST", "LAST", "STEP"))
    parser.add_argument("--law", default="penalty",
                        choices=["penalty", "constraint", "exponential"])
    parser.add_argument("--level", type=int, default=0,
                        help="the convergence study's mesh level (default 0)")
    parser.add_argument("--fraction", type=float,
                        help="'Time step fraction' (default 0.01 / 2^level)")
    parser.add_argument("--graded-half-width", type=float, default=0.45,
                        help="the mesh's 'Graded half-width' [R]")
    parser.add_argument("--penalty-factor", type=float, default=100.,
                        help="the penalty law's 'Penalty factor' (default 100)")
    parser.add_argument("--degree", type=int, default=2,
                        help="the elements' polynomial degree (default 2)")
    parser.add_argument("--scheme", default="energy conserving",
                        choices=["energy conserving", "newmark",
                                 "generalized alpha"])
    parser.add_argument("--fit-degree", type=int, default=6,
                        help="degree of the trend fitted in v (default 6)")
    parser.add_argument("--print", action="store_true",
                        help="print every speed's epsilon")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--diskimpact",
                        default=os.path.join(ROOT, "build", "diskimpact"))
    parser.add_argument("-o", "--output",
                        help="CSV: v, epsilon, residual, contact DoFs")
    args = parser.parse_args()
    if args.fraction is None:
        args.fraction = 0.01 / (1 << args.level)

    first, last, step = args.speeds
    speeds = list(np.round(np.arange(first, last + 0.5 * step, step), 12))
    if len(speeds) < args.fit_degree + 2:
        sys.exit(f"fixed_mesh_scan: {len(speeds)} speeds are too few for a "
                 f"degree-{args.fit_degree} fit")
    with tempfile.TemporaryDirectory() as work:
        with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
            rows = sorted(pool.map(lambda v: run(v, args, work), speeds))
    v = np.array([r[0] for r in rows])
    eps = np.array([r[1] for r in rows])
    dofs = {r[2] for r in rows}
    touched = np.array([r[3] for r in rows])
    if len(dofs) != 1:
        sys.exit("fixed_mesh_scan: the mesh changed with the speed "
                 f"({sorted(dofs)} DoFs)")
    trend = np.polynomial.Polynomial.fit(v, eps, args.fit_degree)(v)
    residual = eps - trend
    jumps = np.diff(residual)
    print(f"{args.law}, {args.scheme}, Q{args.degree}, mesh level {args.level}, time step fraction {args.fraction:g}, "
          f"{dofs.pop()} DoFs, {len(v)} speeds {v[0]:.9g} ... {v[-1]:.9g}")
    print(f"  residual from a degree-{args.fit_degree} fit: rms {residual.std():.2e}, "
          f"largest {np.abs(residual).max():.2e}")
    if len(v) >= 4:
        scatter = np.diff(eps, 3).std() / np.sqrt(20.)
        print(f"  point-to-point scatter: {scatter:.2e}")
    k = int(np.argmax(np.abs(jumps)))
    print(f"  largest jump between neighbours beyond the trend: {jumps[k]:+.2e} "
          f"(v = {v[k]:.9g} to {v[k + 1]:.9g}: epsilon {eps[k]:.8f}, {eps[k + 1]:.8f})")
    grows = [f"{v[i + 1]:.9g} ({touched[i]} to {touched[i + 1]})"
             for i in np.flatnonzero(np.diff(touched))]
    print(f"  contact DoFs: {touched[0]} at the first speed; one more edge node "
          f"reached at v = {', '.join(grows) if grows else 'none'}")
    print_residual_periods(v, residual, touched)
    if args.print:
        for row in zip(v, eps, residual, touched):
            print(f"  v = {row[0]:.9g}: epsilon = {row[1]:.8f}, residual {row[2]:+.2e}, "
                  f"contact DoFs {row[3]}")
    if args.output:
        with open(args.output, "w", newline="") as f:
            writer = csv.writer(f)
            writer.writerow(["velocity", "epsilon", "residual", "contact_dofs"])
            for row in zip(v, eps, residual, touched):
                writer.writerow([f"{row[0]:.9g}", f"{row[1]:.12g}", f"{row[2]:.6e}", row[3]])


if __name__ == "__main__":
    main()
