// Seed 001 §7.a (labels paper;ringed;ringed_modeling;optim): the implicit
// ringed blend (73) of two quadrics, its contour curves (76)-(80) and the
// approximation of Example 7.6 by exact rational ringed surfaces
// (81)-(84), (87). The paper does not give lambda and n of (73)
// (ERRATA.md); this test uses lambda = 1/2, n = 2 (SPEC.md §8f.7a).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <cstdio>

#include "cyclide/implicit_blend.hpp"
#include "optim/implicit_blend_optimizer.hpp"

using namespace cyclide;

namespace {

// Example 7.6 (85): f1 = y^2 + z^2 - 9, f2 = x^2 - 2xy - 12x + y^2 + 12y +
// 2z^2 + 28, P1: f10 = x, P2: f20 = x + y - 10 (signs as printed); lambda =
// 1/2, n = 2. With n odd (even powers of the planes) the branch from
// (0, 3, 0) runs into the line P1 n P2 instead of reaching P2 for every
// lambda (traced in 0.05 steps); with n = 2 all six branches reach P2.
ImplicitBlend example76(double lambda = 0.5, int n = 2) {
  const double q1[10] = {0, 1, 1, 0, 0, 0, 0, 0, 0, -9};
  const double q2[10] = {1, 1, 2, -2, 0, 0, -12, 12, 0, 28};
  const double p1[4] = {1, 0, 0, 0}, p2[4] = {1, 1, 0, -10};
  Quadric f1, f2;
  PlaneFn g1, g2;
  EXPECT_EQ(make_quadric(q1, f1), Status::ok);
  EXPECT_EQ(make_quadric(q2, f2), Status::ok);
  EXPECT_EQ(make_plane_fn(p1, g1), Status::ok);
  EXPECT_EQ(make_plane_fn(p2, g2), Status::ok);
  ImplicitBlend B;
  EXPECT_EQ(make_implicit_blend(f1, f2, g1, g2, lambda, n, B), Status::ok);
  return B;
}

// (86)
const Vec3d kV[3] = {Vec3d(0, 0, 1), Vec3d(0, 1, 0), Vec3d(0, 1, 1) / std::sqrt(2.0)};

// |f| and |f_v| relative to the gradients (distance-like) at x.
void expect_on_contour(const ImplicitBlend& B, const Vec3d& v, const Vec3d& x, double tol) {
  const BlendJet<double> J = blend_eval(B, x, &v);
  EXPECT_LE(std::abs(J.f) / J.grad.norm(), tol) << x.transpose();
  EXPECT_LE(std::abs(J.grad.dot(v)) / J.hv.norm(), tol) << x.transpose();
}

}  // namespace

// f, grad f and H v (76) against central differences of the blend.
TEST(ImplicitBlend, GradientAndHessianMatchFiniteDifferences) {
  for (int n : {1, 2, 3}) {
    const ImplicitBlend B = example76(0.3, n);
    const Vec3d x(1.3, -0.7, 2.1), v = Vec3d(0.2, -1.0, 0.5);
    const BlendJet<double> J = blend_eval(B, x, &v);
    const double h = 1e-5;
    for (int j = 0; j < 3; ++j) {
      Vec3d e = Vec3d::Zero();
      e[j] = h;
      const BlendJet<double> P = blend_eval(B, Vec3d(x + e)), M = blend_eval(B, Vec3d(x - e));
      const double fd = (P.f - M.f) / (2 * h);
      EXPECT_NEAR(J.grad[j], fd, 1e-6 * (1 + std::abs(fd)));
      const double fdv = (P.grad.dot(v) - M.grad.dot(v)) / (2 * h);  // d f_v / dx_j
      EXPECT_NEAR(J.hv[j], fdv, 1e-6 * (1 + std::abs(fdv)));
    }
    EXPECT_DOUBLE_EQ(contour_function(B, x, v), J.grad.dot(v));
  }
}

