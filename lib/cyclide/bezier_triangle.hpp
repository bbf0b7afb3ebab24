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
#include <algorithm>
#include <cmath>
#include <limits>

#include "cyclide/status.hpp"

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

// ------------------------------------------------------------- evaluators
// De Casteljau on the homogeneous control points (weights may be <= 0; the
// homogeneous point is what is interpolated). The affine point is x = X / w.
// point_at_infinity when |w| <= 64 eps W, W = the same de Casteljau sums
// on the absolute weights |w_i| at the absolute parameters, which bounds
// their rounding (the weight polynomial vanishes there to rounding: the
// point lies at infinity). W is the weights' own scale: a bound taken from
// all four homogeneous components would grow with the patch's distance from
// the origin and, beyond about 1/(64 eps) = 7e13 of its size, refuse every
// point of a valid patch. not_finite for NaN/Inf parameters. On error x is
// untouched.

// Homogeneous point of the cubic triangle at barycentrics (r, s, t).
inline Eigen::Vector4d evaluate_homogeneous(const RationalCubicTriangle& T, double r, double s,
                                            double t) noexcept {
  // Work array in the documented order; each step lowers the degree by one:
  // b^{n-1}_{ijk} = r b_{i+1,j,k} + s b_{i,j+1,k} + t b_{i,j,k+1}.
  Eigen::Vector4d b[10];
  for (int i = 0; i < 10; ++i) b[i] = T.control[i];
  // index of (i, j) in degree n (k = n - i - j): rows by descending i.
  auto idx = [](int n, int i, int j) {
    int before = 0;  // coefficients with a larger i
    for (int ii = n; ii > i; --ii) before += n - ii + 1;
    return before + (n - i - j);
  };
  for (int n = 3; n > 0; --n) {
    Eigen::Vector4d c[10];
    for (int i = n - 1; i >= 0; --i)
      for (int j = n - 1 - i; j >= 0; --j)
        c[idx(n - 1, i, j)] = r * b[idx(n, i + 1, j)] + s * b[idx(n, i, j + 1)] + t * b[idx(n, i, j)];
    for (int i = 0; i < 10; ++i) b[i] = c[i];
  }
  return b[0];
}

// Homogeneous point of the bicubic at (s, t) (s along the first index).
inline Eigen::Vector4d evaluate_homogeneous(const RationalBicubicPatch& P, double s,
                                            double t) noexcept {
  auto casteljau = [](Eigen::Vector4d p[4], double x) {
    for (int n = 3; n > 0; --n)
      for (int i = 0; i < n; ++i) p[i] = (1 - x) * p[i] + x * p[i + 1];
    return p[0];
  };
  Eigen::Vector4d col[4];
  for (int i = 0; i < 4; ++i) {
    Eigen::Vector4d row[4] = {P.control[i][0], P.control[i][1], P.control[i][2], P.control[i][3]};
    col[i] = casteljau(row, t);
  }
  return casteljau(col, s);
}

namespace detail {
// X = (w, w x) with |w| judged against weight_scale, the rounding bound W
// of its de Casteljau sums (see above).
inline Status dehomogenize(const Eigen::Vector4d& X, double weight_scale,
                           Eigen::Vector3d& x) noexcept {
  if (!X.allFinite()) return Status::numerical_overflow;
  if (std::abs(X[0]) <= 64 * std::numeric_limits<double>::epsilon() * weight_scale)
    return Status::point_at_infinity;
  const Eigen::Vector3d p = X.tail<3>() / X[0];
  if (!p.allFinite()) return Status::numerical_overflow;
  x = p;
  return Status::ok;
}
}  // namespace detail

inline Status evaluate(const RationalCubicTriangle& T, double r, double s, double t,
                       Eigen::Vector3d& x) noexcept {
  if (!std::isfinite(r) || !std::isfinite(s) || !std::isfinite(t)) return Status::not_finite;
  RationalCubicTriangle W;  // the absolute weights, for the rounding bound
  for (int i = 0; i < 10; ++i) W.control[i] = Eigen::Vector4d(std::abs(T.control[i][0]), 0, 0, 0);
  const double bound = evaluate_homogeneous(W, std::abs(r), std::abs(s), std::abs(t))[0];
  return detail::dehomogenize(evaluate_homogeneous(T, r, s, t), bound, x);
}

inline Status evaluate(const RationalBicubicPatch& P, double s, double t,
                       Eigen::Vector3d& x) noexcept {
  if (!std::isfinite(s) || !std::isfinite(t)) return Status::not_finite;
  // The rounding bound of the weight: de Casteljau on |w_ij| with the
  // absolute factors |1 - x|, |x| of each step.
  double col[4];
  for (int i = 0; i < 4; ++i) {
    double row[4];
    for (int j = 0; j < 4; ++j) row[j] = std::abs(P.control[i][j][0]);
    for (int n = 3; n > 0; --n)
      for (int j = 0; j < n; ++j) row[j] = std::abs(1 - t) * row[j] + std::abs(t) * row[j + 1];
    col[i] = row[0];
  }
  for (int n = 3; n > 0; --n)
    for (int i = 0; i < n; ++i) col[i] = std::abs(1 - s) * col[i] + std::abs(s) * col[i + 1];
  return detail::dehomogenize(evaluate_homogeneous(P, s, t), col[0], x);
}

}  // namespace v0
}  // namespace cyclide
