#include "cyclide/exact.hpp"

#include <algorithm>
#include <cmath>

namespace cyclide {
inline namespace v0 {

namespace {

// Polynomial arithmetic that remembers whether a degree bound was exceeded.
struct Algebra {
  bool overflow = false;

  // u = mid + half t.
  double mid = 0.0, half = 1.0;

  // A curve polynomial as a polynomial in t (Bernstein curves converted).
  ExactPoly lift(const RationalCurve& c, const CurvePoly& p) {
    ExactPoly r;
    if (c.bernstein) {
      from_bernstein(p.c, p.deg, (c.u0 - mid) / half, (c.u0 + c.h - mid) / half, r);
      return r;
    }
    // p(mid + half t): Taylor shift by mid, then scale coefficient k by half^k.
    r.assign(p);
    for (int i = 0; i < r.deg; ++i)
      for (int j = r.deg - 1; j >= i; --j) r.c[j] = r.c[j] + mid * r.c[j + 1];
    double f = 1.0;
    for (int k = 0; k <= r.deg; ++k, f *= half) r.c[k] *= f;
    return r;
  }
  ExactPoly mul(const ExactPoly& a, const ExactPoly& b) {
    ExactPoly r;
    if (!multiply(a, b, r)) overflow = true;
    return r;
  }
  struct V {
    ExactPoly c[3];
  };
  V vec(const ExactPoly& x, const ExactPoly& y, const ExactPoly& z) { return {{x, y, z}}; }
  V add(const V& a, const V& b) { return {{a.c[0] + b.c[0], a.c[1] + b.c[1], a.c[2] + b.c[2]}}; }
  V sub(const V& a, const V& b) { return {{a.c[0] - b.c[0], a.c[1] - b.c[1], a.c[2] - b.c[2]}}; }
  V scale(const ExactPoly& s, const V& a) {
    return {{mul(s, a.c[0]), mul(s, a.c[1]), mul(s, a.c[2])}};
  }
  ExactPoly dot(const V& a, const V& b) {
    return mul(a.c[0], b.c[0]) + mul(a.c[1], b.c[1]) + mul(a.c[2], b.c[2]);
  }
  V cross(const V& a, const V& b) {
    return {{mul(a.c[1], b.c[2]) - mul(a.c[2], b.c[1]), mul(a.c[2], b.c[0]) - mul(a.c[0], b.c[2]),
             mul(a.c[0], b.c[1]) - mul(a.c[1], b.c[0])}};
  }
  V derivative(const V& a) {
    return {{a.c[0].derivative(), a.c[1].derivative(), a.c[2].derivative()}};
  }
  // Cramer's rule for n_i . X = b_i: X = num / det.
  void cramer(const V n[3], const ExactPoly b[3], V& num, ExactPoly& det) {
    const V c23 = cross(n[1], n[2]), c31 = cross(n[2], n[0]), c12 = cross(n[0], n[1]);
    det = dot(n[0], c23);
    num = add(add(scale(b[0], c23), scale(b[1], c31)), scale(b[2], c12));
  }
};

ExactVec3 to_exact(const Algebra::V& v, const ExactPoly& w) {
  ExactVec3 e;
  e.x = v.c[0];
  e.y = v.c[1];
  e.z = v.c[2];
  e.w = w;
  for (ExactPoly* p : {&e.x, &e.y, &e.z, &e.w}) p->trim_relative(1e-14);
  return e;
}

// Homogeneous curve data: numerator P, weight w.
struct Hom {
  Algebra::V P;
  ExactPoly w;
};

Hom homogeneous(Algebra& A, const RationalCurve& c) {
  return {A.vec(A.lift(c, c.x), A.lift(c, c.y), A.lift(c, c.z)), A.lift(c, c.w)};
}

// The curve seen from the local origin O: (P - O w) / w = p - O.
Hom homogeneous(Algebra& A, const RationalCurve& c, const Vec3d& O) {
  Hom h = homogeneous(A, c);
  for (int j = 0; j < 3; ++j) h.P.c[j] = h.P.c[j] - h.w.scaled(O[j]);
  return h;
}

// The local origin of a frame: the first curve's point at the middle of
// the domain (t = 0). The planes' right-hand sides are products of two
// positions; formed about O they are of the size of the model, where about
// the coordinate origin a model moved far away would cancel eps |O|^2 (see
// prcs_local_planes). Points come back as N / D + O = (N + O D) / D.
Vec3d local_origin(const RationalCurve& c, double mid) {
  const Vec3d O = c.point(mid);
  return std::isfinite(O.squaredNorm()) ? O : Vec3d::Zero();  // a pole at mid: no shift
}

Algebra::V add_origin(const Algebra::V& N, const ExactPoly& D, const Vec3d& O) {
  return {{N.c[0] + D.scaled(O[0]), N.c[1] + D.scaled(O[1]), N.c[2] + D.scaled(O[2])}};
}

// |P1/w1 - N/D|^2 as num/den: |P1 D - N w1|^2 / (w1 D)^2.
void squared_distance(Algebra& A, const Hom& p, const Algebra::V& N, const ExactPoly& D,
                      ExactPoly& num, ExactPoly& den) {
  const Algebra::V diff = A.sub(A.scale(D, p.P), A.scale(p.w, N));
  num = A.dot(diff, diff);
  const ExactPoly wd = A.mul(p.w, D);
  den = A.mul(wd, wd);
  num.trim_relative(1e-14);
  den.trim_relative(1e-14);
}

// Row of a PRCS normal plane, multiplied by w: (w T | T . P) with
// T = P' w - P w' (parallel to p'); a line element gives (t | t . P).
void normal_plane_row(Algebra& A, const RationalCurve& c, const Hom& h, Algebra::V& n,
                      ExactPoly& b) {
  if (c.kind == CurveKind::line_element) {
    n = A.vec(ExactPoly(c.tangent.x()), ExactPoly(c.tangent.y()), ExactPoly(c.tangent.z()));
    b = A.dot(n, h.P);  // w = 1 for a line element
    return;
  }
  const Algebra::V T = A.sub(A.scale(h.w, A.derivative(h.P)), A.scale(h.w.derivative(), h.P));
  n = A.scale(h.w, T);
  b = A.dot(T, h.P);
}

}  // namespace

Status exact_prcs_frame(const RationalCurve& p1, const RationalCurve& p2, ExactFrame& out,
                        double mid, double half) {
  Algebra A;
  A.mid = mid;
  A.half = half;
  const Vec3d O = local_origin(p1, mid);
  const Hom h1 = homogeneous(A, p1, O), h2 = homogeneous(A, p2, O);
  Algebra::V n[3];
  ExactPoly b[3];
  normal_plane_row(A, p1, h1, n[0], b[0]);
  normal_plane_row(A, p2, h2, n[1], b[1]);
  // Bisector (10) times w1^2 w2^2: 2 (P1 w2 - P2 w1) w1 w2 . X =
  // |P1|^2 w2^2 - |P2|^2 w1^2.
  const ExactPoly w12 = A.mul(h1.w, h2.w);
  const Algebra::V e = A.sub(A.scale(h2.w, h1.P), A.scale(h1.w, h2.P));
  n[2] = A.scale(w12.scaled(2.0), e);
  b[2] = A.mul(A.dot(h1.P, h1.P), A.mul(h2.w, h2.w)) -
         A.mul(A.dot(h2.P, h2.P), A.mul(h1.w, h1.w));
  Algebra::V N;
  ExactPoly D;
  A.cramer(n, b, N, D);
  // s'(u) = (N' D - N D') / (half D^2)  (' = d/dt).
  const Algebra::V Ns = A.sub(A.scale(D, A.derivative(N)), A.scale(D.derivative(), N));
  const ExactPoly D2 = A.mul(D, D).scaled(half);
  ExactFrame F;
  F.o = to_exact(add_origin(N, D, O), D);
  F.a = to_exact(Ns, D2);
  F.p = to_exact(add_origin(h1.P, h1.w, O), h1.w);
  squared_distance(A, h1, N, D, F.r2_num, F.r2_den);
  if (A.overflow) return Status::degree_too_high;
  if (F.o.w.is_zero()) return Status::dependent_planes;
  out = F;
  return Status::ok;
}

Status exact_prrs_frame(const RationalCurve& p1, const RationalCurve& p2,
                        const RationalCurve& p3, ExactFrame& out, double mid, double half) {
  Algebra A;
  A.mid = mid;
  A.half = half;
  const Vec3d O = local_origin(p1, mid);  // about O, as in exact_prcs_frame
  const Hom h1 = homogeneous(A, p1, O), h2 = homogeneous(A, p2, O), h3 = homogeneous(A, p3, O);
  // e_j = p1 - p_j = (P1 w_j - P_j w1) / (w1 w_j); n = e2 x e3 up to the
  // factor w1^2 w2 w3, which does not change the planes.
  const Algebra::V e2 = A.sub(A.scale(h2.w, h1.P), A.scale(h1.w, h2.P));
  const Algebra::V e3 = A.sub(A.scale(h3.w, h1.P), A.scale(h1.w, h3.P));
  Algebra::V n[3];
  ExactPoly b[3];
  // (24) times w1: n . X = n . P1 / w1  ->  (w1 n | n . P1).
  const Algebra::V nn = A.cross(e2, e3);
  n[0] = A.scale(h1.w, nn);
  b[0] = A.dot(nn, h1.P);
  // (25), (26) times w1^2 w_j^2 (see PRCS's bisector).
  const Hom* hj[2] = {&h2, &h3};
  const Algebra::V* ej[2] = {&e2, &e3};
  for (int j = 0; j < 2; ++j) {
    const ExactPoly w1j = A.mul(h1.w, hj[j]->w);
    n[1 + j] = A.scale(w1j.scaled(2.0), *ej[j]);
    b[1 + j] = A.mul(A.dot(h1.P, h1.P), A.mul(hj[j]->w, hj[j]->w)) -
               A.mul(A.dot(hj[j]->P, hj[j]->P), A.mul(h1.w, h1.w));
  }
  Algebra::V N;
  ExactPoly D;
  A.cramer(n, b, N, D);
  ExactFrame F;
  F.o = to_exact(add_origin(N, D, O), D);
  // n(u) = (p1 - p2) x (p1 - p3) = nn / (w1^2 w2 w3).
  F.a = to_exact(nn, A.mul(A.mul(h1.w, h1.w), A.mul(h2.w, h3.w)));
  F.p = to_exact(add_origin(h1.P, h1.w, O), h1.w);
  squared_distance(A, h1, N, D, F.r2_num, F.r2_den);
  if (A.overflow) return Status::degree_too_high;
  if (F.o.w.is_zero()) return Status::collinear_points;
  out = F;
  return Status::ok;
}

Status exact_ringed_frame(const RationalCurve& d, const RationalCurve& n,
                          const RationalCurve& c, ExactFrame& out, double mid, double half) {
  Algebra A;
  A.mid = mid;
  A.half = half;
  const Hom hd = homogeneous(A, d), hn = homogeneous(A, n), hc = homogeneous(A, c);
  ExactFrame F;
  F.o = to_exact(hd.P, hd.w);
  F.a = to_exact(hn.P, hn.w);
  F.p = to_exact(hc.P, hc.w);
  squared_distance(A, hc, hd.P, hd.w, F.r2_num, F.r2_den);
  if (A.overflow) return Status::degree_too_high;
  out = F;
  return Status::ok;
}

double cross_identity_residual(const ExactVec3& a, const ExactVec3& b) {
  Algebra A;
  double worst = 0, scale = 0;
  const ExactPoly* an[3] = {&a.x, &a.y, &a.z};
  const ExactPoly* bn[3] = {&b.x, &b.y, &b.z};
  for (int j = 0; j < 3; ++j) {
    const ExactPoly l = A.mul(*an[j], b.w), r = A.mul(*bn[j], a.w);
    const ExactPoly d = l - r;
    for (int k = 0; k <= d.deg; ++k) worst = std::max(worst, std::abs(d.c[k]));
    for (int k = 0; k <= l.deg; ++k) scale = std::max(scale, std::abs(l.c[k]));
    for (int k = 0; k <= r.deg; ++k) scale = std::max(scale, std::abs(r.c[k]));
  }
  if (A.overflow) return HUGE_VAL;
  return scale > 0 ? worst / scale : worst;
}

}  // namespace v0
}  // namespace cyclide
