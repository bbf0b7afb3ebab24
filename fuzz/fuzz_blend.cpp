// Fuzz target of the blends of the C ABI (SPEC §8d, issue 4):
// cyc_surface_derivatives_u, cyc_blend_canal, cyc_blend_ringed and
// cyc_continuity_report on two input surfaces built from fuzzed data (the
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
//    the angle is in [0, pi/2], all measures are >= 0.
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

struct Ctx {
  cyc_context* ctx = nullptr;
  fz::HandlerLog log;
  fz::HandlerLog* logp = nullptr;
  Surf s[2];
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

void op_blend(Input& in, Ctx& c, bool canal) {
  const char* fn = canal ? "cyc_blend_canal" : "cyc_blend_ringed";
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
  switch (in.range(0, 3)) {
    case 0: break;
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
  const int nulls = in.rarely() ? in.range(1, 3) : 0;  // 1 start, 2 end, 3 out
  cyc_surface* const kSentinelOut = reinterpret_cast<cyc_surface*>(uintptr_t(0x5eed));
  cyc_surface* out = kSentinelOut;
  cyc_surface* out2 = kSentinelOut;
  auto call = [&](cyc_surface** o) {
    const cyc_blend_end* a = nulls == 1 ? nullptr : &ends[0];
    const cyc_blend_end* b = nulls == 2 ? nullptr : &ends[1];
    cyc_surface** oo = nulls == 3 ? nullptr : o;
    return canal ? cyc_blend_canal(c.ctx, a, b, K, t0, t1, oo)
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

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Input in(data, size);
  Ctx c;
  if (cyc_context_create(nullptr, &c.ctx) != CYC_OK) return 0;
  if (in.flag()) {
    cyc_context_set_error_handler(c.ctx, &fz::HandlerLog::callback, &c.log);
    c.logp = &c.log;
  }
  build_surface(in, c, 0);
  build_surface(in, c, 1);
  const int nops = in.range(1, 12);
  for (int i = 0; i < nops; ++i) {
    switch (in.range(0, 3)) {
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
