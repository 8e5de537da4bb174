"""The thesis' Appendix B beam in YADE: N spheres (r = 0.1 m) in a row, Timoshenko bonds
(E_b = 4 GPa, nu_b = 0.3) through the core (servo_bc.Bonds), simply supported (pinned
left, roller right), 1 kN at midspan, settled by NewtonIntegrator's damping. Writes one
line `deflection VALUE` (the midspan's, m) into FILE. Eq. B1 gives it in closed form:
  F Le^3 / 48 E I + F Le f_s / 4 G A,   Le = 2 r (N - 1), f_s = 10/9.
  yade -n -x inputs/yade/bpm_beam.py N FILE      (N odd, >= 3)"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))  # yade -x: the script's folder
from common import args, servo_bc  # noqa: E402
from yade import O, utils  # noqa: E402
from yade.wrapper import ForceResetter, FrictMat, NewtonIntegrator, PyRunner  # noqa: E402

n_text, out = args('N FILE', 2)
n = int(n_text)
if n < 3 or n % 2 == 0:
    sys.exit('bpm_beam.py: N must be odd and at least 3, got %s' % n_text)
R, F = 0.1, 1e3
mat = O.materials.append(FrictMat(density=925.0, young=4e9, poisson=0.3))
ids = [O.bodies.append(utils.sphere((2 * R * i, 0.0, 0.0), R, material=mat)) for i in range(n)]
O.bodies[ids[0]].state.blockedDOFs = 'xyzXZ'    # pinned: free to turn about y only
O.bodies[ids[-1]].state.blockedDOFs = 'yzXZ'    # roller: also free to slide along x
mid = ids[n // 2]
bonds = servo_bc.Bonds(ids, 'beam', E=4e9, nu=0.3)
O.engines = [ForceResetter(), bonds.engine, PyRunner(command='O.forces.addF(%d, (0, 0, %r))' % (mid, -F), iterPeriod=1),
             NewtonIntegrator(damping=0.2, gravity=(0, 0, 0))]
O.dt = 0.5 * bonds.critical_dt()
prev, d = None, 0.0
for chunk in range(1000):  # until the midspan settles to 1e-9 of its deflection
    O.run(2000, True)
    d = -O.bodies[mid].state.pos[2]
    if prev is not None and abs(d - prev) <= 1e-9 * abs(d):
        break
    prev = d
else:
    sys.exit('bpm_beam.py: the midspan did not settle in 2e6 steps (last change %g m)' % abs(d - prev))
with open(out, 'w') as f:
    f.write('deflection %.17g\n' % d)
print('bpm_beam: %d spheres, %d bonds, deflection %.9g m, %d steps' % (n, bonds.count, d, O.iter))
