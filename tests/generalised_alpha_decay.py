#!/usr/bin/env python3
"""Generalised-alpha's energy decay on the vibrating bar against its theory.

Usage: generalised_alpha_decay.py STEPS_PER_PERIOD DIR_TRAPEZOIDAL DIR_RHO_0.5 DIR_RHO_0

The theory is independent of IMPM: the amplification matrix of Chung and
Hulbert's (1993) generalised-alpha method for one mode of angular frequency
omega, u'' + omega^2 u = 0, with Omega = omega dt = 2 pi / STEPS_PER_PERIOD
and alpha_m = (2 rho - 1)/(rho + 1), alpha_f = rho/(rho + 1),
gamma = 1/2 - alpha_m + alpha_f, beta = (1 - alpha_m + alpha_f)^2 / 4;
the modulus |lambda| of its complex pair gives the energy ratio per period
|lambda|^(2 N). The measured decay is the slope of the total energy
(steps.csv) over the second half of the run, per period, less that of the
trapezoidal rule on the same grid (the loss of the mapping between points
and nodes, which the theory of a single mode does not have).
Checks: the decay grows as rho_inf falls, and with rho_inf = 0 (the
largest algorithmic damping) it is within 35 % of the theory; rho_inf =
0.5's is printed (it is below the mapping's loss).
"""
import cmath
import csv
import math
import sys


def solve3(L, R):
    M = [L[i][:] + R[i][:] for i in range(3)]
    for c in range(3):
        p = max(range(c, 3), key=lambda r: abs(M[r][c]))
        M[c], M[p] = M[p], M[c]
        for r in range(3):
            if r != c:
                f = M[r][c] / M[c][c]
                M[r] = [a - f * b for a, b in zip(M[r], M[c])]
    return [[M[i][3 + j] / M[i][i] for j in range(3)] for i in range(3)]


def eigenvalues3(A):
    tr = A[0][0] + A[1][1] + A[2][2]
    c2 = sum(A[i][i] * A[j][j] - A[i][j] * A[j][i] for i in range(3) for j in range(i + 1, 3))
    det = (A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1])
           - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0])
           + A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]))
    p = lambda z: z ** 3 - tr * z ** 2 + c2 * z - det
    roots = [complex(0.4, 0.9) ** k for k in range(3)]  # Durand-Kerner
    for _ in range(1000):
        roots = [r - p(r) / math.prod(r - s for j, s in enumerate(roots) if j != i)
                 for i, r in enumerate(roots)]
    return roots


def energy_loss_per_period(rho, steps):
    am, af = (2 * rho - 1) / (rho + 1), rho / (rho + 1)
    gamma, beta = 0.5 - am + af, 0.25 * (1 - am + af) ** 2
    w2 = (2 * math.pi / steps) ** 2  # dt = 1
    L = [[(1 - af) * w2, 0, 1 - am], [1, 0, -beta], [0, 1, -gamma]]
    R = [[-af * w2, 0, -am], [1, 1, 0.5 - beta], [0, 1, 1 - gamma]]
    pair = max(eigenvalues3(solve3(L, R)), key=lambda z: abs(z.imag))
    return 1 - abs(pair) ** (2 * steps)


def measured_decay(directory, period=10.0):
    rows = [r for r in csv.DictReader(open(directory + "/steps.csv")) if r["converged"] == "1"]
    t = [float(r["time"]) for r in rows]
    e = [float(r["total_energy"]) for r in rows]
    half = len(t) // 2
    return (e[half] - e[-1]) / e[0] / ((t[-1] - t[half]) / period)


steps = float(sys.argv[1])
baseline = measured_decay(sys.argv[2])
half = measured_decay(sys.argv[3]) - baseline
zero = measured_decay(sys.argv[4]) - baseline
theory_half, theory_zero = energy_loss_per_period(0.5, steps), energy_loss_per_period(0.0, steps)
print("energy loss per period at %g steps a period: the trapezoidal rule's (the mapping's) %.2e" % (steps, baseline))
print("rho_inf = 0.5: %.2e beyond it, theory %.2e" % (half, theory_half))
ok_zero = abs(zero - theory_zero) < 0.35 * theory_zero
print("rho_inf = 0: %.2e beyond it, theory %.2e: within 35 %%: %s" % (zero, theory_zero, "yes" if ok_zero else "NO"))
ok_order = zero > half
print("the decay grows as rho_inf falls: %s" % ("yes" if ok_order else "NO"))
sys.exit(0 if ok_zero and ok_order else 1)
