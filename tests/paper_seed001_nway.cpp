// Seed 001 §6, eqs. (62)-(67): n-way blends through an auxiliary sphere
// (labels paper;ringed;ringed_modeling). Example 6.2 with (68)-(69) and
// lambda_i = 0.2: the derived numbers of ERRATA.md / the transcription
// (distances, n*_i, rho*, d*_i(0.2) under (66) as printed), the joining
// circles (pair 1-3 intersects at lambda = 0.2: see SPEC.md §8f.6), the
// blends C^1 at both ends; the degenerate cases; a RapidCheck property over
// random 3-way configurations.

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "cyclide/blend.hpp"
#include "cyclide/evaluator.hpp"
#include "cyclide/nway.hpp"
#include "cyclide/pcurve.hpp"

using namespace cyclide;

namespace {

constexpr double kPi = 3.14159265358979323846;

CurvePoly poly(std::initializer_list<double> c) {
  CurvePoly p;
  p.assign(c.begin(), int(c.size()) - 1);
  return p;
}

// A normal ringed surface (n = d') from d's coefficients (power form, x y z
// per power) and rho (power form) on [0, 1].
void normal_ringed(int deg, const double* dc, const CurvePoly& rho, Surface& S) {
  double nc[3 * 8] = {};
  for (int k = 1; k <= deg; ++k)
    for (int j = 0; j < 3; ++j) nc[3 * (k - 1) + j] = k * dc[3 * k + j];
  RationalCurve d, n;
  ASSERT_EQ(make_polynomial_curve(deg, dc, d), Status::ok);
  ASSERT_EQ(make_polynomial_curve(deg - 1, nc, n), Status::ok);
  // The automatic field may take a projection whose sigma vanishes in
  // [0, 1] (R_3: |n x e3| = |6t^2 - 10t|, zero at t = 0); then Example 3.3
  // (n is quadratic).
  RingedFieldOptions fo;
  if (make_ringed_dnr(d, n, rho, CurvePoly(1.0), fo, nullptr, 0.0, 1.0, S) == Status::ok) return;
  fo.method = RingedFieldMethod::quadratic;
  for (fo.which = 0; fo.which < 2; ++fo.which)
    if (make_ringed_dnr(d, n, rho, CurvePoly(1.0), fo, nullptr, 0.0, 1.0, S) == Status::ok) return;
  FAIL() << "no field for this n";
}

// Example 6.2, (68).
void example62(Surface (&R)[3]) {
  const double d1[12] = {-9, -7, 0, 12, 4, 0, -23, 0, 0, 14, 0, 0};
  const double d2[12] = {6, -8, 0, 4, 4, 0, 0, 3, 0, -4, -2, 0};
  const double d3[12] = {0, 8, -8, 0, 0, 4, 0, -5, -3, 0, 2, 2};
  normal_ringed(3, d1, poly({4.0 / 6, 1.0 / 6}), R[0]);
  normal_ringed(3, d2, poly({1, 0, -0.5}), R[1]);
  normal_ringed(3, d3, poly({9.0 / 6, -4.0 / 6}), R[2]);
}

// (69), lambda_i = 0.2.
NwayOptions example62_options() {
  NwayOptions o;
  o.center = NwayCenter::given;
  o.s = Vec3d(0.5, 0.3, -0.25);
  o.r = 2.6;
  for (double& l : o.lambda) l = 0.2;
  return o;
}

double rel(const Vec3d& a, const Vec3d& b, double scale) { return (a - b).norm() / scale; }

// |K - J| relative to J's magnitudes, the largest over the six entries.
double jet_error(const RingedJet& K, const RingedJet& J) {
  const double scale = 1 + J.d.norm() + J.dd.norm() + J.n.norm() + J.dn.norm() + J.rho +
                       std::abs(J.drho);
  return std::max({rel(K.d, J.d, scale), rel(K.dd, J.dd, scale), rel(K.n, J.n, scale),
                   rel(K.dn, J.dn, scale), std::abs(K.rho - J.rho) / scale,
                   std::abs(K.drho - J.drho) / scale});
}

// Brute force: the smallest distance between samples of two circles on
// the sphere (center s + r cos(theta) a, radius r sin(theta), plane _|_ a).
double sampled_distance(const Vec3d& s, double r, const Vec3d& a, double ta, const Vec3d& b,
                        double tb, int N) {
  auto basis = [](const Vec3d& x, Vec3d& e1, Vec3d& e2) {
    e1 = x.cross(std::abs(x.x()) < 0.9 ? Vec3d::UnitX() : Vec3d::UnitY()).normalized();
    e2 = x.cross(e1);
  };
  Vec3d a1, a2, b1, b2;
  basis(a, a1, a2);
  basis(b, b1, b2);
  double best = HUGE_VAL;
  for (int i = 0; i < N; ++i) {
    const double p = 2 * kPi * i / N;
    const Vec3d P = s + r * (std::cos(ta) * a + std::sin(ta) * (std::cos(p) * a1 + std::sin(p) * a2));
    for (int j = 0; j < N; ++j) {
      const double q = 2 * kPi * j / N;
      const Vec3d Q =
          s + r * (std::cos(tb) * b + std::sin(tb) * (std::cos(q) * b1 + std::sin(q) * b2));
      best = std::min(best, (P - Q).norm());
    }
  }
  return best;
}

// Each blend reproduces the end jet of R_i at t = 0 and S_i's jet at
// lambda_i at t = 1 (C^1 in (d, n, rho)), and joins R_i's surface C^1 in
// the circle family (continuity report).
void expect_c1(const Surface* const* R, const double* u, int n,
               const Surface (&B)[kMaxNwayEnds][2], const int (&count)[kMaxNwayEnds],
               const NwayReport& rep, double tol) {
  for (int i = 0; i < n; ++i) {
    RingedJet K0, K1;
    ASSERT_EQ(ringed_jet(B[i][0], B[i][0].u0, K0), Status::ok);
    ASSERT_EQ(ringed_jet(B[i][count[i] - 1], 1.0, K1), Status::ok);
    EXPECT_LE(jet_error(K0, rep.end_jet[i]), tol) << "end " << i;
    EXPECT_LE(jet_error(K1, rep.sphere_jet[i]), tol) << "sphere " << i;
    ContinuityReport C;
    const double lambda = u[i] == R[i]->u1 ? 1.0 : -1.0;
    ASSERT_EQ(continuity_report(*R[i], u[i], lambda, B[i][0], 0.0, 1, nullptr, 32, C), Status::ok);
    EXPECT_LE(C.max_gap, tol * C.point_scale);
    EXPECT_LE(C.circle_jump[0], tol);
    EXPECT_LE(C.circle_jump[1], tol);
  }
}

}  // namespace

