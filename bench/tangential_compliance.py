#!/usr/bin/python3
"""The tables of docs/validation/tangential-compliance.md: task 'tangential
contact' against Cattaneo's disk and Mindlin's sphere.

usage: bench/tangential_compliance.py [--diskimpact build/diskimpact]
                                      [--work output/tangential_compliance]
                                      [--part disk|sphere|all] [--reuse]

disk: params/tangential_contact.prm (plane strain, nu = 0.3, P = 1e-4 pi E2
R, mu = 0.5) with 8, 16 and 32 elements across Hertz's half-width, on one
rank: the rigid motion at the contact point over Cattaneo's law, and the
stick zone's edge, for q = Q/(mu P) from 0.01 to 0.95 (about 1 minute).

sphere: params/tangential_contact_sphere.prm (the half sphere in 3D, mu =
0.5, q = 0.01) at the loads 1e-4, 1e-5, 1e-6 and nu = 0.3, 0.45, on two
ranks: the initial tangential compliance over Mindlin's (about 20
minutes).
"""
import argparse
import csv
import os
import re
import subprocess
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run(diskimpact, prm_text, directory, ranks, reuse=False):
    """Run diskimpact on prm_text in directory (with reuse, only if it has no
    table yet); return the table's rows and the run's seconds."""
    table = os.path.join(directory, "output", "tangential_law.csv")
    if reuse and os.path.exists(table):
        return list(csv.DictReader(open(table, newline=""))), 0.
    os.makedirs(directory, exist_ok=True)
    prm = os.path.join(directory, "case.prm")
    with open(prm, "w") as f:
        f.write(prm_text)
    command = [diskimpact, prm]
    if ranks > 1:
        command = ["mpirun", "-np", str(ranks)] + command
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    start = time.time()
    with open(os.path.join(directory, "run.log"), "w") as log:
        subprocess.run(command, cwd=directory, stdout=log,
                       stderr=subprocess.STDOUT, check=True, env=env)
    rows = list(csv.DictReader(open(table, newline="")))
    return rows, time.time() - start


def setting(text, entry, value):
    """text with 'set <entry> = ...' replaced by value."""
    pattern = re.compile(r"(set %s\s*=).*" % re.escape(entry))
    assert pattern.search(text), entry
    return pattern.sub(lambda m: m.group(1) + " " + value, text)


def disk(diskimpact, work, reuse):
    base = open(os.path.join(ROOT, "params", "tangential_contact.prm")).read()
    base = setting(base, "Output directory", "output")
    results = {}
    for n in (8, 16, 32):
        text = setting(base, "Elements across contact", str(n))
        results[n], seconds = run(diskimpact, text,
                                  os.path.join(work, f"disk_{n}"), 1, reuse)
        print(f"disk, {n} elements across: {seconds:.0f} s")
    print("\n| Q/(μP) | δ_c/R, 32 across | Cattaneo | δ_c/Cattaneo − 1: 8 | 16 | 32 "
          "| Rθ/δ_c | c/a | √(1 − q) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for i, r in enumerate(results[32]):
        theory = float(r["theory_displacement"])
        errors = " | ".join(
            f"{float(results[n][i]['contact_displacement']) / theory - 1:+.1e}"
            for n in (8, 16, 32))
        fe = float(r["contact_displacement"])
        print(f"| {float(r['tangential_load']):.2f} | {fe:.5e} | {theory:.5e} | "
              f"{errors} | {float(r['rotation']) / fe:+.2f} | "
              f"{float(r['stick_radius']):.3f} | "
              f"{float(r['theory_stick_radius']):.3f} |")


def sphere(diskimpact, work, reuse):
    base = open(os.path.join(ROOT, "params",
                             "tangential_contact_sphere.prm")).read()
    base = setting(base, "Output directory", "output")
    base = setting(base, "Loads", "1e-4, 1e-5, 1e-6")
    base = setting(base, "Tangential loads", "0.01")
    print("\n| ν | β | load | a/R | δ_c/Mindlin − 1 | Rθ/δ_c | c/a "
          "| k_n/(2E*a) | k_t/k_n | 2(1 − ν)/(2 − ν) | a/h | DoFs |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for nu in (0.3, 0.45):
        text = setting(base, "Poisson ratio", str(nu))
        rows, seconds = run(diskimpact, text,
                            os.path.join(work, f"sphere_nu{nu}"), 2, reuse)
        beta = (1 - 2 * nu) / (2 * (1 - nu))
        for r in rows:
            fe = float(r["contact_displacement"])
            a, q = float(r["hertz_half_width"]), float(r["tangential_load"])
            k_n = float(r["normal_stiffness"])
            # The initial stiffness: the secant at q over Mindlin's secant
            # shape (1 - (1 - q)^(2/3)) / (2q/3).
            k_t = float(r["tangential_stiffness"]) * (
                (1 - (1 - q) ** (2 / 3)) / (2 * q / 3))
            print(f"| {nu} | {beta:.3f} | {float(r['load']):.0e} | {a:.4f} | "
                  f"{fe / float(r['theory_displacement']) - 1:+.4f} | "
                  f"{float(r['rotation']) / fe:+.2f} | "
                  f"{float(r['stick_radius']):.3f} | {k_n / (2 * a):.4f} | "
                  f"{k_t / k_n:.4f} | {2 * (1 - nu) / (2 - nu):.4f} | "
                  f"{float(r['elements_across']):.1f} | {r['n_dofs']} |")
        print(f"(nu = {nu}: {seconds:.0f} s on 2 ranks)")


parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
parser.add_argument("--diskimpact",
                    default=os.path.join(ROOT, "build", "diskimpact"))
parser.add_argument("--work",
                    default=os.path.join("output", "tangential_compliance"))
parser.add_argument("--part", choices=("disk", "sphere", "all"), default="all")
parser.add_argument("--reuse", action="store_true",
                    help="take the tables of earlier runs in --work")
args = parser.parse_args()
diskimpact = os.path.abspath(args.diskimpact)
if args.part in ("disk", "all"):
    disk(diskimpact, args.work, args.reuse)
if args.part in ("sphere", "all"):
    sphere(diskimpact, args.work, args.reuse)
