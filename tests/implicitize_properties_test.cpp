// RapidCheck properties of the implicitization fit and of the closed-form
// classification (labels "darboux" and "property"). Inputs: dyadic
// coordinates in [-2, 2]; lines at least ~10 degrees apart and skew by a
// margin; similarities with a random rotation, scale in [1/4, 4] and a
// translation in [-2, 2]^3. Tolerances are named here (SPEC.md §12b).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "cyclide/darboux_classify.hpp"
#include "cyclide/implicitize.hpp"
#include "cyclide/surface.hpp"

using namespace cyclide;

namespace {

// The fit agrees with a closed form: max |A - t B| / max |A| (t matching
// the largest coefficient).
constexpr double kAgreeTol = 1e-7;
// A ringed surface of three generic cubics is no Darboux cyclide: its
// residual stays above this (SPEC: kDarbouxFitTol = 1e-9 decides).
constexpr double kNotDarboux = 1e-6;
// Normal-form numbers (a, b, c) agree after a similarity.
constexpr double kInvariantTol = 1e-9;

double dyadic(int n) { return double(n) / 64.0; }
// Uniform at every size (inRange scales its spread with the size, which
// would put the first cases at (-2, -2, -2), all parallel and coplanar).
rc::Gen<int> uniform(int lo, int hi) { return rc::gen::resize(100, rc::gen::inRange(lo, hi)); }
rc::Gen<double> coord() { return rc::gen::map(uniform(-128, 129), dyadic); }
rc::Gen<Vec3d> point() {
  return rc::gen::apply([](double x, double y, double z) { return Vec3d(x, y, z); }, coord(),
                        coord(), coord());
}

// A direction of length >= 1/4.
Vec3d direction() {
  const Vec3d d = *point();
  RC_PRE(d.norm() >= 0.25);
  return d;
}

rc::Gen<Similarity> similarity() {
  return rc::gen::exec([] {
    const Vec3d q = *point();
    const double w = *coord();
    RC_PRE(q.squaredNorm() + w * w > 0.01);
    Similarity T;
    T.R = Eigen::Quaterniond(w, q.x(), q.y(), q.z()).normalized().toRotationMatrix();
    T.scale = std::pow(2.0, *uniform(-2, 3)) * (1 + std::abs(*coord()) / 4);
    T.origin = *point();
    return T;
  });
}

RationalCurve line(const Vec3d& P, const Vec3d& d) {
  RationalCurve c;
  RC_ASSERT(make_line(P, d, c) == Status::ok);
  return c;
}

double up_to_scale(const Darboux& A, const Darboux& B) {
  int i = 0;
  for (int j = 0; j < kDarbouxCoeffs; ++j)
    if (std::abs(A.k[j]) > std::abs(A.k[i])) i = j;
  const double t = A.k[i] / B.k[i];
  double r = 0;
  for (int j = 0; j < kDarbouxCoeffs; ++j) r = std::max(r, std::abs(A.k[j] - t * B.k[j]));
  return r / std::abs(A.k[i]);
}

// Skew lines: angle >= ~10 degrees, distance between them >= 1/8.
void require_skew(const Vec3d& P1, const Vec3d& v, const Vec3d& P2, const Vec3d& w) {
  const Vec3d n = v.cross(w);
  RC_PRE(n.norm() >= 0.17 * v.norm() * w.norm());
  RC_PRE(std::abs((P2 - P1).dot(n)) >= 0.125 * n.norm());
}

// The circle-family surface fits the Darboux cyclide: residual, nullity 1.
void assert_fits(const Surface& S) {
  DarbouxFit F;
  RC_ASSERT(fit_darboux(S, F) == Status::ok);
  RC_LOG() << "residual " << F.residual << " nullity " << F.nullity << "\n";
  RC_ASSERT(F.residual <= kDarbouxFitTol);
  RC_ASSERT(F.is_darboux);
  RC_ASSERT(F.nullity == 1);
}

}  // namespace

RC_GTEST_PROP(ImplicitizeProperties, PrcsOfTwoSkewLinesIsADarbouxCyclide, ()) {
  const Vec3d P1 = *point(), v = direction(), P2 = *point(), w = direction();
  require_skew(P1, v, P2, w);
  Surface S;
  RC_PRE(make_prcs(line(P1, v), line(P2, w), nullptr, -1, 1, S) == Status::ok);
  assert_fits(S);
}