// The derived numbers of Example 6.2 under (66) as printed.
TEST(NwayExample62, DerivedNumbers) {
  Surface R[3];
  example62(R);
  RingedJet J[3];
  for (int i = 0; i < 3; ++i) ASSERT_EQ(ringed_jet(R[i], 1.0, J[i]), Status::ok);
  EXPECT_LT((J[0].d - Vec3d(-6, -3, 0)).norm(), 1e-13);
  EXPECT_LT((J[0].dd - Vec3d(8, 4, 0)).norm(), 1e-12);
  EXPECT_NEAR(J[0].rho, 5.0 / 6, 1e-14);
  EXPECT_LT((J[1].d - Vec3d(6, -3, 0)).norm(), 1e-13);
  EXPECT_LT((J[1].dd - Vec3d(-8, 4, 0)).norm(), 1e-12);
  EXPECT_NEAR(J[1].rho, 0.5, 1e-14);
  EXPECT_LT((J[2].d - Vec3d(0, 5, -5)).norm(), 1e-13);
  EXPECT_LT((J[2].dd - Vec3d(0, -4, 4)).norm(), 1e-12);
  EXPECT_NEAR(J[2].rho, 5.0 / 6, 1e-14);
  NwayOptions o = example62_options();
  o.side = NwaySide::printed;
  o.require_disjoint = false;
  NwaySphere S;
  ASSERT_EQ(nway_sphere(J, 3, o, S), Status::ok);
  const double dist[3] = {7.29400, 6.41892, 6.70093};
  const Vec3d ns[3] = {Vec3d(-0.891143, -0.452426, 0.0342747),
                       Vec3d(0.856842, -0.514105, 0.0389474),
                       Vec3d(-0.0746165, 0.701395, -0.708857)};
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(S.distance[i], dist[i], 5e-6);
    EXPECT_LT((S.n_star[i] - ns[i]).norm(), 1e-6);
    // (66), (67) as printed: rho* = 2r sqrt(0.16) = 2.08, d* = s - 0.6 r n*,
    // on the side of s opposite d_i(1).
    const RingedJet P = nway_sphere_jet(S.s, S.r, S.n_star[i], 0.2, NwaySide::printed, 1);
    EXPECT_NEAR(P.rho, 2.08, 1e-14);
    EXPECT_LT((P.d - (o.s - 0.6 * 2.6 * ns[i])).norm(), 1e-5);
    EXPECT_NEAR((P.d - J[i].d).norm(), S.distance[i] + 0.6 * 2.6, 1e-12);  // beyond s
    EXPECT_LT((P.dd - 2 * 2.6 * S.n_star[i]).norm(), 1e-14);
    EXPECT_NEAR(P.drho, 2.6 * 0.6 / 0.4, 1e-13);
    // The facing side: the circle at the same lambda on R_i's side of s.
    const RingedJet F = nway_sphere_jet(S.s, S.r, S.n_star[i], 0.2, NwaySide::facing, 1);
    EXPECT_LT((F.d - (o.s + 0.6 * 2.6 * ns[i])).norm(), 1e-5);
    EXPECT_NEAR(F.rho, 2.08, 1e-14);
    EXPECT_LT((F.d - J[i].d).norm(), S.distance[i] - 1.5);
  }
  EXPECT_NEAR(S.bound, 6.41892, 5e-6);
  EXPECT_LT(S.r, S.bound);  // (65)
  // (63) with the incentre (64) and N = (d1 - d2) x (d1 - d3) = (0, 60, 96).
  EXPECT_LT((S.N - Vec3d(0, 60, 96)).norm(), 1e-12);
  EXPECT_LT((S.y - Vec3d(0, -0.2061088247196685, -1.746181984550207)).norm(), 1e-12);
}

