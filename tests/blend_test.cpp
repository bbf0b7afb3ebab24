// Blends of seed 000 §9 (labels "paper;blend"): exact u-derivatives of
// surface points, the Fig. 6 situation (two quadratic cones joined by a C^1
// ringed blend through cubic curves), canal blends (G^(K-1), Prop. 6) and
// their weakness (parallel normal planes, reported as a status), and the
// continuity report of a join.

#include <gtest/gtest.h>

#include <cmath>

#include "cyclide/blend.hpp"

using namespace cyclide;

namespace {

const double kPi = std::acos(-1.0);

// PRRS of three lines A + u R d_k through the apex A, d_k = (cos, sin, 1)
// in the frame (e1, e2, e3): a circular quadratic cone with axis e3.
Surface cone(const Vec3d& A, const Vec3d& e1, const Vec3d& e2, const Vec3d& e3, double u0,
             double u1) {
  RationalCurve L[3];
  for (int k = 0; k < 3; ++k) {
    const double t = 2 * kPi * k / 3 + 0.3;
    EXPECT_EQ(make_line(A, std::cos(t) * e1 + std::sin(t) * e2 + e3, L[k]), Status::ok);
  }
  Surface S;
  EXPECT_EQ(make_prrs(L[0], L[1], L[2], nullptr, u0, u1, S), Status::ok);
  return S;
}

Surface cone1() { return cone({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 0.5, 1.0); }
// Axis -x, apex (4, 0, 4): its wide end circle (u = 1) faces cone1's.
Surface cone2() { return cone({4, 0, 4}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, 0.5, 1.0); }

// A PRCS surface of two cubic curves (generic canal surface).
Surface canal() {
  const double c1[12] = {0, 0, 0, 1, 0.2, 0, 0, 0.5, 0.1, 0.05, 0, 0};
  const double c2[12] = {0, 1, 0.5, 1, -0.1, 0.3, 0.2, 0, 0, 0, 0.1, 0};
  RationalCurve p1, p2;
  EXPECT_EQ(make_polynomial_curve(3, c1, p1), Status::ok);
  EXPECT_EQ(make_polynomial_curve(3, c2, p2), Status::ok);
  Surface S;
  EXPECT_EQ(make_prcs(p1, p2, nullptr, 0.0, 1.0, S), Status::ok);
  return S;
}

// The guide of the spline blends: the cylinder of radius 1 about the axis
// (1, 0, 1) through (1.2, 0, 2.8) (reached at u = 1/2), PRRS of three lines.
Surface guide_cylinder() {
  const Vec3d axis(1, 0, 1), c0(1.2, 0, 2.8);
  const Vec3d e1 = Vec3d(1, 0, -1).normalized(), e2(0, 1, 0);
  RationalCurve L[3];
  for (int k = 0; k < 3; ++k) {
    const double a = 2 * kPi * k / 3;
    EXPECT_EQ(make_line(c0 + std::cos(a) * e1 + std::sin(a) * e2 - 0.5 * axis, axis, L[k]),
              Status::ok);
  }
  Surface G;
  EXPECT_EQ(make_prrs(L[0], L[1], L[2], nullptr, 0.0, 1.0, G), Status::ok);
  return G;
}

// Ends of a spline blend from cone A (upper end) through the guide's waist
// circle (lambda 2: along the guide's u, from A towards B) to cone B.
void guide_ends(const Surface& A, const Surface& G, const Surface& B, BlendEnd (&ends)[3]) {
  const Surface* S[3] = {&A, &G, &B};
  const double us[3] = {1.0, 0.5, 1.0}, vs[3] = {HUGE_VAL, -0.5, 0.7};
  for (int i = 0; i < 3; ++i) {
    ends[i] = BlendEnd();
    ends[i].surface = S[i];
    ends[i].u = us[i];
    for (int j = 0; j < 3; ++j) ends[i].v[j] = vs[j];
  }
  ends[1].lambda = 2.0;
}

double rel(const Vec3d& a, const Vec3d& b) {
  return (a - b).norm() / std::max(1.0, std::max(a.norm(), b.norm()));
}

}  // namespace

TEST(Derivatives, MatchEvalAndFiniteDifferences) {
  for (const Surface& S : {cone1(), canal()}) {
    for (double u : {0.55, 0.7, 0.9}) {
      for (double v : {-3.0, -0.4, 0.0, 0.8, 2.5, 1e300, HUGE_VAL}) {
        Vec3d d[kMaxBlendOrder + 1];
        ASSERT_EQ(derivatives_u(S, u, v, 0, d), Status::ok);
        double x[3], xu[3];
        EvalOut o;
        o.point = x;
        o.du = xu;
        ASSERT_EQ(S.eval(u, std::isfinite(v) ? v : 1e300, o), Status::ok);
        EXPECT_LT(rel(d[0], Vec3d(x[0], x[1], x[2])), 1e-12);
        ASSERT_EQ(derivatives_u(S, u, v, kMaxBlendOrder, d), Status::ok);
        EXPECT_LT(rel(d[1], Vec3d(xu[0], xu[1], xu[2])), 1e-12) << u << " " << v;
        // Central differences of order l-1 give order l.
        const double h = 1e-5;
        for (int l = 1; l <= 4; ++l) {
          Vec3d dp[kMaxBlendOrder + 1], dm[kMaxBlendOrder + 1];
          ASSERT_EQ(derivatives_u(S, u + h, v, l - 1, dp), Status::ok);
          ASSERT_EQ(derivatives_u(S, u - h, v, l - 1, dm), Status::ok);
          const Vec3d fd = (dp[l - 1] - dm[l - 1]) / (2 * h);
          EXPECT_LT((fd - d[l]).norm() / std::max(1.0, d[l].norm()), 1e-6) << l;
        }
      }
    }
  }
}

TEST(Derivatives, Validation) {
  const Surface S = cone1();
  Vec3d d[kMaxBlendOrder + 2];
  d[0] = Vec3d(7, 7, 7);
  EXPECT_EQ(derivatives_u(S, 0.7, 0.0, -1, d), Status::invalid_argument);
  EXPECT_EQ(derivatives_u(S, 0.7, 0.0, kMaxBlendOrder + 1, d), Status::degree_too_high);
  EXPECT_EQ(derivatives_u(S, NAN, 0.0, 1, d), Status::not_finite);
  EXPECT_EQ(derivatives_u(S, 0.7, NAN, 1, d), Status::not_finite);
  EXPECT_EQ(derivatives_u(S, 0.7, 0.0, 1, nullptr), Status::null_argument);
  EXPECT_EQ(d[0], Vec3d(7, 7, 7));
}

// Fig. 6: two quadratic cones, C^1 ringed blend through three cubic curves.
TEST(RingedBlend, Figure6ConesC1AndHigherOrders) {
  const Surface A = cone1(), B = cone2();
  for (int K = 1; K <= 3; ++K) {
    BlendEnd s, e;
    s.surface = &A;
    s.u = 1.0;  // upper end: lambda = +1 (continue A)
    e.surface = &B;
    e.u = 1.0;  // upper end: lambda = -1 (lead into B towards its apex)
    const double vs[3] = {HUGE_VAL, -0.5, 0.7};
    for (int j = 0; j < 3; ++j) s.v[j] = e.v[j] = vs[j];
    EXPECT_EQ(blend_lambda(s, 0), 1.0);
    EXPECT_EQ(blend_lambda(e, 1), -1.0);
    Surface X;
    RationalCurve p[3];
    double bad = -1;
    ASSERT_EQ(make_ringed_blend(s, e, K, 0.0, 1.0, X, &bad, p), Status::ok) << K << " " << bad;
    for (int j = 0; j < 3; ++j) EXPECT_EQ(p[j].degree(), 2 * K + 1);
    // Both joins: gap, C^K of the circle family, C^K at the generator point
    // (where the two v-parameterizations agree), tangent planes.
    struct Join {
      const Surface* S;
      double u, lambda, t;
    } joins[2] = {{&A, 1.0, 1.0, 0.0}, {&B, 1.0, -1.0, 1.0}};
    for (const Join& J : joins) {
      ContinuityReport R;
      ASSERT_EQ(continuity_report(*J.S, J.u, J.lambda, X, J.t, K, nullptr, 64, R), Status::ok);
      EXPECT_LE(R.max_gap, 1e-12 * R.point_scale);
      EXPECT_LE(R.max_normal_angle, 1e-9);
      for (int l = 0; l <= K; ++l) EXPECT_LE(R.circle_jump[l], 1e-9) << "K " << K << " l " << l;
      ContinuityReport G;  // at the generator only
      const double vg = HUGE_VAL;
      ASSERT_EQ(continuity_report(*J.S, J.u, J.lambda, X, J.t, K, &vg, 1, G), Status::ok);
      for (int l = 0; l <= K; ++l)
        EXPECT_LE(G.point_jump[l], 1e-9 * std::max(G.point_scale_l[l], G.point_scale)) << "K " << K << " l " << l;
      // Order K+1 is generically not continuous (the report sees it).
      if (K < kMaxBlendOrder) {
        ContinuityReport H;
        ASSERT_EQ(continuity_report(*J.S, J.u, J.lambda, X, J.t, K + 1, nullptr, 16, H),
                  Status::ok);
        EXPECT_GT(H.circle_jump[K + 1], 1e-6);
      }
    }
  }
}

// Faa di Bruno (reparameterize): x(u) = (u^3, u^2 - u, 1/(1 + u)) at
// u0 = 0.5 with u = phi(t) = u0 + a t + b t^2/2 + c t^3/6, against the
// series of x(phi(t)) formed directly (the same truncated arithmetic, a
// different route: no composition).
TEST(Reparameterize, FaaDiBrunoMatchesTheComposedSeries) {
  const double u0 = 0.5, jet[3] = {1.7, -0.6, 2.3};
  Taylor<double, 3> U;
  U.c[0] = u0;
  U.c[1] = jet[0];
  U.c[2] = jet[1] / 2;
  U.c[3] = jet[2] / 6;
  const Taylor<double, 3> one(1.0);
  const Taylor<double, 3> X[3] = {U * U * U, U * U - U, one / (one + U)};
  // d^k x / du^k at u0.
  const double w = 1 + u0;
  const Vec3d dx[4] = {{u0 * u0 * u0, u0 * u0 - u0, 1 / w},
                       {3 * u0 * u0, 2 * u0 - 1, -1 / (w * w)},
                       {6 * u0, 2, 2 / (w * w * w)},
                       {6, 0, -6 / (w * w * w * w)}};
  Vec3d out[4];
  reparameterize(3, dx, jet, out);
  const double fact[4] = {1, 1, 2, 6};
  for (int l = 0; l <= 3; ++l)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(out[l][j], fact[l] * X[j].c[l], 1e-13) << l << j;
  // phi'' = phi''' = 0: plain lambda^l scaling.
  const double plain[3] = {-2.0, 0.0, 0.0};
  reparameterize(3, dx, plain, out);
  for (int l = 0; l <= 3; ++l) EXPECT_EQ(out[l], std::pow(-2.0, l) * dx[l]) << l;
}

// The higher Hermite scalars phi'', ... change the blend but keep the join
// geometrically C^K: the continuity report with the same jet sees no jumps,
// the plain lambda^l comparison sees one at order 2.
TEST(RingedBlend, HigherReparameterizationDerivativesKeepGK) {
  const Surface A = cone1(), B = cone2();
  const int K = 3;
  BlendEnd s, e;
  s.surface = &A;
  s.u = 1.0;
  s.lambda = 1.3;
  s.phi[0] = 0.8;   // phi''
  s.phi[1] = -0.5;  // phi'''
  e.surface = &B;
  e.u = 1.0;
  e.lambda = -0.7;
  e.phi[0] = -0.4;
  const double vs[3] = {HUGE_VAL, -0.5, 0.7};
  for (int j = 0; j < 3; ++j) s.v[j] = e.v[j] = vs[j];
  Surface X, Y;
  ASSERT_EQ(make_ringed_blend(s, e, K, 0.0, 1.0, X), Status::ok);
  BlendEnd s0 = s, e0 = e;
  s0.phi[0] = s0.phi[1] = e0.phi[0] = 0.0;
  ASSERT_EQ(make_ringed_blend(s0, e0, K, 0.0, 1.0, Y), Status::ok);
  double x[3], y[3];
  ASSERT_EQ(X.eval(0.5, 0.2, {x, nullptr, nullptr, nullptr}), Status::ok);
  ASSERT_EQ(Y.eval(0.5, 0.2, {y, nullptr, nullptr, nullptr}), Status::ok);
  EXPECT_GT(rel(Vec3d(x[0], x[1], x[2]), Vec3d(y[0], y[1], y[2])), 1e-3);  // another shape
  const BlendEnd* ends[2] = {&s, &e};
  for (int i = 0; i < 2; ++i) {
    double jet[kMaxBlendOrder];
    blend_jet(*ends[i], i, K, jet);
    EXPECT_EQ(jet[0], ends[i]->lambda);
    EXPECT_EQ(jet[1], ends[i]->phi[0]);
    ContinuityReport R, P;
    ASSERT_EQ(continuity_report(*ends[i]->surface, 1.0, jet, X, double(i), K, nullptr, 32, R),
              Status::ok);
    EXPECT_LE(R.max_gap, 1e-12 * R.point_scale);
    for (int l = 0; l <= K; ++l) EXPECT_LE(R.circle_jump[l], 1e-9) << i << " " << l;
    ASSERT_EQ(continuity_report(*ends[i]->surface, 1.0, jet[0], X, double(i), K, nullptr, 32, P),
              Status::ok);
    EXPECT_GT(P.circle_jump[2], 1e-4) << i;
  }
}

// make_hermite_spline: every piece takes the knot data, so the pieces
// agree to order K at the interior knots.
TEST(Hermite, SplinePiecesJoinCK) {
  const int K = 2, n = 3;
  const double u[n] = {0.0, 0.4, 1.0};
  Vec3d data[n * (K + 1)];
  for (int i = 0; i < n * (K + 1); ++i) data[i] = Vec3d(0.3 * i, std::sin(i), 1.0 / (1 + i));
  RationalCurve P[n - 1];
  ASSERT_EQ(make_hermite_spline(K, n, u, data, P), Status::ok);
  const auto left = P[0].taylor<K>(0.4), right = P[1].taylor<K>(0.4);
  double f = 1;
  for (int j = 0; j <= K; ++j) {
    if (j > 0) f *= j;
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(f * left[c].c[j], data[(K + 1) + j][c], 1e-12) << j;
      EXPECT_NEAR(f * right[c].c[j], data[(K + 1) + j][c], 1e-12) << j;
    }
  }
  EXPECT_EQ(make_hermite_spline(K, 1, u, data, P), Status::invalid_argument);
  EXPECT_EQ(make_hermite_spline(K, kMaxSplineKnots + 1, u, data, P), Status::invalid_argument);
  const double bad[n] = {0.0, 1.0, 0.5};
  EXPECT_EQ(make_hermite_spline(K, n, bad, data, P), Status::bad_domain);
}

