// Laguerre geometry and the isotropic model (seed 004 §2); see laguerre.hpp.
#include "cyclide/laguerre.hpp"

#include <cmath>

namespace cyclide {
inline namespace v0 {

namespace {
bool finite(const Vec3d& v) { return v.allFinite(); }
}  // namespace

Status normalize_plane(double e0, const Vec3d& e, OrientedPlane& out) noexcept {
  if (!std::isfinite(e0) || !finite(e)) return Status::not_finite;
  // Scale by the largest component first: |e| may underflow or overflow.
  const double big = e.cwiseAbs().maxCoeff();
  if (big == 0) return Status::invalid_argument;
  const Vec3d es = e / big;
  const double len = es.norm();
  OrientedPlane p;
  p.e = es / len;
  p.e0 = (e0 / big) / len;
  if (!std::isfinite(p.e0)) return Status::numerical_overflow;
  out = p;
  return Status::ok;
}

bool in_oriented_contact(const Cycle& z, const OrientedPlane& p, double tol) noexcept {
  // Relative to the terms' own size (no floor of one model unit, which
  // would accept any plane near a cycle of size << 1); exact at zero.
  const double g = p.e0 + p.e.dot(z.m) + z.r;
  return std::abs(g) <= tol * (std::abs(p.e0) + z.m.norm() + std::abs(z.r));
}

Status laguerre_to_isotropic(const OrientedPlane& p_in, IsotropicPoint& out) noexcept {
  OrientedPlane p;
  const Status st = normalize_plane(p_in.e0, p_in.e, p);
  if (st != Status::ok) return st;
  const double e1 = p.e[0], e2 = p.e[1], e3 = p.e[2];
  IsotropicPoint y;
  if (e1 == 0 && e2 == 0 && e3 > 0) {  // the exceptional plane (c, 0, 0, 1)
    y.exceptional = true;
    y.c = p.e0;
    out = y;
    return Status::ok;
  }
  // 1 - e3 without cancellation near W: (1 - e3)(1 + e3) = e1^2 + e2^2.
  const double one_minus_e3 = e3 > 0 ? (e1 * e1 + e2 * e2) / (1 + e3) : 1 - e3;
  if (one_minus_e3 == 0) return Status::numerical_overflow;  // e1^2 + e2^2 underflowed
  y.y = Vec3d(e1, e2, p.e0) / one_minus_e3;  // (2.3)
  if (!finite(y.y)) return Status::numerical_overflow;
  out = y;
  return Status::ok;
}

Status isotropic_to_laguerre(const IsotropicPoint& y, OrientedPlane& out) noexcept {
  if (y.exceptional) {
    if (!std::isfinite(y.c)) return Status::not_finite;
    out.e0 = y.c;
    out.e = Vec3d(0, 0, 1);
    return Status::ok;
  }
  if (!finite(y.y)) return Status::not_finite;
  const double q = y.y[0] * y.y[0] + y.y[1] * y.y[1];
  const double N = 1 + q;
  if (!std::isfinite(N)) return Status::numerical_overflow;
  OrientedPlane p;
  p.e = Vec3d(2 * y.y[0] / N, 2 * y.y[1] / N, 1 - 2 / N);  // e3 = (q - 1)/N without cancellation
  p.e0 = 2 * y.y[2] / N;
  if (!std::isfinite(p.e0) || !finite(p.e)) return Status::numerical_overflow;
  out = p;
  return Status::ok;
}

IsotropicParaboloid cycle_to_paraboloid(const Cycle& z) noexcept {
  IsotropicParaboloid P;
  P.k = z.r + z.m[2];
  P.l1 = z.m[0];
  P.l2 = z.m[1];
  P.c0 = z.r - z.m[2];
  return P;
}

bool on_paraboloid(const IsotropicParaboloid& P, const IsotropicPoint& y, double tol) noexcept {
  if (y.exceptional) {
    // The paraboloid's "value at infinity": k = r + m3 must equal -c
    // (the plane (c, 0, 0, 1) touches (m, r) iff c + m3 + r = 0).
    return std::abs(P.k + y.c) <= tol * (std::abs(P.k) + std::abs(y.c));
  }
  const double q = y.y[0] * y.y[0] + y.y[1] * y.y[1];
  const double lin = 2 * (P.l1 * y.y[0] + P.l2 * y.y[1]);
  const double g = 2 * y.y[2] + P.k * q + lin + P.c0;
  const double scale = 2 * std::abs(y.y[2]) + std::abs(P.k) * q + std::abs(lin) + std::abs(P.c0);
  // Every term is a length (y1, y2 dimensionless): relative to their sum,
  // the same for the model scaled by any s.
  return std::abs(g) <= tol * scale;
}

IsotropicPoint isotropic_translate(const IsotropicPoint& y, const Vec3d& t) noexcept {
  IsotropicPoint r = y;
  if (y.exceptional) {
    r.c = y.c - t[2];
    return r;
  }
  const double q = y.y[0] * y.y[0] + y.y[1] * y.y[1];
  r.y[2] = y.y[2] - t[0] * y.y[0] - t[1] * y.y[1] - 0.5 * t[2] * (q - 1);  // (2.5)
  return r;
}

OrientedPlane translate(const OrientedPlane& p, const Vec3d& t) noexcept {
  OrientedPlane r = p;
  r.e0 = p.e0 - p.e.dot(t);
  return r;
}

IsotropicPoint isotropic_dilatation(const IsotropicPoint& y, double d) noexcept {
  IsotropicPoint r = y;
  if (y.exceptional) {
    r.c = y.c - d;
    return r;
  }
  const double q = y.y[0] * y.y[0] + y.y[1] * y.y[1];
  r.y[2] = y.y[2] - 0.5 * d * (1 + q);  // (2.6), radius rule (laguerre.hpp)
  return r;
}

OrientedPlane dilatation(const OrientedPlane& p, double d) noexcept {
  OrientedPlane r = p;
  r.e0 = p.e0 - d;
  return r;
}

}  // namespace v0
}  // namespace cyclide
