// Fuzz target of the blends of the C ABI (SPEC §8d, issue 4):
// cyc_surface_derivatives_u, cyc_blend_canal, cyc_blend_ringed,
// cyc_blend_ringed_matched and cyc_continuity_report on two input surfaces built from fuzzed data (the
// Fig. 6-like cones of tests/blend_test.cpp, PRRS of three lines, PRCS of
// two lines or two cubics; coincident lines and wild coordinates make
// degenerate ones likely), with hostile arguments: NULL surfaces / ends /
// outputs, u outside the domain, v NaN / +-Inf, lambda 0 / negative / huge /
// NaN, K out of range, t0 >= t1, identical ends, n <= 0, NULL va.
//
// Oracles:
//  - every status is known, never CYC_E_INTERNAL; last status/message and the
//    error handler agree with it (fz::check_call); documented statuses for the
//    validation errors (NULL, K, t0 >= t1, NaN, n < 1); blends give
//    CYC_E_NOT_FINITE only for a non-finite or > 1e100 input;
//  - on error every output is untouched (sentinel prefill; the *out surface
//    pointer keeps its value); on OK every output is finite;
//  - every call made twice gives identical bits (blends: identical points of
//    the two surfaces at the ends and inside);
//  - OK blends: the end points x_i(u_i, v_ij) lie on the blend's circles at
//    t0 and t1 (distance relative to the geometry and derivative scale);
//    for well-scaled inputs (see `judged`), the continuity report of each
//    join has gap <= 1e-7 of the point scale, unless the join is
//    ill-conditioned (derivatives 1e6 times the geometry: not judged) or a
//    canal blend meets a non-canal input (its circle is another one);
//  - continuity reports: K and samples echo the input, 0 <= singular <= n,
//    the angle is in [0, pi/2], all measures are >= 0;
//  - cyc_optimize_blend (op_optimize, rare: each call is a Ceres solve, at
//    most 4 iterations on quadratures mostly 1..4, and an input's solves
//    are capped by kSolveBudget): fuzzed kind, ends, K, interval,
//    objective (weights, bounds, 0..2 targets and obstacles, NULL arrays,
//    negative counts, quadrature sizes) and options, NULL objective /
//    options / outputs. NULL pointers give NULL_ARGUMENT, otherwise the
//    status is one of the validation errors present; without any it is OK
//    or a blend status: the plain blend's own failure, OK where the plain
//    blend is OK and the objective moderate, NUMERICAL_OVERFLOW at most
//    where the start is valid (a reference call with a default objective
//    on the same nodes). On error nothing is written; on OK the summary
//    holds (final <= initial cost = the sum of its terms, termination,
//    iterations <= max_iterations, weight / 2 fairness at the start), the
//    ends keep surface, u, v and the fixed orders, lambda stays nonzero in
//    its bounds with the start's sign, the ends rebuild the same surface
//    through cyc_blend_*, well-scaled joins keep a small gap, and a second
//    call gives identical results.
//
// Input layout: see make_seeds.py (BlendEncoder), which mirrors this file.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "fuzz_common.hpp"

