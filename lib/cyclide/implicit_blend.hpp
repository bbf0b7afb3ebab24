// Implicit ringed blends and their contour curves (seed 001 §7.a, eqs.
// (73)-(80), (84), (87)). The blend (73)
//   f = f1 (1 - lambda) f20^(n+1) - f2 lambda f10^(n+1)
// of two quadrics f1, f2 bounded by the planes f10 = 0, f20 = 0 is
// evaluated with its gradient and the Hessian times a vector (grad f_v =
// H v of the contour function f_v = grad f . v, (76)) by product rules,
// generic in the scalar (double or ceres::Jet). The geometric steps of the
// approximation — contour points on the bounding planes (77)/(78), circle
// centres (79), branch pairing, the auxiliary directrix and the tangents
// (80), and the exact ringed surface through three contour cubics — are
// here; the choice of the tangent lengths (81)-(83) is the optimizer's
// (lib/optim/implicit_blend_optimizer.hpp). Allocation-free.
#pragma once

#include <Eigen/Core>

#include "cyclide/curve.hpp"
#include "cyclide/surface.hpp"

namespace cyclide {
inline namespace v0 {

// Largest exponent n of (73) (f10^(n+1) stays finite for |f10| <= 1e15).
constexpr int kMaxImplicitExponent = 16;

// A quadric f(x) = x^T A x + 2 b.x + c (A symmetric): the symmetric 4x4
// matrix [[A, b], [b^T, c]] acting on (x, 1).
struct Quadric {
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Vec3d b = Vec3d::Zero();
  double c = 0.0;

  template <class S>
  S value(const Vec3<S>& x) const {
    const Vec3<S> Ax = A.cast<S>() * x;
    return x.dot(Ax) + S(2.0) * x.dot(b.cast<S>()) + S(c);
  }
  template <class S>
  Vec3<S> gradient(const Vec3<S>& x) const {  // 2 (A x + b)
    return S(2.0) * (A.cast<S>() * x + b.cast<S>());
  }
  Eigen::Matrix3d hessian() const { return 2.0 * A; }
};

// A linear polynomial f(x) = n.x + d (a bounding plane).
struct PlaneFn {
  Vec3d n = Vec3d::UnitX();
  double d = 0.0;
  template <class S>
  S value(const Vec3<S>& x) const {
    return x.dot(n.cast<S>()) + S(d);
  }
};

// Quadric from its 10 coefficients of
//   q0 x^2 + q1 y^2 + q2 z^2 + q3 xy + q4 xz + q5 yz + q6 x + q7 y + q8 z + q9.
// not_finite for non-finite or |q| > kMaxInputMagnitude; invalid_argument
// if the quadratic part is zero (a plane is not a quadric here).
Status make_quadric(const double* q, Quadric& out);
// Its coefficients (the inverse of make_quadric).
void quadric_coefficients(const Quadric& Q, double* q);
// Cylinder of revolution |x - P|^2 - ((x - P).u)^2 - r^2 (u normalized):
// invalid_argument for u = 0 or r <= 0.
Status make_cylinder(const Vec3d& P, const Vec3d& u, double r, Quadric& out);
// Cone of revolution ((x - A).u)^2 - cos^2(alpha) |x - A|^2 with apex A,
// axis u and half-angle alpha in (0, pi/2): invalid_argument otherwise.
Status make_cone(const Vec3d& apex, const Vec3d& u, double half_angle, Quadric& out);
// Plane a x + b y + c z + d from 4 coefficients: invalid_argument for
// (a, b, c) = 0.
Status make_plane_fn(const double* abcd, PlaneFn& out);

// The blend (73) and its inputs.
struct ImplicitBlend {
  Quadric f1, f2;       // the quadrics R1, R2
  PlaneFn f10, f20;     // their bounding planes P1, P2
  double lambda = 0.5;  // in (0, 1)
  int n = 1;            // 1 <= n <= kMaxImplicitExponent
};

// Validates: invalid_argument for lambda outside (0, 1) or n outside
// 1..kMaxImplicitExponent, not_finite for non-finite numbers,
// dependent_planes for coincident bounding planes (parallel distinct planes
// are allowed: the coaxial case). Nothing is written on error.
Status make_implicit_blend(const Quadric& f1, const Quadric& f2, const PlaneFn& f10,
                           const PlaneFn& f20, double lambda, int n, ImplicitBlend& out);

template <class S>
S int_power(const S& x, int k) {
  S r(1.0);
  for (int i = 0; i < k; ++i) r = r * x;
  return r;
}

// f (73), its gradient and grad(f_v) = H v (76) at x by product rules.
// With m = n + 1, g1 = f10, g2 = f20 (linear, Hessian 0):
//   grad(f1 g2^m) = g2^m grad f1 + m f1 g2^(m-1) grad g2,
//   H(f1 g2^m) v = g2^m H1 v + m g2^(m-1) (grad f1 (grad g2.v) +
//                  grad g2 (grad f1.v)) + m (m-1) f1 g2^(m-2) grad g2 (grad g2.v).
template <class S>
struct BlendJet {
  S f;
  Vec3<S> grad;
  Vec3<S> hv;  // grad f_v = H v (only when asked)
};

namespace detail {
// One term F g^m of (73) with its gradient and H v.
template <class S>
void blend_term(const Quadric& F, const PlaneFn& g, int m, const Vec3<S>& x, const Vec3d* v,
                S& val, Vec3<S>& grad, Vec3<S>& hv) {
  const S q = F.value(x), G = g.value(x);
  const Vec3<S> dq = F.gradient(x), dg = g.n.cast<S>();
  const S Gm2 = int_power(G, m - 2), Gm1 = Gm2 * G, Gm = Gm1 * G;
  val = q * Gm;
  grad = Gm * dq + (S(double(m)) * q * Gm1) * dg;
  if (!v) return;
  const Vec3<S> vv = v->cast<S>();
  const S dgv = dg.dot(vv), dqv = dq.dot(vv);
  hv = Gm * (F.hessian().cast<S>() * vv) + (S(double(m)) * Gm1) * (dq * dgv + dg * dqv) +
       (S(double(m * (m - 1))) * q * Gm2 * dgv) * dg;
}
}  // namespace detail

template <class S>
BlendJet<S> blend_eval(const ImplicitBlend& B, const Vec3<S>& x, const Vec3d* v = nullptr) {
  const int m = B.n + 1;
  S a, b;
  Vec3<S> ga, gb, ha = Vec3<S>::Zero(), hb = Vec3<S>::Zero();
  detail::blend_term(B.f1, B.f20, m, x, v, a, ga, ha);
  detail::blend_term(B.f2, B.f10, m, x, v, b, gb, hb);
  const S l1(1.0 - B.lambda), l2(B.lambda);
  BlendJet<S> r;
  r.f = l1 * a - l2 * b;
  r.grad = l1 * ga - l2 * gb;
  r.hv = l1 * ha - l2 * hb;
  return r;
}

// The contour function f_v = grad f . v (76).
template <class S>
S contour_function(const ImplicitBlend& B, const Vec3<S>& x, const Vec3d& v) {
  return blend_eval(B, x).grad.dot(v.cast<S>());
}

// The Ferguson cubic (Hermite with end points and end tangents on [0, 1]).
template <class S, class P, class D>
Vec3<S> ferguson(const Vec3<P>& p, const Vec3<D>& dp, const Vec3<P>& q, const Vec3<D>& dq,
                 const S& t) {
  const S t2 = t * t, t3 = t2 * t;
  const S h00 = S(2.0) * t3 - S(3.0) * t2 + S(1.0), h10 = t3 - S(2.0) * t2 + t;
  const S h01 = S(3.0) * t2 - S(2.0) * t3, h11 = t3 - t2;
  return h00 * p.template cast<S>() + h10 * dp.template cast<S>() +
         h01 * q.template cast<S>() + h11 * dq.template cast<S>();
}
template <class S, class P, class D>
Vec3<S> ferguson_derivative(const Vec3<P>& p, const Vec3<D>& dp, const Vec3<P>& q,
                            const Vec3<D>& dq, const S& t) {
  const S t2 = t * t;
  const S h00 = S(6.0) * t2 - S(6.0) * t, h10 = S(3.0) * t2 - S(4.0) * t + S(1.0);
  const S h01 = S(6.0) * t - S(6.0) * t2, h11 = S(3.0) * t2 - S(2.0) * t;
  return h00 * p.template cast<S>() + h10 * dp.template cast<S>() +
         h01 * q.template cast<S>() + h11 * dq.template cast<S>();
}

// (79): the centre of the circle through p1, p2, p3,
//   s = (p1 + p2)/2 + ((a.b) - |b|^2)/(2 |a x b|^2) ((a.b) a - |a|^2 b),
// a = p2 - p1, b = p3 - p1. collinear_points when |a x b| <= 1e-12 |a| |b|
// (or a point repeats), not_finite for non-finite input.
Status circle_center(const Vec3d& p1, const Vec3d& p2, const Vec3d& p3, Vec3d& s);

// Contour points on a bounding plane, (77) (end = 0: P1) and (78) (end =
// 1: P2). There the other term of (73) vanishes to order n + 1 >= 2, so
// f = (1-lambda) f20^(n+1) f1 and grad f = (1-lambda) f20^(n+1) grad f1 on
// the circle f1 = f10 = 0: the contour points of the blend on P1 are those
// of the quadric R1 on its end circle — the intersection of the conic f1 =
// 0 in the plane with the line grad f1 . v = 0 (linear for a quadric), a
// quadratic equation solved in closed form (no iteration). Up to 2 points.
// invalid_argument for v = 0 or end not 0/1; not_finite; whole_circle is
// set (count 0, status ok) when every circle point is a contour point (v
// along the quadric's axis, Definition 7.1 excludes it); singular_point
// when the other plane's f_j0 vanishes at a point (the end circle meets
// the other bounding plane: f = 0 on all of P1 there).
struct PlaneContourPoints {
  int count = 0;
  bool whole_circle = false;
  Vec3d points[2] = {Vec3d::Zero(), Vec3d::Zero()};
};
Status end_contour_points(const ImplicitBlend& B, int end, const Vec3d& v,
                          PlaneContourPoints& out);

// The contour point of B for v in the plane normal.(x - origin) = 0 by 2D
// Newton on (f, f_v) in plane coordinates, from x (the start; written with
// the result only on success). <= 50 steps with step halving on increase;
// singular_point if the 2x2 Jacobian is singular, numerical_overflow if it
// does not converge (|f|/|grad f| and |f_v|/|H v| <= 1e-13 scale).
Status plane_contour_newton(const ImplicitBlend& B, const Vec3d& v, const Vec3d& normal,
                            const Vec3d& origin, Vec3d& x);

// (80): t = grad f x grad f_v / |grad f x grad f_v| at x; singular_point
// if the cross product vanishes (relative 1e-12).
Status contour_tangent(const ImplicitBlend& B, const Vec3d& v, const Vec3d& x, Vec3d& t);

// Numerical trace of the contour curve f = f_v = 0 from p (on P1) into the
// blend until it crosses P2 (predictor along (80), minimum-norm Newton
// corrector; step L/64 halved on failure down to L/4096, L = |P2 side
// reference - p|): the crossing point, refined by Newton in P2. Used to
// pair p_i with q_i (the same branch). numerical_overflow if the trace
// fails or returns to P1, singular_point at a singular contour point.
Status trace_contour(const ImplicitBlend& B, const Vec3d& v, const Vec3d& p,
                     const Vec3d& toward, Vec3d& hit);

// The data of one piece of the approximation: three contour branches from
// the plane A (points p_i) to the plane B (points q_i), their unit tangents
// (80) oriented from A to B, the circle centres (79) and the auxiliary
// directrix dbar: the Ferguson cubic s1 -> s2 with tangents |s1 - s2| nA,
// |s1 - s2| nB (unit plane normals oriented from A to B).
struct ContourPiece {
  Vec3d v[3];
  Vec3d p[3], q[3];
  Vec3d tp[3], tq[3];
  Vec3d s1, s2;
  Vec3d nA, nB;
  Vec3d dbar(double t) const;
  Vec3d dbar_derivative(double t) const;
  double length() const { return (s2 - s1).norm(); }
};

// The one-piece data between P1 and P2 for directions v[0..2]: contour
// points (77)/(78), pairing by trace_contour, the choice of one branch per
// direction maximizing the smaller triangle (p1 p2 p3 and q1 q2 q3, sine
// of the smallest angle), centres (79), dbar and tangents (80).
// Statuses: those of the steps; empty_real_locus if a direction has no
// contour point on P1 or P2 (or the whole circle), collinear_points if no
// choice has three non-collinear points at both ends.
Status contour_piece(const ImplicitBlend& B, const Vec3d (&v)[3], ContourPiece& out);

// Remark 7.5: the same with both branches c_v1^+, c_v1^- of the contour
// curve for v1 (the two P1 points, each paired by its trace) and the best
// branch for v2 (v = {v1, v1, v2} in the result).
Status contour_piece_two_curves(const ImplicitBlend& B, const Vec3d& v1, const Vec3d& v2,
                                ContourPiece& out);

// The piece data for given end points (refinement (84): p, q from the
// cut planes), with tangents, centres and dbar; nA, nB are the planes'
// normals (oriented here from p to q).
Status contour_piece_from_points(const ImplicitBlend& B, const Vec3d (&v)[3],
                                 const Vec3d (&p)[3], const Vec3d (&q)[3], const Vec3d& nA,
                                 const Vec3d& nB, ContourPiece& out);

// The exact ringed surface through three Ferguson cubics c_i(t) = (p_i,
// dp_i; q_i, dq_i) on [0, 1]: directrix d = the circumcentre (79) of
// c1(t), c2(t), c3(t) — a rational curve with numerator degree 15 and
// weight degree 12 = deg |a x b|^2 (kMaxCurveDegree = 15 holds it exactly)
// — orientation n = (c1 - c2) x (c1 - c3) (degree 6) and the curve c1;
// make_ringed(d, n, c1). Every circle passes through c1(t), c2(t), c3(t)
// (to rounding). Statuses: collinear_points if the three points are
// collinear at a sampled parameter, those of make_ringed.
Status ringed_through_cubics(const Vec3d (&p)[3], const Vec3d (&dp)[3], const Vec3d (&q)[3],
                             const Vec3d (&dq)[3], Surface& out);

// The error integral (87): int_0^1 int_0^1 f^2/|grad f|^2 (s(t, u)) du dt
// with u the angle / 2 pi on each circle of S (the whole circle), by
// Gauss-Legendre in t (nt nodes, 1..64) and the trapezoid rule in u (nu
// nodes, 4..1024; exact for trigonometric polynomials of degree < nu).
// singular_point if grad f = 0 at a node.
Status blend_error_87(const ImplicitBlend& B, const Surface& S, int nt, int nu, double& error);

}  // namespace v0
}  // namespace cyclide
