// Benchmarks of seed 004 (Laguerre geometry, parabolic Dupin cyclides, G1
// design) through the C ABI: Lambda^{-1} of a grid of isotropic points,
// a 64 x 64 grid of points on a rational bicubic cyclide patch (the bicubic
// Psi case of the PN grid; BM_PnSurfaceGrid itself waits for the PN
// surface handle), cubic triangle construction, Delaunay of 1000 / 10000
// points, and the design of a surface from 1000 oriented points of an
// ellipsoid cap with a caller workspace.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "cyclide/cyclide.h"

namespace {

struct Ctx {
  cyc_context* ctx = nullptr;
  Ctx() { cyc_context_create(nullptr, &ctx); }
  ~Ctx() { cyc_context_destroy(ctx); }
};

void normal_of(double y1, double y2, double n[3]) {
  const double N = 1 + y1 * y1 + y2 * y2;
  n[0] = 2 * y1 / N, n[1] = 2 * y2 / N, n[2] = (y1 * y1 + y2 * y2 - 1) / N;
}

// The lower cap of the ellipsoid (2, 1.5, 1) at k x k jittered normals.
std::vector<cyc_oriented_point> ellipsoid_cap(int k, double h) {
  std::vector<cyc_oriented_point> data;
  const double D[3] = {4.0, 2.25, 1.0};
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      const bool border = i == 0 || j == 0 || i == k - 1 || j == k - 1;
      const double jx = border ? 0 : 0.05 * std::sin(3.7 * i + 5.1 * j);
      const double jy = border ? 0 : 0.05 * std::cos(2.3 * i - 4.9 * j);
      const double y1 = -h + 2 * h * (i + 0.5 + jx) / k, y2 = -h + 2 * h * (j + 0.5 + jy) / k;
      cyc_oriented_point A;
      normal_of(y1, y2, A.normal);
      const double s = std::sqrt(D[0] * A.normal[0] * A.normal[0] +
                                 D[1] * A.normal[1] * A.normal[1] + D[2] * A.normal[2] * A.normal[2]);
      for (int c = 0; c < 3; ++c) A.point[c] = D[c] * A.normal[c] / s;
      data.push_back(A);
    }
  return data;
}

