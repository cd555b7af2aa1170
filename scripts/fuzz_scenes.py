#!/usr/bin/env python3
"""Mutation fuzzer for IMPM's scene reader and checks.

Corrupts the shipped scenes (prm/*.prm) at random with a fixed seed (delete a
line, duplicate a line, truncate the file, replace a number by 0, a negative,
a huge or a tiny number or nan) and runs each mutated scene with
`--stop-after-step 1` under a time-out. Every run must end in one of two
ways: exit 0, or exit 1 with exactly one line starting with "Error: " and
none of deal.II's exception text (a failed load step may list its attempts
on the lines after it). A signal or abort is a crash, the time-out a hang,
anything else raw text. Prints the counts of each outcome and every case
that is not one of the two; exits 1 if there is any. A run in which Open MPI
itself failed to start (its own "ompi_rte_init failed" report, before any
of IMPM's code runs) is run again, up to twice, and named in the output:
that is the machine's fault, not the scene reader's (seen once, 2026-11-27,
in a whole-suite run beside other tests).

Usage: fuzz_scenes.py IMPM PRM_DIRECTORY [--cases N] [--seed S]
           [--timeout SECONDS] [--exclude NAME ...] [--keep DIRECTORY]
           [--list]
"""
import argparse
import glob
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time

NUMBER = re.compile(r"(?<![\w.])[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?(?![\w.])")
MPI_START_FAILURE = re.compile(r"ompi_rte_init failed|orte_ess_init failed")
RAW_TEXT = re.compile(
    r"An error occurred in line|Stacktrace|The violated condition|"
    r"Additional information|terminate called|Aborted|Segmentation")
REPLACEMENTS = {
    "zero": "0",
    "negative": None,  # the number with its sign flipped
    "huge": "1e300",
    "huge integer": "2147483647",
    "tiny": "1e-300",
    "nan": "nan",
}


def mutate(lines, rng):
    """One random mutation of a scene's lines: (description, new lines)."""
    kind = rng.choice(["delete", "duplicate", "truncate", "number"])
    if kind == "delete":
        i = rng.randrange(len(lines))
        return f"delete line {i + 1}", lines[:i] + lines[i + 1:]
    if kind == "duplicate":
        i = rng.randrange(len(lines))
        return f"duplicate line {i + 1}", lines[:i + 1] + lines[i:]
    if kind == "truncate":
        text = "".join(lines)
        cut = rng.randrange(len(text))
        return f"truncate at byte {cut}", [text[:cut]]
    # A number on a 'set' line, replaced.
    candidates = [(i, m) for i, line in enumerate(lines)
                  if line.strip().startswith("set ")
                  for m in NUMBER.finditer(line.split("=", 1)[-1])]
    if not candidates:
        return "no change", lines
    i, match = rng.choice(candidates)
    name = rng.choice(list(REPLACEMENTS))
    value = REPLACEMENTS[name]
    if value is None:
        value = match.group(0)[1:] if match.group(0).startswith("-") \
            else "-" + match.group(0)
    head, tail = lines[i].split("=", 1)
    tail = tail[:match.start()] + value + tail[match.end():]
    return (f"line {i + 1}: {match.group(0)} -> {value} ({name})",
            lines[:i] + [head + "=" + tail] + lines[i + 1:])


def classify(status, output):
    """The outcome of one run."""
    if status is None:
        return "hang"
    if status < 0 or status > 128:
        return "crash"
    if RAW_TEXT.search(output):
        return "raw text"
    if status == 0:
        return "ran"
    error_lines = [line for line in output.splitlines()
                   if line.startswith("Error: ")]
    if status == 1 and len(error_lines) == 1:
        return "clear error"
    return "raw text"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("impm")
    parser.add_argument("prm_directory")
    parser.add_argument("--cases", type=int, default=300)
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument("--timeout", type=float, default=60.)
    parser.add_argument("--exclude", nargs="*", default=[])
    parser.add_argument("--keep", help="copy the failing scenes here")
    parser.add_argument("--list", action="store_true",
                        help="print every case's mutation and first line")
    arguments = parser.parse_args()
    # The cases run in directories of their own: a relative path to the
    # program (build/impm) is taken from where the script was started.
    arguments.impm = os.path.abspath(arguments.impm)

    scenes = sorted(path for path in glob.glob(
        os.path.join(arguments.prm_directory, "*.prm"))
        if os.path.basename(path) not in arguments.exclude)
    rng = random.Random(arguments.seed)
    counts = {}
    failures = []
    work = tempfile.mkdtemp(prefix="impm-fuzz-")
    start = time.time()
    try:
        for case in range(arguments.cases):
            scene = rng.choice(scenes)
            with open(scene) as source:
                lines = source.readlines()
            description, mutated = mutate(lines, rng)
            directory = os.path.join(work, f"case_{case}")
            os.makedirs(directory)
            path = os.path.join(directory, "scene.prm")
            with open(path, "w") as target:
                target.write("".join(mutated))
            case_start = time.time()
            for attempt in range(3):
                try:
                    run = subprocess.run(
                        [arguments.impm, path, "--stop-after-step", "1"],
                        cwd=directory, stdout=subprocess.PIPE,
                        stderr=subprocess.STDOUT, timeout=arguments.timeout)
                    status, output = run.returncode, run.stdout.decode(
                        errors="replace")
                except subprocess.TimeoutExpired:
                    status, output = None, ""
                if status == 0 or not MPI_START_FAILURE.search(output):
                    break
                print(f"case {case}: Open MPI failed to start "
                      f"(attempt {attempt + 1}); run again", flush=True)
            outcome = classify(status, output)
            counts[outcome] = counts.get(outcome, 0) + 1
            if arguments.list:
                first = next((line for line in output.splitlines()
                              if line.startswith("Error: ")), "")
                print(f"case {case} ({os.path.basename(scene)}, "
                      f"{description}): {outcome} in "
                      f"{time.time() - case_start:.1f} s {first}", flush=True)
            if outcome not in ("ran", "clear error"):
                name = os.path.basename(scene)
                failures.append((case, name, description, outcome, output))
                if arguments.keep:
                    os.makedirs(arguments.keep, exist_ok=True)
                    shutil.copy(path, os.path.join(
                        arguments.keep, f"case_{case}_{name}"))
            shutil.rmtree(directory)
    finally:
        shutil.rmtree(work, ignore_errors=True)

    for case, name, description, outcome, output in failures:
        print(f"case {case} ({name}, {description}): {outcome}")
        for line in output.splitlines()[-8:]:
            print(f"    | {line}")
    print(f"fuzz_scenes: {arguments.cases} cases from {len(scenes)} scenes "
          f"(seed {arguments.seed}) in {time.time() - start:.0f} s: " +
          ", ".join(f"{counts.get(outcome, 0)} {outcome}" for outcome in
                    ("ran", "clear error", "crash", "hang", "raw text")))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
