"""Contexts, handles, curves, surfaces, blends and Dupin cyclides."""

import collections
import math
import threading
import weakref
from ctypes import byref, c_double, c_int, c_size_t

from . import _array
from . import _lib as L
from ._lib import lib
from .errors import ClosedError, make_error

# ------------------------------------------------------------------ live handles

_live = collections.Counter()
_live_lock = threading.Lock()


def _track(kind, delta):
    with _live_lock:
        _live[kind] += delta
        if _live[kind] == 0:
            del _live[kind]


def live_handles():
    """{class name: count} of C objects created through the binding and not
    yet freed (contexts, curves, surfaces, skins, exports)."""
    with _live_lock:
        return dict(_live)


def version():
    """(version string of the loaded library, its version number, ABI)."""
    return (lib.cyc_version_string().decode(), lib.cyc_version_number(),
            lib.cyc_abi_version())


def status_name(status):
    return lib.cyc_status_name(int(status)).decode()


# ------------------------------------------------------------------ context


class Context:
    """A cyclide context (cyc_context). Use it from one thread at a time.

    Close it with close() or a with-block; closing also closes every handle
    created with it that is still open (handles are freed exactly once; a
    garbage-collected handle frees itself). Errors of calls made with it
    raise cyclide.Error subclasses carrying its last error message.
    """

    def __init__(self, error_handler=None):
        p = L.P_context()
        st = lib.cyc_context_create(None, byref(p))
        if st != 0:
            raise make_error(st, "could not create a context", "cyc_context_create")
        self._ptr = p
        self._children = weakref.WeakSet()
        self._handler = None
        _track("Context", 1)
        if error_handler is not None:
            self.set_error_handler(error_handler)

    # -- lifetime
    @property
    def ptr(self):
        if self._ptr is None:
            raise ClosedError(1, "the context is closed")
        return self._ptr

    @property
    def closed(self):
        return self._ptr is None

    def close(self):
        """Free the context and every still-open handle made with it. Safe to
        call more than once."""
        p, self._ptr = self._ptr, None
        if p is None:
            return
        for child in list(self._children):
            child.close()
        lib.cyc_context_destroy(p)
        self._handler = None
        _track("Context", -1)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        try:
            self.close()
        except Exception:  # interpreter shutdown
            pass

    def _adopt(self, handle):
        self._children.add(handle)
        return handle

    # -- errors
    @property
    def last_status(self):
        return lib.cyc_context_last_status(self.ptr)

    @property
    def last_error(self):
        return lib.cyc_context_last_error(self.ptr).decode("utf-8", "replace")

    def check(self, status, function=None):
        """Raise the Error for a non-zero status (with the last message)."""
        if status != 0:
            raise make_error(status, self.last_error, function)
        return status

    def call(self, name, *args):
        """Call the C function `name` with this context first; raise on error."""
        return self.check(getattr(lib, name)(self.ptr, *args), name)

    def set_error_handler(self, handler):
        """handler(status, message) on every error (None removes it).
        Exceptions raised by the handler are printed and ignored."""
        if handler is None:
            self.call("cyc_context_set_error_handler", L.cyc_error_handler(), None)
            self._handler = None
            return

        def trampoline(status, message, _userdata):
            handler(status, message.decode("utf-8", "replace") if message else "")

        cb = L.cyc_error_handler(trampoline)
        self.call("cyc_context_set_error_handler", cb, None)
        self._handler = cb  # keep the C callback alive

    # -- shortcuts
    def line(self, point, direction):
        return Curve.line(self, point, direction)

    def point(self, point):
        return Curve.point(self, point)


