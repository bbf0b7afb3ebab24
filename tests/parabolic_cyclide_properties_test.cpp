// Seed 004 §4.1 properties over random well-conditioned inputs (labels
// "laguerre;property"): parabolic Dupin cyclides in random rigid frames, the
// family G from random quadratics (Thm 4.1), offsets, cones (Thm 4.2), the
// net projection (Remark 4.2), and the exact rational cubic triangles and
// bicubic patches (§4.1).
//
// Tolerances (named below so SPEC can quote them):
//
//   constant          value   meaning
//   kImplicitTol      1e-11   |(4.2)| / (sum of |terms| of (4.2)) at a point that lies on Phi
//                             (world points taken back to the frame: origins up to 5 cost digits)
//   kDerivedTol       1e-10   the same for a cyclide derived from a quadratic (Thm 4.1): its
//                             a, b and rotation carry the rounding of the 2x2 eigenproblem
//   kTangentTol       1e-10   |G ^ P| / (|G| |P|): gradient G of (4.2) vs the dual plane P
//                             (only where |G| >= 1e-6 |X|^2, away from singular points)
//   kCircleTol        1e-12   distances to a parameter circle / its plane, over (1 + |x|)
//   kAngleTol         1e-12   cos of the normals' angle with a cone axis vs sin(half-angle)
//   kNetTol           1e-11   net projection vs ((a - c) u, (b - c) v), over (1 + |c|)(1 + |u| + |v|)
//   kPatchTol         1e-12   |patch point - envelope point P ^ P_y1 ^ P_y2| / (1 + |x|)
//   kEdgeTol          1e-12   shared-edge control points after the weight scale, relative
//
// Inputs: a, b in [-2, 2] with |a|, |b|, |a - b| >= 0.1 (regular types),
// parameters in [-3, 3], quadratic coefficients in [-2, 2], cone parameters
// lambda in [-2, 2], |mu| in [0.1, 2], random rotations from normalized
// quaternions, origins in [-5, 5]^3, triangles with area >= 0.05 in [-2, 2]^2.

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "cyclide/bezier_triangle.hpp"
#include "cyclide/laguerre.hpp"
#include "cyclide/parabolic_cyclide.hpp"

using namespace cyclide;

namespace {

constexpr double kImplicitTol = 1e-11;
constexpr double kDerivedTol = 1e-10;
constexpr double kTangentTol = 1e-10;
constexpr double kCircleTol = 1e-12;
constexpr double kAngleTol = 1e-12;
constexpr double kNetTol = 1e-11;
constexpr double kPatchTol = 1e-12;
constexpr double kEdgeTol = 1e-12;

// Uniform at every size (inRange alone scales with RapidCheck's size).
double uniform(double lo, double hi) {
  const int k = *rc::gen::resize(100, rc::gen::inRange(0, 1 << 30));
  return lo + (hi - lo) * (k / double(1 << 30));
}
double away_from_zero(double lo, double hi) {  // |x| in [lo, hi], random sign
  const double m = uniform(lo, hi);
  const bool neg = *rc::gen::resize(100, rc::gen::inRange(0, 2)) == 1;
  return neg ? -m : m;
}

Eigen::Matrix3d random_rotation() {
  double q[4];
  for (double& x : q) x = uniform(-1, 1);
  RC_PRE(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3] >= 0.1);
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
}

ParabolicCyclide random_cyclide() {
  ParabolicCyclide c;
  c.a = away_from_zero(0.1, 2);
  c.b = away_from_zero(0.1, 2);
  RC_PRE(std::abs(c.a - c.b) >= 0.1);
  c.frame = random_rotation();
  const double o0 = uniform(-5, 5);
  const double o1 = uniform(-5, 5);
  const double o2 = uniform(-5, 5);
  c.origin = Vec3d(o0, o1, o2);
  return c;
}

