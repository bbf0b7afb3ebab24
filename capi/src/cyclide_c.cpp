// The C ABI over the C++ core. Every entry point runs through one guard
// (`run`) that checks the context, maps exceptions to statuses, records the
// last status and message in the context, and calls the error handler.
// Outputs are written only after everything has succeeded.
#include <cstdint>

#include "capi_internal.hpp"
#include "cyclide/darboux.hpp"
#include "cyclide/darboux_lines.hpp"
#include "cyclide/inverted_surface.hpp"
#include "cyclide/implicitize.hpp"
#include "cyclide/darboux_classify.hpp"
#include "cyclide/hermite.hpp"

using namespace cyclide;

// The frozen C numbers equal the core's.
#define CYC_SAME(c, s) static_assert(int(c) == int(Status::s), #c)
static_assert(CYC_SURFACE_PRCS == int(SurfaceKind::prcs) &&
                  CYC_SURFACE_PRRS == int(SurfaceKind::prrs) &&
                  CYC_SURFACE_RINGED == int(SurfaceKind::ringed) &&
                  CYC_SURFACE_DUPIN == int(SurfaceKind::dupin) &&
                  CYC_SURFACE_PARABOLIC == int(SurfaceKind::parabolic),
              "surface kinds");
CYC_SAME(CYC_OK, ok);
CYC_SAME(CYC_E_NULL_ARGUMENT, null_argument);
CYC_SAME(CYC_E_INVALID_ARGUMENT, invalid_argument);
CYC_SAME(CYC_E_NOT_FINITE, not_finite);
CYC_SAME(CYC_E_DEGREE_TOO_HIGH, degree_too_high);
CYC_SAME(CYC_E_BAD_DOMAIN, bad_domain);
CYC_SAME(CYC_E_DEPENDENT_PLANES, dependent_planes);
CYC_SAME(CYC_E_ZERO_TANGENT, zero_tangent);
CYC_SAME(CYC_E_COLLINEAR_POINTS, collinear_points);
CYC_SAME(CYC_E_DEGENERATE_CIRCLE_PARAMETER, degenerate_circle_parameter);
CYC_SAME(CYC_E_NOT_CANAL, not_canal);
CYC_SAME(CYC_E_SINGULAR_POINT, singular_point);
CYC_SAME(CYC_E_DEGENERATE_RINGED, degenerate_ringed);
CYC_SAME(CYC_E_PARALLEL_LINES, parallel_lines);
CYC_SAME(CYC_E_NO_COMMON_NORMAL, no_common_normal);
CYC_SAME(CYC_E_RANK_DEFICIENT, rank_deficient);
CYC_SAME(CYC_E_AT_INVERSION_CENTER, at_inversion_center);
CYC_SAME(CYC_E_NOT_PARABOLIC, not_parabolic);
CYC_SAME(CYC_E_EMPTY_REAL_LOCUS, empty_real_locus);
CYC_SAME(CYC_E_TOO_FEW_LINES, too_few_lines);
CYC_SAME(CYC_E_NO_NORMAL_FORM, no_normal_form);
CYC_SAME(CYC_E_NOT_PYTHAGOREAN, not_pythagorean);
CYC_SAME(CYC_E_INTERSECTING_CIRCLES, intersecting_circles);
CYC_SAME(CYC_E_NESTED_SPHERES, nested_spheres);
CYC_SAME(CYC_E_CURVATURE_RADIUS_TOO_LARGE, curvature_radius_too_large);
CYC_SAME(CYC_E_SPHERE_PENCIL, sphere_pencil);
CYC_SAME(CYC_E_NO_TOUCHING_SPHERE, no_touching_sphere);
CYC_SAME(CYC_E_SINGLE_TOUCHING_SPHERE, single_touching_sphere);
CYC_SAME(CYC_E_DEGENERATE_CYCLIDE, degenerate_cyclide);
CYC_SAME(CYC_E_NOT_ISOMETRIC, not_isometric);
CYC_SAME(CYC_E_NOT_ON_LIE_QUADRIC, not_on_lie_quadric);
CYC_SAME(CYC_E_POINT_AT_INFINITY, point_at_infinity);
CYC_SAME(CYC_E_TANGENT_GENERATING_SPHERES, tangent_generating_spheres);
CYC_SAME(CYC_E_BLEND_FOLDS, blend_folds);
CYC_SAME(CYC_E_DEVELOPABLE, developable);
CYC_SAME(CYC_E_POLE_IN_GAUSS_IMAGE, pole_in_gauss_image);
CYC_SAME(CYC_E_RIDGE, ridge);
CYC_SAME(CYC_E_NUMERICAL_OVERFLOW, numerical_overflow);
CYC_SAME(CYC_E_BUFFER_TOO_SMALL, buffer_too_small);
CYC_SAME(CYC_E_OUT_OF_MEMORY, out_of_memory);
CYC_SAME(CYC_E_IO, io_error);
CYC_SAME(CYC_E_UNSUPPORTED, unsupported);
CYC_SAME(CYC_E_INTERNAL, internal_error);
static_assert(CYC_MAX_CURVE_DEGREE == kMaxCurveDegree, "bound");
static_assert(CYC_MAX_HERMITE_ORDER == kMaxHermiteOrder, "bound");
static_assert(CYC_MAX_MOBIUS_DEGREE == kMaxMobiusDegree, "bound");

using namespace cyclide::capi;

// ------------------------------------------------------------ inputs

namespace cyclide::capi {
Outcome circle_parameter_of(const char* fn, const cyc_mobius* f, Mobius& m);
}

// The circle parameter f of a creator (NULL: f = v, m untouched): f.degree
// is compared with its bound before the coefficient arrays are read, every
// coefficient is checked and named (f.alpha[k], ...). Also used by the
// creators of ringed_c.cpp.
Outcome capi::circle_parameter_of(const char* fn, const cyc_mobius* f, Mobius& m) {
  if (!f) return ok();
  TRY(check_range(fn, "f.degree", f->degree, 0, kMaxMobiusDegree, CYC_E_DEGREE_TOO_HIGH));
  const size_t n = size_t(f->degree) + 1;
  TRY(check_doubles(fn, "f.alpha", f->alpha, n));
  TRY(check_doubles(fn, "f.beta", f->beta, n));
  TRY(check_doubles(fn, "f.gamma", f->gamma, n));
  TRY(check_doubles(fn, "f.delta", f->delta, n));
  Mobius r;
  if (Status s = make_mobius(f->degree, f->alpha, f->beta, f->gamma, f->delta, r);
      s != Status::ok) {
    if (s == Status::degenerate_circle_parameter)
      return fail(int(s), "%s: the circle parameter f has alpha = beta = gamma = delta = 0", fn);
    return fail(int(s), "%s: circle parameter f: %s", fn, explain(s));
  }
  m = r;
  return ok();
}

namespace {

// The output buffers of a batch or grid of count points (data NULL: not
// wanted): stride, capacity and span.
Outcome check_outputs(const char* fn, const cyc_buffer3& points, const cyc_buffer3& du,
                      const cyc_buffer3& dv, const cyc_buffer3& normals, size_t count) {
  for (auto [name, b] : {std::pair<const char*, const cyc_buffer3*>{"points", &points},
                         {"du", &du}, {"dv", &dv}, {"normals", &normals}}) {
    TRY(check_buffer(fn, name, *b, count));
  }
  return ok();
}

// The domain [u0, u1] of a creator.
Outcome check_domain(const char* fn, double u0, double u1) {
  TRY(check_double(fn, "u0", u0));
  return check_double(fn, "u1", u1);
}

// A construction failure located at u, in the construction's words; the
// generic statuses keep their explanation.
Outcome failure_at(const char* fn, Status s, double bad_u) {
  if (s == Status::bad_domain)
    return fail(int(s), "%s: the domain [u0, u1] is empty or reversed", fn);
  if (s == Status::not_finite || !std::isfinite(bad_u)) return from_core(fn, s);
  return from_core_at(fn, s, bad_u);
}

// cyc_prrs_create and cyc_ringed_create: three curves, a Mobius f, a domain.
template <class Make>
Outcome three_curve_surface(const char* fn, cyc_context* ctx, const cyc_curve* const (&in)[3],
                            const cyc_mobius* f, double u0, double u1, cyc_surface** out,
                            const char* invalid, const char* dependent, Make&& make) {
  for (int i = 0; i < 3; ++i)
    if (!in[i]) return fail(CYC_E_NULL_ARGUMENT, "%s: input curve %d of 3 is NULL", fn, i + 1);
  REQUIRE(out);
  Mobius m;
  TRY(circle_parameter_of(fn, f, m));
  TRY(check_domain(fn, u0, u1));
  Surface S;
  double bad_u = u0;
  const Status s = make(in[0]->curve, in[1]->curve, in[2]->curve, f ? &m : nullptr, S, &bad_u);
  if (s == Status::invalid_argument) return fail(int(s), "%s: %s", fn, invalid);
  if (s == Status::dependent_planes && dependent)
    return fail(int(s), "%s: %s (at u = %.17g)", fn, dependent, bad_u);
  if (s != Status::ok) return failure_at(fn, s, bad_u);
  return emit(fn, ctx, out, S);
}

}  // namespace