// The quadric constructors reproduce Example 7.6's f2 = (x - y - 6)^2 + 2z^2
// - 8 up to a factor: the cylinder of radius 2 about {x - y = 6, z = 0}.
TEST(ImplicitBlend, CylinderAndConeConstructors) {
  Quadric C;
  ASSERT_EQ(make_cylinder(Vec3d(6, 0, 0), Vec3d(1, 1, 0), 2.0, C), Status::ok);
  const ImplicitBlend B = example76();
  for (const Vec3d& x : {Vec3d(1, 2, 3), Vec3d(-4, 0.5, 1), Vec3d(8, 2, 2)})
    EXPECT_NEAR(2 * C.value(x), B.f2.value(x), 1e-12 * (1 + x.squaredNorm()));
  Quadric K;
  ASSERT_EQ(make_cone(Vec3d(1, 1, 1), Vec3d(0, 0, 2), std::atan(0.5), K), Status::ok);
  EXPECT_NEAR(K.value(Vec3d(1.5, 1, 2)), 0.0, 1e-14);  // radius 1/2 at height 1
  EXPECT_EQ(make_cylinder(Vec3d::Zero(), Vec3d::Zero(), 1, C), Status::invalid_argument);
  EXPECT_EQ(make_cylinder(Vec3d::Zero(), Vec3d::UnitX(), -1, C), Status::invalid_argument);
  EXPECT_EQ(make_cone(Vec3d::Zero(), Vec3d::UnitX(), 2.0, K), Status::invalid_argument);
  double q[10];
  quadric_coefficients(B.f2, q);
  const double expect[10] = {1, 1, 2, -2, 0, 0, -12, 12, 0, 28};
  for (int k = 0; k < 10; ++k) EXPECT_EQ(q[k], expect[k]);
}

TEST(ImplicitBlend, DegenerateInputsHaveStatuses) {
  const ImplicitBlend E = example76();
  ImplicitBlend B;
  EXPECT_EQ(make_implicit_blend(E.f1, E.f2, E.f10, E.f20, 0.0, 1, B), Status::invalid_argument);
  EXPECT_EQ(make_implicit_blend(E.f1, E.f2, E.f10, E.f20, 1.0, 1, B), Status::invalid_argument);
  EXPECT_EQ(make_implicit_blend(E.f1, E.f2, E.f10, E.f20, 0.5, 0, B), Status::invalid_argument);
  EXPECT_EQ(make_implicit_blend(E.f1, E.f2, E.f10, E.f20, NAN, 1, B), Status::not_finite);
  PlaneFn same = E.f10;
  same.n *= -2;  // -2x = 0: the same plane as x = 0
  EXPECT_EQ(make_implicit_blend(E.f1, E.f2, E.f10, same, 0.5, 1, B), Status::dependent_planes);
  PlaneFn parallel = E.f10;
  parallel.d = -10;  // x = 10: parallel, distinct — allowed (the coaxial case)
  EXPECT_EQ(make_implicit_blend(E.f1, E.f2, E.f10, parallel, 0.5, 1, B), Status::ok);
  const double bad[10] = {1, 0, 0, 0, 0, 0, 0, 0, 0, INFINITY};
  Quadric Q;
  EXPECT_EQ(make_quadric(bad, Q), Status::not_finite);
  const double plane_like[10] = {0, 0, 0, 0, 0, 0, 1, 0, 0, 0};
  EXPECT_EQ(make_quadric(plane_like, Q), Status::invalid_argument);
  const double zero_plane[4] = {0, 0, 0, 1};
  PlaneFn g;
  EXPECT_EQ(make_plane_fn(zero_plane, g), Status::invalid_argument);
  PlaneContourPoints pts;
  EXPECT_EQ(end_contour_points(E, 0, Vec3d::Zero(), pts), Status::invalid_argument);
  EXPECT_EQ(end_contour_points(E, 2, kV[0], pts), Status::invalid_argument);
  // v along R1's axis: every point of the end circle is a contour point.
  ASSERT_EQ(end_contour_points(E, 0, Vec3d::UnitX(), pts), Status::ok);
  EXPECT_TRUE(pts.whole_circle);
  EXPECT_EQ(pts.count, 0);
  Vec3d s;
  EXPECT_EQ(circle_center(Vec3d(0, 0, 0), Vec3d(1, 1, 1), Vec3d(2, 2, 2), s),
            Status::collinear_points);
  EXPECT_EQ(circle_center(Vec3d(0, 0, 0), Vec3d(NAN, 1, 1), Vec3d(2, 2, 2), s),
            Status::not_finite);
}

