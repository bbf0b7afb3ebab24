// The C entry points of seed 002's sphere skins (SPEC.md §9): ends from an
// apex or a sphere, skins and chains of skins (creation tier: they allocate
// the handle and its patches), evaluation, grids, twist, lambda and the
// patches' info (allocation-free).
#include "capi_internal.hpp"
#include "cyclide/curve.hpp"
#include "cyclide/skin_export.hpp"
#include "cyclide/sphere_skin.hpp"

#ifndef CYCLIDE_HAVE_CERES
#define CYCLIDE_HAVE_CERES 0
#endif
#if CYCLIDE_HAVE_CERES
#include "optim/skin_optimizer.hpp"
#endif

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>

using namespace cyclide;
using namespace cyclide::capi;

static_assert(CYC_SKIN_RMF == int(SkinPairing::rmf) &&
                  CYC_SKIN_KUNKLI_HOFFMANN == int(SkinPairing::kunkli_hoffmann) &&
                  CYC_SKIN_CROSS_TANGENTS == int(SkinPairing::cross_tangents),
              "skin pairings");
static_assert(CYC_RMF_REFERENCE == int(RmfMethod::reference) &&
                  CYC_RMF_DOUBLE_REFLECTION == int(RmfMethod::double_reflection),
              "RMF methods");

// struct cyc_sphere_skin is in capi_internal.hpp (skin export and tessellation use it).

