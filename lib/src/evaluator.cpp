// The evaluator's kernels (evaluator.hpp), compiled for two instruction
// sets: the x86-64 baseline (SSE2) and AVX2, chosen once from the CPU.
//
// Each kernel is a template over the wanted outputs. The exported variants
// are thin wrappers marked `flatten`, so the whole kernel is inlined into
// each wrapper and compiled with that wrapper's target; no code compiled for
// AVX2 is ever shared (as an out-of-line template instance) with the
// baseline path. The core is compiled with -ffp-contract=off: vector lanes
// round exactly like scalar operations, so both variants, and the grid and
// single-point paths, give identical bits (tested).
#include "cyclide/evaluator.hpp"

#include "cyclide/compiled_frame.hpp"

#include <cstdint>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define CYC_X86_64 1
#define CYC_AVX2_TARGET __attribute__((flatten, target("avx2")))
#endif

// The vector helpers below return vectors by value; they are always
// inlined, so the compilers' note that this ABI differs without AVX (GCC's,
// and Clang's for the single-point kernel's vector rotation data) concerns
// no real call.
#if defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

#if defined(__GNUC__)
#define CYC_FLATTEN __attribute__((flatten))
#else
#define CYC_FLATTEN
#endif

namespace cyclide {
inline namespace v0 {

namespace {

constexpr int kNormalLag = 8;

// One chunk of results in structure-of-arrays form (vectorizes). Every
// array is there whatever is wanted: the unused ones only take stack, and
// dropping them moved the used ones against each other in the caches
// (20 instead of 16 cycles per ringed point with normals, measured).
struct Chunk {
  double x[3][kChunk], xu[3][kChunk], xv[3][kChunk], n[3][kChunk];
  double c[kChunk], s[kChunk];  // the rotation's cos and sin / |a| (ringed normals)
};

// The rotations (CircleParameter) of a chunk's values of v, as arrays.
struct ChunkRotations {
  double s1[kChunk], s0[kChunk], W[kChunk], G[kChunk], W2[kChunk], G2[kChunk],
      WG2[kChunk];

  // The rotations of f's coefficients in R (s1, s0 set).
  CYC_ALWAYS_INLINE void form(const RotationData& R, int count) {
    for (int i = 0; i < count; ++i) {
      const CircleParameter q = circle_rotation(R, s1[i], s0[i]);
      W[i] = q.W;
      G[i] = q.G;
      W2[i] = q.W2;
      G2[i] = q.G2;
      WG2[i] = q.WG2;
    }
  }
  CYC_ALWAYS_INLINE CircleParameter operator[](int i) const {
    return CircleParameter{s1[i], s0[i], W[i], G[i], W2[i], G2[i], WG2[i]};
  }
};

// Evaluate the chunk's rotations Q (count <= kChunk) on a row with
// constants C; returns the number of singular (ringed) normals.
template <bool DU, bool DV, bool NORMAL, bool CANAL>
CYC_ALWAYS_INLINE std::int64_t eval_chunk(const CircleRow& row, const CircleConstants& C,
                                          const ChunkRotations& Q, int count, Chunk& out) {
  const RotationData R = row.r, D = row.r_u;  // local copies: no aliasing with out
  const double k = rotation_rate_factor(R);
  const double inv_radius = row.inv_radius;
  // Ringed normals in one more loop over the points' (c, s), its
  // normalization kNormalLag points behind its direction: the square root
  // and division of one point overlap the multiplications of the next (one
  // loop doing point, direction and length had a dependency chain too long
  // for the CPU to overlap iterations).
  constexpr bool ringed = NORMAL && !CANAL;
  std::int64_t nsingular = 0;
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC ivdep
#endif
  for (int i = 0; i < count; ++i) {
    PointResult P;
    eval_point<DU, DV, NORMAL && CANAL, CANAL>(R, D, k, inv_radius, C, Q[i], P);
    for (int j = 0; j < 3; ++j) {
      out.x[j][i] = P.x[j];
      if constexpr (DU) out.xu[j][i] = P.xu[j];
      if constexpr (DV) out.xv[j][i] = P.xv[j];
      if constexpr (NORMAL && CANAL) out.n[j][i] = P.n[j];
    }
    if constexpr (ringed) {
      out.c[i] = P.c;
      out.s[i] = P.s;
    }
  }
  if constexpr (ringed) {
    auto direction = [&](int i) {
      double m[3];
      ringed_normal_direction(C, out.c[i], out.s[i], m);
      for (int j = 0; j < 3; ++j) out.n[j][i] = m[j];
    };
    auto normalize = [&](int i) {
      const double m[3] = {out.n[0][i], out.n[1][i], out.n[2][i]};
      double n[3], singular;
      unit_normal(m, C.singular_floor2, n, singular);
      for (int j = 0; j < 3; ++j) out.n[j][i] = n[j];
      nsingular += singular != 0.0 ? 1 : 0;
    };
    constexpr int L = kNormalLag;
    const int lead = count < L ? count : L;
    for (int i = 0; i < lead; ++i) direction(i);
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC ivdep
#endif
    for (int i = L; i < count; ++i) {
      direction(i);
      normalize(i - L);
    }
    for (int i = count - lead; i < count; ++i) normalize(i);
  }
  return nsingular;
}

// Copy n doubles to dst with non-temporal stores where dst allows it: a
// large grid's output does not fit in the caches, and ordinary stores would
// first read every line they write (SPEC §1b).
CYC_ALWAYS_INLINE void stream_copy(double* dst, const double* src, int n) {
  int i = 0;
#if defined(CYC_X86_64)
  if ((reinterpret_cast<std::uintptr_t>(dst) & 7) == 0) {
    if (reinterpret_cast<std::uintptr_t>(dst) & 15) {
      dst[0] = src[0];
      i = 1;
    }
    for (; i + 2 <= n; i += 2) _mm_stream_pd(dst + i, _mm_loadu_pd(src + i));
  }
#endif
  for (; i < n; ++i) dst[i] = src[i];
}

// Four doubles as one vector (GCC/Clang extension), 8-byte aligned.
typedef double V4 __attribute__((vector_size(32), aligned(8)));

// Points i..i+3 of SoA rows x, y, z as 12 consecutive doubles x0 y0 z0 x1 ...
CYC_ALWAYS_INLINE void transpose4(const double* x, const double* y, const double* z,
                                  double* dst) {
  V4 X, Y, Z;
  __builtin_memcpy(&X, x, sizeof X);
  __builtin_memcpy(&Y, y, sizeof Y);
  __builtin_memcpy(&Z, z, sizeof Z);
  // Two in-lane unpacks, two blends and two 128-bit lane moves (no
  // general permutes):
  //   xy = x0 y0 x2 y2, yz = y1 z1 y3 z3, zx = z0 x1 z2 x3,
  //   x0 y0 z0 x1 = (xy.lo, zx.lo), y1 z1 x2 y2 = (yz.lo, xy.hi), z2 x3 y3 z3 = (zx.hi, yz.hi).
#if defined(__clang__)
  const V4 xy = __builtin_shufflevector(X, Y, 0, 4, 2, 6);
  const V4 yz = __builtin_shufflevector(Y, Z, 1, 5, 3, 7);
  const V4 zx = __builtin_shufflevector(Z, X, 0, 5, 2, 7);
  const V4 o0 = __builtin_shufflevector(xy, zx, 0, 1, 4, 5);
  const V4 o1 = __builtin_shufflevector(yz, xy, 0, 1, 6, 7);
  const V4 o2 = __builtin_shufflevector(zx, yz, 2, 3, 6, 7);
#else
  typedef long long M4 __attribute__((vector_size(32)));
  const V4 xy = __builtin_shuffle(X, Y, M4{0, 4, 2, 6});
  const V4 yz = __builtin_shuffle(Y, Z, M4{1, 5, 3, 7});
  const V4 zx = __builtin_shuffle(Z, X, M4{0, 5, 2, 7});
  const V4 o0 = __builtin_shuffle(xy, zx, M4{0, 1, 4, 5});
  const V4 o1 = __builtin_shuffle(yz, xy, M4{0, 1, 6, 7});
  const V4 o2 = __builtin_shuffle(zx, yz, M4{2, 3, 6, 7});
#endif
  __builtin_memcpy(dst, &o0, sizeof o0);
  __builtin_memcpy(dst + 4, &o1, sizeof o1);
  __builtin_memcpy(dst + 8, &o2, sizeof o2);
}

// Store chunk entries [0, count) of one output at indices k0 + i.
CYC_ALWAYS_INLINE void store(const double (*soa)[kChunk], int count, const Strided3& b,
                             std::size_t k0, bool stream) {
  double* p = b.data + k0 * b.stride;
  if (b.stride == 3) {
    // Contiguous: transpose four points at a time (into the caller's buffer,
    // or into L1 scratch that is then streamed out).
    double stage[3 * kChunk];
    double* dst = stream ? stage : p;
    int i = 0;
    for (; i + 4 <= count; i += 4) transpose4(soa[0] + i, soa[1] + i, soa[2] + i, dst + 3 * i);
    for (; i < count; ++i)
      for (int j = 0; j < 3; ++j) dst[3 * i + j] = soa[j][i];
    if (stream) stream_copy(p, stage, 3 * count);
    return;
  }
  for (int i = 0; i < count; ++i, p += b.stride) {
    p[0] = soa[0][i];
    p[1] = soa[1][i];
    p[2] = soa[2][i];
  }
}

// f's coefficients are the same on both rows (bit for bit).
CYC_ALWAYS_INLINE bool same_f(const RotationData& x, const RotationData& y) {
  return x.alpha == y.alpha && x.beta == y.beta && x.gamma == y.gamma && x.delta == y.delta;
}

// A block of rows: the circles' constants are formed once per row; per
// chunk of v the circle parameters (s1, s0) are formed once for the block,
// and so are the rotations when f is the same on every row (f constant in
// u), else once per row.
template <bool DU, bool DV, bool NORMAL, bool CANAL>
std::size_t grid_block(const CircleRow* rows, int nrows, std::size_t first_row,
                       const double* vs, std::size_t nv, const GridOut& out) {
  constexpr bool ringed = NORMAL && !CANAL;
  CircleConstants C[kGridBlockRows];
  bool shared = true;
  for (int r = 0; r < nrows; ++r) {
    const RotationData& R = rows[r].r;
    circle_constants<ringed>(R, rows[r].r_u, rotation_rate_factor(R), C[r]);
    shared = shared && same_f(R, rows[0].r);
  }
  Chunk c;
  ChunkRotations Q;
  std::size_t singular = 0;
  for (std::size_t j = 0; j < nv; j += kChunk) {
    const int count = int(nv - j < std::size_t(kChunk) ? nv - j : kChunk);
    for (int i = 0; i < count; ++i) circle_parameter(vs[j + i], Q.s1[i], Q.s0[i]);
    if (shared) Q.form(rows[0].r, count);
    for (int r = 0; r < nrows; ++r) {
      if (!shared) Q.form(rows[r].r, count);
      singular += std::size_t(eval_chunk<DU, DV, NORMAL, CANAL>(rows[r], C[r], Q, count, c));
      const std::size_t k0 = (first_row + std::size_t(r)) * nv + j;
      if (out.points.data) store(c.x, count, out.points, k0, out.stream);
      if constexpr (DU) store(c.xu, count, out.du, k0, out.stream);
      if constexpr (DV) store(c.xv, count, out.dv, k0, out.stream);
      if constexpr (NORMAL) store(c.n, count, out.normals, k0, out.stream);
    }
  }
#if defined(CYC_X86_64)
  if (out.stream) _mm_sfence();  // order the non-temporal stores before returning
#endif
  return singular;
}

template <bool DU, bool DV, bool NORMAL, bool CANAL>
CYC_ALWAYS_INLINE void point(const CircleRow& row, double v, PointResult& P) {
  double s1, s0;
  circle_parameter(v, s1, s0);
  const RotationData& R = row.r;
  const double k = rotation_rate_factor(R);
  CircleConstants C;
  circle_constants<NORMAL && !CANAL>(R, row.r_u, k, C);
  eval_point<DU, DV, NORMAL, CANAL>(R, row.r_u, k, row.inv_radius, C,
                                    circle_rotation(R, s1, s0), P);
}

// ------------------------------------------------------------ single points

// (x, y, z) of Lane4 vectors (lane 3 is carried along and never read).
CYC_ALWAYS_INLINE Lane4 splat(double x) { return Lane4{x, x, x, x}; }

// x0 y0 + x1 y1 + x2 y2, summed left to right like the scalar dot products.
CYC_ALWAYS_INLINE double dot3(const Lane4& x, const Lane4& y) {
  const Lane4 p = x * y;
  return p[0] + p[1] + p[2];
}

// x x y as (y z x)(z x y) - (z x y)(y z x): each lane is the scalar formula.
CYC_ALWAYS_INLINE Lane4 cross3(const Lane4& x, const Lane4& y) {
#if defined(__clang__)
  const Lane4 x1 = __builtin_shufflevector(x, x, 1, 2, 0, 3);
  const Lane4 x2 = __builtin_shufflevector(x, x, 2, 0, 1, 3);
  const Lane4 y1 = __builtin_shufflevector(y, y, 1, 2, 0, 3);
  const Lane4 y2 = __builtin_shufflevector(y, y, 2, 0, 1, 3);
#else
  typedef long long M4 __attribute__((vector_size(32)));
  const Lane4 x1 = __builtin_shuffle(x, M4{1, 2, 0, 3});
  const Lane4 x2 = __builtin_shuffle(x, M4{2, 0, 1, 3});
  const Lane4 y1 = __builtin_shuffle(y, M4{1, 2, 0, 3});
  const Lane4 y2 = __builtin_shuffle(y, M4{2, 0, 1, 3});
#endif
  return x1 * y2 - x2 * y1;
}

CYC_ALWAYS_INLINE void put3(const Lane4& x, double (&dst)[3]) {
  for (int j = 0; j < 3; ++j) dst[j] = x[j];
}

// One point straight from a compiled frame: CompiledFrame::row followed by
// point, operation for operation (so the bits equal the grid's, which goes
// through the row), but on (x, y, z, w) vectors. The frame's series already
// come as vectors; one vector operation replaces three scalar ones, and no
// CircleRow is stored and loaded again (SPEC §1b).
template <bool DU, bool DV, bool NORMAL, bool CANAL>
CYC_ALWAYS_INLINE bool frame_point(const CompiledFrame& F, const double (&f4)[4], double u,
                                   double v, PointResult& P) {
  constexpr bool ringed = NORMAL && !CANAL;
  constexpr int N = DU || ringed ? 1 : 0;
  // The row: rotation data at u (CompiledFrame::row).
  Lane4 so[N + 2], sa[N + 1], sp[N + 1];
  if (!F.series<N>(u, so, sa, sp) || !CompiledFrame::bounded<N>(so, sa, sp)) return false;
  const Lane4 o = so[0], a = sa[0], d = sp[0] - so[0];
  const double aa = dot3(a, a), dd = dot3(d, d);
  if (!(aa >= kMinAxisLength * kMinAxisLength) || !(dd > 0)) return false;
  const double ad = dot3(a, d);
  const Lane4 axd = cross3(a, d);
  // The circle's constants (circle_constants).
  const double inv_aa = 1.0 / aa;
  const double q = ad * inv_aa;
  const Lane4 a0 = splat(q) * a, a1 = d - a0;
  // The rotation of v (circle_rotation).
  const double alpha = f4[0], beta = f4[1], gamma = f4[2], delta = f4[3];
  const double k = 2.0 * (beta * gamma - alpha * delta);
  double s1, s0;
  circle_parameter(v, s1, s0);
  const double W = alpha * s1 + beta * s0, G = gamma * s1 + delta * s0;
  const double W2 = W * W, G2 = G * G, WG2 = 2.0 * (W * G);
  // The point (eval_point).
  const double G2aa = G2 * aa;
  const double inv = 1.0 / (W2 + G2aa);
  const double cd = W2 - G2aa;
  P.c = cd * inv;
  P.s = WG2 * inv;
  const Lane4 r = a0 + splat(P.c) * a1 + splat(P.s) * axd;
  put3(o + r, P.x);
  if (DV) put3(splat(k * inv * (s0 * s0)) * cross3(a, r), P.xv);  // the rotation rate about a
  // The rotation data's u-derivatives (CompiledFrame::row's second half).
  Lane4 o_u{}, a_u{}, d_u{}, axd_u{};
  double aa_u = 0, ad_u = 0;
  if (N == 1) {
    o_u = so[N];
    a_u = sa[N];
    d_u = sp[N] - so[N];
    aa_u = 2.0 * dot3(a, a_u);
    ad_u = dot3(a_u, d) + dot3(a, d_u);
    axd_u = cross3(a_u, d) + cross3(a, d_u);
  }
  if (DU) {
    // f is constant in u: its u-derivatives are the row's zeros, kept in
    // the formula so that every rounding matches eval_point's.
    const double zero = 0.0;
    const double ca = 2.0 * G2 * ad, cx = WG2;
    const double Wu = zero * s1 + zero * s0, Gu = zero * s1 + zero * s0;
    const double W2u = 2.0 * W * Wu, G2u = 2.0 * G * Gu, WGu = Wu * G + W * Gu;
    const double den_u = W2u + G2u * aa + G2 * aa_u;
    const double cd_u = W2u - G2u * aa - G2 * aa_u;
    const double ca_u = 2.0 * (G2u * ad + G2 * ad_u), cx_u = 2.0 * WGu;
    const Lane4 num_u = splat(cd_u) * d + splat(cd) * d_u + splat(ca_u) * a +
                        splat(ca) * a_u + splat(cx_u) * axd + splat(cx) * axd_u;
    put3(o_u + (num_u - splat(den_u) * r) * splat(inv), P.xu);
  }
  if (NORMAL) {
    if (CANAL) {  // (x - s)/r
      put3(r * splat(1.0 / std::sqrt(dd)), P.n);
      P.singular = 0.0;
    } else {  // circle_constants' ringed part, ringed_normal_direction, unit_normal
      const double q_u = (ad_u * aa - ad * aa_u) * (inv_aa * inv_aa);
      const double h = 0.5 * aa_u * inv_aa;
      const double sg = k > 0 ? 1.0 : (k < 0 ? -1.0 : 0.0);
      const Lane4 a0_u = splat(q_u) * a + splat(q) * a_u;
      const Lane4 e0 = o_u + a0_u, u1 = d_u - a0_u, u2 = axd_u - splat(h) * axd;
      const Lane4 t1 = splat(sg) * axd, t2 = splat(sg) * (splat(aa) * d - splat(ad) * a);
      const Lane4 u1t1 = cross3(u1, t1);
      const Lane4 k0 = u1t1, k1 = cross3(e0, t1), k2 = -cross3(e0, t2);
      const Lane4 k3 = -cross3(u2, t2) - splat(aa) * u1t1;
      const Lane4 k4 = cross3(u2, t1) - cross3(u1, t2);
      const double M = std::sqrt(dot3(e0, e0)) + std::sqrt(dot3(u1, u1) + dot3(u2, u2) * inv_aa);
      const double floor2 = singular_floor2(M, dot3(axd, axd));
      const double s2 = P.s * P.s, cs = P.c * P.s;
      const Lane4 m = k0 + splat(P.c) * k1 + splat(P.s) * k2 + splat(s2) * k3 + splat(cs) * k4;
      const double len2 = dot3(m, m);
      const double ok = len2 > floor2 ? 1.0 : 0.0;
      put3(m * splat(ok / std::sqrt(len2 > floor2 ? len2 : floor2)), P.n);
      P.singular = 1.0 - ok;
    }
  }
  return true;
}

// frame_point, then the wanted outputs written (all or nothing) with the
// checks of Surface::eval: singular_point for an undefined normal,
// numerical_overflow for a non-finite result. What is wanted is known at
// compile time (the kernel index), except the point itself.
template <bool DU, bool DV, bool NORMAL, bool CANAL>
CYC_ALWAYS_INLINE bool frame_eval(const CompiledFrame& F, const double (&f4)[4], double u,
                                  double v, const EvalOut& out, Status& status) {
  PointResult P;
  if (!frame_point<DU, DV, NORMAL, CANAL>(F, f4, u, v, P)) return false;
  if (NORMAL && !CANAL && P.singular != 0.0) {
    status = Status::singular_point;
    return true;
  }
  double check = out.point ? nonfinite3(P.x) : 0.0;
  if (DU) check += nonfinite3(P.xu);
  if (DV) check += nonfinite3(P.xv);
  if (NORMAL) check += nonfinite3(P.n);
  if (!(check == 0.0)) {
    status = Status::numerical_overflow;
    return true;
  }
  auto put = [](double* dst, const double (&src)[3]) {
    for (int j = 0; j < 3; ++j) dst[j] = src[j];
  };
  if (out.point) put(out.point, P.x);
  if (DU) put(out.du, P.xu);
  if (DV) put(out.dv, P.xv);
  if (NORMAL) put(out.normal, P.n);
  status = Status::ok;
  return true;
}

// ------------------------------------------------------------ variants

#define CYC_FLAGS(i) ((i) & 8) != 0, ((i) & 4) != 0, ((i) & 2) != 0, ((i) & 1) != 0
#define CYC_TABLE(fn)                                                              \
  {fn<CYC_FLAGS(0)>,  fn<CYC_FLAGS(1)>,  fn<CYC_FLAGS(2)>,  fn<CYC_FLAGS(3)>,  \
   fn<CYC_FLAGS(4)>,  fn<CYC_FLAGS(5)>,  fn<CYC_FLAGS(6)>,  fn<CYC_FLAGS(7)>,  \
   fn<CYC_FLAGS(8)>,  fn<CYC_FLAGS(9)>,  fn<CYC_FLAGS(10)>, fn<CYC_FLAGS(11)>, \
   fn<CYC_FLAGS(12)>, fn<CYC_FLAGS(13)>, fn<CYC_FLAGS(14)>, fn<CYC_FLAGS(15)>}

// The wrappers of one variant: NAME is its suffix, ATTR its attributes.
#define CYC_VARIANT(NAME, ATTR, LABEL)                                                   \
  template <bool DU, bool DV, bool NORMAL, bool CANAL>                                   \
  ATTR std::size_t grid_##NAME(const CircleRow* rows, int nrows, std::size_t first_row,  \
                               const double* vs, std::size_t nv, const GridOut& out) {   \
    return grid_block<DU, DV, NORMAL, CANAL>(rows, nrows, first_row, vs, nv, out);       \
  }                                                                                      \
  template <bool DU, bool DV, bool NORMAL, bool CANAL>                                   \
  ATTR void point_##NAME(const CircleRow& row, double v, PointResult& P) {               \
    point<DU, DV, NORMAL, CANAL>(row, v, P);                                             \
  }                                                                                      \
  template <bool DU, bool DV, bool NORMAL, bool CANAL>                                   \
  ATTR bool frame_point_##NAME(const CompiledFrame& F, const double(&f4)[4], double u,   \
                               double v, PointResult& P) {                               \
    return frame_point<DU, DV, NORMAL, CANAL>(F, f4, u, v, P);                           \
  }                                                                                      \
  template <bool DU, bool DV, bool NORMAL, bool CANAL>                                   \
  ATTR bool frame_eval_##NAME(const CompiledFrame& F, const double(&f4)[4], double u,    \
                              double v, const EvalOut& out, Status& status) {            \
    return frame_eval<DU, DV, NORMAL, CANAL>(F, f4, u, v, out, status);                  \
  }                                                                                      \
  template <bool WITH_DU>                                                                \
  ATTR bool frame_row_##NAME(const CompiledFrame& F, const double(&f4)[4], double u,     \
                             CircleRow& row) {                                           \
    return F.row<WITH_DU>(u, f4, row);                                                   \
  }                                                                                      \
  const Kernels k_##NAME = {LABEL, CYC_TABLE(grid_##NAME), CYC_TABLE(point_##NAME),      \
                            CYC_TABLE(frame_point_##NAME), CYC_TABLE(frame_eval_##NAME), \
                            {frame_row_##NAME<false>, frame_row_##NAME<true>}};

CYC_VARIANT(baseline, CYC_FLATTEN, "baseline")
#if defined(CYC_AVX2_TARGET)
CYC_VARIANT(avx2, CYC_AVX2_TARGET, "x86-64-v3 (AVX2)")
#endif

#undef CYC_VARIANT
#undef CYC_TABLE
#undef CYC_FLAGS

}  // namespace

const Kernels& baseline_kernels() { return k_baseline; }

const Kernels* avx2_kernels() {
#if defined(CYC_AVX2_TARGET)
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx2")) return &k_avx2;
#endif
  return nullptr;
}

const Kernels& kernels() {
  static const Kernels* const chosen = avx2_kernels() ? avx2_kernels() : &k_baseline;
  return *chosen;
}

}  // namespace v0
}  // namespace cyclide
