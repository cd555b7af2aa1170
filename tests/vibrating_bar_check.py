#!/usr/bin/env python3
"""The vibrating bar against its analytical solution (tests/vibrating_bar.prm).

Usage: vibrating_bar_check.py OUTPUT_DIRECTORY END_TIME V0 DISPLACEMENT_LIMIT [ENERGY_LIMIT]

Reads point_history.csv (the point nearest x = 24.75 m) and steps.csv
(kinetic_energy) and compares with u(X, t) = v0/omega sin(pi X/2L)
sin(omega t), omega = pi c/2L, c = sqrt(E/rho) = 10 m/s, L = 25 m,
v0 as given: the largest difference of the displacement over the first
period relative to the amplitude at X (the phase error of a period error
grows with time), the period from the downward zero crossings
of the displacement (linear interpolation between rows) against 4L/c = 10 s,
and the total energy (steps.csv: kinetic + strain) at every step against the
initial rho v0^2 L / 4 per m of thickness (ENERGY_LIMIT, 2e-3 by default).
Prints each check with yes/NO and its figure; exits non-zero on a NO."""
import csv
import math
import sys

directory, end_time = sys.argv[1], float(sys.argv[2])
v0, limit = float(sys.argv[3]), float(sys.argv[4])
energy_limit = float(sys.argv[5]) if len(sys.argv) > 5 else 2e-3
E, rho, L = 100.0, 1.0, 25.0
c = math.sqrt(E / rho)
omega = math.pi * c / (2 * L)
rows = list(csv.DictReader(open(directory + "/point_history.csv")))
X = float(rows[0]["x"])
amplitude = v0 / omega * math.sin(math.pi * X / (2 * L))
times = [float(r["time"]) for r in rows]
u = [float(r["displacement_x"]) for r in rows]
first_period = 4 * L / c
error = max(abs(ui - amplitude * math.sin(omega * t))
            for t, ui in zip(times, u) if t <= first_period + 1e-9)
crossings = []
for k in range(1, len(u)):
    if u[k - 1] > 0 >= u[k]:
        crossings.append(times[k - 1] + (times[k] - times[k - 1]) * u[k - 1] / (u[k - 1] - u[k]))
period = (crossings[-1] - crossings[0]) / (len(crossings) - 1) if len(crossings) > 1 else float("nan")
print("tip point X = %.4f m, amplitude %.6f m" % (X, amplitude))
print("largest displacement error over the first period / amplitude below %g: %s (%.2e)"
      % (limit, "yes" if error / amplitude < limit else "NO", error / amplitude))
relative = abs(period - 4 * L / c) / (4 * L / c)
print("period from %d downward crossings within 5e-3 of 4L/c = %.1f s: %s (%.5f s, %.2e)"
      % (len(crossings), 4 * L / c, "yes" if relative < 5e-3 else "NO", period, relative))
steps = [r for r in csv.DictReader(open(directory + "/steps.csv")) if r.get("converged", "1") == "1"]
total = [float(r["total_energy"]) for r in steps]
exact = 0.5 * rho * v0 ** 2 * L / 2  # per m of thickness: int_0^L 0.5 rho v0^2 sin^2 = rho v0^2 L/4
drift = max(abs(e - exact) for e in total) / exact
print("total (kinetic + strain) energy within %g of the initial %.6e J/m at every step: %s (largest difference %.2e, at the end %.2e)"
      % (energy_limit, exact, "yes" if drift < energy_limit else "NO", drift, (exact - total[-1]) / exact))
failed = error / amplitude >= limit or not relative < 5e-3 or not drift < energy_limit
sys.exit(1 if failed else 0)
