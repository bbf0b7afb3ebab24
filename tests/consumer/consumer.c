/* A user of the installed library, built three ways by tests/ffi/c.cmake
 * (find_package, add_subdirectory, pkg-config): only <cyclide/cyclide.h>
 * and libcyclide.so, nothing of the source tree.
 *
 * 1. The header and the library linked agree (version, ABI version).
 * 2. Example 2 of seed 000: a PRCS through two lines, x(1/4, 1) by (23).
 * 3. The G^1 canal blend (K = 2) of the two cones of Fig. 6 (seed 000 §9):
 *    cone A (apex 0, axis z) and cone B (apex (4,0,4), axis -x), each a PRRS
 *    through three lines of the cone, u in [0.5, 1], blended between their
 *    circles at u = 1. On a 9 x 8 grid (cyc_surface_eval_grid, checked
 *    against cyc_surface_eval) every point lies on the sphere touching the
 *    canal surface along its circle, the normal is the unit (x - s) / r and
 *    is perpendicular to x_t and x_v; at t = 0 and t = 1 the blend's points
 *    lie on the cones' end circles and its normals are perpendicular to the
 *    cones' rulings (the cones' tangent planes: G^1); cyc_continuity_report
 *    agrees. Exit status 0 only if every check holds. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <cyclide/cyclide.h>

static int failures = 0;

static void check(int ok, const char* what, double value) {
  if (!ok) {
    ++failures;
    fprintf(stderr, "consumer: FAILED %s (%.3g)\n", what, value);
  }
}

static int status_ok(cyc_context* ctx, int status, const char* call) {
  if (status != CYC_OK) {
    ++failures;
    fprintf(stderr, "consumer: %s returned %s: %s\n", call, cyc_status_name(status),
            cyc_context_last_error(ctx));
    return 0;
  }
  return 1;
}

static double dot3(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static double norm3(const double a[3]) { return sqrt(dot3(a, a)); }

/* A cone with apex A and axis e3: the PRRS through three of its lines. */
static cyc_surface* cone(cyc_context* ctx, const double A[3], const double e1[3],
                         const double e2[3], const double e3[3]) {
  const double pi = 3.14159265358979323846;
  cyc_curve* L[3] = {NULL, NULL, NULL};
  cyc_surface* S = NULL;
  int k, j, ok = 1;
  for (k = 0; k < 3; ++k) {
    const double t = 2 * pi * k / 3 + 0.3;
    double d[3];
    for (j = 0; j < 3; ++j) d[j] = cos(t) * e1[j] + sin(t) * e2[j] + e3[j];
    ok = ok && status_ok(ctx, cyc_curve_create_line(ctx, A, d, &L[k]), "cyc_curve_create_line");
  }
  if (ok) status_ok(ctx, cyc_prrs_create(ctx, L[0], L[1], L[2], NULL, 0.5, 1.0, &S), "cyc_prrs_create");
  for (k = 0; k < 3; ++k) cyc_curve_destroy(ctx, L[k]);
  return S;
}

static void example2(cyc_context* ctx) {
  const double O[3] = {0, 0, 0}, X[3] = {1, 0, 0}, P[3] = {0, 0, 1}, W[3] = {2, 1, 0};
  cyc_curve *l1 = NULL, *l2 = NULL;
  cyc_surface* s = NULL;
  double x[3] = {0, 0, 0};
  if (status_ok(ctx, cyc_curve_create_line(ctx, O, X, &l1), "cyc_curve_create_line") &&
      status_ok(ctx, cyc_curve_create_line(ctx, P, W, &l2), "cyc_curve_create_line") &&
      status_ok(ctx, cyc_prcs_create(ctx, l1, l2, NULL, -0.5, 0.5, &s), "cyc_prcs_create") &&
      status_ok(ctx, cyc_surface_eval(ctx, s, 0.25, 1.0, x, NULL, NULL, NULL), "cyc_surface_eval")) {
    /* (23) at u = 1/4, v = 1. */
    const double want = (0.25 - 0.75 - 1 - 3) / 12.0;
    check(fabs(x[0] - want) < 1e-14, "Example 2: x(1/4, 1) by (23)", x[0] - want);
  }
  cyc_surface_destroy(ctx, s);
  cyc_curve_destroy(ctx, l1);
  cyc_curve_destroy(ctx, l2);
}

