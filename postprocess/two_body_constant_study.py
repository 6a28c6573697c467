#!/usr/bin/python3
"""The constants of the two-disk contact law, measured with error bars,
against the law derived in docs/theory/two-body-law.md.

Two half disks (plane strain) pressed together by equal and opposite
uniform body forces of total P (task 'quasistatic contact' with
'Kind = body' in subsection Partner). The approach of the centres of mass
gives the pair's constant

    C_pair = pi E_eff delta / P - 2 ln(4 R_eff / a),   a^2 = 4 P R_eff / (pi E_eff),

to compare with C_eff = sum_i w_i [C_i + 2 ln(R_i / R_eff)], w_i = E_eff / E_i,
C_i = -2 ln 2 - (1 + nu2_i) / 4 (docs/theory/disk-contact-constants.md);
each body's share of the approach (its contact centre relative to its
centre of mass) gives its own C_i at the common a, which the derivation
says is its wall constant.

Configurations: R2/R1 = 1, 1/2, 1/4 for pair A (both E = 1, nu = 0.3) and
pair B (partner E = 3, nu = 0.2). Method of postprocess/contact_constant_study.py,
per configuration: a probe run finds h_contact, then two loads x and 4x
(x = P/(pi E2 R1) near 1e-6) put the pair's Hertz half-width a on a mesh node
(a = 1.5 n h_contact); runs at n = 16, 32 elements across the contact,
grading 0.075, penalty factors 400, 1600, 6400, and n = 16 at grading 0.0375.
The value is the n = 32 result extrapolated linearly in 1/kappa and in the
load; its uncertainty the sum of the mesh, grading, penalty-fit and load
terms (as for the wall).

usage: two_body_constant_study.py [--diskimpact build/diskimpact] [-o DIR]
"""
import argparse
import csv
import os
import subprocess
import time

from contact_constant_study import (FINE_GRADING, GRADING, KAPPAS, MESHES, NUMERICS,
                                    error_budget)

TARGET_LOAD = 1e-6
RATIOS = [1.0, 0.5, 0.25]
PAIRS = {"A": dict(E2=1.0, nu2=0.3), "B": dict(E2=3.0, nu2=0.2)}
CONSTANTS = ("C_pair", "C_body", "C_partner")
EXACT = {"C_pair": "C_eff", "C_body": "C_body_wall", "C_partner": "C_partner_wall"}

PRM = """set Task = quasistatic contact
set Output directory = {out}
subsection Geometry
  set Domain = half disk
  set Global refinements = 2
end
subsection Material
  set Plane model = plane strain
  set Young modulus = 1
  set Poisson ratio = 0.3
end
subsection Partner
  set Kind = body
  set Radius = {ratio}
  subsection Material
    set Young modulus = {E2}
    set Poisson ratio = {nu2}
  end
end
""" + NUMERICS


def run(exe, work, loads, **p):
    name = "pair_" + "_".join(str(v) for v in p.values())
    out = os.path.join(work, name)
    prm = out + ".prm"
    with open(prm, "w") as f:
        f.write(PRM.format(out=out, loads=", ".join(repr(x) for x in loads), **p))
    subprocess.run([exe, prm], check=True, stdout=subprocess.DEVNULL)
    rows = list(csv.DictReader(open(os.path.join(out, "contact_law.csv"))))
    return [{k: float(v) for k, v in r.items()} for r in rows]


def node_loads(exe, work, pair):
    """Two loads x, 4x near TARGET_LOAD with a = 1.5 n h_contact."""
    probe = run(exe, work, [TARGET_LOAD], n_across=MESHES[0], grading=0.3,
                kappa=KAPPAS[0], **pair)[0]
    a_over_h = probe["hertz_half_width"] / probe["h_contact"]
    x = TARGET_LOAD * (1.5 * MESHES[0] / a_over_h) ** 2  # a ~ sqrt(P)
    return [x, 4.0 * x]


def study(exe, work, name, ratio):
    pair = dict(ratio=ratio, **PAIRS[name])
    loads = node_loads(exe, work, pair)
    runs = {(n, k): run(exe, work, loads, n_across=n, grading=GRADING, kappa=k, **pair)
            for n in MESHES for k in KAPPAS}
    fine = run(exe, work, loads[:1], n_across=MESHES[0], grading=FINE_GRADING,
               kappa=KAPPAS[-1], **pair)[0]
    node = max(abs(r["hertz_half_width"] / r["h_contact"] - 1.5 * n)
               for (n, _), rs in runs.items() for r in rs)
    results = []
    for constant in CONSTANTS:
        value, parts = error_budget(runs, fine, constant)
        exact = runs[(MESHES[0], KAPPAS[0])][0][EXACT[constant]]
        results.append(dict(pair=name, radius_ratio=ratio, constant=constant,
                            value=value, uncertainty=sum(parts.values()),
                            derived=exact, deviation=value - exact, **parts,
                            load_x=loads[0], a_over_h_offset=node))
    return results


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--diskimpact", default="build/diskimpact")
    parser.add_argument("-o", "--output", default="output/two_body_constants")
    a = parser.parse_args()
    start = time.time()
    os.makedirs(a.output, exist_ok=True)
    exe = os.path.abspath(a.diskimpact)
    table = []
    for name in PAIRS:
        for ratio in RATIOS:
            rows = study(exe, a.output, name, ratio)
            for r in rows:
                print(f"pair {name} R2/R1 = {ratio:<5} {r['constant']:9s} "
                      f"{r['value']:+.6f} +- {r['uncertainty']:.1e} (mesh "
                      f"{r['mesh']:.1e}, grading {r['grading']:.1e}, 1/kappa fit "
                      f"{r['penalty']:.1e}, load {r['load']:.1e}); derived "
                      f"{r['derived']:+.6f}, difference {r['deviation']:+.1e}",
                      flush=True)
            if rows[0]["a_over_h_offset"] > 1e-3:
                print(f"warning: a/h_contact differs from 1.5 n by "
                      f"{rows[0]['a_over_h_offset']:.1e}: the contact edge is not "
                      "on a node")
            table.extend(rows)
    path = os.path.join(a.output, "two_body_constants.csv")
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(table[0]))
        w.writeheader()
        w.writerows(table)
    print(f"wrote {path} ({time.time() - start:.0f} s)")


if __name__ == "__main__":
    main()
