// G1 surface design with parabolic Dupin cyclide patches (seed 004 §4.2).
//
// Oriented point data (A_i, alpha_i) -- points with unit normals a_i of a
// surface with one sign of Gaussian curvature -- are mapped into the
// isotropic model: B_i = Lambda(alpha_i) (the tangent plane as a point) and
// beta_i, the tangent plane of the paraboloid Lambda(A_i) (2.4) at B_i (the
// point A_i as a cycle of radius 0). The projections b_i of B_i onto
// y3 = 0 are triangulated and (B_i, beta_i) interpolated by a Powell-Sabin
// 6-split C1 piecewise quadratic; Lambda^{-1} maps each quadratic
// micro-triangle onto a rational cubic Bezier triangle on a parabolic
// Dupin cyclide of the family G (§4.1). The patches meet with common
// tangent planes along cubic circles: G1 where the joint is smooth, an
// edge of regression (Fig. 3) where the two patches lie on the same side
// of the joint.
//
// Invariance (§4.2): a translation of the data adds a quadratic to the
// isotropic interpolant (2.5), an offset of the data adds
// -(d/2)(1 + y1^2 + y2^2) (2.6), and Powell-Sabin splines reproduce
// quadratics: design(moved data) = moved design.
#pragma once

#include <cstddef>

#include "cyclide/bezier_triangle.hpp"
#include "cyclide/laguerre.hpp"
#include "cyclide/status.hpp"
#include "cyclide/vec.hpp"

