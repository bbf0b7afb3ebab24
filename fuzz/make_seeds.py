#!/usr/bin/env python3
"""Write the seed corpora fuzz/corpus/fuzz_create/, fuzz_eval/, fuzz_darboux/,
fuzz_lines/, fuzz_blend/, fuzz_ringed/, fuzz_implicit/, fuzz_skin/ and fuzz_lie/.

The harnesses read their input through FuzzedDataProvider integral reads
only (fuzz_common.hpp): ConsumeIntegralInRange(lo, hi) takes
ceil(bits(hi - lo) / 8) bytes from the END of the input, most significant
byte first, and returns lo + value % (hi - lo + 1); an exhausted input reads
as lo. So a seed is written as the list of consumed bytes, reversed. The
encoders below mirror, call by call, what fuzz_create.cpp and fuzz_eval.cpp
consume; keep them in sync with the harnesses (check a seed with
CYCLIDE_FUZZ_VERBOSE=1 build/.../fuzz/fuzz_eval fuzz/corpus/fuzz_eval/<seed>).

Run from anywhere: python3 fuzz/make_seeds.py  (idempotent: rewrites the
seed-* files, leaves other corpus files alone).
"""
import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
NAN = float("nan")
INF = float("inf")


class Encoder:
    def __init__(self):
        self.consumed = []

    # -- FuzzedDataProvider primitives
    def range(self, lo, hi, v):
        assert lo <= v <= hi, (lo, hi, v)
        r, n = hi - lo, 0
        while n < 8 and (r >> (8 * n)) > 0:
            n += 1
        x = v - lo
        self.consumed.extend(x.to_bytes(n, "big") if n else b"")

    def flag(self, b):
        self.range(0, 1, 1 if b else 0)

    def rarely(self, b):  # range(0, 15) == 0
        self.range(0, 15, 0 if b else 1)

    def u64(self, v):
        self.range(0, 2**64 - 1, v)

    # -- doubles (fuzz_common.hpp Input::wild / moderate)
    def wild(self, v):
        """Any double as raw bits (mode 0)."""
        self.range(0, 5, 0)
        self.u64(struct.unpack("<Q", struct.pack("<d", v))[0])

    def moderate(self, v):
        if v == int(v) and -10 <= v <= 10:
            self.range(0, 2, 0)
            self.range(-10, 10, int(v))
        elif v * 256 == int(v * 256) and abs(v) <= 10:
            self.range(0, 2, 1)
            self.range(-2560, 2560, int(v * 256))
        else:
            k = round(v * (1 << 20) / 10.0)
            assert abs(k) <= (1 << 20)
            self.range(0, 2, 2)
            self.range(-(1 << 20), 1 << 20, k)

    def fill(self, values, style):
        """Input::fill: style 0 wild, 1 moderate, 2 mixed (moderate chosen
        when the value allows it)."""
        for v in values:
            if style == 0:
                self.wild(v)
            elif style == 1:
                self.moderate(v)
            else:
                ok = not math.isnan(v) and not math.isinf(v) and abs(v) <= 10 and \
                    (v * (1 << 20) / 10.0) == round(v * (1 << 20) / 10.0)
                self.flag(not ok)
                (self.moderate if ok else self.wild)(v)

    def data(self):
        return bytes(reversed(self.consumed))


# ---------------------------------------------------------------- fuzz_create

class CreateEncoder(Encoder):
    """Mirrors fuzz_create.cpp. Track the pool sizes the harness will see
    (every creation in a seed is meant to succeed; check with the verbose
    log)."""

    BAD_DEGREES = [-1, -2, 16, 17, "max+1", 100, -2**31, 2**31 - 1]

    def __init__(self, alloc_mode=1, fail_at=0, fail_after=False, handler=True):
        super().__init__()
        self.ops = []
        self.curves = 0
        self.range(0, 2, alloc_mode)
        if alloc_mode == 2:
            self.range(0, 15, fail_at)
            self.flag(fail_after)
        self.flag(handler)
        self.nops_at = len(self.consumed)

    def finish(self, context_first=False):
        # nops is consumed right after the handler flag: splice it in.
        body = self.consumed[self.nops_at:]
        self.consumed = self.consumed[:self.nops_at]
        assert 1 <= len(self.ops) <= 16
        self.range(1, 16, len(self.ops))
        self.consumed.extend(body)
        self.flag(context_first)
        return self.data()

    def op(self, code):
        self.ops.append(code)
        self.range(0, 12, code)

    def degree(self, d, maxd):
        if isinstance(d, int) and 0 <= d <= maxd:
            self.range(0, 3, 0)
            self.range(0, maxd, d)
        else:
            self.range(0, 3, 3)
            self.range(0, 7, self.BAD_DEGREES.index(d))

    def stride(self, s, minimum):
        if s == minimum:
            self.range(0, 3, 0)
        elif minimum < s <= minimum + 3:
            self.range(0, 3, 1)
            self.range(minimum, minimum + 3, s)
        elif s < minimum:
            self.range(0, 3, 2)
            self.range(0, minimum - 1, s)
        else:
            self.range(0, 3, 3)
            self.range(minimum, 64, s)

    def polynomial(self, rows, rational=False, stride=None, degree=None, style=1,
                   null_coeffs=False, null_out=False, ok=True):
        """rows: list of (x, y, z) or (x, y, z, w); degree defaults to
        len(rows) - 1 (pass a bad one to test rejection)."""
        width = 4 if rational else 3
        stride = stride if stride is not None else width
        self.op(1 if rational else 0)
        self.degree(len(rows) - 1 if degree is None else degree, 15)
        self.stride(stride, width)
        self.rarely(null_coeffs)
        self.rarely(null_out)
        self.range(0, 2, style)
        for k, row in enumerate(rows):
            self.fill(row[:width], style)
            if rational and k == 0:
                self.flag(False)  # keep w0 as given
        self.curves += ok

    def bezier(self, ctrl, weights, u0, u1, stride=3, style=1, ok=True):
        self.op(2)
        self.degree(len(ctrl) - 1, 15)
        self.stride(stride, 3)
        self.rarely(False)
        self.rarely(False)
        self.flag(weights is not None)
        self.range(0, 2, style)
        for row in ctrl:
            self.fill(row, style)
        if weights is not None:
            self.fill(weights, style)
        self.fill([u0, u1], style)
        self.curves += ok

    def simple(self, kind, p, d=None, style=1, nulls=(False, False, False), ok=True):
        code = {"line": 3, "point": 4, "line_element": 5}[kind]
        self.op(code)
        for b in nulls:
            self.rarely(b)
        self.range(0, 2, style)
        self.fill(p, style)
        if kind != "point":
            self.fill(d, style)
        self.curves += ok

    def hermite(self, order, start, end, u0, u1, style=1, ok=True):
        """start, end: flat lists of 3 * (order + 1) doubles."""
        self.op(6)
        self.degree(order, 7)
        for _ in range(3):
            self.rarely(False)
        self.range(0, 2, style)
        self.fill(start, style)
        self.fill(end, style)
        self.fill([u0, u1], style)
        self.curves += ok

    def pick(self, index):
        """pick_curve: index into the pool, or None for NULL."""
        if self.curves == 0:
            return
        self.rarely(index is None)
        if index is not None:
            self.range(0, self.curves - 1, index)

    def mobius(self, f):
        """f: None, or (degree, alpha, beta, gamma, delta, style)."""
        if f is None:
            self.range(0, 2, 1)
            return
        degree, arrays, style = f[0], f[1:5], f[5]
        self.range(0, 2, 0)
        if isinstance(degree, int) and 0 <= degree <= 2:
            self.range(0, 3, 1)
            self.range(0, 2, degree)
        else:
            self.range(0, 3, 0)
            self.degree(degree, 15)
        self.range(0, 2, style)
        rows = min(max(degree if isinstance(degree, int) else 16, 0), 15) + 1
        for a in arrays:
            assert len(a) == rows
            self.fill(a, style)

    def surface(self, picks, f, u0, u1, style=1, null_out=False, ok=True,
                sample=0, vs=(0.5, 2.0)):
        self.op(8 if len(picks) == 3 else 7)
        for i in picks:
            self.pick(i)
        self.mobius(f)
        self.range(0, 2, style)
        self.fill([u0, u1], style)
        self.rarely(null_out)
        if ok:  # check_new_surface
            self.flag(sample == 0)
            if sample != 0:
                self.range(0, 256, sample)
            self.wild(vs[0])
            self.moderate(vs[1])

    def curve_eval(self, index, u, order=1, extra=0):
        self.op(9)
        if self.curves == 0:
            return
        self.range(0, self.curves - 1, index)
        self.flag(u == 0.0)
        if u != 0.0:
            self.wild(u)
        if 0 <= order <= 2:
            self.range(0, 3, 1)
            self.range(0, 2, order)
        else:
            self.range(0, 3, 0)
            self.range(-2, 10, order)
        self.range(0, 2, extra)
        self.rarely(False)

    def destroy_curve(self, index, with_ctx=True):
        self.op(10)
        self.flag(True)
        if self.curves == 0:
            return
        self.range(0, self.curves - 1, index)
        self.flag(with_ctx)
        self.curves -= 1

    def null_context(self):
        self.op(11)


def create_seeds():
    seeds = {}

    # Example 2 (seed 000): PRCS of the lines (u,0,0) and (2u,u,1) on [-1/2, 1/2].
    e = CreateEncoder()
    e.simple("line", [0, 0, 0], [1, 0, 0])
    e.simple("line", [0, 0, 1], [2, 1, 0])
    e.surface([0, 1], None, -0.5, 0.5, sample=128, vs=(0.25, 3.0))
    e.curve_eval(1, 0.0)
    e.null_context()
    seeds["seed-example2-prcs-lines"] = e.finish()

    # Example 3: PRRS of the line (u,0,0) and the points (0,0,1), (1,2,1) on [-2, 2].
    e = CreateEncoder(alloc_mode=0, handler=False)
    e.simple("line", [0, 0, 0], [1, 0, 0])
    e.simple("point", [0, 0, 1])
    e.simple("point", [1, 2, 1])
    e.surface([0, 1, 2], None, -2.0, 2.0, sample=256, vs=(-7.0, 0.4))
    e.curve_eval(2, 0.0, order=2)
    seeds["seed-example3-prrs-line-points"] = e.finish(context_first=True)

    # Example 2 with f = (v + 1) / (v + 2) given explicitly, and a line element.
    e = CreateEncoder()
    e.simple("line", [0, 0, 0], [1, 0, 0])
    e.simple("line", [0, 0, 1], [2, 1, 0])
    e.simple("line_element", [0, 1, 1], [0, 0, 1])
    e.surface([0, 1], (0, [1], [1], [1], [2], 1), -0.5, 0.5)
    e.surface([0, 2], (1, [1, 0], [0, 1], [0, 0], [1, 0], 1), 0.0, 1.0)
    seeds["seed-prcs-mobius-line-element"] = e.finish()

    # Polynomial and rational cubics, PRCS and PRRS on them.
    e = CreateEncoder()
    e.polynomial([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]])
    e.polynomial([[0, 0, 1], [2, 1, 0], [0, 0, 0.5], [0.25, 0, 0]], stride=5)
    e.polynomial([[1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 1]], rational=True, stride=6)
    e.surface([0, 1], None, -0.5, 0.5)
    e.surface([0, 1, 2], None, -1.0, 1.0)
    e.curve_eval(0, 0.0)
    e.curve_eval(2, 0.75, order=9)
    seeds["seed-cubics"] = e.finish()

    # Bezier (weighted) and Hermite curves.
    e = CreateEncoder(handler=True)
    e.bezier([[0, 0, 0], [1, 2, 0], [2, 0, 1]], [1, 0.5, 1], 0.0, 1.0)
    e.bezier([[0, 0, 1], [1, 1, 1], [3, 0, 2], [4, 1, 0]], None, -1.0, 2.0, stride=4)
    e.hermite(1, [0, 0, 0, 1, 0, 0], [1, 1, 0, 0, 1, 0], 0.0, 1.0)
    e.hermite(3, [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1], [1, 1, 1, 0, 1, 0, 1, 0, 0, 0, 0, 0],
              -1.0, 1.0)
    e.surface([0, 2], None, 0.0, 1.0, ok=False)
    e.surface([0, 1, 3], None, 0.0, 1.0)
    e.curve_eval(1, 0.5)
    seeds["seed-bezier-hermite"] = e.finish()

    # Out-of-range degrees, strides, NULL pointers: all rejected.
    e = CreateEncoder()
    e.polynomial([[1, 2, 3]] * 16, degree=16, ok=False)
    e.polynomial([[1, 2, 3]], degree=-1, ok=False)
    e.polynomial([[1, 2, 3]] * 16, degree=2**31 - 1, ok=False)
    e.polynomial([[1, 2, 3, 1]] * 2, rational=True, stride=2, ok=False)
    e.polynomial([[1, 2, 3]] * 3, null_coeffs=True, ok=False)
    e.polynomial([[1, 2, 3]] * 3, null_out=True, ok=False)
    e.simple("line", [0, 0, 0], [0, 0, 0], ok=False)
    e.simple("line", [0, 0, 0], [1, 0, 0], nulls=(False, True, False), ok=False)
    e.hermite("max+1", [0.0] * 24, [0.0] * 24, 0, 1, ok=False)
    e.null_context()
    seeds["seed-bad-degrees-nulls"] = e.finish()

    # Non-finite and boundary values: NaN, Inf, 1e100 and its successor.
    e = CreateEncoder()
    e.simple("point", [NAN, 0, 0], style=0, ok=False)
    e.simple("point", [INF, 0, 0], style=0, ok=False)
    e.simple("point", [1e100, -1e100, 0], style=0)
    e.simple("point", [1.0000000000000002e100, 0, 0], style=0, ok=False)
    e.simple("line", [1e-300, 5e-324, 0], [1e100, 1e-300, 0], style=0)
    e.polynomial([[1e100, 0, 0], [0, 1e100, 0], [0, 0, 1e100]], style=0)
    e.surface([0, 1, 2], None, -1e100, 1e100, style=0, ok=False)
    e.surface([1, 2], None, NAN, 1.0, style=0, ok=False)
    e.curve_eval(2, 1e100, order=2)
    seeds["seed-nonfinite-boundaries"] = e.finish()

    # Bad domains and Mobius parameters.
    e = CreateEncoder()
    e.simple("line", [0, 0, 0], [1, 0, 0])
    e.simple("line", [0, 0, 1], [2, 1, 0])
    e.surface([0, 1], None, 0.5, 0.5, ok=False)
    e.surface([0, 1], None, 1.0, -1.0, ok=False)
    e.surface([0, 1], (0, [0], [0], [0], [0], 1), -0.5, 0.5, ok=False)  # f = 0/0
    e.surface([0, 1], (0, [1], [2], [2], [4], 1), -0.5, 0.5, ok=False)  # ad - bc = 0
    e.surface([0, 1], (16, *([[1.0] * 16] * 4), 1), -0.5, 0.5, ok=False)
    e.surface([0, 1], (2, [1, 0, 0], [0, 0, 0], [0, 0, NAN], [1, 0, 0], 0), -0.5, 0.5,
              style=1, ok=False)
    e.surface([None, 1], None, -0.5, 0.5, ok=False)
    seeds["seed-bad-domain-mobius"] = e.finish()

    # The allocator fails: the context, then a curve, then a surface.
    # (allocation 0 is the context, then one per handle)
    e = CreateEncoder(alloc_mode=2, fail_at=0)
    seeds["seed-oom-context"] = e.data()
    e = CreateEncoder(alloc_mode=2, fail_at=1)
    e.simple("line", [0, 0, 0], [1, 0, 0], ok=False)
    e.simple("line", [0, 0, 1], [2, 1, 0])
    e.simple("point", [0, 0, 1])
    e.destroy_curve(0, with_ctx=False)
    seeds["seed-oom-curve"] = e.finish()
    e = CreateEncoder(alloc_mode=2, fail_at=3, fail_after=True)
    e.simple("line", [0, 0, 0], [1, 0, 0])
    e.simple("line", [0, 0, 1], [2, 1, 0])
    e.surface([0, 1], None, -0.5, 0.5, ok=False)
    e.simple("point", [0, 0, 1], ok=False)
    e.destroy_curve(1, with_ctx=True)
    seeds["seed-oom-surface"] = e.finish(context_first=True)

    # PRRS with two points and a cubic; PRCS of parallel lines (Remark 1).
    e = CreateEncoder()
    e.polynomial([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]])
    e.simple("point", [0, 0, 1])
    e.simple("point", [1, 2, 1])
    e.simple("line", [0, 1, 0], [1, 0, 0])
    e.surface([0, 1, 2], None, -1.0, 1.0)
    e.surface([0, 3], None, -1.0, 1.0, ok=False)
    e.surface([1, 2, 1], None, -1.0, 1.0, ok=False)
    seeds["seed-prrs-cubic-points-remark1"] = e.finish()

    return seeds


