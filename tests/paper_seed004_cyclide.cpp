// Seed 004 §4.1 (Peternell-Pottmann), parabolic Dupin cyclides: every worked
// statement of the section as a test (labels "laguerre;paper"). Each check
// compares against an independent computation: the implicit equation (4.2),
// its gradient, the dual planes' incidence, closed forms, or elementary
// geometry; never against the code's own output.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "cyclide/bezier_triangle.hpp"
#include "cyclide/laguerre.hpp"
#include "cyclide/parabolic_cyclide.hpp"
#include "cyclide/surface.hpp"

using namespace cyclide;

namespace {

// |(4.2)| over the sum of the absolute values of its terms at X.
double implicit_rel(double a, double b, const Vec4d& X) {
  const double x0 = X[0], x1 = X[1], x2 = X[2], x3 = X[3];
  const double r2 = x1 * x1 + x2 * x2 + x3 * x3;
  const double F = x0 * (b * x1 * x1 + a * x2 * x2 + (a + b) * x3 * x3) -
                   x3 * (a * b * x0 * x0 + r2);
  const double S = std::abs(x0) * (std::abs(b) * x1 * x1 + std::abs(a) * x2 * x2 +
                                   std::abs(a + b) * x3 * x3) +
                   std::abs(x3) * (std::abs(a * b) * x0 * x0 + r2);
  return std::abs(F) / (S + 1e-300);
}
double implicit_rel(const ParabolicCyclide& c, const Vec3d& x) {
  const Vec3d l = c.frame.transpose() * (x - c.origin);
  return implicit_rel(c.a, c.b, Vec4d(1, l[0], l[1], l[2]));
}

// Homogeneous gradient of (4.2) (the tangent plane at a regular point).
Vec4d implicit_gradient(double a, double b, const Vec4d& X) {
  const double x0 = X[0], x1 = X[1], x2 = X[2], x3 = X[3];
  const double r2 = x1 * x1 + x2 * x2 + x3 * x3;
  return Vec4d(b * x1 * x1 + a * x2 * x2 + (a + b) * x3 * x3 - 2 * a * b * x0 * x3,
               2 * b * x0 * x1 - 2 * x3 * x1, 2 * a * x0 * x2 - 2 * x3 * x2,
               2 * (a + b) * x0 * x3 - (a * b * x0 * x0 + r2) - 2 * x3 * x3);
}

// Angle-free parallelism of two R^4 vectors: |p ^ q| / (|p| |q|).
double parallel_defect(const Vec4d& p, const Vec4d& q) {
  double m = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) m = std::max(m, std::abs(p[i] * q[j] - p[j] * q[i]));
  return m / (p.norm() * q.norm());
}

// Homogeneous point of an affine point.
Vec4d hom(const Vec3d& x) { return Vec4d(1, x[0], x[1], x[2]); }

struct AB {
  double a, b;
};
const AB kSamples[] = {{1, 2}, {2, 0.5}, {1, -1}, {-1.5, 0.7}, {0, 1}, {1.3, 0}};

}  // namespace

// (4.1) satisfies (4.2), and (4.3) consists of its tangent planes: psi . phi = 0
// and psi is the gradient of (4.2) at phi.
TEST(Seed004Cyclide, Eq41SatisfiesEq42AndEq43IsItsDual) {
  for (const AB& s : kSamples)
    for (double u = -2.5; u <= 2.5; u += 0.5)
      for (double v = -2.25; v <= 2.5; v += 0.75) {
        const Vec4d X = parabolic_cyclide_phi(s.a, s.b, u, v);
        const Vec4d expect(1 + u * u + v * v, s.a * u + (s.a - s.b) * u * v * v,
                           s.b * v + (s.b - s.a) * u * u * v, s.a * u * u + s.b * v * v);
        EXPECT_LT((X - expect).norm(), 1e-14 * expect.norm());
        EXPECT_LT(implicit_rel(s.a, s.b, X), 1e-14) << s.a << " " << s.b << " " << u << " " << v;
        const Vec4d P = parabolic_cyclide_psi(s.a, s.b, u, v);
        EXPECT_LT(std::abs(P.dot(X)), 1e-13 * P.norm() * X.norm());
        const Vec4d G = implicit_gradient(s.a, s.b, X);
        if (G.norm() > 1e-6 * X.squaredNorm()) {  // regular point
          EXPECT_LT(parallel_defect(G, P), 1e-12) << s.a << " " << s.b << " " << u << " " << v;
        }
      }
}

