// Delaunay triangulation of points in the plane, for seed 004 §4.2: the
// projections b_i of the isotropic data points B_i are triangulated before
// the Powell-Sabin interpolation (powell_sabin.hpp).
//
// Hand-written: Eigen and Ceres have no triangulation, and CGAL's 2-D
// triangulation is GPL-3+, unsuitable for a library that CAD kernels link.
//
// Algorithm: Bowyer-Watson insertion with "ghost" triangles (one per convex
// hull edge, joined to a vertex at infinity) in Hilbert-curve order; each
// point is located by a visibility walk from the previous insertion, so the
// expected cost is O(n log n) (the sort) plus O(1) per insertion on
// well-spread data. The orientation and incircle predicates are exact: a
// floating-point filter with a forward error bound, and an exact fallback in
// expansion arithmetic (sums of non-overlapping doubles built with the
// error-free two-sum and the fma-based two-product). With exact predicates
// the conflict region of a new point is a star-shaped union of triangles,
// so the result is always a valid triangulation of the convex hull
// (counter-clockwise triangles, no overlaps, every interior edge shared by
// exactly two triangles), also for cocircular input such as grids.
//
// Memory: the core never allocates. The caller provides a workspace of
// delaunay_workspace_size(n) ints and room for delaunay_max_triangles(n)
// triangles (2n - 5; exactly 2n - 2 - h for h points on the hull).
#pragma once

#include <cstddef>

#include "cyclide/bezier_triangle.hpp"
#include "cyclide/status.hpp"

namespace cyclide {
inline namespace v0 {

// Largest point count accepted: the workspace, 26 n + 7 ints, stays below
// 2^31 ints, and the 2n - 5 triangles (and the design's 6 (2n - 5)
// micro-triangles, cyclide_design.hpp) stay below INT_MAX.
constexpr int kMaxDelaunayPoints = 50'000'000;

// Largest triangle count accepted from a caller (validate_triangulation,
// Powell-Sabin, the design): a triangulation of kMaxDelaunayPoints points
// has fewer, and 6 kMaxTriangles micro-triangles still fit in an int, so no
// size derived from a triangle count can overflow.
constexpr int kMaxTriangles = 2 * kMaxDelaunayPoints;

// Smallest nonzero coordinate accepted, relative to the largest (after
// scaling that one into [1/2, 1)): below it the exact predicates' products
// could underflow (about 6e-58).
constexpr double kMinRelativeCoordinate = 0x1p-190;

// Where an input error lies: the non-finite point (first), the two equal
// points (first < second), or, for buffer_too_small, the sizes needed.
struct DelaunayReport {
  int first = -1;
  int second = -1;
  std::size_t work_needed = 0;  // ints
  int triangles_needed = 0;
};

// Ints of workspace delaunay_triangulate needs for n points (0 if n < 3 or
// n > kMaxDelaunayPoints).
std::size_t delaunay_workspace_size(int n) noexcept;

// Upper bound 2n - 5 on the number of triangles of n points, n in
// 3..kMaxDelaunayPoints (0 for any other n: never negative or wrapped).
int delaunay_max_triangles(int n) noexcept;

// The Delaunay triangulation of pts[0..n): triangles tri[0..ntri) as
// counter-clockwise index triples. Where four or more points are cocircular
// one of the Delaunay triangulations is returned (deterministically).
// Statuses:
//   invalid_argument  n < 3 or n > kMaxDelaunayPoints, null pointers, or two
//                     equal points (report->first < report->second)
//   not_finite        a coordinate is NaN, Inf or beyond 1e100 (report->first)
//   collinear_points  all points on one line (no triangle exists)
//   numerical_overflow a nonzero coordinate below kMinRelativeCoordinate times
//                     the largest (report->first): the exact predicates would
//                     underflow
//   buffer_too_small  work_len < delaunay_workspace_size(n) (report->work_needed),
//                     or tri_cap below the triangle count (ntri and
//                     report->triangles_needed get the count)
// On error tri is untouched (ntri too, except for buffer_too_small).
Status delaunay_triangulate(const Vec2d* pts, int n, int* work, std::size_t work_len,
                            int (*tri)[3], int tri_cap, int& ntri,
                            DelaunayReport* report = nullptr) noexcept;

// Ints of workspace validate_triangulation needs for ntri triangles, ntri in
// 1..kMaxTriangles (0 for any other ntri).
std::size_t triangulation_workspace_size(int ntri) noexcept;

// Checks a user-given triangulation: every index in [0, n), every triangle
// counter-clockwise and non-degenerate (exact orientation > 0), and every
// edge used at most twice and then with opposite orientations (ntri in
// 1..kMaxTriangles, else invalid_argument). If
// neighbor != nullptr, neighbor[3t + k] receives the triangle across the
// edge tri[t][k] -> tri[t][(k+1)%3] (or -1 on the boundary). Does not
// detect a triangulation that folds over itself around a vertex with
// consistent edges (a branched covering). Statuses: invalid_argument (with
// report->first = the offending triangle), not_finite, numerical_overflow
// (a coordinate below the exact predicates' range, as delaunay_triangulate;
// report->first = the point), buffer_too_small.
Status validate_triangulation(const Vec2d* pts, int n, const int (*tri)[3], int ntri, int* work,
                              std::size_t work_len, int* neighbor = nullptr,
                              DelaunayReport* report = nullptr) noexcept;

// Exact signs of the two predicates (for tests and callers):
// orient2d > 0 iff a, b, c are counter-clockwise; incircle > 0 iff d lies
// inside the circle through the counter-clockwise a, b, c. Exact for
// finite inputs whose products do not underflow or overflow (|x| <= 1e60).
int orient2d_sign(const Vec2d& a, const Vec2d& b, const Vec2d& c) noexcept;
int incircle_sign(const Vec2d& a, const Vec2d& b, const Vec2d& c, const Vec2d& d) noexcept;

}  // namespace v0
}  // namespace cyclide
