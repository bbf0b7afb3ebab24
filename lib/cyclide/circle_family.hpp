// The one idea at the center of cyclide: a rational one-parameter family of
// circles, each circle the orbit of a generator point under the rotations
// about an axis line, parameterized rationally by one quaternion.
//
// For each u a CircleFrame gives
//   o(u)  a point on the axis   (spine point s for canal surfaces, PRCS;
//                                 circle center c for ringed surfaces, PRRS)
//   a(u)  the axis direction     (s' for PRCS, n for PRRS; the normal of the
//                                 circle's plane; any length)
//   p(u)  the generator          (p1(u): the point with f = infinity)
//   f(u,v) = (alpha v + beta) / (gamma v + delta), a Mobius map of v.
// and the surface point is, eqs. (11) and (27) of seed 000,
//   x(u,v) = o + (f + a) * (p - o) * (f - a) / ((f - a) * (f + a)).
// With q = (alpha v + beta) + (gamma v + delta) a (the same quaternion up to
// the scalar factor gamma v + delta), x - o is a quadratic rational function
// of v: x = o + (P0 + P1 v + P2 v^2) / (Q0 + Q1 v + Q2 v^2), the rational
// quadratic Bezier form of the circle (circle_quadratic: for export; the
// evaluator forms W and G per point instead, which is better conditioned).
// Everything here is generic in the scalar S (double, Taylor series in u,
// Jets).
#pragma once

#include <cmath>

#include "cyclide/vec.hpp"

namespace cyclide {
inline namespace v0 {

template <class S>
struct CircleFrame {
  Vec3<S> o, a, p;
  S alpha, beta, gamma, delta;
};

// x(u, v) - o = (P0 + P1 v + P2 v^2) / (Q0 + Q1 v + Q2 v^2).
template <class S>
struct CircleQuadratic {
  Vec3<S> o;
  Vec3<S> P[3];
  S Q[3];
};

// Expand q d conj(q) with q = W + G a, W = alpha v + beta, G = gamma v + delta,
// d = p - o:  (W^2 - G^2 |a|^2) d + 2 G^2 (a.d) a + 2 W G (a x d), over
// W^2 + G^2 |a|^2 (the expanded form of eq. (11)/(27), see vec.hpp rotate).
template <class S>
CircleQuadratic<S> circle_quadratic(const CircleFrame<S>& F) {
  const Vec3<S> d = F.p - F.o;
  const S aa = F.a.dot(F.a);
  const S ad = F.a.dot(d);
  const Vec3<S> axd = F.a.cross(d);
  const S two(2);
  // Coefficients of v^0, v^1, v^2 in W^2, G^2 and W G.
  const S W2[3] = {F.beta * F.beta, two * F.alpha * F.beta, F.alpha * F.alpha};
  const S G2[3] = {F.delta * F.delta, two * F.gamma * F.delta, F.gamma * F.gamma};
  const S WG[3] = {F.beta * F.delta, F.alpha * F.delta + F.beta * F.gamma,
                   F.alpha * F.gamma};
  CircleQuadratic<S> C;
  C.o = F.o;
  for (int k = 0; k < 3; ++k) {
    C.P[k] = (W2[k] - G2[k] * aa) * d + (two * G2[k] * ad) * F.a + (two * WG[k]) * axd;
    C.Q[k] = W2[k] + G2[k] * aa;
  }
  return C;
}

// The rotation data (evaluator.hpp) of a frame, generic in the scalar: with
// S = Taylor<double, 1> it gives the values and their u-derivatives.
template <class S>
struct RotationTerms {
  Vec3<S> o, d, a, axd;
  S aa, ad, alpha, beta, gamma, delta;
};

template <class S>
RotationTerms<S> rotation_terms(const CircleFrame<S>& F) {
  RotationTerms<S> T;
  T.o = F.o;
  T.d = F.p - F.o;
  T.a = F.a;
  T.axd = F.a.cross(T.d);
  T.aa = F.a.dot(F.a);
  T.ad = F.a.dot(T.d);
  T.alpha = F.alpha;
  T.beta = F.beta;
  T.gamma = F.gamma;
  T.delta = F.delta;
  return T;
}

// The circle of the frame as geometry: center, plane normal (unit), radius^2.
template <class S>
struct CircleGeometry {
  Vec3<S> center;
  Vec3<S> normal;  // a(u), not normalized
  S radius2;
};

// Center c = o + ((a.d)/|a|^2) a and radius^2 = |d|^2 - (a.d)^2/|a|^2: the
// foot of the generator on the axis and its distance (rational in u, as
// seed 000 §2 says: c, n and rho^2 are rational).
template <class S>
CircleGeometry<S> circle_geometry(const CircleFrame<S>& F) {
  const Vec3<S> d = F.p - F.o;
  const S aa = F.a.dot(F.a);
  const S ad = F.a.dot(d);
  CircleGeometry<S> G;
  G.center = F.o + (ad / aa) * F.a;
  G.normal = F.a;
  G.radius2 = d.dot(d) - ad * ad / aa;
  return G;
}

}  // namespace v0
}  // namespace cyclide
