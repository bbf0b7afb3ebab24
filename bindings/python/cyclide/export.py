"""Exact rational Bezier / NURBS export, adaptive tessellation and mesh files
(issue 9, SPEC.md §8j)."""

import collections
import os
from ctypes import byref, c_double, c_size_t

from . import _array
from . import _lib as L
from ._lib import lib
from .core import Handle
from .errors import InvalidInputError

# ------------------------------------------------------------------ tessellation

_OPTION_FIELDS = ("chordal_tolerance", "min_segments", "max_segments", "fixed_segments",
                  "initial_rows")


def tessellation_options(chordal_tolerance=None, min_segments=None, max_segments=None,
                         fixed_segments=None, initial_rows=None, reference_u0=None,
                         reference_u1=None):
    """(cyc_tessellation_options with the defaults and these overrides, the
    objects that must stay alive while it is used)."""
    o = L.cyc_tessellation_options()
    lib.cyc_tessellation_options_default(byref(o))
    given = dict(chordal_tolerance=chordal_tolerance, min_segments=min_segments,
                 max_segments=max_segments, fixed_segments=fixed_segments,
                 initial_rows=initial_rows)
    for k in _OPTION_FIELDS:
        if given[k] is not None:
            setattr(o, k, type(getattr(o, k))(given[k]))
    keep = []
    for name, ref in (("reference_u0", reference_u0), ("reference_u1", reference_u1)):
        if ref is not None:
            v = _array.vec3(ref, name)
            keep.append(v)
            setattr(o, name, v)
    return o, keep


class GridMesh:
    """A grid of rows x cols points (point (i, j) at row i * cols + j),
    optional normals, closed in the cols direction; rgba: an sRGB colour and
    alpha in [0, 1] (None: the writer's palette)."""

    def __init__(self, points, rows, cols, normals=None, closed=True, rgba=None):
        self.rows, self.cols, self.closed = int(rows), int(cols), bool(closed)
        self.rgba = None if rgba is None else tuple(float(c) for c in rgba)
        self.points, self.normals = points, normals

    def _c(self):
        """(cyc_grid_mesh, keepalive)."""
        n = self.rows * self.cols
        p = _array.as_doubles(self.points, (n, 3), "points")
        nm = _array.as_doubles(self.normals, (n, 3), "normals") if self.normals is not None \
            else None
        g = L.cyc_grid_mesh()
        g.points, g.normals = p.ptr, (nm.ptr if nm else None)
        g.stride, g.rows, g.cols, g.closed = 3, self.rows, self.cols, int(self.closed)
        if self.rgba is not None:
            g.rgba[:] = list(self.rgba)
        return g, (p, nm)

    def write(self, ctx, path, format="obj", **options):
        return mesh_write(ctx, path, [self], format, **options)


class Mesh(GridMesh):
    """A tessellation: rows circles at parameters us of segments points each
    (points and normals of shape (rows * segments, 3), closed along the
    circles), the plan's phases and flags, and singular (normals set to 0)."""

    def __init__(self, plan, us, points, normals, singular, raw):
        super().__init__(points, plan.rows, plan.segments, normals, True)
        self.segments = plan.segments
        self.us = us
        self.phase0, self.phase1 = plan.phase0, plan.phase1
        self.max_radius = plan.max_radius
        self.depth_limited = plan.depth_limited
        self.singular = singular
        self._raw = raw  # the C buffers (reused by the writer without copies)
        self._raw_views = (points, normals)

    def _c(self):
        if (self.points is not self._raw_views[0] or self.normals is not self._raw_views[1]
                or self.rows * self.cols != self._raw[0].shape[0]):
            return GridMesh._c(self)  # replaced by the caller: convert those
        pts, nrm = self._raw
        g = L.cyc_grid_mesh()
        g.points, g.normals = pts.ptr, nrm.ptr
        g.stride, g.rows, g.cols, g.closed = 3, self.rows, self.cols, 1
        if self.rgba is not None:
            g.rgba[:] = list(self.rgba)
        return g, self._raw


