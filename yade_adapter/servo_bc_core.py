"""The servo_bc core's C API from Python (ctypes over libservo_bc.so): the library
with its signatures, the constants of sbc/host.h, the version, the result columns,
and ServoBCError. It needs no YADE: the YADE engine (servo_bc.py, beside it) is
built on it, and so can another host or a script.

    import servo_bc_core as core
    core.version()      # '0.3.0'
    core.columns()      # ('increment', 'F11', ...), the header of a 2D results file
    lib = core.library()
    h = lib.sbc_host_create(b'D F 0.99 0 0 0.99', 2, n, xy, r, m, 0, None, dt, kn, msg, len(msg))

The library is found at $SERVO_BC_LIB, beside this file, in the folder `make install` or `pip install .` recorded
(servo_bc_paths.py), or in ../build/.
"""
import ctypes
import os

__all__ = ['ServoBCError', 'library', 'version', 'columns', 'doubles', 'frame_size', 'frame_offsets', 'HostCallbacks',
           'MaterialPoint', 'integrate_points', 'DAMPING_NONE',
           'DAMPING_LOCAL', 'DAMPING_FIRE', 'FIRE_SUMS', 'RELAXING', 'CORRECTED', 'INCREMENT', 'FINISHED', 'FAILED']

DAMPING_NONE, DAMPING_LOCAL, DAMPING_FIRE = 0, 1, 2  # sbc_damping (settings.h)
FIRE_SUMS = 5                                        # SBC_FIRE_SUMS (fire_damping.h)
RELAXING, CORRECTED, INCREMENT, FINISHED, FAILED = range(5)   # sbc_event

_pd = ctypes.POINTER(ctypes.c_double)


class HostCallbacks(ctypes.Structure):
    """sbc_host_callbacks (host.h): the host's side of one step, given once to sbc_host_drive. Each field is
    made from its own function type, e.g. HostCallbacks.interior_type(f) for f(user_data, mix, out)."""
    fire_sums_type = ctypes.CFUNCTYPE(None, ctypes.c_void_p, _pd)
    interior_type = ctypes.CFUNCTYPE(None, ctypes.c_void_p, _pd, _pd)
    contacts_type = ctypes.CFUNCTYPE(None, ctypes.c_void_p, _pd)
    net_force_type = ctypes.CFUNCTYPE(ctypes.c_double, ctypes.c_void_p, _pd)
    frame_type = ctypes.CFUNCTYPE(None, ctypes.c_void_p, _pd)
    interior_state_type = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.POINTER(ctypes.c_long), _pd, _pd)
    row_type = ctypes.CFUNCTYPE(None, ctypes.c_void_p, _pd, ctypes.c_char_p)
    remap_type = ctypes.CFUNCTYPE(None, ctypes.c_void_p, _pd, _pd, ctypes.c_int)
    _fields_ = [('user_data', ctypes.c_void_p), ('fire_sums', fire_sums_type), ('interior', interior_type),
                ('contacts', contacts_type), ('net_force', net_force_type), ('frame', frame_type),
                ('interior_state', interior_state_type), ('row', row_type), ('remap', remap_type)]


def frame_offsets(q, dim=2):
    """SBC_DRIVER_TORQUE, SBC_DRIVER_THETA, SBC_DRIVER_SUMS (driver.h): where the frame callback's buffer
    for q frame particles holds the torques, the rotations (r = 1 in 2D, 3 in 3D per particle) and the
    sums (sum |theta|, particle count); x [3q] and force [3q] come first."""
    r = 3 if dim == 3 else 1
    return 6 * q, (6 + r) * q, (6 + 2 * r) * q


def frame_size(q, dim=2):
    """SBC_DRIVER_FRAME_SIZE (driver.h): the doubles of the frame callback's buffer for q frame particles."""
    return frame_offsets(q, dim)[2] + 2


class Cohesive(ctypes.Structure):
    """sbc_cohesive (contact.h): eqs. 7-8's kn, ks (N/m), kr (N m/rad), fn_u, fs_u (N), m_u (N m), mu."""
    _fields_ = [(name, ctypes.c_double) for name in ('kn', 'ks', 'kr', 'fn_u', 'fs_u', 'm_u', 'mu')]


class PointDef(ctypes.Structure):
    """sbc_point_def (material_point.h)."""
    _fields_ = [('dim', ctypes.c_int), ('n', ctypes.c_int), ('x', _pd), ('r', _pd), ('box', _pd), ('words', ctypes.c_char_p),
                ('kn', ctypes.c_double), ('ks', ctypes.c_double), ('mu', ctypes.c_double),
                ('density', ctypes.c_double), ('dt', ctypes.c_double), ('bonds', ctypes.POINTER(Cohesive))]


