// Google Benchmark suite for cyclide, through the public C API (and, where
// named, the C++ core for comparison).
//
//  * creation of a PRCS surface (two cubics) and a PRRS surface (three cubics)
//  * single-point evaluation: point only, and point + x_u + x_v + normal
//  * grid evaluation 1000 x 1000 into preallocated caller buffers
//  * Darboux cyclides (SPEC §8b): DCMC on Example 4 (core and C API),
//    cyc_invert_darboux, value + gradient (C API and core), and
//    cyc_surface_eval_inverted per point (compare with BM_Eval)
//  * blends (SPEC §8d) and the blend optimizer (§8e, cyc_optimize_blend)
//  * the implicit-blend approximation of seed 001 §7.a (BM_ImplicitBlendApprox)
//
// Every benchmark reports "allocs_per_iter": heap allocations (malloc family
// and operator new, counted by alloc_hook.cpp) per iteration of its timed
// loop. Throughput is reported as items/s (surfaces/s or points/s).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "cyclide/cyclide.h"
#include "cyclide/darboux.hpp"  // the core, for BM_DcmcCore and the core value
#include "cyclide/darboux_lines.hpp"  // the core, for BM_ParabolicLinesCore
#include "cyclide/blend.hpp"  // the core, for BM_BlendRinged / BM_BlendCanal
#include "cyclide/nway.hpp"   // the core, for BM_NwayBlend

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

// ------------------------------------------------------------ Darboux (SPEC §8b)

// Example 4 of seed 000, eq. (34): (u, 0, 0), (0, u, 1), (u, u, 2).
constexpr cyc_line kEx4Lines[3] = {{{0, 0, 0}, {1, 0, 0}}, {{0, 0, 1}, {0, 1, 0}},
                                   {{0, 0, 2}, {1, 1, 0}}};
// Eq. (35) with alpha = 1: z (x^2+y^2+z^2) - y^2 - 3z^2 - 3xy + (xz - 2yz + 2y) + 2z.
constexpr cyc_darboux kEx4Member = {{0, 0, 0, 1, 0, -1, -3, -3, 1, -2, 0, 2, 2, 0}};
constexpr cyc_inversion kInversion = {{0.5, -1.0, 3.0}, 2.0};

// DCMC through the core: one fixed-size 9x10 JacobiSVD per iteration.
void BM_DcmcCore(benchmark::State& state) {
  using namespace cyclide;
  Line L[3];
  for (int i = 0; i < 3; ++i)
    L[i] = {Vec3d(kEx4Lines[i].point[0], kEx4Lines[i].point[1], kEx4Lines[i].point[2]),
            Vec3d(kEx4Lines[i].direction[0], kEx4Lines[i].direction[1],
                  kEx4Lines[i].direction[2])};
  Status bad = Status::ok;
  AllocCounter allocs(state);
  for (auto _ : state) {
    benchmark::DoNotOptimize(L);
    DcmcFamily F;
    const Status st = dcmc(L, F);
    if (st != Status::ok) bad = st;
    benchmark::DoNotOptimize(F);
  }
  allocs.finish();
  if (bad != Status::ok) {
    state.SkipWithError("dcmc (core) failed on Example 4");
    return;
  }
  state.SetItemsProcessed(state.iterations());
}

// DCMC through the C API (argument checks, the guard, copying out).
void BM_DcmcCapi(benchmark::State& state) {
  if (!fixture_ok(state)) return;
  const Fixture& f = fixture();
  cyc_line L[3] = {kEx4Lines[0], kEx4Lines[1], kEx4Lines[2]};
  double n[3];
  cyc_darboux base, quadric;
  int bad = CYC_OK;
  AllocCounter allocs(state);
  for (auto _ : state) {
    benchmark::DoNotOptimize(L);
    const int st = cyc_dcmc(f.ctx, L, n, &base, &quadric);
    if (st != CYC_OK && bad == CYC_OK) bad = st;
    benchmark::DoNotOptimize(base);
    benchmark::DoNotOptimize(quadric);
    benchmark::ClobberMemory();
  }
  allocs.finish();
  if (bad != CYC_OK) {
    state.SkipWithError(describe("cyc_dcmc", bad, f.ctx).c_str());
    return;
  }
  state.SetItemsProcessed(state.iterations());
}

