// Seed 004 §4.2 properties (labels "laguerre;property") over random
// well-conditioned point sets: jittered grids (cells of side 1, points
// within 0.3 of the cell centre, so separations >= 0.4; the outer points
// move only along the grid's outer lines) of 3x3 to 7x7 points, scaled by
// 2^-4..2^4, shifted by up to 100.
//
// Tolerances (relative):
//   constant         value   meaning
//   kAreaTol         1e-12   sum of triangle areas vs convex hull area (long double)
//   kCircleTol       1e-10   no point inside a circumcircle by more than this * r^2
//   kPrecisionTol    1e-11   quadratic data: value / gradient errors over (1 + |f|), (1 + |grad f|)
//   kValueGapTol     1e-12   value jump across shared edges over (1 + |z|)
//   kGradientGapTol  1e-9    gradient jump across shared edges over (1 + |grad z|)
//   kInterpTol       1e-10   value and gradient at the data points
//   kMinAngle        0.05    Powell-Sabin properties discard triangulations with a smaller angle (rad)
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "powell_sabin_checks.hpp"

using namespace cyclide;
using namespace ps_checks;

namespace {

constexpr double kAreaTol = 1e-12;
constexpr double kCircleTol = 1e-10;
constexpr double kPrecisionTol = 1e-11;
constexpr double kValueGapTol = 1e-12;
constexpr double kGradientGapTol = 1e-9;
constexpr double kInterpTol = 1e-10;
constexpr double kMinAngle = 0.05;  // radians, smallest macro-triangle angle accepted

int pick(int lo, int hi) { return *rc::gen::resize(100, rc::gen::inRange(lo, hi + 1)); }
double uniform(double lo, double hi) { return lo + (hi - lo) * pick(0, 1 << 20) / double(1 << 20); }

std::vector<Vec2d> jittered_grid() {
  const int nx = pick(3, 7);
  const int ny = pick(3, 7);
  const double scale = std::ldexp(1.0, pick(-4, 4));
  const double sx = uniform(-100, 100);
  const double sy = uniform(-100, 100);
  std::vector<Vec2d> pts;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      // Points on the grid's outer lines move only along them: a hull
      // point jittered just off a hull line would make a needle triangle
      // (an ill-conditioned input, not the property's subject).
      const double jx = (i == 0 || i == nx - 1) ? 0.0 : uniform(-0.3, 0.3);
      const double jy = (j == 0 || j == ny - 1) ? 0.0 : uniform(-0.3, 0.3);
      pts.emplace_back(sx + scale * (i + jx), sy + scale * (j + jy));
    }
  return pts;
}

Quadratic random_quadratic() {
  Quadratic f;
  f.c = uniform(-2, 2);
  const double lx = uniform(-2, 2);
  const double ly = uniform(-2, 2);
  f.l = Vec2d(lx, ly);
  f.qxx = uniform(-2, 2);
  f.qxy = uniform(-2, 2);
  f.qyy = uniform(-2, 2);
  return f;
}

// The orientation sign of lattice points 1 + k 2^-50 from their integer
// offsets (independent of the code's predicates).
int orient_exact_lattice(const Vec2d& a, const Vec2d& b, const Vec2d& c) {
  const auto k = [](double x) { return static_cast<long long>(std::ldexp(x - 1, 50)); };
  const long long d = (k(a.x()) - k(c.x())) * (k(b.y()) - k(c.y())) -
                      (k(a.y()) - k(c.y())) * (k(b.x()) - k(c.x()));
  return (d > 0) - (d < 0);
}

int incircle_exact_lattice(const Vec2d& a, const Vec2d& b, const Vec2d& c, const Vec2d& d) {
  const auto k = [](double x) { return static_cast<long long>(std::ldexp(x - 1, 50)); };
  const long long adx = k(a.x()) - k(d.x()), ady = k(a.y()) - k(d.y());
  const long long bdx = k(b.x()) - k(d.x()), bdy = k(b.y()) - k(d.y());
  const long long cdx = k(c.x()) - k(d.x()), cdy = k(c.y()) - k(d.y());
  const long long det = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
                        (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
                        (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
  return (det > 0) - (det < 0);
}

// Smallest angle (radians) of the triangles: the properties assume
// well-shaped macro triangles.
double min_angle(const std::vector<Vec2d>& pts, const std::vector<Tri>& tri) {
  double worst = 4;
  for (const Tri& t : tri)
    for (int k = 0; k < 3; ++k) {
      const Vec2d u = pts[t[(k + 1) % 3]] - pts[t[k]], w = pts[t[(k + 2) % 3]] - pts[t[k]];
      worst = std::min(worst, std::acos(std::clamp(u.dot(w) / (u.norm() * w.norm()), -1.0, 1.0)));
    }
  return worst;
}

}  // namespace

RC_GTEST_PROP(DelaunayProperties, ValidAndEmptyCircles, ()) {
  const auto pts = jittered_grid();
  std::vector<Tri> tri;
  RC_ASSERT(triangulate(pts, tri) == Status::ok);
  RC_ASSERT(check_triangulation(pts, tri, kAreaTol) == "");
  RC_ASSERT(check_empty_circles(pts, tri, kCircleTol) == "");
}

RC_GTEST_PROP(DelaunayProperties, ExactGridsWithTies, ()) {
  // Unjittered grids with random spacings: all cells cocircular.
  const int nx = pick(2, 12);
  const int ny = pick(2, 12);
  RC_PRE(nx * ny >= 3);
  const double hx = std::ldexp(1.0, pick(-6, 6)) * pick(1, 7);
  const double hy = std::ldexp(1.0, pick(-6, 6)) * pick(1, 7);
  std::vector<Vec2d> pts;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) pts.emplace_back(i * hx, j * hy);
  std::vector<Tri> tri;
  RC_ASSERT(triangulate(pts, tri) == Status::ok);
  RC_ASSERT(check_triangulation(pts, tri, kAreaTol) == "");
  RC_ASSERT(tri.size() == 2u * (nx - 1) * (ny - 1));
}