# ---------------------------------------------------------------- fuzz_eval

class EvalEncoder(Encoder):
    """Mirrors fuzz_eval.cpp."""

    def __init__(self, prrs, curves, mobius, u0_eighths, len_sixteenths, handler=True):
        super().__init__()
        self.u0 = u0_eighths / 8.0
        self.u1 = self.u0 + len_sixteenths / 16.0
        self.flag(handler)
        self.flag(prrs)
        for c in curves:
            self.curve(*c)
        if mobius is None:
            self.range(0, 2, 0)
        elif mobius == "identity":
            self.range(0, 2, 1)
        else:
            degree = len(mobius[0]) - 1
            self.range(0, 2, 2)
            self.range(0, 2, degree)
            for arr in mobius:
                self.fill(arr, 1)
        self.range(-16, 16, u0_eighths)
        self.range(1, 64, len_sixteenths)
        self.nops_at = len(self.consumed)
        self.nops = 0

    def curve(self, kind, *args):
        if kind == "polynomial":  # rows, stride
            rows, stride = args
            self.range(0, 5, 0)
            self.range(1, 3, len(rows) - 1)
            self.range(3, 5, stride)
            for r in rows:
                self.fill(r, 1)
        elif kind == "rational":  # rows of xyz, wmode, weights, stride
            rows, wmode, w, stride = args
            self.range(0, 5, 1)
            self.range(1, 3, len(rows) - 1)
            self.range(4, 6, stride)
            self.range(0, 2, wmode)
            for k, r in enumerate(rows):
                self.fill(r, 1)
                if wmode == 1 and k > 0:
                    self.moderate(w[k] * 4.0)
                elif wmode == 2:
                    self.moderate(w[k])
        elif kind == "bezier":  # ctrl, weights (quarters) or None, a (quarters), len (eighths)
            ctrl, weights, a4, len8 = args
            self.range(0, 5, 2)
            self.range(1, 3, len(ctrl) - 1)
            self.range(3, 5, 3)
            for r in ctrl:
                self.fill(r, 1)
            self.flag(weights is not None)
            for w in weights or []:
                self.range(1, 16, w)
            self.range(-8, 8, a4)
            self.range(1, 32, len8)
        elif kind == "hermite":  # order, a (quarters), len (eighths), start, end
            order, a4, len8, start, end = args
            self.range(0, 5, 3)
            self.range(0, 1, order)
            self.range(-8, 8, a4)
            self.range(1, 32, len8)
            self.fill(start, 1)
            self.fill(end, 1)
        elif kind == "line":
            p, d = args
            self.range(0, 5, 4)
            self.fill(p, 1)
            self.fill(d, 1)
        elif kind == "point":
            (p,) = args
            self.range(0, 5, 5)
            self.fill(p, 1)
        elif kind == "line_element":
            p, d = args
            self.range(0, 5, 5)
            self.fill(p, 1)
            self.fill(d, 1)
        else:
            raise ValueError(kind)

    def finish(self):
        body = self.consumed[self.nops_at:]
        self.consumed = self.consumed[:self.nops_at]
        assert 1 <= self.nops <= 24
        self.range(1, 24, self.nops)
        self.consumed.extend(body)
        return self.data()

    def op(self, code):
        self.nops += 1
        self.range(0, 8, code)

    # parameters: ("t", fraction) in-domain, ("k", sample), ("m", moderate),
    # ("w", wild), ("end", 0/1); v: ("m", x), ("w", x), ("i", small int), ("big", x, e)
    def u(self, spec):
        kind, x = spec if isinstance(spec, tuple) else ("m", spec)
        if kind == "t":
            self.range(0, 4, 0)
            self.range(0, 65535, round(x * 65535))
        elif kind == "k":
            self.range(0, 4, 1)
            self.range(0, 256, x)
        elif kind == "m":
            self.range(0, 4, 2)
            self.moderate(x)
        elif kind == "w":
            self.range(0, 4, 3)
            self.wild(x)
        else:
            self.range(0, 4, 4)
            self.flag(x)

    def v(self, spec):
        kind, x = spec if isinstance(spec, tuple) else ("m", spec)
        if kind == "m":
            self.range(0, 3, 0)
            self.moderate(x)
        elif kind == "w":
            self.range(0, 3, 1)
            self.wild(x)
        elif kind == "i":
            self.range(0, 3, 2)
            self.range(-3, 3, x)
        else:  # ("big", (mantissa, exponent))
            self.range(0, 3, 3)
            self.moderate(x[0])
            self.range(0, 12, x[1])

    def eval(self, u, v, mask=15):
        self.op(0)
        self.u(u)
        self.v(v)
        if mask == 15:
            self.range(0, 15, 1)
        else:
            self.range(0, 15, 0)
            self.range(0, 15, mask)

    def buf(self, spec):
        """None (not wanted) or (stride, extra capacity 0/1)."""
        if spec is None:
            self.range(0, 3, 0)
            return
        stride, extra = spec
        self.range(0, 3, 1)
        if stride < 3:
            self.range(0, 7, 0)
            self.range(0, 2, stride)
        else:
            self.range(0, 7, 1)
            self.range(3, 5, stride)
        self.range(0, 1, extra)
        self.rarely(False)

    def batch(self, uvs, uv_stride=2, bufs=((3, 0), (3, 0), (4, 1), (3, 0)), singular=True):
        self.op(1)
        self.range(0, 12, len(uvs))
        if uv_stride < 2:
            self.range(0, 7, 0)
            self.range(0, 1, uv_stride)
        else:
            self.range(0, 7, 1)
            self.range(2, 4, uv_stride)
        self.rarely(False)
        for u, v in uvs:
            self.u(u)
            self.v(v)
        for b in bufs:
            self.buf(b)
        self.flag(singular)

    def grid(self, us, vs, bufs=((3, 0), (5, 1), None, (3, 0)), singular=True):
        self.op(2)
        self.range(0, 4, len(us))
        self.range(0, 5, len(vs))
        self.rarely(False)
        self.rarely(False)
        for u in us:
            self.u(u)
        for v in vs:
            self.v(v)
        for b in bufs:
            self.buf(b)
        self.flag(singular)

    def circle(self, u, v=None):  # v is read only if the circle exists
        self.op(3)
        self.u(u)
        if v is not None:
            self.v(v)

    def sphere(self, u):
        self.op(4)
        self.u(u)

    def ringed_data(self, u, mask=15):
        self.op(5)
        self.u(u)
        if mask == 15:
            self.range(0, 3, 1)
        else:
            self.range(0, 3, 0)
            self.range(0, 15, mask)

    def ringed_sphere(self, u):
        self.op(6)
        self.u(u)

    def canal_test(self, tol=0.0, mask=3):
        self.op(7)
        if tol == 0.0:
            self.range(0, 2, 0)
        else:
            self.range(0, 2, 1)
            self.wild(tol)
        if mask == 3:
            self.range(0, 3, 1)
        else:
            self.range(0, 3, 0)
            self.range(0, 3, mask)

    def parameter_of(self, u, v=None, point=None):
        self.op(8)
        self.u(u)
        if v is not None:
            self.range(0, 3, 0)
            self.v(v)
        elif point is not None:
            self.range(0, 3, 1)
            self.fill(point, 1)
        else:
            self.range(0, 3, 3)


def all_ops(e, prcs):
    """One of each query, in the domain."""
    e.eval(("t", 0.5), 0.25)
    e.eval(("k", 0), ("i", -3), mask=1)
    e.batch([(("t", 0.1), 0.0), (("t", 0.9), -2.0), (("k", 128), ("big", (1.5, 6)))])
    e.grid([("t", 0.0), ("t", 0.5), ("end", 1)], [-1.0, 0.0, 0.5, 3.0])
    e.circle(("t", 0.3), 1.5)
    e.sphere(("t", 0.7))
    e.ringed_data(("t", 0.4))
    e.ringed_sphere(("t", 0.6))
    e.canal_test()
    e.parameter_of(("t", 0.2), v=0.75)
    e.parameter_of(("t", 0.2), point=[1, 2, 3])


def eval_seeds():
    seeds = {}
    line = lambda p, d: ("line", p, d)

    # Example 2 (seed 000): PRCS of (u,0,0) and (2u,u,1) on [-1/2, 1/2].
    e = EvalEncoder(False, [line([0, 0, 0], [1, 0, 0]), line([0, 0, 1], [2, 1, 0])],
                    None, -4, 16)
    all_ops(e, True)
    seeds["seed-example2-prcs-lines"] = e.finish()

    # Example 3: PRRS of (u,0,0), (0,0,1), (1,2,1) on [-2, 2].
    e = EvalEncoder(True, [line([0, 0, 0], [1, 0, 0]), ("point", [0, 0, 1]),
                           ("point", [1, 2, 1])], None, -16, 64)
    all_ops(e, False)
    seeds["seed-example3-prrs-line-points"] = e.finish()

    # Example 2 with the identity f spelled out, and with f = (v + u)/(v + 2).
    e = EvalEncoder(False, [line([0, 0, 0], [1, 0, 0]), line([0, 0, 1], [2, 1, 0])],
                    "identity", -4, 16, handler=False)
    all_ops(e, True)
    seeds["seed-example2-identity-f"] = e.finish()
    e = EvalEncoder(False, [line([0, 0, 0], [1, 0, 0]), line([0, 0, 1], [2, 1, 0])],
                    [[1, 0], [0, 1], [1, 0], [2, 0]], -4, 16)
    all_ops(e, True)
    seeds["seed-example2-mobius-f"] = e.finish()

    # Example 3 with f of degree 2.
    e = EvalEncoder(True, [line([0, 0, 0], [1, 0, 0]), ("point", [0, 0, 1]),
                           ("point", [1, 2, 1])],
                    [[1, 0, 0.5], [0, 1, 0], [0, 0, 0], [1, 0, 0]], -8, 32)
    all_ops(e, False)
    seeds["seed-example3-mobius-f"] = e.finish()

    # PRCS of a cubic and a line element; of two cubics.
    cubic1 = ("polynomial", [[0, 0, 0], [1, 0, 0], [0, 0.5, 0], [0, 0, 0.25]], 3)
    cubic2 = ("polynomial", [[0, 0, 2], [1, 1, 0], [0.5, 0, 0], [0, 0.125, 0]], 4)
    e = EvalEncoder(False, [cubic1, ("line_element", [0, 1, 1], [0, 0, 1])], None, -2, 16)
    all_ops(e, True)
    seeds["seed-prcs-cubic-line-element"] = e.finish()
    e = EvalEncoder(False, [cubic1, cubic2], None, -2, 8)
    all_ops(e, True)
    seeds["seed-prcs-two-cubics"] = e.finish()

    # PRRS of three cubics (rational, Bezier, Hermite).
    e = EvalEncoder(True, [
        ("rational", [[0, 0, 0], [1, 0, 0], [0, 1, 0]], 1, [4, 0.25, 0.5], 4),
        ("bezier", [[0, 0, 2], [1, 0, 2], [2, 1, 2], [3, 0, 3]], [4, 2, 4, 4], 0, 8),
        ("hermite", 1, 0, 8, [0, 3, 0, 1, 0, 0], [1, 3, 1, 0, 1, 0]),
    ], None, 0, 16)
    all_ops(e, False)
    seeds["seed-prrs-three-cubics"] = e.finish()

    # Parameters outside the domain and non-finite: errors, untouched outputs.
    e = EvalEncoder(False, [line([0, 0, 0], [1, 0, 0]), line([0, 0, 1], [2, 1, 0])],
                    None, -4, 16)
    e.eval(("w", NAN), 0.5)
    e.eval(("t", 0.5), ("w", INF))
    e.eval(("w", 1.0000000000000002e100), 0.5)
    e.eval(("t", 0.5), ("w", 1e100))
    e.eval(("m", 7.5), ("w", -1e30))
    e.eval(("t", 0.5), 0.5, mask=0)
    e.batch([(("t", 0.5), 0.0), (("w", NAN), 1.0)])
    e.batch([(("t", 0.5), 0.0)], uv_stride=1)
    e.batch([(("t", 0.5), 0.0), (("t", 0.6), 0.0)], bufs=((2, 0), None, None, None))
    e.grid([("t", 0.5)], [("w", INF), 0.0])
    e.grid([("w", -INF)], [0.0])
    e.circle(("w", NAN))
    e.sphere(("w", INF))
    e.ringed_data(("w", NAN), mask=5)
    e.ringed_sphere(("w", 1e101))
    e.canal_test(tol=NAN)
    e.canal_test(mask=0)
    e.parameter_of(("t", 0.5), point=[0, 0, 0])
    e.parameter_of(("w", NAN))
    seeds["seed-nonfinite-parameters"] = e.finish()

    # Example 3 far outside its domain, and at huge v (the generator).
    e = EvalEncoder(True, [line([0, 0, 0], [1, 0, 0]), ("point", [0, 0, 1]),
                           ("point", [1, 2, 1])], None, -16, 64)
    e.eval(("m", 9.75), ("big", (9.5, 12)))
    e.eval(("w", 1e50), 1.0)
    e.grid([("w", -1e6), ("m", -10), ("k", 256)], [("i", -3), ("big", (-1, 9)), ("w", 5e-324)])
    e.batch([(("w", 1e15), ("w", 1e-300)), (("k", 17), ("w", -0.0))])
    e.parameter_of(("m", 3.5), v=("big", (2.5, 10)))
    e.ringed_sphere(("m", -6))
    seeds["seed-prrs-far-parameters"] = e.finish()

    # Regression (kKnownIssueCircleQuadratic, fuzz_common.hpp): far from the
    # domain the spine speed |a| = |s'| is ~6e8 and x_v lost 5 digits to the
    # quotient rule (found by fuzz_eval; normal . x_v = 5e-6 |x_v|).
    e = EvalEncoder(False, [
        ("polynomial", [[0, 0, -10], [-8.9609375, -9.9755859375, -5.6005859375],
                        [-8, -10, 0.25], [-9.9921875, -10, -9.99998092651367]], 3),
        ("rational", [[-9.90234375, -10, -9.1015625], [-10, -2, -9.5]], 0, None, 4),
    ], None, -15, 12)
    e.eval(("w", -126.95703125), -9.0)
    e.eval(("w", -126.95703125), ("w", 1.0078125))
    e.grid([("w", -126.95703125), ("t", 0.5)], [-9.0, 1.0078125, 0.5], bufs=((3, 0), (3, 0), (3, 0), (3, 0)))
    seeds["seed-regress-xv-far-spine"] = e.finish()

    # Regression (same issue): G(v) = gamma v + delta = 0 at v = -1 with
    # |a| ~ 6e7 at u = -15: Q(v) rounds to 0, so eval reported
    # CYC_E_NUMERICAL_OVERFLOW, eval_grid CYC_OK with NaN points and
    # eval_batch CYC_E_INTERNAL on a validated row.
    e = EvalEncoder(False, [
        ("polynomial", [[-5, -9.9609375, 1], [-9.997463226318359, -9.9414043426513672, -7],
                        [-8, -10, -9.9609375]], 3),
        ("polynomial", [[-9.9755859375, -9.970703125, -8.9609375], [-9.9755859375, -10, -10],
                        [-10, -7.998046875, 0]], 3),
    ], [[-9.0], [-8.99609375], [-8.99609375], [-8.99609375]], -14, 4)
    e.grid([("m", -15.0 / 2)], [-1.0], bufs=((3, 0), None, None, None))
    e.grid([("w", -15.0)], [-1.0], bufs=((3, 0), None, None, None))
    e.batch([(("w", -15.0), -1.0)], bufs=((3, 0), None, None, None))
    e.eval(("w", -15.0), -1.0, mask=1)
    seeds["seed-regress-g-zero-far-spine"] = e.finish()

    return seeds


