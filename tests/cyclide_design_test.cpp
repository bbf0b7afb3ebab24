// G1 surface design with parabolic Dupin cyclide patches (seed 004 §4.2):
// worked cases and RapidCheck properties (labels laguerre;paper and
// laguerre;property). Every check goes through an independent path: the
// patches are evaluated from their rational cubic control points
// (de Casteljau), and compared with the data, with exact surfaces, or with
// the design of moved data.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <vector>

#include "cyclide/bezier_triangle.hpp"
#include "cyclide/cyclide_design.hpp"
#include "cyclide/laguerre.hpp"

using namespace cyclide;

namespace {

// Tolerances (SPEC §8i.6), relative to the data's scale L = 1 + max |A_i|.
constexpr double kInterpTol = 1e-11;   // patch point at a datum = A_i
constexpr double kSeamTol = 1e-11;     // two patches at a shared edge point
constexpr double kMoveTol = 1e-10;     // design(moved data) = moved design
constexpr double kExactTol = 1e-11;    // sphere / cyclide reproduced
constexpr double kNormalTol = 1e-6;    // finite-difference patch normal vs sigma^-1(y)

struct Design {
  Status status = Status::internal_error;
  std::vector<QuadraticGraphTriangle> iso;
  std::vector<RationalCubicTriangle> patches;
  CyclideDesignReport report;
};

Design design(const std::vector<OrientedPoint>& data, bool allow_ridges = false) {
  const int n = int(data.size());
  Design D;
  std::vector<unsigned char> work(cyclide_design_workspace_size(n, 0));
  const int cap = cyclide_design_max_patches(n, 0);
  D.iso.resize(cap);
  D.patches.resize(cap);
  CyclideDesignOptions o;
  o.allow_ridges = allow_ridges;
  int np = 0;
  D.status = design_cyclide_surface(data.data(), n, nullptr, 0, o, work.data(), work.size(),
                                    D.iso.data(), D.patches.data(), cap, np, &D.report);
  D.iso.resize(D.status == Status::ok ? np : 0);
  D.patches.resize(D.status == Status::ok ? np : 0);
  return D;
}

double scale_of(const std::vector<OrientedPoint>& data) {
  double L = 1;
  for (const auto& d : data) L = std::max(L, 1 + d.point.norm());
  return L;
}

// sigma^{-1}: the unit normal of the isotropic point with projection y.
Vec3d normal_of(const Vec2d& y) {
  const double N = 1 + y.squaredNorm();
  return Vec3d(2 * y[0] / N, 2 * y[1] / N, 1 - 2 / N);
}

Vec3d eval(const RationalCubicTriangle& T, double r, double s, double t) {
  Vec3d x = Vec3d::Constant(NAN);
  EXPECT_EQ(evaluate(T, r, s, t, x), Status::ok);
  return x;
}

Vec2d domain_point(const QuadraticGraphTriangle& q, double r, double s, double t) {
  return r * q.vertex[0] + s * q.vertex[1] + t * q.vertex[2];
}

// The data whose isotropic image is the graph of f over the points b.
template <class F>
std::vector<OrientedPoint> data_of_graph(const std::vector<Vec2d>& b, F f) {
  std::vector<OrientedPoint> data;
  for (const Vec2d& y : b) {
    IsotropicDatum d;
    d.b = y;
    f(y, d.z, d.g);
    OrientedPoint A;
    EXPECT_EQ(oriented_point_from_isotropic(d, A), Status::ok);
    data.push_back(A);
  }
  return data;
}

// A k x k grid over [-h, h]^2 (deterministic), its interior points
// jittered. The border stays straight: jittered hull points are nearly
// collinear and Delaunay joins them by slivers, over which the
// Powell-Sabin interpolant is poor and its patches fold (a ridge, found
// when this grid jittered every point).
std::vector<Vec2d> grid(int k, double h, double jitter = 0.13) {
  std::vector<Vec2d> b;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      const bool border = i == 0 || j == 0 || i == k - 1 || j == k - 1;
      const double dx = border ? 0 : jitter * std::sin(3.7 * i + 5.1 * j);
      const double dy = border ? 0 : jitter * std::cos(2.3 * i - 4.9 * j);
      b.emplace_back(-h + 2 * h * (i + 0.5 + 0.4 * dx) / k, -h + 2 * h * (j + 0.5 + 0.4 * dy) / k);
    }
  return b;
}