// (4.3) = Lambda^{-1} of the graph y3 = -(a y1^2 + b y2^2) / 2 (isotropic_dual_plane).
TEST(Seed004Cyclide, Eq43IsLambdaInverseOfAParaboloid) {
  const double a = 1.5, b = -0.5;
  for (double u = -2; u <= 2; u += 0.5)
    for (double v = -2; v <= 2; v += 0.5) {
      const Vec4d P = parabolic_cyclide_psi(a, b, u, v);
      const Vec4d D = isotropic_dual_plane(Vec3d(u, v, -(a * u * u + b * v * v) / 2));
      EXPECT_LT((P - D).norm(), 1e-15 * (1 + P.norm()));
    }
}

// The types of §4.1: horn ab > 0, ring ab < 0, thorn a = 0 or b = 0, sphere a = b.
TEST(Seed004Cyclide, Types) {
  EXPECT_EQ(parabolic_cyclide_type(1, 2), ParabolicCyclideType::horn);
  EXPECT_EQ(parabolic_cyclide_type(-1, -3), ParabolicCyclideType::horn);
  EXPECT_EQ(parabolic_cyclide_type(1, -2), ParabolicCyclideType::ring);
  EXPECT_EQ(parabolic_cyclide_type(0, 2), ParabolicCyclideType::thorn);
  EXPECT_EQ(parabolic_cyclide_type(2, 0), ParabolicCyclideType::thorn);
  EXPECT_EQ(parabolic_cyclide_type(2, 2), ParabolicCyclideType::sphere);
  EXPECT_EQ(parabolic_cyclide_type(0, 0), ParabolicCyclideType::point);
  ParabolicCyclide c;
  c.a = c.b = 0;
  Vec3d x(7, 7, 7);
  EXPECT_EQ(parabolic_cyclide_point(c, 0.5, 0.5, x), Status::degenerate_cyclide);
  EXPECT_EQ(x, Vec3d(7, 7, 7));
}

// ERRATA 004: for a = b, (4.2) factors into the plane x3 = a x0 and the sphere
// |x|^2 = a x0 x3 (centre (0, 0, a/2), radius |a|/2), and (4.1) is that sphere.
TEST(Seed004Cyclide, ErrataSphereCase) {
  const double a = 1.7;
  for (double x1 = -1; x1 <= 1; x1 += 0.4)
    for (double x3 = -1; x3 <= 2; x3 += 0.5) {
      const Vec4d X(0.8, x1, 0.3 - x1, x3);
      const double r2 = X.tail<3>().squaredNorm();
      const double lhs = parabolic_cyclide_implicit(a, a, X);
      EXPECT_NEAR(lhs, (a * X[0] - X[3]) * (r2 - a * X[0] * X[3]), 1e-13);
    }
  ParabolicCyclide c;
  c.a = c.b = a;
  for (double u = -3; u <= 3; u += 0.75) {
    Vec3d x;
    ASSERT_EQ(parabolic_cyclide_point(c, u, 0.4 * u - 1, x), Status::ok);
    EXPECT_NEAR((x - Vec3d(0, 0, a / 2)).norm(), a / 2, 1e-14);
    Vec2d uv;
    ASSERT_EQ(parameter_of(c, x, uv), Status::ok);
    EXPECT_NEAR(uv[0], u, 1e-12);
    EXPECT_NEAR(uv[1], 0.4 * u - 1, 1e-12);
  }
}

