// Truncated Taylor series in one variable: the arithmetic that carries a
// quantity and its first N derivatives through the constructions of seed 000
// without finite differences (ERRATA "numerical pitfalls": s' must be exact).
//
// Taylor<T,N> holds c[k] = f^(k)(u0)/k!, k = 0..N. Products and quotients
// are the Cauchy products of the series truncated at order N. T is any
// scalar (double, or ceres::Jet later), so derivatives with respect to
// design parameters flow through the same code.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <type_traits>

namespace cyclide {
inline namespace v0 {

template <class T, int N>
struct Taylor {
  static_assert(N >= 0, "order must be non-negative");
  T c[N + 1];

  Taylor() {
    for (int k = 0; k <= N; ++k) c[k] = T(0);
  }
  Taylor(const T& value) {  // NOLINT: a constant is a series
    c[0] = value;
    for (int k = 1; k <= N; ++k) c[k] = T(0);
  }
  // Plain numbers (Eigen writes Scalar(0); Jets have explicit constructors).
  template <class A, typename std::enable_if<std::is_arithmetic<A>::value &&
                                                 !std::is_same<A, T>::value,
                                             int>::type = 0>
  Taylor(A value) : Taylor(T(value)) {}  // NOLINT
  // The variable itself around u0: u0 + h.
  static Taylor variable(const T& u0) {
    Taylor t(u0);
    if (N >= 1) t.c[1] = T(1);
    return t;
  }
  const T& value() const { return c[0]; }
  // k-th derivative (k! c[k]).
  T derivative(int k) const {
    T f(1);
    for (int i = 2; i <= k; ++i) f *= T(i);
    return f * c[k];
  }
  // The series of f' truncated at order N-1 is returned as order N with a
  // zero last coefficient (callers that need f' exactly to order N-1 use it).
  Taylor derivative_series() const {
    Taylor d;
    for (int k = 0; k < N; ++k) d.c[k] = T(k + 1) * c[k + 1];
    return d;
  }

  Taylor& operator+=(const Taylor& o) {
    for (int k = 0; k <= N; ++k) c[k] += o.c[k];
    return *this;
  }
  Taylor& operator-=(const Taylor& o) {
    for (int k = 0; k <= N; ++k) c[k] -= o.c[k];
    return *this;
  }
  Taylor& operator*=(const Taylor& o) { return *this = *this * o; }
  Taylor& operator/=(const Taylor& o) { return *this = *this / o; }

  friend Taylor operator+(Taylor a, const Taylor& b) { return a += b; }
  friend Taylor operator-(Taylor a, const Taylor& b) { return a -= b; }
  friend Taylor operator-(const Taylor& a) {
    Taylor r;
    for (int k = 0; k <= N; ++k) r.c[k] = -a.c[k];
    return r;
  }
  friend Taylor operator*(const Taylor& a, const Taylor& b) {
    Taylor r;
    for (int k = 0; k <= N; ++k) {
      T s(0);
      for (int i = 0; i <= k; ++i) s += a.c[i] * b.c[k - i];
      r.c[k] = s;
    }
    return r;
  }
  // Series division: r = a / b with r_k = (a_k - sum_{i<k} r_i b_{k-i}) / b_0.
  friend Taylor operator/(const Taylor& a, const Taylor& b) {
    Taylor r;
    const T inv = T(1) / b.c[0];
    for (int k = 0; k <= N; ++k) {
      T s = a.c[k];
      for (int i = 0; i < k; ++i) s -= r.c[i] * b.c[k - i];
      r.c[k] = s * inv;
    }
    return r;
  }
  friend bool operator==(const Taylor& a, const Taylor& b) {
    for (int k = 0; k <= N; ++k)
      if (!(a.c[k] == b.c[k])) return false;
    return true;
  }
  friend bool operator!=(const Taylor& a, const Taylor& b) { return !(a == b); }
  // Orderings compare values only (used by Eigen's generic code).
  friend bool operator<(const Taylor& a, const Taylor& b) { return a.c[0] < b.c[0]; }
  friend bool operator>(const Taylor& a, const Taylor& b) { return a.c[0] > b.c[0]; }
  friend bool operator<=(const Taylor& a, const Taylor& b) { return a.c[0] <= b.c[0]; }
  friend bool operator>=(const Taylor& a, const Taylor& b) { return a.c[0] >= b.c[0]; }
};

// sqrt of a series with positive value: r_0 = sqrt(a_0),
// r_k = (a_k - sum_{0<i<k} r_i r_{k-i}) / (2 r_0).
template <class T, int N>
Taylor<T, N> sqrt(const Taylor<T, N>& a) {
  using std::sqrt;
  Taylor<T, N> r;
  r.c[0] = sqrt(a.c[0]);
  const T inv = T(1) / (T(2) * r.c[0]);
  for (int k = 1; k <= N; ++k) {
    T s = a.c[k];
    for (int i = 1; i < k; ++i) s -= r.c[i] * r.c[k - i];
    r.c[k] = s * inv;
  }
  return r;
}

template <class T, int N>
Taylor<T, N> abs(const Taylor<T, N>& a) {
  return a.c[0] < T(0) ? -a : a;
}

template <class T, int N>
bool isfinite(const Taylor<T, N>& a) {
  using std::isfinite;
  for (int k = 0; k <= N; ++k)
    if (!isfinite(a.c[k])) return false;
  return true;
}

// Value of a scalar, of a series, or of a Ceres Jet (member `a`): lets
// templated code read plain numbers for its degeneracy tests.
inline double value_of(double x) { return x; }
template <class J>
auto value_of(const J& x) -> decltype(double(x.a)) {
  return double(x.a);
}
template <class T, int N>
double value_of(const Taylor<T, N>& x) {
  return value_of(x.c[0]);
}

}  // namespace v0
}  // namespace cyclide

