// Seed 002 properties over random valid inputs (labels
// "property;sphere_skin"; SPEC.md §8g): two spheres with touching circles
// whose axes point roughly from one to the other, random tangent lengths.
// Inputs the skin refuses (nested spheres, kappa r >= 1) are discarded.

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "cyclide/sphere_skin.hpp"

using namespace cyclide;

namespace {

// Uniform on lo..hi at every size (inRange alone scales its range with
// RapidCheck's size: the first cases would all sit at lo, the extreme
// corner of the input space).
double dyadic(int lo, int hi, double scale) {
  return *rc::gen::resize(100, rc::gen::inRange(lo, hi + 1)) / scale;
}

Vec3d random_vec(double r) {
  return Vec3d(dyadic(-64, 64, 64 / r), dyadic(-64, 64, 64 / r), dyadic(-64, 64, 64 / r));
}

// An end on a random sphere near `m`, its axis `dir` tilted at random, the
// circle's plane at a random height, tangent length `len`.
SkinEnd random_end(const Vec3d& m, const Vec3d& dir, double len) {
  const double R = dyadic(16, 64, 32);  // 0.5 .. 2
  Vec3d axis = dir.normalized() + random_vec(0.6);
  RC_PRE(axis.norm() > 0.2);
  axis.normalize();
  const double h = dyadic(-16, 16, 64) * R;  // |h| <= R/4: gentle cones (apex beyond ~3.5 r)
  SkinEnd e;
  RC_PRE(skin_end_from_sphere(m, R, m + h * axis, len * axis, e) == Status::ok);
  return e;
}

struct Pair {
  SkinEnd s, e;
  SphereSkin S;
};

// A valid random skin with the options' pairing and method.
Pair random_skin(const SkinOptions& o) {
  Pair P;
  const Vec3d m0 = random_vec(2.0);
  const Vec3d m1 = m0 + Vec3d(4, 0, 0) + random_vec(2.0);
  const Vec3d d = m1 - m0;
  const double len = d.norm() * dyadic(24, 64, 32);  // 0.75 .. 2 chord lengths
  P.s = random_end(m0, d, len);
  P.e = random_end(m1, d, len * dyadic(24, 40, 32));
  // Well-conditioned spines: max kappa |p_f - p_i| <= 20 (sharper kinks
  // make the double-reflection table's quintic dense output, not the
  // reference, the limit of the 1e-10 agreement; SPEC §8g).
  const SkinSpine a = make_skin_spine(P.s, P.e);
  for (int i = 0; i <= 64; ++i)
    RC_PRE(skin_spine_curvature(a, i / 64.0) * (P.e.center - P.s.center).norm() <= 20.0);
  const Status st = make_sphere_skin(P.s, P.e, o, P.S);
  RC_PRE(st != Status::nested_spheres && st != Status::curvature_radius_too_large);
  RC_ASSERT(st == Status::ok);
  // Well-conditioned skins: lambda >= 0.05 min(r_i, r_f) on a 33 x 32 grid
  // (a skin whose curves cross the spine is valid by the statuses but
  // folds; the twist measure divides by lambda^2 there).
  const double rmin = 0.05 * std::min(P.s.radius, P.e.radius);
  for (int i = 0; i <= 32; ++i)
    for (int j = 0; j < 32; ++j)
      RC_PRE(skin_lambda(P.S, 0.19634954 * j, i / 32.0) >= rmin);
  return P;
}

Vec3d at(const SphereSkin& S, double theta, double t, Vec3d* xt = nullptr, Vec3d* xth = nullptr,
         Vec3d* n = nullptr) {
  double x[3], a[3], b[3], c[3];
  const Status st = skin_eval(S, theta, t, x, a, b, n ? c : nullptr);
  RC_ASSERT(st == Status::ok);
  if (xth) *xth = Vec3d(a[0], a[1], a[2]);
  if (xt) *xt = Vec3d(b[0], b[1], b[2]);
  if (n) *n = Vec3d(c[0], c[1], c[2]);
  return Vec3d(x[0], x[1], x[2]);
}

double theta_gen() { return dyadic(-201, 201, 64); }

}  // namespace

