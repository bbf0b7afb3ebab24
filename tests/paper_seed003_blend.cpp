// Seed 003 §4: blending two cones (canal surfaces) with one or two Dupin
// cyclides, Algorithm 2, Lemmas 4.6, 4.7 and eqs. (33)-(46) (ERRATA: (45),
// (46) are the asymptotes of the hyperbolas (43)).
#include <gtest/gtest.h>

#include <cmath>

#include "cyclide/blend.hpp"
#include "cyclide/cyclide_blend.hpp"

using namespace cyclide;

namespace {

LieCone cone(const Vec3d& c, const Vec3d& n, double rho, double slope, int orientation) {
  LieCone K;
  EXPECT_EQ(cone_from_circle(c, n, rho, slope, orientation, K), Status::ok);
  return K;
}

Vec3d point(const Surface& S, double u, double v) {
  double x[3];
  EXPECT_EQ(S.eval(u, v, EvalOut{x, nullptr, nullptr, nullptr}), Status::ok);
  return {x[0], x[1], x[2]};
}

void expect_g1(const LieCone& R, const LieCone& S, const CyclideBlend& B, double tol) {
  CyclideBlendContinuity C;
  ASSERT_EQ(cyclide_blend_continuity(R, S, B, 24, C), Status::ok);
  for (int j = 0; j < 3; ++j) {
    EXPECT_LE(C.gap[j], tol * C.scale) << "joint " << j;
    EXPECT_LE(C.angle[j], tol) << "joint " << j;
  }
}

// Lemma 4.7: span(x, y) of positive x, y is R^{1,1,0} iff |x.y| = |x||y|.
double lemma47_defect(const Lie6d& x, const Lie6d& y) {
  return std::abs(std::abs(lie_dot(x, y)) - std::sqrt(lie_dot(x, x) * lie_dot(y, y))) /
         std::sqrt(lie_dot(x, x) * lie_dot(y, y));
}

}  // namespace

// The cones' Lie form: r0 neutral, r+ positive and orthogonal to r0 (the
// tangent space (12) = R^{1,1,0}), and the circle read back.
TEST(Seed003Remark31, ConesAreDegenerateTangentSpaces) {
  const LieCone K = cone({1, 2, 3}, {0, 1, 1}, 0.8, 0.25, 1);
  EXPECT_NEAR(lie_dot(K.r0, K.r0), 0.0, 1e-13);
  EXPECT_NEAR(lie_dot(K.r0, K.r_plus), 0.0, 1e-13);
  EXPECT_GT(lie_dot(K.r_plus, K.r_plus), 0.1);
  const Lie6d v[2] = {K.r0, K.r_plus};
  LieSubspace R;
  ASSERT_EQ(lie_span(v, 2, R), Status::ok);
  EXPECT_EQ(R.signature, (Signature{1, 1, 0}));
  Vec3d c, n;
  double r;
  ASSERT_EQ(cone_circle(K, c, n, r), Status::ok);
  EXPECT_NEAR((c - Vec3d(1, 2, 3)).norm(), 0.0, 1e-13);
  EXPECT_NEAR((n - Vec3d(0, 1, 1).normalized()).norm(), 0.0, 1e-13);
  EXPECT_NEAR(r, 0.8, 1e-13);
  // The apex form: the same cone.
  LieCone A;
  ASSERT_EQ(cone_from_circle_apex({1, 2, 3}, {0, 1, 1}, 0.8,
                                  Vec3d(1, 2, 3) - (0.8 / 0.25) * Vec3d(0, 1, 1).normalized(), 1,
                                  A),
            Status::ok);
  EXPECT_NEAR((A.r0 - K.r0).norm(), 0.0, 1e-12);
  EXPECT_NEAR((A.r_plus - K.r_plus).norm(), 0.0, 1e-12);
}

