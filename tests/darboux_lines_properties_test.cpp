// RapidCheck properties of the line and circle-family analysis of parabolic
// Darboux cyclides and of Props. 2, 3, 5 (labels "darboux" and "property").
// Random well-conditioned inputs: three lines in planes at least 0.25
// apart, directions 10..160 degrees apart, dyadic coordinates in [-2, 2],
// then a random rotation. Tolerances are relative (SPEC.md §8c).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "cyclide/darboux_classify.hpp"
#include "cyclide/darboux_lines.hpp"
#include "cyclide/implicitize.hpp"

using namespace cyclide;

namespace {

// |F(X)| <= kOnSurfaceTol (|grad F(X)| r + 1e-6 scale(F) r^3), r = 1 + |X|:
// X within ~1e-8 r of F away from singular points.
constexpr double kOnSurfaceTol = 1e-8;

double dyadic(int n) { return double(n) / 64.0; }
rc::Gen<double> coord() { return rc::gen::map(rc::gen::inRange(-128, 129), dyadic); }

Eigen::Matrix3d random_rotation() {
  const Vec3d axis(*coord(), *coord(), *coord());
  const double angle = *rc::gen::inRange(0, 360) * M_PI / 180;
  if (axis.norm() < 0.1) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

struct Frame {
  Eigen::Matrix3d R;
  Line L[3];
};

// Three lines l_i(u) = P_i + u d_i in the planes z = h_i, rotated by R.
Frame three_skew_lines() {
  Frame F;
  F.R = random_rotation();
  const double a0 = *rc::gen::inRange(0, 180), s1 = *rc::gen::inRange(10, 81),
               s2 = *rc::gen::inRange(10, 81);
  const double angles[3] = {a0, a0 + s1, a0 + s1 + s2};
  const double h0 = *coord(), g1 = 0.25 + std::abs(*coord()), g2 = 0.25 + std::abs(*coord());
  const double h[3] = {h0, h0 + g1, h0 - g2};
  for (int i = 0; i < 3; ++i) {
    const double a = angles[i] * M_PI / 180.0;
    F.L[i].P = F.R * Vec3d(*coord(), *coord(), h[i]);
    F.L[i].d = F.R * Vec3d(std::cos(a), std::sin(a), 0);
  }
  return F;
}

// Diagnostics for a failing case.
void dump(const Darboux& D, const ParabolicLines& A) {
  std::printf("F:");
  for (double v : D.k) std::printf(" %.17g", v);
  std::printf("\n");
  for (int i = 0; i < A.line_count; ++i) {
    const Line& L = A.lines[i].line;
    std::printf(" line P=(%g %g %g) d=(%g %g %g) t=%.17g m=%d\n", L.P.x(), L.P.y(), L.P.z(),
                L.d.x(), L.d.y(), L.d.z(), A.lines[i].t, A.lines[i].multiplicity);
  }
  for (int i = 0; i < A.plane_count; ++i)
    std::printf(" plane t=%.17g kind %d\n", A.planes[i].t, int(A.planes[i].kind));
}

// (The floor keeps singular points, where grad F = 0, from failing.)
bool on_surface(const Darboux& D, const Vec3d& X) {
  const double r = 1 + X.norm();
  return std::abs(D.value(X)) <=
         kOnSurfaceTol * (D.gradient(X).norm() * r + 1e-6 * D.scale() * r * r * r);
}

// How close the conic of the plane n.X = t is to a double line: its middle
// |eigenvalue| over the largest (the conic fitted from six values of F,
// exact: F restricted to a plane of the pencil is quadratic).
double conic_rank1_ratio(const Darboux& D, const Vec3d& n, double t) {
  const Vec3d e1 = n.unitOrthogonal(), e2 = n.cross(e1);
  auto f = [&](double x, double y) { return D.value(t * n + x * e1 + y * e2); };
  const double c = f(0, 0), ax = 0.5 * (f(1, 0) + f(-1, 0)) - c,
               ay = 0.5 * (f(0, 1) + f(0, -1)) - c, bx = 0.5 * (f(1, 0) - f(-1, 0)),
               by = 0.5 * (f(0, 1) - f(0, -1)), axy = f(1, 1) - ax - ay - bx - by - c;
  Eigen::Matrix3d M;
  M << ax, axy / 2, bx / 2, axy / 2, ay, by / 2, bx / 2, by / 2, c;
  Eigen::Vector3d mu = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(M).eigenvalues().cwiseAbs();
  std::sort(mu.data(), mu.data() + 3);
  return mu[2] > 0 ? mu[1] / mu[2] : 0.0;
}

int find_line(const ParabolicLines& A, const Line& L) {
  const Vec3d d = L.d.normalized();
  for (int i = 0; i < A.line_count; ++i) {
    const Line& F = A.lines[i].line;
    if (F.d.cross(d).norm() > 1e-6) continue;
    const Vec3d w = L.P - F.P;
    if ((w - w.dot(F.d) * F.d).norm() <= 1e-6 * (1 + L.P.norm())) return i;
  }
  return -1;
}

Darboux normalized(Darboux D) {
  const double s = D.scale();
  for (double& v : D.k) v /= s;
  return D;
}

// Every found line lies on F; every plane through a line cuts a circle on F.
void check_lines_and_circles(const Darboux& D, const ParabolicLines& A) {
  RC_ASSERT(A.line_count <= 6);  // at most six real lines (six circle families)
  for (int i = 0; i < A.line_count; ++i) {
    const Line& L = A.lines[i].line;
    for (double s : {-1.5, 0.0, 2.0}) {
      if (!on_surface(D, L.P + s * L.d)) dump(D, A);
      RC_ASSERT(on_surface(D, L.P + s * L.d));
    }
    const double th = *rc::gen::inRange(5, 175) * M_PI / 180;
    const Vec3d k = A.n.cross(L.d);
    CircleOrLine c;
    const Status st = pencil_circle(D, L, std::cos(th) * A.n + std::sin(th) * k, c);
    if (st == Status::empty_real_locus) continue;
    RC_ASSERT(st == Status::ok);
    RC_ASSERT(!c.is_line);
    const Vec3d e1 = c.axis.unitOrthogonal(), e2 = c.axis.cross(e1);
    for (double a = 0; a < 6.2; a += 1.1)
      RC_ASSERT(on_surface(D, c.point + c.radius * (std::cos(a) * e1 + std::sin(a) * e2)));
  }
}

// The points of a surface lie on F: at the ends and the middle of the
// domain, and at random u (a base point between the domain samples, where
// two input lines meet, shows there and not at the samples).
void check_surface_on(const Darboux& D, const Surface& S) {
  std::vector<double> us = {S.u0, 0.5 * (S.u0 + S.u1), S.u1};
  for (int i = 0; i < 4; ++i)
    us.push_back(S.u0 + (S.u1 - S.u0) * *rc::gen::inRange(0, 1000001) / 1e6);
  for (double u : us)
    for (double v : {-3.0, -0.4, 0.0, 0.7, 5.0}) {
      double x[3];
      EvalOut o;
      o.point = x;
      if (S.eval(u, v, o) != Status::ok) continue;
      RC_ASSERT(on_surface(D, {x[0], x[1], x[2]}));
    }
}

}  // namespace

// DCMC members contain their three lines, and the analysis finds them.
RC_GTEST_PROP(DarbouxLinesProperties, DcmcLinesAreFoundAndCarryCircles, ()) {
  const Frame F = *rc::gen::exec(three_skew_lines);
  DcmcFamily fam;
  RC_PRE(dcmc(F.L, fam) == Status::ok);
  const Darboux D = normalized(fam.member(*coord()));
  RC_PRE(darboux_type(D) == DarbouxType::parabolic);
  ParabolicLines A;
  RC_ASSERT(parabolic_lines(D, A) == Status::ok);
  for (const Line& L : F.L) {
    if (find_line(A, L) < 0) dump(D, A);
    RC_ASSERT(find_line(A, L) >= 0);
  }
  check_lines_and_circles(D, A);
  RC_ASSERT(A.circle_families() == A.line_count + (A.l0_circles ? 1 : 0));
  // Prop. 5: PRRS from the pencil through one of the lines gives F again.
  Surface S;
  const Status st = parameterize_parabolic_prrs(D, -1, 1, S);
  if (st == Status::ok) check_surface_on(D, S);
  else RC_ASSERT(st == Status::collinear_points || st == Status::dependent_planes);
}

// Prop. 2 / §7 in general: PRCS(l1, l2) lies on the DCMC member through
// l1, l2 and l3 = lambda l1 + (1 - lambda) l2 (41), lambda = w.w/(w.w - 1)
// (42) in the normal form, for which l3 is a double line; Prop. 3 then
// reparameterizes it by PRCS from the pencil through l3.
RC_GTEST_PROP(DarbouxLinesProperties, Prop2PrcsOfTwoLinesIsACanalCyclideWithDoubleLineL3, ()) {
  const Eigen::Matrix3d R = random_rotation();
  const Vec3d w(*coord(), *coord(), *coord());
  RC_PRE(std::abs(w.y()) >= 0.25);                               // skew
  RC_PRE(std::abs(w.squaredNorm() - 1) >= 0.25);                // not a hyperboloid
  RC_PRE(std::abs(w.x() - 1) >= 0.1);                           // case (II)
  const Vec3d o(*coord(), *coord(), *coord());
  const double lambda = w.squaredNorm() / (w.squaredNorm() - 1);
  // (45): l1 = u e1, l2 = e3 + u w; moved by X -> o + R X.
  const Line l1{o, R * Vec3d(1, 0, 0)}, l2{o + R * Vec3d(0, 0, 1), R * w};
  const Line l3{o + (1 - lambda) * R * Vec3d(0, 0, 1), R * (lambda * Vec3d(1, 0, 0) + (1 - lambda) * w)};
  const Line three[3] = {l1, l2, l3};
  DcmcFamily fam;
  RC_ASSERT(dcmc(three, fam) == Status::ok);
  // The member for which l3 is a double line: grad F . e = 0 along l3, e in
  // its plane orthogonal to it (linear in alpha, least squares).
  const Vec3d e = fam.n.cross(l3.d).normalized();
  double bq = 0, qq = 0;
  for (double s : {-1.0, 0.0, 1.0}) {
    const Vec3d X = l3.P + s * l3.d;
    const double gb = fam.base.gradient(X).dot(e), gq = fam.quadric.gradient(X).dot(e);
    bq += gb * gq;
    qq += gq * gq;
  }
  const Darboux D = normalized(fam.member(-bq / qq));
  RC_ASSERT(darboux_type(D) == DarbouxType::parabolic);
  RationalCurve c1, c2;
  RC_ASSERT(make_line(l1.P, l1.d, c1) == Status::ok);
  RC_ASSERT(make_line(l2.P, l2.d, c2) == Status::ok);
  Surface S;
  RC_PRE(make_prcs(c1, c2, nullptr, -0.5, 0.5, S) == Status::ok);
  check_surface_on(D, S);
  // The analysis: l3 double, and five lines (Prop. 2 (II)).
  ParabolicLines A;
  RC_ASSERT(parabolic_lines(D, A) == Status::ok);
  // Special w make two of the four other lines (nearly) coincide: a plane
  // whose conic is within 1e-3 of a double line sits on the boundary between
  // a real and an imaginary pair, where rounding decides (RC found an
  // imaginary pair with eigenvalues -3.7e-6 and -0.83: three families, not
  // five). Such inputs are not well-conditioned for the count.
  for (int i = 0; i < A.plane_count; ++i)
    if (A.planes[i].kind != SectionKind::double_line)
      RC_PRE(conic_rank1_ratio(D, A.n, A.planes[i].t) > 1e-3);
  const int i3 = find_line(A, l3);
  if (i3 < 0 || A.lines[i3].multiplicity != 2 || A.circle_families() != 5) dump(D, A);
  RC_ASSERT(i3 >= 0);
  RC_ASSERT(A.lines[i3].multiplicity == 2);
  RC_ASSERT(A.circle_families() == 5);
  RC_ASSERT(A.double_families() == 1);
  check_lines_and_circles(D, A);
  // Prop. 3.
  Surface T;
  const Status st = parameterize_parabolic_prcs(D, -1, 1, T);
  if (st == Status::ok) check_surface_on(D, T);
  else RC_ASSERT(st == Status::dependent_planes || st == Status::zero_tangent);
}

// The closed-form classification (Props. 8, 9) and the line analysis agree
// on the circle families: App. A through its implicit equation (70) pulled
// back to the input, App. B through the fitted equation of the PRRS output.
RC_GTEST_PROP(DarbouxLinesProperties, CircleCountsAgreeWithProps8And9, ()) {
  const Eigen::Matrix3d R = random_rotation();
  const Vec3d o(*coord(), *coord(), *coord());
  const double s = 0.5 + std::abs(*coord());
  // Normal forms (67)/(68) and (77), moved by X -> o + s R X.
  const bool dupin = *rc::gen::inRange(0, 4) == 0;
  const double a = dupin ? 0 : *coord(), c = dupin ? 0 : *coord();
  RC_PRE(dupin || std::abs(a) + std::abs(c) >= 0.125);
  const Vec3d P1 = o, v = s * (R * Vec3d(1, 0, 0)), P2 = o + s * (R * Vec3d(0, 0, 1));
  LinesClassification C;
  RC_ASSERT(classify_line_element(P1, v, P2, R * Vec3d(a, 1, c), C) == Status::ok);
  Darboux N, D;
  RC_ASSERT(line_element_cyclide(C.nf, N, D) == Status::ok);
  ParabolicLines A;
  RC_ASSERT(parabolic_lines(D, A) == Status::ok);
  if (A.circle_families() != C.circle_families || A.double_families() != C.double_families)
    dump(D, A);
  RC_ASSERT(A.circle_families() == C.circle_families);
  RC_ASSERT(A.double_families() == C.double_families);
  check_lines_and_circles(D, A);

  // Prop. 9 (P3 = (a, b, c), b != 0; Dupin for a = 0, b^2 + c^2 = 1).
  const double th = *rc::gen::inRange(10, 170) * M_PI / 180;
  const Vec3d P3n = dupin ? Vec3d(0, std::sin(th), std::cos(th))
                          : Vec3d(*coord(), 0.25 + std::abs(*coord()), *coord());
  const Vec3d P3 = o + s * (R * P3n);
  RC_ASSERT(classify_line_two_points(P1, v, P2, P3, C) == Status::ok);
  RationalCurve l1, p2, p3;
  RC_ASSERT(make_line(P1, v, l1) == Status::ok);
  RC_ASSERT(make_point(P2, p2) == Status::ok);
  RC_ASSERT(make_point(P3, p3) == Status::ok);
  Surface S;
  RC_PRE(make_prrs(l1, p2, p3, nullptr, -2, 2, S) == Status::ok);
  DarbouxFit F;
  RC_ASSERT(fit_darboux(S, F) == Status::ok);
  RC_ASSERT(F.is_darboux);
  RC_ASSERT(parabolic_lines(F.D, A) == Status::ok);
  if (A.circle_families() != C.circle_families || A.double_families() != C.double_families)
    dump(F.D, A);
  RC_ASSERT(A.circle_families() == C.circle_families);
  RC_ASSERT(A.double_families() == C.double_families);
}
