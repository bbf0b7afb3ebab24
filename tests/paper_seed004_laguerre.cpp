// Seed 004 (Peternell–Pottmann, "Designing rational surfaces with rational
// offsets"), §2–§3: the Laguerre primitives of laguerre.hpp (the
// cyclographic model (2.1), the Blaschke cylinder (2.2), the isotropic model
// Lambda (2.3) with its exceptional planes, Lemma 2.1 / (2.4), translations
// (2.5), dilatations (2.6), the exterior product of §4.1) and PN surfaces as
// Lambda^{-1} images (Theorem 3.2) on the examples of §3 and §4.1 (spheres
// from cycle paraboloids, parabolic Dupin cyclides (4.1)-(4.3), the
// developable and point-at-infinity degeneracies). Labels "paper;laguerre".
//
// Every expectation is computed independently of the code under test: from
// the paper's closed forms, implicit equations, or direct linear algebra.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <vector>

#include "cyclide/laguerre.hpp"
#include "cyclide/pn_surface.hpp"

using namespace cyclide;

namespace {

OrientedPlane unit_plane(double e0, const Vec3d& e) {
  OrientedPlane p;
  EXPECT_EQ(normalize_plane(e0, e, p), Status::ok);
  return p;
}

IsotropicPoint lambda(const OrientedPlane& p) {
  IsotropicPoint y;
  EXPECT_EQ(laguerre_to_isotropic(p, y), Status::ok);
  return y;
}

IsotropicPoint finite_point(const Vec3d& y) {
  IsotropicPoint p;
  p.y = y;
  return p;
}

// (2.4) evaluated directly: 2 y3 + q (r + m3) + 2 y1 m1 + 2 y2 m2 + r - m3.
double paraboloid_24(const Cycle& z, const Vec3d& y) {
  const double q = y[0] * y[0] + y[1] * y[1];
  return 2 * y[2] + q * (z.r + z.m[2]) + 2 * y[0] * z.m[0] + 2 * y[1] * z.m[1] + z.r - z.m[2];
}

// ------------------------------------------------------------ Bezier helpers

double binom(int n, int k) {
  double b = 1;
  for (int i = 1; i <= k; ++i) b = b * (n - k + i) / i;
  return b;
}

double bernstein(int n, int i, double t) {
  return binom(n, i) * std::pow(t, i) * std::pow(1 - t, n - i);
}

// Control net (bidegree m, n) whose tensor Bernstein form interpolates the
// homogeneous polynomial map f at the grid (i/m, j/n): exact for maps of
// bidegree <= (m, n). Solved per component with the collocation matrices.
std::vector<Vec4d> bezier_from_map(const std::function<Vec4d(double, double)>& f, int m, int n) {
  auto nodes = [](int deg) {
    std::vector<double> t(deg + 1);
    for (int i = 0; i <= deg; ++i) t[i] = deg == 0 ? 0.5 : double(i) / deg;
    return t;
  };
  const std::vector<double> tu = nodes(m), tv = nodes(n);
  Eigen::MatrixXd Mu(m + 1, m + 1), Mv(n + 1, n + 1);
  for (int a = 0; a <= m; ++a)
    for (int i = 0; i <= m; ++i) Mu(a, i) = bernstein(m, i, tu[a]);
  for (int b = 0; b <= n; ++b)
    for (int j = 0; j <= n; ++j) Mv(b, j) = bernstein(n, j, tv[b]);
  std::vector<Vec4d> net((m + 1) * (n + 1));
  for (int c = 0; c < 4; ++c) {
    Eigen::MatrixXd F(m + 1, n + 1);
    for (int a = 0; a <= m; ++a)
      for (int b = 0; b <= n; ++b) F(a, b) = f(tu[a], tv[b])[c];
    const Eigen::MatrixXd C1 = Mu.fullPivLu().solve(F);                             // Mu C Mv^T = F
    const Eigen::MatrixXd C = Mv.fullPivLu().solve(C1.transpose()).transpose();  // C Mv^T = C1
    for (int i = 0; i <= m; ++i)
      for (int j = 0; j <= n; ++j) net[i * (n + 1) + j][c] = C(i, j);
  }
  return net;
}

// A polynomial surface y(u, v) (weight 1) as a Bezier net of bidegree (m, n).
std::vector<Vec4d> polynomial_net(const std::function<Vec3d(double, double)>& y, int m, int n) {
  return bezier_from_map(
      [&](double u, double v) {
        const Vec3d p = y(u, v);
        return Vec4d(1, p[0], p[1], p[2]);
      },
      m, n);
}

PnSurface make(const std::vector<Vec4d>& net, int m, int n) {
  PnSurface S;
  EXPECT_EQ(make_pn_surface(net.data(), m, n, S), Status::ok);
  return S;
}

// The quadratic graph y3 = -(a y1^2 + b y2^2)/2 + c over the parameter
// square mapped affinely to [y1a, y1b] x [y2a, y2b].
struct Graph {
  double a, b, c, y1a, y1b, y2a, y2b;
  Vec3d y(double u, double v) const {
    const double y1 = y1a + (y1b - y1a) * u, y2 = y2a + (y2b - y2a) * v;
    return Vec3d(y1, y2, -(a * y1 * y1 + b * y2 * y2) / 2 + c);
  }
};

// ------------------------------------------------------------------ §2

// (2.1): the hyperplane E = (e0, e1, e2, e3, 1) meets R^3 (x4 = 0) at the
// angle pi/4, and contains the cyclographic point (m, r) of every cycle in
// oriented contact with e (E . (1, m, r) = e0 + e.m + r).
TEST(Seed004Laguerre, Eq21_CyclographicHyperplaneAngleAndContact) {
  const OrientedPlane p = unit_plane(0.7, Vec3d(1, -2, 2));
  const auto E = cyclographic_hyperplane(p);
  const Eigen::Vector4d normal(E[1], E[2], E[3], E[4]);  // of sum E_i x_i + E0 = 0
  const double cos_angle = normal[3] / normal.norm();   // with R^3's normal (0,0,0,1)
  EXPECT_NEAR(std::acos(cos_angle), M_PI / 4, 1e-15);
  const Cycle z{Vec3d(0.3, -1.1, 2.0), 0.8};
  // The plane through the point of contact m + r e with normal e touches z.
  OrientedPlane t;
  t.e = p.e;
  t.e0 = -p.e.dot(z.m + z.r * p.e);
  const auto Et = cyclographic_hyperplane(t);
  Eigen::Matrix<double, 5, 1> zeta;
  zeta << 1, z.m[0], z.m[1], z.m[2], z.r;
  EXPECT_NEAR(Et.dot(zeta), 0, 1e-15);
  EXPECT_TRUE(in_oriented_contact(z, t));
  // The opposite orientation does not touch (it touches (m, -r)).
  OrientedPlane flipped{-t.e0, -t.e};
  EXPECT_FALSE(in_oriented_contact(z, flipped));
  EXPECT_TRUE(in_oriented_contact(Cycle{z.m, -z.r}, flipped));
}

// (2.2): Blaschke points of unit planes lie on the cylinder Delta.
TEST(Seed004Laguerre, Eq22_BlaschkePointsOnCylinder) {
  for (const Vec3d& e : {Vec3d(1, 2, 3), Vec3d(0, 0, 1), Vec3d(-1e-9, 0, -1), Vec3d(5, -1, 0)}) {
    const auto B = blaschke_point(unit_plane(-4.5, e));
    EXPECT_EQ(B[0], 1.0);
    EXPECT_NEAR(B[1] * B[1] + B[2] * B[2] + B[3] * B[3], 1.0, 1e-15);
    EXPECT_DOUBLE_EQ(B[4], unit_plane(-4.5, e).e0);
  }
}

// (2.3): Lambda is the projection of the Blaschke point from W = (0,0,1,0)
// onto x3 = 0 (coordinates y1 = x1, y2 = x2, y3 = x4): the line W + t (B - W)
// meets x3 = 0 at t = 1 / (1 - e3).
TEST(Seed004Laguerre, Eq23_LambdaIsStereographicProjection) {
  const Vec3d normals[] = {Vec3d(1, 2, 3), Vec3d(0.3, -0.2, -5), Vec3d(1, 0, 0), Vec3d(-2, 1, 0.5)};
  for (const Vec3d& e : normals) {
    const OrientedPlane p = unit_plane(1.25, e);
    const auto B = blaschke_point(p);
    const Eigen::Vector4d Wp(0, 0, 1, 0), Bp(B[1], B[2], B[3], B[4]);
    const double t = -Wp[2] / (Bp[2] - Wp[2]);
    const Eigen::Vector4d s = Wp + t * (Bp - Wp);
    EXPECT_NEAR(s[2], 0, 1e-15);
    const IsotropicPoint y = lambda(p);
    ASSERT_FALSE(y.exceptional);
    EXPECT_NEAR((y.y - Vec3d(s[0], s[1], s[3])).norm(), 0, 1e-14 * (1 + y.y.norm()));
  }
}

// Λ maps the exceptional plane (e0, 0, 0, 1) to the real number e0 and back;
// the plane with normal -W is an ordinary point, (0, 0, e0 / 2).
TEST(Seed004Laguerre, Eq23_ExceptionalPlanesAreRealNumbers) {
  for (double c : {0.0, 2.5, -1e7}) {
    const IsotropicPoint y = lambda(unit_plane(2 * c, Vec3d(0, 0, 2)));  // unnormalized input
    ASSERT_TRUE(y.exceptional);
    EXPECT_DOUBLE_EQ(y.c, c);
    OrientedPlane p;
    ASSERT_EQ(isotropic_to_laguerre(y, p), Status::ok);
    EXPECT_EQ(p.e0, c);
    EXPECT_EQ(p.e, Vec3d(0, 0, 1));
    const IsotropicPoint down = lambda(unit_plane(c, Vec3d(0, 0, -1)));
    ASSERT_FALSE(down.exceptional);
    EXPECT_EQ(down.y, Vec3d(0, 0, c / 2));
  }
  // The exceptional planes touch a cycle iff c + m3 + r = 0 ((2.4) extended by r + m3).
  const Cycle z{Vec3d(1, 2, 3), 0.5};
  IsotropicPoint c;
  c.exceptional = true;
  c.c = -3.5;
  EXPECT_TRUE(on_paraboloid(cycle_to_paraboloid(z), c));
  c.c = -3.4;
  EXPECT_FALSE(on_paraboloid(cycle_to_paraboloid(z), c));
}

// (2.3) for normals within delta of W: with e = (a, b, 1) / s, s = sqrt(1 +
// delta^2), delta^2 = a^2 + b^2, the exact image is y = (a, b, e0') (s + 1) /
// delta^2 for the plane (e0', (a, b, 1)) (1 - e3 = delta^2 / (s (s + 1))).
TEST(Seed004Laguerre, Eq23_NormalsNearW) {
  for (double delta : {1e-8, 1e-10, 1e-12, 1e-15, 1e-100}) {
    for (double theta : {0.3, 2.0, -2.5}) {
      const double a = delta * std::cos(theta), b = delta * std::sin(theta), e0 = -0.75;
      const double d2 = a * a + b * b, s = std::sqrt(1 + d2);
      const Vec3d expect = Vec3d(a, b, e0) * ((s + 1) / d2);
      IsotropicPoint y;
      OrientedPlane p;
      p.e0 = e0;
      p.e = Vec3d(a, b, 1);  // laguerre_to_isotropic normalizes
      const Status st = laguerre_to_isotropic(p, y);
      if (delta < 1e-150) {
        EXPECT_EQ(st, Status::numerical_overflow);
        continue;
      }
      ASSERT_EQ(st, Status::ok);
      ASSERT_FALSE(y.exceptional);
      EXPECT_LE((y.y - expect).norm(), 1e-14 * expect.norm()) << delta;
      // Λ^{-1} recovers the unit plane to full accuracy.
      OrientedPlane back;
      ASSERT_EQ(isotropic_to_laguerre(y, back), Status::ok);
      EXPECT_LE((back.e - Vec3d(a, b, 1) / s).norm(), 1e-15);
      EXPECT_NEAR(back.e0, e0 / s, 1e-15);
    }
  }
}

// Lemma 2.1 / (2.4) on a worked example: the cycle m = (1, 2, 3), r = 1/2
// has k = 7/2, l = (1, 2), c0 = -5/2; its tangent plane with normal
// (0, 0, -1) is e0 = 5/2, Lambda = (0, 0, 5/4), and 2 * 5/4 - 5/2 = 0.
TEST(Seed004Laguerre, Lemma21_Eq24_WorkedExample) {
  const Cycle z{Vec3d(1, 2, 3), 0.5};
  const IsotropicParaboloid P = cycle_to_paraboloid(z);
  EXPECT_EQ(P.k, 3.5);
  EXPECT_EQ(P.l1, 1.0);
  EXPECT_EQ(P.l2, 2.0);
  EXPECT_EQ(P.c0, -2.5);
  const OrientedPlane t{2.5, Vec3d(0, 0, -1)};
  EXPECT_TRUE(in_oriented_contact(z, t));
  const IsotropicPoint y = lambda(t);
  EXPECT_EQ(y.y, Vec3d(0, 0, 1.25));
  EXPECT_EQ(paraboloid_24(z, y.y), 0.0);
  EXPECT_TRUE(on_paraboloid(P, y));
  // A general tangent plane (normal e, e0 = -e.m - r) lands on (2.4).
  for (const Vec3d& e : {Vec3d(1, 1, 1), Vec3d(-3, 0.5, 0.1), Vec3d(0.2, -0.1, 0.9)}) {
    OrientedPlane q;
    q.e = e.normalized();
    q.e0 = -q.e.dot(z.m) - z.r;
    const IsotropicPoint w = lambda(q);
    EXPECT_NEAR(paraboloid_24(z, w.y), 0, 1e-13 * (1 + w.y.squaredNorm()));
  }
  // A point cycle (r = 0) gives the paraboloid of planes through it; a
  // cycle with r + m3 = 0 a plane of I^3 (it touches the exceptional plane c = 0).
  EXPECT_EQ(cycle_to_paraboloid(Cycle{Vec3d(0, 0, -2), 2}).k, 0.0);
}

// (2.5): a translation by t = (a, b, c) of R^3. In plane coordinates the
// paper writes e0 -> e0 + a e1 + b e2 + c e3 (a translation by -t) and
// y3 -> y3 + a y1 + b y2 + (c/2)(y1^2 + y2^2 - 1); laguerre.hpp's translate
// by t is that map with (a, b, c) = -t.
TEST(Seed004Laguerre, Eq25_Translation) {
  const OrientedPlane p = unit_plane(0.4, Vec3d(0.3, -0.7, 0.2));
  const Vec3d t(1.5, -2, 0.25);
  const OrientedPlane moved = translate(p, t);
  // A point x of p goes to x + t on the moved plane.
  const Vec3d x = -p.e0 * p.e + Vec3d(0.7, 0.3, 0).cross(p.e);  // some point of p
  EXPECT_NEAR(p.e0 + p.e.dot(x), 0, 1e-15);
  EXPECT_NEAR(moved.e0 + moved.e.dot(x + t), 0, 1e-14);
  // (2.5) with (a, b, c) = -t, written out.
  const IsotropicPoint y = lambda(p);
  const double q = y.y[0] * y.y[0] + y.y[1] * y.y[1];
  const Vec3d expect(y.y[0], y.y[1],
                     y.y[2] - t[0] * y.y[0] - t[1] * y.y[1] - t[2] / 2 * (q - 1));
  EXPECT_LE((lambda(moved).y - expect).norm(), 1e-14 * (1 + expect.norm()));
  EXPECT_LE((isotropic_translate(y, t).y - expect).norm(), 1e-14 * (1 + expect.norm()));
  // The exceptional plane (c, 0, 0, 1) moves to c - t3.
  IsotropicPoint c;
  c.exceptional = true;
  c.c = 2;
  EXPECT_EQ(isotropic_translate(c, t).c, 1.75);
  EXPECT_EQ(lambda(translate(OrientedPlane{2, Vec3d(0, 0, 1)}, t)).c, 1.75);
}

// (2.6): the dilatation adding d to every radius. With (2.4)'s contact rule
// it is e0 -> e0 - d and y3 -> y3 - (d/2)(y1^2 + y2^2 + 1); the paper's
// printed map (e0 -> e0 + d, y3 + (d/2)(...)) is the same map for -d (it
// subtracts d from the radii). The contact point with (m, r + d) is the
// old one moved by d e (offsetting).
TEST(Seed004Laguerre, Eq26_DilatationAddsToRadius) {
  const Cycle z{Vec3d(0.5, -1, 2), 1.25};
  const double d = 0.75;
  OrientedPlane p;
  p.e = Vec3d(2, -1, 2) / 3;
  p.e0 = -p.e.dot(z.m) - z.r;
  const OrientedPlane q = dilatation(p, d);
  const Cycle zd{z.m, z.r + d};
  EXPECT_NEAR(q.e0 + q.e.dot(zd.m) + zd.r, 0, 1e-15);
  EXPECT_TRUE(in_oriented_contact(zd, q));
  EXPECT_FALSE(in_oriented_contact(Cycle{z.m, z.r - d}, q));
  EXPECT_LE((contact_point(zd, q) - (contact_point(z, p) + d * p.e)).norm(), 1e-15);
  const IsotropicPoint y = lambda(p);
  const double q2 = y.y[0] * y.y[0] + y.y[1] * y.y[1];
  const Vec3d ours(y.y[0], y.y[1], y.y[2] - d / 2 * (q2 + 1));
  EXPECT_LE((lambda(q).y - ours).norm(), 1e-14 * (1 + ours.norm()));
  EXPECT_LE((isotropic_dilatation(y, d).y - ours).norm(), 1e-15 * (1 + ours.norm()));
  // The paper's printed (2.6) with +d equals ours with -d.
  const Vec3d printed(y.y[0], y.y[1], y.y[2] + d / 2 * (q2 + 1));
  EXPECT_LE((isotropic_dilatation(y, -d).y - printed).norm(), 1e-15 * (1 + printed.norm()));
  // The image lies on the paraboloid of the dilated cycle.
  EXPECT_NEAR(paraboloid_24(zd, ours), 0, 1e-14 * (1 + ours.squaredNorm()));
}

// §4.1's exterior product: the planes x1 = 1, x2 = 2, x3 = 3 meet in
// (1 : 1 : 2 : 3); dependent planes give 0; X . w = det[a; b; c; w].
TEST(Seed004Laguerre, Sec41_ExteriorProduct) {
  const Vec4d a(-1, 1, 0, 0), b(-2, 0, 1, 0), c(-3, 0, 0, 1);
  const Vec4d X = exterior_product(a, b, c);
  ASSERT_NE(X[0], 0.0);
  EXPECT_EQ(Vec3d(X[1], X[2], X[3]) / X[0], Vec3d(1, 2, 3));
  EXPECT_EQ(exterior_product(a, b, Vec4d(2 * a - 3 * b)), Vec4d::Zero());
  const Vec4d w(0.3, -1, 2, 0.5);
  Eigen::Matrix4d M;
  M << a.transpose(), b.transpose(), c.transpose(), w.transpose();
  EXPECT_NEAR(X.dot(w), M.determinant(), 1e-14);
}

TEST(Seed004Laguerre, NormalizePlaneStatuses) {
  OrientedPlane p{7, Vec3d(1, 0, 0)};
  EXPECT_EQ(normalize_plane(1, Vec3d::Zero(), p), Status::invalid_argument);
  EXPECT_EQ(normalize_plane(NAN, Vec3d(1, 0, 0), p), Status::not_finite);
  EXPECT_EQ(normalize_plane(1, Vec3d(INFINITY, 0, 0), p), Status::not_finite);
  EXPECT_EQ(p.e0, 7.0);  // untouched on error
  ASSERT_EQ(normalize_plane(6, Vec3d(0, 3, 4), p), Status::ok);
  EXPECT_NEAR(p.e0, 1.2, 1e-15);
  EXPECT_EQ(p.e, Vec3d(0, 0.6, 0.8));
  ASSERT_EQ(normalize_plane(1e-300, Vec3d(0, 1e-300, 0), p), Status::ok);  // tiny scale
  EXPECT_EQ(p.e0, 1.0);
  IsotropicPoint y;
  EXPECT_EQ(laguerre_to_isotropic(OrientedPlane{1, Vec3d::Zero()}, y), Status::invalid_argument);
  OrientedPlane q;
  EXPECT_EQ(isotropic_to_laguerre(finite_point(Vec3d(NAN, 0, 0)), q), Status::not_finite);
  EXPECT_EQ(isotropic_to_laguerre(finite_point(Vec3d(1e200, 0, 0)), q),
            Status::numerical_overflow);
}

// ------------------------------------------------------------------ §3

// Theorem 3.2 on a cycle: Psi = the paraboloid (2.4) of (m, r) is the set of
// tangent planes of the sphere, so Phi = Lambda^{-1}(Psi) is the sphere
// itself, x = m + r n (the contact rule), and its offset at d is the sphere
// (m, r + d).
TEST(Seed004PnSurface, Thm32_SphereFromCycleParaboloid) {
  for (const Cycle& z : {Cycle{Vec3d(1, -2, 0.5), 1.5}, Cycle{Vec3d(0, 0, 0), -0.8},
                         Cycle{Vec3d(3, 1, -2), 2}}) {
    const IsotropicParaboloid P = cycle_to_paraboloid(z);
    // y3 = -(k q + 2 l.y + c0) / 2 over [-1.3, 0.9] x [-0.4, 1.6].
    const auto y = [&](double u, double v) {
      const double y1 = -1.3 + 2.2 * u, y2 = -0.4 + 2 * v;
      const double q = y1 * y1 + y2 * y2;
      return Vec3d(y1, y2, -(z.r + z.m[2]) * q / 2 - z.m[0] * y1 - z.m[1] * y2 - (z.r - z.m[2]) / 2);
    };
    (void)P;
    const PnSurface S = make(polynomial_net(y, 2, 2), 2, 2);
    for (double u : {0.0, 0.25, 0.6, 1.0})
      for (double v : {0.0, 0.4, 0.9}) {
        PnPoint pt;
        ASSERT_EQ(pn_surface_eval(S, u, v, 0, pt), Status::ok);
        EXPECT_NEAR((pt.x - z.m).norm(), std::abs(z.r), 1e-12);
        EXPECT_LE((pt.x - (z.m + z.r * pt.n)).norm(), 1e-12);
        EXPECT_TRUE(in_oriented_contact(z, pt.plane));
        // Offsets: the concentric sphere with radius r + d.
        PnPoint off;
        ASSERT_EQ(pn_surface_eval(S, u, v, 0.3, off), Status::ok);
        EXPECT_LE((off.x - (z.m + (z.r + 0.3) * pt.n)).norm(), 1e-12);
        EXPECT_TRUE(in_oriented_contact(Cycle{z.m, z.r + 0.3}, off.plane));
      }
  }
}

// (4.1)-(4.3), Theorem 4.1: the graph y3 = -(a y1^2 + b y2^2)/2 is mapped to
// the parabolic Dupin cyclide (4.1) (u = y1, v = y2), which satisfies (4.2),
// with tangent planes (4.3) psi = (-(a u^2 + b v^2), 2u, 2v, u^2 + v^2 - 1).
// Its offset at d is Lambda^{-1} of the dilated graph (2.6), the graph of
// -((a + d) y1^2 + (b + d) y2^2)/2 - d/2 (another quadratic).
TEST(Seed004PnSurface, Eq41_42_43_ParabolicCyclide) {
  const Graph graphs[] = {{1, -2, 0, -1.5, 1.2, -0.7, 1.9},    // ring (ab < 0)
                          {2, 0.5, 0, -0.9, 1.1, 0.3, 2.2},    // horn (ab > 0)
                          {1.5, 0, 0, 0.2, 1.7, -1.8, -0.1}};  // limit case b = 0
  for (const Graph& G : graphs) {
    const PnSurface S = make(polynomial_net([&](double u, double v) { return G.y(u, v); }, 2, 2), 2, 2);
    const double a = G.a, b = G.b;
    for (double u : {0.0, 0.3, 0.77, 1.0})
      for (double v : {0.0, 0.5, 0.81, 1.0}) {
        PnPoint pt;
        ASSERT_EQ(pn_surface_eval(S, u, v, 0, pt), Status::ok);
        const Vec3d y = G.y(u, v);
        const double U = y[0], V = y[1];
        // (4.1)
        const Eigen::Vector4d phi(1 + U * U + V * V, a * U + (a - b) * U * V * V,
                                  b * V + (b - a) * U * U * V, a * U * U + b * V * V);
        const Vec3d x41 = Vec3d(phi[1], phi[2], phi[3]) / phi[0];
        EXPECT_LE((pt.x - x41).norm(), 1e-13 * (1 + x41.norm()));
        // (4.2), x0 = 1
        const Vec3d& x = pt.x;
        const double r42 = (b * x[0] * x[0] + a * x[1] * x[1] + (a + b) * x[2] * x[2]) -
                           x[2] * (a * b + x.squaredNorm());
        EXPECT_NEAR(r42, 0, 1e-13 * (1 + std::pow(x.norm(), 3)));
        // (4.3) normalized: the plane (e0, e) = psi / |(psi1, psi2, psi3)|.
        const Eigen::Vector4d psi(-(a * U * U + b * V * V), 2 * U, 2 * V, U * U + V * V - 1);
        const double len = psi.tail<3>().norm();
        EXPECT_NEAR(pt.plane.e0, psi[0] / len, 1e-14 * (1 + std::abs(psi[0] / len)));
        EXPECT_LE((pt.plane.e - Vec3d(psi[1], psi[2], psi[3]) / len).norm(), 1e-15);
        EXPECT_NEAR(pt.plane.e0 + pt.plane.e.dot(pt.x), 0, 1e-13 * (1 + x.norm()));
      }
    // The offset at d = Lambda^{-1} of the dilated graph.
    const double d = -0.35;
    const Graph Gd{a + d, b + d, -d / 2, G.y1a, G.y1b, G.y2a, G.y2b};
    const PnSurface Sd = make(polynomial_net([&](double u, double v) { return Gd.y(u, v); }, 2, 2), 2, 2);
    for (double u : {0.1, 0.5, 0.95})
      for (double v : {0.05, 0.6}) {
        PnPoint off, dil;
        ASSERT_EQ(pn_surface_eval(S, u, v, d, off), Status::ok);
        ASSERT_EQ(pn_surface_eval(Sd, u, v, 0, dil), Status::ok);
        EXPECT_LE((off.x - dil.x).norm(), 1e-12 * (1 + off.x.norm()));
        EXPECT_LE((off.x_u - dil.x_u).norm(), 1e-11 * (1 + off.x_u.norm()));
        EXPECT_LE((off.x_v - dil.x_v).norm(), 1e-11 * (1 + off.x_v.norm()));
        EXPECT_LE((off.n - dil.n).norm(), 1e-15);
        EXPECT_NEAR(off.plane.e0, dil.plane.e0, 1e-13);
      }
  }
}

// Remark to Theorem 3.2: a Psi that is a curve (depends on u only; here with
// product weights w_i s_j varying along v, so the partial in v is zero only
// up to rounding),
// a point, or a piece of an isotropic line has no envelope point.
TEST(Seed004PnSurface, Thm32_DevelopableWhenPsiIsACurve) {
  std::vector<Vec4d> net;
  const Vec3d col[3] = {Vec3d(0.1, 0.2, -0.4), Vec3d(0.9, -0.3, 0.5), Vec3d(1.4, 0.8, 0.1)};
  const double w[3] = {1, 0.6, 2}, s[2] = {1, 1.7};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j) {
      const Vec3d wy = w[i] * s[j] * col[i];
      net.emplace_back(w[i] * s[j], wy[0], wy[1], wy[2]);
    }
  const PnSurface S = make(net, 2, 1);
  EXPECT_FALSE(S.degenerate);
  PnPoint pt;
  pt.x = Vec3d(7, 7, 7);
  for (double u : {0.0, 0.3, 1.0})
    for (double v : {0.0, 0.45, 1.0}) EXPECT_EQ(pn_surface_eval(S, u, v, 0, pt), Status::developable);
  EXPECT_EQ(pt.x, Vec3d(7, 7, 7));  // untouched
  // Degree 0 in v: exactly a curve.
  std::vector<Vec4d> curve = {Vec4d(1, 0, 0, 0), Vec4d(1, 1, 1, 1)};
  EXPECT_EQ(pn_surface_eval(make(curve, 1, 0), 0.5, 0.5, 0, pt), Status::developable);
  // A point and an isotropic line.
  std::vector<Vec4d> point(4, Vec4d(2, 1, 1, 1));
  EXPECT_TRUE(make(point, 1, 1).degenerate);
  EXPECT_EQ(pn_surface_eval(make(point, 1, 1), 0.5, 0.5, 0, pt), Status::developable);
  std::vector<Vec4d> line = {Vec4d(1, 0.5, 0.5, 0), Vec4d(1, 0.5, 0.5, 1), Vec4d(1, 0.5, 0.5, 3),
                             Vec4d(1, 0.5, 0.5, -2)};
  EXPECT_TRUE(make(line, 1, 1).degenerate);
  EXPECT_EQ(pn_surface_eval(make(line, 1, 1), 0.2, 0.7, 0, pt), Status::developable);
}

