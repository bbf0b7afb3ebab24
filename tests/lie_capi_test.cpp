// Seed 003's Lie sphere geometry and Dupin cyclides through the C ABI
// (labels "lie;capi"): Lie spheres, subspaces, Witt extensions,
// transformations, cyclides from spheres (the torus and every degenerate
// case of §3.1), validation of caller-supplied cyc_dupin values, untouched
// outputs on error, all-or-nothing grids, the CYC_SURFACE_DUPIN handle and
// the context's allocator. Links cyclide_core too, to compare bits.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>

#include "cyclide/cyclide.h"
#include "cyclide/cyclide_blend.hpp"
#include "cyclide/dupin.hpp"
#include "cyclide/lie.hpp"
#include "hardening/lie_spheres.hpp"

using cyclide::DupinCyclide;
using cyclide::DupinPoint;
using cyclide::LieSphere;
using cyclide::Status;
using cyclide::Vec3d;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

// Fill any object with a byte pattern and check it is still there.
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

double norm3(const double* v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
double dot3(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Oriented spheres and planes as a host writes them (one copy, shared with
// the hardening tests).
using hostile::plane;
using hostile::sphere;

// |dist(x, z axis circle of radius R) - r| for a torus about the z axis.
double torus_residual(const double* x, double R, double r) {
  const double rho = std::hypot(x[0], x[1]) - R;
  return std::abs(std::hypot(rho, x[2]) - r);
}

struct LieCapi : ::testing::Test {
  cyc_context* ctx = nullptr;
  cyc_lie_sphere torus_spheres[3];
  void SetUp() override {
    ASSERT_EQ(cyc_context_create(nullptr, &ctx), CYC_OK);
    torus_spheres[0] = sphere(3, 0, 0, 1);
    torus_spheres[1] = sphere(0, 3, 0, 1);
    torus_spheres[2] = sphere(-3, 0, 0, 1);
  }
  void TearDown() override { cyc_context_destroy(ctx); }
  cyc_dupin torus() {
    cyc_dupin D;
    EXPECT_EQ(cyc_dupin_from_spheres(ctx, torus_spheres, &D), CYC_OK)
        << cyc_context_last_error(ctx);
    return D;
  }
  // Fails with `status`, the message naming the function, out untouched.
  void expect_fail(int got, int status, const char* fn) {
    EXPECT_EQ(got, status) << cyc_context_last_error(ctx);
    EXPECT_EQ(cyc_context_last_status(ctx), status);
    EXPECT_TRUE(contains(cyc_context_last_error(ctx), fn)) << cyc_context_last_error(ctx);
  }
};

const double kXis[] = {-7.0, -1.0, -0.3, 0.0, 0.25, 1.0, 2.5, 40.0};
const double kZetas[] = {-5.0, -1.0, 0.0, 0.5, 1.0, 3.0};

}  // namespace

// Statuses 119-126 have names (cyc_status_name missed them before this
// section existed: fuzz_lie's first run).
TEST(LieCapiStatus, Names) {
  EXPECT_STREQ(cyc_status_name(CYC_E_SPHERE_PENCIL), "CYC_E_SPHERE_PENCIL");
  EXPECT_STREQ(cyc_status_name(CYC_E_NO_TOUCHING_SPHERE), "CYC_E_NO_TOUCHING_SPHERE");
  EXPECT_STREQ(cyc_status_name(CYC_E_SINGLE_TOUCHING_SPHERE), "CYC_E_SINGLE_TOUCHING_SPHERE");
  EXPECT_STREQ(cyc_status_name(CYC_E_DEGENERATE_CYCLIDE), "CYC_E_DEGENERATE_CYCLIDE");
  EXPECT_STREQ(cyc_status_name(CYC_E_NOT_ISOMETRIC), "CYC_E_NOT_ISOMETRIC");
  EXPECT_STREQ(cyc_status_name(CYC_E_NOT_ON_LIE_QUADRIC), "CYC_E_NOT_ON_LIE_QUADRIC");
  EXPECT_STREQ(cyc_status_name(125), "CYC_E_POINT_AT_INFINITY");
  EXPECT_STREQ(cyc_status_name(CYC_E_TANGENT_GENERATING_SPHERES),
               "CYC_E_TANGENT_GENERATING_SPHERES");
  EXPECT_STREQ(cyc_status_name(127), "CYC_E_BLEND_FOLDS");
  EXPECT_STREQ(cyc_status_name(128), "CYC_E_DEVELOPABLE");
  EXPECT_STREQ(cyc_status_name(131), "CYC_E_UNKNOWN");
}

// ------------------------------------------------------------ Lie spheres

TEST_F(LieCapi, VectorsAndSpheresRoundTrip) {
  const cyc_lie_sphere in[4] = {sphere(1, -2, 0.5, -0.75), sphere(4, 5, 6, 0),
                                plane(0, 0, 2, 3), {CYC_LIE_POINT_AT_INFINITY, {0}, 0, {0}, 0}};
  const int kinds[4] = {CYC_LIE_SPHERE, CYC_LIE_POINT, CYC_LIE_PLANE, CYC_LIE_POINT_AT_INFINITY};
  for (int i = 0; i < 4; ++i) {
    double x[6], xx = 1;
    ASSERT_EQ(cyc_lie_vector(ctx, &in[i], x), CYC_OK);
    ASSERT_EQ(cyc_lie_dot(ctx, x, x, &xx), CYC_OK);
    EXPECT_NEAR(xx, 0.0, 1e-12);
    for (double scale : {1.0, -3.0, 1e-5}) {
      double y[6];
      for (int r = 0; r < 6; ++r) y[r] = scale * x[r];
      cyc_lie_sphere back;
      ASSERT_EQ(cyc_lie_sphere_of(ctx, y, &back), CYC_OK) << cyc_context_last_error(ctx);
      EXPECT_EQ(back.kind, kinds[i]);
      if (kinds[i] == CYC_LIE_SPHERE || kinds[i] == CYC_LIE_POINT) {
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(back.m[k], in[i].m[k], 1e-12);
        EXPECT_NEAR(back.rho, in[i].rho, 1e-12);
      }
      if (kinds[i] == CYC_LIE_PLANE) {
        EXPECT_NEAR(back.n[2], 1.0, 1e-12);
        EXPECT_NEAR(back.lambda, 1.5, 1e-12);  // 2z = 3 rescaled to |n| = 1
      }
    }
  }
  // Oriented contact: a sphere touching the plane z = 1.5 from below.
  double p[6], s[6], t[6];
  const cyc_lie_sphere below = sphere(0, 0, 1, 0.5), wrong = sphere(0, 0, 1, -0.5);
  ASSERT_EQ(cyc_lie_vector(ctx, &in[2], p), CYC_OK);
  ASSERT_EQ(cyc_lie_vector(ctx, &below, s), CYC_OK);
  ASSERT_EQ(cyc_lie_vector(ctx, &wrong, t), CYC_OK);
  int contact = -1;
  ASSERT_EQ(cyc_lie_in_contact(ctx, p, s, 1e-9, &contact), CYC_OK);
  EXPECT_EQ(contact, 1);
  ASSERT_EQ(cyc_lie_in_contact(ctx, p, t, 1e-9, &contact), CYC_OK);
  EXPECT_EQ(contact, 0);
  // The core's bits.
  double c[6];
  ASSERT_EQ(cyc_lie_vector(ctx, &in[0], c), CYC_OK);
  cyclide::Lie6d core;
  ASSERT_EQ(cyclide::lie_vector(cyclide::oriented_sphere({1, -2, 0.5}, -0.75), core), Status::ok);
  for (int r = 0; r < 6; ++r) EXPECT_EQ(c[r], core[r]);
}

TEST_F(LieCapi, LieSphereErrorsLeaveOutputsUntouched) {
  double x[6];
  cyc_lie_sphere bad = sphere(0, kNaN, 0, 1);
  poison(x);
  expect_fail(cyc_lie_vector(ctx, &bad, x), CYC_E_NOT_FINITE, "cyc_lie_vector");
  EXPECT_TRUE(poisoned(x));
  bad = plane(0, 0, 0, 1);
  expect_fail(cyc_lie_vector(ctx, &bad, x), CYC_E_INVALID_ARGUMENT, "cyc_lie_vector");
  EXPECT_TRUE(poisoned(x));
  bad.kind = 7;
  expect_fail(cyc_lie_vector(ctx, &bad, x), CYC_E_INVALID_ARGUMENT, "cyc_lie_vector");
  EXPECT_TRUE(contains(cyc_context_last_error(ctx), "kind = 7"));
  EXPECT_TRUE(poisoned(x));
  expect_fail(cyc_lie_vector(ctx, nullptr, x), CYC_E_NULL_ARGUMENT, "cyc_lie_vector");
  EXPECT_EQ(cyc_lie_vector(nullptr, &bad, x), CYC_E_NULL_ARGUMENT);
  EXPECT_TRUE(poisoned(x));
  // Non-neutral, zero and NaN vectors.
  cyc_lie_sphere out;
  poison(out);
  const double e1[6] = {1, 0, 0, 0, 0, 0}, zero[6] = {0}, nan6[6] = {0, 0, kNaN, 0, 0, 0};
  expect_fail(cyc_lie_sphere_of(ctx, e1, &out), CYC_E_NOT_ON_LIE_QUADRIC, "cyc_lie_sphere_of");
  expect_fail(cyc_lie_sphere_of(ctx, zero, &out), CYC_E_INVALID_ARGUMENT, "cyc_lie_sphere_of");
  expect_fail(cyc_lie_sphere_of(ctx, nan6, &out), CYC_E_NOT_FINITE, "cyc_lie_sphere_of");
  EXPECT_TRUE(poisoned(out));
  double d;
  poison(d);
  // Beyond the input range |x| <= 1e100 (SPEC §9b.2); within it the
  // product cannot overflow.
  const double big[6] = {1e300, 0, 0, 0, 0, 0};
  expect_fail(cyc_lie_dot(ctx, big, big, &d), CYC_E_NOT_FINITE, "cyc_lie_dot");
  int contact;
  poison(contact);
  expect_fail(cyc_lie_in_contact(ctx, e1, e1, -1.0, &contact), CYC_E_INVALID_ARGUMENT,
              "cyc_lie_in_contact");
  EXPECT_TRUE(poisoned(d));
  EXPECT_TRUE(poisoned(contact));
}

// ------------------------------------------------------------ subspaces

TEST_F(LieCapi, SpanComplementAndSignatures) {
  double v[18];
  for (int i = 0; i < 3; ++i) ASSERT_EQ(cyc_lie_vector(ctx, &torus_spheres[i], v + 6 * i), CYC_OK);
  int dim = -1, sig[3] = {-1, -1, -1};
  ASSERT_EQ(cyc_lie_span(ctx, v, 3, &dim, sig), CYC_OK);
  EXPECT_EQ(dim, 3);
  EXPECT_EQ(sig[0], 2);
  EXPECT_EQ(sig[1], 0);
  EXPECT_EQ(sig[2], 1);
  double basis[36];
  int cdim = -1, csig[3];
  ASSERT_EQ(cyc_lie_complement(ctx, v, 3, basis, &cdim, csig), CYC_OK);
  EXPECT_EQ(cdim, 3);
  EXPECT_EQ(csig[0], 2);
  EXPECT_EQ(csig[1], 0);
  EXPECT_EQ(csig[2], 1);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      double d = 1;
      ASSERT_EQ(cyc_lie_dot(ctx, basis + 6 * j, v + 6 * i, &d), CYC_OK);
      EXPECT_NEAR(d, 0.0, 1e-12 * norm3(v + 6 * i) * 10);
    }
  for (int k = 18; k < 36; ++k) EXPECT_EQ(basis[k], 0.0);
  // The empty span: the whole space R^{4,0,2}.
  ASSERT_EQ(cyc_lie_complement(ctx, nullptr, 0, nullptr, &cdim, csig), CYC_OK);
  EXPECT_EQ(cdim, 6);
  EXPECT_EQ(csig[0], 4);
  EXPECT_EQ(csig[2], 2);
  // Table 1 rule and impossible triples.
  const int s101[3] = {1, 0, 2};
  int out[3] = {-1, -1, -1};
  ASSERT_EQ(cyc_lie_complement_signature(ctx, s101, out), CYC_OK);
  EXPECT_EQ(out[0], 3);
  EXPECT_EQ(out[1], 0);
  EXPECT_EQ(out[2], 0);
  const int impossible[][3] = {{5, 0, 0}, {0, 3, 0}, {0, 0, 3}, {-1, 0, 0}, {3, 2, 0}};
  for (const auto& s : impossible) {
    int o[3] = {-7, -7, -7};
    expect_fail(cyc_lie_complement_signature(ctx, s, o), CYC_E_INVALID_ARGUMENT,
                "cyc_lie_complement_signature");
    EXPECT_EQ(o[0], -7);
  }
  poison(dim);
  expect_fail(cyc_lie_span(ctx, v, 7, &dim, sig), CYC_E_INVALID_ARGUMENT, "cyc_lie_span");
  v[3] = kNaN;
  expect_fail(cyc_lie_span(ctx, v, 3, &dim, sig), CYC_E_NOT_FINITE, "cyc_lie_span");
  EXPECT_TRUE(poisoned(dim));
}

TEST_F(LieCapi, WittExtensionThroughC) {
  // u: three torus spheres; w: their images under a Lie transformation.
  cyc_lie_transform A, B, T;
  const double c[3] = {1, 2, -1}, t[3] = {0.5, -1, 2};
  ASSERT_EQ(cyc_lie_transform_inversion(ctx, c, 2.0, &A), CYC_OK);
  ASSERT_EQ(cyc_lie_transform_translation(ctx, t, &B), CYC_OK);
  ASSERT_EQ(cyc_lie_transform_compose(ctx, &A, &B, &T), CYC_OK);
  double u[18], w[18];
  for (int i = 0; i < 3; ++i) {
    ASSERT_EQ(cyc_lie_vector(ctx, &torus_spheres[i], u + 6 * i), CYC_OK);
    for (int r = 0; r < 6; ++r) {
      double s = 0;
      for (int k = 0; k < 6; ++k) s += T.m[6 * r + k] * u[6 * i + k];
      w[6 * i + r] = s;
    }
  }
  double M[36], residual = -1;
  ASSERT_EQ(cyc_lie_witt_extension(ctx, u, w, 3, M, &residual), CYC_OK)
      << cyc_context_last_error(ctx);
  EXPECT_LT(residual, 1e-9);
  // Row-major: (M u_i)_r = sum_k M[6r + k] u_ik = w_ir.
  for (int i = 0; i < 3; ++i)
    for (int r = 0; r < 6; ++r) {
      double s = 0;
      for (int k = 0; k < 6; ++k) s += M[6 * r + k] * u[6 * i + k];
      EXPECT_NEAR(s, w[6 * i + r], 1e-9 * (1 + std::abs(w[6 * i + r])));
    }
  cyc_lie_transform MT;
  std::memcpy(MT.m, M, sizeof M);
  int lie = -1;
  ASSERT_EQ(cyc_lie_transform_classify(ctx, &MT, &lie, nullptr, nullptr), CYC_OK);
  EXPECT_EQ(lie, 1);
  // Not isometric: w scaled by 2 changes the Gram matrix; dependent u.
  for (double& x : w) x *= 2;
  double sentinel[36];
  poison(sentinel);
  expect_fail(cyc_lie_witt_extension(ctx, u, w, 3, sentinel, nullptr), CYC_E_NOT_ISOMETRIC,
              "cyc_lie_witt_extension");
  std::memcpy(u + 12, u, 6 * sizeof(double));
  expect_fail(cyc_lie_witt_extension(ctx, u, u, 3, sentinel, nullptr), CYC_E_RANK_DEFICIENT,
              "cyc_lie_witt_extension");
  expect_fail(cyc_lie_witt_extension(ctx, u, u, 0, sentinel, nullptr), CYC_E_INVALID_ARGUMENT,
              "cyc_lie_witt_extension");
  EXPECT_TRUE(poisoned(sentinel));
}

// ------------------------------------------------------------ transforms

TEST_F(LieCapi, TransformClassifyAndApply) {
  cyc_lie_transform T;
  int lie, lag, mob;
  const double t[3] = {1, -2, 3};
  ASSERT_EQ(cyc_lie_transform_translation(ctx, t, &T), CYC_OK);
  ASSERT_EQ(cyc_lie_transform_classify(ctx, &T, &lie, &lag, &mob), CYC_OK);
  EXPECT_EQ(lie + 2 * lag + 4 * mob, 7);  // Euclidean: both
  ASSERT_EQ(cyc_lie_transform_dilatation(ctx, 0.75, &T), CYC_OK);
  ASSERT_EQ(cyc_lie_transform_classify(ctx, &T, &lie, &lag, &mob), CYC_OK);
  EXPECT_EQ(lie + 2 * lag + 4 * mob, 3);  // Laguerre only
  const double c[3] = {0, 0, 0};
  ASSERT_EQ(cyc_lie_transform_inversion(ctx, c, 2.0, &T), CYC_OK);
  ASSERT_EQ(cyc_lie_transform_classify(ctx, &T, &lie, &lag, &mob), CYC_OK);
  EXPECT_EQ(lie + 2 * lag + 4 * mob, 5);  // Mobius only
  ASSERT_EQ(cyc_lie_transform_orientation_reversal(ctx, &T), CYC_OK);
  ASSERT_EQ(cyc_lie_transform_classify(ctx, &T, &lie, &lag, &mob), CYC_OK);
  EXPECT_EQ(lie, 1);
  const double R[9] = {0, -1, 0, 1, 0, 0, 0, 0, 1};
  ASSERT_EQ(cyc_lie_transform_rotation(ctx, R, &T), CYC_OK);
  ASSERT_EQ(cyc_lie_transform_classify(ctx, &T, &lie, &lag, &mob), CYC_OK);
  EXPECT_EQ(lie + 2 * lag + 4 * mob, 7);
  // A rotation by 90 degrees about z maps the sphere at (3,0,0) to (0,3,0).
  cyc_lie_sphere out;
  ASSERT_EQ(cyc_lie_transform_apply(ctx, &T, &torus_spheres[0], &out), CYC_OK);
  EXPECT_EQ(out.kind, CYC_LIE_SPHERE);
  EXPECT_NEAR(out.m[0], 0, 1e-12);
  EXPECT_NEAR(out.m[1], 3, 1e-12);
  EXPECT_NEAR(out.rho, 1, 1e-12);
  // An inversion maps a sphere through its center to a plane.
  const double ic[3] = {2, 0, 0};
  ASSERT_EQ(cyc_lie_transform_inversion(ctx, ic, 1.0, &T), CYC_OK);
  ASSERT_EQ(cyc_lie_transform_apply(ctx, &T, &torus_spheres[0], &out), CYC_OK);
  EXPECT_EQ(out.kind, CYC_LIE_PLANE);
  // Not orthogonal: not Lie.
  cyc_lie_transform S;
  ASSERT_EQ(cyc_lie_transform_translation(ctx, t, &S), CYC_OK);
  S.m[0] = 1.5;
  ASSERT_EQ(cyc_lie_transform_classify(ctx, &S, &lie, &lag, &mob), CYC_OK);
  EXPECT_EQ(lie + lag + mob, 0);
  // Errors leave outputs untouched.
  cyc_lie_transform U;
  poison(U);
  const double skew[9] = {1, 0.1, 0, 0, 1, 0, 0, 0, 1};
  expect_fail(cyc_lie_transform_rotation(ctx, skew, &U), CYC_E_INVALID_ARGUMENT,
              "cyc_lie_transform_rotation");
  expect_fail(cyc_lie_transform_scaling(ctx, 0.0, &U), CYC_E_INVALID_ARGUMENT,
              "cyc_lie_transform_scaling");
  expect_fail(cyc_lie_transform_scaling(ctx, -2.0, &U), CYC_E_INVALID_ARGUMENT,
              "cyc_lie_transform_scaling");
  expect_fail(cyc_lie_transform_inversion(ctx, ic, 0.0, &U), CYC_E_INVALID_ARGUMENT,
              "cyc_lie_transform_inversion");
  expect_fail(cyc_lie_transform_dilatation(ctx, kNaN, &U), CYC_E_NOT_FINITE,
              "cyc_lie_transform_dilatation");
  expect_fail(cyc_lie_transform_dilatation(ctx, 1e200, &U), CYC_E_NOT_FINITE,  // > 1e100
              "cyc_lie_transform_dilatation");
  S.m[7] = kNaN;
  expect_fail(cyc_lie_transform_compose(ctx, &S, &T, &U), CYC_E_NOT_FINITE,
              "cyc_lie_transform_compose");
  EXPECT_TRUE(poisoned(U));
  poison(out);
  expect_fail(cyc_lie_transform_apply(ctx, &S, &torus_spheres[0], &out), CYC_E_NOT_FINITE,
              "cyc_lie_transform_apply");
  EXPECT_TRUE(poisoned(out));
}

// ------------------------------------------------------------ Dupin cyclides

// The torus from the spheres (3,0,0), (0,3,0), (-3,0,0) of radius 1: points
// on the torus, unit normals, tangent planes x . n = lambda, the core's bits.
TEST_F(LieCapi, TorusFromSpheres) {
  const cyc_dupin D = torus();
  EXPECT_EQ(D.type, CYC_DUPIN_QUARTIC);
  int sig[3] = {-1, -1, -1};
  EXPECT_EQ(cyc_dupin_classify_spheres(ctx, torus_spheres, sig), CYC_OK);
  EXPECT_EQ(sig[0] * 100 + sig[1] * 10 + sig[2], 201);
  // The core's cyclide, bit for bit.
  const LieSphere s[3] = {cyclide::oriented_sphere({3, 0, 0}, 1),
                          cyclide::oriented_sphere({0, 3, 0}, 1),
                          cyclide::oriented_sphere({-3, 0, 0}, 1)};
  DupinCyclide C;
  ASSERT_EQ(cyclide::dupin_from_spheres(s, C), Status::ok);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) EXPECT_EQ(D.theta[6 * i + j], C.theta(i, j));
  for (double xi : kXis)
    for (double zeta : kZetas) {
      cyc_dupin_point P;
      ASSERT_EQ(cyc_dupin_eval(ctx, &D, xi, zeta, 0.0, &P), CYC_OK) << cyc_context_last_error(ctx);
      EXPECT_LE(torus_residual(P.point, 3, 1), 1e-12) << xi << " " << zeta;
      EXPECT_NEAR(norm3(P.normal), 1.0, 1e-13);
      EXPECT_NEAR(dot3(P.point, P.normal), P.lambda, 1e-12);
      EXPECT_NEAR(dot3(P.d_xi, P.normal), 0.0, 1e-10 * (1 + norm3(P.d_xi)));
      EXPECT_NEAR(dot3(P.d_zeta, P.normal), 0.0, 1e-10 * (1 + norm3(P.d_zeta)));
      DupinPoint Q;
      ASSERT_EQ(cyclide::dupin_eval(C, xi, zeta, 0.0, Q), Status::ok);
      for (int k = 0; k < 3; ++k) EXPECT_EQ(P.point[k], Q.point[k]);
      // The point lies on a(xi), touching it along the normal.
      cyc_lie_sphere a;
      const double t[2] = {xi, 1.0};
      ASSERT_EQ(cyc_dupin_sphere(ctx, &D, 0, t, &a), CYC_OK);
      ASSERT_EQ(a.kind, CYC_LIE_SPHERE);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(P.point[k] - a.rho * P.normal[k], a.m[k], 1e-11);
      // Offsets: the point c + d n, and the offset cyclide is a torus too.
      cyc_dupin_point O;
      ASSERT_EQ(cyc_dupin_eval(ctx, &D, xi, zeta, 0.25, &O), CYC_OK);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(O.point[k], P.point[k] + 0.25 * P.normal[k], 1e-12);
    }
  cyc_dupin E;
  ASSERT_EQ(cyc_dupin_offset(ctx, &D, 0.25, &E), CYC_OK);
  for (double xi : kXis) {
    cyc_dupin_point P, O;
    ASSERT_EQ(cyc_dupin_eval(ctx, &D, xi, 0.7, 0.25, &P), CYC_OK);
    ASSERT_EQ(cyc_dupin_eval(ctx, &E, xi, 0.7, 0.0, &O), CYC_OK);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(O.point[k], P.point[k], 1e-11);
  }
  // Swapped families: the same surface.
  cyc_dupin W;
  ASSERT_EQ(cyc_dupin_swap_families(ctx, &D, &W), CYC_OK);
  cyc_dupin_point P;
  ASSERT_EQ(cyc_dupin_eval(ctx, &W, 0.3, -2.0, 0.0, &P), CYC_OK);
  EXPECT_LE(torus_residual(P.point, 3, 1), 1e-12);
  // Homogeneous parameters at infinity and the grid.
  const double inf[2] = {1, 0}, z[2] = {0.5, 1};
  ASSERT_EQ(cyc_dupin_eval_homogeneous(ctx, &D, inf, z, 0.0, &P), CYC_OK);
  EXPECT_LE(torus_residual(P.point, 3, 1), 1e-12);
  double pts[3 * 8 * 6], nrm[3 * 8 * 6];
  ASSERT_EQ(cyc_dupin_eval_grid(ctx, &D, kXis, 8, kZetas, 6, 0.0, pts, nrm), CYC_OK);
  for (size_t i = 0; i < 8; ++i)
    for (size_t j = 0; j < 6; ++j) {
      ASSERT_EQ(cyc_dupin_eval(ctx, &D, kXis[i], kZetas[j], 0.0, &P), CYC_OK);
      EXPECT_EQ(std::memcmp(pts + 3 * (i * 6 + j), P.point, sizeof P.point), 0);
      EXPECT_EQ(std::memcmp(nrm + 3 * (i * 6 + j), P.normal, sizeof P.normal), 0);
    }
  // From vectors and from the subspace: the same surface.
  double a[18];
  for (int i = 0; i < 3; ++i) ASSERT_EQ(cyc_lie_vector(ctx, &torus_spheres[i], a + 6 * i), CYC_OK);
  cyc_dupin V, S;
  ASSERT_EQ(cyc_dupin_from_vectors(ctx, a, &V), CYC_OK);
  // The vectors are decoded to spheres first (SPEC §8h.3): the same
  // cyclide to rounding, no longer bit for bit.
  EXPECT_EQ(V.type, D.type);
  for (int k = 0; k < 36; ++k) EXPECT_NEAR(V.theta[k], D.theta[k], 1e-14) << k;
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(V.origin[k], D.origin[k], 1e-15) << k;
  int ssig[3];
  ASSERT_EQ(cyc_dupin_from_subspace(ctx, a, 3, &S, ssig), CYC_OK) << cyc_context_last_error(ctx);
  EXPECT_EQ(ssig[0] * 100 + ssig[1] * 10 + ssig[2], 201);
  for (double xi : {-1.0, 0.5, 2.0}) {
    ASSERT_EQ(cyc_dupin_eval(ctx, &S, xi, 0.3, 0.0, &P), CYC_OK);
    EXPECT_LE(torus_residual(P.point, 3, 1), 1e-12);
  }
}

