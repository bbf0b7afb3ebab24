// Seed 002: sphere skins by rotation-minimizing transport (sphere_skin.hpp,
// SPEC.md §8g).
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

void skin_chord_tangents(SkinEnd& start, SkinEnd& end) {
  const double chord = (end.center - start.center).norm();
  if (!(chord > 0) || !std::isfinite(chord)) return;
  for (SkinEnd* e : {&start, &end}) {
    const double len = e->tangent.norm();
    if (!(len > 0) || !std::isfinite(len)) continue;
    const double k = chord / len;
    e->tangent *= k;
    e->inv_c *= k;
  }
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

// |alpha'| stays away from 0 on [0, 1]: |alpha'|^2 is a quartic, so it has
// at most two local minima; every local minimum of 33 samples is refined
// by golden sections on its bracket, against 1e-16 of the largest sample.
bool spine_regular(const SkinSpine& a) {
  constexpr int kSamples = 32;
  double n2[kSamples + 1], hi = 0;
  for (int i = 0; i <= kSamples; ++i) {
    n2[i] = a.d1(double(i) / kSamples).squaredNorm();
    hi = std::max(hi, n2[i]);
  }
  if (!std::isfinite(hi) || !(hi > 0)) return false;
  double lo = HUGE_VAL;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int k = 0; k <= kSamples; ++k) {
    lo = std::min(lo, n2[k]);
    if ((k > 0 && n2[k - 1] < n2[k]) || (k < kSamples && n2[k + 1] < n2[k])) continue;
    double l = double(std::max(k - 1, 0)) / kSamples, r = double(std::min(k + 1, kSamples)) / kSamples;
    for (int it = 0; it < 50; ++it) {
      const double m1 = r - g * (r - l), m2 = l + g * (r - l);
      if (a.d1(m1).squaredNorm() < a.d1(m2).squaredNorm()) r = m2;
      else l = m1;
    }
    lo = std::min(lo, a.d1(0.5 * (l + r)).squaredNorm());
  }
  return lo > 1e-16 * hi;
}

Vec3d orthonormal_to(const Vec3d& w, const Vec3d& d1) {
  const Vec3d u = d1.normalized();
  return (w - w.dot(u) * u).normalized();
}

}  // namespace

