// Gauss-Legendre quadrature (shared by the blend optimizer and the
// implicit-blend approximation of seed 001 §7.a). Allocation-free.
#pragma once

#include <cmath>

namespace cyclide {
inline namespace v0 {

// Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_n from the
// Chebyshev-like guess), n >= 1.
inline void gauss_legendre(int n, double* x, double* w) {
  const double pi = std::acos(-1.0);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(pi * (i + 0.75) / (n + 0.5)), dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = z;  // P_{k-1}, P_k
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n == 1 ? 1.0 : n * (z * p1 - p0) / (z * z - 1);
      const double step = p1 / dp;
      z -= step;
      if (std::abs(step) <= 1e-16) break;
    }
    x[i] = z;
    w[i] = 2.0 / ((1 - z * z) * dp * dp);
  }
}

// The same on [0, 1] (nodes (x + 1)/2, weights w/2).
inline void gauss_legendre01(int n, double* x, double* w) {
  gauss_legendre(n, x, w);
  for (int i = 0; i < n; ++i) {
    x[i] = 0.5 * (x[i] + 1.0);
    w[i] *= 0.5;
  }
}

}  // namespace v0
}  // namespace cyclide
