// Seed 004 §4.2 (labels "laguerre;paper"): the triangulation of the
// projected data points b_i and their Powell-Sabin interpolation. Worked
// statements: quadratic precision ("translational invariance is achieved by
// the quadratic precision of Powell-Sabin interpolants", with (2.5)),
// invariance under offsetting ((2.6) adds the quadratic -(d/2)(1 + y1^2 +
// y2^2)), interpolation of (B_i, beta_i), C^1 (the G^1 of Fig. 2 in the
// isotropic model). Plus the Delaunay triangulation's contract: exact
// predicates (checked against 128-bit integer determinants), validity on
// cocircular input, degenerate inputs and their statuses, and speed.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <vector>

#include "powell_sabin_checks.hpp"

using namespace cyclide;
using namespace ps_checks;

namespace {

static_assert(sizeof(Tri) == 3 * sizeof(int), "Tri is an int[3]");

__extension__ typedef __int128 i128;

int sign128(i128 x) { return (x > 0) - (x < 0); }

// Exact determinants over integers (independent of the expansion arithmetic).
int orient_int(long long ax, long long ay, long long bx, long long by, long long cx, long long cy) {
  return sign128(i128(ax - cx) * (by - cy) - i128(ay - cy) * (bx - cx));
}
int incircle_int(const long long p[4][2]) {
  i128 dx[3], dy[3], lift[3];
  for (int i = 0; i < 3; ++i) {
    dx[i] = p[i][0] - p[3][0];
    dy[i] = p[i][1] - p[3][1];
    lift[i] = dx[i] * dx[i] + dy[i] * dy[i];
  }
  return sign128(lift[0] * (dx[1] * dy[2] - dx[2] * dy[1]) + lift[1] * (dx[2] * dy[0] - dx[0] * dy[2]) +
                 lift[2] * (dx[0] * dy[1] - dx[1] * dy[0]));
}

Vec2d P(long long x, long long y) { return Vec2d(double(x), double(y)); }

std::vector<Vec2d> random_points(int n, unsigned seed, double min_sep = 0) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec2d> p;
  while (static_cast<int>(p.size()) < n) {
    const Vec2d q(u(rng), u(rng));
    bool far = true;
    for (const Vec2d& r : p)
      if ((r - q).norm() < min_sep) far = false;
    if (far) p.push_back(q);
  }
  return p;
}

std::vector<Tri> delaunay(const std::vector<Vec2d>& pts) {
  std::vector<Tri> tri;
  EXPECT_EQ(triangulate(pts, tri), Status::ok);
  return tri;
}

}  // namespace

// ------------------------------------------------------------------ predicates

TEST(DelaunayPredicates, OrientationExactNearCollinear) {
  // Points within a few units of a long line through integers up to 2^40:
  // the floating-point determinant is swamped by rounding, the sign is not.
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<long long> big(-(1LL << 40), 1LL << 40);
  std::uniform_int_distribution<long long> tiny(-2, 2);
  int nonzero = 0, zero = 0;
  for (int i = 0; i < 2000; ++i) {
    const long long ax = big(rng), ay = big(rng), dx = big(rng) / 1024, dy = big(rng) / 1024;
    const long long bx = ax + dx, by = ay + dy;
    const long long cx = ax + 2 * dx + tiny(rng), cy = ay + 2 * dy + tiny(rng);
    const int expect = orient_int(ax, ay, bx, by, cx, cy);
    EXPECT_EQ(orient2d_sign(P(ax, ay), P(bx, by), P(cx, cy)), expect);
    (expect == 0 ? zero : nonzero)++;
  }
  EXPECT_GT(zero, 50);
  EXPECT_GT(nonzero, 50);
}

TEST(DelaunayPredicates, OrientationExactForNonIntegers) {
  // The classic: c near the line through (12, 12), (24, 24) on a grid of ulps
  // of 0.5; scaled by 2^53 all coordinates are integers below 2^58.
  const double ulp = std::ldexp(1.0, -53);
  for (int i = 0; i < 32; ++i)
    for (int j = 0; j < 32; ++j) {
      const Vec2d c(0.5 + i * ulp, 0.5 + j * ulp);
      const long long s = 1LL << 53;
      const int expect = orient_int(static_cast<long long>(c.x() * s), static_cast<long long>(c.y() * s),
                                    12 * s, 12 * s, 24 * s, 24 * s);
      EXPECT_EQ(orient2d_sign(c, Vec2d(12, 12), Vec2d(24, 24)), expect) << i << " " << j;
    }
}

