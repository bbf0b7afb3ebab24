// PRCS: Parameterization of Rational Canal Surfaces (seed 000, §3,
// eqs. (8)-(13)). Two rational curves p1, p2 (or a curve and a line element)
// give the spine s(u) as the intersection of the normal planes M, N and the
// bisector plane B; the surface is the rotation of p1 about the spine
// tangent s' through s (CircleFrame o = s, a = s', p = p1).
#pragma once

#include "cyclide/circle_family.hpp"
#include "cyclide/config.hpp"
#include "cyclide/curve.hpp"
#include "cyclide/planes.hpp"
#include "cyclide/status.hpp"

namespace cyclide {
inline namespace v0 {

// Normal of the normal plane of a PRCS input at u, as a series: p'(u), or
// the constant tangent of a line element (its derivatives are zero).
template <int N, class S>
Vec3<Taylor<S, N>> normal_plane_normal(const RationalCurve& c,
                                       const Vec3<Taylor<S, N + 1>>& P) {
  if (c.kind == CurveKind::line_element)
    return {Taylor<S, N>(S(c.tangent.x())), Taylor<S, N>(S(c.tangent.y())),
            Taylor<S, N>(S(c.tangent.z()))};
  return derivative(P);
}

// The planes (8), (9), (10) at u as series of order K:
//   M: p1' . X = p1' . p1,  N: p2' . X = p2' . p2,
//   B: 2 (p1 - p2) . X = |p1|^2 - |p2|^2.
// Generic in the scalar S of u (double, or a Ceres Jet for derivatives
// with respect to design parameters).
// P1, P2 are p1, p2 as series of order K+1 (evaluated once by the caller).
template <int K, class S>
ThreePlanes<Taylor<S, K>> prcs_planes(const RationalCurve& p1, const RationalCurve& p2,
                                       const Vec3<Taylor<S, K + 1>>& P1,
                                       const Vec3<Taylor<S, K + 1>>& P2) {
  const Vec3<Taylor<S, K>> q1 = truncate<K>(P1), q2 = truncate<K>(P2);
  ThreePlanes<Taylor<S, K>> T;
  T.n[0] = normal_plane_normal<K>(p1, P1);
  T.n[1] = normal_plane_normal<K>(p2, P2);
  T.n[2] = Taylor<S, K>(S(2.0)) * (q1 - q2);
  T.b[0] = T.n[0].dot(q1);
  T.b[1] = T.n[1].dot(q2);
  T.b[2] = q1.dot(q1) - q2.dot(q2);
  return T;
}

template <int K, class S>
ThreePlanes<Taylor<S, K>> prcs_planes(const RationalCurve& p1, const RationalCurve& p2,
                                       const S& u) {
  return prcs_planes<K>(p1, p2, p1.taylor<K + 1>(u), p2.taylor<K + 1>(u));
}

// Classify the planes at u: zero tangents (relative to tangent_scale), then
// dependent planes (Remark 1: e.g. two lines of curvature).
template <class S>
Status check_prcs_planes(const ThreePlanes<S>& T, double tangent_scale) {
  if (!planes_finite(T)) return Status::numerical_overflow;  // a pole
  const double min2 = kZeroTangentTol * kZeroTangentTol * tangent_scale * tangent_scale;
  for (int i = 0; i < 2; ++i) {
    Vec3d n(value_of(T.n[i][0]), value_of(T.n[i][1]), value_of(T.n[i][2]));
    if (!(n.squaredNorm() > min2)) return Status::zero_tangent;
  }
  if (!(relative_determinant(T) > kDependentPlanesTol)) return Status::dependent_planes;
  return Status::ok;
}

// The planes (8)-(10) in the local variable Y = X - p1(u), the spine seen
// from the generator point itself:
//   M: p1' . Y = 0,  N: p2' . Y = p2' . (p2 - p1),
//   B: 2 (p1 - p2) . Y = -|p1 - p2|^2,
// (subtract n_i . p1 from both sides of (8)-(10)). The normals are those of
// prcs_planes, so the relative determinant and every status are the same;
// but the right-hand sides are formed from differences p2 - p1 of the size
// of the model, where |p1|^2 - |p2|^2 in (10) cancels to eps |p|^2: a model
// moved 10^6 of its size from the origin would lose 12 digits of its spine
// (eps |p|^2 / |p1 - p2| instead of eps |p|). s = p1 + Y.
template <int K, class S>
ThreePlanes<Taylor<S, K>> prcs_local_planes(const RationalCurve& p1, const RationalCurve& p2,
                                             const Vec3<Taylor<S, K + 1>>& P1,
                                             const Vec3<Taylor<S, K + 1>>& P2) {
  const Vec3<Taylor<S, K>> e = truncate<K>(P2) - truncate<K>(P1);  // p2 - p1
  ThreePlanes<Taylor<S, K>> T;
  T.n[0] = normal_plane_normal<K>(p1, P1);
  T.n[1] = normal_plane_normal<K>(p2, P2);
  T.n[2] = Taylor<S, K>(S(-2.0)) * e;
  T.b[0] = Taylor<S, K>(S(0.0));
  T.b[1] = T.n[1].dot(e);
  T.b[2] = -e.dot(e);
  return T;
}

// Spine s(u) as a series of order K (needs p1, p2 to order K+1), about the
// local origin p1(u) (prcs_local_planes).
template <int K, class S>
Status prcs_spine(const RationalCurve& p1, const RationalCurve& p2, const S& u,
                  double tangent_scale, Vec3<Taylor<S, K>>& s) {
  const auto P1 = p1.taylor<K + 1>(u);
  const auto T = prcs_local_planes<K>(p1, p2, P1, p2.taylor<K + 1>(u));
  if (Status st = check_prcs_planes(T, tangent_scale); st != Status::ok) return st;
  s = truncate<K>(P1) + intersect(T);
  return Status::ok;
}

// The circle frame of PRCS at u to order N: o = s, a = s', p = p1. The
// spine is needed to order N+1 (a = s'), hence p1, p2 to order N+2; it is
// found about the local origin p1(u) (prcs_local_planes).
template <int N, class S>
Status prcs_frame(const RationalCurve& p1, const RationalCurve& p2, const S& u,
                  double tangent_scale, CircleFrame<Taylor<S, N>>& F) {
  const auto P1 = p1.taylor<N + 2>(u);
  const auto T = prcs_local_planes<N + 1>(p1, p2, P1, p2.taylor<N + 2>(u));
  if (Status st = check_prcs_planes(T, tangent_scale); st != Status::ok) return st;
  const Vec3<Taylor<S, N + 1>> s = truncate<N + 1>(P1) + intersect(T);
  F.o = truncate<N>(s);
  F.a = derivative(s);
  F.p = truncate<N>(P1);
  return Status::ok;
}

}  // namespace v0
}  // namespace cyclide
