"""The Python binding end to end: surfaces, blends, grids, skins and their
export, tessellation and mesh files, Dupin cyclides, errors, lifetimes.

Runs with numpy (outputs are arrays) or without it (CYCLIDE_NO_NUMPY=1 or
numpy missing: tuples and lists); the checks go through support.tolist so
both paths are judged alike, and ArrayTypes checks which path is active.
"""

import gc
import math
import os
import struct
import tempfile
import unittest

import cyclide
from support import (FORCED_FALLBACK, Case, cone, dist, dot, norm, numpy, rows, skin_ends,
                     sub, tolist)

HAVE_NUMPY = cyclide.numpy_enabled()


def lines_prcs(ctx):
    """Example 2 of seed 000 (the README's C example)."""
    l1 = cyclide.Curve.line(ctx, (0, 0, 0), (1, 0, 0))
    l2 = cyclide.Curve.line(ctx, (0, 0, 1), (2, 1, 0))
    return cyclide.Surface.prcs(ctx, l1, l2, -0.5, 0.5)


class ArrayTypes(Case):
    def test_the_active_path(self):
        if FORCED_FALLBACK:
            self.assertFalse(cyclide.numpy_enabled())
        elif numpy is not None:
            self.assertTrue(cyclide.numpy_enabled())
        g = lines_prcs(self.ctx).eval_grid([0.0, 0.1], [0.0, 1.0])
        if cyclide.numpy_enabled():
            self.assertIsInstance(g.points, numpy.ndarray)
            self.assertEqual(g.points.shape, (4, 3))
            self.assertEqual(g.points.dtype, numpy.float64)
        else:
            self.assertIsInstance(g.points, list)
            self.assertEqual(len(g.points), 4)
            self.assertIsInstance(g.points[0], tuple)

    def test_fallback_in_process(self):
        """use_numpy(False) switches to lists/tuples; same numbers."""
        s = lines_prcs(self.ctx)
        us, vs = [-0.5, 0.0, 0.25], [0.0, 1.0, -3.0]
        ref = rows(s.eval_grid(us, vs).points)
        prev = cyclide.use_numpy(False)
        try:
            g = s.eval_grid(us, vs)
            self.assertIsInstance(g.points, list)
            self.assertIsInstance(s.eval(0.25, 1.0).point, tuple)
            self.assertEqual(rows(g.points), ref)
        finally:
            if prev:
                cyclide.use_numpy(True)
        if not cyclide.numpy_available():
            with self.assertRaises(ImportError):
                cyclide.use_numpy(True)