namespace {

// The reference frame of a piece and the RMF's angle rate against it:
// b the unit tangent, U = R(a -> b) u = u - k (a + b) with k = (b . u)/(1 +
// a . b) (u orthogonal to a), V = b x U, and omega = phi' = -U' . V (the
// RMF does not turn about b; the frame (b, U, V) turns at U' . V).
struct PieceFrame {
  Vec3d b, U, V;
  double omega;
};

PieceFrame piece_frame(const SkinSpine& s, const Vec3d& a, const Vec3d& u, double t) {
  const Vec3d d1 = s.d1(t), d2 = s.d2(t);
  const double len = d1.norm();
  PieceFrame F;
  F.b = d1 / len;
  const Vec3d db = (d2 - d2.dot(F.b) * F.b) / len;
  const double den = 1.0 + a.dot(F.b), bu = F.b.dot(u);
  const double k = bu / den;
  const double dk = (db.dot(u) * den - bu * a.dot(db)) / (den * den);
  F.U = u - k * (a + F.b);
  const Vec3d dU = -dk * (a + F.b) - k * db;
  F.V = F.b.cross(F.U);
  F.omega = -dU.dot(F.V);
  return F;
}

// Sum of c[m] T_m(x), m = 0..n (Clenshaw).
double chebyshev(const double* c, int n, double x) {
  double b1 = 0, b2 = 0;
  for (int m = n; m >= 1; --m) {
    const double b0 = c[m] + 2 * x * b1 - b2;
    b2 = b1;
    b1 = b0;
  }
  return c[0] + x * b1 - b2;
}

// The pieces: from each start node of 65, the last node whose unit
// tangent stays within ~45 degrees (b_s . b_e >= 0.7) of the start's.
int split_pieces(const SkinSpine& s, double (&bounds)[kRmfMaxPieces + 1]) {
  constexpr int kNodes = 64;
  Vec3d b[kNodes + 1];
  for (int k = 0; k <= kNodes; ++k) b[k] = s.d1(double(k) / kNodes).normalized();
  int n = 0, start = 0;
  bounds[0] = 0.0;
  while (start < kNodes) {
    int end = start + 1;
    while (end < kNodes && b[start].dot(b[end + 1]) >= 0.7) ++end;
    if (n == kRmfMaxPieces) return -1;
    bounds[++n] = double(end) / kNodes;
    start = end;
  }
  return n;
}

// cos(pi j / 64), j < 128: the DCT's cosines for every n | 64.
const double* cosines64() {
  struct Table {
    double c[128];
    Table() {
      for (int j = 0; j < 128; ++j) c[j] = std::cos(std::acos(-1.0) * j / 64);
    }
  };
  static const Table table;  // thread-safe initialization, no allocation
  return table.c;
}

// One reference piece from (a, u) at t0 to t1: the angle rate at the
// Chebyshev-Lobatto nodes x_k = cos(pi k / n), its coefficients (DCT-I),
// integrated exactly; n doubled from 8 (the nodes are nested) until the
// tail half (|c_{n-2}| + |c_{n-1}| + |c_n|) is <= tol.
bool reference_piece(const SkinSpine& s, RmfPiece& P, double tol, double& estimate) {
  const double mid = 0.5 * (P.t0 + P.t1), half = 0.5 * (P.t1 - P.t0);
  static_assert(kRmfMaxDegree == 64, "cosines64 serves n | 64");
  double f[kRmfMaxDegree + 1];
  int n = 8;
  for (int k = 0; k <= n; ++k)
    f[k] = piece_frame(s, P.a, P.u, mid + half * cosines64()[k * (kRmfMaxDegree / n)]).omega;
  for (;;) {
    double c[kRmfMaxDegree + 3] = {};  // c[n + 1], c[n + 2] = 0 for the integral
    const double* cosine = cosines64();  // cos(pi j / n) = cosine[j * 64 / n]
    const int stride = kRmfMaxDegree / n;
    for (int m = 0; m <= n; ++m) {
      double sum = 0.5 * (f[0] + (m % 2 ? -f[n] : f[n]));
      for (int k = 1; k < n; ++k) sum += f[k] * cosine[((m * k) % (2 * n)) * stride];
      c[m] = sum * 2.0 / n;
    }
    c[0] *= 0.5;
    c[n] *= 0.5;
    double tail = half * (std::abs(c[n - 2]) + std::abs(c[n - 1]) + std::abs(c[n]));
    for (int m = 0; m <= n; ++m)
      if (!std::isfinite(c[m])) return false;
    if (tail <= tol || 2 * n > kRmfMaxDegree) {
      if (!(tail <= tol)) return false;
      // phi = integral of the series from x = -1, times dt/dx = half:
      // C_m = half (c_{m-1} - c_{m+1}) / (2m), C_0 from phi(-1) = 0.
      P.degree = n + 1;
      double alt = 0;
      for (int m = 1; m <= n + 1; ++m) {
        const double prev = m == 1 ? 2 * c[0] : c[m - 1];
        P.phi[m] = half * (prev - c[m + 1]) / (2.0 * m);
        alt += (m % 2 ? -1.0 : 1.0) * P.phi[m];
      }
      P.phi[0] = -alt;
      estimate = tail;
      return true;
    }
    // Double n: the old nodes are the even ones.
    for (int k = n; k >= 0; --k) f[2 * k] = f[k];
    n *= 2;
    for (int k = 1; k < n; k += 2)
      f[k] = piece_frame(s, P.a, P.u, mid + half * cosines64()[k * (kRmfMaxDegree / n)]).omega;
  }
}

// W1 at t in piece P.
Vec3d piece_w1(const SkinSpine& s, const RmfPiece& P, double t) {
  const PieceFrame F = piece_frame(s, P.a, P.u, t);
  const double x = (2 * t - P.t0 - P.t1) / (P.t1 - P.t0);
  const double phi = chebyshev(P.phi, P.degree, std::min(std::max(x, -1.0), 1.0));
  return std::cos(phi) * F.U + std::sin(phi) * F.V;
}

// The pieces of split_pieces, each halved (at most 10 times) while its
// series does not converge by degree kRmfMaxDegree (shorter pieces
// converge faster: the complex singularities of the rate move away
// relative to the piece).
Status reference_rmf(const SkinSpine& spine, const Vec3d& u0, double tolerance, RmfTable& T) {
  double bounds[kRmfMaxPieces + 1];
  const int nb = split_pieces(spine, bounds);
  if (nb < 1) return Status::numerical_overflow;
  Vec3d u = u0;
  double total = 0, t = 0;
  int degree = 0, n = 0, next = 1;
  while (t < 1.0) {
    while (bounds[next] <= t) ++next;
    double end = bounds[next];
    for (int halvings = 0;; ++halvings) {
      if (n == kRmfMaxPieces || halvings > 10) return Status::numerical_overflow;
      RmfPiece& P = T.piece[n];
      P.t0 = t;
      P.t1 = end;
      P.a = spine.d1(P.t0).normalized();
      P.u = (u - u.dot(P.a) * P.a).normalized();
      double est = 0;
      if (reference_piece(spine, P, tolerance * (P.t1 - P.t0), est)) {
        total += est;
        degree = std::max(degree, P.degree);
        u = piece_w1(spine, P, P.t1);
        t = end;
        ++n;
        break;
      }
      end = 0.5 * (t + end);
    }
  }
  T.pieces = n;
  T.substeps = degree;
  T.error_estimate = total;
  return Status::ok;
}

Status reflection_rmf(const SkinSpine& spine, const Vec3d& u0, double tolerance, RmfTable& T) {
  // Step doubling: the tables with m and 2m steps per interval differ by
  // ~15 times the error of the finer one (the method is of order 4).
  Vec3d coarse[kRmfIntervals + 1], fine[kRmfIntervals + 1];
  if (!reflection_table(spine, u0, 1, coarse)) return Status::numerical_overflow;
  for (int m = 2; m <= kRmfMaxSubsteps; m *= 2) {
    if (!reflection_table(spine, u0, m, fine)) return Status::numerical_overflow;
    double diff = 0;
    for (int k = 0; k <= kRmfIntervals; ++k) diff = std::max(diff, (fine[k] - coarse[k]).norm());
    const double estimate = diff / 15.0;
    if (estimate <= tolerance) {
      for (int k = 0; k <= kRmfIntervals; ++k) {
        const double t = double(k) / kRmfIntervals;
        T.w[k] = orthonormal_to(fine[k], spine.d1(t));
        T.dw[k] = rmf_rate(spine, t, T.w[k]);
        T.ddw[k] = rmf_second(spine, t, T.w[k]);
      }
      T.substeps = m;
      T.error_estimate = estimate;
      return Status::ok;
    }
    std::copy(fine, fine + kRmfIntervals + 1, coarse);
  }
  return Status::numerical_overflow;  // the tolerance is not met
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
  const Vec3d d0 = spine.d1(0.0).normalized();
  const Vec3d start = w0 - w0.dot(d0) * d0;
  if (!(start.norm() > kParallelTol * w0.norm())) return Status::invalid_argument;
  const Vec3d u0 = start.normalized();
  // Written in place: callers build into scratch objects (make_sphere_skin
  // copies a complete skin into its output only on success).
  out.method = method;
  out.pieces = 0;
  return method == RmfMethod::reference ? reference_rmf(spine, u0, tolerance, out)
                                        : reflection_rmf(spine, u0, tolerance, out);
}

void rmf_at(const SkinSpine& spine, const RmfTable& T, double t, Vec3d& w1, Vec3d* dw1) {
  t = std::min(std::max(t, 0.0), 1.0);
  if (T.method == RmfMethod::reference) {
    int i = 0;
    while (i + 1 < T.pieces && t > T.piece[i].t1) ++i;
    w1 = orthonormal_to(piece_w1(spine, T.piece[i], t), spine.d1(t));
    if (dw1) *dw1 = rmf_rate(spine, t, w1);
    return;
  }
  const double pos = t * kRmfIntervals;
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

// out = S without the unused half of the RMF table (a reference skin
// carries no double-reflection table and vice versa): ~19 KB less to copy.
void copy_skin(const SphereSkin& S, SphereSkin& out) {
  out.ends[0] = S.ends[0];
  out.ends[1] = S.ends[1];
  out.spine = S.spine;
  out.pairing = S.pairing;
  out.delta = S.delta;
  for (int e = 0; e < 2; ++e) {
    out.kappa[e] = S.kappa[e];
    for (int k = 0; k < 3; ++k) out.a_coeff[e][k] = S.a_coeff[e][k];
  }
  const RmfTable& T = S.rmf;
  RmfTable& R = out.rmf;
  R.method = T.method;
  R.pieces = T.pieces;
  R.substeps = T.substeps;
  R.error_estimate = T.error_estimate;
  std::copy(T.piece, T.piece + T.pieces, R.piece);
  if (T.method == RmfMethod::double_reflection) {
    std::copy(T.w, T.w + kRmfIntervals + 1, R.w);
    std::copy(T.dw, T.dw + kRmfIntervals + 1, R.dw);
    std::copy(T.ddw, T.ddw + kRmfIntervals + 1, R.ddw);
  }
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
  // Validity first (it needs only the spine): ERRATA's a c > 0 for every
  // theta iff kappa r < 1 at both ends.
  for (int e = 0; e < 2; ++e) {
    const double kappa = skin_spine_curvature(S.spine, double(e));
    if (!std::isfinite(kappa)) return spine_regular(S.spine) ? Status::numerical_overflow
                                                             : Status::zero_tangent;
    if (!(kappa * S.ends[e].radius < 1.0 - 1e-12)) return Status::curvature_radius_too_large;
  }
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
  copy_skin(S, out);
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

// The cubic Hermite basis on [0, 1] at t, the weights of (p0, m0, p1, m1),
// and (if dH is given) its derivatives.
void cubic_hermite_basis(double t, double* H, double* dH = nullptr) {
  const double t2 = t * t, t3 = t2 * t;
  H[0] = 2 * t3 - 3 * t2 + 1;
  H[1] = t3 - 2 * t2 + t;
  H[2] = -2 * t3 + 3 * t2;
  H[3] = t3 - t2;
  if (!dH) return;
  dH[0] = 6 * t2 - 6 * t;
  dH[1] = 3 * t2 - 4 * t + 1;
  dH[2] = -6 * t2 + 6 * t;
  dH[3] = 3 * t2 - 2 * t;
}

// lambda = H0 r_i - H1 a_i r_i + H2 r_f - H3 a_f r_f (seed 002 eqs. (6)-(11):
// the cubic Hermite (6), (7), (8), (10) with the end scalars a_i, a_f of (9),
// (11)); with the basis' derivatives dH in place of H, lambda's t-derivative.
double hermite_lambda(const double* H, double ri, double ai, double rf, double af) {
  return H[0] * ri - H[1] * ai * ri + H[2] * rf - H[3] * af * rf;
}

// Everything at one t that does not depend on theta.
struct SkinColumn {
  Vec3d alpha, d1, W1, W2, dW1, dW2;
  double H[4], dH[4];  // cubic Hermite basis (p0, m0, p1, m1) and derivatives
  double dturn;        // delta s'(t), s(t) = 3 t^2 - 2 t^3
  double cturn, sturn; // cos, sin of delta s(t)
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
  cubic_hermite_basis(t, c.H, c.dH);
  const double t2 = t * t, t3 = t2 * t;
  const double turn = S.delta * (3 * t2 - 2 * t3);
  c.cturn = std::cos(turn);
  c.sturn = std::sin(turn);
  c.dturn = S.delta * (6 * t - 6 * t2);
  return c;
}

// cos and sin of theta and of theta + delta (the grid forms them once per
// theta; the rotation by delta s(t) is applied by the addition theorem).
struct ThetaTrig {
  double c, s, cd, sd;
};

ThetaTrig theta_trig(const SphereSkin& S, double theta) {
  return {std::cos(theta), std::sin(theta), std::cos(theta + S.delta),
          std::sin(theta + S.delta)};
}

// a(theta) of end e and its theta-derivative.
void end_a(const SphereSkin& S, int e, const ThetaTrig& g, double& a, double& da) {
  const double c = e ? g.cd : g.c, s = e ? g.sd : g.s;
  const double* k = S.a_coeff[e];
  a = k[0] - (c * k[1] + s * k[2]);
  da = s * k[1] - c * k[2];
}

struct SkinPoint {
  Vec3d x, xt, xth;
};

SkinPoint point(const SphereSkin& S, const SkinColumn& c, const ThetaTrig& g) {
  const double ri = S.ends[0].radius, rf = S.ends[1].radius;
  double ai, dai, af, daf;
  end_a(S, 0, g, ai, dai);
  end_a(S, 1, g, af, daf);
  // lambda: the cubic Hermite (6), (7), (8), (10).
  const double lam = hermite_lambda(c.H, ri, ai, rf, af);
  const double lam_t = hermite_lambda(c.dH, ri, ai, rf, af);
  const double lam_th = -c.H[1] * dai * ri - c.H[3] * daf * rf;
  // phi = theta + delta s(t).
  const double cp = g.c * c.cturn - g.s * c.sturn, sp = g.s * c.cturn + g.c * c.sturn;
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

double skin_magnitude(const SphereSkin& S) {
  double m = 0;
  for (const Vec3d& c : S.spine.c) m = std::max(m, c.lpNorm<Eigen::Infinity>());
  for (int e = 0; e < 2; ++e) {
    m = std::max(m, S.ends[e].radius);
    for (double a : S.a_coeff[e]) m = std::max(m, std::abs(a) * S.ends[e].radius);
  }
  return std::isfinite(m) ? m : HUGE_VAL;
}

double skin_lambda(const SphereSkin& S, double theta, double t, double* a) {
  double H[4];  // only the basis: no frame (RMF) needed for lambda
  cubic_hermite_basis(t, H);
  const ThetaTrig g = theta_trig(S, theta);
  double ai, dai, af, daf;
  end_a(S, 0, g, ai, dai);
  end_a(S, 1, g, af, daf);
  if (a) a[0] = ai, a[1] = af;
  const double ri = S.ends[0].radius, rf = S.ends[1].radius;
  return hermite_lambda(H, ri, ai, rf, af);
}

void skin_lambda_polynomials(const SphereSkin& S, double (&L)[3][4]) {
  // The cubic Hermite basis in power form (cubic_hermite_basis).
  static constexpr double H[4][4] = {
      {1, 0, -3, 2}, {0, 1, -2, 1}, {0, 0, 3, -2}, {0, 0, -1, 1}};
  const double ri = S.ends[0].radius, rf = S.ends[1].radius;
  const double* ai = S.a_coeff[0];
  const double* af = S.a_coeff[1];
  const double cd = std::cos(S.delta), sd = std::sin(S.delta);
  // lambda = H0 ri - H1 ri a_i + H2 rf - H3 rf a_f with a_i = ai0 - c ai1 -
  // s ai2 and a_f = af0 - c (cd af1 + sd af2) - s (cd af2 - sd af1).
  const double w0[4] = {ri, -ri * ai[0], rf, -rf * af[0]};
  const double wc[4] = {0, ri * ai[1], 0, rf * (cd * af[1] + sd * af[2])};
  const double ws[4] = {0, ri * ai[2], 0, rf * (cd * af[2] - sd * af[1])};
  for (int k = 0; k < 4; ++k) {
    L[0][k] = L[1][k] = L[2][k] = 0.0;
    for (int b = 0; b < 4; ++b) {
      L[0][k] += w0[b] * H[b][k];
      L[1][k] += wc[b] * H[b][k];
      L[2][k] += ws[b] * H[b][k];
    }
  }
}

void skin_directions(const SphereSkin& S, double t, Vec3d& V1, Vec3d& V2) {
  const SkinColumn c = column(S, t);
  V1 = c.cturn * c.W1 + c.sturn * c.W2;  // w(t; 0): phi = delta s(t)
  V2 = -c.sturn * c.W1 + c.cturn * c.W2;  // w(t; pi/2)
}

Status skin_eval(const SphereSkin& S, double theta, double t, double* x, double* x_theta,
                 double* x_t, double* normal) {
  if (!std::isfinite(theta) || !std::isfinite(t)) return Status::not_finite;
  if (!(t >= 0.0 && t <= 1.0)) return Status::bad_domain;
  const SkinPoint p = point(S, column(S, t), theta_trig(S, theta));
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
                      int nt, double* x, double* normal, std::size_t* singular) {
  if (!theta || !t) return Status::null_argument;
  if (ntheta < 0 || nt < 0) return Status::invalid_argument;
  for (int i = 0; i < ntheta; ++i)
    if (!std::isfinite(theta[i])) return Status::not_finite;
  for (int j = 0; j < nt; ++j) {
    if (!std::isfinite(t[j])) return Status::not_finite;
    if (!(t[j] >= 0.0 && t[j] <= 1.0)) return Status::bad_domain;
  }
  // Validated: every point is written (singular normals as (0, 0, 0), as
  // the circle-family grids do). cos/sin of theta once per theta (in blocks
  // of 64 on the stack), the spine and RMF once per t.
  constexpr int kBlock = 64;
  ThetaTrig g[kBlock];
  // Skins beyond 1e50 may overflow in evaluation: then every point is
  // evaluated first as skin_eval checks it (numerical_overflow before
  // anything is written); below, no product of the formulas can.
  if (skin_magnitude(S) > 1e50)
    for (int j = 0; j < nt; ++j) {
      const SkinColumn c = column(S, t[j]);
      for (int i = 0; i < ntheta; ++i) {
        const SkinPoint p = point(S, c, theta_trig(S, theta[i]));
        if (!input_ok(p.x) || !input_ok(p.xt) || !input_ok(p.xth))
          return Status::numerical_overflow;
      }
    }
  std::size_t bad = 0;
  // i0 advances by the block's own size m <= ntheta - i0, so it never
  // passes ntheta (no int overflow for any count).
  for (int i0 = 0, m = 0; i0 < ntheta; i0 += m) {
    m = std::min(kBlock, ntheta - i0);
    for (int i = 0; i < m; ++i) g[i] = theta_trig(S, theta[i0 + i]);
    for (int j = 0; j < nt; ++j) {
      const SkinColumn c = column(S, t[j]);
      for (int i = 0; i < m; ++i) {
        const SkinPoint p = point(S, c, g[i]);
        const std::size_t k = std::size_t(j) * std::size_t(ntheta) + std::size_t(i0 + i);
        if (x) put(p.x, x + 3 * k);
        if (normal) {
          Vec3d n = Vec3d::Zero();
          if (!unit_normal(p, n)) ++bad;
          put(n, normal + 3 * k);
        }
      }
    }
  }
  if (singular) *singular = bad;
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
      const SkinPoint q = point(S, c, theta_trig(S, theta));
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
