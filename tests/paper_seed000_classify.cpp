// Seed 000 §7 and Appendices A, B: the implicitization fit of PRCS/PRRS
// outputs against the printed equations (39), (70), (73), the lines
// (41)-(43), (71)-(72), (74)-(75), and the closed-form classification of
// Props. 2, 8 (with ERRATA), 9 with every case and its counts.
#include <gtest/gtest.h>

#include <cmath>

#include "cyclide/darboux_classify.hpp"
#include "cyclide/implicitize.hpp"
#include "cyclide/surface.hpp"
#include "seed000_equations.hpp"

using namespace cyclide;
using seed000::eq39;
using seed000::eq73;

namespace {

RationalCurve line(Vec3d P, Vec3d d) {
  RationalCurve c;
  EXPECT_EQ(make_line(P, d, c), Status::ok);
  return c;
}
RationalCurve point(Vec3d P) {
  RationalCurve c;
  EXPECT_EQ(make_point(P, c), Status::ok);
  return c;
}
RationalCurve element(Vec3d P, Vec3d t) {
  RationalCurve c;
  EXPECT_EQ(make_line_element(P, t, c), Status::ok);
  return c;
}

DarbouxFit fit(const Surface& S) {
  DarbouxFit F;
  EXPECT_EQ(fit_darboux(S, F), Status::ok);
  EXPECT_TRUE(F.is_darboux) << F.residual;
  EXPECT_LE(F.residual, kDarbouxFitTol);
  EXPECT_EQ(F.nullity, 1);
  return F;
}

// max |A - t B| / max|A| for the t that matches the largest coefficient.
double up_to_scale(const Darboux& A, const Darboux& B) {
  int i = 0;
  for (int j = 0; j < kDarbouxCoeffs; ++j)
    if (std::abs(A.k[j]) > std::abs(A.k[i])) i = j;
  const double t = A.k[i] / B.k[i];
  double r = 0;
  for (int j = 0; j < kDarbouxCoeffs; ++j) r = std::max(r, std::abs(A.k[j] - t * B.k[j]));
  return r / std::abs(A.k[i]);
}

Darboux normalized(Darboux D) {
  const double s = D.scale();
  for (double& k : D.k) k /= s;
  return D;
}

// |F(X)| relative to the size of the terms at X (F normalized to max 1).
double algebraic(const Darboux& D, const Vec3d& X) {
  const double r = 1 + X.squaredNorm();
  return std::abs(normalized(D).value(X)) / (r * r);
}
double gradient_size(const Darboux& D, const Vec3d& X) {
  const double r = 1 + X.norm();
  return normalized(D).gradient(X).norm() / (r * r * r);
}
// A "double line" of the paper is a double component of a plane section
// through the line at infinity l0 (the planes l.X = const): the plane is
// tangent along it, so grad F is parallel to l there (grad F = 0 only at
// the singular points). Returns |grad F x l^| relative like gradient_size.
double double_line(const Darboux& D, const Vec3d& X) {
  const double r = 1 + X.norm();
  const Darboux N = normalized(D);
  return N.gradient(X).cross(N.l().normalized()).norm() / (r * r * r);
}

constexpr double kOn = 1e-9;  // algebraic residual of fitted equations

const double kTs[] = {-3.0, -1.1, -0.25, 0.0, 0.6, 2.0, 5.0};

// A fixed similarity (rotation about (1, 2, 2)/3, scale 2.5, translation).
Similarity some_similarity() {
  Similarity T;
  T.R = Eigen::AngleAxisd(0.7, Vec3d(1, 2, 2) / 3).toRotationMatrix();
  T.scale = 2.5;
  T.origin = Vec3d(0.3, -1.2, 0.8);
  return T;
}

}  // namespace

// ---------------------------------------------------------------- §7

