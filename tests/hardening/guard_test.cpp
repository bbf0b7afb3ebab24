// The guard every entry point runs through (SPEC §9b.1), tried on EVERY
// status-returning entry point of cyclide.h whose first parameter is the
// context (the list is generated from the header, so a new entry point is
// tried as soon as it is declared). Each is called the way a careless host
// calls it: every argument after the context zero (NULL pointers, zero
// counts and degrees, zero structs).
//  - With a NULL context: CYC_E_NULL_ARGUMENT, and no crash.
//  - A failing call reports one status three ways that agree (return value,
//    cyc_context_last_status, the error handler's status), and a message that
//    names the function.
//  - Re-entrant handlers: the handler calls the library on the same context
//    -- a call that succeeds, a call that fails with another status, the same
//    failing call again, three levels deep -- and the outer call still returns
//    its own status; afterwards the context holds the outer call's status and
//    message, and the message pointer the handler was given (the context's
//    buffer) reads the outer call's message again.
// Heap contexts and caller-memory contexts (cyc_context_init_static) alike.

#include <gtest/gtest.h>

#include <cyclide/cyclide.h>

#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace {

// f(ctx, 0, 0, ...): every parameter after the context value-initialized.
template <class... A>
int call_with_zeros(int (*f)(cyc_context*, A...), cyc_context* ctx) {
  return f(ctx, A{}...);
}

struct Entry {
  const char* name;
  int (*call)(cyc_context*);
};

#define CYC_ENTRY(f) {#f, [](cyc_context* c) { return call_with_zeros(&f, c); }},
#define CYC_POINTER_STRUCT(s)
const std::vector<Entry>& entries() {
  static const std::vector<Entry> list = {
#include "cyclide_entry_points.inc"
  };
  return list;
}
#undef CYC_ENTRY
#undef CYC_POINTER_STRUCT

// Entry points that the zero call would reconfigure rather than exercise.
bool skipped(const char* name) { return std::strcmp(name, "cyc_context_set_error_handler") == 0; }

enum class Reentry { none, succeed, fail_other, repeat, nested };
const char* reentry_name(Reentry r) {
  switch (r) {
    case Reentry::none: return "none";
    case Reentry::succeed: return "succeed";
    case Reentry::fail_other: return "fail_other";
    case Reentry::repeat: return "repeat";
    case Reentry::nested: return "nested";
  }
  return "?";
}

// What the handler saw and did.
struct Probe {
  cyc_context* ctx = nullptr;
  Reentry mode = Reentry::none;
  const Entry* entry = nullptr;
  int calls = 0;
  int active = 0;  // handler frames on the stack
  int status = CYC_OK;        // of the first (outer) call
  std::string message;        // of the first (outer) call
  const char* message_pointer = nullptr;  // as given to the first call
  int inner_status = -12345;   // of the handler's own first call
};

// The deepest the handler re-enters: nested goes three levels down, the
// others one (their inner failure calls the handler again, which then only
// records).
int depth_of(Reentry r) { return r == Reentry::nested ? 3 : 1; }

void handler(int status, const char* message, void* userdata) {
  Probe& P = *static_cast<Probe*>(userdata);
  if (P.calls++ == 0) {
    P.status = status;
    P.message = message;
    P.message_pointer = message;
  }
  if (P.active >= depth_of(P.mode)) return;
  ++P.active;
  int inner = CYC_OK;
  switch (P.mode) {
    case Reentry::none: break;
    case Reentry::succeed: {
      const double O[3] = {0, 0, 0}, X[3] = {1, 2, 3};
      cyc_curve* line = nullptr;
      inner = cyc_curve_create_line(P.ctx, O, X, &line);
      cyc_curve_destroy(P.ctx, line);
      break;
    }
    case Reentry::fail_other: {
      const double coeffs[4] = {0, 0, 0, 1};
      cyc_curve* c = nullptr;
      inner = cyc_curve_create_polynomial(P.ctx, 99, coeffs, 4, &c);  // degree too high
      break;
    }
    case Reentry::repeat:
    case Reentry::nested: inner = P.entry->call(P.ctx); break;
  }
  if (P.active == 1) P.inner_status = inner;
  --P.active;
}

