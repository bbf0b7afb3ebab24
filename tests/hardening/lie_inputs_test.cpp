// What a hostile host may pass to seed 003's entry points (Lie spheres,
// subspaces, transforms, Dupin cyclides, cones and Algorithm 2 blends;
// SPEC §8h.7, §9b.2): integer arguments and fields at INT_MIN, -1 and
// INT_MAX, and every double input NaN, infinite or beyond 1e100. Each call
// must return its own status, a message naming the argument or field, and
// leave its outputs untouched. C ABI only.
#include <gtest/gtest.h>

#include <climits>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "cyclide/cyclide.h"
#include "lie_spheres.hpp"
#include "hostile.hpp"

namespace {

using namespace hostile;

const int kBadInts[] = {INT_MIN, -1, INT_MAX};
const int kBadSigns[] = {INT_MIN, 0, 2, INT_MAX};  // for arguments that are +1 or -1

struct LieInputs : ::testing::Test {
  cyc_context* ctx = nullptr;
  cyc_lie_sphere torus[3];
  cyc_dupin D;
  cyc_lie_cone R, S;       // a double blend's cones (dim(R + S) = 4)
  cyc_cyclide_blend B2;    // their blend
  void SetUp() override {
    ASSERT_EQ(cyc_context_create(nullptr, &ctx), CYC_OK);
    torus[0] = sphere(3, 0, 0, 1);
    torus[1] = sphere(0, 3, 0, 1);
    torus[2] = sphere(-3, 0, 0, 1);
    ASSERT_EQ(cyc_dupin_from_spheres(ctx, torus, &D), CYC_OK);
    const double c0[3] = {-3, 0, 0}, n0[3] = {1, 0, 0};
    const double c1[3] = {4, 3, 1}, n1[3] = {-1, -0.2, 0.1};
    ASSERT_EQ(cyc_cone_from_circle(ctx, c0, n0, 1, 0, 1, &R), CYC_OK);
    ASSERT_EQ(cyc_cone_from_circle(ctx, c1, n1, 0.8, 0.3, 1, &S), CYC_OK);
    int dim = 0;
    ASSERT_EQ(cyc_cyclide_blend_dimension(ctx, &R, &S, &dim), CYC_OK);
    ASSERT_EQ(dim, 4);
    ASSERT_EQ(cyc_cyclide_blend_auto(ctx, &R, &S, 16, &B2, nullptr), CYC_OK);
    ASSERT_EQ(B2.pieces, 2);
  }
  void TearDown() override { cyc_context_destroy(ctx); }

