// The optimizer of a blend's free parameters (issue 4 item 6; SPEC.md §8e):
// the jets (phi', phi'', ...) of both ends of a canal or ringed blend
// (seed 000 §9; blend.hpp BlendEnd), and optionally the circle parameters
// of the chosen end points (§9.1 (i): where on the end circles the Hermite
// curves start), chosen by Ceres' Levenberg-Marquardt
// (autodiff Jacobians; the box bounds enforced exactly by the smooth map
// x = mid + half sin(s) of unconstrained variables, with an active set that
// pins parameters on their bounds) against a weighted sum of
//   fairness    the integral of |x_tt|^2 + 2 |x_tv|^2 + |x_vv|^2 over the
//               blend (Gauss-Legendre in t, both charts v in [-1, 1] and
//               1/v in [-1, 1] of the circle), relative to the start blend's;
//   regularity  hinge penalties that keep the PRCS/PRRS planes' relative
//               determinant above min_determinant (the paper's weakness:
//               parallel normal planes) and |x_t| above min_speed L;
//   targets     the blend's circle at t_k passing through X_k (closed-form
//               point-circle distance, relative to L);
//   obstacles   clearance of every circle at the t nodes from spheres
//               (closed-form point-circle distance from the center, hinge).
// L is the length scale of the two end circles. Derivatives are exact:
// Ceres Jets through the same series code (reparameterize, Hermite basis,
// prcs_planes / prrs_planes, intersect, the circle's rational quadratic).
// This is the one tier that allocates (Ceres).
#pragma once

#include "cyclide/blend.hpp"

