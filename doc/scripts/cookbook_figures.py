#!/usr/bin/python3
"""The figures of the cookbook pages (doc/cookbook/<scene>.md).

For each scene in prm/, this runs the page's figure command (the first line
of a page that starts 'build/impm prm/<scene>.prm', with the '--set' options
of a '<!-- figure: ... -->' comment just before its block appended where the
full run is too long) in a temporary folder, and makes
  doc/cookbook/images/<scene>.png       the material points at the last
                                        output step, coloured by a field
                                        (with the rigid body's outline);
  doc/cookbook/images/<scene>_plot.png  a plot from steps.csv (or the other
                                        files the run wrote).
It prints the numbers the plot shows. One impm process at a time.

Usage: /usr/bin/python3 doc/scripts/cookbook_figures.py [--impm build/impm]
           [--only NAME ...] [--keep]
"""
import argparse
import csv
import glob
import math
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
pages = os.path.join(root, "doc", "cookbook")
images = os.path.join(pages, "images")
DPI = 100


# ---------------------------------------------------------------- reading
def figure_commands():
    """{scene: (page, command line, figure options)} from the pages."""
    commands = {}
    for page in sorted(glob.glob(os.path.join(pages, "*.md"))):
        text = open(page).read()
        for options, block in re.findall(
                r"(?:<!-- figure: ([^\n]*?) -->\s*)?"
                r"(?:<!-- test: [^\n]*? -->\s*)?```sh\n(.*?)```", text, re.S):
            for line in block.splitlines():
                match = re.match(r"build/impm prm/(\S+)\.prm", line.strip())
                if match and match.group(1) not in commands:
                    commands[match.group(1)] = (page, line.strip(), options or "")
    return commands


def steps(output):
    rows = []
    for row in csv.DictReader(open(os.path.join(output, "steps.csv"))):
        if row.get("converged", "1") == "1":
            rows.append({k: float(v) for k, v in row.items() if v not in ("", None)})
    return rows


def column(rows, name):
    return np.array([r[name] for r in rows])


def read_grid(path):
    reader = (vtk.vtkXMLPUnstructuredGridReader() if path.endswith(".pvtu")
              else vtk.vtkXMLUnstructuredGridReader())
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    result = {"x": vtk_to_numpy(data.GetPoints().GetData()).copy()}
    point_data = data.GetPointData()
    for i in range(point_data.GetNumberOfArrays()):
        result[point_data.GetArrayName(i)] = vtk_to_numpy(point_data.GetArray(i)).copy()
    cells = []
    for i in range(data.GetNumberOfCells()):
        ids = data.GetCell(i).GetPointIds()
        cells.append([ids.GetId(j) for j in range(ids.GetNumberOfIds())])
    result["cells"] = cells
    return result


def point_series(output):
    """[(step, file)] of the point files, in order."""
    files = glob.glob(os.path.join(output, "points_*.pvtu"))
    files = files or [f for f in glob.glob(os.path.join(output, "points_*.vtu"))]
    series = {}
    for f in files:
        series[int(re.search(r"points_(\d+)", os.path.basename(f)).group(1))] = f
    return sorted(series.items())


def rigid_outlines(output, step):
    outlines = []
    for f in sorted(glob.glob(os.path.join(output, "rigid_*_%05d.vtu" % step))):
        body = read_grid(f)
        for cell in body["cells"]:
            outlines.append(body["x"][cell])
    return outlines


# ---------------------------------------------------------------- pictures
def section(points, dimension):
    """In 3D, the points of the first layer at the symmetry plane y = 0
    (their initial y the smallest), seen along y: (x, z)."""
    if dimension == 2:
        return np.ones(len(points["x"]), bool), (0, 1)
    y0 = points["initial_position"][:, 1]
    return y0 <= y0.min() + 1e-9, (0, 2)


