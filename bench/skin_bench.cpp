// Benchmarks of seed 002 (sphere skins by rotation-minimizing transport,
// issue 6), in the core: one skin with the reference RMF (the angle's rate
// as a Chebyshev series, to 1e-13) and with double reflection, a 256 x 256
// grid of points and normals, one point with partials and normal, the
// twist measure, and a chain of 100 spheres (issue 6's list). The paper
// reports "a couple of seconds" per skin.
#include <benchmark/benchmark.h>

#include <cmath>

#include "cyclide/sphere_skin.hpp"

using namespace cyclide;

namespace {

// Two spheres with skew cone axes (tests/sphere_skin_test.cpp's Skew).
void skew_ends(SkinEnd& s, SkinEnd& e) {
  skin_end_from_sphere({0, 0, 0}, 1.0, {0.3, 0, 0}, {3, 0, 0}, s);
  const Vec3d axis = Vec3d(1.0, 0.6, 0.8).normalized();
  skin_end_from_sphere({4, 1, 0.5}, 1.2, Vec3d(4, 1, 0.5) - 0.4 * axis, 3.0 * axis, e);
}

void BM_SphereSkinCreate(benchmark::State& state) {
  SkinEnd s, e;
  skew_ends(s, e);
  SkinOptions o;
  o.method = RmfMethod(state.range(0));
  static SphereSkin S;
  Status st = Status::ok;
  for (auto _ : state) {
    st = make_sphere_skin(s, e, o, S);
    benchmark::DoNotOptimize(S);
  }
  if (st != Status::ok) state.SkipWithError("make_sphere_skin failed");
  state.counters["substeps"] = S.rmf.substeps;
  state.counters["error_estimate"] = S.rmf.error_estimate;
  state.SetLabel(o.method == RmfMethod::reference ? "reference" : "double_reflection");
}

void BM_SphereSkinGrid(benchmark::State& state) {
  SkinEnd s, e;
  skew_ends(s, e);
  static SphereSkin S;
  if (make_sphere_skin(s, e, SkinOptions{}, S) != Status::ok) {
    state.SkipWithError("make_sphere_skin failed");
    return;
  }
  constexpr int n = 256;
  static double th[n], t[n], X[3 * n * n], N[3 * n * n];
  for (int i = 0; i < n; ++i) th[i] = 2 * std::acos(-1.0) * i / n, t[i] = i / double(n - 1);
  for (auto _ : state) {
    benchmark::DoNotOptimize(skin_eval_grid(S, th, n, t, n, X, N));
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * n * n);
}

void BM_SphereSkinPoint(benchmark::State& state) {
  SkinEnd s, e;
  skew_ends(s, e);
  static SphereSkin S;
  if (make_sphere_skin(s, e, SkinOptions{}, S) != Status::ok) {
    state.SkipWithError("make_sphere_skin failed");
    return;
  }
  double x[3], a[3], b[3], nn[3], th = 0.1;
  for (auto _ : state) {
    th += 1e-3;
    benchmark::DoNotOptimize(skin_eval(S, th, 0.37, x, a, b, nn));
    benchmark::DoNotOptimize(x);
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_SphereSkinTwist(benchmark::State& state) {
  SkinEnd s, e;
  skew_ends(s, e);
  SkinOptions o;
  o.pairing = SkinPairing::kunkli_hoffmann;
  static SphereSkin S;
  if (make_sphere_skin(s, e, o, S) != Status::ok) {
    state.SkipWithError("make_sphere_skin failed");
    return;
  }
  double tw = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(skin_twist(S, 0.5, tw));
    benchmark::DoNotOptimize(tw);
  }
  state.counters["twist"] = tw;
}

// A chain of 100 spheres along a helix: 99 patches.
void BM_SphereSkinChain100(benchmark::State& state) {
  constexpr int kSpheres = 100;
  static SkinEnd ends[kSpheres];
  for (int k = 0; k < kSpheres; ++k) {
    const double a = 0.7 * k;
    const Vec3d m(3 * std::cos(a), 3 * std::sin(a), 1.2 * k);
    const Vec3d dir = Vec3d(-3 * std::sin(a), 3 * std::cos(a), 1.2).normalized();
    skin_end_from_sphere(m, 0.6 + 0.1 * (k % 3), m - 0.1 * dir, 2.5 * dir, ends[k]);
  }
  static SphereSkin P[kSpheres - 1];
  Status st = Status::ok;
  for (auto _ : state) {
    st = make_sphere_skin_chain(ends, kSpheres, SkinOptions{}, P);
    benchmark::DoNotOptimize(P);
  }
  if (st != Status::ok) state.SkipWithError(status_name(st));
  state.SetItemsProcessed(state.iterations() * (kSpheres - 1));
}

}  // namespace

BENCHMARK(BM_SphereSkinCreate)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SphereSkinGrid)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SphereSkinPoint);
BENCHMARK(BM_SphereSkinTwist)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SphereSkinChain100)->Unit(benchmark::kMicrosecond);
