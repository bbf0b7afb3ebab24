// What a hostile host may pass to the optimizer tier's entry points (SPEC
// §8e, §8h.12, §9b.2): every double argument and struct field NaN, infinite
// or beyond 1e100, and counts at INT_MIN, -1 and INT_MAX. Each call must
// return CYC_E_NOT_FINITE / CYC_E_INVALID_ARGUMENT / CYC_E_DEGREE_TOO_HIGH
// with a message naming the field as the caller wrote it, leave its outputs
// untouched, and on CYC_OK write only finite values. C ABI only.
#include <gtest/gtest.h>

#include <climits>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <string>

#include "cyclide/cyclide.h"
#include "hostile.hpp"

namespace {

using namespace hostile;

const int kBadCounts[] = {INT_MIN, -1, INT_MAX};

// Seed 000 Fig. 6's cones (as tests/optimizer_test.cpp): a PRRS cone of
// three lines through A.
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

struct OptimInputs : ::testing::Test {
  cyc_context* ctx = nullptr;
  cyc_surface *a = nullptr, *b = nullptr;
  cyc_blend_end s{}, e{};
  cyc_ringed_jet ja{}, jb{};
  void SetUp() override {
    ASSERT_EQ(cyc_context_create(nullptr, &ctx), CYC_OK);
    if (!cyc_optimizer_available()) GTEST_SKIP() << "no optimizer tier in this build";
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
    // The bump's ends (tests/optimizer_test.cpp): L = 3 + 1 + 1.
    ja.n[0] = 1, ja.dd[2] = 1, ja.rho = 1;
    jb.d[2] = 3, jb.n[0] = 1, jb.n[1] = 1, jb.dd[2] = 1, jb.rho = 1;
  }
  void TearDown() override {
    cyc_surface_destroy(ctx, a);
    cyc_surface_destroy(ctx, b);
    cyc_context_destroy(ctx);
  }
  std::string message() const { return cyc_context_last_error(ctx); }

