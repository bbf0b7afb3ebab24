// Seed 001 §7.a through the C ABI: the implicit blend (73), its contour
// points (77)/(78), and the Ceres approximation (optimizer tier; built
// with or without Ceres, like optimizer_c.cpp: the symbol set is the same
// in every build).
#include <cmath>
#include <cstring>

#include "capi_internal.hpp"
#include "cyclide/implicit_blend.hpp"

#ifndef CYCLIDE_HAVE_CERES
#define CYCLIDE_HAVE_CERES 0
#endif

#if CYCLIDE_HAVE_CERES
#include "optim/implicit_blend_optimizer.hpp"
#endif

using namespace cyclide;
using namespace cyclide::capi;

static_assert(CYC_MAX_IMPLICIT_EXPONENT == kMaxImplicitExponent, "exponent bound");
#if CYCLIDE_HAVE_CERES
static_assert(CYC_MAX_IMPLICIT_PIECES == optim::kMaxImplicitPieces, "piece bound");
#endif

namespace {

// A quadric's 10 coefficients q0..q9 (named name[k]); its quadratic part
// q0..q5 must not vanish (else it is a plane or a constant).
Outcome check_quadric(const char* fn, const char* name, const double* q) {
  TRY(check_doubles(fn, name, q, 10));
  for (int k = 0; k < 6; ++k)
    if (q[k] != 0) return ok();
  return fail(CYC_E_INVALID_ARGUMENT, "%s: %s has a zero quadratic part (q0..q5 = 0): not a "
              "quadric", fn, name);
}

// A plane a x + b y + c z + d (named name[k]) with a normal (a, b, c) != 0.
Outcome check_plane(const char* fn, const char* name, const double* p) {
  TRY(check_doubles(fn, name, p, 4));
  if (p[0] != 0 || p[1] != 0 || p[2] != 0) return ok();
  return fail(CYC_E_INVALID_ARGUMENT, "%s: %s has a zero normal (a, b, c): not a plane", fn,
              name);
}

// The core's blend (73) from the C description, every field checked and
// named (blend.f1[k], ..., blend.lambda, blend.n) before the core sees it.
Outcome blend_of(const char* fn, const cyc_implicit_blend& c, ImplicitBlend& B) {
  TRY(check_quadric(fn, "blend.f1", c.f1));
  TRY(check_quadric(fn, "blend.f2", c.f2));
  TRY(check_plane(fn, "blend.f10", c.f10));
  TRY(check_plane(fn, "blend.f20", c.f20));
  TRY(check_double(fn, "blend.lambda", c.lambda));
  if (!(c.lambda > 0 && c.lambda < 1))
    return fail(CYC_E_INVALID_ARGUMENT, "%s: blend.lambda = %.17g is not in (0, 1)", fn,
                c.lambda);
  TRY(check_range(fn, "blend.n", c.n, 1, kMaxImplicitExponent));
  Quadric f1, f2;
  PlaneFn g1, g2;
  Status st = make_quadric(c.f1, f1);
  if (st == Status::ok) st = make_quadric(c.f2, f2);
  if (st == Status::ok) st = make_plane_fn(c.f10, g1);
  if (st == Status::ok) st = make_plane_fn(c.f20, g2);
  if (st == Status::ok) st = make_implicit_blend(f1, f2, g1, g2, c.lambda, c.n, B);
  if (st == Status::dependent_planes)
    return fail(int(st), "%s: the bounding planes blend.f10 = 0 and blend.f20 = 0 coincide: "
                "the blend (73) has no end circles", fn);
  return from_core(fn, st);
}

// The approximation's options, each field named (options.pieces, ...).
Outcome approx_options_valid(const char* fn, const cyc_implicit_approx_options& p) {
  TRY(check_range(fn, "options.pieces", p.pieces, 1, CYC_MAX_IMPLICIT_PIECES));
  TRY(check_range(fn, "options.nodes", p.nodes, 2, 64));
  TRY(check_range(fn, "options.max_iterations", p.max_iterations, 0, 10000));
  TRY(check_range(fn, "options.error_nodes_t", p.error_nodes_t, 1, 64));
  TRY(check_range(fn, "options.error_nodes_u", p.error_nodes_u, 4, 1024));
  TRY(check_double(fn, "options.psi_weight", p.psi_weight));
  TRY(check_double(fn, "options.length_min_ratio", p.length_min_ratio));
  TRY(check_double(fn, "options.length_max_ratio", p.length_max_ratio));
  TRY(check_double(fn, "options.function_tolerance", p.function_tolerance));
  TRY(check_double(fn, "options.gradient_tolerance", p.gradient_tolerance));
  TRY(check_double(fn, "options.parameter_tolerance", p.parameter_tolerance));
  if (!(p.psi_weight >= 0))
    return fail(CYC_E_INVALID_ARGUMENT, "%s: options.psi_weight = %.17g is negative", fn,
                p.psi_weight);
  if (!(p.length_min_ratio > 0))
    return fail(CYC_E_INVALID_ARGUMENT, "%s: options.length_min_ratio = %.17g is not positive",
                fn, p.length_min_ratio);
  if (!(p.length_max_ratio >= p.length_min_ratio))
    return fail(CYC_E_INVALID_ARGUMENT, "%s: options.length_max_ratio = %.17g is below "
                "options.length_min_ratio = %.17g", fn, p.length_max_ratio, p.length_min_ratio);
  return ok();
}

}  // namespace

