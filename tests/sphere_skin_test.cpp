// Seed 002 (Hoffmann, Monterde, Troll 2015) with ERRATA.md §002: the
// equations of the paper checked on the skin (labels "paper;sphere_skin";
// SPEC.md §8g): Remark 2's end curvature, lambda's closed form (§4), the
// Hermite conditions (4) with (6)-(11) and v = a (x - q), eq. (2)-(3)
// with the usual torsion (the ERRATA's sign), the two RMF integrators,
// the baselines of §2 and their twist, chains, and the degenerate
// statuses.

#include <gtest/gtest.h>

#include <cmath>

#include "cyclide/quadrature.hpp"
#include "cyclide/sphere_skin.hpp"

using namespace cyclide;

namespace {

const double kPi = std::acos(-1.0);

// Two unit spheres with skew cone axes (the situation of Fig. 3/Fig. 8,
// where the pairings differ): the start circle at 0.3 from the first
// sphere's center towards +x, the end circle on the second sphere with its
// axis tilted out of the plane.
struct Skew {
  SkinEnd s, e;
  Skew() {
    EXPECT_EQ(skin_end_from_sphere({0, 0, 0}, 1.0, {0.3, 0, 0}, {3, 0, 0}, s), Status::ok);
    const Vec3d axis = Vec3d(1.0, 0.6, 0.8).normalized();
    EXPECT_EQ(skin_end_from_sphere({4, 1, 0.5}, 1.2, Vec3d(4, 1, 0.5) - 0.4 * axis, 3.0 * axis, e),
              Status::ok);
  }
};

Vec3d eval_x(const SphereSkin& S, double theta, double t, Vec3d* xt = nullptr,
             Vec3d* xth = nullptr) {
  double x[3], a[3], b[3];
  EXPECT_EQ(skin_eval(S, theta, t, x, a, b, nullptr), Status::ok);
  if (xth) *xth = Vec3d(a[0], a[1], a[2]);
  if (xt) *xt = Vec3d(b[0], b[1], b[2]);
  return Vec3d(x[0], x[1], x[2]);
}

}  // namespace

// Remark 2: kappa(0) = 2 |t_i x (3(p_f - p_i) - t_f)| / |t_i|^3.
TEST(SphereSkinPaper, Remark2EndCurvature) {
  Skew k;
  const SkinSpine a = make_skin_spine(k.s, k.e);
  const Vec3d &ti = k.s.tangent, &tf = k.e.tangent;
  const double kappa =
      2 * ti.cross(3.0 * (k.e.center - k.s.center) - tf).norm() / std::pow(ti.norm(), 3);
  EXPECT_NEAR(skin_spine_curvature(a, 0.0), kappa, 1e-14 * kappa);
  // Hermite data of the spine.
  EXPECT_LE((a.point(0) - k.s.center).norm(), 1e-15);
  EXPECT_LE((a.point(1) - k.e.center).norm(), 1e-14);
  EXPECT_LE((a.d1(0) - ti).norm(), 1e-15);
  EXPECT_LE((a.d1(1) - tf).norm(), 1e-14);
}

