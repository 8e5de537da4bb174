# The YADE engine on the closed-form lattice of tests/test_lattice.c, and its
# refusals. Run: yade -n -x tests/yade/closed_form.py PACKING (a 5 x 5 lattice,
# spacing 2 mm, R = 1.02 mm, written by the runner). Prints "N passed, N failed".
import contextlib
import io
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(sys.argv[0])), '..', '..', 'yade_adapter'))
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))    # checks.py
import servo_bc  # noqa: E402
from checks import check, summary  # noqa: E402

packing = sys.argv[1]



def closed_form(bc, extra):
    """P11 = -N kn (2R - d F11)/((N-1) d), P22 likewise, P12 = P21 = 0 (frictionless)."""
    words = '%s F 1.002 0 0 0.997 increments 2 relax 1e-22 20 %s' % (bc, extra)
    servo = servo_bc.run_case(packing, words, density=2e3, kn=1e4, ks=0.0, mu=0.4, dt=1e-5)
    worst = 0.0
    for row in servo.rows:
        t = row['increment'] / 2.0
        f11, f22 = 1 + t * 0.002, 1 - t * 0.003
        p11 = -5 * 1e4 * (2.04e-3 - 2e-3 * f11) / (4 * 2e-3)
        p22 = -5 * 1e4 * (2.04e-3 - 2e-3 * f22) / (4 * 2e-3)
        worst = max(worst, abs(row['P11'] - p11) / -p11, abs(row['P22'] - p22) / -p22,
                    abs(row['P12']) / -p11, abs(row['P21']) / -p11)
    check(len(servo.rows) == 3 and worst <= 1e-9,
          '(%s) closed form: %d increments, max relative error %.3g' % (bc, len(servo.rows), worst))


closed_form('D', '')
closed_form('P', 'tol_force 1e-14 tol_moment 1e-14 gain_force 1e3 gain_moment 1e3')


def frictional_tight(bc):
    """The frictional lattice (ks = kn/5, mu 0.4), F = diag(0.99, 0.995) in 4 increments at
    accuracy tight: the affine closed form to 1e-6 (tests/test_accuracy.c)."""
    servo_bc.O.reset()
    servo = servo_bc.run_case(packing, '%s F 0.99 0 0 0.995 increments 4 accuracy tight' % bc, density=2e3, kn=1e4,
                              ks=2e3, mu=0.4, dt=1e-5)
    worst = 0.0
    for row in servo.rows[1:]:
        f11, f22 = row['F11'], row['F22']
        p11 = -5 * 1e4 * (2.04e-3 - 2e-3 * f11) / (4 * 2e-3)
        p22 = -5 * 1e4 * (2.04e-3 - 2e-3 * f22) / (4 * 2e-3)
        worst = max(worst, abs(row['P11'] - p11) / -p11, abs(row['P22'] - p22) / -p22,
                    abs(row['P12']) / -p11, abs(row['P21']) / -p11)
    check(len(servo.rows) == 5 and worst <= 1e-6,
          '(%s) frictional lattice, accuracy tight: %d increments, max relative error %.3g'
          % (bc, len(servo.rows), worst))


frictional_tight('D')
frictional_tight('P')

# kn, ks hold exactly on every contact, for unequal radii too (Ip2 MatchMakers)
servo_bc.O.reset()
mat = servo_bc.O.materials.append(servo_bc.FrictMat(young=1e7, poisson=0.3, frictionAngle=0.4))
a = servo_bc.O.bodies.append(servo_bc.utils.sphere((0, 0, 0), 1e-3, material=mat))
b = servo_bc.O.bodies.append(servo_bc.utils.sphere((2.4e-3, 0, 0), 1.5e-3, material=mat))


class Frozen(object):
    engine = servo_bc.PyRunner(command='pass', iterPeriod=1000000)
    damping = 0.0


servo_bc.O.engines = servo_bc.engines(Frozen, kn=1e4, ks=2e3)
servo_bc.O.dt = 1e-7
servo_bc.O.run(1, True)
i = servo_bc.O.interactions[a, b]
check(i.phys.kn == 1e4 and i.phys.ks == 2e3, 'stiffness: kn = %g, ks = %g on a contact of radii 1 and 1.5 mm'
      % (i.phys.kn, i.phys.ks))


