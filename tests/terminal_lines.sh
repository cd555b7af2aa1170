#!/usr/bin/env bash
# What a run prints on the terminal outside test mode, on MPIEXEC N
# processes if given (only the first prints):
#  1. by default the scene's description, one line per attempt, the table
#     of timings and one line of totals: the vibrating bar (TESTS/
#     vibrating_bar.prm), explicit MUSL, 2 s in 400 steps of 0.005 s; with
#     inertia the totals name the energy balance's largest error and its
#     step, those of steps.csv's energy_error (a quasi-static run's do not);
#  2. 'Output/Terminal interval' = 150: the lines of steps 150, 300 and the
#     last (400) only; steps.csv still holds all 400;
#  3. with a cut: the collapse (TESTS/collapse_h1.prm) in 5 nominal load
#     steps takes 11, three attempts cut; at an interval of 3 the three
#     cut attempts are printed with steps 3, 6, 9 and the last, 11;
#  4. --quiet, and 'Output/Quiet' = true: only the line of totals;
#  5. --quiet on a failing run: no line on standard output, the error's one
#     line on standard error, a non-zero exit code;
#  6. a step's time resolves its time step: the bar over 2e-4 s in steps of
#     1e-5 s prints t 0.000010 s, 0.000020 s, ... 0.000200 s (four decimals
#     printed 0.0000 for all of them), and in steps of 5e-9 s 5.000e-09 s
#     to 2.000e-08 s;
#  7. the totals of a resumed run name the whole run's largest energy
#     balance error: the collapse (TESTS/collapse_h1.prm) in explicit steps
#     of 0.01 s to 1.2 s, whose largest error is at step 75, stopped after
#     step 90 and resumed from the checkpoint of step 80, names step 75 as
#     the run without a stop does (until 2026-11-29 the resumed run's
#     totals knew only the steps after the checkpoint).
# Usage: terminal_lines.sh IMPM TESTS [MPIEXEC N]
tests=$2
source "$(dirname "$0")/script_helpers.sh" "$@"
bar=("$tests/vibrating_bar.prm" --overwrite --set "Testing/Enabled=false" --set "Inertia/Integrator=explicit MUSL"
  --set "Time/End time=2" --set "Time/Time step=0.005")

# 1. Every attempt.
"${launcher[@]}" "$impm" "${bar[@]}" > out.txt 2> log.txt || fail "the bar failed"
[ "$(grep -c "^step " out.txt)" -eq 400 ] || fail "not one line per step by default"
grep -q "^Scene 'vibrating_bar' (2D)" out.txt || fail "no description of the scene"
grep -q "^| Total wallclock time elapsed since start" out.txt || fail "no table of timings"
tail -1 out.txt | grep -q "^Finished 'vibrating_bar': 400 load steps (0 cuts)" ||
  fail "the last line is not the totals"
/usr/bin/python3 - results/steps.csv "$(tail -1 out.txt)" <<'PY' ||
import csv, re, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["converged"] == "1"]
largest = max(rows, key=lambda r: abs(float(r["energy_error"])))
percent = 100. * abs(float(largest["energy_error"]))
text = "%.0f" % percent if percent >= 10 else "%.1f" % percent if percent >= 1 else "%.2g" % percent
expected = ", energy balance error at most %s %% (step %s);" % (text, largest["step"])
print("totals: ..." + sys.argv[2][sys.argv[2].index(", energy"):])
sys.exit(0 if expected in sys.argv[2] else 1)
PY
  fail "the totals do not name the energy balance's largest error of steps.csv"

# 2. Every 150th step and the last.
"${launcher[@]}" "$impm" "${bar[@]}" --set "Output/Terminal interval=150" > out.txt 2> log.txt ||
  fail "the bar with a terminal interval failed"
[ "$(grep "^step " out.txt | awk '{print $2}' | tr '\n' ' ')" = "150 300 400 " ] ||
  { cp out.txt log.txt; fail "'Terminal interval' = 150 does not print steps 150, 300 and 400"; }
[ "$(wc -l < results/steps.csv)" -eq 401 ] || fail "steps.csv does not hold every step"

# 3. Failed attempts are printed whatever the interval.
collapse=("$tests/collapse_h1.prm" --set "Testing/Enabled=false" --set "Solver/Load steps=5" --overwrite
  --set "Output/Terminal interval=3")
