// Fuzz target of the evaluation family of the C ABI. Builds a valid surface
// from fuzzed but moderate data (curves of degree <= 3, lines, points and
// line elements with coordinates in [-10, 10], an optional Mobius f of
// degree <= 2, a domain inside [-2, 6]), skips the input if creation fails,
// then calls cyc_surface_eval, _eval_batch, _eval_grid, _circle, _sphere,
// _ringed_data, _ringed_sphere, _canal_test and _parameter_of with fuzzed
// parameters (in and out of the domain, NaN, Inf, huge), NULL outputs,
// strides and capacities.
//
// Oracles:
//  - statuses known, never CYC_E_INTERNAL; last error/handler consistent;
//  - on OK every output is finite (parameter_of: finite or HUGE_VAL);
//  - on error every output is untouched (sentinel-filled buffers), and batch
//    and grid never write outside the requested vectors (stride gaps,
//    vectors past count, capacity);
//  - every call made twice gives bit-identical results (memcmp);
//  - eval_batch / eval_grid results equal cyc_surface_eval's, bitwise or to
//    1e-12 relative, with singular normals (0,0,0) counted in *singular;
//  - geometry on OK: the point lies on the circle of its u (|x - c|^2 =
//    radius^2, (x - c).n = 0, relative 1e-6); PRCS: on the touching sphere
//    (| |x - s|^2 - r^2 | <= 1e-6 max(1, r^2)); normals are unit and
//    orthogonal to x_u and x_v; ringed data agree with the circle;
//    parameter_of inverts eval; PRRS surfaces have no touching sphere.
//  - accuracy oracles are waived, and the region avoided, where the known
//    evaluator defect of fuzz_common.hpp (kKnownIssueCircleQuadratic) applies.
//
// Input layout: see make_seeds.py (EvalEncoder), which mirrors this file.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "fuzz_common.hpp"

