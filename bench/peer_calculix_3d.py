#!/usr/bin/python3
"""CalculiX and diskimpact on the same sphere impact: epsilon, error, time.

The 3D counterpart of bench/peer_calculix.py (whose functions it uses):
the same impact in both codes, one after the other, each with its error
against a reference epsilon.

A sphere, E = 1, nu = 0.3, rho = 1, R = 1, centre (R, 0, 0), touches the
rigid wall x = 0 at the origin at t = 0 and hits it at v = 0.1 c,
c = sqrt(E2 / rho), E2 = E / (1 - nu^2) (diskimpact's velocity unit for
a sphere). Both codes compute the quarter y >= 0, z >= 0 with u_y = 0 on
y = 0 and u_z = 0 on z = 0 (exact for a head-on impact).

Three parts, run one after the other on one core each
(OMP_NUM_THREADS=1, DEAL_II_NUM_THREADS=1, one MPI rank):

1. Reference. diskimpact's convergence study of this case,
   params/impact_convergence_sphere_3d.prm at v = 0.1 c: Q2, penalty
   contact (kappa = 100), energy-conserving steps, two mesh levels (4
   elements across the largest Hertz radius, grading 0.6,
   dt = tau_est / 100; then every element size and dt halved, 162705
   DoFs). Its estimate "epsilon = eps_ref +- bar" (epsilon_estimate.csv,
   the bar three times the difference of the levels) is the reference;
   the study's wall time is printed (2.5 to 3.5 minutes). --reference EPS
   BAR skips the study and uses the given values instead, e.g. those
   printed by an earlier run, or those of build/diskimpact
   DIR/reference.prm on the reference.prm that a run with --work DIR
   leaves there.

2. CalculiX (ccx 2.20) gets a gmsh mesh of the quarter ball in 10-node
   tetrahedra (C3D10, mid-side nodes on the sphere) graded toward the
   contact point (--hmin within DIST_MIN of it, growing to --hmax at
   DIST_MAX). The wall is a block x in [-0.1, 0], y and z in
   [-h_w, 0.8 - h_w], of 20-node bricks (C3D20, one layer, side
   h_w = WALL_ELEMENT_FACTOR h_min) with all its nodes fixed; it covers
   the contact radius a = sqrt(R delta_max) = 0.47 R with a margin.
   Contact is ccx's face-to-face penalty contact (*CONTACT PAIR,
   TYPE=SURFACE TO SURFACE), frictionless: slave = the ball's element
   faces on the sphere with x < 0.5 R, master = the wall's face x = 0,
   linear pressure-overclosure with slope kappa E2 / h_min (kappa = 100).
   Implicit dynamics *DYNAMIC, DIRECT, ALPHA = 0 (Newmark's average
   acceleration, no numerical damping) at the fixed time increment
   (7.01 R/c) / N, N = --steps-per-contact, up to 1.25 * 7.01 R/c (the
   contact lasts 7.01 R/c and delta_max is 0.225 R in diskimpact's runs
   at 0.1 c). epsilon = J / (m v) - 1 with J the wall's reaction
   impulse (trapezoidal sum of the total reaction force RF_x of the wall
   nodes over the increments, which is the momentum balance of Newmark's
   rule) and m the mass of the meshed quarter ball (its volume from the
   10-node tetrahedra, integrated exactly). The run fails if ccx fails
   or if the reaction force is not zero at the end (sphere still on the
   wall). The defaults, h = 0.1 ... 0.25 R (about 5 elements across the
   contact radius) and N = 100 increments, match diskimpact's first
   setting (4 elements across, about 100 steps).

3. diskimpact's plain impact task (Task = impact, Output interval = 0)
   of the quarter sphere (Body = sphere, Dimension = 3, its default
   Domain = quarter sphere) at each setting of DISKIMPACT_SETTINGS, all
   Q2, 0 global refinements, penalty factor 100, grading 0.6: 4 or 6
   elements across the contact, dt = tau_est / 100 or / 200 ('Elements
   across contact' is at least 4). The first setting is the reference
   study's base level, so its error against the reference is a third of
   the bar by construction.

Prints the reference with its bar and wall time; for each CalculiX mesh
(--hmin takes several sizes, each run and compared on its own) and for
each diskimpact setting epsilon, its error |epsilon - eps_ref|, DoFs (3
per node of the quarter ball), steps and wall time; then the cheapest
diskimpact setting (smallest wall time) whose error is at most
CalculiX's, the difference of the two epsilon, the ratio of the wall
times CalculiX / diskimpact and whether it is at least 30, whether
CalculiX's error exceeds the reference's bar and whether the comparison
still holds with the bar counted against diskimpact (its error + bar <=
CalculiX's error - bar); last the wall time of each part. diskimpact's
errors are measured against a reference from diskimpact itself (finer
mesh and time step); CalculiX's are independent of it.

usage: bench/peer_calculix_3d.py [--hmin H [H ...]] [--hmax H]
                                 [--steps-per-contact N] [--speed V]
                                 [--reference-model 3d|axisymmetric]
                                 [--reference-levels N]
                                 [--reference EPS BAR] [--work DIR]

--speed V runs the same at v = V c (the contact time scaled as Hertz's,
v^(-1/5)); at low speeds --reference-model axisymmetric takes the sharper
axisymmetric study as the reference (docs/validation/peer-calculix-3d.md).
--reference-levels N gives the reference study N mesh levels instead of
its default (2 in 3D, 3 axisymmetric).
       (bench/peer_calculix_3d.sh installs calculix-ccx and gmsh and
       calls this)
"""
import argparse
import math
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import peer_calculix as pc  # noqa: E402



