#!/usr/bin/env pvpython
"""Draw the grid fields of the collapse headless (doc/images/grid_fields.png).

Run from the repository's root, after building build/impm:

    xvfb-run -a pvpython doc/scripts/render_grid_fields.py

(Debian 12: apt-get install -y paraview python3-paraview xvfb.)  It runs prm/collapse.prm (h = 0.5 m, 40 load
steps, about 5 s) into a temporary directory with

    --set "Output/Grid fields=all" --set "Output/Interval=1"

(the point files at the start and the end, the grid files at the end) and
draws the last entry of the grid.pvd series: the cells written (those the
points' supports cover) coloured by the magnitude of the last load step's
displacement increment, their edges, the reaction of the base as arrows
(1 m per 50 kN/m, on the rollers' nodes x = 0 and y = 0) and the material points of the point file of the step's
start as black dots. Options: --impm PATH (default build/impm), --out FILE
(default doc/images/grid_fields.png).
"""

import argparse
import os
import re
import subprocess
import sys
import tempfile

import paraview.simple as pv

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
from render_gallery import white_view  # noqa: E402
SIZE = [800, 450]


def last_grid_file(run_dir):
    """The .pvtu of the last entry of RUN_DIR/grid.pvd and its step."""
    text = open(os.path.join(run_dir, "grid.pvd")).read()
    last = re.findall(r'file="(grid_(\d+)\.pvtu)"', text)[-1]
    return os.path.join(run_dir, last[0]), int(last[1])


def render(grid_file, points_file, title, png):
    view = white_view(pv, SIZE)

    box = pv.PolyLineSource()
    box.Points = [0, 0, 0, 16, 0, 0, 16, 8, 0, 0, 8, 0, 0, 0, 0]
    shown = pv.Show(box, view)
    shown.AmbientColor = shown.DiffuseColor = [0.6, 0.6, 0.6]

    grid = pv.XMLPartitionedUnstructuredGridReader(FileName=[grid_file])
    shown = pv.Show(grid, view)
    shown.SetRepresentationType("Surface With Edges")
    shown.EdgeColor = [0.3, 0.3, 0.3]
    pv.ColorBy(shown, ("POINTS", "displacement_increment", "Magnitude"))
    lut = pv.GetColorTransferFunction("displacement_increment")
    lut.ApplyPreset("Viridis (matplotlib)", True)
    lut.AutomaticRescaleRangeMode = "Never"
    lut.RescaleTransferFunction(0.0, 0.25)
    bar = pv.GetScalarBar(lut, view)
    bar.Title = "|increment| (m)"
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    bar.TitleFontSize = 14
    bar.LabelFontSize = 12
    bar.RangeLabelFormat = bar.LabelFormat = "%.2f"
    bar.WindowLocation = "Any Location"
    bar.Orientation = "Vertical"
    bar.Position = [0.89, 0.12]
    bar.ScalarBarLength = 0.6
    shown.SetScalarBarVisibility(view, True)

    points = pv.XMLPartitionedUnstructuredGridReader(FileName=[points_file])
    dots = pv.Show(points, view)
    dots.SetRepresentationType("Points")
    dots.ColorArrayName = ["POINTS", ""]
    dots.AmbientColor = dots.DiffuseColor = [0, 0, 0]
    dots.PointSize = 1.5

    arrows = pv.Glyph(Input=grid, GlyphType="Arrow")
    arrows.OrientationArray = ["POINTS", "reaction"]
    arrows.ScaleArray = ["POINTS", "reaction"]
    arrows.ScaleFactor = 1.0 / 50e3
    arrows.GlyphMode = "All Points"
    shown = pv.Show(arrows, view)
    shown.ColorArrayName = ["POINTS", ""]
    shown.AmbientColor = shown.DiffuseColor = [0.85, 0.1, 0.1]

    text = pv.Text(Text=title)
    shown = pv.Show(text, view)
    shown.Color = [0, 0, 0]
    shown.FontSize = 15
    shown.WindowLocation = "Upper Left Corner"

    pv.Render(view)
    view.CameraParallelProjection = 1
    view.CameraPosition = [8.0, 3.9, 50]
    view.CameraFocalPoint = [8.0, 3.9, 0]
    view.CameraViewUp = [0, 1, 0]
    view.CameraParallelScale = 4.7
    pv.SaveScreenshot(png, view, ImageResolution=SIZE)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--impm", default=os.path.join(ROOT, "build", "impm"))
    parser.add_argument("--out", default=os.path.join(ROOT, "doc", "images",
                                                      "grid_fields.png"))
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as scratch:
        run_dir = os.path.join(scratch, "collapse")
        command = [args.impm, os.path.join(ROOT, "prm", "collapse.prm"),
                   "--set", "Output directory=" + run_dir,
                   "--set", "Output/Interval=1",
                   "--set", "Output/Grid fields=all"]
        print(" ".join(command), flush=True)
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
        grid_file, step = last_grid_file(run_dir)
        points_file = os.path.join(run_dir, "points_%05d.pvtu" % (step - 1))
        render(grid_file, points_file,
               "Collapse, grid fields of load step %d: the cells written,\n"
               "the step's displacement increment, the reactions (arrows),\n"
               "the points at the step's start" % step, args.out)
    print("wrote " + args.out, flush=True)
    # ParaView 5.11's Python crashes while it shuts down under xvfb-run
    # after the picture is written; leave without its clean-up.
    os._exit(0)


if __name__ == "__main__":
    main()
