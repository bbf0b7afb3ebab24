// PRRS: Parameterization of Rational Ringed Surfaces (seed 000, §4,
// eqs. (24)-(27)). Three rational curves (one or two may be points) give the
// normal n = (p1 - p2) x (p1 - p3), and the directrix c(u) as the
// intersection of the plane M through the three points with two bisector
// planes; the surface is the rotation of p1 about n through c
// (CircleFrame o = c, a = n, p = p1). No derivative of the inputs is needed.
#pragma once

#include <algorithm>

#include "cyclide/circle_family.hpp"
#include "cyclide/config.hpp"
#include "cyclide/curve.hpp"
#include "cyclide/planes.hpp"
#include "cyclide/status.hpp"

namespace cyclide {
inline namespace v0 {

// The normals of the planes (24)-(26), from e2 = p1 - p2 and e3 = p1 - p3:
// n = e2 x e3 (M), 2 e2 (B1), 2 e3 (B2).
template <int K, class S>
void prrs_normals(const Vec3<Taylor<S, K>>& e2, const Vec3<Taylor<S, K>>& e3,
                  ThreePlanes<Taylor<S, K>>& T) {
  T.n[0] = e2.cross(e3);
  T.n[1] = Taylor<S, K>(S(2.0)) * e2;
  T.n[2] = Taylor<S, K>(S(2.0)) * e3;
}

// The planes (24)-(26) in the local variable Y = X - p1(u):
//   M: n . Y = 0,  B1: 2 (p1 - p2) . Y = -|p1 - p2|^2,
//   B2: 2 (p1 - p3) . Y = -|p1 - p3|^2,
// the same normals as prrs_planes (the same relative determinant), with
// right-hand sides of the model's size instead of the differences
// |p1|^2 - |p_j|^2 that cancel to eps |p|^2 far from the origin (see
// prcs_local_planes). The directrix is c = p1 + Y.
template <int K, class S>
ThreePlanes<Taylor<S, K>> prrs_local_planes(const Vec3<Taylor<S, K>>& q1,
                                             const Vec3<Taylor<S, K>>& q2,
                                             const Vec3<Taylor<S, K>>& q3) {
  using T_ = Taylor<S, K>;
  const Vec3<T_> e2 = q1 - q2, e3 = q1 - q3;
  ThreePlanes<T_> T;
  prrs_normals<K, S>(e2, e3, T);
  T.b[0] = T_(S(0.0));
  T.b[1] = -e2.dot(e2);
  T.b[2] = -e3.dot(e3);
  return T;
}

// The planes (24), (25), (26) at u as series of order K:
//   M: n . X = n . p1,  B1: 2 (p1 - p2) . X = |p1|^2 - |p2|^2,
//   B2: 2 (p1 - p3) . X = |p1|^2 - |p3|^2.
// q1, q2, q3: the three curves at u as series of order K (the optimizer
// passes Hermite curves whose coefficients are Jets).
template <int K, class S>
ThreePlanes<Taylor<S, K>> prrs_planes(const Vec3<Taylor<S, K>>& q1, const Vec3<Taylor<S, K>>& q2,
                                       const Vec3<Taylor<S, K>>& q3) {
  ThreePlanes<Taylor<S, K>> T;
  prrs_normals<K, S>(q1 - q2, q1 - q3, T);
  T.b[0] = T.n[0].dot(q1);
  T.b[1] = q1.dot(q1) - q2.dot(q2);
  T.b[2] = q1.dot(q1) - q3.dot(q3);
  return T;
}

template <int K, class S>
ThreePlanes<Taylor<S, K>> prrs_planes(const RationalCurve& p1, const RationalCurve& p2,
                                       const RationalCurve& p3, const S& u) {
  return prrs_planes<K, S>(p1.taylor<K>(u), p2.taylor<K>(u), p3.taylor<K>(u));
}

// The sine of the smallest angle of the triangle p1 p2 p3, from the planes'
// normals n = e2 x e3, 2 e2, 2 e3: |e2 x e3| over the product of the two
// longest sides. The circle through the points is well determined only if
// every angle is: the sine at p1 alone (the planes' relative determinant)
// stays large when p2 nears p1, where the circle is rounding noise.
template <class S>
double prrs_smallest_sine(const ThreePlanes<S>& T) {
  Vec3d n[3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) n[i][j] = value_of(T.n[i][j]);
  double side[3] = {0.5 * n[1].stableNorm(), 0.5 * n[2].stableNorm(),
                    0.5 * (n[1] - n[2]).stableNorm()};
  std::sort(side, side + 3);
  const double den = side[1] * side[2];
  if (!(den > 0)) return 0.0;
  return n[0].stableNorm() / den;
}

// Small means the three points are (nearly) collinear or two (nearly)
// coincide.
template <class S>
Status check_prrs_planes(const ThreePlanes<S>& T) {
  if (!planes_finite(T)) return Status::numerical_overflow;  // a pole
  if (!(prrs_smallest_sine(T) > kDependentPlanesTol)) return Status::collinear_points;
  return Status::ok;
}

template <int N, class S>
Status prrs_frame(const RationalCurve& p1, const RationalCurve& p2,
                  const RationalCurve& p3, const S& u, CircleFrame<Taylor<S, N>>& F) {
  const auto P1 = p1.taylor<N>(u);
  const auto T = prrs_local_planes<N, S>(P1, p2.taylor<N>(u), p3.taylor<N>(u));
  if (Status st = check_prrs_planes(T); st != Status::ok) return st;
  F.o = P1 + intersect(T);  // directrix c(u), about the local origin p1(u)
  F.a = T.n[0];             // n(u)
  F.p = P1;
  return Status::ok;
}

}  // namespace v0
}  // namespace cyclide
