"""cyclide: exact rational circle-family surfaces (ctypes binding of
libcyclide's C ABI, <cyclide/cyclide.h>).

    import cyclide
    with cyclide.Context() as ctx:
        l1 = cyclide.Curve.line(ctx, (0, 0, 0), (1, 0, 0))
        l2 = cyclide.Curve.line(ctx, (0, 0, 1), (2, 1, 0))
        s = cyclide.Surface.prcs(ctx, l1, l2, -0.5, 0.5)
        p = s.eval(0.25, 1.0)              # p.point, p.normal
        g = s.eval_grid(us, vs)            # g.points: shape (len(us) * len(vs), 3)

The library is found through CYCLIDE_LIBRARY, CYCLIDE_LIB_DIR, pkg-config
or ctypes.util.find_library (see _lib.py). Arrays are numpy arrays when
numpy is importable (disable with CYCLIDE_NO_NUMPY=1 or use_numpy(False)),
else tuples and lists of tuples. Failing calls raise cyclide.Error
subclasses with .status and .message.
"""

from . import _lib
from ._array import numpy_available, numpy_enabled, use_numpy
from ._lib import ABI_VERSION, LibraryNotFound
from ._lib import (CYC_SURFACE_PRCS, CYC_SURFACE_PRRS, CYC_SURFACE_RINGED, CYC_SURFACE_DUPIN,
                   CYC_SURFACE_PARABOLIC, CYC_SKIN_RMF, CYC_SKIN_KUNKLI_HOFFMANN,
                   CYC_SKIN_CROSS_TANGENTS, CYC_RMF_REFERENCE, CYC_RMF_DOUBLE_REFLECTION,
                   CYC_DUPIN_DEGENERATE, CYC_DUPIN_PARABOLIC, CYC_DUPIN_QUARTIC,
                   CYC_MESH_OBJ, CYC_MESH_PLY, CYC_MESH_STL, CYC_MESH_GLB, CYC_LIE_SPHERE,
                   CYC_LIE_POINT, CYC_LIE_PLANE, CYC_LIE_POINT_AT_INFINITY)
from .errors import (STATUS, Error, InvalidInputError, NotFiniteError, BadDomainError,
                     GeometryError, NumericalError, ResourceError, BufferTooSmallError,
                     OutOfMemoryError, UnsupportedError, InternalError, ClosedError)
from .errors import IOError_ as FileError
from .errors import *  # noqa: F401,F403  (the CYC_* status constants)
from .core import (Context, Curve, Surface, Mobius, BlendEnd, blend_canal, blend_ringed,
                   blend_ringed_matched, continuity_report, LieSphere, Dupin, live_handles,
                   version, status_name, SurfacePoint, Grid, Circle, Sphere, DupinPoint,
                   Continuity)
from .skin import SkinEnd, SphereSkin, skin_options, SkinInfo
from .export import (tessellation_options, GridMesh, Mesh, tessellate, tessellate_skin,
                     mesh_write, MeshStats, BezierExport, Patch, PatchInfo, Nurbs,
                     SkinExportReport, tau_of_v, v_of_tau)

__version__ = _lib.lib.cyc_version_string().decode()
