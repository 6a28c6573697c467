#!/usr/bin/python3
"""CalculiX and diskimpact on the same disk impact: epsilon, error, time.

The same impact in both codes, one after the other, each with its error
against a reference epsilon.

Plane strain, E = 1, nu = 0.3, rho = 1, R = 1; the half disk (y >= 0,
symmetric about the impact axis) hits the rigid wall x = 0 at
v = 0.1 c, c = sqrt(E / ((1 - nu^2) rho)), touching it at t = 0.

Three parts, run one after the other on one core each
(OMP_NUM_THREADS=1, DEAL_II_NUM_THREADS=1, one MPI rank):

1. Reference. diskimpact's convergence study (Task = impact convergence)
   of this case with the wall as an exact non-penetration constraint
   (Law = constraint: no penalty error), quartic elements, three mesh
   levels (base: 1 global refinement, 6 elements across the contact,
   grading 0.6, dt = tau_est / 100; each level halves every element size
   and dt). Its estimate "epsilon = eps_ref +- bar" (epsilon_estimate.csv)
   is the reference; the study's wall time is printed (about 5 minutes,
   most of it the finest level, 86744 DoFs). --reference EPS BAR skips
   the study and uses the given values instead, e.g. those printed by an
   earlier run, or those of build/diskimpact DIR/reference.prm on the
   reference.prm that a run with --work DIR leaves there.

2. CalculiX (ccx 2.20) gets a gmsh mesh of 8-node quadrilaterals graded
   toward the contact point (--hmin at the contact, --hmax far from it),
   extruded into one layer of 20-node bricks (C3D20) with u_z = 0 on every
   node: exact plane strain, since the plane field solves the layer's
   discrete equations. (ccx expands its own CPE8 elements into such
   bricks internally, but ccx 2.20 does not pass *INITIAL CONDITIONS,
   TYPE=VELOCITY on to the expanded nodes: the disk would not move.) The
   wall is a block x in [-0.1, 0] of bricks with all its nodes fixed.
   Contact is ccx's face-to-face penalty contact (*CONTACT PAIR,
   TYPE=SURFACE TO SURFACE), frictionless: slave = the disk's element
   faces on the arc with x < 0.5 R (the contact half-width reaches about
   0.45 R), master = the wall's face x = 0, linear pressure-overclosure
   with slope kappa E2 / h_min (kappa = 100, E2 = E / (1 - nu^2)).
   Implicit dynamics *DYNAMIC, DIRECT, ALPHA = 0 (Newmark's average
   acceleration, no numerical damping) at the fixed time increment
   (5.9 R/c) / N, N = --steps-per-contact, up to 1.25 * 5.9 R/c (the
   contact lasts about 5.9 R/c). epsilon = J / (m v) - 1 with J the
   wall's reaction impulse (trapezoidal sum of the total reaction force
   RF_x of the wall nodes over the increments, which is the momentum
   balance of Newmark's rule) and m the mass of the meshed half disk. The
   run fails if ccx fails or if the reaction force is not zero at the end
   (disk still on the wall). The defaults (h = 0.02 ... 0.2 R, N = 100)
   keep ccx near a minute; h = 0.01 ... 0.1 R with N = 200 takes more
   than 10 minutes.

3. diskimpact's plain impact task (penalty contact, energy-conserving
   time stepping) at each setting of DISKIMPACT_SETTINGS: the
   convergence study's base discretization (1 global refinement, 6
   elements across the contact, grading 0.6, kappa = 100,
   dt = tau_est / 100) with degree 2, 3 and 4, params/impact.prm's
   discretization (degree 2, 3 global refinements, 12 elements across,
   grading 0.3, kappa = 400, dt = tau_est / 200), and the study's first
   refined level with degree 4.

Prints the reference with its bar and wall time; for CalculiX and for
each diskimpact setting epsilon, its error |epsilon - eps_ref|, DoFs (2
per node of the plane mesh), steps and wall time; then the cheapest
diskimpact setting (smallest wall time) whose error is at most
CalculiX's, the difference of the two epsilon, the ratio of the wall
times CalculiX / diskimpact and whether it is at least 30. Since the
reference has a bar, it also says whether CalculiX's error exceeds the
bar and whether the comparison still holds with the bar counted against
diskimpact (its error + bar <= CalculiX's error - bar). diskimpact's
errors are measured against a reference from diskimpact itself (another
contact law, finer meshes); CalculiX's are independent of it.

usage: bench/peer_calculix.py [--hmin H] [--hmax H] [--steps-per-contact N]
                              [--reference EPS BAR] [--work DIR]
       (bench/peer_calculix.sh installs calculix-ccx and gmsh and calls
       this)
"""
import argparse
import csv
import math
import os
import re
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "diskimpact")
NU = 0.3
E2 = 1. / (1. - NU * NU)          # plane strain: E / (1 - nu^2)
SPEED = 0.1                      # v / c
VELOCITY = SPEED * math.sqrt(E2)   # rho = 1
CONTACT_TIME = 5.9 / math.sqrt(E2)   # about 5.9 R/c at 0.1 c
KAPPA = 100.                     # penalty factor of CalculiX's contact
SLAVE_X = 0.5                    # slave faces: disk arc with x < SLAVE_X
WALL_THICKNESS = 0.1
WALL_HEIGHT = 0.8
LAYER = 0.05                     # thickness of the brick layer
THREADS = {"OMP_NUM_THREADS": "1", "DEAL_II_NUM_THREADS": "1"}

