"""FE^2 with the material points spread over MPI ranks (fe2/macro.py, comm): a 2 x 2 mesh of 16 (P) points (the
patch test's prestressed 5 x 5 lattice), its boundary taken to (F - I) X in 2 load steps with the condensed
tangent. Rank 0 prints the displacements and the nodal forces of every step as hexadecimal floats, then a line
`time ...` (wall time of the load, s; compared by nobody). Run alone and under mpirun: the lines before the time
must be the same (tests/fe2_mpi.sh).
Usage: python3 tests/fe2_mpi.py [mpi]"""
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'fe2'))
import macro  # noqa: E402

comm = None
if sys.argv[1:] == ['mpi']:
    from mpi4py import MPI
    comm = MPI.COMM_WORLD
rank = comm.Get_rank() if comm is not None else 0
W = H = 0.2
F = [0.9985, 0.0008, 0.0, -0.0003, 0.999, 0.0, 0.0, 0.0, 1.0]
model = macro.Macro((W, H), (2, 2), lambda k, X: macro.lattice_point('P accuracy balanced'), tangent='condensed',
                    threads=1, comm=comm)
target = np.array([(F[3 * c] - (1.0 if c == 0 else 0.0)) * x + (F[3 * c + 1] - (1.0 if c == 1 else 0.0)) * y
                   for x, y, c in zip(model.X[0], model.X[1], model.comp)])
boundary = model.dofs_where(lambda x, y, c: np.isclose(x, 0.0) or np.isclose(y, 0.0) or np.isclose(x, W) or
                            np.isclose(y, H))
lines = []
t0 = time.time()
model.load(boundary, lambda t: t * target[boundary], 2, tol=1e-8, max_iterations=12,
           on_step=lambda t, m, history: lines.append('step %s iterations %d u %s r %s' % (
               float(t).hex(), len(history) - 1, ' '.join(float(v).hex() for v in m.U),
               ' '.join(float(v).hex() for v in m.trial_r))))
elapsed = time.time() - t0
if rank == 0:
    print('\n'.join(lines))
    print('time %.3f points %d ranks %d' % (elapsed, model.count, comm.Get_size() if comm is not None else 1))
