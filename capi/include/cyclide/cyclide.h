/* cyclide: exact rational surfaces made of circles and spheres.
 *
 * The stable C ABI. Conventions (SPEC.md "C ABI"):
 *  - Every call takes an explicit context first; a context is used by one
 *    thread at a time; read-only handles may be shared between threads.
 *  - Every function returning int returns a status (cyclide_errors.h);
 *    CYC_OK is 0. On any error the outputs are left untouched and the
 *    context's last-error message says what went wrong.
 *  - A NULL context is reported as CYC_E_NULL_ARGUMENT, never a crash.
 *  - Handles are opaque; cyc_*_destroy(ctx, NULL) is a no-op.
 *  - Batches write into caller buffers described by cyc_buffer3.
 * This header includes only <stddef.h> and compiles as C99 and as C++. */
#ifndef CYCLIDE_H
#define CYCLIDE_H

#include <stddef.h>

#include "cyclide/cyclide_errors.h"
#include "cyclide/cyclide_version.h"

#if defined(_WIN32)
#if defined(CYCLIDE_BUILDING)
#define CYC_API __declspec(dllexport)
#else
#define CYC_API __declspec(dllimport)
#endif
#else
#define CYC_API __attribute__((visibility("default")))
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------ bounds */

/** Largest degree of an input curve (numerator and weight). */
#define CYC_MAX_CURVE_DEGREE 15
/** Largest order K of two-point C^K Hermite interpolation (degree 2K+1). */
#define CYC_MAX_HERMITE_ORDER 7
/** Largest degree in u of the coefficients of the circle parameter f. */
#define CYC_MAX_MOBIUS_DEGREE 15
/** Size of a context's last-error message buffer, including the NUL. */
#define CYC_ERROR_MESSAGE_SIZE 1024

/* ------------------------------------------------------------ types */

typedef struct cyc_context cyc_context;
typedef struct cyc_curve cyc_curve;
typedef struct cyc_surface cyc_surface;

/** A sphere: center and squared radius (frozen). */
typedef struct cyc_sphere {
  double center[3];
  double radius2;
} cyc_sphere;

/** A circle: center, unit normal of its plane, squared radius (frozen). */
typedef struct cyc_circle {
  double center[3];
  double normal[3];
  double radius2;
} cyc_circle;

/** The circle parameter f(u,v) = (alpha(u) v + beta(u)) / (gamma(u) v +
 *  delta(u)) with polynomial coefficients in power form, degree <=
 *  CYC_MAX_MOBIUS_DEGREE (frozen). f = v is alpha = 1, delta = 1, degree 0. */
typedef struct cyc_mobius {
  int degree;
  double alpha[CYC_MAX_MOBIUS_DEGREE + 1];
  double beta[CYC_MAX_MOBIUS_DEGREE + 1];
  double gamma[CYC_MAX_MOBIUS_DEGREE + 1];
  double delta[CYC_MAX_MOBIUS_DEGREE + 1];
} cyc_mobius;

/** A caller buffer of 3-vectors: vector i is data[i*stride .. i*stride+2].
 *  capacity counts vectors; stride counts doubles and is >= 3. data = NULL
 *  means "not wanted". */
typedef struct cyc_buffer3 {
  double* data;
  size_t capacity;
  size_t stride;
} cyc_buffer3;

/** Optional custom allocator. alloc must return memory aligned to
 *  `alignment` (a power of two <= 64) or NULL; free accepts what alloc
 *  returned. */
typedef struct cyc_allocator {
  void* (*alloc)(void* userdata, size_t size, size_t alignment);
  void (*free)(void* userdata, void* ptr);
  void* userdata;
} cyc_allocator;

/** Called on every error with the status and message. The message is the
 *  context's buffer, valid until the next call on the context. The handler
 *  may call the library, also on the same context (such a call replaces the
 *  buffer's text while the handler runs): the failing call still returns its
 *  own status, and when the handler returns the context's last status and
 *  message are the failing call's again. It must not destroy the context. */
typedef void (*cyc_error_handler)(int status, const char* message, void* userdata);

/* ------------------------------------------------------------ versions */

/** CYC_VERSION_NUMBER of the library actually linked. */
CYC_API int cyc_version_number(void);
/** CYC_VERSION_STRING of the library actually linked (static string). */
CYC_API const char* cyc_version_string(void);
/** CYC_ABI_VERSION of the library actually linked. */
CYC_API int cyc_abi_version(void);
/** Static name of a status code ("CYC_E_DEPENDENT_PLANES"); never NULL. */
CYC_API const char* cyc_status_name(int status);

/* ------------------------------------------------------------ context */

/** Create a context. allocator may be NULL (malloc/free); it is copied. */
CYC_API int cyc_context_create(const cyc_allocator* allocator, cyc_context** out);
/** Destroy a context (NULL: no-op). Handles keep their own allocator copy
 *  and may be destroyed after their context. */
CYC_API void cyc_context_destroy(cyc_context* ctx);
/** The last error message of this context ("" after success); never NULL,
 *  also for ctx == NULL. */
CYC_API const char* cyc_context_last_error(const cyc_context* ctx);
/** The status of the last call on this context (CYC_OK after success). */
CYC_API int cyc_context_last_status(const cyc_context* ctx);
/** Install (or with handler = NULL remove) an error callback. */
CYC_API int cyc_context_set_error_handler(cyc_context* ctx, cyc_error_handler handler,
                                          void* userdata);

/* ------------------------------------------------ caller memory (issue 10)
 * The caller-memory tier (SPEC.md §9b): a context placed in the caller's
 * block, and every handle created through it carved from the rest of that
 * block, so a hot loop's surfaces and curves live in memory the caller
 * owns (an arena on the stack, in a pool, in shared memory) and nothing
 * touches the heap. Size the block with the queries below:
 *   cyc_context_static_size() + n_surfaces * cyc_surface_static_size()
 *   + n_curves * cyc_curve_static_size()  (+ other handles' needs).
 * Destroying a handle returns its bytes only if it is the block's most
 * recent one; otherwise they stay used until the caller reuses the whole
 * block. Handles of a static context must be destroyed (or simply
 * abandoned) while the block is alive; cyc_context_destroy on a static
 * context frees nothing. */

/** Bytes a static context needs for itself (alignment slack included). */
CYC_API size_t cyc_context_static_size(void);
/** Bytes one surface (cyc_surface) takes from a static context's block. */
CYC_API size_t cyc_surface_static_size(void);
/** Bytes one curve (cyc_curve) takes from a static context's block. */
CYC_API size_t cyc_curve_static_size(void);
/** Place a context at mem (any alignment; size bytes, at least
 *  cyc_context_static_size()); its handles are carved from the rest of the
 *  block. fallback (may be NULL) serves allocations that do not fit; NULL:
 *  those fail with CYC_E_OUT_OF_MEMORY. CYC_E_NULL_ARGUMENT,
 *  CYC_E_BUFFER_TOO_SMALL, CYC_E_INVALID_ARGUMENT (a fallback without
 *  alloc or free). *out is written only on success. */
CYC_API int cyc_context_init_static(void* mem, size_t size, const cyc_allocator* fallback,
                                    cyc_context** out);
/** Bytes still free in a static context's block (0 for other contexts). */
CYC_API size_t cyc_context_static_remaining(const cyc_context* ctx);

/* ------------------------------------------------------------ curves */

/** Polynomial curve p(u) = sum_k c_k u^k; coeffs holds degree+1 rows
 *  (x, y, z), row k at coeffs + k*stride (stride >= 3 doubles). */
CYC_API int cyc_curve_create_polynomial(cyc_context* ctx, int degree, const double* coeffs,
                                        size_t stride, cyc_curve** out);
/** Rational curve (x(u), y(u), z(u)) / w(u); coeffs holds degree+1 rows
 *  (x, y, z, w) in power form, stride >= 4. */
CYC_API int cyc_curve_create_rational(cyc_context* ctx, int degree, const double* coeffs,
                                      size_t stride, cyc_curve** out);
/** Rational Bezier curve over [u0, u1]: degree+1 control points (stride >=
 *  3) and weights (NULL: all 1). */
CYC_API int cyc_curve_create_bezier(cyc_context* ctx, int degree, const double* ctrl,
                                    size_t stride, const double* weights, double u0,
                                    double u1, cyc_curve** out);
/** Line p(u) = point + u * direction. */
CYC_API int cyc_curve_create_line(cyc_context* ctx, const double point[3],
                                  const double direction[3], cyc_curve** out);
/** Constant point (PRRS input). */
CYC_API int cyc_curve_create_point(cyc_context* ctx, const double point[3],
                                   cyc_curve** out);
/** Line element: a point with a tangent (PRCS input; its normal plane is the
 *  constant plane through point orthogonal to tangent). */
CYC_API int cyc_curve_create_line_element(cyc_context* ctx, const double point[3],
                                          const double tangent[3], cyc_curve** out);
/** Two-point C^K Hermite curve of degree 2K+1 on [u0, u1]: start and end
 *  each hold K+1 rows (p, p', ..., p^(K)) of 3 doubles, K <=
 *  CYC_MAX_HERMITE_ORDER. */
CYC_API int cyc_curve_create_hermite(cyc_context* ctx, int order, double u0, double u1,
                                     const double* start, const double* end,
                                     cyc_curve** out);
/** Destroy a curve (NULL: no-op). ctx may be NULL. */
CYC_API void cyc_curve_destroy(cyc_context* ctx, cyc_curve* curve);
/** Degree of the curve (max of numerator and weight degrees). */
CYC_API int cyc_curve_degree(cyc_context* ctx, const cyc_curve* curve, int* degree);
/** p(u) and its derivatives up to `order` (<= 8): out receives order+1 rows
 *  of 3 doubles; capacity counts doubles and must be >= 3*(order+1). */
CYC_API int cyc_curve_eval(cyc_context* ctx, const cyc_curve* curve, double u, int order,
                           double* out, size_t capacity);

/* ------------------------------------------------------------ surfaces */

/** Surface kinds reported by cyc_surface_kind. */
#define CYC_SURFACE_PRCS 1 /* canal surface by PRCS (seed 000 eq. 8-13) */
#define CYC_SURFACE_PRRS 2 /* ringed surface by PRRS (seed 000 eq. 24-27) */
#define CYC_SURFACE_RINGED 3 /* ringed surface (d, n, rho) through a curve c (seed 001 eq. 3) */
#define CYC_SURFACE_DUPIN 4 /* Dupin cyclide from Lie sphere geometry (seed 003, cyc_dupin_surface_create) */
#define CYC_SURFACE_PARABOLIC 5 /* parabolic Dupin cyclide, its u-circles of (4.1) (seed 004) */

/** PRCS: the canal surface through p1 and p2 (either may be a line element;
 *  not a point), x(u,v) of eq. (11) with circle parameter f (NULL: f = v),
 *  checked on the domain [u0, u1]. Statuses: CYC_E_DEPENDENT_PLANES,
 *  CYC_E_ZERO_TANGENT, CYC_E_NOT_FINITE, CYC_E_BAD_DOMAIN,
 *  CYC_E_DEGENERATE_CIRCLE_PARAMETER, CYC_E_NUMERICAL_OVERFLOW. */
CYC_API int cyc_prcs_create(cyc_context* ctx, const cyc_curve* p1, const cyc_curve* p2,
                            const cyc_mobius* f, double u0, double u1, cyc_surface** out);
/** PRRS: the ringed surface through p1, p2, p3 (one or two may be points),
 *  x(u,v) of eq. (27). Adds CYC_E_COLLINEAR_POINTS. */
CYC_API int cyc_prrs_create(cyc_context* ctx, const cyc_curve* p1, const cyc_curve* p2,
                            const cyc_curve* p3, const cyc_mobius* f, double u0,
                            double u1, cyc_surface** out);
/** Ringed surface R : (d, n, rho) of seed 001: the circles centered at the
 *  directrix d(u) in the planes with normal n(u) (the orientation function),
 *  parameterized by eq. (3) (the rotation of the curve c about the line
 *  element (d, n), circle parameter f; NULL: f = v). d, n and c are curves
 *  or points (constant), not line elements. The circle's center is the foot
 *  of c on the line (d, n): d itself when (c - d).n = 0, as for a curve of
 *  eq. (4) c = d + rho f. Statuses as cyc_prrs_create: CYC_E_DEPENDENT_PLANES
 *  where n = 0, CYC_E_SINGULAR_POINT where c lies on the line (radius 0). */
CYC_API int cyc_ringed_create(cyc_context* ctx, const cyc_curve* d, const cyc_curve* n,
                              const cyc_curve* c, const cyc_mobius* f, double u0, double u1,
                              cyc_surface** out);
/** Destroy a surface (NULL: no-op). ctx may be NULL. */
CYC_API void cyc_surface_destroy(cyc_context* ctx, cyc_surface* surface);
/** CYC_SURFACE_PRCS, CYC_SURFACE_PRRS, CYC_SURFACE_RINGED or
 *  CYC_SURFACE_DUPIN. */
CYC_API int cyc_surface_kind(cyc_context* ctx, const cyc_surface* surface, int* kind);
/** The domain [u0, u1] the surface was checked on. */
CYC_API int cyc_surface_domain(cyc_context* ctx, const cyc_surface* surface, double* u0,
                               double* u1);
/** x(u,v) and, where the pointer is not NULL, x_u, x_v and the unit normal
 *  (canal: (x - s)/r; ringed: x_u x x_v normalized, CYC_E_SINGULAR_POINT
 *  where it vanishes). Any output may be NULL; allocation-free. */
CYC_API int cyc_surface_eval(cyc_context* ctx, const cyc_surface* surface, double u,
                             double v, double point[3], double du[3], double dv[3],
                             double normal[3]);
/** Evaluate count parameter pairs uv[i*uv_stride], uv[i*uv_stride+1]
 *  (uv_stride >= 2). Each wanted buffer needs capacity >= count. Singular
 *  normals are written as (0,0,0) and counted in *singular (may be NULL).
 *  All or nothing: on error no buffer is written. Allocation-free. */
CYC_API int cyc_surface_eval_batch(cyc_context* ctx, const cyc_surface* surface,
                                   const double* uv, size_t uv_stride, size_t count,
                                   cyc_buffer3 points, cyc_buffer3 du, cyc_buffer3 dv,
                                   cyc_buffer3 normals, size_t* singular);
/** Evaluate the grid (us[i], vs[j]) into index i*nv + j, reusing the circle
 *  of each u. Singular normals (ringed only) are written as (0,0,0) and
 *  counted in *singular (may be NULL). All or nothing. Allocation-free. */
CYC_API int cyc_surface_eval_grid(cyc_context* ctx, const cyc_surface* surface,
                                  const double* us, size_t nu, const double* vs,
                                  size_t nv, cyc_buffer3 points, cyc_buffer3 du,
                                  cyc_buffer3 dv, cyc_buffer3 normals, size_t* singular);
/** The circle v -> x(u, v). */
CYC_API int cyc_surface_circle(cyc_context* ctx, const cyc_surface* surface, double u,
                               cyc_circle* out);
/** The sphere touching a canal surface along its circle at u: spine point
 *  s(u) and r^2(u). CYC_E_NOT_CANAL for PRRS surfaces. */
CYC_API int cyc_surface_sphere(cyc_context* ctx, const cyc_surface* surface, double u,
                               cyc_sphere* out);
/** Ringed-surface data at u (eq. (1) for canal surfaces): directrix point
 *  c(u), normal n(u) (not unit: s' or (p1-p2)x(p1-p3)), rho^2(u), and
 *  rho rho'(u). Any output may be NULL. */
CYC_API int cyc_surface_ringed_data(cyc_context* ctx, const cyc_surface* surface,
                                    double u, double c[3], double n[3], double* rho2,
                                    double* rho_rho_prime);
/** The sphere of the family (3) at u: center c + (rho rho'/(n.c')) n and
 *  its squared radius. CYC_E_DEGENERATE_RINGED where n.c' = 0. */
CYC_API int cyc_surface_ringed_sphere(cyc_context* ctx, const cyc_surface* surface,
                                      double u, cyc_sphere* out);
/** Canal test (2) over the domain: the largest relative residual
 *  |[(n.c')c' + rho rho' n'] x n| / scale at the domain samples, and
 *  *is_canal = (residual <= tolerance); tolerance <= 0 uses 1e-9 plus the
 *  residual's rounding floor 8192 eps max |c| / rho (c the circles' centers,
 *  rho their radii: a surface far from the origin decides as at the origin);
 *  a tolerance that is NaN, infinite or beyond 1e100 is CYC_E_NOT_FINITE. */
CYC_API int cyc_surface_canal_test(cyc_context* ctx, const cyc_surface* surface,
                                   double tolerance, double* max_residual, int* is_canal);
/** The v whose point x(u, v) is the point of the circle at u closest to
 *  `point`; HUGE_VAL when that is the generator (f = infinity). */
CYC_API int cyc_surface_parameter_of(cyc_context* ctx, const cyc_surface* surface,
                                     double u, const double point[3], double* v);

/* ------------------------------------------------ Darboux cyclides (seed 000 §5-6) */

/** Number of coefficients of a Darboux cyclide. */
#define CYC_DARBOUX_COEFFS 14

/** A Darboux cyclide (31): phi0 (X.X)^2 + phi1 (X.X) + phi2 = 0 with
 *  phi1 = lx x + ly y + lz z and phi2 = qxx x^2 + qyy y^2 + qzz z^2 + qxy xy
 *  + qxz xz + qyz yz + bx x + by y + bz z + c; k[] holds, in this order,
 *  phi0, lx, ly, lz, qxx, qyy, qzz, qxy, qxz, qyz, bx, by, bz, c (frozen). */
typedef struct cyc_darboux {
  double k[CYC_DARBOUX_COEFFS];
} cyc_darboux;

/** What a Darboux equation describes (frozen numbers). */
enum cyc_darboux_type {
  CYC_DARBOUX_ZERO = 0,      /* all coefficients zero */
  CYC_DARBOUX_QUARTIC = 1,   /* phi0 != 0 */
  CYC_DARBOUX_PARABOLIC = 2, /* phi0 = 0, phi1 != 0: a cubic */
  CYC_DARBOUX_QUADRIC = 3,   /* phi0 = phi1 = 0 */
  CYC_DARBOUX_PLANE = 4,
  CYC_DARBOUX_CONSTANT = 5,  /* a nonzero constant: no point */
  CYC_DARBOUX_REDUCIBLE = 6  /* plane x sphere, plane pair (detected cases) */
};

/** An inversion at the sphere with this center and radius > 0 (frozen). */
typedef struct cyc_inversion {
  double center[3];
  double radius;
} cyc_inversion;

/** A generalized sphere a (X.X) + b.X + c = 0: a plane if a = 0 (frozen). */
typedef struct cyc_general_sphere {
  double a;
  double b[3];
  double c;
} cyc_general_sphere;

/** A circle (center `point`, unit plane normal `axis`, radius) or, if
 *  is_line, the line through `point` with unit direction `axis` (frozen). */
typedef struct cyc_circle_or_line {
  int is_line;
  double point[3];
  double axis[3];
  double radius;
} cyc_circle_or_line;

/** A line point + t direction (frozen). */
typedef struct cyc_line {
  double point[3];
  double direction[3];
} cyc_line;

/** Value F(x) and gradient (may be NULL) of a Darboux equation. */
CYC_API int cyc_darboux_eval(cyc_context* ctx, const cyc_darboux* d, const double x[3],
                             double* value, double gradient[3]);
/** The cyc_darboux_type of an equation (relative threshold 1e-12). */
CYC_API int cyc_darboux_classify(cyc_context* ctx, const cyc_darboux* d, int* type);

/** X' = center + radius^2 (X - center)/|X - center|^2;
 *  CYC_E_AT_INVERSION_CENTER for X = center. */
CYC_API int cyc_invert_point(cyc_context* ctx, const cyc_inversion* inv, const double x[3],
                             double out[3]);
/** The image of a sphere or plane (normalized: largest |coefficient| = 1). */
CYC_API int cyc_invert_sphere(cyc_context* ctx, const cyc_inversion* inv,
                              const cyc_general_sphere* s, cyc_general_sphere* out);
/** The image of a circle or line: a circle, or a line when the input
 *  passes through the center. */
CYC_API int cyc_invert_circle(cyc_context* ctx, const cyc_inversion* inv,
                              const cyc_circle_or_line* c, cyc_circle_or_line* out);
/** The image of a Darboux cyclide, in closed form (normalized: largest
 *  |coefficient| = 1). A center on the cyclide gives phi0 = 0 (§5). */
CYC_API int cyc_invert_darboux(cyc_context* ctx, const cyc_inversion* inv,
                               const cyc_darboux* d, cyc_darboux* out);
/** x(u, v) of a surface carried through an inversion: the point, the
 *  partials pushed forward by the inversion's differential and the unit
 *  normal reflected accordingly. Outputs may be NULL except point. */
CYC_API int cyc_surface_eval_inverted(cyc_context* ctx, const cyc_surface* surface,
                                      const cyc_inversion* inv, double u, double v,
                                      double point[3], double du[3], double dv[3],
                                      double normal[3]);