def picture(scene, output, field, label, dimension=2, scale=1.0, cmap="viridis",
            limits=None, symmetric=False, title=None, extent=None, outline=None):
    series = point_series(output)
    step, path = series[-1]
    points = read_grid(path)
    keep, (i, j) = section(points, dimension)
    x = points["x"][keep]
    if field == "displacement_magnitude":
        values = np.linalg.norm(points["displacement"][keep], axis=1)
    elif callable(field):
        values = field(points)[keep]
    else:
        values = points[field][keep]
    values = values * scale
    lo = extent[0] if extent else (x[:, i].min(), x[:, j].min())
    hi = extent[1] if extent else (x[:, i].max(), x[:, j].max())
    outlines = rigid_outlines(output, step) if dimension == 2 else []
    if outline:  # a rigid body's section, given by the scene's function
        outlines.append(np.array(outline))
    width = 6.4
    aspect = (hi[1] - lo[1]) / max(hi[0] - lo[0], 1e-12)
    height = min(max(width * aspect, 2.2), 6.4) + 0.9
    fig, ax = plt.subplots(figsize=(width, height))
    ax.set_aspect("equal")
    pad = 0.03 * max(hi[0] - lo[0], hi[1] - lo[1])
    ax.set_xlim(lo[0] - pad, hi[0] + pad)
    ax.set_ylim(lo[1] - pad, hi[1] + pad)
    vmin, vmax = limits if limits else (values.min(), values.max())
    if symmetric:
        vmax = max(abs(vmin), abs(vmax))
        vmin = -vmax
    order = np.argsort(values) if not symmetric else np.arange(len(values))
    sc = ax.scatter(x[order, i], x[order, j], c=values[order], s=1, marker="s",
                    linewidths=0, cmap=cmap, vmin=vmin, vmax=vmax)
    fig.colorbar(sc, ax=ax, label=label, shrink=0.85)
    fig.tight_layout()
    fig.canvas.draw()
    # a marker about as wide as a point's share of the body, once the
    # colour bar has taken its room
    spacing = (points["volume"][keep] ** (1.0 / dimension)).mean() \
        if "volume" in points else 0.1
    bbox = ax.get_window_extent()
    per_unit = min(bbox.width / (ax.get_xlim()[1] - ax.get_xlim()[0]),
                   bbox.height / (ax.get_ylim()[1] - ax.get_ylim()[0]))  # pixels per m
    sc.set_sizes([max((0.95 * spacing * per_unit * 72.0 / DPI) ** 2, 0.3)])
    for body in outlines:
        polygon = np.vstack([body, body[:1]])
        ax.fill(polygon[:, 0], polygon[:, 1], color="0.6", alpha=0.6, zorder=3)
        ax.plot(polygon[:, 0], polygon[:, 1], color="k", lw=1, zorder=4)
    ax.set_xlabel("x (m)")
    ax.set_ylabel(("z" if dimension == 3 else "y") + " (m)")
    ax.set_title(title or "%s: %s at the last output step" % (scene, label.split(" (")[0]),
                 fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(images, scene + ".png"), dpi=DPI)
    plt.close(fig)
    return points


def new_plot(xlabel, ylabel, title, size=(6.0, 3.8)):
    fig, ax = plt.subplots(figsize=size)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=9)
    ax.grid(alpha=0.3)
    return fig, ax


def save_plot(fig, scene):
    fig.tight_layout()
    fig.savefig(os.path.join(images, scene + "_plot.png"), dpi=DPI)
    plt.close(fig)


def say(scene, text):
    print("%s: %s" % (scene, text))


# ---------------------------------------------------------------- scenes
IMPM = None  # the executable (main() sets it), for scenes that run twice
PRANDTL_VM = (2 + math.pi) * 2e4 / math.sqrt(2) * 0.5 / 1e3  # kN, half footing