class Handle:
    """Base of the owning wrappers: .ptr, close(), with-block, __del__."""

    _destroy = None  # name of the C destroy function
    _with_ctx = True  # destroy takes (ctx, handle)

    def __init__(self, ctx, ptr):
        self._ctx = ctx
        self._ptr = ptr
        _track(type(self).__name__, 1)
        ctx._adopt(self)

    @property
    def ctx(self):
        return self._ctx

    @property
    def ptr(self):
        if self._ptr is None:
            raise ClosedError(1, "%s is closed" % type(self).__name__)
        return self._ptr

    @property
    def closed(self):
        return self._ptr is None

    def close(self):
        """Free the C object (once; later calls do nothing). Handles carry
        their own allocator, so this works after the context is closed."""
        p, self._ptr = self._ptr, None
        if p is None:
            return
        destroy = getattr(lib, self._destroy)
        if self._with_ctx:
            destroy(None, p)
        else:
            destroy(p)
        _track(type(self).__name__, -1)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        try:
            self.close()
        except Exception:
            pass

    def _call(self, name, *args):
        return self._ctx.call(name, self.ptr, *args)


# ------------------------------------------------------------------ curves


class Curve(Handle):
    """An input curve (cyc_curve): polynomial, rational, Bezier, line, point,
    line element or Hermite."""

    _destroy = "cyc_curve_destroy"

    @classmethod
    def _make(cls, ctx, name, *args):
        p = L.P_curve()
        ctx.call(name, *args, byref(p))
        return cls(ctx, p)

    @classmethod
    def line(cls, ctx, point, direction):
        """p(u) = point + u direction."""
        return cls._make(ctx, "cyc_curve_create_line", _array.vec3(point),
                         _array.vec3(direction))

    @classmethod
    def point(cls, ctx, point):
        return cls._make(ctx, "cyc_curve_create_point", _array.vec3(point))

    @classmethod
    def line_element(cls, ctx, point, tangent):
        return cls._make(ctx, "cyc_curve_create_line_element", _array.vec3(point),
                         _array.vec3(tangent))

    @classmethod
    def polynomial(cls, ctx, coeffs):
        """p(u) = sum_k coeffs[k] u^k; coeffs of shape (degree + 1, 3)."""
        a = _array.as_doubles(coeffs, (-1, 3), "coeffs")
        return cls._make(ctx, "cyc_curve_create_polynomial", a.shape[0] - 1, a.ptr, 3)

    @classmethod
    def rational(cls, ctx, coeffs):
        """(x, y, z)(u) / w(u); coeffs rows (x, y, z, w) in power form."""
        a = _array.as_doubles(coeffs, (-1, 4), "coeffs")
        return cls._make(ctx, "cyc_curve_create_rational", a.shape[0] - 1, a.ptr, 4)

    @classmethod
    def bezier(cls, ctx, control, weights=None, u0=0.0, u1=1.0):
        c = _array.as_doubles(control, (-1, 3), "control")
        w = None
        if weights is not None:
            w = _array.as_doubles(weights, (c.shape[0],), "weights")
        return cls._make(ctx, "cyc_curve_create_bezier", c.shape[0] - 1, c.ptr, 3,
                         w.ptr if w else None, float(u0), float(u1))

    @classmethod
    def hermite(cls, ctx, start, end, u0=0.0, u1=1.0):
        """C^K Hermite curve: start and end of shape (K + 1, 3), rows
        p, p', ..., p^(K)."""
        s = _array.as_doubles(start, (-1, 3), "start")
        e = _array.as_doubles(end, (s.shape[0], 3), "end")
        return cls._make(ctx, "cyc_curve_create_hermite", s.shape[0] - 1, float(u0), float(u1),
                         s.ptr, e.ptr)

    @property
    def degree(self):
        d = c_int()
        self._call("cyc_curve_degree", byref(d))
        return d.value

    def eval(self, u, order=0):
        """p(u) (order 0: a vector) or the rows p, p', ... p^(order)."""
        out = _array.OutArray((order + 1, 3))
        self._call("cyc_curve_eval", float(u), int(order), out.ptr, out.size)
        r = out.result()
        return r[0] if order == 0 else r


# ------------------------------------------------------------------ surfaces


