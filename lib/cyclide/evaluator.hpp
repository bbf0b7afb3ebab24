// The one evaluator of circle-family surfaces: from a circle row (the
// rotation data of one u and their u-derivatives) to points, x_u, x_v and
// unit normals.
//
// Per point, q = W + G a with W = alpha s1 + beta s0, G = gamma s1 + delta s0,
// (s1, s0) = (v, 1) for |v| <= 1 and (1, 1/v) otherwise (q scaled by 1/v:
// the same rotation), and eqs. (11)/(27) expanded:
//   x = o + [(W^2 - G^2 |a|^2) d + 2 G^2 (a.d) a + 2 W G (a x d)] / (W^2 + G^2 |a|^2),
// with d = p - o. Forming W and G first keeps the result accurate when f is
// nearly degenerate or |a| is far from 1 (expanding into a quadratic in v
// first cancelled, and once even gave 0/0). x_v is the exact rotation rate
//   x_v = 2 (beta gamma - alpha delta) s0^2 a x (x - o) / (W^2 + G^2 |a|^2).
// Ringed normals need neither x_u nor x_v per point: see CircleConstants.
//
// eval_point is the per-point formula. Grids evaluate it over chunks of
// kChunk values of v into structure-of-arrays scratch with no control flow
// (the two cases of v are exact blends), so the compiler vectorizes the loop;
// each chunk is then stored to the caller's strided buffers. Everything is
// specialized at compile time on what is wanted, and compiled twice
// (evaluator.cpp): for the baseline x86-64 and for AVX2, chosen once at
// run time from the CPU (SPEC §1b).
#pragma once

#include <cmath>
#include <cstddef>

#include "cyclide/status.hpp"

