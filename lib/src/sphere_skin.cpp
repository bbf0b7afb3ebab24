// Seed 002: sphere skins by rotation-minimizing transport (sphere_skin.hpp,
// SPEC.md §9).
#include "cyclide/sphere_skin.hpp"

#include <algorithm>
#include <cmath>

#include "cyclide/curve.hpp"
#include "cyclide/quadrature.hpp"

namespace cyclide {
inline namespace v0 {

namespace {

constexpr double kParallelTol = 1e-9;  // relative: apex off the axis, e parallel to t

bool finite_end(const SkinEnd& e) {
  return input_ok(e.center) && input_ok(e.radius) && input_ok(e.tangent) && input_ok(e.inv_c);
}

}  // namespace

Status skin_end_from_apex(const Vec3d& center, double radius, const Vec3d& tangent,
                          const Vec3d& apex, SkinEnd& out) {
  if (!input_ok(center) || !input_ok(radius) || !input_ok(tangent) || !input_ok(apex))
    return Status::not_finite;
  if (!(radius > 0)) return Status::invalid_argument;
  const double tt = tangent.squaredNorm();
  if (!(tt > 0)) return Status::zero_tangent;
  const Vec3d d = apex - center;  // = c t
  if (!(d.norm() > 0) || d.cross(tangent).norm() > kParallelTol * d.norm() * std::sqrt(tt))
    return Status::invalid_argument;
  SkinEnd e;
  e.center = center;
  e.radius = radius;
  e.tangent = tangent;
  e.inv_c = tt / d.dot(tangent);
  out = e;
  return Status::ok;
}

Status skin_end_from_sphere(const Vec3d& sphere_center, double sphere_radius,
                            const Vec3d& center, const Vec3d& tangent, SkinEnd& out) {
  if (!input_ok(sphere_center) || !input_ok(sphere_radius) || !input_ok(center) ||
      !input_ok(tangent))
    return Status::not_finite;
  if (!(sphere_radius > 0)) return Status::invalid_argument;
  const double len = tangent.norm();
  if (!(len > 0)) return Status::zero_tangent;
  const Vec3d u = tangent / len;
  const Vec3d mp = sphere_center - center;  // = h u
  if (mp.cross(u).norm() > kParallelTol * std::max(mp.norm(), sphere_radius))
    return Status::invalid_argument;
  const double h = mp.dot(u);
  const double r2 = sphere_radius * sphere_radius - h * h;
  if (!(r2 > 0)) return Status::invalid_argument;  // the plane misses the sphere
  SkinEnd e;
  e.center = center;
  e.radius = std::sqrt(r2);
  e.tangent = tangent;
  // The apex x = p + c' u with (x - q).(q - m) = 0: c' = -r^2 / h; c = c'/|t|.
  e.inv_c = -h * len / r2;
  out = e;
  return Status::ok;
}

void skin_end_sphere(const SkinEnd& e, Vec3d& center, double& radius) {
  const double len = e.tangent.norm();
  const double h = len > 0 ? -e.radius * e.radius * e.inv_c / len : 0.0;
  center = len > 0 ? Vec3d(e.center + (h / len) * e.tangent) : e.center;
  radius = std::sqrt(e.radius * e.radius + h * h);
}

SkinSpine make_skin_spine(const SkinEnd& start, const SkinEnd& end) {
  // Cubic Hermite alpha(0) = p_i, alpha(1) = p_f, alpha' = t_i, t_f.
  const Vec3d &p0 = start.center, &p1 = end.center, &t0 = start.tangent, &t1 = end.tangent;
  SkinSpine a;
  a.c[0] = p0;
  a.c[1] = t0;
  a.c[2] = 3.0 * (p1 - p0) - 2.0 * t0 - t1;
  a.c[3] = 2.0 * (p0 - p1) + t0 + t1;
  return a;
}

double skin_spine_curvature(const SkinSpine& a, double t) {
  const Vec3d d1 = a.d1(t), d2 = a.d2(t);
  const double n = d1.norm();
  return d1.cross(d2).norm() / (n * n * n);
}

namespace {

// The RMF equation W' = -(W . alpha''/|alpha'|^2) alpha' (seed 002 §4 with
// ERRATA: w1' = |alpha'| mu t).
Vec3d rmf_rate(const SkinSpine& a, double t, const Vec3d& w) {
  const Vec3d d1 = a.d1(t), d2 = a.d2(t);
  return (-w.dot(d2) / d1.squaredNorm()) * d1;
}

// W'' by differentiating the equation: with g = (W . alpha'')/|alpha'|^2,
// W' = -g alpha', W'' = -g' alpha' - g alpha'', g' = (W'.alpha'' +
// W.alpha''')/|alpha'|^2 - 2 g (alpha'.alpha'')/|alpha'|^2.
Vec3d rmf_second(const SkinSpine& a, double t, const Vec3d& w) {
  const Vec3d d1 = a.d1(t), d2 = a.d2(t), d3 = a.d3();
  const double n2 = d1.squaredNorm();
  const double g = w.dot(d2) / n2;
  const Vec3d dw = -g * d1;
  const double dg = (dw.dot(d2) + w.dot(d3)) / n2 - 2.0 * g * d1.dot(d2) / n2;
  return -dg * d1 - g * d2;
}

// One table of W1 with m steps per interval. False if a step degenerates.
bool rk4_table(const SkinSpine& a, const Vec3d& w0, int m, Vec3d* w) {
  const int n = kRmfIntervals * m;
  const double h = 1.0 / n;
  Vec3d y = w0;
  w[0] = y;
  for (int i = 0; i < n; ++i) {
    const double t = double(i) / n;
    const Vec3d k1 = rmf_rate(a, t, y);
    const Vec3d k2 = rmf_rate(a, t + 0.5 * h, y + 0.5 * h * k1);
    const Vec3d k3 = rmf_rate(a, t + 0.5 * h, y + 0.5 * h * k2);
    const Vec3d k4 = rmf_rate(a, t + h, y + h * k3);
    y += (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    if ((i + 1) % m == 0) w[(i + 1) / m] = y;
  }
  return input_ok(y);
}

// Double reflection (Wang, Juttler, Zheng, Liu 2008, Algorithm 1): reflect
// the frame in the bisector plane of x_k x_{k+1}, then in the plane that
// takes the reflected tangent to t_{k+1}.
bool reflection_table(const SkinSpine& a, const Vec3d& w0, int m, Vec3d* w) {
  const int n = kRmfIntervals * m;
  Vec3d r = w0, x = a.point(0.0), t = a.d1(0.0).normalized();
  w[0] = r;
  for (int i = 0; i < n; ++i) {
    const double s = double(i + 1) / n;
    const Vec3d x1 = a.point(s), t1 = a.d1(s).normalized();
    const Vec3d v1 = x1 - x;
    const double c1 = v1.squaredNorm();
    if (!(c1 > 0)) return false;
    const Vec3d rL = r - (2.0 / c1) * v1.dot(r) * v1;
    const Vec3d tL = t - (2.0 / c1) * v1.dot(t) * v1;
    const Vec3d v2 = t1 - tL;
    const double c2 = v2.squaredNorm();
    r = c2 > 0 ? Vec3d(rL - (2.0 / c2) * v2.dot(rL) * v2) : rL;
    x = x1;
    t = t1;
    if ((i + 1) % m == 0) w[(i + 1) / m] = r;
  }
  return input_ok(r);
}

// |alpha'| stays away from 0 on [0, 1]: the minimum over the table nodes,
// refined by golden sections around the smallest, against 1e-8 of the
// largest.
bool spine_regular(const SkinSpine& a) {
  int k = 0;
  double lo = HUGE_VAL, hi = 0;
  for (int i = 0; i <= kRmfIntervals; ++i) {
    const double n = a.d1(double(i) / kRmfIntervals).squaredNorm();
    if (n < lo) lo = n, k = i;
    hi = std::max(hi, n);
  }
  double l = double(std::max(k - 1, 0)) / kRmfIntervals;
  double r = double(std::min(k + 1, kRmfIntervals)) / kRmfIntervals;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 60; ++it) {
    const double m1 = r - g * (r - l), m2 = l + g * (r - l);
    if (a.d1(m1).squaredNorm() < a.d1(m2).squaredNorm()) r = m2;
    else l = m1;
  }
  lo = std::min(lo, a.d1(0.5 * (l + r)).squaredNorm());
  return std::isfinite(hi) && lo > 1e-16 * hi && hi > 0;
}

Vec3d orthonormal_to(const Vec3d& w, const Vec3d& d1) {
  const Vec3d u = d1.normalized();
  return (w - w.dot(u) * u).normalized();
}

}  // namespace

Status transport_rmf(const SkinSpine& spine, const Vec3d& w0, RmfMethod method,
                     double tolerance, RmfTable& out) {
  for (const Vec3d& c : spine.c)
    if (!input_ok(c)) return Status::not_finite;
  if (!input_ok(w0) || !std::isfinite(tolerance)) return Status::not_finite;
  if (!(tolerance > 0)) return Status::invalid_argument;
  if (method != RmfMethod::reference && method != RmfMethod::double_reflection)
    return Status::invalid_argument;
  if (!spine_regular(spine)) return Status::zero_tangent;
  const Vec3d d0 = spine.d1(0.0);
  const Vec3d start = w0 - w0.dot(d0.normalized()) * d0.normalized();
  if (!(start.norm() > kParallelTol * w0.norm())) return Status::invalid_argument;
  const Vec3d u0 = start.normalized();
  // Step doubling: the tables with m and 2m steps per interval differ by
  // ~15 times the error of the finer one (both methods are of order 4).
  static_assert(kRmfMaxSubsteps >= 1, "");
  Vec3d coarse[kRmfIntervals + 1], fine[kRmfIntervals + 1];
  auto table = [&](int m, Vec3d* w) {
    return method == RmfMethod::reference ? rk4_table(spine, u0, m, w)
                                          : reflection_table(spine, u0, m, w);
  };
  if (!table(1, coarse)) return Status::numerical_overflow;
  for (int m = 2; m <= kRmfMaxSubsteps; m *= 2) {
    if (!table(m, fine)) return Status::numerical_overflow;
    double diff = 0;
    for (int k = 0; k <= kRmfIntervals; ++k) diff = std::max(diff, (fine[k] - coarse[k]).norm());
    const double estimate = diff / 15.0;
    if (estimate <= tolerance) {
      // The reference extrapolates (Richardson: order 5); double
      // reflection returns its finer table. Both are renormalized on the
      // normal planes.
      RmfTable& T = out;
      for (int k = 0; k <= kRmfIntervals; ++k) {
        const double t = double(k) / kRmfIntervals;
        const Vec3d w = method == RmfMethod::reference
                            ? Vec3d(fine[k] + (fine[k] - coarse[k]) / 15.0)
                            : fine[k];
        T.w[k] = orthonormal_to(w, spine.d1(t));
        T.dw[k] = rmf_rate(spine, t, T.w[k]);
        T.ddw[k] = rmf_second(spine, t, T.w[k]);
      }
      T.method = method;
      T.substeps = m;
      T.error_estimate = estimate;
      return Status::ok;
    }
    std::copy(fine, fine + kRmfIntervals + 1, coarse);
  }
  return Status::numerical_overflow;  // the tolerance is not met
}

void rmf_at(const SkinSpine& spine, const RmfTable& T, double t, Vec3d& w1, Vec3d* dw1) {
  const double pos = std::min(std::max(t, 0.0), 1.0) * kRmfIntervals;
  const int k = std::min(int(pos), kRmfIntervals - 1);
  const double s = pos - k, h = 1.0 / kRmfIntervals;
  // Quintic Hermite basis on [0, 1] (value, first and second derivative at
  // both ends).
  const double s2 = s * s, s3 = s2 * s, s4 = s3 * s, s5 = s4 * s;
  const double h0 = 1 - 10 * s3 + 15 * s4 - 6 * s5, h5 = 10 * s3 - 15 * s4 + 6 * s5;
  const double h1 = s - 6 * s3 + 8 * s4 - 3 * s5, h4 = -4 * s3 + 7 * s4 - 3 * s5;
  const double h2 = 0.5 * (s2 - 3 * s3 + 3 * s4 - s5), h3 = 0.5 * (s3 - 2 * s4 + s5);
  const Vec3d w = h0 * T.w[k] + h5 * T.w[k + 1] + (h * h1) * T.dw[k] + (h * h4) * T.dw[k + 1] +
                  (h * h * h2) * T.ddw[k] + (h * h * h3) * T.ddw[k + 1];
  w1 = orthonormal_to(w, spine.d1(t));
  if (dw1) *dw1 = rmf_rate(spine, t, w1);
}

namespace {

// The coordinate axis least aligned with both tangents.
Vec3d default_e(const Vec3d& t0, const Vec3d& t1) {
  const Vec3d u0 = t0.normalized(), u1 = t1.normalized();
  int best = 0;
  double score = HUGE_VAL;
  for (int i = 0; i < 3; ++i) {
    const double s = std::max(std::abs(u0[i]), std::abs(u1[i]));
    if (s < score) score = s, best = i;
  }
  return Vec3d::Unit(best);
}

// Kunkli-Hoffmann's start or end direction +- e x t / |e x t|, negative
// where the angle between t and p_f - p_i exceeds pi/2 (§2).
bool kh_direction(const Vec3d& e, const Vec3d& t, const Vec3d& chord, Vec3d& u) {
  const Vec3d c = e.cross(t);
  if (!(c.norm() > kParallelTol * e.norm() * t.norm())) return false;
  u = c.normalized();
  if (t.dot(chord) < 0) u = -u;
  return true;
}

// The pairing's start and end directions (end only for the baselines).
Status pairing_directions(const SkinEnd& s, const SkinEnd& f, const SkinOptions& o, Vec3d& u0,
                          Vec3d& u1) {
  const Vec3d chord = f.center - s.center;
  if (o.pairing == SkinPairing::cross_tangents) {
    const Vec3d c = s.tangent.cross(f.tangent);
    if (!(c.norm() > kParallelTol * s.tangent.norm() * f.tangent.norm()))
      return Status::parallel_lines;
    u0 = u1 = c.normalized();
    return Status::ok;
  }
  const Vec3d e = o.e.squaredNorm() > 0 ? o.e : default_e(s.tangent, f.tangent);
  if (!kh_direction(e, s.tangent, chord, u0) || !kh_direction(e, f.tangent, chord, u1))
    return Status::invalid_argument;
  return Status::ok;
}

// One end's validity and a(theta) coefficients (eqs. (9), (11); ERRATA:
// a c = 1 + mu r > 0 for every theta iff kappa r < 1).
Status end_scalars(const SkinSpine& a, const RmfTable& T, const SkinEnd& e, double t,
                   double& kappa, double (&coeff)[3]) {
  kappa = skin_spine_curvature(a, t);
  if (!std::isfinite(kappa)) return Status::numerical_overflow;
  if (!(kappa * e.radius < 1.0 - 1e-12)) return Status::curvature_radius_too_large;
  Vec3d w1;
  rmf_at(a, T, t, w1, nullptr);
  const Vec3d d1 = a.d1(t), d2 = a.d2(t), w2 = d1.normalized().cross(w1);
  const double k = e.inv_c * e.radius / d1.squaredNorm();
  coeff[0] = e.inv_c;
  coeff[1] = k * w1.dot(d2);
  coeff[2] = k * w2.dot(d2);
  return Status::ok;
}

Status check_ends(const SkinEnd& s, const SkinEnd& f, const SkinOptions& o) {
  if (!finite_end(s) || !finite_end(f) || !input_ok(o.reference) || !input_ok(o.e) ||
      !std::isfinite(o.tolerance))
    return Status::not_finite;
  if (!(s.radius > 0) || !(f.radius > 0) || !(o.tolerance > 0)) return Status::invalid_argument;
  if (o.pairing != SkinPairing::rmf && o.pairing != SkinPairing::kunkli_hoffmann &&
      o.pairing != SkinPairing::cross_tangents)
    return Status::invalid_argument;
  if (!(s.tangent.norm() > 0) || !(f.tangent.norm() > 0)) return Status::zero_tangent;
  // Nested (or equal) spheres: |m1 - m2| <= |R1 - R2|.
  Vec3d m[2];
  double R[2];
  skin_end_sphere(s, m[0], R[0]);
  skin_end_sphere(f, m[1], R[1]);
  if (!input_ok(m[0]) || !input_ok(m[1]) || !input_ok(R[0]) || !input_ok(R[1]))
    return Status::numerical_overflow;
  if ((m[0] - m[1]).norm() <= std::abs(R[0] - R[1]) + 1e-12 * std::max(R[0], R[1]))
    return Status::nested_spheres;
  return Status::ok;
}

Status build_skin(const SkinEnd& start, const SkinEnd& end, const Vec3d* w0,
                  const SkinOptions& o, SphereSkin& out) {
  if (Status st = check_ends(start, end, o); st != Status::ok) return st;
  if (w0 && !input_ok(*w0)) return Status::not_finite;
  Vec3d u0, u1;
  const bool baseline = o.pairing != SkinPairing::rmf;
  if (baseline || (!w0 && o.reference.squaredNorm() == 0)) {
    SkinOptions kh = o;
    if (!baseline) kh.pairing = SkinPairing::kunkli_hoffmann;
    if (Status st = pairing_directions(start, end, kh, u0, u1); st != Status::ok) return st;
  }
  if (w0) u0 = *w0;
  else if (!baseline && o.reference.squaredNorm() > 0) u0 = o.reference;
  SphereSkin S;
  S.ends[0] = start;
  S.ends[1] = end;
  S.spine = make_skin_spine(start, end);
  // Valid ends (<= 1e100) can give a spine beyond the input range (3 (p_f -
  // p_i) - 2 t_i - t_f): an overflow, not a non-finite input (which
  // transport_rmf would report for its own argument).
  for (const Vec3d& c : S.spine.c)
    if (!input_ok(c)) return Status::numerical_overflow;
  S.pairing = o.pairing;
  if (Status st = transport_rmf(S.spine, u0, o.method, o.tolerance, S.rmf); st != Status::ok)
    return st;
  if (baseline) {
    // Delta: the angle about t_f from the transported start to u_f.
    Vec3d w1;
    rmf_at(S.spine, S.rmf, 1.0, w1, nullptr);
    const Vec3d tf = S.spine.d1(1.0).normalized();
    const Vec3d uf = orthonormal_to(u1, tf);
    S.delta = std::atan2(w1.cross(uf).dot(tf), w1.dot(uf));
  }
  for (int e = 0; e < 2; ++e)
    if (Status st = end_scalars(S.spine, S.rmf, S.ends[e], double(e), S.kappa[e], S.a_coeff[e]);
        st != Status::ok)
      return st;
  out = S;
  return Status::ok;
}

}  // namespace

Status make_sphere_skin(const SkinEnd& start, const SkinEnd& end, const SkinOptions& options,
                        SphereSkin& out) {
  return build_skin(start, end, nullptr, options, out);
}

Status make_sphere_skin_from(const SkinEnd& start, const SkinEnd& end, const Vec3d& w0,
                             const SkinOptions& options, SphereSkin& out) {
  return build_skin(start, end, &w0, options, out);
}

namespace {

// Everything at one t that does not depend on theta.
struct SkinColumn {
  Vec3d alpha, d1, W1, W2, dW1, dW2;
  double H[4], dH[4];  // cubic Hermite basis (p0, m0, p1, m1) and derivatives
  double turn, dturn;  // delta s(t), delta s'(t)
};

SkinColumn column(const SphereSkin& S, double t) {
  SkinColumn c;
  c.alpha = S.spine.point(t);
  c.d1 = S.spine.d1(t);
  const Vec3d d2 = S.spine.d2(t);
  const double len = c.d1.norm();
  const Vec3d u = c.d1 / len;
  const Vec3d du = (d2 - d2.dot(u) * u) / len;
  rmf_at(S.spine, S.rmf, t, c.W1, &c.dW1);
  c.W2 = u.cross(c.W1);
  c.dW2 = du.cross(c.W1) + u.cross(c.dW1);
  const double t2 = t * t, t3 = t2 * t;
  c.H[0] = 2 * t3 - 3 * t2 + 1;
  c.H[1] = t3 - 2 * t2 + t;
  c.H[2] = -2 * t3 + 3 * t2;
  c.H[3] = t3 - t2;
  c.dH[0] = 6 * t2 - 6 * t;
  c.dH[1] = 3 * t2 - 4 * t + 1;
  c.dH[2] = -6 * t2 + 6 * t;
  c.dH[3] = 3 * t2 - 2 * t;
  c.turn = S.delta * (3 * t2 - 2 * t3);
  c.dturn = S.delta * (6 * t - 6 * t2);
  return c;
}

// a(theta) of end e and its theta-derivative.
void end_a(const SphereSkin& S, int e, double theta, double& a, double& da) {
  const double phi = theta + (e ? S.delta : 0.0);
  const double* k = S.a_coeff[e];
  const double c = std::cos(phi), s = std::sin(phi);
  a = k[0] - (c * k[1] + s * k[2]);
  da = s * k[1] - c * k[2];
}

struct SkinPoint {
  Vec3d x, xt, xth;
};

SkinPoint point(const SphereSkin& S, const SkinColumn& c, double theta) {
  const double ri = S.ends[0].radius, rf = S.ends[1].radius;
  double ai, dai, af, daf;
  end_a(S, 0, theta, ai, dai);
  end_a(S, 1, theta, af, daf);
  // lambda: the cubic Hermite (6), (7), (8), (10).
  const double lam = c.H[0] * ri - c.H[1] * ai * ri + c.H[2] * rf - c.H[3] * af * rf;
  const double lam_t = c.dH[0] * ri - c.dH[1] * ai * ri + c.dH[2] * rf - c.dH[3] * af * rf;
  const double lam_th = -c.H[1] * dai * ri - c.H[3] * daf * rf;
  const double phi = theta + c.turn, cp = std::cos(phi), sp = std::sin(phi);
  const Vec3d w = cp * c.W1 + sp * c.W2;
  const Vec3d w_th = -sp * c.W1 + cp * c.W2;
  const Vec3d w_t = cp * c.dW1 + sp * c.dW2 + c.dturn * w_th;
  SkinPoint p;
  p.x = c.alpha + lam * w;
  p.xt = c.d1 + lam_t * w + lam * w_t;
  p.xth = lam_th * w + lam * w_th;
  return p;
}

bool unit_normal(const SkinPoint& p, Vec3d& n) {
  const Vec3d m = p.xth.cross(p.xt);
  const double len = m.norm();
  if (!(len > 1e-14 * p.xth.norm() * p.xt.norm()) || !std::isfinite(len)) return false;
  n = m / len;
  return true;
}

void put(const Vec3d& v, double* out) {
  out[0] = v.x();
  out[1] = v.y();
  out[2] = v.z();
}

}  // namespace

double skin_lambda(const SphereSkin& S, double theta, double t, double* a) {
  const SkinColumn c = column(S, t);
  double ai, dai, af, daf;
  end_a(S, 0, theta, ai, dai);
  end_a(S, 1, theta, af, daf);
  if (a) a[0] = ai, a[1] = af;
  const double ri = S.ends[0].radius, rf = S.ends[1].radius;
  return c.H[0] * ri - c.H[1] * ai * ri + c.H[2] * rf - c.H[3] * af * rf;
}

Status skin_eval(const SphereSkin& S, double theta, double t, double* x, double* x_theta,
                 double* x_t, double* normal) {
  if (!std::isfinite(theta) || !std::isfinite(t)) return Status::not_finite;
  if (!(t >= 0.0 && t <= 1.0)) return Status::bad_domain;
  const SkinPoint p = point(S, column(S, t), theta);
  Vec3d n;
  if (normal && !unit_normal(p, n)) return Status::singular_point;
  if (!input_ok(p.x) || !input_ok(p.xt) || !input_ok(p.xth)) return Status::numerical_overflow;
  if (x) put(p.x, x);
  if (x_theta) put(p.xth, x_theta);
  if (x_t) put(p.xt, x_t);
  if (normal) put(n, normal);
  return Status::ok;
}

Status skin_eval_grid(const SphereSkin& S, const double* theta, int ntheta, const double* t,
                      int nt, double* x, double* normal, int* bad) {
  if (!theta || !t) return Status::null_argument;
  if (ntheta < 0 || nt < 0) return Status::invalid_argument;
  for (int i = 0; i < ntheta; ++i)
    if (!std::isfinite(theta[i])) return Status::not_finite;
  for (int j = 0; j < nt; ++j) {
    if (!std::isfinite(t[j])) return Status::not_finite;
    if (!(t[j] >= 0.0 && t[j] <= 1.0)) return Status::bad_domain;
  }
  // Two passes keep the outputs all-or-nothing: every point is checked
  // first as skin_eval checks it (a singular point where normals are asked
  // for, then values beyond the range: a grid fails where skin_eval fails).
  for (int pass = 0; pass < 2; ++pass)
    for (int j = 0; j < nt; ++j) {
      const SkinColumn c = column(S, t[j]);
      for (int i = 0; i < ntheta; ++i) {
        const SkinPoint p = point(S, c, theta[i]);
        const size_t k = size_t(j) * size_t(ntheta) + size_t(i);
        Vec3d n;
        if (normal && !unit_normal(p, n)) {
          if (bad) *bad = int(k);
          return Status::singular_point;
        }
        if (pass == 0) {
          if (!input_ok(p.x) || !input_ok(p.xt) || !input_ok(p.xth)) {
            if (bad) *bad = int(k);
            return Status::numerical_overflow;
          }
          continue;
        }
        if (x) put(p.x, x + 3 * k);
        if (normal) put(n, normal + 3 * k);
      }
    }
  return Status::ok;
}

Status skin_twist(const SphereSkin& S, double theta, double& twist) {
  if (!std::isfinite(theta)) return Status::not_finite;
  constexpr int kPieces = 8, kNodes = 16;
  double z[kNodes], w[kNodes];
  gauss_legendre01(kNodes, z, w);
  double sum = 0;
  for (int p = 0; p < kPieces; ++p)
    for (int i = 0; i < kNodes; ++i) {
      const double t = (p + z[i]) / kPieces;
      const SkinColumn c = column(S, t);
      const SkinPoint q = point(S, c, theta);
      const Vec3d y = q.x - c.alpha, dy = q.xt - c.d1;
      const double yy = y.squaredNorm();
      if (!(yy > 0)) return Status::singular_point;  // the curve meets the spine
      sum += w[i] / kPieces * std::abs(y.cross(dy).dot(c.d1.normalized())) / yy;
    }
  if (!std::isfinite(sum)) return Status::numerical_overflow;
  twist = sum;
  return Status::ok;
}

Status make_sphere_skin_chain(const SkinEnd* ends, int n, const SkinOptions& options,
                              SphereSkin* patches, int* bad_patch) {
  if (!ends || !patches) return Status::null_argument;
  if (n < 2) return Status::invalid_argument;
  // Two passes (all-or-nothing without n skins on the stack): the first
  // validates every patch in one scratch skin, the second writes them.
  SphereSkin scratch;
  for (int pass = 0; pass < 2; ++pass) {
    Vec3d w0 = Vec3d::Zero();
    for (int k = 0; k + 1 < n; ++k) {
      SphereSkin& S = pass == 0 ? scratch : patches[k];
      const Status st = k == 0 ? make_sphere_skin(ends[0], ends[1], options, S)
                               : make_sphere_skin_from(ends[k], ends[k + 1], w0, options, S);
      if (st != Status::ok) {
        if (pass == 1) return Status::internal_error;  // the first pass built the same
        if (bad_patch) *bad_patch = k;
        return st;
      }
      // The next start: this patch's direction at t = 1 for theta = 0.
      Vec3d w1;
      rmf_at(S.spine, S.rmf, 1.0, w1, nullptr);
      const Vec3d w2 = S.spine.d1(1.0).normalized().cross(w1);
      w0 = std::cos(S.delta) * w1 + std::sin(S.delta) * w2;
    }
  }
  return Status::ok;
}

}  // namespace v0
}  // namespace cyclide