GraphQuadratic random_quadratic() {
  GraphQuadratic q;
  q.q20 = uniform(-2, 2);
  q.q11 = uniform(-2, 2);
  q.q02 = uniform(-2, 2);
  q.q10 = uniform(-2, 2);
  q.q01 = uniform(-2, 2);
  q.q00 = uniform(-2, 2);
  return q;
}

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
Vec3d local(const ParabolicCyclide& c, const Vec3d& x) { return c.frame.transpose() * (x - c.origin); }
double implicit_rel(const ParabolicCyclide& c, const Vec3d& x) {
  const Vec3d l = local(c, x);
  return implicit_rel(c.a, c.b, Vec4d(1, l[0], l[1], l[2]));
}
Vec4d implicit_gradient(double a, double b, const Vec4d& X) {
  const double x0 = X[0], x1 = X[1], x2 = X[2], x3 = X[3];
  const double r2 = x1 * x1 + x2 * x2 + x3 * x3;
  return Vec4d(b * x1 * x1 + a * x2 * x2 + (a + b) * x3 * x3 - 2 * a * b * x0 * x3,
               2 * b * x0 * x1 - 2 * x3 * x1, 2 * a * x0 * x2 - 2 * x3 * x2,
               2 * (a + b) * x0 * x3 - (a * b * x0 * x0 + r2) - 2 * x3 * x3);
}
double parallel_defect(const Vec4d& p, const Vec4d& q) {
  double m = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) m = std::max(m, std::abs(p[i] * q[j] - p[j] * q[i]));
  return m / (p.norm() * q.norm());
}

// The envelope point of the graph y3 = q / 2 at y, computed here from the
// definition (independent of the library): P ^ P_y1 ^ P_y2 by a 4x4 cofactor
// expansion with Eigen determinants.
Vec3d envelope(const GraphQuadratic& q, const Vec2d& y) {
  const double y1 = y[0], y2 = y[1];
  const double qv = q.q20 * y1 * y1 + q.q11 * y1 * y2 + q.q02 * y2 * y2 + q.q10 * y1 + q.q01 * y2 + q.q00;
  Eigen::Matrix<double, 3, 4> M;
  M << qv, 2 * y1, 2 * y2, y1 * y1 + y2 * y2 - 1,  //
      2 * q.q20 * y1 + q.q11 * y2 + q.q10, 2, 0, 2 * y1,  //
      q.q11 * y1 + 2 * q.q02 * y2 + q.q01, 0, 2, 2 * y2;
  Vec4d X;
  for (int i = 0; i < 4; ++i) {
    Eigen::Matrix3d m;
    int col = 0;
    for (int j = 0; j < 4; ++j)
      if (j != i) m.col(col++) = M.col(j);
    X[i] = ((i % 2) ? -1.0 : 1.0) * m.determinant();
  }
  return X.tail<3>() / X[0];
}

// Ordinates of y3 = q / 2 over a triangle: the polar form of q / 2 at pairs of vertices.
double half_q_polar(const GraphQuadratic& q, const Vec2d& A, const Vec2d& B) {
  return (q.q20 * A[0] * B[0] + q.q11 * (A[0] * B[1] + A[1] * B[0]) / 2 + q.q02 * A[1] * B[1] +
          q.q10 * (A[0] + B[0]) / 2 + q.q01 * (A[1] + B[1]) / 2 + q.q00) /
         2;
}
QuadraticGraphTriangle triangle_of(const GraphQuadratic& q, const Vec2d V[3]) {
  static const int kPair[6][2] = {{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2}, {2, 2}};
  QuadraticGraphTriangle T;
  for (int i = 0; i < 3; ++i) T.vertex[i] = V[i];
  for (int i = 0; i < 6; ++i) T.ordinate[i] = half_q_polar(q, V[kPair[i][0]], V[kPair[i][1]]);
  return T;
}

void random_triangle(Vec2d V[3]) {
  for (int i = 0; i < 3; ++i) {
    const double x = uniform(-2, 2);
    const double y = uniform(-2, 2);
    V[i] = Vec2d(x, y);
  }
  const Vec2d d1 = V[1] - V[0], d2 = V[2] - V[0];
  RC_PRE(std::abs(d1.x() * d2.y() - d1.y() * d2.x()) >= 0.1);  // area >= 0.05
}

}  // namespace