// The lower cap of the sphere (c, R): normals a = sigma^{-1}(b), points
// c + R a (outward normals, the contact rule x = m + r e).
std::vector<OrientedPoint> sphere_data(const Vec3d& c, double R, const std::vector<Vec2d>& b) {
  std::vector<OrientedPoint> data;
  for (const Vec2d& y : b) {
    OrientedPoint A;
    A.normal = normal_of(y);
    A.point = c + R * A.normal;
    data.push_back(A);
  }
  return data;
}

// The ellipsoid x^2/p^2 + y^2/q^2 + z^2/s^2 = 1 at the normal a:
// the support point D a / sqrt(a . D a), D = diag(p^2, q^2, s^2).
std::vector<OrientedPoint> ellipsoid_data(const Vec3d& axes, const Vec3d& c,
                                          const std::vector<Vec2d>& b) {
  std::vector<OrientedPoint> data;
  const Vec3d D = axes.cwiseProduct(axes);
  for (const Vec2d& y : b) {
    OrientedPoint A;
    A.normal = normal_of(y);
    A.point = c + D.cwiseProduct(A.normal) / std::sqrt(A.normal.dot(D.cwiseProduct(A.normal)));
    data.push_back(A);
  }
  return data;
}

const double kBary[][3] = {{1, 0, 0},       {0, 1, 0},     {0, 0, 1},        {1. / 3, 1. / 3, 1. / 3},
                           {0.5, 0.5, 0},   {0, 0.5, 0.5}, {0.2, 0.1, 0.7},  {0.6, 0.3, 0.1}};

// The checks every design must pass: the patches interpolate the data
// (points and, by finite differences, normals), and patches sharing a
// domain edge meet there in the same points with the same tangent plane.
void expect_interpolates_and_g1(const std::vector<OrientedPoint>& data, const Design& D) {
  const double L = scale_of(data);
  std::vector<Vec2d> b;
  for (const auto& A : data) {
    IsotropicDatum d;
    ASSERT_EQ(isotropic_datum(A, d), Status::ok);
    b.push_back(d.b);
  }
  // Interpolation: every patch vertex that is a datum's b_i maps to A_i.
  std::vector<int> hit(data.size(), 0);
  for (std::size_t k = 0; k < D.iso.size(); ++k)
    for (int v = 0; v < 3; ++v)
      for (std::size_t i = 0; i < b.size(); ++i)
        if ((D.iso[k].vertex[v] - b[i]).norm() <= 1e-14 * (1 + b[i].norm())) {
          const double w[3] = {v == 0 ? 1. : 0., v == 1 ? 1. : 0., v == 2 ? 1. : 0.};
          EXPECT_LE((eval(D.patches[k], w[0], w[1], w[2]) - data[i].point).norm(), kInterpTol * L)
              << "datum " << i << " patch " << k;
          ++hit[i];
        }
  for (std::size_t i = 0; i < data.size(); ++i) EXPECT_GT(hit[i], 0) << "datum " << i;
  // G1 at every shared micro-edge: same points, and each patch's tangent
  // plane (finite differences of its control-point evaluation) has the
  // normal sigma^{-1}(y).
  for (std::size_t k = 0; k < D.iso.size(); ++k) {
    for (int e = 0; e < 3; ++e) {
      const Vec2d p0 = D.iso[k].vertex[e], p1 = D.iso[k].vertex[(e + 1) % 3];
      for (std::size_t m = k + 1; m < D.iso.size(); ++m) {
        int f0 = -1, f1 = -1;
        for (int v = 0; v < 3; ++v) {
          if (D.iso[m].vertex[v] == p0) f0 = v;
          if (D.iso[m].vertex[v] == p1) f1 = v;
        }
        if (f0 < 0 || f1 < 0) continue;
        for (double s : {0.1, 0.37, 0.5, 0.81}) {
          double wk[3] = {0, 0, 0}, wm[3] = {0, 0, 0};
          wk[e] = 1 - s;
          wk[(e + 1) % 3] = s;
          wm[f0] = 1 - s;
          wm[f1] = s;
          const Vec3d xk = eval(D.patches[k], wk[0], wk[1], wk[2]);
          const Vec3d xm = eval(D.patches[m], wm[0], wm[1], wm[2]);
          EXPECT_LE((xk - xm).norm(), kSeamTol * L) << "patches " << k << ", " << m;
        }
      }
    }
    // The patch's own tangent plane at its centroid.
    const double h = 1e-6;
    const double c = 1.0 / 3;
    const Vec3d xr = eval(D.patches[k], c + h, c - h, c) - eval(D.patches[k], c - h, c + h, c);
    const Vec3d xs = eval(D.patches[k], c, c + h, c - h) - eval(D.patches[k], c, c - h, c + h);
    const Vec3d n = normal_of(domain_point(D.iso[k], c, c, c));
    const Vec3d cr = xr.cross(xs);
    if (cr.norm() > 0) EXPECT_NEAR(std::abs(cr.normalized().dot(n)), 1.0, kNormalTol) << k;
  }
}

}  // namespace

