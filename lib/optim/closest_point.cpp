#include "optim/closest_point.hpp"

#include <ceres/ceres.h>

#include <cmath>
#include "ceres_options.hpp"

namespace cyclide {
inline namespace v0 {
namespace optim {

namespace {

// Residual x(u, v) - X with the evaluator's exact partials as Jacobian.
class PointResidual final : public ceres::SizedCostFunction<3, 1, 1> {
 public:
  PointResidual(const Surface& S, const Vec3d& X) : S_(S), X_(X) {}
  bool Evaluate(double const* const* params, double* residuals,
                double** jacobians) const override {
    double x[3], xu[3], xv[3];
    const bool want = jacobians && (jacobians[0] || jacobians[1]);
    if (S_.eval(params[0][0], params[1][0],
                {x, want ? xu : nullptr, want ? xv : nullptr, nullptr}) != Status::ok)
      return false;  // Ceres shortens the step
    for (int k = 0; k < 3; ++k) residuals[k] = x[k] - X_[k];
    if (jacobians) {
      if (jacobians[0])
        for (int k = 0; k < 3; ++k) jacobians[0][k] = xu[k];
      if (jacobians[1])
        for (int k = 0; k < 3; ++k) jacobians[1][k] = xv[k];
    }
    return true;
  }

 private:
  const Surface& S_;
  Vec3d X_;
};

// Distance from X to the circle at u (closed form), or +inf if undefined.
double circle_distance(const Surface& S, double u, const Vec3d& X) {
  Vec3d c, n;
  double rho2;
  if (S.circle(u, c, n, rho2) != Status::ok) return HUGE_VAL;
  const Vec3d w = X - c;
  const double h = w.dot(n);
  const double d = (w - h * n).norm();
  const double e = d - std::sqrt(rho2);
  return std::sqrt(h * h + e * e);
}

}  // namespace

Status closest_point(const Surface& S, const Vec3d& X, ClosestPoint& out) {
  if (!input_ok(X)) return Status::not_finite;
  // Global start on the circles.
  double best_u = S.u0, best = HUGE_VAL;
  for (int k = 0; k < kDomainSamples; ++k) {
    const double u = S.sample(k);
    const double d = circle_distance(S, u, X);
    if (d < best) {
      best = d;
      best_u = u;
    }
  }
  if (!std::isfinite(best)) return Status::numerical_overflow;
  double u = best_u, v = 0;
  if (Status st = S.parameter_of(u, X, v); st != Status::ok) return st;
  if (!std::isfinite(v)) v = 1e12;  // the generator: a large finite v
  // Local refinement.
  ceres::Problem problem;
  problem.AddResidualBlock(new PointResidual(S, X), nullptr, &u, &v);
  problem.SetParameterLowerBound(&u, 0, S.u0);
  problem.SetParameterUpperBound(&u, 0, S.u1);
  const ceres::Solver::Options options = quiet_dense_options(100, 1e-16, 1e-16, 1e-14);
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  double x[3];
  if (S.eval(u, v, {x, nullptr, nullptr, nullptr}) != Status::ok)
    return Status::numerical_overflow;
  ClosestPoint R;
  R.u = u;
  R.v = v;
  R.point = Vec3d(x[0], x[1], x[2]);
  R.distance = (R.point - X).norm();
  R.iterations = int(summary.iterations.size());
  out = R;
  return Status::ok;
}

}  // namespace optim
}  // namespace v0
}  // namespace cyclide
