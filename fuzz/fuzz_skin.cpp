// Fuzz target of seed 002's sphere skins through the C ABI (SPEC.md §9):
// ends raw, from an apex (cyc_skin_end_from_apex) or from a sphere
// (cyc_skin_end_from_sphere), with moderate or wild numbers (NaN, Inf,
// 1e300, denormals, zero radius or tangent); options (pairing and method
// valid or not, tolerance default, 1e-6..1e-14, 0, wild, 1e-300 or NaN,
// fuzzed reference and e); single skins and chains of n = -1..6 ends; then
// evaluation, grids, twist, lambda and info with fuzzed patch, theta and t,
// NULL pointers, a NULL context, destruction in a fuzzed order and a
// tracking allocator that can fail the n-th allocation; rarely a static
// context (cyc_context_init_static, SPEC 2a) in a fuzzed block with the
// tracker or nothing as its fallback. Issue 9: the skins' rational Bezier
// export (op_export) and their adaptive tessellation (op_tessellate), with
// the oracles written above those functions.
//
// Oracles:
//  - every status is known, never CYC_E_INTERNAL; last status/message and
//    the error handler agree with it (fz::check_call);
//  - the validation statuses in their order: NULL pointers
//    CYC_E_NULL_ARGUMENT, unknown pairing/method, n < 2 and a patch out of
//    range CYC_E_INVALID_ARGUMENT, non-finite theta/t CYC_E_NOT_FINITE, t
//    outside [0, 1] CYC_E_BAD_DOMAIN; CYC_E_NOT_FINITE from creation only
//    with a non-finite or beyond-1e100 input, and then always (unless
//    out of memory);
//  - on error every output is untouched (sentinels: handles, *bad_patch
//    unless a patch failed, points, info, twist, lambda);
//  - on OK every number written is finite; the patch count is 1 or n - 1;
//    lambda(theta, 0) = r_i and lambda(theta, 1) = r_f exactly; info
//    echoes the options and the start (spine c0 = p_i, c1 = t_i), kappa r <
//    1 - 1e-12 at both ends, substeps a power of two in 2..256, the error
//    estimate within the tolerance; a grid equals single evaluations bit
//    for bit and fails exactly when one of them fails with its status;
//    repeated calls give the same bits;
//  - for moderate inputs: s(theta, 0) lies on the start circle and
//    s(theta, 1) on the end circle (|x - p| = r, (x - p) . t = 0, to 1e-9
//    of the data's scale); normals are unit and orthogonal to both partials
//    (1e-9, judged where the partials are not nearly parallel); ends from
//    a sphere give that sphere back (cyc_skin_end_sphere);
//  - handles destroy cleanly (also after their context) and nothing leaks.
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "fuzz_common.hpp"

