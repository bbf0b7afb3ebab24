// Two-point C^K Hermite interpolation (seed 000 §9 (ii)): the polynomial
// curve of degree 2K+1 on [u0,u1] with prescribed p, p', ..., p^(K) at both
// ends, built in Bernstein form and returned in power form.
#pragma once

#include "cyclide/curve.hpp"

namespace cyclide {
inline namespace v0 {

constexpr int kMaxHermiteOrder = (kMaxCurveDegree - 1) / 2;  // 7
constexpr int kMaxSplineKnots = 16;  // knots of make_hermite_spline (15 pieces)

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
