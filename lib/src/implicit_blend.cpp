// Implicit ringed blends, seed 001 §7.a (see implicit_blend.hpp).
#include "cyclide/implicit_blend.hpp"

#include <algorithm>
#include <cmath>

#include "cyclide/hermite.hpp"
#include "cyclide/quadrature.hpp"

namespace cyclide {
inline namespace v0 {

namespace {

bool finite3(const Vec3d& v) { return input_ok(v); }

bool quadric_ok(const Quadric& Q) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (!input_ok(Q.A(i, j))) return false;
  return finite3(Q.b) && input_ok(Q.c);
}

// An orthonormal pair (e1, e2) perpendicular to the unit vector a.
void plane_basis(const Vec3d& a, Vec3d& e1, Vec3d& e2) {
  const Vec3d h = std::abs(a.x()) < 0.9 ? Vec3d::UnitX() : Vec3d::UnitY();
  e1 = (h - h.dot(a) * a).normalized();
  e2 = a.cross(e1);
}

// Distance-like residual of the contour system at x: |f|/|grad f| +
// |f_v|/|grad f_v| (HUGE_VAL where a gradient vanishes).
double contour_residual(const ImplicitBlend& B, const Vec3d& v, const Vec3d& x) {
  const BlendJet<double> J = blend_eval(B, x, &v);
  const double g = J.grad.norm(), h = J.hv.norm();
  if (!(g > 0) || !(h > 0)) return HUGE_VAL;
  const double r = std::abs(J.f) / g + std::abs(J.grad.dot(v)) / h;
  return std::isfinite(r) ? r : HUGE_VAL;
}

// Minimum-norm Newton projection onto f = f_v = 0 (the corrector of the
// trace): x -= J^T (J J^T)^-1 F with J = [grad f; H v].
bool project_to_contour(const ImplicitBlend& B, const Vec3d& v, double scale, Vec3d& x) {
  for (int it = 0; it < 12; ++it) {
    const BlendJet<double> J = blend_eval(B, x, &v);
    const Vec3d g = J.grad, h = J.hv;
    const double F0 = J.f, F1 = g.dot(v);
    const double a = g.dot(g), b = g.dot(h), c = h.dot(h), det = a * c - b * b;
    if (!(det > 1e-24 * a * c)) return false;
    const double y0 = (c * F0 - b * F1) / det, y1 = (a * F1 - b * F0) / det;
    const Vec3d dx = y0 * g + y1 * h;
    if (!finite3(dx)) return false;
    x -= dx;
    if (dx.norm() <= 1e-14 * scale) return true;
  }
  return contour_residual(B, v, x) <= 1e-11 * scale;
}

}  // namespace

Status make_quadric(const double* q, Quadric& out) {
  if (!q) return Status::null_argument;
  for (int k = 0; k < 10; ++k)
    if (!input_ok(q[k])) return Status::not_finite;
  Quadric Q;
  Q.A << q[0], q[3] / 2, q[4] / 2, q[3] / 2, q[1], q[5] / 2, q[4] / 2, q[5] / 2, q[2];
  Q.b = Vec3d(q[6], q[7], q[8]) / 2;
  Q.c = q[9];
  if (Q.A.cwiseAbs().maxCoeff() == 0) return Status::invalid_argument;
  out = Q;
  return Status::ok;
}

void quadric_coefficients(const Quadric& Q, double* q) {
  q[0] = Q.A(0, 0);
  q[1] = Q.A(1, 1);
  q[2] = Q.A(2, 2);
  q[3] = 2 * Q.A(0, 1);
  q[4] = 2 * Q.A(0, 2);
  q[5] = 2 * Q.A(1, 2);
  q[6] = 2 * Q.b.x();
  q[7] = 2 * Q.b.y();
  q[8] = 2 * Q.b.z();
  q[9] = Q.c;
}

// |x - P|^2 - ((x - P).u)^2 - r^2 = x^T (I - u u^T) x - 2 x.(I - u u^T) P + ...
Status make_cylinder(const Vec3d& P, const Vec3d& u, double r, Quadric& out) {
  if (!input_ok(P) || !input_ok(u) || !input_ok(r)) return Status::not_finite;
  if (!(u.norm() > 0) || !(r > 0)) return Status::invalid_argument;
  const Vec3d a = u.normalized();
  const Eigen::Matrix3d M = Eigen::Matrix3d::Identity() - a * a.transpose();
  Quadric Q;
  Q.A = M;
  Q.b = -(M * P);
  Q.c = P.dot(M * P) - r * r;
  out = Q;
  return Status::ok;
}

// ((x - A).u)^2 - cos^2 |x - A|^2 = (x - A)^T (u u^T - cos^2 I) (x - A).
Status make_cone(const Vec3d& apex, const Vec3d& u, double half_angle, Quadric& out) {
  if (!input_ok(apex) || !input_ok(u) || !input_ok(half_angle)) return Status::not_finite;
  const double pi = std::acos(-1.0);
  if (!(u.norm() > 0) || !(half_angle > 0) || !(half_angle < pi / 2))
    return Status::invalid_argument;
  const Vec3d a = u.normalized();
  const double c2 = std::cos(half_angle) * std::cos(half_angle);
  const Eigen::Matrix3d M = a * a.transpose() - c2 * Eigen::Matrix3d::Identity();
  Quadric Q;
  Q.A = M;
  Q.b = -(M * apex);
  Q.c = apex.dot(M * apex);
  out = Q;
  return Status::ok;
}

Status make_plane_fn(const double* abcd, PlaneFn& out) {
  if (!abcd) return Status::null_argument;
  for (int k = 0; k < 4; ++k)
    if (!input_ok(abcd[k])) return Status::not_finite;
  const Vec3d n(abcd[0], abcd[1], abcd[2]);
  if (!(n.norm() > 0)) return Status::invalid_argument;
  out.n = n;
  out.d = abcd[3];
  return Status::ok;
}

Status make_implicit_blend(const Quadric& f1, const Quadric& f2, const PlaneFn& f10,
                           const PlaneFn& f20, double lambda, int n, ImplicitBlend& out) {
  if (!std::isfinite(lambda)) return Status::not_finite;
  if (!(lambda > 0 && lambda < 1) || n < 1 || n > kMaxImplicitExponent)
    return Status::invalid_argument;
  if (!quadric_ok(f1) || !quadric_ok(f2) || !finite3(f10.n) || !finite3(f20.n) ||
      !input_ok(f10.d) || !input_ok(f20.d))
    return Status::not_finite;
  const double n1 = f10.n.norm(), n2 = f20.n.norm();
  if (!(n1 > 0) || !(n2 > 0)) return Status::invalid_argument;
  // Coincident planes: parallel normals and equal normalized offsets.
  const Vec3d u1 = f10.n / n1, u2 = f20.n / n2;
  const double sgn = u1.dot(u2) < 0 ? -1.0 : 1.0;
  const double scale = 1 + std::abs(f10.d / n1) + std::abs(f20.d / n2);
  if (u1.cross(u2).norm() <= 1e-14 && std::abs(f10.d / n1 - sgn * f20.d / n2) <= 1e-14 * scale)
    return Status::dependent_planes;
  out = ImplicitBlend{f1, f2, f10, f20, lambda, n};
  return Status::ok;
}

Status circle_center(const Vec3d& p1, const Vec3d& p2, const Vec3d& p3, Vec3d& s) {
  if (!finite3(p1) || !finite3(p2) || !finite3(p3)) return Status::not_finite;
  const Vec3d a = p2 - p1, b = p3 - p1;
  const double ab = a.dot(b), aa = a.squaredNorm(), bb = b.squaredNorm();
  const double cr2 = a.cross(b).squaredNorm();
  if (!(cr2 > 1e-24 * aa * bb)) return Status::collinear_points;
  const Vec3d c = 0.5 * (p1 + p2) + ((ab - bb) / (2 * cr2)) * (ab * a - aa * b);  // (79)
  if (!finite3(c)) return Status::numerical_overflow;
  s = c;
  return Status::ok;
}

// (77)/(78): the conic F = 0 of the end plane met by the line grad F . v =
// 0, in plane coordinates x = o + E y.
Status end_contour_points(const ImplicitBlend& B, int end, const Vec3d& v,
                          PlaneContourPoints& out) {
  if (end != 0 && end != 1) return Status::invalid_argument;
  if (!finite3(v)) return Status::not_finite;
  if (!(v.norm() > 0)) return Status::invalid_argument;
  const Quadric& F = end == 0 ? B.f1 : B.f2;
  const PlaneFn& g = end == 0 ? B.f10 : B.f20;
  const PlaneFn& other = end == 0 ? B.f20 : B.f10;
  const double gn = g.n.norm();
  const Vec3d N = g.n / gn, o = -(g.d / gn) * N;
  Vec3d e1, e2;
  plane_basis(N, e1, e2);
  const Vec3d w = v.normalized();
  const Vec3d Av = F.A * w;
  const Eigen::Vector2d l(e1.dot(Av), e2.dot(Av));
  const double l0 = Av.dot(o) + F.b.dot(w);
  const double scaleA = F.A.cwiseAbs().maxCoeff();
  const double L = 1 + o.norm() + std::sqrt(std::abs(F.c) / scaleA) + F.b.norm() / scaleA;
  PlaneContourPoints R;
  if (!(l.norm() > 1e-12 * scaleA)) {
    // grad F . v constant on the plane: every point or none.
    R.whole_circle = std::abs(l0) <= 1e-12 * scaleA * L;
    out = R;
    return Status::ok;
  }
  const Eigen::Vector2d y0 = (-l0 / l.squaredNorm()) * l;
  const Eigen::Vector2d dir = Eigen::Vector2d(-l.y(), l.x()) / l.norm();
  // F(o + E(y0 + r dir)) = qa r^2 + 2 qb r + qc.
  const Vec3d x0 = o + y0.x() * e1 + y0.y() * e2;
  const Vec3d xd = dir.x() * e1 + dir.y() * e2;
  const double qa = xd.dot(F.A * xd), qb = xd.dot(F.A * x0 + F.b), qc = F.value(x0);
  double r[2];
  int k = 0;
  const double disc = qb * qb - qa * qc;
  if (std::abs(qa) <= 1e-14 * scaleA) {
    if (std::abs(qb) > 1e-14 * scaleA * L) r[k++] = -qc / (2 * qb);
  } else if (disc >= 0) {
    const double sq = std::sqrt(disc);
    const double r1 = (-qb - (qb < 0 ? -sq : sq)) / qa;
    r[k++] = r1;
    if (sq > 1e-14 * std::abs(qb) && r1 != 0) r[k++] = qc / (qa * r1);
  }
  for (int i = 0; i < k; ++i) {
    const Vec3d x = x0 + r[i] * xd;
    if (!finite3(x)) return Status::numerical_overflow;
    if (std::abs(other.value(x)) <= 1e-12 * other.n.norm() * (1 + x.norm()))
      return Status::singular_point;
    R.points[R.count++] = x;
  }
  out = R;
  return Status::ok;
}

Status plane_contour_newton(const ImplicitBlend& B, const Vec3d& v, const Vec3d& normal,
                            const Vec3d& origin, Vec3d& x) {
  if (!finite3(v) || !finite3(normal) || !finite3(origin) || !finite3(x))
    return Status::not_finite;
  if (!(v.norm() > 0) || !(normal.norm() > 0)) return Status::invalid_argument;
  const Vec3d N = normal.normalized();
  Vec3d e1, e2;
  plane_basis(N, e1, e2);
  const double scale = 1 + x.norm();
  Vec3d y = x - N.dot(x - origin) * N;  // start: the projection onto the plane
  double res = contour_residual(B, v, y);
  for (int it = 0; it < 50 && res > 1e-14 * scale; ++it) {
    const BlendJet<double> J = blend_eval(B, y, &v);
    Eigen::Matrix2d M;
    M << J.grad.dot(e1), J.grad.dot(e2), J.hv.dot(e1), J.hv.dot(e2);
    const double det = M.determinant();
    if (!(std::abs(det) > 1e-14 * M.cwiseAbs().maxCoeff() * M.cwiseAbs().maxCoeff()))
      return Status::singular_point;
    const Eigen::Vector2d step = M.inverse() * Eigen::Vector2d(J.f, J.grad.dot(v));
    double h = 1.0;
    bool moved = false;
    for (int k = 0; k < 30; ++k, h *= 0.5) {
      const Vec3d z = y - h * (step.x() * e1 + step.y() * e2);
      const double rz = contour_residual(B, v, z);
      if (rz < res) {
        y = z;
        res = rz;
        moved = true;
        break;
      }
    }
    if (!moved) break;
  }
  if (!(res <= 1e-11 * scale)) return Status::numerical_overflow;
  x = y;
  return Status::ok;
}

Status contour_tangent(const ImplicitBlend& B, const Vec3d& v, const Vec3d& x, Vec3d& t) {
  if (!finite3(v) || !finite3(x)) return Status::not_finite;
  const BlendJet<double> J = blend_eval(B, x, &v);
  const Vec3d c = J.grad.cross(J.hv);  // (80)
  if (!(c.norm() > 1e-12 * J.grad.norm() * J.hv.norm()) || !finite3(c))
    return Status::singular_point;
  t = c.normalized();
  return Status::ok;
}

// Predictor along (80), corrector project_to_contour.
Status trace_contour(const ImplicitBlend& B, const Vec3d& v, const Vec3d& p, const Vec3d& toward,
                     Vec3d& hit) {
  if (!finite3(v) || !finite3(p) || !finite3(toward)) return Status::not_finite;
  const double L = (toward - p).norm();
  if (!(L > 0)) return Status::invalid_argument;
  const double side1 = B.f10.value(toward) >= 0 ? 1.0 : -1.0;
  const double side2 = B.f20.value(p) >= 0 ? 1.0 : -1.0;
  Vec3d t;
  if (Status st = contour_tangent(B, v, p, t); st != Status::ok) return st;
  const Vec3d N1 = side1 * B.f10.n.normalized();
  if (t.dot(N1) < 0 || (std::abs(t.dot(N1)) < 1e-3 && t.dot(toward - p) < 0)) t = -t;
  Vec3d x = p;
  double h = L / 64;
  for (int attempts = 0; attempts < 8192; ++attempts) {
    Vec3d y = x + h * t;
    if (!project_to_contour(B, v, L, y) || (y - x).norm() > 2 * h ||
        (y - x).dot(t) <= 0) {
      h *= 0.5;
      if (h < L / 4096) return Status::numerical_overflow;
      continue;
    }
    Vec3d ty;
    if (Status st = contour_tangent(B, v, y, ty); st != Status::ok) return st;
    if (ty.dot(t) < 0) ty = -ty;
    if (side1 * B.f10.value(y) < -1e-9 * L * B.f10.n.norm()) return Status::numerical_overflow;
    if (side2 * B.f20.value(y) <= 0) {
      // Crossed P2 between x and y: Newton in P2 from the chord's crossing.
      const double gx = B.f20.value(x), gy = B.f20.value(y);
      Vec3d z = x + (gx / (gx - gy)) * (y - x);
      const Vec3d N2 = B.f20.n.normalized();
      const Vec3d o2 = -(B.f20.d / B.f20.n.norm()) * N2;
      if (Status st = plane_contour_newton(B, v, N2, o2, z); st != Status::ok) return st;
      hit = z;
      return Status::ok;
    }
    x = y;
    t = ty;
    h = std::min(2 * h, L / 64);
  }
  return Status::numerical_overflow;
}

Vec3d ContourPiece::dbar(double t) const {
  const double L = length();
  return ferguson(s1, Vec3d(L * nA), s2, Vec3d(L * nB), t);
}
Vec3d ContourPiece::dbar_derivative(double t) const {
  const double L = length();
  return ferguson_derivative(s1, Vec3d(L * nA), s2, Vec3d(L * nB), t);
}

Status contour_piece_from_points(const ImplicitBlend& B, const Vec3d (&v)[3],
                                 const Vec3d (&p)[3], const Vec3d (&q)[3], const Vec3d& nA,
                                 const Vec3d& nB, ContourPiece& out) {
  ContourPiece P;
  for (int i = 0; i < 3; ++i) {
    if (!finite3(v[i]) || !finite3(p[i]) || !finite3(q[i])) return Status::not_finite;
    P.v[i] = v[i];
    P.p[i] = p[i];
    P.q[i] = q[i];
  }
  if (!finite3(nA) || !finite3(nB)) return Status::not_finite;
  if (!(nA.norm() > 0) || !(nB.norm() > 0)) return Status::invalid_argument;
  if (Status st = circle_center(p[0], p[1], p[2], P.s1); st != Status::ok) return st;
  if (Status st = circle_center(q[0], q[1], q[2], P.s2); st != Status::ok) return st;
  if (!(P.length() > 0)) return Status::invalid_argument;
  const Vec3d dir = P.s2 - P.s1;
  P.nA = nA.normalized();
  P.nB = nB.normalized();
  if (P.nA.dot(dir) < 0) P.nA = -P.nA;
  if (P.nB.dot(dir) < 0) P.nB = -P.nB;
  for (int i = 0; i < 3; ++i) {
    if (Status st = contour_tangent(B, v[i], p[i], P.tp[i]); st != Status::ok) return st;
    if (Status st = contour_tangent(B, v[i], q[i], P.tq[i]); st != Status::ok) return st;
    // Oriented from A to B: the branch crosses each plane along +n.
    if (P.tp[i].dot(P.nA) < 0) P.tp[i] = -P.tp[i];
    if (P.tq[i].dot(P.nB) < 0) P.tq[i] = -P.tq[i];
  }
  out = P;
  return Status::ok;
}

namespace {

// Shape quality of a triangle: |a x b| / (|a|^2 + |b|^2 + |a - b|^2) (0:
// collinear; 1/(2 sqrt 3) for equilateral).
double triangle_quality(const Vec3d& p1, const Vec3d& p2, const Vec3d& p3) {
  const Vec3d a = p2 - p1, b = p3 - p1;
  const double s = a.squaredNorm() + b.squaredNorm() + (a - b).squaredNorm();
  return s > 0 ? a.cross(b).norm() / s : 0.0;
}

}  // namespace

namespace {

// The branches: slot i follows the contour curve for v[i]; fixed[i] = -1
// lets the slot take either P1 point, 0 or 1 prescribes it (Remark 7.5:
// both branches of one curve).
Status choose_branches(const ImplicitBlend& B, const Vec3d (&v)[3], const int (&fixed)[3],
                       ContourPiece& out) {
  PlaneContourPoints P1[3], P2[3];
  Vec3d toward = Vec3d::Zero();
  int nq = 0;
  for (int i = 0; i < 3; ++i) {
    if (Status st = end_contour_points(B, 0, v[i], P1[i]); st != Status::ok) return st;
    if (Status st = end_contour_points(B, 1, v[i], P2[i]); st != Status::ok) return st;
    if (P1[i].count == 0 || P2[i].count == 0 || fixed[i] >= P1[i].count)
      return Status::empty_real_locus;
    for (int j = 0; j < P2[i].count; ++j, ++nq) toward += P2[i].points[j];
  }
  toward /= double(nq);
  // Pair every candidate p with the q its branch reaches (-1: none).
  int pair[3][2] = {{-1, -1}, {-1, -1}, {-1, -1}};
  Status last = Status::ok;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < P1[i].count; ++j) {
      Vec3d hit;
      const Status st = trace_contour(B, v[i], P1[i].points[j], toward, hit);
      if (st != Status::ok) {
        last = st;
        continue;
      }
      const double tol = 1e-6 * (1 + (toward - P1[i].points[j]).norm());
      for (int k = 0; k < P2[i].count; ++k)
        if ((hit - P2[i].points[k]).norm() <= tol) pair[i][j] = k;
    }
  // The branch choice with the best pair of triangles.
  double best = 0;
  int choice[3] = {-1, -1, -1};
  for (int a = 0; a < P1[0].count; ++a)
    for (int b = 0; b < P1[1].count; ++b)
      for (int c = 0; c < P1[2].count; ++c) {
        const int j[3] = {a, b, c};
        bool ok = true;
        for (int i = 0; i < 3; ++i)
          ok = ok && pair[i][j[i]] >= 0 && (fixed[i] < 0 || fixed[i] == j[i]);
        if (!ok) continue;
        const double qp = triangle_quality(P1[0].points[a], P1[1].points[b], P1[2].points[c]);
        const double qq = triangle_quality(P2[0].points[pair[0][a]], P2[1].points[pair[1][b]],
                                           P2[2].points[pair[2][c]]);
        if (std::min(qp, qq) > best) {
          best = std::min(qp, qq);
          for (int i = 0; i < 3; ++i) choice[i] = j[i];
        }
      }
  if (choice[0] < 0) return last != Status::ok ? last : Status::empty_real_locus;
  if (!(best > 1e-6)) return Status::collinear_points;
  Vec3d p[3], q[3];
  for (int i = 0; i < 3; ++i) {
    p[i] = P1[i].points[choice[i]];
    q[i] = P2[i].points[pair[i][choice[i]]];
  }
  return contour_piece_from_points(B, v, p, q, B.f10.n, B.f20.n, out);
}

}  // namespace

