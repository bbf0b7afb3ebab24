// Google Benchmark suite for cyclide, through the public C API only.
//
//  * creation of a PRCS surface (two cubics) and a PRRS surface (three cubics)
//  * single-point evaluation: point only, and point + x_u + x_v + normal
//  * grid evaluation 1000 x 1000 into preallocated caller buffers
//
// Every benchmark reports "allocs_per_iter": heap allocations (malloc family
// and operator new, counted by alloc_hook.cpp) per iteration of its timed
// loop. Throughput is reported as items/s (surfaces/s or points/s).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "cyclide/cyclide.h"

std::uint64_t cyc_bench_alloc_count();  // alloc_hook.cpp
bool cyc_bench_alloc_hooked();          // false: allocations are not counted

namespace {

// ------------------------------------------------------------ inputs

// Cubic perturbations of the lines of seed 000, Example 2: p1 = (u, 0, 0),
// p2 = (2u, u, 1); p3 (PRRS only) is a third, non-collinear cubic.
// Rows are the power-form coefficients c_0..c_3 as (x, y, z).
constexpr double kP1[4][3] = {{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0},
                              {0.0, 0.05, 0.02}, {0.1, 0.0, -0.05}};
constexpr double kP2[4][3] = {{0.0, 0.0, 1.0}, {2.0, 1.0, 0.0},
                              {0.03, 0.0, 0.05}, {-0.05, 0.1, 0.0}};
constexpr double kP3[4][3] = {{0.0, 2.0, 0.0}, {-1.0, 0.0, 1.0},
                              {0.0, -0.1, 0.0}, {0.05, 0.0, 0.1}};
constexpr double kU0 = -1.0, kU1 = 1.0;

enum class Kind { prcs, prrs };

// One context, the three curves and both surfaces, built once.
struct Fixture {
  cyc_context* ctx = nullptr;
  cyc_curve* curve[3] = {nullptr, nullptr, nullptr};
  cyc_surface* prcs = nullptr;
  cyc_surface* prrs = nullptr;
  std::string error;  // empty when everything was created

  const cyc_surface* surface(Kind k) const { return k == Kind::prcs ? prcs : prrs; }
};

std::string describe(const char* what, int status, const cyc_context* ctx) {
  return std::string(what) + " failed: " + cyc_status_name(status) + ": " +
         cyc_context_last_error(ctx);
}

Fixture build_fixture() {
  Fixture f;
  int st = cyc_context_create(nullptr, &f.ctx);
  if (st != CYC_OK) {
    f.error = std::string("cyc_context_create failed: ") + cyc_status_name(st);
    return f;
  }
  const double(*rows[3])[3] = {kP1, kP2, kP3};
  for (int i = 0; i < 3; ++i) {
    st = cyc_curve_create_polynomial(f.ctx, 3, &rows[i][0][0], 3, &f.curve[i]);
    if (st != CYC_OK) {
      f.error = describe("cyc_curve_create_polynomial", st, f.ctx);
      return f;
    }
  }
  st = cyc_prcs_create(f.ctx, f.curve[0], f.curve[1], nullptr, kU0, kU1, &f.prcs);
  if (st != CYC_OK) {
    f.error = describe("cyc_prcs_create", st, f.ctx);
    return f;
  }
  st = cyc_prrs_create(f.ctx, f.curve[0], f.curve[1], f.curve[2], nullptr, kU0, kU1,
                       &f.prrs);
  if (st != CYC_OK) f.error = describe("cyc_prrs_create", st, f.ctx);
  return f;
}

const Fixture& fixture() {
  static const Fixture f = build_fixture();  // lives until exit
  return f;
}

// Parameters: u over the domain, v over tan of (-pi/2, pi/2) so that both
// branches of the circle evaluation (|v| <= 1 and |v| > 1) are exercised.
double v_of(double t) {  // t in (0, 1)
  const double pi = 3.14159265358979323846;
  return std::tan(pi * (t - 0.5));
}

constexpr std::size_t kPairs = 4096;  // power of two
struct Pairs {
  double uv[kPairs][2];
};
const Pairs& random_pairs() {
  static const Pairs p = [] {
    Pairs r{};
    std::mt19937_64 g(20240601);
    std::uniform_real_distribution<double> U(kU0, kU1), T(0.02, 0.98);
    for (auto& e : r.uv) {
      e[0] = U(g);
      e[1] = v_of(T(g));
    }
    return r;
  }();
  return p;
}

// ------------------------------------------------------------ allocation counter

// Counts allocations between construction and finish() and stores them as
// the per-iteration average "allocs_per_iter".
class AllocCounter {
 public:
  explicit AllocCounter(benchmark::State& s) : s_(s), start_(cyc_bench_alloc_count()) {}
  void finish() {
    if (!cyc_bench_alloc_hooked()) return;  // no counter rather than a false 0
    const std::uint64_t n = cyc_bench_alloc_count() - start_;
    s_.counters["allocs_per_iter"] =
        benchmark::Counter(double(n), benchmark::Counter::kAvgIterations);
  }

