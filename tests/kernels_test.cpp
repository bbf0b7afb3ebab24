// The evaluator's kernel variants (SPEC §1b): the baseline and the AVX2+FMA
// kernels, the compiled-frame fast paths and the grid's store paths
// (contiguous, strided, non-temporal) all give the same surface.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "cyclide/surface.hpp"

namespace cyclide {
namespace {

// Cubic perturbations of Example 2's lines (as in bench/), plus a third cubic.
const double kP1[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 0.05, 0.02}, {0.1, 0, -0.05}};
const double kP2[4][3] = {{0, 0, 1}, {2, 1, 0}, {0.03, 0, 0.05}, {-0.05, 0.1, 0}};
const double kP3[4][3] = {{0, 2, 0}, {-1, 0, 1}, {0, -0.1, 0}, {0.05, 0, 0.1}};

Surface make(bool canal) {
  RationalCurve c[3];
  const double(*rows[3])[3] = {kP1, kP2, kP3};
  for (int i = 0; i < 3; ++i) EXPECT_EQ(make_polynomial_curve(3, &rows[i][0][0], c[i]), Status::ok);
  Surface s;
  const Status st = canal ? make_prcs(c[0], c[1], nullptr, -1, 1, s)
                          : make_prrs(c[0], c[1], c[2], nullptr, -1, 1, s);
  EXPECT_EQ(st, Status::ok);
  EXPECT_TRUE(s.compiled.valid);
  return s;
}

const double kVs[] = {0.0, 0.3, -0.9, 1.0, -1.0, 1.7, -42.0, 1e6, -3e12, 1e300};

double rel(const double* a, const double* b, double scale) {
  double m = 0;
  for (int j = 0; j < 3; ++j) m = std::max(m, std::abs(a[j] - b[j]));
  return m / scale;
}

void expect_close(const PointResult& a, const PointResult& b, int flags, double tol) {
  const bool du = flags & 8, dv = flags & 4, normal = flags & 2;
  const double sx = 1 + std::abs(a.x[0]) + std::abs(a.x[1]) + std::abs(a.x[2]);
  EXPECT_LE(rel(a.x, b.x, sx), tol);
  auto size = [](const double* w) { return std::abs(w[0]) + std::abs(w[1]) + std::abs(w[2]); };
  if (du) {
    EXPECT_LE(rel(a.xu, b.xu, 1 + size(a.xu)), tol);
  }
  if (dv) {
    EXPECT_LE(rel(a.xv, b.xv, 1e-300 + size(a.xv)), tol);
  }
  if (normal) {
    EXPECT_LE(rel(a.n, b.n, 1.0), tol);
  }
}

bool same(const PointResult& a, const PointResult& b, int flags) {
  bool eq = std::memcmp(a.x, b.x, sizeof a.x) == 0;
  if (flags & 8) eq &= std::memcmp(a.xu, b.xu, sizeof a.xu) == 0;
  if (flags & 4) eq &= std::memcmp(a.xv, b.xv, sizeof a.xv) == 0;
  if (flags & 2) eq &= std::memcmp(a.n, b.n, sizeof a.n) == 0;
  return eq;
}

// Both variants give identical bits (SPEC §1b: no FMA contraction), the
// compiled-frame row, the one-kernel fast path and what Surface::eval's
// kernel writes give identical bits, and
// these agree with the reference frames (plane intersection) to 1e-11.
TEST(Kernels, VariantsAndFastPathsAgreeWithTheReference) {
  std::vector<const Kernels*> variants = {&baseline_kernels()};
  if (avx2_kernels()) variants.push_back(avx2_kernels());
  for (bool canal : {true, false}) {
    const Surface s = make(canal);
    Surface ref = s;
    ref.compiled.valid = false;  // the plane-intersection frames
    double f4[4];
    s.constant_f(f4);
    for (int k = 0; k <= 20; ++k) {
      const double u = -1 + 0.1 * k;
      CircleRow row;
      ASSERT_EQ(ref.row(u, true, row), Status::ok);
      CircleRow fast0;
      ASSERT_TRUE(baseline_kernels().frame_row[1](s.compiled, f4, u, fast0));
      for (const Kernels* K : variants) {
        CircleRow fast;
        ASSERT_TRUE(K->frame_row[1](s.compiled, f4, u, fast)) << K->isa << " u=" << u;
        EXPECT_EQ(std::memcmp(&fast, &fast0, sizeof fast), 0) << K->isa << " u=" << u;
        for (int f = 0; f < 16; ++f) {
          if ((f & 1) != canal) continue;
          for (double v : kVs) {
            PointResult want, got, fast_point, direct;
            baseline_kernels().point[f](row, v, want);
            K->point[f](row, v, got);
            EXPECT_TRUE(same(want, got, f)) << K->isa << " f=" << f << " u=" << u << " v=" << v;
            K->point[f](fast, v, fast_point);
            expect_close(want, fast_point, f, 1e-11);
            ASSERT_TRUE(K->frame_point[f](s.compiled, f4, u, v, direct));
            EXPECT_TRUE(same(fast_point, direct, f)) << K->isa << " f=" << f << " u=" << u;
            // Surface::eval's kernel writes exactly these results.
            PointResult written;
            const EvalOut out{written.x, (f & 8) ? written.xu : nullptr,
                              (f & 4) ? written.xv : nullptr, (f & 2) ? written.n : nullptr};
            Status st = Status::internal_error;
            ASSERT_TRUE(K->frame_eval[f](s.compiled, f4, u, v, out, st));
            ASSERT_EQ(st, Status::ok) << K->isa << " f=" << f << " u=" << u << " v=" << v;
            EXPECT_TRUE(same(direct, written, f)) << K->isa << " f=" << f << " u=" << u;
          }
        }
      }
    }
  }
}

// A grid big enough for non-temporal stores (SPEC §1b: >= 8 MiB of output)
// equals, bit for bit, the same rows evaluated as a small grid into
// strided buffers, also when the output does not start on a 16-byte
// boundary; every singular count is zero here.
TEST(Kernels, GridStorePathsGiveIdenticalBits) {
  for (bool canal : {true, false}) {
    const Surface s = make(canal);
    const std::size_t nu = 400, nv = 1100;  // 2 outputs x 400 x 1100 x 24 B > 8 MiB
    std::vector<double> us(nu), vs(nv);
    for (std::size_t i = 0; i < nu; ++i) us[i] = -1 + 2.0 * double(i) / double(nu - 1);
    for (std::size_t j = 0; j < nv; ++j) vs[j] = std::tan(3.14159 * ((j + 0.5) / nv - 0.5));
    std::vector<double> big_x(3 * nu * nv + 1), big_n(3 * nu * nv + 1);
    Strided3 px{big_x.data() + 1, 3}, pn{big_n.data() + 1, 3};  // 8-byte offset
    std::size_t singular = 1;
    ASSERT_EQ(s.eval_grid(us.data(), nu, vs.data(), nv, px, {}, {}, pn, &singular), Status::ok);
    EXPECT_EQ(singular, 0u);
    // Rows 37..39 (a block boundary inside) again, strided by 5.
    const std::size_t r0 = 37, nr = 3;
    std::vector<double> sx(5 * nr * nv), sn(5 * nr * nv);
    ASSERT_EQ(s.eval_grid(us.data() + r0, nr, vs.data(), nv, {sx.data(), 5}, {}, {},
                          {sn.data(), 5}, &singular),
              Status::ok);
    for (std::size_t i = 0; i < nr; ++i)
      for (std::size_t j = 0; j < nv; ++j)
        for (int c = 0; c < 3; ++c) {
          const std::size_t big = 3 * ((r0 + i) * nv + j) + c, small = 5 * (i * nv + j) + c;
          ASSERT_EQ(std::memcmp(&px.data[big], &sx[small], sizeof(double)), 0) << i << " " << j;
          ASSERT_EQ(std::memcmp(&pn.data[big], &sn[small], sizeof(double)), 0) << i << " " << j;
        }
    // And single points give the grid's bits.
    for (std::size_t j = 0; j < nv; j += 7) {
      double x[3], n[3];
      ASSERT_EQ(s.eval(us[r0], vs[j], {x, nullptr, nullptr, n}), Status::ok);
      EXPECT_EQ(std::memcmp(x, &px.data[3 * (r0 * nv + j)], sizeof x), 0) << j;
      EXPECT_EQ(std::memcmp(n, &pn.data[3 * (r0 * nv + j)], sizeof n), 0) << j;
    }
  }
}

// f varying in u (the grid forms the rotations per row instead of once per
// v for the block): grids still give single points' bits, on both surface
// kinds, with every output; ringed normals are unit and along x_u x x_v.
TEST(Kernels, GridWithMobiusVaryingInUGivesSinglePointBits) {
  // f = ((1 + u) v + u/2) / ((u/3) v + 2): its determinant 2 + 2u - u^2/6
  // changes sign at u = 6 - sqrt(48) ~ -0.93, so rows of both orientations
  // of v occur (the first row of the grid is u = -0.95).
  const double alpha[2] = {1, 1}, beta[2] = {0, 0.5}, gamma[2] = {0, 1.0 / 3}, delta[2] = {2, 0};
  Mobius f;
  ASSERT_EQ(make_mobius(1, alpha, beta, gamma, delta, f), Status::ok);
  RationalCurve c[3];
  const double(*rows[3])[3] = {kP1, kP2, kP3};
  for (int i = 0; i < 3; ++i) ASSERT_EQ(make_polynomial_curve(3, &rows[i][0][0], c[i]), Status::ok);
  for (bool canal : {true, false}) {
    Surface s;
    ASSERT_EQ(canal ? make_prcs(c[0], c[1], &f, -1, 1, s) : make_prrs(c[0], c[1], c[2], &f, -1, 1, s),
              Status::ok);
    const std::size_t nu = 21, nv = 300;  // two blocks of rows, two chunks of v
    std::vector<double> us(nu), vs(nv);
    for (std::size_t i = 0; i < nu; ++i) us[i] = -0.95 + 1.9 * double(i) / double(nu - 1);
    for (std::size_t j = 0; j < nv; ++j) vs[j] = std::tan(3.14159 * ((j + 0.5) / nv - 0.5));
    std::vector<double> x(3 * nu * nv), xu(3 * nu * nv), xv(3 * nu * nv), n(3 * nu * nv);
    std::size_t singular = 1;
    ASSERT_EQ(s.eval_grid(us.data(), nu, vs.data(), nv, {x.data(), 3}, {xu.data(), 3},
                          {xv.data(), 3}, {n.data(), 3}, &singular),
              Status::ok);
    EXPECT_EQ(singular, 0u);
    for (std::size_t i = 0; i < nu; ++i)
      for (std::size_t j = 0; j < nv; j += 13) {
        double px[3], pu[3], pv[3], pn[3];
        ASSERT_EQ(s.eval(us[i], vs[j], {px, pu, pv, pn}), Status::ok);
        const std::size_t k = 3 * (i * nv + j);
        EXPECT_EQ(std::memcmp(px, &x[k], sizeof px), 0) << canal << " " << i << " " << j;
        EXPECT_EQ(std::memcmp(pu, &xu[k], sizeof pu), 0) << canal << " " << i << " " << j;
        EXPECT_EQ(std::memcmp(pv, &xv[k], sizeof pv), 0) << canal << " " << i << " " << j;
        EXPECT_EQ(std::memcmp(pn, &n[k], sizeof pn), 0) << canal << " " << i << " " << j;
        if (canal) continue;
        const double m[3] = {pu[1] * pv[2] - pu[2] * pv[1], pu[2] * pv[0] - pu[0] * pv[2],
                             pu[0] * pv[1] - pu[1] * pv[0]};
        const double len = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
        EXPECT_NEAR(std::sqrt(pn[0] * pn[0] + pn[1] * pn[1] + pn[2] * pn[2]), 1.0, 1e-14);
        EXPECT_NEAR((pn[0] * m[0] + pn[1] * m[1] + pn[2] * m[2]) / len, 1.0, 1e-9)
            << i << " " << j;
      }
  }
}

}  // namespace
}  // namespace cyclide
