"""Arrays in and out: numpy when available, else lists and tuples.

numpy is used when it imports and neither CYCLIDE_NO_NUMPY=1 is set in the
environment nor cyclide.use_numpy(False) was called. Inputs may be anything
float64-convertible (arrays of any dtype or layout, nested sequences,
scalars); C-contiguous float64 copies are made only when needed. Outputs
are numpy arrays (vectors of shape (3,), point sets of shape (n, 3)) or,
without numpy, tuples (vectors) and lists of tuples (point sets).
"""

import ctypes
import math
import os
from ctypes import POINTER, c_double

try:
    if os.environ.get("CYCLIDE_NO_NUMPY", "") not in ("", "0"):
        raise ImportError("CYCLIDE_NO_NUMPY is set")
    import numpy as _np
except ImportError:
    _np = None

_state = {"numpy": _np is not None}
P_double = POINTER(c_double)


def numpy_available():
    """True if numpy could be imported (and was not disabled by the env)."""
    return _np is not None


def numpy_enabled():
    """True if outputs are numpy arrays."""
    return _state["numpy"]


def use_numpy(flag=True):
    """Turn numpy arrays on or off (off: lists and tuples). Returns the
    previous setting. Raises ImportError when asked for numpy without it."""
    prev = _state["numpy"]
    if flag and _np is None:
        raise ImportError("numpy is not available")
    _state["numpy"] = bool(flag)
    return prev


class DoubleArray:
    """A C double array for input: .ptr (POINTER(c_double)), .size, .shape;
    keeps its storage alive."""

    __slots__ = ("ptr", "size", "shape", "_keep")

    def __init__(self, ptr, size, shape, keep):
        self.ptr, self.size, self.shape, self._keep = ptr, size, shape, keep


def _flatten(x, out):
    if isinstance(x, (int, float)):
        out.append(float(x))
        return ()
    try:
        items = list(x)
    except TypeError:
        out.append(float(x))
        return ()
    shapes = [_flatten(i, out) for i in items]
    inner = shapes[0] if shapes else ()
    if any(s != inner for s in shapes):
        raise ValueError("ragged input: rows of different shapes")
    return (len(items),) + inner


def as_doubles(x, shape=None, name="array"):
    """x as contiguous float64 storage. shape: an expected shape where -1
    stands for any length (e.g. (-1, 3)); a flat input of the right total
    size is accepted for (-1, k) too."""
    if _state["numpy"] and _np is not None:
        a = _np.ascontiguousarray(_np.asarray(x, dtype=_np.float64))
        shp = a.shape
        if shape is not None:
            shp = _check_shape(shp, shape, name)
            a = a.reshape(shp)
        return DoubleArray(a.ctypes.data_as(P_double), a.size, shp, a)
    flat = []
    shp = _flatten(x, flat)
    if shape is not None:
        shp = _check_shape(shp, shape, name)
    buf = (c_double * max(len(flat), 1))(*flat)
    return DoubleArray(ctypes.cast(buf, P_double), len(flat), shp, buf)


def _check_shape(shp, want, name):
    size = 1
    for s in shp:
        size *= s
    fixed = 1
    for w in want:
        if w != -1:
            fixed *= w
    if len(shp) == len(want) and all(w in (-1, s) for s, w in zip(shp, want)):
        return tuple(shp)
    # accept flat input (or a single vector for (-1, k)) with the right size
    if want.count(-1) == 1 and fixed and size % fixed == 0 and len(shp) <= 1:
        return tuple(size // fixed if w == -1 else w for w in want)
    if -1 not in want and size == fixed:
        return tuple(want)
    raise ValueError("%s: shape %s does not match %s" % (name, tuple(shp), tuple(want)))


def vec3(x, name="vector"):
    """Three finite-or-not doubles as a ctypes array (no checks beyond the
    length: the library reports non-finite values)."""
    vals = [float(v) for v in (x.tolist() if hasattr(x, "tolist") else x)]
    if len(vals) != 3:
        raise ValueError("%s: expected 3 numbers, got %d" % (name, len(vals)))
    return (c_double * 3)(*vals)


class OutArray:
    """Output storage of n rows of k doubles (or a flat shape)."""

    __slots__ = ("shape", "size", "ptr", "_buf")

    def __init__(self, shape):
        self.shape = tuple(shape)
        size = 1
        for s in self.shape:
            size *= s
        self.size = size
        if _state["numpy"] and _np is not None:
            self._buf = _np.zeros(self.shape, dtype=_np.float64)
            self.ptr = self._buf.ctypes.data_as(P_double)
        else:
            self._buf = (c_double * max(size, 1))()
            self.ptr = ctypes.cast(self._buf, P_double)

    def result(self):
        """numpy array of the shape, or nested lists with tuples innermost."""
        if _state["numpy"] and _np is not None and not isinstance(self._buf, ctypes.Array):
            return self._buf
        flat = list(self._buf[:self.size])
        return nest(flat, self.shape)


def nest(flat, shape):
    if len(shape) <= 1:
        return tuple(flat)
    step = len(flat) // shape[0] if shape[0] else 0
    return [nest(flat[i * step:(i + 1) * step], shape[1:]) for i in range(shape[0])]


def out_vec(carray):
    """A ctypes double array as a numpy vector or a tuple."""
    vals = list(carray)
    if _state["numpy"] and _np is not None:
        return _np.array(vals, dtype=_np.float64)
    return tuple(vals)


def out_list(vals):
    """A flat list of numbers as a numpy vector or a tuple."""
    if _state["numpy"] and _np is not None:
        return _np.array(list(vals), dtype=_np.float64)
    return tuple(float(v) for v in vals)


def norm(v):
    return math.sqrt(sum(float(c) * float(c) for c in v))