namespace {

using fz::Input;

cyc_sphere_skin* const kSentinel = reinterpret_cast<cyc_sphere_skin*>(uintptr_t(0x5eed0bad0000ull));
constexpr int kBadSentinel = -777;
constexpr double kPi = 3.14159265358979323846;

struct Skin {
  cyc_sphere_skin* h = nullptr;
  int count = 0;
  std::vector<cyc_skin_end> ends;  // count + 1
  bool moderate = false;           // every end from moderate numbers, options not wild
  cyc_skin_options opt;            // as passed (defaults for NULL)
};

struct State {
  explicit State(Input& i) : in(i) {}
  Input& in;
  cyc_context* ctx = nullptr;
  fz::HandlerLog log;
  fz::HandlerLog* logp = nullptr;
  std::vector<Skin> skins;
  // Patch constructions left (a chain builds each patch twice): one costs
  // up to ~0.1 s without sanitizers when the RMF tolerance is not met (8
  // tables of up to 256 x 256 RK4 steps); valid calls beyond are skipped
  // (their bytes are still read).
  int budget = 12;
  bool spend(int cost) {
    if (cost > budget) {
      FZ_LOG("  (skipped: %d patch constructions left, %d needed)", budget, cost);
      return false;
    }
    budget -= cost;
    return true;
  }
  void check(const char* fn, int s) { fz::check_call(fn, ctx, s, logp); }
};

// |v| <= 1e100 and finite: the library's input range.
bool in_range(double v) { return std::isfinite(v) && std::abs(v) <= 1e100; }
bool in_range3(const double* v) { return in_range(v[0]) && in_range(v[1]) && in_range(v[2]); }
bool end_in_range(const cyc_skin_end& e) {
  return in_range3(e.center) && in_range(e.radius) && in_range3(e.tangent) && in_range(e.inv_c);
}
bool same_bits(const void* a, const void* b, size_t n) { return std::memcmp(a, b, n) == 0; }

// ------------------------------------------------------------ ends

void log_end(const char* what, const cyc_skin_end& e) {
  FZ_LOG("    %s: center (%a, %a, %a) radius %a tangent (%a, %a, %a) inv_c %a", what,
         e.center[0], e.center[1], e.center[2], e.radius, e.tangent[0], e.tangent[1],
         e.tangent[2], e.inv_c);
}

struct End {
  cyc_skin_end e;
  bool moderate = false;
};

// Values by style: 0 wild, 1 moderate, 2 mixed.
void values(Input& in, double* v, int n, int style) { in.fill(v, size_t(n), style); }

End make_end(State& st) {
  Input& in = st.in;
  End out;
  cyc_skin_end& e = out.e;
  std::memset(&e, 0, sizeof e);
  const int kind = in.range(0, 3);
  if (kind == 3) {
    // A sphere (m, R), a direction of length L, the circle at h = frac R.
    double m[3], d[3];
    values(in, m, 3, 1);
    const double R = in.range(1, 64) / 16.0;
    values(in, d, 3, 1);
    const double L = in.range(1, 40) / 4.0;
    const double frac = in.range(-15, 15) / 16.0;
    const double len = fz::norm3(d);
    double t[3] = {L, 0, 0}, p[3];
    if (len > 0)
      for (int k = 0; k < 3; ++k) t[k] = d[k] / len * L;
    for (int k = 0; k < 3; ++k) p[k] = m[k] - frac * R * t[k] / L;
    cyc_skin_end r;
    std::memset(&r, 0x5a, sizeof r);
    const int s = cyc_skin_end_from_sphere(st.ctx, m, R, p, t, &r);
    st.check("cyc_skin_end_from_sphere", s);
    if (s == CYC_OK) {
      e = r;
      out.moderate = true;
    } else {
      // The tangent fails the 1e-9 parallel test only by rounding: a raw end.
      std::memcpy(e.center, p, sizeof p);
      e.radius = R;
      std::memcpy(e.tangent, t, sizeof t);
    }
    return out;
  }
  const int style = in.range(0, 2);
  double v[8];
  values(in, v, 8, style);
  std::memcpy(e.center, v, 3 * sizeof(double));
  e.radius = v[3];
  std::memcpy(e.tangent, v + 4, 3 * sizeof(double));
  e.inv_c = v[7];
  if (kind == 0) {
    out.moderate = style == 1;
    return out;
  }
  double x[3];
  const bool raw_point = in.flag();
  if (raw_point) {
    values(in, x, 3, style);
  } else {
    double c[1];
    values(in, c, 1, style);
    for (int k = 0; k < 3; ++k)
      x[k] = kind == 1 ? e.center[k] + c[0] * e.tangent[k] : e.center[k] - c[0] * e.tangent[k];
  }
  const int nulls = in.rarely() ? in.range(0, 3) : -1;
  cyc_skin_end r;
  std::memset(&r, 0x5a, sizeof r);
  cyc_skin_end keep = r;
  int s;
  const char* fn;
  bool bad_input;
  if (kind == 1) {
    // apex x; the circle (center, radius, tangent).
    fn = "cyc_skin_end_from_apex";
    s = cyc_skin_end_from_apex(st.ctx, nulls == 0 ? nullptr : e.center, e.radius,
                               nulls == 1 ? nullptr : e.tangent, nulls == 2 ? nullptr : x,
                               nulls == 3 ? nullptr : &r);
    bad_input = !in_range3(e.center) || !in_range(e.radius) || !in_range3(e.tangent) ||
                !in_range3(x);
  } else {
    // The sphere (x, radius) and the circle's center and tangent.
    fn = "cyc_skin_end_from_sphere";
    s = cyc_skin_end_from_sphere(st.ctx, nulls == 0 ? nullptr : x, e.radius,
                                 nulls == 1 ? nullptr : e.center, nulls == 2 ? nullptr : e.tangent,
                                 nulls == 3 ? nullptr : &r);
    bad_input = !in_range3(e.center) || !in_range(e.radius) || !in_range3(e.tangent) ||
                !in_range3(x);
  }
  st.check(fn, s);
  if (nulls >= 0) {
    FZ_CHECK(s == CYC_E_NULL_ARGUMENT, "%s: NULL argument %d gave %s", fn, nulls,
             cyc_status_name(s));
  } else {
    FZ_CHECK((s == CYC_E_NOT_FINITE) == bad_input, "%s: %s with bad_input %d", fn,
             cyc_status_name(s), int(bad_input));
    FZ_CHECK(s == CYC_OK || s == CYC_E_NOT_FINITE || s == CYC_E_INVALID_ARGUMENT ||
                 s == CYC_E_ZERO_TANGENT,
             "%s: undocumented %s", fn, cyc_status_name(s));
  }
  if (s != CYC_OK) {
    FZ_CHECK(same_bits(&r, &keep, sizeof r), "%s wrote on error", fn);
    out.moderate = style == 1;  // the raw end
    return out;
  }
  FZ_CHECK(same_bits(r.center, e.center, sizeof r.center) &&
               same_bits(r.tangent, e.tangent, sizeof r.tangent),
           "%s: center or tangent changed", fn);
  FZ_CHECK(std::isfinite(r.inv_c) && std::isfinite(r.radius) && r.radius > 0,
           "%s: OK with radius %g inv_c %g", fn, r.radius, r.inv_c);
  if (kind == 1)
    FZ_CHECK(same_bits(&r.radius, &e.radius, sizeof r.radius), "%s: radius changed", fn);
  if (kind == 2 && style == 1) {
    // The sphere back.
    double m[3], R = -1;
    cyc_skin_end_sphere(&r, m, &R);
    const double scale =
        std::max({fz::norm3(x), e.radius, fz::norm3(e.center), 1e-300});
    // (center - x may leave the axis by 1e-9 of max(|center - x|, R).)
    FZ_CHECK(fz::dist3(m, x) <= 3e-9 * scale && std::abs(R - e.radius) <= 1e-9 * scale,
             "%s: the sphere back is (%g %g %g; %g), not (%g %g %g; %g)", fn, m[0], m[1], m[2],
             R, x[0], x[1], x[2], e.radius);
  }
  e = r;
  return out;
}

End make_logged_end(State& st) {
  const End e = make_end(st);
  log_end(e.moderate ? "end (moderate)" : "end", e.e);
  return e;
}

// ------------------------------------------------------------ options

struct Options {
  cyc_skin_options o;
  bool null = false;
  bool valid_enums = true;
  bool bad_input = false;  // a non-finite or beyond-1e100 number
  bool wild = false;
};

Options make_options(Input& in) {
  Options r;
  cyc_skin_options_init(&r.o);
  const int mode = in.range(0, 3);
  if (mode == 0) {
    r.null = true;
    return r;
  }
  if (mode == 1) return r;
  if (mode == 3) {
    r.o.pairing = in.range(0, 2);
    r.o.method = in.range(0, 1);
    return r;
  }
  switch (in.range(0, 5)) {
    case 0: r.o.pairing = in.range(-1, 3); break;
    case 1: r.o.pairing = in.flag() ? INT_MIN : INT_MAX; break;
    default: r.o.pairing = in.range(0, 2);
  }
  switch (in.range(0, 4)) {
    case 0: r.o.method = in.range(-1, 2); break;
    case 1: r.o.method = in.flag() ? INT_MIN : INT_MAX; break;
    default: r.o.method = in.range(0, 1);
  }
  switch (in.range(0, 5)) {
    case 0: break;
    case 1: r.o.tolerance = std::pow(10.0, -double(in.range(6, 14))); break;
    case 2: r.o.tolerance = 0.0; break;
    case 3: r.o.tolerance = in.wild(); r.wild = true; break;
    case 4: r.o.tolerance = 1e-300; break;
    default: r.o.tolerance = std::numeric_limits<double>::quiet_NaN();
  }
  if (in.flag()) {
    const int style = in.range(0, 2);
    values(in, r.o.reference, 3, style);
    r.wild |= style != 1;
  }
  if (in.flag()) {
    const int style = in.range(0, 2);
    values(in, r.o.e, 3, style);
    r.wild |= style != 1;
  }
  r.valid_enums = r.o.pairing >= 0 && r.o.pairing <= 2 && r.o.method >= 0 && r.o.method <= 1;
  r.bad_input = !std::isfinite(r.o.tolerance) || !in_range3(r.o.reference) || !in_range3(r.o.e);
  return r;
}

// ------------------------------------------------------------ creation

// What a creation may return once the arguments are valid pointers and the
// enums known.
bool creation_status(int s) {
  return s == CYC_OK || s == CYC_E_INVALID_ARGUMENT || s == CYC_E_NOT_FINITE ||
         s == CYC_E_ZERO_TANGENT || s == CYC_E_PARALLEL_LINES || s == CYC_E_NESTED_SPHERES ||
         s == CYC_E_CURVATURE_RADIUS_TOO_LARGE || s == CYC_E_NUMERICAL_OVERFLOW ||
         s == CYC_E_OUT_OF_MEMORY;
}

void record(State& st, cyc_sphere_skin* h, int expected_count, const cyc_skin_end* ends,
            const Options& o, bool moderate) {
  int count = -1;
  const int s = cyc_sphere_skin_patch_count(st.ctx, h, &count);
  st.check("cyc_sphere_skin_patch_count", s);
  FZ_CHECK(s == CYC_OK && count == expected_count, "patch count %d, expected %d", count,
           expected_count);
  Skin k;
  k.h = h;
  k.count = count;
  k.ends.assign(ends, ends + count + 1);
  k.moderate = moderate && !o.wild;
  k.opt = o.o;
  st.skins.push_back(k);
}

void op_create(State& st) {
  Input& in = st.in;
  const End a = make_logged_end(st), b = make_logged_end(st);
  const Options o = make_options(in);
  const int nulls = in.rarely() ? in.range(0, 2) : -1;
  if (!st.spend(1)) return;
  cyc_sphere_skin* h = kSentinel;
  const int s = cyc_sphere_skin_create(st.ctx, nulls == 0 ? nullptr : &a.e,
                                       nulls == 1 ? nullptr : &b.e, o.null ? nullptr : &o.o,
                                       nulls == 2 ? nullptr : &h);
  st.check("cyc_sphere_skin_create", s);
  const bool bad_input = !end_in_range(a.e) || !end_in_range(b.e) || (!o.null && o.bad_input);
  if (nulls >= 0) {
    FZ_CHECK(s == CYC_E_NULL_ARGUMENT, "create: NULL %d gave %s", nulls, cyc_status_name(s));
  } else if (!o.null && !o.valid_enums) {  // (a number beyond 1e100 may be named first)
    FZ_CHECK(s == CYC_E_INVALID_ARGUMENT || s == CYC_E_NOT_FINITE,
             "create: pairing %d method %d gave %s", o.o.pairing, o.o.method,
             cyc_status_name(s));
  } else {
    FZ_CHECK(creation_status(s), "create: undocumented %s", cyc_status_name(s));
    if (s != CYC_E_OUT_OF_MEMORY)
      FZ_CHECK((s == CYC_E_NOT_FINITE) == bad_input, "create: %s with bad_input %d: %s",
               cyc_status_name(s), int(bad_input), cyc_context_last_error(st.ctx));
  }
  if (s != CYC_OK) {
    FZ_CHECK(h == kSentinel, "cyc_sphere_skin_create wrote *out on error");
    return;
  }
  FZ_CHECK(h != nullptr && h != kSentinel, "create: OK without a handle");
  const cyc_skin_end ends[2] = {a.e, b.e};
  record(st, h, 1, ends, o, a.moderate && b.moderate);
}

// cyc_optimize_skin_tangents (seed 002 Remark 2; optimizer tier): fuzzed
// ends, skin options and tangent options (mostly the defaults; rarely 0,
// 1, negative, huge or wild). Oracles: known statuses (UNSUPPORTED exactly
// without Ceres), nothing written on error, and on OK finite ends with
// the same centers, radii and tangent directions, kappa r < 1 reported,
// and a skin that cyc_sphere_skin_create accepts (up to a failing
// allocator).
void op_tangents(State& st) {
  Input& in = st.in;
  const End a = make_logged_end(st), b = make_logged_end(st);
  const Options o = make_options(in);
  cyc_skin_tangent_options t;
  cyc_skin_tangent_options_init(&t);
  bool bad_options = false;
  for (double* x : {&t.target, &t.min_ratio, &t.max_ratio}) {
    if (!in.rarely()) continue;
    switch (in.range(0, 4)) {
      case 0: *x = 0.0; break;
      case 1: *x = 1.0; break;
      case 2: *x = -in.range(1, 16) / 8.0; break;
      case 3: *x = in.range(1, 64) / 8.0; break;
      default: *x = in.wild(); break;
    }
  }
  if (in.rarely()) t.max_iterations = in.flag() ? -1 : in.range(0, 3);
  bad_options = !(t.target > 0 && t.target < 1) || !(t.min_ratio > 0 && t.min_ratio <= 1) ||
                !(t.max_ratio >= 1) || t.max_iterations < 0 || !std::isfinite(t.max_ratio);
  const bool null_opt = in.rarely();
  if (!st.spend(2)) return;
  cyc_skin_end out[2];
  cyc_skin_tangent_summary sum;
  fz::fill_sentinel(reinterpret_cast<double*>(out), sizeof out / (sizeof(double)));
  std::memset(&sum, 0xA5, sizeof sum);
  const cyc_skin_tangent_summary blank = sum;
  const int s = cyc_optimize_skin_tangents(st.ctx, &a.e, &b.e, o.null ? nullptr : &o.o,
                                           null_opt ? nullptr : &t, &out[0], &out[1], &sum);
  st.check("cyc_optimize_skin_tangents", s);
  if (!cyc_optimizer_available()) {
    FZ_CHECK(s == CYC_E_UNSUPPORTED, "tangents without Ceres: %s", cyc_status_name(s));
    return;
  }
  if (!o.null && !o.valid_enums) {
    FZ_CHECK(s == CYC_E_INVALID_ARGUMENT, "tangents: bad enums gave %s", cyc_status_name(s));
  } else if (!null_opt && bad_options) {
    FZ_CHECK(s == CYC_E_INVALID_ARGUMENT || s == CYC_E_NOT_FINITE, "tangents: bad options gave %s",
             cyc_status_name(s));
  } else {
    FZ_CHECK(creation_status(s) && s != CYC_E_OUT_OF_MEMORY, "tangents: undocumented %s",
             cyc_status_name(s));
  }
  if (s != CYC_OK) {
    FZ_CHECK(fz::all_sentinel(reinterpret_cast<double*>(out), sizeof out / (sizeof(double))) &&
                 std::memcmp(&sum, &blank, sizeof sum) == 0,
             "tangents wrote on error");
    return;
  }
  const cyc_skin_end* in_ends[2] = {&a.e, &b.e};
  for (int e = 0; e < 2; ++e) {
    const cyc_skin_end &i0 = *in_ends[e], &o0 = out[e];
    FZ_CHECK(std::memcmp(i0.center, o0.center, sizeof i0.center) == 0 && i0.radius == o0.radius,
             "tangents: end %d moved its circle", e);
    FZ_CHECK(fz::finite3(o0.tangent) && std::isfinite(o0.inv_c), "tangents: end %d not finite", e);
    FZ_CHECK(sum.scale[e] > 0 && std::isfinite(sum.scale[e]) && sum.kappa_r[e] < 1,
             "tangents: end %d scale %g kappa r %g", e, sum.scale[e], sum.kappa_r[e]);
  }
  cyc_sphere_skin* h = nullptr;
  const int c = cyc_sphere_skin_create(st.ctx, &out[0], &out[1], o.null ? nullptr : &o.o, &h);
  st.check("cyc_sphere_skin_create", c);
  FZ_CHECK(c == CYC_OK || c == CYC_E_OUT_OF_MEMORY, "tangents OK but the skin gives %s",
           cyc_status_name(c));
  if (c == CYC_OK) cyc_sphere_skin_destroy(st.ctx, h);
}

void op_chain(State& st) {
  Input& in = st.in;
  const int n = in.range(-1, 6);
  std::vector<cyc_skin_end> ends(size_t(std::max(n, 1)));
  bool moderate = true, bad_input = false;
  for (int i = 0; i < n; ++i) {
    const End e = make_logged_end(st);
    ends[size_t(i)] = e.e;
    moderate &= e.moderate;
    bad_input |= !end_in_range(e.e);
  }
  const Options o = make_options(in);
  const bool null_ends = in.rarely(), null_out = in.rarely(), with_bad = in.flag();
  if (!st.spend(2 * std::max(n - 1, 0))) return;
  cyc_sphere_skin* h = kSentinel;
  int bad = kBadSentinel;
  const int s = cyc_sphere_skin_chain_create(st.ctx, null_ends ? nullptr : ends.data(), n,
                                             o.null ? nullptr : &o.o, null_out ? nullptr : &h,
                                             with_bad ? &bad : nullptr);
  st.check("cyc_sphere_skin_chain_create", s);
  bad_input |= !o.null && o.bad_input;
  bool validation = true;  // a status before any patch is built
  if (null_ends || null_out) {
    FZ_CHECK(s == CYC_E_NULL_ARGUMENT, "chain: NULL gave %s", cyc_status_name(s));
  } else if (n < 2 || (!o.null && !o.valid_enums)) {
    FZ_CHECK(s == CYC_E_INVALID_ARGUMENT, "chain: n %d, pairing %d, method %d gave %s", n,
             o.o.pairing, o.o.method, cyc_status_name(s));
  } else {
    validation = false;
    FZ_CHECK(creation_status(s), "chain: undocumented %s", cyc_status_name(s));
    // NOT_FINITE for a bad input in the first failing patch only; an OK
    // chain never has one.
    if (s == CYC_OK) FZ_CHECK(!bad_input, "chain: OK with a non-finite input");
    if (s == CYC_E_NOT_FINITE) FZ_CHECK(bad_input, "chain: NOT_FINITE without a bad input");
  }
  if (s != CYC_OK) {
    FZ_CHECK(h == kSentinel, "chain wrote *out on error");
    if (validation || s == CYC_E_OUT_OF_MEMORY || !with_bad) {
      FZ_CHECK(bad == kBadSentinel, "chain wrote *bad_patch = %d on %s", bad, cyc_status_name(s));
    } else if ((s == CYC_E_NOT_FINITE || s == CYC_E_INVALID_ARGUMENT) && bad == kBadSentinel) {
      // Refused by the validation of every end and option before any patch
      // is built (the message names the field): no patch failed.
    } else {
      FZ_CHECK(bad >= 0 && bad <= n - 2, "chain: bad_patch %d of %d ends", bad, n);
      if (s == CYC_E_NOT_FINITE)
        FZ_CHECK(!end_in_range(ends[size_t(bad)]) || !end_in_range(ends[size_t(bad) + 1]) ||
                     (!o.null && o.bad_input),
                 "chain: patch %d NOT_FINITE with finite ends", bad);
    }
    return;
  }
  FZ_CHECK(bad == kBadSentinel, "chain wrote *bad_patch on OK");
  record(st, h, n - 1, ends.data(), o, moderate);
}

// ------------------------------------------------------------ queries

Skin* pick(State& st) {
  const int i = st.in.range(0, 7);
  if (st.skins.empty() || i == 7) return nullptr;
  return &st.skins[size_t(i) % st.skins.size()];
}

int patch_of(Input& in) {
  const int p = in.range(-2, 8);
  return p == -2 ? INT_MIN : p == 8 ? INT_MAX : p;
}

double theta_of(Input& in) {
  switch (in.range(0, 3)) {
    case 0: return in.moderate();
    case 1: return in.wild();
    case 2: return in.range(-16, 16) * 0.39269908169872414;
    default: return 0.0;
  }
}

double t_of(Input& in) {
  switch (in.range(0, 4)) {
    case 0: return in.range(0, 16) / 16.0;
    case 1: return in.flag() ? 1.0 : 0.0;
    case 2: return in.moderate();
    case 3: return in.wild();
    default: return in.flag() ? std::nextafter(1.0, 2.0) : -std::numeric_limits<double>::denorm_min();
  }
}

// The status the validation of (skin, patch, theta, t) gives, or CYC_OK.
int expected(const Skin* k, int patch, double theta, double t, bool with_t = true) {
  if (!k) return CYC_E_NULL_ARGUMENT;
  if (patch < 0 || patch >= k->count) return CYC_E_INVALID_ARGUMENT;
  if (!std::isfinite(theta) || (with_t && !std::isfinite(t))) return CYC_E_NOT_FINITE;
  if (with_t && !(t >= 0.0 && t <= 1.0)) return CYC_E_BAD_DOMAIN;
  return CYC_OK;
}

double scale_of(const Skin& k, int patch) {
  const cyc_skin_end& a = k.ends[size_t(patch)];
  const cyc_skin_end& b = k.ends[size_t(patch) + 1];
  return std::max({fz::norm3(a.center), fz::norm3(b.center), fz::norm3(a.tangent),
                   fz::norm3(b.tangent), a.radius, b.radius, 1e-300});
}

// The circle oracles at t = 0 and t = 1 and the normal oracles (moderate).
void geometry(const Skin& k, int patch, double t, const double* x, const double* xa,
              const double* xb, const double* n) {
  if (!k.moderate) return;
  const double scale = scale_of(k, patch);
  if (x && (t == 0.0 || t == 1.0)) {
    const cyc_skin_end& e = k.ends[size_t(patch) + (t == 1.0 ? 1 : 0)];
    const double d[3] = {x[0] - e.center[0], x[1] - e.center[1], x[2] - e.center[2]};
    const double r = fz::norm3(d), along = fz::dot3(d, e.tangent) / fz::norm3(e.tangent);
    FZ_CHECK(std::abs(r - e.radius) <= 1e-9 * scale && std::abs(along) <= 1e-9 * scale,
             "s(theta, %g) is off its circle: |x - p| = %.17g, r = %.17g, (x - p).t^ = %g "
             "(scale %g)",
             t, r, e.radius, along, scale);
  }
  if (n) {
    FZ_CHECK(std::abs(fz::norm3(n) - 1.0) <= 1e-9, "normal not unit: %.17g", fz::norm3(n));
    if (xa && xb) {
      const double la = fz::norm3(xa), lb = fz::norm3(xb);
      const double c[3] = {xa[1] * xb[2] - xa[2] * xb[1], xa[2] * xb[0] - xa[0] * xb[2],
                           xa[0] * xb[1] - xa[1] * xb[0]};
      if (fz::norm3(c) >= 1e-6 * la * lb) {  // not nearly parallel partials
        FZ_CHECK(std::abs(fz::dot3(n, xa)) <= 1e-9 * la && std::abs(fz::dot3(n, xb)) <= 1e-9 * lb,
                 "normal not orthogonal to the partials: %g %g", fz::dot3(n, xa) / la,
                 fz::dot3(n, xb) / lb);
      }
    }
  }
}

void op_eval(State& st) {
  Input& in = st.in;
  Skin* k = pick(st);
  const int patch = patch_of(in);
  const double theta = theta_of(in), t = t_of(in);
  const int mask = in.range(0, 15);
  double out[4][3];
  fz::fill_sentinel(&out[0][0], 12);
  double* p[4];
  for (int j = 0; j < 4; ++j) p[j] = (mask >> j) & 1 ? out[j] : nullptr;
  const int s = cyc_sphere_skin_eval(st.ctx, k ? k->h : nullptr, patch, theta, t, p[0], p[1],
                                     p[2], p[3]);
  st.check("cyc_sphere_skin_eval", s);
  const int e = expected(k, patch, theta, t);
  if (e != CYC_OK) FZ_CHECK(s == e, "eval: %s, expected %s", cyc_status_name(s), cyc_status_name(e));
  else
    FZ_CHECK(s == CYC_OK || s == CYC_E_SINGULAR_POINT || s == CYC_E_NUMERICAL_OVERFLOW,
             "eval: undocumented %s", cyc_status_name(s));
  if (s != CYC_OK) {
    FZ_CHECK(fz::all_sentinel(&out[0][0], 12), "eval wrote on error");
    if (s == CYC_E_SINGULAR_POINT) FZ_CHECK(p[3], "eval: SINGULAR_POINT without a normal asked");
    return;
  }
  for (int j = 0; j < 4; ++j) {
    if (p[j]) FZ_CHECK(fz::finite3(p[j]), "eval: OK with non-finite output %d", j);
    else FZ_CHECK(fz::all_sentinel(out[j], 3), "eval: wrote output %d not asked for", j);
  }
  // Every output at once: the same bits (a normal may make it fail).
  double all[4][3];
  const int s2 = cyc_sphere_skin_eval(st.ctx, k->h, patch, theta, t, all[0], all[1], all[2],
                                      all[3]);
  st.check("cyc_sphere_skin_eval", s2);
  if (s2 == CYC_OK) {
    for (int j = 0; j < 4; ++j)
      if (p[j]) FZ_CHECK(same_bits(all[j], out[j], sizeof all[j]), "eval: output %d differs", j);
    geometry(*k, patch, t, all[0], all[1], all[2], all[3]);
  } else {
    FZ_CHECK(s2 == CYC_E_SINGULAR_POINT && !p[3], "eval: %s with every output, OK without",
             cyc_status_name(s2));
  }
}

void op_grid(State& st) {
  Input& in = st.in;
  Skin* k = pick(st);
  const int patch = patch_of(in);
  const int nth = in.range(-1, 6), nt = in.range(-1, 6);
  std::vector<double> th(size_t(std::max(nth, 1))), ts(size_t(std::max(nt, 1)));
  for (int i = 0; i < nth; ++i) th[size_t(i)] = theta_of(in);
  for (int j = 0; j < nt; ++j) ts[size_t(j)] = t_of(in);
  const int mask = in.range(0, 3);
  const bool null_theta = in.rarely(), null_t = in.rarely();
  const size_t npts = size_t(std::max(nth, 0)) * size_t(std::max(nt, 0));
  std::vector<double> P(3 * npts + 1), N(3 * npts + 1);
  fz::fill_sentinel(P.data(), P.size());
  fz::fill_sentinel(N.data(), N.size());
  double* pp = mask & 1 ? P.data() : nullptr;
  double* pn = mask & 2 ? N.data() : nullptr;
  size_t singular = 12345;
  const bool null_singular = in.flag();
  const int s = cyc_sphere_skin_eval_grid(st.ctx, k ? k->h : nullptr, patch,
                                          null_theta ? nullptr : th.data(), nth,
                                          null_t ? nullptr : ts.data(), nt, pp, pn,
                                          null_singular ? nullptr : &singular);
  st.check("cyc_sphere_skin_eval_grid", s);
  // The validation in its order.
  int e = CYC_OK;
  if (!k || null_theta || null_t) e = CYC_E_NULL_ARGUMENT;
  else if (patch < 0 || patch >= k->count || nth < 0 || nt < 0) e = CYC_E_INVALID_ARGUMENT;
  else {
    for (int i = 0; i < nth && e == CYC_OK; ++i)
      if (!std::isfinite(th[size_t(i)])) e = CYC_E_NOT_FINITE;
    for (int j = 0; j < nt && e == CYC_OK; ++j) {
      if (!std::isfinite(ts[size_t(j)])) e = CYC_E_NOT_FINITE;
      else if (!(ts[size_t(j)] >= 0.0 && ts[size_t(j)] <= 1.0)) e = CYC_E_BAD_DOMAIN;
    }
  }
  if (e != CYC_OK) {
    FZ_CHECK(s == e, "grid: %s, expected %s", cyc_status_name(s), cyc_status_name(e));
  } else {
    FZ_CHECK(s == CYC_OK || s == CYC_E_NUMERICAL_OVERFLOW, "grid: undocumented %s",
             cyc_status_name(s));
  }
  if (s != CYC_OK) {
    FZ_CHECK(fz::all_sentinel(P.data(), P.size()) && fz::all_sentinel(N.data(), N.size()),
             "grid wrote on error");
    FZ_CHECK(singular == 12345, "grid wrote *singular on error");
  } else {
    FZ_CHECK(fz::is_sentinel(P[3 * npts]) && fz::is_sentinel(N[3 * npts]),
             "grid wrote past its points");
    if (!pp) FZ_CHECK(fz::all_sentinel(P.data(), P.size()), "grid wrote points not asked for");
    if (!pn) FZ_CHECK(fz::all_sentinel(N.data(), N.size()), "grid wrote normals not asked for");
  }
  if (e != CYC_OK) return;
  // Against single evaluations: OK with the same bits, except that where
  // the single normal is SINGULAR_POINT the grid wrote (0, 0, 0) and counted
  // it (the point itself as the single evaluation without a normal); on
  // error one of them fails with that status.
  bool seen = false;
  size_t zeros = 0;
  for (int j = 0; j < nt; ++j)
    for (int i = 0; i < nth; ++i) {
      double x[3], n[3];
      int se = cyc_sphere_skin_eval(st.ctx, k->h, patch, th[size_t(i)], ts[size_t(j)],
                                    pp ? x : nullptr, nullptr, nullptr, pn ? n : nullptr);
      st.check("cyc_sphere_skin_eval", se);
      const size_t q = 3 * (size_t(j) * size_t(nth) + size_t(i));
      const bool singular_here = pn && se == CYC_E_SINGULAR_POINT;
      if (singular_here) {
        ++zeros;
        se = cyc_sphere_skin_eval(st.ctx, k->h, patch, th[size_t(i)], ts[size_t(j)],
                                  pp ? x : nullptr, nullptr, nullptr, nullptr);
        st.check("cyc_sphere_skin_eval", se);
      }
      if (s == CYC_OK) {
        FZ_CHECK(se == CYC_OK, "grid OK but eval (%d, %d) gives %s", i, j, cyc_status_name(se));
        if (pp) FZ_CHECK(same_bits(x, &P[q], sizeof x) && fz::finite3(x), "grid point (%d, %d) differs", i, j);
        if (pn && !singular_here)
          FZ_CHECK(same_bits(n, &N[q], sizeof n) && fz::finite3(n), "grid normal (%d, %d) differs", i, j);
        if (singular_here)
          FZ_CHECK(N[q] == 0 && N[q + 1] == 0 && N[q + 2] == 0, "grid singular normal (%d, %d) not 0", i, j);
      } else {
        seen |= se == s;
      }
    }
  if (s != CYC_OK) FZ_CHECK(seen, "grid failed with %s, no single evaluation did", cyc_status_name(s));
  if (s == CYC_OK && !null_singular)
    FZ_CHECK(singular == (pn ? zeros : 0), "grid counted %zu singular normals, %zu found", singular,
             pn ? zeros : size_t(0));
}

void op_twist(State& st) {
  Input& in = st.in;
  Skin* k = pick(st);
  const int patch = patch_of(in);
  const double theta = theta_of(in);
  const bool null_out = in.rarely();
  double tw = fz::sentinel();
  const int s = cyc_sphere_skin_twist(st.ctx, k ? k->h : nullptr, patch, theta,
                                      null_out ? nullptr : &tw);
  st.check("cyc_sphere_skin_twist", s);
  int e = expected(k, patch, theta, 0.0, false);
  if (null_out && k) e = CYC_E_NULL_ARGUMENT;
  if (e != CYC_OK) FZ_CHECK(s == e, "twist: %s, expected %s", cyc_status_name(s), cyc_status_name(e));
  else FZ_CHECK(s == CYC_OK || s == CYC_E_SINGULAR_POINT || s == CYC_E_NUMERICAL_OVERFLOW,
                "twist: undocumented %s", cyc_status_name(s));
  if (s != CYC_OK) {
    FZ_CHECK(fz::is_sentinel(tw), "twist wrote on error");
    return;
  }
  FZ_CHECK(std::isfinite(tw) && tw >= 0, "twist: OK with %g", tw);
  double again = 0;
  FZ_CHECK(cyc_sphere_skin_twist(st.ctx, k->h, patch, theta, &again) == CYC_OK &&
               same_bits(&again, &tw, sizeof tw),
           "twist not deterministic");
  st.check("cyc_sphere_skin_twist", CYC_OK);
}

void op_lambda(State& st) {
  Input& in = st.in;
  Skin* k = pick(st);
  const int patch = patch_of(in);
  const double theta = theta_of(in), t = t_of(in);
  const bool with_a = in.flag(), null_out = in.rarely();
  double lam = fz::sentinel(), a[2];
  fz::fill_sentinel(a, 2);
  const int s = cyc_sphere_skin_lambda(st.ctx, k ? k->h : nullptr, patch, theta, t,
                                       null_out ? nullptr : &lam, with_a ? a : nullptr);
  st.check("cyc_sphere_skin_lambda", s);
  int e = expected(k, patch, theta, t);
  if (null_out && k) e = CYC_E_NULL_ARGUMENT;
  if (e != CYC_OK) FZ_CHECK(s == e, "lambda: %s, expected %s", cyc_status_name(s), cyc_status_name(e));
  else FZ_CHECK(s == CYC_OK || s == CYC_E_NUMERICAL_OVERFLOW, "lambda: undocumented %s",
                cyc_status_name(s));
  if (s != CYC_OK) {
    FZ_CHECK(fz::is_sentinel(lam) && fz::all_sentinel(a, 2), "lambda wrote on error");
    return;
  }
  FZ_CHECK(std::isfinite(lam), "lambda: OK with %g", lam);
  if (with_a) FZ_CHECK(std::isfinite(a[0]) && std::isfinite(a[1]), "lambda: OK with non-finite a");
  else FZ_CHECK(fz::all_sentinel(a, 2), "lambda wrote a not asked for");
  // The Hermite conditions (6), (8): lambda = r at the ends, exactly.
  if (t == 0.0 || t == 1.0) {
    const double r = k->ends[size_t(patch) + (t == 1.0 ? 1 : 0)].radius;
    FZ_CHECK(lam == r, "lambda(theta, %g) = %.17g, r = %.17g", t, lam, r);
  }
}

void op_info(State& st) {
  Input& in = st.in;
  Skin* k = pick(st);
  const int patch = patch_of(in);
  const bool null_out = in.rarely();
  cyc_sphere_skin_info I;
  std::memset(&I, 0x5a, sizeof I);
  const cyc_sphere_skin_info keep = I;
  const int s = cyc_sphere_skin_info_get(st.ctx, k ? k->h : nullptr, patch, null_out ? nullptr : &I);
  st.check("cyc_sphere_skin_info_get", s);
  int e = !k || null_out ? CYC_E_NULL_ARGUMENT
                         : patch < 0 || patch >= k->count ? CYC_E_INVALID_ARGUMENT : CYC_OK;
  FZ_CHECK(s == e, "info: %s, expected %s", cyc_status_name(s), cyc_status_name(e));
  if (s != CYC_OK) {
    FZ_CHECK(same_bits(&I, &keep, sizeof I), "info wrote on error");
    return;
  }
  const cyc_skin_end& a = k->ends[size_t(patch)];
  const cyc_skin_end& b = k->ends[size_t(patch) + 1];
  FZ_CHECK(I.pairing == k->opt.pairing && I.method == k->opt.method, "info: pairing %d method %d",
           I.pairing, I.method);
  FZ_CHECK(std::isfinite(I.kappa[0]) && std::isfinite(I.kappa[1]) && std::isfinite(I.delta) &&
               std::isfinite(I.rmf_error_estimate),
           "info: non-finite");
  FZ_CHECK(I.kappa[0] * a.radius < 1.0 - 1e-12 && I.kappa[1] * b.radius < 1.0 - 1e-12,
           "info: kappa r = %g, %g", I.kappa[0] * a.radius, I.kappa[1] * b.radius);
  // Double reflection: steps per interval, a power of 2 in 2..256;
  // reference: the largest Chebyshev degree, n + 1 with n a power of 2 in
  // 8..64 (regress-info-reference-degree).
  const int q = k->opt.method == CYC_RMF_DOUBLE_REFLECTION ? I.rmf_substeps : I.rmf_substeps - 1;
  const int lo = k->opt.method == CYC_RMF_DOUBLE_REFLECTION ? 2 : 8;
  const int hi = k->opt.method == CYC_RMF_DOUBLE_REFLECTION ? 256 : 64;
  FZ_CHECK(q >= lo && q <= hi && (q & (q - 1)) == 0, "info: substeps %d (method %d)",
           I.rmf_substeps, k->opt.method);
  FZ_CHECK(I.rmf_error_estimate >= 0 && I.rmf_error_estimate <= k->opt.tolerance,
           "info: error estimate %g, tolerance %g", I.rmf_error_estimate, k->opt.tolerance);
  if (k->opt.pairing == CYC_SKIN_RMF) FZ_CHECK(I.delta == 0.0, "info: rmf with delta %g", I.delta);
  for (int j = 0; j < 4; ++j) FZ_CHECK(fz::finite3(I.spine[j]), "info: non-finite spine");
  FZ_CHECK(same_bits(I.spine[0], a.center, sizeof a.center) &&
               same_bits(I.spine[1], a.tangent, sizeof a.tangent),
           "info: the spine does not start at the start end");
}

// cyc_sphere_skin_export_create (issue 9, SPEC 8j.1b): fuzzed domain (u in
// [0, count] mostly, v whole or a rectangle in tan(theta/2), bad bounds
// rarely) and options (NULL, tolerance 1e-9..1e-3 of the scale, 0, NaN,
// 1e-19; degree 1..24 or out of range). Oracles: the validation statuses
// in their order (NULL, options, non-finite, domain), *out and the report
// untouched on error; on OK positive weights, finite report with
// error_estimate <= 2 tolerance (+ rounding), and for moderate skins the
// patches at a fuzzed (s, t) within 2 tolerance of cyc_sphere_skin_eval at
// their own (u = patch + t, theta = 2 atan v).
void op_export(State& st) {
  Input& in = st.in;
  Skin* k = pick(st);
  const int count = k ? k->count : 1;
  cyc_export_domain D{0.0, double(count), 0.0, 0.0, 1};
  switch (in.range(0, 5)) {
    case 0: break;
    case 1: D.u0 = in.range(0, 8) / 8.0 * count; D.u1 = D.u0 + in.range(1, 8) / 8.0 * (count - D.u0); break;
    case 2: D.whole_circle = 0; D.v0 = in.range(-16, 15) / 4.0; D.v1 = D.v0 + in.range(1, 16) / 4.0; break;
    case 3: D.u1 = count + in.range(0, 2) * 0.5; D.u0 = in.flag() ? -0.5 : D.u1; break;  // bad or empty
    case 4: D.u0 = in.flag() ? NAN : HUGE_VAL; break;
    default: D.whole_circle = 0; D.v0 = in.moderate(); D.v1 = in.moderate(); break;
  }
  cyc_skin_export_options o;
  cyc_skin_export_options_default(&o);
  const bool null_options = in.rarely();
  const double scale = k ? scale_of(*k, 0) : 1.0;
  switch (in.range(0, 7)) {
    case 0: case 1: break;
    case 2: o.tolerance = scale * std::pow(10.0, -double(in.range(3, 9))); break;
    case 3: o.tolerance = 0.0; break;
    case 4: o.tolerance = NAN; break;
    case 5: o.tolerance = 1e-19; break;
    default: o.tolerance = 1e-6 * scale; break;
  }
  if (in.flag()) o.degree = in.rarely() ? in.range(-2, 30) : in.range(1, 12);
  const bool null_out = in.rarely();
  if (k && !st.spend(1)) return;
  cyc_bezier_export* const kNoExport = reinterpret_cast<cyc_bezier_export*>(uintptr_t(0x5eed0e0));
  cyc_bezier_export* e = kNoExport;
  cyc_skin_export_report r;
  std::memset(&r, 0x5a, sizeof r);
  const cyc_skin_export_report keep = r;
  const int s = cyc_sphere_skin_export_create(st.ctx, k ? k->h : nullptr, &D,
                                              null_options ? nullptr : &o,
                                              null_out ? nullptr : &e, &r);
  st.check("cyc_sphere_skin_export_create", s);
  const cyc_skin_export_options& used = null_options ? cyc_skin_export_options{1e-9, 7} : o;
  const bool bad_options = !(used.tolerance > 0) || !std::isfinite(used.tolerance) ||
                           used.degree < 1 || used.degree > 24;
  const bool nonfinite = !std::isfinite(D.u0) || !std::isfinite(D.u1) ||
                         (!D.whole_circle && (!std::isfinite(D.v0) || !std::isfinite(D.v1)));
  const bool bad_domain = !(D.u0 >= 0 && D.u0 < D.u1 && D.u1 <= count) ||
                          (!D.whole_circle && !(D.v0 < D.v1));
  int want = CYC_OK;
  if (!k || null_out) want = CYC_E_NULL_ARGUMENT;
  else if (bad_options) want = CYC_E_INVALID_ARGUMENT;
  else if (nonfinite) want = CYC_E_NOT_FINITE;
  else if (bad_domain) want = CYC_E_BAD_DOMAIN;
  if (want != CYC_OK)
    FZ_CHECK(s == want, "skin export: %s, expected %s", cyc_status_name(s), cyc_status_name(want));
  else
    FZ_CHECK(s == CYC_OK || s == CYC_E_NUMERICAL_OVERFLOW || s == CYC_E_OUT_OF_MEMORY ||
                 s == CYC_E_INVALID_ARGUMENT,
             "skin export: undocumented %s", cyc_status_name(s));
  if (s != CYC_OK) {
    FZ_CHECK(e == kNoExport && same_bits(&r, &keep, sizeof r), "skin export wrote on error");
    return;
  }
  const int n = cyc_bezier_export_count(e);
  FZ_CHECK(n >= 1 && n <= CYC_MAX_EXPORT_PATCHES, "skin export: %d patches", n);
  FZ_CHECK(std::isfinite(r.error_estimate) && r.error_estimate >= 0 && std::isfinite(r.rmf_error) &&
               r.t_intervals >= 1 && (r.exact == 0 || r.exact == 1),
           "skin export: report");
  FZ_CHECK(r.error_estimate <= 2 * used.tolerance * (1 + 1e-9) + 1e-11 * scale,
           "skin export: error %g, tolerance %g", r.error_estimate, used.tolerance);
  const int idx = in.range(0, 1 << 12) % n;
  cyc_bezier_patch_info info;
  std::vector<double> cp(4 * 30 * 5);
  const int sp = cyc_bezier_export_patch(st.ctx, e, idx, &info, cp.data(), cp.size());
  st.check("cyc_bezier_export_patch", sp);
  FZ_CHECK(sp == CYC_OK && info.deg_u == used.degree + 3 && info.deg_v == 4, "skin patch %d: %s",
           idx, cyc_status_name(sp));
  for (int i = 0; i < (info.deg_u + 1) * 5; ++i)
    FZ_CHECK(cp[size_t(4 * i)] > 0 && std::isfinite(cp[size_t(4 * i)]), "skin patch weight %g",
             cp[size_t(4 * i)]);
  const double ps = in.range(0, 16) / 16.0, pt = in.range(0, 16) / 16.0;
  double x[3], uv[2];
  const int se = cyc_bezier_export_eval(st.ctx, e, idx, ps, pt, x, uv);
  st.check("cyc_bezier_export_eval", se);
  FZ_CHECK(se == CYC_OK && fz::finite3(x), "skin patch eval: %s", cyc_status_name(se));
  if (k->moderate) {
    const int patch = std::min(k->count - 1, std::max(0, int(std::floor(uv[0]))));
    const double t = std::min(1.0, std::max(0.0, uv[0] - patch));
    double y[3];
    const int sy =
        cyc_sphere_skin_eval(st.ctx, k->h, patch, 2 * std::atan(uv[1]), t, y, nullptr, nullptr,
                             nullptr);
    st.check("cyc_sphere_skin_eval", sy);
    if (sy == CYC_OK) {
      const double d[3] = {x[0] - y[0], x[1] - y[1], x[2] - y[2]};
      FZ_CHECK(fz::norm3(d) <= 2 * used.tolerance + 1e-9 * scale,
               "skin export off the skin by %g (tolerance %g)", fz::norm3(d), used.tolerance);
    }
  }
  cyc_bezier_export_destroy(e);
}

// cyc_sphere_skin_tessellate_plan/_eval (issue 9, SPEC 8j.2a): tolerance
// 1e-1..1e-3 of the scale (or bad), segments <= 256, row_cap <= 512.
// Oracles: statuses, *plan untouched on error; on OK ts strictly increasing
// from 0 to 1, rows and segments within the options, finite points equal
// (to 1e-12 of the scale) to cyc_sphere_skin_eval at (2 pi j / N, ts[i])
// with the default phase 0, unit or zero normals.
void op_tessellate(State& st) {
  Input& in = st.in;
  Skin* k = pick(st);
  const int patch = in.rarely() ? patch_of(in) : in.range(0, 5);
  cyc_tessellation_options o;
  cyc_tessellation_options_default(&o);
  const double scale = k ? scale_of(*k, 0) : 1.0;
  o.chordal_tolerance = scale * std::pow(10.0, -double(in.range(1, 3)));
  o.max_segments = in.range(8, 256);
  o.min_segments = in.range(3, 8);
  if (in.rarely()) o.fixed_segments = in.range(3, 64);
  if (in.rarely()) o.chordal_tolerance = in.flag() ? 0.0 : NAN;
  const int row_cap = in.range(2, 512);
  std::vector<double> ts(static_cast<size_t>(row_cap));
  const size_t wb = cyc_sphere_skin_tessellation_workspace_size(
      o.fixed_segments > 0 ? o.fixed_segments : o.max_segments);
  std::vector<double> work(wb / sizeof(double) + 1);
  if (k && !st.spend(1)) return;
  cyc_tessellation_plan plan;
  std::memset(&plan, 0x5a, sizeof plan);
  const cyc_tessellation_plan keep = plan;
  const int s = cyc_sphere_skin_tessellate_plan(st.ctx, k ? k->h : nullptr, patch, &o, ts.data(),
                                                row_cap, work.data(), wb, &plan);
  st.check("cyc_sphere_skin_tessellate_plan", s);
  if (!k) FZ_CHECK(s == CYC_E_NULL_ARGUMENT, "skin plan without a skin: %s", cyc_status_name(s));
  FZ_CHECK(s == CYC_OK || s == CYC_E_NULL_ARGUMENT || s == CYC_E_INVALID_ARGUMENT ||
               s == CYC_E_NOT_FINITE || s == CYC_E_BUFFER_TOO_SMALL ||
               s == CYC_E_NUMERICAL_OVERFLOW || s == CYC_E_SINGULAR_POINT,
           "skin plan: undocumented %s", cyc_status_name(s));
  if (s != CYC_OK) {
    FZ_CHECK(same_bits(&plan, &keep, sizeof plan), "skin plan written on error");
    return;
  }
  FZ_CHECK(plan.rows >= 2 && plan.rows <= row_cap && plan.segments >= 3 &&
               plan.segments <= (o.fixed_segments > 0 ? o.fixed_segments : o.max_segments),
           "skin plan: %d rows x %d", plan.rows, plan.segments);
  FZ_CHECK(ts[0] == 0.0 && ts[size_t(plan.rows - 1)] == 1.0, "skin plan: ends %g %g", ts[0],
           ts[size_t(plan.rows - 1)]);
  for (int i = 1; i < plan.rows; ++i)
    FZ_CHECK(ts[size_t(i)] > ts[size_t(i - 1)], "skin plan: ts not increasing at %d", i);
  const size_t npts = size_t(plan.rows) * size_t(plan.segments);
  if (npts > (1u << 16)) return;
  std::vector<double> P(3 * npts), N(3 * npts);
  size_t singular = 0;
  const int se = cyc_sphere_skin_tessellate_eval(st.ctx, k->h, patch, &plan, ts.data(),
                                                 {P.data(), npts, 3}, {N.data(), npts, 3},
                                                 &singular);
  st.check("cyc_sphere_skin_tessellate_eval", se);
  FZ_CHECK(se == CYC_OK || se == CYC_E_NUMERICAL_OVERFLOW, "skin mesh: %s", cyc_status_name(se));
  if (se != CYC_OK) return;
  for (size_t q = 0; q < npts; ++q) {
    FZ_CHECK(fz::finite3(&P[3 * q]), "skin mesh: non-finite point %zu", q);
    const double l = fz::norm3(&N[3 * q]);
    FZ_CHECK(l == 0.0 || std::abs(l - 1.0) <= 1e-9, "skin mesh: normal length %g", l);
  }
  if (plan.phase0 == 0.0 && plan.phase1 == 0.0) {
    const int i = in.range(0, plan.rows - 1), j = in.range(0, plan.segments - 1);
    double y[3];
    const int sy = cyc_sphere_skin_eval(st.ctx, k->h, patch, 2 * kPi * j / plan.segments,
                                        ts[size_t(i)], y, nullptr, nullptr, nullptr);
    st.check("cyc_sphere_skin_eval", sy);
    const double* x = &P[3 * (size_t(i) * size_t(plan.segments) + size_t(j))];
    const double d[3] = {x[0] - y[0], x[1] - y[1], x[2] - y[2]};
    if (sy == CYC_OK)
      FZ_CHECK(fz::norm3(d) <= 1e-12 * scale + 1e-12 * fz::norm3(y),
               "skin mesh point (%d, %d) off s(theta_j, t_i) by %g", i, j, fz::norm3(d));
  }
}

void op_destroy(State& st) {
  const int i = st.in.range(0, 7);
  if (st.skins.empty()) return;
  const size_t j = size_t(i) % st.skins.size();
  cyc_sphere_skin_destroy(st.ctx, st.skins[j].h);
  st.skins.erase(st.skins.begin() + long(j));
}

void op_nulls(State& st) {
  cyc_sphere_skin* h = st.skins.empty() ? nullptr : st.skins.front().h;
  double x[3], tw, lam;
  fz::fill_sentinel(x, 3);
  const double one = 0.5;
  int count = -1;
  cyc_sphere_skin_info I;
  cyc_skin_end e;
  cyc_sphere_skin* out = kSentinel;
  const double z[3] = {0, 0, 0}, u[3] = {1, 0, 0};
  FZ_CHECK(cyc_sphere_skin_eval(nullptr, h, 0, 0, 0, x, x, x, x) == CYC_E_NULL_ARGUMENT, "ctx");
  FZ_CHECK(cyc_sphere_skin_eval_grid(nullptr, h, 0, &one, 1, &one, 1, x, x, nullptr) == CYC_E_NULL_ARGUMENT, "ctx");
  FZ_CHECK(cyc_sphere_skin_twist(nullptr, h, 0, 0, &tw) == CYC_E_NULL_ARGUMENT, "ctx");
  FZ_CHECK(cyc_sphere_skin_lambda(nullptr, h, 0, 0, 0, &lam, nullptr) == CYC_E_NULL_ARGUMENT, "ctx");
  FZ_CHECK(cyc_sphere_skin_info_get(nullptr, h, 0, &I) == CYC_E_NULL_ARGUMENT, "ctx");
  FZ_CHECK(cyc_sphere_skin_patch_count(nullptr, h, &count) == CYC_E_NULL_ARGUMENT, "ctx");
  FZ_CHECK(cyc_skin_end_from_apex(nullptr, z, 1, u, u, &e) == CYC_E_NULL_ARGUMENT, "ctx");
  FZ_CHECK(cyc_skin_end_from_sphere(nullptr, z, 1, z, u, &e) == CYC_E_NULL_ARGUMENT, "ctx");
  FZ_CHECK(cyc_sphere_skin_create(nullptr, &e, &e, nullptr, &out) == CYC_E_NULL_ARGUMENT, "ctx");
  FZ_CHECK(cyc_sphere_skin_chain_create(nullptr, &e, 1, nullptr, &out, nullptr) ==
               CYC_E_NULL_ARGUMENT,
           "ctx");
  FZ_CHECK(fz::all_sentinel(x, 3) && count == -1 && out == kSentinel, "wrote with a NULL context");
  cyc_sphere_skin_destroy(st.ctx, nullptr);
  cyc_sphere_skin_destroy(nullptr, nullptr);
  cyc_skin_end_sphere(nullptr, x, &lam);
  cyc_skin_options_init(nullptr);
  FZ_CHECK(fz::all_sentinel(x, 3), "cyc_skin_end_sphere(NULL) wrote");
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
  State st(in);
  // Rarely a static context (SPEC 2a): handles carved from a block, the
  // tracker as its fallback (or none).
  const bool in_block = in.rarely();
  std::vector<unsigned char> block(in_block ? (size_t(in.range(0, 1 << 8)) << 12) + 64 : 0);
  const int sc = in_block ? cyc_context_init_static(block.data(), block.size(),
                                                    alloc_mode ? &a : nullptr, &st.ctx)
                          : cyc_context_create(alloc_mode ? &a : nullptr, &st.ctx);
  if (in_block && sc == CYC_E_BUFFER_TOO_SMALL) {
    FZ_CHECK(block.size() < cyc_context_static_size(), "static context refused %zu bytes",
             block.size());
    return 0;
  }
  FZ_CHECK(sc == CYC_OK || (alloc_mode == 2 && sc == CYC_E_OUT_OF_MEMORY), "context: %s",
           cyc_status_name(sc));
  if (sc != CYC_OK) {
    FZ_CHECK(tracker.live.empty(), "failed context creation leaked");
    return 0;
  }
  if (in.flag()) {
    FZ_CHECK(fz::install_handler(st.ctx, st.log) == CYC_OK,
             "handler");
    st.logp = &st.log;
  }
  const int nops = in.range(1, 12);
  for (int i = 0; i < nops; ++i) {
    switch (in.range(0, 9)) {
      case 8: op_tangents(st); break;
      case 0: op_create(st); break;
      case 1: op_chain(st); break;
      case 2: op_eval(st); break;
      case 3: op_grid(st); break;
      case 4: op_twist(st); break;
      case 5: op_lambda(st); break;
      case 6: op_info(st); break;
      case 7: op_destroy(st); break;
      default:
        switch (in.range(0, 2)) {
          case 0: op_export(st); break;
          case 1: op_tessellate(st); break;
          default: op_nulls(st);
        }
    }
  }
  // Tear down in a fuzzed order: handles may outlive their context.
  const bool context_first = in.flag();
  if (context_first) cyc_context_destroy(st.ctx);
  for (const Skin& k : st.skins) cyc_sphere_skin_destroy(context_first ? nullptr : st.ctx, k.h);
  if (!context_first) cyc_context_destroy(st.ctx);
  if (alloc_mode) FZ_CHECK(tracker.live.empty(), "%zu allocations leaked", tracker.live.size());
  return 0;
}