class ServoBCError(RuntimeError):
    """A servo_bc message: bad words, a frame that cannot be built, a diverging controller."""


def _installed_libdir():
    """The library folder `make install` or `pip install .` recorded (servo_bc_paths.py), or ''."""
    try:
        import servo_bc_paths
        return servo_bc_paths.LIBDIR
    except ImportError:
        return ''


def _load():
    here = os.path.dirname(os.path.abspath(__file__))
    libdir = _installed_libdir()
    candidates = [os.environ.get('SERVO_BC_LIB', ''), os.path.join(here, 'libservo_bc.so'),
                  os.path.join(libdir, 'libservo_bc.so') if libdir else '',
                  os.path.join(here, '..', 'build', 'libservo_bc.so')]
    for path in candidates:
        if path and os.path.exists(path):
            lib = ctypes.CDLL(os.path.abspath(path))
            break
    else:
        raise ServoBCError('servo_bc: libservo_bc.so not found (run `make yade` or `make install`, or set '
                           'SERVO_BC_LIB)')
    D, I, P = ctypes.c_double, ctypes.c_int, ctypes.c_void_p
    pd, pi = ctypes.POINTER(ctypes.c_double), ctypes.POINTER(ctypes.c_int)
    sig = {
        'sbc_host_create': (P, [ctypes.c_char_p, I, I, pd, pd, pd, I, pi, D, D, ctypes.c_char_p, ctypes.c_size_t]),
        'sbc_host_free': (None, [P]),
        'sbc_host_frame_size': (I, [P]),
        'sbc_host_frame_particles': (pi, [P]),
        'sbc_host_drive': (I, [P, ctypes.POINTER(HostCallbacks)]),
        'sbc_host_step': (I, [P]),
        'sbc_host_message': (ctypes.c_char_p, [P]),
        'sbc_host_progress_line': (None, [P, ctypes.c_long, D, ctypes.c_char_p, ctypes.c_size_t]),
        'sbc_host_command_x': (pd, [P]),
        'sbc_host_command_theta': (pd, [P]),
        'sbc_host_command_free': (ctypes.POINTER(ctypes.c_ubyte), [P]),
        'sbc_host_result': (None, [P, pd]),
        'sbc_host_damping': (I, [P, pd, pd]),
        'sbc_host_warning': (I, [P, ctypes.c_char_p, ctypes.c_size_t]),
        'sbc_version': (ctypes.c_char_p, []),
        'sbc_column_count': (I, [I]),
        'sbc_column_name': (ctypes.c_char_p, [I, I]),
        'sbc_bpm_host_create': (P, [ctypes.c_char_p, D, D, D, pd, I, pd, pd, pd, ctypes.c_char_p, ctypes.c_size_t]),
        'sbc_bpm_host_bond_count': (I, [P]),
        'sbc_bpm_host_intact': (I, [P]),
        'sbc_bpm_host_dissipated': (D, [P]),
        'sbc_bpm_host_loads': (I, [P, pd, pd, pd, D, pd]),
        'sbc_bpm_host_strain_energy': (D, [P]),
        'sbc_bpm_critical_dt': (D, [P]),
        'sbc_bpm_free': (None, [P]),
        'sbc_cohesive_host_create': (P, [ctypes.c_char_p, I, pd, pd, ctypes.c_char_p, ctypes.c_size_t]),
        'sbc_cohesive_host_free': (None, [P]),
        'sbc_cohesive_host_kn': (D, [P]),
        'sbc_cohesive_host_bond_count': (I, [P]),
        'sbc_cohesive_host_bonds_initial': (I, [P]),
        'sbc_cohesive_host_loads': (I, [P, pd, pd, pd, D, pd]),
        'sbc_cohesive_host_message': (ctypes.c_char_p, [P]),
        'sbc_cohesive_host_sums': (None, [P, pd]),
        'sbc_point_create': (P, [ctypes.POINTER(PointDef), P]),
        'sbc_cohesive_parse': (I, [I, ctypes.POINTER(ctypes.c_char_p), ctypes.c_char_p, ctypes.POINTER(Cohesive), P]),
        'sbc_point_free': (None, [P]),
        'sbc_point_integrate': (I, [P, pd, pd, pd, P]),
        'sbc_point_certified': (I, [P]),
        'sbc_point_commit': (I, [P]),
        'sbc_point_revert': (None, [P]),
        'sbc_point_state_size': (ctypes.c_size_t, [P]),
        'sbc_point_save': (None, [P, pd]),
        'sbc_point_load': (I, [P, pd, ctypes.c_size_t, P]),
        'sbc_point_tangent_perturbation': (I, [P, D, pd, P]),
        'sbc_point_tangent_affine': (I, [P, pd, P]),
        'sbc_point_tangent_condensed': (I, [P, pd, ctypes.POINTER(I), P]),
        'sbc_points_integrate': (I, [ctypes.POINTER(P), I, pd, pd, pi, pd, I, P]),
        'sbc_host_sealed': (I, [P]),
        'sbc_host_seal': (I, [P, pd, pd, pd]),
        'sbc_remap_displacement': (None, [I, pd, pd, pd, pd]),
    }
    for name, (res, args) in sig.items():
        fn = getattr(lib, name)
        fn.restype, fn.argtypes = res, args
    return lib


