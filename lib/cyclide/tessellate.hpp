// Adaptive tessellation of circle-family surfaces with a chordal tolerance
// (issue 9 item 3), using the circle structure: every row of the mesh is
// one circle of the family, cut into N arcs of equal angle (N from the
// largest radius: r (1 - cos(pi / N)) <= tol / 2), and the rows are placed
// adaptively along u (an interval is halved while its middle circle strays
// more than tol / 2 from the chords between its end circles, at the mesh
// angles and halfway between them).
//
// Angles. The evaluator rotates the generator p(u) about the axis a(u) by
// q = W + G a, W = alpha s1 + beta s0, G = gamma s1 + delta s0 (evaluator.hpp),
// i.e. by the angle theta with (cos(theta/2), sin(theta/2)) proportional to
// (W, G |a|). The point at angle theta therefore has the homogeneous circle
// parameter (s1, s0) solving
//   [alpha beta; gamma delta] (s1, s0)^T = (cos(theta/2), sin(theta/2) / |a|),
// and v = s1 / s0 (v = +-1e300 where s0 vanishes: the evaluator reads such v
// as (1, 1/v), the generator to rounding). No inverse trigonometry per point.
//
// Seams and joins. Angles are measured about a(u) from a reference
// direction in the circle's plane: by default the generator p(u) - c(u); or,
// at either end of the domain, the projection of a caller's world vector
// into that end circle's plane (the angle offset is interpolated linearly
// in u in between, so the rows do not twist). Two surfaces that share an
// end circle and are tessellated with the same reference vector there and
// the same N produce the same boundary vertices to rounding (a watertight
// join after welding within ~1e-12 of the model size).
//
// Memory: allocation-free. The caller provides the row parameters (up to
// row_cap) and the output buffers (rows x N points, closed in v: column N
// is column 0 again and is not written), and a scratch of
// tessellation_workspace_size(N) doubles for the row checks.
#pragma once

#include <cstddef>

#include "cyclide/evaluator.hpp"
#include "cyclide/status.hpp"
#include "cyclide/surface.hpp"

namespace cyclide {
inline namespace v0 {

// Largest number of arcs per circle.
constexpr int kMaxCircleSegments = 4096;
// Largest halving depth of a u-interval (the rows then stand 2^-depth of
// the initial spacing apart). The planner's scratch holds two circles per
// depth.
constexpr int kMaxTessellationDepth = 16;

struct TessellationOptions {
  double chordal_tolerance = 1e-3;  // > 0, model units
  int min_segments = 8;             // arcs per circle, >= 3
  int max_segments = 1024;          // <= kMaxCircleSegments
  int fixed_segments = 0;           // > 0: exactly this N (for shared joins)
  int initial_rows = 9;             // uniform rows before refinement, >= 2
  // Optional world reference vectors for the angle 0 at u0 and u1 (null:
  // the generator p(u)). A vector (nearly) along the circle's axis is
  // invalid_argument.
  const double* reference_u0 = nullptr;
  const double* reference_u1 = nullptr;
};

// What the planner found.
struct TessellationPlan {
  int rows = 0;       // circles (us[0] = u0 < ... < us[rows - 1] = u1)
  int segments = 0;   // arcs per circle N (points per row)
  double phase0 = 0;  // angle offset at u0 and u1 (radians, about a(u))
  double phase1 = 0;
  double max_radius = 0;
  bool depth_limited = false;  // some interval hit kMaxTessellationDepth
};

// Whether the options are in range (both planners' invalid_argument).
bool tessellation_options_valid(const TessellationOptions& o) noexcept;

// Doubles of scratch the planner needs for N arcs per circle.
std::size_t tessellation_workspace_size(int segments) noexcept;

// Chooses N and the rows: us[0..plan.rows) receives the circles' u (sorted).
// Statuses: invalid_argument (options out of range, a reference along the
// axis), buffer_too_small (the rows needed exceed row_cap: the planner
// stops there, plan.rows = row_cap, so the work is bounded by the caller's
// budget; or work_len is too small, plan untouched), and the
// surface's evaluation statuses (singular_point, numerical_overflow, ...)
// at a row. The surface must be closed in v (every kind here is: v runs
// over the whole circle).
Status tessellation_plan(const Surface& s, const TessellationOptions& options, double* us,
                         int row_cap, double* work, std::size_t work_len,
                         TessellationPlan& plan) noexcept;

// The mesh of a plan: point (i, j) = the circle us[i] at angle
// phase(u) + 2 pi j / N, at index i * N + j of points and normals (either
// may have data = nullptr). Normals at singular points (ringed surfaces) are
// (0, 0, 0) and counted in *singular (may be null). Every row is validated
// before anything is written; the buffers must hold rows * N entries
// (checked by the caller tier).
Status tessellation_eval(const Surface& s, const TessellationPlan& plan, const double* us,
                         const Strided3& points, const Strided3& normals,
                         std::size_t* singular) noexcept;

// The circle parameter v of the point at angle theta (about a(u), from the
// generator) on the circle u: the solution of the 2 x 2 system above.
Status circle_parameter_at_angle(const Surface& s, double u, double theta, double& v) noexcept;

}  // namespace v0
}  // namespace cyclide