// §4.2 with data from a sphere: Lambda maps a sphere's tangent planes to a
// paraboloid (2.4), a quadratic, which the Powell-Sabin spline reproduces;
// so every patch lies on the sphere (a = b in (4.1)).
TEST(Seed004Design, SphereDataGiveTheSphere) {
  const Vec3d c(1.5, -2, 0.25);
  const double R = 3;
  const auto data = sphere_data(c, R, grid(5, 0.6));
  const Design D = design(data);
  ASSERT_EQ(D.status, Status::ok);
  EXPECT_EQ(int(D.patches.size()), 6 * D.report.triangles);
  EXPECT_EQ(D.report.ridge_patches, 0);
  for (const auto& T : D.patches)
    for (const auto& w : kBary)
      EXPECT_NEAR((eval(T, w[0], w[1], w[2]) - c).norm(), R, kExactTol * (R + c.norm()));
  expect_interpolates_and_g1(data, D);
}

// Data from a parabolic Dupin cyclide of G (Thm 4.1: y3 = q/2 with q =
// -(a y1^2 + b y2^2)): the design reproduces the cyclide, whose points
// satisfy (4.2).
TEST(Seed004Design, CyclideDataGiveTheCyclide) {
  const double a = 2, b = -1;  // a ring cyclide
  const auto data = data_of_graph(grid(5, 0.7), [&](const Vec2d& y, double& z, Vec2d& g) {
    z = -0.5 * (a * y[0] * y[0] + b * y[1] * y[1]);
    g = Vec2d(-a * y[0], -b * y[1]);
  });
  const Design D = design(data);
  ASSERT_EQ(D.status, Status::ok) << D.report.ridge_patches;
  for (const auto& T : D.patches)
    for (const auto& w : kBary) {
      const Vec3d x = eval(T, w[0], w[1], w[2]);
      // (4.2) at x0 = 1, relative to the size of its terms.
      const double q = x.squaredNorm();
      const double lhs = b * x[0] * x[0] + a * x[1] * x[1] + (a + b) * x[2] * x[2] -
                         x[2] * (a * b + q);
      const double terms = std::abs(b) * x[0] * x[0] + std::abs(a) * x[1] * x[1] +
                           std::abs(a + b) * x[2] * x[2] + std::abs(x[2]) * (std::abs(a * b) + q);
      EXPECT_LE(std::abs(lhs), kExactTol * (1 + terms));
    }
  expect_interpolates_and_g1(data, D);
}

