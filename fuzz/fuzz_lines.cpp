// Fuzz target of the lines and circle families of parabolic Darboux
// cyclides (SPEC §8c, issue 3): cyc_parabolic_lines, cyc_pencil_circle,
// cyc_parabolic_parameterize, cyc_prrs_lines_analyze, cyc_prrs_lines_cyclide.
//
// Cyclides: the paper's (Examples 2, 4, 5, the family (60), App. A, B),
// arbitrary and sparse coefficients, near-reducible ones ((l.X + delta) times
// a sphere plus a tiny perturbation, e.g. z (X.X - 1) + tiny), near-quadrics
// (tiny l), DCMC members of fuzzed lines (so that the analysis sees real
// parabolic cyclides with known lines), examples with one hostile
// coefficient (NaN, Inf, huge, tiny), all optionally scaled.
//
// Oracles (abort on violation):
//  - every status is known, never CYC_E_INTERNAL; last status/message and
//    the error handler agree (fz::check_call); NULL arguments give
//    CYC_E_NULL_ARGUMENT; every call made twice gives identical bits;
//  - on error every output is untouched (byte sentinels; the surface pointer
//    *out keeps its value); on OK every output is finite;
//  - cyc_parabolic_lines: agrees with cyc_darboux_classify (NOT_PARABOLIC
//    exactly for finite non-parabolic input); |n| = 1; plane_count <= 5 with
//    kinds in 1..4; line_count <= 10; unit directions orthogonal to n, the
//    point nearest the origin, n . P = t; multiplicities in {1, 2};
//    circle_families = line_count + l0_circles; double_families = number of
//    double lines; scaling the coefficients by 2^e (no under/overflow) gives
//    identical bits;
//  - for well-scaled cyclides (every nonzero |k| in [1e-3, 1e3], |l| >=
//    1e-3 max |k|): every line lies on F (|F| <= 1e-8 |grad F| (1 + |X|)
//    plus the rounding of F's terms), cyc_pencil_circle accepts it (OK or
//    EMPTY_REAL_LOCUS) and its circle (the other line for the plane through
//    l0) lies on F; surfaces from cyc_parabolic_parameterize lie on F;
//  - DCMC members of three well-separated lines (see dcmc_member): the three
//    lines are found;
//  - cyc_parabolic_parameterize: PRCS without a double line is NOT_CANAL,
//    too few lines TOO_FEW_LINES (consistent with cyc_parabolic_lines);
//  - §8: flags are 0/1 and nested (cyclide => pencil => common_parameter =>
//    coplanar_pair), l4 is zero without a pencil, else unit and orthogonal to
//    the common normal; cyc_prrs_lines_cyclide is INVALID_ARGUMENT exactly
//    when the analysis has no common parameter or no pencil; on OK the
//    result is normalized (max |k| = 1), the residual finite and >= 0, and
//    for well-scaled lines l1, l3 and l4 lie on it (and l2 when (56) holds).
//
// Input layout: see make_seeds.py (LinesEncoder), which mirrors this file.
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
// |F(X)| <= kOnTol |grad F(X)| (1 + |X|) (+ rounding): X within ~1e-8 of F.
constexpr double kOnTol = 1e-8;

struct Ctx {
  cyc_context* ctx = nullptr;
  fz::HandlerLog log;
  fz::HandlerLog* logp = nullptr;
  void check(const char* fn, int s) { fz::check_call(fn, ctx, s, logp); }
};

// Byte sentinels for outputs of any layout (ints, padding).
constexpr unsigned char kByte = 0xA7;
template <class T>
void sentinel(T& x) {
  std::memset(static_cast<void*>(&x), kByte, sizeof x);
}
template <class T>
bool untouched(const T& x) {
  const auto* p = reinterpret_cast<const unsigned char*>(&x);
  for (size_t i = 0; i < sizeof x; ++i)
    if (p[i] != kByte) return false;
  return true;
}
template <class T>
bool same_bits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

bool finite_n(const double* v, int n) {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}
double max_abs(const double* k, int n) {
  double r = 0;
  for (int i = 0; i < n; ++i) r = std::max(r, std::abs(k[i]));
  return r;
}
void cross3(const double* a, const double* b, double* r) {
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
}
void normalize3(double* v) {
  const double n = fz::norm3(v);
  for (int i = 0; i < 3; ++i) v[i] /= n;
}

// ------------------------------------------------------------ inputs

// A dyadic coordinate in [-2, 2] (k / 64).
double dyadic(Input& in) { return double(in.range(-128, 128)) / 64.0; }

// ------------------------------------------------------------ Darboux

enum { kPhi0, kLx, kLy, kLz, kQxx, kQyy, kQzz, kQxy, kQxz, kQyz, kBx, kBy, kBz, kC };

void monomials(const double* X0, double* m, bool absolute) {
  double X[3];
  for (int i = 0; i < 3; ++i) X[i] = absolute ? std::abs(X0[i]) : X0[i];
  const double x = X[0], y = X[1], z = X[2], S = x * x + y * y + z * z;
  const double v[14] = {S * S, x * S, y * S, z * S, x * x, y * y, z * z,
                        x * y, x * z, y * z, x,     y,     z,     1.0};
  std::memcpy(m, v, sizeof v);
}
// sum |k_i| |monomial_i(X)|: the size of F's terms at X.
double abs_value(const double* k, const double* X) {
  double m[14], r = 0;
  monomials(X, m, true);
  for (int i = 0; i < 14; ++i) r += std::abs(k[i]) * m[i];
  return r;
}

// Well-scaled: every nonzero |k| in [1e-3, 1e3] and |l| >= 1e-3 max |k|.
bool darboux_ws(const cyc_darboux& D) {
  for (double v : D.k)
    if (!(v == 0 || (std::abs(v) >= 1e-3 && std::abs(v) <= 1e3))) return false;
  return fz::norm3(D.k + 1) >= 1e-3 * max_abs(D.k, 14) && D.k[0] == 0;
}

