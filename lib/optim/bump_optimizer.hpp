// Seed 001 §5 and §5.a: Ceres chooses the bump of the P-curve blend's
// directrix, d* = d + w b(t; tau) (eqs. (50)-(52), (57)), to make the blend
// "more normal" (eq. (58)) and to clear spherical obstacles (eq. (54)).
// Optimizer tier: allocates (Ceres); only in libcyclide_optim.
#pragma once

#include "cyclide/pcurve.hpp"
#include "optim/blend_optimizer.hpp"

namespace cyclide {
inline namespace v0 {
namespace optim {

struct BumpObjective {
  double deviance = 1.0;  // weight of (58), the integral of sin^2 angle(n, d*')
  const SphereObstacle* obstacles = nullptr;
  int obstacle_count = 0;
  double clearance = 0.0;        // wanted |d* - s| - rho - r, beyond (54)'s 0
  double obstacle_weight = 1.0;  // weight of the hinge on (54)
  int nodes = 64;                // midpoint nodes on [0, 1] (4..1024)
};

struct BumpOptions {
  double w_bound = 2.0;   // |w_j| <= w_bound L (L: the ends' distance + radii)
  double tau_min = 0.2;   // tau in [tau_min, tau_max] (within (0, 1))
  double tau_max = 0.8;
  bool free_tau = true;   // else tau stays at the start's
  int max_iterations = 50;
  double function_tolerance = 1e-10;
  double gradient_tolerance = 1e-12;
  double parameter_tolerance = 1e-10;
};

// The start bump is options.bump of `blend` (w = 0: none; its kind is
// kept). The cost (1/2 the sum of squared residuals): deviance/2 times the
// midpoint rule of (58), plus obstacle_weight/2 times the mean over the
// nodes of max(0, (r + clearance + (|d*'| + |rho'|) h/2 - (|d*(t) - s| -
// rho(t))) / L)^2 per obstacle (h = 1/nodes: the hinge covers each node's
// cell to first order, so a zero obstacle term means (54) holds between the
// nodes too, not only at them). d*, d*' are exact in (w, tau) (n, rho do not move: the circles
// translate), so Ceres differentiates them with Jets (AutoDiff, 4
// parameters); bounds are Ceres' own. The result is rebuilt by
// make_ringed_pcurve_blend; if that fails or costs more than the start,
// the start is returned (termination reverted): final <= initial always.
// summary.obstacles / summary.fairness hold the final obstacle and
// deviance terms (fairness = the deviance term here). Statuses:
// invalid_argument (negative weights, nodes outside 4..1024, tau bounds
// not in (0, 1) or tau_min > tau_max, w_bound <= 0, counts, a two-piece
// bump with a P-biarc and free tau), not_finite, singular_point (d*' = 0 at
// a node of the start), and those of make_ringed_pcurve_blend. Nothing is
// written on error.
Status optimize_pcurve_bump(const RingedJet& a, const RingedJet& b,
                            const RingedBlendOptions& blend, const BumpObjective& objective,
                            const BumpOptions& options, Surface (&pieces)[2], int& count,
                            DirectrixBump& chosen, BlendSummary& summary);

// The free parameters optimize_pcurve_bump solves for (w's components and
// tau; tau's box is [tau, tau] when it is not free), boxes and starts; no
// solve. Statuses of its validation.
Status describe_bump_parameters(const RingedJet& a, const RingedJet& b,
                                const RingedBlendOptions& blend, const BumpObjective& objective,
                                const BumpOptions& options, FreeParameters& out);

}  // namespace optim
}  // namespace v0
}  // namespace cyclide
