#!/usr/bin/env python3
"""Check regenerated test outputs against the ones before the per-step
lines of the test summary were printed in its scales (issue 30).

In every .output file of TESTS_DIRECTORY that has a counterpart in
OLD_DIRECTORY and differs from it:
* the two have the same lines, except per-step lines ('step ...');
* a changed step line has the same step, load, iterations and measure
  labels, in the same order; its measures that are not forces, lengths or
  counts are printed exactly as before;
* each force (R<k>x, R<k>y, R<k>z, R<k>n, R<k>t) times S L^(dim-1), each
  length (R<k>ux, ...) times L, each count (R<k>c, R<k>s; now an integer)
  equals the old value within the rounding of both printouts: half a unit
  in the old value's last digit plus half a unit in the new value's last
  digit times the scale;
* L, S and dim are read from the file's 'scales: ' line.
It also counts the values whose new printout keeps less than the old one's
precision (the new rounding, in SI units, larger than the old).

Usage: scripts/check_scaled_step_lines.py OLD_DIRECTORY [TESTS_DIRECTORY]
with OLD_DIRECTORY holding the old tests/*.output files, e.g.
  mkdir old && for f in tests/*.output; do
    git show BASE:$f > old/$(basename $f); done
Exit status 1 if a check fails.
"""
import glob
import os
import re
import sys

NUMBER = re.compile(r'^-?\d+(?:\.(\d+))?(?:e([+-]\d+))?$')
PREFIX = re.compile(r'^(step +\d+  load \S+  iterations \d+)(.*)$')


def half_unit(printed):
    """Half a unit in the last printed digit of the number @p printed."""
    match = NUMBER.match(printed)
    if not match:
        raise ValueError('not a number: ' + printed)
    decimals = len(match.group(1) or '')
    exponent = int(match.group(2) or 0)
    return 0.5 * 10.0 ** (exponent - decimals)


def kind_of(label):
    if re.match(r'^R\d+[xyznt]$', label):
        return 'force'
    if re.match(r'^R\d+u[xyz]$', label):
        return 'length'
    if re.match(r'^R\d+[cs]$', label):
        return 'count'
    return None


def measures(rest):
    """The (label, value) pairs after 'iterations N'."""
    tokens = rest.split()
    if len(tokens) % 2:
        raise ValueError('odd measure list: ' + rest)
    return list(zip(tokens[0::2], tokens[1::2]))


def main():
    old_directory = sys.argv[1]
    tests_directory = sys.argv[2] if len(sys.argv) > 2 else 'tests'
    problems = values = coarser = 0
    changed, unchanged = [], 0
    largest = 0.  # largest |new * scale - old| / tolerance
    for new_file in sorted(glob.glob(os.path.join(tests_directory,
                                                  '*.output'))):
        name = os.path.basename(new_file)
        old_file = os.path.join(old_directory, name)
        if not os.path.exists(old_file):
            continue
        old = open(old_file).read().splitlines()
        new = open(new_file).read().splitlines()
        if old == new:
            unchanged += 1
            continue
        changed.append(name)

        def problem(*message):
            nonlocal problems
            problems += 1
            print('PROBLEM', name + ':', *message)

        if len(old) != len(new):
            problem('line count', len(old), '->', len(new))
            continue
        scales = [l for l in new if l.startswith('scales: ')]
        match = scales and re.match(r'^scales: L = (\S+) m, S = (\S+) Pa;',
                                    scales[0])
        if not match:
            problem('no scales line')
            continue
        length, stress = float(match.group(1)), float(match.group(2))
        dim = 3 if 'reactions in S L^2' in scales[0] else 2
        scale_of = {'force': stress * length ** (dim - 1), 'length': length,
                    'count': 1.}
        for number, (a, b) in enumerate(zip(old, new), 1):
            if a == b:
                continue
            ma, mb = PREFIX.match(a), PREFIX.match(b)
            if not ma or not mb:
                problem('line', number, 'changed and is no step line:', a,
                        '|', b)
                continue
            if ma.group(1) != mb.group(1):
                problem('line', number, 'step prefix changed:', ma.group(1),
                        '|', mb.group(1))
                continue
            pa, pb = measures(ma.group(2)), measures(mb.group(2))
            if [l for l, _ in pa] != [l for l, _ in pb]:
                problem('line', number, 'labels changed')
                continue
            for (label, x), (_, y) in zip(pa, pb):
                kind = kind_of(label)
                if kind is None:
                    if x != y:
                        problem('line', number, label, 'changed:', x, y)
                    continue
                if kind == 'count' and not re.match(r'^\d+$', y):
                    problem('line', number, label, 'is no integer:', y)
                    continue
                scale = scale_of[kind]
                tolerance = (half_unit(x) + half_unit(y) * scale +
                             1e-12 * abs(float(x)))
                difference = abs(float(y) * scale - float(x))
                values += 1
                largest = max(largest, difference / tolerance)
                if half_unit(y) * scale > half_unit(x) * (1 + 1e-9):
                    coarser += 1
                if difference > tolerance:
                    problem('line', number, label, 'old', x, 'new', y,
                            'scale', scale, 'difference', difference,
                            'tolerance', tolerance)
    print('files unchanged:', unchanged)
    print('files changed (%d):' % len(changed), ' '.join(changed))
    print('values checked:', values, '; problems:', problems)
    print('largest |new x scale - old| / tolerance: %.3f' % largest)
    print('values printed now with a coarser rounding than before (in SI '
          'units):', coarser)
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