// A two-piece ringed blend from cone A through the waist circle of a guide
// cylinder (axis (1, 0, 1) through (1.2, 0, 2.8), radius 1) to cone B: the
// pieces share the guide's circle at t = 1/2 and join C^K there (circle
// family and the generator point), each is G^K to the guide and the outer
// pieces to the cones.
TEST(RingedBlend, SplineThroughAGuideCircle) {
  const Surface A = cone1(), B = cone2(), G = guide_cylinder();
  for (int K = 1; K <= 2; ++K) {
    BlendEnd ends[3];
    guide_ends(A, G, B, ends);
    const double knots[3] = {0.0, 0.5, 1.0};
    Surface piece[2];
    Surface* const pieces[2] = {&piece[0], &piece[1]};
    int bad_piece = -1;
    ASSERT_EQ(make_ringed_blend_spline(ends, 3, K, knots, pieces, &bad_piece), Status::ok);
    // The pieces join each other C^K at t = 1/2.
    ContinuityReport R;
    ASSERT_EQ(continuity_report(piece[0], 0.5, 1.0, piece[1], 0.5, K, nullptr, 32, R),
              Status::ok);
    EXPECT_LE(R.max_gap, 1e-12 * R.point_scale);
    EXPECT_LE(R.max_normal_angle, 1e-9);
    for (int l = 0; l <= K; ++l) EXPECT_LE(R.circle_jump[l], 1e-9) << K << " " << l;
    const double vg = HUGE_VAL;
    ASSERT_EQ(continuity_report(piece[0], 0.5, 1.0, piece[1], 0.5, K, &vg, 1, R), Status::ok);
    for (int l = 0; l <= K; ++l)
      EXPECT_LE(R.point_jump[l], 1e-9 * std::max(R.point_scale_l[l], R.point_scale)) << l;
    // Each piece meets the guide G^K (its jet) and the cones.
    double jet[kMaxBlendOrder] = {2.0};
    for (int p = 0; p < 2; ++p) {
      ASSERT_EQ(continuity_report(G, 0.5, jet, piece[p], 0.5, K, nullptr, 32, R), Status::ok);
      EXPECT_LE(R.max_gap, 1e-12 * R.point_scale);
      for (int l = 0; l <= K; ++l) EXPECT_LE(R.circle_jump[l], 1e-9) << p << " " << l;
    }
    ASSERT_EQ(continuity_report(A, 1.0, 1.0, piece[0], 0.0, K, nullptr, 32, R), Status::ok);
    for (int l = 0; l <= K; ++l) EXPECT_LE(R.circle_jump[l], 1e-9);
    ASSERT_EQ(continuity_report(B, 1.0, -1.0, piece[1], 1.0, K, nullptr, 32, R), Status::ok);
    for (int l = 0; l <= K; ++l) EXPECT_LE(R.circle_jump[l], 1e-9);
    // An interior end needs its direction.
    ends[1].lambda = 0.0;
    EXPECT_EQ(make_ringed_blend_spline(ends, 3, K, knots, pieces), Status::invalid_argument);
    EXPECT_EQ(make_ringed_blend_spline(ends, 1, K, knots, pieces), Status::invalid_argument);
    // A failing piece is named (the second: its knots are reversed).
    ends[1].lambda = 2.0;
    const double bad_knots[3] = {0.0, 0.5, 0.25};
    EXPECT_EQ(make_ringed_blend_spline(ends, 3, K, bad_knots, pieces, &bad_piece),
              Status::bad_domain);
    EXPECT_EQ(bad_piece, 1);
  }
}

