// Seed 003 §4, Case II: Ceres chooses the double cyclide blend's family
// parameter (see cyclide_blend_optimizer.hpp).
#include "optim/cyclide_blend_optimizer.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>
#include "ceres_options.hpp"

namespace cyclide {
inline namespace v0 {
namespace optim {

namespace {

const double kHalfPi = 2 * std::atan(1.0);

// Distance from the point X to the whole circle C: with h the height of X
// over C's plane and q its distance from the axis, sqrt(h^2 + (q - r)^2).
double point_circle_distance(const Vec3d& X, const BlendCircle& C) {
  const Vec3d d = X - C.center;
  const double h = d.dot(C.normal);
  const double q = (d - h * C.normal).norm();
  return std::hypot(h, q - C.radius);
}

// The extent of a piece: how far apart its two glued circles C0 (u = 0)
// and C1 (u = 1) are: |c0 - c1| + |r0 - r1| + (r0 + r1) / 2 |n0 x n1|
// (0 only when they are one circle: the piece collapsed).
double piece_extent(const BlendCircle& C0, const BlendCircle& C1) {
  return (C0.center - C1.center).norm() + std::abs(C0.radius - C1.radius) +
         0.5 * (C0.radius + C1.radius) * C0.normal.cross(C1.normal).norm();
}

// The residuals of a blend, laid out as
//   [fairness: pieces * 2 n][joint points: K][joint radius: 0 or 1]
//   [obstacles: M * pieces * n][regularity: pieces],
// n = objective.circles. The joint terms are 0 for a single cyclide (no
// joint).
class Residuals {
 public:
  Residuals(const CyclideBlendObjective& o, int pieces, double L)
      : o_(o), pieces_(pieces), L_(L) {}

  int count() const {
    const int n = o_.circles;
    return pieces_ * 2 * n + o_.joint_point_count + (o_.joint_radius > 0 ? 1 : 0) +
           o_.obstacle_count * pieces_ * n + pieces_;
  }

  // False if a circle is undefined (through infinity, singular).
  bool of_blend(const CyclideBlend& B, double* r) const {
    const int n = o_.circles;
    const double two_pi = 4 * kHalfPi;
    // Fairness: log radii of both families, minus their mean.
    const int N = pieces_ * 2 * n;
    double mean = 0;
    for (int i = 0; i < pieces_; ++i)
      for (int f = 0; f < 2; ++f)
        for (int k = 0; k < n; ++k) {
          const double s = f == 0 ? double(k) / (n - 1) : two_pi * (k + 0.5) / n;
          BlendCircle C;
          if (cyclide_blend_circle(B, i, f, s, C) != Status::ok) return false;
          if (!(C.radius > 0) || !std::isfinite(C.radius)) return false;
          const double lr = std::log(C.radius);
          r[(i * 2 + f) * n + k] = lr;
          mean += lr;
        }
    mean /= N;
    const double wf = std::sqrt(o_.fairness / N);
    for (int j = 0; j < N; ++j) r[j] = wf * (r[j] - mean);
    int at = N;
    // The joint circle (piece 0 at u = 1).
    BlendCircle J;
    const bool has_joint = B.pieces == 2;
    if (has_joint && cyclide_blend_circle(B, 0, 0, 1.0, J) != Status::ok) return false;
    const double wp = o_.joint_point_count > 0 ? std::sqrt(o_.joint_point_weight / o_.joint_point_count) : 0;
    for (int k = 0; k < o_.joint_point_count; ++k)
      r[at++] = has_joint ? wp * point_circle_distance(o_.joint_points[k], J) / L_ : 0.0;
    if (o_.joint_radius > 0)
      r[at++] = has_joint ? std::sqrt(o_.joint_radius_weight) * (J.radius - o_.joint_radius) / L_
                          : 0.0;
    // Obstacles: the hinge per sphere and family-0 circle.
    const int M = o_.obstacle_count;
    const double wo = M > 0 ? std::sqrt(o_.obstacle_weight / (M * pieces_ * n)) : 0;
    for (int i = 0; i < pieces_ && M > 0; ++i)
      for (int k = 0; k < n; ++k) {
        BlendCircle C;
        if (cyclide_blend_circle(B, i, 0, double(k) / (n - 1), C) != Status::ok) return false;
        for (int m = 0; m < M; ++m) {
          const SphereObstacle& X = o_.obstacles[m];
          const double gap = X.radius + o_.clearance - point_circle_distance(X.center, C);
          r[at + m * pieces_ * n + i * n + k] = gap > 0 ? wo * gap / L_ : 0.0;
        }
      }
    at += M * pieces_ * n;
    // Regularity: each piece's extent above min_extent L. Near the
    // asymptotes (45), (46) a piece collapses onto its cone's circle (the
    // double blend tends to a single cyclide plus a sliver) and the
    // construction loses accuracy; fairness alone may prefer that limit.
    const double wr = std::sqrt(o_.regularity);
    for (int i = 0; i < pieces_; ++i) {
      BlendCircle C0, C1;
      if (cyclide_blend_circle(B, i, 0, 0.0, C0) != Status::ok ||
          cyclide_blend_circle(B, i, 0, 1.0, C1) != Status::ok)
        return false;
      const double short_by = 1.0 - piece_extent(C0, C1) / (o_.min_extent * L_);
      r[at++] = o_.min_extent > 0 && short_by > 0 ? wr * short_by : 0.0;
    }
    return true;
  }

  // The terms of the cost 1/2 |r|^2.
  void terms(const double* r, BlendSummary& sum) const {
    const int N = pieces_ * 2 * o_.circles;
    const int K = o_.joint_point_count + (o_.joint_radius > 0 ? 1 : 0);
    const int G = count() - pieces_;  // the regularity residuals come last
    sum.fairness = sum.targets = sum.obstacles = sum.regularity = 0;
    for (int j = 0; j < count(); ++j) {
      const double c = 0.5 * r[j] * r[j];
      (j < N ? sum.fairness : j < N + K ? sum.targets : j < G ? sum.obstacles : sum.regularity) +=
          c;
    }
  }

 private:
  const CyclideBlendObjective& o_;
  int pieces_;
  double L_;
};

// The residuals of the blend at phi on a fixed branch (false: no valid
// blend there).
// phi = atan(unit alpha), unit = cyclide_blend_unit (scale-free).
struct FamilyCost {
  LieCone R, S;
  int branch;
  const Residuals* residuals;
  double unit = 1;
  bool operator()(const double* phi, double* r) const {
    CyclideBlend B;
    if (cyclide_blend(R, S, branch, std::tan(phi[0]) / unit, B) != Status::ok) return false;
    return residuals->of_blend(B, r);
  }
};

FamilyCost family_cost(const LieCone& R, const LieCone& S, int branch, const Residuals* res) {
  FamilyCost f{R, S, branch, res};
  double unit = 1;
  if (cyclide_blend_unit(R, S, unit) == Status::ok) f.unit = unit;
  return f;
}

// Ceres' view of FamilyCost with the derivative by central differences,
// one-sided where one probe has no valid blend (near the end of a valid
// run). Hand-written rather than ceres::NumericDiffCostFunction, which
// ignores a failing probe and hands Ceres an unwritten Jacobian.
class FamilyCostFunction : public ceres::CostFunction {
 public:
  explicit FamilyCostFunction(const FamilyCost& f) : f_(f) {
    set_num_residuals(f.residuals->count());
    mutable_parameter_block_sizes()->push_back(1);
  }
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const double phi = parameters[0][0];
    if (!f_(&phi, residuals)) return false;
    if (!jacobians || !jacobians[0]) return true;
    const int n = num_residuals();
    const double h = 1e-6 * std::max(1.0, std::abs(phi));
    std::vector<double> plus(n), minus(n);
    const double xp = phi + h, xm = phi - h;
    const bool p = f_(&xp, plus.data()), m = f_(&xm, minus.data());
    if (!p && !m) return false;
    for (int j = 0; j < n; ++j)
      jacobians[0][j] = p && m ? (plus[j] - minus[j]) / (2 * h)
                        : p    ? (plus[j] - residuals[j]) / h
                               : (residuals[j] - minus[j]) / h;
    return true;
  }

 private:
  FamilyCost f_;
};

Status check(const CyclideBlendObjective& o, const CyclideBlendOptimizerOptions& p) {
  for (double x : {o.fairness, o.joint_point_weight, o.joint_radius, o.joint_radius_weight,
                   o.clearance, o.obstacle_weight, o.regularity, o.min_extent,
                   p.function_tolerance, p.gradient_tolerance, p.parameter_tolerance})
    if (!std::isfinite(x)) return Status::not_finite;
  if (o.fairness < 0 || o.joint_point_weight < 0 || o.joint_radius < 0 ||
      o.joint_radius_weight < 0 || o.clearance < 0 || o.obstacle_weight < 0 ||
      o.regularity < 0 || o.min_extent < 0)
    return Status::invalid_argument;
  if (o.circles < 4 || o.circles > 256) return Status::invalid_argument;
  if (o.joint_point_count < 0 || (o.joint_point_count > 0 && !o.joint_points))
    return Status::invalid_argument;
  if (o.obstacle_count < 0 || (o.obstacle_count > 0 && !o.obstacles))
    return Status::invalid_argument;
  for (int k = 0; k < o.joint_point_count; ++k)
    if (!o.joint_points[k].allFinite()) return Status::not_finite;
  for (int k = 0; k < o.obstacle_count; ++k) {
    if (!o.obstacles[k].center.allFinite() || !std::isfinite(o.obstacles[k].radius))
      return Status::not_finite;
    if (o.obstacles[k].radius < 0) return Status::invalid_argument;
  }
  if (p.samples < 8 || p.samples > 4096 || p.branch < -1 || p.branch > 1 ||
      p.max_iterations < 0)
    return Status::invalid_argument;
  return Status::ok;
}

// L: the cones' circle centers' distance plus both radii.
Status length_scale(const LieCone& R, const LieCone& S, double& L) {
  Vec3d cr, nr, cs, ns;
  double rr = 0, rs = 0;
  if (Status st = cone_circle(R, cr, nr, rr); st != Status::ok) return st;
  if (Status st = cone_circle(S, cs, ns, rs); st != Status::ok) return st;
  L = (cr - cs).norm() + std::abs(rr) + std::abs(rs);
  return (L > 0 && std::isfinite(L)) ? Status::ok : Status::invalid_argument;
}

// 1/2 |r|^2 of the blend at phi on a branch, or HUGE_VAL if there is no
// valid blend there (or its residuals are undefined). *status receives
// cyclide_blend's status.
double cost_at(const FamilyCost& f, double phi, std::vector<double>& r, CyclideBlend* keep,
               Status* status) {
  CyclideBlend B;
  const Status st = cyclide_blend(f.R, f.S, f.branch, std::tan(phi) / f.unit, B);
  if (status) *status = st;
  if (st != Status::ok || !f.residuals->of_blend(B, r.data())) return HUGE_VAL;
  double c = 0;
  for (double x : r) c += 0.5 * x * x;
  if (!std::isfinite(c)) return HUGE_VAL;
  if (keep) *keep = B;
  return c;
}

// The scan: the best valid sample (its blend builds as surfaces) and the
// box of phi around it: to half way to the first invalid sample on each
// side (or a quarter step inside +-pi/2).
struct ScanResult {
  int branch = 0;
  double start = 0, lower = 0, upper = 0, cost = HUGE_VAL;
  CyclideBlend blend;
};

Status scan(const LieCone& R, const LieCone& S, const Residuals& res,
            const CyclideBlendOptimizerOptions& p, ScanResult& out) {
  const int n = p.samples;
  const double h = 2 * kHalfPi / n;
  auto phi_of = [&](int k) { return -kHalfPi + h * (k + 0.5); };
  std::vector<double> r(res.count()), cost(n);
  bool folded = false;
  ScanResult best;
  int best_k = -1;
  std::vector<double> best_costs;
  for (int branch : {1, -1}) {
    if (p.branch != 0 && branch != p.branch) continue;
    const FamilyCost f = family_cost(R, S, branch, &res);
    for (int k = 0; k < n; ++k) {
      Status st = Status::ok;
      CyclideBlend B;
      cost[k] = cost_at(f, phi_of(k), r, &B, &st);
      folded |= st == Status::blend_folds;
      if (cost[k] < best.cost && !cyclide_blend_pieces_build(B)) cost[k] = HUGE_VAL;
      if (cost[k] < best.cost) {
        best.cost = cost[k], best.branch = branch, best.blend = B, best_k = k;
        best.start = phi_of(k);
      }
    }
    if (best.branch == branch) best_costs = cost;
  }
  if (best_k < 0) return folded ? Status::blend_folds : Status::singular_point;
  int lo = best_k, hi = best_k;
  while (lo > 0 && std::isfinite(best_costs[lo - 1])) --lo;
  while (hi < n - 1 && std::isfinite(best_costs[hi + 1])) ++hi;
  best.lower = lo > 0 ? phi_of(lo) - 0.5 * h : phi_of(0) - 0.25 * h;
  best.upper = hi < n - 1 ? phi_of(hi) + 0.5 * h : phi_of(n - 1) + 0.25 * h;
  out = best;
  return Status::ok;
}

FreeParameter family_parameter(const ScanResult& s) {
  FreeParameter q;
  q.role = ParameterRole::family;
  q.index = s.branch;
  q.lower = s.lower;
  q.upper = s.upper;
  q.start = q.value = s.start;
  return q;
}

// Case I: the single cyclide and its cost (no free parameter).
Status single_blend(const LieCone& R, const LieCone& S, const CyclideBlendObjective& objective,
                    double L, CyclideBlend& out, BlendSummary& summary) {
  CyclideBlend B;
  if (Status st = cyclide_blend(R, S, 1, 0.0, B); st != Status::ok) return st;
  const Residuals res(objective, 1, L);
  std::vector<double> r(res.count());
  if (!res.of_blend(B, r.data()) || !cyclide_blend_pieces_build(B)) return Status::singular_point;
  BlendSummary sum;
  res.terms(r.data(), sum);
  sum.initial_cost = sum.final_cost = sum.fairness + sum.targets + sum.obstacles + sum.regularity;
  sum.length_scale = L;
  out = B;
  summary = sum;
  return Status::ok;
}

}  // namespace

Status describe_cyclide_blend_parameters(const LieCone& R, const LieCone& S,
                                         const CyclideBlendObjective& objective,
                                         const CyclideBlendOptimizerOptions& options,
                                         FreeParameters& out) {
  if (Status st = check(objective, options); st != Status::ok) return st;
  int dim = 0;
  if (Status st = cyclide_blend_dimension(R, S, dim); st != Status::ok) return st;
  double L = 0;
  if (Status st = length_scale(R, S, L); st != Status::ok) return st;
  FreeParameters P;
  if (dim == 4) {
    const Residuals res(objective, 2, L);
    ScanResult s;
    if (Status st = scan(R, S, res, options, s); st != Status::ok) return st;
    P.add(family_parameter(s));
  }
  out = P;
  return Status::ok;
}

Status optimize_cyclide_blend(const LieCone& R, const LieCone& S,
                              const CyclideBlendObjective& objective,
                              const CyclideBlendOptimizerOptions& options, CyclideBlend& out,
                              BlendSummary& summary) {
  const auto clock0 = std::chrono::steady_clock::now();
  if (Status st = check(objective, options); st != Status::ok) return st;
  int dim = 0;
  if (Status st = cyclide_blend_dimension(R, S, dim); st != Status::ok) return st;
  double L = 0;
  if (Status st = length_scale(R, S, L); st != Status::ok) return st;
  if (dim == 3) return single_blend(R, S, objective, L, out, summary);

  const Residuals res(objective, 2, L);
  ScanResult s;
  if (Status st = scan(R, S, res, options, s); st != Status::ok) return st;
  FreeParameters params;
  params.add(family_parameter(s));

  // Ceres refines phi inside the valid run (central differences of the
  // exact construction; a phi without a valid blend rejects the step).
  double phi = s.start;
  ceres::Problem problem;
  problem.AddResidualBlock(new FamilyCostFunction(family_cost(R, S, s.branch, &res)), nullptr,
                           &phi);
  problem.SetParameterLowerBound(&phi, 0, s.lower);
  problem.SetParameterUpperBound(&phi, 0, s.upper);
  ceres::Solver::Options so =
      quiet_dense_options(options.max_iterations, options.function_tolerance,
                          options.gradient_tolerance, options.parameter_tolerance);
  // A true trust region (dogleg) starting at the scan's step: the residuals
  // do not vanish at the optimum (fairness), so Gauss-Newton's model can be
  // far off; steps start at the scale the scan resolved.
  so.trust_region_strategy_type = ceres::DOGLEG;
  so.initial_trust_region_radius = 2 * kHalfPi / options.samples;
  so.max_trust_region_radius = s.upper - s.lower;
  ceres::Solver::Summary cs;
  if (options.max_iterations > 0) ceres::Solve(so, &problem, &cs);

  BlendSummary sum;
  sum.initial_cost = s.cost;
  sum.iterations = options.max_iterations > 0 ? std::max(0, int(cs.iterations.size()) - 1) : 0;
  sum.length_scale = L;
  sum.termination = cs.termination_type == ceres::NO_CONVERGENCE
                        ? BlendTermination::iteration_limit
                        : BlendTermination::converged;
  // The result, rebuilt; the best sample if it is no valid blend or worse.
  const FamilyCost f = family_cost(R, S, s.branch, &res);
  std::vector<double> r(res.count());
  CyclideBlend B;
  double final_cost = cost_at(f, phi, r, &B, nullptr);
  if (options.max_iterations == 0 || cs.termination_type == ceres::FAILURE ||
      !(final_cost <= s.cost) || !cyclide_blend_pieces_build(B)) {
    if (options.max_iterations > 0) sum.termination = BlendTermination::reverted;
    phi = s.start;
    B = s.blend;
    final_cost = cost_at(f, phi, r, nullptr, nullptr);
  }
  res.terms(r.data(), sum);
  sum.final_cost = final_cost;
  sum.parameters = params;
  sum.parameters.p[0].value = phi;
  sum.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock0).count();
  out = B;
  summary = sum;
  return Status::ok;
}

}  // namespace optim
}  // namespace v0
}  // namespace cyclide
