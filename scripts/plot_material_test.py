#!/usr/bin/env python3
"""The figure of a material test ('Material test' in a scene, written by
impm to its 'File'): the stress path p'-q, the compression curve e-ln p'
(when the material has a void ratio, else the volumetric strain against
ln p') and q against the axial strain (the shear stress against the shear
strain for simple shear). Compression positive, as the file.

Needs matplotlib (Debian: apt-get install python3-matplotlib, for
/usr/bin/python3).

Usage: python3 scripts/plot_material_test.py FILE.csv [FIGURE.png]
(without FIGURE, FILE with .png in place of .csv).
"""

import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    file_name = sys.argv[1]
    figure_name = (sys.argv[2] if len(sys.argv) > 2 else
                   file_name.rsplit(".", 1)[0] + ".png")
    with open(file_name) as f:
        rows = [{k: float(v) for k, v in row.items()}
                for row in csv.DictReader(f)]
    column = {key: [row[key] for row in rows] for key in rows[0]}
    kpa = 1e-3
    shear = max(abs(g) for g in column["shear_strain"]) > 0.

    fig, axes = plt.subplots(1, 3, figsize=(13, 4))
    axes[0].plot([p * kpa for p in column["p"]],
                 [q * kpa for q in column["q"]])
    axes[0].set_xlabel("p' (kPa)")
    axes[0].set_ylabel("q (kPa)")
    axes[0].set_title("stress path")

    log_p = [math.log(p) if p > 0. else float("nan") for p in column["p"]]
    if "void_ratio" in column:
        axes[1].plot(log_p, column["void_ratio"])
        axes[1].set_ylabel("void ratio e")
    else:
        axes[1].plot(log_p, column["volumetric_strain"])
        axes[1].set_ylabel("volumetric strain")
        axes[1].invert_yaxis()
    axes[1].set_xlabel("ln p' (p' in Pa)")
    axes[1].set_title("compression")

    if shear:
        axes[2].plot(column["shear_strain"],
                     [t * kpa for t in column["shear_stress"]])
        axes[2].set_xlabel("shear strain gamma")
        axes[2].set_ylabel("shear stress (kPa)")
    else:
        axes[2].plot(column["axial_strain"], [q * kpa for q in column["q"]])
        axes[2].set_xlabel("axial strain")
        axes[2].set_ylabel("q (kPa)")
    axes[2].set_title("stress-strain")
    for ax in axes:
        ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(figure_name, dpi=120)
    print("wrote " + figure_name)


if __name__ == "__main__":
    main()
