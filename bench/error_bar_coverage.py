#!/usr/bin/python3
"""Do the error bars hold? The 14 standard points of
docs/validation/elastic-disk-restitution.md.

For plane stress nu = 0.33 (params/impact_convergence.prm, quadratic, three
mesh levels) and plane strain nu2 = 0.9 (params/impact_convergence_plane_strain.prm,
quartic, two mesh levels) at v/c = 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.3:
runs the study as shipped (epsilon +- bar), then the same study with one
more mesh level, and prints whether the finer level's epsilon lies within
the shipped bar. Each study on 2 MPI ranks; prints one row per point and a
Markdown table at the end.

The model "quick" (params/impact_convergence_quick.prm, cubic, two mesh
levels: the two-second estimate) is run only when asked for, and so are the
sweeps' studies, "sweep-stress" and "sweep-strain" (params/sweep.prm and
params/sweep_plane_strain.prm as one study at each speed: mesh levels added
while the bar exceeds their 'Target error', or the time step of the last two
halved); for those, "one level finer" is one beyond the levels the study
chose, with its time step halved as often as the study's finest run, and
every level halving the element size (where the study raised the degree
instead, 'Degree levels from', the finer run is still the refined mesh).

usage: bench/error_bar_coverage.py [--speeds 0.005,0.1]
                                   [--models stress,strain,quick,sweep-stress,sweep-strain]
                                   [--diskimpact build/diskimpact]
       (build first; about 12 minutes for all 14 points on 2 cores)
"""
import argparse
import csv
import os
import re
import subprocess
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MODELS = {
    "stress": ("plane stress nu = 0.33", "params/impact_convergence.prm"),
    "strain": ("plane strain nu2 = 0.9", "params/impact_convergence_plane_strain.prm"),
    "quick": ("plane stress nu = 0.33, two cubic levels",
              "params/impact_convergence_quick.prm"),
    "sweep-stress": ("plane stress nu = 0.33, sweep, cubic, target 1e-3", "params/sweep.prm"),
    "sweep-strain": ("plane strain nu2 = 0.9, sweep, quartic, target 1e-3",
                     "params/sweep_plane_strain.prm"),
}


def study(diskimpact, template, velocity, directory, levels=None, halvings=0):
    """Run the study of @template at @velocity (a sweep's file as one study)
    with its own mesh levels, or with exactly @levels, no target error and
    the base time step halved @halvings times; return (mesh levels run, the
    time step halvings of its finest run, wall seconds)."""
    text = open(os.path.join(ROOT, template)).read()
    text = re.sub(r"set Task\s*=\s*sweep", "set Task = impact convergence", text)
    text = re.sub(r"set Velocities\s*=.*", f"set Velocity = {velocity}", text)
    text = re.sub(r"\n\s*set (?:Error estimate|Convergence study per point)\s*=.*", "", text)
    if levels is not None:
        text = re.sub(r"set Mesh levels\s*=\s*\d+", f"set Mesh levels = {levels}", text)
        text = re.sub(r"set Target error\s*=.*", "set Target error = 0", text)
        text = re.sub(r"set Largest time step halvings\s*=.*",
                      "set Largest time step halvings = 0", text)
        text = re.sub(r"set Halve first above\s*=.*", "set Halve first above = 0", text)
        # the finer level halves the element size, also where the study
        # raised the degree instead (a check independent of that choice)
        text = re.sub(r"set Degree levels from\s*=.*", "set Degree levels from = 0", text)
        fraction = float(re.search(r"set Time step fraction\s*=\s*([0-9.eE+-]+)", text)[1])
        text = re.sub(r"set Time step fraction\s*=.*",
                      f"set Time step fraction = {fraction * 0.5 ** halvings!r}", text)
    text = re.sub(r"set Velocity\s*=\s*[0-9.eE+-]+", f"set Velocity = {velocity}", text)
    text = re.sub(r"set Output directory\s*=.*", f"set Output directory = {directory}", text)
    prm = os.path.join(directory + ".prm")
    open(prm, "w").write(text)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    start = time.time()
    subprocess.run(["mpirun", "-np", "2", diskimpact, prm],
                   check=True, stdout=subprocess.DEVNULL, env=env)
    seconds = time.time() - start
    runs = list(csv.DictReader(open(os.path.join(directory, "impact_convergence.csv"))))
    mesh = [(int(r["level"]), int(r["time_halvings"])) for r in runs
            if r["factor"] in ("base", "mesh")]
    return max(mesh)[0] + 1, max(mesh)[1], seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--speeds", default="0.005,0.01,0.02,0.05,0.1,0.2,0.3")
    parser.add_argument("--models", default="stress,strain")
    parser.add_argument("--diskimpact", default=os.path.join(ROOT, "build", "diskimpact"))
    args = parser.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for model in args.models.split(","):
            name, template = MODELS[model]
            for v in args.speeds.split(","):
                shipped = os.path.join(work, f"{model}_{v}")
                finer = shipped + "_finer"
                shipped_levels, halvings, seconds = study(args.diskimpact, template, v, shipped)
                total = next(r for r in csv.DictReader(open(os.path.join(shipped, "epsilon_estimate.csv")))
                             if r["factor"] == "total")
                epsilon, bar = float(total["limit"]), float(total["error"])
                levels, _, finer_seconds = study(args.diskimpact, template, v, finer,
                                                 shipped_levels + 1, halvings)
                runs = list(csv.DictReader(open(os.path.join(finer, "impact_convergence.csv"))))
                finest = next(float(r["epsilon"]) for r in runs
                              if r["factor"] == "mesh" and int(r["level"]) == levels - 1)
                row = (name, v, epsilon, bar, seconds, finest, abs(finest - epsilon),
                       abs(finest - epsilon) <= bar, finer_seconds)
                rows.append(row)
                print(f"{name}, v = {v} c: {epsilon:.8f} +- {bar:.2e} "
                      f"({shipped_levels} levels, time step halved {halvings} more times, "
                      f"{seconds:.1f} s); "
                      f"level {levels - 1}: {finest:.8f}, distance {row[6]:.2e}, "
                      f"{'inside' if row[7] else 'OUTSIDE'} ({finer_seconds:.1f} s)", flush=True)
    print("\n| model | v/c | ε ± bar (shipped) | wall | one level finer | distance | inside |")
    print("|---|---|---|---|---|---|---|")
    for name, v, eps, bar, s, fine, dist, inside, _ in rows:
        print(f"| {name} | {v} | {eps:.6f} ± {bar:.1e} | {s:.1f} s | {fine:.6f} | {dist:.1e} | "
              f"{'yes' if inside else 'no'} |")
    print(f"\n{sum(r[7] for r in rows)} of {len(rows)} bars contain the finer level")


if __name__ == "__main__":
    main()
