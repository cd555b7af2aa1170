#!/usr/bin/python3
"""Figures and tables of the accuracy-cost study (doc/benchmarks/).

Usage:
  doc/scripts/plot_study.py [--data doc/benchmarks] [--formulation-runs DIR]
                            [--page doc/benchmarks/accuracy_cost.md]
                            [--page doc/benchmarks/README.md]

Reads the CSV files that scripts/run_study.sh writes with scripts/study.py
into the data directory:
  column.csv              column runs (cells x points per cell x basis)
  column_points_16.csv    every final point of the column on 16 cells, 2x2,
                          GIMP and standard MPM (the Testing printout)
  formulation.csv         column, 64 cells: previously converged vs updated
                          Lagrangian, repeated
  formulation_points.csv  every final point of those two runs
  formulation_collapse.csv  the same comparison on the collapse, h = 0.5 m, 6x6
  collapse.csv            the collapse, h = 1, 0.5, 0.25 m x 3x3, 6x6
and writes into the same directory
  column_error_vs_h.png        (a) error of eq. 13 against the cell size h
  column_error_vs_time.png     (b) error against wall time (accuracy-cost front)
  time_per_phase.png           (c) time of each phase against the number of points
  column_stress_h3.125.png     (d) vertical stress against initial height Z
  formulation_check.csv        the equality check of the two formulations
and, with --page (repeatable; --readme is the same option), replaces the
blocks between
  <!-- BEGIN NAME --> and <!-- END NAME -->
of each Markdown file named by the tables (NAME = column-table,
column-phases, formulation-table, formulation-kernels, collapse-table,
collapse-phases: accuracy_cost.md; machine: README.md).  A block is written
into every page that has its markers; a block that no page has is reported.
--formulation-runs names the directory where
study.py --keep put the two Testing runs of the formulation comparison; their
steps.csv (error_sigma_zz of every step, 10 significant digits) are compared
too.
"""

import argparse
import csv
import glob
import json
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

PHASES = ["basis evaluation", "system setup", "stress update", "assembly",
          "linear solve", "point update", "output"]
SERIES = [("GIMP", "2"), ("GIMP", "3"), ("standard MPM", "2"), ("standard MPM", "3")]
STYLE = {("GIMP", "2"): dict(color="C0", marker="o", ls="-"),
         ("GIMP", "3"): dict(color="C0", marker="s", ls="--"),
         ("standard MPM", "2"): dict(color="C3", marker="o", ls="-"),
         ("standard MPM", "3"): dict(color="C3", marker="s", ls="--")}


def read(path):
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return list(csv.DictReader(f))


def num(row, key, default=float("nan")):
    try:
        return float(row.get(key, ""))
    except (TypeError, ValueError):
        return default


def ok(rows):
    return [r for r in rows if r.get("status") == "ok"]


def series_rows(rows, basis, ppc):
    sel = [r for r in ok(rows) if r.get("basis") == basis
           and r.get("points_per_cell_direction") == ppc]
    return sorted(sel, key=lambda r: -num(r, "h"))


def label(basis, ppc):
    return f"{basis}, {ppc}x{ppc} points"


# --------------------------------------------------------------------------
# figures
# --------------------------------------------------------------------------
def guide(ax, x0, y0, xs, slope, text):
    """A line of the given slope through (x0, y0) over the range xs."""
    lo, hi = min(xs), max(xs)
    ax.plot([lo, hi], [y0 * (lo / x0) ** slope, y0 * (hi / x0) ** slope],
            color="0.5", lw=1, ls=":")
    ax.text(lo, y0 * (lo / x0) ** slope, text, color="0.4", fontsize=8, ha="right",
            va="center")