namespace {

inline SkinEnd end_of(const cyc_skin_end& e) {
  SkinEnd s;
  s.center = vec(e.center);
  s.radius = e.radius;
  s.tangent = vec(e.tangent);
  s.inv_c = e.inv_c;
  return s;
}

inline cyc_skin_end c_end_of(const SkinEnd& s) {
  cyc_skin_end e;
  put3(e.center, s.center);
  e.radius = s.radius;
  put3(e.tangent, s.tangent);
  e.inv_c = s.inv_c;
  return e;
}

// The handle and its patch array, or NULL (out of memory).
cyc_sphere_skin* allocate_skin(const cyc_allocator& a, int count) {
  cyc_sphere_skin* h = allocate<cyc_sphere_skin>(a);
  if (!h) return nullptr;
  void* mem = a.alloc(a.userdata, sizeof(SphereSkin) * size_t(count), alignof(SphereSkin));
  if (!mem) {
    release(h);
    return nullptr;
  }
  h->patches = static_cast<SphereSkin*>(mem);
  for (int k = 0; k < count; ++k) new (h->patches + k) SphereSkin();
  h->count = count;
  return h;
}

void destroy_skin(cyc_sphere_skin* h) {
  if (!h) return;
  if (h->patches) {
    for (int k = 0; k < h->count; ++k) h->patches[k].~SphereSkin();
    h->allocator.free(h->allocator.userdata, h->patches);
  }
  release(h);
}

// A skin end (cyc_skin_end), every field named: name.center[i], ...
Outcome check_end(const char* fn, const char* name, const cyc_skin_end& e) {
  char field[64];
  std::snprintf(field, sizeof field, "%s.center", name);
  TRY(check_doubles(fn, field, e.center, 3));
  std::snprintf(field, sizeof field, "%s.radius", name);
  TRY(check_double(fn, field, e.radius));
  std::snprintf(field, sizeof field, "%s.tangent", name);
  TRY(check_doubles(fn, field, e.tangent, 3));
  std::snprintf(field, sizeof field, "%s.inv_c", name);
  return check_double(fn, field, e.inv_c);
}

// The skin options (name: the argument, "options" or "skin"); NULL: the
// defaults.
Outcome options_of(const char* fn, const char* name, const cyc_skin_options* o,
                   SkinOptions& out) {
  out = SkinOptions{};
  if (!o) return ok();
  char field[64];
  std::snprintf(field, sizeof field, "%s.tolerance", name);
  TRY(check_double(fn, field, o->tolerance));
  std::snprintf(field, sizeof field, "%s.reference", name);
  TRY(check_doubles(fn, field, o->reference, 3));
  std::snprintf(field, sizeof field, "%s.e", name);
  TRY(check_doubles(fn, field, o->e, 3));
  if (o->pairing != CYC_SKIN_RMF && o->pairing != CYC_SKIN_KUNKLI_HOFFMANN &&
      o->pairing != CYC_SKIN_CROSS_TANGENTS)
    return fail(CYC_E_INVALID_ARGUMENT,
                "%s: %s.pairing = %d is not CYC_SKIN_RMF (0), CYC_SKIN_KUNKLI_HOFFMANN (1) "
                "or CYC_SKIN_CROSS_TANGENTS (2)",
                fn, name, o->pairing);
  if (o->method != CYC_RMF_REFERENCE && o->method != CYC_RMF_DOUBLE_REFLECTION)
    return fail(CYC_E_INVALID_ARGUMENT,
                "%s: %s.method = %d is not CYC_RMF_REFERENCE (0) or "
                "CYC_RMF_DOUBLE_REFLECTION (1)",
                fn, name, o->method);
  out.pairing = SkinPairing(o->pairing);
  out.method = RmfMethod(o->method);
  out.tolerance = o->tolerance;
  out.reference = vec(o->reference);
  out.e = vec(o->e);
  return ok();
}

// A message for a failed skin from start to end (where: "" or "patch k: ";
// chained: a later patch of a chain, whose start direction is given).
Outcome skin_failure(const char* fn, const char* where, Status s, const SkinEnd& a,
                     const SkinEnd& b, const SkinOptions& o, bool chained = false) {
  const int st = int(s);
  const SkinEnd* ends[2] = {&a, &b};
  const char* names[2] = {"start", "end"};
  switch (s) {
    case Status::not_finite:
      return fail(st, "%s: %san end or option is NaN, infinite or larger than 1e100", fn, where);
    case Status::invalid_argument:
      for (int e = 0; e < 2; ++e)
        if (!(ends[e]->radius > 0))
          return fail(st, "%s: %sthe %s circle's radius %.17g is not positive", fn, where,
                      names[e], ends[e]->radius);
      if (!(o.tolerance > 0))
        return fail(st, "%s: %soptions.tolerance = %.17g is not positive", fn, where,
                    o.tolerance);
      if (o.pairing == SkinPairing::kunkli_hoffmann ||
          (o.pairing == SkinPairing::rmf && !chained && o.reference.squaredNorm() == 0))
        return fail(st,
                    "%s: %sthe Kunkli-Hoffmann direction e x t is undefined (options.e is "
                    "parallel to a tangent)",
                    fn, where);
      return fail(st,
                  "%s: %sthe start direction is parallel to the start tangent (options."
                  "reference, or the previous patch's end direction)",
                  fn, where);
    case Status::zero_tangent:
      for (int e = 0; e < 2; ++e)
        if (!(ends[e]->tangent.norm() > 0))
          return fail(st, "%s: %sthe %s tangent is zero", fn, where, names[e]);
      return fail(st,
                  "%s: %sthe spine's tangent alpha' (nearly) vanishes on [0, 1] (the cubic "
                  "Hermite spine of the two centers and tangents doubles back)",
                  fn, where);
    case Status::parallel_lines:
      return fail(st,
                  "%s: %scross-tangent pairing: the tangents are parallel (t_i x t_f = 0); use "
                  "another pairing",
                  fn, where);
    case Status::nested_spheres: {
      Vec3d m[2];
      double R[2];
      skin_end_sphere(a, m[0], R[0]);
      skin_end_sphere(b, m[1], R[1]);
      return fail(st,
                  "%s: %sthe spheres are nested or equal: start sphere center (%.17g, %.17g, "
                  "%.17g) radius %.17g, end sphere center (%.17g, %.17g, %.17g) radius %.17g "
                  "(|m_i - m_f| = %.17g <= |R_i - R_f| = %.17g)",
                  fn, where, m[0].x(), m[0].y(), m[0].z(), R[0], m[1].x(), m[1].y(), m[1].z(),
                  R[1], (m[0] - m[1]).norm(), std::abs(R[0] - R[1]));
    }
    case Status::curvature_radius_too_large: {
      const SkinSpine sp = make_skin_spine(a, b);
      const double kr[2] = {skin_spine_curvature(sp, 0.0) * a.radius,
                            skin_spine_curvature(sp, 1.0) * b.radius};
      const int e = kr[0] < 1.0 - 1e-12 ? 1 : 0;
      return fail(st,
                  "%s: %skappa r = %.17g >= 1 at the %s (t = %d): kappa is the spine's "
                  "curvature there, r the circle's radius; the skin would fold (seed 002 "
                  "Remark 2). Longer tangents or a smaller circle help",
                  fn, where, kr[e], names[e], e);
    }
    case Status::numerical_overflow: {
      const SkinSpine sp = make_skin_spine(a, b);
      for (const Vec3d& c : sp.c)
        if (!input_ok(c))
          return fail(st,
                      "%s: %sthe spine's power-form coefficients leave the range (3 (p_f - p_i) "
                      "- 2 t_i - t_f etc. beyond 1e100)",
                      fn, where);
      for (int e = 0; e < 2; ++e) {
        Vec3d m;
        double R;
        skin_end_sphere(*ends[e], m, R);
        if (!input_ok(m) || !input_ok(R))
          return fail(st, "%s: %sthe %s end's sphere leaves the range (beyond 1e100)", fn, where,
                      names[e]);
      }
      return fail(st,
                  "%s: %sthe RMF tolerance %.3g is not met with %d steps per table interval, "
                  "or values overflow",
                  fn, where, o.tolerance, kRmfMaxSubsteps);
    }
    default:
      return fail(st, "%s: %s%s", fn, where, explain(s));
  }
}

// The patch of a handle, or a reason why not.
Outcome patch_of(const char* fn, const cyc_sphere_skin* skin, int patch, const SphereSkin*& S) {
  if (patch < 0 || patch >= skin->count)
    return fail(CYC_E_INVALID_ARGUMENT, "%s: patch = %d is outside 0..%d", fn, patch,
                skin->count - 1);
  S = &skin->patches[patch];
  return ok();
}

Outcome check_params(const char* fn, double theta, double t) {
  TRY(check_double(fn, "theta", theta));
  TRY(check_double(fn, "t", t));
  if (!(t >= 0.0 && t <= 1.0))
    return fail(CYC_E_BAD_DOMAIN, "%s: t = %.17g is outside [0, 1]", fn, t);
  return ok();
}

Outcome eval_failure(const char* fn, Status s, double theta, double t) {
  switch (s) {
    case Status::singular_point:
      return fail(int(s),
                  "%s: the normal is undefined at theta = %.17g, t = %.17g (s_theta x s_t = 0, "
                  "or beyond the range)",
                  fn, theta, t);
    case Status::numerical_overflow:
      return fail(int(s), "%s: values overflow at theta = %.17g, t = %.17g", fn, theta, t);
    default:
      return from_core(fn, s);
  }
}

}  // namespace

