// Laguerre geometry in R^3 and its isotropic model (seed 004 §2).
//
// The elements are oriented planes and cycles (oriented spheres and points).
// Their basic relation is oriented contact. Seed 004 maps them through the
// cyclographic model (2.1) and the Blaschke cylinder (2.2) into the isotropic
// model I^3 (2.3), where planes are points and cycles are paraboloids (2.4).
//
// Sign conventions (all derived from (2.4), which the tests check):
//   * An oriented plane is e0 + e.x = 0 with unit normal e.
//   * A cycle (m, r) touches it iff e0 + e.m + r = 0; the point of contact
//     is m + r e. So e is the outward normal of a sphere with r > 0.
//   * Adding d to every signed radius (the dilatation that maps a surface to
//     its offset s + d n) maps e0 to e0 - d. Seed 004 writes the dilatation
//     as e0 -> e0 + d before (2.6); with (2.4)'s contact rule that map
//     subtracts d from the radii. `dilatation` below follows the radius rule,
//     so its (2.6) reads y3 - (d/2)(1 + y1^2 + y2^2).
#pragma once

#include <Eigen/Core>

#include "cyclide/status.hpp"
#include "cyclide/vec.hpp"

namespace cyclide {
inline namespace v0 {

template <class S>
using Vec4 = Eigen::Matrix<S, 4, 1>;
using Vec4d = Eigen::Vector4d;

// An oriented plane e0 + e.x = 0 with unit normal e (plane coordinates
// (e0, e1, e2, e3) of seed 004 §2).
struct OrientedPlane {
  double e0 = 0;
  Vec3d e = Vec3d(0, 0, 1);
};

// A cycle: the oriented sphere with centre m and signed radius r, or the
// point m (r = 0). In the cyclographic model it is the point (m, r) of R^4.
struct Cycle {
  Vec3d m = Vec3d::Zero();
  double r = 0;
};

// A point of the isotropic conformal closure I^3 = R^3 u R (seed 004 §2):
// a finite point y = (y1, y2, y3), or, for the exceptional plane (c, 0, 0, 1)
// whose unit normal is the projection centre W = (0, 0, 1), the real number c.
struct IsotropicPoint {
  bool exceptional = false;
  Vec3d y = Vec3d::Zero();  // when !exceptional
  double c = 0;             // when exceptional
};

// The paraboloid (or plane) of (2.4) that a cycle becomes in I^3:
//   2 y3 + k (y1^2 + y2^2) + 2 (l1 y1 + l2 y2) + c0 = 0,
// k = r + m3, l = (m1, m2), c0 = r - m3. k = 0 (a plane) exactly when the
// cycle touches an exceptional plane, whose real number is then c = -m3 - r.
struct IsotropicParaboloid {
  double k = 0;
  double l1 = 0, l2 = 0;
  double c0 = 0;
};

// ---------------------------------------------------------------- planes

// Normalize plane coordinates (e0, e) by 1/|e| (a positive scale keeps the
// orientation). invalid_argument for e = 0, not_finite for NaN/Inf.
Status normalize_plane(double e0, const Vec3d& e, OrientedPlane& out) noexcept;

// Oriented contact of a cycle and a plane, to a tolerance relative to the
// scale of the data: |e0 + e.m + r| <= tol * (|e0| + |m| + |r|) (no
// absolute floor: the same verdict for the model scaled by any s).
bool in_oriented_contact(const Cycle& z, const OrientedPlane& p, double tol = 1e-12) noexcept;

// Point of contact m + r e of a cycle with a plane it touches.
inline Vec3d contact_point(const Cycle& z, const OrientedPlane& p) noexcept {
  return z.m + z.r * p.e;
}

// The cyclographic image of a plane, the hyperplane (2.1) E = (e0, e1, e2, e3, 1)
// (homogeneous: E . (x1, x2, x3, x4, 1)-style pairing with the cycle (m, r)
// reads e0 + e.m + r, contact when 0).
inline Eigen::Matrix<double, 5, 1> cyclographic_hyperplane(const OrientedPlane& p) noexcept {
  Eigen::Matrix<double, 5, 1> E;
  E << p.e0, p.e[0], p.e[1], p.e[2], 1.0;
  return E;
}

// The Blaschke map (2.2): the plane as the point (1, e1, e2, e3, e0) of the
// cylinder Delta: x1^2 + x2^2 + x3^2 = 1 (homogeneous coordinates of R^4).
inline Eigen::Matrix<double, 5, 1> blaschke_point(const OrientedPlane& p) noexcept {
  Eigen::Matrix<double, 5, 1> B;
  B << 1.0, p.e[0], p.e[1], p.e[2], p.e0;
  return B;
}

// ------------------------------------------------------- the isotropic model

// Lambda = sigma o delta o zeta, (2.3): y = (e1, e2, e0) / (1 - e3), and the
// exceptional plane (c, 0, 0, 1) -> the real number c. 1 - e3 is formed as
// (e1^2 + e2^2) / (1 + e3) for e3 > 0, so planes near W keep their digits.
// The plane is normalized first (normalize_plane's statuses);
// numerical_overflow if y overflows (a normal within ~1e-154 of W).
Status laguerre_to_isotropic(const OrientedPlane& p, IsotropicPoint& out) noexcept;

// Lambda^{-1}: the plane of y in homogeneous plane coordinates, scaled by
// N = 1 + y1^2 + y2^2 (so that it is polynomial in y, the form of (4.3)/(4.4)):
//   (2 y3, 2 y1, 2 y2, y1^2 + y2^2 - 1).
// Its normal part has length N. Templated for Taylor jets (partials of
// Lambda^{-1} of a surface, seed 004 Thm. 3.2).
template <class S>
Vec4<S> isotropic_dual_plane(const Vec3<S>& y) {
  const S q = y[0] * y[0] + y[1] * y[1];
  return Vec4<S>(S(2) * y[2], S(2) * y[0], S(2) * y[1], q - S(1));
}

// Lambda^{-1} as a unit plane: e = (2 y1, 2 y2, y1^2 + y2^2 - 1) / N,
// e0 = 2 y3 / N; the real number c -> (c, 0, 0, 1). not_finite for NaN/Inf,
// numerical_overflow if N overflows.
Status isotropic_to_laguerre(const IsotropicPoint& y, OrientedPlane& out) noexcept;

// Exterior product of three vectors of R^4 (seed 004 §4.1): the homogeneous
// point X = (x0, x1, x2, x3) with u . X = 0 for each plane u of the three
// (plane u0 x0 + u1 x1 + u2 x2 + u3 x3 = 0 in homogeneous point coordinates;
// the affine point is (x1, x2, x3) / x0). Zero iff the planes are dependent.
// Sign: X = det-expansion with X . w = det[a; b; c; w] for every w.
template <class S>
Vec4<S> exterior_product(const Vec4<S>& a, const Vec4<S>& b, const Vec4<S>& c) {
  // 2x2 minors of the rows a, b (columns i < j).
  auto m = [&](int i, int j) { return a[i] * b[j] - a[j] * b[i]; };
  const S m01 = m(0, 1), m02 = m(0, 2), m03 = m(0, 3), m12 = m(1, 2), m13 = m(1, 3),
          m23 = m(2, 3);
  // Laplace expansion of det[a; b; c; w] along the last row w.
  return Vec4<S>(-(c[1] * m23 - c[2] * m13 + c[3] * m12), (c[0] * m23 - c[2] * m03 + c[3] * m02),
                 -(c[0] * m13 - c[1] * m03 + c[3] * m01), (c[0] * m12 - c[1] * m02 + c[2] * m01));
}

// The cycle's paraboloid (2.4).
IsotropicParaboloid cycle_to_paraboloid(const Cycle& z) noexcept;

// Whether an isotropic point lies on a cycle's paraboloid (i.e. its plane
// touches the cycle), to tol relative to the scale of the terms; the
// exceptional real number c lies on it iff c + m3 + r = 0.
bool on_paraboloid(const IsotropicParaboloid& P, const IsotropicPoint& y,
                   double tol = 1e-12) noexcept;

// --------------------------------------- Laguerre maps as isotropic Mobius maps

// The translation x -> x + t of R^3: planes e0 -> e0 - e.t; in I^3, (2.5):
//   y3 -> y3 - t1 y1 - t2 y2 - (t3 / 2)(y1^2 + y2^2 - 1),  c -> c - t3.
IsotropicPoint isotropic_translate(const IsotropicPoint& y, const Vec3d& t) noexcept;
OrientedPlane translate(const OrientedPlane& p, const Vec3d& t) noexcept;

// The dilatation adding d to every signed radius (surface -> its offset
// s + d n): planes e0 -> e0 - d; in I^3, (2.6) with the sign of this file's
// header:  y3 -> y3 - (d / 2)(1 + y1^2 + y2^2),  c -> c - d.
IsotropicPoint isotropic_dilatation(const IsotropicPoint& y, double d) noexcept;
OrientedPlane dilatation(const OrientedPlane& p, double d) noexcept;

}  // namespace v0
}  // namespace cyclide
