"""Status codes of cyclide_errors.h and the exceptions raised for them.

Every failing C call raises an Error subclass chosen by the status family
(1-99 invalid input, 100-199 degenerate geometry, 200-299 numerical,
300-399 resources, 400-499 unsupported / internal), with the context's last
error message. The numbers are frozen in the C ABI; the completeness test
checks STATUS against cyclide_errors.h.
"""

#: name -> value, as in cyclide_errors.h (frozen numbers).
STATUS = {
    "CYC_OK": 0,
    "CYC_E_NULL_ARGUMENT": 1,
    "CYC_E_INVALID_ARGUMENT": 2,
    "CYC_E_NOT_FINITE": 3,
    "CYC_E_DEGREE_TOO_HIGH": 4,
    "CYC_E_BAD_DOMAIN": 5,
    "CYC_E_DEPENDENT_PLANES": 100,
    "CYC_E_ZERO_TANGENT": 101,
    "CYC_E_COLLINEAR_POINTS": 102,
    "CYC_E_DEGENERATE_CIRCLE_PARAMETER": 103,
    "CYC_E_NOT_CANAL": 104,
    "CYC_E_SINGULAR_POINT": 105,
    "CYC_E_DEGENERATE_RINGED": 106,
    "CYC_E_PARALLEL_LINES": 107,
    "CYC_E_NO_COMMON_NORMAL": 108,
    "CYC_E_RANK_DEFICIENT": 109,
    "CYC_E_AT_INVERSION_CENTER": 110,
    "CYC_E_NOT_PARABOLIC": 111,
    "CYC_E_EMPTY_REAL_LOCUS": 112,
    "CYC_E_TOO_FEW_LINES": 113,
    "CYC_E_NO_NORMAL_FORM": 114,
    "CYC_E_NOT_PYTHAGOREAN": 115,
    "CYC_E_INTERSECTING_CIRCLES": 116,
    "CYC_E_NESTED_SPHERES": 117,
    "CYC_E_CURVATURE_RADIUS_TOO_LARGE": 118,
    "CYC_E_SPHERE_PENCIL": 119,
    "CYC_E_NO_TOUCHING_SPHERE": 120,
    "CYC_E_SINGLE_TOUCHING_SPHERE": 121,
    "CYC_E_DEGENERATE_CYCLIDE": 122,
    "CYC_E_NOT_ISOMETRIC": 123,
    "CYC_E_NOT_ON_LIE_QUADRIC": 124,
    "CYC_E_POINT_AT_INFINITY": 125,
    "CYC_E_TANGENT_GENERATING_SPHERES": 126,
    "CYC_E_BLEND_FOLDS": 127,
    "CYC_E_DEVELOPABLE": 128,
    "CYC_E_POLE_IN_GAUSS_IMAGE": 129,
    "CYC_E_RIDGE": 130,
    "CYC_E_NUMERICAL_OVERFLOW": 200,
    "CYC_E_BUFFER_TOO_SMALL": 300,
    "CYC_E_OUT_OF_MEMORY": 301,
    "CYC_E_IO": 302,
    "CYC_E_UNSUPPORTED": 400,
    "CYC_E_INTERNAL": 401,
}
STATUS_NAMES = {v: k for k, v in STATUS.items()}
globals().update(STATUS)  # CYC_OK, CYC_E_NOT_FINITE, ... as module constants


class Error(Exception):
    """A cyclide call failed: .status (the C status code), .name
    ("CYC_E_..."), .message (the context's last error), .function."""

    def __init__(self, status, message="", function=None):
        self.status = int(status)
        self.name = STATUS_NAMES.get(self.status, "CYC_E_UNKNOWN")
        self.message = message
        self.function = function
        where = "%s: " % function if function else ""
        super().__init__("%s%s (%d): %s" % (where, self.name, self.status, message))


class InvalidInputError(Error, ValueError):
    """Statuses 1-99: a NULL, out-of-range, non-finite or too-high input."""


class NotFiniteError(InvalidInputError):
    """CYC_E_NOT_FINITE: NaN, Inf or |x| > 1e100 in an input."""


class BadDomainError(InvalidInputError):
    """CYC_E_BAD_DOMAIN: a parameter interval empty or reversed, or outside."""


class GeometryError(Error):
    """Statuses 100-199: degenerate geometry for the construction."""


class NumericalError(Error, ArithmeticError):
    """Statuses 200-299: values beyond the supported range."""


class ResourceError(Error):
    """Statuses 300-399: buffers, memory, files."""


class BufferTooSmallError(ResourceError):
    """CYC_E_BUFFER_TOO_SMALL."""


class OutOfMemoryError(ResourceError, MemoryError):
    """CYC_E_OUT_OF_MEMORY."""


class IOError_(ResourceError, OSError):
    """CYC_E_IO: a file could not be written."""

    def __init__(self, status, message="", function=None):
        ResourceError.__init__(self, status, message, function)


class UnsupportedError(Error, NotImplementedError):
    """Statuses 400-499 but CYC_E_INTERNAL: not in this build."""


class InternalError(Error, RuntimeError):
    """CYC_E_INTERNAL: a bug in cyclide."""


class ClosedError(InvalidInputError):
    """A method was called on a closed handle or with a closed context
    (reported as CYC_E_NULL_ARGUMENT without calling the library)."""


_SPECIFIC = {3: NotFiniteError, 5: BadDomainError, 300: BufferTooSmallError,
             301: OutOfMemoryError, 302: IOError_, 401: InternalError}


def error_class(status):
    """The exception class for a status code."""
    status = int(status)
    if status in _SPECIFIC:
        return _SPECIFIC[status]
    if 1 <= status <= 99:
        return InvalidInputError
    if 100 <= status <= 199:
        return GeometryError
    if 200 <= status <= 299:
        return NumericalError
    if 300 <= status <= 399:
        return ResourceError
    if 400 <= status <= 499:
        return UnsupportedError
    return Error


def make_error(status, message="", function=None):
    return error_class(status)(status, message, function)
