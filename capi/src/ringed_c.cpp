// The C entry points of ringed surfaces (d, n, rho) of seed 001: Hermite
// jets of surfaces and the P-curve blend of §4 (creation tier: it allocates
// the surface handles). cyc_ringed_create is with the other creators in
// cyclide_c.cpp.
#include <cmath>

#include "capi_internal.hpp"
#include "cyclide/contour.hpp"
#include "cyclide/pcurve.hpp"

using namespace cyclide;
using namespace cyclide::capi;

namespace {

// rho = rho_num / rho_den from power-form coefficient arrays (rho_den NULL:
// 1).
Outcome radius_from(const char* fn, int num_degree, const double* num, int den_degree,
                    const double* den, CurvePoly& rn, CurvePoly& rd) {
  REQUIRE(num);
  if (num_degree < 0 || (den && den_degree < 0))
    return fail(CYC_E_INVALID_ARGUMENT, "%s: negative degree of rho", fn);
  if (num_degree > kMaxCurveDegree || (den && den_degree > kMaxCurveDegree))
    return fail(CYC_E_DEGREE_TOO_HIGH, "%s: degree of rho above %d", fn, kMaxCurveDegree);
  for (int k = 0; k <= num_degree; ++k)
    if (!std::isfinite(num[k])) return fail(CYC_E_NOT_FINITE, "%s: rho_num[%d] is not finite", fn, k);
  if (den)
    for (int k = 0; k <= den_degree; ++k)
      if (!std::isfinite(den[k]))
        return fail(CYC_E_NOT_FINITE, "%s: rho_den[%d] is not finite", fn, k);
  rn.assign(num, num_degree);
  rd = CurvePoly(1.0);
  if (den) rd.assign(den, den_degree);
  if (rd.is_zero()) return fail(CYC_E_INVALID_ARGUMENT, "%s: rho_den is zero", fn);
  return ok();
}

// rho and the circle parameter f (NULL: m untouched) of the creators.
Outcome radius_and_circle(const char* fn, int num_degree, const double* num, int den_degree,
                          const double* den, const cyc_mobius* f, CurvePoly& rn, CurvePoly& rd,
                          Mobius& m) {
  if (Outcome o = radius_from(fn, num_degree, num, den_degree, den, rn, rd); o.status) return o;
  return mobius_from(fn, f, m);
}

// The message of a failed ringed creation.
Outcome ringed_failure(const char* fn, Status s, double bad_u) {
  if (s == Status::not_pythagorean)
    return fail(int(s), "%s: %s (|n x v| is not a polynomial, or the SOS roots are too "
                "ill-conditioned)", fn, explain(s));
  if (s == Status::invalid_argument)
    return fail(int(s), "%s: %s (v = 0, which not 0/1 or beyond the directions found, "
                "QUADRATIC for deg n > 2, n = 0, a line element, or an unknown method)",
                fn, explain(s));
  return located(s) && std::isfinite(bad_u) ? from_core_at(fn, s, bad_u) : from_core(fn, s);
}

// The field options of the (d, n, rho) creators (NULL: defaults).
Outcome field_options(const char* fn, const cyc_ringed_field_options* options,
                      RingedFieldOptions& o) {
  if (!options) return ok();
  if (options->method < 0 || options->method > 3)
    return fail(CYC_E_INVALID_ARGUMENT, "%s: unknown method %d", fn, options->method);
  o.method = RingedFieldMethod(options->method);
  o.v = vec(options->v);
  o.which = options->which;
  return ok();
}

// The inputs of the (d, n, rho) creators: rho (or R), the circle
// parameter and the field options.
Outcome dnr_inputs(const char* fn, int num_degree, const double* num, int den_degree,
                   const double* den, const cyc_mobius* f,
                   const cyc_ringed_field_options* options, CurvePoly& rn, CurvePoly& rd,
                   Mobius& m, RingedFieldOptions& o) {
  if (Outcome e = radius_and_circle(fn, num_degree, num, den_degree, den, f, rn, rd, m); e.status)
    return e;
  return field_options(fn, options, o);
}

cyc_ringed_field_report field_report(const RingedFieldReport& rep) {
  cyc_ringed_field_report R;
  R.method = int(rep.method);
  put3(R.v, rep.v);
  R.directions = rep.directions;
  R.sos_residual = rep.sos.residual;
  R.sos_margin = rep.method == RingedFieldMethod::sos ? rep.sos.margin : 0.0;
  return R;
}

}  // namespace