TEST(DelaunayPredicates, IncircleExactOnLatticeCircles) {
  // x^2 + y^2 = 1105^2 has 4 * 3^3 = 108 lattice points (1105 = 5 * 13 * 17); scaled
  // by 2^12 they stay exact. A fourth point on the circle gives 0, one unit
  // off the circle gives the sign of the integer determinant.
  std::vector<std::array<long long, 2>> circle;
  const long long r = 1105;
  for (long long x = -r; x <= r; ++x) {
    const long long y2 = r * r - x * x;
    const long long y = static_cast<long long>(std::llround(std::sqrt(double(y2))));
    if (y * y == y2) {
      circle.push_back({x, y});
      if (y != 0) circle.push_back({x, -y});
    }
  }
  ASSERT_EQ(circle.size(), 108u);
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<std::size_t> pick(0, circle.size() - 1);
  std::uniform_int_distribution<int> nudge(-1, 1);
  const long long s = 1LL << 12;
  int zero = 0;
  for (int it = 0; it < 3000; ++it) {
    long long p[4][2];
    for (int i = 0; i < 4; ++i) {
      const auto& c = circle[pick(rng)];
      p[i][0] = c[0] * s;
      p[i][1] = c[1] * s;
    }
    p[3][0] += nudge(rng);
    p[3][1] += nudge(rng);
    const int o = orient_int(p[0][0], p[0][1], p[1][0], p[1][1], p[2][0], p[2][1]);
    if (o == 0) continue;
    if (o < 0) std::swap(p[0], p[1]);
    const int expect = incircle_int(p);
    zero += expect == 0;
    EXPECT_EQ(incircle_sign(P(p[0][0], p[0][1]), P(p[1][0], p[1][1]), P(p[2][0], p[2][1]),
                            P(p[3][0], p[3][1])),
              expect);
  }
  EXPECT_GT(zero, 100);
}

// ------------------------------------------------------------------ Delaunay

TEST(Delaunay, SquareGivesTwoTriangles) {
  const std::vector<Vec2d> pts = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const auto tri = delaunay(pts);
  EXPECT_EQ(tri.size(), 2u);
  EXPECT_EQ(check_triangulation(pts, tri), "");
}

TEST(Delaunay, CocircularGridIsValid) {
  // A 30 x 30 integer grid: every unit square is four cocircular points.
  std::vector<Vec2d> pts;
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 30; ++j) pts.emplace_back(i, j);
  const auto tri = delaunay(pts);
  EXPECT_EQ(check_triangulation(pts, tri), "");
  EXPECT_EQ(check_empty_circles(pts, tri, 1e-12), "");
  EXPECT_EQ(tri.size(), 2u * 29 * 29);
}

TEST(Delaunay, DecimalGridTiesAreFast) {
  // Spacing 0.1 shifted by 1/3: coordinates and their differences are
  // rounded, every cell needs the exact incircle fallback.
  std::vector<Vec2d> pts;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) pts.emplace_back(1.0 / 3 + 0.1 * i, 7.0 / 3 + 0.1 * j);
  const auto t0 = std::chrono::steady_clock::now();
  const auto tri = delaunay(pts);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_LT(ms, 100.0);
  EXPECT_EQ(check_triangulation(pts, tri), "");
  EXPECT_EQ(check_empty_circles(pts, tri, 1e-10), "");
}

TEST(Delaunay, LatticeCircleAllCocircular) {
  // The 108 lattice points of x^2 + y^2 = 1105^2 plus the centre: every
  // incircle test among circle points is a tie.
  std::vector<Vec2d> pts = {{0, 0}};
  const long long r = 1105;
  for (long long x = -r; x <= r; ++x) {
    const long long y2 = r * r - x * x;
    const long long y = static_cast<long long>(std::llround(std::sqrt(double(y2))));
    if (y * y == y2) {
      pts.emplace_back(double(x), double(y));
      if (y != 0) pts.emplace_back(double(x), double(-y));
    }
  }
  const auto tri = delaunay(pts);
  EXPECT_EQ(check_triangulation(pts, tri), "");
  EXPECT_EQ(check_empty_circles(pts, tri, 1e-12), "");
  EXPECT_EQ(tri.size(), 108u);  // a fan around the centre
}

