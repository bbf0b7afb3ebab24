// The C entry points of blends (seed 000 §9): exact u-derivatives, canal
// and ringed blends (creation tier: they allocate the surface handle) and
// the continuity report (SPEC.md "Blends").
#include <climits>
#include <cmath>

#include "capi_internal.hpp"
#include "cyclide/blend.hpp"

using namespace cyclide;
using namespace cyclide::capi;

static_assert(CYC_MAX_BLEND_ORDER == kMaxBlendOrder, "blend order bound");

namespace {

// The samples a continuity report takes along the common circle: a bound
// that no sampling needs to exceed, so a count read from garbage cannot
// start 2^31 evaluations.
constexpr int kMaxContinuitySamples = 1 << 20;

Outcome check_order(const char* fn, int K, int lo) {
  if (K < lo) return fail(CYC_E_INVALID_ARGUMENT, "%s: K = %d is below %d", fn, K, lo);
  if (K > kMaxBlendOrder)
    return fail(CYC_E_DEGREE_TOO_HIGH, "%s: K = %d exceeds CYC_MAX_BLEND_ORDER = %d", fn, K,
                kMaxBlendOrder);
  return ok();
}

// A circle parameter v: f(u, v) is a Mobius map of the projective line, so
// v = +-infinity is the point f = alpha / gamma of the circle and any
// number is valid; only NaN is not.
Outcome check_circle_parameter(const char* fn, const char* name, double v) {
  if (!std::isnan(v)) return ok();
  return fail(CYC_E_NOT_FINITE, "%s: %s = %.17g is NaN", fn, name, v);
}

// The fields of a blend end that a blend of order K reads: u, the circle
// parameters v[0..nv-1], lambda and phi[m - 2] = phi^(m) for m = 2..K
// (named name.u, ...). The unused phi are not read.
Outcome check_end(const char* fn, const char* name, const cyc_blend_end& e, int K, int nv) {
  char field[64];
  std::snprintf(field, sizeof field, "%s.u", name);
  TRY(check_double(fn, field, e.u));
  for (int j = 0; j < nv; ++j) {
    std::snprintf(field, sizeof field, "%s.v[%d]", name, j);
    TRY(check_circle_parameter(fn, field, e.v[j]));
  }
  std::snprintf(field, sizeof field, "%s.lambda", name);
  TRY(check_double(fn, field, e.lambda));
  std::snprintf(field, sizeof field, "%s.phi", name);
  return check_doubles(fn, field, e.phi, size_t(K > 1 ? K - 1 : 0));
}

// The points v[j] a blend reads: two for the canal blend's curves, three
// for the ringed blend's (seed 000 §9.1, §9.2).
int points_of(int lo) { return lo == 2 ? 2 : 3; }

}  // namespace

BlendEnd capi::end_of(const cyc_blend_end& e) {
  BlendEnd b;
  b.surface = &e.surface->surface;
  b.u = e.u;
  for (int j = 0; j < 3; ++j) b.v[j] = e.v[j];
  b.lambda = e.lambda;
  for (int m = 0; m < kMaxBlendOrder - 1; ++m) b.phi[m] = e.phi[m];
  return b;
}