namespace {

using fz::Input;

constexpr int kDomainSamples = 257;  // the core's kDomainSamples (config.hpp)
constexpr size_t kSizeSentinel = size_t(0x5eed5eed5eedull);

struct Ctx {
  cyc_context* ctx = nullptr;
  fz::HandlerLog log;
  fz::HandlerLog* logp = nullptr;
  const cyc_surface* S = nullptr;
  int kind = 0;
  double u0 = 0, u1 = 1;
  bool has_f = false;
  cyc_mobius f{};
  void check(const char* fn, int s) { fz::check_call(fn, ctx, s, logp); }
};

using fz::kKnownIssueCircleQuadratic;  // see fuzz_common.hpp

// ------------------------------------------------------------ building

// Verbose log of curve inputs, exactly (hex floats).
void log_rows(const char* what, const double* v, int rows, size_t stride, int width) {
  if (!fz::verbose()) return;
  if (*what) std::fprintf(stderr, "    %s:\n", what);
  for (int k = 0; k < rows; ++k) {
    std::fprintf(stderr, "     ");
    for (int j = 0; j < width; ++j) std::fprintf(stderr, " %a", v[size_t(k) * stride + size_t(j)]);
    std::fprintf(stderr, "\n");
  }
}

cyc_curve* build_curve(Input& in, Ctx& c, bool prrs) {
  cyc_curve* out = nullptr;
  int s = CYC_E_INVALID_ARGUMENT;
  const char* fn = "";
  switch (in.range(0, 5)) {
    case 0: {  // polynomial of degree 1..3
      const int deg = in.range(1, 3);
      const size_t stride = size_t(in.range(3, 5));
      std::vector<double> v = fz::exact(size_t(deg) * stride + 3);
      for (int k = 0; k <= deg; ++k) in.fill(&v[size_t(k) * stride], 3, 1);
      fn = "cyc_curve_create_polynomial";
      log_rows("polynomial rows (x y z)", v.data(), deg + 1, stride, 3);
      s = cyc_curve_create_polynomial(c.ctx, deg, v.data(), stride, &out);
      break;
    }
    case 1: {  // rational of degree 1..3
      const int deg = in.range(1, 3);
      const size_t stride = size_t(in.range(4, 6));
      const int wmode = in.range(0, 2);  // 0: w = 1, 1: w0 = 4 and small w_k, 2: any
      std::vector<double> v = fz::exact(size_t(deg) * stride + 4);
      for (int k = 0; k <= deg; ++k) {
        double* row = &v[size_t(k) * stride];
        in.fill(row, 3, 1);
        row[3] = wmode == 0 ? (k == 0 ? 1.0 : 0.0)
                 : wmode == 1 ? (k == 0 ? 4.0 : in.moderate() / 4.0)
                              : in.moderate();
      }
      fn = "cyc_curve_create_rational";
      log_rows("rational rows (x y z w)", v.data(), deg + 1, stride, 4);
      s = cyc_curve_create_rational(c.ctx, deg, v.data(), stride, &out);
      break;
    }
    case 2: {  // rational Bezier of degree 1..3 on its own interval
      const int deg = in.range(1, 3);
      const size_t stride = size_t(in.range(3, 5));
      std::vector<double> v = fz::exact(size_t(deg) * stride + 3);
      for (int k = 0; k <= deg; ++k) in.fill(&v[size_t(k) * stride], 3, 1);
      const bool weighted = in.flag();
      std::vector<double> w = fz::exact(size_t(deg) + 1);
      if (weighted)
        for (double& x : w) x = double(in.range(1, 16)) / 4.0;
      const double a = double(in.range(-8, 8)) / 4.0;
      const double len = double(in.range(1, 32)) / 8.0;
      fn = "cyc_curve_create_bezier";
      log_rows("bezier control points", v.data(), deg + 1, stride, 3);
      if (weighted) log_rows("bezier weights", w.data(), 1, 0, deg + 1);
      FZ_LOG("    on [%a, %a]", a, a + len);
      s = cyc_curve_create_bezier(c.ctx, deg, v.data(), stride, weighted ? w.data() : nullptr,
                                  a, a + len, &out);
      break;
    }
    case 3: {  // Hermite of order 0 or 1 (degree 1 or 3)
      const int order = in.range(0, 1);
      const double a = double(in.range(-8, 8)) / 4.0;
      const double len = double(in.range(1, 32)) / 8.0;
      const size_t n = 3 * size_t(order + 1);
      std::vector<double> p = fz::exact(n), q = fz::exact(n);
      in.fill(p.data(), n, 1);
      in.fill(q.data(), n, 1);
      fn = "cyc_curve_create_hermite";
      log_rows("hermite start", p.data(), order + 1, 3, 3);
      log_rows("hermite end", q.data(), order + 1, 3, 3);
      FZ_LOG("    on [%a, %a]", a, a + len);
      s = cyc_curve_create_hermite(c.ctx, order, a, a + len, p.data(), q.data(), &out);
      break;
    }
    case 4: {
      double p[3], d[3];
      in.fill(p, 3, 1);
      in.fill(d, 3, 1);
      fn = "cyc_curve_create_line";
      log_rows("line point, direction", p, 1, 3, 3);
      log_rows("", d, 1, 3, 3);
      s = cyc_curve_create_line(c.ctx, p, d, &out);
      break;
    }
    default: {
      double p[3], d[3];
      in.fill(p, 3, 1);
      if (prrs) {
        fn = "cyc_curve_create_point";
        log_rows("point", p, 1, 3, 3);
        s = cyc_curve_create_point(c.ctx, p, &out);
      } else {
        in.fill(d, 3, 1);
        fn = "cyc_curve_create_line_element";
        log_rows("line element point, tangent", p, 1, 3, 3);
        log_rows("", d, 1, 3, 3);
        s = cyc_curve_create_line_element(c.ctx, p, d, &out);
      }
      break;
    }
  }
  c.check(fn, s);
  return s == CYC_OK ? out : nullptr;
}

bool build_mobius(Input& in, cyc_mobius& m) {
  const int mode = in.range(0, 2);
  if (mode == 0) return false;
  std::memset(&m, 0, sizeof m);
  if (mode == 1) {  // f = v spelled out
    m.degree = 0;
    m.alpha[0] = 1.0;
    m.delta[0] = 1.0;
    return true;
  }
  m.degree = in.range(0, 2);
  for (double* a : {m.alpha, m.beta, m.gamma, m.delta}) {
    in.fill(a, size_t(m.degree) + 1, 1);
    log_rows("mobius alpha/beta/gamma/delta", a, 1, 0, m.degree + 1);
  }
  return true;
}

// ------------------------------------------------------------ parameters

double domain_sample(double u0, double u1, int k) {
  return u0 + (u1 - u0) * double(k) / double(kDomainSamples - 1);
}

double param_u(Input& in, const Ctx& c) {
  switch (in.range(0, 4)) {
    case 0: return c.u0 + (c.u1 - c.u0) * double(in.range(0, 65535)) / 65535.0;
    case 1: return domain_sample(c.u0, c.u1, in.range(0, kDomainSamples - 1));
    case 2: return in.moderate();
    case 3: return in.wild();
    default: return in.flag() ? c.u1 : c.u0;
  }
}

double param_v(Input& in) {
  switch (in.range(0, 3)) {
    case 0: return in.moderate();
    case 1: return in.wild();
    case 2: return double(in.range(-3, 3));
    default: {
      const double m = in.moderate();
      return m * std::pow(10.0, double(in.range(0, 12)));
    }
  }
}

// ------------------------------------------------------------ helpers

bool same_bits(const void* a, const void* b, size_t n) { return std::memcmp(a, b, n) == 0; }

// Bitwise equal, or equal to 1e-12 relative to the larger vector.
bool close3(const double* a, const double* b) {
  if (same_bits(a, b, 3 * sizeof(double))) return true;
  const double scale = std::max({1e-300, fz::norm3(a), fz::norm3(b)});
  return fz::dist3(a, b) <= 1e-12 * scale;
}

struct Geometry {
  int status = CYC_E_INTERNAL;
  cyc_circle circle{};
  bool has_sphere = false;
  cyc_sphere sphere{};
  // Length scale of the frame at u: radius, center, sphere (PRCS).
  double L = 1;
};

Geometry geometry(Ctx& c, double u) {
  Geometry g;
  g.status = cyc_surface_circle(c.ctx, c.S, u, &g.circle);
  c.check("cyc_surface_circle", g.status);
  if (g.status != CYC_OK) return g;
  double L = std::max({1.0, std::sqrt(g.circle.radius2), fz::norm3(g.circle.center)});
  if (c.kind == CYC_SURFACE_PRCS) {
    const int s = cyc_surface_sphere(c.ctx, c.S, u, &g.sphere);
    c.check("cyc_surface_sphere", s);
    FZ_CHECK(s == CYC_OK, "circle OK but sphere failed at u = %.17g: %s", u,
             cyc_context_last_error(c.ctx));
    g.has_sphere = true;
    L = std::max({L, std::sqrt(g.sphere.radius2), fz::norm3(g.sphere.center)});
  }
  g.L = L;
  return g;
}

const cyc_mobius* mobius(const Ctx& c) { return c.has_f ? &c.f : nullptr; }

// The known issue (fuzz_common.hpp): may it explain a failure at (u, v)?
bool known_issue_waives(Ctx& c, double u, double v) {
  return fz::known_issue_waives(c.ctx, c.S, mobius(c), u, v, c.logp);
}
// Parameters the harness skips while the known issue stands.
bool known_issue_avoid(Ctx& c, double u, double v) {
  const bool avoid = fz::known_issue_avoid(c.ctx, c.S, mobius(c), u, v, c.logp);
  if (avoid) FZ_LOG("    (skipped: known issue at u = %.17g v = %.17g)", u, v);
  return avoid;
}

// FZ_CHECK unless the known circle_point defect explains the failure.
#define FZ_CHECK_ACCURACY(c, u, v, cond, ...) \
  FZ_CHECK((cond) || known_issue_waives(c, u, v), __VA_ARGS__)

// |ringed n| at u (PRCS: the spine speed |s'|), 0 if unavailable.
double spine_speed(Ctx& c, double u) {
  double n[3];
  const int s = cyc_surface_ringed_data(c.ctx, c.S, u, nullptr, n, nullptr, nullptr);
  c.check("cyc_surface_ringed_data", s);
  return s == CYC_OK ? fz::norm3(n) : 0.0;
}

// The geometric invariants of an OK point evaluation at (u, v).
void check_point(Ctx& c, double u, double v, const double* x, const double* xu,
                 const double* xv, const double* n) {
  const Geometry g = geometry(c, u);
  FZ_CHECK(g.status == CYC_OK, "eval OK at u = %.17g but circle failed: %s", u,
           cyc_context_last_error(c.ctx));
  const double L = g.L;
  if (x) {
    const double d[3] = {x[0] - g.circle.center[0], x[1] - g.circle.center[1],
                         x[2] - g.circle.center[2]};
    const double dd = fz::dot3(d, d);
    FZ_CHECK_ACCURACY(c, u, v, std::abs(dd - g.circle.radius2) <= 1e-6 * L * L,
             "point off its circle: u = %.17g v = %.17g |x-c|^2 = %.17g radius^2 = %.17g "
             "(scale %g)",
             u, v, dd, g.circle.radius2, L);
    const double off = fz::dot3(d, g.circle.normal);
    FZ_CHECK_ACCURACY(c, u, v, std::abs(off) <= 1e-6 * L,
             "point off the circle's plane: u = %.17g v = %.17g (x-c).n = %.17g (scale %g)", u,
             v, off, L);
    if (g.has_sphere) {
      const double e[3] = {x[0] - g.sphere.center[0], x[1] - g.sphere.center[1],
                           x[2] - g.sphere.center[2]};
      const double ee = fz::dot3(e, e), r2 = g.sphere.radius2;
      FZ_CHECK_ACCURACY(c, u, v, std::abs(ee - r2) <= 1e-6 * std::max(1.0, r2),
               "PRCS point off its touching sphere: u = %.17g v = %.17g |x-s|^2 = %.17g "
               "r^2 = %.17g",
               u, v, ee, r2);
    }
  }
  if (n) {
    const double nn = fz::norm3(n);
    FZ_CHECK_ACCURACY(c, u, v, std::abs(nn - 1.0) <= 1e-6, "normal not unit at u = %.17g v = %.17g: |n| = %.17g",
             u, v, nn);
    // Normals are orthogonal to the partials (PRCS: the canal property).
    // PRCS normals are (x - s)/r, whose rounding is relative to |s| / r.
    // PRRS normals are x_u x x_v normalized, whose rounding is relative to
    // |x_u| |x_v| / |x_u x x_v| (large near singular points); without both
    // partials there is nothing to compare.
    double cond = 1.0;
    if (g.has_sphere) {
      cond = std::max(1.0, (fz::norm3(g.sphere.center) + (x ? fz::norm3(x) : 0.0)) /
                               std::sqrt(g.sphere.radius2));
    } else if (xu && xv) {
      const double cr[3] = {xu[1] * xv[2] - xu[2] * xv[1], xu[2] * xv[0] - xu[0] * xv[2],
                            xu[0] * xv[1] - xu[1] * xv[0]};
      cond = std::max(1.0, fz::norm3(xu) * fz::norm3(xv) / fz::norm3(cr));
    } else {
      return;
    }
    for (const double* t : {xu, xv}) {
      if (!t) continue;
      if (t == xv && kKnownIssueCircleQuadratic) continue;
      const double nt = fz::dot3(n, t), tl = fz::norm3(t);
      // Relative to |t|, or for x_u (which can vanish, e.g. near a constant
      // generator) to the spine speed |s'| = |ringed n| as well.
      const bool ok = std::abs(nt) <= 1e-6 * cond * tl + 1e-300 ||
                      (t == xu && std::abs(nt) <= 1e-12 * cond * spine_speed(c, u));
      FZ_CHECK_ACCURACY(c, u, v, ok,
               "normal not orthogonal to x_%s at u = %.17g v = %.17g: n.t = %.3g |t| = %.3g",
               t == xu ? "u" : "v", u, v, nt, tl);
    }
  }
}

// ------------------------------------------------------------ eval

struct EvalResult {
  int status;
  double out[4][3];
};

EvalResult eval_once(Ctx& c, double u, double v, unsigned mask) {
  EvalResult r;
  fz::fill_sentinel(&r.out[0][0], 12);
  double* p[4];
  for (int i = 0; i < 4; ++i) p[i] = (mask >> i) & 1u ? r.out[i] : nullptr;
  r.status = cyc_surface_eval(c.ctx, c.S, u, v, p[0], p[1], p[2], p[3]);
  c.check("cyc_surface_eval", r.status);
  return r;
}

// Evaluate twice (bit-identical), check untouched-on-error / finite-on-OK.
EvalResult eval_checked(Ctx& c, double u, double v, unsigned mask) {
  const EvalResult a = eval_once(c, u, v, mask);
  const EvalResult b = eval_once(c, u, v, mask);
  FZ_CHECK(a.status == b.status && same_bits(a.out, b.out, sizeof a.out),
           "cyc_surface_eval is not deterministic at u = %.17g v = %.17g", u, v);
  if (a.status != CYC_OK) {
    FZ_CHECK(fz::all_sentinel(&a.out[0][0], 12), "cyc_surface_eval: %s but wrote an output",
             cyc_status_name(a.status));
    if (mask == 0) FZ_CHECK(a.status == CYC_E_NULL_ARGUMENT, "eval without outputs: %s",
                            cyc_status_name(a.status));
    return a;
  }
  FZ_CHECK(mask != 0, "cyc_surface_eval OK without any output");
  for (int i = 0; i < 4; ++i) {
    if ((mask >> i) & 1u)
      FZ_CHECK(fz::finite3(a.out[i]), "cyc_surface_eval OK but output %d not finite at u = "
               "%.17g v = %.17g", i, u, v);
    else
      FZ_CHECK(fz::all_sentinel(a.out[i], 3), "cyc_surface_eval wrote unrequested output %d",
               i);
  }
  return a;
}

void op_eval(Input& in, Ctx& c) {
  const double u = param_u(in, c), v = param_v(in);
  const unsigned mask = in.range(0, 15) == 0 ? unsigned(in.range(0, 15)) : 15u;
  FZ_LOG("eval u = %.17g v = %.17g mask %u", u, v, mask);
  if (known_issue_avoid(c, u, v)) return;
  const EvalResult r = eval_checked(c, u, v, mask);
  if (r.status == CYC_E_SINGULAR_POINT) {
    FZ_CHECK(mask & 8u, "singular point reported without a normal requested");
    return;
  }
  if (r.status != CYC_OK) return;
  auto want = [&](int i) { return (mask >> i) & 1u ? r.out[i] : nullptr; };
  check_point(c, u, v, want(0), want(1), want(2), want(3));
}

// ------------------------------------------------------------ batch, grid

struct Buf {
  std::vector<double> mem;
  cyc_buffer3 b{nullptr, 0, 3};
  bool wanted = false;
};

Buf make_buf(Input& in, size_t count) {
  Buf B;
  if (in.range(0, 3) == 0) {  // not wanted: data NULL, other fields arbitrary
    B.b = {nullptr, 0, 1};
    return B;
  }
  const size_t stride = in.range(0, 7) == 0 ? size_t(in.range(0, 2)) : size_t(in.range(3, 5));
  size_t cap = count + size_t(in.range(0, 1));
  if (in.rarely() && cap > 0) cap -= 2 > cap ? cap : 2;
  B.mem = fz::exact(cap == 0 ? 1 : (cap - 1) * std::max<size_t>(stride, 3) + 3);
  B.b = {B.mem.data(), cap, stride};
  B.wanted = true;
  return B;
}

struct BatchCall {
  int status;
  std::vector<double> mem[4];
  size_t singular;
};

// The vectors of one wanted buffer: entries [0, count) finite, everything
// else (stride gaps, vectors past count) untouched.
void check_layout(const Buf& B, const std::vector<double>& mem, size_t count, const char* fn) {
  const size_t stride = B.b.stride;
  for (size_t i = 0; i < mem.size(); ++i) {
    const bool in_vector = i / stride < count && i % stride < 3;
    if (in_vector)
      FZ_CHECK(std::isfinite(mem[i]), "%s OK but element %zu = %g", fn, i, mem[i]);
    else
      FZ_CHECK(fz::is_sentinel(mem[i]), "%s wrote element %zu outside its vectors", fn, i);
  }
}

// Compare entry k of a batch/grid call with cyc_surface_eval at (u, v).
void compare_entry(Ctx& c, const Buf* bufs, const BatchCall& r, size_t k, double u, double v,
                   size_t& singular, const char* fn) {
  unsigned mask = 1u;  // the point: computed (and checked) whenever anything is
  for (int i = 0; i < 4; ++i)
    if (bufs[i].wanted) mask |= 1u << i;
  EvalResult e = eval_checked(c, u, v, mask);
  if (e.status == CYC_E_SINGULAR_POINT && (mask & 8u)) {
    ++singular;
    const double* n = &r.mem[3][k * bufs[3].b.stride];
    FZ_CHECK(n[0] == 0 && n[1] == 0 && n[2] == 0,
             "%s: singular normal %zu not written as (0,0,0)", fn, k);
    mask &= ~8u;
    e = eval_checked(c, u, v, mask);
  }
  FZ_CHECK(e.status == CYC_OK, "%s OK but cyc_surface_eval(%.17g, %.17g) = %s", fn, u, v,
           cyc_status_name(e.status));
  for (int i = 0; i < 4; ++i) {
    if (!((mask >> i) & 1u) || !bufs[i].wanted) continue;
    const double* got = &r.mem[i][k * bufs[i].b.stride];
    FZ_CHECK(close3(got, e.out[i]),
             "%s entry %zu output %d differs from cyc_surface_eval at u = %.17g v = %.17g: "
             "(%.17g %.17g %.17g) vs (%.17g %.17g %.17g)",
             fn, k, i, u, v, got[0], got[1], got[2], e.out[i][0], e.out[i][1], e.out[i][2]);
  }
  check_point(c, u, v, e.out[0], (mask & 2u) ? e.out[1] : nullptr,
              (mask & 4u) ? e.out[2] : nullptr, (mask & 8u) ? e.out[3] : nullptr);
}

template <class Call>
void run_batch(Ctx& c, Buf* bufs, bool want_singular, size_t count, const char* fn,
               Call&& call, const std::vector<std::pair<double, double>>& uv) {
  BatchCall r[2];
  for (BatchCall& x : r) {
    for (int i = 0; i < 4; ++i) {
      fz::fill_sentinel(bufs[i].mem.data(), bufs[i].mem.size());
    }
    x.singular = kSizeSentinel;
    x.status = call(want_singular ? &x.singular : nullptr);
    c.check(fn, x.status);
    for (int i = 0; i < 4; ++i) x.mem[i] = bufs[i].mem;
  }
  FZ_CHECK(r[0].status == r[1].status && r[0].singular == r[1].singular,
           "%s is not deterministic", fn);
  for (int i = 0; i < 4; ++i)
    FZ_CHECK(r[0].mem[i] == r[1].mem[i] ||
                 same_bits(r[0].mem[i].data(), r[1].mem[i].data(),
                           r[0].mem[i].size() * sizeof(double)),
             "%s is not deterministic (buffer %d)", fn, i);
  const BatchCall& R = r[0];
  if (R.status != CYC_OK) {
    for (int i = 0; i < 4; ++i)
      FZ_CHECK(fz::all_sentinel(R.mem[i].data(), R.mem[i].size()),
               "%s: %s but wrote buffer %d", fn, cyc_status_name(R.status), i);
    FZ_CHECK(R.singular == kSizeSentinel, "%s: %s but wrote *singular", fn,
             cyc_status_name(R.status));
    return;
  }
  for (int i = 0; i < 4; ++i) {
    if (!bufs[i].wanted) continue;
    FZ_CHECK(bufs[i].b.stride >= 3 && bufs[i].b.capacity >= count,
             "%s OK with buffer %d stride %zu capacity %zu for %zu vectors", fn, i,
             bufs[i].b.stride, bufs[i].b.capacity, count);
    check_layout(bufs[i], R.mem[i], count, fn);
  }
  // Without any buffer nothing is computed; else every entry is what
  // cyc_surface_eval gives.
  if (!bufs[0].wanted && !bufs[1].wanted && !bufs[2].wanted && !bufs[3].wanted) {
    FZ_CHECK(!want_singular || R.singular == 0, "%s: *singular = %zu without normals", fn,
             R.singular);
    return;
  }
  size_t singular = 0;
  for (size_t k = 0; k < count; ++k)
    compare_entry(c, bufs, R, k, uv[k].first, uv[k].second, singular, fn);
  if (want_singular) {
    FZ_CHECK(R.singular == singular, "%s: *singular = %zu, cyc_surface_eval found %zu", fn,
             R.singular, singular);
    if (c.kind == CYC_SURFACE_PRCS)
      FZ_CHECK(singular == 0, "%s: singular normals on a canal surface", fn);
  }
}

void op_batch(Input& in, Ctx& c) {
  const size_t count = size_t(in.range(0, 12));
  const size_t uv_stride = in.range(0, 7) == 0 ? size_t(in.range(0, 1)) : size_t(in.range(2, 4));
  const bool null_uv = in.rarely();
  std::vector<double> uvmem = fz::exact(count ? (count - 1) * std::max<size_t>(uv_stride, 2) + 2
                                              : 1);
  std::vector<std::pair<double, double>> uv(count);
  for (size_t k = 0; k < count; ++k) {
    uv[k].first = param_u(in, c);
    uv[k].second = param_v(in);
    if (uv_stride >= 2) {
      uvmem[k * uv_stride] = uv[k].first;
      uvmem[k * uv_stride + 1] = uv[k].second;
    }
  }
  Buf bufs[4];
  for (Buf& b : bufs) b = make_buf(in, count);
  const bool want_singular = in.flag();
  FZ_LOG("eval_batch count %zu uv_stride %zu, buffers %d%d%d%d", count, uv_stride,
         int(bufs[0].wanted), int(bufs[1].wanted), int(bufs[2].wanted), int(bufs[3].wanted));
  for (size_t k = 0; k < count; ++k)
    FZ_LOG("    uv[%zu] = (%.17g, %.17g)", k, uv[k].first, uv[k].second);
  for (const auto& p : uv)
    if (known_issue_avoid(c, p.first, p.second)) return;
  run_batch(c, bufs, want_singular, count, "cyc_surface_eval_batch",
            [&](size_t* singular) {
              return cyc_surface_eval_batch(c.ctx, c.S, null_uv ? nullptr : uvmem.data(),
                                            uv_stride, count, bufs[0].b, bufs[1].b, bufs[2].b,
                                            bufs[3].b, singular);
            },
            uv);
}

void op_grid(Input& in, Ctx& c) {
  const size_t nu = size_t(in.range(0, 4)), nv = size_t(in.range(0, 5));
  const bool null_us = in.rarely(), null_vs = in.rarely();
  std::vector<double> us = fz::exact(nu ? nu : 1), vs = fz::exact(nv ? nv : 1);
  for (size_t i = 0; i < nu; ++i) us[i] = param_u(in, c);
  for (size_t j = 0; j < nv; ++j) vs[j] = param_v(in);
  const size_t count = nu * nv;
  std::vector<std::pair<double, double>> uv(count);
  for (size_t i = 0; i < nu; ++i)
    for (size_t j = 0; j < nv; ++j) uv[i * nv + j] = {us[i], vs[j]};
  Buf bufs[4];
  for (Buf& b : bufs) b = make_buf(in, count);
  const bool want_singular = in.flag();
  FZ_LOG("eval_grid %zu x %zu, buffers %d%d%d%d", nu, nv, int(bufs[0].wanted),
         int(bufs[1].wanted), int(bufs[2].wanted), int(bufs[3].wanted));
  for (size_t i = 0; i < nu; ++i) FZ_LOG("    us[%zu] = %.17g", i, us[i]);
  for (size_t j = 0; j < nv; ++j) FZ_LOG("    vs[%zu] = %.17g", j, vs[j]);
  for (const auto& p : uv)
    if (known_issue_avoid(c, p.first, p.second)) return;
  run_batch(c, bufs, want_singular, count, "cyc_surface_eval_grid",
            [&](size_t* singular) {
              return cyc_surface_eval_grid(c.ctx, c.S, null_us ? nullptr : us.data(), nu,
                                           null_vs ? nullptr : vs.data(), nv, bufs[0].b,
                                           bufs[1].b, bufs[2].b, bufs[3].b, singular);
            },
            uv);
}

// ------------------------------------------------------------ per-u queries

void op_circle(Input& in, Ctx& c) {
  const double u = param_u(in, c);
  cyc_circle a, b;
  fz::fill_sentinel(reinterpret_cast<double*>(&a), sizeof a / sizeof(double));
  fz::fill_sentinel(reinterpret_cast<double*>(&b), sizeof b / sizeof(double));
  const int sa = cyc_surface_circle(c.ctx, c.S, u, &a);
  c.check("cyc_surface_circle", sa);
  const int sb = cyc_surface_circle(c.ctx, c.S, u, &b);
  c.check("cyc_surface_circle", sb);
  FZ_LOG("circle u = %.17g -> %s", u, cyc_status_name(sa));
  FZ_CHECK(sa == sb && same_bits(&a, &b, sizeof a), "cyc_surface_circle not deterministic");
  if (sa != CYC_OK) {
    FZ_CHECK(fz::all_sentinel(reinterpret_cast<double*>(&a), sizeof a / sizeof(double)),
             "cyc_surface_circle: %s but wrote the output", cyc_status_name(sa));
    return;
  }
  FZ_CHECK(fz::finite3(a.center) && fz::finite3(a.normal) && std::isfinite(a.radius2) &&
               a.radius2 >= 0,
           "cyc_surface_circle OK but not finite (or radius^2 < 0) at u = %.17g", u);
  FZ_CHECK(std::abs(fz::norm3(a.normal) - 1.0) <= 1e-12, "circle normal not unit: %.17g",
           fz::norm3(a.normal));
  // A point of this circle (any v) lies on it.
  const double v = param_v(in);
  if (known_issue_avoid(c, u, v)) return;
  const EvalResult e = eval_checked(c, u, v, 1u);
  if (e.status == CYC_OK) check_point(c, u, v, e.out[0], nullptr, nullptr, nullptr);
}

void op_sphere(Input& in, Ctx& c) {
  const double u = param_u(in, c);
  cyc_sphere a, b;
  fz::fill_sentinel(reinterpret_cast<double*>(&a), 4);
  fz::fill_sentinel(reinterpret_cast<double*>(&b), 4);
  const int sa = cyc_surface_sphere(c.ctx, c.S, u, &a);
  c.check("cyc_surface_sphere", sa);
  const int sb = cyc_surface_sphere(c.ctx, c.S, u, &b);
  c.check("cyc_surface_sphere", sb);
  FZ_CHECK(sa == sb && same_bits(&a, &b, sizeof a), "cyc_surface_sphere not deterministic");
  if (c.kind == CYC_SURFACE_PRRS)
    FZ_CHECK(sa == CYC_E_NOT_CANAL, "cyc_surface_sphere on PRRS: %s", cyc_status_name(sa));
  if (sa != CYC_OK) {
    FZ_CHECK(fz::all_sentinel(reinterpret_cast<double*>(&a), 4),
             "cyc_surface_sphere: %s but wrote the output", cyc_status_name(sa));
    return;
  }
  FZ_CHECK(fz::finite3(a.center) && std::isfinite(a.radius2) && a.radius2 >= 0,
           "cyc_surface_sphere OK but not finite at u = %.17g", u);
  cyc_circle ci;
  const int sc = cyc_surface_circle(c.ctx, c.S, u, &ci);
  c.check("cyc_surface_circle", sc);
  FZ_CHECK(sc == CYC_OK, "sphere OK but circle %s at u = %.17g", cyc_status_name(sc), u);
}

struct Ringed {
  int status;
  double v[8];  // c[3], n[3], rho2, rho_rho_prime
};

Ringed ringed_once(Ctx& c, double u, unsigned mask) {
  Ringed r;
  fz::fill_sentinel(r.v, 8);
  r.status = cyc_surface_ringed_data(c.ctx, c.S, u, mask & 1u ? r.v : nullptr,
                                     mask & 2u ? r.v + 3 : nullptr, mask & 4u ? r.v + 6 : nullptr,
                                     mask & 8u ? r.v + 7 : nullptr);
  c.check("cyc_surface_ringed_data", r.status);
  return r;
}

void op_ringed_data(Input& in, Ctx& c) {
  const double u = param_u(in, c);
  const unsigned mask = in.range(0, 3) == 0 ? unsigned(in.range(0, 15)) : 15u;
  const Ringed a = ringed_once(c, u, mask), b = ringed_once(c, u, mask);
  FZ_CHECK(a.status == b.status && same_bits(a.v, b.v, sizeof a.v),
           "cyc_surface_ringed_data not deterministic");
  if (a.status != CYC_OK) {
    FZ_CHECK(fz::all_sentinel(a.v, 8), "cyc_surface_ringed_data: %s but wrote an output",
             cyc_status_name(a.status));
    return;
  }
  const size_t lo[4] = {0, 3, 6, 7}, n[4] = {3, 3, 1, 1};
  for (int i = 0; i < 4; ++i)
    for (size_t j = lo[i]; j < lo[i] + n[i]; ++j) {
      if ((mask >> i) & 1u)
        FZ_CHECK(std::isfinite(a.v[j]), "ringed_data OK but output %zu = %g", j, a.v[j]);
      else
        FZ_CHECK(fz::is_sentinel(a.v[j]), "ringed_data wrote unrequested output %zu", j);
    }
  if (mask != 15u) return;
  // Eq. (1)/(27): c, n, rho^2 are the circle's center, plane normal, radius^2.
  const Geometry g = geometry(c, u);
  FZ_CHECK(g.status == CYC_OK, "ringed data OK but circle %s at u = %.17g",
           cyc_status_name(g.status), u);
  FZ_CHECK(fz::dist3(a.v, g.circle.center) <= 1e-9 * g.L,
           "ringed c differs from the circle center at u = %.17g by %.3g (scale %g)", u,
           fz::dist3(a.v, g.circle.center), g.L);
  const double nl = fz::norm3(a.v + 3);
  FZ_CHECK(nl > 0, "ringed n = 0 at u = %.17g", u);
  const double nu[3] = {a.v[3] / nl, a.v[4] / nl, a.v[5] / nl};
  FZ_CHECK(fz::dist3(nu, g.circle.normal) <= 1e-9,
           "ringed n not along the circle normal at u = %.17g", u);
  FZ_CHECK(std::abs(std::max(0.0, a.v[6]) - g.circle.radius2) <= 1e-9 * g.L * g.L,
           "ringed rho^2 = %.17g, circle radius^2 = %.17g at u = %.17g", a.v[6],
           g.circle.radius2, u);
}

void op_ringed_sphere(Input& in, Ctx& c) {
  const double u = param_u(in, c);
  cyc_sphere a, b;
  fz::fill_sentinel(reinterpret_cast<double*>(&a), 4);
  fz::fill_sentinel(reinterpret_cast<double*>(&b), 4);
  const int sa = cyc_surface_ringed_sphere(c.ctx, c.S, u, &a);
  c.check("cyc_surface_ringed_sphere", sa);
  const int sb = cyc_surface_ringed_sphere(c.ctx, c.S, u, &b);
  c.check("cyc_surface_ringed_sphere", sb);
  FZ_CHECK(sa == sb && same_bits(&a, &b, sizeof a),
           "cyc_surface_ringed_sphere not deterministic");
  if (sa != CYC_OK) {
    FZ_CHECK(fz::all_sentinel(reinterpret_cast<double*>(&a), 4),
             "cyc_surface_ringed_sphere: %s but wrote the output", cyc_status_name(sa));
    return;
  }
  FZ_CHECK(fz::finite3(a.center) && std::isfinite(a.radius2),
           "cyc_surface_ringed_sphere OK but not finite at u = %.17g", u);
}

void op_canal_test(Input& in, Ctx& c) {
  double tol;
  switch (in.range(0, 2)) {
    case 0: tol = 0.0; break;
    case 1: tol = in.wild(); break;
    default: tol = std::pow(10.0, -double(in.range(0, 15))); break;
  }
  const unsigned mask = in.range(0, 3) == 0 ? unsigned(in.range(0, 3)) : 3u;
  struct R {
    int status;
    double res;
    int is_canal;
  } r[2];
  for (R& x : r) {
    fz::fill_sentinel(&x.res, 1);
    x.is_canal = -77;
    x.status = cyc_surface_canal_test(c.ctx, c.S, tol, mask & 1u ? &x.res : nullptr,
                                      mask & 2u ? &x.is_canal : nullptr);
    c.check("cyc_surface_canal_test", x.status);
  }
  FZ_LOG("canal_test tol %g -> %s", tol, cyc_status_name(r[0].status));
  FZ_CHECK(r[0].status == r[1].status && same_bits(&r[0].res, &r[1].res, sizeof(double)) &&
               r[0].is_canal == r[1].is_canal,
           "cyc_surface_canal_test not deterministic");
  if (mask == 0) {
    FZ_CHECK(r[0].status == CYC_E_NULL_ARGUMENT, "canal_test without outputs: %s",
             cyc_status_name(r[0].status));
  } else if (std::isnan(tol)) {
    FZ_CHECK(r[0].status == CYC_E_NOT_FINITE, "canal_test(NaN): %s",
             cyc_status_name(r[0].status));
  }
  if (r[0].status != CYC_OK) {
    FZ_CHECK(fz::is_sentinel(r[0].res) && r[0].is_canal == -77,
             "canal_test: %s but wrote an output", cyc_status_name(r[0].status));
    return;
  }
  if (mask & 1u)
    FZ_CHECK(std::isfinite(r[0].res) && r[0].res >= 0, "canal_test residual %g", r[0].res);
  if (mask & 2u) FZ_CHECK(r[0].is_canal == 0 || r[0].is_canal == 1, "is_canal %d", r[0].is_canal);
  if (mask == 3u)
    FZ_CHECK(r[0].is_canal == (r[0].res <= (tol > 0 ? tol : 1e-9)),
             "is_canal %d inconsistent with residual %g and tolerance %g", r[0].is_canal,
             r[0].res, tol);
}

void op_parameter_of(Input& in, Ctx& c) {
  const double u = param_u(in, c);
  double X[3];
  bool from_eval = false;
  double v0 = 0;
  switch (in.range(0, 3)) {
    case 0: {
      v0 = param_v(in);
      if (known_issue_avoid(c, u, v0)) return;
      const EvalResult e = eval_checked(c, u, v0, 1u);
      if (e.status != CYC_OK) return;
      std::memcpy(X, e.out[0], sizeof X);
      from_eval = true;
      break;
    }
    case 1: in.fill(X, 3, 1); break;
    case 2: in.fill(X, 3, 0); break;
    default: {
      cyc_circle ci;
      const int s = cyc_surface_circle(c.ctx, c.S, u, &ci);
      c.check("cyc_surface_circle", s);
      if (s != CYC_OK) return;
      std::memcpy(X, ci.center, sizeof X);
      break;
    }
  }
  double va = fz::sentinel(), vb = fz::sentinel();
  const int sa = cyc_surface_parameter_of(c.ctx, c.S, u, X, &va);
  c.check("cyc_surface_parameter_of", sa);
  const int sb = cyc_surface_parameter_of(c.ctx, c.S, u, X, &vb);
  c.check("cyc_surface_parameter_of", sb);
  FZ_LOG("parameter_of u = %.17g -> %s v = %.17g (from v0 = %.17g)", u, cyc_status_name(sa), va,
         v0);
  FZ_CHECK(sa == sb && same_bits(&va, &vb, sizeof va), "parameter_of not deterministic");
  if (sa != CYC_OK) {
    FZ_CHECK(fz::is_sentinel(va), "parameter_of: %s but wrote v", cyc_status_name(sa));
    return;
  }
  FZ_CHECK(std::isfinite(va) || va == HUGE_VAL, "parameter_of OK but v = %g", va);
  if (!from_eval || !std::isfinite(va)) return;
  // Round trip: x(u, parameter_of(u, x(u, v0))) = x(u, v0).
  const EvalResult e = eval_checked(c, u, va, 1u);
  if (e.status != CYC_OK) return;  // e.g. |v| > 1e100
  const Geometry g = geometry(c, u);
  FZ_CHECK(g.status == CYC_OK, "parameter_of OK but circle failed");
  FZ_CHECK_ACCURACY(c, u, v0, fz::dist3(e.out[0], X) <= 1e-6 * g.L,
           "parameter_of does not invert eval at u = %.17g: v0 = %.17g -> v = %.17g, "
           "points %.3g apart (scale %g)",
           u, v0, va, fz::dist3(e.out[0], X), g.L);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fz::choose_reentry(data, size);
  Input in(data, size);
  Ctx c;
  if (cyc_context_create(nullptr, &c.ctx) != CYC_OK) return 0;
  if (in.flag()) {
    fz::install_handler(c.ctx, c.log);
    c.logp = &c.log;
  }

  const bool prrs = in.flag();
  cyc_curve* curves[3] = {nullptr, nullptr, nullptr};
  const int ncurves = prrs ? 3 : 2;
  for (int i = 0; i < ncurves; ++i) curves[i] = build_curve(in, c, prrs);
  cyc_mobius m;
  const bool has_f = build_mobius(in, m);
  c.has_f = has_f;
  if (has_f) c.f = m;
  c.u0 = double(in.range(-16, 16)) / 8.0;
  c.u1 = c.u0 + double(in.range(1, 64)) / 16.0;

  cyc_surface* S = nullptr;
  int s = CYC_E_NULL_ARGUMENT;
  if (curves[0] && curves[1] && (!prrs || curves[2])) {
    s = prrs ? cyc_prrs_create(c.ctx, curves[0], curves[1], curves[2], has_f ? &m : nullptr,
                               c.u0, c.u1, &S)
             : cyc_prcs_create(c.ctx, curves[0], curves[1], has_f ? &m : nullptr, c.u0, c.u1,
                               &S);
    c.check(prrs ? "cyc_prrs_create" : "cyc_prcs_create", s);
  }
  // The surface owns copies of its inputs: destroy the curves now (ASan
  // would see a surface that kept pointers to them).
  for (cyc_curve* cu : curves) cyc_curve_destroy(c.ctx, cu);
  FZ_LOG("%s on [%g, %g] f=%s -> %s", prrs ? "PRRS" : "PRCS", c.u0, c.u1,
         has_f ? "given" : "NULL", cyc_status_name(s));
  if (s != CYC_OK) {
    cyc_context_destroy(c.ctx);
    return 0;
  }
  c.S = S;
  c.kind = prrs ? CYC_SURFACE_PRRS : CYC_SURFACE_PRCS;
  int kind = 0;
  FZ_CHECK(cyc_surface_kind(c.ctx, S, &kind) == CYC_OK && kind == c.kind, "kind %d", kind);

  const int nops = in.range(1, 24);
  for (int i = 0; i < nops; ++i) {
    switch (in.range(0, 8)) {
      case 0: op_eval(in, c); break;
      case 1: op_batch(in, c); break;
      case 2: op_grid(in, c); break;
      case 3: op_circle(in, c); break;
      case 4: op_sphere(in, c); break;
      case 5: op_ringed_data(in, c); break;
      case 6: op_ringed_sphere(in, c); break;
      case 7: op_canal_test(in, c); break;
      default: op_parameter_of(in, c); break;
    }
  }
  cyc_surface_destroy(c.ctx, S);
  cyc_context_destroy(c.ctx);
  return 0;
}