void BM_LambdaInverse(benchmark::State& state) {
  Ctx c;
  cyc_isotropic_point y{0, {0.3, -0.2, 0.7}, 0};
  cyc_oriented_plane p;
  for (auto _ : state) {
    y.y[0] += 1e-9;
    benchmark::DoNotOptimize(cyc_isotropic_to_laguerre(c.ctx, &y, &p));
    benchmark::DoNotOptimize(p);
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_ParabolicCyclideEval(benchmark::State& state) {
  Ctx c;
  const cyc_graph_quadratic q{{-1.0, 0.2, 0.5, 0.4, -0.2, 0.3}};
  cyc_parabolic_cyclide C;
  if (cyc_parabolic_cyclide_from_quadratic(c.ctx, &q, &C) != CYC_OK)
    return state.SkipWithError("from_quadratic");
  double x[3], n[3], u = 0.1;
  for (auto _ : state) {
    u += 1e-9;
    benchmark::DoNotOptimize(cyc_parabolic_cyclide_eval(c.ctx, &C, u, 0.37, x, n));
    benchmark::DoNotOptimize(x);
  }
  state.SetItemsProcessed(state.iterations());
}

// 64 x 64 points of the exact rational bicubic of a cyclide (§4.1).
void BM_BicubicPatchGrid64(benchmark::State& state) {
  Ctx c;
  const cyc_graph_quadratic q{{-1.0, 0.2, 0.5, 0.4, -0.2, 0.3}};
  const double corner[2] = {-0.5, -0.5}, e1[2] = {1, 0}, e2[2] = {0, 1};
  cyc_rational_bicubic_patch P;
  if (cyc_cyclide_bicubic_patch(c.ctx, &q, corner, e1, e2, &P) != CYC_OK)
    return state.SkipWithError("bicubic");
  std::vector<double> out(3 * 64 * 64);
  int bad = 0;
  for (auto _ : state) {
    for (int i = 0; i < 64; ++i)
      for (int j = 0; j < 64; ++j)
        bad += cyc_bicubic_patch_eval(c.ctx, &P, i / 63.0, j / 63.0, &out[3 * (64 * i + j)]);
    benchmark::DoNotOptimize(out.data());
  }
  if (bad) state.SkipWithError("eval failed");
  state.SetItemsProcessed(state.iterations() * 64 * 64);
}

// Lambda^{-1} with offsets of a bicubic Psi (Thm. 3.2) on a 64 x 64 grid.
void BM_PnSurfaceGrid(benchmark::State& state) {
  Ctx c;
  double control[4 * 16];
  for (int i = 0, k = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const double y1 = -0.6 + 0.4 * i, y2 = -0.6 + 0.4 * j;
      const double w = 1 + 0.1 * ((i + j) % 2);
      const double y3 = 0.3 - 0.5 * y1 * y1 + 0.2 * y2 * y2 + 0.1 * y1 * y2 * y2;
      control[k++] = w;  // homogeneous (w, w y1, w y2, w y3)
      control[k++] = w * y1;
      control[k++] = w * y2;
      control[k++] = w * y3;
    }
  cyc_pn_surface* S = nullptr;
  if (cyc_pn_surface_create(c.ctx, 3, 3, control, &S) != CYC_OK)
    return state.SkipWithError(cyc_context_last_error(c.ctx));
  std::vector<double> us(64), pts(3 * 64 * 64), nrm(3 * 64 * 64);
  for (int i = 0; i < 64; ++i) us[i] = i / 63.0;
  size_t failed = 0;
  for (auto _ : state) {
    if (cyc_pn_surface_eval_grid(c.ctx, S, us.data(), 64, us.data(), 64, 0.25,
                                 cyc_buffer3{pts.data(), 4096, 3}, cyc_buffer3{nrm.data(), 4096, 3},
                                 &failed) != CYC_OK)
      return state.SkipWithError(cyc_context_last_error(c.ctx));
    benchmark::DoNotOptimize(pts.data());
  }
  state.counters["failed"] = double(failed);
  state.SetItemsProcessed(state.iterations() * 64 * 64);
  cyc_pn_surface_destroy(S);
}

void BM_CubicTriangle(benchmark::State& state) {
  Ctx c;
  cyc_quadratic_graph_triangle t{{{-0.5, -0.4}, {0.7, -0.1}, {0.1, 0.8}},
                                 {0.1, 0.2, 0.3, 0.1, 0.0, -0.2}};
  cyc_rational_cubic_triangle T;
  for (auto _ : state) {
    t.ordinate[0] += 1e-12;
    benchmark::DoNotOptimize(cyc_cyclide_cubic_triangle(c.ctx, &t, &T));
    benchmark::DoNotOptimize(T);
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_Delaunay(benchmark::State& state) {
  Ctx c;
  const int n = int(state.range(0));
  std::vector<double> pts(2 * n);
  unsigned s = 12345;
  for (double& p : pts) {
    s = s * 1103515245u + 12345u;
    p = (s >> 8) / double(1 << 24);
  }
  std::vector<unsigned char> work(cyc_delaunay_workspace_size(n));
  std::vector<int> tri(3 * cyc_delaunay_max_triangles(n));
  int nt = 0;
  for (auto _ : state) {
    if (cyc_delaunay_triangulate(c.ctx, pts.data(), n, work.data(), work.size(), tri.data(),
                                 int(tri.size() / 3), &nt) != CYC_OK)
      return state.SkipWithError(cyc_context_last_error(c.ctx));
    benchmark::DoNotOptimize(tri.data());
  }
  state.SetItemsProcessed(state.iterations() * n);
}

void BM_Design1000(benchmark::State& state) {
  Ctx c;
  // 32 x 32 = 1024 oriented points of the cap (about 1000).
  const auto data = ellipsoid_cap(32, 0.6);
  const int n = int(data.size());
  std::vector<unsigned char> work(cyc_design_workspace_size(n, 0));
  const int cap = cyc_design_max_patches(n, 0);
  std::vector<cyc_rational_cubic_triangle> patches(cap);
  int np = 0;
  cyc_design_options o{1};
  cyc_design_report rep;
  for (auto _ : state) {
    if (cyc_design_cyclide_surface(c.ctx, data.data(), n, nullptr, 0, &o, work.data(),
                                   work.size(), nullptr, patches.data(), cap, &np, &rep) != CYC_OK)
      return state.SkipWithError(cyc_context_last_error(c.ctx));
    benchmark::DoNotOptimize(patches.data());
  }
  state.counters["patches"] = np;
  state.counters["ridge_patches"] = rep.ridge_patches;
  state.SetItemsProcessed(state.iterations() * n);
}

}  // namespace

BENCHMARK(BM_LambdaInverse);
BENCHMARK(BM_ParabolicCyclideEval);
BENCHMARK(BM_BicubicPatchGrid64)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PnSurfaceGrid)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CubicTriangle);
BENCHMARK(BM_Delaunay)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Design1000)->Unit(benchmark::kMillisecond);
