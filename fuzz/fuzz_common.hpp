// Shared helpers of the cyclide fuzz targets (fuzz_create.cpp, fuzz_eval.cpp).
//
// Inputs are decoded with FuzzedDataProvider using only integral reads
// (ConsumeIntegralInRange), which take bytes from the END of the input, most
// significant byte first. fuzz/make_seeds.py relies on exactly that to write
// seed files that encode chosen examples: if you change what a harness
// consumes, update the matching encoder there (and regenerate the seeds).
//
// Oracles abort() with a message (libFuzzer reports the input as a crash;
// the replay driver makes the CTest test fail).
#pragma once

#include <FuzzedDataProvider.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <set>
#include <vector>

#include "cyclide/cyclide.h"

namespace fz {

// ------------------------------------------------------------ reporting

// CYCLIDE_FUZZ_VERBOSE=1 prints every call and status (triage, seed checks).
inline bool verbose() {
  static const bool v = [] {
    const char* e = std::getenv("CYCLIDE_FUZZ_VERBOSE");
    return e && *e && *e != '0';
  }();
  return v;
}

#define FZ_LOG(...)                      \
  do {                                   \
    if (::fz::verbose()) {               \
      std::fprintf(stderr, __VA_ARGS__); \
      std::fputc('\n', stderr);          \
    }                                    \
  } while (0)

#define FZ_CHECK(cond, ...)                                                       \
  do {                                                                            \
    if (!(cond)) {                                                                \
      std::fprintf(stderr, "\n*** cyclide fuzz oracle failed at %s:%d: %s\n    ", \
                   __FILE__, __LINE__, #cond);                                    \
      std::fprintf(stderr, __VA_ARGS__);                                          \
      std::fputc('\n', stderr);                                                   \
      std::fflush(stderr);                                                        \
      std::abort();                                                               \
    }                                                                             \
  } while (0)

inline bool known_status(int s) {
  return std::strcmp(cyc_status_name(s), "CYC_E_UNKNOWN") != 0;
}

// ------------------------------------------------------------ error handler

// Re-entrant error handlers. For each input one of four behaviours is
// chosen from a hash of its bytes (choose_reentry, called first by every
// harness, so a reproducer replays the same way): the handler only records;
// it also makes a call that succeeds on the same context (a line, created
// and destroyed); a call that fails with another status (a curve of degree
// 99); or both. Whatever it does, the failing call must return its own
// status and leave its own status and message in the context (check_call).
enum class Reentry { none = 0, succeed = 1, fail = 2, both = 3 };

inline Reentry& reentry_mode() {
  static Reentry mode = Reentry::none;
  return mode;
}

inline void choose_reentry(const uint8_t* data, size_t size) {
  uint32_t h = 2166136261u;  // FNV-1a
  for (size_t i = 0; i < size; ++i) h = (h ^ data[i]) * 16777619u;
  reentry_mode() = Reentry(h % 4);
}

// The calls a re-entrant handler makes on ctx, and their expected statuses.
inline void reenter(cyc_context* ctx) {
  const Reentry mode = reentry_mode();
  if (mode == Reentry::succeed || mode == Reentry::both) {
    const double O[3] = {0, 0, 0}, X[3] = {1, 2, 3};
    cyc_curve* line = nullptr;
    const int s = cyc_curve_create_line(ctx, O, X, &line);
    // A failing tracking allocator or a full caller block may refuse it.
    FZ_CHECK(s == CYC_OK || s == CYC_E_OUT_OF_MEMORY, "re-entrant cyc_curve_create_line: %d", s);
    cyc_curve_destroy(ctx, line);
  }
  if (mode == Reentry::fail || mode == Reentry::both) {
    const double coeffs[4] = {0, 0, 0, 1};
    cyc_curve* c = nullptr;
    const int s = cyc_curve_create_polynomial(ctx, 99, coeffs, 4, &c);
    FZ_CHECK(s == CYC_E_DEGREE_TOO_HIGH && c == nullptr,
             "re-entrant cyc_curve_create_polynomial(degree 99): %d", s);
  }
}

// Records the error callback so that every call can be checked against it;
// re-enters the library on ctx as reentry_mode() says. Errors of the
// handler's own calls are not recorded (they are not the call under test).
struct HandlerLog {
  int calls = 0;
  int status = CYC_OK;
  const char* message = nullptr;
  cyc_context* ctx = nullptr;  // the context the handler is installed on
  int active = 0;              // handler frames on the stack
  static void callback(int status, const char* message, void* userdata) {
    auto* log = static_cast<HandlerLog*>(userdata);
    if (log->active > 0) return;
    FZ_LOG("    (error handler: %s)", message);
    ++log->calls;
    log->status = status;
    log->message = message;
    if (log->ctx) {
      ++log->active;
      reenter(log->ctx);
      --log->active;
    }
  }
};

// Install log as ctx's error handler.
inline int install_handler(cyc_context* ctx, HandlerLog& log) {
  log.ctx = ctx;
  return cyc_context_set_error_handler(ctx, &HandlerLog::callback, &log);
}

// The contract every call on a live context satisfies: a known status, never
// CYC_E_INTERNAL ("a bug in cyclide"), last status/message recorded, the
// error handler called exactly on errors with the same status and message.
inline void check_call(const char* fn, const cyc_context* ctx, int s, HandlerLog* log) {
  FZ_LOG("  %s -> %s%s%s", fn, cyc_status_name(s), s ? ": " : "",
         s ? cyc_context_last_error(ctx) : "");
  FZ_CHECK(known_status(s), "%s returned unknown status %d", fn, s);
  FZ_CHECK(s != CYC_E_INTERNAL, "%s returned CYC_E_INTERNAL: %s", fn,
           cyc_context_last_error(ctx));
  FZ_CHECK(cyc_context_last_status(ctx) == s, "%s: last_status %d != returned %d", fn,
           cyc_context_last_status(ctx), s);
  const char* msg = cyc_context_last_error(ctx);
  FZ_CHECK(msg != nullptr, "%s: last_error is NULL", fn);
  const size_t len = strnlen(msg, CYC_ERROR_MESSAGE_SIZE);
  FZ_CHECK(len < CYC_ERROR_MESSAGE_SIZE, "%s: last_error not NUL-terminated", fn);
  if (s == CYC_OK) {
    FZ_CHECK(len == 0, "%s: OK but last_error = \"%s\"", fn, msg);
  } else {
    FZ_CHECK(len > 0, "%s: %s but last_error is empty", fn, cyc_status_name(s));
  }
  if (log) {
    if (s == CYC_OK) {
      FZ_CHECK(log->calls == 0, "%s: OK but the error handler was called", fn);
    } else {
      FZ_CHECK(log->calls == 1, "%s: error handler called %d times (expected 1)", fn,
               log->calls);
      FZ_CHECK(log->status == s, "%s: handler status %d != %d", fn, log->status, s);
      FZ_CHECK(log->message && std::strcmp(log->message, msg) == 0,
               "%s: handler message differs from last_error", fn);
    }
    log->calls = 0;
    log->message = nullptr;
  }
}

// ------------------------------------------------------------ known issue

// KNOWN ISSUE (reported; set to false once fixed). The evaluator
// (lib/cyclide/evaluator.hpp, circle_family.hpp circle_point) computes the
// circle point through the expanded quadratic P(v)/Q(v),
// Q = W^2 + |a|^2 G^2 with W = alpha v + beta, G = gamma v + delta, and x_v
// through the quotient rule. Horner on P and Q cancels where W and |a| G are
// small compared with their terms (f nearly degenerate at v, or G(v) = 0 with
// |a| large): points leave their circle, Q(v) can round to 0 or below, and
// then eval reports CYC_E_NUMERICAL_OVERFLOW on a validated row, eval_grid
// returns CYC_OK with NaN points and eval_batch CYC_E_INTERNAL. And x_v
// cancels when |a| is far from 1 (relative error 4e-5 at |a| = 2e9). While
// the flag is set, the harnesses skip parameters where the Horner condition
// number of Q exceeds 1e4, waive accuracy oracles there, and do not check
// normal . x_v = 0.
// FIXED: the evaluator now forms W and G per point and x_v from the exact
// rotation rate (lib/cyclide/evaluator.hpp); the regression inputs stay in
// the corpus. Kept switchable for bisecting old versions.
constexpr bool kKnownIssueCircleQuadratic = false;
constexpr double kKnownIssueKappa = 1e4;

// kappa = ((|alpha v| + |beta|)^2 + |a|^2 (|gamma v| + |delta|)^2) / Q(v) at
// (u, v), with a = the ringed n (PRCS: s', PRRS: n) and f as given (NULL:
// f = v); NaN if the ringed data are unavailable.
inline double circle_kappa(cyc_context* ctx, const cyc_surface* S, const cyc_mobius* f,
                           double u, double v, HandlerLog* log) {
  double n[3];
  const int s = cyc_surface_ringed_data(ctx, S, u, nullptr, n, nullptr, nullptr);
  check_call("cyc_surface_ringed_data", ctx, s, log);
  if (s != CYC_OK) return std::numeric_limits<double>::quiet_NaN();
  const double aa = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  double al = 1, be = 0, ga = 0, de = 1;
  if (f && f->degree >= 0 && f->degree <= CYC_MAX_MOBIUS_DEGREE) {
    auto horner = [&](const double* k) {
      double r = k[f->degree];
      for (int i = f->degree - 1; i >= 0; --i) r = r * u + k[i];
      return r;
    };
    al = horner(f->alpha);
    be = horner(f->beta);
    ga = horner(f->gamma);
    de = horner(f->delta);
  }
  const double W = al * v + be, G = ga * v + de;
  const double sw = std::abs(al * v) + std::abs(be), sg = std::abs(ga * v) + std::abs(de);
  const double kappa = (sw * sw + aa * sg * sg) / (W * W + aa * G * G);
  FZ_LOG("    (known issue: kappa = %g at u = %.17g v = %.17g)", kappa, u, v);
  return kappa;
}

// Parameters to avoid while the known issue stands (kappa known and large).
inline bool known_issue_avoid(cyc_context* ctx, const cyc_surface* S, const cyc_mobius* f,
                              double u, double v, HandlerLog* log) {
  if (!kKnownIssueCircleQuadratic || !std::isfinite(u) || !std::isfinite(v)) return false;
  return circle_kappa(ctx, S, f, u, v, log) > kKnownIssueKappa;
}

// Whether the known issue may explain a failed accuracy oracle (kappa large
// or unknown).
inline bool known_issue_waives(cyc_context* ctx, const cyc_surface* S, const cyc_mobius* f,
                               double u, double v, HandlerLog* log) {
  if (!kKnownIssueCircleQuadratic) return false;
  return !(circle_kappa(ctx, S, f, u, v, log) <= kKnownIssueKappa);
}

// ------------------------------------------------------------ allocator

// A tracking allocator: checks the alignment contract, that free gets only
// what alloc returned, counts live blocks (leaks of handles), and can fail
// the n-th allocation (CYC_E_OUT_OF_MEMORY paths).
struct Tracker {
  std::set<void*> live;
  long count = 0;     // allocations attempted
  long fail_at = -1;  // index of the allocation that fails (-1: none)
  bool fail_after = false;  // also fail every later one
  static void* alloc(void* ud, size_t size, size_t alignment) {
    auto* t = static_cast<Tracker*>(ud);
    FZ_CHECK(alignment > 0 && (alignment & (alignment - 1)) == 0 && alignment <= 64,
             "allocator asked for alignment %zu", alignment);
    FZ_CHECK(size > 0 && size < (size_t(1) << 30), "allocator asked for %zu bytes", size);
    const long k = t->count++;
    if (t->fail_at >= 0 && (k == t->fail_at || (t->fail_after && k > t->fail_at)))
      return nullptr;
    const size_t a = alignment < alignof(std::max_align_t) ? alignof(std::max_align_t)
                                                            : alignment;
    void* p = std::aligned_alloc(a, (size + a - 1) / a * a);
    if (p) t->live.insert(p);
    return p;
  }
  static void free(void* ud, void* p) {
    auto* t = static_cast<Tracker*>(ud);
    if (!p) return;
    FZ_CHECK(t->live.erase(p) == 1, "allocator free of %p which alloc did not return", p);
    std::free(p);
  }
  cyc_allocator allocator() { return {&Tracker::alloc, &Tracker::free, this}; }
};

// ------------------------------------------------------------ input

constexpr double kSpecial[] = {
    0.0, -0.0, 1.0, -1.0, 2.0, 0.5, 3.0, 10.0, -10.0, 1.0 / 3.0,
    std::numeric_limits<double>::quiet_NaN(), -std::numeric_limits<double>::quiet_NaN(),
    std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
    1e100, -1e100, 1.0000000000000002e100, -1.0000000000000002e100,  // just above 1e100
    1e30, -1e30, 1e-30, 1e15, 1e-15, 1e-12, 1e-10, 1e50, 1e-100, 1e300, -1e300, 1e-300,
    DBL_MAX, -DBL_MAX, DBL_MIN, std::numeric_limits<double>::denorm_min(),
    DBL_EPSILON, 3.141592653589793, 0.1, -0.5};
constexpr int kNumSpecial = int(sizeof kSpecial / sizeof kSpecial[0]);

class Input {
 public:
  Input(const uint8_t* data, size_t size) : p_(data, size) {}

  int range(int lo, int hi) { return p_.ConsumeIntegralInRange<int>(lo, hi); }
  bool flag() { return range(0, 1) == 1; }
  // true with probability ~1/16 (NULL pointers, invalid sizes).
  bool rarely() { return range(0, 15) == 0; }
  uint64_t u64() { return p_.ConsumeIntegral<uint64_t>(); }
  size_t remaining() { return p_.remaining_bytes(); }

  // Any double: raw bits, specials (NaN, Inf, 1e100 and just above, huge,
  // tiny, denormal), small integers, dyadic fractions, powers of ten.
  double wild() {
    switch (range(0, 5)) {
      case 0: {
        const uint64_t bits = u64();
        double d;
        std::memcpy(&d, &bits, sizeof d);
        return d;
      }
      case 1: return kSpecial[range(0, kNumSpecial - 1)];
      case 2: return double(range(-16, 16));
      case 3: return double(range(-32768, 32767)) / 256.0;
      case 4: {
        const double m = double(range(-9, 9));
        return m * std::pow(10.0, double(range(-330, 330)));
      }
      default: {  // a few ulps around a boundary value
        static constexpr double kEdge[] = {1e100, 1e30, 1e-30, 1e-12, 1e-10, 1.0, 0.0};
        double x = kEdge[range(0, 6)];
        if (flag()) x = -x;
        const int steps = range(-4, 4);
        for (int i = 0; i < std::abs(steps); ++i)
          x = std::nextafter(x, steps > 0 ? HUGE_VAL : -HUGE_VAL);
        return x;
      }
    }
  }

  // A moderate value in [-10, 10]: integers or exact binary fractions.
  double moderate() {
    switch (range(0, 2)) {
      case 0: return double(range(-10, 10));
      case 1: return double(range(-2560, 2560)) / 256.0;
      default: return double(range(-(1 << 20), 1 << 20)) * (10.0 / double(1 << 20));
    }
  }

  // Fill n doubles: style 0 wild, 1 moderate, 2 mixed per value.
  void fill(double* v, size_t n, int style) {
    for (size_t i = 0; i < n; ++i)
      v[i] = style == 0 ? wild() : style == 1 ? moderate() : (flag() ? wild() : moderate());
  }

 private:
  FuzzedDataProvider p_;
};

// A coordinate: moderate, wild, well-scaled (m * 10^e, |e| <= 3) or a small
// integer (fuzz_darboux, fuzz_lines; fuzz/make_seeds.py mirrors it).
inline double coord(Input& in) {
  switch (in.range(0, 3)) {
    case 0: return in.moderate();
    case 1: return in.wild();
    case 2: return double(in.range(-99, 99)) / 10.0 * std::pow(10.0, double(in.range(-3, 2)));
    default: return double(in.range(-4, 4));
  }
}
inline void coords(Input& in, double* v, int n) {
  for (int i = 0; i < n; ++i) v[i] = coord(in);
}

// ------------------------------------------------------------ sentinels

// A sentinel bit pattern (a signalling-NaN-like payload no computation
// produces) written into every output before a call.
constexpr uint64_t kSentinelBits = 0x7ff4dead5eed1234ull;
inline double sentinel() {
  double d;
  std::memcpy(&d, &kSentinelBits, sizeof d);
  return d;
}
inline bool is_sentinel(double d) { return std::memcmp(&d, &kSentinelBits, sizeof d) == 0; }
inline void fill_sentinel(double* p, size_t n) {
  for (size_t i = 0; i < n; ++i) std::memcpy(p + i, &kSentinelBits, sizeof(double));
}
inline bool all_sentinel(const double* p, size_t n) {
  for (size_t i = 0; i < n; ++i)
    if (!is_sentinel(p[i])) return false;
  return true;
}

inline bool finite3(const double* v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}
// |v| without underflow or overflow of the squares (x_v ~ 1/v^2 at huge v).
inline double norm3(const double* v) {
  const double m = std::max({std::abs(v[0]), std::abs(v[1]), std::abs(v[2])});
  if (!(m > 0) || !std::isfinite(m)) return m;
  const double a = v[0] / m, b = v[1] / m, c = v[2] / m;
  return m * std::sqrt(a * a + b * b + c * c);
}
inline double dot3(const double* a, const double* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline double dist3(const double* a, const double* b) {
  const double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  return norm3(d);
}

// An exactly sized heap copy so that ASan sees any read past the end.
inline std::vector<double> exact(size_t n) { return std::vector<double>(n); }

}  // namespace fz
