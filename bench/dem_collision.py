#!/usr/bin/python3
"""Head-on or oblique collision of two identical spheres in a DEM code (LIGGGHTS, LAMMPS or Yade).

Two spheres of radius R and density rho (atom type 1) sit on the x axis,
just apart, and move toward each other with speed v each (relative speed
2v). No gravity, no walls, box boundaries far away. The contact model comes
from a snippet file of ready-to-paste lines for the chosen code (SI units),
which is copied verbatim into the generated input script after the atoms
are created and before the run:

  LIGGGHTS:  fix ... property/global youngsModulus / poissonsRatio /
             coefficientRestitution / coefficientFriction ... lines and
             pair_style gran model hertz tangential history / pair_coeff * *
             (the script adds 'hard_particles yes', which LIGGGHTS 3.8 needs
             for E > 1e9 Pa in SI units)
  LAMMPS:    pair_style granular
             pair_coeff * * hertz/material E damp nu tangential ... damping ...
  Yade:      mat = O.materials.append(ViscElMat(en=..., tc=..., ...)), or
             LudingMat(k1=..., kp=..., ...) after a line 'tc = ...' (Python;
             the generated script builds both spheres from 'mat' with the
             matching Ip2 and Law2)

With --dimension 2 (LAMMPS only) the bodies are disks: 'dimension 2',
mass rho pi R^2 per unit thickness ('set ... density/disc'), moment of
inertia m R^2 / 2 ('fix nve/sphere disc'), and the snippet's law is the
linear 'hooke k_n eta_n' of the pair, whose contact time
pi / sqrt(k_n / m_eff - (eta_n / 2 m_eff)^2), m_eff = m / 2, sets dt.

The time step is dt = t_H / 2000 (Yade: tc / 2000, tc from the snippet)
with t_H the Hertz contact time
2.94328 (15 m v^2 / (16 E* sqrt(R)))^(2/5) / v, m the sphere mass and
E* = E / (1 - nu^2) (E and nu parsed from youngsModulus / poissonsRatio,
or from the numbers after hertz/material, dmt or jkr). That wall-equivalent
time equals the one of the two-sphere problem. The spheres start 20 steps
of travel apart and run 3 t_H beyond that.

The centre gap d - 2R and both x-velocities are written every step (fix
print; Yade: a PyRunner). Then
  epsilon      = -(v1x' - v2x') / (v1x - v2x), before = first line,
                 after = last line (the spheres must have separated),
  contact_time = time with d < 2R, from the first and last overlapping
                 steps, each end refined by linear interpolation of the gap
                 between the bracketing steps.

usage: bench/dem_collision.py --code liggghts|lammps|yade --snippet FILE
                              --radius R --density RHO --speeds v1 [v2 ...]
                              [--dimension 3|2] [--work DIR]
       prints 'speed <v> epsilon <eps> contact_time <t_c>' per speed.
       Without --work each run happens in a temporary directory, removed
       unless the run fails.

As a module: collide(code, snippet_text, radius, density, speed, work_dir)
returns (epsilon, contact_time); hertz_time(...) gives t_H.
oblique(code, snippet_text, radius, density, speed, angle, work_dir) runs
the collision at an angle of incidence: each sphere also moves along the
contact plane (point-symmetric, so the contact plane acts on each sphere
as a rigid wall would, friction and Mindlin's stiffness included) and it
returns sphere 1's tangential restitution, spin and rebound angle as well
(the y-velocity and z-spin of sphere 1 join the history).
bench/dem_check_deps.sh installs the three codes.
"""
import argparse
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

BINARY = {"liggghts": "liggghts", "lammps": "lmp", "yade": "yade"}
STEPS_PER_CONTACT = 2000   # dt = t_H / STEPS_PER_CONTACT
PRE_STEPS = 20             # steps of free travel before contact
RUN_CONTACTS = 3           # run length after contact begins, in t_H


class DEMError(RuntimeError):
    """A DEM run that could not be set up, failed or gave unusable output."""

    def __init__(self, message, log_tail=""):
        super().__init__(message)
        self.log_tail = log_tail


def material(code, snippet):
    """(E, nu) of atom type 1 as given in the snippet."""
    if code == "liggghts":
        E = re.search(r"\byoungsModulus\s+peratomtype\s+(\S+)", snippet)
        nu = re.search(r"\bpoissonsRatio\s+peratomtype\s+(\S+)", snippet)
    else:  # E damp nu
        E = nu = re.search(r"\b(?:hertz/material|dmt|jkr)\s+(\S+)\s+\S+\s+"
                           r"(\S+)", snippet)
    try:
        return float(E.group(1)), float(nu.group(nu.lastindex))
    except (AttributeError, ValueError):
        raise DEMError("cannot read Young's modulus and Poisson ratio from "
                       "the %s snippet" % code) from None