RC_GTEST_PROP(ParabolicCyclideProperties, PointsSatisfyImplicitAndTangentPlanes, ()) {
  const ParabolicCyclide c = random_cyclide();
  const double u = uniform(-3, 3);
  const double v = uniform(-3, 3);
  Vec3d x, n;
  RC_ASSERT(parabolic_cyclide_point(c, u, v, x) == Status::ok);
  RC_ASSERT(parabolic_cyclide_normal(c, u, v, n) == Status::ok);
  RC_ASSERT(implicit_rel(c, x) <= kImplicitTol);
  const Vec3d l = local(c, x);
  const Vec4d X(1, l[0], l[1], l[2]);
  const Vec4d G = implicit_gradient(c.a, c.b, X);
  const Vec4d P = parabolic_cyclide_psi(c.a, c.b, u, v);
  if (G.norm() >= 1e-6 * X.squaredNorm()) RC_ASSERT(parallel_defect(G, P) <= kTangentTol);
  // The world normal is frame * (unit normal of (4.3)).
  RC_ASSERT((c.frame.transpose() * n - P.tail<3>() / P.tail<3>().norm()).norm() <= 1e-14);
}

RC_GTEST_PROP(ParabolicCyclideProperties, ParameterCirclesContainTheirLinesAndPoints, ()) {
  const ParabolicCyclide c = random_cyclide();
  const double p = uniform(-3, 3);
  const double q = uniform(-3, 3);
  const double t = uniform(-3, 3);
  Circle3 U, V;
  RC_ASSERT(parabolic_u_circle(c, p, U) == Status::ok);
  RC_ASSERT(parabolic_v_circle(c, p, V) == Status::ok);
  const Line3 e = parabolic_line_e(c), f = parabolic_line_f(c);
  const Vec3d ep = e.point + t * e.direction, fp = f.point + t * f.direction;
  RC_ASSERT(std::abs(U.normal.dot(ep - U.centre)) <= kCircleTol * (1 + ep.norm()));
  RC_ASSERT(std::abs(V.normal.dot(fp - V.centre)) <= kCircleTol * (1 + fp.norm()));
  Vec3d x, y;
  RC_ASSERT(parabolic_cyclide_point(c, p, q, x) == Status::ok);
  RC_ASSERT(parabolic_cyclide_point(c, q, p, y) == Status::ok);
  RC_ASSERT(std::abs((x - U.centre).norm() - U.radius) <= kCircleTol * (1 + x.norm()));
  RC_ASSERT(std::abs(U.normal.dot(x - U.centre)) <= kCircleTol * (1 + x.norm()));
  RC_ASSERT(std::abs((y - V.centre).norm() - V.radius) <= kCircleTol * (1 + y.norm()));
  RC_ASSERT(std::abs(V.normal.dot(y - V.centre)) <= kCircleTol * (1 + y.norm()));
  // e and f lie on Phi.
  RC_ASSERT(implicit_rel(c, ep) <= kImplicitTol);
  RC_ASSERT(implicit_rel(c, fp) <= kImplicitTol);
}

RC_GTEST_PROP(ParabolicCyclideProperties, QuadraticGraphsAreMovedNormalForms, ()) {
  const GraphQuadratic q = random_quadratic();
  ParabolicCyclide c;
  const Status st = parabolic_cyclide_from_quadratic(q, c);
  RC_PRE(st == Status::ok);
  RC_PRE(std::abs(c.a) + std::abs(c.b) >= 0.05);
  const double y1 = uniform(-3, 3);
  const double y2 = uniform(-3, 3);
  const Vec3d x = envelope(q, Vec2d(y1, y2));
  RC_ASSERT(implicit_rel(c, x) <= kDerivedTol);
  // Round trip q -> cyclide -> q.
  GraphQuadratic r;
  RC_ASSERT(quadratic_of_parabolic_cyclide(c, r) == Status::ok);
  const double d[6] = {r.q20 - q.q20, r.q11 - q.q11, r.q02 - q.q02,
                       r.q10 - q.q10, r.q01 - q.q01, r.q00 - q.q00};
  for (double e : d) RC_ASSERT(std::abs(e) <= 1e-13);
  // The offset at distance d: the graph q - d (1 + |y|^2) carries x + d n.
  const double dist = uniform(-2, 2);
  ParabolicCyclide co;
  RC_PRE(parabolic_cyclide_from_quadratic(offset_quadratic(q, dist), co) == Status::ok);
  OrientedPlane pl;
  IsotropicPoint ip;
  ip.y = Vec3d(y1, y2, 0);
  RC_ASSERT(isotropic_to_laguerre(ip, pl) == Status::ok);
  RC_ASSERT(implicit_rel(co, x + dist * pl.e) <= kDerivedTol);
}

