#!/usr/bin/python3
"""Render the final state of the collapse (the paper's Figure 3).

Usage:
  scripts/render_collapse.py --runs DIR [--out doc/benchmarks] [--matplotlib]
  scripts/render_collapse.py --compute --runs DIR [--impm build/impm] [--out ...]

DIR holds the collapse runs as kept by `scripts/study.py --keep DIR` (one
sub-directory per case, with points.pvd and study_case.json); with --compute
the six cases (h = 1, 0.5, 0.25 m x 3x3, 6x6 points per cell) are run first
with scripts/study.py into DIR (point files of the initial and final state
only).

Every case's last point file is drawn with the points coloured by the
vertical Cauchy stress stress_yy (one colour range for all cases, diverging
and white at zero: compression blue, tension red), into
  OUT/collapse_h<h>_<n>x<n>.png   (one per case)
  OUT/collapse_panel.png          (all cases, rows = points per cell,
                                   columns = h).
The renderer is ParaView's pvbatch, run under `xvfb-run -a` (Debian packages
paraview, python3-paraview, xvfb); each point is a disc of 1.2 times its
initial spacing (Point Gaussian).  If pvbatch or xvfb-run is missing or fails, or
with --matplotlib, the images are drawn with matplotlib instead (a scatter
plot of the points, read with Python's vtk module) and the script says so.
"""

import argparse
import glob
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

# Fixed view: the grid is 16 m x 8 m, the body starts as the 8 m x 8 m block
# at the origin.
VIEW = dict(xmin=-0.3, xmax=14.5, ymin=-0.3, ymax=8.5)


# --------------------------------------------------------------------------
# pvbatch worker: run as `pvbatch render_collapse.py --worker SPEC.json`
# --------------------------------------------------------------------------
def worker(spec_file):
    from paraview import simple as pv

    spec = json.load(open(spec_file))
    lo, hi = spec["range"]
    for case in spec["cases"]:
        reader = pv.XMLPartitionedUnstructuredGridReader(FileName=[case["file"]])
        view = pv.CreateRenderView()
        view.ViewSize = spec["size"]
        view.Background = [1, 1, 1]
        try:
            view.UseColorPaletteForBackground = 0
        except AttributeError:
            pass
        view.OrientationAxesVisibility = 0
        view.CameraParallelProjection = 1

        # outline of the grid (16 m x 8 m) and of the initial block
        for box, colour in (((0, 16, 0, 8), [0.6, 0.6, 0.6]), ((0, 8, 0, 8), [0.3, 0.3, 0.3])):
            poly = pv.PolyLineSource()
            x0, x1, y0, y1 = box
            poly.Points = [x0, y0, 0, x1, y0, 0, x1, y1, 0, x0, y1, 0, x0, y0, 0]
            d = pv.Show(poly, view)
            d.AmbientColor = colour
            d.DiffuseColor = colour
            d.LineWidth = 1.0

        display = pv.Show(reader, view)
        display.SetRepresentationType("Point Gaussian")
        display.GaussianRadius = case["radius"]
        try:
            display.ShaderPreset = "Plain circle"
        except AttributeError:
            pass
        pv.ColorBy(display, ("POINTS", "stress_yy"))
        lut = pv.GetColorTransferFunction("stress_yy")
        lut.AutomaticRescaleRangeMode = "Never"
        # diverging, white at zero: compression blue, tension red
        lut.ColorSpace = "Diverging"
        points = [lo, 0.230, 0.299, 0.754]
        if lo < 0 < hi:
            points += [0.0, 0.865, 0.865, 0.865]
        lut.RGBPoints = points + [hi, 0.706, 0.016, 0.150]
        bar = pv.GetScalarBar(lut, view)
        bar.Title = "stress_yy (Pa)"
        bar.ComponentTitle = ""
        bar.TitleColor = [0, 0, 0]
        bar.LabelColor = [0, 0, 0]
        bar.TitleFontSize = 14
        bar.LabelFontSize = 12
        bar.RangeLabelFormat = "%-#.3g"
        bar.WindowLocation = "Any Location"
        bar.Orientation = "Horizontal"
        bar.Position = [0.55, 0.80]
        bar.ScalarBarLength = 0.4
        display.SetScalarBarVisibility(view, True)

        text = pv.Text(Text=case["title"])
        t = pv.Show(text, view)
        t.Color = [0, 0, 0]
        t.FontSize = 16
        t.WindowLocation = "Upper Left Corner"

        # a first render resets the camera of a new view; set ours after it
        pv.Render(view)
        cx = 0.5 * (VIEW["xmin"] + VIEW["xmax"])
        cy = 0.5 * (VIEW["ymin"] + VIEW["ymax"]) + 1.0
        view.CameraPosition = [cx, cy, 50]
        view.CameraFocalPoint = [cx, cy, 0]
        view.CameraViewUp = [0, 1, 0]
        aspect = spec["size"][0] / spec["size"][1]
        half_height = max(0.5 * (VIEW["ymax"] - VIEW["ymin"]) + 1.2,
                          0.5 * (VIEW["xmax"] - VIEW["xmin"]) / aspect)
        view.CameraParallelScale = half_height
        pv.Render(view)
        pv.SaveScreenshot(case["png"], view, ImageResolution=spec["size"])
        pv.Delete(view)
        print("rendered", case["png"])