// Is X on F: |F| <= kOnTol |grad F| (1 + |X|) + the rounding of F's terms.
bool on_cyclide(Ctx& c, const cyc_darboux& D, const double* X, double tol_scale = 1,
                double* ratio = nullptr) {
  double val, g[3];
  const int s = cyc_darboux_eval(c.ctx, &D, X, &val, g);
  c.check("cyc_darboux_eval", s);
  if (s != CYC_OK) return true;  // overflow far out: nothing to judge
  const double tol = tol_scale * kOnTol * fz::norm3(g) * (1 + fz::norm3(X)) +
                     1e3 * kEps * abs_value(D.k, X);
  if (ratio) *ratio = std::abs(val) / (fz::norm3(g) * (1 + fz::norm3(X)));
  return std::abs(val) <= tol;
}

// Is the line (P, d) (d unit) on F: three points.
bool line_on(Ctx& c, const cyc_darboux& D, const double* P, const double* d, double* ratio) {
  const double len = 1 + fz::norm3(P);
  for (double s : {-1.5, 0.25, 2.0}) {
    double X[3];
    for (int i = 0; i < 3; ++i) X[i] = P[i] + s * len * d[i];
    if (!on_cyclide(c, D, X, 1, ratio)) return false;
  }
  return true;
}

void example(Input& in, cyc_darboux& D) {
  std::fill(D.k, D.k + 14, 0.0);
  double* k = D.k;
  switch (in.range(0, 5)) {
    case 0:  // Example 2 (39)
      k[kLz] = 4, k[kQyy] = -8, k[kQzz] = -3, k[kQxy] = -6, k[kBz] = -1;
      break;
    case 1:  // Example 5 (61)
      k[kLz] = 1, k[kQxy] = 0.5, k[kQxz] = -0.5, k[kQyz] = 0.5, k[kQyy] = -1,
      k[kQzz] = -13.0 / 4, k[kBz] = 0.75;
      break;
    case 2: {  // Example 4 (35)
      const double a = coord(in);
      k[kLz] = 1, k[kQyy] = -1, k[kQzz] = -3, k[kQxy] = -3, k[kBz] = 2, k[kQxz] = a,
      k[kQyz] = -2 * a, k[kBy] = 2 * a;
      break;
    }
    case 3: {  // Appendix A (70)
      const double a = coord(in), cc = coord(in);
      k[kLy] = cc, k[kLz] = -1, k[kQyy] = 1 - a * a - cc * cc, k[kQxy] = 2 * a, k[kQzz] = 2,
      k[kBy] = -cc, k[kBz] = -1;
      break;
    }
    case 4:  // Appendix B (73)
      k[kLz] = 4, k[kQyy] = -3, k[kQzz] = -8, k[kQxy] = -4, k[kQyz] = -10, k[kBy] = 10,
      k[kBz] = 4;
      break;
    default: {  // the DCMC family (60) of Example 5
      const double a = coord(in);
      k[kLz] = 1, k[kQxy] = 0.5, k[kQyy] = -1, k[kQzz] = a, k[kQxz] = -(34 + 8 * a) / 16,
      k[kQyz] = -(9 + 4 * a) / 8, k[kBy] = (13 + 4 * a) / 16, k[kBz] = -(1 + 4 * a) / 16;
      break;
    }
  }
}

// ------------------------------------------------------------ lines

// Three lines for DCMC members: in planes z = h_i (gaps >= 1/4 when `good`),
// directions at angles a0, a0 + s1, a0 + s1 + s2 (degrees), dyadic points,
// then a coordinate permutation/sign change. good: s1, s2 in [10, 80].
struct Three {
  cyc_line L[3];
  bool good = false;  // well separated: the oracle expects all three found
};

