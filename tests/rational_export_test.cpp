// Exact rational Bezier export (issue 9 item 1; rational_export.hpp), label
// export. Every exported patch is evaluated at 9 x 9 local parameters and
// compared with Surface::eval at the corresponding (u, v); the patches must
// tile the requested rectangle (u-major, contiguous) with positive weights.
//
// Tolerance kExportTol = 1e-12: patch point vs Surface::eval, relative to
// the surface's size, the largest |x| sampled. The property draws
// well-conditioned frames only (|o| + |p - o| <= kMaxFrameSize = 20 on the
// exported interval): random perturbations of the inputs can bring a spine
// or directrix near a pole, and there (|x| ~ 500, |x_u| ~ 1e5, or a spine
// 18 away from points of size 1) the export missed by up to 1.35e-12
// relative, or ran out of pieces (numerical_overflow, as documented);
// rational_export.cpp computes its products in long double since the
// spine case (3e-12 in double).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "cyclide/dupin.hpp"
#include "cyclide/exact.hpp"
#include "cyclide/lie.hpp"
#include "cyclide/rational_export.hpp"
#include "cyclide/surface.hpp"

using namespace cyclide;

namespace {

constexpr double kExportTol = 1e-12;

RationalCurve line(Vec3d P, Vec3d d) {
  RationalCurve c;
  EXPECT_EQ(make_line(P, d, c), Status::ok);
  return c;
}
RationalCurve cubic(const double (&c)[12]) {
  RationalCurve r;
  EXPECT_EQ(make_polynomial_curve(3, c, r), Status::ok);
  return r;
}

// Example 2 of seed 000: PRCS of the lines (u, 0, 0) and (2u, u, 1).
Surface example2(const Mobius* f = nullptr) {
  Surface S;
  EXPECT_EQ(make_prcs(line({0, 0, 0}, {1, 0, 0}), line({0, 0, 1}, {2, 1, 0}), f, -0.5, 0.5, S),
            Status::ok);
  return S;
}

// PRCS of two polynomial cubics (blend_test's canal()).
const double kC1[12] = {0, 0, 0, 1, 0.2, 0, 0, 0.5, 0.1, 0.05, 0, 0};
const double kC2[12] = {0, 1, 0.5, 1, -0.1, 0.3, 0.2, 0, 0, 0, 0.1, 0};
Surface canal(const Mobius* f = nullptr) {
  Surface S;
  EXPECT_EQ(make_prcs(cubic(kC1), cubic(kC2), f, 0.0, 1.0, S), Status::ok);
  return S;
}

// PRRS of three polynomial cubics (kernels_test's curves).
const double kP1[12] = {0, 0, 0, 1, 0, 0, 0, 0.05, 0.02, 0.1, 0, -0.05};
const double kP2[12] = {0, 0, 1, 2, 1, 0, 0.03, 0, 0.05, -0.05, 0.1, 0};
const double kP3[12] = {0, 2, 0, -1, 0, 1, 0, -0.1, 0, 0.05, 0, 0.1};
Surface prrs(const Mobius* f = nullptr) {
  Surface S;
  EXPECT_EQ(make_prrs(cubic(kP1), cubic(kP2), cubic(kP3), f, -1, 1, S), Status::ok);
  return S;
}

// Ringed (d, n, c): directrix d a cubic, orientation n a quadratic, the
// circles through the cubic c.
Surface ringed(const Mobius* f = nullptr) {
  const double d[12] = {0, 0, 0, 1, 0.5, 0, 0, 0.25, 1, 0, 0, 0.125};
  const double n[9] = {1, 0, 0, 0, 0.5, 0.2, 0.1, 0, 0.3};
  const double c[12] = {0, 1, 0.2, 1, 0.3, 0, 0.1, 0.2, 0.9, 0, -0.1, 0.1};
  RationalCurve D, N, C;
  EXPECT_EQ(make_polynomial_curve(3, d, D), Status::ok);
  EXPECT_EQ(make_polynomial_curve(2, n, N), Status::ok);
  EXPECT_EQ(make_polynomial_curve(3, c, C), Status::ok);
  Surface S;
  EXPECT_EQ(make_ringed(D, N, C, f, -1, 1, S), Status::ok);
  return S;
}

// f = ((1 + u) v + 0.3 u^2) / (0.2 u v + 1.5 - u): non-constant in u.
Mobius varying_f() {
  const double al[3] = {1, 1, 0}, be[3] = {0, 0, 0.3}, ga[3] = {0, 0.2, 0}, de[3] = {1.5, -1, 0};
  Mobius m;
  EXPECT_EQ(make_mobius(2, al, be, ga, de, m), Status::ok);
  return m;
}

// (E4): m = n_o + n_p + 2 (n_a + n_f) from the exact frame over [ua, ub].
int header_degree(const Surface& S, double ua, double ub) {
  ExactFrame E;
  const double mid = 0.5 * (ua + ub), half = 0.5 * (ub - ua);
  Status st = Status::internal_error;
  if (S.kind == SurfaceKind::prcs) st = exact_prcs_frame(S.curve[0], S.curve[1], E, mid, half);
  if (S.kind == SurfaceKind::prrs)
    st = exact_prrs_frame(S.curve[0], S.curve[1], S.curve[2], E, mid, half);
  if (S.kind == SurfaceKind::ringed)
    st = exact_ringed_frame(S.curve[0], S.curve[1], S.curve[2], E, mid, half);
  EXPECT_EQ(st, Status::ok);
  auto n = [](const ExactVec3& e) { return std::max({e.x.deg, e.y.deg, e.z.deg, e.w.deg}); };
  const int nf = std::max({S.f.alpha.deg, S.f.beta.deg, S.f.gamma.deg, S.f.delta.deg});
  return n(E.o) + n(E.p) + 2 * (n(E.a) + nf);
}

struct Report {
  double max_rel_err = 0;  // relative to the largest |x|
  double min_weight = HUGE_VAL;
  bool tiles = true;
};

Vec3d surface_point(const Surface& S, double u, double v) {
  if (std::isinf(v)) v = std::copysign(1e300, v);
  double x[3];
  EXPECT_EQ(S.eval(u, v, {x, nullptr, nullptr, nullptr}), Status::ok) << u << " " << v;
  return Vec3d(x[0], x[1], x[2]);
}

// Checks the patches of an export over D: accuracy, weights, tiling.
Report check(const Surface& S, const ExportDomain& D, const std::vector<RationalBezierPatch>& P) {
  Report R;
  double size = 0, err = 0;
  for (const RationalBezierPatch& p : P) {
    EXPECT_EQ(p.deg_v, 2);
    for (int i = 0; i < (p.deg_u + 1) * (p.deg_v + 1); ++i)
      R.min_weight = std::min(R.min_weight, p.cp[i][0]);
    for (int a = 0; a <= 8; ++a)
      for (int b = 0; b <= 8; ++b) {
        const double s = a / 8.0, t = b / 8.0;
        double u, v;
        patch_parameters(p, s, t, u, v);
        const Vec3d x = surface_point(S, u, v), y = patch_point(p, s, t);
        size = std::max(size, x.norm());
        err = std::max(err, (x - y).norm());
      }
  }
  R.max_rel_err = err / size;
  // Tiling: u-intervals contiguous from D.u0 to D.u1; within each, the
  // v-pieces contiguous from D.v0 to D.v1 (-inf to inf for whole circles).
  const double va = D.whole_circle ? -HUGE_VAL : D.v0, vb = D.whole_circle ? HUGE_VAL : D.v1;
  double u_expect = D.u0;
  size_t k = 0;
  while (k < P.size()) {
    const double u0 = P[k].u0, u1 = P[k].u1;
    if (u0 != u_expect || !(u1 > u0)) R.tiles = false;
    double v_expect = va;
    while (k < P.size() && P[k].u0 == u0) {
      if (P[k].u1 != u1 || P[k].v0 != v_expect || !(P[k].v1 > P[k].v0)) R.tiles = false;
      v_expect = P[k].v1;
      ++k;
    }
    if (v_expect != vb) R.tiles = false;
    u_expect = u1;
  }
  if (u_expect != D.u1) R.tiles = false;
  return R;
}

std::vector<RationalBezierPatch> export_all(const Surface& S, const ExportDomain& D,
                                            Status expect = Status::ok) {
  int count = -1;
  EXPECT_EQ(rational_bezier_patch_count(S, D, count), expect);
  if (expect != Status::ok) return {};
  std::vector<RationalBezierPatch> P(count);
  int written = -1;
  EXPECT_EQ(export_rational_bezier(S, D, P.data(), count, written), Status::ok);
  EXPECT_EQ(written, count);
  P.resize(std::max(0, written));
  return P;
}

void expect_exact(const Surface& S, const ExportDomain& D, int deg_u, int min_patches,
                  int max_patches) {
  const std::vector<RationalBezierPatch> P = export_all(S, D);
  ASSERT_GE(int(P.size()), min_patches);
  ASSERT_LE(int(P.size()), max_patches);
  EXPECT_EQ(header_degree(S, D.u0, D.u1), deg_u);
  for (const RationalBezierPatch& p : P) EXPECT_EQ(p.deg_u, deg_u);
  const Report R = check(S, D, P);
  EXPECT_LE(R.max_rel_err, kExportTol);
  EXPECT_GT(R.min_weight, 0.0);
  EXPECT_TRUE(R.tiles);
}

}  // namespace