// s(theta, 0) on the first circle, s(theta, 1) on the second; s_t at the
// ends along the cone's generatrix, a (x - q) with a c > 0 (ERRATA), and
// tangent to the sphere.
RC_GTEST_PROP(SphereSkinProperties, EndsOnTheCirclesAlongTheCones, ()) {
  const Pair P = random_skin(SkinOptions{});
  const double theta = theta_gen();
  for (int end = 0; end < 2; ++end) {
    const SkinEnd& E = end ? P.e : P.s;
    Vec3d xt;
    const Vec3d q = at(P.S, theta, end, &xt);
    const double scale = E.center.norm() + E.radius;
    RC_ASSERT(std::abs((q - E.center).norm() - E.radius) <= 1e-12 * scale);
    RC_ASSERT(std::abs((q - E.center).dot(E.tangent.normalized())) <= 1e-12 * scale);
    // The generatrix direction c (x - q) = t - inv_c r w... as c t - (q - p)
    // divided by c: g = t - inv_c (q - p), pointing to the apex when c > 0.
    const Vec3d g = E.tangent - E.inv_c * (q - E.center);
    RC_ASSERT(xt.cross(g).norm() <= 1e-11 * xt.norm() * g.norm());
    RC_ASSERT(xt.dot(g) > 0);  // a c > 0
    Vec3d m;
    double R;
    skin_end_sphere(E, m, R);
    RC_ASSERT(std::abs(xt.dot((q - m).normalized())) <= 1e-11 * xt.norm());
  }
}

// The transported frame stays orthonormal and W1' is parallel to t (dense
// output between the nodes too).
RC_GTEST_PROP(SphereSkinProperties, FrameOrthonormalAndRotationMinimizing, ()) {
  const Pair P = random_skin(SkinOptions{});
  const double t = dyadic(0, 1000, 1000);
  Vec3d w, dw;
  rmf_at(P.S.spine, P.S.rmf, t, w, &dw);
  const Vec3d u = P.S.spine.d1(t).normalized();
  RC_ASSERT(std::abs(w.norm() - 1) <= 1e-15 * 4);
  RC_ASSERT(std::abs(w.dot(u)) <= 1e-15 * 4);
  RC_ASSERT(dw.cross(u).norm() <= 1e-13 * (1 + dw.norm()));
  // Reference: the pieces join (the next piece starts at the previous
  // one's end direction). Double reflection: the dense value at a node is
  // the node.
  const RmfTable& T = P.S.rmf;
  RC_ASSERT(T.pieces >= 1);
  for (int i = 0; i + 1 < T.pieces; ++i) {
    Vec3d end;
    rmf_at(P.S.spine, T, T.piece[i].t1, end, nullptr);
    RC_ASSERT((end - T.piece[i + 1].u).norm() <= 1e-14);
  }
  SkinOptions dr;
  dr.method = RmfMethod::double_reflection;
  SphereSkin B;
  RC_ASSERT(make_sphere_skin(P.s, P.e, dr, B) == Status::ok);
  const int k = *rc::gen::inRange(0, kRmfIntervals + 1);
  Vec3d wk;
  rmf_at(B.spine, B.rmf, double(k) / kRmfIntervals, wk, nullptr);
  RC_ASSERT((wk - B.rmf.w[k]).norm() <= 1e-15 * 4);
}

// Double reflection and the reference integration agree to 1e-10.
RC_GTEST_PROP(SphereSkinProperties, DoubleReflectionAgreesWithReference, ()) {
  const Pair P = random_skin(SkinOptions{});
  SkinOptions dr;
  dr.method = RmfMethod::double_reflection;
  SphereSkin B;
  RC_ASSERT(make_sphere_skin(P.s, P.e, dr, B) == Status::ok);
  for (int i = 0; i < 8; ++i) {
    const double t = dyadic(0, 1000, 1000);
    Vec3d wa, wb;
    rmf_at(P.S.spine, P.S.rmf, t, wa, nullptr);
    rmf_at(B.spine, B.rmf, t, wb, nullptr);
    RC_ASSERT((wa - wb).norm() <= 1e-10);
    const double theta = theta_gen();
    RC_ASSERT((at(P.S, theta, t) - at(B, theta, t)).norm() <= 1e-10 * (1 + at(B, theta, t).norm()));
  }
}