void three_lines(Input& in, Three& T) {
  const bool good = in.flag();
  const double a0 = in.range(0, 179);
  const double s1 = good ? in.range(10, 80) : in.range(0, 179);
  const double s2 = good ? in.range(10, 80) : in.range(0, 179);
  const double h0 = dyadic(in);
  const double g1 = good ? 0.25 + std::abs(dyadic(in)) : dyadic(in);
  const double g2 = good ? 0.25 + std::abs(dyadic(in)) : dyadic(in);
  const double h[3] = {h0, h0 + g1, h0 - g2};
  const double ang[3] = {a0, a0 + s1, a0 + s1 + s2};
  const int perm = in.range(0, 5), signs = in.range(0, 7);
  static constexpr int kPerm[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1},
                                      {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  for (int i = 0; i < 3; ++i) {
    const double a = ang[i] * M_PI / 180.0;
    const double P[3] = {dyadic(in), dyadic(in), h[i]};
    const double d[3] = {std::cos(a), std::sin(a), 0};
    for (int j = 0; j < 3; ++j) {
      const double sg = (signs >> j) & 1 ? -1.0 : 1.0;
      T.L[i].point[kPerm[perm][j]] = sg * P[j];
      T.L[i].direction[kPerm[perm][j]] = sg * d[j];
    }
  }
  T.good = good;
}

// A normalized DCMC member base + alpha quadric of three lines; false if
// DCMC fails.
bool dcmc_member(Input& in, Ctx& c, const Three& T, double alpha, cyc_darboux& D) {
  cyc_darboux base, quad;
  const int s = cyc_dcmc(c.ctx, T.L, nullptr, &base, &quad);
  c.check("cyc_dcmc", s);
  (void)in;
  if (s != CYC_OK) return false;
  for (int i = 0; i < 14; ++i) D.k[i] = base.k[i] + alpha * quad.k[i];
  const double m = max_abs(D.k, 14);
  if (!(m > 0) || !std::isfinite(m)) return false;
  for (double& v : D.k) v /= m;
  return true;
}

// A cyclide: examples, arbitrary or sparse coefficients, near-reducible,
// near-quadric, DCMC members, hostile; optionally scaled. Returns false for
// near-reducible ones: a plane nearly on F makes every line of it nearly on
// F, so its lines are ill-conditioned and the geometry is not judged.
bool cyclide(Input& in, Ctx& c, cyc_darboux& D) {
  bool judge = true;
  std::fill(D.k, D.k + 14, 0.0);
  switch (in.range(0, 6)) {
    case 0: example(in, D); break;
    case 1:  // arbitrary; phi0 = 0 unless rarely
      coords(in, D.k, 14);
      if (!in.rarely()) D.k[0] = 0;
      break;
    case 2:  // sparse moderate
      for (int i = 1; i < 14; ++i)
        if (!in.flag()) D.k[i] = in.moderate();
      break;
    case 3: {  // (l.X + delta)(X.X + e.X + f) + tiny: near-reducible
      judge = false;
      double l[3], e[3];
      if (in.flag()) {  // z (X.X - 1)
        l[0] = l[1] = 0, l[2] = 1, e[0] = e[1] = e[2] = 0;
      } else {
        coords(in, l, 3);
        coords(in, e, 3);
      }
      const double delta = in.flag() ? 0.0 : coord(in), f = in.flag() ? -1.0 : coord(in);
      for (int i = 0; i < 3; ++i) {
        D.k[1 + i] = l[i];
        D.k[4 + i] = l[i] * e[i] + delta;
        D.k[10 + i] = f * l[i] + delta * e[i];
      }
      D.k[kQxy] = l[0] * e[1] + l[1] * e[0];
      D.k[kQxz] = l[0] * e[2] + l[2] * e[0];
      D.k[kQyz] = l[1] * e[2] + l[2] * e[1];
      D.k[kC] = delta * f;
      const int which = in.range(0, 13), ex = in.range(0, 60);
      D.k[which] += std::ldexp(coord(in), -ex);
      break;
    }
    case 4: {  // a quadric plus a tiny l
      for (int i = 4; i < 14; ++i) D.k[i] = in.moderate();
      const int ex = in.range(0, 80);
      for (int i = 1; i < 4; ++i) D.k[i] = std::ldexp(double(in.range(-2, 2)), -ex);
      break;
    }
    case 5: {  // a DCMC member of fuzzed lines
      Three T;
      three_lines(in, T);
      const double alpha = coord(in);
      if (!dcmc_member(in, c, T, alpha, D)) example(in, D);
      break;
    }
    default: {  // an example with one hostile coefficient
      example(in, D);
      D.k[in.range(0, 13)] = in.wild();
      break;
    }
  }
  if (in.rarely()) {  // scaled
    const double s = in.flag() ? std::ldexp(1.0, in.range(-60, 60)) : in.wild();
    for (double& v : D.k) v *= s;
  }
  return judge;
}

void log_darboux(const char* what, const cyc_darboux& D) {
  if (!fz::verbose()) return;
  FZ_LOG("%s", what);
  for (int i = 0; i < 14; ++i) FZ_LOG("    k[%d] = %a (%.17g)", i, D.k[i], D.k[i]);
}

// ------------------------------------------------------------ checks

// Find L (any point, any direction) among the found lines (1e-6, scale aware).
bool found(const cyc_cyclide_lines& A, const cyc_line& L) {
  double d[3] = {L.direction[0], L.direction[1], L.direction[2]};
  normalize3(d);
  for (int i = 0; i < A.line_count; ++i) {
    const cyc_cyclide_line& F = A.lines[i];
    double cr[3];
    cross3(F.direction, d, cr);
    if (fz::norm3(cr) > 1e-6) continue;
    double w[3];
    for (int j = 0; j < 3; ++j) w[j] = L.point[j] - F.point[j];
    const double wd = fz::dot3(w, F.direction);
    for (int j = 0; j < 3; ++j) w[j] -= wd * F.direction[j];
    if (fz::norm3(w) <= 1e-6 * (1 + fz::norm3(L.point))) return true;
  }
  return false;
}

int parabolic_lines_checked(Ctx& c, const cyc_darboux& D, cyc_cyclide_lines& out) {
  cyc_cyclide_lines r[2];
  int s[2];
  for (int i = 0; i < 2; ++i) {
    sentinel(r[i]);
    s[i] = cyc_parabolic_lines(c.ctx, &D, &r[i]);
    c.check("cyc_parabolic_lines", s[i]);
  }
  FZ_CHECK(s[0] == s[1] && same_bits(r[0], r[1]), "cyc_parabolic_lines not deterministic");
  if (s[0] != CYC_OK) {
    FZ_CHECK(untouched(r[0]), "cyc_parabolic_lines: %s but wrote the output",
             cyc_status_name(s[0]));
    return s[0];
  }
  const cyc_cyclide_lines& A = r[0];
  FZ_CHECK(fz::finite3(A.normal) && std::abs(fz::norm3(A.normal) - 1) <= 1e-12,
           "parabolic_lines: |n| = %.17g", fz::norm3(A.normal));
  FZ_CHECK(A.plane_count >= 0 && A.plane_count <= CYC_MAX_SECTION_PLANES,
           "parabolic_lines: plane_count %d", A.plane_count);
  FZ_CHECK(A.line_count >= 0 && A.line_count <= CYC_MAX_CYCLIDE_LINES,
           "parabolic_lines: line_count %d", A.line_count);
  for (int i = 0; i < A.plane_count; ++i) {
    FZ_CHECK(std::isfinite(A.plane_t[i]), "parabolic_lines: plane %d t not finite", i);
    FZ_CHECK(A.plane_kind[i] >= CYC_SECTION_LINE_PAIR && A.plane_kind[i] <= CYC_SECTION_LINE_AND_L0,
             "parabolic_lines: plane %d kind %d", i, A.plane_kind[i]);
  }
  int doubles = 0;
  for (int i = 0; i < A.line_count; ++i) {
    const cyc_cyclide_line& L = A.lines[i];
    FZ_CHECK(fz::finite3(L.point) && fz::finite3(L.direction) && std::isfinite(L.t),
             "parabolic_lines: line %d not finite", i);
    FZ_CHECK(L.multiplicity == 1 || L.multiplicity == 2, "parabolic_lines: line %d mult %d", i,
             L.multiplicity);
    doubles += L.multiplicity == 2;
    FZ_CHECK(std::abs(fz::norm3(L.direction) - 1) <= 1e-12, "line %d: |d| = %.17g", i,
             fz::norm3(L.direction));
    FZ_CHECK(std::abs(fz::dot3(L.direction, A.normal)) <= 1e-12, "line %d: d . n = %.3g", i,
             fz::dot3(L.direction, A.normal));
    const double nP = fz::norm3(L.point);
    FZ_CHECK(std::abs(fz::dot3(L.point, L.direction)) <= 1e-12 * nP + 1e-300,
             "line %d: P not nearest the origin: P . d = %.3g (|P| = %g)", i,
             fz::dot3(L.point, L.direction), nP);
    FZ_CHECK(std::abs(fz::dot3(L.point, A.normal) - L.t) <= 1e-10 * (nP + std::abs(L.t)) + 1e-300,
             "line %d: n . P = %.17g but t = %.17g", i, fz::dot3(L.point, A.normal), L.t);
  }
  FZ_CHECK(A.l0_circles == 0 || A.l0_circles == 1, "l0_circles %d", A.l0_circles);
  FZ_CHECK(A.circle_families == A.line_count + A.l0_circles,
           "circle_families %d != line_count %d + l0_circles %d", A.circle_families,
           A.line_count, A.l0_circles);
  FZ_CHECK(A.double_families == doubles, "double_families %d but %d double lines",
           A.double_families, doubles);
  out = A;
  return CYC_OK;
}

// The pencil circle of a found line at angle theta (0: the plane through l0)
// lies on F.
void check_pencil(Ctx& c, const cyc_darboux& D, const cyc_cyclide_lines& A, int i,
                  int angle_deg, bool ws) {
  const cyc_cyclide_line& F = A.lines[i];
  double k[3];
  cross3(A.normal, F.direction, k);
  normalize3(k);
  const double th = angle_deg * M_PI / 180.0;
  double m[3];
  for (int j = 0; j < 3; ++j) m[j] = std::cos(th) * A.normal[j] + std::sin(th) * k[j];
  cyc_line L;
  std::memcpy(L.point, F.point, sizeof L.point);
  std::memcpy(L.direction, F.direction, sizeof L.direction);
  cyc_circle_or_line r[2];
  int s[2];
  for (int j = 0; j < 2; ++j) {
    sentinel(r[j]);
    s[j] = cyc_pencil_circle(c.ctx, &D, &L, m, &r[j]);
    c.check("cyc_pencil_circle", s[j]);
  }
  FZ_LOG("pencil_circle line %d angle %d -> %s", i, angle_deg, cyc_status_name(s[0]));
  FZ_CHECK(s[0] == s[1] && same_bits(r[0], r[1]), "cyc_pencil_circle not deterministic");
  if (s[0] != CYC_OK) {
    FZ_CHECK(untouched(r[0]), "cyc_pencil_circle: %s but wrote the output",
             cyc_status_name(s[0]));
    // The plane through l0 of a line whose section is (line, l0 twice) has
    // no finite residual: EMPTY_REAL_LOCUS, like an imaginary circle.
    if (ws)
      FZ_CHECK(s[0] == CYC_E_EMPTY_REAL_LOCUS,
               "pencil_circle rejects line %d of the well-scaled cyclide: %s", i,
               cyc_status_name(s[0]));
    return;
  }
  const cyc_circle_or_line& C = r[0];
  FZ_CHECK(C.is_line == 0 || C.is_line == 1, "pencil_circle is_line %d", C.is_line);
  FZ_CHECK(fz::finite3(C.point) && fz::finite3(C.axis) && std::isfinite(C.radius) &&
               C.radius >= 0,
           "pencil_circle OK but not finite");
  FZ_CHECK(std::abs(fz::norm3(C.axis) - 1) <= 1e-12, "pencil_circle |axis| = %.17g",
           fz::norm3(C.axis));
  if (!ws) return;
  if (C.is_line) {
    double ratio = 0;
    FZ_CHECK(line_on(c, D, C.point, C.axis, &ratio),
             "pencil_circle: the other line of the plane through l0 is off F (ratio %.3g)",
             ratio);
    return;
  }
  double e1[3], e2[3];
  const double* a = C.axis;
  const double t[3] = {std::abs(a[0]) < 0.6 ? 1.0 : 0.0, std::abs(a[0]) < 0.6 ? 0.0 : 1.0, 0};
  cross3(a, t, e1);
  normalize3(e1);
  cross3(a, e1, e2);
  for (double phi = 0; phi < 6.2; phi += 1.1) {
    double X[3];
    for (int j = 0; j < 3; ++j)
      X[j] = C.point[j] + C.radius * (std::cos(phi) * e1[j] + std::sin(phi) * e2[j]);
    double ratio = 0;
    FZ_CHECK(on_cyclide(c, D, X, 1, &ratio),
             "pencil circle of line %d (angle %d deg) off F at phi %.1f: ratio %.3g "
             "(r = %g)", i, angle_deg, phi, ratio, C.radius);
  }
}

// cyc_parabolic_parameterize with the surface pointer and inputs checked.
void parameterize(Input& in, Ctx& c, const cyc_darboux& D, const cyc_cyclide_lines* A,
                  int lines_status, bool ws) {
  int kind;
  switch (in.range(0, 3)) {
    case 0: kind = CYC_SURFACE_PRCS; break;
    case 1: kind = CYC_SURFACE_PRRS; break;
    case 2: kind = 0; break;
    default: kind = in.range(-3, 7); break;
  }
  double u0, u1;
  if (in.flag()) {
    u0 = -1, u1 = 1;
  } else {
    u0 = coord(in);
    u1 = coord(in);
  }
  const bool want_inputs = !in.rarely();
  const int nulls = in.rarely() ? in.range(1, 2) : 0;
  cyc_surface* const kUnset = reinterpret_cast<cyc_surface*>(uintptr_t(0x5eed));
  cyc_surface* S = kUnset;
  cyc_line inputs[3];
  sentinel(inputs);
  const int s = cyc_parabolic_parameterize(c.ctx, nulls == 1 ? nullptr : &D, kind, u0, u1,
                                           want_inputs ? inputs : nullptr,
                                           nulls == 2 ? nullptr : &S);
  c.check("cyc_parabolic_parameterize", s);
  FZ_LOG("parabolic_parameterize kind %d [%.17g, %.17g] -> %s", kind, u0, u1,
         cyc_status_name(s));
  if (nulls) {
    FZ_CHECK(s == CYC_E_NULL_ARGUMENT, "parabolic_parameterize(NULL): %s", cyc_status_name(s));
    FZ_CHECK(S == kUnset && untouched(inputs), "parabolic_parameterize(NULL) wrote an output");
    return;
  }
  if (s != CYC_OK) {
    FZ_CHECK(S == kUnset, "parabolic_parameterize: %s but changed *out", cyc_status_name(s));
    FZ_CHECK(untouched(inputs), "parabolic_parameterize: %s but wrote inputs",
             cyc_status_name(s));
    if (kind != CYC_SURFACE_PRCS && kind != CYC_SURFACE_PRRS)
      FZ_CHECK(s == CYC_E_INVALID_ARGUMENT, "parabolic_parameterize kind %d: %s", kind,
               cyc_status_name(s));
    // (u0, u1 beyond the input range are refused first: NOT_FINITE)
    if (A && lines_status == CYC_OK && kind == CYC_SURFACE_PRCS && A->double_families == 0 &&
        std::abs(u0) <= 1e100 && std::abs(u1) <= 1e100)
      FZ_CHECK(s == CYC_E_NOT_CANAL, "PRCS without a double line: %s", cyc_status_name(s));
    if (lines_status != CYC_OK && lines_status != CYC_E_NULL_ARGUMENT &&
        (kind == CYC_SURFACE_PRCS || kind == CYC_SURFACE_PRRS))
      // (parameterize validates its own numbers first: NOT_FINITE names one)
      FZ_CHECK(s == lines_status || s == CYC_E_NOT_FINITE,
               "parabolic_lines failed with %s but parameterize %s",
               cyc_status_name(lines_status), cyc_status_name(s));
    return;
  }
  FZ_CHECK(kind == CYC_SURFACE_PRCS || kind == CYC_SURFACE_PRRS, "kind %d accepted", kind);
  FZ_CHECK(S != kUnset && S != nullptr, "parabolic_parameterize OK without a surface");
  if (A && lines_status == CYC_OK)
    FZ_CHECK(A->line_count >= (kind == CYC_SURFACE_PRCS ? 3 : 4),
             "parameterize OK with %d lines", A->line_count);
  if (want_inputs) {
    FZ_CHECK(finite_n(&inputs[0].point[0], 18), "parameterize inputs not finite");
    if (kind == CYC_SURFACE_PRCS) {
      const cyc_line zero{{0, 0, 0}, {0, 0, 0}};
      FZ_CHECK(std::memcmp(&inputs[2], &zero, sizeof zero) == 0, "PRCS: third input not zero");
    }
  }
  int type = -1;
  const int st = cyc_surface_kind(c.ctx, S, &type);
  c.check("cyc_surface_kind", st);
  FZ_CHECK(st == CYC_OK && type == kind, "surface type %d != kind %d", type, kind);
  if (ws) {
    double a = 0, b = 0;
    const int sd = cyc_surface_domain(c.ctx, S, &a, &b);
    c.check("cyc_surface_domain", sd);
    for (double fu : {0.0, 0.5, 1.0})
      for (double v : {-3.0, -0.4, 0.0, 0.7, 5.0}) {
        const double u = a + fu * (b - a);
        double X[3];
        const int se = cyc_surface_eval(c.ctx, S, u, v, X, nullptr, nullptr, nullptr);
        c.check("cyc_surface_eval", se);
        if (se != CYC_OK) continue;
        double ratio = 0;
        FZ_CHECK(on_cyclide(c, D, X, 1, &ratio),
                 "parameterized surface (kind %d) off F at u = %g v = %g: ratio %.3g", kind, u,
                 v, ratio);
      }
  }
  cyc_surface_destroy(c.ctx, S);
}

// The whole analysis of one cyclide; `expect` (3 lines) must be found.
void analyze(Input& in, Ctx& c, const cyc_darboux& D, const Three* expect, bool judge = true) {
  log_darboux("parabolic_lines of", D);
  const bool null_out = in.rarely();
  if (null_out) {
    const int s = cyc_parabolic_lines(c.ctx, &D, nullptr);
    c.check("cyc_parabolic_lines", s);
    FZ_CHECK(s == CYC_E_NULL_ARGUMENT, "parabolic_lines(NULL): %s", cyc_status_name(s));
  }
  cyc_cyclide_lines A;
  const int s = parabolic_lines_checked(c, D, A);
  FZ_LOG("parabolic_lines -> %s (%d lines, %d planes)", cyc_status_name(s),
         s == CYC_OK ? A.line_count : -1, s == CYC_OK ? A.plane_count : -1);
  // Against the classification.
  int type = -1;
  const int sc = cyc_darboux_classify(c.ctx, &D, &type);
  c.check("cyc_darboux_classify", sc);
  if (sc == CYC_OK) {
    if (type != CYC_DARBOUX_PARABOLIC)
      FZ_CHECK(s == CYC_E_NOT_PARABOLIC, "type %d but parabolic_lines %s", type,
               cyc_status_name(s));
    else
      FZ_CHECK(s != CYC_E_NOT_PARABOLIC, "parabolic but parabolic_lines NOT_PARABOLIC");
  } else {
    FZ_CHECK(s == sc, "classify %s but parabolic_lines %s", cyc_status_name(sc),
             cyc_status_name(s));
  }
  bool ws = judge && s == CYC_OK && darboux_ws(D);
  if (ws) {
    // The analysis resolves degenerate planes ~1e-4 L apart (SPEC §8c);
    // closer ones (e.g. a line pair next to an imaginary pair) may give lines
    // off F by ~their gap: not judged (see fuzz/README.md).
    const double ln = fz::norm3(D.k + 1);
    const double L = std::max({max_abs(D.k + 4, 6) / ln, std::sqrt(max_abs(D.k + 10, 3) / ln),
                               std::cbrt(std::abs(D.k[13]) / ln)});
    for (int i = 0; i < A.plane_count; ++i)
      for (int j = i + 1; j < A.plane_count; ++j)
        if (std::abs(A.plane_t[i] - A.plane_t[j]) < 1e-6 * L) ws = false;
    // Lines far beyond the length scale (|P| > 1e3 L, e.g. a parallel pair
    // 4e4 L apart) are ill-conditioned: not judged.
    for (int i = 0; i < A.line_count; ++i)
      if (fz::norm3(A.lines[i].point) > 1e3 * L) ws = false;
  }
  if (s == CYC_OK) {
    // Scaling by 2^e changes nothing (no under/overflow in range).
    const int e = in.range(-8, 8);
    const double m = max_abs(D.k, 14);
    double mn = m;
    for (double v : D.k)
      if (v != 0) mn = std::min(mn, std::abs(v));
    if (e != 0 && m < 1e90 && mn > 1e-200) {
      cyc_darboux E = D;
      for (double& v : E.k) v = std::ldexp(v, e);
      cyc_cyclide_lines B;
      const int sb = parabolic_lines_checked(c, E, B);
      FZ_CHECK(sb == CYC_OK && same_bits(A, B),
               "parabolic_lines of 2^%d D differs (%s, %d lines vs %d)", e,
               cyc_status_name(sb), sb == CYC_OK ? B.line_count : -1, A.line_count);
    }
    if (ws) {
      for (int i = 0; i < A.line_count; ++i) {
        double ratio = 0;
        FZ_CHECK(line_on(c, D, A.lines[i].point, A.lines[i].direction, &ratio),
                 "line %d (t = %.17g, mult %d) is off the cyclide: ratio %.3g", i, A.lines[i].t,
                 A.lines[i].multiplicity, ratio);
      }
    }
    const int npc = A.line_count ? in.range(0, 3) : 0;
    for (int j = 0; j < npc; ++j) {
      const int i = in.range(0, A.line_count - 1);
      const int angle = in.flag() ? 0 : in.range(1, 179);
      check_pencil(c, D, A, i, angle, ws);
    }
    if (expect && expect->good) {
      for (int i = 0; i < 3; ++i) {
        if (!found(A, expect->L[i])) {
          for (int j = 0; j < A.line_count; ++j)
            FZ_LOG("  found P = (%g %g %g) d = (%g %g %g) t = %.17g m %d", A.lines[j].point[0],
                   A.lines[j].point[1], A.lines[j].point[2], A.lines[j].direction[0],
                   A.lines[j].direction[1], A.lines[j].direction[2], A.lines[j].t,
                   A.lines[j].multiplicity);
        }
        FZ_CHECK(found(A, expect->L[i]),
                 "DCMC line %d (P = (%g %g %g), d = (%g %g %g)) not found among %d", i,
                 expect->L[i].point[0], expect->L[i].point[1], expect->L[i].point[2],
                 expect->L[i].direction[0], expect->L[i].direction[1],
                 expect->L[i].direction[2], A.line_count);
      }
    }
  } else if (expect && expect->good && type == CYC_DARBOUX_PARABOLIC) {
    FZ_CHECK(false, "parabolic_lines of a DCMC member failed: %s", cyc_status_name(s));
  }
  if (in.flag()) parameterize(in, c, D, &A, s, ws);
}

// ------------------------------------------------------------ ops

void op_analyze(Input& in, Ctx& c) {
  cyc_darboux D;
  const bool judge = cyclide(in, c, D);
  analyze(in, c, D, nullptr, judge);
}

// DCMC member of fuzzed lines: the lines must be found when well separated.
void op_dcmc_member(Input& in, Ctx& c) {
  Three T;
  three_lines(in, T);
  const double alpha = in.flag() ? dyadic(in) : coord(in);
  cyc_darboux D;
  if (!dcmc_member(in, c, T, alpha, D)) {
    FZ_CHECK(!T.good || !(std::abs(alpha) <= 1e100), "DCMC of three well-separated lines failed");
    return;
  }
  // Alpha beyond [-8, 8] or a member that is not parabolic is not judged.
  if (!(std::abs(alpha) <= 8)) T.good = false;
  analyze(in, c, D, &T);
}

void op_pencil(Input& in, Ctx& c) {
  cyc_darboux D;
  cyclide(in, c, D);
  cyc_line L;
  coords(in, L.point, 3);
  coords(in, L.direction, 3);
  double m[3];
  coords(in, m, 3);
  const int nulls = in.rarely() ? in.range(1, 4) : 0;
  cyc_circle_or_line r[2];
  int s[2];
  for (int j = 0; j < 2; ++j) {
    sentinel(r[j]);
    s[j] = cyc_pencil_circle(c.ctx, nulls == 1 ? nullptr : &D, nulls == 2 ? nullptr : &L,
                             nulls == 3 ? nullptr : m, nulls == 4 ? nullptr : &r[j]);
    c.check("cyc_pencil_circle", s[j]);
  }
  FZ_CHECK(s[0] == s[1] && same_bits(r[0], r[1]), "cyc_pencil_circle not deterministic");
  if (nulls) FZ_CHECK(s[0] == CYC_E_NULL_ARGUMENT, "pencil_circle(NULL): %s",
                      cyc_status_name(s[0]));
  if (s[0] != CYC_OK) {
    FZ_CHECK(untouched(r[0]), "cyc_pencil_circle: %s but wrote the output",
             cyc_status_name(s[0]));
    return;
  }
  FZ_CHECK(fz::finite3(r[0].point) && fz::finite3(r[0].axis) && std::isfinite(r[0].radius),
           "pencil_circle OK but not finite");
}

void op_parameterize(Input& in, Ctx& c) {
  cyc_darboux D;
  cyclide(in, c, D);
  parameterize(in, c, D, nullptr, CYC_OK, false);
}

// §8: l1, l2 in one plane meeting at u0, l3 at height h (normal form up to
// a coordinate permutation), Example 5 (given or with mu applied), or any.
void prrs_lines(Input& in, cyc_line* L, bool& ws) {
  ws = false;
  switch (in.range(0, 3)) {
    case 0: {
      const cyc_line ex5[3] = {{{0, 0, 0}, {1, 0, 0}}, {{0, 0, 0}, {2, 1, 0}},
                               {{1, 1, 1}, {-2, 4, 0}}};
      std::memcpy(L, ex5, sizeof ex5);
      if (in.flag()) L[2].direction[0] = -1, L[2].direction[1] = 2;  // (58), mu = 1/2
      ws = true;
      break;
    }
    case 1:
    case 2: {
      const double u0 = dyadic(in), h = dyadic(in);
      double O[3] = {dyadic(in), dyadic(in), dyadic(in)};
      double d[3][3];
      for (auto& di : d) di[0] = dyadic(in), di[1] = dyadic(in), di[2] = 0;
      double P3[3] = {dyadic(in), dyadic(in), O[2] + h};
      for (int i = 0; i < 3; ++i) {
        L[0].point[i] = O[i] - u0 * d[0][i];
        L[1].point[i] = O[i] - u0 * d[1][i];
        L[2].point[i] = P3[i] - u0 * d[2][i];
        for (int j = 0; j < 3; ++j) L[j].direction[i] = d[j][i];
      }
      ws = std::abs(h) >= 0.25;
      for (int i = 0; i < 3; ++i) {
        const double ni = fz::norm3(d[i]);
        if (ni < 0.25) ws = false;
        for (int j = i + 1; j < 3; ++j) {
          double cr[3];
          cross3(d[i], d[j], cr);
          if (fz::norm3(cr) < 0.1 * ni * fz::norm3(d[j])) ws = false;
        }
      }
      if (in.rarely()) {  // perturb l2 off the common parameter or plane
        const int e = in.range(1, 60);
        L[1].point[in.range(0, 2)] += std::ldexp(1.0, -e);
        ws = false;
      }
      break;
    }
    default:
      for (int i = 0; i < 3; ++i) {
        coords(in, L[i].point, 3);
        coords(in, L[i].direction, 3);
      }
      break;
  }
}

double line_ratio(Ctx& c, const cyc_darboux& D, const cyc_line& L) {
  double d[3] = {L.direction[0], L.direction[1], L.direction[2]};
  normalize3(d);
  double ratio = 0;
  if (line_on(c, D, L.point, d, &ratio)) return 0;
  return ratio > 0 ? ratio : 1;
}

void op_prrs_lines(Input& in, Ctx& c) {
  cyc_line L[3];
  bool ws;
  prrs_lines(in, L, ws);
  const bool apply_mu = in.flag();
  const int nulls = in.rarely() ? in.range(1, 2) : 0;
  cyc_prrs_lines_analysis a[2];
  int sa[2];
  for (int j = 0; j < 2; ++j) {
    sentinel(a[j]);
    sa[j] = cyc_prrs_lines_analyze(c.ctx, nulls == 1 ? nullptr : L, nulls == 2 ? nullptr : &a[j]);
    c.check("cyc_prrs_lines_analyze", sa[j]);
  }
  FZ_CHECK(sa[0] == sa[1] && same_bits(a[0], a[1]), "cyc_prrs_lines_analyze not deterministic");
  FZ_LOG("prrs_lines_analyze -> %s", cyc_status_name(sa[0]));
  if (nulls) {
    FZ_CHECK(sa[0] == CYC_E_NULL_ARGUMENT, "prrs_lines_analyze(NULL): %s",
             cyc_status_name(sa[0]));
    return;
  }
  const cyc_prrs_lines_analysis& A = a[0];
  if (sa[0] != CYC_OK) {
    FZ_CHECK(untouched(A), "prrs_lines_analyze: %s but wrote the output", cyc_status_name(sa[0]));
  } else {
    FZ_CHECK(finite_n(&A.a2, 8) && std::isfinite(A.mu) && finite_n(A.l4.point, 3) &&
                 finite_n(A.l4.direction, 3),
             "prrs_lines_analyze OK but not finite");
    for (int f : {A.coplanar_pair, A.common_parameter, A.pencil, A.cyclide})
      FZ_CHECK(f == 0 || f == 1, "prrs_lines_analyze flag %d", f);
    FZ_CHECK(!A.cyclide || A.pencil, "cyclide without pencil");
    FZ_CHECK(!A.pencil || A.common_parameter, "pencil without common parameter");
    FZ_CHECK(!A.common_parameter || A.coplanar_pair, "common parameter but not coplanar");
    if (!A.pencil) {
      const cyc_line zero{{0, 0, 0}, {0, 0, 0}};
      FZ_CHECK(std::memcmp(&A.l4, &zero, sizeof zero) == 0, "l4 set without a pencil");
    } else {
      double n[3];
      cross3(L[0].direction, L[1].direction, n);
      normalize3(n);
      FZ_CHECK(std::abs(fz::norm3(A.l4.direction) - 1) <= 1e-12 &&
                   std::abs(fz::dot3(A.l4.direction, n)) <= 1e-9,
               "l4 direction not unit or not orthogonal to n");
    }
  }
  // The cyclide, optionally after d3 -> mu d3.
  cyc_line M[3];
  std::memcpy(M, L, sizeof M);
  bool mu_applied = false;
  if (apply_mu && sa[0] == CYC_OK && A.mu != 0 && std::abs(A.mu) <= 1e6) {
    for (double& v : M[2].direction) v *= A.mu;
    mu_applied = true;
  }
  cyc_prrs_lines_analysis B = A;
  int sb = sa[0];
  if (mu_applied) {
    sb = cyc_prrs_lines_analyze(c.ctx, M, &B);
    c.check("cyc_prrs_lines_analyze", sb);
  }
  cyc_darboux r[2];
  double res[2];
  int sc[2];
  for (int j = 0; j < 2; ++j) {
    sentinel(r[j]);
    sentinel(res[j]);
    sc[j] = cyc_prrs_lines_cyclide(c.ctx, M, &r[j], j ? nullptr : &res[j]);
    c.check("cyc_prrs_lines_cyclide", sc[j]);
  }
  FZ_LOG("prrs_lines_cyclide%s -> %s", mu_applied ? " (mu applied)" : "",
         cyc_status_name(sc[0]));
  FZ_CHECK(sc[0] == sc[1] && same_bits(r[0], r[1]), "cyc_prrs_lines_cyclide not deterministic");
  FZ_CHECK(untouched(res[1]), "prrs_lines_cyclide wrote a NULL residual");
  if (sb == CYC_OK) {
    const bool expect_invalid = !B.common_parameter || !B.pencil;
    if (expect_invalid)
      FZ_CHECK(sc[0] == CYC_E_INVALID_ARGUMENT, "analysis without pencil but cyclide: %s",
               cyc_status_name(sc[0]));
    else
      FZ_CHECK(sc[0] != CYC_E_INVALID_ARGUMENT, "analysis with pencil but cyclide invalid");
  } else {
    FZ_CHECK(sc[0] == sb, "analysis %s but cyclide %s", cyc_status_name(sb),
             cyc_status_name(sc[0]));
  }
  if (sc[0] != CYC_OK) {
    FZ_CHECK(untouched(r[0]) && untouched(res[0]), "prrs_lines_cyclide: %s but wrote an output",
             cyc_status_name(sc[0]));
    return;
  }
  const cyc_darboux& D = r[0];
  FZ_CHECK(finite_n(D.k, 14) && std::isfinite(res[0]) && res[0] >= 0,
           "prrs_lines_cyclide OK but not finite");
  FZ_CHECK(max_abs(D.k, 14) == 1.0, "prrs_lines_cyclide not normalized: %.17g",
           max_abs(D.k, 14));
  if (!ws || std::abs(B.mu) > 1e3) return;
  // l1, l3, l4 lie on it; l2 too when (56) holds.
  const cyc_line* on[3] = {&M[0], &M[2], &B.l4};
  for (int i = 0; i < 3; ++i) {
    const double q = line_ratio(c, D, *on[i]);
    FZ_CHECK(q == 0, "prrs_lines_cyclide: line %s off the cyclide (ratio %.3g)",
             i == 0 ? "l1" : i == 1 ? "l3" : "l4", q);
  }
  if (B.cyclide) {
    FZ_CHECK(res[0] <= 1e-8, "(56) holds but the residual is %.3g", res[0]);
    const double q = line_ratio(c, D, M[1]);
    FZ_CHECK(q == 0, "(56) holds but l2 is off the cyclide (ratio %.3g)", q);
  }
  // Analyze the result: the lines, their circles, Prop. 5.
  if (in.flag()) analyze(in, c, D, nullptr);
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
  const int nops = in.range(1, 8);
  for (int i = 0; i < nops; ++i) {
    switch (in.range(0, 4)) {
      case 0: op_analyze(in, c); break;
      case 1: op_dcmc_member(in, c); break;
      case 2: op_pencil(in, c); break;
      case 3: op_parameterize(in, c); break;
      default: op_prrs_lines(in, c); break;
    }
  }
  // A NULL context is reported, never a crash.
  cyc_darboux D{};
  D.k[3] = 1;
  cyc_cyclide_lines A;
  FZ_CHECK(cyc_parabolic_lines(nullptr, &D, &A) == CYC_E_NULL_ARGUMENT,
           "cyc_parabolic_lines(NULL context)");
  cyc_context_destroy(c.ctx);
  return 0;
}