class Mobius:
    """The circle parameter f(u, v) = (alpha v + beta) / (gamma v + delta)
    with polynomial coefficients in u (power form)."""

    def __init__(self, alpha=(1.0,), beta=(0.0,), gamma=(0.0,), delta=(1.0,)):
        self.coeffs = [list(map(float, c)) for c in (alpha, beta, gamma, delta)]

    def to_c(self):
        m = L.cyc_mobius()
        deg = max(len(c) for c in self.coeffs) - 1
        if deg > L.CYC_MAX_MOBIUS_DEGREE:
            raise make_error(4, "Mobius degree %d > %d" % (deg, L.CYC_MAX_MOBIUS_DEGREE))
        m.degree = deg
        for field, c in zip(("alpha", "beta", "gamma", "delta"), self.coeffs):
            arr = getattr(m, field)
            for k, x in enumerate(c):
                arr[k] = x
        return m


SurfacePoint = collections.namedtuple("SurfacePoint", "point du dv normal")
Grid = collections.namedtuple("Grid", "points normals du dv singular")
Circle = collections.namedtuple("Circle", "center normal radius")
Sphere = collections.namedtuple("Sphere", "center radius")


def _mobius_ptr(f):
    if f is None:
        return None, None
    m = f.to_c() if isinstance(f, Mobius) else f
    return byref(m), m


def _buffer(out):
    if out is None:
        return L.cyc_buffer3(None, 0, 3)
    return L.cyc_buffer3(out.ptr, out.shape[0], 3)


