// The optimizer tier through the C ABI: point inversion on seed 000's
// Example 2 (canal) and Example 5 (ringed). A point pushed off the surface
// along the unit normal by t must come back to its foot at distance |t|.
#include <gtest/gtest.h>

#include <cmath>

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
