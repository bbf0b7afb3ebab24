// Rational unit fields f perpendicular to a general orientation function n
// (seed 001 §3): the projection directions of Example 3.3 for quadratic n
// and the stereographic construction (20)-(23) with a numerical sum of
// squares for any n. See pcurve.hpp for the statements.
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "cyclide/pcurve.hpp"
#include "poly_roots.hpp"
#include "power_form.hpp"

namespace cyclide {
inline namespace v0 {

namespace {

constexpr int kMaxSosDegree = kMaxCurveDegree - 1;  // even bound on deg |N|^2 (14)
using CPoly = Complex[kMaxCurveDegree + 1];

using detail::finite;
using detail::max_abs;
using detail::square_norm;

// The numerator N of n in power form, trimmed; false for a point or line
// element.
bool numerator(const RationalCurve& n, CurvePoly (&N)[3], CurvePoly& w) {
  if (n.kind != CurveKind::rational) return false;
  detail::power_form(n, N, w);
  return true;
}

// g = sqrt(lead) prod (t - z_k) over the m roots of |N|^2 = q (degree 2m)
// with the largest imaginary parts, as complex coefficients; the relative
// remainder of |g|^2 - q. False if the roots cannot be computed.
bool sum_of_squares(const CurvePoly& q, CPoly& g, int& m, double& residual) {
  m = q.deg / 2;
  for (Complex& z : g) z = 0;
  g[0] = std::sqrt(q.c[q.deg]);
  if (m > 0) {
    Complex z[kMaxSosDegree];
    if (detail::poly_roots(q, z) != q.deg) return false;
    // Largest imaginary parts first (insertion sort: at most 14 roots).
    for (int i = 1; i < q.deg; ++i)
      for (int j = i; j > 0 && z[j].imag() > z[j - 1].imag(); --j) std::swap(z[j], z[j - 1]);
    for (int k = 0; k < m; ++k)  // g <- g (t - z_k)
      for (int i = k + 1; i >= 0; --i) g[i] = (i > 0 ? g[i - 1] : Complex(0)) - z[k] * g[i];
  }
  double worst = 0;
  for (int e = 0; e <= q.deg; ++e) {
    double s = q.c[e];
    for (int i = 0; i <= m; ++i)
      if (e - i >= 0 && e - i <= m) s -= (g[i] * std::conj(g[e - i])).real();
    worst = std::max(worst, std::abs(s));
  }
  residual = worst / max_abs(q);
  return std::isfinite(residual);
}

Complex ceval(const CPoly& g, int m, double t) {
  Complex s = g[m];
  for (int k = m - 1; k >= 0; --k) s = s * t + g[k];
  return s;
}

}  // namespace

// Example 3.3.
Status quadratic_projection_directions(const RationalCurve& n, Vec3d (&v)[2], int& count) {
  CurvePoly N[3], w;
  if (!numerator(n, N, w)) return Status::invalid_argument;
  for (const CurvePoly& p : N)
    if (!finite(p)) return Status::not_finite;
  if (w.deg != 0 || !(w.c[0] != 0)) return Status::invalid_argument;
  Vec3d a, b, c;
  for (int j = 0; j < 3; ++j) {
    if (N[j].deg > 2) return Status::invalid_argument;
    c[j] = N[j].c[0];
    b[j] = N[j].c[1];
    a[j] = N[j].c[2];
  }
  const double scale = std::max({a.norm(), b.norm(), c.norm()});
  if (!(scale > 0)) return Status::invalid_argument;  // n = 0
  a /= scale, b /= scale, c /= scale;
  // The discriminant form of the projected complex quadratic.
  const Eigen::Matrix3d M = b * b.transpose() - 2 * (a * c.transpose() + c * a.transpose());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(M);  // ascending eigenvalues
  const Eigen::Vector3d l = es.eigenvalues();
  const Vec3d q1 = es.eigenvectors().col(2), q3 = es.eigenvectors().col(0);
  const double s1 = std::sqrt(std::max(0.0, l(1) - l(0))), s3 = std::sqrt(std::max(0.0, l(2) - l(1)));
  Vec3d cand[3];
  int m = 0;
  if (s1 + s3 > 1e-12) {
    cand[m++] = (s1 * q3 - s3 * q1).normalized();
    cand[m++] = (s1 * q3 + s3 * q1).normalized();
  } else {
    // M = 0 (n constant): every direction not parallel to n works.
    const Vec3d n0 = (c.norm() > 0 ? c : b.norm() > 0 ? b : a).normalized();
    const Vec3d e = std::abs(n0.x()) < 0.9 ? Vec3d::UnitX() : Vec3d::UnitY();
    cand[m++] = (e - e.dot(n0) * n0).normalized();
  }
  // Coefficients in a plane with normal m (n(t) in that plane for all t):
  // for v in the plane the projection is the line through the origin
  // along e = m x v, p(t) = n(t).e, |p| a polynomial (the discriminant
  // test above misses this family, and may give v = m, killing p).
  const Vec3d big = a.norm() >= b.norm() && a.norm() >= c.norm() ? a : b.norm() >= c.norm() ? b : c;
  Vec3d mn = a.cross(b);
  for (const Vec3d& x : {b.cross(c), c.cross(a)})
    if (x.norm() > mn.norm()) mn = x;
  if (!(mn.norm() > 1e-12)) {  // rank 1: any plane containing big
    const Vec3d e = std::abs(big.normalized().x()) < 0.9 ? Vec3d::UnitX() : Vec3d::UnitY();
    mn = big.cross(e);
  }
  const Vec3d mh = mn.normalized();
  if (std::abs(mh.dot(a)) + std::abs(mh.dot(b)) + std::abs(mh.dot(c)) <= 1e-12)
    cand[m++] = mn.cross(big).normalized();
  Vec3d found[2];
  int k = 0;
  for (int i = 0; i < m && k < 2; ++i) {
    RationalField f;
    if (projection_field(n, cand[i], f) != Status::ok) continue;
    if (k == 1 && std::abs(std::abs(found[0].dot(cand[i])) - 1) < 1e-12) continue;  // same plane
    found[k++] = cand[i];
  }
  if (k == 0) return Status::not_pythagorean;
  for (int i = 0; i < k; ++i) v[i] = found[i];
  count = k;
  return Status::ok;
}

// Eqs. (20)-(23).
Status sos_field(const RationalCurve& n, RationalField& out, SosFieldReport* report) {
  CurvePoly N[3], w;
  if (!numerator(n, N, w)) return Status::invalid_argument;
  int deg = 0;
  for (const CurvePoly& p : N) {
    if (!finite(p)) return Status::not_finite;
    deg = std::max(deg, p.deg);
  }
  if (2 * deg > kMaxSosDegree) return Status::degree_too_high;
  // Scale N (f does not depend on it) so its largest coefficient is 1.
  const double s = std::max({max_abs(N[0]), max_abs(N[1]), max_abs(N[2])});
  if (!(s > 0)) return Status::invalid_argument;
  for (CurvePoly& p : N) p = p.scaled(1.0 / s);
  CurvePoly q = square_norm(N);
  q.trim_relative(1e-15);
  if (q.deg % 2 != 0) return Status::not_pythagorean;  // cannot happen for |N|^2 > 0
  CPoly g;
  int m = 0;
  SosFieldReport rep;
  if (!sum_of_squares(q, g, m, rep.residual)) return Status::not_pythagorean;
  if (!(rep.residual <= 1e-8)) return Status::not_pythagorean;
  // Choose the pole axis and rotation: at a real root t of n3 the
  // denominator is |e^{i theta} g(t) - (n1 + i n2)(t)|^2; keep it largest
  // relative to |N(t)|^2 (between such roots it is >= n3^2 > 0).
  double best = -1, best_theta = 0;
  int best_axis = 2;
  for (int axis : {2, 0, 1}) {
    const CurvePoly& n3 = N[axis];
    const CurvePoly& n1 = N[(axis + 1) % 3];
    const CurvePoly& n2 = N[(axis + 2) % 3];
    if (max_abs(n3) == 0) continue;  // the pole lies on every circle
    double roots[kMaxCurveDegree];
    const int r = detail::nearly_real_roots(n3, roots);  // n3 is tiny near them too
    if (r < 0) continue;
    for (int k = 0; k < 16; ++k) {
      const double theta = k * (3.141592653589793 / 8);
      const Complex e = std::polar(1.0, theta);
      double worst = 4;
      for (int i = 0; i < r; ++i) {
        const double t = roots[i];
        const Complex p(n1(t), n2(t));
        const double nn = std::norm(p) + n3(t) * n3(t);
        if (!(nn > 0)) {
          worst = 0;
          break;
        }
        worst = std::min(worst, (std::norm(e * ceval(g, m, t) - p) + n3(t) * n3(t)) / nn);
      }
      if (worst > best + 1e-12) best = worst, best_theta = theta, best_axis = axis;
    }
    if (best >= 1) break;  // good enough: no need for another pole
  }
  if (!(best > 1e-8)) return Status::not_pythagorean;
  rep.margin = best;
  rep.pole_axis = best_axis;
  rep.theta = best_theta;
  // H = e^{i theta} g - (n1, n2); f = (2 H1 n3, 2 H2 n3, |H|^2 - n3^2) / (|H|^2 + n3^2).
  const int ax = best_axis, i1 = (ax + 1) % 3, i2 = (ax + 2) % 3;
  const Complex e = std::polar(1.0, best_theta);
  CurvePoly H1, H2;
  H1.deg = H2.deg = std::max(m, std::max(N[i1].deg, N[i2].deg));
  for (int k = 0; k <= m; ++k) {
    const Complex c = e * g[k];
    H1.c[k] = c.real();
    H2.c[k] = c.imag();
  }
  H1 = H1 - N[i1];
  H2 = H2 - N[i2];
  CurvePoly H1s, H2s, n3s, a, b;
  multiply(H1, H1, H1s);
  multiply(H2, H2, H2s);
  multiply(N[ax], N[ax], n3s);
  multiply(H1, N[ax], a);
  multiply(H2, N[ax], b);
  RationalField f;
  f.F[i1] = a.scaled(2.0);
  f.F[i2] = b.scaled(2.0);
  f.F[ax] = H1s + H2s - n3s;
  f.w = H1s + H2s + n3s;
  for (CurvePoly& p : f.F) p.trim();
  f.w.trim();
  out = f;
  if (report) *report = rep;
  return Status::ok;
}

namespace {

// The degree of n's numerator (power form), -1 for a point/line element.
int numerator_degree(const RationalCurve& n) {
  CurvePoly N[3], w;
  if (!numerator(n, N, w)) return -1;
  return std::max({N[0].deg, N[1].deg, N[2].deg});
}

Status field_by_projection(const RationalCurve& n, const Vec3d& v, RationalField& f,
                           RingedFieldReport& rep) {
  if (!input_ok(v)) return Status::not_finite;
  const double vmax = v.cwiseAbs().maxCoeff();  // scaled first: |v| of tiny v underflows
  if (!(vmax > 0)) return Status::invalid_argument;
  rep.method = RingedFieldMethod::projection;
  rep.v = (v / vmax).normalized();
  return projection_field(n, rep.v, f);
}

Status field_by_quadratic(const RationalCurve& n, int which, RationalField& f,
                          RingedFieldReport& rep) {
  if (which != 0 && which != 1) return Status::invalid_argument;
  Vec3d v[2];
  int count = 0;
  if (Status st = quadratic_projection_directions(n, v, count); st != Status::ok) return st;
  if (which >= count) return Status::invalid_argument;
  rep.method = RingedFieldMethod::quadratic;
  rep.directions = count;
  rep.v = v[which];
  return projection_field(n, rep.v, f);
}

// The routes of RingedFieldMethod::automatic, in order (k = 0..5):
// projection along e3, e1, e2 (Prop. 3.2); Example 3.3's directions 0 and
// 1 (only for deg n <= 2); SOS (20)-(23). False if route k does not apply.
constexpr int kAutomaticRoutes = 6;
bool automatic_route(int k, int deg, RingedFieldOptions& o) {
  o = RingedFieldOptions();
  if (k <= 2) {
    o.method = RingedFieldMethod::projection;
    o.v = k == 0 ? Vec3d::UnitZ() : k == 1 ? Vec3d::UnitX() : Vec3d::UnitY();
    return true;
  }
  if (k <= 4) {
    o.method = RingedFieldMethod::quadratic;
    o.which = k - 3;
    return deg <= 2;
  }
  o.method = RingedFieldMethod::sos;
  return true;
}

}  // namespace

Status ringed_field(const RationalCurve& n, const RingedFieldOptions& options, RationalField& f,
                    RingedFieldReport* report) {
  RingedFieldReport rep;
  RationalField out;
  Status st = Status::invalid_argument;
  switch (options.method) {
    case RingedFieldMethod::projection:
      st = field_by_projection(n, options.v, out, rep);
      break;
    case RingedFieldMethod::quadratic:
      st = field_by_quadratic(n, options.which, out, rep);
      break;
    case RingedFieldMethod::sos:
      rep.method = RingedFieldMethod::sos;
      st = sos_field(n, out, &rep.sos);
      break;
    case RingedFieldMethod::automatic: {
      // The first route that does not answer not_pythagorean.
      const int deg = numerator_degree(n);
      if (deg < 0) return Status::invalid_argument;
      st = Status::not_pythagorean;
      RingedFieldOptions o;
      for (int k = 0; k < kAutomaticRoutes && st == Status::not_pythagorean; ++k)
        if (automatic_route(k, deg, o)) st = ringed_field(n, o, out, &rep);
      break;
    }
    default:
      return Status::invalid_argument;
  }
  if (st != Status::ok) return st;
  f = out;
  if (report) *report = rep;
  return Status::ok;
}

namespace {

// The surface (3) through c = d + rho f for one field.
Status ringed_with_field(const RationalCurve& d, const RationalCurve& n, const CurvePoly& rho_num,
                         const CurvePoly& rho_den, const RationalField& f,
                         const Mobius* circle_f, double u0, double u1, Surface& out,
                         double* bad_u) {
  RationalCurve c;
  if (Status st = ringed_curve(d, rho_num, rho_den, f, c); st != Status::ok) return st;
  return make_ringed(d, n, c, circle_f, u0, u1, out, bad_u);
}

}  // namespace

Status make_ringed_dnr(const RationalCurve& d, const RationalCurve& n, const CurvePoly& rho_num,
                       const CurvePoly& rho_den, const RingedFieldOptions& options,
                       const Mobius* circle_f, double u0, double u1, Surface& out,
                       RingedFieldReport* report, double* bad_u) {
  Surface S;
  RingedFieldReport rep;
  RationalField f;
  if (options.method != RingedFieldMethod::automatic) {
    if (Status st = ringed_field(n, options, f, &rep); st != Status::ok) return st;
    if (Status st = ringed_with_field(d, n, rho_num, rho_den, f, circle_f, u0, u1, S, bad_u);
        st != Status::ok)
      return st;
  } else {
    // Automatic: the routes in ringed_field's order, each kept only if its
    // field is defined on the whole domain (a projection's sigma = |n x v|
    // may vanish inside [u0, u1], e.g. Example 6.2's R_3 along e3 at t =
    // 0); the first route's failure is reported if none works.
    RingedFieldOptions o;
    Status first = Status::ok;
    double first_bad = NAN;
    bool built = false;
    const int deg = numerator_degree(n);
    if (deg < 0) return Status::invalid_argument;
    for (int k = 0; k < kAutomaticRoutes && !built; ++k) {
      if (!automatic_route(k, deg, o)) continue;
      RingedFieldReport r;
      Status st = ringed_field(n, o, f, &r);
      double bad = NAN;
      if (st == Status::ok)
        st = ringed_with_field(d, n, rho_num, rho_den, f, circle_f, u0, u1, S, &bad);
      if (st == Status::ok) {
        rep = r;
        built = true;
      } else if (first == Status::ok && st != Status::not_pythagorean &&
                 !(st == Status::invalid_argument && o.method == RingedFieldMethod::quadratic)) {
        first = st;  // the first route whose field existed but failed
        first_bad = bad;
      }
    }
    if (!built) {
      if (bad_u) *bad_u = first_bad;
      return first == Status::ok ? Status::not_pythagorean : first;
    }
  }
  out = S;
  if (report) *report = rep;
  return Status::ok;
}

Status make_ringed_pcurve(const RationalCurve& d, const CurvePoly (&x)[4], double phi,
                          const CurvePoly& rho_num, const CurvePoly& rho_den,
                          const Mobius* circle_f, double u0, double u1, Surface& out,
                          double* bad_u) {
  if (!std::isfinite(phi)) return Status::not_finite;
  PCurveFrame P;
  if (Status st = pcurve_frame(x, P); st != Status::ok) return st;
  RationalCurve n, c;
  double nc[3 * (kMaxCurveDegree + 1)];
  int deg = 0;
  for (const CurvePoly& p : P.n) deg = std::max(deg, p.deg);
  for (int k = 0; k <= deg; ++k)
    for (int j = 0; j < 3; ++j) nc[3 * k + j] = P.n[j].c[k];
  if (Status st = make_polynomial_curve(deg, nc, n); st != Status::ok)
    return st == Status::not_finite ? Status::numerical_overflow : st;
  if (Status st = ringed_curve(d, rho_num, rho_den, pcurve_field(P, phi), c); st != Status::ok)
    return st;
  Surface S;
  if (Status st = make_ringed(d, n, c, circle_f, u0, u1, S, bad_u); st != Status::ok) return st;
  out = S;
  return Status::ok;
}

}  // namespace v0
}  // namespace cyclide