TEST(Delaunay, CollinearPointsOnTheHull) {
  // Many points on the hull edges and one interior point.
  std::vector<Vec2d> pts;
  for (int i = 0; i <= 10; ++i) {
    pts.emplace_back(i, 0);
    pts.emplace_back(i, 10);
    if (i > 0 && i < 10) {
      pts.emplace_back(0, i);
      pts.emplace_back(10, i);
    }
  }
  pts.emplace_back(3.3, 4.7);
  const auto tri = delaunay(pts);
  EXPECT_EQ(check_triangulation(pts, tri), "");
  EXPECT_EQ(check_empty_circles(pts, tri, 1e-12), "");
}

TEST(Delaunay, ThousandRandomPointsInMilliseconds) {
  const auto pts = random_points(1000, 42);
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<Tri> tri;
  ASSERT_EQ(triangulate(pts, tri), Status::ok);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_LT(ms, 50.0);
  EXPECT_EQ(check_triangulation(pts, tri), "");
  EXPECT_EQ(check_empty_circles(pts, tri, 1e-12), "");
}

TEST(Delaunay, HundredThousandPointsScale) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1000);
  std::vector<Vec2d> pts(100000);
  for (auto& p : pts) p = Vec2d(u(rng), u(rng));
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<Tri> tri;
  ASSERT_EQ(triangulate(pts, tri), Status::ok);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_LT(ms, 1000.0);
  EXPECT_EQ(check_triangulation(pts, tri, 1e-9), "");
}

TEST(Delaunay, HugeAndTinyCoordinatesAreScaledExactly) {
  // |x| up to 1e100 is valid input; the predicates see exactly scaled points.
  for (const double scale : {1e99, 1e-100}) {
    std::vector<Vec2d> pts;
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j) pts.emplace_back(i * scale, j * scale);
    std::vector<Tri> tri;
    ASSERT_EQ(triangulate(pts, tri), Status::ok) << scale;
    EXPECT_EQ(check_triangulation(pts, tri), "") << scale;
  }
}

TEST(Delaunay, DegenerateInputsAndTheirStatuses) {
  std::vector<Tri> tri;
  DelaunayReport rep;
  EXPECT_EQ(triangulate({{0, 0}, {1, 0}}, tri), Status::invalid_argument);  // n < 3
  EXPECT_EQ(triangulate({{0, 0}, {1, 1}, {2, 2}, {-3, -3}}, tri), Status::collinear_points);
  EXPECT_EQ(triangulate({{0, 0}, {1, 0}, {0, 1}, {5, 5}, {1, 0}}, tri, &rep), Status::invalid_argument);
  EXPECT_EQ(rep.first, 1);
  EXPECT_EQ(rep.second, 4);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(triangulate({{0, 0}, {1, 0}, {0, nan}}, tri, &rep), Status::not_finite);
  EXPECT_EQ(rep.first, 2);
  EXPECT_EQ(triangulate({{0, 0}, {1e101, 0}, {0, 1}}, tri, &rep), Status::not_finite);
  EXPECT_EQ(rep.first, 1);
  EXPECT_EQ(triangulate({{0, 0}, {std::numeric_limits<double>::infinity(), 0}, {0, 1}}, tri),
            Status::not_finite);
  // A dynamic range the exact predicates cannot take (their degree-4 terms
  // would underflow): refused, not triangulated wrongly. The fuzz finding
  // (regress-delaunay-underflow): 1e100 with 1e-104; the bound is 2^-190
  // relative to the largest coordinate scaled into [1/2, 1).
  EXPECT_EQ(triangulate({{0, 0}, {1e100, 0}, {0, 1}, {1e-104, 3}}, tri, &rep),
            Status::numerical_overflow);
  EXPECT_EQ(rep.first, 2);  // (0, 1) is already 1e-100 of the largest
  EXPECT_EQ(triangulate({{0, 0}, {1, 0}, {0, 1}, {0x1p-190, 0.5}}, tri, &rep),  // 1 -> 1/2
            Status::numerical_overflow);
  EXPECT_EQ(triangulate({{0, 0}, {1, 0}, {0, 1}, {0x1p-189, 0.5}}, tri), Status::ok);
  EXPECT_EQ(triangulate({{0, 0}, {0.75, 0}, {0, 0.75}, {0x1p-190, 0.5}}, tri), Status::ok);
  EXPECT_EQ(check_triangulation({{0, 0}, {0.75, 0}, {0, 0.75}, {0x1p-190, 0.5}}, tri), "");

  // Buffers: the needed sizes are reported, the outputs untouched.
  const std::vector<Vec2d> pts = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {0.5, 0.4}};
  std::vector<int> work(delaunay_workspace_size(5));
  int out[8][3] = {};
  int ntri = -7;
  EXPECT_EQ(delaunay_triangulate(pts.data(), 5, work.data(), work.size() - 1, out, 8, ntri, &rep),
            Status::buffer_too_small);
  EXPECT_EQ(rep.work_needed, work.size());
  EXPECT_EQ(ntri, -7);
  EXPECT_EQ(delaunay_triangulate(pts.data(), 5, work.data(), work.size(), out, 3, ntri, &rep),
            Status::buffer_too_small);
  EXPECT_EQ(rep.triangles_needed, 4);
  EXPECT_EQ(ntri, 4);
  EXPECT_EQ(out[0][0], 0);
  EXPECT_EQ(out[0][1], 0);
  EXPECT_EQ(delaunay_max_triangles(5), 5);
  EXPECT_EQ(delaunay_triangulate(pts.data(), 5, work.data(), work.size(), out, 4, ntri), Status::ok);
  EXPECT_EQ(ntri, 4);
}

