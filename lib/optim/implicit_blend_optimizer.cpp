// Seed 001 §7.a: the implicit-blend approximation (see
// implicit_blend_optimizer.hpp).
#include "optim/implicit_blend_optimizer.hpp"

#include <ceres/ceres.h>

#include <chrono>
#include <cmath>
#include <vector>

#include "cyclide/quadrature.hpp"
#include "ceres_options.hpp"

namespace cyclide {
inline namespace v0 {
namespace optim {

namespace {

// Omega (81) as a sum of squared residuals over the Gauss-Legendre nodes:
//   Phi (82): sqrt(w_k) f/|grad f| and sqrt(w_k) f_v/|grad f_v| at c_i(t_k),
//   Psi (83): sqrt(w w_k) L (a.n)/(|a| |n|), the same for b, with a = c1 -
//   c2, b = c1 - c3 and n = dbar'(t_k) (the tangent of the auxiliary
//   directrix: the transcription notes that Psi's printed first argument
//   dbar is likely meant as dbar'; a point is no direction). The factor L
//   = |s2 - s1| gives Psi the length^2 units of Phi.
struct OmegaCost {
  const ImplicitBlend* B;
  const ContourPiece* P;
  const std::vector<double>* tn;
  const std::vector<double>* tw;
  double psi;  // sqrt(w) L
  int residual_count() const { return 8 * int(tn->size()); }

  template <class T>
  bool operator()(const T* const ab, T* r) const {
    using std::sqrt;
    int k = 0;
    for (size_t node = 0; node < tn->size(); ++node) {
      const T t((*tn)[node]);
      const double sw = std::sqrt((*tw)[node]);
      Vec3<T> c[3];
      for (int i = 0; i < 3; ++i) {
        const Vec3<T> dp = P->tp[i].cast<T>() * ab[i], dq = P->tq[i].cast<T>() * ab[3 + i];
        c[i] = ferguson(P->p[i], dp, P->q[i], dq, t);
        const BlendJet<T> J = blend_eval(*B, c[i], &P->v[i]);
        const T g2 = J.grad.squaredNorm(), h2 = J.hv.squaredNorm();
        if (!(g2 > T(0)) || !(h2 > T(0))) return false;
        r[k++] = T(sw) * J.f / sqrt(g2);
        r[k++] = T(sw) * J.grad.dot(P->v[i].cast<T>()) / sqrt(h2);
      }
      const Vec3d n = P->dbar_derivative((*tn)[node]).normalized();
      const Vec3<T> a = c[0] - c[1], b = c[0] - c[2];
      const T na = a.norm(), nb = b.norm();
      if (!(na > T(0)) || !(nb > T(0))) return false;
      r[k++] = T(sw * psi) * a.dot(n.cast<T>()) / na;
      r[k++] = T(sw * psi) * b.dot(n.cast<T>()) / nb;
    }
    return true;
  }
};

double omega_of(const OmegaCost& f, const double* ab) {
  std::vector<double> r(size_t(f.residual_count()));
  if (!f(ab, r.data())) return HUGE_VAL;
  double s = 0;
  for (double x : r) s += x * x;
  return std::isfinite(s) ? s : HUGE_VAL;
}

Status check(const Vec3d (&v)[3], const ImplicitApproxOptions& o) {
  for (double x : {o.psi_weight, o.length_min_ratio, o.length_max_ratio, o.function_tolerance,
                   o.gradient_tolerance, o.parameter_tolerance})
    if (!std::isfinite(x)) return Status::not_finite;
  for (const Vec3d& w : v)
    if (!input_ok(w)) return Status::not_finite;
  const int used = o.two_curves ? 2 : 3;
  for (int i = 0; i < used; ++i) {
    if (!(v[i].norm() > 0)) return Status::invalid_argument;
    for (int j = 0; j < i; ++j)
      if (v[i].normalized().cross(v[j].normalized()).norm() <= 1e-9)
        return Status::invalid_argument;
  }
  if (o.pieces < 1 || o.pieces > kMaxImplicitPieces || o.psi_weight < 0 || o.nodes < 2 ||
      o.nodes > 64 || !(o.length_min_ratio > 0) || !(o.length_max_ratio >= o.length_min_ratio) ||
      o.max_iterations < 0 || o.max_iterations > 10000 || o.error_nodes_t < 1 ||
      o.error_nodes_t > 64 || o.error_nodes_u < 4 || o.error_nodes_u > 1024)
    return Status::invalid_argument;
  return Status::ok;
}

void cubic_tangents(const ContourPiece& P, const double* ab, Vec3d (&dp)[3], Vec3d (&dq)[3]) {
  for (int i = 0; i < 3; ++i) {
    dp[i] = ab[i] * P.tp[i];
    dq[i] = ab[3 + i] * P.tq[i];
  }
}

// One piece: Ceres on (alpha_i, beta_i), revert-if-worse, the surface.
Status solve_piece(const ImplicitBlend& B, const ContourPiece& P, const ImplicitApproxOptions& o,
                   Surface& S, ImplicitApproxPiece& R) {
  std::vector<double> tn(size_t(o.nodes)), tw(size_t(o.nodes));
  gauss_legendre01(o.nodes, tn.data(), tw.data());
  const OmegaCost f{&B, &P, &tn, &tw, std::sqrt(o.psi_weight) * P.length()};
  double ab[6], lo[6], hi[6];
  for (int i = 0; i < 3; ++i) {
    const double L = (P.q[i] - P.p[i]).norm();
    if (!(L > 0)) return Status::invalid_argument;
    ab[i] = ab[3 + i] = L;
    lo[i] = lo[3 + i] = o.length_min_ratio * L;
    hi[i] = hi[3 + i] = o.length_max_ratio * L;
  }
  double ab0[6];
  for (int k = 0; k < 6; ++k) ab0[k] = ab[k];
  const double initial = omega_of(f, ab);
  if (!std::isfinite(initial)) return Status::singular_point;
  ceres::Solver::Summary cs;
  if (o.max_iterations > 0) {
    ceres::Problem problem;
    auto* cost = new ceres::AutoDiffCostFunction<OmegaCost, ceres::DYNAMIC, 6>(
        new OmegaCost(f), f.residual_count());
    problem.AddResidualBlock(cost, nullptr, ab);
    for (int k = 0; k < 6; ++k) {
      problem.SetParameterLowerBound(ab, k, lo[k]);
      problem.SetParameterUpperBound(ab, k, hi[k]);
    }
    const ceres::Solver::Options so = quiet_dense_options(
        o.max_iterations, o.function_tolerance, o.gradient_tolerance, o.parameter_tolerance);
    ceres::Solve(so, &problem, &cs);
  }
  ImplicitApproxPiece r;
  r.omega_initial = initial;
  r.iterations = o.max_iterations > 0 ? int(cs.iterations.size()) - 1 : 0;
  double omega = omega_of(f, ab);
  Vec3d dp[3], dq[3];
  cubic_tangents(P, ab, dp, dq);
  Surface T;
  if (!(omega <= initial) || ringed_through_cubics(P.p, dp, P.q, dq, T) != Status::ok) {
    for (int k = 0; k < 6; ++k) ab[k] = ab0[k];
    omega = initial;
    r.reverted = true;
    cubic_tangents(P, ab, dp, dq);
    if (Status st = ringed_through_cubics(P.p, dp, P.q, dq, T); st != Status::ok) return st;
  }
  r.omega = omega;
  for (int i = 0; i < 3; ++i) {
    r.alpha[i] = ab[i];
    r.beta[i] = ab[3 + i];
  }
  if (Status st = blend_error_87(B, T, o.error_nodes_t, o.error_nodes_u, r.error87);
      st != Status::ok)
    return st;
  S = T;
  R = r;
  return Status::ok;
}

// The parameter in [0, 1] where the cubic c crosses the plane N.(x - o) =
// 0, nearest to tau (sign changes on 64 intervals, then bisection).
bool cubic_plane_crossing(const Vec3d& p, const Vec3d& dp, const Vec3d& q, const Vec3d& dq,
                          const Vec3d& N, const Vec3d& o, double tau, double& t) {
  auto g = [&](double s) { return N.dot(ferguson(p, dp, q, dq, s) - o); };
  bool found = false;
  double best = 0;
  for (int k = 0; k < 64; ++k) {
    double a = k / 64.0, b = (k + 1) / 64.0, ga = g(a), gb = g(b);
    if (ga == 0) gb = ga, b = a;
    if (ga * gb > 0) continue;
    for (int it = 0; it < 60 && b - a > 1e-15; ++it) {
      const double m = 0.5 * (a + b), gm = g(m);
      if ((gm <= 0) == (ga <= 0)) {
        a = m;
        ga = gm;
      } else {
        b = m;
      }
    }
    const double s = 0.5 * (a + b);
    if (!found || std::abs(s - tau) < std::abs(best - tau)) best = s;
    found = true;
  }
  t = best;
  return found;
}

}  // namespace

Status approximate_implicit_blend(const ImplicitBlend& B, const Vec3d (&v)[3],
                                  const ImplicitApproxOptions& options,
                                  Surface (&pieces)[kMaxImplicitPieces], int& count,
                                  ImplicitApproxReport& report) {
  const auto clock0 = std::chrono::steady_clock::now();
  if (Status st = check(v, options); st != Status::ok) return st;
  ContourPiece whole;
  if (Status st = options.two_curves ? contour_piece_two_curves(B, v[0], v[1], whole)
                                     : contour_piece(B, v, whole);
      st != Status::ok)
    return st;
  const Vec3d(&w)[3] = whole.v;  // the branches' directions (Remark 7.5: v1, v1, v2)
  std::vector<Surface> S(size_t(options.pieces));
  ImplicitApproxReport rep;
  rep.pieces = options.pieces;
  if (Status st = solve_piece(B, whole, options, S[0], rep.piece[0]); st != Status::ok)
    return st;
  rep.data[0] = whole;
  if (options.pieces > 1) {
    // (84): cut planes dbar'(tau).(x - dbar(tau)) = 0 at tau = k/pieces;
    // their contour points by 2D Newton from the one-piece cubics.
    const int m = options.pieces;
    Vec3d ends[kMaxImplicitPieces + 1][3], normals[kMaxImplicitPieces + 1];
    Vec3d dp[3], dq[3];
    for (int i = 0; i < 3; ++i) {
      dp[i] = rep.piece[0].alpha[i] * whole.tp[i];
      dq[i] = rep.piece[0].beta[i] * whole.tq[i];
    }
    for (int i = 0; i < 3; ++i) {
      ends[0][i] = whole.p[i];
      ends[m][i] = whole.q[i];
    }
    normals[0] = whole.nA;
    normals[m] = whole.nB;
    for (int k = 1; k < m; ++k) {
      const double tau = double(k) / m;
      const Vec3d o = whole.dbar(tau), N = whole.dbar_derivative(tau);
      if (!(N.norm() > 0)) return Status::zero_tangent;
      normals[k] = N;
      for (int i = 0; i < 3; ++i) {
        double t = tau;
        if (!cubic_plane_crossing(whole.p[i], dp[i], whole.q[i], dq[i], N, o, tau, t))
          return Status::empty_real_locus;
        Vec3d x = ferguson(whole.p[i], dp[i], whole.q[i], dq[i], t);
        if (Status st = plane_contour_newton(B, w[i], N, o, x); st != Status::ok) return st;
        ends[k][i] = x;
      }
    }
    for (int k = 0; k < m; ++k) {
      ContourPiece P;
      if (Status st = contour_piece_from_points(B, w, ends[k], ends[k + 1], normals[k],
                                                normals[k + 1], P);
          st != Status::ok)
        return st;
      if (Status st = solve_piece(B, P, options, S[size_t(k)], rep.piece[k]); st != Status::ok)
        return st;
      rep.data[k] = P;
    }
  }
  for (int k = 0; k < options.pieces; ++k) {
    rep.omega += rep.piece[k].omega;
    // (87) of the piecewise surface on I = [0, 1], piece k on [k/m, (k+1)/m]
    // (each piece's own integral is over its parameter [0, 1]).
    rep.error87 += rep.piece[k].error87 / options.pieces;
  }
  rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock0).count();
  for (int k = 0; k < options.pieces; ++k) pieces[k] = S[size_t(k)];
  count = options.pieces;
  report = rep;
  return Status::ok;
}

}  // namespace optim
}  // namespace v0
}  // namespace cyclide