# ---------------------------------------------------------------- fuzz_darboux

class DarbouxEncoder(Encoder):
    """Mirrors fuzz_darboux.cpp. surface: None, "example2", "example3" or
    ("lines", p1, d1, p2, d2, u0_quarters, len_quarters)."""

    def __init__(self, surface=None, handler=True):
        super().__init__()
        self.flag(handler)
        self.has_surface = surface is not None
        if surface is None:
            self.range(0, 3, 0)
        elif surface == "example2":
            self.range(0, 3, 1)
        elif surface == "example3":
            self.range(0, 3, 2)
        else:
            _, p1, d1, p2, d2, a4, len4 = surface
            self.range(0, 3, 3)
            for v in list(p1) + list(d1) + list(p2) + list(d2):
                self.moderate(v)
            self.range(-8, 8, a4)
            self.range(1, 16, len4)
        self.nops = 0
        self.nops_at = len(self.consumed)

    def finish(self):
        body = self.consumed[self.nops_at:]
        self.consumed = self.consumed[:self.nops_at]
        assert 1 <= self.nops <= 16
        self.range(1, 16, self.nops)
        self.consumed.extend(body)
        return self.data()

    def op(self, code):
        self.nops += 1
        self.range(0, 7, code)

    # -- values (fuzz_darboux.cpp coord, direction, inversion, point)
    def coord(self, v):
        if math.isfinite(v) and v == int(v) and -4 <= v <= 4:
            self.range(0, 3, 3)
            self.range(-4, 4, int(v))
        elif not math.isnan(v) and not math.isinf(v) and abs(v) <= 10 and \
                (v * (1 << 20) / 10.0) == round(v * (1 << 20) / 10.0):
            self.range(0, 3, 0)
            self.moderate(v)
        else:
            self.range(0, 3, 1)
            self.wild(v)

    def coords(self, vs):
        for v in vs:
            self.coord(v)

    def direction(self, d):
        axes = [(1, 0, 0), (0, 1, 0), (0, 0, 1), (-1, 0, 0), (0, -1, 0), (0, 0, -1)]
        if tuple(d) in axes:
            self.flag(True)
            self.range(0, 5, axes.index(tuple(d)))
        else:
            self.flag(False)
            self.coords(d)

    def inversion(self, center, radius):
        self.coords(center)
        e = math.frexp(radius)[1] - 1 if radius > 0 else None
        if radius > 0 and -10 <= e <= 10 and radius == 2.0 ** e:
            self.range(0, 2, 0)
            self.range(-10, 10, e)
        else:
            self.range(0, 2, 1)
            self.coord(radius)

    def point(self, spec):
        """("p", xyz) | ("center",) | ("offset", e, (i, j, k)) | ("sphere", axis)
        | ("wild", xyz)."""
        kind = spec[0]
        if kind == "p":
            self.range(0, 4, 0)
            self.coords(spec[1])
        elif kind == "center":
            self.range(0, 4, 1)
        elif kind == "offset":
            self.range(0, 4, 2)
            self.range(1, 1074, spec[1])
            for v in spec[2]:
                self.range(-2, 2, v)
        elif kind == "sphere":
            self.range(0, 4, 3)
            self.range(0, 2, spec[1])
        else:
            self.range(0, 4, 4)
            for v in spec[1]:
                self.wild(v)

    def nulls(self, which=0, top=3):
        self.rarely(which != 0)
        if which:
            self.range(1, top, which)

    # -- ops
    def invert_point(self, inv, point, nulls=0):
        self.op(1)
        self.inversion(*inv)
        self.point(point)
        self.nulls(nulls)

    def invert_sphere(self, inv, sphere, nulls=0):
        """sphere: ("sphere", C, axis_index, r or "through") | ("plane", n, P or
        "through") | ("any", a, b, c)."""
        self.op(2)
        self.inversion(*inv)
        kind = sphere[0]
        if kind == "sphere":
            _, C, a, r = sphere
            self.range(0, 3, 0)
            self.coords(C)
            self.range(0, 5, a)
            self.flag(r == "through")
            if r != "through":
                self.coord(r)
        elif kind == "plane":
            _, n, P = sphere
            self.range(0, 3, 2)
            self.direction(n)
            self.flag(P == "through")
            if P != "through":
                self.coords(P)
        else:
            _, a, b, c = sphere
            self.range(0, 3, 3)
            self.coord(a)
            self.coords(b)
            self.coord(c)
        self.nulls(nulls)

    def invert_circle(self, inv, is_line, axis, radius=None, through=None, point=None,
                      angle=5, nulls=0):
        """through: t (a line point m + t axis, or the circle through m) or None
        with point given."""
        self.op(3)
        self.inversion(*inv)
        self.flag(is_line)
        self.direction(axis)
        self.flag(through is not None)
        if not is_line:
            self.flag(radius < 0)
            self.coord(radius)
        if through is not None:
            self.coord(through)
        else:
            self.coords(point)
        self.range(0, 63, angle)
        self.nulls(nulls)

    def darboux(self, spec):
        """("coeffs", k14) | ("sparse", k14 moderate, zeros where 0) | ("ex4", alpha)
        | ("sphere", C, r, s) | ("torus", C, r, s)."""
        kind = spec[0]
        if kind == "coeffs":
            self.range(0, 3, 0)
            self.coords(spec[1])
        elif kind == "sparse":
            self.range(0, 3, 1)
            for v in spec[1]:
                self.flag(v == 0)
                if v != 0:
                    self.moderate(v)
        elif kind == "ex4":
            self.range(0, 3, 2)
            self.coord(spec[1])
        else:
            _, C, r, s = spec
            self.range(0, 3, 3)
            self.coords(C)
            self.coord(r)
            self.coord(s)
            self.flag(kind == "sphere")

    def darboux_eval(self, d, X, grad=True, nulls=0):
        self.op(5)
        self.darboux(d)
        self.coords(X)
        self.rarely(not grad)
        self.nulls(nulls)

    def classify(self, d, zero=False, nulls=0):
        self.op(6)
        self.darboux(d)
        self.rarely(zero)
        self.nulls(nulls, top=2)

    def invert_darboux(self, inv, d, on=None, nulls=0):
        self.op(4)
        self.inversion(*inv)
        self.darboux(d)
        self.flag(on is not None)
        if on is not None:
            self.point(on)
        self.nulls(nulls)

    def dcmc(self, lines, near_parallel=None, normal=True, nulls=0, alpha=None, ts=0):
        """lines: "ex4" | ("planes", [(P, (dx, dy))] * 3, coplanar) |
        ("common", [P] * 3, d1, d2, a, b) | ("any", [(P, d)] * 3).
        alpha: read only when the call succeeds."""
        self.op(0)
        if lines == "ex4":
            self.range(0, 4, 0)
        elif lines[0] == "planes":
            self.range(0, 4, 1)
            for P, d in lines[1]:
                self.coords(P)
                self.coord(d[0])
                self.coord(d[1])
            self.flag(lines[2])
        elif lines[0] == "common":
            _, Ps, d1, d2, a, b = lines
            self.range(0, 4, 3)
            for P in Ps:
                self.coords(P)
            self.coords(d1)
            self.coords(d2)
            self.coord(a)
            self.coord(b)
        else:
            self.range(0, 4, 4)
            for P, d in lines[1]:
                self.coords(P)
                self.coords(d)
        self.rarely(near_parallel is not None)
        if near_parallel is not None:
            e, deltas = near_parallel
            self.range(1, 60, e)
            for v in deltas:
                self.range(-1, 1, v)
        self.rarely(not normal)
        self.nulls(nulls)
        if alpha is not None:
            self.coord(alpha)
            self.range(0, 3, ts)

    def surface_inverted(self, inv, u, v, mask=7, null_point=False, center_on_surface=False):
        """u: ("t", k of 1024) or ("w", x); v: ("m", x) or ("w", x)."""
        self.op(7)
        if not self.has_surface:
            return
        self.inversion(*inv)
        self.flag(u[0] == "t")
        (self.range(0, 1024, u[1]) if u[0] == "t" else self.wild(u[1]))
        self.flag(v[0] == "m")
        (self.moderate(v[1]) if v[0] == "m" else self.wild(v[1]))
        self.rarely(mask != 7)
        if mask != 7:
            self.range(0, 7, mask)
        self.rarely(null_point)
        self.flag(center_on_surface)


def darboux_seeds():
    seeds = {}
    unit = ((0, 0, 0), 1.0)
    ex4 = "ex4"

    # Example 4 of seed 000, eq. (34)-(35): DCMC, members, types, values.
    e = DarbouxEncoder()
    e.dcmc(ex4, alpha=0)
    e.dcmc(ex4, alpha=2.5, ts=2)
    e.dcmc(ex4, normal=False, alpha=-3, ts=1)
    e.classify(("ex4", 0))
    e.classify(("ex4", 1.5))
    e.darboux_eval(("ex4", 0), (2, -2, -1))
    e.darboux_eval(("ex4", 1), (0.5, 0, 0), grad=False)
    e.invert_darboux(unit, ("ex4", 0), on=("p", (3, 0, 0)))
    e.invert_darboux(((0, 0, 1), 0.5), ("ex4", 2), on=("p", (0, 3, 1)))
    seeds["seed-example4-dcmc"] = e.finish()

    # DCMC on lines in planes z = h, with a common normal in general
    # position, coplanar, near-parallel, parallel and skew lines.
    e = DarbouxEncoder(handler=False)
    e.dcmc(("planes", [((1, 0, -1), (1, 2)), ((0, 1, 0.5), (-1, 1)), ((2, 2, 3), (0, 1))],
            False), alpha=1, ts=3)
    e.dcmc(("common", [(0, 0, 0), (1, 2, 3), (-1, 0, 2)], (1, 1, 0), (0, 1, 1), 2, -1),
           alpha=0.5)
    e.dcmc(("planes", [((0, 0, 0), (1, 0)), ((0, 0, 0), (0, 1)), ((0, 0, 2), (1, 1))], True))
    e.dcmc(ex4, near_parallel=(40, (1, 0, -1)))
    e.dcmc(("planes", [((0, 0, 0), (1, 0)), ((0, 0, 1), (2, 0)), ((0, 0, 2), (1, 1))], False))
    e.dcmc(("any", [((0, 0, 0), (1, 0, 0)), ((0, 0, 1), (0, 1, 0)), ((0, 0, 2), (0, 1, 1))]))
    e.dcmc(ex4, nulls=1)
    e.dcmc(ex4, nulls=3)
    seeds["seed-dcmc-lines"] = e.finish()

    # The unit inversion: points, the center, a few ulps from it, the sphere
    # itself; spheres and planes through the center; circles and lines
    # through the center.
    e = DarbouxEncoder()
    e.invert_point(unit, ("p", (2, 0, 0)))
    e.invert_point(unit, ("p", (0.5, -1.25, 3)))
    e.invert_point(unit, ("center",))
    e.invert_point(unit, ("offset", 1074, (1, 0, -1)))
    e.invert_point(unit, ("offset", 30, (1, 2, 0)))
    e.invert_point(unit, ("sphere", 1))
    e.invert_sphere(unit, ("sphere", (1, 0, 0), 0, "through"))
    e.invert_sphere(unit, ("sphere", (0, 2, 0), 2, 0.5))
    e.invert_sphere(unit, ("plane", (0, 0, 1), "through"))
    e.invert_sphere(unit, ("plane", (0, 1, 0), (0, 3, 0)))
    e.invert_circle(unit, False, (0, 0, 1), radius=1, through=0)
    e.invert_circle(unit, True, (1, 0, 0), through=2)
    e.invert_circle(unit, True, (0, 1, 0), point=(1, 0, 0), angle=9)
    e.invert_circle(unit, False, (1, 0, 0), radius=0.5, point=(0, 2, 0))
    e.invert_darboux(unit, ("sphere", (1, 0, 0), 1, 1), on=("center",))
    e.invert_darboux(unit, ("torus", (2, 0, 0), 1, 1), on=("p", (1, 0, 0)))
    seeds["seed-unit-inversion"] = e.finish()

    # Hostile inversions: NaN / Inf / zero / negative radius, huge centers,
    # tiny and huge radii, NULL arguments.
    e = DarbouxEncoder()
    e.invert_point(((NAN, 0, 0), 1.0), ("p", (1, 2, 3)))
    e.invert_point(((0, 0, 0), INF), ("p", (1, 2, 3)))
    e.invert_point(((0, 0, 0), 0.0), ("p", (1, 2, 3)))
    e.invert_point(((0, 0, 0), -1.0), ("p", (1, 2, 3)))
    e.invert_point(((1e100, 0, 0), 2.0 ** -10), ("wild", (-1e100, 1e-300, 5e-324)))
    e.invert_point(((1, 1, 1), 1e-160), ("p", (1, 1, 2)))
    e.invert_point(unit, ("p", (1, 2, 3)), nulls=2)
    e.invert_sphere(((0, 0, 0), 1e50), ("any", 0, (0, 0, 0), 1))
    e.invert_circle(((1e90, 0, 0), 1.0), False, (0, 0, 1), radius=1e-90, point=(1, 1, 1))
    e.invert_darboux(((0, 0, 0), 1e30), ("coeffs", [1e100] * 14), on=("p", (1, 1, 1)))
    e.darboux_eval(("coeffs", [1e100] * 14), (1e100, 1e100, 1e100))
    e.darboux_eval(("coeffs", [NAN] + [0] * 13), (0, 0, 0))
    e.classify(("sparse", [0] * 14), zero=True)
    e.classify(("coeffs", [1e-300] * 14))
    seeds["seed-hostile-inversions"] = e.finish()

    # Surfaces through an inversion: Example 2 (PRCS) and 3 (PRRS), the
    # center on the surface, at infinity-bound parameters.
    for name, surf in (("seed-surface-inverted-example2", "example2"),
                       ("seed-surface-inverted-example3", "example3")):
        e = DarbouxEncoder(surface=surf)
        e.surface_inverted(((0, 0, 3), 1.0), ("t", 512), ("m", 0.5))
        e.surface_inverted(((1, -1, 2), 0.5), ("t", 100), ("m", -2))
        e.surface_inverted(((0, 0, 0), 2.0), ("t", 700), ("m", 1.5), center_on_surface=True)
        e.surface_inverted(unit, ("w", NAN), ("m", 0.5))
        e.surface_inverted(unit, ("t", 3), ("w", 1e100), mask=1)
        e.surface_inverted(unit, ("t", 3), ("m", 1), null_point=True)
        seeds[name] = e.finish()
    e = DarbouxEncoder(surface=("lines", (0, 0, 0), (1, 0, 0), (0, 0, 1), (2, 1, 0), -2, 4))
    e.surface_inverted(((0, 0, 3), 1.0), ("t", 256), ("m", 0.25))
    seeds["seed-surface-inverted-prcs-lines"] = e.finish()

    return seeds