def refused(words, expect, **keywords):
    servo_bc.O.reset()
    ids, _ = servo_bc.load_packing(packing, 2e3, 1e4, 2e3, 0.4)
    try:
        servo_bc.ServoBC(words, ids, 1e-5, 1e4, **keywords)
        check(False, "refuses '%s' (accepted)" % words)
    except servo_bc.ServoBCError as e:
        check(expect in str(e), "refuses '%s': %s" % (words, e))


# the bad words every host refuses (tests/bad_words.txt: words, a tab, the expected text)
with open(os.path.join(os.path.dirname(os.path.abspath(sys.argv[0])), '..', 'bad_words.txt')) as f:
    for line in f:
        if line.strip() and not line.startswith('#'):
            words, expect = line.rstrip('\n').split('\t')
            refused(words, expect)
refused('D', 'increments', increments=0)
refused('D damping 0.7 0.5', "alpha 0.7 and beta 0.5 differ")
refused('D frame boundary', "'boundary' is not a YADE group mask")
refused('D frame 64', "keyword 'frame': '64' names no particle")

# the arguments YADE gives: body ids, time step, stiffness
def refused_call(label, expect, ids_of, dt=1e-5, kn=1e4):
    servo_bc.O.reset()
    ids, _ = servo_bc.load_packing(packing, 2e3, 1e4, 2e3, 0.4)
    try:
        servo_bc.ServoBC('D', ids_of(ids), dt, kn)
        check(False, 'refuses %s (accepted)' % label)
    except servo_bc.ServoBCError as e:
        check(expect in str(e), 'refuses %s: %s' % (label, e))


refused_call('a body that does not exist', 'body 999 does not exist', lambda ids: ids + [999])
refused_call('a body listed twice', 'body %d is listed twice' % 3, lambda ids: ids + [3])
refused_call('no bodies', 'no bodies', lambda ids: [])
refused_call('a box among the spheres', 'is a Box (expected a sphere)',
             lambda ids: ids + [servo_bc.O.bodies.append(servo_bc.utils.box((0, 0, 1), (1e-3, 1e-3, 1e-3)))])
refused_call('a zero time step', 'time step 0 s', lambda ids: ids, dt=0.0)
refused_call('a NaN time step', 'time step nan s', lambda ids: ids, dt=float('nan'))
refused_call('a negative stiffness', 'kn', lambda ids: ids, kn=-1.0)

# YADE's own sphere mass on one body (4/3 pi R^3 rho, 800 times lighter than the disc):
# the time step is checked against its critical step before the run, naming it
servo_bc.O.reset()
ids, _ = servo_bc.load_packing(packing, 2e3, 1e4, 2e3, 0.4)
servo_bc.O.bodies[ids[7]].state.mass = 4.0 / 3.0 * math.pi * 1.02e-3 ** 3 * 2e3
try:
    servo_bc.ServoBC('D', ids, 1e-4, 1e4)
    check(False, 'sphere mass: accepted at 1e-4 s')
except servo_bc.ServoBCError as e:
    check('exceeds the critical step' in str(e) and 'of particle 7 (mass 8.89' in str(e), 'sphere mass: %s' % e)

# a time step of 1/1143 of the critical step: accepted, with the core's warning
# (time_step.h) printed once, as one line
servo_bc.O.reset()
ids, _ = servo_bc.load_packing(packing, 2e3, 1e4, 2e3, 0.4)
printed = io.StringIO()
with contextlib.redirect_stdout(printed):
    servo_bc.ServoBC('D F 0.999 0 0 0.999', ids, 1e-6, 1e4)
slow = [l for l in printed.getvalue().splitlines() if l.startswith('servo_bc: WARNING: ')]
check(len(slow) == 1 and 'servo_bc: WARNING: servo_bc: time step 1e-06 s is 1/1143 of the critical step 0.00114342 s'
      in slow[0], 'a slow time step: %s' % (slow or 'no warning'))

# a diverging controller stops the run with the core's message, no NaN
servo_bc.O.reset()
try:
    servo_bc.run_case(packing, 'P F 0.99 -0.02 -0.02 0.99 increments 2 tol_force 1e-14 gain_force 1e9 update fixed', 2e3, 1e4,
                      2e3, 0.4, 1e-5)
    check(False, 'divergence: no error')