extern "C" {

int cyc_version_number(void) { return CYC_VERSION_NUMBER; }
const char* cyc_version_string(void) { return CYC_VERSION_STRING; }
int cyc_abi_version(void) { return CYC_ABI_VERSION; }
const char* cyc_status_name(int status) {
  switch (status) {
    case CYC_OK: case CYC_E_NULL_ARGUMENT: case CYC_E_INVALID_ARGUMENT:
    case CYC_E_NOT_FINITE: case CYC_E_DEGREE_TOO_HIGH: case CYC_E_BAD_DOMAIN:
    case CYC_E_DEPENDENT_PLANES: case CYC_E_ZERO_TANGENT: case CYC_E_COLLINEAR_POINTS:
    case CYC_E_DEGENERATE_CIRCLE_PARAMETER: case CYC_E_NOT_CANAL:
    case CYC_E_SINGULAR_POINT: case CYC_E_DEGENERATE_RINGED:
    case CYC_E_PARALLEL_LINES: case CYC_E_NO_COMMON_NORMAL: case CYC_E_RANK_DEFICIENT:
    case CYC_E_AT_INVERSION_CENTER: case CYC_E_NOT_PARABOLIC: case CYC_E_EMPTY_REAL_LOCUS:
    case CYC_E_TOO_FEW_LINES: case CYC_E_NO_NORMAL_FORM: case CYC_E_NOT_PYTHAGOREAN:
    case CYC_E_INTERSECTING_CIRCLES: case CYC_E_NESTED_SPHERES:
    case CYC_E_CURVATURE_RADIUS_TOO_LARGE: case CYC_E_SPHERE_PENCIL:
    case CYC_E_NO_TOUCHING_SPHERE: case CYC_E_SINGLE_TOUCHING_SPHERE:
    case CYC_E_DEGENERATE_CYCLIDE: case CYC_E_NOT_ISOMETRIC: case CYC_E_NOT_ON_LIE_QUADRIC:
    case CYC_E_POINT_AT_INFINITY: case CYC_E_TANGENT_GENERATING_SPHERES:
    case CYC_E_BLEND_FOLDS: case CYC_E_DEVELOPABLE: case CYC_E_POLE_IN_GAUSS_IMAGE:
    case CYC_E_RIDGE:
    case CYC_E_NUMERICAL_OVERFLOW: case CYC_E_BUFFER_TOO_SMALL: case CYC_E_OUT_OF_MEMORY:
    case CYC_E_IO:
    case CYC_E_UNSUPPORTED: case CYC_E_INTERNAL:
      return status_name(Status(status));
    default:
      return "CYC_E_UNKNOWN";
  }
}

// ------------------------------------------------------------ context

int cyc_context_create(const cyc_allocator* allocator, cyc_context** out) {
  if (!out) return CYC_E_NULL_ARGUMENT;
  cyc_allocator a = kDefaultAllocator;
  if (allocator) {
    if (!allocator->alloc || !allocator->free) return CYC_E_INVALID_ARGUMENT;
    a = *allocator;
  }
  void* mem = a.alloc(a.userdata, sizeof(cyc_context), alignof(cyc_context));
  if (!mem) return CYC_E_OUT_OF_MEMORY;
  cyc_context* ctx = new (mem) cyc_context();
  ctx->allocator = a;
  *out = ctx;
  return CYC_OK;
}

void cyc_context_destroy(cyc_context* ctx) {
  if (!ctx) return;
  const cyc_allocator a = ctx->allocator;
  const bool static_context = ctx->caller_memory;
  ctx->~cyc_context();
  if (!static_context) a.free(a.userdata, ctx);  // a static context's block is the caller's
}

// ------------------------------------------------------------ caller memory

namespace {

// The static context's allocator (userdata = the context): carve the block
// in order, then the fallback.
void* arena_alloc(void* userdata, size_t size, size_t alignment) {
  CallerArena& A = static_cast<cyc_context*>(userdata)->arena;
  const auto p = reinterpret_cast<std::uintptr_t>(A.next);
  const std::uintptr_t q = (p + alignment - 1) / alignment * alignment;
  const auto end = reinterpret_cast<std::uintptr_t>(A.end);
  if (q >= p && q <= end && size <= end - q) {
    A.last = reinterpret_cast<unsigned char*>(q);
    A.next = A.last + size;
    return A.last;
  }
  return A.fallback.alloc ? A.fallback.alloc(A.fallback.userdata, size, alignment) : nullptr;
}

void arena_free(void* userdata, void* ptr) {
  if (!ptr) return;
  CallerArena& A = static_cast<cyc_context*>(userdata)->arena;
  auto* p = static_cast<unsigned char*>(ptr);
  if (p >= A.begin && p < A.end) {
    if (p == A.last) A.next = A.last, A.last = nullptr;  // the most recent block: give it back
    return;
  }
  if (A.fallback.free) A.fallback.free(A.fallback.userdata, ptr);
}

// Bytes an object takes from a block: its size plus the worst alignment slack.
constexpr size_t static_bytes(size_t size, size_t alignment) { return size + alignment - 1; }

}  // namespace

size_t cyc_context_static_size(void) { return static_bytes(sizeof(cyc_context), alignof(cyc_context)); }
size_t cyc_surface_static_size(void) { return static_bytes(sizeof(cyc_surface), alignof(cyc_surface)); }
size_t cyc_curve_static_size(void) { return static_bytes(sizeof(cyc_curve), alignof(cyc_curve)); }

int cyc_context_init_static(void* mem, size_t size, const cyc_allocator* fallback,
                            cyc_context** out) {
  if (!mem || !out) return CYC_E_NULL_ARGUMENT;
  if (fallback && (!fallback->alloc || !fallback->free)) return CYC_E_INVALID_ARGUMENT;
  if (size < cyc_context_static_size()) return CYC_E_BUFFER_TOO_SMALL;
  const auto p = reinterpret_cast<std::uintptr_t>(mem);
  const size_t pad = (alignof(cyc_context) - p % alignof(cyc_context)) % alignof(cyc_context);
  auto* block = static_cast<unsigned char*>(mem);
  cyc_context* ctx = new (block + pad) cyc_context();
  ctx->caller_memory = true;
  ctx->arena.begin = block;
  ctx->arena.next = block + pad + sizeof(cyc_context);
  ctx->arena.end = block + size;
  if (fallback) ctx->arena.fallback = *fallback;
  ctx->allocator = {arena_alloc, arena_free, ctx};
  *out = ctx;
  return CYC_OK;
}

size_t cyc_context_static_remaining(const cyc_context* ctx) {
  if (!ctx || !ctx->caller_memory) return 0;
  return size_t(ctx->arena.end - ctx->arena.next);
}

const char* cyc_context_last_error(const cyc_context* ctx) {
  return ctx ? ctx->message : "cyc_context_last_error: context is NULL";
}

int cyc_context_last_status(const cyc_context* ctx) {
  return ctx ? ctx->last_status : CYC_E_NULL_ARGUMENT;
}

int cyc_context_set_error_handler(cyc_context* ctx, cyc_error_handler handler,
                                  void* userdata) {
  const char* fn = "cyc_context_set_error_handler";
  return run(ctx, fn, [&] {
    ctx->handler = handler;
    ctx->handler_userdata = userdata;
    return ok();
  });
}

// ------------------------------------------------------------ curves

namespace {
// Validate stride and degree of a strided coefficient table with `width`
// doubles per row and pack it densely (degree+1 rows) into `packed`.
// The rows are named name[k][j]. The degree is compared with its bound
// (64 bits) before any row is read.
Outcome pack_rows(const char* fn, const char* name, int degree, const double* rows,
                  size_t stride, int width, double* packed) {
  if (stride < size_t(width))
    return fail(CYC_E_INVALID_ARGUMENT, "%s: stride = %zu is below %d doubles per row", fn,
                stride, width);
  TRY(check_range(fn, "degree", degree, 0, CYC_MAX_CURVE_DEGREE, CYC_E_DEGREE_TOO_HIGH));
  TRY(check_span(fn, name, size_t(degree) + 1, stride, size_t(width)));
  TRY(check_rows(fn, name, rows, size_t(degree) + 1, stride, size_t(width)));
  for (int k = 0; k <= degree; ++k)
    for (int j = 0; j < width; ++j) packed[width * k + j] = rows[k * stride + j];
  return ok();
}
}  // namespace

int cyc_curve_create_polynomial(cyc_context* ctx, int degree, const double* coeffs,
                                size_t stride, cyc_curve** out) {
  const char* fn = "cyc_curve_create_polynomial";
  return run(ctx, fn, [&] {
    REQUIRE(coeffs);
    REQUIRE(out);
    double packed[3 * (kMaxCurveDegree + 1)];
    TRY(pack_rows(fn, "coeffs", degree, coeffs, stride, 3, packed));
    RationalCurve c;
    if (Status s = make_polynomial_curve(degree, packed, c); s != Status::ok)
      return from_core(fn, s);
    return emit(fn, ctx, out, c);
  });
}

int cyc_curve_create_rational(cyc_context* ctx, int degree, const double* coeffs,
                              size_t stride, cyc_curve** out) {
  const char* fn = "cyc_curve_create_rational";
  return run(ctx, fn, [&] {
    REQUIRE(coeffs);
    REQUIRE(out);
    double packed[4 * (kMaxCurveDegree + 1)];
    TRY(pack_rows(fn, "coeffs", degree, coeffs, stride, 4, packed));
    RationalCurve c;
    if (Status s = make_rational_curve(degree, packed, c); s != Status::ok)
      return s == Status::invalid_argument
                 ? fail(int(s), "%s: the weight w(u) is identically zero", fn)
                 : from_core(fn, s);
    return emit(fn, ctx, out, c);
  });
}

int cyc_curve_create_bezier(cyc_context* ctx, int degree, const double* ctrl,
                            size_t stride, const double* weights, double u0, double u1,
                            cyc_curve** out) {
  const char* fn = "cyc_curve_create_bezier";
  return run(ctx, fn, [&] {
    REQUIRE(ctrl);
    REQUIRE(out);
    double packed[3 * (kMaxCurveDegree + 1)];
    TRY(pack_rows(fn, "ctrl", degree, ctrl, stride, 3, packed));
    if (weights) TRY(check_doubles(fn, "weights", weights, size_t(degree) + 1));
    TRY(check_domain(fn, u0, u1));
    RationalCurve c;
    if (Status s = make_bezier_curve(degree, packed, weights, u0, u1, c); s != Status::ok)
      return s == Status::invalid_argument
                 ? fail(int(s), "%s: all weights are zero", fn)
             : s == Status::bad_domain
                 ? fail(int(s), "%s: the domain [u0, u1] = [%.17g, %.17g] is empty or reversed",
                        fn, u0, u1)
                 : from_core(fn, s);
    return emit(fn, ctx, out, c);
  });
}

int cyc_curve_create_line(cyc_context* ctx, const double point[3],
                          const double direction[3], cyc_curve** out) {
  const char* fn = "cyc_curve_create_line";
  return run(ctx, fn, [&] {
    REQUIRE(point);
    REQUIRE(direction);
    REQUIRE(out);
    TRY(check_doubles(fn, "point", point, 3));
    TRY(check_doubles(fn, "direction", direction, 3));
    RationalCurve c;
    if (Status s = make_line(vec(point), vec(direction), c); s != Status::ok)
      return s == Status::zero_tangent ? fail(int(s), "%s: direction is zero", fn)
                                       : from_core(fn, s);
    return emit(fn, ctx, out, c);
  });
}

int cyc_curve_create_point(cyc_context* ctx, const double point[3], cyc_curve** out) {
  const char* fn = "cyc_curve_create_point";
  return run(ctx, fn, [&] {
    REQUIRE(point);
    REQUIRE(out);
    TRY(check_doubles(fn, "point", point, 3));
    RationalCurve c;
    if (Status s = make_point(vec(point), c); s != Status::ok) return from_core(fn, s);
    return emit(fn, ctx, out, c);
  });
}

int cyc_curve_create_line_element(cyc_context* ctx, const double point[3],
                                  const double tangent[3], cyc_curve** out) {
  const char* fn = "cyc_curve_create_line_element";
  return run(ctx, fn, [&] {
    REQUIRE(point);
    REQUIRE(tangent);
    REQUIRE(out);
    TRY(check_doubles(fn, "point", point, 3));
    TRY(check_doubles(fn, "tangent", tangent, 3));
    RationalCurve c;
    if (Status s = make_line_element(vec(point), vec(tangent), c); s != Status::ok)
      return s == Status::zero_tangent ? fail(int(s), "%s: tangent is zero", fn)
                                       : from_core(fn, s);
    return emit(fn, ctx, out, c);
  });
}

int cyc_curve_create_hermite(cyc_context* ctx, int order, double u0, double u1,
                             const double* start, const double* end, cyc_curve** out) {
  const char* fn = "cyc_curve_create_hermite";
  return run(ctx, fn, [&] {
    REQUIRE(start);
    REQUIRE(end);
    REQUIRE(out);
    TRY(check_range(fn, "order", order, 0, CYC_MAX_HERMITE_ORDER, CYC_E_DEGREE_TOO_HIGH));
    TRY(check_rows(fn, "start", start, size_t(order) + 1, 3, 3));
    TRY(check_rows(fn, "end", end, size_t(order) + 1, 3, 3));
    TRY(check_domain(fn, u0, u1));
    Vec3d a[kMaxHermiteOrder + 1], b[kMaxHermiteOrder + 1];
    for (int j = 0; j <= order; ++j) {
      a[j] = vec(start + 3 * j);
      b[j] = vec(end + 3 * j);
    }
    RationalCurve c;
    if (Status s = make_hermite_curve(order, u0, u1, a, b, c); s != Status::ok)
      return from_core(fn, s);
    return emit(fn, ctx, out, c);
  });
}

void cyc_curve_destroy(cyc_context*, cyc_curve* curve) { release(curve); }

int cyc_curve_degree(cyc_context* ctx, const cyc_curve* curve, int* degree) {
  const char* fn = "cyc_curve_degree";
  return run(ctx, fn, [&] {
    REQUIRE(curve);
    REQUIRE(degree);
    *degree = curve->curve.degree();
    return ok();
  });
}

int cyc_curve_eval(cyc_context* ctx, const cyc_curve* curve, double u, int order,
                   double* out, size_t capacity) {
  const char* fn = "cyc_curve_eval";
  constexpr int kMaxOrder = 8;
  return run(ctx, fn, [&] {
    REQUIRE(curve);
    REQUIRE(out);
    TRY(check_range(fn, "order", order, 0, kMaxOrder));
    const size_t need = 3 * size_t(order + 1);
    if (capacity < need)
      return fail(CYC_E_BUFFER_TOO_SMALL, "%s: capacity %zu doubles, %zu needed", fn,
                  capacity, need);
    TRY(check_double(fn, "u", u));
    const auto P = curve->curve.taylor<kMaxOrder>(u);
    double tmp[3 * (kMaxOrder + 1)];
    for (int k = 0; k <= order; ++k)
      for (int j = 0; j < 3; ++j) {
        tmp[3 * k + j] = P[j].derivative(k);
        if (!std::isfinite(tmp[3 * k + j]))
          return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: not finite at u = %.17g (a pole?)", fn,
                      u);
      }
    std::memcpy(out, tmp, need * sizeof(double));
    return ok();
  });
}