# ---------------------------------------------------------------- fuzz_lines

class LinesEncoder(Encoder):
    """Mirrors fuzz_lines.cpp. Cyclides, lines, analyses as the harness reads
    them; `lines` arguments give how many lines the analysis finds (needed
    for the pencil-circle choices: index 0 is always used)."""

    coord = DarbouxEncoder.coord
    coords = DarbouxEncoder.coords

    def __init__(self, handler=True):
        super().__init__()
        self.flag(handler)
        self.nops = 0
        self.nops_at = len(self.consumed)

    def finish(self):
        body = self.consumed[self.nops_at:]
        self.consumed = self.consumed[:self.nops_at]
        assert 1 <= self.nops <= 8
        self.range(1, 8, self.nops)
        self.consumed.extend(body)
        return self.data()

    def op(self, code):
        self.nops += 1
        self.range(0, 4, code)

    def dyadic(self, v):
        assert v * 64 == int(v * 64) and abs(v) <= 2, v
        self.range(-128, 128, int(v * 64))

    def example(self, spec):
        """("ex2",) | ("ex5",) | ("ex4", a) | ("appA", a, c) | ("appB",) |
        ("family", a)."""
        names = ["ex2", "ex5", "ex4", "appA", "appB", "family"]
        self.range(0, 5, names.index(spec[0]))
        for v in spec[1:]:
            self.coord(v)

    def three(self, good, a0, s1, s2, h0, g1, g2, points, perm=0, signs=0):
        self.flag(good)
        self.range(0, 179, a0)
        for s in (s1, s2):
            self.range(10, 80, s) if good else self.range(0, 179, s)
        self.dyadic(h0)
        for g in (g1, g2):
            self.dyadic(g - 0.25 if good else g)
        self.range(0, 5, perm)
        self.range(0, 7, signs)
        for px, py in points:
            self.dyadic(px)
            self.dyadic(py)

    def cyclide(self, spec, scale=None):
        """("example", ex) | ("coeffs", k14) | ("dcmc", three_args, alpha) |
        ("z_sphere", which, e, v) (z (X.X - 1) + v 2^-e on k[which]) |
        ("hostile", ex, which, v)."""
        kind = spec[0]
        if kind == "example":
            self.range(0, 6, 0)
            self.example(spec[1])
        elif kind == "coeffs":
            self.range(0, 6, 1)
            self.coords(spec[1])
            self.rarely(spec[1][0] != 0)
        elif kind == "dcmc":
            self.range(0, 6, 5)
            self.three(*spec[1])
            self.coord(spec[2])
        elif kind == "z_sphere":
            _, which, e, v = spec
            self.range(0, 6, 3)
            self.flag(True)   # z (X.X + f), l = e_z
            self.flag(True)   # delta = 0
            self.flag(True)   # f = -1
            self.range(0, 13, which)
            self.range(0, 60, e)
            self.coord(v)
        else:
            _, ex, which, v = spec
            self.range(0, 6, 6)
            self.example(ex)
            self.range(0, 13, which)
            self.wild(v)
        self.rarely(scale is not None)
        if scale is not None:
            self.flag(True)
            self.range(-60, 60, scale)

    def parameterize(self, kind, domain=None, inputs=True, nulls=0):
        """kind: "prcs" | "prrs" | 0 | ("any", k)."""
        if kind == "prcs":
            self.range(0, 3, 0)
        elif kind == "prrs":
            self.range(0, 3, 1)
        elif kind == 0:
            self.range(0, 3, 2)
        else:
            self.range(0, 3, 3)
            self.range(-3, 7, kind[1])
        self.flag(domain is None)
        if domain is not None:
            self.coord(domain[0])
            self.coord(domain[1])
        self.rarely(not inputs)
        self.rarely(nulls != 0)
        if nulls:
            self.range(1, 2, nulls)

    def analysis(self, lines, scale=1, pencils=(), param=None, null_out=False):
        """After a successful cyc_parabolic_lines with `lines` lines:
        pencils = angles in degrees (0: the plane through l0) of line 0."""
        self.rarely(null_out)
        if lines is not None:
            self.range(-8, 8, scale)
            if lines:
                self.range(0, 3, len(pencils))
                for a in pencils:
                    if lines > 1:
                        self.range(0, lines - 1, 0)
                    self.flag(a == 0)
                    if a:
                        self.range(1, 179, a)
        self.flag(param is not None)
        if param is not None:
            self.parameterize(*param)

    def analyze(self, cyclide, lines, **kw):
        self.op(0)
        self.cyclide(cyclide)
        self.analysis(lines, **kw)

    def dcmc_member(self, three_args, alpha, lines, **kw):
        self.op(1)
        self.three(*three_args)
        self.flag(True)
        self.dyadic(alpha)
        self.analysis(lines, **kw)

    def pencil(self, cyclide, P, d, m, nulls=0):
        self.op(2)
        self.cyclide(cyclide)
        self.coords(P)
        self.coords(d)
        self.coords(m)
        self.rarely(nulls != 0)
        if nulls:
            self.range(1, 4, nulls)

    def param_op(self, cyclide, *param):
        self.op(3)
        self.cyclide(cyclide)
        self.parameterize(*param)

    def prrs(self, lines, apply_mu=False, nulls=0, analyze=None):
        """lines: ("ex5", hat) | ("normal", u0, h, O, d1, d2, d3, P3xy) |
        ("any", [(P, d)] * 3); analyze: None or (line count, analysis kw)
        when the cyclide is computed."""
        self.op(4)
        if lines[0] == "ex5":
            self.range(0, 3, 0)
            self.flag(lines[1])
        elif lines[0] == "normal":
            _, u0, h, O, d1, d2, d3, P3 = lines
            self.range(0, 3, 1)
            self.dyadic(u0)
            self.dyadic(h)
            for v in O:
                self.dyadic(v)
            for d in (d1, d2, d3):
                self.dyadic(d[0])
                self.dyadic(d[1])
            self.dyadic(P3[0])
            self.dyadic(P3[1])
            self.rarely(False)
        else:
            self.range(0, 3, 3)
            for P, d in lines[1]:
                self.coords(P)
                self.coords(d)
        self.flag(apply_mu)
        self.rarely(nulls != 0)
        if nulls:
            self.range(1, 2, nulls)
        if analyze is not None:
            self.flag(True)
            self.analysis(analyze[0], **analyze[1])


def lines_seeds():
    seeds = {}
    # Example 2 (39): five lines, l3 double; Prop. 3 (PRCS) and Prop. 5.
    e = LinesEncoder()
    e.analyze(("example", ("ex2",)), 5, scale=3, pencils=(0, 45, 120), param=("prcs",))
    e.analyze(("example", ("ex2",)), 5, scale=-2, pencils=(90,), param=("prrs", (-2, 3)))
    seeds["seed-example2"] = e.finish()
    # Example 5 (61): six lines; Prop. 5 (PRRS); Prop. 3 fails (no double line).
    e = LinesEncoder()
    e.analyze(("example", ("ex5",)), 6, scale=1, pencils=(0, 30, 150), param=("prrs",))
    e.analyze(("example", ("ex5",)), 6, scale=-1, pencils=(60,), param=("prcs",))
    seeds["seed-example5"] = e.finish()
    # Example 4 (35), the family (60), App. A (70), App. B (73).
    e = LinesEncoder(handler=False)
    e.analyze(("example", ("ex4", 1)), 6, scale=2, pencils=(0, 77), param=("prrs",))
    e.analyze(("example", ("family", -3.25)), 6, scale=4, pencils=(10,))
    e.analyze(("example", ("appA", 2, 1)), 4, pencils=(0, 100), param=("prcs",))
    e.analyze(("example", ("appB",)), 3, pencils=(45,), param=("prcs", (0, 1)))
    seeds["seed-paper-examples"] = e.finish()
    # DCMC members of well-separated lines: the three lines are found.
    e = LinesEncoder()
    three = (True, 20, 50, 60, 0.5, 0.75, 0.5, [(0.25, -1), (1, 0.5), (-0.5, 0)], 1, 5)
    e.dcmc_member(three, 0.5, 6, scale=5, pencils=(0, 90), param=("prrs",))
    e.analyze(("dcmc", three, 1.5), 6, pencils=(33,))
    seeds["seed-dcmc-members"] = e.finish()
    # Seed 000 §8: Example 5 (given lines, with mu = 1/2 applied), normal form.
    e = LinesEncoder()
    e.prrs(("ex5", False), apply_mu=True, analyze=(6, dict(pencils=(0, 45), param=("prrs",))))
    e.prrs(("ex5", True))
    e.prrs(("normal", 0.5, 1, (0, 0, 0), (1, 0), (2, 1), (-1, 1.5), (1, 1)), apply_mu=True)
    e.prrs(("any", [((0, 0, 0), (1, 0, 0)), ((0, 0, 1), (0, 1, 0)), ((1, 1, 1), (1, 1, 0))]))
    e.prrs(("ex5", False), nulls=2)
    seeds["seed-prrs-lines"] = e.finish()
    # Hostile: near-reducible z (X.X - 1) + tiny, NaN / Inf / huge
    # coefficients, lines not on the cyclide, bad kinds and domains, NULLs.
    e = LinesEncoder()
    e.analyze(("z_sphere", 13, 40, 1), None, param=("prrs",))
    e.analyze(("z_sphere", 5, 52, -3), None)
    e.analyze(("hostile", ("ex2",), 0, NAN), None, param=("prcs",))
    e.analyze(("hostile", ("ex5",), 3, 1e300), None)
    seeds["seed-hostile-cyclides"] = e.finish()
    e = LinesEncoder()
    e.pencil(("example", ("ex2",)), (0, 0, 0), (1, 0, 0), (0, 0, 1))
    e.pencil(("example", ("ex2",)), (0, 0, 5), (1, 0, 0), (0, 1, 0))
    e.pencil(("example", ("ex2",)), (0, 0, 0), (1, 0, 0), (0, 0, 1), nulls=4)
    e.param_op(("example", ("ex5",)), ("any", 7))
    e.param_op(("example", ("ex5",)), "prrs", (2, -2))
    e.param_op(("example", ("ex2",)), "prcs", None, True, 2)
    seeds["seed-hostile-lines"] = e.finish()
    return seeds


# ---------------------------------------------------------------- fuzz_blend

