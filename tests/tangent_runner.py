"""The runner's keyword `tangent KIND FILE` (docs/fe2.md, "The runner's tangent file"), through servo-bc:
- a prestressed frictionless 5 x 5 disc lattice (spacing d = 2 mm, R = 1.01 mm, kn 1e4 N/m) under (D) at
  F = diag(0.999, 0.998) in 2 increments, `tight`: at every increment C1111 = C2222 = N kn / (N - 1),
  C1212 = P22 / F22, C2121 = P11 / F11 (P, F from the run's own rows), every other component 0; affine and
  condensed to 1e-8 of C1111, perturbation to 1e-4 (the issue's figures); the header has dim^4 = 16 columns;
- the same on a 4^3 sphere lattice (3D, 81 columns): C1111 = N^2 kn / ((N - 1)^2 d), C_ijij = P_jj / F_jj;
- the perturbations leave the run as it was: the rows with `tangent perturbation` equal those without, byte for
  byte;
- a frictional 5 x 5 lattice (ks 2e3 N/m, mu 0.4, nothing slides) under (P) and (T): condensed against
  perturbation within 1e-3 of |C| (the issue's figure before sliding; measured 9e-5 and 1.3e-4);
- cohesive bonds on the touching lattice stretched along x: the perturbation tangent's C1111 = C2222 =
  N kb_n / (N - 1) to 1e-4, the condensed one's to 1e-9 (interior dynamic and newton); affine refused by line
  and keyword;
- refusals: `tangent` with mixed, an unknown kind, and a tangent file over the script, each with the line and the
  keyword; `servo-bc --decks` leaves the keyword out of the hosts' decks.
Prints "N passed, N failed". Usage: python3 tests/tangent_runner.py SERVO_BC"""
import csv
import math
import os
import re
import subprocess
import sys
import tempfile

runner = os.path.abspath(sys.argv[1])
passed = failed = 0
N, D, R, KN = 5, 2e-3, 1.01e-3, 1e4


def check(ok, label):
    global passed, failed
    passed, failed = passed + bool(ok), failed + (not ok)
    print('%stangent runner: %s' % ('' if ok else 'FAIL ', label))


def run(folder, name, lines, args=()):
    path = os.path.join(folder, name + '.sbc')
    with open(path, 'w') as f:
        f.write('\n'.join(lines) + '\n')
    p = subprocess.run([runner, *args, name + '.sbc'], cwd=folder, capture_output=True, text=True)
    return p.returncode, p.stdout + p.stderr


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def case(folder, name, dim, bc, kind, F, friction=False, extra=''):
    """the script of one run; its tangent file NAME_C.csv, rows NAME.csv"""
    words = 'servo_bc %s F %s increments %d accuracy tight%s file %s.csv' % (
        bc, ' '.join('%g' % v for v in F), 2 if dim == 2 else 1, extra, name)
    if kind:
        words += ' tangent %s %s_C.csv' % (kind, name)
    packing = ('lattice square %d %d spacing %g radius %g' % (N, N, D, R) if dim == 2 else
               'lattice cubic 4 4 4 spacing %g radius %g' % (D, R))
    law = 'contact frictional kn %g ks %s' % (KN, '2e3 mu 0.4' if friction else '0 mu 0')
    return run(folder, name, ['dimension %d' % dim, packing, law, 'density %g' % (2e3 if dim == 2 else 2650),
                              'timestep 2e-6', words, 'run'])


def closed_form(dim, tangent, results):
    """largest |C - closed form| / C1111 over the increments, and the count of increments"""
    n = 4 if dim == 3 else N
    c1111 = KN * n / (n - 1) if dim == 2 else KN * n * n / ((n - 1) ** 2 * D)
    worst = 0.0
    for t, r in zip(tangent, results):
        for i in range(dim):
            for j in range(dim):
                for k in range(dim):
                    for l in range(dim):
                        if i == j == k == l:
                            want = c1111
                        elif i == k and j == l and i != j:
                            want = float(r['P%d%d' % (j + 1, j + 1)]) / float(r['F%d%d' % (j + 1, j + 1)])
                        else:
                            want = 0.0
                        got = float(t['C%d%d%d%d' % (i + 1, j + 1, k + 1, l + 1)])
                        worst = max(worst, abs(got - want) / c1111)
    return worst, len(tangent)