// §4: lambda(t) = r_f t^2 (3 - 2t + a_f (1 - t)) - r_i (t - 1)^2 (-1 + (-2 +
// a_i) t), the Hermite solution of (6), (7), (8), (10); and a_i, a_f of
// (9), (11) with theta_0 measured from the principal normal (ERRATA):
// a_i c_i = 1 - cos(theta_0) kappa(0) r_i, cos(theta_0) = w . n(0).
TEST(SphereSkinPaper, LambdaAndEndScalars) {
  Skew k;
  SphereSkin S;
  ASSERT_EQ(make_sphere_skin(k.s, k.e, SkinOptions{}, S), Status::ok);
  for (double theta : {0.0, 0.7, 2.0, -2.5}) {
    double a[2];
    const double ri = k.s.radius, rf = k.e.radius;
    for (double t : {0.0, 0.2, 0.5, 0.9, 1.0}) {
      const double lam = skin_lambda(S, theta, t, a);
      const double paper =
          rf * t * t * (3 - 2 * t + a[1] * (1 - t)) - ri * (t - 1) * (t - 1) * (-1 + (-2 + a[0]) * t);
      EXPECT_NEAR(lam, paper, 1e-14) << theta << " " << t;
    }
    // (9) and (11) from the Frenet frame at the ends.
    for (int end = 0; end < 2; ++end) {
      const double t = end;
      const Vec3d d1 = S.spine.d1(t), d2 = S.spine.d2(t);
      const Vec3d tt = d1.normalized();
      const Vec3d n = (d2 - d2.dot(tt) * tt).normalized();
      Vec3d x = eval_x(S, theta, t);
      const Vec3d w = (x - S.spine.point(t)).normalized();
      const double kappa = skin_spine_curvature(S.spine, t);
      const SkinEnd& E = S.ends[end];
      EXPECT_NEAR(a[end], E.inv_c * (1 - w.dot(n) * kappa * E.radius), 1e-13) << end;
    }
  }
}

// (4) with ERRATA's v = a (x - q): the curve theta = const starts at q_i on
// the first circle with s_t = a_i (x_i - q_i), ends at q_f with a_f (x_f - q_f).
TEST(SphereSkinPaper, HermiteConditions4) {
  Skew k;
  SphereSkin S;
  ASSERT_EQ(make_sphere_skin(k.s, k.e, SkinOptions{}, S), Status::ok);
  for (double theta = -3; theta < 3.2; theta += 0.5) {
    double a[2];
    skin_lambda(S, theta, 0.5, a);
    for (int end = 0; end < 2; ++end) {
      const SkinEnd& E = S.ends[end];
      Vec3d xt;
      const Vec3d q = eval_x(S, theta, end, &xt);
      EXPECT_NEAR((q - E.center).norm(), E.radius, 1e-13);
      EXPECT_NEAR((q - E.center).dot(E.tangent.normalized()), 0.0, 1e-13);
      const Vec3d apex = E.center + (1.0 / E.inv_c) * E.tangent;
      const Vec3d v = a[end] * (apex - q);
      EXPECT_LE((xt - v).norm(), 1e-12 * v.norm()) << theta << " end " << end;
    }
  }
}

// Eqs. (2)-(3) with ERRATA: W1(t) = cos theta(t) n(t) - sin theta(t) b(t)
// with theta(t) = theta_0 + int tau |alpha'| and the usual torsion tau =
// det(alpha', alpha'', alpha''') / |alpha' x alpha''|^2; cos theta_0 =
// w_i . n(0), sin theta_0 = -w_i . b(0). (The printed minus sign gives a
// frame that is not rotation-minimizing.)
TEST(SphereSkinPaper, RmfIsFrenetTurnedByTheTorsionIntegral) {
  Skew k;
  SphereSkin S;
  ASSERT_EQ(make_sphere_skin(k.s, k.e, SkinOptions{}, S), Status::ok);
  const SkinSpine& a = S.spine;
  auto frenet = [&](double t, Vec3d& n, Vec3d& b) {
    const Vec3d d1 = a.d1(t), d2 = a.d2(t);
    b = d1.cross(d2).normalized();
    n = b.cross(d1.normalized());
  };
  Vec3d n0, b0, w0;
  frenet(0.0, n0, b0);
  rmf_at(a, S.rmf, 0.0, w0, nullptr);
  const double theta0 = std::atan2(-w0.dot(b0), w0.dot(n0));
  double z[16], w[16];
  gauss_legendre01(16, z, w);
  double integral = 0;
  const int pieces = 16;
  for (double T : {0.25, 0.5, 1.0}) {
    integral = 0;
    for (int p = 0; p < pieces; ++p)
      for (int i = 0; i < 16; ++i) {
        const double t = T * (p + z[i]) / pieces;
        const Vec3d d1 = a.d1(t), d2 = a.d2(t), d3 = a.d3();
        const Vec3d c = d1.cross(d2);
        integral += T * w[i] / pieces * d1.dot(d2.cross(d3)) / c.squaredNorm() * d1.norm();
      }
    Vec3d n, b, W1;
    frenet(T, n, b);
    rmf_at(a, S.rmf, T, W1, nullptr);
    const double th = theta0 + integral;
    EXPECT_LE((W1 - (std::cos(th) * n - std::sin(th) * b)).norm(), 1e-11) << T;
    const double wrong = theta0 - integral;  // the printed sign
    if (std::abs(integral) > 1e-3) {
      EXPECT_GT((W1 - (std::cos(wrong) * n - std::sin(wrong) * b)).norm(), 1e-4) << T;
    }
  }
}