class BlendEncoder(Encoder):
    """Mirrors fuzz_blend.cpp. Surfaces: ("none",), ("cone",) (cone1 /
    cone2 of tests/blend_test.cpp by index), ("prrs", lines), ("prcs",
    lines), ("cubic", curves) with each value a small integer (coordinate
    mode 3) or a sixteenth (mode 2), and an optional domain (u0_quarters,
    len_quarters). Ops are appended with derivatives/blend/continuity and
    encoded by finish()."""

    def __init__(self, surfaces, handler=True):
        super().__init__()
        self.flag(handler)
        for s in surfaces:
            self.surface(*s)
        self.ops = []

    def coord(self, v):
        if v == int(v) and -4 <= v <= 4:
            self.range(0, 3, 3)
            self.range(-4, 4, int(v))
        else:
            assert v * 16 == int(v * 16) and abs(v) <= 4, v
            self.range(0, 3, 2)
            self.range(-64, 64, int(v * 16))

    def surface(self, kind, curves=None, domain=None, coincident=False):
        modes = {"none": 0, "cone": 1, "prrs": 2, "prcs": 3, "cubic": 4}
        self.range(0, 4, modes[kind])
        if modes[kind] < 2:
            return
        for c in curves:
            for x in c:
                self.coord(x)
        self.rarely(coincident)
        self.flag(domain is not None)
        if domain is not None:
            self.range(-8, 8, domain[0])
            self.range(1, 16, domain[1])

    def pick(self, k):  # 0: A, 1: B, 2: NULL
        self.range(0, 3, k)

    def u(self, spec):
        """("lo",), ("hi",), ("in", sixteenths), ("below"|"above", sixteenths),
        ("wild", value)."""
        k = spec[0]
        if k == "lo":
            self.range(0, 4, 0)
        elif k == "hi":
            self.range(0, 4, 1)
        elif k == "in":
            self.range(0, 4, 2)
            self.range(0, 16, spec[1])
        elif k in ("below", "above"):
            self.range(0, 4, 3)
            self.flag(k == "below")
            self.range(1, 64, spec[1])
        else:
            self.range(0, 4, 4)
            self.wild(spec[1])

    def v(self, v):
        if isinstance(v, tuple):  # ("tan", hundredths)
            self.range(0, 4, 1)
            self.range(-150, 150, v[1])
        elif v in (INF, -INF):
            self.range(0, 4, 0)
            self.flag(v > 0)
        elif not math.isnan(v) and v == int(v) and -4 <= v <= 4:
            self.range(0, 4, 3)
            self.range(-4, 4, int(v))
        elif not math.isnan(v) and abs(v) <= 10 and v * 256 == int(v * 256):
            self.range(0, 4, 2)
            self.moderate(v)
        else:
            self.range(0, 4, 4)
            self.wild(v)

    def lam(self, v):
        if v == 0:
            self.range(0, 3, 0)
        elif v in (1, -1):
            self.range(0, 3, 1)
            self.flag(v > 0)
        elif not math.isnan(v) and abs(v) <= 4 and v * 16 == int(v * 16):
            self.range(0, 3, 2)
            self.range(-64, 64, int(v * 16))
        else:
            self.range(0, 3, 3)
            self.wild(v)

    BAD_K = [-1, -2, 8, 100, -2**31, 2**31 - 1]

    def K(self, k):
        bad = not (0 <= k <= 7)
        self.rarely(bad)
        if bad:
            self.range(0, 5, self.BAD_K.index(k))
        else:
            self.range(0, 7, k)

    def derivatives(self, pick, u, v, K, null_out=False):
        self.ops.append(0)
        self.range(0, 63, 0)
        self.pick(pick)
        self.u(u)
        self.v(v)
        self.K(K)
        self.rarely(null_out)

    def end(self, pick, u, vs, lam, phi=None, bad_phi=None):
        """phi: None (all 0) or six eighths in [-2, 2] (phi'', ...);
        bad_phi: None or (index 0..5, NAN or 1e300)."""
        self.pick(pick)
        self.u(u)
        for v in vs:
            self.v(v)
        self.lam(lam)
        self.rarely(phi is not None)
        if phi is not None:
            assert len(phi) == 6
            for p in phi:
                self.range(-16, 16, int(p * 8))
        self.rarely(bad_phi is not None)
        if bad_phi is not None:
            self.range(0, 5, bad_phi[0])
            self.flag(math.isnan(bad_phi[1]))

    def blend(self, canal, start, end, K, t=None, nulls=0, matched=False):
        """start/end: (pick, u, (v0, v1, v2), lambda); end None: identical.
        t: None (0, 1), ("moderate", t0, t1), ("equal", t), ("wild", t0, t1).
        matched: cyc_blend_ringed_matched (op byte 62)."""
        op = 62 if matched else 2 if canal else 1
        self.ops.append(op)
        self.range(0, 63, op)
        self.end(*start)
        self.rarely(end is None)
        if end is not None:
            self.end(*end)
        self.K(K)
        self.interval(t)
        self.rarely(nulls != 0)
        if nulls:
            self.range(1, 3, nulls)

    def interval(self, t):
        """param_t: None (0, 1), ("moderate", t0, t1), ("equal", t), ("wild", t0, t1)."""
        if t is None:
            self.range(0, 3, 0)
        elif t[0] == "moderate":
            self.range(0, 3, 1)
            self.moderate(t[1])
            self.moderate(t[2])
        elif t[0] == "equal":
            self.range(0, 3, 2)
            self.moderate(t[1])
        else:
            self.range(0, 3, 3)
            self.wild(t[1])
            self.wild(t[2])

    # -- op_optimize (cyc_optimize_blend)
    BAD_KIND = [-1, 2, 3, -2**31, 2**31 - 1]
    BAD_QUADRATURE = [0, -1, 17, -2**31, 16]

    def real(self, x):
        """param_real: None keeps the default; else a sixteenth in [0, 4],
        an integer 0..8, 0, a negative sixteenth, 1e300 or wild."""
        self.rarely(x is not None)
        if x is None:
            return
        if not math.isfinite(x) or x == 1e300:
            self.range(0, 5, 4 if x == 1e300 else 5)
            if x != 1e300:
                self.wild(x)
        elif x == 0:
            self.range(0, 5, 2)
        elif x == int(x) and 0 < x <= 8:
            self.range(0, 5, 1)
            self.range(0, 8, int(x))
        elif 0 < x <= 4 and x * 16 == int(x * 16):
            self.range(0, 5, 0)
            self.range(0, 64, int(x * 16))
        elif -4 <= x < 0 and x * 16 == int(x * 16):
            self.range(0, 5, 3)
            self.range(1, 64, int(-x * 16))
        else:
            self.range(0, 5, 5)
            self.wild(x)

    def quadrature(self, q):
        bad = not 1 <= q <= 4
        self.rarely(bad)
        if bad:
            self.range(0, 4, self.BAD_QUADRATURE.index(q))
        else:
            self.range(1, 4, q)

    def count(self, items, null_count=None, negative=None):
        """param_count: the list's length, or a NULL array with null_count
        items, or a negative count (-1 or INT32_MIN)."""
        odd = null_count is not None or negative is not None
        self.rarely(odd)
        if not odd:
            self.range(0, 2, len(items))
        elif negative is not None:
            self.flag(True)
            self.flag(negative == -1)
        else:
            self.flag(False)
            self.range(1, 2, null_count)

    def targets(self, items, **odd):
        """items: (point, t) with t ("frac", sixteenths of [t0, t1]),
        ("moderate", v) or ("wild", v)."""
        self.count(items, **odd)
        if odd:
            return
        for point, t in items:
            for x in point:
                self.coord(x)
            kinds = {"frac": 0, "moderate": 1, "wild": 2}
            self.range(0, 2, kinds[t[0]])
            if t[0] == "frac":
                self.range(0, 16, t[1])
            elif t[0] == "moderate":
                self.moderate(t[1])
            else:
                self.wild(t[1])

    def obstacles(self, items, **odd):
        """items: (center, radius): a sixteenth in [0, 4], 0, a negative
        sixteenth >= -1, or ("wild", v)."""
        self.count(items, **odd)
        if odd:
            return
        for center, r in items:
            for x in center:
                self.coord(x)
            if isinstance(r, tuple):
                self.range(0, 3, 3)
                self.wild(r[1])
            elif r == 0:
                self.range(0, 3, 1)
            elif r > 0:
                self.range(0, 3, 0)
                self.range(0, 64, int(r * 16))
            else:
                self.range(0, 3, 2)
                self.range(1, 16, int(-r * 16))

    OBJECTIVE_REALS = ("fairness", "regularity", "min_determinant", "min_speed",
                       "target_weight", "clearance", "obstacle_weight")
    OPTION_REALS = ("lambda_min_ratio", "lambda_max_ratio", "higher_bound",
                    "function_tolerance", "gradient_tolerance", "parameter_tolerance")

    def objective(self, o):
        """o: None (NULL: the defaults) or a dict: the reals above (missing:
        default), targets / obstacles ((items, odd-kwargs) or items),
        quadrature (qt, qv)."""
        self.rarely(o is None)
        if o is None:
            return
        for name in self.OBJECTIVE_REALS:
            self.real(o.get(name))
        for name in ("targets", "obstacles"):
            spec = o.get(name, [])
            items, odd = spec if isinstance(spec, tuple) else (spec, {})
            getattr(self, name)(items, **odd)
        qt, qv = o.get("quadrature", (2, 2))
        self.quadrature(qt)
        self.quadrature(qv)

    def options(self, p, K):
        """p: None (NULL: the defaults, 50 iterations) or a dict: the reals
        above, free_orders (0..K or a bad value), max_iterations (0..4 or
        -1 / INT32_MIN)."""
        self.rarely(p is None)
        if p is None:
            return
        for name in self.OPTION_REALS:
            self.real(p.get(name))
        f = p.get("free_orders", 0)
        top = max(0, min(K, 7))
        bad = not 0 <= f <= top
        self.rarely(bad)
        if bad:
            self.range(0, 3, [-1, -2**31, 8, min(K, 100) + 1].index(f))
        else:
            self.range(0, top, f)
        it = p.get("max_iterations", 3)
        self.rarely(not 0 <= it <= 4)
        if 0 <= it <= 4:
            self.range(0, 4, it)
        else:
            self.flag(it == -1)

    def optimize(self, kind, start, end, K, t=None, objective=None, options=None, nulls=0):
        """kind: "canal", "ringed" or a BAD_KIND value; start/end as for
        blend; objective / options: see above (the string "null" for NULL);
        nulls: 1 start, 2 end, 3 out, 4 start_out, 5 end_out, 6 summary."""
        self.ops.append(63)
        self.range(0, 63, 63)
        bad = kind not in ("canal", "ringed")
        self.rarely(bad)
        if bad:
            self.range(0, 4, self.BAD_KIND.index(kind))
        else:
            self.flag(kind == "ringed")
        self.end(*start)
        self.rarely(end is None)
        if end is not None:
            self.end(*end)
        self.K(K)
        self.interval(t)
        self.objective(None if objective == "null" else (objective or {}))
        self.options(None if options == "null" else (options or {}), K)
        self.rarely(nulls != 0)
        if nulls:
            self.range(1, 6, nulls)

    def continuity(self, a, b, ua, ub, lam, K, n, va=None, null_out=False):
        """n: ("few", n in 1..8), ("bad", n in -2..0), ("many", 1..64),
        ("min",) INT32_MIN; va None: NULL."""
        self.ops.append(3)
        self.range(0, 63, 3)
        self.pick(a)
        self.pick(b)
        self.u(ua)
        self.u(ub)
        self.lam(lam)
        self.K(K)
        kinds = {"few": 0, "bad": 1, "many": 2, "min": 3}
        self.range(0, 3, kinds[n[0]])
        count = 0
        if n[0] == "few":
            self.range(1, 8, n[1]); count = n[1]
        elif n[0] == "bad":
            self.range(-2, 0, n[1])
        elif n[0] == "many":
            self.range(1, 64, n[1]); count = n[1]
        else:
            self.flag(True)
        self.flag(va is None)
        if va is not None:
            assert len(va) == min(count, 8)
            for v in va:
                self.v(v)
        self.rarely(null_out)

    def finish(self):
        # nops is read before the ops: splice it in after the surfaces.
        return self.data_with_ops()

    def data_with_ops(self):
        body = self.consumed[self.ops_at:]
        head = self.consumed[:self.ops_at]
        self.consumed = head
        assert 1 <= len(self.ops) <= 12
        self.range(1, 12, len(self.ops))
        self.consumed.extend(body)
        return self.data()

    def start_ops(self):
        self.ops_at = len(self.consumed)


def blend_seeds():
    seeds = {}
    G = INF
    # Fig. 6-like cones: ringed K = 1, 2, 3 and canal K = 2, 3 between the
    # upper end circles (lambda chosen by the domain), joins reported.
    e = BlendEncoder([("cone",), ("cone",)])
    e.start_ops()
    vs = (G, -0.5, 0.75)
    for K in (1, 2, 3):
        e.blend(False, (0, ("hi",), vs, 0), (1, ("hi",), vs, 0), K)
    for K in (2, 3):
        e.blend(True, (0, ("hi",), (G, 0.25, 0), 0), (1, ("hi",), (G, 0.25, 0), 0), K)
    e.continuity(0, 1, ("hi",), ("hi",), -1, 2, ("few", 3), va=[G, 0, ("tan", 40)])
    e.derivatives(0, ("in", 8), ("tan", -70), 7)
    e.continuity(0, 0, ("in", 5), ("in", 5), 1, 3, ("many", 32))
    seeds["seed-fig6-cones"] = e.finish()
    # PRRS of three lines / PRCS of two lines (moved apart), explicit lambda.
    l1 = [(0, 0, 0, 1, 0, 0), (0, 1, 0, 0, 1, 1), (0, 0, 1, 1, 1, 0)]
    l2 = [(0, 0, 0, 1, 0.5, 0), (0, 1, 1, 0, 1, -1)]
    e = BlendEncoder([("prrs", l1, (0, 4)), ("prcs", l2, (-2, 6))])
    e.start_ops()
    e.blend(False, (0, ("hi",), (G, 1, -1), 1.5), (1, ("lo",), (G, 0.5, -2), 0.75), 2,
            ("moderate", -1, 2))
    e.blend(True, (1, ("in", 4), (1, -1, 0), -1), (0, ("lo",), (G, 2, 0), 1), 3)
    e.blend(False, (0, ("above", 8), (0, 1, 2), 0), (1, ("below", 3), (-1, 0, 1), 0), 1)
    e.derivatives(1, ("in", 3), G, 4)
    e.continuity(1, 0, ("lo",), ("hi",), 0.5, 1, ("few", 2), va=[1, -G])
    seeds["seed-lines"] = e.finish()
    # PRCS of two cubics, canal and ringed blends into a PRRS.
    c1 = [(0, 0, 0), (1, 0.25, 0), (0, 0.5, 0.125), (0.0625, 0, 0)]
    c2 = [(0, 1, 0.5), (1, -0.125, 0.25), (0.25, 0, 0), (0, 0.125, 0)]
    cubic = [tuple(x for row in c for x in row) for c in (c1, c2)]
    e = BlendEncoder([("cubic", cubic), ("prrs", l1)])
    e.start_ops()
    e.blend(True, (0, ("hi",), (G, 0.5, 0), 0), (1, ("lo",), (G, -0.5, 0), 0), 2)
    e.blend(False, (0, ("hi",), (G, 0.5, -1), 0), (1, ("lo",), (G, -0.5, 1), 0), 3)
    e.derivatives(0, ("in", 16), 0.5, 3)
    seeds["seed-cubics"] = e.finish()
    # Hostile: NULL surfaces / ends / out, u outside / wild, v NaN, lambda
    # NaN / huge, K out of range, t0 >= t1, identical ends, coincident lines,
    # n <= 0, NULL va and outputs.
    e = BlendEncoder([("prcs", [l2[0], l2[0]], None, True), ("cone",)], handler=False)
    e.start_ops()
    cone_end = (1, ("hi",), (G, -0.5, 0.75), 0)
    e.blend(False, (2, ("hi",), (G, 0, 1), 0), cone_end, 1)
    e.blend(False, cone_end, cone_end, 1, nulls=3)
    e.blend(False, cone_end, None, 2)
    e.blend(False, (1, ("lo",), (NAN, 0, 1), 0), cone_end, 1)
    e.blend(True, (1, ("lo",), (G, 0, 1), NAN), cone_end, 2)
    e.blend(True, (1, ("lo",), (G, 0, 1), 1e300), cone_end, 2)
    e.blend(True, (1, ("lo",), (G, 0, 1), 1e60), cone_end, 3)
    e.blend(False, (1, ("wild", 1e101), (G, 0, 1), 0), cone_end, 1)
    e.blend(True, (1, ("lo",), (G, 0, 1), 0), cone_end, 1)
    seeds["seed-hostile-blends"] = e.finish()
    e = BlendEncoder([("cone",), ("prrs", [l1[0], l1[0], l1[1]])])
    e.start_ops()
    cone_end = (0, ("hi",), (G, -0.5, 0.75), 0)
    e.blend(False, (0, ("lo",), (G, 0, 1), 0), cone_end, 8)
    e.blend(False, (0, ("lo",), (G, 0, 1), 0), cone_end, 2, ("equal", 0.5))
    e.blend(False, (0, ("lo",), (G, 0, 1), 0), cone_end, 2, ("wild", 1, -1))
    e.blend(False, (0, ("below", 16), (G, 0, 1), 0), (1, ("hi",), (G, 0, 1), 0), 2)
    # t1 = 2^192 overflows the power-form Hermite curves (the raw input
    # regress-blend-huge-interval decodes differently since ends read phi).
    e.blend(False, (0, ("lo",), (G, 0, 1), 0), cone_end, 2, ("wild", 0, 2.0**192))
    e.derivatives(0, ("wild", NAN), 0, 2)
    e.derivatives(0, ("lo",), -G, -1)
    e.derivatives(0, ("wild", 1e30), 1, 7)
    e.continuity(0, 0, ("lo",), ("hi",), 1e200, 2, ("bad", 0))
    e.continuity(0, 0, ("wild", 1e300), ("hi",), 1, 7, ("few", 1), va=[NAN])
    e.continuity(0, 1, ("lo",), ("hi",), 1e90, 3, ("few", 2))
    e.continuity(2, 0, ("lo",), ("hi",), 1, 3, ("few", 2), null_out=True)
    seeds["seed-hostile-args"] = e.finish()
    # Matched circle parameterizations: the Fig. 6 cones K = 1..3, the
    # lines, and v triples in opposite cyclic orders (refused).
    e = BlendEncoder([("cone",), ("cone",)])
    e.start_ops()
    for K in (1, 2, 3):
        e.blend(False, (0, ("hi",), vs, 0), (1, ("hi",), vs, 0), K, matched=True)
    e.blend(False, (0, ("hi",), (G, -0.5, 0.75), 0), (1, ("hi",), (G, 0.75, -0.5), 0), 1,
            matched=True)
    e.continuity(0, 1, ("hi",), ("hi",), -1, 2, ("few", 3), va=[G, 0, ("tan", 40)])
    seeds["seed-matched-cones"] = e.finish()
    e = BlendEncoder([("prrs", l1, (0, 4)), ("prrs", l1, (-2, 6))])
    e.start_ops()
    e.blend(False, (0, ("hi",), (G, 1, -1), 1.5), (1, ("lo",), (G, 1, -1), 0.75), 2,
            ("moderate", -1, 2), matched=True)
    e.blend(False, (0, ("above", 8), (0, 1, 2), 0), (1, ("below", 3), (-1, 0, 1), 0), 1,
            matched=True)
    seeds["seed-matched-lines"] = e.finish()
    seeds.update(optimize_seeds(l1, l2))
    return seeds