// §3: where Psi is touched by isotropic lines (y3-parallel occluding
// contour), Phi has a point at infinity. Psi = (u, v^2, v) folds over the
// (y1, y2) plane along v = 0, where Psi_v = (0, 0, 1) is isotropic.
// Near the contour the envelope conditions P.x = P_u.x = P_v.x = 0 still hold
// and |x| grows like 1 / v.
TEST(Seed004PnSurface, Sec3_IsotropicContourGivesPointAtInfinity) {
  const auto y = [](double u, double v) { return Vec3d(u, v * v, v); };
  const PnSurface S = make(polynomial_net(y, 1, 2), 1, 2);
  PnPoint pt;
  for (double u : {0.0, 0.5, 1.0}) EXPECT_EQ(pn_surface_eval(S, u, 0, 0, pt), Status::point_at_infinity);
  double previous = 0;
  for (double v : {1e-1, 1e-2, 1e-3, 1e-4}) {
    const double u = 0.4;
    ASSERT_EQ(pn_surface_eval(S, u, v, 0, pt), Status::ok) << v;
    // P = (2v, 2u, 2v^2, u^2 + v^4 - 1) and its partials, by hand.
    const Eigen::Vector4d P(2 * v, 2 * u, 2 * v * v, u * u + v * v * v * v - 1);
    const Eigen::Vector4d Pu(0, 2, 0, 2 * u), Pv(2, 0, 4 * v, 4 * v * v * v);
    const Eigen::Vector4d X1(1, pt.x[0], pt.x[1], pt.x[2]);
    const double s = 1 + pt.x.norm();
    EXPECT_NEAR(P.dot(X1), 0, 1e-13 * s);
    EXPECT_NEAR(Pu.dot(X1), 0, 1e-13 * s);
    EXPECT_NEAR(Pv.dot(X1), 0, 1e-13 * s);
    EXPECT_GT(pt.x.norm(), 5 * previous);
    previous = pt.x.norm();
  }
}

