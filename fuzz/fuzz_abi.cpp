// Fuzz target of the whole C ABI as a hostile host sees it: every
// status-returning entry point of cyclide.h whose first parameter is the
// context (the list is generated from the header, cmake/cyclide_entry_points.cmake,
// so a new entry point is fuzzed as soon as it is declared), called with
// arguments decoded by their C type alone:
//  - int:      small values 0..8, 16, -1, -2, INT_MAX, INT_MIN, INT_MAX / 2 + 1
//              (doubling it overflows), INT_MIN + 1;
//  - size_t:   0..8, 16, SIZE_MAX, SIZE_MAX / 2 + 1, SIZE_MAX / 3, SIZE_MAX / 8 + 1
//              (products and byte offsets overflow);
//  - double:   fz::kSpecial (NaN, +-Inf, 1e100 and just above, 1e308, denormals,
//              -0.0, ...) and small dyadic values;
//  - handles (const cyc_surface*, ...): NULL or a valid handle of the fixture
//              (PRCS and PRRS of lines, a Dupin torus, curves, a sphere skin, an
//              export);
//  - handle outputs (cyc_surface** ...): NULL or 64 slots holding a sentinel;
//  - const arrays of numbers: NULL or 4096 entries of fuzzed values;
//  - output arrays of numbers and output structs: NULL or a region of
//              sentinel bytes (4096 numbers or 64 structs);
//  - const structs without pointer members: NULL or 64 structs of fuzzed
//              words (doubles from the table, small and extreme ints);
//              structs with pointer members: NULL or zero-filled;
//  - cyc_buffer3 (by value): no data, or an output region with its true
//              capacity at a fuzzed stride (0..6, SIZE_MAX);
//  - strings: NULL, "", a path in a scratch directory, a path in a missing
//              directory, the directory itself; void* work blocks: NULL.
// The small counts keep every honest array inside the regions; the extreme
// ones must be refused before anything is read, written or multiplied.
// Each input makes up to four calls, on a fresh context through a tracking
// allocator (which can fail the n-th allocation), with an error handler
// that re-enters the library (fz::choose_reentry), or with a NULL context.
//
// Oracles: no crash, no sanitizer report, no leak; with a NULL context
// CYC_E_NULL_ARGUMENT; otherwise fz::check_call (a known status, never
// CYC_E_INTERNAL, last status / message / handler agree, also with
// re-entrant handlers); on error every output region and handle slot is
// untouched (but for the documented working arrays); on success every
// handle written is valid and destroyed, and nothing stays allocated.
#include <sys/stat.h>
#include <unistd.h>

#include <climits>
#include <cstdint>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "fuzz_common.hpp"

namespace {

using fz::Input;

// ------------------------------------------------------------ the header

template <class T>
struct pointer_struct : std::false_type {};
#define CYC_ENTRY(f)
#define CYC_POINTER_STRUCT(s) \
  template <>                 \
  struct pointer_struct<s> : std::true_type {};
#include "cyclide_entry_points.inc"
#undef CYC_ENTRY
#undef CYC_POINTER_STRUCT

template <class T>
constexpr bool is_handle_v =
    std::is_same_v<T, cyc_curve> || std::is_same_v<T, cyc_surface> ||
    std::is_same_v<T, cyc_sphere_skin> || std::is_same_v<T, cyc_bezier_export> ||
    std::is_same_v<T, cyc_pn_surface> || std::is_same_v<T, cyc_context>;

// Entry points whose outputs are documented as working arrays (unspecified
// after an error): cyc_tessellate_plan's us (header, SPEC §8j.4).
bool outputs_are_scratch(const char* name) {
  return std::strcmp(name, "cyc_tessellate_plan") == 0 ||
         std::strcmp(name, "cyc_sphere_skin_tessellate_plan") == 0;
}

// ------------------------------------------------------------ fixture

// Valid handles, built once in a context of their own and shared read-only
// by every input (handles may be used with any context).
struct Fixture {
  cyc_context* ctx = nullptr;
  std::vector<cyc_curve*> curves;
  std::vector<cyc_surface*> surfaces;
  std::vector<cyc_sphere_skin*> skins;
  std::vector<cyc_bezier_export*> exports;
  std::vector<cyc_pn_surface*> pn;  // none yet: NULL only

