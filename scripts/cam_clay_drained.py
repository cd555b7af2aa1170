#!/usr/bin/env python3
"""Drained triaxial compression of Modified Cam-clay by numerical
integration of the rate equations: the independent reference of
tests/cam_clay_element.cc, cases (c) and (d). Plain Python (no numpy).

The model (compression positive; p, q Kirchhoff stresses; logarithmic
strains eps_v = eps_a + 2 eps_r, eps_s = 2/3 (eps_a - eps_r)):

  elastic   d eps_v^e = kappa* dp / p,   d eps_s^e = dq / (3 G)
  yield     f = q^2/M^2 + p (p - p_c) = 0
  flow      d eps_v^p = L (2p - p_c),    d eps_s^p = L 2q/M^2
  hardening d p_c = p_c d eps_v^p / (lambda* - kappa*)

with kappa* = kappa/(1 + e0), lambda* = lambda/(1 + e0). The path holds
the lateral stress: dq = 3 dp. The consistency condition df = 0 gives the
multiplier L per dp:

  L = [(2p - p_c) + 6q/M^2] (lambda* - kappa*) dp / (p p_c (2p - p_c)).

The state (p_c, eps_v, eps_s) is integrated in p by the classical
fourth-order Runge-Kutta method (p_c as an unknown of its own, not from the
yield condition, which the script prints as a check), on every interval
with N and 2N steps; the printed difference of the two bounds the error.

(c) a normally consolidated sample from p0 = p_c0: plastic from the start,
    hardening, towards the critical state p_cs = 3 p0/(3 - M), q = M p.
(d) an overconsolidated sample, p_c0 = OCR p0 with OCR = 10: elastic up to
    the yield point (the root of f on the path, a quadratic), then
    softening, p decreasing back along the path towards the same p_cs.

Usage: python3 scripts/cam_clay_drained.py
"""

import math

# The parameters of tests/cam_clay_element.cc.
M = 1.2
LAMBDA = 0.2
KAPPA = 0.04
E0 = 1.0
G = 3.0e6
P0 = 1.0e5

KAPPA_STAR = KAPPA / (1.0 + E0)
THETA = (LAMBDA - KAPPA) / (1.0 + E0)
P_CS = 3.0 * P0 / (3.0 - M)


def rates(p, state):
    """d(p_c, eps_v, eps_s)/dp on the yield surface along dq = 3 dp."""
    pc = state[0]
    q = 3.0 * (p - P0)
    fp = 2.0 * p - pc
    multiplier = (fp + 6.0 * q / M**2) * THETA / (p * pc * fp)
    return [pc * multiplier * fp / THETA,
            KAPPA_STAR / p + multiplier * fp,
            1.0 / G + multiplier * 2.0 * q / M**2]


def integrate(p_start, state, p_end, n):
    """Classical RK4 over [p_start, p_end] in n steps."""
    h = (p_end - p_start) / n
    y = list(state)
    p = p_start
    for _ in range(n):
        k1 = rates(p, y)
        k2 = rates(p + h / 2, [a + h / 2 * b for a, b in zip(y, k1)])
        k3 = rates(p + h / 2, [a + h / 2 * b for a, b in zip(y, k2)])
        k4 = rates(p + h, [a + h * b for a, b in zip(y, k3)])
        y = [a + h / 6 * (b + 2 * c + 2 * d + e)
             for a, b, c, d, e in zip(y, k1, k2, k3, k4)]
        p += h
    return y


def table(name, p_start, state, targets, n=4000):
    """Integrate through the targets, print p/p0, eps_a, eps_v and checks."""
    print(name)
    print("  {p/p0, eps_a, eps_v} (compression positive), "
          "|RK4 N - 2N|, f/p^2 with the integrated p_c")
    fine = list(state)
    coarse = list(state)
    p = p_start
    for target in targets:
        p_next = target * P0
        coarse = integrate(p, coarse, p_next, n)
        fine = integrate(p, fine, p_next, 2 * n)
        p = p_next
        eps_v, eps_s = fine[1], fine[2]
        eps_a = eps_v / 3.0 + eps_s
        difference = max(abs(a - b) for a, b in zip(fine[1:], coarse[1:]))
        q = 3.0 * (p - P0)
        f = q**2 / M**2 + p * (p - fine[0])
        print("  {%.6f, %.10f, %.10f},  %.1e  %.1e"
              % (target, eps_a, eps_v, difference, f / p**2))


def main():
    print("M = %g, lambda = %g, kappa = %g, e0 = %g, G = %g, p0 = %g"
          % (M, LAMBDA, KAPPA, E0, G, P0))
    print("critical state on the path: p_cs/p0 = %.10f, q_cs/p0 = %.10f"
          % (P_CS / P0, M * P_CS / P0))

    # (c) Normally consolidated: p_c0 = p0, on the surface at the start.
    fractions = [0.2, 0.4, 0.6, 0.8, 0.9, 0.95, 0.98]
    targets = [1.0 + f * (P_CS / P0 - 1.0) for f in fractions]
    table("(c) normally consolidated, at q/q_cs = "
          + ", ".join("%g" % f for f in fractions),
          P0, [P0, 0.0, 0.0], targets)

    # (d) OCR = 10: elastic to the yield point, then softening.
    pc0 = 10.0 * P0
    # f = 9 (p - p0)^2 / M^2 + p (p - p_c0) = 0: a p^2 + b p + c = 0.
    a = 9.0 / M**2 + 1.0
    b = -18.0 * P0 / M**2 - pc0
    c = 9.0 * P0**2 / M**2
    p_yield = (-b + math.sqrt(b * b - 4.0 * a * c)) / (2.0 * a)
    q_yield = 3.0 * (p_yield - P0)
    print("(d) OCR 10: yield at p_y/p0 = %.10f, q_y/p0 = %.10f"
          % (p_yield / P0, q_yield / P0))
    elastic = [pc0,
               KAPPA_STAR * math.log(p_yield / P0),
               q_yield / (3.0 * G)]
    fractions = [0.8, 0.6, 0.4, 0.2, 0.1, 0.05]
    targets = [P_CS / P0 + f * (p_yield - P_CS) / P0 for f in fractions]
    table("(d) softening, at (p - p_cs)/(p_y - p_cs) = "
          + ", ".join("%g" % f for f in fractions),
          p_yield, elastic, targets)


if __name__ == "__main__":
    main()