  // Every bad value in *field: `call` returns `status` naming `name`.
  void expect_refused(double* field, const char* name, const std::function<int()>& call,
                      int status = CYC_E_NOT_FINITE) {
    const double keep = *field;
    for (double x : kBadDoubles) {
      *field = x;
      EXPECT_EQ(call(), status) << name << " = " << x;
      EXPECT_NE(message().find(name), std::string::npos) << message();
    }
    *field = keep;
  }
};

// Item 5: a.rho = 1e308 (or b.rho, options.w_bound) gave +-inf boxes with
// OK; NaN in a.dd, a.dn, a.drho gave OK; +Inf in a.rho gave
// CYC_E_INVALID_ARGUMENT. Every field of both jets, the blend options, the
// start bump and the bump options is now refused by name, nothing written.
TEST_F(OptimInputs, BumpParametersValidateEveryField) {
  cyc_free_parameter P[4];
  int n = -7;
  cyc_bump_options opt;
  cyc_bump_options_init(&opt);
  cyc_pcurve_blend_options blend;
  cyc_pcurve_blend_options_init(&blend);
  cyc_directrix_bump start{};
  start.tau = 0.5;
  start.kind = CYC_BUMP_SINGLE;
  auto call = [&] {
    poison(P);
    n = -7;
    const int st =
        cyc_optimize_pcurve_bump_parameters(ctx, &ja, &jb, &blend, &start, &opt, P, 4, &n);
    if (st != CYC_OK) {
      EXPECT_TRUE(poisoned(P));
      EXPECT_EQ(n, -7);
    }
    return st;
  };
  ASSERT_EQ(call(), CYC_OK) << message();
  ASSERT_EQ(n, 4);
  struct Field {
    double* p;
    const char* name;
  };
  const Field fields[] = {
      {&ja.d[0], "a.d[0]"},   {&ja.dd[1], "a.dd[1]"}, {&ja.n[2], "a.n[2]"},
      {&ja.dn[0], "a.dn[0]"}, {&ja.rho, "a.rho"},     {&ja.drho, "a.drho"},
      {&jb.d[2], "b.d[2]"},   {&jb.rho, "b.rho"},     {&jb.drho, "b.drho"},
      {&blend.tau, "blend.tau"}, {&blend.v[1], "blend.v[1]"}, {&start.w[2], "start.w[2]"},
      {&start.tau, "start.tau"}, {&opt.w_bound, "options.w_bound"},
      {&opt.tau_min, "options.tau_min"}, {&opt.tau_max, "options.tau_max"},
      {&opt.function_tolerance, "options.function_tolerance"},
      {&opt.gradient_tolerance, "options.gradient_tolerance"},
      {&opt.parameter_tolerance, "options.parameter_tolerance"}};
  for (const Field& f : fields) expect_refused(f.p, f.name, call);
  // Ranges, by name.
  opt.w_bound = 0;
  EXPECT_EQ(call(), CYC_E_INVALID_ARGUMENT);
  EXPECT_NE(message().find("options.w_bound"), std::string::npos) << message();
  opt.w_bound = 2;
  opt.function_tolerance = -1;
  EXPECT_EQ(call(), CYC_E_INVALID_ARGUMENT);
  EXPECT_NE(message().find("options.function_tolerance"), std::string::npos) << message();
  opt.function_tolerance = 1e-10;
  for (int k : kBadCounts) {
    opt.max_iterations = k;
    if (k >= 0) continue;
    EXPECT_EQ(call(), CYC_E_INVALID_ARGUMENT);
    EXPECT_NE(message().find("options.max_iterations"), std::string::npos) << message();
  }
  opt.max_iterations = 50;
  // The largest valid magnitudes give finite boxes (w_bound L <= 1e100 x 5e100).
  ja.rho = 1e100;
  opt.w_bound = 1e100;
  ASSERT_EQ(call(), CYC_OK) << message();
  for (int i = 0; i < n; ++i) {
    EXPECT_TRUE(std::isfinite(P[i].lower) && std::isfinite(P[i].upper) &&
                std::isfinite(P[i].start));
  }
}

// The solve refuses the same fields (before any solve), and its objective's
// fields and counts by name.
TEST_F(OptimInputs, BumpSolveValidatesObjective) {
  cyc_bump_objective obj;
  cyc_bump_objective_init(&obj);
  cyc_blend_obstacle obs[2] = {{{0, 3, 1.5}, 0.5}, {{0, -3, 1.5}, 0.5}};
  obj.obstacles = obs;
  obj.obstacle_count = 2;
  cyc_surface* pieces[2] = {nullptr, nullptr};
  int count = -7;
  auto call = [&] {
    const int st = cyc_optimize_pcurve_bump(ctx, &ja, &jb, nullptr, nullptr, &obj, nullptr,
                                            pieces, &count, nullptr, nullptr);
    if (st != CYC_OK) {
      EXPECT_EQ(pieces[0], nullptr);
      EXPECT_EQ(count, -7);
    }
    return st;
  };
  expect_refused(&ja.rho, "a.rho", call);
  expect_refused(&jb.dn[1], "b.dn[1]", call);
  expect_refused(&obj.deviance, "objective.deviance", call);
  expect_refused(&obj.clearance, "objective.clearance", call);
  expect_refused(&obj.obstacle_weight, "objective.obstacle_weight", call);
  expect_refused(&obs[1].center[2], "objective.obstacles[1].center[2]", call);
  expect_refused(&obs[1].radius, "objective.obstacles[1].radius", call);
  obs[0].radius = -1;
  EXPECT_EQ(call(), CYC_E_INVALID_ARGUMENT);
  EXPECT_NE(message().find("objective.obstacles[0].radius"), std::string::npos) << message();
  obs[0].radius = 0.5;
  for (int k : kBadCounts) {
    obj.obstacle_count = k;
    EXPECT_EQ(call(), CYC_E_INVALID_ARGUMENT) << k;
    EXPECT_NE(message().find("objective.obstacle_count"), std::string::npos) << message();
    obj.nodes = k;
    obj.obstacle_count = 2;
    EXPECT_EQ(call(), CYC_E_INVALID_ARGUMENT) << k;
    EXPECT_NE(message().find("objective.nodes"), std::string::npos) << message();
    obj.nodes = 64;
  }
  obj.obstacles = nullptr;
  EXPECT_EQ(call(), CYC_E_NULL_ARGUMENT);
  EXPECT_NE(message().find("objective.obstacles"), std::string::npos) << message();
}

// Item 5: with K = 2 the blend reads phi[0] only; NaN / Inf in the unused
// phi[1..5] (the phi[3], phi[5]) and in a canal blend's v[2] were
// copied into start_out / end_out with CYC_OK. The chosen ends now carry
// only what the optimizer chose (unused entries 0): every output finite.
TEST_F(OptimInputs, BlendOutputsNeverCopyUnreadInputs) {
  cyc_optimize_options opt;
  cyc_optimize_options_init(&opt);
  opt.max_iterations = 0;  // the start blend: cheap, and the copy path is the same
  for (int m = 1; m < CYC_MAX_BLEND_ORDER - 1; ++m) {
    s.phi[m] = m % 2 ? kNaN : kInf;
    e.phi[m] = m % 2 ? -kInf : kNaN;
  }
  cyc_surface* X = nullptr;
  cyc_blend_end so, eo;
  cyc_optimize_summary sum;
  ASSERT_EQ(cyc_optimize_blend(ctx, CYC_BLEND_RINGED, &s, &e, 2, 0.0, 1.0, nullptr, &opt, &X,
                               &so, &eo, &sum),
            CYC_OK)
      << message();
  for (const cyc_blend_end* r : {&so, &eo}) {
    EXPECT_TRUE(std::isfinite(r->u) && std::isfinite(r->lambda));
    for (int m = 0; m < CYC_MAX_BLEND_ORDER - 1; ++m) {
      EXPECT_TRUE(std::isfinite(r->phi[m])) << "phi[" << m << "] = " << r->phi[m];
      if (m >= 1) {
        EXPECT_EQ(r->phi[m], 0.0);
      }
    }
  }
  EXPECT_EQ(so.surface, s.surface);
  EXPECT_EQ(eo.u, e.u);
  EXPECT_EQ(so.v[0], s.v[0]);  // the generator point (v = infinity) is kept
  for (double c : {sum.initial_cost, sum.final_cost, sum.length_scale, sum.fairness_scale})
    EXPECT_TRUE(std::isfinite(c));
  cyc_surface_destroy(ctx, X);
}

// Every read field of the ends, the interval, the objective and the
// options is refused by name; K and the counts by name at INT_MIN, -1,
// INT_MAX; nothing is written.
TEST_F(OptimInputs, BlendValidatesEveryReadField) {
  cyc_blend_objective obj;
  cyc_blend_objective_init(&obj);
  cyc_optimize_options opt;
  cyc_optimize_options_init(&opt);
  cyc_blend_target tg[2] = {{{2, 0, 2}, 0.5}, {{2, 0.5, 2}, 0.6}};
  cyc_blend_obstacle ob[2] = {{{9, 9, 9}, 1}, {{-9, 9, 9}, 1}};
  obj.targets = tg;
  obj.target_count = 2;
  obj.obstacles = ob;
  obj.obstacle_count = 2;
  double t0 = 0, t1 = 1;
  int K = 2;
  cyc_surface* X = nullptr;
  cyc_blend_end so, eo;
  poison(so);
  poison(eo);
  auto solve = [&] {
    const int st = cyc_optimize_blend(ctx, CYC_BLEND_RINGED, &s, &e, K, t0, t1, &obj, &opt, &X,
                                      &so, &eo, nullptr);
    if (st != CYC_OK) {
      EXPECT_EQ(X, nullptr);
      EXPECT_TRUE(poisoned(so));
      EXPECT_TRUE(poisoned(eo));
    }
    return st;
  };
  cyc_free_parameter P[8];
  int n = -7;
  auto describe = [&] {
    poison(P);
    const int st = cyc_optimize_blend_parameters(ctx, CYC_BLEND_RINGED, &s, &e, K, t0, t1, &opt,
                                                 P, 8, &n);
    if (st != CYC_OK) {
      EXPECT_TRUE(poisoned(P));
      EXPECT_EQ(n, -7);
    }
    return st;
  };
  struct Field {
    double* p;
    const char* name;
  };
  const Field both[] = {{&s.u, "start.u"},
                        {&e.lambda, "end.lambda"},
                        {&s.phi[0], "start.phi[0]"},
                        {&e.v[1], "end.v[1]"},
                        {&t0, "t0"},
                        {&t1, "t1"},
                        {&opt.lambda_min_ratio, "options.lambda_min_ratio"},
                        {&opt.lambda_max_ratio, "options.lambda_max_ratio"},
                        {&opt.higher_bound, "options.higher_bound"},
                        {&opt.circle_parameter_range, "options.circle_parameter_range"},
                        {&opt.function_tolerance, "options.function_tolerance"},
                        {&opt.gradient_tolerance, "options.gradient_tolerance"},
                        {&opt.parameter_tolerance, "options.parameter_tolerance"}};
  for (const Field& f : both) {
    if (f.p == &e.v[1]) {  // +-infinity is the generator, valid
      for (double x : {kNaN, 1e308, -1e101}) {
        const double keep = *f.p;
        *f.p = x;
        EXPECT_EQ(solve(), CYC_E_NOT_FINITE);
        EXPECT_NE(message().find(f.name), std::string::npos) << message();
        EXPECT_EQ(describe(), CYC_E_NOT_FINITE);
        EXPECT_NE(message().find(f.name), std::string::npos) << message();
        *f.p = keep;
      }
      continue;
    }
    expect_refused(f.p, f.name, solve);
    expect_refused(f.p, f.name, describe);
  }
  const Field objective[] = {{&obj.fairness, "objective.fairness"},
                             {&obj.regularity, "objective.regularity"},
                             {&obj.min_determinant, "objective.min_determinant"},
                             {&obj.min_speed, "objective.min_speed"},
                             {&obj.target_weight, "objective.target_weight"},
                             {&obj.clearance, "objective.clearance"},
                             {&obj.obstacle_weight, "objective.obstacle_weight"},
                             {&tg[1].point[2], "objective.targets[1].point[2]"},
                             {&tg[0].t, "objective.targets[0].t"},
                             {&ob[1].center[0], "objective.obstacles[1].center[0]"},
                             {&ob[1].radius, "objective.obstacles[1].radius"}};
  for (const Field& f : objective) expect_refused(f.p, f.name, solve);
  obj.fairness = -1;
  EXPECT_EQ(solve(), CYC_E_INVALID_ARGUMENT);
  EXPECT_NE(message().find("objective.fairness"), std::string::npos) << message();
  obj.fairness = 1;
  for (int k : kBadCounts) {
    K = k;
    EXPECT_EQ(solve(), k > 0 ? CYC_E_DEGREE_TOO_HIGH : CYC_E_INVALID_ARGUMENT) << k;
    EXPECT_NE(message().find("K = "), std::string::npos) << message();
    EXPECT_EQ(describe(), k > 0 ? CYC_E_DEGREE_TOO_HIGH : CYC_E_INVALID_ARGUMENT) << k;
    K = 2;
    obj.target_count = k;
    EXPECT_EQ(solve(), CYC_E_INVALID_ARGUMENT) << k;
    EXPECT_NE(message().find("objective.target_count"), std::string::npos) << message();
    obj.target_count = 2;
    obj.obstacle_count = k;
    EXPECT_EQ(solve(), CYC_E_INVALID_ARGUMENT) << k;
    EXPECT_NE(message().find("objective.obstacle_count"), std::string::npos) << message();
    obj.obstacle_count = 2;
    obj.quadrature_t = k;
    EXPECT_EQ(solve(), CYC_E_INVALID_ARGUMENT) << k;
    EXPECT_NE(message().find("objective.quadrature_t"), std::string::npos) << message();
    obj.quadrature_t = 8;
    opt.free_orders = k;
    EXPECT_EQ(solve(), CYC_E_INVALID_ARGUMENT) << k;
    EXPECT_NE(message().find("options.free_orders"), std::string::npos) << message();
    opt.free_orders = 0;
  }
}

// The Dupin blend optimizer: the cones' vectors and the objective's fields
// and counts by name (checked before the cones are used).
TEST_F(OptimInputs, CyclideBlendValidatesEveryField) {
  cyc_lie_cone r{}, q{};
  cyc_cyclide_blend_objective obj;
  cyc_cyclide_blend_objective_init(&obj);
  cyc_cyclide_blend_options opt;
  cyc_cyclide_blend_options_init(&opt);
  double joint[6] = {0, 0, 0, 1, 1, 1};
  obj.joint_points = joint;
  obj.joint_point_count = 2;
  cyc_cyclide_blend out;
  poison(out);
  auto call = [&] {
    const int st = cyc_optimize_cyclide_blend(ctx, &r, &q, &obj, &opt, &out, nullptr);
    EXPECT_TRUE(poisoned(out));
    return st;
  };
  expect_refused(&r.r0[3], "r.r0[3]", call);
  expect_refused(&q.r_plus[5], "s.r_plus[5]", call);
  expect_refused(&joint[4], "objective.joint_points[4]", call);
  expect_refused(&obj.joint_radius, "objective.joint_radius", call);
  expect_refused(&obj.min_extent, "objective.min_extent", call);
  expect_refused(&opt.gradient_tolerance, "options.gradient_tolerance", call);
  for (int k : kBadCounts) {
    obj.joint_point_count = k;
    EXPECT_EQ(call(), CYC_E_INVALID_ARGUMENT) << k;
    EXPECT_NE(message().find("objective.joint_point_count"), std::string::npos) << message();
    obj.joint_point_count = 2;
    opt.samples = k;
    EXPECT_EQ(call(), CYC_E_INVALID_ARGUMENT) << k;
    EXPECT_NE(message().find("options.samples"), std::string::npos) << message();
    opt.samples = 64;
  }
}

TEST_F(OptimInputs, ClosestPointNamesThePoint) {
  double p[3] = {0, 0, 0}, u = 7, v = 7;
  auto call = [&] { return cyc_optimize_closest_point(ctx, a, p, &u, &v, nullptr, nullptr); };
  expect_refused(&p[2], "point[2]", call);
  EXPECT_EQ(u, 7.0);
  EXPECT_EQ(v, 7.0);
}

}  // namespace