// The closed-form image of a cyclide's coefficients (cyc_invert_darboux).
void BM_InvertDarboux(benchmark::State& state) {
  if (!fixture_ok(state)) return;
  const Fixture& f = fixture();
  cyc_darboux D = kEx4Member, out;
  cyc_inversion inv = kInversion;
  int bad = CYC_OK;
  AllocCounter allocs(state);
  for (auto _ : state) {
    benchmark::DoNotOptimize(D);
    benchmark::DoNotOptimize(inv);
    const int st = cyc_invert_darboux(f.ctx, &inv, &D, &out);
    if (st != CYC_OK && bad == CYC_OK) bad = st;
    benchmark::DoNotOptimize(out);
    benchmark::ClobberMemory();
  }
  allocs.finish();
  if (bad != CYC_OK) {
    state.SkipWithError(describe("cyc_invert_darboux", bad, f.ctx).c_str());
    return;
  }
  state.SetItemsProcessed(state.iterations());
}

// Points of random (u, v) for the Darboux value benchmarks: the surface's
// points, so that they are of the size the surfaces produce.
struct Points {
  double x[kPairs][3];
};
const Points& surface_points() {
  static const Points p = [] {
    Points r{};
    const Fixture& f = fixture();
    const Pairs& P = random_pairs();
    for (std::size_t i = 0; i < kPairs; ++i)
      if (!f.prcs || cyc_surface_eval(f.ctx, f.prcs, P.uv[i][0], P.uv[i][1], r.x[i], nullptr,
                                      nullptr, nullptr) != CYC_OK)
        r.x[i][0] = r.x[i][1] = r.x[i][2] = double(i % 7) - 3.0;
    return r;
  }();
  return p;
}

// F(X) and grad F(X) of a Darboux cyclide: the C API, or the core.
void BM_DarbouxValueGradient(benchmark::State& state, bool capi) {
  if (!fixture_ok(state)) return;
  const Fixture& f = fixture();
  const Points& X = surface_points();
  cyclide::Darboux core;
  std::memcpy(core.k, kEx4Member.k, sizeof core.k);
  const cyc_darboux D = kEx4Member;
  std::size_t i = 0;
  int bad = CYC_OK;
  AllocCounter allocs(state);
  for (auto _ : state) {
    const double* x = X.x[i++ & (kPairs - 1)];
    double value, gradient[3];
    if (capi) {
      const int st = cyc_darboux_eval(f.ctx, &D, x, &value, gradient);
      if (st != CYC_OK && bad == CYC_OK) bad = st;
    } else {
      const cyclide::Vec3d p(x[0], x[1], x[2]);
      value = core.value(p);
      const cyclide::Vec3d g = core.gradient(p);
      gradient[0] = g.x();
      gradient[1] = g.y();
      gradient[2] = g.z();
    }
    benchmark::DoNotOptimize(value);
    benchmark::DoNotOptimize(gradient);
    benchmark::ClobberMemory();
  }
  allocs.finish();
  if (bad != CYC_OK) {
    state.SkipWithError(describe("cyc_darboux_eval", bad, f.ctx).c_str());
    return;
  }
  state.SetItemsProcessed(state.iterations());
}

// cyc_surface_eval_inverted per point (a surface carried through an
// inversion, §5), to compare with BM_Eval of the same mode.
void BM_EvalInverted(benchmark::State& state, Kind kind, bool full) {
  if (!fixture_ok(state)) return;
  const Fixture& f = fixture();
  const cyc_surface* surf = f.surface(kind);
  const Pairs& P = random_pairs();
  const cyc_inversion inv = kInversion;
  double x[3], xu[3], xv[3], n[3];
  double* pdu = full ? xu : nullptr;
  double* pdv = full ? xv : nullptr;
  double* pn = full ? n : nullptr;
  benchmark::DoNotOptimize(pdu);
  std::size_t i = 0;
  int bad = CYC_OK;
  AllocCounter allocs(state);
  for (auto _ : state) {
    const double* uv = P.uv[i++ & (kPairs - 1)];
    const int st = cyc_surface_eval_inverted(f.ctx, surf, &inv, uv[0], uv[1], x, pdu, pdv, pn);
    if (st != CYC_OK && bad == CYC_OK) bad = st;
    benchmark::DoNotOptimize(x);
    benchmark::ClobberMemory();
  }
  allocs.finish();
  if (bad != CYC_OK) {
    state.SkipWithError(describe("cyc_surface_eval_inverted", bad, f.ctx).c_str());
    return;
  }
  state.SetItemsProcessed(state.iterations());
}