// A convex surface that is no cyclide: the lower part of an ellipsoid
// (radii of curvature 1.3..4.5; normals 6.5 degrees apart or more).
// Coarser data of more eccentric ellipsoids fold: the interpolant's
// piecewise constant Hessian errs by more than the small radii allow
// (axes (4, 1, 1) on an 8 x 8 grid: 82 of 588 patches; see FoldingData).
TEST(Seed004Design, EllipsoidDataAreInterpolatedG1) {
  const auto data = ellipsoid_data(Vec3d(3, 2.5, 2), Vec3d(0.5, 0, -1), grid(6, 0.6));
  const Design D = design(data);
  ASSERT_EQ(D.status, Status::ok);
  EXPECT_EQ(D.report.ridge_patches, 0);
  EXPECT_NE(D.report.orientation, 0);
  expect_interpolates_and_g1(data, D);
}

// §4.2: "a translation in design space will 'add' a quadratic function to
// the surface Psi" (2.5), which Powell-Sabin reproduces; and offsetting
// the data gives the offset surface (2.6).
TEST(Seed004Design, TranslationAndOffsetInvariance) {
  const auto data = ellipsoid_data(Vec3d(3, 2.5, 2), Vec3d(0.5, 0, -1), grid(5, 0.6));
  const Design D = design(data);
  ASSERT_EQ(D.status, Status::ok);
  const Vec3d t(10, -4, 7);
  const double d = 0.75;
  auto moved = data, offset = data;
  for (auto& A : moved) A.point += t;
  for (auto& A : offset) A.point += d * A.normal;
  const Design M = design(moved), O = design(offset);
  ASSERT_EQ(M.status, Status::ok);
  ASSERT_EQ(O.status, Status::ok);
  ASSERT_EQ(M.patches.size(), D.patches.size());
  ASSERT_EQ(O.patches.size(), D.patches.size());
  const double L = scale_of(moved);
  for (std::size_t k = 0; k < D.patches.size(); ++k)
    for (const auto& w : kBary) {
      const Vec3d x = eval(D.patches[k], w[0], w[1], w[2]);
      EXPECT_LE((eval(M.patches[k], w[0], w[1], w[2]) - (x + t)).norm(), kMoveTol * L);
      const Vec3d n = normal_of(domain_point(D.iso[k], w[0], w[1], w[2]));
      EXPECT_LE((eval(O.patches[k], w[0], w[1], w[2]) - (x + d * n)).norm(), kMoveTol * L);
    }
}

// Fig. 3: data whose isotropic interpolant makes a principal radius change
// sign (a cubic graph in I^3) give patches that fold: reported as ridge,
// or counted when ridges are allowed. Cross-checked by the orientation of
// finite differences of the patches' own evaluation.
TEST(Seed004Design, FoldingDataAreARidge) {
  const auto data = data_of_graph(grid(6, 0.8), [](const Vec2d& y, double& z, Vec2d& g) {
    z = 2 * y[0] * y[0] * y[0] + 0.1 * y[1] * y[1];
    g = Vec2d(6 * y[0] * y[0], 0.2 * y[1]);
  });
  const Design refused = design(data);
  EXPECT_EQ(refused.status, Status::ridge);
  EXPECT_GT(refused.report.ridge_patches, 0);
  EXPECT_GE(refused.report.first_ridge_patch, 0);
  const Design D = design(data, true);
  ASSERT_EQ(D.status, Status::ok);
  EXPECT_EQ(D.report.ridge_patches, refused.report.ridge_patches);
  // Independent: n . (x_r x x_s) from the control points changes sign.
  int plus = 0, minus = 0;
  const double h = 1e-6, c = 1.0 / 3;
  for (std::size_t k = 0; k < D.patches.size(); ++k) {
    const Vec3d xr = eval(D.patches[k], c + h, c, c - h) - eval(D.patches[k], c - h, c, c + h);
    const Vec3d xs = eval(D.patches[k], c, c + h, c - h) - eval(D.patches[k], c, c - h, c + h);
    const Vec2d y = domain_point(D.iso[k], c, c, c);
    // Orientation relative to the domain's: (r -> s) turns like the
    // micro-triangle's vertices.
    const Vec2d e1 = D.iso[k].vertex[0] - D.iso[k].vertex[2];
    const Vec2d e2 = D.iso[k].vertex[1] - D.iso[k].vertex[2];
    const double dom = e1[0] * e2[1] - e1[1] * e2[0];
    const double o = normal_of(y).dot(xr.cross(xs)) * (dom > 0 ? 1 : -1);
    plus += o > 0;
    minus += o < 0;
  }
  EXPECT_GT(plus, 0);
  EXPECT_GT(minus, 0);
}