/* The blend's points at parameter t lie on the cone's end circle (u = 1)
 * and its normals are perpendicular to the cone's ruling x - apex. */
static void check_join(cyc_context* ctx, const cyc_surface* cone_surface, const double apex[3],
                       const double* X, const double* N, const char* which) {
  cyc_circle c;
  int j, k;
  double worst_circle = 0, worst_ruling = 0;
  if (!status_ok(ctx, cyc_surface_circle(ctx, cone_surface, 1.0, &c), "cyc_surface_circle")) return;
  for (j = 0; j < 8; ++j) {
    const double* x = X + 3 * j;
    const double* n = N + 3 * j;
    double d[3], ruling[3];
    for (k = 0; k < 3; ++k) d[k] = x[k] - c.center[k];
    for (k = 0; k < 3; ++k) ruling[k] = x[k] - apex[k];
    worst_circle = fmax(worst_circle, fabs(dot3(d, d) - c.radius2) / c.radius2);
    worst_circle = fmax(worst_circle, fabs(dot3(d, c.normal)) / sqrt(c.radius2));
    worst_ruling = fmax(worst_ruling, fabs(dot3(n, ruling)) / norm3(ruling));
  }
  printf("consumer:   join with %s: on its end circle %.1e, normal . ruling %.1e\n", which,
         worst_circle, worst_ruling);
  check(worst_circle < 1e-12, which, worst_circle);
  check(worst_ruling < 1e-9, which, worst_ruling);
}