  Fixture() {
    FZ_CHECK(cyc_context_create(nullptr, &ctx) == CYC_OK, "fixture context");
    const double O[3] = {0, 0, 0}, X[3] = {1, 0, 0}, P[3] = {0, 0, 1}, W[3] = {2, 1, 0},
                 Q[3] = {0, 2, 0}, Y[3] = {0, 1, 1};
    cyc_curve *l1 = nullptr, *l2 = nullptr, *l3 = nullptr;
    FZ_CHECK(cyc_curve_create_line(ctx, O, X, &l1) == CYC_OK, "line 1");
    FZ_CHECK(cyc_curve_create_line(ctx, P, W, &l2) == CYC_OK, "line 2");
    FZ_CHECK(cyc_curve_create_line(ctx, Q, Y, &l3) == CYC_OK, "line 3");
    curves = {l1, l2, l3};
    const double cubic[16] = {0, 0, 0, 1, 1, 0.5, 0, 0, 0, 1, 0.25, 0, 0, 0, 1, 0};
    cyc_curve* c = nullptr;
    FZ_CHECK(cyc_curve_create_polynomial(ctx, 3, cubic, 4, &c) == CYC_OK, "cubic");
    curves.push_back(c);
    cyc_surface* s = nullptr;
    FZ_CHECK(cyc_prcs_create(ctx, l1, l2, nullptr, -0.5, 0.5, &s) == CYC_OK, "PRCS");
    surfaces.push_back(s);
    FZ_CHECK(cyc_prrs_create(ctx, l1, l2, l3, nullptr, -0.5, 0.5, &s) == CYC_OK, "PRRS");
    surfaces.push_back(s);
    // A torus: the Dupin cyclide of three equal spheres on a circle.
    cyc_lie_sphere sp[3];
    std::memset(sp, 0, sizeof sp);
    for (int i = 0; i < 3; ++i) {
      const double a = 2.0943951023931957 * i;
      sp[i].kind = CYC_LIE_SPHERE;
      sp[i].m[0] = 3 * std::cos(a);
      sp[i].m[1] = 3 * std::sin(a);
      sp[i].rho = 1;
    }
    cyc_dupin D;
    if (cyc_dupin_from_spheres(ctx, sp, &D) == CYC_OK &&
        cyc_dupin_surface_create(ctx, &D, nullptr, nullptr, -1, 1, &s) == CYC_OK)
      surfaces.push_back(s);
    cyc_skin_end a, b;
    const double c0[3] = {0, 0, 0}, e0[3] = {0, 0, 0.5}, t0[3] = {0, 0, 4};
    const double c1[3] = {3, 0, 4}, e1[3] = {2.5, 0, 4}, t1[3] = {4, 0, 0};
    cyc_sphere_skin* k = nullptr;
    if (cyc_skin_end_from_sphere(ctx, c0, 1, e0, t0, &a) == CYC_OK &&
        cyc_skin_end_from_sphere(ctx, c1, 1, e1, t1, &b) == CYC_OK &&
        cyc_sphere_skin_create(ctx, &a, &b, nullptr, &k) == CYC_OK)
      skins.push_back(k);
    cyc_bezier_export* e = nullptr;
    if (cyc_bezier_export_create(ctx, surfaces[0], nullptr, &e) == CYC_OK) exports.push_back(e);
  }