BENCHMARK(BM_DcmcCore);
BENCHMARK(BM_DcmcCapi);
BENCHMARK(BM_InvertDarboux);
BENCHMARK_CAPTURE(BM_DarbouxValueGradient, capi, true);
BENCHMARK_CAPTURE(BM_DarbouxValueGradient, core, false);
BENCHMARK_CAPTURE(BM_EvalInverted, prcs_point, Kind::prcs, false);
BENCHMARK_CAPTURE(BM_EvalInverted, prcs_point_du_dv_normal, Kind::prcs, true);
BENCHMARK_CAPTURE(BM_EvalInverted, prrs_point, Kind::prrs, false);
BENCHMARK_CAPTURE(BM_EvalInverted, prrs_point_du_dv_normal, Kind::prrs, true);

// ------------------------------------------------------------ lines of parabolic cyclides (§8c)

// Eq. (39) (Example 2 continued): 4z X.X - 8y^2 - 3z^2 - 6xy - z; five lines,
// one double.
constexpr cyc_darboux kEx2Cyclide = {{0, 0, 0, 4, 0, -8, -3, -6, 0, 0, 0, 0, -1, 0}};
// Eq. (61) (Example 5): z X.X + xy/2 - y^2 - 13z^2/4 - xz/2 + yz/2 + 3z/4; six lines.
constexpr cyc_darboux kEx5Cyclide = {{0, 0, 0, 1, 0, -1, -3.25, 0.5, -0.5, 0.5, 0, 0, 0.75, 0}};
// Example 5's lines (57) with mu = 1/2 applied to d3: (58).
constexpr cyc_line kEx5Lines[3] = {{{0, 0, 0}, {1, 0, 0}}, {{0, 0, 0}, {2, 1, 0}},
                                   {{1, 1, 1}, {-1, 2, 0}}};

const cyc_darboux& lines_cyclide(int which) { return which == 2 ? kEx2Cyclide : kEx5Cyclide; }

// The line and circle-family analysis through the core (one 5x5 real
// eigenproblem, up to five 3x3 symmetric ones).
void BM_ParabolicLinesCore(benchmark::State& state, int which) {
  using namespace cyclide;
  Darboux D;
  std::memcpy(D.k, lines_cyclide(which).k, sizeof D.k);
  Status bad = Status::ok;
  int lines = 0;
  AllocCounter allocs(state);
  for (auto _ : state) {
    benchmark::DoNotOptimize(D);
    ParabolicLines A;
    const Status st = parabolic_lines(D, A);
    if (st != Status::ok) bad = st;
    lines = A.line_count;
    benchmark::DoNotOptimize(A);
  }
  allocs.finish();
  if (bad != Status::ok) {
    state.SkipWithError("parabolic_lines (core) failed");
    return;
  }
  state.counters["lines"] = lines;
  state.SetItemsProcessed(state.iterations());
}

// The same through cyc_parabolic_lines.
void BM_ParabolicLinesCapi(benchmark::State& state, int which) {
  if (!fixture_ok(state)) return;
  const Fixture& f = fixture();
  cyc_darboux D = lines_cyclide(which);
  cyc_cyclide_lines A;
  int bad = CYC_OK;
  AllocCounter allocs(state);
  for (auto _ : state) {
    benchmark::DoNotOptimize(D);
    const int st = cyc_parabolic_lines(f.ctx, &D, &A);
    if (st != CYC_OK && bad == CYC_OK) bad = st;
    benchmark::DoNotOptimize(A);
    benchmark::ClobberMemory();
  }
  allocs.finish();
  if (bad != CYC_OK) {
    state.SkipWithError(describe("cyc_parabolic_lines", bad, f.ctx).c_str());
    return;
  }
  state.counters["lines"] = A.line_count;
  state.SetItemsProcessed(state.iterations());
}