// Every case of §3.1 with its status; nothing written on error.
TEST_F(LieCapi, DegenerateTriples) {
  struct Case {
    cyc_lie_sphere s[3];
    int status;
    int signature;  // p r q as a number, -1: untouched
  };
  const Case cases[] = {
      {{sphere(0, 0, 1, 1), sphere(0, 0, 2, 2), sphere(0, 0, -1, -1)}, CYC_E_SPHERE_PENCIL, 20},
      {{sphere(0, 0, 0, 10), sphere(0.5, 0, 0, 5), sphere(-0.3, 0, 0, 1)},
       CYC_E_NO_TOUCHING_SPHERE, 102},
      {{sphere(0, 0, 0, 1), sphere(3, 0, 0, -2), sphere(0, 5, 0, 1)},
       CYC_E_SINGLE_TOUCHING_SPHERE, 111},
      {{sphere(3, 0, 0, 1), sphere(3, 0, 0, 1), sphere(-3, 0, 0, 1)}, CYC_E_INVALID_ARGUMENT, -1},
      {{sphere(3, 0, 0, 1), sphere(0, kNaN, 0, 1), sphere(-3, 0, 0, 1)}, CYC_E_NOT_FINITE, -1},
      {{sphere(3, 0, 0, 1), plane(0, 0, 0, 1), sphere(-3, 0, 0, 1)}, CYC_E_INVALID_ARGUMENT, -1},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.status);
    int sig[3] = {-1, -1, -1};
    const int st = cyc_dupin_classify_spheres(ctx, c.s, sig);
    expect_fail(st, c.status, "cyc_dupin_classify_spheres");
    if (c.signature >= 0) {
      EXPECT_EQ(sig[0] * 100 + sig[1] * 10 + sig[2], c.signature);
    } else {
      EXPECT_EQ(sig[0], -1);
    }
    cyc_dupin out;
    poison(out);
    expect_fail(cyc_dupin_from_spheres(ctx, c.s, &out), c.status, "cyc_dupin_from_spheres");
    EXPECT_TRUE(poisoned(out));
  }
  // A non-neutral vector, a zero vector, NaN.
  double a[18];
  for (int i = 0; i < 3; ++i) ASSERT_EQ(cyc_lie_vector(ctx, &torus_spheres[i], a + 6 * i), CYC_OK);
  cyc_dupin out;
  poison(out);
  double b[18];
  std::memcpy(b, a, sizeof a);
  b[6] += 1.0;
  expect_fail(cyc_dupin_from_vectors(ctx, b, &out), CYC_E_NOT_ON_LIE_QUADRIC,
              "cyc_dupin_from_vectors");
  std::memcpy(b, a, sizeof a);
  for (int r = 0; r < 6; ++r) b[12 + r] = 0;
  expect_fail(cyc_dupin_from_vectors(ctx, b, &out), CYC_E_INVALID_ARGUMENT,
              "cyc_dupin_from_vectors");
  b[0] = kNaN;
  expect_fail(cyc_dupin_from_vectors(ctx, b, &out), CYC_E_NOT_FINITE, "cyc_dupin_from_vectors");
  // A subspace that is not PE: three nested spheres span R^{1,2}.
  const cyc_lie_sphere nested[3] = {sphere(0, 0, 0, 10), sphere(0.5, 0, 0, 5),
                                    sphere(-0.3, 0, 0, 1)};
  for (int i = 0; i < 3; ++i) ASSERT_EQ(cyc_lie_vector(ctx, &nested[i], b + 6 * i), CYC_OK);
  int sig[3] = {-1, -1, -1};
  expect_fail(cyc_dupin_from_subspace(ctx, b, 3, &out, sig), CYC_E_NOT_ISOMETRIC,
              "cyc_dupin_from_subspace");
  EXPECT_TRUE(contains(cyc_context_last_error(ctx), "signature"));
  EXPECT_EQ(sig[0], -1);
  expect_fail(cyc_dupin_from_subspace(ctx, a, 2, &out, sig), CYC_E_INVALID_ARGUMENT,
              "cyc_dupin_from_subspace");
  EXPECT_TRUE(poisoned(out));
}

