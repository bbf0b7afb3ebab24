// Internal helpers of the seed-001 sources (pcurve.cpp, ringed_field.cpp):
// coefficient checks and the homogeneous power form of a curve.
#pragma once

#include <algorithm>
#include <cmath>

#include "cyclide/curve.hpp"

namespace cyclide {
inline namespace v0 {
namespace detail {

template <int Cap>
double max_abs(const Poly<double, Cap>& p) {
  double m = 0;
  for (int k = 0; k <= p.deg; ++k) m = std::max(m, std::abs(p.c[k]));
  return m;
}

inline bool finite(const CurvePoly& p) {
  for (int k = 0; k <= p.deg; ++k)
    if (!std::isfinite(p.c[k])) return false;
  return true;
}

// |N|^2 = N.N (the caller keeps 2 deg N within kMaxCurveDegree).
inline CurvePoly square_norm(const CurvePoly (&N)[3]) {
  CurvePoly s, t;
  for (const CurvePoly& p : N) {
    multiply(p, p, t);
    s = s + t;
  }
  return s;
}

// The homogeneous power-form polynomials (x, y, z, w) of a curve
// (Bernstein curves converted on their interval), trimmed.
inline void power_form(const RationalCurve& c, CurvePoly (&P)[3], CurvePoly& w) {
  const CurvePoly* src[4] = {&c.x, &c.y, &c.z, &c.w};
  CurvePoly* dst[4] = {&P[0], &P[1], &P[2], &w};
  for (int i = 0; i < 4; ++i) {
    if (c.bernstein)
      from_bernstein(src[i]->c, c.degree(), c.u0, c.u0 + c.h, *dst[i]);
    else
      *dst[i] = *src[i];
    dst[i]->trim();
  }
}

}  // namespace detail
}  // namespace v0
}  // namespace cyclide