namespace cyclide {
inline namespace v0 {

// The rotation data of one circle (and, in a second copy, their
// u-derivatives): everything a point needs besides v.
struct RotationData {
  double o[3], d[3], a[3], axd[3];       // axis point, p - o, axis, a x d
  double aa, ad;                         // |a|^2, a . d
  double alpha, beta, gamma, delta;      // f = (alpha v + beta) / (gamma v + delta)
};

// Per-u data.
struct CircleRow {
  RotationData r;    // values
  RotationData r_u;  // d/du of every field (when computed)
  double inv_radius = 0;  // canal: 1 / r(u), for the normal (x - s)/r
};

// What an evaluation writes (null = not wanted).
struct EvalOut {
  double* point = nullptr;
  double* du = nullptr;
  double* dv = nullptr;
  double* normal = nullptr;
};

// Caller-owned strided output of 3-vectors: element i at data + i * stride.
struct Strided3 {
  double* data = nullptr;
  std::size_t stride = 3;  // in doubles, >= 3
  double* at(std::size_t i) const { return data + i * stride; }
};

// The ringed normal is undefined where |x~_u x x_v| <= kSingularTol M |x_v|,
// M >= |x~_u| on the circle (CircleConstants).
constexpr double kSingularTol = 1e-14;

constexpr int kChunk = 256;

#if defined(__GNUC__)
#define CYC_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define CYC_ALWAYS_INLINE inline
#endif

// The two cases of v as exact blends (w is 0 or 1): (s1, s0) = (v, 1) for
// |v| <= 1, (1, 1/v) otherwise.
CYC_ALWAYS_INLINE void circle_parameter(double v, double& s1, double& s0) {
  const double w = std::abs(v) <= 1.0 ? 1.0 : 0.0, w1 = 1.0 - w;
  s1 = w * v + w1;
  s0 = w + w1 / (w1 * v + w);
}

// 0 if x's components are finite, NaN otherwise (x - x is NaN for Inf and
// NaN): a sum of these tests many values with one comparison, no branches.
CYC_ALWAYS_INLINE double nonfinite3(const double (&x)[3]) {
  return (x[0] - x[0]) + (x[1] - x[1]) + (x[2] - x[2]);
}

// One point's results (only the wanted ones are computed).
struct PointResult {
  double x[3], xu[3], xv[3], n[3];
  double c, s;       // cos theta and sin theta / |a| of the point's rotation
  double singular;   // 1.0 where the (ringed) normal is undefined
};

// The rotation q = W + G a of one value of v: W = alpha s1 + beta s0,
// G = gamma s1 + delta s0, and the products the point needs. When f is
// the same on many circles (f constant in u), a grid forms these once per
// v for all of them.
struct CircleParameter {
  double s1, s0, W, G;
  double W2, G2, WG2;  // W^2, G^2, 2 W G
};

// k = 2 (beta gamma - alpha delta): x_v = k s0^2 a x (x - o) / den, and its
// sign orients the ringed normal.
CYC_ALWAYS_INLINE double rotation_rate_factor(const RotationData& R) {
  return 2.0 * (R.beta * R.gamma - R.alpha * R.delta);
}

CYC_ALWAYS_INLINE CircleParameter circle_rotation(const RotationData& R, double s1, double s0) {
  CircleParameter q;
  q.s1 = s1;
  q.s0 = s0;
  q.W = R.alpha * s1 + R.beta * s0;
  q.G = R.gamma * s1 + R.delta * s0;
  q.W2 = q.W * q.W;
  q.G2 = q.G * q.G;
  q.WG2 = 2.0 * (q.W * q.G);
  return q;
}

// What every point of one circle shares besides the rotation data (SPEC
// §1b). With c = cos theta = (W^2 - G^2 |a|^2) / den and
// s = sin theta / |a| = 2 W G / den, den = W^2 + G^2 |a|^2, the rotation
// of d about a by theta is
//   x - o = a0 + c a1 + s a x d,   a0 = (a.d / |a|^2) a,  a1 = d - a0.
// The ringed normal: the normal line does not depend on how the points of
// each circle are parameterized, so x_u may be replaced by x~_u, the
// u-derivative at a fixed angle theta, and x_v by a x (x - o):
//   x~_u = e0 + c u1 + s u2,   e0 = o_u + a0_u,  u1 = d_u - a0_u,
//                              u2 = (a x d)_u - (|a|_u / |a|) a x d,
//   sgn(k) a x (x - o) = c t1 - s t2,   t1 = sgn(k) a x d,
//                                       t2 = sgn(k) (|a|^2 d - (a.d) a),
// with k = 2 (beta gamma - alpha delta) (x_v = k s0^2 a x (x - o) / den),
// so the unit normal x_u x x_v / |...| is that of x~_u x (c t1 - s t2).
// Expanded, with c^2 = 1 - |a|^2 s^2, that cross product is
//   m = k0 + c k1 + s k2 + s^2 k3 + c s k4,
//   k0 = u1 x t1, k1 = e0 x t1, k2 = -e0 x t2, k3 = -u2 x t2 - |a|^2 u1 x t1,
//   k4 = u2 x t1 - u1 x t2:
// 14 multiplications per point instead of 18 (the multipliers are what a
// grid of normals waits on).
struct CircleConstants {
  double a0[3], a1[3];
  double k[5][3];  // ringed normals only
  // kSingularTol^2 M^2 |a x d|^2, M = |e0| + sqrt(|u1|^2 + |u2|^2 / |a|^2)
  // >= |x~_u| on the whole circle, |a x d| = |a x (x - o)|: the normal is
  // undefined where |x~_u x a x (x - o)| is not above its root.
  double singular_floor2;
};

CYC_ALWAYS_INLINE double dot3(const double (&x)[3], const double (&y)[3]) {
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}

CYC_ALWAYS_INLINE void cross3(const double (&x)[3], const double (&y)[3], double (&z)[3]) {
  z[0] = x[1] * y[2] - x[2] * y[1];
  z[1] = x[2] * y[0] - x[0] * y[2];
  z[2] = x[0] * y[1] - x[1] * y[0];
}

// CircleConstants::singular_floor2 from M and tt = |a x d|^2 (at least
// DBL_MIN, so that |m|^2 raised to it can be divided by).
CYC_ALWAYS_INLINE double singular_floor2(double M, double tt) {
  const double f = kSingularTol * kSingularTol * (M * M) * tt;
  return f > 0x1p-1022 ? f : 0x1p-1022;  // NaN -> DBL_MIN as well
}

// The constants of the circle with rotation data R, their u-derivatives D
// (read only if RINGED_NORMAL) and k.
template <bool RINGED_NORMAL>
CYC_ALWAYS_INLINE void circle_constants(const RotationData& R, const RotationData& D, double k,
                                        CircleConstants& C) {
  const double inv_aa = 1.0 / R.aa;
  const double q = R.ad * inv_aa;  // a0 = q a
  for (int j = 0; j < 3; ++j) {
    C.a0[j] = q * R.a[j];
    C.a1[j] = R.d[j] - C.a0[j];
  }
  if (!RINGED_NORMAL) return;
  const double q_u = (D.ad * R.aa - R.ad * D.aa) * (inv_aa * inv_aa);
  const double h = 0.5 * D.aa * inv_aa;  // |a|_u / |a|
  const double sg = k > 0 ? 1.0 : (k < 0 ? -1.0 : 0.0);  // k = 0: t = 0, all singular
  double e0[3], u1[3], u2[3], t1[3], t2[3];
  for (int j = 0; j < 3; ++j) {
    const double a0_u = q_u * R.a[j] + q * D.a[j];
    e0[j] = D.o[j] + a0_u;
    u1[j] = D.d[j] - a0_u;
    u2[j] = D.axd[j] - h * R.axd[j];
    t1[j] = sg * R.axd[j];
    t2[j] = sg * (R.aa * R.d[j] - R.ad * R.a[j]);
  }
  double u1t1[3], e0t1[3], e0t2[3], u2t2[3], u2t1[3], u1t2[3];
  cross3(u1, t1, u1t1);
  cross3(e0, t1, e0t1);
  cross3(e0, t2, e0t2);
  cross3(u2, t2, u2t2);
  cross3(u2, t1, u2t1);
  cross3(u1, t2, u1t2);
  for (int j = 0; j < 3; ++j) {
    C.k[0][j] = u1t1[j];
    C.k[1][j] = e0t1[j];
    C.k[2][j] = -e0t2[j];
    C.k[3][j] = -u2t2[j] - R.aa * u1t1[j];
    C.k[4][j] = u2t1[j] - u1t2[j];
  }
  const double M = std::sqrt(dot3(e0, e0)) + std::sqrt(dot3(u1, u1) + dot3(u2, u2) * inv_aa);
  C.singular_floor2 = singular_floor2(M, dot3(R.axd, R.axd));
}

// m = x~_u x (c t1 - s t2): the ringed normal before its length is
// divided out.
CYC_ALWAYS_INLINE void ringed_normal_direction(const CircleConstants& C, double c, double s,
                                               double (&m)[3]) {
  const double s2 = s * s, cs = c * s;
  for (int j = 0; j < 3; ++j)
    m[j] = C.k[0][j] + c * C.k[1][j] + s * C.k[2][j] + s2 * C.k[3][j] + cs * C.k[4][j];
}

// The unit normal m / |m|, with singular = 1 (and n = 0) where
// |m|^2 <= floor2 (CircleConstants::singular_floor2, > 0). Without
// branches: |m|^2 is raised to floor2 before the division.
CYC_ALWAYS_INLINE void unit_normal(const double (&m)[3], double floor2, double (&n)[3],
                                   double& singular) {
  const double len2 = m[0] * m[0] + m[1] * m[1] + m[2] * m[2];
  const double ok = len2 > floor2 ? 1.0 : 0.0;
  const double il = ok / std::sqrt(len2 > floor2 ? len2 : floor2);  // needs -fno-math-errno to vectorize
  n[0] = m[0] * il;
  n[1] = m[1] * il;
  n[2] = m[2] * il;
  singular = 1.0 - ok;
}

// The per-point formula. k = 2 (beta gamma - alpha delta) of R, C the
// circle's constants (with the ringed-normal part if NORMAL && !CANAL),
// q the rotation of v. DU, DV, NORMAL: what is wanted; CANAL: normal
// (x - s)/r instead of the ringed normal.
template <bool DU, bool DV, bool NORMAL, bool CANAL>
CYC_ALWAYS_INLINE void eval_point(const RotationData& R, const RotationData& D, double k,
                                  double inv_radius, const CircleConstants& C,
                                  const CircleParameter& q, PointResult& P) {
  const double G2aa = q.G2 * R.aa;
  const double inv = 1.0 / (q.W2 + G2aa);
  const double cd = q.W2 - G2aa;
  P.c = cd * inv;
  P.s = q.WG2 * inv;
  double r[3];
  for (int j = 0; j < 3; ++j) {
    r[j] = C.a0[j] + P.c * C.a1[j] + P.s * R.axd[j];
    P.x[j] = R.o[j] + r[j];
  }
  if (DV) {
    // Exact rotation rate about a: d theta/dv = 2 (beta gamma - alpha delta) |a| / den
    // (den of the scaled q; x_v = s0^2 times it).
    const double rate = k * inv * (q.s0 * q.s0);
    P.xv[0] = rate * (R.a[1] * r[2] - R.a[2] * r[1]);
    P.xv[1] = rate * (R.a[2] * r[0] - R.a[0] * r[2]);
    P.xv[2] = rate * (R.a[0] * r[1] - R.a[1] * r[0]);
  }
  if (DU) {
    // x = o + num / den, num = cd d + ca a + cx a x d: x_u = o_u + (num_u - den_u r) / den,
    // with W_u, G_u from f's u-derivatives.
    const double W = q.W, G = q.G, G2 = q.G2;
    const double ca = 2.0 * G2 * R.ad, cx = q.WG2;
    const double Wu = D.alpha * q.s1 + D.beta * q.s0, Gu = D.gamma * q.s1 + D.delta * q.s0;
    const double W2u = 2.0 * W * Wu, G2u = 2.0 * G * Gu, WGu = Wu * G + W * Gu;
    const double den_u = W2u + G2u * R.aa + G2 * D.aa;
    const double cd_u = W2u - G2u * R.aa - G2 * D.aa;
    const double ca_u = 2.0 * (G2u * R.ad + G2 * D.ad), cx_u = 2.0 * WGu;
    for (int j = 0; j < 3; ++j) {
      const double num_u = cd_u * R.d[j] + cd * D.d[j] + ca_u * R.a[j] + ca * D.a[j] +
                           cx_u * R.axd[j] + cx * D.axd[j];
      P.xu[j] = D.o[j] + (num_u - den_u * r[j]) * inv;
    }
  }
  if (NORMAL) {
    if (CANAL) {
      for (int j = 0; j < 3; ++j) P.n[j] = r[j] * inv_radius;  // (x - s)/r
      P.singular = 0.0;
    } else {
      double m[3];
      ringed_normal_direction(C, P.c, P.s, m);
      unit_normal(m, C.singular_floor2, P.n, P.singular);
    }
  }
}

// Wanted outputs and surface kind as one index 0..15 (the specializations).
constexpr int kernel_index(bool du, bool dv, bool normal, bool canal) {
  return (du ? 8 : 0) | (dv ? 4 : 0) | (normal ? 2 : 0) | (canal ? 1 : 0);
}

// The caller's four outputs of a grid (null data = not wanted).
struct GridOut {
  Strided3 points, du, dv, normals;
  bool stream = false;  // large contiguous output: bypass the cache (SPEC §1b)
};

// Rows first_row .. first_row + nrows of a grid with columns vs[0..nv):
// point (i, j) goes to index i * nv + j. Returns the number of singular
// normals.
using GridBlockFn = std::size_t (*)(const CircleRow* rows, int nrows, std::size_t first_row,
                                    const double* vs, std::size_t nv, const GridOut& out);
// One point of a row.
using PointFn = void (*)(const CircleRow& row, double v, PointResult& out);
// One point straight from a compiled frame (compiled_frame.hpp) with f
// constant in u (f4 = alpha, beta, gamma, delta): false where the compiled
// frame is not trusted at u (the caller takes the reference path).
struct CompiledFrame;
using FramePointFn = bool (*)(const CompiledFrame& frame, const double (&f4)[4], double u,
                              double v, PointResult& out);
// FramePointFn writing the wanted outputs itself (Surface::eval's fast
// path): false where the compiled frame is not trusted at u; otherwise
// status is ok, singular_point or numerical_overflow, and out is written
// only when it is ok.
using FrameEvalFn = bool (*)(const CompiledFrame& frame, const double (&f4)[4], double u,
                             double v, const EvalOut& out, Status& status);
// The circle row of a compiled frame (CompiledFrame::row), with or without
// u-derivatives.
using FrameRowFn = bool (*)(const CompiledFrame& frame, const double (&f4)[4], double u,
                            CircleRow& out);

// Grid outputs of at least this many bytes are written with non-temporal
// stores: they exceed the caches, so ordinary stores would first read every
// line they write.
constexpr std::size_t kStreamingBytes = std::size_t(8) << 20;

// Rows per grid block: the rows of a block share the per-v work and stay in L1.
constexpr int kGridBlockRows = 16;

// The kernels of one instruction set.
struct Kernels {
  const char* isa;  // "x86-64-v3 (AVX2)" or "baseline"
  GridBlockFn grid[16];
  PointFn point[16];
  FramePointFn frame_point[16];
  FrameEvalFn frame_eval[16];
  FrameRowFn frame_row[2];  // [with u-derivatives]
};

// The kernels for this CPU, chosen once.
const Kernels& kernels();
// Each variant by name (for tests and benchmarks): the baseline always, the
// AVX2 one only where the CPU has it (else null).
const Kernels& baseline_kernels();
const Kernels* avx2_kernels();

}  // namespace v0
}  // namespace cyclide
