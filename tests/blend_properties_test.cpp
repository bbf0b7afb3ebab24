// RapidCheck properties of blends (labels "property;blend"): over random
// pairs of surfaces (PRRS of three random lines, PRCS of two random lines,
// the second moved apart), a blend either is built and joins both end
// circles (gap), C^K in the circle family (ringed, Prop. 7) or G^1 (canal,
// Prop. 6), or is refused with one of the documented degenerate statuses.
// Tolerances are relative; cases whose continuity report shows a badly
// conditioned join (huge derivative scales) are discarded with RC_PRE.

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <utility>

#include "cyclide/blend.hpp"

using namespace cyclide;

namespace {

constexpr double kGapTol = 1e-8;      // relative to the point scale
constexpr double kAngleTol = 1e-5;    // radians (near-singular ringed points)
constexpr double kCircleTol = 1e-5;   // relative circle-family jumps

double dyadic() { return *rc::gen::inRange(-64, 65) / 32.0; }
Vec3d dyadic3() { return Vec3d(dyadic(), dyadic(), dyadic()); }

bool degenerate(Status s) {
  return s == Status::dependent_planes || s == Status::zero_tangent ||
         s == Status::collinear_points || s == Status::singular_point ||
         s == Status::numerical_overflow || s == Status::degenerate_circle_parameter;
}

// PRRS of three random lines, or PRCS of two; shifted by `offset`.
bool random_surface(bool canal, const Vec3d& offset, Surface& S) {
  RationalCurve L[3];
  for (int k = 0; k < (canal ? 2 : 3); ++k) {
    Vec3d d = dyadic3();
    if (d.norm() < 0.25) return false;
    if (make_line(dyadic3() + offset, d, L[k]) != Status::ok) return false;
  }
  const Status st = canal ? make_prcs(L[0], L[1], nullptr, 0.0, 1.0, S)
                          : make_prrs(L[0], L[1], L[2], nullptr, 0.0, 1.0, S);
  return st == Status::ok;
}

// count circle parameters spread over the circle: atan(v_j) = phi0 +
// j pi/count + a jitter of up to 0.2, wrapped into (-pi/2, pi/2]; the
// first one is the generator v = inf one time in nine.
void random_vs(double* v, int count) {
  const double pi = std::acos(-1.0);
  const double phi0 = *rc::gen::inRange(-157, 158) / 100.0;
  for (int j = 0; j < count; ++j) {
    double phi = phi0 + j * pi / count + *rc::gen::inRange(-20, 21) / 100.0;
    while (phi > pi / 2) phi -= pi;
    while (phi <= -pi / 2) phi += pi;
    v[j] = std::abs(phi - pi / 2) < 1e-9 ? HUGE_VAL : std::tan(phi);
  }
  if (*rc::gen::inRange(0, 9) == 0) v[0] = HUGE_VAL;
}

void check_join(const Surface& In, double u, double lambda, const Surface& X, double t, int K,
                bool canal) {
  ContinuityReport R;
  const Status st = continuity_report(In, u, lambda, X, t, K, nullptr, 24, R);
  RC_PRE(st == Status::ok);
  // Badly conditioned joins (derivatives 1e6 times the geometry) are discarded.
  for (int l = 1; l <= K; ++l) RC_PRE(R.point_scale_l[l] <= 1e6 * std::max(1.0, R.point_scale));
  RC_ASSERT(R.max_gap <= kGapTol * R.point_scale);
  if (R.singular_samples == 0) RC_ASSERT(R.max_normal_angle <= kAngleTol);
  const int top = canal ? 0 : K;  // canal: circles match to order K-2 (K = 2: 0)
  for (int l = 0; l <= top; ++l) RC_ASSERT(R.circle_jump[l] <= kCircleTol);
}

// Are the chosen points of an end apart on their circle (at least a
// quarter of its radius)? The blends' circles come from bisector planes of
// the points (canal: of two, ringed: of three): for close points (e.g. v = tan(-1.44) and
// tan(-1.5), both near the generator) the circle of the join is
// ill-conditioned (radius^2 off by 1.4e-5 relative while the points agree
// to 1e-10: RC seed 7535241990548302642), which is not a well-conditioned
// input.
bool points_apart(const Surface& S, double u, const double* v, int count) {
  Vec3d c, n;
  double r2 = 0;
  if (S.circle(u, c, n, r2) != Status::ok || !(r2 > 0)) return false;
  Vec3d P[3];
  for (int j = 0; j < count; ++j) {
    double x[3];
    const double w = std::isfinite(v[j]) ? v[j] : 1e300;
    if (S.eval(u, w, {x, nullptr, nullptr, nullptr}) != Status::ok) return false;
    P[j] = Vec3d(x[0], x[1], x[2]);
  }
  for (int i = 0; i < count; ++i)
    for (int j = i + 1; j < count; ++j)
      if (!((P[i] - P[j]).norm() >= 0.25 * std::sqrt(r2))) return false;
  return true;
}

// Two random line-ringed surfaces (the second moved apart), the ends A(1)
// -> B(0) with three well-separated points each, and K in 1..3.
int random_ringed_join(Surface& A, Surface& B, BlendEnd& s, BlendEnd& e) {
  RC_PRE(random_surface(false, Vec3d(0, 0, 0), A));
  RC_PRE(random_surface(false, Vec3d(6, 1, 0), B));
  const int K = *rc::gen::inRange(1, 4);
  s.surface = &A;
  s.u = 1.0;
  e.surface = &B;
  e.u = 0.0;
  random_vs(s.v, 3);
  random_vs(e.v, 3);
  RC_PRE(points_apart(A, s.u, s.v, 3) && points_apart(B, e.u, e.v, 3));
  return K;
}

}  // namespace