// Lemma 4.6 (i): touching generating spheres (r0 . s0 = 0) are the case the
// paper omits; reported. Invalid cones are reported too.
TEST(Seed003Lemma46, TangentGeneratingSpheresAndBadCones) {
  // Two unit cylinders on one axis whose circles' spheres touch: the
  // spheres (0,0,0; 1) and (0,0,2; -1) are externally tangent with opposite
  // orientation, i.e. in oriented contact.
  const LieCone R = cone({0, 0, 0}, {0, 0, 1}, 1, 0, 1);
  const LieCone S = cone({0, 0, 2}, {0, 0, -1}, 1, 0, -1);
  EXPECT_NEAR(lie_dot(R.r0, S.r0), 0.0, 1e-13);
  int dim = 0;
  EXPECT_EQ(cyclide_blend_dimension(R, S, dim), Status::tangent_generating_spheres);
  CyclideBlend B;
  EXPECT_EQ(cyclide_blend(R, S, 1, 0.0, B), Status::tangent_generating_spheres);
  EXPECT_EQ(cyclide_blend_dimension(R, R, dim), Status::invalid_argument);  // R = S
  LieCone bad = R;
  bad.r0[kE1] += 0.5;  // not neutral
  EXPECT_EQ(cyclide_blend_dimension(bad, S, dim), Status::not_on_lie_quadric);
  bad = R;
  bad.r_plus = 0.1 * R.r0 + lie_basis(kER);  // negative: no real cone, (11)
  EXPECT_EQ(cyclide_blend_dimension(bad, S, dim), Status::invalid_argument);
  LieCone out;
  EXPECT_EQ(cone_from_circle_apex({0, 0, 0}, {0, 0, 1}, 1, {1, 0, 2}, 1, out),
            Status::invalid_argument);  // apex off the axis
  EXPECT_EQ(cone_from_spheres({0, 0, 0}, 1, {0, 0, 1}, 2, out),
            Status::invalid_argument);  // |drho| > |dm|
}

// Case I: two equal cylinders whose axes meet at the same distance 3 from
// both circles: dim(R + S) = 3, A = R + S = R^{2,1}, and the single cyclide
// is the quarter of the torus with core circle through both circle centers.
TEST(Seed003Algorithm2, SingleCyclideElbowIsATorus) {
  const LieCone R = cone({0, 0, 0}, {0, 0, 1}, 1, 0, 1);
  const LieCone S = cone({3, 0, 3}, {-1, 0, 0}, 1, 0, 1);
  int dim = 0;
  ASSERT_EQ(cyclide_blend_dimension(R, S, dim), Status::ok);
  EXPECT_EQ(dim, 3);
  const Lie6d span[4] = {R.r0, R.r_plus, S.r0, S.r_plus};
  LieSubspace A;
  ASSERT_EQ(lie_span(span, 4, A), Status::ok);
  EXPECT_EQ(A.signature, (Signature{2, 0, 1}));  // Lemma 4.6 (ii)
  CyclideBlend B;
  ASSERT_EQ(cyclide_blend(R, S, 1, 0.0, B), Status::ok);
  ASSERT_EQ(B.pieces, 1);
  Surface P;
  ASSERT_EQ(cyclide_blend_surface(B, 0, P), Status::ok);
  for (double u : {0.0, 0.2, 0.5, 0.8, 1.0})
    for (double v : {-3.0, -0.5, 0.0, 1.0, 7.0}) {
      const Vec3d x = point(P, u, v);
      const double t = std::hypot(std::hypot(x[0] - 3, x[2]) - 3, x[1]) - 1;
      EXPECT_NEAR(t, 0.0, 1e-12) << u << " " << v;
      // The quarter between the circles: x <= 4 and z >= -1 ... the patch
      // stays in the quadrant x - 3 <= 0, z >= 0 of the core circle.
      const Vec3d core = Vec3d(x[0] - 3, 0, x[2]);
      EXPECT_LE(core[0], 1e-12);
      EXPECT_GE(core[2], -1e-12);
    }
  expect_g1(R, S, B, 1e-11);
  double q = 0;
  CyclideBlend C;
  ASSERT_EQ(cyclide_blend_auto(R, S, C, 64, &q), Status::ok);
  EXPECT_EQ(C.pieces, 1);
  // Quality = min / max circle radius: meridians 1, parallels up to 4.
  EXPECT_GE(q, 0.25 - 1e-12);
  EXPECT_NEAR(q, 0.25, 0.01);
}