def cantilever(scene, output):
    points = picture(scene, output, "stress_xx", "stress_xx (Pa)", cmap="coolwarm",
                     symmetric=True)
    x0 = points["initial_position"]
    u = points["displacement"]
    E, I, L, P, G, A = 1e6, 1.0 / 12, 10.0, -1.0, 5e5, 1.0
    fig, ax = new_plot("x (m)", "vertical displacement (mm)",
                       "cantilever: deflection of the points against beam theory")
    ax.plot(x0[:, 0], u[:, 1] * 1e3, ".", ms=2, label="IMPM, every point")
    xs = np.linspace(0, L, 100)
    w = P * xs ** 2 * (3 * L - xs) / (6 * E * I) + P * xs / (5.0 / 6 * G * A)
    ax.plot(xs, w * 1e3, "k--", label="Euler-Bernoulli + shear")
    end = x0[:, 0].max()
    tip = u[np.abs(x0[:, 0] - end) < 1e-9, 1].mean()
    theory = P * end ** 2 * (3 * L - end) / (6 * E * I) + P * end / (5.0 / 6 * G * A)
    ax.legend(fontsize=8)
    save_plot(fig, scene)
    say(scene, "end deflection %.4e m at x = %.4f, theory %.4e, ratio %.4f"
        % (tip, end, theory, tip / theory))


def circular_plate_axisymmetric(scene, output):
    points = picture(scene, output, "stress_yy", "stress_yy (kPa)", scale=1e-3,
                     cmap="viridis_r", limits=(-30, 0))
    rows = steps(output)
    force = -rows[-1]["reaction_y+_y"]
    a, E, nu, w = 1.0, 1e7, 0.3, 1e-3
    x, x0, s = points["x"], points["initial_position"], points["stress_yy"]
    top = x0[:, 1] >= x0[:, 1].max() - 1e-9
    fig, ax = new_plot("r (m)", "vertical stress under the plate (kPa)",
                       "circular plate: the top row of points against Boussinesq's rigid punch")
    ax.plot(x[top, 0], -s[top] / 1e3, "o", ms=3, label="IMPM, top row of points")
    r = np.linspace(0, 0.98 * a, 100)
    boussinesq = 2 * a * E * w / (1 - nu ** 2)  # force of the punch on a half-space
    ax.plot(r, boussinesq / (2 * math.pi * a * np.sqrt(a ** 2 - r ** 2)) / 1e3, "k--",
            label="half-space, P / (2 pi a sqrt(a^2 - r^2))")
    ax.set_xlim(0, 2.5)
    ax.set_ylim(0, 60)
    ax.legend(fontsize=8)
    save_plot(fig, scene)
    say(scene, "force %.4e N, half-space %.4e N, settlement ratio %.4f"
        % (force, boussinesq, boussinesq / force))


def circular_footing_tresca(scene, output):
    picture(scene, output, "plastic_multiplier", "plastic multiplier", cmap="magma_r",
            extent=((0, 0), (3, 2.5)), limits=(0, 0.05))
    rows = steps(output)
    settlement = [0.0] + list(0.03 * column(rows, "load_factor"))
    pressure = [0.0] + list(-column(rows, "reaction_y+_y") / (math.pi * 1e4))
    fig, ax = new_plot("settlement (m)", "bearing pressure q / c",
                       "circular footing on Tresca clay: q / c against settlement")
    ax.plot(settlement, pressure, "-", lw=1.5, label="IMPM, F-bar, h = R/8")
    ax.axhline(6.05, color="k", ls="--", label="Houlsby and Wroth, rough: 6.05")
    ax.set_ylim(0, 8)
    ax.legend(fontsize=8, loc="lower right")
    save_plot(fig, scene)
    k = int(np.argmax(pressure))
    say(scene, "q/c peak %.3f at %.4f m, %.3f at %.4f m"
        % (pressure[k], settlement[k], pressure[-1], settlement[-1]))


