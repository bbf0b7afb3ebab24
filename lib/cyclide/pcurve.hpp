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
#include "cyclide/ringed.hpp"
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

// Example 3.3, eqs. (17)-(19): for a quadratic (or linear, or constant)
// polynomial orientation function n = a t^2 + b t + c, the unit directions
// v for which |n x v|^2 = |n|^2 - (n.v)^2 is a polynomial square, so that
// Prop. 3.2 applies. The projection of n onto the plane perpendicular to v,
// written in the complex coordinate z(x) = x.e for an isotropic e = e1 + i e2
// (e1, e2 an orthonormal basis of that plane), is p(t) = A t^2 + B t + C;
// |p|^2 is a square iff p = A (t - r)^2 (or is constant), i.e. iff the
// discriminant B^2 - 4AC = e^T M e vanishes, M = b b^T - 2 (a c^T + c a^T).
// With M's eigenvalues l1 >= l2 >= l3 (eigenvectors q1, q2, q3), the
// isotropic solutions are e = sqrt(l2 - l3) q1 +- i sqrt(l1 - l3) q2 +
// sqrt(l1 - l2) q3 (up to signs), whose plane has the real normal
// v = sqrt(l2 - l3) q3 -+ sqrt(l1 - l2) q1 (normalized): a real solution
// exists for every quadratic n, as the paper states. Writes the distinct
// directions (1 or 2) that pass projection_field's square-root test to
// v[0..count-1]. invalid_argument for a rational n (its numerator is taken
// when its weight is constant) or degree > 2; not_pythagorean if no candidate
// passes (rounding on nearly repeated eigenvalues).
Status quadratic_projection_directions(const RationalCurve& n, Vec3d (&v)[2], int& count);

// Eqs. (20)-(23) for any polynomial (or rational: its numerator N spans the
// same planes) orientation function n: a sum of squares |N|^2 = g1^2 + g2^2
// (21), the stereographic image h = s + g/n3 (20), (22) and its inverse
// (23), written with H = g - (n1, n2) as
//   f = (2 H1 n3, 2 H2 n3, |H|^2 - n3^2) / (|H|^2 + n3^2),
// a rational unit field with f.n = 0. The SOS is NUMERICAL: g1 + i g2 =
// sqrt(lead) prod (t - z_k) over the roots z_k of |N|^2 in the upper half
// plane (companion-matrix eigenvalues, Eigen, polished by Newton), so |f| = 1
// and f.n = 0 hold to the reported relative remainder of |g|^2 - |N|^2. The
// pole of the stereographic projection (the z, x or y axis) and a constant
// rotation g -> e^{i theta} g are chosen so that the denominator stays away
// from zero at the real roots of n3 (the only places it can vanish).
struct SosFieldReport {
  double residual = 0.0;  // max |coef(|g|^2 - |N|^2)| / max |coef(|N|^2)|
  double margin = 0.0;    // min over real roots of n3 of (|H|^2 + n3^2) / |N|^2, in [0, 4]; 4 if none
  int pole_axis = 2;      // 0, 1, 2: stereographic pole on the x, y, z axis
  double theta = 0.0;     // the rotation of g
};
// degree_too_high if 2 deg N > kMaxCurveDegree; invalid_argument for n = 0
// or a point/line element; not_finite for non-finite coefficients;
// not_pythagorean if the remainder exceeds 1e-8 (roots too ill-conditioned)
// or the denominator vanishes somewhere for every pole and rotation.
Status sos_field(const RationalCurve& n, RationalField& out, SosFieldReport* report = nullptr);

// How make_ringed_dnr finds the rational unit field f perpendicular to n.
enum class RingedFieldMethod : int {
  automatic = 0,   // an exact route if one exists, else sos: projection along
                   // e3, e1, e2 (Prop. 3.2), then Example 3.3 for deg n <= 2
  projection = 1,  // Prop. 3.2 along options.v
  quadratic = 2,   // Example 3.3 (deg n <= 2): solution options.which of v
  sos = 3,         // eqs. (20)-(23), numerical
};
struct RingedFieldOptions {
  RingedFieldMethod method = RingedFieldMethod::automatic;
  Vec3d v = Vec3d::UnitZ();  // projection: any nonzero length
  int which = 0;             // quadratic: 0 or 1 (if two solutions)
};
struct RingedFieldReport {
  RingedFieldMethod method = RingedFieldMethod::automatic;  // the route taken
  Vec3d v = Vec3d::Zero();  // projection / quadratic: the direction used
  int directions = 0;       // quadratic: the number of solutions found
  SosFieldReport sos;       // sos: the SOS step's accuracy (zeros otherwise)
};
// The field f of n by the chosen method. invalid_argument: v = 0, which
// not 0/1 or beyond the solutions found, quadratic for deg n > 2; then
// the statuses of projection_field, quadratic_projection_directions and
// sos_field.
Status ringed_field(const RationalCurve& n, const RingedFieldOptions& options, RationalField& f,
                    RingedFieldReport* report = nullptr);

