// Seed 002 (Hoffmann, Monterde, Troll 2015): blending two spheres by a
// rotation-minimizing surface, and skins of chains of spheres (SPEC.md §8g).
// Read with ERRATA.md §002: v = a (x - q), theta measured from the
// principal normal, the torsion sign, beta' and the validity a c > 0.
//
// The skin of two spheres touches each along a given circle (center p,
// radius r) whose tangent cone has its axis along the spine's end tangent
// t and its apex x = p + c t:
//   s(theta, t) = alpha(t) + lambda(t; theta) w(t; theta),          (§4)
// alpha the cubic Hermite spine (alpha(0) = p_i, alpha(1) = p_f,
// alpha' = t_i, t_f at the ends), w(t; theta) = cos theta W1(t) + sin theta
// W2(t) the rotation-minimizing transport of the start direction
// (W1' = -(W1 . alpha''/|alpha'|^2) alpha', W2 = t^ x W1: one RMF serves
// every theta), and lambda the cubic Hermite (6), (7), (8), (10) with the
// scalars a_i(theta), a_f(theta) of (9), (11). The sections t = const are
// not circles (lambda depends on theta through a_i, a_f), so the skin is a
// surface of its own, not a circle family.
//
// The RMF is not rational. Two integrators with error control: the
// reference reduces the RMF equation to its angle against an explicit
// frame (the minimal rotation of the piece's start tangent, on pieces where
// the tangent turns less than ~45 degrees), whose rate is explicit, and
// integrates that rate as a Chebyshev series (exact integration of the
// interpolant, degree doubled until the tail is below the tolerance);
// double reflection (Wang, Juttler, Zheng, Liu 2008) tabulates W1 on 256
// intervals with step doubling and is evaluated between the nodes by
// quintic Hermite interpolation of W1, W1', W1''. Allocation-free.
#pragma once

#include <cmath>
#include <cstddef>

#include "cyclide/status.hpp"
#include "cyclide/vec.hpp"