extern "C" {

namespace {
// The ten coefficients of a quadric for the caller, if finite (else
// nothing is written).
Outcome quadric_out(const char* fn, const Quadric& Q, double* coeffs) {
  double q[10];
  quadric_coefficients(Q, q);
  for (double c : q)
    if (!std::isfinite(c))
      return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: a coefficient of the quadric overflows", fn);
  std::memcpy(coeffs, q, sizeof q);
  return ok();
}
}  // namespace

int cyc_implicit_cylinder(cyc_context* ctx, const double point[3], const double direction[3],
                          double radius, double coeffs[10]) {
  const char* fn = "cyc_implicit_cylinder";
  return run(ctx, fn, [&]() -> Outcome {
    REQUIRE(point);
    REQUIRE(direction);
    REQUIRE(coeffs);
    TRY(check_doubles(fn, "point", point, 3));
    TRY(check_doubles(fn, "direction", direction, 3));
    TRY(check_positive(fn, "radius", radius));
    Quadric Q;
    if (Status st = make_cylinder(vec(point), vec(direction), radius, Q); st != Status::ok) {
      if (st == Status::invalid_argument)
        return fail(int(st), "%s: direction is zero: the cylinder has no axis", fn);
      return from_core(fn, st);
    }
    return quadric_out(fn, Q, coeffs);
  });
}

int cyc_implicit_cone(cyc_context* ctx, const double apex[3], const double axis[3],
                      double half_angle, double coeffs[10]) {
  const char* fn = "cyc_implicit_cone";
  return run(ctx, fn, [&]() -> Outcome {
    REQUIRE(apex);
    REQUIRE(axis);
    REQUIRE(coeffs);
    TRY(check_doubles(fn, "apex", apex, 3));
    TRY(check_doubles(fn, "axis", axis, 3));
    TRY(check_double(fn, "half_angle", half_angle));
    if (!(half_angle > 0 && half_angle < std::acos(-1.0) / 2))
      return fail(CYC_E_INVALID_ARGUMENT, "%s: half_angle = %.17g is not in (0, pi/2)", fn,
                  half_angle);
    Quadric Q;
    if (Status st = make_cone(vec(apex), vec(axis), half_angle, Q); st != Status::ok) {
      if (st == Status::invalid_argument)
        return fail(int(st), "%s: axis is zero: the cone has no axis", fn);
      return from_core(fn, st);
    }
    return quadric_out(fn, Q, coeffs);
  });
}

int cyc_implicit_blend_eval(cyc_context* ctx, const cyc_implicit_blend* blend, const double x[3],
                            double* f, double grad[3], const double v[3], double* f_v,
                            double grad_f_v[3]) {
  const char* fn = "cyc_implicit_blend_eval";
  return run(ctx, fn, [&]() -> Outcome {
    REQUIRE(blend);
    REQUIRE(x);
    ImplicitBlend B;
    if (Outcome e = blend_of(fn, *blend, B); e.status) return e;
    TRY(check_doubles(fn, "x", x, 3));
    if (v) TRY(check_doubles(fn, "v", v, 3));
    const Vec3d X = vec(x);
    const Vec3d V = v ? vec(v) : Vec3d::Zero();
    const BlendJet<double> J = blend_eval(B, X, v ? &V : nullptr);
    const double fv = J.grad.dot(V);
    // The powers f10^(n+1), f20^(n+1) of (73) overflow far from the planes.
    if (!std::isfinite(J.f) || !J.grad.allFinite() || !std::isfinite(fv) || !J.hv.allFinite())
      return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: f (73) or its derivatives overflow at x = "
                  "(%.17g, %.17g, %.17g)", fn, X.x(), X.y(), X.z());
    if (f) *f = J.f;
    if (grad) put3(grad, J.grad);
    if (v && f_v) *f_v = fv;
    if (v && grad_f_v) put3(grad_f_v, J.hv);
    return ok();
  });
}