TEST(Delaunay, ValidationOfUserTriangulations) {
  const std::vector<Vec2d> pts = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 0}};
  std::vector<int> work(triangulation_workspace_size(4));
  int nb[12];
  DelaunayReport rep;
  const int good[3][3] = {{0, 1, 2}, {0, 2, 3}, {1, 4, 2}};
  ASSERT_EQ(validate_triangulation(pts.data(), 5, good, 3, work.data(), work.size(), nb), Status::ok);
  EXPECT_EQ(nb[1], 2);   // edge 1 -> 2 of triangle 0 is shared with triangle 2
  EXPECT_EQ(nb[2], 1);   // edge 2 -> 0 with triangle 1
  EXPECT_EQ(nb[0], -1);  // 0 -> 1 on the boundary
  const int clockwise[1][3] = {{0, 2, 1}};
  EXPECT_EQ(validate_triangulation(pts.data(), 5, clockwise, 1, work.data(), work.size(), nullptr, &rep),
            Status::invalid_argument);
  EXPECT_EQ(rep.first, 0);
  const int flat[2][3] = {{0, 1, 2}, {0, 1, 4}};  // 0, 1, 4 collinear
  EXPECT_EQ(validate_triangulation(pts.data(), 5, flat, 2, work.data(), work.size(), nullptr, &rep),
            Status::invalid_argument);
  EXPECT_EQ(rep.first, 1);
  const int out_of_range[1][3] = {{0, 1, 5}};
  EXPECT_EQ(validate_triangulation(pts.data(), 5, out_of_range, 1, work.data(), work.size()),
            Status::invalid_argument);
  const int same_direction[2][3] = {{0, 1, 2}, {0, 1, 3}};  // 0 -> 1 twice
  EXPECT_EQ(validate_triangulation(pts.data(), 5, same_direction, 2, work.data(), work.size()),
            Status::invalid_argument);
  const std::vector<Vec2d> fan = {{0, 0}, {1, 0}, {0.5, 1}, {0.5, -1}, {0.6, 2}};
  const int three[3][3] = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};  // edge 0-1 three times
  EXPECT_EQ(validate_triangulation(fan.data(), 5, three, 3, work.data(), work.size()),
            Status::invalid_argument);
  EXPECT_EQ(validate_triangulation(pts.data(), 5, good, 3, work.data(), 8), Status::buffer_too_small);
  // Tiny triangles are exact (the points are scaled by a power of two) ...
  std::vector<Vec2d> tiny = pts;
  for (Vec2d& p : tiny) p *= 1e-300;
  EXPECT_EQ(validate_triangulation(tiny.data(), 5, good, 3, work.data(), work.size()), Status::ok);
  EXPECT_EQ(validate_triangulation(tiny.data(), 5, clockwise, 1, work.data(), work.size()),
            Status::invalid_argument);
  // ... but a dynamic range beyond 2^190 is refused.
  tiny[4] = Vec2d(1e100, 0);
  EXPECT_EQ(validate_triangulation(tiny.data(), 5, good, 3, work.data(), work.size(), nullptr, &rep),
            Status::numerical_overflow);
  EXPECT_EQ(rep.first, 1);
}

