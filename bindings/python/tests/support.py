"""Helpers for the binding's tests: plain-Python vector math that accepts
numpy arrays or tuples, and the shapes of the tests."""

import math
import os
import unittest

import cyclide

try:
    import numpy
except ImportError:
    numpy = None

FORCED_FALLBACK = os.environ.get("CYCLIDE_NO_NUMPY", "") not in ("", "0")


def tolist(x):
    """numpy arrays and nested tuples as nested lists."""
    if hasattr(x, "tolist"):
        return x.tolist()
    if isinstance(x, (list, tuple)):
        return [tolist(i) for i in x]
    return x


def sub(a, b):
    return [float(x) - float(y) for x, y in zip(a, b)]


def dot(a, b):
    return sum(float(x) * float(y) for x, y in zip(a, b))


def norm(a):
    return math.sqrt(dot(a, a))


def dist(a, b):
    return norm(sub(a, b))


def rows(points):
    """A (n, 3) result as a list of 3-lists."""
    return [list(map(float, r)) for r in tolist(points)]


def cone(ctx, apex, e1, e2, e3):
    """The cone of tests/capi_test.c's blend_cone: PRRS of three lines
    through apex along cos t e1 + sin t e2 + e3, on u in [0.5, 1]."""
    lines = []
    for k in range(3):
        t = 2.0 * math.pi * k / 3 + 0.3
        d = [math.cos(t) * a + math.sin(t) * b + c for a, b, c in zip(e1, e2, e3)]
        lines.append(cyclide.Curve.line(ctx, apex, d))
    s = cyclide.Surface.prrs(ctx, lines[0], lines[1], lines[2], 0.5, 1.0)
    for line in lines:
        line.close()
    return s


def skin_ends(ctx):
    """The two ends of tests/sphere_skin_capi_test.cpp (skewed cone axes)."""
    s = cyclide.SkinEnd.from_sphere(ctx, (0, 0, 0), 1.0, (0.3, 0, 0), (3, 0, 0))
    ax = [1.0, 0.6, 0.8]
    n = norm(ax)
    ax = [a / n for a in ax]
    P = [4 - 0.4 * ax[0], 1 - 0.4 * ax[1], 0.5 - 0.4 * ax[2]]
    e = cyclide.SkinEnd.from_sphere(ctx, (4, 1, 0.5), 1.2, P, [3 * a for a in ax])
    return s, e


class Case(unittest.TestCase):
    """Each test with a fresh context, and no C object left behind."""

    def setUp(self):
        self.before = cyclide.live_handles()
        self.ctx = cyclide.Context()

    def tearDown(self):
        self.ctx.close()
        self.assertEqual(cyclide.live_handles(), self.before)

    def assertVec(self, a, b, tol, msg=None):
        self.assertLessEqual(dist(a, b), tol, msg or "%s vs %s" % (tolist(a), tolist(b)))