// (79) against the brute-force circumcentre: the point of the plane of
// p1, p2, p3 equidistant from them (a 3x3 linear solve).
TEST(ImplicitBlend, CircleCenterIsTheCircumcentre) {
  const Vec3d P[4][3] = {{Vec3d(1, 2, 3), Vec3d(-2, 0, 1), Vec3d(4, -1, 2)},
                         {Vec3d(0, 0, 0), Vec3d(3, 0, 0), Vec3d(0, 4, 0)},
                         {Vec3d(5, 5, -5), Vec3d(1, -3, 2), Vec3d(-7, 2, 9)},
                         {Vec3d(0.1, 0.2, 0.3), Vec3d(0.3, 0.1, 0.2), Vec3d(0.2, 0.3, 0.1)}};
  for (const auto& p : P) {
    Vec3d s;
    ASSERT_EQ(circle_center(p[0], p[1], p[2], s), Status::ok);
    Eigen::Matrix3d M;
    Vec3d r;
    M.row(0) = 2 * (p[1] - p[0]).transpose();
    r[0] = p[1].squaredNorm() - p[0].squaredNorm();
    M.row(1) = 2 * (p[2] - p[0]).transpose();
    r[1] = p[2].squaredNorm() - p[0].squaredNorm();
    const Vec3d n = (p[1] - p[0]).cross(p[2] - p[0]);
    M.row(2) = n.transpose();
    r[2] = n.dot(p[0]);
    const Vec3d brute = M.colPivHouseholderQr().solve(r);
    EXPECT_LE((s - brute).norm(), 1e-12 * (1 + brute.norm()));
  }
}

// (77), (78): the contour points of Example 7.6 on P1 and P2 satisfy f =
// f_v = 0 (absolute, to 1e-10) and the plane equation; on P1 they are
// (0, +-3, 0), (0, 0, +-3), (0, -+3/sqrt2, +-3/sqrt2).
TEST(PaperSeed001Implicit, Example76ContourPointsOnTheBoundingPlanes) {
  const ImplicitBlend B = example76();
  for (int end = 0; end < 2; ++end)
    for (const Vec3d& v : kV) {
      PlaneContourPoints pts;
      ASSERT_EQ(end_contour_points(B, end, v, pts), Status::ok);
      ASSERT_EQ(pts.count, 2);
      for (int k = 0; k < 2; ++k) {
        const Vec3d& x = pts.points[k];
        const BlendJet<double> J = blend_eval(B, x, &v);
        EXPECT_LE(std::abs(J.f), 1e-10) << x.transpose();
        EXPECT_LE(std::abs(J.grad.dot(v)), 1e-10) << x.transpose();
        EXPECT_LE(std::abs((end == 0 ? B.f10 : B.f20).value(x)), 1e-12);
        if (end == 0) EXPECT_NEAR(x.norm(), 3.0, 1e-12);
        else EXPECT_NEAR((x - Vec3d(8, 2, 0)).norm(), 2.0, 1e-12);
      }
    }
  ContourPiece P;
  ASSERT_EQ(contour_piece(B, kV, P), Status::ok);
  // The end circles' centres (79): R1's (0,0,0), R2's (8, 2, 0).
  EXPECT_LE(P.s1.norm(), 1e-12);
  EXPECT_LE((P.s2 - Vec3d(8, 2, 0)).norm(), 1e-12);
  for (int i = 0; i < 3; ++i) {
    expect_on_contour(B, kV[i], P.p[i], 1e-12);
    expect_on_contour(B, kV[i], P.q[i], 1e-12);
    EXPECT_NEAR(P.tp[i].norm(), 1.0, 1e-14);
    EXPECT_GT(P.tp[i].dot(P.nA), 0);
    EXPECT_GT(P.tq[i].dot(P.nB), 0);
  }
}

