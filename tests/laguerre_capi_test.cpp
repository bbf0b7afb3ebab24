// Seed 004 through the C ABI (labels "laguerre;capi"): Laguerre geometry and
// the isotropic model (§2), parabolic Dupin cyclides (§4.1), their rational
// patches, Delaunay / Powell-Sabin and the G1 design (§4.2). Success paths
// are checked against independent formulas ((2.3), (2.4) contact, (2.5),
// (2.6), (4.2), interpolation of the design data); every error path leaves
// the outputs untouched and names the function in the message.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <vector>

#include "cyclide/cyclide.h"

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

template <class T>
void poison(T& x) {
  std::memset(static_cast<void*>(&x), 0xA5, sizeof x);
}
template <class T>
bool poisoned(const T& x) {
  const unsigned char* p = reinterpret_cast<const unsigned char*>(&x);
  for (size_t i = 0; i < sizeof x; ++i)
    if (p[i] != 0xA5) return false;
  return true;
}
bool contains(const char* s, const char* what) { return std::strstr(s, what) != nullptr; }
double dot3(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm3(const double* v) { return std::sqrt(dot3(v, v)); }

// sigma^{-1}: the unit normal of the isotropic parameter y (stereographic
// from W = (0, 0, 1)), written out independently of the library.
void normal_of(double y1, double y2, double n[3]) {
  const double N = 1 + y1 * y1 + y2 * y2;
  n[0] = 2 * y1 / N, n[1] = 2 * y2 / N, n[2] = (y1 * y1 + y2 * y2 - 1) / N;
}

cyc_parabolic_cyclide normal_form(double a, double b) {
  cyc_parabolic_cyclide c;
  std::memset(&c, 0, sizeof c);
  c.a = a, c.b = b;
  c.frame[0] = c.frame[4] = c.frame[8] = 1;
  return c;
}

// (4.1) in the normal form, independently.
void phi(double a, double b, double u, double v, double x[3]) {
  const double x0 = 1 + u * u + v * v;
  x[0] = (a * u + (a - b) * u * v * v) / x0;
  x[1] = (b * v + (b - a) * u * u * v) / x0;
  x[2] = (a * u * u + b * v * v) / x0;
}
// (4.2) with x0 = 1.
double implicit42(double a, double b, const double* x) {
  const double s = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
  return b * x[0] * x[0] + a * x[1] * x[1] + (a + b) * x[2] * x[2] - x[2] * (a * b + s);
}

struct LaguerreCapi : ::testing::Test {
  cyc_context* ctx = nullptr;
  void SetUp() override { ASSERT_EQ(cyc_context_create(nullptr, &ctx), CYC_OK); }
  void TearDown() override { cyc_context_destroy(ctx); }
  void expect_message(const char* fn) {
    EXPECT_TRUE(contains(cyc_context_last_error(ctx), fn)) << cyc_context_last_error(ctx);
  }
};

// ------------------------------------------------------------ §2

TEST_F(LaguerreCapi, LambdaIsTheStereographicFormula23AndLambdaInverseUndoesIt) {
  // A plane e0 + e.x = 0, e unit: Lambda = (e1, e2, e0) / (1 - e3).
  const double e[3] = {0.36, -0.48, 0.8};
  cyc_oriented_plane p{2.5, {e[0], e[1], e[2]}};
  cyc_isotropic_point y;
  ASSERT_EQ(cyc_laguerre_to_isotropic(ctx, &p, &y), CYC_OK);
  EXPECT_EQ(y.exceptional, 0);
  EXPECT_NEAR(y.y[0], e[0] / (1 - e[2]), 1e-14);
  EXPECT_NEAR(y.y[1], e[1] / (1 - e[2]), 1e-14);
  EXPECT_NEAR(y.y[2], 2.5 / (1 - e[2]), 1e-13);
  cyc_oriented_plane q;
  ASSERT_EQ(cyc_isotropic_to_laguerre(ctx, &y, &q), CYC_OK);
  EXPECT_NEAR(q.e0, p.e0, 1e-14);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(q.e[i], p.e[i], 1e-15);
  // A non-unit plane is normalized first (positive scale keeps orientation).
  cyc_oriented_plane p2{5.0, {2 * e[0], 2 * e[1], 2 * e[2]}};
  cyc_isotropic_point y2;
  ASSERT_EQ(cyc_laguerre_to_isotropic(ctx, &p2, &y2), CYC_OK);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(y2.y[i], y.y[i], 1e-13);
  // The exceptional plane (c, 0, 0, 1) is the real number c, and back.
  cyc_oriented_plane w{-1.25, {0, 0, 1}};
  ASSERT_EQ(cyc_laguerre_to_isotropic(ctx, &w, &y), CYC_OK);
  EXPECT_EQ(y.exceptional, 1);
  EXPECT_EQ(y.c, -1.25);
  ASSERT_EQ(cyc_isotropic_to_laguerre(ctx, &y, &q), CYC_OK);
  EXPECT_EQ(q.e0, -1.25);
  EXPECT_EQ(q.e[2], 1.0);
}

TEST_F(LaguerreCapi, LambdaErrors) {
  cyc_isotropic_point y;
  poison(y);
  cyc_oriented_plane zero{1, {0, 0, 0}};
  EXPECT_EQ(cyc_laguerre_to_isotropic(ctx, &zero, &y), CYC_E_INVALID_ARGUMENT);
  expect_message("cyc_laguerre_to_isotropic");
  cyc_oriented_plane nan{kNaN, {0, 0, 1}};
  EXPECT_EQ(cyc_laguerre_to_isotropic(ctx, &nan, &y), CYC_E_NOT_FINITE);
  cyc_oriented_plane big{0, {1e101, 0, 0}};
  EXPECT_EQ(cyc_laguerre_to_isotropic(ctx, &big, &y), CYC_E_NOT_FINITE);
  EXPECT_EQ(cyc_laguerre_to_isotropic(ctx, nullptr, &y), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_laguerre_to_isotropic(ctx, &zero, nullptr), CYC_E_NULL_ARGUMENT);
  expect_message("cyc_laguerre_to_isotropic");
  EXPECT_EQ(cyc_laguerre_to_isotropic(nullptr, &zero, &y), CYC_E_NULL_ARGUMENT);
  EXPECT_TRUE(poisoned(y));
  cyc_oriented_plane q;
  poison(q);
  cyc_isotropic_point bad{2, {0, 0, 0}, 0};
  EXPECT_EQ(cyc_isotropic_to_laguerre(ctx, &bad, &q), CYC_E_INVALID_ARGUMENT);
  expect_message("cyc_isotropic_to_laguerre");
  cyc_isotropic_point inf{0, {kInf, 0, 0}, 0};
  EXPECT_EQ(cyc_isotropic_to_laguerre(ctx, &inf, &q), CYC_E_NOT_FINITE);
  cyc_isotropic_point cnan{1, {0, 0, 0}, kNaN};
  EXPECT_EQ(cyc_isotropic_to_laguerre(ctx, &cnan, &q), CYC_E_NOT_FINITE);
  EXPECT_EQ(cyc_isotropic_to_laguerre(ctx, nullptr, &q), CYC_E_NULL_ARGUMENT);
  EXPECT_TRUE(poisoned(q));
}

// (2.4): the planes touching a cycle are the points of its paraboloid.
TEST_F(LaguerreCapi, CycleParaboloidHoldsExactlyTheTouchingPlanes24) {
  cyc_cycle z{{1.0, -2.0, 0.5}, 1.5};
  cyc_isotropic_paraboloid P;
  ASSERT_EQ(cyc_cycle_paraboloid(ctx, &z, &P), CYC_OK);
  EXPECT_EQ(P.k, 1.5 + 0.5);
  EXPECT_EQ(P.l1, 1.0);
  EXPECT_EQ(P.l2, -2.0);
  EXPECT_EQ(P.c0, 1.5 - 0.5);
  for (int k = 0; k < 8; ++k) {
    double e[3];
    normal_of(0.3 * k - 1, 0.7 - 0.2 * k, e);
    // The touching plane with normal e: e0 = -e.m - r.
    cyc_oriented_plane p{-dot3(e, z.m) - z.r, {e[0], e[1], e[2]}};
    cyc_isotropic_point y;
    ASSERT_EQ(cyc_laguerre_to_isotropic(ctx, &p, &y), CYC_OK);
    int on = -1;
    ASSERT_EQ(cyc_paraboloid_contains(ctx, &P, &y, 0, &on), CYC_OK);
    EXPECT_EQ(on, 1) << k;
    // (2.4) directly.
    const double r2 = y.y[0] * y.y[0] + y.y[1] * y.y[1];
    EXPECT_NEAR(2 * y.y[2] + P.k * r2 + 2 * (P.l1 * y.y[0] + P.l2 * y.y[1]) + P.c0, 0,
                1e-12 * (1 + r2) * 10);
    p.e0 += 0.1;  // moved off: no contact
    ASSERT_EQ(cyc_laguerre_to_isotropic(ctx, &p, &y), CYC_OK);
    ASSERT_EQ(cyc_paraboloid_contains(ctx, &P, &y, 0, &on), CYC_OK);
    EXPECT_EQ(on, 0) << k;
  }
  cyc_isotropic_paraboloid Q;
  poison(Q);
  cyc_cycle bad{{0, kNaN, 0}, 1};
  EXPECT_EQ(cyc_cycle_paraboloid(ctx, &bad, &Q), CYC_E_NOT_FINITE);
  expect_message("cyc_cycle_paraboloid");
  EXPECT_EQ(cyc_cycle_paraboloid(ctx, nullptr, &Q), CYC_E_NULL_ARGUMENT);
  EXPECT_TRUE(poisoned(Q));
  int on = 7;
  cyc_isotropic_point y{0, {0, 0, 0}, 0};
  EXPECT_EQ(cyc_paraboloid_contains(ctx, &P, &y, 2.0, &on), CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(cyc_paraboloid_contains(ctx, &P, &y, kNaN, &on), CYC_E_NOT_FINITE);  // §9b.2
  expect_message("cyc_paraboloid_contains");
  EXPECT_EQ(on, 7);
}

// (2.5), (2.6) against the planes moved directly: translating / offsetting a
// plane and mapping it by Lambda commute.
TEST_F(LaguerreCapi, TranslationAndDilatationCommuteWithLambda25And26) {
  const double t[3] = {0.5, -1.5, 2.0};
  double e[3];
  normal_of(0.4, -0.9, e);
  cyc_oriented_plane p{0.75, {e[0], e[1], e[2]}};
  cyc_isotropic_point y, ty, via;
  ASSERT_EQ(cyc_laguerre_to_isotropic(ctx, &p, &y), CYC_OK);
  ASSERT_EQ(cyc_isotropic_translate(ctx, &y, t, &ty), CYC_OK);
  // The translated plane: e0 - e.t.
  cyc_oriented_plane tp;
  ASSERT_EQ(cyc_plane_translate(ctx, &p, t, &tp), CYC_OK);
  EXPECT_NEAR(tp.e0, p.e0 - dot3(e, t), 1e-15);
  ASSERT_EQ(cyc_laguerre_to_isotropic(ctx, &tp, &via), CYC_OK);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(ty.y[i], via.y[i], 1e-13);
  // (2.5) written out.
  const double q = y.y[0] * y.y[0] + y.y[1] * y.y[1];
  EXPECT_NEAR(ty.y[2], y.y[2] - t[0] * y.y[0] - t[1] * y.y[1] - t[2] / 2 * (q - 1), 1e-13);
  // The offset by d: e0 - d; (2.6) y3 - (d / 2)(1 + q).
  const double d = 0.3;
  cyc_isotropic_point dy;
  cyc_oriented_plane dp;
  ASSERT_EQ(cyc_isotropic_dilatation(ctx, &y, d, &dy), CYC_OK);
  ASSERT_EQ(cyc_plane_dilatation(ctx, &p, d, &dp), CYC_OK);
  EXPECT_NEAR(dp.e0, p.e0 - d, 1e-15);
  EXPECT_NEAR(dy.y[2], y.y[2] - d / 2 * (1 + q), 1e-14);
  ASSERT_EQ(cyc_laguerre_to_isotropic(ctx, &dp, &via), CYC_OK);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(dy.y[i], via.y[i], 1e-13);
  // Exceptional: c -> c - t3, c -> c - d.
  cyc_isotropic_point c{1, {0, 0, 0}, 4.0};
  ASSERT_EQ(cyc_isotropic_translate(ctx, &c, t, &ty), CYC_OK);
  EXPECT_EQ(ty.c, 2.0);
  ASSERT_EQ(cyc_isotropic_dilatation(ctx, &c, d, &dy), CYC_OK);
  EXPECT_EQ(dy.c, 3.7);
  // Errors.
  cyc_isotropic_point out;
  cyc_oriented_plane pout;
  poison(out);
  poison(pout);
  const double tn[3] = {0, kNaN, 0};
  EXPECT_EQ(cyc_isotropic_translate(ctx, &y, tn, &out), CYC_E_NOT_FINITE);
  expect_message("cyc_isotropic_translate");
  EXPECT_EQ(cyc_isotropic_translate(ctx, &y, nullptr, &out), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_isotropic_dilatation(ctx, &y, kInf, &out), CYC_E_NOT_FINITE);
  expect_message("cyc_isotropic_dilatation");
  EXPECT_EQ(cyc_plane_translate(ctx, &p, tn, &pout), CYC_E_NOT_FINITE);
  expect_message("cyc_plane_translate");
  EXPECT_EQ(cyc_plane_dilatation(ctx, &p, kNaN, &pout), CYC_E_NOT_FINITE);
  expect_message("cyc_plane_dilatation");
  EXPECT_EQ(cyc_plane_dilatation(ctx, nullptr, 1, &pout), CYC_E_NULL_ARGUMENT);
  EXPECT_TRUE(poisoned(out));
  EXPECT_TRUE(poisoned(pout));
}

// ------------------------------------------------------------ §4.1

TEST_F(LaguerreCapi, NormalFormPointsSatisfy42AndMatch41) {
  const double ab[][2] = {{1, -1}, {2, 0.5}, {1.5, 0}, {-1, 3}};
  for (const auto& p : ab) {
    const cyc_parabolic_cyclide c = normal_form(p[0], p[1]);
    for (int k = 0; k < 6; ++k) {
      const double u = 0.4 * k - 1, v = 0.7 - 0.3 * k;
      double x[3], n[3], ref[3];
      ASSERT_EQ(cyc_parabolic_cyclide_eval(ctx, &c, u, v, x, n), CYC_OK);
      phi(p[0], p[1], u, v, ref);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(x[i], ref[i], 1e-14);
      EXPECT_NEAR(implicit42(p[0], p[1], x), 0, 1e-13);
      double F = 1;
      ASSERT_EQ(cyc_parabolic_cyclide_implicit(ctx, &c, x, &F), CYC_OK);
      EXPECT_NEAR(F, 0, 1e-13);
      double nref[3];
      normal_of(u, v, nref);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(n[i], nref[i], 1e-15);
      // The tangent plane (4.3) passes through x: psi0 + psi.x = 0.
      EXPECT_NEAR(-(p[0] * u * u + p[1] * v * v) + 2 * u * x[0] + 2 * v * x[1] +
                      (u * u + v * v - 1) * x[2],
                  0, 1e-13);
    }
    const double off[3] = {0.3, 0.2, 5};
    double F = 0;
    ASSERT_EQ(cyc_parabolic_cyclide_implicit(ctx, &c, off, &F), CYC_OK);
    EXPECT_NEAR(F, implicit42(p[0], p[1], off), 1e-12);
  }
  // Only one output.
  const cyc_parabolic_cyclide c = normal_form(1, -1);
  double x[3];
  EXPECT_EQ(cyc_parabolic_cyclide_eval(ctx, &c, 0.5, 0.5, x, nullptr), CYC_OK);
}

TEST_F(LaguerreCapi, TypesLinesAndCircles) {
  int t = -1;
  cyc_parabolic_cyclide c = normal_form(1, 2);
  ASSERT_EQ(cyc_parabolic_cyclide_type(ctx, &c, &t), CYC_OK);
  EXPECT_EQ(t, CYC_PARABOLIC_HORN);
  c = normal_form(1, -2);
  ASSERT_EQ(cyc_parabolic_cyclide_type(ctx, &c, &t), CYC_OK);
  EXPECT_EQ(t, CYC_PARABOLIC_RING);
  c = normal_form(0, 2);
  ASSERT_EQ(cyc_parabolic_cyclide_type(ctx, &c, &t), CYC_OK);
  EXPECT_EQ(t, CYC_PARABOLIC_THORN);
  c = normal_form(2, 2);
  ASSERT_EQ(cyc_parabolic_cyclide_type(ctx, &c, &t), CYC_OK);
  EXPECT_EQ(t, CYC_PARABOLIC_SPHERE);
  c = normal_form(0, 0);
  ASSERT_EQ(cyc_parabolic_cyclide_type(ctx, &c, &t), CYC_OK);
  EXPECT_EQ(t, CYC_PARABOLIC_POINT);

  c = normal_form(1.5, -0.5);
  cyc_line e, f;
  ASSERT_EQ(cyc_parabolic_cyclide_lines(ctx, &c, &e, &f), CYC_OK);
  // e: x1 = 0, x3 = a; f: x2 = 0, x3 = b.
  for (double s : {-2.0, 0.0, 3.0}) {
    EXPECT_NEAR(e.point[0] + s * e.direction[0], 0, 1e-15);
    EXPECT_NEAR(e.point[2] + s * e.direction[2], 1.5, 1e-15);
    EXPECT_NEAR(f.point[1] + s * f.direction[1], 0, 1e-15);
    EXPECT_NEAR(f.point[2] + s * f.direction[2], -0.5, 1e-15);
  }
  EXPECT_NEAR(norm3(e.direction), 1, 1e-15);
  // The u-circle contains phi(u, v) for every v, the v-circle phi(u, v) for every u.
  const double u = 0.6, v = -0.8;
  cyc_circle cu, cv;
  ASSERT_EQ(cyc_parabolic_cyclide_u_circle(ctx, &c, u, &cu), CYC_OK);
  ASSERT_EQ(cyc_parabolic_cyclide_v_circle(ctx, &c, v, &cv), CYC_OK);
  for (int k = 0; k < 5; ++k) {
    double x[3], d[3];
    phi(1.5, -0.5, u, -2 + k, x);
    for (int i = 0; i < 3; ++i) d[i] = x[i] - cu.center[i];
    EXPECT_NEAR(dot3(d, d), cu.radius2, 1e-13);
    EXPECT_NEAR(dot3(d, cu.normal), 0, 1e-14);
    phi(1.5, -0.5, -2 + k, v, x);
    for (int i = 0; i < 3; ++i) d[i] = x[i] - cv.center[i];
    EXPECT_NEAR(dot3(d, d), cv.radius2, 1e-13);
    EXPECT_NEAR(dot3(d, cv.normal), 0, 1e-14);
  }
  // Errors.
  poison(e);
  poison(cu);
  EXPECT_EQ(cyc_parabolic_cyclide_lines(ctx, &c, nullptr, nullptr), CYC_E_NULL_ARGUMENT);
  expect_message("cyc_parabolic_cyclide_lines");
  EXPECT_EQ(cyc_parabolic_cyclide_u_circle(ctx, &c, kNaN, &cu), CYC_E_NOT_FINITE);
  expect_message("cyc_parabolic_cyclide_u_circle");
  EXPECT_EQ(cyc_parabolic_cyclide_v_circle(ctx, &c, kInf, &cu), CYC_E_NOT_FINITE);
  expect_message("cyc_parabolic_cyclide_v_circle");
  cyc_parabolic_cyclide bad = c;
  bad.frame[1] = 0.5;  // not a rotation
  EXPECT_EQ(cyc_parabolic_cyclide_lines(ctx, &bad, &e, nullptr), CYC_E_INVALID_ARGUMENT);
  expect_message("cyc_parabolic_cyclide_lines");
  EXPECT_TRUE(poisoned(e));
  EXPECT_TRUE(poisoned(cu));
  t = 9;
  bad.a = kNaN;
  EXPECT_EQ(cyc_parabolic_cyclide_type(ctx, &bad, &t), CYC_E_NOT_FINITE);
  expect_message("cyc_parabolic_cyclide_type");
  EXPECT_EQ(t, 9);
}

TEST_F(LaguerreCapi, EvalErrorsLeaveOutputsUntouched) {
  double x[3], n[3];
  poison(x);
  poison(n);
  cyc_parabolic_cyclide c = normal_form(0, 0);
  EXPECT_EQ(cyc_parabolic_cyclide_eval(ctx, &c, 0, 0, x, n), CYC_E_DEGENERATE_CYCLIDE);
  expect_message("cyc_parabolic_cyclide_eval");
  c = normal_form(1, -1);
  EXPECT_EQ(cyc_parabolic_cyclide_eval(ctx, &c, kNaN, 0, x, n), CYC_E_NOT_FINITE);
  EXPECT_EQ(cyc_parabolic_cyclide_eval(ctx, &c, 0, 1e101, x, n), CYC_E_NOT_FINITE);
  EXPECT_EQ(cyc_parabolic_cyclide_eval(ctx, &c, 0, 0, nullptr, nullptr), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_parabolic_cyclide_eval(ctx, nullptr, 0, 0, x, n), CYC_E_NULL_ARGUMENT);
  c.origin[2] = kInf;
  EXPECT_EQ(cyc_parabolic_cyclide_eval(ctx, &c, 0, 0, x, n), CYC_E_NOT_FINITE);
  c = normal_form(1, -1);
  c.frame[0] = 2;
  EXPECT_EQ(cyc_parabolic_cyclide_eval(ctx, &c, 0, 0, x, n), CYC_E_INVALID_ARGUMENT);
  expect_message("cyc_parabolic_cyclide_eval");
  EXPECT_TRUE(poisoned(x));
  EXPECT_TRUE(poisoned(n));
  double F;
  poison(F);
  const double xn[3] = {0, kNaN, 0};
  c = normal_form(1, -1);
  EXPECT_EQ(cyc_parabolic_cyclide_implicit(ctx, &c, xn, &F), CYC_E_NOT_FINITE);
  expect_message("cyc_parabolic_cyclide_implicit");
  EXPECT_TRUE(poisoned(F));
}

// Thm 4.1: the graph y3 = q / 2 is a cyclide of G, and its tangent planes
// are the graph's points: Lambda^{-1}(y, q(y)/2) touches the cyclide at the
// point of parameter y (with an identity frame, (u, v) = y).
TEST_F(LaguerreCapi, CyclideFromQuadraticCarriesTheGraphsPlanesThm41) {
  cyc_graph_quadratic q{{-1.0, 0.0, 0.5, 0.4, -0.2, 0.3}};
  cyc_parabolic_cyclide c;
  ASSERT_EQ(cyc_parabolic_cyclide_from_quadratic(ctx, &q, &c), CYC_OK);
  cyc_graph_quadratic back;
  ASSERT_EQ(cyc_parabolic_cyclide_quadratic(ctx, &c, &back), CYC_OK);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(back.q[i], q.q[i], 1e-13) << i;
  for (int k = 0; k < 6; ++k) {
    const double y1 = 0.3 * k - 0.8, y2 = 0.5 - 0.25 * k;
    const double Q = q.q[0] * y1 * y1 + q.q[1] * y1 * y2 + q.q[2] * y2 * y2 + q.q[3] * y1 +
                     q.q[4] * y2 + q.q[5];
    cyc_isotropic_point y{0, {y1, y2, Q / 2}, 0};
    cyc_oriented_plane P;
    ASSERT_EQ(cyc_isotropic_to_laguerre(ctx, &y, &P), CYC_OK);
    // The world point: parameter_of of the plane's contact point. Take the
    // parameter (u, v) = frame2^T y.
    const double u = c.frame[0] * y1 + c.frame[1] * y2, v = c.frame[3] * y1 + c.frame[4] * y2;
    double x[3], n[3];
    ASSERT_EQ(cyc_parabolic_cyclide_eval(ctx, &c, u, v, x, n), CYC_OK);
    EXPECT_NEAR(P.e0 + dot3(P.e, x), 0, 1e-12) << k;
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(n[i], P.e[i], 1e-13);
    double F = 1;
    ASSERT_EQ(cyc_parabolic_cyclide_implicit(ctx, &c, x, &F), CYC_OK);
    EXPECT_NEAR(F, 0, 1e-11);
    double uv[2];
    ASSERT_EQ(cyc_parabolic_cyclide_parameter_of(ctx, &c, x, uv), CYC_OK);
    EXPECT_NEAR(uv[0], u, 1e-10);
    EXPECT_NEAR(uv[1], v, 1e-10);
  }
  // A point (a = b = 0): q = -(y1^2 + y2^2)... shifted: q00 = -1 -> a = b = 0.
  cyc_graph_quadratic pt{{-1.0, 0.0, -1.0, 0.0, 0.0, 1.0}};
  cyc_parabolic_cyclide out;
  poison(out);
  EXPECT_EQ(cyc_parabolic_cyclide_from_quadratic(ctx, &pt, &out), CYC_E_DEGENERATE_CYCLIDE);
  expect_message("cyc_parabolic_cyclide_from_quadratic");
  cyc_graph_quadratic nan{{kNaN, 0, 0, 0, 0, 0}};
  EXPECT_EQ(cyc_parabolic_cyclide_from_quadratic(ctx, &nan, &out), CYC_E_NOT_FINITE);
  EXPECT_EQ(cyc_parabolic_cyclide_from_quadratic(ctx, nullptr, &out), CYC_E_NULL_ARGUMENT);
  EXPECT_TRUE(poisoned(out));
  // Not of G: a frame tilting x3.
  cyc_parabolic_cyclide tilted = normal_form(1, -1);
  tilted.frame[4] = 0, tilted.frame[5] = 1, tilted.frame[7] = -1, tilted.frame[8] = 0;
  poison(back);
  EXPECT_EQ(cyc_parabolic_cyclide_quadratic(ctx, &tilted, &back), CYC_E_INVALID_ARGUMENT);
  expect_message("cyc_parabolic_cyclide_quadratic");
  EXPECT_TRUE(poisoned(back));
}

// Thm 4.2: the cone Gamma(lambda, mu) touches the cyclide along the cubic
// circle: every circle point lies on the cone (angle with the axis from the
// apex = the half angle) and the cone's generator through it is tangent.
TEST_F(LaguerreCapi, ConeTouchesAlongTheCubicCircleThm42) {
  const double a = 1.5, b = -0.5, lambda = 0.7, mu = 0.4;
  const cyc_parabolic_cyclide c = normal_form(a, b);
  cyc_revolution_cone K;
  ASSERT_EQ(cyc_parabolic_cyclide_cone(ctx, &c, lambda, mu, &K), CYC_OK);
  EXPECT_EQ(K.cylinder, 0);
  EXPECT_NEAR(K.half_angle, std::atan2(std::abs(mu), std::sqrt(1 + lambda * lambda)), 1e-14);
  for (int k = 0; k < 6; ++k) {
    const double t = 0.5 * k - 1.3;
    double x[3], ref[3];
    ASSERT_EQ(cyc_parabolic_cyclide_cubic_circle_point(ctx, &c, lambda, mu, t, x), CYC_OK);
    phi(a, b, t, lambda * t + mu, ref);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(x[i], ref[i], 1e-14);
    double d[3];
    for (int i = 0; i < 3; ++i) d[i] = x[i] - K.apex[i];
    const double angle = std::acos(std::abs(dot3(d, K.axis)) / norm3(d));
    EXPECT_NEAR(std::min(angle, M_PI - angle), K.half_angle, 1e-10) << k;
    // The generator apex -> x lies in the tangent plane at x.
    double n[3];
    normal_of(t, lambda * t + mu, n);
    EXPECT_NEAR(dot3(d, n), 0, 1e-11);
  }
  cyc_revolution_cone out;
  poison(out);
  // mu = 0 and a + b lambda^2 = 0: a pencil of planes.
  EXPECT_EQ(cyc_parabolic_cyclide_cone(ctx, &c, std::sqrt(3.0), 0, &out), CYC_E_DEPENDENT_PLANES);
  expect_message("cyc_parabolic_cyclide_cone");
  EXPECT_EQ(cyc_parabolic_cyclide_cone(ctx, &c, kNaN, 0, &out), CYC_E_NOT_FINITE);
  EXPECT_TRUE(poisoned(out));
  double x[3];
  poison(x);
  EXPECT_EQ(cyc_parabolic_cyclide_cubic_circle_point(ctx, &c, 0, 0, kInf, x), CYC_E_NOT_FINITE);
  expect_message("cyc_parabolic_cyclide_cubic_circle_point");
  EXPECT_TRUE(poisoned(x));
}

// Remark 4.2: for x = phi(u, v) the net projection onto x3 = cc is
// ((a - cc) u, (b - cc) v); parameter_of gives (u, v) back.
TEST_F(LaguerreCapi, NetProjectionRemark42) {
  const double a = 2, b = -1;
  const cyc_parabolic_cyclide c = normal_form(a, b);
  const double u = 0.4, v = -1.2, cc = 0.25;
  double x[3], p[2], uv[2];
  phi(a, b, u, v, x);
  ASSERT_EQ(cyc_parabolic_cyclide_net_projection(ctx, &c, x, cc, p), CYC_OK);
  EXPECT_NEAR(p[0], (a - cc) * u, 1e-13);
  EXPECT_NEAR(p[1], (b - cc) * v, 1e-13);
  ASSERT_EQ(cyc_parabolic_cyclide_parameter_of(ctx, &c, x, uv), CYC_OK);
  EXPECT_NEAR(uv[0], u, 1e-13);
  EXPECT_NEAR(uv[1], v, 1e-13);
  poison(p);
  poison(uv);
  const double on_e_plane[3] = {0.3, 0.1, a};
  EXPECT_EQ(cyc_parabolic_cyclide_net_projection(ctx, &c, on_e_plane, cc, p),
            CYC_E_POINT_AT_INFINITY);
  expect_message("cyc_parabolic_cyclide_net_projection");
  EXPECT_EQ(cyc_parabolic_cyclide_parameter_of(ctx, &c, on_e_plane, uv), CYC_E_POINT_AT_INFINITY);
  expect_message("cyc_parabolic_cyclide_parameter_of");
  const cyc_parabolic_cyclide sphere = normal_form(1, 1);
  EXPECT_EQ(cyc_parabolic_cyclide_net_projection(ctx, &sphere, x, cc, p), CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(cyc_parabolic_cyclide_net_projection(ctx, &c, x, kNaN, p), CYC_E_NOT_FINITE);
  EXPECT_EQ(cyc_parabolic_cyclide_parameter_of(ctx, &c, nullptr, uv), CYC_E_NULL_ARGUMENT);
  EXPECT_TRUE(poisoned(p));
  EXPECT_TRUE(poisoned(uv));
}

// ------------------------------------------------------------ patches

// The cubic triangle of a graph triangle lies on the graph's cyclide, its
// points are the contact points of the graph's planes at the same domain
// point, and its corners are Lambda^{-1} contact points of the vertices.
TEST_F(LaguerreCapi, CubicTriangleAndBicubicLieOnTheCyclide) {
  // q over the triangle: ordinates of y3 = q/2 by the polar form.
  cyc_graph_quadratic q{{-1.0, 0.2, 0.5, 0.4, -0.2, 0.3}};
  auto q_of = [&](double y1, double y2) {
    return q.q[0] * y1 * y1 + q.q[1] * y1 * y2 + q.q[2] * y2 * y2 + q.q[3] * y1 + q.q[4] * y2 +
           q.q[5];
  };
  // Polar form of q/2 for the Bezier ordinates.
  auto polar = [&](const double* A, const double* B) {
    return 0.5 * (q.q[0] * A[0] * B[0] + q.q[1] * (A[0] * B[1] + A[1] * B[0]) / 2 +
                  q.q[2] * A[1] * B[1] + q.q[3] * (A[0] + B[0]) / 2 +
                  q.q[4] * (A[1] + B[1]) / 2 + q.q[5]);
  };
  cyc_quadratic_graph_triangle tri;
  const double V[3][2] = {{-0.5, -0.4}, {0.7, -0.1}, {0.1, 0.8}};
  std::memcpy(tri.vertex, V, sizeof V);
  const int pairs[6][2] = {{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2}, {2, 2}};
  for (int k = 0; k < 6; ++k) tri.ordinate[k] = polar(V[pairs[k][0]], V[pairs[k][1]]);
  cyc_rational_cubic_triangle T;
  ASSERT_EQ(cyc_cyclide_cubic_triangle(ctx, &tri, &T), CYC_OK);
  cyc_parabolic_cyclide c;
  ASSERT_EQ(cyc_parabolic_cyclide_from_quadratic(ctx, &q, &c), CYC_OK);
  const double bary[][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.2, 0.3, 0.5}, {0.6, 0.1, 0.3}};
  for (const auto& w : bary) {
    double x[3];
    ASSERT_EQ(cyc_cubic_triangle_eval(ctx, &T, w[0], w[1], w[2], x), CYC_OK);
    double F = 1;
    ASSERT_EQ(cyc_parabolic_cyclide_implicit(ctx, &c, x, &F), CYC_OK);
    EXPECT_NEAR(F, 0, 1e-11);
    // The plane Lambda^{-1}(y, q(y)/2) at the domain point touches there.
    const double y1 = w[0] * V[0][0] + w[1] * V[1][0] + w[2] * V[2][0];
    const double y2 = w[0] * V[0][1] + w[1] * V[1][1] + w[2] * V[2][1];
    cyc_isotropic_point y{0, {y1, y2, q_of(y1, y2) / 2}, 0};
    cyc_oriented_plane P;
    ASSERT_EQ(cyc_isotropic_to_laguerre(ctx, &y, &P), CYC_OK);
    EXPECT_NEAR(P.e0 + dot3(P.e, x), 0, 1e-12);
    // ... and is the same point as the cyclide's at (u, v) = frame2^T y.
    const double u = c.frame[0] * y1 + c.frame[1] * y2, v = c.frame[3] * y1 + c.frame[4] * y2;
    double xc[3];
    ASSERT_EQ(cyc_parabolic_cyclide_eval(ctx, &c, u, v, xc, nullptr), CYC_OK);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(x[i], xc[i], 1e-12);
  }
  // The bicubic over a parallelogram.
  const double corner[2] = {-0.3, -0.2}, e1[2] = {0.6, 0.1}, e2[2] = {-0.1, 0.5};
  cyc_rational_bicubic_patch B;
  ASSERT_EQ(cyc_cyclide_bicubic_patch(ctx, &q, corner, e1, e2, &B), CYC_OK);
  for (double s : {0.0, 0.3, 1.0})
    for (double t : {0.0, 0.6, 1.0}) {
      double x[3];
      ASSERT_EQ(cyc_bicubic_patch_eval(ctx, &B, s, t, x), CYC_OK);
      const double y1 = corner[0] + s * e1[0] + t * e2[0], y2 = corner[1] + s * e1[1] + t * e2[1];
      const double u = c.frame[0] * y1 + c.frame[1] * y2, v = c.frame[3] * y1 + c.frame[4] * y2;
      double xc[3];
      ASSERT_EQ(cyc_parabolic_cyclide_eval(ctx, &c, u, v, xc, nullptr), CYC_OK);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(x[i], xc[i], 1e-12);
    }
  // Errors.
  cyc_rational_cubic_triangle Tout;
  cyc_rational_bicubic_patch Bout;
  poison(Tout);
  poison(Bout);
  cyc_quadratic_graph_triangle flat = tri;
  flat.vertex[2][0] = 2 * V[1][0] - V[0][0], flat.vertex[2][1] = 2 * V[1][1] - V[0][1];
  EXPECT_EQ(cyc_cyclide_cubic_triangle(ctx, &flat, &Tout), CYC_E_COLLINEAR_POINTS);
  expect_message("cyc_cyclide_cubic_triangle");
  flat = tri;
  flat.ordinate[3] = kNaN;
  EXPECT_EQ(cyc_cyclide_cubic_triangle(ctx, &flat, &Tout), CYC_E_NOT_FINITE);
  EXPECT_EQ(cyc_cyclide_cubic_triangle(ctx, nullptr, &Tout), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_cyclide_bicubic_patch(ctx, &q, corner, e1, e1, &Bout), CYC_E_COLLINEAR_POINTS);
  expect_message("cyc_cyclide_bicubic_patch");
  const double enan[2] = {kNaN, 0};
  EXPECT_EQ(cyc_cyclide_bicubic_patch(ctx, &q, corner, enan, e2, &Bout), CYC_E_NOT_FINITE);
  EXPECT_EQ(cyc_cyclide_bicubic_patch(ctx, &q, nullptr, e1, e2, &Bout), CYC_E_NULL_ARGUMENT);
  EXPECT_TRUE(poisoned(Tout));
  EXPECT_TRUE(poisoned(Bout));
  double x[3];
  poison(x);
  EXPECT_EQ(cyc_cubic_triangle_eval(ctx, &T, kNaN, 0, 1, x), CYC_E_NOT_FINITE);
  expect_message("cyc_cubic_triangle_eval");
  EXPECT_EQ(cyc_bicubic_patch_eval(ctx, &B, 0, kInf, x), CYC_E_NOT_FINITE);
  expect_message("cyc_bicubic_patch_eval");
  // A zero triangle has weight 0 everywhere: at infinity.
  cyc_rational_cubic_triangle Z;
  std::memset(&Z, 0, sizeof Z);
  EXPECT_EQ(cyc_cubic_triangle_eval(ctx, &Z, 0.2, 0.3, 0.5, x), CYC_E_POINT_AT_INFINITY);
  cyc_rational_bicubic_patch ZB;
  std::memset(&ZB, 0, sizeof ZB);
  EXPECT_EQ(cyc_bicubic_patch_eval(ctx, &ZB, 0.2, 0.3, x), CYC_E_POINT_AT_INFINITY);
  EXPECT_TRUE(poisoned(x));
}

// ------------------------------------------------------------ §4.2

// Orientation of three 2-D points, independently.
double orient(const double* p, int i, int j, int k) {
  return (p[2 * j] - p[2 * i]) * (p[2 * k + 1] - p[2 * i + 1]) -
         (p[2 * j + 1] - p[2 * i + 1]) * (p[2 * k] - p[2 * i]);
}

TEST_F(LaguerreCapi, DelaunayTrianglesAreCounterClockwiseWithEmptyCircumcircles) {
  std::vector<double> pts;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      pts.push_back(i + 0.2 * std::sin(7.0 * i + 3.0 * j)), pts.push_back(j + 0.2 * std::cos(5.0 * i - j));
  const int n = 25;
  std::vector<unsigned char> work(cyc_delaunay_workspace_size(n));
  const int cap = cyc_delaunay_max_triangles(n);
  EXPECT_EQ(cap, 2 * n - 5);
  std::vector<int> tri(3 * cap);
  int ntri = 0;
  ASSERT_EQ(cyc_delaunay_triangulate(ctx, pts.data(), n, work.data(), work.size(), tri.data(), cap,
                                     &ntri),
            CYC_OK);
  double area = 0;
  for (int t = 0; t < ntri; ++t) {
    const int a = tri[3 * t], b = tri[3 * t + 1], c = tri[3 * t + 2];
    EXPECT_GT(orient(pts.data(), a, b, c), 0);
    area += orient(pts.data(), a, b, c) / 2;
    // Empty circumcircle (lifted determinant).
    for (int d = 0; d < n; ++d) {
      if (d == a || d == b || d == c) continue;
      auto row = [&](int i, double* r) {
        r[0] = pts[2 * i] - pts[2 * d], r[1] = pts[2 * i + 1] - pts[2 * d + 1];
        r[2] = r[0] * r[0] + r[1] * r[1];
      };
      double A[3], B[3], C[3];
      row(a, A), row(b, B), row(c, C);
      const double det = A[0] * (B[1] * C[2] - B[2] * C[1]) - A[1] * (B[0] * C[2] - B[2] * C[0]) +
                         A[2] * (B[0] * C[1] - B[1] * C[0]);
      EXPECT_LE(det, 1e-9) << t << " " << d;
    }
  }
  EXPECT_GT(area, 14);  // the hull of the jittered 4 x 4 square
  // Errors: too small tri (the count comes back), workspace, equal points,
  // collinear, NaN, n.
  std::vector<int> tri2(tri.size(), -7);
  int need = 0;
  EXPECT_EQ(cyc_delaunay_triangulate(ctx, pts.data(), n, work.data(), work.size(), tri2.data(), 3,
                                     &need),
            CYC_E_BUFFER_TOO_SMALL);
  EXPECT_EQ(need, ntri);
  expect_message("cyc_delaunay_triangulate");
  int untouched = -3;
  EXPECT_EQ(cyc_delaunay_triangulate(ctx, pts.data(), n, work.data(), work.size() - 1, tri2.data(),
                                     cap, &untouched),
            CYC_E_BUFFER_TOO_SMALL);
  EXPECT_TRUE(contains(cyc_context_last_error(ctx), "needed"));
  std::vector<double> dup = pts;
  dup[10] = dup[0], dup[11] = dup[1];
  EXPECT_EQ(cyc_delaunay_triangulate(ctx, dup.data(), n, work.data(), work.size(), tri2.data(),
                                     cap, &untouched),
            CYC_E_INVALID_ARGUMENT);
  EXPECT_TRUE(contains(cyc_context_last_error(ctx), "equal"));
  const double line[8] = {0, 0, 1, 1, 2, 2, 3, 3};
  std::vector<unsigned char> w4(cyc_delaunay_workspace_size(4));
  EXPECT_EQ(cyc_delaunay_triangulate(ctx, line, 4, w4.data(), w4.size(), tri2.data(), cap,
                                     &untouched),
            CYC_E_COLLINEAR_POINTS);
  std::vector<double> nan = pts;
  nan[7] = kNaN;
  EXPECT_EQ(cyc_delaunay_triangulate(ctx, nan.data(), n, work.data(), work.size(), tri2.data(),
                                     cap, &untouched),
            CYC_E_NOT_FINITE);
  EXPECT_EQ(cyc_delaunay_triangulate(ctx, pts.data(), 2, work.data(), work.size(), tri2.data(),
                                     cap, &untouched),
            CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(cyc_delaunay_triangulate(ctx, pts.data(), n, nullptr, 0, tri2.data(), cap, &untouched),
            CYC_E_NULL_ARGUMENT);
  expect_message("cyc_delaunay_triangulate");
  EXPECT_EQ(untouched, -3);
  for (int v : tri2) EXPECT_EQ(v, -7);
  EXPECT_EQ(cyc_delaunay_workspace_size(2), 0u);
  EXPECT_EQ(cyc_delaunay_max_triangles(2), 0);
  // A reused (dirty) workspace gives the same triangulation (regression:
  // stale marks in new triangle slots gave CYC_E_INTERNAL).
  std::vector<int> again(tri.size());
  int n3 = 0;
  ASSERT_EQ(cyc_delaunay_triangulate(ctx, pts.data(), n, work.data(), work.size(), again.data(),
                                     cap, &n3),
            CYC_OK);
  ASSERT_EQ(n3, ntri);
  for (int i = 0; i < 3 * ntri; ++i) EXPECT_EQ(again[i], tri[i]);
}

// Powell-Sabin reproduces quadratics: data from f give f everywhere.
TEST_F(LaguerreCapi, PowellSabinReproducesAQuadratic) {
  auto f = [](double x, double y) { return 0.3 * x * x - 0.2 * x * y + 0.7 * y * y + x - 2; };
  const double b[10] = {0, 0, 2, 0, 2, 2, 0, 2, 1.1, 0.9};
  double z[5], g[10];
  for (int i = 0; i < 5; ++i) {
    const double x = b[2 * i], y = b[2 * i + 1];
    z[i] = f(x, y);
    g[2 * i] = 0.6 * x - 0.2 * y + 1, g[2 * i + 1] = -0.2 * x + 1.4 * y;
  }
  const int tri[12] = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
  std::vector<unsigned char> work(cyc_powell_sabin_workspace_size(5, 4));
  std::vector<cyc_quadratic_graph_triangle> out(24);
  int nout = 0;
  ASSERT_EQ(cyc_powell_sabin_interpolate(ctx, b, z, g, 5, tri, 4, work.data(), work.size(),
                                         out.data(), 24, &nout),
            CYC_OK);
  ASSERT_EQ(nout, 24);
  for (const auto& t : out) {
    const double w[3] = {0.2, 0.5, 0.3};
    double y[2] = {0, 0};
    for (int k = 0; k < 3; ++k) y[0] += w[k] * t.vertex[k][0], y[1] += w[k] * t.vertex[k][1];
    const double r = w[0], s = w[1], u = w[2];
    const double val = t.ordinate[0] * r * r + 2 * t.ordinate[1] * r * s + 2 * t.ordinate[2] * r * u +
                       t.ordinate[3] * s * s + 2 * t.ordinate[4] * s * u + t.ordinate[5] * u * u;
    EXPECT_NEAR(val, f(y[0], y[1]), 1e-13);
  }
  // Errors.
  std::vector<cyc_quadratic_graph_triangle> out2(24);
  poison(out2[0]);
  int n2 = -1;
  EXPECT_EQ(cyc_powell_sabin_interpolate(ctx, b, z, g, 5, tri, 4, work.data(), work.size(),
                                         out2.data(), 23, &n2),
            CYC_E_BUFFER_TOO_SMALL);
  EXPECT_EQ(n2, 24);
  expect_message("cyc_powell_sabin_interpolate");
  n2 = -1;
  EXPECT_EQ(cyc_powell_sabin_interpolate(ctx, b, z, g, 5, tri, 4, work.data(), work.size() - 1,
                                         out2.data(), 24, &n2),
            CYC_E_BUFFER_TOO_SMALL);
  const int cw[12] = {0, 4, 1, 1, 2, 4, 2, 3, 4, 3, 0, 4};
  EXPECT_EQ(cyc_powell_sabin_interpolate(ctx, b, z, g, 5, cw, 4, work.data(), work.size(),
                                         out2.data(), 24, &n2),
            CYC_E_INVALID_ARGUMENT);
  const int oob[12] = {0, 1, 9, 1, 2, 4, 2, 3, 4, 3, 0, 4};
  EXPECT_EQ(cyc_powell_sabin_interpolate(ctx, b, z, g, 5, oob, 4, work.data(), work.size(),
                                         out2.data(), 24, &n2),
            CYC_E_INVALID_ARGUMENT);
  double zn[5] = {z[0], z[1], kNaN, z[3], z[4]};
  EXPECT_EQ(cyc_powell_sabin_interpolate(ctx, b, zn, g, 5, tri, 4, work.data(), work.size(),
                                         out2.data(), 24, &n2),
            CYC_E_NOT_FINITE);
  EXPECT_EQ(cyc_powell_sabin_interpolate(ctx, b, z, nullptr, 5, tri, 4, work.data(), work.size(),
                                         out2.data(), 24, &n2),
            CYC_E_NULL_ARGUMENT);
  expect_message("cyc_powell_sabin_interpolate");
  EXPECT_EQ(n2, -1);
  EXPECT_TRUE(poisoned(out2[0]));
}

TEST_F(LaguerreCapi, IsotropicDatumRoundTripAndItsPlaneTouchesThePoint) {
  double a[3];
  normal_of(0.3, -0.6, a);
  cyc_oriented_point A{{1.0, 2.0, -0.5}, {a[0], a[1], a[2]}};
  cyc_isotropic_datum d;
  ASSERT_EQ(cyc_isotropic_datum_of(ctx, &A, &d), CYC_OK);
  EXPECT_NEAR(d.b[0], 0.3, 1e-15);
  EXPECT_NEAR(d.b[1], -0.6, 1e-15);
  // B = Lambda(tangent plane): z = e0 / (1 - a3), e0 = -a.A.
  EXPECT_NEAR(d.z, -dot3(a, A.point) / (1 - a[2]), 1e-14);
  // g = -(A3 b + (A1, A2)).
  EXPECT_NEAR(d.g[0], -(A.point[2] * 0.3 + A.point[0]), 1e-14);
  EXPECT_NEAR(d.g[1], -(A.point[2] * -0.6 + A.point[1]), 1e-14);
  cyc_oriented_point back;
  ASSERT_EQ(cyc_oriented_point_of(ctx, &d, &back), CYC_OK);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(back.point[i], A.point[i], 1e-13);
    EXPECT_NEAR(back.normal[i], A.normal[i], 1e-15);
  }
  cyc_isotropic_datum dout;
  poison(dout);
  cyc_oriented_point pole{{0, 0, 0}, {0, 0, 1}};
  EXPECT_EQ(cyc_isotropic_datum_of(ctx, &pole, &dout), CYC_E_POLE_IN_GAUSS_IMAGE);
  expect_message("cyc_isotropic_datum_of");
  cyc_oriented_point zero{{0, 0, 0}, {0, 0, 0}};
  EXPECT_EQ(cyc_isotropic_datum_of(ctx, &zero, &dout), CYC_E_INVALID_ARGUMENT);
  cyc_oriented_point nan{{kNaN, 0, 0}, {0, 0, -1}};
  EXPECT_EQ(cyc_isotropic_datum_of(ctx, &nan, &dout), CYC_E_NOT_FINITE);
  EXPECT_TRUE(poisoned(dout));
  poison(back);
  cyc_isotropic_datum dn{{0, kNaN}, 0, {0, 0}};
  EXPECT_EQ(cyc_oriented_point_of(ctx, &dn, &back), CYC_E_NOT_FINITE);
  expect_message("cyc_oriented_point_of");
  EXPECT_TRUE(poisoned(back));
  // The pole test.
  int has = -1;
  cyc_oriented_point up[3] = {{{0, 0, 0}, {0.3, 0, 0.95}}, {{0, 0, 0}, {-0.2, 0.3, 0.93}},
                              {{0, 0, 0}, {-0.2, -0.3, 0.93}}};
  ASSERT_EQ(cyc_gauss_image_contains_pole(ctx, up, 3, &has), CYC_OK);
  EXPECT_EQ(has, 1);
  cyc_oriented_point down[3] = {{{0, 0, 0}, {0.3, 0, -0.95}}, {{0, 0, 0}, {-0.2, 0.3, -0.93}},
                                {{0, 0, 0}, {-0.2, -0.3, -0.93}}};
  ASSERT_EQ(cyc_gauss_image_contains_pole(ctx, down, 3, &has), CYC_OK);
  EXPECT_EQ(has, 0);
  has = 5;
  EXPECT_EQ(cyc_gauss_image_contains_pole(ctx, down, 0, &has), CYC_E_INVALID_ARGUMENT);
  expect_message("cyc_gauss_image_contains_pole");
  EXPECT_EQ(has, 5);
}

// Data on an ellipsoid's lower cap (normals a = sigma^{-1}(b) on a jittered
// grid): support point D a / sqrt(a . D a).
std::vector<cyc_oriented_point> ellipsoid_cap(int k, double h, double p = 2, double q = 1.5) {
  std::vector<cyc_oriented_point> data;
  const double D[3] = {p * p, q * q, 1.0};
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      const bool border = i == 0 || j == 0 || i == k - 1 || j == k - 1;
      const double jx = border ? 0 : 0.05 * std::sin(3.7 * i + 5.1 * j);
      const double jy = border ? 0 : 0.05 * std::cos(2.3 * i - 4.9 * j);
      const double y1 = -h + 2 * h * (i + 0.5 + jx) / k, y2 = -h + 2 * h * (j + 0.5 + jy) / k;
      cyc_oriented_point A;
      normal_of(y1, y2, A.normal);
      const double s = std::sqrt(D[0] * A.normal[0] * A.normal[0] + D[1] * A.normal[1] * A.normal[1] +
                                 D[2] * A.normal[2] * A.normal[2]);
      for (int c = 0; c < 3; ++c) A.point[c] = D[c] * A.normal[c] / s;
      data.push_back(A);
    }
  return data;
}

// §4.2: the design interpolates its data: each datum's b_i is a corner of
// some patch, and the patch's point there is A_i; every patch point has
// the normal of its domain point (finite differences of the patch).
TEST_F(LaguerreCapi, DesignInterpolatesEllipsoidData) {
  const auto data = ellipsoid_cap(5, 0.6);
  const int n = int(data.size());
  const size_t bytes = cyc_design_workspace_size(n, 0);
  const int cap = cyc_design_max_patches(n, 0);
  ASSERT_GT(bytes, 0u);
  ASSERT_EQ(cap, 6 * (2 * n - 5));
  std::vector<unsigned char> work(bytes);
  std::vector<cyc_quadratic_graph_triangle> iso(cap);
  std::vector<cyc_rational_cubic_triangle> patches(cap);
  int np = 0;
  cyc_design_report rep;
  ASSERT_EQ(cyc_design_cyclide_surface(ctx, data.data(), n, nullptr, 0, nullptr, work.data(),
                                       work.size(), iso.data(), patches.data(), cap, &np, &rep),
            CYC_OK);
  EXPECT_EQ(np, rep.patches);
  EXPECT_EQ(np, 6 * rep.triangles);
  EXPECT_EQ(rep.ridge_patches, 0);
  std::vector<int> hit(n, 0);
  for (int k = 0; k < np; ++k)
    for (int corner = 0; corner < 3; ++corner)
      for (int i = 0; i < n; ++i) {
        double a[3];
        normal_of(iso[k].vertex[corner][0], iso[k].vertex[corner][1], a);
        if (std::abs(a[0] - data[i].normal[0]) + std::abs(a[1] - data[i].normal[1]) +
                std::abs(a[2] - data[i].normal[2]) > 1e-12)
          continue;
        double w[3] = {0, 0, 0};
        w[corner] = 1;
        double x[3];
        ASSERT_EQ(cyc_cubic_triangle_eval(ctx, &patches[k], w[0], w[1], w[2], x), CYC_OK);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(x[c], data[i].point[c], 1e-11);
        hit[i] = 1;
      }
  for (int i = 0; i < n; ++i) EXPECT_TRUE(hit[i]) << i;
  // Normals by finite differences at the centroid of each patch.
  const double h = 1e-6, c3 = 1.0 / 3;
  for (int k = 0; k < np; ++k) {
    double p[4][3];
    ASSERT_EQ(cyc_cubic_triangle_eval(ctx, &patches[k], c3 + h, c3, c3 - h, p[0]), CYC_OK);
    ASSERT_EQ(cyc_cubic_triangle_eval(ctx, &patches[k], c3 - h, c3, c3 + h, p[1]), CYC_OK);
    ASSERT_EQ(cyc_cubic_triangle_eval(ctx, &patches[k], c3, c3 + h, c3 - h, p[2]), CYC_OK);
    ASSERT_EQ(cyc_cubic_triangle_eval(ctx, &patches[k], c3, c3 - h, c3 + h, p[3]), CYC_OK);
    double xr[3], xs[3];
    for (int c = 0; c < 3; ++c) xr[c] = p[0][c] - p[1][c], xs[c] = p[2][c] - p[3][c];
    double y[2] = {0, 0};
    for (int v = 0; v < 3; ++v) y[0] += c3 * iso[k].vertex[v][0], y[1] += c3 * iso[k].vertex[v][1];
    double nrm[3];
    normal_of(y[0], y[1], nrm);
    EXPECT_NEAR(dot3(xr, nrm) / norm3(xr), 0, 1e-5) << k;
    EXPECT_NEAR(dot3(xs, nrm) / norm3(xs), 0, 1e-5) << k;
  }
  // The same through the context's allocator (work = NULL), iso NULL.
  std::vector<cyc_rational_cubic_triangle> p2(cap);
  int np2 = 0;
  ASSERT_EQ(cyc_design_cyclide_surface(ctx, data.data(), n, nullptr, 0, nullptr, nullptr, 0,
                                       nullptr, p2.data(), cap, &np2, nullptr),
            CYC_OK);
  ASSERT_EQ(np2, np);
  EXPECT_EQ(std::memcmp(p2.data(), patches.data(), sizeof(patches[0]) * np), 0);
  // A caller's triangulation: a fan of 4 triangles over 5 data.
  // (Sphere data: the isotropic image is a quadratic, reproduced exactly.)
  const auto sphere = ellipsoid_cap(5, 0.6, 1, 1);
  std::vector<cyc_oriented_point> five = {sphere[0], sphere[4], sphere[24], sphere[20], sphere[12]};
  // Their b: corners of the grid and the centre -> counter-clockwise fan
  // (b of data[0] = (-h, -h) side, data[4] = (-h, +h) ... order by b).
  cyc_isotropic_datum d[5];
  for (int i = 0; i < 5; ++i) ASSERT_EQ(cyc_isotropic_datum_of(ctx, &five[i], &d[i]), CYC_OK);
  std::vector<int> fan;
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    const double o = (d[i].b[0] - d[4].b[0]) * (d[j].b[1] - d[4].b[1]) -
                     (d[i].b[1] - d[4].b[1]) * (d[j].b[0] - d[4].b[0]);
    if (o > 0)
      fan.insert(fan.end(), {4, i, j});
    else
      fan.insert(fan.end(), {4, j, i});
  }
  const size_t fb = cyc_design_workspace_size(5, 4);
  std::vector<unsigned char> fw(fb);
  std::vector<cyc_rational_cubic_triangle> fp(24);
  int nf = 0;
  ASSERT_EQ(cyc_design_cyclide_surface(ctx, five.data(), 5, fan.data(), 4, nullptr, fw.data(),
                                       fb, nullptr, fp.data(), 24, &nf, nullptr),
            CYC_OK);
  EXPECT_EQ(nf, 24);
}