// The joining circles of Example 6.2 at lambda_i = 0.2: angular radius
// acos(0.6) = 53.13 deg each; the axes of c_1 and c_3 are 105.97 deg apart
// (< 106.26 deg), so c_1 and c_3 intersect — on either side. lambda = 0.19
// separates them.
TEST(NwayExample62, JoiningCirclesOneAndThreeMeetAtLambdaPointTwo) {
  Surface R[3];
  example62(R);
  RingedJet J[3];
  for (int i = 0; i < 3; ++i) ASSERT_EQ(ringed_jet(R[i], 1.0, J[i]), Status::ok);
  for (NwaySide side : {NwaySide::printed, NwaySide::facing}) {
    NwayOptions o = example62_options();
    o.side = side;
    NwaySphere S;
    EXPECT_EQ(nway_sphere(J, 3, o, S), Status::intersecting_circles);
    EXPECT_EQ(S.worst_i, 0);
    EXPECT_EQ(S.worst_j, 2);
    const double phi13 = std::acos(S.n_star[0].dot(S.n_star[2]));
    EXPECT_NEAR(phi13 * 180 / kPi, 105.96985, 1e-4);
    EXPECT_NEAR(S.gap[0][2], phi13 - 2 * std::acos(0.6), 1e-12);
    EXPECT_LT(S.gap[0][2], -0.005);
    EXPECT_GT(S.gap[0][1], 0.25);
    EXPECT_GT(S.gap[1][2], 0.18);
    // Brute force agrees: the sampled circles come within sampling distance.
    const double t = std::acos(0.6);
    EXPECT_LT(sampled_distance(S.s, S.r, S.n_star[0], t, S.n_star[2], t, 720), 0.03);
    EXPECT_NEAR(sampled_distance(S.s, S.r, S.n_star[0], t, S.n_star[1], t, 720),
                2 * S.r * std::sin(S.gap[0][1] / 2), 0.03);
    for (double& l : o.lambda) l = 0.19;
    EXPECT_EQ(nway_sphere(J, 3, o, S), Status::ok);
    EXPECT_GT(S.min_gap, 0.02);
    EXPECT_FALSE(S.nested[0][2]);
  }
}