TEST(CanalBlend, K2IsG1) {
  const Surface A = cone1(), B = cone2();
  for (int K = 2; K <= 3; ++K) {
    BlendEnd s, e;
    s.surface = &A;
    s.u = 1.0;
    e.surface = &B;
    e.u = 1.0;
    s.v[0] = e.v[0] = HUGE_VAL;
    s.v[1] = e.v[1] = 0.3;
    Surface X;
    double bad = -1;
    ASSERT_EQ(make_canal_blend(s, e, K, 0.0, 1.0, X, &bad), Status::ok) << bad;
    const double lam[2] = {1.0, -1.0};
    const Surface* in[2] = {&A, &B};
    for (int i = 0; i < 2; ++i) {
      ContinuityReport R;
      ASSERT_EQ(continuity_report(*in[i], 1.0, lam[i], X, double(i), K, nullptr, 64, R),
                Status::ok);
      EXPECT_LE(R.max_gap, 1e-12 * R.point_scale) << K;
      EXPECT_LE(R.max_normal_angle, 1e-9) << K;  // G^1 (Prop. 6)
      EXPECT_LE(R.circle_jump[0], 1e-9);
    }
    double res = 1;
    ASSERT_EQ(X.canal_test(res), Status::ok);
    EXPECT_LT(res, 1e-9);
  }
}