/** The circle at u of a surface carried through an inversion: the image of
 *  the circle v -> x(u, v), a line when that circle passes through the
 *  center (§5: the inverted surface is again a family of circles). */
CYC_API int cyc_surface_circle_inverted(cyc_context* ctx, const cyc_surface* surface,
                                        const cyc_inversion* inv, double u,
                                        cyc_circle_or_line* out);
/** cyc_surface_eval_grid of the surface carried through an inversion
 *  (points, partials, normals as in cyc_surface_eval_inverted). All or
 *  nothing: CYC_E_AT_INVERSION_CENTER (or CYC_E_NUMERICAL_OVERFLOW) if a
 *  grid point is at the center (or its image overflows), buffers untouched.
 *  Evaluates the grid twice (validate, then write); no allocation. */
CYC_API int cyc_surface_eval_grid_inverted(cyc_context* ctx, const cyc_surface* surface,
                                           const cyc_inversion* inv, const double* us,
                                           size_t nu, const double* vs, size_t nv,
                                           cyc_buffer3 points, cyc_buffer3 du,
                                           cyc_buffer3 dv, cyc_buffer3 normals,
                                           size_t* singular);

/** DCMC (§6): the parabolic Darboux cyclides through three mutually
 *  non-parallel lines with a common normal n form the family
 *  base + alpha * quadric (phi0 = 0, phi1 = n.X with |n| = 1; `quadric` is
 *  a quadric through the lines). alpha is not canonical (ERRATA): compare
 *  families by membership. normal may be NULL. Statuses:
 *  CYC_E_PARALLEL_LINES, CYC_E_NO_COMMON_NORMAL, CYC_E_RANK_DEFICIENT. */
CYC_API int cyc_dcmc(cyc_context* ctx, const cyc_line lines[3], double normal[3],
                     cyc_darboux* base, cyc_darboux* quadric);

/* ---------------------- lines and circle families of parabolic cyclides (§6-8) */

/** Capacities of cyc_cyclide_lines (frozen): a cubic surface has at
 *  most 10 lines meeting the line l0 at infinity (two in each of five
 *  planes); the real ones on a parabolic cyclide are at most six. */
#define CYC_MAX_CYCLIDE_LINES 10
#define CYC_MAX_SECTION_PLANES 5

/** The degenerate conic of a plane n.X = t through l0 (frozen numbers). */
enum cyc_section_kind {
  CYC_SECTION_LINE_PAIR = 1,      /* two real lines (meeting or parallel) */
  CYC_SECTION_DOUBLE_LINE = 2,    /* one real line counted twice */
  CYC_SECTION_IMAGINARY_PAIR = 3, /* complex conjugate lines */
  CYC_SECTION_LINE_AND_L0 = 4     /* one finite line, l0 counted twice */
};

/** A real line on a parabolic cyclide (frozen). */
typedef struct cyc_cyclide_line {
  double point[3];     /* the point nearest the origin */
  double direction[3]; /* unit, orthogonal to the normal n */
  double t;            /* the line lies in the plane n.X = t */
  int multiplicity;    /* 2 for a double line: its circles count twice */
} cyc_cyclide_line;

/** The lines and circle families of a parabolic cyclide (frozen). Every
 *  plane through a line (except the plane n.X = t) cuts a circle: one
 *  family per line; a double line's family has multiplicity two (a canal
 *  surface: one double line; a Dupin cyclide: two). */
typedef struct cyc_cyclide_lines {
  double normal[3];  /* n: the planes n.X = t contain l0 */
  int plane_count;   /* planes n.X = t whose conic is degenerate */
  double plane_t[CYC_MAX_SECTION_PLANES];
  int plane_kind[CYC_MAX_SECTION_PLANES]; /* enum cyc_section_kind */
  int line_count;    /* distinct real finite lines */
  cyc_cyclide_line lines[CYC_MAX_CYCLIDE_LINES];
  int l0_circles;       /* 1 if the planes n.X = t cut circles (one more family) */
  int circle_families;  /* real families of circles: line_count + l0_circles */
  int double_families;  /* families of multiplicity two (double lines) */
} cyc_cyclide_lines;

/** The real lines of a parabolic (cubic, irreducible) Darboux cyclide and
 *  its families of circles. CYC_E_NOT_PARABOLIC for other types (invert a
 *  quartic at one of its points first: cyc_invert_darboux). */
CYC_API int cyc_parabolic_lines(cyc_context* ctx, const cyc_darboux* d, cyc_cyclide_lines* out);

/** The circle cut from a parabolic cyclide by the plane through its line
 *  `line` with unit normal `plane_normal` (orthogonal to the line), besides
 *  the line itself; for the plane through l0, the other line of the pair
 *  (is_line). CYC_E_INVALID_ARGUMENT if the line is not on the cyclide or
 *  the plane does not contain it; CYC_E_EMPTY_REAL_LOCUS if the circle is
 *  imaginary. */
CYC_API int cyc_pencil_circle(cyc_context* ctx, const cyc_darboux* d, const cyc_line* line,
                              const double plane_normal[3], cyc_circle_or_line* out);

/** Parameterize a parabolic cyclide over u in [u0, u1] (f = v) by PRCS
 *  (kind CYC_SURFACE_PRCS, Prop. 3: needs a double line and three mutually
 *  skew lines; CYC_E_NOT_CANAL without a double line) or PRRS
 *  (CYC_SURFACE_PRRS, Prop. 5: a line and three lines outside its plane,
 *  not all coplanar). The circles u = const lie in the pencil of planes
 *  through one line of the cyclide; CYC_E_TOO_FEW_LINES if the lines are
 *  missing. Of the choices of axis and input lines, the first is taken
 *  whose input lines do not meet at a u in [u0, u1] (the pencil plane
 *  there would have no circle) and whose surface is regular there;
 *  CYC_E_COLLINEAR_POINTS (PRRS) or CYC_E_DEPENDENT_PLANES (PRCS) when no
 *  choice is. The linearly parameterized input lines are written to
 *  `inputs` (3 entries, may be NULL; the third is unused for PRCS).
 *  Allocates the surface (creation tier). */
CYC_API int cyc_parabolic_parameterize(cyc_context* ctx, const cyc_darboux* d, int kind,
                                       double u0, double u1, cyc_line inputs[3],
                                       cyc_surface** out);

/** Seed 000 §8: PRRS of three lines l_i(u) = point + u direction with a
 *  common normal, l1 and l2 in one plane (frozen). In the normal form (52)
 *  the surface is a parabolic cyclide iff (55) and (56) hold (Prop. 4). */
typedef struct cyc_prrs_lines_analysis {
  int coplanar_pair;     /* l1, l2 lie in one plane */
  int common_parameter;  /* l1(u0) = l2(u0) for one u0 */
  double a2, b2, a3, b3, x3, y3; /* the normal form (52) */
  double cond55, cond56; /* the left-hand sides of (55), (56) */
  int pencil;            /* (55): the circle planes form a pencil */
  int cyclide;           /* (55) and (56): a parabolic Darboux cyclide */
  double mu;             /* nonzero root of (56) for d3 -> mu d3 (0: none) */
  cyc_line l4;           /* the pencil's axis (59), if pencil */
} cyc_prrs_lines_analysis;

CYC_API int cyc_prrs_lines_analyze(cyc_context* ctx, const cyc_line lines[3],
                                   cyc_prrs_lines_analysis* out);
/** §8's construction: DCMC on l1, l3, l4 and the member containing l2;
 *  residual (may be NULL) is the largest relative distance of l2 from it,
 *  ~0 exactly when (56) holds. CYC_E_INVALID_ARGUMENT unless l1, l2 meet
 *  in one plane at one parameter and (55) holds. */
CYC_API int cyc_prrs_lines_cyclide(cyc_context* ctx, const cyc_line lines[3], cyc_darboux* out,
                                   double* residual);

/* ------------- implicitization and classification (seed 000 §7, App. A, B) */

/** Bounds of cyc_darboux_fit_points (frozen). */
#define CYC_MIN_FIT_POINTS 20
#define CYC_MAX_FIT_POINTS 64

/** The Darboux cyclide (31) through sample points (frozen). */
typedef struct cyc_darboux_fit {
  cyc_darboux d;      /* normalized: largest |k| = 1, first |k| > 1e-6 positive */
  double residual;    /* max |F|/max(|grad F|, 1e-3) over the samples, relative
                         to the sample box diagonal (a distance estimate) */
  double sigma_ratio; /* smallest / largest singular value of the system */
  int nullity;        /* equations through the points (> 1: sphere or plane;
                         d is then the lowest-degree one) */
  int points;         /* samples used */
  int is_darboux;     /* residual <= 1e-9 */
} cyc_darboux_fit;

/** Fit (31) through `count` points (x, y, z consecutive), count in
 *  [CYC_MIN_FIT_POINTS, CYC_MAX_FIT_POINTS]. */
CYC_API int cyc_darboux_fit_points(cyc_context* ctx, const double* points, int count,
                                   cyc_darboux_fit* out);
/** Fit (31) through 8 x 8 samples of a surface: confirms that a PRCS/PRRS
 *  output is a Darboux cyclide (is_darboux) and gives its equation. */
CYC_API int cyc_darboux_fit_surface(cyc_context* ctx, const cyc_surface* surface,
                                    cyc_darboux_fit* out);

/** What Props. 2, 8, 9 say PRCS/PRRS of the simplest inputs produce (frozen). */
enum cyc_cyclide_kind {
  CYC_CYCLIDE_HYPERBOLOID = 1,        /* Prop. 2 with w.w = 1 */
  CYC_CYCLIDE_PARABOLIC_DARBOUX = 2,  /* case (II) */
  CYC_CYCLIDE_PARABOLIC_DUPIN = 3     /* case (I): PN parameterization */
};

/** The closed-form classification and the normal form (frozen): the input
 *  moved by X' = scale R (X - origin) (R row-major, a rotation) and
 *  reparameterized by u = alpha u' + beta is the paper's normal form (45),
 *  (67)/(68) or (77) with parameters a, b, c. */
typedef struct cyc_lines_classification {
  int kind;            /* enum cyc_cyclide_kind */
  int paper_case;      /* 1 = (I), 2 = (II), 0 = hyperboloid */
  int circle_families; /* distinct real families (0 for the hyperboloid) */
  int double_families; /* of which of multiplicity two */
  int pn;              /* the PRCS/PRRS parameterization is PN */
  int swapped;         /* two lines: l1, l2 exchanged to reach (45) */
  double a, b, c;
  double rotation[9];
  double scale;
  double origin[3];
  double alpha, beta;
} cyc_lines_classification;

/** Prop. 2: PRCS of two lines l_i(u) = point + u direction. Case (I) also
 *  covers c = 0, a = w.w (l1 double), which the paper misses (SPEC §12b).
 *  CYC_E_PARALLEL_LINES, CYC_E_ZERO_TANGENT, CYC_E_NO_NORMAL_FORM (the lines
 *  intersect). */
CYC_API int cyc_classify_two_lines(cyc_context* ctx, const cyc_line* l1, const cyc_line* l2,
                                   cyc_lines_classification* out);
/** Prop. 8 (App. A): PRCS of a line and the line element (p2, w); the
 *  implicit equation (70) in the input coordinates is written to
 *  `implicit` (may be NULL). CYC_E_NO_NORMAL_FORM if p2 is on the line or
 *  w in the plane of the line and p2. */
CYC_API int cyc_classify_line_element(cyc_context* ctx, const cyc_line* l1, const double p2[3],
                                      const double w[3], cyc_lines_classification* out,
                                      cyc_darboux* implicit);
/** Prop. 9 (App. B): PRRS of a line and the points p2, p3.
 *  CYC_E_NO_NORMAL_FORM if they lie in one plane. */
CYC_API int cyc_classify_line_two_points(cyc_context* ctx, const cyc_line* l1,
                                         const double p2[3], const double p3[3],
                                         cyc_lines_classification* out);

/* ------------------------------------------------------------ blends */

/* Blends of seed 000 §9 (SPEC.md "Blends"). Derivative orders up to
 * CYC_MAX_BLEND_ORDER (the Hermite curves have degree 2K+1). */
#define CYC_MAX_BLEND_ORDER 7

/** d^l x/du^l (u, v) for l = 0..K, exact (Taylor-series frames through the
 *  rotation formula), written to out[3*l .. 3*l+2] (capacity 3*(K+1)).
 *  v may be +-infinity (the generator). CYC_E_INVALID_ARGUMENT for K < 0,
 *  CYC_E_DEGREE_TOO_HIGH for K > CYC_MAX_BLEND_ORDER. Allocation-free; on
 *  error nothing is written. */
CYC_API int cyc_surface_derivatives_u(cyc_context* ctx, const cyc_surface* surface, double u,
                                      double v, int K, double* out);

/** One end of a blend: the end circle u of `surface`, the circle parameters
 *  v[j] of the chosen points (v[0], v[1] for canal blends; v[0..2] for
 *  ringed blends) and the free Hermite scalars of the end: the derivatives
 *  of a reparameterization u = phi(t) of the surface at its end circle,
 *  lambda = phi' (the tangent length; its sign is the direction: the blend
 *  continues the start surface and leads into the end surface; 0 chooses +1
 *  or -1 by the nearer end of the surface's domain) and phi[m - 2] =
 *  phi^(m) for m = 2..K (0: none). The blend's curves take the derivatives
 *  d^l/dt^l x(phi(t), v[j]) (Faa di Bruno; with phi = 0 simply lambda^l
 *  d^l x/du^l), so every choice keeps the join geometrically C^K.
 *  A blend of order K reads phi[0..K-2] only (the others are ignored);
 *  zero-initialize the struct ({0}) all the same. u, lambda and the phi
 *  read must lie in |x| <= 1e100; v[j] may be any number but NaN (+-inf is
 *  the circle's point f = infinity). */
typedef struct cyc_blend_end {
  const cyc_surface* surface;
  double u;
  double v[3];
  double lambda;
  double phi[CYC_MAX_BLEND_ORDER - 1];
} cyc_blend_end;

/** Canal blend (§9.1): two C^K Hermite curves (degree 2K+1) on [t0, t1]
 *  through the points v[0], v[1] of both ends, then PRCS; class G^(K-1)
 *  across the joins (Prop. 6). K in 2..CYC_MAX_BLEND_ORDER. Where the normal
 *  planes M, N become (nearly) parallel on [t0, t1], CYC_E_DEPENDENT_PLANES
 *  (the message names the blend parameter), and the other statuses of
 *  cyc_prcs_create; CYC_E_NUMERICAL_OVERFLOW when valid inputs overflow
 *  the construction (lambda^l d^l x or the Hermite coefficients beyond
 *  1e100). Creation: allocates *out (destroy with cyc_surface_destroy);
 *  *out is written only on success. */
CYC_API int cyc_blend_canal(cyc_context* ctx, const cyc_blend_end* start,
                            const cyc_blend_end* end, int K, double t0, double t1,
                            cyc_surface** out);
/** Ringed blend (§9.2): three C^K Hermite curves through v[0..2], then PRRS
 *  (f = v); class C^K (Prop. 7). K in 1..CYC_MAX_BLEND_ORDER. Statuses of
 *  cyc_prrs_create, and CYC_E_NUMERICAL_OVERFLOW as for cyc_blend_canal. */
CYC_API int cyc_blend_ringed(cyc_context* ctx, const cyc_blend_end* start,
                             const cyc_blend_end* end, int K, double t0, double t1,
                             cyc_surface** out);

/** Ringed blend whose circle parameterization continues the inputs' (Prop. 7
 *  with the inputs' own f): the same surface as cyc_blend_ringed, with
 *  f(t, v) = (alpha v + beta)/(gamma v + delta), alpha..delta of degree 2K+1
 *  Hermite-interpolating at each end the Mobius map that carries the input's
 *  circle parameter to the blend's (fixed by the points v[0..2]). For every
 *  v, t -> x(t, v) then continues u -> x_input(phi(u), v) to order K (C^K
 *  parameterizations, not only C^K circles; check with cyc_continuity_report's
 *  point_jump). CYC_E_DEGENERATE_CIRCLE_PARAMETER when no such family exists:
 *  the two inputs' v run in opposite senses relative to the blend's circles
 *  (reparameterize one by v -> -v), or the interpolated map degenerates
 *  inside; otherwise the statuses of cyc_blend_ringed. */
CYC_API int cyc_blend_ringed_matched(cyc_context* ctx, const cyc_blend_end* start,
                                     const cyc_blend_end* end, int K, double t0, double t1,
                                     cyc_surface** out);

/** Piecewise blends (spline Hermite curves where one piece is not enough):
 *  the blend passes through the circles ends[0], ..., ends[n-1] in order
 *  (2 <= n <= CYC_MAX_SPLINE_KNOTS; the interior ones on guide surfaces,
 *  each with lambda != 0: the direction along its guide); piece i runs on
 *  [knots[i], knots[i+1]] from ends[i] to ends[i+1]. Both pieces at an
 *  interior circle take its data with its jet, so consecutive pieces share
 *  that circle and join C^K (ringed) / G^(K-1) (canal), and each piece is
 *  G^K to its guide. Writes n-1 new handles to pieces[0..n-2] (all or
 *  nothing); on a degenerate piece the message names the piece and its
 *  parameter. Statuses of cyc_blend_canal / cyc_blend_ringed,
 *  CYC_E_INVALID_ARGUMENT for n out of range or an interior lambda of 0. */
#define CYC_MAX_SPLINE_KNOTS 16
CYC_API int cyc_blend_canal_spline(cyc_context* ctx, const cyc_blend_end* ends, int n, int K,
                                   const double* knots, cyc_surface** pieces);
CYC_API int cyc_blend_ringed_spline(cyc_context* ctx, const cyc_blend_end* ends, int n, int K,
                                    const double* knots, cyc_surface** pieces);
/** cyc_blend_ringed_spline with matched circle parameterizations
 *  (cyc_blend_ringed_matched) in every piece: the pieces continue each
 *  other's and the guides' parameterizations to order K for every v. */
CYC_API int cyc_blend_ringed_spline_matched(cyc_context* ctx, const cyc_blend_end* ends, int n,
                                            int K, const double* knots, cyc_surface** pieces);

/* ------------------------------------------- ringed surfaces (seed 001) */

/** Hermite data of a ringed surface (d, n, rho) at a join (seed 001 eq. 37):
 *  directrix d and d', orientation function n and n' (with its length), the
 *  circle radius rho and rho'. */
typedef struct cyc_ringed_jet {
  double d[3], dd[3];
  double n[3], dn[3];
  double rho, drho;
} cyc_ringed_jet;

/** The jet of any surface of the library at u: d = the circle's center,
 *  n = its axis, rho = its radius. CYC_E_SINGULAR_POINT for radius 0. */
CYC_API int cyc_surface_ringed_jet(cyc_context* ctx, const cyc_surface* surface, double u,
                                   cyc_ringed_jet* out);

/** Options of cyc_blend_ringed_pcurve (initialize with
 *  cyc_pcurve_blend_options_init). */
typedef struct cyc_pcurve_blend_options {
  int sign;    /* branch of eqs. (43) / (47): +1 (default, "more suitable") or -1 */
  double tau;  /* 0 (default): one P-curve of degree 6, eq. (43); in (0, 1): P-biarc (47) */
  double v[3]; /* projection direction (default (0, 0, 1)); any nonzero length */
} cyc_pcurve_blend_options;
CYC_API void cyc_pcurve_blend_options_init(cyc_pcurve_blend_options* options);

/** The two-surface blend of seed 001 §4 between the ends a (t = 0) and b
 *  (t = 1): (d, n.v, rho) by a Ferguson cubic (eq. 38), the projection of n
 *  perpendicular to v by a planar P-curve (39) of degree 6 (43) or a P-biarc
 *  (47), the curve c = d + rho (n x v)/sigma (4), (15) and the
 *  parameterization (3): exact rational ringed surfaces (CYC_SURFACE_RINGED),
 *  C^1 in the circle family at both ends. Writes one handle (tau = 0, on
 *  [0, 1]) or two ([0, tau], [tau, 1]) to pieces[0..1] and their number to
 *  *count; all or nothing. The P-curve depends on the frame of the plane
 *  perpendicular to v (its e1 is the projection of the x axis, of the y axis
 *  when v is near x): with v = (0, 0, 1) the paper's coordinates.
 *  CYC_E_NOT_PYTHAGOREAN when n is parallel to v at an end (the projected
 *  data vanish: no square root) or so nearly parallel, at an end or inside,
 *  that the planar P-curve's condition exceeds 1e5 (the circles would carry
 *  rounding beyond ~1e-11, their derivatives beyond ~1e-7: choose another v
 *  or sign), CYC_E_NUMERICAL_OVERFLOW when its coefficients exceed 1e100
 *  (tau near 0), CYC_E_BAD_DOMAIN for tau outside [0, 1),
 *  CYC_E_INVALID_ARGUMENT for sign not +-1 or v = 0, and the statuses of
 *  cyc_ringed_create. options may be NULL (defaults). */
CYC_API int cyc_blend_ringed_pcurve(cyc_context* ctx, const cyc_ringed_jet* a,
                                    const cyc_ringed_jet* b,
                                    const cyc_pcurve_blend_options* options,
                                    cyc_surface** pieces, int* count);