  template <class H>
  const std::vector<H*>& of() const {
    if constexpr (std::is_same_v<H, cyc_curve>) return curves;
    else if constexpr (std::is_same_v<H, cyc_surface>) return surfaces;
    else if constexpr (std::is_same_v<H, cyc_sphere_skin>) return skins;
    else if constexpr (std::is_same_v<H, cyc_bezier_export>) return exports;
    else if constexpr (std::is_same_v<H, cyc_pn_surface>) return pn;
    else {
      static const std::vector<H*> none;
      return none;
    }
  }
};

const Fixture& fixture() {
  static const Fixture* F = new Fixture();  // lives to the end (not a leak)
  return *F;
}

const std::string& scratch_dir() {
  static const std::string dir = [] {
    std::string d = "/tmp/cyclide-fuzz-abi-" + std::to_string(getpid());
    mkdir(d.c_str(), 0700);
    return d;
  }();
  return dir;
}

// ------------------------------------------------------------ one call

constexpr size_t kNumbers = 4096;  // entries of a number region
constexpr size_t kStructs = 64;    // structs of a struct region, handle slots
constexpr unsigned char kSentinelByte = 0xA5;

// The regions one call's arguments point to, and what to check afterwards.
struct Call {
  Input& in;
  cyc_context* ctx;
  std::vector<std::vector<unsigned char>> regions;  // owned memory
  struct Output {
    size_t region;  // index into regions
  };
  std::vector<Output> outputs;  // regions the call may write only on success
  struct Slots {
    void** slots;
    void (*destroy)(cyc_context*, void*);
  };
  std::vector<Slots> handle_slots;
  std::vector<std::string> strings;

  unsigned char* region(size_t bytes, bool output) {
    regions.emplace_back(bytes + 64, kSentinelByte);
    unsigned char* p = regions.back().data();
    const auto a = reinterpret_cast<uintptr_t>(p);
    p += (64 - a % 64) % 64;  // aligned for any type
    if (output) outputs.push_back({regions.size() - 1});
    return p;
  }

  int an_int() {
    static constexpr int table[] = {-1,      -2,      INT_MAX, INT_MIN, INT_MAX / 2 + 1,
                                    INT_MIN + 1, 16};
    if (in.range(0, 3) != 0) return in.range(0, 8);
    return table[in.range(0, int(sizeof table / sizeof table[0]) - 1)];
  }
  size_t a_size() {
    static constexpr size_t table[] = {SIZE_MAX, SIZE_MAX / 2 + 1, SIZE_MAX / 3,
                                       SIZE_MAX / 8 + 1, 16};
    if (in.range(0, 3) != 0) return size_t(in.range(0, 8));
    return table[in.range(0, int(sizeof table / sizeof table[0]) - 1)];
  }
  double a_double() {
    if (in.flag()) return double(in.range(-64, 64)) / 8.0;
    return fz::kSpecial[in.range(0, fz::kNumSpecial - 1)];
  }

  // Fill bytes with words a struct of doubles and ints may hold.
  void fill_words(unsigned char* p, size_t bytes) {
    for (size_t off = 0; off + 8 <= bytes; off += 8) {
      if (in.remaining() == 0) {
        std::memset(p + off, 0, bytes - off);
        return;
      }
      if (in.flag()) {
        const double d = a_double();
        std::memcpy(p + off, &d, 8);
      } else {
        const int32_t w[2] = {an_int(), an_int()};
        std::memcpy(p + off, w, 8);
      }
    }
  }

  template <class T>
  T arg() {
    if constexpr (std::is_same_v<T, int>) {
      return an_int();
    } else if constexpr (std::is_same_v<T, size_t>) {
      return a_size();
    } else if constexpr (std::is_same_v<T, double>) {
      return a_double();
    } else if constexpr (std::is_same_v<T, cyc_buffer3>) {
      cyc_buffer3 b{nullptr, 0, 3};
      static constexpr size_t strides[] = {0, 1, 2, 3, 4, 6, SIZE_MAX};
      b.stride = strides[in.range(0, 6)];
      if (in.range(0, 3) != 0) {
        b.data = reinterpret_cast<double*>(region(kNumbers * sizeof(double), true));
        b.capacity = b.stride >= 3 ? kNumbers / b.stride : kNumbers / 3;
      }
      return b;
    } else if constexpr (std::is_pointer_v<T>) {
      return pointer_arg<T>();
    } else {
      static_assert(std::is_trivially_copyable_v<T>, "a by-value argument the fuzzer lacks");
      T t;
      std::memset(&t, 0, sizeof t);
      return t;
    }
  }