// Both integrators meet their tolerance and agree; the reference reaches
// 1e-13.
TEST(SphereSkinPaper, DoubleReflectionAgreesWithTheReference) {
  Skew k;
  SkinOptions ref, dr;
  dr.method = RmfMethod::double_reflection;
  SphereSkin A, B;
  ASSERT_EQ(make_sphere_skin(k.s, k.e, ref, A), Status::ok);
  ASSERT_EQ(make_sphere_skin(k.s, k.e, dr, B), Status::ok);
  EXPECT_LE(A.rmf.error_estimate, 1e-13);
  EXPECT_LE(B.rmf.error_estimate, 1e-13);
  EXPECT_EQ(A.rmf.method, RmfMethod::reference);
  EXPECT_EQ(B.rmf.method, RmfMethod::double_reflection);
  for (int i = 0; i <= 100; ++i) {
    const double t = i / 100.0 - 0.0013 * (i % 3);
    const double tc = std::max(t, 0.0);
    Vec3d wa, wb;
    rmf_at(A.spine, A.rmf, tc, wa, nullptr);
    rmf_at(B.spine, B.rmf, tc, wb, nullptr);
    EXPECT_LE((wa - wb).norm(), 1e-12) << tc;
  }
}

// §2's baselines on skew axes: their pairing differs from the RMF's by
// delta, and the measured twist of their parameter curves is |delta|,
// while the RMF skin's is zero; all three start at the same point.
TEST(SphereSkinPaper, BaselinesTwistTheRmfDoesNot) {
  Skew k;
  SkinOptions o;
  SphereSkin R, KH, X;
  ASSERT_EQ(make_sphere_skin(k.s, k.e, o, R), Status::ok);
  o.pairing = SkinPairing::kunkli_hoffmann;
  ASSERT_EQ(make_sphere_skin(k.s, k.e, o, KH), Status::ok);
  o.pairing = SkinPairing::cross_tangents;
  ASSERT_EQ(make_sphere_skin(k.s, k.e, o, X), Status::ok);
  EXPECT_EQ(R.delta, 0.0);
  EXPECT_GT(std::abs(KH.delta), 0.05);
  EXPECT_LE((eval_x(R, 0.4, 0.0) - eval_x(KH, 0.4, 0.0)).norm(), 1e-14);
  for (double theta : {0.0, 1.0, 2.5, -1.7}) {
    double tr, tk, tx;
    ASSERT_EQ(skin_twist(R, theta, tr), Status::ok);
    ASSERT_EQ(skin_twist(KH, theta, tk), Status::ok);
    ASSERT_EQ(skin_twist(X, theta, tx), Status::ok);
    EXPECT_LE(tr, 1e-10);
    EXPECT_NEAR(tk, std::abs(KH.delta), 1e-9);
    EXPECT_NEAR(tx, std::abs(X.delta), 1e-9);
  }
  // KH's end point at theta = 0 is its u_f = +-e x t_f / |e x t_f|, e the
  // default (the axis least aligned with both tangents: y here); the cross
  // pairing's is t_i x t_f / |t_i x t_f| at both ends.
  const Vec3d q = eval_x(KH, 0.0, 1.0) - k.e.center;
  EXPECT_NEAR(std::abs(q.normalized().dot(Vec3d(0, 1, 0).cross(k.e.tangent).normalized())), 1.0,
              1e-12);
  const Vec3d c = k.s.tangent.cross(k.e.tangent).normalized();
  EXPECT_LE(((eval_x(X, 0.0, 0.0) - k.s.center).normalized() - c).norm(), 1e-13);
  EXPECT_LE(((eval_x(X, 0.0, 1.0) - k.e.center).normalized() - c).norm(), 1e-12);
}

