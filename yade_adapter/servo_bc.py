"""servo_bc for YADE: micro-scale boundary conditions (D), (P), (T), mixed on a
frame of boundary particles, driven by the servo_bc core (libservo_bc.so).

Python only moves data between YADE and the core (ctypes over sbc/host.h);
every decision -- relaxation, residuals, corrections, increments -- is the
core's, the same code that drives the embedded engine and the LAMMPS fix.
ctypes rather than a CPython extension: YADE ships no C++ headers, the core
already builds as a shared library, and the per-step cost is YADE's attribute
access, not the call (see docs/yade/servo_bc.md for the measured split).

Usage (2D: spheres in z = 0 with blockedDOFs 'zXY'):

    import servo_bc
    ids, frame = servo_bc.load_packing('packing.yade', density=2e3, kn=1e4, ks=2e3, mu=0.4)
    servo = servo_bc.ServoBC('P F 1 0.1 0 1 increments 10 file out.csv', ids, dt=1e-6, kn=1e4)
    O.engines = servo_bc.engines(servo, kn=1e4, ks=2e3)
    servo.run()          # returns when the path is finished; raises ServoBCError otherwise
"""
import ctypes
import time
import math
import os
import sys

from servo_bc_core import (ServoBCError, DAMPING_NONE, DAMPING_LOCAL, DAMPING_FIRE,  # noqa: F401
                           RELAXING, CORRECTED, INCREMENT, FINISHED, FAILED, HostCallbacks, frame_offsets as _frame_offsets,
                           library as _core, columns as _columns, doubles as _doubles, version as _version,
                           free as _free)
from servo_bc_bonds import Bonds, Cohesive, _check_bodies, _instances  # noqa: F401 (Bonds, Cohesive: the API)
from yade import O, utils, Vector3
from yade.wrapper import (ForceResetter, InsertionSortCollider, Bo1_Sphere_Aabb, InteractionLoop,
                          Ig2_Sphere_Sphere_ScGeom, Ip2_FrictMat_FrictMat_FrictPhys,
                          Law2_ScGeom_FrictPhys_CundallStrack, NewtonIntegrator, PyRunner, FrictMat,
                          MatchMaker)

__all__ = ['ServoBCError', 'ServoBC', 'Bonds', 'Cohesive', 'load_packing', 'engines', 'run_case', 'COLUMNS',
           'FRAME_MASK']

RATTLER_SCAN = 1000                     # steps between full scans for contact-free bodies
PROGRESS_CHECK = 100                    # steps between looks at the clock for a progress line
PROGRESS_EVERY = 10.0                   # s of wall time between progress lines of a long increment
FRAME_MASK = 2                          # groupMask bit of the frame bodies load_packing flags


def load_packing(path, density, kn, ks, mu, young=None, dimension=2):
    """Creates the discs of a packing written by the runner (`write_packing yade FILE`:
    x y z r frame per line, m). Each disc gets the 2D mass rho_A pi R^2 (density: kg/m^2)
    and the disc inertia M R^2 / 2 about z, so that the dynamics are the embedded
    engine's; blockedDOFs 'zXY'. dimension 3: free spheres of mass rho 4/3 pi R^3 (density:
    kg/m^3) and inertia 2/5 M R^2, as the embedded sphere engine's. Material: FrictMat with friction angle atan(mu); the
    stiffnesses kn, ks (N/m) are imposed per contact by engines(). Particles flagged in the
    fifth column get the groupMask bit FRAME_MASK (servo words `frame 2`).
    Returns (ids, frame_ids)."""
    if not (density > 0 and kn > 0 and ks >= 0 and mu >= 0):
        raise ServoBCError('servo_bc load_packing: density %g, kn %g must be > 0; ks %g, mu %g >= 0'
                           % (density, kn, ks, mu))
    rows = []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            words = line.split('#', 1)[0].split()
            if not words:
                continue
            if len(words) not in (4, 5):
                raise ServoBCError('servo_bc load_packing: %s:%d: expected "x y z r [frame]", got %d words'
                                   % (path, number, len(words)))
            try:
                values = [float(w) for w in words]
            except ValueError:
                raise ServoBCError('servo_bc load_packing: %s:%d: not a number in "%s"' % (path, number, line.strip()))
            rows.append(values)
    if not rows:
        raise ServoBCError('servo_bc load_packing: %s holds no particle' % path)
    rmin = min(r[3] for r in rows)
    mat = O.materials.append(FrictMat(young=young or kn / rmin, poisson=ks / kn, frictionAngle=math.atan(mu),
                                      density=1.0))
    ids, frame = [], []
    for x, y, z, r, *flag in rows:
        b = utils.sphere((x, y, z), r, material=mat)
        if dimension == 3:
            m = density * 4.0 / 3.0 * math.pi * r ** 3
            b.state.mass = m
            b.state.inertia = (0.4 * m * r * r,) * 3
        else:
            m = density * math.pi * r * r
            b.state.mass = m
            b.state.inertia = (0.5 * m * r * r,) * 3
            b.state.blockedDOFs = 'zXY'
        i = O.bodies.append(b)
        ids.append(i)
        if flag and flag[0] != 0:
            b.groupMask |= FRAME_MASK
            frame.append(i)
    return ids, frame


