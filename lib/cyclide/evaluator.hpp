// The one evaluator of circle-family surfaces: from a circle row (the
// rotation data of one u and their u-derivatives) to points, x_u, x_v and
// unit normals for many v at once.
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
// Points are computed in chunks of kChunk values of v into
// structure-of-arrays scratch on the stack with no control flow (the two
// cases of v are exact blends), so the compiler vectorizes the loop; the
// chunk is then written to the caller's strided buffers. The kernel is
// specialized at compile time on what is wanted.
#pragma once

#include <cmath>
#include <cstddef>

#include "cyclide/circle_family.hpp"

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

// Caller-owned strided output of 3-vectors: element i at data + i * stride.
struct Strided3 {
  double* data = nullptr;
  std::size_t stride = 3;  // in doubles, >= 3
  double* at(std::size_t i) const { return data + i * stride; }
};

// |x_u x x_v| <= kSingularTol |x_u| |x_v|: the normal is undefined.
constexpr double kSingularTol = 1e-14;

constexpr int kChunk = 64;

// One chunk of results in structure-of-arrays form.
struct Chunk {
  double x[3][kChunk], xu[3][kChunk], xv[3][kChunk], n[3][kChunk];
  double singular[kChunk];  // 1.0 where the (ringed) normal is undefined
};

// Evaluate v[0..count) (count <= kChunk) of a row. DU, DV, NORMAL: what is
// wanted; CANAL: normal (x - s)/r instead of x_u x x_v normalized.
template <bool DU, bool DV, bool NORMAL, bool CANAL>
void eval_chunk(const CircleRow& row, const double* v, int count, Chunk& out) {
  constexpr bool need_du = DU || (NORMAL && !CANAL);
  constexpr bool need_dv = DV || (NORMAL && !CANAL);
  const RotationData R = row.r, D = row.r_u;  // local copies: no aliasing with out
  const double k = 2.0 * (R.beta * R.gamma - R.alpha * R.delta);
  const double inv_radius = row.inv_radius;
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC ivdep
#endif
  for (int i = 0; i < count; ++i) {
    const double vi = v[i];
    // (s1, s0) = (v, 1) or (1, 1/v), as exact blends (w is 0 or 1).
    const double w = std::abs(vi) <= 1.0 ? 1.0 : 0.0, w1 = 1.0 - w;
    const double s1 = w * vi + w1, s0 = w + w1 / (w1 * vi + w);
    const double W = R.alpha * s1 + R.beta * s0, G = R.gamma * s1 + R.delta * s0;
    const double W2 = W * W, G2 = G * G, WG = W * G;
    const double den = W2 + G2 * R.aa;
    const double inv = 1.0 / den;
    const double cd = W2 - G2 * R.aa, ca = 2.0 * G2 * R.ad, cx = 2.0 * WG;
    double r[3], xu[3], xv[3];
    for (int j = 0; j < 3; ++j) {
      r[j] = (cd * R.d[j] + ca * R.a[j] + cx * R.axd[j]) * inv;
      out.x[j][i] = R.o[j] + r[j];
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
      if (DV)
        for (int j = 0; j < 3; ++j) out.xv[j][i] = s0 * s0 * xv[j];
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
        if (DU) out.xu[j][i] = xu[j];
      }
    }
    if (NORMAL) {
      if (CANAL) {
        for (int j = 0; j < 3; ++j) out.n[j][i] = r[j] * inv_radius;  // (x - s)/r
      } else {
        const double c0 = xu[1] * xv[2] - xu[2] * xv[1];
        const double c1 = xu[2] * xv[0] - xu[0] * xv[2];
        const double c2 = xu[0] * xv[1] - xu[1] * xv[0];
        const double len2 = c0 * c0 + c1 * c1 + c2 * c2;
        const double ref2 = (xu[0] * xu[0] + xu[1] * xu[1] + xu[2] * xu[2]) *
                            (xv[0] * xv[0] + xv[1] * xv[1] + xv[2] * xv[2]);
        // Singular: |x_u x x_v| <= tol |x_u||x_v| (also when len2 = 0).
        const double ok = len2 > kSingularTol * kSingularTol * ref2 && len2 > 0 ? 1.0 : 0.0;
        const double il = ok / std::sqrt(len2 + (1.0 - ok));  // needs -fno-math-errno to vectorize
        out.n[0][i] = c0 * il;
        out.n[1][i] = c1 * il;
        out.n[2][i] = c2 * il;
        out.singular[i] = 1.0 - ok;
      }
    }
  }
}

// Write chunk entries [0, count) to outputs at index k0 + i.
template <bool DU, bool DV, bool NORMAL>
void scatter_chunk(const Chunk& c, int count, std::size_t k0, const Strided3& points,
                   const Strided3& du, const Strided3& dv, const Strided3& normals) {
  auto put = [count, k0](const Strided3& b, const double (*a)[kChunk]) {
    double* p = b.at(k0);
    for (int i = 0; i < count; ++i, p += b.stride) {
      p[0] = a[0][i];
      p[1] = a[1][i];
      p[2] = a[2][i];
    }
  };
  if (points.data) put(points, c.x);
  if (DU) put(du, c.xu);
  if (DV) put(dv, c.xv);
  if (NORMAL) put(normals, c.n);
}

// A whole row of a grid: returns the number of singular normals.
template <bool DU, bool DV, bool NORMAL, bool CANAL>
std::size_t eval_row_grid(const CircleRow& row, const double* vs, std::size_t nv,
                          std::size_t k0, const Strided3& points, const Strided3& du,
                          const Strided3& dv, const Strided3& normals) {
  Chunk c;
  std::size_t singular = 0;
  for (std::size_t j = 0; j < nv; j += kChunk) {
    const int count = int(nv - j < std::size_t(kChunk) ? nv - j : kChunk);
    eval_chunk<DU, DV, NORMAL, CANAL>(row, vs + j, count, c);
    if (NORMAL && !CANAL)
      for (int i = 0; i < count; ++i) singular += c.singular[i] != 0.0;
    scatter_chunk<DU, DV, NORMAL>(c, count, k0 + j, points, du, dv, normals);
  }
  return singular;
}

using RowGridFn = std::size_t (*)(const CircleRow&, const double*, std::size_t, std::size_t,
                                  const Strided3&, const Strided3&, const Strided3&,
                                  const Strided3&);

// The specialization for a combination of wanted outputs.
RowGridFn row_grid_kernel(bool du, bool dv, bool normal, bool canal);

}  // namespace v0
}  // namespace cyclide