// Statuses of creation and evaluation; outputs untouched on error.
TEST(Seed004PnSurface, Statuses) {
  std::vector<Vec4d> net = polynomial_net([](double u, double v) { return Vec3d(u, v, u * v); }, 1, 1);
  PnSurface S;
  EXPECT_EQ(make_pn_surface(nullptr, 1, 1, S), Status::null_argument);
  EXPECT_EQ(make_pn_surface(net.data(), -1, 1, S), Status::invalid_argument);
  std::vector<Vec4d> big(100, Vec4d(1, 0, 0, 0));
  EXPECT_EQ(make_pn_surface(big.data(), kMaxPnDegree + 1, 0, S), Status::degree_too_high);
  std::vector<Vec4d> bad = net;
  bad[2][0] = 0;
  EXPECT_EQ(make_pn_surface(bad.data(), 1, 1, S), Status::invalid_argument);
  bad[2][0] = -1;
  EXPECT_EQ(make_pn_surface(bad.data(), 1, 1, S), Status::invalid_argument);
  bad = net;
  bad[1][3] = NAN;
  EXPECT_EQ(make_pn_surface(bad.data(), 1, 1, S), Status::not_finite);
  bad[1][3] = 2e100;
  EXPECT_EQ(make_pn_surface(bad.data(), 1, 1, S), Status::not_finite);
  bad = net;
  bad[1][0] = 1e-250;  // affine point 1e250
  bad[1][1] = 1e-0;
  EXPECT_EQ(make_pn_surface(bad.data(), 1, 1, S), Status::not_finite);
  EXPECT_EQ(S.degree_u, 0);  // untouched
  ASSERT_EQ(make_pn_surface(net.data(), 1, 1, S), Status::ok);
  PnPoint pt;
  EXPECT_EQ(pn_surface_eval(S, -0.1, 0.5, 0, pt), Status::bad_domain);
  EXPECT_EQ(pn_surface_eval(S, 0.5, 1.0000001, 0, pt), Status::bad_domain);
  EXPECT_EQ(pn_surface_eval(S, NAN, 0.5, 0, pt), Status::not_finite);
  EXPECT_EQ(pn_surface_eval(S, 0.5, 0.5, INFINITY, pt), Status::not_finite);
  EXPECT_EQ(pn_surface_eval(S, 0.5, 0.5, 1e101, pt), Status::not_finite);
  EXPECT_EQ(pt.x, Vec3d::Zero());
  EXPECT_EQ(pn_surface_eval(S, 0.5, 0.5, 0, pt), Status::ok);
}