# diskimpact: the convergence study's base discretization (penalty)
BASE = {"degree": 2, "refinements": 1, "across": 6, "grading": 0.6,
        "law": "penalty", "kappa": 100., "fraction": 0.01}
# its first refined level: every element size and the time step halved
LEVEL1 = {**BASE, "refinements": 2, "across": 12, "grading": 0.3,
          "fraction": 0.005}
DISKIMPACT_SETTINGS = [
    ("Q2 base", BASE),
    ("Q3 base", {**BASE, "degree": 3}),
    ("Q4 base", {**BASE, "degree": 4}),
    ("Q2 as impact.prm", {**BASE, "refinements": 3, "across": 12,
                          "grading": 0.3, "kappa": 400., "fraction": 0.005}),
    ("Q4 level 1", {**LEVEL1, "degree": 4}),
]
REFERENCE = {**BASE, "degree": 4, "law": "constraint"}
REFERENCE_LEVELS = 3
# diskimpact's lines of subsections Geometry and Material for this body
DISK_LINES = ("  set Domain             = half disk\n",
              "  set Plane model   = plane strain\n")

GEO = """R = 1;
Point(1) = {{R, 0, 0}}; Point(2) = {{0, 0, 0}};
Point(3) = {{2*R, 0, 0}}; Point(4) = {{R, R, 0}};
Circle(1) = {{3, 1, 4}}; Circle(2) = {{4, 1, 2}};
Line(3) = {{2, 1}}; Line(4) = {{1, 3}};
Curve Loop(1) = {{1, 2, 3, 4}}; Plane Surface(1) = {{1}};
Field[1] = Distance; Field[1].PointsList = {{2}};
Field[2] = Threshold; Field[2].InField = 1;
Field[2].SizeMin = {hmin}; Field[2].SizeMax = {hmax};
Field[2].DistMin = 0.25; Field[2].DistMax = 1.0;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0; Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.RecombineAll = 1; Mesh.Algorithm = 6;
Mesh.ElementOrder = 2; Mesh.SecondOrderIncomplete = 1;
Physical Surface("DISK") = {{1}};
"""


def fail(message):
    sys.exit("peer_calculix: " + message)