// The weakness of §9.1: two coaxial cylinders and antipodal points give
// normal planes M, N that coincide (p1' = p2' along the axis).
TEST(CanalBlend, ParallelPlanesReported) {
  RationalCurve L[3], M[3];
  for (int k = 0; k < 3; ++k) {
    const double t = 2 * kPi * k / 3;
    ASSERT_EQ(make_line({std::cos(t), std::sin(t), 0}, {0, 0, 1}, L[k]), Status::ok);
    ASSERT_EQ(make_line({std::cos(t), std::sin(t), 3}, {0, 0, 1}, M[k]), Status::ok);
  }
  Surface A, B;
  ASSERT_EQ(make_prrs(L[0], L[1], L[2], nullptr, 0.0, 1.0, A), Status::ok);
  ASSERT_EQ(make_prrs(M[0], M[1], M[2], nullptr, 0.0, 1.0, B), Status::ok);
  double va = 0, vb = 0;
  ASSERT_EQ(A.parameter_of(1.0, Vec3d(-1, 0, 1), va), Status::ok);
  ASSERT_EQ(B.parameter_of(0.0, Vec3d(-1, 0, 3), vb), Status::ok);
  BlendEnd s, e;
  s.surface = &A;
  s.u = 1.0;
  s.v[0] = HUGE_VAL;
  s.v[1] = va;
  e.surface = &B;
  e.u = 0.0;
  e.v[0] = HUGE_VAL;
  e.v[1] = vb;
  Surface X, untouched;
  untouched.u1 = 42;
  X = untouched;
  double bad = -1;
  EXPECT_EQ(make_canal_blend(s, e, 2, 0.0, 1.0, X, &bad), Status::dependent_planes);
  EXPECT_GE(bad, 0.0);
  EXPECT_LE(bad, 1.0);
  EXPECT_EQ(X.u1, 42);
  // The ringed blend of the same data is fine (a cylinder piece).
  s.v[2] = e.v[2] = 0.5;
  Surface Y;
  EXPECT_EQ(make_ringed_blend(s, e, 2, 0.0, 1.0, Y), Status::ok);
}