// cyc_pencil_circle on Example 5's six lines, planes at 64 angles (the
// plane through l0 excluded).
void BM_PencilCircle(benchmark::State& state) {
  if (!fixture_ok(state)) return;
  const Fixture& f = fixture();
  const cyc_darboux D = kEx5Cyclide;
  cyc_cyclide_lines A;
  if (int st = cyc_parabolic_lines(f.ctx, &D, &A); st != CYC_OK || A.line_count == 0) {
    state.SkipWithError(describe("cyc_parabolic_lines", st, f.ctx).c_str());
    return;
  }
  struct Query {
    cyc_line line;
    double m[3];
  };
  std::vector<Query> q;
  for (int i = 0; i < A.line_count; ++i) {
    const cyc_cyclide_line& L = A.lines[i];
    const double* n = A.normal;
    const double* d = L.direction;
    const double k[3] = {n[1] * d[2] - n[2] * d[1], n[2] * d[0] - n[0] * d[2],
                         n[0] * d[1] - n[1] * d[0]};
    for (int a = 1; a <= 64; ++a) {
      const double th = M_PI * a / 65.0;
      Query x;
      std::memcpy(x.line.point, L.point, sizeof x.line.point);
      std::memcpy(x.line.direction, L.direction, sizeof x.line.direction);
      for (int j = 0; j < 3; ++j) x.m[j] = std::cos(th) * n[j] + std::sin(th) * k[j];
      q.push_back(x);
    }
  }
  std::size_t i = 0;
  int bad = CYC_OK;
  cyc_circle_or_line C;
  AllocCounter allocs(state);
  for (auto _ : state) {
    const Query& x = q[i++ % q.size()];
    const int st = cyc_pencil_circle(f.ctx, &D, &x.line, x.m, &C);
    if (st != CYC_OK && st != CYC_E_EMPTY_REAL_LOCUS && bad == CYC_OK) bad = st;
    benchmark::DoNotOptimize(C);
    benchmark::ClobberMemory();
  }
  allocs.finish();
  if (bad != CYC_OK) {
    state.SkipWithError(describe("cyc_pencil_circle", bad, f.ctx).c_str());
    return;
  }
  state.SetItemsProcessed(state.iterations());
}

// Seed 000 §8: DCMC on l1, l3, l4 and the member through l2, for (58).
void BM_PrrsLinesCyclide(benchmark::State& state) {
  if (!fixture_ok(state)) return;
  const Fixture& f = fixture();
  cyc_line L[3] = {kEx5Lines[0], kEx5Lines[1], kEx5Lines[2]};
  cyc_darboux D;
  double residual = 0;
  int bad = CYC_OK;
  AllocCounter allocs(state);
  for (auto _ : state) {
    benchmark::DoNotOptimize(L);
    const int st = cyc_prrs_lines_cyclide(f.ctx, L, &D, &residual);
    if (st != CYC_OK && bad == CYC_OK) bad = st;
    benchmark::DoNotOptimize(D);
    benchmark::ClobberMemory();
  }
  allocs.finish();
  if (bad != CYC_OK) {
    state.SkipWithError(describe("cyc_prrs_lines_cyclide", bad, f.ctx).c_str());
    return;
  }
  state.SetItemsProcessed(state.iterations());
}

// Props. 3 / 5: the analysis, the pencil's lines and the surface's creation
// (allocates the handle: creation tier), then cyc_surface_destroy.
void BM_ParabolicParameterize(benchmark::State& state, int kind) {
  if (!fixture_ok(state)) return;
  const Fixture& f = fixture();
  const cyc_darboux D = kind == CYC_SURFACE_PRCS ? kEx2Cyclide : kEx5Cyclide;
  int bad = CYC_OK;
  AllocCounter allocs(state);
  for (auto _ : state) {
    cyc_surface* S = nullptr;
    const int st = cyc_parabolic_parameterize(f.ctx, &D, kind, -1, 1, nullptr, &S);
    if (st != CYC_OK && bad == CYC_OK) bad = st;
    benchmark::DoNotOptimize(S);
    cyc_surface_destroy(f.ctx, S);
  }
  allocs.finish();
  if (bad != CYC_OK) {
    state.SkipWithError(describe("cyc_parabolic_parameterize", bad, f.ctx).c_str());
    return;
  }
  state.SetItemsProcessed(state.iterations());
}

BENCHMARK_CAPTURE(BM_ParabolicLinesCore, ex2_eq39, 2);
BENCHMARK_CAPTURE(BM_ParabolicLinesCore, ex5_eq61, 5);
BENCHMARK_CAPTURE(BM_ParabolicLinesCapi, ex2_eq39, 2);
BENCHMARK_CAPTURE(BM_ParabolicLinesCapi, ex5_eq61, 5);
BENCHMARK(BM_PencilCircle);
BENCHMARK(BM_PrrsLinesCyclide);
BENCHMARK_CAPTURE(BM_ParabolicParameterize, prcs_ex2_eq39, CYC_SURFACE_PRCS);
BENCHMARK_CAPTURE(BM_ParabolicParameterize, prrs_ex5_eq61, CYC_SURFACE_PRRS);