// A straight spine (coaxial circles, Frenet undefined): the RMF is
// constant, the skin a surface of revolution without twist.
TEST(SphereSkinPaper, StraightSpine) {
  SkinEnd s, e;
  ASSERT_EQ(skin_end_from_sphere({0, 0, 0}, 1.0, {0.2, 0, 0}, {2, 0, 0}, s), Status::ok);
  ASSERT_EQ(skin_end_from_sphere({3, 0, 0}, 0.5, {2.9, 0, 0}, {2, 0, 0}, e), Status::ok);
  SphereSkin S;
  ASSERT_EQ(make_sphere_skin(s, e, SkinOptions{}, S), Status::ok);
  Vec3d w0, w1;
  rmf_at(S.spine, S.rmf, 0.0, w0, nullptr);
  for (double t : {0.3, 0.77, 1.0}) {
    rmf_at(S.spine, S.rmf, t, w1, nullptr);
    EXPECT_LE((w1 - w0).norm(), 1e-15);
  }
  double tw;
  ASSERT_EQ(skin_twist(S, 1.0, tw), Status::ok);
  EXPECT_LE(tw, 1e-14);
  // Revolution: the distance from the axis depends on t only.
  for (double t : {0.1, 0.5, 0.8}) {
    const Vec3d a = eval_x(S, 0.3, t), b = eval_x(S, 2.9, t);
    EXPECT_NEAR(std::hypot(a.y(), a.z()), std::hypot(b.y(), b.z()), 1e-14);
    EXPECT_NEAR(a.x(), b.x(), 1e-14);
  }
}

// The grid gives the single points' bits; normals are unit, orthogonal to
// the partials, and outward (away from the spine) where lambda > 0.
TEST(SphereSkinPaper, GridAndNormals) {
  Skew k;
  SphereSkin S;
  ASSERT_EQ(make_sphere_skin(k.s, k.e, SkinOptions{}, S), Status::ok);
  const double th[5] = {-3.0, -1.0, 0.0, 1.5, 3.1};
  const double ts[4] = {0.0, 0.3, 0.61, 1.0};
  double X[60], N[60];
  ASSERT_EQ(skin_eval_grid(S, th, 5, ts, 4, X, N), Status::ok);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 5; ++i) {
      double x[3], a[3], b[3], n[3];
      ASSERT_EQ(skin_eval(S, th[i], ts[j], x, a, b, n), Status::ok);
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(x[c], X[3 * (5 * j + i) + c]);
        EXPECT_EQ(n[c], N[3 * (5 * j + i) + c]);
      }
      const Vec3d nv(n[0], n[1], n[2]), xa(a[0], a[1], a[2]), xb(b[0], b[1], b[2]);
      EXPECT_NEAR(nv.norm(), 1.0, 1e-15);
      EXPECT_LE(std::abs(nv.dot(xa)), 1e-13 * xa.norm());
      EXPECT_LE(std::abs(nv.dot(xb)), 1e-13 * xb.norm());
      EXPECT_GT(nv.dot(Vec3d(x[0], x[1], x[2]) - S.spine.point(ts[j])), 0.0);
    }
}

