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

// The polynomials are in the local variable t = (u - origin) / scale:
// Bezier and Hermite curves put t = -1..1 on their interval, which keeps
// the power form well conditioned for high degrees (power form about u = 0
// on [0.5, 1.5] loses 1e-8 at degree 15; the local form keeps ~1e-14).
struct RationalCurve {
  CurveKind kind = CurveKind::rational;
  CurvePoly x, y, z, w;  // homogeneous numerator (x, y, z) and weight w, in t
  double origin = 0.0, scale_u = 1.0;  // t = (u - origin) / scale_u
  Vec3d tangent = Vec3d::Zero();  // line elements only

  int degree() const;
  bool is_polynomial() const { return w.deg == 0; }

  // p(u + h) as a Taylor series to order N: the point and its derivatives
  // p^(k)(u) / k!. Constant kinds have zero derivatives (ERRATA: a line
  // element's point has derivative zero; its tangent is separate).
  template <int N, class S>
  Vec3<Taylor<S, N>> taylor(const S& u) const {
    const S t = (u - S(origin)) / S(scale_u);
    Taylor<S, N> X = x.taylor<N>(t), Y = y.taylor<N>(t), Z = z.taylor<N>(t),
                 W = w.taylor<N>(t);
    // d/du = (1/scale_u) d/dt: coefficient k scales by scale_u^-k.
    S f(1);
    for (int k = 1; k <= N; ++k) {
      f = f / S(scale_u);
      X.c[k] *= f;
      Y.c[k] *= f;
      Z.c[k] *= f;
      W.c[k] *= f;
    }
    return Vec3<Taylor<S, N>>(X / W, Y / W, Z / W);
  }
  Vec3d point(double u) const {
    const double t = (u - origin) / scale_u;
    const double W = w(t);
    return Vec3d(x(t) / W, y(t) / W, z(t) / W);
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