extern "C" {

void cyc_ringed_field_options_init(cyc_ringed_field_options* options) {
  if (!options) return;
  const RingedFieldOptions d;
  options->method = int(d.method);
  put3(options->v, d.v);
  options->which = d.which;
}

int cyc_ringed_dnr_create(cyc_context* ctx, const cyc_curve* d, const cyc_curve* n,
                          int rho_num_degree, const double* rho_num, int rho_den_degree,
                          const double* rho_den, const cyc_ringed_field_options* options,
                          const cyc_mobius* f, double u0, double u1, cyc_surface** out,
                          cyc_ringed_field_report* report) {
  const char* fn = "cyc_ringed_dnr_create";
  return run(ctx, fn, [&] {
    REQUIRE(d);
    REQUIRE(n);
    REQUIRE(out);
    CurvePoly rn, rd;
    Mobius m;
    RingedFieldOptions o;
    if (Outcome e = dnr_inputs(fn, rho_num_degree, rho_num, rho_den_degree, rho_den, f, options,
                               rn, rd, m, o);
        e.status)
      return e;
    Surface S;
    RingedFieldReport rep;
    double bad_u = NAN;
    if (Status s = make_ringed_dnr(d->curve, n->curve, rn, rd, o, f ? &m : nullptr, u0, u1, S,
                                   &rep, &bad_u);
        s != Status::ok)
      return ringed_failure(fn, s, bad_u);
    if (Outcome e = emit(fn, ctx, out, S); e.status) return e;
    if (report) *report = field_report(rep);
    return ok();
  });
}

int cyc_ringed_sqrt_create(cyc_context* ctx, const cyc_curve* d, const cyc_curve* n,
                           int R_num_degree, const double* R_num, int R_den_degree,
                           const double* R_den, const cyc_ringed_field_options* options,
                           const cyc_mobius* f, double u0, double u1, cyc_surface** out,
                           cyc_ringed_sqrt_report* report) {
  const char* fn = "cyc_ringed_sqrt_create";
  return run(ctx, fn, [&] {
    REQUIRE(d);
    REQUIRE(n);
    REQUIRE(out);
    CurvePoly rn, rd;
    Mobius m;
    RingedFieldOptions o;
    if (Outcome e =
            dnr_inputs(fn, R_num_degree, R_num, R_den_degree, R_den, f, options, rn, rd, m, o);
        e.status)
      return e;
    if (rn.is_zero()) return fail(CYC_E_INVALID_ARGUMENT, "%s: R_num is zero", fn);
    Surface S;
    RingedSqrtReport rep;
    double bad_u = NAN;
    if (Status s = make_ringed_sqrt(d->curve, n->curve, rn, rd, o, f ? &m : nullptr, u0, u1, S,
                                    &rep, &bad_u);
        s != Status::ok) {
      if (s == Status::empty_real_locus)
        return fail(int(s), "%s: %s (R = R_num / R_den is negative somewhere on the real line)",
                    fn, explain(s));
      if (s == Status::not_pythagorean)
        return fail(int(s), "%s: %s (the numerical conic step left a remainder above 1e-8, "
                    "or the field's method does not apply)", fn, explain(s));
      return ringed_failure(fn, s, bad_u);
    }
    if (Outcome e = emit(fn, ctx, out, S); e.status) return e;
    if (report) {
      cyc_ringed_sqrt_report R;
      R.field = field_report(rep.field);
      R.exact_square = rep.exact_square ? 1 : 0;
      R.conic_residual = rep.residual;
      R.conic_degree = rep.conic_degree;
      *report = R;
    }
    return ok();
  });
}

int cyc_ringed_pcurve_create(cyc_context* ctx, const cyc_curve* d, int x_degree,
                             const double* x, double phi, int rho_num_degree,
                             const double* rho_num, int rho_den_degree, const double* rho_den,
                             const cyc_mobius* f, double u0, double u1, cyc_surface** out) {
  const char* fn = "cyc_ringed_pcurve_create";
  return run(ctx, fn, [&] {
    REQUIRE(d);
    REQUIRE(x);
    REQUIRE(out);
    if (x_degree < 0) return fail(CYC_E_INVALID_ARGUMENT, "%s: x_degree < 0", fn);
    // Checked before x is read: n = (8) has degree 2 x_degree.
    if (2 * x_degree > kMaxCurveDegree)
      return fail(CYC_E_DEGREE_TOO_HIGH, "%s: x_degree %d: the P-curve's degree %d exceeds %d",
                  fn, x_degree, 2 * x_degree, kMaxCurveDegree);
    CurvePoly rn, rd;
    Mobius m;
    if (Outcome o = radius_and_circle(fn, rho_num_degree, rho_num, rho_den_degree, rho_den, f,
                                      rn, rd, m);
        o.status)
      return o;
    CurvePoly q[4];
    for (int i = 0; i < 4; ++i) {
      double c[kMaxCurveDegree + 1];
      for (int k = 0; k <= x_degree; ++k) c[k] = x[4 * k + i];
      q[i].assign(c, x_degree);
    }
    Surface S;
    double bad_u = NAN;
    if (Status s = make_ringed_pcurve(d->curve, q, phi, rn, rd, f ? &m : nullptr, u0, u1, S,
                                      &bad_u);
        s != Status::ok) {
      if (s == Status::invalid_argument)
        return fail(int(s), "%s: %s (x = 0, or d is a line element)", fn, explain(s));
      return located(s) && std::isfinite(bad_u) ? from_core_at(fn, s, bad_u) : from_core(fn, s);
    }
    return emit(fn, ctx, out, S);
  });
}

int cyc_surface_ringed_jet(cyc_context* ctx, const cyc_surface* surface, double u,
                           cyc_ringed_jet* out) {
  const char* fn = "cyc_surface_ringed_jet";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    REQUIRE(out);
    RingedJet J;
    if (Status s = ringed_jet(surface->surface, u, J); s != Status::ok) return from_core(fn, s);
    *out = c_jet_of(J);
    return ok();
  });
}

