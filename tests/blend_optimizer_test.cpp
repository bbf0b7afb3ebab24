// The blend optimizer (labels "optim;blend"; SPEC.md §8e): on the Fig. 6
// cones and a canal pair, the optimized blend is never worse than the
// defaults, keeps its bounds, still joins G^K (continuity report with the
// returned jets), clears a spherical obstacle the default blend runs
// through, and passes a target circle point; bad objectives and options
// give their statuses. Plus a RapidCheck property over random pairs.

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "optim/blend_optimizer.hpp"

using namespace cyclide;
using namespace cyclide::optim;

namespace {

const double kPi = std::acos(-1.0);

Surface cone(const Vec3d& A, const Vec3d& e1, const Vec3d& e2, const Vec3d& e3) {
  RationalCurve L[3];
  for (int k = 0; k < 3; ++k) {
    const double t = 2 * kPi * k / 3 + 0.3;
    EXPECT_EQ(make_line(A, std::cos(t) * e1 + std::sin(t) * e2 + e3, L[k]), Status::ok);
  }
  Surface S;
  EXPECT_EQ(make_prrs(L[0], L[1], L[2], nullptr, 0.5, 1.0, S), Status::ok);
  return S;
}
Surface cone1() { return cone({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}); }
Surface cone2() { return cone({4, 0, 4}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}); }

struct Ends {
  BlendEnd s, e;
};
Ends fig6_ends(const Surface& A, const Surface& B, int count) {
  Ends E;
  E.s.surface = &A;
  E.s.u = 1.0;
  E.e.surface = &B;
  E.e.u = 1.0;
  const double vs[3] = {HUGE_VAL, -0.5, 0.7};
  for (int j = 0; j < count; ++j) E.s.v[j] = E.e.v[j] = vs[j];
  if (count == 2) E.s.v[1] = E.e.v[1] = 0.3;
  return E;
}

// The join of the blend X with the input at t: gap and circle jumps to
// `top` with the end's jet.
void expect_join(const BlendEnd& in, int index, const Surface& X, double t, int K, int top) {
  double jet[kMaxBlendOrder];
  blend_jet(in, index, K, jet);
  ContinuityReport R;
  ASSERT_EQ(continuity_report(*in.surface, in.u, jet, X, t, K, nullptr, 32, R), Status::ok);
  EXPECT_LE(R.max_gap, 1e-10 * R.point_scale);
  EXPECT_LE(R.max_normal_angle, 1e-8);
  for (int l = 0; l <= top; ++l) EXPECT_LE(R.circle_jump[l], 1e-8) << "order " << l;
}

// The closest approach of X's points to c over a grid.
double min_distance(const Surface& X, const Vec3d& c) {
  double best = HUGE_VAL;
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j < 48; ++j) {
      double x[3];
      const double v = std::tan(kPi * (j + 0.5) / 48 - kPi / 2);
      if (X.eval(i / 40.0, v, {x, nullptr, nullptr, nullptr}) != Status::ok) continue;
      best = std::min(best, (Vec3d(x[0], x[1], x[2]) - c).norm());
    }
  return best;
}

}  // namespace

TEST(BlendOptimizer, RingedFig6FairerAndStillCK) {
  const Surface A = cone1(), B = cone2();
  for (int K = 1; K <= 2; ++K) {
    Ends E = fig6_ends(A, B, 3);
    Surface X;
    BlendEnd so, eo;
    BlendSummary sum;
    ASSERT_EQ(optimize_blend(BlendKind::ringed, E.s, E.e, K, 0.0, 1.0, BlendObjective{},
                             BlendOptions{}, X, &so, &eo, sum),
              Status::ok);
    EXPECT_LE(sum.final_cost, sum.initial_cost);
    EXPECT_NE(sum.termination, BlendTermination::reverted);
    EXPECT_GT(sum.iterations, 0);
    EXPECT_GT(sum.fairness_scale, 0);
    // Defaults: lambda_0 = +1 (start), -1 (end); bounds [1/4, 4] |lambda_0|.
    EXPECT_GE(so.lambda, 0.25);
    EXPECT_LE(so.lambda, 4.0);
    EXPECT_LE(eo.lambda, -0.25);
    EXPECT_GE(eo.lambda, -4.0);
    expect_join(so, 0, X, 0.0, K, K);
    expect_join(eo, 1, X, 1.0, K, K);
  }
}