except servo_bc.ServoBCError as e:
    # with remap none the frame runs half a radius from F X in iteration 0; with the presets' remap x the
    # interior follows the frame and the residual's growth stops it in iteration 1
    check(('increment 1, iteration 0' in str(e) and 'half its radius' in str(e)) or
          ('increment 1, iteration 1' in str(e) and 'grew more than 1000-fold' in str(e) and 'r_force = ' in str(e)),
          'divergence: %s' % e)

# confinement (confine.h): the centre disc moved out through the right edge after
# the frame is built stops the run at increment 0, whose row is not written
servo_bc.O.reset()
ids, _ = servo_bc.load_packing(packing, 2e3, 1e4, 0.0, 0.4)
escape_csv = os.path.join(os.path.dirname(os.path.abspath(packing)), 'escape.csv')
servo = servo_bc.ServoBC('D F 1.002 0 0 0.997 increments 2 relax 1e-22 20 file %s' % escape_csv, ids, 1e-5, 1e4)
servo_bc.O.engines = servo_bc.engines(servo, kn=1e4, ks=0.0)
centre = [i for i in servo.interior if abs(servo_bc.O.bodies[i].state.pos[0] - 4e-3) < 1e-9
          and abs(servo_bc.O.bodies[i].state.pos[1] - 4e-3) < 1e-9][0]
servo_bc.O.bodies[centre].state.pos = (0.0105, 0.004, 0.0)
try:
    servo.run()
    check(False, 'escaped disc: no error')
except servo_bc.ServoBCError as e:
    with open(escape_csv) as f:
        lines = len(f.readlines())
    check(('increment 0: interior particle %d escaped through a gap between frame particles (its centre (0.0105, '
           '0.004) m' % centre) in str(e) and lines == 1, 'escaped disc: %s; the CSV keeps its header alone' % e)

# the module's COLUMNS are the library's (columns.h): the results file's header
with open(escape_csv) as f:
    header = f.readline().strip()
check(header == ','.join(servo_bc.COLUMNS) and len(servo_bc.COLUMNS) == 25,
      'COLUMNS from the library: %d names, the results file\'s header' % len(servo_bc.COLUMNS))

# the documented 0.1 call forms (CHANGELOG.md): ServoBC(words, ids, dt) takes kn from
# the contact law engines() builds, and a fourth positional argument may be `done`;
# the rows equal those of the kn form to the last digit
def rows_of(make):
    servo_bc.O.reset()
    ids, _ = servo_bc.load_packing(packing, 2e3, 1e4, 0.0, 0.4)
    servo = make(ids)
    servo_bc.O.engines = servo_bc.engines(servo, kn=1e4, ks=0.0)
    servo.run()
    return servo, [[row[c] for c in servo_bc.COLUMNS] for row in servo.rows]


WORDS = 'D F 1.002 0 0 0.997 increments 2 relax 1e-22 20'
_, with_kn = rows_of(lambda ids: servo_bc.ServoBC(WORDS, ids, 1e-5, 1e4))
_, old_form = rows_of(lambda ids: servo_bc.ServoBC(WORDS, ids, 1e-5))
called = []
servo, old_done = rows_of(lambda ids: servo_bc.ServoBC(WORDS, ids, 1e-5, lambda s: called.append(s)))
check(len(with_kn) == 3 and old_form == with_kn and old_done == with_kn and called == [servo] and servo.kn == 1e4,
      'ServoBC(words, ids, dt) and ServoBC(words, ids, dt, done): kn %g N/m from engines(), %d rows equal to the '
      'kn form, done called %d time(s)' % (servo.kn, len(old_form), len(called)))
# no contact law known: the run stops with a ServoBCError that names kn
servo_bc.O.reset()
ids, _ = servo_bc.load_packing(packing, 2e3, 1e4, 0.0, 0.4)
servo = servo_bc.ServoBC(WORDS, ids, 1e-5)
servo_bc.O.engines = [servo_bc.ForceResetter(), servo.engine, servo_bc.NewtonIntegrator()]
try:
    servo.run(max_steps=10)
    check(False, 'ServoBC without kn and without engines(): ran')
except servo_bc.ServoBCError as e:
    check('no normal contact stiffness kn' in str(e), 'ServoBC without kn and without engines(): %s' % e)
version = servo_bc.__version__
check(len(version.split('.')) == 3 and all(p.isdigit() for p in version.split('.')),
      'servo_bc.__version__ %s' % version)
print('yade version: %s' % version)

sys.exit(summary())