void cyc_pcurve_blend_options_init(cyc_pcurve_blend_options* options) {
  if (!options) return;
  const RingedBlendOptions d;
  options->sign = d.sign;
  options->tau = d.tau;
  put3(options->v, d.v);
}

int cyc_blend_ringed_pcurve(cyc_context* ctx, const cyc_ringed_jet* a, const cyc_ringed_jet* b,
                            const cyc_pcurve_blend_options* options, cyc_surface** pieces,
                            int* count) {
  return cyc_blend_ringed_pcurve_bump(ctx, a, b, options, nullptr, pieces, count);
}

int cyc_blend_ringed_pcurve_bump(cyc_context* ctx, const cyc_ringed_jet* a,
                                 const cyc_ringed_jet* b, const cyc_pcurve_blend_options* options,
                                 const cyc_directrix_bump* bump, cyc_surface** pieces,
                                 int* count) {
  const char* fn = bump ? "cyc_blend_ringed_pcurve_bump" : "cyc_blend_ringed_pcurve";
  return run(ctx, fn, [&] {
    REQUIRE(a);
    REQUIRE(b);
    REQUIRE(pieces);
    REQUIRE(count);
    RingedBlendOptions o;
    if (Outcome e = pcurve_blend_options_of(fn, options, bump, o); e.status) return e;
    Surface S[2];
    int n = 0;
    double bad_u = NAN;  // set where a piece's domain scan fails
    if (Status s = make_ringed_pcurve_blend(jet_of(*a), jet_of(*b), o, S, n, &bad_u);
        s != Status::ok) {
      if (s == Status::not_pythagorean)
        return fail(int(s), "%s: %s (n is parallel to v at an end)", fn, explain(s));
      if (s == Status::bad_domain)
        return fail(int(s), "%s: tau = %.17g is neither 0 nor in (0, 1)", fn, o.tau);
      if (s == Status::invalid_argument)
        return fail(int(s), "%s: the projection direction v is zero, or a two-piece bump "
                    "and a P-biarc split at different tau", fn);
      return located(s) && std::isfinite(bad_u) ? from_core_at(fn, s, bad_u) : from_core(fn, s);
    }
    if (Outcome e = emit_pieces(fn, ctx, S, n, pieces, count); e.status) return e;
    return ok();
  });
}

