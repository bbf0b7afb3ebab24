#include "cyclide/hermite.hpp"

namespace cyclide {
inline namespace v0 {

// With n = 2K+1 and h = u1 - u0 the j-th derivatives at the ends are
//   p^(j)(u0) = n!/(n-j)! h^-j  sum_{i<=j} (-1)^(j-i) C(j,i) b_i,
//   p^(j)(u1) = n!/(n-j)! h^-j  sum_{i<=j} (-1)^(j-i) C(j,i) b_{n-j+i},
// triangular in b_0..b_K and b_n..b_{n-K}: solve them one by one.
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
  const double h = u1 - u0;
  Vec3d b[kMaxCurveDegree + 1];
  double factor = 1.0;  // h^j (n-j)!/n!
  for (int j = 0; j <= K; ++j) {
    if (j > 0) factor *= h / double(n - j + 1);
    Vec3d s = factor * start[j];
    for (int i = 0; i < j; ++i) s -= (((j - i) % 2) ? -1.0 : 1.0) * binomial(j, i) * b[i];
    b[j] = s;
    Vec3d e = factor * end[j];
    for (int i = 1; i <= j; ++i)
      e -= (((j - i) % 2) ? -1.0 : 1.0) * binomial(j, i) * b[n - j + i];
    b[n - j] = ((j % 2) ? -1.0 : 1.0) * e;
  }
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
