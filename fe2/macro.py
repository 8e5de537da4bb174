"""FE^2 on GetFEM: a finite-strain, quasi-static finite element model, plane strain (2D) or 3D, whose quadrature
points are servo_bc material points (material_point.h through yade_adapter/servo_bc_core.py).

Total Lagrangian: the unknown is the displacement u(X) on the reference mesh (bilinear quadrilaterals with 2 x 2
Gauss points, or trilinear hexahedra with 2 x 2 x 2); at every Gauss point F = I + Grad u goes to the point, which
returns the first Piola stress P (2D: N/m, a 2D aggregate's force per unit length, so nodal forces are in N per
unit thickness of the model; 3D: N/m^2, nodal forces in N). The residual and the tangent are GetFEM's generic
assembly of

    r_a = int P : Grad N_a dV            K_ab = int (C : Grad N_b) : Grad N_a dV,   C_ijkl = dP_ij/dF_kl

with P and C stored at the Gauss points (GetFEM im_data, column-major). The macro Newton, its
convergence test, the commit / revert of every point and the cut of a load step are ours (docs/fe2.md).
"""
import concurrent.futures
import os
import sys
import warnings

import getfem as gf
import numpy as np
import scipy.sparse
import scipy.sparse.linalg

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'yade_adapter'))
import servo_bc_core as core  # noqa: E402

TANGENTS = ('condensed', 'affine', 'perturbation')


class MacroFailure(RuntimeError):
    """A load step that cannot be completed: the points failed below the smallest step, or the Newton did not
    converge; the message names the step, the iteration and the residual and ends with the last attempt's Newton
    history, which `history` holds (the residual norms over the reaction, one per iteration)."""

    def __init__(self, message, history=()):
        self.history = list(history)
        if self.history:
            message += '; its Newton history: ' + ' '.join('%.2e' % h for h in self.history)
        super().__init__(message)


def _column_major(rows, dim=2):
    """9-slot row-major 3 x 3 tensors -> GetFEM's column-major dim x dim blocks, all points in one vector."""
    out = np.empty((len(rows), dim * dim))
    for k, t in enumerate(rows):
        for i in range(dim):
            for j in range(dim):
                out[k, i + dim * j] = t[3 * i + j]
    return out.ravel()


def _tangent_column_major(rows, dim=2):
    """81-slot C[9 (3i + j) + 3k + l] -> column-major dim^4 blocks (index i + d j + d^2 k + d^3 l)."""
    d = dim
    out = np.empty((len(rows), d ** 4))
    for n, C in enumerate(rows):
        for i in range(d):
            for j in range(d):
                for k in range(d):
                    for l in range(d):
                        out[n, i + d * j + d * d * k + d ** 3 * l] = C[9 * (3 * i + j) + 3 * k + l]
    return out.ravel()


