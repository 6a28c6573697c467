"""Render one mode shape of a body computed in 3D (modes.pvd) with ParaView.

    xvfb-run -a pvbatch postprocess/render_mode_3d.py OUTPUT_DIR --mode N
        [-o out.png] [--warp-scale 0.15] [--size 800 700]

Task 'modal analysis' with 'Dimension = 3' writes OUTPUT_DIR/modes.pvd with
one vector field mode_NNN per mode (NNN = the index of modes.csv). This
warps the body by mode N (mass-normalized, times the scale), colours it by
the displacement's magnitude, titles it with the mode's label from
OUTPUT_DIR/modes.csv and saves a PNG (default OUTPUT_DIR/mode_NNN.png).
"""

import argparse
import csv
import os
import sys

from paraview.simple import (
    ColorBy,
    GetActiveViewOrCreate,
    GetColorTransferFunction,
    GetScalarBar,
    PVDReader,
    SaveScreenshot,
    Show,
    Text,
    WarpByVector,
)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("output_dir", help="diskimpact output directory")
    parser.add_argument("--mode", type=int, required=True,
                        help="the mode's index in modes.csv")
    parser.add_argument("-o", "--output", help="PNG to write")
    parser.add_argument("--warp-scale", type=float, default=0.15)
    parser.add_argument("--size", type=int, nargs=2, default=[800, 700])
    args = parser.parse_args()

    pvd = os.path.join(args.output_dir, "modes.pvd")
    if not os.path.exists(pvd):
        sys.exit(f"render_mode_3d: {pvd} does not exist (run task 'modal "
                 "analysis' with 'Dimension = 3')")
    with open(os.path.join(args.output_dir, "modes.csv"), newline="") as f:
        rows = {int(r["index"]): r for r in csv.DictReader(f)}
    if args.mode not in rows:
        sys.exit(f"render_mode_3d: no mode {args.mode} in modes.csv "
                 f"(0 ... {max(rows)})")
    row = rows[args.mode]
    field = f"mode_{args.mode:03d}"
    title = (f"mode {args.mode}: {row['family']} n = {row['n']}, l = {row['l']}"
             f" ({row['multiplicity']} modes), omega = {float(row['omega']):.6f}"
             if row["family"] not in ("rigid", "unlabelled")
             else f"mode {args.mode}: {row['family']}")

    reader = PVDReader(FileName=pvd)
    warped = WarpByVector(Input=reader)
    warped.Vectors = ["POINTS", field]
    warped.ScaleFactor = args.warp_scale
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = args.size
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    view.Background = [1, 1, 1]
    view.OrientationAxesVisibility = 1
    display = Show(warped, view)
    ColorBy(display, ("POINTS", field, "Magnitude"))
    display.RescaleTransferFunctionToDataRange(True, False)
    display.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(GetColorTransferFunction(field), view)
    bar.Title = "|u|"
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    label = Text(Text=title)
    label_display = Show(label, view)
    label_display.Color = [0, 0, 0]
    label_display.FontSize = 14
    label_display.WindowLocation = "Upper Center"
    view.CameraPosition = [1 + 3.2, 2.4, 2.0]
    view.CameraFocalPoint = [1, 0, 0]
    view.CameraViewUp = [0, 0, 1]
    view.ResetCamera()
    output = args.output or os.path.join(args.output_dir, f"{field}.png")
    SaveScreenshot(output, view, ImageResolution=args.size)
    print(f"render_mode_3d: wrote {output}")


if __name__ == "__main__":
    main()
