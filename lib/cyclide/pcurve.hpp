// P-curves of seed 001 §3-4 and what they give a ringed surface
// R : (d, n, rho): a rational unit vector field f perpendicular to the
// orientation function n (eqs. (5), (6)), the rational curve c = d + rho f on
// R (eq. (4)), hence the rational parameterization (3) (ringed_dnr.hpp).
//  - spatial P-curves n = x conj-rotated from a quaternion polynomial,
//    eqs. (8)-(12) (Prop. 3.1);
//  - orientation functions whose projection along v is a planar P-curve,
//    eqs. (13)-(16) (Prop. 3.2);
//  - planar P-curves x = w^2 interpolating C^1 Hermite data, of degree 6
//    (eq. (43)) or as P-biarcs (eqs. (44)-(47)), and the two-surface blend
//    of §4 built from them (eqs. (36)-(39)).
// Polynomials are in power form in the parameter t; allocation-free.
#pragma once

#include <complex>

#include "cyclide/curve.hpp"
#include "cyclide/hermite.hpp"
#include "cyclide/surface.hpp"

namespace cyclide {
inline namespace v0 {

using Complex = std::complex<double>;

// Eqs. (8)-(11): for the quaternion polynomial x0 + x1 i + x2 j + x3 k, the
// P-curve n (8), its perpendicular companions n1 (10) and n2 (11), and the
// common norm sigma (9): |n| = |n1| = |n2| = sigma, pairwise orthogonal,
// det[n, n1, n2] = sigma^3.
struct PCurveFrame {
  CurvePoly n[3], n1[3], n2[3];
  CurvePoly sigma;
};
// degree_too_high if 2 deg x exceeds kMaxCurveDegree; not_finite for
// non-finite coefficients; invalid_argument if x is identically zero.
Status pcurve_frame(const CurvePoly (&x)[4], PCurveFrame& out);

// A rational vector field F(t) / w(t) in power form (the spherical curve f
// of eqs. (5), (12), (15), (23)).
struct RationalField {
  CurvePoly F[3];
  CurvePoly w;
};

// Eq. (12): f = (cos(phi) n1 + sin(phi) n2) / sigma, a unit field
// perpendicular to n for every phi.
RationalField pcurve_field(const PCurveFrame& P, double phi);

// q with q^2 = p (leading coefficient of q positive). False if p is not a
// square: its degree is odd, its leading coefficient negative, or the
// remainder p - q^2 exceeds `tol` relative to p's largest coefficient.
// *residual (may be null) receives that relative remainder.
bool poly_sqrt(const CurvePoly& p, CurvePoly& q, double tol = 1e-10, double* residual = nullptr);

// Eqs. (13)-(16): for the polynomial orientation function n (a polynomial
// curve) and the unit vector v, f = n x v / sigma with sigma^2 = |n|^2 -
// (n.v)^2 (eq. (14)); not_pythagorean if that is not a polynomial square
// (Prop. 3.2 does not apply), invalid_argument for a rational n or |v| != 1.
Status projection_field(const RationalCurve& n, const Vec3d& v, RationalField& out);

// Eq. (4): c = d + rho f with rho = rho_num / rho_den, as one rational
// curve (power form): (D rho_den w_f + w_d rho_num F) / (w_d rho_den w_f).
// d is a polynomial or rational curve (power or Bernstein form) or a point.
// degree_too_high beyond kMaxCurveDegree.
Status ringed_curve(const RationalCurve& d, const CurvePoly& rho_num, const CurvePoly& rho_den,
                    const RationalField& f, RationalCurve& c);

// Planar P-curve x = w^2 (eq. (40)), w of degree n <= 3 in Bernstein form
// on [0, 1] in the global parameter t (eq. (41); the P-biarc pieces use
// the same basis, eq. (44)).
struct PlanarPCurve {
  int n = 0;
  Complex w[4];
};

// Eq. (43): the C^1 Hermite interpolant of x(0) = p0, x'(0) = v0, x(1) = p1,
// x'(1) = v1 by a P-curve of degree 6 (n = 3); sign +1 or -1 chooses the
// branch of w2, w3 (+1: the "more suitable" one). not_pythagorean if p0 or
// p1 is 0 (no square root to divide by); invalid_argument for another sign.
Status planar_pcurve_hermite(Complex p0, Complex v0, Complex p1, Complex v1, int sign,
                             PlanarPCurve& out);
// Eqs. (44)-(47): the P-biarc, two quartic P-curves joining C^1 at t = tau
// in (0, 1) (out[0] on [0, tau], out[1] on [tau, 1]); statuses as above,
// bad_domain for tau outside (0, 1).
Status planar_pbiarc(Complex p0, Complex v0, Complex p1, Complex v1, double tau, int sign,
                     PlanarPCurve (&out)[2]);
// x = w^2 = (x1, x2) and sigma = |w|^2 = |x| in power form.
void planar_pcurve_polys(const PlanarPCurve& P, CurvePoly& x1, CurvePoly& x2, CurvePoly& sigma);

// Hermite data of a ringed surface (d, n, rho) at a join (eq. (37)).
struct RingedJet {
  Vec3d d = Vec3d::Zero(), dd = Vec3d::Zero();  // d, d'
  Vec3d n = Vec3d::Zero(), dn = Vec3d::Zero();  // n, n'
  double rho = 0.0, drho = 0.0;                 // rho, rho'
};

// The jet of a circle-family surface at u: d = circle center, n = the
// frame's axis (with its length), rho = radius (rho' = (rho rho')/rho).
Status ringed_jet(const Surface& S, double u, RingedJet& out);

// The two-surface blend of §4 on t in [0, 1]: (d, n.v, rho) by a Ferguson
// cubic (38), the projection of n onto the plane perpendicular to v by a
// planar P-curve (39): of degree 6 (43) if tau = 0, else a P-biarc (47)
// joining at tau; f = n x v / sigma (15), c = d + rho f (4), surface (3).
// One piece (tau = 0) on [0, 1] or two on [0, tau], [tau, 1]; *count is
// set to the number written. C^1 in the circle family at both ends (the
// circles' d, n, rho are C^1; n's length is part of the data). Statuses of
// the pieces above and of make_ringed (with *bad_u); nothing is written
// on error.
struct RingedBlendOptions {
  int sign = 1;                  // branch of (43) / (47)
  double tau = 0.0;              // 0: degree 6; in (0, 1): P-biarc
  Vec3d v = Vec3d::UnitZ();      // the projection direction (unit)
};
Status make_ringed_pcurve_blend(const RingedJet& a, const RingedJet& b,
                                const RingedBlendOptions& options, Surface (&pieces)[2],
                                int& count, double* bad_u = nullptr);

}  // namespace v0
}  // namespace cyclide
