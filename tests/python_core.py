"""The core's C API from plain Python (yade_adapter/servo_bc_core.py), no YADE:
the module loads without it, its version and result columns are the runner's,
and a host handle is made on a 5 x 5 lattice (16 frame discs) or refused with
the core's message. Prints "N passed, N failed".
Usage: python3 tests/python_core.py LIBSERVO_BC.so SERVO_BC"""
import copy
import ctypes
import os
import pickle
import struct
import subprocess
import sys
import tempfile

lib_path, runner = sys.argv[1], os.path.abspath(sys.argv[2])
os.environ['SERVO_BC_LIB'] = os.path.abspath(lib_path)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'yade_adapter'))
import servo_bc_core as core  # noqa: E402

passed = failed = 0


def check(ok, label):
    global passed, failed
    if ok:
        passed += 1
        print('python core: %s' % label)
    else:
        failed += 1
        print('FAIL python core: %s' % label)


check('yade' not in sys.modules, 'servo_bc_core imports without YADE')
runner_version = subprocess.run([runner, '--version'], capture_output=True, text=True).stdout.split()
check(runner_version == ['servo-bc', core.version()], 'version %s, the runner\'s' % core.version())
with tempfile.TemporaryDirectory() as tmp:
    csv = os.path.join(tmp, 'run.csv')
    with open(os.path.join(tmp, 'run.sbc'), 'w') as f:
        f.write('dimension 2\nlattice square 5 5 spacing 2e-3 radius 1.02e-3\ncontact frictional kn 1e4 ks 0 mu 0.4\n'
                'density 2e3\ntimestep 1e-5\nservo_bc D F 0.999 0 0 0.999 increments 1 file %s\nrun\n' % csv)
    subprocess.run([runner, os.path.join(tmp, 'run.sbc')], capture_output=True, check=True)
    with open(csv) as f:
        header = f.readline().strip()
check(','.join(core.columns()) == header and len(core.columns()) == 25,
      '%d columns, the results file\'s header' % len(core.columns()))

lib = core.library()
xy = [c * 2e-3 for j in range(5) for i in range(5) for c in (i, j)]
n = 25
r = core.doubles([1.02e-3] * n)
m = core.doubles([2e3 * 3.141592653589793 * 1.02e-3 ** 2] * n)
msg = ctypes.create_string_buffer(512)
h = lib.sbc_host_create(b'Q F 1 0 0 1', 2, n, core.doubles(xy), r, m, 0, None, 1e-5, 1e4, msg, 512)
check(not h and b"'Q'" in msg.value, 'bad words refused with the core\'s message: %s' % msg.value.decode())
h = lib.sbc_host_create(b'P F 1 0.01 0 1 increments 2', 2, n, core.doubles(xy), r, m, 0, None, 1e-5, 1e4, msg, 512)
check(bool(h) and lib.sbc_host_frame_size(h) == 16, 'a host handle on the 5 x 5 lattice: a frame of %d discs'
      % (lib.sbc_host_frame_size(h) if h else -1))
if h:
    lib.sbc_host_free(h)

# the material point (material_point.h) through the module: (D) on the prestressed 5 x 5 lattice (radius 1.01 mm,
# frictionless), P11 = -N kn (2R - d F11) / ((N - 1) d) and C1111 = N kn / (N - 1); a state saved as bytes and
# loaded into a new point continues bit for bit
lattice = dict(x=xy, r=[1.01e-3] * n, kn=1e4, density=2e3, dt=2e-6)
point = core.MaterialPoint(words='D accuracy tight', **lattice)
ok, P, ratio = point.integrate([0.999, 0, 0, 0, 0.998, 0, 0, 0, 0])
want = -5 * 1e4 * (2.02e-3 - 2e-3 * 0.999) / (4 * 2e-3)
check(ok and ratio == 1.0 and abs(P[0] - want) <= 1e-6 * abs(want), 'material point (D): P11 %.9g N/m, closed form %.9g'
      % (P[0], want))
point.commit()
C = point.tangent(1e-4)
check(abs(C[0] - 12500) <= 1e-4 * 12500, 'material point: perturbation C1111 %.6g, closed form 12500' % C[0])
A = point.tangent()
check(abs(A[0] - 12500) <= 1e-8 * 12500 and abs(A[10] - P[4] / 0.998) <= 1e-8 * 12500,
      'material point: affine C1111 %.9g, C1212 %.9g (closed forms 12500, %.9g)' % (A[0], A[10], P[4] / 0.998))
K, mechanisms = point.condensed()
check(abs(K[0] - 12500) <= 1e-8 * 12500 and abs(K[10] - P[4] / 0.998) <= 1e-8 * 12500 and mechanisms == 9,
      'material point: condensed C1111 %.9g, C1212 %.9g, %d degrees of freedom without stiffness' % (K[0], K[10], mechanisms))
