// Seed 001 §5.a: the bump optimizer (see bump_optimizer.hpp).
#include "optim/bump_optimizer.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "cyclide/ringed.hpp"
#include "ceres_options.hpp"

namespace cyclide {
inline namespace v0 {
namespace optim {

namespace {

// The plain blend at a node: d, d', n (unit), rho, |rho'|.
struct Node {
  double t;
  Vec3d d, dd, n;
  double rho, drho;
};

// b(t; tau) and b'(t; tau): (52) with the sign of ERRATA.md, or (57).
template <class T>
void bump_at(BumpKind kind, double t, const T& tau, T& b, T& db) {
  if (kind == BumpKind::single) {
    const double g = (1 - t) * (1 - t) * t * t, dg = 2 * t - 6 * t * t + 4 * t * t * t;
    const T h = t * (2.0 - 4.0 * tau) + tau * (5.0 * tau - 3.0), dh = 2.0 - 4.0 * tau;
    const T K = (1.0 - tau) * (1.0 - tau) * (1.0 - tau) * tau * tau * tau;
    b = -(g * h) / K;
    db = -(dg * h + g * dh) / K;
    return;
  }
  if (T(t) <= tau) {
    const T k = tau * tau * tau;
    b = t * t * (3.0 * tau - 2.0 * t) / k;
    db = (6.0 * t * tau - 6.0 * t * t) / k;
  } else {
    const T k = (1.0 - tau) * (1.0 - tau) * (1.0 - tau);
    b = (t - 1) * (t - 1) * (2.0 * t - 3.0 * tau + 1.0) / k;
    db = (2 * (t - 1) * (2.0 * t - 3.0 * tau + 1.0) + 2.0 * (t - 1) * (t - 1)) / k;
  }
}

struct BumpCost {
  const std::vector<Node>* nodes;
  const BumpObjective* objective;
  BumpKind kind;
  double L;
  double fixed_tau;  // < 0: tau is the parameter
  int residual_count() const {
    return int(nodes->size()) * (1 + objective->obstacle_count);
  }
  template <class T>
  bool operator()(const T* const w, const T* const tau_p, T* r) const {
    const T tau = fixed_tau < 0 ? tau_p[0] : T(fixed_tau);
    const double N = double(nodes->size());
    const double sd = std::sqrt(objective->deviance / N), so = std::sqrt(objective->obstacle_weight / N);
    int k = 0;
    for (const Node& q : *nodes) {
      T b, db;
      bump_at(kind, q.t, tau, b, db);
      T D[3], X[3];
      for (int j = 0; j < 3; ++j) {
        D[j] = q.dd[j] + w[j] * db;
        X[j] = q.d[j] + w[j] * b;
      }
      // sin angle(n, D) = |n x D| / |D| (n unit).
      const T c0 = q.n[1] * D[2] - q.n[2] * D[1], c1 = q.n[2] * D[0] - q.n[0] * D[2],
              c2 = q.n[0] * D[1] - q.n[1] * D[0];
      const T dn2 = D[0] * D[0] + D[1] * D[1] + D[2] * D[2];
      if (!(dn2 > T(0))) return false;
      using std::sqrt;
      r[k++] = sd * sqrt(c0 * c0 + c1 * c1 + c2 * c2) / sqrt(dn2);
      for (int o = 0; o < objective->obstacle_count; ++o) {
        const SphereObstacle& S = objective->obstacles[o];
        const T e0 = X[0] - S.center.x(), e1 = X[1] - S.center.y(), e2 = X[2] - S.center.z();
        const T dist = sqrt(e0 * e0 + e1 * e1 + e2 * e2);
        // Conservative over the node's cell [t - h/2, t + h/2] (h = 1/N):
        // |d* - s| - rho changes by at most (|d*'| + |rho'|) h/2 to first
        // order, so a zero hinge at every node clears the whole blend
        // (without it, a large bump can pass the sphere between nodes).
        const T reach = T(0.5 / N) * (sqrt(dn2) + T(q.drho));
        const T gap = T(S.radius + objective->clearance) - (dist - q.rho) + reach;
        r[k++] = gap > T(0) ? T(so) * gap / L : T(0);
      }
    }
    return true;
  }
};

// Every input within the core's range |x| <= kMaxInputMagnitude (so the
// boxes +-w_bound L and every residual stay finite), then the ranges.
bool jet_ok(const RingedJet& j) {
  return input_ok(j.d) && input_ok(j.dd) && input_ok(j.n) && input_ok(j.dn) && input_ok(j.rho) &&
         input_ok(j.drho);
}

Status check(const RingedJet& a, const RingedJet& b, const RingedBlendOptions& blend,
             const BumpObjective& o, const BumpOptions& p) {
  if (!jet_ok(a) || !jet_ok(b)) return Status::not_finite;
  for (double x : {o.deviance, o.clearance, o.obstacle_weight, p.w_bound, p.tau_min, p.tau_max,
                   p.function_tolerance, p.gradient_tolerance, p.parameter_tolerance})
    if (!input_ok(x)) return Status::not_finite;
  if (!input_ok(blend.bump.w) || !input_ok(blend.bump.tau) || !input_ok(blend.tau) ||
      !input_ok(blend.v))
    return Status::not_finite;
  if (o.deviance < 0 || o.clearance < 0 || o.obstacle_weight < 0) return Status::invalid_argument;
  if (o.nodes < 4 || o.nodes > 1024 || o.obstacle_count < 0 ||
      (o.obstacle_count > 0 && !o.obstacles))
    return Status::invalid_argument;
  for (int i = 0; i < o.obstacle_count; ++i) {
    if (!input_ok(o.obstacles[i].center) || !input_ok(o.obstacles[i].radius))
      return Status::not_finite;
    if (o.obstacles[i].radius < 0) return Status::invalid_argument;
  }
  if (!(p.w_bound > 0) || !(p.tau_min > 0) || !(p.tau_max < 1) || p.tau_min > p.tau_max ||
      p.max_iterations < 0 || p.function_tolerance < 0 || p.gradient_tolerance < 0 ||
      p.parameter_tolerance < 0)
    return Status::invalid_argument;
  if (blend.tau != 0.0 && blend.bump.kind == BumpKind::two_piece && p.free_tau)
    return Status::invalid_argument;
  return Status::ok;
}

// The node data of the plain blend (no bump) at the midpoints of [0, 1].
Status sample_nodes(const RingedJet& a, const RingedJet& b, const RingedBlendOptions& blend,
                    int n, std::vector<Node>& nodes) {
  RingedBlendOptions plain = blend;
  plain.bump = DirectrixBump();
  Surface P[2];
  int count = 0;
  if (Status st = make_ringed_pcurve_blend(a, b, plain, P, count); st != Status::ok) return st;
  nodes.resize(n);
  for (int i = 0; i < n; ++i) {
    const double t = (i + 0.5) / n;
    const Surface& S = count == 2 && t >= P[1].u0 ? P[1] : P[0];
    RingedData R;
    if (Status st = S.ringed(t, R); st != Status::ok) return st;
    if (!(R.n.norm() > 0)) return Status::dependent_planes;
    const double rho = std::sqrt(std::max(0.0, R.rho2));
    nodes[i] = {t, R.c, R.dc, R.n.normalized(), rho,
                rho > 0 ? std::abs(R.rho_rho_prime) / rho : 0.0};
  }
  return Status::ok;
}

double evaluate(const BumpCost& f, const double* w, double tau, double* deviance_term) {
  std::vector<double> r(f.residual_count());
  if (!f(w, &tau, r.data())) return HUGE_VAL;
  double dev = 0, all = 0;
  const int stride = 1 + f.objective->obstacle_count;
  for (size_t i = 0; i < r.size(); ++i) {
    all += 0.5 * r[i] * r[i];
    if (i % stride == 0) dev += 0.5 * r[i] * r[i];
  }
  if (deviance_term) *deviance_term = dev;
  return all;
}

// The unknowns (issue 4's common description): w's components in
// [-w_bound L, w_bound L], tau in [tau_min, tau_max] or held at the start's
// (lower = upper); starts clamped into the boxes.
void bump_parameters(const DirectrixBump& bump, const BumpOptions& options, double L,
                     FreeParameters& out) {
  out = FreeParameters();
  for (int j = 0; j < 3; ++j) {
    FreeParameter q;
    q.role = ParameterRole::bump_displacement;
    q.index = j;
    q.lower = -options.w_bound * L;
    q.upper = options.w_bound * L;
    q.start = q.value = std::min(std::max(bump.w[j], q.lower), q.upper);
    out.add(q);
  }
  FreeParameter t;
  t.role = ParameterRole::bump_position;
  t.lower = options.free_tau ? options.tau_min : bump.tau;
  t.upper = options.free_tau ? options.tau_max : bump.tau;
  t.start = t.value = std::min(std::max(bump.tau, t.lower), t.upper);
  out.add(t);
}

double ends_length(const RingedJet& a, const RingedJet& b) {
  return (a.d - b.d).norm() + std::abs(a.rho) + std::abs(b.rho);
}

}  // namespace

Status describe_bump_parameters(const RingedJet& a, const RingedJet& b,
                                const RingedBlendOptions& blend, const BumpObjective& objective,
                                const BumpOptions& options, FreeParameters& out) {
  if (Status st = check(a, b, blend, objective, options); st != Status::ok) return st;
  const double L = ends_length(a, b);
  if (!(L > 0) || !std::isfinite(L)) return Status::invalid_argument;
  bump_parameters(blend.bump, options, L, out);
  return Status::ok;
}

Status optimize_pcurve_bump(const RingedJet& a, const RingedJet& b,
                            const RingedBlendOptions& blend, const BumpObjective& objective,
                            const BumpOptions& options, Surface (&pieces)[2], int& count,
                            DirectrixBump& chosen, BlendSummary& summary) {
  const auto clock0 = std::chrono::steady_clock::now();
  if (Status st = check(a, b, blend, objective, options); st != Status::ok) return st;
  std::vector<Node> nodes;
  if (Status st = sample_nodes(a, b, blend, objective.nodes, nodes); st != Status::ok) return st;
  const double L = ends_length(a, b);
  if (!(L > 0) || !std::isfinite(L)) return Status::invalid_argument;
  const BumpKind kind = blend.bump.kind;
  const bool free_tau = options.free_tau;
  FreeParameters params;
  bump_parameters(blend.bump, options, L, params);
  double w[3] = {params.p[0].start, params.p[1].start, params.p[2].start};
  double tau = params.p[3].start;
  BumpCost f{&nodes, &objective, kind, L, free_tau ? -1.0 : blend.bump.tau};
  const double w0[3] = {w[0], w[1], w[2]};
  const double tau0 = tau;
  const double initial = evaluate(f, w, tau, nullptr);
  if (!std::isfinite(initial)) return Status::singular_point;  // d*' = 0 at a node
  // The start blend must exist (it is the fallback).
  RingedBlendOptions start = blend;
  start.bump.w = Vec3d(w0[0], w0[1], w0[2]);
  start.bump.tau = free_tau ? tau0 : blend.bump.tau;
  Surface S0[2];
  int c0 = 0;
  if (Status st = make_ringed_pcurve_blend(a, b, start, S0, c0); st != Status::ok) return st;

  ceres::Problem problem;
  auto* cost = new ceres::AutoDiffCostFunction<BumpCost, ceres::DYNAMIC, 3, 1>(
      new BumpCost(f), f.residual_count());
  problem.AddResidualBlock(cost, nullptr, w, &tau);
  for (int j = 0; j < 3; ++j) {
    problem.SetParameterLowerBound(w, j, params.p[j].lower);
    problem.SetParameterUpperBound(w, j, params.p[j].upper);
  }
  if (free_tau) {
    problem.SetParameterLowerBound(&tau, 0, params.p[3].lower);
    problem.SetParameterUpperBound(&tau, 0, params.p[3].upper);
  } else {
    problem.SetParameterBlockConstant(&tau);
  }
  const ceres::Solver::Options so =
      quiet_dense_options(options.max_iterations, options.function_tolerance,
                          options.gradient_tolerance, options.parameter_tolerance);
  ceres::Solver::Summary cs;
  if (options.max_iterations > 0) ceres::Solve(so, &problem, &cs);

  BlendSummary sum;
  sum.initial_cost = initial;
  sum.iterations = options.max_iterations > 0 ? int(cs.iterations.size()) - 1 : 0;
  sum.length_scale = L;
  sum.termination = cs.termination_type == ceres::NO_CONVERGENCE ? BlendTermination::iteration_limit
                                                                  : BlendTermination::converged;
  // The result, rebuilt; the start if it fails or is worse.
  RingedBlendOptions best = blend;
  best.bump.w = Vec3d(w[0], w[1], w[2]);
  best.bump.tau = tau;
  double dev = 0;
  double final_cost = evaluate(f, w, tau, &dev);
  Surface S[2];
  int c = 0;
  if (!(final_cost <= initial) || make_ringed_pcurve_blend(a, b, best, S, c) != Status::ok) {
    best = start;
    final_cost = evaluate(f, w0, tau0, &dev);
    for (int k = 0; k < c0; ++k) S[k] = S0[k];
    c = c0;
    sum.termination = BlendTermination::reverted;
  }
  sum.final_cost = final_cost;
  sum.parameters = params;
  for (int j = 0; j < 3; ++j) sum.parameters.p[j].value = best.bump.w[j];
  sum.parameters.p[3].value = best.bump.tau;
  sum.fairness = dev;
  sum.obstacles = final_cost - dev;
  sum.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock0).count();
  for (int k = 0; k < c; ++k) pieces[k] = S[k];
  count = c;
  chosen = best.bump;
  summary = sum;
  return Status::ok;
}

}  // namespace optim
}  // namespace v0
}  // namespace cyclide
