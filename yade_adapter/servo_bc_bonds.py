"""servo_bc for YADE, the bonded bodies: Bonds (the thesis' parallel and Timoshenko beam bonds, sbc/bpm_host.h)
and Cohesive (the paper's 2D cohesive law, eqs. 7-8), each a PyRunner that hands the core its bodies' centres
and velocities every step and adds the bonds' loads to O.forces. Imported by servo_bc, which exports both."""
import ctypes
import sys

from servo_bc_core import ServoBCError, library as _core, doubles as _doubles, free as _free
from yade import O
from yade.wrapper import PyRunner

_instances = []         # every ServoBC, Bonds and Cohesive made: each one's step callback is named by its place


def _check_bodies(bodies, who):
    """Every id names an existing sphere, once."""
    if not bodies:
        raise ServoBCError('%s: no bodies (expected the ids of the packing\'s spheres)' % who)
    seen = set()
    for i in bodies:
        if not isinstance(i, int) or isinstance(i, bool) or i < 0 or i >= len(O.bodies) or O.bodies[i] is None:
            raise ServoBCError('%s: body %r does not exist (expected ids of O.bodies, 0 to %d)'
                               % (who, i, len(O.bodies) - 1))
        if not hasattr(O.bodies[i].shape, 'radius'):
            raise ServoBCError('%s: body %d is a %s (expected a sphere)' % (who, i, type(O.bodies[i].shape).__name__))
        if i in seen:
            raise ServoBCError('%s: body %d is listed twice' % (who, i))
        seen.add(i)


class _BondedBodies(object):
    """What Bonds and Cohesive check as they run: no body of theirs erased, and no other
    Bonds or Cohesive engine of O.engines on the same bodies (which would bond them twice).
    Checked at the first step and every CHECK_EVERY steps after it."""
    CHECK_EVERY = 100

    def _bodies_checked(self, who):
        self._since_bodies += 1
        if self._since_bodies < self.CHECK_EVERY and self._bodies_seen:
            return
        self._since_bodies = 0
        bodies = O.bodies
        for i in self.bodies:
            if i >= len(bodies) or bodies[i] is None:
                raise ServoBCError('%s: body %d was erased after it was bonded (step %d); erase bonded bodies '
                                   'before creating %s' % (who, i, O.iter, type(self).__name__))
        if self._bodies_seen:
            return
        self._bodies_seen = True
        mine = set(self.bodies)
        for engine in O.engines:
            other = _bonded_engines.get(getattr(engine, 'label', ''))
            if other is None or other is self:
                continue
            shared = sorted(mine.intersection(other.bodies))
            if shared:
                raise ServoBCError('%s: body %d (and %d more) is bonded by another %s in O.engines too, which '
                                   'would bond it twice; one Bonds or Cohesive per body'
                                   % (who, shared[0], len(shared) - 1, type(other).__name__))


_bonded_engines = {}    # PyRunner label -> its Bonds or Cohesive