namespace {

// The matched blends' own reason for degenerate_circle_parameter (piece:
// the spline piece, or -1 for a single blend).
Outcome unmatched(const char* fn, int piece, double bad_u) {
  char where[32] = "";
  if (piece >= 0) std::snprintf(where, sizeof where, "piece %d: ", piece);
  return fail(CYC_E_DEGENERATE_CIRCLE_PARAMETER,
              "%s: %sno Mobius family joins the ends' circle parameterizations (at u = "
              "%.17g): the inputs' v run in opposite senses relative to the blend's circles, "
              "or the interpolated map degenerates there; reparameterize one input by "
              "v -> -v, or use the generator parameterization (cyc_blend_ringed)",
              fn, where, bad_u);
}

template <class Make>
Outcome blend(const char* fn, cyc_context* ctx, const cyc_blend_end* start,
              const cyc_blend_end* end, int K, int lo, double t0, double t1, cyc_surface** out,
              Make&& make, bool matched = false) {
  REQUIRE(start);
  REQUIRE(end);
  REQUIRE(start->surface);
  REQUIRE(end->surface);
  REQUIRE(out);
  TRY(check_order(fn, K, lo));
  TRY(check_end(fn, "start", *start, K, points_of(lo)));
  TRY(check_end(fn, "end", *end, K, points_of(lo)));
  TRY(check_double(fn, "t0", t0));
  TRY(check_double(fn, "t1", t1));
  Surface S;
  double bad_u = t0;
  const Status s = make(end_of(*start), end_of(*end), K, t0, t1, S, &bad_u);
  if (s == Status::bad_domain)
    return fail(int(s), "%s: the blend's interval [t0, t1] = [%.17g, %.17g] is empty or "
                "reversed", fn, t0, t1);
  if (matched && s == Status::degenerate_circle_parameter) return unmatched(fn, -1, bad_u);
  if (s != Status::ok) return located(s) ? from_core_at(fn, s, bad_u) : from_core(fn, s);
  return emit(fn, ctx, out, S);
}

// n-1 handles, built all or nothing by the core's spline blend.
template <class Make>
Outcome blend_spline(const char* fn, cyc_context* ctx, const cyc_blend_end* ends, int n, int K,
                     int lo, const double* knots, cyc_surface** pieces, Make&& make,
                     bool matched = false) {
  REQUIRE(ends);
  REQUIRE(knots);
  REQUIRE(pieces);
  // n is compared with its bound before ends and knots are read.
  TRY(check_range(fn, "n", n, 2, kMaxSplineKnots));
  for (int i = 0; i < n; ++i)
    if (!ends[i].surface) return fail(CYC_E_NULL_ARGUMENT, "%s: ends[%d].surface is NULL", fn, i);
  TRY(check_order(fn, K, lo));
  char name[24];
  for (int i = 0; i < n; ++i) {
    std::snprintf(name, sizeof name, "ends[%d]", i);
    TRY(check_end(fn, name, ends[i], K, points_of(lo)));
  }
  TRY(check_doubles(fn, "knots", knots, size_t(n)));
  BlendEnd be[kMaxSplineKnots];
  for (int i = 0; i < n; ++i) be[i] = end_of(ends[i]);
  cyc_surface* h[kMaxSplineKnots - 1] = {};
  Surface* s[kMaxSplineKnots - 1] = {};
  auto release_all = [&] {
    for (int i = 0; i + 1 < n; ++i) cyc_surface_destroy(ctx, h[i]);
  };
  for (int i = 0; i + 1 < n; ++i) {
    if (emit(fn, ctx, &h[i], Surface()).status) {
      release_all();
      return fail(CYC_E_OUT_OF_MEMORY, "%s: allocator returned NULL", fn);
    }
    s[i] = &h[i]->surface;
  }
  int bad_piece = 0;
  double bad_u = knots[0];
  const Status st = make(be, n, K, knots, s, &bad_piece, &bad_u);
  if (st != Status::ok) {
    release_all();
    if (matched && st == Status::degenerate_circle_parameter)
      return unmatched(fn, bad_piece, bad_u);
    if (st == Status::invalid_argument)
      return fail(int(st), "%s: an interior end has lambda = 0: its direction along its guide "
                  "surface is undefined", fn);
    if (st == Status::bad_domain)
      return fail(int(st), "%s: piece %d: the knots are not increasing (knots[%d] >= "
                  "knots[%d])", fn, bad_piece, bad_piece, bad_piece + 1);
    if (located(st))
      return fail(int(st), "%s: piece %d: %s (at u = %.17g)", fn, bad_piece, explain(st), bad_u);
    return from_core(fn, st);
  }
  for (int i = 0; i + 1 < n; ++i) pieces[i] = h[i];
  return ok();
}

}  // namespace

extern "C" {

int cyc_blend_canal_spline(cyc_context* ctx, const cyc_blend_end* ends, int n, int K,
                           const double* knots, cyc_surface** pieces) {
  const char* fn = "cyc_blend_canal_spline";
  return run(ctx, fn, [&] {
    return blend_spline(fn, ctx, ends, n, K, 2, knots, pieces,
                        [](const BlendEnd* e, int m, int k, const double* t, Surface* const* p,
                           int* bp, double* bu) {
                          return make_canal_blend_spline(e, m, k, t, p, bp, bu);
                        });
  });
}

int cyc_blend_ringed_spline(cyc_context* ctx, const cyc_blend_end* ends, int n, int K,
                            const double* knots, cyc_surface** pieces) {
  const char* fn = "cyc_blend_ringed_spline";
  return run(ctx, fn, [&] {
    return blend_spline(fn, ctx, ends, n, K, 1, knots, pieces,
                        [](const BlendEnd* e, int m, int k, const double* t, Surface* const* p,
                           int* bp, double* bu) {
                          return make_ringed_blend_spline(e, m, k, t, p, bp, bu);
                        });
  });
}

int cyc_blend_ringed_spline_matched(cyc_context* ctx, const cyc_blend_end* ends, int n, int K,
                                    const double* knots, cyc_surface** pieces) {
  const char* fn = "cyc_blend_ringed_spline_matched";
  return run(ctx, fn, [&] {
    return blend_spline(
        fn, ctx, ends, n, K, 1, knots, pieces,
        [](const BlendEnd* e, int m, int k, const double* t, Surface* const* p, int* bp,
           double* bu) {
          return make_ringed_blend_spline(e, m, k, t, p, bp, bu, BlendCircles::matched);
        },
        true);
  });
}

int cyc_surface_derivatives_u(cyc_context* ctx, const cyc_surface* surface, double u,
                              double v, int K, double* out) {
  const char* fn = "cyc_surface_derivatives_u";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    REQUIRE(out);
    TRY(check_order(fn, K, 0));
    TRY(check_double(fn, "u", u));
    TRY(check_circle_parameter(fn, "v", v));
    Vec3d d[kMaxBlendOrder + 1];
    if (Status s = derivatives_u(surface->surface, u, v, K, d); s != Status::ok)
      return from_core_at(fn, s, u);
    for (int l = 0; l <= K; ++l)
      if (!d[l].allFinite())
        return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: d^%d x / du^%d at (u, v) = (%.17g, %.17g) "
                    "is not finite", fn, l, l, u, v);
    for (int l = 0; l <= K; ++l) put3(out + 3 * l, d[l]);
    return ok();
  });
}

