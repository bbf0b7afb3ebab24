//! Raw, hand-written FFI declarations of the cyclide C ABI
//! (`<cyclide/cyclide.h>` and `<cyclide/cyclide_errors.h>`).
//!
//! Every `CYC_API` function of the header is declared in the `extern "C"`
//! block below with the C names and types; every `typedef struct` is a
//! `#[repr(C)]` struct with the same fields in the same order; the enums and
//! `#define` constants are `c_int` constants; the opaque handles are empty
//! `#[repr(C)]` structs with a `PhantomData` marker (not `Send`, `Sync` or
//! `Unpin`: the safe crate `cyclide` decides what may cross threads).
//!
//! No bindgen: `bindings/rust/check_sys.py` fails when a function, struct or
//! constant of the header is missing here (or here and not in the header),
//! and the layout test (`tests/layout.rs`) compares `size_of`, `align_of`
//! and every field offset with what the C compiler says for the installed
//! header. The conventions (statuses, contexts, ownership) are those of the
//! header and SPEC.md section 9; see the header for each function's
//! contract. Link: `build.rs` (`CYCLIDE_LIB_DIR` or `pkg-config cyclide`).

#![allow(non_camel_case_types, non_snake_case)]

use std::marker::{PhantomData, PhantomPinned};
use std::os::raw::{c_char, c_int, c_void};

// ------------------------------------------------------------ versions
// The header version this crate was written against (cyclide_version.h).
pub const CYC_VERSION_MAJOR: c_int = 0;
pub const CYC_VERSION_MINOR: c_int = 1;
pub const CYC_VERSION_PATCH: c_int = 0;
pub const CYC_VERSION_NUMBER: c_int =
    CYC_VERSION_MAJOR * 10000 + CYC_VERSION_MINOR * 100 + CYC_VERSION_PATCH;
pub const CYC_VERSION_STRING: &str = "0.1.0";
pub const CYC_ABI_VERSION: c_int = 0;

// ------------------------------------------------------------ statuses and enums
// enum cyc_status
pub const CYC_OK: c_int = 0;
pub const CYC_E_NULL_ARGUMENT: c_int = 1;
pub const CYC_E_INVALID_ARGUMENT: c_int = 2;
pub const CYC_E_NOT_FINITE: c_int = 3;
pub const CYC_E_DEGREE_TOO_HIGH: c_int = 4;
pub const CYC_E_BAD_DOMAIN: c_int = 5;
pub const CYC_E_DEPENDENT_PLANES: c_int = 100;
pub const CYC_E_ZERO_TANGENT: c_int = 101;
pub const CYC_E_COLLINEAR_POINTS: c_int = 102;
pub const CYC_E_DEGENERATE_CIRCLE_PARAMETER: c_int = 103;
pub const CYC_E_NOT_CANAL: c_int = 104;
pub const CYC_E_SINGULAR_POINT: c_int = 105;
pub const CYC_E_DEGENERATE_RINGED: c_int = 106;
pub const CYC_E_PARALLEL_LINES: c_int = 107;
pub const CYC_E_NO_COMMON_NORMAL: c_int = 108;
pub const CYC_E_RANK_DEFICIENT: c_int = 109;
pub const CYC_E_AT_INVERSION_CENTER: c_int = 110;
pub const CYC_E_NOT_PARABOLIC: c_int = 111;
pub const CYC_E_EMPTY_REAL_LOCUS: c_int = 112;
pub const CYC_E_TOO_FEW_LINES: c_int = 113;
pub const CYC_E_NO_NORMAL_FORM: c_int = 114;
pub const CYC_E_NOT_PYTHAGOREAN: c_int = 115;
pub const CYC_E_INTERSECTING_CIRCLES: c_int = 116;
pub const CYC_E_NESTED_SPHERES: c_int = 117;
pub const CYC_E_CURVATURE_RADIUS_TOO_LARGE: c_int = 118;
pub const CYC_E_SPHERE_PENCIL: c_int = 119;
pub const CYC_E_NO_TOUCHING_SPHERE: c_int = 120;
pub const CYC_E_SINGLE_TOUCHING_SPHERE: c_int = 121;
pub const CYC_E_DEGENERATE_CYCLIDE: c_int = 122;
pub const CYC_E_NOT_ISOMETRIC: c_int = 123;
pub const CYC_E_NOT_ON_LIE_QUADRIC: c_int = 124;
pub const CYC_E_POINT_AT_INFINITY: c_int = 125;
pub const CYC_E_TANGENT_GENERATING_SPHERES: c_int = 126;
pub const CYC_E_BLEND_FOLDS: c_int = 127;
pub const CYC_E_DEVELOPABLE: c_int = 128;
pub const CYC_E_POLE_IN_GAUSS_IMAGE: c_int = 129;
pub const CYC_E_RIDGE: c_int = 130;
pub const CYC_E_NUMERICAL_OVERFLOW: c_int = 200;
pub const CYC_E_BUFFER_TOO_SMALL: c_int = 300;
pub const CYC_E_OUT_OF_MEMORY: c_int = 301;
pub const CYC_E_IO: c_int = 302;
pub const CYC_E_UNSUPPORTED: c_int = 400;
pub const CYC_E_INTERNAL: c_int = 401;
// enum cyc_darboux_type
pub const CYC_DARBOUX_ZERO: c_int = 0;
pub const CYC_DARBOUX_QUARTIC: c_int = 1;
pub const CYC_DARBOUX_PARABOLIC: c_int = 2;
pub const CYC_DARBOUX_QUADRIC: c_int = 3;
pub const CYC_DARBOUX_PLANE: c_int = 4;
pub const CYC_DARBOUX_CONSTANT: c_int = 5;
pub const CYC_DARBOUX_REDUCIBLE: c_int = 6;
// enum cyc_section_kind
pub const CYC_SECTION_LINE_PAIR: c_int = 1;
pub const CYC_SECTION_DOUBLE_LINE: c_int = 2;
pub const CYC_SECTION_IMAGINARY_PAIR: c_int = 3;
pub const CYC_SECTION_LINE_AND_L0: c_int = 4;
// enum cyc_cyclide_kind
pub const CYC_CYCLIDE_HYPERBOLOID: c_int = 1;
pub const CYC_CYCLIDE_PARABOLIC_DARBOUX: c_int = 2;
pub const CYC_CYCLIDE_PARABOLIC_DUPIN: c_int = 3;
// enum cyc_mesh_format
pub const CYC_MESH_OBJ: c_int = 0;
pub const CYC_MESH_PLY: c_int = 1;
pub const CYC_MESH_STL: c_int = 2;
pub const CYC_MESH_GLB: c_int = 3;
// enum cyc_parabolic_cyclide_type
pub const CYC_PARABOLIC_HORN: c_int = 0;
pub const CYC_PARABOLIC_RING: c_int = 1;
pub const CYC_PARABOLIC_THORN: c_int = 2;
pub const CYC_PARABOLIC_SPHERE: c_int = 3;
pub const CYC_PARABOLIC_POINT: c_int = 4;

// ------------------------------------------------------------ #define constants
pub const CYC_MAX_CURVE_DEGREE: c_int = 15;
pub const CYC_MAX_HERMITE_ORDER: c_int = 7;
pub const CYC_MAX_MOBIUS_DEGREE: c_int = 15;
pub const CYC_ERROR_MESSAGE_SIZE: c_int = 1024;
pub const CYC_SURFACE_PRCS: c_int = 1;
pub const CYC_SURFACE_PRRS: c_int = 2;
pub const CYC_SURFACE_RINGED: c_int = 3;
pub const CYC_SURFACE_DUPIN: c_int = 4;
pub const CYC_SURFACE_PARABOLIC: c_int = 5;
pub const CYC_DARBOUX_COEFFS: c_int = 14;
pub const CYC_MAX_CYCLIDE_LINES: c_int = 10;
pub const CYC_MAX_SECTION_PLANES: c_int = 5;
pub const CYC_MIN_FIT_POINTS: c_int = 20;
pub const CYC_MAX_FIT_POINTS: c_int = 64;
pub const CYC_MAX_BLEND_ORDER: c_int = 7;
pub const CYC_MAX_SPLINE_KNOTS: c_int = 16;
pub const CYC_RINGED_FIELD_AUTO: c_int = 0;
pub const CYC_RINGED_FIELD_PROJECTION: c_int = 1;
pub const CYC_RINGED_FIELD_QUADRATIC: c_int = 2;
pub const CYC_RINGED_FIELD_SOS: c_int = 3;
pub const CYC_BUMP_SINGLE: c_int = 0;
pub const CYC_BUMP_TWO_PIECE: c_int = 1;
pub const CYC_NWAY_MAX_ENDS: c_int = 8;
pub const CYC_NWAY_CENTER_AUTO: c_int = 0;
pub const CYC_NWAY_CENTER_ALPHA: c_int = 1;
pub const CYC_NWAY_CENTER_GIVEN: c_int = 2;
pub const CYC_NWAY_SIDE_FACING: c_int = 0;
pub const CYC_NWAY_SIDE_PRINTED: c_int = 1;
pub const CYC_BLEND_CANAL: c_int = 0;
pub const CYC_BLEND_RINGED: c_int = 1;
pub const CYC_MAX_QUADRATURE: c_int = 16;
pub const CYC_OPTIMIZE_CONVERGED: c_int = 0;
pub const CYC_OPTIMIZE_ITERATION_LIMIT: c_int = 1;
pub const CYC_OPTIMIZE_REVERTED: c_int = 2;
pub const CYC_PARAMETER_JET: c_int = 0;
pub const CYC_PARAMETER_BUMP_DISPLACEMENT: c_int = 1;
pub const CYC_PARAMETER_BUMP_POSITION: c_int = 2;
pub const CYC_PARAMETER_CIRCLE_POINT: c_int = 3;
pub const CYC_PARAMETER_FAMILY: c_int = 4;
pub const CYC_MAX_IMPLICIT_EXPONENT: c_int = 16;
pub const CYC_MAX_IMPLICIT_PIECES: c_int = 8;
pub const CYC_SKIN_RMF: c_int = 0;
pub const CYC_SKIN_KUNKLI_HOFFMANN: c_int = 1;
pub const CYC_SKIN_CROSS_TANGENTS: c_int = 2;
pub const CYC_RMF_REFERENCE: c_int = 0;
pub const CYC_RMF_DOUBLE_REFLECTION: c_int = 1;
pub const CYC_LIE_SPHERE: c_int = 1;
pub const CYC_LIE_POINT: c_int = 2;
pub const CYC_LIE_PLANE: c_int = 3;
pub const CYC_LIE_POINT_AT_INFINITY: c_int = 4;
pub const CYC_DUPIN_DEGENERATE: c_int = 1;
pub const CYC_DUPIN_PARABOLIC: c_int = 2;
pub const CYC_DUPIN_QUARTIC: c_int = 3;
pub const CYC_MAX_CIRCLE_SEGMENTS: c_int = 4096;
pub const CYC_MAX_EXPORT_PATCHES: c_int = 4096;
pub const CYC_MAX_PN_DEGREE: c_int = 8;

