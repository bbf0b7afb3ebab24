// Fuzz target of the creation family of the C ABI: every cyc_curve_create_*
// entry point (random degrees including out-of-range ones, random doubles
// including NaN/Inf/huge/tiny, strides, NULL pointers), then cyc_prcs_create
// and cyc_prrs_create on random combinations with an optional cyc_mobius and
// random domains, optionally through a tracking (and failing) allocator.
//
// Oracles (fuzz_common.hpp check_call for every call on a context):
//  - every status is known and never CYC_E_INTERNAL; last status/message and
//    the error handler agree with it ("" after success, non-empty on error);
//  - on error the out handle is unchanged (prefilled with a sentinel);
//  - on success the handle is non-NULL, its degree/kind/domain are sane, and
//    it destroys cleanly; at the end no allocation is live (the tracking
//    allocator; LSan in the fuzz build);
//  - calls with a NULL context return CYC_E_NULL_ARGUMENT;
//  - curves: cyc_curve_eval is finite on OK, untouched on error, and exact
//    at u = 0 for polynomials, lines, points and line elements;
//  - surfaces: at the domain samples validated at creation (u0 + (u1 -
//    u0) k / 256), cyc_surface_circle (and cyc_surface_sphere for PRCS) must
//    succeed, and eval_grid on those circles gives finite points (outside
//    the known issue of fuzz_common.hpp).
//
// Input layout: see make_seeds.py (CreateEncoder), which mirrors this file.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "fuzz_common.hpp"

