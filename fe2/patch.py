"""The FE^2 patch test (make fe2-patch, docs/fe2.md): a 3 x 3 mesh whose 36 Gauss points carry the same
aggregate (a prestressed 5 x 5 frictional lattice) under (D), (P), (T) and the mixed layer with its top D D (bottom
and top D, the sides P).

1. The mesh deformed uniformly by F (every node at u = (F - I) X): the nodal forces equal those of the single
   aggregate's P on the mesh's edges, f_a = P . int N_a N0 dS (zero inside).
2. The boundary nodes at (F - I) X, the four inside nodes free and started at u = 0: the macro Newton with the
   condensed tangent finds the uniform state again, quadratically (its second contraction at most a tenth of its
   first, or the residual at round-off after two iterations); its residual ratios and those of the perturbation
   and the affine tangents are printed, and the nodal forces at convergence against the same closed form.
3. (D) along the load path u = t (F2 - I) X on the boundary (F2 - I = 4 (F - I)) in one step with a Newton of at most 2 iterations, too few
   for the whole step: the step is reverted and cut in half, and the cut path ends bit for bit where two half steps
   from the start end, at the closed form's nodal forces.
4. A step whose Newton cannot converge (a tolerance no residual meets) stops the path with MacroFailure, whose
   message and `history` carry the last attempt's residuals; a singular macro stiffness fails the step by name;
   36 distinct points (lattices of spacings 1 + 1e-3 k) made on the model's 1 and 2 threads are the same bits.
5. In 3D: a 2 x 2 x 2 mesh of trilinear hexahedra whose 64 Gauss points carry a prestressed 4 x 4 x 4 frictional
   cubic lattice of spheres under (D), (P) and (T) (`rotation zero interior newton`: docs/fe2.md, "The 3D macro
   model"), deformed by a full 3 x 3 F: 1. and 2. again, with the condensed tangent.

Prints one line per condition and tangent, then `patch max relative difference VALUE` (the largest over
everything above with the condensed tangent, relative to the largest closed-form nodal force); exits 1 when it
exceeds 1e-6, a Newton with the condensed or the perturbation tangent does not converge, or the condensed one's is
not quadratic.
Usage: python3 fe2/patch.py [TANGENT ...]   (default: condensed affine; perturbation on request)"""
import sys
import time

import numpy as np

import macro

W, H, NX, NY = 0.3, 0.3, 3, 3
F = [0.9985, 0.0008, 0.0, -0.0003, 0.999, 0.0, 0.0, 0.0, 1.0]
LIMIT = 1e-6
# the load path's end (3.): four times F's strain, where the condensed tangent's quadratic Newton needs 3 iterations
F_PATH = [4.0 * f - 3.0 * (1.0 if k in (0, 4, 8) else 0.0) for k, f in enumerate(F)]
TANGENTS = sys.argv[1:] or ['condensed', 'affine']
for name in TANGENTS:
    if name not in macro.TANGENTS:
        sys.exit("fe2/patch.py: tangent '%s' (expected %s)" % (name, ', '.join(macro.TANGENTS)))


def uniform(model, F=F):
    """u = (F - I) X at every dof."""
    return np.array([sum((F[3 * c + j] - (1.0 if c == j else 0.0)) * model.X[j, k] for j in range(model.dim))
                     for k, c in enumerate(model.comp)])


def quadratic(history):
    """The Newton's contractions (the first two) and whether they show the quadratic rate: the second at most a
    tenth of the first (a linear rate repeats it), or the residual at round-off (1e-12 of the reaction) after two
    iterations, where no contraction can be measured."""
    c = [history[i + 1] / history[i] for i in range(min(2, len(history) - 1))]
    return c, len(c) == 2 and (c[1] <= 0.1 * c[0] or history[2] <= 1e-12)


def relative(f, want):
    return np.max(np.abs(f - want)) / np.max(np.abs(want))


