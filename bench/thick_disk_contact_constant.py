#!/usr/bin/python3
"""The contact law's constant of free elastic disks of finite thickness.

A disk of radius R and thickness H pressed on the rigid wall with its rim by
a uniform body force of P per unit thickness (task 'quasistatic contact',
the quarter y >= 0, 0 <= z <= H/2 in 3D, faces free). Where the contact's
half-width a is small against H, the contact is locally plane strain, and
the approach of the centre of mass follows the logarithmic law in
plane-strain units,

    delta / R = x [ln(4 / x) + C(H/R)],   x = P / (pi E2 R),  E2 = E / (1 - nu^2),

whose constant C depends on H/R through the field beyond the contact (a
disk with held faces is the plane-strain disk, C = -2 ln 2 - (1 + nu2) / 4,
nu2 = nu / (1 - nu)). For each H the bench computes the 3D disk and the 2D
plane-strain disk on the same section mesh (the conforming graded mesh the
3D mesh extrudes; a held 3D disk equals that 2D disk to rounding), at two
loads with a = a1 = min(H/10, R/50) and a1 / 2, and takes

    C(H/R) = C_plane_strain + lim_{a -> 0} [C_3D(a) - C_2D(a)],

the limit extrapolated linearly in a (the faces' corners disturb the
contact over a length of order a). The difference cancels most of the
section's discretization and penalty errors. The bar is the size of the
extrapolation plus, with two meshes (--elements 4 6 --grading 0.6 0.4),
the change of the extrapolated difference between them. Runs finished in
--work are kept (time 0 in the table).

usage: bench/thick_disk_contact_constant.py [--thickness 0.1 0.25 0.5 1 2]
       [--elements 4] [--grading 0.6] [--penalty 400] [--poisson 0.3]
       [--ranks 2] [--work DIR] [--csv FILE]
About 32 minutes on 2 ranks with the defaults (one mesh).
"""
import argparse
import csv
import math
import os
import sys
import tempfile

from diskimpact_run import run_diskimpact


def prm_text(directory, thickness, loads, elements, grading, penalty, nu):
    """A quasistatic contact of the plane-strain section (thickness 0) or
    of the free 3D disk of @p thickness."""
    geometry = ("  set Dimension          = 3\n"
                f"  set Thickness          = {thickness!r}\n"
                "  set Faces              = free\n") if thickness else ""
    return f"""set Task             = quasistatic contact
set Output directory = {directory}
subsection Geometry
{geometry}  set Domain             = half disk
  set Global refinements = 0
end
subsection Material
  set Plane model   = plane strain
  set Poisson ratio = {nu!r}
end
subsection Contact
  set Penalty factor = {penalty!r}
end
subsection Quasistatic contact
  set Loads                   = {", ".join(repr(x) for x in loads)}
  set Graded mesh             = conforming
  set Elements across contact = {elements}
  set Grading                 = {grading!r}
  set Newton tolerance        = 1e-9
end
"""


def constants(work, name, thickness, loads, elements, grading, args):
    """C_com at each load of one run."""
    directory = os.path.join(work, name)
    prm = directory + ".prm"
    text = prm_text(directory, thickness, loads, elements, grading,
                    args.penalty, args.poisson)
    table = os.path.join(directory, "contact_law.csv")
    # A finished run of the same parameter file in --work is kept.
    finished = os.path.exists(table) and os.path.exists(prm) and \
        open(prm).read() == text
    seconds = 0.
    if not finished:
        if os.path.exists(table):      # another parameter file's result
            os.remove(table)
        with open(prm, "w") as f:
            f.write(text)
        seconds = run_diskimpact(prm, args.ranks)
    with open(table) as f:
        rows = list(csv.DictReader(f))
    return ([float(r["C_com"]) for r in rows], [int(r["n_dofs"]) for r in rows],
            seconds)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--thickness", type=float, nargs="+",
                        default=[0.1, 0.25, 0.5, 1., 2.], help="H / R")
    parser.add_argument("--elements", type=int, nargs="+", default=[4],
                        help="elements across a, one per mesh (even)")
    parser.add_argument("--grading", type=float, nargs="+", default=[0.6],
                        help="grading, one per mesh")
    parser.add_argument("--penalty", type=float, default=400.)
    parser.add_argument("--poisson", type=float, default=0.3)
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--work", default=None)
    parser.add_argument("--csv", default=None)
    args = parser.parse_args()
    if len(args.elements) != len(args.grading) or len(args.elements) > 2:
        sys.exit("thick_disk_contact_constant: give one or two meshes, as "
                 "many --grading as --elements")
    work = args.work or tempfile.mkdtemp(prefix="thick_disk_constant_")
    os.makedirs(work, exist_ok=True)
    nu = args.poisson
    nu2 = nu / (1. - nu)
    plane_strain = -2. * math.log(2.) - (1. + nu2) / 4.
    print(f"plane-strain constant C = -2 ln 2 - (1 + nu2)/4 = "
          f"{plane_strain:.6f} (nu = {nu}); work in {work}")
    print(" H/R  mesh   a/R      C_3D       C_2D    C_3D-C_2D     DoFs 3D"
          "   time [s] (the 3D run, both loads)")
    table = []
    for H in args.thickness:
        a1 = min(0.1 * H, 0.02)
        widths = [a1, 0.5 * a1]
        loads = [(a / 2.) ** 2 for a in widths]   # a = 2 R sqrt(x)
        limits = []
        for n, g in zip(args.elements, args.grading):
            tag = f"H{H:g}_n{n}_g{g:g}"
            c3, dofs, t3 = constants(work, "disk_" + tag, H, loads, n, g, args)
            c2, _, _ = constants(work, "section_" + tag, 0, loads, n, g, args)
            differences = [x - y for x, y in zip(c3, c2)]
            for a, x, y, d, m in zip(widths, c3, c2, differences, dofs):
                print(f"{H:4g}  {n}/{g:<4g} {a:.4f}  {x:9.5f}  {y:9.5f}  "
                      f"{d:9.5f}  {m:9d}  {t3:8.0f}", flush=True)
            limits.append((2. * differences[1] - differences[0],
                           abs(differences[1] - differences[0])))
        difference, extrapolation = limits[-1]
        mesh = abs(limits[-1][0] - limits[0][0]) if len(limits) > 1 else 0.
        table.append((H, plane_strain + difference, extrapolation + mesh,
                      extrapolation, mesh))
    print("\n H/R   C(H/R) +- bar          extrapolation  mesh")
    for H, C, bar, extrapolation, mesh in table:
        print(f"{H:4g}  {C:9.5f} +- {bar:.1e}     {extrapolation:.1e}"
              f"        {mesh:.1e}")
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            out = csv.writer(f)
            out.writerow(["thickness", "C_com", "bar", "extrapolation",
                          "mesh", "plane_strain"])
            for row in table:
                out.writerow(list(row) + [plane_strain])


if __name__ == "__main__":
    main()
