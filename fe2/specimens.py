"""The packings of the FE^2 demos (fe2/biaxial.py, fe2/triaxial.py): made once by the runner's `generate periodic`
and kept in the output folder, read back with macro.read_packing (a torn file is made again, never used)."""
import argparse
import os
import subprocess
import sys
import time

import numpy as np

import macro


def run(runner, script, path):
    """Writes script to path and runs the runner on it; exits with its error when it fails. Returns its output."""
    with open(path, 'w') as f:
        f.write(script)
    done = subprocess.run([runner, path], capture_output=True, text=True)
    if done.returncode:
        sys.exit('fe2: %s failed: %s' % (path, (done.stderr or done.stdout).strip()[-400:]))
    return done.stdout


def packing_path(out, n0, seed, dim=2):
    return os.path.abspath(os.path.join(out, 'packing%s_n%d_seed%d.txt' % ('' if dim == 2 else '3d', n0, seed)))


def cube(x):
    """[0, L] three times: the periodic cube of a generated 3D packing (x [3 n]), whose corner particle sits at the
    origin with its copies at exactly L on each axis: L the largest x of a particle at y = z = 0."""
    return [0.0, max(x[3 * k] for k in range(len(x) // 3) if x[3 * k + 1] == 0.0 and x[3 * k + 2] == 0.0)] * 3


def packing(runner, out, law, generate, n0, seed, dim=2):
    """The packing `generate` % (n0, seed) under law (the runner's contact, density and timestep lines): x [dim n],
    r [n], box ([x0, x1, y0, y1] in 2D; cube(x) in 3D)."""
    path = packing_path(out, n0, seed, dim)
    if os.path.exists(path):
        try:
            x, r, box = macro.read_packing(path, dim)
            return x, r, box if dim == 2 else cube(x)
        except ValueError as e:          # a torn cache: made again, never used
            print('fe2: %s; generating it again' % e, flush=True)
            os.remove(path)
    run(runner, 'dimension %d\n%s\n%s\nwrite_packing text %s\n' % (dim, law, generate % (n0, seed), path),
        path + '.sbc')
    x, r, box = macro.read_packing(path, dim)
    return x, r, box if dim == 2 else cube(x)


def write_curves(out, name, us, curves, plot, title, ylabel):
    """OUT/NAME.csv (u,force_K... for K in D, P, T, DNS; a path that stopped leaves its later cells empty), one
    CSV per curve and, when the plot program exists, OUT/NAME.svg. Returns the curves' names."""
    names = [k for k in ('D', 'P', 'T', 'DNS') if k in curves]
    with open(os.path.join(out, name + '.csv'), 'w') as f:
        f.write('u,' + ','.join('force_' + k for k in names) + '\n')
        for i, u in enumerate(us):
            f.write('%.17g,' % u + ','.join('%.17g' % curves[k][i] if i < len(curves[k]) else ''
                                            for k in names) + '\n')
    files = []
    for k in names:
        path = os.path.join(out, '%s_%s.csv' % (name, k))
        with open(path, 'w') as f:
            f.write('u,force\n' + ''.join('%.17g,%.17g\n' % (u, v) for u, v in zip(us, curves[k])))
        files += [path, 'FE2 (%s)' % k if k != 'DNS' else 'DNS']
    if os.path.exists(plot):
        subprocess.run([plot, os.path.join(out, name + '.svg'), title, 'platen displacement u (mm)', ylabel, 'u',
                        '1e3', 'force', '1'] + files, check=True)
    return names


def platen_path(model, bottom, top, held, lateral, us, label, tolerance, histories=None):
    """The platen test of the demos: the dofs bottom and held at 0, top at -u for each u of us in turn (one load
    step each, cut where it must), under the nodal loads lateral, the macro Newton to tolerance of the reaction.
    Returns the top force (N, compression positive: minus the reactions of top) at each u reached; a path that
    stops (MacroFailure) prints why and returns the forces before it. A line per macro iteration (u, iteration,
    residual over the reaction, seconds since the path began) and one per step. histories (a list): gets the macro Newton's
    residual history of every committed step."""
    fixed = np.concatenate([bottom, top, held])
    forces, u_prev, seen, t0 = [], 0.0, [], time.time()

    def progress(step, iteration, residual):   # a line per macro iteration: a long step is never silent
        print('fe2 %s: u %.4e m, iteration %d, residual %.3e of the reaction, %.1f s'
              % (label, u, iteration, residual, time.time() - t0), flush=True)

    def values_at(u0, u1):
        return lambda t: np.concatenate([np.zeros(len(bottom)), np.full(len(top), -(u0 + t * (u1 - u0))),
                                         np.zeros(len(held))])
    for u in us:
        seen.clear()
        try:
            cuts = model.load(fixed, values_at(u_prev, u), 1, tol=tolerance, max_iterations=15,
                              on_step=lambda t, m, history: (seen.append(len(history) - 1),
                                                             histories is not None and histories.append(history)),
                              external_at=lambda t: lateral, on_iteration=progress)
        except macro.MacroFailure as e:  # the path ends here; the rows before it stand
            print('fe2 %s stopped at u = %g m: %s' % (label, u, e), flush=True)
            return forces
        u_prev = u
        forces.append(-float(np.sum(model.trial_r[top])))
        print('fe2 %s: u %.4e m, force %.6g N, Newton iterations %s, %d cut(s), %d uncertified points'
              % (label, u, forces[-1], '+'.join(str(v) for v in seen), cuts, model.uncertified), flush=True)
    return forces


def arguments(doc, n0, pressure, only):
    """The demos' command line (their docstrings give it), with their defaults of n0, pressure and only."""
    a = argparse.ArgumentParser(description=doc.split('\n')[0])
    a.add_argument('--n0', type=int, default=n0)
    a.add_argument('--elements', type=int, default=1)
    a.add_argument('--steps', type=int, default=4)
    a.add_argument('--strain', type=float, default=0.01)
    a.add_argument('--pressure', type=float, default=pressure)
    a.add_argument('--out', default='out/fe2')
    a.add_argument('--runner', default='build/servo-bc')
    a.add_argument('--plot', default='build/servo-bc-plot')
    a.add_argument('--threads', type=int, default=2)
    a.add_argument('--only', default=only)
    a.add_argument('--specimen', type=int, default=0)
    args = a.parse_args()
    os.makedirs(args.out, exist_ok=True)
    return args


def point_seed(args, k):
    """The seed of Gauss point k's packing: k + 1 in specimen 0, 10000 S + k + 1 in specimen S (--specimen)."""
    return 10000 * args.specimen + k + 1


def dns_seed(args):
    """The seed of the DNS's packing: 1000, 10000 S + 1000 in specimen S."""
    return 10000 * args.specimen + 1000


def compare(name, args, L, us, fe2, dns, title):
    """The demo's curves: fe2(bc, args, L, us) -> (forces, seconds creating the points, seconds in all) for each of
    D, P, T and dns(args, L, us) -> (forces, the packing's description, seconds) that args.only names; writes them
    (write_curves), prints their cost, and exits 1 when a path stopped before the last u."""
    only = args.only.split(',')
    curves, cost = {}, {}
    for bc in ('D', 'P', 'T'):
        if bc in only:
            curves[bc], created, wall = fe2(bc, args, L, us)
            cost[bc] = 'points created in %.1f s, whole path %.1f s' % (created, wall)
    if 'DNS' in only:
        curves['DNS'], particles, wall = dns(args, L, us)
        cost['DNS'] = '%s; %.1f s' % (particles.strip(), wall)
    names = write_curves(args.out, name, us, curves, args.plot, title, 'force on the platen (N)')
    for k in names:
        print('fe2 %s %s: %s' % (name, k, cost[k]))
    print('fe2 %s: wrote %s' % (name, os.path.join(args.out, name + '.csv')))
    stopped = [k for k in names if len(curves[k]) < len(us)]
    if stopped:
        sys.exit('fe2/%s.py: the path of %s stopped before u = %g m (above)' % (name, ', '.join(stopped), us[-1]))
