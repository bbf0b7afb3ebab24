// Exact rational tensor-product Bezier export of circle-family surfaces
// (issue 9 item 1): kinds prcs, prrs and ringed through their exact frames
// (E1)-(E6), kinds dupin and parabolic through closed forms of bidegree
// (2, 2) (E7)-(E9); and the assembly of one export's patches into a
// tensor-product NURBS (N1)-(N4) below.
//
// Math (the equation numbers (E1)..(E6) are referred to in
// lib/src/rational_export.cpp). With the exact frame of exact.hpp
//   o = O / wo,  a = A / wa,  p = P / wp          (polynomials in u)
// and f(u, v) = (alpha v + beta) / (gamma v + delta):
//   (E1) q = W + G a, W = alpha v + beta, G = gamma v + delta, rotates
//        d = p - o about a (circle_family.hpp); scaling q by wa gives the
//        same rotation with a polynomial quaternion q' = W wa + G A.
//   (E2) p - o = D / (wo wp),  D = P wo - O wp.
//   (E3) R(D) = N(v) / Q(v) with N = N0 + N1 v + N2 v^2, Q = Q0 + Q1 v + Q2 v^2
//        the numerator and denominator of circle_quadratic for the frame
//        (o = 0, a = A, p = D, alpha wa, beta wa, gamma, delta):
//          Q_k = W2_k + G2_k |A|^2,
//          N_k = (W2_k - G2_k |A|^2) D + 2 G2_k (A.D) A + 2 WG_k (A x D),
//        W2, G2, WG the v-coefficients of W'^2, G^2 and W' G (W' = W wa).
//   (E4) x = o + R(p - o) = [O wp Q + N] / (wo wp Q): the homogeneous point
//        X_h(u, v) = sum_k (wo wp Q_k, O wp Q_k + N_k) v^k,
//        of degree m in u and 2 in v, where (n_x = the largest degree of the
//        numerators and the weight of x, n_f that of alpha..delta)
//          m = n_o + n_p + 2 (n_a + n_f).
//        Examples with f = v (tests/rational_export_test.cpp pins them):
//        PRCS of Example 2's lines 5, of two polynomial cubics 43 (spine
//        10, s' 15); PRRS of three polynomial cubics 30; ringed (d, n, c) of
//        degrees (3, 2, 3): 10; PRRS of three rational cubics 66; PRCS of
//        two rational cubics <= 26 + 3 + 2 * 52 = 133. A Mobius f of degree
//        n_f adds 2 n_f. The degrees are those of exact.hpp's frames, whose
//        leading coefficients below 1e-14 of the largest are dropped, so a
//        short u-interval may give a lower m. Not always the minimal degree
//        (Example 2 gives (5, 2); its closed form (23) has (3, 2)).
//   (E5) v-pieces: Bernstein of degree 2 on [v0, v1]; |v| > 1 is written in
//        w = 1/v (the evaluator's convention): X_h w^2 = X2 + X1 w + X0 w^2.
//        The initial cuts are v = +-1 and, when the circle parameter's own
//        scale c (the geometric mean over the samples of |B| / |A|, q(v) =
//        A v + B the half-angle vector below; |a| for f = v) is far from 1
//        (|log2 c| > 3), also v = +-c: a model scaled by s has PRCS's v ->
//        s v, and without the cut at c the arc bisection would need about
//        |log2 s| levels.
//        Each piece is an arc of less than 120 degrees of every circle
//        (checked at 65 values of u), so its middle weight
//        <q(v0), q(v1)> = |q0||q1| cos(arc/2) is positive.
//   (E6) u: all polynomials are converted to Bernstein form on [u0, u1]
//        first (power form -> Bernstein by Horner in the Bernstein basis,
//        stable: see bernstein_from_power) and multiplied there with the
//        binomially weighted product, in long double (x86: 64-bit
//        mantissa; the numerators O wp Q + N are differences of terms of
//        the frame's size |o| + |p - o|, which can exceed |x| many times);
//        a u-interval is bisected (de Casteljau) until every weight of
//        every v-piece is positive.
//   (E7) parabolic (seed 004 (4.1)): Surface::eval reproduces (4.1)
//        (parabolic_frame, f = v), so the homogeneous point is
//          X_h(u, v) = (phi0, origin phi0 + frame (phi1, phi2, phi3)),
//          phi = (1 + u^2 + v^2, a u + (a - b) u v^2, b v + (b - a) u^2 v,
//                 a u^2 + b v^2),
//        of degree (2, 2), with weight phi0 = 1 + u^2 + v^2 > 0 (the frame
//        route (E4) would give m = 6 = n_o 3 + n_p 1 + 2 n_a 1, with the
//        common factor wo = 2 (1 + u^2)).
//   (E8) dupin (seed 003 (25)-(30), ERRATA.md's signs; dupin.hpp): with
//        xi = x0 : x1, x0 = xm0 u + xm1, x1 = xm2 u + xm3 and zeta = z0 : z1,
//        z0 = zm0 v + zm1, z1 = zm2 v + zm3 (DupinView's maps),
//          a(u) = theta(2 x0 x1 e1 + (x1^2 - x0^2) e2 + (x1^2 + x0^2) e-)  (29)
//          b(v) = theta(2 z0 z1 e3 + (z1^2 - z0^2) e+ + (z1^2 + z0^2) er)  (30)
//        are quadratic in u and in v, and (25) c^ = (er.a) b - (er.b) a
//        (er.x = -x_r) is bilinear in them: degree (2, 2). (26)-(27): x =
//        c^_123 / w + origin with w = -c^.n_inf = c^_- - c^_+, so
//          X_h(u, v) = (w, c^_123 + origin w).
//        Surface::eval(u, v) = c(xi(u), zeta(v)) (DupinView), so X_h is the
//        surface exactly; no frame (circumcentre, axis) enters, which is
//        why it is often better conditioned than the evaluator (a random
//        cyclide whose zeta map squeezed most of a circle into a short
//        v-interval: patches within 2e-10 of dupin_eval_homogeneous,
//        Surface::eval off by 1e-9; worse ones fail the check below).
//        u is taken as mid + half t (t in [-1, 1]), the coefficients formed
//        in long double.
//   (E9) In (E7)/(E8), v -> X_h(u, v) is a quadratic parameterization of
//        the same circle as (E3), so X_h = lambda(u) (Q, Q o + N) (the
//        circle's rational quadratic form is unique up to a factor); thus
//        the piece weights (E5) are lambda(u) times <q(v0), q(v1)> etc.,
//        and (E5)/(E6) apply unchanged: the arc test uses Surface::frame at
//        the 65 samples (a frame failing there, e.g. point_at_infinity or
//        singular_point, is returned), the pole test the sign of X_h's
//        weight at v = 1 (lambda(u) Q(u, 1), Q > 0).
//
// Degrees: deg_u = max(m, 1) <= kMaxExportDegree (else degree_too_high;
// m = 0, one circle for every u, is written as degree 1), deg_v = 2;
// dupin and parabolic: deg_u = 2 (E7)/(E8).
// Patches: the v-pieces (at least one per part of [v0, v1] split at v = -1
// and 1, and at +-c (E5); a whole circle has at least 4) times the u-intervals (at least 1),
// in u-major order (all v-pieces of the first u-interval, then the next);
// a u-interval is bisected at most kMaxExportDepth times, a v-piece as well.
// Accuracy: exact up to rounding. The exact frames are power forms (in t on
// [-1, 1] over [u0, u1]), which lose accuracy at high degree; so every
// patch is checked against Surface::eval at 3 x 3 points (error <=
// kExportCheckTol times the largest |x| there, else numerical_overflow).
// The tests find ~5e-16 relative to |x| for polynomial cubic inputs
// (<= 1e-12 over 120000 random well-conditioned cases), ~6e-14 for the
// degree-63 pieces of a rational quartic PRCS.
// Dupin and parabolic: ~3e-15 (dupin) and ~4e-16 (parabolic) relative in
// the tests, 20000 random cases each within 1e-12 (test property, which
// draws cyclides of bounded frames and a uniform enough circle parameter).
// Allocation: none (evaluation tier); the caller owns the patch array.
// Stack: about 320 KB at the deepest (GCC -O2: export 81 KB, the products
// 151 KB in long double, exact_prrs_frame 76 KB).
// Work: ~60 Bernstein products of degree <= m (O(m^2) each), O(m^2) per
// u-bisection and per patch, 9 Surface::eval per patch.
#pragma once

