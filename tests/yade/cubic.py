# The YADE engine in 3D on the 4 x 4 x 4 simple cubic lattices of
# docs/frame3d.md (spheres free in 3D, spacing d = 2 mm, kn 1e4 N/m, mass 1
# g), 2 increments at accuracy tight against their closed forms: (D) and (P)
# on the prestressed lattice (R = 1.02 mm) with friction (ks = kn / 2, mu
# 0.5) under F = diag(0.999, 0.998, 0.997); (T) on the touching frictionless
# lattice (R = 1 mm) under F = diag(1 - 2e-6, 1 - 1e-6, 1); the stress stage
# of the 3D layer; and the refusals in 3D. Run: yade -n -x tests/yade/cubic.py.
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

N, d, kn, m = 4, 2e-3, 1e4, 1e-3


def lattice(R, mu):
    O.reset()
    mat = O.materials.append(FrictMat(young=kn / R, poisson=0.0, frictionAngle=math.atan(mu), density=1.0))
    ids = []
    for k in range(N):
        for j in range(N):
            for i in range(N):
                b = utils.sphere((i * d, j * d, k * d), R, material=mat)
                b.state.mass = m
                b.state.inertia = (0.4 * m * R * R,) * 3
                ids.append(O.bodies.append(b))
    return ids


def run(words, R=1.02e-3, ks=0.0, mu=0.0):
    ids = lattice(R, mu)
    servo = servo_bc.ServoBC(words, ids, 1e-5, kn)
    O.engines = servo_bc.engines(servo, kn, ks)
    servo.run(2000000)
    return servo


def closed_form(label, servo, form):
    """The rows against docs/frame3d.md: prestressed (R = 1.02 mm, (D) or (P)): P_ii = -N^2 kn (2R -
    d F_ii) / ((N - 1)^2 d^2) within 1e-6 of max |P|; touching (R = 1 mm, frictionless, (T)): P_ii =
    -kn (1 - F_ii) (N - 1)^2 / (d (N - 3/2)^2) within 1e-5; P_ij = 0, |hill_mandel| <= 1e-6."""
    worst = pmax = hm = 0.0
    for row in servo.rows:
        for i in range(1, 4):
            for j in range(1, 4):
                F = row['F%d%d' % (i, i)]
                if i != j:
                    e = 0.0
                elif form == 'touching':
                    e = -kn * (1 - F) * (N - 1) ** 2 / (d * (N - 1.5) ** 2)
                else:
                    e = -N * N * kn * (2 * 1.02e-3 - d * F) / ((N - 1) ** 2 * d * d)
                pmax = max(pmax, abs(e))
                worst = max(worst, abs(row['P%d%d' % (i, j)] - e))
        hm = max(hm, abs(row['hill_mandel']))
    tol = 1e-5 if form == 'touching' else 1e-6
    check(servo.dim == 3 and len(servo.rows) == 3 and worst <= tol * pmax and hm <= 1e-6,
          '3d %s, 4^3 lattice: %d rows, max |P - closed form| = %.3g of max |P| (%.6g N/m^2), |hill_mandel| <= %.3g'
          % (label, len(servo.rows), worst / pmax if pmax else math.inf, pmax, hm))


for bc in ('D', 'P'):
    closed_form('(%s) frictional' % bc, run('%s F 0.999 0 0 0 0.998 0 0 0 0.997 increments 2 accuracy tight' % bc,
                                              ks=0.5 * kn, mu=0.5), 'prestressed')
closed_form('(T) frictionless touching', run('T F 0.999998 0 0 0 0.999999 0 0 0 1 increments 2 accuracy tight',
                                             R=1e-3), 'touching')

# the stress stage of the 3D layer (mixed: zlo D D D, zhi D D T, the sides P P P) on the touching lattice
# with friction: F33 = 1 - p d (N - 3/2)^2 / (kn (N - 1)^2) = 1 - 1/720 and P33 = -1e4 within 1e-6
servo = run('mixed stress P33 -1e4 2 F 1 0 0 0 1 0 0 0 1 increments 1 accuracy tight', R=1e-3, ks=0.5 * kn, mu=0.5)
row = servo.rows[2] if len(servo.rows) == 4 else None
err = max(abs((1 - row['F33']) * 720 - 1), abs(row['P33'] + 1e4) / 1e4) if row else math.inf
hm = max(abs(r['hill_mandel']) for r in servo.rows)
check(err <= 1e-6 and hm <= 1e-6, '3d layer (mixed), stress stage on the 4^3 touching lattice: F33 and P33 within %.3g of '
      'the closed form, |hill_mandel| <= %.3g' % (err, hm))

for words, expect in (('mixed stress P22 -1 1', 'the packing is 3D but the words are 2D'),
                      ('D F 0.999 0 0 1', "4 values give a 2D F, but the packing is 3D")):
    try:
        run(words)
        check(False, 'refuses %r' % words)
    except servo_bc.ServoBCError as e:
        check(expect in str(e), 'refuses %r: %s' % (words, e))
sys.exit(summary())