// Issue 4's common description of free parameters: describe_blend_parameters
// lists what optimize_blend solves for (K = 2: phi', phi'' per end), with
// boxes around the start, and the summary reports the chosen values — the
// jets written to the chosen ends, inside their boxes.
TEST(BlendOptimizer, FreeParametersDescribedAndReported) {
  const Surface A = cone1(), B = cone2();
  Ends E = fig6_ends(A, B, 3);
  FreeParameters D;
  ASSERT_EQ(describe_blend_parameters(BlendKind::ringed, E.s, E.e, 2, 0.0, 1.0, BlendOptions{}, D),
            Status::ok);
  ASSERT_EQ(D.count, 4);
  for (int i = 0; i < D.count; ++i) {
    const FreeParameter& q = D.p[i];
    EXPECT_EQ(q.role, ParameterRole::jet);
    EXPECT_EQ(q.index, i / 2);
    EXPECT_EQ(q.order, i % 2 + 1);
    EXPECT_LE(q.lower, q.start);
    EXPECT_LE(q.start, q.upper);
    EXPECT_LT(q.lower, q.upper);
  }
  EXPECT_EQ(D.p[0].lower, 0.25);  // lambda_0 = +1 at the start, -1 at the end
  EXPECT_EQ(D.p[0].upper, 4.0);
  EXPECT_EQ(D.p[2].lower, -4.0);
  EXPECT_EQ(D.p[2].upper, -0.25);
  EXPECT_EQ(D.p[1].lower, -4.0);
  Surface X;
  BlendEnd so, eo;
  BlendSummary sum;
  ASSERT_EQ(optimize_blend(BlendKind::ringed, E.s, E.e, 2, 0.0, 1.0, BlendObjective{},
                           BlendOptions{}, X, &so, &eo, sum),
            Status::ok);
  ASSERT_EQ(sum.parameters.count, 4);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(sum.parameters.p[i].lower, D.p[i].lower);
    EXPECT_EQ(sum.parameters.p[i].upper, D.p[i].upper);
    EXPECT_EQ(sum.parameters.p[i].start, D.p[i].start);
    EXPECT_GE(sum.parameters.p[i].value, D.p[i].lower);
    EXPECT_LE(sum.parameters.p[i].value, D.p[i].upper);
  }
  EXPECT_EQ(sum.parameters.p[0].value, so.lambda);
  EXPECT_EQ(sum.parameters.p[1].value, so.phi[0]);
  EXPECT_EQ(sum.parameters.p[2].value, eo.lambda);
  EXPECT_EQ(sum.parameters.p[3].value, eo.phi[0]);
  // Validation as optimize_blend's.
  BlendOptions bad;
  bad.lambda_min_ratio = 2;
  EXPECT_EQ(describe_blend_parameters(BlendKind::ringed, E.s, E.e, 2, 0.0, 1.0, bad, D),
            Status::invalid_argument);
}

TEST(BlendOptimizer, CanalK2NeverWorseAndG1) {
  const Surface A = cone1(), B = cone2();
  Ends E = fig6_ends(A, B, 2);
  Surface X;
  BlendEnd so, eo;
  BlendSummary sum;
  ASSERT_EQ(optimize_blend(BlendKind::canal, E.s, E.e, 2, 0.0, 1.0, BlendObjective{},
                           BlendOptions{}, X, &so, &eo, sum),
            Status::ok);
  EXPECT_LE(sum.final_cost, sum.initial_cost);
  expect_join(so, 0, X, 0.0, 2, 0);
  expect_join(eo, 1, X, 1.0, 2, 0);
}