// ------------------------------------------------------------ surfaces

int cyc_prcs_create(cyc_context* ctx, const cyc_curve* p1, const cyc_curve* p2,
                    const cyc_mobius* f, double u0, double u1, cyc_surface** out) {
  const char* fn = "cyc_prcs_create";
  return run(ctx, fn, [&] {
    REQUIRE(p1);
    REQUIRE(p2);
    REQUIRE(out);
    Mobius m;
    TRY(circle_parameter_of(fn, f, m));
    TRY(check_domain(fn, u0, u1));
    Surface S;
    double bad_u = u0;
    const Status s = make_prcs(p1->curve, p2->curve, f ? &m : nullptr, u0, u1, S, &bad_u);
    const bool point_input =
        p1->curve.kind == CurveKind::point || p2->curve.kind == CurveKind::point;
    const bool two_elements = p1->curve.kind == CurveKind::line_element &&
                              p2->curve.kind == CurveKind::line_element;
    if (s == Status::zero_tangent && point_input)
      return fail(int(s), "%s: p1 or p2 is a constant point: its normal plane is undefined "
                  "(a PRCS input is a curve or a line element)", fn);
    if (s == Status::zero_tangent)
      return fail(int(s), "%s: p1 and p2 have zero tangents on the whole domain", fn);
    if (s == Status::dependent_planes && two_elements)
      return fail(int(s), "%s: p1 and p2 are both line elements: their normal planes M, N are "
                  "fixed and no circle sweeps between them", fn);
    if (s == Status::dependent_planes)
      return fail(int(s), "%s: the normal planes M, N of p1, p2 (8), (9) and their bisector "
                  "plane B (10) are (nearly) dependent at u = %.17g, so the sphere center s "
                  "is undefined (seed 000 Remark 1: e.g. two lines of curvature, or parallel "
                  "normal planes)", fn, bad_u);
    if (s != Status::ok) return failure_at(fn, s, bad_u);
    return emit(fn, ctx, out, S);
  });
}

