"""Loading libcyclide and the ctypes declarations of the C ABI.

Every wrapped C function is declared in FUNCTIONS (name -> (restype,
argtypes)); the completeness test (tests/test_completeness.py) checks that
each of them exists in cyclide.h with the same number and kinds of
parameters, and that the structs below have the header's fields in order.

Library search order:
  1. CYCLIDE_LIBRARY: the full path of the shared library;
  2. CYCLIDE_LIB_DIR: a directory holding libcyclide.so(.ABI);
  3. `pkg-config --variable=libdir cyclide`;
  4. ctypes.util.find_library("cyclide").
The loaded library's ABI version must equal ABI_VERSION.
"""

import ctypes
import ctypes.util
import os
import subprocess
import sys
from ctypes import (CFUNCTYPE, POINTER, Structure, c_char_p, c_double, c_float, c_int,
                    c_size_t, c_void_p)

#: The CYC_ABI_VERSION this binding was written against (= SOVERSION).
ABI_VERSION = 0

# ------------------------------------------------------------------ opaque handles


class cyc_context(Structure):
    pass


class cyc_curve(Structure):
    pass


class cyc_surface(Structure):
    pass


class cyc_sphere_skin(Structure):
    pass


class cyc_bezier_export(Structure):
    pass


P_context = POINTER(cyc_context)
P_curve = POINTER(cyc_curve)
P_surface = POINTER(cyc_surface)
P_skin = POINTER(cyc_sphere_skin)
P_export = POINTER(cyc_bezier_export)
P_double = POINTER(c_double)
P_int = POINTER(c_int)
P_size_t = POINTER(c_size_t)

# ------------------------------------------------------------------ constants

CYC_MAX_CURVE_DEGREE = 15
CYC_MAX_HERMITE_ORDER = 7
CYC_MAX_MOBIUS_DEGREE = 15
CYC_MAX_BLEND_ORDER = 7
CYC_MAX_SPLINE_KNOTS = 16
CYC_MAX_CIRCLE_SEGMENTS = 4096
CYC_MAX_EXPORT_PATCHES = 4096

CYC_SURFACE_PRCS = 1
CYC_SURFACE_PRRS = 2
CYC_SURFACE_RINGED = 3
CYC_SURFACE_DUPIN = 4
CYC_SURFACE_PARABOLIC = 5

CYC_SKIN_RMF = 0
CYC_SKIN_KUNKLI_HOFFMANN = 1
CYC_SKIN_CROSS_TANGENTS = 2
CYC_RMF_REFERENCE = 0
CYC_RMF_DOUBLE_REFLECTION = 1

CYC_LIE_SPHERE = 1
CYC_LIE_POINT = 2
CYC_LIE_PLANE = 3
CYC_LIE_POINT_AT_INFINITY = 4

CYC_DUPIN_DEGENERATE = 1
CYC_DUPIN_PARABOLIC = 2
CYC_DUPIN_QUARTIC = 3

CYC_MESH_OBJ = 0
CYC_MESH_PLY = 1
CYC_MESH_STL = 2
CYC_MESH_GLB = 3

# ------------------------------------------------------------------ frozen structs


def _arr(t, n):
    return t * n


class cyc_sphere(Structure):
    _fields_ = [("center", _arr(c_double, 3)), ("radius2", c_double)]


class cyc_circle(Structure):
    _fields_ = [("center", _arr(c_double, 3)), ("normal", _arr(c_double, 3)),
                ("radius2", c_double)]


class cyc_mobius(Structure):
    _fields_ = [("degree", c_int),
                ("alpha", _arr(c_double, CYC_MAX_MOBIUS_DEGREE + 1)),
                ("beta", _arr(c_double, CYC_MAX_MOBIUS_DEGREE + 1)),
                ("gamma", _arr(c_double, CYC_MAX_MOBIUS_DEGREE + 1)),
                ("delta", _arr(c_double, CYC_MAX_MOBIUS_DEGREE + 1))]


class cyc_buffer3(Structure):
    _fields_ = [("data", P_double), ("capacity", c_size_t), ("stride", c_size_t)]


cyc_alloc_fn = CFUNCTYPE(c_void_p, c_void_p, c_size_t, c_size_t)
cyc_free_fn = CFUNCTYPE(None, c_void_p, c_void_p)


class cyc_allocator(Structure):
    _fields_ = [("alloc", cyc_alloc_fn), ("free", cyc_free_fn), ("userdata", c_void_p)]