// A caller-memory context in a block of its own.
struct StaticContext {
  std::vector<unsigned char> block = std::vector<unsigned char>(1 << 20);
  cyc_context* ctx = nullptr;
  StaticContext() { cyc_context_init_static(block.data(), block.size(), nullptr, &ctx); }
};

TEST(Guard, EveryEntryPointIsListed) {
  // The generator reads "CYC_API int cyc_x(cyc_context* ctx"; if the header's
  // style changes, it must still find them all.
  EXPECT_GE(entries().size(), 170u);
}

TEST(Guard, NullContextIsNullArgumentEverywhere) {
  for (const Entry& e : entries()) {
    if (skipped(e.name)) continue;
    EXPECT_EQ(e.call(nullptr), CYC_E_NULL_ARGUMENT) << e.name;
  }
  EXPECT_EQ(cyc_context_set_error_handler(nullptr, handler, nullptr), CYC_E_NULL_ARGUMENT);
}

// One entry point on one context with one way of re-entering.
void check_call(cyc_context* ctx, const Entry& e, Reentry mode) {
  Probe P;
  P.ctx = ctx;
  P.mode = mode;
  P.entry = &e;
  ASSERT_EQ(cyc_context_set_error_handler(ctx, handler, &P), CYC_OK);
  const int rc = e.call(ctx);
  const std::string where = std::string(e.name) + " (handler " + reentry_name(mode) + ")";
  if (rc == CYC_OK) {
    EXPECT_EQ(P.calls, 0) << where << ": the handler ran on success";
    EXPECT_EQ(cyc_context_last_status(ctx), CYC_OK) << where;
  } else {
    EXPECT_GE(P.calls, 1) << where << ": the handler was not called";
    EXPECT_EQ(P.status, rc) << where << ": the handler saw another status";
    EXPECT_EQ(cyc_context_last_status(ctx), rc) << where;
    EXPECT_EQ(std::string(cyc_context_last_error(ctx)), P.message) << where;
    EXPECT_NE(P.message.find(e.name), std::string::npos)
        << where << ": the message does not name the function: " << P.message;
    EXPECT_EQ(P.message_pointer, cyc_context_last_error(ctx)) << where;
    EXPECT_EQ(std::string(P.message_pointer), P.message)
        << where << ": the handler's message pointer no longer reads the call's message";
    switch (mode) {
      case Reentry::none: break;
      case Reentry::succeed: EXPECT_EQ(P.inner_status, CYC_OK) << where; break;
      case Reentry::fail_other: EXPECT_EQ(P.inner_status, CYC_E_DEGREE_TOO_HIGH) << where; break;
      case Reentry::repeat:
      case Reentry::nested: EXPECT_EQ(P.inner_status, rc) << where << ": not deterministic"; break;
    }
  }
  ASSERT_EQ(cyc_context_set_error_handler(ctx, nullptr, nullptr), CYC_OK);
}

void check_all(cyc_context* ctx) {
  size_t failing = 0;
  std::string succeeded;
  for (const Entry& e : entries()) {
    if (skipped(e.name)) continue;
    for (Reentry mode : {Reentry::none, Reentry::succeed, Reentry::fail_other, Reentry::repeat,
                         Reentry::nested})
      check_call(ctx, e, mode);
    if (e.call(ctx) != CYC_OK)
      ++failing;
    else
      succeeded += std::string(" ") + e.name;
  }
  // Zero arguments are an error almost everywhere (NULL outputs); the few
  // entry points that accept them are listed, for the reader.
  if (!succeeded.empty()) std::printf("accept all-zero arguments:%s\n", succeeded.c_str());
  EXPECT_GE(failing, entries().size() - 10);
}

TEST(Guard, ReentrantHandlersOnAHeapContext) {
  cyc_context* ctx = nullptr;
  ASSERT_EQ(cyc_context_create(nullptr, &ctx), CYC_OK);
  check_all(ctx);
  cyc_context_destroy(ctx);
}