#include "cyclide/config.hpp"
#include "cyclide/status.hpp"
#include "cyclide/surface.hpp"

namespace cyclide {
inline namespace v0 {

// Largest degree in u of an exported patch (E4): PRCS of rational cubics
// need <= 133 (131 measured), PRRS of rational cubics 66, polynomial cubic
// inputs <= 43; a Mobius f of degree n_f adds 2 n_f. A patch is 15.5 KB.
constexpr int kMaxExportDegree = 160;
// Bisections of a u-interval or a v-piece.
constexpr int kMaxExportDepth = 16;
// Most v-pieces (u-intervals) of one export.
constexpr int kMaxExportVPieces = 128;
constexpr int kMaxExportUPieces = 512;
// Largest degree along v: 2 for circle families, 4 for sphere skins
// (skin_export.hpp). A patch holds at most kPatchControlPoints control
// points, (deg_u + 1)(deg_v + 1) <= kPatchControlPoints.
constexpr int kMaxExportDegreeV = 4;
constexpr int kPatchControlPoints = (kMaxExportDegree + 1) * 3;
// Patches must reproduce Surface::eval to this, relative to their size.
constexpr double kExportCheckTol = 1e-9;

struct RationalBezierPatch {
  int deg_u = 0, deg_v = 2;
  // The parameter rectangle covered, v in the surface's v. The local
  // parameters (s, t) in [0, 1]^2 map to u = u0 + s (u1 - u0) and
  //   v = v0 + t (v1 - v0)                 if !reciprocal_v,
  //   1/v = (1 - t)/v0 + t/v1              if reciprocal_v (|v| >= 1; v0 or
  //                                        v1 may be -inf or +inf, 1/inf = 0).
  // In both cases v increases with t (the orientation of the surface).
  double u0 = 0, u1 = 1, v0 = 0, v1 = 1;
  bool reciprocal_v = false;
  // Homogeneous control point (w, w x, w y, w z) of (i, j), i = 0..deg_u,
  // j = 0..deg_v, at cp[i * (deg_v + 1) + j]. Every w > 0.
  double cp[kPatchControlPoints][4];
};

// What to export: u in [u0, u1] (inside the surface's domain) and v in
// [v0, v1] (finite), or, with whole_circle, v over R and infinity.
struct ExportDomain {
  double u0 = 0, u1 = 1, v0 = -1, v1 = 1;
  bool whole_circle = false;
  static ExportDomain rectangle(double ua, double ub, double va, double vb) {
    return {ua, ub, va, vb, false};
  }
  static ExportDomain circles(double ua, double ub) { return {ua, ub, 0, 0, true}; }
};

// The patches of S over D into out[0..cap). Statuses: ok (count written);
// invalid_argument (an unknown kind); not_finite (a NaN or infinite bound);
// bad_domain (not u0 < u1 inside the surface's domain, not v0 < v1);
// degree_too_high (m >
// kMaxExportDegree, or the exact frame's own bound); point_at_infinity (the
// weight wo wp changes sign or vanishes at one of 65 values of u in
// [u0, u1] -- a pole the builder's samples may have missed -- or the
// weights keep both signs after kMaxExportDepth bisections where wo wp
// changes sign); numerical_overflow (weights not positive after
// kMaxExportDepth bisections otherwise, piece limits exceeded, or the check
// against Surface::eval failed); Surface::eval's status where it fails at a
// check point; dupin and parabolic: Surface::frame's status where it fails
// at one of the 65 samples (E9: point_at_infinity, singular_point, ...); buffer_too_small (count = the number needed, nothing
// written; out may be null with cap = 0); null_argument (out null, cap >=
// count). On every other status count is 0. out is written only after
// every patch was built and checked (two passes): never half-written.
Status export_rational_bezier(const Surface& S, const ExportDomain& D, RationalBezierPatch* out,
                              int cap, int& count);

// The number of patches export_rational_bezier writes for (S, D): its
// statuses but buffer_too_small and those of the check against
// Surface::eval (the count does not build the patches).
Status rational_bezier_patch_count(const Surface& S, const ExportDomain& D, int& count);

// Homogeneous point (w, w x, w y, w z) of the patch at local (s, t) in
// [0, 1]^2 (de Casteljau in u, then in v).
void patch_eval_homogeneous(const RationalBezierPatch& P, double s, double t, double (&h)[4]);
// The point x (h[1..3] / h[0]).
Vec3d patch_point(const RationalBezierPatch& P, double s, double t);
// The surface parameters (u, v) of local (s, t); v is +-HUGE_VAL at w = 0.
void patch_parameters(const RationalBezierPatch& P, double s, double t, double& u, double& v);

// ------------------------------------------------ NURBS assembly (N1)-(N4)
//
// (N1) v-parameter. The NURBS runs in tau, a monotone reparameterization of
//      the surface's v on R and infinity in which every v-piece (E5) is
//      linear:  tau = v for |v| <= 1,  tau = 2 sign(v) - 1/v for |v| >= 1
//      (tau in [-2, 2]; tau = -2 and 2 are both v = infinity, the generator
//      p(u)). A piece in v (|v| <= 1) has local t linear in v = tau, a
//      reciprocal piece t linear in 1/v = 2 sign(v) - tau: the Bezier
//      pieces are the NURBS' knot spans without reparameterization.
// (N2) Knots. u: the surface's u (patches are linear in u);
//      U = (u_0 x (p + 1), u_1 x p, ..., u_{nu-1} x p, u_nu x (p + 1)),
//      u_i the boundaries of the nu u-intervals, p = deg_u; v likewise in
//      tau with q = deg_v = 2 at the nv v-pieces' boundaries. Clamped, C0 at
//      every interior knot (multiplicity = degree); (nu p + 1) x (nv q + 1)
//      control points, nu p + p + 2 and nv q + q + 2 knots.
// (N3) Control net: patch (iu, iv)'s point (i, j) is net point
//      (iu p + i, iv q + j), at cp[(iu p + i) * cp_v + iv q + j], homogeneous
//      (w, wx, wy, wz). Each patch is homogeneous up to its own positive
//      factor (build_patch scales each by a power of two), so patch (iu, iv)
//      is first scaled by the ratio of the weight sums over its edge shared
//      with the left (iv > 0) or lower (iv = 0, iu > 0) neighbour; every
//      shared edge then must agree to kNurbsJoinTol relative to the largest
//      |component| on it (numerical_overflow otherwise) and keeps the
//      earlier patch's values. Finally the net is scaled by a power of two,
//      largest weight in [0.5, 1). For a whole circle the ends tau = -2 and
//      2 are the same curve p(u) (not merged: the net is clamped, not
//      periodic).
// (N4) nurbs_eval_homogeneous: de Boor in u on the q + 1 rows of the v-span,
//      then in v (the homogeneous point; the spans are half-open, the last
//      one closed).
constexpr double kNurbsJoinTol = 1e-12;

// tau(v) of (N1) (v = +-inf gives +-2) and its inverse (tau = +-2 gives
// +-HUGE_VAL); tau outside [-2, 2] is clamped.
double export_tau_of_v(double v);
double export_v_of_tau(double tau);

struct NurbsSize {
  int deg_u = 0, deg_v = 0;
  int nu = 0, nv = 0;    // Bezier patches in u and v
  int cp_u = 0, cp_v = 0;  // control points in u and v (cp_u * cp_v in all)
  int knots_u() const { return cp_u + deg_u + 1; }
  int knots_v() const { return cp_v + deg_v + 1; }
  int cp_count() const { return cp_u * cp_v; }
};

// Caller-owned output of assemble_nurbs (a pointer may be null with its
// capacity 0 for a size query).
struct NurbsBuffers {
  double* knots_u = nullptr;
  int cap_knots_u = 0;
  double* knots_v = nullptr;
  int cap_knots_v = 0;
  double (*cp)[4] = nullptr;
  int cap_cp = 0;
};

// The shape of the patch grid (u-major, rows of equal v-pieces, equal
// degrees, contiguous u-intervals): invalid_argument otherwise, or for
// count <= 0 or patches null (null_argument).
Status nurbs_size(const RationalBezierPatch* patches, int count, NurbsSize& size);

// The NURBS (N1)-(N3) of the patches of one export into B. Statuses of
// nurbs_size; buffer_too_small (size filled, nothing written) when a
// capacity is too small; null_argument for a null array with enough
// capacity; numerical_overflow when shared control points do not agree
// (N3) or a weight is not positive. B is written only on ok.
Status assemble_nurbs(const RationalBezierPatch* patches, int count, const NurbsBuffers& B,
                      NurbsSize& size);

// A read-only view of an assembled NURBS (arrays as assemble_nurbs wrote).
struct NurbsView {
  NurbsSize size;
  const double* knots_u = nullptr;
  const double* knots_v = nullptr;
  const double (*cp)[4] = nullptr;
};

// (N4): the homogeneous point at (u, tau), both clamped to the knot range.
void nurbs_eval_homogeneous(const NurbsView& N, double u, double tau, double (&h)[4]);
Vec3d nurbs_point(const NurbsView& N, double u, double tau);

// Bernstein coefficients b[0..n] on [t0, t1] of sum_k c[k] t^k: Horner in
// the Bernstein basis (each step a convex combination times t0 or t1, so the
// error is O(n eps sum |c_k| max(|t0|,|t1|)^k)). poly.hpp's to_bernstein
// Taylor-shifts first, which cancels like 3^n for t in [-1, 1].
void bernstein_from_power(const double* c, int n, double t0, double t1, double* b);

}  // namespace v0
}  // namespace cyclide