def disk_mesh(work, hmin, hmax):
    """Nodes {id: (x, y)} and 8-node quads of the half disk from gmsh."""
    geo = os.path.join(work, "disk.geo")
    with open(geo, "w") as f:
        f.write(GEO.format(hmin=hmin, hmax=hmax))
    inp = os.path.join(work, "disk_mesh.inp")
    result = subprocess.run(["gmsh", "-2", geo, "-format", "inp", "-o", inp],
                            capture_output=True, text=True)
    if result.returncode != 0 or not os.path.exists(inp):
        fail("gmsh failed: " + (result.stderr or result.stdout).strip()
             .replace("\n", " ")[-300:])
    nodes, quads, block = {}, [], None
    with open(inp) as f:
        lines = f.read().splitlines()
    i = 0
    while i < len(lines):
        line = lines[i]
        if line.startswith("*"):
            block = ("node" if line.upper().startswith("*NODE") else
                     "quad" if "CPS8" in line.upper() else None)
        elif block == "node":
            n, x, y, _ = line.split(",")
            nodes[int(n)] = (float(x), float(y))
        elif block == "quad":
            entries = [e for e in line.split(",") if e.strip()]
            while len(entries) < 9:       # continuation lines
                i += 1
                entries += [e for e in lines[i].split(",") if e.strip()]
            quads.append([int(e) for e in entries[1:9]])
        i += 1
    used = {n for q in quads for n in q}
    if not quads:
        fail("gmsh gave no 8-node quadrilaterals")
    return {n: xy for n, xy in nodes.items() if n in used}, quads


def wall_mesh(first_node, n_along):
    """8-node quads of the block x in [-t, 0], y in [-H / n, H (1 - 1/n)]."""
    nodes, quads = {}, []
    t, dy = WALL_THICKNESS, WALL_HEIGHT / n_along
    number = first_node

    def node(x, y):
        nonlocal number
        nodes[number] = (x, y)
        number += 1
        return number - 1
    for j in range(n_along):
        y0, y1 = (j - 1) * dy, j * dy
        corners = [node(-t, y0), node(0., y0), node(0., y1), node(-t, y1)]
        sides = [node(-t / 2, y0), node(0., (y0 + y1) / 2),
                 node(-t / 2, y1), node(-t, (y0 + y1) / 2)]
        quads.append(corners + sides)
    return nodes, quads


def extrude(nodes, quads, offset):
    """One layer of C3D20 bricks over 8-node quads: node n at z = 0 keeps
    its number, n + offset is at z = LAYER and n + 2 offset (corner nodes
    only) at z = LAYER / 2."""
    nodes3 = {}
    for n, (x, y) in nodes.items():
        nodes3[n] = (x, y, 0.)
        nodes3[n + offset] = (x, y, LAYER)
    for n in {n for q in quads for n in q[:4]}:
        x, y = nodes[n]
        nodes3[n + 2 * offset] = (x, y, 0.5 * LAYER)
    bricks = []
    for q in quads:
        corners, sides = q[:4], q[4:]
        bricks.append(corners + [n + offset for n in corners] + sides +
                      [n + offset for n in sides] +
                      [n + 2 * offset for n in corners])
    return nodes3, bricks


def serendipity(xi, eta):
    """Shape function derivatives of the 8-node quadrilateral."""
    corners = ((-1, -1), (1, -1), (1, 1), (-1, 1))
    sides = ((0, -1), (1, 0), (0, 1), (-1, 0))
    dxi, deta = [], []
    for a, b in corners:
        dxi.append(0.25 * a * (1 + b * eta) * (2 * a * xi + b * eta))
        deta.append(0.25 * b * (1 + a * xi) * (a * xi + 2 * b * eta))
    for a, b in sides:
        if a == 0:
            dxi.append(-xi * (1 + b * eta))
            deta.append(0.5 * b * (1 - xi * xi))
        else:
            dxi.append(0.5 * a * (1 - eta * eta))
            deta.append(-eta * (1 + a * xi))
    return dxi, deta


def mesh_area(nodes, quads):
    """Area of the 8-node quads (3 x 3 Gauss points): m / (rho LAYER)."""
    g = math.sqrt(0.6)
    rule = ((-g, 5. / 9.), (0., 8. / 9.), (g, 5. / 9.))
    area = 0.
    for q in quads:
        xy = [nodes[n] for n in q]
        for xi, wx in rule:
            for eta, we in rule:
                dxi, deta = serendipity(xi, eta)
                j11 = sum(d * p[0] for d, p in zip(dxi, xy))
                j12 = sum(d * p[1] for d, p in zip(dxi, xy))
                j21 = sum(d * p[0] for d, p in zip(deta, xy))
                j22 = sum(d * p[1] for d, p in zip(deta, xy))
                area += wx * we * (j11 * j22 - j12 * j21)
    return area


def write_lines(f, values, per_line=8):
    for i in range(0, len(values), per_line):
        f.write(", ".join(str(v) for v in values[i:i + per_line]) + "\n")