namespace cyclide {
inline namespace v0 {

// One end of a skin: the touching circle of a sphere and its tangent cone.
//   center   p, the circle's center
//   radius   r > 0
//   tangent  t: the cone's axis, and the spine's end tangent alpha'(end)
//            (its length is the Hermite tangent length; the circle lies in
//            the plane through p orthogonal to t; t points along the skin,
//            from the start sphere towards the end sphere)
//   inv_c    1/c with c t = x - p, x the cone's apex; 0: a cylinder (the
//            circle is a great circle of its sphere)
// The sphere touched along the circle has its center m = p + h t^ with
// h = -r^2 inv_c / |t| and radius sqrt(r^2 + h^2) (skin_end_sphere).
struct SkinEnd {
  Vec3d center = Vec3d::Zero();
  double radius = 0.0;
  Vec3d tangent = Vec3d::Zero();
  double inv_c = 0.0;
};

// The end from the cone's apex x (on the axis through p along t; a point
// off the axis by more than 1e-9 relative is invalid_argument, x = p too).
Status skin_end_from_apex(const Vec3d& center, double radius, const Vec3d& tangent,
                          const Vec3d& apex, SkinEnd& out);
// The end on the sphere (m, R) at the circle with center p (|p - m| < R;
// p - m parallel to t to 1e-9 relative, else invalid_argument).
Status skin_end_from_sphere(const Vec3d& sphere_center, double sphere_radius,
                            const Vec3d& center, const Vec3d& tangent, SkinEnd& out);
// The sphere of an end.
void skin_end_sphere(const SkinEnd& e, Vec3d& center, double& radius);

// The default tangent lengths: both |p_f - p_i| (the chord), directions,
// cones and spheres kept (1/c scales with the tangent). Ends with a zero
// tangent or coincident centers are left as they are.
void skin_chord_tangents(SkinEnd& start, SkinEnd& end);

// The cubic Hermite spine in power form: alpha(t) = c[0] + c[1] t + c[2] t^2
// + c[3] t^3 on [0, 1].
struct SkinSpine {
  Vec3d c[4];
  Vec3d point(double t) const { return c[0] + t * (c[1] + t * (c[2] + t * c[3])); }
  Vec3d d1(double t) const { return c[1] + t * (2.0 * c[2] + 3.0 * t * c[3]); }
  Vec3d d2(double t) const { return 2.0 * c[2] + 6.0 * t * c[3]; }
  Vec3d d3() const { return 6.0 * c[3]; }
};
SkinSpine make_skin_spine(const SkinEnd& start, const SkinEnd& end);
// Curvature of the spine at t (|alpha' x alpha''| / |alpha'|^3). At t = 0
// it is Remark 2's 2 |t_i x (3(p_f - p_i) - t_f)| / |t_i|^3.
double skin_spine_curvature(const SkinSpine& a, double t);

// How W1 is transported along the spine.
enum class RmfMethod : int {
  reference = 0,          // the angle's rate as a Chebyshev series (default)
  double_reflection = 1,  // Wang, Juttler, Zheng, Liu 2008
};

constexpr int kRmfIntervals = 256;     // double reflection: table intervals on [0, 1]
constexpr int kRmfMaxSubsteps = 256;   // double reflection: steps per interval (at most)
constexpr int kRmfMaxPieces = 16;      // reference: pieces of [0, 1]
constexpr int kRmfMaxDegree = 64;      // reference: Chebyshev degree per piece (at most)

// Reference: on [t0, t1], W1 = cos(phi) U + sin(phi) (b x U) with b the
// unit tangent, U(t) = u - ((b . u)/(1 + a . b)) (a + b) the minimal
// rotation of a = b(t0) onto b(t) applied to u = W1(t0), and phi(t) the
// Chebyshev series phi[0..degree] in x = (2t - t0 - t1)/(t1 - t0).
struct RmfPiece {
  double t0 = 0.0, t1 = 1.0;
  Vec3d a = Vec3d::Zero(), u = Vec3d::Zero();
  int degree = 0;
  double phi[kRmfMaxDegree + 2] = {};
};

struct RmfTable {
  RmfMethod method = RmfMethod::reference;
  int pieces = 0;  // reference
  RmfPiece piece[kRmfMaxPieces];
  // Double reflection: W1 at t_k = k / kRmfIntervals with W1' and W1''
  // (from the RMF equation).
  Vec3d w[kRmfIntervals + 1];
  Vec3d dw[kRmfIntervals + 1];
  Vec3d ddw[kRmfIntervals + 1];
  int substeps = 0;  // steps per interval (double reflection) or the largest degree (reference)
  double error_estimate = 0.0;  // estimated max |W1 - exact|
};

// Transports the unit vector w0 (orthogonal to alpha'(0); it is projected
// and normalized) along the spine, doubling the steps (double reflection)
// or the degree (reference) until the estimated error is <= tolerance
// (> 0). Statuses: invalid_argument (tolerance <= 0, w0 parallel to
// alpha'(0)), not_finite, zero_tangent (alpha' vanishes on [0, 1]),
// numerical_overflow (the tolerance is not met with kRmfMaxSubsteps steps
// per interval, degree kRmfMaxDegree or kRmfMaxPieces pieces; the table is
// not written).
Status transport_rmf(const SkinSpine& spine, const Vec3d& w0, RmfMethod method,
                     double tolerance, RmfTable& out);
// W1(t), W1'(t) (t in [0, 1]): reference, from the piece's angle series;
// double reflection, quintic Hermite between the nodes, projected
// orthogonal to alpha'(t) and normalized. W1' from the equation.
void rmf_at(const SkinSpine& spine, const RmfTable& table, double t, Vec3d& w1, Vec3d* dw1);

// Which points of the two circles the parameter curves theta = const join.
//  rmf: the rotation-minimizing transport (seed 002, §3.1 and §4).
//  kunkli_hoffmann: the baseline of §2 ([7]): q = p +- r e x t / |e x t| at
//    both ends (the sign by the angle between t and p_f - p_i), then both
//    rotated by theta about their axes.
//  cross_tangents: §2's q = p + r t_i x t_f / |t_i x t_f| at both ends.
// The baselines use the same spine and lambda, with w = the RMF turned by
// Delta (3 t^2 - 2 t^3) about the tangent, Delta the angle from the
// transported start point to the baseline's end point: the end conditions
// (4) hold (the extra turn starts and ends with zero rate) and the twist
// against the RMF is |Delta|.
enum class SkinPairing : int { rmf = 0, kunkli_hoffmann = 1, cross_tangents = 2 };

struct SkinOptions {
  SkinPairing pairing = SkinPairing::rmf;
  RmfMethod method = RmfMethod::reference;
  double tolerance = 1e-13;  // of the RMF table
  // The direction W1(0) of theta = 0 for the rmf pairing (projected
  // orthogonal to t_i); zero: the Kunkli-Hoffmann start point's direction,
  // so that theta means the same point at t = 0 for every pairing.
  Vec3d reference = Vec3d::Zero();
  // Kunkli-Hoffmann's e; zero: the coordinate axis least aligned with t_i
  // and t_f.
  Vec3d e = Vec3d::Zero();
};

struct SphereSkin {
  SkinEnd ends[2];
  SkinSpine spine;
  RmfTable rmf;
  SkinPairing pairing = SkinPairing::rmf;
  double delta = 0.0;       // the pairing's extra turn at t = 1 (0: rmf)
  double kappa[2] = {0, 0};  // spine curvature at t = 0, 1
  // a(theta) = A0 - (cos(theta + d) A1 + sin(theta + d) A2) per end (eqs.
  // (9), (11) with 1/c: a c = 1 + mu r, mu = -(w . alpha'')/|alpha'|^2;
  // d = 0 at the start, delta at the end).
  double a_coeff[2][3] = {{0, 0, 0}, {0, 0, 0}};
};

// The skin of start -> end. Statuses: null_argument never (references);
// not_finite (a non-finite or beyond-1e100 input); invalid_argument (radius
// <= 0, a bad tolerance, e parallel to an axis for kunkli_hoffmann, an
// unknown pairing or method); zero_tangent (t = 0 or alpha' = 0 on [0,1]);
// parallel_lines (cross_tangents with t_i parallel to t_f);
// nested_spheres (one end's sphere inside or equal to the other's);
// curvature_radius_too_large (kappa r >= 1 at an end: a c <= 0 for some
// theta, ERRATA.md: the skin folds there; Remark 2); numerical_overflow.
// out is written only on success.
Status make_sphere_skin(const SkinEnd& start, const SkinEnd& end, const SkinOptions& options,
                        SphereSkin& out);

// The skin with the start direction W1(0) = w0 given (chains pass the end
// frame on); options.reference is ignored.
Status make_sphere_skin_from(const SkinEnd& start, const SkinEnd& end, const Vec3d& w0,
                             const SkinOptions& options, SphereSkin& out);

// s(theta, t), ds/dtheta, ds/dt and the unit normal (ds/dtheta x ds/dt
// normalized: outward where lambda > 0), any output may be null. theta any
// finite number, t in [0, 1] (bad_domain outside). With normal requested,
// singular_point where |s_theta x s_t| <= 1e-14 |s_theta| |s_t|. Nothing
// is written on error.
Status skin_eval(const SphereSkin& S, double theta, double t, double* x, double* x_theta,
                 double* x_t, double* normal);
// The grid theta[i] x t[j] (ntheta values of theta, nt of t), row-major by
// t (index j * ntheta + i), 3 doubles per output point; x or normal may be
// null. The arguments (and for skins beyond 1e50, every point's finiteness:
// numerical_overflow) are validated before anything is written; normals
// at singular points are written as (0, 0, 0) and counted in *singular
// (may be null), as the circle-family grids do.
Status skin_eval_grid(const SphereSkin& S, const double* theta, int ntheta, const double* t,
                      int nt, double* x, double* normal, std::size_t* singular = nullptr);

// The largest magnitude among the spine's coefficients, the radii and
// a r (lambda's slopes): beyond 1e50 the grid validates every point
// before writing (evaluation may overflow: numerical_overflow).
double skin_magnitude(const SphereSkin& S);

// lambda(t; theta) and the end scalars a_i(theta), a_f(theta) (eqs. (9),
// (11)).
double skin_lambda(const SphereSkin& S, double theta, double t, double* a = nullptr);

// The skin as a trigonometric polynomial of degree 2 in theta (the exact
// export, skin_export.hpp): with c = cos theta, s = sin theta,
//   s(theta, t) = alpha(t) + (L0(t) + Lc(t) c + Ls(t) s) (c V1(t) + s V2(t)),
// L0, Lc, Ls the cubics of lambda (6)-(11) with a_f(theta) expanded by the
// addition theorem (L[a][k] the coefficient of t^k, a = 0, c, s), and V1,
// V2 the directions w(t; 0), w(t; pi/2) (W1, W2 turned by delta s(t)).
void skin_lambda_polynomials(const SphereSkin& S, double (&L)[3][4]);
// One of those cubics at t (Horner).
inline double skin_cubic_at(const double (&c)[4], double t) {
  return c[0] + t * (c[1] + t * (c[2] + t * c[3]));
}
// max over theta of |lambda(t; theta)| = |L0| + hypot(Lc, Ls).
inline double skin_lambda_max(const double (&L)[3][4], double t) {
  return std::abs(skin_cubic_at(L[0], t)) +
         std::hypot(skin_cubic_at(L[1], t), skin_cubic_at(L[2], t));
}
// V1(t), V2(t) (t in [0, 1], not checked).
void skin_directions(const SphereSkin& S, double t, Vec3d& V1, Vec3d& V2);

// The twist of the parameter curve theta against the RMF, measured on the
// evaluated surface: the integral over [0, 1] of |omega| with omega =
// ((s - alpha) x (s_t - alpha')) . t^ / |s - alpha|^2 (the rate at which
// the curve's direction from the spine turns about the tangent); 0 for the
// RMF pairing, |delta| for the baselines. Gauss-Legendre, 8 x 16 nodes.
Status skin_twist(const SphereSkin& S, double theta, double& twist);

// A chain of spheres: ends[0..n-1] (n >= 2) the touching circles, one per
// sphere, patch k from ends[k] to ends[k+1]; the start direction of patch
// k + 1 is the end direction of patch k, so theta-curves continue across
// the shared circles, and the patches join G^1 there (both are tangent to
// the cone along the circle). patches[0..n-2] written only on success;
// *bad_patch (may be null) names the failing patch.
Status make_sphere_skin_chain(const SkinEnd* ends, int n, const SkinOptions& options,
                              SphereSkin* patches, int* bad_patch = nullptr);

}  // namespace v0
}  // namespace cyclide
