// Internal to the exports (rational_export.cpp (E5), skin_export.cpp (K2)):
// a v-piece and the Bernstein coefficients of a quadratic in v on it.
#pragma once

#include <utility>

namespace cyclide {
inline namespace v0 {
namespace detail {

// v in [v0, v1], in x = v or (rec) x = 1/v over [x0, x1].
struct VPiece {
  bool rec = false;
  double x0 = 0, x1 = 0, v0 = 0, v1 = 0;
};

// The degree-2 Bernstein coefficients on the piece of x0 + x1 v + x2 v^2
// (times w^2 = 1/v^2 on a reciprocal piece: X2 + X1 w + X0 w^2).
template <class R>
void v_controls(const VPiece& p, R x0, R x1, R x2, R (&c)[3]) {
  if (p.rec) std::swap(x0, x2);
  const R a = p.x0, b = p.x1;
  c[0] = x0 + (x1 + x2 * a) * a;
  c[1] = x0 + x1 * R(0.5) * (a + b) + x2 * a * b;  // the blossom
  c[2] = x0 + (x1 + x2 * b) * b;
}

}  // namespace detail
}  // namespace v0
}  // namespace cyclide
