// The implicit equations printed in seed 000, as Darboux coefficients, for
// the tests (one definition each, with the equation number).
#pragma once

#include "cyclide/darboux.hpp"

namespace cyclide {
namespace seed000 {

// Example 4, (35): z X.X - y^2 - 3 z^2 - 3 x y + 2 z + alpha (x z - 2 y z + 2 y).
inline Darboux eq35(double alpha) {
  Darboux D;
  D.k[kLz] = 1;
  D.k[kQyy] = -1;
  D.k[kQzz] = -3;
  D.k[kQxy] = -3;
  D.k[kBz] = 2;
  D.k[kQxz] = alpha;
  D.k[kQyz] = -2 * alpha;
  D.k[kBy] = 2 * alpha;
  return D;
}

// Example 2 continued, (39): 4 z X.X - 8 y^2 - 3 z^2 - 6 x y - z.
inline Darboux eq39() {
  Darboux D;
  D.k[kLz] = 4;
  D.k[kQyy] = -8;
  D.k[kQzz] = -3;
  D.k[kQxy] = -6;
  D.k[kBz] = -1;
  return D;
}

// Example 5, (60): the DCMC family in the paper's alpha.
inline Darboux eq60(double alpha) {
  Darboux D;
  D.k[kLz] = 1;
  D.k[kQxy] = 0.5;
  D.k[kQyy] = -1;
  D.k[kQzz] = alpha;
  D.k[kQxz] = -(34 + 8 * alpha) / 16;
  D.k[kQyz] = -(9 + 4 * alpha) / 8;
  D.k[kBy] = (13 + 4 * alpha) / 16;
  D.k[kBz] = -(1 + 4 * alpha) / 16;
  return D;
}

// Example 5, (61): z X.X + (x y - x z + y z)/2 - y^2 - 13/4 z^2 + 3/4 z.
inline Darboux eq61() {
  Darboux D;
  D.k[kLz] = 1;
  D.k[kQxy] = 0.5;
  D.k[kQxz] = -0.5;
  D.k[kQyz] = 0.5;
  D.k[kQyy] = -1;
  D.k[kQzz] = -13.0 / 4;
  D.k[kBz] = 0.75;
  return D;
}

// Appendix A, (70): (c y - z) X.X + (1 - a^2 - c^2) y^2 + 2 a x y + 2 z^2 - c y - z.
inline Darboux eq70(double a, double c) {
  Darboux D;
  D.k[kLy] = c;
  D.k[kLz] = -1;
  D.k[kQyy] = 1 - a * a - c * c;
  D.k[kQxy] = 2 * a;
  D.k[kQzz] = 2;
  D.k[kBy] = -c;
  D.k[kBz] = -1;
  return D;
}

// Appendix B, (73): 4 z X.X - 3 y^2 - 8 z^2 - 4 x y - 10 y z + 10 y + 4 z.
inline Darboux eq73() {
  Darboux D;
  D.k[kLz] = 4;
  D.k[kQyy] = -3;
  D.k[kQzz] = -8;
  D.k[kQxy] = -4;
  D.k[kQyz] = -10;
  D.k[kBy] = 10;
  D.k[kBz] = 4;
  return D;
}

}  // namespace seed000
}  // namespace cyclide
