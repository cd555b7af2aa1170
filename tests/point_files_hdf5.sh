#!/usr/bin/env bash
# 'Output/Format = hdf5': the collapse_h1_4steps scene writes its points into
# one .h5 file per load step (all processes into one file) and the
# points.xdmf series. Read back with h5py and the XDMF's XML, checked
# against what the run prints by another route:
#  * the series has one entry per accepted load step plus the initial
#    state, at the load factors of steps.csv, each naming an existing file;
#  * no *.tmp file is left;
#  * every file holds all material points, and nodes = initial_position +
#    displacement to single precision (deal.II 9.4's HDF5 writer stores the
#    positions in double, the fields in single precision);
#  * in the last file, the extents of the points equal the test summary's
#    "extent in x/y" line, and the three printed points (found by their
#    initial position) have the printed displacement and vertical stress
#    (scaled by the scene's reference stress, 20 kPa) to the printed digits
#    (1e-6), within single precision (2e-6 absolute here);
#  * on two processes, the rank field holds both ranks;
#  * a write that fails past the size check (a directory in the way of the
#    temporary file) stops the run with one line and HDF5's reason, not
#    HDF5's error stack (the end of this script).
# Usage: point_files_hdf5.sh IMPM SCENE [MPIEXEC N]
scene=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
"${launcher[@]}" "$impm" "$scene" --set "Output/Format=hdf5" \
  --set "Output/Interval=1" --set "Output directory=out" > log.txt 2>&1 ||
  fail "the run failed"
ls out/*.tmp > /dev/null 2>&1 && fail "temporary files left: $(ls out/*.tmp)"
/usr/bin/python3 - "${4:-1}" <<'PY' || fail "see above"
import csv, re, sys
import xml.etree.ElementTree as ET
import h5py, numpy as np
processes = int(sys.argv[1])
problems = []
steps = [s for s in csv.DictReader(open("out/steps.csv")) if s["converged"] == "1"]
grids = ET.parse("out/points.xdmf").getroot().findall(".//Grid[@GridType='Uniform']")
times = [float(g.find("Time").get("Value")) for g in grids]
expected = [0.0] + [float(s["load_factor"]) for s in steps]
if len(times) != len(expected) or max(abs(a - b) for a, b in zip(times, expected)) > 1e-12:
    problems.append("series times %s, load factors %s" % (times, expected))
log = open("log.txt").read()
n_points = int(re.search(r"material points: (\d+)", log).group(1))
files = [g.find("Geometry/DataItem").text.strip().split(":")[0] for g in grids]
for name in files:
    with h5py.File("out/" + name, "r") as f:
        nodes = f["nodes"][:]
        if nodes.shape[0] != n_points:
            problems.append("%s: %d points, not %d" % (name, nodes.shape[0], n_points))
        moved = f["initial_position"][:, :2] + f["displacement"][:, :2]
        if np.abs(moved - nodes[:, :2]).max() > 1e-6 * max(1, np.abs(nodes).max()):
            problems.append("%s: nodes differ from initial position + displacement" % name)
with h5py.File("out/" + files[-1], "r") as f:
    nodes, X, u = f["nodes"][:], f["initial_position"][:], f["displacement"][:]
    stress_yy, rank = f["stress_yy"][:].ravel(), f["rank"][:].ravel()
for d, axis in enumerate("xy"):
    printed = re.search(r"extent in %s: .*final \[([-\d.]+), ([-\d.]+)\]" % axis, log)
    low, high = float(printed.group(1)), float(printed.group(2))
    if abs(nodes[:, d].min() - low) > 1e-6 or abs(nodes[:, d].max() - high) > 1e-6:
        problems.append("extent in %s: file [%g, %g], printed [%g, %g]"
                        % (axis, nodes[:, d].min(), nodes[:, d].max(), low, high))
for line in re.findall(r"point \d+: X = .*", log):
    x0, y0, ux, uy, syy = map(float, re.search(
        r"X = (\S+) (\S+), u = (\S+) (\S+), sigma_vertical = (\S+),", line).groups())
    match = np.where(np.abs(X[:, 0] - x0) + np.abs(X[:, 1] - y0) < 2e-6)[0]
    if len(match) != 1:
        problems.append("printed point %s not found once" % line)
        continue
    p = match[0]
    if (abs(u[p, 0] - ux) > 2e-6 or abs(u[p, 1] - uy) > 2e-6 or
            abs(stress_yy[p] / 2e4 - syy) > 2e-6):
        problems.append("point at %s: file u = %s, sigma_yy = %g; printed %s"
                        % (X[p, :2], u[p, :2], stress_yy[p] / 2e4, line))
if sorted(set(rank.astype(int))) != list(range(processes)):
    problems.append("ranks in the file: %s" % sorted(set(rank)))
for problem in problems:
    print(problem)
print("%d files, %d points each, checked" % (len(files), n_points))
sys.exit(1 if problems else 0)
PY
# A write that fails past the size check: a directory of the user's (with a
# file in it) in the way of step 2's temporary file, written into with
# --overwrite (which keeps what IMPM did not write). The run must stop with
# a non-zero exit and IMPM's one line naming the file and HDF5's reason,
# without HDF5's own error stack; the files of steps 0 and 1 stay whole.
mkdir -p blocked/points_00002.h5.tmp && : > blocked/points_00002.h5.tmp/a_file
"${launcher[@]}" "$impm" "$scene" --set "Output/Format=hdf5" --overwrite \
  --set "Output/Interval=1" --set "Output directory=blocked" > blocked.txt 2>&1 &&
  { cp blocked.txt log.txt; fail "the blocked HDF5 write did not stop the run"; }
[ "$(grep -c '^Error: ' blocked.txt)" = 1 ] &&
  grep -q "^Error: Writing the file blocked/points_00002.h5 failed (HDF5: H5Fcreate(): unable to create file; .*)\.$" blocked.txt ||
  { cp blocked.txt log.txt; fail "the blocked HDF5 write was not reported in IMPM's one line"; }
grep -q "HDF5-DIAG\|#000:" blocked.txt && { cp blocked.txt log.txt; fail "HDF5 printed its error stack"; }
/usr/bin/python3 -c "
import h5py
for k in (0, 1):
    with h5py.File('blocked/points_%05d.h5' % k, 'r') as f:
        assert f['nodes'].shape[0] > 0
" || fail "the files written before the failed write do not read"
echo "point_files_hdf5: the HDF5 series matches the run; a failed write is one line"
