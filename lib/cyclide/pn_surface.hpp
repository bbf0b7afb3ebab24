// PN (Pythagorean-normal) surfaces as Lambda^{-1} images of rational
// surfaces of the isotropic model (seed 004 §3, Theorems 3.1 and 3.2).
//
// A rational tensor-product Bezier surface Psi(u, v) of I^3 is a
// two-parameter family of points y(u, v), i.e. (through Lambda^{-1}) of
// oriented planes
//   P(u, v) = isotropic_dual_plane(y) = (2 y3, 2 y1, 2 y2, y1^2 + y2^2 - 1)
// (the plane Lambda^{-1}(y) scaled by N = 1 + y1^2 + y2^2, laguerre.hpp).
// Theorem 3.2: their envelope Phi = Lambda^{-1}(Psi) is a PN surface. Its
// point is the intersection of P with its two partials, the exterior product
//   X = P ^ P_u ^ P_v  (homogeneous, x = (X1, X2, X3) / X0),
// and its unit normal is the (rational) normal of P,
//   n = (2 y1, 2 y2, y1^2 + y2^2 - 1) / N.
// Every offset x + d n is rational too: it is Lambda^{-1} of the dilated
// surface y3 -> y3 - (d/2) N ((2.6), sign of laguerre.hpp's header).
//
// Everything here is evaluated exactly (rational formulas, no
// approximation): the Bezier form and its first and second partials, the
// quotient rule for y, the chain rule for P (quadratic in y), the product
// rule for X and the quotient rule for x.
//
// Degenerate points (Theorem 3.2's remarks):
//   * X = 0: the plane and its two partials are dependent; Psi is locally a
//     curve (or its parameterization is singular) and Phi has no envelope
//     point: developable.
//   * X0 = 0, X != 0: X0 = 4 N det J with J the Jacobian of
//     (u, v) -> (y1, y2), so Psi is touched by an isotropic line there
//     (y3-parallel occluding contour, seed 004 §3) and the point of Phi lies
//     at infinity: point_at_infinity.
// Both are decided relative to reference scales (see pn_surface_eval).
#pragma once

#include <cstddef>

#include "cyclide/config.hpp"
#include "cyclide/laguerre.hpp"
#include "cyclide/status.hpp"
#include "cyclide/vec.hpp"

namespace cyclide {
inline namespace v0 {

// A rational tensor-product Bezier surface Psi of the isotropic model over
// [0, 1]^2: control[i * (degree_v + 1) + j] = (w, w y1, w y2, w y3) (weight
// first, w > 0), i along u (0..degree_u), j along v (0..degree_v).
// Build it with make_pn_surface, which validates and derives the reference
// scales below.
struct PnSurface {
  int degree_u = 0;
  int degree_v = 0;
  Vec4d control[(kMaxPnDegree + 1) * (kMaxPnDegree + 1)];
  // Reference parametric speeds of y3 (a length) and of (y1, y2)
  // (dimensionless): max(degree) * (w_max / w_min) * the longest edge of the
  // affine control net in y3, resp. in (y1, y2). Kept apart, since the
  // isotropic similarities (rotations about z, scalings, translations) move
  // y3 and leave |(y1, y2)| alone; they set the scale of "X = 0" and
  // "X0 = 0" when a partial vanishes.
  double speed_ref = 0;
  double speed_ref_12 = 0;
  // Psi is a point (all planes equal) or lies on an isotropic line (all
  // planes parallel): no point of Phi anywhere (developable).
  bool degenerate = false;
};

// One point of Phi or of its offset at signed distance d.
struct PnPoint {
  Vec3d y = Vec3d::Zero();      // Psi(u, v) in I^3 (the undilated one)
  Vec3d x = Vec3d::Zero();      // the point x + d n
  Vec3d x_u = Vec3d::Zero();    // its partials x_u + d n_u, x_v + d n_v
  Vec3d x_v = Vec3d::Zero();
  Vec3d n = Vec3d::Zero();      // unit normal (the same for every offset)
  Vec3d n_u = Vec3d::Zero();    // its partials (exact)
  Vec3d n_v = Vec3d::Zero();
  OrientedPlane plane;          // the tangent plane e0 + n.x = 0 at x
};

// Validates and stores Psi. control holds (degree_u + 1) * (degree_v + 1)
// homogeneous points in the order of PnSurface::control.
//   null_argument      control == nullptr
//   invalid_argument   a degree < 0, or a weight <= 0
//   degree_too_high    a degree > kMaxPnDegree
//   not_finite         NaN/Inf or |value| > kMaxInputMagnitude, or an affine
//                      point y = (w y) / w beyond kMaxInputMagnitude
// out is written only on ok.
Status make_pn_surface(const Vec4d* control, int degree_u, int degree_v, PnSurface& out) noexcept;

// Psi at (u, v) with its first and second partials, from the Bezier form
// (homogeneous) and the quotient rule. (u, v) must lie in [0, 1]^2.
struct IsotropicJet {
  Vec3d y, y_u, y_v, y_uu, y_uv, y_vv;
};
Status pn_isotropic_jet(const PnSurface& S, double u, double v, IsotropicJet& out) noexcept;

// The point of the offset of Phi at signed distance d (d = 0: Phi itself) at
// (u, v), with partials, unit normal and tangent plane (Theorem 3.2, (2.6)).
//   bad_domain          (u, v) outside [0, 1]^2
//   not_finite          u, v or d NaN/Inf or |d| > kMaxInputMagnitude
//   point_at_infinity   |X0| <= kPnAtInfinityTol * N * max(|P~_u|, B12) *
//                       max(|P~_v|, B12), P~ the normal part (P1, P2, P3),
//                       B12 = 2 (1 + |(y1, y2)|) S.speed_ref_12 (X0 = 4 N det J
//                       is dimensionless: the test is invariant under the
//                       isotropic similarities)
//   developable         S.degenerate, or X0 = 0 as above and also the length
//                       part (X1, X2, X3) <= kPnDevelopableTol * (|P0| m_u m_v +
//                       |P~| l_u m_v + |P~| m_u l_v), m = max(|P~_*|, B12),
//                       l = max(|P0_*|, 2 S.speed_ref) (each X_i is a length
//                       times two dimensionless factors: the reference has
//                       the same units, so the test moves with the data)
//   numerical_overflow  a non-finite intermediate or output
// out is written only on ok. Allocation-free, O(degree_u * degree_v).
Status pn_surface_eval(const PnSurface& S, double u, double v, double d, PnPoint& out) noexcept;

// The grid (us[i], vs[j]) at index i * nv + j, offset d. All us, vs and d
// are validated (statuses of pn_surface_eval) and capacity >= nu * nv
// checked (else buffer_too_small with *needed = nu * nv, if needed is not
// null) before anything is written. Each point's own status goes to
// point_status[k] (may be null); a point that is not ok is written as a
// zero PnPoint. Returns ok when the call itself was valid; *failed (may be
// null) counts the points that are not ok.
Status pn_surface_eval_grid(const PnSurface& S, const double* us, std::size_t nu,
                            const double* vs, std::size_t nv, double d, PnPoint* out,
                            Status* point_status, std::size_t capacity, std::size_t* needed,
                            std::size_t* failed) noexcept;

}  // namespace v0
}  // namespace cyclide
