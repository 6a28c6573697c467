#!/usr/bin/python3
"""Oblique impacts of the elastic disk or sphere against rigid-body impulse theory.

Runs task 'sweep' on 2 ranks over the angles of incidence --angles
(degrees) at the speed --speed (0.02c), friction coefficient --mu (0.1):
  --body disk:   the whole disk, plane stress, nu = --poisson (0.3), Q2, the mesh of
                 tests/regression/impact_oblique_headon.prm; 20 angles from
                 2.5 to 65 by default;
  --body sphere: the half sphere in 3D, nu = --poisson, Q2, the mesh of
                 tests/regression/impact_oblique_sphere.prm; 10 angles from
                 5 to 65 by default.
Both with time steps of t_c/100 ('Time step fraction' 0.01).
Prints a Markdown table with, per angle:
  v_n = speed cos(angle), the normal speed;
  psi1 = 2 v_cp / (mu (1 + eps) v_n), the contact point's normalised
         incidence (gross sliding throughout for psi1 > 2 (1 + 1/k), k =
         I / (m R^2): 6 for the disk, 7 for the sphere);
  eps, the normal restitution;
  the centre of mass's tangential restitution e_t and the spin R omega'/v_n,
         the finite elements' beside rigid-body impulse theory's given eps
         (computed here, independently of diskimpact's own reference);
  the contact point's tangential restitution beta = -v_cp'/v_cp (theory:
         -1 + (1 + 1/k) mu (1 + eps) v_n / v_cp while sliding, 0 where it
         stops);
  psi2, the normalised rebound, and the friction work over E(0);
and writes the rows to WORK/oblique_<body>.csv; with --figure, psi2 against
psi1 to that PNG. Its last line is the sweep's wall time.

usage: bench/oblique_sweep.py [--body disk|sphere] [--mu 0.1] [--speed 0.02]
       [--poisson 0.3]
       [--angles 2.5 5 ...] [--work DIR] [--figure PNG]
       [--diskimpact build/diskimpact]
"""
import argparse
import csv
import math
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REGRESSION = os.path.join(HERE, "..", "tests", "regression")
# Per body: its base parameter file, k = I / (m R^2), the default angles and
# the figure's title.
BODIES = {
    "disk": {"base": os.path.join(REGRESSION, "impact_oblique_headon.prm"),
             "k": 0.5,
             "angles": [2.5, 5, 7.5, 10, 12.5, 15, 17.5, 20, 22.5, 25, 27.5,
                        30, 32.5, 35, 40, 45, 50, 55, 60, 65],
             "title": "elastic disk"},
    "sphere": {"base": os.path.join(REGRESSION, "impact_oblique_sphere.prm"),
               "k": 0.4,
               "angles": [5, 10, 15, 20, 25, 30, 35, 45, 55, 65],
               "title": "elastic sphere (3D)"}}


def sweep(diskimpact, work, body, mu, speed, angles, poisson):
    """The sweep on 2 ranks; its rows."""
    prm = os.path.join(work, f"oblique_{body}.prm")
    with open(prm, "w") as f:
        f.write(f"include {os.path.abspath(BODIES[body]['base'])}\n"
                "set Task = sweep\n"
                f"set Output directory = {os.path.abspath(work)}\n"
                "subsection Contact\n"
                f"  set Friction coefficient = {mu}\n"
                "end\n"
                "subsection Material\n"
                f"  set Poisson ratio = {poisson}\n"
                "end\n"
                "subsection Time stepping\n"
                "  set Time step fraction = 0.01\n"
                "end\n"
                "subsection Impact\n"
                f"  set Velocities = {speed}\n"
                "  set Angles of incidence = "
                + ", ".join(f"{a:g}" for a in angles) + "\n"
                "  set Convergence study per point = false\n"
                "  set Resume = false\n"
                "end\n")
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    subprocess.run(["mpirun", "-np", "2", diskimpact, prm], check=True,
                   stdout=subprocess.DEVNULL, env=env)
    with open(os.path.join(work, "restitution.csv"), newline="") as f:
        return [{k: float(v) if k != "status" and v else math.nan
                 for k, v in r.items()} for r in csv.DictReader(f)]


