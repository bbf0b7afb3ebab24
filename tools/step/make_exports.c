/* make_exports DIR: writes a few exact rational Bezier exports of cyclide
 * surfaces (schema "cyclide-rational-bezier" v1, SPEC.md §8j.3) through the
 * C ABI only, as inputs of tools/step's cyclide-step (scripts/step).
 *
 *   example2_whole.json    seed 000 Example 2 (PRCS of two lines), whole circles, degree (5, 2)
 *   example2_rect.json     the same over a rectangle (v in [-0.7, 2.5])
 *   ringed_quadratic.json  a ringed surface (d quadratic, n linear, c quadratic): degree (10, 2)
 *   dupin_torus.json       the Dupin cyclide touching three unit spheres (a torus), xi in [-3, 3]
 *   dupin_torus_half_a/b   the whole torus as two exports (xi in [-1, 1]; xi = 1/u, u in [-1, 1]):
 *                          given together to cyclide-step they sew into a closed shell (a solid)
 *   dupin_ring.json        the torus inverted at a point off it (a ring cyclide), with u/v maps
 *   parabolic_ring.json    a parabolic ring cyclide (a = 1, b = -0.5), whole circles
 *   prcs_cubic.json        a PRCS through a polynomial cubic and a line: degree (43, 2), beyond
 *                          OCCT's 25 (cyclide-step must refuse it)
 *
 * Prints one line per file: name, patches, degrees. Exit 1 on any failure. */
#include <cyclide/cyclide.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static cyc_context* g_ctx;

static void check(int status, const char* what) {
  if (status != CYC_OK) {
    fprintf(stderr, "make_exports: %s: status %d: %s\n", what, status,
            cyc_context_last_error(g_ctx));
    exit(1);
  }
}

/* Exports s over D into DIR/name.json and reports it. */
static void export_json(const char* dir, const char* name, const cyc_surface* s,
                        const cyc_export_domain* D) {
  cyc_bezier_export* e = NULL;
  cyc_bezier_patch_info info;
  char path[4096];
  check(cyc_bezier_export_create(g_ctx, s, D, &e), name);
  check(cyc_bezier_export_patch(g_ctx, e, 0, &info, NULL, 0), name);
  if (snprintf(path, sizeof path, "%s/%s.json", dir, name) >= (int)sizeof path) {
    fprintf(stderr, "make_exports: path too long\n");
    exit(1);
  }
  check(cyc_bezier_export_write_json(g_ctx, e, path), path);
  printf("%-22s %4d patches, degree (%d, %d)\n", name, cyc_bezier_export_count(e), info.deg_u,
         info.deg_v);
  cyc_bezier_export_destroy(e);
}

static cyc_lie_sphere unit_sphere(double x, double y, double z) {
  cyc_lie_sphere s;
  memset(&s, 0, sizeof s);
  s.kind = CYC_LIE_SPHERE;
  s.m[0] = x, s.m[1] = y, s.m[2] = z;
  s.rho = 1;
  return s;
}