// ------------------------------------------------------------ blends (SPEC §8d)

// The Fig. 6-like cones of tests/blend_test.cpp: PRRS of three lines through
// the apex, cone 1 (apex 0, axis z) and cone 2 (apex (4, 0, 4), axis -x),
// both on [1/2, 1]; the blends join their u = 1 circles.
void cone_lines(int which, double (*P)[3], double (*D)[3]) {
  for (int k = 0; k < 3; ++k) {
    const double t = 2 * M_PI * k / 3 + 0.3, c = std::cos(t), s = std::sin(t);
    const double A0[3] = {0, 0, 0}, A1[3] = {4, 0, 4};
    const double d0[3] = {c, s, 1}, d1[3] = {-1, c, s};
    for (int j = 0; j < 3; ++j) {
      P[k][j] = which ? A1[j] : A0[j];
      D[k][j] = which ? d1[j] : d0[j];
    }
  }
}

cyclide::Surface core_cone(int which) {
  using namespace cyclide;
  double P[3][3], D[3][3];
  cone_lines(which, P, D);
  RationalCurve L[3];
  for (int k = 0; k < 3; ++k)
    make_line(Vec3d(P[k][0], P[k][1], P[k][2]), Vec3d(D[k][0], D[k][1], D[k][2]), L[k]);
  Surface S;
  make_prrs(L[0], L[1], L[2], nullptr, 0.5, 1.0, S);
  return S;
}

cyc_surface* capi_cone(cyc_context* ctx, int which) {
  double P[3][3], D[3][3];
  cone_lines(which, P, D);
  cyc_curve* L[3] = {nullptr, nullptr, nullptr};
  for (int k = 0; k < 3; ++k) cyc_curve_create_line(ctx, P[k], D[k], &L[k]);
  cyc_surface* S = nullptr;
  cyc_prrs_create(ctx, L[0], L[1], L[2], nullptr, 0.5, 1.0, &S);
  for (cyc_curve* c : L) cyc_curve_destroy(ctx, c);
  return S;
}

constexpr double kBlendV[3] = {HUGE_VAL, -0.5, 0.7};

// Core blend construction (Hermite curves from exact u-derivatives, then
// make_prrs / make_prcs with their domain checks): allocation-free.
void BM_BlendCore(benchmark::State& state, bool canal) {
  using namespace cyclide;
  const int K = int(state.range(0));
  const Surface A = core_cone(0), B = core_cone(1);
  BlendEnd s, e;
  s.surface = &A;
  e.surface = &B;
  s.u = e.u = 1.0;
  for (int j = 0; j < 3; ++j) s.v[j] = e.v[j] = kBlendV[j];
  if (canal) s.v[1] = e.v[1] = 0.3;
  Status bad = Status::ok;
  AllocCounter allocs(state);
  for (auto _ : state) {
    benchmark::DoNotOptimize(s);
    Surface X;
    const Status st = canal ? make_canal_blend(s, e, K, 0.0, 1.0, X)
                            : make_ringed_blend(s, e, K, 0.0, 1.0, X);
    if (st != Status::ok) bad = st;
    benchmark::DoNotOptimize(X);
    benchmark::ClobberMemory();
  }
  allocs.finish();
  if (bad != Status::ok) {
    state.SkipWithError("blend (core) failed on the cones");
    return;
  }
  state.SetItemsProcessed(state.iterations());
}
void BM_BlendRinged(benchmark::State& state) { BM_BlendCore(state, false); }
void BM_BlendCanal(benchmark::State& state) { BM_BlendCore(state, true); }