_lib = None


def library():
    """The core's shared library with the signatures of its C API (ctypes), loaded once."""
    global _lib
    if _lib is None:
        _lib = _load()
    return _lib


def columns(dim=2):
    """The result columns of a dim-dimensional results file in its order, from the library (columns.h)."""
    lib = library()
    return tuple(lib.sbc_column_name(dim, k).decode() for k in range(lib.sbc_column_count(dim)))


def doubles(values):
    """A ctypes array of the values (double)."""
    return (ctypes.c_double * len(values))(*values)


def free(name, handle):
    """Calls the library's free function name on handle, unless the library is already gone (interpreter exit)."""
    if _lib is not None and handle:
        getattr(_lib, name)(handle)


def version():
    """The version of the servo_bc core (CHANGELOG.md)."""
    return library().sbc_version().decode()


class _Error(ctypes.Structure):
    """sbc_error (status.h): the status and the message."""
    _fields_ = [('status', ctypes.c_int), ('message', ctypes.c_char * 512)]   # SBC_ERROR_LEN


# sbc_point_status by value (material_point.h)
POINT_STATUS = ('converged', 'failed', 'uncertified')


def _values(name, values, count):
    """values as a list of count floats, or a ServoBCError naming name and the count given (the C side reads count)."""
    try:
        out = [float(v) for v in values]
    except TypeError:
        raise ServoBCError('material point: %s is not a sequence of numbers' % name) from None
    if len(out) != count:
        raise ServoBCError('material point: %s has %d values (expected %d)' % (name, len(out), count))
    return out