cyc_error_handler = CFUNCTYPE(None, c_int, c_char_p, c_void_p)

# ---- blends


class cyc_blend_end(Structure):
    _fields_ = [("surface", P_surface), ("u", c_double), ("v", _arr(c_double, 3)),
                ("lambda", c_double), ("phi", _arr(c_double, CYC_MAX_BLEND_ORDER - 1))]


class cyc_continuity(Structure):
    _fields_ = [("K", c_int), ("samples", c_int), ("singular_samples", c_int),
                ("max_gap", c_double), ("point_scale", c_double),
                ("max_normal_angle", c_double),
                ("point_jump", _arr(c_double, CYC_MAX_BLEND_ORDER + 1)),
                ("point_scale_l", _arr(c_double, CYC_MAX_BLEND_ORDER + 1)),
                ("circle_jump", _arr(c_double, CYC_MAX_BLEND_ORDER + 1))]


# ---- sphere skins


class cyc_skin_end(Structure):
    _fields_ = [("center", _arr(c_double, 3)), ("radius", c_double),
                ("tangent", _arr(c_double, 3)), ("inv_c", c_double)]


class cyc_skin_options(Structure):
    _fields_ = [("pairing", c_int), ("method", c_int), ("tolerance", c_double),
                ("reference", _arr(c_double, 3)), ("e", _arr(c_double, 3))]


class cyc_sphere_skin_info(Structure):
    _fields_ = [("kappa", _arr(c_double, 2)), ("delta", c_double), ("rmf_substeps", c_int),
                ("rmf_error_estimate", c_double), ("spine", _arr(_arr(c_double, 3), 4)),
                ("pairing", c_int), ("method", c_int)]


# ---- Lie sphere geometry, Dupin cyclides


class cyc_lie_sphere(Structure):
    _fields_ = [("kind", c_int), ("m", _arr(c_double, 3)), ("rho", c_double),
                ("n", _arr(c_double, 3)), ("lambda", c_double)]


class cyc_dupin(Structure):
    _fields_ = [("theta", _arr(c_double, 36)), ("type", c_int), ("origin", _arr(c_double, 3)),
                ("unit", c_double)]


class cyc_dupin_point(Structure):
    _fields_ = [("point", _arr(c_double, 3)), ("normal", _arr(c_double, 3)),
                ("lambda", c_double), ("d_xi", _arr(c_double, 3)),
                ("d_zeta", _arr(c_double, 3))]


# ---- export and tessellation


class cyc_tessellation_options(Structure):
    _fields_ = [("chordal_tolerance", c_double), ("min_segments", c_int),
                ("max_segments", c_int), ("fixed_segments", c_int), ("initial_rows", c_int),
                ("reference_u0", P_double), ("reference_u1", P_double)]


class cyc_tessellation_plan(Structure):
    _fields_ = [("rows", c_int), ("segments", c_int), ("phase0", c_double),
                ("phase1", c_double), ("max_radius", c_double), ("depth_limited", c_int)]


class cyc_export_domain(Structure):
    _fields_ = [("u0", c_double), ("u1", c_double), ("v0", c_double), ("v1", c_double),
                ("whole_circle", c_int)]


class cyc_bezier_patch_info(Structure):
    _fields_ = [("deg_u", c_int), ("deg_v", c_int), ("u0", c_double), ("u1", c_double),
                ("v0", c_double), ("v1", c_double), ("reciprocal_v", c_int)]


class cyc_nurbs_size(Structure):
    _fields_ = [("deg_u", c_int), ("deg_v", c_int), ("cp_u", c_int), ("cp_v", c_int),
                ("knots_u", c_int), ("knots_v", c_int)]


class cyc_grid_mesh(Structure):
    _fields_ = [("points", P_double), ("normals", P_double), ("stride", c_size_t),
                ("rows", c_int), ("cols", c_int), ("closed", c_int),
                ("rgba", _arr(c_float, 4))]


class cyc_mesh_write_options(Structure):
    _fields_ = [("weld_tolerance", c_double), ("name", c_char_p)]


class cyc_mesh_stats(Structure):
    _fields_ = [("vertices", c_size_t), ("triangles", c_size_t), ("welded_rows", c_int),
                ("collapsed_rows", c_int), ("coordinate_sum", c_double),
                ("tolerance", c_double)]


class cyc_skin_export_options(Structure):
    _fields_ = [("tolerance", c_double), ("degree", c_int)]


class cyc_skin_export_report(Structure):
    _fields_ = [("error_estimate", c_double), ("rmf_error", c_double), ("exact", c_int),
                ("t_intervals", c_int)]


