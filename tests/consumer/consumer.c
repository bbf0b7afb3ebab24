/* A minimal user of the installed library: Example 2 of seed 000. */
#include <math.h>
#include <stdio.h>

#include <cyclide/cyclide.h>

int main(void) {
  const double O[3] = {0, 0, 0}, X[3] = {1, 0, 0}, P[3] = {0, 0, 1}, W[3] = {2, 1, 0};
  cyc_context* ctx = NULL;
  cyc_curve *l1 = NULL, *l2 = NULL;
  cyc_surface* s = NULL;
  double x[3];
  int ok = cyc_context_create(NULL, &ctx) == CYC_OK &&
           cyc_curve_create_line(ctx, O, X, &l1) == CYC_OK &&
           cyc_curve_create_line(ctx, P, W, &l2) == CYC_OK &&
           cyc_prcs_create(ctx, l1, l2, NULL, -0.5, 0.5, &s) == CYC_OK &&
           cyc_surface_eval(ctx, s, 0.25, 1.0, x, NULL, NULL, NULL) == CYC_OK;
  /* (23) at u = 1/4, v = 1. */
  ok = ok && fabs(x[0] - (0.25 - 0.75 - 1 - 3) / 12.0) < 1e-14;
  printf("consumer: cyclide %s, x(1/4, 1) = (%g, %g, %g): %s\n", cyc_version_string(), x[0],
         x[1], x[2], ok ? "ok" : "FAILED");
  cyc_surface_destroy(ctx, s);
  cyc_curve_destroy(ctx, l1);
  cyc_curve_destroy(ctx, l2);
  cyc_context_destroy(ctx);
  return ok ? 0 : 1;
}
