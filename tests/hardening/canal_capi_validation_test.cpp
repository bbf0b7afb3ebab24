// The C ABI of the canal, ringed, Darboux and blend families as a hostile
// host sees it (SPEC §9b.2, "C ABI checks of the canal families"):
//  - every count, degree, order, kind, sign and index argument or struct
//    field at INT_MAX, INT_MIN and -1 is refused with a status and a message
//    naming it, before any array it sizes is read, and the outputs are
//    untouched;
//  - every double input (argument, array entry, struct field) that is NaN,
//    infinite or beyond |x| <= 1e100 is CYC_E_NOT_FINITE with a message
//    "<function>: <name> = <value> ..." naming it, outputs untouched
//    (circle parameters v are points of the projective line: only NaN is
//    refused; v of a surface evaluation must be finite);
//  - construction failures speak in their own words (no other
//    construction's remark or algorithm as the explanation).
#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "cyclide/cyclide.h"
#include "hostile.hpp"

namespace {

using hostile::kInf;
using hostile::kNaN;
constexpr unsigned char kSentinel = 0xA5;

// Valid inputs of every entry point; the tests change one field at a time.
struct Env {
  cyc_context* ctx = nullptr;
  cyc_curve* p1 = nullptr;  // (u, 0, 0)
  cyc_curve* p2 = nullptr;  // (2u, u, 1)
  cyc_curve* p3 = nullptr;  // (0, u, 2)
  cyc_curve* d = nullptr;   // the directrix (u, 0, 0)
  cyc_curve* n = nullptr;   // the axis (1, u, 0)
  cyc_surface* S = nullptr; // PRCS of p1, p2 on [-1, 1]
  cyc_ringed_jet a{}, b{};  // jets of S at its ends
  cyc_mobius f{};           // f = (v + 0 u) / (1), degree 1
  cyc_inversion inv{{3, 0, 0}, 2};
  cyc_darboux D{};          // the unit sphere: (X.X)^2 ... as phi0 = 0, x^2 + y^2 + z^2 - 1
  cyc_line lines[3] = {{{0, 0, 0}, {1, 0, 0}}, {{0, 1, 0}, {0, 1, 1}}, {{0, 0, 1}, {1, 1, 0}}};
  cyc_implicit_blend B{};
  double x[3] = {0.5, 0.25, 0.125};
  double v3[3] = {0, 0, 1};
  double rho[2] = {0.5, 0.1};
  double xq[8] = {1, 0, 0.5, 0, 0, 1, 0, -1};  // x(u) = (1, u, 0.5, -u)

  // The outputs: every output of a call points into this block.
  alignas(64) unsigned char out[4096];
  template <class T>
  T* o(size_t offset = 0) {
    return reinterpret_cast<T*>(out + offset);
  }
  cyc_buffer3 buffer(size_t offset) { return {o<double>(offset), 8, 3}; }

