// Parabolic Dupin cyclides as Lambda^{-1} images of paraboloids, and the
// rational cubic triangles / bicubic patches they carry (seed 004 §4.1).
//
// Normal form (a, b), in its own frame (homogeneous point (x0, x1, x2, x3),
// affine x / x0):
//   (4.1) phi(u, v) = (1 + u^2 + v^2, a u + (a - b) u v^2, b v + (b - a) u^2 v, a u^2 + b v^2)
//   (4.2) x0 (b x1^2 + a x2^2 + (a + b) x3^2) - x3 (a b x0^2 + x1^2 + x2^2 + x3^2) = 0
//   (4.3) psi(u, v) = (-(a u^2 + b v^2), 2u, 2v, u^2 + v^2 - 1)
// (4.3) is isotropic_dual_plane of the graph y3 = -(a y1^2 + b y2^2) / 2 with
// (u, v) = (y1, y2); the plane's unit normal (2u, 2v, u^2 + v^2 - 1) / N is the
// surface's oriented normal n, and the offset s + d n is the graph
// q -> q - d (1 + y1^2 + y2^2) (laguerre.hpp's sign of (2.6)).
//
// A cyclide of the family G (through the line at infinity x0 = x3 = 0) is the
// normal form moved rigidly: x = origin + frame * x_local, frame a rotation
// about x3. Its parameters (u, v) are the normal form's; the isotropic
// parameters are y = frame2 (u, v) (frame2 the upper-left 2x2 of frame).
#pragma once

#include <Eigen/Core>

#include "cyclide/bezier_triangle.hpp"
#include "cyclide/circle_family.hpp"
#include "cyclide/laguerre.hpp"
#include "cyclide/status.hpp"
#include "cyclide/vec.hpp"

