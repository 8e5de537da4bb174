"""The FE^2 biaxial demo (make fe2-demo, docs/fe2.md "The biaxial demo"): plane-strain biaxial compression of a
square specimen of frictional discs, once as FE^2 with (D), (P) and (T) aggregates at the Gauss points and once
as a direct DEM simulation (DNS) of the whole specimen, with the same particle statistics.

The material: discs of radii uniform in [1, 2] mm (kn 1e4 N/m, ks 2e3 N/m, mu 0.4, 2000 kg/m^2), a periodic
packing jammed by the runner's `generate periodic` and compressed by 1 % (`strain 0.01`), so that it carries a
prestress. Every Gauss point gets its own packing of n0 discs (seed 1, 2, ...: a heterogeneous specimen); the
DNS packing has n0 times the number of Gauss points (seed 1000), and its box sets the specimen's side L.

The test: the sides under the lateral pressure p (N/m) from the start, the platens smooth (the bottom's vertical
displacement 0, the top's -u, the bottom-left corner's horizontal one 0 in FE), then u in `steps` equal steps to
L * strain. The DNS is the runner's mixed frame on the whole specimen: `left T D`, `right T D` under `stress P11
-p 0` (held from increment 0), `bottom D D`, `top D D` following F22 = 1 - u / L (its platens move sideways with
the specimen's mean lateral stretch, F11 measured). Force per unit thickness on the top (N), compression
positive: FE^2 the reactions of the top's vertical dofs, DNS -P22 L.

Writes OUT/biaxial.csv (u,force_D,force_P,force_T,force_DNS, m and N), one CSV per curve for the figure, and
prints the cost of each. A path that stops (a point that fails below the smallest step cut) keeps its rows, leaves
its later cells empty, and makes the script exit 1 after writing everything. Usage (defaults: the demo's size, a few minutes on 2 cores):
  python3 fe2/biaxial.py [--n0 100] [--elements 1] [--steps 4] [--strain 0.01] [--pressure 50] [--out out/fe2]
                         [--runner build/servo-bc] [--plot build/servo-bc-plot] [--threads 2]"""
import argparse
import os
import subprocess
import sys
import time

import numpy as np

import macro

KN, KS, MU, DENSITY, DT = 1e4, 2e3, 0.4, 2e3, 1e-4  # N/m, N/m, -, kg/m^2, s (0.09 of the critical step)
LAW = 'contact frictional kn %g ks %g mu %g\ndensity %g\ntimestep %g' % (KN, KS, MU, DENSITY, DT)
GENERATE = 'generate periodic n0 %d rmin 1e-3 polydispersity 2 seed %d strain 0.01'
# (T) sealed: without the walls an interior disc of one 2 x 2 point escapes between frame discs (docs/fe2.md)
WORDS = {'D': 'D accuracy tight', 'P': 'P accuracy tight', 'T': 'T accuracy tight seal yes'}
TOLERANCE = 1e-3  # the macro Newton's, of the reaction: the points' frictional equilibria are not smoother


def run(runner, script, path):
    with open(path, 'w') as f:
        f.write(script)
    done = subprocess.run([runner, path], capture_output=True, text=True)
    if done.returncode:
        sys.exit('fe2/biaxial.py: %s failed: %s' % (path, (done.stderr or done.stdout).strip()[-400:]))
    return done.stdout


def packing_path(out, n0, seed):
    return os.path.abspath(os.path.join(out, 'packing_n%d_seed%d.txt' % (n0, seed)))


def packing(runner, out, n0, seed):
    """A generated packing (x [2n], r [n], box [4]) from the runner's write_packing text, kept in out."""
    path = packing_path(out, n0, seed)
    if os.path.exists(path):
        try:
            return macro.read_packing(path)
        except ValueError as e:          # a torn cache: made again, never used
            print('fe2/biaxial.py: %s; generating it again' % e, flush=True)
            os.remove(path)
    run(runner, 'dimension 2\n%s\n%s\nwrite_packing text %s\n' % (LAW, GENERATE % (n0, seed), path),
        path + '.sbc')
    return macro.read_packing(path)


def fe2(bc, args, L, us):
    """The top force (N, compression positive) at each u of us, and the wall time."""
    t0 = time.time()

    def make_point(k, X):
        x, r, box = packing(args.runner, args.out, args.n0, k + 1)
        return macro.core.MaterialPoint(x, r, WORDS[bc], kn=KN, ks=KS, mu=MU, density=DENSITY, dt=DT, box=box)

    n = args.elements
    model = macro.Macro(L, L, n, n, make_point, tangent='condensed', threads=args.threads)
    created = time.time() - t0
    x, y, c = model.X[0], model.X[1], model.comp
    bottom = np.flatnonzero(np.isclose(y, 0.0) & (c == 1))
    top = np.flatnonzero(np.isclose(y, L) & (c == 1))
    corner = np.flatnonzero(np.isclose(x, 0.0) & np.isclose(y, 0.0) & (c == 0))
    fixed = np.concatenate([bottom, top, corner])
    lateral = macro.boundary_forces([-args.pressure, 0, 0, 0, 0, 0, 0, 0, 0], L, L, n, n, model.X, c)
    forces, u_prev, seen = [], 0.0, []

    def values_at(u0, u1):
        return lambda t: np.concatenate([np.zeros(len(bottom)), np.full(len(top), -(u0 + t * (u1 - u0))),
                                         np.zeros(len(corner))])
    for u in us:
        seen.clear()
        try:
            cuts = model.load(fixed, values_at(u_prev, u), 1, tol=TOLERANCE, max_iterations=15,
                              on_step=lambda t, m, history: seen.append(len(history) - 1),
                              external_at=lambda t: lateral)
        except macro.MacroFailure as e:  # the path ends here; the rows before it stand
            print('fe2/biaxial.py: (%s) stopped at u = %g m: %s' % (bc, u, e), flush=True)
            return forces, created, time.time() - t0
        u_prev = u
        forces.append(-float(np.sum(model.trial_r[top])))
        print('fe2 (%s): u %.4e m, force %.6g N, Newton iterations %s, %d cut(s), %d uncertified points'
              % (bc, u, forces[-1], '+'.join(str(v) for v in seen), cuts, model.uncertified), flush=True)
    return forces, created, time.time() - t0