// A caller's cyc_dupin is validated by every function taking it.
TEST_F(LieCapi, CorruptedCyclidesAreRejected) {
  const cyc_dupin good = torus();
  cyc_dupin bad[4] = {good, good, good, good};
  bad[0].theta[7] += 1e-3;  // not orthogonal
  bad[1].theta[20] = kNaN;
  bad[2].type = 9;
  bad[3].type = good.type == CYC_DUPIN_QUARTIC ? CYC_DUPIN_PARABOLIC : CYC_DUPIN_QUARTIC;
  const int expect[4] = {CYC_E_INVALID_ARGUMENT, CYC_E_NOT_FINITE, CYC_E_INVALID_ARGUMENT,
                         CYC_E_INVALID_ARGUMENT};
  for (int k = 0; k < 4; ++k) {
    SCOPED_TRACE(k);
    cyc_dupin_point P;
    cyc_dupin out;
    cyc_lie_sphere s;
    cyc_surface* h = nullptr;
    double pts[6];
    poison(P);
    poison(out);
    poison(s);
    poison(pts);
    const double t[2] = {0, 1}, xs[2] = {0, 1};
    expect_fail(cyc_dupin_eval(ctx, &bad[k], 0.1, 0.2, 0.0, &P), expect[k], "cyc_dupin_eval");
    expect_fail(cyc_dupin_eval_homogeneous(ctx, &bad[k], t, t, 0.0, &P), expect[k],
                "cyc_dupin_eval_homogeneous");
    expect_fail(cyc_dupin_sphere(ctx, &bad[k], 0, t, &s), expect[k], "cyc_dupin_sphere");
    expect_fail(cyc_dupin_offset(ctx, &bad[k], 0.5, &out), expect[k], "cyc_dupin_offset");
    expect_fail(cyc_dupin_swap_families(ctx, &bad[k], &out), expect[k], "cyc_dupin_swap_families");
    expect_fail(cyc_dupin_eval_grid(ctx, &bad[k], xs, 2, xs, 1, 0.0, pts, nullptr), expect[k],
                "cyc_dupin_eval_grid");
    expect_fail(cyc_dupin_surface_create(ctx, &bad[k], nullptr, nullptr, -1, 1, &h), expect[k],
                "cyc_dupin_surface_create");
    EXPECT_TRUE(poisoned(P));
    EXPECT_TRUE(poisoned(out));
    EXPECT_TRUE(poisoned(s));
    EXPECT_TRUE(poisoned(pts));
    EXPECT_EQ(h, nullptr);
  }
  EXPECT_TRUE(contains(cyc_context_last_error(ctx), "type"));
}