worst, failures = 0.0, 0
for bc in ('D', 'P', 'T', 'mixed top D D'):
    words = '%s accuracy tight' % bc
    single = macro.lattice_point(words)
    ok, P, _ = single.integrate(F)
    if not ok:
        print('FAIL patch %s: the single aggregate: %s' % (bc, single.message))
        failures += 1
        continue
    for tangent in TANGENTS:
        t0 = time.time()
        model = macro.Macro((W, H), (NX, NY), lambda k, X: macro.lattice_point(words), tangent=tangent)
        want = model.traction_forces(P)
        target = uniform(model)
        if tangent == TANGENTS[0]:
            P_all, conv, _, message = model.integrate(model.deformation(target))
            uniform_diff = relative(model.internal_forces(P_all), want) if all(conv) else float('inf')
            worst = max(worst, uniform_diff)
            print('patch %s uniform: 36 points, nodal forces against P . int N_a N0 dS: %.3e%s'
                  % (bc, uniform_diff, '' if all(conv) else ' (' + message + ')'))
        boundary = model.dofs_where(lambda x, y, c: x in (0.0, W) or y in (0.0, H) or
                                    np.isclose(x, W) or np.isclose(y, H))
        converged, _, history = model.newton(boundary, target[boundary], tol=1e-8, max_iterations=20)
        newton_diff = relative(model.trial_r, want) if converged else float('inf')
        ratios = ['%.2e' % v for v in history]
        print('patch %s Newton %-12s %2d iterations, residual/reaction %s; nodal forces %.3e, largest |u - (F - I) X| '
              '%.2e m (%.1f s)' % (bc, tangent, len(history) - 1, ' '.join(ratios), newton_diff,
                                   np.max(np.abs(model.trial_U - target)) if converged else float('nan'),
                                   time.time() - t0))
        if tangent == 'condensed':
            worst = max(worst, newton_diff)
            # quadratic: each contraction a fraction of the one before (a linear rate repeats it)
            c, rate = quadratic(history)
            print('patch %s Newton condensed: contractions %s (quadratic: the second at most 0.1 of the first: %s)'
                  % (bc, ' '.join('%.2e' % v for v in c), rate))
            if not rate:
                print('FAIL patch %s: the condensed tangent\'s Newton is not quadratic' % bc)
                failures += 1
        if not converged and tangent != 'affine':
            print('FAIL patch %s: %s' % (bc, model.last_message))
            failures += 1

def cut_path(steps):
    model = macro.Macro((W, H), (NX, NY), lambda k, X: macro.lattice_point('D accuracy tight'), tangent='condensed')
    boundary = model.dofs_where(lambda x, y, c: np.isclose(x, 0.0) or np.isclose(y, 0.0) or np.isclose(x, W) or
                                np.isclose(y, H))
    target = uniform(model, F_PATH)
    seen = []
    cuts = model.load(boundary, lambda t: t * target[boundary], steps, tol=1e-8, max_iterations=2,
                      on_step=lambda t, m, history: seen.append((t, len(history) - 1)))
    return model, cuts, seen


ok, P, _ = macro.lattice_point('D accuracy tight').integrate(F_PATH)
cut, cuts, seen = cut_path(1)
halves, cuts2, seen2 = cut_path(2)
want = cut.traction_forces(P)
path_diff = relative(cut.trial_r, want)
same = np.array_equal(cut.trial_r, halves.trial_r) and np.array_equal(cut.U, halves.U)
print('patch D load path: one step with at most 2 Newton iterations: %d cut(s), steps at t = %s; two half steps: '
      '%d cuts; the same nodal forces and displacements bit for bit: %s; nodal forces %.3e'
      % (cuts, ' '.join('%g (%d iterations)' % v for v in seen), cuts2, same, path_diff))
if not (cuts >= 1 and cuts2 == 0 and same):
    print('FAIL patch D load path: expected a cut step ending where two half steps end')
    failures += 1
worst = max(worst, path_diff)
# a step that cannot converge (a tolerance no residual meets) stops the path with its last Newton history
stuck = macro.Macro((W, H), (NX, NY), lambda k, X: macro.lattice_point('D accuracy tight'), tangent='condensed')
edge = stuck.dofs_where(lambda x, y, c: np.isclose(x, 0.0) or np.isclose(y, 0.0) or np.isclose(x, W) or
                        np.isclose(y, H))