other = core.MaterialPoint(words='D accuracy tight', **lattice)
other.load(point.state())
F2 = [0.998, 0.0005, 0, 0, 0.999, 0, 0, 0, 0]
a, b = point.integrate(F2), other.integrate(F2)
check(a[0] and a == b, 'material point: the committed state as %d bytes, loaded into another point, continues bit for bit'
      % len(point.state()))
batch = [core.MaterialPoint(words='P accuracy balanced', **lattice) for _ in range(4)]
Fs = [[1 - 0.0005 * k, 0.0002 * k, 0, 0, 0.999, 0, 0, 0, 0] for k in range(4)]
P2, conv2, _, _ = core.integrate_points(batch, Fs, threads=2)
alone = [core.MaterialPoint(words='P accuracy balanced', **lattice).integrate(F)[1] for F in Fs]
check(all(conv2) and P2 == alone, 'material points: a batch of 4 on 2 threads, bit for bit each point alone')
try:
    core.MaterialPoint(words='D F 0.99 0 0 1', **lattice)
    check(False, 'material point: F in the words refused')
except core.ServoBCError as e:
    check("keyword 'F'" in str(e), 'material point: F in the words refused: %s' % e)

# converged but not certified: a 60-disc frictionless irregular packing under (T) at `tight` (interior dynamic, the
# runner's path) converges at F = I and after a step, but its states miss the stated accuracy (|hill_mandel| 1e-4 > 1e-6): the runner stops, the
# material point goes on and says so
with tempfile.TemporaryDirectory() as tmp:
    packing = os.path.join(tmp, 'irregular.txt')
    with open(os.path.join(tmp, 'make.sbc'), 'w') as f:
        f.write('dimension 2\ngenerate periodic n0 60 rmin 1e-3 polydispersity 2 seed 3 strain 0.01\n'
                'write_packing text %s\n' % packing)
    subprocess.run([runner, 'make.sbc'], cwd=tmp, check=True, capture_output=True)
    with open(os.path.join(tmp, 'run.sbc'), 'w') as f:
        f.write('dimension 2\nread_packing %s\ncontact frictional kn 1e4 ks 0 mu 0\ndensity 2e3\ntimestep 1e-5\n'
                'servo_bc T F 0.9995 0.0005 0 0.9998 accuracy tight\nrun\n' % packing)
    stopped = subprocess.run([runner, 'run.sbc'], cwd=tmp, capture_output=True, text=True)
    x, r, box = [], [], None
    for line in open(packing):
        w = line.split()
        if w and w[0] == 'box':
            box = [float(v) for v in w[1:5]]
        elif w and not w[0].startswith('#'):
            x += [float(v) for v in w[:2]]
            r.append(float(w[2]))
check(stopped.returncode != 0 and 'cannot be certified' in stopped.stdout + stopped.stderr,
      'uncertified: the runner stops on the 60-disc frictionless packing under (T), tight')
point = core.MaterialPoint(x, r, 'T accuracy tight interior dynamic', kn=1e4, density=2e3, dt=1e-5, box=box)
created = point.certified()
ok, P, ratio = point.integrate([0.9995, 0.0005, 0, 0, 0.9998, 0, 0, 0, 1])
check(not created and not ok and point.status == 'uncertified' and 'cannot be certified' in point.message and
      ratio == 0.5 and all(v == v and abs(v) < 1e30 for v in P) and P[0] < 0 and not point.certified(),
      'uncertified: the material point is created and integrates, status %s, P11 %.6g N/m, ratio %g: %s'
      % (point.status, P[0], ratio, point.message[:90]))
point.revert()
P_batch, conv_batch, _, _ = core.integrate_points([point], [[0.9995, 0.0005, 0, 0, 0.9998, 0, 0, 0, 1]])
check(point.status == 'uncertified' and conv_batch == [False] and P_batch[0] == P,
      'uncertified: integrate_points gives the same P bit for bit and the point\'s status %s' % point.status)