TEST(Blend, Validation) {
  const Surface A = cone1(), B = cone2();
  BlendEnd s, e;
  s.surface = &A;
  s.u = 1.0;
  e.surface = &B;
  e.u = 1.0;
  s.v[1] = e.v[1] = 0.5;
  s.v[2] = e.v[2] = -0.5;
  Surface X;
  EXPECT_EQ(make_canal_blend(s, e, 1, 0, 1, X), Status::invalid_argument);
  EXPECT_EQ(make_ringed_blend(s, e, 0, 0, 1, X), Status::invalid_argument);
  EXPECT_EQ(make_ringed_blend(s, e, kMaxBlendOrder + 1, 0, 1, X), Status::degree_too_high);
  EXPECT_EQ(make_ringed_blend(s, e, 1, 1, 0, X), Status::bad_domain);
  BlendEnd n = s;
  n.surface = nullptr;
  EXPECT_EQ(make_ringed_blend(n, e, 1, 0, 1, X), Status::null_argument);
  n = s;
  n.v[1] = NAN;
  EXPECT_EQ(make_ringed_blend(n, e, 1, 0, 1, X), Status::not_finite);
  // Three points of which two coincide: the PRRS planes are dependent.
  n = s;
  n.v[2] = n.v[1];
  EXPECT_NE(make_ringed_blend(n, e, 1, 0, 1, X), Status::ok);
  ContinuityReport R;
  EXPECT_EQ(continuity_report(A, 1, 1, B, 1, -1, nullptr, 4, R), Status::invalid_argument);
  EXPECT_EQ(continuity_report(A, 1, 1, B, 1, 1, nullptr, 0, R), Status::invalid_argument);
  EXPECT_EQ(continuity_report(A, 1, 1, B, 1, 8, nullptr, 4, R), Status::degree_too_high);
}

