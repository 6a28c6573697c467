#!/usr/bin/python3
"""Robustness scenarios beyond bad input: an interrupted and resumed sweep,
a write failure (a full disk), and two runs into one output directory.

usage: check_scenarios.py SCENARIO --diskimpact PATH --mpirun PATH
                          [--work DIR]
SCENARIO: resume | full-disk | lock

resume     A sweep on 2 ranks is interrupted with SIGINT after two points,
           rerun and killed with SIGKILL after one more, then rerun to the
           end. No finished row may be lost or recomputed (its text,
           wall time included, stays as written), the table always reads
           whole, the last run reports the rows it kept, and every epsilon
           equals that of an uninterrupted sweep.
full-disk  Result files whose temporary file is /dev/full (every write fails
           with ENOSPC, as on a full disk), the ParaView pieces and records
           among them: one line naming the file and the cause, exit code 1,
           no file under the result name and no .vtu/.pvtu left, on 1 and 2
           ranks.
lock       A second run into the directory of a running sweep (held with
           SIGSTOP meanwhile) refuses with one line and touches nothing;
           the first ends as if alone.
"""
import argparse
import csv
import os
import shutil
import signal
import subprocess
import sys
import time

import h5py

SWEEP_PRM = """set Task             = sweep
set Output directory = output
subsection Geometry
  set Domain             = half disk
  set Global refinements = 2
end
subsection Material
  set Plane model   = plane stress
  set Poisson ratio = 0.33
end
subsection Contact
  set Penalty factor = 100
end
subsection Impact
  set Velocities     = 0.02, 0.03, 0.05, 0.07, 0.1, 0.15, 0.2, 0.25
  set Convergence study per point = false
end
subsection Time stepping
  # Points of about a second: mpirun takes up to a second to end its
  # ranks after SIGINT, and the sweep must still be running then.
  set Time step fraction = 0.005
end
"""


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def table(work):
    """output/restitution.csv as rows (dicts); it must always read whole."""
    with open(os.path.join(work, "output", "restitution.csv"),
              newline="") as f:
        rows = list(csv.DictReader(f))
    if len(rows) != 8 or any(None in r.values() for r in rows):
        fail(f"restitution.csv is not whole: {rows}")
    return rows


def done_rows(work):
    """The finished rows, by velocity, exactly as written."""
    if not os.path.exists(os.path.join(work, "output", "restitution.csv")):
        return {}
    return {r["velocity"]: r for r in table(work) if r["status"] == "done"}


def default_signals():
    """SIGINT as at a terminal, even where CI starts us with it ignored."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)


def start(args, work, ranks=2):
    # mpirun -q: without mpirun's own notice of a non-zero exit code.
    command = ([args.mpirun, "-q", "-np", str(ranks)] if ranks > 1 else []) \
        + [args.diskimpact, "run.prm"]
    return subprocess.Popen(command, cwd=work, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True,
                            start_new_session=True,
                            preexec_fn=default_signals)


def descendants(pid):
    """The process ids of all descendants of @p pid (from /proc)."""
    children = {}
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open(f"/proc/{entry}/stat") as f:
                    parent = int(f.read().rsplit(")", 1)[1].split()[1])
                children.setdefault(parent, []).append(int(entry))
            except (OSError, IndexError, ValueError):
                pass
    found, todo = [], [pid]
    while todo:
        for child in children.get(todo.pop(), []):
            found.append(child)
            todo.append(child)
    return found


def signal_all(process, number):
    """Send signal @p number to @p process and all its descendants."""
    for pid in [process.pid] + descendants(process.pid):
        try:
            os.kill(pid, number)
        except ProcessLookupError:
            pass


def wait_for_rows(process, work, count, timeout=120):
    """Wait until the table has @p count finished rows."""
    end = time.time() + timeout
    while time.time() < end:
        if len(done_rows(work)) >= count:
            return
        if process.poll() is not None:
            fail(f"the sweep ended before {count} rows: "
                 f"{process.stderr.read()}")
        time.sleep(0.05)
    fail(f"no {count} finished rows within {timeout} s")


def check_kept(before, after, when):
    for v, row in before.items():
        if after.get(v) != row:
            fail(f"{when}: the finished row v = {v} changed or was lost: "
                 f"{row} -> {after.get(v)}")


def reference_sweep(args, root):
    work = os.path.join(root, "reference")
    os.makedirs(work)
    with open(os.path.join(work, "run.prm"), "w") as f:
        f.write(SWEEP_PRM)
    process = start(args, work)
    out, err = process.communicate(timeout=600)
    if process.returncode != 0:
        fail(f"the uninterrupted sweep failed: {err}")
    return {r["velocity"]: float(r["epsilon"]) for r in table(work)}


def scenario_resume(args, root):
    reference = reference_sweep(args, root)
    work = os.path.join(root, "interrupted")
    os.makedirs(work)
    with open(os.path.join(work, "run.prm"), "w") as f:
        f.write(SWEEP_PRM)

    # SIGINT (Ctrl-C) after two rows, to mpirun and its ranks (mpirun puts
    # each rank in a process group of its own; a batch system's signal
    # reaches them all).
    process = start(args, work)
    wait_for_rows(process, work, 2)
    signal_all(process, signal.SIGINT)
    process.communicate(timeout=60)
    first = done_rows(work)
    print(f"after SIGINT: {len(first)} of 8 rows done, "
          f"{sum(r['status'] == 'pending' for r in table(work))} pending")

    # SIGKILL of everything after one more row.
    process = start(args, work)
    wait_for_rows(process, work, len(first) + 1)
    signal_all(process, signal.SIGKILL)
    process.communicate(timeout=60)
    second = done_rows(work)
    check_kept(first, second, "after SIGKILL")
    print(f"after SIGKILL: {len(second)} of 8 rows done")

    # To the end.
    process = start(args, work)
    out, err = process.communicate(timeout=600)
    if process.returncode != 0:
        fail(f"the resumed sweep failed: {err}")
    if f"{len(second)} kept from the earlier run" not in out:
        fail(f"the resumed sweep does not report {len(second)} kept rows:\n"
             + out)
    final = done_rows(work)
    check_kept(second, final, "after the resumed run")
    if len(final) != 8:
        fail(f"{len(final)} of 8 rows done at the end")
    worst = max(abs(float(final[v]["epsilon"]) - e)
                for v, e in reference.items())
    if worst > 1e-12:
        fail(f"epsilon differs from the uninterrupted sweep by {worst:.1e}")
    with h5py.File(os.path.join(work, "output", "restitution.h5"), "r") as h5:
        if h5["restitution"].attrs["complete"] != 1.0:
            fail("restitution.h5 does not say the sweep is complete")
    print(f"resumed: {len(second)} rows kept, none recomputed, all 8 done, "
          f"epsilon equal to the uninterrupted sweep's (largest difference "
          f"{worst:.1e}); restitution.h5 complete")


IMPACT_PRM = """set Task             = impact
set Output directory = output
subsection Geometry
  set Domain             = half disk
  set Global refinements = 1