#: Struct name -> ctypes class (checked against the header's field names).
STRUCTS = {cls.__name__: cls for cls in (
    cyc_sphere, cyc_circle, cyc_mobius, cyc_buffer3, cyc_allocator, cyc_blend_end,
    cyc_continuity, cyc_skin_end, cyc_skin_options, cyc_sphere_skin_info, cyc_lie_sphere,
    cyc_dupin, cyc_dupin_point, cyc_tessellation_options, cyc_tessellation_plan,
    cyc_export_domain, cyc_bezier_patch_info, cyc_nurbs_size, cyc_grid_mesh,
    cyc_mesh_write_options, cyc_mesh_stats, cyc_skin_export_options,
    cyc_skin_export_report)}

# ------------------------------------------------------------------ functions

_I, _D, _Z, _S, _V = c_int, c_double, c_size_t, c_char_p, None
PP_curve = POINTER(P_curve)
PP_surface = POINTER(P_surface)
PP_skin = POINTER(P_skin)
PP_export = POINTER(P_export)
P_lie = POINTER(cyc_lie_sphere)
P_dupin = POINTER(cyc_dupin)
P_topt = POINTER(cyc_tessellation_options)
P_tplan = POINTER(cyc_tessellation_plan)
P_end = POINTER(cyc_blend_end)
P_skin_end = POINTER(cyc_skin_end)
P_skin_opt = POINTER(cyc_skin_options)