// cyc_blend_ringed + cyc_surface_destroy (creation tier: the handle).
void BM_BlendRingedCapi(benchmark::State& state) {
  if (!fixture_ok(state)) return;
  const Fixture& f = fixture();
  const int K = int(state.range(0));
  cyc_surface* A = capi_cone(f.ctx, 0);
  cyc_surface* B = capi_cone(f.ctx, 1);
  cyc_blend_end s{A, 1.0, {kBlendV[0], kBlendV[1], kBlendV[2]}, 0.0, {}};
  cyc_blend_end e{B, 1.0, {kBlendV[0], kBlendV[1], kBlendV[2]}, 0.0, {}};
  int bad = (A && B) ? CYC_OK : CYC_E_INVALID_ARGUMENT;
  AllocCounter allocs(state);
  for (auto _ : state) {
    cyc_surface* X = nullptr;
    const int st = cyc_blend_ringed(f.ctx, &s, &e, K, 0.0, 1.0, &X);
    if (st != CYC_OK && bad == CYC_OK) bad = st;
    benchmark::DoNotOptimize(X);
    cyc_surface_destroy(f.ctx, X);
  }
  allocs.finish();
  cyc_surface_destroy(f.ctx, A);
  cyc_surface_destroy(f.ctx, B);
  if (bad != CYC_OK) {
    state.SkipWithError(describe("cyc_blend_ringed", bad, f.ctx).c_str());
    return;
  }
  state.SetItemsProcessed(state.iterations());
}

// cyc_surface_derivatives_u on cone 1 at 64 (u, v) pairs.
void BM_DerivativesU(benchmark::State& state) {
  if (!fixture_ok(state)) return;
  const Fixture& f = fixture();
  const int K = int(state.range(0));
  cyc_surface* A = capi_cone(f.ctx, 0);
  double out[3 * (CYC_MAX_BLEND_ORDER + 1)];
  int bad = A ? CYC_OK : CYC_E_INVALID_ARGUMENT;
  std::size_t i = 0;
  AllocCounter allocs(state);
  for (auto _ : state) {
    const double u = 0.5 + (i % 8) / 16.0, v = std::tan(M_PI * ((i / 8) % 8 + 0.5) / 8 - M_PI / 2);
    ++i;
    const int st = cyc_surface_derivatives_u(f.ctx, A, u, v, K, out);
    if (st != CYC_OK && bad == CYC_OK) bad = st;
    benchmark::DoNotOptimize(out);
    benchmark::ClobberMemory();
  }
  allocs.finish();
  cyc_surface_destroy(f.ctx, A);
  if (bad != CYC_OK) {
    state.SkipWithError(describe("cyc_surface_derivatives_u", bad, f.ctx).c_str());
    return;
  }
  state.SetItemsProcessed(state.iterations());
}

// cyc_continuity_report of the join of cone 1 (u = 1) and its C^2 ringed
// blend (t = 0): K = 2, 16 samples spread over the circle.
void BM_ContinuityReport(benchmark::State& state) {
  if (!fixture_ok(state)) return;
  const Fixture& f = fixture();
  cyc_surface* A = capi_cone(f.ctx, 0);
  cyc_surface* B = capi_cone(f.ctx, 1);
  cyc_blend_end s{A, 1.0, {kBlendV[0], kBlendV[1], kBlendV[2]}, 0.0, {}};
  cyc_blend_end e{B, 1.0, {kBlendV[0], kBlendV[1], kBlendV[2]}, 0.0, {}};
  cyc_surface* X = nullptr;
  int bad = cyc_blend_ringed(f.ctx, &s, &e, 2, 0.0, 1.0, &X);
  cyc_continuity R;
  AllocCounter allocs(state);
  for (auto _ : state) {
    if (bad != CYC_OK) break;
    const int st = cyc_continuity_report(f.ctx, A, 1.0, 1.0, X, 0.0, 2, nullptr, 16, &R);
    if (st != CYC_OK && bad == CYC_OK) bad = st;
    benchmark::DoNotOptimize(R);
    benchmark::ClobberMemory();
  }
  allocs.finish();
  cyc_surface_destroy(f.ctx, X);
  cyc_surface_destroy(f.ctx, A);
  cyc_surface_destroy(f.ctx, B);
  if (bad != CYC_OK) {
    state.SkipWithError(describe("cyc_continuity_report", bad, f.ctx).c_str());
    return;
  }
  state.SetItemsProcessed(state.iterations() * 16);
}

// ------------------------------------------------------------ blend optimizer (SPEC §8e)