TEST(Example2Continued, FitEqualsEq39AndLines41To43LieOnIt) {
  Surface S;
  ASSERT_EQ(make_prcs(line({0, 0, 0}, {1, 0, 0}), line({0, 0, 1}, {2, 1, 0}), nullptr, -0.5, 0.5,
                      S),
            Status::ok);
  const DarbouxFit F = fit(S);
  EXPECT_LE(up_to_scale(F.D, eq39()), 1e-10);
  EXPECT_EQ(darboux_type(F.D), DarbouxType::parabolic);
  // (42): lambda = w.w / (w.w - 1) = 5/4; (41): l3 = lambda l1 + (1 - lambda) l2.
  const double lambda = 5.0 / (5.0 - 1.0);
  EXPECT_EQ(lambda, 1.25);
  for (double u : kTs) {
    const Vec3d l3 = lambda * Vec3d(u, 0, 0) + (1 - lambda) * Vec3d(2 * u, u, 1);
    EXPECT_LE((l3 - Vec3d(3 * u, -u, -1) / 4).norm(), 1e-15);
    EXPECT_LE(algebraic(F.D, l3), kOn);
    EXPECT_LE(double_line(F.D, l3), 1e-9) << "l3 is a double line";
    EXPECT_LE(algebraic(F.D, Vec3d(u, -0.75 * u, 0)), kOn);  // (43)
    EXPECT_LE(algebraic(F.D, Vec3d(u, -2 * u, 1)), kOn);     // (43)
    EXPECT_LE(algebraic(F.D, Vec3d(u, 0, 0)), kOn);          // l1, l2 (21)
    EXPECT_LE(algebraic(F.D, Vec3d(2 * u, u, 1)), kOn);
  }
  LinesClassification C;
  ASSERT_EQ(classify_two_lines({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {2, 1, 0}, C), Status::ok);
  EXPECT_EQ(C.kind, CyclideKind::parabolic_darboux);
  EXPECT_EQ(C.paper_case, 2);
  EXPECT_EQ(C.circle_families, 5);
  EXPECT_EQ(C.double_families, 1);
  EXPECT_FALSE(C.pn);
  EXPECT_NEAR(C.nf.a, 2, 1e-15);
  EXPECT_NEAR(C.nf.b, 1, 1e-15);
  EXPECT_NEAR(C.nf.c, 0, 1e-15);
  EXPECT_FALSE(C.nf.swapped);
}

// Prop. 2 on lines in general position: the normal form, (46), (47), (50)
// against make_prcs on the same input, and the case with its counts.
struct Prop2Case {
  Vec3d w;  // in the normal form (45)
  CyclideKind kind;
  int families, doubles;
};

TEST(Prop2, EveryCaseWithSpineRadiusAndFit) {
  const Prop2Case cases[] = {
      {{0.6, 0.8, 0}, CyclideKind::hyperboloid, 0, 0},      // w.w = 1
      {{0, 0.6, -0.8}, CyclideKind::hyperboloid, 0, 0},
      {{1, 0.5, -0.3}, CyclideKind::parabolic_dupin, 4, 2},  // (I) a = 1
      {{1, -2, 1.5}, CyclideKind::parabolic_dupin, 4, 2},
      {{2, 1, 0}, CyclideKind::parabolic_darboux, 5, 1},     // (II)
      {{-0.4, 2, 1.5}, CyclideKind::parabolic_darboux, 5, 1},
      {{0.3, -1.2, 0.8}, CyclideKind::parabolic_darboux, 5, 1},
  };
  const Similarity M = some_similarity();  // input = M^-1 (normal form)
  for (const Prop2Case& k : cases) {
    SCOPED_TRACE(k.w.transpose());
    // Input: the normal form moved by M^-1 and reparameterized u = 2u' - 0.5.
    const double al = 2, be = -0.5;
    const Vec3d P1 = M.inverse(Vec3d(0, 0, 0) - (be / al) * Vec3d(1, 0, 0));
    const Vec3d v = M.R.transpose() * Vec3d(1, 0, 0) / (M.scale * al);
    const Vec3d P2 = M.inverse(Vec3d(0, 0, 1) - (be / al) * k.w);
    const Vec3d w = M.R.transpose() * k.w / (M.scale * al);
    LinesClassification C;
    ASSERT_EQ(classify_two_lines(P1, v, P2, w, C), Status::ok);
    EXPECT_EQ(C.kind, k.kind);
    EXPECT_EQ(C.circle_families, k.families);
    EXPECT_EQ(C.double_families, k.doubles);
    EXPECT_EQ(C.pn, k.kind == CyclideKind::parabolic_dupin);
    if (k.kind == CyclideKind::parabolic_dupin) {
      // a = 1: every shift beta gives a normal form (45) (the classifier
      // takes beta = 0); a and w.w are the invariants.
      EXPECT_NEAR(C.nf.a, 1, 1e-12);
      EXPECT_NEAR(Vec3d(C.nf.a, C.nf.b, C.nf.c).squaredNorm(), k.w.squaredNorm(), 1e-12);
    } else {
      EXPECT_LE((Vec3d(C.nf.a, C.nf.b, C.nf.c) - k.w).norm(), 1e-12);
      EXPECT_NEAR(C.nf.alpha, al, 1e-12);
      EXPECT_NEAR(C.nf.beta, be, 1e-12);
    }
    Surface S;
    ASSERT_EQ(make_prcs(line(P1, v), line(P2, w), nullptr, -1.5, 1.5, S), Status::ok);
    for (double u : {-1.5, -0.4, 0.3, 1.2}) {
      Vec3d s, s46;
      double r2, r47;
      ASSERT_EQ(S.sphere(u, s, r2), Status::ok);
      const double up = C.nf.to_normal_parameter(u);
      ASSERT_EQ(two_lines_sphere(C.nf, up, s46, r47), Status::ok);
      EXPECT_LE((C.nf.T.inverse(s46) - s).norm(), 1e-11 * (1 + s.norm()));
      const double r2_in = r47 / (C.nf.T.scale * C.nf.T.scale);
      EXPECT_NEAR(r2, r2_in, 1e-11 * (1 + r2));
      double r50;
      if (k.kind == CyclideKind::parabolic_dupin) {
        ASSERT_EQ(two_lines_dupin_r2(C.nf, up, r50), Status::ok);
        EXPECT_NEAR(r50, r47, 1e-12 * (1 + r47));
      } else {
        EXPECT_EQ(two_lines_dupin_r2(C.nf, up, r50), Status::invalid_argument);
      }
    }
    const DarbouxFit F = fit(S);
    EXPECT_EQ(darboux_type(F.D), k.kind == CyclideKind::hyperboloid ? DarbouxType::quadric
                                                                    : DarbouxType::parabolic);
    // (I): l2 is a double line (F and grad F vanish on it).
    for (double u : kTs) {
      EXPECT_LE(algebraic(F.D, P2 + u * w), kOn);
      if (k.kind == CyclideKind::parabolic_dupin) {
        EXPECT_LE(double_line(F.D, P2 + u * w), 1e-8); }
    }
  }
}

TEST(Prop2, TheCaseAEqualsWWWithCZeroIsDupinAsWell) {
  // Not in Prop. 2: c = 0, a = w.w (here w = (1/2, 1/2, 0)) makes l1 the
  // double line; it is case (I) with l1, l2 exchanged (PRCS is symmetric),
  // and r^2 (47) = Z^2 / (4 b^2) is a square (PN).
  const Vec3d w(0.5, 0.5, 0);
  LinesClassification C, D;
  ASSERT_EQ(classify_two_lines({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, w, C), Status::ok);
  EXPECT_EQ(C.kind, CyclideKind::parabolic_dupin);
  EXPECT_EQ(C.circle_families, 4);
  EXPECT_TRUE(C.pn);
  ASSERT_EQ(classify_two_lines({0, 0, 1}, w, {0, 0, 0}, {1, 0, 0}, D), Status::ok);
  EXPECT_EQ(D.kind, CyclideKind::parabolic_dupin);
  EXPECT_NEAR(D.nf.a, 1, 1e-14);
  Surface S;
  ASSERT_EQ(make_prcs(line({0, 0, 0}, {1, 0, 0}), line({0, 0, 1}, w), nullptr, -1, 1, S),
            Status::ok);
  const DarbouxFit F = fit(S);
  for (double u : kTs) {
    EXPECT_LE(algebraic(F.D, Vec3d(u, 0, 0)), kOn);
    EXPECT_LE(double_line(F.D, Vec3d(u, 0, 0)), 1e-8) << "l1 is a double line";
  }
  for (double u : {-0.8, 0.1, 0.7}) {
    Vec3d s;
    double r2;
    ASSERT_EQ(two_lines_sphere(C.nf, u, s, r2), Status::ok);
    const double Z = 0.5 + 0.5 * (1 - 0.5) * u * u;
    EXPECT_NEAR(r2, Z * Z, 1e-15);  // Z^2 / (4 b^2), b = 1/2
  }
}

TEST(Prop2, NoNormalFormInTheGivenOrderSwapsTheLines) {
  // a = v.w / v.v = 1 with (P2 - P1).v != 0: no shift beta reaches (45)
  // (Prop. 2's "we can achieve" fails here); the exchanged order has
  // a' = v.w / w.w = 1/2 = w'.w', so it is Dupin iff its c' = 0.
  const Vec3d P1(0, 0, 0), v(1, 0, 0), P2(1, 0, 1), w(1, 1, 0);
  LinesClassification C;
  ASSERT_EQ(classify_two_lines(P1, v, P2, w, C), Status::ok);
  EXPECT_TRUE(C.nf.swapped);
  EXPECT_NEAR(C.nf.a, 0.5, 1e-14);
  Surface S;
  ASSERT_EQ(make_prcs(line(P1, v), line(P2, w), nullptr, -1, 1, S), Status::ok);
  fit(S);
  for (double u : {-0.7, 0.2, 0.9}) {
    Vec3d s, s46;
    double r2, r47;
    ASSERT_EQ(S.sphere(u, s, r2), Status::ok);
    ASSERT_EQ(two_lines_sphere(C.nf, C.nf.to_normal_parameter(u), s46, r47), Status::ok);
    EXPECT_LE((C.nf.T.inverse(s46) - s).norm(), 1e-12 * (1 + s.norm()));
  }
}

TEST(Prop2, DegenerateInputs) {
  LinesClassification C;
  C.circle_families = 99;
  EXPECT_EQ(classify_two_lines({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {2, 0, 0}, C),
            Status::parallel_lines);
  EXPECT_EQ(classify_two_lines({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 1, 0}, C),
            Status::no_normal_form);  // coplanar (intersecting): b = 0
  EXPECT_EQ(classify_two_lines({0, 0, 0}, {0, 0, 0}, {0, 0, 1}, {2, 1, 0}, C),
            Status::zero_tangent);
  EXPECT_EQ(classify_two_lines({0, 0, NAN}, {1, 0, 0}, {0, 0, 1}, {2, 1, 0}, C),
            Status::not_finite);
  EXPECT_EQ(C.circle_families, 99);  // untouched
}

// ---------------------------------------------------------------- App. A

TEST(AppendixA, SpineCyclideLinesAndProp8Cases) {
  // (67), (68); Prop. 8 with ERRATA: (I) a = c = 0, (II) (a, c) != (0, 0),
  // including a = 0 != c and c = 0 != a.
  const double acs[][2] = {{0, 0}, {0.3, 0.7}, {-1.2, 0.4}, {0, 0.5}, {0.6, 0}, {2, -1.5}};
  const Similarity M = some_similarity();
  for (const auto& ac : acs) {
    const double a = ac[0], c = ac[1];
    SCOPED_TRACE(testing::Message() << "a=" << a << " c=" << c);
    for (bool moved : {false, true}) {
      // moved: the input is the normal form mapped by M^-1 (w scaled by -3).
      const Vec3d P1 = moved ? M.inverse(Vec3d::Zero()) : Vec3d::Zero();
      const Vec3d v = moved ? Vec3d(M.R.transpose() * Vec3d(1, 0, 0) / M.scale) : Vec3d(1, 0, 0);
      const Vec3d P2 = moved ? M.inverse(Vec3d(0, 0, 1)) : Vec3d(0, 0, 1);
      const Vec3d w = moved ? Vec3d(-3 * (M.R.transpose() * Vec3d(a, 1, c))) : Vec3d(a, 1, c);
      LinesClassification C;
      ASSERT_EQ(classify_line_element(P1, v, P2, w, C), Status::ok);
      const bool dupin = a == 0 && c == 0;
      EXPECT_EQ(C.kind, dupin ? CyclideKind::parabolic_dupin : CyclideKind::parabolic_darboux);
      EXPECT_EQ(C.paper_case, dupin ? 1 : 2);
      EXPECT_EQ(C.circle_families, dupin ? 2 : 3);
      EXPECT_EQ(C.double_families, dupin ? 2 : 1);
      EXPECT_EQ(C.pn, dupin);
      EXPECT_NEAR(C.nf.a, a, 1e-13);
      EXPECT_NEAR(C.nf.c, c, 1e-13);
      Surface S;
      ASSERT_EQ(make_prcs(line(P1, v), element(P2, w), nullptr, -1, 1, S), Status::ok);
      // (69) against the spine of PRCS.
      for (double u : {-1.0, -0.3, 0.4, 0.9}) {
        Vec3d s, s69;
        double r2;
        ASSERT_EQ(S.sphere(u, s, r2), Status::ok);
        ASSERT_EQ(line_element_spine(C.nf, C.nf.to_normal_parameter(u), s69), Status::ok);
        EXPECT_LE((C.nf.T.inverse(s69) - s).norm(), 1e-12 * (1 + s.norm()));
      }
      // (70) in closed form equals the fit (in the input coordinates).
      Darboux N, G;
      ASSERT_EQ(line_element_cyclide(C.nf, N, G), Status::ok);
      const DarbouxFit F = fit(S);
      EXPECT_LE(up_to_scale(F.D, G), 1e-9);
      if (!moved) {
        EXPECT_LE(up_to_scale(F.D, N), 1e-9);
        for (double x : kTs)
          for (double y : {-2.0, -0.3, 0.5, 1.7}) {
            // (71): C(x, y, cy) = y (2xa + (1 - a^2 + c^2) y - 2c).
            EXPECT_NEAR(N.value({x, y, c * y}),
                        y * (2 * x * a + (1 - a * a + c * c) * y - 2 * c), 1e-12);
            // (72): C(x, y, cy + 1) = -(x - ay)^2.
            const double d = x - a * y;
            EXPECT_NEAR(N.value({x, y, c * y + 1}), -d * d, 1e-12);
          }
      }
      // l2^ = P2 + u w is a double line; P2 singular; l1 on the surface.
      for (double u : kTs) {
        EXPECT_LE(algebraic(G, P2 + u * w / w.norm()), kOn);
        EXPECT_LE(double_line(G, P2 + u * w / w.norm()), 1e-9);
        EXPECT_LE(algebraic(G, P1 + u * v), kOn);
        if (dupin) { EXPECT_LE(double_line(G, P1 + u * v), 1e-9) << "(I): l1 double"; }
      }
    }
  }
}

TEST(AppendixA, Degenerate) {
  LinesClassification C;
  EXPECT_EQ(classify_line_element({0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, C),
            Status::no_normal_form);  // P2 on l1
  EXPECT_EQ(classify_line_element({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {1, 0, 2}, C),
            Status::no_normal_form);  // w in the plane of l1 and P2
  EXPECT_EQ(classify_line_element({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0, 0, 0}, C),
            Status::zero_tangent);
}

// ---------------------------------------------------------------- App. B

TEST(AppendixB, Example3FitIsEq73WithLines74And75) {
  // (28): l1 = (u, 0, 0), P2 = (0, 0, 1), P3 = (1, 2, 1).
  Surface S;
  ASSERT_EQ(make_prrs(line({0, 0, 0}, {1, 0, 0}), point({0, 0, 1}), point({1, 2, 1}), nullptr, -2,
                      2, S),
            Status::ok);
  const DarbouxFit F = fit(S);
  EXPECT_LE(up_to_scale(F.D, eq73()), 1e-9);
  for (double u : kTs) {
    const Vec3d l74(1 - u, 2 * (1 - u), 1);  // (74): a double line
    EXPECT_LE(algebraic(F.D, l74), kOn);
    EXPECT_LE(double_line(F.D, l74), 1e-9);  // the plane z = 1 is tangent along it
    EXPECT_LE(algebraic(F.D, Vec3d(u, (10 - 4 * u) / 3, 0)), kOn);  // (75)
    EXPECT_LE(algebraic(F.D, Vec3d(u, 0, 0)), kOn);                 // l1
  }
  for (const Vec3d& P : {Vec3d(0, 0, 1), Vec3d(1, 2, 1)}) {  // singular points
    EXPECT_LE(algebraic(F.D, P), kOn);
    EXPECT_LE(gradient_size(F.D, P), 1e-9);
  }
  LinesClassification C;
  ASSERT_EQ(classify_line_two_points({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {1, 2, 1}, C), Status::ok);
  EXPECT_EQ(C.kind, CyclideKind::parabolic_darboux);
  EXPECT_EQ(C.circle_families, 3);
  EXPECT_EQ(C.double_families, 1);
  EXPECT_LE((Vec3d(C.nf.a, C.nf.b, C.nf.c) - Vec3d(1, 2, 1)).norm(), 1e-15);
}

TEST(AppendixB, Prop9EveryCase) {
  // (77): P3 = (a, b, c); (I) a = 0, b^2 + c^2 = 1; (II) otherwise.
  const Vec3d P3s[] = {{0, 0.6, 0.8}, {0, -1, 0}, {0, 0.8, -0.6},  // (I)
                       {1, 2, 1},     {0, 0.5, 0.5}, {0.2, 0.6, 0.8}, {-1, 3, 0}};
  const Similarity M = some_similarity();
  for (const Vec3d& P3 : P3s) {
    SCOPED_TRACE(P3.transpose());
    const bool dupin = P3.x() == 0 && std::abs(P3.tail<2>().squaredNorm() - 1) < 1e-15;
    const Vec3d P1 = M.inverse(Vec3d(-0.5, 0, 0)), v = M.R.transpose() * Vec3d(2, 0, 0);
    const Vec3d P2 = M.inverse(Vec3d(0, 0, 1)), Q3 = M.inverse(P3);
    LinesClassification C;
    ASSERT_EQ(classify_line_two_points(P1, v, P2, Q3, C), Status::ok);
    EXPECT_EQ(C.kind, dupin ? CyclideKind::parabolic_dupin : CyclideKind::parabolic_darboux);
    EXPECT_EQ(C.circle_families, dupin ? 2 : 3);
    EXPECT_EQ(C.double_families, dupin ? 2 : 1);
    EXPECT_EQ(C.pn, dupin);
    EXPECT_LE((Vec3d(C.nf.a, C.nf.b, C.nf.c) - P3).norm(), 1e-13);
    Surface S;
    ASSERT_EQ(make_prrs(line(P1, v), point(P2), point(Q3), nullptr, -2, 2, S), Status::ok);
    const DarbouxFit F = fit(S);
    EXPECT_EQ(darboux_type(F.D), DarbouxType::parabolic);
    for (const Vec3d& P : {P2, Q3}) EXPECT_LE(gradient_size(F.D, P), 1e-9);  // singular
    for (double u : kTs) {
      EXPECT_LE(double_line(F.D, P2 + u * (Q3 - P2)), 1e-9);  // the double line P2 P3
      EXPECT_LE(algebraic(F.D, P1 + u * v), kOn);
      if (dupin) { EXPECT_LE(double_line(F.D, P1 + u * v), 1e-9) << "(I): l1 double"; }
    }
  }
  LinesClassification C;
  EXPECT_EQ(classify_line_two_points({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {3, 0, 2}, C),
            Status::no_normal_form);  // coplanar: b = 0
}

// ---------------------------------------------------------------- the fit

TEST(Fit, SphereAndPlaneReportTheirNullityAndTheLowestEquation) {
  Vec3d X[40];
  for (int i = 0; i < 40; ++i) {
    const double t = 0.37 * i, p = 0.21 * i - 4;
    X[i] = Vec3d(1, -2, 0.5) + 1.5 * Vec3d(std::cos(t) * std::cos(p), std::sin(t) * std::cos(p),
                                            std::sin(p));
  }
  DarbouxFit F;
  ASSERT_EQ(fit_darboux(X, 40, F), Status::ok);
  EXPECT_EQ(F.nullity, 5);  // (S - r^2)(phi0 S + l.X + beta)
  EXPECT_TRUE(F.is_darboux);
  EXPECT_EQ(darboux_type(F.D), DarbouxType::quadric);  // the sphere itself
  for (int i = 0; i < 40; ++i) EXPECT_LE(algebraic(F.D, X[i]), 1e-12);
  for (int i = 0; i < 40; ++i) X[i] = Vec3d(0.3 * i - 5, std::sin(i), 2 - 0.1 * i + 0.5 * std::sin(i));
  ASSERT_EQ(fit_darboux(X, 40, F), Status::ok);
  EXPECT_EQ(F.nullity, 5);  // (n.X - d)(gamma S + a.X + e)
  EXPECT_EQ(darboux_type(F.D), DarbouxType::plane);
}

TEST(Fit, InvalidInputsLeaveTheOutputUntouched) {
  Vec3d X[kMaxFitPoints + 1];
  for (int i = 0; i <= kMaxFitPoints; ++i) X[i] = Vec3d(i, i * i, std::sin(i));
  DarbouxFit F;
  F.points = -7;
  EXPECT_EQ(fit_darboux(nullptr, 30, F), Status::null_argument);
  EXPECT_EQ(fit_darboux(X, kMinFitPoints - 1, F), Status::invalid_argument);
  EXPECT_EQ(fit_darboux(X, kMaxFitPoints + 1, F), Status::invalid_argument);
  X[3].y() = NAN;
  EXPECT_EQ(fit_darboux(X, 30, F), Status::not_finite);
  X[3].y() = 1e101;
  EXPECT_EQ(fit_darboux(X, 30, F), Status::not_finite);
  for (int i = 0; i < 30; ++i) X[i] = Vec3d(1, 2, 3);
  EXPECT_EQ(fit_darboux(X, 30, F), Status::invalid_argument);
  EXPECT_EQ(F.points, -7);
}

TEST(Fit, Example5RingedSurfaceIsADarbouxCyclideButThreeCubicsAreNot) {
  // (57), (58): the ringed surface of Example 5 is (61), a parabolic cyclide.
  Surface S;
  ASSERT_EQ(make_prrs(line({0, 0, 0}, {1, 0, 0}), line({0, 0, 0}, {2, 1, 0}),
                      line({1, 1, 1}, {-1, 2, 0}), nullptr, 0.1, 1, S),
            Status::ok);
  fit(S);
  // Three cubics: a ringed surface of higher degree.
  const double c1[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  const double c2[] = {0, 1, 0, 0, 1, 1, 1, 0, 0, 0, 0, -1};
  const double c3[] = {2, 0, 1, 0, -1, 0, 1, 1, 0, 0.5, 0, 0};
  RationalCurve p1, p2, p3;
  ASSERT_EQ(make_polynomial_curve(3, c1, p1), Status::ok);
  ASSERT_EQ(make_polynomial_curve(3, c2, p2), Status::ok);
  ASSERT_EQ(make_polynomial_curve(3, c3, p3), Status::ok);
  Surface T;
  ASSERT_EQ(make_prrs(p1, p2, p3, nullptr, 0.2, 0.8, T), Status::ok);
  DarbouxFit F;
  ASSERT_EQ(fit_darboux(T, F), Status::ok);
  EXPECT_FALSE(F.is_darboux);
  EXPECT_GT(F.residual, 1e-5);
  EXPECT_EQ(F.nullity, 0);
}
