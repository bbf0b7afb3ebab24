// Seed 001 (ringed surfaces (d, n, rho)), labels "paper;ringed": P-curves
// and their perpendicular companions (8)-(11), the spherical curves (12) and
// (15), the curve c = d + rho f (4) and the parameterization (3), planar
// P-curve Hermite interpolation (43) and P-biarcs (47), and the two-surface
// blend of §4 on Example 4.1 (the derived numbers of the transcription).

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cyclide/blend.hpp"
#include "cyclide/contour.hpp"
#include "cyclide/pcurve.hpp"
#include "seed001_data.hpp"
#include "cyclide/ringed.hpp"

using namespace cyclide;

namespace {

CurvePoly poly(std::initializer_list<double> c) {
  CurvePoly p;
  p.assign(c.begin(), int(c.size()) - 1);
  return p;
}

Vec3d eval3(const CurvePoly (&P)[3], double t) { return Vec3d(P[0](t), P[1](t), P[2](t)); }

Vec3d point(const Surface& S, double u, double v) {
  double x[3];
  EvalOut o;
  o.point = x;
  EXPECT_EQ(S.eval(u, v, o), Status::ok);
  return Vec3d(x[0], x[1], x[2]);
}

// Example 4.1's Hermite data (37) at R1(1) and R2(0) (transcription notes).
RingedJet example41_start() {
  RingedJet J;
  J.d = Vec3d(-4, -3, 1);
  J.dd = Vec3d(2, 4, 3);
  J.rho = 1.25;
  J.drho = 0.5;
  J.n = Vec3d(1, 1, 1);
  J.dn = Vec3d(0, 1, 1);
  return J;
}
RingedJet example41_end() {
  RingedJet J;
  J.d = Vec3d(0, 0, 0);
  J.dd = Vec3d(3, 1, 1);
  J.rho = 2;
  J.drho = 1;
  J.n = Vec3d(4, 0, 0);
  J.dn = Vec3d(0, 1, 1);
  return J;
}

}  // namespace

// (8)-(11): |n| = |n1| = |n2| = sigma, pairwise orthogonal, det = sigma^3
// (transcription note 1), for a cubic quaternion polynomial.
TEST(PCurve, FrameIdentities) {
  const CurvePoly x[4] = {poly({1, 0.5, -0.25}), poly({0, 1, 0, 0.5}), poly({-1, 0.25}),
                          poly({0.5, 0, 1})};
  PCurveFrame P;
  ASSERT_EQ(pcurve_frame(x, P), Status::ok);
  EXPECT_EQ(P.sigma.deg, 6);
  for (double t : {-1.5, -0.3, 0.0, 0.7, 2.0}) {
    const Vec3d n = eval3(P.n, t), a = eval3(P.n1, t), b = eval3(P.n2, t);
    const double s = P.sigma(t), tol = 1e-13 * s * s;
    EXPECT_NEAR(n.squaredNorm(), s * s, tol);
    EXPECT_NEAR(a.squaredNorm(), s * s, tol);
    EXPECT_NEAR(b.squaredNorm(), s * s, tol);
    EXPECT_NEAR(n.dot(a), 0, tol);
    EXPECT_NEAR(n.dot(b), 0, tol);
    EXPECT_NEAR(a.dot(b), 0, tol);
    EXPECT_NEAR(n.dot(a.cross(b)), s * s * s, 1e-13 * s * s * s);
  }
  CurvePoly big[4] = {poly({0, 0, 0, 0, 0, 0, 0, 0, 1}), CurvePoly(), CurvePoly(), CurvePoly()};
  EXPECT_EQ(pcurve_frame(big, P), Status::degree_too_high);
  CurvePoly zero[4];
  EXPECT_EQ(pcurve_frame(zero, P), Status::invalid_argument);
}

// Prop. 3.1: n a spatial P-curve, f by (12), c by (4): the parameterization
// (3) is rational and every point is at distance rho from d in the plane
// through d perpendicular to n.
TEST(PCurve, Proposition31RingedSurface) {
  const CurvePoly x[4] = {poly({1, 0.5}), poly({0, 1}), poly({0.5, 0, 0.25}), poly({0.25, -0.5})};
  PCurveFrame P;
  ASSERT_EQ(pcurve_frame(x, P), Status::ok);
  RationalCurve d, n, c;
  const double dc[12] = {0, 0, 0, 1, 0.5, 0, 0, 0.25, 1, 0, 0, 0.125};
  ASSERT_EQ(make_polynomial_curve(3, dc, d), Status::ok);
  double nc[3 * 5] = {};
  for (int k = 0; k <= 4; ++k)
    for (int j = 0; j < 3; ++j) nc[3 * k + j] = P.n[j].c[k];
  ASSERT_EQ(make_polynomial_curve(4, nc, n), Status::ok);
  const CurvePoly rho = poly({1, 0.25, 0.125});
  ASSERT_EQ(ringed_curve(d, rho, CurvePoly(1.0), pcurve_field(P, 0.7), c), Status::ok);
  Surface S;
  ASSERT_EQ(make_ringed(d, n, c, nullptr, -1.0, 1.0, S), Status::ok);
  EXPECT_EQ(S.kind, SurfaceKind::ringed);
  for (double t : {-1.0, -0.4, 0.3, 1.0})
    for (double v : {-3.0, -0.5, 0.0, 1.0, 1e300}) {
      const Vec3d X = point(S, t, v), D = d.point(t), N = n.point(t);
      EXPECT_NEAR((X - D).norm(), rho(t), 1e-12 * (1 + rho(t)));
      EXPECT_NEAR((X - D).dot(N), 0, 1e-12 * N.norm() * (1 + rho(t)));
    }
  // The circle of the surface is (d, n, rho).
  Vec3d center, un;
  double r2;
  ASSERT_EQ(S.circle(0.3, center, un, r2), Status::ok);
  EXPECT_LT((center - d.point(0.3)).norm(), 1e-13);
  EXPECT_NEAR(r2, rho(0.3) * rho(0.3), 1e-13);
}

// Prop. 3.2 on R1 of Example 4.1 (48): n1 = (1, t, t), v = (0, 1, 1)/sqrt 2:
// |n|^2 - (n.v)^2 = 1 (eq. (14)), f = n x v (15) is constant. With v = e1
// the remainder 2 t^2 is a square too; with v = e3 (1 + t^2) it is not.
TEST(PCurve, Proposition32Projection) {
  RationalCurve n;
  const double nc[6] = {1, 0, 0, 0, 1, 1};
  ASSERT_EQ(make_polynomial_curve(1, nc, n), Status::ok);
  RationalField f;
  const Vec3d v = Vec3d(0, 1, 1).normalized();
  ASSERT_EQ(projection_field(n, v, f), Status::ok);
  EXPECT_EQ(f.w.deg, 0);
  for (double t : {-2.0, 0.0, 0.5, 3.0}) {
    const Vec3d F = eval3(f.F, t) / f.w(t), N = n.point(t);
    EXPECT_NEAR(F.norm(), 1.0, 1e-14);
    EXPECT_NEAR(F.dot(N), 0.0, 1e-14);
  }
  EXPECT_EQ(projection_field(n, Vec3d::UnitX(), f), Status::ok);
  EXPECT_EQ(f.w.deg, 1);
  EXPECT_EQ(projection_field(n, Vec3d::UnitZ(), f), Status::not_pythagorean);
  EXPECT_EQ(projection_field(n, Vec3d(0, 0, 2), f), Status::invalid_argument);
  CurvePoly q;
  double res = -1;
  EXPECT_TRUE(poly_sqrt(poly({4, -4, 1}), q, 1e-12, &res));  // (t - 2)^2
  EXPECT_EQ(q.deg, 1);
  EXPECT_NEAR(q.c[1], 1, 1e-15);
  EXPECT_NEAR(q.c[0], -2, 1e-15);
  EXPECT_FALSE(poly_sqrt(poly({1, 0, 2, 0, 1.5}), q, 1e-12, &res));
  EXPECT_GT(res, 1e-3);
  EXPECT_FALSE(poly_sqrt(poly({1, 2, -1}), q));  // negative leading coefficient
  EXPECT_FALSE(poly_sqrt(poly({1, 2}), q));      // odd degree
}

