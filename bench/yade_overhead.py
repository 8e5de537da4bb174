# Per-step cost of the servo_bc YADE engine against the same scene with the frame
# held (frame bodies blocked, no engine), and how it splits between the core
# (time inside the ctypes calls) and the Python marshalling around them.
#   yade -n -x bench/yade_overhead.py SIDE STEPS PACKING   (a SIDE x SIDE lattice)
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(sys.argv[0])), '..', 'yade_adapter'))
import servo_bc  # noqa: E402

side, steps, packing = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
O = servo_bc.O


def scene(servo_words):
    O.reset()
    ids, frame = servo_bc.load_packing(packing, 2e3, 1e4, 2e3, 0.4)
    if servo_words:
        servo = servo_bc.ServoBC(servo_words, ids, 1e-6, 1e4)
    else:
        class Held(object):   # the frame held: blocked, nothing driving it
            engine = servo_bc.PyRunner(command='pass', iterPeriod=10 ** 9)
            damping = 0.7
        servo = Held
        for i in servo_bc.ServoBC('D', ids, 1e-6, 1e4).frame:
            O.bodies[i].state.blockedDOFs = 'xyzXYZ'
    O.engines = servo_bc.engines(servo, 1e4, 2e3)
    O.dt = 1e-6
    O.run(10, True)      # collider and interactions set up
    return servo


# the core's share: every ctypes call timed, less the engine's callbacks the
# core makes from within sbc_host_step (Python's time)
lib = servo_bc._core()
inside = [0.0]


class Timed(object):
    def __init__(self, fn):
        self.fn, self.restype, self.argtypes = fn, fn.restype, fn.argtypes

    def __call__(self, *a):
        t = time.perf_counter()
        r = self.fn(*a)
        inside[0] += time.perf_counter() - t
        return r


for name in ('sbc_host_step', 'sbc_host_command_x', 'sbc_host_command_theta', 'sbc_host_command_free',
             'sbc_host_result'):
    setattr(lib, name, Timed(getattr(lib, name)))


def called_back(method):
    def call(*a):
        t = time.perf_counter()
        r = method(*a)
        inside[0] -= time.perf_counter() - t
        return r
    return call


for name in ('_fire_sums_callback', '_interior_callback', '_contacts_callback', '_net_force_callback',
             '_frame_callback', '_interior_state_callback', '_row_callback'):
    setattr(servo_bc.ServoBC, name, called_back(getattr(servo_bc.ServoBC, name)))

scene(None)
t = time.perf_counter(); O.run(steps, True); held = time.perf_counter() - t
servo = scene('D F 0.999 0 0 0.999 increments 1000000')
inside[0] = 0.0
t = time.perf_counter(); O.run(steps, True); driven = time.perf_counter() - t
n = side * side
extra = (driven - held) / steps
print('(%d increments converged in the servo_bc run)' % len(servo.rows))
print('yade %6d particles: held %.1f us/step (%.0f ns/particle-step), servo_bc %.1f us/step: +%.1f us/step '
      '(%.0f %%), of which core %.1f us, Python marshalling %.1f us'
      % (n, 1e6 * held / steps, 1e9 * held / steps / n, 1e6 * driven / steps, 1e6 * extra,
         100 * extra * steps / held, 1e6 * inside[0] / steps, 1e6 * (extra - inside[0] / steps)))
