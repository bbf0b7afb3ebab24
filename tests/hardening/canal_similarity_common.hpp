// Shared part of the similarity properties of the canal / ringed / Darboux /
// blend families (SPEC §9b.4, "PRCS, PRRS, ringed, Darboux, blends, n-way"),
// included by canal_similarity_*.cpp. Everything goes through the C ABI.
//
// Tolerances. A model of size L moved by g(x) = s R x + t is first ROUNDED:
// its moved inputs carry errors of about eps |t| (eps = 2^-52), so no
// construction can give the moved outputs better than that error times its
// condition. Every comparison therefore allows
//   kTol * (s L) + kRound * |t|                      for points and lengths,
//   (kTol + kRound * |t| / (s L)) * (scale of the vector)  for vectors,
//   kTol + kRound * |t| / (s L)                      for unit directions,
// kTol = 1e-9 (the relative accuracy of the unmoved constructions, SPEC §9)
// and kRound = 1e-12 (about 4500 eps: the rounding of the moved inputs
// times the condition the generators admit). A construction that forms
// |x|^2 differences in absolute coordinates loses eps |t|^2 / L instead,
// 10^-4 L at |t| = 10^6 L, and fails these bounds by orders of magnitude.
#pragma once

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "cyclide/cyclide.h"
#include "similarity.hpp"

