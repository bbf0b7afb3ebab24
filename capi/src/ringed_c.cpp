// The C entry points of ringed surfaces (d, n, rho) of seed 001: Hermite
// jets of surfaces and the P-curve blend of §4 (creation tier: it allocates
// the surface handles). cyc_ringed_create is with the other creators in
// cyclide_c.cpp.
#include <cmath>

#include "capi_internal.hpp"
#include "cyclide/pcurve.hpp"

using namespace cyclide;
using namespace cyclide::capi;

namespace {

RingedJet jet_of(const cyc_ringed_jet& j) {
  RingedJet J;
  J.d = vec(j.d);
  J.dd = vec(j.dd);
  J.n = vec(j.n);
  J.dn = vec(j.dn);
  J.rho = j.rho;
  J.drho = j.drho;
  return J;
}

}  // namespace

extern "C" {

int cyc_surface_ringed_jet(cyc_context* ctx, const cyc_surface* surface, double u,
                           cyc_ringed_jet* out) {
  const char* fn = "cyc_surface_ringed_jet";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    REQUIRE(out);
    RingedJet J;
    if (Status s = ringed_jet(surface->surface, u, J); s != Status::ok) return from_core(fn, s);
    cyc_ringed_jet C;
    put3(C.d, J.d);
    put3(C.dd, J.dd);
    put3(C.n, J.n);
    put3(C.dn, J.dn);
    C.rho = J.rho;
    C.drho = J.drho;
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

int cyc_blend_ringed_pcurve(cyc_context* ctx, const cyc_ringed_jet* a, const cyc_ringed_jet* b,
                            const cyc_pcurve_blend_options* options, cyc_surface** pieces,
                            int* count) {
  const char* fn = "cyc_blend_ringed_pcurve";
  return run(ctx, fn, [&] {
    REQUIRE(a);
    REQUIRE(b);
    REQUIRE(pieces);
    REQUIRE(count);
    RingedBlendOptions o;
    if (options) {
      o.sign = options->sign;
      o.tau = options->tau;
      o.v = vec(options->v);
      if (o.sign != 1 && o.sign != -1)
        return fail(CYC_E_INVALID_ARGUMENT, "%s: sign = %d is not +1 or -1", fn, o.sign);
    }
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
        return fail(int(s), "%s: the projection direction v is zero", fn);
      return located(s) && std::isfinite(bad_u) ? from_core_at(fn, s, bad_u) : from_core(fn, s);
    }
    cyc_surface* h[2] = {nullptr, nullptr};
    for (int k = 0; k < n; ++k)
      if (Outcome e = emit(fn, ctx, &h[k], S[k]); e.status) {
        cyc_surface_destroy(ctx, h[0]);
        return e;
      }
    for (int k = 0; k < n; ++k) pieces[k] = h[k];
    *count = n;
    return ok();
  });
}

}  // extern "C"
