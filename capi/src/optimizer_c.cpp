// The optimizer tier's C entry points. Built with or without Ceres; the
// symbol set is the same in every build (SPEC.md "Optimizer tier").
#include <cstdio>
#include <cstring>
#include <vector>

#include "capi_internal.hpp"
#include "lie_internal.hpp"

#ifndef CYCLIDE_HAVE_CERES
#define CYCLIDE_HAVE_CERES 0
#endif

#if CYCLIDE_HAVE_CERES
#include "optim/blend_optimizer.hpp"
#include "optim/bump_optimizer.hpp"
#include "optim/closest_point.hpp"
#include "optim/cyclide_blend_optimizer.hpp"
static_assert(CYC_PARAMETER_FAMILY == int(cyclide::optim::ParameterRole::family),
              "parameter roles");
#endif

using namespace cyclide;
using namespace cyclide::capi;

extern "C" {

int cyc_optimizer_available(void) { return CYCLIDE_HAVE_CERES; }

int cyc_optimize_closest_point(cyc_context* ctx, const cyc_surface* surface,
                               const double point[3], double* u, double* v,
                               double closest[3], double* distance) {
  const char* fn = "cyc_optimize_closest_point";
  return run(ctx, fn, [&]() -> Outcome {
    REQUIRE(surface);
    REQUIRE(point);
    REQUIRE(u);
    REQUIRE(v);
#if CYCLIDE_HAVE_CERES
    optim::ClosestPoint R;
    if (Status s = optim::closest_point(surface->surface, vec(point), R); s != Status::ok)
      return from_core(fn, s);
    *u = R.u;
    *v = R.v;
    if (closest) put3(closest, R.point);
    if (distance) *distance = R.distance;
    return ok();
#else
    (void)distance;
    (void)closest;
    return fail(CYC_E_UNSUPPORTED, "%s: this build has no optimizer tier (Ceres)", fn);
#endif
  });
}

void cyc_blend_objective_init(cyc_blend_objective* o) {
  if (!o) return;
  std::memset(o, 0, sizeof *o);
  o->fairness = 1.0;
  o->regularity = 1.0;
  o->min_determinant = 1e-2;
  o->min_speed = 1e-2;
  o->target_weight = 1.0;
  o->obstacle_weight = 1.0;
  o->quadrature_t = 8;
  o->quadrature_v = 4;
}

void cyc_optimize_options_init(cyc_optimize_options* p) {
  if (!p) return;
  std::memset(p, 0, sizeof *p);
  p->lambda_min_ratio = 0.25;
  p->lambda_max_ratio = 4.0;
  p->higher_bound = 4.0;
  p->max_iterations = 50;
  p->function_tolerance = 1e-8;
  p->gradient_tolerance = 1e-10;
  p->parameter_tolerance = 1e-8;
}

}  // extern "C"

namespace {

#if CYCLIDE_HAVE_CERES
optim::BlendOptions blend_options_of(const cyc_optimize_options* options) {
  cyc_optimize_options p;
  cyc_optimize_options_init(&p);
  if (options) p = *options;
  optim::BlendOptions P;
  P.free_orders = p.free_orders;
  P.lambda_min_ratio = p.lambda_min_ratio;
  P.lambda_max_ratio = p.lambda_max_ratio;
  P.higher_bound = p.higher_bound;
  P.circle_parameter_range = p.circle_parameter_range;
  P.max_iterations = p.max_iterations;
  P.function_tolerance = p.function_tolerance;
  P.gradient_tolerance = p.gradient_tolerance;
  P.parameter_tolerance = p.parameter_tolerance;
  return P;
}

optim::BumpOptions bump_options_of(const cyc_bump_options* options) {
  cyc_bump_options p;
  cyc_bump_options_init(&p);
  if (options) p = *options;
  optim::BumpOptions P;
  P.w_bound = p.w_bound;
  P.tau_min = p.tau_min;
  P.tau_max = p.tau_max;
  P.free_tau = p.free_tau != 0;
  P.max_iterations = p.max_iterations;
  P.function_tolerance = p.function_tolerance;
  P.gradient_tolerance = p.gradient_tolerance;
  P.parameter_tolerance = p.parameter_tolerance;
  return P;
}

cyc_optimize_summary summary_of(const optim::BlendSummary& R) {
  cyc_optimize_summary m;
  std::memset(&m, 0, sizeof m);
  m.initial_cost = R.initial_cost;
  m.final_cost = R.final_cost;
  m.iterations = R.iterations;
  m.seconds = R.seconds;
  m.termination = int(R.termination);
  m.fairness = R.fairness;
  m.regularity = R.regularity;
  m.targets = R.targets;
  m.obstacles = R.obstacles;
  m.length_scale = R.length_scale;
  m.fairness_scale = R.fairness_scale;
  return m;
}

// The size query / copy of the _parameters entry points: all or nothing.
Outcome emit_parameters(const char* fn, const optim::FreeParameters& D, cyc_free_parameter* params,
                        int capacity, int* count) {
  if (params && capacity < D.count)
    return fail(CYC_E_BUFFER_TOO_SMALL, "%s: capacity %d < %d parameters", fn, capacity, D.count);
  if (params)
    for (int i = 0; i < D.count; ++i) {
      const optim::FreeParameter& q = D.p[i];
      cyc_free_parameter c;
      c.role = int(q.role);
      c.index = q.index;
      c.order = q.order;
      c.lower = q.lower;
      c.upper = q.upper;
      c.start = q.start;
      params[i] = c;
    }
  *count = D.count;
  return ok();
}
#endif

}  // namespace

