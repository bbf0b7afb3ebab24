// Inputs of the constructions: rational curves, lines, points and line
// elements (seed 000 §3: "one of the two curves can be replaced by a line
// element"; §4: "one or two of the given curves can be replaced with points").
#pragma once

#include "cyclide/config.hpp"
#include "cyclide/poly.hpp"
#include "cyclide/status.hpp"
#include "cyclide/vec.hpp"

namespace cyclide {
inline namespace v0 {

using CurvePoly = Poly<double, kMaxCurveDegree>;

enum class CurveKind : int {
  rational = 0,      // p(u) = (x(u), y(u), z(u)) / w(u)
  point = 1,         // constant point (PRRS input)
  line_element = 2,  // constant point P with a tangent t (PRCS input)
};

// Two bases: power form in u (curves given by coefficients), or Bernstein
// form on [u0, u0 + h] (Bezier and Hermite curves). Bernstein curves are
// evaluated by de Casteljau: converting a degree-15 Hermite curve to power
// form loses up to 4e-5 in its 7th derivative, de Casteljau keeps ~1e-13.
template <int N, class S>
Vec3<Taylor<S, N>> scale_by(const Vec3<Taylor<S, N>>& P, const S& f) {
  Vec3<Taylor<S, N>> R = P;
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k <= N; ++k) R[j].c[k] *= f;
  return R;
}

struct RationalCurve {
  CurveKind kind = CurveKind::rational;
  CurvePoly x, y, z, w;  // homogeneous (x, y, z, w): power or Bernstein coefficients
  bool bernstein = false;
  double u0 = 0.0, h = 1.0;  // Bernstein interval [u0, u0 + h]
  Vec3d tangent = Vec3d::Zero();  // line elements only

  int degree() const;
  // True if the weight is constant (power form: degree 0; Bernstein form:
  // all weights equal). Set by the constructors; skips the series division.
  bool constant_weight = false;
  bool is_polynomial() const { return constant_weight; }
  void update_constant_weight() {
    constant_weight = true;
    for (int k = 1; k <= w.deg; ++k)
      if (w.c[k] != (bernstein ? w.c[0] : 0.0)) constant_weight = false;
  }

  // p(u + h) as a Taylor series to order N: the point and its derivatives
  // p^(k)(u) / k!. Constant kinds have zero derivatives (ERRATA: a line
  // element's point has derivative zero; its tangent is separate).
  template <int N, class S>
  Vec3<Taylor<S, N>> taylor(const S& u) const {
    Vec3<Taylor<S, N>> P;
    Taylor<S, N> W;
    if (bernstein) {
      const S t = (u - S(u0)) / S(h);
      const int n = degree();
      P = {bernstein_taylor<N>(x.c, n, t, h), bernstein_taylor<N>(y.c, n, t, h),
           bernstein_taylor<N>(z.c, n, t, h)};
      if (constant_weight) return scale_by(P, S(1.0 / w.c[0]));
      W = bernstein_taylor<N>(w.c, n, t, h);
    } else {
      P = {x.taylor<N>(u), y.taylor<N>(u), z.taylor<N>(u)};
      if (constant_weight) return scale_by(P, S(1.0 / w.c[0]));
      W = w.taylor<N>(u);
    }
    return Vec3<Taylor<S, N>>(P[0] / W, P[1] / W, P[2] / W);
  }
  Vec3d point(double u) const {
    const auto P = taylor<0>(u);
    return Vec3d(P[0].c[0], P[1].c[0], P[2].c[0]);
  }
};

// Constructors validate (finite, |values| <= kMaxInputMagnitude, degree
// <= kMaxCurveDegree, weight not identically zero) and leave `out`
// untouched on error.

// Polynomial curve: xyz holds degree+1 points (c_k as x,y,z), p = sum c_k u^k.
Status make_polynomial_curve(int degree, const double* xyz, RationalCurve& out);
// Rational curve: xyzw holds degree+1 homogeneous coefficients (x,y,z,w).
Status make_rational_curve(int degree, const double* xyzw, RationalCurve& out);
// Rational Bezier curve on [u0,u1]: degree+1 control points and weights
// (weights may be null: all 1; non-positive weights are allowed but a zero
// of the weight inside the domain is reported when a surface is built).
Status make_bezier_curve(int degree, const double* ctrl, const double* weights,
                         double u0, double u1, RationalCurve& out);
// Line P + u d (d != 0).
Status make_line(const Vec3d& P, const Vec3d& d, RationalCurve& out);
// Constant point P.
Status make_point(const Vec3d& P, RationalCurve& out);
// Line element (P, t), t != 0.
Status make_line_element(const Vec3d& P, const Vec3d& t, RationalCurve& out);

// True if x is finite and |x| <= kMaxInputMagnitude.
inline bool input_ok(double x) {
  return std::isfinite(x) && std::abs(x) <= kMaxInputMagnitude;
}
inline bool input_ok(const Vec3d& v) {
  return input_ok(v.x()) && input_ok(v.y()) && input_ok(v.z());
}

}  // namespace v0
}  // namespace cyclide
