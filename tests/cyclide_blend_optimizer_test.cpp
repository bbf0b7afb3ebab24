// Seed 003 §4, Case II (labels optim;lie): Ceres chooses the double cyclide
// blend's family parameter phi = atan(unit alpha) on the hyperbolas (43)
// (unit = cyclide_blend_unit, the frame's power of 2) against
// a user objective — evenly curved patches, a joint circle through given
// points or of a given radius, clearance from spheres — never worse than
// the best scanned sample and always a valid, G1 blend.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <vector>

#include "cyclide/cyclide_blend.hpp"
#include "optim/cyclide_blend_optimizer.hpp"

using namespace cyclide;
using namespace cyclide::optim;

namespace {

LieCone cone(const Vec3d& c, const Vec3d& n, double rho, double slope, int orientation) {
  LieCone K;
  EXPECT_EQ(cone_from_circle(c, n, rho, slope, orientation, K), Status::ok);
  return K;
}

// The double-blend configuration of tests/paper_seed003_blend.cpp: two
// cylinders with parallel, offset axes facing each other (valid blends on
// branch -1 only).
void offset_cylinders(LieCone& R, LieCone& S) {
  R = cone({0, 0, 0}, {0, 0, 1}, 1, 0, 1);
  S = cone({2, 0, 3}, {0, 0, -1}, 1, 0, 1);
}

double circle_distance(const Vec3d& X, const BlendCircle& C) {
  const Vec3d d = X - C.center;
  const double h = d.dot(C.normal);
  return std::hypot(h, (d - h * C.normal).norm() - C.radius);
}

// The fairness term recomputed independently: w/2 times the mean squared
// deviation of the log radii (n circles of each family per piece).
bool fairness_cost(const CyclideBlend& B, int n, double& cost) {
  std::vector<double> lr;
  const double two_pi = 8 * std::atan(1.0);
  for (int i = 0; i < B.pieces; ++i)
    for (int f = 0; f < 2; ++f)
      for (int k = 0; k < n; ++k) {
        BlendCircle C;
        const double s = f == 0 ? double(k) / (n - 1) : two_pi * (k + 0.5) / n;
        if (cyclide_blend_circle(B, i, f, s, C) != Status::ok) return false;
        lr.push_back(std::log(C.radius));
      }
  double mean = 0, var = 0;
  for (double x : lr) mean += x;
  mean /= double(lr.size());
  for (double x : lr) var += (x - mean) * (x - mean);
  cost = 0.5 * var / double(lr.size());
  return true;
}

// The default objective recomputed: fairness plus the regularity hinge
// on each piece's extent (min_extent L, L = the cones' centers' distance
// plus radii).
bool default_cost(const LieCone& R, const LieCone& S, const CyclideBlend& B, double& cost) {
  const CyclideBlendObjective o;
  if (!fairness_cost(B, o.circles, cost)) return false;
  Vec3d cr, nr, cs, ns;
  double rr, rs;
  if (cone_circle(R, cr, nr, rr) != Status::ok || cone_circle(S, cs, ns, rs) != Status::ok)
    return false;
  const double L = (cr - cs).norm() + std::abs(rr) + std::abs(rs);
  for (int i = 0; i < B.pieces; ++i) {
    BlendCircle A, Z;
    if (cyclide_blend_circle(B, i, 0, 0.0, A) != Status::ok ||
        cyclide_blend_circle(B, i, 0, 1.0, Z) != Status::ok)
      return false;
    const double e = (A.center - Z.center).norm() + std::abs(A.radius - Z.radius) +
                     0.5 * (A.radius + Z.radius) * A.normal.cross(Z.normal).norm();
    const double h = std::max(0.0, 1.0 - e / (o.min_extent * L));
    cost += 0.5 * o.regularity * h * h;
  }
  return true;
}

void expect_g1(const LieCone& R, const LieCone& S, const CyclideBlend& B, double tol) {
  CyclideBlendContinuity C;
  ASSERT_EQ(cyclide_blend_continuity(R, S, B, 24, C), Status::ok);
  for (int j = 0; j < 3; ++j) {
    EXPECT_LE(C.gap[j], tol * C.scale) << "joint " << j;
    EXPECT_LE(C.angle[j], tol) << "joint " << j;
  }
}

}  // namespace

