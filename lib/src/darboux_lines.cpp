#include "cyclide/darboux_lines.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

namespace cyclide {
inline namespace v0 {

int ParabolicLines::double_families() const {
  int k = 0;
  for (int i = 0; i < line_count; ++i) k += lines[i].multiplicity == 2;
  return k;
}

namespace {

using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;

// ------------------------------------------------ polynomials in t

// Coefficients c[0..5] of a polynomial of degree <= 5 in t.
struct P5 {
  double c[6] = {0, 0, 0, 0, 0, 0};
  double operator()(double t) const {
    double s = c[5];
    for (int k = 4; k >= 0; --k) s = s * t + c[k];
    return s;
  }
  P5 derivative() const {
    P5 d;
    for (int k = 1; k <= 5; ++k) d.c[k - 1] = k * c[k];
    return d;
  }
};
P5 poly(double c0, double c1 = 0, double c2 = 0, double c3 = 0) {
  P5 p;
  p.c[0] = c0;
  p.c[1] = c1;
  p.c[2] = c2;
  p.c[3] = c3;
  return p;
}
P5 operator*(const P5& a, const P5& b) {  // the product must have degree <= 5
  P5 p;
  for (int i = 0; i <= 5; ++i)
    for (int j = 0; i + j <= 5; ++j) p.c[i + j] += a.c[i] * b.c[j];
  return p;
}
P5 operator+(const P5& a, const P5& b) {
  P5 p;
  for (int k = 0; k <= 5; ++k) p.c[k] = a.c[k] + b.c[k];
  return p;
}
P5 operator-(const P5& a, const P5& b) {
  P5 p;
  for (int k = 0; k <= 5; ++k) p.c[k] = a.c[k] - b.c[k];
  return p;
}

// ------------------------------------------------ the pencil of sections

// F / (|l| L^3) in scaled coordinates X = L Y, Y = t n + E eta, for the
// length scale L of the coefficients: every number below is O(1).
struct Sections {
  Vec3d n, e1, e2;
  double L = 1;
  Mat2 S;        // E^T Q E / (|l| L)
  Vec2 g, h;     // beta(t) = t g + h
  double q = 0, bn = 0, c0 = 0;  // gamma(t) = t^3 + q t^2 + bn t + c0

  Mat2 A(double t) const { return S + t * Mat2::Identity(); }
  Vec2 beta(double t) const { return t * g + h; }
  double gamma(double t) const { return ((t + q) * t + bn) * t + c0; }
  // A point of the plane t in input coordinates.
  Vec3d point(double t, const Vec2& eta) const { return L * (t * n + eta[0] * e1 + eta[1] * e2); }
  Vec3d direction(const Vec2& d) const { return (d[0] * e1 + d[1] * e2).normalized(); }
};

Sections sections_of(const Darboux& D) {
  Sections P;
  const Vec3d l = D.l();
  const double ln = l.norm();
  P.n = l / ln;
  P.e1 = P.n.unitOrthogonal();
  P.e2 = P.n.cross(P.e1);
  const Eigen::Matrix3d Q = D.Q();
  const Vec3d b = D.b();
  // The length at which the cubic balances the other terms.
  P.L = std::max({Q.cwiseAbs().maxCoeff() / ln, std::sqrt(b.cwiseAbs().maxCoeff() / ln),
                  std::cbrt(std::abs(D.c()) / ln)});
  if (!(P.L > 0)) P.L = 1;
  const double s2 = 1 / (ln * P.L), s1 = s2 / P.L, s0 = s1 / P.L;
  const Vec3d Qe1 = Q * P.e1, Qe2 = Q * P.e2, Qn = Q * P.n;
  P.S << P.e1.dot(Qe1), P.e1.dot(Qe2), P.e2.dot(Qe1), P.e2.dot(Qe2);
  P.S *= s2;
  P.g = s2 * Vec2(P.e1.dot(Qn), P.e2.dot(Qn));
  P.h = 0.5 * s1 * Vec2(P.e1.dot(b), P.e2.dot(b));
  P.q = s2 * P.n.dot(Qn);
  P.bn = s1 * P.n.dot(b);
  P.c0 = s0 * D.c();
  return P;
}

// The conic of the plane t, M = [[A, beta], [beta^T, gamma]] in (eta, 1).
Eigen::Matrix3d section_conic(const Sections& P, double t) {
  Eigen::Matrix3d M;
  M.topLeftCorner<2, 2>() = P.A(t);
  M.block<2, 1>(0, 2) = P.beta(t);
  M.block<1, 2>(2, 0) = P.beta(t).transpose();
  M(2, 2) = P.gamma(t);
  return M;
}

// Is the conic of the plane t of rank <= 1 (a double line, or zero)?
bool double_line_at(const Sections& P, double t) {
  const Eigen::Vector3d mu =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(section_conic(P, t), Eigen::EigenvaluesOnly)
          .eigenvalues()
          .cwiseAbs();
  double big = mu.maxCoeff(), mid = mu.sum() - big - mu.minCoeff();
  return mid <= kLineAnalysisTol * big;
}

// r(t) = gamma det A - beta^T adj(A) beta: the conic's determinant.
P5 section_determinant(const Sections& P) {
  const P5 a00 = poly(P.S(0, 0), 1), a11 = poly(P.S(1, 1), 1), a01 = poly(P.S(0, 1));
  const P5 b0 = poly(P.h[0], P.g[0]), b1 = poly(P.h[1], P.g[1]);
  const P5 gam = poly(P.c0, P.bn, P.q, 1);
  const P5 detA = a00 * a11 - a01 * a01;
  const P5 two = poly(2);
  return gam * detA - (a11 * b0 * b0 - two * a01 * b0 * b1 + a00 * b1 * b1);
}

// Newton on p from t (a few steps, each kept only while it stays close).
// Newton on p from t; false unless it converges (the last step below
// 1e-10 (1 + |t|), or p(t) = 0): at the real part of a complex pair with a
// small imaginary part Newton wanders instead.
bool polish(const P5& p, double& t) {
  const P5 dp = p.derivative();
  for (int it = 0; it < 6; ++it) {
    const double v = p(t), d = dp(t);
    if (v == 0) return true;
    if (!(std::abs(d) > 0)) return false;
    const double step = v / d;
    if (!(std::abs(step) <= 1e-3 * (1 + std::abs(t)))) return false;
    t -= step;
    if (std::abs(step) <= 1e-10 * (1 + std::abs(t))) return true;
  }
  return false;
}

// Is t a root of r to rounding (relative to the sizes of its terms)?
// (tight: the test for a multiple root at the polished center of a cluster,
// where two distinct roots delta apart leave |r| ~ |r''| delta^2 / 8).
bool is_root(const P5& r, double t, bool tight = false) {
  double size = 0;
  for (int k = 5; k >= 0; --k) size = size * std::abs(t) + std::abs(r.c[k]);
  // In the scaled coordinates every input of r is O(1) or less, so its
  // coefficients carry absolute rounding errors ~1e-16: hence the floor.
  return tight ? std::abs(r(t)) <= 1e-14 * size + 1e-15
               : std::abs(r(t)) <= 1e-11 * size + 1e-14;
}

// Do the members re[i..j) of a cluster polish (Newton on r) into distinct
// simple roots? Two planes 1e-7 apart (scaled) are at the limit where r at
// their midpoint is rounding-sized, so the center test alone would merge
// them (fuzz_lines regress-two-close-line-pair-planes); a true multiple root
// sends Newton from every member to the same point (or not at all).
bool resolves_into_simple_roots(const P5& r, const double* re, int i, int j) {
  double prev = 0;
  for (int k = i; k < j; ++k) {
    double t = re[k];
    if (!polish(r, t) || !is_root(r, t, true)) return false;
    if (k > i && !(std::abs(t - prev) > 1e-9 * (1 + std::abs(t)))) return false;
    prev = t;
  }
  return true;
}

// Real roots of the monic quintic r. A double line is a root of
// multiplicity 2 or 3, which the eigenvalues split by up to ~eps^(1/3)
// (also into complex pairs with |Im| <= 1e-5): a cluster is polished by
// Newton on the derivative of its multiplicity and kept if that converges
// and r vanishes there (tightly), unless the plane there is not a double
// line (double_line(t) false) and the members resolve into distinct simple
// roots; otherwise its members are separate simple roots, kept where Newton
// on r converges and r vanishes (a complex pair's real part fails:
// fuzz_lines limit-close-degenerate-planes).
template <class DoubleLine>
int real_roots(const P5& r, const DoubleLine& double_line, double (&roots)[5]) {
  Eigen::Matrix<double, 5, 5> C = Eigen::Matrix<double, 5, 5>::Zero();
  for (int i = 1; i < 5; ++i) C(i, i - 1) = 1;
  for (int i = 0; i < 5; ++i) C(i, 4) = -r.c[i];
  const Eigen::EigenSolver<Eigen::Matrix<double, 5, 5>> eig(C, false);
  double re[5];
  int count = 0;
  for (int i = 0; i < 5; ++i) {
    const auto z = eig.eigenvalues()[i];
    if (std::abs(z.imag()) <= 1e-5 * (1 + std::abs(z.real()))) re[count++] = z.real();
  }
  for (int i = 1; i < count; ++i)  // insertion sort (at most five values)
    for (int j = i; j > 0 && re[j] < re[j - 1]; --j) std::swap(re[j], re[j - 1]);
  int out = 0;
  auto keep = [&](double t) {
    if (is_root(r, t) && (out == 0 || std::abs(t - roots[out - 1]) > 1e-13 * (1 + std::abs(t))))
      roots[out++] = t;
  };
  for (int i = 0; i < count;) {
    int j = i + 1;
    while (j < count && re[j] - re[j - 1] <= 1e-4 * (1 + std::abs(re[j]))) ++j;
    if (j - i > 1) {
      double t = 0;
      for (int k = i; k < j; ++k) t += re[k];
      t /= (j - i);
      P5 p = r;
      for (int m = 1; m < j - i; ++m) p = p.derivative();
      if (polish(p, t) && is_root(r, t, true) &&
          (double_line(t) || !resolves_into_simple_roots(r, re, i, j))) {
        keep(t);
        i = j;
        continue;
      }
    }
    for (int k = i; k < j; ++k) {
      double t = re[k];
      if (polish(r, t)) keep(t);
    }
    i = j;
  }
  return out;
}

// Symmetric 2x2 eigen decomposition, ascending.
void eigen2(const Mat2& A, double& l0, double& l1, Vec2& v0, Vec2& v1) {
  const Eigen::SelfAdjointEigenSolver<Mat2> es(A);
  l0 = es.eigenvalues()[0];
  l1 = es.eigenvalues()[1];
  v0 = es.eigenvectors().col(0);
  v1 = es.eigenvectors().col(1);
}

struct Found {
  int plane_count = 0;
  SectionPlane planes[kMaxSectionPlanes];
  int line_count = 0;
  CyclideLine lines[kMaxCyclideLines];
};

// The point of the line X + s d (|d| = 1) nearest the origin. Projected
// twice: once leaves P.d ~ eps |X|, which is not small against |P| for a
// line through (nearly) the origin (fuzz_lines).
Vec3d foot(const Vec3d& X, const Vec3d& d) {
  const Vec3d P = X - X.dot(d) * d;
  return P - P.dot(d) * d;
}

void add_line(const Sections& P, double t, const Vec2& p, const Vec2& dir, int mult, Found& F) {
  if (F.line_count >= kMaxCyclideLines) return;
  CyclideLine c;
  c.line.d = P.direction(dir);
  const Vec3d X = P.point(t, p);
  c.line.P = foot(X, c.line.d);
  c.t = P.L * t;
  c.multiplicity = mult;
  F.lines[F.line_count++] = c;
}

void add_plane(const Sections& P, double t, SectionKind kind, Found& F) {
  if (F.plane_count >= kMaxSectionPlanes) return;
  F.planes[F.plane_count++] = {P.L * t, kind};
}

// A line a x + b y + c = 0 of the plane t (homogeneous line coordinates
// w = (a, b, c) in eta); false for the line at infinity, which is l0.
bool add_line_coords(const Sections& P, double t, const Eigen::Vector3d& w, int mult, Found& F) {
  const Vec2 ab(w[0], w[1]);
  if (ab.norm() <= kLineAnalysisTol * std::abs(w[2])) return false;
  add_line(P, t, (-w[2] / ab.squaredNorm()) * ab, Vec2(-ab[1], ab[0]), mult, F);
  return true;
}

// The degenerate conic of the plane t, M = [[A, beta], [beta^T, gamma]]
// (det M = 0). With the eigenpairs (mu_a, w_a), (mu_b, w_b) of the two
// largest |mu|: M = mu_a w_a w_a^T + mu_b w_b w_b^T, so for opposite signs
// the lines are sqrt|mu_a| w_a +- sqrt|mu_b| w_b; for mu_b = 0 (rank 1) the
// double line w_a; for equal signs a complex pair. Parallel lines and the
// pair (finite line, l0) need no special case: their common point is at
// infinity. (Symmetric eigenvectors are well conditioned where the point
// -A^{-1} beta is not.)
void section_lines(const Sections& P, double t, Found& F) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(section_conic(P, t));
  int idx[3] = {0, 1, 2};
  const auto& mu = es.eigenvalues();
  std::sort(idx, idx + 3, [&](int i, int j) { return std::abs(mu[i]) > std::abs(mu[j]); });
  const double ma = mu[idx[0]], mb = mu[idx[1]];
  const Eigen::Vector3d wa = es.eigenvectors().col(idx[0]), wb = es.eigenvectors().col(idx[1]);
  if (!(std::abs(ma) > 0)) return;  // M = 0: the plane lies on F (reducible, excluded before)
  if (std::abs(mb) <= kLineAnalysisTol * std::abs(ma)) {
    if (add_line_coords(P, t, wa, 2, F)) add_plane(P, t, SectionKind::double_line, F);
    return;
  }
  if ((ma > 0) == (mb > 0)) {
    add_plane(P, t, SectionKind::imaginary_pair, F);
    return;
  }
  const double sa = std::sqrt(std::abs(ma)), sb = std::sqrt(std::abs(mb));
  const bool first = add_line_coords(P, t, sa * wa + sb * wb, 1, F);
  const bool second = add_line_coords(P, t, sa * wa - sb * wb, 1, F);
  add_plane(P, t, first && second ? SectionKind::line_pair : SectionKind::line_and_l0, F);
}

// Is the conic of the plane t = -mu (A singular) degenerate: beta . v = 0
// for the null direction v of A (or A = 0)?
bool degenerate_at(const Sections& P, double t) {
  double l0, l1;
  Vec2 v0, v1;
  eigen2(P.A(t), l0, l1, v0, v1);
  if (std::max(std::abs(l0), std::abs(l1)) <= kLineAnalysisTol) return true;
  const Vec2 v = std::abs(l0) <= std::abs(l1) ? v0 : v1;
  return std::abs(P.beta(t).dot(v)) <= kLineAnalysisTol;
}

// Gauss-Newton polish of a simple line on F (the conic split is only as
// accurate as its plane t, which is ill-conditioned where two degenerate
// planes are close): the line's three degrees of freedom, a shift in its
// plane (along m = n x d), a shift of the plane (along n) and a turn in the
// plane (d -> d + phi m), against F(P + s d) = 0 at four s, which is the
// whole cubic restriction. Steps are kept only while the residual drops.
void polish_line(const Darboux& U, const Vec3d& n, double L, CyclideLine& c) {
  Vec3d P = c.line.P, d = c.line.d;
  const double s4[4] = {-1.5 * L, -0.5 * L, 0.5 * L, 1.5 * L};
  auto residual = [&](const Vec3d& Q, const Vec3d& e) {
    double r = 0;
    for (double s : s4) r += std::pow(U.value(Q + s * e), 2);
    return r;
  };
  double best = residual(P, d);
  for (int it = 0; it < 4 && best > 0; ++it) {
    const Vec3d m = n.cross(d);
    Eigen::Matrix<double, 4, 3> J;
    Eigen::Vector4d r;
    for (int i = 0; i < 4; ++i) {
      const Vec3d X = P + s4[i] * d, g = U.gradient(X);
      r[i] = U.value(X);
      J(i, 0) = g.dot(m);
      J(i, 1) = g.dot(n);
      J(i, 2) = s4[i] * g.dot(m);
    }
    const Eigen::Vector3d step = J.colPivHouseholderQr().solve(-r);
    const Vec3d Q = P + step[0] * m + step[1] * n, e = (d + step[2] * m).normalized();
    const double next = residual(Q, e);
    if (!(next < best)) break;
    best = next;
    P = Q;
    d = e;
  }
  c.line.d = d;
  c.line.P = foot(P, d);
  c.t = n.dot(c.line.P);
}

bool lines_finite(const Found& F) {
  for (int i = 0; i < F.line_count; ++i)
    if (!F.lines[i].line.P.allFinite() || !F.lines[i].line.d.allFinite() ||
        !std::isfinite(F.lines[i].t))
      return false;
  return true;
}

}  // namespace

Status parabolic_lines(const Darboux& D, ParabolicLines& out) {
  for (double v : D.k)
    if (!input_ok(v)) return Status::not_finite;
  if (darboux_type(D) != DarbouxType::parabolic) return Status::not_parabolic;
  // The lines do not depend on the equation's scale: work on it divided
  // exactly by a power of two, so that |l| and the products below neither
  // underflow nor overflow (fuzz_lines: subnormal coefficients gave
  // |l| = 0 and a NaN normal with ok).
  const Darboux U = D.exponent_normalized();
  const Sections P = sections_of(U);
  // The planes where A(t) is singular: t = -(eigenvalues of S).
  double m0, m1;
  Vec2 w0, w1;
  eigen2(P.S, m0, m1, w0, w1);
  const double special[2] = {-m1, -m0};
  double roots[5];
  const int nr = real_roots(
      section_determinant(P), [&](double t) { return double_line_at(P, t); }, roots);
  // Where A(t) is singular (t = -mu_k, in closed form) and the conic is
  // degenerate, r(t) = -lambda (beta.v)^2 = 0: that plane is a root, a
  // multiple one for a double line, which the eigenvalues split into
  // nearby reals or complex pairs (by ~1e-5 for fitted equations). It is
  // analyzed at the exact t, and the roots within 1e-4 of it are its
  // splinters (a distinct plane that close is below the resolution).
  Found F;
  bool root_at[2] = {degenerate_at(P, special[0]), degenerate_at(P, special[1])};
  if (root_at[0] && root_at[1] && std::abs(special[0] - special[1]) <= kLineAnalysisTol)
    root_at[1] = false;
  auto near_special = [&](double t) {
    for (int k = 0; k < 2; ++k)
      if (root_at[k] && std::abs(t - special[k]) <= 1e-4 * (1 + std::abs(special[k]))) return true;
    return false;
  };
  for (int k = 0; k < 2; ++k)
    if (root_at[k]) section_lines(P, special[k], F);
  for (int i = 0; i < nr; ++i)
    if (!near_special(roots[i])) section_lines(P, roots[i], F);
  for (int i = 0; i < F.line_count; ++i)
    if (F.lines[i].multiplicity == 1) polish_line(U, P.n, P.L, F.lines[i]);
  if (!lines_finite(F) || !P.n.allFinite()) return Status::numerical_overflow;
  ParabolicLines R;
  R.n = P.n;
  R.plane_count = F.plane_count;
  std::copy(F.planes, F.planes + F.plane_count, R.planes);
  R.line_count = F.line_count;
  std::copy(F.lines, F.lines + F.line_count, R.lines);
  R.l0_circles = std::abs(P.S(0, 0) - P.S(1, 1)) <= kLineAnalysisTol &&
                 std::abs(P.S(0, 1)) <= kLineAnalysisTol;
  out = R;
  return Status::ok;
}

// F on the plane X = P + s d + r e (e = m x d) is r G(s, r) with the circle
//   G = (l.e)(s^2 + r^2) + s (2 (l.e) P.d + 2 d.Qe)
//       + r (2 (l.e) P.e + l.P + e.Qe) + (l.e)|P|^2 + 2 (l.P) P.e + 2 e.QP + b.e.
Status pencil_circle(const Darboux& D, const Line& L, const Vec3d& m, CircleOrLine& out) {
  for (double v : D.k)
    if (!input_ok(v)) return Status::not_finite;
  if (!input_ok(L.P) || !input_ok(L.d) || !input_ok(m)) return Status::not_finite;
  if (darboux_type(D) != DarbouxType::parabolic) return Status::not_parabolic;
  if (!(L.d.norm() > 0) || !(m.norm() > 0)) return Status::invalid_argument;
  const Vec3d d = L.d.normalized(), mh = m.normalized();
  if (std::abs(mh.dot(d)) > 1e-9) return Status::invalid_argument;
  const Vec3d P = L.P - L.P.dot(d) * d, e = mh.cross(d).normalized();
  // L must lie on F (relative to the size of F's terms along it).
  const double scale = D.scale() * std::pow(1 + P.norm(), 3);
  for (double s : {-1.0, 0.0, 1.0})
    if (std::abs(D.value(P + s * (1 + P.norm()) * d)) > 1e-9 * scale) return Status::invalid_argument;
  const Vec3d l = D.l(), b = D.b();
  const Eigen::Matrix3d Q = D.Q();
  const double le = l.dot(e), lP = l.dot(P);
  const double bs = 2 * le * P.dot(d) + 2 * d.dot(Q * e);
  const double br = 2 * le * P.dot(e) + lP + e.dot(Q * e);
  const double c0 = le * P.squaredNorm() + 2 * lP * P.dot(e) + 2 * e.dot(Q * P) + b.dot(e);
  CircleOrLine C;
  C.axis = mh;
  if (std::abs(le) <= 1e-12 * l.norm()) {  // the plane through l0: the other line
    // No finite residual: the section is the line and l0 counted twice.
    // G = bs s + br r + c0: scaled by max(|bs|, |br|) first, so that tiny
    // coefficients do not underflow their squares (fuzz_lines).
    const double big = std::max(std::abs(bs), std::abs(br));
    if (!(big > 0)) return Status::empty_real_locus;
    const double u = bs / big, w = br / big, k = -(c0 / big) / (u * u + w * w);
    C.is_line = true;
    C.point = P + k * (u * d + w * e);
    C.axis = (-w * d + u * e).normalized();
  } else {
    const double s0 = -bs / (2 * le), r0 = -br / (2 * le);
    const double rad2 = s0 * s0 + r0 * r0 - c0 / le;
    const double size = s0 * s0 + r0 * r0 + std::abs(c0 / le);
    if (rad2 < -1e-12 * size) return Status::empty_real_locus;
    C.point = P + s0 * d + r0 * e;
    C.radius = std::sqrt(std::max(rad2, 0.0));
  }
  if (!C.point.allFinite() || !C.axis.allFinite() || !std::isfinite(C.radius))
    return Status::numerical_overflow;
  out = C;
  return Status::ok;
}

// ------------------------------------------------ Props. 3 and 5

// The plane (X - P1).(k + u n) = 0 meets Lj: Pj + s dj at
//   s = -[(Pj - P1).k + u (Pj - P1).n] / (dj.k).
Status pencil_line(const Vec3d& n, const Line& axis, const Line& Lj, Line& out) {
  const Vec3d k = n.cross(axis.d).normalized();
  const double dk = Lj.d.dot(k);
  const Vec3d D = Lj.P - axis.P;
  if (!(std::abs(dk) > 1e-9 * Lj.d.norm())) return Status::parallel_lines;
  if (!(std::abs(D.dot(n)) > 1e-12 * (1 + D.norm()))) return Status::invalid_argument;  // same plane
  Line R;
  R.P = Lj.P - (D.dot(k) / dk) * Lj.d;
  R.d = -(D.dot(n) / dk) * Lj.d;
  if (!R.P.allFinite() || !R.d.allFinite()) return Status::numerical_overflow;
  out = R;
  return Status::ok;
}

namespace {

bool same_plane(const CyclideLine& a, const CyclideLine& b) {
  return std::abs(a.t - b.t) <= 1e-9 * (1 + std::max(std::abs(a.t), std::abs(b.t)));
}
bool parallel(const CyclideLine& a, const CyclideLine& b) {
  return a.line.d.cross(b.line.d).norm() <= 1e-9;
}
// Skew: in different planes through l0 and not parallel.
bool skew(const CyclideLine& a, const CyclideLine& b) { return !same_plane(a, b) && !parallel(a, b); }

Status build_input(const ParabolicLines& A, int axis, const int* used, int count, PencilInput& out) {
  PencilInput I;
  I.axis = axis;
  I.count = count;
  for (int j = 0; j < count; ++j) {
    I.used[j] = used[j];
    if (Status st = pencil_line(A.n, A.lines[axis].line, A.lines[used[j]].line, I.curves[j]);
        st != Status::ok)
      return st;
  }
  out = I;
  return Status::ok;
}


// The candidate inputs of Prop. 3: a double line as axis, two more lines
// skew to it and to each other. visit(axis, used, count) returns true to stop.
template <class Visit>
void for_each_prcs_input(const ParabolicLines& A, Visit visit) {
  for (int a = 0; a < A.line_count; ++a) {
    if (A.lines[a].multiplicity != 2) continue;
    for (int i = 0; i < A.line_count; ++i)
      for (int j = i + 1; j < A.line_count; ++j) {
        const CyclideLine &L0 = A.lines[a], &Li = A.lines[i], &Lj = A.lines[j];
        if (i == a || j == a || !skew(L0, Li) || !skew(L0, Lj) || !skew(Li, Lj)) continue;
        const int used[2] = {i, j};
        if (visit(a, used, 2)) return;
      }
  }
}

// The candidate inputs of Prop. 5: an axis and three lines outside its
// plane, not all in one plane and not parallel to the axis (the
// "additional line" shares a plane with one of the others).
template <class Visit>
void for_each_prrs_input(const ParabolicLines& A, Visit visit) {
  const int n = A.line_count;
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        for (int k = j + 1; k < n; ++k) {
          const CyclideLine& L0 = A.lines[a];
          const int idx[3] = {i, j, k};
          bool ok = true;
          for (int m : idx) ok = ok && m != a && !same_plane(L0, A.lines[m]) && !parallel(L0, A.lines[m]);
          if (!ok) continue;
          if (same_plane(A.lines[i], A.lines[j]) && same_plane(A.lines[j], A.lines[k])) continue;
          if (visit(a, idx, 3)) return;
        }
}

// The input curves are lines c_j(u) = P_j + u d_j. Where two of them meet,
// at a u inside the domain, the PRCS/PRRS points coincide: the frame there
// is 0/0 (a base point of the map) and the circle of that pencil plane is
// lost. u* minimizes |dP + u dd|; they meet if the gap is rounding of the
// terms (relative to their size, so that far from the origin and at any
// scale the decision is the same).
bool inputs_meet_in(const PencilInput& I, double u0, double u1) {
  for (int i = 0; i < I.count; ++i)
    for (int j = i + 1; j < I.count; ++j) {
      const Line &a = I.curves[i], &b = I.curves[j];
      const Vec3d dP = a.P - b.P, dd = a.d - b.d;
      const double dd2 = dd.squaredNorm();
      const double u = dd2 > 0 ? -dP.dot(dd) / dd2 : u0;  // dd = 0: parallel, any u
      const double slack = 1e-9 * (u1 - u0);
      if (!(u >= u0 - slack && u <= u1 + slack)) continue;
      const double size = a.P.norm() + b.P.norm() + std::abs(u) * (a.d.norm() + b.d.norm());
      if ((dP + u * dd).norm() <= 1e-9 * size) return true;
    }
  return false;
}

Status first_input(const ParabolicLines& A, bool canal, PencilInput& out) {
  Status st = Status::too_few_lines;
  auto take = [&](int a, const int* used, int count) {
    st = build_input(A, a, used, count, out);
    return st == Status::ok;
  };
  if (canal) for_each_prcs_input(A, take);
  else for_each_prrs_input(A, take);
  return st;
}

}  // namespace

Status prcs_input_from_lines(const ParabolicLines& A, PencilInput& out) {
  if (A.double_families() == 0) return Status::not_canal;
  return first_input(A, true, out);
}

Status prrs_input_from_lines(const ParabolicLines& A, PencilInput& out) {
  return first_input(A, false, out);
}

namespace {

// Props. 3, 5 over [u0, u1]: the first candidate input whose PRCS/PRRS is
// regular on the whole domain (a pencil plane through the common point of
// two input lines, or parallel normal planes, make a candidate fail there;
// another axis or other lines avoid it). Otherwise the first failure.
Status parameterize(const Darboux& D, bool canal, double u0, double u1, Surface& out,
                    PencilInput* input) {
  ParabolicLines A;
  if (Status st = parabolic_lines(D, A); st != Status::ok) return st;
  if (canal && A.double_families() == 0) return Status::not_canal;
  Status first = Status::too_few_lines;
  bool tried = false, success = false;
  auto attempt = [&](int a, const int* used, int count) {
    PencilInput I;
    Status st = build_input(A, a, used, count, I);
    if (st == Status::ok && inputs_meet_in(I, u0, u1))
      st = canal ? Status::dependent_planes : Status::collinear_points;
    RationalCurve c[3];
    for (int j = 0; j < I.count && st == Status::ok; ++j)
      st = make_line(I.curves[j].P, I.curves[j].d, c[j]);
    Surface S;
    if (st == Status::ok)
      st = canal ? make_prcs(c[0], c[1], nullptr, u0, u1, S)
                 : make_prrs(c[0], c[1], c[2], nullptr, u0, u1, S);
    if (st == Status::ok) {
      out = S;
      if (input) *input = I;
      return success = true;
    }
    if (!tried) first = st;
    tried = true;
    // Errors of the domain do not depend on the candidate: stop there.
    return st == Status::bad_domain || st == Status::not_finite;
  };
  if (canal) for_each_prcs_input(A, attempt);
  else for_each_prrs_input(A, attempt);
  return success ? Status::ok : first;
}

}  // namespace

Status parameterize_parabolic_prcs(const Darboux& D, double u0, double u1, Surface& out,
                                   PencilInput* input) {
  return parameterize(D, true, u0, u1, out, input);
}
Status parameterize_parabolic_prrs(const Darboux& D, double u0, double u1, Surface& out,
                                   PencilInput* input) {
  return parameterize(D, false, u0, u1, out, input);
}

// ------------------------------------------------ §8

namespace {

// The similarity and reparameterization to the normal form (52):
// X = o + (1/sigma) R^T Y, u = u0 + kappa w.
struct NormalFrame {
  Vec3d o, x, y, z;
  double sigma = 1, kappa = 1, u0 = 0;
  Vec3d to_input(const Vec3d& Y) const { return o + (Y[0] * x + Y[1] * y + Y[2] * z) / sigma; }
};

}  // namespace

Status prrs_lines_analysis(const Line (&lines)[3], PrrsLinesAnalysis& out) {
  for (const Line& L : lines) {
    if (!input_ok(L.P) || !input_ok(L.d)) return Status::not_finite;
    if (!(L.d.norm() > 0)) return Status::invalid_argument;
  }
  const Vec3d &d1 = lines[0].d, &d2 = lines[1].d, &d3 = lines[2].d;
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (lines[i].d.normalized().cross(lines[j].d.normalized()).norm() <= 1e-10)
        return Status::parallel_lines;
  const Vec3d n = d1.cross(d2).normalized();
  if (std::abs(n.dot(d3.normalized())) > 1e-10) return Status::no_common_normal;
  PrrsLinesAnalysis R;
  const Vec3d P21 = lines[1].P - lines[0].P;
  const double size = 1 + lines[0].P.norm() + lines[1].P.norm() + lines[2].P.norm();
  R.coplanar_pair = std::abs(P21.dot(n)) <= 1e-10 * size;
  // l1(u0) = l2(u0): P2 - P1 = u0 (d1 - d2).
  const Vec3d dd = d1 - d2;
  const double u0 = P21.dot(dd) / dd.squaredNorm();
  R.common_parameter = R.coplanar_pair && (P21 - u0 * dd).norm() <= 1e-10 * size;
  if (!R.common_parameter) {
    out = R;
    return Status::ok;
  }
  NormalFrame N;
  N.u0 = u0;
  N.o = lines[0].P + u0 * d1;
  const Vec3d P3 = lines[2].P + u0 * d3 - N.o;
  const double h = P3.dot(n);
  if (!(std::abs(h) > 1e-12 * size)) return Status::invalid_argument;  // all three coplanar
  N.z = h > 0 ? n : Vec3d(-n);
  N.x = d1.normalized();
  N.y = N.z.cross(N.x);
  N.sigma = 1 / std::abs(h);
  N.kappa = 1 / (N.sigma * d1.norm());
  const double f = N.sigma * N.kappa;
  R.a2 = f * d2.dot(N.x);
  R.b2 = f * d2.dot(N.y);
  R.a3 = f * d3.dot(N.x);
  R.b3 = f * d3.dot(N.y);
  R.x3 = N.sigma * P3.dot(N.x);
  R.y3 = N.sigma * P3.dot(N.y);
  const double a2 = R.a2, b2 = R.b2, a3 = R.a3, b3 = R.b3;
  R.cond55 = b2 * (1 - a3) - b3 * (1 - a2);
  R.cond56 = b2 * (a3 * a3 + b3 * b3) - b3 * (a2 * a2 + b2 * b2) + a2 * b3 - a3 * b2;
  const double m2 = 1 + a2 * a2 + b2 * b2, m3 = 1 + a3 * a3 + b3 * b3;
  R.pencil = std::abs(R.cond55) > 1e-10 * (1 + std::abs(b2) + std::abs(b3)) * (1 + std::hypot(a2, a3));
  R.cyclide = R.pencil && std::abs(R.cond56) <= 1e-10 * m2 * m3;
  // (56) with (a3, b3) -> mu (a3, b3): mu [mu b2 |d3|^2 - b3 |d2|^2 + a2 b3 - a3 b2] = 0.
  const double q = b2 * (a3 * a3 + b3 * b3);
  if (std::abs(q) > 0) R.mu = (b3 * (a2 * a2 + b2 * b2) - a2 * b3 + a3 * b2) / q;
  // The axis of Sigma: b2 x + (1 - a2) y - ((1 - a2) y3 + b2 x3) z = 0 and
  // z = b2 / cond55 (the pencil's planes are Pi_A + u Pi_B in (52)).
  if (R.pencil) {
    const double z4 = b2 / R.cond55;
    const Vec2 nA(b2, 1 - a2);
    const double cA = ((1 - a2) * R.y3 + b2 * R.x3) * z4;  // nA . (x, y) = cA
    const Vec2 p = nA * (cA / nA.squaredNorm());
    const Vec3d P4(p[0], p[1], z4), D4(-nA[1], nA[0], 0);
    R.l4.P = N.to_input(P4);
    R.l4.d = (D4[0] * N.x + D4[1] * N.y).normalized();
  }
  if (!std::isfinite(R.cond55) || !std::isfinite(R.cond56) || !std::isfinite(R.mu) ||
      !R.l4.P.allFinite() || !R.l4.d.allFinite())
    return Status::numerical_overflow;
  out = R;
  return Status::ok;
}

Status prrs_lines_cyclide(const Line (&lines)[3], Darboux& out, double* residual) {
  PrrsLinesAnalysis A;
  if (Status st = prrs_lines_analysis(lines, A); st != Status::ok) return st;
  if (!A.common_parameter || !A.pencil) return Status::invalid_argument;
  const Line three[3] = {lines[0], lines[2], A.l4};
  DcmcFamily F;
  if (Status st = dcmc(three, F); st != Status::ok) return st;
  // alpha from l2: base(l2(s)) + alpha quadric(l2(s)) = 0 at samples of s
  // (a cubic in s: four samples determine it), least squares.
  const Line& l2 = lines[1];
  const double len = 1 + l2.P.norm();
  const Vec3d d = l2.d.normalized() * len;
  double bb = 0, bq = 0, qq = 0;
  double fb[4], fq[4];
  for (int i = 0; i < 4; ++i) {
    const Vec3d X = l2.P + (i - 1.5) * d;
    fb[i] = F.base.value(X);
    fq[i] = F.quadric.value(X);
    bq += fb[i] * fq[i];
    qq += fq[i] * fq[i];
    bb += fb[i] * fb[i];
  }
  if (!(qq > 1e-24 * std::max(bb, 1e-300))) return Status::rank_deficient;
  const double alpha = -bq / qq;
  Darboux C = F.member(alpha);
  if (!C.normalize()) return Status::numerical_overflow;
  double res = 0;
  for (int i = 0; i < 4; ++i) {
    const Vec3d X = l2.P + (i - 1.5) * d;
    res = std::max(res, std::abs(C.value(X)) / (C.gradient(X).norm() * len + 1e-300));
  }
  for (double v : C.k)
    if (!std::isfinite(v)) return Status::numerical_overflow;
  out = C;
  if (residual) *residual = res;
  return Status::ok;
}

}  // namespace v0
}  // namespace cyclide
