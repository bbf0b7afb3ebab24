// Issue 9 item 1 for seed 002's sphere skins (label export; SPEC.md
// §8j.1b): the rational Bezier export (K1)-(K4) of skin_export.hpp --
// exact in theta (degree 4 in v = tan(theta/2)), within the stated
// tolerance in t, exact for a straight spine -- checked against skin_eval
// on dense grids, its NURBS assembly over a chain, its statuses, and a
// RapidCheck property over random skins.

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <vector>

#include "cyclide/skin_export.hpp"

using namespace cyclide;

namespace {

// The skew skin of tests/sphere_skin_test.cpp (Fig. 3/8's situation).
SphereSkin skew_skin(SkinPairing pairing = SkinPairing::rmf) {
  SkinEnd s, e;
  EXPECT_EQ(skin_end_from_sphere({0, 0, 0}, 1.0, {0.3, 0, 0}, {3, 0, 0}, s), Status::ok);
  const Vec3d axis = Vec3d(1.0, 0.6, 0.8).normalized();
  EXPECT_EQ(skin_end_from_sphere({4, 1, 0.5}, 1.2, Vec3d(4, 1, 0.5) - 0.4 * axis, 3.0 * axis, e),
            Status::ok);
  SkinOptions o;
  o.pairing = pairing;
  SphereSkin S;
  EXPECT_EQ(make_sphere_skin(s, e, o, S), Status::ok);
  return S;
}

Vec3d skin_point(const SphereSkin& S, double theta, double t) {
  double x[3] = {0, 0, 0};
  EXPECT_EQ(skin_eval(S, theta, t, x, nullptr, nullptr, nullptr), Status::ok);
  return Vec3d(x[0], x[1], x[2]);
}

// The largest distance between each patch and the skin (patch k of a chain
// by u = k + t) on an n x n grid of local parameters; checks the weights.
double max_deviation(const SphereSkin* skins, const std::vector<RationalBezierPatch>& P, int n) {
  double dev = 0.0;
  for (const RationalBezierPatch& p : P) {
    for (int i = 0; i < (p.deg_u + 1) * (p.deg_v + 1); ++i) EXPECT_GT(p.cp[i][0], 0.0);
    const int k = std::min(int(std::floor(p.u0)), int(std::ceil(p.u1)) - 1);
    for (int a = 0; a <= n; ++a)
      for (int b = 0; b <= n; ++b) {
        double u, v;
        patch_parameters(p, double(a) / n, double(b) / n, u, v);
        const double t = std::min(1.0, std::max(0.0, u - k));
        const Vec3d y = patch_point(p, double(a) / n, double(b) / n);
        dev = std::max(dev, (y - skin_point(skins[k], 2 * std::atan(v), t)).norm());
      }
  }
  return dev;
}

std::vector<RationalBezierPatch> export_all(const SphereSkin* skins, int n, const ExportDomain& D,
                                            const SkinExportOptions& o, SkinExportReport& r) {
  int count = 0;
  EXPECT_EQ(export_sphere_skin(skins, n, D, o, nullptr, 0, count, &r), Status::buffer_too_small);
  std::vector<RationalBezierPatch> P(std::size_t(std::max(count, 0)));
  int written = 0;
  EXPECT_EQ(export_sphere_skin(skins, n, D, o, P.data(), count, written, &r), Status::ok);
  EXPECT_EQ(written, count);
  return P;
}

}  // namespace

// The whole skin within the tolerance: bidegree (q + 3, 4), four 90-degree
// v-pieces per t-interval, the sampled bound (K4) an honest estimate.
TEST(SkinExport, WholeSkinWithinTolerance) {
  const SphereSkin S = skew_skin();
  SkinExportOptions o;
  o.tolerance = 1e-9;
  SkinExportReport r;
  const auto P = export_all(&S, 1, ExportDomain::circles(0, 1), o, r);
  ASSERT_FALSE(P.empty());
  EXPECT_EQ(int(P.size()), 4 * r.t_intervals);
  EXPECT_FALSE(r.exact);
  for (const auto& p : P) {
    EXPECT_EQ(p.deg_u, o.degree + 3);
    EXPECT_EQ(p.deg_v, 4);
  }
  const double dev = max_deviation(&S, P, 16);
  EXPECT_LE(dev, 2 * o.tolerance);
  EXPECT_LE(r.error_estimate, o.tolerance * 2);
  EXPECT_GT(r.error_estimate, 0.0);
  EXPECT_LE(r.rmf_error, 1e-11);
  // v = +-inf is theta = pi: the reciprocal pieces' far ends.
  EXPECT_EQ(P[0].v0, -HUGE_VAL);
  EXPECT_TRUE(P[0].reciprocal_v);
  EXPECT_EQ(P[3].v1, HUGE_VAL);
}

