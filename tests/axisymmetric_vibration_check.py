#!/usr/bin/env python3
"""Axisymmetric vibrations against their analytical solutions
(tests/axisymmetric_bar.prm, tests/axisymmetric_radial_mode.prm).

Usage: axisymmetric_vibration_check.py OUTPUT_DIRECTORY MODE DISPLACEMENT_LIMIT
           ENERGY_LIMIT FIRST_STEP_ENERGY FIRST_STEP_TOLERANCE

E = 100 Pa, nu = 0.3, rho = 1, v0 = 0.01 m/s; c = sqrt(M/rho) the P-wave
speed, M = E (1 - nu)/((1 + nu)(1 - 2 nu)).
MODE axial: a solid cylinder of radius R = 1 m and length L = 25 m along
  the axis in uniaxial strain: u_z(Z, t) = v0/omega sin(pi Z/2L)
  sin(omega t), omega = pi c/2L, u_r = 0; its energy rho v0^2 L pi R^2/4.
MODE radial: the first radial mode of a free solid cylinder of radius a =
  1 m, H = 0.5 m long in plane strain: u_r(r, t) = v0/omega J1(x1 r/a)
  sin(omega t), x1 J0(x1) = (1 - 2 nu)/(1 - nu) J1(x1), omega = x1 c/a,
  u_z = 0; its energy pi rho v0^2 H int_0^a J1(x1 r/a)^2 r dr.
Checks, each printed with yes/NO and its figure:
 * the moving component of both history points within DISPLACEMENT_LIMIT
   of its amplitude at every step of the first period;
 * the period from the downward zero crossings within 5e-3 of 2 pi/omega;
 * the other component below 1e-3 of the amplitude; in the axial mode the
   two points (two radii) moving as one, to 1e-3 of the amplitude;
 * the first step's FIRST_STEP_ENERGY (total_energy for the implicit
   rules; kinetic_energy for the explicit ones, whose strain energy is half
   a step from their kinetic energy) within FIRST_STEP_TOLERANCE of the
   exact energy, which has the rings' 2 pi r (a plane model's would be
   another: the axial bar's rho v0^2 L R/4), and the total energy within
   ENERGY_LIMIT of it at every step.
Exits non-zero on a NO."""
import csv
import math
import sys

directory, mode = sys.argv[1], sys.argv[2]
limit, energy_limit = float(sys.argv[3]), float(sys.argv[4])
first_step_energy, first_step_tolerance = sys.argv[5], float(sys.argv[6])
E, nu, rho, v0 = 100.0, 0.3, 1.0, 0.01
c = math.sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) / rho)


def bessel(n, x):
    return sum((-1) ** k / (math.factorial(k) * math.factorial(k + n)) * (x / 2) ** (2 * k + n)
               for k in range(40))


if mode == "axial":
    L, R = 25.0, 1.0
    omega = math.pi * c / (2 * L)
    moving, other = "displacement_y", "displacement_x"
    shape = lambda r, z: math.sin(math.pi * z / (2 * L))
    exact_energy = rho * v0 ** 2 * L * math.pi * R ** 2 / 4
else:
    a, H = 1.0, 0.5
    ratio = (1 - 2 * nu) / (1 - nu)
    low, high = 1.0, 3.0  # x J0(x) - ratio J1(x) changes sign once here
    for _ in range(100):
        mid = 0.5 * (low + high)
        f = lambda x: x * bessel(0, x) - ratio * bessel(1, x)
        low, high = (low, mid) if f(low) * f(mid) <= 0 else (mid, high)
    x1 = 0.5 * (low + high)
    omega = x1 * c / a
    moving, other = "displacement_x", "displacement_y"
    shape = lambda r, z: bessel(1, x1 * r / a)
    n = 4000  # midpoint rule for int_0^a J1(x1 r/a)^2 r dr
    exact_energy = math.pi * rho * v0 ** 2 * H * sum(
        bessel(1, x1 * (i + 0.5) / n) ** 2 * (i + 0.5) / n * a * a / n for i in range(n))
period_exact = 2 * math.pi / omega
rows = list(csv.DictReader(open(directory + "/point_history.csv")))
ok = True


def check(text, good, figure):
    global ok
    ok = ok and good
    print("%s: %s (%s)" % (text, "yes" if good else "NO", figure))


histories = {}
for r in rows:
    histories.setdefault(r["point"], []).append(r)
largest_amplitude = 0.
for point, history in sorted(histories.items()):
    X, Z = float(history[0]["x"]), float(history[0]["y"])
    amplitude = v0 / omega * shape(X, Z)
    largest_amplitude = max(largest_amplitude, abs(amplitude))
    times = [float(r["time"]) for r in history]
    u = [float(r[moving]) for r in history]
    error = max(abs(ui - amplitude * math.sin(omega * t))
                for t, ui in zip(times, u) if t <= period_exact + 1e-9)
    check("%s at r = %.4f, z = %.4f within %g of its amplitude %.4e m over the first period"
          % (moving, X, Z, limit, amplitude), error / amplitude < limit,
          "%.2e" % (error / amplitude))
    crossings = []
    for k in range(1, len(u)):
        if u[k - 1] > 0 >= u[k]:
            crossings.append(times[k - 1] + (times[k] - times[k - 1]) * u[k - 1] / (u[k - 1] - u[k]))
    period = ((crossings[-1] - crossings[0]) / (len(crossings) - 1)
              if len(crossings) > 1 else float("nan"))
    relative = abs(period - period_exact) / period_exact
    check("  its period within 5e-3 of %.6f s" % period_exact, relative < 5e-3,
          "%.6f s, %.2e" % (period, relative))
still = max(abs(float(r[other])) for r in rows)
check("%s below 1e-3 of the amplitude" % other, still / largest_amplitude < 1e-3,
      "%.2e" % (still / largest_amplitude))
if mode == "axial":
    first, second = (histories[p] for p in sorted(histories))
    spread = max(abs(float(r1[moving]) - float(r2[moving])) for r1, r2 in zip(first, second))
    check("the two radii moving as one, to 1e-3 of the amplitude",
          spread / largest_amplitude < 1e-3, "%.2e" % (spread / largest_amplitude))
steps = [r for r in csv.DictReader(open(directory + "/steps.csv")) if r.get("converged", "1") == "1"]
total = [float(r["total_energy"]) for r in steps]
start = float(steps[0][first_step_energy])
check("%s of the first step within %g of the exact %.6e J"
      % (first_step_energy, first_step_tolerance, exact_energy),
      abs(start - exact_energy) / exact_energy < first_step_tolerance,
      "%.2e" % (abs(start - exact_energy) / exact_energy))
drift = max(abs(e - exact_energy) for e in total) / exact_energy
check("total energy within %g of it at every step" % energy_limit, drift < energy_limit,
      "%.2e" % drift)
sys.exit(0 if ok else 1)