class Macro:
    """A rectangle [0, W] x [0, H] of nx x ny bilinear elements (lengths (W, H), divisions (nx, ny)), or a box
    [0, W] x [0, H] x [0, D] of trilinear ones (lengths (W, H, D), divisions (nx, ny, nz)), a material point per
    Gauss point made by make_point(index, X) (X the point's reference position, m), called from `threads` threads at
    once (each call makes its own point; a make_point that writes a file shared with another call must lock it). tangent: 'condensed', 'affine'
    or 'perturbation' (step h)."""

    BOUNDARY = 1  # the mesh region of the outer faces

    def __init__(self, lengths, divisions, make_point, tangent='condensed', h=1e-5, threads=2, comm=None):
        if tangent not in TANGENTS:
            raise ValueError("fe2: tangent '%s' (expected one of %s)" % (tangent, ', '.join(TANGENTS)))
        if len(lengths) not in (2, 3) or len(divisions) != len(lengths):
            raise ValueError('fe2: lengths %r and divisions %r (expected 2 or 3 of each)' % (lengths, divisions))
        self.tangent, self.h, self.threads, self.comm = tangent, h, threads, comm
        self.dim = d = len(lengths)
        self.mesh = gf.Mesh('cartesian', *[np.linspace(0.0, L, n + 1) for L, n in zip(lengths, divisions)])
        self.mesh.set_region(self.BOUNDARY, self.mesh.outer_faces())
        self.mf = gf.MeshFem(self.mesh, d)
        self.mf.set_classical_fem(1)
        self.mim = gf.MeshIm(self.mesh, gf.Integ('IM_GAUSS_PARALLELEPIPED(%d,3)' % d))
        self.md = gf.Model('real')
        self.md.add_fem_variable('u', self.mf)
        self.md.add_im_data('P', gf.MeshImData(self.mim, -1, [d, d]))
        self.md.add_im_data('C', gf.MeshImData(self.mim, -1, [d, d, d, d]))
        self.md.add_initialized_data('P0', np.zeros(d * d), [d, d])
        self.mimd_F = gf.MeshImData(self.mim, -1, [d, d])
        where = self.md.interpolation('X', gf.MeshImData(self.mim, -1, [d])).reshape(-1, d)
        # on the ranks of comm (mpi4py), each rank keeps the points k = rank, rank + size, ...; every rank
        # assembles and solves the macro problem alike from the gathered P and C
        rank, size = (comm.Get_rank(), comm.Get_size()) if comm is not None else (0, 1)
        self.count = len(where)
        self.mine = list(range(rank, self.count, size))
        self.pool = concurrent.futures.ThreadPoolExecutor(max(1, threads))
        # the points are made on the threads (a point's creation, a relaxation at F = I, runs in C without the GIL)
        self.points = list(self.pool.map(lambda k: make_point(k, where[k]), self.mine))
        self.X = self.mf.basic_dof_nodes()          # [dim, ndof] the node of each dof
        self.comp = np.arange(self.mf.nbdof()) % d   # the component of each dof (Q1 vector: interleaved)
        self.U = np.zeros(self.mf.nbdof())

    # the fields at the Gauss points
    def deformation(self, U):
        """F at every Gauss point, 9-slot row-major (2D: F33 = 1)."""
        d = self.dim
        self.md.set_variable('u', U)
        Fc = self.md.interpolation('Id(%d)+Grad_u' % d, self.mimd_F).reshape(-1, d * d)
        if d == 3:
            return [[f[0], f[3], f[6], f[1], f[4], f[7], f[2], f[5], f[8]] for f in Fc]
        return [[f[0], f[2], 0.0, f[1], f[3], 0.0, 0.0, 0.0, 1.0] for f in Fc]

    def internal_forces(self, P):
        """r_a = int P : Grad N_a dV (2D: N per unit thickness; 3D: N)."""
        self.md.set_variable('P', _column_major(P, self.dim))
        return np.asarray(gf.asm_generic(self.mim, 1, 'P:Grad_Test_u', -1, self.md, 'select_output', 'u'))

    def traction_forces(self, P):
        """The nodal forces of a uniform first Piola stress P (9 slots) on the outer faces: f_a = int (P N) . N_a dS
        (N the outward normal), per dof."""
        self.md.set_variable('P0', _column_major([P], self.dim))
        return np.asarray(gf.asm_generic(self.mim, 1, '(P0*Normal).Test_u', self.BOUNDARY, self.md,
                                         'select_output', 'u'))

    def stiffness(self, C):
        self.md.set_variable('C', _tangent_column_major(C, self.dim))
        K = gf.asm_generic(self.mim, 2, '(C:Grad_Test2_u):Grad_Test_u', -1, self.md, 'select_output', 'u', 'u')
        jc, ir = K.csc_ind()
        n = self.mf.nbdof()
        return scipy.sparse.csc_matrix((np.asarray(K.csc_val()), np.asarray(ir), np.asarray(jc)), shape=(n, n))

    def _gathered(self, mine):
        """Values of this rank's points (in self.mine's order) -> the values of every point, in index order."""
        if self.comm is None:
            return list(mine)
        out = [None] * self.count
        for indices, values in self.comm.allgather((self.mine, list(mine))):
            for k, v in zip(indices, values):
                out[k] = v
        return out

    def integrate(self, Fs):
        """Every point to Fs[k] (9 values each; this rank integrates its own). Returns (P, usable, ratios,
        message) of every point: usable is converged, certified or not (a point that converged to a state its
        words cannot certify returns P; self.uncertified counts them); the message is the failed point's with
        the smallest index."""
        P, _, ratios, message = core.integrate_points(self.points, [Fs[k] for k in self.mine], self.threads)
        ok = [p.status != 'failed' for p in self.points]
        first = next((k for k, c in zip(self.mine, ok) if not c), self.count)
        uncertified = sum(p.status == 'uncertified' for p in self.points)
        if self.comm is not None:
            first, message = min(self.comm.allgather((first, message)))
            uncertified = self.comm.allreduce(uncertified)
        self.uncertified = uncertified
        return self._gathered(P), self._gathered(ok), self._gathered(ratios), message if first < self.count else ''

    def tangents(self):
        """C at every point's current state (the last integrate), the points' own (material_point.h)."""
        if self.tangent == 'condensed':
            return self._gathered(self.pool.map(lambda p: p.condensed()[0], self.points))
        h = self.h if self.tangent == 'perturbation' else None
        return self._gathered(self.pool.map(lambda p: p.tangent(h), self.points))

    # one load step
    def newton(self, fixed, values, tol=1e-8, max_iterations=12, step=0, external=None, on_iteration=None):
        """Newton from the committed state to the dofs `fixed` at `values`, under the nodal loads `external`
        (per dof, N per unit thickness; None: none). Returns (converged, ratio, history): history the residual
        norms relative to the reaction norm, ratio the points' suggested step ratio when one failed (else 1).
        on_iteration(step, iteration, residual) after each residual. The points hold the state of the last
        iteration (commit or revert it)."""
        free = np.setdiff1d(np.arange(self.mf.nbdof()), fixed)
        U = self.U.copy()
        U[fixed] = values
        history = []
        for iteration in range(max_iterations + 1):
            P, ok, ratios, message = self.integrate(self.deformation(U))
            if not all(ok):
                self.last_message = 'step %d, iteration %d: %s' % (step, iteration, message)
                return False, min(ratios), history
            r = self.internal_forces(P)
            if external is not None:
                r = r - external
            reaction = np.linalg.norm(r[fixed])
            norm = np.linalg.norm(r[free]) / (reaction if reaction > 0 else 1.0)
            history.append(norm)
            if on_iteration:
                on_iteration(step, iteration, norm)
            if norm <= tol:
                self.trial_U, self.trial_P, self.trial_r = U, P, r
                return True, 1.0, history
            if iteration == max_iterations:
                break
            K = self.stiffness(self.tangents())
            with warnings.catch_warnings():
                warnings.simplefilter('ignore', scipy.sparse.linalg.MatrixRankWarning)
                dU = scipy.sparse.linalg.spsolve(K[free][:, free].tocsc(), r[free])
            if not np.all(np.isfinite(dU)):
                self.last_message = 'step %d, iteration %d: the macro stiffness is singular (the points\' tangents ' \
                    'leave a mode of the mesh without stiffness)' % (step, iteration)
                return False, 0.5, history
            U[free] -= dU
        self.last_message = 'step %d: the macro Newton did not converge in %d iterations (residual %.3g of the ' \
            'reaction)' % (step, max_iterations, history[-1])
        return False, 0.5, history

    def commit(self):
        for p in self.points:
            p.commit()
        self.U = self.trial_U

    def revert(self):
        for p in self.points:
            p.revert()

    def load(self, fixed, values_at, steps, tol=1e-8, max_iterations=12, min_fraction=1e-3, on_step=None,
             external_at=None, on_iteration=None):
        """The load path t in [0, 1] in `steps` equal steps, the dofs `fixed` at values_at(t) under the nodal
        loads external_at(t) (None: none); a step whose points fail or whose Newton does not converge is reverted
        and cut (by the points' ratio, else by half), down to min_fraction of a step. on_step(t, macro, history)
        after every committed step, on_iteration(step, iteration, residual) after every macro iteration."""
        t, dt, cuts, k = 0.0, 1.0 / steps, 0, 0
        while t < 1.0 - 1e-12:
            dt = min(dt, 1.0 - t)
            ok, ratio, history = self.newton(fixed, values_at(t + dt), tol, max_iterations, k + 1,
                                             external_at(t + dt) if external_at else None, on_iteration)
            if not ok:
                self.revert()
                cuts += 1
                dt *= ratio
                if dt < min_fraction / steps:
                    raise MacroFailure('fe2: load step at t = %.6g cut below %.3g of a step: %s'
                                       % (t, min_fraction, self.last_message), history)
                continue
            self.commit()
            t += dt
            k += 1
            if on_step:
                on_step(t, self, history)
        return cuts

    def dofs_where(self, predicate):
        """The dofs whose node satisfies predicate(x, y, component) (3D: predicate(x, y, z, component))."""
        return np.array([k for k in range(self.mf.nbdof()) if predicate(*self.X[:, k], self.comp[k])], dtype=int)