// The RMF skin's twist is never larger than the baselines' (and ~0).
RC_GTEST_PROP(SphereSkinProperties, RmfTwistNeverLarger, ()) {
  const Pair P = random_skin(SkinOptions{});
  SkinOptions kh;
  kh.pairing = SkinPairing::kunkli_hoffmann;
  SphereSkin K;
  const Status st = make_sphere_skin(P.s, P.e, kh, K);
  RC_PRE(st == Status::ok);
  const double theta = theta_gen();
  double tr = 0, tk = 0;
  RC_PRE(skin_twist(P.S, theta, tr) == Status::ok && skin_twist(K, theta, tk) == Status::ok);
  // The measure's rounding: s_t - alpha' cancels |alpha'| against
  // lambda-sized terms, divided by |s - alpha| = |lambda|: ~eps
  // |alpha'|/|lambda| per unit t.
  double scale = 0;
  for (int i = 0; i <= 64; ++i)
    scale = std::max(scale, P.S.spine.d1(i / 64.0).norm() /
                                std::abs(skin_lambda(P.S, theta, i / 64.0)));
  RC_ASSERT(tr <= 1e-12 * (1 + scale));
  RC_ASSERT(tr <= tk + 1e-12 * (1 + scale));
  RC_ASSERT(std::abs(tk - std::abs(K.delta)) <= 1e-9 + 1e-12 * scale);
}

// Normals: unit, orthogonal to both partials.
RC_GTEST_PROP(SphereSkinProperties, NormalsUnitAndOrthogonal, ()) {
  const Pair P = random_skin(SkinOptions{});
  const double theta = theta_gen(), t = dyadic(0, 1000, 1000);
  double x[3], a[3], b[3], n[3];
  const Status st = skin_eval(P.S, theta, t, x, a, b, n);
  RC_PRE(st != Status::singular_point);
  RC_ASSERT(st == Status::ok);
  const Vec3d N(n[0], n[1], n[2]), A(a[0], a[1], a[2]), B(b[0], b[1], b[2]);
  RC_ASSERT(std::abs(N.norm() - 1) <= 1e-15 * 4);
  RC_ASSERT(std::abs(N.dot(A)) <= 1e-12 * A.norm());
  RC_ASSERT(std::abs(N.dot(B)) <= 1e-12 * B.norm());
  // The partials against central differences.
  const double h = 1e-6;
  const Vec3d dt = (at(P.S, theta, std::min(t + h, 1.0)) - at(P.S, theta, std::max(t - h, 0.0))) /
                   (std::min(t + h, 1.0) - std::max(t - h, 0.0));
  const Vec3d dth = (at(P.S, theta + h, t) - at(P.S, theta - h, t)) / (2 * h);
  RC_ASSERT((dt - B).norm() <= 1e-5 * (1 + B.norm()));
  RC_ASSERT((dth - A).norm() <= 1e-5 * (1 + A.norm()));
}

// Chains of 3..5 spheres are G^1 at every shared circle (same points and
// normals for every theta).
RC_GTEST_PROP(SphereSkinProperties, ChainsAreG1, ()) {
  const int n = *rc::gen::inRange(3, 6);
  SkinEnd ends[5];
  Vec3d m = Vec3d::Zero(), dir(1, 0, 0);
  for (int k = 0; k < n; ++k) {
    const Vec3d next = m + 4.0 * dir;
    ends[k] = random_end(m, dir, 4.0 * dyadic(24, 48, 32));
    m = next;
    dir = (dir + random_vec(0.5)).normalized();
  }
  SphereSkin P[4];
  int bad = -1;
  const Status st = make_sphere_skin_chain(ends, n, SkinOptions{}, P, &bad);
  RC_PRE(st != Status::nested_spheres && st != Status::curvature_radius_too_large);
  RC_ASSERT(st == Status::ok);
  for (int k = 0; k + 2 < n; ++k) {
    const double theta = theta_gen();
    Vec3d n0, n1;
    const Vec3d x0 = at(P[k], theta, 1.0, nullptr, nullptr, &n0);
    const Vec3d x1 = at(P[k + 1], theta, 0.0, nullptr, nullptr, &n1);
    RC_ASSERT((x0 - x1).norm() <= 1e-11 * (1 + x0.norm()));
    RC_ASSERT((n0 - n1).norm() <= 1e-9);
  }
}