// fuzz_blend regress-continuity-huge-lambda: lambda = 1e90 with K = 2 made
// |lambda^2 x_uu| ~ 1e180, whose norm overflowed: continuity_report returned
// ok with point_jump / point_scale_l = inf. Non-finite measures are now
// numerical_overflow (and `out` is untouched).
TEST(Blend, RegressionContinuityReportHugeLambdaOverflows) {
  const Surface A = cone1();
  const double va[2] = {0.0, 1.0};
  ContinuityReport R;
  R.max_gap = 42;
  EXPECT_EQ(continuity_report(A, 1.0, 1e90, A, 1.0, 2, va, 2, R), Status::numerical_overflow);
  EXPECT_EQ(continuity_report(A, 1.0, -1e80, A, 1.0, 2, va, 2, R), Status::numerical_overflow);
  EXPECT_EQ(R.max_gap, 42);
  // A large but representable lambda still gives finite measures.
  ASSERT_EQ(continuity_report(A, 1.0, 1e20, A, 1.0, 2, va, 2, R), Status::ok);
  for (int l = 0; l <= 2; ++l) {
    EXPECT_TRUE(std::isfinite(R.point_jump[l])) << l;
    EXPECT_TRUE(std::isfinite(R.point_scale_l[l])) << l;
    EXPECT_TRUE(std::isfinite(R.circle_jump[l])) << l;
  }
}