// A tighter tolerance needs more t-intervals (and a higher degree fewer).
TEST(SkinExport, IntervalsFollowTheToleranceAndDegree) {
  const SphereSkin S = skew_skin();
  int prev = 0;
  for (double tol : {1e-4, 1e-7, 1e-10}) {
    SkinExportOptions o;
    o.tolerance = tol;
    SkinExportReport r;
    const auto P = export_all(&S, 1, ExportDomain::circles(0, 1), o, r);
    EXPECT_GE(r.t_intervals, prev);
    prev = r.t_intervals;
    EXPECT_LE(max_deviation(&S, P, 8), 2 * tol) << tol;
  }
  EXPECT_GT(prev, 1);
  SkinExportOptions lo, hi;
  lo.degree = 3;
  hi.degree = 15;
  SkinExportReport rl, rh;
  export_all(&S, 1, ExportDomain::circles(0, 1), lo, rl);
  export_all(&S, 1, ExportDomain::circles(0, 1), hi, rh);
  EXPECT_LT(rh.t_intervals, rl.t_intervals);
}

// (K3): a straight spine with the RMF pairing has a constant frame, so the
// skin is rational and the export exact: one t-interval, rounding only.
TEST(SkinExport, StraightSpineIsExact) {
  SkinEnd s, e;
  ASSERT_EQ(skin_end_from_sphere({0, 0, 0}, 1.0, {0.2, 0, 0}, {2, 0, 0}, s), Status::ok);
  ASSERT_EQ(skin_end_from_sphere({3, 0, 0}, 0.5, {2.9, 0, 0}, {2, 0, 0}, e), Status::ok);
  SphereSkin S;
  ASSERT_EQ(make_sphere_skin(s, e, SkinOptions{}, S), Status::ok);
  SkinExportOptions o;
  o.tolerance = 1e-12;
  o.degree = 1;
  SkinExportReport r;
  const auto P = export_all(&S, 1, ExportDomain::circles(0, 1), o, r);
  EXPECT_TRUE(r.exact);
  EXPECT_EQ(r.t_intervals, 1);
  ASSERT_EQ(P.size(), 4u);
  EXPECT_EQ(P[0].deg_u, 4);  // alpha and lambda cubic, the frame constant
  EXPECT_LE(max_deviation(&S, P, 16), 1e-14);
}

// A rectangle: v in [-0.5, 2] (theta from -0.93 to 2.21) splits at 0 and 1,
// the last piece reciprocal; u in [0.2, 0.7]; the baseline pairings (with
// their extra turn delta s(t)) export as well.
TEST(SkinExport, RectangleAndBaselinePairings) {
  for (SkinPairing pairing :
       {SkinPairing::rmf, SkinPairing::kunkli_hoffmann, SkinPairing::cross_tangents}) {
    const SphereSkin S = skew_skin(pairing);
    SkinExportOptions o;
    o.tolerance = 1e-8;
    SkinExportReport r;
    const auto P = export_all(&S, 1, ExportDomain::rectangle(0.2, 0.7, -0.5, 2.0), o, r);
    ASSERT_EQ(int(P.size()), 3 * r.t_intervals);
    EXPECT_EQ(P[0].u0, 0.2);
    EXPECT_EQ(P.back().u1, 0.7);
    EXPECT_EQ(P[0].v0, -0.5);
    EXPECT_EQ(P[1].v0, 0.0);
    EXPECT_TRUE(P[2].reciprocal_v);
    EXPECT_EQ(P[2].v1, 2.0);
    EXPECT_LE(max_deviation(&S, P, 12), 2 * o.tolerance) << int(pairing);
  }
}

