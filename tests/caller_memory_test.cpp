// Issue 10 item 4: the caller-memory tier (SPEC.md §9b; labels capi;ffi):
// a context placed in the caller's block with cyc_context_init_static, its
// handles carved from the rest of the block, sized by the static size
// queries; with and without a fallback allocator. The zero-heap proof is
// CallerMemory.NoHeapAtAll in tests/alloc_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "cyclide/cyclide.h"

namespace {

// A PRCS of two lines (seed 000 Example 2's shape) through ctx.
int make_prcs(cyc_context* ctx, cyc_curve** l1, cyc_curve** l2, cyc_surface** s) {
  const double O[3] = {0, 0, 0}, X[3] = {1, 0, 0}, P[3] = {0, 0, 1}, w[3] = {2, 1, 0};
  if (int st = cyc_curve_create_line(ctx, O, X, l1)) return st;
  if (int st = cyc_curve_create_line(ctx, P, w, l2)) return st;
  return cyc_prcs_create(ctx, *l1, *l2, nullptr, -0.5, 0.5, s);
}

// A counting fallback allocator.
struct Counting {
  int allocs = 0, frees = 0;
  static void* alloc(void* ud, size_t size, size_t alignment) {
    ++static_cast<Counting*>(ud)->allocs;
    const size_t a = alignment < alignof(std::max_align_t) ? alignof(std::max_align_t) : alignment;
    return std::aligned_alloc(a, (size + a - 1) / a * a);
  }
  static void free(void* ud, void* p) {
    ++static_cast<Counting*>(ud)->frees;
    std::free(p);
  }
  cyc_allocator allocator() { return {alloc, free, this}; }
};

bool inside(const void* p, const std::vector<unsigned char>& block) {
  const auto* c = static_cast<const unsigned char*>(p);
  return c >= block.data() && c < block.data() + block.size();
}

}  // namespace

// The sizes the queries promise are enough: a block of exactly
// context + 2 curves + 1 surface holds them, at any alignment of the block.
TEST(CallerMemory, SizeQueriesSufficeAtAnyAlignment) {
  const size_t need =
      cyc_context_static_size() + 2 * cyc_curve_static_size() + cyc_surface_static_size();
  for (size_t offset = 0; offset < 16; ++offset) {
    std::vector<unsigned char> block(need + offset);
    cyc_context* ctx = nullptr;
    ASSERT_EQ(cyc_context_init_static(block.data() + offset, need, nullptr, &ctx), CYC_OK);
    EXPECT_TRUE(inside(ctx, block));
    cyc_curve *l1 = nullptr, *l2 = nullptr;
    cyc_surface* s = nullptr;
    ASSERT_EQ(make_prcs(ctx, &l1, &l2, &s), CYC_OK) << offset << cyc_context_last_error(ctx);
    EXPECT_TRUE(inside(l1, block) && inside(l2, block) && inside(s, block));
    double x[3], n[3];
    ASSERT_EQ(cyc_surface_eval(ctx, s, 0.1, 0.3, x, nullptr, nullptr, n), CYC_OK);
    EXPECT_TRUE(std::isfinite(x[0]) && std::abs(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] - 1) < 1e-12);
    cyc_surface_destroy(ctx, s);
    cyc_curve_destroy(ctx, l2);
    cyc_curve_destroy(ctx, l1);
    cyc_context_destroy(ctx);
  }
}

// Without a fallback the block's end is CYC_E_OUT_OF_MEMORY with a message,
// *out untouched; the remaining bytes shrink by at most the static sizes;
// destroying the most recent handle gives its bytes back, an older one not.
TEST(CallerMemory, ExhaustionAndTheMostRecentBlock) {
  std::vector<unsigned char> block(cyc_context_static_size() + 2 * cyc_curve_static_size() +
                                   cyc_surface_static_size() / 2);
  cyc_context* ctx = nullptr;
  ASSERT_EQ(cyc_context_init_static(block.data(), block.size(), nullptr, &ctx), CYC_OK);
  const size_t r0 = cyc_context_static_remaining(ctx);
  const double O[3] = {0, 0, 0}, X[3] = {1, 0, 0}, P[3] = {0, 0, 1}, w[3] = {2, 1, 0};
  cyc_curve *l1 = nullptr, *l2 = nullptr;
  ASSERT_EQ(cyc_curve_create_line(ctx, O, X, &l1), CYC_OK);
  const size_t r1 = cyc_context_static_remaining(ctx);
  EXPECT_LE(r0 - r1, cyc_curve_static_size());
  ASSERT_EQ(cyc_curve_create_line(ctx, P, w, &l2), CYC_OK);
  cyc_surface* const kSentinel = reinterpret_cast<cyc_surface*>(std::uintptr_t(0x5eed));
  cyc_surface* s = kSentinel;
  EXPECT_EQ(cyc_prcs_create(ctx, l1, l2, nullptr, -0.5, 0.5, &s), CYC_E_OUT_OF_MEMORY);
  EXPECT_EQ(s, kSentinel);
  EXPECT_NE(std::strstr(cyc_context_last_error(ctx), "cyc_prcs_create"), nullptr);
  // The most recent block (l2) comes back; then l1 is not the most recent.
  const size_t r2 = cyc_context_static_remaining(ctx);
  cyc_curve_destroy(ctx, l2);
  EXPECT_EQ(cyc_context_static_remaining(ctx), r1);
  EXPECT_GT(cyc_context_static_remaining(ctx), r2);
  cyc_curve_destroy(ctx, l1);
  EXPECT_EQ(cyc_context_static_remaining(ctx), r1);  // l1 is not the most recent any more
  cyc_context_destroy(ctx);
  // An ordinary context has no block.
  cyc_context* heap = nullptr;
  ASSERT_EQ(cyc_context_create(nullptr, &heap), CYC_OK);
  EXPECT_EQ(cyc_context_static_remaining(heap), 0u);
  cyc_context_destroy(heap);
  EXPECT_EQ(cyc_context_static_remaining(nullptr), 0u);
}

