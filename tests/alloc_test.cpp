// The evaluation entry points of the C ABI perform zero heap allocations
// (label capi). Global operator new/delete (every variant) and the C heap
// functions are replaced by counting wrappers that forward to glibc's
// __libc_* implementations; the counters only count inside an armed region.
// Positive controls prove that the counters see allocations made by this
// file, by the C++ runtime and by libcyclide.so itself.
#include <gtest/gtest.h>

#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <new>
#include <vector>

#include "cyclide/cyclide.h"
#include "cyclide/darboux_classify.hpp"
#include "cyclide/cyclide_blend.hpp"
#include "cyclide/dupin.hpp"
#include "cyclide/implicitize.hpp"
#include "cyclide/skin_export.hpp"
#include "cyclide/sphere_skin.hpp"
#include "cyclide/surface.hpp"

#if !defined(__GLIBC__)
#error "alloc_test forwards to glibc's __libc_malloc family"
#endif

// ------------------------------------------------------------ counting heap

extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t n, std::size_t size);
void* __libc_realloc(void* p, std::size_t size);
void __libc_free(void* p);
void* __libc_memalign(std::size_t alignment, std::size_t size);
void* __libc_valloc(std::size_t size);
void* __libc_pvalloc(std::size_t size);
}

namespace {

std::atomic<bool> g_armed{false};
std::atomic<long> g_allocations{0};  // allocations made while armed
std::atomic<long> g_frees{0};        // frees made while armed

inline void note_allocation() {
  if (g_armed.load(std::memory_order_relaxed))
    g_allocations.fetch_add(1, std::memory_order_relaxed);
}
inline void note_free(void* p) {
  if (p && g_armed.load(std::memory_order_relaxed)) g_frees.fetch_add(1, std::memory_order_relaxed);
}

void* aligned_or_null(std::size_t alignment, std::size_t size) {
  if (alignment < sizeof(void*)) alignment = sizeof(void*);
  return __libc_memalign(alignment, size ? size : 1);
}

void* new_or_throw(std::size_t size) {
  note_allocation();
  void* p = __libc_malloc(size ? size : 1);
  if (!p) throw std::bad_alloc();
  return p;
}
void* new_aligned_or_throw(std::size_t size, std::align_val_t a) {
  note_allocation();
  void* p = aligned_or_null(static_cast<std::size_t>(a), size);
  if (!p) throw std::bad_alloc();
  return p;
}
void delete_any(void* p) noexcept {
  note_free(p);
  __libc_free(p);
}

// Results of an armed region.
struct Heap {
  long allocations = 0;
  long frees = 0;
};

// Run f with the counters armed. Nothing else (no gtest) runs in between.
template <class F>
Heap measure(F&& f) {
  g_allocations.store(0);
  g_frees.store(0);
  g_armed.store(true);
  f();
  g_armed.store(false);
  Heap h;
  h.allocations = g_allocations.load();
  h.frees = g_frees.load();
  return h;
}

}  // namespace

#define CYC_TEST_EXPORT __attribute__((visibility("default"), used))

// The C heap (exported so that libcyclide.so and libstdc++ bind to it).
extern "C" {
CYC_TEST_EXPORT void* malloc(std::size_t size) noexcept {
  note_allocation();
  return __libc_malloc(size);
}
CYC_TEST_EXPORT void* calloc(std::size_t n, std::size_t size) noexcept {
  note_allocation();
  return __libc_calloc(n, size);
}
CYC_TEST_EXPORT void* realloc(void* p, std::size_t size) noexcept {
  note_allocation();
  return __libc_realloc(p, size);
}
CYC_TEST_EXPORT void free(void* p) noexcept {
  note_free(p);
  __libc_free(p);
}
CYC_TEST_EXPORT void* aligned_alloc(std::size_t alignment, std::size_t size) noexcept {
  note_allocation();
  return __libc_memalign(alignment, size);
}
CYC_TEST_EXPORT void* memalign(std::size_t alignment, std::size_t size) noexcept {
  note_allocation();
  return __libc_memalign(alignment, size);
}
CYC_TEST_EXPORT int posix_memalign(void** out, std::size_t alignment, std::size_t size) noexcept {
  note_allocation();
  if (alignment < sizeof(void*) || (alignment & (alignment - 1)) != 0) return EINVAL;
  void* p = __libc_memalign(alignment, size);
  if (!p) return ENOMEM;
  *out = p;
  return 0;
}
CYC_TEST_EXPORT void* valloc(std::size_t size) noexcept {
  note_allocation();
  return __libc_valloc(size);
}
CYC_TEST_EXPORT void* pvalloc(std::size_t size) noexcept {
  note_allocation();
  return __libc_pvalloc(size);
}
}  // extern "C"

// Every replaceable global allocation function.
CYC_TEST_EXPORT void* operator new(std::size_t size) { return new_or_throw(size); }
CYC_TEST_EXPORT void* operator new[](std::size_t size) { return new_or_throw(size); }
CYC_TEST_EXPORT void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  note_allocation();
  return __libc_malloc(size ? size : 1);
}
CYC_TEST_EXPORT void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  note_allocation();
  return __libc_malloc(size ? size : 1);
}
CYC_TEST_EXPORT void* operator new(std::size_t size, std::align_val_t a) {
  return new_aligned_or_throw(size, a);
}
CYC_TEST_EXPORT void* operator new[](std::size_t size, std::align_val_t a) {
  return new_aligned_or_throw(size, a);
}
CYC_TEST_EXPORT void* operator new(std::size_t size, std::align_val_t a,
                                   const std::nothrow_t&) noexcept {
  note_allocation();
  return aligned_or_null(static_cast<std::size_t>(a), size);
}
CYC_TEST_EXPORT void* operator new[](std::size_t size, std::align_val_t a,
                                     const std::nothrow_t&) noexcept {
  note_allocation();
  return aligned_or_null(static_cast<std::size_t>(a), size);
}
CYC_TEST_EXPORT void operator delete(void* p) noexcept { delete_any(p); }
CYC_TEST_EXPORT void operator delete[](void* p) noexcept { delete_any(p); }
CYC_TEST_EXPORT void operator delete(void* p, std::size_t) noexcept { delete_any(p); }
CYC_TEST_EXPORT void operator delete[](void* p, std::size_t) noexcept { delete_any(p); }
CYC_TEST_EXPORT void operator delete(void* p, const std::nothrow_t&) noexcept { delete_any(p); }
CYC_TEST_EXPORT void operator delete[](void* p, const std::nothrow_t&) noexcept { delete_any(p); }
CYC_TEST_EXPORT void operator delete(void* p, std::align_val_t) noexcept { delete_any(p); }
CYC_TEST_EXPORT void operator delete[](void* p, std::align_val_t) noexcept { delete_any(p); }
CYC_TEST_EXPORT void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
  delete_any(p);
}
CYC_TEST_EXPORT void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
  delete_any(p);
}
CYC_TEST_EXPORT void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept {
  delete_any(p);
}
CYC_TEST_EXPORT void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept {
  delete_any(p);
}