def rigid_body(k, mu, eps, vn, vt, spin):
    """Rigid-body impulse theory: v_t', omega' R and v_cp' of a round body
    of moment of inertia k m R^2."""
    vcp = vt - spin  # spin as omega R
    jump = (1 + 1 / k) * mu * (1 + eps) * vn
    if jump < abs(vcp):  # slides throughout
        jt = -math.copysign(mu * (1 + eps) * vn, vcp)
    else:  # the contact point stops and stays stopped
        jt = -vcp / (1 + 1 / k)
    return vt + jt, spin - jt / k, vcp + (1 + 1 / k) * jt


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--body", choices=sorted(BODIES), default="disk")
    p.add_argument("--mu", type=float, default=0.1)
    p.add_argument("--speed", type=float, default=0.02)
    p.add_argument("--poisson", type=float, default=0.3)
    p.add_argument("--angles", type=float, nargs="+")
    p.add_argument("--work")
    p.add_argument("--figure")
    p.add_argument("--diskimpact",
                   default=os.path.join(HERE, "..", "build", "diskimpact"))
    args = p.parse_args()
    body = BODIES[args.body]
    k = body["k"]
    angles = args.angles or body["angles"]
    work = args.work or os.path.join("output", f"oblique_{args.body}")
    os.makedirs(work, exist_ok=True)
    start = time.time()
    rows = sweep(args.diskimpact, work, args.body, args.mu, args.speed,
                 angles, args.poisson)
    wall = time.time() - start

    table = []
    for s in rows:
        angle = s["angle"]
        vn = s["velocity"] * math.cos(math.radians(angle))
        vt = s["velocity"] * math.sin(math.radians(angle))
        eps = s["epsilon"]
        vt1, spin1, vcp1 = rigid_body(k, args.mu, eps, vn, vt, 0.)
        scale = 0.5 * args.mu * (1 + eps) * vn
        table.append({
            "angle": angle, "v_n": vn, "psi1": s["psi_incident"],
            "epsilon": eps,
            "e_t": s["tangential_restitution"], "e_t_rigid": vt1 / vt,
            "spin": s["spin_final"] / vn, "spin_rigid": spin1 / vn,
            "beta": s["contact_point_restitution"], "beta_rigid": -vcp1 / vt,
            "psi2": s["psi_rebound"], "psi2_rigid": vcp1 / scale,
            "friction_work": s["friction_work"],
            "energy_error": s["energy_error"]})
    with open(os.path.join(work, f"oblique_{args.body}.csv"), "w",
              newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(table[0]))
        writer.writeheader()
        writer.writerows(table)

    print(f"mu = {args.mu}, speed {args.speed} c; theory: rigid-body impulse "
          "theory with the computed epsilon")
    print("| angle | v_n | psi1 | eps | e_t | e_t theory | R omega'/v_n "
          "| theory | beta | beta theory | psi2 | psi2 theory "
          "| friction work |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in table:
        for key, value in r.items():  # no "-0.0000" for a zero
            if abs(value) < 5e-13:
                r[key] = 0.
        print(f"| {r['angle']:g} | {r['v_n']:.5f} | {r['psi1']:.3f} "
              f"| {r['epsilon']:.6f} "
              f"| {r['e_t']:.6f} | {r['e_t_rigid']:.6f} "
              f"| {r['spin']:.5f} | {r['spin_rigid']:.5f} "
              f"| {r['beta']:.4f} | {r['beta_rigid']:.4f} "
              f"| {r['psi2']:.3f} | {r['psi2_rigid']:.3f} "
              f"| {r['friction_work']:.4f} |")
    print(f"largest energy error {max(r['energy_error'] for r in table):.2e}")
    if args.figure:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(5.5, 4))
        psi1 = [r["psi1"] for r in table]
        ax.plot(psi1, [r["psi2"] for r in table], "o-",
                label="finite elements")
        ax.plot(psi1, [r["psi2_rigid"] for r in table], "k--",
                label="rigid-body impulse theory")
        ax.axhline(0, color="grey", lw=0.5)
        ax.axvline(2 * (1 + 1 / k), color="grey", lw=0.5, ls=":")
        ax.set_xlabel(r"$\psi_1 = 2 v_{cp} / (\mu (1 + \varepsilon) v_n)$")
        ax.set_ylabel(r"$\psi_2 = 2 v_{cp}' / (\mu (1 + \varepsilon) v_n)$")
        ax.set_title(f"{body['title']}, $\\nu$ = {args.poisson}, "
                     f"$\\mu$ = {args.mu}, "
                     f"$v$ = {args.speed} c")
        ax.legend()
        fig.tight_layout()
        fig.savefig(args.figure, dpi=120)
    print(f"{len(angles)} impacts in {wall:.1f} s (task 'sweep', "
          "2 ranks)")


if __name__ == "__main__":
    sys.exit(main())