def contact_time(speed):
    """The contact time at v/c = speed: 7.01 R/c at 0.1 c in diskimpact's
    runs, scaled as Hertz's t_c ~ v^(-1/5)."""
    return 7.01 * (0.1 / speed) ** 0.2 / math.sqrt(pc.E2)


DIST_MIN = 0.3                   # element size hmin up to this distance
DIST_MAX = 1.2                   # from the contact point, hmax from here
WALL_ELEMENT_FACTOR = 2.         # wall brick side / hmin
SPHERE_LINES = ("  set Body               = sphere\n"
                "  set Dimension          = 3\n", "")

# diskimpact: the 3D convergence study's base level (Q2, penalty)
BASE = {"degree": 2, "refinements": 0, "across": 4, "grading": 0.6,
        "law": "penalty", "kappa": 100., "fraction": 0.01,
        "body": SPHERE_LINES}
DISKIMPACT_SETTINGS = [
    ("Q2 4 across", BASE),
    ("Q2 4 across, dt/200", {**BASE, "fraction": 0.005}),
    ("Q2 6 across", {**BASE, "across": 6}),
    ("Q2 6 across, dt/200", {**BASE, "across": 6, "fraction": 0.005}),
]
# the reference: the convergence study from BASE (two mesh levels), or
# with --reference-model axisymmetric the axisymmetric model's study of
# params/sweep_sphere.prm (three mesh levels, 6 to 24 elements across)
REFERENCE = BASE
REFERENCE_LEVELS = 2
AXISYMMETRIC = {**BASE, "refinements": 1, "across": 6,
                "body": ("  set Body               = sphere\n", "")}
AXISYMMETRIC_LEVELS = 3

# The sphere's quarter wedge about its polar axis z (azimuth 0 ... 90
# degrees) turned by 120 degrees about (1, 1, 1) (z -> x, x -> y, y -> z):
# the quarter y >= 0, z >= 0 with the poles on the x axis, the one at the
# origin a mesh vertex.
GEO = """SetFactory("OpenCASCADE");
Sphere(1) = {{0, 0, 0, 1, -Pi/2, Pi/2, Pi/2}};
Rotate {{{{1, 1, 1}}, {{0, 0, 0}}, 2*Pi/3}} {{ Volume{{1}}; }}
Translate {{1, 0, 0}} {{ Volume{{1}}; }}
Field[1] = MathEval; Field[1].F = "Sqrt(x*x + y*y + z*z)";
Field[2] = Threshold; Field[2].InField = 1;
Field[2].SizeMin = {hmin}; Field[2].SizeMax = {hmax};
Field[2].DistMin = {dmin}; Field[2].DistMax = {dmax};
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0; Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.ElementOrder = 2;
Physical Volume("BALL") = {{1}};
"""
# C3D10 faces (ccx's S1 ... S4) by their corner nodes
TET_FACES = ((0, 1, 2), (0, 3, 1), (1, 3, 2), (2, 3, 0))


