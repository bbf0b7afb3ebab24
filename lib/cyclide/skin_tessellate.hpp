// Adaptive tessellation of sphere skins (seed 002, sphere_skin.hpp) with a
// chordal tolerance (issue 9; SPEC.md §8j.2a). A skin s(theta, t) is not a
// circle family (its sections t = const are not circles), but theta is an
// angle on the end circles and s is 2 pi periodic in it, so the mesh is a
// grid like tessellate.hpp's: every row is the section t = const cut at N
// equal steps in theta, and the rows are placed adaptively in t.
//
// Columns. Row t has the points theta = phase(t) + 2 pi j / N, j < N
// (closed: column N is column 0 again and is not written). N starts from
// the largest lambda, lambda_max = max_t |L0(t)| + hypot(Lc(t), Ls(t))
// (skin_lambda_polynomials, sampled at 65 values of t): the smallest N with
// lambda_max (1 - cos(pi / N)) <= tol / 2, clamped to [min_segments,
// max_segments], or fixed_segments. It is then verified: on every row the
// planner evaluates, the section at theta_j + h/4, h/2, 3h/4 (h = 2 pi / N)
// must lie within tol / 2 of the chord's point at the same fraction between
// theta_j and theta_j+1 (a parametric, hence stricter, form of the chord
// height). A row that fails raises N (by the factor sqrt(deviation /
// (tol/2)) the quadratic convergence predicts, at least by one) and the
// planning restarts (65 uniform rows are checked first, so restarts are
// rare). At max_segments (or fixed_segments) a failing row is accepted and
// reported (SkinTessellationReport::segment_limited; the C ABI's
// depth_limited bit 2).
//
// Rows. initial_rows uniform rows, then an interval [ta, tb] is halved
// while its rows at 1/4, 1/2, 3/4 stray from the chords between its end
// rows: more than tol / 2 at the 4N angles theta_j + k h / 4 (the mesh
// angles, halfway and the quarters; same angle index: the chords join
// corresponding points), or more than tol along either diagonal of a cell
// (the points theta_j + f h and theta_j+1 - f h of the row at fraction f
// against the chords (ta, theta_j)-(tb, theta_j+1) and (ta, theta_j+1)-(tb,
// theta_j): the mesh writer's triangles cut the cells along a diagonal; a
// diagonal's error includes the theta share, hence tol / 2 + max(tol / 2,
// the five rows' section deviation), so that a segment-limited N does not
// drive the rows to the depth limit). Depth
// limit kMaxTessellationDepth (plan.depth_limited). The halves reuse the
// parent's rows, so each check evaluates two new rows.
//
// Seam and joins. The angle offset phase(t) is linear in t between phase0
// (t = 0) and phase1 (t = 1), both 0 by default (the seam on theta = 0).
// options.reference_u0 / reference_u1, if given, are world vectors whose
// projections into the end circle's plane give the angle 0 there, measured
// about the spine's unit tangent from w(0; 0) at t = 0, from w(1; 0) at
// t = 1 (the other end takes the same offset when only one is given;
// unwrapped to the shorter turn). The patches of a chain
// (make_sphere_skin_chain) continue theta across the shared circles, so
// patch k's row t = 1 and patch k + 1's row t = 0 are the same points (to
// rounding) when both are planned with the same N and the same phase at the
// shared circle (defaults, or the same reference vector there): plan every
// patch, take the largest plan.segments, plan again with fixed_segments =
// that N (skin_chain_tessellation_segments does the first pass). The mesh
// writer (mesh_io.hpp) then welds the joins.
//
// Memory: allocation-free. The caller provides the row parameters ts (up to
// row_cap), the output buffers (rows x N points) and a scratch of
// skin_tessellation_workspace_size(N) doubles, N = fixed_segments or
// max_segments (N may grow up to it).
#pragma once

#include <cstddef>

#include "cyclide/sphere_skin.hpp"
#include "cyclide/status.hpp"
#include "cyclide/tessellate.hpp"

namespace cyclide {
inline namespace v0 {

// What the skin planner measured (beyond TessellationPlan).
struct SkinTessellationReport {
  bool segment_limited = false;  // N = max_segments (or fixed) misses tol/2 on some row
  double theta_deviation = 0;    // largest section-chord deviation over the final rows
  double t_deviation = 0;        // largest chord deviation of the final intervals (vertical)
  double diagonal_deviation = 0; // largest deviation along the cells' diagonals
  int passes = 0;                // planning passes (N raised between them)
};

// Doubles of scratch the planner needs when N may reach `segments` (0 out of
// range): 37 rows of 4N points and the 4N angles' cosines and sines.
std::size_t skin_tessellation_workspace_size(int segments) noexcept;

// Chooses N and the rows: ts[0..plan.rows) receives the rows' t (sorted,
// ts[0] = 0, ts[rows - 1] = 1). plan.max_radius is lambda_max, plan.phase0
// and plan.phase1 the angle offsets; plan.depth_limited as tessellate.hpp.
// report may be null. Statuses: invalid_argument (options out of range as
// tessellation_plan's, row_cap < 0, a reference vector along the end
// circle's axis), null_argument (ts null with row_cap > 0), not_finite (a
// non-finite reference), buffer_too_small (work below
// skin_tessellation_workspace_size(fixed_segments or max_segments): plan
// untouched; or more rows than row_cap: the planner stops there, plan.rows
// = row_cap, so the work is bounded by the caller's budget),
// numerical_overflow (a point is not finite). plan and report are written
// on ok and buffer_too_small (rows), ts up to plan.rows.
Status skin_tessellation_plan(const SphereSkin& S, const TessellationOptions& options, double* ts,
                              int row_cap, double* work, std::size_t work_len,
                              TessellationPlan& plan,
                              SkinTessellationReport* report = nullptr) noexcept;

// The first pass of a chain's shared N: the largest plan.segments of
// patches[0..count) planned with options (fixed_segments then forces it).
// Statuses as skin_tessellation_plan's; invalid_argument for count < 1,
// null_argument for null patches or ts.
Status skin_chain_tessellation_segments(const SphereSkin* patches, int count,
                                        const TessellationOptions& options, double* ts,
                                        int row_cap, double* work, std::size_t work_len,
                                        int& segments) noexcept;

// The mesh of a plan: point (i, j) = s(phase(ts[i]) + 2 pi j / N, ts[i]) at
// index i * N + j of points and normals (either may have data = nullptr),
// the values of skin_eval_grid (bit for bit). Normals at singular points
// are (0, 0, 0) and counted in *singular (may be null). Validated before
// anything is written: null_argument (ts), invalid_argument (rows < 2,
// N out of 3..kMaxCircleSegments, stride < 3), not_finite (a phase or
// ts[i]), bad_domain (ts[i] outside [0, 1]), numerical_overflow (skins
// beyond 1e50 whose points overflow). The buffers must hold rows * N
// entries (checked by the caller tier).
Status skin_tessellation_eval(const SphereSkin& S, const TessellationPlan& plan, const double* ts,
                              const Strided3& points, const Strided3& normals,
                              std::size_t* singular) noexcept;

}  // namespace v0
}  // namespace cyclide