namespace {

// Keeps allocations observable so that the compiler cannot elide them.
void* volatile g_sink = nullptr;

// ------------------------------------------------------------ positive controls

TEST(AllocCounter, CountsStdVector) {
  const Heap h = measure([] {
    std::vector<double> v(64, 1.0);
    g_sink = v.data();
  });
  EXPECT_GE(h.allocations, 1);
  EXPECT_GE(h.frees, 1);
}

TEST(AllocCounter, CountsEveryReplacedFunction) {
  using Fn = void (*)();
  const Fn cases[] = {
      [] { delete static_cast<int*>(g_sink = new int(1)); },
      [] { delete[] static_cast<int*>(g_sink = new int[8]); },
      [] { ::operator delete(g_sink = ::operator new(16, std::nothrow)); },
      [] { ::operator delete[](g_sink = ::operator new[](16, std::nothrow)); },
      [] {
        ::operator delete(g_sink = ::operator new(16, std::align_val_t(64)), std::align_val_t(64));
      },
      [] {
        ::operator delete[](g_sink = ::operator new[](16, std::align_val_t(64)),
                            std::align_val_t(64));
      },
      [] {
        ::operator delete(g_sink = ::operator new(16, std::align_val_t(64), std::nothrow),
                          std::align_val_t(64));
      },
      [] { std::free(g_sink = std::malloc(16)); },
      [] { std::free(g_sink = std::calloc(4, 4)); },
      [] { std::free(g_sink = std::realloc(nullptr, 16)); },
      [] { std::free(g_sink = std::aligned_alloc(64, 64)); },
      [] {
        void* p = nullptr;
        if (posix_memalign(&p, 64, 64) == 0) std::free(g_sink = p);
      },
  };
  int i = 0;
  for (Fn f : cases) {
    const Heap h = measure(f);
    EXPECT_EQ(h.allocations, 1) << "case " << i;
    EXPECT_EQ(h.frees, 1) << "case " << i;
    ++i;
  }
  // Disarmed: nothing is counted.
  g_allocations.store(0);
  g_sink = std::malloc(8);
  std::free(g_sink);
  EXPECT_EQ(g_allocations.load(), 0);
}

// The library's own calls to the heap are interposed too: creating a handle
// on a default-allocator context allocates inside libcyclide.so.
TEST(AllocCounter, SeesAllocationsInsideLibcyclide) {
  cyc_context* ctx = nullptr;
  ASSERT_EQ(cyc_context_create(nullptr, &ctx), CYC_OK);
  const double P[3] = {1, 2, 3};
  cyc_curve* c = nullptr;
  int status = -1;
  Heap h = measure([&] { status = cyc_curve_create_point(ctx, P, &c); });
  EXPECT_EQ(status, CYC_OK);
  EXPECT_GE(h.allocations, 1);
  h = measure([&] { cyc_curve_destroy(ctx, c); });
  EXPECT_GE(h.frees, 1);
  h = measure([&] { cyc_context_destroy(ctx); });
  EXPECT_GE(h.frees, 1);
}

// ------------------------------------------------------------ fixtures

bool finite(const double* a, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(a[i])) return false;
  return true;
}

cyc_buffer3 buffer(std::vector<double>& v, std::size_t stride = 3) {
  cyc_buffer3 b;
  b.data = v.data();
  b.stride = stride;
  b.capacity = v.size() / stride;
  return b;
}

// Example 2 (PRCS of (u,0,0), (2u,u,1)) and Example 3 (PRRS of (u,0,0),
// (0,0,1), (1,2,1)) of seed 000 on [-1, 1]; everything the measured calls
// need is allocated here, outside the measured regions.
class AllocFree : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_EQ(cyc_context_create(nullptr, &ctx), CYC_OK);
    const double c1[6] = {0, 0, 0, 1, 0, 0}, c2[6] = {0, 0, 1, 2, 1, 0};
    const double P2[3] = {0, 0, 1}, P3[3] = {1, 2, 1};
    ASSERT_EQ(cyc_curve_create_polynomial(ctx, 1, c1, 3, &line), CYC_OK);
    ASSERT_EQ(cyc_curve_create_polynomial(ctx, 1, c2, 3, &p2), CYC_OK);
    ASSERT_EQ(cyc_curve_create_point(ctx, P2, &q2), CYC_OK);
    ASSERT_EQ(cyc_curve_create_point(ctx, P3, &q3), CYC_OK);
    ASSERT_EQ(cyc_prcs_create(ctx, line, p2, nullptr, -1, 1, &prcs), CYC_OK);
    ASSERT_EQ(cyc_prrs_create(ctx, line, q2, q3, nullptr, -1, 1, &prrs), CYC_OK);
    for (std::size_t i = 0; i < kGrid; ++i) {
      us[i] = -1.0 + 2.0 * double(i) / double(kGrid - 1);
      vs[i] = -8.0 + 16.0 * double(i) / double(kGrid - 1) + 0.0123;
    }
    for (std::size_t k = 0; k < kBatch; ++k) {
      uv[2 * k] = -0.95 + 1.9 * double(k) / double(kBatch - 1);
      uv[2 * k + 1] = std::tan(0.37 * double(k)) + 0.25;
    }
    points.assign(3 * kGrid * kGrid, 0.0);
    du.assign(3 * kGrid * kGrid, 0.0);
    dv.assign(3 * kGrid * kGrid, 0.0);
    normals.assign(4 * kGrid * kGrid, 0.0);  // stride 4
  }
  void TearDown() override {
    cyc_surface_destroy(ctx, prcs);
    cyc_surface_destroy(ctx, prrs);
    cyc_curve_destroy(ctx, line);
    cyc_curve_destroy(ctx, p2);
    cyc_curve_destroy(ctx, q2);
    cyc_curve_destroy(ctx, q3);
    cyc_context_destroy(ctx);
  }

  static constexpr std::size_t kGrid = 64;
  static constexpr std::size_t kBatch = 256;
  static constexpr int kRepeat = 50;

  cyc_context* ctx = nullptr;
  cyc_curve* line = nullptr;
  cyc_curve* p2 = nullptr;
  cyc_curve* q2 = nullptr;
  cyc_curve* q3 = nullptr;
  cyc_surface* prcs = nullptr;
  cyc_surface* prrs = nullptr;
  double us[kGrid] = {};
  double vs[kGrid] = {};
  double uv[2 * kBatch] = {};
  std::vector<double> points, du, dv, normals;
};

TEST_F(AllocFree, SurfaceEvalPointOnly) {
  for (cyc_surface* S : {prcs, prrs}) {
    SCOPED_TRACE(S == prcs ? "PRCS" : "PRRS");
    double x[3] = {0, 0, 0};
    int status = -1, bad = 0;
    Heap h =
        measure([&] { status = cyc_surface_eval(ctx, S, 0.3, 0.7, x, nullptr, nullptr, nullptr); });
    EXPECT_EQ(status, CYC_OK);
    EXPECT_TRUE(finite(x, 3));
    EXPECT_EQ(h.allocations, 0);
    EXPECT_EQ(h.frees, 0);
    h = measure([&] {
      for (int r = 0; r < kRepeat; ++r)
        bad += cyc_surface_eval(ctx, S, -0.9 + 0.03 * r, 0.5 * r - 7, x, nullptr, nullptr,
                                nullptr) != CYC_OK;
    });
    EXPECT_EQ(bad, 0);
    EXPECT_EQ(h.allocations, 0);
    EXPECT_EQ(h.frees, 0);
  }
}