 private:
  benchmark::State& s_;
  std::uint64_t start_;
};

bool fixture_ok(benchmark::State& state) {
  const Fixture& f = fixture();
  if (!f.error.empty()) {
    state.SkipWithError(f.error.c_str());
    return false;
  }
  return true;
}

// ------------------------------------------------------------ creation

// Surface from curves that already exist (create + destroy per iteration).
void BM_Create(benchmark::State& state, Kind kind) {
  if (!fixture_ok(state)) return;
  const Fixture& f = fixture();
  int bad = CYC_OK;
  AllocCounter allocs(state);
  for (auto _ : state) {
    cyc_surface* s = nullptr;
    const int st = kind == Kind::prcs
                       ? cyc_prcs_create(f.ctx, f.curve[0], f.curve[1], nullptr, kU0, kU1, &s)
                       : cyc_prrs_create(f.ctx, f.curve[0], f.curve[1], f.curve[2], nullptr,
                                         kU0, kU1, &s);
    if (st != CYC_OK) {
      bad = st;
      break;
    }
    benchmark::DoNotOptimize(s);
    cyc_surface_destroy(f.ctx, s);
  }
  allocs.finish();
  if (bad != CYC_OK) {
    state.SkipWithError(describe("surface creation", bad, f.ctx).c_str());
    return;
  }
  state.SetItemsProcessed(state.iterations());
}

// Everything from coefficients: the curves, the surface, and destruction.
void BM_CreateFromCoefficients(benchmark::State& state, Kind kind) {
  if (!fixture_ok(state)) return;
  const Fixture& f = fixture();
  const double(*rows[3])[3] = {kP1, kP2, kP3};
  const int ncurves = kind == Kind::prcs ? 2 : 3;
  int bad = CYC_OK;
  AllocCounter allocs(state);
  for (auto _ : state) {
    cyc_curve* c[3] = {nullptr, nullptr, nullptr};
    for (int i = 0; i < ncurves && bad == CYC_OK; ++i)
      if (int st = cyc_curve_create_polynomial(f.ctx, 3, &rows[i][0][0], 3, &c[i]);
          st != CYC_OK)
        bad = st;
    cyc_surface* s = nullptr;
    if (bad == CYC_OK) {
      const int st = kind == Kind::prcs
                         ? cyc_prcs_create(f.ctx, c[0], c[1], nullptr, kU0, kU1, &s)
                         : cyc_prrs_create(f.ctx, c[0], c[1], c[2], nullptr, kU0, kU1, &s);
      if (st != CYC_OK) bad = st;
    }
    benchmark::DoNotOptimize(s);
    cyc_surface_destroy(f.ctx, s);
    for (cyc_curve* ci : c) cyc_curve_destroy(f.ctx, ci);
    if (bad != CYC_OK) break;
  }
  allocs.finish();
  if (bad != CYC_OK) {
    state.SkipWithError(describe("creation from coefficients", bad, f.ctx).c_str());
    return;
  }
  state.SetItemsProcessed(state.iterations());
}

// ------------------------------------------------------------ single points

// One cyc_surface_eval per iteration at a varying (u, v).
void BM_Eval(benchmark::State& state, Kind kind, bool full) {
  if (!fixture_ok(state)) return;
  const Fixture& f = fixture();
  const cyc_surface* surf = f.surface(kind);
  const Pairs& P = random_pairs();
  double x[3], xu[3], xv[3], n[3];
  double* pdu = full ? xu : nullptr;
  double* pdv = full ? xv : nullptr;
  double* pn = full ? n : nullptr;
  benchmark::DoNotOptimize(pdu);  // keep the mode opaque to the optimizer
  std::size_t i = 0;
  int bad = CYC_OK;
  AllocCounter allocs(state);
  for (auto _ : state) {
    const double* uv = P.uv[i++ & (kPairs - 1)];
    const int st = cyc_surface_eval(f.ctx, surf, uv[0], uv[1], x, pdu, pdv, pn);
    if (st != CYC_OK && bad == CYC_OK) bad = st;
    benchmark::DoNotOptimize(x);
    benchmark::ClobberMemory();
  }
  allocs.finish();
  if (bad != CYC_OK) {
    state.SkipWithError(describe("cyc_surface_eval", bad, f.ctx).c_str());
    return;
  }
  state.SetItemsProcessed(state.iterations());
}

// cyc_surface_eval_batch over the same kPairs random (u, v) per iteration:
// the core's per-point cost without the per-call C API overhead.
void BM_EvalBatch(benchmark::State& state, Kind kind, bool full) {
  if (!fixture_ok(state)) return;
  const Fixture& f = fixture();
  const cyc_surface* surf = f.surface(kind);
  const Pairs& P = random_pairs();
  std::vector<double> x(3 * kPairs), xu(3 * kPairs), xv(3 * kPairs), n(3 * kPairs);
  const cyc_buffer3 none = {nullptr, 0, 3};
  const cyc_buffer3 bx = {x.data(), kPairs, 3};
  const cyc_buffer3 bu = full ? cyc_buffer3{xu.data(), kPairs, 3} : none;
  const cyc_buffer3 bv = full ? cyc_buffer3{xv.data(), kPairs, 3} : none;
  const cyc_buffer3 bn = full ? cyc_buffer3{n.data(), kPairs, 3} : none;
  int bad = CYC_OK;
  AllocCounter allocs(state);
  for (auto _ : state) {
    size_t singular = 0;
    const int st = cyc_surface_eval_batch(f.ctx, surf, &P.uv[0][0], 2, kPairs, bx, bu, bv,
                                          bn, &singular);
    if (st != CYC_OK && bad == CYC_OK) bad = st;
    benchmark::DoNotOptimize(x.data());
    benchmark::ClobberMemory();
  }
  allocs.finish();
  if (bad != CYC_OK) {
    state.SkipWithError(describe("cyc_surface_eval_batch", bad, f.ctx).c_str());
    return;
  }
  state.SetItemsProcessed(state.iterations() * int64_t(kPairs));
}

// ------------------------------------------------------------ grids

enum GridOut { kPoints = 0, kPointsNormals = 1, kAll = 2 };

// One cyc_surface_eval_grid of nu x nv (state.range(0) x state.range(1)) per
// iteration into caller buffers allocated before the timed loop.
void BM_Grid(benchmark::State& state, Kind kind, GridOut what) {
  if (!fixture_ok(state)) return;
  const Fixture& f = fixture();
  const cyc_surface* surf = f.surface(kind);
  const std::size_t nu = std::size_t(state.range(0)), nv = std::size_t(state.range(1));
  const std::size_t count = nu * nv;
  std::vector<double> us(nu), vs(nv);
  for (std::size_t i = 0; i < nu; ++i)
    us[i] = kU0 + (kU1 - kU0) * double(i) / double(nu > 1 ? nu - 1 : 1);
  for (std::size_t j = 0; j < nv; ++j) vs[j] = v_of((double(j) + 0.5) / double(nv));
  std::vector<double> x(3 * count), n, xu, xv;
  if (what != kPoints) n.resize(3 * count);
  if (what == kAll) {
    xu.resize(3 * count);
    xv.resize(3 * count);
  }
  auto buf = [&](std::vector<double>& b) {
    return b.empty() ? cyc_buffer3{nullptr, 0, 3} : cyc_buffer3{b.data(), count, 3};
  };
  int bad = CYC_OK;
  size_t singular = 0;
  AllocCounter allocs(state);
  for (auto _ : state) {
    const int st = cyc_surface_eval_grid(f.ctx, surf, us.data(), nu, vs.data(), nv, buf(x),
                                         buf(xu), buf(xv), buf(n), &singular);
    if (st != CYC_OK && bad == CYC_OK) bad = st;
    benchmark::DoNotOptimize(x.data());
    benchmark::ClobberMemory();
  }
  allocs.finish();
  if (bad != CYC_OK) {
    state.SkipWithError(describe("cyc_surface_eval_grid", bad, f.ctx).c_str());
    return;
  }
  state.counters["singular"] = double(singular);
  state.SetItemsProcessed(state.iterations() * int64_t(count));
}

// ------------------------------------------------------------ registration

BENCHMARK_CAPTURE(BM_Create, prcs, Kind::prcs);
BENCHMARK_CAPTURE(BM_Create, prrs, Kind::prrs);
BENCHMARK_CAPTURE(BM_CreateFromCoefficients, prcs, Kind::prcs);
BENCHMARK_CAPTURE(BM_CreateFromCoefficients, prrs, Kind::prrs);

BENCHMARK_CAPTURE(BM_Eval, prcs_point, Kind::prcs, false);
BENCHMARK_CAPTURE(BM_Eval, prcs_point_du_dv_normal, Kind::prcs, true);
BENCHMARK_CAPTURE(BM_Eval, prrs_point, Kind::prrs, false);
BENCHMARK_CAPTURE(BM_Eval, prrs_point_du_dv_normal, Kind::prrs, true);

BENCHMARK_CAPTURE(BM_EvalBatch, prcs_point, Kind::prcs, false);
BENCHMARK_CAPTURE(BM_EvalBatch, prcs_point_du_dv_normal, Kind::prcs, true);
BENCHMARK_CAPTURE(BM_EvalBatch, prrs_point, Kind::prrs, false);
BENCHMARK_CAPTURE(BM_EvalBatch, prrs_point_du_dv_normal, Kind::prrs, true);

BENCHMARK_CAPTURE(BM_Grid, prcs_points, Kind::prcs, kPoints)
    ->Args({1000, 1000})->Args({100, 100})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Grid, prcs_points_normals, Kind::prcs, kPointsNormals)
    ->Args({1000, 1000})->Args({100, 100})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Grid, prcs_all, Kind::prcs, kAll)
    ->Args({1000, 1000})->Args({100, 100})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Grid, prrs_points, Kind::prrs, kPoints)
    ->Args({1000, 1000})->Args({100, 100})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Grid, prrs_points_normals, Kind::prrs, kPointsNormals)
    ->Args({1000, 1000})->Args({100, 100})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Grid, prrs_all, Kind::prrs, kAll)
    ->Args({1000, 1000})->Args({100, 100})->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
