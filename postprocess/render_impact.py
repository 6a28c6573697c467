"""Render one deformed state of a diskimpact run with ParaView, whole disk.

    xvfb-run -a pvbatch postprocess/render_impact.py OUTPUT_DIR [-o out.png]
        [--field von_mises] [--time T] [--warp-scale 1] [--range MIN MAX]
        [--size 800 600] [--zoom H] [--pvd impact.pvd]

Loads OUTPUT_DIR/impact.pvd (task impact; --pvd contact.pvd for task
quasistatic contact), picks the snapshot nearest to T (default: the one with
the largest von Mises stress), reflects a half disk (Domain = half disk, the
mesh lies in y >= 0) about the impact axis y = 0 with ParaView's Reflect
filter (the y components of vectors and the xy components of tensors change
sign; a full disk is left as it is), warps it by the displacement times the
scale factor, colours it by the field and saves a PNG with a colour bar and
the time in the title. The rigid wall is drawn as a black line (not with a
partner body, subsection Partner: both bodies are in the PVD). An
elastic-plastic body's cell fields equivalent_plastic_strain and
von_mises_stress can be shown; --zoom H shows the square of half-size H R
next to the contact.

Units: a dimensionless run's .vtu files hold the values in the units of the
parameter file; the colour bar shows stresses over E2 and the displacement
magnitude over R (E2 and R read from OUTPUT_DIR/used_parameters.json), and
the title's time is t c/R (impact.pvd) or the load P/(pi E2 R)
(contact.pvd), as in the .pvd file. An SI run (Units = SI) writes SI: the
colour bar shows stresses in Pa and displacements in m, the title the time
in s.
"""

import argparse
import json
import math
import os
import sys

from paraview.simple import (
    Calculator,
    ColorBy,
    GetActiveViewOrCreate,
    GetColorTransferFunction,
    GetScalarBar,
    Line,
    PVDReader,
    Reflect,
    SaveScreenshot,
    Show,
    Text,
    WarpByVector,
)

FIELDS = {
    "von_mises": ("von Mises stress", "stress"),
    "principal_stress_1": ("largest principal stress", "stress"),
    "principal_stress_2": ("smallest principal stress", "stress"),
    "pressure": ("pressure -tr(sigma)/3", "stress"),
    "displacement": ("displacement magnitude", "length"),
    # An elastic-plastic body's cell fields.
    "equivalent_plastic_strain": ("equivalent plastic strain", "strain"),
    "von_mises_stress": ("von Mises stress", "stress"),
}


def parse_arguments():
    parser = argparse.ArgumentParser(
        description="Render a diskimpact state (impact.pvd) as a PNG, the "
        "half disk reflected about y = 0.")
    parser.add_argument("output_dir", help="diskimpact output directory")
    parser.add_argument("-o", "--output",
                        help="PNG to write (default OUTPUT_DIR/"
                        "<pvd name>_<field>.png)")
    parser.add_argument("--field", default="von_mises", choices=FIELDS,
                        help="field to colour by (default von_mises)")
    parser.add_argument("--time", type=float,
                        help="time of the snapshot: the nearest one is "
                        "shown (units of the .pvd: R/c for impact.pvd, s "
                        "for an SI run); "
                        "default the snapshot with the largest von Mises "
                        "stress (an elastic-plastic body's: the last)")
    parser.add_argument("--warp-scale", type=float, default=1.0,
                        help="displacement scale factor (default 1: the "
                        "true deformed disk; the displacement includes the "
                        "rigid-body motion, which other factors scale too)")
    parser.add_argument("--range", type=float, nargs=2,
                        metavar=("MIN", "MAX"),
                        help="colour range in the colour bar's units "
                        "(default: the snapshot's range, symmetric about "
                        "0 for signed fields)")
    parser.add_argument("--size", type=int, nargs=2, default=[800, 600],
                        metavar=("WIDTH", "HEIGHT"),
                        help="image size in pixels (default 800 600)")
    parser.add_argument("--zoom", type=float,
                        help="show the square of half-size ZOOM R about "
                        "the wall point (the contact) instead of the whole "
                        "body")
    parser.add_argument("--pvd", default="impact.pvd",
                        help="the .pvd file in OUTPUT_DIR (default "
                        "impact.pvd; contact.pvd has the same fields)")
    return parser.parse_args()