TEST_F(LaguerreCapi, DesignErrors) {
  const auto data = ellipsoid_cap(4, 0.6);
  const int n = int(data.size());
  const size_t bytes = cyc_design_workspace_size(n, 0);
  const int cap = cyc_design_max_patches(n, 0);
  std::vector<unsigned char> work(bytes);
  std::vector<cyc_rational_cubic_triangle> patches(cap);
  poison(patches[0]);
  int np = -1;
  cyc_design_report rep;
  // Workspace too small: the bytes needed come back.
  EXPECT_EQ(cyc_design_cyclide_surface(ctx, data.data(), n, nullptr, 0, nullptr, work.data(),
                                       bytes - 1, nullptr, patches.data(), cap, &np, &rep),
            CYC_E_BUFFER_TOO_SMALL);
  EXPECT_EQ(rep.work_needed, bytes);
  expect_message("cyc_design_cyclide_surface");
  // Too few patches: the count comes back.
  EXPECT_EQ(cyc_design_cyclide_surface(ctx, data.data(), n, nullptr, 0, nullptr, work.data(),
                                       bytes, nullptr, patches.data(), 2, &np, &rep),
            CYC_E_BUFFER_TOO_SMALL);
  EXPECT_GT(np, 2);
  EXPECT_EQ(np, rep.patches_needed);
  EXPECT_TRUE(poisoned(patches[0]));
  np = -1;
  // A NaN datum, a normal at W, W inside the normals' cone.
  auto bad = data;
  bad[3].point[1] = kNaN;
  EXPECT_EQ(cyc_design_cyclide_surface(ctx, bad.data(), n, nullptr, 0, nullptr, work.data(),
                                       bytes, nullptr, patches.data(), cap, &np, &rep),
            CYC_E_NOT_FINITE);
  EXPECT_EQ(rep.first_bad_datum, 3);
  bad = data;
  bad[5].normal[0] = 0, bad[5].normal[1] = 0, bad[5].normal[2] = 1;
  EXPECT_EQ(cyc_design_cyclide_surface(ctx, bad.data(), n, nullptr, 0, nullptr, work.data(),
                                       bytes, nullptr, patches.data(), cap, &np, &rep),
            CYC_E_POLE_IN_GAUSS_IMAGE);
  EXPECT_EQ(rep.first_bad_datum, 5);
  bad = data;
  for (auto& A : bad) A.normal[2] = -A.normal[2];  // the upper cap: W inside
  EXPECT_EQ(cyc_design_cyclide_surface(ctx, bad.data(), n, nullptr, 0, nullptr, work.data(),
                                       bytes, nullptr, patches.data(), cap, &np, &rep),
            CYC_E_POLE_IN_GAUSS_IMAGE);
  expect_message("cyc_design_cyclide_surface");
  // Collinear projections: normals in one plane through W.
  std::vector<cyc_oriented_point> line;
  for (int i = 0; i < 4; ++i) {
    cyc_oriented_point A;
    normal_of(0.2 * i - 0.3, 0, A.normal);
    for (int c = 0; c < 3; ++c) A.point[c] = A.normal[c];
    line.push_back(A);
  }
  std::vector<unsigned char> w4(cyc_design_workspace_size(4, 0));
  EXPECT_EQ(cyc_design_cyclide_surface(ctx, line.data(), 4, nullptr, 0, nullptr, w4.data(),
                                       w4.size(), nullptr, patches.data(), cap, &np, &rep),
            CYC_E_COLLINEAR_POINTS);
  // Two data with the same b_i.
  bad = data;
  bad[1].normal[0] = data[0].normal[0], bad[1].normal[1] = data[0].normal[1],
  bad[1].normal[2] = data[0].normal[2];
  EXPECT_EQ(cyc_design_cyclide_surface(ctx, bad.data(), n, nullptr, 0, nullptr, work.data(),
                                       bytes, nullptr, patches.data(), cap, &np, &rep),
            CYC_E_INVALID_ARGUMENT);
  // n, tri, NULL.
  EXPECT_EQ(cyc_design_cyclide_surface(ctx, data.data(), 2, nullptr, 0, nullptr, work.data(),
                                       bytes, nullptr, patches.data(), cap, &np, &rep),
            CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(cyc_design_cyclide_surface(ctx, data.data(), n, nullptr, 3, nullptr, work.data(),
                                       bytes, nullptr, patches.data(), cap, &np, &rep),
            CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(cyc_design_cyclide_surface(ctx, nullptr, n, nullptr, 0, nullptr, work.data(), bytes,
                                       nullptr, patches.data(), cap, &np, &rep),
            CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_design_cyclide_surface(ctx, data.data(), n, nullptr, 0, nullptr, work.data(),
                                       bytes, nullptr, nullptr, cap, &np, &rep),
            CYC_E_NULL_ARGUMENT);
  expect_message("cyc_design_cyclide_surface");
  EXPECT_EQ(np, -1);
  EXPECT_TRUE(poisoned(patches[0]));
  EXPECT_EQ(cyc_design_workspace_size(2, 0), 0u);
  EXPECT_EQ(cyc_design_max_patches(2, 0), 0);
}

// Fig. 3: data whose isotropic interpolant is a cubic graph fold: ridge,
// unless allowed (then counted).
TEST_F(LaguerreCapi, DesignReportsRidges) {
  std::vector<cyc_oriented_point> data;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      const double y1 = -0.8 + 1.6 * (i + 0.5) / 6, y2 = -0.8 + 1.6 * (j + 0.5) / 6;
      cyc_isotropic_datum d{{y1, y2}, 2 * y1 * y1 * y1 + 0.1 * y2 * y2, {6 * y1 * y1, 0.2 * y2}};
      cyc_oriented_point A;
      ASSERT_EQ(cyc_oriented_point_of(ctx, &d, &A), CYC_OK);
      data.push_back(A);
    }
  const int n = int(data.size());
  std::vector<unsigned char> work(cyc_design_workspace_size(n, 0));
  const int cap = cyc_design_max_patches(n, 0);
  std::vector<cyc_rational_cubic_triangle> patches(cap);
  poison(patches[0]);
  int np = -1;
  cyc_design_report rep;
  EXPECT_EQ(cyc_design_cyclide_surface(ctx, data.data(), n, nullptr, 0, nullptr, work.data(),
                                       work.size(), nullptr, patches.data(), cap, &np, &rep),
            CYC_E_RIDGE);
  EXPECT_GT(rep.ridge_patches, 0);
  EXPECT_GE(rep.first_ridge_patch, 0);
  EXPECT_TRUE(contains(cyc_context_last_error(ctx), "cyc_design_cyclide_surface"));
  EXPECT_EQ(np, -1);
  EXPECT_TRUE(poisoned(patches[0]));
  cyc_design_options o{1};
  ASSERT_EQ(cyc_design_cyclide_surface(ctx, data.data(), n, nullptr, 0, &o, work.data(),
                                       work.size(), nullptr, patches.data(), cap, &np, &rep),
            CYC_OK);
  EXPECT_GT(rep.ridge_patches, 0);
}

// The allocator is used only with work = NULL, and failure is reported.
struct Counting {
  int allocs = 0;
  bool refuse = false;
};
void* counting_alloc(void* ud, size_t size, size_t) {
  auto* c = static_cast<Counting*>(ud);
  ++c->allocs;
  return c->refuse ? nullptr : std::malloc(size);
}
void counting_free(void*, void* p) { std::free(p); }

TEST(LaguerreCapiAllocator, DesignWorkspaceFromTheContext) {
  Counting count;
  cyc_allocator a{counting_alloc, counting_free, &count};
  cyc_context* ctx = nullptr;
  ASSERT_EQ(cyc_context_create(&a, &ctx), CYC_OK);
  const int base = count.allocs;
  const auto data = ellipsoid_cap(5, 0.6);
  const int n = int(data.size());
  const int cap = cyc_design_max_patches(n, 0);
  std::vector<cyc_rational_cubic_triangle> patches(cap);
  int np = 0;
  ASSERT_EQ(cyc_design_cyclide_surface(ctx, data.data(), n, nullptr, 0, nullptr, nullptr, 0,
                                       nullptr, patches.data(), cap, &np, nullptr),
            CYC_OK);
  EXPECT_EQ(count.allocs, base + 1);
  count.refuse = true;
  np = -1;
  EXPECT_EQ(cyc_design_cyclide_surface(ctx, data.data(), n, nullptr, 0, nullptr, nullptr, 0,
                                       nullptr, patches.data(), cap, &np, nullptr),
            CYC_E_OUT_OF_MEMORY);
  EXPECT_TRUE(contains(cyc_context_last_error(ctx), "cyc_design_cyclide_surface"));
  EXPECT_EQ(np, -1);
  count.refuse = false;
  cyc_context_destroy(ctx);
}

}  // namespace

