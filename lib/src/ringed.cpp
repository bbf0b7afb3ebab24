#include "cyclide/ringed.hpp"

#include <cmath>

namespace cyclide {
inline namespace v0 {

namespace {
template <int N>
Vec3d coeff(const Vec3<Taylor<double, N>>& v, int k) {
  return {v[0].c[k], v[1].c[k], v[2].c[k]};
}
}  // namespace

RingedData ringed_data(const CircleFrame<T1>& F) {
  const CircleGeometry<T1> G = circle_geometry(F);
  RingedData R;
  R.c = coeff(G.center, 0);
  R.dc = coeff(G.center, 1);
  R.n = coeff(G.normal, 0);
  R.dn = coeff(G.normal, 1);
  R.rho2 = G.radius2.c[0];
  R.rho_rho_prime = 0.5 * G.radius2.c[1];
  return R;
}

RingedData ringed_from_canal(const Vec3<Taylor<double, 2>>& s,
                             const Taylor<double, 2>& r2) {
  using T = Taylor<double, 1>;
  // n = s' and r r' = (r^2)'/2 as series of order 1.
  const Vec3<T> n = derivative(s);
  const T rr = T(0.5) * derivative(r2);
  const Vec3<T> s1 = truncate<1>(s);
  const T r21 = truncate<1>(r2);
  const T nn = n.dot(n);
  const Vec3<T> c = s1 - (rr / nn) * n;
  // rho^2 = r^2 - (r r')^2 / |s'|^2  (= r^2 (|s'|^2 - r'^2) / |s'|^2).
  const T rho2 = r21 - rr * rr / nn;
  RingedData R;
  R.c = coeff(c, 0);
  R.dc = coeff(c, 1);
  R.n = coeff(n, 0);
  R.dn = coeff(n, 1);
  R.rho2 = rho2.c[0];
  R.rho_rho_prime = 0.5 * rho2.c[1];
  return R;
}

double canal_residual(const RingedData& R) {
  const double nc = R.n.dot(R.dc);
  const Vec3d E = nc * R.dc + R.rho_rho_prime * R.dn;
  // The scale must not cancel: where n.c' = 0 on a canal surface also
  // rho rho' = 0, and dividing rounding by rounding gave residuals ~1. Use
  // |n| |c'| for |n.c'| and rho^2 |n'|/|n| as the natural size of rho rho'.
  const double nn = R.n.norm();
  if (!(nn > 0)) return 0.0;
  const double scale =
      (nn * R.dc.squaredNorm() +
       (std::abs(R.rho_rho_prime) + R.rho2 * R.dn.norm() / nn) * R.dn.norm()) * nn;
  if (!(scale > 0)) return 0.0;
  return E.cross(R.n).norm() / scale;
}

Status ringed_sphere(const RingedData& R, Vec3d& center, double& radius2) {
  const double nc = R.n.dot(R.dc);
  if (!(std::abs(nc) > 1e-12 * R.n.norm() * R.dc.norm())) return Status::degenerate_ringed;
  const double k = R.rho_rho_prime / nc;
  const Vec3d m = R.c + k * R.n;
  const double r2 = R.rho2 + k * k * R.n.squaredNorm();
  if (!std::isfinite(m.x()) || !std::isfinite(m.y()) || !std::isfinite(m.z()) ||
      !std::isfinite(r2))
    return Status::numerical_overflow;
  center = m;
  radius2 = r2;
  return Status::ok;
}

}  // namespace v0
}  // namespace cyclide