// The local origin (SPEC §8h.3, §8h.7): built far from 0 it is at the
// spheres (their best frame), the same bits as the core; a returned cyc_dupin round-trips
// through every function taking it (offset and swap keep the origin), a
// hand-set origin translates the cyclide, and NaN/Inf is CYC_E_NOT_FINITE.
TEST_F(LieCapi, OriginRoundTripsAndIsValidated) {
  const double t[3] = {6e3, -4.8e3, 6.4e3};  // |t| = 1e4
  cyc_lie_sphere far[3];
  for (int i = 0; i < 3; ++i) {
    far[i] = torus_spheres[i];
    for (int k = 0; k < 3; ++k) far[i].m[k] += t[k];
  }
  cyc_dupin D;
  ASSERT_EQ(cyc_dupin_from_spheres(ctx, far, &D), CYC_OK) << cyc_context_last_error(ctx);
  LieSphere s[3];
  for (int i = 0; i < 3; ++i)
    s[i] = cyclide::oriented_sphere(Vec3d(far[i].m[0], far[i].m[1], far[i].m[2]), far[i].rho);
  DupinCyclide C;
  ASSERT_EQ(cyclide::dupin_from_spheres(s, C), Status::ok);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(D.origin[k], C.origin[k]);
  }
  // The local origin is at the spheres (their best frame: the mean of the
  // centres or one of them, SPEC §8h.3), not at 0.
  EXPECT_LE(std::hypot(D.origin[0] - t[0], D.origin[1] - t[1], D.origin[2] - t[2]), 3 + 1e-11);
  cyc_dupin O, W, back;
  ASSERT_EQ(cyc_dupin_offset(ctx, &D, 0.25, &O), CYC_OK);
  ASSERT_EQ(cyc_dupin_swap_families(ctx, &D, &W), CYC_OK);
  ASSERT_EQ(cyc_dupin_swap_families(ctx, &W, &back), CYC_OK);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(O.origin[k], D.origin[k]);
    EXPECT_EQ(W.origin[k], D.origin[k]);
  }
  EXPECT_EQ(std::memcmp(&back, &D, sizeof D), 0);  // padding zeroed too
  for (double xi : kXis)
    for (double zeta : kZetas) {
      cyc_dupin_point P;
      ASSERT_EQ(cyc_dupin_eval(ctx, &D, xi, zeta, 0.0, &P), CYC_OK);
      DupinPoint Q;
      ASSERT_EQ(cyclide::dupin_eval(C, xi, zeta, 0.0, Q), Status::ok);
      for (int k = 0; k < 3; ++k) EXPECT_EQ(P.point[k], Q.point[k]);
      const double local[3] = {P.point[0] - t[0], P.point[1] - t[1], P.point[2] - t[2]};
      EXPECT_LE(torus_residual(local, 3, 1), 1e-12 * (1 + 1e4)) << xi << " " << zeta;
      EXPECT_NEAR(dot3(P.point, P.normal), P.lambda, 1e-12 * (1 + 1e4));
    }
  // A hand-set origin moves theta's cyclide by exactly that much.
  const cyc_dupin D0 = torus();
  cyc_dupin D1 = D0;
  const double shift[3] = {5, -7, 11};
  for (int k = 0; k < 3; ++k) D1.origin[k] = D0.origin[k] + shift[k];
  cyc_dupin_point P0, P1;
  ASSERT_EQ(cyc_dupin_eval(ctx, &D0, 0.3, -0.7, 0.5, &P0), CYC_OK);
  ASSERT_EQ(cyc_dupin_eval(ctx, &D1, 0.3, -0.7, 0.5, &P1), CYC_OK);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(P1.point[k] - P0.point[k], shift[k], 1e-13);
  EXPECT_NEAR(P1.lambda - P0.lambda, dot3(P0.normal, shift), 1e-13);
  // Non-finite origins.
  for (double bad : {kNaN, HUGE_VAL, -HUGE_VAL}) {
    cyc_dupin B = D0;
    B.origin[1] = bad;
    cyc_dupin_point P;
    cyc_dupin out;
    cyc_lie_sphere ls;
    cyc_surface* h = nullptr;
    poison(P);
    poison(out);
    poison(ls);
    const double tt[2] = {0, 1};
    expect_fail(cyc_dupin_eval(ctx, &B, 0.1, 0.2, 0.0, &P), CYC_E_NOT_FINITE, "cyc_dupin_eval");
    EXPECT_TRUE(contains(cyc_context_last_error(ctx), "origin"));
    expect_fail(cyc_dupin_sphere(ctx, &B, 0, tt, &ls), CYC_E_NOT_FINITE, "cyc_dupin_sphere");
    expect_fail(cyc_dupin_offset(ctx, &B, 0.5, &out), CYC_E_NOT_FINITE, "cyc_dupin_offset");
    expect_fail(cyc_dupin_swap_families(ctx, &B, &out), CYC_E_NOT_FINITE,
                "cyc_dupin_swap_families");
    expect_fail(cyc_dupin_surface_create(ctx, &B, nullptr, nullptr, -1, 1, &h), CYC_E_NOT_FINITE,
                "cyc_dupin_surface_create");
    EXPECT_TRUE(poisoned(P));
    EXPECT_TRUE(poisoned(out));
    EXPECT_TRUE(poisoned(ls));
    EXPECT_EQ(h, nullptr);
  }
}

