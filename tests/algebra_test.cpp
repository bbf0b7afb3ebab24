// The core algebra against definitions: quaternion product (12), the
// sandwich of (11) against the expanded evaluator, polynomials, series,
// Bernstein form and Hermite interpolation.
#include <gtest/gtest.h>

#include <cmath>

#include "cyclide/circle_family.hpp"
#include "cyclide/hermite.hpp"
#include "cyclide/poly.hpp"

using namespace cyclide;

TEST(Quaternion, ProductIsEq12) {
  const Quat<double> a{0.5, Vec3d(1, -2, 3)}, b{-1.5, Vec3d(0.25, 4, -1)};
  const Quat<double> p = a * b;
  // ab - a.b + a b + b a + a x b
  EXPECT_DOUBLE_EQ(p.w, 0.5 * -1.5 - Vec3d(1, -2, 3).dot(Vec3d(0.25, 4, -1)));
  const Vec3d v = 0.5 * Vec3d(0.25, 4, -1) + -1.5 * Vec3d(1, -2, 3) +
                  Vec3d(1, -2, 3).cross(Vec3d(0.25, 4, -1));
  EXPECT_LE((p.v - v).norm(), 1e-15);
}

TEST(Quaternion, ExpandedRotationEqualsLiteralEq11) {
  // (f + s') * d * (f - s') / ((f - s') * (f + s')) for a few f, s', d.
  for (double f : {-3.0, -0.2, 0.0, 0.7, 5.0}) {
    const Vec3d a(0.3, -1.1, 2.0), d(1.0, 0.4, -0.6);
    const Quat<double> q{f, a};
    const Quat<double> dq{0.0, d};
    const Quat<double> num = q * dq * q.conj();
    const Quat<double> den = q.conj() * q;
    EXPECT_NEAR(num.w, 0.0, 1e-14);  // a vector: zero scalar part (§3)
    EXPECT_LE(den.v.norm(), 1e-15);  // the denominator is a scalar
    EXPECT_LE((num.v / den.w - rotate(q, d)).norm(), 1e-14);
    // tan(theta/2) = |s'| / f (13): the angle between the components of d
    // orthogonal to the axis.
    const Vec3d ax = a.normalized();
    const Vec3d d0 = d - d.dot(ax) * ax, d1 = rotate(q, d) - d.dot(ax) * ax;
    const double theta = std::atan2(ax.dot(d0.cross(d1)), d0.dot(d1));
    EXPECT_NEAR(f * std::sin(theta / 2), a.norm() * std::cos(theta / 2),
                1e-12 * (1 + std::abs(f)));
  }
}

TEST(Poly, TaylorShiftGivesDerivatives) {
  const double c[] = {1, -2, 0.5, 3};  // 1 - 2u + u^2/2 + 3u^3
  Poly<double, 5> p;
  ASSERT_TRUE(p.assign(c, 3));
  const double u = 0.7;
  const auto t = p.taylor<3>(u);
  EXPECT_DOUBLE_EQ(t.c[0], p(u));
  EXPECT_NEAR(t.derivative(1), -2 + u + 9 * u * u, 1e-14);
  EXPECT_NEAR(t.derivative(2), 1 + 18 * u, 1e-14);
  EXPECT_NEAR(t.derivative(3), 18, 1e-14);
}

TEST(Poly, MultiplyRespectsCapacity) {
  Poly<double, 3> a = Poly<double, 3>::linear(1, 1), r;
  Poly<double, 3> b;
  const double c[] = {0, 0, 0, 1};
  ASSERT_TRUE(b.assign(c, 3));
  EXPECT_FALSE(multiply(a, b, r));  // degree 4 > 3: reported, not reallocated
  EXPECT_TRUE(multiply(a, a, r));
  EXPECT_DOUBLE_EQ(r(2.0), 9.0);
}

TEST(Poly, BernsteinRoundTrip) {
  const double c[] = {0.3, -1, 2, 0.25, -0.75};
  Poly<double, 8> p, q;
  ASSERT_TRUE(p.assign(c, 4));
  double b[5];
  to_bernstein(p, -0.5, 2.0, b);
  // Bernstein coefficients interpolate the end values.
  EXPECT_NEAR(b[0], p(-0.5), 1e-14);
  EXPECT_NEAR(b[4], p(2.0), 1e-13);
  ASSERT_TRUE(from_bernstein(b, 4, -0.5, 2.0, q));
  for (int k = 0; k <= 4; ++k) EXPECT_NEAR(q.c[k], p.c[k], 1e-13);
}