namespace canal_similarity {

using Eigen::Vector3d;
using similarity::Similarity;

constexpr double kTol = 1e-9;
constexpr double kRound = 1e-12;

inline std::string sci(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3e", x);
  return buf;
}

// ------------------------------------------------------------ probe
// CYC_PROP_PROBE=1 prints the worst error / bound of every check.
struct Probe {
  std::map<std::string, std::pair<double, long>> worst;
  ~Probe() {
    if (!std::getenv("CYC_PROP_PROBE")) return;
    for (const auto& [name, w] : worst)
      std::printf("probe %-44s worst err/bound %.3e over %ld\n", name.c_str(), w.first,
                  w.second);
  }
};
inline Probe& probe() {
  static Probe p;
  return p;
}

#define SIM_CHECK(name, err, bound)                                           \
  do {                                                                        \
    const double e_ = (err), b_ = (bound);                                    \
    auto& w_ = ::canal_similarity::probe().worst[name];                       \
    w_.first = std::max(w_.first, b_ > 0 ? e_ / b_ : (e_ > 0 ? 1e300 : 0.0)); \
    ++w_.second;                                                              \
    if (!(e_ <= b_))                                                          \
      RC_FAIL(std::string(name) + ": error " + ::canal_similarity::sci(e_) + " > bound " + \
              ::canal_similarity::sci(b_));                                            \
  } while (false)

// The bounds of the header comment for a model of size L moved by g.
struct Bounds {
  double sL = 1, t = 0;
  Bounds(const Similarity& g, double L) : sL(g.s * L), t(g.t.norm()) {}
  double point() const { return kTol * sL + kRound * t; }
  double rel() const { return kTol + kRound * t / sL; }  // relative / direction
};

inline Vector3d v3(const double* x) { return {x[0], x[1], x[2]}; }
// A handle was made (RapidCheck cannot print pointers to opaque types).
inline bool made(const void* p) { return p != nullptr; }

// A moved output (a) against the moved original output (b).
inline void check_point(const char* name, const double* a, const Vector3d& b, const Bounds& B,
                        double amp = 1) {
  SIM_CHECK(name, (v3(a) - b).norm(), amp * B.point());
}
inline void check_vector(const char* name, const double* a, const Vector3d& b, double scale,
                         const Bounds& B, double amp = 1) {
  SIM_CHECK(name, (v3(a) - b).norm(), amp * B.rel() * scale);
}
inline void check_scalar(const char* name, double a, double b, double scale, const Bounds& B,
                         double amp = 1) {
  SIM_CHECK(name, std::abs(a - b), amp * B.rel() * scale);
}

// ------------------------------------------------------------ generators
// An integer in [lo, hi], uniform at every RapidCheck size.
inline int gen_int(int lo, int hi) { return *rc::gen::resize(100, rc::gen::inRange(lo, hi + 1)); }
// k / den with |k| <= n.
inline double gen_signed(int n, int den) { return double(gen_int(-n, n)) / double(den); }
inline Vector3d gen_vec(int n = 16, int den = 8) {
  return {gen_signed(n, den), gen_signed(n, den), gen_signed(n, den)};
}

// A curve input of the C ABI: homogeneous power-form rows (x, y, z, w), a
// point, or a line element (point, tangent).
struct CurveSpec {
  enum Kind { rational, point, line_element } kind = rational;
  int degree = 0;
  double h[4 * 16] = {};
  double P[3] = {}, T[3] = {};
};

// A cubic p(u) = sum c_k u^k, c_0, c_1 in [-2, 2]^3, c_2, c_3 in [-1, 1]^3
// (steps 1/8); one in four rational with weight 1 + w1 u + w2 u^2,
// |w_i| <= 1/4 (>= 1/2 on |u| <= 1).
inline CurveSpec gen_cubic() {
  CurveSpec c;
  c.degree = 3;
  for (int k = 0; k < 4; ++k) {
    const int n = k < 2 ? 16 : 8;
    for (int j = 0; j < 3; ++j) c.h[4 * k + j] = gen_signed(n, 8);
    c.h[4 * k + 3] = k == 0 ? 1.0 : 0.0;
  }
  if (gen_int(0, 3) == 0) {
    c.h[7] = gen_signed(4, 16);
    c.h[11] = gen_signed(4, 16);
  }
  return c;
}
inline CurveSpec gen_line() {
  CurveSpec c;
  c.degree = 1;
  Vector3d p = gen_vec(), d = gen_vec();
  if (d.norm() < 0.25) d = Vector3d(1, 0.5, 0.25);
  for (int j = 0; j < 3; ++j) {
    c.h[j] = p[j];
    c.h[4 + j] = d[j];
  }
  c.h[3] = 1;
  return c;
}
inline CurveSpec point_spec(const Vector3d& p) {
  CurveSpec c;
  c.kind = CurveSpec::point;
  for (int j = 0; j < 3; ++j) c.P[j] = p[j];
  return c;
}
inline CurveSpec gen_point() { return point_spec(gen_vec()); }
inline CurveSpec gen_line_element() {
  CurveSpec c;
  c.kind = CurveSpec::line_element;
  Vector3d p = gen_vec(), t = gen_vec();
  if (t.norm() < 0.25) t = Vector3d(0, 0.5, 1);
  for (int j = 0; j < 3; ++j) {
    c.P[j] = p[j];
    c.T[j] = t[j];
  }
  return c;
}

// A curve of points moved by g: (X_k, w_k) -> (s R X_k + t w_k, w_k).
inline CurveSpec moved_points(const CurveSpec& c, const Similarity& g) {
  CurveSpec m = c;
  if (c.kind != CurveSpec::rational) {
    g.point(c.P, m.P);
    g.direction(c.T, m.T);
    return m;
  }
  for (int k = 0; k <= c.degree; ++k) {
    const Vector3d Y = g.vector(v3(c.h + 4 * k)) + g.t * c.h[4 * k + 3];
    for (int j = 0; j < 3; ++j) m.h[4 * k + j] = Y[j];
  }
  return m;
}
// A curve of vectors (an orientation function n) moved by g: R n.
inline CurveSpec moved_directions(const CurveSpec& c, const Similarity& g) {
  CurveSpec m = c;
  if (c.kind != CurveSpec::rational) {
    g.direction(c.P, m.P);
    return m;
  }
  for (int k = 0; k <= c.degree; ++k) {
    const Vector3d Y = g.direction(v3(c.h + 4 * k));
    for (int j = 0; j < 3; ++j) m.h[4 * k + j] = Y[j];
  }
  return m;
}

// ------------------------------------------------------------ handles
// One context and the handles made through it (destroyed at the end).
struct Scene {
  cyc_context* ctx = nullptr;
  std::vector<cyc_curve*> curves;
  std::vector<cyc_surface*> surfaces;
  Scene() { RC_ASSERT(cyc_context_create(nullptr, &ctx) == CYC_OK); }
  ~Scene() {
    for (cyc_surface* s : surfaces) cyc_surface_destroy(ctx, s);
    for (cyc_curve* c : curves) cyc_curve_destroy(ctx, c);
    cyc_context_destroy(ctx);
  }
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  cyc_curve* curve(const CurveSpec& c) {
    cyc_curve* out = nullptr;
    int st = CYC_E_INTERNAL;
    switch (c.kind) {
      case CurveSpec::rational:
        st = cyc_curve_create_rational(ctx, c.degree, c.h, 4, &out);
        break;
      case CurveSpec::point: st = cyc_curve_create_point(ctx, c.P, &out); break;
      case CurveSpec::line_element:
        st = cyc_curve_create_line_element(ctx, c.P, c.T, &out);
        break;
    }
    RC_ASSERT(st == CYC_OK);
    curves.push_back(out);
    return out;
  }
  // A surface handle kept for destruction (null on error).
  cyc_surface* keep(int st, cyc_surface* s) {
    if (st != CYC_OK) return nullptr;
    surfaces.push_back(s);
    return s;
  }
};

// p(u) and p'(u) of a curve handle.
inline void curve_jet(Scene& S, cyc_curve* c, double u, Vector3d& p, Vector3d& dp) {
  double out[6];
  RC_ASSERT(cyc_curve_eval(S.ctx, c, u, 1, out, 6) == CYC_OK);
  p = v3(out);
  dp = v3(out + 3);
}

// A random parameter of [u0, u1] (dyadic fraction) and a circle parameter
// v = tan(phi), phi in (-pi/2, pi/2).
inline double gen_u(double u0, double u1) { return u0 + (u1 - u0) * gen_int(0, 64) / 64.0; }
inline double gen_v() { return std::tan(gen_int(-150, 150) / 100.0); }

// Ringed normals x_u x x_v / |.| are compared where their condition
// kappa = |x_u||x_v| / |x_u x x_v| is at most this (times kappa).
constexpr double kMaxKappa = 1e3;

// The model's size: the largest distance of its circles' centers, points
// and radii from a reference point of it (translation-free).
struct Extent {
  bool first = true;
  Vector3d c0 = Vector3d::Zero();
  double L = 0, min_radius = HUGE_VAL;
  void add(const Vector3d& x) {
    if (first) c0 = x, first = false;
    L = std::max(L, (x - c0).norm());
  }
  void radius(double r) {
    L = std::max(L, r);
    min_radius = std::min(min_radius, r);
  }
};

// Everything compared at one (u, v) of two surfaces: the original S (model
// of size L) and the moved T, whose parameter of the same point is kv * v.
inline void compare_surfaces(Scene& A, cyc_surface* S, Scene& M, cyc_surface* T, const Similarity& g,
                      double L, double kv, bool canal, double u, double v,
                             double amp = 1) {
  const Bounds B(g, L);
  double x[3], xu[3], xv[3], n[3], y[3], yu[3], yv[3], m[3];
  const int s0 = cyc_surface_eval(A.ctx, S, u, v, x, xu, xv, n);
  const int s1 = cyc_surface_eval(M.ctx, T, u, kv * v, y, yu, yv, m);
  // A ringed normal may vanish (CYC_E_SINGULAR_POINT): without normals then.
  RC_ASSERT(s0 == CYC_OK || s0 == CYC_E_SINGULAR_POINT);
  if (s0 != CYC_OK || s1 != CYC_OK) {
    RC_ASSERT(cyc_surface_eval(A.ctx, S, u, v, x, xu, xv, nullptr) == CYC_OK);
    RC_ASSERT(cyc_surface_eval(M.ctx, T, u, kv * v, y, yu, yv, nullptr) == CYC_OK);
  }
  check_point("x' = g(x)", y, g.point(v3(x)), B, amp);
  check_vector("x'_u = s R x_u", yu, g.vector(v3(xu)), g.s * std::max(L, v3(xu).norm()), B, amp);
  if (s0 == CYC_OK && s1 == CYC_OK) {
    const double kappa =
        canal ? 1.0 : v3(xu).norm() * v3(xv).norm() / v3(xu).cross(v3(xv)).norm();
    if (kappa <= kMaxKappa) check_vector("normal' = R normal", m, g.direction(v3(n)), 1.0, B, amp * kappa);
  }
  cyc_circle c0, c1;
  RC_ASSERT(cyc_surface_circle(A.ctx, S, u, &c0) == CYC_OK);
  RC_ASSERT(cyc_surface_circle(M.ctx, T, u, &c1) == CYC_OK);
  check_point("circle center' = g(center)", c1.center, g.point(v3(c0.center)), B, amp);
  check_vector("circle normal' = R normal", c1.normal, g.direction(v3(c0.normal)), 1.0, B, amp);
  check_scalar("circle radius2' = s^2 radius2", c1.radius2, g.s * g.s * c0.radius2,
               2 * g.s * g.s * L * L, B, amp);
  double rc0[3], rn0[3], rr0, rd0, rc1[3], rn1[3], rr1, rd1;
  RC_ASSERT(cyc_surface_ringed_data(A.ctx, S, u, rc0, rn0, &rr0, &rd0) == CYC_OK);
  RC_ASSERT(cyc_surface_ringed_data(M.ctx, T, u, rc1, rn1, &rr1, &rd1) == CYC_OK);
  check_point("ringed c' = g(c)", rc1, g.point(v3(rc0)), B, amp);
  // n scales like the circle parameter (s' or (p1-p2)x(p1-p3) or the given n).
  check_vector("ringed n' = k R n", rn1, kv * g.direction(v3(rn0)), kv * v3(rn0).norm(), B, amp);
  // For canal surfaces eq. (1) forms rho^2 = r^2 - (r r')^2 / |s'|^2: a
  // difference that cancels by (r / rho)^2 where the touching sphere is
  // much larger than its circle.
  double cancel = 1;
  if (canal) {
    cyc_sphere q;
    RC_ASSERT(cyc_surface_sphere(A.ctx, S, u, &q) == CYC_OK);
    cancel = std::max(1.0, q.radius2 / std::max(rr0, 1e-300));
  }
  check_scalar("ringed rho2' = s^2 rho2", rr1, g.s * g.s * rr0, 2 * g.s * g.s * L * L, B,
               amp * cancel);
  check_scalar("ringed rho rho'' = s^2 rho rho'", rd1, g.s * g.s * rd0,
               2 * g.s * g.s * std::max(L * L, std::abs(rd0)), B, amp * cancel);
  if (canal) {
    cyc_sphere q0, q1;
    RC_ASSERT(cyc_surface_sphere(A.ctx, S, u, &q0) == CYC_OK);
    RC_ASSERT(cyc_surface_sphere(M.ctx, T, u, &q1) == CYC_OK);
    // The touching sphere reaches r from its circle (s = c + k n, k = rho
    // rho' / (n . c'), eq. (3)): its errors scale with r, not with L.
    const double q = std::max(1.0, std::sqrt(q0.radius2) / L);
    check_point("sphere center' = g(center)", q1.center, g.point(v3(q0.center)), B, amp * q);
    check_scalar("sphere radius2' = s^2 radius2", q1.radius2, g.s * g.s * q0.radius2,
                 2 * g.s * g.s * L * L, B, amp * q * q);
  }
}

// Eq. (2) is scale-free, but its rounding floor is not position-free: the
// residual compares derivatives of the circle's center and radius that are
// formed from positions rounded to eps |t|, so far from the origin it is
// ~eps |t| / rho however canal the surface. The moved residual must stay
// below 1e-8 plus that floor (kRound |t| / (s rho_min)), and the decision
// (default tolerance 1e-9) must be the same where the floor is below it.
inline void compare_canal_test(Scene& A, cyc_surface* S, Scene& M, cyc_surface* T, bool canal,
                               const Similarity& g, double rho_min) {
  double r0 = -1, r1 = -1;
  int c0 = -1, c1 = -1;
  RC_ASSERT(cyc_surface_canal_test(A.ctx, S, 0, &r0, &c0) == CYC_OK);
  RC_ASSERT(cyc_surface_canal_test(M.ctx, T, 0, &r1, &c1) == CYC_OK);
  const double floor = kRound * g.t.norm() / (g.s * rho_min);
  if (canal) {
    SIM_CHECK("canal test residual (canal)", r1, 1e-8 + floor);
    RC_ASSERT(c0 == 1);
    RC_ASSERT(c1 == 1);  // the default tolerance includes the rounding floor
  } else if (r0 > 1e-4) {
    RC_ASSERT(c1 == 0);
  }
}

}  // namespace canal_similarity