RC_GTEST_PROP(BlendProperties, RingedBlendIsCKOrDegenerate, ()) {
  Surface A, B;
  BlendEnd s, e;
  const int K = random_ringed_join(A, B, s, e);
  Surface X;
  double bad = -1;
  const Status st = make_ringed_blend(s, e, K, 0.0, 1.0, X, &bad);
  if (st != Status::ok) {
    RC_ASSERT(degenerate(st));
    RC_TAG("degenerate");
    RC_SUCCEED("refused with a documented status");
  }
  check_join(A, 1.0, 1.0, X, 0.0, K, false);
  check_join(B, 0.0, 1.0, X, 1.0, K, false);
}

RC_GTEST_PROP(BlendProperties, CanalBlendIsG1OrDegenerate, ()) {
  Surface A, B;
  RC_PRE(random_surface(true, Vec3d(0, 0, 0), A));
  RC_PRE(random_surface(true, Vec3d(6, 1, 0), B));
  const int K = *rc::gen::inRange(2, 4);
  BlendEnd s, e;
  s.surface = &A;
  s.u = 1.0;
  e.surface = &B;
  e.u = 0.0;
  random_vs(s.v, 2);
  random_vs(e.v, 2);
  RC_PRE(points_apart(A, s.u, s.v, 2) && points_apart(B, e.u, e.v, 2));
  Surface X;
  double bad = -1;
  const Status st = make_canal_blend(s, e, K, 0.0, 1.0, X, &bad);
  if (st != Status::ok) {
    RC_ASSERT(degenerate(st));
    RC_ASSERT(bad >= 0.0 && bad <= 1.0);
    RC_TAG("degenerate");
    RC_SUCCEED("refused with a documented status");
  }
  check_join(A, 1.0, 1.0, X, 0.0, K, true);
  check_join(B, 0.0, 1.0, X, 1.0, K, true);
}

// BlendCircles::matched (Prop. 7 with the inputs' own f): where the
// generator blend exists, the matched one is either refused with
// degenerate_circle_parameter (the end maps' orientations differ, or the
// interpolated Mobius family degenerates inside) or continues both inputs'
// parameterizations to order K for every v, on the generator blend's circles.
RC_GTEST_PROP(BlendProperties, MatchedRingedBlendIsCKForEveryVOrRefused, ()) {
  Surface A, B;
  BlendEnd s, e;
  const int K = random_ringed_join(A, B, s, e);
  Surface G, M;
  RC_PRE(make_ringed_blend(s, e, K, 0.0, 1.0, G) == Status::ok);
  double bad = -1;
  const Status st = make_ringed_blend(s, e, K, 0.0, 1.0, M, &bad, nullptr, BlendCircles::matched);
  if (st != Status::ok) {
    RC_ASSERT(st == Status::degenerate_circle_parameter);
    RC_ASSERT(bad >= 0.0 && bad <= 1.0);
    RC_TAG("refused");
    RC_SUCCEED("refused with degenerate_circle_parameter");
  }
  for (const auto& J : {std::make_pair(&A, 0.0), std::make_pair(&B, 1.0)}) {
    const double u = J.second == 0.0 ? 1.0 : 0.0;
    ContinuityReport R;
    RC_PRE(continuity_report(*J.first, u, 1.0, M, J.second, K, nullptr, 24, R) == Status::ok);
    for (int l = 1; l <= K; ++l) RC_PRE(R.point_scale_l[l] <= 1e6 * std::max(1.0, R.point_scale));
    RC_ASSERT(R.max_gap <= kGapTol * R.point_scale);
    for (int l = 0; l <= K; ++l)
      RC_ASSERT(R.point_jump[l] <= kCircleTol * std::max(R.point_scale_l[l], R.point_scale));
  }
  const double t = *rc::gen::inRange(0, 101) / 100.0;
  const double v = std::tan(*rc::gen::inRange(-156, 157) / 100.0);
  double x[3];
  RC_ASSERT(M.eval(t, v, {x, nullptr, nullptr, nullptr}) == Status::ok);
  Vec3d c, n;
  double r2;
  RC_ASSERT(G.circle(t, c, n, r2) == Status::ok);
  const Vec3d X(x[0], x[1], x[2]);
  const double scale = c.norm() + std::sqrt(r2);
  RC_ASSERT(std::abs((X - c).norm() - std::sqrt(r2)) <= kGapTol * scale);
  RC_ASSERT(std::abs((X - c).dot(n)) <= kGapTol * scale);
}
