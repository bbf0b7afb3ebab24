// Two-point C^K Hermite interpolation (seed 000 §9 (ii)): the polynomial
// curve of degree 2K+1 on [u0,u1] with prescribed p, p', ..., p^(K) at both
// ends, built in Bernstein form and returned in power form.
#pragma once

#include "cyclide/curve.hpp"

namespace cyclide {
inline namespace v0 {

constexpr int kMaxHermiteOrder = (kMaxCurveDegree - 1) / 2;  // 7

// start[j], end[j] = p^(j)(u0), p^(j)(u1) for j = 0..K.
Status make_hermite_curve(int K, double u0, double u1, const Vec3d* start,
                          const Vec3d* end, RationalCurve& out);

}  // namespace v0
}  // namespace cyclide
