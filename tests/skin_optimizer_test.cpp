// Seed 002 Remark 2: Ceres picks tangent lengths that make a sphere skin
// valid (labels "optim;sphere_skin"; SPEC.md §8g).

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "optim/skin_optimizer.hpp"

using namespace cyclide;
using namespace cyclide::optim;

namespace {

struct Ends {
  SkinEnd s, e;
};

// Fig. 7's situation: short tangents bend the spine so sharply at the ends
// that kappa r > 1 (the skin folds); the directions are kept.
Ends short_tangents(double scale) {
  Ends E;
  EXPECT_EQ(skin_end_from_sphere({0, 0, 0}, 1.0, {0.3, 0, 0}, Vec3d(3, 0, 0) * scale, E.s),
            Status::ok);
  const Vec3d axis = Vec3d(1.0, 0.6, 0.3).normalized();
  EXPECT_EQ(
      skin_end_from_sphere({4, 1, 0.5}, 1.2, Vec3d(4, 1, 0.5) - 0.4 * axis, 3.0 * scale * axis, E.e),
      Status::ok);
  return E;
}

}  // namespace

TEST(SkinOptimizer, ValidInputIsReturnedAsIs) {
  const Ends E = short_tangents(1.0);
  SphereSkin S;
  ASSERT_EQ(make_sphere_skin(E.s, E.e, SkinOptions{}, S), Status::ok);
  SkinEnd s, e;
  SkinTangentSummary sum;
  ASSERT_EQ(optimize_skin_tangents(E.s, E.e, SkinOptions{}, SkinTangentOptions{}, s, e, sum),
            Status::ok);
  EXPECT_EQ(sum.iterations, 0);
  EXPECT_EQ(s.tangent, E.s.tangent);
  EXPECT_EQ(e.tangent, E.e.tangent);
  EXPECT_LT(sum.kappa_r[0], 1.0);
}

TEST(SkinOptimizer, ShortTangentsAreLengthenedUntilValid) {
  const Ends E = short_tangents(0.3);
  SphereSkin S;
  ASSERT_EQ(make_sphere_skin(E.s, E.e, SkinOptions{}, S), Status::curvature_radius_too_large);
  SkinEnd s, e;
  SkinTangentSummary sum;
  ASSERT_EQ(optimize_skin_tangents(E.s, E.e, SkinOptions{}, SkinTangentOptions{}, s, e, sum),
            Status::ok);
  EXPECT_GT(sum.iterations, 0);
  EXPECT_GT(std::max(sum.kappa_r_initial[0], sum.kappa_r_initial[1]), 1.0);
  for (int i = 0; i < 2; ++i) EXPECT_LE(sum.kappa_r[i], 0.9 * (1 + 1e-3)) << i;
  EXPECT_GT(std::max(sum.scale[0], sum.scale[1]), 1.0);
  // Directions kept, lengths scaled by the reported factors.
  EXPECT_LE((s.tangent - sum.scale[0] * E.s.tangent).norm(), 1e-12 * s.tangent.norm());
  EXPECT_LE((e.tangent - sum.scale[1] * E.e.tangent).norm(), 1e-12 * e.tangent.norm());
  // The cones and spheres stay (the apex x = p + c t with c = 1/inv_c).
  for (int i = 0; i < 2; ++i) {
    const SkinEnd &in = i ? E.e : E.s, &out = i ? e : s;
    const Vec3d x0 = in.center + in.tangent / in.inv_c, x1 = out.center + out.tangent / out.inv_c;
    EXPECT_LE((x0 - x1).norm(), 1e-12 * x0.norm()) << i;
    Vec3d m0, m1;
    double R0, R1;
    skin_end_sphere(in, m0, R0);
    skin_end_sphere(out, m1, R1);
    EXPECT_LE((m0 - m1).norm(), 1e-12) << i;
    EXPECT_NEAR(R0, R1, 1e-12) << i;
  }
  ASSERT_EQ(make_sphere_skin(s, e, SkinOptions{}, S), Status::ok);
  EXPECT_NEAR(S.kappa[0] * s.radius, sum.kappa_r[0], 1e-9);
  // The smallest change: the active end sits near the target (not far
  // inside it).
  EXPECT_GT(std::max(sum.kappa_r[0], sum.kappa_r[1]), 0.85);
}

TEST(SkinOptimizer, Statuses) {
  const Ends E = short_tangents(0.3);
  SkinEnd s, e;
  SkinTangentSummary sum;
  SkinTangentOptions o;
  o.target = 1.0;
  EXPECT_EQ(optimize_skin_tangents(E.s, E.e, SkinOptions{}, o, s, e, sum), Status::invalid_argument);
  o = SkinTangentOptions{};
  o.min_ratio = NAN;
  EXPECT_EQ(optimize_skin_tangents(E.s, E.e, SkinOptions{}, o, s, e, sum), Status::not_finite);
  // The box too small to reach validity.
  o = SkinTangentOptions{};
  o.max_ratio = 1.5;
  EXPECT_EQ(optimize_skin_tangents(E.s, E.e, SkinOptions{}, o, s, e, sum),
            Status::curvature_radius_too_large);
  // Other failures pass through (nested spheres).
  EXPECT_EQ(optimize_skin_tangents(E.s, E.s, SkinOptions{}, SkinTangentOptions{}, s, e, sum),
            Status::nested_spheres);
}

// Random short tangents: the result is a valid skin whose ends satisfy
// kappa r <= target (to the penalty's slack), or curvature_radius_too_large.
RC_GTEST_PROP(SkinOptimizerProperties, ResultIsValidOrRefused, ()) {
  const double scale = *rc::gen::inRange(5, 120) / 100.0;
  const Ends E = short_tangents(scale);
  SkinEnd s, e;
  SkinTangentSummary sum;
  const Status st =
      optimize_skin_tangents(E.s, E.e, SkinOptions{}, SkinTangentOptions{}, s, e, sum);
  if (st != Status::ok) {
    RC_ASSERT(st == Status::curvature_radius_too_large);
    return;
  }
  SphereSkin S;
  RC_ASSERT(make_sphere_skin(s, e, SkinOptions{}, S) == Status::ok);
  RC_ASSERT(S.kappa[0] * s.radius < 1.0);
  RC_ASSERT(S.kappa[1] * e.radius < 1.0);
}