// Example 7.6 end to end: one piece, then the refinement (84) into two.
TEST(PaperSeed001Implicit, Example76ApproximationAndRefinement) {
  const ImplicitBlend B = example76();
  optim::ImplicitApproxOptions o;
  Surface S[optim::kMaxImplicitPieces];
  int count = 0;
  optim::ImplicitApproxReport one, two;
  ASSERT_EQ(optim::approximate_implicit_blend(B, kV, o, S, count, one), Status::ok);
  ASSERT_EQ(count, 1);
  EXPECT_TRUE(std::isfinite(one.error87));
  EXPECT_LE(one.piece[0].omega, one.piece[0].omega_initial);
  // An exact ringed surface whose circles pass through c_v1, c_v2, c_v3.
  EXPECT_EQ(S[0].kind, SurfaceKind::ringed);
  const ContourPiece& P = one.data[0];
  for (int k = 0; k <= 16; ++k) {
    const double t = k / 16.0;
    Vec3d C, N;
    double r2 = 0;
    ASSERT_EQ(S[0].circle(t, C, N, r2), Status::ok);
    for (int i = 0; i < 3; ++i) {
      const Vec3d dp = one.piece[0].alpha[i] * P.tp[i], dq = one.piece[0].beta[i] * P.tq[i];
      const Vec3d c = ferguson(P.p[i], dp, P.q[i], dq, t);
      EXPECT_NEAR((c - C).squaredNorm(), r2, 1e-9 * (1 + r2)) << "t " << t << " i " << i;
      EXPECT_NEAR((c - C).dot(N), 0.0, 1e-9 * (1 + std::sqrt(r2)));
    }
  }
  // The ends of the surface are the end circles of R1 and R2.
  Vec3d C, N;
  double r2 = 0;
  ASSERT_EQ(S[0].circle(0.0, C, N, r2), Status::ok);
  EXPECT_LE(C.norm(), 1e-9);
  EXPECT_NEAR(r2, 9.0, 1e-9);
  ASSERT_EQ(S[0].circle(1.0, C, N, r2), Status::ok);
  EXPECT_LE((C - Vec3d(8, 2, 0)).norm(), 1e-9);
  EXPECT_NEAR(r2, 4.0, 1e-9);

  o.pieces = 2;
  ASSERT_EQ(optim::approximate_implicit_blend(B, kV, o, S, count, two), Status::ok);
  ASSERT_EQ(count, 2);
  // The cut plane's points lie on the contour curves (2D Newton).
  for (int i = 0; i < 3; ++i) expect_on_contour(B, kV[i], two.data[1].p[i], 1e-11);
  // The pieces meet in one circle.
  Vec3d C0, N0, C1, N1;
  double ra = 0, rb = 0;
  ASSERT_EQ(S[0].circle(1.0, C0, N0, ra), Status::ok);
  ASSERT_EQ(S[1].circle(0.0, C1, N1, rb), Status::ok);
  EXPECT_LE((C0 - C1).norm(), 1e-9);
  EXPECT_NEAR(ra, rb, 1e-9);
  EXPECT_TRUE(std::isfinite(two.error87));
  EXPECT_LT(two.error87, one.error87);
  std::printf("Example 7.6 (lambda 1/2, n 2): (87) one piece %.6g (Omega %.6g -> %.6g), "
              "two pieces (%.6g + %.6g)/2 = %.6g (Omega %.6g)\n",
              one.error87, one.piece[0].omega_initial, one.omega, two.piece[0].error87,
              two.piece[1].error87, two.error87, two.omega);
}