namespace cyclide {
inline namespace v0 {
namespace optim {

enum class BlendKind : int { canal = 0, ringed = 1 };

struct SphereObstacle {
  Vec3d center = Vec3d::Zero();
  double radius = 0.0;
};

// The blend's circle at parameter t should pass through point.
struct TargetPoint {
  Vec3d point = Vec3d::Zero();
  double t = 0.0;
};

constexpr int kMaxQuadrature = 16;

struct BlendObjective {
  double fairness = 1.0;           // weight of the fairness integral
  double regularity = 1.0;         // weight of the hinge penalties
  double min_determinant = 1e-2;   // relative plane determinant kept above this
  double min_speed = 1e-2;         // |x_t| kept above min_speed * L
  const TargetPoint* targets = nullptr;
  int target_count = 0;
  double target_weight = 1.0;
  const SphereObstacle* obstacles = nullptr;
  int obstacle_count = 0;
  double clearance = 0.0;          // wanted distance beyond each radius
  double obstacle_weight = 1.0;
  int quadrature_t = 8;            // Gauss-Legendre nodes in t (1..16)
  int quadrature_v = 4;            // nodes per circle chart (1..16)
};

struct BlendOptions {
  // Free derivative orders per end: 1 = the tangent lengths phi' only,
  // m = phi', ..., phi^(m); 0 = min(K, 2). Orders above are kept as given.
  int free_orders = 0;
  // |phi'| stays in [lambda_min_ratio, lambda_max_ratio] |lambda_0| with the
  // sign of lambda_0 (the start value); |phi^(m)| <= higher_bound |lambda_0|.
  double lambda_min_ratio = 0.25;
  double lambda_max_ratio = 4.0;
  double higher_bound = 4.0;
  // > 0: the circle parameters v[j] of the chosen end points (§9.1 (i))
  // are unknowns too, as the angles theta = 2 atan v (radians; v = infinity
  // is theta = pi), each within theta_0 +- min(circle_parameter_range,
  // 0.45 x the angle to its end's nearest other point) so the points stay
  // distinct and in order. 0 (the default): the points are kept.
  double circle_parameter_range = 0.0;
  int max_iterations = 50;
  double function_tolerance = 1e-8;
  double gradient_tolerance = 1e-10;
  double parameter_tolerance = 1e-8;
};

// The common description of a blend's free parameters (issue 4): every
// optimizer of the library states its unknowns as FreeParameters — what
// each one is, its box and its start — and reports the chosen values.
// The families so far: the ends' jets phi', phi'', ... and the chosen
// points' circle parameters of the canal and ringed blends (seed 000 §9,
// below) and the directrix bump w, tau of the
// P-curve blend (seed 001 §5, bump_optimizer.hpp), and the family
// parameter phi = atan(unit alpha) of the double cyclide blend of two cones
// (seed 003 §4, cyclide_blend_optimizer.hpp). (The reparameterization
// factors mu are not free parameters of any blend built here: mu is fixed by
// the Hermite data's jets — those are the jet parameters.)
enum class ParameterRole : int {
  jet = 0,                // phi^(order) at end `index` (0 start, 1 end); order 1 = lambda
  bump_displacement = 1,  // w_index (index 0, 1, 2) of d* = d + w b(t; tau)
  bump_position = 2,      // tau
  circle_point = 3,       // theta = 2 atan v of point `order` (j) at end `index`
  family = 4,             // phi = atan(unit alpha) of a double cyclide blend on branch `index` (+-1)
};
struct FreeParameter {
  ParameterRole role = ParameterRole::jet;
  int index = 0;
  int order = 0;
  double lower = 0.0, upper = 0.0;  // the box; lower == upper: held fixed
  double start = 0.0;               // the start value (inside the box)
  double value = 0.0;               // the chosen value (the start before solving)
};
constexpr int kMaxFreeParameters = 2 * kMaxBlendOrder + 6;  // jets, then 3 points per end
struct FreeParameters {
  FreeParameter p[kMaxFreeParameters];
  int count = 0;
  void add(const FreeParameter& q) { p[count++] = q; }
};

enum class BlendTermination : int {
  converged = 0,        // a tolerance was met (function, gradient, parameter as Ceres')
  iteration_limit = 1,  // max_iterations reached (the best point is kept)
  reverted = 2,         // the optimum did not give a valid blend: the start is returned
};

struct BlendSummary {
  double initial_cost = 0.0;  // the objective at the start (the defaults)
  double final_cost = 0.0;    // at the returned blend (<= initial_cost)
  int iterations = 0;
  double seconds = 0.0;
  BlendTermination termination = BlendTermination::converged;
  // The objective's terms at the returned blend (each already weighted).
  double fairness = 0.0, regularity = 0.0, targets = 0.0, obstacles = 0.0;
  double length_scale = 0.0;  // L
  double fairness_scale = 0.0;  // the start blend's fairness integral (normalizer)
  FreeParameters parameters;    // the unknowns: boxes, starts and chosen values
};

// Optimizes the jets of start and end (their lambda and phi[] are the start
// values; lambda = 0 means blend_lambda's default) and, with
// options.circle_parameter_range > 0, their points' v[], and writes the
// blend to out and the chosen ends to start_out / end_out (may be null). If the
// start blend is degenerate, the lambdas scaled by 1/2, 2, 1/4, 4 are tried
// as starts; if all fail, that status (with *bad_t) is returned. Statuses:
// invalid_argument (weights < 0, quadrature outside 1..16, bounds with
// lambda_min_ratio > lambda_max_ratio or <= 0, K outside the blend's range,
// obstacle radius < 0, counts < 0 or a null array with a positive count),
// not_finite (any non-finite number in objective or options), and those of
// make_canal_blend / make_ringed_blend. Nothing is written on error.
Status optimize_blend(BlendKind kind, const BlendEnd& start, const BlendEnd& end, int K,
                      double t0, double t1, const BlendObjective& objective,
                      const BlendOptions& options, Surface& out, BlendEnd* start_out,
                      BlendEnd* end_out, BlendSummary& summary, double* bad_t = nullptr);

// The free parameters optimize_blend would solve for (its start search
// included: the first valid of the lambdas scaled by 1, 1/2, 2, 1/4, 4),
// with their boxes and starts; no solve. Statuses of optimize_blend's
// validation and start search.
Status describe_blend_parameters(BlendKind kind, const BlendEnd& start, const BlendEnd& end,
                                 int K, double t0, double t1, const BlendOptions& options,
                                 FreeParameters& out, double* bad_t = nullptr);

}  // namespace optim
}  // namespace v0
}  // namespace cyclide
