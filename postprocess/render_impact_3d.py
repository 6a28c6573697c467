"""Render an impact computed in 3D (impact.pvd) at its largest stress with
ParaView.

    xvfb-run -a pvbatch postprocess/render_impact_3d.py OUTPUT_DIR
        [-o out.png] [--warp-scale 3] [--field von_mises] [--size 900 700]

Task 'impact' with 'Dimension = 3' writes OUTPUT_DIR/impact.pvd with the
computed quarter of the body. This picks the state with the largest von
Mises stress (the body at its largest compression), mirrors the quarter
about the planes z = 0 and y = 0 into three quarters of the whole body
(the quarter y < 0, z > 0 open to show the inside), warps it by
--warp-scale times the displacement, colours it by --field (von_mises or
pressure, in units of E* or Pa as the run's), draws the wall as a grey
square and saves a PNG
(default OUTPUT_DIR/impact_3d_<field>.png).
"""

import argparse
import os
import sys

from paraview.simple import (
    AppendDatasets,
    ColorBy,
    GetActiveViewOrCreate,
    GetColorTransferFunction,
    GetScalarBar,
    Plane,
    PVDReader,
    Reflect,
    SaveScreenshot,
    Show,
    Text,
    WarpByVector,
)
from paraview import servermanager


def largest_stress_time(reader, field):
    """The time of the state whose field reaches its largest value."""
    best_time, best = reader.TimestepValues[0], -1.0
    for time in reader.TimestepValues:
        reader.UpdatePipeline(time)
        data = servermanager.Fetch(reader)
        array = data.GetPointData().GetArray(field)
        if array is None:
            continue
        high = array.GetRange()[1]
        if high > best:
            best_time, best = time, high
    return best_time


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("output_dir", help="diskimpact output directory")
    parser.add_argument("-o", "--output", help="PNG to write")
    parser.add_argument("--warp-scale", type=float, default=3.0)
    parser.add_argument("--field", default="von_mises",
                        choices=["von_mises", "pressure"])
    parser.add_argument("--size", type=int, nargs=2, default=[900, 700])
    args = parser.parse_args()

    pvd = os.path.join(args.output_dir, "impact.pvd")
    if not os.path.exists(pvd):
        sys.exit(f"render_impact_3d: {pvd} does not exist (run task 'impact' "
                 "with 'Dimension = 3')")
    reader = PVDReader(FileName=pvd)
    time = largest_stress_time(reader, args.field)

    # Three quarters of the whole body: the computed one, its mirror image
    # about z = 0 and that one's about y = 0; the quarter y < 0, z > 0 is
    # left open to show the inside.
    below = Reflect(Input=reader)
    below.Plane = "Z"
    below.CopyInput = 0
    across = Reflect(Input=below)
    across.Plane = "Y"
    across.CopyInput = 0
    body = AppendDatasets(Input=[reader, below, across])
    warped = WarpByVector(Input=body)
    warped.Vectors = ["POINTS", "displacement"]
    warped.ScaleFactor = args.warp_scale

    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = args.size
    view.ViewTime = time
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    view.Background = [1, 1, 1]
    view.OrientationAxesVisibility = 1
    display = Show(warped, view)
    ColorBy(display, ("POINTS", args.field))
    display.RescaleTransferFunctionToDataRange(True, False)
    display.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(GetColorTransferFunction(args.field), view)
    bar.Title = args.field.replace("_", " ")
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0, 0, 0]

    # The wall x = 0, a grey square behind the body.
    bounds = reader.GetDataInformation().GetBounds()
    size = 1.3 * (bounds[1] - bounds[0])
    wall = Plane(Origin=[0, -size / 2, -size / 2],
                 Point1=[0, size / 2, -size / 2],
                 Point2=[0, -size / 2, size / 2])
    wall_display = Show(wall, view)
    wall_display.ColorArrayName = [None, ""]
    wall_display.DiffuseColor = [0.6, 0.6, 0.6]
    wall_display.Opacity = 0.5

    label = Text(Text=f"t = {time:.4g}, displacement x {args.warp_scale:g}")
    label_display = Show(label, view)
    label_display.Color = [0, 0, 0]
    label_display.FontSize = 14
    label_display.WindowLocation = "Upper Center"
    radius = 0.5 * (bounds[1] - bounds[0])
    view.CameraFocalPoint = [radius, 0, 0]
    view.CameraPosition = [radius + 3.0 * radius, -2.6 * radius, 2.2 * radius]
    view.CameraViewUp = [0, 0, 1]
    view.ResetCamera()
    output = args.output or os.path.join(args.output_dir,
                                         f"impact_3d_{args.field}.png")
    SaveScreenshot(output, view, ImageResolution=args.size)
    print(f"render_impact_3d: wrote {output}")


if __name__ == "__main__":
    main()
