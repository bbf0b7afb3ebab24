// Lie spheres as a host writes them (cyc_lie_sphere), for the seed 003
// hardening tests.
#pragma once

#include <cstring>

#include "cyclide/cyclide.h"

namespace hostile {

// The oriented sphere with centre (x, y, z) and signed radius rho.
inline cyc_lie_sphere sphere(double x, double y, double z, double rho) {
  cyc_lie_sphere s;
  std::memset(&s, 0, sizeof s);
  s.kind = CYC_LIE_SPHERE;
  s.m[0] = x, s.m[1] = y, s.m[2] = z;
  s.rho = rho;
  return s;
}

// The oriented plane n . X = lambda.
inline cyc_lie_sphere plane(double nx, double ny, double nz, double lambda) {
  cyc_lie_sphere s;
  std::memset(&s, 0, sizeof s);
  s.kind = CYC_LIE_PLANE;
  s.n[0] = nx, s.n[1] = ny, s.n[2] = nz;
  s.lambda = lambda;
  return s;
}

}  // namespace hostile
