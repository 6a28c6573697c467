"""Render the 3D view of a sphere's impact (impact_3d.pvd) with ParaView.

    xvfb-run -a pvbatch postprocess/render_sphere_3d.py OUTPUT_DIR
        [-o out.png] [--field von_mises] [--time T] [--warp-scale 1]
        [--size 900 700]

A sphere's impact run with 'Revolved view' > 0 (subsection Impact) writes
OUTPUT_DIR/impact_3d.pvd: the meridian revolved about the impact axis (the
3D x axis), as the sphere's surface and the two cut planes that show the
inside. This picks the snapshot nearest to T (default: the one with the
largest von Mises stress), warps it by the displacement times the scale
factor, colours it by the field and saves a PNG with the rigid wall x = 0
drawn as a grey square. A dimensionless run's field is shown over
E* = E / (1 - nu^2) (from OUTPUT_DIR/used_parameters.json); an SI run
(Units = SI) writes its .vtu files in SI and the field is shown in Pa.
"""

import argparse
import json
import os
import sys

from paraview.simple import (
    Calculator,
    ColorBy,
    GetActiveViewOrCreate,
    GetColorTransferFunction,
    GetScalarBar,
    Plane,
    PVDReader,
    SaveScreenshot,
    Show,
    WarpByVector,
)


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("output_dir", help="diskimpact output directory")
    parser.add_argument("-o", "--output", help="PNG to write (default "
                        "OUTPUT_DIR/impact_3d_<field>.png)")
    parser.add_argument("--field", default="von_mises",
                        choices=["von_mises", "pressure", "hoop_stress",
                                 "principal_stress_1", "principal_stress_2"])
    parser.add_argument("--time", type=float,
                        help="snapshot time, t c/R (s for an SI run; "
                        "default: the largest stress)")
    parser.add_argument("--warp-scale", type=float, default=1.0)
    parser.add_argument("--size", type=int, nargs=2, default=[900, 700])
    return parser.parse_args()


def stress_unit(output_dir):
    """How the .vtu's stresses are shown: (divisor, title suffix). SI runs
    write Pa; a dimensionless run's stresses are shown over
    E* = E / (1 - nu^2) from used_parameters.json (as written without it)."""
    path = os.path.join(output_dir, "used_parameters.json")
    if not os.path.exists(path):
        return 1.0, ""
    with open(path) as f:
        prm = json.load(f)

    def value(entry):
        return entry["value"] if isinstance(entry, dict) else entry

    if value(prm.get("Units", "dimensionless")) == "SI":
        return 1.0, " [Pa]"
    nu = float(value(prm["Material"]["Poisson ratio"]))
    return float(value(prm["Material"]["Young modulus"])) / (1.0 - nu * nu), " / E*"


def main():
    args = parse_arguments()
    pvd = os.path.join(args.output_dir, "impact_3d.pvd")
    if not os.path.exists(pvd):
        sys.exit(f"render_sphere_3d: {pvd} does not exist (run the sphere's "
                 "impact with 'Revolved view = 270' in subsection Impact)")
    reader = PVDReader(FileName=pvd)
    times = reader.TimestepValues
    times = list(times) if hasattr(times, "__len__") else [times or 0.0]

    def largest(time):
        reader.UpdatePipeline(time)
        return reader.GetPointDataInformation().GetArray(
            "von_mises").GetRange(0)[1]

    time = max(times, key=largest) if args.time is None else \
        min(times, key=lambda t: abs(t - args.time))
    modulus, unit = stress_unit(args.output_dir)
    scale = 1.0 / modulus
    shown = args.field + "_scaled"
    calculator = Calculator(Input=reader, AttributeType="Point Data",
                            ResultArrayName=shown,
                            Function=f"{args.field}*{scale!r}")
    warp = WarpByVector(Input=calculator, Vectors=["POINTS", "displacement"],
                        ScaleFactor=args.warp_scale)
    warp.UpdatePipeline(time)

    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = args.size
    view.ViewTime = time
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    display = Show(warp, view)
    display.Representation = "Surface"
    ColorBy(display, ("POINTS", shown))
    lut = GetColorTransferFunction(shown)
    low, high = warp.GetPointDataInformation().GetArray(shown).GetRange(0)
    signed = args.field != "von_mises"
    if signed:
        high = max(abs(low), abs(high))
        low = -high
    else:
        low = 0.0
    lut.ApplyPreset("Cool to Warm" if signed else "Viridis (matplotlib)",
                    True)
    lut.RescaleTransferFunction(low, max(high, low + 1e-12))
    lut.AutomaticRescaleRangeMode = "Never"
    display.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(lut, view)
    bar.Title = args.field + unit
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    bar.TitleFontSize = bar.LabelFontSize = 16
    bar.RangeLabelFormat = "%-#6.3g"

    # The wall x = 0, a square of side 2.6 R about the contact point.
    bounds = reader.GetDataInformation().GetBounds()
    radius = 0.5 * (bounds[1] - bounds[0])
    wall = Plane(Origin=[0.0, -1.3 * radius, -1.3 * radius],
                 Point1=[0.0, 1.3 * radius, -1.3 * radius],
                 Point2=[0.0, -1.3 * radius, 1.3 * radius])
    wall_display = Show(wall, view)
    wall_display.AmbientColor = wall_display.DiffuseColor = [0.6, 0.6, 0.6]
    wall_display.Opacity = 0.5

    view.CameraPosition = [4.0 * radius, 2.5 * radius, -3.5 * radius]
    view.CameraFocalPoint = [radius, 0.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.ResetCamera()
    view.CameraPosition = [4.0 * radius, 2.5 * radius, -3.5 * radius]
    view.CameraFocalPoint = [radius, 0.0, 0.0]
    view.Update()
    output = args.output or os.path.join(args.output_dir,
                                         f"impact_3d_{args.field}.png")
    SaveScreenshot(output, view, ImageResolution=args.size)
    print(f"render_sphere_3d: t = {time:g}"
          f"{' s' if unit == ' [Pa]' else ' R/c'}, {output}")


if __name__ == "__main__":
    main()
