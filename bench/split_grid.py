#!/usr/bin/python3
"""epsilon on a grid of mesh level m and time level t: where the split runs'
two parts, d_t and d_h, come from.

A sweep's parameter file (params/sweep.prm, params/sweep_plane_strain.prm) is
run as a convergence study with its base set to mesh level m (global
refinements + m, elements across the contact * 2^m, grading / 2^m, time step
/ 2^m) and 'Time step levels' for the time levels t = m ... m + n - 1 (time
step / 2^t), one study per speed and mesh level, on 2 MPI ranks. Prints
epsilon per cell, then per speed the split's parts at mesh level 1,
d_t = eps(0, t) - eps(0, t - 1) and d_h = eps(1, t) - eps(0, t), and the bar
3 (|d_t| + |d_h|), at t = 1 (the study's second level) and t = 2 (its time
step halved once): what decides between a time step halving and a mesh
level (docs/theory/impact-method.md).

usage: bench/split_grid.py PRM --speeds 0.005,0.1 [--mesh-levels 0,1]
                           [--time-levels 3] [--diskimpact build/diskimpact]
       (mesh level 0 with 3 time levels and 1 with 2 at one quartic
       plane-strain speed: about 5 s on 2 cores)
"""
import argparse
import csv
import os
import re
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def study_on_mesh_level(diskimpact, template, velocity, m, time_levels, directory):
    """epsilon at time levels m ... m + time_levels - 1 on mesh level m."""
    text = open(template).read()
    scale = {"Global refinements": lambda x: str(int(x) + m),
             "Elements across contact": lambda x: str(int(x) * 2 ** m),
             "Grading": lambda x: repr(float(x) / 2 ** m),
             "Time step fraction": lambda x: repr(float(x) / 2 ** m)}
    for name, change in scale.items():
        text = re.sub(rf"(set {name}\s*=\s*)(\S+)", lambda g: g[1] + change(g[2]), text)
    text = re.sub(r"set Task\s*=.*", "set Task = impact convergence", text)
    text = re.sub(r"set Velocities\s*=.*", f"set Velocity = {velocity}", text)
    text = re.sub(r"\n\s*set (Error estimate|Convergence study per point|Target error|Largest mesh levels|"
                  r"Separate time step error|Largest time step halvings)\s*=.*", "", text)
    text = re.sub(r"set Mesh levels\s*=.*",
                  f"set Mesh levels = 1\n  set Time step levels = {time_levels}", text)
    text = re.sub(r"set Output directory\s*=.*", f"set Output directory = {directory}", text)
    open(directory + ".prm", "w").write(text)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    subprocess.run(["mpirun", "-np", "2", diskimpact, directory + ".prm"],
                   check=True, stdout=subprocess.DEVNULL, env=env)
    runs = csv.DictReader(open(os.path.join(directory, "impact_convergence.csv")))
    return {m + int(r["level"]): float(r["epsilon"]) for r in runs
            if r["factor"] in ("base", "time step")}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("prm")
    parser.add_argument("--speeds", required=True)
    parser.add_argument("--mesh-levels", default="0,1")
    parser.add_argument("--time-levels", type=int, default=3,
                        help="time levels on mesh level 0 (one fewer per mesh level)")
    parser.add_argument("--diskimpact", default=os.path.join(ROOT, "build", "diskimpact"))
    args = parser.parse_args()
    grid = {}
    with tempfile.TemporaryDirectory() as work:
        for v in args.speeds.split(","):
            for m in map(int, args.mesh_levels.split(",")):
                n = max(1, args.time_levels - m)
                cells = study_on_mesh_level(args.diskimpact, os.path.abspath(args.prm), v, m, n,
                                            os.path.join(work, f"v{v}_m{m}"))
                grid.update({(v, m, t): e for t, e in cells.items()})
                print(f"v/c = {v}, mesh level {m}: " +
                      ", ".join(f"t = {t}: {e:.8f}" for t, e in sorted(cells.items())), flush=True)
    print("\n| v/c | d_t, t = 1 | d_h, t = 1 | bar | d_t, t = 2 | d_h, t = 2 | bar |")
    print("|---|---|---|---|---|---|---|")
    for v in args.speeds.split(","):
        cells = []
        for t in (1, 2):
            try:
                d_t = grid[v, 0, t] - grid[v, 0, t - 1]
                d_h = grid[v, 1, t] - grid[v, 0, t]
                cells.append(f"{d_t:+.1e} | {d_h:+.1e} | {3 * (abs(d_t) + abs(d_h)):.1e}")
            except KeyError:
                cells.append("– | – | –")
        print(f"| {v} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
