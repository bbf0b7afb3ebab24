// Seed 002's sphere skins through the C ABI (labels "sphere_skin;capi"):
// handles, the core's bits (the test links cyclide_core too), grids, chains,
// info, twist, lambda, every error path with untouched outputs, messages,
// the context's allocator and out-of-memory.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "cyclide/cyclide.h"
#include "cyclide/skin_export.hpp"
#include "cyclide/sphere_skin.hpp"

using cyclide::make_sphere_skin;
using cyclide::make_sphere_skin_chain;
using cyclide::RmfMethod;
using cyclide::SkinEnd;
using cyclide::SkinOptions;
using cyclide::SkinPairing;
using cyclide::SphereSkin;
using cyclide::Status;
using cyclide::Vec3d;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr uint64_t kSentinelBits = 0x7ff4dead5eed1234ull;

double sentinel() {
  double d;
  std::memcpy(&d, &kSentinelBits, sizeof d);
  return d;
}
void fill(double* p, size_t n) {
  for (size_t i = 0; i < n; ++i) p[i] = sentinel();
}
bool untouched(const double* p, size_t n) {
  for (size_t i = 0; i < n; ++i)
    if (std::memcmp(p + i, &kSentinelBits, sizeof(double)) != 0) return false;
  return true;
}

cyc_sphere_skin* const kHandleSentinel =
    reinterpret_cast<cyc_sphere_skin*>(uintptr_t(0x5eed0bad0000ull));

SkinEnd core_end(const cyc_skin_end& e) {
  SkinEnd s;
  s.center = Vec3d(e.center[0], e.center[1], e.center[2]);
  s.radius = e.radius;
  s.tangent = Vec3d(e.tangent[0], e.tangent[1], e.tangent[2]);
  s.inv_c = e.inv_c;
  return s;
}

double norm(const double* v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
double dot(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double dist(const double* a, const double* b) {
  const double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  return norm(d);
}
bool same(const double* a, const double* b, size_t n) {
  return std::memcmp(a, b, n * sizeof(double)) == 0;
}
bool contains(const char* s, const char* what) { return std::strstr(s, what) != nullptr; }

// The skew unit spheres of tests/sphere_skin_test.cpp (Fig. 3/8 like).
struct SkinCapi : ::testing::Test {
  cyc_context* ctx = nullptr;
  cyc_skin_end s{}, e{};
  std::vector<cyc_sphere_skin*> owned;
  void SetUp() override {
    ASSERT_EQ(cyc_context_create(nullptr, &ctx), CYC_OK);
    const double m0[3] = {0, 0, 0}, p0[3] = {0.3, 0, 0}, t0[3] = {3, 0, 0};
    ASSERT_EQ(cyc_skin_end_from_sphere(ctx, m0, 1.0, p0, t0, &s), CYC_OK);
    const Vec3d axis = Vec3d(1.0, 0.6, 0.8).normalized();
    const Vec3d P = Vec3d(4, 1, 0.5) - 0.4 * axis, T = 3.0 * axis;
    const double m1[3] = {4, 1, 0.5}, p1[3] = {P.x(), P.y(), P.z()}, t1[3] = {T.x(), T.y(), T.z()};
    ASSERT_EQ(cyc_skin_end_from_sphere(ctx, m1, 1.2, p1, t1, &e), CYC_OK);
  }
  void TearDown() override {
    for (cyc_sphere_skin* h : owned) cyc_sphere_skin_destroy(ctx, h);
    cyc_context_destroy(ctx);
  }
  cyc_sphere_skin* make(const cyc_skin_options* o = nullptr) {
    cyc_sphere_skin* h = nullptr;
    EXPECT_EQ(cyc_sphere_skin_create(ctx, &s, &e, o, &h), CYC_OK) << cyc_context_last_error(ctx);
    if (h) owned.push_back(h);
    return h;
  }
  // ends[0..2] of the core's chain test.
  void chain_ends(cyc_skin_end* ends) {
    const double m0[3] = {0, 0, 0}, p0[3] = {0.3, 0, 0}, t0[3] = {3, 0, 0};
    ASSERT_EQ(cyc_skin_end_from_sphere(ctx, m0, 1.0, p0, t0, &ends[0]), CYC_OK);
    const Vec3d ax = Vec3d(1, 0.5, 0.3).normalized();
    const Vec3d P1 = Vec3d(4, 1, 0) - 0.1 * ax, T1 = 3.0 * ax;
    const double m1[3] = {4, 1, 0}, p1[3] = {P1.x(), P1.y(), P1.z()},
                 t1[3] = {T1.x(), T1.y(), T1.z()};
    ASSERT_EQ(cyc_skin_end_from_sphere(ctx, m1, 0.8, p1, t1, &ends[1]), CYC_OK);
    const Vec3d ax2 = Vec3d(0.2, 1, -0.4).normalized();
    const Vec3d P2 = Vec3d(6, 4, -1) - 0.3 * ax2, T2 = 3.0 * ax2;
    const double m2[3] = {6, 4, -1}, p2[3] = {P2.x(), P2.y(), P2.z()},
                 t2[3] = {T2.x(), T2.y(), T2.z()};
    ASSERT_EQ(cyc_skin_end_from_sphere(ctx, m2, 1.1, p2, t2, &ends[2]), CYC_OK);
  }
};

const double kThetas[] = {-3.0, -1.0, 0.0, 0.4, 1.5, 3.1, 10.0};
const double kTs[] = {0.0, 1e-3, 0.3, 0.5, 0.61, 0.999, 1.0};

}  // namespace

TEST_F(SkinCapi, OptionsDefaultsAreTheCore) {
  cyc_skin_options o;
  std::memset(&o, 0x5a, sizeof o);
  cyc_skin_options_init(&o);
  const SkinOptions d;
  EXPECT_EQ(o.pairing, CYC_SKIN_RMF);
  EXPECT_EQ(o.method, CYC_RMF_REFERENCE);
  EXPECT_EQ(o.tolerance, d.tolerance);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(o.reference[k], 0.0);
    EXPECT_EQ(o.e[k], 0.0);
  }
  cyc_skin_options_init(nullptr);  // ignored
}

TEST_F(SkinCapi, EndsAgreeWithTheCore) {
  SkinEnd a;
  ASSERT_EQ(cyclide::skin_end_from_sphere({0, 0, 0}, 1.0, {0.3, 0, 0}, {3, 0, 0}, a), Status::ok);
  const SkinEnd b = core_end(s);
  EXPECT_EQ(a.center, b.center);
  EXPECT_EQ(a.radius, b.radius);
  EXPECT_EQ(a.tangent, b.tangent);
  EXPECT_EQ(a.inv_c, b.inv_c);
  // From the apex: the same end.
  const double apex[3] = {s.center[0] + s.tangent[0] / s.inv_c, s.center[1] + s.tangent[1] / s.inv_c,
                          s.center[2] + s.tangent[2] / s.inv_c};
  cyc_skin_end x;
  ASSERT_EQ(cyc_skin_end_from_apex(ctx, s.center, s.radius, s.tangent, apex, &x), CYC_OK);
  EXPECT_NEAR(x.inv_c, s.inv_c, 1e-15);
  EXPECT_EQ(x.radius, s.radius);
  // The sphere back.
  double m[3], R = 0;
  cyc_skin_end_sphere(&s, m, &R);
  EXPECT_NEAR(R, 1.0, 1e-15);
  EXPECT_LE(norm(m), 1e-15);
  double m2[3];
  fill(m2, 3);
  cyc_skin_end_sphere(nullptr, m2, &R);  // NULL-safe, nothing written
  EXPECT_TRUE(untouched(m2, 3));
  cyc_skin_end_sphere(&s, nullptr, nullptr);
  cyc_skin_end_sphere(&s, m2, nullptr);
  EXPECT_TRUE(same(m, m2, 3));
}

