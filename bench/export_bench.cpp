// Benchmarks of issue 9 (SPEC.md §8j) through the C ABI: the exact rational
// Bezier export of a typical blend (the C^1 ringed blend of seed 000 Fig. 6
// between two cones, whole circles), and the adaptive tessellation of the
// same blend to a chordal tolerance of 1e-4 (plan, and plan + mesh).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "cyclide/cyclide.h"

namespace {

// The cone with apex A whose rulings through A make 45 degrees with e3
// (three lines, PRRS), as in the demo's Fig. 6 scene.
cyc_surface* cone(cyc_context* ctx, const double A[3], const double e1[3], const double e2[3],
                  const double e3[3]) {
  cyc_curve* L[3];
  for (int k = 0; k < 3; ++k) {
    const double t = 2 * 3.14159265358979323846 * k / 3 + 0.3;
    double d[3];
    for (int j = 0; j < 3; ++j) d[j] = std::cos(t) * e1[j] + std::sin(t) * e2[j] + e3[j];
    cyc_curve_create_line(ctx, A, d, &L[k]);
  }
  cyc_surface* S = nullptr;
  cyc_prrs_create(ctx, L[0], L[1], L[2], nullptr, 0.5, 1.0, &S);
  for (cyc_curve* l : L) cyc_curve_destroy(ctx, l);
  return S;
}

// Seed 000 Fig. 6: the C^1 ringed blend of cone A (apex 0, axis z) and
// cone B (apex (4, 0, 4), axis -x) at their circles u = 1.
struct Blend {
  cyc_context* ctx = nullptr;
  cyc_surface *a = nullptr, *b = nullptr, *blend = nullptr;
  Blend() {
    cyc_context_create(nullptr, &ctx);
    const double O[3] = {0, 0, 0}, A2[3] = {4, 0, 4}, X[3] = {1, 0, 0}, Y[3] = {0, 1, 0},
                 Z[3] = {0, 0, 1}, MX[3] = {-1, 0, 0};
    a = cone(ctx, O, X, Y, Z);
    b = cone(ctx, A2, Y, Z, MX);
    cyc_blend_end s, e;
    std::memset(&s, 0, sizeof s);
    s.surface = a;
    s.u = 1.0;
    s.v[0] = HUGE_VAL;
    s.v[1] = -0.5;
    s.v[2] = 0.7;
    e = s;
    e.surface = b;
    cyc_blend_ringed(ctx, &s, &e, 1, 0.0, 1.0, &blend);
  }
  ~Blend() {
    cyc_surface_destroy(ctx, blend);
    cyc_surface_destroy(ctx, a);
    cyc_surface_destroy(ctx, b);
    cyc_context_destroy(ctx);
  }
};

void BM_ExportBlendWholeCircles(benchmark::State& state) {
  Blend B;
  if (!B.blend) {
    state.SkipWithError("blend construction failed");
    return;
  }
  const cyc_export_domain D{0.0, 1.0, 0, 0, 1};
  int patches = 0, degree = 0;
  for (auto _ : state) {
    cyc_bezier_export* e = nullptr;
    if (cyc_bezier_export_create(B.ctx, B.blend, &D, &e) != CYC_OK) {
      state.SkipWithError(cyc_context_last_error(B.ctx));
      return;
    }
    patches = cyc_bezier_export_count(e);
    cyc_bezier_patch_info info;
    cyc_bezier_export_patch(B.ctx, e, 0, &info, nullptr, 0);
    degree = info.deg_u;
    cyc_bezier_export_destroy(e);
  }
  state.counters["patches"] = patches;
  state.counters["deg_u"] = degree;
}

void tessellate(benchmark::State& state, bool with_mesh) {
  Blend B;
  if (!B.blend) {
    state.SkipWithError("blend construction failed");
    return;
  }
  cyc_tessellation_options o;
  cyc_tessellation_options_default(&o);
  o.chordal_tolerance = 1e-4;
  o.max_segments = 4096;
  std::vector<unsigned char> work(cyc_tessellation_workspace_size(o.max_segments));
  std::vector<double> us(1 << 16);
  std::vector<double> pts, nrm;
  cyc_tessellation_plan plan{};
  for (auto _ : state) {
    if (cyc_tessellate_plan(B.ctx, B.blend, &o, us.data(), int(us.size()), work.data(),
                            work.size(), &plan) != CYC_OK) {
      state.SkipWithError(cyc_context_last_error(B.ctx));
      return;
    }
    if (!with_mesh) continue;
    const size_t n = size_t(plan.rows) * plan.segments;
    if (pts.size() < 3 * n) pts.resize(3 * n), nrm.resize(3 * n);
    cyc_tessellate_eval(B.ctx, B.blend, &plan, us.data(), cyc_buffer3{pts.data(), n, 3},
                        cyc_buffer3{nrm.data(), n, 3}, nullptr);
    benchmark::DoNotOptimize(pts.data());
  }
  state.counters["rows"] = plan.rows;
  state.counters["segments"] = plan.segments;
  state.counters["triangles"] = 2.0 * (plan.rows - 1) * plan.segments;
}

void BM_TessellatePlanBlend1e4(benchmark::State& state) { tessellate(state, false); }
void BM_TessellateBlend1e4(benchmark::State& state) { tessellate(state, true); }

// A sphere skin (seed 002, the skew skin of the tests: spheres of radii 1
// and 1.2, a curved spine, the RMF pairing) planned and meshed to a chordal
// tolerance of 1e-4 (SPEC.md §8j.2a).
// The skew skin of tests/sphere_skin_test.cpp (null on failure, with the
// context's message).
cyc_sphere_skin* skew_skin(cyc_context* ctx) {
  cyc_skin_end ends[2];
  const double ax[3] = {1.0 / std::sqrt(2.0), 0.6 / std::sqrt(2.0), 0.8 / std::sqrt(2.0)};
  const double m0[3] = {0, 0, 0}, p0[3] = {0.3, 0, 0}, t0[3] = {3, 0, 0};
  const double m1[3] = {4, 1, 0.5};
  const double p1[3] = {4 - 0.4 * ax[0], 1 - 0.4 * ax[1], 0.5 - 0.4 * ax[2]};
  const double t1[3] = {3 * ax[0], 3 * ax[1], 3 * ax[2]};
  cyc_sphere_skin* skin = nullptr;
  if (cyc_skin_end_from_sphere(ctx, m0, 1.0, p0, t0, &ends[0]) != CYC_OK ||
      cyc_skin_end_from_sphere(ctx, m1, 1.2, p1, t1, &ends[1]) != CYC_OK ||
      cyc_sphere_skin_create(ctx, &ends[0], &ends[1], nullptr, &skin) != CYC_OK)
    return nullptr;
  return skin;
}

// The export of the skew skin over whole circles at the default tolerance
// 1e-9 (SPEC 8j.1b): patches of degree (10, 4).
void BM_SkinExport(benchmark::State& state) {
  cyc_context* ctx = nullptr;
  cyc_context_create(nullptr, &ctx);
  cyc_sphere_skin* skin = skew_skin(ctx);
  if (!skin) {
    state.SkipWithError(cyc_context_last_error(ctx));
    cyc_context_destroy(ctx);
    return;
  }
  const cyc_export_domain whole = {0, 1, 0, 0, 1};
  cyc_skin_export_report r{};
  for (auto _ : state) {
    cyc_bezier_export* e = nullptr;
    if (cyc_sphere_skin_export_create(ctx, skin, &whole, nullptr, &e, &r) != CYC_OK) {
      state.SkipWithError(cyc_context_last_error(ctx));
      break;
    }
    benchmark::DoNotOptimize(e);
    cyc_bezier_export_destroy(e);
  }
  state.counters["t_intervals"] = r.t_intervals;
  state.counters["error"] = r.error_estimate;
  cyc_sphere_skin_destroy(ctx, skin);
  cyc_context_destroy(ctx);
}

void BM_SkinTessellate(benchmark::State& state) {
  cyc_context* ctx = nullptr;
  cyc_context_create(nullptr, &ctx);
  cyc_sphere_skin* skin = skew_skin(ctx);
  if (!skin) {
    state.SkipWithError(cyc_context_last_error(ctx));
    cyc_context_destroy(ctx);
    return;
  }
  cyc_tessellation_options o;
  cyc_tessellation_options_default(&o);
  o.chordal_tolerance = 1e-4;
  std::vector<double> work(cyc_sphere_skin_tessellation_workspace_size(o.max_segments) /
                           sizeof(double));
  std::vector<double> ts(1 << 16), pts, nrm;
  cyc_tessellation_plan plan{};
  for (auto _ : state) {
    if (cyc_sphere_skin_tessellate_plan(ctx, skin, 0, &o, ts.data(), int(ts.size()), work.data(),
                                        work.size() * sizeof(double), &plan) != CYC_OK) {
      state.SkipWithError(cyc_context_last_error(ctx));
      break;
    }
    const size_t n = size_t(plan.rows) * plan.segments;
    if (pts.size() < 3 * n) pts.resize(3 * n), nrm.resize(3 * n);
    cyc_sphere_skin_tessellate_eval(ctx, skin, 0, &plan, ts.data(), cyc_buffer3{pts.data(), n, 3},
                                    cyc_buffer3{nrm.data(), n, 3}, nullptr);
    benchmark::DoNotOptimize(pts.data());
  }
  state.counters["rows"] = plan.rows;
  state.counters["segments"] = plan.segments;
  state.counters["triangles"] = 2.0 * (plan.rows - 1) * plan.segments;
  cyc_sphere_skin_destroy(ctx, skin);
  cyc_context_destroy(ctx);
}

}  // namespace

BENCHMARK(BM_ExportBlendWholeCircles)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TessellatePlanBlend1e4)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TessellateBlend1e4)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SkinTessellate)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SkinExport)->Unit(benchmark::kMillisecond);
