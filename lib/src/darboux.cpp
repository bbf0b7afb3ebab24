#include "cyclide/darboux.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>

#include "cyclide/curve.hpp"

namespace cyclide {
inline namespace v0 {

// ------------------------------------------------------------ the surface

Eigen::Matrix3d Darboux::Q() const {
  Eigen::Matrix3d M;
  M << k[kQxx], 0.5 * k[kQxy], 0.5 * k[kQxz],  //
      0.5 * k[kQxy], k[kQyy], 0.5 * k[kQyz],   //
      0.5 * k[kQxz], 0.5 * k[kQyz], k[kQzz];
  return M;
}

void Darboux::set(double phi0, const Vec3d& l, const Eigen::Matrix3d& Q, const Vec3d& b,
                  double c) {
  k[kPhi0] = phi0;
  k[kLx] = l.x();
  k[kLy] = l.y();
  k[kLz] = l.z();
  k[kQxx] = Q(0, 0);
  k[kQyy] = Q(1, 1);
  k[kQzz] = Q(2, 2);
  k[kQxy] = Q(0, 1) + Q(1, 0);
  k[kQxz] = Q(0, 2) + Q(2, 0);
  k[kQyz] = Q(1, 2) + Q(2, 1);
  k[kBx] = b.x();
  k[kBy] = b.y();
  k[kBz] = b.z();
  k[kC] = c;
}

double Darboux::value(const Vec3d& X) const {
  const double S = X.squaredNorm();
  return (phi0() * S + l().dot(X)) * S + X.dot(Q() * X) + b().dot(X) + c();
}

// grad [phi0 S^2 + (l.X) S + X.QX + b.X + c]
//   = 4 phi0 S X + S l + 2 (l.X) X + 2 Q X + b.
Vec3d Darboux::gradient(const Vec3d& X) const {
  const double S = X.squaredNorm();
  return (4 * phi0() * S + 2 * l().dot(X)) * X + S * l() + 2 * (Q() * X) + b();
}

double Darboux::scale() const {
  double m = 0;
  for (double v : k) m = std::max(m, std::abs(v));
  return m;
}

bool Darboux::normalize() {
  const double s = scale();
  if (!std::isfinite(s) || !(s > 0)) return false;
  for (double& v : k) v /= s;
  return true;
}

Darboux Darboux::exponent_normalized() const {
  Darboux D = *this;
  const int e = std::ilogb(scale());
  for (double& v : D.k) v = std::ldexp(v, -e);
  return D;
}

namespace {

bool negligible(double size, double scale) { return size <= kDarbouxZeroTol * scale; }

// A cubic (l.X)(X.X) + X.QX + b.X + c is reducible iff it is
// (l.X + delta)(X.X + e.X + f): then Q = sym(l e^T) + delta I, so Q on the
// plane orthogonal to l is delta times the identity, and e, f follow.
bool parabolic_reducible(const Darboux& D) {
  const Vec3d l = D.l();
  const double L = l.norm();
  const Vec3d lh = l / L;
  const Vec3d w1 = lh.unitOrthogonal(), w2 = lh.cross(w1);
  const Eigen::Matrix3d Q = D.Q();
  const double q11 = w1.dot(Q * w1), q22 = w2.dot(Q * w2), q12 = w1.dot(Q * w2);
  const double tol = 1e-10 * D.scale();
  if (std::abs(q11 - q22) > tol || std::abs(q12) > tol) return false;
  const double delta = 0.5 * (q11 + q22);
  const Vec3d v = (Q - delta * Eigen::Matrix3d::Identity()) * lh;
  const double e_l = v.dot(lh) / L;
  const Vec3d e = 2 * v / L - e_l * lh;
  // b = f l + delta e, c = delta f.
  const Vec3d rest = D.b() - delta * e;
  const double f = rest.dot(l) / (L * L);
  return (rest - f * l).norm() <= tol && std::abs(D.c() - delta * f) <= tol;
}

// A quadric is a plane pair (reducible) iff its 4x4 matrix has rank <= 2.
bool quadric_reducible(const Darboux& D) {
  Eigen::Matrix4d M = Eigen::Matrix4d::Zero();
  M.topLeftCorner<3, 3>() = D.Q();
  M.block<3, 1>(0, 3) = 0.5 * D.b();
  M.block<1, 3>(3, 0) = 0.5 * D.b().transpose();
  M(3, 3) = D.c();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eig(M, Eigen::EigenvaluesOnly);
  const Eigen::Vector4d ev = eig.eigenvalues();
  const double big = ev.cwiseAbs().maxCoeff();
  int rank = 0;
  for (int i = 0; i < 4; ++i) rank += std::abs(ev[i]) > 1e-10 * big;
  return rank <= 2;
}

// A quartic is reducible iff (normalized to phi0 = 1) it is a product of two
// spheres (S + a.X + alpha)(S + b.X + beta), S = X.X, possibly complex
// conjugate: then l = a + b, Q = (alpha + beta) I + sym(a b^T),
// b_lin = beta a + alpha b, c = alpha beta. With a, b = l/2 +- d:
// M = Q - l l^T / 4 = sigma I - d d^T (sigma = alpha + beta) has a double
// eigenvalue sigma; w = b_lin - sigma l / 2 = (beta - alpha) d lies along
// the third eigenvector, and c = (sigma^2 - delta^2)/4 with
// delta^2 = |w|^2 / (sigma - lambda3) (also for imaginary d).
bool quartic_reducible(const Darboux& D) {
  const double p0 = D.phi0();
  const Vec3d l = D.l() / p0, b = D.b() / p0;
  const double c = D.c() / p0;
  const Eigen::Matrix3d M = D.Q() / p0 - 0.25 * l * l.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(M);
  const Vec3d ev = eig.eigenvalues();
  double size = 0;
  for (double v : D.k) size = std::max(size, std::abs(v / p0));
  const double tol = 1e-10 * std::max(size, 1.0) * std::max(size, 1.0);
  // The double eigenvalue: the closer pair (ascending order).
  const bool low = ev[1] - ev[0] <= ev[2] - ev[1];
  if (std::abs(low ? ev[1] - ev[0] : ev[2] - ev[1]) > 1e-10 * std::max(size, 1.0)) return false;
  const double sigma = low ? 0.5 * (ev[0] + ev[1]) : 0.5 * (ev[1] + ev[2]);
  const double lambda3 = low ? ev[2] : ev[0];
  const Vec3d v3 = eig.eigenvectors().col(low ? 2 : 0);
  const Vec3d w = b - 0.5 * sigma * l;
  if ((w - w.dot(v3) * v3).norm() > 1e-10 * std::max(size, 1.0)) return false;
  const double gap = sigma - lambda3;
  if (std::abs(gap) <= 1e-10 * std::max(size, 1.0)) return w.norm() <= 1e-10 * std::max(size, 1.0);
  return std::abs(c - 0.25 * (sigma * sigma - w.squaredNorm() / gap)) <= tol;
}

}  // namespace

DarbouxType darboux_type(const Darboux& D0) {
  if (!(D0.scale() > 0)) return DarbouxType::zero;
  // The type does not depend on the equation's scale: classify it after an
  // exact division by a power of two (fuzz_lines: z (a X.X - b) at
  // |k| ~ 1e-164 was parabolic, 2^7 times it reducible).
  const Darboux D = D0.exponent_normalized();
  const double s = D.scale();
  const double q = std::max({std::abs(D.k[kQxx]), std::abs(D.k[kQyy]), std::abs(D.k[kQzz]),
                             std::abs(D.k[kQxy]), std::abs(D.k[kQxz]), std::abs(D.k[kQyz])});
  if (!negligible(std::abs(D.phi0()), s))
    return quartic_reducible(D) ? DarbouxType::reducible : DarbouxType::quartic;
  if (!negligible(D.l().cwiseAbs().maxCoeff(), s))
    return parabolic_reducible(D) ? DarbouxType::reducible : DarbouxType::parabolic;
  if (!negligible(q, s)) return quadric_reducible(D) ? DarbouxType::reducible : DarbouxType::quadric;
  if (!negligible(D.b().cwiseAbs().maxCoeff(), s)) return DarbouxType::plane;
  return DarbouxType::constant;
}

// F(Y + m) with S_X = S_Y + 2 m.Y + |m|^2, expanded term by term.
Darboux translate(const Darboux& D, const Vec3d& m) {
  const double p0 = D.phi0(), mm = m.squaredNorm();
  const Vec3d l = D.l(), b = D.b();
  const Eigen::Matrix3d Q = D.Q(), I = Eigen::Matrix3d::Identity();
  const double lm = l.dot(m);
  const Vec3d l2 = l + 4 * p0 * m;
  const Eigen::Matrix3d Q2 = Q + p0 * (2 * mm * I + 4 * m * m.transpose()) +
                             (l * m.transpose() + m * l.transpose()) + lm * I;
  const Vec3d b2 = b + 2 * (Q * m) + 4 * p0 * mm * m + mm * l + 2 * lm * m;
  const double c2 = D.c() + p0 * mm * mm + lm * mm + m.dot(Q * m) + b.dot(m);
  Darboux T;
  T.set(p0, l2, Q2, b2, c2);
  return T;
}

// ------------------------------------------------------------ inversion

Status check_inversion(const Inversion& inv) {
  if (!input_ok(inv.m) || !input_ok(inv.rho)) return Status::not_finite;
  if (!(inv.rho > 0)) return Status::invalid_argument;
  return Status::ok;
}

namespace {
// rho^2 Y / |Y|^2 = q rho Y/|Y| with q = rho/|Y|, for Y != 0. Never squares
// |Y|: |Y|^2 underflows to 0 for |Y| < 1e-154 although the image is finite
// (fuzz_darboux found AT_INVERSION_CENTER for a point 1e-170 from m).
double inverse_ratio(const Inversion& inv, const Vec3d& Y) { return inv.rho / Y.stableNorm(); }
Vec3d inverse_offset(const Inversion& inv, const Vec3d& Y) {
  const double n = Y.stableNorm();
  return (inv.rho * (inv.rho / n)) * (Y / n);
}
bool at_center(const Inversion& inv, const Vec3d& X) { return (X.array() == inv.m.array()).all(); }

// X' without checks (X != m).
Vec3d invert_raw(const Inversion& inv, const Vec3d& X) { return inv.m + inverse_offset(inv, X - inv.m); }
}  // namespace

Status invert_point(const Inversion& inv, const Vec3d& X, Vec3d& out) {
  if (Status st = check_inversion(inv); st != Status::ok) return st;
  if (!input_ok(X)) return Status::not_finite;
  if (at_center(inv, X)) return Status::at_inversion_center;
  const Vec3d R = invert_raw(inv, X);
  if (!input_ok(R)) return Status::numerical_overflow;
  out = R;
  return Status::ok;
}

// In coordinates centered at m, (A, B, C) -> (C, k B, k^2 A), k = rho^2.
Status invert_sphere(const Inversion& inv, const GeneralSphere& S, GeneralSphere& out) {
  if (Status st = check_inversion(inv); st != Status::ok) return st;
  if (!input_ok(S.A) || !input_ok(S.B) || !input_ok(S.C)) return Status::not_finite;
  if (S.A == 0 && S.B.squaredNorm() == 0) return Status::invalid_argument;
  const Vec3d m = inv.m;
  const double k = inv.rho * inv.rho;
  // Centered at m.
  const double A = S.A;
  const Vec3d B = S.B + 2 * S.A * m;
  const double C = S.C + S.B.dot(m) + S.A * m.squaredNorm();
  // Inverted, then back to X = Y + m.
  const double A2 = C, C2y = k * k * A;
  const Vec3d B2y = k * B;
  GeneralSphere R;
  R.A = A2;
  R.B = B2y - 2 * A2 * m;
  R.C = C2y - B2y.dot(m) + A2 * m.squaredNorm();
  // Every coefficient finite (std::max skips a NaN, e.g. inf - inf in R.C:
  // fuzz_darboux found NaN returned with ok).
  if (!std::isfinite(R.A) || !R.B.allFinite() || !std::isfinite(R.C))
    return Status::numerical_overflow;
  const double s = std::max({std::abs(R.A), R.B.cwiseAbs().maxCoeff(), std::abs(R.C)});
  if (!(s > 0)) return Status::invalid_argument;
  R.A /= s;
  R.B /= s;
  R.C /= s;
  out = R;
  return Status::ok;
}

namespace {

// Whether the three points are resolved: pairwise apart by more than the
// rounding of their coordinates. An image that collapses below that (a far
// circle, or rho^2 underflowing) has no circle through them (fuzz_darboux
// found a zero-axis "line" returned with ok).
bool apart(const Vec3d& a, const Vec3d& b) {
  const double big = std::max(a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff());
  return (b - a).norm() > 64 * std::numeric_limits<double>::epsilon() * big;
}
bool distinct(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  return apart(a, b) && apart(a, c) && apart(b, c);
}

// The circle through three distinct points (is_line if they are collinear).
CircleOrLine through(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  CircleOrLine r;
  const Vec3d ab = b - a, ac = c - a, n = ab.cross(ac);
  const double n2 = n.squaredNorm();
  if (!(n2 > 1e-24 * ab.squaredNorm() * ac.squaredNorm())) {
    r.is_line = true;
    r.point = a;
    r.axis = (ab.squaredNorm() >= ac.squaredNorm() ? ab : ac).normalized();
    return r;
  }
  const Vec3d center =
      a + (ac.squaredNorm() * n.cross(ab) + ab.squaredNorm() * ac.cross(n)) / (2 * n2);
  r.point = center;
  r.axis = n / std::sqrt(n2);
  r.radius = (center - a).norm();
  return r;
}

}  // namespace

Status invert_circle(const Inversion& inv, const CircleOrLine& c, CircleOrLine& out) {
  if (Status st = check_inversion(inv); st != Status::ok) return st;
  if (!input_ok(c.point) || !input_ok(c.axis) || !input_ok(c.radius)) return Status::not_finite;
  if (!(c.axis.squaredNorm() > 0)) return Status::invalid_argument;
  const Vec3d ax = c.axis.normalized();
  const Vec3d e1 = ax.unitOrthogonal(), e2 = ax.cross(e1);
  CircleOrLine r;
  // Where m lies on the input to the rounding of the coordinates (not only
  // relative to its distance from c.point: fuzz_darboux found a line through
  // m at |m| ~ 123, off by rounding, mapped to a line of a wrong direction).
  const double resolution = 16 * std::numeric_limits<double>::epsilon() *
                            (inv.m.norm() + c.point.norm());
  if (c.is_line) {
    // Through m: the line maps to itself. Otherwise the circle through m
    // whose diameter is the image of the foot F = m - h of m on the line:
    // center m - rho^2 h / (2 |h|^2), radius rho^2 / (2 |h|), in the plane
    // of the line and m (closed form: three far image points are not
    // resolved when the line passes close to m).
    const Vec3d w = inv.m - c.point;
    const Vec3d h = w - w.dot(ax) * ax;  // m minus its foot on the line
    const double off = h.norm();
    if (off <= std::max(1e-14 * (w.norm() + inv.rho), resolution)) {
      r = c;
      r.axis = ax;
    } else {
      const double k = inv.rho * inv.rho;
      r.is_line = false;
      r.point = inv.m - (k / (2 * off * off)) * h;
      r.radius = k / (2 * off);
      r.axis = h.cross(ax).normalized();
      // A circle below the rounding of its center (rho^2 underflowing) is
      // not resolved.
      if (!(r.radius > 64 * std::numeric_limits<double>::epsilon() * r.point.norm()))
        return Status::numerical_overflow;
    }
  } else {
    if (!(c.radius > 0)) return Status::invalid_argument;
    // Three points of the circle away from m; if m is on the circle, two
    // points give the image line.
    const Vec3d w = inv.m - c.point;
    const Vec3d in_plane = w - w.dot(ax) * ax;
    const double on = std::abs(w.dot(ax)) + std::abs(in_plane.norm() - c.radius);
    const double angle0 = in_plane.squaredNorm() > 0 ? std::atan2(in_plane.dot(e2), in_plane.dot(e1)) : 0.0;
    Vec3d P[3];
    for (int i = 0; i < 3; ++i) {
      const double t = angle0 + 2.0943951023931957 * (i + 0.5);  // away from m's angle
      P[i] = c.point + c.radius * (std::cos(t) * e1 + std::sin(t) * e2);
    }
    const Vec3d Q0 = invert_raw(inv, P[0]), Q1 = invert_raw(inv, P[1]);
    if (on <= std::max(1e-14 * (c.radius + w.norm()), resolution)) {
      if (!apart(Q0, Q1)) return Status::numerical_overflow;
      r.is_line = true;
      r.point = Q0;
      r.axis = (Q1 - Q0).normalized();
    } else {
      const Vec3d Q2 = invert_raw(inv, P[2]);
      if (!distinct(Q0, Q1, Q2)) return Status::numerical_overflow;
      r = through(Q0, Q1, Q2);
    }
  }
  if (!input_ok(r.point) || !input_ok(r.axis) || !std::isfinite(r.radius))
    return Status::numerical_overflow;
  out = r;
  return Status::ok;
}

Status invert_darboux(const Inversion& inv, const Darboux& D, Darboux& out) {
  if (Status st = check_inversion(inv); st != Status::ok) return st;
  for (double v : D.k)
    if (!input_ok(v)) return Status::not_finite;
  if (!(D.scale() > 0)) return Status::invalid_argument;
  const double k = inv.rho * inv.rho;
  const Darboux G = translate(D, inv.m);  // centered at m
  Darboux H;
  H.set(G.c(), k * G.b(), k * k * G.Q(), k * k * k * G.l(), k * k * k * k * G.phi0());
  Darboux R = translate(H, -inv.m);
  // Every coefficient finite (scale() skips a NaN, e.g. inf - inf or 0 inf:
  // fuzz_darboux found NaN returned with ok).
  for (double v : R.k)
    if (!std::isfinite(v)) return Status::numerical_overflow;
  if (!R.normalize()) return Status::invalid_argument;
  out = R;
  return Status::ok;
}

Status invert_surface_point(const Inversion& inv, const SurfacePoint& p, bool du, bool dv,
                            bool normal, SurfacePoint& out) {
  if (Status st = check_inversion(inv); st != Status::ok) return st;
  if (at_center(inv, p.x)) return Status::at_inversion_center;
  const Vec3d Y = p.x - inv.m;
  // The differential is q^2 times the reflection in the plane normal to Y.
  const double q = inverse_ratio(inv, Y);
  const Vec3d Yh = Y.stableNormalized();
  auto reflect = [&](const Vec3d& v) { return v - 2 * Yh.dot(v) * Yh; };
  SurfacePoint r;
  r.x = inv.m + inverse_offset(inv, Y);
  if (du) r.du = q * (q * reflect(p.du));
  if (dv) r.dv = q * (q * reflect(p.dv));
  if (normal) r.normal = reflect(p.normal);
  bool finite = input_ok(r.x);
  if (du) finite &= input_ok(r.du);
  if (dv) finite &= input_ok(r.dv);
  if (normal) finite &= input_ok(r.normal);
  if (!finite) return Status::numerical_overflow;
  out = r;
  return Status::ok;
}

// ------------------------------------------------------------ DCMC

Darboux DcmcFamily::member(double alpha) const {
  Darboux D = base;
  for (int i = 0; i < kDarbouxCoeffs; ++i) D.k[i] += alpha * quadric.k[i];
  return D;
}

namespace {

// Coefficients (t^0, t^1, t^2) of each phi2 monomial along P + t d, in the
// order qxx, qyy, qzz, qxy, qxz, qyz, bx, by, bz, c.
void monomials_along(const Line& L, double (&rows)[3][10]) {
  const Vec3d& P = L.P;
  const Vec3d& d = L.d;
  const int pairs[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
  for (int m = 0; m < 6; ++m) {
    const int i = pairs[m][0], j = pairs[m][1];
    rows[0][m] = P[i] * P[j];
    rows[1][m] = P[i] * d[j] + P[j] * d[i];
    rows[2][m] = d[i] * d[j];
  }
  for (int i = 0; i < 3; ++i) {
    rows[0][6 + i] = P[i];
    rows[1][6 + i] = d[i];
    rows[2][6 + i] = 0;
  }
  rows[0][9] = 1;
  rows[1][9] = rows[2][9] = 0;
}

}  // namespace

Status dcmc(const Line (&lines)[3], DcmcFamily& out) {
  for (int i = 0; i < 3; ++i) {
    if (!input_ok(lines[i].P) || !input_ok(lines[i].d)) return Status::not_finite;
    if (!(lines[i].d.squaredNorm() > 0)) return Status::invalid_argument;
  }
  // Steps 3-4 solve for the coefficients of phi2, monomials of degrees 0, 1
  // and 2 in X: their columns scale like 1, |X|, |X|^2, so in the caller's
  // coordinates the rank test below would depend on where the lines are and
  // how large they are (a configuration 10^6 of its size away, or scaled by
  // 2^30, has a 10^12-conditioned system and looked rank deficient). They
  // are solved in the normalized coordinates Y = (X - O) / lambda of the
  // lines' own frame (O the mean of the given points, which lie on the
  // lines where the caller's model is -- their feet from the coordinate
  // origin would be |X| apart along the lines; lambda the largest distance
  // of the lines from O), and the family is carried back exactly:
  // F(X) = lambda^3 F_Y((X - O) / lambda).
  const Vec3d O = (lines[0].P + lines[1].P + lines[2].P) / 3.0;
  Line L[3];
  double lambda = 0;
  for (int i = 0; i < 3; ++i) {
    L[i].d = lines[i].d.normalized();
    const Vec3d P = lines[i].P - O;
    L[i].P = P - P.dot(L[i].d) * L[i].d;  // nearest to O
    lambda = std::max(lambda, L[i].P.norm());
  }
  if (!(lambda > 0)) lambda = 1;  // three concurrent lines: no length of their own
  for (Line& l : L) l.P /= lambda;
  // Mutually non-parallel, with a common normal n (step 2: phi1 = n . X).
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (L[i].d.cross(L[j].d).norm() <= 1e-10) return Status::parallel_lines;
  const Vec3d n = L[0].d.cross(L[1].d).normalized();
  if (std::abs(n.dot(L[2].d)) > 1e-10) return Status::no_common_normal;
  // Step 3: l_i in D for phi0 = 0, phi1 = n.X: along P + t d (n.d = 0),
  //   (n.P)(|P|^2 + 2 t P.d + t^2) + phi2(P + t d) = 0 for all t.
  Eigen::Matrix<double, 9, 10> A;
  Eigen::Matrix<double, 9, 1> r;
  for (int i = 0; i < 3; ++i) {
    double rows[3][10];
    monomials_along(L[i], rows);
    const double h = n.dot(L[i].P);
    const double rhs[3] = {-h * L[i].P.squaredNorm(), -2 * h * L[i].P.dot(L[i].d), -h};
    for (int e = 0; e < 3; ++e) {
      for (int m = 0; m < 10; ++m) A(3 * i + e, m) = rows[e][m];
      r(3 * i + e) = rhs[e];
    }
  }
  // Step 4, rank-revealing: one null direction expected (ERRATA: a quadric
  // through the lines); more means the lines do not fix the family.
  const Eigen::JacobiSVD<Eigen::Matrix<double, 9, 10>> svd(A, Eigen::ComputeFullU |
                                                                  Eigen::ComputeFullV);
  const auto& sv = svd.singularValues();
  int rank = 0;
  for (int i = 0; i < sv.size(); ++i) rank += sv[i] > 1e-10 * sv[0];
  if (rank < 9) return Status::rank_deficient;
  const Eigen::Matrix<double, 10, 1> x = svd.solve(r);  // minimum norm: orthogonal to the null space
  const Eigen::Matrix<double, 10, 1> h = svd.matrixV().col(9);
  if (!((A * x - r).norm() <= 1e-9 * (1 + r.norm()))) return Status::rank_deficient;
  auto fill = [&](Darboux& D, const Eigen::Matrix<double, 10, 1>& v, const Vec3d& l) {
    D = Darboux{};
    D.k[kLx] = l.x();
    D.k[kLy] = l.y();
    D.k[kLz] = l.z();
    for (int m = 0; m < 10; ++m) D.k[kQxx + m] = v[m];
  };
  // Back to X: in lambda^3 F_Y((X - O) / lambda) the cubic (n.Z)|Z|^2 keeps
  // its coefficients, phi2's quadratic, linear and constant ones take
  // lambda, lambda^2, lambda^3 (the quadric, defined up to a factor, is
  // multiplied by lambda^2 instead: 1, lambda, lambda^2); then Z = X - O.
  Eigen::Matrix<double, 10, 1> xs = x, hs = h;
  for (int m = 0; m < 10; ++m) {
    const double e = m < 6 ? 1.0 : m < 9 ? lambda : lambda * lambda;
    xs[m] *= lambda * e;
    hs[m] *= e;
  }
  DcmcFamily F;
  F.n = n;
  fill(F.base, xs, n);
  fill(F.quadric, hs, Vec3d::Zero());
  F.base = translate(F.base, -O);
  F.quadric = translate(F.quadric, -O);
  // The output's normal form (SPEC §8b): a unit quadric, and as base the
  // member of the family base + alpha quadric whose quadric part (phi2's
  // ten coefficients) is orthogonal to it -- the minimum-norm solution of
  // step 4 in X, as the frame's scaling and translation do not keep it.
  double qq = 0;
  for (int m = kQxx; m <= kC; ++m) qq += F.quadric.k[m] * F.quadric.k[m];
  if (!(qq > 0) || !std::isfinite(qq)) return Status::numerical_overflow;
  const double qn = std::sqrt(qq);
  double bq = 0;
  for (int m = kQxx; m <= kC; ++m) {
    F.quadric.k[m] /= qn;
    bq += F.base.k[m] * F.quadric.k[m];
  }
  for (int m = kQxx; m <= kC; ++m) F.base.k[m] -= bq * F.quadric.k[m];
  // A translation keeps the cubic (n.X)|X|^2: phi1 is n exactly.
  F.base.k[kLx] = n.x();
  F.base.k[kLy] = n.y();
  F.base.k[kLz] = n.z();
  for (double v : F.base.k)
    if (!std::isfinite(v)) return Status::numerical_overflow;
  out = F;
  return Status::ok;
}

}  // namespace v0
}  // namespace cyclide