// The optimizer's validation: options out of range, zero or parallel
// directions, a direction without contour points; nothing written.
TEST(ImplicitBlend, OptimizerRefusesBadOptionsAndDirections) {
  const ImplicitBlend B = example76();
  Surface S[optim::kMaxImplicitPieces];
  int count = -7;
  optim::ImplicitApproxReport R;
  optim::ImplicitApproxOptions o;
  o.pieces = 0;
  EXPECT_EQ(optim::approximate_implicit_blend(B, kV, o, S, count, R), Status::invalid_argument);
  o = optim::ImplicitApproxOptions();
  o.pieces = optim::kMaxImplicitPieces + 1;
  EXPECT_EQ(optim::approximate_implicit_blend(B, kV, o, S, count, R), Status::invalid_argument);
  o = optim::ImplicitApproxOptions();
  o.psi_weight = NAN;
  EXPECT_EQ(optim::approximate_implicit_blend(B, kV, o, S, count, R), Status::not_finite);
  o = optim::ImplicitApproxOptions();
  o.nodes = 1;
  EXPECT_EQ(optim::approximate_implicit_blend(B, kV, o, S, count, R), Status::invalid_argument);
  o = optim::ImplicitApproxOptions();
  const Vec3d parallel[3] = {Vec3d(0, 0, 1), Vec3d(0, 0, -2), Vec3d(0, 1, 0)};
  EXPECT_EQ(optim::approximate_implicit_blend(B, parallel, o, S, count, R),
            Status::invalid_argument);
  const Vec3d zero[3] = {Vec3d(0, 0, 1), Vec3d::Zero(), Vec3d(0, 1, 0)};
  EXPECT_EQ(optim::approximate_implicit_blend(B, zero, o, S, count, R), Status::invalid_argument);
  // v = e1 is R1's axis: every point of P1's circle is a contour point.
  const Vec3d axis[3] = {Vec3d(1, 0, 0), Vec3d(0, 0, 1), Vec3d(0, 1, 0)};
  EXPECT_EQ(optim::approximate_implicit_blend(B, axis, o, S, count, R), Status::empty_real_locus);
  EXPECT_EQ(count, -7);
  // Zero iterations: the start cubics (alpha = beta = |q - p|), not reverted.
  o.max_iterations = 0;
  ASSERT_EQ(optim::approximate_implicit_blend(B, kV, o, S, count, R), Status::ok);
  EXPECT_EQ(R.piece[0].omega, R.piece[0].omega_initial);
  for (int i = 0; i < 3; ++i)
    EXPECT_DOUBLE_EQ(R.piece[0].alpha[i], (R.data[0].q[i] - R.data[0].p[i]).norm());
}

// The 2D Newton of the refinement converges to the contour point from a
// nearby start in an interior plane, and reports a non-finite start.
TEST(ImplicitBlend, PlaneNewtonFindsInteriorContourPoints) {
  const ImplicitBlend B = example76();
  ContourPiece P;
  ASSERT_EQ(contour_piece(B, kV, P), Status::ok);
  const Vec3d o = P.dbar(0.5), N = P.dbar_derivative(0.5);
  for (int i = 0; i < 3; ++i) {
    Vec3d x = P.dbar(0.5) + 0.5 * (P.p[i] - P.s1 + P.q[i] - P.s2);  // a rough start
    ASSERT_EQ(plane_contour_newton(B, kV[i], N, o, x), Status::ok) << i;
    expect_on_contour(B, kV[i], x, 1e-11);
    EXPECT_LE(std::abs(N.normalized().dot(x - o)), 1e-12 * (1 + x.norm()));
  }
  Vec3d bad(NAN, 0, 0);
  EXPECT_EQ(plane_contour_newton(B, kV[0], N, o, bad), Status::not_finite);
}