class Surfaces(Case):
    def test_prcs_example(self):
        s = lines_prcs(self.ctx)
        self.assertEqual(s.kind, cyclide.CYC_SURFACE_PRCS)
        self.assertEqual(s.domain, (-0.5, 0.5))
        p = s.eval(0.25, 1.0, derivatives=True)
        self.assertAlmostEqual(float(p.point[0]), (0.25 - 0.75 - 1 - 3) / 12.0, delta=1e-14)
        self.assertAlmostEqual(norm(p.normal), 1.0, delta=1e-12)
        self.assertLess(abs(dot(p.normal, p.du)), 1e-9 * max(1.0, norm(p.du)))
        self.assertLess(abs(dot(p.normal, p.dv)), 1e-9 * max(1.0, norm(p.dv)))
        sph = s.sphere(0.25)  # the point lies on the touching sphere
        self.assertAlmostEqual(dist(p.point, sph.center), sph.radius, delta=1e-12)
        c = s.circle(0.25)
        self.assertAlmostEqual(dist(p.point, c.center), c.radius, delta=1e-12)
        v = s.parameter_of(0.25, p.point)
        self.assertVec(s.point(0.25, v), p.point, 1e-12)
        res, is_canal = s.canal_test()
        self.assertTrue(is_canal, res)
        d = tolist(s.derivatives_u(0.25, 1.0, 2))
        self.assertEqual(len(d), 3)
        self.assertVec(d[0], p.point, 1e-12)
        self.assertVec(d[1], p.du, 1e-12)

    def test_prrs_ringed_and_curves(self):
        ctx = self.ctx
        # PRRS of a cubic, a line and a point; a ringed surface (d, n, c).
        c1 = cyclide.Curve.polynomial(ctx, [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 0.25]])
        self.assertEqual(c1.degree, 3)
        self.assertVec(c1.eval(0.5), (0.5, 0.25, 0.25 * 0.125), 1e-15)
        self.assertEqual(len(tolist(c1.eval(0.5, order=2))), 3)
        l2 = cyclide.Curve.line(ctx, (0, 0, 2), (1, 1, 0))
        pt = cyclide.Curve.point(ctx, (3, -1, 1))
        s = cyclide.Surface.prrs(ctx, c1, l2, pt, 0.0, 1.0)
        self.assertEqual(s.kind, cyclide.CYC_SURFACE_PRRS)
        for u in (0.0, 0.3, 1.0):  # the circle at u passes through p1, p2, p3
            c = s.circle(u)
            for q in (c1.eval(u), l2.eval(u), (3, -1, 1)):
                self.assertAlmostEqual(dist(q, c.center), c.radius, delta=1e-9)
        # f = 1/v as a Mobius map: x(u, 0) = p1(u).
        f = cyclide.Mobius(alpha=[0.0], beta=[1.0], gamma=[1.0], delta=[0.0])
        s2 = cyclide.Surface.prrs(ctx, c1, l2, pt, 0.0, 1.0, f=f)
        self.assertVec(s2.point(0.4, 0.0), c1.eval(0.4), 1e-12)
        d = cyclide.Curve.line(ctx, (0, 0, 0), (0, 0, 1))
        n = cyclide.Curve.point(ctx, (0, 0, 1))
        c = cyclide.Curve.line(ctx, (2, 0, 0), (0, 0, 1))
        r = cyclide.Surface.ringed(ctx, d, n, c, 0.0, 1.0)
        self.assertEqual(r.kind, cyclide.CYC_SURFACE_RINGED)
        for v in (-2.0, 0.0, 0.5, 7.0):  # a cylinder of radius 2 about z
            x = tolist(r.point(0.5, v))
            self.assertAlmostEqual(math.hypot(x[0], x[1]), 2.0, delta=1e-12)
            self.assertAlmostEqual(x[2], 0.5, delta=1e-12)
        b = cyclide.Curve.bezier(ctx, [[0, 0, 0], [1, 1, 0], [2, 0, 0]], weights=[1, 2, 1])
        self.assertEqual(b.degree, 2)
        h = cyclide.Curve.hermite(ctx, [[0, 0, 0], [1, 0, 0]], [[1, 1, 0], [0, 1, 0]])
        self.assertVec(h.eval(1.0), (1, 1, 0), 1e-14)
        le = cyclide.Curve.line_element(ctx, (0, 0, 0), (0, 0, 1))
        q = cyclide.Curve.rational(ctx, [[0, 0, 1, 1], [1, 0, 0, 0], [0, 1, 0, 1]])
        self.assertVec(q.eval(1.0), (0.5, 0.5, 0.5), 1e-15)
        le.close()

    def test_grids_through_numpy_inputs(self):
        s = lines_prcs(self.ctx)
        us, vs = [-0.5, -0.1, 0.2, 0.5], [-2.0, 0.0, 0.5, 1.0, 3.0]
        inputs = [(us, vs), (tuple(us), tuple(vs))]
        if numpy is not None:
            big = numpy.zeros((4, 2))
            big[:, 1] = us  # a strided column: a contiguous copy is made
            inputs += [(numpy.array(us, dtype=numpy.float32), vs),
                       (us, numpy.array([-2, 0, 1, 3, 5], dtype=numpy.int32)),
                       (big[:, 1], numpy.array(vs)),
                       (numpy.array(us), numpy.array([-2, 0, 0.5, 1, 3], dtype=object)),
                       (numpy.array(us, dtype=numpy.float64)[::-1][::-1], vs)]
        for a, b in inputs:
            g = s.eval_grid(a, b, derivatives=True)
            pts, nrm = rows(g.points), rows(g.normals)
            self.assertEqual(len(pts), len(us) * len(vs))
            self.assertEqual(g.singular, 0)
            ua, va = [float(x) for x in tolist(a)], [float(x) for x in tolist(b)]
            for i, u in enumerate(ua):
                for j, v in enumerate(va):
                    p = s.eval(u, v, derivatives=True)
                    k = i * len(vs) + j
                    self.assertEqual(pts[k], tolist(p.point))  # bit for bit
                    self.assertEqual(nrm[k], tolist(p.normal))
                    self.assertEqual(rows(g.du)[k], tolist(p.du))
                    self.assertAlmostEqual(norm(nrm[k]), 1.0, delta=1e-12)
        uv = [[u, v] for u in us for v in vs]
        batch = s.eval_batch(numpy.array(uv) if numpy is not None else uv)
        self.assertEqual(rows(batch.points), rows(s.eval_grid(us, vs).points))
        self.assertEqual(rows(s.eval_batch([0.25, 1.0]).points), [tolist(s.point(0.25, 1.0))])
        with self.assertRaises(ValueError):
            s.eval_batch([[0.1, 0.2, 0.3]])
        empty = s.eval_grid([], vs)
        self.assertEqual(len(rows(empty.points)), 0)