def run_constants(output_dir):
    """E2, R and the wall (point, normal) from used_parameters.json."""
    path = os.path.join(output_dir, "used_parameters.json")
    if not os.path.exists(path):
        print(f"render_impact: no {path}; values shown as written "
              "(units of the parameter file)", file=sys.stderr)
        return None
    with open(path) as f:
        prm = json.load(f)

    def entry(section, name):
        # deal.II's JSON: {"Section": {"Entry": {"value": "...", ...}}}
        value = prm[section][name]
        return value["value"] if isinstance(value, dict) else value

    def vector(section, name):
        return [float(x) for x in entry(section, name).split(",")]

    units = prm.get("Units", "dimensionless")
    units = units["value"] if isinstance(units, dict) else units
    young = float(entry("Material", "Young modulus"))
    nu = float(entry("Material", "Poisson ratio"))
    plane_strain = entry("Material", "Plane model") == "plane strain"
    return {
        # E2 = E / (1 - nu^2) in plane strain (Gerl & Zippelius 1999, eq. 2).
        "E2": young / (1 - nu * nu) if plane_strain else young,
        "R": float(entry("Geometry", "Radius")),
        "wall_point": vector("Contact", "Wall point"),
        "wall_normal": vector("Contact", "Wall normal"),
        # A partner body (subsection Partner) replaces the wall.
        "partner_body": "Partner" in prm and entry("Partner", "Kind") == "body",
        # An SI run writes its .vtu files in SI (m, Pa) and the .pvd in s.
        "si": units == "SI",
    }


def field_maximum(source, name, time):
    source.UpdatePipeline(time)
    array = source.GetPointDataInformation().GetArray(name)
    if array is None:  # an elastic-plastic body writes no von_mises
        return time
    return array.GetRange(-1 if array.GetNumberOfComponents() > 1 else 0)[1]