def ball_mesh(work, hmin, hmax):
    """Node coordinates {id: (x, y, z)} and C3D10 connectivity (ccx's
    node order) of the quarter ball from gmsh."""
    geo = os.path.join(work, "ball.geo")
    with open(geo, "w") as f:
        f.write(GEO.format(hmin=hmin, hmax=hmax, dmin=DIST_MIN,
                           dmax=DIST_MAX))
    inp = os.path.join(work, "ball_mesh.inp")
    result = subprocess.run(["gmsh", "-3", geo, "-format", "inp", "-o", inp],
                            capture_output=True, text=True)
    if result.returncode != 0 or not os.path.exists(inp):
        pc.fail("gmsh failed: " + (result.stderr or result.stdout).strip()
                .replace("\n", " ")[-300:])
    nodes, tets, section = {}, [], None
    with open(inp) as f:
        for line in f:
            if line.startswith("*"):
                keyword = line.upper().replace(" ", "")
                section = ("nodes" if keyword.startswith("*NODE") else
                           "tets" if "TYPE=C3D10" in keyword else None)
                continue
            values = [v for v in line.split(",") if v.strip()]
            if section == "nodes":
                nodes[int(values[0])] = tuple(float(v) for v in values[1:4])
            elif section == "tets":
                tets.append([int(v) for v in values[1:11]])
    if not tets or any(len(t) != 10 for t in tets):
        pc.fail("gmsh gave no 10-node tetrahedra")
    used = {n for t in tets for n in t}
    return {n: p for n, p in nodes.items() if n in used}, tets


def tet10_gradients(lam):
    """Derivatives of the C3D10 shape functions by lam_1, lam_2, lam_3 at
    the barycentric point lam (lam_0 = 1 - lam_1 - lam_2 - lam_3)."""
    def d_lam(i):
        return [-1.] * 3 if i == 0 else [float(k == i - 1) for k in range(3)]
    gradients = [[(4. * lam[i] - 1.) * d for d in d_lam(i)]
                 for i in range(4)]
    for i, j in ((0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)):
        gradients.append([4. * (lam[j] * a + lam[i] * b)
                          for a, b in zip(d_lam(i), d_lam(j))])
    return gradients


def tet10_volume(nodes, tets):
    """Volume of the 10-node tetrahedra: det J is a cubic polynomial on
    the reference tetrahedron, integrated exactly by the 5-point
    degree-3 rule (weights -4/5 and 9/20 of the reference volume 1/6)."""
    points = [((0.25,) * 4, -0.8)] + [
        (tuple(0.5 if k == i else 1. / 6. for k in range(4)), 0.45)
        for i in range(4)]
    rule = [(tet10_gradients(lam), weight / 6.) for lam, weight in points]
    volume = 0.
    for t in tets:
        x = [nodes[n] for n in t]
        for gradients, weight in rule:
            j = [[sum(p[r] * g[c] for p, g in zip(x, gradients))
                  for c in range(3)] for r in range(3)]
            volume += weight * (
                j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1]) -
                j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0]) +
                j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]))
    return volume


def wall_bricks(first_node, n_side, size):
    """C3D20 bricks of the block x in [-t, 0], y and z in
    [-size, (n_side - 1) size]: nodes {id: (x, y, z)} and connectivity;
    each brick's face S2 is on x = 0."""
    t = pc.WALL_THICKNESS
    numbers = {}

    def node(i, j, k):            # half-element indices along y, z, x
        if (i, j, k) not in numbers:
            numbers[(i, j, k)] = first_node + len(numbers)
        return numbers[(i, j, k)]
    # local axes (xi, eta, zeta) along (y, z, x): a right-handed brick
    corners = ((0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0),
               (0, 0, 2), (2, 0, 2), (2, 2, 2), (0, 2, 2))
    sides = ((1, 0, 0), (2, 1, 0), (1, 2, 0), (0, 1, 0),
             (1, 0, 2), (2, 1, 2), (1, 2, 2), (0, 1, 2),
             (0, 0, 1), (2, 0, 1), (2, 2, 1), (0, 2, 1))
    bricks = []
    for i in range(0, 2 * n_side, 2):
        for j in range(0, 2 * n_side, 2):
            bricks.append([node(i + a, j + b, c) for a, b, c in
                           corners + sides])
    coordinates = {n: (-t + 0.5 * t * k, (0.5 * i - 1.) * size,
                       (0.5 * j - 1.) * size)
                   for (i, j, k), n in numbers.items()}
    return coordinates, bricks


