// Exact polynomial numerators and denominators of the circle frames
// (seed 000 §2: c, n, rho^2 and s, r^2 are rational). The evaluator does
// not use them (it evaluates the planes numerically, which is better
// conditioned); they exist for exact export (rational Bezier patches) and
// to check the constructions against the papers' closed forms.
//
// Rational inputs p_i = P_i / w_i are handled homogeneously: each plane row
// is multiplied by the denominators it carries, so the spine / directrix is
// N(u) / D(u) with polynomial N, D. Bounds: for inputs of degree d the
// PRCS spine has degree <= 10d - 4 (polynomial inputs: 4d - 2), the PRRS
// directrix <= 12d; kMaxExactDegree = 160 covers PRCS for d <= 15 and
// PRRS for d <= 13. Exceeding it reports degree_too_high.
#pragma once

#include "cyclide/config.hpp"
#include "cyclide/curve.hpp"
#include "cyclide/poly.hpp"
#include "cyclide/status.hpp"

namespace cyclide {
inline namespace v0 {

using ExactPoly = Poly<double, kMaxExactDegree>;

// (x(u), y(u), z(u)) / w(u).
struct ExactVec3 {
  ExactPoly x, y, z, w;
  Vec3d operator()(double u) const {
    const double W = w(u);
    return Vec3d(x(u) / W, y(u) / W, z(u) / W);
  }
};

// The exact frame of a circle family with f = v: axis point o, axis a,
// generator p (all as ExactVec3), and the squared sphere radius
// r^2 = |p - o|^2 = r2_num / r2_den (for PRCS, the canal radius).
struct ExactFrame {
  ExactVec3 o, a, p;
  ExactPoly r2_num, r2_den;
};

// The frames in the variable t with u = mid + half t (default: t = u).
// Evaluating in a domain-local t (the domain becomes [-1, 1]) keeps the
// power form well conditioned for the compiled frames (compiled_frame.hpp).
// `a` is always d/du (PRCS: s'(u) = (ds/dt) / half).
Status exact_prcs_frame(const RationalCurve& p1, const RationalCurve& p2, ExactFrame& out,
                        double mid = 0.0, double half = 1.0);
Status exact_prrs_frame(const RationalCurve& p1, const RationalCurve& p2,
                        const RationalCurve& p3, ExactFrame& out, double mid = 0.0,
                        double half = 1.0);

// The ringed surface (d, n, c) of seed 001 eq. (3): o = d, a = n, p = c.
Status exact_ringed_frame(const RationalCurve& d, const RationalCurve& n,
                          const RationalCurve& c, ExactFrame& out, double mid = 0.0,
                          double half = 1.0);

// The cross-multiplied identity a.num * b.den == b.num * a.den, coefficient
// by coefficient, relative to the largest coefficient (tests use it to
// compare with the papers' closed forms without normalizing factors).
double cross_identity_residual(const ExactVec3& a, const ExactVec3& b);

}  // namespace v0
}  // namespace cyclide