int cyc_prrs_create(cyc_context* ctx, const cyc_curve* p1, const cyc_curve* p2,
                    const cyc_curve* p3, const cyc_mobius* f, double u0, double u1,
                    cyc_surface** out) {
  const char* fn = "cyc_prrs_create";
  return run(ctx, fn, [&] {
    return three_curve_surface(
        fn, ctx, {p1, p2, p3}, f, u0, u1, out,
        "inputs must be curves or points, not all points and no line elements",
        "the circle through p1, p2, p3 has no axis (its plane is undefined)",
        [&](const RationalCurve& a, const RationalCurve& b, const RationalCurve& c,
            const Mobius* m, Surface& S, double* bad) {
          return make_prrs(a, b, c, m, u0, u1, S, bad);
        });
  });
}

int cyc_ringed_create(cyc_context* ctx, const cyc_curve* d, const cyc_curve* n,
                      const cyc_curve* c, const cyc_mobius* f, double u0, double u1,
                      cyc_surface** out) {
  const char* fn = "cyc_ringed_create";
  return run(ctx, fn, [&] {
    return three_curve_surface(
        fn, ctx, {d, n, c}, f, u0, u1, out,
        "d, n and c must be curves or points, not line elements",
        "the orientation function n vanishes: no circle plane",
        [&](const RationalCurve& a, const RationalCurve& b, const RationalCurve& cc,
            const Mobius* m, Surface& S, double* bad) {
          return make_ringed(a, b, cc, m, u0, u1, S, bad);
        });
  });
}

void cyc_surface_destroy(cyc_context*, cyc_surface* surface) { release(surface); }

int cyc_surface_kind(cyc_context* ctx, const cyc_surface* surface, int* kind) {
  const char* fn = "cyc_surface_kind";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    REQUIRE(kind);
    *kind = int(surface->surface.kind);
    return ok();
  });
}

int cyc_surface_domain(cyc_context* ctx, const cyc_surface* surface, double* u0,
                       double* u1) {
  const char* fn = "cyc_surface_domain";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    REQUIRE(u0);
    REQUIRE(u1);
    *u0 = surface->surface.u0;
    *u1 = surface->surface.u1;
    return ok();
  });
}

namespace {
// The surface parameter u is an input (|u| <= 1e100); the circle parameter
// v is any finite number (f(u, v) is a Mobius map of the whole line). Only
// called once the core has refused (u, v) as not finite: names the one to
// blame.
Outcome bad_point(const char* fn, const char* u_name, double u, const char* v_name, double v) {
  TRY(check_double(fn, u_name, u));
  if (!std::isfinite(v))
    return fail(CYC_E_NOT_FINITE, "%s: %s = %.17g %s", fn, v_name, v, what_is_wrong(v));
  return from_core(fn, Status::not_finite);
}

// After the core refused a batch or grid as not finite (it validates every
// entry before it writes anything): the first entry to blame.
Outcome bad_batch(const char* fn, const double* uv, size_t stride, size_t count) {
  char u_name[48], v_name[48];
  for (size_t k = 0; k < count; ++k) {
    const double u = uv[k * stride], v = uv[k * stride + 1];
    if (beyond_input_range(u) || !std::isfinite(v)) {
      std::snprintf(u_name, sizeof u_name, "uv[%zu][0]", k);
      std::snprintf(v_name, sizeof v_name, "uv[%zu][1]", k);
      return bad_point(fn, u_name, u, v_name, v);
    }
  }
  return from_core(fn, Status::not_finite);
}
Outcome bad_grid(const char* fn, const double* us, size_t nu, const double* vs, size_t nv) {
  TRY(check_doubles(fn, "us", us, nu));
  for (size_t j = 0; j < nv; ++j)
    if (!std::isfinite(vs[j]))
      return fail(CYC_E_NOT_FINITE, "%s: vs[%zu] = %.17g %s", fn, j, vs[j], what_is_wrong(vs[j]));
  return from_core(fn, Status::not_finite);
}

// The guarded path of cyc_surface_eval: argument errors, and evaluation
// errors (status s) with their message and the error handler. Kept out of
// line so that the hot path stays small.
#if defined(__GNUC__)
__attribute__((noinline, cold))
#endif
int surface_eval_error(cyc_context* ctx, const cyc_surface* surface, double u, double v,
                       Status s) {
  const char* fn = "cyc_surface_eval";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    if (s == Status::ok) return fail(CYC_E_NULL_ARGUMENT, "%s: no output requested", fn);
    if (s == Status::not_finite) return bad_point(fn, "u", u, "v", v);
    return fail(int(s), "%s: %s (at u = %.17g, v = %.17g)", fn, explain(s), u, v);
  });
}
}  // namespace

// Single points are the hottest entry point (SPEC §1b): with valid
// arguments it calls the evaluator directly instead of through the guard's
// closure. Surface::eval is noexcept (allocation-free, no exceptions), so
// the guard has nothing to catch here; every error is reported through it.
int cyc_surface_eval(cyc_context* ctx, const cyc_surface* surface, double u, double v,
                     double point[3], double du[3], double dv[3], double normal[3]) {
  if (!ctx) return CYC_E_NULL_ARGUMENT;
  Status s = Status::ok;  // ok below: no output was requested
  if (surface && (point || du || dv || normal)) {
    // Surface::eval writes the outputs only on success.
    s = surface->surface.eval(u, v, EvalOut{point, du, dv, normal});
    if (s == Status::ok) return succeed(ctx);
  }
  return surface_eval_error(ctx, surface, u, v, s);
}

int cyc_surface_eval_batch(cyc_context* ctx, const cyc_surface* surface, const double* uv,
                           size_t uv_stride, size_t count, cyc_buffer3 points,
                           cyc_buffer3 du, cyc_buffer3 dv, cyc_buffer3 normals,
                           size_t* singular) {
  const char* fn = "cyc_surface_eval_batch";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    if (count) REQUIRE(uv);
    if (uv_stride < 2)
      return fail(CYC_E_INVALID_ARGUMENT, "%s: uv_stride = %zu is below 2", fn, uv_stride);
    TRY(check_span(fn, "uv", count, uv_stride, 2));
    TRY(check_outputs(fn, points, du, dv, normals, count));
    const Status s = surface->surface.eval_batch(uv, uv_stride, count, strided(points),
                                                 strided(du), strided(dv),
                                                 strided(normals), singular);
    if (s == Status::not_finite) return bad_batch(fn, uv, uv_stride, count);
    return from_core(fn, s);
  });
}

int cyc_surface_eval_grid(cyc_context* ctx, const cyc_surface* surface, const double* us,
                          size_t nu, const double* vs, size_t nv, cyc_buffer3 points,
                          cyc_buffer3 du, cyc_buffer3 dv, cyc_buffer3 normals,
                          size_t* singular) {
  const char* fn = "cyc_surface_eval_grid";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    if (nu) REQUIRE(us);
    if (nv) REQUIRE(vs);
    size_t count = 0;
    TRY(check_grid_sizes(fn, "us", nu, "vs", nv, count));
    TRY(check_outputs(fn, points, du, dv, normals, count));
    const Status s = surface->surface.eval_grid(us, nu, vs, nv, strided(points),
                                                strided(du), strided(dv),
                                                strided(normals), singular);
    if (s == Status::not_finite) return bad_grid(fn, us, nu, vs, nv);
    return from_core(fn, s);
  });
}

