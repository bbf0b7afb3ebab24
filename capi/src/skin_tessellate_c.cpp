// C ABI of the sphere skins' adaptive tessellation (issue 9, SPEC.md
// §8j.2a; skin_tessellate.hpp). Allocation-free: the caller provides the
// rows, the scratch and the mesh buffers. The skin handle and its patches
// are struct cyc_sphere_skin of capi_internal.hpp.
#include <cmath>
#include <cstdint>

#include "capi_internal.hpp"
#include "cyclide/skin_tessellate.hpp"

using namespace cyclide;
using namespace cyclide::capi;

namespace {

// The checks of cyc_tessellate_plan's options (export_c.cpp), same messages:
// every field named, counts compared with their bounds as 64-bit integers.
Outcome check_options(const char* fn, const cyc_tessellation_options& o) {
  TRY(check_double(fn, "options.chordal_tolerance", o.chordal_tolerance));
  if (!(o.chordal_tolerance > 0))
    return fail(CYC_E_INVALID_ARGUMENT,
                "%s: options.chordal_tolerance = %.17g is not positive (a distance in model "
                "units)",
                fn, o.chordal_tolerance);
  TRY(check_range(fn, "options.min_segments", o.min_segments, 3, CYC_MAX_CIRCLE_SEGMENTS));
  TRY(check_range(fn, "options.max_segments", o.max_segments, o.min_segments,
                  CYC_MAX_CIRCLE_SEGMENTS));
  if (o.fixed_segments != 0)
    TRY(check_range(fn, "options.fixed_segments", o.fixed_segments, 3, CYC_MAX_CIRCLE_SEGMENTS));
  TRY(check_range(fn, "options.initial_rows", o.initial_rows, 2, 1 << 16));
  if (o.reference_u0) TRY(check_doubles(fn, "options.reference_u0", o.reference_u0, 3));
  if (o.reference_u1) TRY(check_doubles(fn, "options.reference_u1", o.reference_u1, 3));
  return ok();
}

// A plan handed back to the evaluator: its sizes and phases.
Outcome check_plan(const char* fn, const cyc_tessellation_plan& plan) {
  TRY(check_range(fn, "plan.rows", plan.rows, 2, INT32_MAX));
  TRY(check_range(fn, "plan.segments", plan.segments, 3, CYC_MAX_CIRCLE_SEGMENTS));
  TRY(check_double(fn, "plan.phase0", plan.phase0));
  return check_double(fn, "plan.phase1", plan.phase1);
}

TessellationOptions core_options(const cyc_tessellation_options& o) {
  TessellationOptions t;
  t.chordal_tolerance = o.chordal_tolerance;
  t.min_segments = o.min_segments;
  t.max_segments = o.max_segments;
  t.fixed_segments = o.fixed_segments;
  t.initial_rows = o.initial_rows;
  t.reference_u0 = o.reference_u0;
  t.reference_u1 = o.reference_u1;
  return t;
}

Outcome check_patch(const char* fn, const cyc_sphere_skin* skin, int patch) {
  if (patch < 0 || patch >= skin->count)
    return fail(CYC_E_INVALID_ARGUMENT, "%s: patch = %d is outside 0..%d", fn, patch,
                skin->count - 1);
  return ok();
}

}  // namespace

size_t cyc_sphere_skin_tessellation_workspace_size(int segments) {
  return skin_tessellation_workspace_size(segments) * sizeof(double);
}

int cyc_sphere_skin_tessellate_plan(cyc_context* ctx, const cyc_sphere_skin* skin, int patch,
                                    const cyc_tessellation_options* options, double* ts,
                                    int row_cap, void* work, size_t work_bytes,
                                    cyc_tessellation_plan* plan) {
  const char* fn = "cyc_sphere_skin_tessellate_plan";
  return run(ctx, fn, [&] {
    REQUIRE(skin);
    REQUIRE(options);
    REQUIRE(ts);
    REQUIRE(work);
    REQUIRE(plan);
    if (Outcome o = check_patch(fn, skin, patch); o.status) return o;
    TRY(check_range(fn, "row_cap", row_cap, 2, INT32_MAX));
    TRY(check_options(fn, *options));
    if (reinterpret_cast<std::uintptr_t>(work) % alignof(double) != 0)
      return fail(CYC_E_INVALID_ARGUMENT, "%s: work is not 8-byte aligned", fn);
    const int n_max = options->fixed_segments > 0 ? options->fixed_segments : options->max_segments;
    const size_t need = cyc_sphere_skin_tessellation_workspace_size(n_max);
    if (work_bytes < need)
      return fail(CYC_E_BUFFER_TOO_SMALL, "%s: work holds %zu bytes, %zu needed", fn, work_bytes,
                  need);
    TessellationPlan P;
    SkinTessellationReport R;
    const Status s = skin_tessellation_plan(skin->patches[patch], core_options(*options), ts,
                                            row_cap, static_cast<double*>(work),
                                            work_bytes / sizeof(double), P, &R);
    if (s == Status::buffer_too_small)
      return fail(CYC_E_BUFFER_TOO_SMALL,
                  "%s: more than row_cap = %d rows are needed for chordal tolerance %.3g", fn,
                  row_cap, options->chordal_tolerance);
    if (s == Status::invalid_argument)
      return fail(CYC_E_INVALID_ARGUMENT,
                  "%s: a reference vector lies along the spine's tangent at an end circle", fn);
    if (s != Status::ok) return from_core(fn, s);
    plan->rows = P.rows;
    plan->segments = P.segments;
    plan->phase0 = P.phase0;
    plan->phase1 = P.phase1;
    plan->max_radius = P.max_radius;
    plan->depth_limited = (P.depth_limited ? 1 : 0) | (R.segment_limited ? 2 : 0);
    return ok();
  });
}

int cyc_sphere_skin_tessellate_eval(cyc_context* ctx, const cyc_sphere_skin* skin, int patch,
                                    const cyc_tessellation_plan* plan, const double* ts,
                                    cyc_buffer3 points, cyc_buffer3 normals, size_t* singular) {
  const char* fn = "cyc_sphere_skin_tessellate_eval";
  return run(ctx, fn, [&] {
    REQUIRE(skin);
    REQUIRE(plan);
    REQUIRE(ts);
    if (Outcome o = check_patch(fn, skin, patch); o.status) return o;
    TRY(check_plan(fn, *plan));
    // The buffers first: rows * segments (both bounded above, no overflow in
    // size_t) before the rows' parameters are read.
    const size_t count = size_t(plan->rows) * size_t(plan->segments);
    if (Outcome o = check_buffer(fn, "points", points, count); o.status) return o;
    if (Outcome o = check_buffer(fn, "normals", normals, count); o.status) return o;
    TRY(check_doubles(fn, "ts", ts, size_t(plan->rows)));
    for (int i = 0; i < plan->rows; ++i)
      if (!(ts[i] >= 0.0 && ts[i] <= 1.0))
        return fail(CYC_E_BAD_DOMAIN,
                    "%s: ts[%d] = %.17g is outside [0, 1]", fn, i, ts[i]);
    TessellationPlan P;
    P.rows = plan->rows;
    P.segments = plan->segments;
    P.phase0 = plan->phase0;
    P.phase1 = plan->phase1;
    const Status s = skin_tessellation_eval(skin->patches[patch], P, ts,
                                            Strided3{points.data, points.stride},
                                            Strided3{normals.data, normals.stride}, singular);
    return s == Status::ok ? ok() : from_core(fn, s);
  });
}