/* Ringed surfaces R : (d, n, rho) from their three functions (seed 001 §3):
 * the rational parameterization (3) through the curve c = d + rho f (4), f a
 * rational unit field perpendicular to n found by one of these methods. */
#define CYC_RINGED_FIELD_AUTO 0       /* exact if possible (projection along z, x, y; then
                                         QUADRATIC for deg n <= 2), else SOS */
#define CYC_RINGED_FIELD_PROJECTION 1 /* Prop. 3.2, eqs. (13)-(16): f = n x v / sigma */
#define CYC_RINGED_FIELD_QUADRATIC 2  /* Example 3.3, (17)-(19): v found for quadratic n */
#define CYC_RINGED_FIELD_SOS 3        /* eqs. (20)-(23): numerical sum of squares of |n|^2 */

/** Options of cyc_ringed_dnr_create (initialize with
 *  cyc_ringed_field_options_init). */
typedef struct cyc_ringed_field_options {
  int method;  /* CYC_RINGED_FIELD_* (default AUTO) */
  double v[3]; /* PROJECTION: the direction, any nonzero length (default (0, 0, 1)) */
  int which;   /* QUADRATIC: 0 (default) or 1, which of the (up to two) directions */
} cyc_ringed_field_options;
CYC_API void cyc_ringed_field_options_init(cyc_ringed_field_options* options);

/** What cyc_ringed_dnr_create did. */
typedef struct cyc_ringed_field_report {
  int method;          /* the method used (never AUTO) */
  double v[3];         /* PROJECTION / QUADRATIC: the unit direction used */
  int directions;      /* QUADRATIC: the number of directions found (1 or 2) */
  double sos_residual; /* SOS: max |coef(g1^2 + g2^2 - |N|^2)| / max |coef(|N|^2)|: |f| = 1
                          and f.n = 0 hold to about this (0 for the exact methods) */
  double sos_margin;   /* SOS: min (|H|^2 + n3^2) / |N|^2 over the real roots of n3, in (0, 4] */
} cyc_ringed_field_report;

/** The ringed surface (d, n, rho) with rho = rho_num / rho_den, polynomials in
 *  power form of degrees rho_num_degree / rho_den_degree (rho_den NULL: 1),
 *  d a curve or point, n a polynomial or rational curve (for the field only
 *  its numerator matters: it spans the same planes). The field f by
 *  options->method (NULL: defaults); report (may be NULL) receives what was
 *  done. The surface is CYC_SURFACE_RINGED, exact rational for PROJECTION
 *  and QUADRATIC; for SOS its circles are exact but |f| = 1 only to
 *  report->sos_residual (the radius is rho |f|). Statuses:
 *  CYC_E_NOT_PYTHAGOREAN (|n x v| is not a polynomial: Prop. 3.2 does not
 *  apply; SOS: roots too ill-conditioned), CYC_E_INVALID_ARGUMENT (v = 0,
 *  which not 0/1 or beyond the directions found, QUADRATIC for deg n > 2, a
 *  line element, n = 0, an unknown method), CYC_E_DEGREE_TOO_HIGH (SOS: 2 deg
 *  n > 14; c beyond the degree bound), and those of cyc_ringed_create on the
 *  domain (where sigma or the SOS denominator vanishes f is undefined).
 *  All or nothing. */
CYC_API int cyc_ringed_dnr_create(cyc_context* ctx, const cyc_curve* d, const cyc_curve* n,
                                  int rho_num_degree, const double* rho_num,
                                  int rho_den_degree, const double* rho_den,
                                  const cyc_ringed_field_options* options, const cyc_mobius* f,
                                  double u0, double u1, cyc_surface** out,
                                  cyc_ringed_field_report* report);

/** What cyc_ringed_sqrt_create did. */
typedef struct cyc_ringed_sqrt_report {
  cyc_ringed_field_report field; /* how the unit field u perpendicular to n was found */
  int exact_square;              /* 1: R_num R_den was a polynomial square (rho rational) */
  double conic_residual;         /* max |coef(a^2 + |n|^2 b^2 - R_num R_den c^2)| over the
                                    largest coefficient of the terms: |f|^2 = R holds to
                                    about this (0 if exact_square) */
  int conic_degree;              /* degree of the reduced conic's coefficient product */
} cyc_ringed_sqrt_report;

/** Seed 001 §3.d, Theorem 3.6: the ringed surface (d, n, rho = sqrt(R)) with
 *  R = R_num / R_den >= 0 a rational function that need not be a square (a
 *  canal surface seen as ringed has such a radius, eq. (24)). f with n.f = 0
 *  and f.f = R (25) is f = (a u + b n x u) / (c R_den), u the unit field of
 *  options (as in cyc_ringed_dnr_create), a, b, c polynomials solving the
 *  conic a^2 + |n|^2 b^2 = R_num R_den c^2 over R[t] (the paper's (34)-(35)),
 *  found NUMERICALLY (roots by the companion matrix, a null space, an
 *  isotropic vector, Gauss-Newton polish); c = d + f (26). The surface is
 *  CYC_SURFACE_RINGED with exact circles; |f|^2 = R to
 *  report->conic_residual. Statuses: CYC_E_EMPTY_REAL_LOCUS (R < 0 somewhere
 *  on the real line), CYC_E_INVALID_ARGUMENT (R_num or R_den zero, n zero, a
 *  point or line element), CYC_E_DEGREE_TOO_HIGH (R_num R_den or 2 deg n
 *  beyond 14, f beyond CYC_MAX_CURVE_DEGREE), CYC_E_NOT_PYTHAGOREAN (the
 *  numerical conic step left a remainder above 1e-8), those of
 *  cyc_ringed_dnr_create's field, and those of cyc_ringed_create on the
 *  domain (CYC_E_SINGULAR_POINT where R = 0). All or nothing. */
CYC_API int cyc_ringed_sqrt_create(cyc_context* ctx, const cyc_curve* d, const cyc_curve* n,
                                   int R_num_degree, const double* R_num, int R_den_degree,
                                   const double* R_den, const cyc_ringed_field_options* options,
                                   const cyc_mobius* f, double u0, double u1, cyc_surface** out,
                                   cyc_ringed_sqrt_report* report);

/** Prop. 3.1: the ringed surface (d, n, rho) whose orientation function n is
 *  the spatial P-curve (8) of the quaternion polynomial x0 + x1 i + x2 j +
 *  x3 k, given as x_degree + 1 rows (x0, x1, x2, x3), row k the coefficients
 *  of u^k; f = (cos phi n1 + sin phi n2) / sigma (10)-(12); rho as in
 *  cyc_ringed_dnr_create. Exact rational. CYC_E_INVALID_ARGUMENT for x = 0
 *  or x_degree < 0, CYC_E_DEGREE_TOO_HIGH for 2 x_degree >
 *  CYC_MAX_CURVE_DEGREE (x_degree is compared with its bound before x is
 *  read), then the statuses of cyc_ringed_create. */
CYC_API int cyc_ringed_pcurve_create(cyc_context* ctx, const cyc_curve* d, int x_degree,
                                     const double* x, double phi, int rho_num_degree,
                                     const double* rho_num, int rho_den_degree,
                                     const double* rho_den, const cyc_mobius* f, double u0,
                                     double u1, cyc_surface** out);

/** Seed 001 §5, eqs. (50)-(52), (57): a bump added to the directrix of the
 *  P-curve blend, d* = d + w b(t) (the paper's (50) calls w "v").
 *  b(0) = b'(0) = b(1) = b'(1) = 0, b(tau) = 1, b'(tau) = 0. */
#define CYC_BUMP_SINGLE 0    /* (52) with the sign of ERRATA.md (+1 at tau), a quintic */
#define CYC_BUMP_TWO_PIECE 1 /* (57): cubics on [0, tau] and [tau, 1]; the blend is split at tau */
typedef struct cyc_directrix_bump {
  double w[3]; /* displacement of d at t = tau (all zero: no bump) */
  double tau;  /* in (0, 1) */
  int kind;    /* CYC_BUMP_* */
} cyc_directrix_bump;

/** cyc_blend_ringed_pcurve with the directrix moved by bump (NULL: none):
 *  only d moves (n, rho and f are kept), so the circles are translated by
 *  w b(t) and the ends (51) keep their Hermite data. A two-piece bump gives
 *  two pieces [0, tau], [tau, 1] (with a P-biarc only at the same tau:
 *  else CYC_E_INVALID_ARGUMENT). CYC_E_BAD_DOMAIN for the bump's tau
 *  outside (0, 1) when w != 0, CYC_E_INVALID_ARGUMENT for an unknown kind;
 *  else as cyc_blend_ringed_pcurve. */
CYC_API int cyc_blend_ringed_pcurve_bump(cyc_context* ctx, const cyc_ringed_jet* a,
                                         const cyc_ringed_jet* b,
                                         const cyc_pcurve_blend_options* options,
                                         const cyc_directrix_bump* bump, cyc_surface** pieces,
                                         int* count);

/* ------------------------- n-way blends through a sphere (seed 001 §6) */

/** At most this many ends in cyc_blend_ringed_nway. */
#define CYC_NWAY_MAX_ENDS 8
/* Where the auxiliary sphere's center s comes from (eq. 63). */
#define CYC_NWAY_CENTER_AUTO 0  /* s = y + alpha N, alpha from the end tangents (default) */
#define CYC_NWAY_CENTER_ALPHA 1 /* s = y + alpha N with options.alpha */
#define CYC_NWAY_CENTER_GIVEN 2 /* s = options.s (Example 6.2, eq. 69) */
/* On which side of s the joining circle c_i = S_i(lambda_i) lies (eq. 66). */
#define CYC_NWAY_SIDE_FACING 0  /* S_i runs from the pole facing R_i's end (default) */
#define CYC_NWAY_SIDE_PRINTED 1 /* (66) as printed: small lambda beyond s, away from R_i */

/** Options of cyc_blend_ringed_nway (initialize with cyc_nway_options_init). */
typedef struct cyc_nway_options {
  int center;        /* CYC_NWAY_CENTER_* */
  double alpha;      /* CENTER_ALPHA: the factor of N in (63) */
  double s[3];       /* CENTER_GIVEN: the center */
  double r;          /* > 0: the radius; 0 (default): r_fraction * bound (65) */
  double r_fraction; /* in (0, 1), default 0.5 */
  double lambda[CYC_NWAY_MAX_ENDS]; /* each in (0, 1), default 0.5: c_i = S_i(lambda_i) */
  int side;             /* CYC_NWAY_SIDE_* */
  int require_disjoint; /* nonzero (default): intersecting joining circles are an error */
  int auto_v;  /* nonzero (default): each blend projects along n_a x n_b; 0: blend.v */
  cyc_pcurve_blend_options blend; /* sign, tau and v of every blend */
  int auto_lambda; /* nonzero: lambda[] ignored, each lambda_i chosen so that the circles
                      keep a gap of at least a tenth of their axes' angle (theta_i = 0.45
                      min_j angle(axis_i, axis_j)); default 0 */
} cyc_nway_options;
CYC_API void cyc_nway_options_init(cyc_nway_options* options);

/** What cyc_blend_ringed_nway computed (ends i < n; the rest zero). */
typedef struct cyc_nway_report {
  double y[3];        /* (64): the incentre (n = 3) or centroid (n > 3) of the end centers */
  double normal[3];   /* (63): N = sum_k d_k x d_k+1 (= (d1 - d2) x (d1 - d3) for n = 3) */
  double alpha;       /* the alpha used (0 for CENTER_GIVEN) */
  double s[3], r;     /* the sphere */
  double bound;       /* (65): min |d_i - s|; r in (0, bound) */
  double clear_bound; /* min (|d_i - s| - rho_i): below it the end circles miss the sphere */
  double n_star[CYC_NWAY_MAX_ENDS][3]; /* (66): (d_i - s) / |d_i - s| */
  double distance[CYC_NWAY_MAX_ENDS];  /* |d_i - s| */
  double theta[CYC_NWAY_MAX_ENDS];     /* angular radius of c_i: cos = 1 - 2 lambda_i */
  double gap[CYC_NWAY_MAX_ENDS][CYC_NWAY_MAX_ENDS]; /* signed angular gap of c_i, c_j (rad):
                                                       > 0 disjoint, <= 0 intersecting */
  int nested[CYC_NWAY_MAX_ENDS][CYC_NWAY_MAX_ENDS]; /* disjoint, one cap inside the other */
  double min_gap;
  int worst_i, worst_j;                             /* the pair of min_gap */
  cyc_ringed_jet end_jet[CYC_NWAY_MAX_ENDS];        /* R_i at its end, moving away from R_i */
  cyc_ringed_jet sphere_jet[CYC_NWAY_MAX_ENDS];     /* S_i at lambda_i (67), as interpolated */
  double v[CYC_NWAY_MAX_ENDS][3];                   /* each blend's projection direction */
  int failed_end;                                   /* the blend that failed, -1: none */
  double lambda[CYC_NWAY_MAX_ENDS];                 /* the lambda_i used (given or chosen) */
} cyc_nway_report;

/** Seed 001 §6, eqs. (62)-(67): the n-way blend (3 <= n <= CYC_NWAY_MAX_ENDS)
 *  of the ringed surfaces ends[i] at their end parameters end_u[i] (the
 *  nearer end of the domain says which way R_i leaves: at u1 as is, at u0
 *  reversed) through an auxiliary sphere (s, r): s on the line through the
 *  incentre y of the end centers along N (63), (64), r in (0, min |d_i - s|)
 *  (65); the sphere seen from R_i as the ringed surface S_i (66); and for
 *  each i the two-surface P-curve blend B_i (cyc_blend_ringed_pcurve) from
 *  R_i's end (t = 0) to the joining circle c_i = S_i(lambda_i) (t = 1),
 *  C^1 in (d, n, rho) at both ends. S_i's n is the unit direction of travel
 *  into the sphere, signed like n_i . d_i' at R_i's end.
 *  blends has 2 n slots: B_i is blends[2i] (and blends[2i + 1] for a P-biarc
 *  or two-piece split; else NULL), counts[i] its number of pieces. All or
 *  nothing: the handles and counts are written only on success. report (may
 *  be NULL) is written on every return but CYC_E_NULL_ARGUMENT, as far as
 *  the construction got. Statuses: CYC_E_INVALID_ARGUMENT (n out of range,
 *  r < 0, r_fraction outside (0, 1), unknown center/side, sign not +-1),
 *  CYC_E_NOT_FINITE, CYC_E_COLLINEAR_POINTS (end centers collinear or
 *  coincident: no incentre, no plane), CYC_E_BAD_DOMAIN (end_u outside the
 *  domain, a lambda outside (0, 1), r outside (0, bound): an end center in
 *  the sphere), CYC_E_INTERSECTING_CIRCLES (two joining circles meet and
 *  require_disjoint), then the statuses of cyc_surface_ringed_jet and
 *  cyc_blend_ringed_pcurve (report->failed_end names the blend). */
CYC_API int cyc_blend_ringed_nway(cyc_context* ctx, const cyc_surface* const* ends,
                                  const double* end_u, int n, const cyc_nway_options* options,
                                  cyc_surface** blends, int* counts, cyc_nway_report* report);

/** The sphere (center, radius) as a ringed surface for display: circles
 *  perpendicular to axis (any nonzero length), u in [1e-3, 1 - 1e-3] (the
 *  poles, where the circles vanish, are left out). Exact rational. */
CYC_API int cyc_nway_sphere_create(cyc_context* ctx, const double center[3], double radius,
                                   const double axis[3], cyc_surface** out);

/** Eq. (54): the clearance min over the domain of |d(u) - s| - rho(u) - r of
 *  any surface of the library (d the circle's center) from the sphere
 *  (center, radius): positive means no circle meets the sphere (sufficient,
 *  not necessary). 257 samples and golden-section refinement (1e-12 in u);
 *  *at_u (may be NULL) receives the minimizer. CYC_E_INVALID_ARGUMENT for
 *  radius < 0. */
CYC_API int cyc_surface_sphere_clearance(cyc_context* ctx, const cyc_surface* surface,
                                         const double center[3], double radius,
                                         double* clearance, double* at_u);

/** Eq. (58): the integral over the domain of sin^2 of the angle between the
 *  circle axis n and the directrix tangent d' (how far a ringed surface is
 *  from a normal one; Example 5.2), composite Simpson on 1024 intervals.
 *  CYC_E_SINGULAR_POINT where d' = 0. */
CYC_API int cyc_surface_normal_deviance(cyc_context* ctx, const cyc_surface* surface,
                                        double* value);

/** Contour points (seed 001 Definition 7.1: the surface normal is orthogonal
 *  to v; the silhouette in the projection along v) on the circle at u of
 *  any surface of the library, v of any nonzero length: up to 4 points,
 *  ordered by angle on the circle, written as rows of 3 doubles to points
 *  (capacity counts doubles and must be >= 12), their number to *count;
 *  *whole_circle = 1 (and *count = 0) when every point of the circle
 *  qualifies (the definition excludes the sweeping circles). Each point is
 *  a root of a quartic, exact to rounding (the general contour curve (70)
 *  has nested square roots). CYC_E_INVALID_ARGUMENT for v = 0,
 *  CYC_E_BUFFER_TOO_SMALL, CYC_E_SINGULAR_POINT for radius 0, and the
 *  statuses of cyc_surface_ringed_data at u. All or nothing. */
CYC_API int cyc_surface_contour_points(cyc_context* ctx, const cyc_surface* surface, double u,
                                       const double v[3], double* points, size_t capacity,
                                       int* count, int* whole_circle);

/** Eqs. (71), (72), Prop. 7.2: for a ringed surface (d, n, rho) with
 *  polynomial n, n.v = 0 identically and |n| a polynomial (n a P-curve),
 *  the two rational contour curves c+- = d +- rho (n x v)/|n| (rho as in
 *  cyc_ringed_dnr_create). CYC_E_INVALID_ARGUMENT if n.v is not 0 (relative
 *  1e-12 of n's coefficients) or v = 0, CYC_E_NOT_PYTHAGOREAN if |n| is not a
 *  polynomial (then no rational contour curve exists). Writes both handles
 *  or neither. */
CYC_API int cyc_ringed_contour_curves(cyc_context* ctx, const cyc_curve* d, const cyc_curve* n,
                                      int rho_num_degree, const double* rho_num,
                                      int rho_den_degree, const double* rho_den,
                                      const double v[3], cyc_curve** plus, cyc_curve** minus);

/** Continuity of the join of surface a at u = ua and surface b at u = ub
 *  along a common circle, at the points x_a(ua, va[i]) and their closest
 *  points on b's circle. lambda = du_a/du_b. All jumps compare b's
 *  derivatives with lambda^l times a's. */
typedef struct cyc_continuity {
  int K;                    /* orders 0..K compared */
  int samples;
  int singular_samples;     /* a normal undefined there (angle skipped) */
  double max_gap;           /* max |x_a - x_b| */
  double point_scale;       /* max |x|, radius: for relative gaps */
  double max_normal_angle;  /* radians in [0, pi/2] between tangent planes */
  /* max |d^l x_b - lambda^l d^l x_a| at corresponding points, and the
   * largest norm of the two: C^K of the parameterizations (zero only where
   * the circle parameterizations agree to order K). */
  double point_jump[CYC_MAX_BLEND_ORDER + 1];
  double point_scale_l[CYC_MAX_BLEND_ORDER + 1];
  /* relative jump of the l-th u-derivative of the circle's center, unit
   * normal and radius^2 (the largest): C^K of the surface up to a
   * reparameterization of its circles (Prop. 7). */
  double circle_jump[CYC_MAX_BLEND_ORDER + 1];
} cyc_continuity;

/** va: n circle parameters of a, 1 <= n <= 1048576 (NULL: n parameters
 *  spread over the whole circle); other n are CYC_E_INVALID_ARGUMENT. K in
 *  0..CYC_MAX_BLEND_ORDER. CYC_E_NUMERICAL_OVERFLOW if
 *  lambda^l d^l x overflows. Allocation-free; *out is written only on
 *  success. */
CYC_API int cyc_continuity_report(cyc_context* ctx, const cyc_surface* a, double ua,
                                  double lambda, const cyc_surface* b, double ub, int K,
                                  const double* va, int n, cyc_continuity* out);

/* ------------------------------------------------------------ optimizer */

/** 1 if this build includes the Ceres-based optimizer tier, else 0. The
 *  cyc_optimize_* entry points of later versions return CYC_E_UNSUPPORTED
 *  when it is 0. */
CYC_API int cyc_optimizer_available(void);

/** Point inversion: the parameters (u, v) of the point of the surface
 *  closest to `point` (u within the domain), that point and its distance.
 *  A closed-form scan of the circles gives the start, Levenberg-Marquardt
 *  (Ceres) refines it. Optimizer tier: may allocate; CYC_E_UNSUPPORTED
 *  without Ceres. Any of closest/distance may be NULL. */
CYC_API int cyc_optimize_closest_point(cyc_context* ctx, const cyc_surface* surface,
                                       const double point[3], double* u, double* v,
                                       double closest[3], double* distance);