// The lines e: x1 = 0, x3 = a and f: x2 = 0, x3 = b lie on Phi, are
// perpendicular, and carry a constant tangent plane (x3 = a, resp. x3 = b);
// Phi meets the plane at infinity in the absolute conic and g: x0 = x3 = 0.
TEST(Seed004Cyclide, ParabolicLinesAndCurveAtInfinity) {
  for (const AB& s : kSamples) {
    if (s.a == 0 || s.b == 0) continue;  // the thorn's tangent plane degenerates on a line
    ParabolicCyclide c;
    c.a = s.a;
    c.b = s.b;
    const Line3 e = parabolic_line_e(c), f = parabolic_line_f(c);
    EXPECT_NEAR(e.direction.dot(f.direction), 0, 1e-15);
    for (double t = -3; t <= 3; t += 0.5) {
      const Vec4d E = hom(e.point + t * e.direction), F = hom(f.point + t * f.direction);
      EXPECT_NEAR(E[1], 0, 0);
      EXPECT_NEAR(E[3], s.a, 1e-15);
      EXPECT_NEAR(F[2], 0, 0);
      EXPECT_NEAR(F[3], s.b, 1e-15);
      EXPECT_LT(implicit_rel(s.a, s.b, E), 1e-14);
      EXPECT_LT(implicit_rel(s.a, s.b, F), 1e-14);
      const Vec4d GE = implicit_gradient(s.a, s.b, E), GF = implicit_gradient(s.a, s.b, F);
      if (GE.norm() > 1e-9) {
        EXPECT_LT(parallel_defect(GE, Vec4d(-s.a, 0, 0, 1)), 1e-13);
      }
      if (GF.norm() > 1e-9) {
        EXPECT_LT(parallel_defect(GF, Vec4d(-s.b, 0, 0, 1)), 1e-13);
      }
    }
    // x0 = 0: (4.2) = -x3 (x1^2 + x2^2 + x3^2): the line g and the absolute conic j.
    const Vec4d X(0, 0.3, -1.2, 0.7);
    EXPECT_NEAR(parabolic_cyclide_implicit(s.a, s.b, X), -X[3] * X.squaredNorm(), 1e-14);
    EXPECT_EQ(parabolic_cyclide_implicit(s.a, s.b, Vec4d(0, 0.3, -1.2, 0)), 0.0);
  }
}

// "For a plane through e or f, the intersection with Phi is a circle. These
// circles (parameter lines of (4.1)) are principal curvature lines."
TEST(Seed004Cyclide, ParameterLinesAreCirclesInPlanesThroughEAndF) {
  ParabolicCyclide c;
  c.a = 1.2;
  c.b = -0.7;
  c.frame = Eigen::AngleAxisd(0.7, Vec3d(1, 2, 3).normalized()).toRotationMatrix();
  c.origin = Vec3d(0.5, -1, 2);
  const Line3 e = parabolic_line_e(c), f = parabolic_line_f(c);
  for (double p = -2; p <= 2; p += 0.5) {
    Circle3 U, V;
    ASSERT_EQ(parabolic_u_circle(c, p, U), Status::ok);
    ASSERT_EQ(parabolic_v_circle(c, p, V), Status::ok);
    EXPECT_NEAR(U.normal.norm(), 1, 1e-15);
    // The plane of U contains e, the plane of V contains f.
    for (double t : {-2.0, 0.0, 3.0}) {
      EXPECT_NEAR(U.normal.dot(e.point + t * e.direction - U.centre), 0, 1e-13);
      EXPECT_NEAR(V.normal.dot(f.point + t * f.direction - V.centre), 0, 1e-13);
    }
    for (double q = -4; q <= 4; q += 0.25) {
      Vec3d x, y;
      ASSERT_EQ(parabolic_cyclide_point(c, p, q, x), Status::ok);  // u = p fixed
      ASSERT_EQ(parabolic_cyclide_point(c, q, p, y), Status::ok);  // v = p fixed
      EXPECT_NEAR((x - U.centre).norm(), U.radius, 1e-13);
      EXPECT_NEAR(U.normal.dot(x - U.centre), 0, 1e-13);
      EXPECT_NEAR((y - V.centre).norm(), V.radius, 1e-13);
      EXPECT_NEAR(V.normal.dot(y - V.centre), 0, 1e-13);
    }
  }
}