// The ringed surface R : (d, n, rho), rho = rho_num / rho_den, as the
// rational surface (3) through c = d + rho f (4) with f = ringed_field(n):
// Props. 3.1/3.2, Example 3.3, Theorem 3.5. Statuses of ringed_field,
// ringed_curve and make_ringed (*bad_u where the domain scan fails: where
// sigma or the SOS denominator vanishes the field is undefined and c
// escapes, reported as that scan's status). `automatic` tries the routes
// (projection along e3, e1, e2; Example 3.3's two directions; SOS) until
// one gives a surface on the whole domain, and reports the first failure
// of a route whose field existed if none does.
Status make_ringed_dnr(const RationalCurve& d, const RationalCurve& n, const CurvePoly& rho_num,
                       const CurvePoly& rho_den, const RingedFieldOptions& options,
                       const Mobius* circle_f, double u0, double u1, Surface& out,
                       RingedFieldReport* report = nullptr, double* bad_u = nullptr);

// §3.d, Theorem 3.6: the ringed surface R : (d, n, rho = sqrt(R)), R =
// R_num / R_den >= 0 a rational function that need not be a square (as for
// a canal surface seen as ringed, eq. (24)). f with n.f = 0 and f.f = R (25)
// is found as f = (a u + b n x u) / (c R_den), u = ringed_field(n, options)
// a unit field perpendicular to n, and a, b, c polynomials solving the conic
// a^2 + |n|^2 b^2 = R_num R_den c^2 over R[t] (the paper's (34)-(35)). The
// conic is solved NUMERICALLY (roots of |n|^2 and R_num R_den by the
// companion matrix, then a null space and an isotropic vector; see
// ringed_sqrt.cpp), so |f|^2 = R holds to the reported residual; f.n = 0 is
// exact when u is. When R_num R_den is a square, rho is rational and f =
// sqrt(R_num R_den) u / R_den (exact_square).
struct RingedSqrtReport {
  RingedFieldReport field;    // how u was found
  bool exact_square = false;  // R_num R_den was a polynomial square
  double residual = 0.0;      // max|coef(a^2 + N b^2 - P c^2)| / max of the terms' coefs
  int conic_degree = 0;       // deg of G N1 P1, the reduced conic (ringed_sqrt.cpp)
};
// invalid_argument: R_num or R_den zero, n a point/line element or zero;
// not_finite; empty_real_locus: R < 0 somewhere on R (odd-multiplicity real
// root, negative leading coefficient or odd degree of R_num R_den);
// degree_too_high: R_num R_den or 2 deg n beyond 14, or f beyond
// kMaxCurveDegree; not_pythagorean: the numerical conic step failed (its
// remainder exceeded 1e-8); and the statuses of ringed_field.
Status sqrt_radius_field(const RationalCurve& n, const CurvePoly& R_num, const CurvePoly& R_den,
                         const RingedFieldOptions& options, RationalField& f,
                         RingedSqrtReport* report = nullptr);
// (26): c = d + f and the surface (3) through it; statuses of
// sqrt_radius_field, ringed_curve and make_ringed (*bad_u).
Status make_ringed_sqrt(const RationalCurve& d, const RationalCurve& n, const CurvePoly& R_num,
                        const CurvePoly& R_den, const RingedFieldOptions& options,
                        const Mobius* circle_f, double u0, double u1, Surface& out,
                        RingedSqrtReport* report = nullptr, double* bad_u = nullptr);

