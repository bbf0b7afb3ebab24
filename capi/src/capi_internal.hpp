// Internals shared by the C ABI's translation units: handle layouts, the
// guard every entry point runs through, messages and buffer checks.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <type_traits>
#include <utility>

#include "cyclide/cyclide.h"
#include "cyclide/blend.hpp"
#include "cyclide/config.hpp"
#include "cyclide/pcurve.hpp"
#include "cyclide/rational_export.hpp"
#include "cyclide/sphere_skin.hpp"
#include "cyclide/surface.hpp"

using cyclide::RationalCurve;
using cyclide::Surface;

// ------------------------------------------------------------ handles

// The caller-memory tier (cyc_context_init_static): a block of the
// caller's memory that handles are carved from, in order; a free gives the
// memory back only for the most recent block (a creator's scratch), others
// stay used until the caller reuses the whole block. Past the block's end
// the fallback allocator serves (none: CYC_E_OUT_OF_MEMORY).
struct CallerArena {
  unsigned char* begin = nullptr;
  unsigned char* next = nullptr;
  unsigned char* end = nullptr;
  unsigned char* last = nullptr;  // the most recent block, or null
  cyc_allocator fallback = {nullptr, nullptr, nullptr};
};

struct cyc_context {
  cyc_allocator allocator;
  cyc_error_handler handler = nullptr;
  void* handler_userdata = nullptr;
  int last_status = CYC_OK;
  char message[CYC_ERROR_MESSAGE_SIZE] = {0};
  bool caller_memory = false;  // in the caller's block (cyc_context_init_static)
  CallerArena arena;           // used when caller_memory
};

struct cyc_curve {
  cyc_allocator allocator;
  RationalCurve curve;
};

struct cyc_surface {
  cyc_allocator allocator;
  Surface surface;
};

// A sphere skin (sphere_skin_c.cpp): the handle owns count patches in one
// array from the context's allocator.
struct cyc_sphere_skin {
  cyc_allocator allocator;
  int count = 0;
  cyclide::SphereSkin* patches = nullptr;
};

// An exact rational Bezier export (export_c.cpp, sphere_skin_c.cpp): a
// header and the patches in one allocation.
struct cyc_bezier_export {
  cyc_allocator allocator;
  int count;
  cyclide::RationalBezierPatch* patches;  // count entries right after the header
};

// One block for an export of count patches (0 < count <=
// CYC_MAX_EXPORT_PATCHES), the patches uninitialized; null if the
// allocator fails. Freed by cyc_bezier_export_destroy.
inline cyc_bezier_export* allocate_export(const cyc_allocator& a, int count) {
  using P = cyclide::RationalBezierPatch;
  const size_t head = (sizeof(cyc_bezier_export) + alignof(P) - 1) / alignof(P) * alignof(P);
  void* mem = a.alloc(a.userdata, head + size_t(count) * sizeof(P), alignof(P));
  if (!mem) return nullptr;
  auto* E = new (mem) cyc_bezier_export;
  E->allocator = a;
  E->count = count;
  E->patches = reinterpret_cast<P*>(static_cast<char*>(mem) + head);
  return E;
}