// Thm 4.1: the graph of q = -(a y1^2 + b y2^2) gives the normal form itself, and
// a general quadratic gives a moved normal form: its envelope points satisfy
// (4.2) in the cyclide's frame, and the parameters are y = frame (u, v).
TEST(Seed004Cyclide, Theorem41QuadraticGraphsAreParabolicCyclides) {
  GraphQuadratic q0;
  q0.q20 = -1.5;
  q0.q02 = 0.5;
  ParabolicCyclide c0;
  ASSERT_EQ(parabolic_cyclide_from_quadratic(q0, c0), Status::ok);
  EXPECT_NEAR(c0.a, 1.5, 1e-15);
  EXPECT_NEAR(c0.b, -0.5, 1e-15);
  EXPECT_LT((c0.frame - Eigen::Matrix3d::Identity()).norm(), 1e-15);
  EXPECT_LT(c0.origin.norm(), 1e-15);

  GraphQuadratic q{0.3, -1.1, -0.8, 0.4, -0.6, 0.25};
  ParabolicCyclide c;
  ASSERT_EQ(parabolic_cyclide_from_quadratic(q, c), Status::ok);
  EXPECT_NEAR(c.frame(2, 2), 1, 1e-15);
  for (double y1 = -2; y1 <= 2; y1 += 0.5)
    for (double y2 = -2; y2 <= 2; y2 += 0.5) {
      Vec4d X;
      ASSERT_EQ(graph_envelope_point(q, Vec2d(y1, y2), X), Status::ok);
      EXPECT_NEAR(X[0], 4 * (1 + y1 * y1 + y2 * y2), 1e-13);
      const Vec3d x = X.tail<3>() / X[0];
      EXPECT_LT(implicit_rel(c, x), 1e-13);
      const Vec2d w = c.frame.topLeftCorner<2, 2>().transpose() * Vec2d(y1, y2);
      Vec3d p;
      ASSERT_EQ(parabolic_cyclide_point(c, w[0], w[1], p), Status::ok);
      EXPECT_LT((p - x).norm(), 1e-13 * (1 + x.norm()));
    }
  // A sphere results when the quadratic part is a multiple of y1^2 + y2^2.
  GraphQuadratic s{-0.7, 0, -0.7, 0.2, 0.4, -0.1};
  ParabolicCyclide cs;
  ASSERT_EQ(parabolic_cyclide_from_quadratic(s, cs), Status::ok);
  EXPECT_EQ(parabolic_cyclide_type(cs.a, cs.b), ParabolicCyclideType::sphere);
  // A point (a = b = 0): the paraboloid of a cycle of radius 0, (2.4).
  const Cycle z{Vec3d(0.3, -0.2, 0.5), 0};
  const IsotropicParaboloid Pz = cycle_to_paraboloid(z);
  GraphQuadratic qp{-Pz.k, 0, -Pz.k, -2 * Pz.l1, -2 * Pz.l2, -Pz.c0};  // q = 2 y3
  ParabolicCyclide cp;
  EXPECT_EQ(parabolic_cyclide_from_quadratic(qp, cp), Status::degenerate_cyclide);
}

// §4.1: "Offsetting needs not preserve the type": the dilatation (2.6)
// q -> q - d (1 + |y|^2) gives the offset s + d n; horn (1, 2) at d = -0.75
// becomes the ring (-0.5, 0.5).
TEST(Seed004Cyclide, OffsetsAreCyclidesOfPossiblyAnotherType) {
  GraphQuadratic q{-1, 0, -2, 0, 0, 0};  // the horn (a, b) = (1, 2)
  const double d = -0.75;
  ParabolicCyclide c, co;
  ASSERT_EQ(parabolic_cyclide_from_quadratic(q, c), Status::ok);
  ASSERT_EQ(parabolic_cyclide_from_quadratic(offset_quadratic(q, d), co), Status::ok);
  EXPECT_EQ(parabolic_cyclide_type(c.a, c.b), ParabolicCyclideType::horn);
  EXPECT_EQ(parabolic_cyclide_type(co.a, co.b), ParabolicCyclideType::ring);
  EXPECT_NEAR(co.a, -0.5, 1e-15);
  EXPECT_NEAR(co.b, 0.5, 1e-15);
  for (double u = -2; u <= 2; u += 0.5)
    for (double v = -2; v <= 2; v += 0.5) {
      Vec3d x, n;
      ASSERT_EQ(parabolic_cyclide_point(c, u, v, x), Status::ok);
      ASSERT_EQ(parabolic_cyclide_normal(c, u, v, n), Status::ok);
      EXPECT_LT(implicit_rel(co, x + d * n), 1e-13);
    }
}