def _work(segments, size_fn):
    nbytes = size_fn(int(segments))
    if nbytes == 0:
        raise InvalidInputError(2, "segments %d out of range" % segments)
    return (c_double * ((nbytes + 7) // 8))(), nbytes  # 8-byte aligned


def _tessellate(ctx, plan_fn, eval_fn, size_fn, head, row_cap, options):
    o, keep = tessellation_options(**options)
    segs = o.fixed_segments if o.fixed_segments > 0 else o.max_segments
    work, nbytes = _work(segs, size_fn)
    us = (c_double * int(row_cap))()
    plan = L.cyc_tessellation_plan()
    ctx.call(plan_fn, *head, byref(o), us, int(row_cap), work, nbytes, byref(plan))
    n = plan.rows * plan.segments
    pts, nrm = _array.OutArray((n, 3)), _array.OutArray((n, 3))
    singular = c_size_t()
    ctx.call(eval_fn, *head, byref(plan), us, L.cyc_buffer3(pts.ptr, n, 3),
             L.cyc_buffer3(nrm.ptr, n, 3), byref(singular))
    del keep
    return Mesh(plan, _array.out_list(us[:plan.rows]), pts.result(), nrm.result(),
                singular.value, (pts, nrm))


def tessellate(surface, row_cap=4096, **options):
    """The adaptive mesh of a Surface (cyc_tessellate_plan + _eval).
    options: chordal_tolerance, min_segments, max_segments, fixed_segments,
    initial_rows, reference_u0, reference_u1."""
    return _tessellate(surface.ctx, "cyc_tessellate_plan", "cyc_tessellate_eval",
                       lib.cyc_tessellation_workspace_size, (surface.ptr,), row_cap, options)


def tessellate_skin(skin, patch=0, row_cap=4096, **options):
    """The adaptive mesh of a sphere-skin patch (rows t = const)."""
    return _tessellate(skin.ctx, "cyc_sphere_skin_tessellate_plan",
                       "cyc_sphere_skin_tessellate_eval",
                       lib.cyc_sphere_skin_tessellation_workspace_size, (skin.ptr, int(patch)),
                       row_cap, options)


# ------------------------------------------------------------------ mesh files

MESH_FORMATS = {"obj": L.CYC_MESH_OBJ, "ply": L.CYC_MESH_PLY, "stl": L.CYC_MESH_STL,
                "glb": L.CYC_MESH_GLB}
MeshStats = collections.namedtuple(
    "MeshStats", "vertices triangles welded_rows collapsed_rows coordinate_sum tolerance")


def mesh_write(ctx, path, grids, format="obj", weld_tolerance=-1.0, name=None):
    """Write GridMesh / Mesh objects as one welded triangle mesh (obj, ply,
    stl or glb; or a CYC_MESH_* number). Returns MeshStats."""
    fmt = MESH_FORMATS[format.lower()] if isinstance(format, str) else int(format)
    grids = list(grids)
    arr = (L.cyc_grid_mesh * max(len(grids), 1))()
    keep = []
    for k, g in enumerate(grids):
        c, alive = g._c()
        arr[k] = c
        keep.append(alive)
    opts = L.cyc_mesh_write_options(float(weld_tolerance),
                                    name.encode() if name is not None else None)
    stats = L.cyc_mesh_stats()
    ctx.call("cyc_mesh_write", os.fsencode(path), int(fmt), arr, len(grids), byref(opts),
             byref(stats))
    return MeshStats(stats.vertices, stats.triangles, stats.welded_rows, stats.collapsed_rows,
                     stats.coordinate_sum, stats.tolerance)


# ------------------------------------------------------------------ exact export

PatchInfo = collections.namedtuple("PatchInfo", "deg_u deg_v u0 u1 v0 v1 reciprocal_v")
Patch = collections.namedtuple("Patch", "info control")
Nurbs = collections.namedtuple("Nurbs", "deg_u deg_v knots_u knots_v control")
SkinExportReport = collections.namedtuple("SkinExportReport",
                                          "error_estimate rmf_error exact t_intervals")


def tau_of_v(v):
    return lib.cyc_export_tau_of_v(float(v))


def v_of_tau(tau):
    return lib.cyc_export_v_of_tau(float(tau))


def _domain(u0, u1, v0, v1, whole_circle):
    return L.cyc_export_domain(float(u0), float(u1), float(v0), float(v1), int(whole_circle))


class BezierExport(Handle):
    """Tensor-product rational Bezier patches of a surface or a sphere skin
    (homogeneous control points (w, w x, w y, w z), i along u); len() is the
    patch count. For skins, .report is the SkinExportReport."""

    _destroy = "cyc_bezier_export_destroy"
    _with_ctx = False
    report = None

    @classmethod
    def from_surface(cls, surface, u0=None, u1=None, v0=0.0, v1=0.0, whole_circle=True):
        """cyc_bezier_export_create over u in [u0, u1] (default the domain)
        and v in [v0, v1] or the whole circle."""
        d0, d1 = surface.domain
        dom = _domain(d0 if u0 is None else u0, d1 if u1 is None else u1, v0, v1, whole_circle)
        p = L.P_export()
        surface.ctx.call("cyc_bezier_export_create", surface.ptr, byref(dom), byref(p))
        return cls(surface.ctx, p)

    @classmethod
    def from_skin(cls, skin, u0=None, u1=None, v0=0.0, v1=0.0, whole_circle=True,
                  tolerance=None, degree=None):
        """cyc_sphere_skin_export_create: u = patch + t in [0, patch_count]
        (default all), v = tan(theta / 2); within `tolerance` of the skin."""
        dom = _domain(0.0 if u0 is None else u0, skin.patch_count if u1 is None else u1, v0,
                      v1, whole_circle)
        o = L.cyc_skin_export_options()
        lib.cyc_skin_export_options_default(byref(o))
        if tolerance is not None:
            o.tolerance = float(tolerance)
        if degree is not None:
            o.degree = int(degree)
        p, rep = L.P_export(), L.cyc_skin_export_report()
        skin.ctx.call("cyc_sphere_skin_export_create", skin.ptr, byref(dom), byref(o), byref(p),
                      byref(rep))
        e = cls(skin.ctx, p)
        e.report = SkinExportReport(rep.error_estimate, rep.rmf_error, bool(rep.exact),
                                    rep.t_intervals)
        e.tolerance = o.tolerance
        return e

    def __len__(self):
        return lib.cyc_bezier_export_count(self.ptr)

    @property
    def count(self):
        return len(self)

    def patch(self, index):
        """Patch(info, control) with control of shape (deg_u + 1, deg_v + 1, 4)."""
        info = L.cyc_bezier_patch_info()
        self._ctx.call("cyc_bezier_export_patch", self.ptr, int(index), byref(info), None, 0)
        out = _array.OutArray((info.deg_u + 1, info.deg_v + 1, 4))
        self._ctx.call("cyc_bezier_export_patch", self.ptr, int(index), byref(info), out.ptr,
                       out.size)
        return Patch(PatchInfo(info.deg_u, info.deg_v, info.u0, info.u1, info.v0, info.v1,
                               bool(info.reciprocal_v)), out.result())

    def patches(self):
        return [self.patch(k) for k in range(len(self))]

    def eval(self, index, s, t):
        """(point, (u, v)) of patch index at local (s, t) in [0, 1]^2."""
        x, uv = (c_double * 3)(), (c_double * 2)()
        self._ctx.call("cyc_bezier_export_eval", self.ptr, int(index), float(s), float(t), x, uv)
        return _array.out_vec(x), tuple(uv)

    def nurbs(self):
        """The patches as one clamped NURBS: Nurbs(deg_u, deg_v, knots_u,
        knots_v, control of shape (cp_u, cp_v, 4))."""
        size = L.cyc_nurbs_size()
        self._ctx.call("cyc_bezier_export_nurbs", self.ptr, byref(size), None, 0, None, 0, None, 0)
        ku, kv = _array.OutArray((size.knots_u,)), _array.OutArray((size.knots_v,))
        cp = _array.OutArray((size.cp_u, size.cp_v, 4))
        self._ctx.call("cyc_bezier_export_nurbs", self.ptr, byref(size), ku.ptr, ku.size, kv.ptr,
                       kv.size, cp.ptr, cp.size)
        return Nurbs(size.deg_u, size.deg_v, ku.result(), kv.result(), cp.result())

    def write_json(self, path):
        """The patches as JSON (schema cyclide-rational-bezier, version 1)."""
        self._ctx.call("cyc_bezier_export_write_json", self.ptr, os.fsencode(path))


__all__ = ["tessellation_options", "GridMesh", "Mesh", "tessellate", "tessellate_skin",
           "mesh_write", "MeshStats", "BezierExport", "Patch", "PatchInfo", "Nurbs",
           "SkinExportReport", "tau_of_v", "v_of_tau", "MESH_FORMATS"]
