// The C entry points of seed 001 §6: n-way blends of ringed surfaces
// through an auxiliary sphere (creation tier: they allocate the handles).
#include <cmath>

#include "capi_internal.hpp"
#include "cyclide/nway.hpp"

using namespace cyclide;
using namespace cyclide::capi;

static_assert(CYC_NWAY_MAX_ENDS == kMaxNwayEnds, "C and core agree on the most ends");
static_assert(CYC_NWAY_CENTER_AUTO == int(NwayCenter::automatic) &&
                  CYC_NWAY_CENTER_ALPHA == int(NwayCenter::alpha) &&
                  CYC_NWAY_CENTER_GIVEN == int(NwayCenter::given),
              "center modes");
static_assert(CYC_NWAY_SIDE_FACING == int(NwaySide::facing) &&
                  CYC_NWAY_SIDE_PRINTED == int(NwaySide::printed),
              "sides");

namespace cyclide::capi {
// The P-curve blend's options and bump, each field checked and named
// (ringed_c.cpp).
Outcome pcurve_blend_inputs(const char* fn, const char* options_name,
                            const cyc_pcurve_blend_options* options,
                            const cyc_directrix_bump* bump, RingedBlendOptions& o);
}  // namespace cyclide::capi

namespace {

void put_report(cyc_nway_report& C, const NwayReport& R) {
  C = cyc_nway_report();
  const NwaySphere& S = R.sphere;
  put3(C.y, S.y);
  put3(C.normal, S.N);
  C.alpha = S.alpha;
  put3(C.s, S.s);
  C.r = S.r;
  C.bound = S.bound;
  C.clear_bound = S.clear_bound;
  for (int i = 0; i < kMaxNwayEnds; ++i) {
    put3(C.n_star[i], S.n_star[i]);
    C.distance[i] = S.distance[i];
    C.theta[i] = S.theta[i];
    C.lambda[i] = S.lambda[i];
    for (int j = 0; j < kMaxNwayEnds; ++j) {
      C.gap[i][j] = S.gap[i][j];
      C.nested[i][j] = S.nested[i][j] ? 1 : 0;
    }
    C.end_jet[i] = c_jet_of(R.end_jet[i]);
    C.sphere_jet[i] = c_jet_of(R.sphere_jet[i]);
    put3(C.v[i], R.v[i]);
  }
  C.min_gap = S.min_gap;
  C.worst_i = S.worst_i;
  C.worst_j = S.worst_j;
  C.failed_end = R.failed_end;
}

Outcome options_of(const char* fn, const cyc_nway_options* c, int n, NwayOptions& o) {
  if (!c) return ok();
  TRY(check_range(fn, "options.center", c->center, CYC_NWAY_CENTER_AUTO, CYC_NWAY_CENTER_GIVEN));
  TRY(check_range(fn, "options.side", c->side, CYC_NWAY_SIDE_FACING, CYC_NWAY_SIDE_PRINTED));
  TRY(check_double(fn, "options.alpha", c->alpha));
  TRY(check_doubles(fn, "options.s", c->s, 3));
  TRY(check_double(fn, "options.r", c->r));
  TRY(check_double(fn, "options.r_fraction", c->r_fraction));
  // (65): r in (0, bound); r = 0 takes r_fraction * bound.
  if (c->r < 0)
    return fail(CYC_E_INVALID_ARGUMENT, "%s: options.r = %.17g is negative", fn, c->r);
  if (c->r == 0 && !(c->r_fraction > 0 && c->r_fraction < 1))
    return fail(CYC_E_INVALID_ARGUMENT, "%s: options.r_fraction = %.17g is not in (0, 1) "
                "(with options.r = 0 the radius is r_fraction times the bound (65))", fn,
                c->r_fraction);
  // lambda[] is read for the n ends unless chosen automatically.
  if (!c->auto_lambda) TRY(check_doubles(fn, "options.lambda", c->lambda, size_t(n)));
  o.center = NwayCenter(c->center);
  o.alpha = c->alpha;
  o.s = vec(c->s);
  o.r = c->r;
  o.r_fraction = c->r_fraction;
  for (int i = 0; i < kMaxNwayEnds; ++i) o.lambda[i] = i < n ? c->lambda[i] : 0.5;
  o.side = NwaySide(c->side);
  o.require_disjoint = c->require_disjoint != 0;
  o.auto_v = c->auto_v != 0;
  o.auto_lambda = c->auto_lambda != 0;
  return pcurve_blend_inputs(fn, "options.blend", &c->blend, nullptr, o.blend);
}

Outcome explain_failure(const char* fn, Status s, const NwayReport& R, const NwayOptions& o,
                        double bad_u) {
  const NwaySphere& S = R.sphere;
  switch (s) {
    case Status::intersecting_circles:
      return fail(int(s), "%s: joining circles c_%d and c_%d (ends %d and %d) meet (angular "
                  "gap %.3g rad)", fn, S.worst_i + 1, S.worst_j + 1, S.worst_i, S.worst_j,
                  S.min_gap);
    case Status::collinear_points:
      return fail(int(s), "%s: the end centers are collinear or coincident (no incentre)", fn);
    case Status::bad_domain:
      if (R.failed_end >= 0)
        return fail(int(s), "%s: end_u[%d] is outside the surface's domain", fn, R.failed_end);
      if (S.n > 0 && !(S.r > 0 && S.r < S.bound))
        return fail(int(s), "%s: the sphere's radius r = %.17g (options.r, or "
                    "options.r_fraction times the bound) is outside (0, %.17g) (65)", fn, S.r,
                    S.bound);
      for (int i = 0; i < kMaxNwayEnds; ++i)
        if (!o.auto_lambda && !(o.lambda[i] > 0 && o.lambda[i] < 1))
          return fail(int(s), "%s: options.lambda[%d] = %.17g is not in (0, 1)", fn, i,
                      o.lambda[i]);
      return fail(int(s), "%s: a joining circle's lambda is outside (0, 1)", fn);
    default:
      break;
  }
  if (R.failed_end >= 0) {
    if (located(s) && std::isfinite(bad_u))
      return fail(int(s), "%s: blend %d: %s (at t = %.17g)", fn, R.failed_end, explain(s), bad_u);
    return fail(int(s), "%s: end %d: %s", fn, R.failed_end, explain(s));
  }
  return from_core(fn, s);
}

}  // namespace

