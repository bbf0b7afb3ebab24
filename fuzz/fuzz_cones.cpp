// Fuzz target of seed 003's cyclide blends of two cones (Algorithm 2)
// through the C ABI (SPEC.md §8h.6): cones from circles (moderate,
// dyadic data: "tame"), from spheres, from apices, or raw Lie vectors
// (wild numbers); then cyc_cyclide_blend_dimension / _beta / _build /
// _auto / _quality / _continuity / _surface_create (with cyc_surface_eval)
// and the cone circle and surface, on valid or corrupted blend values.
//
// Oracles:
//  - every status is known, never CYC_E_INTERNAL, last status and message
//    agree (fz::check_call);
//  - on error every output is untouched (sentinels);
//  - on OK every number written is finite; dim is 3 or 4; pieces 1 or 2;
//    quality in [0, 1];
//  - a blend built from tame cones is G1 at every glued circle: gaps <=
//    1e-6 scale and tangent-plane angles <= 1e-6 rad (measured: <= 1e-9,
//    SPEC §8h.6; the margin covers blends next to the edges of the valid
//    alpha-intervals);
//  - the blend's surfaces evaluate (OK or a known status) to finite points.
#include "fuzz_common.hpp"

using fz::Input;

namespace {

struct State {
  explicit State(Input& i) : in(i) {}
  Input& in;
  cyc_context* ctx = nullptr;
  void check(const char* fn, int s) { fz::check_call(fn, ctx, s, nullptr); }
};

bool finite(const double* v, int n) {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

// A cone; tame = built from a circle with moderate dyadic data.
cyc_lie_cone cone(State& st, bool& tame) {
  Input& in = st.in;
  cyc_lie_cone K;
  std::memset(&K, 0, sizeof K);
  const int how = in.range(0, 4);
  tame = false;
  if (how <= 1) {  // circle + slope (twice as likely)
    double c[3], n[3];
    for (int i = 0; i < 3; ++i) c[i] = double(in.range(-64, 64)) / 16.0;
    for (int i = 0; i < 3; ++i) n[i] = double(in.range(-16, 16)) / 16.0;
    const double radius = double(in.range(4, 36)) / 16.0;
    const double slope = double(in.range(-12, 12)) / 16.0;
    const int orientation = in.flag() ? 1 : -1;
    FZ_LOG("cone_from_circle((%.17g, %.17g, %.17g), (%.17g, %.17g, %.17g), %.17g, %.17g, %d)",
           c[0], c[1], c[2], n[0], n[1], n[2], radius, slope, orientation);
    const int r = cyc_cone_from_circle(st.ctx, c, n, radius, slope, orientation, &K);
    st.check("cyc_cone_from_circle", r);
    tame = r == CYC_OK;
    if (r != CYC_OK) FZ_CHECK(n[0] == 0 && n[1] == 0 && n[2] == 0, "circle cone failed");
    return K;
  }
  if (how == 2) {  // apex
    double c[3], n[3], a[3];
    for (int i = 0; i < 3; ++i) c[i] = double(in.range(-64, 64)) / 16.0;
    for (int i = 0; i < 3; ++i) n[i] = double(in.range(-16, 16)) / 16.0;
    const double h = double(in.range(-64, 64)) / 8.0;
    for (int i = 0; i < 3; ++i) a[i] = c[i] + h * n[i] + (in.rarely() ? 0.5 : 0.0);
    const int r = cyc_cone_from_circle_apex(st.ctx, c, n, double(in.range(1, 40)) / 16.0, a,
                                            in.flag() ? 1 : -1, &K);
    st.check("cyc_cone_from_circle_apex", r);
    return K;
  }
  if (how == 3) {  // spheres
    double m[3], dm[3];
    for (int i = 0; i < 3; ++i) m[i] = in.wild();
    for (int i = 0; i < 3; ++i) dm[i] = in.wild();
    const int r = cyc_cone_from_spheres(st.ctx, m, in.wild(), dm, in.wild(), &K);
    st.check("cyc_cone_from_spheres", r);
    return K;
  }
  for (int i = 0; i < 6; ++i) K.r0[i] = in.wild();  // raw
  for (int i = 0; i < 6; ++i) K.r_plus[i] = in.wild();
  return K;
}

void check_blend(const cyc_cyclide_blend& B) {
  FZ_CHECK(B.pieces == 1 || B.pieces == 2, "pieces = %d", B.pieces);
  FZ_CHECK(std::isfinite(B.alpha) && std::isfinite(B.beta) && finite(B.joint, 6),
           "non-finite blend data");
  for (int i = 0; i < B.pieces; ++i)
    FZ_CHECK(finite(B.piece[i].theta, 36) && finite(B.piece[i].origin, 3), "theta or origin");
}

void use_blend(State& st, const cyc_lie_cone& R, const cyc_lie_cone& S, bool tame,  // NOLINT
               cyc_cyclide_blend& B) {
  Input& in = st.in;
  if (in.rarely()) {  // corrupt it (a valid-looking corruption voids the G1 oracle)
    if (in.flag()) B.piece[in.range(0, 1)].theta[in.range(0, 35)] += in.wild();
    else B.piece[in.range(0, 1)].origin[in.range(0, 2)] = in.wild();
    if (in.flag()) B.pieces = in.range(-1, 3);
    tame = false;
  }
  cyc_cyclide_blend_report rep;
  std::memset(&rep, 0xab, sizeof rep);
  cyc_cyclide_blend_report sentinel = rep;
  const int n = in.range(1, 8);
  const int rc = cyc_cyclide_blend_continuity(st.ctx, &R, &S, &B, n, &rep);
  st.check("cyc_cyclide_blend_continuity", rc);
  if (rc != CYC_OK) {
    FZ_CHECK(std::memcmp(&rep, &sentinel, sizeof rep) == 0, "report written on error");
  } else {
    FZ_CHECK(finite(rep.gap, 3) && finite(rep.angle, 3) && std::isfinite(rep.scale), "report");
    if (tame) {
      for (int j = 0; j < 3; ++j) {
        FZ_CHECK(rep.gap[j] <= 1e-6 * std::max(1.0, rep.scale), "gap[%d] = %g (scale %g)", j,
                 rep.gap[j], rep.scale);
        FZ_CHECK(rep.angle[j] <= 1e-6, "angle[%d] = %g", j, rep.angle[j]);
      }
    }
  }
  double q = -7;
  const int rq = cyc_cyclide_blend_quality(st.ctx, &B, &q);
  st.check("cyc_cyclide_blend_quality", rq);
  if (rq == CYC_OK) FZ_CHECK(q >= 0 && q <= 1 + 1e-12, "quality %g", q);
  else FZ_CHECK(q == -7, "quality written on error");
  cyc_surface* P = nullptr;
  const int rs = cyc_cyclide_blend_surface_create(st.ctx, &B, in.range(-1, 2), &P);
  st.check("cyc_cyclide_blend_surface_create", rs);
  if (rs != CYC_OK) {
    FZ_CHECK(P == nullptr, "surface written on error");
    return;
  }
  for (int k = 0; k < 3; ++k) {
    const double u = double(in.range(0, 16)) / 16.0, v = double(in.range(-64, 64)) / 8.0;
    double x[3] = {1e300, 1e300, 1e300};
    const int re = cyc_surface_eval(st.ctx, P, u, v, x, nullptr, nullptr, nullptr);
    st.check("cyc_surface_eval", re);
    if (re == CYC_OK) FZ_CHECK(finite(x, 3), "non-finite point");
  }
  cyc_surface_destroy(st.ctx, P);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fz::choose_reentry(data, size);
  Input in(data, size);
  State st(in);
  if (cyc_context_create(nullptr, &st.ctx) != CYC_OK) return 0;
  bool tame_r = false, tame_s = false;
  const cyc_lie_cone R = cone(st, tame_r), S = cone(st, tame_s);
  const bool tame = tame_r && tame_s;
  // The cones' circles.
  {
    double c[3] = {7, 7, 7}, n[3] = {7, 7, 7}, r = 7;
    const int rc = cyc_cone_circle(st.ctx, &R, c, n, &r);
    st.check("cyc_cone_circle", rc);
    if (rc == CYC_OK) FZ_CHECK(finite(c, 3) && finite(n, 3) && std::isfinite(r) && r >= 0, "circle");
    else FZ_CHECK(c[0] == 7 && n[0] == 7 && r == 7, "circle written on error");
  }
  int dim = -1;
  const int rd = cyc_cyclide_blend_dimension(st.ctx, &R, &S, &dim);
  st.check("cyc_cyclide_blend_dimension", rd);
  if (rd == CYC_OK) FZ_CHECK(dim == 3 || dim == 4, "dim = %d", dim);
  else FZ_CHECK(dim == -1, "dim written on error");
  const int branch = in.rarely() ? in.range(-2, 2) : (in.flag() ? 1 : -1);
  const double alpha = in.flag() ? double(in.range(-256, 256)) / 32.0 : in.wild();
  double beta = 12345;
  const int rb = cyc_cyclide_blend_beta(st.ctx, &R, &S, branch, alpha, &beta);
  st.check("cyc_cyclide_blend_beta", rb);
  if (rb == CYC_OK) FZ_CHECK(std::isfinite(beta), "beta");
  else FZ_CHECK(beta == 12345, "beta written on error");
  cyc_cyclide_blend B;
  std::memset(&B, 0xcd, sizeof B);
  const cyc_cyclide_blend sentinel = B;
  // 0: Algorithm 2 at (branch, alpha); 1: the core's automatic choice;
  // 2 (rarely, a Ceres solve): the optimizer tier with a random objective.
  const int mode = in.rarely() ? 2 : int(in.flag());
  FZ_LOG("branch %d alpha %.17g mode %d", branch, alpha, mode);
  cyc_optimize_summary sum;
  std::memset(&sum, 0xcd, sizeof sum);
  int rr = CYC_OK;
  if (mode == 0) {
    rr = cyc_cyclide_blend_build(st.ctx, &R, &S, branch, alpha, &B);
  } else if (mode == 1) {
    rr = cyc_cyclide_blend_auto(st.ctx, &R, &S, in.range(8, 24), &B, nullptr);
  } else {
    cyc_cyclide_blend_objective o;
    cyc_cyclide_blend_objective_init(&o);
    cyc_cyclide_blend_options p;
    cyc_cyclide_blend_options_init(&p);
    o.fairness = in.flag() ? 1.0 : in.wild();
    o.joint_radius = in.flag() ? 0.0 : in.wild();
    o.min_extent = in.flag() ? 0.05 : in.wild();
    const double point[3] = {in.wild(), in.wild(), in.wild()};
    const cyc_blend_obstacle obstacle = {{in.wild(), in.wild(), in.wild()}, in.wild()};
    if (in.flag()) o.joint_points = point, o.joint_point_count = 1;
    if (in.flag()) o.obstacles = &obstacle, o.obstacle_count = 1;
    // Out-of-range sizes exercise the validation; in range, the work is
    // 2 branches x samples x (circles per family and piece), so large
    // samples come with few circles and vice versa: both near their maxima
    // (4096 x 256) is allowed work of about 10 s under the fuzzer's
    // instrumentation, libFuzzer's timeout (findings/README, 2026-11-23).
    p.samples = in.rarely() ? in.range(0, 5000) : in.range(8, 16);
    const bool many_samples = p.samples > 64 && p.samples <= 4096;
    o.circles = in.rarely() ? (many_samples ? in.range(-1, 8) : in.range(-1, 300)) : in.range(4, 8);
    p.branch = in.rarely() ? in.range(-2, 2) : 0;
    p.max_iterations = in.range(0, 6);
    rr = cyc_optimize_cyclide_blend(st.ctx, &R, &S, &o, &p, &B, &sum);
  }
  static const char* const names[3] = {"cyc_cyclide_blend_build", "cyc_cyclide_blend_auto",
                                       "cyc_optimize_cyclide_blend"};
  st.check(names[mode], rr);
  if (mode == 2 && rr == CYC_OK)
    FZ_CHECK(std::isfinite(sum.final_cost) && sum.final_cost <= sum.initial_cost,
             "optimizer cost %g -> %g", sum.initial_cost, sum.final_cost);
  if (mode == 2 && rr != CYC_OK) {
    cyc_optimize_summary untouched;
    std::memset(&untouched, 0xcd, sizeof untouched);
    FZ_CHECK(std::memcmp(&sum, &untouched, sizeof sum) == 0, "summary written on error");
  }
  if (rr != CYC_OK) {
    FZ_CHECK(std::memcmp(&B, &sentinel, sizeof B) == 0, "blend written on error");
  } else {
    FZ_CHECK(rd == CYC_OK, "blend OK but dimension failed");
    check_blend(B);
    FZ_CHECK((B.pieces == 1) == (dim == 3), "pieces %d for dim %d", B.pieces, dim);
    use_blend(st, R, S, tame, B);
  }
  cyc_context_destroy(st.ctx);
  return 0;
}
