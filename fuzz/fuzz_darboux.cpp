// Fuzz target of the Darboux family of the C ABI (SPEC §8b, issue 3):
// cyc_dcmc, cyc_invert_point / _sphere / _circle / _darboux,
// cyc_darboux_eval / _classify and cyc_surface_eval_inverted, on fuzzed
// doubles with hostile cases made likely: NaN, +-Inf, 0, huge, tiny, points
// at (or a few ulps from) the inversion center, circles and lines through the
// center, near-parallel and coplanar DCMC lines, Example 4 of seed 000.
//
// Oracles:
//  - every status is known, never CYC_E_INTERNAL; last status/message and the
//    error handler agree with it (fz::check_call); NULL arguments give
//    CYC_E_NULL_ARGUMENT; non-finite inputs are rejected;
//  - on error every output is bit-for-bit untouched (sentinel prefill); on OK
//    every output is finite; every call made twice gives identical bits;
//  - darboux_eval: value and gradient of 2 D are exactly 2x those of D;
//    classify: a type in [0, 6], the same for 2 D and -D, QUARTIC exactly when
//    |phi0| > 1e-12 max |k|, ZERO exactly for all-zero coefficients;
//  - inversion, for well-scaled inputs (every magnitude 0 or in [1e-3, 1e3],
//    the point at least 1e-3 of the scale from the center): points are an
//    involution to relative 1e-9 plus the rounding they cannot avoid (scale
//    aware: |Y| |m| / |Y'| eps, see involution_tol); images of sphere and
//    circle points lie on the image sphere / circle / line; points of a
//    cyclide map onto the inverted cyclide (residual relative to a majorant
//    of the terms the closed form adds, computed here);
//  - DCMC on OK: |n| = 1, n . d_i = 0, base = (0, n, phi2), quadric =
//    (0, 0, phi2) with unit phi2 orthogonal to base's; for well-scaled lines
//    every member base + alpha quadric vanishes on the three lines (relative
//    to the terms of the member at the sample point);
//  - surface_eval_inverted equals invert_point of cyc_surface_eval's point,
//    has the same status when eval fails, a unit normal, and keeps the
//    normal's angles with the partials.
//
// Input layout: see make_seeds.py (DarbouxEncoder), which mirrors this file.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "fuzz_common.hpp"