Status contour_piece(const ImplicitBlend& B, const Vec3d (&v)[3], ContourPiece& out) {
  const int free[3] = {-1, -1, -1};
  return choose_branches(B, v, free, out);
}

Status contour_piece_two_curves(const ImplicitBlend& B, const Vec3d& v1, const Vec3d& v2,
                                ContourPiece& out) {
  const Vec3d v[3] = {v1, v1, v2};
  const int fixed[3] = {0, 1, -1};
  return choose_branches(B, v, fixed, out);
}

namespace {

using PolyC = Poly<double, kMaxCurveDegree>;

// Power form of the Ferguson cubic's coordinate j.
PolyC cubic_power(const Vec3d& p, const Vec3d& dp, const Vec3d& q, const Vec3d& dq, int j) {
  PolyC r;
  r.deg = 3;
  r.c[0] = p[j];
  r.c[1] = dp[j];
  r.c[2] = 3 * (q[j] - p[j]) - 2 * dp[j] - dq[j];
  r.c[3] = 2 * (p[j] - q[j]) + dp[j] + dq[j];
  return r;
}

PolyC mul(const PolyC& a, const PolyC& b) {
  PolyC r;
  multiply(a, b, r);  // degrees stay <= 15 by construction (checked by the caller)
  return r;
}

}  // namespace