RC_GTEST_PROP(ImplicitizeProperties, PrrsOfALineAndTwoPointsIsADarbouxCyclide, ()) {
  const Vec3d P1 = *point(), v = direction(), P2 = *point(), P3 = *point();
  // Points off the line's plane by a margin: |(P2 - P1) x v . (P3 - P1)|.
  const Vec3d n = (P2 - P1).cross(v);
  RC_PRE(n.norm() >= 0.125 * v.norm());
  RC_PRE(std::abs(n.normalized().dot(P3 - P1)) >= 0.125);
  RationalCurve p2, p3;
  RC_ASSERT(make_point(P2, p2) == Status::ok);
  RC_ASSERT(make_point(P3, p3) == Status::ok);
  Surface S;
  RC_PRE(make_prrs(line(P1, v), p2, p3, nullptr, -1, 1, S) == Status::ok);
  assert_fits(S);
  LinesClassification C;
  RC_ASSERT(classify_line_two_points(P1, v, P2, P3, C) == Status::ok);
}

RC_GTEST_PROP(ImplicitizeProperties, LineElementFitAgreesWithClosedFormEq70, ()) {
  const Vec3d P1 = *point(), v = direction(), P2 = *point(), w = direction();
  const Vec3d d = (P2 - P1) - (P2 - P1).dot(v) / v.squaredNorm() * v;  // P2 off l1
  RC_PRE(d.norm() >= 0.125);
  RC_PRE(std::abs(w.dot(d.cross(v).normalized())) >= 0.17 * w.norm());  // w off the plane
  RationalCurve le;
  RC_ASSERT(make_line_element(P2, w, le) == Status::ok);
  Surface S;
  RC_PRE(make_prcs(line(P1, v), le, nullptr, -1, 1, S) == Status::ok);
  LinesClassification C;
  RC_ASSERT(classify_line_element(P1, v, P2, w, C) == Status::ok);
  Darboux N, G;
  RC_ASSERT(line_element_cyclide(C.nf, N, G) == Status::ok);
  DarbouxFit F;
  RC_ASSERT(fit_darboux(S, F) == Status::ok);
  RC_ASSERT(F.is_darboux);
  RC_LOG() << "agreement " << up_to_scale(F.D, G) << "\n";
  RC_ASSERT(up_to_scale(F.D, G) <= kAgreeTol);
}

RC_GTEST_PROP(ImplicitizeProperties, ThreeGenericCubicsAreNotADarbouxCyclide, ()) {
  RationalCurve p[3];
  for (auto& c : p) {
    double xyz[12];
    for (double& x : xyz) x = *coord();
    // Cubic terms of size >= 1/2 keep the curves away from lines and conics.
    const Vec3d c3 = *point();
    RC_PRE(c3.norm() >= 0.5);
    for (int j = 0; j < 3; ++j) xyz[9 + j] = c3[j];
    RC_ASSERT(make_polynomial_curve(3, xyz, c) == Status::ok);
  }
  Surface S;
  RC_PRE(make_prrs(p[0], p[1], p[2], nullptr, -1, 1, S) == Status::ok);
  DarbouxFit F;
  RC_ASSERT(fit_darboux(S, F) == Status::ok);
  RC_LOG() << "residual " << F.residual << "\n";
  RC_ASSERT(!F.is_darboux);
  RC_ASSERT(F.residual >= kNotDarboux);
}

