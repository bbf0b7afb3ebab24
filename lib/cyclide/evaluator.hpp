// The one evaluator of circle-family surfaces: from a circle row (the
// quadratic x = o + (P0 + P1 v + P2 v^2)/(Q0 + Q1 v + Q2 v^2) of one u and
// the u-derivatives of its coefficients) to points, x_u, x_v and unit
// normals for many v at once.
//
// Points are computed in chunks of kChunk values of v into
// structure-of-arrays scratch on the stack (no branches in the loop: the
// |v| > 1 case, evaluated in t = 1/v, is a select), so the compiler
// vectorizes it; the chunk is then written to the caller's strided buffers.
// The kernel is specialized at compile time on what is wanted.
#pragma once

#include <cmath>
#include <cstddef>

#include "cyclide/circle_family.hpp"

namespace cyclide {
inline namespace v0 {

// Per-u data: the circle quadratic and its u-derivative, in plain doubles.
struct CircleRow {
  CircleQuadratic<double> q;    // values
  CircleQuadratic<double> q_u;  // d/du of every coefficient (when computed)
  double inv_radius = 0;        // canal: 1 / r(u), for the normal (x - s)/r
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
  const CircleQuadratic<double>& C = row.q;
  const CircleQuadratic<double>& D = row.q_u;
  // Coefficients as plain scalars: the loop below then only reads registers.
  double P[3][3], Pu[3][3], o[3], ou[3];
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j) {
      P[k][j] = C.P[k][j];
      Pu[k][j] = D.P[k][j];
    }
  for (int j = 0; j < 3; ++j) {
    o[j] = C.o[j];
    ou[j] = D.o[j];
  }
  const double Q0 = C.Q[0], Q1 = C.Q[1], Q2 = C.Q[2];
  const double Qu0 = D.Q[0], Qu1 = D.Q[1], Qu2 = D.Q[2];
  const double inv_radius = row.inv_radius;
#if defined(__GNUC__)
#pragma GCC ivdep
#endif
  for (int i = 0; i < count; ++i) {
    const double vi = v[i];
    // |v| <= 1: Horner in v; else in t = 1/v with the coefficients reversed.
    // Written as exact arithmetic blends (w is 0 or 1, coefficients finite)
    // so that the loop has no control flow and vectorizes.
    const double w = std::abs(vi) <= 1.0 ? 1.0 : 0.0, w1 = 1.0 - w;
    const double t = w * vi + w1 / (w1 * vi + w);  // v, or 1/v
    const double qlo = w * Q0 + w1 * Q2, qhi = w * Q2 + w1 * Q0;
    const double den = qlo + t * (Q1 + t * qhi);
    const double inv = 1.0 / den;
    double r[3], xu[3], xv[3];
    for (int j = 0; j < 3; ++j) {
      const double lo = w * P[0][j] + w1 * P[2][j], hi = w * P[2][j] + w1 * P[0][j];
      r[j] = (lo + t * (P[1][j] + t * hi)) * inv;
      out.x[j][i] = o[j] + r[j];
    }
    if (need_dv) {
      // d/dt of num/den, times dt/dv = -t^2 outside.
      const double chain = (w - w1 * t * t) * inv;
      const double dden = Q1 + 2.0 * t * qhi;
      for (int j = 0; j < 3; ++j) {
        const double hi = w * P[2][j] + w1 * P[0][j];
        xv[j] = (P[1][j] + 2.0 * t * hi - dden * r[j]) * chain;
        if (DV) out.xv[j][i] = xv[j];
      }
    }
    if (need_du) {
      // x_u = o_u + (num_u - den_u r) / den.
      const double uden = w * Qu0 + w1 * Qu2 + t * (Qu1 + t * (w * Qu2 + w1 * Qu0));
      for (int j = 0; j < 3; ++j) {
        const double lo = w * Pu[0][j] + w1 * Pu[2][j], hi = w * Pu[2][j] + w1 * Pu[0][j];
        xu[j] = ou[j] + (lo + t * (Pu[1][j] + t * hi) - uden * r[j]) * inv;
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