int cyc_surface_circle(cyc_context* ctx, const cyc_surface* surface, double u,
                       cyc_circle* out) {
  const char* fn = "cyc_surface_circle";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    REQUIRE(out);
    TRY(check_double(fn, "u", u));
    Vec3d c, n;
    double r2;
    if (Status s = surface->surface.circle(u, c, n, r2); s != Status::ok)
      return from_core_at(fn, s, u);
    put3(out->center, c);
    put3(out->normal, n);
    out->radius2 = r2;
    return ok();
  });
}

int cyc_surface_sphere(cyc_context* ctx, const cyc_surface* surface, double u,
                       cyc_sphere* out) {
  const char* fn = "cyc_surface_sphere";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    REQUIRE(out);
    Vec3d c;
    double r2;
    // The kind is checked before u: a PRRS surface has no spheres at any u.
    if (Status s = surface->surface.sphere(u, c, r2); s != Status::ok) {
      if (s == Status::not_finite) TRY(check_double(fn, "u", u));
      if (s == Status::not_canal)
        return fail(int(s), "%s: the surface is not a canal surface by construction (PRRS, "
                    "ringed): it has no touching spheres", fn);
      return from_core_at(fn, s, u);
    }
    put3(out->center, c);
    out->radius2 = r2;
    return ok();
  });
}

int cyc_surface_ringed_data(cyc_context* ctx, const cyc_surface* surface, double u,
                            double c[3], double n[3], double* rho2,
                            double* rho_rho_prime) {
  const char* fn = "cyc_surface_ringed_data";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    TRY(check_double(fn, "u", u));
    RingedData R;
    if (Status s = surface->surface.ringed(u, R); s != Status::ok)
      return from_core_at(fn, s, u);
    if (c) put3(c, R.c);
    if (n) put3(n, R.n);
    if (rho2) *rho2 = R.rho2;
    if (rho_rho_prime) *rho_rho_prime = R.rho_rho_prime;
    return ok();
  });
}

int cyc_surface_ringed_sphere(cyc_context* ctx, const cyc_surface* surface, double u,
                              cyc_sphere* out) {
  const char* fn = "cyc_surface_ringed_sphere";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    REQUIRE(out);
    TRY(check_double(fn, "u", u));
    RingedData R;
    if (Status s = surface->surface.ringed(u, R); s != Status::ok)
      return from_core_at(fn, s, u);
    Vec3d m;
    double r2;
    if (Status s = ringed_sphere(R, m, r2); s != Status::ok) return from_core_at(fn, s, u);
    if (!m.allFinite() || !std::isfinite(r2))
      return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: the sphere at u = %.17g overflows (n.c' is "
                  "too small for its radius)", fn, u);
    put3(out->center, m);
    out->radius2 = r2;
    return ok();
  });
}

int cyc_surface_canal_test(cyc_context* ctx, const cyc_surface* surface, double tolerance,
                           double* max_residual, int* is_canal) {
  const char* fn = "cyc_surface_canal_test";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    if (!max_residual && !is_canal)
      return fail(CYC_E_NULL_ARGUMENT, "%s: no output requested", fn);
    // tolerance <= 0 chooses the default; NaN or beyond the input range is
    // an error like any other double input.
    TRY(check_double(fn, "tolerance", tolerance));
    double worst = 0, floor = 0;
    if (Status s = surface->surface.canal_test(worst, &floor); s != Status::ok)
      return from_core(fn, s);
    const double tol = tolerance > 0 ? tolerance : kCanalTolerance + kCanalFloorFactor * floor;
    if (max_residual) *max_residual = worst;
    if (is_canal) *is_canal = worst <= tol;
    return ok();
  });
}

int cyc_surface_parameter_of(cyc_context* ctx, const cyc_surface* surface, double u,
                             const double point[3], double* v) {
  const char* fn = "cyc_surface_parameter_of";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    REQUIRE(point);
    REQUIRE(v);
    TRY(check_double(fn, "u", u));
    TRY(check_doubles(fn, "point", point, 3));
    double r;
    if (Status s = surface->surface.parameter_of(u, vec(point), r); s != Status::ok)
      return from_core_at(fn, s, u);
    if (std::isnan(r))
      return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: the circle parameter of point is undefined "
                  "at u = %.17g", fn, u);
    *v = r;
    return ok();
  });
}

}  // extern "C"

// ------------------------------------------------------------ Darboux cyclides

static_assert(CYC_DARBOUX_COEFFS == kDarbouxCoeffs, "coefficient count");
static_assert(CYC_DARBOUX_REDUCIBLE == int(DarbouxType::reducible), "type numbers");
static_assert(CYC_DARBOUX_QUARTIC == int(DarbouxType::quartic), "type numbers");

namespace {

// Outputs: every double of a result finite, or the call is
// CYC_E_NUMERICAL_OVERFLOW (valid inputs near the range's end can overflow
// a product: never a non-finite output with CYC_OK).
bool finite_all(const double* x, size_t n) {
  for (size_t i = 0; i < n; ++i)
    if (!std::isfinite(x[i])) return false;
  return true;
}
bool finite_line(const cyc_line& l) { return finite_all(l.point, 3) && finite_all(l.direction, 3); }
Outcome overflow(const char* fn, const char* what) {
  return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: %s overflows (not finite in double precision)", fn,
              what);
}

// The coefficients of a Darboux equation (31), named name.k[i].
Outcome read_darboux(const char* fn, const char* name, const cyc_darboux& in, Darboux& out) {
  char field[48];
  std::snprintf(field, sizeof field, "%s.k", name);
  TRY(check_doubles(fn, field, in.k, CYC_DARBOUX_COEFFS));
  std::memcpy(out.k, in.k, sizeof out.k);
  return ok();
}

// An inversion (X - m) -> rho^2 (X - m) / |X - m|^2 at the sphere (m, rho):
// rho must be positive.
Outcome read_inversion(const char* fn, const cyc_inversion& in, Inversion& out) {
  TRY(check_doubles(fn, "inv.center", in.center, 3));
  TRY(check_double(fn, "inv.radius", in.radius));
  if (!(in.radius > 0))
    return fail(CYC_E_INVALID_ARGUMENT, "%s: inv.radius = %.17g is not positive: an inversion "
                "needs a sphere of radius > 0", fn, in.radius);
  out.m = vec(in.center);
  out.rho = in.radius;
  return from_core(fn, check_inversion(out));
}

// A line's point and direction, named name.point, name.direction.
Outcome read_line(const char* fn, const char* name, const cyc_line& l, Line& out) {
  char field[48];
  std::snprintf(field, sizeof field, "%s.point", name);
  TRY(check_doubles(fn, field, l.point, 3));
  std::snprintf(field, sizeof field, "%s.direction", name);
  TRY(check_doubles(fn, field, l.direction, 3));
  out = {vec(l.point), vec(l.direction)};
  return ok();
}
// lines[0..2], named lines[i].point, lines[i].direction.
Outcome read_lines(const char* fn, const cyc_line lines[3], Line (&out)[3]) {
  char name[24];
  for (int i = 0; i < 3; ++i) {
    std::snprintf(name, sizeof name, "lines[%d]", i);
    TRY(read_line(fn, name, lines[i], out[i]));
  }
  return ok();
}

// The failures of constructions on three lines l1, l2, l3 (DCMC of §6,
// PRRS of lines of §8): parallel lines, no common normal, a zero direction.
Outcome three_lines_failure(const char* fn, Status s, const Line (&L)[3],
                            const char* construction) {
  if (s == Status::invalid_argument)
    for (int i = 0; i < 3; ++i)
      if (!(L[i].d.squaredNorm() > 0))
        return fail(int(s), "%s: lines[%d].direction is zero", fn, i);
  if (s == Status::parallel_lines)
    return fail(int(s), "%s: two of the three lines are parallel (%s needs mutually "
                "non-parallel lines)", fn, construction);
  if (s == Status::no_common_normal)
    return fail(int(s), "%s: the three directions have no common normal: the lines do not "
                "lie in parallel planes (%s needs them to)", fn, construction);
  return from_core(fn, s);
}
void put_line(cyc_line& out, const Line& L) {
  put3(out.point, L.P);
  put3(out.direction, L.d);
}

