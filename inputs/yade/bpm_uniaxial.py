"""The thesis' uniform (simple cubic) packing under uniaxial tension in YADE: NX x NY x NZ
spheres (r = 0.1 m, 925 kg/m^3) on a cubic lattice of spacing 0.2 m, Timoshenko bonds
(E_b = 4 GPa, nu_b = 0.3) through the core (servo_bc.Bonds); the left face held in x (one
of its spheres in y and z too), 1 kN shared by the right face's spheres along +x, settled
by NewtonIntegrator's damping. Writes `modulus VALUE` (Pa) into FILE:
E = (F / dL) (L0 / A), dL the stretch between the faces' mean centres, L0 = 0.2 (NX - 1) m,
A = NY NZ (0.2 m)^2 (eq. 64); the thesis' value is pi E_b / 4.
  yade -n -x inputs/yade/bpm_uniaxial.py NX NY NZ FILE"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))  # yade -x: the script's folder
from common import args, servo_bc  # noqa: E402
from yade import O, utils  # noqa: E402
from yade.wrapper import ForceResetter, FrictMat, NewtonIntegrator, PyRunner  # noqa: E402

nx, ny, nz, out = args('NX NY NZ FILE', 4)
nx, ny, nz = int(nx), int(ny), int(nz)
if nx < 2 or ny < 1 or nz < 1:
    sys.exit('bpm_uniaxial.py: NX must be at least 2, NY and NZ at least 1')
S, F = 0.2, 1e3
mat = O.materials.append(FrictMat(density=925.0, young=4e9, poisson=0.3))
ids, left, right = [], [], []
for i in range(nx):
    for j in range(ny):
        for k in range(nz):
            b = O.bodies.append(utils.sphere((S * i, S * j, S * k), 0.5 * S, material=mat))
            ids.append(b)
            if i == 0:
                left.append(b)
            if i == nx - 1:
                right.append(b)
for b in left:
    O.bodies[b].state.blockedDOFs = 'x'
O.bodies[left[0]].state.blockedDOFs = 'xyz'
bonds = servo_bc.Bonds(ids, 'beam', E=4e9, nu=0.3)
pull = 'for b in %r: O.forces.addF(b, (%r, 0, 0))' % (right, F / len(right))
O.engines = [ForceResetter(), bonds.engine, PyRunner(command=pull, iterPeriod=1),
             NewtonIntegrator(damping=0.2, gravity=(0, 0, 0))]
O.dt = 0.5 * bonds.critical_dt()


def stretch():
    xl = sum(O.bodies[b].state.pos[0] for b in left) / len(left)
    xr = sum(O.bodies[b].state.pos[0] for b in right) / len(right)
    return xr - xl - S * (nx - 1)


prev, d = None, 0.0
for chunk in range(1000):  # until the stretch settles to 1e-9 of itself
    O.run(2000, True)
    d = stretch()
    if prev is not None and abs(d - prev) <= 1e-9 * abs(d):
        break
    prev = d
else:
    sys.exit('bpm_uniaxial.py: the stretch did not settle in 2e6 steps (last change %g m)' % abs(d - prev))
E = F / d * S * (nx - 1) / (ny * nz * S * S)
with open(out, 'w') as f:
    f.write('modulus %.17g\n' % E)
print('bpm_uniaxial: %d spheres, %d bonds, modulus %.9g Pa, %d steps' % (len(ids), bonds.count, E, O.iter))