// cyc_optimize_blend on the cones' blend (K = state.range(0)) with the
// default objective and options (8 x 4 quadrature, up to 50
// Levenberg-Marquardt iterations), then cyc_surface_destroy. Every solve is
// the same (deterministic), so the last summary gives the counters:
// "iterations" (Ceres', all rounds), "cost_reduction" (initial / final
// cost), "initial_cost" and "final_cost".
// points: the chosen points' circle parameters free too (circle_parameter_range
// 1.5, seed 000 §9.1 (i)): 10 (ringed) or 8 (canal) unknowns at K = 2.
void BM_OptimizeBlend(benchmark::State& state, int kind, bool points) {
  if (!cyc_optimizer_available()) {
    state.SkipWithError("no optimizer tier in this build (Ceres not found)");
    return;
  }
  if (!fixture_ok(state)) return;
  const Fixture& f = fixture();
  const int K = int(state.range(0));
  cyc_surface* A = capi_cone(f.ctx, 0);
  cyc_surface* B = capi_cone(f.ctx, 1);
  cyc_blend_end s{A, 1.0, {kBlendV[0], kBlendV[1], kBlendV[2]}, 0.0, {}};
  cyc_blend_end e{B, 1.0, {kBlendV[0], kBlendV[1], kBlendV[2]}, 0.0, {}};
  if (kind == CYC_BLEND_CANAL) s.v[1] = e.v[1] = 0.3;  // as BM_BlendCanal
  cyc_optimize_summary sum{};
  cyc_optimize_options options;
  cyc_optimize_options_init(&options);
  if (points) options.circle_parameter_range = 1.5;
  int bad = (A && B) ? CYC_OK : CYC_E_INVALID_ARGUMENT;
  AllocCounter allocs(state);
  for (auto _ : state) {
    cyc_surface* X = nullptr;
    const int st = cyc_optimize_blend(f.ctx, kind, &s, &e, K, 0.0, 1.0, nullptr, &options, &X,
                                      nullptr, nullptr, &sum);
    if (st != CYC_OK && bad == CYC_OK) bad = st;
    benchmark::DoNotOptimize(X);
    cyc_surface_destroy(f.ctx, X);
  }
  allocs.finish();
  cyc_surface_destroy(f.ctx, A);
  cyc_surface_destroy(f.ctx, B);
  if (bad != CYC_OK) {
    state.SkipWithError(describe("cyc_optimize_blend", bad, f.ctx).c_str());
    return;
  }
  state.counters["iterations"] = sum.iterations;
  state.counters["cost_reduction"] = sum.final_cost > 0 ? sum.initial_cost / sum.final_cost : 0;
  state.counters["initial_cost"] = sum.initial_cost;
  state.counters["final_cost"] = sum.final_cost;
  state.SetItemsProcessed(state.iterations());
}

// Seed 001 §6: the 3-way blend of Example 6.2 (ends (68) as normal ringed
// surfaces, sphere (69), lambda_i = 0.19 so that the joining circles are
// disjoint; degree-6 blends) in the core: the sphere, the circle test and
// three make_ringed_pcurve_blend calls per iteration. Allocation-free.
void BM_NwayBlend(benchmark::State& state) {
  using namespace cyclide;
  auto normal_ringed = [](const double* dc, const CurvePoly& rho, Surface& S) {
    double nc[9];
    for (int k = 0; k < 9; ++k) nc[k] = (k / 3 + 1) * dc[k + 3];
    RationalCurve d, n;
    if (make_polynomial_curve(3, dc, d) != Status::ok ||
        make_polynomial_curve(2, nc, n) != Status::ok)
      return false;
    // The automatic field, else Example 3.3's (R_3's projection along e3
    // has sigma = |6t^2 - 10t|, zero at t = 0).
    RingedFieldOptions fo;
    if (make_ringed_dnr(d, n, rho, CurvePoly(1.0), fo, nullptr, 0.0, 1.0, S) == Status::ok)
      return true;
    fo.method = RingedFieldMethod::quadratic;
    for (fo.which = 0; fo.which < 2; ++fo.which)
      if (make_ringed_dnr(d, n, rho, CurvePoly(1.0), fo, nullptr, 0.0, 1.0, S) == Status::ok)
        return true;
    return false;
  };
  const double d1[12] = {-9, -7, 0, 12, 4, 0, -23, 0, 0, 14, 0, 0};
  const double d2[12] = {6, -8, 0, 4, 4, 0, 0, 3, 0, -4, -2, 0};
  const double d3[12] = {0, 8, -8, 0, 0, 4, 0, -5, -3, 0, 2, 2};
  const double r1[2] = {4.0 / 6, 1.0 / 6}, r2[3] = {1, 0, -0.5}, r3[2] = {9.0 / 6, -4.0 / 6};
  CurvePoly p1, p2, p3;
  p1.assign(r1, 1);
  p2.assign(r2, 2);
  p3.assign(r3, 1);
  static Surface R[3];
  if (!normal_ringed(d1, p1, R[0]) || !normal_ringed(d2, p2, R[1]) ||
      !normal_ringed(d3, p3, R[2])) {
    state.SkipWithError("Example 6.2's ends not built");
    return;
  }
  const Surface* ends[3] = {&R[0], &R[1], &R[2]};
  const double u[3] = {1, 1, 1};
  NwayOptions o;
  o.center = NwayCenter::given;
  o.s = Vec3d(0.5, 0.3, -0.25);
  o.r = 2.6;
  for (double& l : o.lambda) l = 0.19;
  static Surface B[kMaxNwayEnds][2];
  int count[kMaxNwayEnds] = {};
  Status bad = Status::ok;
  AllocCounter allocs(state);
  for (auto _ : state) {
    const Status st = make_ringed_nway_blend(ends, u, 3, o, B, count);
    if (st != Status::ok) bad = st;
    benchmark::DoNotOptimize(B);
  }
  allocs.finish();
  if (bad != Status::ok) {
    state.SkipWithError(status_name(bad));
    return;
  }
  state.SetItemsProcessed(state.iterations());
}