int cyc_surface_contour_points(cyc_context* ctx, const cyc_surface* surface, double u,
                               const double v[3], double* points, size_t capacity, int* count,
                               int* whole_circle) {
  const char* fn = "cyc_surface_contour_points";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    REQUIRE(v);
    REQUIRE(points);
    REQUIRE(count);
    REQUIRE(whole_circle);
    if (capacity < 12)
      return fail(CYC_E_BUFFER_TOO_SMALL, "%s: capacity %zu < 12 doubles", fn, capacity);
    ContourPoints P;
    if (Status s = contour_points(surface->surface, u, vec(v), P); s != Status::ok) {
      if (s == Status::invalid_argument) return fail(int(s), "%s: v is zero", fn);
      return from_core(fn, s);
    }
    for (int k = 0; k < P.count; ++k) put3(points + 3 * k, P.points[k]);
    *count = P.count;
    *whole_circle = P.whole_circle ? 1 : 0;
    return ok();
  });
}

int cyc_ringed_contour_curves(cyc_context* ctx, const cyc_curve* d, const cyc_curve* n,
                              int rho_num_degree, const double* rho_num, int rho_den_degree,
                              const double* rho_den, const double v[3], cyc_curve** plus,
                              cyc_curve** minus) {
  const char* fn = "cyc_ringed_contour_curves";
  return run(ctx, fn, [&] {
    REQUIRE(d);
    REQUIRE(n);
    REQUIRE(v);
    REQUIRE(plus);
    REQUIRE(minus);
    CurvePoly rn, rd;
    if (Outcome o = radius_from(fn, rho_num_degree, rho_num, rho_den_degree, rho_den, rn, rd);
        o.status)
      return o;
    RationalCurve P, M;
    if (Status s = contour_curves_71(d->curve, n->curve, rn, rd, vec(v), P, M); s != Status::ok) {
      if (s == Status::invalid_argument)
        return fail(int(s), "%s: n.v is not identically 0 (eq. 71), v = 0, or n is not a curve",
                    fn);
      if (s == Status::not_pythagorean)
        return fail(int(s), "%s: |n| is not a polynomial: no rational contour curve (Prop. 7.2)",
                    fn);
      return from_core(fn, s);
    }
    cyc_curve* h[2] = {nullptr, nullptr};
    if (Outcome e = emit(fn, ctx, &h[0], P); e.status) return e;
    if (Outcome e = emit(fn, ctx, &h[1], M); e.status) {
      cyc_curve_destroy(ctx, h[0]);
      return e;
    }
    *plus = h[0];
    *minus = h[1];
    return ok();
  });
}

int cyc_surface_sphere_clearance(cyc_context* ctx, const cyc_surface* surface,
                                 const double center[3], double radius, double* clearance,
                                 double* at_u) {
  const char* fn = "cyc_surface_sphere_clearance";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    REQUIRE(center);
    REQUIRE(clearance);
    double c = 0, u = 0;
    if (Status s = sphere_clearance(surface->surface, vec(center), radius, c, &u);
        s != Status::ok) {
      if (s == Status::invalid_argument) return fail(int(s), "%s: radius < 0", fn);
      return from_core(fn, s);
    }
    *clearance = c;
    if (at_u) *at_u = u;
    return ok();
  });
}

int cyc_surface_normal_deviance(cyc_context* ctx, const cyc_surface* surface, double* value) {
  const char* fn = "cyc_surface_normal_deviance";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    REQUIRE(value);
    double v = 0;
    if (Status s = normal_deviance(surface->surface, v); s != Status::ok) return from_core(fn, s);
    *value = v;
    return ok();
  });
}

}  // extern "C"
