#!/usr/bin/python3
"""Run the robustness suite written by generate_cases.py and check that
diskimpact refuses every bad input cleanly.

usage: run_cases.py CASES_DIR [--shard K/N] [--ranks R] [--diskimpact PATH]
       [--mpirun PATH] [--timeout SECONDS] [--memory-limit MB] [--keep]
       [--verbose] [NAME ...]

Each case (CASES_DIR/manifest.json) runs in a fresh temporary copy of its
folder ("diskimpact PRM", or "MPIRUN -np RANKS diskimpact PRM"). It passes
when
  - it ends within the timeout (else: hang),
  - without a signal (exit code >= 128 or negative: crash),
  - without "MPI_ABORT", "----", "Abort", "Segmentation" on standard error
    (else: abort output),
  - with a non-zero exit code (else: exit 0),
  - standard error is exactly one line (else: no message, multi-line
    message) that starts with "diskimpact: error:" (else: wrong prefix) and
    contains the case's expected substring, compared case-insensitively
    (else: lacks substring),
  - and no file or directory appeared in the working directory (else: files
    left behind).
Under mpirun, its notices that a rank exited with a non-zero code (printed
for any failing run) are removed from standard error first.
--shard K/N runs every N-th case starting with the K-th (after --ranks
selects the cases with that many MPI ranks); NAMEs select cases by name.
--memory-limit caps each process's address space (0: no limit), so that a
case that allocates without bound fails alone instead of exhausting the
machine. Prints one line per failing case and the summary
"N cases, M failed"; the exit code is 0 only if every case passed.
"""
import argparse
import json
import os
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
from pathlib import Path

PREFIX = "diskimpact: error:"
CRASH_MARKERS = ("MPI_ABORT", "----", "Abort", "Segmentation")
# Failure kinds, most severe first; a case is grouped under its first.
KINDS = ("hang", "crash", "abort output", "exit 0", "no message",
         "multi-line message", "wrong prefix", "lacks substring",
         "files left behind")
# mpirun's boxed notices that a rank exited with a non-zero code: it prints
# them for every failing run, a clean refusal included, so they are removed
# before standard error is judged (an MPI_ABORT notice is not).
MPIRUN_NOTICES = ("terminated normally, but", "exited with non-zero status")
MPI_DEFAULTS = {"OMPI_ALLOW_RUN_AS_ROOT": "1",
                "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
                "OMPI_MCA_rmaps_base_oversubscribe": "1",
                # no Open MPI daemon for a run without mpirun
                "OMPI_MCA_ess_singleton_isolated": "1"}


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("cases_dir", type=Path)
    parser.add_argument("names", nargs="*", help="run only these cases")
    parser.add_argument("--shard", default="1/1", help="K/N: the K-th of N parts")
    parser.add_argument("--ranks", type=int, help="only cases with this many ranks")
    parser.add_argument("--diskimpact", default="diskimpact")
    parser.add_argument("--mpirun", default="mpirun")
    parser.add_argument("--timeout", type=float, default=60.)
    parser.add_argument("--memory-limit", type=int, default=4096,
                        help="address-space limit per process [MB]")
    parser.add_argument("--keep", action="store_true",
                        help="keep the working directories of failing cases")
    parser.add_argument("--verbose", action="store_true",
                        help="also print the message of every passing case")
    return parser.parse_intermixed_args()


def select_cases(args):
    """The manifest's cases chosen by names, --ranks and --shard."""
    cases = json.loads((args.cases_dir / "manifest.json").read_text())
    if args.names:
        unknown = set(args.names) - {case["name"] for case in cases}
        if unknown:
            sys.exit(f"run_cases.py: unknown cases {sorted(unknown)}")
        cases = [case for case in cases if case["name"] in args.names]
    if args.ranks is not None:
        cases = [case for case in cases if case["ranks"] == args.ranks]
    k, n = (int(part) for part in args.shard.split("/"))
    if not 1 <= k <= n:
        sys.exit(f"run_cases.py: bad --shard {args.shard}")
    return cases[k - 1::n]


def tree(directory):
    """Every path below DIRECTORY, relative to it."""
    return {str(path.relative_to(directory)) for path in directory.rglob("*")}


def limit_memory(megabytes):
    """A preexec_fn capping the address space (None: no limit)."""
    if megabytes <= 0:
        return None
    size = megabytes * 1024 * 1024
    return lambda: resource.setrlimit(resource.RLIMIT_AS, (size, size))


def command(case, args):
    """The command line of CASE, under mpirun if it has several ranks."""
    run = [args.diskimpact, case["prm"]]
    if case["ranks"] > 1:
        return [args.mpirun, "-np", str(case["ranks"])] + run
    return run