// The degrees of the header's examples (E4): m = n_o + n_p + 2 (n_a + n_f).
TEST(RationalExport, Example2LinesRectangleAndWholeCircle) {
  const Surface S = example2();
  // |a| = |s'| >= sqrt(10): v in [-1, 1] is an arc of < 120 degrees.
  expect_exact(S, ExportDomain::rectangle(-0.5, 0.5, -1, 1), 5, 1, 1);
  expect_exact(S, ExportDomain::rectangle(-0.3, 0.4, -2.5, 7), 5, 2, 16);
  expect_exact(S, ExportDomain::circles(-0.5, 0.5), 5, 4, 32);
}

TEST(RationalExport, CubicCanalSurface) {
  const Surface S = canal();
  expect_exact(S, ExportDomain::rectangle(0.1, 0.9, -0.7, 2.0), 43, 2, 64);
  expect_exact(S, ExportDomain::circles(0.0, 1.0), 43, 4, 64);
}

TEST(RationalExport, CubicPrrs) {
  const Surface S = prrs();
  expect_exact(S, ExportDomain::rectangle(-1, 1, -3, 0.5), 30, 2, 64);
  expect_exact(S, ExportDomain::circles(-0.6, 0.8), 30, 4, 64);
}

TEST(RationalExport, RingedDnc) {
  const Surface S = ringed();
  expect_exact(S, ExportDomain::rectangle(-1, 1, -0.25, 0.25), 10, 1, 16);
  expect_exact(S, ExportDomain::circles(-1, 1), 10, 4, 64);
}

