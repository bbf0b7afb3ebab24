// The optimizer tier's C entry points. Built with or without Ceres; the
// symbol set is the same in every build (SPEC.md "Optimizer tier").
#include <cstdarg>
#include <cstdint>
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

#if CYCLIDE_HAVE_CERES
namespace {

// Every double the optimizers read goes through the shared check
// (capi_internal.hpp) with its name as the caller wrote it, e.g.
// objective.obstacles[2].radius or start.phi[1]; the name is formatted only
// on failure. check_field: one double; check_fields: n doubles, name[i].
Outcome check_named(const char* fn, const double* x, size_t n, bool indexed, const char* fmt,
                    va_list ap) {
  for (size_t i = 0; i < n; ++i)
    if (beyond_input_range(x[i])) {
      char name[160];
      std::vsnprintf(name, sizeof name, fmt, ap);
      return indexed ? check_doubles(fn, name, x, n) : check_double(fn, name, x[0]);
    }
  return ok();
}

#if defined(__GNUC__)
__attribute__((format(printf, 3, 4)))
#endif
Outcome check_field(const char* fn, const double* x, const char* fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  Outcome o = check_named(fn, x, 1, false, fmt, ap);
  va_end(ap);
  return o;
}

#if defined(__GNUC__)
__attribute__((format(printf, 4, 5)))
#endif
Outcome check_fields(const char* fn, const double* x, size_t n, const char* fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  Outcome o = check_named(fn, x, n, true, fmt, ap);
  va_end(ap);
  return o;
}

// A range condition on a named double (the name and value in the message).
Outcome require_that(const char* fn, bool holds, const char* name, double x, const char* what) {
  if (holds) return ok();
  return fail(CYC_E_INVALID_ARGUMENT, "%s: %s = %.17g %s", fn, name, x, what);
}

// A weight, clearance or tolerance: finite, within the input range, >= 0.
Outcome check_nonnegative(const char* fn, const char* name, double x) {
  TRY(check_double(fn, name, x));
  return require_that(fn, x >= 0, name, x, "is negative (it must be >= 0)");
}

// The most targets, obstacles or joint points one objective may list: each
// adds residuals at every quadrature node (up to 1024 in the bump
// optimizer), so the residual count and the Jacobian stay bounded and no
// count arithmetic can overflow.
constexpr int kMaxObjectiveItems = 4096;

// A caller's count and array: 0..kMaxObjectiveItems, and the array non-NULL
// when the count is positive.
Outcome check_items(const char* fn, const char* count_name, int count, const char* array_name,
                    const void* array) {
  TRY(check_range(fn, count_name, count, 0, kMaxObjectiveItems));
  if (count > 0 && !array)
    return fail(CYC_E_NULL_ARGUMENT, "%s: %s is NULL with %s = %d", fn, array_name, count_name,
                count);
  return ok();
}

// Spherical obstacles: centers within the input range, radius >= 0.
Outcome check_obstacles(const char* fn, const char* name, const cyc_blend_obstacle* obstacles,
                        int count) {
  for (int q = 0; q < count; ++q) {
    const cyc_blend_obstacle& o = obstacles[q];
    TRY(check_fields(fn, o.center, 3, "%s[%d].center", name, q));
    TRY(check_field(fn, &o.radius, "%s[%d].radius", name, q));
    if (!(o.radius >= 0))
      return fail(CYC_E_INVALID_ARGUMENT, "%s: %s[%d].radius = %.17g is negative", fn, name, q,
                  o.radius);
  }
  return ok();
}

// Ceres' three convergence tolerances (>= 0 each).
template <class Options>
Outcome check_tolerances(const char* fn, const char* name, const Options& p) {
  char field[96];
  const double v[3] = {p.function_tolerance, p.gradient_tolerance, p.parameter_tolerance};
  const char* names[3] = {"function_tolerance", "gradient_tolerance", "parameter_tolerance"};
  for (int i = 0; i < 3; ++i) {
    std::snprintf(field, sizeof field, "%s.%s", name, names[i]);
    TRY(check_nonnegative(fn, field, v[i]));
  }
  std::snprintf(field, sizeof field, "%s.max_iterations", name);
  return check_range(fn, field, p.max_iterations, 0, INT32_MAX);
}

// Seed 001's Hermite data of a join (eq. 37), every field named.
Outcome check_jet(const char* fn, const char* name, const cyc_ringed_jet& j) {
  TRY(check_fields(fn, j.d, 3, "%s.d", name));
  TRY(check_fields(fn, j.dd, 3, "%s.dd", name));
  TRY(check_fields(fn, j.n, 3, "%s.n", name));
  TRY(check_fields(fn, j.dn, 3, "%s.dn", name));
  TRY(check_field(fn, &j.rho, "%s.rho", name));
  return check_field(fn, &j.drho, "%s.drho", name);
}

// The P-curve blend's options and the start bump (either may be NULL).
Outcome check_pcurve_inputs(const char* fn, const cyc_pcurve_blend_options* blend,
                            const cyc_directrix_bump* start) {
  if (blend) {
    TRY(check_double(fn, "blend.tau", blend->tau));
    TRY(check_doubles(fn, "blend.v", blend->v, 3));
  }
  if (start) {
    TRY(check_doubles(fn, "start.w", start->w, 3));
    TRY(check_double(fn, "start.tau", start->tau));
  }
  return ok();
}

// The bump optimizer's bounds and solver options (defaults when NULL).
Outcome check_bump_options(const char* fn, const cyc_bump_options& p,
                           const cyc_pcurve_blend_options* blend,
                           const cyc_directrix_bump* start) {
  TRY(check_double(fn, "options.w_bound", p.w_bound));
  TRY(require_that(fn, p.w_bound > 0, "options.w_bound", p.w_bound,
                   "is not positive (|w_j| <= w_bound L)"));
  TRY(check_double(fn, "options.tau_min", p.tau_min));
  TRY(check_double(fn, "options.tau_max", p.tau_max));
  if (!(p.tau_min > 0 && p.tau_min <= p.tau_max && p.tau_max < 1))
    return fail(CYC_E_INVALID_ARGUMENT,
                "%s: options.tau_min = %.17g, options.tau_max = %.17g: tau's box must satisfy "
                "0 < tau_min <= tau_max < 1",
                fn, p.tau_min, p.tau_max);
  TRY(check_tolerances(fn, "options", p));
  const double tau = blend ? blend->tau : 0.0;
  const bool two_piece = start && start->kind == CYC_BUMP_TWO_PIECE;
  if (tau != 0.0 && two_piece && p.free_tau)
    return fail(CYC_E_INVALID_ARGUMENT,
                "%s: a two-piece bump on a P-biarc (blend.tau = %.17g) keeps its position at the "
                "biarc's joint: set options.free_tau = 0",
                fn, tau);
  return ok();
}

// One end of an optimized blend (cyc_blend_end): u, lambda, the phi[m - 2]
// for m = 2..K (the only ones the call reads) and the circle parameters of
// the chosen points v[0..points) (2 canal, 3 ringed; +-infinity is the
// generator, NaN or a finite value beyond the input range is refused).
Outcome check_blend_end(const char* fn, const char* name, const cyc_blend_end& e, int K,
                        int points) {
  TRY(check_field(fn, &e.u, "%s.u", name));
  TRY(check_field(fn, &e.lambda, "%s.lambda", name));
  TRY(check_fields(fn, e.phi, size_t(K - 1), "%s.phi", name));
  for (int j = 0; j < points; ++j)
    if (!std::isinf(e.v[j])) TRY(check_field(fn, &e.v[j], "%s.v[%d]", name, j));
  return ok();
}

// The blend optimizer's kind, order, interval, ends and options, every field
// named (objective: see check_blend_objective).
Outcome check_blend_call(const char* fn, int kind, const cyc_blend_end& start,
                         const cyc_blend_end& end, int K, double t0, double t1,
                         const cyc_optimize_options& p) {
  if (kind != CYC_BLEND_CANAL && kind != CYC_BLEND_RINGED)
    return fail(CYC_E_INVALID_ARGUMENT,
                "%s: kind = %d is neither CYC_BLEND_CANAL (0) nor CYC_BLEND_RINGED (1)", fn, kind);
  const bool canal = kind == CYC_BLEND_CANAL;
  TRY(check_range(fn, "K", K, canal ? 2 : 1, kMaxBlendOrder, CYC_E_DEGREE_TOO_HIGH));
  TRY(check_double(fn, "t0", t0));
  TRY(check_double(fn, "t1", t1));
  TRY(check_blend_end(fn, "start", start, K, canal ? 2 : 3));
  TRY(check_blend_end(fn, "end", end, K, canal ? 2 : 3));
  TRY(check_range(fn, "options.free_orders", p.free_orders, 0, K));
  TRY(check_double(fn, "options.lambda_min_ratio", p.lambda_min_ratio));
  TRY(require_that(fn, p.lambda_min_ratio > 0 && p.lambda_min_ratio <= 1,
                   "options.lambda_min_ratio", p.lambda_min_ratio, "is outside (0, 1]"));
  TRY(check_double(fn, "options.lambda_max_ratio", p.lambda_max_ratio));
  TRY(require_that(fn, p.lambda_max_ratio >= 1, "options.lambda_max_ratio", p.lambda_max_ratio,
                   "is below 1"));
  TRY(check_nonnegative(fn, "options.higher_bound", p.higher_bound));
  TRY(check_nonnegative(fn, "options.circle_parameter_range", p.circle_parameter_range));
  return check_tolerances(fn, "options", p);
}

// The blend optimizer's objective (defaults when NULL).
Outcome check_blend_objective(const char* fn, const cyc_blend_objective& o) {
  TRY(check_nonnegative(fn, "objective.fairness", o.fairness));
  TRY(check_nonnegative(fn, "objective.regularity", o.regularity));
  TRY(check_double(fn, "objective.min_determinant", o.min_determinant));
  TRY(require_that(fn, o.min_determinant > 0 && o.min_determinant < 1,
                   "objective.min_determinant", o.min_determinant,
                   "is outside (0, 1) (a relative determinant of the PRCS/PRRS planes)"));
  TRY(check_double(fn, "objective.min_speed", o.min_speed));
  TRY(require_that(fn, o.min_speed > 0, "objective.min_speed", o.min_speed,
                   "is not positive (|x_t| >= min_speed L)"));
  TRY(check_nonnegative(fn, "objective.target_weight", o.target_weight));
  TRY(check_nonnegative(fn, "objective.clearance", o.clearance));
  TRY(check_nonnegative(fn, "objective.obstacle_weight", o.obstacle_weight));
  TRY(check_range(fn, "objective.quadrature_t", o.quadrature_t, 1, CYC_MAX_QUADRATURE));
  TRY(check_range(fn, "objective.quadrature_v", o.quadrature_v, 1, CYC_MAX_QUADRATURE));
  TRY(check_items(fn, "objective.target_count", o.target_count, "objective.targets", o.targets));
  TRY(check_items(fn, "objective.obstacle_count", o.obstacle_count, "objective.obstacles",
                  o.obstacles));
  for (int q = 0; q < o.target_count; ++q) {
    TRY(check_fields(fn, o.targets[q].point, 3, "objective.targets[%d].point", q));
    TRY(check_field(fn, &o.targets[q].t, "objective.targets[%d].t", q));
  }
  return check_obstacles(fn, "objective.obstacles", o.obstacles, o.obstacle_count);
}

// The P-curve bump optimizer's objective (defaults when NULL).
Outcome check_bump_objective(const char* fn, const cyc_bump_objective& o) {
  TRY(check_nonnegative(fn, "objective.deviance", o.deviance));
  TRY(check_nonnegative(fn, "objective.clearance", o.clearance));
  TRY(check_nonnegative(fn, "objective.obstacle_weight", o.obstacle_weight));
  TRY(check_range(fn, "objective.nodes", o.nodes, 4, 1024));
  TRY(check_items(fn, "objective.obstacle_count", o.obstacle_count, "objective.obstacles",
                  o.obstacles));
  return check_obstacles(fn, "objective.obstacles", o.obstacles, o.obstacle_count);
}

// The Dupin blend optimizer's cones, objective and options.
Outcome check_cyclide_call(const char* fn, const cyc_lie_cone& r, const cyc_lie_cone& s,
                           const cyc_cyclide_blend_objective& o,
                           const cyc_cyclide_blend_options& p) {
  TRY(check_doubles(fn, "r.r0", r.r0, 6));
  TRY(check_doubles(fn, "r.r_plus", r.r_plus, 6));
  TRY(check_doubles(fn, "s.r0", s.r0, 6));
  TRY(check_doubles(fn, "s.r_plus", s.r_plus, 6));
  TRY(check_nonnegative(fn, "objective.fairness", o.fairness));
  TRY(check_nonnegative(fn, "objective.joint_point_weight", o.joint_point_weight));
  TRY(check_nonnegative(fn, "objective.joint_radius", o.joint_radius));
  TRY(check_nonnegative(fn, "objective.joint_radius_weight", o.joint_radius_weight));
  TRY(check_nonnegative(fn, "objective.clearance", o.clearance));
  TRY(check_nonnegative(fn, "objective.obstacle_weight", o.obstacle_weight));
  TRY(check_nonnegative(fn, "objective.regularity", o.regularity));
  TRY(check_nonnegative(fn, "objective.min_extent", o.min_extent));
  TRY(check_range(fn, "objective.circles", o.circles, 4, 256));
  TRY(check_items(fn, "objective.joint_point_count", o.joint_point_count,
                  "objective.joint_points", o.joint_points));
  TRY(check_items(fn, "objective.obstacle_count", o.obstacle_count, "objective.obstacles",
                  o.obstacles));
  TRY(check_doubles(fn, "objective.joint_points", o.joint_points,
                    3 * size_t(o.joint_point_count)));
  TRY(check_obstacles(fn, "objective.obstacles", o.obstacles, o.obstacle_count));
  TRY(check_range(fn, "options.samples", p.samples, 8, 4096));
  TRY(check_range(fn, "options.branch", p.branch, -1, 1));
  return check_tolerances(fn, "options", p);
}
}  // namespace
#endif  // CYCLIDE_HAVE_CERES

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
    TRY(check_doubles(fn, "point", point, 3));
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
    cyc_blend_objective o;
    cyc_optimize_options p;
    cyc_blend_objective_init(&o);
    cyc_optimize_options_init(&p);
    if (objective) o = *objective;
    if (options) p = *options;
    TRY(check_blend_call(fn, kind, *start, *end, K, t0, t1, p));
    TRY(check_blend_objective(fn, o));
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
    // The chosen end: the caller's surface and u, the optimized lambda,
    // phi^(m) for m = 2..K and the points' v; the entries the call does not
    // read (phi beyond K, v[2] of a canal blend) are 0, never copied from
    // the caller unvalidated.
    const int points = kind == CYC_BLEND_CANAL ? 2 : 3;
    auto put_end = [&](const cyc_blend_end& in, const BlendEnd& b, cyc_blend_end* dst) {
      cyc_blend_end r;
      std::memset(&r, 0, sizeof r);
      r.surface = in.surface;
      r.u = in.u;
      r.lambda = b.lambda;
      for (int m = 0; m + 2 <= K; ++m) r.phi[m] = b.phi[m];
      for (int j = 0; j < points; ++j) r.v[j] = b.v[j];
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
    // Pointers before values: the obstacle array the objective counts.
    if (objective)
      TRY(check_items(fn, "objective.obstacle_count", objective->obstacle_count,
                      "objective.obstacles", objective->obstacles));
    TRY(check_jet(fn, "a", *a));
    TRY(check_jet(fn, "b", *b));
    TRY(check_pcurve_inputs(fn, blend, start));
    RingedBlendOptions B;
    if (Outcome e = pcurve_blend_options_of(fn, blend, start, B); e.status) return e;
    cyc_bump_objective o;
    cyc_bump_options p;
    cyc_bump_objective_init(&o);
    cyc_bump_options_init(&p);
    if (objective) o = *objective;
    if (options) p = *options;
    TRY(check_bump_objective(fn, o));
    TRY(check_bump_options(fn, p, blend, start));
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
    cyc_optimize_options p;
    cyc_optimize_options_init(&p);
    if (options) p = *options;
    TRY(check_blend_call(fn, kind, *start, *end, K, t0, t1, p));
    optim::FreeParameters D;
    double bad = t0;
    const optim::BlendKind k =
        kind == CYC_BLEND_CANAL ? optim::BlendKind::canal : optim::BlendKind::ringed;
    const Status st = optim::describe_blend_parameters(k, end_of(*start), end_of(*end), K, t0, t1,
                                                       blend_options_of(&p), D, &bad);
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
    TRY(check_jet(fn, "a", *a));
    TRY(check_jet(fn, "b", *b));
    TRY(check_pcurve_inputs(fn, blend, start));
    RingedBlendOptions B;
    if (Outcome e = pcurve_blend_options_of(fn, blend, start, B); e.status) return e;
    cyc_bump_options p;
    cyc_bump_options_init(&p);
    if (options) p = *options;
    TRY(check_bump_options(fn, p, blend, start));
    optim::FreeParameters D;
    if (Status st = optim::describe_bump_parameters(jet_of(*a), jet_of(*b), B,
                                                    optim::BumpObjective(),
                                                    bump_options_of(&p), D);
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
Outcome cyclide_objective_of(const char* fn, const cyc_lie_cone& r, const cyc_lie_cone& s,
                             const cyc_cyclide_blend_objective* objective,
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
  TRY(check_cyclide_call(fn, r, s, o, p));
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
    if (Outcome e = cyclide_objective_of(fn, *r, *s, objective, options, points, obstacles, O, P);
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
    if (Outcome e = cyclide_objective_of(fn, *r, *s, objective, options, points, obstacles, O, P);
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