  // The call's status is `status`, and its message names fn and every
  // string of `names` (the argument or field, and whatever else it must say).
  void expect(int got, int status, const char* fn, std::initializer_list<const char*> names) {
    EXPECT_EQ(got, status) << cyc_context_last_error(ctx);
    EXPECT_EQ(cyc_context_last_status(ctx), status);
    const std::string msg = cyc_context_last_error(ctx);
    EXPECT_NE(msg.find(fn), std::string::npos) << msg;
    for (const char* n : names) EXPECT_NE(msg.find(n), std::string::npos) << n << " in: " << msg;
  }
};

// ------------------------------------------------- integers (SPEC §9b.2)

// (2, INT_MAX, 1): p + r <= 4 wrapped and the call returned OK with garbage.
TEST_F(LieInputs, ComplementSignatureCountsNearIntMaxAreRefused) {
  for (int slot = 0; slot < 3; ++slot)
    for (int bad : kBadInts) {
      int sig[3] = {2, 0, 1};
      sig[slot] = bad;
      int out[3] = {7, 7, 7};
      const char* names[3] = {"signature[0]", "signature[1]", "signature[2]"};
      expect(cyc_lie_complement_signature(ctx, sig, out), CYC_E_INVALID_ARGUMENT,
             "cyc_lie_complement_signature", {names[slot]});
      EXPECT_EQ(out[0], 7);
      EXPECT_EQ(out[1], 7);
      EXPECT_EQ(out[2], 7);
    }
  // The reported input, and pairs whose sum wraps.
  const int reported[3] = {2, INT_MAX, 1};
  int out[3] = {7, 7, 7};
  EXPECT_EQ(cyc_lie_complement_signature(ctx, reported, out), CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(out[0], 7);
  const int wrap[3] = {INT_MAX, INT_MAX, 0};
  EXPECT_EQ(cyc_lie_complement_signature(ctx, wrap, out), CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(out[0], 7);
  // Within the bounds the rule still decides: (4, 2, 0) has p + r = 6 > 4.
  const int too_big[3] = {4, 2, 0};
  expect(cyc_lie_complement_signature(ctx, too_big, out), CYC_E_INVALID_ARGUMENT,
         "cyc_lie_complement_signature", {"(4, 2, 0)"});
  const int fine[3] = {2, 0, 1};
  ASSERT_EQ(cyc_lie_complement_signature(ctx, fine, out), CYC_OK);
  EXPECT_EQ(out[0], 2);
  EXPECT_EQ(out[1], 0);
  EXPECT_EQ(out[2], 1);
}

TEST_F(LieInputs, VectorCountsOutsideTheirRangeAreRefused) {
  double v[36] = {0};
  for (int i = 0; i < 6; ++i) v[7 * i] = 1;  // e1 .. er
  for (int bad : kBadInts) {
    int dim = -7, sig[3] = {7, 7, 7};
    expect(cyc_lie_span(ctx, v, bad, &dim, sig), CYC_E_INVALID_ARGUMENT, "cyc_lie_span", {"k = "});
    EXPECT_EQ(dim, -7);
    EXPECT_EQ(sig[0], 7);
    double basis[36];
    poison(basis);
    expect(cyc_lie_complement(ctx, v, bad, basis, &dim, sig), CYC_E_INVALID_ARGUMENT,
           "cyc_lie_complement", {"k = "});
    EXPECT_TRUE(poisoned(basis));
    double T[36], res = -7;
    poison(T);
    expect(cyc_lie_witt_extension(ctx, v, v, bad, T, &res), CYC_E_INVALID_ARGUMENT,
           "cyc_lie_witt_extension", {"k = "});
    EXPECT_TRUE(poisoned(T));
    EXPECT_EQ(res, -7);
    cyc_dupin out;
    poison(out);
    expect(cyc_dupin_from_subspace(ctx, v, bad, &out, sig), CYC_E_INVALID_ARGUMENT,
           "cyc_dupin_from_subspace", {"k = "});
    EXPECT_TRUE(poisoned(out));
  }
  int dim = -7;
  expect(cyc_lie_span(ctx, v, 7, &dim, nullptr), CYC_E_INVALID_ARGUMENT, "cyc_lie_span", {"k = 7"});
  ASSERT_EQ(cyc_lie_span(ctx, v, 6, &dim, nullptr), CYC_OK);
  EXPECT_EQ(dim, 6);
}

TEST_F(LieInputs, KindsTypesFamiliesAndIndicesOutsideTheirRangeAreRefused) {
  for (int bad : kBadInts) {
    cyc_lie_sphere s = torus[0];
    s.kind = bad;
    double x[6];
    poison(x);
    expect(cyc_lie_vector(ctx, &s, x), CYC_E_INVALID_ARGUMENT, "cyc_lie_vector", {"sphere.kind"});
    EXPECT_TRUE(poisoned(x));

    cyc_dupin E = D;
    E.type = bad;
    cyc_dupin_point P;
    poison(P);
    expect(cyc_dupin_eval(ctx, &E, 0.5, 0.5, 0, &P), CYC_E_INVALID_ARGUMENT, "cyc_dupin_eval",
           {"cyclide.type"});
    EXPECT_TRUE(poisoned(P));

    const double t[2] = {1, 1};
    cyc_lie_sphere out;
    poison(out);
    expect(cyc_dupin_sphere(ctx, &D, bad, t, &out), CYC_E_INVALID_ARGUMENT, "cyc_dupin_sphere",
           {"family"});
    EXPECT_TRUE(poisoned(out));

    cyc_cyclide_blend B = B2;
    B.pieces = bad;
    double q = -7;
    expect(cyc_cyclide_blend_quality(ctx, &B, &q), CYC_E_INVALID_ARGUMENT,
           "cyc_cyclide_blend_quality", {"blend.pieces"});
    EXPECT_EQ(q, -7);
    double c[3], n[3], r = -7;
    poison(c);
    expect(cyc_cyclide_blend_circle(ctx, &B2, bad, 0, 0.5, c, n, &r), CYC_E_INVALID_ARGUMENT,
           "cyc_cyclide_blend_circle", {"piece"});
    expect(cyc_cyclide_blend_circle(ctx, &B2, 0, bad, 0.5, c, n, &r), CYC_E_INVALID_ARGUMENT,
           "cyc_cyclide_blend_circle", {"family"});
    EXPECT_TRUE(poisoned(c));
    EXPECT_EQ(r, -7);
    cyc_surface* surf = nullptr;
    expect(cyc_cyclide_blend_surface_create(ctx, &B2, bad, &surf), CYC_E_INVALID_ARGUMENT,
           "cyc_cyclide_blend_surface_create", {"piece"});
    EXPECT_EQ(surf, nullptr);

    cyc_cyclide_blend out_blend;
    poison(out_blend);
    expect(cyc_cyclide_blend_auto(ctx, &R, &S, bad, &out_blend, &q), CYC_E_INVALID_ARGUMENT,
           "cyc_cyclide_blend_auto", {"samples"});
    cyc_cyclide_blend_report rep;
    poison(rep);
    expect(cyc_cyclide_blend_continuity(ctx, &R, &S, &B2, bad, &rep), CYC_E_INVALID_ARGUMENT,
           "cyc_cyclide_blend_continuity", {"n = "});
    EXPECT_TRUE(poisoned(rep));
  }
  for (int bad : kBadSigns) {
    double q = -7;
    cyc_cyclide_blend out_blend;
    poison(out_blend);
    // A double blend's branch of (43) is +1 or -1; the field was not read.
    cyc_cyclide_blend B = B2;
    B.branch = bad;
    expect(cyc_cyclide_blend_quality(ctx, &B, &q), CYC_E_INVALID_ARGUMENT,
           "cyc_cyclide_blend_quality", {"blend.branch"});
    EXPECT_EQ(q, -7);

    expect(cyc_cyclide_blend_build(ctx, &R, &S, bad, 0.0, &out_blend), CYC_E_INVALID_ARGUMENT,
           "cyc_cyclide_blend_build", {"branch"});
    double beta = -7;
    expect(cyc_cyclide_blend_beta(ctx, &R, &S, bad, 0.0, &beta), CYC_E_INVALID_ARGUMENT,
           "cyc_cyclide_blend_beta", {"branch"});
    EXPECT_EQ(beta, -7);
    EXPECT_TRUE(poisoned(out_blend));
    const double cc[3] = {0, 0, 0}, nn[3] = {0, 0, 1}, apex[3] = {0, 0, 3};
    cyc_lie_cone K;
    poison(K);
    expect(cyc_cone_from_circle(ctx, cc, nn, 1, 0.2, bad, &K), CYC_E_INVALID_ARGUMENT,
           "cyc_cone_from_circle", {"orientation"});
    expect(cyc_cone_from_circle_apex(ctx, cc, nn, 1, apex, bad, &K), CYC_E_INVALID_ARGUMENT,
           "cyc_cone_from_circle_apex", {"orientation"});
    EXPECT_TRUE(poisoned(K));
  }
}

// Grid sizes beyond the address space (an array that cannot exist, a
// product that wraps, 3 doubles per point past PTRDIFF_MAX bytes) are
// refused before anything is read, evaluated or written.
TEST_F(LieInputs, GridSizesWhoseProductOverflowsAreRefused) {
  const double xs[1] = {0.5};
  double pts[3];
  poison(pts);
  const size_t big = SIZE_MAX / 2;
  expect(cyc_dupin_eval_grid(ctx, &D, xs, big, xs, 3, 0, pts, nullptr), CYC_E_INVALID_ARGUMENT,
         "cyc_dupin_eval_grid", {"xis"});
  expect(cyc_dupin_eval_grid(ctx, &D, xs, 1, xs, SIZE_MAX / 3 + 1, 0, pts, nullptr),
         CYC_E_INVALID_ARGUMENT, "cyc_dupin_eval_grid", {"zetas"});
  expect(cyc_dupin_eval_grid(ctx, &D, xs, size_t(1) << 30, xs, size_t(1) << 30, 0, pts, nullptr),
         CYC_E_INVALID_ARGUMENT, "cyc_dupin_eval_grid", {"points"});
  EXPECT_TRUE(poisoned(pts));
}

// ------------------------------------------ doubles (SPEC §9b.2, 8h.7)
//
// Every double input goes through the shared checks: NaN, infinite or
// beyond |x| <= 1e100 is CYC_E_NOT_FINITE naming the argument, its index or
// the struct field.

TEST_F(LieInputs, LieSphereFieldsOfTheirKindAreCheckedAndNamed) {
  for (double bad : kBadDoubles) {
    double x[6];
    poison(x);
    cyc_lie_sphere s = torus[0];
    s.m[1] = bad;
    expect(cyc_lie_vector(ctx, &s, x), CYC_E_NOT_FINITE, "cyc_lie_vector", {"sphere.m[1]"});
    s = torus[0];
    s.rho = bad;
    expect(cyc_lie_vector(ctx, &s, x), CYC_E_NOT_FINITE, "cyc_lie_vector", {"sphere.rho"});
    s = plane(0, 0, 1, 2);
    s.n[2] = bad;
    expect(cyc_lie_vector(ctx, &s, x), CYC_E_NOT_FINITE, "cyc_lie_vector", {"sphere.n[2]"});
    s = plane(0, 0, 1, 2);
    s.lambda = bad;
    expect(cyc_lie_vector(ctx, &s, x), CYC_E_NOT_FINITE, "cyc_lie_vector", {"sphere.lambda"});
    EXPECT_TRUE(poisoned(x));
    // Fields of another kind are not read.
    s = plane(0, 0, 1, 2);
    s.rho = bad;
    s.m[0] = bad;
    EXPECT_EQ(cyc_lie_vector(ctx, &s, x), CYC_OK);
    poison(x);

    cyc_lie_sphere trio[3] = {torus[0], torus[1], torus[2]};
    trio[2].rho = bad;
    cyc_dupin out;
    poison(out);
    expect(cyc_dupin_from_spheres(ctx, trio, &out), CYC_E_NOT_FINITE, "cyc_dupin_from_spheres",
           {"spheres[2].rho"});
    int sig[3] = {7, 7, 7};
    expect(cyc_dupin_classify_spheres(ctx, trio, sig), CYC_E_NOT_FINITE,
           "cyc_dupin_classify_spheres", {"spheres[2].rho"});
    EXPECT_EQ(sig[0], 7);
    EXPECT_TRUE(poisoned(out));
  }
  cyc_lie_sphere flat = plane(0, 0, 0, 1);
  double x[6];
  expect(cyc_lie_vector(ctx, &flat, x), CYC_E_INVALID_ARGUMENT, "cyc_lie_vector",
         {"sphere.n = 0"});
}

TEST_F(LieInputs, VectorsAndTransformsAreCheckedPerEntry) {
  double v[18];
  ASSERT_EQ(cyc_lie_vector(ctx, &torus[0], v), CYC_OK);
  ASSERT_EQ(cyc_lie_vector(ctx, &torus[1], v + 6), CYC_OK);
  ASSERT_EQ(cyc_lie_vector(ctx, &torus[2], v + 12), CYC_OK);
  for (double bad : kBadDoubles) {
    double w[18];
    std::memcpy(w, v, sizeof w);
    w[8] = bad;  // vector 1, entry 2
    int dim = -7;
    expect(cyc_lie_span(ctx, w, 3, &dim, nullptr), CYC_E_NOT_FINITE, "cyc_lie_span",
           {"vectors[1][2]"});
    expect(cyc_lie_complement(ctx, w, 3, nullptr, &dim, nullptr), CYC_E_NOT_FINITE,
           "cyc_lie_complement", {"vectors[1][2]"});
    EXPECT_EQ(dim, -7);
    double T[36];
    poison(T);
    expect(cyc_lie_witt_extension(ctx, v, w, 3, T, nullptr), CYC_E_NOT_FINITE,
           "cyc_lie_witt_extension", {"w[1][2]"});
    expect(cyc_lie_witt_extension(ctx, w, v, 3, T, nullptr), CYC_E_NOT_FINITE,
           "cyc_lie_witt_extension", {"u[1][2]"});
    EXPECT_TRUE(poisoned(T));
    cyc_dupin out;
    poison(out);
    expect(cyc_dupin_from_vectors(ctx, w, &out), CYC_E_NOT_FINITE, "cyc_dupin_from_vectors",
           {"a[1][2]"});
    expect(cyc_dupin_from_subspace(ctx, w, 3, &out, nullptr), CYC_E_NOT_FINITE,
           "cyc_dupin_from_subspace", {"span[1][2]"});
    EXPECT_TRUE(poisoned(out));
    double d = -7;
    expect(cyc_lie_dot(ctx, v, w + 6, &d), CYC_E_NOT_FINITE, "cyc_lie_dot", {"y[2]"});
    expect(cyc_lie_dot(ctx, w + 6, v, &d), CYC_E_NOT_FINITE, "cyc_lie_dot", {"x[2]"});
    EXPECT_EQ(d, -7);
    int contact = -7;
    expect(cyc_lie_in_contact(ctx, v, v + 6, bad, &contact), CYC_E_NOT_FINITE,
           "cyc_lie_in_contact", {"tol"});
    EXPECT_EQ(contact, -7);
    cyc_lie_sphere back;
    poison(back);
    expect(cyc_lie_sphere_of(ctx, w + 6, &back), CYC_E_NOT_FINITE, "cyc_lie_sphere_of", {"x[2]"});
    EXPECT_TRUE(poisoned(back));

    // Transforms: their arguments and every matrix entry.
    cyc_lie_transform M, out_t;
    poison(out_t);
    const double t[3] = {1, bad, 0};
    expect(cyc_lie_transform_translation(ctx, t, &out_t), CYC_E_NOT_FINITE,
           "cyc_lie_transform_translation", {"t[1]"});
    double rot[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    rot[4] = bad;
    expect(cyc_lie_transform_rotation(ctx, rot, &out_t), CYC_E_NOT_FINITE,
           "cyc_lie_transform_rotation", {"R[4]"});
    expect(cyc_lie_transform_scaling(ctx, bad, &out_t), CYC_E_NOT_FINITE,
           "cyc_lie_transform_scaling", {"s = "});
    expect(cyc_lie_transform_dilatation(ctx, bad, &out_t), CYC_E_NOT_FINITE,
           "cyc_lie_transform_dilatation", {"d = "});
    expect(cyc_lie_transform_inversion(ctx, t, 1, &out_t), CYC_E_NOT_FINITE,
           "cyc_lie_transform_inversion", {"center[1]"});
    const double c0[3] = {0, 0, 0};
    expect(cyc_lie_transform_inversion(ctx, c0, bad, &out_t), CYC_E_NOT_FINITE,
           "cyc_lie_transform_inversion", {"radius"});
    ASSERT_EQ(cyc_lie_transform_scaling(ctx, 2, &M), CYC_OK);
    cyc_lie_transform B = M;
    B.m[7] = bad;
    expect(cyc_lie_transform_compose(ctx, &B, &M, &out_t), CYC_E_NOT_FINITE,
           "cyc_lie_transform_compose", {"first.m[7]"});
    expect(cyc_lie_transform_compose(ctx, &M, &B, &out_t), CYC_E_NOT_FINITE,
           "cyc_lie_transform_compose", {"then.m[7]"});
    EXPECT_TRUE(poisoned(out_t));
    cyc_lie_sphere img;
    poison(img);
    expect(cyc_lie_transform_apply(ctx, &B, &torus[0], &img), CYC_E_NOT_FINITE,
           "cyc_lie_transform_apply", {"T.m[7]"});
    cyc_lie_sphere in = torus[0];
    in.m[2] = bad;
    expect(cyc_lie_transform_apply(ctx, &M, &in, &img), CYC_E_NOT_FINITE,
           "cyc_lie_transform_apply", {"in.m[2]"});
    EXPECT_TRUE(poisoned(img));
    int is_lie = -7;
    expect(cyc_lie_transform_classify(ctx, &B, &is_lie, nullptr, nullptr), CYC_E_NOT_FINITE,
           "cyc_lie_transform_classify", {"T.m[7]"});
    EXPECT_EQ(is_lie, -7);
  }
  // Non-positive radii and scales name themselves.
  cyc_lie_transform out_t;
  const double c0[3] = {0, 0, 0};
  expect(cyc_lie_transform_inversion(ctx, c0, 0, &out_t), CYC_E_INVALID_ARGUMENT,
         "cyc_lie_transform_inversion", {"radius = 0"});
  expect(cyc_lie_transform_scaling(ctx, -1, &out_t), CYC_E_INVALID_ARGUMENT,
         "cyc_lie_transform_scaling", {"s = -1"});
}

TEST_F(LieInputs, DupinValuesAndEvaluationArgumentsAreCheckedAndNamed) {
  for (double unit : {0.0, -0.0, -1.0}) {  // the unit must be positive
    cyc_dupin E = D;
    E.unit = unit;
    cyc_dupin_point P;
    poison(P);
    expect(cyc_dupin_eval(ctx, &E, 0.5, 0.5, 0, &P), CYC_E_INVALID_ARGUMENT, "cyc_dupin_eval",
           {"cyclide.unit", "is not positive"});
  }
  for (double bad : kBadDoubles) {
    cyc_dupin E = D;
    E.origin[1] = bad;
    cyc_dupin_point P;
    poison(P);
    expect(cyc_dupin_eval(ctx, &E, 0.5, 0.5, 0, &P), CYC_E_NOT_FINITE, "cyc_dupin_eval",
           {"cyclide.origin[1]"});
    E = D;
    E.theta[5] = bad;
    expect(cyc_dupin_eval(ctx, &E, 0.5, 0.5, 0, &P), CYC_E_NOT_FINITE, "cyc_dupin_eval",
           {"cyclide.theta[5]"});
    cyc_dupin U = D;
    U.unit = bad;
    expect(cyc_dupin_eval(ctx, &U, 0.5, 0.5, 0, &P), CYC_E_NOT_FINITE, "cyc_dupin_eval",
           {"cyclide.unit"});
    expect(cyc_dupin_eval(ctx, &D, bad, 0.5, 0, &P), CYC_E_NOT_FINITE, "cyc_dupin_eval",
           {"xi = "});
    expect(cyc_dupin_eval(ctx, &D, 0.5, bad, 0, &P), CYC_E_NOT_FINITE, "cyc_dupin_eval",
           {"zeta = "});
    expect(cyc_dupin_eval(ctx, &D, 0.5, 0.5, bad, &P), CYC_E_NOT_FINITE, "cyc_dupin_eval",
           {"offset"});
    const double ok2[2] = {1, 2}, bad2[2] = {1, bad};
    expect(cyc_dupin_eval_homogeneous(ctx, &D, bad2, ok2, 0, &P), CYC_E_NOT_FINITE,
           "cyc_dupin_eval_homogeneous", {"xi[1]"});
    expect(cyc_dupin_eval_homogeneous(ctx, &D, ok2, bad2, 0, &P), CYC_E_NOT_FINITE,
           "cyc_dupin_eval_homogeneous", {"zeta[1]"});
    expect(cyc_dupin_eval_homogeneous(ctx, &D, ok2, ok2, bad, &P), CYC_E_NOT_FINITE,
           "cyc_dupin_eval_homogeneous", {"offset"});
    EXPECT_TRUE(poisoned(P));
    cyc_lie_sphere s;
    poison(s);
    expect(cyc_dupin_sphere(ctx, &D, 0, bad2, &s), CYC_E_NOT_FINITE, "cyc_dupin_sphere", {"t[1]"});
    EXPECT_TRUE(poisoned(s));
    cyc_dupin out;
    poison(out);
    expect(cyc_dupin_offset(ctx, &D, bad, &out), CYC_E_NOT_FINITE, "cyc_dupin_offset", {"d = "});
    expect(cyc_dupin_swap_families(ctx, &E, &out), CYC_E_NOT_FINITE, "cyc_dupin_swap_families",
           {"in.theta[5]"});
    EXPECT_TRUE(poisoned(out));
    const double xs[3] = {0, 0.5, bad};
    double pts[27];
    poison(pts);
    expect(cyc_dupin_eval_grid(ctx, &D, xs, 3, ok2, 2, 0, pts, nullptr), CYC_E_NOT_FINITE,
           "cyc_dupin_eval_grid", {"xis[2]"});
    expect(cyc_dupin_eval_grid(ctx, &D, ok2, 2, xs, 3, 0, pts, nullptr), CYC_E_NOT_FINITE,
           "cyc_dupin_eval_grid", {"zetas[2]"});
    EXPECT_TRUE(poisoned(pts));
    const double map[4] = {1, 0, 0, bad};
    cyc_surface* surf = nullptr;
    expect(cyc_dupin_surface_create(ctx, &D, map, nullptr, 0, 1, &surf), CYC_E_NOT_FINITE,
           "cyc_dupin_surface_create", {"xi_map[3]"});
    expect(cyc_dupin_surface_create(ctx, &D, nullptr, map, 0, 1, &surf), CYC_E_NOT_FINITE,
           "cyc_dupin_surface_create", {"zeta_map[3]"});
    expect(cyc_dupin_surface_create(ctx, &D, nullptr, nullptr, bad, 1, &surf), CYC_E_NOT_FINITE,
           "cyc_dupin_surface_create", {"u0"});
    EXPECT_EQ(surf, nullptr);
  }
  cyc_surface* surf = nullptr;
  expect(cyc_dupin_surface_create(ctx, &D, nullptr, nullptr, 1, 0, &surf), CYC_E_BAD_DOMAIN,
         "cyc_dupin_surface_create", {"[u0, u1]"});
  EXPECT_EQ(surf, nullptr);
}

TEST_F(LieInputs, ConeArgumentsAreCheckedAndFailuresSpeakOfTheirOwnArguments) {
  const double c[3] = {0, 0, 0}, n[3] = {0, 0, 1}, apex[3] = {0, 0, 5}, zero[3] = {0, 0, 0};
  for (double bad : kBadDoubles) {
    cyc_lie_cone K;
    poison(K);
    const double b3[3] = {0, bad, 0};
    expect(cyc_cone_from_spheres(ctx, b3, 1, n, 0.2, &K), CYC_E_NOT_FINITE,
           "cyc_cone_from_spheres", {"m[1]"});
    expect(cyc_cone_from_spheres(ctx, c, bad, n, 0.2, &K), CYC_E_NOT_FINITE,
           "cyc_cone_from_spheres", {"rho = "});
    expect(cyc_cone_from_spheres(ctx, c, 1, b3, 0.2, &K), CYC_E_NOT_FINITE,
           "cyc_cone_from_spheres", {"dm[1]"});
    expect(cyc_cone_from_spheres(ctx, c, 1, n, bad, &K), CYC_E_NOT_FINITE,
           "cyc_cone_from_spheres", {"drho"});
    expect(cyc_cone_from_circle(ctx, b3, n, 1, 0.2, 1, &K), CYC_E_NOT_FINITE,
           "cyc_cone_from_circle", {"center[1]"});
    expect(cyc_cone_from_circle(ctx, c, b3, 1, 0.2, 1, &K), CYC_E_NOT_FINITE,
           "cyc_cone_from_circle", {"normal[1]"});
    expect(cyc_cone_from_circle(ctx, c, n, bad, 0.2, 1, &K), CYC_E_NOT_FINITE,
           "cyc_cone_from_circle", {"radius"});
    expect(cyc_cone_from_circle(ctx, c, n, 1, bad, 1, &K), CYC_E_NOT_FINITE,
           "cyc_cone_from_circle", {"slope"});
    expect(cyc_cone_from_circle_apex(ctx, c, n, 1, b3, 1, &K), CYC_E_NOT_FINITE,
           "cyc_cone_from_circle_apex", {"apex[1]"});
    EXPECT_TRUE(poisoned(K));

    cyc_lie_cone Rb = R;
    Rb.r0[0] = bad;
    double cc[3], nn[3], rr = -7;
    poison(cc);
    expect(cyc_cone_circle(ctx, &Rb, cc, nn, &rr), CYC_E_NOT_FINITE, "cyc_cone_circle",
           {"cone.r0[0]"});
    EXPECT_TRUE(poisoned(cc));
    EXPECT_EQ(rr, -7);
    int dim = -7;
    expect(cyc_cyclide_blend_dimension(ctx, &Rb, &S, &dim), CYC_E_NOT_FINITE,
           "cyc_cyclide_blend_dimension", {"r.r0[0]"});
    cyc_lie_cone Sb = S;
    Sb.r_plus[3] = bad;
    expect(cyc_cyclide_blend_dimension(ctx, &R, &Sb, &dim), CYC_E_NOT_FINITE,
           "cyc_cyclide_blend_dimension", {"s.r_plus[3]"});
    EXPECT_EQ(dim, -7);
    cyc_surface* surf = nullptr;
    expect(cyc_cone_surface_create(ctx, &R, bad, 1, &surf), CYC_E_NOT_FINITE,
           "cyc_cone_surface_create", {"h0"});
    EXPECT_EQ(surf, nullptr);
    double beta = -7;
    expect(cyc_cyclide_blend_beta(ctx, &R, &S, 1, bad, &beta), CYC_E_NOT_FINITE,
           "cyc_cyclide_blend_beta", {"alpha"});
    EXPECT_EQ(beta, -7);
    cyc_cyclide_blend out;
    poison(out);
    expect(cyc_cyclide_blend_build(ctx, &R, &S, 1, bad, &out), CYC_E_NOT_FINITE,
           "cyc_cyclide_blend_build", {"alpha"});
    expect(cyc_cyclide_blend_auto(ctx, &R, &Sb, 16, &out, nullptr), CYC_E_NOT_FINITE,
           "cyc_cyclide_blend_auto", {"s.r_plus[3]"});
    EXPECT_TRUE(poisoned(out));

    // A caller's blend: its parameters, joint and pieces.
    cyc_cyclide_blend Bb = B2;
    Bb.alpha = bad;
    double q = -7;
    expect(cyc_cyclide_blend_quality(ctx, &Bb, &q), CYC_E_NOT_FINITE,
           "cyc_cyclide_blend_quality", {"blend.alpha"});
    Bb = B2;
    Bb.joint[2] = bad;
    expect(cyc_cyclide_blend_quality(ctx, &Bb, &q), CYC_E_NOT_FINITE,
           "cyc_cyclide_blend_quality", {"blend.joint[2]"});
    Bb = B2;
    Bb.piece[1].origin[2] = bad;
    expect(cyc_cyclide_blend_quality(ctx, &Bb, &q), CYC_E_NOT_FINITE,
           "cyc_cyclide_blend_quality", {"blend.piece[1].origin[2]"});
    EXPECT_EQ(q, -7);
    double ctr[3], nrm[3], rad = -7;
    expect(cyc_cyclide_blend_circle(ctx, &B2, 0, 1, bad, ctr, nrm, &rad), CYC_E_NOT_FINITE,
           "cyc_cyclide_blend_circle", {"s = "});
    EXPECT_EQ(rad, -7);
  }
  // Invalid circles: the message names the argument, not another
  // construction's quantity (radius 0 used to speak of r_plus).
  cyc_lie_cone K;
  poison(K);
  for (double r : {0.0, -1.0}) {
    expect(cyc_cone_from_circle(ctx, c, n, r, 0.2, 1, &K), CYC_E_INVALID_ARGUMENT,
           "cyc_cone_from_circle", {"radius = "});
    EXPECT_EQ(std::string(cyc_context_last_error(ctx)).find("r_plus"), std::string::npos);
    expect(cyc_cone_from_circle_apex(ctx, c, n, r, apex, 1, &K), CYC_E_INVALID_ARGUMENT,
           "cyc_cone_from_circle_apex", {"radius = "});
  }
  expect(cyc_cone_from_circle(ctx, c, zero, 1, 0.2, 1, &K), CYC_E_INVALID_ARGUMENT,
         "cyc_cone_from_circle", {"normal = (0, 0, 0)"});
  const double off_axis[3] = {1, 0, 5};
  expect(cyc_cone_from_circle_apex(ctx, c, n, 1, off_axis, 1, &K), CYC_E_INVALID_ARGUMENT,
         "cyc_cone_from_circle_apex", {"apex = ", "axis"});
  expect(cyc_cone_from_spheres(ctx, c, 0, n, 0.2, &K), CYC_E_INVALID_ARGUMENT,
         "cyc_cone_from_spheres", {"rho = 0"});
  const double slow[3] = {0, 0, 0.1};
  expect(cyc_cone_from_spheres(ctx, c, 1, slow, 0.2, &K), CYC_E_INVALID_ARGUMENT,
         "cyc_cone_from_spheres", {"|dm|", "|drho|"});
  EXPECT_TRUE(poisoned(K));
  // A cone that is no cone names itself.
  cyc_lie_cone bent = R;
  bent.r_plus[0] += 0.5 * (std::abs(bent.r_plus[0]) + 1);
  bent.r_plus[5] += 3 * (std::abs(bent.r_plus[5]) + 1);
  int dim = -7;
  const int st = cyc_cyclide_blend_dimension(ctx, &R, &bent, &dim);
  EXPECT_NE(st, CYC_OK);
  EXPECT_NE(std::string(cyc_context_last_error(ctx)).find("s is not a cone"), std::string::npos)
      << cyc_context_last_error(ctx);
  EXPECT_EQ(dim, -7);
  // One cone twice: nothing to blend, said in Algorithm 2's words.
  cyc_cyclide_blend out;
  expect(cyc_cyclide_blend_build(ctx, &R, &R, 1, 0.0, &out), CYC_E_INVALID_ARGUMENT,
         "cyc_cyclide_blend_build", {"nothing to blend"});
}

}  // namespace