// The geometric second family: the family-1 circle at angle s passes
// through the point of the first glued circle at that angle, and meets
// every family-0 circle (it lies on the cyclide).
TEST(CyclideBlendCircles, SecondFamilyThroughTheGluedCircle) {
  LieCone R, S;
  offset_cylinders(R, S);
  CyclideBlend B;
  ASSERT_EQ(cyclide_blend(R, S, -1, std::tan(0.3), B), Status::ok);
  for (int i = 0; i < 2; ++i) {
    BlendCircle G;
    ASSERT_EQ(cyclide_blend_circle(B, i, 0, 0.0, G), Status::ok);
    const Vec3d u = G.normal.unitOrthogonal(), w = G.normal.cross(u);
    for (double s : {0.0, 1.0, 2.5, 4.0}) {
      const Vec3d X = G.center + G.radius * (std::cos(s) * u + std::sin(s) * w);
      BlendCircle C;
      ASSERT_EQ(cyclide_blend_circle(B, i, 1, s, C), Status::ok);
      EXPECT_LE(circle_distance(X, C), 1e-10 * (1 + C.radius));
      EXPECT_NEAR(C.normal.norm(), 1.0, 1e-14);
    }
  }
  BlendCircle C;
  EXPECT_EQ(cyclide_blend_circle(B, 2, 0, 0.5, C), Status::invalid_argument);
  EXPECT_EQ(cyclide_blend_circle(B, 0, 0, 1.5, C), Status::invalid_argument);
  EXPECT_EQ(cyclide_blend_circle(B, 0, 2, 0.5, C), Status::invalid_argument);
  EXPECT_EQ(cyclide_blend_circle(B, 0, 1, NAN, C), Status::not_finite);
}

// The default objective (fairness): a valid blend on the only valid branch,
// G1 at all three circles, the parameter inside its box, never worse than
// the scan's best, and a local minimum of the independently computed cost.
TEST(CyclideBlendOptimizer, FairestDoubleBlendIsALocalMinimum) {
  LieCone R, S;
  offset_cylinders(R, S);
  CyclideBlend B;
  BlendSummary sum;
  CyclideBlendObjective obj;
  ASSERT_EQ(optimize_cyclide_blend(R, S, obj, CyclideBlendOptimizerOptions(), B, sum),
            Status::ok);
  EXPECT_EQ(B.pieces, 2);
  EXPECT_EQ(B.branch, -1);
  EXPECT_LE(sum.final_cost, sum.initial_cost);
  ASSERT_EQ(sum.parameters.count, 1);
  const FreeParameter& p = sum.parameters.p[0];
  EXPECT_EQ(p.role, ParameterRole::family);
  EXPECT_EQ(p.index, -1);
  EXPECT_LE(p.lower, p.value);
  EXPECT_LE(p.value, p.upper);
  double unit = 0;
  ASSERT_EQ(cyclide_blend_unit(R, S, unit), Status::ok);
  EXPECT_NEAR(std::tan(p.value) / unit, B.alpha, 1e-12 * (1 + std::abs(B.alpha)));
  expect_g1(R, S, B, 1e-9);
  double c0 = 0, f0 = 0;
  ASSERT_TRUE(default_cost(R, S, B, c0));
  ASSERT_TRUE(fairness_cost(B, obj.circles, f0));
  EXPECT_NEAR(c0, sum.final_cost, 1e-12);
  EXPECT_NEAR(f0, sum.fairness, 1e-12);
  EXPECT_NEAR(sum.fairness + sum.regularity, sum.final_cost, 1e-15);
  for (double d : {-1e-3, 1e-3}) {
    CyclideBlend N;
    if (p.value + d < p.lower || p.value + d > p.upper) continue;
    if (cyclide_blend(R, S, -1, std::tan(p.value + d) / unit, N) != Status::ok) continue;
    double c = 0;
    ASSERT_TRUE(default_cost(R, S, N, c));
    EXPECT_GE(c, sum.final_cost - 1e-12) << "phi + " << d;
  }
  // The query lists the same parameter without solving.
  FreeParameters P;
  ASSERT_EQ(describe_cyclide_blend_parameters(R, S, obj, CyclideBlendOptimizerOptions(), P),
            Status::ok);
  ASSERT_EQ(P.count, 1);
  EXPECT_EQ(P.p[0].start, p.start);
  EXPECT_EQ(P.p[0].lower, p.lower);
  EXPECT_EQ(P.p[0].upper, p.upper);
}