def write_bricks(f, first, bricks):
    for e, b in enumerate(bricks, start=first):
        f.write(f"{e}, " + ", ".join(map(str, b[:15])) + ",\n" +
                ", ".join(map(str, b[15:])) + "\n")


def calculix_input(work, hmin, hmax, dt, end_time):
    """Writes impact.inp; returns (plane DoFs, mass of the meshed disk)."""
    disk_nodes, disk_quads = disk_mesh(work, hmin, hmax)
    wall_nodes, wall_quads = wall_mesh(
        max(disk_nodes) + 1, max(1, round(WALL_HEIGHT / hmin)))
    offset = 10 ** len(str(max(wall_nodes)))
    disk3, disk_bricks = extrude(disk_nodes, disk_quads, offset)
    wall3, wall_bricks = extrude(wall_nodes, wall_quads, offset)
    first_wall = len(disk_bricks) + 1
    symmetry = [n for n, p in disk3.items() if abs(p[1]) < 1e-10]

    def on_arc(n):
        x, y = disk_nodes[n]
        return abs(math.hypot(x - 1., y) - 1.) < 1e-8
    # slave: faces of the disk's bricks on the arc near the contact point
    # (edge k of a quad, corners k, k + 1, is face S(k + 2) of its brick)
    slave = []
    for e, q in enumerate(disk_quads, start=1):
        for k in range(4):
            edge = (q[k], q[(k + 1) % 4], q[4 + k])
            if (all(on_arc(n) for n in edge) and
                    min(disk_nodes[n][0] for n in edge) < SLAVE_X):
                slave.append((e, k + 3))
    if not slave:
        fail("no disk faces found on the arc near the contact point")
    mass = mesh_area(disk_nodes, disk_quads) * LAYER      # rho = 1
    with open(os.path.join(work, "impact.inp"), "w") as f:
        f.write("*HEADING\ndisk impact, plane strain, nu = 0.3\n*NODE\n")
        for n, (x, y, z) in sorted({**disk3, **wall3}.items()):
            f.write(f"{n}, {x:.15g}, {y:.15g}, {z:.15g}\n")
        f.write("*ELEMENT, TYPE=C3D20, ELSET=EDISK\n")
        write_bricks(f, 1, disk_bricks)
        f.write("*ELEMENT, TYPE=C3D20, ELSET=EWALL\n")
        write_bricks(f, first_wall, wall_bricks)
        f.write("*NSET, NSET=NDISK\n")
        write_lines(f, sorted(disk3))
        f.write("*NSET, NSET=NSYM\n")
        write_lines(f, sorted(symmetry))
        f.write("*NSET, NSET=NWALL\n")
        write_lines(f, sorted(wall3))
        f.write("*SURFACE, NAME=SDISK, TYPE=ELEMENT\n")
        for e, face in slave:
            f.write(f"{e}, S{face}\n")
        f.write("*SURFACE, NAME=SWALL, TYPE=ELEMENT\n")
        for e in range(first_wall, first_wall + len(wall_bricks)):
            f.write(f"{e}, S4\n")                   # the face x = 0
        f.write("*MATERIAL, NAME=MDISK\n*ELASTIC\n1., 0.3\n"
                "*DENSITY\n1.\n")
        f.write("*MATERIAL, NAME=MWALL\n*ELASTIC\n1000., 0.3\n"
                "*DENSITY\n1.\n")
        f.write("*SOLID SECTION, ELSET=EDISK, MATERIAL=MDISK\n")
        f.write("*SOLID SECTION, ELSET=EWALL, MATERIAL=MWALL\n")
        f.write("*BOUNDARY\nNDISK, 3, 3\nNSYM, 2, 2\nNWALL, 1, 3\n")
        f.write("*SURFACE INTERACTION, NAME=SI\n"
                "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n"
                f"{KAPPA * E2 / hmin:.10g}\n")
        f.write("*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE\n"
                "SDISK, SWALL\n")
        f.write("*INITIAL CONDITIONS, TYPE=VELOCITY\n"
                f"NDISK, 1, {-VELOCITY:.15g}\n")
        f.write("*STEP, INC=1000000\n*DYNAMIC, DIRECT, ALPHA=0.\n"
                f"{dt:.12g}, {end_time:.12g}\n")
        f.write("*NODE PRINT, NSET=NWALL, TOTALS=ONLY\nRF\n*END STEP\n")
    return 2 * len(disk_nodes), mass


