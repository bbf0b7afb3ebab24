// Dupin cyclides in Lie sphere geometry (seed 003 §3): the envelopes of the
// oriented spheres touching three given ones, as PE-subspaces A = R^{2,1}
// of R^{4,2}, with Algorithm 1's principal PN parameterization.
//
// A cyclide is stored as a Lie transformation theta with theta(A0) = A
// (Remark 3.12): A0 = span(e1, e2, e-), A0^perp = span(e3, e+, er), and the
// two sphere families are
//   a(xi)        = theta(2 xi0 xi1 e1 + (xi1^2 - xi0^2) e2 + (xi1^2 + xi0^2) e-)  (29)
//   a_perp(zeta) = theta(2 z0 z1 e3 + (z1^2 - z0^2) e+ + (z1^2 + z0^2) er)         (30)
// in homogeneous parameters xi = xi0 : xi1, zeta = z0 : z1 ((30) with the
// "+" ERRATA.md restores), so the spheres at xi = infinity are reachable.
// The surface point and its rational unit normal are (25)-(27) and
// (31)-(32) with ERRATA.md's signs:
//   c^ = (er . a) a_perp - (er . a_perp) a,     c = -c^_123 / (c^ . n_inf),
//   n^ = (n_inf . a) a_perp - (n_inf . a_perp) a,
//   n  =  n^_123 / (n^ . er),   lambda = n^_+ / (n^ . er),
// and the tangent plane at c is x . n = lambda; a touching sphere (m, rho)
// of either family has c - rho n = m.
//
// Local origin (SPEC §8h.3). A sphere (m, rho) has n_inf-type coordinates
// |m|^2 - rho^2 +- 1 in (4), so Lie vectors of spheres at distance D from
// the origin carry the scale that decodes them, (6), with an absolute error
// eps D^2: a cyclide built and stored in global coordinates loses about
// eps D^4 (a torus moved by 100: 9e-10; from D ~ 430 the Witt step failed
// with not_isometric). The same holds for the size L of the model in the
// unit length (the terms are L^2 / unit^2 against 1). theta is therefore
// stored in local coordinates (x - origin) / unit: the cyclide is theta's
// cyclide scaled by unit and translated by +origin. The builders pick the
// frame at the inputs (best_frame: an origin at their centres, a power of 2
// near their size), and every function below that returns points, planes
// or Lie spheres returns them globally.
#pragma once

#include "cyclide/circle_family.hpp"
#include "cyclide/lie.hpp"
#include "cyclide/status.hpp"

