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
//   x_v = 2 (beta gamma - alpha delta) s0^2 a x (x - o) / (W^2 + G^2 |a|^2);
// ringed normals use it without the s0^2 (parallel, finite as v -> inf).
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

// |x_u x x_v| <= kSingularTol |x_u| |x_v|: the normal is undefined.
constexpr double kSingularTol = 1e-14;

constexpr int kChunk = 64;

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
  double xv_dir[3];  // x_v before the factor s0^2 (finite as v -> infinity)
  double singular;   // 1.0 where the (ringed) normal is undefined
};

// The unit normal x_u x x_v / |x_u x x_v| of a ringed surface, with
// singular = 1 (and n = 0) where |x_u x x_v| <= kSingularTol |x_u| |x_v|.
CYC_ALWAYS_INLINE void ringed_normal(const double (&xu)[3], const double (&xv)[3],
                                     double (&n)[3], double& singular) {
  const double c0 = xu[1] * xv[2] - xu[2] * xv[1];
  const double c1 = xu[2] * xv[0] - xu[0] * xv[2];
  const double c2 = xu[0] * xv[1] - xu[1] * xv[0];
  const double len2 = c0 * c0 + c1 * c1 + c2 * c2;
  const double ref2 = (xu[0] * xu[0] + xu[1] * xu[1] + xu[2] * xu[2]) *
                      (xv[0] * xv[0] + xv[1] * xv[1] + xv[2] * xv[2]);
  // Singular: |x_u x x_v| <= tol |x_u||x_v| (also when len2 = 0).
  const double ok = len2 > kSingularTol * kSingularTol * ref2 && len2 > 0 ? 1.0 : 0.0;
  const double il = ok / std::sqrt(len2 + (1.0 - ok));  // needs -fno-math-errno to vectorize
  n[0] = c0 * il;
  n[1] = c1 * il;
  n[2] = c2 * il;
  singular = 1.0 - ok;
}

// The per-point formula. k = 2 (beta gamma - alpha delta) of R. DU, DV,
// NORMAL: what is wanted; CANAL: normal (x - s)/r instead of x_u x x_v
// normalized.
template <bool DU, bool DV, bool NORMAL, bool CANAL>
CYC_ALWAYS_INLINE void eval_point(const RotationData& R, const RotationData& D, double k,
                                  double inv_radius, double s1, double s0, PointResult& P) {
  constexpr bool need_du = DU || (NORMAL && !CANAL);
  constexpr bool need_dv = DV || (NORMAL && !CANAL);
  const double W = R.alpha * s1 + R.beta * s0, G = R.gamma * s1 + R.delta * s0;
  const double W2 = W * W, G2 = G * G, WG = W * G;
  const double inv = 1.0 / (W2 + G2 * R.aa);
  const double cd = W2 - G2 * R.aa, ca = 2.0 * G2 * R.ad, cx = 2.0 * WG;
  double r[3], xu[3] = {0, 0, 0}, xv[3] = {0, 0, 0};
  for (int j = 0; j < 3; ++j) {
    r[j] = (cd * R.d[j] + ca * R.a[j] + cx * R.axd[j]) * inv;
    P.x[j] = R.o[j] + r[j];
  }
  if (need_dv) {
    // Exact rotation rate about a: d theta/dv = 2 (beta gamma - alpha delta) |a| / den
    // (den of the scaled q; x_v = s0^2 times it). xv holds the direction
    // before the s0^2 factor: for |v| > 1 it is -dx/dt (t = 1/v), which
    // stays finite as v -> infinity, so normals are defined there too.
    const double rate = k * inv;
    xv[0] = rate * (R.a[1] * r[2] - R.a[2] * r[1]);
    xv[1] = rate * (R.a[2] * r[0] - R.a[0] * r[2]);
    xv[2] = rate * (R.a[0] * r[1] - R.a[1] * r[0]);
    for (int j = 0; j < 3; ++j) {
      P.xv_dir[j] = xv[j];
      if (DV) P.xv[j] = s0 * s0 * xv[j];
    }
  }
  if (need_du) {
    // x_u = o_u + (num_u - den_u r) / den, with W_u, G_u from f's u-derivatives.
    const double Wu = D.alpha * s1 + D.beta * s0, Gu = D.gamma * s1 + D.delta * s0;
    const double W2u = 2.0 * W * Wu, G2u = 2.0 * G * Gu, WGu = Wu * G + W * Gu;
    const double den_u = W2u + G2u * R.aa + G2 * D.aa;
    const double cd_u = W2u - G2u * R.aa - G2 * D.aa;
    const double ca_u = 2.0 * (G2u * R.ad + G2 * D.ad), cx_u = 2.0 * WGu;
    for (int j = 0; j < 3; ++j) {
      const double num_u = cd_u * R.d[j] + cd * D.d[j] + ca_u * R.a[j] + ca * D.a[j] +
                           cx_u * R.axd[j] + cx * D.axd[j];
      xu[j] = D.o[j] + (num_u - den_u * r[j]) * inv;
      if (DU) P.xu[j] = xu[j];
    }
  }
  if (NORMAL) {
    if (CANAL) {
      for (int j = 0; j < 3; ++j) P.n[j] = r[j] * inv_radius;  // (x - s)/r
      P.singular = 0.0;
    } else {
      ringed_normal(xu, xv, P.n, P.singular);
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
