#!/usr/bin/env bash
# The cookbook pages stay true: for each page of doc/cookbook/, the ```prm
# blocks put one after the other are the scene the page names
# (first_footing.prm), every ```sh block is run as the page gives it
# (build/impm replaced by the executable under test) and must succeed, and
# the numbers the page quotes from those runs are checked against the files
# the runs wrote (first_scene.md: the force at 0.2 m, 37.9 kN; the stiff
# layer at 5 mm, 55.9 kN without F-bar and 42.2 kN with it).
# Usage: cookbook.sh IMPM COOKBOOK_DIRECTORY
pages=$(realpath "$2")
source "$(dirname "$0")/script_helpers.sh" "$@"

/usr/bin/python3 - "$pages/first_scene.md" "$impm" <<'PY' || fail "first_scene.md"
import csv, re, shlex, subprocess, sys
page, impm = sys.argv[1], sys.argv[2]
text = open(page).read()
with open("first_footing.prm", "w") as scene:
    scene.write("\n".join(re.findall(r"```prm\n(.*?)```", text, re.S)))
for block in re.findall(r"```sh\n(.*?)```", text, re.S):
    command = block.strip()
    if command.startswith("build/impm"):
        command = shlex.quote(impm) + command[len("build/impm"):]
    run = subprocess.run(command, shell=True, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True)
    print("$ " + block.strip()[:100] + ("..." if len(block.strip()) > 100 else ""))
    print("  exit %d%s" % (run.returncode, (": " + run.stdout.strip().splitlines()[-1]) if run.stdout.strip() else ""))
    if run.returncode != 0:
        print(run.stdout)
        raise SystemExit(1)

def force(directory, load_factor):
    for row in csv.DictReader(open(directory + "/steps.csv")):
        if abs(float(row["load_factor"]) - load_factor) < 1e-9:
            return -float(row["reaction_y+_y"]) / 1e3
    raise SystemExit(f"{directory}: no step at load factor {load_factor}")

ok = True
for directory, load_factor, quoted in (("output", 1., 37.9),
                                       ("output_stiff", 0.25, 55.9),
                                       ("output_stiff", 1., 72.0),
                                       ("output_f_bar", 0.25, 42.2)):
    value = force(directory, load_factor)
    good = abs(value - quoted) <= 0.05 + 1e-9
    ok = ok and good
    print(f"{directory} at load factor {load_factor}: {value:.3f} kN, the page says {quoted} ({'ok' if good else 'DIFFERS'})")
raise SystemExit(0 if ok else 1)
PY
echo "cookbook: every command of the pages ran and the numbers they quote hold"
