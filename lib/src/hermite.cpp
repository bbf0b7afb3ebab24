#include "cyclide/hermite.hpp"

namespace cyclide {
inline namespace v0 {

Status make_hermite_curve(int K, double u0, double u1, const Vec3d* start,
                          const Vec3d* end, RationalCurve& out) {
  if (!start || !end) return Status::null_argument;
  if (K < 0) return Status::invalid_argument;
  if (K > kMaxHermiteOrder) return Status::degree_too_high;
  if (!input_ok(u0) || !input_ok(u1)) return Status::not_finite;
  if (!(u1 > u0)) return Status::bad_domain;
  for (int j = 0; j <= K; ++j)
    if (!input_ok(start[j]) || !input_ok(end[j])) return Status::not_finite;
  const int n = 2 * K + 1;
  Vec3d b[kMaxCurveDegree + 1];
  hermite_bernstein(K, u1 - u0, start, end, b);
  double ctrl[3 * (kMaxCurveDegree + 1)];
  for (int i = 0; i <= n; ++i)
    for (int k = 0; k < 3; ++k) ctrl[3 * i + k] = b[i][k];
  return make_bezier_curve(n, ctrl, nullptr, u0, u1, out);
}

Status make_hermite_spline(int K, int n, const double* u, const Vec3d* data,
                           RationalCurve* pieces) {
  if (!u || !data || !pieces) return Status::null_argument;
  if (n < 2 || n > kMaxSplineKnots) return Status::invalid_argument;
  if (K < 0) return Status::invalid_argument;
  if (K > kMaxHermiteOrder) return Status::degree_too_high;
  RationalCurve tmp[kMaxSplineKnots - 1];
  for (int i = 0; i + 1 < n; ++i)
    if (Status st = make_hermite_curve(K, u[i], u[i + 1], data + i * (K + 1),
                                       data + (i + 1) * (K + 1), tmp[i]);
        st != Status::ok)
      return st;
  for (int i = 0; i + 1 < n; ++i) pieces[i] = tmp[i];
  return Status::ok;
}

}  // namespace v0
}  // namespace cyclide
