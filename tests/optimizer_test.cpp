// The optimizer tier through the C ABI: point inversion on seed 000's
// Example 2 (canal) and Example 5 (ringed). A point pushed off the surface
// along the unit normal by t must come back to its foot at distance |t|.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "cyclide/cyclide.h"

namespace {

struct Fixture {
  cyc_context* ctx = nullptr;
  cyc_curve* c[3] = {nullptr, nullptr, nullptr};
  cyc_surface* s = nullptr;
  ~Fixture() {
    cyc_surface_destroy(ctx, s);
    for (cyc_curve* k : c) cyc_curve_destroy(ctx, k);
    cyc_context_destroy(ctx);
  }
};

void push_off_and_recover(cyc_context* ctx, const cyc_surface* s, double u, double v,
                          double t) {
  double x[3], n[3];
  ASSERT_EQ(cyc_surface_eval(ctx, s, u, v, x, nullptr, nullptr, n), CYC_OK);
  const double X[3] = {x[0] + t * n[0], x[1] + t * n[1], x[2] + t * n[2]};
  double ru, rv, foot[3], dist;
  ASSERT_EQ(cyc_optimize_closest_point(ctx, s, X, &ru, &rv, foot, &dist), CYC_OK)
      << cyc_context_last_error(ctx);
  EXPECT_NEAR(dist, std::abs(t), 1e-9) << u << " " << v;
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(foot[k], x[k], 1e-7);
}

}  // namespace

TEST(Optimizer, IsAvailableWithCeres) { EXPECT_EQ(cyc_optimizer_available(), 1); }

TEST(Optimizer, ClosestPointOnExample2CanalSurface) {
  Fixture f;
  ASSERT_EQ(cyc_context_create(nullptr, &f.ctx), CYC_OK);
  const double O[3] = {0, 0, 0}, X[3] = {1, 0, 0}, P[3] = {0, 0, 1}, W[3] = {2, 1, 0};
  ASSERT_EQ(cyc_curve_create_line(f.ctx, O, X, &f.c[0]), CYC_OK);
  ASSERT_EQ(cyc_curve_create_line(f.ctx, P, W, &f.c[1]), CYC_OK);
  ASSERT_EQ(cyc_prcs_create(f.ctx, f.c[0], f.c[1], nullptr, -0.5, 0.5, &f.s), CYC_OK);
  for (double u : {-0.3, 0.0, 0.2})
    for (double v : {-2.0, 0.5, 3.0})
      for (double t : {-0.02, 0.0, 0.05}) push_off_and_recover(f.ctx, f.s, u, v, t);
}

TEST(Optimizer, ClosestPointOnExample5RingedSurface) {
  Fixture f;
  ASSERT_EQ(cyc_context_create(nullptr, &f.ctx), CYC_OK);
  const double O[3] = {0, 0, 0}, X[3] = {1, 0, 0}, D2[3] = {2, 1, 0}, Q[3] = {1, 1, 1},
               D3[3] = {-1, 2, 0};
  ASSERT_EQ(cyc_curve_create_line(f.ctx, O, X, &f.c[0]), CYC_OK);
  ASSERT_EQ(cyc_curve_create_line(f.ctx, O, D2, &f.c[1]), CYC_OK);
  ASSERT_EQ(cyc_curve_create_line(f.ctx, Q, D3, &f.c[2]), CYC_OK);
  ASSERT_EQ(cyc_prrs_create(f.ctx, f.c[0], f.c[1], f.c[2], nullptr, 0.1, 1, &f.s), CYC_OK);
  for (double u : {0.3, 0.6})
    for (double v : {-1.0, 0.7})
      for (double t : {-0.01, 0.01}) push_off_and_recover(f.ctx, f.s, u, v, t);
}

TEST(Optimizer, ErrorsLeaveOutputsUntouched) {
  Fixture f;
  ASSERT_EQ(cyc_context_create(nullptr, &f.ctx), CYC_OK);
  const double O[3] = {0, 0, 0}, X[3] = {1, 0, 0}, P[3] = {0, 0, 1}, W[3] = {2, 1, 0};
  ASSERT_EQ(cyc_curve_create_line(f.ctx, O, X, &f.c[0]), CYC_OK);
  ASSERT_EQ(cyc_curve_create_line(f.ctx, P, W, &f.c[1]), CYC_OK);
  ASSERT_EQ(cyc_prcs_create(f.ctx, f.c[0], f.c[1], nullptr, -0.5, 0.5, &f.s), CYC_OK);
  const double bad[3] = {NAN, 0, 0};
  double u = 7, v = 7;
  EXPECT_EQ(cyc_optimize_closest_point(f.ctx, f.s, bad, &u, &v, nullptr, nullptr),
            CYC_E_NOT_FINITE);
  EXPECT_EQ(u, 7.0);
  EXPECT_EQ(v, 7.0);
  EXPECT_EQ(cyc_optimize_closest_point(f.ctx, nullptr, O, &u, &v, nullptr, nullptr),
            CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_optimize_closest_point(nullptr, f.s, O, &u, &v, nullptr, nullptr),
            CYC_E_NULL_ARGUMENT);
}

