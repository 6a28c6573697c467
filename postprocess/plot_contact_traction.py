"""The wall's traction along the contact of an impact: pressure and friction.

usage: xvfb-run -a pvbatch postprocess/plot_contact_traction.py OUTPUT_DIR
           [-o out.png] [--csv out.csv] [--time T] [--pvd impact.pvd]

Reads the field contact_traction of OUTPUT_DIR/impact.pvd (a run of task
impact with Output interval small enough to catch the states of interest)
at the state nearest to T (in the .pvd's time unit; default: the state
with the largest total pressure), and plots, against the undeformed
coordinate along the wall's tangent, the pressure p (the traction's
component along the wall's normal) and the friction traction tau (along
the tangent), with +-mu p dashed: where |tau| reaches mu p the surface
slips, elsewhere it sticks. A sphere in 3D is shown in its plane of
incidence z = 0. --csv writes the numbers too. Without -o the PNG is
OUTPUT_DIR/contact_traction.png. Wall and mu come
from OUTPUT_DIR/used_parameters.json; units are the files' (Pa and m for
an SI run, else E and R of the parameter file).
"""
import argparse
import csv
import json
import os

from paraview.simple import MergeBlocks, PVDReader, servermanager
from vtk.numpy_interface import dataset_adapter as dsa

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def vector(text):
    values = [float(x) for x in text.split(",")]
    return np.array(values + [0.0] * (3 - len(values)))


def wall_and_friction(directory):
    with open(os.path.join(directory, "used_parameters.json")) as f:
        contact = json.load(f)["Contact"]
    normal = vector(contact["Wall normal"]["value"])
    normal /= np.linalg.norm(normal)
    tangent = np.array([-normal[1], normal[0], 0.0])
    return normal, tangent, float(contact["Friction coefficient"]["value"])


def state(merged, time):
    """Points and contact tractions of the state at @p time."""
    merged.UpdatePipeline(time)
    data = dsa.WrapDataObject(servermanager.Fetch(merged))
    if "contact_traction" not in data.PointData.keys():
        raise SystemExit("error: the files have no field contact_traction "
                         "(written by task impact)")
    return (np.asarray(data.Points),
            np.asarray(data.PointData["contact_traction"]))


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("directory")
    p.add_argument("-o", "--output")
    p.add_argument("--csv")
    p.add_argument("--time", type=float)
    p.add_argument("--pvd", default="impact.pvd")
    args = p.parse_args()
    pvd = os.path.join(args.directory, args.pvd)
    if not os.path.isfile(pvd):
        raise SystemExit(f"error: no {pvd}")
    normal, tangent, mu = wall_and_friction(args.directory)
    reader = PVDReader(FileName=pvd)
    merged = MergeBlocks(Input=reader)
    times = list(reader.TimestepValues) or [0.0]
    if args.time is None:
        totals = [np.abs(state(merged, t)[1] @ normal).sum() for t in times]
        time = times[int(np.argmax(totals))]
    else:
        time = min(times, key=lambda t: abs(t - args.time))
    points, traction = state(merged, time)
    pressure = traction @ normal
    friction = traction @ tangent
    keep = (np.abs(traction).sum(axis=1) > 0.0) & (np.abs(points[:, 2]) <
                                                   1e-9 * np.abs(points).max())
    if not keep.any():
        raise SystemExit(f"error: no contact at time {time:g}")
    s = points[keep] @ tangent
    rows = sorted(set(zip(np.round(s, 12), pressure[keep], friction[keep])))
    s, pressure, friction = (np.array(c) for c in zip(*rows))

    out = args.output or os.path.join(args.directory, "contact_traction.png")
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["coordinate_along_wall", "pressure",
                        "friction_traction"])
            w.writerows(zip(s, pressure, friction))
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.plot(s, pressure, "o-", ms=3, label="pressure p")
    ax.plot(s, friction, "s-", ms=3, label="friction traction τ")
    if mu > 0.0:
        ax.plot(s, mu * pressure, "k--", lw=0.8, label="±μ p (slip)")
        ax.plot(s, -mu * pressure, "k--", lw=0.8)
    ax.axhline(0.0, color="grey", lw=0.5)
    ax.set_xlabel("undeformed coordinate along the wall")
    ax.set_ylabel("traction")
    ax.set_title(f"contact traction at t = {time:.6g}")
    ax.legend()
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"{out}: t = {time:g}, {len(s)} points in contact, "
          f"largest p = {pressure.max():.6g}, largest |tau| = "
          f"{np.abs(friction).max():.6g}")


if __name__ == "__main__":
    main()
