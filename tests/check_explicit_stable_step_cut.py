"""Check tests/explicit_stable_step_cut.sh's runs independently of IMPM.

The stable explicit step of a state is h / max_p sqrt(M_p / rho0) with the
P-wave modulus M_p of each point's stress and the reference density rho0
(a point's mass and its Kirchhoff stiffness both go with its initial volume):
  * the bar (E = 100 Pa, nu = 0, rho0 = 1 kg/m^3, h = 1 m, C = 0.9, points
    of 0.25 m^2): M = E at every J;
  * the Cam-clay column (kappa* = 0.04 / 2 = 0.02, G = 200 kPa, p_ref = 100
    Pa, rho0 = 1800 kg/m^3, h = 1 m, C = 0.99): M = max(p', p_ref) /
    kappa* + 4 G / 3 with p' = -tr(tau) / 3, tau = J sigma.
From the point files written after every converged step (the state the next
step starts from), the step lines of the log and the rows of steps.csv: every converged step's time
step is at most the stable step of its start state, every attempt refused as
"time step above the stable one" above it, the attempt after a refusal the
Courant number C times it, and the run reaches 3 s. The bar:
no refusal, J above 1.235 (where sqrt(E J / rho0) would have refused 0.09 s)
and sigma_xx = E ln(J) / J to 1e-5 of E (single-precision files). The column:
at least one refusal, and its strain energy at 3 s within 0.5 % of the run at
0.005 s.
Usage: check_explicit_stable_step_cut.py BAR_DIRECTORY BAR_LOG CLAY_DIRECTORY
           CLAY_LOG FINE_CLAY_STEPS_CSV
"""
import csv
import math
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

V0 = 0.25
H = 1.0


def read(directory, step, names):
    reader = vtk.vtkXMLPUnstructuredGridReader()
    reader.SetFileName(f"{directory}/points_{step:05d}.pvtu")
    reader.Update()
    data = reader.GetOutput().GetPointData()
    return [vtk_to_numpy(data.GetArray(name)).astype(float) for name in names]


def bar_state(directory, step):
    volume, stress = read(directory, step, ["volume", "stress_xx"])
    return volume / V0, stress


def bar_stable(directory, step):
    return H / math.sqrt(100.0 / 1.0)


def clay_stable(directory, step):
    volume, sxx, syy, szz = read(directory, step,
                                 ["volume", "stress_xx", "stress_yy", "stress_zz"])
    mean = -(volume / V0) * (sxx + syy + szz) / 3
    modulus = np.maximum(mean, 100.0) / 0.02 + 4 * 2e5 / 3
    return H / math.sqrt(modulus.max() / 1800.0)


def follow(directory, log, stable, courant):
    """(converged steps, refusals) after checking each attempt: its outcome
    from the log's step line, its time from steps.csv's row (10 digits)."""
    converged, refused, last_time = 0, 0, 0.0
    lines = [line for line in open(log) if line.startswith("step ")]
    rows = list(csv.DictReader(open(f"{directory}/steps.csv")))
    assert len(lines) == len(rows), f"{directory}: {len(lines)} step lines, {len(rows)} rows"
    after_refusal = False
    for line, row in zip(lines, rows):
        assert (row["converged"] == "1") == ("iterations 0" in line), line
        target = float(row["time"])
        limit = stable(directory, converged)
        step = target - last_time
        if after_refusal:
            assert abs(step - courant * limit) < 1e-6 * limit, \
                f"{directory}: cut to {step} s, not {courant} x {limit} s"
        after_refusal = "time step above the stable one" in line
        if after_refusal:
            assert step > limit * (1 + 1e-6), \
                f"{directory}: refused {step} s at t = {last_time} s, stable {limit} s"
            refused += 1
            continue
        assert "iterations 0" in line, line
        assert step <= limit * (1 + 1e-6), \
            f"{directory}: took {step} s at t = {last_time} s, stable {limit} s"
        converged += 1
        last_time = target
    assert abs(last_time - 3.0) < 1e-9, f"{directory}: the run ended at t = {last_time} s"
    return converged, refused


bar, bar_log, clay, clay_log, fine_steps = sys.argv[1:6]

converged, refused = follow(bar, bar_log, bar_stable, 0.9)
assert refused == 0, f"the bar refused {refused} steps"
largest_ratio, worst_stress = 0.0, 0.0
for step in range(1, converged + 1):
    ratios, stress = bar_state(bar, step)
    largest_ratio = max(largest_ratio, ratios.max())
    worst_stress = max(worst_stress, np.abs(stress - 100.0 * np.log(ratios) / ratios).max() / 100.0)
assert largest_ratio > 1.235, f"the bar's largest J is only {largest_ratio}"
assert worst_stress < 1e-5, f"the bar's stress off E ln(J)/J by {worst_stress} E"
print(f"bar: {converged} steps of 0.09 s, none refused; largest J {largest_ratio:.4f}; "
      f"stress against E ln(J)/J within {worst_stress:.1e} E")

converged, refused = follow(clay, clay_log, clay_stable, 0.99)
assert refused > 0, "the column refused no step: the test does not reach its stiffening"
first = clay_stable(clay, 0)


def strain_energy(path):
    rows = [r for r in csv.DictReader(open(path)) if r["converged"] == "1"]
    return float(rows[-1]["strain_energy"])


energy, fine = strain_energy(f"{clay}/steps.csv"), strain_energy(fine_steps)
assert abs(energy - fine) < 5e-3 * fine, f"the column's strain energy {energy} against {fine} J"
print(f"Cam-clay column: {converged} steps converged, {refused} refused above the stable step "
      f"(the stable step of the start {first:.5f} s, where the reference pressure's modulus "
      f"allows 0.08 s); strain energy at 3 s "
      f"{energy:.5e} J against {fine:.5e} J at 0.005 s ({(energy - fine) / fine * 100:+.2f} %)")
