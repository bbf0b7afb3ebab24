"""Sphere skins by rotation-minimizing surfaces (seed 002) and chains."""

import collections
from ctypes import byref, c_double, c_int, c_size_t

from . import _array
from . import _lib as L
from .core import Grid, Handle, SurfacePoint
from ._lib import lib


class SkinEnd:
    """One end of a skin: the circle (center, radius) where the skin touches
    a sphere, the tangent (the cone's axis and the spine's end tangent) and
    inv_c (1/c of the cone's apex; 0: a great circle). Build it with
    from_sphere or from_apex, or give the fields directly."""

    def __init__(self, center, radius, tangent, inv_c):
        self.center = [float(x) for x in center]
        self.radius = float(radius)
        self.tangent = [float(x) for x in tangent]
        self.inv_c = float(inv_c)

    @classmethod
    def _from_c(cls, e):
        return cls(list(e.center), e.radius, list(e.tangent), e.inv_c)

    def to_c(self, e=None):
        e = e if e is not None else L.cyc_skin_end()
        e.center[:] = self.center
        e.radius = self.radius
        e.tangent[:] = self.tangent
        e.inv_c = self.inv_c
        return e

    @classmethod
    def from_sphere(cls, ctx, sphere_center, sphere_radius, center, tangent):
        """The end on a sphere at the circle with this center (inside the
        sphere, on its axis along tangent)."""
        e = L.cyc_skin_end()
        ctx.call("cyc_skin_end_from_sphere", _array.vec3(sphere_center), float(sphere_radius),
                 _array.vec3(center), _array.vec3(tangent), byref(e))
        return cls._from_c(e)

    @classmethod
    def from_apex(cls, ctx, center, radius, tangent, apex):
        e = L.cyc_skin_end()
        ctx.call("cyc_skin_end_from_apex", _array.vec3(center), float(radius),
                 _array.vec3(tangent), _array.vec3(apex), byref(e))
        return cls._from_c(e)

    def sphere(self):
        """(center, radius) of the end's sphere."""
        c, r = (c_double * 3)(), c_double()
        lib.cyc_skin_end_sphere(byref(self.to_c()), c, byref(r))
        return _array.out_vec(c), r.value

    def __repr__(self):
        return "SkinEnd(center=%s, radius=%g, tangent=%s, inv_c=%g)" % (
            self.center, self.radius, self.tangent, self.inv_c)


def skin_options(pairing=None, method=None, tolerance=None, reference=None, e=None):
    """A cyc_skin_options with the library's defaults and these overrides."""
    o = L.cyc_skin_options()
    lib.cyc_skin_options_init(byref(o))
    if pairing is not None:
        o.pairing = int(pairing)
    if method is not None:
        o.method = int(method)
    if tolerance is not None:
        o.tolerance = float(tolerance)
    if reference is not None:
        o.reference[:] = [float(x) for x in reference]
    if e is not None:
        o.e[:] = [float(x) for x in e]
    return o


SkinInfo = collections.namedtuple(
    "SkinInfo", "kappa delta rmf_substeps rmf_error_estimate spine pairing method")


class SphereSkin(Handle):
    """A skin of two spheres (one patch) or a chain of spheres (patches
    0 .. patch_count - 1, each on theta real, t in [0, 1])."""

    _destroy = "cyc_sphere_skin_destroy"

    @classmethod
    def create(cls, ctx, start, end, **options):
        """The skin from SkinEnd start to end; options as skin_options()."""
        o = skin_options(**options)
        p = L.P_skin()
        ctx.call("cyc_sphere_skin_create", byref(start.to_c()), byref(end.to_c()), byref(o),
                 byref(p))
        return cls(ctx, p)

    @classmethod
    def chain(cls, ctx, ends, **options):
        """The chain of patches ends[k] -> ends[k + 1] (joined G^1). On a
        patch failure the error has .bad_patch."""
        ends = list(ends)
        arr = (L.cyc_skin_end * max(len(ends), 1))()
        for k, e in enumerate(ends):
            e.to_c(arr[k])
        o = skin_options(**options)
        p, bad = L.P_skin(), c_int(-1)
        st = lib.cyc_sphere_skin_chain_create(ctx.ptr, arr, len(ends), byref(o), byref(p),
                                              byref(bad))
        try:
            ctx.check(st, "cyc_sphere_skin_chain_create")
        except Exception as exc:
            exc.bad_patch = bad.value if bad.value >= 0 else None
            raise
        return cls(ctx, p)

    @property
    def patch_count(self):
        n = c_int()
        self._call("cyc_sphere_skin_patch_count", byref(n))
        return n.value

    def eval(self, theta, t, patch=0, derivatives=False, normal=True):
        """SurfacePoint(point, d/dtheta, d/dt, normal) of patch at (theta, t)."""
        x = (c_double * 3)()
        dth = (c_double * 3)() if derivatives else None
        dt = (c_double * 3)() if derivatives else None
        n = (c_double * 3)() if normal else None
        self._call("cyc_sphere_skin_eval", int(patch), float(theta), float(t), x, dth, dt, n)
        o = _array.out_vec
        return SurfacePoint(o(x), o(dth) if dth else None, o(dt) if dt else None,
                            o(n) if n else None)

    def eval_grid(self, thetas, ts, patch=0, normals=True):
        """Grid(points, normals, None, None, singular): point (i, j) =
        s(thetas[i], ts[j]) at row j * len(thetas) + i (the C order)."""
        a = _array.as_doubles(thetas, (-1,), "thetas")
        b = _array.as_doubles(ts, (-1,), "ts")
        pts = _array.OutArray((a.size * b.size, 3))
        nrm = _array.OutArray((a.size * b.size, 3)) if normals else None
        singular = c_size_t()
        self._call("cyc_sphere_skin_eval_grid", int(patch), a.ptr, a.size, b.ptr, b.size,
                   pts.ptr, nrm.ptr if nrm else None, byref(singular))
        return Grid(pts.result(), nrm.result() if nrm else None, None, None, singular.value)

    def info(self, patch=0):
        i = L.cyc_sphere_skin_info()
        self._call("cyc_sphere_skin_info_get", int(patch), byref(i))
        return SkinInfo(tuple(i.kappa), i.delta, i.rmf_substeps, i.rmf_error_estimate,
                        [tuple(r) for r in i.spine], i.pairing, i.method)

    def twist(self, theta=0.0, patch=0):
        tw = c_double()
        self._call("cyc_sphere_skin_twist", int(patch), float(theta), byref(tw))
        return tw.value

    def lam(self, theta, t, patch=0):
        """(lambda(t; theta), (a_i(theta), a_f(theta)))."""
        lm, a = c_double(), (c_double * 2)()
        self._call("cyc_sphere_skin_lambda", int(patch), float(theta), float(t), byref(lm), a)
        return lm.value, tuple(a)

    def tessellate(self, patch=0, **options):
        from .export import tessellate_skin
        return tessellate_skin(self, patch, **options)

    def export(self, u0=None, u1=None, v0=0.0, v1=0.0, whole_circle=True, tolerance=None,
               degree=None):
        from .export import BezierExport
        return BezierExport.from_skin(self, u0, u1, v0, v1, whole_circle, tolerance, degree)
