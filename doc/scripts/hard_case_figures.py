#!/usr/bin/python3
"""Runs the hard-case scenes with build/impm and draws the figures of
doc/hard_cases.md into doc/figures/.

Usage (from the repository root):

    python3 doc/scripts/hard_case_figures.py build/impm [--keep] [--np N]

Every run goes to a fresh directory under /tmp (removed at the end unless
--keep is given; its path is printed). The measured numbers quoted in
doc/hard_cases.md are printed to stdout and written to
doc/figures/hard_case_numbers.txt. Needs numpy and matplotlib (Debian:
python3-matplotlib); reads the point files with vtk (python3-vtk9) if it can
be imported, otherwise with its own parser of deal.II's zlib/base64 VTU; the
two-process run needs mpirun. Runs
one impm job at a time; about 30 s on a 2-core machine.
"""

import base64
import csv
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET
import zlib

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

try:
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError:  # fall back on parse_vtu below
    vtk = None

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
TESTS = os.path.join(ROOT, "tests")
PRM = os.path.join(ROOT, "prm")
FIGURES = os.path.join(ROOT, "doc", "figures")
DPI = 100

numbers = []  # lines of the numbers file
# Path of the material subsection in the parameter file: "Material" in the
# single-body layout, "Body 1/Material" once the scene holds several bodies
# (decided in main() from `impm --print-parameters`).
MATERIAL = "Material"


def note(line=""):
    print(line, flush=True)
    numbers.append(line)


# --------------------------------------------------------------------------
# running impm and reading its output
# --------------------------------------------------------------------------

class Runner:
    def __init__(self, impm, work):
        self.impm = os.path.abspath(impm)
        self.work = work

    def run(self, name, scene, sets=(), np_=1, expect_fail=False):
        """Runs impm on `scene` with output in work/name; returns
        (output directory, stdout, stderr, return code, command string)."""
        out = os.path.join(self.work, name)
        if os.path.exists(out):
            shutil.rmtree(out)
        args = [self.impm, scene, "--set", "Output directory=" + out]
        for s in sets:
            args += ["--set", s]
        env = dict(os.environ)
        if np_ > 1:
            args = ["mpirun", "-np", str(np_)] + args
            env["OMPI_ALLOW_RUN_AS_ROOT"] = "1"
            env["OMPI_ALLOW_RUN_AS_ROOT_CONFIRM"] = "1"
        start = time.time()
        p = subprocess.run(args, cwd=self.work, env=env,
                           capture_output=True, text=True)
        wall = time.time() - start
        if (p.returncode != 0) != expect_fail:
            sys.stderr.write(p.stdout + p.stderr)
            raise SystemExit("impm run '%s' returned %d" % (name, p.returncode))
        shown = " ".join(
            (["mpirun", "-np", str(np_)] if np_ > 1 else [])
            + ["build/impm", os.path.relpath(scene, ROOT)]
            + ['--set "%s"' % s for s in sets])
        print("  ran %-34s %5.1f s" % (name, wall), flush=True)
        return out, p.stdout, p.stderr, p.returncode, shown


