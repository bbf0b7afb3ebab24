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

namespace cyclide::capi {
// The circle parameter f (NULL: m untouched), each field checked and named
// (cyclide_c.cpp).
Outcome circle_parameter_of(const char* fn, const cyc_mobius* f, Mobius& m);
// The P-curve blend's options and bump, each field checked and named
// (options may be named "options.blend" by a caller that embeds them).
Outcome pcurve_blend_inputs(const char* fn, const char* options_name,
                            const cyc_pcurve_blend_options* options,
                            const cyc_directrix_bump* bump, RingedBlendOptions& o);
}  // namespace cyclide::capi

namespace {

// The names of a radius function's arguments: rho_num..., or R_num... of
// cyc_ringed_sqrt_create.
struct RadiusNames {
  const char* num_degree;
  const char* num;
  const char* den_degree;
  const char* den;
};
constexpr RadiusNames kRho = {"rho_num_degree", "rho_num", "rho_den_degree", "rho_den"};
constexpr RadiusNames kR = {"R_num_degree", "R_num", "R_den_degree", "R_den"};

// rho = rho_num / rho_den from power-form coefficient arrays (rho_den NULL:
// 1). The degrees are compared with their bounds before the arrays they
// size are read.
Outcome radius_from(const char* fn, const RadiusNames& names, int num_degree, const double* num,
                    int den_degree, const double* den, CurvePoly& rn, CurvePoly& rd) {
  if (!num) return fail(CYC_E_NULL_ARGUMENT, "%s: %s is NULL", fn, names.num);
  TRY(check_range(fn, names.num_degree, num_degree, 0, kMaxCurveDegree, CYC_E_DEGREE_TOO_HIGH));
  if (den)
    TRY(check_range(fn, names.den_degree, den_degree, 0, kMaxCurveDegree,
                    CYC_E_DEGREE_TOO_HIGH));
  TRY(check_doubles(fn, names.num, num, size_t(num_degree) + 1));
  if (den) TRY(check_doubles(fn, names.den, den, size_t(den_degree) + 1));
  rn.assign(num, num_degree);
  rd = CurvePoly(1.0);
  if (den) rd.assign(den, den_degree);
  if (rd.is_zero())
    return fail(CYC_E_INVALID_ARGUMENT, "%s: %s is the zero polynomial: the radius is undefined",
                fn, names.den);
  return ok();
}

// rho and the circle parameter f (NULL: m untouched) of the creators.
Outcome radius_and_circle(const char* fn, const RadiusNames& names, int num_degree,
                          const double* num, int den_degree, const double* den,
                          const cyc_mobius* f, CurvePoly& rn, CurvePoly& rd, Mobius& m) {
  TRY(radius_from(fn, names, num_degree, num, den_degree, den, rn, rd));
  return circle_parameter_of(fn, f, m);
}

// The message of a failed ringed creation.
Outcome ringed_failure(const char* fn, Status s, double bad_u) {
  if (s == Status::not_pythagorean)
    return fail(int(s), "%s: the unit field f perpendicular to n does not exist in this form: "
                "|n x v| is not a polynomial (Prop. 3.2), or the roots of the sum of squares "
                "(20)-(23) are too ill-conditioned", fn);
  if (s == Status::invalid_argument)
    return fail(int(s), "%s: no unit field perpendicular to n from these inputs: the "
                "projection direction v is 0, which is not 0/1 or beyond the directions found, "
                "QUADRATIC with deg n > 2, n = 0, d or n a line element, or an unknown method",
                fn);
  if (s == Status::degree_too_high)
    return fail(int(s), "%s: the ringed surface's curves exceed degree %d (SOS needs "
                "2 deg n <= 14; c = d + rho f must stay within the curve degree bound)", fn,
                kMaxCurveDegree);
  return located(s) && std::isfinite(bad_u) ? from_core_at(fn, s, bad_u) : from_core(fn, s);
}

// The field options of the (d, n, rho) creators (NULL: defaults).
Outcome field_options(const char* fn, const cyc_ringed_field_options* options,
                      RingedFieldOptions& o) {
  if (!options) return ok();
  TRY(check_range(fn, "options.method", options->method, CYC_RINGED_FIELD_AUTO,
                  CYC_RINGED_FIELD_SOS));
  TRY(check_doubles(fn, "options.v", options->v, 3));
  // which selects one of at most two directions (Example 3.3).
  TRY(check_range(fn, "options.which", options->which, 0, 1));
  o.method = RingedFieldMethod(options->method);
  o.v = vec(options->v);
  o.which = options->which;
  return ok();
}

// The inputs of the (d, n, rho) creators: rho (or R), the circle
// parameter, the field options and the domain.
Outcome dnr_inputs(const char* fn, const RadiusNames& names, int num_degree, const double* num,
                   int den_degree, const double* den, const cyc_mobius* f,
                   const cyc_ringed_field_options* options, double u0, double u1,
                   CurvePoly& rn, CurvePoly& rd, Mobius& m, RingedFieldOptions& o) {
  TRY(radius_and_circle(fn, names, num_degree, num, den_degree, den, f, rn, rd, m));
  TRY(field_options(fn, options, o));
  TRY(check_double(fn, "u0", u0));
  return check_double(fn, "u1", u1);
}

// A jet's six fields, named name.d ... name.drho.
Outcome check_jet(const char* fn, const char* name, const cyc_ringed_jet& J) {
  char field[64];
  const std::pair<const char*, const double*> vectors[] = {
      {"d", J.d}, {"dd", J.dd}, {"n", J.n}, {"dn", J.dn}};
  for (const auto& [f, x] : vectors) {
    std::snprintf(field, sizeof field, "%s.%s", name, f);
    TRY(check_doubles(fn, field, x, 3));
  }
  std::snprintf(field, sizeof field, "%s.rho", name);
  TRY(check_double(fn, field, J.rho));
  std::snprintf(field, sizeof field, "%s.drho", name);
  return check_double(fn, field, J.drho);
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

Outcome capi::pcurve_blend_inputs(const char* fn, const char* options_name,
                                  const cyc_pcurve_blend_options* options,
                                  const cyc_directrix_bump* bump, RingedBlendOptions& o) {
  char field[64];
  if (options) {
    // The branch of (43) / (47) is a sign.
    if (options->sign != 1 && options->sign != -1)
      return fail(CYC_E_INVALID_ARGUMENT, "%s: %s.sign = %d is not +1 or -1", fn, options_name,
                  options->sign);
    std::snprintf(field, sizeof field, "%s.tau", options_name);
    TRY(check_double(fn, field, options->tau));
    std::snprintf(field, sizeof field, "%s.v", options_name);
    TRY(check_doubles(fn, field, options->v, 3));
  }
  if (bump) {
    if (bump->kind != CYC_BUMP_SINGLE && bump->kind != CYC_BUMP_TWO_PIECE)
      return fail(CYC_E_INVALID_ARGUMENT, "%s: bump.kind = %d is neither CYC_BUMP_SINGLE nor "
                  "CYC_BUMP_TWO_PIECE", fn, bump->kind);
    TRY(check_doubles(fn, "bump.w", bump->w, 3));
    TRY(check_double(fn, "bump.tau", bump->tau));
  }
  return pcurve_blend_options_of(fn, options, bump, o);
}

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
    TRY(dnr_inputs(fn, kRho, rho_num_degree, rho_num, rho_den_degree, rho_den, f, options, u0,
                   u1, rn, rd, m, o));
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
    TRY(dnr_inputs(fn, kR, R_num_degree, R_num, R_den_degree, R_den, f, options, u0, u1, rn, rd,
                   m, o));
    if (rn.is_zero())
      return fail(CYC_E_INVALID_ARGUMENT, "%s: R_num is the zero polynomial: rho = sqrt(R) "
                  "vanishes identically", fn);
    Surface S;
    RingedSqrtReport rep;
    double bad_u = NAN;
    if (Status s = make_ringed_sqrt(d->curve, n->curve, rn, rd, o, f ? &m : nullptr, u0, u1, S,
                                    &rep, &bad_u);
        s != Status::ok) {
      if (s == Status::empty_real_locus)
        return fail(int(s), "%s: R = R_num / R_den is negative somewhere on the real line: "
                    "no real rho = sqrt(R) (Theorem 3.6 needs R >= 0)", fn);
      if (s == Status::not_pythagorean)
        return fail(int(s), "%s: no f with n.f = 0 and f.f = R (25): the numerical solution "
                    "of the conic (34)-(35) left a remainder above 1e-8, or the field's "
                    "method does not apply", fn);
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
    // Checked before x is read, in 64 bits: n = (8) has degree 2 x_degree,
    // so x_degree <= CYC_MAX_CURVE_DEGREE / 2.
    TRY(check_range(fn, "x_degree", x_degree, 0, kMaxCurveDegree / 2, CYC_E_DEGREE_TOO_HIGH));
    TRY(check_rows(fn, "x", x, size_t(x_degree) + 1, 4, 4));
    TRY(check_double(fn, "phi", phi));
    CurvePoly rn, rd;
    Mobius m;
    TRY(radius_and_circle(fn, kRho, rho_num_degree, rho_num, rho_den_degree, rho_den, f, rn, rd,
                          m));
    TRY(check_double(fn, "u0", u0));
    TRY(check_double(fn, "u1", u1));
    CurvePoly q[4];
    for (int i = 0; i < 4; ++i) {
      double c[kMaxCurveDegree / 2 + 1];
      for (int k = 0; k <= x_degree; ++k) c[k] = x[4 * k + i];
      q[i].assign(c, x_degree);
    }
    Surface S;
    double bad_u = NAN;
    if (Status s = make_ringed_pcurve(d->curve, q, phi, rn, rd, f ? &m : nullptr, u0, u1, S,
                                      &bad_u);
        s != Status::ok) {
      if (s == Status::invalid_argument)
        return fail(int(s), "%s: the quaternion polynomial x is zero (no P-curve n), or d is "
                    "a line element", fn);
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
    TRY(check_double(fn, "u", u));
    RingedJet J;
    if (Status s = ringed_jet(surface->surface, u, J); s != Status::ok) {
      if (s == Status::singular_point)
        return fail(int(s), "%s: the circle at u = %.17g has radius 0: its axis n is undefined",
                    fn, u);
      return from_core_at(fn, s, u);
    }
    const cyc_ringed_jet C = c_jet_of(J);
    // The jet is an input of the P-curve blends: it must be one there.
    if (check_jet(fn, "jet", C).status)
      return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: the jet at u = %.17g leaves the input range "
                  "|x| <= 1e100 (it could not be passed to a blend)", fn, u);
    *out = C;
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

}  // extern "C"

namespace {

// cyc_blend_ringed_pcurve (bump NULL) and cyc_blend_ringed_pcurve_bump; fn
// names the entry point called.
int pcurve_blend(const char* fn, cyc_context* ctx, const cyc_ringed_jet* a,
                 const cyc_ringed_jet* b, const cyc_pcurve_blend_options* options,
                 const cyc_directrix_bump* bump, cyc_surface** pieces, int* count) {
  return run(ctx, fn, [&] {
    REQUIRE(a);
    REQUIRE(b);
    REQUIRE(pieces);
    REQUIRE(count);
    TRY(check_jet(fn, "a", *a));
    TRY(check_jet(fn, "b", *b));
    RingedBlendOptions o;
    TRY(pcurve_blend_inputs(fn, "options", options, bump, o));
    Surface S[2];
    int n = 0;
    double bad_u = NAN;  // set where a piece's domain scan fails
    if (Status s = make_ringed_pcurve_blend(jet_of(*a), jet_of(*b), o, S, n, &bad_u);
        s != Status::ok) {
      if (s == Status::not_pythagorean) {
        double kappa = 0;
        if (ringed_pcurve_blend_condition(jet_of(*a), jet_of(*b), o, kappa) == Status::ok)
          return fail(int(s), "%s: n is nearly parallel to the projection direction v (at "
                      "an end or inside): the planar P-curve (39) has condition %.3g > 1e5 "
                      "(its circles would carry rounding of ~5 eps times that); choose "
                      "another options.v or options.sign", fn, kappa);
        return fail(int(s), "%s: n is parallel to the projection direction v at an end: the "
                    "projected Hermite data vanish and the planar P-curve (39) has no square "
                    "root there", fn);
      }
      if (s == Status::bad_domain) {
        if (bump && !(o.bump.tau > 0 && o.bump.tau < 1))
          return fail(int(s), "%s: bump.tau = %.17g is not in (0, 1)", fn, o.bump.tau);
        return fail(int(s), "%s: options.tau = %.17g is neither 0 nor in (0, 1)", fn, o.tau);
      }
      if (s == Status::invalid_argument)
        return fail(int(s), "%s: the projection direction options.v is zero, or a two-piece "
                    "bump and a P-biarc split at different tau", fn);
      return located(s) && std::isfinite(bad_u) ? from_core_at(fn, s, bad_u) : from_core(fn, s);
    }
    if (Outcome e = emit_pieces(fn, ctx, S, n, pieces, count); e.status) return e;
    return ok();
  });
}

}  // namespace

extern "C" {

int cyc_blend_ringed_pcurve(cyc_context* ctx, const cyc_ringed_jet* a, const cyc_ringed_jet* b,
                            const cyc_pcurve_blend_options* options, cyc_surface** pieces,
                            int* count) {
  return pcurve_blend("cyc_blend_ringed_pcurve", ctx, a, b, options, nullptr, pieces, count);
}

int cyc_blend_ringed_pcurve_bump(cyc_context* ctx, const cyc_ringed_jet* a,
                                 const cyc_ringed_jet* b, const cyc_pcurve_blend_options* options,
                                 const cyc_directrix_bump* bump, cyc_surface** pieces,
                                 int* count) {
  return pcurve_blend("cyc_blend_ringed_pcurve_bump", ctx, a, b, options, bump, pieces, count);
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
    TRY(check_double(fn, "u", u));
    TRY(check_doubles(fn, "v", v, 3));
    ContourPoints P;
    if (Status s = contour_points(surface->surface, u, vec(v), P); s != Status::ok) {
      if (s == Status::invalid_argument)
        return fail(int(s), "%s: the direction v is zero: no contour (Definition 7.1)", fn);
      if (s == Status::singular_point)
        return fail(int(s), "%s: the circle at u = %.17g has radius 0", fn, u);
      if (s == Status::dependent_planes)
        return fail(int(s), "%s: the circle's axis n is zero at u = %.17g", fn, u);
      return from_core_at(fn, s, u);
    }
    for (int k = 0; k < P.count; ++k)
      if (!P.points[k].allFinite())
        return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: contour point %d at u = %.17g is not finite",
                    fn, k, u);
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
    TRY(radius_from(fn, kRho, rho_num_degree, rho_num, rho_den_degree, rho_den, rn, rd));
    TRY(check_doubles(fn, "v", v, 3));
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
    TRY(check_doubles(fn, "center", center, 3));
    TRY(check_double(fn, "radius", radius));
    if (!(radius >= 0))
      return fail(CYC_E_INVALID_ARGUMENT, "%s: radius = %.17g is negative", fn, radius);
    double c = 0, u = 0;
    if (Status s = sphere_clearance(surface->surface, vec(center), radius, c, &u);
        s != Status::ok)
      return from_core(fn, s);
    if (!std::isfinite(c) || !std::isfinite(u))
      return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: the clearance is not finite (%.17g at u = "
                  "%.17g)", fn, c, u);
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
    if (Status s = normal_deviance(surface->surface, v); s != Status::ok) {
      if (s == Status::singular_point)
        return fail(int(s), "%s: the directrix tangent d' vanishes on the domain: the angle "
                    "of (58) is undefined there", fn);
      return from_core(fn, s);
    }
    if (!std::isfinite(v))
      return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: the integral (58) is not finite", fn);
    *value = v;
    return ok();
  });
}

}  // extern "C"