// §4.2: "the Gaussian image of the interpolating surface should not
// contain W": a normal at W, or normals around it (an upper cap).
TEST(Seed004Design, GaussImageContainingThePoleIsRefused) {
  auto data = sphere_data(Vec3d::Zero(), 2, grid(4, 0.5));
  data[5].normal = Vec3d(0, 0, 1);
  Design D = design(data);
  EXPECT_EQ(D.status, Status::pole_in_gauss_image);
  EXPECT_EQ(D.report.first_bad_datum, 5);
  std::vector<OrientedPoint> cap;
  for (int i = 0; i < 12; ++i) {
    const double phi = 2 * M_PI * i / 12;
    OrientedPoint A;
    A.normal = Vec3d(0.5 * std::cos(phi), 0.5 * std::sin(phi), std::sqrt(0.75));
    A.point = 2 * A.normal;
    cap.push_back(A);
  }
  EXPECT_TRUE(gauss_image_contains_pole(cap.data(), int(cap.size())));
  EXPECT_EQ(design(cap).status, Status::pole_in_gauss_image);
  // The same cap turned upside down is fine.
  for (auto& A : cap) A.normal[2] = -A.normal[2], A.point = 2 * A.normal;
  EXPECT_FALSE(gauss_image_contains_pole(cap.data(), int(cap.size())));
  EXPECT_EQ(design(cap).status, Status::ok);
}

TEST(Seed004Design, IsotropicDatumRoundTrip) {
  const auto data = ellipsoid_data(Vec3d(3, 2.5, 2), Vec3d(0.5, 0, -1), grid(4, 0.6));
  for (const auto& A : data) {
    IsotropicDatum d;
    ASSERT_EQ(isotropic_datum(A, d), Status::ok);
    // B = Lambda(alpha): alpha's plane through A.
    OrientedPlane alpha;
    IsotropicPoint B;
    B.y = Vec3d(d.b[0], d.b[1], d.z);
    ASSERT_EQ(isotropic_to_laguerre(B, alpha), Status::ok);
    EXPECT_NEAR(alpha.e0 + alpha.e.dot(A.point), 0.0, 1e-13 * (1 + A.point.norm()));
    EXPECT_NEAR((alpha.e - A.normal).norm(), 0.0, 1e-14);
    // beta is tangent to the paraboloid of the point cycle A, (2.4).
    const IsotropicParaboloid P = cycle_to_paraboloid(Cycle{A.point, 0});
    for (double h : {1e-3, -1e-3}) {
      IsotropicPoint Q;
      const Vec2d y = d.b + Vec2d(h, 0.5 * h);
      Q.y = Vec3d(y[0], y[1], d.z + d.g.dot(y - d.b));
      // Q on beta, off the paraboloid by O(h^2) only.
      const double on = 2 * Q.y[2] + P.k * y.squaredNorm() + 2 * (P.l1 * y[0] + P.l2 * y[1]) + P.c0;
      EXPECT_LE(std::abs(on), 10 * h * h * (1 + A.point.norm()));
    }
    OrientedPoint back;
    ASSERT_EQ(oriented_point_from_isotropic(d, back), Status::ok);
    EXPECT_NEAR((back.point - A.point).norm(), 0.0, 1e-13 * (1 + A.point.norm()));
    EXPECT_NEAR((back.normal - A.normal).norm(), 0.0, 1e-14);
  }
}