def reaction_history(dat_path):
    """(time, total x reaction of the wall) per increment from ccx's .dat."""
    history, current = [], None
    with open(dat_path) as f:
        for line in f:
            match = re.search(r"force \(fx,fy,fz\).*time\s+([-+.\dEe]+)",
                              line)
            if match:
                current = float(match.group(1))
                continue
            if current is not None and line.strip():
                values = line.split()
                try:
                    history.append((current, float(values[0])))
                except ValueError:
                    pass
                current = None
    return history


def run_calculix(args, work, write_input=calculix_input,
                 contact_time=CONTACT_TIME):
    """ccx on the input of write_input(work, hmin, hmax, dt, end_time),
    which returns (DoFs, mass of the meshed body)."""
    dt = contact_time / args.steps_per_contact
    end_time = 1.25 * contact_time
    n_dofs, mass = write_input(work, args.hmin, args.hmax, dt, end_time)
    start = time.time()
    result = subprocess.run(["ccx", "-i", "impact"], cwd=work,
                            capture_output=True, text=True,
                            env={**os.environ, **THREADS})
    seconds = time.time() - start
    with open(os.path.join(work, "ccx.log"), "w") as f:
        f.write(result.stdout + result.stderr)
    if result.returncode != 0 or "Job finished" not in result.stdout:
        errors = [l.strip() for l in (result.stdout + result.stderr)
                  .splitlines() if "ERROR" in l]
        fail(f"ccx failed (exit code {result.returncode}): " +
             (errors[-1] if errors else "no 'Job finished'"))
    history = reaction_history(os.path.join(work, "impact.dat"))
    if not history or abs(history[-1][0] - end_time) > 1e-6 * end_time:
        fail("ccx's .dat has no reaction force history up to the end time")
    impulse, previous = 0., (0., 0.)
    for t, force in history:
        impulse += 0.5 * (t - previous[0]) * (force + previous[1])
        previous = (t, force)
    # RF_x of the fixed wall = the wall's push on the disk (+x)
    epsilon = impulse / (mass * VELOCITY) - 1.
    largest = max(abs(f) for _, f in history)
    if (largest == 0. or abs(history[-1][1]) > 1e-9 * largest or
            epsilon <= 0.):
        fail("ccx's run ended before the disk left the wall (reaction "
             f"force at the end {history[-1][1]:.3g}, largest {largest:.3g})")
    energies = [float(e) for e in re.findall(
        r"total energy\s*=\s*([-+.\dEe]+)", result.stdout)]
    kinetic = 0.5 * mass * VELOCITY ** 2
    drift = (max(energies) - min(energies)) / kinetic if energies else None
    equations = re.search(r"number of equations\s+(\d+)", result.stdout)
    return {"epsilon": epsilon, "dofs": n_dofs, "steps": len(history),
            "seconds": seconds, "drift": drift,
            "equations": int(equations.group(1)) if equations else None}


def diskimpact_prm(path, output, setting, task="impact", levels=None):
    """Writes a diskimpact parameter file for this case (the body's lines
    of subsections Geometry and Material: setting["body"], default
    DISK_LINES)."""
    geometry, material = setting.get("body", DISK_LINES)
    contact = ("set Law = constraint" if setting["law"] == "constraint" else
               f"set Penalty factor = {setting['kappa']:g}")
    text = f"""set Task             = {task}
set Output directory = {output}
subsection Geometry
{geometry}  set Global refinements = {setting['refinements']}
end
subsection Material
{material}  set Young modulus = 1
  set Poisson ratio = {NU:g}
  set Density       = 1
end
subsection Finite element
  set Degree = {setting['degree']}
end
subsection Contact
  {contact}
end
subsection Impact
  set Velocity                = {SPEED:g}
  set Elements across contact = {setting['across']}
  set Grading                 = {setting['grading']:g}
  set Output interval         = 0
end
subsection Time stepping
  set Scheme             = energy conserving
  set Time step fraction = {setting['fraction']:g}
end
"""
    if levels is not None:
        text += ("subsection Impact convergence\n"
                 f"  set Mesh levels      = {levels}\n"
                 "  set Time step levels = 1\n"
                 "  set Penalty levels   = 1\nend\n")
    with open(path, "w") as f:
        f.write(text)


