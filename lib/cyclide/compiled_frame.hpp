// Compiled frames: the exact rational frame of a PRCS/PRRS surface
// (exact.hpp) in the domain-local variable t = (u - mid)/half, evaluated by
// Horner with derivatives. About 8x cheaper per u than intersecting the
// planes on series, which matters for single-point evaluation.
//
// A compiled frame is an accelerator, never the reference: it is built at
// creation only if its degrees fit kCompiledCap, and used only if it agrees
// with the numerical frame (prcs.hpp / prrs.hpp) at every domain sample to
// kCompiledTol. At evaluation it is used only inside the domain and where
// the plane determinant D(t) is not small; elsewhere the numerical frame
// (with its degeneracy checks) decides.
#pragma once

#include "cyclide/circle_family.hpp"
#include "cyclide/poly.hpp"

namespace cyclide {
inline namespace v0 {

constexpr int kCompiledCap = 40;
constexpr double kCompiledTol = 1e-12;

using CompiledPoly = Poly<double, kCompiledCap>;

// Value and normalized derivatives (p^(j)(u)/j!, j <= M) of a polynomial in
// t = (u - mid)/half at t: Horner with derivatives, then d/du = d/dt / half.
template <int M>
Taylor<double, M> horner_taylor(const CompiledPoly& p, double t, double inv_half) {
  double r[M + 1];
  r[0] = p.c[p.deg];
  for (int j = 1; j <= M; ++j) r[j] = 0.0;
  for (int k = p.deg - 1; k >= 0; --k) {
    for (int j = M; j >= 1; --j) r[j] = r[j] * t + r[j - 1];
    r[0] = r[0] * t + p.c[k];
  }
  Taylor<double, M> out;
  double f = 1.0;
  for (int j = 0; j <= M; ++j, f *= inv_half) out.c[j] = r[j] * f;
  return out;
}

struct CompiledFrame {
  bool valid = false;
  bool axis_is_spine_derivative = false;  // PRCS: a = do/du; PRRS: a = A(t)
  double mid = 0.0, inv_half = 1.0;
  double u0 = 0.0, u1 = 0.0;  // trusted interval (the domain)
  double det_floor = 0.0;     // |D(t)| below this: not trusted at u
  CompiledPoly o[4], a[4], p[4];  // (x, y, z, w) numerators and weights

  // The frame (o, a, p) at u to order N; false if not trusted at u.
  template <int N>
  bool eval(double u, Vec3<Taylor<double, N>>& O, Vec3<Taylor<double, N>>& A,
            Vec3<Taylor<double, N>>& P) const {
    if (!valid || !(u >= u0 && u <= u1)) return false;
    const double t = (u - mid) * inv_half;
    if (axis_is_spine_derivative) {
      // o to order N+1, a = o'.
      const Taylor<double, N + 1> W = horner_taylor<N + 1>(o[3], t, inv_half);
      if (!(std::abs(W.c[0]) > det_floor)) return false;
      Vec3<Taylor<double, N + 1>> S;
      for (int j = 0; j < 3; ++j) S[j] = horner_taylor<N + 1>(o[j], t, inv_half) / W;
      O = truncate<N>(S);
      A = derivative(S);
    } else {
      const Taylor<double, N> W = horner_taylor<N>(o[3], t, inv_half);
      if (!(std::abs(W.c[0]) > det_floor)) return false;
      const Taylor<double, N> AW = horner_taylor<N>(a[3], t, inv_half);
      for (int j = 0; j < 3; ++j) {
        O[j] = horner_taylor<N>(o[j], t, inv_half) / W;
        A[j] = horner_taylor<N>(a[j], t, inv_half) / AW;
      }
    }
    const Taylor<double, N> PW = horner_taylor<N>(p[3], t, inv_half);
    for (int j = 0; j < 3; ++j) P[j] = horner_taylor<N>(p[j], t, inv_half) / PW;
    return true;
  }
};

}  // namespace v0
}  // namespace cyclide