// A chain of three spheres: u = k + t, the patches meet exactly at the
// shared circle, and the whole export assembles into one NURBS (N1)-(N4)
// that reproduces the patches.
TEST(SkinExport, ChainAssemblesIntoOneNurbs) {
  SkinEnd ends[3];
  ASSERT_EQ(skin_end_from_sphere({0, 0, 0}, 1.0, {0.3, 0, 0}, {3, 0, 0}, ends[0]), Status::ok);
  const Vec3d ax = Vec3d(1, 0.5, 0.3).normalized();
  ASSERT_EQ(skin_end_from_sphere({4, 1, 0}, 0.8, Vec3d(4, 1, 0) - 0.1 * ax, 3.0 * ax, ends[1]),
            Status::ok);
  const Vec3d ax2 = Vec3d(0.2, 1, -0.4).normalized();
  ASSERT_EQ(skin_end_from_sphere({6, 4, -1}, 1.1, Vec3d(6, 4, -1) - 0.3 * ax2, 3.0 * ax2, ends[2]),
            Status::ok);
  SphereSkin C[2];
  ASSERT_EQ(make_sphere_skin_chain(ends, 3, SkinOptions{}, C), Status::ok);
  SkinExportOptions o;
  o.tolerance = 1e-9;
  SkinExportReport r;
  const auto P = export_all(C, 2, ExportDomain::circles(0, 2), o, r);
  EXPECT_LE(max_deviation(C, P, 10), 2 * o.tolerance);
  NurbsSize N;
  ASSERT_EQ(nurbs_size(P.data(), int(P.size()), N), Status::ok);
  EXPECT_EQ(N.deg_v, 4);
  EXPECT_EQ(N.nv, 4);
  std::vector<double> ku(std::size_t(N.knots_u())), kv(std::size_t(N.knots_v()));
  std::vector<double> cp(4 * std::size_t(N.cp_count()));
  NurbsBuffers B{ku.data(), N.knots_u(), kv.data(), N.knots_v(),
                 reinterpret_cast<double(*)[4]>(cp.data()), N.cp_count()};
  ASSERT_EQ(assemble_nurbs(P.data(), int(P.size()), B, N), Status::ok);
  const NurbsView V{N, ku.data(), kv.data(), reinterpret_cast<const double(*)[4]>(cp.data())};
  double err = 0.0;
  for (const auto& p : P)
    for (double s : {0.0, 0.3, 1.0})
      for (double t : {0.0, 0.6, 1.0}) {
        double u, v;
        patch_parameters(p, s, t, u, v);
        err = std::max(err, (nurbs_point(V, u, export_tau_of_v(v)) - patch_point(p, s, t)).norm());
      }
  EXPECT_LE(err, 1e-12);
  // The shared circle u = 1 is in both skins: theta-curves continue.
  for (double theta : {-2.0, 0.5, 3.0})
    EXPECT_LE((nurbs_point(V, 1.0, export_tau_of_v(std::tan(theta / 2))) -
               skin_point(C[1], theta, 0.0))
                  .norm(),
              1e-9);
}

TEST(SkinExport, Statuses) {
  const SphereSkin S = skew_skin();
  SkinExportOptions o;
  int count = -1;
  RationalBezierPatch P[1];
  P[0].deg_u = 77;
  const ExportDomain W = ExportDomain::circles(0, 1);
  EXPECT_EQ(export_sphere_skin(nullptr, 1, W, o, P, 1, count), Status::null_argument);
  EXPECT_EQ(export_sphere_skin(&S, 0, W, o, P, 1, count), Status::invalid_argument);
  for (double tol : {0.0, -1.0, double(NAN), HUGE_VAL}) {
    SkinExportOptions b;
    b.tolerance = tol;
    EXPECT_EQ(export_sphere_skin(&S, 1, W, b, P, 1, count), Status::invalid_argument) << tol;
  }
  for (int q : {0, kMaxSkinExportDegree + 1}) {
    SkinExportOptions b;
    b.degree = q;
    EXPECT_EQ(export_sphere_skin(&S, 1, W, b, P, 1, count), Status::invalid_argument) << q;
  }
  EXPECT_EQ(export_sphere_skin(&S, 1, ExportDomain::circles(NAN, 1), o, P, 1, count),
            Status::not_finite);
  EXPECT_EQ(export_sphere_skin(&S, 1, ExportDomain::rectangle(0, 1, 0, HUGE_VAL), o, P, 1, count),
            Status::not_finite);
  EXPECT_EQ(export_sphere_skin(&S, 1, ExportDomain::circles(0, 1.5), o, P, 1, count),
            Status::bad_domain);
  EXPECT_EQ(export_sphere_skin(&S, 1, ExportDomain::circles(0.5, 0.5), o, P, 1, count),
            Status::bad_domain);
  EXPECT_EQ(export_sphere_skin(&S, 1, ExportDomain::rectangle(0, 1, 1, 1), o, P, 1, count),
            Status::bad_domain);
  // Too small a buffer: the count, nothing written.
  EXPECT_EQ(export_sphere_skin(&S, 1, W, o, P, 1, count), Status::buffer_too_small);
  EXPECT_GT(count, 1);
  EXPECT_EQ(P[0].deg_u, 77);
  // Below the rounding of the frame: numerical_overflow, nothing written.
  SkinExportOptions tiny;
  tiny.tolerance = 1e-19;
  SkinExportReport r;
  r.t_intervals = -5;
  std::vector<RationalBezierPatch> Q(8);
  Q[0].deg_u = 77;
  EXPECT_EQ(export_sphere_skin(&S, 1, W, tiny, Q.data(), 8, count, &r),
            Status::numerical_overflow);
  EXPECT_EQ(count, 0);
  EXPECT_EQ(Q[0].deg_u, 77);
  EXPECT_EQ(r.t_intervals, -5);
}