// The grid: validation before writing, buffer_too_small with the needed
// count, per-point statuses, and the same bits as single evaluation.
TEST(Seed004PnSurface, GridEvaluation) {
  const auto y = [](double u, double v) { return Vec3d(u, v * v, v); };  // infinity at v = 0
  const PnSurface S = make(polynomial_net(y, 1, 2), 1, 2);
  const double us[3] = {0, 0.5, 1}, vs[2] = {0, 0.5};
  PnPoint out[6];
  Status st[6];
  std::size_t needed = 0, failed = 0;
  EXPECT_EQ(pn_surface_eval_grid(S, us, 3, vs, 2, 0.1, out, st, 5, &needed, &failed),
            Status::buffer_too_small);
  EXPECT_EQ(needed, 6u);
  const double bad_v[2] = {0.5, 2};
  EXPECT_EQ(pn_surface_eval_grid(S, us, 3, bad_v, 2, 0.1, out, st, 6, &needed, &failed),
            Status::bad_domain);
  EXPECT_EQ(out[0].x, Vec3d::Zero());
  ASSERT_EQ(pn_surface_eval_grid(S, us, 3, vs, 2, 0.1, out, st, 6, &needed, &failed), Status::ok);
  EXPECT_EQ(failed, 3u);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j) {
      PnPoint p;
      const Status s = pn_surface_eval(S, us[i], vs[j], 0.1, p);
      EXPECT_EQ(st[i * 2 + j], s);
      EXPECT_EQ(s, j == 0 ? Status::point_at_infinity : Status::ok);
      if (s == Status::ok) {
        EXPECT_EQ(out[i * 2 + j].x, p.x);
      }
    }
}

}  // namespace