// Thm 4.2 and Remark 4.1: u = t, v = lambda t + mu in (4.3) is a cone of
// revolution touching Phi along the cubic circle c(t) = phi(t, lambda t + mu),
// an isophote; mu = 0 gives a cylinder, lambda = 0 a circle and the line e.
TEST(Seed004Cyclide, Theorem42ConesOfRevolutionAlongCubicCircles) {
  ParabolicCyclide c;
  c.a = 1;
  c.b = 2.5;
  for (double lambda : {-1.5, 0.0, 0.4, 2.0})
    for (double mu : {-1.0, 0.0, 0.7}) {
      RevolutionCone K;
      ASSERT_EQ(cubic_circle_cone(c, lambda, mu, K), Status::ok);
      EXPECT_EQ(K.cylinder, mu == 0);
      EXPECT_EQ(K.circle_and_line, lambda == 0);
      double cos_first = 0;
      for (double t = -3; t <= 3; t += 0.5) {
        const double v = lambda * t + mu;
        const Vec4d P = parabolic_cyclide_psi(c.a, c.b, t, v);
        Vec3d x;
        ASSERT_EQ(cubic_circle_point(c, lambda, mu, t, x), Status::ok);
        EXPECT_LT(std::abs(P.dot(hom(x))), 1e-13 * P.norm() * hom(x).norm());  // c(t) on Gamma(t)
        EXPECT_LT(implicit_rel(c.a, c.b, hom(x)), 1e-13);                     // c(t) on Phi
        const Vec4d G = implicit_gradient(c.a, c.b, hom(x));
        EXPECT_LT(parallel_defect(G, P), 1e-12);  // Gamma(t) is Phi's tangent plane
        const Vec3d n = P.tail<3>() / P.tail<3>().norm();
        const double cosang = n.dot(K.axis);
        if (t == -3) cos_first = cosang;
        EXPECT_NEAR(cosang, cos_first, 1e-14);  // isophote
        EXPECT_NEAR(std::abs(cosang), std::sin(K.half_angle), 1e-14);
        if (!K.cylinder) {
          EXPECT_LT(std::abs(P.dot(hom(K.apex))), 1e-12 * P.norm() * hom(K.apex).norm());
          // The generator apex -> c(t) makes the half-angle with the axis.
          const Vec3d g = (x - K.apex).normalized();
          EXPECT_NEAR(std::abs(g.dot(K.axis)), std::cos(K.half_angle), 1e-12);
        }
      }
      if (lambda == 0) {  // Gamma also touches Phi along e: its planes tend to x3 = a
        const Vec4d P = parabolic_cyclide_psi(c.a, c.b, 1e6, mu) / 1e12;
        EXPECT_LT(parallel_defect(P, Vec4d(-c.a, 0, 0, 1)), 1e-6);
      }
    }
  RevolutionCone K;
  ParabolicCyclide r;  // ring a = 1, b = -1: lambda = 1, mu = 0 gives a + b lambda^2 = 0
  EXPECT_EQ(cubic_circle_cone(r, 1, 0, K), Status::dependent_planes);
}

// Remark 4.2: the net line through phi(u, v) meeting e and f hits x3 = c at
// ((a - c) u, (b - c) v); it inverts the parameterization.
TEST(Seed004Cyclide, Remark42NetProjection) {
  ParabolicCyclide c;
  c.a = 0.8;
  c.b = -1.3;
  c.frame = Eigen::AngleAxisd(-1.1, Vec3d(0.2, -1, 0.5).normalized()).toRotationMatrix();
  c.origin = Vec3d(3, 1, -2);
  const Line3 e = parabolic_line_e(c), f = parabolic_line_f(c);
  for (double u = -2; u <= 2; u += 0.5)
    for (double v = -2; v <= 2; v += 0.5)
      for (double cc : {-2.0, 0.1, 3.0}) {
        Vec3d x;
        ASSERT_EQ(parabolic_cyclide_point(c, u, v, x), Status::ok);
        Vec2d p;
        const Status st = net_projection(c, x, cc, p);
        const Vec3d l = c.frame.transpose() * (x - c.origin);
        if (std::abs(l[2] - c.a) < 1e-9 || std::abs(l[2] - c.b) < 1e-9) continue;
        ASSERT_EQ(st, Status::ok);
        EXPECT_NEAR(p[0], (c.a - cc) * u, 1e-12);
        EXPECT_NEAR(p[1], (c.b - cc) * v, 1e-12);
        // The line from x to the image point meets e and f (coplanar with each).
        const Vec3d img = c.origin + c.frame * Vec3d(p[0], p[1], cc);
        const Vec3d d = img - x;
        EXPECT_NEAR(d.cross(e.direction).dot(e.point - x), 0, 1e-11 * d.norm());
        EXPECT_NEAR(d.cross(f.direction).dot(f.point - x), 0, 1e-11 * d.norm());
        Vec2d uv;
        ASSERT_EQ(parameter_of(c, x, uv), Status::ok);
        EXPECT_NEAR(uv[0], u, 1e-12);
        EXPECT_NEAR(uv[1], v, 1e-12);
        // Independent inversion read off (4.1): x1 = -u (x3 - a), x2 = -v (x3 - b).
        EXPECT_NEAR(uv[0], l[0] / (c.a - l[2]), 1e-12);
        // Off Phi: a point of the same net line (through E = (0, (b - a) v, a) and
        // F = ((a - b) u, 0, b), local) has the parameter of its third point on Phi.
        const Vec3d E(0, (c.b - c.a) * v, c.a), F((c.a - c.b) * u, 0, c.b);
        const Vec3d off = c.origin + c.frame * (l + 0.37 * (F - E));
        Vec2d uv_off;
        ASSERT_EQ(parameter_of(c, off, uv_off), Status::ok);
        EXPECT_NEAR(uv_off[0], u, 1e-11);
        EXPECT_NEAR(uv_off[1], v, 1e-11);
      }
  // Points of e and f: their parameter is at infinity.
  Vec2d uv(9, 9);
  EXPECT_EQ(parameter_of(c, e.point + 0.3 * e.direction, uv), Status::point_at_infinity);
  EXPECT_EQ(parameter_of(c, f.point - 2 * f.direction, uv), Status::point_at_infinity);
  EXPECT_EQ(uv, Vec2d(9, 9));
}