TEST_F(AllocFree, SurfaceEvalPointDerivativesNormal) {
  for (cyc_surface* S : {prcs, prrs}) {
    SCOPED_TRACE(S == prcs ? "PRCS" : "PRRS");
    double x[3], xu[3], xv[3], n[3];
    int status = -1, bad = 0;
    Heap h = measure([&] { status = cyc_surface_eval(ctx, S, 0.3, 0.7, x, xu, xv, n); });
    EXPECT_EQ(status, CYC_OK);
    EXPECT_TRUE(finite(x, 3) && finite(xu, 3) && finite(xv, 3) && finite(n, 3));
    EXPECT_EQ(h.allocations, 0);
    EXPECT_EQ(h.frees, 0);
    h = measure([&] {
      for (int r = 0; r < kRepeat; ++r)
        bad += cyc_surface_eval(ctx, S, -0.9 + 0.03 * r, 0.5 * r - 7.1, x, xu, xv, n) != CYC_OK;
    });
    EXPECT_EQ(bad, 0);
    EXPECT_EQ(h.allocations, 0);
    EXPECT_EQ(h.frees, 0);
  }
}

TEST_F(AllocFree, SurfaceEvalBatch) {
  for (cyc_surface* S : {prcs, prrs}) {
    SCOPED_TRACE(S == prcs ? "PRCS" : "PRRS");
    int status = -1;
    std::size_t singular = 99;
    const cyc_buffer3 P = buffer(points), DU = buffer(du), DV = buffer(dv), N = buffer(normals, 4);
    Heap h = measure(
        [&] { status = cyc_surface_eval_batch(ctx, S, uv, 2, kBatch, P, DU, DV, N, &singular); });
    EXPECT_EQ(status, CYC_OK);
    EXPECT_TRUE(finite(points.data(), 3 * kBatch));
    EXPECT_LT(singular, kBatch);
    EXPECT_EQ(h.allocations, 0);
    EXPECT_EQ(h.frees, 0);
    // Points only.
    const cyc_buffer3 none = {nullptr, 0, 3};
    h = measure([&] {
      status = cyc_surface_eval_batch(ctx, S, uv, 2, kBatch, P, none, none, none, nullptr);
    });
    EXPECT_EQ(status, CYC_OK);
    EXPECT_EQ(h.allocations, 0);
    EXPECT_EQ(h.frees, 0);
  }
}

TEST_F(AllocFree, SurfaceEvalGrid64x64) {
  for (cyc_surface* S : {prcs, prrs}) {
    SCOPED_TRACE(S == prcs ? "PRCS" : "PRRS");
    int status = -1;
    std::size_t singular = 99;
    const cyc_buffer3 P = buffer(points), DU = buffer(du), DV = buffer(dv), N = buffer(normals, 4);
    Heap h = measure([&] {
      status = cyc_surface_eval_grid(ctx, S, us, kGrid, vs, kGrid, P, DU, DV, N, &singular);
    });
    EXPECT_EQ(status, CYC_OK);
    EXPECT_TRUE(finite(points.data(), points.size()));
    EXPECT_TRUE(finite(du.data(), du.size()));
    EXPECT_TRUE(finite(dv.data(), dv.size()));
    EXPECT_TRUE(finite(normals.data(), normals.size()));
    EXPECT_LT(singular, kGrid * kGrid);
    EXPECT_EQ(h.allocations, 0);
    EXPECT_EQ(h.frees, 0);
    const cyc_buffer3 none = {nullptr, 0, 3};
    h = measure([&] {
      status = cyc_surface_eval_grid(ctx, S, us, kGrid, vs, kGrid, P, none, none, none, nullptr);
    });
    EXPECT_EQ(status, CYC_OK);
    EXPECT_EQ(h.allocations, 0);
    EXPECT_EQ(h.frees, 0);
  }
}

TEST_F(AllocFree, SurfaceCircle) {
  for (cyc_surface* S : {prcs, prrs}) {
    SCOPED_TRACE(S == prcs ? "PRCS" : "PRRS");
    cyc_circle c;
    int bad = 0;
    const Heap h = measure([&] {
      for (int r = 0; r < kRepeat; ++r)
        bad += cyc_surface_circle(ctx, S, -0.98 + 0.04 * r, &c) != CYC_OK;
    });
    EXPECT_EQ(bad, 0);
    EXPECT_TRUE(finite(c.center, 3) && finite(c.normal, 3) && std::isfinite(c.radius2));
    EXPECT_EQ(h.allocations, 0);
    EXPECT_EQ(h.frees, 0);
  }
}

TEST_F(AllocFree, SurfaceSphere) {
  cyc_sphere s;
  int bad = 0;
  const Heap h = measure([&] {
    for (int r = 0; r < kRepeat; ++r)
      bad += cyc_surface_sphere(ctx, prcs, -0.98 + 0.04 * r, &s) != CYC_OK;
  });
  EXPECT_EQ(bad, 0);
  EXPECT_TRUE(finite(s.center, 3) && std::isfinite(s.radius2));
  EXPECT_EQ(h.allocations, 0);
  EXPECT_EQ(h.frees, 0);
}

TEST_F(AllocFree, SurfaceRingedData) {
  for (cyc_surface* S : {prcs, prrs}) {
    SCOPED_TRACE(S == prcs ? "PRCS" : "PRRS");
    double c[3], n[3], rho2 = 0, rr = 0;
    int bad = 0;
    const Heap h = measure([&] {
      for (int r = 0; r < kRepeat; ++r)
        bad += cyc_surface_ringed_data(ctx, S, -0.98 + 0.04 * r, c, n, &rho2, &rr) != CYC_OK;
    });
    EXPECT_EQ(bad, 0);
    EXPECT_TRUE(finite(c, 3) && finite(n, 3) && std::isfinite(rho2) && std::isfinite(rr));
    EXPECT_EQ(h.allocations, 0);
    EXPECT_EQ(h.frees, 0);
  }
}

TEST_F(AllocFree, CurveEval) {
  for (cyc_curve* C : {line, p2, q2}) {
    double out[27];
    int bad = 0;
    const Heap h = measure([&] {
      for (int r = 0; r < kRepeat; ++r)
        bad += cyc_curve_eval(ctx, C, -1.0 + 0.04 * r, r % 9, out, 27) != CYC_OK;
    });
    EXPECT_EQ(bad, 0);
    EXPECT_TRUE(finite(out, 3));
    EXPECT_EQ(h.allocations, 0);
    EXPECT_EQ(h.frees, 0);
  }
}

TEST_F(AllocFree, SurfaceRingedSphere) {
  for (cyc_surface* S : {prcs, prrs}) {
    SCOPED_TRACE(S == prcs ? "PRCS" : "PRRS");
    cyc_sphere sp;
    int bad = 0;
    const Heap h = measure([&] {
      for (int r = 0; r < kRepeat; ++r)
        bad += cyc_surface_ringed_sphere(ctx, S, -0.97 + 0.04 * r, &sp) != CYC_OK;
    });
    EXPECT_EQ(bad, 0);
    EXPECT_TRUE(finite(sp.center, 3) && std::isfinite(sp.radius2));
    EXPECT_EQ(h.allocations, 0);
    EXPECT_EQ(h.frees, 0);
  }
}

TEST_F(AllocFree, SurfaceCanalTest) {
  for (cyc_surface* S : {prcs, prrs}) {
    SCOPED_TRACE(S == prcs ? "PRCS" : "PRRS");
    double res = -1;
    int is_canal = -1, status = -1;
    const Heap h = measure([&] { status = cyc_surface_canal_test(ctx, S, 0.0, &res, &is_canal); });
    EXPECT_EQ(status, CYC_OK);
    EXPECT_TRUE(std::isfinite(res));
    EXPECT_EQ(h.allocations, 0);
    EXPECT_EQ(h.frees, 0);
  }
}