def main():
    args = parse_arguments()
    pvd = os.path.join(args.output_dir, args.pvd)
    if not os.path.exists(pvd):
        sys.exit(f"render_impact: {pvd} does not exist (task impact writes "
                 "impact.pvd, task quasistatic contact contact.pvd)")
    reader = PVDReader(FileName=pvd)
    times = reader.TimestepValues
    times = list(times) if hasattr(times, "__len__") else [times or 0.0]

    if args.time is None:
        time = max(times, key=lambda t: field_maximum(reader, "von_mises", t))
    else:
        time = min(times, key=lambda t: abs(t - args.time))
        if abs(time - args.time) > 1e-9 * max(1.0, abs(args.time)):
            print(f"render_impact: no snapshot at {args.time:g}; showing the "
                  f"nearest, {time:g} (snapshots {times[0]:g} .. "
                  f"{times[-1]:g})")

    # A half disk lies in y >= 0: mirror it (and its fields) about y = 0.
    reader.UpdatePipeline(time)
    xmin, xmax, ymin, ymax = reader.GetDataInformation().GetBounds()[:4]
    source = reader
    if ymin > -1e-6 * (xmax - xmin):
        source = Reflect(Input=reader, Plane="Y", Center=0.0, CopyInput=1,
                         FlipAllInputArrays=1)
        print("render_impact: half disk reflected about y = 0")

    constants = run_constants(args.output_dir)
    label, kind = FIELDS[args.field]
    if kind == "strain":
        scale, unit = 1.0, "as written"
    elif constants is None:
        scale, unit = 1.0, "as written"  # no "/ unit" in the colour bar
    elif constants["si"]:
        scale, unit = 1.0, "Pa" if kind == "stress" else "m"
    elif kind == "stress":
        scale, unit = 1.0 / constants["E2"], "E2"
    else:
        scale, unit = 1.0 / constants["R"], "R"
    expression = "mag(displacement)" if args.field == "displacement" \
        else args.field
    shown = args.field + "_scaled"
    calculator = Calculator(Input=source, AttributeType="Point Data",
                            ResultArrayName=shown,
                            Function=f"{expression}*{scale!r}")
    warp = WarpByVector(Input=calculator, Vectors=["POINTS", "displacement"],
                        ScaleFactor=args.warp_scale)
    warp.UpdatePipeline(time)

    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = args.size
    view.ViewTime = time
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    view.InteractionMode = "2D"
    view.CameraParallelProjection = 1

    display = Show(warp, view)
    display.Representation = "Surface"
    ColorBy(display, ("POINTS", shown))
    lut = GetColorTransferFunction(shown)
    low, high = warp.GetPointDataInformation().GetArray(shown).GetRange(0)
    signed = args.field in ("principal_stress_1", "principal_stress_2",
                            "pressure")
    if args.range:
        low, high = args.range
    elif signed:
        high = max(abs(low), abs(high))
        low = -high
    else:
        low = 0.0
    if high <= low:
        high = low + 1e-12
    lut.ApplyPreset("Cool to Warm" if signed else "Viridis (matplotlib)",
                    True)
    lut.RescaleTransferFunction(low, high)
    lut.AutomaticRescaleRangeMode = "Never"
    display.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(lut, view)
    bar.Title = (args.field if unit == "as written" else
                 f"{args.field} [{unit}]" if constants and constants["si"] else
                 f"{args.field} / {unit}")
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    bar.TitleFontSize = bar.LabelFontSize = 16
    bar.RangeLabelFormat = "%-#6.3g"
    bar.WindowLocation = "Any Location"
    bar.Orientation = "Vertical"
    bar.Position = [0.86, 0.15]
    bar.ScalarBarLength = 0.7

    # The wall: the line through the wall point normal to the wall normal
    # (none when the body collides with a partner body).
    if constants is not None and not constants["partner_body"]:
        (px, py), (nx, ny) = constants["wall_point"], constants["wall_normal"]
        length = math.hypot(nx, ny)
        tx, ty = -ny / length, nx / length
        half = 1.3 * constants["R"]
        wall = Line(Point1=[px - half * tx, py - half * ty, 0.0],
                    Point2=[px + half * tx, py + half * ty, 0.0])
        wall_display = Show(wall, view)
        wall_display.AmbientColor = wall_display.DiffuseColor = [0, 0, 0]
        wall_display.LineWidth = 3.0

    si = constants is not None and constants["si"]
    when = (f"t = {time:.4g} s" if si and args.pvd.startswith("impact")
            else f"t = {time:.3f} R/c" if args.pvd.startswith("impact")
            else f"P/(pi E2 R) = {time:.3g}" if args.pvd.startswith("contact")
            else f"time {time:g}")
    title = Text(Text=f"{label}, {when}")
    title_display = Show(title, view)
    title_display.WindowLocation = "Upper Center"
    title_display.FontSize = 22
    title_display.Color = [0.0, 0.0, 0.0]

    view.CameraPosition = [0.0, 0.0, 1.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.ResetCamera()
    view.CameraParallelScale *= 1.04
    if args.zoom and constants is not None:
        (px, py) = constants["wall_point"]
        half = args.zoom * constants["R"]
        view.CameraFocalPoint = [px + half, py, 0.0]
        view.CameraPosition = [px + half, py, 1.0]
        view.CameraParallelScale = half

    output = args.output or os.path.join(
        args.output_dir,
        f"{os.path.splitext(args.pvd)[0]}_{args.field}.png")
    SaveScreenshot(output, view, ImageResolution=args.size)
    print(f"render_impact: {label} at {when} "
          f"(colour range {low:.4g} .. {high:.4g} {unit}) -> {output}")


if __name__ == "__main__":
    main()
