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
            (--yade installs it);
  LIGGGHTS, dem/liggghts_thornton.txt (for a plastic sphere: Thornton's
            elastic-plastic model thornton_ning with the fitted yield ratio)
            at every speed of the table, against the model's epsilon
            (restitution_law.csv, epsilon_thornton_fit);
  Yade,     dem/yade_luding.py (for a plastic sphere: Luding's
            elastic-plastic LudingMat with the fitted kp / k1 and plasticity
            depth) likewise against epsilon_luding_fit, if yade is
            installed.
Prints epsilon and the contact time of the DEM code beside diskimpact's,
and fails (exit 1) unless LIGGGHTS (and Yade, where it ran) reproduces
epsilon at the reference speed within --tolerance (1e-3), and each
elastic-plastic contact the fitted model's epsilon at every speed within
--tolerance and, extrapolated from two time steps, within 1e-5. (Their
contact times count the flight to zero overlap that the plastic overlap
leaves after the force vanishes, unlike the finite elements'.)

For a disk (the law's DEM inputs are 2D, dem/lammps_2d.txt) the collisions
run in LAMMPS with 'dimension 2' at every speed of the table (the linear
spring-dashpot: constant epsilon and contact time), and the check is that
LAMMPS reproduces epsilon at the reference speed within --tolerance and its
contact time within 1e-3 (relative).

With --oblique SWEEP.csv (restitution.csv of diskimpact's task 'sweep'
over 'Angles of incidence' for the same sphere, in its own units: the
sphere in 3D, the same Poisson ratio and friction coefficient as the law)
it also runs the oblique wall impact in each code with the exported lines
(the tangential part included) at every angle of the sweep, at the sweep's
speed v/c times the law's c: and prints, per angle, the tangential
restitution e_t = v_t'/v_t, the spin R omega'/v_n and the rebound angle of
the code beside diskimpact's, and the largest differences. It fails if a
code's run fails or the sphere does not match the law.

usage: bench/dem_check.py DIR [--tolerance 1e-3] [--yade]
                              [--oblique SWEEP.csv]
       (installs Debian's liggghts and lammps if missing)
"""
import argparse
import csv
import json
import math
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
    parser.add_argument("--oblique", metavar="SWEEP_CSV",
                        help="diskimpact's oblique sweep of the same sphere")
    parser.add_argument("--oblique-speed", type=float, default=0.01,
                        help="the DEM's oblique impacts at this speed [m/s]")
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
    dimension = law["dem"].get("dimension", 3)
    density = float(law["parameters"]["Material"]["Density"])  # kg/m^3
    v_ref = law["dem"]["reference_speed_si"]
    table = [(float(r["speed_si"]), float(r["epsilon"]),
              float(r["contact_time_si"])) for r in rows]
    table.sort()
    # A plastic sphere's Thornton and Luding models, with their own epsilon
    # at each speed.
    thornton, luding = ([(float(r["speed_si"]), float(r[column]),
                          float(r["contact_time_si"]))
                         for r in sorted(rows, key=lambda r: float(r["speed_si"]))
                         if column in r]
                        for column in ("epsilon_thornton_fit",
                                       "epsilon_luding_fit"))

    def run(code, snippet_name, speeds):
        snippet = open(os.path.join(args.directory, "dem",
                                    snippet_name)).read()
        print(f"{code} ({snippet_name}):")
        print("  speed [m/s]  eps diskimpact  eps DEM       difference  "
              "t_c diskimpact [s]  t_c DEM [s]  rel. difference")
        results = []
        for v, eps, tc in speeds:
            e_dem, tc_dem = dem_collision.collide(code, snippet, radius,
                                                  density, v,
                                                  dimension=dimension)
            results.append((v, eps, e_dem, tc, tc_dem))
            print(f"  {v:11.5g}  {eps:13.7f}  {e_dem:12.7f}  "
                  f"{e_dem - eps:+11.2e}  {tc:17.6e}  {tc_dem:11.6e}  "
                  f"{tc_dem / tc - 1:+.3e}")
        return results

    reference = (v_ref, law["dem"]["epsilon"], law["dem"]["contact_time_si"])
    if dimension == 2:
        disk_check(args, law, table, reference, radius, density, run)
        return
    extremes = [table[0], reference, table[-1]]
    checked = {"LIGGGHTS": run("liggghts", "liggghts.txt", extremes)}
    run("lammps", "lammps.txt", table)
    if shutil.which("yade"):
        checked["Yade"] = run("yade", "yade.py", extremes)
    else:
        print("yade: not installed, skipped (bench/dem_check.py --yade "
              "installs it)")
    if args.oblique:
        codes = [("liggghts", "liggghts.txt"), ("lammps", "lammps.txt")]
        if shutil.which("yade"):
            codes.append(("yade", "yade.py"))
        oblique_check(args.directory, law, args.oblique, radius, density,
                      codes, args.oblique_speed)
    failed = False
    for code, results in checked.items():
        error = abs(results[1][2] - results[1][1])
        print(f"{code} at the reference speed {v_ref:g} m/s: |eps_DEM - eps| "
              f"= {error:.2e} (tolerance {args.tolerance:g})")
        failed = failed or not error <= args.tolerance
    if failed:
        sys.exit("dem_check: a DEM code misses epsilon at the reference speed")
    if thornton:
        dem = law["dem"]
        print(f"Thornton's model fitted: p_y = "
              f"{dem['limiting_pressure_si']:.6g} Pa, yield ratio "
              f"{dem['liggghts_thornton_ning_yield_ratio']:.6g}, v_y = "
              f"{dem['thornton_yield_speed_si']:.6g} m/s, largest residual "
              f"against the FE {law['thornton_fit']['max_residual']:.3g}")
        plastic_check(args, "liggghts", "liggghts_thornton.txt", thornton,
                      radius, density, run)
        if shutil.which("yade"):
            print(f"Luding's model fitted: kp / k1 = "
                  f"{law['luding_fit']['stiffness_ratio']:.6g}, v_p = "
                  f"{dem['luding_plastic_speed_si']:.6g} m/s, largest "
                  f"residual against the FE "
                  f"{law['luding_fit']['max_residual']:.3g}")
            plastic_check(args, "yade", "yade_luding.py", luding, radius,
                          density, run)


def plastic_check(args, code, snippet_name, model, radius, density, run):
    """A code's elastic-plastic contact (LIGGGHTS' thornton_ning, Yade's
    LudingMat) with the exported inputs against the fitted model's epsilon
    at every speed (the 'eps diskimpact' column is the model's here);
    exits 1 if a speed misses it by more than the tolerance, or by more
    than 1e-5 extrapolated from two time steps."""
    print("(eps diskimpact: the fitted model's epsilon; t_c diskimpact: the "
          "finite elements')")
    results = run(code, snippet_name, model)
    error = max(abs(e_dem - eps) for _, eps, e_dem, _, _ in results)
    print(f"{code} {snippet_name} against the model: largest |eps_DEM - "
          f"eps| = {error:.2e} (tolerance {args.tolerance:g})")
    # LIGGGHTS adds the overlap's increments with the stiffness at the
    # step's end, Yade's LudingMat its unloading stiffness from the largest
    # overlap of the step before, both first order in the step: halved
    # steps extrapolate to the model's closed form.
    snippet = open(os.path.join(args.directory, "dem", snippet_name)).read()
    fine = dem_collision.STEPS_PER_CONTACT * 2
    print(f"  extrapolated from {fine // 2} and {fine} steps per contact:")
    extrapolated_error = 0.0
    for v, eps, e_dem, _, _ in results:
        e_fine = dem_collision.collide(code, snippet, radius, density,
                                       v, steps_per_contact=fine)[0]
        e_limit = 2.0 * e_fine - e_dem
        extrapolated_error = max(extrapolated_error, abs(e_limit - eps))
        print(f"  {v:11.5g}  {eps:13.7f}  {e_limit:12.7f}  "
              f"{e_limit - eps:+11.2e}")
    print(f"{code} {snippet_name} extrapolated: largest |eps_DEM - eps| = "
          f"{extrapolated_error:.2e} (tolerance 1e-5)")
    if not (error <= args.tolerance and extrapolated_error <= 1e-5):
        sys.exit(f"dem_check: {code}'s {snippet_name} misses the fitted "
                 "model's epsilon")


def disk_check(args, law, table, reference, radius, density, run):
    """The disk's law in LAMMPS' 2D: every speed of the table and the
    reference speed head-on, then the oblique sweep if given; exits 1 if
    epsilon or the contact time at the reference speed is missed."""
    results = run("lammps", "lammps_2d.txt", sorted(table + [reference]))
    if args.oblique:
        oblique_check(args.directory, law, args.oblique, radius, density,
                      [("lammps", "lammps_2d.txt")], args.oblique_speed,
                      dimension=2)
    # The reference row: the smooth fit's epsilon, which the law exports.
    v, eps, e_dem, tc, tc_dem = next(r for r in results
                                     if r[:2] == reference[:2])
    eps_error, tc_error = abs(e_dem - eps), abs(tc_dem / tc - 1.0)
    print(f"LAMMPS (2D) at the reference speed {v:g} m/s: |eps_DEM - eps| = "
          f"{eps_error:.2e} (tolerance {args.tolerance:g}), contact time "
          f"{tc_error:.2e} (tolerance 1e-3)")
    if not (eps_error <= args.tolerance and tc_error <= 1e-3):
        sys.exit("dem_check: LAMMPS misses epsilon or the contact time at "
                 "the reference speed")


def oblique_check(directory, law, sweep_csv, radius, density, codes,
                  speed, dimension=3):
    """The oblique impacts of the sweep in each code; prints the table."""
    with open(sweep_csv, newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["status"] == "done"]
    if not rows:
        sys.exit(f"dem_check: no finished points in {sweep_csv}")
    nu = float(law["parameters"]["Material"]["Poisson ratio"])
    mu = float(law["dem"].get("friction_coefficient", 0.0))
    for r in rows:
        if (abs(float(r["poisson_ratio"]) - nu) > 1e-12 or
                abs(float(r["friction"]) - mu) > 1e-12):
            sys.exit(f"dem_check: the sweep {sweep_csv} has nu = "
                     f"{r['poisson_ratio']}, mu = {r['friction']}; the law "
                     f"has nu = {nu}, mu = {mu}")
    c = law["si_scales"]["c_m_per_s"]
    print(f"Oblique impacts: mu = {mu:g}, nu = {nu:g}, the sweep's speed "
          f"times c = {c:.6g} m/s")
    largest = {}
    for code, snippet_name in codes:
        snippet = open(os.path.join(directory, "dem", snippet_name)).read()
        print(f"{code} ({snippet_name}):")
        print("  angle   speed [m/s]  eps FE     eps DEM    e_t FE     "
              "e_t DEM    R w'/v_n FE  DEM      rebound FE  DEM")
        for r in rows:
            angle = float(r["angle"])
            v_n = float(r["velocity"]) * math.cos(math.radians(angle))
            fe = {"epsilon": float(r["epsilon_base"]),
                  "tangential_restitution": float(r["tangential_restitution"]),
                  "spin": float(r["spin_final"]) / v_n,
                  "rebound_angle": float(r["rebound_angle"])}
            dem = dem_collision.oblique(code, snippet, radius, density, speed,
                                        angle, dimension=dimension)
            for key in fe:
                largest[(code, key)] = max(largest.get((code, key), 0.0),
                                           abs(dem[key] - fe[key]))
            print(f"  {angle:5g}  {speed:11.5g}  {fe['epsilon']:.6f}  "
                  f"{dem['epsilon']:.6f}  "
                  f"{fe['tangential_restitution']:.6f}  "
                  f"{dem['tangential_restitution']:.6f}  "
                  f"{fe['spin']:9.5f}  {dem['spin']:9.5f}  "
                  f"{fe['rebound_angle']:9.4f}  {dem['rebound_angle']:9.4f}")
        print(f"  largest |DEM - FE|: epsilon "
              f"{largest[(code, 'epsilon')]:.2e}, e_t "
              f"{largest[(code, 'tangential_restitution')]:.2e}, spin "
              f"{largest[(code, 'spin')]:.2e}, rebound angle "
              f"{largest[(code, 'rebound_angle')]:.3f} degrees")


if __name__ == "__main__":
    main()
