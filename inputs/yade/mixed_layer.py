# Sect. 5.3 in YADE: the infinite frictional layer under mixed (D)-(P)-(T) (Table 5):
# P22* = -1.05e6 N/m in 6 increments, then F12 = 0.2 in 100 (Table 6 physics; dt,
# gains, tolerances as docs/reproduction-irregular.md and inputs/lammps/mixed_layer.in).
#   yade -n -x inputs/yade/mixed_layer.py OUT.csv [N0 [INCREMENTS]]
import os
import sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))  # yade -x: the script's folder
from common import args, runner_packing, servo_bc  # noqa: E402

out, *rest = args('OUT.csv [N0 [INCREMENTS]]', 1)
n0 = int(rest[0]) if rest else 410
inc = int(rest[1]) if len(rest) > 1 else 100
packing = runner_packing(['dimension 2', 'generate periodic n0 %d rmin 0.8e-3 polydispersity 1.5 seed 1' % n0],
                         out + '.packing')
words = ('mixed F 1 %.17g 0 1 increments %d stress P22 -1.05e6 6 accuracy paper relax 1e-3 20 damping 0.7 0.7 gain_force 1 '
         'gain_moment 1 tol_force 1e-6 tol_moment 1e-6 max_iterations 100000 frame %d file %s'
         % (0.2 * inc / 100.0, inc, servo_bc.FRAME_MASK, out))
servo_bc.run_case(packing, words, density=1e4, kn=1e8, ks=4e7, mu=0.6, dt=5e-6)
