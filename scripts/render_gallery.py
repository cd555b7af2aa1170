#!/usr/bin/env pvpython
"""Make the README's gallery: four scenes of prm/, run and drawn headless.

Run from the repository's root, after building build/impm:

    xvfb-run -a pvpython scripts/render_gallery.py

(Debian 12: apt-get install -y paraview xvfb.)  Options:

    --impm PATH     the executable (default build/impm)
    --runs DIR      keep the runs in DIR/NAME (default: a temporary directory,
                    removed at the end); a run already there (its
                    summary.json exists) is drawn again without running it
    --out DIR       where the pictures go (default doc/images)
    --only NAME...  only these scenes (collapse, footing, cone, wheel)

Each scene is run with `impm SCENE --set "Output directory=DIR/NAME" --set
"Output/Interval=1000"` (the points written only at the start and at the
end) and the scene's own `sets` below (none now: every scene runs in full,
as in prm/; a coarser variant would go there) on one process, and its last state is
drawn into OUT/NAME.png, 800 x 500 pixels: the material points as discs
coloured by one field, the rigid bodies in grey, the grid's box as a thin
line.  The script prints each run's wall time and the field's range.
"""

import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SIZE = [800, 500]

# The scenes. `radius`: the discs' radius (0.5-0.6 of the points' initial
# spacing, h / points per cell direction); `range`: the colour range, fixed
# so that remade pictures compare; `view`: the part of the x-y plane shown
# (2D) or the camera (3D).
SCENES = [
    dict(name="collapse", prm="prm/collapse.prm", sets=[],
         field="stress_yy", colours="diverging", range=[-64e3, 32e3],
         title="Collapse: vertical stress stress_yy (Pa)",
         radius=0.6 * 0.5 / 3, grid=[0, 16, 0, 8],
         view=[-0.3, 14.5, -0.3, 8.3]),
    dict(name="footing", prm="prm/strip_footing_rigid.prm", sets=[],
         field="plastic_multiplier", colours="Inferno (matplotlib)",
         range=[0.0, 1.0], format="%.2f",
         title="Rigid footing pushed 1 m into clay: plastic multiplier",
         radius=0.55 * 0.25 / 2, grid=[0, 5, 0, 3],
         view=[-0.6, 5.1, -0.1, 3.1]),
    dict(name="cone", prm="prm/cone_penetration.prm", sets=[],
         field="von_mises_stress", colours="Viridis (matplotlib)",
         range=[0.0, 30e3],
         title="Cone pushed 0.4 m into clay (3D): von Mises stress (Pa)",
         radius=0.5 * 0.125 / 2, grid=None, mirror_x=True,
         camera=dict(position=[0.25, -2.6, 1.9], focal=[0.0, 0.35, 0.55],
                     up=[0, 0, 1], angle=30)),
    dict(name="wheel", prm="prm/wheel_rolling.prm", sets=[],
         field="plastic_multiplier", colours="Inferno (matplotlib)",
         range=[0.0, 0.5], format="%.2f",
         title="Wheel rolled 2 m over clay: plastic multiplier",
         radius=0.55 * 0.125 / 2, grid=[0, 5, 0, 3],
         view=[-0.1, 5.1, 0.9, 3.1]),
]


def last_step_files(run_dir):
    """The files of the last time step of RUN_DIR/points.pvd: the points'
    .pvtu (part 0) and the rigid bodies' .vtu files (parts 1, 2, ...)."""
    text = open(os.path.join(run_dir, "points.pvd")).read()
    entries = re.findall(r'timestep="([^"]+)"[^>]*part="(\d+)"[^>]*file="([^"]+)"', text)
    last = entries[-1][0]
    files = [(int(part), f) for step, part, f in entries if step == last]
    files.sort()
    return [os.path.join(run_dir, f) for part, f in files], float(last)


def run_scene(scene, impm, run_dir):
    """Run SCENE into RUN_DIR unless a complete run is there; return the
    wall time in seconds (None if reused)."""
    if os.path.exists(os.path.join(run_dir, "summary.json")):
        return None
    command = [impm, os.path.join(ROOT, scene["prm"]),
               "--set", "Output directory=" + run_dir,
               "--set", "Output/Interval=1000"]
    for entry in scene["sets"]:
        command += ["--set", entry]
    print(" ".join(command), flush=True)
    start = time.time()
    with open(os.path.join(os.path.dirname(run_dir), scene["name"] + ".log"), "w") as log:
        subprocess.run(command, check=True, stdout=log, stderr=subprocess.STDOUT)
    return time.time() - start


def colour_map(pv, scene):
    lut = pv.GetColorTransferFunction(scene["field"])
    lut.AutomaticRescaleRangeMode = "Never"
    lo, hi = scene["range"]
    if scene["colours"] == "diverging":
        # white at zero: compression blue, tension red
        lut.ColorSpace = "Diverging"
        lut.RGBPoints = [lo, 0.230, 0.299, 0.754, 0.0, 0.865, 0.865, 0.865,
                         hi, 0.706, 0.016, 0.150]
    else:
        lut.ApplyPreset(scene["colours"], True)
        lut.RescaleTransferFunction(lo, hi)
    return lut


def white_view(pv, size):
    """A render view of SIZE pixels on white, without orientation axes
    (also used by doc/scripts/render_grid_fields.py)."""
    view = pv.CreateRenderView()
    view.ViewSize = size
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    view.Background = [1, 1, 1]
    view.OrientationAxesVisibility = 0
    return view


