#include "cyclide/pcurve.hpp"

#include "poly_roots.hpp"
#include "power_form.hpp"
#include "cyclide/ringed.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cyclide {
inline namespace v0 {

using detail::finite;
using detail::max_abs;
using detail::power_form;

namespace {

// Polynomial arithmetic on CurvePoly that remembers a degree overflow.
struct Ring {
  bool overflow = false;
  CurvePoly mul(const CurvePoly& a, const CurvePoly& b) {
    CurvePoly r;
    if (!multiply(a, b, r)) overflow = true;
    return r;
  }
  CurvePoly sq(const CurvePoly& a) { return mul(a, a); }
};

}  // namespace

// Eqs. (8)-(11).
Status pcurve_frame(const CurvePoly (&x)[4], PCurveFrame& out) {
  int deg = 0;
  bool zero = true;
  for (const CurvePoly& p : x) {
    if (!finite(p)) return Status::not_finite;
    deg = std::max(deg, p.deg);
    zero = zero && p.is_zero();
  }
  if (zero) return Status::invalid_argument;
  if (2 * deg > kMaxCurveDegree) return Status::degree_too_high;
  Ring R;
  const CurvePoly s00 = R.sq(x[0]), s11 = R.sq(x[1]), s22 = R.sq(x[2]), s33 = R.sq(x[3]);
  auto twice = [&](const CurvePoly& a, const CurvePoly& b) { return R.mul(a, b).scaled(2.0); };
  PCurveFrame P;
  P.n[0] = s00 + s11 - s22 - s33;
  P.n[1] = twice(x[1], x[2]) - twice(x[0], x[3]);
  P.n[2] = twice(x[0], x[2]) + twice(x[1], x[3]);
  P.sigma = s00 + s11 + s22 + s33;
  P.n1[0] = twice(x[1], x[2]) + twice(x[0], x[3]);
  P.n1[1] = s00 - s11 + s22 - s33;
  P.n1[2] = twice(x[2], x[3]) - twice(x[0], x[1]);
  P.n2[0] = twice(x[1], x[3]) - twice(x[0], x[2]);
  P.n2[1] = twice(x[0], x[1]) + twice(x[2], x[3]);
  P.n2[2] = s00 - s11 - s22 + s33;
  if (R.overflow) return Status::degree_too_high;
  out = P;
  return Status::ok;
}

// Eq. (12).
RationalField pcurve_field(const PCurveFrame& P, double phi) {
  RationalField f;
  const double c = std::cos(phi), s = std::sin(phi);
  for (int j = 0; j < 3; ++j) f.F[j] = P.n1[j].scaled(c) + P.n2[j].scaled(s);
  f.w = P.sigma;
  return f;
}

// Top-down: q's leading coefficient is sqrt of p's; each further
// coefficient of q follows from the next coefficient of p = q^2.
bool poly_sqrt(const CurvePoly& p, CurvePoly& q, double tol, double* residual) {
  CurvePoly a = p;
  a.trim();
  const double scale = max_abs(a);
  if (residual) *residual = HUGE_VAL;
  if (!(scale > 0)) {  // p = 0: q = 0
    q = CurvePoly();
    if (residual) *residual = 0;
    return true;
  }
  if (a.deg % 2 != 0 || !(a.c[a.deg] > 0)) return false;
  const int m = a.deg / 2;
  CurvePoly r;
  r.deg = m;
  r.c[m] = std::sqrt(a.c[a.deg]);
  for (int k = m - 1; k >= 0; --k) {
    // Coefficient of t^(m + k) in q^2: 2 q_m q_k + sum_{i+j=m+k, k<i,j<m} q_i q_j.
    double s = a.c[m + k];
    for (int i = k + 1; i < m; ++i) {
      const int j = m + k - i;
      if (j > k && j < m) s -= r.c[i] * r.c[j];
    }
    r.c[k] = s / (2 * r.c[m]);
  }
  // Remainder: every coefficient of p - q^2.
  double worst = 0;
  for (int e = 0; e <= a.deg; ++e) {
    double s = a.c[e];
    for (int i = 0; i <= m; ++i)
      if (e - i >= 0 && e - i <= m) s -= r.c[i] * r.c[e - i];
    worst = std::max(worst, std::abs(s));
  }
  const double rel = worst / scale;
  if (residual) *residual = rel;
  if (!(rel <= tol)) return false;
  q = r;
  return true;
}

// Eqs. (13)-(16).
Status projection_field(const RationalCurve& n, const Vec3d& v, RationalField& out) {
  if (!input_ok(v)) return Status::not_finite;
  if (!(std::abs(v.norm() - 1.0) <= 1e-12)) return Status::invalid_argument;
  if (n.kind == CurveKind::line_element) return Status::invalid_argument;
  CurvePoly N[3], w;
  power_form(n, N, w);
  if (w.deg != 0) return Status::invalid_argument;  // polynomial n only
  for (CurvePoly& p : N) p = p.scaled(1.0 / w.c[0]);
  Ring R;
  const CurvePoly nv = N[0].scaled(v.x()) + N[1].scaled(v.y()) + N[2].scaled(v.z());
  CurvePoly s2 = R.sq(N[0]) + R.sq(N[1]) + R.sq(N[2]) - R.sq(nv);
  if (R.overflow) return Status::degree_too_high;
  s2.trim_relative(1e-14);
  CurvePoly sigma;
  if (!poly_sqrt(s2, sigma) || sigma.is_zero()) return Status::not_pythagorean;
  RationalField f;
  // n x v.
  f.F[0] = N[1].scaled(v.z()) - N[2].scaled(v.y());
  f.F[1] = N[2].scaled(v.x()) - N[0].scaled(v.z());
  f.F[2] = N[0].scaled(v.y()) - N[1].scaled(v.x());
  f.w = sigma;
  out = f;
  return Status::ok;
}

// Eq. (4).
Status ringed_curve(const RationalCurve& d, const CurvePoly& rho_num, const CurvePoly& rho_den,
                    const RationalField& f, RationalCurve& c) {
  if (d.kind == CurveKind::line_element) return Status::invalid_argument;
  if (!finite(rho_num) || !finite(rho_den) || !finite(f.w)) return Status::not_finite;
  for (const CurvePoly& p : f.F)
    if (!finite(p)) return Status::not_finite;
  if (rho_den.is_zero() || f.w.is_zero()) return Status::invalid_argument;
  CurvePoly D[3], wd;
  power_form(d, D, wd);
  Ring R;
  const CurvePoly den = R.mul(R.mul(wd, rho_den), f.w);
  const CurvePoly dq = R.mul(rho_den, f.w), wr = R.mul(wd, rho_num);
  double h[4 * (kMaxCurveDegree + 1)] = {};
  int deg = den.deg;
  CurvePoly num[3];
  for (int j = 0; j < 3; ++j) {
    num[j] = R.mul(D[j], dq) + R.mul(wr, f.F[j]);
    deg = std::max(deg, num[j].deg);
  }
  if (R.overflow) return Status::degree_too_high;
  for (int k = 0; k <= deg; ++k) {
    for (int j = 0; j < 3; ++j) h[4 * k + j] = num[j].c[k];
    h[4 * k + 3] = den.c[k];
  }
  const Status st = make_rational_curve(deg, h, c);
  return st == Status::not_finite ? Status::numerical_overflow : st;
}

// ------------------------------------------------------------ planar P-curves

namespace {

// sqrt with the principal branch; not_pythagorean for 0 (eqs. (43), (47)
// divide by it).
bool root(Complex p, Complex& r) {
  if (!(std::abs(p) > 0)) return false;
  r = std::sqrt(p);
  return true;
}

bool finite(Complex z) { return std::isfinite(z.real()) && std::isfinite(z.imag()); }

// The square roots r0 = sqrt(p0), r1 = sqrt(p1) of the end data, with the
// relative sign of r1 fixed by the data alone: r1 conj(r0) in the right
// half-plane (the P-curve w turns from r0 to r1 by less than a right angle,
// so p = w^2 by less than half a turn; ties on the imaginary axis to the
// upper half). Principal roots in the frame of the plane would make that
// sign depend on where the frame's e1 points: the same jets rotated about
// v crossed the branch cut at one end only and got the other interpolant
// (sign flipped). The overall sign of w does not matter (p = w^2).
bool roots(Complex p0, Complex p1, Complex& r0, Complex& r1) {
  if (!root(p0, r0) || !root(p1, r1)) return false;
  const Complex z = r1 * std::conj(r0);
  if (z.real() < 0 || (z.real() == 0 && z.imag() < 0)) r1 = -r1;
  return true;
}

Status check_data(Complex p0, Complex v0, Complex p1, Complex v1, int sign) {
  for (Complex z : {p0, v0, p1, v1})
    if (!finite(z) || !(std::abs(z.real()) <= kMaxInputMagnitude) ||
        !(std::abs(z.imag()) <= kMaxInputMagnitude))
      return Status::not_finite;
  if (sign != 1 && sign != -1) return Status::invalid_argument;
  return Status::ok;
}

Status finish(const Complex* w, int count) {
  for (int i = 0; i < count; ++i)
    if (!finite(w[i])) return Status::numerical_overflow;
  return Status::ok;
}

}  // namespace

// Eq. (43).
Status planar_pcurve_hermite(Complex p0, Complex v0, Complex p1, Complex v1, int sign,
                             PlanarPCurve& out) {
  if (Status st = check_data(p0, v0, p1, v1, sign); st != Status::ok) return st;
  Complex r0, r1;
  if (!roots(p0, p1, r0, r1)) return Status::not_pythagorean;
  const double s = sign;
  PlanarPCurve P;
  P.n = 3;
  P.w[0] = r0;
  P.w[1] = (6.0 * p0 + v0) / (6.0 * r0);
  P.w[2] = s * (6.0 * p1 - v1) / (6.0 * r1);
  P.w[3] = s * r1;
  if (Status st = finish(P.w, 4); st != Status::ok) return st;
  out = P;
  return Status::ok;
}

// Eq. (47) (all signs equal; the square roots placed as the ERRATA / the
// transcription's symbolic check confirm).
Status planar_pbiarc(Complex p0, Complex v0, Complex p1, Complex v1, double tau, int sign,
                     PlanarPCurve (&out)[2]) {
  if (Status st = check_data(p0, v0, p1, v1, sign); st != Status::ok) return st;
  if (!std::isfinite(tau)) return Status::not_finite;
  if (!(tau > 0 && tau < 1)) return Status::bad_domain;
  Complex r0, r1;
  if (!roots(p0, p1, r0, r1)) return Status::not_pythagorean;
  const double s = sign;
  Complex w[6];
  w[0] = r0;
  w[1] = (4.0 * p0 + v0) / (4.0 * r0);
  w[2] = ((tau - 1) * (s * r0 * v1 + r1 * (4.0 * p0 + v0)) + s * 4.0 * r0 * p1) /
         (4.0 * r0 * r1 * tau);
  w[3] = (tau * (-r1 * v0 + s * r0 * (4.0 * p1 - v1)) - 4.0 * p0 * r1) /
         (4.0 * r0 * r1 * (tau - 1));
  w[4] = s * (4.0 * p1 - v1) / (4.0 * r1);
  w[5] = s * r1;
  if (Status st = finish(w, 6); st != Status::ok) return st;
  for (int k = 0; k < 2; ++k) {
    out[k].n = 2;
    for (int i = 0; i < 3; ++i) out[k].w[i] = w[3 * k + i];
  }
  return Status::ok;
}

void planar_pcurve_polys(const PlanarPCurve& P, CurvePoly& x1, CurvePoly& x2, CurvePoly& sigma) {
  double re[4], im[4];
  for (int i = 0; i <= P.n; ++i) {
    re[i] = P.w[i].real();
    im[i] = P.w[i].imag();
  }
  CurvePoly a, b;
  from_bernstein(re, P.n, 0.0, 1.0, a);
  from_bernstein(im, P.n, 0.0, 1.0, b);
  Ring R;
  // (a + i b)^2 = a^2 - b^2 + 2 i a b; |w|^2 = a^2 + b^2.
  x1 = R.sq(a) - R.sq(b);
  x2 = R.mul(a, b).scaled(2.0);
  sigma = R.sq(a) + R.sq(b);
}

// ------------------------------------------------------------ the blend of §4

Status ringed_jet(const Surface& S, double u, RingedJet& out) {
  RingedData R;
  if (Status st = S.ringed(u, R); st != Status::ok) return st;
  if (!(R.rho2 > 0)) return Status::singular_point;
  out = ringed_jet_from(R);
  return Status::ok;
}

RingedJet ringed_jet_from(const RingedData& R) {
  RingedJet J;
  J.d = R.c;
  J.dd = R.dc;
  J.n = R.n;
  J.dn = R.dn;
  J.rho = std::sqrt(R.rho2);
  J.drho = R.rho_rho_prime / J.rho;
  return J;
}

namespace {

// |n x v| / |n| below this: n counts as parallel to v (§4 blend).
constexpr double kParallelTol = 1e-8;

// A rotation taking v to e3 (rows: an orthonormal basis e1, e2, v), with
// e1 the projection of the x axis (of the y axis if v is near x) onto the
// plane: the identity for v = e3, so the paper's coordinates are kept
// (the P-curve interpolants depend on the plane's frame through the
// branch of the complex square roots).
Eigen::Matrix3d to_e3(const Vec3d& v) {
  const Vec3d a = std::abs(v.x()) < 0.9 ? Vec3d::UnitX() : Vec3d::UnitY();
  const Vec3d e1 = (a - a.dot(v) * v).normalized(), e2 = v.cross(e1);
  Eigen::Matrix3d M;
  M.row(0) = e1.transpose();
  M.row(1) = e2.transpose();
  M.row(2) = v.transpose();
  return M;
}

// The Ferguson cubic (C^1 Hermite on [0, 1]) of scalar data, power form.
CurvePoly ferguson(double p0, double v0, double p1, double v1) {
  const double s[2] = {p0, v0}, e[2] = {p1, v1};
  double b[4];
  hermite_bernstein(1, 1.0, s, e, b);
  CurvePoly p;
  from_bernstein(b, 3, 0.0, 1.0, p);
  return p;
}

// Rotate the polynomial vector P (in the frame of M's rows) back: M^T P.
void rotate_back(const Eigen::Matrix3d& M, const CurvePoly (&P)[3], CurvePoly (&out)[3]) {
  for (int j = 0; j < 3; ++j)
    out[j] = P[0].scaled(M(0, j)) + P[1].scaled(M(1, j)) + P[2].scaled(M(2, j));
}

// p(t0 + h s) as a polynomial in s (Horner on the linear t0 + h s).
CurvePoly shifted(const CurvePoly& p, double t0, double h) {
  const CurvePoly lin = CurvePoly::linear(t0, h);
  CurvePoly q(p.c[p.deg]), r;
  for (int k = p.deg - 1; k >= 0; --k) {
    multiply(q, lin, r);  // degree <= p.deg: fits
    r.c[0] += p.c[k];
    q = r;
  }
  return q;
}

// The planar P-curve w in r = 1 - t: its Bernstein coefficients reversed.
PlanarPCurve reversed(const PlanarPCurve& P) {
  PlanarPCurve R;
  R.n = P.n;
  for (int i = 0; i <= P.n; ++i) R.w[i] = P.w[P.n - i];
  return R;
}

// The curve c (power form in r) as a Bernstein curve in r = 1 - t: on
// [u0, u0 + h] = [1, 0] of the global t.
RationalCurve bernstein_in_r(const RationalCurve& c) {
  const int n = c.degree();
  RationalCurve B;
  const CurvePoly* src[4] = {&c.x, &c.y, &c.z, &c.w};
  CurvePoly* dst[4] = {&B.x, &B.y, &B.z, &B.w};
  for (int i = 0; i < 4; ++i) {
    CurvePoly p = *src[i];
    p.deg = n;  // common formal degree (the coefficients above are zero)
    double b[kMaxCurveDegree + 1];
    to_bernstein(p, 0.0, 1.0, b);
    dst[i]->assign(b, n);
  }
  B.bernstein = true;
  B.u0 = 1.0;
  B.h = -1.0;
  B.update_constant_weight();
  return B;
}

Status polynomial_curve(const CurvePoly (&P)[3], RationalCurve& out) {
  int deg = 0;
  for (const CurvePoly& p : P) deg = std::max(deg, p.deg);
  double xyz[3 * (kMaxCurveDegree + 1)];
  for (int k = 0; k <= deg; ++k)
    for (int j = 0; j < 3; ++j) xyz[3 * k + j] = P[j].c[k];
  return make_polynomial_curve(deg, xyz, out);
}

}  // namespace

namespace {

Status pcurve_blend(const RingedJet& a, const RingedJet& b, const RingedBlendOptions& options,
                    Surface (&pieces)[2], int& count, double* bad_u);

}  // namespace

// Validated inputs that the construction cannot carry (e.g. tau = 1e-255:
// w2 of (47) ~ 1e255, the P-curve's coefficients beyond 1e100) overflow;
// not_finite stays reserved for non-finite or > 1e100 inputs.
Status make_ringed_pcurve_blend(const RingedJet& a, const RingedJet& b,
                                const RingedBlendOptions& options, Surface (&pieces)[2],
                                int& count, double* bad_u) {
  for (const RingedJet* J : {&a, &b})
    if (!input_ok(J->d) || !input_ok(J->dd) || !input_ok(J->n) || !input_ok(J->dn) ||
        !input_ok(J->rho) || !input_ok(J->drho))
      return Status::not_finite;
  if (!input_ok(options.v) || !input_ok(options.tau)) return Status::not_finite;
  const Status st = pcurve_blend(a, b, options, pieces, count, bad_u);
  return st == Status::not_finite ? Status::numerical_overflow : st;
}

namespace {

// The largest condition of the planar part the blend accepts (SPEC 8f.5):
// its circles (d, n, rho) then carry rounding of about 5 eps kappa, their
// derivatives about 14 eps kappa^1.5 (1e-7 here).
constexpr double kMaxPCurveCondition = 1e5;

// The blend's planar part: the rotation M taking v to e3 and the P-curve(s)
// (39) of the projection of n, one (43) or two (47) pieces [0, split],
// [split, 1] (the two-piece bump (57) splits a single P-curve at its tau).
struct PlanarLayout {
  Eigen::Matrix3d M;
  PlanarPCurve P[2];
  int m = 1;
  double split = 1.0;
};

Status planar_layout(const RingedJet& a, const RingedJet& b, const RingedBlendOptions& options,
                     PlanarLayout& L) {
  // v scaled by its largest component before normalizing: |v| of a tiny v
  // (components ~1e-245, fuzz_ringed regress-tiny-v) underflows to 0.
  const double vmax = options.v.cwiseAbs().maxCoeff();
  if (!(vmax > 0)) return Status::invalid_argument;
  if (options.tau != 0.0 && !(options.tau > 0 && options.tau < 1)) return Status::bad_domain;
  L.M = to_e3((options.v / vmax).normalized());
  // (39): the planar data as complex numbers. n (nearly) parallel to v at
  // an end leaves no planar data to take the square root of (rounding
  // would make |p| ~ 1e-16 |n|, and w1 huge).
  const Vec3d n0 = L.M * a.n, dn0 = L.M * a.dn, n1 = L.M * b.n, dn1 = L.M * b.dn;
  const Complex p0(n0.x(), n0.y()), v0(dn0.x(), dn0.y()), p1(n1.x(), n1.y()),
      v1(dn1.x(), dn1.y());
  if (!(std::abs(p0) > kParallelTol * n0.norm()) || !(std::abs(p1) > kParallelTol * n1.norm()))
    return Status::not_pythagorean;
  L.m = options.tau == 0.0 ? 1 : 2;
  L.split = L.m == 1 ? 1.0 : options.tau;
  const Status st = L.m == 1 ? planar_pcurve_hermite(p0, v0, p1, v1, options.sign, L.P[0])
                             : planar_pbiarc(p0, v0, p1, v1, options.tau, options.sign, L.P);
  if (st != Status::ok) return st;
  // x = w^2 beyond the curves' magnitude bound (w2 of (47) ~ 1/tau).
  for (int k = 0; k < L.m; ++k)
    for (int i = 0; i <= L.P[k].n; ++i)
      if (!(std::norm(L.P[k].w[i]) <= kMaxInputMagnitude)) return Status::numerical_overflow;
  // §5: the bump; the two-piece bump (57) splits the blend at its tau.
  const DirectrixBump& B = options.bump;
  if (!input_ok(B.w) || !input_ok(B.tau)) return Status::not_finite;
  const bool bumped = B.w != Vec3d::Zero();
  if (bumped && !(B.tau > 0 && B.tau < 1)) return Status::bad_domain;
  if (bumped && B.kind != BumpKind::single && B.kind != BumpKind::two_piece)
    return Status::invalid_argument;
  if (bumped && B.kind == BumpKind::two_piece) {
    if (L.m == 2 && options.tau != B.tau) return Status::invalid_argument;  // one split only
    if (L.m == 1) L.P[1] = L.P[0];  // the same P-curve on both sides
    L.m = 2;
    L.split = B.tau;
  }
  return Status::ok;
}

// Piece k's planar part x = (x1, x2) = w^2 and sigma = |w|^2 as polynomials
// in its variable s in [0, length]: s = t for the first piece, s = 1 - t
// for the second (built from its outer end, see pcurve_blend).
struct PiecePolys {
  CurvePoly x1, x2, sigma;
  double length = 1;
};
PiecePolys piece_polys(const PlanarLayout& L, int k) {
  const bool mirrored = k == 1;
  PiecePolys p;
  planar_pcurve_polys(mirrored ? reversed(L.P[k]) : L.P[k], p.x1, p.x2, p.sigma);
  p.length = mirrored ? 1 - L.split : L.split;
  return p;
}

// min of sigma >= 0 over [0, length]: the ends and the real roots of sigma'.
double least_sigma(const CurvePoly& sigma, double length) {
  double low = std::min(sigma(0.0), sigma(length));
  double s[kMaxCurveDegree];
  const int r = detail::nearly_real_roots(sigma.derivative(), s);
  for (int i = 0; i < r; ++i)
    if (s[i] > 0 && s[i] < length) low = std::min(low, sigma(s[i]));
  return low;
}

// The condition of the blend's planar part: the largest term of x = w^2 on
// a piece's domain over the least |x| = sigma there. n nearly parallel
// to v at an end (w small there, w' = v/(2w) large (43)) or inside (w
// passing near 0, e.g. a biarc whose joint is 0) makes x cancel, and the
// cancellation reaches c = d + rho f through f = (x2, -x1)/sigma. The
// pieces' polynomials are returned in pp for the construction.
double layout_condition(const PlanarLayout& L, PiecePolys (&pp)[2]) {
  double kappa = 0;
  for (int k = 0; k < L.m; ++k) {
    const PiecePolys& p = pp[k] = piece_polys(L, k);
    double top = 0, power = 1;  // the largest term |x_i| s^i on [0, length]
    for (int i = 0; i <= std::max(p.x1.deg, p.x2.deg); ++i, power *= p.length)
      top = std::max(top, power * std::hypot(i <= p.x1.deg ? p.x1.c[i] : 0.0,
                                              i <= p.x2.deg ? p.x2.c[i] : 0.0));
    const double low = least_sigma(p.sigma, p.length);  // rounding can make it <= 0
    kappa = std::max(kappa, low > 0 ? top / low : std::numeric_limits<double>::infinity());
  }
  return kappa;
}

Status pcurve_blend(const RingedJet& a, const RingedJet& b, const RingedBlendOptions& options,
                    Surface (&pieces)[2], int& count, double* bad_u) {
  PlanarLayout L;
  if (Status st = planar_layout(a, b, options, L); st != Status::ok) return st;
  PiecePolys pp[2];
  if (!(layout_condition(L, pp) <= kMaxPCurveCondition)) return Status::not_pythagorean;
  const Eigen::Matrix3d& M = L.M;
  const int m = L.m;
  // Data in the frame where v = e3 (38), (39).
  const Vec3d d0 = M * a.d, dd0 = M * a.dd, n0 = M * a.n, dn0 = M * a.dn;
  const Vec3d d1 = M * b.d, dd1 = M * b.dd, n1 = M * b.n, dn1 = M * b.dn;
  // (38): Ferguson cubics for d, n . v and rho.
  CurvePoly D[3], rho = ferguson(a.rho, a.drho, b.rho, b.drho);
  for (int j = 0; j < 3; ++j) D[j] = ferguson(d0[j], dd0[j], d1[j], dd1[j]);
  const CurvePoly n3 = ferguson(n0.z(), dn0.z(), n1.z(), dn1.z());
  const DirectrixBump& B = options.bump;
  const bool bumped = B.w != Vec3d::Zero();
  CurvePoly bump[2];
  if (bumped) bump_polys(B, bump[0], bump[1]);
  const Vec3d Mw = M * B.w;
  const double knots[3] = {0.0, L.split, 1.0};
  Surface out[2];
  for (int k = 0; k < m; ++k) {
    // The coefficients (47) of the P-biarc grow like 1/tau in the piece
    // [0, tau] and like 1/(1 - tau) in [tau, 1], where they multiply t^2
    // and (1 - t)^2: each piece is well conditioned in powers of the
    // distance from its outer end. So the second piece is built in r = 1 - t
    // (its Bernstein control points reversed) and handed over as a
    // Bernstein curve in r on [1, 0] (h = -1); in powers of t it missed its
    // end's d by 14 at tau = 1 - 2e-16 (fuzz_ringed regress-tau-near-one).
    const double t0 = knots[k], t1 = knots[k + 1];
    const bool mirrored = k == 1;
    CurvePoly Dl[3], n3l = mirrored ? shifted(n3, 1, -1) : n3,
                     rhol = mirrored ? shifted(rho, 1, -1) : rho;
    for (int j = 0; j < 3; ++j) {
      // (50): d* = d + w b, in the frame of v.
      const CurvePoly Dj = bumped ? D[j] + bump[k].scaled(Mw[j]) : D[j];
      Dl[j] = mirrored ? shifted(Dj, 1, -1) : Dj;
    }
    // n = (x1, x2, n3); f = n x e3 / sigma = (x2, -x1, 0) / sigma (15);
    // c = d + rho f (4); everything rotated back to world coordinates.
    const CurvePoly &x1 = pp[k].x1, &x2 = pp[k].x2, &sigma = pp[k].sigma;
    const CurvePoly nl[3] = {x1, x2, n3l};
    RationalField f;
    const CurvePoly fl[3] = {x2, -x1, CurvePoly()};
    CurvePoly Dw[3], Nw[3];
    rotate_back(M, Dl, Dw);
    rotate_back(M, nl, Nw);
    rotate_back(M, fl, f.F);
    f.w = sigma;
    RationalCurve dc, nc, cc;
    if (Status st = polynomial_curve(Dw, dc); st != Status::ok) return st;
    if (Status st = polynomial_curve(Nw, nc); st != Status::ok) return st;
    if (Status st = ringed_curve(dc, rhol, CurvePoly(1.0), f, cc); st != Status::ok) return st;
    if (mirrored) {
      dc = bernstein_in_r(dc);
      nc = bernstein_in_r(nc);
      cc = bernstein_in_r(cc);
    }
    if (Status st = make_ringed(dc, nc, cc, nullptr, t0, t1, out[k], bad_u); st != Status::ok)
      return st;
  }
  for (int k = 0; k < m; ++k) pieces[k] = out[k];
  count = m;
  return Status::ok;
}

}  // namespace

Status ringed_pcurve_blend_condition(const RingedJet& a, const RingedJet& b,
                                     const RingedBlendOptions& options, double& kappa) {
  PlanarLayout L;
  if (Status st = planar_layout(a, b, options, L); st != Status::ok) return st;
  PiecePolys pp[2];
  kappa = layout_condition(L, pp);
  return Status::ok;
}

// (52) (sign per ERRATA.md) and (57).
void bump_polys(const DirectrixBump& bump, CurvePoly& left, CurvePoly& right) {
  const double tau = bump.tau;
  const CurvePoly t = CurvePoly::linear(0, 1), one_minus_t = CurvePoly::linear(1, -1);
  CurvePoly a, b;
  if (bump.kind == BumpKind::single) {
    // -(1 - t)^2 t^2 (t (2 - 4 tau) + tau (5 tau - 3)) / ((1 - tau)^3 tau^3).
    multiply(one_minus_t, one_minus_t, a);
    multiply(a, t, b);
    multiply(b, t, a);
    multiply(a, CurvePoly::linear(tau * (5 * tau - 3), 2 - 4 * tau), b);
    left = right = b.scaled(-1.0 / (std::pow(1 - tau, 3) * std::pow(tau, 3)));
    return;
  }
  // t^2 (3 tau - 2 t) / tau^3 and (t - 1)^2 (2 t - 3 tau + 1) / (1 - tau)^3.
  multiply(t, t, a);
  multiply(a, CurvePoly::linear(3 * tau, -2), b);
  left = b.scaled(1.0 / std::pow(tau, 3));
  multiply(one_minus_t, one_minus_t, a);
  multiply(a, CurvePoly::linear(1 - 3 * tau, 2), b);
  right = b.scaled(1.0 / std::pow(1 - tau, 3));
}

namespace {

// |d(u) - s| - rho(u) - r.
Status clearance_at(const Surface& S, const Vec3d& s, double r, double u, double& value) {
  RingedData R;
  if (Status st = S.ringed(u, R); st != Status::ok) return st;
  value = (R.c - s).norm() - std::sqrt(std::max(0.0, R.rho2)) - r;
  return Status::ok;
}

}  // namespace

// Eq. (54).
Status sphere_clearance(const Surface& S, const Vec3d& s, double r, double& clearance,
                        double* at_u) {
  if (!input_ok(s) || !input_ok(r)) return Status::not_finite;
  if (!(r >= 0)) return Status::invalid_argument;
  constexpr int kSamples = 257;
  double best = HUGE_VAL, best_u = S.u0;
  int best_k = 0;
  for (int k = 0; k < kSamples; ++k) {
    const double u = S.u0 + (S.u1 - S.u0) * k / (kSamples - 1);
    double v;
    if (Status st = clearance_at(S, s, r, u, v); st != Status::ok) return st;
    if (v < best) best = v, best_u = u, best_k = k;
  }
  // Golden section on the bracket around the best sample.
  double lo = S.u0 + (S.u1 - S.u0) * std::max(0, best_k - 1) / (kSamples - 1);
  double hi = S.u0 + (S.u1 - S.u0) * std::min(kSamples - 1, best_k + 1) / (kSamples - 1);
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1, f2;
  if (Status st = clearance_at(S, s, r, x1, f1); st != Status::ok) return st;
  if (Status st = clearance_at(S, s, r, x2, f2); st != Status::ok) return st;
  while (hi - lo > 1e-12 * (1 + std::abs(lo))) {
    if (f1 < f2) {
      hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo);
      if (Status st = clearance_at(S, s, r, x1, f1); st != Status::ok) return st;
    } else {
      lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo);
      if (Status st = clearance_at(S, s, r, x2, f2); st != Status::ok) return st;
    }
  }
  if (std::min(f1, f2) < best) best = std::min(f1, f2), best_u = f1 < f2 ? x1 : x2;
  if (!std::isfinite(best)) return Status::numerical_overflow;
  clearance = best;
  if (at_u) *at_u = best_u;
  return Status::ok;
}

// Eq. (58).
Status normal_deviance(const Surface& S, double& value) {
  constexpr int kIntervals = 1024;  // even
  const double h = (S.u1 - S.u0) / kIntervals;
  double sum = 0;
  for (int k = 0; k <= kIntervals; ++k) {
    RingedData R;
    if (Status st = S.ringed(S.u0 + h * k, R); st != Status::ok) return st;
    const double dd = R.dc.squaredNorm(), nn = R.n.squaredNorm();
    if (!(dd > 0) || !(nn > 0)) return Status::singular_point;
    const double cos2 = R.dc.dot(R.n) * R.dc.dot(R.n) / (dd * nn);
    const double w = (k == 0 || k == kIntervals) ? 1 : (k % 2 ? 4 : 2);
    sum += w * std::max(0.0, 1 - cos2);
  }
  value = sum * h / 3;
  if (!std::isfinite(value)) return Status::numerical_overflow;
  return Status::ok;
}

}  // namespace v0
}  // namespace cyclide