def optimize_seeds(l1, l2):
    """Seeds of op_optimize (cyc_optimize_blend): few iterations, small
    quadratures."""
    seeds = {}
    G = INF
    # Fig. 6 cones: ringed K = 1, 2, 3 and canal K = 2; a target, an
    # obstacle, free_orders 1, 0 iterations, NULL optional outputs.
    e = BlendEncoder([("cone",), ("cone",)])
    e.start_ops()
    vs = (G, -0.5, 0.75)
    ringed = ((0, ("hi",), vs, 0), (1, ("hi",), vs, 0))
    canal = ((0, ("hi",), (G, 0.25, 0), 0), (1, ("hi",), (G, 0.25, 0), 0))
    e.optimize("ringed", *ringed, 1, options={"max_iterations": 4})
    e.optimize("ringed", *ringed, 2, objective={"targets": [((2, 0, 3), ("frac", 8))],
                                                "quadrature": (3, 2)},
               options={"max_iterations": 2, "free_orders": 1})
    e.optimize("canal", *canal, 2, objective={"obstacles": [((2, 0, 2), 0.5)],
                                              "quadrature": (2, 1)}, nulls=4)
    e.optimize("ringed", *ringed, 3, options={"max_iterations": 0}, nulls=6)
    e.continuity(0, 1, ("hi",), ("hi",), -1, 2, ("few", 3), va=[G, 0, ("tan", 40)])
    seeds["seed-optimize-fig6"] = e.finish()
    # Lines: explicit lambdas and phi, a moderate interval, targets and an
    # obstacle with every free order, and a NULL objective (the defaults,
    # 8 x 4 quadrature) without iterations. Each input may spend 60 work
    # units on solves (fuzz_blend.cpp kSolveBudget): these use 56.
    e = BlendEncoder([("prrs", l1, (0, 4)), ("prcs", l2, (-2, 6))])
    e.start_ops()
    e.optimize("ringed", (0, ("hi",), (G, 1, -1), 1.5), (1, ("lo",), (G, 0.5, -2), 0.75), 2,
               t=("moderate", -1, 2), objective={"quadrature": (1, 2)},
               options={"free_orders": 2, "max_iterations": 2})
    e.optimize("canal", (1, ("in", 4), (1, -1, 0), -1, (0.5, -0.25, 0, 0, 0, 0)),
               (0, ("lo",), (G, 2, 0), 1), 3,
               objective={"targets": [((0, 1, 1), ("frac", 4)), ((1, 0, 2), ("moderate", 0.25))],
                          "obstacles": [((0.5, 0.5, 0.5), 0.25)], "clearance": 0.125,
                          "quadrature": (1, 2)},
               options={"free_orders": 3, "max_iterations": 2, "higher_bound": 0.5})
    e.optimize("ringed", (0, ("hi",), (G, 1, -1), 0), (1, ("lo",), (G, 0.5, -2), 0), 2,
               objective="null", options={"max_iterations": 0})
    seeds["seed-optimize-lines"] = e.finish()
    # The defaults: NULL options (50 iterations) on a 1 x 1 quadrature (53
    # units), and NULL objective and options together on validation errors
    # (a solve with both is beyond the budget).
    e = BlendEncoder([("cone",), ("cone",)])
    e.start_ops()
    vs = (G, -0.5, 0.75)
    ringed = ((0, ("hi",), vs, 0), (1, ("hi",), vs, 0))
    e.optimize("ringed", *ringed, 1, objective={"quadrature": (1, 1)}, options="null")
    e.optimize("ringed", *ringed, 0, objective="null", options="null")
    e.optimize("canal", *ringed, 2, t=("equal", 0.5), objective="null", options="null")
    e.optimize("ringed", *ringed, 2, objective="null", options="null", nulls=3)
    seeds["seed-optimize-defaults"] = e.finish()
    # Hostile: each validation error once, NULL pointers, huge (valid) weights.
    e = BlendEncoder([("cone",), ("prrs", l1, (0, 4))], handler=False)
    e.start_ops()
    cone = (0, ("hi",), (G, -0.5, 0.75), 0)
    other = (1, ("lo",), (G, 1, -1), 0)
    e.optimize(2, cone, other, 1)
    e.optimize("canal", cone, other, 1)
    e.optimize("ringed", cone, other, 8)
    e.optimize("ringed", cone, other, 2, objective={"targets": ([], {"null_count": 2}),
                                                    "obstacles": ([], {"negative": -1})})
    e.optimize("ringed", cone, other, 2, objective={"fairness": NAN, "regularity": -0.5,
                                                    "min_determinant": 2, "quadrature": (0, 17)})
    e.optimize("ringed", cone, other, 2, objective={"obstacles": [((0, 0, 0), -0.5)]})
    e.optimize("ringed", cone, other, 2, options={"lambda_min_ratio": 2, "lambda_max_ratio": 0.5})
    e.optimize("ringed", cone, other, 2, options={"free_orders": 3, "max_iterations": -1})
    e.optimize("ringed", (0, ("hi",), (NAN, 0, 1), 0), other, 1, t=("equal", 0.5))
    e.optimize("ringed", cone, other, 1, nulls=3)
    e.optimize("ringed", cone, None, 1, nulls=1)
    e.optimize("ringed", cone, other, 1, objective={"fairness": 1e300, "target_weight": 1e300,
                                                    "targets": [((1, 1, 1), ("moderate", 0.5))]})
    seeds["seed-optimize-hostile"] = e.finish()
    return seeds


# ---------------------------------------------------------------- fuzz_ringed


class RingedEncoder(Encoder):
    """Mirrors fuzz_ringed.cpp: handler flag, ops (create / blend)."""

    def __init__(self, ops, handler=True):
        super().__init__()
        self.flag(handler)
        self.range(1, 8, len(ops))
        for op in ops:
            op(self)

    def curve(self, spec):
        """spec: None (NULL), ("poly", deg, 12 values), ("point", xyz),
        ("element", p, t)."""
        if spec is None:
            self.range(0, 4, 4)
            return
        kind = spec[0]
        code = {"poly": 0, "point": 2, "element": 3}[kind]
        self.range(0, 4, code)
        self.rarely(False)
        vals = list(spec[-1]) if kind != "element" else list(spec[1]) + list(spec[2])
        vals = (vals + [0] * 12)[:12]
        self.fill(vals, 1)
        if kind == "poly":
            self.range(0, 3, spec[1])

    def create(self, d, n, c, domain=None, null_out=False):
        self.flag(False)  # op_create
        self.curve(d)
        self.curve(n)
        self.curve(c)
        self.flag(domain is not None)
        if domain is not None:
            self.range(0, 2, 1)
            self.fill(domain, 1)
        self.rarely(null_out)

    def jet(self, j, rho_abs=True):
        self.rarely(False)
        self.fill(list(j["d"]) + list(j["dd"]) + list(j["n"]) + list(j["dn"]) +
                  [j["rho"], j["drho"]], 1)
        self.flag(rho_abs)

    def blend(self, a, b, sign=1, tau=0.0, v=None, null_options=False, nulls=0):
        self.flag(True)  # op_blend
        self.jet(a)
        self.jet(b)
        self.rarely(null_options)
        if not null_options:
            if sign == 1:
                self.range(0, 3, 0)
            elif sign == -1:
                self.range(0, 3, 1)
            else:
                self.range(0, 3, 2)
                self.range(-3, 3, sign)
            if tau == 0.0:
                self.range(0, 3, 0)
            elif tau * 16 == int(tau * 16) and 0 < tau < 1:
                self.range(0, 3, 1)
                self.range(1, 15, int(tau * 16))
            else:
                self.range(0, 3, 2)
                self.moderate(tau)
            self.flag(v is not None)
            if v is not None:
                self.flag(False)
                self.fill(v, 1)
        self.rarely(nulls != 0)
        if nulls:
            self.range(1, 4, nulls)

    def dnr(self, d, n, rho=(1.5, 0.25, 0), rho_degree=1, den=None, domain=None,
            method=0, v=None, which=0, null_out=False, xdeg=1, x=None, phi=0.25):
        """op_dnr: cyc_ringed_dnr_create then cyc_ringed_pcurve_create.
        method None: NULL options; den (degree, (a, b)) or None."""
        self.range(0, 255, 2)  # op_dnr
        self.curve(d)
        self.curve(n)
        self.range(0, 2, rho_degree)
        self.rarely(False)
        self.fill(rho, 1)
        self.rarely(den is not None)
        self.range(0, 1, den[0] if den else 0)
        self.fill(den[1] if den else (1, 0), 1)
        self.flag(domain is not None)
        if domain is not None:
            self.range(0, 2, 1)
            self.fill(domain, 1)
        self.rarely(method is None)
        if method is not None:
            self.range(-1, 4, method)
            self.flag(v is not None)
            if v is not None:
                self.flag(False)
                self.fill(v, 1)
            self.rarely(False)
            self.range(0, 1, which)
        self.rarely(null_out)
        self.rarely(False)
        self.range(0, 3, xdeg)
        self.rarely(False)
        self.fill(((list(x) if x else [1, 0, 0.5, 0, 0, 1, 0, -1]) + [0] * 16)[:16], 1)
        self.flag(True)
        self.moderate(phi)

    def bump(self, a, b, w=(0, 0, -1), tau=0.5, kind=0, blend_tau=None, null_bump=False):
        """op_bump: cyc_blend_ringed_pcurve_bump; blend_tau None: degree 6,
        "same": the bump's tau, else a sixteenth."""
        self.range(0, 255, 4)  # op_bump
        self.jet(a)
        self.jet(b)
        self.rarely(null_bump)
        self.rarely(False)
        self.fill(w, 1)
        self.flag(True)
        self.range(1, 15, int(tau * 16))
        self.rarely(False)
        self.range(0, 1, kind)
        self.flag(blend_tau is not None)
        if blend_tau is not None:
            self.flag(blend_tau == "same")
            if blend_tau != "same":
                self.range(1, 15, int(blend_tau * 16))

    def bump_optimize(self, a, b, nodes=16, obstacle=None, iters=5, free_tau=True):
        """op_bump_optimize; obstacle (center, radius) or None."""
        self.range(0, 255, 6)  # op_bump_optimize
        self.jet(a)
        self.jet(b)
        self.rarely(False)
        self.range(4, 32, nodes)
        self.flag(True)  # deviance weight 1
        self.fill(obstacle[0] if obstacle else (0, 0, 0), 1)
        self.flag(False)
        self.moderate(obstacle[1] if obstacle else 0)
        self.rarely(False)
        self.range(0, 1, 1 if obstacle else 0)
        self.rarely(False)
        self.flag(True)  # clearance 0
        self.range(0, 8, iters)
        self.flag(free_tau)
        self.rarely(False)
        self.rarely(False)

    def nway(self, ends, center=0, alpha=0, s=(0, 0, 0), r=None, r_fraction=None,
             lambdas=None, side=0, require_disjoint=True, auto_v=True, tau=0.0,
             null_options=False, nulls=0, n=None):
        """op_nway: ends = [(P, T, nvec, rho, end_u_code)]; n overrides
        len(ends) (2 or 9: out of range, the ends beyond len(ends) are
        points at the origin)."""
        n = len(ends) if n is None else n
        self.range(0, 255, 8)  # op_nway
        self.range(2, 9, n)
        for i in range(n):
            P, T, nv, rho, code = ends[i] if i < len(ends) else ((0, 0, 0), (1, 0, 0),
                                                                    (1, 0, 0), 1, 0)
            self.rarely(False)
            self.fill(list(P) + list(T) + list(nv), 1)
            self.moderate(rho)
            self.range(0, 3, code)
        self.rarely(null_options)
        if not null_options:
            self.range(0, 3, center)
            self.moderate(alpha)
            self.fill(s, 1)
            if r is None:
                self.range(0, 2, 0)
            else:
                self.range(0, 2, 1)
                self.moderate(r)
            self.flag(r_fraction is not None)
            if r_fraction is not None:
                self.moderate(r_fraction)
            for i in range(min(n, 8)):
                lam = lambdas[i] if lambdas else 0.5
                self.rarely(False)
                self.range(1, 15, int(lam * 16))
            self.range(0, 2, side)
            self.flag(require_disjoint)
            self.flag(auto_v)
            self.range(0, 2, 0 if tau == 0 else 1)
        self.rarely(nulls > 0)
        if nulls:
            self.range(1, 4, nulls)