namespace {

using fz::Input;
using fz::coord;
using fz::coords;

constexpr double kEps = 2.220446049250313e-16;

struct Ctx {
  cyc_context* ctx = nullptr;
  fz::HandlerLog log;
  fz::HandlerLog* logp = nullptr;
  cyc_surface* S = nullptr;
  double u0 = 0, u1 = 1;
  void check(const char* fn, int s) { fz::check_call(fn, ctx, s, logp); }
};

bool same_bits(const void* a, const void* b, size_t n) { return std::memcmp(a, b, n) == 0; }
template <class T>
void sentinel(T& x) {
  static_assert(sizeof(T) % sizeof(double) == 0, "double-sized");
  fz::fill_sentinel(reinterpret_cast<double*>(&x), sizeof(T) / sizeof(double));
}
template <class T>
bool untouched(const T& x) {
  return fz::all_sentinel(reinterpret_cast<const double*>(&x), sizeof(T) / sizeof(double));
}
// A magnitude of a well-scaled input: 0 or in [1e-3, 1e3].
bool ws(double v) { return v == 0 || (std::abs(v) >= 1e-3 && std::abs(v) <= 1e3); }
bool ws3(const double* v) { return ws(v[0]) && ws(v[1]) && ws(v[2]); }
bool finite_n(const double* v, int n) {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}
void sub3(const double* a, const double* b, double* r) {
  for (int i = 0; i < 3; ++i) r[i] = a[i] - b[i];
}
void cross3(const double* a, const double* b, double* r) {
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
}

// ------------------------------------------------------------ inputs


// A unit-ish direction: a signed coordinate axis, or three coordinates.
void direction(Input& in, double* d) {
  if (in.flag()) {
    const int a = in.range(0, 5);
    d[0] = d[1] = d[2] = 0;
    d[a % 3] = a < 3 ? 1.0 : -1.0;
  } else {
    coords(in, d, 3);
  }
}

void inversion(Input& in, cyc_inversion& inv) {
  coords(in, inv.center, 3);
  switch (in.range(0, 2)) {
    case 0: inv.radius = std::ldexp(1.0, in.range(-10, 10)); break;
    case 1: inv.radius = coord(in); break;
    default: inv.radius = in.wild(); break;
  }
}

// A point, hostile to the inversion: anywhere, exactly the center, a tiny
// offset from it, on the inversion sphere, or wild.
void point(Input& in, const cyc_inversion& inv, double* X) {
  switch (in.range(0, 4)) {
    case 0: coords(in, X, 3); break;
    case 1: std::memcpy(X, inv.center, sizeof(double) * 3); break;
    case 2: {
      const int e = in.range(1, 1074);
      for (int i = 0; i < 3; ++i) X[i] = inv.center[i] + std::ldexp(double(in.range(-2, 2)), -e);
      break;
    }
    case 3: {
      const int a = in.range(0, 2);
      std::memcpy(X, inv.center, sizeof(double) * 3);
      X[a] += inv.radius;
      break;
    }
    default:
      for (int i = 0; i < 3; ++i) X[i] = in.wild();
      break;
  }
}

// ------------------------------------------------------------ Darboux helpers

// Monomials of (31) in coefficient order; with `absolute` of |x|, |y|, |z|.
void monomials(const double* X0, double* m, bool absolute = false) {
  double X[3];
  for (int i = 0; i < 3; ++i) X[i] = absolute ? std::abs(X0[i]) : X0[i];
  const double x = X[0], y = X[1], z = X[2], S = x * x + y * y + z * z;
  const double v[14] = {S * S, x * S, y * S, z * S, x * x, y * y, z * z,
                        x * y, x * z, y * z, x,     y,     z,     1.0};
  std::memcpy(m, v, sizeof v);
}
double value(const double* k, const double* X) {
  double m[14], r = 0;
  monomials(X, m);
  for (int i = 0; i < 14; ++i) r += k[i] * m[i];
  return r;
}
// sum |k_i| |monomial_i(X)|: the size of the terms of F(X).
double abs_value(const double* k, const double* X) {
  double m[14], r = 0;
  monomials(X, m, true);
  for (int i = 0; i < 14; ++i) r += std::abs(k[i]) * m[i];
  return r;
}
double max_abs(const double* k, int n) {
  double r = 0;
  for (int i = 0; i < n; ++i) r = std::max(r, std::abs(k[i]));
  return r;
}

// The cyclide as (phi0, l, Q, b, c) for the translation formula.
struct Dx {
  double p0, l[3], Q[3][3], b[3], c;
};
Dx unpack(const double* k, bool absolute) {
  auto f = [&](double v) { return absolute ? std::abs(v) : v; };
  Dx D;
  D.p0 = f(k[0]);
  for (int i = 0; i < 3; ++i) {
    D.l[i] = f(k[1 + i]);
    D.Q[i][i] = f(k[4 + i]);
    D.b[i] = f(k[10 + i]);
  }
  D.Q[0][1] = D.Q[1][0] = 0.5 * f(k[7]);
  D.Q[0][2] = D.Q[2][0] = 0.5 * f(k[8]);
  D.Q[1][2] = D.Q[2][1] = 0.5 * f(k[9]);
  D.c = f(k[13]);
  return D;
}
void pack(const Dx& D, double* k) {
  k[0] = D.p0;
  for (int i = 0; i < 3; ++i) {
    k[1 + i] = D.l[i];
    k[4 + i] = D.Q[i][i];
    k[10 + i] = D.b[i];
  }
  k[7] = D.Q[0][1] + D.Q[1][0];
  k[8] = D.Q[0][2] + D.Q[2][0];
  k[9] = D.Q[1][2] + D.Q[2][1];
  k[13] = D.c;
}
// F(Y + m) (the core's translate, written out again; on absolute values and
// |m| it gives majorants of every coefficient's terms).
Dx translate(const Dx& D, const double* m) {
  const double mm = fz::dot3(m, m), lm = fz::dot3(D.l, m);
  double Qm[3];
  for (int i = 0; i < 3; ++i) Qm[i] = fz::dot3(D.Q[i], m);
  Dx T;
  T.p0 = D.p0;
  for (int i = 0; i < 3; ++i) {
    T.l[i] = D.l[i] + 4 * D.p0 * m[i];
    for (int j = 0; j < 3; ++j)
      T.Q[i][j] = D.Q[i][j] + D.p0 * ((i == j ? 2 * mm : 0.0) + 4 * m[i] * m[j]) +
                  (D.l[i] * m[j] + m[i] * D.l[j]) + (i == j ? lm : 0.0);
    T.b[i] = D.b[i] + 2 * Qm[i] + 4 * D.p0 * mm * m[i] + mm * D.l[i] + 2 * lm * m[i];
  }
  T.c = D.c + D.p0 * mm * mm + lm * mm + fz::dot3(m, Qm) + fz::dot3(D.b, m);
  return T;
}
// The unnormalized image of the cyclide k[] (absolute: a majorant of the
// terms of each coefficient).
void image(const double* k, const cyc_inversion& inv, bool absolute, double* out) {
  double m[3], mneg[3];
  for (int i = 0; i < 3; ++i) {
    m[i] = absolute ? std::abs(inv.center[i]) : inv.center[i];
    mneg[i] = absolute ? m[i] : -m[i];
  }
  const double q = inv.radius * inv.radius;
  const Dx G = translate(unpack(k, absolute), m);
  Dx H;
  H.p0 = G.c;
  for (int i = 0; i < 3; ++i) {
    H.l[i] = q * G.b[i];
    for (int j = 0; j < 3; ++j) H.Q[i][j] = q * q * G.Q[i][j];
    H.b[i] = q * q * q * G.l[i];
  }
  H.c = q * q * q * q * G.p0;
  pack(translate(H, mneg), out);
}

// ------------------------------------------------------------ inversion helpers

// The rounding an inversion X -> X' -> X'' cannot avoid: X' = m + Y' loses
// |m| eps of Y' = X' - m, which X'' magnifies by |Y| / |Y'|.
double involution_tol(const double* X, const double* m, double Y, double Yp) {
  const double nX = fz::norm3(X), nm = fz::norm3(m);
  return 1e-9 * (nX + nm) + 64 * kEps * (nX + nm + Y * (nm + Yp) / Yp);
}

// cyc_invert_point twice (deterministic), sentinel and finite checks.
int invert_point_checked(Ctx& c, const cyc_inversion* inv, const double* X, double* out,
                         bool null_out = false) {
  double a[3], b[3];
  fz::fill_sentinel(a, 3);
  fz::fill_sentinel(b, 3);
  const int sa = cyc_invert_point(c.ctx, inv, X, null_out ? nullptr : a);
  c.check("cyc_invert_point", sa);
  const int sb = cyc_invert_point(c.ctx, inv, X, null_out ? nullptr : b);
  c.check("cyc_invert_point", sb);
  FZ_CHECK(sa == sb && same_bits(a, b, sizeof a), "cyc_invert_point not deterministic");
  if (null_out || !inv || !X)
    FZ_CHECK(sa == CYC_E_NULL_ARGUMENT, "cyc_invert_point(NULL): %s", cyc_status_name(sa));
  if (sa != CYC_OK) {
    FZ_CHECK(fz::all_sentinel(a, 3), "cyc_invert_point: %s but wrote the output",
             cyc_status_name(sa));
    return sa;
  }
  FZ_CHECK(fz::finite3(a), "cyc_invert_point OK but not finite");
  if (out) std::memcpy(out, a, sizeof a);
  return sa;
}

// Inversion at a valid, well-scaled sphere?
bool inversion_ws(const cyc_inversion& inv) {
  return ws3(inv.center) && inv.radius >= 1e-3 && inv.radius <= 1e3;
}
bool inversion_valid(const cyc_inversion& inv) {
  return finite_n(inv.center, 3) && std::isfinite(inv.radius) && inv.radius > 0 &&
         max_abs(inv.center, 3) <= 1e100 && inv.radius <= 1e100;
}
// X well-scaled and at least 1e-3 of the scale away from the center.
bool away_from_center(const cyc_inversion& inv, const double* X) {
  double Y[3];
  sub3(X, inv.center, Y);
  const double scale = std::max({fz::norm3(X), fz::norm3(inv.center), inv.radius});
  return ws3(X) && fz::norm3(Y) >= 1e-3 * scale;
}

// ------------------------------------------------------------ ops

void op_invert_point(Input& in, Ctx& c) {
  cyc_inversion inv;
  inversion(in, inv);
  double X[3];
  point(in, inv, X);
  const int nulls = in.rarely() ? in.range(1, 3) : 0;
  FZ_LOG("invert_point m = (%a %a %a) rho = %a X = (%a %a %a)", inv.center[0], inv.center[1],
         inv.center[2], inv.radius, X[0], X[1], X[2]);
  double Xp[3];
  const int s = invert_point_checked(c, nulls == 1 ? nullptr : &inv, nulls == 2 ? nullptr : X,
                                     Xp, nulls == 3);
  if (nulls) return;
  if (!inversion_valid(inv)) {
    FZ_CHECK(s == CYC_E_NOT_FINITE || s == CYC_E_INVALID_ARGUMENT,
             "invert_point with an invalid inversion: %s", cyc_status_name(s));
    return;
  }
  if (!finite_n(X, 3) || max_abs(X, 3) > 1e100) {
    FZ_CHECK(s == CYC_E_NOT_FINITE, "invert_point of a non-finite point: %s",
             cyc_status_name(s));
    return;
  }
  const bool at_center = X[0] == inv.center[0] && X[1] == inv.center[1] && X[2] == inv.center[2];
  FZ_CHECK(at_center == (s == CYC_E_AT_INVERSION_CENTER), "invert_point %s the center: %s",
           at_center ? "at" : "off", cyc_status_name(s));
  if (s != CYC_OK || !inversion_ws(inv) || !away_from_center(inv, X)) return;
  // The image lies on the ray from m through X at distance rho^2 / |Y|.
  double Y[3], Yp[3];
  sub3(X, inv.center, Y);
  sub3(Xp, inv.center, Yp);
  const double nY = fz::norm3(Y), nYp = fz::norm3(Yp);
  double Xpp[3];
  const int s2 = invert_point_checked(c, &inv, Xp, Xpp);
  const double want = inv.radius * inv.radius / nY;
  if (s2 == CYC_E_AT_INVERSION_CENTER) {
    // X' rounded to m: only possible when rho^2/|Y| is below m's ulps.
    FZ_CHECK(want <= 4 * kEps * fz::norm3(inv.center),
             "X' = m although rho^2/|Y| = %g (|m| = %g)", want, fz::norm3(inv.center));
    return;
  }
  FZ_CHECK(s2 == CYC_OK, "inverting X' = inv(X) failed: %s", cyc_status_name(s2));
  const double err = fz::dist3(Xpp, X), tol = involution_tol(X, inv.center, nY, nYp);
  FZ_CHECK(err <= tol, "inversion is not an involution: |X'' - X| = %.3g > %.3g (|Y| = %g, "
           "|Y'| = %g)", err, tol, nY, nYp);
}

// A general sphere: a sphere (center, radius; optionally through m), a plane
// or any coefficients; `P` is one of its points when `has_point`.
void general_sphere(Input& in, const cyc_inversion& inv, cyc_general_sphere& S, double* P,
                    bool& has_point) {
  has_point = false;
  switch (in.range(0, 3)) {
    case 0:
    case 1: {  // sphere of center C through P = C + r u
      double C[3], u[3];
      coords(in, C, 3);
      const int a = in.range(0, 5);
      u[0] = u[1] = u[2] = 0;
      u[a % 3] = a < 3 ? 1.0 : -1.0;
      double r;
      if (in.flag()) {  // through the inversion center
        double w[3];
        sub3(inv.center, C, w);
        r = fz::norm3(w);
      } else {
        r = std::abs(coord(in));
      }
      for (int i = 0; i < 3; ++i) P[i] = C[i] + r * u[i];
      S.a = 1.0;
      for (int i = 0; i < 3; ++i) S.b[i] = -2 * C[i];
      S.c = fz::dot3(C, C) - r * r;
      has_point = true;
      break;
    }
    case 2: {  // plane through P with normal nrm (optionally through m)
      double nrm[3];
      direction(in, nrm);
      if (in.flag()) std::memcpy(P, inv.center, sizeof(double) * 3);
      else coords(in, P, 3);
      S.a = 0;
      std::memcpy(S.b, nrm, sizeof nrm);
      S.c = -fz::dot3(nrm, P);
      has_point = true;
      break;
    }
    default:
      S.a = coord(in);
      coords(in, S.b, 3);
      S.c = coord(in);
      break;
  }
}

void op_invert_sphere(Input& in, Ctx& c) {
  cyc_inversion inv;
  inversion(in, inv);
  cyc_general_sphere S;
  double P[3];
  bool has_point;
  general_sphere(in, inv, S, P, has_point);
  const int nulls = in.rarely() ? in.range(1, 3) : 0;
  cyc_general_sphere r[2];
  int st[2];
  for (int i = 0; i < 2; ++i) {
    sentinel(r[i]);
    st[i] = cyc_invert_sphere(c.ctx, nulls == 1 ? nullptr : &inv, nulls == 2 ? nullptr : &S,
                              nulls == 3 ? nullptr : &r[i]);
    c.check("cyc_invert_sphere", st[i]);
  }
  FZ_LOG("invert_sphere m = (%a %a %a) rho = %a; (%a; %a %a %a; %a) -> %s", inv.center[0],
         inv.center[1], inv.center[2], inv.radius, S.a, S.b[0], S.b[1], S.b[2], S.c,
         cyc_status_name(st[0]));
  if (st[0] == CYC_OK)
    FZ_LOG("    -> (%a; %a %a %a; %a)", r[0].a, r[0].b[0], r[0].b[1], r[0].b[2], r[0].c);
  FZ_CHECK(st[0] == st[1] && same_bits(&r[0], &r[1], sizeof r[0]),
           "cyc_invert_sphere not deterministic");
  if (nulls) FZ_CHECK(st[0] == CYC_E_NULL_ARGUMENT, "invert_sphere(NULL): %s",
                      cyc_status_name(st[0]));
  if (st[0] != CYC_OK) {
    FZ_CHECK(untouched(r[0]), "cyc_invert_sphere: %s but wrote the output",
             cyc_status_name(st[0]));
    return;
  }
  const cyc_general_sphere& R = r[0];
  const double k4[5] = {R.a, R.b[0], R.b[1], R.b[2], R.c};
  FZ_CHECK(finite_n(k4, 5), "cyc_invert_sphere OK but not finite");
  FZ_CHECK(std::abs(max_abs(k4, 5) - 1.0) <= 4 * kEps, "invert_sphere not normalized: max %.17g",
           max_abs(k4, 5));
  if (!has_point || !inversion_ws(inv) || !ws3(P) || !away_from_center(inv, P)) return;
  const double in5[5] = {S.a, S.b[0], S.b[1], S.b[2], S.c};
  if (!std::all_of(in5, in5 + 5, [](double v) { return std::abs(v) <= 1e7; })) return;
  // The image of P lies on the image sphere. As Darboux cyclides (qxx = qyy
  // = qzz = a, b, c), the closed form is the cyclide one times |X' - m|^2.
  double Xp[3];
  if (invert_point_checked(c, &inv, P, Xp) != CYC_OK) return;
  double kd[14] = {}, raw[14], maj[14];
  kd[4] = kd[5] = kd[6] = S.a;
  std::memcpy(kd + 10, S.b, sizeof S.b);
  kd[13] = S.c;
  image(kd, inv, false, raw);
  image(kd, inv, true, maj);
  double Y[3], Yp[3];
  sub3(P, inv.center, Y);
  sub3(Xp, inv.center, Yp);
  const double nY = fz::norm3(Y), nYp = fz::norm3(Yp), nm = fz::norm3(inv.center);
  const double s_est = max_abs(raw, 14), amp = max_abs(maj, 14) / s_est;
  if (!(amp <= 1e6)) return;  // the closed form cancels too much to judge here
  const double F = R.a * fz::dot3(Xp, Xp) + fz::dot3(R.b, Xp) + R.c;
  const double grad = fz::norm3(R.b) + 2 * std::abs(R.a) * fz::norm3(Xp);
  const double dX = 8 * kEps * (nm + nYp * (2 + (fz::norm3(P) + nm) / nY));
  // F(X') |X' - m|^2 = image cyclide (X'); its terms over |X' - m|^2.
  const double terms = abs_value(maj, Xp) / (s_est * std::max(nYp * nYp, 1e-300));
  const double tol = 1e-9 * terms + 1e3 * grad * dX;
  FZ_CHECK(std::abs(F) <= tol,
           "image of a sphere point is off the image sphere: |F| = %.3g > %.3g", std::abs(F), tol);
}

void op_invert_circle(Input& in, Ctx& c) {
  cyc_inversion inv;
  inversion(in, inv);
  cyc_circle_or_line C;
  C.is_line = in.flag() ? 1 : 0;
  direction(in, C.axis);
  const bool through = in.flag();
  double ax[3] = {C.axis[0], C.axis[1], C.axis[2]};
  const double na = fz::norm3(ax);
  if (na > 0 && std::isfinite(na))
    for (double& v : ax) v /= na;
  // e1: a unit vector orthogonal to the axis.
  double e1[3], e2[3];
  {
    const double t[3] = {std::abs(ax[0]) < 0.6 ? 1.0 : 0.0, std::abs(ax[0]) < 0.6 ? 0.0 : 1.0, 0};
    cross3(ax, t, e1);
    const double n1 = fz::norm3(e1);
    if (n1 > 0)
      for (double& v : e1) v /= n1;
    cross3(ax, e1, e2);
  }
  C.radius = C.is_line ? 0.0 : (in.flag() ? coord(in) : std::abs(coord(in)));
  if (through) {  // through the inversion center
    const double t = coord(in);
    for (int i = 0; i < 3; ++i)
      C.point[i] = C.is_line ? inv.center[i] + t * ax[i] : inv.center[i] - C.radius * e1[i];
  } else {
    coords(in, C.point, 3);
  }
  const double angle = double(in.range(0, 63)) * (6.283185307179586 / 64.0);
  const int nulls = in.rarely() ? in.range(1, 3) : 0;
  cyc_circle_or_line r[2];
  int st[2];
  for (int i = 0; i < 2; ++i) {
    std::memset(&r[i], 0, sizeof r[i]);
    r[i].is_line = -77;
    fz::fill_sentinel(r[i].point, 3);
    fz::fill_sentinel(r[i].axis, 3);
    fz::fill_sentinel(&r[i].radius, 1);
    st[i] = cyc_invert_circle(c.ctx, nulls == 1 ? nullptr : &inv, nulls == 2 ? nullptr : &C,
                              nulls == 3 ? nullptr : &r[i]);
    c.check("cyc_invert_circle", st[i]);
  }
  FZ_LOG("invert_circle m = (%a %a %a) rho = %a; %s p = (%a %a %a) axis = (%a %a %a) r = %a through=%d -> %s",
         inv.center[0], inv.center[1], inv.center[2], inv.radius, C.is_line ? "line" : "circle",
         C.point[0], C.point[1], C.point[2], C.axis[0], C.axis[1], C.axis[2], C.radius, int(through),
         cyc_status_name(st[0]));
  FZ_CHECK(st[0] == st[1] && same_bits(&r[0], &r[1], sizeof r[0]),
           "cyc_invert_circle not deterministic");
  if (nulls) FZ_CHECK(st[0] == CYC_E_NULL_ARGUMENT, "invert_circle(NULL): %s",
                      cyc_status_name(st[0]));
  const cyc_circle_or_line& R = r[0];
  if (st[0] != CYC_OK) {
    FZ_CHECK(R.is_line == -77 && fz::all_sentinel(R.point, 3) && fz::all_sentinel(R.axis, 3) &&
                 fz::is_sentinel(R.radius),
             "cyc_invert_circle: %s but wrote the output", cyc_status_name(st[0]));
    return;
  }
  FZ_CHECK(R.is_line == 0 || R.is_line == 1, "invert_circle is_line = %d", R.is_line);
  FZ_CHECK(fz::finite3(R.point) && fz::finite3(R.axis) && std::isfinite(R.radius),
           "cyc_invert_circle OK but not finite");
  FZ_CHECK(std::abs(fz::norm3(R.axis) - 1) <= 1e-12, "invert_circle axis not unit: %.17g",
           fz::norm3(R.axis));
  if (!R.is_line) FZ_CHECK(R.radius >= 0, "invert_circle radius %g", R.radius);
  // A point of the input maps onto the output.
  if (!inversion_ws(inv) || !ws3(C.point) || !ws(C.radius) || na < 1e-3 || na > 1e3) return;
  if (!C.is_line && !(C.radius >= 1e-3)) return;
  double P[3];
  for (int i = 0; i < 3; ++i)
    P[i] = C.is_line ? C.point[i] + std::tan(angle / 2 - 1.5) * ax[i]
                     : C.point[i] + C.radius * (std::cos(angle) * e1[i] + std::sin(angle) * e2[i]);
  if (!away_from_center(inv, P)) return;
  double Xp[3];
  if (invert_point_checked(c, &inv, P, Xp) != CYC_OK) return;
  double d[3];
  sub3(Xp, R.point, d);
  double dist;
  if (R.is_line) {
    double cr[3];
    cross3(d, R.axis, cr);
    dist = fz::norm3(cr);
  } else {
    const double h = fz::dot3(d, R.axis);
    double inpl[3];
    for (int i = 0; i < 3; ++i) inpl[i] = d[i] - h * R.axis[i];
    dist = std::hypot(h, fz::norm3(inpl) - R.radius);
  }
  // The output comes from three inverted points of the input: its accuracy
  // is that of the inverted points (scale aware, as for the involution),
  // magnified by how nearly collinear they are (radius / |Y'|).
  double Y[3], Yp[3];
  sub3(P, inv.center, Y);
  sub3(Xp, inv.center, Yp);
  const double nY = fz::norm3(Y), nYp = fz::norm3(Yp), nm = fz::norm3(inv.center);
  const double scale = fz::norm3(Xp) + fz::norm3(R.point) + (R.is_line ? 0.0 : R.radius) + nm;
  const double dX = nm + nYp * (2 + (fz::norm3(P) + nm) / nY);
  const double amp = R.is_line ? 1.0 : std::max(1.0, R.radius / std::max(nYp, 1e-300));
  const double tol = 1e-9 * scale + 1e3 * kEps * dX * amp * amp;
  FZ_LOG("    P = (%.17g %.17g %.17g) -> X' = (%.17g %.17g %.17g); image %s p = (%.17g %.17g %.17g) "
         "axis = (%.17g %.17g %.17g) r = %.17g",
         P[0], P[1], P[2], Xp[0], Xp[1], Xp[2], R.is_line ? "line" : "circle", R.point[0],
         R.point[1], R.point[2], R.axis[0], R.axis[1], R.axis[2], R.radius);
  FZ_CHECK(dist <= tol, "image of a %s point is off the image %s: %.3g > %.3g",
           C.is_line ? "line" : "circle", R.is_line ? "line" : "circle", dist, tol);
}

// A Darboux equation: fuzzed coefficients, sparse moderate ones, Example 4
// (35) or a sphere; optionally adjusted (c) to pass through X0.
void darboux(Input& in, cyc_darboux& D) {
  switch (in.range(0, 3)) {
    case 0: coords(in, D.k, 14); break;
    case 1:
      for (double& v : D.k) v = in.flag() ? 0.0 : in.moderate();
      break;
    case 2: {  // eq. (35)
      const double a = coord(in);
      const double k[14] = {0, 0, 0, 1, 0, -1, -3, -3, a, -2 * a, 0, 2 * a, 2, 0};
      std::memcpy(D.k, k, sizeof k);
      break;
    }
    default: {  // a sphere scaled by s, or a torus-like quartic
      double C[3];
      coords(in, C, 3);
      const double r = coord(in), s = coord(in);
      std::memset(D.k, 0, sizeof D.k);
      if (in.flag()) {
        D.k[4] = D.k[5] = D.k[6] = s;
        for (int i = 0; i < 3; ++i) D.k[10 + i] = -2 * s * C[i];
        D.k[13] = s * (fz::dot3(C, C) - r * r);
      } else {  // (X.X + R^2 - r^2)^2 - 4 R^2 (x^2 + y^2), R = |C|
        const double R2 = fz::dot3(C, C), e = R2 - r * r;
        D.k[0] = s;
        D.k[4] = D.k[5] = s * (2 * e - 4 * R2);
        D.k[6] = s * 2 * e;
        D.k[13] = s * e * e;
      }
      break;
    }
  }
}

void op_darboux_eval(Input& in, Ctx& c) {
  cyc_darboux D;
  darboux(in, D);
  double X[3];
  coords(in, X, 3);
  const bool want_grad = !in.rarely();
  const int nulls = in.rarely() ? in.range(1, 3) : 0;
  struct R {
    int s;
    double v[4];
  } r[3];
  cyc_darboux D2 = D;
  for (double& v : D2.k) v *= 2;
  for (int i = 0; i < 3; ++i) {
    fz::fill_sentinel(r[i].v, 4);
    r[i].s = cyc_darboux_eval(c.ctx, nulls == 1 ? nullptr : (i == 2 ? &D2 : &D),
                              nulls == 2 ? nullptr : X, nulls == 3 ? nullptr : r[i].v,
                              want_grad ? r[i].v + 1 : nullptr);
    c.check("cyc_darboux_eval", r[i].s);
  }
  FZ_CHECK(r[0].s == r[1].s && same_bits(r[0].v, r[1].v, sizeof r[0].v),
           "cyc_darboux_eval not deterministic");
  if (nulls) {
    FZ_CHECK(r[0].s == CYC_E_NULL_ARGUMENT, "darboux_eval(NULL): %s", cyc_status_name(r[0].s));
  } else if (!finite_n(D.k, 14) || max_abs(D.k, 14) > 1e100 || !finite_n(X, 3) ||
             max_abs(X, 3) > 1e100) {
    FZ_CHECK(r[0].s == CYC_E_NOT_FINITE, "darboux_eval of non-finite input: %s",
             cyc_status_name(r[0].s));
  }
  if (r[0].s != CYC_OK) {
    FZ_CHECK(fz::all_sentinel(r[0].v, 4), "cyc_darboux_eval: %s but wrote an output",
             cyc_status_name(r[0].s));
    return;
  }
  FZ_CHECK(finite_n(r[0].v, want_grad ? 4 : 1), "cyc_darboux_eval OK but not finite");
  if (!want_grad) FZ_CHECK(fz::all_sentinel(r[0].v + 1, 3), "darboux_eval wrote the gradient");
  // Scaling the equation by 2 scales value and gradient by exactly 2.
  if (r[2].s == CYC_OK) {
    for (int i = 0; i < (want_grad ? 4 : 1); ++i) {
      const double a = r[0].v[i], b = r[2].v[i];
      if (std::abs(a) < 1e-290 || std::abs(b) < 1e-290) continue;  // subnormal rounding
      FZ_CHECK(b == 2 * a, "darboux_eval(2 D) output %d = %.17g != 2 x %.17g", i, b, a);
    }
  }
  // The value against the sum of its terms computed here.
  const double v = value(D.k, X), terms = abs_value(D.k, X);
  if (std::isfinite(terms))  // (1e-300: subnormal terms round absolutely)
    FZ_CHECK(std::abs(r[0].v[0] - v) <= 64 * kEps * terms + 1e-300,
             "darboux_eval value %.17g, expected %.17g (terms %g)", r[0].v[0], v, terms);
}

void op_darboux_classify(Input& in, Ctx& c) {
  cyc_darboux D;
  darboux(in, D);
  if (in.rarely()) std::memset(D.k, 0, sizeof D.k);
  const int nulls = in.rarely() ? in.range(1, 2) : 0;
  cyc_darboux Dv[3] = {D, D, D};
  for (double& v : Dv[1].k) v *= 2;
  for (double& v : Dv[2].k) v = -v;
  int t[4], s[4];
  for (int i = 0; i < 4; ++i) {
    t[i] = -77;
    s[i] = cyc_darboux_classify(c.ctx, nulls == 1 ? nullptr : &Dv[i == 3 ? 0 : i],
                                nulls == 2 ? nullptr : &t[i]);
    c.check("cyc_darboux_classify", s[i]);
  }
  FZ_CHECK(s[0] == s[3] && t[0] == t[3], "cyc_darboux_classify not deterministic");
  if (nulls) FZ_CHECK(s[0] == CYC_E_NULL_ARGUMENT, "classify(NULL): %s", cyc_status_name(s[0]));
  if (s[0] != CYC_OK) {
    FZ_CHECK(t[0] == -77, "classify: %s but wrote the type", cyc_status_name(s[0]));
    return;
  }
  FZ_CHECK(t[0] >= CYC_DARBOUX_ZERO && t[0] <= CYC_DARBOUX_REDUCIBLE, "type %d", t[0]);
  const double scale = max_abs(D.k, 14);
  FZ_CHECK((t[0] == CYC_DARBOUX_ZERO) == (scale == 0), "type %d for scale %g", t[0], scale);
  // A quartic is QUARTIC or, if it is a product of two spheres, REDUCIBLE.
  const bool quartic = std::abs(D.k[0]) > 1e-12 * scale;
  FZ_CHECK(!quartic || t[0] == CYC_DARBOUX_QUARTIC || t[0] == CYC_DARBOUX_REDUCIBLE,
           "type %d with phi0 = %g, scale %g", t[0], D.k[0], scale);
  FZ_CHECK(quartic || t[0] != CYC_DARBOUX_QUARTIC, "QUARTIC with phi0 = %g, scale %g", D.k[0],
           scale);
  FZ_LOG("classify -> %d (2D: %d, -D: %d)", t[0], t[1], t[2]);
  // The type does not depend on the equation's scale (it is classified
  // after an exact division by a power of two), down to subnormals.
  if (s[1] == CYC_OK)
    FZ_CHECK(t[1] == t[0], "classify(2 D) = %d != classify(D) = %d", t[1], t[0]);
  FZ_CHECK(s[2] == CYC_OK && t[2] == t[0], "classify(-D) = %d != classify(D) = %d", t[2], t[0]);
}

void op_invert_darboux(Input& in, Ctx& c) {
  cyc_inversion inv;
  inversion(in, inv);
  cyc_darboux D;
  darboux(in, D);
  double X0[3];
  const bool on = in.flag();
  if (on) {  // make D pass through X0 (possibly the center)
    point(in, inv, X0);
    D.k[13] -= value(D.k, X0);
  }
  const int nulls = in.rarely() ? in.range(1, 3) : 0;
  cyc_darboux r[2];
  int st[2];
  for (int i = 0; i < 2; ++i) {
    sentinel(r[i]);
    st[i] = cyc_invert_darboux(c.ctx, nulls == 1 ? nullptr : &inv, nulls == 2 ? nullptr : &D,
                               nulls == 3 ? nullptr : &r[i]);
    c.check("cyc_invert_darboux", st[i]);
  }
  if (fz::verbose()) {
    FZ_LOG("invert_darboux m = (%a %a %a) rho = %a -> %s", inv.center[0], inv.center[1],
           inv.center[2], inv.radius, cyc_status_name(st[0]));
    if (on) FZ_LOG("    X0 = (%a %a %a), D(X0) = %a", X0[0], X0[1], X0[2], value(D.k, X0));
    for (int i = 0; i < 14; ++i)
      FZ_LOG("    k[%d] = %a -> %a", i, D.k[i], st[0] == CYC_OK ? r[0].k[i] : 0.0);
  }
  FZ_CHECK(st[0] == st[1] && same_bits(&r[0], &r[1], sizeof r[0]),
           "cyc_invert_darboux not deterministic");
  if (nulls) FZ_CHECK(st[0] == CYC_E_NULL_ARGUMENT, "invert_darboux(NULL): %s",
                      cyc_status_name(st[0]));
  if (st[0] != CYC_OK) {
    FZ_CHECK(untouched(r[0]), "cyc_invert_darboux: %s but wrote the output",
             cyc_status_name(st[0]));
    return;
  }
  const cyc_darboux& R = r[0];
  FZ_CHECK(finite_n(R.k, 14), "cyc_invert_darboux OK but not finite");
  FZ_CHECK(max_abs(R.k, 14) == 1.0, "invert_darboux not normalized: max %.17g",
           max_abs(R.k, 14));
  // Well-scaled: X0 on D maps onto the image.
  if (!on || !inversion_ws(inv) || !std::all_of(D.k, D.k + 13, ws) || !away_from_center(inv, X0))
    return;
  // X0 is on D only if the shift of the constant term did not round away: a
  // huge constant term absorbs D(X0) (k13 - D(X0) == 0, fuzz_darboux finding
  // regress-invert-huge-constant-term).
  if (!(std::abs(value(D.k, X0)) <= 16 * kEps * abs_value(D.k, X0))) return;
  double Xp[3];
  if (invert_point_checked(c, &inv, X0, Xp) != CYC_OK) return;
  double raw[14], maj[14];
  image(D.k, inv, false, raw);
  image(D.k, inv, true, maj);
  const double s_est = max_abs(raw, 14);
  if (!(max_abs(maj, 14) <= 1e6 * s_est)) return;  // too much cancellation to judge
  double val, grad[3];
  const int se = cyc_darboux_eval(c.ctx, &R, Xp, &val, grad);
  c.check("cyc_darboux_eval", se);
  if (se != CYC_OK) return;
  double Y[3], Yp[3];
  sub3(X0, inv.center, Y);
  sub3(Xp, inv.center, Yp);
  const double nY = fz::norm3(Y), nYp = fz::norm3(Yp), nm = fz::norm3(inv.center);
  const double dX = 8 * kEps * (nm + nYp * (2 + (fz::norm3(X0) + nm) / nY));
  // D(X0) is only zero to the rounding of its terms; the image carries that
  // times |Y'|^4 (part of the majorant's terms).
  const double tol = 1e-9 * abs_value(maj, Xp) / s_est + 1e3 * fz::norm3(grad) * dX;
  FZ_CHECK(std::abs(val) <= tol,
           "a point of the cyclide maps off the inverted cyclide: |F'(X')| = %.3g > %.3g",
           std::abs(val), tol);
}

// Three lines for DCMC: Example 4 (34), lines in planes z = h_i, lines with a
// common normal in general position, near-parallel or arbitrary lines.
void dcmc_lines(Input& in, cyc_line* L) {
  switch (in.range(0, 4)) {
    case 0: {
      const cyc_line ex4[3] = {{{0, 0, 0}, {1, 0, 0}}, {{0, 0, 1}, {0, 1, 0}},
                               {{0, 0, 2}, {1, 1, 0}}};
      std::memcpy(L, ex4, sizeof ex4);
      break;
    }
    case 1:
    case 2: {  // z = h_i; case 2: line 2 nearly parallel to line 1
      for (int i = 0; i < 3; ++i) {
        coords(in, L[i].point, 3);
        L[i].direction[0] = coord(in);
        L[i].direction[1] = coord(in);
        L[i].direction[2] = 0;
      }
      if (in.flag()) L[1].point[2] = L[0].point[2];  // two coplanar lines
      break;
    }
    case 3: {  // common normal: d3 = a d1 + b d2
      for (int i = 0; i < 3; ++i) coords(in, L[i].point, 3);
      coords(in, L[0].direction, 3);
      coords(in, L[1].direction, 3);
      const double a = coord(in), b = coord(in);
      for (int i = 0; i < 3; ++i) L[2].direction[i] = a * L[0].direction[i] + b * L[1].direction[i];
      break;
    }
    default:
      for (int i = 0; i < 3; ++i) {
        coords(in, L[i].point, 3);
        coords(in, L[i].direction, 3);
      }
      break;
  }
  if (in.rarely()) {  // line 2 nearly parallel to line 1
    const int e = in.range(1, 60);
    for (int i = 0; i < 3; ++i)
      L[1].direction[i] = L[0].direction[i] + std::ldexp(double(in.range(-1, 1)), -e);
  }
}

bool lines_ws(const cyc_line* L) {
  for (int i = 0; i < 3; ++i) {
    if (!ws3(L[i].point) || !ws3(L[i].direction)) return false;
    const double ni = fz::norm3(L[i].direction);
    if (ni < 1e-3) return false;
    for (int j = i + 1; j < 3; ++j) {
      double cr[3];
      cross3(L[i].direction, L[j].direction, cr);
      if (fz::norm3(cr) < 1e-2 * ni * fz::norm3(L[j].direction)) return false;
    }
  }
  return true;
}

void op_dcmc(Input& in, Ctx& c) {
  cyc_line L[3];
  dcmc_lines(in, L);
  const bool want_n = !in.rarely();
  const int nulls = in.rarely() ? in.range(1, 3) : 0;
  struct R {
    int s;
    double n[3];
    cyc_darboux base, quadric;
  } r[2];
  for (R& x : r) {
    fz::fill_sentinel(x.n, 3);
    sentinel(x.base);
    sentinel(x.quadric);
    x.s = cyc_dcmc(c.ctx, nulls == 1 ? nullptr : L, want_n ? x.n : nullptr,
                   nulls == 2 ? nullptr : &x.base, nulls == 3 ? nullptr : &x.quadric);
    c.check("cyc_dcmc", x.s);
  }
  FZ_LOG("dcmc -> %s", cyc_status_name(r[0].s));
  FZ_CHECK(r[0].s == r[1].s && same_bits(r[0].n, r[1].n, sizeof r[0].n) &&
               same_bits(&r[0].base, &r[1].base, sizeof r[0].base) &&
               same_bits(&r[0].quadric, &r[1].quadric, sizeof r[0].quadric),
           "cyc_dcmc not deterministic");
  if (nulls) FZ_CHECK(r[0].s == CYC_E_NULL_ARGUMENT, "dcmc(NULL): %s", cyc_status_name(r[0].s));
  const R& o = r[0];
  if (o.s != CYC_OK) {
    FZ_CHECK(fz::all_sentinel(o.n, 3) && untouched(o.base) && untouched(o.quadric),
             "cyc_dcmc: %s but wrote an output", cyc_status_name(o.s));
    return;
  }
  FZ_CHECK(finite_n(o.base.k, 14) && finite_n(o.quadric.k, 14), "cyc_dcmc OK but not finite");
  if (!want_n) {
    FZ_CHECK(fz::all_sentinel(o.n, 3), "cyc_dcmc wrote the unrequested normal");
  } else {
    FZ_CHECK(fz::finite3(o.n) && std::abs(fz::norm3(o.n) - 1) <= 1e-12, "dcmc normal |n| = %.17g",
             fz::norm3(o.n));
    FZ_CHECK(same_bits(o.n, o.base.k + 1, sizeof o.n), "dcmc: base phi1 != n . X");
  }
  FZ_CHECK(o.base.k[0] == 0 && o.quadric.k[0] == 0 && o.quadric.k[1] == 0 &&
               o.quadric.k[2] == 0 && o.quadric.k[3] == 0,
           "dcmc: base or quadric has phi0 != 0 or the quadric has phi1 != 0");
  const double nb = fz::norm3(o.base.k + 1);
  FZ_CHECK(std::abs(nb - 1) <= 1e-12, "dcmc: |base phi1| = %.17g", nb);
  for (int i = 0; i < 3; ++i) {
    const double nd = fz::norm3(L[i].direction);
    FZ_CHECK(std::abs(fz::dot3(o.base.k + 1, L[i].direction)) <= 1e-9 * nd,
             "dcmc: n . d_%d = %.3g", i, fz::dot3(o.base.k + 1, L[i].direction));
  }
  double qq = 0, bq = 0, bb = 0;
  for (int i = 4; i < 14; ++i) {
    qq += o.quadric.k[i] * o.quadric.k[i];
    bq += o.base.k[i] * o.quadric.k[i];
    bb += o.base.k[i] * o.base.k[i];
  }
  FZ_CHECK(std::abs(std::sqrt(qq) - 1) <= 1e-12, "dcmc: |quadric| = %.17g", std::sqrt(qq));
  FZ_CHECK(std::abs(bq) <= 1e-9 * std::sqrt(bb) + 1e-300,
           "dcmc: base not orthogonal to the quadric: %.3g (|base| %g)", bq, std::sqrt(bb));
  // Members contain the lines (well-scaled lines only).
  const double alpha = coord(in);
  const int ts = in.range(0, 3);
  if (!lines_ws(L) || !std::isfinite(alpha) || std::abs(alpha) > 1e6) return;
  cyc_darboux M = o.base;
  for (int i = 0; i < 14; ++i) M.k[i] += alpha * o.quadric.k[i];
  const double tvals[4] = {0.0, 1.0, -2.5, 7.0};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j) {
      const double t = tvals[(ts + j) % 4];
      double X[3];
      for (int a = 0; a < 3; ++a) X[a] = L[i].point[a] + t * L[i].direction[a];
      double val;
      const int se = cyc_darboux_eval(c.ctx, &M, X, &val, nullptr);
      c.check("cyc_darboux_eval", se);
      FZ_CHECK(se == CYC_OK, "member eval failed: %s", cyc_status_name(se));
      // Relative to the coefficient scale at the sample's magnitude (the
      // solve's error is relative to the largest coefficient, not to each).
      const double sx = std::max({std::abs(X[0]), std::abs(X[1]), std::abs(X[2])});
      double kmax[14];
      std::fill(kmax, kmax + 14, max_abs(M.k, 14));
      const double X3[3] = {sx, sx, sx};
      const double tol = 1e-8 * abs_value(kmax, X3);
      FZ_CHECK(std::abs(val) <= tol,
               "DCMC member (alpha = %g) off line %d at t = %g: |F| = %.3g > %.3g", alpha, i,
               t, std::abs(val), tol);
    }
}