// Seed 001 §7.a, Example 7.6 (lambda 1/2, n 2): one implicit-blend
// approximation through the C API (contour points, branch tracing, the
// Ceres solve of Omega, the degree-15 directrix, make_ringed and the (87)
// quadrature) with `pieces` = range(0) (1: one piece; 2: refinement (84)).
void BM_ImplicitBlendApprox(benchmark::State& state) {
  if (!cyc_optimizer_available()) {
    state.SkipWithError("no optimizer tier in this build (Ceres not found)");
    return;
  }
  if (!fixture_ok(state)) return;
  const Fixture& f = fixture();
  cyc_implicit_blend B{{0, 1, 1, 0, 0, 0, 0, 0, 0, -9},
                       {1, 1, 2, -2, 0, 0, -12, 12, 0, 28},
                       {1, 0, 0, 0},
                       {1, 1, 0, -10},
                       0.5,
                       2};
  const double v[9] = {0, 0, 1, 0, 1, 0, 0, 0.70710678118654752, 0.70710678118654752};
  cyc_implicit_approx_options o;
  cyc_implicit_approx_options_init(&o);
  o.pieces = int(state.range(0));
  cyc_implicit_approx_report rep{};
  int bad = CYC_OK;
  AllocCounter allocs(state);
  for (auto _ : state) {
    cyc_surface* S[CYC_MAX_IMPLICIT_PIECES] = {};
    int count = 0;
    const int st = cyc_optimize_implicit_blend(f.ctx, &B, v, &o, S, &count, &rep);
    if (st != CYC_OK && bad == CYC_OK) bad = st;
    benchmark::DoNotOptimize(S);
    for (int k = 0; k < count; ++k) cyc_surface_destroy(f.ctx, S[k]);
  }
  allocs.finish();
  if (bad != CYC_OK) {
    state.SkipWithError(describe("cyc_optimize_implicit_blend", bad, f.ctx).c_str());
    return;
  }
  state.counters["error87"] = rep.error87;
  state.counters["omega"] = rep.omega;
  state.SetItemsProcessed(state.iterations());
}

BENCHMARK(BM_BlendRinged)->Arg(1)->Arg(2)->Arg(3);
BENCHMARK(BM_NwayBlend);
BENCHMARK(BM_BlendCanal)->Arg(2)->Arg(3);
BENCHMARK(BM_BlendRingedCapi)->Arg(2);
BENCHMARK(BM_DerivativesU)->Arg(1)->Arg(2)->Arg(3);
BENCHMARK(BM_ContinuityReport);
BENCHMARK_CAPTURE(BM_OptimizeBlend, ringed, CYC_BLEND_RINGED, false)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_OptimizeBlend, canal, CYC_BLEND_CANAL, false)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_OptimizeBlend, ringed_points, CYC_BLEND_RINGED, true)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_OptimizeBlend, canal_points, CYC_BLEND_CANAL, true)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ImplicitBlendApprox)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

}  // namespace