def run_exe(prm):
    """Runs build/diskimpact on one core; returns its wall time."""
    start = time.time()
    result = subprocess.run([EXE, prm], capture_output=True, text=True,
                            env={**os.environ, **THREADS})
    seconds = time.time() - start
    if result.returncode != 0:
        fail("diskimpact failed on " + os.path.basename(prm) + ": " +
             (result.stderr or result.stdout).strip()
             .replace("\n", " ")[-300:])
    return seconds


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def run_reference(work, setting=REFERENCE, levels=REFERENCE_LEVELS):
    """diskimpact's convergence study (default: with the exact constraint):
    (epsilon estimate, its bar, epsilon per level, wall time)."""
    prm, output = (os.path.join(work, "reference.prm"),
                   os.path.join(work, "reference"))
    diskimpact_prm(prm, output, setting, task="impact convergence",
                   levels=levels)
    seconds = run_exe(prm)
    total = [row for row in read_csv(os.path.join(
        output, "epsilon_estimate.csv")) if row["factor"] == "total"]
    if not total:
        fail("the reference study wrote no total estimate")
    levels = [(int(row["n_dofs"]), float(row["epsilon"])) for row in
              read_csv(os.path.join(output, "impact_convergence.csv"))
              if row["factor"] in ("base", "mesh")]
    return {"epsilon": float(total[0]["limit"]),
            "bar": float(total[0]["error"]), "levels": levels,
            "seconds": seconds}


def run_diskimpact(work, name, setting):
    """One impact of diskimpact at a setting of DISKIMPACT_SETTINGS."""
    stem = re.sub(r"\W+", "_", name.lower())
    prm, output = os.path.join(work, stem + ".prm"), os.path.join(work, stem)
    diskimpact_prm(prm, output, setting)
    seconds = run_exe(prm)
    summary = read_csv(os.path.join(output, "summary.csv"))[0]
    return {"epsilon": float(summary["epsilon"]),
            "dofs": int(summary["n_dofs"]), "steps": int(summary["steps"]),
            "seconds": seconds}


def describe(setting):
    return (f"degree {setting['degree']}, global refinements "
            f"{setting['refinements']}, {setting['across']} elements across "
            f"the contact, grading {setting['grading']:g}, penalty factor "
            f"{setting['kappa']:g}, dt = tau_est / "
            f"{1. / setting['fraction']:g}")


def run_all(args, work):
    """The reference (unless given), CalculiX, then every diskimpact
    setting, one after the other."""
    if args.reference:
        reference = {"epsilon": args.reference[0], "bar": args.reference[1],
                     "levels": None, "seconds": None}
    else:
        reference = run_reference(work)
    ccx = run_calculix(args, work)
    own = [(name, setting, run_diskimpact(work, name, setting))
           for name, setting in DISKIMPACT_SETTINGS]
    return reference, ccx, own


def report_reference(reference, study=None):
    """The reference; study: how it was computed (default: this case's
    study with the exact constraint)."""
    eps, bar = reference["epsilon"], reference["bar"]
    if reference["seconds"] is None:
        print(f"reference (given): epsilon = {eps:.8f} +- {bar:.2e}")
        return
    if study is None:
        study = (f"Law = constraint, Q{REFERENCE['degree']}, "
                 f"{REFERENCE_LEVELS} mesh levels")
    print(f"reference: diskimpact's convergence study, {study} ("
          + ", ".join(f"{e:.8f} on {n} DoFs"
                      for n, e in reference["levels"]) + ")")
    print(f"reference: epsilon = {eps:.8f} +- {bar:.2e}, "
          f"wall {reference['seconds']:.1f} s")