// A cylinder (class I) has a point at infinity on every zeta-circle of one
// xi: eval fails there, and a grid containing that xi writes nothing.
TEST_F(LieCapi, GridIsAllOrNothing) {
  const cyc_lie_sphere s[3] = {sphere(0, 0, 0, 1), sphere(0, 0, 1, 1), sphere(0, 0, 2, 1)};
  cyc_dupin D;
  ASSERT_EQ(cyc_dupin_from_spheres(ctx, s, &D), CYC_OK) << cyc_context_last_error(ctx);
  EXPECT_EQ(D.type, CYC_DUPIN_DEGENERATE);
  // z(xi) is the Mobius map with z(0) = 0, z(inf) = 1, z(1) = 2: z = xi /
  // (xi - 1/2), infinite at xi = 1/2.
  cyc_dupin_point P;
  poison(P);
  expect_fail(cyc_dupin_eval(ctx, &D, 0.5, 0.3, 0.0, &P), CYC_E_POINT_AT_INFINITY,
              "cyc_dupin_eval");
  EXPECT_TRUE(poisoned(P));
  const double xis[3] = {0.0, 0.2, 0.5}, zetas[2] = {0.3, -1.0};
  double pts[18], nrm[18];
  poison(pts);
  poison(nrm);
  expect_fail(cyc_dupin_eval_grid(ctx, &D, xis, 3, zetas, 2, 0.0, pts, nrm),
              CYC_E_POINT_AT_INFINITY, "cyc_dupin_eval_grid");
  EXPECT_TRUE(poisoned(pts));
  EXPECT_TRUE(poisoned(nrm));
  // Without it: points on the cylinder x^2 + y^2 = 1.
  ASSERT_EQ(cyc_dupin_eval_grid(ctx, &D, xis, 2, zetas, 2, 0.0, pts, nullptr), CYC_OK);
  EXPECT_TRUE(poisoned(nrm));
  for (int k = 0; k < 4; ++k)
    EXPECT_NEAR(std::hypot(pts[3 * k], pts[3 * k + 1]), 1.0, 1e-12);
  // Empty grids and NULL arrays.
  EXPECT_EQ(cyc_dupin_eval_grid(ctx, &D, nullptr, 0, zetas, 2, 0.0, pts, nrm), CYC_OK);
  expect_fail(cyc_dupin_eval_grid(ctx, &D, nullptr, 2, zetas, 2, 0.0, pts, nrm),
              CYC_E_NULL_ARGUMENT, "cyc_dupin_eval_grid");
  const double nan_xis[2] = {0.0, kNaN};
  expect_fail(cyc_dupin_eval_grid(ctx, &D, nan_xis, 2, zetas, 2, 0.0, pts, nrm), CYC_E_NOT_FINITE,
              "cyc_dupin_eval_grid");
  expect_fail(cyc_dupin_eval_grid(ctx, &D, xis, SIZE_MAX / 2, zetas, 2, 0.0, pts, nrm),
              CYC_E_INVALID_ARGUMENT, "cyc_dupin_eval_grid");
  EXPECT_TRUE(poisoned(nrm));
  // Other evaluation errors.
  const double zero[2] = {0, 0}, one[2] = {0, 1};
  expect_fail(cyc_dupin_eval_homogeneous(ctx, &D, zero, one, 0.0, &P), CYC_E_INVALID_ARGUMENT,
              "cyc_dupin_eval_homogeneous");
  cyc_lie_sphere a;
  poison(a);
  expect_fail(cyc_dupin_sphere(ctx, &D, 2, one, &a), CYC_E_INVALID_ARGUMENT, "cyc_dupin_sphere");
  expect_fail(cyc_dupin_sphere(ctx, &D, 0, zero, &a), CYC_E_INVALID_ARGUMENT, "cyc_dupin_sphere");
  expect_fail(cyc_dupin_eval(ctx, &D, kNaN, 0, 0, &P), CYC_E_NOT_FINITE, "cyc_dupin_eval");
  EXPECT_TRUE(poisoned(a));
  EXPECT_TRUE(poisoned(P));
}