// ------------------------------------------------------------ cyc_optimize_blend

namespace {

cyc_surface* cone(cyc_context* ctx, const double A[3], const double e1[3], const double e2[3],
                  const double e3[3]) {
  cyc_curve* L[3] = {nullptr, nullptr, nullptr};
  for (int k = 0; k < 3; ++k) {
    const double t = 2.0 * std::acos(-1.0) * k / 3 + 0.3;
    double d[3];
    for (int j = 0; j < 3; ++j) d[j] = std::cos(t) * e1[j] + std::sin(t) * e2[j] + e3[j];
    EXPECT_EQ(cyc_curve_create_line(ctx, A, d, &L[k]), CYC_OK);
  }
  cyc_surface* S = nullptr;
  EXPECT_EQ(cyc_prrs_create(ctx, L[0], L[1], L[2], nullptr, 0.5, 1.0, &S), CYC_OK);
  for (cyc_curve* l : L) cyc_curve_destroy(ctx, l);
  return S;
}

struct Fig6 {
  cyc_context* ctx = nullptr;
  cyc_surface *a = nullptr, *b = nullptr;
  cyc_blend_end s{}, e{};
  Fig6() {
    EXPECT_EQ(cyc_context_create(nullptr, &ctx), CYC_OK);
    const double O[3] = {0, 0, 0}, A2[3] = {4, 0, 4}, X[3] = {1, 0, 0}, Y[3] = {0, 1, 0},
                 Z[3] = {0, 0, 1}, MX[3] = {-1, 0, 0};
    a = cone(ctx, O, X, Y, Z);
    b = cone(ctx, A2, Y, Z, MX);
    const double vs[3] = {HUGE_VAL, -0.5, 0.7};
    s.surface = a;
    s.u = 1.0;
    e.surface = b;
    e.u = 1.0;
    for (int j = 0; j < 3; ++j) s.v[j] = e.v[j] = vs[j];
  }
  ~Fig6() {
    cyc_surface_destroy(ctx, a);
    cyc_surface_destroy(ctx, b);
    cyc_context_destroy(ctx);
  }
};

// The optimized ends rebuild the returned blend X bit for bit through
// cyc_blend_ringed (K = 2 on [0, 1]).
void expect_rebuilds(cyc_context* ctx, const cyc_surface* X, const cyc_blend_end& so,
                     const cyc_blend_end& eo) {
  cyc_surface* Y = nullptr;
  ASSERT_EQ(cyc_blend_ringed(ctx, &so, &eo, 2, 0.0, 1.0, &Y), CYC_OK);
  double x[3], y[3];
  EXPECT_EQ(cyc_surface_eval(ctx, X, 0.4, 0.3, x, nullptr, nullptr, nullptr), CYC_OK);
  EXPECT_EQ(cyc_surface_eval(ctx, Y, 0.4, 0.3, y, nullptr, nullptr, nullptr), CYC_OK);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(x[k], y[k]);
  cyc_surface_destroy(ctx, Y);
}

}  // namespace

TEST(Optimizer, BlendDefaultsAndSummary) {
  cyc_blend_objective o;
  cyc_optimize_options p;
  cyc_blend_objective_init(&o);
  cyc_optimize_options_init(&p);
  cyc_blend_objective_init(nullptr);
  cyc_optimize_options_init(nullptr);
  EXPECT_EQ(o.fairness, 1.0);
  EXPECT_EQ(o.quadrature_t, 8);
  EXPECT_EQ(o.targets, nullptr);
  EXPECT_EQ(p.max_iterations, 50);
  EXPECT_EQ(p.lambda_max_ratio, 4.0);

  Fig6 f;
  cyc_surface* X = nullptr;
  cyc_blend_end so, eo;
  cyc_optimize_summary sum;
  ASSERT_EQ(cyc_optimize_blend(f.ctx, CYC_BLEND_RINGED, &f.s, &f.e, 2, 0.0, 1.0, nullptr,
                               nullptr, &X, &so, &eo, &sum),
            CYC_OK)
      << cyc_context_last_error(f.ctx);
  EXPECT_LE(sum.final_cost, sum.initial_cost);
  EXPECT_GT(sum.iterations, 0);
  EXPECT_GE(sum.seconds, 0.0);
  EXPECT_TRUE(sum.termination == CYC_OPTIMIZE_CONVERGED ||
              sum.termination == CYC_OPTIMIZE_ITERATION_LIMIT);
  EXPECT_NEAR(sum.final_cost, sum.fairness + sum.regularity + sum.targets + sum.obstacles,
              1e-12 * (1 + sum.final_cost));
  EXPECT_EQ(so.surface, f.a);
  EXPECT_EQ(eo.surface, f.b);
  EXPECT_GT(so.lambda, 0.0);
  EXPECT_LT(eo.lambda, 0.0);
  // The optimized ends rebuild the same blend through cyc_blend_ringed.
  expect_rebuilds(f.ctx, X, so, eo);
  // The join still holds (continuity report with the new tangent length;
  // free_orders = min(K, 2) = 2 also moved phi'', so compare order 0 only).
  cyc_continuity R;
  ASSERT_EQ(cyc_continuity_report(f.ctx, f.a, 1.0, so.lambda, X, 0.0, 1, nullptr, 16, &R), CYC_OK);
  EXPECT_LE(R.max_gap, 1e-10 * R.point_scale);
  EXPECT_LE(R.max_normal_angle, 1e-8);
  cyc_surface_destroy(f.ctx, X);
}

