// Implicitization check (issue 3, item 7): the Darboux cyclide (31) through
// sample points of a surface, by a rank-revealing least-squares fit, with a
// geometric residual that says whether the points lie on one (SPEC.md §12a).
//
//   phi0 (X.X)^2 + (l.X)(X.X) + X.QX + b.X + c = 0                    (31)
//
// Allocation-free: fixed-size Eigen matrices (at most kMaxFitPoints x 14).
#pragma once

#include "cyclide/darboux.hpp"
#include "cyclide/status.hpp"
#include "cyclide/vec.hpp"

namespace cyclide {
inline namespace v0 {

class Surface;

// Sample counts: at most kMaxFitPoints rows; at least kMinFitPoints (the
// 14 unknowns plus margin, so that a non-cyclide cannot be fitted exactly).
constexpr int kMaxFitPoints = 64;
constexpr int kMinFitPoints = 20;
// A singular value sigma_i <= kFitNullityTol * sigma_max counts as zero
// (nullity = dimension of the family of (31)-equations through the points).
constexpr double kFitNullityTol = 1e-9;
// "The points lie on a Darboux cyclide": residual <= kDarbouxFitTol.
constexpr double kDarbouxFitTol = 1e-9;

struct DarbouxFit {
  // The fitted equation in the input coordinates, normalized: the largest
  // |coefficient| is 1 and the first coefficient (in DarbouxCoeff order)
  // with |k| > 1e-6 is positive. If nullity > 1, the member of the family
  // with the lowest leading monomial (e.g. the sphere itself, not sphere x
  // plane; the plane itself, not plane x sphere).
  Darboux D;
  // max over the samples of |F(x)| / max(|grad F(x)|, 1e-3), computed in
  // the centered unit-box coordinates with |coefficients|_2 = 1, relative to
  // the diagonal of the sample box (a distance estimate; the floor keeps
  // singular points and double lines, where F and grad F vanish, finite).
  double residual = 0;
  // sigma_min / sigma_max of the row-normalized 14-column system.
  double sigma_ratio = 0;
  int nullity = 0;   // singular values <= kFitNullityTol * sigma_max
  int points = 0;    // samples used
  bool is_darboux = false;  // residual <= kDarbouxFitTol
};

// Fit through count points (kMinFitPoints <= count <= kMaxFitPoints).
// Statuses: null_argument, invalid_argument (count out of range, or all
// points equal), not_finite (a point fails input_ok), numerical_overflow.
Status fit_darboux(const Vec3d* points, int count, DarbouxFit& out);

// Fit through the surface at 8 x 8 samples: u at the midpoints of 8 equal
// parts of [u0, u1], v = tan(pi (j + 1/2) / 8 - pi / 2), j = 0..7 (an even
// spread of the circle for the stereographic-like parameter f = v); samples
// where eval fails are skipped. invalid_argument if fewer than
// kMinFitPoints remain.
Status fit_darboux(const Surface& S, DarbouxFit& out);

}  // namespace v0
}  // namespace cyclide