extern "C" {

int cyc_skin_end_from_apex(cyc_context* ctx, const double center[3], double radius,
                           const double tangent[3], const double apex[3], cyc_skin_end* out) {
  const char* fn = "cyc_skin_end_from_apex";
  return run(ctx, fn, [&] {
    REQUIRE(center);
    REQUIRE(tangent);
    REQUIRE(apex);
    REQUIRE(out);
    TRY(check_doubles(fn, "center", center, 3));
    TRY(check_double(fn, "radius", radius));
    TRY(check_doubles(fn, "tangent", tangent, 3));
    TRY(check_doubles(fn, "apex", apex, 3));
    SkinEnd e;
    const Status s = skin_end_from_apex(vec(center), radius, vec(tangent), vec(apex), e);
    if (s == Status::invalid_argument) {
      if (!(radius > 0))
        return fail(int(s), "%s: radius = %.17g is not positive", fn, radius);
      return fail(int(s),
                  "%s: the apex is off the axis through center along tangent (by more than "
                  "1e-9 relative) or equals center",
                  fn);
    }
    if (s == Status::zero_tangent) return fail(int(s), "%s: tangent is zero", fn);
    if (s != Status::ok) return from_core(fn, s);
    *out = c_end_of(e);
    return ok();
  });
}

int cyc_skin_end_from_sphere(cyc_context* ctx, const double sphere_center[3],
                             double sphere_radius, const double center[3],
                             const double tangent[3], cyc_skin_end* out) {
  const char* fn = "cyc_skin_end_from_sphere";
  return run(ctx, fn, [&] {
    REQUIRE(sphere_center);
    REQUIRE(center);
    REQUIRE(tangent);
    REQUIRE(out);
    TRY(check_doubles(fn, "sphere_center", sphere_center, 3));
    TRY(check_double(fn, "sphere_radius", sphere_radius));
    TRY(check_doubles(fn, "center", center, 3));
    TRY(check_doubles(fn, "tangent", tangent, 3));
    SkinEnd e;
    const Status s =
        skin_end_from_sphere(vec(sphere_center), sphere_radius, vec(center), vec(tangent), e);
    if (s == Status::invalid_argument) {
      if (!(sphere_radius > 0))
        return fail(int(s), "%s: sphere_radius = %.17g is not positive", fn, sphere_radius);
      return fail(int(s),
                  "%s: center is off the sphere's axis along tangent (by more than 1e-9 "
                  "relative), or the circle's plane misses the sphere",
                  fn);
    }
    if (s == Status::zero_tangent) return fail(int(s), "%s: tangent is zero", fn);
    if (s != Status::ok) return from_core(fn, s);
    *out = c_end_of(e);
    return ok();
  });
}

void cyc_skin_end_sphere(const cyc_skin_end* end, double center[3], double* radius) {
  if (!end) return;
  Vec3d m;
  double R;
  skin_end_sphere(end_of(*end), m, R);
  if (center) put3(center, m);
  if (radius) *radius = R;
}

void cyc_skin_options_init(cyc_skin_options* options) {
  if (!options) return;
  const SkinOptions d;
  options->pairing = int(d.pairing);
  options->method = int(d.method);
  options->tolerance = d.tolerance;
  put3(options->reference, d.reference);
  put3(options->e, d.e);
}

int cyc_sphere_skin_create(cyc_context* ctx, const cyc_skin_end* start, const cyc_skin_end* end,
                           const cyc_skin_options* options, cyc_sphere_skin** out) {
  const char* fn = "cyc_sphere_skin_create";
  return run(ctx, fn, [&] {
    REQUIRE(start);
    REQUIRE(end);
    REQUIRE(out);
    TRY(check_end(fn, "start", *start));
    TRY(check_end(fn, "end", *end));
    SkinOptions o;
    TRY(options_of(fn, "options", options, o));
    cyc_sphere_skin* h = allocate_skin(ctx->allocator, 1);
    if (!h) return fail(CYC_E_OUT_OF_MEMORY, "%s: allocator returned NULL", fn);
    const SkinEnd a = end_of(*start), b = end_of(*end);
    if (Status s = make_sphere_skin(a, b, o, h->patches[0]); s != Status::ok) {
      destroy_skin(h);
      return skin_failure(fn, "", s, a, b, o);
    }
    *out = h;
    return ok();
  });
}

int cyc_sphere_skin_chain_create(cyc_context* ctx, const cyc_skin_end* ends, int n,
                                 const cyc_skin_options* options, cyc_sphere_skin** out,
                                 int* bad_patch) {
  const char* fn = "cyc_sphere_skin_chain_create";
  return run(ctx, fn, [&] {
    REQUIRE(ends);
    REQUIRE(out);
    if (n < 2) return fail(CYC_E_INVALID_ARGUMENT, "%s: n = %d ends; a chain needs n >= 2", fn, n);
    for (int i = 0; i < n; ++i) {
      char name[32];
      std::snprintf(name, sizeof name, "ends[%d]", i);
      TRY(check_end(fn, name, ends[i]));
    }
    SkinOptions o;
    TRY(options_of(fn, "options", options, o));
    cyc_sphere_skin* h = allocate_skin(ctx->allocator, n - 1);
    if (!h) return fail(CYC_E_OUT_OF_MEMORY, "%s: allocator returned NULL (%d patches)", fn, n - 1);
    // The core converts the ends itself: they are read in place.
    SkinEnd* converted = static_cast<SkinEnd*>(
        ctx->allocator.alloc(ctx->allocator.userdata, sizeof(SkinEnd) * size_t(n),
                             alignof(SkinEnd)));
    if (!converted) {
      destroy_skin(h);
      return fail(CYC_E_OUT_OF_MEMORY, "%s: allocator returned NULL (%d ends)", fn, n);
    }
    for (int i = 0; i < n; ++i) new (converted + i) SkinEnd(end_of(ends[i]));
    int bad = 0;
    const Status s = make_sphere_skin_chain(converted, n, o, h->patches, &bad);
    Outcome r = ok();
    if (s != Status::ok) {
      char where[32];
      std::snprintf(where, sizeof where, "patch %d: ", bad);
      const int k = std::min(std::max(bad, 0), n - 2);
      r = skin_failure(fn, where, s, converted[k], converted[k + 1], o, k > 0);
    }
    ctx->allocator.free(ctx->allocator.userdata, converted);
    if (s != Status::ok) {
      destroy_skin(h);
      if (bad_patch) *bad_patch = bad;
      return r;
    }
    *out = h;
    return ok();
  });
}

void cyc_sphere_skin_destroy(cyc_context*, cyc_sphere_skin* skin) { destroy_skin(skin); }

int cyc_sphere_skin_patch_count(cyc_context* ctx, const cyc_sphere_skin* skin, int* count) {
  const char* fn = "cyc_sphere_skin_patch_count";
  return run(ctx, fn, [&] {
    REQUIRE(skin);
    REQUIRE(count);
    *count = skin->count;
    return ok();
  });
}

int cyc_sphere_skin_eval(cyc_context* ctx, const cyc_sphere_skin* skin, int patch, double theta,
                         double t, double x[3], double x_theta[3], double x_t[3],
                         double normal[3]) {
  const char* fn = "cyc_sphere_skin_eval";
  return run(ctx, fn, [&] {
    REQUIRE(skin);
    const SphereSkin* S = nullptr;
    if (Outcome r = patch_of(fn, skin, patch, S); r.status) return r;
    if (Outcome r = check_params(fn, theta, t); r.status) return r;
    // The core writes every output or none.
    if (Status s = skin_eval(*S, theta, t, x, x_theta, x_t, normal); s != Status::ok)
      return eval_failure(fn, s, theta, t);
    return ok();
  });
}

int cyc_sphere_skin_eval_grid(cyc_context* ctx, const cyc_sphere_skin* skin, int patch,
                              const double* theta, int ntheta, const double* t, int nt,
                              double* points, double* normals, size_t* singular) {
  const char* fn = "cyc_sphere_skin_eval_grid";
  return run(ctx, fn, [&] {
    REQUIRE(skin);
    REQUIRE(theta);
    REQUIRE(t);
    const SphereSkin* S = nullptr;
    if (Outcome r = patch_of(fn, skin, patch, S); r.status) return r;
    TRY(check_range(fn, "ntheta", ntheta, 0, INT32_MAX));
    TRY(check_range(fn, "nt", nt, 0, INT32_MAX));
    TRY(check_doubles(fn, "theta", theta, size_t(ntheta)));
    TRY(check_doubles(fn, "t", t, size_t(nt)));
    for (int j = 0; j < nt; ++j) {
      if (!(t[j] >= 0.0 && t[j] <= 1.0))
        return fail(CYC_E_BAD_DOMAIN, "%s: t[%d] = %.17g is outside [0, 1]", fn, j, t[j]);
    }
    std::size_t count = 0;
    if (Status s = skin_eval_grid(*S, theta, ntheta, t, nt, points, normals, &count);
        s != Status::ok)
      return from_core(fn, s);
    if (singular) *singular = count;
    return ok();
  });
}

int cyc_sphere_skin_info_get(cyc_context* ctx, const cyc_sphere_skin* skin, int patch,
                             cyc_sphere_skin_info* out) {
  const char* fn = "cyc_sphere_skin_info_get";
  return run(ctx, fn, [&] {
    REQUIRE(skin);
    REQUIRE(out);
    const SphereSkin* S = nullptr;
    if (Outcome r = patch_of(fn, skin, patch, S); r.status) return r;
    cyc_sphere_skin_info I;
    std::memset(&I, 0, sizeof I);
    I.kappa[0] = S->kappa[0];
    I.kappa[1] = S->kappa[1];
    I.delta = S->delta;
    I.rmf_substeps = S->rmf.substeps;
    I.rmf_error_estimate = S->rmf.error_estimate;
    for (int k = 0; k < 4; ++k) put3(I.spine[k], S->spine.c[k]);
    I.pairing = int(S->pairing);
    I.method = int(S->rmf.method);
    *out = I;
    return ok();
  });
}

int cyc_sphere_skin_twist(cyc_context* ctx, const cyc_sphere_skin* skin, int patch, double theta,
                          double* twist) {
  const char* fn = "cyc_sphere_skin_twist";
  return run(ctx, fn, [&] {
    REQUIRE(skin);
    REQUIRE(twist);
    const SphereSkin* S = nullptr;
    if (Outcome r = patch_of(fn, skin, patch, S); r.status) return r;
    TRY(check_double(fn, "theta", theta));
    double w = 0;
    if (Status s = skin_twist(*S, theta, w); s != Status::ok) {
      if (s == Status::singular_point)
        return fail(int(s), "%s: the curve theta = %.17g meets the spine", fn, theta);
      return from_core(fn, s);
    }
    *twist = w;
    return ok();
  });
}

int cyc_sphere_skin_lambda(cyc_context* ctx, const cyc_sphere_skin* skin, int patch, double theta,
                           double t, double* lambda, double a[2]) {
  const char* fn = "cyc_sphere_skin_lambda";
  return run(ctx, fn, [&] {
    REQUIRE(skin);
    REQUIRE(lambda);
    const SphereSkin* S = nullptr;
    if (Outcome r = patch_of(fn, skin, patch, S); r.status) return r;
    if (Outcome r = check_params(fn, theta, t); r.status) return r;
    double ends[2];
    const double l = skin_lambda(*S, theta, t, ends);
    if (!input_ok(l) || !input_ok(ends[0]) || !input_ok(ends[1]))
      return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: values overflow at theta = %.17g, t = %.17g",
                  fn, theta, t);
    *lambda = l;
    if (a) a[0] = ends[0], a[1] = ends[1];
    return ok();
  });
}