// §4.1: a quadratic Bezier triangle on the paraboloid becomes a rational cubic
// Bezier triangle on the cyclide (the exterior product of the de Casteljau
// planes), and parallelograms become rational bicubics (Fig. 1's horn patch).
TEST(Seed004Cyclide, CubicTriangleAndBicubicPatchOnTheNormalForm) {
  const double a = 1, b = 2;  // a horn cyclide, as in Fig. 1
  // Bezier ordinates of z = -(a y1^2 + b y2^2) / 2 from its blossom.
  QuadraticGraphTriangle T;
  T.vertex[0] = Vec2d(-1, -0.5);
  T.vertex[1] = Vec2d(1.5, -0.2);
  T.vertex[2] = Vec2d(0.1, 1.2);
  static const int kPair[6][2] = {{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2}, {2, 2}};
  for (int i = 0; i < 6; ++i) {
    const Vec2d& A = T.vertex[kPair[i][0]];
    const Vec2d& B = T.vertex[kPair[i][1]];
    T.ordinate[i] = -(a * A[0] * B[0] + b * A[1] * B[1]) / 2;
  }
  RationalCubicTriangle C;
  ASSERT_EQ(cyclide_cubic_triangle(T, C), Status::ok);
  for (double r = 0; r <= 1; r += 0.125)
    for (double s = 0; r + s <= 1; s += 0.125) {
      const double t = 1 - r - s;
      const Vec2d y = r * T.vertex[0] + s * T.vertex[1] + t * T.vertex[2];
      const Vec4d phi = parabolic_cyclide_phi(a, b, y[0], y[1]);
      Vec3d x;
      ASSERT_EQ(evaluate(C, r, s, t, x), Status::ok);
      EXPECT_LT((x - phi.tail<3>() / phi[0]).norm(), 1e-13);
      EXPECT_GT(evaluate_homogeneous(C, r, s, t)[0], 0);
    }
  GraphQuadratic q{-a, 0, -b, 0, 0, 0};
  RationalBicubicPatch B;
  const Vec2d corner(-0.5, -1), e1(1.5, 0.5), e2(-0.3, 2);
  ASSERT_EQ(cyclide_bicubic_patch(q, corner, e1, e2, B), Status::ok);
  for (double s = 0; s <= 1; s += 0.125)
    for (double t = 0; t <= 1; t += 0.125) {
      const Vec2d y = corner + s * e1 + t * e2;
      const Vec4d phi = parabolic_cyclide_phi(a, b, y[0], y[1]);
      Vec3d x;
      ASSERT_EQ(evaluate(B, s, t, x), Status::ok);
      EXPECT_LT((x - phi.tail<3>() / phi[0]).norm(), 1e-13);
    }
}