RC_GTEST_PROP(DelaunayProperties, RandomLatticeSubsetsWithTies, ()) {
  // Distinct points of a 7 x 7 lattice around 1.0 with spacing 2^-50 (a few
  // ulps): collinear and cocircular quadruples everywhere, every predicate
  // decided by the exact fallback. Collinear subsets must be reported.
  const int count = pick(3, 30);
  std::vector<Vec2d> pts;
  std::vector<int> used(49, 0);
  for (int k = 0; k < count; ++k) {
    const int c = pick(0, 48);
    if (used[c]) continue;
    used[c] = 1;
    pts.emplace_back(1 + std::ldexp(c % 7, -50), 1 + std::ldexp(c / 7, -50));
  }
  RC_PRE(pts.size() >= 3u);
  bool collinear = true;
  for (std::size_t i = 2; i < pts.size(); ++i)
    if (orient_exact_lattice(pts[0], pts[1], pts[i]) != 0) collinear = false;
  std::vector<Tri> tri;
  const Status s = triangulate(pts, tri);
  if (collinear) {
    RC_ASSERT(s == Status::collinear_points);
    return;
  }
  RC_ASSERT(s == Status::ok);
  RC_ASSERT(check_triangulation(pts, tri, kAreaTol) == "");
  // Empty circumcircles, decided exactly on the integer offsets.
  for (const Tri& t : tri)
    for (const Vec2d& d : pts) RC_ASSERT(incircle_exact_lattice(pts[t[0]], pts[t[1]], pts[t[2]], d) <= 0);
}

RC_GTEST_PROP(PowellSabinProperties, QuadraticPrecision, ()) {
  const auto pts = jittered_grid();
  std::vector<Tri> tri;
  RC_ASSERT(triangulate(pts, tri) == Status::ok);
  RC_PRE(min_angle(pts, tri) > kMinAngle);
  const Quadratic f = random_quadratic();
  std::vector<double> z;
  std::vector<Vec2d> g;
  for (const Vec2d& p : pts) {
    z.push_back(f.value(p));
    g.push_back(f.gradient(p));
  }
  std::vector<cyclide::QuadraticGraphTriangle> patches;
  RC_ASSERT(interpolate(pts, z, g, tri, patches) == Status::ok);
  for (const auto& m : patches) {
    const Vec2d p = (m.vertex[0] + 2 * m.vertex[1] + 3 * m.vertex[2]) / 6;
    double v;
    Vec2d grad;
    RC_ASSERT(quadratic_graph_eval(m, p, v, grad) == Status::ok);
    RC_ASSERT(std::fabs(v - f.value(p)) <= kPrecisionTol * (1 + std::fabs(f.value(p))));
    RC_ASSERT((grad - f.gradient(p)).norm() <= kPrecisionTol * (1 + f.gradient(p).norm()));
  }
}

RC_GTEST_PROP(PowellSabinProperties, InterpolatesAndIsC1, ()) {
  const auto pts = jittered_grid();
  std::vector<Tri> tri;
  RC_ASSERT(triangulate(pts, tri) == Status::ok);
  RC_PRE(min_angle(pts, tri) > kMinAngle);
  // Arbitrary data: random values and gradients at the points.
  std::vector<double> z;
  std::vector<Vec2d> g;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    z.push_back(uniform(-3, 3));
    const double gx = uniform(-3, 3);
    const double gy = uniform(-3, 3);
    g.emplace_back(gx, gy);
  }
  std::vector<cyclide::QuadraticGraphTriangle> patches;
  RC_ASSERT(interpolate(pts, z, g, tri, patches) == Status::ok);
  for (std::size_t t = 0; t < tri.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int i = tri[t][k];
      double v;
      Vec2d grad;
      RC_ASSERT(quadratic_graph_eval(patches[6 * t + 2 * k], pts[i], v, grad) == Status::ok);
      RC_ASSERT(std::fabs(v - z[i]) <= kInterpTol * (1 + std::fabs(z[i])));
      RC_ASSERT((grad - g[i]).norm() <= kInterpTol * (1 + g[i].norm()));
    }
  const Continuity c = continuity(patches);
  RC_ASSERT(c.max_value_gap <= kValueGapTol);
  RC_ASSERT(c.max_gradient_gap <= kGradientGapTol);
}
