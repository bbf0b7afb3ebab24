#include "cyclide/curve.hpp"

#include <algorithm>

namespace cyclide {
inline namespace v0 {

int RationalCurve::degree() const {
  return std::max({x.deg, y.deg, z.deg, w.deg});
}

namespace {

bool all_ok(const double* v, int n) {
  for (int i = 0; i < n; ++i)
    if (!input_ok(v[i])) return false;
  return true;
}

Status check_degree(int degree) {
  if (degree < 0) return Status::invalid_argument;
  if (degree > kMaxCurveDegree) return Status::degree_too_high;
  return Status::ok;
}

}  // namespace

Status make_rational_curve(int degree, const double* xyzw, RationalCurve& out) {
  if (!xyzw) return Status::null_argument;
  if (Status s = check_degree(degree); s != Status::ok) return s;
  if (!all_ok(xyzw, 4 * (degree + 1))) return Status::not_finite;
  RationalCurve c;
  double cx[kMaxCurveDegree + 1], cy[kMaxCurveDegree + 1], cz[kMaxCurveDegree + 1],
      cw[kMaxCurveDegree + 1];
  for (int k = 0; k <= degree; ++k) {
    cx[k] = xyzw[4 * k];
    cy[k] = xyzw[4 * k + 1];
    cz[k] = xyzw[4 * k + 2];
    cw[k] = xyzw[4 * k + 3];
  }
  c.x.assign(cx, degree);
  c.y.assign(cy, degree);
  c.z.assign(cz, degree);
  c.w.assign(cw, degree);
  c.x.trim();
  c.y.trim();
  c.z.trim();
  c.w.trim();
  if (c.w.is_zero()) return Status::invalid_argument;
  c.update_constant_weight();
  out = c;
  return Status::ok;
}

Status make_polynomial_curve(int degree, const double* xyz, RationalCurve& out) {
  if (!xyz) return Status::null_argument;
  if (Status s = check_degree(degree); s != Status::ok) return s;
  if (!all_ok(xyz, 3 * (degree + 1))) return Status::not_finite;
  double h[4 * (kMaxCurveDegree + 1)];
  for (int k = 0; k <= degree; ++k) {
    h[4 * k] = xyz[3 * k];
    h[4 * k + 1] = xyz[3 * k + 1];
    h[4 * k + 2] = xyz[3 * k + 2];
    h[4 * k + 3] = k == 0 ? 1.0 : 0.0;
  }
  return make_rational_curve(degree, h, out);
}

Status make_bezier_curve(int degree, const double* ctrl, const double* weights,
                         double u0, double u1, RationalCurve& out) {
  if (!ctrl) return Status::null_argument;
  if (Status s = check_degree(degree); s != Status::ok) return s;
  if (!all_ok(ctrl, 3 * (degree + 1)) || (weights && !all_ok(weights, degree + 1)) ||
      !input_ok(u0) || !input_ok(u1))
    return Status::not_finite;
  if (!(u1 > u0)) return Status::bad_domain;
  // Homogeneous Bernstein coefficients (w_i P_i, w_i) -> power form in u.
  double b[4][kMaxCurveDegree + 1];
  for (int i = 0; i <= degree; ++i) {
    const double wi = weights ? weights[i] : 1.0;
    for (int j = 0; j < 3; ++j) b[j][i] = wi * ctrl[3 * i + j];
    b[3][i] = wi;
  }
  RationalCurve c;
  CurvePoly* polys[4] = {&c.x, &c.y, &c.z, &c.w};
  // Kept in Bernstein form (see RationalCurve); all four share the degree.
  bool weight_zero = true;
  for (int j = 0; j < 4; ++j) polys[j]->assign(b[j], degree);
  for (int i = 0; i <= degree; ++i) weight_zero = weight_zero && b[3][i] == 0.0;
  if (weight_zero) return Status::invalid_argument;
  c.bernstein = true;
  c.u0 = u0;
  c.h = u1 - u0;
  c.update_constant_weight();
  out = c;
  return Status::ok;
}

Status make_line(const Vec3d& P, const Vec3d& d, RationalCurve& out) {
  if (!input_ok(P) || !input_ok(d)) return Status::not_finite;
  if (d.squaredNorm() == 0.0) return Status::zero_tangent;
  const double h[8] = {P.x(), P.y(), P.z(), 1.0, d.x(), d.y(), d.z(), 0.0};
  return make_rational_curve(1, h, out);
}

Status make_point(const Vec3d& P, RationalCurve& out) {
  if (!input_ok(P)) return Status::not_finite;
  const double h[4] = {P.x(), P.y(), P.z(), 1.0};
  RationalCurve c;
  make_rational_curve(0, h, c);
  c.kind = CurveKind::point;
  out = c;
  return Status::ok;
}

Status make_line_element(const Vec3d& P, const Vec3d& t, RationalCurve& out) {
  if (!input_ok(P) || !input_ok(t)) return Status::not_finite;
  if (t.squaredNorm() == 0.0) return Status::zero_tangent;
  RationalCurve c;
  make_point(P, c);
  c.kind = CurveKind::line_element;
  c.tangent = t;
  out = c;
  return Status::ok;
}

}  // namespace v0
}  // namespace cyclide