TEST(RationalExport, VaryingMobius) {
  const Mobius f = varying_f();
  // n_f = 2 adds 4 to each degree.
  expect_exact(example2(&f), ExportDomain::circles(-0.5, 0.5), 9, 4, 64);
  expect_exact(canal(&f), ExportDomain::circles(0.0, 1.0), 47, 4, 64);
  expect_exact(prrs(&f), ExportDomain::rectangle(-1, 1, -5, 5), 34, 3, 64);
  expect_exact(ringed(&f), ExportDomain::circles(-0.5, 1), 14, 4, 64);
}

TEST(RationalExport, ReciprocalPiecesEndAtInfinityAndOrientV) {
  const Surface S = example2();
  const std::vector<RationalBezierPatch> P = export_all(S, ExportDomain::circles(-0.5, 0.5));
  ASSERT_FALSE(P.empty());
  EXPECT_TRUE(P.front().reciprocal_v);
  EXPECT_EQ(P.front().v0, -HUGE_VAL);
  EXPECT_EQ(P.back().v1, HUGE_VAL);
  // The generator p(u) (f = infinity) is the patch's edge t = 0.
  for (double s : {0.0, 0.3, 1.0}) {
    double u, v;
    patch_parameters(P.front(), s, 0.0, u, v);
    EXPECT_EQ(v, -HUGE_VAL);
    const Vec3d p(u, 0, 0);  // p1 = l1(u)
    EXPECT_LE((patch_point(P.front(), s, 0.0) - p).norm(), 1e-14);
  }
  // v increases with t on every patch (consistent orientation).
  for (const RationalBezierPatch& p : P) {
    double u, va, vb;
    patch_parameters(p, 0.5, 0.25, u, va);
    patch_parameters(p, 0.5, 0.75, u, vb);
    EXPECT_LT(va, vb);
  }
}