end
subsection Material
  set Plane model   = plane stress
  set Poisson ratio = 0.33
end
subsection Impact
  set Velocity        = 0.05
  set Output interval = 10
  set Number of projected modes = 4
end
subsection Time stepping
  set Time step fraction = 0.02
end
"""


def scenario_full_disk(args, root):
    cases = [("impact", IMPACT_PRM, name, ranks)
             for name in ("used_parameters.prm", "summary.csv", "impact.csv",
                          "impact.h5", "impact.pvd", "mode_energies.csv")
             for ranks in (1, 2)]
    # The ParaView files: a rank's piece of the first or a later state, and
    # the record that lists the pieces.
    cases += [("impact", IMPACT_PRM, name, ranks)
              for name, ranks in (("impact_0000.0.vtu", 1),
                                  ("impact_0001.0.vtu", 1),
                                  ("impact_0000.1.vtu", 2),
                                  ("impact_0000.pvtu", 2))]
    cases += [("sweep", SWEEP_PRM.replace(
        "0.02, 0.03, 0.05, 0.07, 0.1, 0.15, 0.2, 0.25", "0.05, 0.1"), name, 2)
        for name in ("restitution.csv", "restitution.h5")]
    for task, prm, name, ranks in cases:
        work = os.path.join(root, f"{task}_{name}_{ranks}")
        os.makedirs(os.path.join(work, "output"))
        with open(os.path.join(work, "run.prm"), "w") as f:
            f.write(prm)
        os.symlink("/dev/full", os.path.join(work, "output", name + ".tmp"))
        process = start(args, work, ranks)
        out, err = process.communicate(timeout=300)
        lines = err.splitlines()
        expected = f"diskimpact: error: cannot write output/{name}: " \
                   "No space left on device"
        if process.returncode == 0 or lines != [expected]:
            fail(f"{task}, {name}, {ranks} rank(s): exit code "
                 f"{process.returncode}, stderr {err!r}")
        if os.path.exists(os.path.join(work, "output", name)):
            fail(f"{task}, {name}: a file is left under the result name")
        left = [f for f in os.listdir(os.path.join(work, "output"))
                if f.endswith(".vtu") or f.endswith(".pvtu")]
        if left:
            fail(f"{task}, {name}: ParaView files of the failed run are left: {left}")
        print(f"{task}, {name}, {ranks} rank(s): '{lines[0]}', exit code "
              f"{process.returncode}, no {name}")


def scenario_lock(args, root):
    reference = reference_sweep(args, root)
    work = os.path.join(root, "locked")
    os.makedirs(work)
    with open(os.path.join(work, "run.prm"), "w") as f:
        f.write(SWEEP_PRM)
    first = start(args, work)
    wait_for_rows(first, work, 1)
    # Held (SIGSTOP) while the second run tries: it must still be running
    # then, however fast its points are on this machine.
    signal_all(first, signal.SIGSTOP)
    try:
        before = sorted(os.listdir(os.path.join(work, "output")))
        second = start(args, work, 1)
        out, err = second.communicate(timeout=60)
    finally:
        signal_all(first, signal.SIGCONT)
    lines = err.splitlines()
    if second.returncode == 0 or len(lines) != 1 or \
            "is in use by another diskimpact run" not in lines[0]:
        fail(f"the second run: exit code {second.returncode}, stderr {err!r}")
    out, err = first.communicate(timeout=600)
    if first.returncode != 0:
        fail(f"the first run failed after the second tried: {err}")
    final = {v: float(r["epsilon"]) for v, r in done_rows(work).items()}
    if final != reference:
        fail(f"the first run's table differs from an undisturbed one: {final}")
    print(f"second run refused: '{lines[0]}'; the first completed all 8 "
          f"points as if alone (files while both ran: {before})")


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("scenario", choices=["resume", "full-disk", "lock"])
    parser.add_argument("--diskimpact", required=True)
    parser.add_argument("--mpirun", required=True)
    parser.add_argument("--work", default="scenario_" + str(os.getpid()))
    args = parser.parse_args()
    root = os.path.abspath(f"{args.work}_{args.scenario}")
    shutil.rmtree(root, ignore_errors=True)
    os.makedirs(root)
    {"resume": scenario_resume, "full-disk": scenario_full_disk,
     "lock": scenario_lock}[args.scenario](args, root)
    shutil.rmtree(root, ignore_errors=True)
    print("OK")


if __name__ == "__main__":
    main()
