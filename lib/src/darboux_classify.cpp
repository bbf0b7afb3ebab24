#include "cyclide/darboux_classify.hpp"

#include <algorithm>
#include <cmath>

#include "cyclide/curve.hpp"

namespace cyclide {
inline namespace v0 {

Darboux pullback(const Darboux& D, const Similarity& T) {
  const double s = T.scale;
  const Eigen::Matrix3d& R = T.R;
  Darboux H;
  H.set(s * s * s * s * D.phi0(), s * s * s * (R.transpose() * D.l()),
        s * s * (R.transpose() * D.Q() * R), s * (R.transpose() * D.b()), D.c());
  return translate(H, -T.origin);
}

namespace {

bool finite(const NormalForm& nf) {
  return std::isfinite(nf.a) && std::isfinite(nf.b) && std::isfinite(nf.c) &&
         std::isfinite(nf.alpha) && std::isfinite(nf.beta) && std::isfinite(nf.T.scale) &&
         nf.T.R.allFinite() && nf.T.origin.allFinite();
}

// The similarity with T(P1 + beta v) = 0, T(P1 + beta v + d) = e3 and v
// along e1 (d orthogonal to v, d != 0), and the parameter map with
// l1(alpha u' + beta) -> u' e1: (45), (67), (77).
NormalForm frame(const Vec3d& P1, const Vec3d& v, double beta, const Vec3d& d) {
  const Vec3d vh = v.normalized(), dh = d.normalized();
  NormalForm nf;
  nf.T.R.row(0) = vh.transpose();
  nf.T.R.row(1) = dh.cross(vh).transpose();  // e2 = e3 x e1: det R = +1
  nf.T.R.row(2) = dh.transpose();
  nf.T.scale = 1.0 / d.norm();
  nf.T.origin = P1 + beta * v;
  nf.alpha = d.norm() / v.norm();
  nf.beta = beta;
  return nf;
}

// (44) -> (45) in the given order: the simultaneous shift beta makes
// P2 - P1 + beta (w - v) orthogonal to v; it does not exist if (w - v).v = 0
// (a = 1) unless (P2 - P1).v = 0 (then beta = 0).
bool two_lines_normal_form(const Vec3d& P1, const Vec3d& v, const Vec3d& P2, const Vec3d& w,
                           NormalForm& nf) {
  const double vv = v.squaredNorm();
  const Vec3d e = P2 - P1;
  const double den = (w - v).dot(v);
  double beta = 0;
  if (std::abs(den) <= kClassifyTol * vv) {
    if (std::abs(e.dot(v)) > kClassifyTol * e.norm() * v.norm()) return false;
  } else {
    beta = -e.dot(v) / den;
  }
  Vec3d d = e + beta * (w - v);
  d -= (d.dot(v) / vv) * v;  // orthogonal to rounding
  if (!(d.norm() > 0)) return false;
  nf = frame(P1, v, beta, d);
  const Vec3d w45 = nf.T.R * w / v.norm();  // w' = scale R (alpha w)
  nf.a = w45.x();
  nf.b = w45.y();
  nf.c = w45.z();
  return finite(nf);
}

void set_counts(LinesClassification& C, CyclideKind kind, int paper_case, int families,
                int doubles, bool pn) {
  C.kind = kind;
  C.paper_case = paper_case;
  C.circle_families = families;
  C.double_families = doubles;
  C.pn = pn;
}

// Prop. 8 and 9 share the counts: (I) 2 families, both double, PN;
// (II) 3 families, one double.
void set_case(LinesClassification& C, bool case1) {
  if (case1)
    set_counts(C, CyclideKind::parabolic_dupin, 1, 2, 2, true);
  else
    set_counts(C, CyclideKind::parabolic_darboux, 2, 3, 1, false);
}

// (67), (77): l1 -> u' e1 with P2 -> e3 (beta = foot of P2 on l1).
// False if P2 lies on l1.
bool point_normal_form(const Vec3d& P1, const Vec3d& v, const Vec3d& P2, NormalForm& nf) {
  const Vec3d e = P2 - P1;
  const double beta = e.dot(v) / v.squaredNorm();
  const Vec3d d = e - beta * v;
  if (!(d.norm() > kClassifyTol * e.norm())) return false;
  nf = frame(P1, v, beta, d);
  return true;
}

bool zero(const Vec3d& v) { return !(v.squaredNorm() > 0); }

}  // namespace

Status classify_two_lines(const Vec3d& P1, const Vec3d& v, const Vec3d& P2, const Vec3d& w,
                          LinesClassification& out) {
  if (!input_ok(P1) || !input_ok(v) || !input_ok(P2) || !input_ok(w)) return Status::not_finite;
  if (zero(v) || zero(w)) return Status::zero_tangent;
  const Vec3d n = v.cross(w);
  if (n.norm() <= kClassifyTol * v.norm() * w.norm()) return Status::parallel_lines;
  // Skew: (P2 - P1).(v x w) != 0; otherwise b = 0 in (45).
  if (std::abs((P2 - P1).dot(n)) <= kClassifyTol * (P2 - P1).norm() * n.norm())
    return Status::no_normal_form;
  LinesClassification C;
  if (!two_lines_normal_form(P1, v, P2, w, C.nf)) {
    if (!two_lines_normal_form(P2, w, P1, v, C.nf)) return Status::no_normal_form;
    C.nf.swapped = true;
  }
  const double a = C.nf.a, c = C.nf.c;
  const double ww = a * a + C.nf.b * C.nf.b + c * c;
  if (std::abs(ww - 1) <= kClassifyTol) {
    set_counts(C, CyclideKind::hyperboloid, 0, 0, 0, false);  // (47) is not a square
  } else if (std::abs(a - 1) <= kClassifyTol ||
             (std::abs(c) <= kClassifyTol * std::sqrt(ww) &&
              std::abs(a - ww) <= kClassifyTol * ww)) {
    // (I): l2 double (a = 1, Prop. 2), or l1 double (c = 0, a = w.w: the
    // same case with l1, l2 exchanged; r^2 (47) is then a square too).
    set_counts(C, CyclideKind::parabolic_dupin, 1, 4, 2, true);
  } else {
    set_counts(C, CyclideKind::parabolic_darboux, 2, 5, 1, false);
  }
  out = C;
  return Status::ok;
}

Status classify_line_element(const Vec3d& P1, const Vec3d& v, const Vec3d& P2, const Vec3d& w,
                             LinesClassification& out) {
  if (!input_ok(P1) || !input_ok(v) || !input_ok(P2) || !input_ok(w)) return Status::not_finite;
  if (zero(v) || zero(w)) return Status::zero_tangent;
  LinesClassification C;
  if (!point_normal_form(P1, v, P2, C.nf)) return Status::no_normal_form;
  // (68): w in the normal frame, scaled to y-component 1 (w independent
  // of e1, e3).
  const Vec3d wn = C.nf.T.R * w;
  if (!(std::abs(wn.y()) > kClassifyTol * w.norm())) return Status::no_normal_form;
  C.nf.a = wn.x() / wn.y();
  C.nf.b = 1;
  C.nf.c = wn.z() / wn.y();
  if (!finite(C.nf)) return Status::numerical_overflow;
  // Prop. 8 with ERRATA: (I) a = c = 0, (II) (a, c) != (0, 0).
  set_case(C, std::abs(wn.x()) <= kClassifyTol * w.norm() &&
                  std::abs(wn.z()) <= kClassifyTol * w.norm());
  out = C;
  return Status::ok;
}

Status classify_line_two_points(const Vec3d& P1, const Vec3d& v, const Vec3d& P2,
                                const Vec3d& P3, LinesClassification& out) {
  if (!input_ok(P1) || !input_ok(v) || !input_ok(P2) || !input_ok(P3)) return Status::not_finite;
  if (zero(v)) return Status::zero_tangent;
  LinesClassification C;
  if (!point_normal_form(P1, v, P2, C.nf)) return Status::no_normal_form;
  const Vec3d P = C.nf.T.apply(P3);  // (77)
  const double m = std::max(1.0, P.norm());
  if (!(std::abs(P.y()) > kClassifyTol * m)) return Status::no_normal_form;
  C.nf.a = P.x();
  C.nf.b = P.y();
  C.nf.c = P.z();
  if (!finite(C.nf)) return Status::numerical_overflow;
  // Prop. 9: (I) a = 0 and b^2 + c^2 = 1.
  set_case(C, std::abs(P.x()) <= kClassifyTol * m &&
                  std::abs(P.y() * P.y() + P.z() * P.z() - 1) <= kClassifyTol * m * m);
  out = C;
  return Status::ok;
}

// ------------------------------------------------------------ closed forms

Status two_lines_sphere(const NormalForm& nf, double u, Vec3d& s, double& r2) {
  if (!std::isfinite(u) || !finite(nf)) return Status::not_finite;
  const double a = nf.a, b = nf.b, c = nf.c, ww = a * a + b * b + c * c;
  if (!(b != 0)) return Status::invalid_argument;
  const double Y = c + 2 * (ww - a) * u + c * (ww - 1) * u * u;  // (46), (47)
  const double Z = b + b * (1 - ww) * u * u;
  const Vec3d S(u, Y / (2 * b), 0.5 * (1 + (1 - ww) * u * u));
  const double R2 = (Y * Y + Z * Z) / (4 * b * b);
  if (!S.allFinite() || !std::isfinite(R2)) return Status::numerical_overflow;
  s = S;
  r2 = R2;
  return Status::ok;
}

Status two_lines_dupin_r2(const NormalForm& nf, double u, double& r2) {
  if (!std::isfinite(u) || !finite(nf)) return Status::not_finite;
  const double b = nf.b, c = nf.c, bc = b * b + c * c;
  if (!(b != 0) || std::abs(nf.a - 1) > kClassifyTol) return Status::invalid_argument;
  const double q = bc * u * u + 2 * u * c + 1;  // (50)
  const double R2 = bc / (4 * b * b) * q * q;
  if (!std::isfinite(R2)) return Status::numerical_overflow;
  r2 = R2;
  return Status::ok;
}

Status line_element_spine(const NormalForm& nf, double u, Vec3d& s) {
  if (!std::isfinite(u) || !finite(nf)) return Status::not_finite;
  const double a = nf.a, c = nf.c;
  const Vec3d S(u, 0.5 * (c * (1 - u * u) - 2 * a * u), 0.5 * (1 + u * u));  // (69)
  if (!S.allFinite()) return Status::numerical_overflow;
  s = S;
  return Status::ok;
}

Status line_element_cyclide(const NormalForm& nf, Darboux& normal, Darboux& input) {
  if (!finite(nf)) return Status::not_finite;
  const double a = nf.a, c = nf.c;
  Darboux N;  // (70)
  N.k[kLy] = c;
  N.k[kLz] = -1;
  N.k[kQyy] = 1 - a * a - c * c;
  N.k[kQxy] = 2 * a;
  N.k[kQzz] = 2;
  N.k[kBy] = -c;
  N.k[kBz] = -1;
  Darboux G = pullback(N, nf.T);
  if (!G.normalize()) return Status::numerical_overflow;
  normal = N;
  input = G;
  return Status::ok;
}

}  // namespace v0
}  // namespace cyclide