TEST_F(SkinCapi, EndErrorsWriteNothing) {
  cyc_skin_end out;
  std::memset(&out, 0x77, sizeof out);
  cyc_skin_end keep;
  std::memcpy(&keep, &out, sizeof out);
  const double c[3] = {0, 0, 0}, t[3] = {1, 0, 0}, z[3] = {0, 0, 0}, off[3] = {1, 1, 0},
               nan3[3] = {kNaN, 0, 0};
  EXPECT_EQ(cyc_skin_end_from_apex(nullptr, c, 1, t, off, &out), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_skin_end_from_apex(ctx, nullptr, 1, t, off, &out), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_skin_end_from_apex(ctx, c, 1, t, off, nullptr), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_skin_end_from_apex(ctx, c, 1, t, off, &out), CYC_E_INVALID_ARGUMENT);
  EXPECT_TRUE(contains(cyc_context_last_error(ctx), "cyc_skin_end_from_apex"));
  EXPECT_EQ(cyc_skin_end_from_apex(ctx, c, 1, t, c, &out), CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(cyc_skin_end_from_apex(ctx, c, 0, t, t, &out), CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(cyc_skin_end_from_apex(ctx, c, 1, z, t, &out), CYC_E_ZERO_TANGENT);
  EXPECT_EQ(cyc_skin_end_from_apex(ctx, nan3, 1, t, t, &out), CYC_E_NOT_FINITE);
  EXPECT_EQ(cyc_skin_end_from_apex(ctx, c, 1e101, t, t, &out), CYC_E_NOT_FINITE);
  EXPECT_EQ(cyc_skin_end_from_sphere(nullptr, c, 1, c, t, &out), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_skin_end_from_sphere(ctx, c, 1, c, nullptr, &out), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_skin_end_from_sphere(ctx, c, -1, c, t, &out), CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(cyc_skin_end_from_sphere(ctx, c, 1, off, t, &out), CYC_E_INVALID_ARGUMENT);
  const double far[3] = {2, 0, 0};
  EXPECT_EQ(cyc_skin_end_from_sphere(ctx, c, 1, far, t, &out), CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(cyc_skin_end_from_sphere(ctx, c, 1, c, z, &out), CYC_E_ZERO_TANGENT);
  EXPECT_EQ(cyc_skin_end_from_sphere(ctx, c, kNaN, c, t, &out), CYC_E_NOT_FINITE);
  EXPECT_EQ(std::memcmp(&out, &keep, sizeof out), 0);
}

// create / eval / destroy, and the C values are the core's bits for every
// pairing and method.
TEST_F(SkinCapi, EvalEqualsTheCoreBitForBit) {
  for (int pairing : {CYC_SKIN_RMF, CYC_SKIN_KUNKLI_HOFFMANN, CYC_SKIN_CROSS_TANGENTS})
    for (int method : {CYC_RMF_REFERENCE, CYC_RMF_DOUBLE_REFLECTION}) {
      SCOPED_TRACE(pairing * 10 + method);
      cyc_skin_options o;
      cyc_skin_options_init(&o);
      o.pairing = pairing;
      o.method = method;
      cyc_sphere_skin* h = make(&o);
      ASSERT_NE(h, nullptr);
      int count = 0;
      ASSERT_EQ(cyc_sphere_skin_patch_count(ctx, h, &count), CYC_OK);
      EXPECT_EQ(count, 1);
      SkinOptions co;
      co.pairing = SkinPairing(pairing);
      co.method = RmfMethod(method);
      SphereSkin S;
      ASSERT_EQ(make_sphere_skin(core_end(s), core_end(e), co, S), Status::ok);
      for (double th : kThetas)
        for (double t : kTs) {
          double x[3], xa[3], xb[3], n[3], X[3], XA[3], XB[3], N[3];
          ASSERT_EQ(cyc_sphere_skin_eval(ctx, h, 0, th, t, x, xa, xb, n), CYC_OK);
          ASSERT_EQ(cyclide::skin_eval(S, th, t, X, XA, XB, N), Status::ok);
          EXPECT_TRUE(same(x, X, 3) && same(xa, XA, 3) && same(xb, XB, 3) && same(n, N, 3))
              << th << " " << t;
          // Any subset of outputs gives the same bits.
          double y[3], m[3];
          ASSERT_EQ(cyc_sphere_skin_eval(ctx, h, 0, th, t, y, nullptr, nullptr, nullptr), CYC_OK);
          ASSERT_EQ(cyc_sphere_skin_eval(ctx, h, 0, th, t, nullptr, nullptr, nullptr, m), CYC_OK);
          EXPECT_TRUE(same(x, y, 3) && same(n, m, 3));
          double l = 0, a[2], L = 0, A[2];
          ASSERT_EQ(cyc_sphere_skin_lambda(ctx, h, 0, th, t, &l, a), CYC_OK);
          L = cyclide::skin_lambda(S, th, t, A);
          EXPECT_TRUE(same(&l, &L, 1) && same(a, A, 2));
        }
    }
}

// s(theta, 0) on the start circle, s(theta, 1) on the end circle; normals
// unit and orthogonal to both partials; lambda = r at the ends.
TEST_F(SkinCapi, EndCirclesAndNormals) {
  cyc_sphere_skin* h = make();
  ASSERT_NE(h, nullptr);
  const cyc_skin_end* E[2] = {&s, &e};
  for (double th : kThetas) {
    for (int end = 0; end < 2; ++end) {
      double x[3];
      ASSERT_EQ(cyc_sphere_skin_eval(ctx, h, 0, th, double(end), x, nullptr, nullptr, nullptr),
                CYC_OK);
      const double d[3] = {x[0] - E[end]->center[0], x[1] - E[end]->center[1],
                           x[2] - E[end]->center[2]};
      EXPECT_NEAR(norm(d), E[end]->radius, 1e-13);
      EXPECT_NEAR(dot(d, E[end]->tangent) / norm(E[end]->tangent), 0.0, 1e-13);
      double l = 0;
      ASSERT_EQ(cyc_sphere_skin_lambda(ctx, h, 0, th, double(end), &l, nullptr), CYC_OK);
      EXPECT_NEAR(l, E[end]->radius, 1e-14);
    }
    for (double t : kTs) {
      double xa[3], xb[3], n[3];
      ASSERT_EQ(cyc_sphere_skin_eval(ctx, h, 0, th, t, nullptr, xa, xb, n), CYC_OK);
      EXPECT_NEAR(norm(n), 1.0, 1e-15);
      EXPECT_LE(std::abs(dot(n, xa)), 1e-13 * norm(xa));
      EXPECT_LE(std::abs(dot(n, xb)), 1e-13 * norm(xb));
    }
  }
}

TEST_F(SkinCapi, GridEqualsSingleEvalsBitwise) {
  cyc_skin_options o;
  cyc_skin_options_init(&o);
  o.pairing = CYC_SKIN_KUNKLI_HOFFMANN;
  for (cyc_sphere_skin* h : {make(), make(&o)}) {
    ASSERT_NE(h, nullptr);
    const int nth = 7, nt = 7;
    std::vector<double> P(3 * nth * nt), N(3 * nth * nt), P2(3 * nth * nt), N2(3 * nth * nt);
    ASSERT_EQ(cyc_sphere_skin_eval_grid(ctx, h, 0, kThetas, nth, kTs, nt, P.data(), N.data(), nullptr),
              CYC_OK);
    ASSERT_EQ(cyc_sphere_skin_eval_grid(ctx, h, 0, kThetas, nth, kTs, nt, P2.data(), nullptr, nullptr),
              CYC_OK);
    ASSERT_EQ(cyc_sphere_skin_eval_grid(ctx, h, 0, kThetas, nth, kTs, nt, nullptr, N2.data(), nullptr),
              CYC_OK);
    EXPECT_TRUE(same(P.data(), P2.data(), P.size()));
    EXPECT_TRUE(same(N.data(), N2.data(), N.size()));
    for (int j = 0; j < nt; ++j)
      for (int i = 0; i < nth; ++i) {
        double x[3], n[3];
        ASSERT_EQ(cyc_sphere_skin_eval(ctx, h, 0, kThetas[i], kTs[j], x, nullptr, nullptr, n),
                  CYC_OK);
        EXPECT_TRUE(same(x, &P[3 * (j * nth + i)], 3)) << i << " " << j;
        EXPECT_TRUE(same(n, &N[3 * (j * nth + i)], 3)) << i << " " << j;
      }
    // Empty grids and no outputs are fine.
    EXPECT_EQ(cyc_sphere_skin_eval_grid(ctx, h, 0, kThetas, 0, kTs, nt, P.data(), N.data(), nullptr),
              CYC_OK);
    EXPECT_EQ(cyc_sphere_skin_eval_grid(ctx, h, 0, kThetas, nth, kTs, nt, nullptr, nullptr, nullptr),
              CYC_OK);
  }
}

TEST_F(SkinCapi, ChainOfThreeEndsIsTwoPatchesG1) {
  cyc_skin_end ends[3];
  chain_ends(ends);
  cyc_sphere_skin* h = nullptr;
  int bad = -7;
  ASSERT_EQ(cyc_sphere_skin_chain_create(ctx, ends, 3, nullptr, &h, &bad), CYC_OK)
      << cyc_context_last_error(ctx);
  owned.push_back(h);
  EXPECT_EQ(bad, -7);  // written only when a patch fails
  int count = 0;
  ASSERT_EQ(cyc_sphere_skin_patch_count(ctx, h, &count), CYC_OK);
  EXPECT_EQ(count, 2);
  // The core's chain, bit for bit.
  SkinEnd ce[3] = {core_end(ends[0]), core_end(ends[1]), core_end(ends[2])};
  std::vector<SphereSkin> P(2);
  ASSERT_EQ(make_sphere_skin_chain(ce, 3, SkinOptions{}, P.data()), Status::ok);
  for (double th = -3; th < 3.2; th += 0.4) {
    double x0[3], x1[3], n0[3], n1[3], X[3], N[3];
    ASSERT_EQ(cyc_sphere_skin_eval(ctx, h, 0, th, 1.0, x0, nullptr, nullptr, n0), CYC_OK);
    ASSERT_EQ(cyc_sphere_skin_eval(ctx, h, 1, th, 0.0, x1, nullptr, nullptr, n1), CYC_OK);
    ASSERT_EQ(cyclide::skin_eval(P[1], th, 0.0, X, nullptr, nullptr, N), Status::ok);
    EXPECT_TRUE(same(x1, X, 3) && same(n1, N, 3));
    EXPECT_LE(dist(x0, x1), 1e-12);
    EXPECT_LE(dist(n0, n1), 1e-11);  // G^1: the same tangent plane
    // Both on the shared circle.
    const double d[3] = {x1[0] - ends[1].center[0], x1[1] - ends[1].center[1],
                         x1[2] - ends[1].center[2]};
    EXPECT_NEAR(norm(d), ends[1].radius, 1e-13);
  }
  // Info of the second patch: its spine starts at the middle end.
  cyc_sphere_skin_info I;
  ASSERT_EQ(cyc_sphere_skin_info_get(ctx, h, 1, &I), CYC_OK);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(I.spine[0][k], ends[1].center[k]);
    EXPECT_EQ(I.spine[1][k], ends[1].tangent[k]);
  }
  // Two ends: a chain of one patch equals cyc_sphere_skin_create.
  cyc_sphere_skin* one = nullptr;
  cyc_skin_end two[2] = {s, e};
  ASSERT_EQ(cyc_sphere_skin_chain_create(ctx, two, 2, nullptr, &one, nullptr), CYC_OK);
  owned.push_back(one);
  cyc_sphere_skin* single = make();
  double a[3], b[3];
  ASSERT_EQ(cyc_sphere_skin_eval(ctx, one, 0, 0.7, 0.4, a, nullptr, nullptr, nullptr), CYC_OK);
  ASSERT_EQ(cyc_sphere_skin_eval(ctx, single, 0, 0.7, 0.4, b, nullptr, nullptr, nullptr), CYC_OK);
  EXPECT_TRUE(same(a, b, 3));
}

TEST_F(SkinCapi, ChainFailureNamesThePatchAndWritesNothing) {
  cyc_skin_end ends[3];
  chain_ends(ends);
  ends[2] = ends[1];  // the third sphere equals the second: nested
  cyc_sphere_skin* h = kHandleSentinel;
  int bad = -7;
  EXPECT_EQ(cyc_sphere_skin_chain_create(ctx, ends, 3, nullptr, &h, &bad), CYC_E_NESTED_SPHERES);
  EXPECT_EQ(h, kHandleSentinel);
  EXPECT_EQ(bad, 1);
  const char* msg = cyc_context_last_error(ctx);
  EXPECT_TRUE(contains(msg, "cyc_sphere_skin_chain_create")) << msg;
  EXPECT_TRUE(contains(msg, "patch 1")) << msg;
  EXPECT_TRUE(contains(msg, "sphere")) << msg;
  // Validation errors leave bad_patch alone.
  bad = -7;
  EXPECT_EQ(cyc_sphere_skin_chain_create(ctx, ends, 1, nullptr, &h, &bad), CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(cyc_sphere_skin_chain_create(ctx, ends, -1, nullptr, &h, &bad), CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(cyc_sphere_skin_chain_create(ctx, nullptr, 3, nullptr, &h, &bad), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_sphere_skin_chain_create(ctx, ends, 3, nullptr, nullptr, &bad),
            CYC_E_NULL_ARGUMENT);
  cyc_skin_options o;
  cyc_skin_options_init(&o);
  o.method = 5;
  EXPECT_EQ(cyc_sphere_skin_chain_create(ctx, ends, 3, &o, &h, &bad), CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(bad, -7);
  EXPECT_EQ(h, kHandleSentinel);
  EXPECT_EQ(cyc_sphere_skin_chain_create(ctx, ends, 3, nullptr, &h, nullptr),
            CYC_E_NESTED_SPHERES);
}

TEST_F(SkinCapi, InfoIsSane) {
  for (int pairing : {CYC_SKIN_RMF, CYC_SKIN_KUNKLI_HOFFMANN, CYC_SKIN_CROSS_TANGENTS}) {
    cyc_skin_options o;
    cyc_skin_options_init(&o);
    o.pairing = pairing;
    o.method = pairing == CYC_SKIN_RMF ? CYC_RMF_DOUBLE_REFLECTION : CYC_RMF_REFERENCE;
    o.tolerance = 1e-12;
    cyc_sphere_skin* h = make(&o);
    ASSERT_NE(h, nullptr);
    cyc_sphere_skin_info I;
    ASSERT_EQ(cyc_sphere_skin_info_get(ctx, h, 0, &I), CYC_OK);
    EXPECT_EQ(I.pairing, pairing);
    EXPECT_EQ(I.method, o.method);
    EXPECT_GT(I.kappa[0], 0.0);
    EXPECT_LT(I.kappa[0] * s.radius, 1.0);
    EXPECT_LT(I.kappa[1] * e.radius, 1.0);
    // Double reflection: steps per interval, a power of 2 in 2..256;
    // reference: the largest Chebyshev degree, n + 1 for n in 8..64.
    if (o.method == CYC_RMF_DOUBLE_REFLECTION) {
      EXPECT_GE(I.rmf_substeps, 2);
      EXPECT_LE(I.rmf_substeps, 256);
      EXPECT_EQ(I.rmf_substeps & (I.rmf_substeps - 1), 0);
    } else {
      EXPECT_GE(I.rmf_substeps, 9);
      EXPECT_LE(I.rmf_substeps, 65);
      EXPECT_EQ((I.rmf_substeps - 1) & (I.rmf_substeps - 2), 0);
    }
    EXPECT_GE(I.rmf_error_estimate, 0.0);
    EXPECT_LE(I.rmf_error_estimate, o.tolerance);
    if (pairing == CYC_SKIN_RMF)
      EXPECT_EQ(I.delta, 0.0);
    else
      EXPECT_GT(std::abs(I.delta), 0.0);
    // The spine's power form: alpha(0) = p_i, alpha'(0) = t_i, alpha(1) = p_f,
    // alpha'(1) = t_f.
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(I.spine[0][k], s.center[k]);
      EXPECT_EQ(I.spine[1][k], s.tangent[k]);
      EXPECT_NEAR(I.spine[0][k] + I.spine[1][k] + I.spine[2][k] + I.spine[3][k], e.center[k],
                  1e-14);
      EXPECT_NEAR(I.spine[1][k] + 2 * I.spine[2][k] + 3 * I.spine[3][k], e.tangent[k], 1e-14);
    }
    // Twist: 0 for the RMF, |delta| for the baselines.
    for (double th : {0.0, 1.0, -2.5}) {
      double tw = -1;
      ASSERT_EQ(cyc_sphere_skin_twist(ctx, h, 0, th, &tw), CYC_OK);
      if (pairing == CYC_SKIN_RMF)
        EXPECT_LE(tw, 1e-10);
      else
        EXPECT_NEAR(tw, std::abs(I.delta), 1e-9);
    }
  }
}

// Every error of the evaluation entry points: status, message, nothing
// written.
TEST_F(SkinCapi, EvaluationErrorsWriteNothing) {
  cyc_sphere_skin* h = make();
  ASSERT_NE(h, nullptr);
  double x[3], xa[3], xb[3], n[3], out[4 * 3], lam, a[2], tw;
  cyc_sphere_skin_info I;
  std::memset(&I, 0x5a, sizeof I);
  cyc_sphere_skin_info keep = I;
  int count = -7;
  fill(x, 3);
  fill(xa, 3);
  fill(xb, 3);
  fill(n, 3);
  fill(out, 12);
  fill(&lam, 1);
  fill(a, 2);
  fill(&tw, 1);
  auto all_untouched = [&] {
    return untouched(x, 3) && untouched(xa, 3) && untouched(xb, 3) && untouched(n, 3) &&
           untouched(out, 12) && untouched(&lam, 1) && untouched(a, 2) && untouched(&tw, 1) &&
           std::memcmp(&I, &keep, sizeof I) == 0 && count == -7;
  };
  const double th2[2] = {0.0, 1.0}, t2[2] = {0.0, 0.5}, tbad[2] = {0.0, 1.5},
               tnan[2] = {kNaN, 0.5}, thnan[2] = {0.0, kNaN};
  // NULL context.
  EXPECT_EQ(cyc_sphere_skin_eval(nullptr, h, 0, 0, 0, x, xa, xb, n), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_sphere_skin_eval_grid(nullptr, h, 0, th2, 2, t2, 2, out, nullptr, nullptr),
            CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_sphere_skin_info_get(nullptr, h, 0, &I), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_sphere_skin_twist(nullptr, h, 0, 0, &tw), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_sphere_skin_lambda(nullptr, h, 0, 0, 0, &lam, a), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_sphere_skin_patch_count(nullptr, h, &count), CYC_E_NULL_ARGUMENT);
  // NULL handle / required outputs.
  struct Case {
    int status;
    int expected;
    const char* what;
  };
  const Case cases[] = {
      {cyc_sphere_skin_eval(ctx, nullptr, 0, 0, 0, x, xa, xb, n), CYC_E_NULL_ARGUMENT, "skin"},
      {cyc_sphere_skin_eval_grid(ctx, nullptr, 0, th2, 2, t2, 2, out, nullptr, nullptr),
       CYC_E_NULL_ARGUMENT, "skin"},
      {cyc_sphere_skin_eval_grid(ctx, h, 0, nullptr, 2, t2, 2, out, nullptr, nullptr),
       CYC_E_NULL_ARGUMENT, "theta"},
      {cyc_sphere_skin_eval_grid(ctx, h, 0, th2, 2, nullptr, 2, out, nullptr, nullptr),
       CYC_E_NULL_ARGUMENT, "t"},
      {cyc_sphere_skin_info_get(ctx, nullptr, 0, &I), CYC_E_NULL_ARGUMENT, "skin"},
      {cyc_sphere_skin_info_get(ctx, h, 0, nullptr), CYC_E_NULL_ARGUMENT, "out"},
      {cyc_sphere_skin_twist(ctx, h, 0, 0, nullptr), CYC_E_NULL_ARGUMENT, "twist"},
      {cyc_sphere_skin_lambda(ctx, h, 0, 0, 0, nullptr, a), CYC_E_NULL_ARGUMENT, "lambda"},
      {cyc_sphere_skin_patch_count(ctx, nullptr, &count), CYC_E_NULL_ARGUMENT, "skin"},
      {cyc_sphere_skin_patch_count(ctx, h, nullptr), CYC_E_NULL_ARGUMENT, "count"},
      // Bad patch.
      {cyc_sphere_skin_eval(ctx, h, 1, 0, 0, x, xa, xb, n), CYC_E_INVALID_ARGUMENT, "patch = 1"},
      {cyc_sphere_skin_eval(ctx, h, -1, 0, 0, x, xa, xb, n), CYC_E_INVALID_ARGUMENT, "patch = -1"},
      {cyc_sphere_skin_eval_grid(ctx, h, 2, th2, 2, t2, 2, out, nullptr, nullptr), CYC_E_INVALID_ARGUMENT,
       "patch"},
      {cyc_sphere_skin_info_get(ctx, h, 1, &I), CYC_E_INVALID_ARGUMENT, "patch"},
      {cyc_sphere_skin_twist(ctx, h, 7, 0, &tw), CYC_E_INVALID_ARGUMENT, "patch"},
      {cyc_sphere_skin_lambda(ctx, h, -3, 0, 0, &lam, a), CYC_E_INVALID_ARGUMENT, "patch"},
      // NaN / infinite parameters.
      {cyc_sphere_skin_eval(ctx, h, 0, kNaN, 0.5, x, xa, xb, n), CYC_E_NOT_FINITE, "theta"},
      {cyc_sphere_skin_eval(ctx, h, 0, 0.5, kNaN, x, xa, xb, n), CYC_E_NOT_FINITE, "t ="},
      {cyc_sphere_skin_eval(ctx, h, 0, HUGE_VAL, 0.5, x, xa, xb, n), CYC_E_NOT_FINITE, "theta"},
      {cyc_sphere_skin_eval_grid(ctx, h, 0, th2, 2, tnan, 2, out, nullptr, nullptr), CYC_E_NOT_FINITE,
       "t[0]"},
      {cyc_sphere_skin_eval_grid(ctx, h, 0, thnan, 2, t2, 2, out, nullptr, nullptr), CYC_E_NOT_FINITE,
       "theta[1]"},
      {cyc_sphere_skin_twist(ctx, h, 0, kNaN, &tw), CYC_E_NOT_FINITE, "theta"},
      {cyc_sphere_skin_lambda(ctx, h, 0, -HUGE_VAL, 0, &lam, a), CYC_E_NOT_FINITE, "theta"},
      // The domain.
      {cyc_sphere_skin_eval(ctx, h, 0, 0, 1.5, x, xa, xb, n), CYC_E_BAD_DOMAIN, "[0, 1]"},
      {cyc_sphere_skin_eval(ctx, h, 0, 0, -1e-300, x, xa, xb, n), CYC_E_BAD_DOMAIN, "[0, 1]"},
      {cyc_sphere_skin_eval(ctx, h, 0, 0, std::nextafter(1.0, 2.0), x, xa, xb, n),
       CYC_E_BAD_DOMAIN, "[0, 1]"},
      {cyc_sphere_skin_eval_grid(ctx, h, 0, th2, 2, tbad, 2, out, nullptr, nullptr), CYC_E_BAD_DOMAIN,
       "t[1]"},
      {cyc_sphere_skin_lambda(ctx, h, 0, 0, 2, &lam, a), CYC_E_BAD_DOMAIN, "[0, 1]"},
      // Negative sizes.
      {cyc_sphere_skin_eval_grid(ctx, h, 0, th2, -1, t2, 2, out, nullptr, nullptr), CYC_E_INVALID_ARGUMENT,
       "negative"},
      {cyc_sphere_skin_eval_grid(ctx, h, 0, th2, 2, t2, -2, out, nullptr, nullptr), CYC_E_INVALID_ARGUMENT,
       "negative"},
  };
  // The message of each case is checked right after the call: redo them.
  for (const Case& c : cases) EXPECT_EQ(c.status, c.expected) << c.what;
  EXPECT_TRUE(all_untouched());
  // Messages (repeat a few calls to read their messages).
  EXPECT_EQ(cyc_sphere_skin_eval(ctx, h, 1, 0, 0, x, xa, xb, n), CYC_E_INVALID_ARGUMENT);
  EXPECT_TRUE(contains(cyc_context_last_error(ctx), "cyc_sphere_skin_eval: patch = 1"))
      << cyc_context_last_error(ctx);
  EXPECT_EQ(cyc_sphere_skin_eval(ctx, h, 0, 0, 1.5, x, xa, xb, n), CYC_E_BAD_DOMAIN);
  EXPECT_TRUE(contains(cyc_context_last_error(ctx), "[0, 1]"));
  EXPECT_EQ(cyc_sphere_skin_eval_grid(ctx, h, 0, th2, 2, t2, 2, out, nullptr, nullptr), CYC_OK);
  EXPECT_STREQ(cyc_context_last_error(ctx), "");
  EXPECT_EQ(cyc_context_last_status(ctx), CYC_OK);
  EXPECT_EQ(cyc_sphere_skin_eval_grid(ctx, h, 0, nullptr, 2, t2, 2, out, nullptr, nullptr),
            CYC_E_NULL_ARGUMENT);
  EXPECT_TRUE(contains(cyc_context_last_error(ctx), "theta is NULL"));
  cyc_sphere_skin_destroy(ctx, nullptr);  // no-op
}

// Every error of creation: status, a message naming the function and the
// cause, *out untouched.
TEST_F(SkinCapi, CreationErrors) {
  cyc_sphere_skin* h = kHandleSentinel;
  auto create = [&](const cyc_skin_end& a, const cyc_skin_end& b,
                    const cyc_skin_options* o = nullptr) {
    const int st = cyc_sphere_skin_create(ctx, &a, &b, o, &h);
    EXPECT_EQ(h, kHandleSentinel);
    EXPECT_TRUE(contains(cyc_context_last_error(ctx), "cyc_sphere_skin_create: "))
        << cyc_context_last_error(ctx);
    return st;
  };
  EXPECT_EQ(cyc_sphere_skin_create(nullptr, &s, &e, nullptr, &h), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_sphere_skin_create(ctx, nullptr, &e, nullptr, &h), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_sphere_skin_create(ctx, &s, nullptr, nullptr, &h), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_sphere_skin_create(ctx, &s, &e, nullptr, nullptr), CYC_E_NULL_ARGUMENT);
  EXPECT_TRUE(contains(cyc_context_last_error(ctx), "out is NULL"));
  EXPECT_EQ(h, kHandleSentinel);
  // Options.
  cyc_skin_options o;
  for (int bad : {-1, 3, 1 << 30}) {
    cyc_skin_options_init(&o);
    o.pairing = bad;
    EXPECT_EQ(create(s, e, &o), CYC_E_INVALID_ARGUMENT);
    EXPECT_TRUE(contains(cyc_context_last_error(ctx), "pairing"));
    cyc_skin_options_init(&o);
    o.method = bad == 3 ? 2 : bad;
    EXPECT_EQ(create(s, e, &o), CYC_E_INVALID_ARGUMENT);
    EXPECT_TRUE(contains(cyc_context_last_error(ctx), "method"));
  }
  cyc_skin_options_init(&o);
  o.tolerance = 0;
  EXPECT_EQ(create(s, e, &o), CYC_E_INVALID_ARGUMENT);
  EXPECT_TRUE(contains(cyc_context_last_error(ctx), "tolerance"));
  o.tolerance = -1;
  EXPECT_EQ(create(s, e, &o), CYC_E_INVALID_ARGUMENT);
  o.tolerance = kNaN;
  EXPECT_EQ(create(s, e, &o), CYC_E_NOT_FINITE);
  cyc_skin_options_init(&o);
  o.reference[0] = HUGE_VAL;
  EXPECT_EQ(create(s, e, &o), CYC_E_NOT_FINITE);
  cyc_skin_options_init(&o);
  o.reference[0] = 1;  // along the start tangent
  EXPECT_EQ(create(s, e, &o), CYC_E_INVALID_ARGUMENT);
  cyc_skin_options_init(&o);
  o.pairing = CYC_SKIN_KUNKLI_HOFFMANN;
  o.e[0] = 2;  // parallel to t_i
  EXPECT_EQ(create(s, e, &o), CYC_E_INVALID_ARGUMENT);
  EXPECT_TRUE(contains(cyc_context_last_error(ctx), "Kunkli-Hoffmann"));
  // Ends.
  cyc_skin_end b = s;
  b.radius = 0;
  EXPECT_EQ(create(b, e), CYC_E_INVALID_ARGUMENT);
  EXPECT_TRUE(contains(cyc_context_last_error(ctx), "start circle's radius"));
  b = s;
  b.center[1] = kNaN;
  EXPECT_EQ(create(b, e), CYC_E_NOT_FINITE);
  b = e;
  b.inv_c = 2e100;
  EXPECT_EQ(create(s, b), CYC_E_NOT_FINITE);
  b = e;
  b.tangent[0] = b.tangent[1] = b.tangent[2] = 0;
  EXPECT_EQ(create(s, b), CYC_E_ZERO_TANGENT);
  EXPECT_TRUE(contains(cyc_context_last_error(ctx), "end tangent is zero"));
  // Nested spheres: equal, and a small one inside.
  EXPECT_EQ(create(s, s), CYC_E_NESTED_SPHERES);
  EXPECT_TRUE(contains(cyc_context_last_error(ctx), "nested"));
  EXPECT_TRUE(contains(cyc_context_last_error(ctx), "start sphere center"));
  cyc_skin_end inner;
  const double mi[3] = {0.2, 0, 0}, pi[3] = {0.3, 0, 0}, ti[3] = {1, 0, 0};
  ASSERT_EQ(cyc_skin_end_from_sphere(ctx, mi, 0.3, pi, ti, &inner), CYC_OK);
  EXPECT_EQ(create(s, inner), CYC_E_NESTED_SPHERES);
  // kappa r >= 1 at the start (short tangent), then at the end.
  b = s;
  for (double& v : b.tangent) v *= 0.05;
  b.inv_c *= 0.05;  // the same cone and sphere (inv_c = |t|^2 / ((x - p) . t))
  EXPECT_EQ(create(b, e), CYC_E_CURVATURE_RADIUS_TOO_LARGE);
  EXPECT_TRUE(contains(cyc_context_last_error(ctx), "kappa r = "));
  EXPECT_TRUE(contains(cyc_context_last_error(ctx), "at the start (t = 0)"))
      << cyc_context_last_error(ctx);
  b = e;
  for (double& v : b.tangent) v *= 0.05;
  b.inv_c *= 0.05;
  EXPECT_EQ(create(s, b), CYC_E_CURVATURE_RADIUS_TOO_LARGE);
  EXPECT_TRUE(contains(cyc_context_last_error(ctx), "at the end (t = 1)"))
      << cyc_context_last_error(ctx);
  // Cross tangents with parallel tangents.
  cyc_skin_options_init(&o);
  o.pairing = CYC_SKIN_CROSS_TANGENTS;
  b = e;
  std::memcpy(b.tangent, s.tangent, sizeof b.tangent);
  EXPECT_EQ(create(s, b, &o), CYC_E_PARALLEL_LINES);
  // Valid ends (|x| <= 1e100) whose spine leaves the input range: an
  // overflow, not a non-finite input (fuzz_skin's
  // regress-spine-beyond-input-range; the core said NOT_FINITE).
  cyc_skin_end far_a{{-1e100, 0, 0}, 1, {1, 0, 0}, 0}, far_b{{1e100, 0, 0}, 1, {1, 0, 0}, 0};
  EXPECT_EQ(create(far_a, far_b), CYC_E_NUMERICAL_OVERFLOW);
  EXPECT_TRUE(contains(cyc_context_last_error(ctx), "spine's power-form coefficients"))
      << cyc_context_last_error(ctx);
  // A tolerance that cannot be met fails cleanly (and in bounded time).
  cyc_skin_options_init(&o);
  o.tolerance = 1e-300;
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_EQ(create(s, e, &o), CYC_E_NUMERICAL_OVERFLOW);
  EXPECT_TRUE(contains(cyc_context_last_error(ctx), "tolerance"));
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 30.0);
  EXPECT_EQ(cyc_context_last_status(ctx), CYC_E_NUMERICAL_OVERFLOW);
}

TEST(SphereSkinCapi, StatusNames) {
  EXPECT_STREQ(cyc_status_name(CYC_E_NESTED_SPHERES), "CYC_E_NESTED_SPHERES");
  EXPECT_STREQ(cyc_status_name(117), "CYC_E_NESTED_SPHERES");
  EXPECT_STREQ(cyc_status_name(CYC_E_CURVATURE_RADIUS_TOO_LARGE),
               "CYC_E_CURVATURE_RADIUS_TOO_LARGE");
  EXPECT_STREQ(cyc_status_name(118), "CYC_E_CURVATURE_RADIUS_TOO_LARGE");
  EXPECT_STREQ(cyc_status_name(128), "CYC_E_DEVELOPABLE");
  EXPECT_STREQ(cyc_status_name(131), "CYC_E_UNKNOWN");
}

namespace {

// A counting allocator that can fail the n-th allocation.
struct Counting {
  long allocs = 0, frees = 0, fail_at = -1, live = 0;
  static void* alloc(void* ud, size_t size, size_t alignment) {
    auto* c = static_cast<Counting*>(ud);
    if (c->allocs++ == c->fail_at) return nullptr;
    const size_t a = alignment < alignof(std::max_align_t) ? alignof(std::max_align_t) : alignment;
    ++c->live;
    return std::aligned_alloc(a, (size + a - 1) / a * a);
  }
  static void free(void* ud, void* p) {
    if (!p) return;
    ++static_cast<Counting*>(ud)->frees;
    --static_cast<Counting*>(ud)->live;
    std::free(p);
  }
};

}  // namespace

// Handles come from the context's allocator and go back to it; a failing
// allocator gives CYC_E_OUT_OF_MEMORY with nothing leaked or written.
TEST(SphereSkinCapi, ContextAllocatorAndOutOfMemory) {
  Counting C;
  const cyc_allocator A = {&Counting::alloc, &Counting::free, &C};
  cyc_context* ctx = nullptr;
  ASSERT_EQ(cyc_context_create(&A, &ctx), CYC_OK);
  cyc_skin_end ends[3];
  const double m0[3] = {0, 0, 0}, p0[3] = {0.3, 0, 0}, t0[3] = {3, 0, 0};
  ASSERT_EQ(cyc_skin_end_from_sphere(ctx, m0, 1.0, p0, t0, &ends[0]), CYC_OK);
  const double m1[3] = {4, 0, 1}, p1[3] = {3.7, 0, 1}, t1[3] = {3, 0, 0};
  ASSERT_EQ(cyc_skin_end_from_sphere(ctx, m1, 1.0, p1, t1, &ends[1]), CYC_OK);
  const double m2[3] = {8, 1, 1}, p2[3] = {7.7, 1, 1}, t2[3] = {3, 0, 0};
  ASSERT_EQ(cyc_skin_end_from_sphere(ctx, m2, 1.0, p2, t2, &ends[2]), CYC_OK);
  const long base = C.allocs;
  // Every allocation of a single skin and of a chain failing in turn.
  for (int chain = 0; chain < 2; ++chain)
    for (long k = 0;; ++k) {
      C.fail_at = base + k;
      C.allocs = base;
      const long frees0 = C.frees;
      cyc_sphere_skin* h = kHandleSentinel;
      int bad = -7;
      const int st = chain ? cyc_sphere_skin_chain_create(ctx, ends, 3, nullptr, &h, &bad)
                           : cyc_sphere_skin_create(ctx, &ends[0], &ends[1], nullptr, &h);
      if (st == CYC_OK) {
        ASSERT_NE(h, kHandleSentinel);
        int count = 0;
        ASSERT_EQ(cyc_sphere_skin_patch_count(ctx, h, &count), CYC_OK);
        EXPECT_EQ(count, chain ? 2 : 1);
        // The handle lives in the allocator's memory: destroying frees it all.
        const long live = (C.allocs - base) - (C.frees - frees0);
        cyc_sphere_skin_destroy(ctx, h);
        EXPECT_EQ(C.frees - frees0, C.allocs - base);
        EXPECT_GE(live, 2);
        EXPECT_GE(k, 2);
        break;
      }
      EXPECT_EQ(st, CYC_E_OUT_OF_MEMORY) << k;
      EXPECT_TRUE(contains(cyc_context_last_error(ctx), "allocator returned NULL"));
      EXPECT_EQ(h, kHandleSentinel);
      EXPECT_EQ(bad, -7);
      EXPECT_EQ(C.frees - frees0, C.allocs - base - 1);  // everything taken was given back
      ASSERT_LT(k, 10);
    }
  // Evaluation allocates nothing from the context.
  C.fail_at = -1;
  cyc_sphere_skin* h = nullptr;
  ASSERT_EQ(cyc_sphere_skin_chain_create(ctx, ends, 3, nullptr, &h, nullptr), CYC_OK);
  const long before = C.allocs;
  double x[3], n[3], P[12], tw, lam;
  const double th[2] = {0, 1}, ts[2] = {0, 1};
  cyc_sphere_skin_info I;
  EXPECT_EQ(cyc_sphere_skin_eval(ctx, h, 1, 0.3, 0.4, x, nullptr, nullptr, n), CYC_OK);
  EXPECT_EQ(cyc_sphere_skin_eval_grid(ctx, h, 0, th, 2, ts, 2, P, nullptr, nullptr), CYC_OK);
  EXPECT_EQ(cyc_sphere_skin_twist(ctx, h, 1, 0.3, &tw), CYC_OK);
  EXPECT_EQ(cyc_sphere_skin_lambda(ctx, h, 0, 0.3, 0.2, &lam, nullptr), CYC_OK);
  EXPECT_EQ(cyc_sphere_skin_info_get(ctx, h, 1, &I), CYC_OK);
  EXPECT_EQ(C.allocs, before);
  // Handles may outlive their context.
  cyc_context_destroy(ctx);
  EXPECT_EQ(C.live, 2);  // the handle and its patches
  cyc_sphere_skin_destroy(nullptr, h);
  EXPECT_EQ(C.live, 0);
}

// A grid fails where a single evaluation fails: points beyond the range
// (|x| > 1e100 from ends within it) are CYC_E_NUMERICAL_OVERFLOW in both,
// and the grid writes nothing (the core's grid returned OK with them).
TEST_F(SkinCapi, GridOverflowsWhereEvalOverflows) {
  const cyc_skin_end a{{0, 0, 0}, 1e100, {1e100, 0, 0}, 0};
  const cyc_skin_end b{{1e100, 0, 0}, 1e100, {1e100, 0, 0}, 0};
  cyc_sphere_skin* h = nullptr;
  ASSERT_EQ(cyc_sphere_skin_create(ctx, &a, &b, nullptr, &h), CYC_OK)
      << cyc_context_last_error(ctx);
  owned.push_back(h);
  const double th[2] = {0, 1}, ts[2] = {0.0, 1.0};
  double P[12], N[12], x[3];
  fill(P, 12);
  fill(N, 12);
  fill(x, 3);
  EXPECT_EQ(cyc_sphere_skin_eval(ctx, h, 0, 0, 1.0, x, nullptr, nullptr, nullptr),
            CYC_E_NUMERICAL_OVERFLOW);
  EXPECT_EQ(cyc_sphere_skin_eval_grid(ctx, h, 0, th, 2, ts, 2, P, nullptr, nullptr),
            CYC_E_NUMERICAL_OVERFLOW);
  // With normals too: the points at t = 1 overflow (a singular normal alone
  // would be written as zero and counted).
  double n[3];
  EXPECT_NE(cyc_sphere_skin_eval(ctx, h, 0, 0, 0.0, nullptr, nullptr, nullptr, n), CYC_OK);
  size_t singular = 77;
  EXPECT_EQ(cyc_sphere_skin_eval_grid(ctx, h, 0, th, 2, ts, 2, P, N, &singular),
            CYC_E_NUMERICAL_OVERFLOW);
  EXPECT_EQ(singular, 77u);
  EXPECT_TRUE(untouched(P, 12) && untouched(N, 12) && untouched(x, 3));
}

// Issue 9 (SPEC.md §8j.1b): the export of a chain through the C ABI is the
// core's export, evaluates onto the skin within the tolerance at the
// reported (u, v) (u = patch + t, theta = 2 atan v), assembles into one
// NURBS, writes JSON, and every error leaves *out and *report untouched.
TEST_F(SkinCapi, ExportOfAChain) {
  cyc_skin_end ends[3];
  chain_ends(ends);
  cyc_sphere_skin* h = nullptr;
  ASSERT_EQ(cyc_sphere_skin_chain_create(ctx, ends, 3, nullptr, &h, nullptr), CYC_OK);
  owned.push_back(h);
  cyc_skin_export_options o;
  cyc_skin_export_options_default(&o);
  EXPECT_EQ(o.tolerance, cyclide::SkinExportOptions{}.tolerance);
  EXPECT_EQ(o.degree, cyclide::SkinExportOptions{}.degree);
  const cyc_export_domain whole = {0, 2, 0, 0, 1};
  cyc_bezier_export* E = nullptr;
  cyc_skin_export_report r{};
  ASSERT_EQ(cyc_sphere_skin_export_create(ctx, h, &whole, &o, &E, &r), CYC_OK)
      << cyc_context_last_error(ctx);
  const int n = cyc_bezier_export_count(E);
  EXPECT_EQ(n, 4 * r.t_intervals);
  EXPECT_EQ(r.exact, 0);
  EXPECT_LE(r.error_estimate, 2 * o.tolerance);
  double worst = 0.0;
  for (int i = 0; i < n; ++i) {
    cyc_bezier_patch_info info;
    ASSERT_EQ(cyc_bezier_export_patch(ctx, E, i, &info, nullptr, 0), CYC_OK);
    EXPECT_EQ(info.deg_u, o.degree + 3);
    EXPECT_EQ(info.deg_v, 4);
    for (double st : {0.0, 0.37, 1.0})
      for (double tt : {0.0, 0.61, 1.0}) {
        double x[3], uv[2], y[3];
        ASSERT_EQ(cyc_bezier_export_eval(ctx, E, i, st, tt, x, uv), CYC_OK);
        const int k = std::min(1, int(uv[0]));
        ASSERT_EQ(cyc_sphere_skin_eval(ctx, h, k, 2 * std::atan(uv[1]),
                                       std::min(1.0, uv[0] - k), y, nullptr, nullptr, nullptr),
                  CYC_OK);
        worst = std::max(worst, dist(x, y));
      }
  }
  EXPECT_LE(worst, 2 * o.tolerance);
  cyc_nurbs_size N;
  ASSERT_EQ(cyc_bezier_export_nurbs(ctx, E, &N, nullptr, 0, nullptr, 0, nullptr, 0), CYC_OK);
  EXPECT_EQ(N.deg_v, 4);
  std::vector<double> ku(size_t(N.knots_u)), kv(size_t(N.knots_v)),
      cp(4 * size_t(N.cp_u) * size_t(N.cp_v));
  EXPECT_EQ(cyc_bezier_export_nurbs(ctx, E, &N, ku.data(), ku.size(), kv.data(), kv.size(),
                                    cp.data(), cp.size()),
            CYC_OK)
      << cyc_context_last_error(ctx);
  const std::string path = ::testing::TempDir() + "skin_export.json";
  ASSERT_EQ(cyc_bezier_export_write_json(ctx, E, path.c_str()), CYC_OK);
  std::FILE* f = std::fopen(path.c_str(), "r");
  ASSERT_NE(f, nullptr);
  char head[64] = {0};
  EXPECT_GT(std::fread(head, 1, sizeof head - 1, f), 0u);
  std::fclose(f);
  EXPECT_TRUE(contains(head, "cyclide-rational-bezier")) << head;
  std::remove(path.c_str());
  cyc_bezier_export_destroy(E);

  // Errors: nothing written.
  cyc_bezier_export* const kOut = reinterpret_cast<cyc_bezier_export*>(uintptr_t(0x5eed0bad1000));
  const auto fails = [&](const cyc_export_domain& d, const cyc_skin_export_options* op,
                         int want, const char* what) {
    cyc_bezier_export* out = kOut;
    cyc_skin_export_report rep{};
    rep.t_intervals = -9;
    EXPECT_EQ(cyc_sphere_skin_export_create(ctx, h, &d, op, &out, &rep), want) << what;
    EXPECT_EQ(out, kOut) << what;
    EXPECT_EQ(rep.t_intervals, -9) << what;
    EXPECT_TRUE(contains(cyc_context_last_error(ctx), "cyc_sphere_skin_export_create")) << what;
  };
  cyc_skin_export_options bad = o;
  bad.tolerance = 0;
  fails(whole, &bad, CYC_E_INVALID_ARGUMENT, "tolerance 0");
  bad = o;
  bad.degree = 25;
  fails(whole, &bad, CYC_E_INVALID_ARGUMENT, "degree 25");
  bad = o;
  bad.tolerance = 1e-19;
  fails(whole, &bad, CYC_E_NUMERICAL_OVERFLOW, "tolerance below rounding");
  fails({0, 2.5, 0, 0, 1}, nullptr, CYC_E_BAD_DOMAIN, "u beyond the chain");
  fails({0, 1, 1, -1, 0}, nullptr, CYC_E_BAD_DOMAIN, "v reversed");
  fails({kNaN, 1, 0, 0, 1}, nullptr, CYC_E_NOT_FINITE, "NaN");
  cyc_bezier_export* out = kOut;
  EXPECT_EQ(cyc_sphere_skin_export_create(ctx, nullptr, &whole, nullptr, &out, nullptr),
            CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_sphere_skin_export_create(ctx, h, nullptr, nullptr, &out, nullptr),
            CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(out, kOut);
  // A straight spine (coaxial circles) exports exactly.
  const double m0[3] = {0, 0, 0}, p0[3] = {0.2, 0, 0}, t0[3] = {2, 0, 0};
  const double m1[3] = {3, 0, 0}, p1[3] = {2.9, 0, 0};
  cyc_skin_end a, b;
  ASSERT_EQ(cyc_skin_end_from_sphere(ctx, m0, 1.0, p0, t0, &a), CYC_OK);
  ASSERT_EQ(cyc_skin_end_from_sphere(ctx, m1, 0.5, p1, t0, &b), CYC_OK);
  cyc_sphere_skin* straight = nullptr;
  ASSERT_EQ(cyc_sphere_skin_create(ctx, &a, &b, nullptr, &straight), CYC_OK);
  owned.push_back(straight);
  const cyc_export_domain one = {0, 1, 0, 0, 1};
  ASSERT_EQ(cyc_sphere_skin_export_create(ctx, straight, &one, nullptr, &E, &r), CYC_OK);
  EXPECT_EQ(r.exact, 1);
  EXPECT_EQ(r.t_intervals, 1);
  EXPECT_LE(r.error_estimate, 1e-14);
  cyc_bezier_export_destroy(E);
}
