// Parabolic Dupin cyclides and their rational patches (seed 004 §4.1); see
// parabolic_cyclide.hpp.
#include "cyclide/parabolic_cyclide.hpp"

#include <algorithm>
#include <cmath>

#include "cyclide/config.hpp"

namespace cyclide {
inline namespace v0 {

namespace {

bool valid(double x) { return std::isfinite(x) && std::abs(x) <= kMaxInputMagnitude; }
template <class M>
bool valid(const M& m) {
  return m.allFinite() && m.cwiseAbs().maxCoeff() <= kMaxInputMagnitude;
}

constexpr double kFrameTol = 1e-12;       // |F^T F - I|_max of a rotation frame
constexpr double kDegenerateTol = 1e-14;  // relative: a = b = 0, collinear domains

Vec3d to_local(const ParabolicCyclide& c, const Vec3d& x) { return c.frame.transpose() * (x - c.origin); }
Vec3d to_world(const ParabolicCyclide& c, const Vec3d& x) { return c.origin + c.frame * x; }

// Whether the frame is a rotation about x3 (the cyclide belongs to G).
bool about_x3(const Eigen::Matrix3d& F) {
  return std::abs(F(2, 2) - 1) <= kFrameTol && std::abs(F(0, 2)) <= kFrameTol &&
         std::abs(F(1, 2)) <= kFrameTol && std::abs(F(2, 0)) <= kFrameTol &&
         std::abs(F(2, 1)) <= kFrameTol;
}

}  // namespace

ParabolicCyclideType parabolic_cyclide_type(double a, double b) noexcept {
  if (a == 0 && b == 0) return ParabolicCyclideType::point;
  if (a == b) return ParabolicCyclideType::sphere;
  if (a == 0 || b == 0) return ParabolicCyclideType::thorn;
  return a * b > 0 ? ParabolicCyclideType::horn : ParabolicCyclideType::ring;
}

// ------------------------------------------------------------ normal form

Vec4d parabolic_cyclide_phi(double a, double b, double u, double v) noexcept {
  const double uu = u * u, vv = v * v;
  return Vec4d(1 + uu + vv, a * u + (a - b) * u * vv, b * v + (b - a) * uu * v,
               a * uu + b * vv);  // (4.1)
}

double parabolic_cyclide_implicit(double a, double b, const Vec4d& x) noexcept {
  const double x0 = x[0], x1 = x[1], x2 = x[2], x3 = x[3];
  return x0 * (b * x1 * x1 + a * x2 * x2 + (a + b) * x3 * x3) -
         x3 * (a * b * x0 * x0 + x1 * x1 + x2 * x2 + x3 * x3);  // (4.2)
}

Vec4d parabolic_cyclide_psi(double a, double b, double u, double v) noexcept {
  // (4.3) = isotropic_dual_plane(u, v, -(a u^2 + b v^2) / 2).
  return Vec4d(-(a * u * u + b * v * v), 2 * u, 2 * v, u * u + v * v - 1);
}

Status validate_parabolic_cyclide(const ParabolicCyclide& c) noexcept {
  if (!valid(c.a) || !valid(c.b) || !valid(c.frame) || !valid(c.origin)) return Status::not_finite;
  const Eigen::Matrix3d G = c.frame.transpose() * c.frame - Eigen::Matrix3d::Identity();
  if (G.cwiseAbs().maxCoeff() > kFrameTol || c.frame.determinant() < 0) return Status::invalid_argument;
  if (c.a == 0 && c.b == 0) return Status::degenerate_cyclide;
  return Status::ok;
}

Status parabolic_cyclide_point(const ParabolicCyclide& c, double u, double v, Vec3d& x) noexcept {
  const Status st = validate_parabolic_cyclide(c);
  if (st != Status::ok) return st;
  if (!valid(u) || !valid(v)) return Status::not_finite;
  const Vec4d X = parabolic_cyclide_phi(c.a, c.b, u, v);
  const Vec3d p = to_world(c, X.tail<3>() / X[0]);  // X[0] = 1 + u^2 + v^2 >= 1
  if (!p.allFinite()) return Status::numerical_overflow;
  x = p;
  return Status::ok;
}

Status parabolic_cyclide_normal(const ParabolicCyclide& c, double u, double v, Vec3d& n) noexcept {
  const Status st = validate_parabolic_cyclide(c);
  if (st != Status::ok) return st;
  if (!valid(u) || !valid(v)) return Status::not_finite;
  OrientedPlane p;  // Lambda^{-1} of (u, v, y3): the normal does not depend on y3
  IsotropicPoint y;
  y.y = Vec3d(u, v, 0);
  const Status s2 = isotropic_to_laguerre(y, p);
  if (s2 != Status::ok) return s2;
  n = c.frame * p.e;
  return Status::ok;
}

double parabolic_cyclide_implicit(const ParabolicCyclide& c, const Vec3d& x) noexcept {
  const Vec3d l = to_local(c, x);
  return parabolic_cyclide_implicit(c.a, c.b, Vec4d(1, l[0], l[1], l[2]));
}

Line3 parabolic_line_e(const ParabolicCyclide& c) noexcept {
  return {to_world(c, Vec3d(0, 0, c.a)), c.frame.col(1)};  // e: x1 = 0, x3 = a
}

Line3 parabolic_line_f(const ParabolicCyclide& c) noexcept {
  return {to_world(c, Vec3d(0, 0, c.b)), c.frame.col(0)};  // f: x2 = 0, x3 = b
}

namespace {
// The u-circle of the normal form (a, b) with the roles of the axes given:
// the diameter from phi(u, 0) to phi(u, oo) (a point of f); see the header.
Circle3 local_u_circle(double a, double b, double u) {
  const double w = 1 + u * u, sw = std::sqrt(w);
  Circle3 C;
  C.centre = Vec3d((a * u / w + (a - b) * u) / 2, 0, (a * u * u / w + b) / 2);
  C.radius = std::abs(b - (a - b) * u * u) / (2 * sw);
  C.normal = Vec3d(1, 0, u) / sw;
  return C;
}
Status finish_circle(const ParabolicCyclide& c, const Circle3& L, Circle3& out) {
  Circle3 C;
  C.centre = to_world(c, L.centre);
  C.normal = c.frame * L.normal;
  C.radius = L.radius;
  if (!C.centre.allFinite() || !C.normal.allFinite() || !std::isfinite(C.radius))
    return Status::numerical_overflow;
  out = C;
  return Status::ok;
}
}  // namespace

Status parabolic_u_circle(const ParabolicCyclide& c, double u, Circle3& out) noexcept {
  const Status st = validate_parabolic_cyclide(c);
  if (st != Status::ok) return st;
  if (!valid(u)) return Status::not_finite;
  return finish_circle(c, local_u_circle(c.a, c.b, u), out);
}

Status parabolic_v_circle(const ParabolicCyclide& c, double v, Circle3& out) noexcept {
  const Status st = validate_parabolic_cyclide(c);
  if (st != Status::ok) return st;
  if (!valid(v)) return Status::not_finite;
  // (4.1) is symmetric under (x1, x2, a, u) <-> (x2, x1, b, v).
  Circle3 L = local_u_circle(c.b, c.a, v);
  std::swap(L.centre[0], L.centre[1]);
  std::swap(L.normal[0], L.normal[1]);
  return finish_circle(c, L, out);
}

// ----------------------------------------------------- the family G (Thm 4.1)

Status parabolic_cyclide_from_quadratic(const GraphQuadratic& q, ParabolicCyclide& out) noexcept {
  const double co[6] = {q.q20, q.q11, q.q02, q.q10, q.q01, q.q00};
  double scale = 0;
  for (double x : co) {
    if (!valid(x)) return Status::not_finite;
    scale = std::max(scale, std::abs(x));
  }
  // Quadratic part y^T M y, M = [q20, q11/2; q11/2, q02] = R diag(l1, l2) R^T
  // with R the rotation by theta, tan 2 theta = q11 / (q20 - q02).
  // theta in (-pi/4, pi/4]: the smallest rotation (the normal form q = -(a y1^2
  // + b y2^2) keeps the identity frame and its a, b in place).
  const double quarter = std::atan(1.0);
  double theta = 0.5 * std::atan2(q.q11, q.q20 - q.q02);
  if (theta > quarter) theta -= 2 * quarter;
  if (theta <= -quarter) theta += 2 * quarter;
  const double cs = std::cos(theta), sn = std::sin(theta);
  const double h = q.q11 / 2;
  const double l1 = q.q20 * cs * cs + 2 * h * sn * cs + q.q02 * sn * sn;
  const double l2 = q.q20 * sn * sn - 2 * h * sn * cs + q.q02 * cs * cs;
  // q = -(A w1^2 + B w2^2) - 2 t1 y1 - 2 t2 y2 - t3 (|y|^2 - 1), (2.5).
  const Vec3d t(-q.q10 / 2, -q.q01 / 2, q.q00);
  const double A = -l1, B = -l2;
  ParabolicCyclide C;
  C.a = A - t[2];
  C.b = B - t[2];
  if (std::abs(C.a) <= kDegenerateTol * scale && std::abs(C.b) <= kDegenerateTol * scale)
    return Status::degenerate_cyclide;  // a cycle of radius 0: all planes through one point
  C.frame << cs, -sn, 0, sn, cs, 0, 0, 0, 1;
  C.origin = t;
  if (!std::isfinite(C.a) || !std::isfinite(C.b)) return Status::numerical_overflow;
  out = C;
  return Status::ok;
}

Status quadratic_of_parabolic_cyclide(const ParabolicCyclide& c, GraphQuadratic& out) noexcept {
  const Status st = validate_parabolic_cyclide(c);
  if (st != Status::ok) return st;
  if (!about_x3(c.frame)) return Status::invalid_argument;
  const Vec3d& t = c.origin;
  const double A = c.a + t[2], B = c.b + t[2];
  Eigen::Matrix2d R = c.frame.topLeftCorner<2, 2>();
  const Eigen::Matrix2d M = R * Eigen::Vector2d(-A, -B).asDiagonal() * R.transpose();
  GraphQuadratic q;
  q.q20 = M(0, 0);
  q.q11 = M(0, 1) + M(1, 0);
  q.q02 = M(1, 1);
  q.q10 = -2 * t[0];
  q.q01 = -2 * t[1];
  q.q00 = t[2];
  out = q;
  return Status::ok;
}

GraphQuadratic offset_quadratic(const GraphQuadratic& q, double d) noexcept {
  GraphQuadratic r = q;  // q - d (1 + y1^2 + y2^2), (2.6) in laguerre.hpp's sign
  r.q20 -= d;
  r.q02 -= d;
  r.q00 -= d;
  return r;
}

Status graph_envelope_point(const GraphQuadratic& q, const Vec2d& y, Vec4d& X) noexcept {
  if (!valid(y)) return Status::not_finite;
  const double y1 = y[0], y2 = y[1];
  const double qv = q.q20 * y1 * y1 + q.q11 * y1 * y2 + q.q02 * y2 * y2 + q.q10 * y1 + q.q01 * y2 + q.q00;
  const double q1 = 2 * q.q20 * y1 + q.q11 * y2 + q.q10;
  const double q2 = q.q11 * y1 + 2 * q.q02 * y2 + q.q01;
  const Vec4d P(qv, 2 * y1, 2 * y2, y1 * y1 + y2 * y2 - 1);  // (4.4)
  const Vec4d P1(q1, 2, 0, 2 * y1), P2(q2, 0, 2, 2 * y2);
  const Vec4d R = exterior_product(P, P1, P2);
  if (!R.allFinite()) return Status::numerical_overflow;
  X = R;
  return Status::ok;
}

// --------------------------------------------------------- cones (Thm 4.2)

Status cubic_circle_cone(const ParabolicCyclide& c, double lambda, double mu,
                         RevolutionCone& out) noexcept {
  const Status st = validate_parabolic_cyclide(c);
  if (st != Status::ok) return st;
  if (!valid(lambda) || !valid(mu)) return Status::not_finite;
  const double a = c.a, b = c.b, l = lambda, m = mu;
  // psi(t, l t + m) = P0 + t P1 + t^2 P2, (4.3).
  const Vec4d P0(-b * m * m, 0, 2 * m, m * m - 1);
  const Vec4d P1(-2 * b * l * m, 2, 2 * l, 2 * l * m);
  const Vec4d P2(-(a + b * l * l), 0, 0, 1 + l * l);
  RevolutionCone K;
  const Vec3d k(-l, 1, m);
  K.axis = c.frame * (k / k.norm());
  K.half_angle = std::atan2(std::abs(m), std::sqrt(1 + l * l));
  K.circle_and_line = (l == 0);
  if (m == 0) {
    // The normals are all perpendicular to k: a cylinder, unless P2 ~ P0 too
    // (a + b l^2 = 0), when all planes share a line (a pencil).
    if (std::abs(a + b * l * l) <= kDegenerateTol * (std::abs(a) + std::abs(b) * l * l))
      return Status::dependent_planes;
    K.cylinder = true;
  } else {
    const Vec4d X = exterior_product(P0, P1, P2);  // x0 = 4 m (1 + l^2) != 0
    const Vec3d apex = to_world(c, X.tail<3>() / X[0]);
    if (!apex.allFinite()) return Status::numerical_overflow;
    K.apex = apex;
  }
  if (!K.axis.allFinite()) return Status::numerical_overflow;
  out = K;
  return Status::ok;
}

Status cubic_circle_point(const ParabolicCyclide& c, double lambda, double mu, double t,
                          Vec3d& x) noexcept {
  if (!valid(lambda) || !valid(mu) || !valid(t)) return Status::not_finite;
  return parabolic_cyclide_point(c, t, lambda * t + mu, x);
}

// ------------------------------------------------ net projection (Remark 4.2)

namespace {
// Where the line {B + s d} meets the plane through the line {A + s e} and x;
// point_at_infinity when it is parallel to that plane.
Status meet_line_plane(const Vec3d& A, const Vec3d& e, const Vec3d& x, const Vec3d& B,
                       const Vec3d& d, double scale, Vec3d& out) {
  const Vec3d n = e.cross(x - A);  // normal of the plane (line, x)
  const double den = n.dot(d);
  if (std::abs(den) <= kDegenerateTol * scale * scale) return Status::point_at_infinity;
  out = B - (n.dot(B - A) / den) * d;
  return Status::ok;
}
}  // namespace

Status net_projection(const ParabolicCyclide& c, const Vec3d& x, double cc, Vec2d& out) noexcept {
  const Status st = validate_parabolic_cyclide(c);
  if (st != Status::ok) return st;
  if (!valid(x) || !valid(cc)) return Status::not_finite;
  if (c.a == c.b) return Status::invalid_argument;  // e and f meet: no hyperbolic net
  const Vec3d l = to_local(c, x);
  const Vec3d A(0, 0, c.a), B(0, 0, c.b), de(0, 1, 0), df(1, 0, 0);  // e, f
  const double scale = 1 + l.norm() + std::abs(c.a) + std::abs(c.b);
  Vec3d E, F;
  Status s1 = meet_line_plane(A, de, l, B, df, scale, F);  // f meets plane (e, x)
  if (s1 != Status::ok) return s1;
  s1 = meet_line_plane(B, df, l, A, de, scale, E);  // e meets plane (f, x)
  if (s1 != Status::ok) return s1;
  // The net line EF meets x3 = cc at E + tau (F - E), tau = (cc - a) / (b - a).
  const double tau = (cc - E[2]) / (F[2] - E[2]);
  const Vec3d p = E + tau * (F - E);
  if (!p.allFinite()) return Status::numerical_overflow;
  out = Vec2d(p[0], p[1]);
  return Status::ok;
}

Status parameter_of(const ParabolicCyclide& c, const Vec3d& x, Vec2d& uv) noexcept {
  const Status st = validate_parabolic_cyclide(c);
  if (st != Status::ok) return st;
  if (!valid(x)) return Status::not_finite;
  if (c.a == c.b) {
    // The sphere a (u, v, u^2 + v^2) / N: stereographic from its top (0, 0, a).
    const Vec3d l = to_local(c, x);
    const double den = c.a - l[2];
    if (std::abs(den) <= kDegenerateTol * (std::abs(c.a) + l.norm())) return Status::point_at_infinity;
    const Vec2d r(l[0] / den, l[1] / den);
    if (!r.allFinite()) return Status::numerical_overflow;
    uv = r;
    return Status::ok;
  }
  const double cc = (c.a + c.b) / 2;  // the similarity case of Remark 4.2
  Vec2d p;
  const Status s1 = net_projection(c, x, cc, p);
  if (s1 != Status::ok) return s1;
  const Vec2d r(p[0] / (c.a - cc), p[1] / (c.b - cc));
  if (!r.allFinite()) return Status::numerical_overflow;
  uv = r;
  return Status::ok;
}

// ----------------------------------------------------- patches (§4.1)

namespace {

// Polar form of the homogeneous dual plane (2 z, 2 h y1, 2 h y2, |y|^2 - h^2)
// at two lifted points p = (h, y1, y2), given the polar form z2 of its first
// component (for a triangle: 2 ordinate_ijk).
Vec4d plane_blossom(double z2, const Vec3d& p, const Vec3d& pp) {
  return Vec4d(z2, p[0] * pp[1] + pp[0] * p[1], p[0] * pp[2] + pp[0] * p[2],
               p[1] * pp[1] + p[2] * pp[2] - p[0] * pp[0]);
}

// Polar form of the homogenized q at two lifted points.
double q_blossom(const GraphQuadratic& q, const Vec3d& p, const Vec3d& pp) {
  return q.q20 * p[1] * pp[1] + q.q11 * (p[1] * pp[2] + p[2] * pp[1]) / 2 + q.q02 * p[2] * pp[2] +
         q.q10 * (p[1] * pp[0] + p[0] * pp[1]) / 2 + q.q01 * (p[2] * pp[0] + p[0] * pp[2]) / 2 +
         q.q00 * p[0] * pp[0];
}

// Index of the cubic coefficient with exponents (i, j, k) in bezier_triangle.hpp's order.
int cubic_index(int i, int j) {
  int before = 0;
  for (int ii = 3; ii > i; --ii) before += 3 - ii + 1;
  return before + (3 - i - j);
}

// The dual quadratic P(beta) = sum D_ij beta_i beta_j (D symmetric); its
// de Casteljau planes U_i = sum_j D_ij beta_j = (1/2) dP/dbeta_i; the point
// U0 ^ U1 ^ U2 is cubic in beta. Returns its monomial coefficients:
// mono[cubic_index(n0, n1)] multiplies beta0^n0 beta1^n1 beta2^n2.
void expand_exterior(const Vec4d D[3][3], Vec4d mono[10]) {
  for (int i = 0; i < 10; ++i) mono[i].setZero();
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l) {
        int n[3] = {0, 0, 0};
        ++n[j];
        ++n[k];
        ++n[l];
        mono[cubic_index(n[0], n[1])] += exterior_product(D[0][j], D[1][k], D[2][l]);
      }
}

int factorial(int n) { return n <= 1 ? 1 : n * factorial(n - 1); }

bool all_finite(const Vec4d* v, int n) {
  for (int i = 0; i < n; ++i)
    if (!v[i].allFinite()) return false;
  return true;
}

}  // namespace

Status cyclide_cubic_triangle(const QuadraticGraphTriangle& tri, RationalCubicTriangle& out) noexcept {
  double size2 = 0;
  for (const auto& v : tri.vertex)
    if (!valid(v)) return Status::not_finite;
  for (double z : tri.ordinate)
    if (!valid(z)) return Status::not_finite;
  const Vec2d d1 = tri.vertex[1] - tri.vertex[0], d2 = tri.vertex[2] - tri.vertex[0];
  size2 = std::max(d1.squaredNorm(), d2.squaredNorm());
  const double detK = d1[0] * d2[1] - d1[1] * d2[0];  // det [1 1 1; vertices]
  if (!(std::abs(detK) > kDegenerateTol * size2)) return Status::collinear_points;
  // Lifted vertices (1, y1, y2) and the quadratic control planes u_ijk.
  Vec3d p[3];
  for (int i = 0; i < 3; ++i) p[i] = Vec3d(1, tri.vertex[i][0], tri.vertex[i][1]);
  // ordinate index of the pair (i, j): 200, 110, 101, 020, 011, 002.
  static constexpr int kPair[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};
  Vec4d D[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) D[i][j] = plane_blossom(2 * tri.ordinate[kPair[i][j]], p[i], p[j]);
  Vec4d mono[10];
  expand_exterior(D, mono);
  // Monomial -> Bernstein: r^i s^j t^k = B^3_ijk i! j! k! / 3!; sign(det K)
  // makes the weights' polynomial positive.
  const double sgn = detK > 0 ? 1.0 : -1.0;
  RationalCubicTriangle T;
  for (int i = 3; i >= 0; --i)
    for (int j = 3 - i; j >= 0; --j) {
      const int k = 3 - i - j, id = cubic_index(i, j);
      T.control[id] = sgn * mono[id] * (double(factorial(i) * factorial(j) * factorial(k)) / 6.0);
    }
  if (!all_finite(T.control, 10)) return Status::numerical_overflow;
  out = T;
  return Status::ok;
}

Status cyclide_bicubic_patch(const GraphQuadratic& q, const Vec2d& corner, const Vec2d& e1,
                             const Vec2d& e2, RationalBicubicPatch& out) noexcept {
  const double co[6] = {q.q20, q.q11, q.q02, q.q10, q.q01, q.q00};
  for (double x : co)
    if (!valid(x)) return Status::not_finite;
  if (!valid(corner) || !valid(e1) || !valid(e2)) return Status::not_finite;
  const double det = e1[0] * e2[1] - e1[1] * e2[0];
  if (!(std::abs(det) > kDegenerateTol * e1.norm() * e2.norm())) return Status::collinear_points;
  // Homogeneous domain coordinates (w, s, t), y = w corner + s e1 + t e2.
  const Vec3d p[3] = {Vec3d(1, corner[0], corner[1]), Vec3d(0, e1[0], e1[1]), Vec3d(0, e2[0], e2[1])};
  Vec4d D[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) D[i][j] = plane_blossom(q_blossom(q, p[i], p[j]), p[i], p[j]);
  // U_w ^ U_s ^ U_t = P ^ P_s ^ P_t / 4 (Euler: P = w U_w + s U_s + t U_t),
  // homogeneous cubic in (w, s, t); at w = 1 a polynomial of total degree 3.
  Vec4d mono[10];
  expand_exterior(D, mono);
  // Power coefficients c[j][k] of s^j t^k, then s^j = sum_i [C(i,j)/C(3,j)] B^3_i(s).
  static constexpr double kBinom[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};
  const double sgn = det > 0 ? 1.0 : -1.0;
  RationalBicubicPatch B;
  for (int i = 0; i < 4; ++i)
    for (int l = 0; l < 4; ++l) {
      Vec4d acc = Vec4d::Zero();
      for (int j = 0; j <= i; ++j)
        for (int k = 0; k <= l && j + k <= 3; ++k)
          acc += mono[cubic_index(3 - j - k, j)] * (kBinom[i][j] / kBinom[3][j]) *
                 (kBinom[l][k] / kBinom[3][k]);
      B.control[i][l] = sgn * acc;
    }
  for (const auto& row : B.control)
    if (!all_finite(row, 4)) return Status::numerical_overflow;
  out = B;
  return Status::ok;
}

void parabolic_u_sphere(const ParabolicCyclide& c, double u, Vec3d& centre, double& rho) noexcept {
  rho = 0.5 * (c.b + (c.b - c.a) * u * u);
  const Vec3d m_local((c.a - c.b) * u, 0.0, c.b - rho);
  centre = c.origin + c.frame * m_local;
}

}  // namespace v0
}  // namespace cyclide