// A chain of three spheres: the patches share the middle circle, the
// theta-curves continue across it, and the joint is G^1.
TEST(SphereSkinPaper, ChainIsG1AtTheSharedCircle) {
  SkinEnd ends[3];
  ASSERT_EQ(skin_end_from_sphere({0, 0, 0}, 1.0, {0.3, 0, 0}, {3, 0, 0}, ends[0]), Status::ok);
  const Vec3d ax = Vec3d(1, 0.5, 0.3).normalized();
  ASSERT_EQ(skin_end_from_sphere({4, 1, 0}, 0.8, Vec3d(4, 1, 0) - 0.1 * ax, 3.0 * ax, ends[1]),
            Status::ok);
  const Vec3d ax2 = Vec3d(0.2, 1, -0.4).normalized();
  ASSERT_EQ(skin_end_from_sphere({6, 4, -1}, 1.1, Vec3d(6, 4, -1) - 0.3 * ax2, 3.0 * ax2, ends[2]),
            Status::ok);
  SphereSkin P[2];
  int bad = -1;
  ASSERT_EQ(make_sphere_skin_chain(ends, 3, SkinOptions{}, P, &bad), Status::ok);
  EXPECT_EQ(bad, -1);
  for (double theta = -3; theta < 3.2; theta += 0.4) {
    double x0[3], x1[3], n0[3], n1[3];
    ASSERT_EQ(skin_eval(P[0], theta, 1.0, x0, nullptr, nullptr, n0), Status::ok);
    ASSERT_EQ(skin_eval(P[1], theta, 0.0, x1, nullptr, nullptr, n1), Status::ok);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(x0[c], x1[c], 1e-12);
      EXPECT_NEAR(n0[c], n1[c], 1e-11);
    }
  }
  // The second patch failing (nested spheres) is named, nothing written.
  SkinEnd bad_ends[3] = {ends[0], ends[1], ends[1]};
  bad_ends[2].center += 0.01 * ax;
  SphereSkin Q[2];
  Q[0].delta = 123.0;
  EXPECT_NE(make_sphere_skin_chain(bad_ends, 3, SkinOptions{}, Q, &bad), Status::ok);
  EXPECT_EQ(bad, 1);
  EXPECT_EQ(Q[0].delta, 123.0);
}

// Ends from apex and from sphere agree; the cone's generatrix from the
// circle to the apex is tangent to the sphere.
TEST(SphereSkinPaper, EndsFromApexAndSphere) {
  const Vec3d m(1, 2, 3), t = Vec3d(0.3, -1, 0.5);
  SkinEnd a, b;
  const Vec3d p = m - 0.4 * t.normalized();
  ASSERT_EQ(skin_end_from_sphere(m, 1.5, p, t, a), Status::ok);
  const Vec3d apex = p + (1.0 / a.inv_c) * t;
  ASSERT_EQ(skin_end_from_apex(p, a.radius, t, apex, b), Status::ok);
  EXPECT_NEAR(a.inv_c, b.inv_c, 1e-15);
  Vec3d mc;
  double R;
  skin_end_sphere(a, mc, R);
  EXPECT_LE((mc - m).norm(), 1e-14);
  EXPECT_NEAR(R, 1.5, 1e-14);
  const Vec3d q = p + a.radius * t.cross(Vec3d(1, 0, 0)).normalized();
  EXPECT_NEAR((apex - q).dot(q - m), 0.0, 1e-13);
  // A great circle: a cylinder (inv_c = 0).
  ASSERT_EQ(skin_end_from_sphere(m, 1.5, m, t, a), Status::ok);
  EXPECT_EQ(a.inv_c, 0.0);
  EXPECT_EQ(a.radius, 1.5);
  // Off the axis, apex at the center, a plane missing the sphere.
  EXPECT_EQ(skin_end_from_apex(p, 1.0, t, p + Vec3d(1, 0, 0), b), Status::invalid_argument);
  EXPECT_EQ(skin_end_from_apex(p, 1.0, t, p, b), Status::invalid_argument);
  EXPECT_EQ(skin_end_from_sphere(m, 1.5, m - 2.0 * t.normalized(), t, b),
            Status::invalid_argument);
}