// ------------------------------------------------------------------ evaluator

TEST(QuadraticGraph, EvaluatorMatchesBernsteinFormAndFiniteDifferences) {
  QuadraticGraphTriangle q;
  q.vertex[0] = Vec2d(0.2, -0.1);
  q.vertex[1] = Vec2d(1.3, 0.4);
  q.vertex[2] = Vec2d(0.1, 1.1);
  const double o[6] = {1.0, -0.5, 2.0, 0.25, 3.0, -1.5};
  std::copy(o, o + 6, q.ordinate);
  // Corner values are the corner ordinates.
  const int corner[3] = {0, 3, 5};
  for (int k = 0; k < 3; ++k) {
    double v;
    Vec2d g;
    ASSERT_EQ(quadratic_graph_eval(q, q.vertex[k], v, g), Status::ok);
    EXPECT_NEAR(v, o[corner[k]], 1e-14);
  }
  // de Casteljau at barycentric (0.2, 0.3, 0.5) and central differences.
  const double r = 0.2, s = 0.3, t = 0.5;
  const Vec2d p = r * q.vertex[0] + s * q.vertex[1] + t * q.vertex[2];
  const double b100 = r * o[0] + s * o[1] + t * o[2];
  const double b010 = r * o[1] + s * o[3] + t * o[4];
  const double b001 = r * o[2] + s * o[4] + t * o[5];
  const double casteljau = r * b100 + s * b010 + t * b001;
  double v;
  Vec2d g;
  ASSERT_EQ(quadratic_graph_eval(q, p, v, g), Status::ok);
  EXPECT_NEAR(v, casteljau, 1e-14);
  const double h = 1e-5;
  for (int d = 0; d < 2; ++d) {
    Vec2d e = Vec2d::Zero();
    e[d] = h;
    double vp, vm;
    Vec2d dummy;
    quadratic_graph_eval(q, p + e, vp, dummy);
    quadratic_graph_eval(q, p - e, vm, dummy);
    EXPECT_NEAR(g[d], (vp - vm) / (2 * h), 1e-9);  // exact for quadratics up to rounding
  }
  QuadraticGraphTriangle flat = q;
  flat.vertex[2] = 0.5 * (q.vertex[0] + q.vertex[1]);
  EXPECT_EQ(quadratic_graph_eval(flat, p, v, g), Status::invalid_argument);
}

// ------------------------------------------------------------------ Powell-Sabin

namespace {

struct Data {
  std::vector<Vec2d> b;
  std::vector<double> z;
  std::vector<Vec2d> g;
};

template <class F, class G>
Data sample(const std::vector<Vec2d>& b, F f, G grad) {
  Data d;
  d.b = b;
  for (const Vec2d& p : b) {
    d.z.push_back(f(p));
    d.g.push_back(grad(p));
  }
  return d;
}

double smooth(const Vec2d& p) { return std::sin(2 * p.x()) * std::exp(0.5 * p.y()) + p.x() * p.y(); }
Vec2d smooth_gradient(const Vec2d& p) {
  return Vec2d(2 * std::cos(2 * p.x()) * std::exp(0.5 * p.y()) + p.y(),
               0.5 * std::sin(2 * p.x()) * std::exp(0.5 * p.y()) + p.x());
}

}  // namespace

TEST(PowellSabin, QuadraticPrecisionGivesTranslationInvariance) {
  // §4.2 with (2.5): a translation adds a quadratic; the PS interpolant of
  // quadratic data is that quadratic on every micro-triangle.
  const auto pts = random_points(60, 3, 0.05);
  const auto tri = delaunay(pts);
  Quadratic f;
  f.c = 0.7;
  f.l = Vec2d(-1.2, 0.4);
  f.qxx = 2.5;
  f.qxy = -0.8;
  f.qyy = 1.1;
  const Data d = sample(pts, [&](const Vec2d& p) { return f.value(p); },
                        [&](const Vec2d& p) { return f.gradient(p); });
  std::vector<QuadraticGraphTriangle> patches;
  ASSERT_EQ(interpolate(d.b, d.z, d.g, tri, patches), Status::ok);
  ASSERT_EQ(patches.size(), 6 * tri.size());
  double worst = 0;
  for (const auto& m : patches)
    for (const auto& w : {std::array<double, 3>{1. / 3, 1. / 3, 1. / 3}, std::array<double, 3>{0.7, 0.2, 0.1},
                          std::array<double, 3>{0.05, 0.05, 0.9}}) {
      const Vec2d p = w[0] * m.vertex[0] + w[1] * m.vertex[1] + w[2] * m.vertex[2];
      double v;
      Vec2d g;
      ASSERT_EQ(quadratic_graph_eval(m, p, v, g), Status::ok);
      worst = std::max(worst, std::fabs(v - f.value(p)) / (1 + std::fabs(f.value(p))));
      worst = std::max(worst, (g - f.gradient(p)).norm() / (1 + f.gradient(p).norm()));
    }
  EXPECT_LT(worst, 1e-12);
}