extern "C" {

int cyc_optimize_blend(cyc_context* ctx, int kind, const cyc_blend_end* start,
                       const cyc_blend_end* end, int K, double t0, double t1,
                       const cyc_blend_objective* objective, const cyc_optimize_options* options,
                       cyc_surface** out, cyc_blend_end* start_out, cyc_blend_end* end_out,
                       cyc_optimize_summary* summary) {
  const char* fn = "cyc_optimize_blend";
  return run(ctx, fn, [&]() -> Outcome {
    REQUIRE(start);
    REQUIRE(end);
    REQUIRE(start->surface);
    REQUIRE(end->surface);
    REQUIRE(out);
#if CYCLIDE_HAVE_CERES
    if (kind != CYC_BLEND_CANAL && kind != CYC_BLEND_RINGED)
      return fail(CYC_E_INVALID_ARGUMENT, "%s: kind %d is neither CYC_BLEND_CANAL nor "
                  "CYC_BLEND_RINGED", fn, kind);
    cyc_blend_objective o;
    cyc_optimize_options p;
    cyc_blend_objective_init(&o);
    cyc_optimize_options_init(&p);
    if (objective) o = *objective;
    if (options) p = *options;
    if (o.target_count < 0 || o.obstacle_count < 0)
      return fail(CYC_E_INVALID_ARGUMENT, "%s: negative target or obstacle count", fn);
    if ((o.target_count > 0 && !o.targets) || (o.obstacle_count > 0 && !o.obstacles))
      return fail(CYC_E_NULL_ARGUMENT, "%s: NULL targets or obstacles with a positive count",
                  fn);
    std::vector<optim::TargetPoint> targets(size_t(o.target_count));
    for (int q = 0; q < o.target_count; ++q) {
      targets[size_t(q)].point = vec(o.targets[q].point);
      targets[size_t(q)].t = o.targets[q].t;
    }
    std::vector<optim::SphereObstacle> obstacles(size_t(o.obstacle_count));
    for (int q = 0; q < o.obstacle_count; ++q) {
      obstacles[size_t(q)].center = vec(o.obstacles[q].center);
      obstacles[size_t(q)].radius = o.obstacles[q].radius;
    }
    optim::BlendObjective O;
    O.fairness = o.fairness;
    O.regularity = o.regularity;
    O.min_determinant = o.min_determinant;
    O.min_speed = o.min_speed;
    O.targets = targets.data();
    O.target_count = o.target_count;
    O.target_weight = o.target_weight;
    O.obstacles = obstacles.data();
    O.obstacle_count = o.obstacle_count;
    O.clearance = o.clearance;
    O.obstacle_weight = o.obstacle_weight;
    O.quadrature_t = o.quadrature_t;
    O.quadrature_v = o.quadrature_v;
    const optim::BlendOptions P = blend_options_of(&p);
    Surface S;
    BlendEnd so, eo;
    optim::BlendSummary R;
    double bad = t0;
    const optim::BlendKind k =
        kind == CYC_BLEND_CANAL ? optim::BlendKind::canal : optim::BlendKind::ringed;
    const Status st =
        optim::optimize_blend(k, end_of(*start), end_of(*end), K, t0, t1, O, P, S, &so, &eo, R, &bad);
    if (st != Status::ok) return located(st) ? from_core_at(fn, st, bad) : from_core(fn, st);
    const Outcome made = emit(fn, ctx, out, S);
    if (made.status) return made;
    auto put_end = [](const cyc_blend_end& in, const BlendEnd& b, cyc_blend_end* dst) {
      cyc_blend_end r = in;
      r.lambda = b.lambda;
      for (int m = 0; m < kMaxBlendOrder - 1; ++m) r.phi[m] = b.phi[m];
      for (int j = 0; j < 3; ++j) r.v[j] = b.v[j];
      *dst = r;
    };
    if (start_out) put_end(*start, so, start_out);
    if (end_out) put_end(*end, eo, end_out);
    if (summary) *summary = summary_of(R);
    return made;
#else
    (void)kind; (void)K; (void)t0; (void)t1; (void)objective; (void)options;
    (void)start_out; (void)end_out; (void)summary;
    return fail(CYC_E_UNSUPPORTED, "%s: this build has no optimizer tier (Ceres)", fn);
#endif
  });
}

void cyc_bump_objective_init(cyc_bump_objective* o) {
  if (!o) return;
  std::memset(o, 0, sizeof *o);
#if CYCLIDE_HAVE_CERES
  const optim::BumpObjective d;
  o->deviance = d.deviance;
  o->clearance = d.clearance;
  o->obstacle_weight = d.obstacle_weight;
  o->nodes = d.nodes;
#else
  o->deviance = 1.0;
  o->obstacle_weight = 1.0;
  o->nodes = 64;
#endif
}

void cyc_bump_options_init(cyc_bump_options* p) {
  if (!p) return;
  std::memset(p, 0, sizeof *p);
  p->w_bound = 2.0;
  p->tau_min = 0.2;
  p->tau_max = 0.8;
  p->free_tau = 1;
  p->max_iterations = 50;
  p->function_tolerance = 1e-10;
  p->gradient_tolerance = 1e-12;
  p->parameter_tolerance = 1e-10;
}

int cyc_optimize_pcurve_bump(cyc_context* ctx, const cyc_ringed_jet* a, const cyc_ringed_jet* b,
                             const cyc_pcurve_blend_options* blend,
                             const cyc_directrix_bump* start, const cyc_bump_objective* objective,
                             const cyc_bump_options* options, cyc_surface** pieces, int* count,
                             cyc_directrix_bump* chosen, cyc_optimize_summary* summary) {
  const char* fn = "cyc_optimize_pcurve_bump";
  return run(ctx, fn, [&]() -> Outcome {
    REQUIRE(a);
    REQUIRE(b);
    REQUIRE(pieces);
    REQUIRE(count);
#if CYCLIDE_HAVE_CERES
    RingedBlendOptions B;
    if (Outcome e = pcurve_blend_options_of(fn, blend, start, B); e.status) return e;
    cyc_bump_objective o;
    cyc_bump_options p;
    cyc_bump_objective_init(&o);
    cyc_bump_options_init(&p);
    if (objective) o = *objective;
    if (options) p = *options;
    if (o.obstacle_count < 0)
      return fail(CYC_E_INVALID_ARGUMENT, "%s: negative obstacle count", fn);
    if (o.obstacle_count > 0 && !o.obstacles)
      return fail(CYC_E_NULL_ARGUMENT, "%s: NULL obstacles with a positive count", fn);
    std::vector<optim::SphereObstacle> obstacles(size_t(o.obstacle_count));
    for (int q = 0; q < o.obstacle_count; ++q) {
      obstacles[size_t(q)].center = vec(o.obstacles[q].center);
      obstacles[size_t(q)].radius = o.obstacles[q].radius;
    }
    optim::BumpObjective O;
    O.deviance = o.deviance;
    O.obstacles = obstacles.data();
    O.obstacle_count = o.obstacle_count;
    O.clearance = o.clearance;
    O.obstacle_weight = o.obstacle_weight;
    O.nodes = o.nodes;
    const optim::BumpOptions P = bump_options_of(&p);
    Surface S[2];
    int n = 0;
    DirectrixBump D;
    optim::BlendSummary R;
    if (Status st = optim::optimize_pcurve_bump(jet_of(*a), jet_of(*b), B, O, P, S, n, D, R);
        st != Status::ok)
      return from_core(fn, st);
    if (Outcome e = emit_pieces(fn, ctx, S, n, pieces, count); e.status) return e;
    if (chosen) {
      cyc_directrix_bump c;
      put3(c.w, D.w);
      c.tau = D.tau;
      c.kind = int(D.kind);
      *chosen = c;
    }
    if (summary) *summary = summary_of(R);
    return ok();
#else
    (void)blend; (void)start; (void)objective; (void)options; (void)chosen; (void)summary;
    return fail(CYC_E_UNSUPPORTED, "%s: this build has no optimizer tier (Ceres)", fn);
#endif
  });
}

int cyc_optimize_blend_parameters(cyc_context* ctx, int kind, const cyc_blend_end* start,
                                  const cyc_blend_end* end, int K, double t0, double t1,
                                  const cyc_optimize_options* options, cyc_free_parameter* params,
                                  int capacity, int* count) {
  const char* fn = "cyc_optimize_blend_parameters";
  return run(ctx, fn, [&]() -> Outcome {
    REQUIRE(start);
    REQUIRE(end);
    REQUIRE(start->surface);
    REQUIRE(end->surface);
    REQUIRE(count);
#if CYCLIDE_HAVE_CERES
    if (kind != CYC_BLEND_CANAL && kind != CYC_BLEND_RINGED)
      return fail(CYC_E_INVALID_ARGUMENT, "%s: kind %d is neither CYC_BLEND_CANAL nor "
                  "CYC_BLEND_RINGED", fn, kind);
    optim::FreeParameters D;
    double bad = t0;
    const optim::BlendKind k =
        kind == CYC_BLEND_CANAL ? optim::BlendKind::canal : optim::BlendKind::ringed;
    const Status st = optim::describe_blend_parameters(k, end_of(*start), end_of(*end), K, t0, t1,
                                                       blend_options_of(options), D, &bad);
    if (st != Status::ok) return located(st) ? from_core_at(fn, st, bad) : from_core(fn, st);
    return emit_parameters(fn, D, params, capacity, count);
#else
    (void)kind; (void)K; (void)t0; (void)t1; (void)options; (void)params; (void)capacity;
    return fail(CYC_E_UNSUPPORTED, "%s: this build has no optimizer tier (Ceres)", fn);
#endif
  });
}

int cyc_optimize_pcurve_bump_parameters(cyc_context* ctx, const cyc_ringed_jet* a,
                                        const cyc_ringed_jet* b,
                                        const cyc_pcurve_blend_options* blend,
                                        const cyc_directrix_bump* start,
                                        const cyc_bump_options* options,
                                        cyc_free_parameter* params, int capacity, int* count) {
  const char* fn = "cyc_optimize_pcurve_bump_parameters";
  return run(ctx, fn, [&]() -> Outcome {
    REQUIRE(a);
    REQUIRE(b);
    REQUIRE(count);
#if CYCLIDE_HAVE_CERES
    RingedBlendOptions B;
    if (Outcome e = pcurve_blend_options_of(fn, blend, start, B); e.status) return e;
    optim::FreeParameters D;
    if (Status st = optim::describe_bump_parameters(jet_of(*a), jet_of(*b), B,
                                                    optim::BumpObjective(),
                                                    bump_options_of(options), D);
        st != Status::ok)
      return from_core(fn, st);
    return emit_parameters(fn, D, params, capacity, count);
#else
    (void)blend; (void)start; (void)options; (void)params; (void)capacity;
    return fail(CYC_E_UNSUPPORTED, "%s: this build has no optimizer tier (Ceres)", fn);
#endif
  });
}

void cyc_cyclide_blend_objective_init(cyc_cyclide_blend_objective* o) {
  if (!o) return;
  std::memset(o, 0, sizeof *o);
  o->fairness = 1.0;
  o->joint_point_weight = 1.0;
  o->joint_radius_weight = 1.0;
  o->obstacle_weight = 1.0;
  o->regularity = 1.0;
  o->min_extent = 0.05;
  o->circles = 16;
}

void cyc_cyclide_blend_options_init(cyc_cyclide_blend_options* p) {
  if (!p) return;
  std::memset(p, 0, sizeof *p);
  p->samples = 64;
  p->max_iterations = 50;
  p->function_tolerance = 1e-10;
  p->gradient_tolerance = 1e-12;
  p->parameter_tolerance = 1e-10;
}

}  // extern "C"