# --------------------------------------------------------------------------
# driver
# --------------------------------------------------------------------------
def final_file(run_dir):
    pvd = os.path.join(run_dir, "points.pvd")
    files = re.findall(r'file="([^"]+)"', open(pvd).read())
    return os.path.join(run_dir, files[-1])


def read_points(pvtu):
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy

    reader = vtk.vtkXMLPUnstructuredGridReader()
    reader.SetFileName(pvtu)
    reader.Update()
    data = reader.GetOutput()
    x = vtk_to_numpy(data.GetPoints().GetData())
    s = vtk_to_numpy(data.GetPointData().GetArray("stress_yy"))
    return x, s


def find_cases(runs):
    cases = []
    for meta in sorted(glob.glob(os.path.join(runs, "*", "study_case.json"))):
        info = json.load(open(meta))
        run_dir = os.path.dirname(meta)
        if not os.path.exists(os.path.join(run_dir, "points.pvd")):
            print(f"render_collapse.py: {run_dir} has no point files; skipped", file=sys.stderr)
            continue
        h = float(info["h"])
        n = int(info["points_per_cell_direction"])
        cases.append(dict(dir=run_dir, h=h, n=n, file=final_file(run_dir)))
    cases.sort(key=lambda c: (c["n"], -c["h"]))
    return cases


def name_of(case):
    return f"collapse_h{case['h']:g}_{case['n']}x{case['n']}.png"


def title_of(case, npoints):
    return f"h = {case['h']:g} m, {case['n']}x{case['n']} points per cell ({npoints} points)"


def render_paraview(cases, out, vrange, size):
    pvbatch = shutil.which("pvbatch")
    xvfb = shutil.which("xvfb-run")
    if not pvbatch or not xvfb:
        return "pvbatch or xvfb-run not found (apt-get install -y paraview python3-paraview xvfb)"
    spec = dict(range=vrange, size=size, cases=[
        dict(file=os.path.abspath(c["file"]), png=os.path.abspath(os.path.join(out, name_of(c))),
             title=c["title"], radius=0.6 * c["h"] / c["n"]) for c in cases])
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(spec, f)
        spec_file = f.name
    try:
        proc = subprocess.run([xvfb, "-a", pvbatch, os.path.abspath(__file__), "--worker", spec_file],
                              capture_output=True, text=True, timeout=600)
    except subprocess.TimeoutExpired:
        return "pvbatch timed out"
    finally:
        os.unlink(spec_file)
    missing = [c for c in spec["cases"] if not os.path.exists(c["png"])]
    if proc.returncode != 0 or missing:
        return (f"pvbatch failed (exit code {proc.returncode}):\n"
                + "\n".join((proc.stderr + proc.stdout).strip().splitlines()[-15:]))
    return None