TEST(PowellSabin, OffsetInvariance) {
  // (2.6): the offset by d adds -(d/2)(1 + y1^2 + y2^2) to the graph. The
  // interpolant of the offset data is the offset interpolant.
  const auto pts = random_points(40, 9, 0.08);
  const auto tri = delaunay(pts);
  const double dist = 0.37;
  const auto offset = [&](const Vec2d& p) { return -dist / 2 * (1 + p.squaredNorm()); };
  const Data d0 = sample(pts, smooth, smooth_gradient);
  const Data d1 = sample(pts, [&](const Vec2d& p) { return smooth(p) + offset(p); },
                         [&](const Vec2d& p) -> Vec2d { return smooth_gradient(p) - dist * p; });
  std::vector<QuadraticGraphTriangle> s0, s1;
  ASSERT_EQ(interpolate(d0.b, d0.z, d0.g, tri, s0), Status::ok);
  ASSERT_EQ(interpolate(d1.b, d1.z, d1.g, tri, s1), Status::ok);
  for (std::size_t i = 0; i < s0.size(); ++i) {
    const Vec2d c = (s0[i].vertex[0] + s0[i].vertex[1] + 2 * s0[i].vertex[2]) / 4;
    double v0, v1;
    Vec2d g0, g1;
    quadratic_graph_eval(s0[i], c, v0, g0);
    quadratic_graph_eval(s1[i], c, v1, g1);
    EXPECT_NEAR(v1, v0 + offset(c), 1e-12);
    EXPECT_LT((g1 - (g0 - dist * c)).norm(), 1e-12);
  }
}

TEST(PowellSabin, InterpolatesValuesAndTangentPlanes) {
  // The graph passes through B_i with tangent plane beta_i.
  const auto pts = random_points(50, 21, 0.05);
  const auto tri = delaunay(pts);
  const Data d = sample(pts, smooth, smooth_gradient);
  std::vector<QuadraticGraphTriangle> patches;
  ASSERT_EQ(interpolate(d.b, d.z, d.g, tri, patches), Status::ok);
  for (std::size_t t = 0; t < tri.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int i = tri[t][k];
      const QuadraticGraphTriangle& m = patches[6 * t + 2 * k];  // (V_k, R_k, Z)
      ASSERT_EQ(m.vertex[0], pts[i]);
      double v;
      Vec2d g;
      quadratic_graph_eval(m, pts[i], v, g);
      EXPECT_NEAR(v, d.z[i], 1e-13 * (1 + std::fabs(d.z[i])));
      EXPECT_LT((g - d.g[i]).norm(), 1e-10 * (1 + d.g[i].norm()));
    }
}