// ------------------------------------------------------------ surface handle

TEST_F(LieCapi, SurfaceHandleMatchesDupinEval) {
  const cyc_dupin D = torus();
  cyc_surface* S = nullptr;
  ASSERT_EQ(cyc_dupin_surface_create(ctx, &D, nullptr, nullptr, -2, 2, &S), CYC_OK)
      << cyc_context_last_error(ctx);
  int kind = 0;
  ASSERT_EQ(cyc_surface_kind(ctx, S, &kind), CYC_OK);
  EXPECT_EQ(kind, CYC_SURFACE_DUPIN);
  double u0 = 0, u1 = 0;
  ASSERT_EQ(cyc_surface_domain(ctx, S, &u0, &u1), CYC_OK);
  EXPECT_EQ(u0, -2);
  EXPECT_EQ(u1, 2);
  for (double u : {-1.5, -0.2, 0.0, 0.7, 2.0})
    for (double v : {-4.0, -1.0, 0.0, 0.5, 3.0}) {
      double x[3], n[3];
      ASSERT_EQ(cyc_surface_eval(ctx, S, u, v, x, nullptr, nullptr, n), CYC_OK)
          << cyc_context_last_error(ctx);
      cyc_dupin_point P;
      ASSERT_EQ(cyc_dupin_eval(ctx, &D, u, v, 0.0, &P), CYC_OK);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(x[k], P.point[k], 1e-12);
      EXPECT_NEAR(std::abs(dot3(n, P.normal)), 1.0, 1e-10);
    }
  cyc_surface_destroy(ctx, S);
  // Parameter maps: xi = 2u + 1, zeta = 1 / v  (0 v + 1) / (1 v + 0).
  const double xm[4] = {2, 1, 0, 1}, zm[4] = {0, 1, 1, 0};
  ASSERT_EQ(cyc_dupin_surface_create(ctx, &D, xm, zm, 0.1, 1, &S), CYC_OK)
      << cyc_context_last_error(ctx);
  double x[3];
  ASSERT_EQ(cyc_surface_eval(ctx, S, 0.5, 4.0, x, nullptr, nullptr, nullptr), CYC_OK);
  cyc_dupin_point P;
  ASSERT_EQ(cyc_dupin_eval(ctx, &D, 2.0, 0.25, 0.0, &P), CYC_OK);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(x[k], P.point[k], 1e-12);
  cyc_surface_destroy(ctx, S);
  // Errors: degenerate maps, domains; the handle untouched.
  cyc_surface* const kSentinel = reinterpret_cast<cyc_surface*>(uintptr_t(0x5eed0bad0000ull));
  S = kSentinel;
  const double flat[4] = {1, 2, 2, 4};
  expect_fail(cyc_dupin_surface_create(ctx, &D, flat, nullptr, 0, 1, &S), CYC_E_INVALID_ARGUMENT,
              "cyc_dupin_surface_create");
  expect_fail(cyc_dupin_surface_create(ctx, &D, nullptr, nullptr, 1, 0, &S), CYC_E_BAD_DOMAIN,
              "cyc_dupin_surface_create");
  EXPECT_EQ(S, kSentinel);
}

