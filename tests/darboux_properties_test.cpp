// RapidCheck properties of Darboux cyclides, inversion and DCMC (labels
// "darboux" and "property"), on random well-conditioned inputs: coordinates
// are dyadic numbers in [-2, 2], lines have directions at least ~10 degrees
// apart, inversion centers stay at least 0.25 away from the points they
// move. Tolerances are relative and named here (SPEC.md §12 quotes them).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "cyclide/darboux.hpp"

using namespace cyclide;

namespace {

// |F(X)| <= kOnSurfaceTol * |grad F(X)| * (1 + |X|): X is within about
// kOnSurfaceTol (1 + |X|) of the surface.
constexpr double kOnSurfaceTol = 1e-9;
// Involution: |inv(inv(X)) - X| <= kInvolutionTol * (1 + |X|).
constexpr double kInvolutionTol = 1e-12;

double dyadic(int n) { return double(n) / 64.0; }  // n in [-128, 128]

rc::Gen<double> coord() { return rc::gen::map(rc::gen::inRange(-128, 129), dyadic); }

rc::Gen<Vec3d> point() {
  return rc::gen::apply([](double x, double y, double z) { return Vec3d(x, y, z); }, coord(),
                        coord(), coord());
}

bool on_surface(const Darboux& D, const Vec3d& X) {
  const double g = D.gradient(X).norm();
  return std::abs(D.value(X)) <= kOnSurfaceTol * g * (1 + X.norm()) * (1 + D.scale());
}

// Three lines in planes z = h_i with pairwise directions 10..160 degrees apart.
struct ThreeLines {
  Line L[3];
};

rc::Gen<ThreeLines> three_lines() {
  return rc::gen::exec([] {
    ThreeLines T;
    // Consecutive angles 10..80 degrees apart: all pairs differ by 10..160.
    const double a0 = *rc::gen::inRange(0, 180), s1 = *rc::gen::inRange(10, 81),
                 s2 = *rc::gen::inRange(10, 81);
    const double angles[3] = {a0, a0 + s1, a0 + s1 + s2};
    for (int i = 0; i < 3; ++i) {
      const double a = angles[i] * M_PI / 180.0;
      T.L[i].P = Vec3d(*coord(), *coord(), *coord());
      T.L[i].d = Vec3d(std::cos(a), std::sin(a), 0);
    }
    return T;
  });
}

RC_GTEST_PROP(DarbouxProperties, EveryDcmcMemberContainsTheThreeLines, ()) {
  const ThreeLines T = *three_lines();
  DcmcFamily F;
  const Status st = dcmc(T.L, F);
  RC_PRE(st == Status::ok);  // coincident planes can leave more freedom
  const double alpha = *coord() * 4;
  const Darboux D = F.member(alpha);
  RC_ASSERT(darboux_type(D) == DarbouxType::parabolic || darboux_type(D) == DarbouxType::reducible);
  for (const Line& L : T.L)
    for (double t : {-2.0, -0.5, 0.75, 3.0}) RC_ASSERT(on_surface(D, L.P + t * L.d));
  // The quadric direction alone also contains them.
  for (const Line& L : T.L) RC_ASSERT(on_surface(F.quadric, L.P + 1.5 * L.d));
}

RC_GTEST_PROP(DarbouxProperties, InversionIsAnInvolution, ()) {
  const Inversion inv{*point(), 0.25 + std::abs(*coord())};
  const Vec3d X = *point();
  RC_PRE((X - inv.m).norm() > 0.25);
  Vec3d Y, Z;
  RC_ASSERT(invert_point(inv, X, Y) == Status::ok);
  RC_ASSERT(invert_point(inv, Y, Z) == Status::ok);
  RC_ASSERT((Z - X).norm() <= kInvolutionTol * (1 + X.norm()));
}

// Inversion commutes with similarities: at scale 2^k (k in [-1000, 320]:
// every coordinate a normal double within the input bound 1e100) the image of a point and of a
// surface point (partials, normal) is 2^k times the image at scale 1, to
// kInvolutionTol. |Y|^2 underflows below 2^-537, so this fails for any
// inversion that squares |X - m|.
RC_GTEST_PROP(DarbouxProperties, InversionCommutesWithScaling, ()) {
  const int k = *rc::gen::inRange(-1000, 321);
  const double s = std::ldexp(1.0, k);
  const Inversion inv{*point(), 0.25 + std::abs(*coord())};
  SurfacePoint p;
  p.x = *point();
  RC_PRE((p.x - inv.m).norm() > 0.25);
  p.du = *point();
  p.dv = *point();
  p.normal = Vec3d(*coord(), *coord(), 1).normalized();
  SurfacePoint q, qs;
  RC_ASSERT(invert_surface_point(inv, p, true, true, true, q) == Status::ok);
  const Inversion inv_s{s * inv.m, s * inv.rho};
  SurfacePoint ps = p;
  ps.x *= s;
  ps.du *= s;
  ps.dv *= s;
  RC_ASSERT(invert_surface_point(inv_s, ps, true, true, true, qs) == Status::ok);
  RC_ASSERT((qs.x / s - q.x).norm() <= kInvolutionTol * q.x.norm());
  RC_ASSERT((qs.du / s - q.du).norm() <= kInvolutionTol * q.du.norm());
  RC_ASSERT((qs.dv / s - q.dv).norm() <= kInvolutionTol * q.dv.norm());
  RC_ASSERT((qs.normal - q.normal).norm() <= kInvolutionTol);
  Vec3d X;
  RC_ASSERT(invert_point(inv_s, ps.x, X) == Status::ok);
  RC_ASSERT(X == qs.x);
}

// AT_INVERSION_CENTER exactly at the center: with rho = 2^-300, a point
// 2^-600 from m = 0 (|Y|^2 = 2^-1200 underflows to 0) has its image at
// distance 1, and one a denormal away has an image past the bound 1e100.
TEST(DarbouxInversion, AtTheCenterOnlyAtTheCenter) {
  const Inversion inv{Vec3d::Zero(), std::ldexp(1.0, -300)};
  Vec3d Y;
  EXPECT_EQ(invert_point(inv, Vec3d(0.0, -0.0, 0.0), Y), Status::at_inversion_center);
  EXPECT_EQ(invert_point(inv, Vec3d(std::ldexp(1.0, -600), 0, 0), Y), Status::ok);
  EXPECT_EQ(Y, Vec3d(1, 0, 0));
  EXPECT_EQ(invert_point(inv, Vec3d(0, 4.9e-324, 0), Y), Status::numerical_overflow);
}

RC_GTEST_PROP(DarbouxProperties, InversionMapsCyclidePointsToTheInvertedCyclide, ()) {
  const ThreeLines T = *three_lines();
  DcmcFamily F;
  RC_PRE(dcmc(T.L, F) == Status::ok);
  const Darboux D = F.member(*coord());
  const Inversion inv{*point(), 0.5 + std::abs(*coord())};
  Darboux R;
  RC_ASSERT(invert_darboux(inv, D, R) == Status::ok);
  for (const Line& L : T.L)
    for (double t : {-1.0, 0.5, 2.0}) {
      const Vec3d X = L.P + t * L.d;
      RC_PRE((X - inv.m).norm() > 0.25);
      Vec3d Y;
      RC_ASSERT(invert_point(inv, X, Y) == Status::ok);
      RC_ASSERT(on_surface(R, Y));
    }
}

RC_GTEST_PROP(DarbouxProperties, SpheresAndCirclesMapToSpheresAndCircles, ()) {
  const Inversion inv{*point(), 0.5 + std::abs(*coord())};
  const Vec3d c = *point(), n0 = *point();
  RC_PRE(n0.norm() > 0.25);
  const double r = 0.25 + std::abs(*coord());
  // Sphere |X - c|^2 = r^2 and its points.
  const GeneralSphere S{1, -2 * c, c.squaredNorm() - r * r};
  GeneralSphere S2;
  RC_ASSERT(invert_sphere(inv, S, S2) == Status::ok);
  const Vec3d n = n0.normalized(), e1 = n.unitOrthogonal(), e2 = n.cross(e1);
  CircleOrLine C{false, c, n, r}, C2;
  RC_ASSERT(invert_circle(inv, C, C2) == Status::ok);
  for (int k = 0; k < 5; ++k) {
    const double t = 1.2566370614359172 * k;
    const Vec3d X = c + r * (std::cos(t) * e1 + std::sin(t) * e2);
    RC_PRE((X - inv.m).norm() > 0.25);
    Vec3d Y;
    RC_ASSERT(invert_point(inv, X, Y) == Status::ok);
    const double scale = 1 + Y.norm();
    const double gs = (2 * S2.A * Y + S2.B).norm();
    RC_ASSERT(std::abs(S2.A * Y.squaredNorm() + S2.B.dot(Y) + S2.C) <= 1e-9 * gs * scale);
    // On the image circle (or line).
    if (C2.is_line) {
      const Vec3d w = Y - C2.point;
      RC_ASSERT((w - w.dot(C2.axis) * C2.axis).norm() <= 1e-9 * scale);
    } else {
      const Vec3d w = Y - C2.point;
      RC_ASSERT(std::abs(w.dot(C2.axis)) <= 1e-9 * scale);
      RC_ASSERT(std::abs(w.norm() - C2.radius) <= 1e-9 * (scale + C2.radius));
    }
  }
}

// A line maps to a circle through m (closed form: center m - rho^2 h /
// (2 |h|^2), h = m minus its foot on the line), or to itself through m.
RC_GTEST_PROP(DarbouxProperties, LinesMapToCirclesThroughTheCenter, ()) {
  const Inversion inv{*point(), 0.5 + std::abs(*coord())};
  const Vec3d p = *point(), d0 = *point();
  RC_PRE(d0.norm() > 0.25);
  const Vec3d d = d0.normalized();
  const Vec3d w = inv.m - p, h = w - w.dot(d) * d;
  RC_PRE(h.norm() > 0.05);
  CircleOrLine L{true, p, d, 0}, C;
  RC_ASSERT(invert_circle(inv, L, C) == Status::ok);
  RC_ASSERT(!C.is_line);
  RC_ASSERT(std::abs((inv.m - C.point).norm() - C.radius) <= 1e-12 * (C.radius + inv.m.norm()));
  for (double s : {-3.0, -0.5, 0.7, 2.0}) {
    const Vec3d X = p + s * d;
    RC_PRE((X - inv.m).norm() > 0.25);
    Vec3d Y;
    RC_ASSERT(invert_point(inv, X, Y) == Status::ok);
    const Vec3d v = Y - C.point;
    const double scale = 1 + Y.norm() + C.radius;
    RC_ASSERT(std::abs(v.dot(C.axis)) <= 1e-9 * scale);
    RC_ASSERT(std::abs(v.norm() - C.radius) <= 1e-9 * scale);
  }
  // The same line moved through m maps to itself.
  const CircleOrLine T{true, inv.m + 0.37 * d, d, 0};
  RC_ASSERT(invert_circle(inv, T, C) == Status::ok);
  RC_ASSERT(C.is_line);
  RC_ASSERT(std::abs(std::abs(C.axis.dot(d)) - 1) <= 1e-12);
}

}  // namespace