RC_GTEST_PROP(ParabolicCyclideProperties, ConesOfRevolutionAlongCubicCircles, ()) {
  const ParabolicCyclide c = random_cyclide();
  const double lambda = uniform(-2, 2);
  const double mu = away_from_zero(0.1, 2);
  const double t = uniform(-3, 3);
  RevolutionCone K;
  RC_ASSERT(cubic_circle_cone(c, lambda, mu, K) == Status::ok);
  RC_ASSERT(!K.cylinder);
  Vec3d x;
  RC_ASSERT(cubic_circle_point(c, lambda, mu, t, x) == Status::ok);
  RC_ASSERT(implicit_rel(c, x) <= kImplicitTol);
  // Gamma(t) in world coordinates: the local plane P moved by the frame.
  const Vec4d P = parabolic_cyclide_psi(c.a, c.b, t, lambda * t + mu);
  const Vec3d l = local(c, x), la = local(c, K.apex);
  RC_ASSERT(std::abs(P.dot(Vec4d(1, l[0], l[1], l[2]))) <= 1e-12 * P.norm() * (1 + l.norm()));
  RC_ASSERT(std::abs(P.dot(Vec4d(1, la[0], la[1], la[2]))) <= 1e-11 * P.norm() * (1 + la.norm()));
  const Vec4d G = implicit_gradient(c.a, c.b, Vec4d(1, l[0], l[1], l[2]));
  if (G.norm() >= 1e-6 * (1 + l.squaredNorm())) RC_ASSERT(parallel_defect(G, P) <= kTangentTol);
  // Cone of revolution: normals at a constant angle with the axis (isophote).
  const Vec3d n = c.frame * P.tail<3>().normalized();
  RC_ASSERT(std::abs(n.dot(K.axis) - mu / std::sqrt(1 + lambda * lambda + mu * mu)) <= kAngleTol);
  RC_ASSERT(std::abs(std::abs(n.dot(K.axis)) - std::sin(K.half_angle)) <= kAngleTol);
  const Vec3d g = x - K.apex;
  if (g.norm() > 1e-3 * (1 + K.apex.norm()))
    RC_ASSERT(std::abs(std::abs(g.normalized().dot(K.axis)) - std::cos(K.half_angle)) <=
              1e-9);
}

RC_GTEST_PROP(ParabolicCyclideProperties, NetProjectionInvertsTheParameterization, ()) {
  const ParabolicCyclide c = random_cyclide();
  const double u = uniform(-3, 3);
  const double v = uniform(-3, 3);
  const double cc = uniform(-3, 3);
  Vec3d x;
  RC_ASSERT(parabolic_cyclide_point(c, u, v, x) == Status::ok);
  const Vec3d l = local(c, x);
  RC_PRE(std::abs(l[2] - c.a) >= 1e-3 && std::abs(l[2] - c.b) >= 1e-3);
  Vec2d p, uv;
  RC_ASSERT(net_projection(c, x, cc, p) == Status::ok);
  const double s = (1 + std::abs(cc)) * (1 + std::abs(u) + std::abs(v));
  RC_ASSERT(std::abs(p[0] - (c.a - cc) * u) <= kNetTol * s);
  RC_ASSERT(std::abs(p[1] - (c.b - cc) * v) <= kNetTol * s);
  RC_ASSERT(parameter_of(c, x, uv) == Status::ok);
  RC_ASSERT(std::abs(uv[0] - u) <= kNetTol * s);
  RC_ASSERT(std::abs(uv[1] - v) <= kNetTol * s);
}