/* ------------------------------------------------------------ blend optimizer */

/* The free parameters of a blend — the jets (lambda = phi', phi'', ...) of
 * both ends, see cyc_blend_end, and optionally where the chosen points v[]
 * lie on the end circles (circle_parameter_range) — chosen by a box-constrained
 * Levenberg-Marquardt (exact derivatives by Ceres' automatic differentiation
 * through the construction) against a weighted objective (SPEC.md §8e). */
#define CYC_BLEND_CANAL 0  /* cyc_blend_canal: K in 2..CYC_MAX_BLEND_ORDER */
#define CYC_BLEND_RINGED 1 /* cyc_blend_ringed: K in 1..CYC_MAX_BLEND_ORDER */
#define CYC_MAX_QUADRATURE 16

/** The blend's circle at parameter t should pass through `point`. */
typedef struct cyc_blend_target {
  double point[3];
  double t;
} cyc_blend_target;

/** A sphere the blend's circles should keep `clearance` away from. */
typedef struct cyc_blend_obstacle {
  double center[3];
  double radius;
} cyc_blend_obstacle;

/** The objective: a weighted sum of
 *  - fairness: the integral of |x_tt|^2 + 2 |x_tv|^2 + |x_vv|^2 over the
 *    blend (Gauss-Legendre, quadrature_t nodes in t and quadrature_v per
 *    chart of the circle: v in [-1, 1] and 1/v in [-1, 1]), divided by the
 *    start blend's (so the term starts at fairness / 2);
 *  - regularity: hinge penalties keeping the PRCS/PRRS planes' relative
 *    determinant above min_determinant at the t nodes (the paper's weakness:
 *    parallel normal planes) and |x_t| above min_speed L;
 *  - targets: the blend's circle at t_k passing through X_k (distance / L);
 *  - obstacles: every circle at the t nodes at least radius + clearance
 *    from each obstacle's center (closed-form point-circle distance; hinge).
 *  L is the size of the two end circles and their distance. Weights are
 *  >= 0; counts 0..4096 (each target or obstacle adds residuals at every
 *  node); arrays may be NULL only with count 0. Every field is checked by
 *  name (objective.targets[1].point[2] ...). */
typedef struct cyc_blend_objective {
  double fairness;        /* default 1 */
  double regularity;      /* default 1 */
  double min_determinant; /* in (0, 1), default 1e-2 */
  double min_speed;       /* > 0, default 1e-2 */
  const cyc_blend_target* targets;
  int target_count;
  double target_weight;   /* default 1 */
  const cyc_blend_obstacle* obstacles;
  int obstacle_count;
  double clearance;       /* >= 0, default 0 */
  double obstacle_weight; /* default 1 */
  int quadrature_t;       /* 1..CYC_MAX_QUADRATURE, default 8 */
  int quadrature_v;       /* 1..CYC_MAX_QUADRATURE, default 4 */
} cyc_blend_objective;

/** Solver options and the parameters' bounds. free_orders: 1 = only the
 *  tangent lengths lambda of both ends, m = phi', ..., phi^(m); 0 = min(K,
 *  2); higher orders keep the given phi. |phi'| stays within
 *  [lambda_min_ratio, lambda_max_ratio] times the start |lambda| (with its
 *  sign), |phi^(m)| <= higher_bound |lambda|. circle_parameter_range > 0
 *  frees the chosen points too (seed 000 §9.1 (i)): each v[j] as the angle
 *  theta = 2 atan v (radians; v = infinity is theta = pi) moves within
 *  theta_0 +- min(circle_parameter_range, 0.45 x the angle to its end's
 *  nearest other point), so the points stay distinct and in order; the
 *  chosen ends then carry the new v[] (a point that did not move keeps
 *  its v exactly). 0 keeps the points. */
typedef struct cyc_optimize_options {
  int free_orders;           /* 0..K, default 0 */
  double lambda_min_ratio;   /* in (0, 1], default 0.25 */
  double lambda_max_ratio;   /* >= 1, default 4 */
  double higher_bound;       /* >= 0, default 4 */
  double circle_parameter_range; /* >= 0 radians, default 0 (points kept) */
  int max_iterations;        /* >= 0 (0: the start blend), default 50 */
  double function_tolerance; /* tolerances as Ceres' (SPEC §8e), default 1e-8 */
  double gradient_tolerance; /* default 1e-10 */
  double parameter_tolerance; /* default 1e-8 */
} cyc_optimize_options;

#define CYC_OPTIMIZE_CONVERGED 0       /* a tolerance was met */
#define CYC_OPTIMIZE_ITERATION_LIMIT 1 /* max_iterations reached; the best point */
#define CYC_OPTIMIZE_REVERTED 2        /* the optimum was no valid blend: the start */

/** What the optimizer did. Costs are 1/2 the sum of squared residuals;
 *  final_cost <= initial_cost always (the start is the default blend, or
 *  the first valid of its lambdas scaled by 1/2, 2, 1/4, 4). */
typedef struct cyc_optimize_summary {
  double initial_cost;
  double final_cost;
  int iterations;
  double seconds;
  int termination;  /* CYC_OPTIMIZE_* */
  double fairness, regularity, targets, obstacles; /* the final cost's terms */
  double length_scale;   /* L */
  double fairness_scale; /* the start blend's fairness integral */
} cyc_optimize_summary;

/** The defaults above (usable without the optimizer tier). NULL is ignored. */
CYC_API void cyc_blend_objective_init(cyc_blend_objective* objective);
CYC_API void cyc_optimize_options_init(cyc_optimize_options* options);

/** Optimizes the blend of `kind` (CYC_BLEND_CANAL or CYC_BLEND_RINGED) from
 *  start to end on [t0, t1]: the ends' lambda and phi[] are the start
 *  values. Writes the blend to *out (a new handle), and optionally the
 *  chosen ends (same surfaces, the optimized lambda, phi and, if freed, v) and
 *  the summary. objective / options NULL: the defaults. Statuses:
 *  CYC_E_INVALID_ARGUMENT (a bad weight, quadrature, bound, count or kind),
 *  CYC_E_NOT_FINITE, CYC_E_NULL_ARGUMENT, CYC_E_DEGREE_TOO_HIGH, and those of
 *  cyc_blend_canal / cyc_blend_ringed when no start blend is valid. Only
 *  the phi[m - 2] with m <= K and the v[] of the kind (2 canal, 3 ringed)
 *  are read and checked; in the chosen ends the others are 0.
 *  Optimizer tier: allocates; CYC_E_UNSUPPORTED without Ceres. Nothing is
 *  written on error. */
CYC_API int cyc_optimize_blend(cyc_context* ctx, int kind, const cyc_blend_end* start,
                               const cyc_blend_end* end, int K, double t0, double t1,
                               const cyc_blend_objective* objective,
                               const cyc_optimize_options* options, cyc_surface** out,
                               cyc_blend_end* start_out, cyc_blend_end* end_out,
                               cyc_optimize_summary* summary);

/** Seed 001 §5.a: the objective of cyc_optimize_pcurve_bump, a weighted sum
 *  of the deviance (58) (the integral of sin^2 angle(n, d*') by the midpoint
 *  rule on `nodes` nodes) and, per obstacle, the mean over the nodes of the
 *  squared hinge max(0, (radius + clearance + (|d*'| + |rho'|) / (2 nodes)
 *  - (|d*(t) - center| - rho(t))) / L) (eq. (54) with a margin, covering
 *  each node's cell to first order; L = the ends' distance plus their
 *  radii). */
typedef struct cyc_bump_objective {
  double deviance; /* weight, default 1 */
  const cyc_blend_obstacle* obstacles;
  int obstacle_count;
  double clearance;       /* >= 0, default 0 */
  double obstacle_weight; /* default 1 */
  int nodes;              /* 4..1024, default 64 (obstacle_count 0..4096) */
} cyc_bump_objective;

/** Bounds and solver options of cyc_optimize_pcurve_bump. */
typedef struct cyc_bump_options {
  double w_bound;             /* |w_j| <= w_bound L, default 2 */
  double tau_min, tau_max;    /* tau's box inside (0, 1), default [0.2, 0.8] */
  int free_tau;               /* 1 (default): tau is optimized; 0: kept */
  int max_iterations;         /* >= 0, default 50 */
  double function_tolerance;  /* Ceres', default 1e-10 */
  double gradient_tolerance;  /* default 1e-12 */
  double parameter_tolerance; /* default 1e-10 */
} cyc_bump_options;

/** The defaults above (usable without the optimizer tier). NULL is ignored. */
CYC_API void cyc_bump_objective_init(cyc_bump_objective* objective);
CYC_API void cyc_bump_options_init(cyc_bump_options* options);

/** Ceres chooses the bump (w, and tau if free) of the P-curve blend of a and
 *  b (cyc_blend_ringed_pcurve_bump) starting from `start` (NULL: w = 0, tau
 *  = 1/2, single; its kind is kept): the "more normal" blend of Example 5.2
 *  and/or clearing spherical obstacles. d* and d*' are exact in (w, tau)
 *  (only the directrix moves), so the derivatives are Jets (autodiff).
 *  Writes the blend's pieces (1 or 2) and *count, the chosen bump (may be
 *  NULL) and the summary (may be NULL; fairness = the final deviance term,
 *  obstacles = the obstacle term). final_cost <= initial_cost always (the
 *  start is returned, termination CYC_OPTIMIZE_REVERTED, if the optimum
 *  is worse or no valid blend). Statuses: CYC_E_INVALID_ARGUMENT (weights
 *  < 0, nodes, bounds, counts, a two-piece bump with a P-biarc and free
 *  tau), CYC_E_NOT_FINITE, CYC_E_NULL_ARGUMENT, CYC_E_SINGULAR_POINT (d*' =
 *  0 at a node of the start), those of cyc_blend_ringed_pcurve_bump.
 *  Optimizer tier: allocates; CYC_E_UNSUPPORTED without Ceres. Nothing is
 *  written on error. */
CYC_API int cyc_optimize_pcurve_bump(cyc_context* ctx, const cyc_ringed_jet* a,
                                     const cyc_ringed_jet* b,
                                     const cyc_pcurve_blend_options* blend,
                                     const cyc_directrix_bump* start,
                                     const cyc_bump_objective* objective,
                                     const cyc_bump_options* options, cyc_surface** pieces,
                                     int* count, cyc_directrix_bump* chosen,
                                     cyc_optimize_summary* summary);

/* Issue 4: the common description of the optimizers' free parameters. Each
 * cyc_optimize_* entry point solves for a list of these; the _parameters
 * queries list them (boxes and starts) for the same inputs without
 * solving. The chosen values are what the optimizer returns (the ends'
 * lambda and phi[], the chosen bump). */
#define CYC_PARAMETER_JET 0               /* phi^(order) at end `index` (0 start, 1 end);
                                             order 1 = lambda */
#define CYC_PARAMETER_BUMP_DISPLACEMENT 1 /* w[index] of the directrix bump */
#define CYC_PARAMETER_BUMP_POSITION 2     /* tau of the directrix bump */
#define CYC_PARAMETER_CIRCLE_POINT 3      /* theta = 2 atan v[order] at end `index` */
#define CYC_PARAMETER_FAMILY 4            /* phi = atan(unit alpha) of a double cyclide
                                             blend on branch `index` (+1 or -1); unit:
                                             see cyc_cyclide_blend_auto */
typedef struct cyc_free_parameter {
  int role;            /* CYC_PARAMETER_* */
  int index;           /* the end or the component */
  int order;           /* the derivative order (CYC_PARAMETER_JET), the point
                          j (CYC_PARAMETER_CIRCLE_POINT), else 0 */
  double lower, upper; /* the box; lower == upper: held fixed */
  double start;        /* the start value (inside the box) */
} cyc_free_parameter;

/** The free parameters of cyc_optimize_blend for these inputs (its start
 *  search included). params NULL: only *count (a size query); else up to
 *  capacity entries and *count. CYC_E_BUFFER_TOO_SMALL if capacity < the
 *  count, then cyc_optimize_blend's validation and start-search statuses.
 *  Optimizer tier; CYC_E_UNSUPPORTED without Ceres. Nothing is written on
 *  error. */
CYC_API int cyc_optimize_blend_parameters(cyc_context* ctx, int kind,
                                          const cyc_blend_end* start, const cyc_blend_end* end,
                                          int K, double t0, double t1,
                                          const cyc_optimize_options* options,
                                          cyc_free_parameter* params, int capacity, int* count);

/** The free parameters of cyc_optimize_pcurve_bump (w's components in
 *  [-w_bound L, w_bound L], tau in [tau_min, tau_max] or held), as
 *  cyc_optimize_blend_parameters. */
CYC_API int cyc_optimize_pcurve_bump_parameters(cyc_context* ctx, const cyc_ringed_jet* a,
                                                const cyc_ringed_jet* b,
                                                const cyc_pcurve_blend_options* blend,
                                                const cyc_directrix_bump* start,
                                                const cyc_bump_options* options,
                                                cyc_free_parameter* params, int capacity,
                                                int* count);

/* ------------------------------------------------------------------ */
/* Seed 001 §7.a: implicit ringed blends and their approximation       */

/** The implicit blend (73) f = f1 (1 - lambda) f20^(n+1) - f2 lambda
 *  f10^(n+1) of two quadrics f1, f2 bounded by the planes f10 = 0, f20 = 0.
 *  A quadric's 10 coefficients are those of
 *    q0 x^2 + q1 y^2 + q2 z^2 + q3 xy + q4 xz + q5 yz + q6 x + q7 y + q8 z + q9,
 *  a plane's 4 those of a x + b y + c z + d. */
typedef struct cyc_implicit_blend {
  double f1[10];
  double f2[10];
  double f10[4];
  double f20[4];
  double lambda; /* in (0, 1) */
  int n;         /* 1..CYC_MAX_IMPLICIT_EXPONENT */
} cyc_implicit_blend;

#define CYC_MAX_IMPLICIT_EXPONENT 16
#define CYC_MAX_IMPLICIT_PIECES 8

/** The coefficients of the cylinder of revolution through `point` with
 *  axis `direction` and radius > 0, or of the cone with apex, axis and
 *  half-angle in (0, pi/2). CYC_E_INVALID_ARGUMENT for a zero direction or
 *  radius/angle out of range, CYC_E_NOT_FINITE. coeffs written on success. */
CYC_API int cyc_implicit_cylinder(cyc_context* ctx, const double point[3],
                                  const double direction[3], double radius, double coeffs[10]);
CYC_API int cyc_implicit_cone(cyc_context* ctx, const double apex[3], const double axis[3],
                              double half_angle, double coeffs[10]);

/** f (73) at x, its gradient (may be NULL) and, with v given (may be
 *  NULL), the contour function f_v = grad f . v (76) and its gradient
 *  H v (may be NULL). Statuses: CYC_E_INVALID_ARGUMENT (lambda outside
 *  (0, 1), n outside 1..16, a zero plane normal or quadratic part),
 *  CYC_E_NOT_FINITE (an input field, named in the message),
 *  CYC_E_NUMERICAL_OVERFLOW (f or a derivative overflows at x),
 *  CYC_E_DEPENDENT_PLANES (coincident bounding planes). Allocation-free;
 *  outputs written only on success. */
CYC_API int cyc_implicit_blend_eval(cyc_context* ctx, const cyc_implicit_blend* blend,
                                    const double x[3], double* f, double grad[3],
                                    const double v[3], double* f_v, double grad_f_v[3]);

/** The contour points (77) (end 0: on f10 = 0) or (78) (end 1: on f20 =
 *  0) for the direction v: up to 2 points (x, y, z each) and *count;
 *  *whole_circle (may be NULL) is set when every point of the end circle
 *  qualifies (count 0). CYC_E_SINGULAR_POINT when a point lies on the
 *  other bounding plane. Allocation-free. */
CYC_API int cyc_implicit_contour_points(cyc_context* ctx, const cyc_implicit_blend* blend,
                                        int end, const double v[3], int* count,
                                        double points[6], int* whole_circle);

/** Options of cyc_optimize_implicit_blend (defaults by _init). */
typedef struct cyc_implicit_approx_options {
  int pieces;              /* 1..CYC_MAX_IMPLICIT_PIECES, default 1: cut planes (84) */
  double psi_weight;       /* w of (81), default 0.01 (Psi scaled by |s2 - s1|^2) */
  int nodes;               /* Gauss-Legendre nodes of (82), (83): 2..64, default 16 */
  double length_min_ratio; /* alpha, beta in [min, max] |q - p|: default 0.1, 4 */
  double length_max_ratio;
  int max_iterations;      /* default 50 */
  double function_tolerance, gradient_tolerance, parameter_tolerance;
  int error_nodes_t;       /* (87): Gauss-Legendre in t, 1..64, default 16 */
  int error_nodes_u;       /* (87): trapezoid on the circle, 4..1024, default 32 */
  int two_curves;          /* Remark 7.5: nonzero = both branches of v1's contour
                              curve and one of v2's (v3 unused); default 0 */
} cyc_implicit_approx_options;

/** Omega and the error (87) of the approximation, per piece and in all. */
typedef struct cyc_implicit_approx_report {
  int pieces;
  double omega;    /* sum of the pieces' Omega (81) */
  double error87;  /* (87) of the piecewise surface on [0, 1]: sum error87_piece / pieces */
  double seconds;
  double omega_initial[CYC_MAX_IMPLICIT_PIECES]; /* Omega at alpha = beta = |q - p| */
  double omega_piece[CYC_MAX_IMPLICIT_PIECES];
  double error87_piece[CYC_MAX_IMPLICIT_PIECES]; /* each piece on its own t in [0, 1] */
  double alpha[CYC_MAX_IMPLICIT_PIECES][3];      /* the tangent lengths of c_v1..c_v3 */
  double beta[CYC_MAX_IMPLICIT_PIECES][3];
  int reverted[CYC_MAX_IMPLICIT_PIECES];         /* 1: the solve did not lower Omega */
} cyc_implicit_approx_report;

CYC_API void cyc_implicit_approx_options_init(cyc_implicit_approx_options* options);

/** Seed 001 §7.a: approximates the implicit blend by exact rational ringed
 *  surfaces (kind CYC_SURFACE_RINGED). For the three directions v (9
 *  numbers, pairwise non-parallel) the contour branches from f10 = 0 to
 *  f20 = 0 are Ferguson cubics whose tangent lengths Ceres chooses to
 *  minimize Omega (81)-(83); each surface's circles pass exactly through
 *  the three cubics (directrix: their circumcentre, a rational curve of
 *  degree 15). With pieces > 1 the blend is cut by planes (84). Writes
 *  pieces[0 .. *count - 1] (the caller provides options->pieces slots and
 *  destroys the handles) and the report (may be NULL). Statuses:
 *  CYC_E_INVALID_ARGUMENT (options, v), CYC_E_NOT_FINITE, those of the
 *  blend (cyc_implicit_blend_eval), CYC_E_EMPTY_REAL_LOCUS (a direction
 *  without contour points on an end plane), CYC_E_COLLINEAR_POINTS,
 *  CYC_E_NUMERICAL_OVERFLOW (a contour branch could not be traced),
 *  CYC_E_SINGULAR_POINT. Optimizer tier: allocates; CYC_E_UNSUPPORTED
 *  without Ceres. Nothing is written on error. */
CYC_API int cyc_optimize_implicit_blend(cyc_context* ctx, const cyc_implicit_blend* blend,
                                        const double v[9],
                                        const cyc_implicit_approx_options* options,
                                        cyc_surface** pieces, int* count,
                                        cyc_implicit_approx_report* report);

/* ------------------------------------------- Seed 002: sphere skins */
/* The skin of two spheres (Hoffmann, Monterde, Troll 2015, with ERRATA.md
 * §002; SPEC.md §9): a surface s(theta, t) = alpha(t) + lambda(t; theta)
 * w(t; theta), t in [0, 1], touching each sphere along a circle, alpha the
 * cubic Hermite spine between the circles' centers and w the
 * rotation-minimizing transport (RMF) of a start direction. The RMF is
 * tabulated numerically (to options.tolerance), so the skin is not
 * rational. Chains of spheres give several patches joined G^1. */

/** One end of a skin: the circle where the skin touches a sphere and the
 *  tangent cone along it (frozen).
 *   center   p, the circle's center
 *   radius   r > 0
 *   tangent  t: the cone's axis and the spine's end tangent (its length is
 *            the Hermite tangent length; the circle lies in the plane
 *            through p orthogonal to t; t points along the skin, from the
 *            start sphere towards the end sphere)
 *   inv_c    1/c with c t = x - p, x the cone's apex; 0: a cylinder (a
 *            great circle of its sphere)
 *  The sphere is m = p + h t/|t|, h = -r^2 inv_c / |t|, radius
 *  sqrt(r^2 + h^2) (cyc_skin_end_sphere). */
typedef struct cyc_skin_end {
  double center[3];
  double radius;
  double tangent[3];
  double inv_c;
} cyc_skin_end;

/** The end with the cone's apex given (on the axis through center along
 *  tangent). CYC_E_NOT_FINITE (an input NaN, infinite or beyond 1e100),
 *  CYC_E_INVALID_ARGUMENT (radius <= 0, apex off the axis by more than 1e-9
 *  relative, apex = center), CYC_E_ZERO_TANGENT (tangent = 0).
 *  Allocation-free; nothing is written on error. */