namespace {

// A counting allocator that can fail the n-th allocation.
struct Counting {
  long allocs = 0, frees = 0, fail_at = -1;
  static void* alloc(void* ud, size_t size, size_t alignment) {
    auto* c = static_cast<Counting*>(ud);
    if (c->allocs++ == c->fail_at) return nullptr;
    const size_t a = alignment < alignof(std::max_align_t) ? alignof(std::max_align_t) : alignment;
    return std::aligned_alloc(a, (size + a - 1) / a * a);
  }
  static void free(void* ud, void* p) {
    if (!p) return;
    ++static_cast<Counting*>(ud)->frees;
    std::free(p);
  }
};

}  // namespace

// The handle comes from the context's allocator; a failing allocator gives
// CYC_E_OUT_OF_MEMORY with nothing written; value functions never allocate.
TEST(LieCapiAlloc, ContextAllocatorAndOutOfMemory) {
  Counting C;
  const cyc_allocator A = {&Counting::alloc, &Counting::free, &C};
  cyc_context* ctx = nullptr;
  ASSERT_EQ(cyc_context_create(&A, &ctx), CYC_OK);
  const cyc_lie_sphere s[3] = {sphere(3, 0, 0, 1), sphere(0, 3, 0, 1), sphere(-3, 0, 0, 1)};
  const long base = C.allocs;
  cyc_dupin D;
  ASSERT_EQ(cyc_dupin_from_spheres(ctx, s, &D), CYC_OK);
  cyc_dupin_point P;
  ASSERT_EQ(cyc_dupin_eval(ctx, &D, 0.2, 0.3, 0.1, &P), CYC_OK);
  double pts[12];
  const double g[2] = {0, 1};
  ASSERT_EQ(cyc_dupin_eval_grid(ctx, &D, g, 2, g, 2, 0.0, pts, nullptr), CYC_OK);
  EXPECT_EQ(C.allocs, base);  // values: no allocation
  cyc_surface* S = nullptr;
  ASSERT_EQ(cyc_dupin_surface_create(ctx, &D, nullptr, nullptr, -1, 1, &S), CYC_OK);
  EXPECT_EQ(C.allocs, base + 1);
  const long frees = C.frees;
  cyc_surface_destroy(ctx, S);
  EXPECT_EQ(C.frees, frees + 1);
  // The only allocation fails.
  C.fail_at = C.allocs;
  cyc_surface* const kSentinel = reinterpret_cast<cyc_surface*>(uintptr_t(0x5eed0bad0000ull));
  S = kSentinel;
  EXPECT_EQ(cyc_dupin_surface_create(ctx, &D, nullptr, nullptr, -1, 1, &S), CYC_E_OUT_OF_MEMORY);
  EXPECT_TRUE(contains(cyc_context_last_error(ctx), "allocator returned NULL"));
  EXPECT_EQ(S, kSentinel);
  EXPECT_EQ(C.frees, frees + 1);
  cyc_context_destroy(ctx);
}

// ------------------------------------------- Algorithm 2 through the C ABI

