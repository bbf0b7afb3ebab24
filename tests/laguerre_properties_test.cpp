// Seed 004 properties over random well-conditioned inputs (labels
// "property;laguerre"): the isotropic model Lambda (2.3) and its inverse,
// Lemma 2.1 / (2.4) both ways, translations (2.5) and dilatations (2.6)
// commuting with Lambda, the Blaschke cylinder (2.2), the exterior product,
// and PN surfaces Lambda^{-1}(Psi) (Theorem 3.2) of random rational
// Bezier surfaces Psi: unit rational normal, tangency, plane incidence,
// exact partials against central differences, offsets, and Laguerre maps
// applied to Psi ((2.5), (2.6)) giving the moved / offset surface.
//
// Tolerances (all relative, named below so SPEC can quote them):
//
//   constant          value  meaning
//   kRoundTripTol     1e-14  |Lambda^-1(Lambda(p)) - p| over (1 + |e0|) (unit planes);
//                            |Lambda(Lambda^-1(y)) - y| / (1 + |y|)
//   kContactTol       1e-13  |e0 + e.m + r| / (1 + |m| + |r|), (2.4) residual / (1 + |y|^2 (1 + |m| + |r|))
//   kMapTol           1e-13  (2.5), (2.6) commuting with Lambda, over (1 + |y|) (1 + |t| or |d|)
//   kExteriorTol      1e-14  |u . X| / (|u| |X|) and |X . w - det| / (|a| |b| |c| |w|)
//   kPnUnitTol        1e-14  ||n| - 1| and |n - rational formula|
//   kPnTangentTol     1e-10  |n . x_u| / |x_u| (and v)
//   kPnPlaneTol       1e-11  |e0 + n . x| / S, S = 1 + |x|; envelope conditions P.(1, x) / (|P| S)
//   kPnDiffTol        1e-6   central differences (h = 1e-5) vs exact x_u, x_v, over |x_u| + S
//   kPnOffsetTol      1e-11  offsets x + d n: distance, normal, plane, over S (1 + |d|)
//   kPnMapTol         1e-9   Lambda^{-1} of the translated / dilated Psi (bidegree doubled,
//                            rebuilt by interpolation) vs x + t / x + d n, over S (1 + |t|)
//
// Random Psi: bidegree (m, n) in 1..3 each, control points (y1, y2) on a
// jittered grid of [a0, a0 + A] x [b0, b0 + B] (A, B in [0.5, 2], jitter
// <= 0.15 of a cell), y3 in [-1, 1], weights in [0.5, 2]; a point is used
// only if the Jacobian of (y1, y2) there (central differences of an
// independent de Casteljau evaluation) has |det J| >= 0.2 |J_u| |J_v| and
// |x| <= 100 (far from the isotropic contour where Phi goes to infinity).

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <vector>

#include "cyclide/laguerre.hpp"
#include "cyclide/pn_surface.hpp"

using namespace cyclide;