// ------------------------------------------------------------ export (§8j.1b)

void cyc_skin_export_options_default(cyc_skin_export_options* options) {
  if (!options) return;
  const SkinExportOptions o;
  options->tolerance = o.tolerance;
  options->degree = o.degree;
}

int cyc_sphere_skin_export_create(cyc_context* ctx, const cyc_sphere_skin* skin,
                                  const cyc_export_domain* domain,
                                  const cyc_skin_export_options* options, cyc_bezier_export** out,
                                  cyc_skin_export_report* report) {
  const char* fn = "cyc_sphere_skin_export_create";
  return run(ctx, fn, [&] {
    REQUIRE(skin);
    REQUIRE(domain);
    REQUIRE(out);
    SkinExportOptions o;
    if (options) {
      o.tolerance = options->tolerance;
      o.degree = options->degree;
    }
    TRY(check_double(fn, "options.tolerance", o.tolerance));
    if (!(o.tolerance > 0.0))
      return fail(CYC_E_INVALID_ARGUMENT,
                  "%s: options.tolerance = %.17g is not positive (a distance in model units)",
                  fn, o.tolerance);
    TRY(check_range(fn, "options.degree", o.degree, 1, kMaxSkinExportDegree));
    TRY(check_double(fn, "domain.u0", domain->u0));
    TRY(check_double(fn, "domain.u1", domain->u1));
    if (!domain->whole_circle) {
      TRY(check_double(fn, "domain.v0", domain->v0));
      TRY(check_double(fn, "domain.v1", domain->v1));
    }
    const ExportDomain D =
        domain->whole_circle
            ? ExportDomain::circles(domain->u0, domain->u1)
            : ExportDomain::rectangle(domain->u0, domain->u1, domain->v0, domain->v1);
    int count = 0;
    const Status s = export_sphere_skin(skin->patches, skin->count, D, o, nullptr, 0, count);
    if (s == Status::bad_domain)
      return fail(CYC_E_BAD_DOMAIN,
                  "%s: [%.17g, %.17g] x [%.17g, %.17g] is empty or u leaves [0, %d] (u = patch + "
                  "t, v = tan(theta / 2))",
                  fn, D.u0, D.u1, D.v0, D.v1, skin->count);
    if (s == Status::numerical_overflow)
      return fail(CYC_E_NUMERICAL_OVERFLOW,
                  "%s: tolerance %.3g cannot be met (below the skin's rounding, or more than %d "
                  "t-intervals)",
                  fn, o.tolerance, kMaxExportUPieces);
    if (s != Status::buffer_too_small) return from_core(fn, s);
    if (count > CYC_MAX_EXPORT_PATCHES)
      return fail(CYC_E_INVALID_ARGUMENT,
                  "%s: %d patches, more than CYC_MAX_EXPORT_PATCHES = %d; export smaller "
                  "rectangles or raise the tolerance",
                  fn, count, CYC_MAX_EXPORT_PATCHES);
    const cyc_allocator a = ctx->allocator;
    cyc_bezier_export* E = allocate_export(a, count);
    if (!E) return fail(CYC_E_OUT_OF_MEMORY, "%s: allocator returned NULL", fn);
    int written = 0;
    SkinExportReport r;
    const Status w = export_sphere_skin(skin->patches, skin->count, D, o, E->patches, count,
                                        written, &r);
    if (w != Status::ok || written != count) {
      a.free(a.userdata, E);
      return w == Status::ok ? fail(CYC_E_INTERNAL, "%s: patch count changed", fn)
                             : from_core(fn, w);
    }
    if (report) {
      report->error_estimate = r.error_estimate;
      report->rmf_error = r.rmf_error;
      report->exact = r.exact ? 1 : 0;
      report->t_intervals = r.t_intervals;
    }
    *out = E;
    return ok();
  });
}

