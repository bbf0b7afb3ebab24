// Contour curves of ringed surfaces (seed 001 §7, Definition 7.1): the
// points of R : (d, n, rho) whose surface normal is orthogonal to a
// direction v — the silhouette of R in the projection along v.
//  - Any circle-family surface of the library, at any u: the contour points
//    on the circle u, i.e. the curve (70) evaluated at u. The general
//    contour has nested square roots (the paper leaves it there); here each
//    point is the root of a quartic in tan(theta/2), exact to rounding.
//  - Eqs. (71), (72), Prop. 7.2: if n.v = 0 identically and n is a P-curve
//    (|n| a polynomial) the two contour curves d +- rho (n x v)/|n| are
//    rational, and are returned as rational curves.
// Allocation-free.
#pragma once

#include "cyclide/curve.hpp"
#include "cyclide/pcurve.hpp"
#include "cyclide/surface.hpp"

namespace cyclide {
inline namespace v0 {

// The contour points on the circle at u for the direction v (any nonzero
// length): up to 4 points (the tangent plane contains v there), ordered by
// angle, written to points[0..count-1]. whole_circle is set (count = 0)
// when every point of the circle qualifies (e.g. v along a cylinder's
// axis): Definition 7.1 excludes the sweeping circles. Statuses:
// invalid_argument for v = 0, not_finite for non-finite u or v, and the
// statuses of Surface::ringed at u; singular_point for radius 0 (the circle
// is a point).
struct ContourPoints {
  int count = 0;
  bool whole_circle = false;
  Vec3d points[4] = {Vec3d::Zero(), Vec3d::Zero(), Vec3d::Zero(), Vec3d::Zero()};
};
Status contour_points(const Surface& S, double u, const Vec3d& v, ContourPoints& out);

// Eq. (72): c+ and c- = d +- rho (n x v)/|n| for polynomial n with n.v = 0
// identically (71), as rational curves (through ringed_curve: the field
// (n x v)/sigma with sigma = |n| of eq. (14)). invalid_argument if (71)
// fails (relative 1e-12 of n's coefficients) or v = 0; not_pythagorean if
// |n| is not a polynomial (Prop. 7.2: then no rational contour curve).
Status contour_curves_71(const RationalCurve& d, const RationalCurve& n, const CurvePoly& rho_num,
                         const CurvePoly& rho_den, const Vec3d& v, RationalCurve& plus,
                         RationalCurve& minus);

}  // namespace v0
}  // namespace cyclide