namespace {

using fz::Input;

cyc_curve* const kCurveSentinel = reinterpret_cast<cyc_curve*>(uintptr_t(0x5eed0c0ffee0ull));
cyc_surface* const kSurfaceSentinel =
    reinterpret_cast<cyc_surface*>(uintptr_t(0x5eed0bad0000ull));

constexpr int kDomainSamples = 257;  // the core's kDomainSamples (config.hpp)

enum CurveKindTag { kPolynomial, kRational, kBezier, kLine, kPoint, kLineElement, kHermite };

struct CurveEntry {
  cyc_curve* handle;
  CurveKindTag tag;
  int max_degree;  // degree bound implied by the inputs
  double c0[3];    // value at u = 0 (polynomial, line, point, line element)
  double c1[3];    // derivative at u = 0 (same)
  bool exact_at_zero;
};

struct State {
  explicit State(Input& input) : in(input) {}
  Input& in;
  cyc_context* ctx = nullptr;
  fz::HandlerLog log;
  fz::HandlerLog* logp = nullptr;
  std::vector<CurveEntry> curves;
  std::vector<cyc_surface*> surfaces;
};

// A degree or order: mostly in [0, max], sometimes out of range.
int pick_degree(Input& in, int max) {
  if (in.range(0, 3) != 3) return in.range(0, max);
  static constexpr int kBad[] = {-1, -2, 16, 17, 8, 100, INT32_MIN, INT32_MAX};
  const int d = kBad[in.range(0, 7)];
  return d == 8 ? max + 1 : d;
}

// A stride in doubles: mostly valid (>= min), sometimes too small or large.
size_t pick_stride(Input& in, int min) {
  switch (in.range(0, 3)) {
    case 0: return size_t(min);
    case 1: return size_t(in.range(min, min + 3));
    case 2: return size_t(in.range(0, min - 1));
    default: return size_t(in.range(min, 64));
  }
}

// Rows actually present in a caller array for a (maybe invalid) degree.
int rows_for(int degree, int max) { return std::min(std::max(degree, 0), max) + 1; }

// The calls returning a new curve share one check.
void finish_curve(State& st, const char* fn, int s, cyc_curve* out, bool out_given,
                  CurveEntry e) {
  fz::check_call(fn, st.ctx, s, st.logp);
  if (s != CYC_OK) {
    FZ_CHECK(out == kCurveSentinel, "%s failed with %s but wrote the out handle", fn,
             cyc_status_name(s));
    return;
  }
  FZ_CHECK(out_given, "%s: OK with a NULL out pointer", fn);
  FZ_CHECK(out != nullptr && out != kCurveSentinel, "%s: OK but handle %p", fn, (void*)out);
  int degree = -12345;
  const int sd = cyc_curve_degree(st.ctx, out, &degree);
  fz::check_call("cyc_curve_degree", st.ctx, sd, st.logp);
  FZ_CHECK(sd == CYC_OK, "cyc_curve_degree failed: %s", cyc_status_name(sd));
  FZ_CHECK(degree >= 0 && degree <= e.max_degree && degree <= CYC_MAX_CURVE_DEGREE,
           "%s: curve degree %d not in [0, %d]", fn, degree, e.max_degree);
  e.handle = out;
  st.curves.push_back(e);
}

void op_polynomial(State& st, bool rational) {
  Input& in = st.in;
  const int width = rational ? 4 : 3;
  const int degree = pick_degree(in, CYC_MAX_CURVE_DEGREE);
  const size_t stride = pick_stride(in, width);
  const bool null_coeffs = in.rarely(), null_out = in.rarely();
  const int style = in.range(0, 2);
  const int rows = rows_for(degree, CYC_MAX_CURVE_DEGREE);
  std::vector<double> c = fz::exact(size_t(rows - 1) * stride + size_t(width));
  for (int k = 0; k < rows; ++k) {
    in.fill(&c[size_t(k) * stride], size_t(width), style);
    if (rational && k == 0 && in.flag()) c[3] = 1.0;  // a usual weight
  }
  cyc_curve* out = kCurveSentinel;
  const char* fn = rational ? "cyc_curve_create_rational" : "cyc_curve_create_polynomial";
  FZ_LOG("%s degree %d stride %zu%s%s", fn, degree, stride, null_coeffs ? " coeffs=NULL" : "",
         null_out ? " out=NULL" : "");
  const int s = rational ? cyc_curve_create_rational(st.ctx, degree,
                                                     null_coeffs ? nullptr : c.data(),
                                                     stride, null_out ? nullptr : &out)
                         : cyc_curve_create_polynomial(st.ctx, degree,
                                                       null_coeffs ? nullptr : c.data(),
                                                       stride, null_out ? nullptr : &out);
  CurveEntry e{};
  e.tag = rational ? kRational : kPolynomial;
  e.max_degree = degree;
  e.exact_at_zero = !rational && degree >= 1;
  if (e.exact_at_zero)
    for (int j = 0; j < 3; ++j) {
      e.c0[j] = c[size_t(j)];
      e.c1[j] = c[stride + size_t(j)];
    }
  finish_curve(st, fn, s, out, !null_out, e);
}

void op_bezier(State& st) {
  Input& in = st.in;
  const int degree = pick_degree(in, CYC_MAX_CURVE_DEGREE);
  const size_t stride = pick_stride(in, 3);
  const bool null_ctrl = in.rarely(), null_out = in.rarely(), weighted = in.flag();
  const int style = in.range(0, 2);
  const int rows = rows_for(degree, CYC_MAX_CURVE_DEGREE);
  std::vector<double> c = fz::exact(size_t(rows - 1) * stride + 3);
  for (int k = 0; k < rows; ++k) in.fill(&c[size_t(k) * stride], 3, style);
  std::vector<double> w = fz::exact(size_t(rows));
  if (weighted) in.fill(w.data(), w.size(), style);
  double u[2];
  in.fill(u, 2, style);
  cyc_curve* out = kCurveSentinel;
  FZ_LOG("cyc_curve_create_bezier degree %d stride %zu weights %d [%g, %g]", degree, stride,
         int(weighted), u[0], u[1]);
  const int s = cyc_curve_create_bezier(st.ctx, degree, null_ctrl ? nullptr : c.data(),
                                        stride, weighted ? w.data() : nullptr, u[0], u[1],
                                        null_out ? nullptr : &out);
  CurveEntry e{};
  e.tag = kBezier;
  e.max_degree = degree;
  finish_curve(st, "cyc_curve_create_bezier", s, out, !null_out, e);
}

void op_hermite(State& st) {
  Input& in = st.in;
  const int order = pick_degree(in, CYC_MAX_HERMITE_ORDER);
  const bool null_start = in.rarely(), null_end = in.rarely(), null_out = in.rarely();
  const int style = in.range(0, 2);
  const size_t n = 3 * size_t(rows_for(order, CYC_MAX_HERMITE_ORDER));
  std::vector<double> a = fz::exact(n), b = fz::exact(n);
  in.fill(a.data(), n, style);
  in.fill(b.data(), n, style);
  double u[2];
  in.fill(u, 2, style);
  cyc_curve* out = kCurveSentinel;
  FZ_LOG("cyc_curve_create_hermite order %d [%g, %g]", order, u[0], u[1]);
  const int s = cyc_curve_create_hermite(st.ctx, order, u[0], u[1],
                                         null_start ? nullptr : a.data(),
                                         null_end ? nullptr : b.data(),
                                         null_out ? nullptr : &out);
  CurveEntry e{};
  e.tag = kHermite;
  e.max_degree = order >= 0 && order <= CYC_MAX_HERMITE_ORDER ? 2 * order + 1 : -1;
  finish_curve(st, "cyc_curve_create_hermite", s, out, !null_out, e);
}

// Line, point, line element: one or two 3-vectors.
void op_simple(State& st, CurveKindTag tag) {
  Input& in = st.in;
  const bool null_p = in.rarely(), null_d = in.rarely(), null_out = in.rarely();
  const int style = in.range(0, 2);
  std::vector<double> p = fz::exact(3), d = fz::exact(3);
  in.fill(p.data(), 3, style);
  if (tag != kPoint) in.fill(d.data(), 3, style);
  cyc_curve* out = kCurveSentinel;
  cyc_curve** outp = null_out ? nullptr : &out;
  const double* pp = null_p ? nullptr : p.data();
  const double* dp = null_d ? nullptr : d.data();
  int s;
  const char* fn;
  CurveEntry e{};
  e.tag = tag;
  e.exact_at_zero = true;
  for (int j = 0; j < 3; ++j) e.c0[j] = p[size_t(j)];
  if (tag == kLine) {
    fn = "cyc_curve_create_line";
    s = cyc_curve_create_line(st.ctx, pp, dp, outp);
    e.max_degree = 1;
    for (int j = 0; j < 3; ++j) e.c1[j] = d[size_t(j)];
  } else if (tag == kPoint) {
    fn = "cyc_curve_create_point";
    s = cyc_curve_create_point(st.ctx, pp, outp);
    e.max_degree = 0;
  } else {
    fn = "cyc_curve_create_line_element";
    s = cyc_curve_create_line_element(st.ctx, pp, dp, outp);
    e.max_degree = 0;  // the point; its tangent is separate (ERRATA)
  }
  FZ_LOG("%s (%g %g %g) (%g %g %g)", fn, p[0], p[1], p[2], d[0], d[1], d[2]);
  finish_curve(st, fn, s, out, !null_out, e);
}

// cyc_curve_eval on a pooled curve: finite on OK, untouched on error, exact
// at u = 0 for the kinds whose value and derivative there are inputs.
void op_curve_eval(State& st) {
  Input& in = st.in;
  if (st.curves.empty()) return;
  const CurveEntry& e = st.curves[size_t(in.range(0, int(st.curves.size()) - 1))];
  const double u = in.flag() ? 0.0 : in.wild();
  const int order = in.range(0, 3) == 0 ? in.range(-2, 10) : in.range(0, 2);
  const size_t need = order >= 0 ? 3 * size_t(order + 1) : 3;
  size_t capacity = need + size_t(in.range(0, 2));
  if (in.rarely()) --capacity;  // one double short
  std::vector<double> out = fz::exact(capacity + 1);  // +1: a guard after capacity
  fz::fill_sentinel(out.data(), out.size());
  FZ_LOG("cyc_curve_eval u = %.17g order %d capacity %zu", u, order, capacity);
  const int s = cyc_curve_eval(st.ctx, e.handle, u, order, out.data(), capacity);
  fz::check_call("cyc_curve_eval", st.ctx, s, st.logp);
  if (s != CYC_OK) {
    FZ_CHECK(fz::all_sentinel(out.data(), out.size()), "cyc_curve_eval: %s but wrote output",
             cyc_status_name(s));
    return;
  }
  FZ_CHECK(order >= 0 && order <= 8 && capacity >= need, "cyc_curve_eval OK: order %d cap %zu",
           order, capacity);
  for (size_t i = 0; i < need; ++i)
    FZ_CHECK(std::isfinite(out[i]), "cyc_curve_eval OK but out[%zu] = %g", i, out[i]);
  FZ_CHECK(fz::all_sentinel(out.data() + need, out.size() - need),
           "cyc_curve_eval wrote past 3*(order+1)");
  if (u == 0.0 && e.exact_at_zero && order >= 1) {
    for (int j = 0; j < 3; ++j) {
      FZ_CHECK(out[size_t(j)] == e.c0[j], "curve(0)[%d] = %.17g, input %.17g", j,
               out[size_t(j)], e.c0[j]);
      if (e.tag == kPolynomial || e.tag == kLine)
        FZ_CHECK(out[size_t(3 + j)] == e.c1[j], "curve'(0)[%d] = %.17g, input %.17g", j,
                 out[size_t(3 + j)], e.c1[j]);
      else
        FZ_CHECK(out[size_t(3 + j)] == 0.0, "constant curve'(0)[%d] = %.17g", j,
                 out[size_t(3 + j)]);
    }
  }
}

const cyc_curve* pick_curve(State& st) {
  if (st.curves.empty() || st.in.rarely()) return nullptr;
  return st.curves[size_t(st.in.range(0, int(st.curves.size()) - 1))].handle;
}

// A cyc_mobius: mostly absent; degrees in and out of range; the entries
// above the degree are NaN (the library must not read them).
bool pick_mobius(Input& in, cyc_mobius& m) {
  if (in.range(0, 2) != 0) return false;
  const int degree = in.range(0, 3) == 0 ? pick_degree(in, CYC_MAX_MOBIUS_DEGREE)
                                         : in.range(0, 2);
  const int style = in.range(0, 2);
  m.degree = degree;
  double* arr[4] = {m.alpha, m.beta, m.gamma, m.delta};
  const int rows = rows_for(degree, CYC_MAX_MOBIUS_DEGREE);
  for (double* a : arr) {
    for (int k = 0; k <= CYC_MAX_MOBIUS_DEGREE; ++k)
      a[k] = std::numeric_limits<double>::quiet_NaN();
    in.fill(a, size_t(rows), style);
  }
  return true;
}

double domain_sample(double u0, double u1, int k) {
  return u0 + (u1 - u0) * double(k) / double(kDomainSamples - 1);
}

// A new surface: kind and domain as created; at the validated domain samples
// the circle (and the sphere of a canal surface) exist, and the points of
// that circle evaluate without internal errors.
void check_new_surface(State& st, cyc_surface* S, int want_kind, double u0, double u1,
                       const cyc_mobius* f) {
  int kind = 0;
  int s = cyc_surface_kind(st.ctx, S, &kind);
  fz::check_call("cyc_surface_kind", st.ctx, s, st.logp);
  FZ_CHECK(s == CYC_OK && kind == want_kind, "kind %d, expected %d", kind, want_kind);
  double d0 = 0, d1 = 0;
  s = cyc_surface_domain(st.ctx, S, &d0, &d1);
  fz::check_call("cyc_surface_domain", st.ctx, s, st.logp);
  FZ_CHECK(s == CYC_OK && d0 == u0 && d1 == u1, "domain [%g, %g], created on [%g, %g]", d0,
           d1, u0, u1);
  const int k = st.in.flag() ? 0 : st.in.range(0, kDomainSamples - 1);
  const double u = domain_sample(u0, u1, k);
  cyc_circle c;
  s = cyc_surface_circle(st.ctx, S, u, &c);
  fz::check_call("cyc_surface_circle", st.ctx, s, st.logp);
  FZ_CHECK(s == CYC_OK, "circle at the validated sample u = %.17g (k = %d) failed: %s", u, k,
           cyc_context_last_error(st.ctx));
  FZ_CHECK(fz::finite3(c.center) && fz::finite3(c.normal) && std::isfinite(c.radius2) &&
               c.radius2 >= 0,
           "circle at u = %.17g not finite", u);
  if (want_kind == CYC_SURFACE_PRCS) {
    cyc_sphere sp;
    s = cyc_surface_sphere(st.ctx, S, u, &sp);
    fz::check_call("cyc_surface_sphere", st.ctx, s, st.logp);
    FZ_CHECK(s == CYC_OK, "sphere at the validated sample u = %.17g failed: %s", u,
             cyc_context_last_error(st.ctx));
    FZ_CHECK(fz::finite3(sp.center) && std::isfinite(sp.radius2) && sp.radius2 >= 0,
             "sphere at u = %.17g not finite", u);
  }
  // Points of the validated circle: eval_grid validates only the row, so a
  // failing point would surface as CYC_E_INTERNAL (caught by check_call).
  const double vs[4] = {0.0, st.in.wild(), st.in.moderate(), 1.0};
  for (double v : vs)  // fuzz_common.hpp kKnownIssueCircleQuadratic
    if (fz::known_issue_avoid(st.ctx, S, f, u, v, st.logp)) return;
  double pts[12];
  fz::fill_sentinel(pts, 12);
  const cyc_buffer3 P{pts, 4, 3}, none{nullptr, 0, 3};
  s = cyc_surface_eval_grid(st.ctx, S, &u, 1, vs, 4, P, none, none, none, nullptr);
  fz::check_call("cyc_surface_eval_grid", st.ctx, s, st.logp);
  if (s == CYC_OK) {
    for (int i = 0; i < 4; ++i)
      FZ_CHECK(fz::finite3(pts + 3 * i), "grid point %d at u = %.17g v = %.17g not finite", i,
               u, vs[i]);
  } else {
    FZ_CHECK(fz::all_sentinel(pts, 12), "eval_grid: %s but wrote points", cyc_status_name(s));
  }
}

void op_surface(State& st, bool prrs) {
  Input& in = st.in;
  const cyc_curve* p1 = pick_curve(st);
  const cyc_curve* p2 = pick_curve(st);
  const cyc_curve* p3 = prrs ? pick_curve(st) : nullptr;
  cyc_mobius m;
  const bool has_f = pick_mobius(in, m);
  const int style = in.range(0, 2);
  double u[2];
  in.fill(u, 2, style);
  const bool null_out = in.rarely();
  cyc_surface* out = kSurfaceSentinel;
  cyc_surface** outp = null_out ? nullptr : &out;
  const char* fn = prrs ? "cyc_prrs_create" : "cyc_prcs_create";
  FZ_LOG("%s %p %p %p f=%s [%.17g, %.17g]", fn, (const void*)p1, (const void*)p2,
         (const void*)p3, has_f ? "yes" : "NULL", u[0], u[1]);
  const int s = prrs ? cyc_prrs_create(st.ctx, p1, p2, p3, has_f ? &m : nullptr, u[0], u[1],
                                       outp)
                     : cyc_prcs_create(st.ctx, p1, p2, has_f ? &m : nullptr, u[0], u[1],
                                       outp);
  fz::check_call(fn, st.ctx, s, st.logp);
  if (s != CYC_OK) {
    FZ_CHECK(out == kSurfaceSentinel, "%s failed with %s but wrote the out handle", fn,
             cyc_status_name(s));
    return;
  }
  FZ_CHECK(!null_out && out != nullptr && out != kSurfaceSentinel, "%s OK, handle %p", fn,
           (void*)out);
  st.surfaces.push_back(out);
  check_new_surface(st, out, prrs ? CYC_SURFACE_PRRS : CYC_SURFACE_PRCS, u[0], u[1],
                    has_f ? &m : nullptr);
}

// Every entry point with ctx = NULL: CYC_E_NULL_ARGUMENT, outputs untouched.
void op_null_context(State& st) {
  FZ_LOG("NULL context calls");
  const double p[3] = {0, 0, 0}, d[3] = {1, 0, 0};
  cyc_curve* c = kCurveSentinel;
  cyc_surface* S = kSurfaceSentinel;
  const cyc_curve* any = st.curves.empty() ? nullptr : st.curves[0].handle;
  int r[8];
  r[0] = cyc_curve_create_line(nullptr, p, d, &c);
  r[1] = cyc_curve_create_point(nullptr, p, &c);
  r[2] = cyc_curve_create_polynomial(nullptr, 1, p, 3, &c);
  r[3] = cyc_prcs_create(nullptr, any, any, nullptr, 0, 1, &S);
  r[4] = cyc_prrs_create(nullptr, any, any, any, nullptr, 0, 1, &S);
  int deg = -7;
  r[5] = cyc_curve_degree(nullptr, any, &deg);
  r[6] = cyc_context_set_error_handler(nullptr, nullptr, nullptr);
  r[7] = cyc_context_last_status(nullptr);
  for (int i = 0; i < 8; ++i)
    FZ_CHECK(r[i] == CYC_E_NULL_ARGUMENT, "NULL context call %d returned %s", i,
             cyc_status_name(r[i]));
  FZ_CHECK(c == kCurveSentinel && S == kSurfaceSentinel && deg == -7,
           "NULL context call wrote an output");
  FZ_CHECK(cyc_context_last_error(nullptr) != nullptr, "last_error(NULL) is NULL");
  cyc_curve_destroy(st.ctx, nullptr);
  cyc_surface_destroy(st.ctx, nullptr);
}

void op_destroy(State& st) {
  Input& in = st.in;
  if (in.flag()) {
    if (st.curves.empty()) return;
    const size_t i = size_t(in.range(0, int(st.curves.size()) - 1));
    FZ_LOG("cyc_curve_destroy #%zu", i);
    cyc_curve_destroy(in.flag() ? st.ctx : nullptr, st.curves[i].handle);
    st.curves.erase(st.curves.begin() + long(i));
  } else {
    if (st.surfaces.empty()) return;
    const size_t i = size_t(in.range(0, int(st.surfaces.size()) - 1));
    FZ_LOG("cyc_surface_destroy #%zu", i);
    cyc_surface_destroy(in.flag() ? st.ctx : nullptr, st.surfaces[i]);
    st.surfaces.erase(st.surfaces.begin() + long(i));
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fz::choose_reentry(data, size);
  Input in(data, size);
  fz::Tracker tracker;
  const int alloc_mode = in.range(0, 2);  // 0 default, 1 tracking, 2 tracking + failure
  if (alloc_mode == 2) {
    tracker.fail_at = in.range(0, 15);
    tracker.fail_after = in.flag();
  }
  cyc_allocator a = tracker.allocator();
  cyc_context* ctx = reinterpret_cast<cyc_context*>(uintptr_t(0x5eedc0de0000ull));
  const int sc = cyc_context_create(alloc_mode ? &a : nullptr, &ctx);
  FZ_LOG("cyc_context_create (allocator mode %d) -> %s", alloc_mode, cyc_status_name(sc));
  FZ_CHECK(sc == CYC_OK || sc == CYC_E_OUT_OF_MEMORY, "cyc_context_create: %s",
           cyc_status_name(sc));
  if (sc != CYC_OK) {
    FZ_CHECK(alloc_mode == 2 && ctx == reinterpret_cast<cyc_context*>(uintptr_t(0x5eedc0de0000ull)),
             "context creation failed without an allocator failure, or wrote *out");
    FZ_CHECK(tracker.live.empty(), "failed context creation leaked");
    return 0;
  }
  FZ_CHECK(ctx != nullptr, "context is NULL");
  FZ_CHECK(cyc_context_last_status(ctx) == CYC_OK && cyc_context_last_error(ctx)[0] == 0,
           "a new context has an error recorded");

  State st(in);
  st.ctx = ctx;
  if (in.flag()) {
    const int s = fz::install_handler(ctx, st.log);
    fz::check_call("cyc_context_set_error_handler", ctx, s, nullptr);
    FZ_CHECK(s == CYC_OK, "set_error_handler failed");
    st.logp = &st.log;
  }

  const int nops = in.range(1, 16);
  for (int i = 0; i < nops; ++i) {
    switch (in.range(0, 12)) {
      case 0: op_polynomial(st, false); break;
      case 1: op_polynomial(st, true); break;
      case 2: op_bezier(st); break;
      case 3: op_simple(st, kLine); break;
      case 4: op_simple(st, kPoint); break;
      case 5: op_simple(st, kLineElement); break;
      case 6: op_hermite(st); break;
      case 7: op_surface(st, false); break;
      case 8: op_surface(st, true); break;
      case 9: op_curve_eval(st); break;
      case 10: op_destroy(st); break;
      case 11: op_null_context(st); break;
      default: op_surface(st, st.curves.size() >= 3 && in.flag()); break;
    }
  }

  // Tear down in a fuzzed order: handles may outlive their context.
  const bool context_first = in.flag();
  if (context_first) cyc_context_destroy(ctx);
  cyc_context* hctx = context_first ? nullptr : ctx;
  for (cyc_surface* S : st.surfaces) cyc_surface_destroy(hctx, S);
  for (const CurveEntry& e : st.curves) cyc_curve_destroy(hctx, e.handle);
  if (!context_first) cyc_context_destroy(ctx);
  if (alloc_mode) FZ_CHECK(tracker.live.empty(), "%zu allocations leaked", tracker.live.size());
  return 0;
}