TEST_F(AllocFree, SurfaceParameterOf) {
  for (cyc_surface* S : {prcs, prrs}) {
    SCOPED_TRACE(S == prcs ? "PRCS" : "PRRS");
    const double X[3] = {0.5, 0.25, 1.0};
    double v = 0;
    int bad = 0;
    const Heap h = measure([&] {
      for (int r = 0; r < kRepeat; ++r)
        bad += cyc_surface_parameter_of(ctx, S, -0.97 + 0.04 * r, X, &v) != CYC_OK;
    });
    EXPECT_EQ(bad, 0);
    EXPECT_FALSE(std::isnan(v));
    EXPECT_EQ(h.allocations, 0);
    EXPECT_EQ(h.frees, 0);
  }
}

TEST_F(AllocFree, KindDomainAndLastError) {
  for (cyc_surface* S : {prcs, prrs}) {
    int kind = 0, bad = 0;
    double u0 = 0, u1 = 0;
    const Heap h = measure([&] {
      bad += cyc_surface_kind(ctx, S, &kind) != CYC_OK;
      bad += cyc_surface_domain(ctx, S, &u0, &u1) != CYC_OK;
      bad += cyc_context_last_status(ctx) != CYC_OK;
      bad += cyc_context_last_error(ctx)[0] != '\0';
    });
    EXPECT_EQ(bad, 0);
    EXPECT_EQ(h.allocations, 0);
    EXPECT_EQ(h.frees, 0);
  }
}

// SPEC.md section 2: "reporting an error never allocates" (a fixed message
// buffer in the context), also with an error handler installed.
int g_handler_calls = 0;
void count_errors(int, const char*, void*) { ++g_handler_calls; }

TEST_F(AllocFree, ErrorsAreReportedWithoutAllocating) {
  ASSERT_EQ(cyc_context_set_error_handler(ctx, count_errors, nullptr), CYC_OK);
  g_handler_calls = 0;
  const double nan = std::nan("");
  double x[3], n[3], out[27];
  cyc_sphere sp;
  std::size_t singular = 0;
  const cyc_buffer3 small = {points.data(), kBatch - 1, 3};
  const cyc_buffer3 none = {nullptr, 0, 3};
  const double P2[3] = {0, 0, 1};
  double v2 = 0;
  ASSERT_EQ(cyc_surface_parameter_of(ctx, prrs, 0.5, P2, &v2), CYC_OK);
  int wrong = 0;
  const Heap h = measure([&] {
    wrong +=
        cyc_surface_eval(ctx, prcs, nan, 0.5, x, nullptr, nullptr, nullptr) != CYC_E_NOT_FINITE;
    wrong += cyc_surface_eval(ctx, prrs, 0.5, v2, x, nullptr, nullptr, n) != CYC_E_SINGULAR_POINT;
    wrong += cyc_surface_eval_batch(ctx, prcs, uv, 2, kBatch, small, none, none, none, &singular) !=
             CYC_E_BUFFER_TOO_SMALL;
    wrong += cyc_surface_eval_grid(ctx, prcs, us, kGrid, vs, kGrid, small, none, none, none,
                                   &singular) != CYC_E_BUFFER_TOO_SMALL;
    wrong += cyc_surface_sphere(ctx, prrs, 0.5, &sp) != CYC_E_NOT_CANAL;
    wrong += cyc_surface_circle(ctx, prcs, nan, nullptr) != CYC_E_NULL_ARGUMENT;
    wrong += cyc_curve_eval(ctx, line, 0.5, 8, out, 3) != CYC_E_BUFFER_TOO_SMALL;
    wrong += cyc_curve_eval(ctx, line, nan, 1, out, 27) != CYC_E_NOT_FINITE;
    wrong += cyc_context_last_error(ctx)[0] == '\0';
  });
  EXPECT_EQ(wrong, 0);
  EXPECT_EQ(g_handler_calls, 8);
  EXPECT_EQ(h.allocations, 0);
  EXPECT_EQ(h.frees, 0);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}

// Darboux cyclides, inversion and DCMC (seed 000 §5-6) are allocation-free
// too: the DCMC solve uses fixed-size Eigen matrices on the stack.
TEST_F(AllocFree, DarbouxInversionAndDcmc) {
  const cyc_line lines[3] = {{{0, 0, 0}, {1, 0, 0}}, {{0, 0, 1}, {0, 1, 0}}, {{0, 0, 2}, {1, 1, 0}}};
  const cyc_inversion inv = {{0.3, 0.9, -0.4}, 1.3};
  const cyc_general_sphere sphere = {1, {0, 0, 0}, -1};
  const cyc_circle_or_line circle = {0, {0, 0, 0}, {0, 0, 1}, 1.0};
  cyc_darboux base, quadric, img;
  cyc_general_sphere s2;
  cyc_circle_or_line c2;
  double n[3], value = 0, grad[3], x[3] = {0.5, -0.25, 1.0}, y[3], p[3], pu[3], pv[3], pn[3];
  int type = -1, bad = 0;
  double gu[2] = {0.1, 0.2}, gv[100], gpts[600], gnrm[600], derivs[12];
  const double cv[4] = {-1, 0, 0.5, 3};
  cyc_continuity cont;
  for (int j = 0; j < 100; ++j) gv[j] = 0.05 * j - 2.5;
  const cyc_buffer3 gp = {gpts, 200, 3}, gn = {gnrm, 200, 3};
  const Heap h = measure([&] {
    for (int r = 0; r < kRepeat; ++r) {
      bad += cyc_dcmc(ctx, lines, n, &base, &quadric) != CYC_OK;
      bad += cyc_darboux_eval(ctx, &base, x, &value, grad) != CYC_OK;
      bad += cyc_darboux_classify(ctx, &base, &type) != CYC_OK;
      bad += cyc_invert_darboux(ctx, &inv, &base, &img) != CYC_OK;
      bad += cyc_invert_point(ctx, &inv, x, y) != CYC_OK;
      bad += cyc_invert_sphere(ctx, &inv, &sphere, &s2) != CYC_OK;
      bad += cyc_invert_circle(ctx, &inv, &circle, &c2) != CYC_OK;
      bad += cyc_surface_eval_inverted(ctx, prcs, &inv, 0.3, 0.1 * r, p, pu, pv, pn) != CYC_OK;
      bad += cyc_surface_circle_inverted(ctx, prcs, &inv, 0.3, &c2) != CYC_OK;
      // Blends (issue 4): end-circle derivatives and the continuity report.
      bad += cyc_surface_derivatives_u(ctx, prcs, 0.3, 0.1 * r, 3, derivs) != CYC_OK;
      bad += cyc_continuity_report(ctx, prcs, 0.3, 1.0, prcs, 0.3, 2, cv, 4, &cont) != CYC_OK;
      bad += cyc_surface_eval_grid_inverted(ctx, prcs, &inv, gu, 2, gv, 100, gp, {}, {}, gn,
                                            nullptr) != CYC_OK;
    }
  });
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(type, CYC_DARBOUX_PARABOLIC);
  EXPECT_EQ(h.allocations, 0);
  EXPECT_EQ(h.frees, 0);
}