def collapse_like(scene, output, dimension=2, title="collapse"):
    picture(scene, output, "von_mises_stress", "von Mises stress (kPa)", scale=1e-3,
            dimension=dimension)
    series = point_series(output)
    load, top, toe = [], [], []
    rows = {int(r["step"]): r for r in steps(output)}
    for step, path in series:
        p = read_grid(path)
        x0, x = p["initial_position"], p["x"]
        vertical = 1 if dimension == 2 else 2
        axis = np.all(np.abs(x0[:, :vertical]) <= x0[:, :vertical].min(axis=0) + 1e-9, axis=1)
        load.append(rows[step]["load_factor"] if step in rows else 0.0)
        top.append(x[axis, vertical].max() - x0[axis, vertical].max())
        toe.append(x[:, 0].max() - x0[:, 0].max())
    fig, ax = new_plot("load factor (gravity)", "displacement (m)",
                       "%s: the top of the symmetry line and the toe" % title)
    ax.plot(load, top, "o-", label="top of the symmetry line (vertical)")
    ax.plot(load, toe, "s-", label="toe run-out (horizontal)")
    ax.legend(fontsize=8)
    save_plot(fig, scene)
    say(scene, "top %.3f m, toe %.3f m at load factor %.3f" % (top[-1], toe[-1], load[-1]))


def collapse(scene, output):
    collapse_like(scene, output)


def collapse_3d(scene, output):
    collapse_like(scene, output, dimension=3, title="collapse in 3D")


def phases(scene, output, dimension):
    picture(scene, output, "von_mises_stress", "von Mises stress (kPa)", scale=1e-3,
            dimension=dimension)
    rows = steps(output)
    names = [k for k in rows[0] if k.startswith("time_") and k != "time_load_balance"]
    fig, ax = new_plot("load step", "wall time (s)",
                       "%s: the phases of each load step (one process)" % scene)
    bottom = np.zeros(len(rows))
    for name in names:
        values = column(rows, name)
        ax.bar(column(rows, "step"), values, bottom=bottom, label=name[5:].replace("_", " "))
        bottom += values
    ax.legend(fontsize=7, ncol=2)
    save_plot(fig, scene)
    totals = {n[5:]: column(rows, n).sum() for n in names}
    say(scene, "phases over the run: " + ", ".join("%s %.2f s" % kv for kv in totals.items()))


def collapse_million(scene, output):
    phases(scene, output, 2)


def collapse_3d_benchmark(scene, output):
    phases(scene, output, 3)


def energies(scene, output, title):
    rows = steps(output)
    fig, ax = new_plot("time (s)", "kinetic energy (J per m)", title)
    ax.semilogy(column(rows, "time"), column(rows, "kinetic_energy"), "-")
    save_plot(fig, scene)
    kinetic = column(rows, "kinetic_energy")
    say(scene, "kinetic energy peak %.4g J at %.3f s, end %.4g J (%.3g of the peak)"
        % (kinetic.max(), column(rows, "time")[kinetic.argmax()], kinetic[-1],
           kinetic[-1] / kinetic.max()))


def collapse_cam_clay(scene, output):
    points = picture(scene, output, "displacement_magnitude", "displacement (m)")
    energies(scene, output, "Cam-clay collapse: kinetic energy")
    x, x0 = points["x"], points["initial_position"]
    axis = np.abs(x0[:, 0] - x0[:, 0].min()) < 1e-9
    say(scene, "run-out %.3f m, top of the symmetry line %.3f m"
        % (x[:, 0].max(), x[axis, 1].max() - x0[axis, 1].max()))


def granular_column_collapse(scene, output):
    picture(scene, output, "displacement_magnitude", "displacement (m)")
    rows = steps(output)
    series = point_series(output)
    times, front = [], []
    step_time = {int(r["step"]): r["time"] for r in rows}
    for step, path in series:
        p = read_grid(path)
        times.append(step_time.get(step, 0.0))
        front.append(p["x"][:, 0].max() - 1.0)
    fig, ax = new_plot("time (s)", "(L - L0) / L0",
                       "granular column (a = 1): the front against Lube et al.")
    ax.plot(times, front, "o-", label="IMPM, outermost point")
    ax.axhline(1.2, color="k", ls="--", label="Lube et al. (2005): 1.2 a")
    ax2 = ax.twinx()
    ax2.semilogy(column(rows, "time"), column(rows, "kinetic_energy"), color="0.6", lw=1)
    ax2.set_ylabel("kinetic energy (J per m), grey")
    ax.legend(fontsize=8, loc="center right")
    save_plot(fig, scene)
    say(scene, "front %.3f L0 at %.2f s; kinetic energy at the end %.3g J, peak %.3g J"
        % (front[-1], times[-1], rows[-1]["kinetic_energy"],
           column(rows, "kinetic_energy").max()))