def run_case(packing, words, density, kn, ks, mu, dt, max_steps=None, cohesive=None, dimension=2):
    """One servo_bc run on a packing file: the discs (spheres with dimension 3), the engines,
    the loading path. cohesive: the words of the paper's cohesive law ('kn KN ks KS kr KR fn
    FN fs FS mr MR mu MU', Cohesive), whose kn, ks, mu replace the arguments'.
    Returns the ServoBC object (rows, plot_data); raises ServoBCError on failure."""
    O.reset()
    ids, _ = load_packing(packing, density, kn, ks, mu, dimension=dimension)
    contacts = Cohesive(ids, cohesive) if cohesive else None
    servo = ServoBC(words, ids, dt, contacts.kn if contacts else kn, contacts=contacts)
    O.engines = engines(servo, kn, ks, contacts)
    try:
        servo.run(max_steps)
    finally:
        if contacts:
            print('servo_bc: cohesive bonds intact %d of %d' % (contacts.bond_count(), contacts.bonds_initial),
                  flush=True)
    return servo


def engines(servo, kn, ks, contacts=None):
    """The engine list of a servo_bc scene: contact law of eq. 6 with kn, ks (N/m) on every
    contact (Ip2 MatchMakers: exact for any radii), the servo_bc engine after the forces and
    before NewtonIntegrator, whose damping is eq. 10 with alpha = beta. The shear increment
    is the relative velocity at the contact point (avoidGranularRatcheting off): YADE's
    default scales its translational part by (R1+R2)/(R1+R2-delta), which moved sigma of the
    paper's regular packing 0.53 % of the stress scale away from the other hosts (0.15 %
    without it, docs/yade/servo_bc.md).
    contacts: a Cohesive object, which owns every contact between its bodies: then YADE
    detects no contact at all (no collider, no InteractionLoop) and its engine computes them."""
    if isinstance(servo, ServoBC):    # a ServoBC made without kn takes the contact law's
        servo._bind(contacts.kn if contacts is not None else kn)
    if contacts is not None:
        return [ForceResetter(), contacts.engine, servo.engine,
                NewtonIntegrator(damping=servo.damping, label='servo_bc_newton')]
    return [ForceResetter(),
            InsertionSortCollider([Bo1_Sphere_Aabb()]),
            InteractionLoop([Ig2_Sphere_Sphere_ScGeom(avoidGranularRatcheting=False)],
                            [Ip2_FrictMat_FrictMat_FrictPhys(kn=MatchMaker(algo='val', val=kn),
                                                             ks=MatchMaker(algo='val', val=ks))],
                            [Law2_ScGeom_FrictPhys_CundallStrack(label='servo_bc_law')]),
            servo.engine,
            NewtonIntegrator(damping=servo.damping, label='servo_bc_newton')]




def _engines_kn():
    """kn (N/m) of the contact law in O.engines (an Ip2_FrictMat_FrictMat_FrictPhys whose kn
    is a MatchMaker of one value, as engines() builds it), or None."""
    for engine in O.engines:
        if isinstance(engine, InteractionLoop):
            for functor in engine.physDispatcher.functors:
                maker = getattr(functor, 'kn', None)
                if isinstance(functor, Ip2_FrictMat_FrictMat_FrictPhys) and maker is not None and maker.algo == 'val':
                    return float(maker.val)
    return None