class Surface(Handle):
    """A circle-family surface (cyc_surface): PRCS, PRRS, ringed, blends,
    Dupin and parabolic cyclides."""

    _destroy = "cyc_surface_destroy"

    @classmethod
    def _make(cls, ctx, name, *args):
        p = L.P_surface()
        ctx.call(name, *args, byref(p))
        return cls(ctx, p)

    @classmethod
    def prcs(cls, ctx, p1, p2, u0, u1, f=None):
        """The canal surface through p1 and p2 (seed 000 eq. (11))."""
        fp, _keep = _mobius_ptr(f)
        return cls._make(ctx, "cyc_prcs_create", p1.ptr, p2.ptr, fp, float(u0), float(u1))

    @classmethod
    def prrs(cls, ctx, p1, p2, p3, u0, u1, f=None):
        """The ringed surface through p1, p2, p3 (seed 000 eq. (27))."""
        fp, _keep = _mobius_ptr(f)
        return cls._make(ctx, "cyc_prrs_create", p1.ptr, p2.ptr, p3.ptr, fp, float(u0),
                         float(u1))

    @classmethod
    def ringed(cls, ctx, d, n, c, u0, u1, f=None):
        """The ringed surface (d, n, rho) through the curve c (seed 001 (3))."""
        fp, _keep = _mobius_ptr(f)
        return cls._make(ctx, "cyc_ringed_create", d.ptr, n.ptr, c.ptr, fp, float(u0),
                         float(u1))

    # -- queries
    @property
    def kind(self):
        k = c_int()
        self._call("cyc_surface_kind", byref(k))
        return k.value

    @property
    def domain(self):
        u0, u1 = c_double(), c_double()
        self._call("cyc_surface_domain", byref(u0), byref(u1))
        return (u0.value, u1.value)

    def eval(self, u, v, derivatives=False, normal=True):
        """SurfacePoint(point, du, dv, normal) at (u, v); du, dv only with
        derivatives=True, normal only with normal=True (else None)."""
        x = (c_double * 3)()
        du = (c_double * 3)() if derivatives else None
        dv = (c_double * 3)() if derivatives else None
        n = (c_double * 3)() if normal else None
        self._call("cyc_surface_eval", float(u), float(v), x, du, dv, n)
        o = _array.out_vec
        return SurfacePoint(o(x), o(du) if du else None, o(dv) if dv else None,
                            o(n) if n else None)

    def point(self, u, v):
        return self.eval(u, v, normal=False).point

    def normal(self, u, v):
        return self.eval(u, v).normal

    def _grid_outputs(self, n, normals, derivatives):
        pts = _array.OutArray((n, 3))
        nrm = _array.OutArray((n, 3)) if normals else None
        du = _array.OutArray((n, 3)) if derivatives else None
        dv = _array.OutArray((n, 3)) if derivatives else None
        return pts, nrm, du, dv

    @staticmethod
    def _grid_result(pts, nrm, du, dv, singular):
        r = lambda a: a.result() if a is not None else None  # noqa: E731
        return Grid(r(pts), r(nrm), r(du), r(dv), singular.value)

    def eval_grid(self, us, vs, normals=True, derivatives=False):
        """The grid (us[i], vs[j]) at row i * len(vs) + j: Grid(points (n, 3),
        normals, du, dv, singular) (singular normals are (0, 0, 0))."""
        a = _array.as_doubles(us, (-1,), "us")
        b = _array.as_doubles(vs, (-1,), "vs")
        n = a.size * b.size
        pts, nrm, du, dv = self._grid_outputs(n, normals, derivatives)
        singular = c_size_t()
        self._call("cyc_surface_eval_grid", a.ptr, a.size, b.ptr, b.size, _buffer(pts),
                   _buffer(du), _buffer(dv), _buffer(nrm), byref(singular))
        return self._grid_result(pts, nrm, du, dv, singular)

    def eval_batch(self, uv, normals=True, derivatives=False):
        """Points at the parameter pairs uv (shape (n, 2)), as eval_grid."""
        a = _array.as_doubles(uv, (-1, 2), "uv")
        n = a.shape[0]
        pts, nrm, du, dv = self._grid_outputs(n, normals, derivatives)
        singular = c_size_t()
        self._call("cyc_surface_eval_batch", a.ptr, 2, n, _buffer(pts), _buffer(du),
                   _buffer(dv), _buffer(nrm), byref(singular))
        return self._grid_result(pts, nrm, du, dv, singular)

    def circle(self, u):
        c = L.cyc_circle()
        self._call("cyc_surface_circle", float(u), byref(c))
        return Circle(_array.out_vec(c.center), _array.out_vec(c.normal),
                      math.sqrt(max(c.radius2, 0.0)))

    def sphere(self, u):
        """The sphere touching a canal surface along its circle at u."""
        s = L.cyc_sphere()
        self._call("cyc_surface_sphere", float(u), byref(s))
        return Sphere(_array.out_vec(s.center), math.sqrt(max(s.radius2, 0.0)))

    def derivatives_u(self, u, v, K):
        """d^l x / du^l (u, v) for l = 0..K, shape (K + 1, 3)."""
        out = _array.OutArray((K + 1, 3))
        self._call("cyc_surface_derivatives_u", float(u), float(v), int(K), out.ptr)
        return out.result()

    def parameter_of(self, u, point):
        v = c_double()
        self._call("cyc_surface_parameter_of", float(u), _array.vec3(point), byref(v))
        return v.value

    def canal_test(self, tolerance=0.0):
        """(max residual, is_canal) of the canal test (2)."""
        r, ok = c_double(), c_int()
        self._call("cyc_surface_canal_test", float(tolerance), byref(r), byref(ok))
        return r.value, bool(ok.value)

    # -- export and meshes (see export.py)
    def tessellate(self, **options):
        from .export import tessellate
        return tessellate(self, **options)

    def export(self, u0=None, u1=None, v0=0.0, v1=0.0, whole_circle=True):
        from .export import BezierExport
        return BezierExport.from_surface(self, u0, u1, v0, v1, whole_circle)


# ------------------------------------------------------------------ blends


class BlendEnd:
    """One end of a blend: the end circle u of `surface`, circle parameters
    v (2 for canal, 3 for ringed blends; +-inf is the generator), the
    tangent length lam (0: chosen by the nearer end of the domain) and
    higher reparameterization derivatives phi (phi'', phi''', ...)."""

    def __init__(self, surface, u, v, lam=0.0, phi=()):
        self.surface, self.u, self.v = surface, float(u), [float(x) for x in v]
        self.lam, self.phi = float(lam), [float(x) for x in phi]
        if not 1 <= len(self.v) <= 3:
            raise ValueError("v: 1 to 3 circle parameters")
        if len(self.phi) > L.CYC_MAX_BLEND_ORDER - 1:
            raise ValueError("phi: at most %d values" % (L.CYC_MAX_BLEND_ORDER - 1))

    def to_c(self):
        e = L.cyc_blend_end()
        e.surface = self.surface.ptr
        e.u = self.u
        for k, x in enumerate(self.v):
            e.v[k] = x
        setattr(e, "lambda", self.lam)
        for k, x in enumerate(self.phi):
            e.phi[k] = x
        return e