TEST(Taylor, QuotientAndSqrt) {
  using T = Taylor<double, 3>;
  const T u = T::variable(0.4);
  const T f = (u * u + T(1.0)) / (u + T(2.0));  // (u^2+1)/(u+2)
  const double x = 0.4;
  EXPECT_NEAR(f.derivative(1), (x * x + 4 * x - 1) / ((x + 2) * (x + 2)), 1e-14);
  const T g = sqrt(u * u + T(1.0));
  EXPECT_NEAR(g.derivative(1), x / std::sqrt(x * x + 1), 1e-14);
  EXPECT_NEAR(g.derivative(2), 1 / std::pow(x * x + 1, 1.5), 1e-14);
}

TEST(Hermite, InterpolatesDerivativesAtBothEnds) {
  for (int K = 0; K <= kMaxHermiteOrder; ++K) {
    Vec3d a[kMaxHermiteOrder + 1], b[kMaxHermiteOrder + 1];
    for (int j = 0; j <= K; ++j) {
      a[j] = Vec3d(1 + j, -0.5 * j, 0.25 * j * j);
      b[j] = Vec3d(-j, 2 - j, 0.5);
    }
    RationalCurve c;
    ASSERT_EQ(make_hermite_curve(K, 0.5, 1.5, a, b, c), Status::ok);
    EXPECT_EQ(c.degree(), 2 * K + 1);
    const auto s = c.taylor<kMaxHermiteOrder>(0.5), e = c.taylor<kMaxHermiteOrder>(1.5);
    // Bernstein form + de Casteljau (SPEC.md "Hermite"): 1e-12 relative up to
    // degree 15 with the j-th derivative within 2e-14 4^j (the power form lost
    // 4e-5 here).
    const int n = 2 * K + 1;
    (void)n;
    for (int j = 0; j <= K; ++j)
      for (int i = 0; i < 3; ++i) {
        // A j-th derivative is n!/(n-j)!/h^j times a j-th difference of the
        // control points: error <= 2^j eps n!/(n-j)! max|b| (h = 1 here).
        double bmax = 0, falling = 1;
        for (int m = 0; m <= n; ++m)
          bmax = std::max({bmax, std::abs(c.x.c[m]), std::abs(c.y.c[m]), std::abs(c.z.c[m])});
        for (int m = 0; m < j; ++m) falling *= n - m;
        const double tol = 4e-16 * std::ldexp(1.0, j) * falling * bmax;
        EXPECT_NEAR(s[i].derivative(j), a[j][i], tol) << K << j;
        EXPECT_NEAR(e[i].derivative(j), b[j][i], tol) << K << j;
      }
  }
  RationalCurve c;
  Vec3d z[9];
  EXPECT_EQ(make_hermite_curve(8, 0, 1, z, z, c), Status::degree_too_high);
}

TEST(CircleQuadratic, IsTheRationalQuadraticOfTheRotation) {
  // x - o = (P0 + P1 v + P2 v^2) / (Q0 + Q1 v + Q2 v^2) equals the rotation
  // (11) of p - o by q = (alpha v + beta) + (gamma v + delta) a.
  CircleFrame<double> F;
  F.o = Vec3d(0.5, -1, 2);
  F.a = Vec3d(0.3, 0.8, -0.4);
  F.p = Vec3d(1.5, 0.25, 1);
  F.alpha = 1.2;
  F.beta = -0.3;
  F.gamma = 0.4;
  F.delta = 0.9;
  const CircleQuadratic<double> C = circle_quadratic(F);
  for (double v : {-3.0, -0.5, 0.0, 0.7, 2.0}) {
    const Vec3d num = C.P[0] + v * C.P[1] + v * v * C.P[2];
    const double den = C.Q[0] + v * C.Q[1] + v * v * C.Q[2];
    const Quat<double> q{F.alpha * v + F.beta, (F.gamma * v + F.delta) * F.a};
    EXPECT_LE((num / den - rotate(q, Vec3d(F.p - F.o))).norm(), 1e-14);
  }
}