#if CYCLIDE_HAVE_CERES
namespace {
// The caller's objective and options with the arrays copied into `points`
// and `obstacles` (which must outlive the returned objective).
Outcome cyclide_objective_of(const char* fn, const cyc_cyclide_blend_objective* objective,
                             const cyc_cyclide_blend_options* options,
                             std::vector<Vec3d>& points,
                             std::vector<optim::SphereObstacle>& obstacles,
                             optim::CyclideBlendObjective& O,
                             optim::CyclideBlendOptimizerOptions& P) {
  cyc_cyclide_blend_objective o;
  cyc_cyclide_blend_options p;
  cyc_cyclide_blend_objective_init(&o);
  cyc_cyclide_blend_options_init(&p);
  if (objective) o = *objective;
  if (options) p = *options;
  if (o.joint_point_count < 0 || o.obstacle_count < 0)
    return fail(CYC_E_INVALID_ARGUMENT, "%s: negative joint point or obstacle count", fn);
  if ((o.joint_point_count > 0 && !o.joint_points) || (o.obstacle_count > 0 && !o.obstacles))
    return fail(CYC_E_NULL_ARGUMENT, "%s: NULL joint_points or obstacles with a positive count",
                fn);
  points.resize(size_t(o.joint_point_count));
  for (int q = 0; q < o.joint_point_count; ++q) points[size_t(q)] = vec(o.joint_points + 3 * q);
  obstacles.resize(size_t(o.obstacle_count));
  for (int q = 0; q < o.obstacle_count; ++q) {
    obstacles[size_t(q)].center = vec(o.obstacles[q].center);
    obstacles[size_t(q)].radius = o.obstacles[q].radius;
  }
  O.fairness = o.fairness;
  O.joint_points = points.data();
  O.joint_point_count = o.joint_point_count;
  O.joint_point_weight = o.joint_point_weight;
  O.joint_radius = o.joint_radius;
  O.joint_radius_weight = o.joint_radius_weight;
  O.obstacles = obstacles.data();
  O.obstacle_count = o.obstacle_count;
  O.clearance = o.clearance;
  O.obstacle_weight = o.obstacle_weight;
  O.regularity = o.regularity;
  O.min_extent = o.min_extent;
  O.circles = o.circles;
  P.samples = p.samples;
  P.branch = p.branch;
  P.max_iterations = p.max_iterations;
  P.function_tolerance = p.function_tolerance;
  P.gradient_tolerance = p.gradient_tolerance;
  P.parameter_tolerance = p.parameter_tolerance;
  return ok();
}
}  // namespace
#endif