TEST(PowellSabin, SplitPointsIncentersAndCollinearity) {
  const auto pts = random_points(50, 33, 0.05);
  const auto tri = delaunay(pts);
  const Data d = sample(pts, smooth, smooth_gradient);
  std::vector<QuadraticGraphTriangle> patches;
  ASSERT_EQ(interpolate(d.b, d.z, d.g, tri, patches), Status::ok);
  // Independent incenters: intersection of two angle bisectors.
  const auto incenter = [&](std::size_t t) {
    const Vec2d a = pts[tri[t][0]], b = pts[tri[t][1]], c = pts[tri[t][2]];
    const Vec2d da = ((b - a).normalized() + (c - a).normalized());
    const Vec2d db = ((a - b).normalized() + (c - b).normalized());
    // a + s da = b + u db
    // Cramer's rule for s: s (da x -db) = (b - a) x -db.
    const auto cr = [](const Vec2d& u, const Vec2d& w) { return u.x() * w.y() - u.y() * w.x(); };
    const double s = cr(b - a, -db) / cr(da, -db);
    return Vec2d(a + s * da);
  };
  std::map<std::pair<int, int>, std::vector<std::size_t>> edge_tris;
  for (std::size_t t = 0; t < tri.size(); ++t) {
    EXPECT_LT((patches[6 * t].vertex[2] - incenter(t)).norm(), 1e-13);
    for (int k = 0; k < 3; ++k)
      edge_tris[{std::min(tri[t][k], tri[t][(k + 1) % 3]), std::max(tri[t][k], tri[t][(k + 1) % 3])}]
          .push_back(t);
  }
  int interior = 0;
  for (const auto& e : edge_tris) {
    const std::size_t t = e.second[0];
    int k = 0;
    while (std::minmax(tri[t][k], tri[t][(k + 1) % 3]) != std::minmax(e.first.first, e.first.second)) ++k;
    const Vec2d r = patches[6 * t + 2 * k].vertex[1];
    const Vec2d p = pts[e.first.first], q = pts[e.first.second];
    // R lies inside the edge.
    EXPECT_LT(std::fabs((q - p).x() * (r - p).y() - (q - p).y() * (r - p).x()) / (q - p).squaredNorm(), 1e-14);
    const double lam = (r - p).dot(q - p) / (q - p).squaredNorm();
    EXPECT_GT(lam, 0);
    EXPECT_LT(lam, 1);
    if (e.second.size() == 1) {
      EXPECT_LT((r - 0.5 * (p + q)).norm(), 1e-15 * (1 + r.norm()));  // boundary: midpoint
      continue;
    }
    ++interior;
    const Vec2d z0 = incenter(e.second[0]), z1 = incenter(e.second[1]);
    const double c = (z1 - z0).x() * (r - z0).y() - (z1 - z0).y() * (r - z0).x();
    EXPECT_LT(std::fabs(c) / (z1 - z0).squaredNorm(), 1e-12);  // Z, R, Z' collinear
  }
  EXPECT_GT(interior, 50);
}

TEST(PowellSabin, C1AcrossMicroAndMacroEdges) {
  const auto pts = random_points(60, 17, 0.05);
  const auto tri = delaunay(pts);
  const Data d = sample(pts, smooth, smooth_gradient);
  std::vector<QuadraticGraphTriangle> patches;
  ASSERT_EQ(interpolate(d.b, d.z, d.g, tri, patches), Status::ok);
  const Continuity c = continuity(patches);
  // Interior micro edges: 6 per macro triangle (Z V_k, Z R_k) plus 2 per
  // interior macro edge.
  EXPECT_GT(c.shared_edges, static_cast<int>(6 * tri.size()));
  EXPECT_LT(c.max_value_gap, 1e-12);
  EXPECT_LT(c.max_gradient_gap, 1e-10);
}

TEST(PowellSabin, UserTriangulationWithSkinnyTriangles) {
  // A caller's (non-Delaunay) triangulation of a fan around a centre with
  // thin triangles: still quadratic precision and C^1.
  std::vector<Vec2d> pts = {{0, 0}};
  const int m = 12;
  for (int k = 0; k < m; ++k) {
    const double a = 2 * M_PI * k / m + (k % 2 ? 0.35 : 0.0);  // uneven angles
    pts.emplace_back((k % 3 ? 1.0 : 3.0) * std::cos(a), (k % 3 ? 1.0 : 3.0) * std::sin(a));
  }
  std::vector<Tri> tri;
  for (int k = 0; k < m; ++k) {
    const int a = 1 + k, b = 1 + (k + 1) % m;
    if (orient2d_sign(pts[0], pts[a], pts[b]) > 0) tri.push_back({0, a, b});
  }
  ASSERT_EQ(tri.size(), static_cast<std::size_t>(m));
  Quadratic f;
  f.c = 1;
  f.l = Vec2d(0.5, -2);
  f.qxx = -1;
  f.qxy = 3;
  f.qyy = 0.5;
  const Data d = sample(pts, [&](const Vec2d& p) { return f.value(p); },
                        [&](const Vec2d& p) { return f.gradient(p); });
  std::vector<QuadraticGraphTriangle> patches;
  ASSERT_EQ(interpolate(d.b, d.z, d.g, tri, patches), Status::ok);
  for (const auto& q : patches) {
    const Vec2d c = (q.vertex[0] + q.vertex[1] + q.vertex[2]) / 3;
    double v;
    Vec2d g;
    quadratic_graph_eval(q, c, v, g);
    EXPECT_NEAR(v, f.value(c), 1e-12 * (1 + std::fabs(f.value(c))));
    EXPECT_LT((g - f.gradient(c)).norm(), 1e-11 * (1 + f.gradient(c).norm()));
  }
  const Data e = sample(pts, smooth, smooth_gradient);
  ASSERT_EQ(interpolate(e.b, e.z, e.g, tri, patches), Status::ok);
  const Continuity c = continuity(patches);
  EXPECT_GE(c.shared_edges, 6 * m + 2 * m);
  EXPECT_LT(c.max_value_gap, 1e-12);
  EXPECT_LT(c.max_gradient_gap, 1e-10);
}

