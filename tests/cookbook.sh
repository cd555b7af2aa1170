#!/usr/bin/env bash
# The cookbook pages stay true, and every scene in prm/ runs. For each page
# of doc/cookbook/ (in its own scratch folder, with prm/ linked into it):
# * its ```prm blocks, put one after the other, are the scene file that the
#   page names in "<!-- scene file: NAME -->" (first_scene.md);
# * every line of its ```sh blocks is run as the page gives it, in order,
#   with build/impm replaced by the executable under test; a line that runs
#   build/impm gets the shortening the page declares for that block in a
#   "<!-- test: --set ... -->" comment just before it, after
#   --set Testing/Enabled=true --set Output/Interval=0 (so that a page may
#   ask for point files, e.g. to check them); such a run must
#   complete, keep its mass (the test summary's "total mass: A (initial
#   B)"), pass every check of the test summary (none ends in "NO" or says
#   "NO ("), and write a summary.json;
# * each "<!-- check VALUE: EXPRESSION -->" compares a number the page
#   quotes with the Python EXPRESSION evaluated on the files the runs wrote,
#   to half a unit of VALUE's last digit (helpers below: steps(), last(),
#   at(), summary(), printed()).
# Every scene prm/NAME.prm must be run by some page (a line starting
# "build/impm prm/NAME.prm"), else the test fails: a new scene needs its
# page. This test replaces the former tests/prm_scenes (every scene run
# shortened, mass, the test summary's checks, summary.json).
# Usage: cookbook.sh IMPM COOKBOOK_DIRECTORY
pages=$(realpath "$2")
source "$(dirname "$0")/script_helpers.sh" "$@"

/usr/bin/python3 - "$impm" "$pages" <<'PY' || fail "the cookbook"
import csv, glob, json, math, os, re, shlex, subprocess, sys, time
impm, pages = sys.argv[1], sys.argv[2]
root = os.path.dirname(os.path.dirname(pages))
work = os.getcwd()
testing = '--set Testing/Enabled=true --set Output/Interval=0'
failures = []


def fail(message):
    failures.append(message)
    print("FAILED: " + message)


def steps(directory="output"):
    """The rows of DIRECTORY/steps.csv, every value a float."""
    rows = []
    for row in csv.DictReader(open(directory + "/steps.csv")):
        rows.append({k: float(v) if v not in ("", None) else math.nan
                     for k, v in row.items()})
    return rows


def last(directory, column):
    """COLUMN of the last converged row of DIRECTORY/steps.csv."""
    return [r for r in steps(directory) if r.get("converged", 1) == 1][-1][column]


def at(directory, column, load_factor):
    """COLUMN of the converged row at LOAD_FACTOR."""
    for r in steps(directory):
        if r.get("converged", 1) == 1 and abs(r["load_factor"] - load_factor) < 1e-9:
            return r[column]
    raise ValueError("%s: no converged step at load factor %g" % (directory, load_factor))


def summary(directory="output"):
    return json.load(open(directory + "/summary.json"))


printout = []


def printed(pattern):
    """The number in the first group of PATTERN's last match in the
    printouts of the page's commands so far."""
    matches = re.findall(pattern, "\n".join(printout), re.M)
    if not matches:
        raise ValueError("nothing printed matches " + pattern)
    match = matches[-1]
    return float(match[0] if isinstance(match, tuple) else match)


def tolerance(value):
    """Half a unit of the last digit of VALUE as written (37.9: 0.05)."""
    mantissa, _, exponent = value.lower().partition("e")
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    return 0.5 * 10 ** (int(exponent or 0) - decimals)


scenes = sorted(os.path.basename(p)[:-4] for p in glob.glob(root + "/prm/*.prm"))
run_by_pages = set()
total_start = time.time()
for page in sorted(glob.glob(pages + "/*.md")):
    name = os.path.basename(page)[:-3]
    text = open(page).read()
    folder = os.path.join(work, name)
    os.makedirs(folder)
    os.chdir(folder)
    os.symlink(os.path.join(root, "prm"), "prm")
    page_start = time.time()
    del printout[:]
    blocks = re.findall(r"```prm\n(.*?)```", text, re.S)
    if blocks:
        scene_file = re.search(r"<!-- scene file: (\S+) -->", text)
        if not scene_file:
            fail(name + ": ```prm blocks but no '<!-- scene file: NAME -->'")
            continue
        with open(scene_file.group(1), "w") as scene:
            scene.write("\n".join(blocks))
    for shortening, block in re.findall(
            r"(?:<!-- test: ([^\n]*?) -->\s*)?```sh\n(.*?)```", text, re.S):
        for line in block.splitlines():
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            command, runs_impm = line, line.startswith("build/impm ")
            if runs_impm:
                scene_run = re.match(r"build/impm prm/(\S+)\.prm", line)
                if scene_run:
                    run_by_pages.add(scene_run.group(1))
                command = " ".join([shlex.quote(impm), line[len("build/impm "):],
                                    testing, shortening])
            start = time.time()
            run = subprocess.run(command, shell=True, stdout=subprocess.PIPE,
                                 stderr=subprocess.STDOUT, text=True)
            printout.append(run.stdout)
            shown = line if len(line) <= 100 else line[:97] + "..."
            print("%s: $ %s%s  (%.1f s)" % (name, shown, "  " + shortening if shortening and runs_impm else "",
                                            time.time() - start))
            if run.returncode != 0:
                fail("%s: '%s' exited with %d:\n%s" % (name, line, run.returncode,
                                                     "\n".join(run.stdout.splitlines()[-10:])))
                continue
            if not runs_impm:
                print("  " + "\n  ".join(run.stdout.strip().splitlines()[-3:]))
                continue
            mass = re.search(r"^total mass: (\S+) \(initial (\S+)\)$", run.stdout, re.M)
            if not mass or mass.group(1) != mass.group(2):
                fail("%s: '%s': mass %s" % (name, line, mass.groups() if mass else "not printed"))
            for check in re.findall(r"^.*(?:NO$|NO \().*$", run.stdout, re.M):
                fail("%s: '%s': %s" % (name, line, check))
            written = [s for s in glob.glob("**/summary.json", recursive=True)
                       if os.path.getmtime(s) >= start - 0.05]
            if not written:
                fail("%s: '%s' wrote no summary.json" % (name, line))
            print("  %d load steps, %d cut, mass kept" % (
                len(re.findall(r"^step ", run.stdout, re.M)),
                len(re.findall(r": step cut$", run.stdout, re.M))))
    for value, expression in re.findall(r"<!-- check (\S+): (.*?) -->", text, re.S):
        try:
            computed = eval(expression)
        except Exception as error:
            fail("%s: check '%s': %s" % (name, expression, error))
            continue
        good = abs(computed - float(value)) <= tolerance(value) * (1 + 1e-9)
        print("  %s: %.6g, the page says %s (%s)" % (expression, computed, value,
                                                      "ok" if good else "DIFFERS"))
        if not good:
            fail("%s: %s is %.6g, the page says %s" % (name, expression, computed, value))
    print("%s: %.1f s" % (name, time.time() - page_start))
    os.chdir(work)
for scene in scenes:
    if scene not in run_by_pages:
        fail("prm/%s.prm has no cookbook page (no page runs 'build/impm prm/%s.prm')"
             % (scene, scene))
print("%d pages, %d scenes, %.1f s" % (len(glob.glob(pages + "/*.md")), len(scenes),
                                       time.time() - total_start))
raise SystemExit(1 if failures else 0)
PY
echo "cookbook: every command of the pages ran and the numbers they quote hold"
