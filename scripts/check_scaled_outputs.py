"""Check every regenerated test output against the previous one, printed
before the test summary was scaled (issue 9): each scaled value times its
scale equals the old printed value within the rounding of both printouts;
all other lines are unchanged (except the Newton order line, which may now
read 'not measured', and the new scales line).

Usage: python3 scripts/check_scaled_outputs.py OLD_OUTPUT_DIRECTORY [TESTS]
with the old tests/*.output files (e.g. from `git show 9d69fab:tests/...`)."""
import re, sys, glob, os
old_directory = sys.argv[1]
tests_directory = sys.argv[2] if len(sys.argv) > 2 else "tests"
def ulp_of_printed(s):
    # half a unit in the last printed digit of s
    m = re.match(r'^-?(\d+)(?:\.(\d+))?(?:e([+-]\d+))?$', s)
    dec = len(m.group(2) or '')
    exp = int(m.group(3) or 0)
    return 0.5 * 10.0 ** (exp - dec)
nums = re.compile(r'-?\d+\.?\d*(?:e[+-]\d+)?')
bad = 0; checked = 0; order_changes = []
for new in sorted(glob.glob(os.path.join(tests_directory, '*.output'))):
    oldf = os.path.join(old_directory, os.path.basename(new))
    if not os.path.exists(oldf): continue
    o = open(oldf).read().splitlines(); n = open(new).read().splitlines()
    sc = [l for l in n if l.startswith('scales: ')]
    if not sc:
        if o != n: print('CHANGED without scales', new); bad += 1
        continue
    m = re.match(r'scales: L = (\S+) m, S = (\S+) Pa', sc[0]); L = float(m.group(1)); S = float(m.group(2))
    dim = 3 if 'S L^2' in sc[0] else 2
    F = S * L ** (dim - 1)
    n = [l for l in n if not l.startswith('scales: ')]
    if len(o) != len(n): print('LINE COUNT', new); bad += 1; continue
    for a, b in zip(o, n):
        if a == b: continue
        if a.startswith('observed Newton order'):
            order_changes.append((os.path.basename(new), a.split(': ')[-1], b.split(': ')[-1])); continue
        if a.startswith('extent'): scales = [L] * 4
        elif a.startswith('largest vertical'): scales = [S]
        elif a.startswith('final reaction'): scales = [F]
        elif a.startswith('point'):
            scales = None
        else:
            print('UNEXPECTED', new, a, '|', b); bad += 1; continue
        na, nb = nums.findall(a.split(':', 1)[1]), nums.findall(b.split(':', 1)[1])
        if a.startswith('point'):
            k = (len(na) - 2) // 2  # dim
            scales = [None] * k + [L] * k + [S, S]
        if a.startswith('final reaction') or a.startswith('largest'):
            na, nb = na[-1:], nb[-1:]
        if len(na) != len(nb): print('COUNT', new, a, b); bad += 1; continue
        for x, y, s in zip(na, nb, scales):
            if s is None:
                if x != y: print('X differs', new, a, b); bad += 1
                continue
            tol = ulp_of_printed(x) + ulp_of_printed(y) * s + 1e-12 * abs(float(x))
            checked += 1
            if abs(float(y) * s - float(x)) > tol:
                print('MISMATCH', new, x, y, s); bad += 1
print('values checked:', checked, 'problems:', bad)
for c in order_changes: print('order line', *c)