TEST(Seed004Design, Validation) {
  auto data = sphere_data(Vec3d::Zero(), 2, grid(3, 0.5));
  const int n = int(data.size());
  std::vector<unsigned char> work(cyclide_design_workspace_size(n, 0));
  const int cap = cyclide_design_max_patches(n, 0);
  std::vector<QuadraticGraphTriangle> iso(cap);
  std::vector<RationalCubicTriangle> patches(cap);
  const RationalCubicTriangle sentinel = patches[0];
  CyclideDesignOptions o;
  CyclideDesignReport rep;
  int np = -7;
  auto run = [&](const OrientedPoint* d, int count, std::size_t bytes, int pcap) {
    return design_cyclide_surface(d, count, nullptr, 0, o, work.data(), bytes, iso.data(),
                                  patches.data(), pcap, np, &rep);
  };
  EXPECT_EQ(run(nullptr, n, work.size(), cap), Status::null_argument);
  EXPECT_EQ(run(data.data(), 2, work.size(), cap), Status::invalid_argument);
  EXPECT_EQ(run(data.data(), n, work.size() - 1, cap), Status::buffer_too_small);
  EXPECT_EQ(rep.work_needed, work.size());
  EXPECT_EQ(run(data.data(), n, work.size(), 1), Status::buffer_too_small);
  EXPECT_GT(rep.patches_needed, 1);
  auto bad = data;
  bad[2].point[1] = NAN;
  EXPECT_EQ(run(bad.data(), n, work.size(), cap), Status::not_finite);
  EXPECT_EQ(rep.first_bad_datum, 2);
  bad = data;
  bad[4] = bad[1];  // the same tangent plane twice: the same b_i
  EXPECT_EQ(run(bad.data(), n, work.size(), cap), Status::invalid_argument);
  bad = data;
  for (int i = 0; i < n; ++i) bad[i].normal = normal_of(Vec2d(0.1 * i, 0.05 * i));
  EXPECT_EQ(run(bad.data(), n, work.size(), cap), Status::collinear_points);
  EXPECT_EQ(np, -7);
  EXPECT_EQ(patches[0].control[0], sentinel.control[0]);
  ASSERT_EQ(run(data.data(), n, work.size(), cap), Status::ok);
  EXPECT_EQ(np, 6 * rep.triangles);
}

// ------------------------------------------------------------ properties

namespace {
double uniform(double lo, double hi) {
  return lo + (hi - lo) * *rc::gen::resize(100, rc::gen::inRange(0, 1 << 20)) / double(1 << 20);
}
}  // namespace

// Random ellipsoid caps (axes 2..3, centre within 5, 4x4 to 7x7 grids of
// normals over [-h, h]^2, h in 0.3..0.6, interior jittered): regular,
// interpolating, G1 at every shared edge, translation and offset
// invariance.
RC_GTEST_PROP(Seed004DesignProperties, InterpolatesG1AndInvariant, ()) {
  const double ax = uniform(2, 3), ay = uniform(2, 3), az = uniform(2, 3);
  const double cx = uniform(-5, 5), cy = uniform(-5, 5), cz = uniform(-5, 5);
  const int k = *rc::gen::inRange(4, 8);
  const double h = uniform(0.3, 0.6);
  const auto data = ellipsoid_data(Vec3d(ax, ay, az), Vec3d(cx, cy, cz), grid(k, h, uniform(0, 0.2)));
  const Design D = design(data);
  RC_ASSERT(D.status == Status::ok);
  RC_ASSERT(D.report.ridge_patches == 0);
  expect_interpolates_and_g1(data, D);
  RC_ASSERT(!::testing::Test::HasFailure());
  const Vec3d t(uniform(-20, 20), uniform(-20, 20), uniform(-20, 20));
  const double d = uniform(-0.5, 0.5) * std::min({ax, ay, az});
  auto moved = data;
  for (auto& A : moved) A.point += t + d * A.normal;
  // An inward offset may fold where it passes a designed radius (offsets of
  // regular surfaces need not be regular, §3): invariance holds regardless.
  const Design M = design(moved, true);
  RC_ASSERT(M.status == Status::ok);
  RC_ASSERT(M.patches.size() == D.patches.size());
  const double L = scale_of(moved);
  for (std::size_t i = 0; i < D.patches.size(); ++i)
    for (const auto& w : kBary) {
      const Vec3d x = eval(D.patches[i], w[0], w[1], w[2]);
      const Vec3d n = normal_of(domain_point(D.iso[i], w[0], w[1], w[2]));
      RC_ASSERT((eval(M.patches[i], w[0], w[1], w[2]) - (x + t + d * n)).norm() <= kMoveTol * L);
    }
}