// ------------------------------------------------------------ surfaces

void op_surface_eval_inverted(Input& in, Ctx& c) {
  if (!c.S) return;
  cyc_inversion inv;
  inversion(in, inv);
  const double u = in.flag() ? c.u0 + (c.u1 - c.u0) * double(in.range(0, 1024)) / 1024.0
                             : in.wild();
  const double v = in.flag() ? in.moderate() : in.wild();
  const unsigned mask = in.rarely() ? unsigned(in.range(0, 7)) : 7u;
  const bool null_point = in.rarely();
  const bool center_on_surface = in.flag();
  if (center_on_surface) {  // the center on the surface: AT_INVERSION_CENTER
    double x0[3];
    const int s0 = cyc_surface_eval(c.ctx, c.S, u, v, x0, nullptr, nullptr, nullptr);
    c.check("cyc_surface_eval", s0);
    if (s0 == CYC_OK) std::memcpy(inv.center, x0, sizeof x0);
  }
  struct R {
    int s;
    double o[4][3];
  } r[2], e;
  for (R& x : r) {
    fz::fill_sentinel(&x.o[0][0], 12);
    x.s = cyc_surface_eval_inverted(c.ctx, c.S, &inv, u, v, null_point ? nullptr : x.o[0],
                                    mask & 1u ? x.o[1] : nullptr, mask & 2u ? x.o[2] : nullptr,
                                    mask & 4u ? x.o[3] : nullptr);
    c.check("cyc_surface_eval_inverted", x.s);
  }
  FZ_LOG("surface_eval_inverted u = %.17g v = %.17g mask %u -> %s", u, v, mask,
         cyc_status_name(r[0].s));
  FZ_CHECK(r[0].s == r[1].s && same_bits(r[0].o, r[1].o, sizeof r[0].o),
           "cyc_surface_eval_inverted not deterministic");
  if (null_point)
    FZ_CHECK(r[0].s == CYC_E_NULL_ARGUMENT, "eval_inverted(NULL point): %s",
             cyc_status_name(r[0].s));
  const R& o = r[0];
  if (o.s != CYC_OK) {
    FZ_CHECK(fz::all_sentinel(&o.o[0][0], 12), "cyc_surface_eval_inverted: %s but wrote an output",
             cyc_status_name(o.s));
  } else {
    FZ_CHECK(fz::finite3(o.o[0]), "eval_inverted OK but point not finite");
    for (int i = 0; i < 3; ++i) {
      if ((mask >> i) & 1u)
        FZ_CHECK(fz::finite3(o.o[i + 1]), "eval_inverted OK but output %d not finite", i + 1);
      else
        FZ_CHECK(fz::all_sentinel(o.o[i + 1], 3), "eval_inverted wrote unrequested output %d",
                 i + 1);
    }
  }
  if (null_point) return;
  // Against cyc_surface_eval and cyc_invert_point.
  fz::fill_sentinel(&e.o[0][0], 12);
  e.s = cyc_surface_eval(c.ctx, c.S, u, v, e.o[0], mask & 1u ? e.o[1] : nullptr,
                         mask & 2u ? e.o[2] : nullptr, mask & 4u ? e.o[3] : nullptr);
  c.check("cyc_surface_eval", e.s);
  if (e.s != CYC_OK) {
    if (inversion_valid(inv))
      FZ_CHECK(o.s == e.s, "eval failed with %s but eval_inverted returned %s",
               cyc_status_name(e.s), cyc_status_name(o.s));
    return;
  }
  if (o.s != CYC_OK) {
    FZ_CHECK(o.s == CYC_E_AT_INVERSION_CENTER || o.s == CYC_E_NUMERICAL_OVERFLOW ||
                 o.s == CYC_E_NOT_FINITE || o.s == CYC_E_INVALID_ARGUMENT,
             "eval OK but eval_inverted %s", cyc_status_name(o.s));
    if (o.s == CYC_E_AT_INVERSION_CENTER)
      FZ_CHECK(e.o[0][0] == inv.center[0] && e.o[0][1] == inv.center[1] &&
                   e.o[0][2] == inv.center[2],
               "eval_inverted: at the center but x != m");
    return;
  }
  double Xp[3];
  const int sp = invert_point_checked(c, &inv, e.o[0], Xp);
  if (sp == CYC_OK) {
    FZ_CHECK(fz::dist3(Xp, o.o[0]) <= 1e-12 * fz::norm3(Xp) + 1e-300,
             "eval_inverted point differs from invert_point(eval): %.3g",
             fz::dist3(Xp, o.o[0]));
  }
  if (!(mask & 4u)) return;
  FZ_CHECK(std::abs(fz::norm3(o.o[3]) - 1) <= 1e-9, "eval_inverted normal |n| = %.17g",
           fz::norm3(o.o[3]));
  // The inversion is conformal: the normal keeps its angles with the partials.
  for (int i = 0; i < 2; ++i) {
    if (!((mask >> i) & 1u)) continue;
    const double a = fz::norm3(e.o[i + 1]), b = fz::norm3(o.o[i + 1]);
    if (!(a > 1e-150 && b > 1e-150) || !std::isfinite(a) || !std::isfinite(b)) continue;
    const double ca = fz::dot3(e.o[3], e.o[i + 1]) / a, cb = fz::dot3(o.o[3], o.o[i + 1]) / b;
    FZ_CHECK(std::abs(ca - cb) <= 1e-9, "eval_inverted: n.x_%c/|x_%c| %.3g, before %.3g",
             i ? 'v' : 'u', i ? 'v' : 'u', cb, ca);
  }
}