def execute(cmd, cwd, tmpdir, args):
    """Run CMD in CWD in a session of its own, with TMPDIR as its temporary
    directory: (exit code or None on timeout, standard error)."""
    # Open MPI keeps a singleton's session directory below TMPDIR under a
    # name that every singleton of the user shares; one TMPDIR per case keeps
    # the shards that run side by side from removing each other's.
    environment = dict(os.environ, TMPDIR=str(tmpdir))
    process = subprocess.Popen(cmd, cwd=cwd, env=environment,
                               stdout=subprocess.DEVNULL,
                               stderr=subprocess.PIPE, start_new_session=True,
                               preexec_fn=limit_memory(args.memory_limit))
    try:
        _, stderr = process.communicate(timeout=args.timeout)
        code = process.returncode
    except subprocess.TimeoutExpired:
        # SIGTERM first: mpirun passes it on to the ranks.
        process.terminate()
        try:
            process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            pass
        kill_session(process.pid)
        _, stderr = process.communicate()
        code = None
    kill_session(process.pid)
    return code, stderr.decode("utf-8", errors="replace")


def kill_session(sid):
    """Kill what is left of the case's session (MPI ranks run in process
    groups of their own, so killing mpirun's group would miss them)."""
    for pid in session_members(sid):
        try:
            os.kill(pid, signal.SIGKILL)
        except ProcessLookupError:
            pass


def session_members(sid):
    """The ids of the processes in session SID (from /proc)."""
    members = []
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            fields = stat.read_text().rsplit(")", 1)[1].split()
        except (OSError, IndexError):
            continue
        if int(fields[3]) == sid:
            members.append(int(stat.parent.name))
    return members


def is_rule(line):
    return len(line) >= 20 and set(line) == {"-"}


def without_mpirun_notices(stderr):
    """STDERR without the boxes (between rules of dashes) that hold one of
    MPIRUN_NOTICES."""
    lines, kept, i = stderr.split("\n"), [], 0
    while i < len(lines):
        end = next((j for j in range(i + 1, len(lines)) if is_rule(lines[j])),
                   None) if is_rule(lines[i]) else None
        box = "\n".join(lines[i:end]) if end else ""
        if any(notice in box for notice in MPIRUN_NOTICES):
            i = end + 1
        else:
            kept.append(lines[i])
            i += 1
    return "\n".join(kept)


def message_failures(stderr, expect):
    """What is wrong with standard error STDERR (one line expected)."""
    if not stderr:
        return ["no message"]
    lines = stderr.split("\n")
    if len(lines) != 2 or lines[1] != "":
        return ["multi-line message"]
    failures = []
    if not lines[0].startswith(PREFIX):
        failures.append("wrong prefix")
    if expect.lower() not in lines[0].lower():
        failures.append("lacks substring")
    return failures


def failures_of(code, stderr, new_paths, expect):
    """The failure kinds of one run, in the order of KINDS."""
    if code is None:
        failures = ["hang"]
    else:
        failures = ["crash"] if code < 0 or code >= 128 else []
        if any(marker in stderr for marker in CRASH_MARKERS):
            failures.append("abort output")
        if code == 0:
            failures.append("exit 0")
        failures += message_failures(stderr, expect)
    if new_paths:
        failures.append("files left behind")
    return failures


def run_case(case, args):
    """Run one case in a fresh copy of its folder: (failure kinds, exit
    code, stderr, new paths)."""
    work = Path(tempfile.mkdtemp(prefix=f"robustness-{case['name']}-"))
    cwd = work / "case"
    shutil.copytree(args.cases_dir / case["directory"], cwd, symlinks=True)
    tmpdir = work / "tmp"
    tmpdir.mkdir()
    before = tree(cwd)
    code, stderr = execute(command(case, args), cwd, tmpdir, args)
    if case["ranks"] > 1:
        stderr = without_mpirun_notices(stderr)
    new_paths = sorted(tree(cwd) - before)
    failures = failures_of(code, stderr, new_paths, case["expect"])
    if failures and args.keep:
        print(f"  kept {cwd}")
    else:
        shutil.rmtree(work, ignore_errors=True)
    return failures, code, stderr, new_paths


def report(case, failures, code, stderr, new_paths):
    """One line for a failing case."""
    details = [f"exit code {'timeout' if code is None else code}"]
    if "lacks substring" in failures:
        details.append(f"expected {case['expect']!r}")
    if new_paths:
        shown = [path for path in new_paths if "/" not in path] or new_paths
        details.append("new: " + ", ".join(shown[:3]))
    details.append(f"stderr: {stderr[:200]!r}")
    ranks = f" [{case['ranks']} ranks]" if case["ranks"] > 1 else ""
    print(f"FAIL {case['name']}{ranks}: {', '.join(failures)} "
          f"({'; '.join(details)})", flush=True)


def main():
    args = parse_arguments()
    for name, value in MPI_DEFAULTS.items():
        os.environ.setdefault(name, value)
    cases = select_cases(args)
    counts = dict.fromkeys(KINDS, 0)
    failed = 0
    for case in cases:
        failures, code, stderr, new_paths = run_case(case, args)
        if failures:
            failed += 1
            counts[failures[0]] += 1
            report(case, failures, code, stderr, new_paths)
        elif args.verbose:
            print(f"ok {case['name']}: {stderr.strip()}", flush=True)
    if failed:
        print("by first failure: " + ", ".join(
            f"{kind} {n}" for kind, n in counts.items() if n))
    print(f"{len(cases)} cases, {failed} failed")
    return 1 if failed or not cases else 0


if __name__ == "__main__":
    sys.exit(main())