def figure_error_vs_h(rows, out):
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    for basis, ppc in SERIES:
        sel = [r for r in series_rows(rows, basis, ppc) if num(r, "error") > 0]
        if sel:
            ax.loglog([num(r, "h") for r in sel], [num(r, "error") for r in sel],
                      label=label(basis, ppc), **STYLE[(basis, ppc)])
    gimp = [r for r in series_rows(rows, "GIMP", "2") if num(r, "error") > 0]
    if gimp:
        hs = [num(r, "h") for r in gimp]
        h0, e0 = hs[0], num(gimp[0], "error")
        guide(ax, h0, e0 * 1.6, hs, 1, "slope 1 ")
        guide(ax, h0, e0 * 0.35, hs, 2, "slope 2 ")
    ax.set_xlabel("cell size h (m)")
    ax.set_ylabel("error of eq. 13 (vertical stress)")
    ax.set_title("Column under self-weight: error against cell size")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "column_error_vs_h.png"), dpi=120)
    plt.close(fig)


def figure_error_vs_time(rows, out):
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    for basis, ppc in SERIES:
        sel = [r for r in series_rows(rows, basis, ppc) if num(r, "error") > 0]
        if not sel:
            continue
        x = [num(r, "wall_time") for r in sel]
        y = [num(r, "error") for r in sel]
        ax.loglog(x, y, label=label(basis, ppc), **STYLE[(basis, ppc)])
        if (basis, ppc) == ("GIMP", "2"):
            for r, xi, yi in zip(sel, x, y):
                ax.annotate(f"{int(num(r, 'cells'))}", (xi, yi), textcoords="offset points",
                            xytext=(4, 4), fontsize=7, color="C0")
    ax.set_xlabel("wall time of the solve (s, median of repetitions; excludes ~1 s start-up)")
    ax.set_ylabel("error of eq. 13")
    ax.set_title("Column: accuracy against cost (labels: number of cells)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "column_error_vs_time.png"), dpi=120)
    plt.close(fig)


def figure_phases(column, collapse, out):
    panels = []
    if column:
        panels.append(("Column, GIMP", [(r, "2x2" if r["points_per_cell_direction"] == "2" else "3x3")
                                        for r in ok(column) if r.get("basis") == "GIMP"]))
    if collapse:
        panels.append(("Collapse, GIMP", [(r, f"{r['points_per_cell_direction']}x"
                                              f"{r['points_per_cell_direction']}")
                                          for r in ok(collapse)]))
    if not panels:
        return
    fig, axes = plt.subplots(1, len(panels), figsize=(6.2 * len(panels), 4.8), squeeze=False)
    for ax, (title, tagged) in zip(axes[0], panels):
        tags = sorted({t for _, t in tagged})
        for k, phase in enumerate(PHASES + ["total"]):
            col = "wall_time" if phase == "total" else "time_" + phase.replace(" ", "_")
            for j, tag in enumerate(tags):
                sel = sorted([r for r, t in tagged if t == tag and num(r, col) > 0],
                             key=lambda r: num(r, "material_points"))
                if not sel:
                    continue
                ax.loglog([num(r, "material_points") for r in sel], [num(r, col) for r in sel],
                          color="k" if phase == "total" else f"C{k}",
                          ls=["-", "--"][j % 2], marker=["o", "s"][j % 2], ms=4,
                          lw=2 if phase == "total" else 1.2,
                          label=f"{phase} ({tag})")
        ax.set_xlabel("material points")
        ax.set_ylabel("wall time (s, median of repetitions)")
        ax.set_title(title + " (solid/dashed: points per cell)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=6.5, ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "time_per_phase.png"), dpi=120)
    plt.close(fig)


def figure_stress_profile(points, out):
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    basis_key = "Material points/Basis"
    for basis, style in (("GIMP", dict(color="C0", marker="o", ms=4, ls="none")),
                         ("standard MPM", dict(color="C3", marker="x", ms=4, ls="none"))):
        sel = [p for p in points if p.get(basis_key) == basis]
        if not sel:
            continue
        sel.sort(key=lambda p: float(p["Z"]))
        ax.plot([float(p["sigma_vertical"]) / 1e3 for p in sel], [float(p["Z"]) for p in sel],
                label=basis, **style)
    ax.plot([-800 * 50 / 1e3, 0], [0, 50], color="k", lw=1,
            label=r"analytical $\sigma_{zz} = -800\,(50 - Z)$")
    ax.set_xlabel("vertical stress (kPa)")
    ax.set_ylabel("initial height Z (m)")
    ax.set_title("Column, 16 cells (h = 3.125 m), 2x2 points, final state")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "column_stress_h3.125.png"), dpi=120)
    plt.close(fig)