def calculix_input(work, hmin, hmax, dt, end_time):
    """Writes impact.inp; returns (DoFs, mass of the meshed quarter ball)."""
    ball, tets = ball_mesh(work, hmin, hmax)
    n_side = max(1, round(pc.WALL_HEIGHT / (WALL_ELEMENT_FACTOR * hmin)))
    wall, bricks = wall_bricks(max(ball) + 1, n_side,
                               pc.WALL_HEIGHT / n_side)

    def on_sphere(n):
        x, y, z = ball[n]
        return abs(math.sqrt((x - 1.) ** 2 + y * y + z * z) - 1.) < 1e-8
    # boundary faces: those of one tetrahedron only
    count = {}
    for t in tets:
        for face in TET_FACES:
            key = frozenset(t[k] for k in face)
            count[key] = count.get(key, 0) + 1
    slave = []
    for e, t in enumerate(tets, start=1):
        for s, face in enumerate(TET_FACES, start=1):
            corners = [t[k] for k in face]
            if (count[frozenset(corners)] == 1 and
                    all(on_sphere(n) for n in corners) and
                    min(ball[n][0] for n in corners) < pc.SLAVE_X):
                slave.append(f"{e}, S{s}")
    if not slave:
        pc.fail("no ball faces found on the sphere near the contact point")
    first_wall = len(tets) + 1
    sets = {
        "NBALL": sorted(ball),
        "NSYMY": sorted(n for n, p in ball.items() if abs(p[1]) < 1e-10),
        "NSYMZ": sorted(n for n, p in ball.items() if abs(p[2]) < 1e-10),
        "NWALL": sorted(wall)}
    with open(os.path.join(work, "impact.inp"), "w") as f:
        f.write("*HEADING\nquarter sphere impact, nu = 0.3\n*NODE\n")
        for n, (x, y, z) in sorted({**ball, **wall}.items()):
            f.write(f"{n}, {x:.15g}, {y:.15g}, {z:.15g}\n")
        f.write("*ELEMENT, TYPE=C3D10, ELSET=EBALL\n")
        for e, t in enumerate(tets, start=1):
            f.write(f"{e}, " + ", ".join(map(str, t)) + "\n")
        f.write("*ELEMENT, TYPE=C3D20, ELSET=EWALL\n")
        pc.write_bricks(f, first_wall, bricks)
        for name, members in sets.items():
            f.write(f"*NSET, NSET={name}\n")
            pc.write_lines(f, members)
        f.write("*SURFACE, NAME=SBALL, TYPE=ELEMENT\n" +
                "\n".join(slave) + "\n")
        f.write("*SURFACE, NAME=SWALL, TYPE=ELEMENT\n" +
                "".join(f"{e}, S2\n" for e in
                        range(first_wall, first_wall + len(bricks))))
        for name, modulus, elements in (("MBALL", 1., "EBALL"),
                                        ("MWALL", 1000., "EWALL")):
            f.write(f"*MATERIAL, NAME={name}\n*ELASTIC\n{modulus:g}, "
                    f"{pc.NU:g}\n*DENSITY\n1.\n*SOLID SECTION, "
                    f"ELSET={elements}, MATERIAL={name}\n")
        f.write("*BOUNDARY\nNSYMY, 2, 2\nNSYMZ, 3, 3\nNWALL, 1, 3\n"
                "*SURFACE INTERACTION, NAME=SI\n"
                "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n"
                f"{pc.KAPPA * pc.E2 / hmin:.10g}\n"
                "*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE\n"
                "SBALL, SWALL\n*INITIAL CONDITIONS, TYPE=VELOCITY\n"
                f"NBALL, 1, {-pc.VELOCITY:.15g}\n*STEP, INC=1000000\n"
                f"*DYNAMIC, DIRECT, ALPHA=0.\n{dt:.12g}, {end_time:.12g}\n"
                "*NODE PRINT, NSET=NWALL, TOTALS=ONLY\nRF\n*END STEP\n")
    return 3 * len(ball), tet10_volume(ball, tets)       # rho = 1


def reference_study(args):
    """The reference study's setting and its number of mesh levels."""
    model, levels = ((AXISYMMETRIC, AXISYMMETRIC_LEVELS)
                     if args.reference_model == "axisymmetric" else
                     (REFERENCE, REFERENCE_LEVELS))
    return model, args.reference_levels or levels