// d = circumcentre (79) of c1, c2, c3 as (N, 2W): W = |a x b|^2 (degree
// 12), N = (c1 + c2) W + ((a.b) - |b|^2) ((a.b) a - |a|^2 b) (degree 15).
Status ringed_through_cubics(const Vec3d (&p)[3], const Vec3d (&dp)[3], const Vec3d (&q)[3],
                             const Vec3d (&dq)[3], Surface& out) {
  for (int i = 0; i < 3; ++i)
    if (!finite3(p[i]) || !finite3(dp[i]) || !finite3(q[i]) || !finite3(dq[i]))
      return Status::not_finite;
  // Collinearity at samples (the circle through the three is undefined).
  for (int k = 0; k <= 32; ++k) {
    const double t = k / 32.0;
    const Vec3d c1 = ferguson(p[0], dp[0], q[0], dq[0], t);
    const Vec3d c2 = ferguson(p[1], dp[1], q[1], dq[1], t);
    const Vec3d c3 = ferguson(p[2], dp[2], q[2], dq[2], t);
    Vec3d s;
    if (circle_center(c1, c2, c3, s) != Status::ok) return Status::collinear_points;
  }
  PolyC c[3][3], a[3], b[3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) c[i][j] = cubic_power(p[i], dp[i], q[i], dq[i], j);
  for (int j = 0; j < 3; ++j) {
    a[j] = c[1][j] - c[0][j];
    b[j] = c[2][j] - c[0][j];
  }
  const PolyC ab = mul(a[0], b[0]) + mul(a[1], b[1]) + mul(a[2], b[2]);
  const PolyC aa = mul(a[0], a[0]) + mul(a[1], a[1]) + mul(a[2], a[2]);
  const PolyC bb = mul(b[0], b[0]) + mul(b[1], b[1]) + mul(b[2], b[2]);
  PolyC cr[3];
  for (int j = 0; j < 3; ++j) {
    const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
    cr[j] = mul(a[j1], b[j2]) - mul(a[j2], b[j1]);
  }
  const PolyC W = mul(cr[0], cr[0]) + mul(cr[1], cr[1]) + mul(cr[2], cr[2]);
  const PolyC k = ab - bb;
  PolyC N[3];
  for (int j = 0; j < 3; ++j) {
    const PolyC V = mul(ab, a[j]) - mul(aa, b[j]);
    N[j] = mul(c[0][j] + c[1][j], W) + mul(k, V);
  }
  double scale = 0;
  for (int e = 0; e <= W.deg; ++e) scale = std::max(scale, std::abs(W.c[e]));
  if (!(scale > 0) || !std::isfinite(scale)) return Status::collinear_points;
  double xyzw[4 * (kMaxCurveDegree + 1)];
  for (int e = 0; e <= kMaxCurveDegree; ++e) {
    for (int j = 0; j < 3; ++j) xyzw[4 * e + j] = N[j].c[e] / scale;
    xyzw[4 * e + 3] = 2 * W.c[e] / scale;
  }
  RationalCurve d, n, c1;
  if (Status st = make_rational_curve(kMaxCurveDegree, xyzw, d); st != Status::ok) return st;
  double ncoef[3 * 7];
  double nscale = 0;
  for (int j = 0; j < 3; ++j)
    for (int e = 0; e <= 6; ++e) nscale = std::max(nscale, std::abs(cr[j].c[e]));
  for (int e = 0; e <= 6; ++e)
    for (int j = 0; j < 3; ++j) ncoef[3 * e + j] = cr[j].c[e] / nscale;
  if (Status st = make_polynomial_curve(6, ncoef, n); st != Status::ok) return st;
  const Vec3d s0[2] = {p[0], dp[0]}, s1[2] = {q[0], dq[0]};
  if (Status st = make_hermite_curve(1, 0.0, 1.0, s0, s1, c1); st != Status::ok) return st;
  return make_ringed(d, n, c1, nullptr, 0.0, 1.0, out);
}