// The line analysis of parabolic cyclides and §8 are allocation-free too.
TEST_F(AllocFree, ParabolicLinesSection8FitAndClassification) {
  const cyc_darboux c39 = {{0, 0, 0, 4, 0, -8, -3, -6, 0, 0, 0, 0, -1, 0}};
  const cyc_line ex5[3] = {{{0, 0, 0}, {1, 0, 0}}, {{0, 0, 0}, {2, 1, 0}}, {{1, 1, 1}, {-1, 2, 0}}};
  const cyc_line x_axis = {{0, 0, 0}, {1, 0, 0}};
  const double side[3] = {0, 0.6, 0.8};
  cyc_cyclide_lines A;
  cyc_circle_or_line c;
  cyc_prrs_lines_analysis P;
  cyc_darboux D;
  double residual = 1;
  cyc_darboux_fit fit;
  cyc_lines_classification cl;
  int bad = 0;
  const Heap h = measure([&] {
    for (int r = 0; r < kRepeat; ++r) {
      bad += cyc_parabolic_lines(ctx, &c39, &A) != CYC_OK;
      bad += cyc_pencil_circle(ctx, &c39, &x_axis, side, &c) != CYC_OK;
      bad += cyc_prrs_lines_analyze(ctx, ex5, &P) != CYC_OK;
      bad += cyc_prrs_lines_cyclide(ctx, ex5, &D, &residual) != CYC_OK;
      bad += cyc_darboux_fit_surface(ctx, prcs, &fit) != CYC_OK;
      bad += cyc_classify_two_lines(ctx, &x_axis, &ex5[2], &cl) != CYC_OK;
      bad += cyc_classify_line_element(ctx, &x_axis, ex5[2].point, side, &cl, &D) != CYC_OK;
      bad += cyc_classify_line_two_points(ctx, &x_axis, ex5[2].point, side, &cl) != CYC_OK;
    }
  });
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(A.line_count, 5);
  EXPECT_EQ(h.allocations, 0);
  EXPECT_EQ(h.frees, 0);
}

