// Contour curves of ringed surfaces (seed 001 §7); see contour.hpp.
#include "cyclide/contour.hpp"

#include <algorithm>
#include <cmath>

#include "cyclide/ringed.hpp"
#include "poly_roots.hpp"
#include "power_form.hpp"

namespace cyclide {
inline namespace v0 {

namespace {

// An orthonormal pair (e1, e2) perpendicular to the unit vector a.
void plane_basis(const Vec3d& a, Vec3d& e1, Vec3d& e2) {
  const Vec3d h = std::abs(a.x()) < 0.9 ? Vec3d::UnitX() : Vec3d::UnitY();
  e1 = (h - h.dot(a) * a).normalized();
  e2 = a.cross(e1);
}

// Real roots of sum_k q[k] z^k (degree <= 4, leading coefficient nonzero):
// the nearly real ones of detail::poly_roots.
int real_roots_quartic(const double* q, int deg, double* z) {
  if (deg == 0) return 0;
  CurvePoly p;
  p.assign(q, deg);
  std::complex<double> w[4];
  if (detail::poly_roots(p, w) != deg) return 0;
  int r = 0;
  for (int i = 0; i < deg; ++i)
    if (std::abs(w[i].imag()) <= 1e-7 * (1 + std::abs(w[i]))) z[r++] = w[i].real();
  return r;
}

}  // namespace

// Definition 7.1 on the circle at u. The circle point at angle theta is
// x = c + rho r, r = cos e1 + sin e2 (e1, e2 orthonormal in the circle's
// plane), its tangent t = n^ x r. A transversal derivative of a smooth
// angle parameterization: x_u = c' + rho' r - rho (r.n^') n^ (r kept
// unit and perpendicular to n^ by the rotation-minimizing choice). The
// surface normal is x_u x t, and the contour condition (x_u x t).v = 0 is
// a quadratic trigonometric polynomial in theta: with z = tan(theta/2),
// times (1 + z^2)^2, a quartic in z (theta = pi is z = infinity).
Status contour_points(const Surface& S, double u, const Vec3d& v, ContourPoints& out) {
  if (!input_ok(u) || !input_ok(v)) return Status::not_finite;
  const double vmax = v.cwiseAbs().maxCoeff();
  if (!(vmax > 0)) return Status::invalid_argument;
  const Vec3d w = (v / vmax).normalized();
  RingedData R;
  if (Status st = S.ringed(u, R); st != Status::ok) return st;
  if (!(R.rho2 > 0)) return Status::singular_point;
  const double nn = R.n.norm();
  if (!(nn > 0)) return Status::dependent_planes;
  const double rho = std::sqrt(R.rho2), drho = R.rho_rho_prime / rho;
  const Vec3d a = R.n / nn, da = (R.dn - a.dot(R.dn) * a) / nn;
  Vec3d e1, e2;
  plane_basis(a, e1, e2);
  const Vec3d A = R.dc, B1 = drho * e1 - rho * e1.dot(da) * a, B2 = drho * e2 - rho * e2.dot(da) * a;
  // f = ((A + c B1 + s B2) x (c e2 - s e1)).w
  //   = c (A x e2).w - s (A x e1).w + c^2 (B1 x e2).w + s^2 (-(B2 x e1).w)
  //     + c s ((B2 x e2).w - (B1 x e1).w).
  const double k_c = A.cross(e2).dot(w), k_s = -A.cross(e1).dot(w);
  const double k_cc = B1.cross(e2).dot(w), k_ss = -B2.cross(e1).dot(w);
  const double k_cs = B2.cross(e2).dot(w) - B1.cross(e1).dot(w);
  // c = (1 - z^2)/(1 + z^2), s = 2z/(1 + z^2); times (1 + z^2)^2:
  // k_c (1 - z^4) + 2 k_s z (1 + z^2) + k_cc (1 - z^2)^2 + 4 k_ss z^2
  // + 2 k_cs z (1 - z^2).
  double q[5] = {k_c + k_cc, 2 * k_s + 2 * k_cs, -2 * k_cc + 4 * k_ss, 2 * k_s - 2 * k_cs,
                 -k_c + k_cc};
  const double scale = (A.norm() + B1.norm() + B2.norm());
  double qmax = 0;
  for (double x : q) qmax = std::max(qmax, std::abs(x));
  ContourPoints P;
  if (!(qmax > 1e-13 * scale)) {  // f = 0 for every theta
    P.whole_circle = true;
    out = P;
    return Status::ok;
  }
  for (double& x : q) x /= qmax;
  int deg = 4;
  while (deg > 0 && std::abs(q[deg]) <= 1e-14) --deg;
  double z[4], theta[5];
  const int r = real_roots_quartic(q, deg, z);
  int m = 0;
  for (int i = 0; i < r; ++i) theta[m++] = 2 * std::atan(z[i]);
  if (deg < 4) theta[m++] = 3.141592653589793;  // z = infinity is a root
  for (int i = 1; i < m; ++i)  // insertion sort (at most 4 angles)
    for (int j = i; j > 0 && theta[j] < theta[j - 1]; --j) std::swap(theta[j], theta[j - 1]);
  for (int i = 0; i < m; ++i) {
    if (i > 0 && theta[i] - theta[i - 1] < 1e-12) continue;  // a double root
    const Vec3d x = R.c + rho * (std::cos(theta[i]) * e1 + std::sin(theta[i]) * e2);
    if (!x.allFinite()) return Status::numerical_overflow;
    P.points[P.count++] = x;
  }
  out = P;
  return Status::ok;
}

// Eqs. (71), (72).
Status contour_curves_71(const RationalCurve& d, const RationalCurve& n, const CurvePoly& rho_num,
                         const CurvePoly& rho_den, const Vec3d& v, RationalCurve& plus,
                         RationalCurve& minus) {
  if (!input_ok(v)) return Status::not_finite;
  const double vmax = v.cwiseAbs().maxCoeff();
  if (!(vmax > 0)) return Status::invalid_argument;
  const Vec3d w = (v / vmax).normalized();
  if (n.kind != CurveKind::rational) return Status::invalid_argument;
  CurvePoly N[3], wn;
  detail::power_form(n, N, wn);
  double nmax = 0;
  for (const CurvePoly& p : N) nmax = std::max(nmax, detail::max_abs(p));
  const CurvePoly nv = N[0].scaled(w.x()) + N[1].scaled(w.y()) + N[2].scaled(w.z());
  if (!(detail::max_abs(nv) <= 1e-12 * nmax)) return Status::invalid_argument;  // (71) fails
  RationalField f;
  // (n x v)/sigma with sigma^2 = |n|^2 - (n.v)^2 = |n|^2 (14): Prop. 7.2.
  if (Status st = projection_field(n, w, f); st != Status::ok) return st;
  RationalCurve cp, cm;
  if (Status st = ringed_curve(d, rho_num, rho_den, f, cp); st != Status::ok) return st;
  for (CurvePoly& p : f.F) p = -p;
  if (Status st = ringed_curve(d, rho_num, rho_den, f, cm); st != Status::ok) return st;
  plus = cp;
  minus = cm;
  return Status::ok;
}

}  // namespace v0
}  // namespace cyclide