point.commit()
saved = point.state()
twin = core.MaterialPoint(x, r, 'T accuracy tight interior dynamic', kn=1e4, density=2e3, dt=1e-5, box=box)
created_size = len(twin.state())
twin.load(saved)
F2 = [0.9993, 0.0007, 0, 0, 0.9997, 0, 0, 0, 1]
check(len(saved) != created_size and point.integrate(F2)[1] == twin.integrate(F2)[1],
      'material point: a committed state of %d values (created with %d: the pair list grew) into a new point, '
      'which continues bit for bit' % (len(saved) // 8, created_size // 8))
bonded = core.MaterialPoint(xy, [1e-3] * n, 'D accuracy tight', kn=1e4, density=2e3, dt=2e-6,
                            bonds='kn 1e4 ks 4e3 kr 1e-4 fn 1e3 fs 1e3 mr 1e3 mu 0')
ok, P, ratio = bonded.integrate([1.001, 0, 0, 0, 1, 0, 0, 0, 1])
check(ok and abs(P[0] - 12.5) <= 1e-6 * 12.5, 'material point with cohesive bonds (eqs. 7-8): the touching 5 x 5 '
      'lattice stretched by 1e-3 carries P11 %.10g N/m, N kb_n e / (N - 1) = 12.5' % P[0])
try:
    core.MaterialPoint(xy, [1e-3] * n, 'D', kn=1e4, bonds='kn 1e4 ks 4e3')
    check(False, 'material point bonds: a law without its values is refused')
except core.ServoBCError as e:
    check('material point bonds' in str(e), 'material point bonds: refuses a law without its values: %s' % e)
again = core.MaterialPoint(words='P accuracy balanced', **lattice)
ok, P, ratio = again.integrate([0.999, 0, 0, 0, 0.999, 0, 0, 0, 1])
check(ok and again.status == 'converged' and again.certified() and ratio == 1.0,
      'uncertified: a certified increment says converged (the 5 x 5 lattice under (P))')


def refused(label, call, expected):
    """call() raises ServoBCError (or TypeError) whose text holds expected"""
    try:
        call()
    except (core.ServoBCError, TypeError) as e:
        check(expected in str(e), '%s: refused: %s' % (label, e))
        return
    check(False, '%s: not refused' % label)


# round 4's reproducers of MaterialPoint: no Python use crashes, every array is checked by length, a state is
# tied to the definition it came from
G = [0.999, 0.001, 0, 0, 0.999, 0, 0, 0, 1]
closed = core.MaterialPoint(words='P accuracy balanced', **lattice)
closed.__del__()
refused('a point used after __del__', lambda: closed.integrate(G), 'this point was closed')
closed.close()                        # twice: nothing
source = core.MaterialPoint(words='P accuracy balanced', **lattice)
source.integrate(G)
source.commit()
shallow, deep = copy.copy(source), copy.deepcopy(source)
P_source = source.integrate(G)[1]
del source
check(shallow.integrate(G)[1] == P_source and deep.integrate(G)[1] == P_source and shallow._p != deep._p,
      'copy.copy and copy.deepcopy: points of their own at the committed state, P bit for bit the original\'s')
refused('pickle', lambda: pickle.dumps(deep), 'not pickled')
refused('F of 4 values', lambda: deep.integrate([0.999, 0.001, 0, 0.999]), 'F has 4 values (expected 9)')
refused('x two values short', lambda: core.MaterialPoint(**dict(lattice, x=lattice['x'][:-2], words='P')),
        'x has %d values (expected %d)' % (len(lattice['x']) - 2, len(lattice['x'])))
refused('a periodic packing without its box', lambda: core.MaterialPoint(x, r, 'P', kn=1e4, density=2e3, dt=1e-5),
        "needs its box: sbc_point_def.box, MaterialPoint(box=[xlo, xhi, ylo, yhi])")
refused('a box of 3 values', lambda: core.MaterialPoint(**dict(lattice, box=[0, 1, 0], words='P')),
        'box has 3 values (expected 4)')
refused('a batch of 3 points and 1 F', lambda: core.integrate_points([shallow, deep, shallow], [G]),
        '3 points and 1 F')
_, conv, _, message = core.integrate_points([deep, deep], [G, G], threads=2)
check(conv == [False, False] and 'points 0 and 1 are the same sbc_point' in message,
      'one point twice in a batch: refused before either is integrated: %s' % message)
refused('a perturbation step of 1e-300', lambda: deep.tangent(1e-300), 'perturbation step 1e-300 (expected 1e-12')
refused('a perturbation step of 0', lambda: deep.tangent(0), 'perturbation step 0 (expected 1e-12')
state = deep.state()
refused('a state into a point with another kn', lambda: core.MaterialPoint(
    **dict(lattice, kn=2 * lattice['kn'], words='P accuracy balanced')).load(state), 'another contact law')
values = list(struct.unpack('%dd' % (len(state) // 8), state))
for at, label in ((len(values) - 18, 'committed F11'), (len(values) // 2, 'a value in the middle')):
    bad = list(values)
    bad[at] = 1e300
    refused('a state whose %s is 1e300' % label, lambda: deep.load(struct.pack('%dd' % len(bad), *bad)),
            'do not match their checksum')
refused('a state of 7 bytes', lambda: deep.load(state[:7]), 'a state of 7 bytes')
check(deep.integrate(G)[1] == P_source, 'after the refused loads the point integrates from its committed state, '
      'bit for bit')
print('%d passed, %d failed' % (passed, failed))
sys.exit(failed > 0)