TEST(RationalExport, CountMatchesAndBufferTooSmallWritesNothing) {
  const Surface S = prrs();
  const ExportDomain D = ExportDomain::circles(-1, 1);
  int count = 0;
  ASSERT_EQ(rational_bezier_patch_count(S, D, count), Status::ok);
  ASSERT_GE(count, 4);
  std::vector<RationalBezierPatch> P(count);
  for (RationalBezierPatch& p : P) p.deg_u = -7;
  int got = 0;
  EXPECT_EQ(export_rational_bezier(S, D, P.data(), count - 1, got), Status::buffer_too_small);
  EXPECT_EQ(got, count);
  for (const RationalBezierPatch& p : P) EXPECT_EQ(p.deg_u, -7);
  EXPECT_EQ(export_rational_bezier(S, D, nullptr, 0, got), Status::buffer_too_small);
  EXPECT_EQ(got, count);
  EXPECT_EQ(export_rational_bezier(S, D, nullptr, count, got), Status::null_argument);
  EXPECT_EQ(got, 0);
  EXPECT_EQ(export_rational_bezier(S, D, P.data(), count, got), Status::ok);
  EXPECT_EQ(got, count);
}

TEST(RationalExport, BadDomains) {
  const Surface S = canal();  // domain [0, 1]
  const double nan = std::nan("");
  std::vector<RationalBezierPatch> P(64);
  for (const ExportDomain& D :
       {ExportDomain::rectangle(nan, 1, 0, 1), ExportDomain::rectangle(0, nan, 0, 1),
        ExportDomain::rectangle(0, 1, nan, 1), ExportDomain::rectangle(0, 1, 0, nan),
        ExportDomain::rectangle(0, 1, -HUGE_VAL, 1), ExportDomain::circles(0, HUGE_VAL)}) {
    int count = 5;
    EXPECT_EQ(export_rational_bezier(S, D, P.data(), 64, count), Status::not_finite);
    EXPECT_EQ(count, 0);
    EXPECT_EQ(rational_bezier_patch_count(S, D, count), Status::not_finite);
  }
  const ExportDomain bad[] = {
      ExportDomain::rectangle(0.5, 0.5, 0, 1), ExportDomain::rectangle(0.6, 0.5, 0, 1),
      ExportDomain::rectangle(0, 1, 1, 1),    ExportDomain::rectangle(0, 1, 2, 1),
      ExportDomain::rectangle(-0.1, 1, 0, 1), ExportDomain::rectangle(0, 1.1, 0, 1),
      ExportDomain::circles(0.2, 0.1),
      ExportDomain::circles(-1, 0.5)};
  for (const ExportDomain& D : bad) {
    int count = 5;
    EXPECT_EQ(export_rational_bezier(S, D, P.data(), 64, count), Status::bad_domain)
        << D.u0 << " " << D.u1 << " " << D.v0 << " " << D.v1;
    EXPECT_EQ(count, 0);
    EXPECT_EQ(rational_bezier_patch_count(S, D, count), Status::bad_domain);
  }
}

TEST(RationalExport, DupinAndParabolicAreUnsupported) {
  Surface P;
  ASSERT_EQ(make_parabolic_cyclide_surface(ParabolicCyclide{}, -1, 1, P), Status::ok);
  const LieSphere s[3] = {oriented_sphere(Vec3d(3, 0, 0), 1), oriented_sphere(Vec3d(0, 3, 0), 1),
                          oriented_sphere(Vec3d(-3, 0, 0), 1)};
  DupinView V;
  ASSERT_EQ(dupin_from_spheres(s, V.cyclide), Status::ok);
  Surface T;
  ASSERT_EQ(make_dupin_surface(V, -0.5, 0.5, T), Status::ok);
  int count = 3;
  EXPECT_EQ(rational_bezier_patch_count(P, ExportDomain::circles(-1, 1), count),
            Status::unsupported);
  EXPECT_EQ(count, 0);
  std::vector<RationalBezierPatch> out(8);
  EXPECT_EQ(export_rational_bezier(T, ExportDomain::circles(-0.5, 0.5), out.data(), 8, count),
            Status::unsupported);
}