def hertz_time(radius, density, E, nu, speed):
    """Hertz contact time of a sphere hitting a rigid wall at speed v."""
    m = density * 4.0 / 3.0 * math.pi * radius**3
    e_star = E / (1.0 - nu**2)
    return 2.94328 * (15.0 * m * speed**2
                      / (16.0 * e_star * math.sqrt(radius)))**0.4 / speed


def linear_time(snippet, radius, density):
    """Contact time of two disks (mass rho pi R^2 per unit thickness) with
    the snippet's linear spring-dashpot 'hooke k_n eta_n'."""
    law = re.search(r"^pair_coeff.*\bhooke\s+(\S+)\s+(\S+)", snippet,
                    re.MULTILINE)
    if law is None:
        raise DEMError("cannot read 'hooke k_n eta_n' from the 2D snippet")
    k, eta = float(law.group(1)), float(law.group(2))
    m_eff = 0.5 * density * math.pi * radius**2
    omega2 = k / m_eff - (0.5 * eta / m_eff)**2
    if not omega2 > 0.0:
        raise DEMError("the snippet's spring-dashpot is overdamped")
    return math.pi / math.sqrt(omega2)


def time_step(code, snippet, radius, density, speed, dimension=3,
              steps_per_contact=STEPS_PER_CONTACT):
    """dt: the contact time of the snippet's law / steps_per_contact."""
    if dimension == 2:
        return linear_time(snippet, radius, density) / steps_per_contact
    if code == "yade":
        tc = re.search(r"\btc\s*=\s*([^,)\s]+)", snippet)
        if tc is None:
            raise DEMError("cannot read tc from the yade snippet")
        return float(tc.group(1)) / steps_per_contact
    E, nu = material(code, snippet)
    return hertz_time(radius, density, E, nu, speed) / steps_per_contact


def yade_script(snippet, radius, speed, tangential, dt, steps, gap):
    """Yade's script: the snippet defines 'mat' (ViscElMat or LudingMat); a
    PyRunner writes the history 'step gap v1x v2x v1y omega1z'."""
    x = radius + 0.5 * gap
    law = "LudingMat_LudingMat_LudingPhys" if "LudingMat(" in snippet else \
        "ViscElMat_ViscElMat_ViscElPhys"
    physics = law.split("_")[-1]
    return f"""\
# ---- contact model (snippet) ----
{snippet.strip()}
# ---- end of snippet ----

O.bodies.append([sphere((-{x!r}, 0, 0), {radius!r}, material=mat),
                 sphere(({x!r}, 0, 0), {radius!r}, material=mat)])
O.bodies[0].state.vel = Vector3({speed!r}, {-tangential!r}, 0)
O.bodies[1].state.vel = Vector3(-{speed!r}, {tangential!r}, 0)
history = open("history.txt", "w")


def record():
    a, b = O.bodies[0].state, O.bodies[1].state
    history.write("%d %r %r %r %r %r\\n" % (O.iter, (b.pos - a.pos).norm()
                                            - {2 * radius!r}, a.vel[0],
                                            b.vel[0], a.vel[1],
                                            a.angVel[2]))


O.engines = [ForceResetter(),
             InsertionSortCollider([Bo1_Sphere_Aabb()]),
             InteractionLoop([Ig2_Sphere_Sphere_ScGeom()],
                             [Ip2_{law}()],
                             [Law2_ScGeom_{physics}_Basic()]),
             NewtonIntegrator(damping=0., gravity=(0, 0, 0)),
             PyRunner(command="record()", iterPeriod=1)]
O.dt = {dt!r}
O.run({steps}, True)
history.close()
"""