def render(pv, scene, files, png):
    view = white_view(pv, SIZE)

    if scene["grid"]:
        x0, x1, y0, y1 = scene["grid"]
        box = pv.PolyLineSource()
        box.Points = [x0, y0, 0, x1, y0, 0, x1, y1, 0, x0, y1, 0, x0, y0, 0]
        shown = pv.Show(box, view)
        shown.AmbientColor = shown.DiffuseColor = [0.6, 0.6, 0.6]

    points = pv.XMLPartitionedUnstructuredGridReader(FileName=[files[0]])
    if scene.get("mirror_x"):
        # the quarter model and its mirror image in the plane x = 0: a half
        # model cut through the axis of symmetry, seen from its cut face
        points = pv.Reflect(Input=points, Plane="X", Center=0.0, CopyInput=1)
    shown = pv.Show(points, view)
    shown.SetRepresentationType("Point Gaussian")
    shown.GaussianRadius = scene["radius"]
    try:
        shown.ShaderPreset = "Plain circle"
    except AttributeError:
        pass
    pv.ColorBy(shown, ("POINTS", scene["field"]))
    lut = colour_map(pv, scene)
    bar = pv.GetScalarBar(lut, view)
    bar.Title = scene["field"]
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    bar.TitleFontSize = 14
    bar.LabelFontSize = 12
    bar.RangeLabelFormat = scene.get("format", "%.0f")
    bar.LabelFormat = scene.get("format", "%.0f")
    bar.WindowLocation = "Any Location"
    bar.Orientation = "Horizontal"
    bar.Position = scene.get("bar", [0.56, 0.80])
    bar.ScalarBarLength = 0.4
    shown.SetScalarBarVisibility(view, True)

    for body in files[1:]:
        surface = pv.XMLUnstructuredGridReader(FileName=[body])
        if scene.get("mirror_x"):
            # the body whole (it is not cut by the symmetry planes): only
            # its half behind the cut face y = 0
            surface = pv.Clip(Input=surface, ClipType="Plane")
            surface.ClipType.Origin = [0, 0, 0]
            surface.ClipType.Normal = [0, 1, 0]
            surface.Invert = 0
        shown = pv.Show(surface, view)
        shown.ColorArrayName = ["POINTS", ""]
        shown.AmbientColor = shown.DiffuseColor = [0.55, 0.55, 0.6]
        if scene["grid"]:
            # 2D: the outline above the points, the inside half transparent
            shown.Opacity = 0.8
            edges = pv.Show(pv.FeatureEdges(Input=pv.ExtractSurface(Input=surface)), view)
            edges.ColorArrayName = ["POINTS", ""]
            edges.AmbientColor = edges.DiffuseColor = [0.1, 0.1, 0.1]
            edges.LineWidth = 2.0

    text = pv.Text(Text=scene["title"])
    shown = pv.Show(text, view)
    shown.Color = [0, 0, 0]
    shown.FontSize = 15
    shown.WindowLocation = "Upper Left Corner"

    # A first render resets the camera of a new view; set ours after it.
    pv.Render(view)
    if scene["grid"]:
        x0, x1, y0, y1 = scene["view"]
        cx, cy = 0.5 * (x0 + x1), 0.5 * (y0 + y1)
        view.CameraParallelProjection = 1
        view.CameraPosition = [cx, cy, 50]
        view.CameraFocalPoint = [cx, cy, 0]
        view.CameraViewUp = [0, 1, 0]
        aspect = SIZE[0] / SIZE[1]
        view.CameraParallelScale = max(0.5 * (y1 - y0), 0.5 * (x1 - x0) / aspect)
    else:
        camera = scene["camera"]
        view.CameraPosition = camera["position"]
        view.CameraFocalPoint = camera["focal"]
        view.CameraViewUp = camera["up"]
        view.CameraViewAngle = camera["angle"]
    pv.Render(view)
    pv.SaveScreenshot(png, view, ImageResolution=SIZE, CompressionLevel="9")
    pv.Delete(view)


def field_range(pv, pvtu, field):
    reader = pv.XMLPartitionedUnstructuredGridReader(FileName=[pvtu])
    reader.UpdatePipeline()
    info = reader.GetDataInformation().GetPointDataInformation().GetArrayInformation(field)
    lo, hi = info.GetComponentRange(0)
    n = reader.GetDataInformation().GetNumberOfPoints()
    pv.Delete(reader)
    return lo, hi, n


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--impm", default=os.path.join(ROOT, "build", "impm"))
    parser.add_argument("--runs", default=None)
    parser.add_argument("--out", default=os.path.join(ROOT, "doc", "images"))
    parser.add_argument("--only", nargs="+", default=None)
    args = parser.parse_args()

    from paraview import simple as pv

    impm = os.path.abspath(args.impm)
    runs = os.path.abspath(args.runs) if args.runs else tempfile.mkdtemp(prefix="impm_gallery_")
    os.makedirs(runs, exist_ok=True)
    os.makedirs(args.out, exist_ok=True)
    try:
        for scene in SCENES:
            if args.only and scene["name"] not in args.only:
                continue
            run_dir = os.path.join(runs, scene["name"])
            seconds = run_scene(scene, impm, run_dir)
            files, load_factor = last_step_files(run_dir)
            lo, hi, n = field_range(pv, files[0], scene["field"])
            png = os.path.join(args.out, scene["name"] + ".png")
            render(pv, scene, files, png)
            took = "reused" if seconds is None else "%.1f s" % seconds
            print("%s: %s, %d points, load factor %g, %s from %.4g to %.4g, run %s, %d bytes"
                  % (scene["name"], png, n, load_factor, scene["field"], lo, hi, took,
                     os.path.getsize(png)), flush=True)
    finally:
        if not args.runs:
            shutil.rmtree(runs, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