// A wanted joint radius (fairness off): any radius the family attains is
// hit; the target is the joint radius of the blend at a known phi.
TEST(CyclideBlendOptimizer, JointCircleOfAGivenRadius) {
  LieCone R, S;
  offset_cylinders(R, S);
  for (double phi0 : {-0.9, 0.2, 1.1}) {
    CyclideBlend T;
    if (cyclide_blend(R, S, -1, std::tan(phi0), T) != Status::ok) continue;
    BlendCircle J;
    ASSERT_EQ(cyclide_blend_circle(T, 0, 0, 1.0, J), Status::ok);
    CyclideBlendObjective obj;
    obj.fairness = 0;
    obj.joint_radius = J.radius;
    CyclideBlend B;
    BlendSummary sum;
    ASSERT_EQ(optimize_cyclide_blend(R, S, obj, CyclideBlendOptimizerOptions(), B, sum),
              Status::ok);
    BlendCircle K;
    ASSERT_EQ(cyclide_blend_circle(B, 0, 0, 1.0, K), Status::ok);
    EXPECT_NEAR(K.radius, J.radius, 1e-6 * J.radius) << "phi0 " << phi0;
    EXPECT_LE(sum.final_cost, 1e-12);
    EXPECT_NEAR(sum.targets, sum.final_cost, 1e-18);
    expect_g1(R, S, B, 1e-9);
  }
}

// A joint circle through a given point: the point of the joint circle of
// the blend at a known phi.
TEST(CyclideBlendOptimizer, JointCircleThroughAPoint) {
  LieCone R, S;
  offset_cylinders(R, S);
  CyclideBlend T;
  ASSERT_EQ(cyclide_blend(R, S, -1, std::tan(0.7), T), Status::ok);
  BlendCircle J;
  ASSERT_EQ(cyclide_blend_circle(T, 0, 0, 1.0, J), Status::ok);
  const Vec3d X = J.center + J.radius * J.normal.unitOrthogonal();
  CyclideBlendObjective obj;
  obj.fairness = 0;
  obj.joint_points = &X;
  obj.joint_point_count = 1;
  CyclideBlend B;
  BlendSummary sum;
  ASSERT_EQ(optimize_cyclide_blend(R, S, obj, CyclideBlendOptimizerOptions(), B, sum),
            Status::ok);
  BlendCircle K;
  ASSERT_EQ(cyclide_blend_circle(B, 0, 0, 1.0, K), Status::ok);
  EXPECT_LE(circle_distance(X, K), 1e-6 * sum.length_scale);
  expect_g1(R, S, B, 1e-9);
}

// An obstacle on the fairest blend's joint circle: with the hinge only,
// the optimizer moves the joint away until every sampled circle clears it.
TEST(CyclideBlendOptimizer, ClearsASphericalObstacle) {
  LieCone R, S;
  offset_cylinders(R, S);
  CyclideBlend F;
  BlendSummary fs;
  ASSERT_EQ(optimize_cyclide_blend(R, S, CyclideBlendObjective(), CyclideBlendOptimizerOptions(),
                                   F, fs),
            Status::ok);
  BlendCircle J;
  ASSERT_EQ(cyclide_blend_circle(F, 0, 0, 1.0, J), Status::ok);
  SphereObstacle O;
  O.center = J.center + J.radius * J.normal.unitOrthogonal();
  O.radius = 0.15;
  double closest = HUGE_VAL;  // the fairest blend runs through the obstacle
  for (int i = 0; i < 2; ++i)
    for (int k = 0; k < 16; ++k) {
      BlendCircle C;
      ASSERT_EQ(cyclide_blend_circle(F, i, 0, k / 15.0, C), Status::ok);
      closest = std::min(closest, circle_distance(O.center, C));
    }
  ASSERT_LT(closest, O.radius);
  CyclideBlendObjective obj;
  obj.fairness = 0;
  obj.obstacles = &O;
  obj.obstacle_count = 1;
  CyclideBlend B;
  BlendSummary sum;
  ASSERT_EQ(optimize_cyclide_blend(R, S, obj, CyclideBlendOptimizerOptions(), B, sum),
            Status::ok);
  EXPECT_LE(sum.final_cost, 1e-20);
  for (int i = 0; i < 2; ++i)
    for (int k = 0; k < obj.circles; ++k) {
      BlendCircle C;
      ASSERT_EQ(cyclide_blend_circle(B, i, 0, double(k) / (obj.circles - 1), C), Status::ok);
      EXPECT_GE(circle_distance(O.center, C), O.radius - 1e-9);
    }
  expect_g1(R, S, B, 1e-9);
}