RC_GTEST_PROP(ParabolicCyclideProperties, CubicTrianglesAreEnvelopesOnTheCyclide, ()) {
  const GraphQuadratic q = random_quadratic();
  Vec2d V[3];
  random_triangle(V);
  RationalCubicTriangle C;
  RC_ASSERT(cyclide_cubic_triangle(triangle_of(q, V), C) == Status::ok);
  const double r = uniform(0, 1);
  const double s = uniform(0, 1 - r);
  const double t = 1 - r - s;
  const Vec2d y = r * V[0] + s * V[1] + t * V[2];
  Vec3d x;
  RC_ASSERT(evaluate(C, r, s, t, x) == Status::ok);
  const Vec3d xe = envelope(q, y);
  RC_ASSERT((x - xe).norm() <= kPatchTol * (1 + xe.norm()));
  ParabolicCyclide c;
  if (parabolic_cyclide_from_quadratic(q, c) == Status::ok && std::abs(c.a) + std::abs(c.b) >= 0.05)
    RC_ASSERT(implicit_rel(c, x) <= kDerivedTol);
}

RC_GTEST_PROP(ParabolicCyclideProperties, BicubicPatchesAreEnvelopes, ()) {
  const GraphQuadratic q = random_quadratic();
  const double c0 = uniform(-2, 2);
  const double c1 = uniform(-2, 2);
  const double e10 = uniform(-2, 2);
  const double e11 = uniform(-2, 2);
  const double e20 = uniform(-2, 2);
  const double e21 = uniform(-2, 2);
  const Vec2d corner(c0, c1), e1(e10, e11), e2(e20, e21);
  RC_PRE(std::abs(e1[0] * e2[1] - e1[1] * e2[0]) >= 0.1);
  RationalBicubicPatch B;
  RC_ASSERT(cyclide_bicubic_patch(q, corner, e1, e2, B) == Status::ok);
  const double s = uniform(0, 1);
  const double t = uniform(0, 1);
  Vec3d x;
  RC_ASSERT(evaluate(B, s, t, x) == Status::ok);
  const Vec3d xe = envelope(q, corner + s * e1 + t * e2);
  RC_ASSERT((x - xe).norm() <= kPatchTol * (1 + xe.norm()));
  RC_ASSERT(evaluate_homogeneous(B, s, t)[0] > 0);
}

// Two triangles sharing the domain edge V1 V2, on graphs that join C^1 there
// (q2 = q1 + k l^2 with l vanishing on the edge): the boundary cubics agree
// up to the weight scale |det K1| / |det K2|.
RC_GTEST_PROP(ParabolicCyclideProperties, SharedEdgesAgree, ()) {
  const GraphQuadratic q1 = random_quadratic();
  Vec2d V[3], W[3];
  random_triangle(V);
  // The second triangle: V2, V1 and the reflection of V0 through the edge's midpoint.
  W[0] = V[2];
  W[1] = V[1];
  W[2] = V[1] + V[2] - V[0];
  const double k = uniform(-2, 2);
  // l(y) = n . (y - V1), n normal to the edge; q2 = q1 + k l^2.
  const Vec2d d = V[2] - V[1], n(-d[1], d[0]);
  const double c = -n.dot(V[1]);
  GraphQuadratic q2 = q1;
  q2.q20 += k * n[0] * n[0];
  q2.q11 += 2 * k * n[0] * n[1];
  q2.q02 += k * n[1] * n[1];
  q2.q10 += 2 * k * n[0] * c;
  q2.q01 += 2 * k * n[1] * c;
  q2.q00 += k * c * c;
  RationalCubicTriangle A, B;
  RC_ASSERT(cyclide_cubic_triangle(triangle_of(q1, V), A) == Status::ok);
  RC_ASSERT(cyclide_cubic_triangle(triangle_of(q2, W), B) == Status::ok);
  // Edge of A: r = 0, from vertex 1 (V1) to vertex 2 (V2): 030, 021, 012, 003.
  // Edge of B: t = 0, from vertex 1 (V1) to vertex 0 (V2): 030, 120, 210, 300.
  const int ea[4] = {6, 7, 8, 9}, eb[4] = {6, 3, 1, 0};
  const double scale = A.control[ea[0]][0] / B.control[eb[0]][0];
  for (int i = 0; i < 4; ++i) {
    const Vec4d pa = A.control[ea[i]], pb = scale * B.control[eb[i]];
    RC_ASSERT((pa - pb).norm() <= kEdgeTol * (1 + pa.norm()));
  }
}