TEST(RationalExport, PoleOfTheDirectrixIsAPointAtInfinity) {
  // d = Bezier (0,0,0) w 1 -> (1,0,0) w -2: weight 1 - 3u vanishes at u = 1/3,
  // between the creation samples.
  const double ctrl[6] = {0, 0, 0, 1, 0, 0}, w[2] = {1, -2};
  RationalCurve d, n, c;
  ASSERT_EQ(make_bezier_curve(1, ctrl, w, 0, 1, d), Status::ok);
  ASSERT_EQ(make_point({0, 0, 1}, n), Status::ok);
  ASSERT_EQ(make_line({0, 1, 0}, {0.5, 0, 0.2}, c), Status::ok);
  Surface S;
  ASSERT_EQ(make_ringed(d, n, c, nullptr, 0, 1, S), Status::ok);
  int count = 0;
  EXPECT_EQ(rational_bezier_patch_count(S, ExportDomain::circles(0, 1), count),
            Status::point_at_infinity);
  // Away from the pole the export is exact.
  expect_exact(S, ExportDomain::circles(0.5, 1), 2, 4, 64);
}

TEST(RationalExport, RationalBezierInputs) {
  // PRCS of a rational quadratic Bezier curve and a line.
  const double ctrl[9] = {0, 0, 0, 1, 0.5, 0.2, 2, 0, 0.4}, w[3] = {1, 0.6, 1.3};
  RationalCurve b;
  ASSERT_EQ(make_bezier_curve(2, ctrl, w, 0, 1, b), Status::ok);
  Surface S;
  ASSERT_EQ(make_prcs(b, line({0, 0, 1.5}, {0.5, 1, 0}), nullptr, 0, 1, S), Status::ok);
  const std::vector<RationalBezierPatch> P = export_all(S, ExportDomain::circles(0, 1));
  ASSERT_FALSE(P.empty());
  const Report R = check(S, ExportDomain::circles(0, 1), P);
  EXPECT_LE(R.max_rel_err, kExportTol);
  EXPECT_GT(R.min_weight, 0.0);
  EXPECT_TRUE(R.tiles);
}

// PRCS of two rational quartics (exact frame degrees: spine 34, s' 55).
Surface rational_quartic_canal(const Mobius* f) {
  double c1[20], c2[20];
  for (int k = 0; k < 5; ++k) {
    const double x[4] = {double(k), 0.3 * k * k, 0.1 * (k % 2), 1.0 + 0.2 * k};
    const double y[4] = {0.5 * k, 1.0 - 0.1 * k, 1.0 + 0.05 * k * k, 1.0 + 0.1 * (k % 3)};
    for (int j = 0; j < 4; ++j) {
      c1[4 * k + j] = x[j];
      c2[4 * k + j] = y[j];
    }
  }
  RationalCurve p1, p2;
  EXPECT_EQ(make_rational_curve(4, c1, p1), Status::ok);
  EXPECT_EQ(make_rational_curve(4, c2, p2), Status::ok);
  Surface S;
  EXPECT_EQ(make_prcs(p1, p2, f, 0, 1, S), Status::ok);
  return S;
}

TEST(RationalExport, LineElementAndPointInputs) {
  // PRCS of a cubic and a line element (seed 000 §3); PRRS of a point and
  // two cubics (§4).
  RationalCurve le, pt;
  ASSERT_EQ(make_line_element({0.2, 1.5, 0.3}, {0.3, 1, 0.2}, le), Status::ok);
  ASSERT_EQ(make_point({0.1, 2.0, -0.5}, pt), Status::ok);
  Surface A, B;
  ASSERT_EQ(make_prcs(cubic(kC1), le, nullptr, 0, 1, A), Status::ok);
  ASSERT_EQ(make_prrs(pt, cubic(kP2), cubic(kP3), nullptr, -1, 1, B), Status::ok);
  expect_exact(A, ExportDomain::circles(0, 1), header_degree(A, 0, 1), 4, 64);
  expect_exact(B, ExportDomain::rectangle(-0.5, 1, -1.5, 2.5), header_degree(B, -0.5, 1), 3, 64);
}

