// The tessellation options and plans of the C ABI, shared by the two
// planners: circle-family surfaces (export_c.cpp) and sphere skins
// (skin_tessellate_c.cpp), so both check and convert them the same way.
#pragma once

#include "capi_internal.hpp"
#include "cyclide/tessellate.hpp"

namespace cyclide {
namespace capi {

// The caller's options as the core's (validated by check_options first).
inline TessellationOptions core_options(const cyc_tessellation_options& o) {
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

// The options, every field named. Counts are compared with their bounds as
// 64-bit integers before any arithmetic.
inline Outcome check_options(const char* fn, const cyc_tessellation_options& o) {
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

// A plan handed back to an evaluator: its sizes and phases.
inline Outcome check_plan(const char* fn, const cyc_tessellation_plan& plan) {
  TRY(check_range(fn, "plan.rows", plan.rows, 2, INT32_MAX));
  TRY(check_range(fn, "plan.segments", plan.segments, 3, CYC_MAX_CIRCLE_SEGMENTS));
  TRY(check_double(fn, "plan.phase0", plan.phase0));
  return check_double(fn, "plan.phase1", plan.phase1);
}

}  // namespace capi
}  // namespace cyclide