// The Fig. 6 optima lie on bounds (SPEC §8e: the sin map's derivative
// vanishes there; alone it crawled into the iteration limit of 50): the
// active set pins them exactly and the solves converge before the limit, at
// costs no higher than the crawl reached (0.3597, 0.2574, 0.00930).
TEST(BlendOptimizer, Fig6BoundOptimaPinnedBeforeTheLimit) {
  const Surface A = cone1(), B = cone2();
  struct Case {
    BlendKind kind;
    int K, count;
    double cost;
  } const cases[] = {{BlendKind::ringed, 1, 3, 0.3597},
                     {BlendKind::ringed, 2, 3, 0.2574},
                     {BlendKind::canal, 2, 2, 0.00930}};
  for (const Case& c : cases) {
    Ends E = fig6_ends(A, B, c.count);
    Surface X;
    BlendEnd so, eo;
    BlendSummary sum;
    ASSERT_EQ(optimize_blend(c.kind, E.s, E.e, c.K, 0.0, 1.0, BlendObjective{}, BlendOptions{},
                             X, &so, &eo, sum),
              Status::ok);
    EXPECT_EQ(sum.termination, BlendTermination::converged) << "K " << c.K;
    EXPECT_LT(sum.iterations, 50) << "K " << c.K;
    EXPECT_LE(sum.final_cost, c.cost) << "K " << c.K;
    if (c.kind == BlendKind::ringed) EXPECT_EQ(eo.lambda, -0.25);  // on |lambda| >= 1/4
    if (c.K == 2) EXPECT_EQ(std::abs(eo.phi[0]), 4.0);              // on |phi''| <= 4
  }
}

// A start on a bound (phi'' of the start = -4 |lambda_0|): the map alone has
// a vanishing derivative there; the active set moves it in or pins it.
TEST(BlendOptimizer, StartOnABound) {
  const Surface A = cone1(), B = cone2();
  for (double phi : {-4.0, 4.0}) {
    Ends E = fig6_ends(A, B, 3);
    E.s.phi[0] = phi;
    Surface X;
    BlendEnd so, eo;
    BlendSummary sum;
    ASSERT_EQ(optimize_blend(BlendKind::ringed, E.s, E.e, 2, 0.0, 1.0, BlendObjective{},
                             BlendOptions{}, X, &so, &eo, sum),
              Status::ok);
    EXPECT_LT(sum.final_cost, sum.initial_cost);
    EXPECT_EQ(sum.termination, BlendTermination::converged) << phi;
    EXPECT_GE(so.phi[0], -4.0);
    EXPECT_LE(so.phi[0], 4.0);
    if (phi < 0) EXPECT_GT(so.phi[0], -4.0);  // it left the bound it started on
    expect_join(so, 0, X, 0.0, 2, 2);
    expect_join(eo, 1, X, 1.0, 2, 2);
  }
}

// An obstacle on the default blend: the optimizer moves the blend away
// (the obstacle term drops, the closest approach grows).
TEST(BlendOptimizer, ClearsASphericalObstacle) {
  const Surface A = cone1(), B = cone2();
  Ends E = fig6_ends(A, B, 3);
  const int K = 2;
  Surface X0;
  ASSERT_EQ(make_ringed_blend(E.s, E.e, K, 0.0, 1.0, X0), Status::ok);
  double x[3];
  ASSERT_EQ(X0.eval(0.5, 1.0, {x, nullptr, nullptr, nullptr}), Status::ok);
  SphereObstacle ob;
  ob.center = Vec3d(x[0], x[1], x[2]);
  ob.radius = 0.3;
  BlendObjective obj;
  obj.obstacles = &ob;
  obj.obstacle_count = 1;
  obj.obstacle_weight = 100.0;
  obj.fairness = 0.01;
  obj.quadrature_t = 12;
  obj.quadrature_v = 8;
  Surface X;
  BlendEnd so, eo;
  BlendSummary sum;
  ASSERT_EQ(optimize_blend(BlendKind::ringed, E.s, E.e, K, 0.0, 1.0, obj, BlendOptions{}, X, &so,
                           &eo, sum),
            Status::ok);
  EXPECT_LT(sum.final_cost, sum.initial_cost);
  // The blend runs through the obstacle's center before, and at most
  // grazes the sphere after (the penetration depth drops fourfold).
  const double d0 = min_distance(X0, ob.center), d1 = min_distance(X, ob.center);
  EXPECT_LT(d0, 0.1);
  EXPECT_LT(ob.radius - d1, 0.25 * (ob.radius - d0))
      << "closest approach " << d0 << " -> " << d1 << ", cost " << sum.initial_cost << " -> "
      << sum.final_cost << " (obstacles " << sum.obstacles << ")";
  expect_join(so, 0, X, 0.0, K, K);
  expect_join(eo, 1, X, 1.0, K, K);
}

