# Sect. 5.3 in YADE: the infinite cohesive layer under mixed (D)-(P)-(T) (Table 5,
# eqs. 7-8): P22* = -1.05e6 N/m in 6 increments, then F12 = 0.2 in 100; Table 6's
# stiffnesses, its strengths times FACTOR (1: Table 6 as printed; 16 gives the
# paper's 1.5x peak over the frictional layer, docs/reproduction-irregular.md); the
# converged settings of inputs/paper/fig11.sh (the default preset, seal yes). Every
# contact is the core's (servo_bc.Cohesive), not YADE's.
#   yade -n -x inputs/yade/cohesive_layer.py OUT.csv [N0 [INCREMENTS [FACTOR]]]
import os
import sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))  # yade -x: the script's folder
from common import args, runner_packing, servo_bc  # noqa: E402

out, *rest = args('OUT.csv [N0 [INCREMENTS [FACTOR]]]', 1)
n0 = int(rest[0]) if rest else 410
inc = int(rest[1]) if len(rest) > 1 else 100
factor = float(rest[2]) if len(rest) > 2 else 1.0
packing = runner_packing(['dimension 2', 'generate periodic n0 %d rmin 0.8e-3 polydispersity 1.5 seed 1' % n0],
                         out + '.packing')
words = ('mixed F 1 %.17g 0 1 increments %d stress P22 -1.05e6 6 seal yes max_iterations 100000 frame %d file %s'
         % (0.2 * inc / 100.0, inc, servo_bc.FRAME_MASK, out))
law = 'kn 1e8 ks 4e7 kr 20 fn %.17g fs %.17g mr %.17g mu 0.6' % (300 * factor, 60 * factor, 0.2 * factor)
servo_bc.run_case(packing, words, density=1e4, kn=1e8, ks=4e7, mu=0.6, dt=5e-6, cohesive=law)
