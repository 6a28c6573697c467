#!/usr/bin/python3
"""A study with 'Largest time step halvings' = 1: after two mesh levels and
the split run it halved the time step of both levels once (the time step's
part d_t of the last difference at least half the mesh's part d_h, the
bar 3 (|d_t| + |d_h|) above the target) instead of adding a mesh level;
epsilon is the finest run, its bar 3 (|d_t| + |d_h|) from the halved runs,
and FINER (the next level of both, computed independently) lies inside.

With --then-mesh the halved bar is still above the target, the mesh's part
dominates and the finest mesh's own halving moved epsilon by less than half
of d_h: the study adds mesh level 2 at the finest step (one run, its split
run the halved level 1); the bar is 3 (|d_t| + |d_h|) with d_t that
halving and d_h the new level's difference, and FINER lies inside.

With --halved-first SHARE the study ran the split run first and, its
time step's part 3 |d_t| at least SHARE of the target, the second level
at the halved step at once: four runs, without level 1 at the unhalved
step (with --then-mesh, that run comes after the halved level 1); the bar
is that of the halved runs, and FINER lies inside.

usage: check_time_halving.py OUTPUT_DIR TARGET FINER [--then-mesh]
                             [--halved-first SHARE]
"""
import csv
import os
import sys

directory, target, finer = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
then_mesh = "--then-mesh" in sys.argv[4:]
share = (float(sys.argv[sys.argv.index("--halved-first") + 1])
         if "--halved-first" in sys.argv else None)
runs = list(csv.DictReader(open(os.path.join(directory, "impact_convergence.csv"))))


def epsilon(factor, level, halvings):
    found = [float(r["epsilon"]) for r in runs if r["factor"] == factor
             and int(r["level"]) == level and int(r["time_halvings"]) == halvings]
    return found[0] if len(found) == 1 else None


def bar(d_t, d_h):
    return 3 * (abs(d_t) + abs(d_h))


base = epsilon("base", 0, 0)
first = (epsilon("mesh", 1, 0), epsilon("split", 1, 0))
halved = (epsilon("mesh", 1, 1), epsilon("split", 1, 1))
third = epsilon("mesh", 2, 0)
rows = list(csv.DictReader(open(os.path.join(directory, "epsilon_estimate.csv"))))
total = next(r for r in rows if r["factor"] == "total")
reported, reported_bar = float(total["limit"]), float(total["error"])
# Halved first without a third level: level 1 at the unhalved step is never run.
skipped = share is not None and not then_mesh
ok = len(runs) == (4 if skipped else 6 if then_mesh else 5)
ok &= (first[0] is None) == skipped
ok &= None not in (base, first[1]) + halved + ((third,) if then_mesh else ())
if ok and share is not None:
    d_t = first[1] - base
    print(f"base mesh: d_t = {d_t:.2e}, 3 |d_t| = {3 * abs(d_t):.2e}")
    ok &= 3 * abs(d_t) >= share * target
    # The halved level 1 ran before any level 1 at the unhalved step.
    order = [(r["factor"], int(r["level"]), int(r["time_halvings"])) for r in runs]
    ok &= order.index(("mesh", 1, 1)) < min(
        [i for i, run in enumerate(order) if run == ("mesh", 1, 0)] + [len(order)])
if ok:
    if not skipped:
        d_t, d_h = first[1] - base, first[0] - first[1]
        print(f"two levels: d_t = {d_t:.2e}, d_h = {d_h:.2e}, "
              f"bar {bar(d_t, d_h):.2e}")
        ok &= bar(d_t, d_h) > target
        if share is None:
            ok &= abs(d_t) >= abs(d_h) / 2
    d_t, d_h = halved[1] - first[1], halved[0] - halved[1]
    print(f"halved once: d_t = {d_t:.2e}, d_h = {d_h:.2e}, bar {bar(d_t, d_h):.2e}")
    if then_mesh:
        own = halved[0] - first[0]
        print(f"  the finest mesh's own halving: {own:.2e}")
        ok &= bar(d_t, d_h) > target and abs(d_t) < abs(d_h) / 2
        ok &= abs(own) < abs(d_h) / 2
        d_t, d_h = own, third - halved[0]
        finest = third
        print(f"mesh level 2 at the finest step: d_t = {d_t:.2e}, "
              f"d_h = {d_h:.2e}, bar {bar(d_t, d_h):.2e}")
    else:
        finest = halved[0]
    expected = bar(d_t, d_h)
    print(f"reported {reported:.8f} +- {reported_bar:.2e}; finer {finer:.8f}, "
          f"{abs(finer - reported):.2e} away")
    ok &= reported == finest
    ok &= abs(reported_bar - expected) <= 1e-9 * expected and reported_bar <= target
    ok &= abs(finer - reported) <= reported_bar
print("OK" if ok else "FAIL")
sys.exit(0 if ok else 1)