def column_compaction(scene, output):
    points = picture(scene, output, "stress_yy", "stress_yy (kPa)", scale=1e-3,
                     title="column: vertical stress at full weight")
    x0, s = points["initial_position"], points["stress_yy"]
    fig, ax = new_plot("vertical stress (kPa)", "initial height Z (m)",
                       "column: vertical stress against -rho_0 g (l0 - Z)")
    ax.plot(s / 1e3, x0[:, 1], "o", ms=3, label="IMPM, every point")
    Z = np.linspace(0, 50, 50)
    ax.plot(-80 * 10 * (50 - Z) / 1e3, Z, "k--", label="analytical")
    ax.legend(fontsize=8)
    save_plot(fig, scene)
    exact = -80 * 10 * (50 - x0[:, 1])
    say(scene, "largest |sigma - exact| / max|exact| %.3e"
        % (np.abs(s - exact).max() / np.abs(exact).max()))


def force_settlement(scene, output, column_name, displacement, xlabel, title,
                     reference=None, reference_label=None, factor=1e-3, sign=-1):
    rows = steps(output)
    settlement = [0.0] + list(displacement * column(rows, "load_factor"))
    force = [0.0] + list(sign * column(rows, column_name) * factor)
    fig, ax = new_plot(xlabel, "force (kN per m)" if factor == 1e-3 else "force", title)
    ax.plot(settlement, force, "-", lw=1.5, label="IMPM")
    if reference is not None:
        ax.axhline(reference, color="k", ls="--", label=reference_label)
    ax.legend(fontsize=8, loc="lower right")
    return fig, ax, np.array(settlement), np.array(force)


