// What a hostile host may pass to the export, tessellation and sphere-skin
// entry points (SPEC §8j, §9, §9b.2): every double argument and struct
// field NaN, infinite or beyond 1e100, counts and sizes at INT_MIN, -1, 0,
// INT_MAX and the largest supported value. Each call returns its status
// with a message naming the argument or field and leaves its outputs
// untouched; on CYC_OK every output is finite. C ABI only.
#include <gtest/gtest.h>

#include <climits>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "cyclide/cyclide.h"
#include "hostile.hpp"

namespace {

using namespace hostile;

const int kBadCounts[] = {INT_MIN, -1, 0, INT_MAX};

struct ExportInputs : ::testing::Test {
  cyc_context* ctx = nullptr;
  cyc_curve *l1 = nullptr, *l2 = nullptr;
  cyc_surface* prcs = nullptr;  // seed 000 Example 2, u in [-0.5, 0.5]
  cyc_skin_end s{}, e{};        // the skew spheres of tests/sphere_skin_capi_test.cpp
  cyc_sphere_skin* skin = nullptr;
  void SetUp() override {
    ASSERT_EQ(cyc_context_create(nullptr, &ctx), CYC_OK);
    const double O[3] = {0, 0, 0}, X[3] = {1, 0, 0}, P[3] = {0, 0, 1}, w[3] = {2, 1, 0};
    ASSERT_EQ(cyc_curve_create_line(ctx, O, X, &l1), CYC_OK);
    ASSERT_EQ(cyc_curve_create_line(ctx, P, w, &l2), CYC_OK);
    ASSERT_EQ(cyc_prcs_create(ctx, l1, l2, nullptr, -0.5, 0.5, &prcs), CYC_OK);
    const double m0[3] = {0, 0, 0}, p0[3] = {0.3, 0, 0}, t0[3] = {3, 0, 0};
    ASSERT_EQ(cyc_skin_end_from_sphere(ctx, m0, 1.0, p0, t0, &s), CYC_OK);
    const double n = std::sqrt(1.0 + 0.36 + 0.64), ax[3] = {1 / n, 0.6 / n, 0.8 / n};
    const double m1[3] = {4, 1, 0.5};
    double p1[3], t1[3];
    for (int k = 0; k < 3; ++k) p1[k] = m1[k] - 0.4 * ax[k], t1[k] = 3 * ax[k];
    ASSERT_EQ(cyc_skin_end_from_sphere(ctx, m1, 1.2, p1, t1, &e), CYC_OK);
    ASSERT_EQ(cyc_sphere_skin_create(ctx, &s, &e, nullptr, &skin), CYC_OK);
  }
  void TearDown() override {
    cyc_sphere_skin_destroy(ctx, skin);
    cyc_surface_destroy(ctx, prcs);
    cyc_curve_destroy(ctx, l1);
    cyc_curve_destroy(ctx, l2);
    cyc_context_destroy(ctx);
  }
  std::string message() const { return cyc_context_last_error(ctx); }
  void expect_named(const char* name) {
    EXPECT_NE(message().find(name), std::string::npos) << message();
  }
  void expect_refused(double* field, const char* name, const std::function<int()>& call,
                      const double* values = kBadDoubles, int nvalues = 5) {
    const double keep = *field;
    for (int i = 0; i < nvalues; ++i) {
      *field = values[i];
      EXPECT_EQ(call(), CYC_E_NOT_FINITE) << name << " = " << values[i];
      expect_named(name);
    }
    *field = keep;
  }
};

// Item 5: on a whole-circle export the reciprocal-v patches reach v =
// +-infinity at an end of t; cyc_bezier_export_eval returned uv[1] = -inf
// with CYC_OK at t = 0, -0.0, 1e-308 (and overflowed to +-inf at denormal
// t). Now every (s, t) of [0, 1]^2 gives finite x and uv, |uv[1]| <= 1e100,
// and the point at (u, v) is x.
TEST_F(ExportInputs, WholeCircleEvalIsFiniteEverywhere) {
  const cyc_export_domain D{-0.5, 0.5, 0, 0, 1};
  cyc_bezier_export* ex = nullptr;
  ASSERT_EQ(cyc_bezier_export_create(ctx, prcs, &D, &ex), CYC_OK) << message();
  const double ts[] = {0.0, -0.0, 5e-324, 1e-310, 1e-308, 1e-300, 0.5, 1 - 1e-16, 1.0};
  int reciprocal = 0;
  for (int k = 0; k < cyc_bezier_export_count(ex); ++k) {
    cyc_bezier_patch_info info;
    ASSERT_EQ(cyc_bezier_export_patch(ctx, ex, k, &info, nullptr, 0), CYC_OK);
    reciprocal += info.reciprocal_v;
    for (double sv : {0.0, 0.5, 1.0})
      for (double t : ts) {
        double x[3], uv[2];
        ASSERT_EQ(cyc_bezier_export_eval(ctx, ex, k, sv, t, x, uv), CYC_OK) << message();
        for (double c : x) EXPECT_TRUE(std::isfinite(c));
        EXPECT_TRUE(std::isfinite(uv[0])) << "patch " << k << " t = " << t;
        EXPECT_TRUE(std::isfinite(uv[1])) << "patch " << k << " t = " << t << ": " << uv[1];
        EXPECT_LE(std::abs(uv[1]), 1e100);
        // (u, v) is accepted by the evaluator and gives x.
        double y[3];
        ASSERT_EQ(cyc_surface_eval(ctx, prcs, uv[0], uv[1], y, nullptr, nullptr, nullptr),
                  CYC_OK)
            << message();
        const double size = 1 + std::abs(x[0]) + std::abs(x[1]) + std::abs(x[2]);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(y[c], x[c], 1e-9 * size);
      }
  }
  EXPECT_GT(reciprocal, 0);  // the case of the finding is exercised
  // s and t named.
  double x[3] = {5, 5, 5}, uv[2] = {5, 5};
  for (double bad : kBadDoubles) {
    EXPECT_EQ(cyc_bezier_export_eval(ctx, ex, 0, bad, 0.5, x, uv), CYC_E_NOT_FINITE);
    expect_named("s = ");
    EXPECT_EQ(cyc_bezier_export_eval(ctx, ex, 0, 0.5, bad, x, uv), CYC_E_NOT_FINITE);
    expect_named("t = ");
  }
  EXPECT_EQ(x[0], 5);
  EXPECT_EQ(uv[1], 5);
  cyc_bezier_export_destroy(ex);
}

// Regression (SkinSimilarity.CircleFamilyExportAndTessellationMove): the
// exact export cut the circle only at v = +-1, and PRCS's v moves to s v,
// so at 2^-20 almost the whole circle lay in |v| < 2^-20 and the arc
// bisection ran out of depth (CYC_E_NUMERICAL_OVERFLOW). With the cuts at
// the parameter's own scale the whole circle exports at 2^-20 .. 2^30 and
// its patches lie on the surface.
TEST(ExportRegression, ScaledPrcsWholeCircleExports) {
  cyc_context* ctx = nullptr;
  ASSERT_EQ(cyc_context_create(nullptr, &ctx), CYC_OK);
  for (int k : {-20, -10, 0, 10, 20, 30}) {
    const double s = std::ldexp(1.0, k);
    double O[3] = {-1, -1, -1}, X[3] = {1, -0.3, -0.3}, P[3] = {-1.3, -1.3, 0},
           W[3] = {2, 0.7, -0.3};
    for (int i = 0; i < 3; ++i) O[i] *= s, P[i] *= s, X[i] *= s, W[i] *= s;
    cyc_curve *a = nullptr, *b = nullptr;
    ASSERT_EQ(cyc_curve_create_line(ctx, O, X, &a), CYC_OK);
    ASSERT_EQ(cyc_curve_create_line(ctx, P, W, &b), CYC_OK);
    cyc_surface* S = nullptr;
    ASSERT_EQ(cyc_prcs_create(ctx, a, b, nullptr, -0.5, 0.5, &S), CYC_OK);
    const cyc_export_domain D{-0.5, 0.3, 0, 0, 1};
    cyc_bezier_export* E = nullptr;
    ASSERT_EQ(cyc_bezier_export_create(ctx, S, &D, &E), CYC_OK)
        << "2^" << k << ": " << cyc_context_last_error(ctx);
    for (int p = 0; p < cyc_bezier_export_count(E); ++p) {
      double x[3], uv[2], y[3];
      ASSERT_EQ(cyc_bezier_export_eval(ctx, E, p, 0.5, 0.5, x, uv), CYC_OK);
      ASSERT_EQ(cyc_surface_eval(ctx, S, uv[0], uv[1], y, nullptr, nullptr, nullptr), CYC_OK);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(x[c], y[c], 1e-9 * 4 * s) << k;
    }
    cyc_bezier_export_destroy(E);
    cyc_surface_destroy(ctx, S);
    cyc_curve_destroy(ctx, a);
    cyc_curve_destroy(ctx, b);
  }
  cyc_context_destroy(ctx);
}

// The skin's whole-circle export likewise.
TEST_F(ExportInputs, SkinWholeCircleEvalIsFinite) {
  const cyc_export_domain D{0, 1, 0, 0, 1};
  cyc_bezier_export* ex = nullptr;
  ASSERT_EQ(cyc_sphere_skin_export_create(ctx, skin, &D, nullptr, &ex, nullptr), CYC_OK)
      << message();
  for (int k = 0; k < cyc_bezier_export_count(ex); ++k)
    for (double t : {0.0, -0.0, 5e-324, 1e-308, 1.0}) {
      double x[3], uv[2];
      ASSERT_EQ(cyc_bezier_export_eval(ctx, ex, k, 0.25, t, x, uv), CYC_OK) << message();
      EXPECT_TRUE(std::isfinite(uv[0]) && std::isfinite(uv[1])) << k << " " << t;
      for (double c : x) EXPECT_TRUE(std::isfinite(c));
    }
  cyc_bezier_export_destroy(ex);
}

// Item 4: the workspace size queries are never negative or wrapped: 0
// outside 3..CYC_MAX_CIRCLE_SEGMENTS, positive and increasing inside; the
// planners refuse the same segment counts naming the field.
TEST_F(ExportInputs, WorkspaceSizeQueries) {
  for (int n : {INT_MIN, -1, 0, 1, 2, CYC_MAX_CIRCLE_SEGMENTS + 1, INT_MAX}) {
    EXPECT_EQ(cyc_tessellation_workspace_size(n), 0u) << n;
    EXPECT_EQ(cyc_sphere_skin_tessellation_workspace_size(n), 0u) << n;
  }
  size_t last[2] = {0, 0};
  for (int n : {3, 4, 64, 1024, CYC_MAX_CIRCLE_SEGMENTS}) {
    const size_t w[2] = {cyc_tessellation_workspace_size(n),
                         cyc_sphere_skin_tessellation_workspace_size(n)};
    for (int i = 0; i < 2; ++i) {
      EXPECT_GT(w[i], last[i]) << n;
      EXPECT_LT(w[i], size_t(1) << 32) << n;  // no wrap: a few MiB at most
      last[i] = w[i];
    }
  }
  cyc_tessellation_options o;
  cyc_tessellation_options_default(&o);
  std::vector<double> work(cyc_tessellation_workspace_size(CYC_MAX_CIRCLE_SEGMENTS) / 8 +
                           cyc_sphere_skin_tessellation_workspace_size(CYC_MAX_CIRCLE_SEGMENTS) /
                               8);
  std::vector<double> us(64);
  cyc_tessellation_plan plan;
  poison(plan);
  auto plan_both = [&](int expected, const char* name, int row_cap = 64) {
    EXPECT_EQ(cyc_tessellate_plan(ctx, prcs, &o, us.data(), row_cap, work.data(),
                                  work.size() * 8, &plan),
              expected);
    expect_named(name);
    EXPECT_EQ(cyc_sphere_skin_tessellate_plan(ctx, skin, 0, &o, us.data(), row_cap,
                                              work.data(), work.size() * 8, &plan),
              expected);
    expect_named(name);
    EXPECT_TRUE(poisoned(plan));
  };
  for (int k : kBadCounts) {
    cyc_tessellation_options_default(&o);
    o.max_segments = k;
    plan_both(CYC_E_INVALID_ARGUMENT, "options.max_segments");
    cyc_tessellation_options_default(&o);
    o.min_segments = k;
    plan_both(CYC_E_INVALID_ARGUMENT, "options.min_segments");
    cyc_tessellation_options_default(&o);
    if (k != 0) {
      o.fixed_segments = k;
      plan_both(CYC_E_INVALID_ARGUMENT, "options.fixed_segments");
      cyc_tessellation_options_default(&o);
    }
    o.initial_rows = k;
    plan_both(CYC_E_INVALID_ARGUMENT, "options.initial_rows");
    cyc_tessellation_options_default(&o);
    if (k < 2) plan_both(CYC_E_INVALID_ARGUMENT, "row_cap", k);
  }
  cyc_tessellation_options_default(&o);
  const double ref_values[] = {kNaN, kInf, 1e200};
  double ref[3] = {1, 0, 0};
  o.reference_u1 = ref;
  for (double b : ref_values) {
    ref[1] = b;
    EXPECT_EQ(cyc_tessellate_plan(ctx, prcs, &o, us.data(), 64, work.data(), work.size() * 8,
                                  &plan),
              CYC_E_NOT_FINITE);
    expect_named("options.reference_u1[1]");
  }
  o.reference_u1 = nullptr;
  for (double b : kBadDoubles) {
    o.chordal_tolerance = b;
    plan_both(CYC_E_NOT_FINITE, "options.chordal_tolerance");
  }
  // The largest supported count plans (fixed_segments = the maximum).
  cyc_tessellation_options_default(&o);
  o.fixed_segments = CYC_MAX_CIRCLE_SEGMENTS;
  o.chordal_tolerance = 0.5;
  EXPECT_EQ(cyc_tessellate_plan(ctx, prcs, &o, us.data(), 64, work.data(), work.size() * 8,
                                &plan),
            CYC_OK)
      << message();
  EXPECT_EQ(plan.segments, CYC_MAX_CIRCLE_SEGMENTS);
}

// A plan handed to the evaluators: its sizes at INT_MIN .. INT_MAX and its
// phases named; rows' parameters named us[i] / ts[i].
TEST_F(ExportInputs, TessellationEvalNamesThePlan) {
  std::vector<double> pts(3 * 64 * 8, 7.0);
  const cyc_buffer3 points{pts.data(), pts.size() / 3, 3};
  const cyc_buffer3 none{nullptr, 0, 3};
  double us[2] = {-0.5, 0.5}, ts[2] = {0, 1};
  cyc_tessellation_plan plan{2, 8, 0, 0, 1, 0};
  auto eval_both = [&](int expected, const char* name) {
    EXPECT_EQ(cyc_tessellate_eval(ctx, prcs, &plan, us, points, none, nullptr), expected);
    expect_named(name);
    EXPECT_EQ(cyc_sphere_skin_tessellate_eval(ctx, skin, 0, &plan, ts, points, none, nullptr),
              expected);
    expect_named(name);
    for (double x : pts) ASSERT_EQ(x, 7.0);
  };
  for (int k : kBadCounts) {
    plan.rows = k;
    eval_both(k == INT_MAX ? CYC_E_BUFFER_TOO_SMALL : CYC_E_INVALID_ARGUMENT,
              k == INT_MAX ? "points" : "plan.rows");
    plan.rows = 2;
    plan.segments = k;
    eval_both(CYC_E_INVALID_ARGUMENT, "plan.segments");
    plan.segments = 8;
  }
  for (double b : kBadDoubles) {
    plan.phase1 = b;
    eval_both(CYC_E_NOT_FINITE, "plan.phase1");
    plan.phase1 = 0;
    us[1] = ts[1] = b;
    eval_both(CYC_E_NOT_FINITE, "[1]");
    us[1] = 0.5, ts[1] = 1;
  }
}

// Export domains, mesh grids and the skin export's options, by name.
TEST_F(ExportInputs, ExportAndMeshFieldsNamed) {
  cyc_export_domain D{-0.5, 0.5, -1, 1, 0};
  cyc_bezier_export* ex = nullptr;
  auto create = [&] {
    const int st = cyc_bezier_export_create(ctx, prcs, &D, &ex);
    EXPECT_EQ(ex, nullptr);
    return st;
  };
  expect_refused(&D.u0, "domain.u0", create);
  expect_refused(&D.v1, "domain.v1", create);
  auto create_skin = [&] {
    const int st = cyc_sphere_skin_export_create(ctx, skin, &D, nullptr, &ex, nullptr);
    EXPECT_EQ(ex, nullptr);
    return st;
  };
  D = {0, 1, -1, 1, 0};
  expect_refused(&D.u1, "domain.u1", create_skin);
  expect_refused(&D.v0, "domain.v0", create_skin);
  cyc_skin_export_options so;
  cyc_skin_export_options_default(&so);
  auto create_skin_o = [&] {
    const int st = cyc_sphere_skin_export_create(ctx, skin, &D, &so, &ex, nullptr);
    EXPECT_EQ(ex, nullptr);
    return st;
  };
  expect_refused(&so.tolerance, "options.tolerance", create_skin_o);
  for (int k : kBadCounts) {
    so.degree = k;
    EXPECT_EQ(create_skin_o(), CYC_E_INVALID_ARGUMENT) << k;
    expect_named("options.degree");
  }
  // Mesh grids: sizes by name, points and normals by index.
  std::vector<double> p(3 * 3 * 4, 0.0);
  for (size_t i = 0; i < p.size(); ++i) p[i] = double(i % 7) + double(i / 5);
  cyc_grid_mesh g{p.data(), p.data(), 3, 3, 4, 0, {0, 0, 0, 0}};
  const std::string path = ::testing::TempDir() + "cyclide_hardening_mesh.obj";
  std::remove(path.c_str());
  for (int k : {INT_MIN, -1, 0, 1}) {
    g.rows = k;
    EXPECT_EQ(cyc_mesh_write(ctx, path.c_str(), CYC_MESH_OBJ, &g, 1, nullptr, nullptr),
              CYC_E_INVALID_ARGUMENT);
    expect_named("grids[0].rows");
    g.rows = 3;
  }
  g.cols = INT_MAX;
  g.rows = INT_MAX;
  g.stride = SIZE_MAX / 2;
  EXPECT_EQ(cyc_mesh_write(ctx, path.c_str(), CYC_MESH_OBJ, &g, 1, nullptr, nullptr),
            CYC_E_INVALID_ARGUMENT);
  expect_named("grids[0]");
  g = {p.data(), p.data(), 3, 3, 4, 0, {0, 0, 0, 0}};
  auto write = [&] {
    return cyc_mesh_write(ctx, path.c_str(), CYC_MESH_OBJ, &g, 1, nullptr, nullptr);
  };
  expect_refused(&p[3 * 5 + 1], "grids[0].points[5][1]", write);
  cyc_mesh_write_options mo{-1, nullptr};
  auto write_o = [&] {
    return cyc_mesh_write(ctx, path.c_str(), CYC_MESH_OBJ, &g, 1, &mo, nullptr);
  };
  expect_refused(&mo.weld_tolerance, "options.weld_tolerance", write_o);
  FILE* f = std::fopen(path.c_str(), "r");
  EXPECT_EQ(f, nullptr);  // nothing was written
  if (f) std::fclose(f);
}

// Sphere skins: every field of the ends and options, theta / t and grid
// arrays by name; counts at INT_MIN, -1, INT_MAX.
TEST_F(ExportInputs, SkinFieldsNamed) {
  cyc_sphere_skin* h = nullptr;
  cyc_skin_options so;
  cyc_skin_options_init(&so);
  auto create = [&] {
    const int st = cyc_sphere_skin_create(ctx, &s, &e, &so, &h);
    EXPECT_EQ(h, nullptr);
    return st;
  };
  expect_refused(&s.center[1], "start.center[1]", create);
  expect_refused(&s.radius, "start.radius", create);
  expect_refused(&e.tangent[2], "end.tangent[2]", create);
  expect_refused(&e.inv_c, "end.inv_c", create);
  expect_refused(&so.tolerance, "options.tolerance", create);
  expect_refused(&so.reference[0], "options.reference[0]", create);
  expect_refused(&so.e[2], "options.e[2]", create);
  cyc_skin_end ends[3] = {s, e, s};
  for (int k = 0; k < 3; ++k) ends[2].center[k] = 2 * e.center[k] - s.center[k];
  auto chain = [&] {
    int bad = -7;
    const int st = cyc_sphere_skin_chain_create(ctx, ends, 3, nullptr, &h, &bad);
    EXPECT_EQ(h, nullptr);
    return st;
  };
  expect_refused(&ends[2].radius, "ends[2].radius", chain);
  double x[3] = {7, 7, 7};
  double theta = 0.3, t = 0.5;
  auto eval = [&] { return cyc_sphere_skin_eval(ctx, skin, 0, theta, t, x, nullptr, nullptr, nullptr); };
  expect_refused(&theta, "theta", eval);
  expect_refused(&t, "t = ", eval);
  EXPECT_EQ(x[0], 7);
  double tw = 7;
  auto twist = [&] { return cyc_sphere_skin_twist(ctx, skin, 0, theta, &tw); };
  expect_refused(&theta, "theta", twist);
  EXPECT_EQ(tw, 7);
  double th[2] = {0, 1}, tt[2] = {0, 1}, pts[12];
  auto grid = [&](int nth, int nt) {
    return cyc_sphere_skin_eval_grid(ctx, skin, 0, th, nth, tt, nt, pts, nullptr, nullptr);
  };
  expect_refused(&th[1], "theta[1]", [&] { return grid(2, 2); });
  expect_refused(&tt[1], "t[1]", [&] { return grid(2, 2); });
  for (int k : {INT_MIN, -1}) {
    EXPECT_EQ(grid(k, 2), CYC_E_INVALID_ARGUMENT);
    expect_named("ntheta");
    EXPECT_EQ(grid(2, k), CYC_E_INVALID_ARGUMENT);
    expect_named("nt");
  }
  // From an apex / a sphere: every argument named.
  double c[3] = {0, 0, 0}, tan[3] = {1, 0, 0}, apex[3] = {-2, 0, 0}, r = 1;
  cyc_skin_end out;
  poison(out);
  auto from_apex = [&] { return cyc_skin_end_from_apex(ctx, c, r, tan, apex, &out); };
  ASSERT_EQ(from_apex(), CYC_OK) << message();
  poison(out);
  expect_refused(&c[2], "center[2]", from_apex);
  expect_refused(&r, "radius", from_apex);
  expect_refused(&apex[0], "apex[0]", from_apex);
  EXPECT_TRUE(poisoned(out));
}

}  // namespace