void cyc_skin_tangent_options_init(cyc_skin_tangent_options* options) {
  if (!options) return;
  std::memset(options, 0, sizeof *options);
  options->target = 0.9;
  options->min_ratio = 1.0 / 16;
  options->max_ratio = 16.0;
  options->max_iterations = 100;
}

int cyc_optimize_skin_tangents(cyc_context* ctx, const cyc_skin_end* start,
                               const cyc_skin_end* end, const cyc_skin_options* skin,
                               const cyc_skin_tangent_options* options, cyc_skin_end* start_out,
                               cyc_skin_end* end_out, cyc_skin_tangent_summary* summary) {
  const char* fn = "cyc_optimize_skin_tangents";
  return run(ctx, fn, [&]() -> Outcome {
    REQUIRE(start);
    REQUIRE(end);
    REQUIRE(start_out);
    REQUIRE(end_out);
#if CYCLIDE_HAVE_CERES
    TRY(check_end(fn, "start", *start));
    TRY(check_end(fn, "end", *end));
    SkinOptions o;
    TRY(options_of(fn, "skin", skin, o));
    cyc_skin_tangent_options p;
    cyc_skin_tangent_options_init(&p);
    if (options) p = *options;
    TRY(check_double(fn, "options.target", p.target));
    TRY(check_double(fn, "options.min_ratio", p.min_ratio));
    TRY(check_double(fn, "options.max_ratio", p.max_ratio));
    if (!(p.target > 0 && p.target < 1) || !(p.min_ratio > 0 && p.min_ratio <= 1) ||
        !(p.max_ratio >= 1) || p.max_iterations < 0)
      return fail(CYC_E_INVALID_ARGUMENT,
                  "%s: options: target %.17g must be in (0, 1), 0 < min_ratio %.17g <= 1 <= "
                  "max_ratio %.17g, max_iterations %d >= 0",
                  fn, p.target, p.min_ratio, p.max_ratio, p.max_iterations);
    optim::SkinTangentOptions P;
    P.target = p.target;
    P.min_ratio = p.min_ratio;
    P.max_ratio = p.max_ratio;
    P.max_iterations = p.max_iterations;
    const SkinEnd a = end_of(*start), b = end_of(*end);
    SkinEnd s, e;
    optim::SkinTangentSummary R;
    if (Status st = optim::optimize_skin_tangents(a, b, o, P, s, e, R); st != Status::ok) {
      if (st == Status::curvature_radius_too_large && R.iterations == 0)
        return skin_failure(fn, "no tangent lengths in [min_ratio, max_ratio] help: ", st, a, b,
                            o);
      return skin_failure(fn, "", st, a, b, o);
    }
    *start_out = c_end_of(s);
    *end_out = c_end_of(e);
    if (summary) {
      cyc_skin_tangent_summary m;
      std::memset(&m, 0, sizeof m);
      for (int i = 0; i < 2; ++i) {
        m.scale[i] = R.scale[i];
        m.kappa_r_initial[i] = R.kappa_r_initial[i];
        m.kappa_r[i] = R.kappa_r[i];
      }
      m.iterations = R.iterations;
      *summary = m;
    }
    return ok();
#else
    (void)skin; (void)options; (void)summary;
    return fail(CYC_E_UNSUPPORTED, "%s: this build has no optimizer tier (Ceres)", fn);
#endif
  });
}

}  // extern "C"