def _blend(name, start, end, K, t0, t1):
    ctx = start.surface.ctx
    s, e = start.to_c(), end.to_c()
    return Surface._make(ctx, name, byref(s), byref(e), int(K), float(t0), float(t1))


def blend_canal(start, end, K=2, t0=0.0, t1=1.0):
    """Canal blend (seed 000 §9.1) from BlendEnd start to end, G^(K-1)."""
    return _blend("cyc_blend_canal", start, end, K, t0, t1)


def blend_ringed(start, end, K=1, t0=0.0, t1=1.0):
    """Ringed blend (seed 000 §9.2), C^K."""
    return _blend("cyc_blend_ringed", start, end, K, t0, t1)


def blend_ringed_matched(start, end, K=1, t0=0.0, t1=1.0):
    """Ringed blend whose circle parameterization continues the inputs'."""
    return _blend("cyc_blend_ringed_matched", start, end, K, t0, t1)


Continuity = collections.namedtuple(
    "Continuity", "K samples singular_samples max_gap point_scale max_normal_angle "
                  "point_jump point_scale_l circle_jump")


def continuity_report(a, ua, lam, b, ub, K, va=None, n=32):
    """Continuity of the join of surface a at u = ua and b at u = ub
    (lam = du_a / du_b); va: circle parameters of a (None: n spread)."""
    r = L.cyc_continuity()
    vals = None
    if va is not None:
        vals = _array.as_doubles(va, (-1,), "va")
        n = vals.size
    a.ctx.call("cyc_continuity_report", a.ptr, float(ua), float(lam), b.ptr, float(ub),
               int(K), vals.ptr if vals else None, int(n), byref(r))
    k = r.K + 1
    return Continuity(r.K, r.samples, r.singular_samples, r.max_gap, r.point_scale,
                      r.max_normal_angle, list(r.point_jump[:k]), list(r.point_scale_l[:k]),
                      list(r.circle_jump[:k]))


# ------------------------------------------------------------------ Dupin cyclides


class LieSphere:
    """An oriented sphere (rho > 0: normals outward), a point, an oriented
    plane x . n = lam, or the point at infinity (seed 003)."""

    def __init__(self, kind, m=(0, 0, 0), rho=0.0, n=(0, 0, 0), lam=0.0):
        self.kind, self.m, self.rho = int(kind), [float(x) for x in m], float(rho)
        self.n, self.lam = [float(x) for x in n], float(lam)

    @classmethod
    def sphere(cls, center, radius):
        return cls(L.CYC_LIE_SPHERE, center, radius)

    @classmethod
    def point(cls, p):
        return cls(L.CYC_LIE_POINT, p)

    @classmethod
    def plane(cls, normal, lam):
        return cls(L.CYC_LIE_PLANE, n=normal, lam=lam)

    def to_c(self, s=None):
        s = s if s is not None else L.cyc_lie_sphere()
        s.kind, s.rho = self.kind, self.rho
        s.m[:] = self.m
        s.n[:] = self.n
        setattr(s, "lambda", self.lam)
        return s

    @classmethod
    def from_c(cls, s):
        return cls(s.kind, list(s.m), s.rho, list(s.n), getattr(s, "lambda"))

    def __repr__(self):
        return "LieSphere(kind=%d, m=%s, rho=%g, n=%s, lam=%g)" % (
            self.kind, self.m, self.rho, self.n, self.lam)


DupinPoint = collections.namedtuple("DupinPoint", "point normal lam d_xi d_zeta")


