"""Check tests/explicit_stable_step_cut.sh's run independently of IMPM.

The bar (E = 100 Pa, nu = 0, rho0 = 1 kg/m^3, cells of h = 1 m, 2x2 points a
cell of 0.25 m^2) stretched in one dimension: a point of volume ratio J has
the density rho0 / J, the P-wave speed sqrt(E J / rho0) and, at Courant
number 1, the stable step h / sqrt(E J / rho0). From the point files written
after every converged step (the state the next step starts from) and the
step lines of the log:
  * every converged step's time step is at most the stable step of its start
    state, and every attempt refused as "time step above the stable one" was
    above it: the refusals come where the stable step falls, and only there;
  * the run reaches its end time, with at least one refusal;
  * the Hencky stress of a point stretched along x alone is
    sigma_xx = E ln(J) / J (Kirchhoff E ln(lambda), lambda = J), to 1e-5 of E
    (single-precision files).
Usage: check_explicit_stable_step_cut.py OUTPUT_DIRECTORY LOG
"""
import glob
import math
import re
import sys

import vtk
from vtk.util.numpy_support import vtk_to_numpy

E, RHO0, H, V0 = 100.0, 1.0, 1.0, 0.25
directory, log = sys.argv[1], sys.argv[2]


def state(step):
    reader = vtk.vtkXMLPUnstructuredGridReader()
    reader.SetFileName(f"{directory}/points_{step:05d}.pvtu")
    reader.Update()
    data = reader.GetOutput().GetPointData()
    volume = vtk_to_numpy(data.GetArray("volume"))
    stress = vtk_to_numpy(data.GetArray("stress_xx"))
    return volume / V0, stress


def stable_step(ratios):
    return H / math.sqrt(E * ratios.max() / RHO0)


# Step lines: "step N  load L  iterations 0 ... t T s" (converged) or
# "step N  load L  time step above the stable one ...: step cut ... t T s".
converged, refused = 0, 0
last_time, end_time = 0.0, None
worst_stress = 0.0
for line in open(log):
    if not line.startswith("step "):
        continue
    target = float(re.search(r" t ([0-9.e+-]+) s", line).group(1))
    ratios, stress = state(converged)
    limit = stable_step(ratios)
    step = target - last_time
    if "time step above the stable one" in line:
        assert step > limit * (1 + 1e-6), f"refused {step} s at t = {last_time} s, stable {limit} s"
        refused += 1
        continue
    assert "iterations 0" in line, line
    assert step <= limit * (1 + 1e-6), f"took {step} s at t = {last_time} s, stable {limit} s"
    converged += 1
    last_time = target
    ratios, stress = state(converged)
    worst_stress = max(worst_stress,
                       max(abs(s - E * math.log(j) / j) for j, s in zip(ratios, stress)) / E)
assert refused > 0, "no step was refused: the test does not reach the stable step's fall"
assert abs(last_time - 3.0) < 1e-9, f"the run ended at t = {last_time} s"
assert worst_stress < 1e-5, f"stress off E ln(J)/J by {worst_stress} E"
ratios, _ = state(converged)
print(f"{converged} steps converged, {refused} refused above the stable step; "
      f"largest volume ratio {ratios.max():.4f}, stable step there {stable_step(ratios):.5f} s; "
      f"stress against E ln(J)/J within {worst_stress:.1e} E")