TEST(Guard, ReentrantHandlersOnACallerMemoryContext) {
  StaticContext S;
  ASSERT_NE(S.ctx, nullptr);
  check_all(S.ctx);
}

// The reported case, spelled out: a failing call whose handler makes a
// successful call used to return CYC_OK.
TEST(Guard, FailingCallReturnsItsOwnStatusWhenTheHandlerSucceeds) {
  cyc_context* ctx = nullptr;
  ASSERT_EQ(cyc_context_create(nullptr, &ctx), CYC_OK);
  Probe P;
  P.ctx = ctx;
  P.mode = Reentry::succeed;
  ASSERT_EQ(cyc_context_set_error_handler(ctx, handler, &P), CYC_OK);
  const double coeffs[4] = {0, 0, 0, 1};
  cyc_curve* c = nullptr;
  EXPECT_EQ(cyc_curve_create_polynomial(ctx, 99, coeffs, 4, &c), CYC_E_DEGREE_TOO_HIGH);
  EXPECT_EQ(c, nullptr);
  EXPECT_EQ(P.inner_status, CYC_OK);
  EXPECT_EQ(cyc_context_last_status(ctx), CYC_E_DEGREE_TOO_HIGH);
  EXPECT_NE(std::string(cyc_context_last_error(ctx)).find("cyc_curve_create_polynomial"),
            std::string::npos);
  cyc_context_destroy(ctx);
}

}  // namespace