namespace {

// Thm. 3.2: Psi = the bilinear patch y = (y1, y2, c) (a plane of I^3, the
// paraboloid (2.4) of the cycle (m, r) = ((0, 0, -c), -c)... checked
// directly): every point x of Phi lies on its plane Lambda^{-1}(y), the
// normal is sigma^{-1}(y1, y2), orthogonal to the partials, and the offset
// at d is x + d n.
TEST_F(LaguerreCapi, PnSurfaceOfABilinearPsi) {
  // Bilinear over [-0.5, 0.5]^2 with y3 = 0.3 + 0.2 y1 - 0.1 y2 (a plane of I^3).
  double control[4 * 4];
  int k = 0;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const double y1 = -0.5 + i, y2 = -0.5 + j;
      control[k++] = 1, control[k++] = y1, control[k++] = y2;
      control[k++] = 0.3 + 0.2 * y1 - 0.1 * y2;
    }
  cyc_pn_surface* S = nullptr;
  ASSERT_EQ(cyc_pn_surface_create(ctx, 1, 1, control, &S), CYC_OK);
  for (double u : {0.0, 0.3, 1.0})
    for (double v : {0.2, 0.9}) {
      cyc_pn_point P, Q;
      ASSERT_EQ(cyc_pn_surface_eval(ctx, S, u, v, 0.0, &P), CYC_OK);
      const double y1 = -0.5 + u, y2 = -0.5 + v;
      double n[3];
      normal_of(y1, y2, n);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(P.normal[i], n[i], 1e-14);
      const double y3 = 0.3 + 0.2 * y1 - 0.1 * y2;
      const double N = 1 + y1 * y1 + y2 * y2;
      EXPECT_NEAR(2 * y3 / N + dot3(n, P.point), 0, 1e-13);
      EXPECT_NEAR(dot3(n, P.x_u), 0, 1e-12 * (1 + norm3(P.x_u)));
      EXPECT_NEAR(dot3(n, P.x_v), 0, 1e-12 * (1 + norm3(P.x_v)));
      ASSERT_EQ(cyc_pn_surface_eval(ctx, S, u, v, 0.7, &Q), CYC_OK);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(Q.point[i], P.point[i] + 0.7 * n[i], 1e-13);
    }
  // The grid equals the single evaluations.
  const double us[3] = {0, 0.5, 1}, vs[2] = {0.25, 0.75};
  double pts[18], nrm[18];
  size_t failed = 9;
  ASSERT_EQ(cyc_pn_surface_eval_grid(ctx, S, us, 3, vs, 2, 0.1, cyc_buffer3{pts, 6, 3},
                                     cyc_buffer3{nrm, 6, 3}, &failed),
            CYC_OK);
  EXPECT_EQ(failed, 0u);
  cyc_pn_point P;
  ASSERT_EQ(cyc_pn_surface_eval(ctx, S, us[2], vs[1], 0.1, &P), CYC_OK);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(pts[15 + i], P.point[i]);
  // Errors.
  poison(P);
  EXPECT_EQ(cyc_pn_surface_eval(ctx, S, 1.5, 0, 0, &P), CYC_E_BAD_DOMAIN);
  expect_message("cyc_pn_surface_eval");
  EXPECT_EQ(cyc_pn_surface_eval(ctx, S, kNaN, 0, 0, &P), CYC_E_NOT_FINITE);
  EXPECT_EQ(cyc_pn_surface_eval(ctx, S, 0, 0, kInf, &P), CYC_E_NOT_FINITE);
  EXPECT_TRUE(poisoned(P));
  double pts2[18];
  poison(pts2);
  EXPECT_EQ(cyc_pn_surface_eval_grid(ctx, S, us, 3, vs, 2, 0.1, cyc_buffer3{pts2, 5, 3},
                                     cyc_buffer3{nullptr, 0, 0}, nullptr),
            CYC_E_BUFFER_TOO_SMALL);
  const double bad_us[3] = {0, 2, 1};
  EXPECT_EQ(cyc_pn_surface_eval_grid(ctx, S, bad_us, 3, vs, 2, 0.1, cyc_buffer3{pts2, 6, 3},
                                     cyc_buffer3{nullptr, 0, 0}, nullptr),
            CYC_E_BAD_DOMAIN);
  expect_message("cyc_pn_surface_eval_grid");
  EXPECT_TRUE(poisoned(pts2));
  cyc_pn_surface_destroy(S);
  // A degenerate Psi (all points equal): developable everywhere.
  double point[16];
  for (int i = 0; i < 4; ++i) point[4 * i] = 1, point[4 * i + 1] = 0.1, point[4 * i + 2] = 0.2, point[4 * i + 3] = 0.3;
  cyc_pn_surface* D = nullptr;
  if (cyc_pn_surface_create(ctx, 1, 1, point, &D) == CYC_OK) {
    EXPECT_EQ(cyc_pn_surface_eval(ctx, D, 0.5, 0.5, 0, &P), CYC_E_DEVELOPABLE);
    cyc_pn_surface_destroy(D);
  }
  cyc_pn_surface* out = reinterpret_cast<cyc_pn_surface*>(uintptr_t(0x5eed));
  EXPECT_EQ(cyc_pn_surface_create(ctx, -1, 1, control, &out), CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(cyc_pn_surface_create(ctx, 9, 1, control, &out), CYC_E_DEGREE_TOO_HIGH);
  double w0[16];
  std::memcpy(w0, control, sizeof w0);
  w0[4] = 0;
  EXPECT_EQ(cyc_pn_surface_create(ctx, 1, 1, w0, &out), CYC_E_INVALID_ARGUMENT);
  w0[4] = kNaN;
  EXPECT_EQ(cyc_pn_surface_create(ctx, 1, 1, w0, &out), CYC_E_NOT_FINITE);
  EXPECT_EQ(cyc_pn_surface_create(ctx, 1, 1, nullptr, &out), CYC_E_NULL_ARGUMENT);
  expect_message("cyc_pn_surface_create");
  EXPECT_EQ(out, reinterpret_cast<cyc_pn_surface*>(uintptr_t(0x5eed)));
}

}  // namespace