// Property: random well-conditioned skins (two spheres 3..7 apart, tilted
// axes, chord-length tangents) export within the tolerance at random
// points of every patch, with positive weights.
RC_GTEST_PROP(SkinExportProperty, WithinToleranceOnRandomSkins, ()) {
  const auto coord = [](double r) {
    return *rc::gen::resize(100, rc::gen::inRange(-64, 65)) * r / 64.0;
  };
  const Vec3d m0(coord(1), coord(1), coord(1));
  const Vec3d m1 = m0 + Vec3d(5 + coord(2), coord(2), coord(2));
  const Vec3d d = (m1 - m0).normalized();
  SkinEnd ends[2];
  for (int k = 0; k < 2; ++k) {
    const Vec3d m = k ? m1 : m0;
    const double R = 0.5 + (coord(1) + 1) * 0.75;
    const Vec3d axis = (d + Vec3d(coord(0.5), coord(0.5), coord(0.5))).normalized();
    const double h = coord(0.25) * R;
    RC_PRE(skin_end_from_sphere(m, R, m + h * axis, (m1 - m0).norm() * axis, ends[k]) ==
           Status::ok);
  }
  SphereSkin S;
  const Status st = make_sphere_skin(ends[0], ends[1], SkinOptions{}, S);
  RC_PRE(st == Status::ok);
  for (int i = 0; i <= 16; ++i)
    for (int j = 0; j < 16; ++j)
      RC_PRE(skin_lambda(S, 0.3926990817 * j, i / 16.0) >= 0.05 * ends[0].radius);
  SkinExportOptions o;
  o.tolerance = 1e-8;
  o.degree = *rc::gen::inRange(4, 12);
  int count = 0;
  SkinExportReport r;
  RC_ASSERT(export_sphere_skin(&S, 1, ExportDomain::circles(0, 1), o, nullptr, 0, count, &r) ==
            Status::buffer_too_small);
  std::vector<RationalBezierPatch> P(static_cast<std::size_t>(count));
  RC_ASSERT(export_sphere_skin(&S, 1, ExportDomain::circles(0, 1), o, P.data(), count, count,
                               &r) == Status::ok);
  RC_ASSERT(r.error_estimate <= 2 * o.tolerance);
  for (const auto& p : P) {
    for (int i = 0; i < (p.deg_u + 1) * 5; ++i) RC_ASSERT(p.cp[i][0] > 0.0);
    const double s = *rc::gen::inRange(0, 1025) / 1024.0;
    const double t = *rc::gen::inRange(0, 1025) / 1024.0;
    double u, v;
    patch_parameters(p, s, t, u, v);
    double x[3];
    RC_ASSERT(skin_eval(S, 2 * std::atan(v), std::min(1.0, u), x, nullptr, nullptr, nullptr) ==
              Status::ok);
    RC_ASSERT((patch_point(p, s, t) - Vec3d(x[0], x[1], x[2])).norm() <= 2 * o.tolerance);
  }
}