CYC_API int cyc_skin_end_from_apex(cyc_context* ctx, const double center[3], double radius,
                                   const double tangent[3], const double apex[3],
                                   cyc_skin_end* out);
/** The end on the sphere (sphere_center, sphere_radius) at the circle with
 *  the given center (inside the sphere, center - sphere_center parallel to
 *  tangent to 1e-9 relative; the circle's plane is orthogonal to tangent).
 *  CYC_E_NOT_FINITE, CYC_E_INVALID_ARGUMENT (sphere_radius <= 0, center off
 *  the sphere's axis along tangent, the plane missing the sphere),
 *  CYC_E_ZERO_TANGENT. Allocation-free; nothing is written on error. */
CYC_API int cyc_skin_end_from_sphere(cyc_context* ctx, const double sphere_center[3],
                                     double sphere_radius, const double center[3],
                                     const double tangent[3], cyc_skin_end* out);
/** The sphere of an end (no status: a pure formula). NULL end: nothing is
 *  written; center or radius may be NULL (not wanted). */
CYC_API void cyc_skin_end_sphere(const cyc_skin_end* end, double center[3], double* radius);

/* Which points of the two circles the parameter curves theta = const join
 * (cyc_skin_options.pairing). */
#define CYC_SKIN_RMF 0             /* the rotation-minimizing transport (default) */
#define CYC_SKIN_KUNKLI_HOFFMANN 1 /* the baseline of §2: +-e x t at both ends */
#define CYC_SKIN_CROSS_TANGENTS 2  /* §2's t_i x t_f at both ends */
/* How the RMF is integrated (cyc_skin_options.method). */
#define CYC_RMF_REFERENCE 0         /* the angle's rate as a Chebyshev series (default) */
#define CYC_RMF_DOUBLE_REFLECTION 1 /* Wang, Juttler, Zheng, Liu 2008 */

/** Options of a skin (initialize with cyc_skin_options_init). The
 *  baselines use the same spine and lambda, turning the RMF by
 *  Delta (3 t^2 - 2 t^3) about the tangent to reach their end point. */
typedef struct cyc_skin_options {
  int pairing;         /* CYC_SKIN_* (default CYC_SKIN_RMF) */
  int method;          /* CYC_RMF_* (default CYC_RMF_REFERENCE) */
  double tolerance;    /* > 0: the RMF table's error bound (default 1e-13) */
  double reference[3]; /* RMF pairing: the direction of theta = 0 at t = 0 (projected
                          orthogonal to the start tangent); zero (default): the
                          Kunkli-Hoffmann start direction */
  double e[3];         /* Kunkli-Hoffmann's e; zero (default): the coordinate axis least
                          aligned with both tangents */
} cyc_skin_options;
/** The defaults above. NULL is ignored. */
CYC_API void cyc_skin_options_init(cyc_skin_options* options);

/** A skin: one patch (cyc_sphere_skin_create) or a chain of patches
 *  (cyc_sphere_skin_chain_create), each on theta any real, t in [0, 1]. */
typedef struct cyc_sphere_skin cyc_sphere_skin;

/** The skin from start to end (options NULL: the defaults). Statuses:
 *  CYC_E_NULL_ARGUMENT (start, end, out), CYC_E_INVALID_ARGUMENT (an
 *  unknown pairing or method, radius <= 0, tolerance <= 0, e parallel to a
 *  tangent for Kunkli-Hoffmann, reference parallel to the start tangent),
 *  CYC_E_NOT_FINITE (an input NaN, infinite or beyond 1e100),
 *  CYC_E_ZERO_TANGENT (a tangent zero, or the spine's alpha' vanishing on
 *  [0, 1]), CYC_E_PARALLEL_LINES (cross tangents with parallel tangents),
 *  CYC_E_NESTED_SPHERES (one end's sphere inside or equal to the other's),
 *  CYC_E_CURVATURE_RADIUS_TOO_LARGE (kappa r >= 1 at an end, seed 002
 *  Remark 2: the skin would fold there; longer tangents help),
 *  CYC_E_NUMERICAL_OVERFLOW (the tolerance is not met with 256 steps per
 *  table interval, or values overflow), CYC_E_OUT_OF_MEMORY. Creation
 *  tier: allocates the handle (about 19 KB per patch). Nothing is written
 *  on error. */
CYC_API int cyc_sphere_skin_create(cyc_context* ctx, const cyc_skin_end* start,
                                   const cyc_skin_end* end, const cyc_skin_options* options,
                                   cyc_sphere_skin** out);
/** A chain of spheres: ends[0 .. n-1] (n >= 2), one circle per sphere, patch
 *  k from ends[k] to ends[k+1] (the middle ends' tangents point along the
 *  chain); the theta = 0 direction of patch k + 1 is the end direction of
 *  patch k, so theta-curves continue across the shared circles and the
 *  patches join G^1 there. options.reference applies to the first patch.
 *  Statuses: CYC_E_NULL_ARGUMENT (ends, out), CYC_E_INVALID_ARGUMENT (n < 2,
 *  options), then those of cyc_sphere_skin_create per patch; on such a
 *  patch failure *bad_patch (may be NULL) receives its index k, else it is
 *  not written. Creation tier. All or nothing: *out is written only on
 *  success. */
CYC_API int cyc_sphere_skin_chain_create(cyc_context* ctx, const cyc_skin_end* ends, int n,
                                         const cyc_skin_options* options, cyc_sphere_skin** out,
                                         int* bad_patch);
/** Destroy a skin (NULL: no-op). */
CYC_API void cyc_sphere_skin_destroy(cyc_context* ctx, cyc_sphere_skin* skin);
/** The number of patches (1 for cyc_sphere_skin_create, n - 1 for a
 *  chain of n ends). */
CYC_API int cyc_sphere_skin_patch_count(cyc_context* ctx, const cyc_sphere_skin* skin,
                                        int* count);

/** s(theta, t) of patch `patch` (0 .. count-1), ds/dtheta, ds/dt and the
 *  unit normal (ds/dtheta x ds/dt normalized: outward where lambda > 0);
 *  every output may be NULL. Statuses: CYC_E_NULL_ARGUMENT (skin),
 *  CYC_E_INVALID_ARGUMENT (patch out of range), CYC_E_NOT_FINITE (theta or
 *  t NaN or infinite), CYC_E_BAD_DOMAIN (t outside [0, 1]),
 *  CYC_E_SINGULAR_POINT (normal asked for where |s_theta x s_t| <= 1e-14
 *  |s_theta| |s_t|), CYC_E_NUMERICAL_OVERFLOW. Allocation-free; nothing is
 *  written on error. */
CYC_API int cyc_sphere_skin_eval(cyc_context* ctx, const cyc_sphere_skin* skin, int patch,
                                 double theta, double t, double x[3], double x_theta[3],
                                 double x_t[3], double normal[3]);
/** The grid theta[0 .. ntheta-1] x t[0 .. nt-1] of a patch: point (i, j) at
 *  index j * ntheta + i, 3 doubles each, in points and normals (either may
 *  be NULL; the caller provides 3 ntheta nt doubles). The values equal
 *  cyc_sphere_skin_eval's bits; normals at singular points (where
 *  cyc_sphere_skin_eval says CYC_E_SINGULAR_POINT) are written as (0, 0, 0)
 *  and counted in *singular (may be NULL), as cyc_surface_eval_grid does.
 *  Statuses: CYC_E_NULL_ARGUMENT (skin, theta, t), CYC_E_INVALID_ARGUMENT
 *  (patch, ntheta < 0 or nt < 0), CYC_E_NOT_FINITE, CYC_E_BAD_DOMAIN,
 *  CYC_E_NUMERICAL_OVERFLOW (a point beyond the range, for skins beyond
 *  1e50). Allocation-free; all or nothing. */
CYC_API int cyc_sphere_skin_eval_grid(cyc_context* ctx, const cyc_sphere_skin* skin, int patch,
                                      const double* theta, int ntheta, const double* t, int nt,
                                      double* points, double* normals, size_t* singular);

/** What a patch is made of. */
typedef struct cyc_sphere_skin_info {
  double kappa[2];           /* the spine's curvature at t = 0 and t = 1 (kappa r < 1) */
  double delta;              /* the pairing's extra turn at t = 1 (0 for CYC_SKIN_RMF) */
  int rmf_substeps;          /* CYC_RMF_DOUBLE_REFLECTION: steps per table interval (2 ..
                                256); CYC_RMF_REFERENCE: the largest Chebyshev degree */
  double rmf_error_estimate; /* estimated max error of the RMF (<= tolerance) */
  double spine[4][3];        /* power form alpha(t) = c0 + c1 t + c2 t^2 + c3 t^3 */
  int pairing;               /* CYC_SKIN_* */
  int method;                /* CYC_RMF_* */
} cyc_sphere_skin_info;
/** The info of a patch. CYC_E_NULL_ARGUMENT (skin, out),
 *  CYC_E_INVALID_ARGUMENT (patch out of range). Nothing is written on
 *  error. */
CYC_API int cyc_sphere_skin_info_get(cyc_context* ctx, const cyc_sphere_skin* skin, int patch,
                                     cyc_sphere_skin_info* out);
/** The twist of the curve theta = const of a patch against the RMF,
 *  measured on the evaluated surface (integral of the rate at which its
 *  direction from the spine turns about the tangent; Gauss-Legendre 8 x 16
 *  nodes): 0 for CYC_SKIN_RMF, |delta| for the baselines.
 *  CYC_E_NULL_ARGUMENT (skin, twist), CYC_E_INVALID_ARGUMENT (patch),
 *  CYC_E_NOT_FINITE (theta), CYC_E_SINGULAR_POINT (the curve meets the
 *  spine), CYC_E_NUMERICAL_OVERFLOW. Allocation-free; nothing is written on
 *  error. */
CYC_API int cyc_sphere_skin_twist(cyc_context* ctx, const cyc_sphere_skin* skin, int patch,
                                  double theta, double* twist);
/** lambda(t; theta) of a patch (the distance factor of s from the spine,
 *  seed 002 eqs. (6)-(8), (10)) and the end scalars a[0] = a_i(theta),
 *  a[1] = a_f(theta) of eqs. (9), (11) (a may be NULL).
 *  CYC_E_NULL_ARGUMENT (skin, lambda), CYC_E_INVALID_ARGUMENT (patch),
 *  CYC_E_NOT_FINITE (theta, t), CYC_E_BAD_DOMAIN (t outside [0, 1]),
 *  CYC_E_NUMERICAL_OVERFLOW. Allocation-free; nothing is written on
 *  error. */
CYC_API int cyc_sphere_skin_lambda(cyc_context* ctx, const cyc_sphere_skin* skin, int patch,
                                   double theta, double t, double* lambda, double a[2]);

/* Adaptive tessellation of a skin patch (SPEC.md §8j.2a), with the
 * tessellation options, plan and buffers of the export block below (the
 * struct tags are declared here). */
struct cyc_tessellation_options;
struct cyc_tessellation_plan;
/** Bytes of workspace cyc_sphere_skin_tessellate_plan needs when N may reach
 *  `segments`: 452 doubles per segment, 0 for segments outside
 *  3..CYC_MAX_CIRCLE_SEGMENTS (never negative or wrapped). */
CYC_API size_t cyc_sphere_skin_tessellation_workspace_size(int segments);
/** Plans the mesh of patch `patch`: rows t = const (ts[0] = 0 < ... <
 *  ts[plan->rows - 1] = 1) of N points at equal steps in theta, theta =
 *  phase(t) + 2 pi j / N, phase linear in t from plan->phase0 to phase1 (0:
 *  the seam on theta = 0; options->reference_u0 / _u1: world vectors whose
 *  projections into the end circle's plane give the angle 0 at t = 0 / 1).
 *  N starts from the largest lambda (plan->max_radius: max_radius (1 -
 *  cos(pi/N)) <= tol/2) and is raised until every planned row's section
 *  lies within tol/2 of its chords at the 1/4, 1/2, 3/4 points; an interval
 *  is halved while its rows at 1/4, 1/2, 3/4 stray more than tol/2 from the
 *  chords between its end rows (at 4N angles) or more than tol along the
 *  cells' diagonals. plan->depth_limited: bit 1 an interval reached the
 *  halving limit, bit 2 N reached max_segments (or fixed_segments) with a
 *  row above tol/2. work: cyc_sphere_skin_tessellation_workspace_size(
 *  fixed_segments or max_segments) bytes, 8-byte aligned. A chain welds
 *  watertight when all its patches are planned with the same N
 *  (fixed_segments = the largest plan->segments of a first pass) and the
 *  same phase at the shared circles (the defaults do). Statuses:
 *  CYC_E_NULL_ARGUMENT, CYC_E_INVALID_ARGUMENT (patch, options as
 *  cyc_tessellate_plan's, row_cap < 2, a reference along the spine's
 *  tangent), CYC_E_NOT_FINITE, CYC_E_BUFFER_TOO_SMALL (work, or more than
 *  row_cap rows needed: the planner stops there), CYC_E_NUMERICAL_OVERFLOW.
 *  *plan is written only on CYC_OK (ts[0 .. row_cap) may be overwritten
 *  on errors of the planning itself). Allocation-free. */
CYC_API int cyc_sphere_skin_tessellate_plan(cyc_context* ctx, const cyc_sphere_skin* skin,
                                            int patch,
                                            const struct cyc_tessellation_options* options,
                                            double* ts, int row_cap, void* work,
                                            size_t work_bytes, struct cyc_tessellation_plan* plan);
/** The mesh of a plan: point (i, j) = s(phase(ts[i]) + 2 pi j / segments,
 *  ts[i]) at index i * segments + j of points and normals (either may have
 *  data = NULL; capacity >= rows * segments; closed in j), the values of
 *  cyc_sphere_skin_eval_grid. Normals at singular points are (0, 0, 0) and
 *  counted in *singular (may be NULL). Statuses: CYC_E_NULL_ARGUMENT,
 *  CYC_E_INVALID_ARGUMENT (patch, plan, stride), CYC_E_NOT_FINITE,
 *  CYC_E_BAD_DOMAIN (ts[i] outside [0, 1]), CYC_E_BUFFER_TOO_SMALL,
 *  CYC_E_NUMERICAL_OVERFLOW; every argument is validated before anything is
 *  written. Allocation-free. */
CYC_API int cyc_sphere_skin_tessellate_eval(cyc_context* ctx, const cyc_sphere_skin* skin,
                                            int patch, const struct cyc_tessellation_plan* plan,
                                            const double* ts, cyc_buffer3 points,
                                            cyc_buffer3 normals, size_t* singular);

/** Seed 002 Remark 2 (optimizer tier): tangent lengths that make a skin
 *  valid (kappa r < 1 at both ends, ERRATA: a c > 0). */
typedef struct cyc_skin_tangent_options {
  double target;      /* kappa r kept <= target, in (0, 1); default 0.9 */
  double min_ratio;   /* each length scale within [min_ratio, max_ratio]; default 1/16 */
  double max_ratio;   /* default 16 */
  int max_iterations; /* >= 0, default 100 */
} cyc_skin_tangent_options;
CYC_API void cyc_skin_tangent_options_init(cyc_skin_tangent_options* options);

typedef struct cyc_skin_tangent_summary {
  double scale[2];           /* t_i -> scale[0] t_i, t_f -> scale[1] t_f */
  double kappa_r_initial[2]; /* kappa(0) r_i, kappa(1) r_f of the input */
  double kappa_r[2];         /* of the result */
  int iterations;            /* 0: the input was valid and is returned as is */
} cyc_skin_tangent_summary;

/** The ends with their tangents rescaled (directions, cones and spheres
 *  kept: inv_c scales with the tangent) so that cyc_sphere_skin_create
 *  succeeds: a valid input is returned unchanged; else Ceres minimizes
 *  (log s_i)^2 + (log s_f)^2 with hinge penalties on kappa r / target - 1
 *  (Remark 2's closed-form end curvatures, autodiff). skin: the skin's
 *  options (NULL: defaults), options NULL: the defaults above. Statuses:
 *  CYC_E_NULL_ARGUMENT (start, end, start_out, end_out),
 *  CYC_E_INVALID_ARGUMENT (target outside (0, 1), ratios not 0 < min <= 1
 *  <= max, max_iterations < 0, or the skin's own), CYC_E_NOT_FINITE,
 *  CYC_E_CURVATURE_RADIUS_TOO_LARGE (no scaling in the box makes the skin
 *  valid), the other statuses of cyc_sphere_skin_create;
 *  CYC_E_UNSUPPORTED without Ceres. summary may be NULL. Nothing is
 *  written on error. */
CYC_API int cyc_optimize_skin_tangents(cyc_context* ctx, const cyc_skin_end* start,
                                       const cyc_skin_end* end, const cyc_skin_options* skin,
                                       const cyc_skin_tangent_options* options,
                                       cyc_skin_end* start_out, cyc_skin_end* end_out,
                                       cyc_skin_tangent_summary* summary);

/* ------------- Lie sphere geometry and Dupin cyclides (seed 003) */
/* Lie sphere geometry in R^{4,2} (seed 003 sec. 2, with ERRATA.md; SPEC.md
 * sec. 8h): coordinates in the orthogonal basis (e1, e2, e3, e+, e-, er)
 * with x . y = x1 y1 + x2 y2 + x3 y3 + x+ y+ - x- y- - xr yr, n_inf = e+ +
 * e-. A 6-vector is 6 doubles in that order. Oriented spheres, planes and
 * points are neutral vectors (x . x = 0) up to scale; oriented contact is
 * x . y = 0. 6x6 matrices (cyc_lie_transform, cyc_dupin, Witt extensions)
 * are ROW-MAJOR: entry (i, j) is m[6*i + j], acting on column vectors
 * (x' = M x), so column j (m[j], m[6 + j], ..., m[30 + j]) is the image of
 * the j-th basis vector.
 * Every function here is allocation-free except cyc_dupin_surface_create
 * (creation tier: it allocates the handle from the context's allocator).
 * Every function writes its outputs only on CYC_OK (the one exception,
 * cyc_dupin_classify_spheres, is documented there). Inputs must be finite
 * (CYC_E_NOT_FINITE); results that overflow are CYC_E_NUMERICAL_OVERFLOW. */

/** Kinds of Lie spheres (frozen). */
#define CYC_LIE_SPHERE 1            /* center m, oriented radius rho (> 0: normals outward) */
#define CYC_LIE_POINT 2             /* the point m (rho = 0) */
#define CYC_LIE_PLANE 3             /* the oriented plane x . n = lambda, normal n */
#define CYC_LIE_POINT_AT_INFINITY 4 /* n_inf */

/** A Lie sphere by its Euclidean data (frozen). Only the fields of its
 *  kind are read; the others are written as 0. A plane's n need not be
 *  unit on input (the plane is rescaled); outputs have |n| = 1. */
typedef struct cyc_lie_sphere {
  int kind; /* CYC_LIE_SPHERE .. CYC_LIE_POINT_AT_INFINITY */
  double m[3];
  double rho;
  double n[3];
  double lambda;
} cyc_lie_sphere;

/** The normalized representative: (4) 2m + (m^2 - rho^2) n_inf - n0 +
 *  2 rho er for spheres and points (n0 = e+ - e-), (7) as corrected
 *  n + lambda n_inf - er for planes, n_inf for the point at infinity.
 *  CYC_E_INVALID_ARGUMENT (unknown kind, plane with n = 0),
 *  CYC_E_NOT_FINITE, CYC_E_NUMERICAL_OVERFLOW. */
CYC_API int cyc_lie_vector(cyc_context* ctx, const cyc_lie_sphere* sphere, double x[6]);
/** The Lie sphere of a representative x of any scale ((6), (9)).
 *  CYC_E_NOT_ON_LIE_QUADRIC when |x . x| > 1e-9 |x|^2, CYC_E_INVALID_ARGUMENT
 *  for x = 0, CYC_E_NOT_FINITE, CYC_E_NUMERICAL_OVERFLOW. */
CYC_API int cyc_lie_sphere_of(cyc_context* ctx, const double x[6], cyc_lie_sphere* out);
/** The inner product x . y of R^{4,2}. CYC_E_NOT_FINITE,
 *  CYC_E_NUMERICAL_OVERFLOW (the product overflows). */
CYC_API int cyc_lie_dot(cyc_context* ctx, const double x[6], const double y[6], double* out);
/** Oriented contact (Lemma 2.7): *contact = |x . y| <= tol |x| |y| (0 or 1).
 *  tol >= 0 (e.g. 1e-9), else CYC_E_INVALID_ARGUMENT; CYC_E_NOT_FINITE. */
CYC_API int cyc_lie_in_contact(cyc_context* ctx, const double x[6], const double y[6],
                               double tol, int* contact);

/** The span of k vectors (vectors: 6*k doubles, 0 <= k <= 6; NULL allowed
 *  for k = 0): its dimension (rank-revealing SVD, relative threshold 1e-10)
 *  and signature (p, r, q) = numbers of positive, zero and negative
 *  eigenvalues of the form on it (zero: |eigenvalue| <= 1e-9 on a
 *  Euclidean-orthonormal basis). signature may be NULL.
 *  CYC_E_INVALID_ARGUMENT (k outside 0..6), CYC_E_NOT_FINITE. */