#: name -> (restype, [argtypes]) of every C function the binding uses.
FUNCTIONS = {
    # versions
    "cyc_version_number": (_I, []),
    "cyc_version_string": (_S, []),
    "cyc_abi_version": (_I, []),
    "cyc_status_name": (_S, [_I]),
    # context
    "cyc_context_create": (_I, [POINTER(cyc_allocator), POINTER(P_context)]),
    "cyc_context_destroy": (_V, [P_context]),
    "cyc_context_last_error": (_S, [P_context]),
    "cyc_context_last_status": (_I, [P_context]),
    "cyc_context_set_error_handler": (_I, [P_context, cyc_error_handler, c_void_p]),
    # curves
    "cyc_curve_create_polynomial": (_I, [P_context, _I, P_double, _Z, PP_curve]),
    "cyc_curve_create_rational": (_I, [P_context, _I, P_double, _Z, PP_curve]),
    "cyc_curve_create_bezier": (_I, [P_context, _I, P_double, _Z, P_double, _D, _D, PP_curve]),
    "cyc_curve_create_line": (_I, [P_context, P_double, P_double, PP_curve]),
    "cyc_curve_create_point": (_I, [P_context, P_double, PP_curve]),
    "cyc_curve_create_line_element": (_I, [P_context, P_double, P_double, PP_curve]),
    "cyc_curve_create_hermite": (_I, [P_context, _I, _D, _D, P_double, P_double, PP_curve]),
    "cyc_curve_destroy": (_V, [P_context, P_curve]),
    "cyc_curve_degree": (_I, [P_context, P_curve, P_int]),
    "cyc_curve_eval": (_I, [P_context, P_curve, _D, _I, P_double, _Z]),
    # surfaces
    "cyc_prcs_create": (_I, [P_context, P_curve, P_curve, POINTER(cyc_mobius), _D, _D,
                             PP_surface]),
    "cyc_prrs_create": (_I, [P_context, P_curve, P_curve, P_curve, POINTER(cyc_mobius), _D,
                             _D, PP_surface]),
    "cyc_ringed_create": (_I, [P_context, P_curve, P_curve, P_curve, POINTER(cyc_mobius),
                               _D, _D, PP_surface]),
    "cyc_surface_destroy": (_V, [P_context, P_surface]),
    "cyc_surface_kind": (_I, [P_context, P_surface, P_int]),
    "cyc_surface_domain": (_I, [P_context, P_surface, P_double, P_double]),
    "cyc_surface_eval": (_I, [P_context, P_surface, _D, _D, P_double, P_double, P_double,
                              P_double]),
    "cyc_surface_eval_batch": (_I, [P_context, P_surface, P_double, _Z, _Z, cyc_buffer3,
                                    cyc_buffer3, cyc_buffer3, cyc_buffer3, P_size_t]),
    "cyc_surface_eval_grid": (_I, [P_context, P_surface, P_double, _Z, P_double, _Z,
                                   cyc_buffer3, cyc_buffer3, cyc_buffer3, cyc_buffer3,
                                   P_size_t]),
    "cyc_surface_circle": (_I, [P_context, P_surface, _D, POINTER(cyc_circle)]),
    "cyc_surface_sphere": (_I, [P_context, P_surface, _D, POINTER(cyc_sphere)]),
    "cyc_surface_ringed_data": (_I, [P_context, P_surface, _D, P_double, P_double, P_double,
                                     P_double]),
    "cyc_surface_canal_test": (_I, [P_context, P_surface, _D, P_double, P_int]),
    "cyc_surface_parameter_of": (_I, [P_context, P_surface, _D, P_double, P_double]),
    # blends
    "cyc_surface_derivatives_u": (_I, [P_context, P_surface, _D, _D, _I, P_double]),
    "cyc_blend_canal": (_I, [P_context, P_end, P_end, _I, _D, _D, PP_surface]),
    "cyc_blend_ringed": (_I, [P_context, P_end, P_end, _I, _D, _D, PP_surface]),
    "cyc_blend_ringed_matched": (_I, [P_context, P_end, P_end, _I, _D, _D, PP_surface]),
    "cyc_continuity_report": (_I, [P_context, P_surface, _D, _D, P_surface, _D, _I, P_double,
                                   _I, POINTER(cyc_continuity)]),
    # sphere skins
    "cyc_skin_end_from_apex": (_I, [P_context, P_double, _D, P_double, P_double, P_skin_end]),
    "cyc_skin_end_from_sphere": (_I, [P_context, P_double, _D, P_double, P_double,
                                      P_skin_end]),
    "cyc_skin_end_sphere": (_V, [P_skin_end, P_double, P_double]),
    "cyc_skin_options_init": (_V, [P_skin_opt]),
    "cyc_sphere_skin_create": (_I, [P_context, P_skin_end, P_skin_end, P_skin_opt, PP_skin]),
    "cyc_sphere_skin_chain_create": (_I, [P_context, P_skin_end, _I, P_skin_opt, PP_skin,
                                          P_int]),
    "cyc_sphere_skin_destroy": (_V, [P_context, P_skin]),
    "cyc_sphere_skin_patch_count": (_I, [P_context, P_skin, P_int]),
    "cyc_sphere_skin_eval": (_I, [P_context, P_skin, _I, _D, _D, P_double, P_double,
                                  P_double, P_double]),
    "cyc_sphere_skin_eval_grid": (_I, [P_context, P_skin, _I, P_double, _I, P_double, _I,
                                       P_double, P_double, P_size_t]),
    "cyc_sphere_skin_info_get": (_I, [P_context, P_skin, _I, POINTER(cyc_sphere_skin_info)]),
    "cyc_sphere_skin_twist": (_I, [P_context, P_skin, _I, _D, P_double]),
    "cyc_sphere_skin_lambda": (_I, [P_context, P_skin, _I, _D, _D, P_double, P_double]),
    "cyc_sphere_skin_tessellation_workspace_size": (_Z, [_I]),
    "cyc_sphere_skin_tessellate_plan": (_I, [P_context, P_skin, _I, P_topt, P_double, _I,
                                             c_void_p, _Z, P_tplan]),
    "cyc_sphere_skin_tessellate_eval": (_I, [P_context, P_skin, _I, P_tplan, P_double,
                                             cyc_buffer3, cyc_buffer3, P_size_t]),
    # Lie sphere geometry and Dupin cyclides
    "cyc_lie_vector": (_I, [P_context, P_lie, P_double]),
    "cyc_dupin_classify_spheres": (_I, [P_context, P_lie, P_int]),
    "cyc_dupin_from_spheres": (_I, [P_context, P_lie, P_dupin]),
    "cyc_dupin_swap_families": (_I, [P_context, P_dupin, P_dupin]),
    "cyc_dupin_offset": (_I, [P_context, P_dupin, _D, P_dupin]),
    "cyc_dupin_eval": (_I, [P_context, P_dupin, _D, _D, _D, POINTER(cyc_dupin_point)]),
    "cyc_dupin_sphere": (_I, [P_context, P_dupin, _I, P_double, P_lie]),
    "cyc_dupin_eval_grid": (_I, [P_context, P_dupin, P_double, _Z, P_double, _Z, _D,
                                 P_double, P_double]),
    "cyc_dupin_surface_create": (_I, [P_context, P_dupin, P_double, P_double, _D, _D,
                                      PP_surface]),
    # tessellation
    "cyc_tessellation_options_default": (_V, [P_topt]),
    "cyc_tessellation_workspace_size": (_Z, [_I]),
    "cyc_tessellate_plan": (_I, [P_context, P_surface, P_topt, P_double, _I, c_void_p, _Z,
                                 P_tplan]),
    "cyc_tessellate_eval": (_I, [P_context, P_surface, P_tplan, P_double, cyc_buffer3,
                                 cyc_buffer3, P_size_t]),
    # exact export
    "cyc_bezier_export_create": (_I, [P_context, P_surface, POINTER(cyc_export_domain),
                                      PP_export]),
    "cyc_bezier_export_destroy": (_V, [P_export]),
    "cyc_bezier_export_count": (_I, [P_export]),
    "cyc_bezier_export_patch": (_I, [P_context, P_export, _I, POINTER(cyc_bezier_patch_info),
                                     P_double, _Z]),
    "cyc_bezier_export_eval": (_I, [P_context, P_export, _I, _D, _D, P_double, P_double]),
    "cyc_bezier_export_nurbs": (_I, [P_context, P_export, POINTER(cyc_nurbs_size), P_double,
                                     _Z, P_double, _Z, P_double, _Z]),
    "cyc_export_tau_of_v": (_D, [_D]),
    "cyc_export_v_of_tau": (_D, [_D]),
    "cyc_bezier_export_write_json": (_I, [P_context, P_export, _S]),
    "cyc_skin_export_options_default": (_V, [POINTER(cyc_skin_export_options)]),
    "cyc_sphere_skin_export_create": (_I, [P_context, P_skin, POINTER(cyc_export_domain),
                                           POINTER(cyc_skin_export_options), PP_export,
                                           POINTER(cyc_skin_export_report)]),
    # writers
    "cyc_mesh_write": (_I, [P_context, _S, _I, POINTER(cyc_grid_mesh), _I,
                            POINTER(cyc_mesh_write_options), POINTER(cyc_mesh_stats)]),
}