static void canal_blend(cyc_context* ctx) {
  enum { NT = 9, NV = 8 };
  const double O[3] = {0, 0, 0}, A2[3] = {4, 0, 4}, X[3] = {1, 0, 0}, Y[3] = {0, 1, 0},
               Z[3] = {0, 0, 1}, MX[3] = {-1, 0, 0};
  cyc_surface *a = cone(ctx, O, X, Y, Z), *b = cone(ctx, A2, Y, Z, MX), *blend = NULL;
  cyc_blend_end s, e;
  cyc_continuity R;
  double ts[NT], vs[NV], P[3 * NT * NV], Du[3 * NT * NV], Dv[3 * NT * NV], Nn[3 * NT * NV];
  double worst_sphere = 0, worst_normal = 0, worst_perp = 0, worst_single = 0;
  size_t singular = 0;
  int i, j, k, kind = -1;
  if (!a || !b) goto done;
  memset(&s, 0, sizeof s);
  s.surface = a;
  s.u = 1.0;
  s.v[0] = HUGE_VAL;
  s.v[1] = -0.5;
  s.v[2] = 0.7;
  e = s;
  e.surface = b;
  if (!status_ok(ctx, cyc_blend_canal(ctx, &s, &e, 2, 0.0, 1.0, &blend), "cyc_blend_canal")) goto done;
  if (status_ok(ctx, cyc_surface_kind(ctx, blend, &kind), "cyc_surface_kind"))
    check(kind == CYC_SURFACE_PRCS, "the canal blend is a PRCS", kind);

  for (i = 0; i < NT; ++i) ts[i] = (double)i / (NT - 1);
  for (j = 0; j < NV; ++j) vs[j] = -3.0 + 0.8 * j;
  {
    cyc_buffer3 bp = {P, NT * NV, 3}, bu = {Du, NT * NV, 3}, bv = {Dv, NT * NV, 3},
                bn = {Nn, NT * NV, 3};
    if (!status_ok(ctx, cyc_surface_eval_grid(ctx, blend, ts, NT, vs, NV, bp, bu, bv, bn, &singular),
                   "cyc_surface_eval_grid"))
      goto done;
  }
  check(singular == 0, "no singular normals", (double)singular);
  for (i = 0; i < NT; ++i) {
    cyc_sphere sp;
    if (!status_ok(ctx, cyc_surface_sphere(ctx, blend, ts[i], &sp), "cyc_surface_sphere")) goto done;
    for (j = 0; j < NV; ++j) {
      const int g = 3 * (i * NV + j);
      const double* x = P + g;
      const double* n = Nn + g;
      const double r = sqrt(sp.radius2);
      double d[3], x1[3], n1[3];
      for (k = 0; k < 3; ++k) d[k] = x[k] - sp.center[k];
      worst_sphere = fmax(worst_sphere, fabs(dot3(d, d) - sp.radius2) / sp.radius2);
      for (k = 0; k < 3; ++k) worst_normal = fmax(worst_normal, fabs(n[k] - d[k] / r));
      worst_normal = fmax(worst_normal, fabs(norm3(n) - 1));
      worst_perp = fmax(worst_perp, fabs(dot3(n, Du + g)) / fmax(1, norm3(Du + g)));
      worst_perp = fmax(worst_perp, fabs(dot3(n, Dv + g)) / fmax(1, norm3(Dv + g)));
      if (status_ok(ctx, cyc_surface_eval(ctx, blend, ts[i], vs[j], x1, NULL, NULL, n1),
                    "cyc_surface_eval"))
        for (k = 0; k < 3; ++k)
          worst_single = fmax(worst_single, fmax(fabs(x1[k] - x[k]), fabs(n1[k] - n[k])));
    }
  }
  printf("consumer: canal blend K = 2 of the cones of Fig. 6, %d x %d points: |x - s|^2 = r^2 "
         "%.1e, n = (x - s)/r %.1e, n . x_t, n . x_v %.1e, grid = single %.1e\n",
         NT, NV, worst_sphere, worst_normal, worst_perp, worst_single);
  check(worst_sphere < 1e-12, "points on the touching spheres", worst_sphere);
  check(worst_normal < 1e-12, "unit normals (x - s)/r", worst_normal);
  check(worst_perp < 1e-9, "normals perpendicular to the partials", worst_perp);
  check(worst_single < 1e-12, "grid evaluation equals single evaluation", worst_single);
  check_join(ctx, a, O, P, Nn, "cone A at t = 0");
  check_join(ctx, b, A2, P + 3 * (NT - 1) * NV, Nn + 3 * (NT - 1) * NV, "cone B at t = 1");
  if (status_ok(ctx, cyc_continuity_report(ctx, a, 1.0, 1.0, blend, 0.0, 0, NULL, 32, &R),
                "cyc_continuity_report")) {
    printf("consumer:   cyc_continuity_report at cone A: gap %.1e, tangent planes %.1e rad\n",
           R.max_gap, R.max_normal_angle);
    check(R.max_gap <= 1e-12 * R.point_scale, "continuity report: gap", R.max_gap);
    check(R.max_normal_angle <= 1e-9, "continuity report: G^1", R.max_normal_angle);
  }
done:
  cyc_surface_destroy(ctx, blend);
  cyc_surface_destroy(ctx, a);
  cyc_surface_destroy(ctx, b);
}

int main(void) {
  cyc_context* ctx = NULL;
  if (cyc_context_create(NULL, &ctx) != CYC_OK) {
    fprintf(stderr, "consumer: cyc_context_create failed\n");
    return 1;
  }
  printf("consumer: header cyclide %s (ABI %d), library %s (ABI %d)\n", CYC_VERSION_STRING,
         CYC_ABI_VERSION, cyc_version_string(), cyc_abi_version());
  check(cyc_version_number() == CYC_VERSION_NUMBER, "library version = header version",
        cyc_version_number());
  check(cyc_abi_version() == CYC_ABI_VERSION, "library ABI = header ABI", cyc_abi_version());
  example2(ctx);
  canal_blend(ctx);
  cyc_context_destroy(ctx);
  printf("consumer: %s\n", failures ? "FAILED" : "ok");
  return failures ? 1 : 0;
}