// The parabolic cyclide as a circle-family surface through the one
// evaluator: cyc_surface_eval equals (4.1) (cyc_parabolic_cyclide_eval).
TEST_F(LaguerreCapi, ParabolicCyclideSurfaceIsItsCircleFamily) {
  cyc_parabolic_cyclide c;
  std::memset(&c, 0, sizeof c);
  c.a = 1.25;
  c.b = -0.5;
  c.frame[0] = c.frame[4] = c.frame[8] = 1;
  c.origin[0] = 2;
  cyc_surface* s = nullptr;
  ASSERT_EQ(cyc_parabolic_cyclide_surface_create(ctx, &c, -1.5, 1.5, &s), CYC_OK)
      << cyc_context_last_error(ctx);
  for (double u : {-1.5, -0.2, 0.7})
    for (double v : {-2.0, 0.0, 0.9, 30.0}) {
      double x[3], n[3], e[3], en[3];
      ASSERT_EQ(cyc_surface_eval(ctx, s, u, v, x, nullptr, nullptr, n), CYC_OK);
      ASSERT_EQ(cyc_parabolic_cyclide_eval(ctx, &c, u, v, e, en), CYC_OK);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(x[i], e[i], 1e-13 * (1 + std::abs(e[i])));
      EXPECT_NEAR(std::abs(n[0] * en[0] + n[1] * en[1] + n[2] * en[2]), 1.0, 1e-12);
    }
  cyc_surface_destroy(ctx, s);
  cyc_parabolic_cyclide horn = c;
  horn.a = 2;
  horn.b = 1;  // a u-circle of radius 0 at u = +-1
  cyc_surface* untouched = reinterpret_cast<cyc_surface*>(&horn);
  cyc_surface* t = untouched;
  EXPECT_EQ(cyc_parabolic_cyclide_surface_create(ctx, &horn, 0.5, 1.5, &t), CYC_E_SINGULAR_POINT);
  EXPECT_EQ(t, untouched);
  EXPECT_NE(std::strstr(cyc_context_last_error(ctx), "cyc_parabolic_cyclide_surface_create"),
            nullptr);
  EXPECT_EQ(cyc_parabolic_cyclide_surface_create(ctx, &c, 1, 0, &t), CYC_E_BAD_DOMAIN);
  EXPECT_EQ(cyc_parabolic_cyclide_surface_create(ctx, nullptr, 0, 1, &t), CYC_E_NULL_ARGUMENT);
}