def ringed_seeds():
    ex41_a = {"d": (-4, -3, 1), "dd": (2, 4, 3), "n": (1, 1, 1), "dn": (0, 1, 1),
              "rho": 1.25, "drho": 0.5}
    ex41_b = {"d": (0, 0, 0), "dd": (3, 1, 1), "n": (4, 0, 0), "dn": (0, 1, 1),
              "rho": 2, "drho": 1}
    seeds = {}
    # Example 4.1 (seed 001 §4): degree 6, both signs, the P-biarc, another v.
    seeds["seed-example41"] = RingedEncoder([
        lambda e: e.blend(ex41_a, ex41_b),
        lambda e: e.blend(ex41_a, ex41_b, sign=-1),
        lambda e: e.blend(ex41_a, ex41_b, tau=0.5),
        lambda e: e.blend(ex41_a, ex41_b, v=(1, 2, 2)),
    ]).data()
    # Hostile options: sign 0, tau 1.5, n parallel to v, NULLs.
    seeds["seed-hostile-blend"] = RingedEncoder([
        lambda e: e.blend(ex41_a, ex41_b, sign=0),
        lambda e: e.blend(ex41_a, ex41_b, tau=1.5),
        lambda e: e.blend(ex41_a, ex41_b, v=(4, 0, 0)),
        lambda e: e.blend(ex41_a, ex41_b, v=(0, 0, 0)),
        lambda e: e.blend(ex41_a, ex41_b, null_options=True, nulls=3),
    ], handler=False).data()
    # (d, n, c): a cylinder (d = line, n = point, c = line), a cubic
    # directrix, a line element and a NULL curve.
    # (d, n, rho) of seed 001 §3: Example 3.3's quadratic n (AUTO, QUADRATIC
    # with both solutions), the SOS route on a cubic n, projection along a
    # given v (and a failing one), a horizontal n, an unknown method, NULL
    # options, with Prop. 3.1 P-curves after each.
    d1 = ("poly", 1, (0, 0, 0, 1, 2, -1))
    nq = ("poly", 2, (0.5, -1, 3, 0, 2, 1, 1, 0, 0))
    ncub = ("poly", 3, (1, -2, 0.5, 0, 1, 3, 2, 0, -1, 0.5, 1, 0.25))
    nlin = ("poly", 1, (1, 0, 0, 0, 1, 1))
    nhor = ("poly", 2, (1, 0, 0, 0, 1, 0, 1, 1, 0))
    seeds["seed-dnr"] = RingedEncoder([
        lambda e: e.dnr(d1, nq, domain=(-1, 2)),
        lambda e: e.dnr(d1, nq, method=2, which=1),
        lambda e: e.dnr(d1, ncub, method=3, x=(1, 0, 0, 0, 0, 1, 1, 0), phi=1.5),
        lambda e: e.dnr(d1, nlin, method=1, v=(0, 1, 1), xdeg=0, x=(1, 2, 3, 4)),
        lambda e: e.dnr(d1, nlin, method=1, v=(0, 0, 1)),
        lambda e: e.dnr(d1, nhor, method=3, den=(1, (2, 1))),
        lambda e: e.dnr(("point", (1, 2, 3)), ncub, method=4),
        lambda e: e.dnr(d1, ncub, method=None, rho_degree=0, rho=(2, 0, 0)),
    ]).data()
    # §5: Example 4.1's blend with bumps (52) and (57), with the P-biarc at
    # the same and at another tau (refused), and a NULL bump.
    seeds["seed-bump"] = RingedEncoder([
        lambda e: e.bump(ex41_a, ex41_b, w=(0, 0, -6)),
        lambda e: e.bump(ex41_a, ex41_b, w=(1, 2, 0.5), tau=0.25, kind=1),
        lambda e: e.bump(ex41_a, ex41_b, w=(1, 2, 0.5), tau=0.25, kind=1, blend_tau="same"),
        lambda e: e.bump(ex41_a, ex41_b, w=(1, 2, 0.5), tau=0.25, kind=1, blend_tau=0.5),
        lambda e: e.bump(ex41_a, ex41_b, null_bump=True, blend_tau=0.5),
    ]).data()
    # §5.a: the bump optimizer on Example 4.1 (deviance only; with a sphere
    # near the middle circle; tau fixed).
    seeds["seed-bump-optimize"] = RingedEncoder([
        lambda e: e.bump_optimize(ex41_a, ex41_b),
        lambda e: e.bump_optimize(ex41_a, ex41_b, obstacle=((-2, -1, 1.25), 0.5), iters=8),
        lambda e: e.bump_optimize(ex41_a, ex41_b, nodes=8, free_tau=False),
    ]).data()
    # §6, Example 6.2's ends as lines (d_i(1), d_i'(1), n = d'), the sphere
    # (69) with lambda = 3/16 (disjoint circles) and 1/4 (c_1, c_3 meet),
    # the automatic sphere with P-biarcs on the printed side, ends at u = 0
    # and 0.5, n = 2 and NULL pointers.
    ex62 = [((-6, -3, 0), (8, 4, 0), (8, 4, 0), 0.8125, 0),
            ((6, -3, 0), (-8, 4, 0), (-8, 4, 0), 0.5, 0),
            ((0, 5, -5), (0, -4, 4), (0, -4, 4), 0.8125, 0)]
    s69 = (0.5, 0.3, -0.25)
    seeds["seed-nway"] = RingedEncoder([
        lambda e: e.nway(ex62, center=2, s=s69, r=2.6, lambdas=[0.1875] * 3),
        lambda e: e.nway(ex62, center=2, s=s69, r=2.6, lambdas=[0.25] * 3),
        lambda e: e.nway(ex62, lambdas=[0.125] * 3, side=1, tau=0.5),
        lambda e: e.nway([x[:4] + (2,) for x in ex62], center=1, alpha=0.01,
                         lambdas=[0.125] * 3, require_disjoint=False),
        lambda e: e.nway(ex62, n=2),
        lambda e: e.nway(ex62, nulls=3),
    ]).data()
    seeds["seed-create"] = RingedEncoder([
        lambda e: e.create(("poly", 1, (0, 0, 0, 0, 0, 1)), ("point", (0, 0, 1)),
                           ("poly", 1, (1, 0, 0, 0, 0, 1))),
        lambda e: e.create(("poly", 3, (0, 0, 0, 1, 0.5, 0, 0, 0.25, 1, 0, 0, 0.125)),
                           ("poly", 1, (1, 0, 0, 0, 1, 1)),
                           ("poly", 1, (0, -1, 1, 2, -1, 1)), domain=(-1, 1)),
        lambda e: e.create(("poly", 1, (0, 0, 0, 0, 0, 1)), ("element", (0, 0, 0), (0, 0, 1)),
                           ("poly", 1, (1, 0, 0, 0, 0, 1))),
        lambda e: e.create(None, ("point", (0, 0, 1)), ("point", (1, 0, 0))),
        lambda e: e.create(("poly", 1, (0, 0, 0, 0, 0, 1)), ("point", (0, 0, 0)),
                           ("poly", 1, (1, 0, 0, 0, 0, 1))),
    ]).data()
    return seeds


# ---------------------------------------------------------------- fuzz_implicit

class ImplicitEncoder(Encoder):
    """Mirrors fuzz_implicit.cpp: handler flag, the blend (mode 0: Example
    7.6; 1: two cylinders with their perpendicular planes), lambda as k/16,
    n, then the ops."""

    coord = DarbouxEncoder.coord
    coords = DarbouxEncoder.coords

    def __init__(self, blend, lambda16, n, ops, handler=True):
        super().__init__()
        self.flag(handler)
        if blend == "example76":
            self.range(0, 2, 0)
        else:
            self.range(0, 2, 1)
            for point, direction, radius in blend:
                self.coords(point)
                self.coords(direction)
                self.coord(radius)
        self.range(0, 2, 0)
        self.range(1, 15, lambda16)
        self.range(-1, 18, n)
        assert 1 <= len(ops) <= 4
        self.range(1, 4, len(ops))
        for op in ops:
            op(self)

    def eval(self, x, v=None):
        self.range(0, 2, 0)
        self.coords(x)
        self.flag(v is not None)
        if v is not None:
            self.coords(v)

    def contour(self, end, v):
        self.range(0, 2, 1)
        self.range(-1, 2, end)
        self.coords(v)

    def optimize(self, pieces, iters, nodes=4, nt=2, nu=6, v=None, two_curves=False):
        self.range(0, 2, 2)
        self.flag(v is not None)
        if v is not None:
            self.coords(v)
        self.range(0, 3, pieces)
        self.range(0, 3, iters)
        self.range(1, 6, nodes)
        self.range(1, 4, nt)
        self.range(3, 8, nu)
        self.rarely(False)
        self.flag(two_curves)


def implicit_seeds():
    seeds = {}
    seeds["seed-example76"] = ImplicitEncoder("example76", 8, 2, [
        lambda e: e.contour(0, (0, 0, 1)),
        lambda e: e.eval((1, 2, 0.5), (0, 0, 1)),
        lambda e: e.optimize(2, 2),
    ]).data()
    cyl = [((0, 0, 0), (1, 0, 0), 3), ((8, 2, 0), (1, 1, 0), 2)]
    seeds["seed-cylinders"] = ImplicitEncoder(cyl, 8, 2, [
        lambda e: e.contour(1, (0, 1, 0)),
        lambda e: e.optimize(1, 1),
        lambda e: e.optimize(1, 2, two_curves=True),
    ]).data()
    return seeds


# ---------------------------------------------------------------- fuzz_skin

class SkinEncoder(Encoder):
    """Mirrors fuzz_skin.cpp: the allocator mode, the handler flag, the ops
    (op() splices their number in), then the teardown order. The harness
    tracks how many skins exist: pick(i) means skins[i % count]."""

    OPS = {"create": 0, "chain": 1, "eval": 2, "grid": 3, "twist": 4, "lambda": 5,
           "info": 6, "destroy": 7, "nulls": 8}

    def __init__(self, alloc_mode=1, fail_at=0, fail_after=False, handler=True):
        super().__init__()
        self.range(0, 2, alloc_mode)
        if alloc_mode == 2:
            self.range(0, 15, fail_at)
            self.flag(fail_after)
        self.flag(handler)
        self.nops_at = len(self.consumed)
        self.nops = 0

    def finish(self, context_first=False):
        body = self.consumed[self.nops_at:]
        self.consumed = self.consumed[:self.nops_at]
        assert 1 <= self.nops <= 12
        self.range(1, 12, self.nops)
        self.consumed.extend(body)
        self.flag(context_first)
        return self.data()

    def op(self, name):
        self.nops += 1
        self.range(0, 8, self.OPS[name])

    def values(self, vs, style):
        self.fill(vs, style)

    # make_end: ("good", m, R16, d, L4, frac16) | ("raw", style, p, r, t, inv_c)
    # | ("apex", style, p, r, t, c_or_point, nulls) | ("sphere", style, p, R, t,
    # c_or_point, nulls): for apex the apex is p + c t, for sphere the sphere's
    # center is p - c t (a tuple instead of c: the point itself).
    def end(self, spec):
        kind = spec[0]
        if kind == "good":
            _, m, R16, d, L4, frac16 = spec
            self.range(0, 3, 3)
            self.values(m, 1)
            self.range(1, 64, R16)
            self.values(d, 1)
            self.range(1, 40, L4)
            self.range(-15, 15, frac16)
            return
        self.range(0, 3, {"raw": 0, "apex": 1, "sphere": 2}[kind])
        _, style, p, r, t, rest = spec[0], spec[1], spec[2], spec[3], spec[4], spec[5:]
        self.range(0, 2, style)
        inv_c = rest[0] if kind == "raw" else 0.0
        self.values(list(p) + [r] + list(t) + [inv_c], style)
        if kind == "raw":
            return
        c, nulls = rest[0], rest[1] if len(rest) > 1 else None
        if isinstance(c, tuple):
            self.flag(True)
            self.values(c, style)
        else:
            self.flag(False)
            self.values([c], style)
        self.rarely(nulls is not None)
        if nulls is not None:
            self.range(0, 3, nulls)

    # options: None (NULL), "default", (pairing, method) (mode 3) or a dict
    # for mode 2: pairing, method (ints; "min"/"max" for INT_MIN/INT_MAX),
    # tol ("default", exponent 6..14, "zero", ("wild", v), "tiny", "nan"),
    # reference / e: (style, values).
    def options(self, o):
        if o is None:
            self.range(0, 3, 0)
        elif o == "default":
            self.range(0, 3, 1)
        elif isinstance(o, tuple):
            self.range(0, 3, 3)
            self.range(0, 2, o[0])
            self.range(0, 1, o[1])
        else:
            self.range(0, 3, 2)
            for key, lo, hi, nmodes in (("pairing", -1, 3, 5), ("method", -1, 2, 4)):
                v = o.get(key, 0)
                if v in ("min", "max"):
                    self.range(0, nmodes, 1)
                    self.flag(v == "min")
                elif 0 <= v <= hi - 1:
                    self.range(0, nmodes, 2)
                    self.range(0, hi - 1, v)
                else:
                    self.range(0, nmodes, 0)
                    self.range(lo, hi, v)
            tol = o.get("tol", "default")
            if tol == "default":
                self.range(0, 5, 0)
            elif isinstance(tol, int):
                self.range(0, 5, 1)
                self.range(6, 14, tol)
            elif tol == "zero":
                self.range(0, 5, 2)
            elif isinstance(tol, tuple):
                self.range(0, 5, 3)
                self.wild_any(tol[1])
            elif tol == "tiny":
                self.range(0, 5, 4)
            else:
                self.range(0, 5, 5)
            for key in ("reference", "e"):
                v = o.get(key)
                self.flag(v is not None)
                if v is not None:
                    self.range(0, 2, v[0])
                    self.values(v[1], v[0])

    def wild_any(self, v):
        self.wild(v)

    def create(self, a, b, o=None, nulls=None):
        self.op("create")
        self.end(a)
        self.end(b)
        self.options(o)
        self.rarely(nulls is not None)
        if nulls is not None:
            self.range(0, 2, nulls)

    def chain(self, ends, n=None, o=None, null_ends=False, null_out=False, with_bad=True):
        self.op("chain")
        self.range(-1, 6, len(ends) if n is None else n)
        for e in ends:
            self.end(e)
        self.options(o)
        self.rarely(null_ends)
        self.rarely(null_out)
        self.flag(with_bad)

    def pick(self, i):
        self.range(0, 7, i)

    def patch(self, p):
        self.range(-2, 8, {"min": -2, "max": 8}.get(p, p))

    # theta: a number (moderate), ("wild", v), ("pi8", k), or 0 (mode 3)
    def theta(self, v):
        if isinstance(v, tuple) and v[0] == "wild":
            self.range(0, 3, 1)
            self.wild(v[1])
        elif isinstance(v, tuple):
            self.range(0, 3, 2)
            self.range(-16, 16, v[1])
        elif v == 0:
            self.range(0, 3, 3)
        else:
            self.range(0, 3, 0)
            self.moderate(v)

    # t: k/16 as ("16", k), 0.0 / 1.0 (mode 1), a moderate number, ("wild",
    # v), "above1" / "below0"
    def t(self, v):
        if isinstance(v, tuple) and v[0] == "16":
            self.range(0, 4, 0)
            self.range(0, 16, v[1])
        elif isinstance(v, tuple):
            self.range(0, 4, 3)
            self.wild(v[1])
        elif v in ("above1", "below0"):
            self.range(0, 4, 4)
            self.flag(v == "above1")
        elif v in (0.0, 1.0):
            self.range(0, 4, 1)
            self.flag(v == 1.0)
        else:
            self.range(0, 4, 2)
            self.moderate(v)

    def eval(self, i, patch, theta, t, mask=15):
        self.op("eval")
        self.pick(i)
        self.patch(patch)
        self.theta(theta)
        self.t(t)
        self.range(0, 15, mask)

    def grid(self, i, patch, thetas, ts, mask=3, null_theta=False, null_t=False, nth=None,
             nt=None):
        self.op("grid")
        self.pick(i)
        self.patch(patch)
        self.range(-1, 6, len(thetas) if nth is None else nth)
        self.range(-1, 6, len(ts) if nt is None else nt)
        for v in thetas:
            self.theta(v)
        for v in ts:
            self.t(v)
        self.range(0, 3, mask)
        self.rarely(null_theta)
        self.rarely(null_t)

    def twist(self, i, patch, theta, null_out=False):
        self.op("twist")
        self.pick(i)
        self.patch(patch)
        self.theta(theta)
        self.rarely(null_out)

    def lam(self, i, patch, theta, t, with_a=True, null_out=False):
        self.op("lambda")
        self.pick(i)
        self.patch(patch)
        self.theta(theta)
        self.t(t)
        self.flag(with_a)
        self.rarely(null_out)

    def info(self, i, patch, null_out=False):
        self.op("info")
        self.pick(i)
        self.patch(patch)
        self.rarely(null_out)

    def destroy(self, i):
        self.op("destroy")
        self.range(0, 7, i)

    def nulls(self):
        self.op("nulls")


