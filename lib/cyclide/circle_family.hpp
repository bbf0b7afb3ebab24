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
// quadratic Bezier form of the circle. Everything here is generic in the
// scalar S (double, Taylor series in u, Jets).
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

// Point x(v) and dx/dv of the circle. For |v| > 1 the quadratic is evaluated
// in t = 1/v (homogeneous form), so every finite v is safe from overflow.
template <class S>
void circle_point(const CircleQuadratic<S>& C, double v, Vec3<S>& x, Vec3<S>* x_v) {
  Vec3<S> num, dnum;
  S den, dden;
  double chain = 1.0;
  // Horner in v for |v| <= 1, else in t = 1/v with the coefficients reversed.
  const bool inner = std::abs(v) <= 1.0;
  const double t = inner ? v : 1.0 / v;
  const int lo = inner ? 0 : 2, hi = 2 - lo;
  const S st(t), s2t(2.0 * t);
  num = C.P[lo] + st * (C.P[1] + st * C.P[hi]);
  den = C.Q[lo] + st * (C.Q[1] + st * C.Q[hi]);
  if (x_v) {
    dnum = C.P[1] + s2t * C.P[hi];
    dden = C.Q[1] + s2t * C.Q[hi];
    if (!inner) chain = -t * t;  // dt/dv
  }
  const S inv = S(1) / den;
  const Vec3<S> r = num * inv;
  x = C.o + r;
  if (x_v) *x_v = (dnum - dden * r) * (inv * S(chain));
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
