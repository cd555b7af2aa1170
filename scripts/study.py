#!/usr/bin/python3
"""Parameter study driver for IMPM: what accuracy costs in time.

Runs `impm SCENE` for the cartesian product of the values given with
--set "Subsection/Entry=v1|v2|..." (a --set without '|' is fixed for all
runs), each run in its own temporary output directory, and writes one CSV row
per run with the varied parameters, the error, the wall time and the time of
every phase (median over --repeat repetitions, and the minimum), Newton
iterations, residual evaluations, points, DoFs, peak memory, the cost per
point evaluation and the share of the linear solve.

Linked values (varied together, not crossed) are given with
  --linked "A=a1|a2|a3" "B=b1|b2|b3"      (one group per --linked)
and, for the column scene, with the convenience
  --column-cells 4,8,16                   (N cells of width 50/N: sets
                                           Grid/Number of cells=1, N,
                                           Grid/Upper corner=50/N, 50 and
                                           Body 1/Upper corner=50/N, 50;
                                           'Body' for scenes of the older
                                           format with one unnumbered body).
A --set of 'Body/Entry' on a scene with numbered bodies means 'Body 1/Entry'.

The error column:
  * `error_sigma_zz` of summary.json (eq. 13 of the paper) when the run has it
    (scenes with `Output/Analytical solution = column`);
  * otherwise, with --reference-finest, the difference to the finest run (the
    smallest cell size h) among the runs that share every other varied
    parameter.  The compared quantity is d = (runout, drop) of the final
    points: runout = largest final x of the points minus their largest initial
    x (how far the toe moves out), drop = minus the vertical displacement of
    the point that starts nearest the top of the left edge of the body (the
    top of the symmetry line of the collapse).  error = |d - d_ref| / |d_ref|
    (Euclidean norms).  The final points are read from the last point file
    (points.pvd) when the run writes point files (Output/Interval > 0, which
    this option then requires), with Python's vtk module.  runout and drop are
    written as columns too.  The reference run gets error 0 and
    reference = yes.

Also from the run's steps.csv: steps_accepted and steps_rejected (load steps
taken, and steps restarted with a smaller increment; summary.json's
load_steps is the nominal number).

Other options:
  --repeat N       run every case N times; times are the median (columns
                   without suffix) and the minimum (suffix _min) of the N
                   runs, and all N values (suffix _all, space separated);
                   counts (Newton iterations, ...) must agree between
                   repetitions (a warning is printed if not).
  --interleave     run the first repetition of every case, then the second,
                   ... (instead of all repetitions of a case in a row), so
                   that a slow drift of the machine affects all cases alike.
  --keep DIR       keep the output directory of every case's first repetition
                   as DIR/<case label>/ (with impm's stdout.txt and stderr.txt,
                   and study_case.json: the --set values, h and the points per
                   cell direction of the case).
  --points-out F   run with the Testing printout of every point
                   (Testing/Enabled=true, Testing/Printed points=100000) and
                   write all final points of all cases to the CSV file F
                   (case, the varied parameters, id, X, Z, ux, uz,
                   sigma_vertical and any further printed field, e.g.
                   sigma_xx; as printed: 6 significant digits).
  --impm PATH      the executable (default: build/impm beside this script's
                   repository).

A run that fails (non-zero exit or no summary.json) is reported on stderr with
the tail of impm's stderr and stdout; its row has status = failed and the
message; the other runs go on.  The exit status is 1 if any run failed.

Example (column, 3 resolutions x 2 bases):
  scripts/study.py prm/column_compaction.prm --column-cells 4,8,16 \\
      --set "Material points/Basis=GIMP|standard MPM" \\
      --set Output/Interval=0 --repeat 3 --out column.csv
"""

import argparse
import csv
import itertools
import json
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

PHASES = [
    "basis evaluation",
    "system setup",
    "stress update",
    "assembly",
    "linear solve",
    "point update",
    "output",
]

# Summary entries copied to the CSV as they are (taken from the first
# repetition; they do not depend on timing).
COUNTS = [
    "material_points",
    "grid_dofs",
    "system_dofs_last_step",
    "load_steps",
    "newton_iterations",
    "residual_evaluations",
    "load_step_cuts",
    "largest_point_increment_in_cells",
    "max_reaction_imbalance",
    "max_tensile_vertical_stress",
    "total_mass",
    "worst_condition_estimate",
    "error_sigma_zz",
]
# Summary entries that depend on timing: median and minimum over repetitions.
TIMED = ["wall_time", "microseconds_per_point_evaluation", "linear_solve_share"]