def report_runs(args, reference, ccx, own):
    print(f"plane strain, nu = {NU:g}, v = {SPEED:g} c; "
          f"{THREADS['OMP_NUM_THREADS']} thread each")
    print(f"CalculiX: one layer of C3D20, h = {args.hmin:g}..{args.hmax:g} "
          f"R, face-to-face penalty {KAPPA:g} E2 / h, "
          f"{ccx['steps']} fixed increments of 5.9/{args.steps_per_contact} "
          "R/c")
    for name, setting, _ in own:
        print(f"diskimpact {name}: {describe(setting)}")
    report_table(reference, ccx, own)
    if ccx["equations"] is not None and ccx["drift"] is not None:
        print(f"CalculiX: {ccx['equations']} equations (brick layer), total "
              f"energy varies by {100 * ccx['drift']:.2f} % of the initial "
              "kinetic energy")


def report_table(reference, ccx, own):
    """epsilon, error, DoFs, steps and wall time of every run."""
    eps = reference["epsilon"]
    print(f"{'run':28s} {'epsilon':>10s} {'error':>8s} {'DoFs':>6s} "
          f"{'steps':>5s} {'wall [s]':>8s}")
    rows = [("CalculiX", ccx)] + [("diskimpact " + name, run)
                                  for name, _, run in own]
    for name, run in rows:
        print(f"{name:28s} {run['epsilon']:10.8f} "
              f"{abs(run['epsilon'] - eps):8.2e} {run['dofs']:6d} "
              f"{run['steps']:5d} {run['seconds']:8.2f}")


def report_comparison(reference, ccx, own):
    eps, bar = reference["epsilon"], reference["bar"]
    ccx_error = abs(ccx["epsilon"] - eps)
    print(f"CalculiX's error {ccx_error:.2e} is "
          f"{'above' if ccx_error > bar else 'within'} the reference's bar "
          f"{bar:.2e}")
    good = [(run["seconds"], name, run) for name, _, run in own
            if abs(run["epsilon"] - eps) <= ccx_error]
    if not good:
        print("no diskimpact setting has an error <= CalculiX's: "
              "acceptance (>= 30x faster at equal or smaller error) NOT met")
        return
    seconds, name, run = min(good, key=lambda entry: entry[0])
    error = abs(run["epsilon"] - eps)
    ratio = ccx["seconds"] / seconds
    print(f"cheapest diskimpact setting with error <= CalculiX's: {name} "
          f"(error {error:.2e} vs {ccx_error:.2e})")
    print(f"epsilon difference (CalculiX - diskimpact {name}): "
          f"{ccx['epsilon'] - run['epsilon']:.2e}")
    print(f"with the reference's bar counted against diskimpact: "
          f"{error:.2e} + {bar:.2e} "
          f"{'<=' if error + bar <= ccx_error - bar else '>'} "
          f"{ccx_error:.2e} - {bar:.2e}")
    print(f"wall time ratio CalculiX / diskimpact {name}: "
          f"{ccx['seconds']:.2f} s / {seconds:.2f} s = {ratio:.1f}: "
          f"{'>=' if ratio >= 30. else '<'} 30, acceptance "
          f"{'met' if ratio >= 30. else 'NOT met'}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--hmin", type=float, default=0.02,
                        help="CalculiX element size at the contact point "
                        "(default %(default)s R)")
    parser.add_argument("--hmax", type=float, default=0.2,
                        help="CalculiX element size far from the contact "
                        "(default %(default)s R)")
    parser.add_argument("--steps-per-contact", type=int, default=100,
                        help="CalculiX time increments per contact time "
                        "(default %(default)s)")
    parser.add_argument("--reference", type=float, nargs=2,
                        metavar=("EPS", "BAR"),
                        help="reference epsilon and its bar instead of "
                        "running diskimpact's convergence study")
    parser.add_argument("--work", default=None,
                        help="keep the input and output files in this "
                        "directory (default: a temporary one, removed)")
    args = parser.parse_args()
    if not os.path.exists(EXE):
        fail(f"{EXE} not found; build first")
    if args.work:
        os.makedirs(args.work, exist_ok=True)
        reference, ccx, own = run_all(args, os.path.abspath(args.work))
    else:
        with tempfile.TemporaryDirectory() as work:
            reference, ccx, own = run_all(args, work)
    report_reference(reference)
    report_runs(args, reference, ccx, own)
    report_comparison(reference, ccx, own)


if __name__ == "__main__":
    main()