def strip_footing(scene, output):
    picture(scene, output, "plastic_multiplier", "plastic multiplier", cmap="magma_r",
            extent=((0, 0), (3, 2)))
    fig, ax, s, f = force_settlement(
        scene, output, "reaction_y+_y", 0.2, "settlement (m)",
        "strip footing: load on the half footing against Prandtl", PRANDTL_VM,
        "Prandtl (2 + pi) c B/2 = %.1f kN" % PRANDTL_VM)
    save_plot(fig, scene)
    say(scene, "force %.2f kN at %.3f m (%.1f at %.2f)" % (f[-1], s[-1], f[len(f) // 2],
                                                            s[len(s) // 2]))


def strip_footing_rigid(scene, output):
    picture(scene, output, "plastic_multiplier", "plastic multiplier", cmap="magma_r",
            extent=((0, 0), (3, 3)))
    fig, ax, s, f = force_settlement(
        scene, output, "rigid_1_force_y", 1.0, "settlement (m)",
        "rigid footing: force on the half footing", PRANDTL_VM,
        "Prandtl, surface footing: %.1f kN" % PRANDTL_VM, sign=1)
    save_plot(fig, scene)
    for target in (0.13, 0.46, 1.0):
        k = np.argmin(np.abs(s - target))
        say(scene, "%.1f kN at %.3f m" % (f[k], s[k]))


def strip_footing_force(scene, output):
    picture(scene, output, "plastic_multiplier", "plastic multiplier", cmap="magma_r",
            extent=((0, 0), (3, 3)))
    rows = steps(output)
    load = 60 * column(rows, "load_factor")
    settlement = -column(rows, "rigid_1_displacement_y")
    fig, ax = new_plot("settlement (m)", "force on the half footing (kN per m)",
                       "footing pushed by a force: the settlement is the unknown")
    ax.plot(settlement, load, "o-", ms=2, label="IMPM (60 kN in 120 steps)")
    ax.axhline(PRANDTL_VM, color="k", ls="--",
               label="Prandtl, surface footing: %.1f kN" % PRANDTL_VM)
    ax.legend(fontsize=8, loc="lower right")
    save_plot(fig, scene)
    say(scene, "settlement %.4f m at %.1f kN" % (settlement[-1], load[-1]))


def strip_footing_mohr_coulomb(scene, output):
    picture(scene, output, "plastic_multiplier", "plastic multiplier", cmap="magma_r",
            extent=((0, 0), (3, 2.25)))
    nc = (math.exp(math.pi * math.tan(math.radians(20))) *
          math.tan(math.radians(55)) ** 2 - 1) / math.tan(math.radians(20))
    prandtl = nc * 1e4 * 0.5 / 1e3
    fig, ax, s, f = force_settlement(
        scene, output, "reaction_y+_y", 0.05, "settlement (m)",
        "Mohr-Coulomb footing: load on the half footing", prandtl,
        "Prandtl N_c c B/2 = %.1f kN" % prandtl)
    save_plot(fig, scene)
    say(scene, "force %.1f kN at %.3f m, Prandtl %.1f kN" % (f[-1], s[-1], prandtl))


def strip_footing_cam_clay(scene, output):
    picture(scene, output, "von_mises_stress", "von Mises stress (kPa)", scale=1e-3,
            extent=((0, 0), (3, 2.5)))
    fig, ax, s, f = force_settlement(
        scene, output, "rigid_1_force_y", 0.25, "settlement (m)",
        "Cam-clay footing: force on the half footing", sign=1)
    save_plot(fig, scene)
    k = np.argmin(np.abs(s - 0.1))
    say(scene, "force %.2f kN at %.3f m, %.2f kN at %.3f m" % (f[-1], s[-1], f[k], s[k]))


def rigid_plate(scene, output):
    points = picture(scene, output, "stress_yy", "stress_yy (kPa)", scale=1e-3)
    rows = steps(output)
    w = 0.25 * column(rows, "load_factor")
    force = column(rows, "rigid_1_force_y") / 1e3
    E, nu = 1e6, 0.3
    stretch = 1 - w
    # a rigid, frictionless plate on a block on rollers: plane strain, Hencky
    exact = -E * np.log(stretch) / (1 - nu ** 2) / stretch / 1e3  # force per m
    fig, ax = new_plot("plate displacement (m)", "force on the plate (kN per m)",
                       "rigid plate compressing a block")
    ax.plot(np.r_[0, w], np.r_[0, force], "o-", label="IMPM (penalty contact)")
    ax.plot(np.r_[0, w], np.r_[0, exact], "k--", label="exact, rigid plate")
    ax.legend(fontsize=8)
    save_plot(fig, scene)
    s = points["stress_yy"]
    say(scene, "force %.1f kN, stress_yy %.1f to %.1f kPa" % (force[-1], s.min() / 1e3,
                                                              s.max() / 1e3))


def slope_mohr_coulomb(scene, output):
    points = picture(scene, output, "plastic_multiplier", "plastic multiplier",
                     cmap="magma_r")
    series = point_series(output)
    rows = {int(r["step"]): r for r in steps(output)}
    load, crest = [], []
    for step, path in series:
        p = read_grid(path)
        x0 = p["initial_position"]
        near = np.argmin((x0[:, 0] - 13) ** 2 + (x0[:, 1] - 10) ** 2)
        load.append(rows[step]["load_factor"] if step in rows else 0.0)
        crest.append(p["displacement"][near, 1] * 1e3)
    fig, ax = new_plot("load factor (gravity)", "vertical displacement (mm)",
                       "slope: the crest's settlement as gravity rises")
    ax.plot(load, crest, "o-", label="point nearest the crest (13, 10)")
    ax.legend(fontsize=8)
    save_plot(fig, scene)
    yielded = (points["plastic_multiplier"] > 0).sum()
    say(scene, "%d of %d points yielded; crest %.2f mm" % (yielded, len(points["x"]),
                                                           crest[-1]))


def slope_factor_of_safety(scene, output):
    failed = os.path.join(output, "first_failed")
    picture(scene, failed, "displacement_magnitude", "displacement (m)",
            title="slope: the first failed trial's last converged step",
            limits=(0, 0.2))
    trials = list(csv.DictReader(open(os.path.join(output, "factor_of_safety.csv"))))
    fig, ax = new_plot("trial", "strength reduction factor F",
                       "slope: the trials of the strength reduction")
    for t in trials:
        stands = t["stands"] == "1"
        ax.plot(int(t["trial"]), float(t["factor"]), "o" if stands else "x",
                color="tab:green" if stands else "tab:red", ms=8)
    ax.plot([], [], "o", color="tab:green", label="stands")
    ax.plot([], [], "x", color="tab:red", label="fails (displacement > 0.1 m)")
    ax.axhline(1.378, color="k", ls="--", label="Bishop's simplified method, 1.378")
    ax.legend(fontsize=8)
    save_plot(fig, scene)
    say(scene, "trials: " + ", ".join("%s %s" % (t["factor"][:6], "stands" if t["stands"] == "1"
                                                  else "fails") for t in trials))


def two_bodies(scene, output):
    picture(scene, output, "stress_yy", "stress_yy (kPa)", scale=1e-3)
    rows = steps(output)
    weight = (1800 * 8 + 2500 * 1) * 10 / 1e3
    fig, ax = new_plot("load factor (gravity)", "base reaction (kN per m)",
                       "two bodies: the base carries their weight")
    ax.plot(np.r_[0, column(rows, "load_factor")],
            np.r_[0, column(rows, "reaction_y-_y") / 1e3], "o-", label="IMPM, reaction_y-_y")
    ax.plot([0, 1], [0, weight], "k--", label="weight, %.0f kN" % weight)
    ax.legend(fontsize=8)
    save_plot(fig, scene)
    say(scene, "base reaction %.1f kN, weight %.1f kN" % (rows[-1]["reaction_y-_y"] / 1e3,
                                                          weight))


def spinning_disc(scene, output):
    """The APIC run's last state, and its strain energy against FLIP's (the
    page's second command, run here beside the first)."""
    picture(scene, output, lambda p: np.hypot(p["velocity_0"], p["velocity_1"]),
            "speed (m/s)", title="spinning disc, APIC: the speed after one revolution")
    flip = output + "_flip"
    subprocess.run([IMPM, os.path.join(root, "prm", scene + ".prm"), "--quiet",
                    "--set", "Output directory=" + flip, "--set", "Output/Interval=0",
                    "--set", "Inertia/Velocity update=FLIP/PIC"], check=True,
                   stdout=subprocess.DEVNULL)
    fig, ax = new_plot("time (s)", "strain energy / total energy",
                       "spinning disc: the rotation's energy that goes into strain")
    for directory, label in ((output, "APIC"), (flip, "FLIP")):
        rows = steps(directory)
        share = column(rows, "strain_energy") / rows[0]["total_energy"]
        ax.semilogy(column(rows, "time"), np.maximum(share, 1e-8), "-", label=label)
        say(scene, "%s: largest strain energy %.3g of the total" % (label, share.max()))
    ax.legend(fontsize=8)
    save_plot(fig, scene)


def wheel_rolling(scene, output):
    picture(scene, output, "plastic_multiplier", "plastic multiplier", cmap="magma_r",
            extent=((0, 0.5), (5, 3)))
    rows = steps(output)
    travel = 2 * column(rows, "load_factor")
    fig, ax = new_plot("travel (m)", "force on the wheel (kN per m)",
                       "rolling wheel: the forces of the clay on the wheel")
    ax.plot(travel, column(rows, "rigid_1_force_y") / 1e3, label="vertical")
    ax.plot(travel, column(rows, "rigid_1_force_x") / 1e3, label="horizontal")
    ax.legend(fontsize=8)
    save_plot(fig, scene)
    fx = column(rows, "rigid_1_force_x") / 1e3
    say(scene, "vertical %.1f kN at the end, horizontal %.2f to %.2f kN (mean %.2f)"
        % (rows[-1]["rigid_1_force_y"] / 1e3, fx.min(), fx.max(), fx.mean()))


def penetration(scene, output, component, quarter, title, dimension, depth, **options):
    picture(scene, output, "plastic_multiplier", "plastic multiplier", cmap="magma_r",
            dimension=dimension, **options)
    rows = steps(output)
    z = depth * column(rows, "load_factor")
    force = column(rows, component) * quarter
    fig, ax = new_plot("penetration (m)", "force (kN per m)" if dimension == 2 else "force (kN)",
                       title)
    ax.plot(np.r_[0, z], np.r_[0, force / 1e3], "-")
    return fig, ax, z, force


def pipe_penetration(scene, output):
    fig, ax, z, f = penetration(scene, output, "rigid_1_force_y", 1, "pipe: force on the half pipe",
                                2, 1.0)
    save_plot(fig, scene)
    say(scene, "force %.2f kN per m at %.2f m" % (f[-1] / 1e3, z[-1]))


def cone_penetration(scene, output):
    fig, ax, z, f = penetration(scene, output, "rigid_1_force_z", 4,
                                "cone: force on the whole cone (4 x the quarter)", 3, 0.4,
                                limits=(0, 1.5), outline=[(0, 0.35), (0.15, 0.61),
                                                          (0.15, 1.01), (0, 1.01)],
                                extent=((0, 0), (0.75, 1.05)))
    su = 2e4 / math.sqrt(3)
    area = math.pi * 0.15 ** 2
    ax2 = ax.twinx()
    lo, hi = ax.get_ylim()
    ax2.set_ylim(lo * 1e3 / area / su, hi * 1e3 / area / su)
    ax2.set_ylabel("q_c / s_u")
    save_plot(fig, scene)
    say(scene, "quarter force %.0f N, q_c %.0f kPa = %.1f s_u" % (
        f[-1] / 4, f[-1] / area / 1e3, f[-1] / area / su))


# ---------------------------------------------------------------- main
def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--impm", default=os.path.join(root, "build", "impm"))
    parser.add_argument("--only", nargs="+", metavar="NAME")
    parser.add_argument("--keep", action="store_true", help="keep the runs' folders")
    args = parser.parse_args()
    impm = os.path.abspath(args.impm)
    global IMPM
    IMPM = impm
    os.makedirs(images, exist_ok=True)
    commands = figure_commands()
    names = args.only or sorted(commands)
    failed = False
    for scene in names:
        if scene not in commands:
            print("%s: no page runs 'build/impm prm/%s.prm'" % (scene, scene))
            failed = True
            continue
        page, line, options = commands[scene]
        work = tempfile.mkdtemp(prefix="cookbook_" + scene + "_")
        os.symlink(os.path.join(root, "prm"), os.path.join(work, "prm"))
        command = " ".join([shlex.quote(impm), line[len("build/impm "):], options,
                            "--quiet"])
        print("%s: $ %s %s (in %s)" % (scene, line, options, work))
        start = time.time()
        run = subprocess.run(command, shell=True, cwd=work, stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True)
        if run.returncode != 0:
            print(run.stdout[-3000:])
            failed = True
            continue
        print("%s: ran in %.1f s" % (scene, time.time() - start))
        output = re.search(r"Output directory=([^\"']+)", line + " " + options)
        output = os.path.join(work, output.group(1) if output else "output")
        globals()[scene](scene, output)
        if not args.keep:
            shutil.rmtree(work)
        for suffix in ("", "_plot"):
            path = os.path.join(images, scene + suffix + ".png")
            print("%s: %s, %d KB" % (scene, os.path.relpath(path, root),
                                     os.path.getsize(path) // 1024))
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