def _spheres3(spheres):
    arr = (L.cyc_lie_sphere * 3)()
    spheres = list(spheres)
    if len(spheres) != 3:
        raise ValueError("three spheres needed")
    for k, s in enumerate(spheres):
        if not isinstance(s, LieSphere):
            s = LieSphere.sphere(*s)  # (center, radius)
        s.to_c(arr[k])
    return arr


class Dupin:
    """A Dupin cyclide (a plain value, cyc_dupin) bound to a context for its
    calls: the envelope of the spheres touching three given ones."""

    def __init__(self, ctx, c_value):
        self.ctx, self._c = ctx, c_value

    @classmethod
    def from_spheres(cls, ctx, spheres):
        """Algorithm 1 of seed 003: spheres are LieSphere or (center, radius)."""
        out = L.cyc_dupin()
        ctx.call("cyc_dupin_from_spheres", _spheres3(spheres), byref(out))
        return cls(ctx, out)

    @staticmethod
    def classify_spheres(ctx, spheres):
        """The signature of the span of three spheres (2, 0, 1) for a cyclide;
        raises the §3.1 case's error otherwise."""
        sig = (c_int * 3)()
        ctx.call("cyc_dupin_classify_spheres", _spheres3(spheres), sig)
        return tuple(sig)

    @property
    def type(self):
        return self._c.type

    def _new(self, name, *args):
        out = L.cyc_dupin()
        self.ctx.call(name, byref(self._c), *args, byref(out))
        return Dupin(self.ctx, out)

    def offset(self, d):
        return self._new("cyc_dupin_offset", float(d))

    def swap_families(self):
        return self._new("cyc_dupin_swap_families")

    def eval(self, xi, zeta, offset=0.0):
        p = L.cyc_dupin_point()
        self.ctx.call("cyc_dupin_eval", byref(self._c), float(xi), float(zeta), float(offset),
                      byref(p))
        o = _array.out_vec
        return DupinPoint(o(p.point), o(p.normal), getattr(p, "lambda"), o(p.d_xi),
                          o(p.d_zeta))

    def eval_grid(self, xis, zetas, offset=0.0):
        """(points, normals), each (len(xis) * len(zetas), 3), row-major."""
        a = _array.as_doubles(xis, (-1,), "xis")
        b = _array.as_doubles(zetas, (-1,), "zetas")
        pts = _array.OutArray((a.size * b.size, 3))
        nrm = _array.OutArray((a.size * b.size, 3))
        self.ctx.call("cyc_dupin_eval_grid", byref(self._c), a.ptr, a.size, b.ptr, b.size,
                      float(offset), pts.ptr, nrm.ptr)
        return pts.result(), nrm.result()

    def sphere(self, family, t):
        """The sphere a(t) (family 0) or a_perp(t) (family 1); t a number or
        a homogeneous pair."""
        if isinstance(t, (int, float)):
            t = (t, 1.0)
        out = L.cyc_lie_sphere()
        self.ctx.call("cyc_dupin_sphere", byref(self._c), int(family),
                      (c_double * 2)(*map(float, t)), byref(out))
        return LieSphere.from_c(out)

    def surface(self, u0, u1, xi_map=None, zeta_map=None):
        """The cyclide as a circle-family Surface over u in [u0, u1];
        xi = (a u + b) / (c u + d) from xi_map = (a, b, c, d) (None: xi = u)."""
        xm = (c_double * 4)(*map(float, xi_map)) if xi_map is not None else None
        zm = (c_double * 4)(*map(float, zeta_map)) if zeta_map is not None else None
        return Surface._make(self.ctx, "cyc_dupin_surface_create", byref(self._c), xm, zm,
                             float(u0), float(u1))


__all__ = ["Context", "Handle", "Curve", "Surface", "Mobius", "BlendEnd", "blend_canal",
           "blend_ringed", "blend_ringed_matched", "continuity_report", "LieSphere", "Dupin",
           "live_handles", "version", "status_name", "SurfacePoint", "Grid", "Circle",
           "Sphere", "DupinPoint", "Continuity"]