def render_matplotlib(cases, out, vrange, size):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    for c in cases:
        x, s = read_points(c["file"])
        fig, ax = plt.subplots(figsize=(size[0] / 100, size[1] / 100), dpi=100)
        ax.plot([0, 16, 16, 0, 0], [0, 0, 8, 8, 0], color="0.6", lw=0.8)
        ax.plot([0, 8, 8, 0, 0], [0, 0, 8, 8, 0], color="0.3", lw=0.8)
        # marker size: the points' initial spacing, in points^2
        fig_w_m = VIEW["xmax"] - VIEW["xmin"]
        spacing_px = c["h"] / c["n"] * (0.8 * size[0]) / fig_w_m
        from matplotlib.colors import Normalize, TwoSlopeNorm
        norm = (TwoSlopeNorm(0.0, vrange[0], vrange[1]) if vrange[0] < 0 < vrange[1]
                else Normalize(vrange[0], vrange[1]))
        sc = ax.scatter(x[:, 0], x[:, 1], c=s, s=(spacing_px * 72 / 100) ** 2, marker="o",
                        linewidths=0, cmap="coolwarm", norm=norm)
        ax.set_xlim(VIEW["xmin"], VIEW["xmax"])
        ax.set_ylim(VIEW["ymin"], VIEW["ymax"])
        ax.set_aspect("equal")
        ax.set_title(c["title"], fontsize=10)
        ax.set_xlabel("x (m)")
        ax.set_ylabel("y (m)")
        fig.colorbar(sc, ax=ax, orientation="horizontal", fraction=0.05, pad=0.15,
                     label="stress_yy (Pa)")
        fig.tight_layout()
        fig.savefig(os.path.join(out, name_of(c)))
        plt.close(fig)
        print("drew", os.path.join(out, name_of(c)))


def panel(cases, out, renderer):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.image as mpimg
    import matplotlib.pyplot as plt

    hs = sorted({c["h"] for c in cases}, reverse=True)
    ns = sorted({c["n"] for c in cases})
    fig, axes = plt.subplots(len(ns), len(hs), figsize=(5.2 * len(hs), 3.3 * len(ns)),
                             squeeze=False)
    for ax in axes.flat:
        ax.axis("off")
    for c in cases:
        ax = axes[ns.index(c["n"])][hs.index(c["h"])]
        ax.imshow(mpimg.imread(os.path.join(out, name_of(c))))
    fig.suptitle("Collapse, final state, points coloured by the vertical stress stress_yy "
                 f"({renderer})", fontsize=12)
    fig.tight_layout()
    path = os.path.join(out, "collapse_panel.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print("wrote", path)


def compute(runs, impm):
    cmd = [sys.executable, os.path.join(HERE, "study.py"), os.path.join(ROOT, "prm", "collapse.prm"),
           "--set", "Grid/Number of cells=16, 8|32, 16|64, 32",
           "--set", "Body 1/Points per cell direction=3|6",
           "--set", "Output/Interval=1000", "--reference-finest",
           "--keep", runs, "--out", os.path.join(runs, "collapse.csv"), "--impm", impm]
    print(" ".join(cmd), file=sys.stderr)
    subprocess.run(cmd, check=False)


def main():
    if len(sys.argv) == 3 and sys.argv[1] == "--worker":
        worker(sys.argv[2])
        return 0
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runs", required=True, help="directory of kept collapse runs")
    parser.add_argument("--out", default=os.path.join(ROOT, "doc", "benchmarks"))
    parser.add_argument("--compute", action="store_true", help="run the six cases first")
    parser.add_argument("--impm", default=os.path.join(ROOT, "build", "impm"))
    parser.add_argument("--matplotlib", action="store_true", help="skip ParaView")
    parser.add_argument("--range", nargs=2, type=float, metavar=("MIN", "MAX"),
                        help="colour range of stress_yy in Pa (default: over all cases)")
    args = parser.parse_args()

    if args.compute:
        compute(args.runs, os.path.abspath(args.impm))
    cases = find_cases(args.runs)
    if not cases:
        raise SystemExit(f"render_collapse.py: no runs with point files under {args.runs}")
    os.makedirs(args.out, exist_ok=True)
    lo, hi = float("inf"), float("-inf")
    for c in cases:
        x, s = read_points(c["file"])
        c["title"] = title_of(c, len(s))
        lo, hi = min(lo, float(s.min())), max(hi, float(s.max()))
    vrange = args.range or [lo, hi]
    print(f"render_collapse.py: {len(cases)} cases, stress_yy range [{vrange[0]:.4g}, "
          f"{vrange[1]:.4g}] Pa", file=sys.stderr)
    size = [900, 560]
    renderer = "matplotlib"
    if not args.matplotlib:
        problem = render_paraview(cases, args.out, vrange, size)
        if problem:
            print(f"render_collapse.py: ParaView rendering did not work, falling back to "
                  f"matplotlib: {problem}", file=sys.stderr)
        else:
            renderer = "ParaView pvbatch"
    if renderer == "matplotlib":
        render_matplotlib(cases, args.out, vrange, size)
    panel(cases, args.out, renderer)
    return 0


if __name__ == "__main__":
    sys.exit(main())