// fuzz_blend regress-blend-huge-lambda: lambda = 1e60 with K = 2 puts
// lambda^2 x_uu ~ 1e120 beyond the Hermite solve's input range; the blend
// reported not_finite ("an input is NaN, infinite or larger than 1e100")
// although every input was valid. Now numerical_overflow.
TEST(Blend, RegressionHugeLambdaIsOverflowNotNonFiniteInput) {
  const Surface A = cone1(), B = cone2();
  BlendEnd s, e;
  s.surface = &A;
  s.u = 1.0;
  s.lambda = 1e60;
  e.surface = &B;
  e.u = 1.0;
  const double vs[3] = {HUGE_VAL, -0.5, 0.7};
  for (int j = 0; j < 3; ++j) s.v[j] = e.v[j] = vs[j];
  Surface X;
  X.u1 = 42;
  EXPECT_EQ(make_ringed_blend(s, e, 2, 0.0, 1.0, X), Status::numerical_overflow);
  EXPECT_EQ(make_canal_blend(s, e, 3, 0.0, 1.0, X), Status::numerical_overflow);
  EXPECT_EQ(X.u1, 42);
  s.lambda = 1e30;  // 1e60 at K = 2: still representable, fine
  EXPECT_NE(make_ringed_blend(s, e, 2, 0.0, 1.0, X), Status::not_finite);
  // regress-blend-huge-interval: t1 = 2^192 (a valid input): the power-form
  // Hermite coefficients leave the range; numerical_overflow, not not_finite.
  s.lambda = 0;
  EXPECT_EQ(make_ringed_blend(s, e, 2, 1.0, std::ldexp(1.0, 192), X), Status::numerical_overflow);
  EXPECT_EQ(X.u1, 42);
}

// Prop. 7 with the inputs' own circle parameterization (BlendCircles::
// matched): f(t, v) Hermite-interpolates the Mobius maps between the
// inputs' and the blend's circle parameters, so x(t, v) continues
// x(phi(u), v) to order K for every v (point_jump, not only circle_jump),
// on the same circles as the generator blend.
TEST(RingedBlend, MatchedCirclesAreCKForEveryV) {
  const Surface A = cone1(), B = cone2();
  for (int K = 1; K <= 3; ++K) {
    BlendEnd s, e;
    s.surface = &A;
    s.u = 1.0;
    e.surface = &B;
    e.u = 1.0;
    const double vs[3] = {HUGE_VAL, -0.5, 0.7};
    for (int j = 0; j < 3; ++j) s.v[j] = e.v[j] = vs[j];
    e.phi[0] = 0.4;  // a non-trivial jet at the end
    Surface G, M;
    ASSERT_EQ(make_ringed_blend(s, e, K, 0.0, 1.0, G), Status::ok);
    double bad = -1;
    ASSERT_EQ(make_ringed_blend(s, e, K, 0.0, 1.0, M, &bad, nullptr, BlendCircles::matched),
              Status::ok)
        << K << " " << bad;
    EXPECT_FALSE(M.f_constant);
    EXPECT_EQ(M.f.alpha.deg, 2 * K + 1);
    double jet_s[kMaxBlendOrder] = {}, jet_e[kMaxBlendOrder] = {};
    blend_jet(s, 0, K, jet_s);
    blend_jet(e, 1, K, jet_e);
    struct Join {
      const Surface* S;
      double u;
      const double* jet;
      double t;
    } joins[2] = {{&A, 1.0, jet_s, 0.0}, {&B, 1.0, jet_e, 1.0}};
    for (const Join& J : joins) {
      ContinuityReport R, RG;
      ASSERT_EQ(continuity_report(*J.S, J.u, J.jet, M, J.t, K, nullptr, 64, R), Status::ok);
      ASSERT_EQ(continuity_report(*J.S, J.u, J.jet, G, J.t, K, nullptr, 64, RG), Status::ok);
      EXPECT_LE(R.max_gap, 1e-12 * R.point_scale);
      EXPECT_LE(R.max_normal_angle, 1e-9);
      for (int l = 0; l <= K; ++l) {
        EXPECT_LE(R.circle_jump[l], 1e-9) << "K " << K << " l " << l;
        EXPECT_LE(R.point_jump[l], 1e-9 * std::max(R.point_scale_l[l], R.point_scale))
            << "K " << K << " l " << l;
      }
      // The generator blend is C^K only in its circles: away from v[0] its
      // parameterization jumps at order 1 already.
      EXPECT_GT(RG.point_jump[1], 1e-3 * std::max(RG.point_scale_l[1], RG.point_scale));
      // Order K+1 is generically not continuous.
      if (K < kMaxBlendOrder) {
        ContinuityReport H;
        ASSERT_EQ(continuity_report(*J.S, J.u, J.jet, M, J.t, K + 1, nullptr, 16, H),
                  Status::ok);
        EXPECT_GT(H.point_jump[K + 1], 1e-6 * std::max(H.point_scale_l[K + 1], H.point_scale));
      }
    }
    // Same surface: every point of M lies on G's circle at the same t.
    for (double t : {0.0, 0.2, 0.5, 0.8, 1.0})
      for (double v : {-4.0, -1.0, 0.0, 0.3, 2.0}) {
        double x[3];
        EvalOut o;
        o.point = x;
        ASSERT_EQ(M.eval(t, v, o), Status::ok);
        Vec3d c, nrm;
        double r2;
        ASSERT_EQ(G.circle(t, c, nrm, r2), Status::ok);
        const Vec3d X(x[0], x[1], x[2]);
        EXPECT_LE(std::abs((X - c).squaredNorm() - r2), 1e-11 * r2) << t << " " << v;
        EXPECT_LE(std::abs((X - c).dot(nrm)), 1e-11 * std::sqrt(r2)) << t << " " << v;
      }
  }
}

