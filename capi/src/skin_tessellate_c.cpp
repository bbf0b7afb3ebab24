// C ABI of the sphere skins' adaptive tessellation (issue 9, SPEC.md
// §8j.2a; skin_tessellate.hpp). Allocation-free: the caller provides the
// rows, the scratch and the mesh buffers. The skin handle and its patches
// are struct cyc_sphere_skin of capi_internal.hpp.
#include <cmath>
#include <cstdint>

#include "capi_internal.hpp"
#include "tessellation_internal.hpp"
#include "cyclide/skin_tessellate.hpp"

using namespace cyclide;
using namespace cyclide::capi;

namespace {

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