// The same elbow moved by t = 1e4 (0.6, -0.48, 0.64): Algorithm 2 runs in
// the frame centred between the two circles (SPEC §8h.3), so the piece is
// still the quarter torus, to 1e-12 (1 + |t|) = 1e-8 absolute (measured
// ~1e-12), its origin is the circles' midpoint and its glued spheres are
// the cones' r0 (global vectors).
TEST(Seed003Algorithm2, SingleElbowFarFromTheOriginIsATorus) {
  const Vec3d t = 1e4 * Vec3d(0.6, -0.48, 0.64);
  const LieCone R = cone(t, {0, 0, 1}, 1, 0, 1);
  const LieCone S = cone(Vec3d(3, 0, 3) + t, {-1, 0, 0}, 1, 0, 1);
  CyclideBlend B;
  ASSERT_EQ(cyclide_blend(R, S, 1, 0.0, B), Status::ok);
  ASSERT_EQ(B.pieces, 1);
  EXPECT_NEAR((B.piece[0].cyclide.origin - (t + Vec3d(1.5, 0, 1.5))).norm(), 0.0, 1e-11);
  const double tol = 1e-12 * (1 + t.norm());
  LieSphere first, second;
  ASSERT_EQ(lie_sphere(B.piece[0].first, first), Status::ok);
  ASSERT_EQ(lie_sphere(B.piece[0].second, second), Status::ok);
  EXPECT_NEAR((first.m - t).norm(), 0.0, tol);
  EXPECT_NEAR((second.m - (Vec3d(3, 0, 3) + t)).norm(), 0.0, tol);
  Surface P;
  ASSERT_EQ(cyclide_blend_surface(B, 0, P), Status::ok);
  for (double u : {0.0, 0.2, 0.5, 0.8, 1.0})
    for (double v : {-3.0, -0.5, 0.0, 1.0, 7.0}) {
      const Vec3d x = point(P, u, v) - t;
      const double r = std::hypot(std::hypot(x[0] - 3, x[2]) - 3, x[1]) - 1;
      EXPECT_NEAR(r, 0.0, tol) << u << " " << v;
      EXPECT_LE(x[0] - 3, tol);
      EXPECT_GE(x[2], -tol);
    }
  expect_g1(R, S, B, 1e-11);
  double q = 0;
  CyclideBlend C;
  ASSERT_EQ(cyclide_blend_auto(R, S, C, 64, &q), Status::ok);
  EXPECT_NEAR(q, 0.25, 0.01);
}