extern "C" {

int cyc_optimize_cyclide_blend(cyc_context* ctx, const cyc_lie_cone* r, const cyc_lie_cone* s,
                               const cyc_cyclide_blend_objective* objective,
                               const cyc_cyclide_blend_options* options, cyc_cyclide_blend* out,
                               cyc_optimize_summary* summary) {
  const char* fn = "cyc_optimize_cyclide_blend";
  return run(ctx, fn, [&]() -> Outcome {
    REQUIRE(r);
    REQUIRE(s);
    REQUIRE(out);
#if CYCLIDE_HAVE_CERES
    std::vector<Vec3d> points;
    std::vector<optim::SphereObstacle> obstacles;
    optim::CyclideBlendObjective O;
    optim::CyclideBlendOptimizerOptions P;
    if (Outcome e = cyclide_objective_of(fn, objective, options, points, obstacles, O, P);
        e.status)
      return e;
    CyclideBlend B;
    optim::BlendSummary R;
    if (Status st = optim::optimize_cyclide_blend(cone_in(r), cone_in(s), O, P, B, R);
        st != Status::ok)
      return cone_status(fn, st);
    cyc_cyclide_blend c;
    if (Outcome e = blend_out(fn, B, &c); e.status) return e;
    *out = c;
    if (summary) *summary = summary_of(R);
    return ok();
#else
    (void)objective; (void)options; (void)summary;
    return fail(CYC_E_UNSUPPORTED, "%s: this build has no optimizer tier (Ceres)", fn);
#endif
  });
}

int cyc_optimize_cyclide_blend_parameters(cyc_context* ctx, const cyc_lie_cone* r,
                                          const cyc_lie_cone* s,
                                          const cyc_cyclide_blend_objective* objective,
                                          const cyc_cyclide_blend_options* options,
                                          cyc_free_parameter* params, int capacity, int* count) {
  const char* fn = "cyc_optimize_cyclide_blend_parameters";
  return run(ctx, fn, [&]() -> Outcome {
    REQUIRE(r);
    REQUIRE(s);
    REQUIRE(count);
#if CYCLIDE_HAVE_CERES
    std::vector<Vec3d> points;
    std::vector<optim::SphereObstacle> obstacles;
    optim::CyclideBlendObjective O;
    optim::CyclideBlendOptimizerOptions P;
    if (Outcome e = cyclide_objective_of(fn, objective, options, points, obstacles, O, P);
        e.status)
      return e;
    optim::FreeParameters D;
    if (Status st = optim::describe_cyclide_blend_parameters(cone_in(r), cone_in(s), O, P, D);
        st != Status::ok)
      return cone_status(fn, st);
    return emit_parameters(fn, D, params, capacity, count);
#else
    (void)objective; (void)options; (void)params; (void)capacity;
    return fail(CYC_E_UNSUPPORTED, "%s: this build has no optimizer tier (Ceres)", fn);
#endif
  });
}

}  // extern "C"