namespace cyclide {
inline namespace v0 {

// A point of the projective line: p0 : p1 (p1 = 0 is infinity).
struct HomogeneousParameter {
  double p0 = 0, p1 = 1;
};

// Laguerre classes, Lemma 3.10 / Thm. 3.11, named by the geometry of the
// sphere centers (the conics A R n L^4 seen from the hyperplane N (8) of
// planes). Note: the paper's text calls class II "quartic" and class III
// "parabolic"; by the centers it is the other way round (a torus, whose
// families have 0 and 2 planes, is class III), see SPEC.md §8h.
enum class DupinLaguerreType : int {
  degenerate = 1,  // I: n_inf in A or A^perp: a cone or cylinder of revolution
  parabolic = 2,   // II: D and D_perp = R^{1,1,0}, one plane per family (cubic)
  quartic = 3,     // III: D = R^2 and D_perp = R^{1,1} (or swapped): quartic
};

struct DupinCyclide {
  // theta's columns are theta(e1), theta(e2), theta(e3), theta(e+), theta(e-),
  // theta(er); A = span of columns 0, 1, 4; A^perp of 2, 3, 5.
  Matrix6d theta = Matrix6d::Identity();
  DupinLaguerreType type = DupinLaguerreType::quartic;
  // The cyclide is theta's cyclide scaled by unit and translated by
  // +origin: a world point x is x = unit * x_local + origin (theta, and the
  // vectors sphere_xi / sphere_zeta below, are in local coordinates). The
  // builders choose a power of 2 near the model's size as the unit, so that
  // theta stays balanced: a Lie scaling by L folded into theta puts ~L and
  // ~1/L into the same coordinates x_+- = a +- b, which keeps b only to
  // eps L^2 (10^-9 of the model at L = 2^12, nothing at 2^27).
  Vec3d origin = Vec3d::Zero();
  double unit = 1;

  // (29): the sphere a(xi) of the first family, in local coordinates.
  template <class S>
  Lie6<S> sphere_xi(const S& x0, const S& x1) const {
    return family(kE1, kE2, kEMinus, x0, x1);
  }
  // (30) corrected: the sphere a_perp(zeta) of the second family (local).
  template <class S>
  Lie6<S> sphere_zeta(const S& z0, const S& z1) const {
    return family(kE3, kEPlus, kER, z0, z1);
  }

 private:
  template <class S>
  Lie6<S> family(int i, int j, int k, const S& t0, const S& t1) const {
    const S two_t0t1 = S(2.0) * t0 * t1;
    const S diff = t1 * t1 - t0 * t0;
    const S sum = t1 * t1 + t0 * t0;
    Lie6<S> out;
    for (int r = 0; r < 6; ++r)
      out[r] = two_t0t1 * S(theta(r, i)) + diff * S(theta(r, j)) + sum * S(theta(r, k));
    return out;
  }
};

// The point sphere (23)/(25) and the tangent plane (31) of the touching
// spheres a and a_perp, generic in the scalar (double, Taylor).
template <class S>
Lie6<S> dupin_point_vector(const Lie6<S>& a, const Lie6<S>& a_perp) {
  return dot_e_r(a) * a_perp - dot_e_r(a_perp) * a;
}
template <class S>
Lie6<S> dupin_normal_vector(const Lie6<S>& a, const Lie6<S>& a_perp) {
  return dot_n_infinity(a) * a_perp - dot_n_infinity(a_perp) * a;
}
// (26)-(27): the Euclidean point of a point sphere c^ (c^ . n_inf != 0).
template <class S>
Vec3<S> euclidean_point(const Lie6<S>& c) {
  const S w = -dot_n_infinity(c);
  return {c[0] / w, c[1] / w, c[2] / w};
}

// ------------------------------------------------------------ construction

// The nearest power of 2 to x > 0 (1 for 0 or non-finite x): a frame's
// unit, so that scaling by it is exact.
inline double nearest_power_of_two(double x) {
  if (!(x > 0) || !std::isfinite(x)) return 1;
  return std::ldexp(1.0, int(std::lround(std::log2(x))));
}

// Case analysis of §3.1 for three Lie spheres (representatives, any scale):
// ok for a cyclide (A = R^{2,1}, i.e. (a1.a2)(a1.a3)(a2.a3) < 0);
// sphere_pencil (dim A = 2, Case I), no_touching_sphere (A = R^{1,2}),
// single_touching_sphere (A = R^{1,1,1}); not_on_lie_quadric for a
// non-neutral vector, invalid_argument for two equal spheres, not_finite.
// *span_signature (may be null) receives A's signature when dim A = 3. The
// case follows from the products a_i . a_j of the normalized inputs (a
// product within 64 eps of its terms counts as zero), not from eigenvalues
// on a Euclidean-orthonormal basis, which shrink like 1/|m|^4 for spheres
// far from the origin.
Status classify_sphere_triple(const Lie6d (&a)[3], Signature* span_signature = nullptr);
// The §3.1 case of three Lie spheres, read exactly as dupin_from_spheres
// reads it (in the spheres' best frame), so that the two always agree.
Status classify_spheres(const LieSphere (&s)[3], Signature* span_signature = nullptr);

// Algorithm 1 (corrected) through the reference pair (28) and a Lie
// transformation theta found by Witt's extension theorem: theta maps
// a0(0), a0(inf), a0(1) to multiples of a1, a2, a3, so the inputs are the
// spheres a(0), a(infinity) and a(1) of the first family (theta is unique up
// to its action on A^perp, which fixes zeta only up to a Mobius map).
// Statuses of classify_sphere_triple, degenerate_cyclide (every sphere of a
// family is a point: A or A^perp in B (5)), not_isometric / numerical_overflow
// from the extension. `out` is written only on success.
//
// Origins. dupin_from_spheres translates the inputs by -origin at the
// geometric level (centres and points minus origin, a plane's lambda minus
// n . origin) before forming (4)/(7), origin = the mean of the finite
// centres and points (0 if all inputs are planes or the point at infinity):
// the build is as accurate as one near the origin (|error| ~ eps (1 + D)).
// dupin_from_vectors decodes its vectors to Lie spheres first (lie_sphere,
// whose weight x . n_inf is read robustly by lie_sphere_weight), so that a
// sphere's centre and radius come back with relative error ~eps, not eps D^2,
// and then proceeds as dupin_from_spheres; so vectors made by (4) from
// global spheres give the same accuracy as the spheres themselves.
Status dupin_from_spheres(const LieSphere (&s)[3], DupinCyclide& out);
Status dupin_from_vectors(const Lie6d (&a)[3], DupinCyclide& out);
// Algorithm 1 on vectors already in the frame theta is to be stored in:
// origin = 0, no decoding (Algorithm 2 builds its pieces in one local frame
// and sets their origin afterwards). Statuses as dupin_from_vectors.
Status dupin_from_local_vectors(const Lie6d (&a)[3], DupinCyclide& out);


// A cyclide from any spanning set of a PE-subspace A (k >= 3 vectors, rank
// 3, signature (2, 0, 1); e.g. R + S of two cones, §4): theta from an
// orthonormal basis of A and of A^perp. not_isometric if the span is not a
// PE-subspace (with its signature in *sig, may be null). origin = the mean
// of the centres of the spanning vectors that are spheres or points (read
// by lie_sphere); all vectors are moved there by the Lie translation by
// -origin. That keeps their rounding (the n_inf-type coordinates of a
// vector at distance D carry eps D^2, which the translation cannot remove),
// so far from the origin this builder is not more accurate than before;
// it only stores theta at the inputs' centre (SPEC §8h.11).
Status dupin_from_subspace(const Lie6d* span, int k, DupinCyclide& out,
                           Signature* sig = nullptr);

// The same cyclide with the families exchanged (Cor. 3.6: A and A^perp
// determine the same surface): theta composed with e1<->e3, e2<->e+, e-<->er;
// the origin is kept.
DupinCyclide swap_families(const DupinCyclide& D);

// Lemma 3.10 / Thm. 3.11 from theta (also stored in D.type at construction).
DupinLaguerreType dupin_laguerre_type(const DupinCyclide& D);

// ------------------------------------------------------------ evaluation

// c(xi, zeta) with its rational unit normal n and the tangent plane x . n =
// lambda; the offset point c + d n and its partials with respect to the
// affine parameters xi, zeta (d = 0: the cyclide itself). Offsets of a
// Dupin cyclide are Dupin cyclides (the Laguerre dilatation by d maps A to
// the offset's PE-subspace).
struct DupinPoint {
  Vec3d point = Vec3d::Zero();   // c + d n
  Vec3d normal = Vec3d::Zero();  // n, unit
  double lambda = 0;             // tangent plane x . n = lambda (of c)
  Vec3d d_xi = Vec3d::Zero(), d_zeta = Vec3d::Zero();
};

// Global coordinates: unit point + origin, unit lambda + n . origin, the
// partials times unit (the normal is invariant). Affine parameters (both finite). point_at_infinity when c^ . n_inf
// vanishes relative to |c^| (kDupinInfinityTol), not_finite for NaN/Inf
// input, numerical_overflow if an output is not finite.
constexpr double kDupinInfinityTol = 1e-13;
Status dupin_eval(const DupinCyclide& D, double xi, double zeta, double offset,
                  DupinPoint& out);
// Homogeneous parameters (either may be infinity); point, normal, lambda
// only (the partials are left zero).
Status dupin_eval_homogeneous(const DupinCyclide& D, HomogeneousParameter xi,
                              HomogeneousParameter zeta, double offset, DupinPoint& out);

// The spheres of the two families as global Lie spheres (a(xi) may be a
// plane or a point; unit centre + origin, unit radius, plane unit lambda +
// n . origin).
Status dupin_sphere_xi(const DupinCyclide& D, HomogeneousParameter xi, LieSphere& out);
Status dupin_sphere_zeta(const DupinCyclide& D, HomogeneousParameter zeta, LieSphere& out);

// The offset cyclide at distance d: theta composed with the Laguerre
// dilatation rho -> rho + d / unit in the local frame (its points are c + d
// n); origin and unit are kept (translations and dilatations commute).
DupinCyclide dupin_offset(const DupinCyclide& D, double d);

// ------------------------------------------- the circle-family view

// The cyclide as a circle-family surface (surface.hpp): u runs through the
// first family's parameter, xi = (xm[0] u + xm[1]) / (xm[2] u + xm[3]), and
// the circle at u is the zeta-line c(xi(u), .) (the characteristic circle of
// a(xi)), with v mapped to zeta = (zm[0] v + zm[1]) / (zm[2] v + zm[3]). So
// Surface::eval(u, v) = c(xi(u), zeta(v)). Its frame: the generator p =
// c(xi, zeta = inf), the circle's center and axis through c(xi, 0) and
// c(xi, 1), and f(zeta) = a . (d x e) / (R^2 - d . e) at zeta = 0, 1 (the
// rotation parameter of eq. (11) is a Mobius function of zeta, affine
// because zeta = inf is the generator).
struct DupinView {
  DupinCyclide cyclide;
  double xi_map[4] = {1, 0, 0, 1};
  double zeta_map[4] = {1, 0, 0, 1};
};

namespace detail {
template <class S>
double value_of(const S& s) {
  return s.c[0];
}
inline double value_of(double s) { return s; }
}  // namespace detail

// The frame of the view at u, generic in the scalar (Taylor series in u).
template <class S>
Status dupin_frame(const DupinView& V, const S& u, CircleFrame<S>& F) {
  using detail::value_of;
  const S x0 = S(V.xi_map[0]) * u + S(V.xi_map[1]);
  const S x1 = S(V.xi_map[2]) * u + S(V.xi_map[3]);
  const Lie6<S> a = V.cyclide.sphere_xi(x0, x1);
  // The points at zeta = inf (the generator), 0 and 1.
  const double zs[3][2] = {{1, 0}, {0, 1}, {1, 1}};
  Vec3<S> X[3];
  for (int i = 0; i < 3; ++i) {
    const Lie6<S> b = V.cyclide.sphere_zeta(S(zs[i][0]), S(zs[i][1]));
    const Lie6<S> c = dupin_point_vector(a, b);
    double scale = 0;
    for (int r = 0; r < 6; ++r) scale = std::max(scale, std::abs(value_of(c[r])));
    if (!(std::abs(value_of(dot_n_infinity(c))) > kDupinInfinityTol * scale))
      return Status::point_at_infinity;
    X[i] = euclidean_point(c);
  }
  // Circumcenter o of X0, X1, X2 and the axis a = (X1 - X0) x (X2 - X0),
  // in local coordinates (the origin is added to o and p at the end).
  const Vec3<S> e1 = X[1] - X[0], e2 = X[2] - X[0];
  const Vec3<S> axis = e1.cross(e2);
  const S aa = axis.dot(axis);
  const double size = std::max(value_of(e1.dot(e1)), value_of(e2.dot(e2)));
  if (!(value_of(aa) > 1e-24 * size * size)) return Status::singular_point;
  const Vec3<S> o =
      X[0] + (e1.dot(e1) * e2.cross(axis) + e2.dot(e2) * axis.cross(e1)) / (S(2.0) * aa);
  // f at zeta = 0 and 1. Eq. (11) turns d = p - o by theta about the axis
  // with tan(theta/2) = |a| / f, so f = |a| cot(theta/2) = |a| sin(theta) /
  // (1 - cos(theta)) = a . (d x e) / (R^2 - d . e) for e = X - o: regular
  // everywhere except at the generator itself (zeta = inf), unlike the
  // (1 + cos) / sin form, which is 0/0 at the antipode.
  const Vec3<S> d = X[0] - o;
  const S R2 = d.dot(d);
  S f[2];
  for (int i = 0; i < 2; ++i) {
    const Vec3<S> e = X[i + 1] - o;
    const S den = R2 - d.dot(e);
    if (!(std::abs(value_of(den)) > 1e-14 * value_of(R2)))
      return Status::degenerate_circle_parameter;
    f[i] = axis.dot(d.cross(e)) / den;
  }
  // f(zeta) = alpha_f zeta + beta_f, zeta = (P v + Q) / (R v + T).
  // World coordinates: x = unit x_local + origin. The axis is a product of
  // two chords (unit^2) and so is f (R^2 - d . e is, and a . (d x e) is
  // unit^4): tan(theta / 2) = |a| / f keeps its value.
  const Vec3d& g = V.cyclide.origin;
  const S unit(V.cyclide.unit), unit2(V.cyclide.unit * V.cyclide.unit);
  const S alpha_f = unit2 * (f[1] - f[0]), beta_f = unit2 * f[0];
  const double* zm = V.zeta_map;
  F.o = unit * o + Vec3<S>(S(g[0]), S(g[1]), S(g[2]));
  F.a = unit2 * axis;
  F.p = unit * X[0] + Vec3<S>(S(g[0]), S(g[1]), S(g[2]));
  F.alpha = alpha_f * S(zm[0]) + beta_f * S(zm[2]);
  F.beta = alpha_f * S(zm[1]) + beta_f * S(zm[3]);
  F.gamma = S(zm[2]);
  F.delta = S(zm[3]);
  // x is invariant under q -> k q: scale f's coefficients to max 1.
  const double m = std::max(std::max(std::abs(value_of(F.alpha)), std::abs(value_of(F.beta))),
                            std::max(std::abs(value_of(F.gamma)), std::abs(value_of(F.delta))));
  if (!(m > 0) || !std::isfinite(m)) return Status::degenerate_circle_parameter;
  const S inv(1.0 / m);
  F.alpha *= inv;
  F.beta *= inv;
  F.gamma *= inv;
  F.delta *= inv;
  return Status::ok;
}

}  // namespace v0
}  // namespace cyclide