// A target: the circle at t = 0.5 should pass through a point off the
// default blend; the optimum's circle is much closer.
TEST(BlendOptimizer, PassesNearATargetPoint) {
  const Surface A = cone1(), B = cone2();
  Ends E = fig6_ends(A, B, 3);
  Surface X0;
  ASSERT_EQ(make_ringed_blend(E.s, E.e, 2, 0.0, 1.0, X0), Status::ok);
  Vec3d c, n;
  double r2;
  ASSERT_EQ(X0.circle(0.5, c, n, r2), Status::ok);
  TargetPoint tp;
  tp.t = 0.5;
  tp.point = c + (std::sqrt(r2) + 0.4) * n.unitOrthogonal();  // 0.4 outside the circle
  BlendObjective obj;
  obj.targets = &tp;
  obj.target_count = 1;
  obj.target_weight = 100.0;
  obj.fairness = 0.01;
  auto distance = [&](const Surface& S) {
    Vec3d cc, nn;
    double rr;
    EXPECT_EQ(S.circle(0.5, cc, nn, rr), Status::ok);
    const Vec3d w = tp.point - cc;
    const double h = w.dot(nn.normalized());
    return std::hypot(h, (w - h * nn.normalized()).norm() - std::sqrt(rr));
  };
  Surface X;
  BlendSummary sum;
  ASSERT_EQ(optimize_blend(BlendKind::ringed, E.s, E.e, 2, 0.0, 1.0, obj, BlendOptions{}, X,
                           nullptr, nullptr, sum),
            Status::ok);
  EXPECT_LT(distance(X), 0.5 * distance(X0)) << distance(X0) << " -> " << distance(X);
  EXPECT_LT(sum.targets, 0.25 * (sum.initial_cost));
}

TEST(BlendOptimizer, Validation) {
  const Surface A = cone1(), B = cone2();
  Ends E = fig6_ends(A, B, 3);
  Surface X;
  BlendSummary sum;
  auto run = [&](BlendKind kind, int K, const BlendObjective& o, const BlendOptions& p) {
    return optimize_blend(kind, E.s, E.e, K, 0.0, 1.0, o, p, X, nullptr, nullptr, sum);
  };
  const BlendObjective O;
  const BlendOptions P;
  EXPECT_EQ(run(BlendKind::canal, 1, O, P), Status::invalid_argument);
  EXPECT_EQ(run(BlendKind::ringed, 0, O, P), Status::invalid_argument);
  EXPECT_EQ(run(BlendKind::ringed, kMaxBlendOrder + 1, O, P), Status::degree_too_high);
  EXPECT_EQ(run(BlendKind(7), 1, O, P), Status::invalid_argument);
  BlendObjective o = O;
  o.fairness = -1;
  EXPECT_EQ(run(BlendKind::ringed, 1, o, P), Status::invalid_argument);
  o = O;
  o.regularity = NAN;
  EXPECT_EQ(run(BlendKind::ringed, 1, o, P), Status::not_finite);
  o = O;
  o.quadrature_t = 0;
  EXPECT_EQ(run(BlendKind::ringed, 1, o, P), Status::invalid_argument);
  o = O;
  o.quadrature_v = kMaxQuadrature + 1;
  EXPECT_EQ(run(BlendKind::ringed, 1, o, P), Status::invalid_argument);
  o = O;
  o.target_count = 2;
  EXPECT_EQ(run(BlendKind::ringed, 1, o, P), Status::null_argument);
  o = O;
  SphereObstacle bad;
  bad.radius = -1;
  o.obstacles = &bad;
  o.obstacle_count = 1;
  EXPECT_EQ(run(BlendKind::ringed, 1, o, P), Status::invalid_argument);
  BlendOptions p = P;
  p.lambda_min_ratio = 2;
  EXPECT_EQ(run(BlendKind::ringed, 1, O, p), Status::invalid_argument);
  p = P;
  p.free_orders = 3;
  EXPECT_EQ(run(BlendKind::ringed, 2, O, p), Status::invalid_argument);
  p = P;
  p.max_iterations = 0;  // no iterations: the start itself
  ASSERT_EQ(run(BlendKind::ringed, 1, O, p), Status::ok);
  EXPECT_EQ(sum.final_cost, sum.initial_cost);
  BlendEnd none = E.s;
  none.surface = nullptr;
  EXPECT_EQ(optimize_blend(BlendKind::ringed, none, E.e, 1, 0.0, 1.0, O, P, X, nullptr, nullptr,
                           sum),
            Status::null_argument);
}