// B reparameterized by v -> -v and its points chosen at the mirrored
// parameters: the same points, so the same generator blend, but B's
// parameter now runs the circles in the opposite sense relative to the
// blend's: no Mobius family joins the two end maps without degenerating,
// which is reported.
TEST(RingedBlend, MatchedCirclesOppositeSensesReported) {
  const Surface A = cone1();
  Surface B = cone2();
  Mobius flip;
  flip.alpha = MobiusPoly(-1.0);
  Surface Bf;
  ASSERT_EQ(make_prrs(B.curve[0], B.curve[1], B.curve[2], &flip, B.u0, B.u1, Bf), Status::ok);
  BlendEnd s, e;
  s.surface = &A;
  s.u = 1.0;
  e.surface = &Bf;
  e.u = 1.0;
  const double vs[3] = {HUGE_VAL, -0.5, 0.5};
  for (int j = 0; j < 3; ++j) {
    s.v[j] = vs[j];
    e.v[j] = -vs[j];
  }
  Surface X;
  X.u0 = -7;
  double bad = -1;
  EXPECT_EQ(make_ringed_blend(s, e, 1, 0.0, 1.0, X, &bad, nullptr, BlendCircles::matched),
            Status::degenerate_circle_parameter);
  EXPECT_EQ(bad, 1.0);
  EXPECT_EQ(X.u0, -7);  // untouched
  EXPECT_EQ(make_ringed_blend(s, e, 1, 0.0, 1.0, X), Status::ok);
  // With B's own parameterization the same points are matched.
  BlendEnd e2 = e;
  e2.surface = &B;
  for (int j = 0; j < 3; ++j) e2.v[j] = vs[j];
  EXPECT_EQ(make_ringed_blend(s, e2, 1, 0.0, 1.0, X, &bad, nullptr, BlendCircles::matched),
            Status::ok);
  EXPECT_EQ(make_ringed_blend(s, e, 1, 0.0, 1.0, X, &bad, nullptr, BlendCircles(7)),
            Status::invalid_argument);
}

// Matched spline blends: every piece continues its neighbours' and the
// guide's parameterization to order K for every v.
TEST(RingedBlend, MatchedSplineThroughAGuideCircle) {
  const Surface A = cone1(), B = cone2(), Gd = guide_cylinder();
  for (int K = 1; K <= 2; ++K) {
    BlendEnd ends[3];
    guide_ends(A, Gd, B, ends);
    const double knots[3] = {0.0, 0.5, 1.0};
    Surface piece[2];
    Surface* const pieces[2] = {&piece[0], &piece[1]};
    int bad_piece = -1;
    double bad_u = -1;
    ASSERT_EQ(make_ringed_blend_spline(ends, 3, K, knots, pieces, &bad_piece, &bad_u,
                                       BlendCircles::matched),
              Status::ok)
        << bad_piece << " " << bad_u;
    ContinuityReport R;
    ASSERT_EQ(continuity_report(piece[0], 0.5, 1.0, piece[1], 0.5, K, nullptr, 32, R),
              Status::ok);
    for (int l = 0; l <= K; ++l)
      EXPECT_LE(R.point_jump[l], 1e-9 * std::max(R.point_scale_l[l], R.point_scale)) << l;
    double jet[kMaxBlendOrder] = {2.0};
    for (int p = 0; p < 2; ++p) {
      ASSERT_EQ(continuity_report(Gd, 0.5, jet, piece[p], 0.5, K, nullptr, 32, R), Status::ok);
      for (int l = 0; l <= K; ++l)
        EXPECT_LE(R.point_jump[l], 1e-9 * std::max(R.point_scale_l[l], R.point_scale))
            << p << " " << l;
    }
  }
}
