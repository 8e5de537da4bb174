# The paper's regular packings (Sect. 4.1, Table 4) under eq. 38 in YADE:
#   yade -n -x inputs/yade/regular.py SIDE BC OUT.csv [INCREMENTS]
# SIDE = 5, 10, 15 (25, 100, 225 particles); BC = D, P or T; INCREMENTS of the 300
# of eq. 38 (default all). Same words as inputs/lammps/regular.in.
import os
import sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))  # yade -x: the script's folder
from common import args, runner_packing, servo_bc  # noqa: E402

side, bc, out, *rest = args('SIDE BC OUT.csv [INCREMENTS]', 3)
inc = int(rest[0]) if rest else 300
t = inc / 300.0
F = (1 - 0.03 * t, -0.3 * t, -0.3 * t, 1 - 0.03 * t)
packing = runner_packing(['dimension 2', 'lattice square %s %s spacing 2.0e-3 radius 1.02e-3' % (side, side)],
                         out + '.packing')
words = ('%s F %.17g %.17g %.17g %.17g increments %d accuracy paper relax 1e-3 20 damping 0.7 0.7 gain_force 1e2 '
         'gain_moment 2e2 gain_deformation 2e-5 tol_force 1e-6 tol_moment 1e-6 tol_deformation 1e-2 file %s'
         % ((bc,) + F + (inc, out)))
servo_bc.run_case(packing, words, density=2e3, kn=1e4, ks=2e3, mu=0.4, dt=1e-6)