// The elbow of two unit cylinders (Case I, a quarter torus) and a double
// blend of a cylinder and a cone: G1 at every circle, the pieces as
// surfaces agree with the core, statuses and untouched outputs on errors.
TEST_F(LieCapi, CyclideBlendsOfCones) {
  const double c1[3] = {0, 0, 0}, n1[3] = {0, 0, 1}, c2[3] = {3, 0, 3}, n2[3] = {-1, 0, 0};
  cyc_lie_cone R, S;
  ASSERT_EQ(cyc_cone_from_circle(ctx, c1, n1, 1, 0, 1, &R), CYC_OK);
  ASSERT_EQ(cyc_cone_from_circle(ctx, c2, n2, 1, 0, 1, &S), CYC_OK);
  int dim = 0;
  ASSERT_EQ(cyc_cyclide_blend_dimension(ctx, &R, &S, &dim), CYC_OK);
  EXPECT_EQ(dim, 3);
  cyc_cyclide_blend B;
  ASSERT_EQ(cyc_cyclide_blend_build(ctx, &R, &S, 1, 0.0, &B), CYC_OK);
  EXPECT_EQ(B.pieces, 1);
  cyc_cyclide_blend_report rep;
  ASSERT_EQ(cyc_cyclide_blend_continuity(ctx, &R, &S, &B, 16, &rep), CYC_OK);
  for (int j = 0; j < 3; ++j) {
    EXPECT_LE(rep.gap[j], 1e-12 * rep.scale);
    EXPECT_LE(rep.angle[j], 1e-12);
  }
  cyc_surface* P = nullptr;
  ASSERT_EQ(cyc_cyclide_blend_surface_create(ctx, &B, 0, &P), CYC_OK);
  for (double u : {0.0, 0.4, 1.0}) {
    double x[3];
    ASSERT_EQ(cyc_surface_eval(ctx, P, u, 0.7, x, nullptr, nullptr, nullptr), CYC_OK);
    EXPECT_NEAR(std::hypot(std::hypot(x[0] - 3, x[2]) - 3, x[1]), 1.0, 1e-12);  // the torus
  }
  cyc_surface_destroy(ctx, P);
  // The same through the core, bit for bit.
  cyclide::LieCone Rc, Sc;
  ASSERT_EQ(cyclide::cone_from_circle({0, 0, 0}, {0, 0, 1}, 1, 0, 1, Rc), cyclide::Status::ok);
  ASSERT_EQ(cyclide::cone_from_circle({3, 0, 3}, {-1, 0, 0}, 1, 0, 1, Sc), cyclide::Status::ok);
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(R.r0[i], Rc.r0[i]);
    EXPECT_EQ(R.r_plus[i], Rc.r_plus[i]);
  }
  // A double blend chosen automatically.
  const double c3[3] = {4, 3, 1}, n3[3] = {-1, -0.2, 0.1};
  const double c0[3] = {-3, 0, 0}, n0[3] = {1, 0, 0};
  ASSERT_EQ(cyc_cone_from_circle(ctx, c0, n0, 1, 0, 1, &R), CYC_OK);
  ASSERT_EQ(cyc_cone_from_circle(ctx, c3, n3, 0.8, 0.3, 1, &S), CYC_OK);
  double q = 0;
  ASSERT_EQ(cyc_cyclide_blend_auto(ctx, &R, &S, 32, &B, &q), CYC_OK);
  EXPECT_EQ(B.pieces, 2);
  EXPECT_GT(q, 0.0);
  double q2 = -1;
  ASSERT_EQ(cyc_cyclide_blend_quality(ctx, &B, &q2), CYC_OK);
  EXPECT_EQ(q, q2);
  ASSERT_EQ(cyc_cyclide_blend_continuity(ctx, &R, &S, &B, 16, &rep), CYC_OK);
  for (int j = 0; j < 3; ++j) {
    EXPECT_LE(rep.gap[j], 1e-9 * rep.scale);
    EXPECT_LE(rep.angle[j], 1e-9);
  }
  double beta = 0;
  ASSERT_EQ(cyc_cyclide_blend_beta(ctx, &R, &S, B.branch, B.alpha, &beta), CYC_OK);
  EXPECT_EQ(beta, B.beta);
  // Errors leave outputs untouched.
  cyc_cyclide_blend sentinel;
  std::memset(&sentinel, 0x5a, sizeof sentinel);
  cyc_cyclide_blend out = sentinel;
  EXPECT_EQ(cyc_cyclide_blend_build(ctx, &R, &R, 1, 0.0, &out), CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(std::memcmp(&out, &sentinel, sizeof out), 0);
  EXPECT_EQ(cyc_cyclide_blend_auto(ctx, &R, &S, 4, &out, nullptr), CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(std::memcmp(&out, &sentinel, sizeof out), 0);
  const double t1[3] = {0, 0, 2}, t2[3] = {0, 0, -1};
  cyc_lie_cone T1, T2;
  ASSERT_EQ(cyc_cone_from_circle(ctx, c1, n1, 1, 0, 1, &T1), CYC_OK);
  ASSERT_EQ(cyc_cone_from_circle(ctx, t1, t2, 1, 0, -1, &T2), CYC_OK);
  EXPECT_EQ(cyc_cyclide_blend_build(ctx, &T1, &T2, 1, 0.0, &out),
            CYC_E_TANGENT_GENERATING_SPHERES);
  EXPECT_EQ(std::memcmp(&out, &sentinel, sizeof out), 0);
  cyc_lie_cone bad = R;
  bad.r0[0] += 1;  // not neutral
  EXPECT_EQ(cyc_cyclide_blend_dimension(ctx, &bad, &S, &dim), CYC_E_NOT_ON_LIE_QUADRIC);
  cyc_cyclide_blend corrupt = B;
  corrupt.piece[1].theta[7] += 0.5;  // not in O(4,2)
  EXPECT_EQ(cyc_cyclide_blend_quality(ctx, &corrupt, &q2), CYC_E_INVALID_ARGUMENT);
  corrupt = B;
  corrupt.pieces = 3;
  EXPECT_EQ(cyc_cyclide_blend_surface_create(ctx, &corrupt, 0, &P), CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(cyc_cyclide_blend_surface_create(ctx, &B, 2, &P), CYC_E_INVALID_ARGUMENT);
  // A cone from a Dupin surface (canal), and a ringed surface has none.
  cyc_surface* tor = nullptr;
  cyc_dupin D;
  cyc_lie_sphere sp[3];
  const double cs[3][3] = {{3, 0, 0}, {0, 3, 0}, {-3, 0, 0}};
  for (int i = 0; i < 3; ++i) sp[i] = sphere(cs[i][0], cs[i][1], cs[i][2], 1);
  ASSERT_EQ(cyc_dupin_from_spheres(ctx, sp, &D), CYC_OK);
  ASSERT_EQ(cyc_dupin_surface_create(ctx, &D, nullptr, nullptr, -0.5, 0.5, &tor), CYC_OK);
  cyc_lie_cone K;
  ASSERT_EQ(cyc_cone_from_surface(ctx, tor, 0.5, 1, 1, &K), CYC_OK);
  double cc[3], nn[3], rr = 0;
  ASSERT_EQ(cyc_cone_circle(ctx, &K, cc, nn, &rr), CYC_OK);
  EXPECT_NEAR(rr, 1.0, 1e-12);  // the torus' meridian circles have radius 1
  cyc_surface_destroy(ctx, tor);
}
