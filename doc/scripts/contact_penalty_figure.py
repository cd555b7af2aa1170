#!/usr/bin/env python3
"""The rigid plate benchmark's error against the penalty factor.

Usage: contact_penalty_figure.py TABLE.csv OUT.png

TABLE.csv is the output of scripts/contact_penalty_study.sh (columns
penalty_factor, relative_error); the dashed line is 0.25 / alpha (the
penetration p h / (alpha E) over the block's height, relative to the
strain), the dotted one the issue's 1 %.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    with open(sys.argv[1]) as f:
        rows = list(csv.DictReader(f))
    alphas = [float(row["penalty_factor"]) for row in rows]
    errors = [100.0 * float(row["relative_error"]) for row in rows]
    fig, ax = plt.subplots(figsize=(5, 3.6))
    ax.loglog(alphas, errors, "o-", label="measured (vertical stress)")
    ax.loglog(alphas, [25.0 / a for a in alphas], "--", label="0.25 / alpha")
    ax.axhline(1.0, color="grey", linestyle=":", label="1 %")
    ax.axvline(100.0, color="grey", linewidth=0.8)
    ax.set_xlabel("penalty factor alpha (stiffness alpha E / h per area)")
    ax.set_ylabel("error against a rigid plate (%)")
    ax.set_title("Rigid plate compressing a block by 25 %")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=120)


if __name__ == "__main__":
    main()