def skin_seeds():
    seeds = {}
    # Two spheres with skew axes (dyadic, as tests/sphere_skin_test.cpp's
    # Skew): unit sphere at 0, circle at x = 3/8, tangent (3, 0, 0); unit
    # sphere at (4, 1, 1/2) with tangent (3, 3/2, 3/2), circle at -1/8 t.
    A = ("sphere", 1, (0.375, 0, 0), 1, (3, 0, 0), 0.125)
    B = ("sphere", 1, (3.625, 0.8125, 0.3125), 1, (3, 1.5, 1.5), -0.125)
    e = SkinEncoder()
    e.create(A, B)
    e.eval(0, 0, ("pi8", 3), 0.0)
    e.eval(0, 0, 0.5, 1.0)
    e.eval(0, 0, -2.25, ("16", 7), mask=9)
    e.grid(0, 0, [0, ("pi8", 4), -1.5], [0.0, ("16", 5), 1.0])
    e.lam(0, 0, 1.25, 1.0)
    e.twist(0, 0, 0.75)
    e.info(0, 0)
    e.create(A, B, (1, 0))
    e.twist(1, 0, 0.75)
    e.create(A, B, (2, 1))
    e.info(2, 0)
    seeds["seed-skew"] = e.finish()

    # A chain of three spheres (tests/sphere_skin_test.cpp's chain, dyadic).
    ends = [("good", (0, 0, 0), 16, (1, 0, 0), 12, -5),
            ("good", (4, 1, 0), 13, (1, 0.5, 0.3), 12, 2),
            ("good", (6, 4, -1), 18, (0.25, 1, -0.375), 12, 5)]
    e = SkinEncoder(handler=False)
    e.chain(ends)
    e.eval(0, 0, 0.5, 1.0)
    e.eval(0, 1, 0.5, 0.0)
    e.grid(0, 1, [0, 1.5, -3], [0.0, ("16", 8)], mask=3)
    e.info(0, 1)
    e.lam(0, 1, 0, 0.0)
    e.chain(ends + [("good", (7, 8, -2), 16, (0.25, 1, -0.25), 12, 4)],
            o={"pairing": 1, "method": 1, "tol": 10})
    e.eval(1, 2, ("pi8", -5), ("16", 11))
    e.destroy(0)
    e.twist(0, 1, 2.5)
    seeds["seed-chain"] = e.finish(context_first=True)

    # The documented errors: nested and equal spheres, kappa r >= 1 (a short
    # tangent), parallel tangents for cross tangents, bad enums, tolerances
    # 0 / NaN / 1e-300, chains with n = -1, 1, NULLs; evaluation with a bad
    # patch, NaN, outside [0, 1].
    short = ("sphere", 1, (3.625, 0.8125, 0.3125), 1, (0.125, 0.0625, 0.0625), -3.0)
    e = SkinEncoder()
    e.create(A, A)
    e.create(A, short)
    e.create(A, ("sphere", 1, (3.625, 0, 0), 1, (3, 0, 0), -0.125), (2, 0))
    e.create(A, B, {"pairing": 3, "method": 0})
    e.create(A, B, {"pairing": "max", "method": -1})
    e.create(A, B, {"tol": "zero"})
    e.create(A, B, {"tol": "nan", "reference": (1, (0, 1, 0))})
    e.create(A, B, {"tol": "tiny"})
    e.chain([A], n=1)
    e.chain([], n=-1)
    e.chain([A, B, A])
    e.nulls()
    seeds["seed-errors"] = e.finish()

    e = SkinEncoder()
    e.create(A, B)
    e.eval(0, 1, 0.5, 0.5)
    e.eval(0, "min", 0.5, 0.5)
    e.eval(0, 0, ("wild", NAN), 0.5)
    e.eval(0, 0, 0.5, ("wild", INF))
    e.eval(0, 0, 0.5, "above1")
    e.grid(0, 0, [0.5, ("wild", 1e300)], [("16", 3), ("wild", 2.0)], mask=2)
    e.grid(0, 0, [], [0.5], nth=-1)
    e.lam(0, 0, 0.5, 0.5, null_out=True)
    e.twist(0, 0, ("wild", -INF))
    e.info(0, "max")
    seeds["seed-eval-errors"] = e.finish()

    # Hostile numbers: NaN, Inf, 1e300, denormals, zero radius and tangent,
    # ends from an apex at the center or off the axis, wild tolerances.
    e = SkinEncoder()
    e.create(("raw", 0, (1e300, 0, 0), 1, (1, 0, 0), 0.5),
             ("raw", 0, (0, 5e-324, 0), 0.0, (0, 0, 0), NAN))
    e.create(("apex", 1, (0, 0, 0), 1, (1, 0, 0), 0.0),
             ("apex", 1, (4, 0, 0), 1, (1, 0, 0), (5, 1, 0)))
    e.create(("apex", 0, (0, 0, 0), 1e100, (1, 0, 0), 1e100),
             ("sphere", 0, (4, 0, 0), INF, (1, 0, 0), 0.5))
    e.create(("raw", 1, (0, 0, 0), 1, (2, 0, 0), -0.5),
             ("raw", 1, (6, 0, 0), 1, (2, 0, 0), 0.5),
             {"tol": ("wild", 1e-320), "method": 1, "e": (0, (NAN, 0, 0))})
    e.create(("raw", 0, (1e99, 1e99, 0), 1, (1e99, 0, 0), 0.0),
             ("raw", 0, (-1e99, -1e99, 0), 1, (-1e99, 0, 0), 0.0))
    e.chain([("apex", 1, (0, 0, 0), 1, (1, 0, 0), 4.0, 2),
             ("raw", 1, (4, 0, 0), 1, (1, 0, 0), 0.0)])
    seeds["seed-hostile"] = e.finish()

    # The grid returned OK with points beyond 1e100 where cyc_sphere_skin_eval
    # says CYC_E_NUMERICAL_OVERFLOW (fixed: the grid checks as eval does).
    e = SkinEncoder()
    e.create(("raw", 0, (0, 0, 0), 1e100, (1e100, 0, 0), 0.0),
             ("raw", 0, (1e100, 0, 0), 1e100, (1e100, 0, 0), 0.0))
    e.grid(0, 0, [0, 1.0], [0.0, 1.0], mask=1)
    e.grid(0, 0, [0, 1.0], [("16", 8), 1.0], mask=3)
    e.eval(0, 0, 0, 1.0, mask=1)
    e.lam(0, 0, 0, 1.0)
    seeds["seed-regress-grid-overflow"] = e.finish()

    # Allocation failures while creating skins and chains.
    for k in (1, 2, 3):
        e = SkinEncoder(alloc_mode=2, fail_at=k, fail_after=(k == 3))
        e.create(A, B)
        e.chain(ends)
        e.eval(0, 0, 0.5, 0.5)
        seeds["seed-alloc-fail-%d" % k] = e.finish()
    return seeds


# ---------------------------------------------------------------- fuzz_lie


class LieEncoder(Encoder):
    """Mirrors fuzz_lie.cpp: the allocator mode, the handler flag, then the
    ops (nops spliced in after the header, like CreateEncoder). Numbers are
    written as fuzz_common.hpp coord() small integers (mode 3) or
    param() sixteenths (mode 0) where possible."""

    def __init__(self, alloc_mode=1, fail_at=0, fail_after=False, handler=True):
        super().__init__()
        self.ops = 0
        self.range(0, 2, alloc_mode)
        if alloc_mode == 2:
            self.range(0, 7, fail_at)
            self.flag(fail_after)
        self.flag(handler)
        self.nops_at = len(self.consumed)

    def finish(self):
        body = self.consumed[self.nops_at:]
        self.consumed = self.consumed[:self.nops_at]
        assert 1 <= self.ops <= 16
        self.range(1, 16, self.ops)
        self.consumed.extend(body)
        return self.data()

    def op(self, code):
        self.ops += 1
        self.range(0, 9, code)

    def coord(self, v):
        if v == int(v) and -4 <= v <= 4:
            self.range(0, 3, 3)
            self.range(-4, 4, int(v))
        else:
            self.range(0, 3, 1)
            self.wild(v)

    def param(self, v):
        assert v * 16 == int(v * 16) and abs(v) <= 4, v
        self.range(0, 3, 0)
        self.range(-64, 64, int(v * 16))

    def sphere(self, m, rho):
        self.range(0, 15, 0)  # CYC_LIE_SPHERE
        for v in list(m) + [rho, 0, 0, 0, 0]:
            self.coord(v)

    def torus_triple(self, R=3, r=1, angles=(0, 2, 4)):
        self.range(0, 3, 1)
        self.coord(R)
        self.coord(r)
        for a in angles:
            self.coord(a)
        for _ in range(3):
            self.flag(True)  # z = 0
            self.flag(True)  # rho = r

    def raw_triple(self, spheres):
        self.range(0, 3, 0)
        for m, rho in spheres:
            self.sphere(m, rho)

    def cyclide(self, triple, how=0):
        self.op(4)
        triple(self)
        self.rarely(False)
        self.range(0, 2, how)

    def operand(self, derive=5, d=0.25):
        # pick(): one cyclide stored, so range(0, 0) consumes nothing.
        self.range(0, 5, derive)
        if derive == 0:  # an offset cyclide at distance d
            self.param(d)

    def eval(self, xi, zeta, offset=None, derive=5):
        self.op(6)
        self.operand(derive)
        self.param(xi)
        self.param(zeta)
        self.flag(offset is None)
        if offset is not None:
            self.param(offset)

    def grid(self, xs, zs, derive=5):
        self.op(7)
        self.operand(derive)
        self.range(0, 5, len(xs))
        self.range(0, 5, len(zs))
        for v in (list(xs) + [0] * 5)[:5]:
            self.param(v)
        for v in (list(zs) + [0] * 5)[:5]:
            self.param(v)
        self.flag(True)      # offset 0
        self.rarely(False)   # points wanted
        self.flag(True)      # normals wanted

    def surface(self, u0=-1, v=0.5):
        self.op(8)
        self.operand()
        self.flag(False)
        self.flag(False)
        self.param(u0)
        self.flag(True)       # u1 = u0 + 1
        self.range(0, 8, 4)
        self.param(v)
        self.flag(True)

    def transform_inversion(self, c, r):
        self.op(1)
        self.range(0, 7, 4)
        for v in c:
            self.coord(v)
        self.coord(r)
        self.flag(True)
        self.sphere((3, 0, 0), 1)


def lie_seeds():
    seeds = {}
    # The torus of tests/lie_capi_test.cpp-like spheres on a circle: build,
    # evaluate, a grid, an offset, swapped families, the surface handle.
    e = LieEncoder()
    e.cyclide(LieEncoder.torus_triple)
    e.eval(0.25, -0.5)
    e.eval(1.5, 2, offset=0.25)
    e.eval(0.5, 0.75, derive=0)
    e.eval(-2, 0.5, derive=1)
    e.grid([0, 0.5, -1, 2], [0, 1, -0.25])
    e.surface()
    seeds["seed-torus"] = e.finish()
    # A cylinder (class I): a point at infinity at xi = 1/2 fails a grid.
    e = LieEncoder()
    e.cyclide(lambda enc: enc.raw_triple([((0, 0, 0), 1), ((0, 0, 1), 1), ((0, 0, 2), 1)]))
    e.grid([0, 0.25, 0.5], [0, 1])
    e.eval(0.5, 0.25)
    seeds["seed-cylinder"] = e.finish()
    # The degenerate cases of sec. 3.1.
    for name, triple in [
            ("pencil", [((0, 0, 1), 1), ((0, 0, 2), 2), ((0, 0, -1), -1)]),
            ("single", [((0, 0, 0), 1), ((3, 0, 0), -2), ((0, 4, 0), 1)]),
            ("equal", [((3, 0, 0), 1), ((3, 0, 0), 1), ((-3, 0, 0), 1)])]:
        e = LieEncoder()
        e.cyclide(lambda enc, t=triple: enc.raw_triple(t))
        seeds["seed-" + name] = e.finish()
    # Transformations, and allocation failure of the surface handle.
    e = LieEncoder()
    e.transform_inversion((1, 2, -1), 2)
    seeds["seed-inversion"] = e.finish()
    e = LieEncoder(alloc_mode=2, fail_at=1)  # 0 is the context
    e.cyclide(LieEncoder.torus_triple)
    e.surface()
    seeds["seed-alloc-fail"] = e.finish()
    return seeds


def write(dirname, seeds):
    path = os.path.join(HERE, "corpus", dirname)
    os.makedirs(path, exist_ok=True)
    for old in os.listdir(path):
        if old.startswith("seed-"):
            os.remove(os.path.join(path, old))
    for name, data in sorted(seeds.items()):
        with open(os.path.join(path, name), "wb") as f:
            f.write(data)
    print(f"{path}: {len(seeds)} seeds")


def write_dictionary():
    """fuzz/dictionaries/cyclide.dict: raw doubles as the harnesses read them
    (Input::wild mode 0: the mode byte is consumed first, then 8 bytes most
    significant first, so the file holds the little-endian double followed
    by the mode byte 0)."""
    values = [
        ("nan", NAN), ("neg_nan", -NAN), ("inf", INF), ("neg_inf", -INF),
        ("max_input", 1e100), ("neg_max_input", -1e100),
        ("above_max_input", 1.0000000000000002e100), ("below_max_input", 9.999999999999999e99),
        ("frame_max", 1e30), ("axis_min", 1e-30), ("dbl_max", 1.7976931348623157e308),
        ("dbl_min", 2.2250738585072014e-308), ("denorm_min", 5e-324), ("tiny", 1e-300),
        ("huge", 1e300), ("neg_zero", -0.0), ("one", 1.0), ("half", 0.5), ("eps", 2.0**-52),
        ("tol_1e-10", 1e-10), ("tol_1e-12", 1e-12), ("big_1e15", 1e15),
    ]
    path = os.path.join(HERE, "dictionaries")
    os.makedirs(path, exist_ok=True)
    lines = ["# Raw doubles as fuzz_common.hpp Input::wild() reads them (written by",
             "# fuzz/make_seeds.py): 8 little-endian bytes, then the mode byte 0."]
    for name, v in values:
        data = struct.pack("<d", v) + b"\x00"
        lines.append('%s="%s"' % (name, "".join("\\x%02x" % b for b in data)))
    with open(os.path.join(path, "cyclide.dict"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"{path}/cyclide.dict: {len(values)} entries")


if __name__ == "__main__":
    write("fuzz_create", create_seeds())
    write("fuzz_eval", eval_seeds())
    write("fuzz_darboux", darboux_seeds())
    write("fuzz_lines", lines_seeds())
    write("fuzz_blend", blend_seeds())
    write("fuzz_ringed", ringed_seeds())
    write("fuzz_implicit", implicit_seeds())
    write("fuzz_skin", skin_seeds())
    write("fuzz_lie", lie_seeds())
    write_dictionary()