// |f| = 1 and f.n = 0 of a rational field at sample parameters.
void expect_unit_perpendicular(const RationalField& f, const RationalCurve& n, double tol) {
  for (double t : {-3.0, -1.0, -0.25, 0.0, 0.5, 1.0, 2.0, 7.0}) {
    const Vec3d F = eval3(f.F, t) / f.w(t), N = n.point(t);
    EXPECT_NEAR(F.norm(), 1.0, tol) << "t = " << t;
    EXPECT_NEAR(F.dot(N) / N.norm(), 0.0, tol) << "t = " << t;
  }
}

// Example 3.3, eqs. (17)-(19): for a quadratic n with independent
// coefficient vectors no coordinate direction makes |n x v| a polynomial,
// but two directions v (the real solutions of (19) the paper proves to
// exist) do, and Prop. 3.2 then gives an exact unit field f = n x v / sigma.
TEST(PCurve, Example33QuadraticOrientation) {
  RationalCurve n;
  // n(t) = (1, 0, 0) t^2 + (0, 2, 1) t + (0.5, -1, 3): rows t^0, t^1, t^2.
  const double nc[9] = {0.5, -1, 3, 0, 2, 1, 1, 0, 0};
  ASSERT_EQ(make_polynomial_curve(2, nc, n), Status::ok);
  RationalField f;
  for (const Vec3d& e : {Vec3d(1, 0, 0), Vec3d(0, 1, 0), Vec3d(0, 0, 1)})
    EXPECT_EQ(projection_field(n, e, f), Status::not_pythagorean);
  Vec3d v[2];
  int count = 0;
  ASSERT_EQ(quadratic_projection_directions(n, v, count), Status::ok);
  EXPECT_EQ(count, 2);
  EXPECT_LT(std::abs(v[0].dot(v[1])), 1 - 1e-6);  // two different planes
  for (int i = 0; i < count; ++i) {
    EXPECT_NEAR(v[i].norm(), 1.0, 1e-15);
    ASSERT_EQ(projection_field(n, v[i], f), Status::ok);
    EXPECT_EQ(f.w.deg, 2);  // sigma = |A| |t - r|^2
    expect_unit_perpendicular(f, n, 1e-12);
  }
  // The ringed surface (d, n, rho) with this f is rational (Prop. 3.2):
  // every point lies on its circle.
  RationalCurve d, c, line;
  const double dc[6] = {0, 0, 0, 1, 2, -1};
  ASSERT_EQ(make_polynomial_curve(1, dc, d), Status::ok);
  ASSERT_EQ(projection_field(n, v[0], f), Status::ok);
  ASSERT_EQ(ringed_curve(d, poly({1.5, 0.25}), poly({1.0}), f, c), Status::ok);
  Surface S;
  ASSERT_EQ(make_ringed(d, n, c, nullptr, -1, 2, S), Status::ok);
  for (double t : {-1.0, 0.3, 2.0})
    for (double u : {-2.0, 0.0, 0.7, 40.0}) {
      const Vec3d X = point(S, t, u), D = d.point(t), N = n.point(t).normalized();
      EXPECT_NEAR((X - D).norm(), 1.5 + 0.25 * t, 1e-12);
      EXPECT_NEAR((X - D).dot(N), 0.0, 1e-12);
    }
  // Degenerate inputs: cubic n, a rational n, a point.
  const double cub[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
  ASSERT_EQ(make_polynomial_curve(3, cub, line), Status::ok);
  EXPECT_EQ(quadratic_projection_directions(line, v, count), Status::invalid_argument);
  ASSERT_EQ(make_point(Vec3d(1, 2, 3), line), Status::ok);
  EXPECT_EQ(quadratic_projection_directions(line, v, count), Status::invalid_argument);
  // A constant n: any direction perpendicular to it.
  const double k[3] = {0, 0, 2};
  ASSERT_EQ(make_polynomial_curve(0, k, line), Status::ok);
  ASSERT_EQ(quadratic_projection_directions(line, v, count), Status::ok);
  EXPECT_EQ(count, 1);
  EXPECT_NEAR(v[0].z(), 0.0, 1e-15);
}

// Eqs. (20)-(23): the stereographic field with a numerical sum of squares
// |n|^2 = g1^2 + g2^2 (21) for a cubic n that is neither a P-curve nor has
// a P-curve projection; f is a unit field perpendicular to n to the
// reported remainder. A horizontal n (n3 = 0: the pole (0, 0, 1) lies on
// every circle, Remark 3.4) takes another pole.
TEST(PCurve, Equations20To23SosField) {
  RationalCurve n;
  const double nc[12] = {1, -2, 0.5, 0, 1, 3, 2, 0, -1, 0.5, 1, 0.25};
  ASSERT_EQ(make_polynomial_curve(3, nc, n), Status::ok);
  RationalField f;
  SosFieldReport rep;
  ASSERT_EQ(sos_field(n, f, &rep), Status::ok);
  EXPECT_LT(rep.residual, 1e-13);
  EXPECT_GT(rep.margin, 1e-3);
  EXPECT_EQ(f.w.deg, 6);
  expect_unit_perpendicular(f, n, 1e-12);
  // The denominator |H|^2 + n3^2 has no real root.
  for (int k = -200; k <= 200; ++k) EXPECT_GT(f.w(k / 20.0), 0.0);
  // The rational ringed surface (Theorem 3.5).
  RationalCurve d, c;
  const double dc[6] = {1, 1, 1, 0, 0, 1};
  ASSERT_EQ(make_polynomial_curve(1, dc, d), Status::ok);
  ASSERT_EQ(ringed_curve(d, poly({2.0}), poly({1.0}), f, c), Status::ok);
  Surface S;
  ASSERT_EQ(make_ringed(d, n, c, nullptr, -2, 2, S), Status::ok);
  for (double t : {-2.0, 0.1, 1.7})
    for (double u : {-1.0, 0.0, 3.0}) {
      const Vec3d X = point(S, t, u), D = d.point(t), N = n.point(t).normalized();
      EXPECT_NEAR((X - D).norm(), 2.0, 1e-11);
      EXPECT_NEAR((X - D).dot(N), 0.0, 1e-11);
    }
  // n3 = 0: the z pole is skipped.
  const double hc[9] = {1, 0, 0, 0, 1, 0, 1, 1, 0};
  RationalCurve h;
  ASSERT_EQ(make_polynomial_curve(2, hc, h), Status::ok);
  ASSERT_EQ(sos_field(h, f, &rep), Status::ok);
  EXPECT_NE(rep.pole_axis, 2);
  expect_unit_perpendicular(f, h, 1e-12);
  // Statuses.
  const double zero[3] = {0, 0, 0};
  ASSERT_EQ(make_polynomial_curve(0, zero, h), Status::ok);
  EXPECT_EQ(sos_field(h, f, &rep), Status::invalid_argument);
  double big[3 * 9] = {};
  big[3 * 8] = 1;
  ASSERT_EQ(make_polynomial_curve(8, big, h), Status::ok);
  EXPECT_EQ(sos_field(h, f, &rep), Status::degree_too_high);
}

// Eq. (43) on Example 4.1's planar data (39): p0 = 1 + i, v0 = i, p1 = 4,
// v1 = i, principal roots, + sign; and x = w^2, sigma = |w|^2.
TEST(PCurve, Equation43Example41) {
  const Complex p0(1, 1), v0(0, 1), p1(4, 0), v1(0, 1);
  PlanarPCurve P;
  ASSERT_EQ(planar_pcurve_hermite(p0, v0, p1, v1, 1, P), Status::ok);
  EXPECT_NEAR(std::abs(P.w[0] - Complex(1.09868411347, 0.455089860562)), 0, 1e-11);
  EXPECT_NEAR(std::abs(P.w[1] - Complex(1.15231696788, 0.584571025065)), 0, 1e-11);
  EXPECT_NEAR(std::abs(P.w[2] - Complex(2, -1.0 / 12)), 0, 1e-14);
  EXPECT_NEAR(std::abs(P.w[3] - Complex(2, 0)), 0, 1e-14);
  CurvePoly x1, x2, sigma;
  planar_pcurve_polys(P, x1, x2, sigma);
  // Coefficients from t^0 up (the notes list them from t^6 down).
  const double n1[7] = {1, 0, 7.286754292, -2.392013333, -1.779182139, -0.4126128915,
                        0.2970540714};
  const double n2[7] = {1, 1, -2.963263730, 2.989495813, -12.17405276, 15.23267300,
                        -5.084852322};
  const double sg[7] = {1.414213562, 0.7071067812, 3.233946190, -3.289833060, 12.07185441,
                        -15.23080967, 5.093521793};
  for (int k = 0; k <= 6; ++k) {
    EXPECT_NEAR(x1.c[k], n1[k], 2e-9) << k;
    EXPECT_NEAR(x2.c[k], n2[k], 2e-8) << k;
    EXPECT_NEAR(sigma.c[k], sg[k], 2e-8) << k;
  }
  // The Hermite conditions (42) and |x| = sigma.
  EXPECT_NEAR(x1(0.0), 1, 1e-14);
  EXPECT_NEAR(x2(0.0), 1, 1e-14);
  EXPECT_NEAR(x1.derivative()(0.0), 0, 1e-13);
  EXPECT_NEAR(x2.derivative()(0.0), 1, 1e-13);
  EXPECT_NEAR(x1(1.0), 4, 1e-12);
  EXPECT_NEAR(x2(1.0), 0, 1e-12);
  EXPECT_NEAR(x1.derivative()(1.0), 0, 1e-11);
  EXPECT_NEAR(x2.derivative()(1.0), 1, 1e-11);
  for (double t : {0.1, 0.5, 0.9})
    EXPECT_NEAR(std::hypot(x1(t), x2(t)), sigma(t), 1e-12 * sigma(t));
  EXPECT_NEAR(x1(0.5), 2.403235340, 1e-9);
  EXPECT_NEAR(x2(0.5), 0.7685629604, 1e-9);
  EXPECT_NEAR(sigma(0.5), 2.523138744, 1e-9);
  EXPECT_EQ(planar_pcurve_hermite(Complex(0, 0), v0, p1, v1, 1, P), Status::not_pythagorean);
  EXPECT_EQ(planar_pcurve_hermite(p0, v0, p1, v1, 0, P), Status::invalid_argument);
}

// Eq. (47), P-biarc at tau = 1/2 on the same data: the transcription's w_i
// and the C^1 join x1(1/2) = x2(1/2), x1'(1/2) = x2'(1/2) (46).
TEST(PCurve, Equation47BiarcExample41) {
  const Complex p0(1, 1), v0(0, 1), p1(4, 0), v1(0, 1);
  PlanarPCurve B[2];
  ASSERT_EQ(planar_pbiarc(p0, v0, p1, v1, 0.5, 1, B), Status::ok);
  const Complex w[6] = {{1.098684113, 0.4550898606}, {1.179133395, 0.6493116073},
                        {2.820866605, -0.7743116073}, {0.2778175085, 1.229401468},
                        {2, -0.125},                  {2, 0}};
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(std::abs(B[i / 3].w[i % 3] - w[i]), 0, 1e-9) << i;
  CurvePoly a1, a2, as, b1, b2, bs;
  planar_pcurve_polys(B[0], a1, a2, as);
  planar_pcurve_polys(B[1], b1, b2, bs);
  EXPECT_NEAR(a1(0.5), 2.40323534, 1e-8);
  EXPECT_NEAR(a2(0.5), 0.7685629604, 1e-9);
  EXPECT_NEAR(b1(0.5), a1(0.5), 1e-12);
  EXPECT_NEAR(b2(0.5), a2(0.5), 1e-12);
  EXPECT_NEAR(a1.derivative()(0.5), 6.0078125, 1e-9);
  EXPECT_NEAR(a2.derivative()(0.5), -3.015625, 1e-9);
  EXPECT_NEAR(b1.derivative()(0.5), 6.0078125, 1e-9);
  EXPECT_NEAR(b2.derivative()(0.5), -3.015625, 1e-9);
  EXPECT_NEAR(b1(1.0), 4, 1e-12);
  EXPECT_NEAR(b2.derivative()(1.0), 1, 1e-11);
  EXPECT_EQ(planar_pbiarc(p0, v0, p1, v1, 1.0, 1, B), Status::bad_domain);
  EXPECT_EQ(planar_pbiarc(p0, v0, Complex(0, 0), v1, 0.5, 1, B), Status::not_pythagorean);
}

// Example 4.1 (§4): Ferguson cubics for (d, n3, rho) (38), the degree-6
// P-curve for (n1, n2) (39), f = (n2, -n1, 0)/sigma, c = d + rho f and the
// parameterization (3) with phi = u: the transcription's values at t = 1/2.
TEST(RingedBlendPCurve, Example41) {
  Surface pieces[2];
  int count = 0;
  RingedBlendOptions o;
  ASSERT_EQ(make_ringed_pcurve_blend(example41_start(), example41_end(), o, pieces, count),
            Status::ok);
  ASSERT_EQ(count, 1);
  const Surface& S = pieces[0];
  EXPECT_EQ(S.kind, SurfaceKind::ringed);
  EXPECT_LT((S.curve[0].point(0.5) - Vec3d(-2.125, -1.125, 0.75)).norm(), 1e-14);
  EXPECT_LT((S.curve[2].point(0.5) - Vec3d(-1.649053274, -2.613247615, 0.75)).norm(), 1e-9);
  const struct {
    double u;
    Vec3d s;
  } ref[4] = {{0, {-2.600946726, 0.3632476150, 0.75}},
              {1, {-2.280559691, 0.03492916982, -0.2852640984}},
              {-1, {-2.671369261, -0.09005308026, 1.785264098}},
              {2, {-1.961918597, -0.6685770886, -0.7354254716}}};
  for (const auto& r : ref) {
    const Vec3d X = point(S, 0.5, r.u);
    EXPECT_LT((X - r.s).norm(), 1e-9) << r.u;
    EXPECT_NEAR((X - Vec3d(-2.125, -1.125, 0.75)).norm(), 1.5625, 1e-13);
  }
  // The end circles are the data's: center d, plane normal n, radius rho.
  const RingedJet J[2] = {example41_start(), example41_end()};
  for (int e = 0; e < 2; ++e) {
    RingedJet K;
    ASSERT_EQ(ringed_jet(S, double(e), K), Status::ok);
    EXPECT_LT((K.d - J[e].d).norm(), 1e-12);
    EXPECT_LT((K.dd - J[e].dd).norm(), 1e-11);
    EXPECT_LT((K.n.normalized() - J[e].n.normalized()).norm(), 1e-12);
    EXPECT_NEAR(K.rho, J[e].rho, 1e-12);
    EXPECT_NEAR(K.drho, J[e].drho, 1e-11);
  }
}

// The P-biarc blend: two pieces on [0, 1/2], [1/2, 1] that join C^1 in the
// circle family and share the circle at 1/2; the minus branch also works.
TEST(RingedBlendPCurve, BiarcPiecesJoinC1) {
  Surface pieces[2];
  int count = 0;
  RingedBlendOptions o;
  o.tau = 0.5;
  ASSERT_EQ(make_ringed_pcurve_blend(example41_start(), example41_end(), o, pieces, count),
            Status::ok);
  ASSERT_EQ(count, 2);
  EXPECT_EQ(pieces[0].u1, 0.5);
  EXPECT_EQ(pieces[1].u0, 0.5);
  ContinuityReport R;
  ASSERT_EQ(continuity_report(pieces[0], 0.5, 1.0, pieces[1], 0.5, 1, nullptr, 32, R),
            Status::ok);
  EXPECT_LE(R.max_gap, 1e-12 * R.point_scale);
  EXPECT_LE(R.circle_jump[0], 1e-12);
  EXPECT_LE(R.circle_jump[1], 1e-10);
  o.tau = 0;
  o.sign = -1;
  EXPECT_EQ(make_ringed_pcurve_blend(example41_start(), example41_end(), o, pieces, count),
            Status::ok);
  o.sign = 2;
  EXPECT_EQ(make_ringed_pcurve_blend(example41_start(), example41_end(), o, pieces, count),
            Status::invalid_argument);
}

// A blend between two ringed surfaces of the library: R1 of Example 4.1
// (48) (rational: d1 = (2t - 6, 2t^2 - 5, t^3), rho1 = t^2/4 + 1,
// n1 = (1, t, t), c1 by Prop. 3.2 with v = (0, 1, 1)/sqrt 2) and a second
// one of the same kind moved away; the blend (any projection direction v)
// meets both C^1 in the circle family (the continuity report).
TEST(RingedBlendPCurve, JoinsLibrarySurfacesC1) {
  auto ringed = [](const Vec3d& shift, Surface& S) {
    RationalCurve d, n, c;
    const double dc[12] = {-6 + shift.x(), -5 + shift.y(), shift.z(), 2, 0, 0, 0, 2, 0, 0, 0, 1};
    const double nc[6] = {1, 0, 0, 0, 1, 1};
    ASSERT_EQ(make_polynomial_curve(3, dc, d), Status::ok);
    ASSERT_EQ(make_polynomial_curve(1, nc, n), Status::ok);
    RationalField f;
    ASSERT_EQ(projection_field(n, Vec3d(0, 1, 1).normalized(), f), Status::ok);
    ASSERT_EQ(ringed_curve(d, poly({1, 0, 0.25}), CurvePoly(1.0), f, c), Status::ok);
    ASSERT_EQ(make_ringed(d, n, c, nullptr, 0.0, 1.0, S), Status::ok);
  };
  Surface A, B;
  ringed(Vec3d(0, 0, 0), A);
  ringed(Vec3d(9, 2, -3), B);
  RingedJet a, b;
  ASSERT_EQ(ringed_jet(A, 1.0, a), Status::ok);
  ASSERT_EQ(ringed_jet(B, 0.0, b), Status::ok);
  EXPECT_LT((a.d - Vec3d(-4, -3, 1)).norm(), 1e-14);  // d1(1) as in the notes
  EXPECT_NEAR(a.rho, 1.25, 1e-14);
  for (const Vec3d& v : {Vec3d(0, 0, 1), Vec3d(Vec3d(1, 2, 2) / 3.0)}) {
    RingedBlendOptions o;
    o.v = v;
    Surface P[2];
    int count = 0;
    ASSERT_EQ(make_ringed_pcurve_blend(a, b, o, P, count), Status::ok);
    ContinuityReport R;
    ASSERT_EQ(continuity_report(A, 1.0, 1.0, P[0], 0.0, 1, nullptr, 32, R), Status::ok);
    EXPECT_LE(R.max_gap, 1e-12 * R.point_scale);
    EXPECT_LE(R.circle_jump[0], 1e-12);
    EXPECT_LE(R.circle_jump[1], 1e-10);
    ASSERT_EQ(continuity_report(B, 0.0, 1.0, P[0], 1.0, 1, nullptr, 32, R), Status::ok);
    EXPECT_LE(R.max_gap, 1e-12 * R.point_scale);
    EXPECT_LE(R.circle_jump[1], 1e-10);
  }
}

// fuzz_ringed regress-tiny-tau-overflow: tau = 2^-847 is a valid P-biarc
// parameter, but w2 of (47) ~ 1/tau overflows the P-curve's coefficients:
// numerical_overflow, not not_finite (reserved for non-finite inputs).
TEST(RingedBlendPCurve, RegressionTinyTauIsOverflow) {
  Surface pieces[2];
  int count = -7;
  RingedBlendOptions o;
  o.tau = std::ldexp(1.0, -847);
  EXPECT_EQ(make_ringed_pcurve_blend(example41_start(), example41_end(), o, pieces, count),
            Status::numerical_overflow);
  EXPECT_EQ(count, -7);
  o.tau = NAN;
  EXPECT_EQ(make_ringed_pcurve_blend(example41_start(), example41_end(), o, pieces, count),
            Status::not_finite);
}

// fuzz_ringed regress-tiny-v: v = (0, 1e-308, 1e-245) is a valid direction
// (e3 up to rounding); its norm underflowed and it was taken for zero.
TEST(RingedBlendPCurve, RegressionTinyProjectionDirection) {
  Surface pieces[2], ref[2];
  int count = 0, ref_count = 0;
  RingedBlendOptions o;
  o.v = Vec3d(0, 1e-308, 1e-245);
  ASSERT_EQ(make_ringed_pcurve_blend(example41_start(), example41_end(), o, pieces, count),
            Status::ok);
  ASSERT_EQ(make_ringed_pcurve_blend(example41_start(), example41_end(), RingedBlendOptions(),
                                     ref, ref_count),
            Status::ok);
  EXPECT_LT((point(pieces[0], 0.5, 1.0) - point(ref[0], 0.5, 1.0)).norm(), 1e-12);
  o.tau = 1.0;
  EXPECT_EQ(make_ringed_pcurve_blend(example41_start(), example41_end(), o, pieces, count),
            Status::bad_domain);
  o.v = Vec3d::Zero();
  EXPECT_EQ(make_ringed_pcurve_blend(example41_start(), example41_end(), o, pieces, count),
            Status::invalid_argument);
}

// The planar part's condition (ringed_pcurve_blend_condition): n nearly
// parallel to v at an end (the CI case of the property, |n||v|/|n x v| =
// 696; the two fuzz_ringed cases at 8e-6 and 1.5e-5 rad, whose end d came
// back off by 5.9e-6 and 5.2e-3 on a scale of ~30) or a P-biarc whose
// joint is n = (n.v) v (the root w passes through 0 there: c came back
// 9.3 off its circle at t = tau) is refused with not_pythagorean; another
// v builds the blend with its end jets to the stated 64 eps kappa (values)
// and 256 eps kappa^1.5 (derivatives).
namespace {
double condition(const RingedJet& a, const RingedJet& b, const RingedBlendOptions& o) {
  double kappa = -1;
  EXPECT_EQ(ringed_pcurve_blend_condition(a, b, o, kappa), Status::ok);
  return kappa;
}
void expect_end_jets(const RingedJet& a, const RingedJet& b, const RingedBlendOptions& o) {
  SCOPED_TRACE(testing::Message() << "v " << o.v.transpose() << " tau " << o.tau);
  const double kappa = condition(a, b, o), eps = std::numeric_limits<double>::epsilon();
  EXPECT_LE(kappa, 1e5);
  Surface P[2];
  int count = 0;
  ASSERT_EQ(make_ringed_pcurve_blend(a, b, o, P, count), Status::ok);
  const RingedJet J[2] = {a, b};
  for (int e = 0; e < 2; ++e) {
    RingedJet K;
    ASSERT_EQ(ringed_jet(P[e ? count - 1 : 0], double(e), K), Status::ok);
    const double scale = 1 + J[e].d.norm() + J[e].dd.norm() + J[e].n.norm() + J[e].dn.norm() +
                         J[e].rho + std::abs(J[e].drho);
    const double tol = 64 * eps * kappa * scale, dtol = 256 * eps * std::pow(kappa, 1.5) * scale;
    EXPECT_LE((K.d - J[e].d).norm(), tol) << "end " << e;
    EXPECT_LE((K.n - J[e].n).norm(), tol) << "end " << e;
    EXPECT_LE(std::abs(K.rho - J[e].rho), tol) << "end " << e;
    EXPECT_LE((K.dd - J[e].dd).norm(), dtol) << "end " << e;
    EXPECT_LE((K.dn - J[e].dn).norm(), dtol) << "end " << e;
    EXPECT_LE(std::abs(K.drho - J[e].drho), dtol) << "end " << e;
  }
}
void expect_refused(const RingedJet& a, const RingedJet& b, const RingedBlendOptions& o) {
  EXPECT_GT(condition(a, b, o), 1e5);
  Surface P[2];
  int count = -7;
  EXPECT_EQ(make_ringed_pcurve_blend(a, b, o, P, count), Status::not_pythagorean);
  EXPECT_EQ(count, -7);
}
}  // namespace

TEST(RingedBlendPCurve, IllConditionedPlanarPartIsRefused) {
  {  // the property's CI case
    RingedJet a, b;
    a.d = Vec3d(-64, -63, -64) / 16;
    a.dd = Vec3d(-63, -64, -64) / 16;
    a.n = a.dn = Vec3d(-4, -4, -4);
    a.rho = 4.25;
    a.drho = -1;
    b = a;
    b.d = Vec3d(2, -2, -4);
    b.dd = Vec3d(-4, -4, -4);
    b.n = Vec3d(-19, 18, -56) / 16;
    RingedBlendOptions o;
    o.sign = -1;
    o.v = Vec3d(-17, 16, -50) / 16;
    expect_refused(a, b, o);
    o.v = Vec3d::UnitZ();
    expect_end_jets(a, b, o);
  }
  {  // fuzz_ringed: v within 8e-6 rad of n at the end b
    RingedJet a, b;
    a.d = Vec3d(3, 4, -0x1.7fcp+2);
    a.dd = Vec3d(-0x1.1fep+3, -10, -0x1.3fep+3);
    a.n = Vec3d(-0x1.3fecp+3, -0x1.3f2p+3, 0);
    a.dn = Vec3d(8, 4, 0);
    a.rho = 8;
    a.drho = 4;
    b.d = Vec3d(0x1.ap-1, -9, -10);
    b.dd = Vec3d(0x1.c9p+1, -7, -7);
    b.n = Vec3d(0x1.18p-14, 0, -8);
    b.dn = Vec3d(4, 0, -8);
    b.rho = 4;
    b.drho = 0;
    RingedBlendOptions o;
    o.v = Vec3d(0x1.56e1fc2f8f359p-997, 0x1.1686868686868p-1007, -0x1.6p+3);
    expect_refused(a, b, o);
    o.v = Vec3d(1, 2, 2) / 3;
    expect_end_jets(a, b, o);
  }
  {  // fuzz_ringed: v within 1.5e-5 rad of n at the end b, |v| ~ 2^-847
    RingedJet a, b;
    a.d = Vec3d(-0x1.3fep+3, -10, -0x1.3ecp+3);
    a.dd = Vec3d(0, 0, -10);
    a.n = Vec3d(-0x1.7f8p+1, -0x1.1f2p+3, -9);
    a.dn = Vec3d(-5, -0x1.048d7cp+3, -0x1.3febecp+3);
    a.rho = 10;  // |rho| as the C entry point takes it
    a.drho = -0x1.17ecp+3;
    b.d = Vec3d(0, 1, -0x1.3fd85p+3);
    b.dd = Vec3d(-0x1.3fep+3, -0x1.1fep+3, 1);
    b.n = Vec3d(0, 0.5, 0);
    b.dn = Vec3d(-10, -0x1.3f38p+3, -0x1.ffcp+2);
    b.rho = 10;
    b.drho = -0x1.3ecp+3;
    RingedBlendOptions o;
    o.sign = -1;
    o.v = Vec3d(-0.0, 0x1.00a010a80000ap-847, 0x1.00b000a0009p-863);
    expect_refused(a, b, o);
  }
  {  // a P-biarc through w = 0 at its joint tau = 1/2: n = (n.v) v there
    RingedJet a;
    a.d = Vec3d(-4, -4, -4);
    a.dd = Vec3d(-4, -4, -4);
    a.n = Vec3d(-0x1.f8p+1, -0x1.f8p+1, -4);
    a.dn = Vec3d(-4, -0x1.f8p+1, -4);
    a.rho = 0x1.1p+2;
    a.drho = -1;
    RingedJet b = a;
    b.d = Vec3d(2, -2, -4);
    RingedBlendOptions o;
    o.sign = -1;
    o.tau = 0.5;
    o.v = Vec3d(-4, -0x1.f8p+1, -4);
    expect_refused(a, b, o);
    o.sign = 1;  // the "more suitable" branch of (47)
    expect_end_jets(a, b, o);
  }
}

// fuzz_ringed regress-tau-near-one: a P-biarc at tau = 1 - 2^-52. The
// coefficients (47) of the second piece grow like 1/(1 - tau); in powers of
// t they cancelled near t = 1 and the end's d was missed by 14. Each piece
// is now built in powers of the distance from its outer end: the end jets
// and the join hold to ~1e-11 for tau from 1e-12 to 1 - 1e-12.
TEST(RingedBlendPCurve, RegressionTauNearOneKeepsTheEnds) {
  const RingedJet J[2] = {example41_start(), example41_end()};
  for (double tau : {1 - std::ldexp(1.0, -52), 1 - 1e-12, 1 - 1e-6, 0.5, 1e-6, 1e-12}) {
    RingedBlendOptions o;
    o.tau = tau;
    Surface P[2];
    int count = 0;
    ASSERT_EQ(make_ringed_pcurve_blend(J[0], J[1], o, P, count), Status::ok) << tau;
    ASSERT_EQ(count, 2);
    for (int e = 0; e < 2; ++e) {
      RingedJet K;
      ASSERT_EQ(ringed_jet(P[e], double(e), K), Status::ok);
      EXPECT_LT((K.d - J[e].d).norm(), 1e-10) << "tau " << tau << " end " << e;
      EXPECT_LT((K.dd - J[e].dd).norm(), 1e-10) << "tau " << tau << " end " << e;
      EXPECT_LT((K.n - J[e].n).norm(), 1e-10) << "tau " << tau << " end " << e;
      EXPECT_LT((K.dn - J[e].dn).norm(), 1e-10) << "tau " << tau << " end " << e;
      EXPECT_LT(std::abs(K.rho - J[e].rho), 1e-10) << "tau " << tau << " end " << e;
    }
    RingedJet L, R;
    ASSERT_EQ(ringed_jet(P[0], tau, L), Status::ok);
    ASSERT_EQ(ringed_jet(P[1], tau, R), Status::ok);
    EXPECT_LT((L.d - R.d).norm() + (L.n - R.n).norm() + std::abs(L.rho - R.rho), 1e-10) << tau;
  }
}

// Definition 7.1 on a surface of revolution about the z axis (d = (0, 0, u),
// n = e3, rho = 1 + u^2/4): for v = e1 the contour (the silhouette's
// generators) is the meridian in the plane x = 0, the points (0, +-rho, u).
TEST(ContourCurves, SurfaceOfRevolution) {
  RationalCurve d, n, c;
  const double dc[6] = {0, 0, 0, 0, 0, 1}, cc[9] = {1, 0, 0, 0, 0, 1, 0.25, 0, 0};
  ASSERT_EQ(make_polynomial_curve(1, dc, d), Status::ok);
  ASSERT_EQ(make_point(Vec3d(0, 0, 1), n), Status::ok);
  ASSERT_EQ(make_polynomial_curve(2, cc, c), Status::ok);
  Surface S;
  ASSERT_EQ(make_ringed(d, n, c, nullptr, -1, 1, S), Status::ok);
  for (double u : {-1.0, -0.3, 0.0, 0.8}) {
    ContourPoints P;
    ASSERT_EQ(contour_points(S, u, Vec3d(2, 0, 0), P), Status::ok);
    ASSERT_EQ(P.count, 2) << u;
    EXPECT_FALSE(P.whole_circle);
    const double rho = 1 + u * u / 4;
    const Vec3d lo(0, -rho, u), hi(0, rho, u);
    EXPECT_LT(std::min((P.points[0] - lo).norm(), (P.points[0] - hi).norm()), 1e-13);
    EXPECT_LT(std::min((P.points[1] - lo).norm(), (P.points[1] - hi).norm()), 1e-13);
    EXPECT_GT((P.points[0] - P.points[1]).norm(), rho);
    // Along the axis every point of the circle has a normal with a z part
    // (rho' != 0) except at u = 0, where the surface is a cylinder locally:
    // there the whole circle is contour for v = e3.
    ASSERT_EQ(contour_points(S, u, Vec3d(0, 0, 1), P), Status::ok);
    EXPECT_EQ(P.whole_circle, u == 0.0) << u;
    EXPECT_EQ(P.count, 0);
  }
  ContourPoints P;
  EXPECT_EQ(contour_points(S, 0.5, Vec3d::Zero(), P), Status::invalid_argument);
  EXPECT_EQ(contour_points(S, NAN, Vec3d(1, 0, 0), P), Status::not_finite);
}

// Eqs. (71), (72), Prop. 7.2 and Corollary 7.3: the normal ringed surface
// (n = d') of the planar PH cubic d = (t - t^3/3, t^2, 0), |d'| = 1 + t^2,
// with rho = 1/2 has n.e3 = 0 and the rational contour curves
// c+- = d +- rho (n x e3)/|n|; they agree with the contour points of
// Definition 7.1 computed on the circles.
TEST(ContourCurves, Equation72PythagoreanOrientation) {
  RationalCurve d, n, plus, minus;
  const double dc[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, -1.0 / 3, 0, 0};
  const double nc[9] = {1, 0, 0, 0, 2, 0, -1, 0, 0};
  ASSERT_EQ(make_polynomial_curve(3, dc, d), Status::ok);
  ASSERT_EQ(make_polynomial_curve(2, nc, n), Status::ok);
  ASSERT_EQ(contour_curves_71(d, n, poly({0.5}), poly({1.0}), Vec3d(0, 0, 1), plus, minus),
            Status::ok);
  RingedFieldOptions o;
  o.method = RingedFieldMethod::projection;
  Surface S;
  ASSERT_EQ(make_ringed_dnr(d, n, poly({0.5}), poly({1.0}), o, nullptr, -1.5, 1.5, S),
            Status::ok);
  for (double t : {-1.5, -0.4, 0.0, 0.7, 1.5}) {
    const Vec3d D = d.point(t), N = n.point(t);
    const Vec3d side = 0.5 * N.cross(Vec3d(0, 0, 1)) / N.norm();
    EXPECT_LT((plus.point(t) - (D + side)).norm(), 1e-13) << t;
    EXPECT_LT((minus.point(t) - (D - side)).norm(), 1e-13) << t;
    ContourPoints P;
    ASSERT_EQ(contour_points(S, t, Vec3d(0, 0, 1), P), Status::ok);
    ASSERT_EQ(P.count, 2) << t;
    for (int i = 0; i < 2; ++i)
      EXPECT_LT(std::min((P.points[i] - plus.point(t)).norm(),
                         (P.points[i] - minus.point(t)).norm()),
                1e-12)
          << t;
  }
  // (71) fails for v = e1; |n| is not a polynomial for n = (1, t, 0).
  EXPECT_EQ(contour_curves_71(d, n, poly({0.5}), poly({1.0}), Vec3d(1, 0, 0), plus, minus),
            Status::invalid_argument);
  const double lin[6] = {1, 0, 0, 0, 1, 0};
  RationalCurve m;
  ASSERT_EQ(make_polynomial_curve(1, lin, m), Status::ok);
  EXPECT_EQ(contour_curves_71(d, m, poly({0.5}), poly({1.0}), Vec3d(0, 0, 1), plus, minus),
            Status::not_pythagorean);
  EXPECT_EQ(contour_curves_71(d, n, poly({0.5}), poly({1.0}), Vec3d::Zero(), plus, minus),
            Status::invalid_argument);
}

using cyclide_test::canal_jet;

// Example 5.2, eqs. (58)-(61): the canal surfaces (59) at t = 1 and (60) at
// t = 0 read as ringed surfaces (1), their §4 blend (Ferguson cubics and
// the degree-6 P-curve (43), + sign), the deviance (58) of the blend
// (0.336653; paper 0.337), and with the bump of v (61), tau = 1/2: (52)
// with the sign of ERRATA.md gives 0.111879 (paper 0.112; as printed 0.646),
// (57) gives 0.1032 (transcription's notes).
TEST(ConstrainedBlend, Example52MoreNormalBlend) {
  const double a = 0.3 - 1.1;  // 0.3 t - 1.1 at t = 1
  const RingedJet J1 = canal_jet(Vec3d(a, a * a - 1, a * a * a), Vec3d(0.3, 0.6 * a, 0.9 * a * a),
                                 Vec3d(0, 0.18, 0.54 * a), 0.03 - 0.22 + 0.736667,
                                 0.06 - 0.22, 0.06);
  const RingedJet J2 = canal_jet(Vec3d(2, 2, 1), Vec3d(0.3, 1.2, 0.6), Vec3d(0, 0.36, 0.18), 1,
                                 0.3, 0.09);
  // The transcription's Hermite data.
  EXPECT_LT((J1.d - Vec3d(-0.759765437551, -0.424375299919, -0.434749640097)).norm(), 1e-11);
  EXPECT_LT((J1.dd - Vec3d(0.314498877110, -0.479057465906, 0.545900074124)).norm(), 1e-11);
  EXPECT_LT((J1.n - Vec3d(0.3, -0.48, 0.576)).norm(), 1e-14);
  EXPECT_LT((J1.dn - Vec3d(0, 0.18, -0.432)).norm(), 1e-14);
  EXPECT_NEAR(J1.rho, 0.535830375705, 1e-11);
  EXPECT_NEAR(J1.drho, -0.159871806151, 1e-11);
  EXPECT_LT((J2.d - Vec3d(1.95238095238, 1.80952380952, 0.904761904762)).norm(), 1e-10);
  EXPECT_LT((J2.dd - Vec3d(0.298639455782, 1.13741496599, 0.568707482993)).norm(), 1e-10);
  EXPECT_NEAR(J2.rho, 0.975900072949, 1e-11);
  EXPECT_NEAR(J2.drho, 0.292072950404, 1e-11);
  // (58) on the plain blend and on the bumped ones.
  Surface P[2];
  int count = 0;
  double dev = 0;
  ASSERT_EQ(make_ringed_pcurve_blend(J1, J2, RingedBlendOptions(), P, count), Status::ok);
  ASSERT_EQ(normal_deviance(P[0], dev), Status::ok);
  EXPECT_NEAR(dev, 0.336653, 1e-6);
  RingedBlendOptions o;
  o.bump.w = Vec3d(-0.23824, -1.04859, 0.13459);
  o.bump.tau = 0.5;
  ASSERT_EQ(make_ringed_pcurve_blend(J1, J2, o, P, count), Status::ok);
  ASSERT_EQ(count, 1);
  ASSERT_EQ(normal_deviance(P[0], dev), Status::ok);
  EXPECT_NEAR(dev, 0.111879, 1e-6);
  // The bump moved d by w at tau and kept the ends (51).
  Surface Q[2];
  ASSERT_EQ(make_ringed_pcurve_blend(J1, J2, RingedBlendOptions(), Q, count), Status::ok);
  RingedJet K, L;
  ASSERT_EQ(ringed_jet(P[0], 0.5, K), Status::ok);
  ASSERT_EQ(ringed_jet(Q[0], 0.5, L), Status::ok);
  EXPECT_LT((K.d - L.d - o.bump.w).norm(), 1e-12);
  EXPECT_LT((K.dd - L.dd).norm(), 1e-11);  // b'(tau) = 0
  for (int e = 0; e < 2; ++e) {
    ASSERT_EQ(ringed_jet(P[0], double(e), K), Status::ok);
    const RingedJet& J = e ? J2 : J1;
    EXPECT_LT((K.d - J.d).norm() + (K.dd - J.dd).norm(), 1e-12);
  }
  // (57): two pieces split at tau, joined C^1.
  o.bump.kind = BumpKind::two_piece;
  ASSERT_EQ(make_ringed_pcurve_blend(J1, J2, o, P, count), Status::ok);
  ASSERT_EQ(count, 2);
  double dev2 = 0;
  ASSERT_EQ(normal_deviance(P[0], dev), Status::ok);
  ASSERT_EQ(normal_deviance(P[1], dev2), Status::ok);
  EXPECT_NEAR(dev + dev2, 0.1032, 1e-4);
  ASSERT_EQ(ringed_jet(P[0], 0.5, K), Status::ok);
  ASSERT_EQ(ringed_jet(P[1], 0.5, L), Status::ok);
  EXPECT_LT((K.d - L.d).norm() + (K.dd - L.dd).norm() + (K.n - L.n).norm(), 1e-11);
  // Statuses: tau of the bump outside (0, 1); a P-biarc split elsewhere.
  o.bump.tau = 1.0;
  EXPECT_EQ(make_ringed_pcurve_blend(J1, J2, o, P, count), Status::bad_domain);
  o.bump.tau = 0.5;
  o.tau = 0.25;
  EXPECT_EQ(make_ringed_pcurve_blend(J1, J2, o, P, count), Status::invalid_argument);
}

// Eq. (54) on Example 4.1's blend: the clearance from a sphere around the
// blend's middle circle is negative (it meets the blend), and a bump away
// from it clears it; the clearance is exact at the minimizer.
TEST(ConstrainedBlend, Equation54SphereClearance) {
  Surface P[2];
  int count = 0;
  ASSERT_EQ(make_ringed_pcurve_blend(example41_start(), example41_end(), RingedBlendOptions(), P,
                                     count),
            Status::ok);
  RingedJet M;
  ASSERT_EQ(ringed_jet(P[0], 0.5, M), Status::ok);
  const Vec3d s = M.d + Vec3d(0, 0, 0.5);
  double clear = 0, at = -1;
  ASSERT_EQ(sphere_clearance(P[0], s, 0.5, clear, &at), Status::ok);
  EXPECT_LT(clear, -1.0);
  RingedJet A;
  ASSERT_EQ(ringed_jet(P[0], at, A), Status::ok);
  EXPECT_NEAR(clear, (A.d - s).norm() - A.rho - 0.5, 1e-14);
  for (double u : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    RingedJet U;
    ASSERT_EQ(ringed_jet(P[0], u, U), Status::ok);
    EXPECT_GE((U.d - s).norm() - U.rho - 0.5, clear - 1e-15);
  }
  RingedBlendOptions o;
  o.bump.w = Vec3d(0, 0, -6);
  ASSERT_EQ(make_ringed_pcurve_blend(example41_start(), example41_end(), o, P, count), Status::ok);
  double moved = 0;
  ASSERT_EQ(sphere_clearance(P[0], s, 0.5, moved), Status::ok);
  EXPECT_GT(moved, clear + 1.0);
  EXPECT_EQ(sphere_clearance(P[0], s, -1.0, moved), Status::invalid_argument);
}

// §3.d, Theorem 3.6: radius rho = sqrt(R) with R not a square.
namespace {

// Points of the ringed surface S with directrix d, axis n and radius
// sqrt(R) (R = R_num / R_den) lie on their circles.
void expect_on_sqrt_circles(const Surface& S, const RationalCurve& d, const RationalCurve& n,
                            const CurvePoly& R_num, const CurvePoly& R_den, double t0, double t1,
                            double tol) {
  for (int i = 0; i <= 6; ++i) {
    const double t = t0 + (t1 - t0) * i / 6.0;
    const double rho = std::sqrt(R_num(t) / R_den(t));
    for (double u : {-3.0, -0.5, 0.0, 0.8, 25.0}) {
      const Vec3d X = point(S, t, u), D = d.point(t), N = n.point(t).normalized();
      EXPECT_NEAR((X - D).norm(), rho, tol * (1 + rho)) << "t = " << t << " u = " << u;
      EXPECT_NEAR((X - D).dot(N), 0.0, tol * (1 + rho)) << "t = " << t << " u = " << u;
    }
  }
}

}  // namespace

// Eq. (24): the canal surface of the spine m = (t, t^2, t^3) and sphere
// radius r = 1 + t/5, seen as a ringed surface (1): d = m - (r r' / |m'|^2)
// m', n = m' and rho^2 = r^2 (|m'|^2 - r'^2) / |m'|^2, not a square. Theorem
// 3.6's surface lies on the canal's spheres |X - m| = r, and its circles
// have radius sqrt(R). |m'|^2 = 1 + 4t^2 + 9t^4 is not a square (m is not a
// PH curve), R's denominator shares its roots (the reduced conic's G) and
// r^2 is a square factor with a real root (t = -5).
TEST(RingedSqrt, Equation24CanalSurface) {
  const CurvePoly r = poly({1.0, 0.2});
  const double dr = 0.2;
  const CurvePoly m[3] = {poly({0, 1}), poly({0, 0, 1}), poly({0, 0, 0, 1})};
  const CurvePoly dm[3] = {poly({1}), poly({0, 2}), poly({0, 0, 3})};
  CurvePoly N, t1, t2;
  for (const CurvePoly& p : dm) {
    multiply(p, p, t1);
    N = N + t1;
  }
  // d = (m N - r r' m') / N.
  double dc[4 * 8] = {};
  CurvePoly D[3];
  for (int j = 0; j < 3; ++j) {
    multiply(m[j], N, t1);
    multiply(r.scaled(dr), dm[j], t2);
    D[j] = t1 - t2;
  }
  RationalCurve d, n;
  for (int k = 0; k <= 7; ++k) {
    for (int j = 0; j < 3; ++j) dc[4 * k + j] = D[j].c[k];
    dc[4 * k + 3] = N.c[k];
  }
  ASSERT_EQ(make_rational_curve(7, dc, d), Status::ok);
  const double nc[9] = {1, 0, 0, 0, 2, 0, 0, 0, 3};
  ASSERT_EQ(make_polynomial_curve(2, nc, n), Status::ok);
  CurvePoly r2, R_num;
  multiply(r, r, r2);
  multiply(r2, N - CurvePoly(dr * dr), R_num);
  Surface S;
  RingedSqrtReport rep;
  ASSERT_EQ(make_ringed_sqrt(d, n, R_num, N, RingedFieldOptions(), nullptr, -1, 1, S, &rep),
            Status::ok);
  EXPECT_FALSE(rep.exact_square);
  EXPECT_EQ(rep.field.method, RingedFieldMethod::quadratic);  // Example 3.3 for n = m'
  EXPECT_LT(rep.residual, 1e-12);
  EXPECT_EQ(rep.conic_degree, 8);  // G = |m'|^2 / 9, P1 = |m'|^2 - r'^2
  expect_on_sqrt_circles(S, d, n, R_num, N, -1, 1, 1e-11);
  for (double t : {-1.0, -0.2, 0.6, 1.0})
    for (double u : {-2.0, 0.0, 1.0, 9.0}) {
      const Vec3d M(m[0](t), m[1](t), m[2](t));
      EXPECT_NEAR((point(S, t, u) - M).norm(), r(t), 1e-11) << t << " " << u;
    }
}

// A ringed surface that is not canal: n = (1, t, t^2) (|n|^2 = 1 + t^2 +
// t^4 is not a square and no projection of n is a P-curve along the axes),
// R = 2 + t^2; the reduced conic x^2 + |n|^2 y^2 = R z^2 has no common roots.
TEST(RingedSqrt, Theorem36GeneralRadius) {
  RationalCurve d, n;
  const double dc[6] = {0, 1, 0, 1, 0, 0.5};
  ASSERT_EQ(make_polynomial_curve(1, dc, d), Status::ok);
  const double nc[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  ASSERT_EQ(make_polynomial_curve(2, nc, n), Status::ok);
  const CurvePoly R = poly({2, 0, 1}), one = poly({1});
  RationalField f;
  RingedSqrtReport rep;
  for (auto method : {RingedFieldMethod::automatic, RingedFieldMethod::sos}) {
    RingedFieldOptions o;
    o.method = method;
    ASSERT_EQ(sqrt_radius_field(n, R, one, o, f, &rep), Status::ok);
    EXPECT_EQ(rep.conic_degree, 6);
    EXPECT_LT(rep.residual, 1e-12);
    for (double t : {-4.0, -1.0, 0.0, 0.5, 3.0}) {
      const Vec3d F = eval3(f.F, t) / f.w(t), Nt = n.point(t);
      EXPECT_NEAR(F.squaredNorm(), R(t), 1e-11 * R(t));
      EXPECT_NEAR(F.dot(Nt) / Nt.norm(), 0.0, 1e-11 * std::sqrt(R(t)));
    }
  }
  Surface S;
  ASSERT_EQ(make_ringed_sqrt(d, n, R, one, RingedFieldOptions(), nullptr, -2, 2, S, &rep),
            Status::ok);
  expect_on_sqrt_circles(S, d, n, R, one, -2, 2, 1e-11);
}

// Statuses: R < 0 somewhere, zero polynomials, a square R (rational rho).
TEST(RingedSqrt, StatusesAndSquareRadius) {
  RationalCurve n, d, p;
  const double nc[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  ASSERT_EQ(make_polynomial_curve(2, nc, n), Status::ok);
  const double dc[3] = {0, 0, 0};
  ASSERT_EQ(make_polynomial_curve(0, dc, d), Status::ok);
  const CurvePoly one = poly({1});
  RationalField f;
  RingedSqrtReport rep;
  const RingedFieldOptions o;
  EXPECT_EQ(sqrt_radius_field(n, poly({-1, 0, 1}), one, o, f), Status::empty_real_locus);
  EXPECT_EQ(sqrt_radius_field(n, poly({-1}), one, o, f), Status::empty_real_locus);
  EXPECT_EQ(sqrt_radius_field(n, poly({0, 1}), one, o, f), Status::empty_real_locus);
  EXPECT_EQ(sqrt_radius_field(n, poly({1, 0, -1}), poly({2, 0, 1}), o, f),
            Status::empty_real_locus);
  EXPECT_EQ(sqrt_radius_field(n, poly({0}), one, o, f), Status::invalid_argument);
  EXPECT_EQ(sqrt_radius_field(n, one, poly({0}), o, f), Status::invalid_argument);
  EXPECT_EQ(sqrt_radius_field(n, poly({NAN}), one, o, f), Status::not_finite);
  ASSERT_EQ(make_point(Vec3d(1, 2, 3), p), Status::ok);
  EXPECT_EQ(sqrt_radius_field(p, one, one, o, f), Status::invalid_argument);
  // R = (1 + t)^2 / (2 + t^2)^2... a square: rho = (1 + t) / (2 + t^2) exactly.
  ASSERT_EQ(sqrt_radius_field(n, poly({1, 2, 1}), poly({4, 0, 4, 0, 1}), o, f, &rep),
            Status::ok);
  EXPECT_TRUE(rep.exact_square);
  EXPECT_EQ(rep.residual, 0.0);
  for (double t : {-2.0, 0.0, 1.5}) {
    const Vec3d F = eval3(f.F, t) / f.w(t);
    EXPECT_NEAR(F.norm(), std::abs(1 + t) / (2 + t * t), 1e-13);
  }
  // A double real root of R (a zero radius, the surface's singular point)
  // is a square factor: the field exists, the surface is singular there.
  ASSERT_EQ(sqrt_radius_field(n, poly({0, 0, 2, 0, 1}), one, o, f, &rep), Status::ok);
  EXPECT_LT(rep.residual, 1e-12);
  Surface S;
  EXPECT_EQ(make_ringed_sqrt(d, n, poly({0, 0, 2, 0, 1}), one, o, nullptr, -1, 1, S),
            Status::singular_point);
}

// make_ringed_dnr's automatic route keeps a field only if it is defined on
// the whole domain: Example 6.2's R_3 (n = d3' = (0, 6t^2 - 10t, 6t^2 - 6t
// + 4)) projects along e3 with sigma = |6t^2 - 10t|, zero at t = 0 in
// [0, 1]; a later route gives the surface. The explicit projection along
// e3 still reports the scan's failure.
TEST(PCurve, AutomaticFieldSkipsRoutesUndefinedOnTheDomain) {
  RationalCurve d, n;
  const double dc[12] = {0, 8, -8, 0, 0, 4, 0, -5, -3, 0, 2, 2};
  const double nc[9] = {0, 0, 4, 0, -10, -6, 0, 6, 6};
  ASSERT_EQ(make_polynomial_curve(3, dc, d), Status::ok);
  ASSERT_EQ(make_polynomial_curve(2, nc, n), Status::ok);
  const CurvePoly rho = poly({1.5, -4.0 / 6}), one = poly({1});
  RingedFieldOptions e3;
  e3.method = RingedFieldMethod::projection;
  Surface S;
  EXPECT_NE(make_ringed_dnr(d, n, rho, one, e3, nullptr, 0, 1, S), Status::ok);
  RingedFieldReport rep;
  ASSERT_EQ(make_ringed_dnr(d, n, rho, one, RingedFieldOptions(), nullptr, 0, 1, S, &rep),
            Status::ok);
  EXPECT_NE(rep.method, RingedFieldMethod::automatic);
  EXPECT_LT(std::abs(rep.v.z()), 1 - 1e-9);  // not the projection along e3
  for (double t : {0.0, 0.5, 1.0})
    for (double u : {-1.0, 0.0, 2.0}) {
      const Vec3d X = point(S, t, u), D = d.point(t), N = n.point(t).normalized();
      EXPECT_NEAR((X - D).norm(), 1.5 - 4.0 * t / 6, 1e-12);
      EXPECT_NEAR((X - D).dot(N), 0.0, 1e-12);
    }
}
