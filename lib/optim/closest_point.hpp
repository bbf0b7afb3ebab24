// The optimizer tier (links Ceres; may allocate). Point inversion: the
// parameters (u, v) of the point of a circle-family surface closest to a
// given point X.
#pragma once

#include "cyclide/surface.hpp"

namespace cyclide {
inline namespace v0 {
namespace optim {

struct ClosestPoint {
  double u = 0, v = 0;  // parameters (v may be HUGE_VAL: the generator p(u))
  Vec3d point;          // x(u, v)
  double distance = 0;  // |x(u, v) - X|
  int iterations = 0;   // Ceres iterations
};

// Global start: the distance from X to each circle has a closed form
// (sqrt(h^2 + (d - rho)^2), h the height over the circle's plane, d the
// distance of the foot from the center), scanned at kDomainSamples circles;
// the best u and its closest circle point start a Levenberg-Marquardt
// refinement of |x(u,v) - X|^2 with the analytic Jacobian [x_u, x_v] and
// u bounded to the domain.
Status closest_point(const Surface& S, const Vec3d& X, ClosestPoint& out);

}  // namespace optim
}  // namespace v0
}  // namespace cyclide