// Weights <= 0 do occur in the control net (the weight's quadratic Bernstein
// coefficients are 1 + A.B), while the weight polynomial stays positive; a
// general rational patch whose weight vanishes reports point_at_infinity.
TEST(Seed004Cyclide, WeightsAndPointsAtInfinity) {
  QuadraticGraphTriangle T;
  T.vertex[0] = Vec2d(2, 0);
  T.vertex[1] = Vec2d(-2, 0);
  T.vertex[2] = Vec2d(0, 2);
  RationalCubicTriangle C;
  ASSERT_EQ(cyclide_cubic_triangle(T, C), Status::ok);
  double wmin = 1e300;
  for (const auto& p : C.control) wmin = std::min(wmin, p[0]);
  EXPECT_LT(wmin, 0);
  for (double r = 0; r <= 1; r += 0.1)
    for (double s = 0; r + s <= 1 + 1e-12; s += 0.1) {
      const double t = std::max(0.0, 1 - r - s);
      const Vec2d y = r * T.vertex[0] + s * T.vertex[1] + t * T.vertex[2];
      // weight = |det K| (1 + |y|^2), det K = 8.
      EXPECT_NEAR(evaluate_homogeneous(C, r, s, t)[0], 8 * (1 + y.squaredNorm()), 1e-12 * 8 * (1 + y.squaredNorm()));
    }
  RationalCubicTriangle Z = C;
  for (auto& p : Z.control) p[0] = 0;
  Vec3d x(5, 5, 5);
  EXPECT_EQ(evaluate(Z, 0.2, 0.3, 0.5, x), Status::point_at_infinity);
  EXPECT_EQ(x, Vec3d(5, 5, 5));
  T.vertex[2] = Vec2d(0, 0);  // collinear domain
  EXPECT_EQ(cyclide_cubic_triangle(T, C), Status::collinear_points);
}

// House rules: invalid inputs are reported and leave the outputs untouched.
TEST(Seed004Cyclide, InvalidInputsAreReported) {
  const Vec3d sentinel(4, 4, 4);
  ParabolicCyclide c;
  Vec3d x = sentinel;
  c.a = std::nan("");
  EXPECT_EQ(parabolic_cyclide_point(c, 0, 0, x), Status::not_finite);
  c.a = 1e101;
  EXPECT_EQ(parabolic_cyclide_point(c, 0, 0, x), Status::not_finite);
  c.a = 1;
  c.frame(0, 0) = 2;  // not a rotation
  EXPECT_EQ(parabolic_cyclide_point(c, 0, 0, x), Status::invalid_argument);
  c.frame = Eigen::Matrix3d::Identity();
  EXPECT_EQ(parabolic_cyclide_point(c, std::nan(""), 0, x), Status::not_finite);
  EXPECT_EQ(x, sentinel);
  // A frame that is not a rotation about x3 has no quadratic (4.4).
  c.frame = Eigen::AngleAxisd(0.3, Vec3d(1, 0, 0)).toRotationMatrix();
  GraphQuadratic q{1, 2, 3, 4, 5, 6};
  EXPECT_EQ(quadratic_of_parabolic_cyclide(c, q), Status::invalid_argument);
  EXPECT_EQ(q.q00, 6);
  ParabolicCyclide out;
  out.a = 7;
  EXPECT_EQ(parabolic_cyclide_from_quadratic(GraphQuadratic{1, 0, 0, std::nan(""), 0, 0}, out),
            Status::not_finite);
  EXPECT_EQ(out.a, 7);
  QuadraticGraphTriangle T;
  T.vertex[0] = Vec2d(0, 0);
  T.vertex[1] = Vec2d(1, 0);
  T.vertex[2] = Vec2d(0, 1);
  T.ordinate[3] = std::numeric_limits<double>::infinity();
  RationalCubicTriangle C;
  C.control[0] = Vec4d(9, 9, 9, 9);
  EXPECT_EQ(cyclide_cubic_triangle(T, C), Status::not_finite);
  EXPECT_EQ(C.control[0], Vec4d(9, 9, 9, 9));
  RationalBicubicPatch B;
  B.control[0][0] = Vec4d(9, 9, 9, 9);
  EXPECT_EQ(cyclide_bicubic_patch(q, Vec2d(0, 0), Vec2d(1, 1), Vec2d(2, 2), B),
            Status::collinear_points);
  EXPECT_EQ(B.control[0][0], Vec4d(9, 9, 9, 9));
  Vec2d uv(3, 3);
  ParabolicCyclide s;
  s.a = s.b = 1;  // a sphere: e and f meet, no hyperbolic net
  EXPECT_EQ(net_projection(s, Vec3d(0.1, 0.2, 0.3), 0.5, uv), Status::invalid_argument);
  EXPECT_EQ(uv, Vec2d(3, 3));
}