class Blends(Case):
    def setUp(self):
        super().setUp()
        ctx = self.ctx
        self.a = cone(ctx, (0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1))
        self.b = cone(ctx, (4, 0, 4), (0, 1, 0), (0, 0, 1), (-1, 0, 0))
        v = (math.inf, -0.5, 0.7)
        self.s = cyclide.BlendEnd(self.a, 1.0, v)
        self.e = cyclide.BlendEnd(self.b, 1.0, v)

    def check_ends(self, blend, K):
        t0, t1 = blend.domain
        for t, surf in ((t0, self.a), (t1, self.b)):
            vs = [-3.0, -0.5, 0.0, 0.3, 1.0, 2.0]
            g = blend.eval_grid([t], vs)
            for x, n in zip(rows(g.points), rows(g.normals)):
                # on the input surface: its circle at u = 1 holds the point
                v = surf.parameter_of(1.0, x)
                self.assertLessEqual(dist(surf.point(1.0, v), x), 1e-9, (t, x))
                self.assertAlmostEqual(norm(n), 1.0, delta=1e-12)
                # same tangent plane (G^1)
                self.assertGreater(abs(dot(n, surf.normal(1.0, v))), 1 - 1e-9)
        rep = cyclide.continuity_report(self.a, 1.0, 1.0, blend, t0, K, n=32)
        self.assertLessEqual(rep.max_gap, 1e-12 * rep.point_scale)
        self.assertLessEqual(rep.max_normal_angle, 1e-9)
        inner = blend.eval_grid([t0 + (t1 - t0) * k / 8 for k in range(9)],
                                [-2.0, 0.0, 0.5, 4.0])
        for n in rows(inner.normals):
            if any(n):
                self.assertAlmostEqual(norm(n), 1.0, delta=1e-12)

    def test_ringed_blend(self):
        r = cyclide.blend_ringed(self.s, self.e, K=1)
        self.assertEqual(r.kind, cyclide.CYC_SURFACE_PRRS)
        self.check_ends(r, 1)

    def test_canal_blend(self):
        c = cyclide.blend_canal(self.s, self.e, K=2)
        self.assertEqual(c.kind, cyclide.CYC_SURFACE_PRCS)
        self.check_ends(c, 2)

    def test_matched_blend_and_errors(self):
        m = cyclide.blend_ringed_matched(self.s, self.e, K=2)
        rep = cyclide.continuity_report(self.a, 1.0, 1.0, m, 0.0, 2, n=32)
        for l in range(3):
            self.assertLessEqual(rep.point_jump[l], 1e-9 * max(rep.point_scale_l[l],
                                                                rep.point_scale))
        with self.assertRaises(cyclide.InvalidInputError) as cm:
            cyclide.blend_canal(self.s, self.e, K=1)
        self.assertEqual(cm.exception.status, cyclide.CYC_E_INVALID_ARGUMENT)
        with self.assertRaises(cyclide.BadDomainError):
            cyclide.blend_ringed(self.s, self.e, K=1, t0=1.0, t1=0.0)
        mirrored = cyclide.BlendEnd(self.b, 1.0, (math.inf, 0.7, -0.5))
        with self.assertRaises(cyclide.GeometryError) as cm:
            cyclide.blend_ringed_matched(self.s, mirrored, K=1)
        self.assertEqual(cm.exception.status, cyclide.CYC_E_DEGENERATE_CIRCLE_PARAMETER)
        self.assertIn("opposite senses", cm.exception.message)


