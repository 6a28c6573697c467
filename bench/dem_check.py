#!/usr/bin/python3
"""diskimpact's restitution law in real DEM codes.

Reads the results of task 'restitution law' (a sphere, 'Units = SI') in
DIR: restitution_law.json, restitution_law.csv and the DEM inputs dem/.
Runs a head-on collision of two such spheres (equivalent to the rigid
wall) with bench/dem_collision.py:
  LIGGGHTS, dem/liggghts.txt (Hertz, constant epsilon): at the reference
            speed and at the smallest and largest speed of the table;
  LAMMPS,   dem/lammps.txt (Hertz with viscoelastic damping, Ramírez et al.'s
            law with the fitted A): at every speed of the table;
  Yade,     dem/yade.py (ViscElMat, a linear spring-dashpot: constant
            epsilon and contact time): as LIGGGHTS, if yade is installed
            (--yade installs it).
Prints epsilon and the contact time of the DEM code beside diskimpact's,
and fails (exit 1) unless LIGGGHTS (and Yade, where it ran) reproduces
epsilon at the reference speed within --tolerance (1e-3).

usage: bench/dem_check.py DIR [--tolerance 1e-3] [--yade]
       (installs Debian's liggghts and lammps if missing)
"""
import argparse
import csv
import json
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import dem_collision  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("directory")
    parser.add_argument("--tolerance", type=float, default=1e-3)
    parser.add_argument("--yade", action="store_true",
                        help="install Yade if missing (a larger install)")
    args = parser.parse_args()
    subprocess.run([os.path.join(os.path.dirname(__file__),
                                 "dem_check_deps.sh")] +
                   (["--yade"] if args.yade else []),
                   check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(args.directory, "restitution_law.json")) as f:
        law = json.load(f)
    if law["dem"] is None:
        sys.exit("dem_check: no DEM inputs in " + args.directory +
                 " (a sphere with 'Units = SI' writes them)")
    with open(os.path.join(args.directory, "restitution_law.csv")) as f:
        rows = list(csv.DictReader(f))
    scales = law["si_scales"]
    radius = scales["R_m"]
    density = float(open(os.path.join(args.directory, "dem",
                                      "liggghts.txt")).read()
                    .split("density ")[1].split()[0])
    v_ref = law["dem"]["reference_speed_si"]
    table = [(float(r["speed_si"]), float(r["epsilon"]),
              float(r["contact_time_si"])) for r in rows]
    table.sort()

    def run(code, snippet_name, speeds):
        snippet = open(os.path.join(args.directory, "dem",
                                    snippet_name)).read()
        print(f"{code} ({snippet_name}):")
        print("  speed [m/s]  eps diskimpact  eps DEM       difference  "
              "t_c diskimpact [s]  t_c DEM [s]  rel. difference")
        results = []
        for v, eps, tc in speeds:
            e_dem, tc_dem = dem_collision.collide(code, snippet, radius,
                                                  density, v)
            results.append((v, eps, e_dem))
            print(f"  {v:11.5g}  {eps:13.7f}  {e_dem:12.7f}  "
                  f"{e_dem - eps:+11.2e}  {tc:17.6e}  {tc_dem:11.6e}  "
                  f"{tc_dem / tc - 1:+.3e}")
        return results

    reference = (v_ref, law["dem"]["epsilon"], law["dem"]["contact_time_si"])
    extremes = [table[0], reference, table[-1]]
    checked = {"LIGGGHTS": run("liggghts", "liggghts.txt", extremes)}
    run("lammps", "lammps.txt", table)
    if shutil.which("yade"):
        checked["Yade"] = run("yade", "yade.py", extremes)
    else:
        print("yade: not installed, skipped (bench/dem_check.py --yade "
              "installs it)")
    failed = False
    for code, results in checked.items():
        error = abs(results[1][2] - results[1][1])
        print(f"{code} at the reference speed {v_ref:g} m/s: |eps_DEM - eps| "
              f"= {error:.2e} (tolerance {args.tolerance:g})")
        failed = failed or not error <= args.tolerance
    if failed:
        sys.exit("dem_check: a DEM code misses epsilon at the reference speed")


if __name__ == "__main__":
    main()