# --------------------------------------------------------------------------
# tables
# --------------------------------------------------------------------------
def g(x, digits=3):
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "–"
    return f"{x:.{digits}g}"


def e(x):
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "–"
    return f"{x:.3e}"


def column_table(rows):
    lines = ["| basis | points per cell | cells | h (m) | points | system DoFs | error (eq. 13) "
             "| rate | Newton iterations | residual evaluations | wall time (s) median / min "
             "| process time (s) | µs per point evaluation | linear solve share | peak memory (MB) |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for basis, ppc in SERIES:
        prev = None
        for r in series_rows(rows, basis, ppc):
            err = num(r, "error")
            rate = (math.log(num(prev, "error") / err) / math.log(num(prev, "h") / num(r, "h"))
                    if prev is not None and err > 0 else float("nan"))
            lines.append(
                f"| {basis} | {ppc}x{ppc} | {int(num(r, 'cells'))} | {g(num(r, 'h'), 4)} "
                f"| {int(num(r, 'material_points'))} | {int(num(r, 'system_dofs_last_step'))} "
                f"| {e(err)} | {'–' if math.isnan(rate) else f'{rate:.2f}'} "
                f"| {int(num(r, 'newton_iterations'))} | {int(num(r, 'residual_evaluations'))} "
                f"| {num(r, 'wall_time'):.3f} / {num(r, 'wall_time_min'):.3f} "
                f"| {num(r, 'process_time'):.2f} "
                f"| {num(r, 'microseconds_per_point_evaluation'):.3f} "
                f"| {num(r, 'linear_solve_share'):.3f} | {num(r, 'peak_memory_mb'):.0f} |")
            prev = r
    failed = [r for r in rows if r.get("status") != "ok"]
    for r in failed:
        lines.append(f"\nFailed: {r['case']}: {r.get('message', '')}")
    return "\n".join(lines)


def timing_table(rows, title, check, prefix):
    out = []
    rows = ok(rows or [])
    by = {r.get("formulation"): r for r in rows}
    pc, ul = by.get("previously converged"), by.get("updated Lagrangian")
    if not rows:
        return out
    out.append(f"{title}:")
    out.append("")
    out.append("| formulation | points | repetitions | assembly (s) median / min "
               "| stress update (s) median | linear solve (s) median "
               "| wall time (s) median / min | Newton iterations | residual evaluations "
               "| µs per point evaluation |")
    out.append("|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        out.append(
            f"| {r['formulation']} | {int(num(r, 'material_points'))} | {r['repetitions']} "
            f"| {num(r, 'time_assembly'):.4f} / {num(r, 'time_assembly_min'):.4f} "
            f"| {num(r, 'time_stress_update'):.4f} | {num(r, 'time_linear_solve'):.4f} "
            f"| {num(r, 'wall_time'):.4f} / {num(r, 'wall_time_min'):.4f} "
            f"| {int(num(r, 'newton_iterations'))} | {int(num(r, 'residual_evaluations'))} "
            f"| {num(r, 'microseconds_per_point_evaluation'):.3f} |")
    if pc and ul:
        ratio = num(ul, "time_assembly") / num(pc, "time_assembly")
        ratio_min = num(ul, "time_assembly_min") / num(pc, "time_assembly_min")
        ws = num(ul, "wall_time") / num(pc, "wall_time")
        check[prefix + "assembly_ratio_median"] = ratio
        check[prefix + "assembly_ratio_min"] = ratio_min
        check[prefix + "wall_ratio_median"] = ws
        if ratio > 1.05 and ratio_min > 1.05:
            verdict = "the previously converged form is faster in the assembly phase"
        elif ratio < 0.95 and ratio_min < 0.95:
            verdict = "the updated Lagrangian form is faster in the assembly phase"
        else:
            verdict = ("no difference beyond the run-to-run scatter (the two ratios straddle "
                       "or lie within 5 % of 1)")
        out.append("")
        out.append(f"Assembly time, updated Lagrangian / previously converged: **{ratio:.2f}** "
                   f"(medians of {pc['repetitions']} repetitions), {ratio_min:.2f} (minima): "
                   f"{verdict}. Whole solve (wall time, medians): {ws:.2f}.")
        if pc.get("time_assembly_all"):
            out.append(f"Assembly times of the repetitions (s): previously converged "
                       f"{pc['time_assembly_all']}; updated Lagrangian {ul['time_assembly_all']}.")
    out.append("")
    return out


def formulation_table(rows, rows_collapse, points, runs_dir):
    out = []
    check = {}
    out += timing_table(rows, "Column, 64 cells, 2x2 points, GIMP", check, "column_")
    out += timing_table(rows_collapse, "Collapse, h = 0.5 m, 6x6 points, GIMP (no condition "
                        "estimate, no point files)", check, "collapse_")
    if points:
        key = "Solver/Formulation"
        a = {p["id"]: p for p in points if p.get(key) == "previously converged"}
        b = {p["id"]: p for p in points if p.get(key) == "updated Lagrangian"}
        common = sorted(set(a) & set(b), key=int)
        fields = [f for f in points[0].keys() if f.startswith("sigma")]
        # stress scale: the largest printed stress magnitude of either run
        scale = max(abs(float(p[f])) for p in points for f in fields if p.get(f))
        max_abs = 0.0
        identical = 0
        compared = 0
        for i in common:
            for f in fields:
                if not a[i].get(f) or not b[i].get(f):
                    continue
                max_abs = max(max_abs, abs(float(a[i][f]) - float(b[i][f])))
                identical += a[i][f] == b[i][f]
                compared += 1
        max_rel = max_abs / scale
        # Significant digits of the printout: those of a printed stress.
        mantissa = str(points[0][fields[0]]).lower().split("e")[0].lstrip("-")
        digits = len(mantissa.replace(".", "").lstrip("0")) or 1
        check.update(points_compared=len(common), points_only_in_one=len(set(a) ^ set(b)),
                     stress_fields=" ".join(fields), values_compared=compared,
                     printed_identical=identical, stress_scale_pa=scale,
                     max_abs_difference_pa=max_abs,
                     max_difference_relative_to_scale=max_rel)
        out.append("Equality check (one more run of each with the Testing printout):")
        out.append("")
        out.append(
            f"Final stresses of every point (Testing printout: {', '.join(fields)}; "
            f"{len(common)} points, {len(set(a) ^ set(b))} in one run only): {identical} of "
            f"{compared} printed values are identical; the largest difference is "
            f"{max_abs:.1e} Pa, {max_rel:.1e} of the largest stress ({scale:.4g} Pa)"
            + (" (the printed values that differ are round-off noise of an otherwise zero "
               "stress)" if 0 < max_rel < 1e-10 else "") + ". "
            + ("**Equal to 1e-10 relative to the stress scale**" if max_rel <= 1e-10
               else "**NOT equal to 1e-10**")
            + (f" (printed with {digits} significant digits)." if digits >= 12 else
               f", with the caveat that the printout has {digits} significant digits: a "
               f"difference below about 1e-{digits} of a printed value cannot show in it."))
    if runs_dir:
        steps = {}
        for meta in glob.glob(os.path.join(runs_dir, "*", "study_case.json")):
            info = json.load(open(meta))
            f = info["sets"].get("Solver/Formulation")
            path = os.path.join(os.path.dirname(meta), "steps.csv")
            if f and os.path.exists(path):
                steps[f] = read(path)
        if "previously converged" in steps and "updated Lagrangian" in steps:
            sa, sb = steps["previously converged"], steps["updated Lagrangian"]
            max_rel = 0.0
            max_abs_e = 0.0
            same_iterations = len(sa) == len(sb)
            for ra, rb in zip(sa, sb):
                same_iterations &= ra["newton_iterations"] == rb["newton_iterations"]
                ea, eb = float(ra["error_sigma_zz"]), float(rb["error_sigma_zz"])
                max_rel = max(max_rel, abs(ea - eb) / max(abs(ea), 1e-300))
                max_abs_e = max(max_abs_e, abs(ea - eb))
            check.update(steps_compared=min(len(sa), len(sb)),
                         same_newton_iterations_every_step=same_iterations,
                         max_relative_difference_error_sigma_zz=max_rel,
                         max_difference_error_sigma_zz=max_abs_e)
            out.append("")
            # The error is |sigma - sigma_a| / |sigma_a|: the difference of two
            # errors is a difference of stresses relative to |sigma_a| (a lower
            # bound of it), while the difference relative to the error itself
            # magnifies round-off by 1 / error.
            out.append(
                f"The error of eq. 13 after each of the {min(len(sa), len(sb))} steps "
                f"(steps.csv, 10 significant digits, |sigma - sigma_a| / |sigma_a| over all "
                f"points): the two runs' errors differ by at most {max_abs_e:.1e} (a stress "
                f"difference relative to |sigma_a|; "
                f"{'within' if max_abs_e <= 1e-10 else 'NOT within'} 1e-10), "
                f"{max_rel:.1e} relative to the error itself (which magnifies round-off by "
                f"1 / error); Newton iterations per step "
                f"{'identical' if same_iterations else 'DIFFERENT'}.")
    return "\n".join(out), check


def collapse_table(rows):
    lines = ["| h (m) | points per cell | points | system DoFs (last step) | load steps "
             "taken (nominal) | Newton iterations | cuts | wall time (s) | process time (s) "
             "| µs per point evaluation | linear solve share | max tensile vertical stress (kPa) "
             "| runout (m) | drop (m) | difference to h = 0.25 m | worst condition estimate |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in sorted(ok(rows), key=lambda r: (r["points_per_cell_direction"], -num(r, "h"))):
        n = r["points_per_cell_direction"]
        lines.append(
            f"| {g(num(r, 'h'))} | {n}x{n} | {int(num(r, 'material_points'))} "
            f"| {int(num(r, 'system_dofs_last_step'))} "
            f"| {g(num(r, 'steps_accepted'))} ({int(num(r, 'load_steps'))}) "
            f"| {int(num(r, 'newton_iterations'))} | {int(num(r, 'load_step_cuts'))} "
            f"| {num(r, 'wall_time'):.2f} | {num(r, 'process_time'):.2f} "
            f"| {num(r, 'microseconds_per_point_evaluation'):.3f} "
            f"| {num(r, 'linear_solve_share'):.3f} "
            f"| {num(r, 'max_tensile_vertical_stress') / 1e3:.1f} "
            f"| {num(r, 'runout'):.3f} | {num(r, 'drop'):.3f} "
            f"| {'reference' if r.get('reference') == 'yes' else e(num(r, 'error'))} "
            f"| {g(num(r, 'worst_condition_estimate'))} |")
    for r in rows:
        if r.get("status") != "ok":
            lines.append(f"\nFailed: {r['case']}: {r.get('message', '')}")
    return "\n".join(lines)


def outside(r, present):
    """Wall time not in any timed phase (medians, so approximate)."""
    return num(r, "wall_time") - sum(max(num(r, "time_" + p.replace(" ", "_")), 0.0)
                                     for p in present
                                     if not math.isnan(num(r, "time_" + p.replace(" ", "_"))))


def phases_table(rows, scene):
    present = [p for p in PHASES if any(num(r, "time_" + p.replace(" ", "_")) > 0 for r in ok(rows))]
    lines = ["| run | points | " + " | ".join(present) + " | outside the phases | total |",
             "|---|---|" + "---|" * (len(present) + 2)]
    for r in ok(rows):
        if scene == "column":
            if r.get("basis") != "GIMP":
                continue
            name = f"{int(num(r, 'cells'))} cells, {r['points_per_cell_direction']}x" \
                   f"{r['points_per_cell_direction']}"
        else:
            name = f"h = {g(num(r, 'h'))} m, {r['points_per_cell_direction']}x" \
                   f"{r['points_per_cell_direction']}"
        lines.append(f"| {name} | {int(num(r, 'material_points'))} | "
                     + " | ".join(f"{num(r, 'time_' + p.replace(' ', '_')):.4f}" for p in present)
                     + f" | {outside(r, present):.4f} | {num(r, 'wall_time'):.4f} |")
    return "\n".join(lines)


def replace_block(text, name, content):
    """The text with the block NAME replaced, and whether it had one."""
    pattern = re.compile(r"(<!-- BEGIN %s -->\n).*?(<!-- END %s -->)" % (name, name), re.S)
    if not pattern.search(text):
        return text, False
    return pattern.sub(lambda m: m.group(1) + content.rstrip() + "\n" + m.group(2), text), True


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--data", default=os.path.join(ROOT, "doc", "benchmarks"))
    parser.add_argument("--formulation-runs")
    parser.add_argument("--page", "--readme", dest="pages", action="append", default=[],
                        help="a Markdown page whose BEGIN/END blocks get the tables "
                             "(repeatable)")
    args = parser.parse_args()
    d = args.data

    column = read(os.path.join(d, "column.csv"))
    points16 = read(os.path.join(d, "column_points_16.csv"))
    formulation = read(os.path.join(d, "formulation.csv"))
    fpoints = read(os.path.join(d, "formulation_points.csv"))
    collapse = read(os.path.join(d, "collapse.csv"))

    if column:
        figure_error_vs_h(column, d)
        figure_error_vs_time(column, d)
    if column or collapse:
        figure_phases(column, collapse, d)
    if points16:
        figure_stress_profile(points16, d)
    blocks = {}
    if column:
        blocks["column-table"] = column_table(column)
        blocks["column-phases"] = phases_table(column, "column")
    if formulation or fpoints:
        text, check = formulation_table(formulation, read(os.path.join(d, "formulation_collapse.csv")),
                                        fpoints, args.formulation_runs)
        blocks["formulation-table"] = text
        with open(os.path.join(d, "formulation_check.csv"), "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["quantity", "value"])
            for k, v in check.items():
                w.writerow([k, v])
    if collapse:
        blocks["collapse-table"] = collapse_table(collapse)
        blocks["collapse-phases"] = phases_table(collapse, "collapse")
    kernels = os.path.join(d, "formulation_kernels.md")
    if os.path.exists(kernels):
        # The first table of build/impm-formulation-kernels, as it printed it
        # (the second, the point stiffness kernel, stays in formulation_kernels.md).
        table = []
        for line in open(kernels):
            if line.startswith("|"):
                table.append(line.rstrip())
            elif table:
                break
        blocks["formulation-kernels"] = "\n".join(table)
    machine = os.path.join(d, "machine.txt")
    if os.path.exists(machine):
        blocks["machine"] = "```\n" + open(machine).read().rstrip() + "\n```"
    for name, content in blocks.items():
        print(f"--- {name} ---\n{content}\n")
    written = set()
    for page in args.pages:
        if not os.path.exists(page):
            print(f"plot_study.py: no page {page}; skipped", file=sys.stderr)
            continue
        text = open(page).read()
        found = []
        for name, content in blocks.items():
            text, had = replace_block(text, name, content)
            if had:
                found.append(name)
        with open(page, "w") as f:
            f.write(text)
        written.update(found)
        print(f"plot_study.py: updated {page} ({', '.join(found) or 'no blocks'})",
              file=sys.stderr)
    if args.pages:
        for name in blocks:
            if name not in written:
                print(f"plot_study.py: no block {name} in the pages; skipped", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