def run_all(args, work):
    """The reference (unless given), CalculiX, then every diskimpact
    setting, one after the other; each part's wall time."""
    seconds = {}
    if not args.reference:
        reference = pc.run_reference(work, *reference_study(args))
        seconds["reference study"] = reference["seconds"]
    else:
        eps, bar = args.reference
        reference = {"epsilon": eps, "bar": bar, "levels": None,
                     "seconds": None}
    ccx = []
    for hmin in args.hmin:   # each mesh in its own directory
        start = time.time()
        mesh_work = os.path.join(work, f"calculix_h{hmin:g}")
        os.makedirs(mesh_work, exist_ok=True)
        run = pc.run_calculix(argparse.Namespace(**{**vars(args),
                                                    "hmin": hmin}),
                              mesh_work, calculix_input,
                              contact_time(args.speed))
        ccx.append({**run, "hmin": hmin})
        seconds[f"CalculiX h = {hmin:g} R (mesh, input and ccx)"] = \
            time.time() - start
    start = time.time()
    own = [(name, setting, pc.run_diskimpact(work, name, setting))
           for name, setting in DISKIMPACT_SETTINGS]
    seconds["diskimpact settings"] = time.time() - start
    return reference, ccx, own, seconds


def report(args, reference, ccx, own):
    model, levels = reference_study(args)
    pc.report_reference(reference, f"{args.reference_model} model, "
                        f"Q{model['degree']}, penalty factor "
                        f"{model['kappa']:g}, {levels} mesh levels")
    print(f"quarter sphere, nu = {pc.NU:g}, v = {pc.SPEED:g} c; "
          f"{pc.THREADS['OMP_NUM_THREADS']} thread each")
    for name, setting, _ in own:
        print(f"diskimpact {name}: {pc.describe(setting)}")
    for run in ccx:
        print(f"\nCalculiX: C3D10, h = {run['hmin']:g}..{args.hmax:g} R, "
              f"face-to-face penalty {pc.KAPPA:g} E2 / h, {run['steps']} "
              f"fixed increments of "
              f"{contact_time(args.speed) * math.sqrt(pc.E2):.3g}"
              f"/{args.steps_per_contact} R/c")
        pc.report_table(reference, run, own)
        if run["equations"] is not None and run["drift"] is not None:
            print(f"CalculiX: {run['equations']} equations, total energy "
                  f"varies by {100 * run['drift']:.2f} % of the initial "
                  f"kinetic energy")
        pc.report_comparison(reference, run, own)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    for flag, options in (
            ("--hmin", {"type": float, "nargs": "+", "default": [0.1],
                        "help": "CalculiX element size at the contact "
                        "point [R]; several sizes: one CalculiX run each, "
                        "each compared on its own (default %(default)s)"}),
            ("--hmax", {"type": float, "default": 0.25, "help":
                        "CalculiX element size far from the contact [R] "
                        "(default %(default)s)"}),
            ("--steps-per-contact", {"type": int, "default": 100, "help":
                                     "CalculiX time increments per contact "
                                     "time (default %(default)s)"}),
            ("--speed", {"type": float, "default": 0.1, "help":
                         "impact speed v/c (default %(default)s)"}),
            ("--reference-model", {"choices": ("3d", "axisymmetric"),
                                   "default": "3d", "help":
                                   "the reference study: diskimpact in 3D "
                                   "(two levels) or the axisymmetric model "
                                   "(three levels; sharper at low speeds)"}),
            ("--reference-levels", {"type": int, "choices": range(2, 7),
                                    "metavar": "N", "help":
                                    "mesh levels of the reference study "
                                    "(default: 2 in 3D, 3 axisymmetric)"}),
            ("--reference", {"type": float, "nargs": 2,
                             "metavar": ("EPS", "BAR"), "help":
                             "use this reference epsilon and bar; skips "
                             "diskimpact's convergence study"}),
            ("--work", {"help": "directory for the input and output files, "
                        "kept (default: a temporary one, removed)"})):
        parser.add_argument(flag, **options)
    args = parser.parse_args()
    pc.SPEED = args.speed
    pc.VELOCITY = args.speed * math.sqrt(pc.E2)
    if not os.path.exists(pc.EXE):
        pc.fail(f"{pc.EXE} not found; build first")
    start = time.time()
    if args.work:
        os.makedirs(args.work, exist_ok=True)
        reference, ccx, own, seconds = run_all(args,
                                               os.path.abspath(args.work))
    else:
        with tempfile.TemporaryDirectory() as work:
            reference, ccx, own, seconds = run_all(args, work)
    report(args, reference, ccx, own)
    print("wall time: " + ", ".join(f"{part} {s:.1f} s"
                                    for part, s in seconds.items()) +
          f"; total {time.time() - start:.1f} s")


if __name__ == "__main__":
    main()
