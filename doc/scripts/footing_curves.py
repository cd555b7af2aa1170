#!/usr/bin/env python3
"""Load-settlement curves of strip-footing runs in one figure.

Usage: footing_curves.py OUT.png PRANDTL_KN SETTLEMENT_M LABEL=steps.csv ...

Each run's steps.csv gives the footing load (-reaction_y+_y, kN per m of
half footing) against the settlement (load factor x SETTLEMENT_M); runs
whose label names "F-bar on" or "cell pressures" are solid, the others
dashed, each pair of runs in one colour; the dotted line is Prandtl's
limit load. Used by
scripts/footing_study.sh.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def curve(path, settlement):
    xs, ys = [0.0], [0.0]
    with open(path) as f:
        for row in csv.DictReader(f):
            if row["converged"] != "1":
                continue
            xs.append(float(row["load_factor"]) * settlement * 1000.0)
            ys.append(-float(row["reaction_y+_y"]) / 1000.0)
    return xs, ys


def main():
    out, prandtl, settlement = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    styles = ["-", "--"]
    for k, spec in enumerate(sys.argv[4:]):
        label, path = spec.rsplit("=", 1)
        xs, ys = curve(path, settlement)
        solid = "F-bar on" in label or "cell pressures" in label
        # Runs come in pairs (one cell size, two treatments): one colour.
        ax.plot(xs, ys, styles[0 if solid else 1], color="C%d" % (k // 2),
                label=label)
    ax.axhline(prandtl, color="k", linestyle=":", label="Prandtl's limit load")
    ax.set_xlabel("settlement (mm)")
    ax.set_ylabel("load on the half footing (kN/m)")
    ax.set_ylim(0, None)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