goal = uniform(stuck, F_PATH)
try:
    stuck.load(edge, lambda t: t * goal[edge], 1, tol=-1.0, max_iterations=2, min_fraction=0.3)
    history = None
except macro.MacroFailure as e:
    history, message = e.history, str(e)
print('patch D failed load step: its Newton history %s in the exception' % history)
if not (history is not None and len(history) == 3 and 'its Newton history: ' in message):
    print('FAIL patch D failed load step: expected MacroFailure with the last attempt\'s 3 residuals')
    failures += 1
# a singular macro stiffness (points whose tangents leave a mode unresisted) fails the step by name, never a NaN F
stuck.tangents = lambda: [[0.0] * 81] * stuck.count
converged, _, history = stuck.newton(edge, 0.5 * goal[edge], tol=1e-8, max_iterations=4)
print('patch D singular macro stiffness: converged %s, %s' % (converged, getattr(stuck, 'last_message', '')))
if converged or 'the macro stiffness is singular' not in stuck.last_message:
    print('FAIL patch D singular macro stiffness: expected the step to fail naming the singular stiffness')
    failures += 1
# the points made on the model's threads: each point k its own (spacing by k), in order, the same bits on 1 and 2
states = [[p.state() for p in macro.Macro((W, H), (NX, NY), lambda k, X: macro.lattice_point(
    'P accuracy tight', spacing=2e-3 * (1.0 + 1e-3 * k), radius=1.01e-3 * (1.0 + 1e-3 * k)), threads=t).points]
    for t in (1, 2)]
distinct = len(set(states[0])) == len(states[0])
print('patch P points made on 1 and 2 threads: %d points, distinct %s, the same bits in the same order %s'
      % (len(states[0]), distinct, states[0] == states[1]))
if not (distinct and states[0] == states[1]):
    print('FAIL patch P points made on threads: expected distinct points, the same on 1 and 2 threads')
    failures += 1

# 5. in 3D
F3 = [0.9985, 0.0008, 0.0004, -0.0003, 0.999, 0.0002, 0.0001, -0.0005, 0.9992]
L3 = 0.2
for bc in ('D', 'P', 'T rotation zero interior newton'):
    words = '%s accuracy tight' % bc
    ok, P, _ = macro.lattice_point(words, N=4, dim=3).integrate(F3)
    t0 = time.time()
    model = macro.Macro((L3, L3, L3), (2, 2, 2), lambda k, X: macro.lattice_point(words, N=4, dim=3))
    want = model.traction_forces(P)
    target = uniform(model, F3)
    P_all, conv, _, message = model.integrate(model.deformation(target))
    uniform_diff = relative(model.internal_forces(P_all), want) if ok and all(conv) else float('inf')
    boundary = model.dofs_where(lambda x, y, z, c: any(np.isclose(v, 0.0) or np.isclose(v, L3) for v in (x, y, z)))
    converged, _, history = model.newton(boundary, target[boundary], tol=1e-8, max_iterations=20)
    newton_diff = relative(model.trial_r, want) if converged else float('inf')
    c, rate = quadratic(history)
    print('patch 3D %s: 64 points, uniform: nodal forces against P . int N_a N0 dS %.3e; Newton condensed %d '
          'iterations, residual/reaction %s, contractions %s (quadratic: %s); nodal forces %.3e (%.1f s)'
          % (bc, uniform_diff, len(history) - 1, ' '.join('%.2e' % v for v in history),
             ' '.join('%.2e' % v for v in c), rate, newton_diff, time.time() - t0))
    worst = max(worst, uniform_diff, newton_diff)
    if not (converged and rate):
        print('FAIL patch 3D %s: %s' % (bc, 'not quadratic' if converged else model.last_message))
        failures += 1
print('patch max relative difference %.3e' % worst)
sys.exit(1 if failures or not worst <= LIMIT else 0)