class Skins(Case):
    def test_skin_eval_and_info(self):
        s, e = skin_ends(self.ctx)
        skin = cyclide.SphereSkin.create(self.ctx, s, e)
        self.assertEqual(skin.patch_count, 1)
        c0, r0 = s.sphere()
        for theta in (0.0, 1.0, 3.0):
            p = skin.eval(theta, 0.0)  # at t = 0 on the start sphere, normal radial
            self.assertAlmostEqual(dist(p.point, c0), r0, delta=1e-12)
            self.assertAlmostEqual(abs(dot(p.normal, sub(p.point, c0))) / r0, 1.0, delta=1e-9)
        info = skin.info()
        self.assertEqual(info.pairing, cyclide.CYC_SKIN_RMF)
        self.assertLess(max(info.kappa) * min(s.radius, e.radius), 1.0)
        self.assertLess(abs(skin.twist(0.5)), 1e-6)
        lam, a = skin.lam(0.5, 0.5)
        self.assertGreater(lam, 0)
        g = skin.eval_grid([0.0, 2.0, 4.0], [0.0, 0.5, 1.0])
        pts = rows(g.points)
        self.assertEqual(pts[1 * 3 + 2], tolist(skin.eval(4.0, 0.5).point))  # j * ntheta + i

    def test_skin_export_within_tolerance(self):
        s, e = skin_ends(self.ctx)
        skin = cyclide.SphereSkin.create(self.ctx, s, e)
        tol = 1e-6
        ex = skin.export(tolerance=tol)
        self.assertLessEqual(ex.report.error_estimate, tol)
        self.assertFalse(ex.report.exact)
        self.assertGreater(len(ex), 0)
        worst = 0.0
        for k in range(len(ex)):
            patch = ex.patch(k)
            cp = tolist(patch.control)
            self.assertEqual(len(cp), patch.info.deg_u + 1)
            self.assertEqual(len(cp[0]), patch.info.deg_v + 1)
            self.assertTrue(all(w[0] > 0 for row in cp for w in row))  # positive weights
            for si in range(5):
                for ti in range(5):
                    x, (u, v) = ex.eval(k, si / 4, ti / 4)
                    theta = 2 * math.atan(v)
                    worst = max(worst, dist(x, skin.eval(theta, min(max(u, 0.0), 1.0)).point))
        self.assertLessEqual(worst, tol)
        nb = ex.nurbs()
        self.assertEqual(len(tolist(nb.knots_u)), len(tolist(nb.control)) + nb.deg_u + 1)
        self.assertEqual(len(tolist(nb.knots_v)), len(tolist(nb.control)[0]) + nb.deg_v + 1)
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "skin.json")
            ex.write_json(path)
            with open(path, encoding="utf-8") as f:
                self.assertIn("cyclide-rational-bezier", f.read(200))

    def test_chain(self):
        ctx = self.ctx
        # ends[0..2] of tests/sphere_skin_capi_test.cpp's chain

        def end(m, r, axis, back):
            n = norm(axis)
            ax = [a / n for a in axis]
            return cyclide.SkinEnd.from_sphere(ctx, m, r, [c - back * a for c, a in zip(m, ax)],
                                               [3 * a for a in ax])

        s = end((0, 0, 0), 1.0, (1, 0, 0), -0.3)
        e = end((4, 1, 0), 0.8, (1, 0.5, 0.3), 0.1)
        third = end((6, 4, -1), 1.1, (0.2, 1, -0.4), 0.3)
        chain = cyclide.SphereSkin.chain(ctx, [s, e, third])
        self.assertEqual(chain.patch_count, 2)
        # G^1 at the shared circle: same point and normal direction
        for theta in (0.0, 2.0):
            p0, p1 = chain.eval(theta, 1.0, patch=0), chain.eval(theta, 0.0, patch=1)
            self.assertLessEqual(dist(p0.point, p1.point), 1e-9)
            self.assertGreater(abs(dot(p0.normal, p1.normal)), 1 - 1e-9)
        ex = chain.export(tolerance=1e-6)
        self.assertLessEqual(ex.report.error_estimate, 1e-6)
        us = sorted({round(p.info.u1, 12) for p in ex.patches()})
        self.assertAlmostEqual(us[-1], 2.0)
        with self.assertRaises(cyclide.InvalidInputError) as cm:
            cyclide.SphereSkin.chain(ctx, [s])
        self.assertEqual(cm.exception.status, cyclide.CYC_E_INVALID_ARGUMENT)
        with self.assertRaises(cyclide.GeometryError) as cm:  # patch 1: e to e
            cyclide.SphereSkin.chain(ctx, [s, e, e])
        self.assertEqual(cm.exception.status, cyclide.CYC_E_NESTED_SPHERES)
        self.assertEqual(cm.exception.bad_patch, 1)