// Seed 000 §9.1 (i) through the C ABI: circle_parameter_range frees the
// chosen points; the query lists 3 CYC_PARAMETER_CIRCLE_POINT angles per end
// after the jets, the chosen ends carry the moved v[] (v = tan(theta / 2))
// and rebuild the returned blend through cyc_blend_ringed; the default
// keeps them; a negative range is CYC_E_INVALID_ARGUMENT.
TEST(Optimizer, FreeCirclePointsThroughTheCApi) {
  Fig6 f;
  cyc_optimize_options p;
  cyc_optimize_options_init(&p);
  EXPECT_EQ(p.circle_parameter_range, 0.0);
  p.circle_parameter_range = 1.0;
  cyc_free_parameter P[10];
  int n = -1;
  ASSERT_EQ(cyc_optimize_blend_parameters(f.ctx, CYC_BLEND_RINGED, &f.s, &f.e, 2, 0.0, 1.0, &p,
                                          P, 10, &n),
            CYC_OK);
  ASSERT_EQ(n, 10);
  for (int i = 4; i < 10; ++i) {
    EXPECT_EQ(P[i].role, CYC_PARAMETER_CIRCLE_POINT);
    EXPECT_EQ(P[i].index, (i - 4) / 3);
    EXPECT_EQ(P[i].order, (i - 4) % 3);
    EXPECT_NEAR(P[i].start, 2 * std::atan(f.s.v[(i - 4) % 3]), 1e-15);
  }
  cyc_surface* X = nullptr;
  cyc_blend_end so, eo;
  cyc_optimize_summary sum, kept;
  ASSERT_EQ(cyc_optimize_blend(f.ctx, CYC_BLEND_RINGED, &f.s, &f.e, 2, 0.0, 1.0, nullptr, &p, &X,
                               &so, &eo, &sum),
            CYC_OK)
      << cyc_context_last_error(f.ctx);
  cyc_surface* X0 = nullptr;
  ASSERT_EQ(cyc_optimize_blend(f.ctx, CYC_BLEND_RINGED, &f.s, &f.e, 2, 0.0, 1.0, nullptr,
                               nullptr, &X0, nullptr, nullptr, &kept),
            CYC_OK);
  EXPECT_LT(sum.final_cost, kept.final_cost);
  int moved = 0;
  for (int j = 0; j < 3; ++j) {
    moved += so.v[j] != f.s.v[j];
    moved += eo.v[j] != f.e.v[j];
    EXPECT_LE(std::abs(std::remainder(2 * std::atan(eo.v[j]) - P[7 + j].start, 4 * std::acos(0.0))),
              P[7 + j].upper - P[7 + j].start + 1e-12);
  }
  EXPECT_GT(moved, 0);
  expect_rebuilds(f.ctx, X, so, eo);
  p.circle_parameter_range = -1.0;
  EXPECT_EQ(cyc_optimize_blend(f.ctx, CYC_BLEND_RINGED, &f.s, &f.e, 2, 0.0, 1.0, nullptr, &p,
                               &X0, nullptr, nullptr, nullptr),
            CYC_E_INVALID_ARGUMENT);
  cyc_surface_destroy(f.ctx, X);
  cyc_surface_destroy(f.ctx, X0);
}