  template <class T>
  T pointer_arg() {
    using P = std::remove_pointer_t<T>;
    using V = std::remove_cv_t<P>;
    if (in.rarely()) return nullptr;
    if constexpr (std::is_function_v<P> || std::is_void_v<V>) {
      return nullptr;  // callbacks, work blocks: their sizes cannot be told
    } else if constexpr (is_handle_v<V>) {
      const auto& list = fixture().of<V>();
      if (list.empty() || in.flag()) return nullptr;
      return list[in.range(0, int(list.size()) - 1)];
    } else if constexpr (std::is_pointer_v<V>) {
      using H = std::remove_cv_t<std::remove_pointer_t<V>>;
      static_assert(is_handle_v<H>, "a pointer to pointer the fuzzer lacks");
      if constexpr (std::is_const_v<P> || std::is_const_v<std::remove_pointer_t<V>>) {
        // An input array of handles (cyc_surface* const*): fixture handles.
        auto** a = reinterpret_cast<H**>(region(kStructs * sizeof(H*), false));
        const auto& list = fixture().of<H>();
        for (size_t i = 0; i < kStructs; ++i)
          a[i] = list.empty() ? nullptr : list[i % list.size()];
        return const_cast<T>(a);
      } else {
        auto** slots = reinterpret_cast<H**>(region(kStructs * sizeof(H*), true));
        handle_slots.push_back({reinterpret_cast<void**>(slots), &destroy_handle<H>});
        return slots;
      }
    } else if constexpr (std::is_same_v<V, char>) {
      static_assert(std::is_const_v<P>, "a char output the fuzzer lacks");
      switch (in.range(0, 4)) {
        case 0: strings.emplace_back(""); break;
        case 1: strings.emplace_back(scratch_dir() + "/out"); break;
        case 2: strings.emplace_back(scratch_dir() + "/missing/out"); break;
        case 3: strings.emplace_back(scratch_dir()); break;
        default: strings.emplace_back(scratch_dir() + "/out.glb"); break;
      }
      return strings.back().c_str();
    } else if constexpr (std::is_arithmetic_v<V>) {
      V* p = reinterpret_cast<V*>(region(kNumbers * sizeof(V), !std::is_const_v<P>));
      if constexpr (std::is_const_v<P>)
        for (size_t i = 0; i < kNumbers; ++i) {
          if constexpr (std::is_floating_point_v<V>)
            p[i] = V(in.remaining() ? a_double() : 0.0);
          else if constexpr (std::is_same_v<V, int>)
            p[i] = in.remaining() ? an_int() : 0;
          else
            p[i] = V(in.remaining() ? a_size() : 0);
        }
      return p;
    } else {
      static_assert(std::is_trivially_copyable_v<V>, "a struct the fuzzer lacks");
      auto* p = region(kStructs * sizeof(V), !std::is_const_v<P>);
      if constexpr (std::is_const_v<P>) {
        if (pointer_struct<V>::value)
          std::memset(p, 0, kStructs * sizeof(V));
        else
          fill_words(p, kStructs * sizeof(V));
      }
      return reinterpret_cast<T>(p);
    }
  }