def version():
    """The version of the servo_bc core this module drives (CHANGELOG.md)."""
    return _version()


def __getattr__(name):
    """servo_bc.__version__ and servo_bc.COLUMNS (the result columns, columns.h): read from the library when
    first asked for (PEP 562)."""
    if name == '__version__':
        return version()
    if name == 'COLUMNS':
        return _columns()
    raise AttributeError(name)


class ServoBC(object):
    """The servo_bc engine. words: the servo_bc words (BC first), the grammar of every host;
    or the words as keyword arguments (ServoBC('P', ids, dt, kn, F=(1, .1, 0, 1), increments=10)).
    bodies: the specimen's body ids. A `frame MASK` word takes the frame from the bodies
    whose groupMask shares a bit with MASK; otherwise the core detects it. dt: O.dt (s).
    kn: the normal contact stiffness of engines() (N/m), which sets how fast the frame
    travels to new positions and the round-off floor of the force balance (relax.h).
    done: called with this object when the path finishes or fails.
    contacts: a Cohesive object that owns the bodies' contacts (Ep and the contact sums of
    relax.h are then its own, not YADE's interactions')."""

    def __init__(self, words, bodies, dt, kn=None, done=None, contacts=None, **keywords):
        if callable(kn) and done is None:    # the 0.1 call form ServoBC(words, bodies, dt, done)
            kn, done = None, kn
        for key, value in keywords.items():
            values = value if isinstance(value, (tuple, list)) else (value,)
            words += ' %s %s' % (key, ' '.join(str(v) for v in values))
        self.words = words
        self.bodies = list(bodies)
        self.dt = float(dt)
        self.kn = None
        self.done = done
        self.contacts = contacts
        self.rows = []            # one dict per converged increment (yade.plot: see plot_data)
        self.error = None
        self.finished = False
        self.steps = 0
        self._h = None
        _instances.append(self)
        # the PyRunner's command runs in __main__: a bound method placed there
        # costs a name lookup per step instead of an import and an index
        name = '_servo_bc_step_%d' % (len(_instances) - 1)
        setattr(sys.modules['__main__'], name, self.step)
        self.engine = PyRunner(command='%s()' % name, iterPeriod=1, label='servo_bc_%d' % (len(_instances) - 1))
        if kn is None and contacts is not None:
            kn = contacts.kn
        if kn is None:
            kn = _engines_kn()
        if kn is not None:
            self._bind(kn)

    def _bind(self, kn):
        """The core's controller, once the normal contact stiffness kn (N/m) is known: from
        ServoBC's kn, the Cohesive contacts, the contact law of O.engines, or engines()."""
        if self._h is not None:
            if float(kn) != self.kn:
                raise ServoBCError('servo_bc: engines() was given kn %g N/m; this ServoBC runs with kn %g N/m'
                                   % (float(kn), self.kn))
            return
        lib = _core()
        words = self.words
        self.kn = float(kn)
        self._started = self._reported = time.time()
        n = len(self.bodies)
        x, r, m = [], [], []
        _check_bodies(self.bodies, 'servo_bc')
        # discs (load_packing: blockedDOFs 'zXY') are 2D; free spheres 3D
        self.dim = 2 if all('z' in O.bodies[i].state.blockedDOFs for i in self.bodies) else 3
        for i in self.bodies:
            b = O.bodies[i]
            x += [b.state.pos[k] for k in range(self.dim)]
            r.append(b.shape.radius)
            m.append(b.state.mass)
        frame_list = self._frame_list(words)
        msg = ctypes.create_string_buffer(512)
        lst = (ctypes.c_int * max(1, len(frame_list)))(*frame_list)
        self._h = lib.sbc_host_create(words.encode(), self.dim, n, _doubles(x), _doubles(r), _doubles(m),
                                      len(frame_list), lst, self.dt, self.kn, msg, 512)
        if not self._h:
            text = msg.value.decode()
            raise ServoBCError(text if text.startswith('servo_bc') else 'servo_bc: ' + text)
        alpha, beta = ctypes.c_double(), ctypes.c_double()
        mode = lib.sbc_host_damping(self._h, ctypes.byref(alpha), ctypes.byref(beta))
        self._fire = mode == DAMPING_FIRE
        self._fire_beta = beta.value     # FIRE: eq. 10 on the free frame rotations of (T)
        self.damping = 0.0               # NewtonIntegrator's: eq. 10 with alpha = beta
        if mode == DAMPING_LOCAL:
            if alpha.value != beta.value:
                raise ServoBCError('servo_bc: keyword damping: alpha %g and beta %g differ; YADE\'s NewtonIntegrator '
                                   'damps forces and moments with one factor' % (alpha.value, beta.value))
            self.damping = alpha.value
        self._interior_states = None      # FIRE: the interior's State objects and (mass, inertia), cached
        self._fire_seen = None            # FIRE: the interior's forces, torques, velocities at the sums
        self.Q = lib.sbc_host_frame_size(self._h)
        particles = lib.sbc_host_frame_particles(self._h)
        self.frame = [self.bodies[particles[q]] for q in range(self.Q)]
        frame_set = set(self.frame)
        self.interior = [i for i in self.bodies if i not in frame_set]
        self.nrot = 3 if self.dim == 3 else 1  # rotation components: about z in 2D, a vector in 3D
        self.theta = [0.0] * (self.nrot * self.Q)  # the frame's rotations, kept here (prescribed ones)
        self._free = None
        self._rattlers = []
        self._law_functor = None
        self._states = [O.bodies[i].state for i in self.frame]
        self._moving = False
        self._columns = _columns(self.dim)
        self._fc_mean = 0.0       # the last measured mean |contact force|, N
        # keyword seal (seal.h): the walls' forces, computed by the core each step
        self._seal = lib.sbc_host_sealed(self._h) == 1
        self._seal_states = [O.bodies[i].state for i in self.bodies]
        self._seal_x = (ctypes.c_double * (self.dim * n))()
        self._seal_f = (ctypes.c_double * (self.dim * n))()
        self._seal_energy = ctypes.c_double(0.0)
        print('servo_bc %s: %s on %d bodies (%dD), frame of %d, kn %g N/m' % (version(), words.split()[0], n, self.dim,
                                                                                self.Q, self.kn), flush=True)
        warning = ctypes.create_string_buffer(2048)
        if lib.sbc_host_warning(self._h, warning, 2048):
            for line in warning.value.decode().splitlines():
                print('servo_bc: WARNING: %s' % line, flush=True)
        self._drive()
        self._apply_commands()

    def _drive(self):
        """The callbacks of sbc_host_drive (host.h): the core's host driver asks through them for what it
        needs on each step. An exception in one is kept and raised once sbc_host_step returns."""
        def guarded(function, default=None):
            def call(*args):
                try:
                    return function(*args)
                except BaseException as e:    # ctypes would print it and go on
                    if self._callback_error is None:
                        self._callback_error = e
                    return default
            return call
        T = HostCallbacks
        self._callback_error = None
        self._stream = {}                 # keyword remap x: body id -> the velocity to take back
        cb = HostCallbacks()
        if self._fire:
            cb.fire_sums = T.fire_sums_type(guarded(self._fire_sums_callback))
        cb.interior = T.interior_type(guarded(self._interior_callback))
        cb.contacts = T.contacts_type(guarded(self._contacts_callback))
        cb.net_force = T.net_force_type(guarded(self._net_force_callback, 0.0))
        cb.frame = T.frame_type(guarded(self._frame_callback))
        cb.interior_state = T.interior_state_type(guarded(self._interior_state_callback))
        cb.row = T.row_type(guarded(self._row_callback))
        cb.remap = T.remap_type(guarded(self._remap_callback))
        self._callbacks = cb              # ctypes keeps no reference of its own
        if _core().sbc_host_drive(self._h, ctypes.byref(cb)):
            raise ServoBCError(_core().sbc_host_message(self._h).decode())

    def _frame_list(self, words):
        w = words.split('#', 1)[0].split()
        if 'frame' not in w[1:]:
            return []
        k = w.index('frame', 1)
        if k + 1 >= len(w):
            return []                        # the core names the missing value
        try:
            mask = int(w[k + 1])
        except ValueError:
            raise ServoBCError("servo_bc: keyword 'frame': '%s' is not a YADE group mask (an integer)" % w[k + 1])
        return [k for k, i in enumerate(self.bodies) if O.bodies[i].groupMask & mask]

    def __del__(self):
        if _free is not None:    # None once the interpreter tears the module down
            _free('sbc_host_free', getattr(self, '_h', None))
        self._h = None

    # -- one step -----------------------------------------------------------
    def _kinetic_energy(self):
        """Ek of the interior (eq. 12): YADE's sum over dynamic bodies (prescribed frame
        bodies are not dynamic) less freely rotating frame bodies and contact-free rattlers,
        which the core leaves out (relax.h). The velocities are YADE's at this point of the
        step, half a step before the embedded engine's."""
        ek = utils.kineticEnergy()
        if self._free_any:
            for q, s in enumerate(self._states):
                if self._free[q]:
                    ek -= 0.5 * s.inertia[2] * s.angVel[2] ** 2
                    if self._moving:
                        ek -= 0.5 * s.mass * s.vel.squaredNorm()
        if self.steps % RATTLER_SCAN == 0:
            # only moving ones matter (a body at rest adds nothing); in a balanced
            # lattice every body has zero net force, and few move
            self._rattlers = [i for i in self.interior if self._contact_free(i) and self._moves(i)]
        for i in self._rattlers:
            if self._contact_free(i):
                s = O.bodies[i].state
                if self.dim == 3:
                    ek -= 0.5 * (s.mass * s.vel.squaredNorm() + sum(s.inertia[k] * s.angVel[k] ** 2 for k in range(3)))
                else:
                    ek -= 0.5 * (s.mass * s.vel.squaredNorm() + s.inertia[2] * s.angVel[2] ** 2)
        return max(ek, 0.0)

    def _law(self):
        if self._law_functor is None:
            loops = [e for e in O.engines if isinstance(e, InteractionLoop)]
            laws = [f for e in loops for f in e.lawDispatcher.functors
                    if isinstance(f, Law2_ScGeom_FrictPhys_CundallStrack)]
            if not laws:
                raise ServoBCError('servo_bc: Ep (eq. 12) needs Law2_ScGeom_FrictPhys_CundallStrack in an '
                                   'InteractionLoop of O.engines (see servo_bc.engines)')
            self._law_functor = laws[0]
        return self._law_functor

    @staticmethod
    def _moves(i):
        s = O.bodies[i].state
        return s.vel.squaredNorm() > 0.0 or s.angVel.squaredNorm() != 0.0

    @staticmethod
    def _contact_free(i):
        return O.forces.f(i).squaredNorm() == 0.0 and O.forces.t(i).squaredNorm() == 0.0

    def _potential_energy(self):
        """Ep (eq. 12): sum over contacts of Fn^2/2kn + Fs^2/2ks. The law's own sum (C++)
        divides by ks, which is 0 for frictionless contacts: then the sum is taken here."""
        if self.contacts is not None:
            return self.contacts.sums()[0]
        ep = self._law().elasticEnergy()
        if math.isfinite(ep):
            return ep
        ep = 0.0
        for I in O.interactions:
            if I.isReal:
                p = I.phys
                ep += 0.5 * p.normalForce.squaredNorm() / p.kn
                if p.ks > 0.0:
                    ep += 0.5 * p.shearForce.squaredNorm() / p.ks
        return ep

    def _contact_sums(self):
        """eq. 39's sum, the contact count and the sum of |contact force| (relax.h)."""
        if self.contacts is not None:
            return tuple(self.contacts.sums()[1:])
        ov, nc, fc = 0.0, 0, 0.0
        for I in O.interactions:
            if I.isReal and I.geom.penetrationDepth > 0.0:
                ov += I.geom.penetrationDepth / (0.5 * (I.geom.refR1 + I.geom.refR2))
                fc += (I.phys.normalForce + I.phys.shearForce).norm()
                nc += 1
        return ov, nc, fc

    def _net_force_max(self, fc_mean):
        """The largest |net contact force| on an interior body (relax.h); YADE's forces are
        the contact forces here, damping is applied later by NewtonIntegrator. While every
        frame body is prescribed (not dynamic), YADE's own unbalancedForce(True), the largest
        force on a dynamic body over the mean |contact force| (C++), times that mean: some
        80 times cheaper per step than a Python loop over 100 bodies. fc_mean: this step's
        mean contact force when measured, else the last one measured (the core decides on
        measured steps only, sbc_controller_needs)."""
        if not self._free_any and fc_mean > 0.0 and self.contacts is None:
            u = utils.unbalancedForce(True)
            if math.isfinite(u):
                return u * fc_mean
        if self.dim == 3:
            return math.sqrt(max([v.squaredNorm() for v in map(O.forces.f, self.interior)] or [0.0]))
        return math.sqrt(max([v[0] * v[0] + v[1] * v[1] for v in map(O.forces.f, self.interior)] or [0.0]))

    def step(self):
        """Called by the PyRunner each step, after the forces and before NewtonIntegrator."""
        if self.finished:
            return
        try:
            if self._h is None:
                raise ServoBCError('servo_bc: ServoBC has no normal contact stiffness kn (N/m): pass kn= to '
                                   'ServoBC, or build the engine list with servo_bc.engines(servo, kn, ks), '
                                   'which gives it the contact law\'s')
            self._step()
        except ServoBCError as e:
            self._stop(e)

    # -- the callbacks of the host driver (sbc_host_callbacks) ----------------
    def _fire_sums_callback(self, user_data, sums):
        """damping fire (fire_damping.h): FIRE's sums over the interior, whose velocities are YADE's
        v^(n-1/2) here (NewtonIntegrator then adds dt F/m, as the embedded engine does)."""
        forces = O.forces
        if self._interior_states is None:
            self._interior_states = [O.bodies[i].state for i in self.interior]
            self._interior_mass = [(st.mass, st.inertia[2]) for st in self._interior_states]
        states = self._interior_states
        fs = list(map(forces.f, self.interior))
        if self.dim == 3:
            ts, vs, ws = list(map(forces.t, self.interior)), [st.vel for st in states], [st.angVel for st in states]
            sums[0] = sum(f.dot(v) + t.dot(w) for f, t, v, w in zip(fs, ts, vs, ws))
            sums[1] = sum(v.squaredNorm() for v in vs)
            sums[2] = sum(f.squaredNorm() for f in fs)
            sums[3] = sum(w.squaredNorm() for w in ws)
            sums[4] = sum(t.squaredNorm() for t in ts)
            self._fire_seen = (fs, ts, vs, ws)
            return
        ts = [t[2] for t in map(forces.t, self.interior)]
        vs = [st.vel for st in states]
        ws = [st.angVel[2] for st in states]
        p = vv = ff = ww = mm = 0.0
        for f, t, v, w in zip(fs, ts, vs, ws):
            p += f[0] * v[0] + f[1] * v[1] + t * w
            vv += v[0] * v[0] + v[1] * v[1]
            ff += f[0] * f[0] + f[1] * f[1]
            ww += w * w
            mm += t * t
        sums[0], sums[1], sums[2], sums[3], sums[4] = p, vv, ff, ww, mm
        self._fire_seen = (fs, ts, vs, ws)

    def _fire_mix(self, mix):
        """FIRE's mix of this step on the interior's velocities; eq. 10 on the torque of a freely
        rotating frame body ((T)), as in the other hosts."""
        keep, push, spin, stop = mix[0], mix[1], mix[2], mix[3]
        fs, ts, vs, ws = self._fire_seen
        half = 0.5 * self.dt * stop
        for st, (mass, inertia), f, t, v, w in zip(self._interior_states, self._interior_mass, fs, ts, vs, ws):
            q = push - half / mass
            if self.dim == 3:
                st.vel = v * keep + f * q
                st.angVel = w * keep + t * (spin - half / inertia)
                continue
            st.vel = (keep * v[0] + q * f[0], keep * v[1] + q * f[1], 0.0)
            st.angVel = (0.0, 0.0, keep * w + (spin - half / inertia) * t)
        if self._free_any and self._fire_beta > 0.0:
            forces = O.forces
            for q, s in enumerate(self._states):
                if self._free[q]:
                    t, w = forces.t(self.frame[q]), s.angVel
                    damp = [-math.copysign(self._fire_beta * abs(t[k]), w[k]) if w[k] != 0.0 else 0.0
                            for k in range(3)]
                    if self.dim == 2:
                        damp[0] = damp[1] = 0.0
                    if any(damp):
                        forces.addT(self.frame[q], tuple(damp))

    def _interior_callback(self, user_data, mix, out):
        """FIRE's mix when given; the interior's Ek and largest net force (relax.h). Eq. 10 is
        NewtonIntegrator's, later in the step."""
        if mix:
            self._fire_mix(mix)
        out[0] = self._kinetic_energy()
        out[1] = self._net_force_max(self._fc_mean)

    def _contacts_callback(self, user_data, out):
        out[0] = self._potential_energy() + (self._seal_energy.value if self._seal else 0.0)
        out[1], out[2], out[3] = self._contact_sums()

    def _net_force_callback(self, user_data, sums):
        """The largest net force again with this step's mean contact force (_net_force_max)."""
        self._fc_mean = sums[3] / sums[2] if sums[2] > 0 else 0.0
        return self._net_force_max(self._fc_mean)

    def _frame_callback(self, user_data, buf):
        Q, r = self.Q, self.nrot
        at_torque, at_theta, at_sums = _frame_offsets(Q, self.dim)
        z = 3 - r                         # the first rotation component: z alone in 2D
        turned = 0.0
        for q, i in enumerate(self.frame):
            s = self._states[q]
            f, t = O.forces.f(i), O.forces.t(i)
            buf[3 * q], buf[3 * q + 1], buf[3 * q + 2] = s.pos[0], s.pos[1], s.pos[2]
            buf[3 * Q + 3 * q], buf[3 * Q + 3 * q + 1], buf[3 * Q + 3 * q + 2] = f[0], f[1], f[2]
            theta = self._frame_theta(q, s)
            for c in range(r):
                buf[at_torque + r * q + c] = t[z + c]
                buf[at_theta + r * q + c] = theta[c]
            turned += self._rotation_length(theta)
        buf[at_sums] = sum(self._rotation_length(list(O.bodies[i].state.rot())[3 - r:]) for i in self.interior) + turned
        buf[at_sums + 1] = len(self.bodies)

    def _rotation_length(self, theta):
        """|theta| of eq. 41: the angle about z in 2D, the rotation vector's length in 3D."""
        return abs(theta[0]) if self.nrot == 1 else math.sqrt(theta[0] ** 2 + theta[1] ** 2 + theta[2] ** 2)

    def _interior_state_callback(self, user_data, ids, x, v):
        """The interior bodies for the confinement test (confine.h): ids, centres, velocities."""
        for k, i in enumerate(self.interior):
            st = O.bodies[i].state
            ids[k] = i
            x[3 * k], x[3 * k + 1], x[3 * k + 2] = st.pos[0], st.pos[1], st.pos[2]
            v[3 * k], v[3 * k + 1], v[3 * k + 2] = st.vel[0], st.vel[1], st.vel[2]

    def _remap_callback(self, user_data, M, origin, sign):
        """keyword remap x (driver.h): the interior's velocity gains the frame's affine move over one step,
        which NewtonIntegrator's x += dt v carries out and the next InteractionLoop's relative velocities
        see (sign +1); the next step takes back exactly what was added (sign -1)."""
        if sign < 0:
            for i, added in self._stream.items():
                st = O.bodies[i].state
                st.vel = st.vel - added
            self._stream = {}
            return
        d, dt, displacement = self.dim, self.dt, _core().sbc_remap_displacement
        x, u = (ctypes.c_double * 3)(), (ctypes.c_double * 3)()
        for i in self.interior:
            st = O.bodies[i].state
            p = st.pos
            x[0], x[1], x[2] = p[0], p[1], p[2]
            displacement(d, M, origin, x, u)
            added = Vector3(*[u[a] / dt if a < d else 0.0 for a in range(3)])
            st.vel = st.vel + added
            self._stream[i] = added

    def _row_callback(self, user_data, row, line):
        self.rows.append(dict(zip(self._columns, row[:len(self._columns)])))
        print(line.decode(), flush=True)
        self._reported = time.time()

    def _seal_forces(self):
        """keyword seal: the walls of the frame's polygon or surface on the bodies (sbc_host_seal),
        added to YADE's forces before anything is measured; the frame bodies' reactions included."""
        d = self.dim
        self._seal_x[:] = [st.pos[k] for st in self._seal_states for k in range(d)]
        touching = _core().sbc_host_seal(self._h, self._seal_x, self._seal_f, ctypes.byref(self._seal_energy))
        if touching < 0:
            raise ServoBCError(_core().sbc_host_message(self._h).decode())
        if touching:
            f = self._seal_f
            for k, i in enumerate(self.bodies):
                fk = tuple(f[d * k + j] for j in range(d)) + (0.0,) * (3 - d)
                if any(fk):
                    O.forces.addF(i, fk)

    def _step(self):
        lib = _core()
        if self._seal:
            self._seal_forces()
        ev = lib.sbc_host_step(self._h)
        self.steps += 1
        if self._callback_error is not None:
            error, self._callback_error = self._callback_error, None
            raise error
        if self.steps % PROGRESS_CHECK == 0:
            self._report_progress()
        if ev == FAILED:
            self._stop(ServoBCError(lib.sbc_host_message(self._h).decode()))
            return
        if ev == FINISHED:
            self._stop(None)
            return
        self._apply_commands(ev in (CORRECTED, INCREMENT))

    def _report_progress(self):
        """A progress line when an increment has run PROGRESS_EVERY seconds since the last line."""
        now = time.time()
        if now - self._reported >= PROGRESS_EVERY:
            self._reported = now
            line = ctypes.create_string_buffer(256)
            _core().sbc_host_progress_line(self._h, self.steps, now - self._started, line, 256)
            print('servo_bc:   ' + line.value.decode(), flush=True)

    def _frame_theta(self, q, state):
        """Frame body q's rotation (nrot components): YADE's own when free ((T)), the commanded one else."""
        r = self.nrot
        return list(state.rot())[3 - r:] if self._free[q] else self.theta[r * q:r * q + r]

    def _apply_commands(self, changed=True):
        """Frame bodies reach new targets within the next NewtonIntegrator pass
        (velocity = (target - position) / dt) and are stopped on the step after;
        prescribed rotations likewise; free ones ((T)) are integrated by YADE
        (blockedDOFs 'xyzXY', 'xyz' in 3D). Steps without new commands cost nothing here."""
        if not changed:
            if self._moving:
                for q, s in enumerate(self._states):
                    s.vel = (0.0, 0.0, 0.0)
                    if not self._free[q]:
                        s.angVel = (0.0, 0.0, 0.0)
                self._moving = False
            return
        lib = _core()
        cx = lib.sbc_host_command_x(self._h)
        ct = lib.sbc_host_command_theta(self._h)
        cf = lib.sbc_host_command_free(self._h)
        free = [bool(cf[q]) for q in range(self.Q)]
        if free != self._free:
            self._free = free
            self._free_any = any(free)
            for q, s in enumerate(self._states):
                s.blockedDOFs = ('xyz' if self.dim == 3 else 'xyzXY') if free[q] else 'xyzXYZ'
        inv = 1.0 / self.dt
        r = self.nrot
        for q, s in enumerate(self._states):
            pos = s.pos
            s.vel = ((cx[3 * q] - pos[0]) * inv, (cx[3 * q + 1] - pos[1]) * inv,
                     (cx[3 * q + 2] - pos[2]) * inv if self.dim == 3 else 0.0)
            if not free[q]:
                w = [(ct[r * q + c] - self.theta[r * q + c]) * inv for c in range(r)]
                s.angVel = tuple(w) if r == 3 else (0.0, 0.0, w[0])
                for c in range(r):
                    self.theta[r * q + c] = ct[r * q + c]
        self._moving = True

    def _stop(self, error):
        self.finished = True
        self.error = error
        O.pause()
        if self.done:
            self.done(self)

    # -- driving and results --------------------------------------------------
    def run(self, max_steps=None):
        """Runs until the loading path is finished; raises ServoBCError with the core's
        message when it fails, and when max_steps pass first. O.dt becomes the dt given to
        ServoBC (the controller's gains and the frame's travel are in its steps); a different
        O.dt is reported, not kept."""
        if O.dt != self.dt:
            print('servo_bc: O.dt %g s replaced by the time step %g s given to ServoBC' % (O.dt, self.dt), flush=True)
        O.dt = self.dt
        if max_steps:
            O.run(int(max_steps), True)
        else:
            O.run()
            O.wait()
        if self.error:
            raise self.error
        if not self.finished:
            raise ServoBCError('servo_bc: the loading path is not finished after %d steps (%d increments done)'
                               % (self.steps, len(self.rows)))

    def plot_data(self):
        """The converged increments as columns, e.g. for yade.plot.data."""
        return {c: [row[c] for row in self.rows] for c in self._columns}