namespace cyclide {
inline namespace v0 {

// The three types of §4.1 plus the two degenerate normal forms.
enum class ParabolicCyclideType {
  horn,    // a b > 0, a != b
  ring,    // a b < 0
  thorn,   // exactly one of a, b is 0
  sphere,  // a = b != 0 (ERRATA 004: (4.2) = (plane x3 = a x0) * sphere)
  point,   // a = b = 0: all planes (4.3) pass through the origin (a cycle of radius 0)
};

ParabolicCyclideType parabolic_cyclide_type(double a, double b) noexcept;

// A parabolic Dupin cyclide: the normal form (a, b) placed by a rigid motion.
struct ParabolicCyclide {
  double a = 1, b = -1;
  Eigen::Matrix3d frame = Eigen::Matrix3d::Identity();  // columns: local axes in world coordinates
  Vec3d origin = Vec3d::Zero();                          // the local origin in world coordinates
};

// A quadratic q(y1, y2) = q20 y1^2 + q11 y1 y2 + q02 y2^2 + q10 y1 + q01 y2 + q00:
// the graph y3 = q / 2 in I^3, whose planes are (4.4) psi = (q, 2u, 2v, u^2 + v^2 - 1).
struct GraphQuadratic {
  double q20 = 0, q11 = 0, q02 = 0, q10 = 0, q01 = 0, q00 = 0;
};

// A line {point + s direction} (unit direction) and a circle in 3-space.
struct Line3 {
  Vec3d point = Vec3d::Zero();
  Vec3d direction = Vec3d(1, 0, 0);
};
struct Circle3 {
  Vec3d centre = Vec3d::Zero();
  Vec3d normal = Vec3d(0, 0, 1);  // unit normal of the circle's plane
  double radius = 0;
};

// ------------------------------------------------------------ normal form

// (4.1), (4.2), (4.3) of the normal form (a, b), local coordinates.
Vec4d parabolic_cyclide_phi(double a, double b, double u, double v) noexcept;
double parabolic_cyclide_implicit(double a, double b, const Vec4d& x) noexcept;
Vec4d parabolic_cyclide_psi(double a, double b, double u, double v) noexcept;

// Validates a cyclide: a, b, frame, origin finite and within kMaxInputMagnitude
// (not_finite), frame a rotation to 1e-12 (invalid_argument), a = b = 0
// (degenerate_cyclide: a point, not a surface).
Status validate_parabolic_cyclide(const ParabolicCyclide& c) noexcept;

// The world point phi(u, v) / phi0 (phi0 = 1 + u^2 + v^2 > 0 always).
// Statuses of validate_parabolic_cyclide; not_finite for bad (u, v); numerical_overflow.
Status parabolic_cyclide_point(const ParabolicCyclide& c, double u, double v, Vec3d& x) noexcept;

// The unit normal n(u, v) = frame (2u, 2v, u^2 + v^2 - 1) / (1 + u^2 + v^2)
// of the tangent plane (4.3) (the orientation whose offsets are (2.6)).
Status parabolic_cyclide_normal(const ParabolicCyclide& c, double u, double v, Vec3d& n) noexcept;

// (4.2) at a world point, the point taken to the local frame (x0 = 1).
double parabolic_cyclide_implicit(const ParabolicCyclide& c, const Vec3d& x) noexcept;

// The parabolic lines e: x1 = 0, x3 = a and f: x2 = 0, x3 = b (world).
// The line at infinity g: x0 = 0, x3 = 0 has the world direction set
// spanned by frame.col(0), frame.col(1) (for G: the horizontal directions).
Line3 parabolic_line_e(const ParabolicCyclide& c) noexcept;
Line3 parabolic_line_f(const ParabolicCyclide& c) noexcept;

// The parameter lines of (4.1) as circles (principal curvature lines, §4.1).
// u = const lies in the plane x1 + u (x3 - a) = 0 through e, v = const in
// x2 + v (x3 - b) = 0 through f. Closed form (local): the points v = 0 and
// v -> oo (on f) are a diameter,
//   u-circle: centre ((a u / (1 + u^2) + (a - b) u) / 2, 0, (a u^2 / (1 + u^2) + b) / 2),
//             radius |b - (a - b) u^2| / (2 sqrt(1 + u^2)), normal (1, 0, u) / sqrt(1 + u^2);
//   v-circle: centre (0, (b v / (1 + v^2) + (b - a) v) / 2, (b v^2 / (1 + v^2) + a) / 2),
//             radius |a - (b - a) v^2| / (2 sqrt(1 + v^2)), normal (0, 1, v) / sqrt(1 + v^2).
// Radius 0 is a singular point of a horn cyclide (the circle collapses).
Status parabolic_u_circle(const ParabolicCyclide& c, double u, Circle3& out) noexcept;
Status parabolic_v_circle(const ParabolicCyclide& c, double v, Circle3& out) noexcept;

// ----------------------------------------------------- the family G (Thm 4.1)

// Thm 4.1: Lambda^{-1}(graph y3 = q / 2) is the normal form (a, b) rotated about
// x3 and translated by t. The rotation R diagonalizes q's quadratic part,
// -(A w1^2 + B w2^2) with y = R w; the translation (2.5) adds
// -2 t1 y1 - 2 t2 y2 - t3 (y1^2 + y2^2 - 1) to q, so
//   t = (-q10 / 2, -q01 / 2, q00),  a = A - q00,  b = B - q00.
// A = B gives a sphere (frame = identity). not_finite for bad coefficients;
// degenerate_cyclide when a = b = 0 to 1e-14 of the coefficients' scale (a point).
Status parabolic_cyclide_from_quadratic(const GraphQuadratic& q, ParabolicCyclide& out) noexcept;

// The inverse: q of a cyclide of G (frame a rotation about x3, to 1e-12, else
// invalid_argument).
Status quadratic_of_parabolic_cyclide(const ParabolicCyclide& c, GraphQuadratic& out) noexcept;

// The offset at distance d (s + d n): q - d (1 + y1^2 + y2^2), (2.6). May change the type.
GraphQuadratic offset_quadratic(const GraphQuadratic& q, double d) noexcept;

// The envelope point of the graph's planes at the isotropic parameter y:
// P ^ P_y1 ^ P_y2 with P = (q, 2 y1, 2 y2, y1^2 + y2^2 - 1); its x0 is
// 4 (1 + y1^2 + y2^2) > 0. not_finite / numerical_overflow.
Status graph_envelope_point(const GraphQuadratic& q, const Vec2d& y, Vec4d& X) noexcept;

// --------------------------------------------------------- cones (Thm 4.2)

// The cone Gamma(lambda, mu): the planes psi(t, lambda t + mu) of (4.3), a
// quadratic family P0 + t P1 + t^2 P2, touching Phi along the cubic circle
// c(t) = phi(t, lambda t + mu). Their unit normals n = sigma^{-1}(y) satisfy
// lambda n1 - n2 + mu (1 - n3) = 0 (y on the line y2 = lambda y1 + mu), i.e.
// k . n = mu / sqrt(1 + lambda^2 + mu^2) with k = frame (-lambda, 1, mu) / |.|
// (stereographic image of a line through the pole W), so Gamma is a cone of
// revolution with axis k, half-angle alpha = atan2(|mu|, sqrt(1 + lambda^2))
// (angle between generators and axis), apex P0 ^ P1 ^ P2.
struct RevolutionCone {
  Vec3d apex = Vec3d::Zero();  // when !cylinder
  Vec3d axis = Vec3d(0, 0, 1);  // unit (world)
  double half_angle = 0;
  bool cylinder = false;         // mu = 0: apex at infinity in direction axis (half_angle 0)
  bool circle_and_line = false;  // lambda = 0: c is the v-circle v = mu, and Gamma also
                                 // touches Phi along e (its plane at t -> oo is x3 = a)
};
// dependent_planes when P0, P1, P2 are dependent (mu = 0 and a + b lambda^2 = 0:
// a pencil of planes, no cone); statuses of validate_parabolic_cyclide.
Status cubic_circle_cone(const ParabolicCyclide& c, double lambda, double mu,
                         RevolutionCone& out) noexcept;
// c(lambda, mu)(t) = phi(t, lambda t + mu), world.
Status cubic_circle_point(const ParabolicCyclide& c, double lambda, double mu, double t,
                          Vec3d& x) noexcept;

// ------------------------------------------------ net projection (Remark 4.2)

// The unique line through x meeting e and f (x's plane through e meets f in F,
// its plane through f meets e in E; the line is EF), intersected with the plane
// x3 = cc (local). For x = phi(u, v) the result is ((a - cc) u, (b - cc) v).
// invalid_argument for a sphere (a = b: e and f meet); point_at_infinity when x
// lies in a plane x3 = a or x3 = b (on e or f, or its net line is parallel to
// e or f: the parameter is at infinity); statuses of validate_parabolic_cyclide.
Status net_projection(const ParabolicCyclide& c, const Vec3d& x, double cc, Vec2d& out) noexcept;

// (u, v) with phi(u, v) = x: the net projection with cc = (a + b) / 2 (a
// similarity), scaled back. For x off Phi, the parameter of the third point
// where x's net line meets the cubic Phi. For a sphere (a = b): the
// stereographic parameter (x1, x2) / (a - x3). point_at_infinity as above.
Status parameter_of(const ParabolicCyclide& c, const Vec3d& x, Vec2d& uv) noexcept;

// ----------------------------------------------------- patches (§4.1)

// The dual quadratic Bezier triangle of the graph (control planes
// u_ijk = (2 ordinate_ijk, y1(A) + y1(B), y2(A) + y2(B), y(A).y(B) - 1), A, B
// the blossom arguments of ijk), one de Casteljau step, and the exterior
// product of §4.1, expanded exactly into the 10 cubic Bernstein coefficients.
// The result is U0 ^ U1 ^ U2 = (det K / 4) P ^ P_y1 ^ P_y2 times sign(det K)
// (K = [1 1 1; vertices]), so its weight polynomial is
// |det K| (1 + y1^2 + y2^2) > 0 on the whole plane: no point at infinity.
// Control weights may still be <= 0 (the weight's Bernstein coefficients are
// |det K| (1 + A.B) in degree 2, e.g. A = (2, 0), B = (-2, 0)); the evaluator
// works on homogeneous points, so this is harmless.
// not_finite for bad input, collinear_points for a degenerate domain
// (|det K| <= 1e-14 max|vertex_i - vertex_0|^2), numerical_overflow.
Status cyclide_cubic_triangle(const QuadraticGraphTriangle& tri, RationalCubicTriangle& out) noexcept;

// The same over the parallelogram corner + s e1 + t e2, (s, t) in [0, 1]^2, of
// the graph y3 = q / 2: the exterior product has total degree 3 (Euler's
// relation cancels the quartic terms), written exactly as a bicubic
// (control[i][j], i along s). Weight polynomial |det[e1 e2]| (1 + |y|^2) > 0.
// collinear_points for |det[e1 e2]| <= 1e-14 |e1| |e2|.
Status cyclide_bicubic_patch(const GraphQuadratic& q, const Vec2d& corner, const Vec2d& e1,
                             const Vec2d& e2, RationalBicubicPatch& out) noexcept;

// ------------------------------------------- as a circle-family surface

// The u-circles of (4.1) as a circle family (circle_family.hpp), generic in
// the scalar (Taylor series in u): at fixed u, (4.1) is a rational
// quadratic circle in v through p(u) = phi(u, inf) = ((a - b) u, 0, b) on f
// and its antipode phi(u, 0) = (a u, 0, a u^2)/(1 + u^2). Its plane
// x1 + u (x3 - a) = 0 contains e, with normal (1, 0, u), whose length
// sqrt(1 + u^2) is exactly the half-angle scale of (4.1) in v; so with the
// axis a(u) = -(1, 0, u) (the sign that turns p towards +x2 for v > 0, as
// (4.1) does) and f(u, v) = v, eq. (11) of seed 000 reproduces (4.1):
// x(u, v) = o + (v + a) * (p - o) * (v - a) / |v + a|^2. Everything is
// rational in u: the family is exact. World coordinates by the
// cyclide's placement.
template <class S>
void parabolic_frame(const ParabolicCyclide& c, const S& u, CircleFrame<S>& F) {
  const S one(1.0), zero(0.0), half(0.5);
  const S den = one + u * u;
  const Vec3<S> p_local(S(c.a - c.b) * u, zero, S(c.b));
  const Vec3<S> antipode(S(c.a) * u / den, zero, S(c.a) * u * u / den);
  const Vec3<S> o_local = half * (p_local + antipode);
  const Vec3<S> a_local(-one, zero, -u);
  auto place = [&](const Vec3<S>& x, bool is_point) {
    Vec3<S> w;
    for (int i = 0; i < 3; ++i) {
      w[i] = is_point ? S(c.origin[i]) : zero;
      for (int j = 0; j < 3; ++j) w[i] += S(c.frame(i, j)) * x[j];
    }
    return w;
  };
  F.o = place(o_local, true);
  F.p = place(p_local, true);
  F.a = place(a_local, false);
  F.alpha = one;
  F.beta = zero;
  F.gamma = zero;
  F.delta = one;
}

// The sphere touching the cyclide along the u-circle (a Dupin cyclide is a
// canal surface): the normals along it meet at m = p - rho frame e3 with
// the signed radius rho = (b + (b - a) u^2)/2 (x = m + rho n, the
// orientation of parabolic_cyclide_normal). World centre.
void parabolic_u_sphere(const ParabolicCyclide& c, double u, Vec3d& centre, double& rho) noexcept;

}  // namespace v0
}  // namespace cyclide