class MaterialPoint:
    """The aggregate as a material point (material_point.h, docs/fe2.md): a packing (x [dim n], dim 2 or 3)
    under (D), (P) or (T) on an embedded engine. integrate(F) -> (converged, P, step_ratio) from the committed state
    (converged: certified at the words' accuracy; self.status 'converged', 'uncertified' (P stands, the reason in
    self.message) or 'failed'; certified() of the current state); commit(),
    revert(); state() -> bytes of the committed state, load(bytes) in a point made alike; tangent(h) -> C
    (81 values, C[9 (3i + j) + 3k + l] = dP_ij / dF_kl) by perturbation, tangent() the affine one, condensed()
    the condensed one. F and P:
    9 values, row-major 3 x 3 slots (the 2 x 2 block in 2D). Every array is checked against the length the C side
    reads. copy.copy and copy.deepcopy make a new point of the same definition at the committed state (as after
    revert()); close() frees the C side at once, after which every call raises ServoBCError."""

    def __init__(self, x, r, words, kn, ks=0.0, mu=0.0, density=2e3, dt=1e-6, box=None, dim=2, bonds=None):
        self._p = None
        lib = library()
        if dim not in (2, 3):
            raise ServoBCError('material point: dimension %r (expected 2 or 3)' % (dim,))
        r = _values('r', r, len(r) if hasattr(r, '__len__') else -1)
        x = _values('x', x, dim * len(r))
        box = _values('box', box, 4) if box else None
        self._args = dict(x=x, r=r, words=words, kn=kn, ks=ks, mu=mu, density=density, dt=dt, box=box, dim=dim,
                          bonds=bonds)
        self._x, self._r = doubles(x), doubles(r)
        self._box = doubles(box) if box else None
        self._words = words.encode()
        err = _Error()
        self._bonds = None
        if bonds is not None:    # the law's words, as the runner's 'contact cohesive' takes them
            w = [v.encode() for v in str(bonds).split()]
            self._bonds = Cohesive()
            if lib.sbc_cohesive_parse(len(w), (ctypes.c_char_p * max(1, len(w)))(*w), b'material point bonds',
                                      ctypes.byref(self._bonds), ctypes.byref(err)):
                raise ServoBCError(err.message.decode())
        d = PointDef(dim, len(r), self._x, self._r, self._box, self._words, kn, ks, mu, density, dt,
                     ctypes.pointer(self._bonds) if self._bonds is not None else None)
        self._p = lib.sbc_point_create(ctypes.byref(d), ctypes.byref(err))
        if not self._p:
            raise ServoBCError(err.message.decode())

    def close(self):
        """Frees the C side now (else at collection); the point is unusable afterwards."""
        handle, self._p = getattr(self, '_p', None), None
        free('sbc_point_free', handle)

    def __del__(self):
        self.close()

    def _handle(self):
        if not getattr(self, '_p', None):
            raise ServoBCError('material point: this point was closed, or its creation failed')
        return self._p

    def __copy__(self):
        other = MaterialPoint(**self._args)
        other.load(self.state())
        return other

    def __deepcopy__(self, memo):
        return self.__copy__()

    def __reduce__(self):
        raise TypeError('a MaterialPoint is not pickled: store state() and load() it into a point made alike')

    def integrate(self, F):
        P, ratio, err = (ctypes.c_double * 9)(), ctypes.c_double(), _Error()
        status = library().sbc_point_integrate(self._handle(), doubles(_values('F', F, 9)), P, ctypes.byref(ratio),
                                               ctypes.byref(err))
        self.message = err.message.decode() if status else ''
        self.status = POINT_STATUS[status]
        return status == 0, list(P), ratio.value

    def certified(self):
        return bool(library().sbc_point_certified(self._handle()))

    def commit(self):
        if library().sbc_point_commit(self._handle()):
            raise ServoBCError('material point: out of memory for its committed state')

    def revert(self):
        library().sbc_point_revert(self._handle())

    def state(self):
        n = library().sbc_point_state_size(self._handle())
        out = (ctypes.c_double * n)()
        library().sbc_point_save(self._handle(), out)
        return bytes(out)

    def load(self, data):
        n = len(data) // ctypes.sizeof(ctypes.c_double)
        err = _Error()
        if len(data) % ctypes.sizeof(ctypes.c_double):
            raise ServoBCError('material point: a state of %d bytes (a state is whole doubles)' % len(data))
        if library().sbc_point_load(self._handle(), (ctypes.c_double * n).from_buffer_copy(data), n,
                                    ctypes.byref(err)):
            raise ServoBCError(err.message.decode())

    def condensed(self):
        """The condensed tangent at the current state: (C, mechanisms), C as tangent() gives it."""
        C, count, err = (ctypes.c_double * 81)(), ctypes.c_int(), _Error()
        if library().sbc_point_tangent_condensed(self._handle(), C, ctypes.byref(count), ctypes.byref(err)):
            raise ServoBCError(err.message.decode())
        return list(C), count.value

    def tangent(self, h=None):
        """At the current state (the last integrate): by perturbation of step h, or affine (Voigt) without h."""
        C, err = (ctypes.c_double * 81)(), _Error()
        lib = library()
        status = lib.sbc_point_tangent_perturbation(self._handle(), float(h), C, ctypes.byref(err)) \
            if h is not None else lib.sbc_point_tangent_affine(self._handle(), C, ctypes.byref(err))
        if status:
            raise ServoBCError(err.message.decode())
        return list(C)


def integrate_points(points, Fs, threads=1):
    """Many MaterialPoints at once (sbc_points_integrate, C11 threads): points[k] to Fs[k] (9 values each).
    Returns (P, converged, ratios, message): P a list of 9-value lists, converged a list of booleans (certified
    converged), the step ratios, and the first failed point's message ('' when all converged); each point's
    status ('converged', 'failed' or 'uncertified': converged, P returned, but not certified) is its .status.
    Bit for bit the results of integrating each point alone, whatever the thread count."""
    n = len(points)
    if len(Fs) != n:
        raise ServoBCError('material points: %d points and %d F (expected one F per point)' % (n, len(Fs)))
    handles = (ctypes.c_void_p * n)(*[p._handle() for p in points])
    F = doubles([v for k, f in enumerate(Fs) for v in _values('F of point %d' % k, f, 9)])
    P, status, ratio, err = (ctypes.c_double * (9 * n))(), (ctypes.c_int * n)(), (ctypes.c_double * n)(), _Error()
    library().sbc_points_integrate(handles, n, F, P, status, ratio, threads, ctypes.byref(err))
    for point, code in zip(points, status):
        point.status = POINT_STATUS[code]
    return ([list(P[9 * k:9 * k + 9]) for k in range(n)], [s == 0 for s in status], list(ratio),
            err.message.decode() if any(status) else '')