def read_csv(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def read_newton(path):
    """{(attempt index, step): [residuals]} in file order; a step number that
    appears again after iteration 0 starts a new attempt."""
    attempts = []
    with open(path) as f:
        for r in csv.DictReader(f):
            step, it, res = int(r["step"]), int(r["iteration"]), float(
                r["relative_residual"])
            if it == 0:
                attempts.append((step, []))
            attempts[-1][1].append(res)
    return attempts


def read_summary(out):
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


VTK_TYPES = {"Float32": "<f4", "Float64": "<f8", "Int32": "<i4",
             "UInt32": "<u4", "Int64": "<i8", "UInt8": "u1"}


def decode_data_array(element, header_type="UInt32", compressed=True):
    """Values of a VTK XML DataArray (ascii, or binary: base64, optionally
    zlib-compressed as written by deal.II)."""
    text = (element.text or "").strip()
    dtype = np.dtype(VTK_TYPES[element.get("type")])
    if not text:
        return np.zeros(0, dtype)
    if element.get("format") == "ascii":
        return np.array(text.split(), dtype=dtype)
    ht = np.dtype(VTK_TYPES[header_type])
    if not compressed:
        raw = base64.b64decode(text)
        n = int(np.frombuffer(raw[:ht.itemsize], ht)[0])
        return np.frombuffer(raw[ht.itemsize:ht.itemsize + n], dtype)

    def b64len(nbytes):
        return 4 * ((nbytes + 2) // 3)

    first = base64.b64decode(text[:b64len(ht.itemsize)])
    nblocks = int(np.frombuffer(first[:ht.itemsize], ht)[0])
    hlen = b64len((3 + nblocks) * ht.itemsize)
    header = np.frombuffer(base64.b64decode(text[:hlen]), ht)
    data = base64.b64decode(text[hlen:])
    out, pos = [], 0
    for size in header[3:3 + nblocks]:
        out.append(zlib.decompress(data[pos:pos + int(size)]))
        pos += int(size)
    return np.frombuffer(b"".join(out), dtype)


def parse_vtu(path):
    """Points and point data of one .vtu piece, without vtk."""
    root = ET.parse(path).getroot()
    compressed = root.get("compressor") is not None
    header_type = root.get("header_type", "UInt32")
    piece = root.find("UnstructuredGrid/Piece")
    n = int(piece.get("NumberOfPoints"))
    if n == 0:
        return None
    chunk = {}
    xyz = piece.find("Points/DataArray")
    chunk["x"] = decode_data_array(xyz, header_type, compressed).reshape(n, -1)
    for a in piece.find("PointData").findall("DataArray"):
        v = decode_data_array(a, header_type, compressed)
        ncomp = int(a.get("NumberOfComponents", "1"))
        chunk[a.get("Name")] = v.reshape(n, ncomp) if ncomp > 1 else v
    return chunk


def read_vtu(path):
    if vtk is None:
        return parse_vtu(path)
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    grid = r.GetOutput()
    chunk = {"x": vtk_to_numpy(grid.GetPoints().GetData())}
    pd = grid.GetPointData()
    for i in range(pd.GetNumberOfArrays()):
        chunk[pd.GetArrayName(i)] = vtk_to_numpy(pd.GetArray(i))
    return chunk


def read_points(out, step):
    """Point data of points_<step>.pvtu: dict of numpy arrays, 'x' are the
    current positions (n x 3)."""
    pvtu = os.path.join(out, "points_%05d.pvtu" % step)
    pieces = [p.get("Source") for p in ET.parse(pvtu).getroot().iter("Piece")]
    data = {}
    for piece in pieces:
        with open(os.path.join(out, piece), "rb") as f:
            if b'NumberOfPoints="0"' in f.read(1000):
                continue  # an empty piece has no <Points>; vtk complains
        chunk = read_vtu(os.path.join(out, piece))
        for k, v in chunk.items():
            data.setdefault(k, []).append(np.array(v, dtype=float))
    return {k: np.concatenate(v) for k, v in data.items()}


def newton_order(res):
    """Smallest observed order log(r_k+1) / log(r_k) over the contractions
    with r_k < 1e-3 and r_k+1 > 1e-10 (near the solution, above round-off):
    the measure behind the test line "observed Newton order near the
    solution >= 1.7"; nan if no contraction qualifies."""
    orders = [np.log(b) / np.log(a) for a, b in zip(res[1:-1], res[2:])
              if a < 1e-3 and b > 1e-10]
    return min(orders) if orders else float("nan")


def save(fig, name):
    """Writes the figure at DPI; a PNG over 150 kB (thousands of scattered
    points) is re-saved with a 256-colour palette to stay small."""
    path = os.path.join(FIGURES, name)
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    if os.path.getsize(path) > 150 * 1024:
        from PIL import Image
        Image.open(path).convert("RGB").quantize(256).save(path,
                                                          optimize=True)
    print("  wrote doc/figures/%s (%d kB)" % (name, os.path.getsize(path) // 1024))


def scatter_points(ax, pts, field, vmin, vmax, cmap="viridis", s=6):
    sc = ax.scatter(pts["x"][:, 0], pts["x"][:, 1], c=pts[field], s=s,
                    cmap=cmap, vmin=vmin, vmax=vmax, linewidths=0)
    ax.set_aspect("equal")
    return sc


# --------------------------------------------------------------------------
# the cases
# --------------------------------------------------------------------------

def case1(run):
    note("== 1. A node fed only by the edge of a point's domain")
    res = {}
    for tag, scene in [("stabilised", "hard_edge_support_stabilised"),
                       ("unstabilised", "hard_edge_support_unstabilised")]:
        out, so, _, _, cmd = run.run("edge_" + tag,
                                     os.path.join(TESTS, scene + ".prm"),
                                     ["Output/Interval=1"])
        s = read_summary(out)
        pts = read_points(out, 2)
        res[tag] = (s, pts)
        note("$ " + cmd)
        note("  worst_condition_estimate = %.4g" % s["worst_condition_estimate"])
        for line in so.splitlines():
            if line.startswith("point "):
                note("  " + line)
    # Reference: the same block in one load step (no tiny supports).
    for tag, ghost in [("one step, stabilised", "true"),
                       ("one step, unstabilised", "false")]:
        out, so, _, _, cmd = run.run(
            "edge_1step_" + ghost,
            os.path.join(TESTS, "hard_edge_support_stabilised.prm"),
            ["Solver/Load steps=1", "Ghost stabilisation/Enabled=" + ghost,
             "Output/Interval=1"])
        res[tag] = (read_summary(out), read_points(out, 1))
        note("$ " + cmd)
        note("  worst_condition_estimate = %.4g" %
             res[tag][0]["worst_condition_estimate"])
        for line in so.splitlines():
            if line.startswith("point "):
                note("  " + line)

    for tag in ["stabilised", "unstabilised", "one step, stabilised"]:
        pts = res[tag][1]
        low = np.isclose(pts["initial_position"][:, 1], 1.25)
        order = np.argsort(pts["initial_position"][low, 0])
        note("  %s: stress_yy of the lowest row (X = 0.25, 0.75, 1.25, 1.75):"
             " %s Pa" % (tag, ", ".join("%.4g" % v for v in
                                        pts["stress_yy"][low][order])))

    # The collapse with and without stabilisation.
    coll = {}
    for tag, ghost in [("stabilised", "true"), ("unstabilised", "false")]:
        out, so, _, _, cmd = run.run(
            "collapse_ghost_" + ghost, os.path.join(PRM, "collapse.prm"),
            ["Ghost stabilisation/Enabled=" + ghost, "Output/Interval=40",
             "Testing/Enabled=true"])
        s = read_summary(out)
        coll[tag] = (s, read_points(out, 40), so, out)
        note("$ " + cmd)
        note("  worst_condition_estimate = %.4g, newton_iterations = %d, "
             "load_step_cuts = %d" % (s["worst_condition_estimate"],
                                      s["newton_iterations"],
                                      s["load_step_cuts"]))
        for line in so.splitlines():
            if line.startswith("extent") or line.startswith("observed"):
                note("  " + line)
    # Largest difference of the final positions and stresses (same ids:
    # match by initial position).
    a, b = coll["stabilised"][1], coll["unstabilised"][1]
    ia = np.lexsort((a["initial_position"][:, 1], a["initial_position"][:, 0]))
    ib = np.lexsort((b["initial_position"][:, 1], b["initial_position"][:, 0]))
    dx = np.abs(a["x"][ia] - b["x"][ib]).max()
    ds = np.abs(a["stress_yy"][ia] - b["stress_yy"][ib])
    note("  collapse, stabilised vs not: largest position difference "
         "%.3g m, largest stress_yy difference %.3g Pa (median %.3g Pa)"
         % (dx, ds.max(), np.median(ds)))

    # Figure 1a: condition estimates and the stress of the hanging block.
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 3.8))
    labels = ["edge block\nghost on", "edge block\nghost off",
              "collapse\nghost on", "collapse\nghost off"]
    vals = [res["stabilised"][0]["worst_condition_estimate"],
            res["unstabilised"][0]["worst_condition_estimate"],
            coll["stabilised"][0]["worst_condition_estimate"],
            coll["unstabilised"][0]["worst_condition_estimate"]]
    colours = ["tab:blue", "tab:red", "tab:blue", "tab:red"]
    ax1.bar(range(4), vals, color=colours)
    ax1.set_yscale("log")
    ax1.set_xticks(range(4))
    ax1.set_xticklabels(labels, fontsize=8)
    for i, v in enumerate(vals):
        ax1.text(i, v * 1.5, "%.1e" % v, ha="center", fontsize=8)
    ax1.set_ylim(1, max(vals) * 50)
    ax1.set_ylabel("worst condition estimate (summary.json)")
    ax1.set_title("2-norm condition estimate, worst over the steps",
                  fontsize=9)

    markers = {"stabilised": ("o", "tab:blue"),
               "unstabilised": ("s", "tab:red"),
               "one step, stabilised": ("x", "k"),
               "one step, unstabilised": ("+", "tab:green")}
    for tag, (m, c) in markers.items():
        pts = res[tag][1]
        X = pts["initial_position"]
        order = np.lexsort((X[:, 0], X[:, 1]))
        ax2.plot(np.arange(len(order)), pts["stress_yy"][order] / 1e3, m,
                 color=c, label=tag + (" (2 steps)" if "one" not in tag else ""),
                 ms=7, mfc="none" if m in "os" else None)
    X = res["stabilised"][1]["initial_position"]
    order = np.lexsort((X[:, 0], X[:, 1]))
    ax2.set_xticks(range(len(order)))
    ax2.set_xticklabels(["(%g, %g)" % (X[i, 0], X[i, 1]) for i in order],
                        rotation=45, fontsize=7)
    ax2.axvspan(-0.5, 3.5, color="0.9", zorder=0)
    ax2.text(1.5, 8, "lowest row", ha="center", fontsize=8)
    ax2.set_xlabel("point (initial x, y); lowest row shaded")
    ax2.set_ylabel("final stress_yy (kPa, tension +)")
    ax2.set_title("hanging block, stress after the last step", fontsize=9)
    ax2.legend(fontsize=7, loc="center right")
    fig.tight_layout()
    save(fig, "hard1_condition.png")

    # Figure 1b: final collapse with and without stabilisation, and the
    # difference of the vertical stress point by point.
    fig, axs = plt.subplots(3, 1, figsize=(7.5, 8.4), sharex=True)
    for ax, tag in zip(axs, ["stabilised", "unstabilised"]):
        s, pts, _, _ = coll[tag]
        sc = scatter_points(ax, pts, "stress_yy", -7e4, 3e4, "viridis", 4)
        ax.set_title("collapse h = 0.5 m, ghost %s: worst condition %.1e"
                     % ("on" if tag == "stabilised" else "off",
                        s["worst_condition_estimate"]), fontsize=9)
        fig.colorbar(sc, ax=ax, label="stress_yy (Pa)", shrink=0.9)
    pa = {k: v[ia] for k, v in a.items()}
    pa["diff"] = ds
    sc = scatter_points(axs[2], pa, "diff", 0, 5e3, "magma_r", 4)
    axs[2].set_title("|stress_yy(ghost on) - stress_yy(ghost off)|, "
                     "at the ghost-on positions", fontsize=9)
    fig.colorbar(sc, ax=axs[2], label="Pa (clipped at 5 kPa)", shrink=0.9)
    for ax in axs:
        ax.set_xlim(0, 16)
        ax.set_ylim(0, 7)
        ax.set_ylabel("y (m)")
    axs[2].set_xlabel("x (m)")
    fig.tight_layout()
    save(fig, "hard1_collapse_shapes.png")
    return coll["stabilised"]


def case2(run):
    note("== 2. Standard MPM cell crossing")
    fig, ax = plt.subplots(figsize=(6, 4.2))
    Z = np.linspace(0, 50, 2)
    ax.plot(-800 * (50 - Z) / 1e3, Z, "k-", label="analytical -800 (50 - Z)")
    for name, m, c in [("column_smpm_plastic_16", "s", "tab:red"),
                       ("column_gimp_plastic_16", "o", "tab:blue")]:
        out, so, _, _, cmd = run.run(name, os.path.join(TESTS, name + ".prm"),
                                     ["Output/Interval=50"])
        pts = read_points(out, 50)
        steps = read_csv(os.path.join(out, "steps.csv"))
        osc = re.search(r"stress oscillation.*: (\S+)", so).group(1)
        note("$ " + cmd)
        note("  stress oscillation (test line) = %s, error of eq. 13 after "
             "step 50 = %.4e" % (osc, steps["error_sigma_zz"][-1]))
        Zp = pts["initial_position"][:, 1]
        dev = np.abs(pts["stress_yy"] + 800 * (50 - Zp)).max()
        note("  largest |stress_yy + 800 (50 - Z)| over the points = %.0f Pa"
             % dev)
        label = ("standard MPM" if "smpm" in name else "GIMP") + \
            " (oscillation %s)" % osc
        ax.plot(pts["stress_yy"] / 1e3, Zp, m, color=c, mfc="none", ms=5,
                label=label)
    for k in range(17):
        ax.axhline(k * 3.125, color="0.85", lw=0.5, zorder=0)
    ax.set_xlabel("final vertical stress stress_yy (kPa)")
    ax.set_ylabel("initial height Z (m)")
    ax.set_title("column, 16 cells (h = 3.125 m), von Mises, 50 steps",
                 fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    save(fig, "hard2_cell_crossing.png")


def case3(run):
    note("== 3. Load steps too large")
    runs = [("collapse_h1_4steps", [], "4 nominal steps", "tab:red"),
            ("collapse_h1_4steps", ["Solver/Easy step iterations=6"],
             "4 nominal steps, Easy step iterations = 6", "tab:orange"),
            ("collapse_h1", [], "40 nominal steps", "tab:blue")]
    style = {0: dict(ms=6, lw=1.5, ls="-", z=3),
             1: dict(ms=3, lw=0.8, ls="--", z=2),
             2: dict(ms=3, lw=0.8, ls="-", z=1)}
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 3.8))
    for i, (name, sets, label, c) in enumerate(runs):
        out, so, _, _, cmd = run.run("%s_%d" % (name, i),
                                     os.path.join(TESTS, name + ".prm"), sets)
        st = read_csv(os.path.join(out, "steps.csv"))
        s = read_summary(out)
        note("$ " + cmd)
        note("  attempts %d, cuts %d, newton_iterations %d"
             % (len(st["step"]), s["load_step_cuts"], s["newton_iterations"]))
        for line in so.splitlines():
            if line.startswith("extent") or "cut" in line:
                note("  " + line)
        note("  largest_point_increment_in_cells (accepted steps) = %.4g"
             % s["largest_point_increment_in_cells"])
        if i < 2:
            note("  steps.csv (step, load_factor, load_increment, converged, "
                 "newton_iterations, relative_residual):")
            for j in range(len(st["step"])):
                note("    %d %.4f %.4f %d %d %.3e" % (
                    st["step"][j], st["load_factor"][j],
                    st["load_increment"][j], st["converged"][j],
                    st["newton_iterations"][j], st["relative_residual"][j]))
        att = np.arange(1, len(st["step"]) + 1)
        ok = st["converged"] == 1
        y = style[i]
        for ax, col in [(ax1, "load_factor"), (ax2, "load_increment")]:
            ax.plot(att, st[col], ls=y["ls"], color=c, lw=y["lw"],
                    zorder=y["z"])
            ax.plot(att[ok], st[col][ok], "o", color=c, ms=y["ms"],
                    zorder=y["z"], label=label if ax is ax1 else None)
            ax.plot(att[~ok], st[col][~ok], "x", color="k", ms=8, mew=1.5,
                    zorder=4)
    ax1.plot([], [], "x", color="k", label="cut (converged = 0)")
    ax1.set_xlabel("attempt (row of steps.csv)")
    ax1.set_ylabel("load factor")
    ax1.legend(fontsize=7)
    ax1.set_title("collapse h = 1 m: load factor per attempt", fontsize=9)
    ax2.set_yscale("log", base=2)
    ax2.set_xlim(0, 20)
    ax2.set_xlabel("attempt (first 20)")
    ax2.set_ylabel("load increment")
    ax2.set_title("load increment per attempt (log2)", fontsize=9)
    fig.tight_layout()
    save(fig, "hard3_step_control.png")


def case4(run):
    note("== 4. Nearly incompressible elasticity")
    fig, ax = plt.subplots(figsize=(6, 4))
    for name, label, c in [("column_nearly_incompressible", "nu = 0.49",
                            "tab:red"),
                           ("column_gimp_elastic_16", "nu = 0", "tab:blue")]:
        out, so, _, _, cmd = run.run(name, os.path.join(TESTS, name + ".prm"))
        st = read_csv(os.path.join(out, "steps.csv"))
        note("$ " + cmd)
        note("  error of eq. 13: step 1 %.4e, step 10 %.4e, step 25 %.4e, "
             "step 50 %.4e" % (st["error_sigma_zz"][0], st["error_sigma_zz"][9],
                               st["error_sigma_zz"][24],
                               st["error_sigma_zz"][-1]))
        for line in so.splitlines():
            if line.startswith("extent in y") or line.startswith("point 0"):
                note("  " + line)
        # Extents are printed in the reference length L of the scales line.
        length = float(re.search(r"scales: L = (\S+) m", so).group(1))
        ymax = [length * float(v) for v in re.search(
            r"extent in y: initial points \[\S+, (\S+)\], final \[\S+, "
            r"(\S+)\]", so).groups()]
        nu = 0.49 if "incompressible" in name else 0.0
        M = 1e6 * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
        Z = ymax[0]
        u_lin = 800 / M * (50 * Z - Z * Z / 2)
        note("  top point (Z = %.4f): settlement %.4f m; small-strain confined "
             "column rho g (l0 Z - Z^2/2) / M with M = E(1-nu)/((1+nu)(1-2nu)) "
             "= %.4g Pa: %.4f m" % (Z, ymax[0] - ymax[1], M, u_lin))
        ax.plot(st["step"], st["error_sigma_zz"], "o-", ms=3, color=c,
                label=label)
    steps = np.arange(1, 51)
    ax.plot(steps, steps / 50 * 3.125 / 200, "k--", lw=1,
            label="lambda h / (4 l0) (cell-constant strain)")
    ax.set_xlabel("load step")
    ax.set_ylabel("error of eq. 13")
    ax.set_title("column, 16 cells, GIMP, Hencky elastic", fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    save(fig, "hard4_incompressible.png")


def case5(run):
    note("== 5. A point leaving the grid")
    scene = os.path.join(TESTS, "point_off_grid.prm")
    out, so, se, rc, cmd = run.run("point_off_grid", scene, expect_fail=True)
    note("$ " + cmd)
    note("  return code %d; stderr:" % rc)
    for line in se.strip().splitlines():
        note("  " + line)
    note("  left in the output directory:")
    for f in sorted(os.listdir(out)):
        path = os.path.join(out, f)
        with open(path, "rb") as fh:
            text = fh.read()
        if f.endswith(".csv"):
            lines = text.decode().strip().splitlines()
            ncols = {len(l.split(",")) for l in lines[1:]} if f == "steps.csv" \
                else {len(l.split(",")) for l in lines}
            status = "%d lines, columns per row %s" % (len(lines), sorted(ncols))
        elif f.endswith(".json"):
            json.loads(text)
            status = "valid JSON"
        else:
            status = "ends with </VTKFile>: %s" % text.rstrip().endswith(
                b"</VTKFile>")
        note("    %-24s %6d bytes  %s" % (f, len(text), status))
    st = read_csv(os.path.join(out, "steps.csv"))
    m = re.search(r"material point (\d+) \(initially at ([\d.]+) ([\d.]+)\)",
                  se)
    X0 = (float(m.group(2)), float(m.group(3)))
    fig, ax = plt.subplots(figsize=(6, 3.6))
    for k in range(3):
        pts = read_points(out, k)
        X = pts["initial_position"]
        sel = np.isclose(X[:, 0], X0[0])
        order = np.argsort(X[sel, 1])
        ax.plot(X[sel, 1][order], pts["x"][sel, 1][order] - X[sel, 1][order],
                "o-", ms=3, label="step %d (load %.1f)" % (k, 0.1 * k))
    moved = re.search(r"moved to \(\S+ (\S+)\)", se)
    if moved:
        ax.plot([X0[1]], [float(moved.group(1)) - X0[1]], "r*", ms=10,
                label="step 3 (load 0.3), point %s: stops the run" %
                m.group(1))
    ax.axhline(-X0[1], color="k", ls="--", lw=1)
    ax.text(1.0, -X0[1] + 0.03, "below this line point %s (initially at "
            "Y = %g) is under the grid's base y = 0" % (m.group(1), X0[1]),
            fontsize=8)
    ax.set_xlim(0, 10)
    ax.set_ylim(-1.1, 0.05)
    ax.set_xlabel("initial height Y (m), points with X = %.2f" % X0[0])
    ax.set_ylabel("vertical displacement (m)")
    ax.set_title("hanging column: the written states; step 3 stops the run",
                 fontsize=9)
    ax.legend(fontsize=7, loc="lower right")
    fig.tight_layout()
    save(fig, "hard5_point_off_grid.png")
    return st


def case6(run, nproc):
    note("== 6. The collapse on %d processes" % nproc)
    scene = os.path.join(TESTS, "collapse_h1.prm")
    out1, so1, _, _, cmd1 = run.run("collapse_h1_np1", scene,
                                    ["Output/Interval=10"])
    outn, son, _, _, cmdn = run.run("collapse_h1_np%d" % nproc, scene,
                                    ["Output/Interval=10"], np_=nproc)
    note("$ " + cmd1)
    note("$ " + cmdn)
    note("  test summaries identical: %s (%d lines)"
         % (so1 == son, len(so1.splitlines())))
    if so1 != son:
        for a, b in zip(so1.splitlines(), son.splitlines()):
            if a != b:
                note("    1 process:  " + a)
                note("    %d processes: " % nproc + b)
    n1 = read_newton(os.path.join(out1, "newton.csv"))
    nn = read_newton(os.path.join(outn, "newton.csv"))
    same_shape = [len(a[1]) for a in n1] == [len(a[1]) for a in nn]
    diffs = [abs(x - y) / x for a, b in zip(n1, nn) for x, y in
             zip(a[1], b[1]) if x > 1e-8]
    def residual_columns(path):
        # step, iteration, relative_residual (the later columns are timings)
        return [",".join(line.split(",")[:3]) for line in open(path)]
    note("  newton.csv: same iteration counts %s; largest relative difference "
         "of residuals above 1e-8: %.2e; identical residual columns: %s" % (
             same_shape, max(diffs),
             residual_columns(os.path.join(out1, "newton.csv")) ==
             residual_columns(os.path.join(outn, "newton.csv"))))
    p1, pn = read_points(out1, 40), read_points(outn, 40)
    i1 = np.lexsort((p1["initial_position"][:, 1],
                     p1["initial_position"][:, 0]))
    i2 = np.lexsort((pn["initial_position"][:, 1],
                     pn["initial_position"][:, 0]))
    note("  final points, 1 vs %d processes: largest position difference "
         "%.2e m, largest stress_yy difference %.2e Pa (point files are "
         "Float32)" % (nproc, np.abs(p1["x"][i1] - pn["x"][i2]).max(),
                       np.abs(p1["stress_yy"][i1] - pn["stress_yy"][i2]).max()))
    fig, axs = plt.subplots(2, 2, figsize=(10, 4.6), sharex=True, sharey=True,
                            layout="constrained")
    cm = plt.get_cmap("coolwarm", nproc)
    for ax, step in zip(axs.flat, [0, 10, 20, 40]):
        pts = read_points(outn, step)
        counts = [int((pts["rank"] == r).sum()) for r in range(nproc)]
        # Points that changed owner since step 0.
        ax.scatter(pts["x"][:, 0], pts["x"][:, 1], c=pts["rank"], s=5,
                   cmap=cm, vmin=-0.5, vmax=nproc - 0.5, linewidths=0)
        ax.set_aspect("equal")
        ax.set_xlim(0, 16)
        ax.set_ylim(0, 8.2)
        ax.set_title("step %d: points per rank %s" % (step, counts),
                     fontsize=9)
        note("  step %d: points per rank %s" % (step, counts))
        if step == 0:
            initial_rank = {tuple(np.round(X, 6)): r for X, r in
                            zip(pts["initial_position"], pts["rank"])}
        else:
            moved = sum(initial_rank[tuple(np.round(X, 6))] != r for X, r in
                        zip(pts["initial_position"], pts["rank"]))
            note("    points owned by another rank than at step 0: %d" % moved)
    for ax in axs[1]:
        ax.set_xlabel("x (m)")
    for ax in axs[:, 0]:
        ax.set_ylabel("y (m)")
    sm = plt.cm.ScalarMappable(cmap=cm,
                               norm=matplotlib.colors.Normalize(-0.5,
                                                                nproc - 0.5))
    cb = fig.colorbar(sm, ax=axs, ticks=range(nproc), shrink=0.8)
    cb.set_label("rank")
    save(fig, "hard6_ranks.png")


def case7(run):
    note("== 7. Tiny yield stress")
    scene = os.path.join(TESTS, "column_tiny_yield.prm")
    out10, so10, _, _, cmd10 = run.run("tiny_yield_10", scene)
    out3, so3, _, _, cmd3 = run.run("tiny_yield_3", scene,
                                    [MATERIAL + "/von Mises/Yield stress=3"])
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 3.8), sharey=True)
    for out, so, cmd, tag in [(out10, so10, cmd10, "10 Pa"),
                              (out3, so3, cmd3, "3 Pa")]:
        s = read_summary(out)
        att = read_newton(os.path.join(out, "newton.csv"))
        st = read_csv(os.path.join(out, "steps.csv"))
        note("$ " + cmd)
        note("  %s: attempts %d, cuts %d, newton_iterations %d" %
             (tag, len(att), s["load_step_cuts"], s["newton_iterations"]))
        for line in so.splitlines():
            if line.startswith("observed") or "cut" in line or \
                    line.startswith("extent in y") or \
                    line.startswith("point 0:"):
                note("  " + line)
        for i in np.where(st["converged"] == 0)[0]:
            rows = range(max(i - 1, 0), min(i + 3, len(st["step"])))
            note("  steps.csv rows %d-%d (step, load_factor, load_increment, "
                 "converged, newton_iterations): %s" % (
                     rows[0] + 1, rows[-1] + 1, "; ".join(
                         "%d %.4g %.4g %d %d" % (
                             st["step"][j], st["load_factor"][j],
                             st["load_increment"][j], st["converged"][j],
                             st["newton_iterations"][j]) for j in rows)))
        ok = [a for a, c in zip(att, st["converged"]) if c == 1]
        orders = np.array([newton_order(r) for _, r in ok])
        note("  observed order of converged steps (as the test line): "
             "min %.2f (step %d), median %.2f, steps below 1.7: %s" %
             (np.nanmin(orders), ok[int(np.nanargmin(orders))][0],
              np.nanmedian(orders),
              [ok[i][0] for i in np.where(orders < 1.7)[0]]))
        if tag == "10 Pa":
            for k in [0, 1, 9, 24, 49]:
                step, r = att[k]
                ax1.semilogy(range(len(r)), r, "o-", ms=4,
                             label="step %d" % step)
                note("  step %d residuals: %s (order %.2f)" %
                     (step, " ".join("%.2e" % x for x in r), newton_order(r)))
        else:
            shown = 0
            colours = ["tab:red", "tab:blue"]
            for (step, r), c in zip(att, st["converged"]):
                if c == 0:
                    note("  step %d cut: residuals %s" % (step, " ".join(
                        "%.3e" % x for x in r[:4] + r[-2:])))
                    if shown < 2:
                        col = colours[shown]
                        ax2.semilogy(range(len(r)), r, "x--", ms=4, color=col,
                                     label="step %d, cut (stalls)" % step)
                        shown += 1
                        retry = [a for a in att if a[0] == step][1][1]
                        ax2.semilogy(range(len(retry)), retry, "o-", ms=4,
                                     color=col,
                                     label="step %d, retried at half size"
                                     % step)
                        note("  step %d retry: %s" % (step, " ".join(
                            "%.2e" % x for x in retry)))
    ax1.axhline(1e-9, color="k", ls="--", lw=0.8)
    ax2.axhline(1e-9, color="k", ls="--", lw=0.8)
    ax1.set_title("yield stress 10 Pa (test scene)", fontsize=9)
    ax2.set_title("yield stress 3 Pa", fontsize=9)
    for ax in (ax1, ax2):
        ax.set_xlabel("Newton iteration")
        ax.legend(fontsize=7)
    ax1.set_ylabel("relative residual |r| / |f_ext|")
    fig.tight_layout()
    save(fig, "hard7_tiny_yield.png")