// The core functions behind cyc_darboux_fit_* and cyc_classify_* (issue 3 items 6, 7): the fit (fixed
// 64x14 QR and 14x14 SVD) and the closed-form classification.
TEST(AllocFreeCore, ImplicitizeAndClassify) {
  using namespace cyclide;
  RationalCurve l1, l2;
  ASSERT_EQ(make_line({0, 0, 0}, {1, 0, 0}, l1), Status::ok);
  ASSERT_EQ(make_line({0, 0, 1}, {2, 1, 0}, l2), Status::ok);
  Surface S;
  ASSERT_EQ(make_prcs(l1, l2, nullptr, -0.5, 0.5, S), Status::ok);
  Vec3d X[32];
  for (int i = 0; i < 32; ++i) X[i] = Vec3d(std::cos(0.4 * i), std::sin(0.4 * i), 0.1 * i);
  DarbouxFit F, G;
  LinesClassification C;
  Darboux N, D;
  Vec3d s;
  double r2 = 0;
  int bad = 0;
  const Heap h = measure([&] {
    for (int r = 0; r < 3; ++r) {
      bad += fit_darboux(S, F) != Status::ok;
      bad += fit_darboux(X, 32, G) != Status::ok;
      bad += classify_two_lines({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {2, 1, 0}, C) != Status::ok;
      bad += two_lines_sphere(C.nf, 0.3, s, r2) != Status::ok;
      bad += classify_line_two_points({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {1, 2, 1}, C) != Status::ok;
      bad += classify_line_element({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0.3, 1, 0.7}, C) != Status::ok;
      bad += line_element_cyclide(C.nf, N, D) != Status::ok;
    }
  });
  EXPECT_EQ(bad, 0);
  EXPECT_TRUE(F.is_darboux);
  EXPECT_EQ(h.allocations, 0);
  EXPECT_EQ(h.frees, 0);
}

// Seed 002's sphere skins in the core (issue 6): construction (the RMF
// table with error control), evaluation with partials and normals, grids,
// the twist measure and chains allocate nothing.
TEST(AllocFreeCore, SphereSkin) {
  using namespace cyclide;
  SkinEnd ends[3];
  ASSERT_EQ(skin_end_from_sphere({0, 0, 0}, 1.0, {0.3, 0, 0}, {3, 0, 0}, ends[0]), Status::ok);
  const Vec3d ax = Vec3d(1, 0.5, 0.3).normalized();
  ASSERT_EQ(skin_end_from_sphere({4, 1, 0}, 0.8, Vec3d(4, 1, 0) - 0.1 * ax, 3.0 * ax, ends[1]),
            Status::ok);
  ASSERT_EQ(skin_end_from_sphere({7, 3, 1}, 1.1, {7, 3, 1}, {3, 1, 1}, ends[2]), Status::ok);
  static SphereSkin S, chain[2];
  static double theta[16], t[16], X[3 * 256], N[3 * 256];
  for (int i = 0; i < 16; ++i) theta[i] = 0.4 * i - 3, t[i] = i / 15.0;
  int bad = 0;
  double twist = 0;
  const Heap h = measure([&] {
    for (RmfMethod m : {RmfMethod::reference, RmfMethod::double_reflection}) {
      SkinOptions o;
      o.method = m;
      bad += make_sphere_skin(ends[0], ends[1], o, S) != Status::ok;
      double x[3], a[3], b[3], n[3];
      bad += skin_eval(S, 0.7, 0.4, x, a, b, n) != Status::ok;
      bad += skin_eval_grid(S, theta, 16, t, 16, X, N) != Status::ok;
      bad += skin_twist(S, 1.0, twist) != Status::ok;
      bad += make_sphere_skin_chain(ends, 3, o, chain) != Status::ok;
    }
  });
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(h.allocations, 0);
  EXPECT_EQ(h.frees, 0);
}

// Issue 9: the export of a sphere skin chain (skin_export.hpp: the frame's
// interpolation matrix is a fixed-capacity Eigen matrix) allocates nothing.
TEST(AllocFreeCore, SkinExport) {
  using namespace cyclide;
  SkinEnd ends[3];
  ASSERT_EQ(skin_end_from_sphere({0, 0, 0}, 1.0, {0.3, 0, 0}, {3, 0, 0}, ends[0]), Status::ok);
  const Vec3d ax = Vec3d(1, 0.5, 0.3).normalized();
  ASSERT_EQ(skin_end_from_sphere({4, 1, 0}, 0.8, Vec3d(4, 1, 0) - 0.1 * ax, 3.0 * ax, ends[1]),
            Status::ok);
  ASSERT_EQ(skin_end_from_sphere({7, 3, 1}, 1.1, {7, 3, 1}, {3, 1, 1}, ends[2]), Status::ok);
  static SphereSkin chain[2];
  ASSERT_EQ(make_sphere_skin_chain(ends, 3, SkinOptions{}, chain), Status::ok);
  static RationalBezierPatch P[256];
  int count = 0, bad = 0;
  SkinExportReport r;
  const Heap h = measure([&] {
    bad += export_sphere_skin(chain, 2, ExportDomain::circles(0, 2), SkinExportOptions{}, P, 256,
                              count, &r) != Status::ok;
    bad += export_sphere_skin(chain, 2, ExportDomain::rectangle(0.5, 1.5, -2, 3),
                              SkinExportOptions{}, P, 256, count, &r) != Status::ok;
  });
  EXPECT_EQ(bad, 0);
  EXPECT_GT(count, 0);
  EXPECT_EQ(h.allocations, 0);
  EXPECT_EQ(h.frees, 0);
}

// Seed 002's sphere skins: creation allocates (the handle), evaluation,
// grids, twist, lambda and info do not, nor do their errors.
TEST(AllocFreeSkin, EvalGridTwistLambdaInfo) {
  cyc_context* ctx = nullptr;
  ASSERT_EQ(cyc_context_create(nullptr, &ctx), CYC_OK);
  cyc_skin_end ends[3];
  const double m0[3] = {0, 0, 0}, p0[3] = {0.3, 0, 0}, t0[3] = {3, 0, 0};
  const double m1[3] = {4, 1, 0.5}, p1[3] = {3.7, 1, 0.5}, t1[3] = {3, 0, 0};
  const double m2[3] = {8, 2, 0}, p2[3] = {7.7, 2, 0}, t2[3] = {3, 0, 0};
  ASSERT_EQ(cyc_skin_end_from_sphere(ctx, m0, 1.0, p0, t0, &ends[0]), CYC_OK);
  ASSERT_EQ(cyc_skin_end_from_sphere(ctx, m1, 1.2, p1, t1, &ends[1]), CYC_OK);
  ASSERT_EQ(cyc_skin_end_from_sphere(ctx, m2, 0.9, p2, t2, &ends[2]), CYC_OK);
  cyc_sphere_skin* h = nullptr;
  ASSERT_EQ(cyc_sphere_skin_chain_create(ctx, ends, 3, nullptr, &h, nullptr), CYC_OK)
      << cyc_context_last_error(ctx);
  double th[16], ts[16];
  for (int i = 0; i < 16; ++i) th[i] = -3 + 0.4 * i, ts[i] = i / 15.0;
  std::vector<double> P(3 * 256), N(3 * 256);
  double x[3], xa[3], xb[3], n[3], tw = 0, lam = 0, a[2];
  cyc_sphere_skin_info I;
  cyc_skin_end e;
  int bad = 0, count = 0;
  const Heap heap = measure([&] {
    for (int r = 0; r < 3; ++r) {
      bad += cyc_sphere_skin_eval(ctx, h, r % 2, th[r], ts[r + 3], x, xa, xb, n) != CYC_OK;
      bad += cyc_sphere_skin_eval_grid(ctx, h, r % 2, th, 16, ts, 16, P.data(), N.data(), nullptr) != CYC_OK;
      bad += cyc_sphere_skin_twist(ctx, h, r % 2, th[r], &tw) != CYC_OK;
      bad += cyc_sphere_skin_lambda(ctx, h, r % 2, th[r], ts[r], &lam, a) != CYC_OK;
      bad += cyc_sphere_skin_info_get(ctx, h, r % 2, &I) != CYC_OK;
      bad += cyc_sphere_skin_patch_count(ctx, h, &count) != CYC_OK;
      bad += cyc_skin_end_from_sphere(ctx, m0, 1.0, p0, t0, &e) != CYC_OK;
      bad += cyc_sphere_skin_eval(ctx, h, 2, 0, 0, x, xa, xb, n) != CYC_E_INVALID_ARGUMENT;
      bad += cyc_sphere_skin_eval(ctx, h, 0, 0, 2, x, xa, xb, n) != CYC_E_BAD_DOMAIN;
    }
  });
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(count, 2);
  EXPECT_EQ(heap.allocations, 0);
  EXPECT_EQ(heap.frees, 0);
  cyc_sphere_skin_destroy(ctx, h);
  cyc_context_destroy(ctx);
}

// Issue 9: the tessellation of a skin chain's patches (plan with the
// caller's scratch, mesh into the caller's buffers) and its errors allocate
// nothing.
TEST(AllocFreeSkin, Tessellation) {
  cyc_context* ctx = nullptr;
  ASSERT_EQ(cyc_context_create(nullptr, &ctx), CYC_OK);
  cyc_skin_end ends[3];
  const double m0[3] = {0, 0, 0}, p0[3] = {0.3, 0, 0}, t0[3] = {3, 0, 0};
  const double m1[3] = {4, 1, 0.5}, p1[3] = {3.7, 1, 0.5}, t1[3] = {3, 0, 0};
  const double m2[3] = {8, 2, 0}, p2[3] = {7.7, 2, 0}, t2[3] = {3, 0, 0};
  ASSERT_EQ(cyc_skin_end_from_sphere(ctx, m0, 1.0, p0, t0, &ends[0]), CYC_OK);
  ASSERT_EQ(cyc_skin_end_from_sphere(ctx, m1, 1.2, p1, t1, &ends[1]), CYC_OK);
  ASSERT_EQ(cyc_skin_end_from_sphere(ctx, m2, 0.9, p2, t2, &ends[2]), CYC_OK);
  cyc_sphere_skin* h = nullptr;
  ASSERT_EQ(cyc_sphere_skin_chain_create(ctx, ends, 3, nullptr, &h, nullptr), CYC_OK)
      << cyc_context_last_error(ctx);
  cyc_tessellation_options o;
  cyc_tessellation_options_default(&o);
  o.chordal_tolerance = 1e-3;
  std::vector<double> work(cyc_sphere_skin_tessellation_workspace_size(o.max_segments) /
                           sizeof(double));
  std::vector<double> ts(4096), pts(3 * 4096 * 256), nrm(3 * 4096 * 256);
  cyc_tessellation_plan plan{};
  size_t singular = 0;
  int bad = 0;
  const Heap heap = measure([&] {
    for (int patch = 0; patch < 2; ++patch) {
      bad += cyc_sphere_skin_tessellate_plan(ctx, h, patch, &o, ts.data(), 4096, work.data(),
                                             work.size() * sizeof(double), &plan) != CYC_OK;
      bad += cyc_sphere_skin_tessellate_eval(ctx, h, patch, &plan, ts.data(),
                                             cyc_buffer3{pts.data(), 4096 * 256, 3},
                                             cyc_buffer3{nrm.data(), 4096 * 256, 3},
                                             &singular) != CYC_OK;
    }
    bad += cyc_sphere_skin_tessellate_plan(ctx, h, 2, &o, ts.data(), 4096, work.data(),
                                           work.size() * sizeof(double),
                                           &plan) != CYC_E_INVALID_ARGUMENT;
    bad += cyc_sphere_skin_tessellate_plan(ctx, h, 0, &o, ts.data(), 2, work.data(),
                                           work.size() * sizeof(double),
                                           &plan) != CYC_E_BUFFER_TOO_SMALL;
    bad += cyc_sphere_skin_tessellate_eval(ctx, h, 0, &plan, ts.data(),
                                           cyc_buffer3{pts.data(), 1, 3},
                                           cyc_buffer3{nullptr, 0, 3},
                                           nullptr) != CYC_E_BUFFER_TOO_SMALL;
  });
  EXPECT_EQ(bad, 0);
  EXPECT_GT(plan.rows, 2);
  EXPECT_EQ(singular, 0u);
  EXPECT_EQ(heap.allocations, 0);
  EXPECT_EQ(heap.frees, 0);
  cyc_sphere_skin_destroy(ctx, h);
  cyc_context_destroy(ctx);
}

// Seed 003's Dupin cyclides: the core's dupin_eval and the C ABI's
// cyc_dupin_eval, cyc_dupin_eval_grid (validation of the value included)
// and their errors allocate nothing.
TEST(AllocFreeLie, DupinEvalAndGrid) {
  using namespace cyclide;
  const LieSphere s[3] = {oriented_sphere({3, 0, 0}, 1), oriented_sphere({0, 3, 0}, 1),
                          oriented_sphere({-3, 0, 0}, 1)};
  DupinCyclide D;
  ASSERT_EQ(dupin_from_spheres(s, D), Status::ok);
  cyc_context* ctx = nullptr;
  ASSERT_EQ(cyc_context_create(nullptr, &ctx), CYC_OK);
  cyc_lie_sphere c[3];
  for (int i = 0; i < 3; ++i) {
    c[i].kind = CYC_LIE_SPHERE;
    c[i].m[0] = s[i].m.x(), c[i].m[1] = s[i].m.y(), c[i].m[2] = s[i].m.z();
    c[i].rho = 1;
    c[i].n[0] = c[i].n[1] = c[i].n[2] = 0;
    c[i].lambda = 0;
  }
  cyc_dupin C;
  ASSERT_EQ(cyc_dupin_from_spheres(ctx, c, &C), CYC_OK);
  double xs[16], zs[16];
  for (int i = 0; i < 16; ++i) xs[i] = -4 + 0.5 * i, zs[i] = -3 + 0.4 * i;
  std::vector<double> P(3 * 256), N(3 * 256);
  cyc_dupin bad_value = C;
  bad_value.theta[3] += 0.5;
  int bad = 0;
  DupinPoint Q;
  cyc_dupin_point R;
  const Heap heap = measure([&] {
    for (int r = 0; r < 3; ++r) {
      bad += dupin_eval(D, xs[r], zs[r + 1], 0.1 * r, Q) != Status::ok;
      bad += cyc_dupin_eval(ctx, &C, xs[r], zs[r + 1], 0.1 * r, &R) != CYC_OK;
      bad += cyc_dupin_eval_grid(ctx, &C, xs, 16, zs, 16, 0.0, P.data(), N.data()) != CYC_OK;
      bad += cyc_dupin_eval(ctx, &bad_value, 0, 0, 0, &R) != CYC_E_INVALID_ARGUMENT;
      bad += cyc_dupin_eval_grid(ctx, &C, xs, 16, zs, 16, NAN, P.data(), nullptr) !=
             CYC_E_NOT_FINITE;
    }
  });
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(heap.allocations, 0);
  EXPECT_EQ(heap.frees, 0);
  cyc_context_destroy(ctx);
}

// Seed 003's Algorithm 2: cones, single and double blends (the automatic
// choice included), quality and continuity reports allocate nothing, in
// the core and through the C ABI (SPEC §2 tier table).
TEST(AllocFreeLie, CyclideBlends) {
  using namespace cyclide;
  cyc_context* ctx = nullptr;
  ASSERT_EQ(cyc_context_create(nullptr, &ctx), CYC_OK);
  const double c0[3] = {-3, 0, 0}, n0[3] = {1, 0, 0}, c1[3] = {4, 3, 1}, n1[3] = {-1, -0.2, 0.1};
  int bad = 0;
  cyc_lie_cone R, S;
  cyc_cyclide_blend B;
  cyc_cyclide_blend_report rep;
  double q = 0;
  LieCone Rc, Sc;
  CyclideBlend Bc;
  CyclideBlendContinuity Cc;
  const Heap heap = measure([&] {
    bad += cyc_cone_from_circle(ctx, c0, n0, 1, 0, 1, &R) != CYC_OK;
    bad += cyc_cone_from_circle(ctx, c1, n1, 0.8, 0.3, 1, &S) != CYC_OK;
    bad += cyc_cyclide_blend_auto(ctx, &R, &S, 16, &B, &q) != CYC_OK;
    bad += cyc_cyclide_blend_build(ctx, &R, &S, B.branch, B.alpha, &B) != CYC_OK;
    bad += cyc_cyclide_blend_quality(ctx, &B, &q) != CYC_OK;
    bad += cyc_cyclide_blend_continuity(ctx, &R, &S, &B, 8, &rep) != CYC_OK;
    bad += cyc_cyclide_blend_build(ctx, &R, &R, 1, 0.0, &B) != CYC_E_INVALID_ARGUMENT;
    bad += cone_from_circle({-3, 0, 0}, {1, 0, 0}, 1, 0, 1, Rc) != Status::ok;
    bad += cone_from_circle({4, 3, 1}, {-1, -0.2, 0.1}, 0.8, 0.3, 1, Sc) != Status::ok;
    bad += cyclide_blend_auto(Rc, Sc, Bc, 16, &q) != Status::ok;
    bad += cyclide_blend_continuity(Rc, Sc, Bc, 8, Cc) != Status::ok;
  });
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(heap.allocations, 0);
  EXPECT_EQ(heap.frees, 0);
  cyc_context_destroy(ctx);
}

// Seed 004 through the C ABI: Lambda / Lambda^{-1}, the parabolic cyclide's
// evaluators, cubic triangle / bicubic construction and evaluation, and the
// design with a caller workspace allocate nothing (SPEC §2 tier table).
TEST(AllocFreeLaguerre, EvaluatorsPatchesAndDesign) {
  cyc_context* ctx = nullptr;
  ASSERT_EQ(cyc_context_create(nullptr, &ctx), CYC_OK);
  // Design data: the lower cap of the ellipsoid (2, 1.5, 1), 6 x 6 normals.
  std::vector<cyc_oriented_point> data;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      const double y1 = -0.6 + 1.2 * (i + 0.5) / 6, y2 = -0.6 + 1.2 * (j + 0.5) / 6;
      const double N = 1 + y1 * y1 + y2 * y2;
      const double a[3] = {2 * y1 / N, 2 * y2 / N, (y1 * y1 + y2 * y2 - 1) / N};
      const double D[3] = {4, 2.25, 1};
      const double s = std::sqrt(D[0] * a[0] * a[0] + D[1] * a[1] * a[1] + D[2] * a[2] * a[2]);
      cyc_oriented_point A;
      for (int c = 0; c < 3; ++c) A.normal[c] = a[c], A.point[c] = D[c] * a[c] / s;
      data.push_back(A);
    }
  const int n = int(data.size());
  std::vector<unsigned char> work(cyc_design_workspace_size(n, 0));
  const int cap = cyc_design_max_patches(n, 0);
  std::vector<cyc_rational_cubic_triangle> patches(cap);
  std::vector<cyc_quadratic_graph_triangle> iso(cap);
  std::vector<unsigned char> dwork(cyc_delaunay_workspace_size(n));
  std::vector<int> tri(3 * cyc_delaunay_max_triangles(n));
  std::vector<double> pts(2 * n);
  for (int i = 0; i < 2 * n; ++i) pts[i] = std::sin(1.3 * i) + 0.1 * i;
  cyc_parabolic_cyclide c;
  std::memset(&c, 0, sizeof c);
  c.a = 1.5, c.b = -0.5;
  c.frame[0] = c.frame[4] = c.frame[8] = 1;
  const cyc_graph_quadratic q{{-1.0, 0.2, 0.5, 0.4, -0.2, 0.3}};
  cyc_quadratic_graph_triangle gt{{{-0.5, -0.4}, {0.7, -0.1}, {0.1, 0.8}}, {0.1, 0.2, 0.3, 0.1, 0.0, -0.2}};
  const double corner[2] = {-0.3, -0.2}, e1[2] = {0.6, 0.1}, e2[2] = {-0.1, 0.5};
  double control[16];
  for (int i = 0, k = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      control[k++] = 1, control[k++] = i - 0.5, control[k++] = j - 0.5, control[k++] = 0.3 + 0.1 * i;
  cyc_pn_surface* pn = nullptr;
  ASSERT_EQ(cyc_pn_surface_create(ctx, 1, 1, control, &pn), CYC_OK);
  double us[8], vs[8], gp[3 * 64], gn[3 * 64];
  for (int i = 0; i < 8; ++i) us[i] = vs[i] = i / 7.0;
  int bad = 0, np = 0, nt = 0;
  const Heap heap = measure([&] {
    for (int r = 0; r < 3; ++r) {
      cyc_pn_point pp;
      size_t failed = 0;
      bad += cyc_pn_surface_eval(ctx, pn, 0.3, 0.1 * r, 0.5, &pp) != CYC_OK;
      bad += cyc_pn_surface_eval_grid(ctx, pn, us, 8, vs, 8, 0.2, cyc_buffer3{gp, 64, 3},
                                      cyc_buffer3{gn, 64, 3}, &failed) != CYC_OK;
      bad += failed != 0;
      cyc_oriented_plane p{0.5 * r, {0.36, -0.48, 0.8}}, back;
      cyc_isotropic_point y;
      bad += cyc_laguerre_to_isotropic(ctx, &p, &y) != CYC_OK;
      bad += cyc_isotropic_to_laguerre(ctx, &y, &back) != CYC_OK;
      double x[3], nrm[3], F, uv[2];
      bad += cyc_parabolic_cyclide_eval(ctx, &c, 0.3 * r, -0.2, x, nrm) != CYC_OK;
      bad += cyc_parabolic_cyclide_implicit(ctx, &c, x, &F) != CYC_OK;
      bad += cyc_parabolic_cyclide_parameter_of(ctx, &c, x, uv) != CYC_OK;
      bad += cyc_parabolic_cyclide_eval(ctx, &c, NAN, 0, x, nrm) != CYC_E_NOT_FINITE;
      cyc_rational_cubic_triangle T;
      cyc_rational_bicubic_patch B;
      bad += cyc_cyclide_cubic_triangle(ctx, &gt, &T) != CYC_OK;
      bad += cyc_cubic_triangle_eval(ctx, &T, 0.2, 0.3, 0.5, x) != CYC_OK;
      bad += cyc_cyclide_bicubic_patch(ctx, &q, corner, e1, e2, &B) != CYC_OK;
      bad += cyc_bicubic_patch_eval(ctx, &B, 0.4, 0.7, x) != CYC_OK;
      bad += cyc_delaunay_triangulate(ctx, pts.data(), n, dwork.data(), dwork.size(), tri.data(),
                                      int(tri.size() / 3), &nt) != CYC_OK;
      bad += cyc_design_cyclide_surface(ctx, data.data(), n, nullptr, 0, nullptr, work.data(),
                                        work.size(), iso.data(), patches.data(), cap, &np,
                                        nullptr) != CYC_OK;
      bad += cyc_design_cyclide_surface(ctx, data.data(), n, nullptr, 0, nullptr, work.data(),
                                        work.size() - 1, iso.data(), patches.data(), cap, &np,
                                        nullptr) != CYC_E_BUFFER_TOO_SMALL;
    }
  });
  EXPECT_EQ(bad, 0);
  EXPECT_GT(np, 0);
  EXPECT_EQ(heap.allocations, 0);
  EXPECT_EQ(heap.frees, 0);
  cyc_pn_surface_destroy(pn);
  cyc_context_destroy(ctx);
}

// Issue 9: the tessellation (plan and mesh) and the queries of a Bezier
// export (its creation allocates, through the context) never allocate.
// Issue 10 item 4: a static context in a stack block (SPEC.md §9b):
// creating curves and a surface, evaluating, destroying -- no heap at all.
TEST(CallerMemory, NoHeapAtAll) {
  alignas(16) static unsigned char block[1 << 16];
  int bad = 0;
  const Heap h = measure([&] {
    cyc_context* ctx = nullptr;
    bad += cyc_context_init_static(block, sizeof block, nullptr, &ctx) != CYC_OK;
    const double O[3] = {0, 0, 0}, X[3] = {1, 0, 0}, P[3] = {0, 0, 1}, w[3] = {2, 1, 0};
    cyc_curve *l1 = nullptr, *l2 = nullptr;
    cyc_surface* s = nullptr;
    bad += cyc_curve_create_line(ctx, O, X, &l1) != CYC_OK;
    bad += cyc_curve_create_line(ctx, P, w, &l2) != CYC_OK;
    bad += cyc_prcs_create(ctx, l1, l2, nullptr, -0.5, 0.5, &s) != CYC_OK;
    double x[3], n[3];
    bad += cyc_surface_eval(ctx, s, 0.1, 0.2, x, nullptr, nullptr, n) != CYC_OK;
    cyc_surface_destroy(ctx, s);
    cyc_curve_destroy(ctx, l2);
    cyc_curve_destroy(ctx, l1);
    cyc_context_destroy(ctx);
  });
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(h.allocations, 0);
  EXPECT_EQ(h.frees, 0);
}

TEST(AllocFreeExport, TessellationAndPatchQueries) {
  cyc_context* ctx = nullptr;
  ASSERT_EQ(cyc_context_create(nullptr, &ctx), CYC_OK);
  const double O[3] = {0, 0, 0}, X[3] = {1, 0, 0}, P[3] = {0, 0, 1}, w[3] = {2, 1, 0};
  cyc_curve *l1 = nullptr, *l2 = nullptr;
  ASSERT_EQ(cyc_curve_create_line(ctx, O, X, &l1), CYC_OK);
  ASSERT_EQ(cyc_curve_create_line(ctx, P, w, &l2), CYC_OK);
  cyc_surface* s = nullptr;
  ASSERT_EQ(cyc_prcs_create(ctx, l1, l2, nullptr, -0.5, 0.5, &s), CYC_OK);
  const cyc_export_domain D{-0.5, 0.5, 0, 0, 1};
  cyc_bezier_export* e = nullptr;
  ASSERT_EQ(cyc_bezier_export_create(ctx, s, &D, &e), CYC_OK);
  cyc_tessellation_options o;
  cyc_tessellation_options_default(&o);
  o.chordal_tolerance = 1e-3;
  o.max_segments = 256;
  std::vector<unsigned char> work(cyc_tessellation_workspace_size(o.max_segments));
  std::vector<double> us(4096), pts(3 * 4096 * 256), nrm(3 * 4096 * 256);
  std::vector<double> control(4 * 64 * 3);
  int bad = 0;
  cyc_tessellation_plan plan{};
  const Heap heap = measure([&] {
    bad += cyc_tessellate_plan(ctx, s, &o, us.data(), 4096, work.data(), work.size(), &plan) !=
           CYC_OK;
    size_t singular = 0;
    bad += cyc_tessellate_eval(ctx, s, &plan, us.data(), cyc_buffer3{pts.data(), 4096 * 256, 3},
                                 cyc_buffer3{nrm.data(), 4096 * 256, 3}, &singular) != CYC_OK;
    for (int k = 0; k < cyc_bezier_export_count(e); ++k) {
      cyc_bezier_patch_info info;
      double x[3], uv[2];
      bad += cyc_bezier_export_patch(ctx, e, k, &info, control.data(), control.size()) != CYC_OK;
      bad += cyc_bezier_export_eval(ctx, e, k, 0.3, 0.6, x, uv) != CYC_OK;
    }
  });
  EXPECT_EQ(bad, 0);
  EXPECT_GT(plan.rows, 2);
  EXPECT_EQ(heap.allocations, 0);
  EXPECT_EQ(heap.frees, 0);
  cyc_bezier_export_destroy(e);
  cyc_surface_destroy(ctx, s);
  cyc_curve_destroy(ctx, l1);
  cyc_curve_destroy(ctx, l2);
  cyc_context_destroy(ctx);
}