def lattice_point(words, N=5, spacing=2e-3, radius=1.01e-3, kn=1e4, ks=2e3, mu=0.4, density=2e3, dt=2e-6, dim=2):
    """A material point on a prestressed N x N square lattice (radius > spacing / 2), frictional; dim 3: an
    N x N x N cubic lattice of spheres (density then in kg/m^3)."""
    if dim == 3:
        x = [c * spacing for k in range(N) for j in range(N) for i in range(N) for c in (i, j, k)]
    else:
        x = [c * spacing for j in range(N) for i in range(N) for c in (i, j)]
    return core.MaterialPoint(x, [radius] * N ** dim, words, kn=kn, ks=ks, mu=mu, density=density, dt=dt, dim=dim)


def read_packing(path, dim=2):
    """A packing written by the runner's `write_packing text`: x [dim n], r [n], box [4] (2D) or None. ValueError
    when the count its first line announces ('# servo_bc packing: 121 discs, ...') is not the particles it holds (a
    torn file), or a line is not 'x y r' ('x y z r' in 3D)."""
    x, r, box, announced = [], [], None, None
    expected = 'x y r' if dim == 2 else 'x y z r'
    with open(path) as f:
        for number, line in enumerate(f, 1):
            words = line.split()
            if number == 1 and line.startswith('# servo_bc packing: ') and len(words) > 3 and words[3].isdigit():
                announced = int(words[3])
            if not words or words[0].startswith('#'):
                continue
            if words[0] != 'box' and len(words) != dim + 1:
                raise ValueError('%s line %d: %d values (expected %s)' % (path, number, len(words), expected))
            if words[0] == 'box':
                box = [float(v) for v in words[1:5]]
                continue
            x += [float(v) for v in words[:dim]]
            r.append(float(words[dim]))
    if announced is not None and announced != len(r):
        raise ValueError('%s: its first line announces %d %s and it holds %d (a torn or edited file)'
                         % (path, announced, 'discs' if dim == 2 else 'spheres', len(r)))
    return x, r, box