TEST(PowellSabin, StatusesAndUntouchedOutputs) {
  const std::vector<Vec2d> b = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<double> z = {0, 1, 2, 1};
  std::vector<Vec2d> g(4, Vec2d(0.5, -0.5));
  const int tri[2][3] = {{0, 1, 2}, {0, 2, 3}};
  std::vector<int> work(powell_sabin_workspace_size(2));
  QuadraticGraphTriangle out[12];
  out[0].ordinate[0] = 42;
  int nout = -3;
  EXPECT_EQ(powell_sabin_interpolate(b.data(), z.data(), g.data(), 4, tri, 2, work.data(), work.size(),
                                     out, 11, nout),
            Status::buffer_too_small);
  EXPECT_EQ(nout, 12);
  nout = -3;
  EXPECT_EQ(powell_sabin_interpolate(b.data(), z.data(), g.data(), 4, tri, 2, work.data(),
                                     work.size() - 1, out, 12, nout),
            Status::buffer_too_small);
  const int clockwise[2][3] = {{0, 2, 1}, {0, 2, 3}};
  EXPECT_EQ(powell_sabin_interpolate(b.data(), z.data(), g.data(), 4, clockwise, 2, work.data(),
                                     work.size(), out, 12, nout),
            Status::invalid_argument);
  const std::vector<Vec2d> flat_b = {{0, 0}, {1, 0}, {2, 0}, {0, 1}};
  const int flat[2][3] = {{0, 1, 2}, {0, 2, 3}};
  EXPECT_EQ(powell_sabin_interpolate(flat_b.data(), z.data(), g.data(), 4, flat, 2, work.data(),
                                     work.size(), out, 12, nout),
            Status::invalid_argument);
  g[2] = Vec2d(std::numeric_limits<double>::quiet_NaN(), 0);
  EXPECT_EQ(powell_sabin_interpolate(b.data(), z.data(), g.data(), 4, tri, 2, work.data(), work.size(),
                                     out, 12, nout),
            Status::not_finite);
  // |x| <= 1e100 everywhere keeps every ordinate below ~1e201: finite.
  const std::vector<double> zbig = {0, 1e100, 2, 1};
  const std::vector<Vec2d> bbig = {{0, 0}, {1e100, 0}, {1e100, 1e100}, {0, 1e100}};
  const std::vector<Vec2d> gbig(4, Vec2d(1e100, -1e100));
  QuadraticGraphTriangle big[12];
  int nbig = 0;
  EXPECT_EQ(powell_sabin_interpolate(bbig.data(), zbig.data(), gbig.data(), 4, tri, 2, work.data(),
                                     work.size(), big, 12, nbig),
            Status::ok);
  for (const auto& m : big)
    for (const double o : m.ordinate) EXPECT_TRUE(std::isfinite(o));
  EXPECT_EQ(out[0].ordinate[0], 42);
  EXPECT_EQ(nout, -3);
  g[2] = Vec2d(0.5, -0.5);
  ASSERT_EQ(powell_sabin_interpolate(b.data(), z.data(), g.data(), 4, tri, 2, work.data(), work.size(),
                                     out, 12, nout),
            Status::ok);
  EXPECT_EQ(nout, 12);
  int index = -5;
  EXPECT_EQ(quadratic_graph_locate(out, 12, Vec2d(0.9, 0.5), 0, index), Status::ok);
  double bary[3];
  ASSERT_EQ(quadratic_graph_barycentric(out[index], Vec2d(0.9, 0.5), bary), Status::ok);
  EXPECT_GE(std::min({bary[0], bary[1], bary[2]}), 0);
  EXPECT_EQ(quadratic_graph_locate(out, 12, Vec2d(2, 2), 1e-12, index), Status::bad_domain);
  EXPECT_EQ(index, -1);
}
