// Intersection point of three planes n_i . X = b_i (seed 000, PRCS step 2,
// PRRS step 3), by Cramer's rule so that it runs on series and Jets:
//   X = (b1 (n2 x n3) + b2 (n3 x n1) + b3 (n1 x n2)) / (n1 . (n2 x n3)).
#pragma once

#include <cmath>

#include "cyclide/vec.hpp"

namespace cyclide {
inline namespace v0 {

template <class S>
struct ThreePlanes {
  Vec3<S> n[3];
  S b[3];
};

// |det| / (|n1| |n2| |n3|) of the values: the sine-like measure of how far
// the planes are from sharing a direction (0 = dependent, 1 = orthogonal).
template <class S>
double relative_determinant(const ThreePlanes<S>& P) {
  Vec3d n[3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) n[i][j] = value_of(P.n[i][j]);
  const double den2 = n[0].squaredNorm() * n[1].squaredNorm() * n[2].squaredNorm();
  if (!(den2 > 0)) return 0.0;
  return std::abs(n[0].dot(n[1].cross(n[2]))) / std::sqrt(den2);
}

// False if a plane is not finite (a pole of a rational input at this u).
template <class S>
bool planes_finite(const ThreePlanes<S>& P) {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(double(value_of(P.b[i])))) return false;
    for (int j = 0; j < 3; ++j)
      if (!std::isfinite(double(value_of(P.n[i][j])))) return false;
  }
  return true;
}

template <class S>
Vec3<S> intersect(const ThreePlanes<S>& P) {
  const Vec3<S> c23 = P.n[1].cross(P.n[2]);
  const Vec3<S> c31 = P.n[2].cross(P.n[0]);
  const Vec3<S> c12 = P.n[0].cross(P.n[1]);
  const S det = P.n[0].dot(c23);
  return (P.b[0] * c23 + P.b[1] * c31 + P.b[2] * c12) / det;
}

}  // namespace v0
}  // namespace cyclide
