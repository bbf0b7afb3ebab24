// Benchmarks of seed 003 (Lie sphere geometry, Dupin cyclides, cyclide
// blends), in the core: a cyclide from three spheres (Algorithm 1 through
// Witt's extension), one point with partials and normal, a 256 x 256 grid
// of points and normals (a loop over dupin_eval and the Surface view's
// eval_grid), and Algorithm 2 (single and double blends of two cones).
#include <benchmark/benchmark.h>

#include <cmath>

#include "cyclide/cyclide.h"
#include "cyclide/cyclide_blend.hpp"
#include "cyclide/dupin.hpp"
#include "cyclide/surface.hpp"

using namespace cyclide;

namespace {

// A generic (non-torus) cyclide: three spheres spanning R^{2,1}.
void three_spheres(LieSphere (&s)[3]) {
  s[0] = oriented_sphere({3, 0, 0.2}, 1.0);
  s[1] = oriented_sphere({0.3, 2.6, 0}, 1.3);
  s[2] = oriented_sphere({-3, 0.4, -0.3}, 0.8);
}

bool cyclide(DupinCyclide& D) {
  LieSphere s[3];
  three_spheres(s);
  return dupin_from_spheres(s, D) == Status::ok;
}

void BM_DupinFromSpheres(benchmark::State& state) {
  LieSphere s[3];
  three_spheres(s);
  DupinCyclide D;
  Status st = Status::ok;
  for (auto _ : state) {
    st = dupin_from_spheres(s, D);
    benchmark::DoNotOptimize(D);
  }
  if (st != Status::ok) state.SkipWithError(status_name(st));
  state.SetItemsProcessed(state.iterations());
}

void BM_DupinPoint(benchmark::State& state) {
  DupinCyclide D;
  if (!cyclide(D)) return state.SkipWithError("dupin_from_spheres failed");
  DupinPoint P;
  double xi = 0.1;
  for (auto _ : state) {
    xi += 1e-6;
    benchmark::DoNotOptimize(dupin_eval(D, xi, 0.37, 0.0, P));
    benchmark::DoNotOptimize(P);
  }
  state.SetItemsProcessed(state.iterations());
}

constexpr int kGrid = 256;
void grid_params(double* xs, double* zs) {
  for (int i = 0; i < kGrid; ++i) {
    xs[i] = -2.0 + 4.0 * i / (kGrid - 1);
    zs[i] = -3.0 + 6.0 * i / (kGrid - 1);
  }
}

// 256 x 256 points and normals by a loop over dupin_eval.
void BM_DupinGridLoop(benchmark::State& state) {
  DupinCyclide D;
  if (!cyclide(D)) return state.SkipWithError("dupin_from_spheres failed");
  static double xs[kGrid], zs[kGrid], X[3 * kGrid * kGrid], N[3 * kGrid * kGrid];
  grid_params(xs, zs);
  for (auto _ : state) {
    DupinPoint P;
    for (int i = 0; i < kGrid; ++i)
      for (int j = 0; j < kGrid; ++j) {
        dupin_eval(D, xs[i], zs[j], 0.0, P);
        double* x = X + 3 * (i * kGrid + j);
        double* n = N + 3 * (i * kGrid + j);
        x[0] = P.point[0], x[1] = P.point[1], x[2] = P.point[2];
        n[0] = P.normal[0], n[1] = P.normal[1], n[2] = P.normal[2];
      }
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * kGrid * kGrid);
}

// The same grid through the Surface view (make_dupin_surface, eval_grid).
void BM_DupinGridSurface(benchmark::State& state) {
  DupinView V;
  if (!cyclide(V.cyclide)) return state.SkipWithError("dupin_from_spheres failed");
  static Surface S;
  if (Status st = make_dupin_surface(V, -2.0, 2.0, S); st != Status::ok)
    return state.SkipWithError(status_name(st));
  static double xs[kGrid], zs[kGrid], X[3 * kGrid * kGrid], N[3 * kGrid * kGrid];
  grid_params(xs, zs);
  Status st = Status::ok;
  for (auto _ : state) {
    st = S.eval_grid(xs, kGrid, zs, kGrid, Strided3{X, 3}, Strided3{}, Strided3{},
                     Strided3{N, 3}, nullptr);
    benchmark::ClobberMemory();
  }
  if (st != Status::ok) state.SkipWithError(status_name(st));
  state.SetItemsProcessed(state.iterations() * kGrid * kGrid);
}

// Case I: two cones cut from one cyclide (its circles at u = 0.2 and 0.8).
bool single_cones(LieCone& R, LieCone& S) {
  DupinView V;
  if (!cyclide(V.cyclide)) return false;
  Surface Sf;
  if (make_dupin_surface(V, 0.0, 1.0, Sf) != Status::ok) return false;
  return cone_from_surface(Sf, 0.2, 1, 1, R) == Status::ok &&
         cone_from_surface(Sf, 0.8, -1, 1, S) == Status::ok;
}

// Case II: a cylinder and a cone facing each other.
bool double_cones(LieCone& R, LieCone& S) {
  return cone_from_circle({0, 0, 0}, {1, 0, 0}, 1.0, 0.0, 1, R) == Status::ok &&
         cone_from_circle({5, 1, 0}, Vec3d(-1, 0, 0.2), 0.8, 0.2, 1, S) == Status::ok;
}

void BM_CyclideBlendSingle(benchmark::State& state) {
  LieCone R, S;
  if (!single_cones(R, S)) return state.SkipWithError("cones failed");
  CyclideBlend B;
  Status st = Status::ok;
  for (auto _ : state) {
    st = cyclide_blend(R, S, 1, 0.0, B);
    benchmark::DoNotOptimize(B);
  }
  if (st != Status::ok) state.SkipWithError(status_name(st));
  state.counters["pieces"] = B.pieces;
  state.SetItemsProcessed(state.iterations());
}

void BM_CyclideBlendDouble(benchmark::State& state) {
  LieCone R, S;
  if (!double_cones(R, S)) return state.SkipWithError("cones failed");
  // The first OK alpha = tan(phi) on branch +1 (then -1).
  double alpha = 0;
  int branch = 0;
  CyclideBlend B;
  for (int b : {1, -1}) {
    for (int k = 1; k < 24 && !branch; ++k) {
      const double a = std::tan(std::acos(-1.0) * (k / 24.0 - 0.5));
      if (cyclide_blend(R, S, b, a, B) == Status::ok) alpha = a, branch = b;
    }
    if (branch) break;
  }
  if (!branch) return state.SkipWithError("no OK double blend");
  Status st = Status::ok;
  for (auto _ : state) {
    st = cyclide_blend(R, S, branch, alpha, B);
    benchmark::DoNotOptimize(B);
  }
  if (st != Status::ok) state.SkipWithError(status_name(st));
  state.counters["pieces"] = B.pieces;
  state.counters["alpha"] = alpha;
  state.SetItemsProcessed(state.iterations());
}

// Algorithm 2's free parameter chosen by the core (scan of 64 angles on
// both branches + golden section, quality = min / max circle radius).
void BM_CyclideBlendAuto(benchmark::State& state) {
  LieCone R, S;
  if (!double_cones(R, S)) return state.SkipWithError("cones failed");
  CyclideBlend B;
  Status st = Status::ok;
  for (auto _ : state) {
    st = cyclide_blend_auto(R, S, B);
    benchmark::DoNotOptimize(B);
  }
  if (st != Status::ok) state.SkipWithError(status_name(st));
  state.SetItemsProcessed(state.iterations());
}

// The optimizer tier (C ABI): the default objective (fairness + regularity)
// scanned at 64 angles per branch, refined by Ceres.
void BM_CyclideBlendOptimize(benchmark::State& state) {
  LieCone R, S;
  if (!double_cones(R, S)) return state.SkipWithError("cones failed");
  cyc_lie_cone r, s;
  for (int i = 0; i < 6; ++i) {
    r.r0[i] = R.r0[i], r.r_plus[i] = R.r_plus[i];
    s.r0[i] = S.r0[i], s.r_plus[i] = S.r_plus[i];
  }
  cyc_context* ctx = nullptr;
  if (cyc_context_create(nullptr, &ctx) != CYC_OK) return state.SkipWithError("context");
  cyc_cyclide_blend B;
  cyc_optimize_summary sum;
  int rc = CYC_OK;
  for (auto _ : state) {
    rc = cyc_optimize_cyclide_blend(ctx, &r, &s, nullptr, nullptr, &B, &sum);
    benchmark::DoNotOptimize(B);
  }
  if (rc != CYC_OK) state.SkipWithError(cyc_context_last_error(ctx));
  state.counters["iterations"] = sum.iterations;
  state.counters["cost"] = sum.final_cost;
  cyc_context_destroy(ctx);
  state.SetItemsProcessed(state.iterations());
}

}  // namespace

BENCHMARK(BM_DupinFromSpheres);
BENCHMARK(BM_DupinPoint);
BENCHMARK(BM_DupinGridLoop)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DupinGridSurface)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CyclideBlendSingle);
BENCHMARK(BM_CyclideBlendDouble);
BENCHMARK(BM_CyclideBlendAuto)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CyclideBlendOptimize)->Unit(benchmark::kMillisecond);
