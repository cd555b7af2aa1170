#!/usr/bin/python3
"""How good is the time-left estimate of the step lines? Runs IMPM on a
scene, notes the wall time at which each step line arrives, and for the
first line at or past each of the chosen shares of the run (50 % by
default) compares the line's "left ~X" with the time the run really took
from that line to its end (the last step line). With --at-wall it does the
same for the first line at or past each share of the run's wall time (the
middle of the run as a clock on the wall sees it, where the share of the
load or time reached may be far from a half).

Usage: scripts/time_left_check.py IMPM SCENE [--set ENTRY=VALUE]...
           [--at 0.25,0.5,0.75] [--at-wall 0.5]"""
import argparse
import re
import subprocess
import sys
import time

UNITS = {"ms": 1e-3, "s": 1., "min": 60., "h": 3600.}


def seconds(text):
    match = re.fullmatch(r"([0-9.]+) ?(ms|s|min|h)", text.strip())
    if not match:
        raise ValueError(text)
    return float(match.group(1)) * UNITS[match.group(2)]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("impm")
    parser.add_argument("scene")
    parser.add_argument("--set", action="append", default=[])
    parser.add_argument("--at", default="0.5")
    parser.add_argument("--at-wall", default="")
    arguments = parser.parse_args()
    shares = [float(x) for x in arguments.at.split(",")]
    wall_shares = [float(x) for x in arguments.at_wall.split(",") if x]
    command = [arguments.impm, arguments.scene, "--overwrite"]
    for entry in arguments.set:
        command += ["--set", entry]
    start = time.time()
    lines = []  # (arrival, share, estimate)
    process = subprocess.Popen(command, stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True)
    for line in process.stdout:
        match = re.search(r" ([0-9.]+)%  step .*  left ~([0-9.]+ ?[a-z]+)", line)
        if line.startswith("step") and match:
            lines.append((time.time() - start, float(match.group(1)) / 100.,
                          seconds(match.group(2))))
    if process.wait() != 0 or not lines:
        sys.exit(f"the run failed or printed no step line: {' '.join(command)}")
    end = lines[-1][0]
    print(f"{' '.join(command[1:])}: {len(lines)} step lines, {end:.1f} s from the start to the last")
    for share in shares:
        arrival, done, estimate = next(l for l in lines if l[1] >= share)
        actual = end - arrival
        print(f"  at {100 * done:.1f} % ({arrival:.1f} s): estimate {estimate:.1f} s left, "
              f"took {actual:.1f} s: error {100 * (estimate / actual - 1):+.1f} %")
    for share in wall_shares:
        arrival, done, estimate = next(l for l in lines if l[0] >= share * end)
        actual = end - arrival
        print(f"  at {100 * share:.0f} % of the wall time ({arrival:.1f} s, {100 * done:.1f} % "
              f"of the run): estimate {estimate:.1f} s left, took {actual:.1f} s: "
              f"error {100 * (estimate / actual - 1):+.1f} %")


if __name__ == "__main__":
    main()