namespace {

using fz::Input;

struct Surf {
  cyc_surface* S = nullptr;
  double u0 = 0, u1 = 1;
  bool ws = false;     // built from moderate data only (judged geometrically)
  bool canal = false;  // a canal surface (PRCS, or the cones of revolution)
};

// Work units of Ceres solves an input may spend (see solve_work): about
// 0.5 s under ASan: the smoke run stays fast, no input nears the timeout.
constexpr int kSolveBudget = 60;

struct Ctx {
  cyc_context* ctx = nullptr;
  fz::HandlerLog log;
  fz::HandlerLog* logp = nullptr;
  Surf s[2];
  int solve_budget = kSolveBudget;
  void check(const char* fn, int s) { fz::check_call(fn, ctx, s, logp); }
};

bool finite_n(const double* v, int n) {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

// ------------------------------------------------------------ inputs

// A coordinate: moderate (well-scaled) or wild.
double coord(Input& in, bool& ws) {
  switch (in.range(0, 3)) {
    case 0: return in.moderate();
    case 1: ws = false; return in.wild();
    case 2: return double(in.range(-64, 64)) / 16.0;
    default: return double(in.range(-4, 4));
  }
}

void build_surface(Input& in, Ctx& c, int index) {
  Surf& s = c.s[index];
  const int mode = in.range(0, 4);
  if (mode == 0) return;  // NULL surface
  double p[3][12] = {};
  bool prrs = false, cubic = false, ws = true;
  s.u0 = 0.5;
  s.u1 = 1.0;
  switch (mode) {
    case 1: {  // tests/blend_test.cpp cone1 / cone2 (axes z / -x): PRRS of 3 lines
      const double pi = std::acos(-1.0);
      for (int k = 0; k < 3; ++k) {
        const double t = 2 * pi * k / 3 + 0.3, ct = std::cos(t), st = std::sin(t);
        const double A0[3] = {0, 0, 0}, A1[3] = {4, 0, 4};
        const double d0[3] = {ct, st, 1}, d1[3] = {-1, ct, st};
        for (int j = 0; j < 3; ++j) {
          p[k][j] = index ? A1[j] : A0[j];
          p[k][3 + j] = index ? d1[j] : d0[j];
        }
      }
      prrs = true;
      break;
    }
    case 2:  // PRRS of three lines
    case 3:  // PRCS of two lines
    case 4:  // PRCS of two polynomial cubics
      prrs = mode == 2;
      cubic = mode == 4;
      for (int i = 0; i < (prrs ? 3 : 2); ++i)
        for (int j = 0; j < (cubic ? 12 : 6); ++j) p[i][j] = coord(in, ws);
      if (in.rarely()) std::memcpy(p[1], p[0], sizeof p[0]);  // coincident curves
      if (in.flag()) {
        s.u0 = double(in.range(-8, 8)) / 4.0;
        s.u1 = s.u0 + double(in.range(1, 16)) / 4.0;
      }
      break;
  }
  if (index == 1 && mode >= 2) {  // move the second surface apart
    for (int i = 0; i < 3; ++i) p[i][0] += 6.0;
  }
  cyc_curve* cu[3] = {nullptr, nullptr, nullptr};
  int st = CYC_OK;
  for (int i = 0; i < (prrs ? 3 : 2) && st == CYC_OK; ++i) {
    st = cubic ? cyc_curve_create_polynomial(c.ctx, 3, p[i], 3, &cu[i])
               : cyc_curve_create_line(c.ctx, p[i], p[i] + 3, &cu[i]);
    c.check("cyc_curve_create", st);
  }
  if (st == CYC_OK) {
    st = prrs ? cyc_prrs_create(c.ctx, cu[0], cu[1], cu[2], nullptr, s.u0, s.u1, &s.S)
              : cyc_prcs_create(c.ctx, cu[0], cu[1], nullptr, s.u0, s.u1, &s.S);
    c.check("cyc_*_create", st);
    if (st != CYC_OK) s.S = nullptr;
  }
  for (cyc_curve* x : cu) cyc_curve_destroy(c.ctx, x);
  s.ws = ws;
  s.canal = mode != 2;
  FZ_LOG("surface %d mode %d -> %s", index, mode, cyc_status_name(st));
}

// Which surface: A, B or NULL (the third choice).
const Surf* pick(Input& in, Ctx& c) {
  const int k = in.range(0, 3);
  return k < 2 ? &c.s[k] : nullptr;
}

// u: an end of the domain, inside, just outside, or wild.
double param_u(Input& in, const Surf* s, bool& ws) {
  const double u0 = s ? s->u0 : 0.0, u1 = s ? s->u1 : 1.0;
  switch (in.range(0, 4)) {
    case 0: return u0;
    case 1: return u1;
    case 2: return u0 + (u1 - u0) * double(in.range(0, 16)) / 16.0;
    case 3: return in.flag() ? u0 - double(in.range(1, 64)) / 16.0
                             : u1 + double(in.range(1, 64)) / 16.0;
    default: ws = false; return in.wild();
  }
}

// v: the generator (+-Inf), tan of a moderate angle, moderate, or wild.
double param_v(Input& in, bool& ws) {
  switch (in.range(0, 4)) {
    case 0: return in.flag() ? HUGE_VAL : -HUGE_VAL;
    case 1: return std::tan(double(in.range(-150, 150)) / 100.0);
    case 2: return in.moderate();
    case 3: return double(in.range(-4, 4));
    default: ws = false; return in.wild();
  }
}

double param_lambda(Input& in, bool& ws) {
  switch (in.range(0, 3)) {
    case 0: return 0.0;
    case 1: return in.flag() ? 1.0 : -1.0;
    case 2: {
      const double l = double(in.range(-64, 64)) / 16.0;
      if (l == 0) return 0.0;
      return l;
    }
    default: ws = false; return in.wild();
  }
}

// K: mostly valid, sometimes out of range on either side.
int param_K(Input& in) {
  if (in.rarely()) {
    static constexpr int kBad[] = {-1, -2, CYC_MAX_BLEND_ORDER + 1, 100, INT32_MIN, INT32_MAX};
    return kBad[in.range(0, 5)];
  }
  return in.range(0, CYC_MAX_BLEND_ORDER);
}

// ------------------------------------------------------------ geometry

// Distance of X from the circle of S at u (NaN if the circle is unavailable).
double circle_distance(Ctx& c, const cyc_surface* S, double u, const double* X, double* scale) {
  cyc_circle C;
  const int st = cyc_surface_circle(c.ctx, S, u, &C);
  c.check("cyc_surface_circle", st);
  if (st != CYC_OK || !(C.radius2 >= 0)) return std::numeric_limits<double>::quiet_NaN();
  double d[3] = {X[0] - C.center[0], X[1] - C.center[1], X[2] - C.center[2]};
  const double h = fz::dot3(d, C.normal);
  double q[3] = {d[0] - h * C.normal[0], d[1] - h * C.normal[1], d[2] - h * C.normal[2]};
  const double r = std::sqrt(C.radius2);
  *scale = std::max({*scale, fz::norm3(C.center), r, fz::norm3(X)});
  return std::hypot(h, fz::norm3(q) - r);
}

// Length scale of the frame of S at u: |center| and radius of the circle
// and, for canal surfaces, of the touching sphere (as fuzz_eval's
// Geometry::L); 1 if unavailable. Two evaluations of the same point by
// different arithmetic agree relative to this, not to |x| (a small point on
// a huge circle is a cancellation).
double frame_scale(Ctx& c, const cyc_surface* S, double u) {
  double L = 1;
  cyc_circle C;
  const int st = cyc_surface_circle(c.ctx, S, u, &C);
  c.check("cyc_surface_circle", st);
  if (st == CYC_OK && C.radius2 >= 0)
    L = std::max({L, fz::norm3(C.center), std::sqrt(C.radius2)});
  cyc_sphere Sp;
  const int ss = cyc_surface_sphere(c.ctx, S, u, &Sp);
  c.check("cyc_surface_sphere", ss);
  if (ss == CYC_OK && Sp.radius2 >= 0)
    L = std::max({L, fz::norm3(Sp.center), std::sqrt(Sp.radius2)});
  return std::isfinite(L) ? L : 1.0;
}

// The lambda the library uses for an end (cyclide::blend_lambda).
double effective_lambda(const cyc_blend_end& e, int index, double u0, double u1) {
  if (e.lambda != 0.0) return e.lambda;
  const double to_upper = std::abs(u1 - e.u), to_lower = std::abs(e.u - u0);
  if (index == 0) return to_upper <= to_lower ? 1.0 : -1.0;
  return to_lower <= to_upper ? 1.0 : -1.0;
}

// ------------------------------------------------------------ operations

void op_derivatives(Input& in, Ctx& c) {
  const Surf* s = pick(in, c);
  bool ws = true;
  const double u = param_u(in, s, ws), v = param_v(in, ws);
  const int K = param_K(in);
  const bool null_out = in.rarely();
  double out[3 * (CYC_MAX_BLEND_ORDER + 2)], again[3 * (CYC_MAX_BLEND_ORDER + 2)];
  fz::fill_sentinel(out, 3 * (CYC_MAX_BLEND_ORDER + 2));
  fz::fill_sentinel(again, 3 * (CYC_MAX_BLEND_ORDER + 2));
  const cyc_surface* S = s ? s->S : nullptr;
  const int st = cyc_surface_derivatives_u(c.ctx, S, u, v, K, null_out ? nullptr : out);
  c.check("cyc_surface_derivatives_u", st);
  if (!S || null_out) FZ_CHECK(st == CYC_E_NULL_ARGUMENT, "derivatives_u: NULL gives %d", st);
  else if (K < 0) FZ_CHECK(st == CYC_E_INVALID_ARGUMENT, "derivatives_u: K = %d gives %d", K, st);
  else if (K > CYC_MAX_BLEND_ORDER)
    FZ_CHECK(st == CYC_E_DEGREE_TOO_HIGH, "derivatives_u: K = %d gives %d", K, st);
  else if (!(std::abs(u) <= 1e100) || std::isnan(v))
    FZ_CHECK(st == CYC_E_NOT_FINITE, "derivatives_u: u %g v %g gives %d", u, v, st);
  const int used = (K >= 0 && K <= CYC_MAX_BLEND_ORDER) ? 3 * (K + 1) : 0;
  if (st != CYC_OK) {
    FZ_CHECK(fz::all_sentinel(out, 3 * (CYC_MAX_BLEND_ORDER + 2)),
             "derivatives_u: output written on error %d", st);
    return;
  }
  FZ_CHECK(finite_n(out, used), "derivatives_u: non-finite output on OK");
  FZ_CHECK(fz::all_sentinel(out + used, 3 * (CYC_MAX_BLEND_ORDER + 2) - used),
           "derivatives_u: wrote past 3(K+1)");
  const int st2 = cyc_surface_derivatives_u(c.ctx, S, u, v, K, again);
  c.check("cyc_surface_derivatives_u", st2);
  FZ_CHECK(st2 == st && std::memcmp(out, again, sizeof out) == 0,
           "derivatives_u: not deterministic");
  // Order 0 is the point of eval (finite v; the generator is v = +-1e300 to
  // rounding: not compared).
  if (std::isfinite(v) && std::isfinite(u) && s->ws && ws && std::abs(v) <= 1e6) {
    double X[3];
    const int se = cyc_surface_eval(c.ctx, S, u, v, X, nullptr, nullptr, nullptr);
    c.check("cyc_surface_eval", se);
    if (se == CYC_OK) {
      const double scale = std::max({frame_scale(c, S, u), fz::norm3(X), fz::norm3(out)});
      FZ_CHECK(fz::dist3(X, out) <= 1e-9 * scale, "derivatives_u: x %.17g from eval (scale %g)",
               fz::dist3(X, out), scale);
    }
  }
}

void blend_end(Input& in, Ctx& c, cyc_blend_end& e, const Surf*& s, bool& ws) {
  s = pick(in, c);
  e.surface = s ? s->S : nullptr;
  if (!e.surface) ws = false;
  if (s && !s->ws) ws = false;
  e.u = param_u(in, s, ws);
  if (s && !(e.u >= s->u0 - 4 && e.u <= s->u1 + 4)) ws = false;
  for (double& v : e.v) v = param_v(in, ws);
  e.lambda = param_lambda(in, ws);
  // Higher reparameterization derivatives phi'', ...: mostly none, else
  // moderate dyadic values, rarely a non-finite one.
  for (double& p : e.phi) p = 0.0;
  if (in.rarely())
    for (double& p : e.phi) p = in.range(-16, 16) / 8.0;
  if (in.rarely()) e.phi[in.range(0, CYC_MAX_BLEND_ORDER - 2)] = in.flag() ? NAN : 1e300;
}

// The largest |phi^(m)| of an end (lambda and phi[]): the scale of the
// reparameterized derivatives is at most (2 max(1, this) (t1 - t0))^l |x^(l)|.
double jet_bound(const cyc_blend_end& e, double lam) {
  double m = std::max(1.0, std::abs(lam));
  for (double p : e.phi) m = std::max(m, std::abs(p));
  return 2 * m;
}

// The blend interval: [0, 1], moderate (maybe reversed), empty, or wild.
void param_t(Input& in, double& t0, double& t1, bool& ws) {
  switch (in.range(0, 3)) {
    case 0: t0 = 0; t1 = 1; break;
    case 1:
      t0 = in.moderate();
      t1 = in.moderate();
      if (!(t1 - t0 >= 1.0 / 16)) ws = false;
      break;
    case 2: t0 = t1 = in.moderate(); break;
    default:
      t0 = in.wild();
      t1 = in.wild();
      ws = false;
      break;
  }
}

void op_blend(Input& in, Ctx& c, bool canal, bool matched = false) {
  const char* fn =
      canal ? "cyc_blend_canal" : matched ? "cyc_blend_ringed_matched" : "cyc_blend_ringed";
  bool ws = true;
  cyc_blend_end ends[2];
  const Surf* es[2];
  blend_end(in, c, ends[0], es[0], ws);
  if (in.rarely()) {  // identical ends
    ends[1] = ends[0];
    es[1] = es[0];
  } else {
    blend_end(in, c, ends[1], es[1], ws);
  }
  const int K = param_K(in);
  double t0 = 0, t1 = 1;
  param_t(in, t0, t1, ws);
  const int nulls = in.rarely() ? in.range(1, 3) : 0;  // 1 start, 2 end, 3 out
  cyc_surface* const kSentinelOut = reinterpret_cast<cyc_surface*>(uintptr_t(0x5eed));
  cyc_surface* out = kSentinelOut;
  cyc_surface* out2 = kSentinelOut;
  auto call = [&](cyc_surface** o) {
    const cyc_blend_end* a = nulls == 1 ? nullptr : &ends[0];
    const cyc_blend_end* b = nulls == 2 ? nullptr : &ends[1];
    cyc_surface** oo = nulls == 3 ? nullptr : o;
    if (canal) return cyc_blend_canal(c.ctx, a, b, K, t0, t1, oo);
    return matched ? cyc_blend_ringed_matched(c.ctx, a, b, K, t0, t1, oo)
                   : cyc_blend_ringed(c.ctx, a, b, K, t0, t1, oo);
  };
  for (const cyc_blend_end& E : ends)
    FZ_LOG("  end: u %a v %a %a %a lambda %a phi'' %a", E.u, E.v[0], E.v[1], E.v[2], E.lambda,
           E.phi[0]);
  FZ_LOG("  K %d t0 %a t1 %a", K, t0, t1);
  const int st = call(&out);
  c.check(fn, st);
  const int count = canal ? 2 : 3;
  // Validation order: NULLs, K, u / lambda / t (finite, |x| <= 1e100), t0 < t1,
  // v not NaN.
  auto bad = [](double x) { return !(std::abs(x) <= 1e100); };
  bool nan_in = bad(t0) || bad(t1), nan_v = false;
  for (const cyc_blend_end& e : ends) {
    if (bad(e.u) || bad(e.lambda)) nan_in = true;
    for (int m = 2; m <= K && K <= CYC_MAX_BLEND_ORDER; ++m)
      if (bad(e.phi[m - 2])) nan_in = true;
    for (int j = 0; j < count; ++j)
      if (std::isnan(e.v[j])) nan_v = true;
  }
  if (nulls || !ends[0].surface || !ends[1].surface)
    FZ_CHECK(st == CYC_E_NULL_ARGUMENT, "%s: NULL gives %s", fn, cyc_status_name(st));
  else if (K < (canal ? 2 : 1))
    FZ_CHECK(st == CYC_E_INVALID_ARGUMENT, "%s: K = %d gives %s", fn, K, cyc_status_name(st));
  else if (K > CYC_MAX_BLEND_ORDER)
    FZ_CHECK(st == CYC_E_DEGREE_TOO_HIGH, "%s: K = %d gives %s", fn, K, cyc_status_name(st));
  else if (nan_in)
    FZ_CHECK(st == CYC_E_NOT_FINITE, "%s: non-finite input gives %s", fn, cyc_status_name(st));
  else if (!(t1 > t0))
    FZ_CHECK(st == CYC_E_BAD_DOMAIN, "%s: t0 >= t1 gives %s", fn, cyc_status_name(st));
  else if (nan_v)
    FZ_CHECK(st == CYC_E_NOT_FINITE, "%s: v NaN gives %s", fn, cyc_status_name(st));
  // NOT_FINITE means a non-finite (or > 1e100) input, nothing else.
  if (st == CYC_E_NOT_FINITE)
    FZ_CHECK(nan_in || nan_v, "%s: NOT_FINITE for valid inputs", fn);
  if (st != CYC_OK) {
    FZ_CHECK(out == kSentinelOut, "%s: *out written on error", fn);
    return;
  }
  FZ_CHECK(out != nullptr && out != kSentinelOut, "%s: OK without a surface", fn);
  // Determinism and finiteness: the same call gives the same surface.
  const int st2 = call(&out2);
  c.check(fn, st2);
  FZ_CHECK(st2 == CYC_OK, "%s: second call gives %s", fn, cyc_status_name(st2));
  double d0 = 0, d1 = 0;
  const int sd = cyc_surface_domain(c.ctx, out, &d0, &d1);
  c.check("cyc_surface_domain", sd);
  FZ_CHECK(sd == CYC_OK && d0 == t0 && d1 == t1, "%s: domain [%g, %g] != [%g, %g]", fn, d0, d1,
           t0, t1);
  int kind = 0;
  const int sk = cyc_surface_kind(c.ctx, out, &kind);
  c.check("cyc_surface_kind", sk);
  FZ_CHECK(kind == (canal ? CYC_SURFACE_PRCS : CYC_SURFACE_PRRS), "%s: kind %d", fn, kind);
  for (int i = 0; i <= 4; ++i) {
    const double t = i == 4 ? t1 : t0 + (t1 - t0) * i / 4.0;
    for (double v : {0.0, 1.0, -2.0}) {
      double X[3], Y[3];
      fz::fill_sentinel(X, 3);
      fz::fill_sentinel(Y, 3);
      const int a = cyc_surface_eval(c.ctx, out, t, v, X, nullptr, nullptr, nullptr);
      c.check("cyc_surface_eval", a);
      const int b = cyc_surface_eval(c.ctx, out2, t, v, Y, nullptr, nullptr, nullptr);
      c.check("cyc_surface_eval", b);
      FZ_CHECK(a == b && std::memcmp(X, Y, sizeof X) == 0, "%s: not deterministic at t %g", fn,
               t);
      if (a == CYC_OK) FZ_CHECK(fz::finite3(X), "%s: eval OK with non-finite point", fn);
    }
  }
  cyc_surface_destroy(c.ctx, out2);

  // The end points lie on the blend's end circles. Scale: the geometry and
  // the derivative terms lambda^l x^(l) (t1 - t0)^l the Hermite curves carry.
  for (int e = 0; e < 2; ++e) {
    const cyc_blend_end& E = ends[e];
    const double lam = effective_lambda(E, e, es[e]->u0, es[e]->u1);
    for (int j = 0; j < count; ++j) {
      double d[3 * (CYC_MAX_BLEND_ORDER + 1)];
      const int sd2 = cyc_surface_derivatives_u(c.ctx, E.surface, E.u, E.v[j], K, d);
      c.check("cyc_surface_derivatives_u", sd2);
      FZ_CHECK(sd2 == CYC_OK, "%s: OK but derivatives_u of an end fails: %s", fn,
               cyc_status_name(sd2));
      double scale = 0, f = 1;
      for (int l = 0; l <= K; ++l) {
        scale = std::max(scale, fz::norm3(d + 3 * l) * f);
        f *= jet_bound(E, lam) * (t1 - t0);
      }
      const double dist = circle_distance(c, out, e ? t1 : t0, d, &scale);
      if (!std::isfinite(dist) || !std::isfinite(scale)) continue;  // circle unavailable
      FZ_LOG("  end %d point %d: distance %g, scale %g", e, j, dist, scale);
      if (ws)
        FZ_CHECK(dist <= 1e-7 * scale, "%s: end %d point %d is %g from the circle (scale %g)",
                 fn, e, j, dist, scale);
    }
  }

  // Well-scaled joins: small gap in the continuity report. A canal blend
  // has the end circles of its inputs only where they are canal surfaces
  // (its circle is fixed by the two points and their normal planes; a
  // ringed input's circle is another one through the two points).
  if (ws && (!canal || (es[0]->canal && es[1]->canal))) {
    for (int e = 0; e < 2; ++e) {
      const cyc_blend_end& E = ends[e];
      const double lam = effective_lambda(E, e, es[e]->u0, es[e]->u1);
      cyc_continuity R;
      const int sr =
          cyc_continuity_report(c.ctx, E.surface, E.u, lam, out, e ? t1 : t0, K, nullptr, 16, &R);
      c.check("cyc_continuity_report", sr);
      if (sr != CYC_OK) continue;
      bool conditioned = std::isfinite(R.point_scale);
      for (int l = 1; l <= K; ++l)
        if (!(R.point_scale_l[l] <= 1e6 * std::max(1.0, R.point_scale))) conditioned = false;
      FZ_LOG("  join %d: gap %g scale %g%s", e, R.max_gap, R.point_scale,
             conditioned ? "" : " (ill-conditioned: not judged)");
      if (conditioned)
        FZ_CHECK(R.max_gap <= 1e-7 * std::max(R.point_scale, 1e-300),
                 "%s: join %d gap %g (scale %g)", fn, e, R.max_gap, R.point_scale);
    }
  }
  cyc_surface_destroy(c.ctx, out);
}

void op_continuity(Input& in, Ctx& c) {
  const Surf* a = pick(in, c);
  const Surf* b = pick(in, c);
  bool ws = true;
  const double ua = param_u(in, a, ws), ub = param_u(in, b, ws);
  const double lambda = param_lambda(in, ws);
  const int K = param_K(in);
  int n;
  switch (in.range(0, 3)) {
    case 0: n = in.range(1, 8); break;
    case 1: n = in.range(-2, 0); break;
    case 2: n = in.range(1, 64); break;
    default: n = in.flag() ? INT32_MIN : 1; break;
  }
  const bool null_va = in.flag();
  std::vector<double> va = fz::exact(size_t(std::max(n, 0)));
  if (!null_va)
    for (int i = 0; i < std::min(n, 8); ++i) va[size_t(i)] = param_v(in, ws);
  const bool null_out = in.rarely();
  cyc_continuity R, R2, blank;
  std::memset(&blank, 0xA5, sizeof blank);
  R = R2 = blank;
  const cyc_surface* A = a ? a->S : nullptr;
  const cyc_surface* B = b ? b->S : nullptr;
  const double* vp = null_va ? nullptr : va.data();
  const int st =
      cyc_continuity_report(c.ctx, A, ua, lambda, B, ub, K, vp, n, null_out ? nullptr : &R);
  c.check("cyc_continuity_report", st);
  if (!A || !B || null_out)
    FZ_CHECK(st == CYC_E_NULL_ARGUMENT, "continuity_report: NULL gives %d", st);
  else if (K < 0 || (K <= CYC_MAX_BLEND_ORDER && n < 1))
    FZ_CHECK(st == CYC_E_INVALID_ARGUMENT, "continuity_report: K %d n %d gives %d", K, n, st);
  else if (K > CYC_MAX_BLEND_ORDER)
    FZ_CHECK(st == CYC_E_DEGREE_TOO_HIGH, "continuity_report: K %d gives %d", K, st);
  else if (!(std::abs(ua) <= 1e100) || !(std::abs(ub) <= 1e100) || !(std::abs(lambda) <= 1e100))
    FZ_CHECK(st == CYC_E_NOT_FINITE, "continuity_report: non-finite input gives %d", st);
  if (st != CYC_OK) {
    FZ_CHECK(std::memcmp(&R, &blank, sizeof R) == 0, "continuity_report: written on error");
    return;
  }
  FZ_CHECK(R.K == K && R.samples == n, "continuity_report: K %d samples %d", R.K, R.samples);
  FZ_CHECK(R.singular_samples >= 0 && R.singular_samples <= n, "singular_samples %d",
           R.singular_samples);
  FZ_CHECK(std::isfinite(R.max_gap) && R.max_gap >= 0 && std::isfinite(R.point_scale) &&
               R.point_scale >= 0,
           "continuity_report: gap %g scale %g", R.max_gap, R.point_scale);
  FZ_CHECK(R.max_normal_angle >= 0 && R.max_normal_angle <= 1.5707963267948968,
           "continuity_report: angle %g", R.max_normal_angle);
  for (int l = 0; l <= CYC_MAX_BLEND_ORDER; ++l) {
    const bool used = l <= K;
    FZ_CHECK(std::isfinite(R.point_jump[l]) && R.point_jump[l] >= 0 &&
                 std::isfinite(R.point_scale_l[l]) && R.point_scale_l[l] >= 0 &&
                 std::isfinite(R.circle_jump[l]) && R.circle_jump[l] >= 0,
             "continuity_report: order %d jump %g scale %g circle %g", l, R.point_jump[l],
             R.point_scale_l[l], R.circle_jump[l]);
    if (!used)
      FZ_CHECK(R.point_jump[l] == 0 && R.point_scale_l[l] == 0 && R.circle_jump[l] == 0,
               "continuity_report: order %d > K written", l);
  }
  const int st2 = cyc_continuity_report(c.ctx, A, ua, lambda, B, ub, K, vp, n, &R2);
  c.check("cyc_continuity_report", st2);
  FZ_CHECK(st2 == st && std::memcmp(&R, &R2, sizeof R) == 0,
           "continuity_report: not deterministic");
  // A surface joins itself: zero gap and jumps at the same circle, lambda 1.
  if (A == B && ua == ub && lambda == 1.0 && ws && a->ws) {
    FZ_CHECK(R.max_gap <= 1e-9 * std::max(R.point_scale, 1e-300),
             "continuity_report: self-join gap %g (scale %g)", R.max_gap, R.point_scale);
    FZ_CHECK(R.circle_jump[0] == 0, "self-join circle jump %g", R.circle_jump[0]);
  }
}

// ------------------------------------------------------------ optimizer

// A fuzzed call of cyc_optimize_blend: its arguments and what the harness
// knows about them. Not copied: obj points into the target/obstacle arrays.
struct OptCall {
  int kind = CYC_BLEND_RINGED;
  cyc_blend_end ends[2] = {};
  const Surf* es[2] = {nullptr, nullptr};
  int K = 1;
  double t0 = 0, t1 = 1;
  cyc_blend_objective obj;
  cyc_optimize_options opt;
  bool null_obj = false, null_opt = false;
  std::vector<cyc_blend_target> targets;  // exactly sized: ASan sees reads past count
  std::vector<cyc_blend_obstacle> obstacles;
  int nulls = 0;          // 1 start, 2 end, 3 out, 4 start_out, 5 end_out, 6 summary
  bool ws = true;         // ends and interval well-scaled (as op_blend)
  bool moderate = true;   // objective and options free of huge or wild numbers
};

// The outputs of one call, sentinel-filled before it.
struct OptOut {
  static cyc_surface* sentinel_surface() {
    return reinterpret_cast<cyc_surface*>(uintptr_t(0x5eed));
  }
  cyc_surface* S = sentinel_surface();
  cyc_blend_end ends[2];
  cyc_optimize_summary sum;
  OptOut() {
    std::memset(ends, 0xA5, sizeof ends);
    std::memset(&sum, 0xA5, sizeof sum);
  }
  bool untouched() const {
    OptOut blank;
    return S == blank.S && std::memcmp(ends, blank.ends, sizeof ends) == 0 &&
           std::memcmp(&sum, &blank.sum, sizeof sum) == 0;
  }
};

int param_kind(Input& in) {
  if (in.rarely()) {
    static constexpr int kBad[] = {-1, 2, 3, INT32_MIN, INT32_MAX};
    return kBad[in.range(0, 4)];
  }
  return in.flag() ? CYC_BLEND_RINGED : CYC_BLEND_CANAL;
}

// A number of the objective or the options: mostly its default, else a
// sixteenth in [0, 4], a small integer, 0, negative, huge (valid for
// weights and upper bounds) or wild (NaN, Inf, raw bits).
void param_real(Input& in, double& x, bool& moderate) {
  if (!in.rarely()) return;
  switch (in.range(0, 5)) {
    case 0: x = in.range(0, 64) / 16.0; break;
    case 1: x = in.range(0, 8); break;
    case 2: x = 0.0; break;
    case 3: x = -in.range(1, 64) / 16.0; break;
    case 4: x = 1e300; moderate = false; break;
    default: x = in.wild(); moderate = false; break;
  }
}

// Quadrature sizes: mostly 1..4 (each evaluation of the objective, and so
// each Ceres iteration, stays cheap), rarely the largest or out of range.
int param_quadrature(Input& in) {
  if (in.rarely()) {
    static constexpr int kEdge[] = {0, -1, CYC_MAX_QUADRATURE + 1, INT32_MIN, CYC_MAX_QUADRATURE};
    return kEdge[in.range(0, 4)];
  }
  return in.range(1, 4);
}

// An array count: 0..2, or rarely negative or positive with a NULL array.
int param_count(Input& in, bool& null_array) {
  null_array = false;
  if (!in.rarely()) return in.range(0, 2);
  if (in.flag()) return in.flag() ? -1 : INT32_MIN;
  null_array = true;
  return in.range(1, 2);
}

void fuzz_targets(Input& in, OptCall& o) {
  bool null_array;
  const int n = param_count(in, null_array);
  o.targets.assign(size_t(null_array ? 0 : std::max(n, 0)), cyc_blend_target{});
  for (cyc_blend_target& T : o.targets) {
    for (double& x : T.point) x = coord(in, o.moderate);
    switch (in.range(0, 2)) {
      case 0: T.t = o.t0 + (o.t1 - o.t0) * in.range(0, 16) / 16.0; break;
      case 1: T.t = in.moderate(); break;
      default: T.t = in.wild(); break;
    }
    if (!(std::abs(T.t) <= 1e3)) o.moderate = false;
  }
  o.obj.targets = null_array ? nullptr : o.targets.data();
  o.obj.target_count = n;
}

void fuzz_obstacles(Input& in, OptCall& o) {
  bool null_array;
  const int n = param_count(in, null_array);
  o.obstacles.assign(size_t(null_array ? 0 : std::max(n, 0)), cyc_blend_obstacle{});
  for (cyc_blend_obstacle& B : o.obstacles) {
    for (double& x : B.center) x = coord(in, o.moderate);
    switch (in.range(0, 3)) {
      case 0: B.radius = in.range(0, 64) / 16.0; break;
      case 1: B.radius = 0.0; break;
      case 2: B.radius = -in.range(1, 16) / 16.0; break;
      default: B.radius = in.wild(); o.moderate = false; break;
    }
  }
  o.obj.obstacles = null_array ? nullptr : o.obstacles.data();
  o.obj.obstacle_count = n;
}

void fuzz_objective(Input& in, OptCall& o) {
  cyc_blend_objective_init(&o.obj);
  o.null_obj = in.rarely();  // the defaults (quadrature 8 x 4)
  if (o.null_obj) return;
  for (double* x : {&o.obj.fairness, &o.obj.regularity, &o.obj.min_determinant,
                    &o.obj.min_speed, &o.obj.target_weight, &o.obj.clearance,
                    &o.obj.obstacle_weight})
    param_real(in, *x, o.moderate);
  fuzz_targets(in, o);
  fuzz_obstacles(in, o);
  o.obj.quadrature_t = param_quadrature(in);
  o.obj.quadrature_v = param_quadrature(in);
}

// free_orders: 0..K, rarely out of range.
int param_free_orders(Input& in, int K) {
  if (in.rarely()) {
    const int kBad[] = {-1, INT32_MIN, CYC_MAX_BLEND_ORDER + 1, std::min(K, 100) + 1};
    return kBad[in.range(0, 3)];
  }
  return in.range(0, std::max(0, std::min(K, CYC_MAX_BLEND_ORDER)));
}

void fuzz_options(Input& in, OptCall& o) {
  cyc_optimize_options_init(&o.opt);
  o.null_opt = in.rarely();  // the defaults (50 iterations: rare, slow)
  if (o.null_opt) return;
  for (double* x : {&o.opt.lambda_min_ratio, &o.opt.lambda_max_ratio, &o.opt.higher_bound,
                    &o.opt.function_tolerance, &o.opt.gradient_tolerance,
                    &o.opt.parameter_tolerance, &o.opt.circle_parameter_range})
    param_real(in, *x, o.moderate);
  o.opt.free_orders = param_free_orders(in, o.K);
  o.opt.max_iterations = in.rarely() ? (in.flag() ? -1 : INT32_MIN) : in.range(0, 4);
}

void fuzz_call(Input& in, Ctx& c, OptCall& o) {
  o.kind = param_kind(in);
  blend_end(in, c, o.ends[0], o.es[0], o.ws);
  if (in.rarely()) {  // identical ends
    o.ends[1] = o.ends[0];
    o.es[1] = o.es[0];
  } else {
    blend_end(in, c, o.ends[1], o.es[1], o.ws);
  }
  o.K = param_K(in);
  param_t(in, o.t0, o.t1, o.ws);
  fuzz_objective(in, o);
  fuzz_options(in, o);
  o.nulls = in.rarely() ? in.range(1, 6) : 0;
}

int call_optimize(Ctx& c, const OptCall& o, OptOut& r, bool all_outputs) {
  const int nulls = all_outputs ? 0 : o.nulls;
  return cyc_optimize_blend(c.ctx, o.kind, nulls == 1 ? nullptr : &o.ends[0],
                            nulls == 2 ? nullptr : &o.ends[1], o.K, o.t0, o.t1,
                            o.null_obj ? nullptr : &o.obj, o.null_opt ? nullptr : &o.opt,
                            nulls == 3 ? nullptr : &r.S, nulls == 4 ? nullptr : &r.ends[0],
                            nulls == 5 ? nullptr : &r.ends[1], nulls == 6 ? nullptr : &r.sum);
}

// ---- the statuses a call may give

constexpr unsigned bit(int status) { return 1u << status; }  // validation statuses 1..5

// A number of the objective / options: NaN or Inf is NOT_FINITE, < 0 invalid.
unsigned number_status(double x) {
  if (!std::isfinite(x)) return bit(CYC_E_NOT_FINITE);
  return x < 0 ? bit(CYC_E_INVALID_ARGUMENT) : 0;
}

bool input_ok(double x) { return std::abs(x) <= 1e100; }

unsigned objective_statuses(const cyc_blend_objective& b) {
  unsigned m = 0;
  for (double x : {b.fairness, b.regularity, b.min_determinant, b.min_speed, b.target_weight,
                   b.clearance, b.obstacle_weight})
    m |= number_status(x);
  if (!(b.min_determinant > 0 && b.min_determinant < 1) || !(b.min_speed > 0))
    m |= bit(CYC_E_INVALID_ARGUMENT);
  for (int q : {b.quadrature_t, b.quadrature_v})
    if (q < 1 || q > CYC_MAX_QUADRATURE) m |= bit(CYC_E_INVALID_ARGUMENT);
  if (b.target_count < 0 || b.obstacle_count < 0) m |= bit(CYC_E_INVALID_ARGUMENT);
  if ((b.target_count > 0 && !b.targets) || (b.obstacle_count > 0 && !b.obstacles))
    m |= bit(CYC_E_NULL_ARGUMENT);
  for (int q = 0; b.targets && q < b.target_count; ++q) {
    const cyc_blend_target& T = b.targets[q];
    if (!input_ok(T.point[0]) || !input_ok(T.point[1]) || !input_ok(T.point[2]) || !input_ok(T.t))
      m |= bit(CYC_E_NOT_FINITE);
  }
  for (int q = 0; b.obstacles && q < b.obstacle_count; ++q) {
    const cyc_blend_obstacle& B = b.obstacles[q];
    if (!input_ok(B.center[0]) || !input_ok(B.center[1]) || !input_ok(B.center[2]) ||
        !input_ok(B.radius))
      m |= bit(CYC_E_NOT_FINITE);
    if (B.radius < 0) m |= bit(CYC_E_INVALID_ARGUMENT);
  }
  return m;
}

unsigned options_statuses(const cyc_optimize_options& p, int K) {
  unsigned m = 0;
  for (double x : {p.lambda_min_ratio, p.lambda_max_ratio, p.higher_bound, p.function_tolerance,
                   p.gradient_tolerance, p.parameter_tolerance, p.circle_parameter_range})
    m |= number_status(x);
  if (!(p.lambda_min_ratio > 0 && p.lambda_min_ratio <= 1) || !(p.lambda_max_ratio >= 1))
    m |= bit(CYC_E_INVALID_ARGUMENT);
  if (p.free_orders < 0 || p.free_orders > K || p.max_iterations < 0)
    m |= bit(CYC_E_INVALID_ARGUMENT);
  return m;
}

// The ends, K and the interval, as op_blend validates them.
unsigned blend_statuses(const OptCall& o) {
  unsigned m = 0;
  if (o.kind != CYC_BLEND_CANAL && o.kind != CYC_BLEND_RINGED) m |= bit(CYC_E_INVALID_ARGUMENT);
  if (o.K < (o.kind == CYC_BLEND_CANAL ? 2 : 1)) m |= bit(CYC_E_INVALID_ARGUMENT);
  if (o.K > CYC_MAX_BLEND_ORDER) m |= bit(CYC_E_DEGREE_TOO_HIGH);
  if (!input_ok(o.t0) || !input_ok(o.t1)) m |= bit(CYC_E_NOT_FINITE);
  else if (!(o.t1 > o.t0)) m |= bit(CYC_E_BAD_DOMAIN);
  const int count = o.kind == CYC_BLEND_CANAL ? 2 : 3;
  for (const cyc_blend_end& e : o.ends) {
    if (!input_ok(e.u) || !input_ok(e.lambda)) m |= bit(CYC_E_NOT_FINITE);
    for (int k = 2; k <= o.K && o.K <= CYC_MAX_BLEND_ORDER; ++k)
      if (!input_ok(e.phi[k - 2])) m |= bit(CYC_E_NOT_FINITE);
    for (int j = 0; j < count; ++j)
      if (std::isnan(e.v[j])) m |= bit(CYC_E_NOT_FINITE);
  }
  return m;
}

bool required_null(const OptCall& o) {
  return (o.nulls >= 1 && o.nulls <= 3) || !o.ends[0].surface || !o.ends[1].surface;
}

// Statuses of a start blend that the optimizer retries with scaled lambdas.
bool degenerate(int s) {
  return s == CYC_E_DEPENDENT_PLANES || s == CYC_E_COLLINEAR_POINTS || s == CYC_E_ZERO_TANGENT ||
         s == CYC_E_SINGULAR_POINT || s == CYC_E_DEGENERATE_CIRCLE_PARAMETER;
}

// The plain blend of the same ends (its status; CYC_OK builds nothing kept).
int plain_blend(Ctx& c, const OptCall& o) {
  cyc_surface* S = nullptr;
  const int st = o.kind == CYC_BLEND_CANAL
                     ? cyc_blend_canal(c.ctx, &o.ends[0], &o.ends[1], o.K, o.t0, o.t1, &S)
                     : cyc_blend_ringed(c.ctx, &o.ends[0], &o.ends[1], o.K, o.t0, o.t1, &S);
  c.check("cyc_blend_*", st);
  if (st == CYC_OK) cyc_surface_destroy(c.ctx, S);
  return st;
}

// The validation statuses the call may give (0: none, the call solves).
unsigned validation_mask(const OptCall& o) {
  return blend_statuses(o) | objective_statuses(o.obj) | options_statuses(o.opt, o.K);
}

// Whether the call frees the chosen points (circle_parameter_range > 0).
bool points_free(const OptCall& o) { return !o.null_opt && o.opt.circle_parameter_range > 0; }

// The work of a valid call's solve in units of one Jacobian evaluation on a
// 1 x 1 quadrature with up to 4 parameters (~5 ms under ASan and coverage):
// quadrature nodes x Jet passes x (iterations + 1), plus the start blends.
// NULL options mean 50 iterations, a NULL objective an 8 x 4 quadrature.
int solve_work(const OptCall& o) {
  const int nt = o.null_obj ? 8 : o.obj.quadrature_t, nz = o.null_obj ? 4 : o.obj.quadrature_v;
  const int it = o.null_opt ? 50 : o.opt.max_iterations;
  const int free = o.opt.free_orders > 0 ? o.opt.free_orders : std::min(o.K, 2);
  const int points = points_free(o) ? 2 * (o.kind == CYC_BLEND_CANAL ? 2 : 3) : 0;
  const int passes = (2 * free + points + 3) / 4;  // 4 derivatives a pass (dynamic autodiff)
  return nt * nz * passes * (it + 1) + 2;
}

// The same start with a default objective on the same nodes (quadrature,
// targets' t) and the same bounds, without iterations: OK exactly when the
// start's frames hold at every node.
int start_status(Ctx& c, const OptCall& o) {
  cyc_blend_objective b;
  cyc_blend_objective_init(&b);
  b.quadrature_t = o.obj.quadrature_t;
  b.quadrature_v = o.obj.quadrature_v;
  b.targets = o.obj.targets;
  b.target_count = o.obj.target_count;
  cyc_optimize_options p = o.opt;
  p.max_iterations = 0;
  cyc_surface* S = nullptr;
  const int st = cyc_optimize_blend(c.ctx, o.kind, &o.ends[0], &o.ends[1], o.K, o.t0, o.t1, &b,
                                    &p, &S, nullptr, nullptr, nullptr);
  c.check("cyc_optimize_blend (start)", st);
  if (st == CYC_OK) cyc_surface_destroy(c.ctx, S);
  return st;
}

// The status: NULL pointers first, then exactly one of the validation
// errors present; without any, OK or a status of the blend construction —
// the plain blend's own failure, and OK where the plain blend is OK and
// the objective is moderate (a valid start blend is always returned); a
// valid start fails only by overflowing a huge objective.
void check_status(Ctx& c, const OptCall& o, unsigned m, int st) {
  const char* name = cyc_status_name(st);
  if (required_null(o)) {
    FZ_CHECK(st == CYC_E_NULL_ARGUMENT, "optimize_blend: NULL gives %s", name);
    return;
  }
  if (!cyc_optimizer_available()) {
    FZ_CHECK(st == CYC_E_UNSUPPORTED, "optimize_blend without Ceres gives %s", name);
    return;
  }
  if (m) {
    // A field beyond the input range |x| <= 1e100 is NOT_FINITE (by its
    // name) before any range check.
    if (m & bit(CYC_E_INVALID_ARGUMENT)) m |= bit(CYC_E_NOT_FINITE);
    FZ_CHECK(st > 0 && st < 32 && (m & bit(st)), "optimize_blend: %s, expected mask %#x", name,
             m);
    return;
  }
  FZ_CHECK(st == CYC_OK || (st >= 100 && st <= 200),
           "optimize_blend: %s for valid arguments", name);
  const int plain = plain_blend(c, o);
  if (plain != CYC_OK && !degenerate(plain))
    FZ_CHECK(st == plain, "optimize_blend: %s, the plain blend %s", name,
             cyc_status_name(plain));
  if (plain == CYC_OK && o.moderate)
    FZ_CHECK(st == CYC_OK, "optimize_blend: %s though the plain blend is OK", name);
  if (plain == CYC_OK && st != CYC_OK && start_status(c, o) == CYC_OK)
    FZ_CHECK(st == CYC_E_NUMERICAL_OVERFLOW, "optimize_blend: %s for a valid start", name);
}

// ---- OK: the result

// The surfaces of two calls agree bit for bit (and are evaluable).
void check_same_surface(Ctx& c, const cyc_surface* A, const cyc_surface* B, double t0, double t1,
                        const char* what) {
  for (int i = 0; i <= 2; ++i) {
    const double t = i == 2 ? t1 : t0 + (t1 - t0) * i / 2.0;
    for (double v : {0.0, 1.0, -2.0}) {
      double X[3], Y[3];
      fz::fill_sentinel(X, 3);
      fz::fill_sentinel(Y, 3);
      const int a = cyc_surface_eval(c.ctx, A, t, v, X, nullptr, nullptr, nullptr);
      c.check("cyc_surface_eval", a);
      const int b = cyc_surface_eval(c.ctx, B, t, v, Y, nullptr, nullptr, nullptr);
      c.check("cyc_surface_eval", b);
      FZ_CHECK(a == b && std::memcmp(X, Y, sizeof X) == 0, "optimize_blend: %s differ at t %g",
               what, t);
      if (a == CYC_OK) FZ_CHECK(fz::finite3(X), "optimize_blend: non-finite point at t %g", t);
    }
  }
}

// The summary's documented invariants.
void check_summary(const OptCall& o, const cyc_optimize_summary& m) {
  const double terms[] = {m.fairness, m.regularity, m.targets, m.obstacles};
  for (double x : terms) FZ_CHECK(std::isfinite(x) && x >= 0, "optimize_blend: term %g", x);
  FZ_CHECK(std::isfinite(m.initial_cost) && std::isfinite(m.final_cost) && m.final_cost >= 0,
           "optimize_blend: costs %g -> %g", m.initial_cost, m.final_cost);
  FZ_CHECK(m.final_cost <= m.initial_cost, "optimize_blend: cost rose %.17g -> %.17g",
           m.initial_cost, m.final_cost);
  const double sum = m.fairness + m.regularity + m.targets + m.obstacles;
  FZ_CHECK(std::abs(m.final_cost - sum) <= 1e-9 * std::max(m.final_cost, sum),
           "optimize_blend: final cost %.17g, terms sum to %.17g", m.final_cost, sum);
  FZ_CHECK(m.termination >= CYC_OPTIMIZE_CONVERGED && m.termination <= CYC_OPTIMIZE_REVERTED,
           "optimize_blend: termination %d", m.termination);
  const int max_it = o.null_opt ? 50 : o.opt.max_iterations;
  FZ_CHECK(m.iterations >= 0 && m.iterations <= max_it, "optimize_blend: %d iterations (max %d)",
           m.iterations, max_it);
  FZ_CHECK(std::isfinite(m.seconds) && m.seconds >= 0, "optimize_blend: seconds %g", m.seconds);
  FZ_CHECK(std::isfinite(m.length_scale) && m.length_scale > 0 && std::isfinite(m.fairness_scale) &&
               m.fairness_scale >= 0,
           "optimize_blend: L %g, fairness scale %g", m.length_scale, m.fairness_scale);
  // Without iterations (or reverted) the result is the start: its fairness
  // term is weight / 2 by the normalization.
  if (max_it == 0) FZ_CHECK(m.final_cost == m.initial_cost, "optimize_blend: 0 iterations moved");
  const double w = o.null_obj ? 1.0 : o.obj.fairness;
  if ((max_it == 0 || m.termination == CYC_OPTIMIZE_REVERTED) && m.fairness_scale > 0 &&
      w <= 1e100)
    FZ_CHECK(std::abs(m.fairness - 0.5 * w) <= 1e-9 * w, "optimize_blend: start fairness %.17g "
             "!= weight / 2 = %.17g", m.fairness, 0.5 * w);
}

// The angle theta = 2 atan v of a circle parameter, and the distance of
// two angles on the circle of angles.
double angle_of(double v) { return 2.0 * std::atan(v); }
double angle_distance(double a, double b) {
  const double two_pi = 4.0 * std::acos(0.0);
  const double d = std::fmod(std::abs(a - b), two_pi);
  return std::min(d, two_pi - d);
}

// The returned points: the input's unless freed; freed, each moved at most
// circle_parameter_range in angle and at most 0.45 x the angle to its
// end's nearest other point (so they stay distinct); unused slots kept.
void check_points(const OptCall& o, int e, const cyc_blend_end& r) {
  const cyc_blend_end& E = o.ends[e];
  const int count = o.kind == CYC_BLEND_CANAL ? 2 : 3;
  for (int j = 0; j < 3; ++j) {
    const bool same = std::memcmp(&r.v[j], &E.v[j], sizeof r.v[j]) == 0;
    if (!points_free(o) || j >= count) {
      FZ_CHECK(same, "optimize_blend: end %d point %d moved (%a -> %a)", e, j, E.v[j], r.v[j]);
      continue;
    }
    if (same) continue;
    const double moved = angle_distance(angle_of(r.v[j]), angle_of(E.v[j]));
    double gap = HUGE_VAL;
    for (int k = 0; k < count; ++k)
      if (k != j) gap = std::min(gap, angle_distance(angle_of(E.v[j]), angle_of(E.v[k])));
    const double box = std::min(o.opt.circle_parameter_range, 0.45 * gap);
    FZ_CHECK(!std::isnan(r.v[j]) && moved <= box * (1 + 1e-12) + 1e-12,
             "optimize_blend: end %d point %d moved %g (box %g): %a -> %a", e, j, moved, box,
             E.v[j], r.v[j]);
  }
}

// A returned end: the input's surface, u and (unless freed) points, the
// jet within the documented bounds around the start lambda (with its
// sign), the orders above free_orders as given.
void check_end(const OptCall& o, int e, const cyc_blend_end& r) {
  const cyc_blend_end& E = o.ends[e];
  FZ_CHECK(r.surface == E.surface && std::memcmp(&r.u, &E.u, sizeof r.u) == 0,
           "optimize_blend: end %d changed its surface or u", e);
  check_points(o, e, r);
  const double l0 = effective_lambda(E, e, o.es[e]->u0, o.es[e]->u1), a = std::abs(l0);
  const cyc_optimize_options& p = o.opt;
  const double lo = l0 > 0 ? p.lambda_min_ratio * a : -p.lambda_max_ratio * a;
  const double hi = l0 > 0 ? p.lambda_max_ratio * a : -p.lambda_min_ratio * a;
  FZ_CHECK(std::isfinite(r.lambda) && r.lambda != 0 && (r.lambda > 0) == (l0 > 0) &&
               r.lambda >= lo && r.lambda <= hi,
           "optimize_blend: end %d lambda %.17g (start %.17g, bounds [%.17g, %.17g])", e,
           r.lambda, l0, lo, hi);
  const int K = o.K, free = p.free_orders > 0 ? p.free_orders : std::min(K, 2);
  for (int m = 2; m <= free; ++m)
    FZ_CHECK(std::abs(r.phi[m - 2]) <= p.higher_bound * a,
             "optimize_blend: end %d phi^(%d) = %g beyond %g", e, m, r.phi[m - 2],
             p.higher_bound * a);
  for (int i = std::max(free - 1, 0); i < CYC_MAX_BLEND_ORDER - 1; ++i)
    FZ_CHECK(std::memcmp(&r.phi[i], &E.phi[i], sizeof(double)) == 0,
             "optimize_blend: end %d fixed phi[%d] changed", e, i);
}

// The returned ends are the blend: cyc_blend_* rebuilds the same surface.
void check_rebuild(Ctx& c, const OptCall& o, const OptOut& r) {
  cyc_surface* Y = nullptr;
  const int st = o.kind == CYC_BLEND_CANAL
                     ? cyc_blend_canal(c.ctx, &r.ends[0], &r.ends[1], o.K, o.t0, o.t1, &Y)
                     : cyc_blend_ringed(c.ctx, &r.ends[0], &r.ends[1], o.K, o.t0, o.t1, &Y);
  c.check("cyc_blend_*", st);
  FZ_CHECK(st == CYC_OK, "optimize_blend: its ends do not rebuild: %s", cyc_status_name(st));
  check_same_surface(c, r.S, Y, o.t0, o.t1, "rebuilt blend and result");
  cyc_surface_destroy(c.ctx, Y);
}

// Well-scaled joins keep a small gap with the returned lambda (order 0:
// free_orders moved phi'' too), as op_blend judges them.
void check_opt_joins(Ctx& c, const OptCall& o, const OptOut& r) {
  const bool canal = o.kind == CYC_BLEND_CANAL;
  if (!o.ws || (canal && !(o.es[0]->canal && o.es[1]->canal))) return;
  for (int e = 0; e < 2; ++e) {
    const cyc_blend_end& E = r.ends[e];
    if (jet_bound(E, E.lambda) > 128) continue;  // wide bounds: not well-scaled
    cyc_continuity R;
    const int sr = cyc_continuity_report(c.ctx, E.surface, E.u, E.lambda, r.S, e ? o.t1 : o.t0,
                                         o.K, nullptr, 16, &R);
    c.check("cyc_continuity_report", sr);
    if (sr != CYC_OK) continue;
    bool conditioned = std::isfinite(R.point_scale);
    for (int l = 1; l <= o.K; ++l)
      if (!(R.point_scale_l[l] <= 1e6 * std::max(1.0, R.point_scale))) conditioned = false;
    FZ_LOG("  optimized join %d: gap %g scale %g%s", e, R.max_gap, R.point_scale,
           conditioned ? "" : " (ill-conditioned: not judged)");
    if (conditioned)
      FZ_CHECK(R.max_gap <= 1e-7 * std::max(R.point_scale, 1e-300),
               "optimize_blend: join %d gap %g (scale %g)", e, R.max_gap, R.point_scale);
  }
}

// A second call with every output gives the same result (determinism, and
// NULL optional outputs change nothing).
// Issue 4's description of the same problem (cyc_optimize_blend_parameters):
// OK whenever the optimizer is (the same validation and start search), 2
// free orders per end, starts inside the boxes, and the chosen jets too.
void check_parameters(Ctx& c, const OptCall& o, const OptOut& r) {
  constexpr int kCap = 2 * CYC_MAX_BLEND_ORDER + 6;
  cyc_free_parameter P[kCap];
  int n = -1;
  const int st = cyc_optimize_blend_parameters(c.ctx, o.kind, &o.ends[0], &o.ends[1], o.K, o.t0,
                                               o.t1, o.null_opt ? nullptr : &o.opt, P, kCap, &n);
  c.check("cyc_optimize_blend_parameters", st);
  FZ_CHECK(st == CYC_OK, "optimize_blend OK but its parameters give %s", cyc_status_name(st));
  if (st != CYC_OK) return;
  const int fo = o.null_opt ? 0 : o.opt.free_orders;
  const int free = fo > 0 ? fo : std::min(o.K, 2);
  const int count = o.kind == CYC_BLEND_CANAL ? 2 : 3, points = points_free(o) ? 2 * count : 0;
  FZ_CHECK(n == 2 * free + points, "blend parameters: count %d for %d free orders, %d points",
           n, free, points);
  for (int i = 2 * free; i < n && i < kCap; ++i) {
    const int e = (i - 2 * free) / count, j = (i - 2 * free) % count;
    const double v = r.ends[e].v[j];
    const double theta = std::memcmp(&v, &o.ends[e].v[j], sizeof v) == 0 ? P[i].start
                                                                          : angle_of(v);
    // The chosen angle lies in the box up to the period (atan folds it).
    const double off = angle_distance(theta, P[i].start);
    FZ_CHECK(P[i].role == CYC_PARAMETER_CIRCLE_POINT && P[i].index == e && P[i].order == j &&
                 P[i].lower <= P[i].start && P[i].start <= P[i].upper &&
                 off <= (P[i].upper - P[i].start) * (1 + 1e-12) + 1e-12,
             "blend point parameter %d (end %d, point %d): chosen %g, start %g, box [%g, %g]", i,
             e, j, theta, P[i].start, P[i].lower, P[i].upper);
  }
  for (int i = 0; i < 2 * free && i < kCap; ++i) {
    const int e = i / free, m = i % free;
    const double v = m == 0 ? r.ends[e].lambda : r.ends[e].phi[m - 1];
    FZ_CHECK(P[i].role == CYC_PARAMETER_JET && P[i].index == e && P[i].order == m + 1 &&
                 P[i].lower <= P[i].start && P[i].start <= P[i].upper && v >= P[i].lower &&
                 v <= P[i].upper,
             "blend parameter %d (end %d, order %d): chosen %g, start %g, box [%g, %g]", i, e,
             m + 1, v, P[i].start, P[i].lower, P[i].upper);
  }
}

void check_ok(Ctx& c, const OptCall& o, OptOut& r1) {
  FZ_CHECK(r1.S && r1.S != OptOut::sentinel_surface(), "optimize_blend: OK without a surface");
  double d0 = 0, d1 = 0;
  const int sd = cyc_surface_domain(c.ctx, r1.S, &d0, &d1);
  c.check("cyc_surface_domain", sd);
  FZ_CHECK(sd == CYC_OK && d0 == o.t0 && d1 == o.t1, "optimize_blend: domain [%g, %g]", d0, d1);
  int kind = 0;
  c.check("cyc_surface_kind", cyc_surface_kind(c.ctx, r1.S, &kind));
  FZ_CHECK(kind == (o.kind == CYC_BLEND_CANAL ? CYC_SURFACE_PRCS : CYC_SURFACE_PRRS),
           "optimize_blend: surface kind %d", kind);
  OptOut r2;
  const int st2 = call_optimize(c, o, r2, true);
  c.check("cyc_optimize_blend", st2);
  FZ_CHECK(st2 == CYC_OK, "optimize_blend: second call gives %s", cyc_status_name(st2));
  check_same_surface(c, r1.S, r2.S, o.t0, o.t1, "two calls");
  for (int e = 0; e < 2; ++e)
    if (o.nulls != 4 + e)
      FZ_CHECK(std::memcmp(&r1.ends[e], &r2.ends[e], sizeof r2.ends[e]) == 0,
               "optimize_blend: end %d differs between calls", e);
  const cyc_optimize_summary &m1 = r1.sum, &m2 = r2.sum;
  if (o.nulls != 6)
    FZ_CHECK(m1.initial_cost == m2.initial_cost && m1.final_cost == m2.final_cost &&
                 m1.iterations == m2.iterations && m1.termination == m2.termination &&
                 m1.fairness == m2.fairness && m1.regularity == m2.regularity &&
                 m1.targets == m2.targets && m1.obstacles == m2.obstacles,
             "optimize_blend: summaries differ between calls");
  FZ_LOG("  optimize: cost %g -> %g, %d iterations, termination %d, %g s", m2.initial_cost,
         m2.final_cost, m2.iterations, m2.termination, m2.seconds);
  check_summary(o, m2);
  for (int e = 0; e < 2; ++e) check_end(o, e, r2.ends[e]);
  check_parameters(c, o, r2);
  check_rebuild(c, o, r2);
  check_opt_joins(c, o, r2);
  cyc_surface_destroy(c.ctx, r2.S);
}

void op_optimize(Input& in, Ctx& c) {
  OptCall o;
  fuzz_call(in, c, o);
  for (const cyc_blend_end& E : o.ends)
    FZ_LOG("  end: u %a v %a %a %a lambda %a phi'' %a", E.u, E.v[0], E.v[1], E.v[2], E.lambda,
           E.phi[0]);
  FZ_LOG("  kind %d K %d t0 %a t1 %a nulls %d objective %s options %s", o.kind, o.K, o.t0, o.t1,
         o.nulls, o.null_obj ? "NULL" : "given", o.null_opt ? "NULL" : "given");
  const unsigned m = validation_mask(o);
  FZ_LOG("  optimize: expected mask %#x, moderate %d, ws %d", m, o.moderate, o.ws);
  // Valid calls solve (twice: determinism); beyond the input's budget they
  // are skipped, the bytes still consumed. Invalid ones fail fast.
  if (!m && !required_null(o) && cyc_optimizer_available()) {
    const int work = solve_work(o);
    if (work > c.solve_budget) {
      FZ_LOG("  optimize: skipped (work %d, budget left %d)", work, c.solve_budget);
      return;
    }
    c.solve_budget -= work;
  }
  OptOut r;
  const int st = call_optimize(c, o, r, false);
  c.check("cyc_optimize_blend", st);
  check_status(c, o, m, st);
  if (st != CYC_OK) {
    FZ_CHECK(r.untouched(), "optimize_blend: output written on error %s", cyc_status_name(st));
    return;
  }
  check_ok(c, o, r);
  cyc_surface_destroy(c.ctx, r.S);
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
  build_surface(in, c, 0);
  build_surface(in, c, 1);
  const int nops = in.range(1, 12);
  for (int i = 0; i < nops; ++i) {
    // One byte: 0..3 (mod 4) the cheap ops, 62 the matched ringed blend, 63
    // the optimizer (a Ceres solve per call: rare enough that the smoke run
    // stays fast). Old inputs decode as before unless that byte is 62 or 63.
    const int op = in.range(0, 63);
    if (op == 63) {
      op_optimize(in, c);
      continue;
    }
    if (op == 62) {
      op_blend(in, c, false, true);
      continue;
    }
    switch (op % 4) {
      case 0: op_derivatives(in, c); break;
      case 1: op_blend(in, c, false); break;
      case 2: op_blend(in, c, true); break;
      default: op_continuity(in, c); break;
    }
  }
  // A NULL context is reported, never a crash.
  double out[3];
  FZ_CHECK(cyc_surface_derivatives_u(nullptr, c.s[0].S, 0.5, 0.0, 0, out) ==
               CYC_E_NULL_ARGUMENT,
           "cyc_surface_derivatives_u(NULL context)");
  for (Surf& s : c.s) cyc_surface_destroy(c.ctx, s.S);
  cyc_context_destroy(c.ctx);
  return 0;
}