// Issue 4's common description through the C ABI: the size query, the
// boxes around the start, BUFFER_TOO_SMALL with nothing written, and the
// optimized jets inside their boxes; the bump's w and tau likewise.
TEST(Optimizer, FreeParametersThroughTheCApi) {
  Fig6 f;
  int count = -1;
  ASSERT_EQ(cyc_optimize_blend_parameters(f.ctx, CYC_BLEND_RINGED, &f.s, &f.e, 2, 0.0, 1.0,
                                          nullptr, nullptr, 0, &count),
            CYC_OK);
  ASSERT_EQ(count, 4);
  cyc_free_parameter P[4], Q[4];
  std::memset(Q, 0x5a, sizeof Q);
  std::memcpy(P, Q, sizeof P);
  int n = -1;
  EXPECT_EQ(cyc_optimize_blend_parameters(f.ctx, CYC_BLEND_RINGED, &f.s, &f.e, 2, 0.0, 1.0,
                                          nullptr, P, 3, &n),
            CYC_E_BUFFER_TOO_SMALL);
  EXPECT_EQ(n, -1);
  EXPECT_EQ(std::memcmp(P, Q, sizeof P), 0);
  EXPECT_EQ(cyc_optimize_blend_parameters(f.ctx, 7, &f.s, &f.e, 2, 0.0, 1.0, nullptr, P, 4, &n),
            CYC_E_INVALID_ARGUMENT);
  ASSERT_EQ(cyc_optimize_blend_parameters(f.ctx, CYC_BLEND_RINGED, &f.s, &f.e, 2, 0.0, 1.0,
                                          nullptr, P, 4, &n),
            CYC_OK);
  ASSERT_EQ(n, 4);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(P[i].role, CYC_PARAMETER_JET);
    EXPECT_EQ(P[i].index, i / 2);
    EXPECT_EQ(P[i].order, i % 2 + 1);
    EXPECT_LE(P[i].lower, P[i].start);
    EXPECT_LE(P[i].start, P[i].upper);
  }
  cyc_surface* X = nullptr;
  cyc_blend_end so, eo;
  ASSERT_EQ(cyc_optimize_blend(f.ctx, CYC_BLEND_RINGED, &f.s, &f.e, 2, 0.0, 1.0, nullptr,
                               nullptr, &X, &so, &eo, nullptr),
            CYC_OK);
  const double chosen[4] = {so.lambda, so.phi[0], eo.lambda, eo.phi[0]};
  for (int i = 0; i < 4; ++i) {
    EXPECT_GE(chosen[i], P[i].lower);
    EXPECT_LE(chosen[i], P[i].upper);
  }
  cyc_surface_destroy(f.ctx, X);
  // The bump: w in [-2L, 2L], tau in [0.2, 0.8].
  cyc_ringed_jet a{}, b{};
  a.n[0] = 1, a.dd[2] = 1, a.rho = 1;
  b.d[2] = 3, b.n[0] = 1, b.n[1] = 1, b.dd[2] = 1, b.rho = 1;
  ASSERT_EQ(cyc_optimize_pcurve_bump_parameters(f.ctx, &a, &b, nullptr, nullptr, nullptr, P, 4,
                                                &n),
            CYC_OK);
  ASSERT_EQ(n, 4);
  for (int j = 0; j < 3; ++j) {
    EXPECT_EQ(P[j].role, CYC_PARAMETER_BUMP_DISPLACEMENT);
    EXPECT_EQ(P[j].index, j);
    EXPECT_DOUBLE_EQ(P[j].upper, 2 * 5.0);  // L = 3 + 1 + 1
  }
  EXPECT_EQ(P[3].role, CYC_PARAMETER_BUMP_POSITION);
  EXPECT_EQ(P[3].lower, 0.2);
  EXPECT_EQ(P[3].upper, 0.8);
  EXPECT_EQ(cyc_optimize_pcurve_bump_parameters(f.ctx, &a, nullptr, nullptr, nullptr, nullptr, P,
                                                4, &n),
            CYC_E_NULL_ARGUMENT);
}