int cyc_implicit_contour_points(cyc_context* ctx, const cyc_implicit_blend* blend, int end,
                                const double v[3], int* count, double points[6],
                                int* whole_circle) {
  const char* fn = "cyc_implicit_contour_points";
  return run(ctx, fn, [&]() -> Outcome {
    REQUIRE(blend);
    REQUIRE(v);
    REQUIRE(count);
    REQUIRE(points);
    ImplicitBlend B;
    if (Outcome e = blend_of(fn, *blend, B); e.status) return e;
    TRY(check_range(fn, "end", end, 0, 1));
    TRY(check_doubles(fn, "v", v, 3));
    PlaneContourPoints P;
    if (Status st = end_contour_points(B, end, vec(v), P); st != Status::ok) {
      if (st == Status::singular_point)
        return fail(int(st), "%s: a contour point (%s) of end %d lies on the other bounding "
                    "plane, where f (73) is singular", fn, end == 0 ? "77" : "78", end);
      if (st == Status::invalid_argument)
        return fail(int(st), "%s: the direction v is zero", fn);
      return from_core(fn, st);
    }
    for (int k = 0; k < P.count; ++k)
      if (!P.points[k].allFinite())
        return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: contour point %d is not finite", fn, k);
    for (int k = 0; k < P.count; ++k) put3(points + 3 * k, P.points[k]);
    *count = P.count;
    if (whole_circle) *whole_circle = P.whole_circle ? 1 : 0;
    return ok();
  });
}

void cyc_implicit_approx_options_init(cyc_implicit_approx_options* p) {
  if (!p) return;
  std::memset(p, 0, sizeof *p);
  p->pieces = 1;
  p->psi_weight = 0.01;
  p->nodes = 16;
  p->length_min_ratio = 0.1;
  p->length_max_ratio = 4.0;
  p->max_iterations = 50;
  p->function_tolerance = 1e-12;
  p->gradient_tolerance = 1e-14;
  p->parameter_tolerance = 1e-12;
  p->error_nodes_t = 16;
  p->error_nodes_u = 32;
}

int cyc_optimize_implicit_blend(cyc_context* ctx, const cyc_implicit_blend* blend,
                                const double v[9], const cyc_implicit_approx_options* options,
                                cyc_surface** pieces, int* count,
                                cyc_implicit_approx_report* report) {
  const char* fn = "cyc_optimize_implicit_blend";
  return run(ctx, fn, [&]() -> Outcome {
    REQUIRE(blend);
    REQUIRE(v);
    REQUIRE(pieces);
    REQUIRE(count);
    // The same validation with or without the optimizer tier.
    ImplicitBlend B;
    TRY(blend_of(fn, *blend, B));
    TRY(check_doubles(fn, "v", v, 9));
    cyc_implicit_approx_options p;
    cyc_implicit_approx_options_init(&p);
    if (options) p = *options;
    TRY(approx_options_valid(fn, p));
#if CYCLIDE_HAVE_CERES
    optim::ImplicitApproxOptions o;
    o.pieces = p.pieces;
    o.psi_weight = p.psi_weight;
    o.nodes = p.nodes;
    o.length_min_ratio = p.length_min_ratio;
    o.length_max_ratio = p.length_max_ratio;
    o.max_iterations = p.max_iterations;
    o.function_tolerance = p.function_tolerance;
    o.gradient_tolerance = p.gradient_tolerance;
    o.parameter_tolerance = p.parameter_tolerance;
    o.error_nodes_t = p.error_nodes_t;
    o.error_nodes_u = p.error_nodes_u;
    o.two_curves = p.two_curves != 0;
    const Vec3d V[3] = {vec(v), vec(v + 3), vec(v + 6)};
    Surface S[optim::kMaxImplicitPieces];
    int n = 0;
    optim::ImplicitApproxReport R;
    if (Status st = optim::approximate_implicit_blend(B, V, o, S, n, R); st != Status::ok) {
      if (st == Status::invalid_argument)
        return fail(int(st), "%s: the contour directions v[0..2] (v[0..1] with "
                    "options.two_curves) must be nonzero and pairwise non-parallel, and each "
                    "contour curve must join distinct end points", fn);
      return from_core(fn, st);
    }
    if (!std::isfinite(R.omega) || !std::isfinite(R.error87))
      return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: the error integral is not finite", fn);
    // All handles or none.
    cyc_surface* h[optim::kMaxImplicitPieces] = {};
    for (int k = 0; k < n; ++k)
      if (Outcome e = emit(fn, ctx, &h[k], S[k]); e.status) {
        for (int j = 0; j < k; ++j) release(h[j]);
        return e;
      }
    for (int k = 0; k < n; ++k) pieces[k] = h[k];
    *count = n;
    if (report) {
      cyc_implicit_approx_report r;
      std::memset(&r, 0, sizeof r);
      r.pieces = R.pieces;
      r.omega = R.omega;
      r.error87 = R.error87;
      r.seconds = R.seconds;
      for (int k = 0; k < n; ++k) {
        r.omega_initial[k] = R.piece[k].omega_initial;
        r.omega_piece[k] = R.piece[k].omega;
        r.error87_piece[k] = R.piece[k].error87;
        for (int i = 0; i < 3; ++i) {
          r.alpha[k][i] = R.piece[k].alpha[i];
          r.beta[k][i] = R.piece[k].beta[i];
        }
        r.reverted[k] = R.piece[k].reverted ? 1 : 0;
      }
      *report = r;
    }
    return ok();
#else
    (void)report;
    return fail(CYC_E_UNSUPPORTED, "%s: this build has no optimizer tier (Ceres)", fn);
#endif
  });
}

}  // extern "C"