TEST(RationalExport, DegreeTooHigh) {
  // m = 34 + 4 + 2 (55 + 15) = 178 > kMaxExportDegree with f of degree 15.
  double al[16] = {1}, be[16] = {}, ga[16] = {}, de[16] = {1};
  ga[15] = 1e-3;
  Mobius f;
  ASSERT_EQ(make_mobius(15, al, be, ga, de, f), Status::ok);
  const Surface S = rational_quartic_canal(&f);
  int count = 1;
  EXPECT_EQ(rational_bezier_patch_count(S, ExportDomain::circles(0, 1), count),
            Status::degree_too_high);
  EXPECT_EQ(count, 0);
}

TEST(RationalExport, IllConditionedExactFormIsReportedNotExported) {
  // With f = v, m = 148 fits, but the power-form exact frame of degree 55
  // has lost the weights' small values (~1e-10 of their largest): on [0, 1]
  // they cannot be made positive, on [0, 0.5] the patches miss
  // Surface::eval by more than kExportCheckTol. On [0, 0.1] (trimmed
  // degree 63) the export is exact again.
  const Surface S = rational_quartic_canal(nullptr);
  int count = 1;
  EXPECT_EQ(rational_bezier_patch_count(S, ExportDomain::circles(0, 1), count),
            Status::numerical_overflow);
  std::vector<RationalBezierPatch> P(64);
  EXPECT_EQ(export_rational_bezier(S, ExportDomain::circles(0, 0.5), P.data(), 64, count),
            Status::numerical_overflow);
  EXPECT_EQ(count, 0);
  expect_exact(S, ExportDomain::circles(0, 0.1), 63, 4, 64);
}

TEST(RationalExport, SpinePoleMissedByTheBuilderIsAPointAtInfinity) {
  // PRCS of two rational cubic Bezier curves whose spine passes through
  // infinity near u = 0.169 (D changes sign; the creation samples only saw
  // |s| large): the export finds it.
  const double b2[12] = {0, 1, 1, 1, 1.5, 1.2, 2, 0.8, 1.4, 3, 1.1, 1.0}, w2[4] = {1.1, 0.8, 1.0, 1.2};
  const double b3[12] = {0, -1, 0, 1, -1.5, 0.2, 2, -0.8, -0.4, 3, -1.1, 0.3}, w3[4] = {1, 1.2, 0.8, 1};
  RationalCurve q2, q3;
  ASSERT_EQ(make_bezier_curve(3, b2, w2, 0, 1, q2), Status::ok);
  ASSERT_EQ(make_bezier_curve(3, b3, w3, 0, 1, q3), Status::ok);
  Surface S;
  ASSERT_EQ(make_prcs(q2, q3, nullptr, 0, 1, S), Status::ok);
  int count = 1;
  EXPECT_EQ(rational_bezier_patch_count(S, ExportDomain::circles(0, 0.2), count),
            Status::point_at_infinity);
  EXPECT_EQ(count, 0);
  expect_exact(S, ExportDomain::circles(0.3, 0.4), 44, 4, 64);
}

TEST(RationalExport, BernsteinFromPowerIsStable) {
  // t^n on [-1, 1] has Bernstein coefficients (-1)^(n-i); n = 60.
  const int n = 60;
  std::vector<double> c(n + 1, 0.0), b(n + 1);
  c[n] = 1.0;
  bernstein_from_power(c.data(), n, -1.0, 1.0, b.data());
  for (int i = 0; i <= n; ++i) EXPECT_NEAR(b[i], ((n - i) % 2) ? -1.0 : 1.0, 1e-13) << i;
  // A cubic on [0.5, 2] against poly.hpp's to_bernstein (fine at low degree).
  Poly<double, 3> p;
  const double pc[4] = {1, -2, 0.5, 3};
  p.assign(pc, 3);
  double ref[4], mine[4];
  to_bernstein(p, 0.5, 2.0, ref);
  bernstein_from_power(pc, 3, 0.5, 2.0, mine);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(mine[i], ref[i], 1e-13);
}

constexpr double kMaxFrameSize = 20.0;