def collapse(result):
    note("== The collapse (prm/collapse.prm, h = 0.5 m)")
    s, pts, so, out = result
    st = read_csv(os.path.join(out, "steps.csv"))
    weight = st["load_factor"] * 64000 * 10
    rel = np.abs(st["reaction_y-_y"] - weight) / weight
    note("  max_tensile_vertical_stress = %.6g Pa" %
         s["max_tensile_vertical_stress"])
    note("  max_reaction_imbalance = %.3g" % s["max_reaction_imbalance"])
    note("  base reaction vs weight: largest relative difference %.2e "
         "(step %d); at the last step %.6g N vs %.6g N" %
         (rel.max(), st["step"][np.argmax(rel)], st["reaction_y-_y"][-1],
          weight[-1]))
    tens = pts["stress_yy"] > 0
    note("  final points: %d, with stress_yy > 0: %d; largest final "
         "stress_yy %.6g Pa at x = (%.3f, %.3f), initially (%.3f, %.3f)" %
         (len(tens), tens.sum(), pts["stress_yy"].max(),
          *pts["x"][np.argmax(pts["stress_yy"])][:2],
          *pts["initial_position"][np.argmax(pts["stress_yy"])][:2]))
    if tens.any():
        note("  tensile points lie in x [%.2f, %.2f], y [%.2f, %.2f]; "
             "their mean stress (xx+yy+zz)/3: min %.3g, max %.3g Pa" %
             (pts["x"][tens, 0].min(), pts["x"][tens, 0].max(),
              pts["x"][tens, 1].min(), pts["x"][tens, 1].max(),
              ((pts["stress_xx"] + pts["stress_yy"] + pts["stress_zz"])[tens]
               / 3).min(),
              ((pts["stress_xx"] + pts["stress_yy"] + pts["stress_zz"])[tens]
               / 3).max()))
        for lo, hi in [(0, 4), (4, 8), (8, 12), (12, 16)]:
            m = tens & (pts["x"][:, 0] >= lo) & (pts["x"][:, 0] < hi)
            if m.any():
                note("    x in [%g, %g): %d tensile points, y in [%.2f, %.2f], "
                     "largest stress_yy %.4g Pa" % (
                         lo, hi, m.sum(), pts["x"][m, 1].min(),
                         pts["x"][m, 1].max(), pts["stress_yy"][m].max()))
        toe = tens & (pts["x"][:, 0] >= 12)
        note("    volume ratio J of the tensile points with x >= 12: %.3f to "
             "%.3f" % ((pts["volume"][toe] / (0.5 / 3) ** 2).min(),
                       (pts["volume"][toe] / (0.5 / 3) ** 2).max()))
    X = pts["initial_position"]
    sym = np.isclose(X[:, 0], X[:, 0].min())
    k = np.argmax(np.where(sym, X[:, 1], -1))
    note("  top point of the symmetry line: initially (%.3f, %.3f), now "
         "(%.3f, %.3f)" % (X[k, 0], X[k, 1], pts["x"][k, 0], pts["x"][k, 1]))
    top = np.argmax(pts["x"][:, 1])
    note("  highest point: now at (%.3f, %.3f), initially at (%.3f, %.3f), "
         "plastic multiplier %.3g" % (*pts["x"][top][:2],
                                      *pts["initial_position"][top][:2],
                                      pts["plastic_multiplier"][top]))
    vol0 = (0.5 / 3) ** 2
    vm_max = pts["von_mises_stress"].max()
    note("  largest von_mises_stress * J (J = volume / initial volume): %.6g "
         "Pa; sqrt(3/2) x 20 kPa = %.6g Pa" % (
             (pts["von_mises_stress"] * pts["volume"] / vol0).max(),
             np.sqrt(1.5) * 2e4))
    note("  largest final von_mises_stress %.6g Pa" % vm_max)

    fig, ax = plt.subplots(figsize=(9, 3.6))
    sc = scatter_points(ax, pts, "stress_yy", -7e4, 3e4, "viridis", 5)
    ax.set_xlim(0, 16)
    ax.set_ylim(0, 8)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title("collapse, h = 0.5 m, 3x3 points per cell, after 40 steps",
                 fontsize=9)
    fig.colorbar(sc, ax=ax, label="stress_yy (Pa)")
    fig.tight_layout()
    save(fig, "collapse_final.png")

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 3.8))
    ax1.plot(st["step"], weight / 1e3, "k-", label="load factor x 64000 kg "
             "x 10 m/s^2")
    ax1.plot(st["step"], st["reaction_y-_y"] / 1e3, "o", ms=4, mfc="none",
             color="tab:blue", label="reaction_y-_y")
    ax1b = ax1.twinx()
    ax1b.semilogy(st["step"], np.maximum(rel, 1e-17), "r.", ms=4)
    ax1b.set_ylabel("|reaction - weight| / weight", color="r")
    ax1.set_xlabel("load step")
    ax1.set_ylabel("force (kN)")
    ax1.legend(fontsize=8, loc="upper left")
    ax1.set_title("base reaction against the weight", fontsize=9)
    ax2.scatter(pts["x"][~tens, 0], pts["x"][~tens, 1], s=3, c="0.8",
                linewidths=0, label="stress_yy <= 0")
    sc = ax2.scatter(pts["x"][tens, 0], pts["x"][tens, 1], s=8,
                     c=pts["stress_yy"][tens], cmap="autumn_r", vmin=0,
                     linewidths=0, label="stress_yy > 0")
    ax2.set_aspect("equal")
    ax2.set_xlim(0, 16)
    ax2.set_ylim(0, 8)
    ax2.set_xlabel("x (m)")
    ax2.set_title("points in vertical tension (%d of %d)" %
                  (tens.sum(), len(tens)), fontsize=9)
    fig.colorbar(sc, ax=ax2, label="stress_yy > 0 (Pa)", shrink=0.8)
    fig.tight_layout()
    save(fig, "collapse_reaction_tension.png")


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    keep = "--keep" in sys.argv
    nproc = 2
    if "--np" in sys.argv:
        nproc = int(sys.argv[sys.argv.index("--np") + 1])
        args.remove(str(nproc))
    if len(args) != 1:
        raise SystemExit(__doc__)
    print("point files read with", "vtk %s" % vtk.vtkVersion.GetVTKVersion()
          if vtk is not None else "the script's own VTU parser (no vtk)")
    os.makedirs(FIGURES, exist_ok=True)
    work = tempfile.mkdtemp(prefix="impm_hard_cases_")
    print("runs in", work)
    run = Runner(args[0], work)
    start = time.time()
    listing = subprocess.run([os.path.abspath(args[0]), "--print-parameters"],
                             capture_output=True, text=True).stdout
    global MATERIAL
    if re.search(r"^subsection Body 1$", listing, re.M):
        MATERIAL = "Body 1/Material"
    for f in [args[0], os.path.join(os.path.dirname(args[0]),
                                    "libimpm_core.so")]:
        if os.path.exists(f):
            digest = subprocess.run(["sha256sum", f], capture_output=True,
                                    text=True).stdout.split()[0]
            note("%s: sha256 %s..., modified %s" % (
                os.path.basename(f), digest[:16],
                time.strftime("%Y-%m-%d %H:%M:%S",
                              time.gmtime(os.path.getmtime(f)))))
    commit = subprocess.run(["git", "-C", ROOT, "log", "-1", "--format=%h %s"],
                            capture_output=True, text=True).stdout.strip()
    note("repository HEAD: %s" % commit)
    result = case1(run)
    case2(run)
    case3(run)
    case4(run)
    case5(run)
    case6(run, nproc)
    case7(run)
    collapse(result)
    note()
    note("total time of the script: %.0f s" % (time.time() - start))
    with open(os.path.join(FIGURES, "hard_case_numbers.txt"), "w") as f:
        f.write("\n".join(numbers) + "\n")
    if keep:
        print("kept", work)
    else:
        shutil.rmtree(work)


if __name__ == "__main__":
    main()
