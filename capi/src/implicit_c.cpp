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

// The core's blend from the C description (validated by the core).
Outcome blend_of(const char* fn, const cyc_implicit_blend& c, ImplicitBlend& B) {
  Quadric f1, f2;
  PlaneFn g1, g2;
  Status st = make_quadric(c.f1, f1);
  if (st == Status::ok) st = make_quadric(c.f2, f2);
  if (st == Status::ok) st = make_plane_fn(c.f10, g1);
  if (st == Status::ok) st = make_plane_fn(c.f20, g2);
  if (st == Status::ok) st = make_implicit_blend(f1, f2, g1, g2, c.lambda, c.n, B);
  return from_core(fn, st);
}

bool finite(const Vec3d& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }

}  // namespace

extern "C" {

int cyc_implicit_cylinder(cyc_context* ctx, const double point[3], const double direction[3],
                          double radius, double coeffs[10]) {
  const char* fn = "cyc_implicit_cylinder";
  return run(ctx, fn, [&]() -> Outcome {
    REQUIRE(point);
    REQUIRE(direction);
    REQUIRE(coeffs);
    Quadric Q;
    if (Status st = make_cylinder(vec(point), vec(direction), radius, Q); st != Status::ok)
      return from_core(fn, st);
    quadric_coefficients(Q, coeffs);
    return ok();
  });
}

int cyc_implicit_cone(cyc_context* ctx, const double apex[3], const double axis[3],
                      double half_angle, double coeffs[10]) {
  const char* fn = "cyc_implicit_cone";
  return run(ctx, fn, [&]() -> Outcome {
    REQUIRE(apex);
    REQUIRE(axis);
    REQUIRE(coeffs);
    Quadric Q;
    if (Status st = make_cone(vec(apex), vec(axis), half_angle, Q); st != Status::ok)
      return from_core(fn, st);
    quadric_coefficients(Q, coeffs);
    return ok();
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
    const Vec3d X = vec(x);
    if (!input_ok(X)) return fail(CYC_E_NOT_FINITE, "%s: x is not finite", fn);
    Vec3d V = Vec3d::Zero();
    if (v) {
      V = vec(v);
      if (!input_ok(V)) return fail(CYC_E_NOT_FINITE, "%s: v is not finite", fn);
    }
    const BlendJet<double> J = blend_eval(B, X, v ? &V : nullptr);
    const double fv = J.grad.dot(V);
    if (!std::isfinite(J.f) || !finite(J.grad) || !std::isfinite(fv) || !finite(J.hv))
      return fail(CYC_E_NOT_FINITE, "%s: the value overflows at x", fn);
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
    PlaneContourPoints P;
    if (Status st = end_contour_points(B, end, vec(v), P); st != Status::ok)
      return from_core(fn, st);
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
#if CYCLIDE_HAVE_CERES
    ImplicitBlend B;
    if (Outcome e = blend_of(fn, *blend, B); e.status) return e;
    cyc_implicit_approx_options p;
    cyc_implicit_approx_options_init(&p);
    if (options) p = *options;
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
    if (Status st = optim::approximate_implicit_blend(B, V, o, S, n, R); st != Status::ok)
      return from_core(fn, st);
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
    (void)options;
    (void)report;
    return fail(CYC_E_UNSUPPORTED, "%s: this build has no optimizer tier (Ceres)", fn);
#endif
  });
}

}  // extern "C"