namespace {

// ------------------------------------------------------------ the rest of the ABI
// The entry points without a context first: what a hostile host passes.

TEST(Guard, ContextCreationRefusesBadArguments) {
  EXPECT_EQ(cyc_context_create(nullptr, nullptr), CYC_E_NULL_ARGUMENT);
  cyc_context* ctx = reinterpret_cast<cyc_context*>(uintptr_t(0x1234));
  const cyc_allocator no_functions = {nullptr, nullptr, nullptr};
  EXPECT_NE(cyc_context_create(&no_functions, &ctx), CYC_OK);
  EXPECT_EQ(ctx, reinterpret_cast<cyc_context*>(uintptr_t(0x1234)));  // untouched on error
  alignas(64) static unsigned char block[1 << 16];
  EXPECT_EQ(cyc_context_init_static(nullptr, sizeof block, nullptr, &ctx), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_context_init_static(block, sizeof block, nullptr, nullptr), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_context_init_static(block, 0, nullptr, &ctx), CYC_E_BUFFER_TOO_SMALL);
  EXPECT_EQ(cyc_context_init_static(block, sizeof block, &no_functions, &ctx),
            CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(ctx, reinterpret_cast<cyc_context*>(uintptr_t(0x1234)));
}

TEST(Guard, NullHandlesAndNullContextsAreHarmless) {
  cyc_context_destroy(nullptr);
  cyc_curve_destroy(nullptr, nullptr);
  cyc_surface_destroy(nullptr, nullptr);
  cyc_sphere_skin_destroy(nullptr, nullptr);
  cyc_bezier_export_destroy(nullptr);
  cyc_pn_surface_destroy(nullptr);
  EXPECT_EQ(cyc_bezier_export_count(nullptr), 0);
  EXPECT_NE(cyc_context_last_error(nullptr), nullptr);
  EXPECT_EQ(cyc_context_last_status(nullptr), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_context_static_remaining(nullptr), 0u);
  cyc_skin_end_sphere(nullptr, nullptr, nullptr);
  cyc_pcurve_blend_options_init(nullptr);
  cyc_ringed_field_options_init(nullptr);
  cyc_nway_options_init(nullptr);
  cyc_blend_objective_init(nullptr);
  cyc_optimize_options_init(nullptr);
  cyc_bump_objective_init(nullptr);
  cyc_bump_options_init(nullptr);
  cyc_implicit_approx_options_init(nullptr);
  cyc_skin_options_init(nullptr);
  cyc_skin_tangent_options_init(nullptr);
  cyc_cyclide_blend_objective_init(nullptr);
  cyc_cyclide_blend_options_init(nullptr);
  cyc_tessellation_options_default(nullptr);
  cyc_skin_export_options_default(nullptr);
}

TEST(Guard, StatusNamesAreNeverNull) {
  for (int s : {INT_MIN, -1, 0, 1, 100, 199, 300, 302, 999, 100000, INT_MAX}) {
    const char* name = cyc_status_name(s);
    ASSERT_NE(name, nullptr) << s;
    EXPECT_GT(std::strlen(name), 0u) << s;
  }
}

TEST(Guard, TauOfVKeepsItsRange) {
  const double inf = std::numeric_limits<double>::infinity();
  for (double v : {0.0, -0.0, 1.0, -1.0, 1e300, -1e300, inf, -inf, 4.9e-324}) {
    const double tau = cyc_export_tau_of_v(v);
    EXPECT_TRUE(tau >= -2 && tau <= 2) << v << " -> " << tau;
  }
  for (double tau : {-3.0, -2.0, -1.0, 0.0, 1.0, 2.0, 3.0, 1e300, -inf, inf}) {
    const double v = cyc_export_v_of_tau(tau);
    EXPECT_FALSE(std::isnan(v)) << tau;
  }
}

// The arguments a host may pass to a size query: everything an int holds.
const int kCounts[] = {INT_MIN, INT_MIN + 1, -1000000, -2, -1, 0,  1,  2,  3,  4,  5,
                       16,      1000,        65536,    1 << 20,        50000000,
                       50000001, 100000000,  100000001, 1 << 30,       INT_MAX / 2 + 1,
                       INT_MAX - 1, INT_MAX};

// A size query never returns a negative or wrapped value: over increasing
// arguments its results are 0 (not supported) or non-decreasing.
template <class F>
void check_monotone(const char* name, F&& f) {
  long double last = 0;
  for (int n : kCounts) {
    const long double r = static_cast<long double>(f(n));
    EXPECT_GE(r, 0.0L) << name << "(" << n << ")";
    if (r == 0) continue;
    EXPECT_GE(r, last) << name << "(" << n << ") wrapped: " << double(r) << " < " << double(last);
    last = r;
  }
}

TEST(Guard, SizeQueriesNeverNegativeNorWrapped) {
  check_monotone("cyc_tessellation_workspace_size", cyc_tessellation_workspace_size);
  check_monotone("cyc_sphere_skin_tessellation_workspace_size",
                 cyc_sphere_skin_tessellation_workspace_size);
  check_monotone("cyc_delaunay_workspace_size", cyc_delaunay_workspace_size);
  check_monotone("cyc_delaunay_max_triangles", cyc_delaunay_max_triangles);
  for (int ntri : kCounts) {
    check_monotone("cyc_powell_sabin_workspace_size",
                   [ntri](int n) { return cyc_powell_sabin_workspace_size(n, ntri); });
    check_monotone("cyc_design_workspace_size",
                   [ntri](int n) { return cyc_design_workspace_size(n, ntri); });
    check_monotone("cyc_design_max_patches",
                   [ntri](int n) { return cyc_design_max_patches(n, ntri); });
  }
  // In ntri (ntri = 0 asks the design to triangulate: not a smaller case).
  for (int n : kCounts) {
    check_monotone("cyc_powell_sabin_workspace_size",
                   [n](int ntri) { return cyc_powell_sabin_workspace_size(n, ntri); });
    check_monotone("cyc_design_workspace_size", [n](int ntri) {
      return ntri == 0 ? size_t(0) : cyc_design_workspace_size(n, ntri);
    });
  }
  // The reported cases.
  EXPECT_GE(cyc_delaunay_max_triangles(INT_MAX), 0);
  EXPECT_GE(cyc_design_max_patches(INT_MAX, 0), 0);
  EXPECT_GE(cyc_design_max_patches(200000000, 0), 0);
}

}  // namespace
