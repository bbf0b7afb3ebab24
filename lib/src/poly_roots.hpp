// Internal: the complex roots of a polynomial of the seed-001 sources
// (ringed_field.cpp, contour.cpp) by Eigen's EigenSolver on the companion
// matrix, of fixed capacity (no heap).
#pragma once

#include <Eigen/Eigenvalues>
#include <complex>

#include "cyclide/curve.hpp"

namespace cyclide {
inline namespace v0 {
namespace detail {

constexpr int kMaxRootsDegree = kMaxCurveDegree - 1;  // 14
using Companion = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxRootsDegree,
                                kMaxRootsDegree>;

// The roots of p (degree 1..kMaxRootsDegree, leading coefficient nonzero):
// eigenvalues of the companion matrix (fixed capacity: no heap), each
// polished by up to three Newton steps that must decrease |p|.
inline int poly_roots(const CurvePoly& p, std::complex<double>* roots) {
  const int m = p.deg;
  Companion C = Companion::Zero(m, m);
  for (int i = 1; i < m; ++i) C(i, i - 1) = 1.0;
  for (int i = 0; i < m; ++i) C(i, m - 1) = -p.c[i] / p.c[m];
  Eigen::EigenSolver<Companion> es(C, false);
  if (es.info() != Eigen::Success) return -1;
  for (int i = 0; i < m; ++i) {
    std::complex<double> z = es.eigenvalues()(i);
    auto eval = [&](std::complex<double> x, std::complex<double>& d) {
      std::complex<double> s = p.c[m];
      d = 0;
      for (int k = m - 1; k >= 0; --k) {
        d = d * x + s;
        s = s * x + p.c[k];
      }
      return s;
    };
    for (int it = 0; it < 3; ++it) {
      std::complex<double> d;
      const std::complex<double> v = eval(z, d);
      if (!(std::abs(d) > 0)) break;
      const std::complex<double> z2 = z - v / d;
      std::complex<double> d2;
      if (!(std::abs(eval(z2, d2)) < std::abs(v))) break;
      z = z2;
    }
    roots[i] = z;
  }
  return m;
}

// The real roots of p, nearly real ones included (|Im z| <= 1e-6 (1 + |z|)),
// after trimming leading coefficients below 1e-15 of the largest: their
// number (0 for a constant), or -1 if the roots cannot be computed.
inline int nearly_real_roots(const CurvePoly& p, double* out) {
  CurvePoly a = p;
  a.trim_relative(1e-15);
  if (a.deg == 0) return 0;
  std::complex<double> z[kMaxRootsDegree];
  if (a.deg > kMaxRootsDegree || poly_roots(a, z) != a.deg) return -1;
  int r = 0;
  for (int i = 0; i < a.deg; ++i)
    if (std::abs(z[i].imag()) <= 1e-6 * (1 + std::abs(z[i]))) out[r++] = z[i].real();
  return r;
}

}  // namespace detail
}  // namespace v0
}  // namespace cyclide
