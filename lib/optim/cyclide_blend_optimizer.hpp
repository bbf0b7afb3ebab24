// Seed 003 §4, Case II: the double cyclide blend of two cones is a
// one-parameter family (the points (alpha, beta) of the hyperbolas (43));
// here Ceres chooses that family parameter against a user objective
// (SPEC.md §8h.12). Optimizer tier: allocates (Ceres); only in
// libcyclide_optim.
//
// The unknown is phi = atan(unit alpha) on one branch (+1 or -1) of (43)
// (unit = cyclide_blend_unit, so that the scan is scale-free); the
// objective is a weighted sum (1/2 the sum of squared residuals) of
//   fairness   the spread of the log radii of the patches' circles
//              (cyclide_blend_circle: `circles` of each family per piece;
//              both principal curvatures of a cyclide are constant along its
//              circles, so equal radii mean an evenly curved blend):
//              sqrt(w / N) (log r_i - mean log r);
//   joint      the joint circle (piece 0 at u = 1, the sphere t0 (44)) passing
//              through given points (closed-form point-circle distance / L)
//              and/or having a given radius ((r - target) / L);
//   obstacles  clearance of every family-0 circle (whole circles, sweeping
//              the patches) from spheres: the hinge max(0, radius +
//              clearance - distance(center, circle)) / L;
//   regularity per piece, the hinge max(0, 1 - e / (min_extent L)) on its
//              extent e = |c0 - c1| + |r0 - r1| + (r0 + r1)/2 |n0 x n1|
//              between its glued circles: near the asymptotes (45), (46) a
//              piece collapses onto its cone's circle (the double blend
//              tends to a single cyclide plus a sliver, where the
//              construction loses accuracy: G1 to 1e-7 instead of 1e-12),
//              and fairness alone can prefer that limit.
// L = the distance of the cones' circle centers plus both radii. The
// construction goes through the Witt extension (not templated on the
// scalar), so the derivative is a central difference (step 1e-6 max(1,
// |phi|), one-sided next to a phi without a valid blend) of the exact
// construction; the residuals are
// geometric (independent of how the construction parameterizes the second
// family), so they are smooth in phi where the blend exists.
//
// Global, then local: the objective is scanned at `samples` values of phi
// on the branch(es) (the blends that exist, do not fold or pinch, and build
// as surfaces), and Ceres refines the best sample within the run of valid
// samples around it. final_cost <= initial_cost (the best sample) always.
#pragma once

#include "cyclide/cyclide_blend.hpp"
#include "optim/blend_optimizer.hpp"

namespace cyclide {
inline namespace v0 {
namespace optim {

struct CyclideBlendObjective {
  double fairness = 1.0;  // weight of the spread of the circles' log radii
  const Vec3d* joint_points = nullptr;  // the joint circle should pass through these
  int joint_point_count = 0;
  double joint_point_weight = 1.0;
  double joint_radius = 0.0;         // > 0: the joint circle's wanted radius; 0: none
  double joint_radius_weight = 1.0;
  const SphereObstacle* obstacles = nullptr;
  int obstacle_count = 0;
  double clearance = 0.0;       // wanted distance beyond each radius
  double obstacle_weight = 1.0;
  double regularity = 1.0;      // weight of the hinge on each piece's extent
  double min_extent = 0.05;     // each piece's extent kept above min_extent L (0: off)
  int circles = 16;             // circles per family and piece (4..256)
};

struct CyclideBlendOptimizerOptions {
  int samples = 64;  // scan points of phi per branch (8..4096)
  int branch = 0;    // 0: both hyperbolas; +1 or -1: only that one
  int max_iterations = 50;
  double function_tolerance = 1e-10;
  double gradient_tolerance = 1e-12;
  double parameter_tolerance = 1e-10;
};

// The blend of R and S with its family parameter chosen (Case II), or the
// single cyclide (Case I: nothing to choose; summary.parameters is empty and
// the costs are the objective at that blend). summary.fairness, .targets
// (both joint terms), .obstacles and .regularity are the final cost's terms;
// summary.parameters holds one ParameterRole::family entry (index = the
// branch): phi's box (the valid run), start (the best sample) and value.
// Statuses: invalid_argument (weights, clearance, min_extent or joint_radius < 0,
// circles outside 4..256, counts < 0 or a null array with a positive count,
// obstacle radius < 0, samples outside 8..4096, branch not in {-1, 0, 1},
// max_iterations < 0), not_finite, those of cyclide_blend_dimension; when
// no sample gives a valid blend: blend_folds if some sample folded, else
// singular_point. Nothing is written on error.
Status optimize_cyclide_blend(const LieCone& R, const LieCone& S,
                              const CyclideBlendObjective& objective,
                              const CyclideBlendOptimizerOptions& options, CyclideBlend& out,
                              BlendSummary& summary);

// The free parameter optimize_cyclide_blend would solve for (after its
// scan: branch, box and start); no solve. Case I: out.count = 0.
Status describe_cyclide_blend_parameters(const LieCone& R, const LieCone& S,
                                         const CyclideBlendObjective& objective,
                                         const CyclideBlendOptimizerOptions& options,
                                         FreeParameters& out);

}  // namespace optim
}  // namespace v0
}  // namespace cyclide