// With a fallback allocator what does not fit goes to it (and back to it
// when destroyed); what fits never does.
TEST(CallerMemory, FallbackAllocatorTakesTheOverflow) {
  Counting counting;
  const cyc_allocator fb = counting.allocator();
  std::vector<unsigned char> block(cyc_context_static_size() + 2 * cyc_curve_static_size());
  cyc_context* ctx = nullptr;
  ASSERT_EQ(cyc_context_init_static(block.data(), block.size(), &fb, &ctx), CYC_OK);
  cyc_curve *l1 = nullptr, *l2 = nullptr;
  cyc_surface* s = nullptr;
  ASSERT_EQ(make_prcs(ctx, &l1, &l2, &s), CYC_OK) << cyc_context_last_error(ctx);
  EXPECT_TRUE(inside(l1, block) && inside(l2, block));
  EXPECT_FALSE(inside(s, block));
  EXPECT_EQ(counting.allocs, 1);
  double x[3];
  ASSERT_EQ(cyc_surface_eval(ctx, s, 0.2, -0.4, x, nullptr, nullptr, nullptr), CYC_OK);
  cyc_surface_destroy(ctx, s);
  EXPECT_EQ(counting.frees, 1);
  cyc_curve_destroy(ctx, l2);
  cyc_curve_destroy(ctx, l1);
  cyc_context_destroy(ctx);
  EXPECT_EQ(counting.allocs, 1);
  EXPECT_EQ(counting.frees, 1);
}

// Same results as a heap context, bit for bit.
TEST(CallerMemory, SameBitsAsAHeapContext) {
  std::vector<unsigned char> block(cyc_context_static_size() + 2 * cyc_curve_static_size() +
                                   cyc_surface_static_size());
  cyc_context *a = nullptr, *b = nullptr;
  ASSERT_EQ(cyc_context_init_static(block.data(), block.size(), nullptr, &a), CYC_OK);
  ASSERT_EQ(cyc_context_create(nullptr, &b), CYC_OK);
  cyc_curve *a1, *a2, *b1, *b2;
  cyc_surface *sa, *sb;
  ASSERT_EQ(make_prcs(a, &a1, &a2, &sa), CYC_OK) << cyc_context_last_error(a);
  ASSERT_EQ(make_prcs(b, &b1, &b2, &sb), CYC_OK);
  for (double u : {-0.5, 0.0, 0.33})
    for (double v : {-3.0, 0.0, 0.7}) {
      double x[3], y[3];
      ASSERT_EQ(cyc_surface_eval(a, sa, u, v, x, nullptr, nullptr, nullptr), CYC_OK);
      ASSERT_EQ(cyc_surface_eval(b, sb, u, v, y, nullptr, nullptr, nullptr), CYC_OK);
      EXPECT_EQ(std::memcmp(x, y, sizeof x), 0);
    }
  cyc_surface_destroy(b, sb);
  cyc_curve_destroy(b, b1);
  cyc_curve_destroy(b, b2);
  cyc_context_destroy(b);
  cyc_context_destroy(a);  // a's handles are simply abandoned with the block
}

TEST(CallerMemory, InitErrors) {
  unsigned char block[4096];
  cyc_context* const kSentinel = reinterpret_cast<cyc_context*>(std::uintptr_t(0x5eed));
  cyc_context* ctx = kSentinel;
  EXPECT_EQ(cyc_context_init_static(nullptr, 4096, nullptr, &ctx), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_context_init_static(block, sizeof block, nullptr, nullptr), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_context_init_static(block, cyc_context_static_size() - 1, nullptr, &ctx),
            CYC_E_BUFFER_TOO_SMALL);
  const cyc_allocator half = {Counting::alloc, nullptr, nullptr};
  EXPECT_EQ(cyc_context_init_static(block, sizeof block, &half, &ctx), CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(ctx, kSentinel);
}