// Random polynomial cubic PRRS / PRCS / ringed surfaces, random
// sub-rectangles or whole circles: every export is exact to kExportTol.
RC_GTEST_PROP(RationalExportProperties, ExportsAreExact, ()) {
  const int kind = *rc::gen::inRange(1, 4);
  auto coef = [] { return *rc::gen::inRange(-100, 101) / 100.0; };
  double c[3][12];
  const double base[3][12] = {{0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0},
                              {0, 0, 1, 2, 1, 0, 0, 0, 0, 0, 0, 0},
                              {0, 2, 0, -1, 0, 1, 0, 0, 0, 0, 0, 0}};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 12; ++k) c[i][k] = base[i][k] + 0.2 * coef();
  RationalCurve C[3];
  for (int i = 0; i < 3; ++i) RC_PRE(make_polynomial_curve(3, c[i], C[i]) == Status::ok);
  Mobius f;
  const bool vary = *rc::gen::inRange(0, 2) == 1;
  if (vary) {
    const double al[2] = {1, 0.3 * coef()}, be[2] = {0.3 * coef(), 0.3 * coef()};
    const double ga[2] = {0.3 * coef(), 0.3 * coef()}, de[2] = {1, 0.3 * coef()};
    RC_PRE(make_mobius(1, al, be, ga, de, f) == Status::ok);
  }
  Surface S;
  Status st = Status::internal_error;
  if (kind == 1) st = make_prcs(C[0], C[1], &f, -1, 1, S);
  if (kind == 2) st = make_prrs(C[0], C[1], C[2], &f, -1, 1, S);
  if (kind == 3) st = make_ringed(C[0], C[2], C[1], &f, -1, 1, S);
  RC_PRE(st == Status::ok);
  const double ua = -1 + *rc::gen::inRange(0, 50) / 50.0, ub = ua + *rc::gen::inRange(1, 51) / 50.0;
  const bool whole = *rc::gen::inRange(0, 2) == 1;
  const double va = *rc::gen::inRange(-400, 400) / 100.0;
  const double vb = va + *rc::gen::inRange(1, 400) / 100.0;
  const ExportDomain D = whole ? ExportDomain::circles(ua, ub) : ExportDomain::rectangle(ua, ub, va, vb);
  // Well-conditioned frames only: |o| + |p - o| <= kMaxFrameSize on [ua, ub]
  // (the perturbations can bring a spine or directrix near a pole, where
  // the surface reaches |x| ~ 500 and |x_u| ~ 1e5; there the export misses
  // by ~1e-12 or runs out of pieces: numerical_overflow).
  for (int k = 0; k <= 32; ++k) {
    CircleFrame<Taylor<double, 0>> F;
    RC_PRE(S.frame<0>(ua + (ub - ua) * k / 32.0, F) == Status::ok);
    Vec3d o, d;
    for (int j = 0; j < 3; ++j) {
      o[j] = F.o[j].c[0];
      d[j] = F.p[j].c[0] - F.o[j].c[0];
    }
    RC_PRE(o.norm() + d.norm() <= kMaxFrameSize);
  }
  int count = 0;
  st = rational_bezier_patch_count(S, D, count);
  // A surface passing through infinity (PRCS spine det 0) is no counterexample.
  RC_PRE(st != Status::point_at_infinity);
  RC_LOG() << "kind " << kind << " f varies " << vary << " u " << ua << " " << ub << " whole "
           << whole << " v " << va << " " << vb << " status " << status_name(st) << "\n";
  RC_ASSERT(st == Status::ok);
  std::vector<RationalBezierPatch> P(count);
  int got = 0;
  RC_ASSERT(export_rational_bezier(S, D, P.data(), count, got) == Status::ok);
  RC_ASSERT(got == count);
  const Report R = check(S, D, P);
  RC_LOG() << "error " << R.max_rel_err << " degree " << P[0].deg_u << " patches " << count
           << "\n";
  RC_ASSERT(R.max_rel_err <= kExportTol);
  for (const RationalBezierPatch& p : P) RC_ASSERT(p.deg_u == header_degree(S, ua, ub));
  RC_ASSERT(R.min_weight > 0.0);
  RC_ASSERT(R.tiles);
}