// The default tangents: chord length, same cones and spheres.
TEST(SphereSkinPaper, ChordTangents) {
  Skew k;
  SkinEnd s = k.s, e = k.e;
  skin_chord_tangents(s, e);
  const double chord = (k.e.center - k.s.center).norm();
  for (int i = 0; i < 2; ++i) {
    const SkinEnd &in = i ? k.e : k.s, &out = i ? e : s;
    EXPECT_NEAR(out.tangent.norm(), chord, 1e-14 * chord);
    EXPECT_LE((out.tangent.normalized() - in.tangent.normalized()).norm(), 1e-15);
    Vec3d m0, m1;
    double R0, R1;
    skin_end_sphere(in, m0, R0);
    skin_end_sphere(out, m1, R1);
    EXPECT_LE((m0 - m1).norm(), 1e-13);
    EXPECT_NEAR(R0, R1, 1e-13);
  }
  SphereSkin S;
  EXPECT_EQ(make_sphere_skin(s, e, SkinOptions{}, S), Status::ok);
}

// The degenerate inputs of the issue: statuses, nothing written.
TEST(SphereSkinPaper, DegenerateInputs) {
  Skew k;
  SphereSkin S;
  S.delta = 7.0;
  auto run = [&](const SkinEnd& s, const SkinEnd& e, SkinOptions o = SkinOptions{}) {
    return make_sphere_skin(s, e, o, S);
  };
  SkinEnd s = k.s;
  s.radius = 0;
  EXPECT_EQ(run(s, k.e), Status::invalid_argument);  // zero-radius circle
  s = k.s;
  s.center.x() = NAN;
  EXPECT_EQ(run(s, k.e), Status::not_finite);
  s = k.s;
  s.tangent = Vec3d::Zero();
  EXPECT_EQ(run(s, k.e), Status::zero_tangent);
  EXPECT_EQ(run(k.s, k.s), Status::nested_spheres);  // coincident spheres
  SkinEnd inner;  // a small sphere inside the first
  ASSERT_EQ(skin_end_from_sphere({0.2, 0, 0}, 0.3, {0.3, 0, 0}, {1, 0, 0}, inner), Status::ok);
  EXPECT_EQ(run(k.s, inner), Status::nested_spheres);
  // kappa r >= 1: short tangents bend the spine sharply at the start.
  s = k.s;
  s.tangent *= 0.05;
  EXPECT_EQ(run(s, k.e), Status::curvature_radius_too_large);
  // cross_tangents with parallel axes.
  SkinEnd e = k.e;
  e.tangent = k.s.tangent;
  SkinOptions o;
  o.pairing = SkinPairing::cross_tangents;
  EXPECT_EQ(run(k.s, e, o), Status::parallel_lines);
  o = SkinOptions{};
  o.tolerance = 0;
  EXPECT_EQ(run(k.s, k.e, o), Status::invalid_argument);
  o.tolerance = NAN;
  EXPECT_EQ(run(k.s, k.e, o), Status::not_finite);
  o = SkinOptions{};
  o.pairing = SkinPairing(9);
  EXPECT_EQ(run(k.s, k.e, o), Status::invalid_argument);
  EXPECT_EQ(S.delta, 7.0);
  // Evaluation outside [0, 1] and of NaN.
  ASSERT_EQ(make_sphere_skin(k.s, k.e, SkinOptions{}, S), Status::ok);
  double x[3] = {5, 5, 5};
  EXPECT_EQ(skin_eval(S, 0.0, 1.5, x, nullptr, nullptr, nullptr), Status::bad_domain);
  EXPECT_EQ(skin_eval(S, NAN, 0.5, x, nullptr, nullptr, nullptr), Status::not_finite);
  EXPECT_EQ(x[0], 5.0);
}