def dns(args, L, us):
    """The DNS's top force (N) at each u of us, its packing's disc count and the wall time."""
    t0 = time.time()
    csv = os.path.join(args.out, 'biaxial_dns_rows.csv')
    n0 = args.n0 * 4 * args.elements ** 2
    steps = len(us) - 1
    packing(args.runner, args.out, n0, 1000)
    run(args.runner, 'dimension 2\n%s\nread_packing %s\n'
        'servo_bc mixed bottom D D top D D left T D right T D stress P11 %.17g 0 F 1 0 0 %.17g increments %d '
        'accuracy tight file %s\nrun\n' % (LAW, packing_path(args.out, n0, 1000), -args.pressure, 1.0 - us[-1] / L,
                                           steps, csv), os.path.join(args.out, 'biaxial_dns.sbc'))
    head, *rows = [line.strip().split(',') for line in open(csv)]
    P22, F22 = head.index('P22'), head.index('F22')
    forces = [-float(row[P22]) * L for row in rows]
    got = [(1.0 - float(row[F22])) * L for row in rows]
    if len(rows) != len(us) or max(abs(a - b) for a, b in zip(got, us)) > 1e-9 * L:
        sys.exit('fe2/biaxial.py: the DNS rows (%d) are not at the platen displacements of FE^2' % len(rows))
    with open(packing_path(args.out, n0, 1000)) as f:
        discs = f.readline().strip('# \n')
    return forces, discs, time.time() - t0


def main():
    a = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    a.add_argument('--n0', type=int, default=100)
    a.add_argument('--elements', type=int, default=1)
    a.add_argument('--steps', type=int, default=4)
    a.add_argument('--strain', type=float, default=0.01)
    a.add_argument('--pressure', type=float, default=50.0)
    a.add_argument('--out', default='out/fe2')
    a.add_argument('--runner', default='build/servo-bc')
    a.add_argument('--plot', default='build/servo-bc-plot')
    a.add_argument('--threads', type=int, default=2)
    a.add_argument('--only', default='D,P,T,DNS')
    args = a.parse_args()
    os.makedirs(args.out, exist_ok=True)
    only = args.only.split(',')
    _, _, box = packing(args.runner, args.out, args.n0 * 4 * args.elements ** 2, 1000)
    L = box[1] - box[0]
    us = [L * args.strain * k / args.steps for k in range(args.steps + 1)]
    print('fe2 biaxial: specimen %.6g m square, %d x %d elements, %d points of n0 %d discs, p %g N/m, u to %.4g m'
          % (L, args.elements, args.elements, 4 * args.elements ** 2, args.n0, args.pressure, us[-1]), flush=True)
    curves, cost = {}, {}
    for bc in ('D', 'P', 'T'):
        if bc in only:
            curves[bc], created, wall = fe2(bc, args, L, us)
            cost[bc] = 'points created in %.1f s, whole path %.1f s' % (created, wall)
    if 'DNS' in only:
        curves['DNS'], discs, wall = dns(args, L, us)
        cost['DNS'] = '%s; %.1f s' % (discs.strip(), wall)
    names = [k for k in ('D', 'P', 'T', 'DNS') if k in curves]
    with open(os.path.join(args.out, 'biaxial.csv'), 'w') as f:  # a path that stopped leaves its cells empty
        f.write('u,' + ','.join('force_' + k for k in names) + '\n')
        for i, u in enumerate(us):
            f.write('%.17g,' % u + ','.join('%.17g' % curves[k][i] if i < len(curves[k]) else ''
                                            for k in names) + '\n')
    files = []
    for k in names:
        path = os.path.join(args.out, 'biaxial_%s.csv' % k)
        with open(path, 'w') as f:
            f.write('u,force\n' + ''.join('%.17g,%.17g\n' % (u, v) for u, v in zip(us, curves[k])))
        files += [path, 'FE2 (%s)' % k if k != 'DNS' else 'DNS']
    if os.path.exists(args.plot):
        subprocess.run([args.plot, os.path.join(args.out, 'biaxial.svg'), 'biaxial compression, p = %g N/m'
                        % args.pressure, 'platen displacement u (mm)', 'force on the platen (N)', 'u', '1e3', 'force',
                        '1'] + files, check=True)
    for k in names:
        print('fe2 biaxial %s: %s' % (k, cost[k]))
    print('fe2 biaxial: wrote %s' % os.path.join(args.out, 'biaxial.csv'))
    stopped = [k for k in names if len(curves[k]) < len(us)]
    if stopped:
        sys.exit('fe2/biaxial.py: the path of %s stopped before u = %g m (above)' % (', '.join(stopped), us[-1]))


if __name__ == '__main__':
    main()
