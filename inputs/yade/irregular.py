# The irregular periodic packing of Sect. 4.2 under simple shear (Figs. 7-9) in YADE:
#   yade -n -x inputs/yade/irregular.py N0 BC OUT.csv [INCREMENTS]
# N0 = 200 gives the paper's 228 (here 232) particles; BC = D, P or T; the 100
# increments of F12 = 0.5 (Table 4 physics; settings of docs/reproduction-irregular.md;
# (T) there uses gain_force 5 gain_deformation 2e-6: edit the words).
import os
import sys
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))  # yade -x: the script's folder
from common import args, runner_packing, servo_bc  # noqa: E402

n0, bc, out, *rest = args('N0 BC OUT.csv [INCREMENTS]', 3)
inc = int(rest[0]) if rest else 100
packing = runner_packing(['dimension 2', 'generate periodic n0 %s rmin 0.67e-3 polydispersity 2 seed 1' % n0],
                         out + '.packing')
words = ('%s F 1 %.17g 0 1 increments %d accuracy paper relax 1e-3 20 damping 0.7 0.7 gain_force 1e2 gain_moment 2e2 '
         'gain_deformation 2e-5 tol_force 1e-6 tol_moment 1e-6 tol_deformation 1e-1 frame %d file %s'
         % (bc, 0.5 * inc / 100.0, inc, servo_bc.FRAME_MASK, out))
servo_bc.run_case(packing, words, density=2e3, kn=1e4, ks=2e3, mu=0.4, dt=1e-6)
