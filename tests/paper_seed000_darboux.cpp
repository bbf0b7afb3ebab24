// Seed 000 §5–7: Darboux cyclides (31), Mobius inversion, and DCMC,
// on the paper's worked examples (Example 4, Example 2 continued).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cyclide/darboux.hpp"
#include "cyclide/inverted_surface.hpp"
#include "seed000_equations.hpp"

namespace cyclide {
namespace {

Darboux example4(double alpha) { return seed000::eq35(alpha); }  // (35)
Darboux example2() { return seed000::eq39(); }                    // (39)

// Is D (up to a factor fixing phi1 = n.X) a member of the DCMC family?
// Returns the residual of D - base after removing the quadric direction,
// relative to |D|.
double membership_residual(const DcmcFamily& F, Darboux D) {
  // Scale D so that its phi1 equals F's (both are multiples of n.X).
  const double s = F.n.dot(D.l());
  for (double& v : D.k) v /= s;
  double dq = 0, qq = 0;
  for (int i = 0; i < kDarbouxCoeffs; ++i) {
    dq += (D.k[i] - F.base.k[i]) * F.quadric.k[i];
    qq += F.quadric.k[i] * F.quadric.k[i];
  }
  const Darboux M = F.member(dq / qq);
  double r = 0;
  for (int i = 0; i < kDarbouxCoeffs; ++i) r = std::max(r, std::abs(M.k[i] - D.k[i]));
  return r / D.scale();
}

TEST(Darboux, Example4DcmcFamilyContainsEq35ForEveryAlpha) {
  // Eq. (34): l1 = (u,0,0), l2 = (0,u,1), l3 = (u,u,2); n = (0,0,1).
  const Line lines[3] = {{{0, 0, 0}, {1, 0, 0}}, {{0, 0, 1}, {0, 1, 0}}, {{0, 0, 2}, {1, 1, 0}}};
  DcmcFamily F;
  ASSERT_EQ(dcmc(lines, F), Status::ok);
  EXPECT_NEAR(std::abs(F.n.z()), 1.0, 1e-15);
  EXPECT_EQ(darboux_type(F.base), DarbouxType::parabolic);
  // The quadric direction is x z - 2 y z + 2 y (ERRATA: alpha is not canonical).
  for (double alpha : {0.0, 1.0, -3.0, 2.5}) EXPECT_LE(membership_residual(F, example4(alpha)), 1e-12);
  // A cubic with a different quadratic part is not a member.
  Darboux other = example4(0);
  other.k[kQxx] = 1;
  EXPECT_GT(membership_residual(F, other), 1e-3);
}

TEST(Darboux, Example4SectionsFactorAsEqs36To38) {
  for (double alpha : {0.0, 0.7, -2.0})
    for (double x : {-1.3, 0.0, 0.4, 2.0})
      for (double y : {-0.6, 0.25, 1.5}) {
        const Darboux C = example4(alpha);
        EXPECT_NEAR(C.value({x, y, 0}), -y * (3 * x + y - 2 * alpha), 1e-12);       // (36)
        EXPECT_NEAR(C.value({x, y, 1}), x * (x - 3 * y + alpha), 1e-12);            // (37)
        EXPECT_NEAR(C.value({x, y, 2}), (x - y) * (2 * x - y + 2 * alpha), 1e-12);  // (38)
      }
}

TEST(Darboux, Example4SixLinesLieOnEveryMember) {
  const Line lines[3] = {{{0, 0, 0}, {1, 0, 0}}, {{0, 0, 1}, {0, 1, 0}}, {{0, 0, 2}, {1, 1, 0}}};
  DcmcFamily F;
  ASSERT_EQ(dcmc(lines, F), Status::ok);
  for (double alpha : {0.0, 1.5}) {
    const Darboux C = example4(alpha);
    // The given lines and the additional ones from (36)-(38).
    const Line six[6] = {lines[0], lines[1], lines[2],
                         {{0, 2 * alpha, 0}, {1, -3, 0}},
                         {{-alpha, 0, 1}, {3, 1, 0}},
                         {{0, 2 * alpha, 2}, {1, 2, 0}}};
    for (const Line& L : six)
      for (double t : {-2.0, 0.3, 5.0}) EXPECT_NEAR(C.value(L.P + t * L.d), 0.0, 1e-11);
  }
  // Every member of the computed family contains the three given lines.
  for (double beta : {-10.0, 0.0, 3.0})
    for (const Line& L : lines)
      for (double t : {-2.0, 0.3, 5.0}) EXPECT_NEAR(F.member(beta).value(L.P + t * L.d), 0.0, 1e-11);
}

TEST(Darboux, Example2ContinuedLinesLieOnEq39) {
  const Darboux C = example2();
  EXPECT_EQ(darboux_type(C), DarbouxType::parabolic);
  // l1, l2 (21), l3 (41) with lambda = 5/4 (42), and the lines (43).
  const Line lines[5] = {{{0, 0, 0}, {1, 0, 0}},
                         {{0, 0, 1}, {2, 1, 0}},
                         {{0, 0, -0.25}, {0.75, -0.25, 0}},
                         {{0, 0, 0}, {1, -0.75, 0}},
                         {{0, 0, 1}, {1, -2, 0}}};
  for (const Line& L : lines)
    for (double t : {-3.0, 0.5, 2.0}) EXPECT_NEAR(C.value(L.P + t * L.d), 0.0, 1e-12);
  // (41)-(42): l3 = lambda l1 + (1 - lambda) l2 with lambda = w.w / (w.w - 1).
  const Vec3d w(2, 1, 0);
  const double lambda = w.squaredNorm() / (w.squaredNorm() - 1);
  EXPECT_DOUBLE_EQ(lambda, 1.25);
  for (double u : {-1.0, 2.0}) {
    const Vec3d l3 = lambda * Vec3d(u, 0, 0) + (1 - lambda) * Vec3d(2 * u, u, 1);
    EXPECT_LE((l3 - 0.25 * Vec3d(3 * u, -u, -1)).norm(), 1e-15);
  }
  // §7: DCMC on l1, l2, l3 gives a family containing the PRCS surface (39).
  const Line three[3] = {lines[0], lines[1], lines[2]};
  DcmcFamily F;
  ASSERT_EQ(dcmc(three, F), Status::ok);
  EXPECT_LE(membership_residual(F, C), 1e-12);
}

TEST(Darboux, TypesIncludingReducibleCases) {
  Darboux sphere;  // x^2 + y^2 + z^2 - 1
  sphere.k[kQxx] = sphere.k[kQyy] = sphere.k[kQzz] = 1;
  sphere.k[kC] = -1;
  EXPECT_EQ(darboux_type(sphere), DarbouxType::quadric);
  Darboux pair;  // x y = 0
  pair.k[kQxy] = 1;
  EXPECT_EQ(darboux_type(pair), DarbouxType::reducible);
  Darboux plane_sphere;  // (z + 2)(X.X + x - 1) = z X.X + z x - z + 2 X.X + 2 x - 2
  plane_sphere.k[kLz] = 1;
  plane_sphere.k[kQxz] = 1;
  plane_sphere.k[kBz] = -1;
  plane_sphere.k[kQxx] = plane_sphere.k[kQyy] = plane_sphere.k[kQzz] = 2;
  plane_sphere.k[kBx] = 2;
  plane_sphere.k[kC] = -2;
  EXPECT_EQ(darboux_type(plane_sphere), DarbouxType::reducible);
  EXPECT_EQ(darboux_type(example2()), DarbouxType::parabolic);
  Darboux torus_like = example2();
  torus_like.k[kPhi0] = 1;
  EXPECT_EQ(darboux_type(torus_like), DarbouxType::quartic);
  // Products of two spheres are reducible quartics (real or complex
  // conjugate factors); a torus is not.
  auto product = [](const GeneralSphere& s1, const GeneralSphere& s2) {
    Darboux P;
    const Eigen::Matrix3d B = 0.5 * (s1.B * s2.B.transpose() + s2.B * s1.B.transpose());
    P.set(s1.A * s2.A, s1.A * s2.B + s2.A * s1.B,
          (s1.A * s2.C + s2.A * s1.C) * Eigen::Matrix3d::Identity() + B,
          s1.B * s2.C + s2.B * s1.C, s1.C * s2.C);
    return P;
  };
  EXPECT_EQ(darboux_type(product({1, {1, -2, 0.5}, -3}, {2, {0.3, 1, -1}, 0.2})),
            DarbouxType::reducible);
  EXPECT_EQ(darboux_type(product({1, {0, 0, 0}, -1}, {1, {0, 0, 0}, -4})), DarbouxType::reducible);
  EXPECT_EQ(darboux_type(product({1, {0, 0, 0}, -1}, {1, {0, 0, 0}, -1})), DarbouxType::reducible);
  Darboux conjugate;  // (X.X)^2 + x^2 = (X.X + i x)(X.X - i x)
  conjugate.k[kPhi0] = 1;
  conjugate.k[kQxx] = 1;
  EXPECT_EQ(darboux_type(conjugate), DarbouxType::reducible);
  Darboux torus;  // (X.X + R^2 - r^2)^2 - 4 R^2 (x^2 + y^2), R = 2, r = 1
  torus.k[kPhi0] = 1;
  torus.k[kQxx] = torus.k[kQyy] = 2 * 3 - 16;
  torus.k[kQzz] = 2 * 3;
  torus.k[kC] = 9;
  EXPECT_EQ(darboux_type(torus), DarbouxType::quartic);
  Darboux spindle = torus;  // a perturbed product is irreducible
  spindle.k[kC] = 9.001;
  EXPECT_EQ(darboux_type(product({1, {1, -2, 0.5}, -3}, {2, {0.3, 1, -1}, 0.2 + 1e-6})),
            DarbouxType::reducible);  // still a product
  Darboux near = product({1, {1, -2, 0.5}, -3}, {2, {0.3, 1, -1}, 0.2});
  near.k[kC] += 1e-3;
  EXPECT_EQ(darboux_type(near), DarbouxType::quartic);
  EXPECT_EQ(darboux_type(spindle), DarbouxType::quartic);
  Darboux plane;
  plane.k[kBx] = 1;
  EXPECT_EQ(darboux_type(plane), DarbouxType::plane);
  EXPECT_EQ(darboux_type(Darboux{}), DarbouxType::zero);
}

// Fuzz finding (fuzz_lines regress-tiny-plane-sphere-type): the type must
// not depend on the equation's scale; z (a X.X - b) with |k| ~ 1e-164 was
// parabolic while 2^7 times it was (rightly) reducible.
TEST(Darboux, RegressionTypeIsScaleInvariantDownToTinyCoefficients) {
  Darboux D;
  D.k[kLz] = 3.59237314748795e-164;
  D.k[kBz] = -3.5994032319253045e-164;
  for (int e : {-7, 0, 7, 300, 600}) {
    Darboux S = D;
    for (double& v : S.k) v = std::ldexp(v, e);
    EXPECT_EQ(darboux_type(S), DarbouxType::reducible) << e;
  }
}

TEST(Darboux, GradientIsTheDerivativeOfTheValue) {
  Darboux D = example4(0.7);
  D.k[kPhi0] = 0.3;
  const Vec3d X(0.4, -1.1, 0.8);
  const double h = 1e-6;
  const Vec3d g = D.gradient(X);
  for (int i = 0; i < 3; ++i) {
    Vec3d e = Vec3d::Zero();
    e[i] = h;
    EXPECT_NEAR((D.value(X + e) - D.value(X - e)) / (2 * h), g[i], 1e-7);
  }
}

// §5: "If the center of the inversion sphere is located on the Darboux
// cyclide, then the equation of its image satisfies phi0 = 0."
TEST(Darboux, InversionAtAPointOfTheCyclideGivesAParabolicOne) {
  const Darboux C = example2();  // contains l1 = (u, 0, 0)
  Inversion on{{0.7, 0, 0}, 1.3}, off{{0.3, 0.9, -0.4}, 1.3};
  Darboux R;
  ASSERT_EQ(invert_darboux(on, C, R), Status::ok);
  EXPECT_LE(std::abs(R.phi0()), 1e-14);
  // A center off the surface gives a quartic; inverting back gives C again.
  ASSERT_EQ(invert_darboux(off, C, R), Status::ok);
  EXPECT_EQ(darboux_type(R), DarbouxType::quartic);
  Darboux back;
  ASSERT_EQ(invert_darboux(off, R, back), Status::ok);
  const double s = C.scale() / back.scale() * (back.k[kLz] > 0 ? 1 : -1);
  for (int i = 0; i < kDarbouxCoeffs; ++i) EXPECT_NEAR(back.k[i] * s, C.k[i], 1e-11);
}

TEST(Darboux, InversionOfPointsSpheresAndCircles) {
  const Inversion inv{{1, 2, 3}, 2};
  Vec3d X;
  EXPECT_EQ(invert_point(inv, {1, 2, 3}, X), Status::at_inversion_center);
  EXPECT_EQ(invert_point({{0, 0, 0}, 0.0}, {1, 0, 0}, X), Status::invalid_argument);
  ASSERT_EQ(invert_point(inv, {1, 2, 4}, X), Status::ok);
  EXPECT_LE((X - Vec3d(1, 2, 7)).norm(), 1e-15);  // distance 1 -> rho^2 = 4
  // The sphere through m of radius 1 centered at m + (1,0,0) maps to the
  // plane x = m.x + rho^2 / 2.
  GeneralSphere S{1, -2 * Vec3d(2, 2, 3), Vec3d(2, 2, 3).squaredNorm() - 1}, P;
  ASSERT_EQ(invert_sphere(inv, S, P), Status::ok);
  EXPECT_LE(std::abs(P.A), 1e-15);
  EXPECT_NEAR(-P.C / P.B.x(), 1 + 2, 1e-14);
  EXPECT_LE(std::abs(P.B.y()) + std::abs(P.B.z()), 1e-15);
  // A circle through m maps to a line; the line maps back to that circle.
  CircleOrLine c{false, {2, 2, 3}, {0, 0, 1}, 1.0}, l, back;
  ASSERT_EQ(invert_circle(inv, c, l), Status::ok);
  EXPECT_TRUE(l.is_line);
  ASSERT_EQ(invert_circle(inv, l, back), Status::ok);
  EXPECT_FALSE(back.is_line);
  EXPECT_LE((back.point - c.point).norm(), 1e-12);
  EXPECT_NEAR(back.radius, 1.0, 1e-12);
  EXPECT_NEAR(std::abs(back.axis.z()), 1.0, 1e-12);
}

// Regression (fuzz_darboux, fuzz/corpus/fuzz_darboux/regress-circle-image-*):
// when the image of a circle or line collapses below the resolution of
// doubles (a circle near 1e100 inverted in a small sphere, or rho^2
// underflowing to 0), the three image points coincide; invert_circle
// returned ok with a "line" of axis (0, 0, 0). Now numerical_overflow.
TEST(Darboux, InvertCircleCollapsedImageIsNumericalOverflow) {
  CircleOrLine out;
  const Inversion small{{0.1, -8, -8.9032}, 1.0 / 64};
  const CircleOrLine far{false, {0x1.249ad2594c37dp+332, -9.375, -1.57}, {0, 1, 0}, 0.23};
  EXPECT_EQ(invert_circle(small, far, out), Status::numerical_overflow);
  const Inversion underflow{{0.0082, -5.4, -36.4}, 0x1.4395b31c8decfp-1017};
  const CircleOrLine line{true, {7.8, 8, 9.9}, {1, 0, 0}, 0};
  EXPECT_EQ(invert_circle(underflow, line, out), Status::numerical_overflow);
  // Still fine: the same circle and line at a resolvable scale.
  const CircleOrLine near{false, {3, -9.375, -1.57}, {0, 1, 0}, 0.23};
  ASSERT_EQ(invert_circle(small, near, out), Status::ok);
  EXPECT_NEAR(out.axis.norm(), 1.0, 1e-12);
  ASSERT_EQ(invert_circle(Inversion{{0.0082, -5.4, -36.4}, 0.5}, line, out), Status::ok);
  EXPECT_FALSE(out.is_line);
  EXPECT_NEAR(out.axis.norm(), 1.0, 1e-12);
}

// Regression (fuzz_darboux, fuzz/corpus/fuzz_darboux/regress-line-through-
// far-center): a line through m = (-122.98828125, -6, 1) (rho = 1/32) misses
// m by the rounding of its point (~1e-14), which was more than 1e-14 (|w| +
// rho): the image was built from three far image points and came out as a
// line of direction (0, 0, 1). Through m to the rounding of the coordinates
// the line is its own image.
TEST(Darboux, InvertLineThroughFarCenterIsTheLineItself) {
  const Inversion inv{{-0x1.ebf4p+6, -0x1.8p+2, 0x1p+0}, 0x1p-5};
  const CircleOrLine line{true,
                          {-0x1.ebeb0634fbe6ep+6, -0x1.8p+2, 0x1.fdc18d1aeea5ap-1},
                          {-0x1p+0, -0x0p+0, 0x1.0000101p-1},
                          0};
  CircleOrLine out;
  ASSERT_EQ(invert_circle(inv, line, out), Status::ok);
  ASSERT_TRUE(out.is_line);
  EXPECT_NEAR(std::abs(out.axis.dot(line.axis.normalized())), 1.0, 1e-15);
  const Vec3d w = inv.m - out.point;
  EXPECT_LE((w - w.dot(out.axis) * out.axis).norm(), 1e-13);
}

// Regression (fuzz_darboux, fuzz/corpus/fuzz_darboux/regress-nan-image-*):
// with huge centers or radii the closed forms overflow to inf - inf = NaN in
// one coefficient; the normalization's max skipped the NaN and
// invert_sphere / invert_darboux returned ok with a NaN coefficient. Now
// numerical_overflow.
TEST(Darboux, InvertSphereAndDarbouxNaNImageIsNumericalOverflow) {
  const Inversion big{{0x1.45p+2, 0x1.249ad2594c37bp+332, -4}, 0x1.249ad2594c379p+332};
  const GeneralSphere S{-25, {14, -6, -0x1.26e978d4fdf3cp-4}, -8};
  GeneralSphere R;
  EXPECT_EQ(invert_sphere(big, S, R), Status::numerical_overflow);
  const Inversion far{{-0x1.0624dd2f1a9fcp-9, -9, -81}, 0x1.51fb1af5204dap+135};
  Darboux D;
  const double k[kDarbouxCoeffs] = {0, 0, 0, 1, 0, -1, -3, -3, 0x1.d6p+9, -0x1.d6p+10,
                                    0, 0x1.d6p+10, 2, 0x1.dae7fc63a19p+20};
  std::copy(k, k + kDarbouxCoeffs, D.k);
  Darboux out;
  EXPECT_EQ(invert_darboux(far, D, out), Status::numerical_overflow);
  // The same equations at a moderate inversion are fine.
  ASSERT_EQ(invert_sphere(Inversion{{1, 2, 3}, 2}, S, R), Status::ok);
  ASSERT_EQ(invert_darboux(Inversion{{1, 2, 3}, 2}, D, out), Status::ok);
  for (double v : out.k) EXPECT_TRUE(std::isfinite(v));
}

// §5: the inverted PRCS surface of Example 2 is a circle family on the
// inverted cyclide (39): grids agree with single points bit for bit, and the
// inverted circles carry the grid's rows.
TEST(Darboux, InvertedSurfaceGridAndCirclesLieOnTheInvertedCyclide) {
  RationalCurve l1, l2;
  ASSERT_EQ(make_line({0, 0, 0}, {1, 0, 0}, l1), Status::ok);
  ASSERT_EQ(make_line({0, 0, 1}, {2, 1, 0}, l2), Status::ok);
  Surface S;
  ASSERT_EQ(make_prcs(l1, l2, nullptr, -0.5, 0.5, S), Status::ok);
  const Inversion inv{{0.3, -0.7, 0.4}, 1.3};
  Darboux img;
  ASSERT_EQ(invert_darboux(inv, example2(), img), Status::ok);
  EXPECT_EQ(darboux_type(img), DarbouxType::quartic);  // the center is not on (39)
  const double us[3] = {-0.5, 0.1, 0.45}, vs[5] = {-3, -0.5, 0, 0.7, 40};
  double P[15 * 3], U[15 * 3], V[15 * 3], N[15 * 3];
  std::size_t singular = 99;
  ASSERT_EQ(eval_grid_inverted(S, inv, us, 3, vs, 5, {P, 3}, {U, 3}, {V, 3}, {N, 3}, &singular),
            Status::ok);
  EXPECT_EQ(singular, 0u);
  for (int i = 0; i < 3; ++i) {
    CircleOrLine c;
    ASSERT_EQ(inverted_circle(S, inv, us[i], c), Status::ok);
    ASSERT_FALSE(c.is_line);
    for (int j = 0; j < 5; ++j) {
      const int k = 5 * i + j;
      const Vec3d X(P + 3 * k);
      EXPECT_NEAR(img.value(X) / img.gradient(X).norm(), 0.0, 1e-12);
      EXPECT_NEAR((X - c.point).norm(), c.radius, 1e-12);
      EXPECT_NEAR((X - c.point).dot(c.axis), 0.0, 1e-12);
      EXPECT_NEAR(Vec3d(N + 3 * k).dot(Vec3d(U + 3 * k)), 0.0, 1e-12 * Vec3d(U + 3 * k).norm());
      // The same bits as one point at a time.
      double x[3], xu[3], xv[3], xn[3];
      EvalOut o{x, xu, xv, xn};
      ASSERT_EQ(S.eval(us[i], vs[j], o), Status::ok);
      SurfacePoint p, r;
      p.x = Vec3d(x);
      p.du = Vec3d(xu);
      p.dv = Vec3d(xv);
      p.normal = Vec3d(xn);
      ASSERT_EQ(invert_surface_point(inv, p, true, true, true, r), Status::ok);
      for (int a = 0; a < 3; ++a) {
        EXPECT_EQ(P[3 * k + a], r.x[a]);
        EXPECT_EQ(U[3 * k + a], r.du[a]);
        EXPECT_EQ(N[3 * k + a], r.normal[a]);
      }
    }
  }
  // All or nothing: a grid point at the center leaves the buffers untouched.
  double x0[3];
  EvalOut o0{x0, nullptr, nullptr, nullptr};
  ASSERT_EQ(S.eval(0.1, 0.7, o0), Status::ok);
  const Inversion at{Vec3d(x0), 1.0};
  std::fill(P, P + 45, 7.0);
  EXPECT_EQ(eval_grid_inverted(S, at, us, 3, vs, 5, {P, 3}, {}, {}, {}, nullptr),
            Status::at_inversion_center);
  EXPECT_TRUE(std::all_of(P, P + 45, [](double v) { return v == 7.0; }));
  // The circle through the center maps to a line.
  CircleOrLine line;
  ASSERT_EQ(inverted_circle(S, at, 0.1, line), Status::ok);
  EXPECT_TRUE(line.is_line);
}

TEST(Darboux, DcmcReportsDegenerateInput) {
  DcmcFamily F;
  const Line parallel[3] = {{{0, 0, 0}, {1, 0, 0}}, {{0, 0, 1}, {2, 0, 0}}, {{0, 0, 2}, {1, 1, 0}}};
  EXPECT_EQ(dcmc(parallel, F), Status::parallel_lines);
  const Line skew[3] = {{{0, 0, 0}, {1, 0, 0}}, {{0, 0, 1}, {0, 1, 0}}, {{0, 0, 2}, {0, 1, 1}}};
  EXPECT_EQ(dcmc(skew, F), Status::no_common_normal);
  const Line bad[3] = {{{0, 0, 0}, {0, 0, 0}}, {{0, 0, 1}, {0, 1, 0}}, {{0, 0, 2}, {1, 1, 0}}};
  EXPECT_EQ(dcmc(bad, F), Status::invalid_argument);
  const Line nan[3] = {{{NAN, 0, 0}, {1, 0, 0}}, {{0, 0, 1}, {0, 1, 0}}, {{0, 0, 2}, {1, 1, 0}}};
  EXPECT_EQ(dcmc(nan, F), Status::not_finite);
}

}  // namespace
}  // namespace cyclide