CYC_API int cyc_lie_span(cyc_context* ctx, const double* vectors, int k, int* dim,
                         int signature[3]);
/** The orthogonal complement (for the form) of span(vectors): its
 *  dimension *dim (6 minus the span's), its signature, and a
 *  Euclidean-orthonormal basis in basis (36 doubles, may be NULL): basis
 *  vector j (j < *dim) is basis[6 j] to basis[6 j + 5]; the remaining
 *  entries are set to 0. Statuses of cyc_lie_span. */
CYC_API int cyc_lie_complement(cyc_context* ctx, const double* vectors, int k, double basis[36],
                               int* dim, int signature[3]);
/** The signature of the complement of any subspace with signature
 *  (p, r, q): (4 - p - r, r, 2 - q - r) (Table 1 as corrected in
 *  ERRATA.md). CYC_E_INVALID_ARGUMENT when no subspace of R^{4,2} has that
 *  signature (a negative entry, p + r > 4 or q + r > 2). */
CYC_API int cyc_lie_complement_signature(cyc_context* ctx, const int signature[3], int out[3]);
/** Witt's extension theorem (Thm. 2.3), constructive: for linearly
 *  independent u_0..u_{k-1} and w_0..w_{k-1} (6*k doubles each, 1 <= k <=
 *  6) with u_i . u_j = w_i . w_j (to 1e-9 relative), a matrix T in O(4,2)
 *  (T^T J T = J) with T u_i = w_i, ROW-MAJOR in T (36 doubles). residual
 *  (may be NULL): max(|T^T J T - J|, |T u_i - w_i| / |w_i|).
 *  CYC_E_INVALID_ARGUMENT (k), CYC_E_NOT_FINITE, CYC_E_RANK_DEFICIENT (u or w
 *  dependent), CYC_E_NOT_ISOMETRIC (Gram matrices or complements'
 *  signatures differ), CYC_E_NUMERICAL_OVERFLOW. */
CYC_API int cyc_lie_witt_extension(cyc_context* ctx, const double* u, const double* w, int k,
                                   double T[36], double* residual);

/** A Lie transformation: an element of O(4,2), ROW-MAJOR (frozen). Lie
 *  spheres map by their representatives, x -> M x. */
typedef struct cyc_lie_transform {
  double m[36];
} cyc_lie_transform;

/** x -> x + t. CYC_E_NOT_FINITE, CYC_E_NUMERICAL_OVERFLOW. */
CYC_API int cyc_lie_transform_translation(cyc_context* ctx, const double t[3],
                                          cyc_lie_transform* out);
/** x -> R x, R a 3x3 ROW-MAJOR orthogonal matrix (rotations and
 *  reflections): CYC_E_INVALID_ARGUMENT when max |R^T R - I| > 1e-9. */
CYC_API int cyc_lie_transform_rotation(cyc_context* ctx, const double R[9],
                                       cyc_lie_transform* out);
/** x -> s x, s > 0 (CYC_E_INVALID_ARGUMENT otherwise). */
CYC_API int cyc_lie_transform_scaling(cyc_context* ctx, double s, cyc_lie_transform* out);
/** The Laguerre dilatation by d: rho -> rho + d, planes moved by d along
 *  their normals (offsets). */
CYC_API int cyc_lie_transform_dilatation(cyc_context* ctx, double d, cyc_lie_transform* out);
/** The inversion at the sphere (center, radius), radius > 0
 *  (CYC_E_INVALID_ARGUMENT otherwise). A Mobius transformation. */
CYC_API int cyc_lie_transform_inversion(cyc_context* ctx, const double center[3], double radius,
                                        cyc_lie_transform* out);
/** rho -> -rho, n -> -n (er -> -er). */
CYC_API int cyc_lie_transform_orientation_reversal(cyc_context* ctx, cyc_lie_transform* out);
/** first, then then: out = then * first (out may alias either input).
 *  CYC_E_NOT_FINITE, CYC_E_NUMERICAL_OVERFLOW. */
CYC_API int cyc_lie_transform_compose(cyc_context* ctx, const cyc_lie_transform* first,
                                      const cyc_lie_transform* then, cyc_lie_transform* out);
/** The image of a Lie sphere (it may change kind: an inversion maps spheres
 *  through its center to planes). Statuses of cyc_lie_vector and
 *  cyc_lie_sphere_of; CYC_E_NOT_FINITE for a non-finite matrix. */
CYC_API int cyc_lie_transform_apply(cyc_context* ctx, const cyc_lie_transform* T,
                                    const cyc_lie_sphere* in, cyc_lie_sphere* out);
/** *is_lie = 1 when M is in O(4,2): max |M^T J M - J| <= 1e-9 max(1,
 *  max|M|^2); *is_laguerre = 1 when also M fixes the line of n_inf (to
 *  1e-9 relative), *is_mobius = 1 when also M fixes the line of er. Any of
 *  the three outputs may be NULL. CYC_E_NOT_FINITE. */
CYC_API int cyc_lie_transform_classify(cyc_context* ctx, const cyc_lie_transform* T,
                                       int* is_lie, int* is_laguerre, int* is_mobius);

/* Dupin cyclides (seed 003 sec. 3): the envelope of the oriented spheres
 * touching three given ones, stored as theta in O(4,2) with theta(A0) = A
 * (Remark 3.12), A0 = span(e1, e2, e-). The two sphere families are
 *   a(xi)        = theta(2 xi0 xi1 e1 + (xi1^2 - xi0^2) e2 + (xi1^2 + xi0^2) e-)
 *   a_perp(zeta) = theta(2 z0 z1 e3 + (z1^2 - z0^2) e+ + (z1^2 + z0^2) er)
 * for homogeneous parameters xi0 : xi1 and z0 : z1 (affine xi = xi0 / xi1),
 * and c(xi, zeta) is the point where a(xi) touches a_perp(zeta). */

/** Laguerre classes (Lemma 3.10 / Thm. 3.11; names by the sphere centers,
 *  see SPEC.md sec. 8h) (frozen). */
#define CYC_DUPIN_DEGENERATE 1 /* I: a cone or cylinder of revolution */
#define CYC_DUPIN_PARABOLIC 2  /* II: one plane per family (cubic) */
#define CYC_DUPIN_QUARTIC 3    /* III: quartic (e.g. a torus) */

/** A Dupin cyclide (frozen): theta ROW-MAJOR (column j is theta(e_j)), its
 *  Laguerre class, and its local frame: the cyclide is theta's cyclide
 *  scaled by unit and translated by +origin (theta acts on local
 *  coordinates (x - origin) / unit, so that the coordinates of its spheres
 *  in (4) stay of size ~1, not |origin|^2 or the model's size^+-2; SPEC.md
 *  sec. 8h.3). The builders choose the frame (unit a power of 2 near the
 *  model's size); points, planes, spheres and partials this API returns
 *  are global. A value, validated by every function taking it: finite
 *  (theta, origin, unit), unit > 0, theta in O(4,2) (max |theta^T J theta
 *  - J| <= 1e-8 max(1, max|theta|^2)) and type the class of theta; else
 *  CYC_E_INVALID_ARGUMENT (CYC_E_NOT_FINITE for NaN/Inf). Every cyc_dupin
 *  this API returns passes that check. origin = {0, 0, 0} and unit = 1 is
 *  theta's cyclide itself. */
typedef struct cyc_dupin {
  double theta[36];
  int type;         /* CYC_DUPIN_DEGENERATE .. CYC_DUPIN_QUARTIC */
  double origin[3]; /* the translation of theta's cyclide */
  double unit;      /* the length unit of theta's cyclide (> 0) */
} cyc_dupin;

/** A point of a Dupin cyclide or of its offset (frozen): point = c + d n,
 *  the unit normal n, the tangent plane x . n = lambda of c, and the
 *  partials of point with respect to the affine xi and zeta (zero from
 *  cyc_dupin_eval_homogeneous). */
typedef struct cyc_dupin_point {
  double point[3];
  double normal[3];
  double lambda;
  double d_xi[3];
  double d_zeta[3];
} cyc_dupin_point;

/** Case analysis of sec. 3.1 for three Lie spheres. Its statuses are the
 *  answer: CYC_OK (a cyclide: span A = R^{2,1}), CYC_E_SPHERE_PENCIL (dim A
 *  = 2, Case I), CYC_E_NO_TOUCHING_SPHERE (A = R^{1,2}),
 *  CYC_E_SINGLE_TOUCHING_SPHERE (A = R^{1,1,1}); for these four, and only
 *  these, signature (may be NULL) receives A's signature (a pencil:
 *  (0, 2, 0)). Errors that leave signature untouched: CYC_E_INVALID_ARGUMENT
 *  (an unknown kind, a plane with n = 0, two equal Lie spheres),
 *  CYC_E_NOT_FINITE, CYC_E_NUMERICAL_OVERFLOW. */
CYC_API int cyc_dupin_classify_spheres(cyc_context* ctx, const cyc_lie_sphere spheres[3],
                                       int signature[3]);
/** Algorithm 1 (corrected): the cyclide whose first family has a(0),
 *  a(infinity), a(1) = the three spheres. Statuses of
 *  cyc_dupin_classify_spheres (except CYC_OK's meaning), CYC_E_DEGENERATE_CYCLIDE
 *  (every sphere of a family is a point: a curve), CYC_E_NOT_ISOMETRIC,
 *  CYC_E_NUMERICAL_OVERFLOW (also: theta not orthogonal to the tolerance
 *  above, an ill-conditioned triple). */
CYC_API int cyc_dupin_from_spheres(cyc_context* ctx, const cyc_lie_sphere spheres[3],
                                   cyc_dupin* out);
/** The same from three representatives a = (a1, a2, a3), 18 doubles, any
 *  scale; adds CYC_E_NOT_ON_LIE_QUADRIC (a vector is not neutral to 1e-9
 *  relative) and CYC_E_INVALID_ARGUMENT (a zero vector). */
CYC_API int cyc_dupin_from_vectors(cyc_context* ctx, const double a[18], cyc_dupin* out);
/** The cyclide of a PE-subspace A = span(span[0..k-1]) (6*k doubles, 3 <=
 *  k <= 6, rank 3, signature (2, 0, 1)); signature (may be NULL) receives
 *  the span's signature on success. CYC_E_INVALID_ARGUMENT (k),
 *  CYC_E_NOT_FINITE, CYC_E_NOT_ISOMETRIC (not a PE-subspace; the message
 *  names its dimension and signature), CYC_E_DEGENERATE_CYCLIDE,
 *  CYC_E_NUMERICAL_OVERFLOW. */
CYC_API int cyc_dupin_from_subspace(cyc_context* ctx, const double* span, int k, cyc_dupin* out,
                                    int signature[3]);
/** The same surface with the two families exchanged (Cor. 3.6). out may
 *  alias in. */
CYC_API int cyc_dupin_swap_families(cyc_context* ctx, const cyc_dupin* in, cyc_dupin* out);
/** The offset cyclide at distance d (points c + d n): theta composed with
 *  the dilatation by d. CYC_E_NOT_FINITE, CYC_E_NUMERICAL_OVERFLOW (theta
 *  overflows or leaves O(4,2) to the tolerance above). out may alias in. */
CYC_API int cyc_dupin_offset(cyc_context* ctx, const cyc_dupin* in, double d, cyc_dupin* out);
/** The point c(xi, zeta) + offset n with normal, tangent plane and
 *  partials, affine (finite) parameters. CYC_E_NOT_FINITE,
 *  CYC_E_POINT_AT_INFINITY (c . n_inf = 0 relative to 1e-13),
 *  CYC_E_SINGULAR_POINT (the normal is undefined), CYC_E_NUMERICAL_OVERFLOW. */
CYC_API int cyc_dupin_eval(cyc_context* ctx, const cyc_dupin* cyclide, double xi, double zeta,
                           double offset, cyc_dupin_point* out);
/** The same at homogeneous parameters xi[0] : xi[1], zeta[0] : zeta[1]
 *  (either may be infinity, x : 0); the partials are 0.
 *  CYC_E_INVALID_ARGUMENT for 0 : 0. */
CYC_API int cyc_dupin_eval_homogeneous(cyc_context* ctx, const cyc_dupin* cyclide,
                                       const double xi[2], const double zeta[2], double offset,
                                       cyc_dupin_point* out);
/** The sphere a(t) (family 0) or a_perp(t) (family 1) at the homogeneous
 *  parameter t[0] : t[1], as a Lie sphere (it may be a plane or a point).
 *  CYC_E_INVALID_ARGUMENT (family not 0 or 1, t = 0 : 0),
 *  CYC_E_NOT_FINITE, CYC_E_NUMERICAL_OVERFLOW. */
CYC_API int cyc_dupin_sphere(cyc_context* ctx, const cyc_dupin* cyclide, int family,
                             const double t[2], cyc_lie_sphere* out);
/** All or nothing: the points (and unit normals) of cyc_dupin_eval at
 *  every (xis[i], zetas[j]), row-major: vector i*nzeta + j at 3*(i*nzeta +
 *  j) of points / normals (either may be NULL). Every point is computed
 *  and checked before anything is written; any failure (e.g. one point at
 *  infinity) fails the whole grid with that point's status and writes
 *  nothing. Every parameter and the offset are checked before any point
 *  (CYC_E_NOT_FINITE: NaN, Inf or beyond 1e100). nxi or nzeta = 0 (and
 *  finite parameters) is
 *  CYC_OK with nothing written;
 *  CYC_E_INVALID_ARGUMENT when nxi * nzeta * 3 overflows size_t. */
CYC_API int cyc_dupin_eval_grid(cyc_context* ctx, const cyc_dupin* cyclide, const double* xis,
                                size_t nxi, const double* zetas, size_t nzeta, double offset,
                                double* points, double* normals);
/** The cyclide as a circle-family surface (kind CYC_SURFACE_DUPIN) over u
 *  in [u0, u1]: xi = (xi_map[0] u + xi_map[1]) / (xi_map[2] u + xi_map[3])
 *  and zeta likewise in v (NULL: the identity; each map needs a d - b c !=
 *  0 to 1e-12 relative, else CYC_E_INVALID_ARGUMENT), so cyc_surface_eval(u,
 *  v) = c(xi(u), zeta(v)) and the circle at u is the characteristic circle
 *  of a(xi(u)). The domain is scanned like the other creators:
 *  CYC_E_POINT_AT_INFINITY or CYC_E_SINGULAR_POINT at a sample (the message
 *  names u), CYC_E_BAD_DOMAIN, CYC_E_NOT_FINITE, CYC_E_OUT_OF_MEMORY.
 *  Creation tier: allocates the handle. */
CYC_API int cyc_dupin_surface_create(cyc_context* ctx, const cyc_dupin* cyclide,
                                     const double xi_map[4], const double zeta_map[4], double u0,
                                     double u1, cyc_surface** out);

/* -------------- cyclide blends of two cones (seed 003 sec. 4, Algorithm 2) */

/** A cone (the tangent cone of a canal surface along a circle) in Lie form
 *  (frozen): R = span(r0, r_plus) = R^{1,1,0}, r0 the sphere touching along
 *  the circle and r_plus the derivative of the normalized sphere family,
 *  pointing INTO the blend (SPEC.md sec. 8h.6). Functions accept any
 *  representative scale and normalize (r0 . n_inf = -2, r_plus . n_inf =
 *  0). They return CYC_E_NOT_ON_LIE_QUADRIC (r0 not neutral),
 *  CYC_E_INVALID_ARGUMENT (r_plus not positive or not orthogonal to r0, a
 *  point sphere), CYC_E_UNSUPPORTED (r0 is a plane: planar tangent cones
 *  are not supported yet), CYC_E_NOT_FINITE. */
typedef struct cyc_lie_cone {
  double r0[6];
  double r_plus[6];
} cyc_lie_cone;

/** The cone of the spheres (m + h dm, rho + h drho), h > 0 into the blend;
 *  needs rho != 0 and |dm| > |drho| (CYC_E_INVALID_ARGUMENT). */
CYC_API int cyc_cone_from_spheres(cyc_context* ctx, const double m[3], double rho,
                                  const double dm[3], double drho, cyc_lie_cone* out);
/** The cone (slope != 0) or cylinder (slope = 0) through the circle
 *  (center, normal, radius > 0) whose radius changes by slope per unit
 *  length along +normal; the blend leaves the circle along +normal.
 *  orientation +1: normals away from the axis, -1: towards it. */
CYC_API int cyc_cone_from_circle(cyc_context* ctx, const double center[3],
                                 const double normal[3], double radius, double slope,
                                 int orientation, cyc_lie_cone* out);
/** The same from the apex, which must lie on the axis and off the circle's
 *  plane (CYC_E_INVALID_ARGUMENT). */
CYC_API int cyc_cone_from_circle_apex(cyc_context* ctx, const double center[3],
                                      const double normal[3], double radius,
                                      const double apex[3], int orientation, cyc_lie_cone* out);
/** The tangent cone of a canal surface (CYC_SURFACE_PRCS or
 *  CYC_SURFACE_DUPIN; else CYC_E_NOT_CANAL) along its circle at u;
 *  direction +1 if the blend continues in +u, -1 in -u; orientation +1
 *  keeps the surface's sphere radii, -1 reverses them. */
CYC_API int cyc_cone_from_surface(cyc_context* ctx, const cyc_surface* surface, double u,
                                  int direction, int orientation, cyc_lie_cone* out);
/** The cone's circle: center, unit normal (into the blend), radius. */
CYC_API int cyc_cone_circle(cyc_context* ctx, const cyc_lie_cone* cone, double center[3],
                            double normal[3], double* radius);
/** The cone as a ringed surface over h in [h0, h1] (h = 0: the circle;
 *  h > 0: the blend's side). Creation tier. */
CYC_API int cyc_cone_surface_create(cyc_context* ctx, const cyc_lie_cone* cone, double h0,
                                    double h1, cyc_surface** out);

/** A single or double cyclide blend (frozen). Each piece is a Dupin
 *  cyclide with xi = 0 at its first glued sphere and xi = infinity at its
 *  second; the blend patch is xi in [0, infinity] (as a surface: u in
 *  [0, 1], xi = u / (1 - u), see cyc_cyclide_blend_surface_create).
 *  pieces = 1: piece[0] runs from R's circle to S's. pieces = 2: piece[0]
 *  runs from R's circle and piece[1] from S's circle, both to the joint
 *  circle of the sphere joint (t0 of (44)), with T = span(alpha r0 +
 *  r_plus, beta s0 + s_plus) on the hyperbola branch (43). */
typedef struct cyc_cyclide_blend {
  int pieces;
  int branch;
  double alpha, beta;
  double joint[6];
  cyc_dupin piece[2];
} cyc_cyclide_blend;

/** dim(R + S): 3 (a single cyclide) or 4 (double blends).
 *  CYC_E_TANGENT_GENERATING_SPHERES (r0 . s0 = 0, Lemma 4.6 (i)),
 *  CYC_E_INVALID_ARGUMENT (one generating sphere for both), and the cone
 *  statuses above. */
CYC_API int cyc_cyclide_blend_dimension(cyc_context* ctx, const cyc_lie_cone* r,
                                        const cyc_lie_cone* s, int* dim);
/** beta(alpha) on branch +1 or -1 of (43); CYC_E_INVALID_ARGUMENT at the
 *  asymptote (45) or for another branch. */
CYC_API int cyc_cyclide_blend_beta(cyc_context* ctx, const cyc_lie_cone* r,
                                   const cyc_lie_cone* s, int branch, double alpha,
                                   double* beta);
/** Algorithm 2 at (branch, alpha) (ignored when dim(R + S) = 3).
 *  CYC_E_BLEND_FOLDS (a piece reaches a circle from the wrong side),
 *  CYC_E_SINGULAR_POINT (a piece pinches: a point sphere in its patch or on
 *  its circles), and the statuses of cyc_cyclide_blend_dimension and
 *  cyc_cyclide_blend_beta. Allocation-free. */
CYC_API int cyc_cyclide_blend_build(cyc_context* ctx, const cyc_lie_cone* r, const cyc_lie_cone* s,
                              int branch, double alpha, cyc_cyclide_blend* out);
/** Algorithm 2 with the free parameter chosen: samples (8..4096) values
 *  alpha = tan(phi) / unit on both branches (unit: the power of 2 nearest
 *  to the cones' size, so that a model and the model scaled by a power of
 *  2 get the same blend), the best by quality, refined by golden
 *  section. quality (may be NULL) = min / max circle radius over
 *  both circle families of the patches. CYC_E_BLEND_FOLDS or
 *  CYC_E_SINGULAR_POINT when no sample is valid. Allocation-free. */
CYC_API int cyc_cyclide_blend_auto(cyc_context* ctx, const cyc_lie_cone* r,
                                   const cyc_lie_cone* s, int samples, cyc_cyclide_blend* out,
                                   double* quality);
