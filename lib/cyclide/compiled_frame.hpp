// Compiled frames: the exact rational frame of a PRCS/PRRS surface
// (exact.hpp) in the domain-local variable t = (u - mid)/half, evaluated by
// Horner with derivatives. Much cheaper per u than intersecting the planes
// on series, which matters for single-point evaluation.
//
// A compiled frame is an accelerator, never the reference: it is built at
// creation only if its degrees fit kCompiledCap, and used only if it agrees
// with the numerical frame (prcs.hpp / prrs.hpp) at every domain sample to
// kCompiledTol. At evaluation it is used only inside the domain and where
// the plane determinant D(t) is not small; elsewhere the numerical frame
// (with its degeneracy checks) decides.
//
// Each of o, a, p is stored as four polynomials (x, y, z numerators and the
// weight w) interleaved coefficient by coefficient, so one Horner step
// advances all four lanes at once (two SSE2 or one AVX2 operation).
#pragma once

#include <cmath>

#include "cyclide/circle_family.hpp"
#include "cyclide/config.hpp"
#include "cyclide/evaluator.hpp"
#include "cyclide/poly.hpp"

namespace cyclide {
inline namespace v0 {

constexpr int kCompiledCap = 40;
constexpr double kCompiledTol = 1e-12;

using CompiledPoly = Poly<double, kCompiledCap>;

// Four doubles (x, y, z, w) as one GCC/Clang vector: one Horner step of all
// four lanes is one AVX2 multiply and add (two of each on SSE2). Only
// 8-byte aligned, so it can live in any caller-allocated handle.
typedef double Lane4 __attribute__((vector_size(32), aligned(8)));

// (x, y, z, w) polynomials of a homogeneous point: coefficient k in c[k].
struct Lanes4 {
  int deg = 0;
  Lane4 c[kCompiledCap + 1] = {};

  // From four polynomials (padded with zeros to the largest degree).
  void assign(const CompiledPoly (&p)[4]) {
    deg = 0;
    for (int l = 0; l < 4; ++l) deg = p[l].deg > deg ? p[l].deg : deg;
    for (int k = 0; k <= kCompiledCap; ++k)
      for (int l = 0; l < 4; ++l) c[k][l] = k <= p[l].deg ? p[l].c[k] : 0.0;
  }
};

// r[j] = (d/du)^j P(t) / j!, j = 0..M, at t (u = mid + half t): Horner
// with derivatives (synthetic division), then d/du = inv_half d/dt.
template <int M>
CYC_ALWAYS_INLINE void horner4(const Lanes4& P, double t, double inv_half, Lane4 (&r)[M + 1]) {
  r[0] = P.c[P.deg];
  for (int j = 1; j <= M; ++j) r[j] = Lane4{0, 0, 0, 0};
  for (int k = P.deg - 1; k >= 0; --k) {
    for (int j = M; j >= 1; --j) r[j] = r[j] * t + r[j - 1];
    r[0] = r[0] * t + P.c[k];
  }
  double f = inv_half;
  for (int j = 1; j <= M; ++j, f *= inv_half) r[j] *= f;
}

// Series of (x, y, z)/w (lane 3 of q is meaningless), given 1/w(t).
template <int M>
CYC_ALWAYS_INLINE void quotient4(const Lane4 (&r)[M + 1], double inv_w, Lane4 (&q)[M + 1]) {
  for (int j = 0; j <= M; ++j) {
    Lane4 s = r[j];
    for (int i = 0; i < j; ++i) s -= q[i] * r[j - i][3];
    q[j] = s * inv_w;
  }
}

struct CompiledFrame {
  bool valid = false;
  bool axis_is_spine_derivative = false;  // PRCS: a = do/du; PRRS: a = A(t)
  double mid = 0.0, inv_half = 1.0;
  double u0 = 0.0, u1 = 0.0;  // trusted interval (the domain)
  double det_floor = 0.0;     // |D(t)| below this: not trusted at u
  Lanes4 o, a, p;             // homogeneous o, a (PRRS only), p

  // The frame (o, a, p) at u to order N; false if not trusted at u.
  template <int N>
  bool eval(double u, Vec3<Taylor<double, N>>& O, Vec3<Taylor<double, N>>& A,
            Vec3<Taylor<double, N>>& P) const {
    Lane4 so[N + 2], sa[N + 1], sp[N + 1];
    if (!series<N>(u, so, sa, sp)) return false;
    for (int l = 0; l < 3; ++l)
      for (int j = 0; j <= N; ++j) {
        O[l].c[j] = so[j][l];
        A[l].c[j] = sa[j][l];
        P[l].c[j] = sp[j][l];
      }
    return true;
  }

  // The circle row (evaluator.hpp) at u for a circle parameter f constant
  // in u (f4 = alpha, beta, gamma, delta), with u-derivatives if WITH_DU
  // and 1/radius if RADIUS. False where the compiled frame is not trusted
  // or a condition of Surface::check_frame fails: the reference path then
  // decides (and reports the status).
  template <bool WITH_DU, bool RADIUS = true>
  bool row(double u, const double (&f4)[4], CircleRow& out) const {
    constexpr int N = WITH_DU ? 1 : 0;
    Lane4 so[N + 2], sa[N + 1], sp[N + 1];
    if (!series<N>(u, so, sa, sp)) return false;
    // check_frame's bound: every frame value (and u-derivative) at most
    // kMaxFrameMagnitude in magnitude; NaN fails too. (Lane 3 holds w/w = 1
    // and its derivatives 0, so it passes.)
    if (!bounded<N>(so, sa, sp)) return false;
    RotationData& R = out.r;
    RotationData& D = out.r_u;
    const Lane4 d = sp[0] - so[0];
    for (int l = 0; l < 3; ++l) {
      R.o[l] = so[0][l];
      R.a[l] = sa[0][l];
      R.d[l] = d[l];
    }
    // a != 0 and not tiny, d != 0 (check_frame's other conditions).
    R.aa = dot3(R.a, R.a);
    const double dd = dot3(R.d, R.d);
    if (!(R.aa >= kMinAxisLength * kMinAxisLength) || !(dd > 0)) return false;
    R.ad = dot3(R.a, R.d);
    cross3(R.a, R.d, R.axd);
    R.alpha = f4[0];
    R.beta = f4[1];
    R.gamma = f4[2];
    R.delta = f4[3];
    if (WITH_DU) {
      const Lane4 d_u = sp[N] - so[N];
      for (int l = 0; l < 3; ++l) {
        D.o[l] = so[N][l];
        D.a[l] = sa[N][l];
        D.d[l] = d_u[l];
      }
      D.aa = 2.0 * dot3(R.a, D.a);
      D.ad = dot3(D.a, R.d) + dot3(R.a, D.d);
      double t1[3], t2[3];
      cross3(D.a, R.d, t1);
      cross3(R.a, D.d, t2);
      for (int l = 0; l < 3; ++l) D.axd[l] = t1[l] + t2[l];
      D.alpha = D.beta = D.gamma = D.delta = 0.0;
    }
    out.inv_radius = RADIUS ? 1.0 / std::sqrt(dd) : 0.0;
    return true;
  }

  // The two steps row starts with; public for the evaluator's single-point
  // kernel, which continues from the series on vectors (evaluator.cpp).

  // Every lane of so[0..N], sa, sp has magnitude <= kMaxFrameMagnitude.
  template <int N>
  static bool bounded(const Lane4 (&so)[N + 2], const Lane4 (&sa)[N + 1],
                      const Lane4 (&sp)[N + 1]) {
    typedef long long Mask4 __attribute__((vector_size(32), aligned(8)));
    const double max2 = kMaxFrameMagnitude * kMaxFrameMagnitude;
    Mask4 ok = so[0] * so[0] <= max2;  // squares: Inf and NaN compare false
    for (int j = 0; j <= N; ++j)
      ok &= (so[j] * so[j] <= max2) & (sa[j] * sa[j] <= max2) & (sp[j] * sp[j] <= max2);
    return (ok[0] & ok[1] & ok[2] & ok[3]) != 0;
  }

  // Normalized u-series of o, a, p to order N at u (so has room for the
  // PRCS spine to order N+1); false if not trusted at u.
  template <int N>
  bool series(double u, Lane4 (&so)[N + 2], Lane4 (&sa)[N + 1], Lane4 (&sp)[N + 1]) const;
};

template <int N>
bool CompiledFrame::series(double u, Lane4 (&so)[N + 2], Lane4 (&sa)[N + 1],
                         Lane4 (&sp)[N + 1]) const {
  if (!valid || !(u >= u0 && u <= u1)) return false;
  const double t = (u - mid) * inv_half;
  if (axis_is_spine_derivative) {
    // o to order N+1; a = o' (normalized coefficients: a_j = (j+1) o_{j+1}).
    Lane4 r[N + 2];
    horner4<N + 1>(o, t, inv_half, r);
    if (!(std::abs(r[0][3]) > det_floor)) return false;
    quotient4<N + 1>(r, 1.0 / r[0][3], so);
    for (int j = 0; j <= N; ++j) sa[j] = double(j + 1) * so[j + 1];
  } else {
    Lane4 r[N + 1], ra[N + 1];
    horner4<N>(o, t, inv_half, r);
    if (!(std::abs(r[0][3]) > det_floor)) return false;
    horner4<N>(a, t, inv_half, ra);
    Lane4 q[N + 1];
    quotient4<N>(r, 1.0 / r[0][3], q);
    for (int j = 0; j <= N; ++j) so[j] = q[j];
    quotient4<N>(ra, 1.0 / ra[0][3], sa);
  }
  Lane4 rp[N + 1];
  horner4<N>(p, t, inv_half, rp);
  quotient4<N>(rp, 1.0 / rp[0][3], sp);
  return true;
}

}  // namespace v0
}  // namespace cyclide