namespace cyclide {
namespace capi {

// ------------------------------------------------------------ memory

inline void* default_alloc(void*, size_t size, size_t alignment) {
  if (alignment <= alignof(std::max_align_t)) return std::malloc(size);
  const size_t rounded = (size + alignment - 1) / alignment * alignment;
  return std::aligned_alloc(alignment, rounded);
}
inline void default_free(void*, void* p) { std::free(p); }

inline const cyc_allocator kDefaultAllocator = {default_alloc, default_free, nullptr};

template <class H>
H* allocate(const cyc_allocator& a) {
  void* mem = a.alloc(a.userdata, sizeof(H), alignof(H));
  if (!mem) return nullptr;
  H* h = new (mem) H();
  h->allocator = a;
  return h;
}

template <class H>
void release(H* h) {
  if (!h) return;
  const cyc_allocator a = h->allocator;
  h->~H();
  a.free(a.userdata, h);
}

// ------------------------------------------------------------ errors

// The result of an entry point's body: a status and, on error, a message.
struct Outcome {
  int status;
  char text[CYC_ERROR_MESSAGE_SIZE];  // only text up to its NUL is meaningful
};

inline Outcome ok() {
  Outcome o;  // the text buffer is not cleared: success has no message
  o.status = CYC_OK;
  o.text[0] = '\0';
  return o;
}

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
inline Outcome fail(int status, const char* fmt, ...) {
  Outcome o;
  o.status = status;
  va_list ap;
  va_start(ap, fmt);
  std::vsnprintf(o.text, sizeof o.text, fmt, ap);
  va_end(ap);
  return o;
}

// What each core status means, for messages.
inline const char* explain(Status s) {
  switch (s) {
    case Status::ok: return "ok";
    case Status::null_argument: return "a required pointer is NULL";
    case Status::invalid_argument: return "an argument is out of its range";
    case Status::not_finite: return "an input is NaN, infinite or larger than 1e100";
    case Status::degree_too_high: return "a degree exceeds its bound";
    case Status::bad_domain: return "the parameter interval is empty or reversed";
    case Status::dependent_planes:
      return "the planes M, N, B are (nearly) dependent (seed 000 Remark 1: e.g. two "
             "lines of curvature, or parallel normal planes)";
    case Status::zero_tangent:
      return "an input curve has a zero tangent, so its normal plane is undefined "
             "(a constant point is not a PRCS input; use a line element)";
    case Status::collinear_points: return "the three PRRS points are (nearly) collinear";
    case Status::degenerate_circle_parameter:
      return "f(u, .) is not a Mobius map here (alpha delta - beta gamma = 0)";
    case Status::not_canal: return "the surface is not a canal surface by construction";
    case Status::singular_point: return "the normal is undefined here (x_u x x_v = 0)";
    case Status::degenerate_ringed: return "n . c' = 0: the sphere family (3) is undefined";
    case Status::parallel_lines: return "two of the lines are parallel (DCMC needs non-parallel lines)";
    case Status::no_common_normal:
      return "the line directions have no common normal (DCMC needs lines in parallel planes)";
    case Status::rank_deficient:
      return "the linear system has more free parameters than expected (degenerate input)";
    case Status::at_inversion_center:
      return "the point is the inversion center: its image is at infinity";
    case Status::not_parabolic:
      return "the cyclide is not an irreducible parabolic (cubic) Darboux cyclide";
    case Status::empty_real_locus: return "the requested real circle or surface is empty";
    case Status::too_few_lines:
      return "the cyclide lacks the lines Props. 3/5 need (a double line, three skew lines)";
    case Status::no_normal_form:
      return "the input has no normal form of Props. 2/8/9 (lines or points coplanar)";
    case Status::not_pythagorean:
      return "the data admit no P-curve here (a norm is not the square of a polynomial, or "
             "planar Hermite data vanish at an end)";
    case Status::intersecting_circles:
      return "two joining circles on the auxiliary sphere intersect (choose other lambdas)";
    case Status::nested_spheres:
      return "one sphere lies inside (or equals) the other: no skin touches both from outside";
    case Status::curvature_radius_too_large:
      return "the spine's curvature times the circle's radius is >= 1 at an end (seed 002 "
             "Remark 2: a c <= 0, the skin folds; lengthen the end tangents)";
    case Status::sphere_pencil:
      return "the three spheres span only a pencil (dim A = 2): infinitely many spheres touch, no cyclide";
    case Status::no_touching_sphere:
      return "no oriented sphere touches all three (span is R^{1,2}, its complement R^3)";
    case Status::single_touching_sphere:
      return "exactly one oriented sphere touches all three (span is R^{1,1,1}): no one-parameter family";
    case Status::degenerate_cyclide:
      return "every sphere of one family is a point: the cyclide degenerates to a curve";
    case Status::not_isometric:
      return "the two subspaces are not isometric (Gram matrices or signatures differ)";
    case Status::not_on_lie_quadric:
      return "the vector is not neutral (x.x != 0): it represents no Lie sphere";
    case Status::point_at_infinity:
      return "the point lies at infinity (c . n_inf = 0)";
    case Status::tangent_generating_spheres:
      return "the two cones' generating spheres are in oriented contact (r0 . s0 = 0), a case seed 003 omits";
    case Status::blend_folds:
      return "a cyclide patch reaches a glued circle from the wrong side, so the blend folds back (try the other hyperbola branch, another alpha, or the other orientation)";
    case Status::developable:
      return "the plane and its two partials are dependent: the isotropic surface is a curve "
             "here, its Lambda^-1 image a developable with no envelope point (seed 004 Thm. 3.2)";
    case Status::pole_in_gauss_image:
      return "a unit normal equals the projection centre W = (0, 0, 1) (seed 004 §4.2): rotate "
             "the data so that its Gauss image avoids W";
    case Status::ridge:
      return "adjacent cyclide patches share tangent planes along an edge but meet in an edge of "
             "regression (seed 004 Fig. 3)";
    case Status::numerical_overflow:
      return "values leave the supported range (|frame| <= 1e30, |axis| >= 1e-30)";
    case Status::buffer_too_small: return "a buffer is too small";
    case Status::out_of_memory: return "out of memory";
    case Status::io_error: return "a file could not be opened or written";
    case Status::unsupported: return "not supported by this build";
    case Status::internal_error: return "internal error";
  }
  return "unknown status";
}

inline Outcome from_core(const char* fn, Status s) {
  if (s == Status::ok) return ok();
  return fail(int(s), "%s: %s", fn, explain(s));
}

inline Outcome from_core_at(const char* fn, Status s, double u) {
  if (s == Status::ok) return ok();
  return fail(int(s), "%s: %s (at u = %.17g)", fn, explain(s), u);
}

// Statuses by which a construction locates a degeneracy at a parameter
// (the message then names it: from_core_at).
inline bool located(Status s) {
  return s == Status::dependent_planes || s == Status::zero_tangent ||
         s == Status::collinear_points || s == Status::numerical_overflow ||
         s == Status::singular_point || s == Status::degenerate_circle_parameter;
}

// Record success in the context (no message).
inline int succeed(cyc_context* ctx) {
  ctx->last_status = CYC_OK;
  ctx->message[0] = '\0';  // no 1 KiB copy on the hot path
  return CYC_OK;
}

// Record a failure in the context: its status and message.
inline void record(cyc_context* ctx, const Outcome& o) {
  ctx->last_status = o.status;
  std::memcpy(ctx->message, o.text, std::strlen(o.text) + 1);
}

// The one guard every entry point runs through. It is re-entrant: the
// error handler may call the library on the same context; it gets the
// context's message buffer (valid until the next call on the context, as
// the header promises), and when it returns the guard writes the call's own
// status and message back, so the call returns, and the context holds, its
// own status and message whatever the handler's calls did.
template <class Body>
int run(cyc_context* ctx, const char* fn, Body&& body) noexcept {
  if (!ctx) return CYC_E_NULL_ARGUMENT;
  const Outcome o = [&]() noexcept -> Outcome {  // no copy of the 1 KiB text
    try {
      return body();
    } catch (const std::bad_alloc&) {
      return fail(CYC_E_OUT_OF_MEMORY, "%s: out of memory", fn);
    } catch (...) {
      return fail(CYC_E_INTERNAL, "%s: unexpected exception", fn);
    }
  }();
  if (o.status == CYC_OK) return succeed(ctx);
  record(ctx, o);
  if (const cyc_error_handler handler = ctx->handler) {
    handler(o.status, ctx->message, ctx->handler_userdata);
    record(ctx, o);  // the handler's own calls may have replaced it
  }
  return o.status;
}

#define REQUIRE(ptr)                                                    \
  do {                                                                  \
    if (!(ptr)) return fail(CYC_E_NULL_ARGUMENT, "%s: %s is NULL", fn, #ptr); \
  } while (0)

// Return the outcome of a check if it failed.
#define TRY(expr)                                  \
  do {                                             \
    if (Outcome o_ = (expr); o_.status) return o_; \
  } while (0)

// ------------------------------------------------------------ inputs
//
// The one validation path for what a caller passes. Every double input
// (argument, array entry or struct field) is checked here before the core
// sees it: NaN, infinite or beyond the input range |x| <= 1e100
// (kMaxInputMagnitude) is CYC_E_NOT_FINITE with a message naming the
// argument, its index or field and the value. Counts, sizes and degrees are
// compared with their bounds before any arithmetic is done on them, so no
// check can overflow.

// NaN, Inf or beyond the core's input range.
inline bool beyond_input_range(double x) { return !(std::abs(x) <= kMaxInputMagnitude); }

inline const char* what_is_wrong(double x) {
  if (std::isnan(x)) return "is NaN";
  if (std::isinf(x)) return "is infinite";
  return "is beyond the input range |x| <= 1e100";
}

// A double argument or struct field, e.g. check_double(fn, "options.tolerance", t).
inline Outcome check_double(const char* fn, const char* name, double x) {
  if (!beyond_input_range(x)) return ok();
  return fail(CYC_E_NOT_FINITE, "%s: %s = %.17g %s", fn, name, x, what_is_wrong(x));
}

// A length, scale or tolerance that must be positive: check_double, then
// x > 0.
inline Outcome check_positive(const char* fn, const char* name, double x) {
  TRY(check_double(fn, name, x));
  if (!(x > 0)) return fail(CYC_E_INVALID_ARGUMENT, "%s: %s = %.17g is not positive", fn, name, x);
  return ok();
}

// n doubles of an array argument or field, named name[i].
inline Outcome check_doubles(const char* fn, const char* name, const double* x, size_t n) {
  for (size_t i = 0; i < n; ++i)
    if (beyond_input_range(x[i]))
      return fail(CYC_E_NOT_FINITE, "%s: %s[%zu] = %.17g %s", fn, name, i, x[i],
                  what_is_wrong(x[i]));
  return ok();
}

// rows x width doubles at a row stride (in doubles), named name[row][col].
inline Outcome check_rows(const char* fn, const char* name, const double* x, size_t rows,
                          size_t stride, size_t width) {
  for (size_t r = 0; r < rows; ++r)
    for (size_t c = 0; c < width; ++c)
      if (const double v = x[r * stride + c]; beyond_input_range(v))
        return fail(CYC_E_NOT_FINITE, "%s: %s[%zu][%zu] = %.17g %s", fn, name, r, c, v,
                    what_is_wrong(v));
  return ok();
}

// An integer argument or field within [lo, hi] (inclusive). Below lo is
// CYC_E_INVALID_ARGUMENT, above hi the given status (a degree bound:
// CYC_E_DEGREE_TOO_HIGH). Takes 64 bits, so any int or size_t compares
// without wrapping.
inline Outcome check_range(const char* fn, const char* name, long long n, long long lo,
                           long long hi, int above = CYC_E_INVALID_ARGUMENT) {
  if (n < lo) return fail(CYC_E_INVALID_ARGUMENT, "%s: %s = %lld is below %lld", fn, name, n, lo);
  if (n > hi) return fail(above, "%s: %s = %lld exceeds %lld", fn, name, n, hi);
  return ok();
}

// a * b, or false when it does not fit in size_t.
inline bool size_product(size_t a, size_t b, size_t& out) {
  return !__builtin_mul_overflow(a, b, &out);
}

// count rows of width doubles at a row stride of `stride` doubles: the
// array spans (count - 1) stride + width doubles, which must be
// addressable (at most PTRDIFF_MAX bytes), so that no index or pointer
// computed from the stride can overflow.
inline Outcome check_span(const char* fn, const char* name, size_t count, size_t stride,
                          size_t width) {
  if (count == 0) return ok();
  constexpr size_t kMaxDoubles = size_t(PTRDIFF_MAX) / sizeof(double);
  size_t last = 0;
  if (!size_product(count - 1, stride, last) || last > kMaxDoubles - width)
    return fail(CYC_E_INVALID_ARGUMENT,
                "%s: %s: %zu rows at a stride of %zu doubles exceed the address space", fn,
                name, count, stride);
  return ok();
}

inline Vec3d vec(const double* p) { return Vec3d(p[0], p[1], p[2]); }

inline void put3(double* dst, const Vec3d& v) {
  dst[0] = v.x();
  dst[1] = v.y();
  dst[2] = v.z();
}

// The circle parameter f of a creator (NULL: f = v, m untouched).
inline Outcome mobius_from(const char* fn, const cyc_mobius* f, Mobius& m) {
  if (!f) return ok();
  if (Status s = make_mobius(f->degree, f->alpha, f->beta, f->gamma, f->delta, m);
      s != Status::ok)
    return fail(int(s), "%s: circle parameter f: %s", fn, explain(s));
  return ok();
}

// Seed 001's Hermite data of a join.
inline RingedJet jet_of(const cyc_ringed_jet& j) {
  RingedJet J;
  J.d = vec(j.d);
  J.dd = vec(j.dd);
  J.n = vec(j.n);
  J.dn = vec(j.dn);
  J.rho = j.rho;
  J.drho = j.drho;
  return J;
}

// The inverse of jet_of.
inline cyc_ringed_jet c_jet_of(const RingedJet& J) {
  cyc_ringed_jet C;
  put3(C.d, J.d);
  put3(C.dd, J.dd);
  put3(C.n, J.n);
  put3(C.dn, J.dn);
  C.rho = J.rho;
  C.drho = J.drho;
  return C;
}

// The P-curve blend's options and bump (either may be NULL: defaults).
inline Outcome pcurve_blend_options_of(const char* fn, const cyc_pcurve_blend_options* options,
                                       const cyc_directrix_bump* bump, RingedBlendOptions& o) {
  if (options) {
    o.sign = options->sign;
    o.tau = options->tau;
    o.v = vec(options->v);
    if (o.sign != 1 && o.sign != -1)
      return fail(CYC_E_INVALID_ARGUMENT, "%s: sign = %d is not +1 or -1", fn, o.sign);
  }
  if (bump) {
    if (bump->kind != CYC_BUMP_SINGLE && bump->kind != CYC_BUMP_TWO_PIECE)
      return fail(CYC_E_INVALID_ARGUMENT, "%s: unknown bump kind %d", fn, bump->kind);
    o.bump.w = vec(bump->w);
    o.bump.tau = bump->tau;
    o.bump.kind = BumpKind(bump->kind);
  }
  return ok();
}

// Hand a new curve to the caller.
template <class H, class T>
Outcome emit(const char* fn, cyc_context* ctx, H** out, const T& value) {
  H* h = allocate<H>(ctx->allocator);
  if (!h) return fail(CYC_E_OUT_OF_MEMORY, "%s: allocator returned NULL", fn);
  if constexpr (std::is_same_v<H, cyc_curve>)
    h->curve = value;
  else
    h->surface = value;
  *out = h;
  return ok();
}

// Hand n (1 or 2) blend pieces to the caller: all or nothing.
inline Outcome emit_pieces(const char* fn, cyc_context* ctx, const Surface* S, int n,
                           cyc_surface** pieces, int* count) {
  cyc_surface* h[2] = {nullptr, nullptr};
  for (int k = 0; k < n; ++k)
    if (Outcome e = emit(fn, ctx, &h[k], S[k]); e.status) {
      for (int j = 0; j < k; ++j) release(h[j]);
      return e;
    }
  for (int k = 0; k < n; ++k) pieces[k] = h[k];
  *count = n;
  return ok();
}

// The sizes of a grid of parameters: two arrays of nu and nv values (each
// addressable) and nu * nv points (fits in size_t), returned in count.
inline Outcome check_grid_sizes(const char* fn, const char* us, size_t nu, const char* vs,
                                size_t nv, size_t& count) {
  TRY(check_span(fn, us, nu, 1, 1));
  TRY(check_span(fn, vs, nv, 1, 1));
  if (!size_product(nu, nv, count))
    return fail(CYC_E_INVALID_ARGUMENT, "%s: %zu x %zu points (%s x %s) do not fit in size_t",
                fn, nu, nv, us, vs);
  return ok();
}

// A caller buffer for n vectors, or a reason why not.
inline Outcome check_buffer(const char* fn, const char* name, const cyc_buffer3& b, size_t n) {
  if (!b.data) return ok();
  if (b.stride < 3)
    return fail(CYC_E_INVALID_ARGUMENT, "%s: %s.stride = %zu is below 3", fn, name, b.stride);
  if (b.capacity < n)
    return fail(CYC_E_BUFFER_TOO_SMALL, "%s: %s holds %zu vectors, %zu needed", fn, name,
                b.capacity, n);
  return check_span(fn, name, n, b.stride, 3);
}

inline Strided3 strided(const cyc_buffer3& b) {
  Strided3 s;
  s.data = b.data;
  s.stride = b.stride;
  return s;
}

// A C blend end as the core's (blend_c.cpp; also the optimizer's).
BlendEnd end_of(const cyc_blend_end& e);

}  // namespace capi
}  // namespace cyclide


