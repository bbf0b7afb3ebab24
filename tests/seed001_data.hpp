// Test data of seed 001 shared by the paper tests and the optimizer tests:
// the Hermite data (37) of a canal surface read as a ringed surface by eq.
// (1), and Example 5.2's two ends ((59) at t = 1, (60) at t = 0).
#pragma once

#include <cmath>

#include "cyclide/pcurve.hpp"
#include "cyclide/ringed.hpp"

namespace cyclide_test {

using namespace cyclide;

inline Taylor<double, 2> series2(double v, double d1, double d2) {
  Taylor<double, 2> s;
  s.c[0] = v;
  s.c[1] = d1;
  s.c[2] = d2 / 2;
  return s;
}

// Eq. (1) at a point of a canal surface (spine m, radius r: values and
// first two derivatives).
inline RingedJet canal_jet(const Vec3d& m, const Vec3d& dm, const Vec3d& ddm, double r, double dr,
                           double ddr) {
  Vec3<Taylor<double, 2>> s;
  for (int j = 0; j < 3; ++j) s[j] = series2(m[j], dm[j], ddm[j]);
  return ringed_jet_from(
      ringed_from_canal(s, series2(r * r, 2 * r * dr, 2 * (dr * dr + r * ddr))));
}

// Example 5.2, eqs. (59), (60).
inline void example52_ends(RingedJet& J1, RingedJet& J2) {
  const double a = 0.3 - 1.1;  // 0.3 t - 1.1 at t = 1
  J1 = canal_jet(Vec3d(a, a * a - 1, a * a * a), Vec3d(0.3, 0.6 * a, 0.9 * a * a),
                 Vec3d(0, 0.18, 0.54 * a), 0.03 - 0.22 + 0.736667, 0.06 - 0.22, 0.06);
  J2 = canal_jet(Vec3d(2, 2, 1), Vec3d(0.3, 1.2, 0.6), Vec3d(0, 0.36, 0.18), 1, 0.3, 0.09);
}

}  // namespace cyclide_test