// Case I (dim(R + S) = 3): nothing to choose; the elbow of two cylinders.
TEST(CyclideBlendOptimizer, SingleCyclideHasNoFreeParameter) {
  const LieCone R = cone({0, 0, 0}, {1, 0, 0}, 1, 0, 1);
  const LieCone S = cone({3, 0, -3}, {0, 0, 1}, 1, 0, 1);
  int dim = 0;
  ASSERT_EQ(cyclide_blend_dimension(R, S, dim), Status::ok);
  ASSERT_EQ(dim, 3);
  CyclideBlend B;
  BlendSummary sum;
  ASSERT_EQ(optimize_cyclide_blend(R, S, CyclideBlendObjective(), CyclideBlendOptimizerOptions(),
                                   B, sum),
            Status::ok);
  EXPECT_EQ(B.pieces, 1);
  EXPECT_EQ(sum.parameters.count, 0);
  EXPECT_EQ(sum.initial_cost, sum.final_cost);
  double c = 0;
  ASSERT_TRUE(fairness_cost(B, 16, c));
  EXPECT_NEAR(sum.fairness, c, 1e-14);
  ASSERT_TRUE(default_cost(R, S, B, c));
  EXPECT_NEAR(sum.final_cost, c, 1e-14);
  FreeParameters P;
  ASSERT_EQ(describe_cyclide_blend_parameters(R, S, CyclideBlendObjective(),
                                              CyclideBlendOptimizerOptions(), P),
            Status::ok);
  EXPECT_EQ(P.count, 0);
}

TEST(CyclideBlendOptimizer, RejectsBadObjectivesAndOptions) {
  LieCone R, S;
  offset_cylinders(R, S);
  CyclideBlend B;
  BlendSummary sum;
  auto run = [&](const CyclideBlendObjective& o, const CyclideBlendOptimizerOptions& p) {
    return optimize_cyclide_blend(R, S, o, p, B, sum);
  };
  const CyclideBlendOptimizerOptions p0;
  CyclideBlendObjective o;
  o.fairness = -1;
  EXPECT_EQ(run(o, p0), Status::invalid_argument);
  o = CyclideBlendObjective();
  o.circles = 3;
  EXPECT_EQ(run(o, p0), Status::invalid_argument);
  o = CyclideBlendObjective();
  o.joint_point_count = 1;  // null array
  EXPECT_EQ(run(o, p0), Status::invalid_argument);
  const Vec3d bad(NAN, 0, 0);
  o.joint_points = &bad;
  EXPECT_EQ(run(o, p0), Status::not_finite);
  o = CyclideBlendObjective();
  SphereObstacle neg;
  neg.radius = -1;
  o.obstacles = &neg;
  o.obstacle_count = 1;
  EXPECT_EQ(run(o, p0), Status::invalid_argument);
  o = CyclideBlendObjective();
  o.joint_radius = INFINITY;
  EXPECT_EQ(run(o, p0), Status::not_finite);
  CyclideBlendOptimizerOptions p;
  p.samples = 4;
  EXPECT_EQ(run(CyclideBlendObjective(), p), Status::invalid_argument);
  p = CyclideBlendOptimizerOptions();
  p.branch = 2;
  EXPECT_EQ(run(CyclideBlendObjective(), p), Status::invalid_argument);
  // Only the folding branch: no valid sample.
  p.branch = 1;
  EXPECT_EQ(run(CyclideBlendObjective(), p), Status::blend_folds);
  // max_iterations = 0: the best sample itself.
  p = CyclideBlendOptimizerOptions();
  p.max_iterations = 0;
  ASSERT_EQ(run(CyclideBlendObjective(), p), Status::ok);
  EXPECT_EQ(sum.parameters.p[0].value, sum.parameters.p[0].start);
  EXPECT_EQ(sum.final_cost, sum.initial_cost);
}