void build_surface(Input& in, Ctx& c) {
  const int mode = in.range(0, 3);
  if (mode == 0) return;
  double p[3][6];
  bool prrs = false;
  switch (mode) {
    case 1: {  // Example 2: lines (u, 0, 0), (2u, u, 1) on [-1/2, 1/2]
      const double a[6] = {0, 0, 0, 1, 0, 0}, b[6] = {0, 0, 1, 2, 1, 0};
      std::memcpy(p[0], a, sizeof a);
      std::memcpy(p[1], b, sizeof b);
      c.u0 = -0.5;
      c.u1 = 0.5;
      break;
    }
    case 2: {  // Example 3: PRRS of (u, 0, 0), (0, 0, 1), (1, 2, 1) on [-2, 2]
      const double a[6] = {0, 0, 0, 1, 0, 0}, b[6] = {0, 0, 1, 0, 0, 0}, d[6] = {1, 2, 1, 0, 0, 0};
      std::memcpy(p[0], a, sizeof a);
      std::memcpy(p[1], b, sizeof b);
      std::memcpy(p[2], d, sizeof d);
      prrs = true;
      c.u0 = -2;
      c.u1 = 2;
      break;
    }
    default:  // PRCS of two moderate lines
      for (int i = 0; i < 2; ++i)
        for (double& x : p[i]) x = in.moderate();
      c.u0 = double(in.range(-8, 8)) / 4.0;
      c.u1 = c.u0 + double(in.range(1, 16)) / 4.0;
      break;
  }
  cyc_curve* cu[3] = {nullptr, nullptr, nullptr};
  int s = CYC_OK;
  for (int i = 0; i < (prrs ? 3 : 2) && s == CYC_OK; ++i) {
    s = (prrs && i > 0) ? cyc_curve_create_point(c.ctx, p[i], &cu[i])
                        : cyc_curve_create_line(c.ctx, p[i], p[i] + 3, &cu[i]);
    c.check("cyc_curve_create", s);
  }
  if (s == CYC_OK) {
    s = prrs ? cyc_prrs_create(c.ctx, cu[0], cu[1], cu[2], nullptr, c.u0, c.u1, &c.S)
             : cyc_prcs_create(c.ctx, cu[0], cu[1], nullptr, c.u0, c.u1, &c.S);
    c.check("cyc_*_create", s);
    if (s != CYC_OK) c.S = nullptr;
  }
  for (cyc_curve* x : cu) cyc_curve_destroy(c.ctx, x);
  FZ_LOG("surface mode %d -> %s", mode, cyc_status_name(s));
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
  build_surface(in, c);
  const int nops = in.range(1, 16);
  for (int i = 0; i < nops; ++i) {
    switch (in.range(0, 7)) {
      case 0: op_dcmc(in, c); break;
      case 1: op_invert_point(in, c); break;
      case 2: op_invert_sphere(in, c); break;
      case 3: op_invert_circle(in, c); break;
      case 4: op_invert_darboux(in, c); break;
      case 5: op_darboux_eval(in, c); break;
      case 6: op_darboux_classify(in, c); break;
      default: op_surface_eval_inverted(in, c); break;
    }
  }
  // A NULL context is reported, never a crash.
  double out[3];
  const double X[3] = {1, 2, 3};
  const cyc_inversion inv{{0, 0, 0}, 1};
  FZ_CHECK(cyc_invert_point(nullptr, &inv, X, out) == CYC_E_NULL_ARGUMENT,
           "cyc_invert_point(NULL context)");
  cyc_surface_destroy(c.ctx, c.S);
  cyc_context_destroy(c.ctx);
  return 0;
}
