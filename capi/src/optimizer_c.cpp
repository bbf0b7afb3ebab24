// The optimizer tier's C entry points. Built with or without Ceres; the
// symbol set is the same in every build (SPEC.md "Optimizer tier").
#include <cstdio>
#include <cstring>

#include "capi_internal.hpp"

#ifndef CYCLIDE_HAVE_CERES
#define CYCLIDE_HAVE_CERES 0
#endif

#if CYCLIDE_HAVE_CERES
#include "optim/closest_point.hpp"
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

}  // extern "C"
