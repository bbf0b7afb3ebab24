// Fuzz target of seed 001 §7.a through the C ABI (SPEC §8f.7a): the
// implicit blend (73) from Example 7.6's coefficients, from fuzzed
// cylinders (cyc_implicit_cylinder) and planes, or from raw fuzzed
// coefficients, with fuzzed lambda and n; then cyc_implicit_blend_eval,
// cyc_implicit_contour_points and cyc_optimize_implicit_blend (few Ceres
// iterations and small quadratures: the CI smoke runs every target; three
// contour curves or Remark 7.5's two).
//
// Oracles:
//  - every status is known, never CYC_E_INTERNAL; last status/message and
//    the error handler agree with it (fz::check_call);
//  - on error every output is untouched (sentinels);
//  - on OK every number written is finite (never NaN with OK): f, the
//    gradients, contour points (count 0..2), the report (Omega, (87) >= 0),
//    and the surfaces' points at 3 x 3 samples; *count equals the pieces
//    asked for and every surface has kind CYC_SURFACE_RINGED.
#include <cmath>
#include <cstdint>
#include <cstring>

#include "fuzz_common.hpp"

namespace {

using fz::Input;

cyc_surface* const kSentinel = reinterpret_cast<cyc_surface*>(uintptr_t(0x5eed0bad0000ull));

struct Ctx {
  cyc_context* ctx = nullptr;
  fz::HandlerLog log;
  fz::HandlerLog* logp = nullptr;
  void check(const char* fn, int s) { fz::check_call(fn, ctx, s, logp); }
};

// Example 7.6 (85) with P1: x = 0, P2: x + y = 10.
void example76(cyc_implicit_blend& B) {
  const double q1[10] = {0, 1, 1, 0, 0, 0, 0, 0, 0, -9};
  const double q2[10] = {1, 1, 2, -2, 0, 0, -12, 12, 0, 28};
  const double g1[4] = {1, 0, 0, 0}, g2[4] = {1, 1, 0, -10};
  std::memcpy(B.f1, q1, sizeof q1);
  std::memcpy(B.f2, q2, sizeof q2);
  std::memcpy(B.f10, g1, sizeof g1);
  std::memcpy(B.f20, g2, sizeof g2);
}

// A cylinder (point, direction, radius) and the plane through the point
// perpendicular to the direction (as the paper's bounding planes).
void cylinder(Input& in, Ctx& c, double* q, double* g) {
  double P[3], U[3];
  fz::coords(in, P, 3);
  fz::coords(in, U, 3);
  const double r = fz::coord(in);
  const int s = cyc_implicit_cylinder(c.ctx, P, U, r, q);
  c.check("cyc_implicit_cylinder", s);
  if (s != CYC_OK) {
    for (int k = 0; k < 10; ++k) q[k] = 0;  // an invalid quadric: the calls below refuse it
  }
  g[0] = U[0];
  g[1] = U[1];
  g[2] = U[2];
  g[3] = -(U[0] * P[0] + U[1] * P[1] + U[2] * P[2]);
}

void make_blend(Input& in, Ctx& c, cyc_implicit_blend& B) {
  switch (in.range(0, 2)) {
    case 0: example76(B); break;
    case 1:
      cylinder(in, c, B.f1, B.f10);
      cylinder(in, c, B.f2, B.f20);
      break;
    default:
      fz::coords(in, B.f1, 10);
      fz::coords(in, B.f2, 10);
      fz::coords(in, B.f10, 4);
      fz::coords(in, B.f20, 4);
  }
  switch (in.range(0, 2)) {
    case 0: B.lambda = in.range(1, 15) / 16.0; break;
    case 1: B.lambda = fz::coord(in); break;
    default: B.lambda = in.wild();
  }
  B.n = in.range(-1, 18);
}

void op_eval(Input& in, Ctx& c, const cyc_implicit_blend& B) {
  double x[3], v[3];
  fz::coords(in, x, 3);
  const bool with_v = in.flag();
  if (with_v) fz::coords(in, v, 3);
  double f = fz::sentinel(), g[3], fv = fz::sentinel(), hv[3];
  fz::fill_sentinel(g, 3);
  fz::fill_sentinel(hv, 3);
  const int s = cyc_implicit_blend_eval(c.ctx, &B, x, &f, g, with_v ? v : nullptr, &fv, hv);
  c.check("cyc_implicit_blend_eval", s);
  if (s != CYC_OK) {
    FZ_CHECK(fz::is_sentinel(f) && fz::all_sentinel(g, 3) && fz::is_sentinel(fv) &&
                 fz::all_sentinel(hv, 3),
             "cyc_implicit_blend_eval wrote on error");
    return;
  }
  FZ_CHECK(std::isfinite(f) && fz::finite3(g), "cyc_implicit_blend_eval: OK with non-finite f");
  if (with_v) FZ_CHECK(std::isfinite(fv) && fz::finite3(hv), "OK with non-finite f_v");
}

void op_contour(Input& in, Ctx& c, const cyc_implicit_blend& B) {
  const int end = in.range(-1, 2);
  double v[3], pts[6];
  fz::coords(in, v, 3);
  fz::fill_sentinel(pts, 6);
  int count = -7, whole = -7;
  const int s = cyc_implicit_contour_points(c.ctx, &B, end, v, &count, pts, &whole);
  c.check("cyc_implicit_contour_points", s);
  if (s != CYC_OK) {
    FZ_CHECK(count == -7 && whole == -7 && fz::all_sentinel(pts, 6),
             "cyc_implicit_contour_points wrote on error");
    return;
  }
  FZ_CHECK(count >= 0 && count <= 2 && (whole == 0 || whole == 1), "count %d whole %d", count,
           whole);
  for (int k = 0; k < count; ++k) FZ_CHECK(fz::finite3(pts + 3 * k), "non-finite point");
}

void op_optimize(Input& in, Ctx& c, const cyc_implicit_blend& B) {
  double v[9] = {0, 0, 1, 0, 1, 0, 0, 0.70710678118654752, 0.70710678118654752};  // (86)
  if (in.flag()) fz::coords(in, v, 9);
  cyc_implicit_approx_options o;
  cyc_implicit_approx_options_init(&o);
  o.pieces = in.range(0, 3);
  o.max_iterations = in.range(0, 3);
  o.nodes = in.range(1, 6);
  o.error_nodes_t = in.range(1, 4);
  o.error_nodes_u = in.range(3, 8);
  if (in.rarely()) o.psi_weight = fz::coord(in);
  o.two_curves = in.flag() ? 1 : 0;
  cyc_surface* S[CYC_MAX_IMPLICIT_PIECES];
  for (auto& p : S) p = kSentinel;
  int count = -7;
  cyc_implicit_approx_report R;
  std::memset(&R, 0x5a, sizeof R);
  const int s = cyc_optimize_implicit_blend(c.ctx, &B, v, &o, S, &count, &R);
  c.check("cyc_optimize_implicit_blend", s);
  if (s != CYC_OK) {
    FZ_CHECK(count == -7, "cyc_optimize_implicit_blend wrote *count on error");
    for (auto* p : S) FZ_CHECK(p == kSentinel, "cyc_optimize_implicit_blend wrote a handle");
    return;
  }
  FZ_CHECK(count == o.pieces && R.pieces == o.pieces, "count %d for %d pieces", count, o.pieces);
  FZ_CHECK(std::isfinite(R.omega) && std::isfinite(R.error87) && R.error87 >= 0 &&
               std::isfinite(R.seconds),
           "OK with a non-finite report");
  for (int k = 0; k < count; ++k) {
    FZ_CHECK(std::isfinite(R.error87_piece[k]) && std::isfinite(R.omega_piece[k]),
             "non-finite piece report");
    int kind = 0;
    const int sk = cyc_surface_kind(c.ctx, S[k], &kind);
    c.check("cyc_surface_kind", sk);
    FZ_CHECK(sk == CYC_OK && kind == CYC_SURFACE_RINGED, "kind %d", kind);
    for (double u : {0.0, 0.5, 1.0})
      for (double w : {0.0, 1.0, -3.0}) {
        double X[3];
        const int se = cyc_surface_eval(c.ctx, S[k], u, w, X, nullptr, nullptr, nullptr);
        c.check("cyc_surface_eval", se);
        if (se == CYC_OK) FZ_CHECK(fz::finite3(X), "non-finite surface point");
      }
    cyc_surface_destroy(c.ctx, S[k]);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fz::choose_reentry(data, size);
  Input in(data, size);
  Ctx c;
  FZ_CHECK(cyc_context_create(nullptr, &c.ctx) == CYC_OK, "context");
  if (in.flag()) {
    FZ_CHECK(fz::install_handler(c.ctx, c.log) == CYC_OK,
             "handler");
    c.logp = &c.log;
  }
  cyc_implicit_blend B;
  std::memset(&B, 0, sizeof B);
  make_blend(in, c, B);
  const int nops = in.range(1, 4);
  for (int i = 0; i < nops; ++i) {
    switch (in.range(0, 2)) {
      case 0: op_eval(in, c, B); break;
      case 1: op_contour(in, c, B); break;
      default: op_optimize(in, c, B);
    }
  }
  FZ_CHECK(cyc_implicit_blend_eval(nullptr, &B, nullptr, nullptr, nullptr, nullptr, nullptr,
                                   nullptr) == CYC_E_NULL_ARGUMENT,
           "cyc_implicit_blend_eval(NULL context)");
  cyc_context_destroy(c.ctx);
  return 0;
}