class Meshes(Case):
    def test_tessellation_and_mesh_files(self):
        s = lines_prcs(self.ctx)
        tol = 1e-3
        m = s.tessellate(chordal_tolerance=tol)
        pts, nrm = rows(m.points), rows(m.normals)
        self.assertEqual(len(pts), m.rows * m.segments)
        self.assertEqual(tolist(m.us)[0], -0.5)
        self.assertEqual(tolist(m.us)[-1], 0.5)
        self.assertEqual(m.singular, 0)
        for x, n in zip(pts[::37], nrm[::37]):
            self.assertAlmostEqual(norm(n), 1.0, delta=1e-12)
        # row i is the circle us[i]: every point on it
        for i in (0, m.rows // 2, m.rows - 1):
            c = s.circle(tolist(m.us)[i])
            for x in pts[i * m.segments:(i + 1) * m.segments:7]:
                self.assertAlmostEqual(dist(x, c.center), c.radius, delta=1e-12)
        # finer tolerance, more points
        self.assertGreater(s.tessellate(chordal_tolerance=tol / 16).points.__len__(), len(pts))
        fixed = s.tessellate(fixed_segments=24, chordal_tolerance=1e-2)
        self.assertEqual(fixed.segments, 24)
        with tempfile.TemporaryDirectory() as d:
            stats = {}
            for fmt in ("obj", "ply", "stl", "glb"):
                path = os.path.join(d, "prcs." + fmt)
                stats[fmt] = cyclide.mesh_write(self.ctx, path, [m], fmt, name="prcs")
                self.assertTrue(os.path.getsize(path) > 0)
                self.assertFalse(os.path.exists(path + ".part"))
            st = stats["obj"]
            self.assertEqual(st.triangles, 2 * (m.rows - 1) * m.segments)
            with open(os.path.join(d, "prcs.obj"), encoding="ascii") as f:
                lines = f.read().splitlines()
            self.assertEqual(sum(1 for l in lines if l.startswith("v ")), st.vertices)
            self.assertEqual(sum(1 for l in lines if l.startswith("f ")), st.triangles)
            with open(os.path.join(d, "prcs.stl"), "rb") as f:
                f.seek(80)
                self.assertEqual(struct.unpack("<I", f.read(4))[0], st.triangles)
            with open(os.path.join(d, "prcs.glb"), "rb") as f:
                self.assertEqual(f.read(4), b"glTF")
            # a user grid (any arrays) written with the mesh: rows reuse nothing
            grid = cyclide.GridMesh(m.points, m.rows, m.segments, closed=True,
                                    rgba=(1, 0.5, 0, 1))
            two = cyclide.mesh_write(self.ctx, os.path.join(d, "two.ply"), [m, grid], "ply")
            # the copy's end rows are welded onto the mesh's, its inner rows not
            self.assertEqual(two.vertices, 2 * st.vertices - 2 * m.segments)
            self.assertEqual(two.welded_rows, 2)
            # a mesh whose points were replaced writes the new points
            moved = s.tessellate(chordal_tolerance=tol)
            moved.points = [[x + 10.0, y, z] for x, y, z in pts]
            st2 = cyclide.mesh_write(self.ctx, os.path.join(d, "moved.obj"), [moved])
            self.assertAlmostEqual(st2.coordinate_sum, st.coordinate_sum + 10.0 * st.vertices,
                                   delta=1e-6 * st.vertices)
            with self.assertRaises(cyclide.ResourceError) as cm:
                cyclide.mesh_write(self.ctx, os.path.join(d, "no", "such", "dir.obj"), [m])
            self.assertEqual(cm.exception.status, cyclide.CYC_E_IO)
            self.assertIsInstance(cm.exception, OSError)

    def test_skin_tessellation_written(self):
        s, e = skin_ends(self.ctx)
        skin = cyclide.SphereSkin.create(self.ctx, s, e)
        m = skin.tessellate(chordal_tolerance=1e-3)
        self.assertEqual(len(rows(m.points)), m.rows * m.segments)
        self.assertEqual(tolist(m.us)[0], 0.0)
        self.assertEqual(tolist(m.us)[-1], 1.0)
        with tempfile.TemporaryDirectory() as d:
            st = cyclide.mesh_write(self.ctx, os.path.join(d, "skin.obj"), [m])
            self.assertGreater(st.triangles, 0)

    def test_surface_export(self):
        s = lines_prcs(self.ctx)
        ex = s.export()
        self.assertGreater(len(ex), 0)
        for k in range(len(ex)):
            info = ex.patch(k).info
            self.assertEqual(info.deg_v, 2)
            for st in ((0, 0), (0.3, 0.7), (1, 1)):
                x, (u, v) = ex.eval(k, *st)
                if math.isfinite(v):
                    self.assertVec(x, s.point(u, v), 1e-9)
        part = s.export(u0=-0.25, u1=0.25, v0=-1, v1=1, whole_circle=False)
        self.assertGreater(len(part), 0)
        self.assertEqual(cyclide.v_of_tau(cyclide.tau_of_v(0.5)), 0.5)


class DupinCyclides(Case):
    def test_torus(self):
        spheres = [((3, 0, 0), 1), ((0, 3, 0), 1), ((-3, 0, 0), 1)]
        self.assertEqual(cyclide.Dupin.classify_spheres(self.ctx, spheres), (2, 0, 1))
        D = cyclide.Dupin.from_spheres(self.ctx, spheres)
        self.assertEqual(D.type, cyclide.CYC_DUPIN_QUARTIC)

        def on_torus(x, r=1.0):
            return (math.hypot(x[0], x[1]) - 3) ** 2 + x[2] ** 2 - r * r

        p = D.eval(0.3, 0.7)
        self.assertAlmostEqual(on_torus(tolist(p.point)), 0, delta=1e-12)
        self.assertAlmostEqual(norm(p.normal), 1.0, delta=1e-12)
        pts, nrm = D.eval_grid([0.0, 0.5, 2.0], [-1.0, 0.25])
        for x in rows(pts):
            self.assertAlmostEqual(on_torus(x), 0, delta=1e-12)
        off = D.offset(0.5)
        self.assertAlmostEqual(on_torus(tolist(off.eval(0.3, 0.7).point), 1.5), 0, delta=1e-12)
        self.assertEqual(D.swap_families().type, cyclide.CYC_DUPIN_QUARTIC)
        a0 = D.sphere(0, 0.0)
        self.assertEqual(a0.kind, cyclide.CYC_LIE_SPHERE)
        self.assertAlmostEqual(abs(a0.rho), 1.0, delta=1e-12)
        surf = D.surface(-1.0, 1.0)
        self.assertEqual(surf.kind, cyclide.CYC_SURFACE_DUPIN)
        for x in rows(surf.eval_grid([-1.0, 0.0, 1.0], [0.0, 3.0]).points):
            self.assertAlmostEqual(on_torus(x), 0, delta=1e-12)
        m = surf.tessellate(chordal_tolerance=1e-2)
        self.assertGreater(m.rows, 2)
        with self.assertRaises(cyclide.GeometryError) as cm:
            cyclide.Dupin.from_spheres(self.ctx, [((0, 0, 0), 1), ((0, 0, 0), 2),
                                                  ((0, 0, 0), 3)])
        self.assertTrue(cm.exception.message)


class Errors(Case):
    def test_nan_input(self):
        s = lines_prcs(self.ctx)
        with self.assertRaises(cyclide.NotFiniteError) as cm:
            s.eval(float("nan"), 0.0)
        err = cm.exception
        self.assertEqual(err.status, cyclide.CYC_E_NOT_FINITE)
        self.assertEqual(err.name, "CYC_E_NOT_FINITE")
        self.assertEqual(err.function, "cyc_surface_eval")
        self.assertTrue(err.message)
        self.assertIn(err.message, str(err))
        self.assertIsInstance(err, ValueError)
        self.assertEqual(self.ctx.last_status, cyclide.CYC_E_NOT_FINITE)
        self.assertEqual(self.ctx.last_error, err.message)
        with self.assertRaises(cyclide.NotFiniteError):
            cyclide.Curve.line(self.ctx, (0, float("nan"), 0), (1, 0, 0))
        with self.assertRaises(cyclide.NotFiniteError):
            s.eval_grid([0.0, float("inf")], [0.0])
        if numpy is not None:
            with self.assertRaises(cyclide.NotFiniteError):
                s.eval_grid(numpy.array([0.0, numpy.nan]), [0.0])
        s.eval(0.1, 0.2)  # a success clears the last error
        self.assertEqual(self.ctx.last_status, 0)
        self.assertEqual(self.ctx.last_error, "")

    def test_bad_domain(self):
        l1 = cyclide.Curve.line(self.ctx, (0, 0, 0), (1, 0, 0))
        l2 = cyclide.Curve.line(self.ctx, (0, 0, 1), (2, 1, 0))
        with self.assertRaises(cyclide.BadDomainError) as cm:
            cyclide.Surface.prcs(self.ctx, l1, l2, 0.5, -0.5)
        self.assertEqual(cm.exception.status, cyclide.CYC_E_BAD_DOMAIN)
        self.assertTrue(cm.exception.message)
        s, e = skin_ends(self.ctx)
        skin = cyclide.SphereSkin.create(self.ctx, s, e)
        with self.assertRaises(cyclide.BadDomainError):
            skin.eval(0.0, 1.5)

    def test_families_and_handler(self):
        seen = []
        ctx = cyclide.Context(error_handler=lambda st, msg: seen.append((st, msg)))
        try:
            l1 = cyclide.Curve.line(ctx, (0, 0, 0), (1, 0, 0))
            with self.assertRaises(cyclide.GeometryError) as cm:
                cyclide.Surface.prcs(ctx, l1, l1, 0, 1)  # the same line twice
            self.assertGreaterEqual(cm.exception.status, 100)
            self.assertEqual(seen[-1], (cm.exception.status, cm.exception.message))
            ctx.set_error_handler(None)
            n = len(seen)
            with self.assertRaises(cyclide.Error):
                cyclide.Surface.prcs(ctx, l1, l1, 0, 1)
            self.assertEqual(len(seen), n)
        finally:
            ctx.close()
        for status, cls in ((1, cyclide.InvalidInputError), (104, cyclide.GeometryError),
                            (200, cyclide.NumericalError), (300, cyclide.BufferTooSmallError),
                            (301, cyclide.OutOfMemoryError), (400, cyclide.UnsupportedError),
                            (401, cyclide.InternalError)):
            err = cyclide.errors.make_error(status, "m")
            self.assertIsInstance(err, cls)
            self.assertIsInstance(err, cyclide.Error)
            self.assertEqual(err.status, status)


class Lifetimes(unittest.TestCase):
    def test_close_twice_and_use_after_close(self):
        before = cyclide.live_handles()
        ctx = cyclide.Context()
        s = lines_prcs(ctx)
        s.close()
        s.close()
        self.assertTrue(s.closed)
        with self.assertRaises(cyclide.ClosedError):
            s.eval(0, 0)
        s2 = lines_prcs(ctx)
        ex = s2.export()
        ctx.close()
        ctx.close()  # twice: nothing
        self.assertTrue(s2.closed and ex.closed)  # the context closed its handles
        with self.assertRaises(cyclide.ClosedError):
            ctx.last_status
        with self.assertRaises(cyclide.ClosedError):
            cyclide.Curve.line(ctx, (0, 0, 0), (1, 0, 0))
        s2.close()
        ex.close()
        self.assertEqual(cyclide.live_handles(), before)

    def test_with_blocks(self):
        before = cyclide.live_handles()
        with cyclide.Context() as ctx:
            with lines_prcs(ctx) as s:
                self.assertFalse(s.closed)
                with s.export() as ex:
                    self.assertGreater(len(ex), 0)
                self.assertTrue(ex.closed)
            self.assertTrue(s.closed)
            self.assertEqual(cyclide.live_handles().get("Curve", 0),
                             before.get("Curve", 0))  # lines_prcs' curves: collected
        self.assertTrue(ctx.closed)
        self.assertEqual(cyclide.live_handles(), before)

    def test_no_leaks_by_garbage_collection(self):
        before = cyclide.live_handles()
        for _ in range(20):
            ctx = cyclide.Context()
            s = lines_prcs(ctx)
            s.tessellate(chordal_tolerance=1e-2)
            a, b = skin_ends(ctx)
            cyclide.SphereSkin.create(ctx, a, b).export(tolerance=1e-4)
            del ctx, s, a, b
        gc.collect()
        self.assertEqual(cyclide.live_handles(), before)

    def test_handles_outlive_the_context_object(self):
        before = cyclide.live_handles()
        s = lines_prcs(cyclide.Context())  # the surface keeps its context alive
        self.assertEqual(cyclide.live_handles()["Context"], before.get("Context", 0) + 1)
        self.assertAlmostEqual(float(s.point(0.25, 1.0)[0]), -0.375, delta=1e-14)
        del s
        gc.collect()
        self.assertEqual(cyclide.live_handles(), before)


if __name__ == "__main__":
    unittest.main()