void put_circle_or_line(cyc_circle_or_line& out, const CircleOrLine& C) {
  out.is_line = C.is_line ? 1 : 0;
  put3(out.point, C.point);
  put3(out.axis, C.axis);
  out.radius = C.radius;
}

void put_darboux(cyc_darboux* out, const Darboux& D) {
  std::memcpy(out->k, D.k, sizeof out->k);
}

}  // namespace

int cyc_darboux_eval(cyc_context* ctx, const cyc_darboux* d, const double x[3], double* value,
                     double gradient[3]) {
  const char* fn = "cyc_darboux_eval";
  return run(ctx, fn, [&] {
    REQUIRE(d);
    REQUIRE(x);
    REQUIRE(value);
    Darboux D;
    TRY(read_darboux(fn, "d", *d, D));
    TRY(check_doubles(fn, "x", x, 3));
    const Vec3d X = vec(x);
    const double v = D.value(X);
    const Vec3d g = D.gradient(X);
    if (!std::isfinite(v) || (gradient && !std::isfinite(g.sum())))
      return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: the value of d at x overflows", fn);
    *value = v;
    if (gradient) put3(gradient, g);
    return ok();
  });
}

int cyc_darboux_classify(cyc_context* ctx, const cyc_darboux* d, int* type) {
  const char* fn = "cyc_darboux_classify";
  return run(ctx, fn, [&] {
    REQUIRE(d);
    REQUIRE(type);
    Darboux D;
    TRY(read_darboux(fn, "d", *d, D));
    *type = int(darboux_type(D));
    return ok();
  });
}

int cyc_invert_point(cyc_context* ctx, const cyc_inversion* inv, const double x[3],
                     double out[3]) {
  const char* fn = "cyc_invert_point";
  return run(ctx, fn, [&] {
    REQUIRE(inv);
    REQUIRE(x);
    REQUIRE(out);
    Inversion I;
    TRY(read_inversion(fn, *inv, I));
    TRY(check_doubles(fn, "x", x, 3));
    Vec3d Y;
    if (Status s = invert_point(I, vec(x), Y); s != Status::ok) {
      if (s == Status::numerical_overflow)
        return fail(int(s), "%s: x is so close to inv.center that its image overflows", fn);
      return from_core(fn, s);
    }
    put3(out, Y);
    return ok();
  });
}

int cyc_invert_sphere(cyc_context* ctx, const cyc_inversion* inv, const cyc_general_sphere* s,
                      cyc_general_sphere* out) {
  const char* fn = "cyc_invert_sphere";
  return run(ctx, fn, [&] {
    REQUIRE(inv);
    REQUIRE(s);
    REQUIRE(out);
    Inversion I;
    TRY(read_inversion(fn, *inv, I));
    TRY(check_double(fn, "s.a", s->a));
    TRY(check_doubles(fn, "s.b", s->b, 3));
    TRY(check_double(fn, "s.c", s->c));
    GeneralSphere R;
    if (Status st = invert_sphere(I, {s->a, vec(s->b), s->c}, R); st != Status::ok) {
      if (st == Status::invalid_argument)
        return fail(int(st), "%s: s.a = 0 and s.b = 0: the equation describes no sphere or "
                    "plane", fn);
      if (st == Status::numerical_overflow)
        return fail(int(st), "%s: the image's coefficients overflow", fn);
      return from_core(fn, st);
    }
    out->a = R.A;
    put3(out->b, R.B);
    out->c = R.C;
    return ok();
  });
}

int cyc_invert_circle(cyc_context* ctx, const cyc_inversion* inv, const cyc_circle_or_line* c,
                      cyc_circle_or_line* out) {
  const char* fn = "cyc_invert_circle";
  return run(ctx, fn, [&] {
    REQUIRE(inv);
    REQUIRE(c);
    REQUIRE(out);
    Inversion I;
    TRY(read_inversion(fn, *inv, I));
    TRY(check_doubles(fn, "c.point", c->point, 3));
    TRY(check_doubles(fn, "c.axis", c->axis, 3));
    TRY(check_double(fn, "c.radius", c->radius));
    CircleOrLine R;
    if (Status st = invert_circle(I, {c->is_line != 0, vec(c->point), vec(c->axis), c->radius}, R);
        st != Status::ok) {
      if (st == Status::invalid_argument && !(vec(c->axis).squaredNorm() > 0))
        return fail(int(st), "%s: c.axis is zero", fn);
      if (st == Status::invalid_argument)
        return fail(int(st), "%s: c.radius = %.17g is not positive", fn, c->radius);
      if (st == Status::numerical_overflow)
        return fail(int(st), "%s: the image is not resolved in double precision (c passes "
                    "too close to inv.center, or the image is below the rounding of its "
                    "center)", fn);
      return from_core(fn, st);
    }
    put_circle_or_line(*out, R);
    return ok();
  });
}

int cyc_invert_darboux(cyc_context* ctx, const cyc_inversion* inv, const cyc_darboux* d,
                       cyc_darboux* out) {
  const char* fn = "cyc_invert_darboux";
  return run(ctx, fn, [&] {
    REQUIRE(inv);
    REQUIRE(d);
    REQUIRE(out);
    Inversion I;
    TRY(read_inversion(fn, *inv, I));
    Darboux D, R;
    TRY(read_darboux(fn, "d", *d, D));
    if (Status st = invert_darboux(I, D, R); st != Status::ok) {
      if (st == Status::numerical_overflow)
        return fail(int(st), "%s: the inverted equation's coefficients overflow", fn);
      return from_core(fn, st);
    }
    put_darboux(out, R);
    return ok();
  });
}

int cyc_surface_eval_inverted(cyc_context* ctx, const cyc_surface* surface,
                              const cyc_inversion* inv, double u, double v, double point[3],
                              double du[3], double dv[3], double normal[3]) {
  const char* fn = "cyc_surface_eval_inverted";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    REQUIRE(inv);
    REQUIRE(point);
    Inversion I;
    TRY(read_inversion(fn, *inv, I));
    TRY(check_double(fn, "u", u));
    if (!std::isfinite(v))
      return fail(CYC_E_NOT_FINITE, "%s: v = %.17g %s", fn, v, what_is_wrong(v));
    SurfacePoint P, R;
    const EvalOut o{P.x.data(), du ? P.du.data() : nullptr, dv ? P.dv.data() : nullptr,
                    normal ? P.normal.data() : nullptr};
    if (Status s = surface->surface.eval(u, v, o); s != Status::ok)
      return fail(int(s), "%s: %s (at u = %.17g, v = %.17g)", fn, explain(s), u, v);
    if (Status s = invert_surface_point(I, P, du, dv, normal, R); s != Status::ok)
      return fail(int(s), "%s: %s (at u = %.17g, v = %.17g)", fn, explain(s), u, v);
    put3(point, R.x);
    if (du) put3(du, R.du);
    if (dv) put3(dv, R.dv);
    if (normal) put3(normal, R.normal);
    return ok();
  });
}

int cyc_surface_circle_inverted(cyc_context* ctx, const cyc_surface* surface,
                                const cyc_inversion* inv, double u, cyc_circle_or_line* out) {
  const char* fn = "cyc_surface_circle_inverted";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    REQUIRE(inv);
    REQUIRE(out);
    Inversion I;
    TRY(read_inversion(fn, *inv, I));
    TRY(check_double(fn, "u", u));
    CircleOrLine R;
    if (Status s = inverted_circle(surface->surface, I, u, R); s != Status::ok)
      return from_core_at(fn, s, u);
    put_circle_or_line(*out, R);
    return ok();
  });
}

int cyc_surface_eval_grid_inverted(cyc_context* ctx, const cyc_surface* surface,
                                   const cyc_inversion* inv, const double* us, size_t nu,
                                   const double* vs, size_t nv, cyc_buffer3 points,
                                   cyc_buffer3 du, cyc_buffer3 dv, cyc_buffer3 normals,
                                   size_t* singular) {
  const char* fn = "cyc_surface_eval_grid_inverted";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    REQUIRE(inv);
    if (nu) REQUIRE(us);
    if (nv) REQUIRE(vs);
    size_t count = 0;
    TRY(check_grid_sizes(fn, "us", nu, "vs", nv, count));
    TRY(check_outputs(fn, points, du, dv, normals, count));
    Inversion I;
    TRY(read_inversion(fn, *inv, I));
    const Status s = eval_grid_inverted(surface->surface, I, us, nu, vs, nv, strided(points),
                                        strided(du), strided(dv), strided(normals), singular);
    if (s == Status::not_finite) return bad_grid(fn, us, nu, vs, nv);
    return from_core(fn, s);
  });
}