  Env() {
    EXPECT_EQ(cyc_context_create(nullptr, &ctx), CYC_OK);
    const double c1[6] = {0, 0, 0, 1, 0, 0}, c2[6] = {0, 0, 1, 2, 1, 0}, c3[6] = {0, 0, 2, 0, 1, 0};
    const double cn[6] = {1, 0, 0, 0, 1, 0};
    EXPECT_EQ(cyc_curve_create_polynomial(ctx, 1, c1, 3, &p1), CYC_OK);
    EXPECT_EQ(cyc_curve_create_polynomial(ctx, 1, c2, 3, &p2), CYC_OK);
    EXPECT_EQ(cyc_curve_create_polynomial(ctx, 1, c3, 3, &p3), CYC_OK);
    EXPECT_EQ(cyc_curve_create_polynomial(ctx, 1, c1, 3, &d), CYC_OK);
    EXPECT_EQ(cyc_curve_create_polynomial(ctx, 1, cn, 3, &n), CYC_OK);
    EXPECT_EQ(cyc_prcs_create(ctx, p1, p2, nullptr, -1, 1, &S), CYC_OK);
    EXPECT_EQ(cyc_surface_ringed_jet(ctx, S, -1, &a), CYC_OK);
    EXPECT_EQ(cyc_surface_ringed_jet(ctx, S, 1, &b), CYC_OK);
    f.degree = 1;
    f.alpha[0] = 1;
    f.delta[0] = 1;
    D.k[4] = D.k[5] = D.k[6] = 1;
    D.k[13] = -1;
    const double q1[10] = {0, 1, 1, 0, 0, 0, 0, 0, 0, -9};
    const double q2[10] = {1, 1, 2, -2, 0, 0, -12, 12, 0, 28};
    const double g1[4] = {1, 0, 0, 0}, g2[4] = {1, 1, 0, -10};
    std::memcpy(B.f1, q1, sizeof q1);
    std::memcpy(B.f2, q2, sizeof q2);
    std::memcpy(B.f10, g1, sizeof g1);
    std::memcpy(B.f20, g2, sizeof g2);
    B.lambda = 0.5;
    B.n = 2;
    seal();
  }
  ~Env() {
    cyc_surface_destroy(ctx, S);
    for (cyc_curve* c : {p1, p2, p3, d, n}) cyc_curve_destroy(ctx, c);
    cyc_context_destroy(ctx);
  }
  cyc_blend_end end(double u, double lambda) const {
    cyc_blend_end e{};
    e.surface = S;
    e.u = u;
    e.v[0] = 0;
    e.v[1] = 1;
    e.v[2] = -1;
    e.lambda = lambda;
    return e;
  }
  void seal() { std::memset(out, kSentinel, sizeof out); }
  bool untouched() const {
    for (unsigned char c : out)
      if (c != kSentinel) return false;
    return true;
  }
};

std::string last_error(const Env& e) { return cyc_context_last_error(e.ctx); }

// ------------------------------------------------------------ counts

// A call with one integer argument or field set to n.
struct CountRow {
  const char* fn;
  const char* name;  // as the message names it
  long long lo, hi;  // the valid range
  int above;         // the status above hi
  std::function<int(Env&, int)> call;
};

std::vector<CountRow> count_rows() {
  const int kDeg = CYC_MAX_CURVE_DEGREE;
  return {
      {"cyc_ringed_pcurve_create", "x_degree", 0, kDeg / 2, CYC_E_DEGREE_TOO_HIGH,
       [](Env& e, int k) {
         return cyc_ringed_pcurve_create(e.ctx, e.d, k, e.xq, 0.3, 0, e.rho, 0, nullptr,
                                         nullptr, -1, 1, e.o<cyc_surface*>());
       }},
      {"cyc_ringed_pcurve_create", "rho_num_degree", 0, kDeg, CYC_E_DEGREE_TOO_HIGH,
       [](Env& e, int k) {
         return cyc_ringed_pcurve_create(e.ctx, e.d, 1, e.xq, 0.3, k, e.rho, 0, nullptr,
                                         nullptr, -1, 1, e.o<cyc_surface*>());
       }},
      {"cyc_ringed_pcurve_create", "f.degree", 0, CYC_MAX_MOBIUS_DEGREE, CYC_E_DEGREE_TOO_HIGH,
       [](Env& e, int k) {
         cyc_mobius f = e.f;
         f.degree = k;
         return cyc_ringed_pcurve_create(e.ctx, e.d, 1, e.xq, 0.3, 0, e.rho, 0, nullptr, &f,
                                         -1, 1, e.o<cyc_surface*>());
       }},
      {"cyc_ringed_dnr_create", "rho_num_degree", 0, kDeg, CYC_E_DEGREE_TOO_HIGH,
       [](Env& e, int k) {
         return cyc_ringed_dnr_create(e.ctx, e.d, e.n, k, e.rho, 0, nullptr, nullptr, nullptr,
                                      -1, 1, e.o<cyc_surface*>(), e.o<cyc_ringed_field_report>(64));
       }},
      {"cyc_ringed_dnr_create", "rho_den_degree", 0, kDeg, CYC_E_DEGREE_TOO_HIGH,
       [](Env& e, int k) {
         return cyc_ringed_dnr_create(e.ctx, e.d, e.n, 0, e.rho, k, e.rho, nullptr, nullptr, -1,
                                      1, e.o<cyc_surface*>(), e.o<cyc_ringed_field_report>(64));
       }},
      {"cyc_ringed_dnr_create", "options.method", 0, 3, CYC_E_INVALID_ARGUMENT,
       [](Env& e, int k) {
         cyc_ringed_field_options o;
         cyc_ringed_field_options_init(&o);
         o.method = k;
         return cyc_ringed_dnr_create(e.ctx, e.d, e.n, 0, e.rho, 0, nullptr, &o, nullptr, -1,
                                      1, e.o<cyc_surface*>(), e.o<cyc_ringed_field_report>(64));
       }},
      {"cyc_ringed_dnr_create", "options.which", 0, 1, CYC_E_INVALID_ARGUMENT,
       [](Env& e, int k) {
         cyc_ringed_field_options o;
         cyc_ringed_field_options_init(&o);
         o.which = k;
         return cyc_ringed_dnr_create(e.ctx, e.d, e.n, 0, e.rho, 0, nullptr, &o, nullptr, -1,
                                      1, e.o<cyc_surface*>(), e.o<cyc_ringed_field_report>(64));
       }},
      {"cyc_ringed_sqrt_create", "R_num_degree", 0, kDeg, CYC_E_DEGREE_TOO_HIGH,
       [](Env& e, int k) {
         return cyc_ringed_sqrt_create(e.ctx, e.d, e.n, k, e.rho, 0, nullptr, nullptr, nullptr,
                                       -1, 1, e.o<cyc_surface*>(), e.o<cyc_ringed_sqrt_report>(64));
       }},
      {"cyc_ringed_sqrt_create", "R_den_degree", 0, kDeg, CYC_E_DEGREE_TOO_HIGH,
       [](Env& e, int k) {
         return cyc_ringed_sqrt_create(e.ctx, e.d, e.n, 0, e.rho, k, e.rho, nullptr, nullptr,
                                       -1, 1, e.o<cyc_surface*>(), e.o<cyc_ringed_sqrt_report>(64));
       }},
      {"cyc_ringed_contour_curves", "rho_num_degree", 0, kDeg, CYC_E_DEGREE_TOO_HIGH,
       [](Env& e, int k) {
         return cyc_ringed_contour_curves(e.ctx, e.d, e.n, k, e.rho, 0, nullptr, e.v3,
                                          e.o<cyc_curve*>(), e.o<cyc_curve*>(8));
       }},
      {"cyc_prcs_create", "f.degree", 0, CYC_MAX_MOBIUS_DEGREE, CYC_E_DEGREE_TOO_HIGH,
       [](Env& e, int k) {
         cyc_mobius f = e.f;
         f.degree = k;
         return cyc_prcs_create(e.ctx, e.p1, e.p2, &f, -1, 1, e.o<cyc_surface*>());
       }},
      {"cyc_prrs_create", "f.degree", 0, CYC_MAX_MOBIUS_DEGREE, CYC_E_DEGREE_TOO_HIGH,
       [](Env& e, int k) {
         cyc_mobius f = e.f;
         f.degree = k;
         return cyc_prrs_create(e.ctx, e.p1, e.p2, e.p3, &f, -1, 1, e.o<cyc_surface*>());
       }},
      {"cyc_ringed_create", "f.degree", 0, CYC_MAX_MOBIUS_DEGREE, CYC_E_DEGREE_TOO_HIGH,
       [](Env& e, int k) {
         cyc_mobius f = e.f;
         f.degree = k;
         return cyc_ringed_create(e.ctx, e.d, e.n, e.p2, &f, -1, 1, e.o<cyc_surface*>());
       }},
      {"cyc_curve_create_polynomial", "degree", 0, kDeg, CYC_E_DEGREE_TOO_HIGH,
       [](Env& e, int k) {
         return cyc_curve_create_polynomial(e.ctx, k, e.xq, 3, e.o<cyc_curve*>());
       }},
      {"cyc_curve_create_rational", "degree", 0, kDeg, CYC_E_DEGREE_TOO_HIGH,
       [](Env& e, int k) {
         return cyc_curve_create_rational(e.ctx, k, e.xq, 4, e.o<cyc_curve*>());
       }},
      {"cyc_curve_create_bezier", "degree", 0, kDeg, CYC_E_DEGREE_TOO_HIGH,
       [](Env& e, int k) {
         return cyc_curve_create_bezier(e.ctx, k, e.xq, 3, nullptr, 0, 1, e.o<cyc_curve*>());
       }},
      {"cyc_curve_create_hermite", "order", 0, CYC_MAX_HERMITE_ORDER, CYC_E_DEGREE_TOO_HIGH,
       [](Env& e, int k) {
         return cyc_curve_create_hermite(e.ctx, k, 0, 1, e.xq, e.xq, e.o<cyc_curve*>());
       }},
      {"cyc_curve_eval", "order", 0, 8, CYC_E_INVALID_ARGUMENT,
       [](Env& e, int k) { return cyc_curve_eval(e.ctx, e.p1, 0.5, k, e.o<double>(), 27); }},
      {"cyc_darboux_fit_points", "count", CYC_MIN_FIT_POINTS, CYC_MAX_FIT_POINTS,
       CYC_E_INVALID_ARGUMENT,
       [](Env& e, int k) {
         return cyc_darboux_fit_points(e.ctx, e.xq, k, e.o<cyc_darboux_fit>());
       }},
      {"cyc_blend_canal", "K", 2, CYC_MAX_BLEND_ORDER, CYC_E_DEGREE_TOO_HIGH,
       [](Env& e, int k) {
         const cyc_blend_end s = e.end(1, 1), t = e.end(-1, 1);
         return cyc_blend_canal(e.ctx, &s, &t, k, 0, 1, e.o<cyc_surface*>());
       }},
      {"cyc_blend_ringed", "K", 1, CYC_MAX_BLEND_ORDER, CYC_E_DEGREE_TOO_HIGH,
       [](Env& e, int k) {
         const cyc_blend_end s = e.end(1, 1), t = e.end(-1, 1);
         return cyc_blend_ringed(e.ctx, &s, &t, k, 0, 1, e.o<cyc_surface*>());
       }},
      {"cyc_blend_ringed_matched", "K", 1, CYC_MAX_BLEND_ORDER, CYC_E_DEGREE_TOO_HIGH,
       [](Env& e, int k) {
         const cyc_blend_end s = e.end(1, 1), t = e.end(-1, 1);
         return cyc_blend_ringed_matched(e.ctx, &s, &t, k, 0, 1, e.o<cyc_surface*>());
       }},
      {"cyc_blend_canal_spline", "n", 2, CYC_MAX_SPLINE_KNOTS, CYC_E_INVALID_ARGUMENT,
       [](Env& e, int k) {
         const cyc_blend_end ends[2] = {e.end(1, 1), e.end(-1, 1)};
         const double knots[2] = {0, 1};
         return cyc_blend_canal_spline(e.ctx, ends, k, 2, knots, e.o<cyc_surface*>());
       }},
      {"cyc_blend_canal_spline", "K", 2, CYC_MAX_BLEND_ORDER, CYC_E_DEGREE_TOO_HIGH,
       [](Env& e, int k) {
         const cyc_blend_end ends[2] = {e.end(1, 1), e.end(-1, 1)};
         const double knots[2] = {0, 1};
         return cyc_blend_canal_spline(e.ctx, ends, 2, k, knots, e.o<cyc_surface*>());
       }},
      {"cyc_blend_ringed_spline", "n", 2, CYC_MAX_SPLINE_KNOTS, CYC_E_INVALID_ARGUMENT,
       [](Env& e, int k) {
         const cyc_blend_end ends[2] = {e.end(1, 1), e.end(-1, 1)};
         const double knots[2] = {0, 1};
         return cyc_blend_ringed_spline(e.ctx, ends, k, 1, knots, e.o<cyc_surface*>());
       }},
      {"cyc_blend_ringed_spline_matched", "K", 1, CYC_MAX_BLEND_ORDER, CYC_E_DEGREE_TOO_HIGH,
       [](Env& e, int k) {
         const cyc_blend_end ends[2] = {e.end(1, 1), e.end(-1, 1)};
         const double knots[2] = {0, 1};
         return cyc_blend_ringed_spline_matched(e.ctx, ends, 2, k, knots, e.o<cyc_surface*>());
       }},
      {"cyc_surface_derivatives_u", "K", 0, CYC_MAX_BLEND_ORDER, CYC_E_DEGREE_TOO_HIGH,
       [](Env& e, int k) {
         return cyc_surface_derivatives_u(e.ctx, e.S, 0, 0, k, e.o<double>());
       }},
      {"cyc_continuity_report", "K", 0, CYC_MAX_BLEND_ORDER, CYC_E_DEGREE_TOO_HIGH,
       [](Env& e, int k) {
         return cyc_continuity_report(e.ctx, e.S, 0, 1, e.S, 0, k, nullptr, 4,
                                      e.o<cyc_continuity>());
       }},
      // n samples of the circle, at most 2^20 (a count from garbage cannot
      // start 2^31 evaluations).
      {"cyc_continuity_report", "n", 1, 1 << 20, CYC_E_INVALID_ARGUMENT,
       [](Env& e, int k) {
         return cyc_continuity_report(e.ctx, e.S, 0, 1, e.S, 0, 1, nullptr, k,
                                      e.o<cyc_continuity>());
       }},
      {"cyc_blend_ringed_pcurve", "options.sign", -1, 1, CYC_E_INVALID_ARGUMENT,
       [](Env& e, int k) {
         cyc_pcurve_blend_options o;
         cyc_pcurve_blend_options_init(&o);
         o.sign = k;
         return cyc_blend_ringed_pcurve(e.ctx, &e.a, &e.b, &o, e.o<cyc_surface*>(),
                                        e.o<int>(16));
       }},
      {"cyc_blend_ringed_pcurve_bump", "bump.kind", 0, 1, CYC_E_INVALID_ARGUMENT,
       [](Env& e, int k) {
         cyc_directrix_bump bump{{0, 0, 1}, 0.5, k};
         return cyc_blend_ringed_pcurve_bump(e.ctx, &e.a, &e.b, nullptr, &bump,
                                             e.o<cyc_surface*>(), e.o<int>(16));
       }},
      {"cyc_implicit_blend_eval", "blend.n", 1, CYC_MAX_IMPLICIT_EXPONENT,
       CYC_E_INVALID_ARGUMENT,
       [](Env& e, int k) {
         cyc_implicit_blend B = e.B;
         B.n = k;
         return cyc_implicit_blend_eval(e.ctx, &B, e.x, e.o<double>(), e.o<double>(8), nullptr,
                                        nullptr, nullptr);
       }},
      {"cyc_implicit_contour_points", "end", 0, 1, CYC_E_INVALID_ARGUMENT,
       [](Env& e, int k) {
         return cyc_implicit_contour_points(e.ctx, &e.B, k, e.v3, e.o<int>(), e.o<double>(8),
                                            e.o<int>(64));
       }},
      {"cyc_optimize_implicit_blend", "options.pieces", 1, CYC_MAX_IMPLICIT_PIECES,
       CYC_E_INVALID_ARGUMENT,
       [](Env& e, int k) {
         const double V[9] = {0, 0, 1, 0, 1, 0, 0, 0.7, 0.7};
         cyc_implicit_approx_options o;
         cyc_implicit_approx_options_init(&o);
         o.pieces = k;
         return cyc_optimize_implicit_blend(e.ctx, &e.B, V, &o, e.o<cyc_surface*>(),
                                            e.o<int>(128), e.o<cyc_implicit_approx_report>(256));
       }},
      {"cyc_optimize_implicit_blend", "options.error_nodes_u", 4, 1024, CYC_E_INVALID_ARGUMENT,
       [](Env& e, int k) {
         const double V[9] = {0, 0, 1, 0, 1, 0, 0, 0.7, 0.7};
         cyc_implicit_approx_options o;
         cyc_implicit_approx_options_init(&o);
         o.error_nodes_u = k;
         return cyc_optimize_implicit_blend(e.ctx, &e.B, V, &o, e.o<cyc_surface*>(),
                                            e.o<int>(128), e.o<cyc_implicit_approx_report>(256));
       }},
      {"cyc_blend_ringed_nway", "n", 3, CYC_NWAY_MAX_ENDS, CYC_E_INVALID_ARGUMENT,
       [](Env& e, int k) {
         const cyc_surface* ends[3] = {e.S, e.S, e.S};
         const double u[3] = {1, 1, 1};
         return cyc_blend_ringed_nway(e.ctx, ends, u, k, nullptr, e.o<cyc_surface*>(),
                                      e.o<int>(256), nullptr);
       }},
      {"cyc_blend_ringed_nway", "options.center", 0, 2, CYC_E_INVALID_ARGUMENT,
       [](Env& e, int k) {
         const cyc_surface* ends[3] = {e.S, e.S, e.S};
         const double u[3] = {1, 1, 1};
         cyc_nway_options o;
         cyc_nway_options_init(&o);
         o.center = k;
         return cyc_blend_ringed_nway(e.ctx, ends, u, 3, &o, e.o<cyc_surface*>(),
                                      e.o<int>(256), nullptr);
       }},
      {"cyc_blend_ringed_nway", "options.side", 0, 1, CYC_E_INVALID_ARGUMENT,
       [](Env& e, int k) {
         const cyc_surface* ends[3] = {e.S, e.S, e.S};
         const double u[3] = {1, 1, 1};
         cyc_nway_options o;
         cyc_nway_options_init(&o);
         o.side = k;
         return cyc_blend_ringed_nway(e.ctx, ends, u, 3, &o, e.o<cyc_surface*>(),
                                      e.o<int>(256), nullptr);
       }},
      {"cyc_blend_ringed_nway", "options.blend.sign", -1, 1, CYC_E_INVALID_ARGUMENT,
       [](Env& e, int k) {
         const cyc_surface* ends[3] = {e.S, e.S, e.S};
         const double u[3] = {1, 1, 1};
         cyc_nway_options o;
         cyc_nway_options_init(&o);
         o.blend.sign = k;
         return cyc_blend_ringed_nway(e.ctx, ends, u, 3, &o, e.o<cyc_surface*>(),
                                      e.o<int>(256), nullptr);
       }},
      {"cyc_parabolic_parameterize", "kind", CYC_SURFACE_PRCS, CYC_SURFACE_PRRS,
       CYC_E_INVALID_ARGUMENT,
       [](Env& e, int k) {
         return cyc_parabolic_parameterize(e.ctx, &e.D, k, -1, 1, e.o<cyc_line>(256),
                                           e.o<cyc_surface*>());
       }},
  };
}

// INT_MAX, INT_MIN and -1 for every count: refused (the status of its side
// of the range), the message names the argument, nothing is written, and
// nothing past the caller's arrays is read (x_degree = INT_MAX used to pass
// 2 x_degree <= 15 by overflow and read x far past its 8 doubles).
TEST(CanalCapiCounts, HostileCountsAreRefusedByName) {
  Env e;
  for (const CountRow& r : count_rows())
    for (long long k : {(long long)INT_MAX, (long long)INT_MIN, -1LL}) {
      if (k >= r.lo && k <= r.hi) continue;  // valid (e.g. sign -1)
      e.seal();
      const int got = r.call(e, int(k));
      if (got == -1) continue;
      const int want = k > r.hi ? r.above : CYC_E_INVALID_ARGUMENT;
      const std::string msg = last_error(e);
      SCOPED_TRACE(std::string(r.fn) + " " + r.name + " = " + std::to_string(k) + ": " + msg);
      EXPECT_EQ(got, want);
      EXPECT_NE(msg.find(std::string(r.fn) + ": " + r.name + " = " + std::to_string(k)),
                std::string::npos);
      EXPECT_TRUE(e.untouched());
    }
}

// nu or nv beyond the address space (nu * nv may then wrap): refused
// before any parameter is read or any buffer written, naming the array.
TEST(CanalCapiCounts, GridSizeProductDoesNotWrap) {
  Env e;
  const double us[2] = {0, 0.5}, vs[2] = {0, 1};
  for (const char* fn : {"cyc_surface_eval_grid", "cyc_surface_eval_grid_inverted"}) {
    e.seal();
    const size_t big = SIZE_MAX / 2 + 1;  // big * 2 wraps to 0
    const cyc_buffer3 P = e.buffer(0), none{nullptr, 0, 0};
    const int got = std::strcmp(fn, "cyc_surface_eval_grid") == 0
                        ? cyc_surface_eval_grid(e.ctx, e.S, us, big, vs, 2, P, none, none, none,
                                                e.o<size_t>(2048))
                        : cyc_surface_eval_grid_inverted(e.ctx, e.S, &e.inv, us, big, vs, 2, P,
                                                         none, none, none, e.o<size_t>(2048));
    EXPECT_EQ(got, CYC_E_INVALID_ARGUMENT) << fn;
    EXPECT_NE(last_error(e).find(": us:"), std::string::npos) << last_error(e);
    EXPECT_TRUE(e.untouched());
  }
  // One row of 2^61 parameters: nu * nv fits, the array vs cannot exist
  // (it was read past its end).
  e.seal();
  const cyc_buffer3 none{nullptr, 0, 0};
  EXPECT_EQ(cyc_surface_eval_grid(e.ctx, e.S, us, 1, vs, SIZE_MAX / 8 + 1, none, none, none,
                                  none, nullptr),
            CYC_E_INVALID_ARGUMENT);
  EXPECT_NE(last_error(e).find(": vs:"), std::string::npos) << last_error(e);
  EXPECT_TRUE(e.untouched());
}

// Strides whose rows would wrap the address space (row k at k * stride
// beyond SIZE_MAX bytes) are refused before any row is read or written: a
// wrapped k * stride addresses memory outside the caller's array.
TEST(CanalCapiCounts, StridesThatWrapAreRefused) {
  Env e;
  const double c[8] = {0, 0, 0, 1, 0, 0, 0, 1};
  const double uv[4] = {0, 0, 0.5, 1};
  const double us[2] = {0, 0.5}, vs[2] = {0, 1};
  const cyc_buffer3 none{nullptr, 0, 0};
  for (size_t stride : {SIZE_MAX, SIZE_MAX / 2 + 1, SIZE_MAX / 8}) {
    struct Case {
      const char* expect;
      std::function<int()> call;
    };
    const Case cases[] = {
        {"cyc_curve_create_polynomial: coeffs:",
         [&] { return cyc_curve_create_polynomial(e.ctx, 1, c, stride, e.o<cyc_curve*>()); }},
        {"cyc_curve_create_rational: coeffs:",
         [&] { return cyc_curve_create_rational(e.ctx, 1, c, stride, e.o<cyc_curve*>()); }},
        {"cyc_curve_create_bezier: ctrl:",
         [&] {
           return cyc_curve_create_bezier(e.ctx, 1, c, stride, nullptr, 0, 1, e.o<cyc_curve*>());
         }},
        {"cyc_surface_eval_batch: uv:",
         [&] {
           return cyc_surface_eval_batch(e.ctx, e.S, uv, stride, 2, e.buffer(0), none, none,
                                         none, e.o<size_t>(2048));
         }},
        {"cyc_surface_eval_batch: points:",
         [&] {
           const cyc_buffer3 P{e.o<double>(), 8, stride};
           return cyc_surface_eval_batch(e.ctx, e.S, uv, 2, 2, P, none, none, none,
                                         e.o<size_t>(2048));
         }},
        {"cyc_surface_eval_grid: normals:",
         [&] {
           const cyc_buffer3 N{e.o<double>(), 8, stride};
           return cyc_surface_eval_grid(e.ctx, e.S, us, 2, vs, 2, none, none, none, N,
                                        e.o<size_t>(2048));
         }},
        {"cyc_surface_eval_grid_inverted: du:",
         [&] {
           const cyc_buffer3 D{e.o<double>(), 8, stride};
           return cyc_surface_eval_grid_inverted(e.ctx, e.S, &e.inv, us, 2, vs, 2, none, D,
                                                 none, none, e.o<size_t>(2048));
         }},
    };
    for (const Case& k : cases) {
      e.seal();
      EXPECT_EQ(k.call(), CYC_E_INVALID_ARGUMENT) << k.expect << " stride " << stride;
      EXPECT_EQ(last_error(e).rfind(k.expect, 0), 0u) << last_error(e);
      EXPECT_TRUE(e.untouched()) << k.expect;
    }
  }
}

// ------------------------------------------------------------ doubles

enum Kind {
  kInput,            // NaN, +-Inf and beyond 1e100 are refused
  kFinite,           // the circle parameter v of an evaluation: NaN and +-Inf
  kCircleParameter,  // a point of the projective line: only NaN
};

struct DoubleRow {
  const char* fn;
  const char* name;  // the message names it: "<fn>: <name> = ..."
  Kind kind;
  std::function<int(Env&, double)> call;
};

#define ROW(fn, name, kind, ...) \
  DoubleRow { fn, name, kind, [](Env& e, double z) { (void)z; __VA_ARGS__ } }

std::vector<DoubleRow> double_rows() {
  std::vector<DoubleRow> R = {
      // ---- curves
      ROW("cyc_curve_create_polynomial", "coeffs[1][2]", kInput,
          double c[6] = {0, 0, 0, 1, 0, 0}; c[5] = z;
          return cyc_curve_create_polynomial(e.ctx, 1, c, 3, e.o<cyc_curve*>());),
      ROW("cyc_curve_create_rational", "coeffs[0][3]", kInput,
          double c[10] = {0, 0, 0, 1, 1, 0, 0, 0, 0, 0}; c[3] = z;
          return cyc_curve_create_rational(e.ctx, 1, c, 5, e.o<cyc_curve*>());),
      ROW("cyc_curve_create_bezier", "ctrl[1][0]", kInput,
          double c[6] = {0, 0, 0, 1, 0, 0}; c[3] = z;
          return cyc_curve_create_bezier(e.ctx, 1, c, 3, nullptr, 0, 1, e.o<cyc_curve*>());),
      ROW("cyc_curve_create_bezier", "weights[1]", kInput,
          const double c[6] = {0, 0, 0, 1, 0, 0}; const double w[2] = {1, z};
          return cyc_curve_create_bezier(e.ctx, 1, c, 3, w, 0, 1, e.o<cyc_curve*>());),
      ROW("cyc_curve_create_bezier", "u1", kInput,
          const double c[6] = {0, 0, 0, 1, 0, 0};
          return cyc_curve_create_bezier(e.ctx, 1, c, 3, nullptr, 0, z, e.o<cyc_curve*>());),
      ROW("cyc_curve_create_line", "direction[2]", kInput,
          const double d[3] = {1, 0, z};
          return cyc_curve_create_line(e.ctx, e.x, d, e.o<cyc_curve*>());),
      ROW("cyc_curve_create_point", "point[0]", kInput,
          const double p[3] = {z, 0, 0};
          return cyc_curve_create_point(e.ctx, p, e.o<cyc_curve*>());),
      ROW("cyc_curve_create_line_element", "tangent[1]", kInput,
          const double t[3] = {1, z, 0};
          return cyc_curve_create_line_element(e.ctx, e.x, t, e.o<cyc_curve*>());),
      ROW("cyc_curve_create_hermite", "end[1][0]", kInput,
          double a[6] = {0, 0, 0, 1, 0, 0}, b[6] = {1, 0, 0, 1, 0, 0}; b[3] = z;
          return cyc_curve_create_hermite(e.ctx, 1, 0, 1, a, b, e.o<cyc_curve*>());),
      ROW("cyc_curve_create_hermite", "u0", kInput,
          const double a[6] = {0, 0, 0, 1, 0, 0};
          return cyc_curve_create_hermite(e.ctx, 1, z, 1, a, a, e.o<cyc_curve*>());),
      ROW("cyc_curve_eval", "u", kInput,
          return cyc_curve_eval(e.ctx, e.p1, z, 1, e.o<double>(), 6);),
      // ---- PRCS, PRRS, ringed
      ROW("cyc_prcs_create", "u0", kInput,
          return cyc_prcs_create(e.ctx, e.p1, e.p2, nullptr, z, 1, e.o<cyc_surface*>());),
      ROW("cyc_prcs_create", "f.delta[1]", kInput,
          cyc_mobius f = e.f; f.delta[1] = z;
          return cyc_prcs_create(e.ctx, e.p1, e.p2, &f, -1, 1, e.o<cyc_surface*>());),
      ROW("cyc_prrs_create", "u1", kInput,
          return cyc_prrs_create(e.ctx, e.p1, e.p2, e.p3, nullptr, -1, z, e.o<cyc_surface*>());),
      ROW("cyc_prrs_create", "f.beta[0]", kInput,
          cyc_mobius f = e.f; f.beta[0] = z;
          return cyc_prrs_create(e.ctx, e.p1, e.p2, e.p3, &f, -1, 1, e.o<cyc_surface*>());),
      ROW("cyc_ringed_create", "f.gamma[1]", kInput,
          cyc_mobius f = e.f; f.gamma[1] = z;
          return cyc_ringed_create(e.ctx, e.d, e.n, e.p2, &f, -1, 1, e.o<cyc_surface*>());),
      ROW("cyc_ringed_create", "u0", kInput,
          return cyc_ringed_create(e.ctx, e.d, e.n, e.p2, nullptr, z, 1, e.o<cyc_surface*>());),
      // ---- evaluation and queries
      ROW("cyc_surface_eval", "u", kInput,
          return cyc_surface_eval(e.ctx, e.S, z, 0, e.o<double>(), nullptr, nullptr, nullptr);),
      ROW("cyc_surface_eval", "v", kFinite,
          return cyc_surface_eval(e.ctx, e.S, 0, z, e.o<double>(), nullptr, nullptr, nullptr);),
      ROW("cyc_surface_eval_batch", "uv[1][0]", kInput,
          const double uv[4] = {0, 0, z, 0};
          return cyc_surface_eval_batch(e.ctx, e.S, uv, 2, 2, e.buffer(0), {}, {}, {},
                                        e.o<size_t>(2048));),
      ROW("cyc_surface_eval_batch", "uv[0][1]", kFinite,
          const double uv[4] = {0, z, 0, 0};
          return cyc_surface_eval_batch(e.ctx, e.S, uv, 2, 2, e.buffer(0), {}, {}, {},
                                        e.o<size_t>(2048));),
      ROW("cyc_surface_eval_grid", "us[1]", kInput,
          const double us[2] = {0, z}, vs[1] = {0};
          return cyc_surface_eval_grid(e.ctx, e.S, us, 2, vs, 1, e.buffer(0), {}, {}, {},
                                       e.o<size_t>(2048));),
      ROW("cyc_surface_eval_grid", "vs[0]", kFinite,
          const double us[1] = {0}, vs[1] = {z};
          return cyc_surface_eval_grid(e.ctx, e.S, us, 1, vs, 1, e.buffer(0), {}, {}, {},
                                       e.o<size_t>(2048));),
      ROW("cyc_surface_circle", "u", kInput,
          return cyc_surface_circle(e.ctx, e.S, z, e.o<cyc_circle>());),
      ROW("cyc_surface_sphere", "u", kInput,
          return cyc_surface_sphere(e.ctx, e.S, z, e.o<cyc_sphere>());),
      ROW("cyc_surface_ringed_data", "u", kInput,
          return cyc_surface_ringed_data(e.ctx, e.S, z, e.o<double>(), e.o<double>(32),
                                         e.o<double>(64), e.o<double>(96));),
      ROW("cyc_surface_ringed_sphere", "u", kInput,
          return cyc_surface_ringed_sphere(e.ctx, e.S, z, e.o<cyc_sphere>());),
      ROW("cyc_surface_canal_test", "tolerance", kInput,
          return cyc_surface_canal_test(e.ctx, e.S, z, e.o<double>(), e.o<int>(16));),
      ROW("cyc_surface_parameter_of", "point[2]", kInput,
          const double p[3] = {0, 0, z};
          return cyc_surface_parameter_of(e.ctx, e.S, 0, p, e.o<double>());),
      ROW("cyc_surface_parameter_of", "u", kInput,
          return cyc_surface_parameter_of(e.ctx, e.S, z, e.x, e.o<double>());),
      // ---- Darboux cyclides and inversions
      ROW("cyc_darboux_eval", "d.k[3]", kInput,
          cyc_darboux D = e.D; D.k[3] = z;
          return cyc_darboux_eval(e.ctx, &D, e.x, e.o<double>(), e.o<double>(8));),
      ROW("cyc_darboux_eval", "x[1]", kInput,
          const double x[3] = {0, z, 0};
          return cyc_darboux_eval(e.ctx, &e.D, x, e.o<double>(), e.o<double>(8));),
      ROW("cyc_darboux_classify", "d.k[13]", kInput,
          cyc_darboux D = e.D; D.k[13] = z;
          return cyc_darboux_classify(e.ctx, &D, e.o<int>());),
      ROW("cyc_invert_point", "inv.radius", kInput,
          cyc_inversion I = e.inv; I.radius = z;
          return cyc_invert_point(e.ctx, &I, e.x, e.o<double>());),
      ROW("cyc_invert_point", "inv.center[1]", kInput,
          cyc_inversion I = e.inv; I.center[1] = z;
          return cyc_invert_point(e.ctx, &I, e.x, e.o<double>());),
      ROW("cyc_invert_point", "x[2]", kInput,
          const double x[3] = {0, 0, z};
          return cyc_invert_point(e.ctx, &e.inv, x, e.o<double>());),
      ROW("cyc_invert_sphere", "s.b[1]", kInput,
          cyc_general_sphere s{1, {0, z, 0}, -1};
          return cyc_invert_sphere(e.ctx, &e.inv, &s, e.o<cyc_general_sphere>());),
      ROW("cyc_invert_sphere", "s.c", kInput,
          cyc_general_sphere s{1, {0, 0, 0}, z};
          return cyc_invert_sphere(e.ctx, &e.inv, &s, e.o<cyc_general_sphere>());),
      ROW("cyc_invert_circle", "c.radius", kInput,
          cyc_circle_or_line c{0, {0, 0, 0}, {0, 0, 1}, z};
          return cyc_invert_circle(e.ctx, &e.inv, &c, e.o<cyc_circle_or_line>());),
      ROW("cyc_invert_circle", "c.axis[0]", kInput,
          cyc_circle_or_line c{0, {0, 0, 0}, {z, 0, 1}, 1};
          return cyc_invert_circle(e.ctx, &e.inv, &c, e.o<cyc_circle_or_line>());),
      ROW("cyc_invert_darboux", "d.k[0]", kInput,
          cyc_darboux D = e.D; D.k[0] = z;
          return cyc_invert_darboux(e.ctx, &e.inv, &D, e.o<cyc_darboux>());),
      ROW("cyc_surface_eval_inverted", "u", kInput,
          return cyc_surface_eval_inverted(e.ctx, e.S, &e.inv, z, 0, e.o<double>(), nullptr,
                                           nullptr, nullptr);),
      ROW("cyc_surface_eval_inverted", "v", kFinite,
          return cyc_surface_eval_inverted(e.ctx, e.S, &e.inv, 0, z, e.o<double>(), nullptr,
                                           nullptr, nullptr);),
      ROW("cyc_surface_circle_inverted", "u", kInput,
          return cyc_surface_circle_inverted(e.ctx, e.S, &e.inv, z,
                                             e.o<cyc_circle_or_line>());),
      ROW("cyc_surface_eval_grid_inverted", "us[0]", kInput,
          const double us[1] = {z}, vs[1] = {0};
          return cyc_surface_eval_grid_inverted(e.ctx, e.S, &e.inv, us, 1, vs, 1, e.buffer(0),
                                                {}, {}, {}, e.o<size_t>(2048));),
      ROW("cyc_surface_eval_grid_inverted", "inv.radius", kInput,
          const double us[1] = {0}, vs[1] = {0}; cyc_inversion I = e.inv; I.radius = z;
          return cyc_surface_eval_grid_inverted(e.ctx, e.S, &I, us, 1, vs, 1, e.buffer(0),
                                                {}, {}, {}, e.o<size_t>(2048));),
      ROW("cyc_dcmc", "lines[1].point[2]", kInput,
          cyc_line L[3]; std::memcpy(L, e.lines, sizeof L); L[1].point[2] = z;
          return cyc_dcmc(e.ctx, L, e.o<double>(), e.o<cyc_darboux>(64),
                          e.o<cyc_darboux>(256));),
      ROW("cyc_dcmc", "lines[2].direction[0]", kInput,
          cyc_line L[3]; std::memcpy(L, e.lines, sizeof L); L[2].direction[0] = z;
          return cyc_dcmc(e.ctx, L, e.o<double>(), e.o<cyc_darboux>(64),
                          e.o<cyc_darboux>(256));),
      ROW("cyc_darboux_fit_points", "points[5][1]", kInput,
          std::vector<double> p(3 * CYC_MIN_FIT_POINTS);
          for (size_t i = 0; i < p.size(); ++i) p[i] = std::sin(double(i));
          p[16] = z;
          return cyc_darboux_fit_points(e.ctx, p.data(), CYC_MIN_FIT_POINTS,
                                        e.o<cyc_darboux_fit>());),
      ROW("cyc_classify_two_lines", "l2.direction[1]", kInput,
          cyc_line l2 = e.lines[1]; l2.direction[1] = z;
          return cyc_classify_two_lines(e.ctx, &e.lines[0], &l2,
                                        e.o<cyc_lines_classification>());),
      ROW("cyc_classify_line_element", "w[2]", kInput,
          const double w[3] = {0, 1, z};
          return cyc_classify_line_element(e.ctx, &e.lines[0], e.x, w,
                                           e.o<cyc_lines_classification>(),
                                           e.o<cyc_darboux>(1024));),
      ROW("cyc_classify_line_element", "l1.point[0]", kInput,
          cyc_line l1 = e.lines[0]; l1.point[0] = z;
          return cyc_classify_line_element(e.ctx, &l1, e.x, e.v3,
                                           e.o<cyc_lines_classification>(),
                                           e.o<cyc_darboux>(1024));),
      ROW("cyc_classify_line_two_points", "p3[1]", kInput,
          const double p3[3] = {0, z, 1};
          return cyc_classify_line_two_points(e.ctx, &e.lines[0], e.x, p3,
                                              e.o<cyc_lines_classification>());),
      ROW("cyc_parabolic_lines", "d.k[1]", kInput,
          cyc_darboux D = e.D; D.k[1] = z;
          return cyc_parabolic_lines(e.ctx, &D, e.o<cyc_cyclide_lines>());),
      ROW("cyc_pencil_circle", "plane_normal[1]", kInput,
          const double m[3] = {0, z, 1};
          return cyc_pencil_circle(e.ctx, &e.D, &e.lines[0], m, e.o<cyc_circle_or_line>());),
      ROW("cyc_pencil_circle", "line.point[0]", kInput,
          cyc_line l = e.lines[0]; l.point[0] = z;
          return cyc_pencil_circle(e.ctx, &e.D, &l, e.v3, e.o<cyc_circle_or_line>());),
      ROW("cyc_parabolic_parameterize", "u1", kInput,
          return cyc_parabolic_parameterize(e.ctx, &e.D, CYC_SURFACE_PRCS, -1, z,
                                            e.o<cyc_line>(256), e.o<cyc_surface*>());),
      ROW("cyc_prrs_lines_analyze", "lines[0].point[0]", kInput,
          cyc_line L[3]; std::memcpy(L, e.lines, sizeof L); L[0].point[0] = z;
          return cyc_prrs_lines_analyze(e.ctx, L, e.o<cyc_prrs_lines_analysis>());),
      ROW("cyc_prrs_lines_cyclide", "lines[2].point[1]", kInput,
          cyc_line L[3]; std::memcpy(L, e.lines, sizeof L); L[2].point[1] = z;
          return cyc_prrs_lines_cyclide(e.ctx, L, e.o<cyc_darboux>(), e.o<double>(1024));),
      // ---- blends (seed 000 §9)
      ROW("cyc_blend_canal", "start.u", kInput,
          cyc_blend_end s = e.end(1, 1), t = e.end(-1, 1); s.u = z;
          return cyc_blend_canal(e.ctx, &s, &t, 2, 0, 1, e.o<cyc_surface*>());),
      ROW("cyc_blend_canal", "end.lambda", kInput,
          cyc_blend_end s = e.end(1, 1), t = e.end(-1, 1); t.lambda = z;
          return cyc_blend_canal(e.ctx, &s, &t, 2, 0, 1, e.o<cyc_surface*>());),
      ROW("cyc_blend_canal", "start.phi[0]", kInput,
          cyc_blend_end s = e.end(1, 1), t = e.end(-1, 1); s.phi[0] = z;
          return cyc_blend_canal(e.ctx, &s, &t, 2, 0, 1, e.o<cyc_surface*>());),
      ROW("cyc_blend_canal", "start.v[1]", kCircleParameter,
          cyc_blend_end s = e.end(1, 1), t = e.end(-1, 1); s.v[1] = z;
          return cyc_blend_canal(e.ctx, &s, &t, 2, 0, 1, e.o<cyc_surface*>());),
      ROW("cyc_blend_canal", "t1", kInput,
          cyc_blend_end s = e.end(1, 1), t = e.end(-1, 1);
          return cyc_blend_canal(e.ctx, &s, &t, 2, 0, z, e.o<cyc_surface*>());),
      ROW("cyc_blend_ringed", "end.v[2]", kCircleParameter,
          cyc_blend_end s = e.end(1, 1), t = e.end(-1, 1); t.v[2] = z;
          return cyc_blend_ringed(e.ctx, &s, &t, 1, 0, 1, e.o<cyc_surface*>());),
      ROW("cyc_blend_ringed", "t0", kInput,
          cyc_blend_end s = e.end(1, 1), t = e.end(-1, 1);
          return cyc_blend_ringed(e.ctx, &s, &t, 1, z, 1, e.o<cyc_surface*>());),
      ROW("cyc_blend_ringed_matched", "end.phi[1]", kInput,
          cyc_blend_end s = e.end(1, 1), t = e.end(-1, 1); t.phi[1] = z;
          return cyc_blend_ringed_matched(e.ctx, &s, &t, 3, 0, 1, e.o<cyc_surface*>());),
      ROW("cyc_blend_canal_spline", "ends[1].u", kInput,
          cyc_blend_end ends[2] = {e.end(1, 1), e.end(-1, 1)}; ends[1].u = z;
          const double knots[2] = {0, 1};
          return cyc_blend_canal_spline(e.ctx, ends, 2, 2, knots, e.o<cyc_surface*>());),
      ROW("cyc_blend_ringed_spline", "knots[1]", kInput,
          const cyc_blend_end ends[2] = {e.end(1, 1), e.end(-1, 1)};
          const double knots[2] = {0, z};
          return cyc_blend_ringed_spline(e.ctx, ends, 2, 1, knots, e.o<cyc_surface*>());),
      ROW("cyc_blend_ringed_spline_matched", "ends[0].lambda", kInput,
          cyc_blend_end ends[2] = {e.end(1, 1), e.end(-1, 1)}; ends[0].lambda = z;
          const double knots[2] = {0, 1};
          return cyc_blend_ringed_spline_matched(e.ctx, ends, 2, 1, knots,
                                                 e.o<cyc_surface*>());),
      ROW("cyc_surface_derivatives_u", "u", kInput,
          return cyc_surface_derivatives_u(e.ctx, e.S, z, 0, 2, e.o<double>());),
      ROW("cyc_surface_derivatives_u", "v", kCircleParameter,
          return cyc_surface_derivatives_u(e.ctx, e.S, 0, z, 2, e.o<double>());),
      ROW("cyc_continuity_report", "lambda", kInput,
          return cyc_continuity_report(e.ctx, e.S, 0, z, e.S, 0, 1, nullptr, 4,
                                       e.o<cyc_continuity>());),
      ROW("cyc_continuity_report", "ub", kInput,
          return cyc_continuity_report(e.ctx, e.S, 0, 1, e.S, z, 1, nullptr, 4,
                                       e.o<cyc_continuity>());),
      ROW("cyc_continuity_report", "va[1]", kCircleParameter,
          const double va[2] = {0, z};
          return cyc_continuity_report(e.ctx, e.S, 0, 1, e.S, 0, 1, va, 2,
                                       e.o<cyc_continuity>());),
      // ---- ringed surfaces (seed 001)
      ROW("cyc_ringed_dnr_create", "rho_num[0]", kInput,
          const double r[1] = {z};
          return cyc_ringed_dnr_create(e.ctx, e.d, e.n, 0, r, 0, nullptr, nullptr, nullptr, -1,
                                       1, e.o<cyc_surface*>(), e.o<cyc_ringed_field_report>(64));),
      ROW("cyc_ringed_dnr_create", "rho_den[1]", kInput,
          const double r[2] = {1, z};
          return cyc_ringed_dnr_create(e.ctx, e.d, e.n, 0, e.rho, 1, r, nullptr, nullptr, -1,
                                       1, e.o<cyc_surface*>(), e.o<cyc_ringed_field_report>(64));),
      ROW("cyc_ringed_dnr_create", "options.v[1]", kInput,
          cyc_ringed_field_options o; cyc_ringed_field_options_init(&o); o.v[1] = z;
          return cyc_ringed_dnr_create(e.ctx, e.d, e.n, 0, e.rho, 0, nullptr, &o, nullptr, -1,
                                       1, e.o<cyc_surface*>(), e.o<cyc_ringed_field_report>(64));),
      ROW("cyc_ringed_dnr_create", "u1", kInput,
          return cyc_ringed_dnr_create(e.ctx, e.d, e.n, 0, e.rho, 0, nullptr, nullptr, nullptr,
                                       -1, z, e.o<cyc_surface*>(),
                                       e.o<cyc_ringed_field_report>(64));),
      ROW("cyc_ringed_dnr_create", "f.alpha[0]", kInput,
          cyc_mobius f = e.f; f.alpha[0] = z;
          return cyc_ringed_dnr_create(e.ctx, e.d, e.n, 0, e.rho, 0, nullptr, nullptr, &f, -1,
                                       1, e.o<cyc_surface*>(), e.o<cyc_ringed_field_report>(64));),
      ROW("cyc_ringed_sqrt_create", "R_den[0]", kInput,
          const double r[1] = {z};
          return cyc_ringed_sqrt_create(e.ctx, e.d, e.n, 0, e.rho, 0, r, nullptr, nullptr, -1,
                                        1, e.o<cyc_surface*>(), e.o<cyc_ringed_sqrt_report>(64));),
      ROW("cyc_ringed_sqrt_create", "u0", kInput,
          return cyc_ringed_sqrt_create(e.ctx, e.d, e.n, 0, e.rho, 0, nullptr, nullptr, nullptr,
                                        z, 1, e.o<cyc_surface*>(),
                                        e.o<cyc_ringed_sqrt_report>(64));),
      ROW("cyc_ringed_pcurve_create", "x[1][3]", kInput,
          double x[8]; std::memcpy(x, e.xq, sizeof x); x[7] = z;
          return cyc_ringed_pcurve_create(e.ctx, e.d, 1, x, 0.3, 0, e.rho, 0, nullptr, nullptr,
                                          -1, 1, e.o<cyc_surface*>());),
      ROW("cyc_ringed_pcurve_create", "phi", kInput,
          return cyc_ringed_pcurve_create(e.ctx, e.d, 1, e.xq, z, 0, e.rho, 0, nullptr, nullptr,
                                          -1, 1, e.o<cyc_surface*>());),
      ROW("cyc_ringed_pcurve_create", "rho_num[1]", kInput,
          const double r[2] = {1, z};
          return cyc_ringed_pcurve_create(e.ctx, e.d, 1, e.xq, 0.3, 1, r, 0, nullptr, nullptr,
                                          -1, 1, e.o<cyc_surface*>());),
      ROW("cyc_ringed_pcurve_create", "u1", kInput,
          return cyc_ringed_pcurve_create(e.ctx, e.d, 1, e.xq, 0.3, 0, e.rho, 0, nullptr,
                                          nullptr, -1, z, e.o<cyc_surface*>());),
      ROW("cyc_surface_ringed_jet", "u", kInput,
          return cyc_surface_ringed_jet(e.ctx, e.S, z, e.o<cyc_ringed_jet>());),
      ROW("cyc_blend_ringed_pcurve", "a.rho", kInput,
          cyc_ringed_jet a = e.a; a.rho = z;
          return cyc_blend_ringed_pcurve(e.ctx, &a, &e.b, nullptr, e.o<cyc_surface*>(),
                                         e.o<int>(16));),
      ROW("cyc_blend_ringed_pcurve", "a.dd[1]", kInput,
          cyc_ringed_jet a = e.a; a.dd[1] = z;
          return cyc_blend_ringed_pcurve(e.ctx, &a, &e.b, nullptr, e.o<cyc_surface*>(),
                                         e.o<int>(16));),
      ROW("cyc_blend_ringed_pcurve", "a.dn[0]", kInput,
          cyc_ringed_jet a = e.a; a.dn[0] = z;
          return cyc_blend_ringed_pcurve(e.ctx, &a, &e.b, nullptr, e.o<cyc_surface*>(),
                                         e.o<int>(16));),
      ROW("cyc_blend_ringed_pcurve", "b.drho", kInput,
          cyc_ringed_jet b = e.b; b.drho = z;
          return cyc_blend_ringed_pcurve(e.ctx, &e.a, &b, nullptr, e.o<cyc_surface*>(),
                                         e.o<int>(16));),
      ROW("cyc_blend_ringed_pcurve", "b.n[2]", kInput,
          cyc_ringed_jet b = e.b; b.n[2] = z;
          return cyc_blend_ringed_pcurve(e.ctx, &e.a, &b, nullptr, e.o<cyc_surface*>(),
                                         e.o<int>(16));),
      ROW("cyc_blend_ringed_pcurve", "options.tau", kInput,
          cyc_pcurve_blend_options o; cyc_pcurve_blend_options_init(&o); o.tau = z;
          return cyc_blend_ringed_pcurve(e.ctx, &e.a, &e.b, &o, e.o<cyc_surface*>(),
                                         e.o<int>(16));),
      ROW("cyc_blend_ringed_pcurve", "options.v[0]", kInput,
          cyc_pcurve_blend_options o; cyc_pcurve_blend_options_init(&o); o.v[0] = z;
          return cyc_blend_ringed_pcurve(e.ctx, &e.a, &e.b, &o, e.o<cyc_surface*>(),
                                         e.o<int>(16));),
      // Without a bump it is still this entry point that speaks.
      ROW("cyc_blend_ringed_pcurve_bump", "a.rho", kInput,
          cyc_ringed_jet a = e.a; a.rho = z;
          return cyc_blend_ringed_pcurve_bump(e.ctx, &a, &e.b, nullptr, nullptr,
                                              e.o<cyc_surface*>(), e.o<int>(16));),
      ROW("cyc_blend_ringed_pcurve_bump", "bump.w[1]", kInput,
          cyc_directrix_bump bump{{0, z, 1}, 0.5, CYC_BUMP_SINGLE};
          return cyc_blend_ringed_pcurve_bump(e.ctx, &e.a, &e.b, nullptr, &bump,
                                              e.o<cyc_surface*>(), e.o<int>(16));),
      ROW("cyc_blend_ringed_pcurve_bump", "bump.tau", kInput,
          cyc_directrix_bump bump{{0, 0, 1}, z, CYC_BUMP_SINGLE};
          return cyc_blend_ringed_pcurve_bump(e.ctx, &e.a, &e.b, nullptr, &bump,
                                              e.o<cyc_surface*>(), e.o<int>(16));),
      ROW("cyc_surface_contour_points", "v[1]", kInput,
          const double v[3] = {0, z, 1};
          return cyc_surface_contour_points(e.ctx, e.S, 0, v, e.o<double>(), 12,
                                            e.o<int>(128), e.o<int>(136));),
      ROW("cyc_surface_contour_points", "u", kInput,
          return cyc_surface_contour_points(e.ctx, e.S, z, e.v3, e.o<double>(), 12,
                                            e.o<int>(128), e.o<int>(136));),
      ROW("cyc_ringed_contour_curves", "v[0]", kInput,
          const double v[3] = {z, 0, 1};
          return cyc_ringed_contour_curves(e.ctx, e.d, e.n, 0, e.rho, 0, nullptr, v,
                                           e.o<cyc_curve*>(), e.o<cyc_curve*>(8));),
      ROW("cyc_ringed_contour_curves", "rho_num[0]", kInput,
          const double r[1] = {z};
          return cyc_ringed_contour_curves(e.ctx, e.d, e.n, 0, r, 0, nullptr, e.v3,
                                           e.o<cyc_curve*>(), e.o<cyc_curve*>(8));),
      ROW("cyc_surface_sphere_clearance", "center[1]", kInput,
          const double c[3] = {0, z, 0};
          return cyc_surface_sphere_clearance(e.ctx, e.S, c, 1, e.o<double>(),
                                              e.o<double>(8));),
      ROW("cyc_surface_sphere_clearance", "radius", kInput,
          return cyc_surface_sphere_clearance(e.ctx, e.S, e.x, z, e.o<double>(),
                                              e.o<double>(8));),
      // ---- implicit blends (seed 001 §7.a)
      ROW("cyc_implicit_cylinder", "point[0]", kInput,
          const double p[3] = {z, 0, 0};
          return cyc_implicit_cylinder(e.ctx, p, e.v3, 1, e.o<double>());),
      ROW("cyc_implicit_cylinder", "radius", kInput,
          return cyc_implicit_cylinder(e.ctx, e.x, e.v3, z, e.o<double>());),
      ROW("cyc_implicit_cone", "axis[0]", kInput,
          const double a[3] = {z, 0, 1};
          return cyc_implicit_cone(e.ctx, e.x, a, 0.5, e.o<double>());),
      ROW("cyc_implicit_cone", "half_angle", kInput,
          return cyc_implicit_cone(e.ctx, e.x, e.v3, z, e.o<double>());),
      ROW("cyc_implicit_blend_eval", "blend.f1[3]", kInput,
          cyc_implicit_blend B = e.B; B.f1[3] = z;
          return cyc_implicit_blend_eval(e.ctx, &B, e.x, e.o<double>(), e.o<double>(8), e.v3,
                                         e.o<double>(32), e.o<double>(40));),
      ROW("cyc_implicit_blend_eval", "blend.f20[3]", kInput,
          cyc_implicit_blend B = e.B; B.f20[3] = z;
          return cyc_implicit_blend_eval(e.ctx, &B, e.x, e.o<double>(), e.o<double>(8), e.v3,
                                         e.o<double>(32), e.o<double>(40));),
      ROW("cyc_implicit_blend_eval", "blend.lambda", kInput,
          cyc_implicit_blend B = e.B; B.lambda = z;
          return cyc_implicit_blend_eval(e.ctx, &B, e.x, e.o<double>(), e.o<double>(8), e.v3,
                                         e.o<double>(32), e.o<double>(40));),
      ROW("cyc_implicit_blend_eval", "v[2]", kInput,
          const double v[3] = {0, 0, z};
          return cyc_implicit_blend_eval(e.ctx, &e.B, e.x, e.o<double>(), e.o<double>(8), v,
                                         e.o<double>(32), e.o<double>(40));),
      ROW("cyc_implicit_contour_points", "blend.f10[1]", kInput,
          cyc_implicit_blend B = e.B; B.f10[1] = z;
          return cyc_implicit_contour_points(e.ctx, &B, 0, e.v3, e.o<int>(), e.o<double>(8),
                                             e.o<int>(64));),
      ROW("cyc_implicit_contour_points", "v[0]", kInput,
          const double v[3] = {z, 0, 1};
          return cyc_implicit_contour_points(e.ctx, &e.B, 0, v, e.o<int>(), e.o<double>(8),
                                             e.o<int>(64));),
      ROW("cyc_optimize_implicit_blend", "v[4]", kInput,
          double V[9] = {0, 0, 1, 0, 1, 0, 0, 0.7, 0.7}; V[4] = z;
          return cyc_optimize_implicit_blend(e.ctx, &e.B, V, nullptr, e.o<cyc_surface*>(),
                                             e.o<int>(128),
                                             e.o<cyc_implicit_approx_report>(256));),
      ROW("cyc_optimize_implicit_blend", "options.length_max_ratio", kInput,
          const double V[9] = {0, 0, 1, 0, 1, 0, 0, 0.7, 0.7};
          cyc_implicit_approx_options o; cyc_implicit_approx_options_init(&o);
          o.length_max_ratio = z;
          return cyc_optimize_implicit_blend(e.ctx, &e.B, V, &o, e.o<cyc_surface*>(),
                                             e.o<int>(128),
                                             e.o<cyc_implicit_approx_report>(256));),
      // ---- n-way blends (seed 001 §6)
      ROW("cyc_blend_ringed_nway", "end_u[1]", kInput,
          const cyc_surface* ends[3] = {e.S, e.S, e.S}; const double u[3] = {1, z, 1};
          return cyc_blend_ringed_nway(e.ctx, ends, u, 3, nullptr, e.o<cyc_surface*>(),
                                       e.o<int>(256), nullptr);),
      ROW("cyc_blend_ringed_nway", "options.r_fraction", kInput,
          const cyc_surface* ends[3] = {e.S, e.S, e.S}; const double u[3] = {1, 1, 1};
          cyc_nway_options o; cyc_nway_options_init(&o); o.r_fraction = z;
          return cyc_blend_ringed_nway(e.ctx, ends, u, 3, &o, e.o<cyc_surface*>(),
                                       e.o<int>(256), nullptr);),
      ROW("cyc_blend_ringed_nway", "options.lambda[2]", kInput,
          const cyc_surface* ends[3] = {e.S, e.S, e.S}; const double u[3] = {1, 1, 1};
          cyc_nway_options o; cyc_nway_options_init(&o); o.lambda[2] = z;
          return cyc_blend_ringed_nway(e.ctx, ends, u, 3, &o, e.o<cyc_surface*>(),
                                       e.o<int>(256), nullptr);),
      ROW("cyc_blend_ringed_nway", "options.s[2]", kInput,
          const cyc_surface* ends[3] = {e.S, e.S, e.S}; const double u[3] = {1, 1, 1};
          cyc_nway_options o; cyc_nway_options_init(&o); o.s[2] = z;
          return cyc_blend_ringed_nway(e.ctx, ends, u, 3, &o, e.o<cyc_surface*>(),
                                       e.o<int>(256), nullptr);),
      ROW("cyc_blend_ringed_nway", "options.blend.tau", kInput,
          const cyc_surface* ends[3] = {e.S, e.S, e.S}; const double u[3] = {1, 1, 1};
          cyc_nway_options o; cyc_nway_options_init(&o); o.blend.tau = z;
          return cyc_blend_ringed_nway(e.ctx, ends, u, 3, &o, e.o<cyc_surface*>(),
                                       e.o<int>(256), nullptr);),
      ROW("cyc_nway_sphere_create", "radius", kInput,
          return cyc_nway_sphere_create(e.ctx, e.x, z, e.v3, e.o<cyc_surface*>());),
      ROW("cyc_nway_sphere_create", "axis[2]", kInput,
          const double a[3] = {0, 1, z};
          return cyc_nway_sphere_create(e.ctx, e.x, 1, a, e.o<cyc_surface*>());),
  };
  return R;
}

std::vector<double> bad_values(Kind k) {
  switch (k) {
    case kInput: return {kNaN, kInf, -kInf, 1e101, -1e300};
    case kFinite: return {kNaN, kInf, -kInf};
    case kCircleParameter: return {kNaN};
  }
  return {};
}

// Every double input: NaN, +-Inf and beyond the input range are
// CYC_E_NOT_FINITE, the message names the argument or field, nothing is
// written.
TEST(CanalCapiDoubles, BadDoublesAreRefusedByName) {
  Env e;
  for (const DoubleRow& r : double_rows())
    for (double z : bad_values(r.kind)) {
      e.seal();
      const int got = r.call(e, z);
      const std::string msg = last_error(e);
      SCOPED_TRACE(std::string(r.fn) + " " + r.name + " = " + std::to_string(z) + ": " + msg);
      EXPECT_EQ(got, CYC_E_NOT_FINITE);
      EXPECT_EQ(msg.rfind(std::string(r.fn) + ": " + r.name + " = ", 0), 0u);
      EXPECT_TRUE(e.untouched());
    }
}

// The rows reach every guarded entry point of these files that takes a
// double (a new entry point without a row fails here).
TEST(CanalCapiDoubles, RowsCoverEveryEntryPoint) {
  std::vector<std::string> fns;
  for (const DoubleRow& r : double_rows()) fns.push_back(r.fn);
  for (const char* fn :
       {"cyc_curve_create_polynomial", "cyc_curve_create_rational", "cyc_curve_create_bezier",
        "cyc_curve_create_line", "cyc_curve_create_point", "cyc_curve_create_line_element",
        "cyc_curve_create_hermite", "cyc_curve_eval", "cyc_prcs_create", "cyc_prrs_create",
        "cyc_ringed_create", "cyc_surface_eval", "cyc_surface_eval_batch",
        "cyc_surface_eval_grid", "cyc_surface_circle", "cyc_surface_sphere",
        "cyc_surface_ringed_data", "cyc_surface_ringed_sphere", "cyc_surface_canal_test",
        "cyc_surface_parameter_of", "cyc_darboux_eval", "cyc_darboux_classify",
        "cyc_invert_point", "cyc_invert_sphere", "cyc_invert_circle", "cyc_invert_darboux",
        "cyc_surface_eval_inverted", "cyc_surface_circle_inverted",
        "cyc_surface_eval_grid_inverted", "cyc_dcmc", "cyc_darboux_fit_points",
        "cyc_classify_two_lines", "cyc_classify_line_element", "cyc_classify_line_two_points",
        "cyc_parabolic_lines", "cyc_pencil_circle", "cyc_parabolic_parameterize",
        "cyc_prrs_lines_analyze", "cyc_prrs_lines_cyclide", "cyc_blend_canal",
        "cyc_blend_ringed", "cyc_blend_ringed_matched", "cyc_blend_canal_spline",
        "cyc_blend_ringed_spline", "cyc_blend_ringed_spline_matched",
        "cyc_surface_derivatives_u", "cyc_continuity_report", "cyc_ringed_dnr_create",
        "cyc_ringed_sqrt_create", "cyc_ringed_pcurve_create", "cyc_surface_ringed_jet",
        "cyc_blend_ringed_pcurve", "cyc_blend_ringed_pcurve_bump",
        "cyc_surface_contour_points", "cyc_ringed_contour_curves",
        "cyc_surface_sphere_clearance", "cyc_implicit_cylinder", "cyc_implicit_cone",
        "cyc_implicit_blend_eval", "cyc_implicit_contour_points", "cyc_optimize_implicit_blend",
        "cyc_blend_ringed_nway", "cyc_nway_sphere_create"})
    EXPECT_NE(std::find(fns.begin(), fns.end(), fn), fns.end()) << fn;
}

// A circle parameter v = +-infinity is the point f = alpha / gamma of the
// circle, not an error: the checks refuse only NaN there.
TEST(CanalCapiDoubles, InfiniteCircleParameterIsAPoint) {
  Env e;
  for (double v : {kInf, -kInf, 1e300}) {
    double d[9];
    EXPECT_EQ(cyc_surface_derivatives_u(e.ctx, e.S, 0.25, v, 2, d), CYC_OK) << last_error(e);
    for (double x : d) EXPECT_TRUE(std::isfinite(x));
  }
}

// ------------------------------------------------------------ messages

// Zero radii name their argument (not the generic "an argument is out of
// its range").
TEST(CanalCapiMessages, ZeroRadiusNamesTheArgument) {
  Env e;
  const cyc_inversion I{{3, 0, 0}, 0};
  const cyc_general_sphere s{1, {0, 0, 0}, -1};
  auto expect = [&](int got, const char* prefix) {
    EXPECT_EQ(got, CYC_E_INVALID_ARGUMENT) << prefix;
    EXPECT_EQ(last_error(e).rfind(prefix, 0), 0u) << last_error(e);
    EXPECT_TRUE(e.untouched()) << prefix;
    e.seal();
  };
  expect(cyc_invert_point(e.ctx, &I, e.x, e.o<double>()), "cyc_invert_point: inv.radius = 0");
  expect(cyc_invert_sphere(e.ctx, &I, &s, e.o<cyc_general_sphere>()),
         "cyc_invert_sphere: inv.radius = 0");
  expect(cyc_implicit_cylinder(e.ctx, e.x, e.v3, 0, e.o<double>()),
         "cyc_implicit_cylinder: radius = 0");
  expect(cyc_nway_sphere_create(e.ctx, e.x, 0, e.v3, e.o<cyc_surface*>()),
         "cyc_nway_sphere_create: radius = 0");
  expect(cyc_surface_sphere_clearance(e.ctx, e.S, e.x, -1, e.o<double>(), nullptr),
         "cyc_surface_sphere_clearance: radius = -1");
}

// Each construction explains its failure in its own words: the implicit
// blend's coincident bounding planes are not PRCS's planes M, N, B, and two
// parallel lines of Prop. 2 are not a DCMC input.
TEST(CanalCapiMessages, FailuresInTheirOwnWords) {
  Env e;
  cyc_implicit_blend B = e.B;
  const double g[4] = {2, 0, 0, 0};
  std::memcpy(B.f20, g, sizeof g);  // 2x = 0 is the plane x = 0 of f10
  double f = 7;
  EXPECT_EQ(cyc_implicit_blend_eval(e.ctx, &B, e.x, &f, nullptr, nullptr, nullptr, nullptr),
            CYC_E_DEPENDENT_PLANES);
  std::string msg = last_error(e);
  EXPECT_EQ(msg.find("M, N"), std::string::npos) << msg;
  EXPECT_EQ(msg.find("Remark 1"), std::string::npos) << msg;
  EXPECT_NE(msg.find("blend.f10"), std::string::npos) << msg;
  EXPECT_EQ(f, 7);

  const cyc_line l1{{0, 0, 0}, {1, 0, 0}}, l2{{0, 1, 1}, {2, 0, 0}};
  cyc_lines_classification C;
  EXPECT_EQ(cyc_classify_two_lines(e.ctx, &l1, &l2, &C), CYC_E_PARALLEL_LINES);
  msg = last_error(e);
  EXPECT_EQ(msg.find("DCMC"), std::string::npos) << msg;
  EXPECT_NE(msg.find("l1 and l2 are parallel"), std::string::npos) << msg;

  // §8's PRRS of three lines is not DCMC either.
  cyc_line L[3] = {l1, l2, {{0, 0, 3}, {0, 1, 0}}};
  cyc_prrs_lines_analysis A;
  EXPECT_EQ(cyc_prrs_lines_analyze(e.ctx, L, &A), CYC_E_PARALLEL_LINES);
  msg = last_error(e);
  EXPECT_EQ(msg.find("DCMC"), std::string::npos) << msg;
  EXPECT_NE(msg.find("§8"), std::string::npos) << msg;
  L[1].direction[0] = 0;
  EXPECT_EQ(cyc_prrs_lines_analyze(e.ctx, L, &A), CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(last_error(e).rfind("cyc_prrs_lines_analyze: lines[1].direction is zero", 0), 0u)
      << last_error(e);

  // A zero polynomial denominator of rho names rho_den.
  const double zero[1] = {0};
  cyc_surface* S = nullptr;
  EXPECT_EQ(cyc_ringed_dnr_create(e.ctx, e.d, e.n, 0, e.rho, 0, zero, nullptr, nullptr, -1, 1,
                                  &S, nullptr),
            CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(last_error(e).rfind("cyc_ringed_dnr_create: rho_den is the zero polynomial", 0), 0u)
      << last_error(e);
  EXPECT_EQ(S, nullptr);
}

// ------------------------------------------------------------ outputs

// f (73) far from the bounding planes overflows: an error, never inf with
// OK, and the outputs untouched.
TEST(CanalCapiOutputs, ImplicitBlendOverflowIsAnError) {
  Env e;
  cyc_implicit_blend B = e.B;
  B.n = CYC_MAX_IMPLICIT_EXPONENT;
  const double x[3] = {1e90, 1e90, 1e90};
  double f = 7, g[3] = {7, 7, 7};
  EXPECT_EQ(cyc_implicit_blend_eval(e.ctx, &B, x, &f, g, nullptr, nullptr, nullptr),
            CYC_E_NUMERICAL_OVERFLOW);
  EXPECT_EQ(f, 7);
  EXPECT_EQ(g[0], 7);
}

// The blend of order K reads phi[0..K-2] only: NaN in an unused phi is no
// part of the input (the struct's documentation: unused phi are ignored).
TEST(CanalCapiOutputs, UnusedPhiIsNotRead) {
  Env e;
  cyc_blend_end s = e.end(1, 1), t = e.end(-1, 1);
  s.phi[1] = s.phi[2] = t.phi[1] = kNaN;  // K = 2 reads phi[0]
  cyc_surface* S = nullptr;
  const int got = cyc_blend_canal(e.ctx, &s, &t, 2, 0, 1, &S);
  EXPECT_NE(got, CYC_E_NOT_FINITE) << last_error(e);
  if (got == CYC_OK) {
    double p[3];
    for (double u : {0.0, 0.5, 1.0})
      for (double v : {-1.0, 0.0, 2.0}) {
        ASSERT_EQ(cyc_surface_eval(e.ctx, S, u, v, p, nullptr, nullptr, nullptr), CYC_OK);
        for (double c : p) EXPECT_TRUE(std::isfinite(c));
      }
  }
  cyc_surface_destroy(e.ctx, S);
}

}  // namespace