/** A circle of piece i's patch, defined geometrically: family 0, the
 *  circle at u = s in [0, 1] (a whole circle; u = 0, 1 are the glued
 *  circles); family 1, the second family's circle through the point of the
 *  first glued circle at angle s (radians) from the direction
 *  unitOrthogonal(normal) of that circle (Eigen's choice: the largest
 *  components' perpendicular). normal is unit. CYC_E_POINT_AT_INFINITY for
 *  a circle through infinity (a line). Allocation-free. */
CYC_API int cyc_cyclide_blend_circle(cyc_context* ctx, const cyc_cyclide_blend* blend,
                                     int piece, int family, double s, double center[3],
                                     double normal[3], double* radius);
/** The quality measure of a blend (validated like a cyc_dupin): min / max
 *  radius of the family-0 circles at u = k/16 (k = 0..16) and the family-1
 *  circles at the angles 2 pi (k + 1/2) / 16 (k = 0..15) of every piece. */
CYC_API int cyc_cyclide_blend_quality(cyc_context* ctx, const cyc_cyclide_blend* blend,
                                      double* quality);
/** Piece i's patch as a circle-family surface (CYC_SURFACE_DUPIN), u in
 *  [0, 1]. Creation tier. */
CYC_API int cyc_cyclide_blend_surface_create(cyc_context* ctx, const cyc_cyclide_blend* blend,
                                             int piece, cyc_surface** out);

/** G1 at the glued circles (frozen): gap[j] the largest distance between
 *  corresponding points, angle[j] the largest angle between tangent planes
 *  (radians), j = 0: cone R / piece 0, 1: the joint (0 for single
 *  blends), 2: cone S / the last piece; scale = the largest |point| +
 *  circle radius seen (for relative gaps). */
typedef struct cyc_cyclide_blend_report {
  double gap[3];
  double angle[3];
  double scale;
} cyc_cyclide_blend_report;
/** The continuity report of a blend of the cones r and s at n >= 1
 *  samples per circle. */
CYC_API int cyc_cyclide_blend_continuity(cyc_context* ctx, const cyc_lie_cone* r,
                                         const cyc_lie_cone* s, const cyc_cyclide_blend* blend,
                                         int n, cyc_cyclide_blend_report* out);

/* Optimizer tier (seed 003 §4, Case II): the double blend's family
 * parameter phi = atan(unit alpha) (unit as in cyc_cyclide_blend_auto)
 * chosen against a user objective (SPEC.md §8h.12). */

/** The objective, a weighted sum (1/2 the sum of squared residuals) of
 *  - fairness: the spread of the log radii of the patches' circles
 *    (cyc_cyclide_blend_circle, `circles` of each family per piece):
 *    sqrt(fairness / N) (log r_i - mean log r);
 *  - the joint circle (the circle of the sphere joint) passing through
 *    joint_points (distance / L) and having joint_radius (if > 0;
 *    (radius - joint_radius) / L);
 *  - obstacles: the hinge max(0, radius + clearance - distance from the
 *    sphere's center to each family-0 circle) / L;
 *  - regularity: per piece, the hinge max(0, 1 - e / (min_extent L)) on the
 *    extent e = |c0 - c1| + |r0 - r1| + (r0 + r1)/2 |n0 x n1| of its glued
 *    circles (near the asymptotes (45), (46) a piece collapses onto its
 *    cone's circle and loses accuracy; fairness alone can prefer that).
 *  L = the distance of the cones' circle centers plus both radii. */
typedef struct cyc_cyclide_blend_objective {
  double fairness;             /* >= 0, default 1 */
  const double* joint_points;  /* 3 * joint_point_count doubles */
  int joint_point_count;
  double joint_point_weight;   /* >= 0, default 1 */
  double joint_radius;         /* > 0: the wanted joint radius; 0 (default): none */
  double joint_radius_weight;  /* >= 0, default 1 */
  const cyc_blend_obstacle* obstacles;
  int obstacle_count;
  double clearance;            /* >= 0, default 0 */
  double obstacle_weight;      /* >= 0, default 1 */
  double regularity;           /* >= 0, default 1 */
  double min_extent;           /* >= 0 (0: off), default 0.05 */
  int circles;                 /* per family and piece, 4..256, default 16
                                  (joint_point_count, obstacle_count 0..4096) */
} cyc_cyclide_blend_objective;

/** The scan and solver options. */
typedef struct cyc_cyclide_blend_options {
  int samples;                /* phi samples per branch, 8..4096, default 64 */
  int branch;                 /* 0 (default): both hyperbolas; +1 or -1: one */
  int max_iterations;         /* >= 0 (0: the best sample), default 50 */
  double function_tolerance;  /* Ceres', default 1e-10 */
  double gradient_tolerance;  /* default 1e-12 */
  double parameter_tolerance; /* default 1e-10 */
} cyc_cyclide_blend_options;

/** The defaults above (usable without the optimizer tier). NULL is ignored. */
CYC_API void cyc_cyclide_blend_objective_init(cyc_cyclide_blend_objective* objective);
CYC_API void cyc_cyclide_blend_options_init(cyc_cyclide_blend_options* options);

/** The blend of the cones r and s with its family parameter chosen: the
 *  objective is scanned at `samples` phi per branch (valid blends only:
 *  built, not folded or pinched, and buildable as surfaces) and Ceres
 *  refines the best sample (central differences of the exact construction)
 *  inside the run of valid samples around it; final_cost <= initial_cost
 *  (the best sample) always. A single cyclide (dim(R + S) = 3) has nothing
 *  to choose: it is returned with its cost. summary (may be NULL):
 *  fairness, targets (the joint terms), obstacles and regularity are the
 *  final cost's terms. Statuses: CYC_E_INVALID_ARGUMENT (weights, counts, circles,
 *  samples, branch, max_iterations), CYC_E_NOT_FINITE, CYC_E_NULL_ARGUMENT,
 *  those of cyc_cyclide_blend_dimension, CYC_E_BLEND_FOLDS or
 *  CYC_E_SINGULAR_POINT when no sample is valid. objective / options NULL:
 *  the defaults. Optimizer tier: allocates; CYC_E_UNSUPPORTED without
 *  Ceres. Nothing is written on error. */
CYC_API int cyc_optimize_cyclide_blend(cyc_context* ctx, const cyc_lie_cone* r,
                                       const cyc_lie_cone* s,
                                       const cyc_cyclide_blend_objective* objective,
                                       const cyc_cyclide_blend_options* options,
                                       cyc_cyclide_blend* out, cyc_optimize_summary* summary);

/** The free parameter of cyc_optimize_cyclide_blend (after its scan; role
 *  CYC_PARAMETER_FAMILY, index = the branch, the box of phi and the start),
 *  as cyc_optimize_blend_parameters; *count = 0 for a single cyclide. */
CYC_API int cyc_optimize_cyclide_blend_parameters(cyc_context* ctx, const cyc_lie_cone* r,
                                                  const cyc_lie_cone* s,
                                                  const cyc_cyclide_blend_objective* objective,
                                                  const cyc_cyclide_blend_options* options,
                                                  cyc_free_parameter* params, int capacity,
                                                  int* count);

/* ======================================================================
 * Export and tessellation (issue 9, SPEC.md §8j): exact rational Bezier
 * patches of a circle-family surface, and adaptive meshes with a chordal
 * tolerance. Every output is written only on CYC_OK.
 * ====================================================================== */

/** Tessellation options (cyc_tessellation_options_default fills them). */
typedef struct cyc_tessellation_options {
  double chordal_tolerance; /* > 0, model units (default 1e-3) */
  int min_segments;         /* arcs per circle, >= 3 (default 8) */
  int max_segments;         /* <= CYC_MAX_CIRCLE_SEGMENTS (default 1024) */
  int fixed_segments;       /* > 0: exactly this many arcs (shared joins); 0: from the tolerance */
  int initial_rows;         /* uniform circles before refinement, >= 2 (default 9) */
  const double* reference_u0; /* world vectors for the angle 0 at u0 / u1 (NULL: the generator) */
  const double* reference_u1;
} cyc_tessellation_options;

/** Largest number of arcs per circle. */
#define CYC_MAX_CIRCLE_SEGMENTS 4096

/** What the planner chose: rows circles of segments points each. */
typedef struct cyc_tessellation_plan {
  int rows;
  int segments;
  double phase0, phase1; /* angle offsets at u0 and u1 (radians, about the axis) */
  double max_radius;
  int depth_limited;     /* some u-interval reached the halving limit */
} cyc_tessellation_plan;

CYC_API void cyc_tessellation_options_default(cyc_tessellation_options* options);
/** Bytes of workspace cyc_tessellate_plan needs for this many arcs: 0 for
 *  segments outside 3..CYC_MAX_CIRCLE_SEGMENTS (never negative or wrapped;
 *  the planner refuses those counts naming the option). */
CYC_API size_t cyc_tessellation_workspace_size(int segments);
/** Chooses the arcs per circle (equal angles, from the largest radius) and
 *  the circles us[0..plan->rows) (u0 ... u1, halved adaptively until every
 *  circle at 1/4, 1/2, 3/4 of an interval is within tol/2 of the chords).
 *  work: at least cyc_tessellation_workspace_size(max_segments or
 *  fixed_segments) bytes, 8-byte aligned. CYC_E_BUFFER_TOO_SMALL: the work,
 *  or more than row_cap >= 2 circles are needed (the planner stops there,
 *  so its work is bounded by row_cap). CYC_E_INVALID_ARGUMENT (options out of range, a
 *  reference along an end circle's axis), CYC_E_NOT_FINITE, and the
 *  surface's statuses at a circle. us[0..row_cap) is also the planner's
 *  working array: after an error other than an argument check its
 *  contents are unspecified (*plan is written only on success).
 *  Allocation-free. */
CYC_API int cyc_tessellate_plan(cyc_context* ctx, const cyc_surface* surface,
                                const cyc_tessellation_options* options, double* us, int row_cap,
                                void* work, size_t work_bytes, cyc_tessellation_plan* plan);
/** The mesh of a plan: point (i, j), the circle us[i] at the angle
 *  phase(u) + 2 pi j / segments, at index i * segments + j of points and
 *  normals (either may have data = NULL; capacity >= rows * segments;
 *  closed in j). Normals at singular points are (0, 0, 0) and counted in
 *  *singular (may be NULL). Every circle is validated before anything is
 *  written. Allocation-free. */
CYC_API int cyc_tessellate_eval(cyc_context* ctx, const cyc_surface* surface,
                                const cyc_tessellation_plan* plan, const double* us,
                                cyc_buffer3 points, cyc_buffer3 normals, size_t* singular);

/** The parameter rectangle of an export: u in [u0, u1] inside the
 *  surface's domain, and v in [v0, v1], or (whole_circle != 0) v over the
 *  whole circle. */
typedef struct cyc_export_domain {
  double u0, u1, v0, v1;
  int whole_circle;
} cyc_export_domain;

/** One rational Bezier patch of an export: degrees, the surface parameters
 *  it covers (with reciprocal_v, 1/v is linear in the local t and v0 or v1
 *  may be +-infinity). */
typedef struct cyc_bezier_patch_info {
  int deg_u, deg_v;
  double u0, u1, v0, v1;
  int reciprocal_v;
} cyc_bezier_patch_info;

/** An exact rational Bezier export (opaque; creation tier: allocated
 *  through the context, about 15.5 KiB per patch). */
/** The most patches one export may hold (about 62 MiB). */
#define CYC_MAX_EXPORT_PATCHES 4096
typedef struct cyc_bezier_export cyc_bezier_export;

/** The tensor-product rational Bezier patches that are the surface over
 *  the domain (SPEC §8j.1; every surface kind: PRCS, PRRS and ringed of
 *  degree (m, 2), Dupin and parabolic cyclides of degree (2, 2)): weights
 *  > 0, each patch checked against the evaluator. CYC_E_NOT_FINITE, CYC_E_BAD_DOMAIN,
 *  CYC_E_DEGREE_TOO_HIGH, CYC_E_POINT_AT_INFINITY (the surface passes
 *  through infinity in the domain), CYC_E_NUMERICAL_OVERFLOW,
 *  CYC_E_INVALID_ARGUMENT (more than CYC_MAX_EXPORT_PATCHES patches),
 *  CYC_E_OUT_OF_MEMORY. *out is written only on success. */
CYC_API int cyc_bezier_export_create(cyc_context* ctx, const cyc_surface* surface,
                                     const cyc_export_domain* domain, cyc_bezier_export** out);
CYC_API void cyc_bezier_export_destroy(cyc_bezier_export* e);
/** The number of patches (0 for NULL). */
CYC_API int cyc_bezier_export_count(const cyc_bezier_export* e);
/** Patch index: its info and (control may be NULL) its homogeneous control
 *  points control[4 (i (deg_v + 1) + j) + 0..3] = (w, w x, w y, w z), i
 *  along u; control_cap in doubles, at least 4 (deg_u + 1)(deg_v + 1)
 *  (else CYC_E_BUFFER_TOO_SMALL with info written). */
CYC_API int cyc_bezier_export_patch(cyc_context* ctx, const cyc_bezier_export* e, int index,
                                    cyc_bezier_patch_info* info, double* control,
                                    size_t control_cap);
/** The patch index at local (s, t) in [0, 1]^2 (de Casteljau), and the
 *  surface parameters (u, v) of that point (uv may be NULL). Every output
 *  is finite: where a reciprocal_v patch reaches v = +-infinity (the
 *  generator) or 1/v underflows next to it, uv[1] is +-1e100, the largest
 *  circle parameter cyc_surface_eval accepts (its point is the generator's
 *  to a relative 1e-100). */
CYC_API int cyc_bezier_export_eval(cyc_context* ctx, const cyc_bezier_export* e, int index,
                                   double s, double t, double x[3], double uv[2]);

/** The sizes of the export's NURBS form (SPEC §8j.1a). */
typedef struct cyc_nurbs_size {
  int deg_u, deg_v;
  int cp_u, cp_v;         /* control points in u and v (cp_u * cp_v in all) */
  int knots_u, knots_v;   /* cp + deg + 1 each */
} cyc_nurbs_size;

/** The export's patches as one clamped tensor-product NURBS: knots in u
 *  (the surface's u) and in tau (tau = v for |v| <= 1, 2 sign(v) - 1/v
 *  beyond: tau in [-2, 2], both ends v = infinity), interior knots of
 *  multiplicity = degree (C0 joins), control points control[4 (i cp_v +
 *  j) + 0..3] = (w, w x, w y, w z) with shared patch edges merged. A size
 *  query with NULL arrays (and 0 capacities) writes only *size; too small
 *  capacities give CYC_E_BUFFER_TOO_SMALL with *size written.
 *  CYC_E_NUMERICAL_OVERFLOW if neighbouring patches disagree on a shared
 *  edge. Allocation-free. */
CYC_API int cyc_bezier_export_nurbs(cyc_context* ctx, const cyc_bezier_export* e,
                                    cyc_nurbs_size* size, double* knots_u, size_t knots_u_cap,
                                    double* knots_v, size_t knots_v_cap, double* control,
                                    size_t control_cap);
/** tau of (SPEC §8j.1a) for a circle parameter v (+-infinity gives +-2)
 *  and its inverse (tau = +-2 gives +-HUGE_VAL; clamped to [-2, 2]). */
CYC_API double cyc_export_tau_of_v(double v);
CYC_API double cyc_export_v_of_tau(double tau);

/* ---- writers (issue 9 item 2) */

/** A grid of rows x cols points (point (i, j) at points + (i cols + j)
 *  stride), normals optional (same indexing; may be NULL), closed: the cols
 *  direction wraps (as cyc_tessellate_eval writes it). rgba: the grid's
 *  colour (sRGB red, green, blue and alpha, each in [0, 1]), written to glb
 *  (a material per colour) and PLY (vertex colours); all four 0 (as a
 *  zero-initialized struct has them): a palette colour chosen by the grid's
 *  index in the call, so the parts of a scene differ. */
typedef struct cyc_grid_mesh {
  const double* points;
  const double* normals;
  size_t stride; /* doubles, >= 3, for both arrays */
  int rows, cols;
  int closed;
  float rgba[4]; /* sRGB + alpha in [0, 1]; {0, 0, 0, 0}: the palette */
} cyc_grid_mesh;

/** File formats of cyc_mesh_write. */
enum cyc_mesh_format {
  CYC_MESH_OBJ = 0, /* ASCII, v / vn / f, %.17g */
  CYC_MESH_PLY = 1, /* binary little-endian, float32 positions and normals */
  CYC_MESH_STL = 2, /* binary, float32 */
  CYC_MESH_GLB = 3  /* glTF 2.0 binary: POSITION, NORMAL, uint32 indices, a
                      primitive and material per colour */
};

/** Options of cyc_mesh_write (NULL: the defaults). */
typedef struct cyc_mesh_write_options {
  double weld_tolerance; /* < 0: 1e-9 x the model size; 0: exact matches only */
  const char* name;      /* glb node/mesh name, OBJ "o" line (NULL: none) */
} cyc_mesh_write_options;

/** What a write produced. */
typedef struct cyc_mesh_stats {
  size_t vertices;  /* distinct vertices after welding */
  size_t triangles;
  int welded_rows;    /* end rows that reuse an earlier grid's vertices */
  int collapsed_rows; /* end rows that became one vertex (poles) */
  double coordinate_sum; /* sum of x + y + z over the vertices (a checksum) */
  double tolerance;      /* the welding tolerance used */
} cyc_mesh_stats;

/** Writes grids[0..count) as one welded, indexed triangle mesh to the file
 *  path (SPEC.md §8j.3): the end rows of a grid that coincide with end
 *  rows of an earlier grid (a shared circle, either direction, any cyclic
 *  offset) share its vertices, so blends written with the shapes they join
 *  are watertight. The file is written to path + ".part" and renamed on
 *  success: on any error path is untouched (and no .part file remains).
 *  CYC_E_NULL_ARGUMENT, CYC_E_INVALID_ARGUMENT (count outside 1..1024, bad
 *  grid sizes or stride, a colour component outside [0, 1], unknown format,
 *  a name longer than 256 bytes, a degenerate grid), CYC_E_NOT_FINITE (a point), CYC_E_IO (the file could
 *  not be written). stats may be NULL. Allocates nothing but the C
 *  library's FILE. */
CYC_API int cyc_mesh_write(cyc_context* ctx, const char* path, int format,
                           const cyc_grid_mesh* grids, int count,
                           const cyc_mesh_write_options* options, cyc_mesh_stats* stats);
/** The export's patches as JSON (schema "cyclide-rational-bezier", version
 *  1, SPEC.md §8j.3), written like cyc_mesh_write (path + ".part", renamed
 *  on success). CYC_E_NULL_ARGUMENT, CYC_E_IO. */
CYC_API int cyc_bezier_export_write_json(cyc_context* ctx, const cyc_bezier_export* e,
                                         const char* path);

/** Options of cyc_sphere_skin_export_create (cyc_skin_export_options_default
 *  fills them). */
typedef struct cyc_skin_export_options {
  double tolerance; /* absolute distance to the skin, model units, > 0 (1e-9) */
  int degree;       /* q, the frame's interpolation degree in t, 1..24 (7):
                       patches of degree (q + 3, 4) */
} cyc_skin_export_options;
/** What cyc_sphere_skin_export_create achieved (SPEC.md §8j.1b). */
typedef struct cyc_skin_export_report {
  double error_estimate; /* largest distance export - skin: sampled bound and measured */
  double rmf_error;      /* the skin's own RMF accuracy (unit vector error x max |lambda|) */
  int exact;             /* 1: straight spines and the RMF pairing, rational: exact */
  int t_intervals;       /* u-intervals (the patches are t_intervals x v-pieces) */
} cyc_skin_export_report;
CYC_API void cyc_skin_export_options_default(cyc_skin_export_options* options);
/** The rational Bezier patches of a sphere skin or chain (SPEC.md §8j.1b),
 *  into the export handle of cyc_bezier_export_create (so _count, _patch,
 *  _eval, _nurbs, _write_json and _destroy apply): exact in theta, with
 *  the export's v = tan(theta / 2) (theta = 2 atan v, v = +-inf is theta =
 *  pi), and u = k + t on patch k of the chain (u in [0, patch count]); the
 *  rotation-minimizing frame, not rational, is interpolated within
 *  options->tolerance (exact when the spine is straight). options NULL:
 *  the defaults; report may be NULL. CYC_E_INVALID_ARGUMENT (options out of
 *  range, more than CYC_MAX_EXPORT_PATCHES patches), CYC_E_NOT_FINITE,
 *  CYC_E_BAD_DOMAIN, CYC_E_NUMERICAL_OVERFLOW (the tolerance cannot be met,
 *  e.g. below the skin's rounding), CYC_E_OUT_OF_MEMORY. *out and *report
 *  are written only on success. */
CYC_API int cyc_sphere_skin_export_create(cyc_context* ctx, const cyc_sphere_skin* skin,
                                          const cyc_export_domain* domain,
                                          const cyc_skin_export_options* options,
                                          cyc_bezier_export** out,
                                          cyc_skin_export_report* report);