// §6 "lambda_i chosen so that the circles c_i do not intersect": with
// auto_lambda the library chooses them (theta_i = 0.45 min_j angle(axis_i,
// axis_j)); on Example 6.2 every gap is then at least a tenth of its axes'
// angle, and the blends are C^1.
TEST(NwayExample62, AutomaticLambdasKeepTheCirclesApart) {
  Surface R[3];
  example62(R);
  const Surface* ends[3] = {&R[0], &R[1], &R[2]};
  const double u[3] = {1, 1, 1};
  NwayOptions o = example62_options();
  o.auto_lambda = true;
  for (double& l : o.lambda) l = 7;  // ignored
  Surface B[kMaxNwayEnds][2];
  int count[kMaxNwayEnds] = {};
  NwayReport rep;
  ASSERT_EQ(make_ringed_nway_blend(ends, u, 3, o, B, count, &rep), Status::ok);
  const NwaySphere& S = rep.sphere;
  for (int i = 0; i < 3; ++i) {
    EXPECT_GT(S.lambda[i], 0.0);
    EXPECT_LT(S.lambda[i], 0.5);
    for (int j = 0; j < 3; ++j)
      if (j != i) {
        const double phi = std::acos(S.n_star[i].dot(S.n_star[j]));
        EXPECT_GE(S.gap[i][j], 0.1 * phi - 1e-12);
        EXPECT_FALSE(S.nested[i][j]);
      }
  }
  // c_1 and c_3 (axes 105.97 deg apart) are the closest pair: both get
  // theta = 0.45 * 105.97 deg.
  EXPECT_NEAR(std::acos(1 - 2 * S.lambda[0]) * 180 / kPi, 0.45 * 105.96985, 1e-3);
  expect_c1(ends, u, 3, B, count, rep, 1e-9);
}

// The blends of Example 6.2 (facing side, the paper's lambda = 0.2 with the
// intersection check relaxed; and lambda = 0.19 with it): built, C^1.
TEST(NwayExample62, BlendsAreC1AtBothEnds) {
  Surface R[3];
  example62(R);
  const Surface* ends[3] = {&R[0], &R[1], &R[2]};
  const double u[3] = {1, 1, 1};
  for (double lambda : {0.2, 0.19}) {
    for (double tau : {0.0, 0.5}) {
      NwayOptions o = example62_options();
      for (double& l : o.lambda) l = lambda;
      o.require_disjoint = lambda != 0.2;
      o.blend.tau = tau;
      Surface B[kMaxNwayEnds][2];
      int count[kMaxNwayEnds] = {};
      NwayReport rep;
      double bad = NAN;
      ASSERT_EQ(make_ringed_nway_blend(ends, u, 3, o, B, count, &rep, &bad), Status::ok)
          << "lambda " << lambda << " tau " << tau << " failed end " << rep.failed_end << " at "
          << bad;
      for (int i = 0; i < 3; ++i) EXPECT_EQ(count[i], tau == 0 ? 1 : 2);
      expect_c1(ends, u, 3, B, count, rep, 1e-9);
      // The sphere's n points along the blend's travel (into the sphere)
      // like R_i's n = d' does at its end; the blend's centers approach s
      // monotonically (no turn-back: the facing side).
      for (int i = 0; i < 3; ++i) {
        double last = HUGE_VAL;
        for (int k = 0; k < count[i]; ++k)
          for (int j = 0; j <= 64; ++j) {
            const double t = B[i][k].u0 + (B[i][k].u1 - B[i][k].u0) * j / 64.0;
            RingedJet K;
            ASSERT_EQ(ringed_jet(B[i][k], t, K), Status::ok);
            const double dist = (K.d - rep.sphere.s).norm();
            EXPECT_LE(dist, last + 1e-12) << "blend " << i << " t " << t;
            last = dist;
          }
        EXPECT_GT(rep.sphere_jet[i].n.dot(rep.sphere_jet[i].dd), 0);
        EXPECT_LT(rep.sphere_jet[i].n.dot(rep.sphere.n_star[i]), 0);
      }
    }
  }
}

