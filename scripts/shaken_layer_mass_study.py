#!/usr/bin/env python3
"""What the lumped mass costs on a layer shaken above its first mode.

The shear column of tests/shaken_layer.prm (H = 10 m, Vs = 7.071 m/s, 20
cells, first mode 0.177 Hz) under two cycles of a 1 Hz sine of base
acceleration (amplitude 0.1 m/s^2), which excites its third and fourth
modes (0.88 and 1.24 Hz). Each run's relative displacement of the point
at y = 9.875 m over 6 s is compared with three references computed here,
not by IMPM: the exact solution by modal superposition (60 modes), and the
semi-discrete solutions of 20 linear elements with lumped and with
consistent mass (an ODE solver to 1e-10). Prints a Markdown table: the
largest difference from the exact solution over the 6 s, as a share of
the largest displacement, and the wall time.

Usage: scripts/shaken_layer_mass_study.py build/impm   (about a minute;
needs SciPy: apt-get install python3-scipy)
"""
import csv
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
from scipy.integrate import solve_ivp

impm = os.path.abspath(sys.argv[1])
scene = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                     "tests", "shaken_layer.prm")
H, G, RHO, Y, END = 10.0, 50.0, 1.0, 9.875, 6.0
VS = np.sqrt(G / RHO)
TIMES = np.round(np.arange(0.0, END + 1e-9, 0.01), 6)


def base_acceleration(t):
    return 0.1 * np.sin(2 * np.pi * t) if t < 2.0 else 0.0


def integrate(matrix, load):
    """u'' = -matrix u - load a_g(t) from rest, sampled at TIMES."""
    n = len(load)

    def rate(t, s):
        return np.concatenate([s[n:], -matrix @ s[:n] - load * base_acceleration(t)])

    return solve_ivp(rate, (0.0, END), np.zeros(2 * n), t_eval=TIMES,
                     rtol=1e-10, atol=1e-13, max_step=0.002).y[:n]


def modal():
    modes = np.arange(1, 61)
    omega = (2 * modes - 1) * np.pi * VS / (2 * H)
    participation = 4 / ((2 * modes - 1) * np.pi)
    q = integrate(np.diag(omega ** 2), participation)
    return np.sin((2 * modes - 1) * np.pi * Y / (2 * H)) @ q


def finite_elements(lumped):
    n_cells, h = 20, H / 20
    K = np.zeros((n_cells + 1, n_cells + 1))
    M = np.zeros_like(K)
    for e in range(n_cells):
        K[e:e + 2, e:e + 2] += G / h * np.array([[1, -1], [-1, 1]])
        M[e:e + 2, e:e + 2] += RHO * h / 6 * np.array([[2, 1], [1, 2]])
    if lumped:
        M = np.diag(M.sum(axis=1))
    K, M = K[1:, 1:], M[1:, 1:]
    inverse = np.linalg.inv(M)
    u = integrate(inverse @ K, inverse @ M @ np.ones(n_cells))
    return (u[18] * (10 - Y) + u[19] * (Y - 9.5)) / 0.5


def run(directory, integrator, time_step, mass):
    start = time.time()
    subprocess.run([impm, scene, "--set", "Testing/Enabled=false",
                    "--set", "Inertia/Integrator=" + integrator,
                    "--set", "Inertia/Mass=" + mass,
                    "--set", "Time/Time step=%g" % time_step,
                    "--set", "Time/End time=%g" % END,
                    "--set", "Base shaking/Acceleration file=" + os.path.abspath("pulse.txt"),
                    "--set", "Output directory=" + directory],
                   check=True, stdout=subprocess.DEVNULL)
    wall = time.time() - start
    rows = [r for r in csv.DictReader(open(directory + "/point_history.csv"))
            if r["point"] == "1"]
    history = {round(float(r["time"]), 6): float(r["displacement_x"]) for r in rows}
    return np.array([history[t] for t in TIMES]), wall


os.chdir(tempfile.mkdtemp())
with open("pulse.txt", "w") as f:
    for i in range(int(END / 0.005) + 1):
        f.write("%g %g 0\n" % (i * 0.005, base_acceleration(i * 0.005)))
exact = modal()
scale = np.abs(exact).max()
print("| model | time step (s) | largest difference from the exact solution | wall time (s) |")
print("|---|---|---|---|")
for name, lumped in (("20 linear elements, lumped mass (ODE solver)", True),
                     ("20 linear elements, consistent mass (ODE solver)", False)):
    u = finite_elements(lumped)
    print("| %s | - | %.1f %% | - |" % (name, 100 * np.abs(u - exact).max() / scale))
for integrator, time_step, mass in (("explicit MUSL", 0.002, "lumped"),
                                    ("explicit MUSL", 0.0005, "lumped"),
                                    ("Newmark", 0.01, "lumped"),
                                    ("Newmark", 0.002, "lumped"),
                                    ("Newmark", 0.01, "consistent"),
                                    ("Newmark", 0.002, "consistent")):
    u, wall = run("run_%s_%g_%s" % (integrator.replace(" ", "_"), time_step, mass),
                  integrator, time_step, mass)
    print("| IMPM, %s, %s mass | %g | %.1f %% | %.2f |"
          % (integrator, mass, time_step, 100 * np.abs(u - exact).max() / scale, wall))
