// Canal and ringed surfaces as data (seed 000 §2, eqs. (1)-(3)).
//   (1) canal (s, r^2) -> ringed (c, n, rho^2),
//   (2) the canal test of a ringed surface,
//   (3) the one-parameter family of spheres of a ringed surface.
// All are written with r r' = (r^2)'/2 and rho rho' = (rho^2)'/2, so that
// only rational quantities appear (ERRATA: "Eq. (1) without square roots").
#pragma once

#include "cyclide/circle_family.hpp"
#include "cyclide/status.hpp"

namespace cyclide {
inline namespace v0 {

using T1 = Taylor<double, 1>;

// Ringed data of a circle family at u, with first derivatives.
struct RingedData {
  Vec3d c, n;            // directrix point, plane normal (not unit)
  Vec3d dc, dn;          // c'(u), n'(u)
  double rho2 = 0;       // rho^2
  double rho_rho_prime = 0;  // rho rho' = (rho^2)'/2
};

// From a frame with first derivatives (any circle family).
RingedData ringed_data(const CircleFrame<T1>& F);

// Eq. (1): c = s - (r r'/|s'|^2) s', n = s', rho^2 = r^2 (|s'|^2 - r'^2)/|s'|^2,
// from the spine s and r^2 as series of order 1 and s'' (for n').
RingedData ringed_from_canal(const Vec3<Taylor<double, 2>>& s,
                             const Taylor<double, 2>& r2);

// Eq. (2): |[(n.c')c' + rho rho' n'] x n| relative to
// (|n| |c'|^2 + (|rho rho'| + rho^2 |n'|/|n|) |n'|) |n|, a bound of the terms
// that does not cancel; 0 means "canal at this u".
double canal_residual(const RingedData& R);

// Eq. (3): the sphere (x - c)^2 - rho^2 - (2 rho rho'/(n.c')) n.(x - c) = 0,
// i.e. center c + k n, radius^2 rho^2 + k^2 |n|^2 with k = rho rho'/(n.c').
// degenerate_ringed when n.c' vanishes relative to |n| |c'|.
Status ringed_sphere(const RingedData& R, Vec3d& center, double& radius2);

}  // namespace v0
}  // namespace cyclide