// (66)-(67) as printed (side = printed) also gives C^1 blends: they cross
// the sphere to the far circle and arrive moving back towards R_i.
TEST(NwayExample62, PrintedSideBlendsAreC1) {
  Surface R[3];
  example62(R);
  const Surface* ends[3] = {&R[0], &R[1], &R[2]};
  const double u[3] = {1, 1, 1};
  NwayOptions o = example62_options();
  o.side = NwaySide::printed;
  for (double& l : o.lambda) l = 0.19;
  Surface B[kMaxNwayEnds][2];
  int count[kMaxNwayEnds] = {};
  NwayReport rep;
  ASSERT_EQ(make_ringed_nway_blend(ends, u, 3, o, B, count, &rep), Status::ok);
  expect_c1(ends, u, 3, B, count, rep, 1e-9);
  for (int i = 0; i < 3; ++i) {
    EXPECT_LT((rep.sphere_jet[i].d - (o.s - 0.62 * 2.6 * rep.sphere.n_star[i])).norm(), 1e-12);
    EXPECT_GT(rep.sphere_jet[i].dd.dot(rep.sphere.n_star[i]), 0);  // towards R_i
  }
}

// A 5-way blend (the paper's Fig. 11 has one; no data given): five normal
// ringed ends around a ring, tilted out of its plane, the automatic sphere;
// axes 72 deg apart, so lambda = 0.08 (caps of 32.9 deg) keeps the circles
// apart.
TEST(NwayBlend, FiveWayAroundARing) {
  Surface R[5];
  const Surface* ends[5];
  const double u[5] = {1, 1, 1, 1, 1};
  for (int i = 0; i < 5; ++i) {
    const double a = 2 * kPi * i / 5;
    const Vec3d radial(std::cos(a), std::sin(a), 0);
    const Vec3d P = 6 * radial + Vec3d(0, 0, 1), T = -3 * radial + Vec3d(0, 0, 0.5 + 0.1 * i);
    // d(t) = P + (t - 1) T + (t - 1)^2 w: a quadratic directrix, n = d'.
    const Vec3d w = 0.5 * radial.cross(Vec3d::UnitZ());
    const Vec3d c0 = P - T + w, c1 = T - 2 * w, c2 = w;
    const double dc[9] = {c0.x(), c0.y(), c0.z(), c1.x(), c1.y(), c1.z(), c2.x(), c2.y(), c2.z()};
    normal_ringed(2, dc, poly({0.5, 0.1 * (i % 3)}), R[i]);
    ends[i] = &R[i];
  }
  NwayOptions o;
  for (double& l : o.lambda) l = 0.08;
  Surface B[kMaxNwayEnds][2];
  int count[kMaxNwayEnds] = {};
  NwayReport rep;
  double bad = NAN;
  ASSERT_EQ(make_ringed_nway_blend(ends, u, 5, o, B, count, &rep, &bad), Status::ok)
      << "failed end " << rep.failed_end << " at " << bad;
  EXPECT_GT(rep.sphere.min_gap, 0);
  EXPECT_LT((rep.sphere.y - Vec3d(0, 0, 1)).norm(), 1e-12);  // the centroid
  EXPECT_GT(rep.sphere.s.z(), 1);  // tangents tilted up lift s
  expect_c1(ends, u, 5, B, count, rep, 1e-9);
}