int cyc_dcmc(cyc_context* ctx, const cyc_line lines[3], double normal[3], cyc_darboux* base,
             cyc_darboux* quadric) {
  const char* fn = "cyc_dcmc";
  return run(ctx, fn, [&] {
    REQUIRE(lines);
    REQUIRE(base);
    REQUIRE(quadric);
    Line L[3];
    TRY(read_lines(fn, lines, L));
    DcmcFamily F;
    if (Status s = dcmc(L, F); s != Status::ok) {
      if (s == Status::rank_deficient)
        return fail(int(s), "%s: the cyclides through the three lines form more than the "
                    "one-parameter family of §6 (the linear system of steps 3-4 is rank "
                    "deficient)", fn);
      return three_lines_failure(fn, s, L, "DCMC");
    }
    if (!F.n.allFinite() || !finite_all(F.base.k, CYC_DARBOUX_COEFFS) ||
        !finite_all(F.quadric.k, CYC_DARBOUX_COEFFS))
      return overflow(fn, "the family base + alpha quadric");
    if (normal) put3(normal, F.n);
    put_darboux(base, F.base);
    put_darboux(quadric, F.quadric);
    return ok();
  });
}

// ------------------------------------------------------------ fit and classification

static_assert(CYC_MIN_FIT_POINTS == kMinFitPoints && CYC_MAX_FIT_POINTS == kMaxFitPoints,
              "fit bounds");

namespace {
bool finite_fit(const DarbouxFit& F) {
  return finite_all(F.D.k, CYC_DARBOUX_COEFFS) && std::isfinite(F.residual) &&
         std::isfinite(F.sigma_ratio);
}
void put_fit(cyc_darboux_fit& out, const DarbouxFit& F) {
  put_darboux(&out.d, F.D);
  out.residual = F.residual;
  out.sigma_ratio = F.sigma_ratio;
  out.nullity = F.nullity;
  out.points = F.points;
  out.is_darboux = F.is_darboux ? 1 : 0;
}
void put_classification(cyc_lines_classification& out, const LinesClassification& C) {
  cyc_lines_classification R;
  std::memset(&R, 0, sizeof R);
  R.kind = int(C.kind);
  R.paper_case = C.paper_case;
  R.circle_families = C.circle_families;
  R.double_families = C.double_families;
  R.pn = C.pn ? 1 : 0;
  R.swapped = C.nf.swapped ? 1 : 0;
  R.a = C.nf.a;
  R.b = C.nf.b;
  R.c = C.nf.c;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) R.rotation[3 * i + j] = C.nf.T.R(i, j);
  R.scale = C.nf.T.scale;
  put3(R.origin, C.nf.T.origin);
  R.alpha = C.nf.alpha;
  R.beta = C.nf.beta;
  out = R;
}
bool finite_classification(const LinesClassification& C) {
  cyc_lines_classification R;
  put_classification(R, C);
  return std::isfinite(R.a) && std::isfinite(R.b) && std::isfinite(R.c) &&
         finite_all(R.rotation, 9) && std::isfinite(R.scale) && finite_all(R.origin, 3) &&
         std::isfinite(R.alpha) && std::isfinite(R.beta);
}
// The classifications' failures in their own words (seed 000 Props. 2, 8,
// 9 and their normal forms (45), (68), (77)).
Outcome classify_failure(const char* fn, Status s, const char* no_normal_form) {
  switch (s) {
    case Status::zero_tangent:
      return fail(int(s), "%s: a direction is zero: l1.direction, or the second line's", fn);
    case Status::parallel_lines:
      return fail(int(s), "%s: l1 and l2 are parallel: they have no common perpendicular, so "
                  "no normal form (45) of Prop. 2", fn);
    case Status::no_normal_form: return fail(int(s), "%s: %s", fn, no_normal_form);
    case Status::numerical_overflow:
      return fail(int(s), "%s: the normal form's coefficients overflow (the inputs are "
                  "too far apart relative to their distance from l1)", fn);
    default: return from_core(fn, s);
  }
}

}  // namespace

int cyc_darboux_fit_points(cyc_context* ctx, const double* points, int count,
                           cyc_darboux_fit* out) {
  const char* fn = "cyc_darboux_fit_points";
  return run(ctx, fn, [&] {
    REQUIRE(points);
    REQUIRE(out);
    TRY(check_range(fn, "count", count, kMinFitPoints, kMaxFitPoints));
    TRY(check_rows(fn, "points", points, size_t(count), 3, 3));
    Vec3d X[kMaxFitPoints];
    for (int i = 0; i < count; ++i) X[i] = vec(points + 3 * i);
    DarbouxFit F;
    const Status s = fit_darboux(X, count, F);
    if (s == Status::invalid_argument) return fail(int(s), "%s: all points are equal", fn);
    if (s != Status::ok) return from_core(fn, s);
    if (!finite_fit(F)) return overflow(fn, "the fitted equation");
    put_fit(*out, F);
    return ok();
  });
}

int cyc_darboux_fit_surface(cyc_context* ctx, const cyc_surface* surface, cyc_darboux_fit* out) {
  const char* fn = "cyc_darboux_fit_surface";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    REQUIRE(out);
    DarbouxFit F;
    const Status s = fit_darboux(surface->surface, F);
    if (s == Status::invalid_argument)
      return fail(int(s), "%s: too few samples of the surface could be evaluated", fn);
    if (s != Status::ok) return from_core(fn, s);
    if (!finite_fit(F)) return overflow(fn, "the fitted equation");
    put_fit(*out, F);
    return ok();
  });
}

int cyc_classify_two_lines(cyc_context* ctx, const cyc_line* l1, const cyc_line* l2,
                           cyc_lines_classification* out) {
  const char* fn = "cyc_classify_two_lines";
  return run(ctx, fn, [&] {
    REQUIRE(l1);
    REQUIRE(l2);
    REQUIRE(out);
    Line A, B;
    TRY(read_line(fn, "l1", *l1, A));
    TRY(read_line(fn, "l2", *l2, B));
    LinesClassification C;
    if (Status s = classify_two_lines(A.P, A.d, B.P, B.d, C); s != Status::ok)
      return classify_failure(fn, s, "l1 and l2 intersect: b = 0 in the normal form (45)");
    if (!finite_classification(C)) return overflow(fn, "the normal form");
    put_classification(*out, C);
    return ok();
  });
}

int cyc_classify_line_element(cyc_context* ctx, const cyc_line* l1, const double p2[3],
                              const double w[3], cyc_lines_classification* out,
                              cyc_darboux* implicit) {
  const char* fn = "cyc_classify_line_element";
  return run(ctx, fn, [&] {
    REQUIRE(l1);
    REQUIRE(p2);
    REQUIRE(w);
    REQUIRE(out);
    Line A;
    TRY(read_line(fn, "l1", *l1, A));
    TRY(check_doubles(fn, "p2", p2, 3));
    TRY(check_doubles(fn, "w", w, 3));
    LinesClassification C;
    if (Status s = classify_line_element(A.P, A.d, vec(p2), vec(w), C); s != Status::ok)
      return classify_failure(fn, s, "p2 lies on l1, or w lies in the plane of l1 and p2: no "
                              "normal form (68) of Prop. 8");
    Darboux N, D;
    if (implicit)
      if (Status s = line_element_cyclide(C.nf, N, D); s != Status::ok)
        return fail(int(s), "%s: the implicit equation (70) in the input coordinates "
                    "overflows", fn);
    if (!finite_classification(C)) return overflow(fn, "the normal form");
    put_classification(*out, C);
    if (implicit && !finite_all(D.k, CYC_DARBOUX_COEFFS))
      return overflow(fn, "the implicit equation (70)");
    if (implicit) put_darboux(implicit, D);
    return ok();
  });
}

