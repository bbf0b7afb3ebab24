// Benchmarks of seed 001 (ringed surfaces (d, n, rho), issue 5): planar
// P-curve Hermite interpolation (43) and P-biarcs (47), the two-surface
// blend of §4 (Example 4.1), the rational fields (20)-(23) and Theorem 3.6
// (rho = sqrt(R), the canal case (24)), and one constrained-blend
// optimization (Example 5.2 through the C API's optimizer tier).
#include <benchmark/benchmark.h>

#include "../tests/seed001_data.hpp"
#include "cyclide/cyclide.h"
#include "cyclide/pcurve.hpp"

using namespace cyclide;

namespace {

// Example 4.1's planar data (39): p0 = 1 + i, v0 = i, p1 = 4, v1 = i.
const Complex p0(1, 1), v0(0, 1), p1(4, 0), v1(0, 1);

void BM_PlanarPCurveHermite(benchmark::State& state) {
  PlanarPCurve P;
  for (auto _ : state) {
    benchmark::DoNotOptimize(planar_pcurve_hermite(p0, v0, p1, v1, 1, P));
    benchmark::DoNotOptimize(P);
  }
}

void BM_PlanarPBiarc(benchmark::State& state) {
  PlanarPCurve P[2];
  for (auto _ : state) {
    benchmark::DoNotOptimize(planar_pbiarc(p0, v0, p1, v1, 0.5, 1, P));
    benchmark::DoNotOptimize(P);
  }
}

// Example 4.1's ends (the transcription's derived Hermite data (37)).
void example41(RingedJet& a, RingedJet& b) {
  a.d = Vec3d(-4, -3, 1), a.dd = Vec3d(2, 4, 3), a.rho = 1.25, a.drho = 0.5;
  a.n = Vec3d(1, 1, 1), a.dn = Vec3d(0, 1, 1);
  b.d = Vec3d(0, 0, 0), b.dd = Vec3d(3, 1, 1), b.rho = 2, b.drho = 1;
  b.n = Vec3d(4, 0, 0), b.dn = Vec3d(0, 1, 1);
}

// The whole blend construction: Ferguson cubics, the P-curve, f, c and the
// surface with its domain scan. Arg: 0 = degree 6 (43), 1 = P-biarc (47).
void BM_RingedPCurveBlend(benchmark::State& state) {
  RingedJet a, b;
  example41(a, b);
  RingedBlendOptions o;
  o.tau = state.range(0) ? 0.5 : 0.0;
  Surface P[2];
  int count = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(make_ringed_pcurve_blend(a, b, o, P, count));
    benchmark::DoNotOptimize(P);
  }
}

// Eqs. (20)-(23) for a cubic n (numerical SOS of |n|^2, degree 6).
void BM_SosField(benchmark::State& state) {
  RationalCurve n;
  const double nc[12] = {1, -2, 0.5, 0, 1, 3, 2, 0, -1, 0.5, 1, 0.25};
  make_polynomial_curve(3, nc, n);
  RationalField f;
  for (auto _ : state) {
    benchmark::DoNotOptimize(sos_field(n, f));
    benchmark::DoNotOptimize(f);
  }
}

CurvePoly poly(std::initializer_list<double> c) {
  CurvePoly p;
  p.assign(c.begin(), int(c.size()) - 1);
  return p;
}

// Theorem 3.6 on the canal surface (24) of m = (t, t^2, t^3), r = 1 + t/5:
// R = r^2 (|m'|^2 - r'^2) / |m'|^2, the reduced conic of degree 8.
void BM_RingedSqrtField(benchmark::State& state) {
  RationalCurve n;
  const double nc[9] = {1, 0, 0, 0, 2, 0, 0, 0, 3};
  make_polynomial_curve(2, nc, n);
  const CurvePoly N = poly({1, 0, 4, 0, 9});
  CurvePoly r2, R_num;
  multiply(poly({1, 0.2}), poly({1, 0.2}), r2);
  multiply(r2, N - CurvePoly(0.04), R_num);
  RationalField f;
  RingedSqrtReport rep;
  for (auto _ : state) {
    benchmark::DoNotOptimize(sqrt_radius_field(n, R_num, N, RingedFieldOptions(), f, &rep));
    benchmark::DoNotOptimize(f);
  }
  state.counters["residual"] = rep.residual;
}

// §5.a: Example 5.2's blend made "more normal" by the Ceres bump optimizer
// (w and tau free, the C API's optimizer tier).
void BM_OptimizePCurveBump(benchmark::State& state) {
  RingedJet J1, J2;
  cyclide_test::example52_ends(J1, J2);
  auto to_c = [](const RingedJet& J) {
    cyc_ringed_jet c;
    for (int j = 0; j < 3; ++j) {
      c.d[j] = J.d[j], c.dd[j] = J.dd[j], c.n[j] = J.n[j], c.dn[j] = J.dn[j];
    }
    c.rho = J.rho, c.drho = J.drho;
    return c;
  };
  const cyc_ringed_jet a = to_c(J1), b = to_c(J2);
  cyc_context* ctx = nullptr;
  if (cyc_context_create(nullptr, &ctx) != CYC_OK) {
    state.SkipWithError("cyc_context_create failed");
    return;
  }
  cyc_bump_objective obj;
  cyc_bump_objective_init(&obj);
  cyc_bump_options opt;
  cyc_bump_options_init(&opt);
  cyc_optimize_summary sum{};
  for (auto _ : state) {
    cyc_surface* pieces[2] = {nullptr, nullptr};
    int count = 0;
    cyc_directrix_bump chosen;
    const int st = cyc_optimize_pcurve_bump(ctx, &a, &b, nullptr, nullptr, &obj, &opt, pieces,
                                            &count, &chosen, &sum);
    if (st != CYC_OK) {
      state.SkipWithError(cyc_status_name(st));
      break;
    }
    for (int k = 0; k < count; ++k) cyc_surface_destroy(ctx, pieces[k]);
  }
  state.counters["iterations"] = sum.iterations;
  state.counters["final_cost"] = sum.final_cost;
  cyc_context_destroy(ctx);
}

}  // namespace

BENCHMARK(BM_PlanarPCurveHermite);
BENCHMARK(BM_PlanarPBiarc);
BENCHMARK(BM_RingedPCurveBlend)->Arg(0)->Arg(1);
BENCHMARK(BM_SosField);
BENCHMARK(BM_RingedSqrtField);
BENCHMARK(BM_OptimizePCurveBump)->Unit(benchmark::kMillisecond);