namespace {

constexpr double kRoundTripTol = 1e-14;
constexpr double kContactTol = 1e-13;
constexpr double kMapTol = 1e-13;
constexpr double kExteriorTol = 1e-14;
constexpr double kPnUnitTol = 1e-14;
constexpr double kPnTangentTol = 1e-10;
constexpr double kPnPlaneTol = 1e-11;
constexpr double kPnDiffTol = 1e-6;
constexpr double kPnOffsetTol = 1e-11;
constexpr double kPnMapTol = 1e-9;

// Uniform on [lo, hi] at every size (inRange alone scales with RapidCheck's size).
double real(double lo, double hi) {
  const int k = *rc::gen::resize(100, rc::gen::inRange(0, (1 << 20) + 1));
  return lo + (hi - lo) * (k / double(1 << 20));
}
int pick(int lo, int hi) { return *rc::gen::resize(100, rc::gen::inRange(lo, hi + 1)); }

Vec3d random_vec(double r) {
  const double a = real(-r, r);
  const double b = real(-r, r);
  const double c = real(-r, r);
  return Vec3d(a, b, c);
}

Vec3d random_unit() {
  const Vec3d v = random_vec(1);
  RC_PRE(v.norm() > 0.25);
  return v.normalized();
}

OrientedPlane random_plane() {
  OrientedPlane p;
  p.e = random_unit();
  p.e0 = real(-10, 10);
  return p;
}

IsotropicPoint lambda(const OrientedPlane& p) {
  IsotropicPoint y;
  RC_ASSERT(laguerre_to_isotropic(p, y) == Status::ok);
  return y;
}

OrientedPlane lambda_inverse(const IsotropicPoint& y) {
  OrientedPlane p;
  RC_ASSERT(isotropic_to_laguerre(y, p) == Status::ok);
  return p;
}

IsotropicPoint finite_point(const Vec3d& y) {
  IsotropicPoint p;
  p.y = y;
  return p;
}

double paraboloid_24(const Cycle& z, const Vec3d& y) {
  const double q = y[0] * y[0] + y[1] * y[1];
  return 2 * y[2] + q * (z.r + z.m[2]) + 2 * y[0] * z.m[0] + 2 * y[1] * z.m[1] + z.r - z.m[2];
}

// ------------------------------------------------------------- §2 properties

RC_GTEST_PROP(LaguerreProperties, LambdaInverseOfLambdaIsIdentity, ()) {
  const OrientedPlane p = random_plane();
  const IsotropicPoint y = lambda(p);
  const OrientedPlane back = lambda_inverse(y);
  RC_ASSERT((back.e - p.e).norm() <= kRoundTripTol * 4);
  RC_ASSERT(std::abs(back.e0 - p.e0) <= kRoundTripTol * 4 * (1 + std::abs(p.e0)));
}

RC_GTEST_PROP(LaguerreProperties, LambdaOfLambdaInverseIsIdentity, ()) {
  const Vec3d y = random_vec(20);
  const IsotropicPoint z = lambda(lambda_inverse(finite_point(y)));
  RC_ASSERT(!z.exceptional);
  RC_ASSERT((z.y - y).norm() <= kRoundTripTol * 8 * (1 + y.norm()));
  // Exceptional points: c <-> the plane (c, 0, 0, 1).
  IsotropicPoint c;
  c.exceptional = true;
  c.c = y[2];
  const OrientedPlane pc = lambda_inverse(c);
  RC_ASSERT(pc.e == Vec3d(0, 0, 1) && pc.e0 == y[2]);
  const IsotropicPoint cb = lambda(pc);
  RC_ASSERT(cb.exceptional && cb.c == y[2]);
}

// (2.3) near W: normals within 1e-8 of W keep their digits (the exact image
// is (a, b, e0) (s + 1) / delta^2 for the plane (e0, (a, b, 1)), s = |(a, b, 1)|).
RC_GTEST_PROP(LaguerreProperties, LambdaNearWIsAccurate, ()) {
  const double delta = std::pow(10.0, real(-15, -8));
  const double theta = real(-M_PI, M_PI);
  const double e0 = real(-10, 10);
  const double a = delta * std::cos(theta), b = delta * std::sin(theta);
  const double d2 = a * a + b * b, s = std::sqrt(1 + d2);
  const Vec3d expect = Vec3d(a, b, e0) * ((s + 1) / d2);
  const IsotropicPoint y = lambda(OrientedPlane{e0, Vec3d(a, b, 1)});
  RC_ASSERT(!y.exceptional);
  RC_ASSERT((y.y - expect).norm() <= kRoundTripTol * 8 * expect.norm());
}

// Lemma 2.1: tangent planes of a cycle land on its paraboloid (2.4), and
// points of the paraboloid are planes in oriented contact with it.
RC_GTEST_PROP(LaguerreProperties, Lemma21TangentPlanesAreParaboloidPoints, ()) {
  Cycle z;
  z.m = random_vec(5);
  z.r = real(-3, 3);
  const double scale = 1 + z.m.norm() + std::abs(z.r);
  OrientedPlane p;
  p.e = random_unit();
  p.e0 = -p.e.dot(z.m) - z.r;
  const IsotropicPoint y = lambda(p);
  RC_ASSERT(!y.exceptional);
  RC_ASSERT(std::abs(paraboloid_24(z, y.y)) <= kContactTol * 8 * (1 + y.y.squaredNorm()) * scale);
  RC_ASSERT(on_paraboloid(cycle_to_paraboloid(z), y, 1e-12));
  // Conversely a point of (2.4): y3 = -(q k + 2 l.y + c0) / 2.
  const double y1 = real(-5, 5);
  const double y2 = real(-5, 5);
  const double q = y1 * y1 + y2 * y2;
  const Vec3d w(y1, y2, -(q * (z.r + z.m[2]) + 2 * (z.m[0] * y1 + z.m[1] * y2) + z.r - z.m[2]) / 2);
  const OrientedPlane t = lambda_inverse(finite_point(w));
  RC_ASSERT(std::abs(t.e0 + t.e.dot(z.m) + z.r) <= kContactTol * 8 * scale);
  RC_ASSERT(in_oriented_contact(z, t, 1e-12));
}

// (2.5) and (2.6) commute with Lambda; the dilated plane touches (m, r + d)
// at the old contact point + d e.
RC_GTEST_PROP(LaguerreProperties, TranslationAndDilatationCommuteWithLambda, ()) {
  const OrientedPlane p = random_plane();
  const Vec3d t = random_vec(5);
  const double d = real(-3, 3);
  const IsotropicPoint y = lambda(p);
  const double sy = 1 + y.y.norm();
  const IsotropicPoint a = lambda(translate(p, t)), b = isotropic_translate(y, t);
  RC_ASSERT((a.y - b.y).norm() <= kMapTol * 10 * sy * sy * (1 + t.norm()));
  const IsotropicPoint c = lambda(dilatation(p, d)), e = isotropic_dilatation(y, d);
  RC_ASSERT((c.y - e.y).norm() <= kMapTol * 10 * sy * sy * (1 + std::abs(d)));
  // Contact with (m, r) where m is any point and r chosen to touch.
  const Vec3d m = random_vec(5);
  const Cycle z{m, -p.e0 - p.e.dot(m)};
  const OrientedPlane q = dilatation(p, d);
  const Cycle zd{m, z.r + d};
  RC_ASSERT(in_oriented_contact(zd, q, 1e-13));
  RC_ASSERT((contact_point(zd, q) - (contact_point(z, p) + d * p.e)).norm() <=
            1e-14 * (1 + m.norm() + std::abs(zd.r)));
  // The translated plane contains x + t for the foot point x = -e0 e.
  const OrientedPlane tp = translate(p, t);
  const Vec3d x = -p.e0 * p.e;
  RC_ASSERT(std::abs(tp.e0 + tp.e.dot(x + t)) <= 1e-14 * (1 + x.norm() + t.norm()));
}

// (2.2): Blaschke points lie on Delta; (2.3) is their projection from W.
RC_GTEST_PROP(LaguerreProperties, BlaschkePointsOnCylinderProjectToLambda, ()) {
  const OrientedPlane p = random_plane();
  const auto B = blaschke_point(p);
  RC_ASSERT(std::abs(B[1] * B[1] + B[2] * B[2] + B[3] * B[3] - 1) <= 1e-15);
  RC_PRE(B[3] < 0.9);  // the projection below is the naive one
  const double t = 1 / (1 - B[3]);
  const Vec3d s(t * B[1], t * B[2], t * B[4]);
  const IsotropicPoint y = lambda(p);
  RC_ASSERT((y.y - s).norm() <= kRoundTripTol * 40 * (1 + s.norm()));
}

RC_GTEST_PROP(LaguerreProperties, ExteriorProductIsOrthogonalAndZeroForDependent, ()) {
  auto v4 = [] {
    const Vec3d a = random_vec(3);
    const double b = real(-3, 3);
    return Vec4d(b, a[0], a[1], a[2]);
  };
  const Vec4d a = v4(), b = v4(), c = v4(), w = v4();
  const Vec4d X = exterior_product(a, b, c);
  for (const Vec4d* u : {&a, &b, &c})
    RC_ASSERT(std::abs(u->dot(X)) <= kExteriorTol * 8 * u->norm() * a.norm() * b.norm() * c.norm());
  Eigen::Matrix4d M;
  M << a.transpose(), b.transpose(), c.transpose(), w.transpose();
  RC_ASSERT(std::abs(X.dot(w) - M.determinant()) <=
            kExteriorTol * 16 * a.norm() * b.norm() * c.norm() * w.norm());
  const double s = real(-2, 2);
  const double r = real(-2, 2);
  const Vec4d dep = s * a + r * b;
  RC_ASSERT(exterior_product(a, b, dep).norm() <=
            kExteriorTol * 16 * a.norm() * b.norm() * (std::abs(s) * a.norm() + std::abs(r) * b.norm()));
}

// --------------------------------------------------------- PN surfaces (§3)

double binom(int n, int k) {
  double b = 1;
  for (int i = 1; i <= k; ++i) b = b * (n - k + i) / i;
  return b;
}

double bern(int n, int i, double t) { return binom(n, i) * std::pow(t, i) * std::pow(1 - t, n - i); }

// Independent evaluation of the homogeneous tensor-product surface
// (de Casteljau in v for every row, then in u).
Vec4d de_casteljau(const std::vector<Vec4d>& net, int m, int n, double u, double v) {
  std::vector<Vec4d> rows(m + 1);
  for (int i = 0; i <= m; ++i) {
    std::vector<Vec4d> c(net.begin() + i * (n + 1), net.begin() + (i + 1) * (n + 1));
    for (int k = 1; k <= n; ++k)
      for (int j = 0; j <= n - k; ++j) c[j] = (1 - v) * c[j] + v * c[j + 1];
    rows[i] = c[0];
  }
  for (int k = 1; k <= m; ++k)
    for (int i = 0; i <= m - k; ++i) rows[i] = (1 - u) * rows[i] + u * rows[i + 1];
  return rows[0];
}

Vec3d affine(const Vec4d& h) { return h.tail<3>() / h[0]; }

// Control net of bidegree (m, n) interpolating a homogeneous polynomial map
// at the grid (i/m, j/n) (exact for maps of bidegree <= (m, n)).
std::vector<Vec4d> bezier_from_map(const std::function<Vec4d(double, double)>& f, int m, int n) {
  Eigen::MatrixXd Mu(m + 1, m + 1), Mv(n + 1, n + 1);
  for (int a = 0; a <= m; ++a)
    for (int i = 0; i <= m; ++i) Mu(a, i) = bern(m, i, double(a) / m);
  for (int b = 0; b <= n; ++b)
    for (int j = 0; j <= n; ++j) Mv(b, j) = bern(n, j, double(b) / n);
  std::vector<Vec4d> net((m + 1) * (n + 1));
  std::vector<Vec4d> samples((m + 1) * (n + 1));
  for (int a = 0; a <= m; ++a)
    for (int b = 0; b <= n; ++b) samples[a * (n + 1) + b] = f(double(a) / m, double(b) / n);
  for (int c = 0; c < 4; ++c) {
    Eigen::MatrixXd F(m + 1, n + 1);
    for (int a = 0; a <= m; ++a)
      for (int b = 0; b <= n; ++b) F(a, b) = samples[a * (n + 1) + b][c];
    const Eigen::MatrixXd C1 = Mu.fullPivLu().solve(F);
    const Eigen::MatrixXd C = Mv.fullPivLu().solve(C1.transpose()).transpose();
    for (int i = 0; i <= m; ++i)
      for (int j = 0; j <= n; ++j) net[i * (n + 1) + j][c] = C(i, j);
  }
  return net;
}

struct RandomPsi {
  int m = 1, n = 1;
  std::vector<Vec4d> net;
};

RandomPsi random_psi() {
  RandomPsi R;
  R.m = pick(1, 3);
  R.n = pick(1, 3);
  const double a0 = real(-2, 2);
  const double b0 = real(-2, 2);
  const double A = real(0.5, 2);
  const double B = real(0.5, 2);
  for (int i = 0; i <= R.m; ++i)
    for (int j = 0; j <= R.n; ++j) {
      const double j1 = real(-0.15, 0.15);
      const double j2 = real(-0.15, 0.15);
      const double y3 = real(-1, 1);
      const double w = real(0.5, 2);
      const double y1 = a0 + A * (i + j1) / R.m, y2 = b0 + B * (j + j2) / R.n;
      R.net.emplace_back(w, w * y1, w * y2, w * y3);
    }
  return R;
}

PnSurface make(const std::vector<Vec4d>& net, int m, int n) {
  PnSurface S;
  RC_ASSERT(make_pn_surface(net.data(), m, n, S) == Status::ok);
  return S;
}

// Whether (u, v) is well conditioned: the (y1, y2) Jacobian (central
// differences of the independent evaluation) is far from singular.
bool well_conditioned(const RandomPsi& R, double u, double v) {
  const double h = 1e-6;
  auto y = [&](double s, double t) { return affine(de_casteljau(R.net, R.m, R.n, s, t)); };
  const double u0 = std::max(u - h, 0.0), u1 = std::min(u + h, 1.0);
  const double v0 = std::max(v - h, 0.0), v1 = std::min(v + h, 1.0);
  const Vec3d yu = (y(u1, v) - y(u0, v)) / (u1 - u0), yv = (y(u, v1) - y(u, v0)) / (v1 - v0);
  const double det = yu[0] * yv[1] - yu[1] * yv[0];
  return std::abs(det) >= 0.2 * yu.head<2>().norm() * yv.head<2>().norm();
}

struct Sample {
  double u, v;
};

Sample random_sample(const RandomPsi& R) {
  const double u = real(0.02, 0.98);
  const double v = real(0.02, 0.98);
  RC_PRE(well_conditioned(R, u, v));
  return {u, v};
}

PnPoint eval_ok(const PnSurface& S, double u, double v, double d) {
  PnPoint p;
  const Status st = pn_surface_eval(S, u, v, d, p);
  RC_ASSERT(st == Status::ok);
  return p;
}

// n is unit and equals (2 y1, 2 y2, y1^2 + y2^2 - 1) / N at the
// independently evaluated y; n is normal to x_u, x_v; x lies on its plane
// and satisfies the envelope conditions with P's partials by differences.
RC_GTEST_PROP(LaguerreProperties, PnSurfaceNormalTangencyAndPlane, ()) {
  const RandomPsi R = random_psi();
  const PnSurface S = make(R.net, R.m, R.n);
  const Sample s = random_sample(R);
  const PnPoint p = eval_ok(S, s.u, s.v, 0);
  RC_PRE(p.x.norm() <= 100);
  const Vec3d y = affine(de_casteljau(R.net, R.m, R.n, s.u, s.v));
  RC_ASSERT((p.y - y).norm() <= 1e-14 * (1 + y.norm()) * 8);
  const double N = 1 + y[0] * y[0] + y[1] * y[1];
  const Vec3d n(2 * y[0] / N, 2 * y[1] / N, (y[0] * y[0] + y[1] * y[1] - 1) / N);
  RC_ASSERT(std::abs(p.n.norm() - 1) <= kPnUnitTol * 4);
  RC_ASSERT((p.n - n).norm() <= kPnUnitTol * 8);
  RC_ASSERT(std::abs(p.n.dot(p.x_u)) <= kPnTangentTol * p.x_u.norm());
  RC_ASSERT(std::abs(p.n.dot(p.x_v)) <= kPnTangentTol * p.x_v.norm());
  const double S0 = 1 + p.x.norm();
  RC_ASSERT(std::abs(p.plane.e0 + p.plane.e.dot(p.x)) <= kPnPlaneTol * S0);
  RC_ASSERT((p.plane.e - p.n).norm() == 0);
  RC_ASSERT(std::abs(p.plane.e0 - 2 * y[2] / N) <= 1e-14 * 8 * (1 + std::abs(y[2])));
}

// The exact partials x_u, x_v (and n_u, n_v) match central differences.
RC_GTEST_PROP(LaguerreProperties, PnSurfacePartialsMatchDifferences, ()) {
  const RandomPsi R = random_psi();
  const PnSurface S = make(R.net, R.m, R.n);
  const Sample s = random_sample(R);
  const double d = real(-2, 2);
  const PnPoint p = eval_ok(S, s.u, s.v, d);
  RC_PRE(p.x.norm() <= 100);
  const double h = 1e-5;
  const PnPoint pu0 = eval_ok(S, s.u - h, s.v, d), pu1 = eval_ok(S, s.u + h, s.v, d);
  const PnPoint pv0 = eval_ok(S, s.u, s.v - h, d), pv1 = eval_ok(S, s.u, s.v + h, d);
  const double S0 = 1 + p.x.norm();
  const Vec3d du = (pu1.x - pu0.x) / (2 * h), dv = (pv1.x - pv0.x) / (2 * h);
  RC_ASSERT((du - p.x_u).norm() <= kPnDiffTol * (p.x_u.norm() + S0));
  RC_ASSERT((dv - p.x_v).norm() <= kPnDiffTol * (p.x_v.norm() + S0));
  const Vec3d nu = (pu1.n - pu0.n) / (2 * h), nv = (pv1.n - pv0.n) / (2 * h);
  RC_ASSERT((nu - p.n_u).norm() <= kPnDiffTol * (p.n_u.norm() + 1));
  RC_ASSERT((nv - p.n_v).norm() <= kPnDiffTol * (p.n_v.norm() + 1));
}

// Offsets: x_d lies at distance |d| from x along n, with the same normal,
// on the dilated plane e0 - d; its partials are x_u + d n_u.
RC_GTEST_PROP(LaguerreProperties, PnSurfaceOffsets, ()) {
  const RandomPsi R = random_psi();
  const PnSurface S = make(R.net, R.m, R.n);
  const Sample s = random_sample(R);
  const double d = real(-3, 3);
  const PnPoint p = eval_ok(S, s.u, s.v, 0), q = eval_ok(S, s.u, s.v, d);
  RC_PRE(p.x.norm() <= 100);
  const double S0 = (1 + p.x.norm()) * (1 + std::abs(d));
  RC_ASSERT(std::abs((q.x - p.x).norm() - std::abs(d)) <= kPnOffsetTol * S0);
  RC_ASSERT((q.x - p.x - d * p.n).norm() <= kPnOffsetTol * S0);
  RC_ASSERT((q.n - p.n).norm() == 0);
  RC_ASSERT(std::abs(q.plane.e0 - (p.plane.e0 - d)) <= kPnOffsetTol * S0);
  RC_ASSERT(std::abs(q.plane.e0 + q.plane.e.dot(q.x)) <= kPnOffsetTol * S0);
  RC_ASSERT(std::abs(q.n.dot(q.x_u)) <= kPnTangentTol * (q.x_u.norm() + p.x_u.norm()));
}

// Laguerre maps applied to Psi: the translated Psi (2.5) gives Phi + t and
// the dilated Psi (2.6) gives the offset x + d n. Both images are rational
// of bidegree (2m, 2n), with weight W^2:
//   (W^2, W Y1, W Y2, W Y3 - t1 W Y1 - t2 W Y2 - (t3/2)(Y1^2 + Y2^2 - W^2)),
//   (W^2, W Y1, W Y2, W Y3 - (d/2)(W^2 + Y1^2 + Y2^2)),
// rebuilt here by interpolation from the independent evaluation.
RC_GTEST_PROP(LaguerreProperties, PnSurfaceLaguerreMapsOfPsi, ()) {
  const RandomPsi R = random_psi();
  const PnSurface S = make(R.net, R.m, R.n);
  const Sample s = random_sample(R);
  const Vec3d t = random_vec(3);
  const double d = real(-3, 3);
  const PnPoint p = eval_ok(S, s.u, s.v, 0);
  RC_PRE(p.x.norm() <= 100);
  const auto translated = bezier_from_map(
      [&](double u, double v) {
        const Vec4d H = de_casteljau(R.net, R.m, R.n, u, v);
        const double W = H[0], Y1 = H[1], Y2 = H[2], Y3 = H[3];
        return Vec4d(W * W, W * Y1, W * Y2,
                     W * Y3 - t[0] * W * Y1 - t[1] * W * Y2 -
                         t[2] / 2 * (Y1 * Y1 + Y2 * Y2 - W * W));
      },
      2 * R.m, 2 * R.n);
  const auto dilated = bezier_from_map(
      [&](double u, double v) {
        const Vec4d H = de_casteljau(R.net, R.m, R.n, u, v);
        const double W = H[0], Y1 = H[1], Y2 = H[2], Y3 = H[3];
        return Vec4d(W * W, W * Y1, W * Y2, W * Y3 - d / 2 * (W * W + Y1 * Y1 + Y2 * Y2));
      },
      2 * R.m, 2 * R.n);
  const PnPoint pt = eval_ok(make(translated, 2 * R.m, 2 * R.n), s.u, s.v, 0);
  const PnPoint pd = eval_ok(make(dilated, 2 * R.m, 2 * R.n), s.u, s.v, 0);
  const double S0 = 1 + p.x.norm();
  RC_ASSERT((pt.x - (p.x + t)).norm() <= kPnMapTol * S0 * (1 + t.norm()));
  RC_ASSERT((pt.n - p.n).norm() <= kPnMapTol);
  RC_ASSERT((pt.x_u - p.x_u).norm() <= kPnMapTol * 100 * (S0 + p.x_u.norm()));
  RC_ASSERT((pd.x - (p.x + d * p.n)).norm() <= kPnMapTol * S0 * (1 + std::abs(d)));
  RC_ASSERT((pd.n - p.n).norm() <= kPnMapTol);
  RC_ASSERT((pd.x_v - (p.x_v + d * p.n_v)).norm() <= kPnMapTol * 100 * (S0 + p.x_v.norm()) * (1 + std::abs(d)));
}

// The grid evaluation writes exactly the single evaluations.
RC_GTEST_PROP(LaguerreProperties, PnGridEqualsSingleEvaluations, ()) {
  const RandomPsi R = random_psi();
  const PnSurface S = make(R.net, R.m, R.n);
  const double us[3] = {0, real(0, 1), 1};
  const double vs[2] = {real(0, 1), 0.5};
  const double d = real(-2, 2);
  PnPoint out[6];
  Status st[6];
  std::size_t needed = 0, failed = 0;
  RC_ASSERT(pn_surface_eval_grid(S, us, 3, vs, 2, d, out, st, 6, &needed, &failed) == Status::ok);
  std::size_t bad = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j) {
      PnPoint p;
      const Status s = pn_surface_eval(S, us[i], vs[j], d, p);
      RC_ASSERT(st[i * 2 + j] == s);
      if (s == Status::ok) {
        RC_ASSERT(out[i * 2 + j].x == p.x && out[i * 2 + j].x_u == p.x_u && out[i * 2 + j].n == p.n);
      } else {
        ++bad;
      }
    }
  RC_ASSERT(bad == failed);
}

}  // namespace
