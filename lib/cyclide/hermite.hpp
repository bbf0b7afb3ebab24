// Two-point C^K Hermite interpolation (seed 000 §9 (ii)): the polynomial
// curve of degree 2K+1 on [u0,u1] with prescribed p, p', ..., p^(K) at both
// ends, built and kept in Bernstein form on [u0, u1] (stable for every
// degree; curve.hpp).
#pragma once

#include "cyclide/curve.hpp"

namespace cyclide {
inline namespace v0 {

constexpr int kMaxHermiteOrder = (kMaxCurveDegree - 1) / 2;  // 7
constexpr int kMaxSplineKnots = 16;  // knots of make_hermite_spline (15 pieces)

// The Bernstein coefficients b_0..b_n (n = 2K+1) on an interval of length
// h of the polynomial with p^(j) = start[j] at its start and end[j] at its
// end (j = 0..K). With these derivatives at the ends
//   p^(j)(u0) = n!/(n-j)! h^-j  sum_{i<=j} (-1)^(j-i) C(j,i) b_i,
//   p^(j)(u1) = n!/(n-j)! h^-j  sum_{i<=j} (-1)^(j-i) C(j,i) b_{n-j+i},
// the system is triangular in b_0..b_K and b_n..b_{n-K}: solve them one by
// one. V is double (a scalar, e.g. a Mobius coefficient) or Vec3d.
template <class V>
void hermite_bernstein(int K, double h, const V* start, const V* end, V* b) {
  const int n = 2 * K + 1;
  double factor = 1.0;  // h^j (n-j)!/n!
  for (int j = 0; j <= K; ++j) {
    if (j > 0) factor *= h / double(n - j + 1);
    V s = factor * start[j];
    for (int i = 0; i < j; ++i) s -= (((j - i) % 2) ? -1.0 : 1.0) * binomial(j, i) * b[i];
    b[j] = s;
    V e = factor * end[j];
    for (int i = 1; i <= j; ++i)
      e -= (((j - i) % 2) ? -1.0 : 1.0) * binomial(j, i) * b[n - j + i];
    b[n - j] = ((j % 2) ? -1.0 : 1.0) * e;
  }
}

// start[j], end[j] = p^(j)(u0), p^(j)(u1) for j = 0..K.
Status make_hermite_curve(int K, double u0, double u1, const Vec3d* start,
                          const Vec3d* end, RationalCurve& out);

// A C^K piecewise Hermite curve (spline) through n >= 2 knots u[0] < ... <
// u[n-1] with data[i * (K + 1) + j] = p^(j)(u[i]): piece i is the two-point
// Hermite curve on [u[i], u[i+1]] (degree 2K+1), so the pieces join C^K
// at the interior knots. pieces[0 .. n-2] are written only on success.
Status make_hermite_spline(int K, int n, const double* u, const Vec3d* data,
                           RationalCurve* pieces);

}  // namespace v0
}  // namespace cyclide