void cyc_nway_options_init(cyc_nway_options* options) {
  if (!options) return;
  const NwayOptions d;
  options->center = int(d.center);
  options->alpha = d.alpha;
  put3(options->s, d.s);
  options->r = d.r;
  options->r_fraction = d.r_fraction;
  for (int i = 0; i < kMaxNwayEnds; ++i) options->lambda[i] = d.lambda[i];
  options->side = int(d.side);
  options->require_disjoint = d.require_disjoint ? 1 : 0;
  options->auto_v = d.auto_v ? 1 : 0;
  cyc_pcurve_blend_options_init(&options->blend);
  options->auto_lambda = d.auto_lambda ? 1 : 0;
}

int cyc_blend_ringed_nway(cyc_context* ctx, const cyc_surface* const* ends, const double* end_u,
                          int n, const cyc_nway_options* options, cyc_surface** blends,
                          int* counts, cyc_nway_report* report) {
  const char* fn = "cyc_blend_ringed_nway";
  return run(ctx, fn, [&] {
    REQUIRE(ends);
    REQUIRE(end_u);
    REQUIRE(blends);
    REQUIRE(counts);
    NwayReport R;
    auto finish = [&](Outcome e) {
      if (report) put_report(*report, R);
      return e;
    };
    // n is compared with its bound before ends and end_u are read.
    if (Outcome e = check_range(fn, "n", n, 3, kMaxNwayEnds); e.status) return finish(e);
    const Surface* S[kMaxNwayEnds] = {};
    for (int i = 0; i < n; ++i) {
      if (!ends[i]) return fail(CYC_E_NULL_ARGUMENT, "%s: ends[%d] is NULL", fn, i);
      S[i] = &ends[i]->surface;
    }
    if (Outcome e = check_doubles(fn, "end_u", end_u, size_t(n)); e.status) return finish(e);
    NwayOptions o;
    if (Outcome e = options_of(fn, options, n, o); e.status) return finish(e);
    // The pieces are large: build them on the heap (this is the creation tier).
    struct Pieces {
      Surface B[kMaxNwayEnds][2];
    };
    cyc_allocator a = ctx->allocator;
    void* mem = a.alloc(a.userdata, sizeof(Pieces), alignof(Pieces));
    if (!mem) return finish(fail(CYC_E_OUT_OF_MEMORY, "%s: allocator returned NULL", fn));
    Pieces* P = new (mem) Pieces();
    auto free_pieces = [&] {
      P->~Pieces();
      a.free(a.userdata, mem);
    };
    int count[kMaxNwayEnds] = {};
    double bad_u = NAN;
    if (Status s = make_ringed_nway_blend(S, end_u, n, o, P->B, count, &R, &bad_u);
        s != Status::ok) {
      free_pieces();
      return finish(explain_failure(fn, s, R, o, bad_u));
    }
    cyc_surface* h[2 * kMaxNwayEnds] = {};
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < count[i]; ++k)
        if (Outcome e = emit(fn, ctx, &h[2 * i + k], P->B[i][k]); e.status) {
          for (cyc_surface* x : h) release(x);
          free_pieces();
          return finish(e);
        }
    free_pieces();
    for (int j = 0; j < 2 * n; ++j) blends[j] = h[j];
    for (int i = 0; i < n; ++i) counts[i] = count[i];
    return finish(ok());
  });
}

int cyc_nway_sphere_create(cyc_context* ctx, const double center[3], double radius,
                           const double axis[3], cyc_surface** out) {
  const char* fn = "cyc_nway_sphere_create";
  return run(ctx, fn, [&] {
    REQUIRE(center);
    REQUIRE(axis);
    REQUIRE(out);
    TRY(check_doubles(fn, "center", center, 3));
    TRY(check_double(fn, "radius", radius));
    TRY(check_doubles(fn, "axis", axis, 3));
    if (!(radius > 0))
      return fail(CYC_E_INVALID_ARGUMENT, "%s: radius = %.17g is not positive", fn, radius);
    Surface S;
    if (Status s = nway_sphere_surface(vec(center), radius, vec(axis), S); s != Status::ok) {
      if (s == Status::invalid_argument)
        return fail(int(s), "%s: axis is zero: the sphere's circles have no axis", fn);
      return from_core(fn, s);
    }
    return emit(fn, ctx, out, S);
  });
}