// The ends of R_i taken at u = 0 (reversed jets) give the same geometry.
TEST(NwayBlend, EndAtLowerParameterIsReversed) {
  Surface R[3];
  example62(R);
  const Surface* ends[3] = {&R[0], &R[1], &R[2]};
  const double u[3] = {0, 0, 0};
  NwayOptions o;  // automatic center, r = 0.5 bound
  for (double& l : o.lambda) l = 0.15;
  Surface B[kMaxNwayEnds][2];
  int count[kMaxNwayEnds] = {};
  NwayReport rep;
  ASSERT_EQ(make_ringed_nway_blend(ends, u, 3, o, B, count, &rep), Status::ok);
  for (int i = 0; i < 3; ++i) {
    RingedJet J;
    ASSERT_EQ(ringed_jet(R[i], 0.0, J), Status::ok);
    EXPECT_LT((rep.end_jet[i].dd + J.dd).norm(), 1e-12);
    EXPECT_LT((rep.end_jet[i].d - J.d).norm(), 1e-12);
  }
  EXPECT_NEAR(rep.sphere.r, 0.5 * rep.sphere.bound, 1e-12);
  expect_c1(ends, u, 3, B, count, rep, 1e-9);
}

// Automatic alpha: every end tangent in the plane of the centers (up to
// symmetry) leaves s at the incentre's height; tilted tangents lift it.
TEST(NwaySphere, AutomaticAlphaFollowsTheTangents) {
  RingedJet J[3];
  const Vec3d P[3] = {Vec3d(4, 0, 0), Vec3d(-2, 3.4641016151377544, 0),
                      Vec3d(-2, -3.4641016151377544, 0)};
  for (int i = 0; i < 3; ++i) {
    J[i].d = P[i];
    J[i].dd = -P[i];
    J[i].n = -P[i];
    J[i].rho = 0.5;
  }
  NwayOptions o;
  for (double& l : o.lambda) l = 0.1;  // caps of 37 deg: disjoint for 3 or 4 ends
  NwaySphere S;
  ASSERT_EQ(nway_sphere(J, 3, o, S), Status::ok);
  EXPECT_LT(S.s.norm(), 1e-12);
  EXPECT_LT(std::abs(S.alpha), 1e-12);
  for (int i = 0; i < 3; ++i) J[i].dd = -P[i] + Vec3d(0, 0, 2);  // tilted up by atan(1/2)
  ASSERT_EQ(nway_sphere(J, 3, o, S), Status::ok);
  EXPECT_NEAR(S.s.z(), 2, 1e-12);  // the tangent lines meet at (0, 0, 2)
  EXPECT_NEAR(S.alpha * S.N.norm(), S.N.z() > 0 ? 2 : -2, 1e-12);
  // n = 4: the centroid and Newell's normal.
  RingedJet K[4];
  for (int i = 0; i < 4; ++i) {
    const double a = kPi / 2 * i;
    K[i].d = Vec3d(3 * std::cos(a), 3 * std::sin(a), 1);
    K[i].dd = Vec3d(0, 0, 1) - K[i].d;
    K[i].n = K[i].dd;
    K[i].rho = 0.4;
  }
  ASSERT_EQ(nway_sphere(K, 4, o, S), Status::ok);
  EXPECT_LT((S.y - Vec3d(0, 0, 1)).norm(), 1e-12);
  EXPECT_LT((S.N.normalized() - Vec3d(0, 0, 1)).norm(), 1e-12);
  EXPECT_LT((S.s - Vec3d(0, 0, 1)).norm(), 1e-12);
}