class LibraryNotFound(ImportError):
    """libcyclide could not be found or does not match this binding."""


def _candidates():
    """(description, path) pairs in the documented search order."""
    names = ["libcyclide.so", "libcyclide.so.%d" % ABI_VERSION]
    if sys.platform == "darwin":
        names = ["libcyclide.dylib", "libcyclide.%d.dylib" % ABI_VERSION]
    elif os.name == "nt":
        names = ["cyclide.dll", "libcyclide.dll"]
    path = os.environ.get("CYCLIDE_LIBRARY")
    if path:
        yield "CYCLIDE_LIBRARY", path
        return  # an explicit path is final: never silently load another one
    libdir = os.environ.get("CYCLIDE_LIB_DIR")
    if libdir:
        for n in names:
            yield "CYCLIDE_LIB_DIR", os.path.join(libdir, n)
        return
    try:
        out = subprocess.run(["pkg-config", "--variable=libdir", "cyclide"],
                             capture_output=True, text=True, timeout=20)
        libdir = out.stdout.strip() if out.returncode == 0 else ""
    except (OSError, subprocess.SubprocessError):
        libdir = ""
    if libdir:
        for n in names:
            yield "pkg-config", os.path.join(libdir, n)
    found = ctypes.util.find_library("cyclide")
    if found:
        yield "find_library", found


def _load():
    tried = []
    for how, path in _candidates():
        if how != "find_library" and not os.path.exists(path):
            tried.append("%s: %s (missing)" % (how, path))
            continue
        try:
            lib = ctypes.CDLL(path)
        except OSError as exc:
            tried.append("%s: %s (%s)" % (how, path, exc))
            continue
        return lib, path
    raise LibraryNotFound("libcyclide not found; set CYCLIDE_LIBRARY or CYCLIDE_LIB_DIR. Tried:\n  "
                          + "\n  ".join(tried or ["nothing"]))


def _declare(lib):
    for name, (restype, argtypes) in FUNCTIONS.items():
        try:
            f = getattr(lib, name)
        except AttributeError:
            raise LibraryNotFound("libcyclide at %s lacks %s (too old for this binding)"
                                  % (lib_path, name)) from None
        f.restype = restype
        f.argtypes = list(argtypes)


lib, lib_path = _load()
_declare(lib)
if lib.cyc_abi_version() != ABI_VERSION:
    raise LibraryNotFound("libcyclide at %s has ABI %d; this binding needs ABI %d"
                          % (lib_path, lib.cyc_abi_version(), ABI_VERSION))