// Random cone pairs facing each other (unit normals near the line of
// centers, radii 0.5 .. 2, slopes -0.4 .. 0.4, orientation +1): whenever a
// double blend exists, the optimized one is valid, G1 at its three circles
// (1e-8 relative), no worse than the best sample, its phi inside the box
// and a local minimum of the (independently recomputed) default cost
// unless it stopped on the box or at the iteration limit.
RC_GTEST_PROP(CyclideBlendOptimizerProperties, OptimizedDoubleBlendsAreValidAndMinimal, ()) {
  // (Drawn one at a time: the order of a constructor's arguments is unspecified.)
  auto vec = [] {
    Vec3d v;
    for (int i = 0; i < 3; ++i) v[i] = *rc::gen::inRange(-200, 201) / 100.0;
    return v;
  };
  const Vec3d cr = vec();
  const Vec3d cs = cr + Vec3d(5, 0, 0) + vec();
  const Vec3d d = (cs - cr).normalized();
  const Vec3d nr = (d + 0.25 * vec()).normalized();
  const Vec3d ns = (-d + 0.25 * vec()).normalized();
  const double rr = *rc::gen::inRange(50, 201) / 100.0, rs = *rc::gen::inRange(50, 201) / 100.0;
  const double kr = *rc::gen::inRange(-40, 41) / 100.0, ks = *rc::gen::inRange(-40, 41) / 100.0;
  LieCone R, S;
  RC_ASSERT(cone_from_circle(cr, nr, rr, kr, 1, R) == Status::ok);
  RC_ASSERT(cone_from_circle(cs, ns, rs, ks, 1, S) == Status::ok);
  int dim = 0;
  RC_PRE(cyclide_blend_dimension(R, S, dim) == Status::ok);
  RC_PRE(dim == 4);
  CyclideBlendObjective obj;
  CyclideBlendOptimizerOptions opt;
  opt.samples = 32;
  CyclideBlend B;
  BlendSummary sum;
  const Status st = optimize_cyclide_blend(R, S, obj, opt, B, sum);
  RC_PRE(st == Status::ok);
  RC_CLASSIFY(sum.termination == BlendTermination::reverted, "reverted");
  RC_ASSERT(B.pieces == 2);
  RC_ASSERT(sum.final_cost <= sum.initial_cost);
  const FreeParameter& p = sum.parameters.p[0];
  RC_ASSERT(p.lower <= p.value && p.value <= p.upper);
  CyclideBlendContinuity C;
  RC_ASSERT(cyclide_blend_continuity(R, S, B, 16, C) == Status::ok);
  for (int j = 0; j < 3; ++j) {
    RC_ASSERT(C.gap[j] <= 1e-8 * std::max(1.0, C.scale));
    RC_ASSERT(C.angle[j] <= 1e-8);
  }
  double c0 = 0;
  RC_ASSERT(default_cost(R, S, B, c0));
  RC_ASSERT(std::abs(c0 - sum.final_cost) <= 1e-12 * (1 + c0));
  if (sum.termination != BlendTermination::converged) return;
  double unit = 0;
  RC_ASSERT(cyclide_blend_unit(R, S, unit) == Status::ok);
  for (double dp : {-1e-3, 1e-3}) {
    if (p.value + dp < p.lower || p.value + dp > p.upper) continue;
    CyclideBlend N;
    if (cyclide_blend(R, S, B.branch, std::tan(p.value + dp) / unit, N) != Status::ok) continue;
    double c = 0;
    if (!default_cost(R, S, N, c)) continue;
    RC_ASSERT(c >= sum.final_cost - 1e-9 * (1 + sum.final_cost));
  }
}
