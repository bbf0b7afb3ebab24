// Bezier triangles shared by seed 004's design pipeline: quadratic graphs in
// the isotropic model (Powell-Sabin micro-triangles, §4.2) and the rational
// cubic triangles / bicubic patches they become on parabolic Dupin cyclides
// (§4.1). Only the data layout lives here; the constructions are in
// powell_sabin.hpp and parabolic_cyclide.hpp.
//
// Index order of Bezier coefficients b_ijk (i + j + k = degree; i belongs to
// vertex 0, j to vertex 1, k to vertex 2; barycentric coordinates (r, s, t)):
// lexicographic with i descending, then j descending:
//   degree 2: 200, 110, 101, 020, 011, 002
//   degree 3: 300, 210, 201, 120, 111, 102, 030, 021, 012, 003
#pragma once

#include <Eigen/Core>

namespace cyclide {
inline namespace v0 {

using Vec2d = Eigen::Vector2d;

// The graph y3 = z(y1, y2) of a quadratic over a triangle of the (y1, y2)
// plane, as a Bezier triangle: z(r, s, t) = sum ordinate_ijk B^2_ijk(r, s, t)
// at the point r vertex[0] + s vertex[1] + t vertex[2].
struct QuadraticGraphTriangle {
  Vec2d vertex[3];
  double ordinate[6] = {0, 0, 0, 0, 0, 0};
};

// A rational cubic Bezier triangle in homogeneous form: control[ijk] =
// (w, w x, w y, w z) (weight first), order as above.
struct RationalCubicTriangle {
  Eigen::Vector4d control[10];
};

// A rational bicubic tensor-product Bezier patch, control[i][j] = (w, w x,
// w y, w z), i along the first and j along the second parameter.
struct RationalBicubicPatch {
  Eigen::Vector4d control[4][4];
};

}  // namespace v0
}  // namespace cyclide