// Degenerate input: the right status and untouched outputs.
TEST(NwayBlend, DegenerateCasesLeaveOutputsUntouched) {
  Surface R[3];
  example62(R);
  const Surface* ends[3] = {&R[0], &R[1], &R[2]};
  const double u[3] = {1, 1, 1};
  Surface B[kMaxNwayEnds][2];
  int count[kMaxNwayEnds] = {7, 7, 7, 7, 7, 7, 7, 7};
  const double u0 = B[0][0].u0;
  auto run = [&](const NwayOptions& o, int n = 3) {
    return make_ringed_nway_blend(ends, u, n, o, B, count);
  };
  NwayOptions o = example62_options();
  o.r = 6.5;  // >= bound 6.41892
  EXPECT_EQ(run(o), Status::bad_domain);
  o.r = -1;
  EXPECT_EQ(run(o), Status::invalid_argument);
  o = example62_options();
  o.lambda[1] = 1.0;
  EXPECT_EQ(run(o), Status::bad_domain);
  o.lambda[1] = 0.0;
  EXPECT_EQ(run(o), Status::bad_domain);
  o.lambda[1] = NAN;
  EXPECT_EQ(run(o), Status::not_finite);
  o = example62_options();  // lambda = 0.2: c_1 and c_3 meet
  EXPECT_EQ(run(o), Status::intersecting_circles);
  o.s = Vec3d(-6, -3, 0);  // s at an end center: bound 0
  o.require_disjoint = false;
  EXPECT_EQ(run(o), Status::bad_domain);
  EXPECT_EQ(run(example62_options(), 2), Status::invalid_argument);
  EXPECT_EQ(run(example62_options(), kMaxNwayEnds + 1), Status::invalid_argument);
  const double bad_u[3] = {1, 1.5, 1};
  EXPECT_EQ(make_ringed_nway_blend(ends, bad_u, 3, example62_options(), B, count),
            Status::bad_domain);
  for (int i = 0; i < kMaxNwayEnds; ++i) EXPECT_EQ(count[i], 7);
  EXPECT_EQ(B[0][0].u0, u0);
  // Collinear and coincident end centers: no incentre, no plane.
  RingedJet J[3];
  for (int i = 0; i < 3; ++i) {
    J[i].d = Vec3d(i, 2 * i, 3 * i);
    J[i].dd = Vec3d(0, 0, 1);
    J[i].n = Vec3d(0, 0, 1);
    J[i].rho = 0.1;
  }
  NwaySphere S;
  S.r = 42;
  EXPECT_EQ(nway_sphere(J, 3, NwayOptions(), S), Status::collinear_points);
  EXPECT_EQ(S.r, 42);
  J[2].d = J[1].d;
  EXPECT_EQ(nway_sphere(J, 3, NwayOptions(), S), Status::collinear_points);
  NwayOptions f;
  f.r_fraction = 1.0;
  J[2].d = Vec3d(5, 0, 1);
  EXPECT_EQ(nway_sphere(J, 3, f, S), Status::invalid_argument);
}

TEST(NwaySphere, DisplaySurfaceLiesOnTheSphere) {
  Surface S;
  const Vec3d s(0.5, 0.3, -0.25), m(1, 2, 2);
  ASSERT_EQ(nway_sphere_surface(s, 2.6, m, S), Status::ok);
  for (double u : {0.01, 0.3, 0.5, 0.9}) {
    for (double v : {-3.0, -0.5, 0.0, 1.0, 7.0}) {
      double x[3];
      EvalOut out;
      out.point = x;
      ASSERT_EQ(S.eval(u, v, out), Status::ok);
      EXPECT_NEAR((Vec3d(x[0], x[1], x[2]) - s).norm(), 2.6, 1e-12);
    }
  }
}

