// Ringed surfaces R : (d, n, rho) of seed 001 §2: the circle of radius rho
// centered at the directrix d(t) in the plane with normal n(t) (the
// orientation function), parameterized by eq. (3) of seed 001 — the same
// rotation formula as eq. (27) of seed 000 — from a rational curve c on the
// surface: CircleFrame o = d, a = n, p = c. Finding a rational c for given
// (d, n, rho) is the work of seed 001 §3 (eq. (4): c = d + rho f with a
// rational unit vector field f perpendicular to n); see pcurve.hpp.
#pragma once

#include "cyclide/circle_family.hpp"
#include "cyclide/curve.hpp"
#include "cyclide/status.hpp"

namespace cyclide {
inline namespace v0 {

// The frame (d, n, c) at u as series of order N. The circle is the orbit of
// c about the line (d, n): its center is the foot of c on that line, d
// itself when (c - d).n = 0 (as for eq. (4)).
template <int N, class S>
Status ringed_frame(const RationalCurve& d, const RationalCurve& n, const RationalCurve& c,
                    const S& u, CircleFrame<Taylor<S, N>>& F) {
  F.o = d.taylor<N>(u);
  F.a = n.taylor<N>(u);
  F.p = c.taylor<N>(u);
  return Status::ok;
}

}  // namespace v0
}  // namespace cyclide