int cyc_blend_canal(cyc_context* ctx, const cyc_blend_end* start, const cyc_blend_end* end,
                    int K, double t0, double t1, cyc_surface** out) {
  const char* fn = "cyc_blend_canal";
  return run(ctx, fn, [&] {
    return blend(fn, ctx, start, end, K, 2, t0, t1, out,
                 [](const BlendEnd& a, const BlendEnd& b, int k, double s0, double s1,
                    Surface& S, double* bad) { return make_canal_blend(a, b, k, s0, s1, S, bad); });
  });
}

int cyc_blend_ringed(cyc_context* ctx, const cyc_blend_end* start, const cyc_blend_end* end,
                     int K, double t0, double t1, cyc_surface** out) {
  const char* fn = "cyc_blend_ringed";
  return run(ctx, fn, [&] {
    return blend(fn, ctx, start, end, K, 1, t0, t1, out,
                 [](const BlendEnd& a, const BlendEnd& b, int k, double s0, double s1,
                    Surface& S, double* bad) { return make_ringed_blend(a, b, k, s0, s1, S, bad); });
  });
}

int cyc_blend_ringed_matched(cyc_context* ctx, const cyc_blend_end* start,
                             const cyc_blend_end* end, int K, double t0, double t1,
                             cyc_surface** out) {
  const char* fn = "cyc_blend_ringed_matched";
  return run(ctx, fn, [&] {
    return blend(
        fn, ctx, start, end, K, 1, t0, t1, out,
        [](const BlendEnd& a, const BlendEnd& b, int k, double s0, double s1, Surface& S,
           double* bad) {
          return make_ringed_blend(a, b, k, s0, s1, S, bad, nullptr, BlendCircles::matched);
        },
        true);
  });
}

int cyc_continuity_report(cyc_context* ctx, const cyc_surface* a, double ua, double lambda,
                          const cyc_surface* b, double ub, int K, const double* va, int n,
                          cyc_continuity* out) {
  const char* fn = "cyc_continuity_report";
  return run(ctx, fn, [&] {
    REQUIRE(a);
    REQUIRE(b);
    REQUIRE(out);
    TRY(check_order(fn, K, 0));
    TRY(check_range(fn, "n", n, 1, kMaxContinuitySamples));
    TRY(check_double(fn, "ua", ua));
    TRY(check_double(fn, "lambda", lambda));
    TRY(check_double(fn, "ub", ub));
    if (va)
      for (int i = 0; i < n; ++i)
        if (std::isnan(va[i]))
          return fail(CYC_E_NOT_FINITE, "%s: va[%d] = %.17g is NaN", fn, i, va[i]);
    ContinuityReport R;
    if (Status s = continuity_report(a->surface, ua, lambda, b->surface, ub, K, va, n, R);
        s != Status::ok)
      return from_core(fn, s);
    cyc_continuity C;
    std::memset(&C, 0, sizeof C);
    C.K = R.K;
    C.samples = R.samples;
    C.singular_samples = R.singular_samples;
    C.max_gap = R.max_gap;
    C.point_scale = R.point_scale;
    C.max_normal_angle = R.max_normal_angle;
    for (int l = 0; l <= kMaxBlendOrder; ++l) {
      C.point_jump[l] = R.point_jump[l];
      C.point_scale_l[l] = R.point_scale_l[l];
      C.circle_jump[l] = R.circle_jump[l];
    }
    bool finite = std::isfinite(C.max_gap) && std::isfinite(C.point_scale) &&
                  std::isfinite(C.max_normal_angle);
    for (int l = 0; l <= kMaxBlendOrder; ++l)
      finite = finite && std::isfinite(C.point_jump[l]) && std::isfinite(C.point_scale_l[l]) &&
               std::isfinite(C.circle_jump[l]);
    if (!finite)
      return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: the jumps of the join overflow", fn);
    *out = C;
    return ok();
  });
}

}  // extern "C"
