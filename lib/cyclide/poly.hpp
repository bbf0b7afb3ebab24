// Univariate polynomials of bounded degree, stored without heap memory.
//
// Poly<T,Cap> is a polynomial of degree <= Cap in power form
// sum_k c[k] u^k. Arithmetic that would exceed Cap reports false instead of
// reallocating (SPEC.md: degree bounds are input errors). Bernstein form on
// an interval is available for the exact rational Bezier export.
#pragma once

#include <cmath>

#include "cyclide/taylor.hpp"

namespace cyclide {
inline namespace v0 {

template <class T, int Cap>
struct Poly {
  static_assert(Cap >= 0, "capacity must be non-negative");
  static constexpr int capacity = Cap;
  int deg = 0;  // formal degree: coefficients above deg are zero
  T c[Cap + 1];

  Poly() {
    for (int k = 0; k <= Cap; ++k) c[k] = T(0);
  }
  explicit Poly(const T& constant) : Poly() { c[0] = constant; }

  // From coefficients c0..c_d (power form). Returns false if d > Cap.
  bool assign(const T* coeffs, int d) {
    if (d < 0 || d > Cap) return false;
    for (int k = 0; k <= Cap; ++k) c[k] = k <= d ? coeffs[k] : T(0);
    deg = d;
    return true;
  }
  template <int Cap2>
  bool assign(const Poly<T, Cap2>& o) {
    if (o.deg > Cap) return false;
    return assign(o.c, o.deg);
  }
  // u as a polynomial: a + b u.
  static Poly linear(const T& a, const T& b) {
    Poly p;
    p.c[0] = a;
    if (Cap >= 1) {
      p.c[1] = b;
      p.deg = 1;
    }
    return p;
  }

  T operator()(const T& u) const {  // Horner
    T s = c[deg];
    for (int k = deg - 1; k >= 0; --k) s = s * u + c[k];
    return s;
  }

  // Taylor coefficients of p(u + h) up to order N (Taylor shift by repeated
  // synthetic division, O(deg * N)), i.e. p and its first N derivatives / k!.
  template <int N, class S>
  Taylor<S, N> taylor(const S& u) const {
    S a[Cap + 1];
    for (int k = 0; k <= deg; ++k) a[k] = S(c[k]);
    Taylor<S, N> t;
    for (int i = 0; i <= N && i <= deg; ++i) {
      for (int j = deg - 1; j >= i; --j) a[j] = a[j] + u * a[j + 1];
      t.c[i] = a[i];
    }
    return t;
  }

  // Drop leading coefficients that are exactly zero.
  void trim() {
    while (deg > 0 && c[deg] == T(0)) --deg;
  }
  // Drop leading coefficients below rel * max|c| (rounding residue of exact
  // cancellations in floating point).
  void trim_relative(double rel) {
    using std::abs;
    double m = 0;
    for (int k = 0; k <= deg; ++k) m = std::max(m, double(abs(value_of(c[k]))));
    while (deg > 0 && double(abs(value_of(c[deg]))) <= rel * m) {
      c[deg] = T(0);
      --deg;
    }
  }
  bool is_zero() const {
    for (int k = 0; k <= deg; ++k)
      if (!(c[k] == T(0))) return false;
    return true;
  }

  Poly derivative() const {
    Poly d;
    d.deg = deg > 0 ? deg - 1 : 0;
    for (int k = 1; k <= deg; ++k) d.c[k - 1] = T(k) * c[k];
    return d;
  }
  Poly scaled(const T& s) const {
    Poly r = *this;
    for (int k = 0; k <= deg; ++k) r.c[k] = r.c[k] * s;
    return r;
  }

  friend Poly operator+(const Poly& a, const Poly& b) {
    Poly r;
    r.deg = a.deg > b.deg ? a.deg : b.deg;
    for (int k = 0; k <= r.deg; ++k) r.c[k] = a.c[k] + b.c[k];
    return r;
  }
  friend Poly operator-(const Poly& a, const Poly& b) {
    Poly r;
    r.deg = a.deg > b.deg ? a.deg : b.deg;
    for (int k = 0; k <= r.deg; ++k) r.c[k] = a.c[k] - b.c[k];
    return r;
  }
  friend Poly operator-(const Poly& a) { return a.scaled(T(-1)); }
};

// r = a * b; false (r untouched) if the product's degree exceeds Cap.
template <class T, int Cap, int CapA, int CapB>
bool multiply(const Poly<T, CapA>& a, const Poly<T, CapB>& b, Poly<T, Cap>& r) {
  const int d = a.deg + b.deg;
  if (d > Cap) return false;
  Poly<T, Cap> p;
  p.deg = d;
  for (int i = 0; i <= a.deg; ++i)
    for (int j = 0; j <= b.deg; ++j) p.c[i + j] += a.c[i] * b.c[j];
  r = p;
  return true;
}

// Taylor coefficients at t of the polynomial with Bernstein coefficients
// b_0..b_n on [0,1], with respect to u = u0 + h t (so d/du = h^-1 d/dt).
// One de Casteljau run gives all derivatives: after n-k steps the k-th
// forward difference of the remaining k+1 points times n!/(n-k)! is the
// k-th derivative. Stable for every degree (unlike the power form).
template <int N, class S, class T>
Taylor<S, N> bernstein_taylor(const T* b, int n, const S& t, double h) {
  S pts[64];
  for (int i = 0; i <= n; ++i) pts[i] = S(b[i]);
  Taylor<S, N> r;
  const S one_minus_t = S(1) - t;
  for (int level = n; level >= 0; --level) {
    const int k = level;  // k+1 = number of points left
    if (k <= N) {
      // k-th forward difference of pts[0..k]: sum (-1)^(k-i) C(k,i) pts[i].
      S diff(0);
      double binom = 1.0;  // C(k, i)
      for (int i = 0; i <= k; ++i) {
        diff += S(((k - i) % 2 ? -binom : binom)) * pts[i];
        binom = binom * double(k - i) / double(i + 1);
      }
      // n!/(n-k)! / k! / h^k  (Taylor coefficient = derivative / k!).
      double f = 1.0;
      for (int i = 0; i < k; ++i) f *= double(n - i) / double(i + 1) / h;
      r.c[k] = S(f) * diff;
    }
    if (level == 0) break;
    for (int i = 0; i < level; ++i) pts[i] = one_minus_t * pts[i] + t * pts[i + 1];
  }
  return r;
}

// Binomial coefficient as a double (exact for the degrees used here).
inline double binomial(int n, int k) {
  if (k < 0 || k > n) return 0.0;
  double r = 1.0;
  for (int i = 1; i <= k; ++i) r = r * double(n - k + i) / double(i);
  return std::round(r);
}

// Bernstein coefficients b_0..b_n of p on [u0,u1] (n = p.deg).
template <class T, int Cap>
void to_bernstein(const Poly<T, Cap>& p, const T& u0, const T& u1, T* b) {
  // Power form in t = (u - u0)/(u1 - u0): shift by u0, then scale by h^k.
  const int n = p.deg;
  T a[Cap + 1];
  for (int k = 0; k <= n; ++k) a[k] = p.c[k];
  for (int i = 0; i < n; ++i)
    for (int j = n - 1; j >= i; --j) a[j] = a[j] + u0 * a[j + 1];
  const T h = u1 - u0;
  T hk(1);
  for (int k = 0; k <= n; ++k) {
    a[k] = a[k] * hk;
    hk = hk * h;
  }
  // b_i = sum_{j<=i} C(i,j)/C(n,j) a_j.
  for (int i = 0; i <= n; ++i) {
    T s(0);
    for (int j = 0; j <= i; ++j) s += T(binomial(i, j) / binomial(n, j)) * a[j];
    b[i] = s;
  }
}

// Power form of the polynomial with Bernstein coefficients b_0..b_n on
// [u0,u1]. Returns false if n > Cap.
template <class T, int Cap>
bool from_bernstein(const T* b, int n, const T& u0, const T& u1, Poly<T, Cap>& p) {
  if (n < 0 || n > Cap) return false;
  T a[Cap + 1];
  // a_j = C(n,j) sum_{i<=j} (-1)^{j-i} C(j,i) b_i  (power form in t).
  for (int j = 0; j <= n; ++j) {
    T s(0);
    for (int i = 0; i <= j; ++i) {
      const double sign = ((j - i) % 2) ? -1.0 : 1.0;
      s += T(sign * binomial(j, i)) * b[i];
    }
    a[j] = T(binomial(n, j)) * s;
  }
  // t = (u - u0)/h: scale by h^-k, then shift by -u0.
  const T h = u1 - u0;
  T hk(1);
  for (int k = 0; k <= n; ++k) {
    a[k] = a[k] / hk;
    hk = hk * h;
  }
  const T m = -u0;
  for (int i = 0; i < n; ++i)
    for (int j = n - 1; j >= i; --j) a[j] = a[j] + m * a[j + 1];
  return p.assign(a, n);
}

}  // namespace v0
}  // namespace cyclide