// Case II, both hyperbolas of (43): on each branch T(alpha, beta) =
// R^{1,1,0} (Lemma 4.7 / (42)), t0 (44) is neutral, orthogonal to T and
// touches neither r0 nor s0 ((34), (35)); A = R + T and B = S + T are
// PE-subspaces. Where the blend is valid it is G1 at all three circles.
TEST(Seed003Algorithm2, DoubleBlendOnBothBranches) {
  const LieCone R = cone({0, 0, 0}, {0, 0, 1}, 1, 0, 1);
  const LieCone S = cone({2, 0, 3}, {0, 0, -1}, 1, 0, 1);  // parallel, offset axes
  int dim = 0;
  ASSERT_EQ(cyclide_blend_dimension(R, S, dim), Status::ok);
  ASSERT_EQ(dim, 4);
  int valid[2] = {0, 0};
  for (int branch : {1, -1})
    for (double alpha : {-5.0, -1.0, -0.4, 0.2, 0.7, 3.0}) {
      double beta = 0;
      ASSERT_EQ(cyclide_blend_beta(R, S, branch, alpha, beta), Status::ok);
      const Lie6d r = alpha * R.r0 + R.r_plus, s = beta * S.r0 + S.r_plus;
      EXPECT_LE(lemma47_defect(r, s), 1e-12);  // (42) on the hyperbola
      const Lie6d t0 = lie_dot(s, s) * r - lie_dot(s, r) * s;  // (44)
      const double scale = t0.norm() * r.norm();
      EXPECT_LE(std::abs(lie_dot(t0, t0)), 1e-12 * t0.squaredNorm());
      EXPECT_LE(std::abs(lie_dot(t0, r)), 1e-12 * scale);
      EXPECT_GT(std::abs(lie_dot(t0, R.r0)), 1e-6 * t0.norm() * R.r0.norm());
      EXPECT_GT(std::abs(lie_dot(t0, S.r0)), 1e-6 * t0.norm() * S.r0.norm());
      const Lie6d a[3] = {R.r0, R.r_plus, s}, b[3] = {S.r0, S.r_plus, r};
      LieSubspace A, Bs;
      ASSERT_EQ(lie_span(a, 3, A), Status::ok);
      ASSERT_EQ(lie_span(b, 3, Bs), Status::ok);
      EXPECT_EQ(A.signature, (Signature{2, 0, 1}));
      EXPECT_EQ(Bs.signature, (Signature{2, 0, 1}));
      CyclideBlend B;
      const Status st = cyclide_blend(R, S, branch, alpha, B);
      EXPECT_TRUE(st == Status::ok || st == Status::singular_point || st == Status::blend_folds)
          << int(st);
      if (st != Status::ok) continue;
      ++valid[branch > 0];
      EXPECT_EQ(B.pieces, 2);
      EXPECT_NEAR(B.beta, beta, 0.0);
      expect_g1(R, S, B, 1e-9);
      // Both pieces end on the joint sphere t0.
      LieSphere t;
      ASSERT_EQ(lie_sphere(B.joint, t), Status::ok);
      for (int i = 0; i < 2; ++i) {
        Surface P;
        ASSERT_EQ(cyclide_blend_surface(B, i, P), Status::ok);
        for (double v : {-1.0, 0.0, 2.0}) {
          const Vec3d x = point(P, 1.0, v);
          if (t.kind == LieSphereKind::sphere) {
            EXPECT_NEAR((x - t.m).norm(), std::abs(t.rho), 1e-9 * (1 + std::abs(t.rho)));
          }
        }
      }
    }
  EXPECT_GT(valid[0], 0);  // this configuration's blends live on branch -1
  EXPECT_EQ(valid[1], 0);
  // The two hyperbolas are the two sides of S: reversing S's direction
  // (r+ -> -r+, the blend leaving S's circle over S itself) maps branch
  // sigma, beta to branch -sigma, -beta with the same T, so the valid
  // blends of one branch are folded blends of the other.
  const LieCone Srev = cone({2, 0, 3}, {0, 0, 1}, 1, 0, 1);
  EXPECT_NEAR((Srev.r0 - S.r0).norm(), 0.0, 1e-14);
  EXPECT_NEAR((Srev.r_plus + S.r_plus).norm(), 0.0, 1e-14);
  CyclideBlend B;
  int checked = 0;
  for (double alpha : {-5.0, -1.0, -0.6, 0.2, 3.0}) {
    double b1 = 0, b2 = 0;
    ASSERT_EQ(cyclide_blend_beta(R, S, -1, alpha, b1), Status::ok);
    ASSERT_EQ(cyclide_blend_beta(R, Srev, 1, alpha, b2), Status::ok);
    EXPECT_NEAR(b2, -b1, 1e-12 * (1 + std::abs(b1)));
    if (cyclide_blend(R, S, -1, alpha, B) == Status::ok) {
      EXPECT_EQ(cyclide_blend(R, Srev, 1, alpha, B), Status::blend_folds);
      ++checked;
    }
  }
  EXPECT_GT(checked, 0);
  double q = 0;
  ASSERT_EQ(cyclide_blend_auto(R, S, B, 64, &q), Status::ok);
  EXPECT_EQ(B.pieces, 2);
  EXPECT_EQ(B.branch, -1);
  EXPECT_GT(q, 0.1);
  expect_g1(R, S, B, 1e-9);
}