/* ======================================================================
 * Seed 004: Laguerre geometry, PN surfaces, parabolic Dupin cyclides, design
 * (Peternell-Pottmann, SPEC.md §8i). Plain values, allocation-free unless
 * stated; every output is written only on CYC_OK; NaN, Inf or |x| > 1e100
 * in an input gives CYC_E_NOT_FINITE.
 * ====================================================================== */

/** An oriented plane e0 + e.x = 0 with unit normal e (seed 004 §2). */
typedef struct cyc_oriented_plane {
  double e0;
  double e[3];
} cyc_oriented_plane;

/** A cycle: the oriented sphere (m, r), or the point m (r = 0). It touches
 *  a plane iff e0 + e.m + r = 0. */
typedef struct cyc_cycle {
  double m[3];
  double r;
} cyc_cycle;

/** A point of the isotropic model I^3 = R^3 u R: y (exceptional = 0), or
 *  the real number c of the plane (c, 0, 0, 1) (exceptional = 1). */
typedef struct cyc_isotropic_point {
  int exceptional;
  double y[3];
  double c;
} cyc_isotropic_point;

/** The paraboloid (2.4) of a cycle: 2 y3 + k (y1^2 + y2^2) + 2 (l1 y1 +
 *  l2 y2) + c0 = 0 (k = r + m3, l = (m1, m2), c0 = r - m3). */
typedef struct cyc_isotropic_paraboloid {
  double k, l1, l2, c0;
} cyc_isotropic_paraboloid;

/** A point with its unit normal (a datum of the design, §4.2). */
typedef struct cyc_oriented_point {
  double point[3];
  double normal[3];
} cyc_oriented_point;

/** A datum in the isotropic model: B = (b, z) and the gradient g of the
 *  tangent plane of Lambda(A) at B. */
typedef struct cyc_isotropic_datum {
  double b[2];
  double z;
  double g[2];
} cyc_isotropic_datum;

/** A quadratic q = q[0] y1^2 + q[1] y1 y2 + q[2] y2^2 + q[3] y1 + q[4] y2 +
 *  q[5]: the graph y3 = q / 2 of I^3 (order q20, q11, q02, q10, q01, q00). */
typedef struct cyc_graph_quadratic {
  double q[6];
} cyc_graph_quadratic;

/** A quadratic Bezier triangle graph over the triangle vertex[0..2]; the
 *  ordinates in the order 200, 110, 101, 020, 011, 002. */
typedef struct cyc_quadratic_graph_triangle {
  double vertex[3][2];
  double ordinate[6];
} cyc_quadratic_graph_triangle;

/** A rational cubic Bezier triangle, homogeneous control points (w, w x,
 *  w y, w z) in the order 300, 210, 201, 120, 111, 102, 030, 021, 012, 003. */
typedef struct cyc_rational_cubic_triangle {
  double control[10][4];
} cyc_rational_cubic_triangle;

/** A rational bicubic patch, control[i][j] = (w, w x, w y, w z), i along s. */
typedef struct cyc_rational_bicubic_patch {
  double control[4][4][4];
} cyc_rational_bicubic_patch;

/** A parabolic Dupin cyclide: the normal form (4.1)-(4.3) with parameters
 *  (a, b), placed by x = origin + frame x_local (frame column-major, its
 *  columns the local axes, a rotation to 1e-12). */
typedef struct cyc_parabolic_cyclide {
  double a, b;
  double frame[9];
  double origin[3];
} cyc_parabolic_cyclide;

/** Types of a parabolic cyclide (§4.1, ERRATA 004 for the sphere). */
enum cyc_parabolic_cyclide_type {
  CYC_PARABOLIC_HORN = 0,   /* a b > 0, a != b */
  CYC_PARABOLIC_RING = 1,   /* a b < 0 */
  CYC_PARABOLIC_THORN = 2,  /* exactly one of a, b is 0 */
  CYC_PARABOLIC_SPHERE = 3, /* a = b != 0 */
  CYC_PARABOLIC_POINT = 4   /* a = b = 0 */
};

/** The cone of revolution Gamma(lambda, mu) of Thm. 4.2. */
typedef struct cyc_revolution_cone {
  double apex[3]; /* when !cylinder */
  double axis[3]; /* unit */
  double half_angle;
  int cylinder;        /* mu = 0: the apex is at infinity */
  int circle_and_line; /* lambda = 0: Gamma also touches along the line e */
} cyc_revolution_cone;

/** Options of the design (zero-initialize for the defaults). */
typedef struct cyc_design_options {
  int allow_ridges; /* nonzero: return folding patchworks (Fig. 3) too */
} cyc_design_options;

/** What the design found (see cyclide_design.hpp): written on success and
 *  on every error after the arguments were read (fields that do not apply
 *  keep their neutral values 0 / -1). */
typedef struct cyc_design_report {
  int triangles;
  int patches;
  int orientation;
  int ridge_patches;
  int first_ridge_patch;
  int first_bad_datum;
  int patches_needed;
  size_t work_needed; /* bytes */
} cyc_design_report;

/* ---- Laguerre geometry and the isotropic model (§2) */

/** Lambda (2.3): the plane (normalized first) as a point of I^3.
 *  CYC_E_INVALID_ARGUMENT for e = 0, CYC_E_NUMERICAL_OVERFLOW for a normal
 *  within ~1e-154 of W = (0, 0, 1). */
CYC_API int cyc_laguerre_to_isotropic(cyc_context* ctx, const cyc_oriented_plane* plane,
                                      cyc_isotropic_point* out);
/** Lambda^{-1}: the unit plane of an isotropic point (exceptional must be 0
 *  or 1, else CYC_E_INVALID_ARGUMENT). */
CYC_API int cyc_isotropic_to_laguerre(cyc_context* ctx, const cyc_isotropic_point* y,
                                      cyc_oriented_plane* out);
/** The paraboloid (2.4) of a cycle. */
CYC_API int cyc_cycle_paraboloid(cyc_context* ctx, const cyc_cycle* cycle,
                                 cyc_isotropic_paraboloid* out);
/** *out = 1 iff y lies on the paraboloid to tol (relative to the terms'
 *  scale; tol in [0, 1), 0 means the default 1e-12), else 0. */
CYC_API int cyc_paraboloid_contains(cyc_context* ctx, const cyc_isotropic_paraboloid* p,
                                    const cyc_isotropic_point* y, double tol, int* out);
/** The translation x -> x + t in I^3 (2.5) and on planes (e0 -> e0 - e.t). */
CYC_API int cyc_isotropic_translate(cyc_context* ctx, const cyc_isotropic_point* y,
                                    const double t[3], cyc_isotropic_point* out);
CYC_API int cyc_plane_translate(cyc_context* ctx, const cyc_oriented_plane* p, const double t[3],
                                cyc_oriented_plane* out);
/** The dilatation adding d to all radii (offset s + d n): (2.6) with the
 *  sign y3 -> y3 - (d/2)(1 + y1^2 + y2^2), planes e0 -> e0 - d. */
CYC_API int cyc_isotropic_dilatation(cyc_context* ctx, const cyc_isotropic_point* y, double d,
                                     cyc_isotropic_point* out);
CYC_API int cyc_plane_dilatation(cyc_context* ctx, const cyc_oriented_plane* p, double d,
                                 cyc_oriented_plane* out);

/* ---- PN surfaces Lambda^{-1}(Psi) (§3, Thm. 3.2) */

/** Largest degree of Psi in each parameter. */
#define CYC_MAX_PN_DEGREE 8

/** An opaque PN surface: a rational tensor-product Bezier surface Psi of
 *  I^3 over [0, 1]^2 and its envelope of planes Phi = Lambda^{-1}(Psi)
 *  (about 5 KiB; creation tier: allocated through the context). */
typedef struct cyc_pn_surface cyc_pn_surface;

/** One point of Phi's offset at distance d: the point x + d n, its partials,
 *  the unit normal n (the same for every offset), the tangent plane and
 *  y = Psi(u, v). */
typedef struct cyc_pn_point {
  double point[3];
  double x_u[3];
  double x_v[3];
  double normal[3];
  cyc_oriented_plane plane;
  double y[3];
} cyc_pn_point;

/** Psi from (degree_u + 1)(degree_v + 1) homogeneous control points
 *  control[4 (i (degree_v + 1) + j) + 0..3] = (w, w y1, w y2, w y3), w > 0,
 *  i along u. CYC_E_INVALID_ARGUMENT (a degree < 0, a weight <= 0),
 *  CYC_E_DEGREE_TOO_HIGH (> CYC_MAX_PN_DEGREE), CYC_E_NOT_FINITE,
 *  CYC_E_OUT_OF_MEMORY. *out is written only on success. */
CYC_API int cyc_pn_surface_create(cyc_context* ctx, int degree_u, int degree_v,
                                  const double* control, cyc_pn_surface** out);
/** Releases a PN surface (NULL is ignored). */
CYC_API void cyc_pn_surface_destroy(cyc_pn_surface* surface);
/** The point of the offset at signed distance d (d = 0: Phi) at (u, v) in
 *  [0, 1]^2. CYC_E_BAD_DOMAIN outside, CYC_E_NOT_FINITE, CYC_E_DEVELOPABLE
 *  (plane and partials dependent), CYC_E_POINT_AT_INFINITY (det of the
 *  parameterization of (y1, y2) vanishes), CYC_E_NUMERICAL_OVERFLOW.
 *  Allocation-free. */
CYC_API int cyc_pn_surface_eval(cyc_context* ctx, const cyc_pn_surface* surface, double u,
                                double v, double d, cyc_pn_point* out);
/** The grid (us[i], vs[j]) into index i nv + j of the wanted buffers
 *  (points, normals; either may have data = NULL), offset d. Every
 *  parameter and the buffers are checked before anything is written; a
 *  point that fails (developable, at infinity) is written as (0, 0, 0) in
 *  both and counted in *failed (may be NULL). Allocation-free. */
CYC_API int cyc_pn_surface_eval_grid(cyc_context* ctx, const cyc_pn_surface* surface,
                                     const double* us, size_t nu, const double* vs, size_t nv,
                                     double d, cyc_buffer3 points, cyc_buffer3 normals,
                                     size_t* failed);

/* ---- parabolic Dupin cyclides (§4.1) */

/** Thm 4.1: Lambda^{-1} of the graph y3 = q / 2. CYC_E_DEGENERATE_CYCLIDE
 *  when a = b = 0 (a point). */
CYC_API int cyc_parabolic_cyclide_from_quadratic(cyc_context* ctx, const cyc_graph_quadratic* q,
                                                 cyc_parabolic_cyclide* out);
/** The quadratic of a cyclide of the family G (frame a rotation about x3). */
CYC_API int cyc_parabolic_cyclide_quadratic(cyc_context* ctx, const cyc_parabolic_cyclide* c,
                                            cyc_graph_quadratic* out);
/** The world point phi(u, v) (4.1) and unit normal (4.3) (either output may
 *  be NULL, not both). Cyclide statuses: CYC_E_NOT_FINITE, CYC_E_INVALID_ARGUMENT
 *  (frame not a rotation), CYC_E_DEGENERATE_CYCLIDE (a = b = 0). */
CYC_API int cyc_parabolic_cyclide_eval(cyc_context* ctx, const cyc_parabolic_cyclide* c,
                                       double u, double v, double point[3], double normal[3]);
/** (4.2) at a world point. */
CYC_API int cyc_parabolic_cyclide_implicit(cyc_context* ctx, const cyc_parabolic_cyclide* c,
                                           const double x[3], double* out);
/** enum cyc_parabolic_cyclide_type of (a, b) (any finite a, b). */
CYC_API int cyc_parabolic_cyclide_type(cyc_context* ctx, const cyc_parabolic_cyclide* c,
                                       int* out);
/** The parabolic lines e (x1 = 0, x3 = a) and f (x2 = 0, x3 = b), world
 *  (either may be NULL). */
CYC_API int cyc_parabolic_cyclide_lines(cyc_context* ctx, const cyc_parabolic_cyclide* c,
                                        cyc_line* e, cyc_line* f);
/** The parameter circles u = const / v = const (radius2 = radius^2). */
CYC_API int cyc_parabolic_cyclide_u_circle(cyc_context* ctx, const cyc_parabolic_cyclide* c,
                                           double u, cyc_circle* out);
CYC_API int cyc_parabolic_cyclide_v_circle(cyc_context* ctx, const cyc_parabolic_cyclide* c,
                                           double v, cyc_circle* out);
/** Thm 4.2: the cone Gamma(lambda, mu) touching along the cubic circle
 *  phi(t, lambda t + mu). CYC_E_DEPENDENT_PLANES when mu = 0 and a + b
 *  lambda^2 = 0 (a pencil of planes). */
CYC_API int cyc_parabolic_cyclide_cone(cyc_context* ctx, const cyc_parabolic_cyclide* c,
                                       double lambda, double mu, cyc_revolution_cone* out);
/** The cubic circle's point phi(t, lambda t + mu), world. */
CYC_API int cyc_parabolic_cyclide_cubic_circle_point(cyc_context* ctx,
                                                     const cyc_parabolic_cyclide* c,
                                                     double lambda, double mu, double t,
                                                     double x[3]);
/** Remark 4.2: the net line of x (meeting e and f) cut with x3 = cc
 *  (local); CYC_E_INVALID_ARGUMENT for a sphere, CYC_E_POINT_AT_INFINITY for
 *  x in a plane x3 = a or x3 = b. */
CYC_API int cyc_parabolic_cyclide_net_projection(cyc_context* ctx,
                                                 const cyc_parabolic_cyclide* c,
                                                 const double x[3], double cc, double out[2]);
/** (u, v) with phi(u, v) = x (statuses as the net projection, except that a
 *  sphere uses its stereographic parameter). */
CYC_API int cyc_parabolic_cyclide_parameter_of(cyc_context* ctx, const cyc_parabolic_cyclide* c,
                                               const double x[3], double uv[2]);
/** The cyclide as a circle-family surface (kind CYC_SURFACE_PARABOLIC) over
 *  u in [u0, u1]: its u-circles of (4.1) through the one evaluator
 *  (cyc_surface_eval etc.; v is the v of (4.1), so points equal
 *  cyc_parabolic_cyclide_eval), cyc_surface_sphere the sphere touching along
 *  the u-circle. CYC_E_BAD_DOMAIN, CYC_E_DEGENERATE_CYCLIDE (a = b = 0),
 *  CYC_E_INVALID_ARGUMENT (frame not a rotation), CYC_E_SINGULAR_POINT (a
 *  u-circle of radius 0 in the domain: a horn cyclide's singular point;
 *  the message names u). Setup tier (one allocation). */
CYC_API int cyc_parabolic_cyclide_surface_create(cyc_context* ctx,
                                                 const cyc_parabolic_cyclide* c, double u0,
                                                 double u1, cyc_surface** out);

/* ---- patches (§4.1) */

/** Lambda^{-1} of a quadratic graph triangle: the exact rational cubic
 *  triangle on its cyclide. CYC_E_COLLINEAR_POINTS for a degenerate domain. */
CYC_API int cyc_cyclide_cubic_triangle(cyc_context* ctx, const cyc_quadratic_graph_triangle* tri,
                                       cyc_rational_cubic_triangle* out);
/** The same over the parallelogram corner + s e1 + t e2 of the graph
 *  y3 = q / 2, as a rational bicubic. CYC_E_COLLINEAR_POINTS for e1 || e2. */
CYC_API int cyc_cyclide_bicubic_patch(cyc_context* ctx, const cyc_graph_quadratic* q,
                                      const double corner[2], const double e1[2],
                                      const double e2[2], cyc_rational_bicubic_patch* out);
/** The triangle at barycentrics (r, s, t), the patch at (s, t) (any real
 *  parameters). CYC_E_POINT_AT_INFINITY where the weight vanishes. */
CYC_API int cyc_cubic_triangle_eval(cyc_context* ctx, const cyc_rational_cubic_triangle* T,
                                    double r, double s, double t, double x[3]);
CYC_API int cyc_bicubic_patch_eval(cyc_context* ctx, const cyc_rational_bicubic_patch* P,
                                   double s, double t, double x[3]);

/* ---- Delaunay triangulation and Powell-Sabin interpolation (§4.2) */

/** Bytes of workspace cyc_delaunay_triangulate needs for n points, and the
 *  bound 2n - 5 on its triangles. The supported n is 3..50,000,000 (every
 *  derived size then fits); for any other n both return 0, never a
 *  negative or wrapped value, and cyc_delaunay_triangulate refuses it. */
CYC_API size_t cyc_delaunay_workspace_size(int n);
CYC_API int cyc_delaunay_max_triangles(int n);
/** The Delaunay triangulation of the points (pts[2i], pts[2i+1]) as
 *  counter-clockwise index triples tri[3k..3k+2], k < *ntri.
 *  CYC_E_INVALID_ARGUMENT (n outside 3..50,000,000, tri_cap < 0, two equal
 *  points), CYC_E_COLLINEAR_POINTS, CYC_E_BUFFER_TOO_SMALL (work_bytes below the
 *  size, or tri_cap below the count: *ntri then receives the count). */
CYC_API int cyc_delaunay_triangulate(cyc_context* ctx, const double* pts, int n, void* work,
                                     size_t work_bytes, int* tri, int tri_cap, int* ntri);
/** Bytes of workspace cyc_powell_sabin_interpolate needs for n in
 *  3..50,000,000 and ntri in 1..100,000,000; 0 for any other arguments
 *  (which the interpolation refuses with CYC_E_INVALID_ARGUMENT). */
CYC_API size_t cyc_powell_sabin_workspace_size(int n, int ntri);
/** The Powell-Sabin C1 quadratic interpolant of values z[i] and gradients
 *  (g[2i], g[2i+1]) at the points (b[2i], b[2i+1]) over tri (3 ntri
 *  indices, counter-clockwise): 6 ntri graph triangles (6t + 2k: V_k R_k Z,
 *  6t + 2k + 1: R_k V_k+1 Z). CYC_E_BUFFER_TOO_SMALL with *nout = 6 ntri. */
CYC_API int cyc_powell_sabin_interpolate(cyc_context* ctx, const double* b, const double* z,
                                         const double* g, int n, const int* tri, int ntri,
                                         void* work, size_t work_bytes,
                                         cyc_quadratic_graph_triangle* out, int out_cap,
                                         int* nout);

/* ---- the design (§4.2) */

/** (A, alpha) -> (B, beta) and back. CYC_E_POLE_IN_GAUSS_IMAGE for a normal
 *  at W = (0, 0, 1), CYC_E_INVALID_ARGUMENT for a zero normal. */
CYC_API int cyc_isotropic_datum_of(cyc_context* ctx, const cyc_oriented_point* a,
                                   cyc_isotropic_datum* out);
CYC_API int cyc_oriented_point_of(cyc_context* ctx, const cyc_isotropic_datum* d,
                                  cyc_oriented_point* out);
/** *out = 1 iff the data's Gauss image contains W (see cyclide_design.hpp). */
CYC_API int cyc_gauss_image_contains_pole(cyc_context* ctx, const cyc_oriented_point* data,
                                          int n, int* out);
/** Bytes of caller workspace for cyc_design_cyclide_surface (ntri = 0: the
 *  Delaunay triangulation is computed). The supported arguments are n in
 *  3..50,000,000 and ntri in 0..100,000,000; for any other both queries
 *  return 0 (never negative or wrapped) and the design refuses them. */
CYC_API size_t cyc_design_workspace_size(int n, int ntri);
/** Upper bound on the patch count: 6 (2n - 5), or 6 ntri (at most 6e8). */
CYC_API int cyc_design_max_patches(int n, int ntri);
/** Seed 004 §4.2: the G1 patchwork of parabolic cyclide cubic triangles
 *  interpolating the oriented points data[0..n). tri = NULL (ntri = 0):
 *  the Delaunay triangulation of the isotropic projections b_i; else 3 ntri
 *  counter-clockwise indices. options NULL: defaults. work = NULL: the
 *  workspace is taken from the context's allocator (setup tier) and
 *  released before returning; else work_bytes >= cyc_design_workspace_size
 *  and nothing is allocated. iso (may be NULL) and patches receive
 *  *npatches = 6 ntri entries. report may be NULL. Statuses:
 *  CYC_E_NULL_ARGUMENT, CYC_E_INVALID_ARGUMENT (n < 3, bad triangulation,
 *  two data with the same b_i), CYC_E_NOT_FINITE, CYC_E_POLE_IN_GAUSS_IMAGE,
 *  CYC_E_NUMERICAL_OVERFLOW (report->first_bad_datum),
 *  CYC_E_COLLINEAR_POINTS, CYC_E_BUFFER_TOO_SMALL (report->work_needed,
 *  report->patches_needed; *npatches = the count when only cap is short),
 *  CYC_E_RIDGE (unless allow_ridges), CYC_E_OUT_OF_MEMORY. */
CYC_API int cyc_design_cyclide_surface(cyc_context* ctx, const cyc_oriented_point* data, int n,
                                       const int* tri, int ntri,
                                       const cyc_design_options* options, void* work,
                                       size_t work_bytes, cyc_quadratic_graph_triangle* iso,
                                       cyc_rational_cubic_triangle* patches, int cap,
                                       int* npatches, cyc_design_report* report);

#ifdef __cplusplus
}
#endif

#endif /* CYCLIDE_H */