int cyc_classify_line_two_points(cyc_context* ctx, const cyc_line* l1, const double p2[3],
                                 const double p3[3], cyc_lines_classification* out) {
  const char* fn = "cyc_classify_line_two_points";
  return run(ctx, fn, [&] {
    REQUIRE(l1);
    REQUIRE(p2);
    REQUIRE(p3);
    REQUIRE(out);
    Line A;
    TRY(read_line(fn, "l1", *l1, A));
    TRY(check_doubles(fn, "p2", p2, 3));
    TRY(check_doubles(fn, "p3", p3, 3));
    LinesClassification C;
    if (Status s = classify_line_two_points(A.P, A.d, vec(p2), vec(p3), C); s != Status::ok)
      return classify_failure(fn, s, "l1, p2 and p3 lie in one plane (or p2 on l1): no "
                              "normal form (77) of Prop. 9");
    if (!finite_classification(C)) return overflow(fn, "the normal form");
    put_classification(*out, C);
    return ok();
  });
}

// ------------------------------------------------------------ lines of parabolic cyclides

int cyc_parabolic_lines(cyc_context* ctx, const cyc_darboux* d, cyc_cyclide_lines* out) {
  const char* fn = "cyc_parabolic_lines";
  return run(ctx, fn, [&] {
    REQUIRE(d);
    REQUIRE(out);
    Darboux D;
    TRY(read_darboux(fn, "d", *d, D));
    ParabolicLines A;
    if (Status s = parabolic_lines(D, A); s != Status::ok) return from_core(fn, s);
    cyc_cyclide_lines R;
    std::memset(&R, 0, sizeof R);
    put3(R.normal, A.n);
    R.plane_count = A.plane_count;
    for (int i = 0; i < A.plane_count; ++i) {
      R.plane_t[i] = A.planes[i].t;
      R.plane_kind[i] = int(A.planes[i].kind);
    }
    R.line_count = A.line_count;
    for (int i = 0; i < A.line_count; ++i) {
      put3(R.lines[i].point, A.lines[i].line.P);
      put3(R.lines[i].direction, A.lines[i].line.d);
      R.lines[i].t = A.lines[i].t;
      R.lines[i].multiplicity = A.lines[i].multiplicity;
    }
    R.l0_circles = A.l0_circles ? 1 : 0;
    R.circle_families = A.circle_families();
    R.double_families = A.double_families();
    bool finite = finite_all(R.normal, 3) && finite_all(R.plane_t, CYC_MAX_SECTION_PLANES);
    for (const cyc_cyclide_line& l : R.lines)
      finite = finite && finite_all(l.point, 3) && finite_all(l.direction, 3) &&
               std::isfinite(l.t);
    if (!finite) return overflow(fn, "a line or section plane");
    *out = R;
    return ok();
  });
}

int cyc_pencil_circle(cyc_context* ctx, const cyc_darboux* d, const cyc_line* line,
                      const double plane_normal[3], cyc_circle_or_line* out) {
  const char* fn = "cyc_pencil_circle";
  return run(ctx, fn, [&] {
    REQUIRE(d);
    REQUIRE(line);
    REQUIRE(plane_normal);
    REQUIRE(out);
    Darboux D;
    TRY(read_darboux(fn, "d", *d, D));
    Line L;
    TRY(read_line(fn, "line", *line, L));
    TRY(check_doubles(fn, "plane_normal", plane_normal, 3));
    CircleOrLine C;
    const Status s = pencil_circle(D, L, vec(plane_normal), C);
    if (s == Status::invalid_argument)
      return fail(int(s), "%s: the line must lie on the cyclide and in the plane", fn);
    if (s != Status::ok) return from_core(fn, s);
    if (!C.point.allFinite() || !C.axis.allFinite() || !std::isfinite(C.radius))
      return overflow(fn, "the circle");
    put_circle_or_line(*out, C);
    return ok();
  });
}

int cyc_parabolic_parameterize(cyc_context* ctx, const cyc_darboux* d, int kind, double u0,
                               double u1, cyc_line inputs[3], cyc_surface** out) {
  const char* fn = "cyc_parabolic_parameterize";
  return run(ctx, fn, [&] {
    REQUIRE(d);
    REQUIRE(out);
    if (kind != CYC_SURFACE_PRCS && kind != CYC_SURFACE_PRRS)
      return fail(CYC_E_INVALID_ARGUMENT, "%s: kind = %d is neither CYC_SURFACE_PRCS nor "
                  "CYC_SURFACE_PRRS", fn, kind);
    Darboux D;
    TRY(read_darboux(fn, "d", *d, D));
    TRY(check_domain(fn, u0, u1));
    Surface S;
    PencilInput I;
    const Status s = kind == CYC_SURFACE_PRCS ? parameterize_parabolic_prcs(D, u0, u1, S, &I)
                                              : parameterize_parabolic_prrs(D, u0, u1, S, &I);
    if (s == Status::collinear_points || s == Status::dependent_planes)
      return fail(int(s), "%s: for every choice of lines, two input lines meet (or the %s "
                  "are degenerate) at a u inside [u0, u1] = [%g, %g]: a pencil plane there "
                  "has no circle of the construction; choose a domain that avoids it", fn,
                  kind == CYC_SURFACE_PRCS ? "PRCS planes" : "PRRS points", u0, u1);
    if (s != Status::ok) return from_core(fn, s);
    cyc_line L[3];
    std::memset(L, 0, sizeof L);
    for (int j = 0; j < I.count; ++j) put_line(L[j], I.curves[j]);
    for (const cyc_line& l : L)
      if (!finite_line(l)) return overflow(fn, "an input line");
    if (Outcome o = emit(fn, ctx, out, S); o.status) return o;
    if (inputs) std::memcpy(inputs, L, sizeof L);
    return ok();
  });
}

int cyc_prrs_lines_analyze(cyc_context* ctx, const cyc_line lines[3],
                           cyc_prrs_lines_analysis* out) {
  const char* fn = "cyc_prrs_lines_analyze";
  return run(ctx, fn, [&] {
    REQUIRE(lines);
    REQUIRE(out);
    Line L[3];
    TRY(read_lines(fn, lines, L));
    PrrsLinesAnalysis A;
    if (Status s = prrs_lines_analysis(L, A); s != Status::ok) {
      if (s == Status::invalid_argument && L[0].d.squaredNorm() > 0 &&
          L[1].d.squaredNorm() > 0 && L[2].d.squaredNorm() > 0)
        return fail(int(s), "%s: the three lines lie in one plane: no normal form (52)", fn);
      return three_lines_failure(fn, s, L, "the PRRS of three lines (§8)");
    }
    cyc_prrs_lines_analysis R;
    std::memset(&R, 0, sizeof R);
    R.coplanar_pair = A.coplanar_pair;
    R.common_parameter = A.common_parameter;
    R.a2 = A.a2;
    R.b2 = A.b2;
    R.a3 = A.a3;
    R.b3 = A.b3;
    R.x3 = A.x3;
    R.y3 = A.y3;
    R.cond55 = A.cond55;
    R.cond56 = A.cond56;
    R.pencil = A.pencil;
    R.cyclide = A.cyclide;
    R.mu = A.mu;
    if (A.pencil) put_line(R.l4, A.l4);
    const double values[] = {R.a2, R.b2, R.a3, R.b3, R.x3, R.y3, R.cond55, R.cond56, R.mu};
    if (!finite_all(values, sizeof values / sizeof *values) || !finite_line(R.l4))
      return overflow(fn, "the normal form (52)");
    *out = R;
    return ok();
  });
}

int cyc_prrs_lines_cyclide(cyc_context* ctx, const cyc_line lines[3], cyc_darboux* out,
                           double* residual) {
  const char* fn = "cyc_prrs_lines_cyclide";
  return run(ctx, fn, [&] {
    REQUIRE(lines);
    REQUIRE(out);
    Line L[3];
    TRY(read_lines(fn, lines, L));
    Darboux D;
    double r = 0;
    const Status s = prrs_lines_cyclide(L, D, &r);
    const bool directions = L[0].d.squaredNorm() > 0 && L[1].d.squaredNorm() > 0 &&
                            L[2].d.squaredNorm() > 0;
    if (s == Status::invalid_argument && directions)
      return fail(int(s), "%s: l1, l2 must meet in one plane at one parameter and (55) hold", fn);
    if (s != Status::ok) return three_lines_failure(fn, s, L, "the PRRS of three lines (§8)");
    if (!finite_all(D.k, CYC_DARBOUX_COEFFS) || std::isnan(r)) return overflow(fn, "the cyclide");
    put_darboux(out, D);
    if (residual) *residual = r;
    return ok();
  });
}