// ERRATA after (46): (45) and (46) are the asymptotes of the hyperbolas
// (43), never solutions: at alpha = (45) there is no beta, and beta tends to
// (46) as alpha grows.
TEST(Seed003Eq45and46, AsymptotesOfTheHyperbolas) {
  const LieCone R = cone({0, 0, 0}, {0, 0, 1}, 1, 0.2, 1);
  const LieCone S = cone({3, 1, 4}, {-1, 0, -1}, 0.7, -0.3, 1);
  const double g00 = lie_dot(R.r0, S.r0);
  const double a45 = -lie_dot(R.r_plus, S.r0) / g00;
  const double b46 = -lie_dot(R.r0, S.r_plus) / g00;
  double beta = 0;
  for (int branch : {1, -1}) {
    EXPECT_EQ(cyclide_blend_beta(R, S, branch, a45, beta), Status::invalid_argument);
    ASSERT_EQ(cyclide_blend_beta(R, S, branch, a45 + 1e-9, beta), Status::ok);
    EXPECT_GT(std::abs(beta), 1e5);  // beta -> infinity at the asymptote (45)
    ASSERT_EQ(cyclide_blend_beta(R, S, branch, 1e9, beta), Status::ok);
    EXPECT_NEAR(beta, b46, 1e-6 * (1 + std::abs(b46)));  // -> (46)
  }
  EXPECT_EQ(cyclide_blend_beta(R, S, 0, 0.0, beta), Status::invalid_argument);
}

// Cones from canal surfaces at a parameter (Remark 4.2): the tangent cones of
// two Dupin tori along their end circles, blended; the blend is G1 with the
// tori themselves.
TEST(Seed003Algorithm2, BlendsCanalSurfacesAlongCircles) {
  auto torus_view = [](const Vec3d& shift, Surface& S) {
    const LieSphere s[3] = {oriented_sphere(shift + Vec3d(3, 0, 0), 1),
                            oriented_sphere(shift + Vec3d(0, 3, 0), 1),
                            oriented_sphere(shift + Vec3d(-3, 0, 0), 1)};
    DupinView V;
    ASSERT_EQ(dupin_from_spheres(s, V.cyclide), Status::ok);
    ASSERT_EQ(make_dupin_surface(V, -0.5, 0.5, S), Status::ok);
  };
  Surface T1, T2;
  torus_view({0, 0, 0}, T1);
  torus_view({9, 2, 1}, T2);
  LieCone R, S;
  ASSERT_EQ(cone_from_surface(T1, 0.5, 1, 1, R), Status::ok);
  ASSERT_EQ(cone_from_surface(T2, -0.5, -1, 1, S), Status::ok);
  CyclideBlend B;
  double q = 0;
  ASSERT_EQ(cyclide_blend_auto(R, S, B, 64, &q), Status::ok);
  Surface P0, Pn;
  ASSERT_EQ(cyclide_blend_surface(B, 0, P0), Status::ok);
  ASSERT_EQ(cyclide_blend_surface(B, B.pieces - 1, Pn), Status::ok);
  ContinuityReport c1, c2;
  ASSERT_EQ(continuity_report(T1, 0.5, 1.0, P0, 0.0, 1, nullptr, 16, c1), Status::ok);
  ASSERT_EQ(continuity_report(T2, -0.5, 1.0, Pn, B.pieces == 1 ? 1.0 : 0.0, 1, nullptr, 16, c2),
            Status::ok);
  EXPECT_LE(c1.max_gap, 1e-10 * c1.point_scale);
  EXPECT_LE(c1.max_normal_angle, 1e-9);
  EXPECT_LE(c2.max_gap, 1e-10 * c2.point_scale);
  EXPECT_LE(c2.max_normal_angle, 1e-9);
  // Non-canal surfaces have no tangent cone.
  Surface ringed;
  RationalCurve d, n, c;
  ASSERT_EQ(make_line({0, 0, 0}, {0, 0, 1}, d), Status::ok);
  ASSERT_EQ(make_point({0.3, 0, 1}, n), Status::ok);
  ASSERT_EQ(make_line({1, 0, 0}, {0.5, 0, 1}, c), Status::ok);
  ASSERT_EQ(make_ringed(d, n, c, nullptr, 0, 1, ringed), Status::ok);
  EXPECT_EQ(cone_from_surface(ringed, 0.5, 1, 1, R), Status::not_canal);
}
