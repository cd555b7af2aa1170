#!/usr/bin/env python3
"""The damped vibrating bar against its analytical solution (tests/stiffness_damping.sh).

Usage: stiffness_damping_check.py OUTPUT_DIRECTORY MODE V0 BETA ALPHA DISPLACEMENT_LIMIT ZETA_LIMIT

The bar of tests/vibrating_bar.prm (E = 100 Pa, rho = 1 kg/m^3, L = 25 m,
c = 10 m/s) started with the velocity v0 sin(k x), k = (2 MODE - 1) pi / 2L,
of one of its modes, Rayleigh damping with the stiffness-proportional
coefficient beta (s) and the mass-proportional alpha (1/s): the mode is a
damped oscillator of angular frequency omega = c k and damping ratio
zeta = alpha / (2 omega) + beta omega / 2, so the displacement of the point
at X is
u(X, t) = v0 / omega_d sin(k X) exp(-zeta omega t) sin(omega_d t),
omega_d = omega sqrt(1 - zeta^2). Reads point_history.csv and checks
 - the largest difference from u over the first period of the mode,
   relative to the amplitude v0 / omega_d sin(k X), below
   DISPLACEMENT_LIMIT;
 - the damping ratio from the logarithmic decrement of the successive
   positive peaks (each the vertex of the parabola through the largest
   row and its neighbours), ln(u_j / u_j+1) = 2 pi zeta / sqrt(1 - zeta^2),
   averaged over the peaks, within ZETA_LIMIT (relative) of zeta.
Prints each check with yes/NO and its figure; exits non-zero on a NO."""
import csv
import math
import sys

directory, mode = sys.argv[1], int(sys.argv[2])
v0, beta, alpha = float(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5])
limit, zeta_limit = float(sys.argv[6]), float(sys.argv[7])
c, L = 10.0, 25.0
k = (2 * mode - 1) * math.pi / (2 * L)
omega = c * k
zeta = alpha / (2 * omega) + beta * omega / 2
omega_d = omega * math.sqrt(1 - zeta ** 2)
rows = list(csv.DictReader(open(directory + "/point_history.csv")))
X = float(rows[0]["x"])
amplitude = v0 / omega_d * math.sin(k * X)
times = [0.0] + [float(r["time"]) for r in rows]
u = [0.0] + [float(r["displacement_x"]) for r in rows]
period = 2 * math.pi / omega_d
error = max(abs(ui - amplitude * math.exp(-zeta * omega * t) * math.sin(omega_d * t))
            for t, ui in zip(times, u) if t <= period + 1e-9)
peaks = []
for j in range(1, len(u) - 1):
    if u[j] > 0 and u[j] >= u[j - 1] and u[j] > u[j + 1]:
        a, b, d = u[j - 1], u[j], u[j + 1]
        peaks.append(b - (a - d) ** 2 / (8 * (a - 2 * b + d)))
decrements = [math.log(peaks[j] / peaks[j + 1]) for j in range(len(peaks) - 1)]
measured = float("nan")
if decrements:
    delta = sum(decrements) / len(decrements)
    measured = delta / math.sqrt(4 * math.pi ** 2 + delta ** 2)
relative = abs(measured - zeta) / zeta
print("mode %d, beta %g s, alpha %g 1/s: omega %.5f rad/s, zeta = %.5f; point X = %.4f m"
      % (mode, beta, alpha, omega, zeta, X))
print("largest displacement error over the first period / amplitude below %g: %s (%.2e)"
      % (limit, "yes" if error / abs(amplitude) < limit else "NO", error / abs(amplitude)))
print("damping ratio from %d peaks within %g of zeta: %s (%.5f, %.2e)"
      % (len(peaks), zeta_limit, "yes" if relative < zeta_limit else "NO", measured, relative))
sys.exit(0 if error / abs(amplitude) < limit and relative < zeta_limit else 1)
