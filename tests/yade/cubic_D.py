# The YADE engine in 3D: (D) on the prestressed 4 x 4 x 4 simple cubic
# lattice of docs/frame3d.md (spheres free in 3D, spacing d = 2 mm, R = 1.02
# mm, kn 1e4 N/m, frictionless, mass 1 g), F = diag(0.999, 0.998, 0.997) in 2
# increments at accuracy tight, against P_ii = -N^2 kn (2R - d F_ii) / ((N -
# 1)^2 d^2), P_ij = 0: every row within 1e-6 of max |P|, |hill_mandel| <=
# 1e-6; and the refusals in 3D. Run: yade -n -x tests/yade/cubic_D.py.
# Prints "N passed, N failed".
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(sys.argv[0])), '..', '..', 'yade_adapter'))
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))    # checks.py
import servo_bc  # noqa: E402
from checks import check, summary  # noqa: E402
from yade import O, utils  # noqa: E402
from yade.wrapper import FrictMat  # noqa: E402

N, d, R, kn, m = 4, 2e-3, 1.02e-3, 1e4, 1e-3



def lattice():
    O.reset()
    mat = O.materials.append(FrictMat(young=kn / R, poisson=0.0, frictionAngle=0.0, density=1.0))
    ids = []
    for k in range(N):
        for j in range(N):
            for i in range(N):
                b = utils.sphere((i * d, j * d, k * d), R, material=mat)
                b.state.mass = m
                b.state.inertia = (0.4 * m * R * R,) * 3
                ids.append(O.bodies.append(b))
    return ids


def run(words):
    ids = lattice()
    servo = servo_bc.ServoBC(words, ids, 1e-5, kn)
    O.engines = servo_bc.engines(servo, kn, 0.0)
    servo.run(2000000)
    return servo


servo = run('D F 0.999 0 0 0 0.998 0 0 0 0.997 increments 2 accuracy tight')
worst = pmax = hm = 0.0
for row in servo.rows:
    for i in range(1, 4):
        for j in range(1, 4):
            e = -N * N * kn * (2 * R - d * row['F%d%d' % (i, i)]) / ((N - 1) ** 2 * d * d) if i == j else 0.0
            pmax = max(pmax, abs(e))
            worst = max(worst, abs(row['P%d%d' % (i, j)] - e))
    hm = max(hm, abs(row['hill_mandel']))
check(servo.dim == 3 and len(servo.rows) == 3 and worst <= 1e-6 * pmax and hm <= 1e-6,
      '3d (D), 4^3 prestressed lattice: %d rows, max |P - closed form| = %.3g of max |P| (%.6g N/m^2), '
      '|hill_mandel| <= %.3g' % (len(servo.rows), worst / pmax if pmax else math.inf, pmax, hm))

for words, expect in (('P F 0.999 0 0 0 1 0 0 0 1', 'this version imposes (D) alone on a 3D frame'),
                      ('D F 0.999 0 0 1', "4 values give a 2D F, but the packing is 3D"),
                      ('D F 0.999 0 0 0 1 0 0 0 1 seal yes', "keyword 'seal' is 2D in this version")):
    try:
        run(words)
        check(False, 'refuses %r' % words)
    except servo_bc.ServoBCError as e:
        check(expect in str(e), 'refuses %r: %s' % (words, e))
sys.exit(summary())
