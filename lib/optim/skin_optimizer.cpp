// Seed 002 Remark 2: tangent lengths that make a sphere skin valid
// (skin_optimizer.hpp).
#include "optim/skin_optimizer.hpp"

#include <ceres/ceres.h>

#include <cmath>
#include "ceres_options.hpp"

namespace cyclide {
inline namespace v0 {
namespace optim {

namespace {

// kappa r at both ends for the scales exp(x): with Delta = p_f - p_i, the
// spine's alpha'(0) = s_i t_i, alpha''(0) = 2 (3 Delta - 2 s_i t_i - s_f
// t_f), alpha'(1) = s_f t_f, alpha''(1) = -6 Delta + 2 s_i t_i + 4 s_f t_f
// (the cubic Hermite's power form differentiated), kappa = |a' x a''| /
// |a'|^3 (Remark 2 at t = 0).
struct TangentCost {
  Vec3d delta, ti, tf;
  double ri, rf, target;
  template <class T>
  void kappa_r(const T* x, T* kr) const {
    using std::exp;
    using std::sqrt;
    const T si = exp(x[0]), sf = exp(x[1]);
    const Vec3<T> a0 = ti.cast<T>() * si, a1 = tf.cast<T>() * sf;
    const Vec3<T> d = delta.cast<T>();
    const Vec3<T> b0 = (d * T(3.0) - a0 * T(2.0) - a1) * T(2.0);
    const Vec3<T> b1 = d * T(-6.0) + a0 * T(2.0) + a1 * T(4.0);
    const T n0 = sqrt(a0.squaredNorm()), n1 = sqrt(a1.squaredNorm());
    kr[0] = sqrt(T(a0.cross(b0).squaredNorm() + 1e-300)) / (n0 * n0 * n0) * ri;
    kr[1] = sqrt(T(a1.cross(b1).squaredNorm() + 1e-300)) / (n1 * n1 * n1) * rf;
  }
  template <class T>
  bool operator()(const T* x, T* r) const {
    T kr[2];
    kappa_r(x, kr);
    r[0] = x[0];
    r[1] = x[1];
    for (int e = 0; e < 2; ++e) {
      const T excess = kr[e] / target - 1.0;
      r[2 + e] = ceres::fmax(excess, T(0.0)) * 1e3;
    }
    return true;
  }
};

}  // namespace

Status optimize_skin_tangents(const SkinEnd& start, const SkinEnd& end, const SkinOptions& skin,
                              const SkinTangentOptions& o, SkinEnd& start_out, SkinEnd& end_out,
                              SkinTangentSummary& summary) {
  if (!std::isfinite(o.target) || !std::isfinite(o.min_ratio) || !std::isfinite(o.max_ratio))
    return Status::not_finite;
  if (!(o.target > 0 && o.target < 1) || !(o.min_ratio > 0 && o.min_ratio <= 1) ||
      !(o.max_ratio >= 1) || o.max_iterations < 0)
    return Status::invalid_argument;
  SphereSkin S;
  const Status first = make_sphere_skin(start, end, skin, S);
  SkinTangentSummary R;
  TangentCost f{end.center - start.center, start.tangent, end.tangent, start.radius,
                end.radius, o.target};
  const double zero[2] = {0, 0};
  f.kappa_r(zero, R.kappa_r_initial);
  if (first == Status::ok) {
    R.kappa_r[0] = R.kappa_r_initial[0];
    R.kappa_r[1] = R.kappa_r_initial[1];
    start_out = start;
    end_out = end;
    summary = R;
    return Status::ok;
  }
  if (first != Status::curvature_radius_too_large) return first;
  double x[2] = {0, 0};
  ceres::Problem problem;
  problem.AddResidualBlock(new ceres::AutoDiffCostFunction<TangentCost, 4, 2>(new TangentCost(f)),
                           nullptr, x);
  for (int i = 0; i < 2; ++i) {
    problem.SetParameterLowerBound(x, i, std::log(o.min_ratio));
    problem.SetParameterUpperBound(x, i, std::log(o.max_ratio));
  }
  // Ceres' default gradient tolerance (1e-10).
  const ceres::Solver::Options so = quiet_dense_options(o.max_iterations, 1e-12, 1e-10, 1e-12);
  ceres::Solver::Summary cs;
  ceres::Solve(so, &problem, &cs);
  // The cones stay: c t = x - p is fixed, so 1/c scales with the tangent.
  SkinEnd s = start, e = end;
  s.tangent *= std::exp(x[0]);
  s.inv_c *= std::exp(x[0]);
  e.tangent *= std::exp(x[1]);
  e.inv_c *= std::exp(x[1]);
  if (const Status st = make_sphere_skin(s, e, skin, S); st != Status::ok)
    return st == Status::curvature_radius_too_large ? st : Status::curvature_radius_too_large;
  R.scale[0] = std::exp(x[0]);
  R.scale[1] = std::exp(x[1]);
  f.kappa_r(x, R.kappa_r);
  R.iterations = std::max(int(cs.iterations.size()) - 1, 1);
  start_out = s;
  end_out = e;
  summary = R;
  return Status::ok;
}

}  // namespace optim
}  // namespace v0
}  // namespace cyclide