def input_script(code, snippet, radius, density, speed, tangential, dt,
                 steps, gap, dimension=3):
    """The complete input script; fix print writes
    'step gap v1x v2x v1y omega1z'."""
    if code == "yade":
        return yade_script(snippet, radius, speed, tangential, dt, steps, gap)
    half = 4.0 * radius
    x = radius + 0.5 * gap
    # 2D: disks in the plane z = 0 (LAMMPS needs a periodic z).
    flat = dimension == 2
    boundary = "f f p" if flat else "f f f"
    density_keyword = "density/disc" if flat else "density"
    integrator = ("nve/sphere disc\nfix flat all enforce2d" if flat
                  else "nve/sphere")
    if code == "liggghts":
        setup = "communicate single vel yes"
        hard = "hard_particles yes  # LIGGGHTS: allows E > 1e9 Pa in SI units\n"
    else:
        setup = "comm_modify vel yes"
        hard = ""
    return f"""\
units si
{"dimension 2" if flat else ""}
atom_style {"granular" if code == "liggghts" else "sphere"}
atom_modify map array
boundary {boundary}
newton off
{setup}
region box block {-half!r} {half!r} {-half!r} {half!r} {-half!r} {half!r} units box
create_box 1 box
neighbor {0.1 * radius!r} bin
neigh_modify delay 0 every 1 check yes
create_atoms 1 single {-x!r} 0 0 units box
create_atoms 1 single {x!r} 0 0 units box
set atom 1 diameter {2 * radius!r} {density_keyword} {density!r} vx {speed!r} vy {-tangential!r}
set atom 2 diameter {2 * radius!r} {density_keyword} {density!r} vx {-speed!r} vy {tangential!r}
{hard}
# ---- contact model (snippet) ----
{snippet.strip()}
# ---- end of snippet ----

fix integr all {integrator}
timestep {dt!r}
variable s equal step
variable g equal sqrt((x[2]-x[1])^2+(y[2]-y[1])^2+(z[2]-z[1])^2)-{2 * radius!r}
variable v1 equal vx[1]
variable v2 equal vx[2]
variable t1 equal vy[1]
compute spin all property/atom omegaz
variable w1 equal c_spin[1]
fix hist all print 1 "${{s}} ${{g}} ${{v1}} ${{v2}} ${{t1}} ${{w1}}" file history.txt screen no
thermo {steps}
run {steps}
"""


def analyse(path, dt, radius=1.0):
    """(epsilon, contact_time) from the fix print history, and the
    tangential outcome of sphere 1 (oblique()'s dictionary without
    epsilon and contact_time)."""
    rows = [[float(w) for w in line.split()] for line in open(path)
            if line.strip() and not line.startswith("#")]
    if len(rows) < 3:
        raise DEMError("history %s has %d lines" % (path, len(rows)))
    t = [r[0] * dt for r in rows]
    gap = [r[1] for r in rows]
    inside = [i for i, g in enumerate(gap) if g < 0.0]
    if not inside:
        raise DEMError("the spheres never touched")
    first, last = inside[0], inside[-1]
    if first == 0:
        raise DEMError("the spheres overlap from the first output step")
    if last == len(rows) - 1:
        raise DEMError("the spheres are still in contact at the end of the run")
    if len(inside) != last - first + 1:
        raise DEMError("the spheres touched more than once")

    def crossing(i, j):  # time of gap = 0 between rows i (gap >= 0) and j
        return t[i] + (t[j] - t[i]) * gap[i] / (gap[i] - gap[j])

    contact_time = crossing(last + 1, last) - crossing(first - 1, first)
    before = rows[0][2] - rows[0][3]
    after = rows[-1][2] - rows[-1][3]
    # Sphere 1 in the wall's frame: normal n = -x, tangent t = e_z x n = -y,
    # spin counterclockwise about e_z.
    v_n, v_n1 = rows[0][2], -rows[-1][2]
    v_t, v_t1, spin1 = -rows[0][4], -rows[-1][4], rows[-1][5]
    tangential = {"rebound_angle": math.degrees(math.atan2(v_t1, v_n1)),
                  "spin": spin1 * radius / v_n}
    if v_t != 0.0:
        tangential["tangential_restitution"] = v_t1 / v_t
        tangential["contact_point_restitution"] = -(v_t1 - spin1 * radius) / v_t
    return -after / before, contact_time, tangential


def collide(code, snippet_text, radius, density, speed, work_dir=None,
            dimension=3, steps_per_contact=STEPS_PER_CONTACT):
    """Run one head-on collision; returns (epsilon, contact_time)."""
    return run(code, snippet_text, radius, density, speed, 0.0, work_dir,
               dimension, steps_per_contact)[:2]