namespace Eigen {
template <class T, int N>
struct NumTraits<cyclide::Taylor<T, N>> : NumTraits<T> {
  typedef cyclide::Taylor<T, N> Real;
  typedef cyclide::Taylor<T, N> NonInteger;
  typedef cyclide::Taylor<T, N> Nested;
  typedef cyclide::Taylor<T, N> Literal;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = (N + 1) * NumTraits<T>::ReadCost,
    AddCost = (N + 1) * NumTraits<T>::AddCost,
    MulCost = (N + 1) * (N + 2) / 2 * NumTraits<T>::MulCost,
  };
};
}  // namespace Eigen

namespace cyclide {
inline namespace v0 {

// The first M+1 coefficients of a series (M <= N).
template <int M, class T, int N>
Taylor<T, M> truncate(const Taylor<T, N>& a) {
  static_assert(M <= N, "cannot extend a series by truncation");
  Taylor<T, M> r;
  for (int k = 0; k <= M; ++k) r.c[k] = a.c[k];
  return r;
}

// f(u0 + h(t)) for the series f around u0 and h with h(t0) = 0 (h.c[0] is
// ignored): the composition, by Horner in h, truncated at order N. With
// h = the derivatives of a reparameterization u = phi(t) it is Faa di
// Bruno's formula: (f o phi)^(l)(t0) = l! r.c[l].
template <class T, int N, class F>
Taylor<T, N> compose(const Taylor<F, N>& f, Taylor<T, N> h) {
  h.c[0] = T(0);
  Taylor<T, N> r(T(f.c[N]));
  for (int k = N - 1; k >= 0; --k) {
    r = r * h;
    r.c[0] += T(f.c[k]);
  }
  return r;
}

// The series of the derivative, exact to order N-1.
template <class T, int N>
Taylor<T, N - 1> derivative(const Taylor<T, N>& a) {
  static_assert(N >= 1, "derivative of an order-0 series is unknown");
  Taylor<T, N - 1> r;
  for (int k = 0; k < N; ++k) r.c[k] = T(k + 1) * a.c[k + 1];
  return r;
}

}  // namespace v0
}  // namespace cyclide