  template <class H>
  static void destroy_handle(cyc_context* c, void* h) {
    if constexpr (std::is_same_v<H, cyc_curve>) cyc_curve_destroy(c, static_cast<H*>(h));
    else if constexpr (std::is_same_v<H, cyc_surface>) cyc_surface_destroy(c, static_cast<H*>(h));
    else if constexpr (std::is_same_v<H, cyc_sphere_skin>)
      cyc_sphere_skin_destroy(c, static_cast<H*>(h));
    else if constexpr (std::is_same_v<H, cyc_bezier_export>)
      cyc_bezier_export_destroy(static_cast<H*>(h));
    else if constexpr (std::is_same_v<H, cyc_pn_surface>)
      cyc_pn_surface_destroy(static_cast<H*>(h));
    else
      FZ_CHECK(false, "a handle output of an unknown type");
  }

  // Whether a region still holds its sentinel.
  bool untouched(const std::vector<unsigned char>& r) const {
    for (unsigned char b : r)
      if (b != kSentinelByte) return false;
    return true;
  }

  void check_after(const char* name, int rc) {
    const uintptr_t sentinel_word = [] {
      uintptr_t w;
      std::memset(&w, kSentinelByte, sizeof w);
      return w;
    }();
    if (rc != CYC_OK) {
      if (!outputs_are_scratch(name))
        for (const Output& o : outputs)
          FZ_CHECK(untouched(regions[o.region]), "%s: %s but an output was written", name,
                   cyc_status_name(rc));
      return;
    }
    for (const Slots& s : handle_slots)
      for (size_t i = 0; i < kStructs; ++i)
        if (reinterpret_cast<uintptr_t>(s.slots[i]) != sentinel_word && s.slots[i])
          s.destroy(ctx, s.slots[i]);
  }
};

template <class... A>
int call_entry(Call& c, int (*f)(cyc_context*, A...)) {
  // A braced list decodes the arguments left to right.
  std::tuple<A...> args{c.arg<A>()...};
  return std::apply([&](A... a) { return f(c.ctx, a...); }, args);
}

struct Entry {
  const char* name;
  int (*call)(Call&);
};

#define CYC_ENTRY(f) {#f, [](Call& c) { return call_entry(c, &f); }},
#define CYC_POINTER_STRUCT(s)
const std::vector<Entry>& entries() {
  static const std::vector<Entry> list = [] {
    std::vector<Entry> all = {
#include "cyclide_entry_points.inc"
    };
    std::vector<Entry> kept;
    for (const Entry& e : all)  // the handler is the harness's own
      if (std::strcmp(e.name, "cyc_context_set_error_handler") != 0) kept.push_back(e);
    return kept;
  }();
  return list;
}
#undef CYC_ENTRY
#undef CYC_POINTER_STRUCT

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fz::choose_reentry(data, size);
  fixture();
  Input in(data, size);
  const auto& list = entries();
  fz::Tracker tracker;
  if (in.rarely()) {
    tracker.fail_at = in.range(0, 8);
    tracker.fail_after = in.flag();
  }
  const cyc_allocator allocator = tracker.allocator();
  cyc_context* ctx = nullptr;
  FZ_CHECK(cyc_context_create(&allocator, &ctx) == CYC_OK || tracker.fail_at == 0,
           "cyc_context_create");
  if (!ctx) return 0;
  fz::HandlerLog log;
  FZ_CHECK(fz::install_handler(ctx, log) == CYC_OK, "install_handler");
  for (int k = 0; k < 4 && in.remaining() > 0; ++k) {
    const Entry& e = list[size_t(in.range(0, int(list.size()) - 1))];
    const bool null_context = in.rarely();
    Call c{in, null_context ? nullptr : ctx, {}, {}, {}, {}};
    FZ_LOG("%s%s", e.name, null_context ? " (NULL context)" : "");
    const int rc = e.call(c);
    if (null_context) {
      FZ_CHECK(rc == CYC_E_NULL_ARGUMENT, "%s(NULL context) returned %s", e.name,
               cyc_status_name(rc));
      continue;
    }
    fz::check_call(e.name, ctx, rc, &log);
    c.check_after(e.name, rc);
  }
  cyc_context_destroy(ctx);
  FZ_CHECK(tracker.live.empty(), "%zu allocations still live after all handles were destroyed",
           tracker.live.size());
  return 0;
}