Status blend_error_87(const ImplicitBlend& B, const Surface& S, int nt, int nu, double& error) {
  if (nt < 1 || nt > 64 || nu < 4 || nu > 1024) return Status::invalid_argument;
  double tn[64], tw[64];
  gauss_legendre01(nt, tn, tw);
  const double pi = std::acos(-1.0);
  double sum = 0;
  for (int i = 0; i < nt; ++i) {
    const double t = S.u0 + (S.u1 - S.u0) * tn[i];
    Vec3d C, N;
    double r2 = 0;
    if (Status st = S.circle(t, C, N, r2); st != Status::ok) return st;
    Vec3d e1, e2;
    plane_basis(N, e1, e2);
    const double r = std::sqrt(r2);
    double row = 0;
    for (int j = 0; j < nu; ++j) {
      const double th = 2 * pi * j / nu;
      const Vec3d x = C + r * (std::cos(th) * e1 + std::sin(th) * e2);
      const BlendJet<double> J = blend_eval(B, x);
      const double g2 = J.grad.squaredNorm();
      if (!(g2 > 0)) return Status::singular_point;
      row += J.f * J.f / g2;
    }
    sum += tw[i] * (S.u1 - S.u0) * row / nu;
  }
  if (!std::isfinite(sum)) return Status::numerical_overflow;
  error = sum;
  return Status::ok;
}

}  // namespace v0
}  // namespace cyclide