namespace cyclide {
inline namespace v0 {

// A unit normal closer than this to W = (0, 0, 1) (|a - W|, radians) has
// no usable point in the isotropic model: its y' = (a1, a2)/(1 - a3) has
// |y'| > 2/kPoleTol.
constexpr double kPoleTol = 1e-12;

// One datum: a point A on the surface and its unit normal a (the oriented
// tangent plane alpha through A).
struct OrientedPoint {
  Vec3d point = Vec3d::Zero();
  Vec3d normal = Vec3d(0, 0, -1);
};

// The datum in the isotropic model: the point B = Lambda(alpha) =
// (b, z) and the gradient g of the tangent plane beta of Lambda(A) at B
// (beta: y3 = z + g . (y' - b)).
struct IsotropicDatum {
  Vec2d b = Vec2d::Zero();
  double z = 0;
  Vec2d g = Vec2d::Zero();
};

// (A, alpha) -> (B, beta). From (2.4) with m = A, r = 0: Lambda(A) is
// y3 = -(A3 |y'|^2 + 2 (A1, A2) . y' - A3) / 2, so g = -(A3 b + (A1, A2)).
// The normal is normalized first; not_finite, invalid_argument (zero
// normal), pole_in_gauss_image (normal within kPoleTol of W = (0, 0, 1):
// its plane has no point in I^3), numerical_overflow.
Status isotropic_datum(const OrientedPoint& A, IsotropicDatum& out) noexcept;

// The inverse: the oriented point whose datum is d. a = sigma^{-1}(b) =
// (2 b, |b|^2 - 1)/(1 + |b|^2), e0 = 2 z/(1 + |b|^2), and A solves
// a . A = -e0, A3 b + (A1, A2) = -g: A3 = e0 - a1 g1 - a2 g2 (the system's
// determinant a3 - a1 b1 - a2 b2 is -1). not_finite / numerical_overflow.
Status oriented_point_from_isotropic(const IsotropicDatum& d, OrientedPoint& out) noexcept;

// Whether the Gauss image of the data contains the projection centre W
// (§4.2: "the Gaussian image of the interpolating surface should not
// contain W"): W within kPoleTol of a normal, or W inside the convex cone
// of the normals (tested exactly when all normals lie in the upper
// hemisphere a3 > 0: the origin inside the convex hull of their gnomonic
// projections (a1, a2)/a3; data reaching below the equator are not
// refused by this test).
bool gauss_image_contains_pole(const OrientedPoint* data, int n) noexcept;

// ------------------------------------------------------------- the design

struct CyclideDesignOptions {
  // Return the patchwork even if some patches fold (Fig. 3); the report
  // still counts them. false: such data give `ridge` and no output.
  bool allow_ridges = false;
};

// What the design found; filled on success and, where it applies, on error.
struct CyclideDesignReport {
  int triangles = 0;   // macro-triangles of the triangulation of the b_i
  int patches = 0;     // 6 per macro-triangle (Powell-Sabin micro-triangles)
  // The orientation sign of the regular patches: the sign of
  // n . (x_y1 x x_y2), x(y1, y2) = Lambda^{-1} of the graph, n the unit
  // normal; its sign is the sign of 1/K relative to the Gauss map.
  int orientation = 0;
  // Micro-triangles where that sign flips or vanishes (at one of 7
  // samples: vertices, edge midpoints, centroid): a patch that meets its
  // neighbours in an edge of regression (Fig. 3) or carries a cusp.
  int ridge_patches = 0;
  int first_ridge_patch = -1;
  int first_bad_datum = -1;   // the datum of a not_finite / pole / overflow error
  std::size_t work_needed = 0;  // bytes, for buffer_too_small
  int patches_needed = 0;       // for buffer_too_small
};

// Bytes of workspace design_cyclide_surface needs for n data (ntri = 0:
// the triangulation is computed, room for Delaunay; else the caller's
// ntri triangles). The supported arguments are n in 3..kMaxDelaunayPoints
// and ntri in 0..kMaxTriangles (delaunay.hpp), for which every derived
// size fits (at most about 2.5e11 bytes); 0 for any other argument.
std::size_t cyclide_design_workspace_size(int n, int ntri) noexcept;

// Upper bound on the patch count: 6 (2n - 5) for a Delaunay triangulation,
// 6 ntri for a given one; at most 6 kMaxTriangles = 6e8, so it never
// wraps. 0 outside the supported arguments of cyclide_design_workspace_size.
int cyclide_design_max_patches(int n, int ntri) noexcept;

// Seed 004 §4.2. data[0..n) oriented points; tri[0..ntri) a triangulation
// of their isotropic projections b_i (counter-clockwise in the (y1, y2)
// plane), or tri = nullptr / ntri = 0 for the Delaunay triangulation of
// the b_i. Writes, per micro-triangle k < npatches = 6 ntri, the isotropic
// quadratic isotropic[k] (the Powell-Sabin interpolant of (B_i, beta_i))
// and its cyclide patch patches[k] (rational cubic Bezier triangle,
// cyclide_cubic_triangle), triangle by triangle.
// Statuses: null_argument; invalid_argument (n outside 3..kMaxDelaunayPoints,
// ntri outside 0..kMaxTriangles, a bad triangulation,
// two data with the same b_i); not_finite, pole_in_gauss_image (a normal at
// W, or W inside the normals' cone: gauss_image_contains_pole),
// numerical_overflow (report->first_bad_datum: a datum beyond the range, or
// whose b_i has a coordinate below kMinRelativeCoordinate of the largest,
// see delaunay.hpp); collinear_points (all b_i on
// a line); buffer_too_small (report->work_needed / patches_needed); ridge
// (some patch folds, unless options.allow_ridges). Outputs untouched on error.
Status design_cyclide_surface(const OrientedPoint* data, int n, const int (*tri)[3], int ntri,
                              const CyclideDesignOptions& options, void* work,
                              std::size_t work_bytes, QuadraticGraphTriangle* isotropic,
                              RationalCubicTriangle* patches, int patch_cap, int& npatches,
                              CyclideDesignReport* report = nullptr) noexcept;

// The point of Lambda^{-1}(graph y3 = z(y1, y2)) over y = (y1, y2) and its
// partials in y1, y2, from the value z, gradient g and Hessian H of the
// graph at y (P = (2 z, 2 y1, 2 y2, |y|^2 - 1), X = P ^ P_1 ^ P_2,
// X_i = P ^ P_1i ^ P_2 + P ^ P_1 ^ P_2i). Also the unit normal
// n = (2 y1, 2 y2, |y|^2 - 1) / (1 + |y|^2). The weight X0 = 4 (1 + |y|^2)
// never vanishes, so this cannot fail for finite input.
struct GraphPointJet {
  Vec3d x, x_1, x_2, n;
};
GraphPointJet graph_point_jet(const Vec2d& y, double z, const Vec2d& g,
                              const Eigen::Matrix2d& H) noexcept;

}  // namespace v0
}  // namespace cyclide
