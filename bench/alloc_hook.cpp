// Allocation counting for the benchmarks: this translation unit replaces the
// global operator new/delete family and interposes the malloc family of the
// whole process (glibc: the executable's definitions win over libc's for
// every shared object, libcyclide.so included, and forward to __libc_*).
// Every allocation event bumps one relaxed atomic counter; frees are not
// counted. Read it with cyc_bench_alloc_count().
//
// Without glibc, or under a sanitizer (which owns malloc itself), nothing is
// replaced and cyc_bench_alloc_hooked() returns false: the benchmarks then
// omit the allocs_per_iter counter rather than report a false zero.
#include <atomic>
#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <new>

#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer) || \
    __has_feature(thread_sanitizer)
#define CYC_BENCH_NO_ALLOC_HOOK 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__) || !defined(__GLIBC__)
#ifndef CYC_BENCH_NO_ALLOC_HOOK
#define CYC_BENCH_NO_ALLOC_HOOK 1
#endif
#endif

#if defined(CYC_BENCH_NO_ALLOC_HOOK)

std::uint64_t cyc_bench_alloc_count() { return 0; }
bool cyc_bench_alloc_hooked() { return false; }

#else  // the glibc hook

#define CYC_BENCH_EXPORT extern "C" __attribute__((visibility("default")))

extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* __libc_memalign(std::size_t, std::size_t);
void* __libc_valloc(std::size_t);
void* __libc_pvalloc(std::size_t);
void __libc_free(void*);
}

namespace {
std::atomic<std::uint64_t> g_allocs{0};
inline void count() { g_allocs.fetch_add(1, std::memory_order_relaxed); }
}  // namespace

std::uint64_t cyc_bench_alloc_count() { return g_allocs.load(std::memory_order_relaxed); }
bool cyc_bench_alloc_hooked() { return true; }

// ------------------------------------------------------------ malloc family

CYC_BENCH_EXPORT void* malloc(std::size_t n) {
  count();
  return __libc_malloc(n);
}
CYC_BENCH_EXPORT void* calloc(std::size_t n, std::size_t m) {
  count();
  return __libc_calloc(n, m);
}
CYC_BENCH_EXPORT void* realloc(void* p, std::size_t n) {
  count();
  return __libc_realloc(p, n);
}
CYC_BENCH_EXPORT void free(void* p) { __libc_free(p); }
CYC_BENCH_EXPORT void* memalign(std::size_t a, std::size_t n) {
  count();
  return __libc_memalign(a, n);
}
CYC_BENCH_EXPORT void* aligned_alloc(std::size_t a, std::size_t n) {
  count();
  return __libc_memalign(a, n);
}
CYC_BENCH_EXPORT int posix_memalign(void** out, std::size_t a, std::size_t n) {
  if (a < sizeof(void*) || (a & (a - 1)) != 0) return EINVAL;
  count();
  void* p = __libc_memalign(a, n);
  if (!p && n) return ENOMEM;
  *out = p;
  return 0;
}
CYC_BENCH_EXPORT void* valloc(std::size_t n) {
  count();
  return __libc_valloc(n);
}
CYC_BENCH_EXPORT void* pvalloc(std::size_t n) {
  count();
  return __libc_pvalloc(n);
}

// ------------------------------------------------------------ operator new/delete

namespace {
void* new_impl(std::size_t n) {
  count();
  if (n == 0) n = 1;
  for (;;) {
    if (void* p = __libc_malloc(n)) return p;
    std::new_handler h = std::get_new_handler();
    if (!h) throw std::bad_alloc();
    h();
  }
}
void* new_aligned_impl(std::size_t n, std::size_t a) {
  count();
  if (n == 0) n = 1;
  for (;;) {
    if (void* p = __libc_memalign(a, n)) return p;
    std::new_handler h = std::get_new_handler();
    if (!h) throw std::bad_alloc();
    h();
  }
}
}  // namespace

#define CYC_BENCH_VIS __attribute__((visibility("default")))

CYC_BENCH_VIS void* operator new(std::size_t n) { return new_impl(n); }
CYC_BENCH_VIS void* operator new[](std::size_t n) { return new_impl(n); }
CYC_BENCH_VIS void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  try {
    return new_impl(n);
  } catch (...) {
    return nullptr;
  }
}
CYC_BENCH_VIS void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  try {
    return new_impl(n);
  } catch (...) {
    return nullptr;
  }
}
CYC_BENCH_VIS void* operator new(std::size_t n, std::align_val_t a) {
  return new_aligned_impl(n, static_cast<std::size_t>(a));
}
CYC_BENCH_VIS void* operator new[](std::size_t n, std::align_val_t a) {
  return new_aligned_impl(n, static_cast<std::size_t>(a));
}
CYC_BENCH_VIS void* operator new(std::size_t n, std::align_val_t a,
                                 const std::nothrow_t&) noexcept {
  try {
    return new_aligned_impl(n, static_cast<std::size_t>(a));
  } catch (...) {
    return nullptr;
  }
}
CYC_BENCH_VIS void* operator new[](std::size_t n, std::align_val_t a,
                                   const std::nothrow_t&) noexcept {
  try {
    return new_aligned_impl(n, static_cast<std::size_t>(a));
  } catch (...) {
    return nullptr;
  }
}

CYC_BENCH_VIS void operator delete(void* p) noexcept { __libc_free(p); }
CYC_BENCH_VIS void operator delete[](void* p) noexcept { __libc_free(p); }
CYC_BENCH_VIS void operator delete(void* p, std::size_t) noexcept { __libc_free(p); }
CYC_BENCH_VIS void operator delete[](void* p, std::size_t) noexcept { __libc_free(p); }
CYC_BENCH_VIS void operator delete(void* p, const std::nothrow_t&) noexcept { __libc_free(p); }
CYC_BENCH_VIS void operator delete[](void* p, const std::nothrow_t&) noexcept {
  __libc_free(p);
}
CYC_BENCH_VIS void operator delete(void* p, std::align_val_t) noexcept { __libc_free(p); }
CYC_BENCH_VIS void operator delete[](void* p, std::align_val_t) noexcept { __libc_free(p); }
CYC_BENCH_VIS void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
  __libc_free(p);
}
CYC_BENCH_VIS void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
  __libc_free(p);
}
CYC_BENCH_VIS void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept {
  __libc_free(p);
}
CYC_BENCH_VIS void operator delete[](void* p, std::align_val_t,
                                     const std::nothrow_t&) noexcept {
  __libc_free(p);
}

#endif  // CYC_BENCH_NO_ALLOC_HOOK