// The unity of the library: a parabolic Dupin cyclide is a rational family
// of circles (its u-lines, in planes through e), evaluated by the one
// quaternion-rotation evaluator of seed 000 (11) with f(u, v) = v; the
// Surface reproduces (4.1) exactly, with the touching spheres of a canal
// surface along its circles.
TEST(Seed004Cyclide, ParabolicCyclideIsACircleFamilySurface) {
  ParabolicCyclide c;
  c.a = 1.5;
  c.b = -0.75;  // a ring cyclide
  c.frame = Eigen::AngleAxisd(0.7, Vec3d(1, 2, -0.5).normalized()).toRotationMatrix();
  c.origin = Vec3d(3, -1, 2);
  Surface S;
  ASSERT_EQ(make_parabolic_cyclide_surface(c, -2, 2, S), Status::ok);
  EXPECT_EQ(S.kind, SurfaceKind::parabolic);
  for (double u : {-2.0, -0.6, 0.0, 0.3, 1.7})
    for (double v : {-3.0, -0.4, 0.0, 0.8, 2.5, 40.0}) {
      Vec3d x, xu, xv, n, expect, n_expect;
      ASSERT_EQ(S.eval(u, v, {x.data(), xu.data(), xv.data(), n.data()}), Status::ok);
      ASSERT_EQ(parabolic_cyclide_point(c, u, v, expect), Status::ok);
      EXPECT_LE((x - expect).norm(), 1e-13 * (1 + expect.norm())) << u << " " << v;
      ASSERT_EQ(parabolic_cyclide_normal(c, u, v, n_expect), Status::ok);
      EXPECT_NEAR(std::abs(n.dot(n_expect)), 1.0, 1e-12);
      // x_u, x_v against central differences of (4.1).
      const double h = 1e-6;
      Vec3d a1, a2;
      ASSERT_EQ(parabolic_cyclide_point(c, u + h, v, a1), Status::ok);
      ASSERT_EQ(parabolic_cyclide_point(c, u - h, v, a2), Status::ok);
      EXPECT_LE((xu - (a1 - a2) / (2 * h)).norm(), 1e-7 * (1 + xu.norm()));
      ASSERT_EQ(parabolic_cyclide_point(c, u, v + h, a1), Status::ok);
      ASSERT_EQ(parabolic_cyclide_point(c, u, v - h, a2), Status::ok);
      EXPECT_LE((xv - (a1 - a2) / (2 * h)).norm(), 1e-7 * (1 + xv.norm()));
      // The touching sphere along the u-circle: x = m + rho n.
      Vec3d m;
      double r2 = 0;
      ASSERT_EQ(S.sphere(u, m, r2), Status::ok);
      EXPECT_NEAR((x - m).norm(), std::sqrt(r2), 1e-12 * (1 + x.norm()));
      EXPECT_NEAR(std::abs((x - m).normalized().dot(n_expect)), 1.0, 1e-12);
    }
  // The circles are the closed-form u-circles.
  for (double u : {-1.0, 0.5}) {
    Vec3d centre, normal;
    double r2;
    ASSERT_EQ(S.circle(u, centre, normal, r2), Status::ok);
    Circle3 C;
    ASSERT_EQ(parabolic_u_circle(c, u, C), Status::ok);
    EXPECT_LE((centre - C.centre).norm(), 1e-13 * (1 + C.centre.norm()));
    EXPECT_NEAR(std::abs(normal.dot(C.normal)), 1.0, 1e-13);
    EXPECT_NEAR(std::sqrt(r2), C.radius, 1e-13 * (1 + C.radius));
  }
  // A horn cyclide's u-circle of radius 0, |b - (a - b) u^2| = 0 at
  // u^2 = b/(a - b): a singular point inside the domain is reported.
  ParabolicCyclide horn;
  horn.a = 2;
  horn.b = 1;  // radius 0 at u = +-1
  double bad = 0;
  EXPECT_EQ(make_parabolic_cyclide_surface(horn, 0.5, 1.5, S, &bad), Status::singular_point);
  EXPECT_NEAR(std::abs(bad), 1.0, 0.1);
  EXPECT_EQ(make_parabolic_cyclide_surface(horn, 1.2, 3, S), Status::ok);
  horn.a = horn.b = 0;
  EXPECT_EQ(make_parabolic_cyclide_surface(horn, 0, 1, S), Status::degenerate_cyclide);
  EXPECT_EQ(make_parabolic_cyclide_surface(c, 1, 0, S), Status::bad_domain);
}