// A normal form of each case of Prop. 2, moved by a similarity and
// reparameterized: the classification finds the case and the invariants
// (a, w.w); exchanging the lines does not change the kind.
RC_GTEST_PROP(ImplicitizeProperties, TwoLinesClassificationIsSimilarityInvariant, ()) {
  const int kase = *uniform(0, 4);
  const double t = dyadic(*uniform(1, 128));  // (0, 2)
  const double phi = *coord();
  Vec3d w;
  CyclideKind kind = CyclideKind::parabolic_darboux;
  switch (kase) {
    case 0:  // w.w = 1, b != 0
      w = Vec3d(std::cos(phi), std::sin(phi) * std::cos(t), std::sin(phi) * std::sin(t));
      RC_PRE(std::abs(w.y()) >= 0.1);
      kind = CyclideKind::hyperboloid;
      break;
    case 1:  // (I) a = 1
      w = Vec3d(1, t - 1 - 1.0 / 64, phi);
      kind = CyclideKind::parabolic_dupin;
      break;
    case 2:  // (I) c = 0, a = w.w: (a - 1/2)^2 + b^2 = 1/4
      w = Vec3d(0.5 + 0.5 * std::cos(phi), 0.5 * std::sin(phi), 0);
      RC_PRE(std::abs(w.y()) >= 0.05);
      kind = CyclideKind::parabolic_dupin;
      break;
    default:
      w = *point();
      RC_PRE(std::abs(w.y()) >= 0.1 && std::abs(w.squaredNorm() - 1) >= 1e-3 &&
             std::abs(w.x() - 1) >= 1e-3 &&
             (std::abs(w.z()) >= 1e-3 || std::abs(w.x() - w.squaredNorm()) >= 1e-3));
  }
  RC_PRE(std::abs(w.y()) > 0);
  const Similarity M = *similarity();
  const double al = std::pow(2.0, *uniform(-2, 3)), be = *coord();
  // Input u = al u' + be: l1(u) = M^-1((u - be)/al e1), l2 = M^-1(e3 + (u - be)/al w).
  const Vec3d v = M.R.transpose() * Vec3d(1, 0, 0) / (M.scale * al);
  const Vec3d P1 = M.inverse(-(be / al) * Vec3d(1, 0, 0));
  const Vec3d wi = M.R.transpose() * w / (M.scale * al);
  const Vec3d P2 = M.inverse(Vec3d(0, 0, 1) - (be / al) * w);
  LinesClassification C, D;
  RC_ASSERT(classify_two_lines(P1, v, P2, wi, C) == Status::ok);
  RC_ASSERT(C.kind == kind);
  RC_ASSERT(std::abs(C.nf.a - w.x()) <= kInvariantTol * (1 + std::abs(w.x())) || C.nf.swapped);
  RC_ASSERT(classify_two_lines(P2, wi, P1, v, D) == Status::ok);
  RC_ASSERT(D.kind == kind);
  RC_ASSERT(D.circle_families == C.circle_families && D.pn == C.pn);
}

RC_GTEST_PROP(ImplicitizeProperties, LineElementAndPointsClassificationIsSimilarityInvariant,
              ()) {
  const bool dupin = *rc::gen::arbitrary<bool>();
  const double t = *coord();
  // Prop. 8: w = (a, 1, c); Prop. 9: P3 = (a, b, c).
  const Vec3d w = dupin ? Vec3d(0, 1, 0) : Vec3d(*coord(), 1, *coord());
  const Vec3d P3 = dupin ? Vec3d(0, std::cos(t), std::sin(t)) : *point();
  RC_PRE(std::abs(P3.y()) >= 0.1);
  const bool dupin9 =
      dupin || (P3.x() == 0 && std::abs(P3.tail<2>().squaredNorm() - 1) <= 1e-12);
  const bool dupin8 = dupin || (w.x() == 0 && w.z() == 0);
  const Similarity M = *similarity();
  const double al = std::pow(2.0, *uniform(-2, 3)), be = *coord();
  const Vec3d v = M.R.transpose() * Vec3d(1, 0, 0) / (M.scale * al);
  const Vec3d P1 = M.inverse(-(be / al) * Vec3d(1, 0, 0));
  const Vec3d P2 = M.inverse(Vec3d(0, 0, 1));
  LinesClassification C8, C9;
  RC_ASSERT(classify_line_element(P1, v, P2, -2 * (M.R.transpose() * w), C8) == Status::ok);
  RC_ASSERT((C8.kind == CyclideKind::parabolic_dupin) == dupin8);
  RC_ASSERT(std::abs(C8.nf.a - w.x()) <= kInvariantTol * (1 + w.norm()));
  RC_ASSERT(std::abs(C8.nf.c - w.z()) <= kInvariantTol * (1 + w.norm()));
  RC_ASSERT(std::abs(C8.nf.beta - be) <= kInvariantTol * (1 + std::abs(be)));
  RC_ASSERT(std::abs(C8.nf.alpha - al) <= kInvariantTol * al);
  RC_ASSERT(classify_line_two_points(P1, v, P2, M.inverse(P3), C9) == Status::ok);
  RC_ASSERT((C9.kind == CyclideKind::parabolic_dupin) == dupin9);
  RC_ASSERT((Vec3d(C9.nf.a, C9.nf.b, C9.nf.c) - P3).norm() <= kInvariantTol * (1 + P3.norm()));
  RC_ASSERT(C9.circle_families == (dupin9 ? 2 : 3));
}