// ------------------------------------------------------------ opaque handles
#[repr(C)]
pub struct cyc_context {
    _data: [u8; 0],
    _marker: PhantomData<(*mut u8, PhantomPinned)>,
}
#[repr(C)]
pub struct cyc_curve {
    _data: [u8; 0],
    _marker: PhantomData<(*mut u8, PhantomPinned)>,
}
#[repr(C)]
pub struct cyc_surface {
    _data: [u8; 0],
    _marker: PhantomData<(*mut u8, PhantomPinned)>,
}
#[repr(C)]
pub struct cyc_sphere_skin {
    _data: [u8; 0],
    _marker: PhantomData<(*mut u8, PhantomPinned)>,
}
#[repr(C)]
pub struct cyc_bezier_export {
    _data: [u8; 0],
    _marker: PhantomData<(*mut u8, PhantomPinned)>,
}
#[repr(C)]
pub struct cyc_pn_surface {
    _data: [u8; 0],
    _marker: PhantomData<(*mut u8, PhantomPinned)>,
}

/// Called on every error with the status and the context's message.
pub type cyc_error_handler =
    Option<unsafe extern "C" fn(status: c_int, message: *const c_char, userdata: *mut c_void)>;

// ------------------------------------------------------------ structs (typedef struct)
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_sphere {
    pub center: [f64; 3],
    pub radius2: f64,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_circle {
    pub center: [f64; 3],
    pub normal: [f64; 3],
    pub radius2: f64,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_mobius {
    pub degree: c_int,
    pub alpha: [f64; CYC_MAX_MOBIUS_DEGREE as usize + 1],
    pub beta: [f64; CYC_MAX_MOBIUS_DEGREE as usize + 1],
    pub gamma: [f64; CYC_MAX_MOBIUS_DEGREE as usize + 1],
    pub delta: [f64; CYC_MAX_MOBIUS_DEGREE as usize + 1],
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_buffer3 {
    pub data: *mut f64,
    pub capacity: usize,
    pub stride: usize,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_allocator {
    pub alloc: Option<
        unsafe extern "C" fn(userdata: *mut c_void, size: usize, alignment: usize) -> *mut c_void,
    >,
    pub free: Option<unsafe extern "C" fn(userdata: *mut c_void, ptr: *mut c_void)>,
    pub userdata: *mut c_void,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_darboux {
    pub k: [f64; CYC_DARBOUX_COEFFS as usize],
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_inversion {
    pub center: [f64; 3],
    pub radius: f64,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_general_sphere {
    pub a: f64,
    pub b: [f64; 3],
    pub c: f64,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_circle_or_line {
    pub is_line: c_int,
    pub point: [f64; 3],
    pub axis: [f64; 3],
    pub radius: f64,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_line {
    pub point: [f64; 3],
    pub direction: [f64; 3],
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_cyclide_line {
    pub point: [f64; 3],
    pub direction: [f64; 3],
    pub t: f64,
    pub multiplicity: c_int,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_cyclide_lines {
    pub normal: [f64; 3],
    pub plane_count: c_int,
    pub plane_t: [f64; CYC_MAX_SECTION_PLANES as usize],
    pub plane_kind: [c_int; CYC_MAX_SECTION_PLANES as usize],
    pub line_count: c_int,
    pub lines: [cyc_cyclide_line; CYC_MAX_CYCLIDE_LINES as usize],
    pub l0_circles: c_int,
    pub circle_families: c_int,
    pub double_families: c_int,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_prrs_lines_analysis {
    pub coplanar_pair: c_int,
    pub common_parameter: c_int,
    pub a2: f64,
    pub b2: f64,
    pub a3: f64,
    pub b3: f64,
    pub x3: f64,
    pub y3: f64,
    pub cond55: f64,
    pub cond56: f64,
    pub pencil: c_int,
    pub cyclide: c_int,
    pub mu: f64,
    pub l4: cyc_line,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_darboux_fit {
    pub d: cyc_darboux,
    pub residual: f64,
    pub sigma_ratio: f64,
    pub nullity: c_int,
    pub points: c_int,
    pub is_darboux: c_int,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_lines_classification {
    pub kind: c_int,
    pub paper_case: c_int,
    pub circle_families: c_int,
    pub double_families: c_int,
    pub pn: c_int,
    pub swapped: c_int,
    pub a: f64,
    pub b: f64,
    pub c: f64,
    pub rotation: [f64; 9],
    pub scale: f64,
    pub origin: [f64; 3],
    pub alpha: f64,
    pub beta: f64,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_blend_end {
    pub surface: *const cyc_surface,
    pub u: f64,
    pub v: [f64; 3],
    pub lambda: f64,
    pub phi: [f64; CYC_MAX_BLEND_ORDER as usize - 1],
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_ringed_jet {
    pub d: [f64; 3],
    pub dd: [f64; 3],
    pub n: [f64; 3],
    pub dn: [f64; 3],
    pub rho: f64,
    pub drho: f64,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_pcurve_blend_options {
    pub sign: c_int,
    pub tau: f64,
    pub v: [f64; 3],
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_ringed_field_options {
    pub method: c_int,
    pub v: [f64; 3],
    pub which: c_int,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_ringed_field_report {
    pub method: c_int,
    pub v: [f64; 3],
    pub directions: c_int,
    pub sos_residual: f64,
    pub sos_margin: f64,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_ringed_sqrt_report {
    pub field: cyc_ringed_field_report,
    pub exact_square: c_int,
    pub conic_residual: f64,
    pub conic_degree: c_int,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_directrix_bump {
    pub w: [f64; 3],
    pub tau: f64,
    pub kind: c_int,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_nway_options {
    pub center: c_int,
    pub alpha: f64,
    pub s: [f64; 3],
    pub r: f64,
    pub r_fraction: f64,
    pub lambda: [f64; CYC_NWAY_MAX_ENDS as usize],
    pub side: c_int,
    pub require_disjoint: c_int,
    pub auto_v: c_int,
    pub blend: cyc_pcurve_blend_options,
    pub auto_lambda: c_int,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_nway_report {
    pub y: [f64; 3],
    pub normal: [f64; 3],
    pub alpha: f64,
    pub s: [f64; 3],
    pub r: f64,
    pub bound: f64,
    pub clear_bound: f64,
    pub n_star: [[f64; 3]; CYC_NWAY_MAX_ENDS as usize],
    pub distance: [f64; CYC_NWAY_MAX_ENDS as usize],
    pub theta: [f64; CYC_NWAY_MAX_ENDS as usize],
    pub gap: [[f64; CYC_NWAY_MAX_ENDS as usize]; CYC_NWAY_MAX_ENDS as usize],
    pub nested: [[c_int; CYC_NWAY_MAX_ENDS as usize]; CYC_NWAY_MAX_ENDS as usize],
    pub min_gap: f64,
    pub worst_i: c_int,
    pub worst_j: c_int,
    pub end_jet: [cyc_ringed_jet; CYC_NWAY_MAX_ENDS as usize],
    pub sphere_jet: [cyc_ringed_jet; CYC_NWAY_MAX_ENDS as usize],
    pub v: [[f64; 3]; CYC_NWAY_MAX_ENDS as usize],
    pub failed_end: c_int,
    pub lambda: [f64; CYC_NWAY_MAX_ENDS as usize],
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_continuity {
    pub K: c_int,
    pub samples: c_int,
    pub singular_samples: c_int,
    pub max_gap: f64,
    pub point_scale: f64,
    pub max_normal_angle: f64,
    pub point_jump: [f64; CYC_MAX_BLEND_ORDER as usize + 1],
    pub point_scale_l: [f64; CYC_MAX_BLEND_ORDER as usize + 1],
    pub circle_jump: [f64; CYC_MAX_BLEND_ORDER as usize + 1],
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_blend_target {
    pub point: [f64; 3],
    pub t: f64,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_blend_obstacle {
    pub center: [f64; 3],
    pub radius: f64,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_blend_objective {
    pub fairness: f64,
    pub regularity: f64,
    pub min_determinant: f64,
    pub min_speed: f64,
    pub targets: *const cyc_blend_target,
    pub target_count: c_int,
    pub target_weight: f64,
    pub obstacles: *const cyc_blend_obstacle,
    pub obstacle_count: c_int,
    pub clearance: f64,
    pub obstacle_weight: f64,
    pub quadrature_t: c_int,
    pub quadrature_v: c_int,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_optimize_options {
    pub free_orders: c_int,
    pub lambda_min_ratio: f64,
    pub lambda_max_ratio: f64,
    pub higher_bound: f64,
    pub circle_parameter_range: f64,
    pub max_iterations: c_int,
    pub function_tolerance: f64,
    pub gradient_tolerance: f64,
    pub parameter_tolerance: f64,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_optimize_summary {
    pub initial_cost: f64,
    pub final_cost: f64,
    pub iterations: c_int,
    pub seconds: f64,
    pub termination: c_int,
    pub fairness: f64,
    pub regularity: f64,
    pub targets: f64,
    pub obstacles: f64,
    pub length_scale: f64,
    pub fairness_scale: f64,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_bump_objective {
    pub deviance: f64,
    pub obstacles: *const cyc_blend_obstacle,
    pub obstacle_count: c_int,
    pub clearance: f64,
    pub obstacle_weight: f64,
    pub nodes: c_int,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_bump_options {
    pub w_bound: f64,
    pub tau_min: f64,
    pub tau_max: f64,
    pub free_tau: c_int,
    pub max_iterations: c_int,
    pub function_tolerance: f64,
    pub gradient_tolerance: f64,
    pub parameter_tolerance: f64,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_free_parameter {
    pub role: c_int,
    pub index: c_int,
    pub order: c_int,
    pub lower: f64,
    pub upper: f64,
    pub start: f64,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_implicit_blend {
    pub f1: [f64; 10],
    pub f2: [f64; 10],
    pub f10: [f64; 4],
    pub f20: [f64; 4],
    pub lambda: f64,
    pub n: c_int,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_implicit_approx_options {
    pub pieces: c_int,
    pub psi_weight: f64,
    pub nodes: c_int,
    pub length_min_ratio: f64,
    pub length_max_ratio: f64,
    pub max_iterations: c_int,
    pub function_tolerance: f64,
    pub gradient_tolerance: f64,
    pub parameter_tolerance: f64,
    pub error_nodes_t: c_int,
    pub error_nodes_u: c_int,
    pub two_curves: c_int,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_implicit_approx_report {
    pub pieces: c_int,
    pub omega: f64,
    pub error87: f64,
    pub seconds: f64,
    pub omega_initial: [f64; CYC_MAX_IMPLICIT_PIECES as usize],
    pub omega_piece: [f64; CYC_MAX_IMPLICIT_PIECES as usize],
    pub error87_piece: [f64; CYC_MAX_IMPLICIT_PIECES as usize],
    pub alpha: [[f64; 3]; CYC_MAX_IMPLICIT_PIECES as usize],
    pub beta: [[f64; 3]; CYC_MAX_IMPLICIT_PIECES as usize],
    pub reverted: [c_int; CYC_MAX_IMPLICIT_PIECES as usize],
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_skin_end {
    pub center: [f64; 3],
    pub radius: f64,
    pub tangent: [f64; 3],
    pub inv_c: f64,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_skin_options {
    pub pairing: c_int,
    pub method: c_int,
    pub tolerance: f64,
    pub reference: [f64; 3],
    pub e: [f64; 3],
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_sphere_skin_info {
    pub kappa: [f64; 2],
    pub delta: f64,
    pub rmf_substeps: c_int,
    pub rmf_error_estimate: f64,
    pub spine: [[f64; 3]; 4],
    pub pairing: c_int,
    pub method: c_int,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_skin_tangent_options {
    pub target: f64,
    pub min_ratio: f64,
    pub max_ratio: f64,
    pub max_iterations: c_int,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_skin_tangent_summary {
    pub scale: [f64; 2],
    pub kappa_r_initial: [f64; 2],
    pub kappa_r: [f64; 2],
    pub iterations: c_int,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_lie_sphere {
    pub kind: c_int,
    pub m: [f64; 3],
    pub rho: f64,
    pub n: [f64; 3],
    pub lambda: f64,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_lie_transform {
    pub m: [f64; 36],
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_dupin {
    pub theta: [f64; 36],
    pub r#type: c_int,
    pub origin: [f64; 3],
    pub unit: f64,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_dupin_point {
    pub point: [f64; 3],
    pub normal: [f64; 3],
    pub lambda: f64,
    pub d_xi: [f64; 3],
    pub d_zeta: [f64; 3],
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_lie_cone {
    pub r0: [f64; 6],
    pub r_plus: [f64; 6],
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_cyclide_blend {
    pub pieces: c_int,
    pub branch: c_int,
    pub alpha: f64,
    pub beta: f64,
    pub joint: [f64; 6],
    pub piece: [cyc_dupin; 2],
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_cyclide_blend_report {
    pub gap: [f64; 3],
    pub angle: [f64; 3],
    pub scale: f64,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_cyclide_blend_objective {
    pub fairness: f64,
    pub joint_points: *const f64,
    pub joint_point_count: c_int,
    pub joint_point_weight: f64,
    pub joint_radius: f64,
    pub joint_radius_weight: f64,
    pub obstacles: *const cyc_blend_obstacle,
    pub obstacle_count: c_int,
    pub clearance: f64,
    pub obstacle_weight: f64,
    pub regularity: f64,
    pub min_extent: f64,
    pub circles: c_int,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_cyclide_blend_options {
    pub samples: c_int,
    pub branch: c_int,
    pub max_iterations: c_int,
    pub function_tolerance: f64,
    pub gradient_tolerance: f64,
    pub parameter_tolerance: f64,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_tessellation_options {
    pub chordal_tolerance: f64,
    pub min_segments: c_int,
    pub max_segments: c_int,
    pub fixed_segments: c_int,
    pub initial_rows: c_int,
    pub reference_u0: *const f64,
    pub reference_u1: *const f64,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_tessellation_plan {
    pub rows: c_int,
    pub segments: c_int,
    pub phase0: f64,
    pub phase1: f64,
    pub max_radius: f64,
    pub depth_limited: c_int,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_export_domain {
    pub u0: f64,
    pub u1: f64,
    pub v0: f64,
    pub v1: f64,
    pub whole_circle: c_int,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_bezier_patch_info {
    pub deg_u: c_int,
    pub deg_v: c_int,
    pub u0: f64,
    pub u1: f64,
    pub v0: f64,
    pub v1: f64,
    pub reciprocal_v: c_int,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_nurbs_size {
    pub deg_u: c_int,
    pub deg_v: c_int,
    pub cp_u: c_int,
    pub cp_v: c_int,
    pub knots_u: c_int,
    pub knots_v: c_int,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_grid_mesh {
    pub points: *const f64,
    pub normals: *const f64,
    pub stride: usize,
    pub rows: c_int,
    pub cols: c_int,
    pub closed: c_int,
    pub rgba: [f32; 4],
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_mesh_write_options {
    pub weld_tolerance: f64,
    pub name: *const c_char,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_mesh_stats {
    pub vertices: usize,
    pub triangles: usize,
    pub welded_rows: c_int,
    pub collapsed_rows: c_int,
    pub coordinate_sum: f64,
    pub tolerance: f64,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_skin_export_options {
    pub tolerance: f64,
    pub degree: c_int,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_skin_export_report {
    pub error_estimate: f64,
    pub rmf_error: f64,
    pub exact: c_int,
    pub t_intervals: c_int,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_oriented_plane {
    pub e0: f64,
    pub e: [f64; 3],
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_cycle {
    pub m: [f64; 3],
    pub r: f64,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_isotropic_point {
    pub exceptional: c_int,
    pub y: [f64; 3],
    pub c: f64,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_isotropic_paraboloid {
    pub k: f64,
    pub l1: f64,
    pub l2: f64,
    pub c0: f64,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_oriented_point {
    pub point: [f64; 3],
    pub normal: [f64; 3],
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_isotropic_datum {
    pub b: [f64; 2],
    pub z: f64,
    pub g: [f64; 2],
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_graph_quadratic {
    pub q: [f64; 6],
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_quadratic_graph_triangle {
    pub vertex: [[f64; 2]; 3],
    pub ordinate: [f64; 6],
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_rational_cubic_triangle {
    pub control: [[f64; 4]; 10],
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_rational_bicubic_patch {
    pub control: [[[f64; 4]; 4]; 4],
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_parabolic_cyclide {
    pub a: f64,
    pub b: f64,
    pub frame: [f64; 9],
    pub origin: [f64; 3],
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_revolution_cone {
    pub apex: [f64; 3],
    pub axis: [f64; 3],
    pub half_angle: f64,
    pub cylinder: c_int,
    pub circle_and_line: c_int,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_design_options {
    pub allow_ridges: c_int,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_design_report {
    pub triangles: c_int,
    pub patches: c_int,
    pub orientation: c_int,
    pub ridge_patches: c_int,
    pub first_ridge_patch: c_int,
    pub first_bad_datum: c_int,
    pub patches_needed: c_int,
    pub work_needed: usize,
}
#[repr(C)]
#[derive(Debug, Copy, Clone)]
pub struct cyc_pn_point {
    pub point: [f64; 3],
    pub x_u: [f64; 3],
    pub x_v: [f64; 3],
    pub normal: [f64; 3],
    pub plane: cyc_oriented_plane,
    pub y: [f64; 3],
}

extern "C" {
    pub fn cyc_version_number() -> c_int;
    pub fn cyc_version_string() -> *const c_char;
    pub fn cyc_abi_version() -> c_int;
    pub fn cyc_status_name(status: c_int) -> *const c_char;
    pub fn cyc_context_create(allocator: *const cyc_allocator, out: *mut *mut cyc_context)
        -> c_int;
    pub fn cyc_context_destroy(ctx: *mut cyc_context);
    pub fn cyc_context_last_error(ctx: *const cyc_context) -> *const c_char;
    pub fn cyc_context_last_status(ctx: *const cyc_context) -> c_int;
    pub fn cyc_context_set_error_handler(
        ctx: *mut cyc_context,
        handler: cyc_error_handler,
        userdata: *mut c_void,
    ) -> c_int;
    // caller memory (issue 10): a context placed in the caller's block
    pub fn cyc_context_static_size() -> usize;
    pub fn cyc_surface_static_size() -> usize;
    pub fn cyc_curve_static_size() -> usize;
    pub fn cyc_context_init_static(
        mem: *mut c_void,
        size: usize,
        fallback: *const cyc_allocator,
        out: *mut *mut cyc_context,
    ) -> c_int;
    pub fn cyc_context_static_remaining(ctx: *const cyc_context) -> usize;
    pub fn cyc_curve_create_polynomial(
        ctx: *mut cyc_context,
        degree: c_int,
        coeffs: *const f64,
        stride: usize,
        out: *mut *mut cyc_curve,
    ) -> c_int;
    pub fn cyc_curve_create_rational(
        ctx: *mut cyc_context,
        degree: c_int,
        coeffs: *const f64,
        stride: usize,
        out: *mut *mut cyc_curve,
    ) -> c_int;
    pub fn cyc_curve_create_bezier(
        ctx: *mut cyc_context,
        degree: c_int,
        ctrl: *const f64,
        stride: usize,
        weights: *const f64,
        u0: f64,
        u1: f64,
        out: *mut *mut cyc_curve,
    ) -> c_int;
    pub fn cyc_curve_create_line(
        ctx: *mut cyc_context,
        point: *const f64,
        direction: *const f64,
        out: *mut *mut cyc_curve,
    ) -> c_int;
    pub fn cyc_curve_create_point(
        ctx: *mut cyc_context,
        point: *const f64,
        out: *mut *mut cyc_curve,
    ) -> c_int;
    pub fn cyc_curve_create_line_element(
        ctx: *mut cyc_context,
        point: *const f64,
        tangent: *const f64,
        out: *mut *mut cyc_curve,
    ) -> c_int;
    pub fn cyc_curve_create_hermite(
        ctx: *mut cyc_context,
        order: c_int,
        u0: f64,
        u1: f64,
        start: *const f64,
        end: *const f64,
        out: *mut *mut cyc_curve,
    ) -> c_int;
    pub fn cyc_curve_destroy(ctx: *mut cyc_context, curve: *mut cyc_curve);
    pub fn cyc_curve_degree(
        ctx: *mut cyc_context,
        curve: *const cyc_curve,
        degree: *mut c_int,
    ) -> c_int;
    pub fn cyc_curve_eval(
        ctx: *mut cyc_context,
        curve: *const cyc_curve,
        u: f64,
        order: c_int,
        out: *mut f64,
        capacity: usize,
    ) -> c_int;
    pub fn cyc_prcs_create(
        ctx: *mut cyc_context,
        p1: *const cyc_curve,
        p2: *const cyc_curve,
        f: *const cyc_mobius,
        u0: f64,
        u1: f64,
        out: *mut *mut cyc_surface,
    ) -> c_int;
    pub fn cyc_prrs_create(
        ctx: *mut cyc_context,
        p1: *const cyc_curve,
        p2: *const cyc_curve,
        p3: *const cyc_curve,
        f: *const cyc_mobius,
        u0: f64,
        u1: f64,
        out: *mut *mut cyc_surface,
    ) -> c_int;
    pub fn cyc_ringed_create(
        ctx: *mut cyc_context,
        d: *const cyc_curve,
        n: *const cyc_curve,
        c: *const cyc_curve,
        f: *const cyc_mobius,
        u0: f64,
        u1: f64,
        out: *mut *mut cyc_surface,
    ) -> c_int;
    pub fn cyc_surface_destroy(ctx: *mut cyc_context, surface: *mut cyc_surface);
    pub fn cyc_surface_kind(
        ctx: *mut cyc_context,
        surface: *const cyc_surface,
        kind: *mut c_int,
    ) -> c_int;
    pub fn cyc_surface_domain(
        ctx: *mut cyc_context,
        surface: *const cyc_surface,
        u0: *mut f64,
        u1: *mut f64,
    ) -> c_int;
    pub fn cyc_surface_eval(
        ctx: *mut cyc_context,
        surface: *const cyc_surface,
        u: f64,
        v: f64,
        point: *mut f64,
        du: *mut f64,
        dv: *mut f64,
        normal: *mut f64,
    ) -> c_int;
    pub fn cyc_surface_eval_batch(
        ctx: *mut cyc_context,
        surface: *const cyc_surface,
        uv: *const f64,
        uv_stride: usize,
        count: usize,
        points: cyc_buffer3,
        du: cyc_buffer3,
        dv: cyc_buffer3,
        normals: cyc_buffer3,
        singular: *mut usize,
    ) -> c_int;
    pub fn cyc_surface_eval_grid(
        ctx: *mut cyc_context,
        surface: *const cyc_surface,
        us: *const f64,
        nu: usize,
        vs: *const f64,
        nv: usize,
        points: cyc_buffer3,
        du: cyc_buffer3,
        dv: cyc_buffer3,
        normals: cyc_buffer3,
        singular: *mut usize,
    ) -> c_int;
    pub fn cyc_surface_circle(
        ctx: *mut cyc_context,
        surface: *const cyc_surface,
        u: f64,
        out: *mut cyc_circle,
    ) -> c_int;
    pub fn cyc_surface_sphere(
        ctx: *mut cyc_context,
        surface: *const cyc_surface,
        u: f64,
        out: *mut cyc_sphere,
    ) -> c_int;
    pub fn cyc_surface_ringed_data(
        ctx: *mut cyc_context,
        surface: *const cyc_surface,
        u: f64,
        c: *mut f64,
        n: *mut f64,
        rho2: *mut f64,
        rho_rho_prime: *mut f64,
    ) -> c_int;
    pub fn cyc_surface_ringed_sphere(
        ctx: *mut cyc_context,
        surface: *const cyc_surface,
        u: f64,
        out: *mut cyc_sphere,
    ) -> c_int;
    pub fn cyc_surface_canal_test(
        ctx: *mut cyc_context,
        surface: *const cyc_surface,
        tolerance: f64,
        max_residual: *mut f64,
        is_canal: *mut c_int,
    ) -> c_int;
    pub fn cyc_surface_parameter_of(
        ctx: *mut cyc_context,
        surface: *const cyc_surface,
        u: f64,
        point: *const f64,
        v: *mut f64,
    ) -> c_int;
    pub fn cyc_darboux_eval(
        ctx: *mut cyc_context,
        d: *const cyc_darboux,
        x: *const f64,
        value: *mut f64,
        gradient: *mut f64,
    ) -> c_int;
    pub fn cyc_darboux_classify(
        ctx: *mut cyc_context,
        d: *const cyc_darboux,
        r#type: *mut c_int,
    ) -> c_int;
    pub fn cyc_invert_point(
        ctx: *mut cyc_context,
        inv: *const cyc_inversion,
        x: *const f64,
        out: *mut f64,
    ) -> c_int;
    pub fn cyc_invert_sphere(
        ctx: *mut cyc_context,
        inv: *const cyc_inversion,
        s: *const cyc_general_sphere,
        out: *mut cyc_general_sphere,
    ) -> c_int;
    pub fn cyc_invert_circle(
        ctx: *mut cyc_context,
        inv: *const cyc_inversion,
        c: *const cyc_circle_or_line,
        out: *mut cyc_circle_or_line,
    ) -> c_int;
    pub fn cyc_invert_darboux(
        ctx: *mut cyc_context,
        inv: *const cyc_inversion,
        d: *const cyc_darboux,
        out: *mut cyc_darboux,
    ) -> c_int;
    pub fn cyc_surface_eval_inverted(
        ctx: *mut cyc_context,
        surface: *const cyc_surface,
        inv: *const cyc_inversion,
        u: f64,
        v: f64,
        point: *mut f64,
        du: *mut f64,
        dv: *mut f64,
        normal: *mut f64,
    ) -> c_int;
    pub fn cyc_surface_circle_inverted(
        ctx: *mut cyc_context,
        surface: *const cyc_surface,
        inv: *const cyc_inversion,
        u: f64,
        out: *mut cyc_circle_or_line,
    ) -> c_int;
    pub fn cyc_surface_eval_grid_inverted(
        ctx: *mut cyc_context,
        surface: *const cyc_surface,
        inv: *const cyc_inversion,
        us: *const f64,
        nu: usize,
        vs: *const f64,
        nv: usize,
        points: cyc_buffer3,
        du: cyc_buffer3,
        dv: cyc_buffer3,
        normals: cyc_buffer3,
        singular: *mut usize,
    ) -> c_int;
    pub fn cyc_dcmc(
        ctx: *mut cyc_context,
        lines: *const cyc_line,
        normal: *mut f64,
        base: *mut cyc_darboux,
        quadric: *mut cyc_darboux,
    ) -> c_int;
    pub fn cyc_parabolic_lines(
        ctx: *mut cyc_context,
        d: *const cyc_darboux,
        out: *mut cyc_cyclide_lines,
    ) -> c_int;
    pub fn cyc_pencil_circle(
        ctx: *mut cyc_context,
        d: *const cyc_darboux,
        line: *const cyc_line,
        plane_normal: *const f64,
        out: *mut cyc_circle_or_line,
    ) -> c_int;
    pub fn cyc_parabolic_parameterize(
        ctx: *mut cyc_context,
        d: *const cyc_darboux,
        kind: c_int,
        u0: f64,
        u1: f64,
        inputs: *mut cyc_line,
        out: *mut *mut cyc_surface,
    ) -> c_int;
    pub fn cyc_prrs_lines_analyze(
        ctx: *mut cyc_context,
        lines: *const cyc_line,
        out: *mut cyc_prrs_lines_analysis,
    ) -> c_int;
    pub fn cyc_prrs_lines_cyclide(
        ctx: *mut cyc_context,
        lines: *const cyc_line,
        out: *mut cyc_darboux,
        residual: *mut f64,
    ) -> c_int;
    pub fn cyc_darboux_fit_points(
        ctx: *mut cyc_context,
        points: *const f64,
        count: c_int,
        out: *mut cyc_darboux_fit,
    ) -> c_int;
    pub fn cyc_darboux_fit_surface(
        ctx: *mut cyc_context,
        surface: *const cyc_surface,
        out: *mut cyc_darboux_fit,
    ) -> c_int;
    pub fn cyc_classify_two_lines(
        ctx: *mut cyc_context,
        l1: *const cyc_line,
        l2: *const cyc_line,
        out: *mut cyc_lines_classification,
    ) -> c_int;
    pub fn cyc_classify_line_element(
        ctx: *mut cyc_context,
        l1: *const cyc_line,
        p2: *const f64,
        w: *const f64,
        out: *mut cyc_lines_classification,
        implicit: *mut cyc_darboux,
    ) -> c_int;
    pub fn cyc_classify_line_two_points(
        ctx: *mut cyc_context,
        l1: *const cyc_line,
        p2: *const f64,
        p3: *const f64,
        out: *mut cyc_lines_classification,
    ) -> c_int;
    pub fn cyc_surface_derivatives_u(
        ctx: *mut cyc_context,
        surface: *const cyc_surface,
        u: f64,
        v: f64,
        K: c_int,
        out: *mut f64,
    ) -> c_int;
    pub fn cyc_blend_canal(
        ctx: *mut cyc_context,
        start: *const cyc_blend_end,
        end: *const cyc_blend_end,
        K: c_int,
        t0: f64,
        t1: f64,
        out: *mut *mut cyc_surface,
    ) -> c_int;
    pub fn cyc_blend_ringed(
        ctx: *mut cyc_context,
        start: *const cyc_blend_end,
        end: *const cyc_blend_end,
        K: c_int,
        t0: f64,
        t1: f64,
        out: *mut *mut cyc_surface,
    ) -> c_int;
    pub fn cyc_blend_ringed_matched(
        ctx: *mut cyc_context,
        start: *const cyc_blend_end,
        end: *const cyc_blend_end,
        K: c_int,
        t0: f64,
        t1: f64,
        out: *mut *mut cyc_surface,
    ) -> c_int;
    pub fn cyc_blend_canal_spline(
        ctx: *mut cyc_context,
        ends: *const cyc_blend_end,
        n: c_int,
        K: c_int,
        knots: *const f64,
        pieces: *mut *mut cyc_surface,
    ) -> c_int;
    pub fn cyc_blend_ringed_spline(
        ctx: *mut cyc_context,
        ends: *const cyc_blend_end,
        n: c_int,
        K: c_int,
        knots: *const f64,
        pieces: *mut *mut cyc_surface,
    ) -> c_int;
    pub fn cyc_blend_ringed_spline_matched(
        ctx: *mut cyc_context,
        ends: *const cyc_blend_end,
        n: c_int,
        K: c_int,
        knots: *const f64,
        pieces: *mut *mut cyc_surface,
    ) -> c_int;
    pub fn cyc_surface_ringed_jet(
        ctx: *mut cyc_context,
        surface: *const cyc_surface,
        u: f64,
        out: *mut cyc_ringed_jet,
    ) -> c_int;
    pub fn cyc_pcurve_blend_options_init(options: *mut cyc_pcurve_blend_options);
    pub fn cyc_blend_ringed_pcurve(
        ctx: *mut cyc_context,
        a: *const cyc_ringed_jet,
        b: *const cyc_ringed_jet,
        options: *const cyc_pcurve_blend_options,
        pieces: *mut *mut cyc_surface,
        count: *mut c_int,
    ) -> c_int;
    pub fn cyc_ringed_field_options_init(options: *mut cyc_ringed_field_options);
    pub fn cyc_ringed_dnr_create(
        ctx: *mut cyc_context,
        d: *const cyc_curve,
        n: *const cyc_curve,
        rho_num_degree: c_int,
        rho_num: *const f64,
        rho_den_degree: c_int,
        rho_den: *const f64,
        options: *const cyc_ringed_field_options,
        f: *const cyc_mobius,
        u0: f64,
        u1: f64,
        out: *mut *mut cyc_surface,
        report: *mut cyc_ringed_field_report,
    ) -> c_int;
    pub fn cyc_ringed_sqrt_create(
        ctx: *mut cyc_context,
        d: *const cyc_curve,
        n: *const cyc_curve,
        R_num_degree: c_int,
        R_num: *const f64,
        R_den_degree: c_int,
        R_den: *const f64,
        options: *const cyc_ringed_field_options,
        f: *const cyc_mobius,
        u0: f64,
        u1: f64,
        out: *mut *mut cyc_surface,
        report: *mut cyc_ringed_sqrt_report,
    ) -> c_int;
    pub fn cyc_ringed_pcurve_create(
        ctx: *mut cyc_context,
        d: *const cyc_curve,
        x_degree: c_int,
        x: *const f64,
        phi: f64,
        rho_num_degree: c_int,
        rho_num: *const f64,
        rho_den_degree: c_int,
        rho_den: *const f64,
        f: *const cyc_mobius,
        u0: f64,
        u1: f64,
        out: *mut *mut cyc_surface,
    ) -> c_int;
    pub fn cyc_blend_ringed_pcurve_bump(
        ctx: *mut cyc_context,
        a: *const cyc_ringed_jet,
        b: *const cyc_ringed_jet,
        options: *const cyc_pcurve_blend_options,
        bump: *const cyc_directrix_bump,
        pieces: *mut *mut cyc_surface,
        count: *mut c_int,
    ) -> c_int;
    pub fn cyc_nway_options_init(options: *mut cyc_nway_options);
    pub fn cyc_blend_ringed_nway(
        ctx: *mut cyc_context,
        ends: *const *const cyc_surface,
        end_u: *const f64,
        n: c_int,
        options: *const cyc_nway_options,
        blends: *mut *mut cyc_surface,
        counts: *mut c_int,
        report: *mut cyc_nway_report,
    ) -> c_int;
    pub fn cyc_nway_sphere_create(
        ctx: *mut cyc_context,
        center: *const f64,
        radius: f64,
        axis: *const f64,
        out: *mut *mut cyc_surface,
    ) -> c_int;
    pub fn cyc_surface_sphere_clearance(
        ctx: *mut cyc_context,
        surface: *const cyc_surface,
        center: *const f64,
        radius: f64,
        clearance: *mut f64,
        at_u: *mut f64,
    ) -> c_int;
    pub fn cyc_surface_normal_deviance(
        ctx: *mut cyc_context,
        surface: *const cyc_surface,
        value: *mut f64,
    ) -> c_int;
    pub fn cyc_surface_contour_points(
        ctx: *mut cyc_context,
        surface: *const cyc_surface,
        u: f64,
        v: *const f64,
        points: *mut f64,
        capacity: usize,
        count: *mut c_int,
        whole_circle: *mut c_int,
    ) -> c_int;
    pub fn cyc_ringed_contour_curves(
        ctx: *mut cyc_context,
        d: *const cyc_curve,
        n: *const cyc_curve,
        rho_num_degree: c_int,
        rho_num: *const f64,
        rho_den_degree: c_int,
        rho_den: *const f64,
        v: *const f64,
        plus: *mut *mut cyc_curve,
        minus: *mut *mut cyc_curve,
    ) -> c_int;
    pub fn cyc_continuity_report(
        ctx: *mut cyc_context,
        a: *const cyc_surface,
        ua: f64,
        lambda: f64,
        b: *const cyc_surface,
        ub: f64,
        K: c_int,
        va: *const f64,
        n: c_int,
        out: *mut cyc_continuity,
    ) -> c_int;
    pub fn cyc_optimizer_available() -> c_int;
    pub fn cyc_optimize_closest_point(
        ctx: *mut cyc_context,
        surface: *const cyc_surface,
        point: *const f64,
        u: *mut f64,
        v: *mut f64,
        closest: *mut f64,
        distance: *mut f64,
    ) -> c_int;
    pub fn cyc_blend_objective_init(objective: *mut cyc_blend_objective);
    pub fn cyc_optimize_options_init(options: *mut cyc_optimize_options);
    pub fn cyc_optimize_blend(
        ctx: *mut cyc_context,
        kind: c_int,
        start: *const cyc_blend_end,
        end: *const cyc_blend_end,
        K: c_int,
        t0: f64,
        t1: f64,
        objective: *const cyc_blend_objective,
        options: *const cyc_optimize_options,
        out: *mut *mut cyc_surface,
        start_out: *mut cyc_blend_end,
        end_out: *mut cyc_blend_end,
        summary: *mut cyc_optimize_summary,
    ) -> c_int;
    pub fn cyc_bump_objective_init(objective: *mut cyc_bump_objective);
    pub fn cyc_bump_options_init(options: *mut cyc_bump_options);
    pub fn cyc_optimize_pcurve_bump(
        ctx: *mut cyc_context,
        a: *const cyc_ringed_jet,
        b: *const cyc_ringed_jet,
        blend: *const cyc_pcurve_blend_options,
        start: *const cyc_directrix_bump,
        objective: *const cyc_bump_objective,
        options: *const cyc_bump_options,
        pieces: *mut *mut cyc_surface,
        count: *mut c_int,
        chosen: *mut cyc_directrix_bump,
        summary: *mut cyc_optimize_summary,
    ) -> c_int;
    pub fn cyc_optimize_blend_parameters(
        ctx: *mut cyc_context,
        kind: c_int,
        start: *const cyc_blend_end,
        end: *const cyc_blend_end,
        K: c_int,
        t0: f64,
        t1: f64,
        options: *const cyc_optimize_options,
        params: *mut cyc_free_parameter,
        capacity: c_int,
        count: *mut c_int,
    ) -> c_int;
    pub fn cyc_optimize_pcurve_bump_parameters(
        ctx: *mut cyc_context,
        a: *const cyc_ringed_jet,
        b: *const cyc_ringed_jet,
        blend: *const cyc_pcurve_blend_options,
        start: *const cyc_directrix_bump,
        options: *const cyc_bump_options,
        params: *mut cyc_free_parameter,
        capacity: c_int,
        count: *mut c_int,
    ) -> c_int;
    pub fn cyc_implicit_cylinder(
        ctx: *mut cyc_context,
        point: *const f64,
        direction: *const f64,
        radius: f64,
        coeffs: *mut f64,
    ) -> c_int;
    pub fn cyc_implicit_cone(
        ctx: *mut cyc_context,
        apex: *const f64,
        axis: *const f64,
        half_angle: f64,
        coeffs: *mut f64,
    ) -> c_int;
    pub fn cyc_implicit_blend_eval(
        ctx: *mut cyc_context,
        blend: *const cyc_implicit_blend,
        x: *const f64,
        f: *mut f64,
        grad: *mut f64,
        v: *const f64,
        f_v: *mut f64,
        grad_f_v: *mut f64,
    ) -> c_int;
    pub fn cyc_implicit_contour_points(
        ctx: *mut cyc_context,
        blend: *const cyc_implicit_blend,
        end: c_int,
        v: *const f64,
        count: *mut c_int,
        points: *mut f64,
        whole_circle: *mut c_int,
    ) -> c_int;
    pub fn cyc_implicit_approx_options_init(options: *mut cyc_implicit_approx_options);
    pub fn cyc_optimize_implicit_blend(
        ctx: *mut cyc_context,
        blend: *const cyc_implicit_blend,
        v: *const f64,
        options: *const cyc_implicit_approx_options,
        pieces: *mut *mut cyc_surface,
        count: *mut c_int,
        report: *mut cyc_implicit_approx_report,
    ) -> c_int;
    pub fn cyc_skin_end_from_apex(
        ctx: *mut cyc_context,
        center: *const f64,
        radius: f64,
        tangent: *const f64,
        apex: *const f64,
        out: *mut cyc_skin_end,
    ) -> c_int;
    pub fn cyc_skin_end_from_sphere(
        ctx: *mut cyc_context,
        sphere_center: *const f64,
        sphere_radius: f64,
        center: *const f64,
        tangent: *const f64,
        out: *mut cyc_skin_end,
    ) -> c_int;
    pub fn cyc_skin_end_sphere(end: *const cyc_skin_end, center: *mut f64, radius: *mut f64);
    pub fn cyc_skin_options_init(options: *mut cyc_skin_options);
    pub fn cyc_sphere_skin_create(
        ctx: *mut cyc_context,
        start: *const cyc_skin_end,
        end: *const cyc_skin_end,
        options: *const cyc_skin_options,
        out: *mut *mut cyc_sphere_skin,
    ) -> c_int;
    pub fn cyc_sphere_skin_chain_create(
        ctx: *mut cyc_context,
        ends: *const cyc_skin_end,
        n: c_int,
        options: *const cyc_skin_options,
        out: *mut *mut cyc_sphere_skin,
        bad_patch: *mut c_int,
    ) -> c_int;
    pub fn cyc_sphere_skin_destroy(ctx: *mut cyc_context, skin: *mut cyc_sphere_skin);
    pub fn cyc_sphere_skin_patch_count(
        ctx: *mut cyc_context,
        skin: *const cyc_sphere_skin,
        count: *mut c_int,
    ) -> c_int;
    pub fn cyc_sphere_skin_eval(
        ctx: *mut cyc_context,
        skin: *const cyc_sphere_skin,
        patch: c_int,
        theta: f64,
        t: f64,
        x: *mut f64,
        x_theta: *mut f64,
        x_t: *mut f64,
        normal: *mut f64,
    ) -> c_int;
    pub fn cyc_sphere_skin_eval_grid(
        ctx: *mut cyc_context,
        skin: *const cyc_sphere_skin,
        patch: c_int,
        theta: *const f64,
        ntheta: c_int,
        t: *const f64,
        nt: c_int,
        points: *mut f64,
        normals: *mut f64,
        singular: *mut usize,
    ) -> c_int;
    pub fn cyc_sphere_skin_info_get(
        ctx: *mut cyc_context,
        skin: *const cyc_sphere_skin,
        patch: c_int,
        out: *mut cyc_sphere_skin_info,
    ) -> c_int;
    pub fn cyc_sphere_skin_twist(
        ctx: *mut cyc_context,
        skin: *const cyc_sphere_skin,
        patch: c_int,
        theta: f64,
        twist: *mut f64,
    ) -> c_int;
    pub fn cyc_sphere_skin_lambda(
        ctx: *mut cyc_context,
        skin: *const cyc_sphere_skin,
        patch: c_int,
        theta: f64,
        t: f64,
        lambda: *mut f64,
        a: *mut f64,
    ) -> c_int;
    pub fn cyc_sphere_skin_tessellation_workspace_size(segments: c_int) -> usize;
    pub fn cyc_sphere_skin_tessellate_plan(
        ctx: *mut cyc_context,
        skin: *const cyc_sphere_skin,
        patch: c_int,
        options: *const cyc_tessellation_options,
        ts: *mut f64,
        row_cap: c_int,
        work: *mut c_void,
        work_bytes: usize,
        plan: *mut cyc_tessellation_plan,
    ) -> c_int;
    pub fn cyc_sphere_skin_tessellate_eval(
        ctx: *mut cyc_context,
        skin: *const cyc_sphere_skin,
        patch: c_int,
        plan: *const cyc_tessellation_plan,
        ts: *const f64,
        points: cyc_buffer3,
        normals: cyc_buffer3,
        singular: *mut usize,
    ) -> c_int;
    pub fn cyc_skin_tangent_options_init(options: *mut cyc_skin_tangent_options);
    pub fn cyc_optimize_skin_tangents(
        ctx: *mut cyc_context,
        start: *const cyc_skin_end,
        end: *const cyc_skin_end,
        skin: *const cyc_skin_options,
        options: *const cyc_skin_tangent_options,
        start_out: *mut cyc_skin_end,
        end_out: *mut cyc_skin_end,
        summary: *mut cyc_skin_tangent_summary,
    ) -> c_int;
    pub fn cyc_lie_vector(
        ctx: *mut cyc_context,
        sphere: *const cyc_lie_sphere,
        x: *mut f64,
    ) -> c_int;
    pub fn cyc_lie_sphere_of(
        ctx: *mut cyc_context,
        x: *const f64,
        out: *mut cyc_lie_sphere,
    ) -> c_int;
    pub fn cyc_lie_dot(ctx: *mut cyc_context, x: *const f64, y: *const f64, out: *mut f64)
        -> c_int;
    pub fn cyc_lie_in_contact(
        ctx: *mut cyc_context,
        x: *const f64,
        y: *const f64,
        tol: f64,
        contact: *mut c_int,
    ) -> c_int;
    pub fn cyc_lie_span(
        ctx: *mut cyc_context,
        vectors: *const f64,
        k: c_int,
        dim: *mut c_int,
        signature: *mut c_int,
    ) -> c_int;
    pub fn cyc_lie_complement(
        ctx: *mut cyc_context,
        vectors: *const f64,
        k: c_int,
        basis: *mut f64,
        dim: *mut c_int,
        signature: *mut c_int,
    ) -> c_int;
    pub fn cyc_lie_complement_signature(
        ctx: *mut cyc_context,
        signature: *const c_int,
        out: *mut c_int,
    ) -> c_int;
    pub fn cyc_lie_witt_extension(
        ctx: *mut cyc_context,
        u: *const f64,
        w: *const f64,
        k: c_int,
        T: *mut f64,
        residual: *mut f64,
    ) -> c_int;
    pub fn cyc_lie_transform_translation(
        ctx: *mut cyc_context,
        t: *const f64,
        out: *mut cyc_lie_transform,
    ) -> c_int;
    pub fn cyc_lie_transform_rotation(
        ctx: *mut cyc_context,
        R: *const f64,
        out: *mut cyc_lie_transform,
    ) -> c_int;
    pub fn cyc_lie_transform_scaling(
        ctx: *mut cyc_context,
        s: f64,
        out: *mut cyc_lie_transform,
    ) -> c_int;
    pub fn cyc_lie_transform_dilatation(
        ctx: *mut cyc_context,
        d: f64,
        out: *mut cyc_lie_transform,
    ) -> c_int;
    pub fn cyc_lie_transform_inversion(
        ctx: *mut cyc_context,
        center: *const f64,
        radius: f64,
        out: *mut cyc_lie_transform,
    ) -> c_int;
    pub fn cyc_lie_transform_orientation_reversal(
        ctx: *mut cyc_context,
        out: *mut cyc_lie_transform,
    ) -> c_int;
    pub fn cyc_lie_transform_compose(
        ctx: *mut cyc_context,
        first: *const cyc_lie_transform,
        then: *const cyc_lie_transform,
        out: *mut cyc_lie_transform,
    ) -> c_int;
    pub fn cyc_lie_transform_apply(
        ctx: *mut cyc_context,
        T: *const cyc_lie_transform,
        r#in: *const cyc_lie_sphere,
        out: *mut cyc_lie_sphere,
    ) -> c_int;
    pub fn cyc_lie_transform_classify(
        ctx: *mut cyc_context,
        T: *const cyc_lie_transform,
        is_lie: *mut c_int,
        is_laguerre: *mut c_int,
        is_mobius: *mut c_int,
    ) -> c_int;
    pub fn cyc_dupin_classify_spheres(
        ctx: *mut cyc_context,
        spheres: *const cyc_lie_sphere,
        signature: *mut c_int,
    ) -> c_int;
    pub fn cyc_dupin_from_spheres(
        ctx: *mut cyc_context,
        spheres: *const cyc_lie_sphere,
        out: *mut cyc_dupin,
    ) -> c_int;
    pub fn cyc_dupin_from_vectors(
        ctx: *mut cyc_context,
        a: *const f64,
        out: *mut cyc_dupin,
    ) -> c_int;
    pub fn cyc_dupin_from_subspace(
        ctx: *mut cyc_context,
        span: *const f64,
        k: c_int,
        out: *mut cyc_dupin,
        signature: *mut c_int,
    ) -> c_int;
    pub fn cyc_dupin_swap_families(
        ctx: *mut cyc_context,
        r#in: *const cyc_dupin,
        out: *mut cyc_dupin,
    ) -> c_int;
    pub fn cyc_dupin_offset(
        ctx: *mut cyc_context,
        r#in: *const cyc_dupin,
        d: f64,
        out: *mut cyc_dupin,
    ) -> c_int;
    pub fn cyc_dupin_eval(
        ctx: *mut cyc_context,
        cyclide: *const cyc_dupin,
        xi: f64,
        zeta: f64,
        offset: f64,
        out: *mut cyc_dupin_point,
    ) -> c_int;
    pub fn cyc_dupin_eval_homogeneous(
        ctx: *mut cyc_context,
        cyclide: *const cyc_dupin,
        xi: *const f64,
        zeta: *const f64,
        offset: f64,
        out: *mut cyc_dupin_point,
    ) -> c_int;
    pub fn cyc_dupin_sphere(
        ctx: *mut cyc_context,
        cyclide: *const cyc_dupin,
        family: c_int,
        t: *const f64,
        out: *mut cyc_lie_sphere,
    ) -> c_int;
    pub fn cyc_dupin_eval_grid(
        ctx: *mut cyc_context,
        cyclide: *const cyc_dupin,
        xis: *const f64,
        nxi: usize,
        zetas: *const f64,
        nzeta: usize,
        offset: f64,
        points: *mut f64,
        normals: *mut f64,
    ) -> c_int;
    pub fn cyc_dupin_surface_create(
        ctx: *mut cyc_context,
        cyclide: *const cyc_dupin,
        xi_map: *const f64,
        zeta_map: *const f64,
        u0: f64,
        u1: f64,
        out: *mut *mut cyc_surface,
    ) -> c_int;
    pub fn cyc_cone_from_spheres(
        ctx: *mut cyc_context,
        m: *const f64,
        rho: f64,
        dm: *const f64,
        drho: f64,
        out: *mut cyc_lie_cone,
    ) -> c_int;
    pub fn cyc_cone_from_circle(
        ctx: *mut cyc_context,
        center: *const f64,
        normal: *const f64,
        radius: f64,
        slope: f64,
        orientation: c_int,
        out: *mut cyc_lie_cone,
    ) -> c_int;
    pub fn cyc_cone_from_circle_apex(
        ctx: *mut cyc_context,
        center: *const f64,
        normal: *const f64,
        radius: f64,
        apex: *const f64,
        orientation: c_int,
        out: *mut cyc_lie_cone,
    ) -> c_int;
    pub fn cyc_cone_from_surface(
        ctx: *mut cyc_context,
        surface: *const cyc_surface,
        u: f64,
        direction: c_int,
        orientation: c_int,
        out: *mut cyc_lie_cone,
    ) -> c_int;
    pub fn cyc_cone_circle(
        ctx: *mut cyc_context,
        cone: *const cyc_lie_cone,
        center: *mut f64,
        normal: *mut f64,
        radius: *mut f64,
    ) -> c_int;
    pub fn cyc_cone_surface_create(
        ctx: *mut cyc_context,
        cone: *const cyc_lie_cone,
        h0: f64,
        h1: f64,
        out: *mut *mut cyc_surface,
    ) -> c_int;
    pub fn cyc_cyclide_blend_dimension(
        ctx: *mut cyc_context,
        r: *const cyc_lie_cone,
        s: *const cyc_lie_cone,
        dim: *mut c_int,
    ) -> c_int;
    pub fn cyc_cyclide_blend_beta(
        ctx: *mut cyc_context,
        r: *const cyc_lie_cone,
        s: *const cyc_lie_cone,
        branch: c_int,
        alpha: f64,
        beta: *mut f64,
    ) -> c_int;
    pub fn cyc_cyclide_blend_build(
        ctx: *mut cyc_context,
        r: *const cyc_lie_cone,
        s: *const cyc_lie_cone,
        branch: c_int,
        alpha: f64,
        out: *mut cyc_cyclide_blend,
    ) -> c_int;
    pub fn cyc_cyclide_blend_auto(
        ctx: *mut cyc_context,
        r: *const cyc_lie_cone,
        s: *const cyc_lie_cone,
        samples: c_int,
        out: *mut cyc_cyclide_blend,
        quality: *mut f64,
    ) -> c_int;
    pub fn cyc_cyclide_blend_circle(
        ctx: *mut cyc_context,
        blend: *const cyc_cyclide_blend,
        piece: c_int,
        family: c_int,
        s: f64,
        center: *mut f64,
        normal: *mut f64,
        radius: *mut f64,
    ) -> c_int;
    pub fn cyc_cyclide_blend_quality(
        ctx: *mut cyc_context,
        blend: *const cyc_cyclide_blend,
        quality: *mut f64,
    ) -> c_int;
    pub fn cyc_cyclide_blend_surface_create(
        ctx: *mut cyc_context,
        blend: *const cyc_cyclide_blend,
        piece: c_int,
        out: *mut *mut cyc_surface,
    ) -> c_int;
    pub fn cyc_cyclide_blend_continuity(
        ctx: *mut cyc_context,
        r: *const cyc_lie_cone,
        s: *const cyc_lie_cone,
        blend: *const cyc_cyclide_blend,
        n: c_int,
        out: *mut cyc_cyclide_blend_report,
    ) -> c_int;
    pub fn cyc_cyclide_blend_objective_init(objective: *mut cyc_cyclide_blend_objective);
    pub fn cyc_cyclide_blend_options_init(options: *mut cyc_cyclide_blend_options);
    pub fn cyc_optimize_cyclide_blend(
        ctx: *mut cyc_context,
        r: *const cyc_lie_cone,
        s: *const cyc_lie_cone,
        objective: *const cyc_cyclide_blend_objective,
        options: *const cyc_cyclide_blend_options,
        out: *mut cyc_cyclide_blend,
        summary: *mut cyc_optimize_summary,
    ) -> c_int;
    pub fn cyc_optimize_cyclide_blend_parameters(
        ctx: *mut cyc_context,
        r: *const cyc_lie_cone,
        s: *const cyc_lie_cone,
        objective: *const cyc_cyclide_blend_objective,
        options: *const cyc_cyclide_blend_options,
        params: *mut cyc_free_parameter,
        capacity: c_int,
        count: *mut c_int,
    ) -> c_int;
    pub fn cyc_tessellation_options_default(options: *mut cyc_tessellation_options);
    pub fn cyc_tessellation_workspace_size(segments: c_int) -> usize;
    pub fn cyc_tessellate_plan(
        ctx: *mut cyc_context,
        surface: *const cyc_surface,
        options: *const cyc_tessellation_options,
        us: *mut f64,
        row_cap: c_int,
        work: *mut c_void,
        work_bytes: usize,
        plan: *mut cyc_tessellation_plan,
    ) -> c_int;
    pub fn cyc_tessellate_eval(
        ctx: *mut cyc_context,
        surface: *const cyc_surface,
        plan: *const cyc_tessellation_plan,
        us: *const f64,
        points: cyc_buffer3,
        normals: cyc_buffer3,
        singular: *mut usize,
    ) -> c_int;
    pub fn cyc_bezier_export_create(
        ctx: *mut cyc_context,
        surface: *const cyc_surface,
        domain: *const cyc_export_domain,
        out: *mut *mut cyc_bezier_export,
    ) -> c_int;
    pub fn cyc_bezier_export_destroy(e: *mut cyc_bezier_export);
    pub fn cyc_bezier_export_count(e: *const cyc_bezier_export) -> c_int;
    pub fn cyc_bezier_export_patch(
        ctx: *mut cyc_context,
        e: *const cyc_bezier_export,
        index: c_int,
        info: *mut cyc_bezier_patch_info,
        control: *mut f64,
        control_cap: usize,
    ) -> c_int;
    pub fn cyc_bezier_export_eval(
        ctx: *mut cyc_context,
        e: *const cyc_bezier_export,
        index: c_int,
        s: f64,
        t: f64,
        x: *mut f64,
        uv: *mut f64,
    ) -> c_int;
    pub fn cyc_bezier_export_nurbs(
        ctx: *mut cyc_context,
        e: *const cyc_bezier_export,
        size: *mut cyc_nurbs_size,
        knots_u: *mut f64,
        knots_u_cap: usize,
        knots_v: *mut f64,
        knots_v_cap: usize,
        control: *mut f64,
        control_cap: usize,
    ) -> c_int;
    pub fn cyc_export_tau_of_v(v: f64) -> f64;
    pub fn cyc_export_v_of_tau(tau: f64) -> f64;
    pub fn cyc_mesh_write(
        ctx: *mut cyc_context,
        path: *const c_char,
        format: c_int,
        grids: *const cyc_grid_mesh,
        count: c_int,
        options: *const cyc_mesh_write_options,
        stats: *mut cyc_mesh_stats,
    ) -> c_int;
    pub fn cyc_bezier_export_write_json(
        ctx: *mut cyc_context,
        e: *const cyc_bezier_export,
        path: *const c_char,
    ) -> c_int;
    pub fn cyc_skin_export_options_default(options: *mut cyc_skin_export_options);
    pub fn cyc_sphere_skin_export_create(
        ctx: *mut cyc_context,
        skin: *const cyc_sphere_skin,
        domain: *const cyc_export_domain,
        options: *const cyc_skin_export_options,
        out: *mut *mut cyc_bezier_export,
        report: *mut cyc_skin_export_report,
    ) -> c_int;
    pub fn cyc_laguerre_to_isotropic(
        ctx: *mut cyc_context,
        plane: *const cyc_oriented_plane,
        out: *mut cyc_isotropic_point,
    ) -> c_int;
    pub fn cyc_isotropic_to_laguerre(
        ctx: *mut cyc_context,
        y: *const cyc_isotropic_point,
        out: *mut cyc_oriented_plane,
    ) -> c_int;
    pub fn cyc_cycle_paraboloid(
        ctx: *mut cyc_context,
        cycle: *const cyc_cycle,
        out: *mut cyc_isotropic_paraboloid,
    ) -> c_int;
    pub fn cyc_paraboloid_contains(
        ctx: *mut cyc_context,
        p: *const cyc_isotropic_paraboloid,
        y: *const cyc_isotropic_point,
        tol: f64,
        out: *mut c_int,
    ) -> c_int;
    pub fn cyc_isotropic_translate(
        ctx: *mut cyc_context,
        y: *const cyc_isotropic_point,
        t: *const f64,
        out: *mut cyc_isotropic_point,
    ) -> c_int;
    pub fn cyc_plane_translate(
        ctx: *mut cyc_context,
        p: *const cyc_oriented_plane,
        t: *const f64,
        out: *mut cyc_oriented_plane,
    ) -> c_int;
    pub fn cyc_isotropic_dilatation(
        ctx: *mut cyc_context,
        y: *const cyc_isotropic_point,
        d: f64,
        out: *mut cyc_isotropic_point,
    ) -> c_int;
    pub fn cyc_plane_dilatation(
        ctx: *mut cyc_context,
        p: *const cyc_oriented_plane,
        d: f64,
        out: *mut cyc_oriented_plane,
    ) -> c_int;
    pub fn cyc_pn_surface_create(
        ctx: *mut cyc_context,
        degree_u: c_int,
        degree_v: c_int,
        control: *const f64,
        out: *mut *mut cyc_pn_surface,
    ) -> c_int;
    pub fn cyc_pn_surface_destroy(surface: *mut cyc_pn_surface);
    pub fn cyc_pn_surface_eval(
        ctx: *mut cyc_context,
        surface: *const cyc_pn_surface,
        u: f64,
        v: f64,
        d: f64,
        out: *mut cyc_pn_point,
    ) -> c_int;
    pub fn cyc_pn_surface_eval_grid(
        ctx: *mut cyc_context,
        surface: *const cyc_pn_surface,
        us: *const f64,
        nu: usize,
        vs: *const f64,
        nv: usize,
        d: f64,
        points: cyc_buffer3,
        normals: cyc_buffer3,
        failed: *mut usize,
    ) -> c_int;
    pub fn cyc_parabolic_cyclide_from_quadratic(
        ctx: *mut cyc_context,
        q: *const cyc_graph_quadratic,
        out: *mut cyc_parabolic_cyclide,
    ) -> c_int;
    pub fn cyc_parabolic_cyclide_quadratic(
        ctx: *mut cyc_context,
        c: *const cyc_parabolic_cyclide,
        out: *mut cyc_graph_quadratic,
    ) -> c_int;
    pub fn cyc_parabolic_cyclide_eval(
        ctx: *mut cyc_context,
        c: *const cyc_parabolic_cyclide,
        u: f64,
        v: f64,
        point: *mut f64,
        normal: *mut f64,
    ) -> c_int;
    pub fn cyc_parabolic_cyclide_implicit(
        ctx: *mut cyc_context,
        c: *const cyc_parabolic_cyclide,
        x: *const f64,
        out: *mut f64,
    ) -> c_int;
    pub fn cyc_parabolic_cyclide_type(
        ctx: *mut cyc_context,
        c: *const cyc_parabolic_cyclide,
        out: *mut c_int,
    ) -> c_int;
    pub fn cyc_parabolic_cyclide_lines(
        ctx: *mut cyc_context,
        c: *const cyc_parabolic_cyclide,
        e: *mut cyc_line,
        f: *mut cyc_line,
    ) -> c_int;
    pub fn cyc_parabolic_cyclide_u_circle(
        ctx: *mut cyc_context,
        c: *const cyc_parabolic_cyclide,
        u: f64,
        out: *mut cyc_circle,
    ) -> c_int;
    pub fn cyc_parabolic_cyclide_v_circle(
        ctx: *mut cyc_context,
        c: *const cyc_parabolic_cyclide,
        v: f64,
        out: *mut cyc_circle,
    ) -> c_int;
    pub fn cyc_parabolic_cyclide_cone(
        ctx: *mut cyc_context,
        c: *const cyc_parabolic_cyclide,
        lambda: f64,
        mu: f64,
        out: *mut cyc_revolution_cone,
    ) -> c_int;
    pub fn cyc_parabolic_cyclide_cubic_circle_point(
        ctx: *mut cyc_context,
        c: *const cyc_parabolic_cyclide,
        lambda: f64,
        mu: f64,
        t: f64,
        x: *mut f64,
    ) -> c_int;
    pub fn cyc_parabolic_cyclide_net_projection(
        ctx: *mut cyc_context,
        c: *const cyc_parabolic_cyclide,
        x: *const f64,
        cc: f64,
        out: *mut f64,
    ) -> c_int;
    pub fn cyc_parabolic_cyclide_parameter_of(
        ctx: *mut cyc_context,
        c: *const cyc_parabolic_cyclide,
        x: *const f64,
        uv: *mut f64,
    ) -> c_int;
    pub fn cyc_parabolic_cyclide_surface_create(
        ctx: *mut cyc_context,
        c: *const cyc_parabolic_cyclide,
        u0: f64,
        u1: f64,
        out: *mut *mut cyc_surface,
    ) -> c_int;
    pub fn cyc_cyclide_cubic_triangle(
        ctx: *mut cyc_context,
        tri: *const cyc_quadratic_graph_triangle,
        out: *mut cyc_rational_cubic_triangle,
    ) -> c_int;
    pub fn cyc_cyclide_bicubic_patch(
        ctx: *mut cyc_context,
        q: *const cyc_graph_quadratic,
        corner: *const f64,
        e1: *const f64,
        e2: *const f64,
        out: *mut cyc_rational_bicubic_patch,
    ) -> c_int;
    pub fn cyc_cubic_triangle_eval(
        ctx: *mut cyc_context,
        T: *const cyc_rational_cubic_triangle,
        r: f64,
        s: f64,
        t: f64,
        x: *mut f64,
    ) -> c_int;
    pub fn cyc_bicubic_patch_eval(
        ctx: *mut cyc_context,
        P: *const cyc_rational_bicubic_patch,
        s: f64,
        t: f64,
        x: *mut f64,
    ) -> c_int;
    pub fn cyc_delaunay_workspace_size(n: c_int) -> usize;
    pub fn cyc_delaunay_max_triangles(n: c_int) -> c_int;
    pub fn cyc_delaunay_triangulate(
        ctx: *mut cyc_context,
        pts: *const f64,
        n: c_int,
        work: *mut c_void,
        work_bytes: usize,
        tri: *mut c_int,
        tri_cap: c_int,
        ntri: *mut c_int,
    ) -> c_int;
    pub fn cyc_powell_sabin_workspace_size(n: c_int, ntri: c_int) -> usize;
    pub fn cyc_powell_sabin_interpolate(
        ctx: *mut cyc_context,
        b: *const f64,
        z: *const f64,
        g: *const f64,
        n: c_int,
        tri: *const c_int,
        ntri: c_int,
        work: *mut c_void,
        work_bytes: usize,
        out: *mut cyc_quadratic_graph_triangle,
        out_cap: c_int,
        nout: *mut c_int,
    ) -> c_int;
    pub fn cyc_isotropic_datum_of(
        ctx: *mut cyc_context,
        a: *const cyc_oriented_point,
        out: *mut cyc_isotropic_datum,
    ) -> c_int;
    pub fn cyc_oriented_point_of(
        ctx: *mut cyc_context,
        d: *const cyc_isotropic_datum,
        out: *mut cyc_oriented_point,
    ) -> c_int;
    pub fn cyc_gauss_image_contains_pole(
        ctx: *mut cyc_context,
        data: *const cyc_oriented_point,
        n: c_int,
        out: *mut c_int,
    ) -> c_int;
    pub fn cyc_design_workspace_size(n: c_int, ntri: c_int) -> usize;
    pub fn cyc_design_max_patches(n: c_int, ntri: c_int) -> c_int;
    pub fn cyc_design_cyclide_surface(
        ctx: *mut cyc_context,
        data: *const cyc_oriented_point,
        n: c_int,
        tri: *const c_int,
        ntri: c_int,
        options: *const cyc_design_options,
        work: *mut c_void,
        work_bytes: usize,
        iso: *mut cyc_quadratic_graph_triangle,
        patches: *mut cyc_rational_cubic_triangle,
        cap: c_int,
        npatches: *mut c_int,
        report: *mut cyc_design_report,
    ) -> c_int;
}