"${launcher[@]}" "$impm" "${collapse[@]}" > out.txt 2> log.txt || fail "the collapse failed"
grep -q "^Finished 'collapse_h1': 11 load steps (3 cuts)" out.txt ||
  { cp out.txt log.txt; fail "the collapse did not take 11 steps with 3 cuts (the test's premise)"; }
grep -q "energy balance" out.txt && fail "a quasi-static run's totals name an energy balance"

[ "$(grep -c "^step .*: step cut " out.txt)" -eq 3 ] || fail "the cut attempts are not all printed"
[ "$(grep "^step .*iterations [0-9]* " out.txt | awk '{print $2}' | tr '\n' ' ')" = "3 6 9 11 " ] ||
  { cp out.txt log.txt; fail "the converged steps printed are not 3, 6, 9 and 11"; }

# 4. Only the totals.
for quiet in "--quiet" "--set Output/Quiet=true"; do
  "${launcher[@]}" "$impm" "${bar[@]}" $quiet > out.txt 2> log.txt || fail "the bar failed ($quiet)"
  [ "$(wc -l < out.txt)" -eq 1 ] && grep -q "^Finished 'vibrating_bar': 400 load steps " out.txt ||
    { cp out.txt log.txt; fail "$quiet printed more than the line of totals"; }
done

# 5. A failing run under --quiet: its error alone.
"${launcher[@]}" "$impm" "${bar[@]}" --quiet --set "Time/Time step=0.5" > out.txt 2> err.txt &&
  fail "a time step above the stable one ran"
[ -s out.txt ] && { cp out.txt log.txt; fail "--quiet printed on standard output in a failing run"; }
grep -q "^Error: Inertia: the time step 0.5 s is above the stable explicit step" err.txt ||
  { cp err.txt log.txt; fail "--quiet hid the error"; }
# 6. The time to the step's resolution.
"${launcher[@]}" "$impm" "${bar[@]}" --set "Time/End time=2e-4" --set "Time/Time step=1e-5" \
  > out.txt 2> log.txt || fail "the bar in steps of 1e-5 s failed"
expected=$(awk 'BEGIN { for (k = 1; k <= 20; ++k) printf "%.6f ", k * 1e-5 }')
[ "$(grep "^step " out.txt | sed 's/.*  t \([^ ]*\) s .*/\1/' | tr '\n' ' ')" = "$expected" ] ||
  { cp out.txt log.txt; fail "the times of steps of 1e-5 s are not 0.000010 to 0.000200"; }
"${launcher[@]}" "$impm" "${bar[@]}" --set "Time/End time=2e-8" --set "Time/Time step=5e-9" \
  > out.txt 2> log.txt || fail "the bar in steps of 5e-9 s failed"
[ "$(grep "^step " out.txt | sed 's/.*  t \([^ ]*\) s .*/\1/' | tr '\n' ' ')" = \
  "5.000e-09 1.000e-08 1.500e-08 2.000e-08 " ] ||
  { cp out.txt log.txt; fail "the times of steps of 5e-9 s are not 5.000e-09 to 2.000e-08"; }
# 7. A resumed run's totals.
explicit=("$tests/collapse_h1.prm" --overwrite --set "Testing/Enabled=false" --set "Gravity/Ramped=false"
  --set "Time/End time=1.2" --set "Time/Time step=0.01" --set "Inertia/Enabled=true"
  --set "Inertia/Integrator=explicit MUSL" --set "Output/Interval=0" --set "Checkpoint/Interval=80")
"${launcher[@]}" "$impm" "${explicit[@]}" > out.txt 2> log.txt || fail "the explicit collapse failed"
whole=$(tail -1 out.txt | sed -n 's/.*\(, energy balance error at most [^;]*\);.*/\1/p')
[ "$whole" = ", energy balance error at most 0.69 % (step 75)" ] ||
  { cp out.txt log.txt; fail "the explicit collapse's largest error is not at step 75 (the test's premise): '$whole'"; }
"$impm" "${explicit[@]}" --stop-after-step 90 > out.txt 2> log.txt || fail "the stopped collapse failed"
"${launcher[@]}" "$impm" "${explicit[@]}" --resume > out.txt 2> log.txt || fail "the resumed collapse failed"
resumed=$(tail -1 out.txt | sed -n 's/.*\(, energy balance error at most [^;]*\);.*/\1/p')
[ "$resumed" = "$whole" ] ||
  { cp out.txt log.txt; fail "the resumed run's totals say '$resumed', the whole run's '$whole'"; }
echo "resumed: the totals name$whole"
echo "terminal_lines: passed"