def phase_column(phase):
    return "time_" + phase.replace(" ", "_")


def parse_spec(spec):
    if "=" not in spec:
        raise SystemExit(f"study.py: --set '{spec}' is not of the form Subsection/Entry=value")
    name, value = spec.split("=", 1)
    return name.strip(), value.split("|")


def read_prm(path):
    """Entries of a deal.II parameter file as {'Sub/Entry': value}."""
    values = {}
    stack = []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if not line:
                continue
            m = re.match(r"subsection\s+(.*)$", line)
            if m:
                stack.append(m.group(1).strip())
                continue
            if line == "end":
                if stack:
                    stack.pop()
                continue
            m = re.match(r"set\s+([^=]*?)\s*=\s*(.*)$", line)
            if m:
                values["/".join(stack + [m.group(1).strip()])] = m.group(2).strip()
    return values


def body_section(base):
    """'Body 1' for scenes with numbered bodies, else 'Body'."""
    if any(k.startswith("Body/") for k in base):
        return "Body"
    return "Body 1"


def translate(name, base):
    """Accept 'Body/Entry' for the first body of a scene with numbered bodies
    ('Body 1/Entry'), so that older commands keep working."""
    if name.startswith("Body/") and body_section(base) == "Body 1":
        return "Body 1/" + name[len("Body/"):]
    return name


def numbers(text):
    return [float(v) for v in text.split(",") if v.strip()]


def cell_size(params):
    """Smallest cell size of the grid given the resolved parameters."""
    try:
        lower = numbers(params.get("Grid/Lower corner", "0, 0"))
        upper = numbers(params["Grid/Upper corner"])
        cells = numbers(params["Grid/Number of cells"])
        return min((u - l) / c for l, u, c in zip(lower, upper, cells))
    except (KeyError, ValueError, ZeroDivisionError):
        return float("nan")


def label_of(index, varied):
    parts = [f"{index:03d}"]
    for name, value in varied:
        short = name.split("/")[-1]
        parts.append(f"{short}-{value}")
    label = "_".join(parts).replace(", ", "x")
    return re.sub(r"[^A-Za-z0-9_.x-]+", "", label.replace(" ", ""))


def tail(text, lines=15):
    return "\n".join(text.rstrip().splitlines()[-lines:])


POINT_LINE = re.compile(r"^point\s+(\d+):\s*(.*)$")
POINT_FIELD = re.compile(r"([A-Za-z_]\w*)\s*=\s*(.*?)\s*(?=,\s*[A-Za-z_]\w*\s*=|$)")


def parse_points(stdout):
    """The Testing printout's point lines, 'point ID: X = x y, u = ux uy,
    sigma_vertical = s[, name = v ...]', as (id, {name: [values]})."""
    points = []
    for line in stdout.splitlines():
        m = POINT_LINE.match(line.strip())
        if m:
            fields = {k: v.split() for k, v in POINT_FIELD.findall(m.group(2))}
            if "X" in fields and "sigma_vertical" in fields:
                points.append((int(m.group(1)), fields))
    return points


def final_point_file(output_dir):
    """Path of the last .pvtu listed in points.pvd, or None."""
    pvd = os.path.join(output_dir, "points.pvd")
    if not os.path.exists(pvd):
        return None
    files = re.findall(r'file="([^"]+)"', open(pvd).read())
    return os.path.join(output_dir, files[-1]) if files else None


def runout_and_drop(pvtu):
    """(runout, drop) of the final points; see the module documentation."""
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy

    reader = vtk.vtkXMLPUnstructuredGridReader()
    reader.SetFileName(pvtu)
    reader.Update()
    data = reader.GetOutput()
    x = vtk_to_numpy(data.GetPoints().GetData())
    pd = data.GetPointData()
    u = vtk_to_numpy(pd.GetArray("displacement"))
    X = vtk_to_numpy(pd.GetArray("initial_position"))
    runout = float(x[:, 0].max() - X[:, 0].max())
    # the point starting nearest the body's top-left corner
    corner = (X[:, 0].min(), X[:, 1].max())
    k = int(((X[:, 0] - corner[0]) ** 2 + (X[:, 1] - corner[1]) ** 2).argmin())
    drop = float(-u[k, 1])
    return runout, drop