with tempfile.TemporaryDirectory() as tmp:
    for dim, F in ((2, (0.999, 0, 0, 0.998)), (3, (0.999, 0, 0, 0, 0.998, 0, 0, 0, 0.997))):
        for kind, tol in (('affine', 1e-8), ('condensed', 1e-8), ('perturbation', 1e-4)):
            name = 'lattice%d_%s' % (dim, kind)
            rc, log = case(tmp, name, dim, 'D', kind, F)
            if rc != 0:
                check(False, '%dD lattice, %s: the run stopped: %s' % (dim, kind, log.strip().splitlines()[-1]))
                continue
            t, r = rows(os.path.join(tmp, name + '_C.csv')), rows(os.path.join(tmp, name + '.csv'))
            with open(os.path.join(tmp, name + '_C.csv')) as f:
                header = f.readline().strip().split(',')
            worst, count = closed_form(dim, t, r)
            check(count == len(r) and len(header) == 1 + dim ** 4 and worst <= tol,
                  '%dD frictionless lattice (D), %s: %d rows of %d columns, closed form to %.2e of C1111 (%g)'
                  % (dim, kind, count, len(header), worst, tol))
        rc, log = case(tmp, 'plain%d' % dim, dim, 'D', None, F)
        with open(os.path.join(tmp, 'plain%d.csv' % dim), 'rb') as a, \
                open(os.path.join(tmp, 'lattice%d_perturbation.csv' % dim), 'rb') as b:
            check(rc == 0 and a.read() == b.read(),
                  '%dD: the rows with tangent perturbation equal those without, byte for byte' % dim)

    for bc in ('P', 'T'):
        C = {}
        for kind in ('condensed', 'perturbation'):
            name = 'friction_%s_%s' % (bc, kind)
            rc, log = case(tmp, name, 2, bc, kind, (0.999, 0, 0, 0.998), friction=True)
            C[kind] = rows(os.path.join(tmp, name + '_C.csv'))[-1] if rc == 0 else None
        if C['condensed'] and C['perturbation']:
            keys = [k for k in C['condensed'] if k != 'increment']
            norm = math.sqrt(sum(float(C['perturbation'][k]) ** 2 for k in keys))
            diff = max(abs(float(C['condensed'][k]) - float(C['perturbation'][k])) for k in keys) / norm
            check(diff <= 1e-3, 'frictional 5 x 5 lattice (%s): condensed against perturbation %.2e of |C| (1e-3)'
                  % (bc, diff))
        else:
            check(False, 'frictional 5 x 5 lattice (%s): a run stopped' % bc)

    # cohesive bonds (eqs. 7-8) on the touching lattice, stretched by F11 = 1.001 in 2 increments: the
    # perturbation tangent C1111 = C2222 = N kb_n / (N - 1) (the bonds hold in tension as in compression) at
    # increment 0 and both increments; the condensed tangent alike (the bonds' blocks), the affine refused
    bonded = ['dimension 2', 'lattice square 5 5 spacing 2e-3 radius 1e-3',
              'contact cohesive kn 1e4 ks 4e3 kr 1e-4 fn 1e3 fs 1e3 mr 1e3 mu 0', 'density 2e3', 'timestep 2e-6']
    rc, log = run(tmp, 'bonded', bonded + ['servo_bc D F 1.001 0 0 1 increments 2 accuracy tight file bonded.csv '
                                           'tangent perturbation bonded_C.csv', 'run'])
    C = rows(os.path.join(tmp, 'bonded_C.csv')) if rc == 0 else []
    want = N * KN / (N - 1)
    worst = max((abs(float(c['C1111']) - want) / want for c in C), default=float('inf'))
    vertical = max((abs(float(c['C2222']) - want) / want for c in C), default=float('inf'))
    check(len(C) == 3 and worst <= 1e-4 and vertical <= 1e-4, 'cohesive bonds: perturbation C1111 and C2222 within '
          '%.2e and %.2e of N kb_n / (N - 1) at %d rows%s' % (worst, vertical, len(C),
                                                                '' if rc == 0 else ': ' + log[-200:]))
    for interior in ('dynamic', 'newton'):  # the bonds' blocks in the condensed tangent
        rc, log = run(tmp, 'bonded_condensed_' + interior,
                      bonded + ['servo_bc D F 1.001 0 0 1 increments 2 accuracy tight interior %s tangent condensed '
                                'bonded_%s.csv' % (interior, interior), 'run'])
        C = rows(os.path.join(tmp, 'bonded_%s.csv' % interior)) if rc == 0 else []
        worst = max((abs(float(c[k]) - want) / want for c in C for k in ('C1111', 'C2222')), default=float('inf'))
        check(len(C) == 3 and worst <= 1e-9, 'cohesive bonds, interior %s: condensed C1111 and C2222 within %.2e of '
              'N kb_n / (N - 1) at %d rows%s' % (interior, worst, len(C), '' if rc == 0 else ': ' + log[-200:]))
    rc, log = run(tmp, 'bonded_affine', bonded + ['servo_bc D F 1.001 0 0 1 tangent affine b.csv', 'run'])
    check(rc != 0 and 'servo_bc (line 6)' in log and "keyword 'tangent'" in log and 'expected condensed or '
          'perturbation' in log, 'cohesive bonds: affine refused: ' + log.strip().splitlines()[-1])
    rc, log = run(tmp, 'mixed', ['dimension 2', 'lattice square 5 5 spacing 2e-3 radius 1.01e-3',
                                 'contact frictional kn 1e4 ks 0 mu 0', 'density 2e3', 'timestep 2e-6',
                                 'servo_bc mixed stress P22 -10 1 F 1 0.001 0 1 tangent condensed m.csv', 'run'])
    check(rc != 0 and "mixed.sbc:7" in log and "keyword 'tangent'" in log and 'mixed' in log,
          'mixed refused: ' + log.strip().splitlines()[-1])
    rc, log = run(tmp, 'kind', ['dimension 2', 'servo_bc D tangent secant k.csv'])
    check(rc != 0 and "kind.sbc:2" in log and "kind 'secant' is not valid (expected affine, condensed or perturbation)"
          in log, 'unknown kind refused: ' + log.strip().splitlines()[-1])
    rc, log = run(tmp, 'over', ['dimension 2', 'lattice square 5 5 spacing 2e-3 radius 1.01e-3',
                                'contact frictional kn 1e4 ks 0 mu 0', 'density 2e3', 'timestep 2e-6',
                                'servo_bc D tangent affine over.sbc', 'run'])
    check(rc != 0 and "keyword 'tangent' 'over.sbc' is this script" in log and
          os.path.getsize(os.path.join(tmp, 'over.sbc')) > 100, 'a tangent file over the script refused, the script '
          'intact: ' + log.strip().splitlines()[-1])
    os.mkdir(os.path.join(tmp, 'decks'))
    rc, log = case(tmp, 'decked', 2, 'P', 'condensed', (0.999, 0, 0, 0.998))
    rc, log = run(tmp, 'decked', open(os.path.join(tmp, 'decked.sbc')).read().splitlines(), ('--decks', 'decks'))
    decks = [os.path.join(tmp, 'decks', f) for f in os.listdir(os.path.join(tmp, 'decks'))]
    texts = [open(f).read() for f in decks if os.path.isfile(f)]
    check(rc == 0 and texts and not any(re.search(r'servo_bc.*\btangent\b', t) for t in texts),
          '--decks: %d files, none with the keyword tangent' % len(texts))

print('%d passed, %d failed' % (passed, failed))
sys.exit(failed > 0)