class Bonds(_BondedBodies):
    """The thesis' 3D bonded particle model on YADE spheres (bpm_host.h): bonds between the
    bodies that touch, Timoshenko beams (model='beam', E_b = E Pa, nu_b = nu) or parallel
    bonds (model='parallel', k^n = E / 2 r_min, k^s = k^n / 4.2), bond radius alpha r_min.
    The core keeps the bonds and their state and runs the bond loop in C; `engine` (a
    PyRunner for every step, between ForceResetter and NewtonIntegrator) hands it the
    bodies' centres and velocities and adds the bonds' forces and moments to O.forces.
    critical_dt(): eq. 48 of the thesis, 0.22 sqrt(m_min / k_max), s.
    strength: None (bonds never fail) or (F_t,u N, F_s,u N, M_b,u N m, M_t,u N m): a bond
    breaks when F_t/F_t,u + |F_s|/F_s,u + |M_b|/M_b,u + |M_t|/M_t,u >= 1 (0 leaves a term
    out) and becomes a frictional contact with coefficient friction."""

    def __init__(self, bodies, model='beam', E=4e9, nu=0.3, alpha=1.0, strength=None, friction=0.0):
        lib = _core()
        self.bodies = list(bodies)
        _check_bodies(self.bodies, 'servo_bc: bonds')
        self._since_bodies, self._bodies_seen = 0, False
        n = len(self.bodies)
        x, r, m = [], [], []
        for i in self.bodies:
            b = O.bodies[i]
            x += [b.state.pos[0], b.state.pos[1], b.state.pos[2]]
            r.append(b.shape.radius)
            m.append(b.state.mass)
        msg = ctypes.create_string_buffer(512)
        if strength is not None and len(strength) != 4:
            raise ServoBCError('servo_bc: bonds: strength needs 4 values (F_t,u N, F_s,u N, M_b,u N m, M_t,u N m), '
                               'got %r' % (strength,))
        fail = _doubles([float(v) for v in strength] + [float(friction)]) if strength is not None else None
        self._h = lib.sbc_bpm_host_create(str(model).encode(), float(E), float(nu), float(alpha), fail, n,
                                          _doubles(x), _doubles(r), _doubles(m), msg, 512)
        if not self._h:
            raise ServoBCError('servo_bc: ' + msg.value.decode())
        self.count = lib.sbc_bpm_host_bond_count(self._h)
        self._states = [O.bodies[i].state for i in self.bodies]
        self._x, self._v, self._w = [(ctypes.c_double * (3 * n))() for _ in range(3)]
        self._load = (ctypes.c_double * (6 * n))()
        _instances.append(self)
        name = '_servo_bc_bonds_%d' % (len(_instances) - 1)
        setattr(sys.modules['__main__'], name, self.step)
        self.engine = PyRunner(command='%s()' % name, iterPeriod=1, label='servo_bc_bonds_%d' % (len(_instances) - 1))
        _bonded_engines[self.engine.label] = self

    def __del__(self):
        if _free is not None:    # None once the interpreter tears the module down
            _free('sbc_bpm_free', getattr(self, '_h', None))
        self._h = None

    def critical_dt(self):
        return _core().sbc_bpm_critical_dt(self._h)

    def strain_energy(self):
        """The bonds' strain energy (eq. 50, or the beams' u K u / 2), J."""
        return _core().sbc_bpm_host_strain_energy(self._h)

    def intact(self):
        """Bonds not broken."""
        return _core().sbc_bpm_host_intact(self._h)

    def dissipated(self):
        """Eq. 51's share of the bonds: energy held by bonds when they broke, friction in
        their contacts, J."""
        return _core().sbc_bpm_host_dissipated(self._h)

    def step(self):
        """Called by the PyRunner each step: YADE's velocities here are v(t - dt/2)."""
        self._bodies_checked('servo_bc: bonds')
        st = self._states
        self._x[:] = [c for s in st for c in (s.pos[0], s.pos[1], s.pos[2])]
        self._v[:] = [c for s in st for c in (s.vel[0], s.vel[1], s.vel[2])]
        self._w[:] = [c for s in st for c in (s.angVel[0], s.angVel[1], s.angVel[2])]
        load = self._load
        if _core().sbc_bpm_host_loads(self._h, self._x, self._v, self._w, O.dt, load):
            raise ServoBCError('servo_bc: bonds: a load stopped being finite at step %d (time step %g s against '
                               'the critical %g s)' % (O.iter, O.dt, self.critical_dt()))
        forces = O.forces
        for k, i in enumerate(self.bodies):
            forces.addF(i, (load[6 * k], load[6 * k + 1], load[6 * k + 2]))
            forces.addT(i, (load[6 * k + 3], load[6 * k + 4], load[6 * k + 5]))


