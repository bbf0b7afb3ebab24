// Issue 10 item 3: thread safety (SPEC.md §2: a context is used by one
// thread at a time; handles are immutable after creation and may be shared
// read-only). Several threads evaluate shared read-only handles -- a canal
// blend of the two cones of seed 000 Fig. 6, a sphere skin and the exact
// export of a cone -- each with its own context, while other threads
// create and destroy their own handles (with heap and static contexts) and
// provoke errors. Every result must equal the single-threaded reference bit
// for bit. Labels "ffi;threads"; scripts/test runs it in the ThreadSanitizer
// build (preset tsan), where any data race fails the test.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <thread>
#include <vector>

#include "cyclide/cyclide.h"

namespace {

constexpr int kEvaluators = 4;
constexpr int kChurners = 2;
constexpr int kRounds = 200;

// A cone with apex A and axis e3: the PRRS through three of its lines
// (tests/consumer/consumer.c).
cyc_surface* cone(cyc_context* ctx, const double A[3], const double e1[3], const double e2[3],
                  const double e3[3]) {
  cyc_curve* L[3] = {nullptr, nullptr, nullptr};
  cyc_surface* S = nullptr;
  bool ok = true;
  for (int k = 0; k < 3; ++k) {
    const double t = 2 * M_PI * k / 3 + 0.3;
    double d[3];
    for (int j = 0; j < 3; ++j) d[j] = std::cos(t) * e1[j] + std::sin(t) * e2[j] + e3[j];
    ok = ok && cyc_curve_create_line(ctx, A, d, &L[k]) == CYC_OK;
  }
  if (ok && cyc_prrs_create(ctx, L[0], L[1], L[2], nullptr, 0.5, 1.0, &S) != CYC_OK) S = nullptr;
  for (cyc_curve* c : L) cyc_curve_destroy(ctx, c);
  return S;
}

// The shared scene: two cones, their canal blend, a skin, an export.
struct Scene {
  cyc_surface *a = nullptr, *b = nullptr, *blend = nullptr;
  cyc_sphere_skin* skin = nullptr;
  cyc_bezier_export* patches = nullptr;
  bool build(cyc_context* ctx) {
    const double O[3] = {0, 0, 0}, A2[3] = {4, 0, 4}, X[3] = {1, 0, 0}, Y[3] = {0, 1, 0},
                 Z[3] = {0, 0, 1}, MX[3] = {-1, 0, 0};
    a = cone(ctx, O, X, Y, Z);
    b = cone(ctx, A2, Y, Z, MX);
    if (!a || !b) return false;
    cyc_blend_end s;
    std::memset(&s, 0, sizeof s);
    s.surface = a;
    s.u = 1.0;
    s.v[0] = HUGE_VAL;
    s.v[1] = -0.5;
    s.v[2] = 0.7;
    cyc_blend_end e = s;
    e.surface = b;
    if (cyc_blend_canal(ctx, &s, &e, 2, 0.0, 1.0, &blend) != CYC_OK) return false;
    cyc_skin_end ends[2];
    const double m0[3] = {0, 0, 0}, p0[3] = {0.3, 0, 0}, t0[3] = {3, 0, 0};
    const double m1[3] = {4, 1, 0.5}, p1[3] = {3.7, 1, 0.5}, t1[3] = {3, 0, 0};
    if (cyc_skin_end_from_sphere(ctx, m0, 1.0, p0, t0, &ends[0]) != CYC_OK ||
        cyc_skin_end_from_sphere(ctx, m1, 1.2, p1, t1, &ends[1]) != CYC_OK ||
        cyc_sphere_skin_create(ctx, &ends[0], &ends[1], nullptr, &skin) != CYC_OK)
      return false;
    // The export of cone a (the canal blend's spine passes through infinity
    // on whole circles: one of its circles is a line).
    const cyc_export_domain whole = {0.5, 1.0, 0, 0, 1};
    return cyc_bezier_export_create(ctx, a, &whole, &patches) == CYC_OK;
  }
  void destroy(cyc_context* ctx) {
    cyc_bezier_export_destroy(patches);
    cyc_sphere_skin_destroy(ctx, skin);
    cyc_surface_destroy(ctx, blend);
    cyc_surface_destroy(ctx, b);
    cyc_surface_destroy(ctx, a);
  }
};

constexpr int kNu = 7, kNv = 6;

// Everything an evaluator computes from the shared scene, in one vector.
std::vector<double> evaluate(cyc_context* ctx, const Scene& S, int& failures) {
  std::vector<double> out;
  double us[kNu], vs[kNv];
  for (int i = 0; i < kNu; ++i) us[i] = double(i) / (kNu - 1);
  for (int j = 0; j < kNv; ++j) vs[j] = -2.5 + 0.9 * j;
  std::vector<double> P(3 * kNu * kNv), N(3 * kNu * kNv);
  size_t singular = 0;
  failures += cyc_surface_eval_grid(ctx, S.blend, us, kNu, vs, kNv, {P.data(), P.size() / 3, 3},
                                    {nullptr, 0, 3}, {nullptr, 0, 3}, {N.data(), N.size() / 3, 3},
                                    &singular) != CYC_OK;
  out.insert(out.end(), P.begin(), P.end());
  out.insert(out.end(), N.begin(), N.end());
  for (double th : {-2.0, 0.3, 1.9}) {
    double x[3], n[3];
    failures += cyc_sphere_skin_eval(ctx, S.skin, 0, th, 0.37, x, nullptr, nullptr, n) != CYC_OK;
    out.insert(out.end(), x, x + 3);
    out.insert(out.end(), n, n + 3);
  }
  for (int k = 0; k < cyc_bezier_export_count(S.patches); ++k) {
    double x[3], uv[2];
    failures += cyc_bezier_export_eval(ctx, S.patches, k, 0.3, 0.8, x, uv) != CYC_OK;
    out.insert(out.end(), x, x + 3);
  }
  // An error on the shared handle: reported in this thread's context only.
  double x[3];
  failures += cyc_surface_eval(ctx, S.blend, NAN, 0.0, x, nullptr, nullptr, nullptr) !=
              CYC_E_NOT_FINITE;
  failures += std::strstr(cyc_context_last_error(ctx), "cyc_surface_eval") == nullptr;
  return out;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// Creates and destroys its own handles: a scene in a heap context, then in
// a static one (the caller-memory tier), with an error path in between.
void churn(int rounds, std::atomic<int>& failures) {
  static thread_local std::vector<unsigned char> block(1 << 20);
  for (int r = 0; r < rounds; ++r) {
    cyc_context* ctx = nullptr;
    const bool in_block = r % 2 == 1;
    if (in_block ? cyc_context_init_static(block.data(), block.size(), nullptr, &ctx) != CYC_OK
                 : cyc_context_create(nullptr, &ctx) != CYC_OK) {
      ++failures;
      continue;
    }
    Scene mine;
    if (!mine.build(ctx)) ++failures;
    const double O[3] = {0, 0, 0}, Zero[3] = {0, 0, 0};
    cyc_curve* bad = nullptr;
    if (cyc_curve_create_line(ctx, O, Zero, &bad) == CYC_OK) ++failures;  // zero direction
    mine.destroy(ctx);
    cyc_context_destroy(ctx);
  }
}

}  // namespace

TEST(Threads, SharedReadOnlyHandlesWhileOthersCreateAndDestroy) {
  cyc_context* main_ctx = nullptr;
  ASSERT_EQ(cyc_context_create(nullptr, &main_ctx), CYC_OK);
  Scene shared;
  ASSERT_TRUE(shared.build(main_ctx)) << cyc_context_last_error(main_ctx);
  int ref_failures = 0;
  const std::vector<double> reference = evaluate(main_ctx, shared, ref_failures);
  ASSERT_EQ(ref_failures, 0) << cyc_context_last_error(main_ctx);
  ASSERT_GT(reference.size(), 250u);

  std::atomic<int> failures{0}, mismatches{0};
  std::vector<std::thread> threads;
  for (int k = 0; k < kEvaluators; ++k)
    threads.emplace_back([&] {
      cyc_context* ctx = nullptr;
      if (cyc_context_create(nullptr, &ctx) != CYC_OK) {
        ++failures;
        return;
      }
      for (int r = 0; r < kRounds; ++r) {
        int f = 0;
        if (!same_bits(evaluate(ctx, shared, f), reference)) ++mismatches;
        failures += f;
      }
      cyc_context_destroy(ctx);
    });
  for (int k = 0; k < kChurners; ++k) threads.emplace_back([&] { churn(kRounds / 4, failures); });
  for (std::thread& t : threads) t.join();

  EXPECT_EQ(failures.load(), 0);
  EXPECT_EQ(mismatches.load(), 0);
  // The main context saw none of the threads' errors.
  EXPECT_EQ(cyc_context_last_status(main_ctx), CYC_E_NOT_FINITE);  // its own last call
  shared.destroy(main_ctx);
  cyc_context_destroy(main_ctx);
}