TEST(Optimizer, BlendErrorsLeaveOutputsUntouched) {
  Fig6 f;
  cyc_surface* const kSent = reinterpret_cast<cyc_surface*>(0x1);
  cyc_surface* X = kSent;
  cyc_blend_end so, eo;
  std::memset(&so, 0x5a, sizeof so);
  const cyc_blend_end so0 = so;
  cyc_optimize_summary sum;
  std::memset(&sum, 0x5a, sizeof sum);
  const cyc_optimize_summary sum0 = sum;
  auto untouched = [&] {
    EXPECT_EQ(X, kSent);
    EXPECT_EQ(std::memcmp(&so, &so0, sizeof so), 0);
    EXPECT_EQ(std::memcmp(&sum, &sum0, sizeof sum), 0);
  };
  EXPECT_EQ(cyc_optimize_blend(f.ctx, 5, &f.s, &f.e, 1, 0, 1, nullptr, nullptr, &X, &so, &eo, &sum),
            CYC_E_INVALID_ARGUMENT);
  untouched();
  EXPECT_EQ(cyc_optimize_blend(f.ctx, CYC_BLEND_RINGED, nullptr, &f.e, 1, 0, 1, nullptr, nullptr,
                               &X, &so, &eo, &sum),
            CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_optimize_blend(f.ctx, CYC_BLEND_RINGED, &f.s, &f.e, 1, 0, 1, nullptr, nullptr,
                               nullptr, &so, &eo, &sum),
            CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_optimize_blend(f.ctx, CYC_BLEND_CANAL, &f.s, &f.e, 1, 0, 1, nullptr, nullptr, &X,
                               &so, &eo, &sum),
            CYC_E_INVALID_ARGUMENT);
  cyc_blend_objective o;
  cyc_blend_objective_init(&o);
  o.obstacle_count = 1;  // NULL array
  EXPECT_EQ(cyc_optimize_blend(f.ctx, CYC_BLEND_RINGED, &f.s, &f.e, 1, 0, 1, &o, nullptr, &X, &so,
                               &eo, &sum),
            CYC_E_NULL_ARGUMENT);
  cyc_blend_objective_init(&o);
  o.fairness = NAN;
  EXPECT_EQ(cyc_optimize_blend(f.ctx, CYC_BLEND_RINGED, &f.s, &f.e, 1, 0, 1, &o, nullptr, &X, &so,
                               &eo, &sum),
            CYC_E_NOT_FINITE);
  cyc_optimize_options p;
  cyc_optimize_options_init(&p);
  p.lambda_min_ratio = 0;
  EXPECT_EQ(cyc_optimize_blend(f.ctx, CYC_BLEND_RINGED, &f.s, &f.e, 1, 0, 1, nullptr, &p, &X, &so,
                               &eo, &sum),
            CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(cyc_optimize_blend(f.ctx, CYC_BLEND_RINGED, &f.s, &f.e, 1, 1, 0, nullptr, nullptr, &X,
                               &so, &eo, &sum),
            CYC_E_BAD_DOMAIN);
  untouched();
  EXPECT_NE(std::string(cyc_context_last_error(f.ctx)), "");
}

// Regression (fuzz_blend regress-optimize-denormal-lambda): a denormal
// lambda scaled by 1/2 for a second start underflowed to 0, which means
// "the default +-1": cyc_optimize_blend returned OK with ends of lambda 0
// and a blend its summary did not describe. No start or bound reaches 0 now.
TEST(Optimizer, RegressionDenormalLambdaNeverBecomesTheDefault) {
  Fig6 f;
  const double tiny = std::numeric_limits<double>::denorm_min();
  f.s.lambda = tiny;
  f.e.lambda = -tiny;
  cyc_optimize_options p;
  cyc_optimize_options_init(&p);
  p.max_iterations = 4;
  for (int kind : {CYC_BLEND_CANAL, CYC_BLEND_RINGED}) {
    cyc_surface *X = nullptr, *Y = nullptr;
    cyc_blend_end so{}, eo{};
    const int plain = kind == CYC_BLEND_CANAL ? cyc_blend_canal(f.ctx, &f.s, &f.e, 2, 0, 1, &Y)
                                              : cyc_blend_ringed(f.ctx, &f.s, &f.e, 2, 0, 1, &Y);
    const int st =
        cyc_optimize_blend(f.ctx, kind, &f.s, &f.e, 2, 0, 1, nullptr, &p, &X, &so, &eo, nullptr);
    if (plain != CYC_OK) {
      EXPECT_EQ(st, plain) << kind;  // canal: a zero tangent for every scaled lambda
    } else {
      ASSERT_EQ(st, CYC_OK) << cyc_context_last_error(f.ctx);
      EXPECT_GT(so.lambda, 0.0);
      EXPECT_LT(eo.lambda, 0.0);
    }
    cyc_surface_destroy(f.ctx, X);
    cyc_surface_destroy(f.ctx, Y);
  }
}

// Regression (fuzz_blend regress-optimize-huge-clearance): huge objective
// numbers overflowed the cost at a valid start blend and were reported as
// CYC_E_DEPENDENT_PLANES (even for a ringed blend). Beyond the input range
// (|x| > 1e100) they are refused as CYC_E_NOT_FINITE naming the field; at
// the range's edge the cost stays finite (or is CYC_E_NUMERICAL_OVERFLOW),
// never a geometric status. Moderate ones still optimize.
TEST(Optimizer, RegressionObjectiveOverflowIsNotDependentPlanes) {
  Fig6 f;
  cyc_blend_objective o;
  cyc_blend_objective_init(&o);
  const cyc_blend_obstacle ball{{0, 0, 0}, 1.0};
  o.obstacles = &ball;
  o.obstacle_count = 1;
  o.quadrature_t = 2;
  o.quadrature_v = 2;
  cyc_optimize_options p;
  cyc_optimize_options_init(&p);
  p.max_iterations = 2;
  for (double clearance : {1e300, 1e100, 0.5}) {
    o.clearance = clearance;
    cyc_surface* X = nullptr;
    const int st = cyc_optimize_blend(f.ctx, CYC_BLEND_RINGED, &f.s, &f.e, 1, 0, 1, &o, &p, &X,
                                      nullptr, nullptr, nullptr);
    if (clearance > 1e100) {
      EXPECT_EQ(st, CYC_E_NOT_FINITE);
      EXPECT_NE(std::strstr(cyc_context_last_error(f.ctx), "objective.clearance"), nullptr)
          << cyc_context_last_error(f.ctx);
    } else if (clearance > 1) {
      EXPECT_TRUE(st == CYC_OK || st == CYC_E_NUMERICAL_OVERFLOW) << st;
    } else {
      EXPECT_EQ(st, CYC_OK) << clearance;
    }
    cyc_surface_destroy(f.ctx, X);
  }
  o.clearance = 0;
  o.fairness = std::numeric_limits<double>::max();
  cyc_surface* X = reinterpret_cast<cyc_surface*>(&o);  // untouched on error
  EXPECT_EQ(cyc_optimize_blend(f.ctx, CYC_BLEND_RINGED, &f.s, &f.e, 1, 0, 1, &o, &p, &X, nullptr,
                               nullptr, nullptr),
            CYC_E_NOT_FINITE);
  EXPECT_NE(std::strstr(cyc_context_last_error(f.ctx), "objective.fairness"), nullptr);
  EXPECT_EQ(X, reinterpret_cast<cyc_surface*>(&o));
}

// Seed 001 §5.a through the C ABI: Example 4.1's blend made "more normal"
// by a bump chosen by Ceres; the summary's terms sum to the cost, the
// chosen bump rebuilds the same blend bit for bit, errors write nothing.
TEST(Optimizer, PCurveBumpMoreNormalThroughTheCApi) {
  Fixture c;
  ASSERT_EQ(cyc_context_create(nullptr, &c.ctx), CYC_OK);
  cyc_ringed_jet a{}, b{};
  const double d0[3] = {-4, -3, 1}, dd0[3] = {2, 4, 3}, n0[3] = {1, 1, 1}, dn[3] = {0, 1, 1};
  const double dd1[3] = {3, 1, 1}, n1[3] = {4, 0, 0};
  std::memcpy(a.d, d0, sizeof d0);
  std::memcpy(a.dd, dd0, sizeof dd0);
  std::memcpy(a.n, n0, sizeof n0);
  std::memcpy(a.dn, dn, sizeof dn);
  a.rho = 1.25;
  a.drho = 0.5;
  std::memcpy(b.dd, dd1, sizeof dd1);
  std::memcpy(b.n, n1, sizeof n1);
  std::memcpy(b.dn, dn, sizeof dn);
  b.rho = 2;
  b.drho = 1;
  cyc_surface* pieces[2] = {nullptr, nullptr};
  int count = -7;
  cyc_directrix_bump chosen;
  chosen.tau = -7;
  cyc_optimize_summary sum;
  sum.iterations = -7;
  cyc_bump_objective o;
  cyc_bump_objective_init(&o);
  EXPECT_EQ(o.deviance, 1.0);
  EXPECT_EQ(o.nodes, 64);
  o.nodes = 1;
  EXPECT_EQ(cyc_optimize_pcurve_bump(c.ctx, &a, &b, nullptr, nullptr, &o, nullptr, pieces, &count,
                                     &chosen, &sum),
            CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(cyc_optimize_pcurve_bump(c.ctx, &a, nullptr, nullptr, nullptr, nullptr, nullptr,
                                     pieces, &count, &chosen, &sum),
            CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(count, -7);
  EXPECT_EQ(chosen.tau, -7);
  EXPECT_EQ(sum.iterations, -7);
  EXPECT_EQ(pieces[0], nullptr);
  ASSERT_EQ(cyc_optimize_pcurve_bump(c.ctx, &a, &b, nullptr, nullptr, nullptr, nullptr, pieces,
                                     &count, &chosen, &sum),
            CYC_OK);
  ASSERT_EQ(count, 1);
  EXPECT_LT(sum.final_cost, sum.initial_cost);
  EXPECT_NEAR(sum.fairness + sum.obstacles, sum.final_cost, 1e-15);
  EXPECT_GE(chosen.tau, 0.2);
  EXPECT_LE(chosen.tau, 0.8);
  double dev = 0;
  ASSERT_EQ(cyc_surface_normal_deviance(c.ctx, pieces[0], &dev), CYC_OK);
  EXPECT_NEAR(dev, 2 * sum.final_cost, 1e-3);
  cyc_surface* again[2] = {nullptr, nullptr};
  int n2 = 0;
  ASSERT_EQ(cyc_blend_ringed_pcurve_bump(c.ctx, &a, &b, nullptr, &chosen, again, &n2), CYC_OK);
  double x[3], y[3];
  ASSERT_EQ(cyc_surface_eval(c.ctx, pieces[0], 0.4, 0.3, x, nullptr, nullptr, nullptr), CYC_OK);
  ASSERT_EQ(cyc_surface_eval(c.ctx, again[0], 0.4, 0.3, y, nullptr, nullptr, nullptr), CYC_OK);
  EXPECT_EQ(std::memcmp(x, y, sizeof x), 0);
  cyc_surface_destroy(c.ctx, pieces[0]);
  cyc_surface_destroy(c.ctx, again[0]);
}

// Seed 002 Remark 2 through the C ABI: short tangents make kappa r > 1
// (cyc_sphere_skin_create refuses), cyc_optimize_skin_tangents lengthens
// them (directions, cones and spheres kept) until the skin is valid; a
// valid input comes back unchanged; bad options and an unreachable box
// give their statuses and write nothing.
TEST(Optimizer, SkinTangentsThroughTheCApi) {
  cyc_context* ctx = nullptr;
  ASSERT_EQ(cyc_context_create(nullptr, &ctx), CYC_OK);
  const double m0[3] = {0, 0, 0}, p0[3] = {0.3, 0, 0}, t0[3] = {0.9, 0, 0};
  const double ax[3] = {0.8281, 0.4969, 0.2484};  // (1, 0.6, 0.3) normalized
  const double m1[3] = {4, 1, 0.5};
  double p1[3], t1[3];
  for (int k = 0; k < 3; ++k) p1[k] = m1[k] - 0.4 * ax[k], t1[k] = 0.9 * ax[k];
  cyc_skin_end s, e;
  ASSERT_EQ(cyc_skin_end_from_sphere(ctx, m0, 1.0, p0, t0, &s), CYC_OK);
  ASSERT_EQ(cyc_skin_end_from_sphere(ctx, m1, 1.2, p1, t1, &e), CYC_OK);
  cyc_sphere_skin* h = nullptr;
  ASSERT_EQ(cyc_sphere_skin_create(ctx, &s, &e, nullptr, &h), CYC_E_CURVATURE_RADIUS_TOO_LARGE);
  cyc_skin_tangent_options o;
  cyc_skin_tangent_options_init(&o);
  EXPECT_EQ(o.target, 0.9);
  cyc_skin_end so, eo;
  cyc_skin_tangent_summary sum;
  ASSERT_EQ(cyc_optimize_skin_tangents(ctx, &s, &e, nullptr, &o, &so, &eo, &sum), CYC_OK)
      << cyc_context_last_error(ctx);
  EXPECT_GT(sum.iterations, 0);
  EXPECT_GT(std::max(sum.kappa_r_initial[0], sum.kappa_r_initial[1]), 1.0);
  EXPECT_LT(std::max(sum.kappa_r[0], sum.kappa_r[1]), 0.9 * 1.001);
  for (int i = 0; i < 2; ++i) {
    const cyc_skin_end &in = i ? e : s, &out = i ? eo : so;
    double c0[3], c1[3], r0, r1;
    cyc_skin_end_sphere(&in, c0, &r0);
    cyc_skin_end_sphere(&out, c1, &r1);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(c0[k], c1[k], 1e-12);
      EXPECT_NEAR(out.tangent[k], sum.scale[i] * in.tangent[k], 1e-12);
    }
    EXPECT_NEAR(r0, r1, 1e-12);
  }
  ASSERT_EQ(cyc_sphere_skin_create(ctx, &so, &eo, nullptr, &h), CYC_OK);
  cyc_sphere_skin_destroy(ctx, h);
  // Valid input: unchanged, 0 iterations.
  cyc_skin_end so2, eo2;
  ASSERT_EQ(cyc_optimize_skin_tangents(ctx, &so, &eo, nullptr, nullptr, &so2, &eo2, nullptr),
            CYC_OK);
  EXPECT_EQ(std::memcmp(&so2, &so, sizeof so), 0);
  EXPECT_EQ(std::memcmp(&eo2, &eo, sizeof eo), 0);
  // Errors write nothing.
  std::memset(&so2, 0x5a, sizeof so2);
  const cyc_skin_end blank = so2;
  o.target = 1.0;
  EXPECT_EQ(cyc_optimize_skin_tangents(ctx, &s, &e, nullptr, &o, &so2, &eo2, &sum),
            CYC_E_INVALID_ARGUMENT);
  cyc_skin_tangent_options_init(&o);
  o.max_ratio = 1.2;
  EXPECT_EQ(cyc_optimize_skin_tangents(ctx, &s, &e, nullptr, &o, &so2, &eo2, &sum),
            CYC_E_CURVATURE_RADIUS_TOO_LARGE);
  EXPECT_EQ(cyc_optimize_skin_tangents(ctx, &s, nullptr, nullptr, nullptr, &so2, &eo2, &sum),
            CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(std::memcmp(&so2, &blank, sizeof so2), 0);
  cyc_context_destroy(ctx);
}

// Seed 003 §4, Case II through the C ABI: the double cyclide blend of two
// cylinders with offset axes, its family parameter chosen for a wanted
// joint radius; the parameter query; validation; outputs untouched on error.
TEST(Optimizer, CyclideBlendFamilyParameter) {
  cyc_context* ctx = nullptr;
  ASSERT_EQ(cyc_context_create(nullptr, &ctx), CYC_OK);
  cyc_lie_cone R, S;
  const double c0[3] = {0, 0, 0}, n0[3] = {0, 0, 1}, c1[3] = {2, 0, 3}, n1[3] = {0, 0, -1};
  ASSERT_EQ(cyc_cone_from_circle(ctx, c0, n0, 1, 0, 1, &R), CYC_OK);
  ASSERT_EQ(cyc_cone_from_circle(ctx, c1, n1, 1, 0, 1, &S), CYC_OK);
  // The joint radius of the blend at alpha = tan(0.2) on branch -1 is the target.
  cyc_cyclide_blend T;
  ASSERT_EQ(cyc_cyclide_blend_build(ctx, &R, &S, -1, std::tan(0.2), &T), CYC_OK);
  double jc[3], jn[3], jr = 0;
  ASSERT_EQ(cyc_cyclide_blend_circle(ctx, &T, 0, 0, 1.0, jc, jn, &jr), CYC_OK);
  EXPECT_NEAR(std::sqrt(jn[0] * jn[0] + jn[1] * jn[1] + jn[2] * jn[2]), 1.0, 1e-14);
  cyc_cyclide_blend_objective o;
  cyc_cyclide_blend_objective_init(&o);
  EXPECT_EQ(o.fairness, 1.0);
  EXPECT_EQ(o.circles, 16);
  o.fairness = 0;
  o.joint_radius = jr;
  cyc_cyclide_blend_options p;
  cyc_cyclide_blend_options_init(&p);
  EXPECT_EQ(p.samples, 64);
  cyc_cyclide_blend B;
  cyc_optimize_summary sum;
  ASSERT_EQ(cyc_optimize_cyclide_blend(ctx, &R, &S, &o, &p, &B, &sum), CYC_OK)
      << cyc_context_last_error(ctx);
  EXPECT_EQ(B.pieces, 2);
  EXPECT_EQ(B.branch, -1);
  double r = 0;
  ASSERT_EQ(cyc_cyclide_blend_circle(ctx, &B, 0, 0, 1.0, jc, jn, &r), CYC_OK);
  EXPECT_NEAR(r, jr, 1e-6 * jr);
  EXPECT_LE(sum.final_cost, sum.initial_cost);
  EXPECT_LE(sum.final_cost, 1e-12);
  cyc_cyclide_blend_report rep;
  ASSERT_EQ(cyc_cyclide_blend_continuity(ctx, &R, &S, &B, 16, &rep), CYC_OK);
  for (int j = 0; j < 3; ++j) EXPECT_LE(rep.angle[j], 1e-9);
  // The free parameter: one family angle on branch -1.
  int count = -1;
  ASSERT_EQ(cyc_optimize_cyclide_blend_parameters(ctx, &R, &S, &o, &p, nullptr, 0, &count),
            CYC_OK);
  ASSERT_EQ(count, 1);
  cyc_free_parameter fp;
  EXPECT_EQ(cyc_optimize_cyclide_blend_parameters(ctx, &R, &S, &o, &p, &fp, 0, &count),
            CYC_E_BUFFER_TOO_SMALL);
  ASSERT_EQ(cyc_optimize_cyclide_blend_parameters(ctx, &R, &S, &o, &p, &fp, 1, &count), CYC_OK);
  EXPECT_EQ(fp.role, CYC_PARAMETER_FAMILY);
  EXPECT_EQ(fp.index, -1);
  EXPECT_LE(fp.lower, fp.start);
  EXPECT_LE(fp.start, fp.upper);
  // Defaults (NULL objective and options): the fairest blend.
  ASSERT_EQ(cyc_optimize_cyclide_blend(ctx, &R, &S, nullptr, nullptr, &B, nullptr), CYC_OK);
  // Errors leave the outputs alone.
  cyc_cyclide_blend untouched;
  std::memset(&untouched, 0xcd, sizeof untouched);
  cyc_cyclide_blend X = untouched;
  o.circles = 2;
  EXPECT_EQ(cyc_optimize_cyclide_blend(ctx, &R, &S, &o, &p, &X, &sum), CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(std::memcmp(&X, &untouched, sizeof X), 0);
  cyc_cyclide_blend_objective_init(&o);
  o.joint_point_count = 1;  // NULL points
  EXPECT_EQ(cyc_optimize_cyclide_blend(ctx, &R, &S, &o, &p, &X, &sum), CYC_E_NULL_ARGUMENT);
  cyc_cyclide_blend_objective_init(&o);
  p.branch = 1;  // only the folding branch
  EXPECT_EQ(cyc_optimize_cyclide_blend(ctx, &R, &S, &o, &p, &X, &sum), CYC_E_BLEND_FOLDS);
  EXPECT_NE(std::string(cyc_context_last_error(ctx)), "");
  EXPECT_EQ(std::memcmp(&X, &untouched, sizeof X), 0);
  EXPECT_EQ(cyc_optimize_cyclide_blend(ctx, nullptr, &S, &o, &p, &X, &sum), CYC_E_NULL_ARGUMENT);
  cyc_context_destroy(ctx);
}
