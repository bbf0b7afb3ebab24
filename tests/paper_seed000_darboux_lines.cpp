// Seed 000 §6–8, App. A–B: the lines and circle families of parabolic
// Darboux cyclides, their parameterization by PRCS and PRRS (Props. 3, 5),
// and §8's conditions (55), (56) with Example 5 end to end.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cyclide/darboux_lines.hpp"
#include "seed000_equations.hpp"

namespace cyclide {
namespace {

Darboux example4(double alpha) { return seed000::eq35(alpha); }
Darboux example2() { return seed000::eq39(); }
Darboux example5_family(double alpha) { return seed000::eq60(alpha); }
Darboux example5() { return seed000::eq61(); }
Darboux appendixA(double a, double c) { return seed000::eq70(a, c); }
Darboux appendixB() { return seed000::eq73(); }

// The index of the found line equal to L (as a set), or -1.
int find_line(const ParabolicLines& A, const Line& L) {
  const Vec3d d = L.d.normalized();
  for (int i = 0; i < A.line_count; ++i) {
    const Line& F = A.lines[i].line;
    if (F.d.cross(d).norm() > 1e-9) continue;
    const Vec3d w = L.P - F.P;
    if ((w - w.dot(F.d) * F.d).norm() <= 1e-9 * (1 + L.P.norm())) return i;
  }
  return -1;
}

void expect_lines_on(const Darboux& D, const ParabolicLines& A) {
  for (int i = 0; i < A.line_count; ++i) {
    const Line& L = A.lines[i].line;
    EXPECT_NEAR(L.d.norm(), 1.0, 1e-14);
    EXPECT_NEAR(L.d.dot(A.n), 0.0, 1e-12);
    for (double s : {-2.0, 0.5, 3.0})
      EXPECT_NEAR(D.value(L.P + s * L.d), 0.0, 1e-11 * D.scale()) << "line " << i;
  }
}

// ---------------------------------------------------------------- Example 4

TEST(DarbouxLines, Example4HasSixLinesInThePlanesOfEqs36To38) {
  for (double alpha : {0.0, 1.5, -0.6}) {
    const Darboux C = example4(alpha);
    ParabolicLines A;
    ASSERT_EQ(parabolic_lines(C, A), Status::ok);
    EXPECT_NEAR(std::abs(A.n.z()), 1.0, 1e-15);
    EXPECT_EQ(A.line_count, 6);
    EXPECT_EQ(A.circle_families(), 6);  // six real families of circles
    EXPECT_EQ(A.double_families(), 0);
    EXPECT_FALSE(A.l0_circles);
    expect_lines_on(C, A);
    const Line six[6] = {{{0, 0, 0}, {1, 0, 0}},          {{0, 0, 1}, {0, 1, 0}},
                         {{0, 0, 2}, {1, 1, 0}},          {{0, 2 * alpha, 0}, {1, -3, 0}},
                         {{-alpha, 0, 1}, {3, 1, 0}},     {{0, 2 * alpha, 2}, {1, 2, 0}}};
    for (const Line& L : six) EXPECT_GE(find_line(A, L), 0);
    int pairs = 0;
    for (int i = 0; i < A.plane_count; ++i) pairs += A.planes[i].kind == SectionKind::line_pair;
    EXPECT_EQ(pairs, 3);  // z = 0, 1, 2
  }
}

// ERRATA: Fig. 3's point (2, -2, -1) lies on the member alpha = -3/5; the
// six circles through it lie in the planes through the point and each line.
TEST(DarbouxLines, Fig3SixCirclesThroughAPoint) {
  const Darboux C = example4(-0.6);
  const Vec3d X(2, -2, -1);
  ASSERT_NEAR(C.value(X), 0.0, 1e-12);
  ParabolicLines A;
  ASSERT_EQ(parabolic_lines(C, A), Status::ok);
  ASSERT_EQ(A.line_count, 6);
  for (int i = 0; i < A.line_count; ++i) {
    const Line& L = A.lines[i].line;
    const Vec3d m = L.d.cross(X - L.P).normalized();
    CircleOrLine circle;
    ASSERT_EQ(pencil_circle(C, L, m, circle), Status::ok);
    ASSERT_FALSE(circle.is_line);
    EXPECT_NEAR((X - circle.point).norm(), circle.radius, 1e-11);
    EXPECT_NEAR((X - circle.point).dot(circle.axis), 0.0, 1e-11);
    const Vec3d e1 = circle.axis.unitOrthogonal(), e2 = circle.axis.cross(e1);
    for (double th = 0; th < 6.2; th += 0.7)
      EXPECT_NEAR(C.value(circle.point + circle.radius * (std::cos(th) * e1 + std::sin(th) * e2)),
                  0.0, 1e-10);
  }
}

// -------------------------------------------------- Example 2 continued

TEST(DarbouxLines, Example2ContinuedFiveLinesOneDoubleProp2CaseII) {
  const Darboux C = example2();
  ParabolicLines A;
  ASSERT_EQ(parabolic_lines(C, A), Status::ok);
  expect_lines_on(C, A);
  EXPECT_EQ(A.line_count, 5);  // "five different real lines" besides l0
  EXPECT_EQ(A.circle_families(), 5);
  EXPECT_EQ(A.double_families(), 1);
  // l1, l2 (21); l3 (41), the double line; l1^, l2^ (43).
  const int i3 = find_line(A, {{0, 0, -0.25}, {3, -1, 0}});
  ASSERT_GE(i3, 0);
  EXPECT_EQ(A.lines[i3].multiplicity, 2);
  EXPECT_NEAR(A.lines[i3].t, -0.25, 1e-12);
  for (const Line& L : {Line{{0, 0, 0}, {1, 0, 0}}, Line{{0, 0, 1}, {2, 1, 0}},
                        Line{{0, 0, 0}, {1, -0.75, 0}}, Line{{0, 0, 1}, {1, -2, 0}}}) {
    const int i = find_line(A, L);
    ASSERT_GE(i, 0);
    EXPECT_EQ(A.lines[i].multiplicity, 1);
  }
}

// Prop. 3: the canal cyclide (39) is PRCS of two lines in the pencil of
// planes through its double line; the circles are its characteristic circles.
TEST(DarbouxLines, Prop3ParameterizesEq39ByPrcs) {
  const Darboux C = example2();
  Surface S;
  PencilInput in;
  ASSERT_EQ(parameterize_parabolic_prcs(C, -3, 3, S, &in), Status::ok);
  ParabolicLines A;
  ASSERT_EQ(parabolic_lines(C, A), Status::ok);
  EXPECT_EQ(A.lines[in.axis].multiplicity, 2);
  const Line& axis = A.lines[in.axis].line;
  for (double u : {-2.5, -1.0, 0.0, 0.4, 2.0}) {
    Vec3d c, m;
    double r2;
    ASSERT_EQ(S.circle(u, c, m, r2), Status::ok);
    EXPECT_NEAR(m.dot(axis.d), 0.0, 1e-10);               // the circle's plane
    EXPECT_NEAR(m.dot(axis.P - c), 0.0, 1e-10);           // contains the double line
    for (double v : {-4.0, -0.3, 0.0, 1.0, 7.0}) {
      double x[3];
      EvalOut o;
      o.point = x;
      ASSERT_EQ(S.eval(u, v, o), Status::ok);
      EXPECT_NEAR(C.value({x[0], x[1], x[2]}), 0.0, 1e-10 * (1 + Vec3d(x[0], x[1], x[2]).squaredNorm()));
    }
  }
  double canal = 1;
  ASSERT_EQ(S.canal_test(canal), Status::ok);
  EXPECT_LE(canal, 1e-9);
  // Example 4 has no double line: not a canal surface.
  ASSERT_EQ(parameterize_parabolic_prcs(example4(0), -1, 1, S), Status::not_canal);
}

// ---------------------------------------------------------------- Example 5

TEST(DarbouxLines, Example5SixLinesEq62And63) {
  const Darboux C = example5();
  for (double x : {-1.0, 0.3, 2.0})
    for (double y : {-0.5, 1.2}) {
      EXPECT_NEAR(C.value({x, y, 0}), 0.5 * (x - 2 * y) * y, 1e-13);                 // (62)
      EXPECT_NEAR(C.value({x, y, 1}), 0.5 * (1 + x) * (-3 + 2 * x + y), 1e-13);
      EXPECT_NEAR(C.value({x, y, 0.25}), (x - y) * (-1 + 2 * x + 6 * y) / 8, 1e-13);
    }
  ParabolicLines A;
  ASSERT_EQ(parabolic_lines(C, A), Status::ok);
  expect_lines_on(C, A);
  EXPECT_EQ(A.line_count, 6);
  EXPECT_EQ(A.double_families(), 0);
  const Line six[6] = {{{0, 0, 0}, {1, 0, 0}},   {{0, 0, 0}, {2, 1, 0}},        // l1, l2
                       {{1, 1, 1}, {-1, 2, 0}},  {{0, 0, 0.25}, {1, 1, 0}},     // l3^, l4
                       {{-1, 0, 1}, {0, 1, 0}},  {{0.5, 0, 0.25}, {-3, 1, 0}}}; // l5, l6 (63)
  for (const Line& L : six) EXPECT_GE(find_line(A, L), 0);
}

// (55), (56), mu = 1/2 (58), l4 (59), the family (60) and alpha = -13/4 (61).
TEST(DarbouxLines, Example5ConditionsMuAndL4) {
  const Line given[3] = {{{0, 0, 0}, {1, 0, 0}}, {{0, 0, 0}, {2, 1, 0}}, {{1, 1, 1}, {-2, 4, 0}}};
  PrrsLinesAnalysis A;
  ASSERT_EQ(prrs_lines_analysis(given, A), Status::ok);
  EXPECT_TRUE(A.coplanar_pair && A.common_parameter);
  EXPECT_TRUE(A.pencil);     // (55) holds
  EXPECT_FALSE(A.cyclide);   // (56) does not
  EXPECT_NEAR(A.mu, 0.5, 1e-15);
  // Not a cyclide: no member of the DCMC family contains l2.
  Darboux D;
  double residual = 0;
  ASSERT_EQ(prrs_lines_cyclide(given, D, &residual), Status::ok);
  EXPECT_GT(residual, 1e-3);

  const Line hat[3] = {given[0], given[1], {{1, 1, 1}, {-1, 2, 0}}};  // (58)
  ASSERT_EQ(prrs_lines_analysis(hat, A), Status::ok);
  EXPECT_TRUE(A.cyclide);
  EXPECT_NEAR(A.cond56, 0.0, 1e-15);
  EXPECT_NEAR(A.mu, 1.0, 1e-15);
  // (59): l4(u) = (u, u, 1/4).
  EXPECT_LE(A.l4.d.cross(Vec3d(1, 1, 0).normalized()).norm(), 1e-15);
  const Vec3d w = A.l4.P - Vec3d(0, 0, 0.25);
  EXPECT_LE((w - w.dot(A.l4.d) * A.l4.d).norm(), 1e-15);

  ASSERT_EQ(prrs_lines_cyclide(hat, D, &residual), Status::ok);
  EXPECT_LE(residual, 1e-13);
  // D is (61) up to a factor.
  const Darboux E = example5();
  const double s = D.k[kLz] / E.k[kLz];
  for (int i = 0; i < kDarbouxCoeffs; ++i) EXPECT_NEAR(D.k[i], s * E.k[i], 1e-14) << i;
  // (60) at alpha = -13/4 is (61), and every member of (60) contains l1, l3^, l4.
  const Darboux M = example5_family(-13.0 / 4);
  for (int i = 0; i < kDarbouxCoeffs; ++i) EXPECT_NEAR(M.k[i], E.k[i], 1e-15) << i;
  for (double alpha : {-2.0, 0.0, 5.0})
    for (const Line& L : {hat[0], hat[2], Line{{0, 0, 0.25}, {1, 1, 0}}})
      for (double u : {-1.5, 0.5, 2.0})
        EXPECT_NEAR(example5_family(alpha).value(L.P + u * L.d), 0.0, 1e-13);
}

// Prop. 5: PRRS of lines from the pencil through a line of (61) gives (61).
TEST(DarbouxLines, Prop5ParameterizesEq61ByPrrs) {
  const Darboux C = example5();
  Surface S;
  PencilInput in;
  ASSERT_EQ(parameterize_parabolic_prrs(C, -2, 2, S, &in), Status::ok);
  EXPECT_EQ(in.count, 3);
  for (double u : {-1.7, -0.5, 0.1, 1.3})
    for (double v : {-5.0, -0.5, 0.0, 0.8, 9.0}) {
      double x[3];
      EvalOut o;
      o.point = x;
      ASSERT_EQ(S.eval(u, v, o), Status::ok);
      EXPECT_NEAR(C.value({x[0], x[1], x[2]}), 0.0, 1e-10 * (1 + Vec3d(x[0], x[1], x[2]).squaredNorm()));
    }
}

// Prop. 5 on cyclides whose first candidate has two input lines meeting at
// u = 0, where the pencil plane's PRRS points coincide (a base point: the
// circle there is lost, and rounding had left the sampled frame at u = 0
// defined, with a circle off F). Found by fuzz_lines. The chosen input
// lines must not meet on the domain, whether or not the meeting u is a
// domain sample ([-1, 1] has u = 0 as a sample, [-0.9, 1.1] does not), and
// every point must lie on F.
TEST(DarbouxLines, Prop5AvoidsInputLinesThatMeetOnTheDomain) {
  Darboux C;
  const double k[14] = {0, 0, 0, 0x1.1511190abb306p-4, 0x1.44fb5d44f192fp-2,
                        0x1.0c2524ece63c5p-1, 0x1.d5b2e83206ba1p-3, -0x1.1377f0a6979d8p-1,
                        0x1.59051fe703a5p-1, 0x1.2851db35cc58ep-4, 1, 0x1.3ea8102921a1fp-1,
                        0x1.bbbc446c743adp-2, 0x1.3da3ced2cff47p-1};
  std::copy(k, k + 14, C.k);
  for (const double u0 : {-1.0, -0.9}) {
    const double u1 = u0 + 2;
    Surface S;
    PencilInput in;
    ASSERT_EQ(parameterize_parabolic_prrs(C, u0, u1, S, &in), Status::ok) << u0;
    for (int i = 0; i < in.count; ++i)
      for (int j = i + 1; j < in.count; ++j) {
        const Vec3d dP = in.curves[i].P - in.curves[j].P, dd = in.curves[i].d - in.curves[j].d;
        const double u = std::clamp(-dP.dot(dd) / dd.squaredNorm(), u0, u1);
        EXPECT_GT((dP + u * dd).norm(), 1e-6 * (1 + dP.norm())) << i << " " << j;
      }
    for (int a = 0; a <= 400; ++a)
      for (double v : {-3.0, -0.4, 0.0, 0.7, 5.0}) {
        const double u = u0 + (u1 - u0) * a / 400.0;
        double x[3];
        EvalOut o;
        o.point = x;
        ASSERT_EQ(S.eval(u, v, o), Status::ok) << u << " " << v;
        const Vec3d X(x[0], x[1], x[2]);
        EXPECT_LE(std::abs(C.value(X)), 1e-10 * (1 + C.gradient(X).norm()) * (1 + X.squaredNorm()))
            << "u = " << u << " v = " << v;
      }
  }
}

// ------------------------------------------------------ Appendices A and B

// Prop. 8 (ERRATA: case II is (a, c) != (0, 0)): the line element's line
// P2 + u w is a double line; a = c = 0 gives a Dupin cyclide.
TEST(DarbouxLines, AppendixAProp8Counts) {
  struct Case { double a, c; int families, doubles; };
  for (const Case& k : {Case{0, 0, 2, 2}, Case{0.5, 0.3, 3, 1}, Case{0, 0.7, 3, 1},
                        Case{-1.2, 0, 3, 1}}) {
    const Darboux C = appendixA(k.a, k.c);
    ParabolicLines A;
    ASSERT_EQ(parabolic_lines(C, A), Status::ok) << k.a << " " << k.c;
    expect_lines_on(C, A);
    EXPECT_EQ(A.circle_families(), k.families) << k.a << " " << k.c;
    EXPECT_EQ(A.double_families(), k.doubles) << k.a << " " << k.c;
    const int i2 = find_line(A, {{0, 0, 1}, {k.a, 1, k.c}});  // l2^ = P2 + u w
    ASSERT_GE(i2, 0);
    EXPECT_EQ(A.lines[i2].multiplicity, 2);
    EXPECT_GE(find_line(A, {{0, 0, 0}, {1, 0, 0}}), 0);  // l1
  }
}

// Example 3 continued: (74) is a double line, (75) and l1 simple.
TEST(DarbouxLines, AppendixBExample3ThreeLines) {
  const Darboux C = appendixB();
  ParabolicLines A;
  ASSERT_EQ(parabolic_lines(C, A), Status::ok);
  expect_lines_on(C, A);
  EXPECT_EQ(A.line_count, 3);
  EXPECT_EQ(A.double_families(), 1);
  const int i2 = find_line(A, {{1, 2, 1}, {-1, -2, 0}});  // (74)
  ASSERT_GE(i2, 0);
  EXPECT_EQ(A.lines[i2].multiplicity, 2);
  EXPECT_GE(find_line(A, {{0, 10.0 / 3, 0}, {1, -4.0 / 3, 0}}), 0);  // (75)
  EXPECT_GE(find_line(A, {{0, 0, 0}, {1, 0, 0}}), 0);                // l1
}

// ---------------------------------------------------------------- statuses

TEST(DarbouxLines, Statuses) {
  ParabolicLines A;
  Darboux sphere;
  sphere.k[kQxx] = sphere.k[kQyy] = sphere.k[kQzz] = 1;
  sphere.k[kC] = -1;
  EXPECT_EQ(parabolic_lines(sphere, A), Status::not_parabolic);
  Darboux torus;  // (X.X)^2 - ... : quartic
  torus.k[kPhi0] = 1;
  torus.k[kC] = -1;
  EXPECT_EQ(parabolic_lines(torus, A), Status::not_parabolic);
  Darboux plane_sphere;  // z (X.X - 1): reducible
  plane_sphere.k[kLz] = 1;
  plane_sphere.k[kBz] = -1;
  EXPECT_EQ(parabolic_lines(plane_sphere, A), Status::not_parabolic);
  Darboux nan = example2();
  nan.k[kQxy] = std::nan("");
  EXPECT_EQ(parabolic_lines(nan, A), Status::not_finite);
  // pencil_circle: a line not on F, a plane not through the line.
  CircleOrLine c;
  EXPECT_EQ(pencil_circle(example2(), {{0, 0, 5}, {1, 0, 0}}, {0, 1, 0}, c), Status::invalid_argument);
  EXPECT_EQ(pencil_circle(example2(), {{0, 0, 0}, {1, 0, 0}}, {1, 1, 0}, c), Status::invalid_argument);
  // The plane through l0 (z = 0) leaves the other line of the pair (43).
  ASSERT_EQ(pencil_circle(example2(), {{0, 0, 0}, {1, 0, 0}}, {0, 0, 1}, c), Status::ok);
  EXPECT_TRUE(c.is_line);
  EXPECT_LE(c.axis.cross(Vec3d(1, -0.75, 0).normalized()).norm(), 1e-14);
  // §8: l1, l2 in different planes: Prop. 4 does not apply.
  const Line skew[3] = {{{0, 0, 0}, {1, 0, 0}}, {{0, 0, 0.5}, {2, 1, 0}}, {{1, 1, 1}, {-1, 2, 0}}};
  PrrsLinesAnalysis P;
  ASSERT_EQ(prrs_lines_analysis(skew, P), Status::ok);
  EXPECT_FALSE(P.coplanar_pair);
  EXPECT_FALSE(P.cyclide);
  Darboux D;
  EXPECT_EQ(prrs_lines_cyclide(skew, D), Status::invalid_argument);
  const Line par[3] = {{{0, 0, 0}, {1, 0, 0}}, {{0, 0, 0}, {2, 0, 0}}, {{1, 1, 1}, {-1, 2, 0}}};
  EXPECT_EQ(prrs_lines_analysis(par, P), Status::parallel_lines);
  // Two double lines only (the Dupin case of App. A): Prop. 3 lacks lines.
  Surface S;
  EXPECT_EQ(parameterize_parabolic_prcs(appendixA(0, 0), -1, 1, S), Status::too_few_lines);
}

// Regression (fuzz_lines, fuzz/corpus/fuzz_lines/regress-subnormal-normal):
// subnormal coefficients made |l| underflow to 0, and parabolic_lines
// returned ok with a NaN normal. The analysis now divides by a power of two
// near max |k| first, so 2^-1072 x (39) gives exactly the lines of (39).
TEST(DarbouxLines, RegressionSubnormalCoefficientsGiveTheSameLines) {
  const Darboux D = example2();
  Darboux tiny = D;
  for (double& v : tiny.k) v = std::ldexp(v, -1072);
  ParabolicLines A, B;
  ASSERT_EQ(parabolic_lines(D, A), Status::ok);
  ASSERT_EQ(parabolic_lines(tiny, B), Status::ok);
  ASSERT_TRUE(B.n.allFinite());
  ASSERT_EQ(B.line_count, A.line_count);
  EXPECT_EQ(B.plane_count, A.plane_count);
  for (int i = 0; i < A.line_count; ++i) {
    EXPECT_EQ(B.lines[i].line.P, A.lines[i].line.P) << i;
    EXPECT_EQ(B.lines[i].line.d, A.lines[i].line.d) << i;
    EXPECT_EQ(B.lines[i].t, A.lines[i].t) << i;
  }
}

// Regression (fuzz_lines, fuzz/corpus/fuzz_lines/regress-two-close-line-pair-
// planes): F = z |X|^2 - y^2 - 3.25 z^2 + xy/2 - 127.5078125 xz + yz/2 + 3z/4
// has degenerate planes z = 0 and z = 1.1556959730e-5 (det M(t) = t (65536 t^4
// - 278528 t^3 - 266121089 t^2 + 265816929 t - 3072) / 65536, exact). Scaled
// by L ~ 64 they are 1.8e-7 apart, where det M at their midpoint is
// rounding-sized: the cluster was taken for a double root at the midpoint,
// whose conic is a line pair, and its lines were off F by a relative 5e-8.
// Now both planes are found and every line is on F.
TEST(DarbouxLines, RegressionTwoCloseLinePairPlanesAreBothFound) {
  Darboux D;
  const double k[14] = {0, 0, 0, 1, 0, -1, -3.25, 0.5, -127.5078125, 0.5, 0, 0, 0.75, 0};
  std::copy(k, k + 14, D.k);
  ParabolicLines A;
  ASSERT_EQ(parabolic_lines(D, A), Status::ok);
  bool at0 = false, at1 = false;
  for (int i = 0; i < A.plane_count; ++i) {
    at0 = at0 || std::abs(A.planes[i].t) <= 1e-12;
    at1 = at1 || std::abs(A.planes[i].t - 1.1556959730040821604e-5) <= 1e-12;
  }
  EXPECT_TRUE(at0);
  EXPECT_TRUE(at1);
  for (int i = 0; i < A.line_count; ++i) {
    const Line& L = A.lines[i].line;
    for (double s : {-10.0, 0.0, 10.0}) {
      const Vec3d X = L.P + s * L.d;
      // |F| against the size of its terms along the line (|X| <= ~70).
      EXPECT_LE(std::abs(D.value(X)), 1e-12 * 128 * std::pow(1 + X.norm(), 3)) << i << " " << s;
    }
  }
}

}  // namespace
}  // namespace cyclide
