#!/usr/bin/python3
"""Two time-left estimates on recorded runs (doc/benchmarks/start_and_progress.md).

Reads the terminal output of IMPM runs (one file each, as `impm SCENE
--set "Output/Interval=0" > LOG` writes it), rebuilds each step line's
arrival from the lines' own step times, and at the first line at or past
25 %, 50 % and 75 % of the run and at half of its wall time compares with
the time the run took from there to its last line:
  recent: the estimate IMPM prints (the progress still to go times the wall
          time per unit of progress of the last five attempts);
  trend:  the rate of the last five attempts and of the five before,
          extrapolated linearly in the progress and integrated to the end
          (never below the last rate's slope of 0).
Prints each estimate's error in per cent.

Usage: scripts/time_left_estimators.py LOG [LOG ...]"""
import re
import sys

UNITS = {"ms": 1e-3, "s": 1., "min": 60., "h": 3600.}
LINE = re.compile(r" ([0-9.]+)%  step ([0-9.]+ ?[a-z]+)")


def seconds(text):
    match = re.fullmatch(r"([0-9.]+) ?(ms|s|min|h)", text.strip())
    return float(match.group(1)) * UNITS[match.group(2)]


def step_lines(path):
    """Per step line: arrival (sum of step times), progress, wall, progress made."""
    rows, arrival, before = [], 0., 0.
    for line in open(path):
        match = LINE.search(line)
        if line.startswith("step") and match:
            wall = seconds(match.group(2))
            arrival += wall
            progress = float(match.group(1)) / 100.
            rows.append((arrival, progress, wall, progress - before))
            before = progress
    return rows


def rate(window):
    """Wall time per unit of progress of the attempts, and their mean progress."""
    wall = sum(r[2] for r in window)
    progress = sum(r[3] for r in window)
    return (wall / progress if progress > 0. else None,
            sum(r[1] for r in window) / len(window))


def recent(rows, i, n=5):
    r, _ = rate(rows[max(0, i - n + 1):i + 1])
    return (1. - rows[i][1]) * r


def trend(rows, i, n=5):
    p = rows[i][1]
    r1, p1 = rate(rows[max(0, i - n + 1):i + 1])
    back = rows[max(0, i - 2 * n + 1):max(0, i - n + 1)]
    if not back:
        return (1. - p) * r1
    r0, p0 = rate(back)
    if r0 is None or p1 <= p0:
        return (1. - p) * r1
    slope = max(0., (r1 - r0) / (p1 - p0))
    left = 1. - p
    return left * r1 + slope * (left * left / 2. + left * (p - p1))


def main():
    for path in sys.argv[1:]:
        rows = step_lines(path)
        end = rows[-1][0]
        points = [(f"{100 * share:.0f} %", next(k for k, r in enumerate(rows) if r[1] >= share))
                  for share in (0.25, 0.5, 0.75)]
        half = next(k for k, r in enumerate(rows) if r[0] >= end / 2.)
        points.append((f"half of the wall time ({100 * rows[half][1]:.0f} %)", half))
        print(f"{path}: {len(rows)} step lines, {end:.1f} s")
        for label, i in points:
            actual = end - rows[i][0]
            print(f"  at {label}: took {actual:.1f} s; recent {100 * (recent(rows, i) / actual - 1):+.0f} %,"
                  f" trend {100 * (trend(rows, i) / actual - 1):+.0f} %")


if __name__ == "__main__":
    main()
