// Seed 002 Remark 2 (and ERRATA.md: a c > 0 iff kappa r < 1 at the ends):
// tangent lengths of the skin's spine chosen by Ceres so that the skin is
// valid (SPEC.md §8g). The optimizer tier: allocates (Ceres).
#pragma once

#include "cyclide/sphere_skin.hpp"

namespace cyclide {
inline namespace v0 {
namespace optim {

struct SkinTangentOptions {
  double target = 0.9;        // kappa r kept at or below target (in (0, 1))
  double min_ratio = 1.0 / 16;  // each length scale sigma within [min_ratio, max_ratio]
  double max_ratio = 16.0;
  int max_iterations = 100;
};

struct SkinTangentSummary {
  double scale[2] = {1, 1};          // sigma_i, sigma_f: t_i -> sigma_i t_i, t_f -> sigma_f t_f
  double kappa_r_initial[2] = {0, 0};  // kappa(0) r_i, kappa(1) r_f of the input
  double kappa_r[2] = {0, 0};          // of the result
  int iterations = 0;                  // 0: the input was already valid (returned as is)
};

// The ends with their tangents rescaled: if the skin of the input is
// valid (make_sphere_skin ok) it is returned unchanged; else Ceres
// minimizes (log sigma_i)^2 + (log sigma_f)^2 + 1e6 (hinge(kappa(0) r_i /
// target - 1)^2 + hinge(kappa(1) r_f / target - 1)^2) over log sigma in
// [log min_ratio, log max_ratio] (Remark 2's closed-form curvatures with
// Jets): the smallest change of the tangent lengths that makes the ends
// valid, directions and cones kept (1/c scales with the tangent, so the
// apex x = p + c t and the sphere stay). Statuses: those of make_sphere_skin other than
// curvature_radius_too_large (nothing to fix), invalid_argument (target
// outside (0, 1), ratios not 0 < min <= 1 <= max, max_iterations < 0),
// not_finite; curvature_radius_too_large if no scaling in the box makes
// the skin valid. Outputs written only on success.
Status optimize_skin_tangents(const SkinEnd& start, const SkinEnd& end, const SkinOptions& skin,
                              const SkinTangentOptions& options, SkinEnd& start_out,
                              SkinEnd& end_out, SkinTangentSummary& summary);

}  // namespace optim
}  // namespace v0
}  // namespace cyclide
