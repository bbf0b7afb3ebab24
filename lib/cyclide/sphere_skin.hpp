// Seed 002 (Hoffmann, Monterde, Troll 2015): blending two spheres by a
// rotation-minimizing surface, and skins of chains of spheres (SPEC.md §9).
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
// The RMF is not rational: it is tabulated on 256 intervals by one of two
// integrators with error control (double reflection, Wang-Juttler-Zheng-Liu
// 2008; or the reference: RK4 with Richardson extrapolation on the RMF
// equation) and evaluated between the nodes by quintic Hermite
// interpolation of W1, W1', W1'' (exact from the equation). Allocation-free.
#pragma once

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
  reference = 0,          // RK4 + Richardson on the RMF equation (default)
  double_reflection = 1,  // Wang, Juttler, Zheng, Liu 2008
};

constexpr int kRmfIntervals = 256;     // table intervals on [0, 1]
constexpr int kRmfMaxSubsteps = 256;   // integration steps per interval (at most)

// W1 at t_k = k / kRmfIntervals with W1' and W1'' (from the RMF equation).
struct RmfTable {
  Vec3d w[kRmfIntervals + 1];
  Vec3d dw[kRmfIntervals + 1];
  Vec3d ddw[kRmfIntervals + 1];
  RmfMethod method = RmfMethod::reference;
  int substeps = 0;             // integration steps per interval used
  double error_estimate = 0.0;  // estimated max |W1 - exact| at the nodes
};

// Transports the unit vector w0 (orthogonal to alpha'(0); it is projected
// and normalized) along the spine, doubling the steps until the estimated
// error is <= tolerance (> 0). Statuses: invalid_argument (tolerance <= 0,
// w0 parallel to alpha'(0)), not_finite, zero_tangent (alpha' vanishes on
// [0, 1]), numerical_overflow (the tolerance is not met with
// kRmfMaxSubsteps steps per interval; the table is not written).
Status transport_rmf(const SkinSpine& spine, const Vec3d& w0, RmfMethod method,
                     double tolerance, RmfTable& out);
// W1(t), W1'(t) (t in [0, 1]): quintic Hermite between the nodes,
// projected orthogonal to alpha'(t) and normalized; W1' from the equation.
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
// finite number, t in [0, 1] (bad_domain outside). singular_point where
// |s_theta x s_t| <= 1e-14 |s_theta| |s_t| (only the normal is then not
// written... nothing is written on error).
Status skin_eval(const SphereSkin& S, double theta, double t, double* x, double* x_theta,
                 double* x_t, double* normal);
// The grid theta[i] x t[j] (nt values of theta, nu of t), row-major by t
// (index j * ntheta + i), 3 doubles per output point. all-or-nothing: on
// a singular point singular_point is returned, on values beyond the range
// numerical_overflow, as skin_eval at that point (with *bad = the index).
Status skin_eval_grid(const SphereSkin& S, const double* theta, int ntheta, const double* t,
                      int nt, double* x, double* normal, int* bad = nullptr);

// lambda(t; theta) and the end scalars a_i(theta), a_f(theta) (eqs. (9),
// (11)).
double skin_lambda(const SphereSkin& S, double theta, double t, double* a = nullptr);

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