// Prop. 3.1: the ringed surface whose orientation function is the P-curve
// n of the quaternion polynomial x (8), with f = (cos phi n1 + sin phi n2)
// / sigma (12). Statuses of pcurve_frame, ringed_curve and make_ringed.
Status make_ringed_pcurve(const RationalCurve& d, const CurvePoly (&x)[4], double phi,
                          const CurvePoly& rho_num, const CurvePoly& rho_den,
                          const Mobius* circle_f, double u0, double u1, Surface& out,
                          double* bad_u = nullptr);

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
// The same from ringed data (rho^2 > 0 assumed).
RingedJet ringed_jet_from(const RingedData& R);

// The two-surface blend of §4 on t in [0, 1]: (d, n.v, rho) by a Ferguson
// cubic (38), the projection of n onto the plane perpendicular to v by a
// planar P-curve (39): of degree 6 (43) if tau = 0, else a P-biarc (47)
// joining at tau; f = n x v / sigma (15), c = d + rho f (4), surface (3).
// One piece (tau = 0) on [0, 1] or two on [0, tau], [tau, 1]; *count is
// set to the number written. C^1 in the circle family at both ends (the
// circles' d, n, rho are C^1; n's length is part of the data). Statuses of
// the pieces above and of make_ringed (with *bad_u); nothing is written
// on error.
// §5, eqs. (50)-(52), (57): a bump added to the blend's directrix,
// d* = d + w b(t) (the paper's (50) calls w "v"; here v is the projection
// direction of (15)). b(0) = b'(0) = b(1) = b'(1) = 0 (51), b(tau) = 1 and
// b'(tau) = 0: single = (52) with the sign of ERRATA.md (as printed (52)
// is -1 at tau and Example 5.2 does not reproduce), a quintic; two_piece =
// (57), cubics on [0, tau] and [tau, 1] (the blend is then split at tau).
// Only d moves: n, rho and f are kept, so c* = c + w b and the circles are
// translated — still an exact rational ringed surface.
enum class BumpKind : int { single = 0, two_piece = 1 };
struct DirectrixBump {
  Vec3d w = Vec3d::Zero();  // displacement at t = tau (zero: no bump)
  double tau = 0.5;         // in (0, 1)
  BumpKind kind = BumpKind::single;
};
// The bump's polynomials on [0, tau] and [tau, 1] (equal for single).
void bump_polys(const DirectrixBump& bump, CurvePoly& left, CurvePoly& right);

struct RingedBlendOptions {
  int sign = 1;                  // branch of (43) / (47)
  double tau = 0.0;              // 0: degree 6; in (0, 1): P-biarc
  Vec3d v = Vec3d::UnitZ();      // the projection direction (unit)
  DirectrixBump bump;            // §5: none by default
};
Status make_ringed_pcurve_blend(const RingedJet& a, const RingedJet& b,
                                const RingedBlendOptions& options, Surface (&pieces)[2],
                                int& count, double* bad_u = nullptr);
// The condition kappa of the blend's planar part x = w^2 (the projection of
// n): its largest coefficient over the least |x| = sigma on the pieces. The
// circles (d, n, rho) carry rounding of about 5 eps kappa, their
// derivatives about 14 eps kappa^1.5; make_ringed_pcurve_blend refuses
// kappa > 1e5 with not_pythagorean (n nearly parallel to v at an end, where
// w is small and w' = v/(2w) large, or inside, where w passes near 0).
// Statuses of the planar part; the jets' values are not validated
// (make_ringed_pcurve_blend does).
Status ringed_pcurve_blend_condition(const RingedJet& a, const RingedJet& b,
                                     const RingedBlendOptions& options, double& kappa);

// Eq. (54) on any circle-family surface (d = the circle's center, rho its
// radius): the clearance min over [u0, u1] of |d(t) - s| - rho(t) - r from
// the sphere (s, r) — positive: no circle meets the sphere (a sufficient
// test, as the paper says). 257 samples, then golden-section refinement
// of the best bracket (1e-12 in t). *at_u receives the minimizer.
// invalid_argument for r < 0; statuses of Surface::ringed.
Status sphere_clearance(const Surface& S, const Vec3d& s, double r, double& clearance,
                        double* at_u = nullptr);
// Eq. (58): the deviance of the directrix tangents from the circle axes,
// the integral over [u0, u1] of sin^2 angle(n, d') (transcription note 8:
// (58)'s integrand for any f perpendicular to n), by composite Simpson on
// 1024 intervals (error ~1e-12 for the blends here). singular_point where
// d' = 0 (the angle is undefined); statuses of Surface::ringed.
Status normal_deviance(const Surface& S, double& value);

}  // namespace v0
}  // namespace cyclide