// Remark 7.5: both branches of the contour curve for v1 = (0, 0, 1) and
// one for v2 = (0, 1, 0) give an exact ringed surface through the three
// cubics as well.
TEST(PaperSeed001Implicit, Remark75TwoContourCurves) {
  const ImplicitBlend B = example76();
  optim::ImplicitApproxOptions o;
  o.two_curves = true;
  Surface S[optim::kMaxImplicitPieces];
  int count = 0;
  optim::ImplicitApproxReport R;
  const Vec3d v[3] = {kV[0], kV[1], Vec3d::Zero()};  // v[2] unused
  ASSERT_EQ(optim::approximate_implicit_blend(B, v, o, S, count, R), Status::ok);
  const ContourPiece& P = R.data[0];
  EXPECT_EQ(P.v[0], kV[0]);
  EXPECT_EQ(P.v[1], kV[0]);
  EXPECT_EQ(P.v[2], kV[1]);
  EXPECT_GT((P.p[0] - P.p[1]).norm(), 1.0);  // the two branches of one curve
  EXPECT_TRUE(std::isfinite(R.error87));
  for (int k = 0; k <= 8; ++k) {
    const double t = k / 8.0;
    Vec3d C, N;
    double r2 = 0;
    ASSERT_EQ(S[0].circle(t, C, N, r2), Status::ok);
    for (int i = 0; i < 3; ++i) {
      const Vec3d c = ferguson(P.p[i], Vec3d(R.piece[0].alpha[i] * P.tp[i]), P.q[i],
                               Vec3d(R.piece[0].beta[i] * P.tq[i]), t);
      EXPECT_NEAR((c - C).squaredNorm(), r2, 1e-9 * (1 + r2));
    }
  }
  std::printf("Remark 7.5 (v1 both branches, v2): (87) %.6g, Omega %.6g\n", R.error87, R.omega);
}

// Random pairs of cylinders (radius 1..3, axes through the bounding
// planes' circles): the contour points on the planes lie on f = f_v = 0
// and on the plane (relative to the gradients, 1e-9).
RC_GTEST_PROP(ImplicitBlendProperties, EndContourPointsLieOnTheContourAndThePlane, ()) {
  auto dy = [] { return *rc::gen::inRange(-32, 33) / 8.0; };
  const Vec3d a1(dy(), dy(), dy()), a2(dy(), dy(), dy()), u1(dy(), dy(), dy()),
      u2(dy(), dy(), dy()), v(dy(), dy(), dy());
  RC_PRE(u1.norm() > 0.1 && u2.norm() > 0.1 && v.norm() > 0.1);
  const double r1 = 1 + *rc::gen::inRange(0, 17) / 8.0, r2 = 1 + *rc::gen::inRange(0, 17) / 8.0;
  Quadric f1, f2;
  RC_ASSERT(make_cylinder(a1, u1, r1, f1) == Status::ok);
  RC_ASSERT(make_cylinder(a2, u2, r2, f2) == Status::ok);
  // Planes perpendicular to the axes through a1, a2 (as for Example 7.6).
  PlaneFn g1{u1, -u1.dot(a1)}, g2{u2, -u2.dot(a2)};
  ImplicitBlend B;
  const double lambda = *rc::gen::inRange(1, 8) / 8.0;
  const int n = *rc::gen::inRange(1, 4);
  const Status made = make_implicit_blend(f1, f2, g1, g2, lambda, n, B);
  RC_PRE(made == Status::ok);
  for (int end = 0; end < 2; ++end) {
    PlaneContourPoints pts;
    const Status st = end_contour_points(B, end, v, pts);
    RC_ASSERT(st == Status::ok || st == Status::singular_point);
    if (st != Status::ok) continue;
    RC_ASSERT(pts.count <= 2);
    const PlaneFn& g = end == 0 ? B.f10 : B.f20;
    for (int k = 0; k < pts.count; ++k) {
      const Vec3d& x = pts.points[k];
      const BlendJet<double> J = blend_eval(B, x, &v);
      const double scale = 1 + x.norm();
      RC_ASSERT(std::abs(g.value(x)) <= 1e-12 * g.n.norm() * scale);
      RC_ASSERT(std::abs(J.f) <= 1e-9 * J.grad.norm() * scale);
      RC_ASSERT(std::abs(J.grad.dot(v)) <=
                1e-9 * (J.hv.norm() * scale + J.grad.norm() * v.norm()));
    }
  }
}