int main(int argc, char** argv) {
  if (argc != 2) {
    fprintf(stderr, "usage: make_exports DIR\n");
    return 2;
  }
  const char* dir = argv[1];
  check(cyc_context_create(NULL, &g_ctx), "cyc_context_create");

  /* Seed 000 Example 2: PRCS of the lines (0,0,0) + u (1,0,0) and (0,0,1) + u (2,1,0). */
  cyc_curve *l1, *l2;
  cyc_surface* ex2;
  {
    const double O[3] = {0, 0, 0}, X[3] = {1, 0, 0}, P[3] = {0, 0, 1}, W[3] = {2, 1, 0};
    check(cyc_curve_create_line(g_ctx, O, X, &l1), "line 1");
    check(cyc_curve_create_line(g_ctx, P, W, &l2), "line 2");
    check(cyc_prcs_create(g_ctx, l1, l2, NULL, -0.5, 0.5, &ex2), "cyc_prcs_create");
    const cyc_export_domain whole = {-0.5, 0.5, 0, 0, 1};
    const cyc_export_domain rect = {-0.5, 0.5, -0.7, 2.5, 0};
    export_json(dir, "example2_whole", ex2, &whole);
    export_json(dir, "example2_rect", ex2, &rect);
  }

  /* Ringed (d, n, c): d(u) = (u, u^2/2, 0), n(u) = (1, u, 0) (the tangent of d), c(u) = d(u) +
   * (0, 0, 0.5 + 0.25 u^2): circles about the curve d of radius 0.5 + 0.25 u^2. */
  {
    const double d[9] = {0, 0, 0, 1, 0, 0, 0, 0.5, 0};
    const double n[6] = {1, 0, 0, 0, 1, 0};
    const double c[9] = {0, 0, 0.5, 1, 0, 0, 0, 0.5, 0.25};
    cyc_curve *cd, *cn, *cc;
    cyc_surface* r;
    check(cyc_curve_create_polynomial(g_ctx, 2, d, 3, &cd), "d");
    check(cyc_curve_create_polynomial(g_ctx, 1, n, 3, &cn), "n");
    check(cyc_curve_create_polynomial(g_ctx, 2, c, 3, &cc), "c");
    check(cyc_ringed_create(g_ctx, cd, cn, cc, NULL, -1, 1, &r), "cyc_ringed_create");
    const cyc_export_domain whole = {-1, 1, 0, 0, 1};
    export_json(dir, "ringed_quadratic", r, &whole);
    cyc_surface_destroy(g_ctx, r);
    cyc_curve_destroy(g_ctx, cd);
    cyc_curve_destroy(g_ctx, cn);
    cyc_curve_destroy(g_ctx, cc);
  }

  /* Dupin cyclides (seed 003): the torus of the spheres touching three unit spheres at
   * (3,0,0), (0,3,0), (-3,0,0); its image under the inversion at (5,0,0) of radius 2 (a
   * point off the torus: a ring cyclide). */
  {
    cyc_lie_sphere sph[3] = {unit_sphere(3, 0, 0), unit_sphere(0, 3, 0), unit_sphere(-3, 0, 0)};
    cyc_lie_sphere inv[3];
    cyc_lie_transform T;
    cyc_dupin torus, ring;
    cyc_surface *st, *sr;
    const double center[3] = {5, 0, 0};
    check(cyc_dupin_from_spheres(g_ctx, sph, &torus), "cyc_dupin_from_spheres");
    /* u is the affine xi (no map): the circles of a(xi) for xi in [-3, 3]. */
    check(cyc_dupin_surface_create(g_ctx, &torus, NULL, NULL, -3, 3, &st),
          "cyc_dupin_surface_create torus");
    const cyc_export_domain whole = {-3, 3, 0, 0, 1};
    export_json(dir, "dupin_torus", st, &whole);
    /* The closed torus as two exports: xi in [-1, 1], and xi = 1/u for u in [-1, 1] (xi
     * from -1 through infinity to 1); they share the circles xi = -1 and xi = 1. */
    {
      const double recip[4] = {0, 1, 1, 0};
      cyc_surface *ha, *hb;
      const cyc_export_domain half = {-1, 1, 0, 0, 1};
      check(cyc_dupin_surface_create(g_ctx, &torus, NULL, NULL, -1, 1, &ha), "torus half a");
      check(cyc_dupin_surface_create(g_ctx, &torus, recip, NULL, -1, 1, &hb), "torus half b");
      export_json(dir, "dupin_torus_half_a", ha, &half);
      export_json(dir, "dupin_torus_half_b", hb, &half);
      cyc_surface_destroy(g_ctx, ha);
      cyc_surface_destroy(g_ctx, hb);
    }
    check(cyc_lie_transform_inversion(g_ctx, center, 2.0, &T), "cyc_lie_transform_inversion");
    for (int i = 0; i < 3; ++i)
      check(cyc_lie_transform_apply(g_ctx, &T, &sph[i], &inv[i]), "cyc_lie_transform_apply");
    check(cyc_dupin_from_spheres(g_ctx, inv, &ring), "cyc_dupin_from_spheres (inverted)");
    const double xm[4] = {2, 1, 1, 3}, zm[4] = {1, 0.5, 0, 1};
    check(cyc_dupin_surface_create(g_ctx, &ring, xm, zm, -0.4, 1.5, &sr),
          "cyc_dupin_surface_create ring");
    const cyc_export_domain rect = {-0.4, 1.5, -1.5, 0.75, 0};
    export_json(dir, "dupin_ring", sr, &rect);
    cyc_surface_destroy(g_ctx, st);
    cyc_surface_destroy(g_ctx, sr);
  }

  /* Parabolic ring cyclide (seed 004 (4.1)), a = 1, b = -0.5, placed. */
  {
    cyc_parabolic_cyclide c;
    cyc_surface* p;
    memset(&c, 0, sizeof c);
    c.a = 1, c.b = -0.5;
    c.frame[0] = 1, c.frame[5] = 1, c.frame[7] = -1; /* a rotation about x by 90 degrees */
    c.origin[0] = 0.5, c.origin[1] = -1, c.origin[2] = 2;
    check(cyc_parabolic_cyclide_surface_create(g_ctx, &c, -2, 2, &p), "parabolic");
    const cyc_export_domain whole = {-2, 2, 0, 0, 1};
    export_json(dir, "parabolic_ring", p, &whole);
    cyc_surface_destroy(g_ctx, p);
  }

  /* A PRCS through a polynomial cubic and Example 2's second line: degree (43, 2), beyond
   * OCCT's limit of 25 (cyclide-step must refuse it with a message). */
  {
    const double cubic[12] = {0, 0, 0, 1, 0, 0, 0, 0.3, 0, 0, 0, 0.2};
    cyc_curve* p1;
    cyc_surface* s;
    check(cyc_curve_create_polynomial(g_ctx, 3, cubic, 3, &p1), "cubic");
    check(cyc_prcs_create(g_ctx, p1, l2, NULL, -0.5, 0.5, &s), "cyc_prcs_create cubic");
    const cyc_export_domain rect = {-0.5, 0.5, -1, 1, 0};
    export_json(dir, "prcs_cubic", s, &rect);
    cyc_surface_destroy(g_ctx, s);
    cyc_curve_destroy(g_ctx, p1);
  }

  cyc_surface_destroy(g_ctx, ex2);
  cyc_curve_destroy(g_ctx, l1);
  cyc_curve_destroy(g_ctx, l2);
  cyc_context_destroy(g_ctx);
  return 0;
}
