// The blend optimizer (blend_optimizer.hpp, SPEC.md §8e): one residual
// vector, generic in the scalar, differentiated by Ceres' Jets.
#include "optim/blend_optimizer.hpp"

#include "cyclide/quadrature.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

#include "cyclide/prcs.hpp"
#include "cyclide/prrs.hpp"
#include "ceres_options.hpp"

namespace cyclide {
inline namespace v0 {
namespace optim {

namespace {

// The Hermite curves' series order at a node: the canal spine s needs the
// curves to order 3 for s' to order 2 (x_tt needs the frame to order 2).
constexpr int kOrder = 4;
using Basis = Taylor<double, kOrder>;

// Everything the residuals need, fixed during the solve.
struct Problem {
  BlendKind kind = BlendKind::canal;
  int K = 0, count = 0, free = 0;
  bool free_points = false;  // the chosen points' circle parameters are unknowns
  double t0 = 0, t1 = 1;
  Vec3d D[2][3][kMaxBlendOrder + 1];  // d^k x/du^k at the chosen points (fixed)
  // The end circles' frames as u-series of order K (coefficients above K
  // zero), for the moving points (free_points).
  CircleFrame<Taylor<double, kMaxBlendOrder>> frame[2];
  double jet0[2][kMaxBlendOrder] = {};  // the jets of orders above `free`
  int nt = 0, nz = 0;
  double tw[kMaxQuadrature] = {}, zn[kMaxQuadrature] = {}, zw[kMaxQuadrature] = {};
  std::vector<Basis> B;   // [node][e][l]: the Hermite basis at the t nodes
  std::vector<Basis> TB;  // [target][e][l]: at the targets' t
  BlendObjective obj;
  std::vector<TargetPoint> targets;
  std::vector<SphereObstacle> obstacles;
  double L = 1;           // length scale
  double fair_norm = 1;   // 1 / sqrt(the start's fairness integral)

  int slots() const { return 2 * (K + 1); }
  // The unknowns: the jets' free orders of both ends, then (free_points)
  // the angles theta = 2 atan v of the chosen points, end by end.
  int jet_index(int e, int m) const { return e * free + m; }
  int point_index(int e, int j) const { return 2 * free + e * count + j; }
  const Basis* basis(int node) const { return &B[size_t(node) * slots()]; }
  int per_node() const { return 1 + int(obstacles.size()) + 2 * nz * (9 + 1); }
  int residuals() const { return nt * per_node() + 2 * int(targets.size()); }
};

// The objective's terms (for the summary; double evaluation only).
struct Terms {
  double fairness = 0, regularity = 0, targets = 0, obstacles = 0;
};

template <class T>
T hinge(const T& q) {
  return value_of(q) > 0 ? q : T(0.0);
}

template <class T>
T sqrt_of(const T& x) {
  using std::sqrt;
  return sqrt(x);
}

// |det(n1, n2, n3)| / (|n1| |n2| |n3|) of the planes' values, as a T.
template <class T, int N>
T relative_det(const ThreePlanes<Taylor<T, N>>& P) {
  Vec3<T> n[3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) n[i][j] = P.n[i][j].c[0];
  const T det = n[0].dot(n[1].cross(n[2]));
  const T den = sqrt_of(T(n[0].squaredNorm() * n[1].squaredNorm() * n[2].squaredNorm()));
  return (value_of(det) < 0 ? -det : det) / den;
}

// The curves p_j at a node: sum over ends and orders of basis * data.
template <class T>
void curves_at(const Problem& P, const Basis* b, const Vec3<T> (&d)[2][3][kMaxBlendOrder + 1],
               Vec3<Taylor<T, kOrder>>* Q) {
  for (int j = 0; j < P.count; ++j)
    for (int c = 0; c < 3; ++c) {
      Taylor<T, kOrder> s;
      for (int e = 0; e < 2; ++e)
        for (int l = 0; l <= P.K; ++l) {
          const Basis& h = b[e * (P.K + 1) + l];
          for (int k = 0; k <= kOrder; ++k) s.c[k] += h.c[k] * d[e][j][l][c];
        }
      Q[j][c] = s;
    }
}

// The blend's circle frame at a node to order 2 (PRCS or PRRS on the
// series), f = v; false where the planes are dependent (a step that
// leaves the valid region is rejected: Ceres shrinks its trust region).
template <class T>
bool frame_of(const Problem& P, const Vec3<Taylor<T, kOrder>>* Q,
              CircleFrame<Taylor<T, 2>>& F, T& rd) {
  if (P.kind == BlendKind::canal) {
    static const RationalCurve polynomial;  // not a line element: n = p'
    const auto planes = prcs_planes<3, T>(polynomial, polynomial, Q[0], Q[1]);
    rd = relative_det(planes);
    if (!(value_of(rd) > kDependentPlanesTol)) return false;
    const Vec3<Taylor<T, 3>> s = intersect(planes);
    F.o = truncate<2>(s);
    F.a = derivative(s);
    F.p = truncate<2>(Q[0]);
  } else {
    const Vec3<Taylor<T, 2>> q1 = truncate<2>(Q[0]), q2 = truncate<2>(Q[1]),
                             q3 = truncate<2>(Q[2]);
    const auto planes = prrs_planes<2, T>(q1, q2, q3);
    rd = relative_det(planes);
    if (!(value_of(rd) > kDependentPlanesTol)) return false;
    F.o = intersect(planes);
    F.a = planes.n[0];
    F.p = q1;
  }
  F.alpha = Taylor<T, 2>(1.0);
  F.beta = Taylor<T, 2>(0.0);
  F.gamma = Taylor<T, 2>(0.0);
  F.delta = Taylor<T, 2>(1.0);
  for (int j = 0; j < 3; ++j)
    if (!std::isfinite(value_of(F.o[j])) || !std::isfinite(value_of(F.a[j]))) return false;
  return true;
}

// The circle's rational quadratic in one chart, x = o + (P0 + P1 z +
// P2 z^2) / (Q0 + Q1 z + Q2 z^2), coefficients as t-series of order 2.
// circle_quadratic of the frame with f = v (alpha = delta = 1, beta = gamma
// = 0) reduces to P0 = 2 (a.d) a - |a|^2 d, P1 = 2 a x d, P2 = d, Q = (|a|^2,
// 0, 1); the chart v = 1/z (alpha <-> beta, gamma <-> delta) is the same
// rational function with the coefficients reversed (multiply by z^2).
template <class T>
void chart_quadratics(const CircleFrame<Taylor<T, 2>>& F, CircleQuadratic<Taylor<T, 2>> (&C)[2]) {
  using U = Taylor<T, 2>;
  const Vec3<U> d = F.p - F.o;
  const U aa = F.a.dot(F.a);
  const U ad = F.a.dot(d);
  const U two(2.0);
  const Vec3<U> P0 = (two * ad) * F.a - aa * d, P1 = two * F.a.cross(d);
  C[0].o = C[1].o = F.o;
  C[0].P[0] = C[1].P[2] = P0;
  C[0].P[1] = C[1].P[1] = P1;
  C[0].P[2] = C[1].P[0] = d;
  C[0].Q[0] = C[1].Q[2] = aa;
  C[0].Q[1] = C[1].Q[1] = U(0.0);
  C[0].Q[2] = C[1].Q[0] = U(1.0);
}

// x_t, x_tt, x_tz, x_zz of x(t, z) = o(t) + N(t, z) / D(t, z) at the node
// (t_i, z) from the chart's quadratic (closed-form quotient rule, the
// t-series coefficients c[k] = d^k/dt^k / k!):
//   f = N/D, f_t = (N_t - f D_t)/D, f_z = (N_z - f D_z)/D,
//   f_tt = (N_tt - 2 f_t D_t - f D_tt)/D,
//   f_tz = (N_tz - f_t D_z - f_z D_t - f D_tz)/D,
//   f_zz = (N_zz - 2 f_z D_z - f D_zz)/D.
template <class T>
struct PointDerivatives {
  Vec3<T> xt, xtt, xtz, xzz;
};

template <class T>
void point_derivatives(const CircleQuadratic<Taylor<T, 2>>& C, double z, PointDerivatives<T>& X) {
  const T z1(z), z2(z * z), two(2.0), twoz(2.0 * z);
  auto quad = [&](const Taylor<T, 2>& a0, const Taylor<T, 2>& a1, const Taylor<T, 2>& a2, T* v) {
    v[0] = a0.c[0] + z1 * a1.c[0] + z2 * a2.c[0];              // value
    v[1] = a0.c[1] + z1 * a1.c[1] + z2 * a2.c[1];              // d/dt
    v[2] = two * (a0.c[2] + z1 * a1.c[2] + z2 * a2.c[2]);      // d2/dt2
    v[3] = a1.c[0] + twoz * a2.c[0];                           // d/dz
    v[4] = a1.c[1] + twoz * a2.c[1];                           // d2/dtdz
    v[5] = two * a2.c[0];                                      // d2/dz2
  };
  T D[6];
  quad(C.Q[0], C.Q[1], C.Q[2], D);
  const T inv = T(1.0) / D[0];
  for (int j = 0; j < 3; ++j) {
    T N[6];
    quad(C.P[0][j], C.P[1][j], C.P[2][j], N);
    const T f = N[0] * inv;
    const T ft = (N[1] - f * D[1]) * inv;
    const T fz = (N[3] - f * D[3]) * inv;
    X.xt[j] = C.o[j].c[1] + ft;
    X.xtt[j] = two * C.o[j].c[2] + (N[2] - two * ft * D[1] - f * D[2]) * inv;
    X.xtz[j] = (N[4] - ft * D[3] - fz * D[1] - f * D[4]) * inv;
    X.xzz[j] = (N[5] - two * fz * D[3] - f * D[5]) * inv;
  }
}

// A point X against the circle of the frame (values): its height h over the
// circle's plane and its distance rho - r from the circle's cylinder, so
// that the distance to the circle is hypot(h, rho - r) (closed form: the
// surfaces are families of circles, so clearance and targets need no
// sampling along v).
template <class T>
void circle_offsets(const CircleFrame<Taylor<T, 2>>& F, const Vec3d& X, T& h, T& radial) {
  CircleFrame<T> V;  // the frame's values
  for (int c = 0; c < 3; ++c) {
    V.o[c] = F.o[c].c[0];
    V.a[c] = F.a[c].c[0];
    V.p[c] = F.p[c].c[0];
  }
  const CircleGeometry<T> G = circle_geometry(V);
  const Vec3<T> n = G.normal / sqrt_of(T(G.normal.squaredNorm()));
  const Vec3<T> w = X.cast<T>() - G.center;
  h = w.dot(n);
  radial = sqrt_of(T((w - h * n).squaredNorm())) - sqrt_of(G.radius2);
}

// The optimizer's dispatch on the order K: detail::with_order with K
// clamped to 0..kMaxBlendOrder, so fn is always called (K outside 1..7 is
// excluded by check_inputs; the clamp keeps such a K at kMaxBlendOrder via
// series_order, as the former switches did).
template <class Fn>
Status with_clamped_order(int K, Fn&& fn) {
  return detail::with_order(std::min(std::max(K, 0), kMaxBlendOrder), std::forward<Fn>(fn));
}

// The series order used for order N: N itself for 1 <= N <= Exact, else
// kMaxBlendOrder (fewer instantiations of the Jet code for the higher orders).
template <int N, int Exact>
constexpr int series_order = (N >= 1 && N <= Exact) ? N : kMaxBlendOrder;

// reparameterize with the series truncated at order K (not kMaxBlendOrder)
// for K <= 3.
template <class D, class T>
void reparameterize_k(int K, const Vec3<D>* dx, const T* jet, Vec3<T>* out) {
  with_clamped_order(K, [&](auto n) -> Status {
    reparameterize_to<series_order<decltype(n)::value, 3>>(K, dx, jet, out);
    return Status::ok;
  });
}

// The frame's series truncated to order N.
template <int N>
CircleFrame<Taylor<double, N>> truncate_frame(const CircleFrame<Taylor<double, kMaxBlendOrder>>& F) {
  CircleFrame<Taylor<double, N>> R;
  R.o = truncate<N>(F.o);
  R.a = truncate<N>(F.a);
  R.p = truncate<N>(F.p);
  R.alpha = truncate<N>(F.alpha);
  R.beta = truncate<N>(F.beta);
  R.gamma = truncate<N>(F.gamma);
  R.delta = truncate<N>(F.delta);
  return R;
}

template <int N, class T>
bool moving_point_order(const CircleFrame<Taylor<double, kMaxBlendOrder>>& F, const T& s1,
                        const T& s0, Vec3<T>* dx) {
  Vec3<Taylor<T, N>> x;
  if (!point_series(truncate_frame<N>(F), s1, s0, x)) return false;
  for (int l = 0; l <= N; ++l)
    for (int c = 0; c < 3; ++c) dx[l][c] = x[c].derivative(l);
  return true;
}

// d^l x/du^l (u, v), l = 0..K, of a chosen point moving on its end circle:
// v = tan(theta / 2) as the homogeneous (sin(theta/2), cos(theta/2)), smooth
// through v = infinity (theta = pi), with theta a Jet.
template <class T>
bool moving_point_derivatives(const CircleFrame<Taylor<double, kMaxBlendOrder>>& F, int K,
                              const T& theta, Vec3<T>* dx) {
  using std::cos;
  using std::sin;
  const T s1 = sin(0.5 * theta), s0 = cos(0.5 * theta);
  bool ok = false;
  with_clamped_order(K, [&](auto n) -> Status {
    ok = moving_point_order<series_order<decltype(n)::value, 3>>(F, s1, s0, dx);
    return Status::ok;
  });
  return ok;
}

// The residual vector (layout: per t node the determinant hinge, one
// clearance hinge per obstacle, then per chart and z node 9 fairness and 1
// speed hinge; then 2 per target). False where a node's frame is
// degenerate or a residual is not finite; *why (if given) tells which.
template <class T>
bool evaluate(const Problem& P, const T* params, T* r, Terms* terms, Status* why = nullptr) {
  auto fail = [why](Status s) {
    if (why) *why = s;
    return false;
  };
  const Status degenerate =
      P.kind == BlendKind::canal ? Status::dependent_planes : Status::collinear_points;
  T jet[2][kMaxBlendOrder];
  for (int e = 0; e < 2; ++e)
    for (int m = 0; m < P.K; ++m)
      jet[e][m] = m < P.free ? params[P.jet_index(e, m)] : T(P.jet0[e][m]);
  Vec3<T> d[2][3][kMaxBlendOrder + 1];
  for (int e = 0; e < 2; ++e)
    for (int j = 0; j < P.count; ++j) {
      if (!P.free_points) {
        reparameterize_k(P.K, P.D[e][j], jet[e], d[e][j]);
        continue;
      }
      Vec3<T> dx[kMaxBlendOrder + 1];
      if (!moving_point_derivatives(P.frame[e], P.K, params[P.point_index(e, j)], dx))
        return fail(Status::degenerate_circle_parameter);
      reparameterize_k(P.K, dx, jet[e], d[e][j]);
    }
  const BlendObjective& O = P.obj;
  const T w_reg(std::sqrt(O.regularity)), w_obs(std::sqrt(O.obstacle_weight)),
      w_tgt(std::sqrt(O.target_weight));
  const double half = 0.5 * (P.t1 - P.t0);
  auto add = [&](double Terms::*field, const T& v) {
    if constexpr (std::is_same<T, double>::value) {
      if (terms) terms->*field += 0.5 * v * v;
    }
  };
  int k = 0;
  for (int i = 0; i < P.nt; ++i) {
    Vec3<Taylor<T, kOrder>> Q[3];
    curves_at(P, P.basis(i), d, Q);
    CircleFrame<Taylor<T, 2>> F;
    T rd;
    if (!frame_of(P, Q, F, rd)) return fail(degenerate);
    r[k] = w_reg * hinge(T((O.min_determinant - rd) / O.min_determinant));
    add(&Terms::regularity, r[k++]);
    for (const SphereObstacle& S : P.obstacles) {
      T h, radial;
      circle_offsets(F, S.center, h, radial);
      const T dist = sqrt_of(T(h * h + radial * radial + 1e-300));
      r[k] = w_obs * hinge(T((S.radius + O.clearance - dist) / P.L));
      add(&Terms::obstacles, r[k++]);
    }
    CircleQuadratic<Taylor<T, 2>> C[2];
    chart_quadratics(F, C);
    for (int chart = 0; chart < 2; ++chart)
      for (int j = 0; j < P.nz; ++j) {
        PointDerivatives<T> X;
        point_derivatives(C[chart], P.zn[j], X);
        const double wq = std::sqrt(O.fairness * P.tw[i] * half * P.zw[j]) * P.fair_norm;
        const T w1(wq), w2(std::sqrt(2.0) * wq);
        for (int c = 0; c < 3; ++c) {
          r[k + c] = w1 * X.xtt[c];
          r[k + 3 + c] = w2 * X.xtz[c];
          r[k + 6 + c] = w1 * X.xzz[c];
        }
        const Vec3<T>& xt = X.xt;
        for (int c = 0; c < 9; ++c) add(&Terms::fairness, r[k + c]);
        k += 9;
        const T speed = sqrt_of(T(xt.squaredNorm()));
        r[k] = w_reg * hinge(T((O.min_speed * P.L - speed) / (O.min_speed * P.L + 1e-300)));
        add(&Terms::regularity, r[k++]);
      }
  }
  for (size_t q = 0; q < P.targets.size(); ++q) {
    Vec3<Taylor<T, kOrder>> Q[3];
    curves_at(P, &P.TB[q * P.slots()], d, Q);
    CircleFrame<Taylor<T, 2>> F;
    T rd;
    if (!frame_of(P, Q, F, rd)) return fail(degenerate);
    T h, radial;
    circle_offsets(F, P.targets[q].point, h, radial);
    r[k] = w_tgt * h / P.L;
    add(&Terms::targets, r[k++]);
    r[k] = w_tgt * radial / P.L;
    add(&Terms::targets, r[k++]);
  }
  for (int q = 0; q < k; ++q)
    if (!std::isfinite(value_of(r[q]))) return fail(Status::numerical_overflow);
  return true;
}

// The box lo <= x <= hi of the free parameters, enforced exactly by the
// smooth map x_i = mid_i + half_i sin(s_i) of the unconstrained solver
// variables s (so Ceres solves an unconstrained problem: its bounds judge
// projected steps by the unprojected model and crawl along active bounds).
// A parameter whose box has zero or non-finite width is fixed at its start.
struct Box {
  int n = 0;
  double lo[kMaxFreeParameters] = {}, hi[kMaxFreeParameters] = {};
  double mid[kMaxFreeParameters] = {}, half[kMaxFreeParameters] = {};
  double x0[kMaxFreeParameters] = {};
  bool fixed[kMaxFreeParameters] = {};
  int pin[kMaxFreeParameters] = {};  // -1 / +1: held at lo / hi (active set)

  Box(const std::vector<double>& l, const std::vector<double>& h, const std::vector<double>& x) {
    n = int(x.size());
    for (int i = 0; i < n; ++i) {
      lo[i] = l[size_t(i)];
      hi[i] = h[size_t(i)];
      x0[i] = x[size_t(i)];
      const double w = hi[i] - lo[i];
      fixed[i] = !(std::isfinite(w) && w > 0);
      half[i] = fixed[i] ? 0.0 : 0.5 * w;
      mid[i] = fixed[i] ? x0[i] : 0.5 * lo[i] + 0.5 * hi[i];
    }
  }
  // The solver variable of x (in [-pi/2, pi/2]; 0 for a fixed parameter).
  double to_s(int i, double x) const {
    if (fixed[i]) return 0.0;
    return std::asin(std::min(std::max((x - mid[i]) / half[i], -1.0), 1.0));
  }
  // x of the solver variable s, inside the box also after rounding; a
  // pinned parameter is its bound (constant).
  template <class T>
  T to_x(int i, const T& s) const {
    using std::sin;
    if (fixed[i]) return T(x0[i]);
    if (pin[i] != 0) return T(pin[i] < 0 ? lo[i] : hi[i]);
    const T x = mid[i] + half[i] * sin(s);
    if (value_of(x) < lo[i]) return T(lo[i]);
    if (value_of(x) > hi[i]) return T(hi[i]);
    return x;
  }
};

// The cost functor in both Ceres forms: one parameter block of fixed size
// (AutoDiffCostFunction, Jets exactly as wide as the parameters) and the
// dynamic form (stride 4) for other counts. The parameters are the solver
// variables s of the box; false (a degenerate node, a residual not finite)
// makes Ceres reject the step and shrink its trust region.
struct Residuals {
  const Problem* P;
  const Box* box;
  bool identity = false;  // the parameters are x itself (the gradient in x)
  template <class T>
  bool operator()(const T* s, T* r) const {
    T x[kMaxFreeParameters];
    for (int i = 0; i < box->n; ++i) x[i] = identity ? s[i] : box->to_x(i, s[i]);
    return evaluate(*P, x, r, nullptr);
  }
  template <class T>
  bool operator()(T const* const* s, T* r) const {
    return (*this)(s[0], r);
  }
};

// The cost function for n = 2 free parameters (free_orders 1, the default
// for K = 1), 4 (free_orders 2, the default for K >= 2), 6, 8 or 10 (the
// defaults with the canal / ringed points free): Jet<double, n>; others:
// dynamic Jets of stride 4.
ceres::CostFunction* make_cost(const Problem& P, const Box& box, bool identity = false) {
  using ceres::AutoDiffCostFunction;
  using ceres::DYNAMIC;
  auto* f = new Residuals{&P, &box, identity};
  switch (box.n) {
    case 2: return new AutoDiffCostFunction<Residuals, DYNAMIC, 2>(f, P.residuals());
    case 4: return new AutoDiffCostFunction<Residuals, DYNAMIC, 4>(f, P.residuals());
    case 6: return new AutoDiffCostFunction<Residuals, DYNAMIC, 6>(f, P.residuals());
    case 8: return new AutoDiffCostFunction<Residuals, DYNAMIC, 8>(f, P.residuals());
    case 10: return new AutoDiffCostFunction<Residuals, DYNAMIC, 10>(f, P.residuals());
    default: {
      auto* cost = new ceres::DynamicAutoDiffCostFunction<Residuals, 4>(f);
      cost->AddParameterBlock(box.n);
      cost->SetNumResiduals(P.residuals());
      return cost;
    }
  }
}

// The box-constrained solve (SPEC.md §8e): Ceres' Levenberg-Marquardt on
// the solver variables s (x = mid + half sin(s)) in rounds with an active
// set. The map's derivative vanishes on the bounds, so on its own an optimum
// on a bound is only crawled towards (the benchmarks ran into the iteration
// limit). A round ends (iteration callback) when a parameter comes within
// kNear of a bound (1 - |sin s| < kNear) that was not examined there yet;
// then, and at the start if a parameter starts near a bound, the gradient in
// x decides: pointing out of the box, the parameter is pinned at the bound
// (held constant with the fixed ones by a SubsetManifold) and the rest are
// solved again; pointing in, it stays free and no longer ends rounds. A
// pinned parameter whose gradient points into the box at the end of a
// round is released once (restarted kNear inside, where the map moves it).
// The rounds share max_iterations; the best point of all rounds is kept.
struct Solved {
  int iterations = 0;  // Ceres' iterations of all rounds
  bool limit = false;  // max_iterations reached before convergence
};

constexpr double kNear = 3e-2;

bool near_bound(double s) { return 1.0 - std::abs(std::sin(s)) < kNear; }

// The gradient of 1/2 |r|^2 in x (false: not evaluable there).
bool gradient_x(const ceres::CostFunction& f, const std::vector<double>& x,
                std::vector<double>& g) {
  const size_t m = size_t(f.num_residuals()), n = x.size();
  std::vector<double> r(m), J(m * n);
  const double* xp = x.data();
  double* jp = J.data();
  if (!f.Evaluate(&xp, r.data(), &jp)) return false;
  g.assign(n, 0.0);
  for (size_t k = 0; k < m; ++k)
    for (size_t i = 0; i < n; ++i) g[i] += J[k * n + i] * r[k];
  for (double gi : g)
    if (!std::isfinite(gi)) return false;
  return true;
}

// Ends a round when a free parameter not yet examined comes near a bound
// (after an accepted step; the state is updated every iteration).
struct NearBound : ceres::IterationCallback {
  const Box* box = nullptr;
  const int* examined = nullptr;  // per parameter: bit 1 the lower, 2 the upper bound
  const double* s = nullptr;
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& it) override {
    if (!it.step_is_successful) return ceres::SOLVER_CONTINUE;
    for (int i = 0; i < box->n; ++i)
      if (!box->fixed[i] && box->pin[i] == 0 && near_bound(s[i]) &&
          !(examined[i] & (s[i] > 0 ? 2 : 1)))
        return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    return ceres::SOLVER_CONTINUE;
  }
};

Solved solve_box(const Problem& P, Box& box, const BlendOptions& options, std::vector<double>& x) {
  Solved out;
  const int n = box.n;
  const double half_pi = std::acos(-1.0) / 2;
  std::vector<double> s(x.size()), best_s(x.size()), g;
  int examined[kMaxFreeParameters] = {};  // the bounds a parameter was examined at
  bool released[kMaxFreeParameters] = {};
  int best_pin[kMaxFreeParameters] = {};
  for (int i = 0; i < n; ++i) s[size_t(i)] = box.to_s(i, x[size_t(i)]);
  const std::unique_ptr<ceres::CostFunction> fx(make_cost(P, box, true));
  // The active set at x = x(s): 1 changed, 0 unchanged, -1 no gradient.
  auto update = [&](bool at_start) {
    for (int i = 0; i < n; ++i) x[size_t(i)] = box.to_x(i, s[size_t(i)]);
    if (!gradient_x(*fx, x, g)) return -1;
    bool changed = false;
    for (int i = 0; i < n; ++i) {
      if (box.fixed[i]) continue;
      const double gi = g[size_t(i)];
      if (box.pin[i] == 0) {
        if (!near_bound(s[size_t(i)])) continue;
        const int side = s[size_t(i)] > 0 ? 1 : -1;
        if (gi * side < 0) {  // descent leaves the box: pin
          box.pin[i] = side;
          s[size_t(i)] = side * half_pi;
          changed = true;
          continue;
        }
        examined[i] |= side > 0 ? 2 : 1;  // stays free
        if (at_start) {  // the map cannot move it off the bound
          s[size_t(i)] = side * std::asin(1.0 - kNear);
          changed = true;
        }
      } else if (gi * box.pin[i] > 0 && !released[i]) {  // descent enters the box
        released[i] = true;
        s[size_t(i)] = box.pin[i] * std::asin(1.0 - kNear);
        box.pin[i] = 0;
        changed = true;
      }
    }
    return changed ? 1 : 0;
  };
  bool start_near = false;
  for (int i = 0; i < n; ++i) start_near |= !box.fixed[i] && near_bound(s[size_t(i)]);
  if (start_near && update(true) < 0) return out;  // x is the start
  NearBound callback;
  callback.box = &box;
  callback.examined = examined;
  callback.s = s.data();
  double best = std::numeric_limits<double>::infinity();
  for (int round = 0; round < 3 * n + 2; ++round) {
    std::vector<int> constant;
    for (int i = 0; i < n; ++i)
      if (box.fixed[i] || box.pin[i] != 0) constant.push_back(i);
    if (int(constant.size()) == n) {  // all pinned: the point is final
      const double* sp = s.data();
      std::vector<double> r(size_t(P.residuals()));
      ceres::CostFunction* f = make_cost(P, box);
      double c = 0;
      if (f->Evaluate(&sp, r.data(), nullptr)) {
        for (double ri : r) c += 0.5 * ri * ri;
        if (c < best) {
          best = c;
          best_s = s;
          std::copy(box.pin, box.pin + n, best_pin);
        }
      }
      delete f;
      break;
    }
    const int budget = options.max_iterations - out.iterations;
    if (budget <= 0) {
      out.limit = true;
      break;
    }
    ceres::Problem problem;
    problem.AddResidualBlock(make_cost(P, box), nullptr, s.data());
    if (!constant.empty())
      problem.SetManifold(s.data(), new ceres::SubsetManifold(n, constant));
    ceres::Solver::Options so =
        quiet_dense_options(budget, options.function_tolerance, options.gradient_tolerance,
                            options.parameter_tolerance);
    so.minimizer_type = ceres::TRUST_REGION;
    so.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
    so.update_state_every_iteration = true;
    so.callbacks.push_back(&callback);
    ceres::Solver::Summary cs;
    ceres::Solve(so, &problem, &cs);
    out.iterations += std::max(int(cs.iterations.size()) - 1, 0);
    if (!cs.IsSolutionUsable()) break;
    if (cs.final_cost < best) {
      best = cs.final_cost;
      best_s = s;
      std::copy(box.pin, box.pin + n, best_pin);
    }
    if (cs.termination_type == ceres::NO_CONVERGENCE) {
      out.limit = true;
      break;
    }
    // Unchanged: converged, or the round was ended by a parameter that
    // stays free (examined now: it no longer ends rounds).
    const int active = update(false);
    if (active < 0 || (active == 0 && cs.termination_type != ceres::USER_SUCCESS)) break;
  }
  if (std::isfinite(best)) {
    std::copy(best_pin, best_pin + n, box.pin);
    for (int i = 0; i < n; ++i) x[size_t(i)] = box.to_x(i, best_s[size_t(i)]);
  }
  return out;
}

// Cost 1/2 |r|^2 at params (double), with its terms. Not ok: the blend's
// degeneracy at a node, or numerical_overflow where valid but huge weights,
// clearance or min_speed overflow the objective (it said dependent_planes
// for those: fuzz_blend regress-optimize-huge-clearance).
Status cost_at(const Problem& P, const std::vector<double>& params, double& cost, Terms& terms) {
  std::vector<double> r(size_t(P.residuals()));
  terms = Terms{};
  Status why = Status::ok;
  if (!evaluate(P, params.data(), r.data(), &terms, &why)) return why;
  cost = terms.fairness + terms.regularity + terms.targets + terms.obstacles;
  return std::isfinite(cost) ? Status::ok : Status::numerical_overflow;
}

bool finite_nonneg(double x) { return std::isfinite(x) && x >= 0; }

Status check_inputs(BlendKind kind, int K, const BlendObjective& O, const BlendOptions& B) {
  if (kind != BlendKind::canal && kind != BlendKind::ringed) return Status::invalid_argument;
  if (K < (kind == BlendKind::canal ? 2 : 1)) return Status::invalid_argument;
  if (K > kMaxBlendOrder) return Status::degree_too_high;
  const double nums[] = {O.fairness, O.regularity, O.min_determinant, O.min_speed,
                         O.target_weight, O.clearance, O.obstacle_weight,
                         B.lambda_min_ratio, B.lambda_max_ratio, B.higher_bound,
                         B.circle_parameter_range, B.function_tolerance, B.gradient_tolerance, B.parameter_tolerance};
  for (double x : nums)
    if (!std::isfinite(x)) return Status::not_finite;
  for (double x : nums)
    if (!finite_nonneg(x)) return Status::invalid_argument;
  if (!(O.min_determinant > 0 && O.min_determinant < 1) || !(O.min_speed > 0))
    return Status::invalid_argument;
  if (O.quadrature_t < 1 || O.quadrature_t > kMaxQuadrature || O.quadrature_v < 1 ||
      O.quadrature_v > kMaxQuadrature)
    return Status::invalid_argument;
  if (O.target_count < 0 || O.obstacle_count < 0) return Status::invalid_argument;
  if ((O.target_count > 0 && !O.targets) || (O.obstacle_count > 0 && !O.obstacles))
    return Status::null_argument;
  for (int q = 0; q < O.target_count; ++q)
    if (!input_ok(O.targets[q].point) || !input_ok(O.targets[q].t)) return Status::not_finite;
  for (int q = 0; q < O.obstacle_count; ++q) {
    if (!input_ok(O.obstacles[q].center) || !input_ok(O.obstacles[q].radius))
      return Status::not_finite;
    if (!(O.obstacles[q].radius >= 0)) return Status::invalid_argument;
  }
  if (!(B.lambda_min_ratio > 0) || !(B.lambda_min_ratio <= 1) || !(B.lambda_max_ratio >= 1))
    return Status::invalid_argument;
  if (B.free_orders < 0 || B.free_orders > K || B.max_iterations < 0)
    return Status::invalid_argument;
  return Status::ok;
}

// The blend for the jets (lambda, phi[]) of both ends and (v non-null)
// the chosen points' circle parameters v[end][j].
Status build(BlendKind kind, BlendEnd s, BlendEnd e, const double (&jet)[2][kMaxBlendOrder],
             int K, double t0, double t1, Surface& out, double* bad, BlendEnd* so, BlendEnd* eo,
             const double (*v)[3] = nullptr) {
  BlendEnd* ends[2] = {&s, &e};
  for (int i = 0; i < 2; ++i) {
    ends[i]->lambda = jet[i][0];
    for (int m = 2; m <= K; ++m) ends[i]->phi[m - 2] = jet[i][m - 1];
    if (v)
      for (int j = 0; j < 3; ++j) ends[i]->v[j] = v[i][j];
  }
  const Status st = kind == BlendKind::canal ? make_canal_blend(s, e, K, t0, t1, out, bad)
                                             : make_ringed_blend(s, e, K, t0, t1, out, bad);
  if (st == Status::ok) {
    if (so) *so = s;
    if (eo) *eo = e;
  }
  return st;
}

// L: the size of the two end circles and their distance.
double length_scale(const BlendEnd& s, const BlendEnd& e) {
  Vec3d c[2], n;
  double r2[2] = {0, 0};
  const BlendEnd* ends[2] = {&s, &e};
  for (int i = 0; i < 2; ++i)
    if (ends[i]->surface->circle(ends[i]->u, c[i], n, r2[i]) != Status::ok) return 1.0;
  const double L = (c[0] - c[1]).norm() + std::sqrt(std::max(0.0, r2[0])) +
                   std::sqrt(std::max(0.0, r2[1]));
  return L > 0 && std::isfinite(L) ? L : 1.0;
}

// The Hermite basis series at t: slot (e, l) is the curve with unit data
// there (x component), zero elsewhere.
Status basis_at(int K, const RationalCurve* unit, double t, Basis* out) {
  for (int q = 0; q < 2 * (K + 1); ++q) out[q] = unit[q].taylor<kOrder>(t)[0];
  for (int q = 0; q < 2 * (K + 1); ++q)
    for (int k = 0; k <= kOrder; ++k)
      if (!std::isfinite(out[q].c[k])) return Status::numerical_overflow;
  return Status::ok;
}

// The start: the given jets, else the lambdas scaled by 1/2, 2, 1/4, 4
// (within the bounds): the first that builds a valid blend, in jet / S0.
Status start_jets(BlendKind kind, const BlendEnd& start, const BlendEnd& end, int K, double t0,
                  double t1, const BlendOptions& options, double (&jet0)[2][kMaxBlendOrder],
                  double (&jet)[2][kMaxBlendOrder], Surface& S0, double* bad_t) {
  for (auto& row : jet0)
    for (double& x : row) x = 0;
  blend_jet(start, 0, K, jet0[0]);
  blend_jet(end, 1, K, jet0[1]);
  for (int e = 0; e < 2; ++e)
    for (int m = 0; m < K; ++m)
      if (!input_ok(jet0[e][m])) return Status::not_finite;
  if (jet0[0][0] == 0 || jet0[1][0] == 0) return Status::invalid_argument;
  Status first = Status::ok;
  for (double f : {1.0, 0.5, 2.0, 0.25, 4.0}) {
    if (f < options.lambda_min_ratio || f > options.lambda_max_ratio) continue;
    std::copy(&jet0[0][0], &jet0[0][0] + 2 * kMaxBlendOrder, &jet[0][0]);
    jet[0][0] *= f;
    jet[1][0] *= f;
    // A denormal lambda scaled to 0 would build the default +-1 blend
    // (fuzz_blend regress-optimize-denormal-lambda).
    if (jet[0][0] == 0 || jet[1][0] == 0) continue;
    double bad = 0;
    const Status st = build(kind, start, end, jet, K, t0, t1, S0, &bad, nullptr, nullptr);
    if (st == Status::ok) return Status::ok;
    if (f == 1.0) {
      first = st;
      if (bad_t) *bad_t = bad;
    }
    // Inputs that are invalid as such do not improve with other lambdas.
    if (st != Status::dependent_planes && st != Status::collinear_points &&
        st != Status::zero_tangent && st != Status::singular_point &&
        st != Status::degenerate_circle_parameter)
      return st;
  }
  return first;
}

// The angle theta = 2 atan v in [-pi, pi] of a circle parameter (v =
// +-infinity, the generator: +-pi).
double angle_of(double v) { return 2.0 * std::atan(v); }

// The circle parameter of the angle theta, exactly the start's v where
// theta did not move (so a generator point v = infinity stays one).
double parameter_of_angle(double theta, double theta0, double v0) {
  return theta == theta0 ? v0 : std::tan(0.5 * theta);
}

// The angular distance of theta and phi on the circle of angles (period
// 2 pi), in [0, pi].
double angle_distance(double theta, double phi) {
  const double two_pi = 2.0 * std::acos(-1.0);
  const double d = std::fmod(std::abs(theta - phi), two_pi);
  return std::min(d, two_pi - d);
}

// The boxes of the chosen points' angles (SPEC §8e): theta_0 +- h with h =
// min(circle_parameter_range, 0.45 x the angular distance to the end's
// nearest other point), so the points stay distinct and keep their order
// on the circle (v -> x is a bijection of the projective line onto the
// circle where the surface is regular).
void point_parameters(const BlendEnd* const (&ends)[2], int count, double range,
                      FreeParameters& out) {
  for (int e = 0; e < 2; ++e)
    for (int j = 0; j < count; ++j) {
      const double theta = angle_of(ends[e]->v[j]);
      double h = range;
      for (int k = 0; k < count; ++k)
        if (k != j) h = std::min(h, 0.45 * angle_distance(theta, angle_of(ends[e]->v[k])));
      FreeParameter q;
      q.role = ParameterRole::circle_point;
      q.index = e;
      q.order = j;
      q.lower = theta - h;
      q.upper = theta + h;
      q.start = q.value = theta;
      out.add(q);
    }
}

// The boxes of the jets (SPEC §8e): |phi'| in [min, max] |lambda_0| with
// lambda_0's sign, |phi^(m)| <= higher_bound |lambda_0|; starts clamped in.
// lambda = 0 means the default +-1: the bounds keep it out (min_ratio
// |lambda_0| underflows to 0 for a denormal lambda_0). Then the points'
// angles if circle_parameter_range > 0.
void blend_parameters(const double (&jet0)[2][kMaxBlendOrder],
                      const double (&jet)[2][kMaxBlendOrder], int free,
                      const BlendEnd* const (&ends)[2], int count, const BlendOptions& options,
                      FreeParameters& out) {
  constexpr double tiny = std::numeric_limits<double>::denorm_min();
  out = FreeParameters();
  for (int e = 0; e < 2; ++e) {
    const double l0 = jet0[e][0], a = std::abs(l0);
    for (int m = 0; m < free; ++m) {
      FreeParameter q;
      q.role = ParameterRole::jet;
      q.index = e;
      q.order = m + 1;
      if (m == 0) {
        q.lower = l0 > 0 ? std::max(options.lambda_min_ratio * a, tiny)
                         : -options.lambda_max_ratio * a;
        q.upper = l0 > 0 ? options.lambda_max_ratio * a
                         : std::min(-options.lambda_min_ratio * a, -tiny);
      } else {
        q.lower = -options.higher_bound * a;
        q.upper = options.higher_bound * a;
      }
      q.start = q.value = std::min(std::max(jet[e][m], q.lower), q.upper);
      out.add(q);
    }
  }
  if (options.circle_parameter_range > 0)
    point_parameters(ends, count, options.circle_parameter_range, out);
}

// The frame of an end circle as u-series of order K, stored at order
// kMaxBlendOrder (the coefficients above K zero).
template <int N>
Status end_frame_order(const Surface& S, double u,
                       CircleFrame<Taylor<double, kMaxBlendOrder>>& out) {
  CircleFrame<Taylor<double, N>> F;
  if (Status st = S.frame<N>(u, F); st != Status::ok) return st;
  auto widen = [](const Taylor<double, N>& a) {
    Taylor<double, kMaxBlendOrder> r;
    for (int k = 0; k <= N; ++k) r.c[k] = a.c[k];
    return r;
  };
  for (int j = 0; j < 3; ++j) {
    out.o[j] = widen(F.o[j]);
    out.a[j] = widen(F.a[j]);
    out.p[j] = widen(F.p[j]);
  }
  out.alpha = widen(F.alpha);
  out.beta = widen(F.beta);
  out.gamma = widen(F.gamma);
  out.delta = widen(F.delta);
  return Status::ok;
}

Status end_frame(const Surface& S, double u, int K,
                 CircleFrame<Taylor<double, kMaxBlendOrder>>& out) {
  return with_clamped_order(K, [&](auto n) -> Status {
    return end_frame_order<series_order<decltype(n)::value, kMaxBlendOrder>>(S, u, out);
  });
}

// The ends' jets and circle parameters for the unknowns x: the jets' free
// orders from x, the rest from jet; the points' v from their angles (the
// start's v where an angle did not move).
void unknowns_to_ends(const Problem& P, const double (&jet)[2][kMaxBlendOrder],
                      const BlendEnd* const (&ends)[2], const FreeParameters& params,
                      const std::vector<double>& x, double (&jets)[2][kMaxBlendOrder],
                      double (&v)[2][3]) {
  std::copy(&jet[0][0], &jet[0][0] + 2 * kMaxBlendOrder, &jets[0][0]);
  for (int e = 0; e < 2; ++e) {
    for (int m = 0; m < P.free; ++m) jets[e][m] = x[size_t(P.jet_index(e, m))];
    for (int j = 0; j < 3; ++j) v[e][j] = ends[e]->v[j];
    if (!P.free_points) continue;
    for (int j = 0; j < P.count; ++j) {
      const int i = P.point_index(e, j);
      v[e][j] = parameter_of_angle(x[size_t(i)], params.p[i].start, ends[e]->v[j]);
    }
  }
}

int free_orders(int K, const BlendOptions& options) {
  return options.free_orders > 0 ? options.free_orders : std::min(K, 2);
}

}  // namespace

Status optimize_blend(BlendKind kind, const BlendEnd& start, const BlendEnd& end, int K,
                      double t0, double t1, const BlendObjective& objective,
                      const BlendOptions& options, Surface& out, BlendEnd* start_out,
                      BlendEnd* end_out, BlendSummary& summary, double* bad_t) {
  const auto clock0 = std::chrono::steady_clock::now();
  if (!start.surface || !end.surface) return Status::null_argument;
  if (Status st = check_inputs(kind, K, objective, options); st != Status::ok) return st;

  double jet0[2][kMaxBlendOrder], jet[2][kMaxBlendOrder];
  Surface S0;
  if (Status st = start_jets(kind, start, end, K, t0, t1, options, jet0, jet, S0, bad_t);
      st != Status::ok)
    return st;

  // The problem.
  Problem P;
  P.kind = kind;
  P.K = K;
  P.count = kind == BlendKind::canal ? 2 : 3;
  P.free = free_orders(K, options);
  P.t0 = t0;
  P.t1 = t1;
  std::copy(&jet[0][0], &jet[0][0] + 2 * kMaxBlendOrder, &P.jet0[0][0]);
  P.free_points = options.circle_parameter_range > 0;
  const BlendEnd* const ends[2] = {&start, &end};
  for (int e = 0; e < 2; ++e) {
    for (int j = 0; j < P.count; ++j)
      if (Status st = derivatives_u(*ends[e]->surface, ends[e]->u, ends[e]->v[j], K, P.D[e][j]);
          st != Status::ok)
        return st;
    if (P.free_points)
      if (Status st = end_frame(*ends[e]->surface, ends[e]->u, K, P.frame[e]); st != Status::ok)
        return st;
  }
  P.obj = objective;
  P.targets.assign(objective.targets, objective.targets + objective.target_count);
  P.obstacles.assign(objective.obstacles, objective.obstacles + objective.obstacle_count);
  P.L = length_scale(start, end);
  P.nt = objective.quadrature_t;
  P.nz = objective.quadrature_v;
  double tn[kMaxQuadrature];
  gauss_legendre(P.nt, tn, P.tw);
  gauss_legendre(P.nz, P.zn, P.zw);
  // The Hermite basis: curves with unit data in one slot.
  RationalCurve unit[2 * (kMaxBlendOrder + 1)];
  for (int e = 0; e < 2; ++e)
    for (int l = 0; l <= K; ++l) {
      Vec3d a[kMaxBlendOrder + 1], b[kMaxBlendOrder + 1];
      for (int q = 0; q <= K; ++q) a[q] = b[q] = Vec3d::Zero();
      (e == 0 ? a : b)[l] = Vec3d(1, 0, 0);
      if (Status st = make_hermite_curve(K, t0, t1, a, b, unit[e * (K + 1) + l]);
          st != Status::ok)
        return st;
    }
  P.B.resize(size_t(P.nt) * P.slots());
  for (int i = 0; i < P.nt; ++i) {
    const double t = 0.5 * (t0 + t1) + 0.5 * (t1 - t0) * tn[i];
    if (Status st = basis_at(K, unit, t, &P.B[size_t(i) * P.slots()]); st != Status::ok)
      return st;
  }
  P.TB.resize(P.targets.size() * P.slots());
  for (size_t q = 0; q < P.targets.size(); ++q)
    if (Status st = basis_at(K, unit, P.targets[q].t, &P.TB[q * P.slots()]);
        st != Status::ok)
      return st;

  // Bounds, the start point (clamped into them) and the fairness
  // normalizer: the start blend's fairness integral F0, so that the
  // fairness term is weight * F / F0 / 2 (1/2 the weight at the start).
  FreeParameters params;
  blend_parameters(jet0, jet, P.free, ends, P.count, options, params);
  std::vector<double> x(size_t(params.count)), lo(x.size()), hi(x.size());
  for (int i = 0; i < params.count; ++i) {
    lo[size_t(i)] = params.p[i].lower;
    hi[size_t(i)] = params.p[i].upper;
    x[size_t(i)] = params.p[i].start;
  }
  Terms terms0;
  double cost0 = 0;
  P.obj.fairness = 1.0;
  if (Status st = cost_at(P, x, cost0, terms0); st != Status::ok) return st;
  const double F0 = 2 * terms0.fairness;
  P.fair_norm = F0 > 0 ? 1.0 / std::sqrt(F0) : 1.0;
  P.obj.fairness = objective.fairness;
  if (Status st = cost_at(P, x, cost0, terms0); st != Status::ok) return st;
  const std::vector<double> x_start = x;

  // Solve: Ceres' Levenberg-Marquardt on the unconstrained solver
  // variables s of the box with an active set of parameters held at their
  // bounds (solve_box), then x of s.
  Box box(lo, hi, x);
  Solved solved;
  if (options.max_iterations > 0) solved = solve_box(P, box, options, x);

  // The result: the optimum if it is a valid blend no worse than the start.
  BlendSummary R;
  R.initial_cost = cost0;
  R.iterations = solved.iterations;
  R.termination = solved.limit ? BlendTermination::iteration_limit : BlendTermination::converged;
  R.length_scale = P.L;
  R.fairness_scale = F0;
  double cost1 = 0;
  Terms terms1;
  bool use = cost_at(P, x, cost1, terms1) == Status::ok && cost1 <= cost0;
  Surface S1;
  BlendEnd s1, e1;
  if (use) {
    double jet1[2][kMaxBlendOrder], v1[2][3];
    unknowns_to_ends(P, jet, ends, params, x, jet1, v1);
    use = build(kind, start, end, jet1, K, t0, t1, S1, nullptr, &s1, &e1, v1) == Status::ok;
  }
  if (!use) {
    double jets[2][kMaxBlendOrder], v[2][3];
    unknowns_to_ends(P, jet, ends, params, x_start, jets, v);
    if (Status st = build(kind, start, end, jets, K, t0, t1, S1, bad_t, &s1, &e1, v);
        st != Status::ok)
      return st;
    cost1 = cost0;
    terms1 = terms0;
    R.termination = BlendTermination::reverted;
  }
  R.final_cost = cost1;
  R.parameters = params;
  const std::vector<double>& chosen = R.termination == BlendTermination::reverted ? x_start : x;
  for (int i = 0; i < params.count; ++i) R.parameters.p[i].value = chosen[size_t(i)];
  R.fairness = terms1.fairness;
  R.regularity = terms1.regularity;
  R.targets = terms1.targets;
  R.obstacles = terms1.obstacles;
  R.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock0).count();
  out = S1;
  if (start_out) *start_out = s1;
  if (end_out) *end_out = e1;
  summary = R;
  return Status::ok;
}

Status describe_blend_parameters(BlendKind kind, const BlendEnd& start, const BlendEnd& end,
                                 int K, double t0, double t1, const BlendOptions& options,
                                 FreeParameters& out, double* bad_t) {
  if (!start.surface || !end.surface) return Status::null_argument;
  if (Status st = check_inputs(kind, K, BlendObjective(), options); st != Status::ok) return st;
  double jet0[2][kMaxBlendOrder], jet[2][kMaxBlendOrder];
  Surface S0;
  if (Status st = start_jets(kind, start, end, K, t0, t1, options, jet0, jet, S0, bad_t);
      st != Status::ok)
    return st;
  const BlendEnd* const ends[2] = {&start, &end};
  blend_parameters(jet0, jet, free_orders(K, options), ends, kind == BlendKind::canal ? 2 : 3,
                   options, out);
  return Status::ok;
}

}  // namespace optim
}  // namespace v0
}  // namespace cyclide