// Random pairs (PRRS of three random lines, the second moved apart): the
// optimizer returns a blend no worse than the defaults, within its bounds,
// joining both ends; or the defaults' degenerate status.
RC_GTEST_PROP(BlendOptimizerProperties, NeverWorseWithinBoundsAndJoined, ()) {
  auto dyadic = [] { return *rc::gen::inRange(-64, 65) / 32.0; };
  Surface S[2];
  for (int i = 0; i < 2; ++i) {
    RationalCurve L[3];
    for (int k = 0; k < 3; ++k) {
      const Vec3d d(dyadic(), dyadic(), dyadic());
      RC_PRE(d.norm() > 0.25);
      const Vec3d p = Vec3d(dyadic(), dyadic(), dyadic()) + (i ? Vec3d(6, 1, 0) : Vec3d::Zero());
      RC_PRE(make_line(p, d, L[k]) == Status::ok);
    }
    RC_PRE(make_prrs(L[0], L[1], L[2], nullptr, 0.0, 1.0, S[i]) == Status::ok);
  }
  BlendEnd s, e;
  s.surface = &S[0];
  s.u = 1.0;
  e.surface = &S[1];
  e.u = 0.0;
  const double vs[3] = {HUGE_VAL, -0.6, 0.8};
  for (int j = 0; j < 3; ++j) s.v[j] = e.v[j] = vs[j];
  const int K = *rc::gen::inRange(1, 3);
  BlendObjective obj;
  obj.quadrature_t = 6;
  obj.quadrature_v = 3;
  BlendOptions opt;
  opt.max_iterations = 15;
  Surface X;
  BlendEnd so, eo;
  BlendSummary sum;
  const Status st = optimize_blend(BlendKind::ringed, s, e, K, 0.0, 1.0, obj, opt, X, &so, &eo, sum);
  if (st != Status::ok) {
    RC_ASSERT(st == Status::dependent_planes || st == Status::collinear_points ||
              st == Status::numerical_overflow || st == Status::singular_point ||
              st == Status::degenerate_circle_parameter);
    RC_SUCCEED("degenerate defaults");
  }
  RC_ASSERT(sum.final_cost <= sum.initial_cost);
  RC_ASSERT(std::isfinite(sum.final_cost));
  const double l0[2] = {blend_lambda(s, 0), blend_lambda(e, 1)};
  const double l1[2] = {so.lambda, eo.lambda};
  for (int i = 0; i < 2; ++i) {
    RC_ASSERT(l1[i] * l0[i] > 0);
    RC_ASSERT(std::abs(l1[i]) >= 0.25 * std::abs(l0[i]) - 1e-12);
    RC_ASSERT(std::abs(l1[i]) <= 4.0 * std::abs(l0[i]) + 1e-12);
  }
  for (int i = 0; i < 2; ++i) {
    const BlendEnd& in = i ? eo : so;
    double jet[kMaxBlendOrder];
    blend_jet(in, i, K, jet);
    ContinuityReport R;
    RC_PRE(continuity_report(*in.surface, in.u, jet, X, double(i), K, nullptr, 16, R) ==
           Status::ok);
    RC_ASSERT(R.max_gap <= 1e-8 * R.point_scale);
  }
}