// Random well-conditioned 3-way configurations: three end centers around
// a random point in a random plane, the ends' tangents roughly towards it
// (tilted), linear directrices, constant n = d' + small, constant radii.
// The joining-circle test agrees with a brute-force sampled distance, and
// built blends are C^1 at both ends.
RC_GTEST_PROP(NwayProperties, ThreeWayBlendsAreC1AndCircleTestAgrees, ()) {
  auto unit = [] { return *rc::gen::inRange(-1000, 1001) / 1000.0; };
  const Vec3d c(4 * unit(), 4 * unit(), 4 * unit());
  Vec3d axis(unit(), unit(), unit());
  RC_PRE(axis.norm() > 0.3);
  axis.normalize();
  const Vec3d e1 = axis.cross(std::abs(axis.x()) < 0.9 ? Vec3d::UnitX() : Vec3d::UnitY()).normalized(),
              e2 = axis.cross(e1);
  Surface R[3];
  const Surface* ends[3] = {&R[0], &R[1], &R[2]};
  const double u[3] = {1, 1, 1};
  NwayOptions o;
  o.r_fraction = 0.3 + 0.2 * unit();
  for (int i = 0; i < 3; ++i) {
    const double a = 2 * kPi * i / 3 + 0.4 * unit();
    const Vec3d radial = std::cos(a) * e1 + std::sin(a) * e2;
    const Vec3d P = c + (5 + unit()) * radial;
    const Vec3d T = -(2 + unit()) * radial + 0.8 * unit() * axis + 0.3 * unit() * radial.cross(axis);
    const Vec3d N = T + 0.2 * Vec3d(unit(), unit(), unit());
    const double dc[6] = {P.x() - T.x(), P.y() - T.y(), P.z() - T.z(), T.x(), T.y(), T.z()};
    RationalCurve d, n;
    RC_ASSERT(make_polynomial_curve(1, dc, d) == Status::ok);
    const double nc[3] = {N.x(), N.y(), N.z()};
    RC_ASSERT(make_polynomial_curve(0, nc, n) == Status::ok);
    RC_PRE(make_ringed_dnr(d, n, CurvePoly(0.4 + 0.3 * unit()), CurvePoly(1.0),
                           RingedFieldOptions(), nullptr, 0.0, 1.0, R[i]) == Status::ok);
    o.lambda[i] = 0.25 + 0.2 * unit();
  }
  Surface B[kMaxNwayEnds][2];
  int count[kMaxNwayEnds] = {};
  NwayReport rep;
  const Status st = make_ringed_nway_blend(ends, u, 3, o, B, count, &rep);
  const NwaySphere& S = rep.sphere;
  if (st == Status::ok || st == Status::intersecting_circles) {
    for (int i = 0; i < 3; ++i)
      for (int j = i + 1; j < 3; ++j) {
        const double g = S.gap[i][j];
        const double dist = sampled_distance(S.s, S.r, S.n_star[i], S.theta[i], S.n_star[j],
                                             S.theta[j], 180);
        // 180 samples: neighbours 2 pi r / 180 apart at most.
        const double h = 2 * kPi * S.r / 180;
        if (g > 0) {
          RC_ASSERT(dist >= 2 * S.r * std::sin(g / 2) - 1e-9);
          RC_ASSERT(dist <= 2 * S.r * std::sin(g / 2) + h);
        } else {
          RC_ASSERT(dist <= h);
        }
      }
  }
  if (st == Status::intersecting_circles) {
    RC_ASSERT(S.min_gap <= 1e-12);
    RC_TAG("intersecting");
    RC_SUCCEED("joining circles meet");
  }
  if (st != Status::ok) {
    // A blend through n = 0 or a vanishing radius, or n parallel to v.
    RC_ASSERT(st == Status::not_pythagorean || st == Status::dependent_planes ||
              st == Status::singular_point || st == Status::numerical_overflow);
    RC_TAG("refused");
    RC_SUCCEED("refused");
  }
  RC_ASSERT(S.min_gap > 0);
  for (int i = 0; i < 3; ++i) {
    RingedJet K0, K1;
    RC_ASSERT(ringed_jet(B[i][0], 0.0, K0) == Status::ok);
    RC_ASSERT(ringed_jet(B[i][count[i] - 1], 1.0, K1) == Status::ok);
    RC_ASSERT(jet_error(K0, rep.end_jet[i]) <= 1e-9);
    RC_ASSERT(jet_error(K1, rep.sphere_jet[i]) <= 1e-9);
    ContinuityReport C;
    RC_ASSERT(continuity_report(R[i], 1.0, 1.0, B[i][0], 0.0, 1, nullptr, 16, C) == Status::ok);
    RC_ASSERT(C.circle_jump[0] <= 1e-9 && C.circle_jump[1] <= 1e-9);
  }
}