def run_once(impm, scene, sets, workdir, testing):
    out = os.path.join(workdir, "output")
    cmd = [impm, scene, "--set", f"Output directory={out}"]
    for name, value in sets:
        cmd += ["--set", f"{name}={value}"]
    if testing:
        cmd += ["--set", "Testing/Enabled=true", "--set", "Testing/Printed points=100000"]
    start = time.perf_counter()
    proc = subprocess.run(cmd, cwd=workdir, capture_output=True, text=True)
    elapsed = time.perf_counter() - start
    summary = None
    path = os.path.join(out, "summary.json")
    if proc.returncode == 0 and os.path.exists(path):
        with open(path) as f:
            summary = json.load(f)
    return cmd, proc, elapsed, summary, out


def main():
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scene")
    parser.add_argument("--set", action="append", default=[], metavar="A/B=v1|v2",
                        help="a parameter and its values (crossed with the others)")
    parser.add_argument("--linked", action="append", nargs="+", default=[],
                        metavar="A/B=v1|v2",
                        help="parameters whose values go together (zipped, not crossed)")
    parser.add_argument("--column-cells", metavar="N1,N2,...",
                        help="column refinement: N cells of width 50/N (square cells)")
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--interleave", action="store_true",
                        help="run repetition k of every case before repetition k+1")
    parser.add_argument("--reference-finest", action="store_true")
    parser.add_argument("--out", required=True)
    parser.add_argument("--impm", default=os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "build", "impm"))
    parser.add_argument("--keep", metavar="DIR")
    parser.add_argument("--points-out", metavar="FILE")
    args = parser.parse_args()

    impm = os.path.abspath(args.impm)
    scene = os.path.abspath(args.scene)
    if not os.access(impm, os.X_OK):
        raise SystemExit(f"study.py: no executable impm at {impm}")
    if not os.path.exists(scene):
        raise SystemExit(f"study.py: no scene file {scene}")
    if args.repeat < 1:
        raise SystemExit("study.py: --repeat must be >= 1")

    base = read_prm(scene)
    body = body_section(base)

    # Factors of the cartesian product: each is a list of names and a list of
    # value tuples (one tuple per level).
    factors = []
    fixed = []
    for spec in args.set:
        name, values = parse_spec(spec)
        name = translate(name, base)
        if len(values) == 1:
            fixed.append((name, values[0]))
        else:
            factors.append(([name], [(v,) for v in values]))
    groups = list(args.linked)
    if args.column_cells:
        cells = [int(c) for c in args.column_cells.split(",") if c.strip()]
        widths = [repr(50.0 / c) for c in cells]
        groups.append([
            "Grid/Number of cells=" + "|".join(f"1, {c}" for c in cells),
            "Grid/Upper corner=" + "|".join(f"{w}, 50" for w in widths),
            f"{body}/Upper corner=" + "|".join(f"{w}, 50" for w in widths),
        ])
    for group in groups:
        parsed = [(translate(n, base), v) for n, v in (parse_spec(s) for s in group)]
        lengths = {len(v) for _, v in parsed}
        if len(lengths) != 1:
            raise SystemExit(f"study.py: linked values of unequal count: {group}")
        factors.append(([n for n, _ in parsed], list(zip(*[v for _, v in parsed]))))

    varied_names = [n for names, _ in factors for n in names]
    # parameters that set the resolution: grid entries and whatever is linked
    # to them; the others define the groups of --reference-finest
    resolution = set()
    for names, _ in factors:
        if any(n.startswith("Grid/") for n in names):
            resolution.update(names)

    if args.reference_finest:
        interval = dict(fixed).get("Output/Interval", base.get("Output/Interval", "1"))
        if "Output/Interval" in varied_names or float(interval) <= 0:
            print("study.py: note: --reference-finest uses error_sigma_zz where present, "
                  "else needs point files (Output/Interval > 0)", file=sys.stderr)

    cases = list(itertools.product(*[levels for _, levels in factors])) if factors else [()]
    print(f"study.py: {len(cases)} case(s) x {args.repeat} repetition(s) of {scene}",
          file=sys.stderr)

    point_rows = []
    point_extra = []  # printed fields besides X and u, in order of appearance
    study_start = time.perf_counter()

    # every case: its --set values and the row it will fill
    jobs = []
    for index, levels in enumerate(cases):
        varied = []
        for (names, _), level in zip(factors, levels):
            varied += list(zip(names, level))
        sets = fixed + varied
        params = dict(base)
        params.update(dict(sets))
        label = label_of(index, [(n, v) for n, v in varied
                                 if not (n.endswith("Upper corner")
                                         and "Grid/Number of cells" in varied_names)])
        row = {name: value for name, value in varied}
        row["case"] = label
        if args.column_cells:
            row["cells"] = numbers(params["Grid/Number of cells"])[-1]
        row["h"] = cell_size(params)
        row["points_per_cell_direction"] = params.get(f"{body}/Points per cell direction", "")
        row["repetitions"] = args.repeat
        jobs.append(dict(label=label, varied=varied, sets=sets, row=row,
                         summaries=[], elapsed=[], failure=None))

    # run order: all repetitions of a case in a row, or (--interleave) one
    # repetition of every case after the other
    if args.interleave:
        order = [(rep, job) for rep in range(args.repeat) for job in jobs]
    else:
        order = [(rep, job) for job in jobs for rep in range(args.repeat)]

    def keep(job, proc, out):
        dest = os.path.join(args.keep, job["label"])
        shutil.rmtree(dest, ignore_errors=True)
        if os.path.isdir(out):
            shutil.copytree(out, dest)
        os.makedirs(dest, exist_ok=True)
        open(os.path.join(dest, "stdout.txt"), "w").write(proc.stdout)
        open(os.path.join(dest, "stderr.txt"), "w").write(proc.stderr)
        with open(os.path.join(dest, "study_case.json"), "w") as f:
            json.dump({"case": job["label"], "scene": scene, "sets": dict(job["sets"]),
                       "h": job["row"]["h"],
                       "points_per_cell_direction": job["row"]["points_per_cell_direction"]},
                      f, indent=1)

    for rep, job in order:
        if job["failure"]:
            continue
        label, row, varied = job["label"], job["row"], job["varied"]
        with tempfile.TemporaryDirectory(prefix="impm_study_") as work:
            cmd, proc, seconds, summary, out = run_once(
                impm, scene, job["sets"], work, args.points_out is not None)
            if summary is None:
                failure = (f"exit code {proc.returncode}" if proc.returncode
                           else "no summary.json written")
                print(f"study.py: run {label} (repetition {rep + 1}) FAILED: {failure}\n"
                      f"  command: {' '.join(repr(c) if ' ' in c else c for c in cmd)}\n"
                      f"  --- stderr (tail) ---\n{tail(proc.stderr)}\n"
                      f"  --- stdout (tail) ---\n{tail(proc.stdout, 8)}",
                      file=sys.stderr)
                last = (proc.stderr.strip() or proc.stdout.strip() or failure).splitlines()
                job["failure"] = failure + ": " + " ".join(l.strip() for l in last[-3:])[:300]
                if args.keep:
                    keep(job, proc, out)
                continue
            job["summaries"].append(summary)
            job["elapsed"].append(seconds)
            if rep == 0:
                steps_csv = os.path.join(out, "steps.csv")
                if os.path.exists(steps_csv):
                    with open(steps_csv) as f:
                        flags = [r.get("converged") for r in csv.DictReader(f)]
                    row["steps_accepted"] = sum(1 for c in flags if c == "1")
                    row["steps_rejected"] = sum(1 for c in flags if c == "0")
                if args.reference_finest and "error_sigma_zz" not in summary:
                    pvtu = final_point_file(out)
                    if pvtu:
                        row["runout"], row["drop"] = runout_and_drop(pvtu)
                if args.points_out:
                    for pid, fields in parse_points(proc.stdout):
                        prow = {name: value for name, value in varied}
                        X, u = fields.pop("X"), fields.pop("u", ["", ""])
                        prow.update(case=label, id=pid, X=X[0], Z=X[-1], ux=u[0], uz=u[-1])
                        for key, values in fields.items():
                            prow[key] = values[0] if len(values) == 1 else " ".join(values)
                            if key not in point_extra:
                                point_extra.append(key)
                        point_rows.append(prow)
                if args.keep:
                    keep(job, proc, out)
            print(f"study.py: {label} (repetition {rep + 1}): points "
                  f"{summary.get('material_points')}, error "
                  f"{summary.get('error_sigma_zz', '-')}, wall time "
                  f"{summary.get('wall_time', float('nan')):.3f} s, Newton "
                  f"{summary.get('newton_iterations')}", file=sys.stderr)

    rows = []
    n_failed = 0
    for job in jobs:
        row, summaries, elapsed, label = job["row"], job["summaries"], job["elapsed"], job["label"]
        if job["failure"]:
            n_failed += 1
            row["status"] = "failed"
            row["message"] = job["failure"]
            rows.append(row)
            continue
        first = summaries[0]
        row["status"] = "ok"
        row["basis"] = first.get("basis", "")
        row["formulation"] = first.get("formulation", "")
        for key in COUNTS:
            if key in first:
                row[key] = first[key]
        for key in ("newton_iterations", "residual_evaluations", "load_step_cuts"):
            seen = {s.get(key) for s in summaries}
            if len(seen) > 1:
                print(f"study.py: warning: {label}: {key} differs between repetitions: "
                      f"{sorted(seen)}", file=sys.stderr)
        if "error_sigma_zz" in first:
            row["error"] = first["error_sigma_zz"]
            row["error_kind"] = "error_sigma_zz"

        def put(column, values):
            if values:
                row[column] = statistics.median(values)
                row[column + "_min"] = min(values)
                if len(values) > 1:
                    row[column + "_all"] = " ".join(f"{v:.6g}" for v in values)

        for key in TIMED:
            put(key, [s[key] for s in summaries if key in s])
        row["peak_memory_mb"] = max(s.get("peak_memory_mb", float("nan")) for s in summaries)
        put("process_time", elapsed)
        for phase in PHASES:
            values = [s.get("wall_time_per_phase", {}).get(phase) for s in summaries]
            put(phase_column(phase), [v for v in values if v is not None])
        rows.append(row)

    if args.reference_finest:
        groups = {}
        for row in rows:
            if row["status"] != "ok" or "error" in row:
                continue
            key = tuple(row.get(n) for n in varied_names if n not in resolution)
            groups.setdefault(key, []).append(row)
        for members in groups.values():
            usable = [r for r in members if "runout" in r]
            if not usable:
                print("study.py: warning: --reference-finest: no point files to compare "
                      "(set Output/Interval > 0)", file=sys.stderr)
                continue
            ref = min(usable, key=lambda r: r["h"])
            norm = math.hypot(ref["runout"], ref["drop"])
            for r in usable:
                r["error"] = math.hypot(r["runout"] - ref["runout"], r["drop"] - ref["drop"]) / norm
                r["error_kind"] = "(runout, drop) relative to finest h"
                r["reference"] = "yes" if r is ref else "no"

    # columns: varied parameters first, then the rest in a fixed order
    columns = ["case", "status"] + varied_names + [
        "cells", "h", "points_per_cell_direction", "basis", "formulation", "repetitions",
        "error", "error_kind", "reference", "runout", "drop"]
    for key in ["wall_time", "process_time"] + [phase_column(p) for p in PHASES] + [
            "microseconds_per_point_evaluation", "linear_solve_share"]:
        columns += [key, key + "_min"]
    columns += ["peak_memory_mb"]
    columns += [c for c in COUNTS if c not in columns] + ["steps_accepted", "steps_rejected"]
    for key in ["wall_time", "process_time"] + [phase_column(p) for p in PHASES] + [
            "microseconds_per_point_evaluation", "linear_solve_share"]:
        columns += [key + "_all"]
    columns += ["message"]
    present = set().union(*[r.keys() for r in rows]) if rows else set()
    columns = [c for c in columns if c in present or c in ("case", "status", "error")]

    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    with open(args.out, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=columns, extrasaction="ignore")
        writer.writeheader()
        for row in rows:
            writer.writerow(row)
    if args.points_out:
        pcols = ["case"] + varied_names + ["id", "X", "Z", "ux", "uz"] + point_extra
        with open(args.points_out, "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=pcols, extrasaction="ignore")
            writer.writeheader()
            for prow in point_rows:
                writer.writerow(prow)
    print(f"study.py: wrote {args.out} ({len(rows)} rows, {n_failed} failed) in "
          f"{time.perf_counter() - study_start:.1f} s", file=sys.stderr)
    return 1 if n_failed else 0


if __name__ == "__main__":
    sys.exit(main())