class Cohesive(_BondedBodies):
    """The paper's 2D cohesive bonds (eqs. 7-8) and frictional contacts (eq. 6) between the
    discs bodies (cohesive_host.h): bodies touching now are bonded; a bond that meets eq. 8
    breaks for good and the pair goes on by eq. 6 with the bond's kn, ks, mu. words: 'kn KN
    ks KS kr KR fn FN fs FS mr MR mu MU' (N/m, N/m, N m/rad, N, N, N m, -), the runner's
    `contact cohesive` words. The core owns every contact between these bodies and runs the
    pair loop in C; `engine` (a PyRunner for every step, after ForceResetter and before the
    servo_bc engine and NewtonIntegrator) hands it the centres and velocities and adds the
    forces and moments to O.forces. YADE must detect no contact between them (engines(...,
    contacts=this))."""

    def __init__(self, bodies, words):
        lib = _core()
        self.bodies = list(bodies)
        self.words = words
        _check_bodies(self.bodies, 'servo_bc: cohesive')
        self._since_bodies, self._bodies_seen = 0, False
        n = len(self.bodies)
        xy, r = [], []
        z0 = O.bodies[self.bodies[0]].state.pos[2]
        for i in self.bodies:
            b = O.bodies[i]
            z = b.state.pos[2]
            # the law is 2D: the discs lie in one plane z = const (a round-off apart)
            if not abs(z - z0) <= 1e-9 * b.shape.radius:
                raise ServoBCError('servo_bc: cohesive: body %d is at z = %g m, body %d at z = %g m: the cohesive law '
                                   'is 2D (discs in one plane z = const, blockedDOFs \'zXY\')'
                                   % (i, z, self.bodies[0], z0))
            xy += [b.state.pos[0], b.state.pos[1]]
            r.append(b.shape.radius)
        msg = ctypes.create_string_buffer(512)
        self._h = lib.sbc_cohesive_host_create(str(words).encode(), n, _doubles(xy), _doubles(r), msg, 512)
        if not self._h:
            raise ServoBCError('servo_bc: ' + msg.value.decode())
        self.kn = lib.sbc_cohesive_host_kn(self._h)
        self.bonds_initial = lib.sbc_cohesive_host_bonds_initial(self._h)
        self._states = [O.bodies[i].state for i in self.bodies]
        self._x, self._v = (ctypes.c_double * (2 * n))(), (ctypes.c_double * (2 * n))()
        self._w = (ctypes.c_double * n)()
        self._load = (ctypes.c_double * (3 * n))()
        self._sums = (ctypes.c_double * 4)()
        _instances.append(self)
        name = '_servo_bc_cohesive_%d' % (len(_instances) - 1)
        setattr(sys.modules['__main__'], name, self.step)
        self.engine = PyRunner(command='%s()' % name, iterPeriod=1, label='servo_bc_cohesive_%d' % (len(_instances) - 1))
        _bonded_engines[self.engine.label] = self

    def __del__(self):
        if _free is not None:    # None once the interpreter tears the module down
            _free('sbc_cohesive_host_free', getattr(self, '_h', None))
        self._h = None

    def bond_count(self):
        """Intact bonds now."""
        return _core().sbc_cohesive_host_bond_count(self._h)

    def sums(self):
        """The last step's Ep (eq. 12 with the bond terms, J), sum dn / Rbar (eq. 39), contact
        count, sum |contact force| (N)."""
        _core().sbc_cohesive_host_sums(self._h, self._sums)
        return list(self._sums)

    def step(self):
        """Called by the PyRunner each step: YADE's velocities here are v(t - dt/2)."""
        self._bodies_checked('servo_bc: cohesive')
        st = self._states
        self._x[:] = [c for s in st for c in (s.pos[0], s.pos[1])]
        self._v[:] = [c for s in st for c in (s.vel[0], s.vel[1])]
        self._w[:] = [s.angVel[2] for s in st]
        load = self._load
        lib = _core()
        if lib.sbc_cohesive_host_loads(self._h, self._x, self._v, self._w, O.dt, load):
            raise ServoBCError('servo_bc: step %d: %s' % (O.iter, lib.sbc_cohesive_host_message(self._h).decode()))
        forces = O.forces
        for k, i in enumerate(self.bodies):
            forces.addF(i, (load[3 * k], load[3 * k + 1], 0.0))
            forces.addT(i, (0.0, 0.0, load[3 * k + 2]))