def oblique(code, snippet_text, radius, density, speed, angle,
            work_dir=None, dimension=3):
    """Run one oblique collision at the angle of incidence @p angle (degrees;
    each sphere's speed @p speed, its normal part speed cos(angle), no spin);
    returns a dictionary of sphere 1's outcome, as on a wall: epsilon,
    contact_time, tangential_restitution (v_t'/v_t), spin (R omega'/v_n,
    counterclockwise with the contact point's velocity v_t - omega R),
    contact_point_restitution (-v_cp'/v_cp) and rebound_angle (degrees)."""
    v_n = speed * math.cos(math.radians(angle))
    v_t = speed * math.sin(math.radians(angle))
    eps, tc, tangential = run(code, snippet_text, radius, density, v_n, v_t,
                              work_dir, dimension)
    return dict(tangential, epsilon=eps, contact_time=tc)


def run(code, snippet_text, radius, density, speed, tangential,
        work_dir=None, dimension=3, steps_per_contact=STEPS_PER_CONTACT):
    """Run one collision, normal speed @p speed and tangential speed
    @p tangential of each sphere (disk in 2D); returns analyse()'s triple."""
    if code not in BINARY:
        raise DEMError("unknown code %r (liggghts, lammps or yade)" % code)
    if dimension == 2 and code != "lammps":
        raise DEMError("2D collisions run in LAMMPS only")
    exe = shutil.which(BINARY[code])
    if exe is None:
        raise DEMError("%s binary '%s' not found on PATH (bench/"
                       "dem_check_deps.sh installs it)" % (code, BINARY[code]))
    if work_dir is None:  # a temporary directory, kept if the run fails
        tmp = tempfile.mkdtemp(prefix="dem_collision_")
        result = run(code, snippet_text, radius, density, speed, tangential,
                     tmp, dimension, steps_per_contact)
        shutil.rmtree(tmp)
        return result
    dt = time_step(code, snippet_text, radius, density, speed, dimension,
                   steps_per_contact)
    steps = PRE_STEPS + RUN_CONTACTS * steps_per_contact
    gap = 2.0 * speed * PRE_STEPS * dt
    run_dir = os.path.join(work_dir, "%s_v%r_t%r" % (code, speed, tangential))
    os.makedirs(run_dir, exist_ok=True)
    script = "collision.py" if code == "yade" else "in.collision"
    with open(os.path.join(run_dir, script), "w") as f:
        f.write(input_script(code, snippet_text, radius, density, speed,
                             tangential, dt, steps, gap, dimension))
    history = os.path.join(run_dir, "history.txt")
    if os.path.exists(history):
        os.remove(history)
    log = os.path.join(run_dir, "run.log")
    with open(log, "w") as out:
        command = ([exe, "-n", "-x", script] if code == "yade" else
                   [exe, "-echo", "screen", "-log", "none", "-in", script])
        rc = subprocess.call(command,
                             cwd=run_dir, stdout=out, stderr=subprocess.STDOUT)
    tail = "".join(open(log, errors="replace").readlines()[-15:])
    if rc != 0 or not os.path.exists(history):
        raise DEMError("%s run failed (exit status %d), log %s:"
                       % (code, rc, log), tail)
    try:
        return analyse(history, dt, radius)
    except DEMError as e:
        raise DEMError("%s (%s)" % (e, run_dir), tail)


def main():
    p = argparse.ArgumentParser(
        description="Coefficient of restitution and contact time of two "
                    "identical spheres colliding head-on in LIGGGHTS, LAMMPS "
                    "or Yade.")
    p.add_argument("--code", required=True, choices=sorted(BINARY))
    p.add_argument("--snippet", required=True,
                   help="file with the contact-model lines (SI units)")
    p.add_argument("--radius", type=float, required=True, help="R in m")
    p.add_argument("--density", type=float, required=True, help="kg/m^3")
    p.add_argument("--speeds", type=float, nargs="+", required=True,
                   help="speed v of each sphere in m/s (relative speed 2v)")
    p.add_argument("--dimension", type=int, choices=(2, 3), default=3,
                   help="2: disks in LAMMPS' 2D (per unit thickness)")
    p.add_argument("--work", help="directory for the runs (default: temporary)")
    args = p.parse_args()
    snippet = open(args.snippet).read()
    try:
        for v in args.speeds:
            eps, tc = collide(args.code, snippet, args.radius, args.density, v,
                              args.work, args.dimension)
            print("speed %r epsilon %r contact_time %r" % (v, eps, tc),
                  flush=True)
    except DEMError as e:
        print("dem_collision: error: %s" % e, file=sys.stderr)
        if e.log_tail:
            sys.stderr.write(e.log_tail)
        sys.exit(1)


if __name__ == "__main__":
    main()
