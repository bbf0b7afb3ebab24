// Blends of seed 000 §9 and the tools to verify them (SPEC.md "Blends"):
// exact u-derivatives of surface points (§9.1 (i)), canal blends (§9.1,
// PRCS of two C^K Hermite curves, G^(K-1) by Prop. 6), ringed blends (§9.2,
// PRRS of three C^K Hermite curves, C^K by Prop. 7), and a continuity report
// of a join between two surfaces along a common circle. Allocation-free.
#pragma once

#include <type_traits>

#include "cyclide/hermite.hpp"
#include "cyclide/surface.hpp"

namespace cyclide {
inline namespace v0 {

// Largest derivative order of derivatives_u and of blends (the Hermite
// curves have degree 2K+1 <= kMaxCurveDegree).
constexpr int kMaxBlendOrder = kMaxHermiteOrder;  // 7

namespace detail {

// Calls fn(std::integral_constant<int, N>()) for N = K and returns its
// status if 0 <= K <= kMaxBlendOrder; Status::degree_too_high (fn not
// called) for any other K.
template <class Fn>
inline Status with_order(int K, Fn&& fn) {
  switch (K) {
    case 0: return fn(std::integral_constant<int, 0>());
    case 1: return fn(std::integral_constant<int, 1>());
    case 2: return fn(std::integral_constant<int, 2>());
    case 3: return fn(std::integral_constant<int, 3>());
    case 4: return fn(std::integral_constant<int, 4>());
    case 5: return fn(std::integral_constant<int, 5>());
    case 6: return fn(std::integral_constant<int, 6>());
    case 7: return fn(std::integral_constant<int, 7>());
    default: return Status::degree_too_high;
  }
}
static_assert(kMaxBlendOrder == 7, "with_order covers 0..7");

}  // namespace detail

// out[l] = d^l x / du^l (u, v), l = 0..K (K <= kMaxBlendOrder), from the frame
// as Taylor series of order K pushed through the rotation formula (no finite
// differences). v may be any finite double or +-infinity (the generator).
// On error nothing is written.
Status derivatives_u(const Surface& S, double u, double v, int K, Vec3d* out);

// A series of doubles as a series of T (e.g. a Ceres Jet: constants).
template <class T, int N>
Taylor<T, N> lift(const Taylor<double, N>& a) {
  Taylor<T, N> r;
  for (int k = 0; k <= N; ++k) r.c[k] = T(a.c[k]);
  return r;
}

// x(u, v) as a u-series of order N, from the circle frame F at u (series
// of order N) and the circle parameter v = s1 / s0 given homogeneously
// (eqs. (11)/(27) expanded as in evaluator.hpp, on series):
//   W = alpha s1 + beta s0,  G = gamma s1 + delta s0,  d = p - o,
//   x = o + ((W^2 - G^2 |a|^2) d + 2 G^2 (a.d) a + 2 W G a x d)
//           / (W^2 + G^2 |a|^2).
// Generic in the scalar T of (s1, s0): derivatives_u uses doubles, the
// blend optimizer Jets when the chosen points move along their circles.
// False (x untouched) where W^2 + G^2 |a|^2 vanishes.
template <class T, int N>
bool point_series(const CircleFrame<Taylor<double, N>>& F, const T& s1, const T& s0,
                  Vec3<Taylor<T, N>>& x) {
  using D = Taylor<double, N>;
  using S = Taylor<T, N>;
  const Vec3<D> d = F.p - F.o;
  const D aa = F.a.dot(F.a), ad = F.a.dot(d);
  const Vec3<D> axd = F.a.cross(d);
  const S W = lift<T>(F.alpha) * S(s1) + lift<T>(F.beta) * S(s0);
  const S G = lift<T>(F.gamma) * S(s1) + lift<T>(F.delta) * S(s0);
  const S W2 = W * W, G2 = G * G, two(2.0), aaT = lift<T>(aa);
  const S den = W2 + G2 * aaT;
  if (!(value_of(den.c[0]) > 0)) return false;
  const S cd = W2 - G2 * aaT, ca = two * G2 * lift<T>(ad), cx = two * W * G;
  for (int j = 0; j < 3; ++j)
    x[j] = lift<T>(F.o[j]) +
           (cd * lift<T>(d[j]) + ca * lift<T>(F.a[j]) + cx * lift<T>(axd[j])) / den;
  return true;
}

// One end of a blend: the end circle u of `surface`, the circle parameters
// of the chosen points P_j = x(u, v[j]) (2 for canal, 3 for ringed blends),
// and the chain-rule factor lambda = du/dt of the input per unit of the
// blend parameter t: the blend's curves satisfy
//   p_j^(l)(t_end) = lambda^l d^l x / du^l (u, v[j]),  l = 0..K.
// lambda's sign is the direction: the blend must continue the first surface
// (lambda > 0 if u is its domain's upper end) and lead into the second
// (lambda > 0 if u is its domain's lower end). lambda = 0 chooses +-1 that way
// (by the nearer end of the domain).
//
// The free Hermite scalars of the end are the derivatives of a
// reparameterization u = phi(t) of the input at its end circle:
// phi' = lambda (the tangent length) and phi'', phi''', ... = phi[0],
// phi[1], ... (0 by default). The curves then take the derivatives of
// x(phi(t), v) (Faa di Bruno), so every choice keeps the join geometrically
// C^K (G^K: the blend meets the input up to a reparameterization) while it
// changes the blend's shape; independent scale factors per order would not.
struct BlendEnd {
  const Surface* surface = nullptr;
  double u = 0.0;
  double v[3] = {0.0, 0.0, 0.0};
  double lambda = 0.0;
  double phi[kMaxBlendOrder - 1] = {};
};

// d^l/dt^l x(phi(t)), l = 0..K, from dx[k] = d^k x/du^k (k = 0..K) and
// jet[m - 1] = phi^(m) (m = 1..K) at the end (Faa di Bruno, as the
// composition of truncated series). Generic in the scalar of the jet
// (double, or a Ceres Jet when the optimizer differentiates a blend with
// respect to its free scalars).
// The series of phi(t) - phi(t_end) of order N from jet[m - 1] = phi^(m),
// m = 1..K (K <= N): c[m] = phi^(m)/m!.
template <int N, class S>
Taylor<S, N> reparameterization_series(const S* jet, int K) {
  Taylor<S, N> h;
  double fact = 1.0;
  for (int m = 1; m <= K; ++m) {
    fact *= m;
    h.c[m] = jet[m - 1] / S(fact);
  }
  return h;
}

// The series are truncated at order N (K <= N; the result is the same for
// every N >= K): the optimizer calls it with N = K.
// The derivatives dx may be doubles or of the jet's scalar (the optimizer's
// moving points).
template <int N, class D, class S>
void reparameterize_to(int K, const Vec3<D>* dx, const S* jet, Vec3<S>* out) {
  const Taylor<S, N> h = reparameterization_series<N>(jet, K);
  for (int j = 0; j < 3; ++j) {
    Taylor<D, N> f;
    double fact = 1.0;
    for (int k = 0; k <= K; ++k) {
      if (k > 0) fact *= k;
      f.c[k] = dx[k][j] / fact;
    }
    const Taylor<S, N> r = compose(f, h);
    fact = 1.0;
    for (int l = 0; l <= K; ++l) {
      if (l > 0) fact *= l;
      out[l][j] = S(fact) * r.c[l];
    }
  }
}

template <class D, class S>
void reparameterize(int K, const Vec3<D>* dx, const S* jet, Vec3<S>* out) {
  reparameterize_to<kMaxBlendOrder>(K, dx, jet, out);
}

// The jet (phi', phi'', ..., phi^(K)) of end `e` (index as blend_lambda).
void blend_jet(const BlendEnd& e, int index, int K, double* jet);

// The lambda used for end `e` (index 0: the blend's start, 1: its end).
double blend_lambda(const BlendEnd& e, int index);

// Canal blend (§9.1): K >= 2 (Prop. 6), Hermite curves of degree 2K+1 on
// [t0, t1] through P_1j -> P_2j (j = 1, 2), then make_prcs. Statuses of
// make_prcs are passed on with *bad_u (e.g. dependent_planes where the normal
// planes M, N are (nearly) parallel, the weakness the paper names).
// `curves` (may be null) receives the two Hermite curves.
Status make_canal_blend(const BlendEnd& start, const BlendEnd& end, int K, double t0,
                        double t1, Surface& out, double* bad_u = nullptr,
                        RationalCurve* curves = nullptr);
// How a ringed blend parameterizes its circles.
//  generator: f = v (the paper's PRRS): the generator p1 (the points v[0]
//    of the ends) at v = infinity. The blend is C^K to the inputs in the
//    circle family and at the generator point; elsewhere the circles'
//    parameterizations differ from the inputs' (G^K, not C^K, for v != v[0]).
//  matched: f(t, v) = (alpha(t) v + beta(t)) / (gamma(t) v + delta(t)) with
//    alpha..delta of degree 2K+1 Hermite-interpolating, at each end, the
//    jet of the Mobius map that carries the input's circle parameter to the
//    blend's (fixed by the three points v[0..2]). Then for every v the
//    curve t -> x(t, v) continues the input's u -> x(phi(u), v) to order K:
//    the parameterizations join C^K (Prop. 7 with the inputs' own f), as
//    tensor-product export and texture coordinates need. The geometry is the
//    same surface as with `generator`. When the two inputs run their circles
//    in opposite senses along the blend (the two maps have determinants of
//    opposite sign) no Mobius family joins them without degenerating:
//    degenerate_circle_parameter (reparameterize one input by v -> -v).
enum class BlendCircles { generator = 0, matched = 1 };

// Ringed blend (§9.2): K >= 1, three Hermite curves, then make_prrs with the
// circle parameterization `circles` (f = v by default).
Status make_ringed_blend(const BlendEnd& start, const BlendEnd& end, int K, double t0,
                         double t1, Surface& out, double* bad_u = nullptr,
                         RationalCurve* curves = nullptr,
                         BlendCircles circles = BlendCircles::generator);

// Piecewise blends (issue 4 item 2: spline curves where one piece is not
// enough): ends[0], ..., ends[n-1] (2 <= n <= kMaxSplineKnots) are circles
// the blend passes through in this order, the interior ones on guide
// surfaces; piece i runs on [knots[i], knots[i+1]] from ends[i] to
// ends[i+1]. The curves are C^K Hermite splines (make_hermite_spline: both
// pieces at an interior knot take that end's data with its jet), so
// consecutive pieces share their circle and join C^K in the circle family
// (ringed; canal: G^(K-1)), and each piece is G^K to the guide surface.
// Interior ends need an explicit lambda (!= 0: the direction along the
// guide); the first and last follow blend_lambda. *pieces[0 .. n-2] (each
// pointer non-null; e.g. the surfaces of C handles) are written only on
// success; on failure *bad_piece (may be null) names the piece and *bad_u
// its parameter.
Status make_canal_blend_spline(const BlendEnd* ends, int n, int K, const double* knots,
                               Surface* const* pieces, int* bad_piece = nullptr,
                               double* bad_u = nullptr);
Status make_ringed_blend_spline(const BlendEnd* ends, int n, int K, const double* knots,
                                Surface* const* pieces, int* bad_piece = nullptr,
                                double* bad_u = nullptr,
                                BlendCircles circles = BlendCircles::generator);

// The join of surface A at u = uA and surface B at u = uB along a common
// circle, at sample points x_A(uA, vA[i]); the corresponding point of B is
// the closest point of B's circle (vB = B.parameter_of). lambda is the
// chain-rule factor du_A/du_B: B's u-derivatives are compared with
// lambda^l times A's (the jet overload: with the derivatives of
// x_A(phi(u_B)), jet = phi', ..., phi^(K) as for BlendEnd).
struct ContinuityReport {
  int K = 0;                 // derivative orders compared: 0..K
  int samples = 0;
  int singular_samples = 0;  // samples where a normal is undefined (skipped)
  double max_gap = 0;        // max |x_A - x_B| at corresponding points
  double point_scale = 0;    // max |x_A|, circle radius (for relative gaps)
  double max_normal_angle = 0;  // radians in [0, pi/2]: angle between tangent planes
  // Parameterization jumps: max |d^l x_B/du^l - lambda^l d^l x_A/du^l| at
  // corresponding points, and the largest of the two norms (relative: the
  // quotient). Zero (C^K in the usual sense) only where the circle
  // parameterizations of A and B agree to order K, e.g. at a blend's
  // generator point.
  double point_jump[kMaxBlendOrder + 1] = {};
  double point_scale_l[kMaxBlendOrder + 1] = {};
  // Circle-family jumps: the l-th u-derivatives of the circle's center,
  // unit plane normal (oriented like A's) and radius^2, relative to their
  // magnitudes (center: |c| + radius, normal: 1, radius^2: radius^2), the
  // largest of the three. Zero to order k means the surfaces join C^k up to
  // a reparameterization of the circles (geometric C^k, Prop. 7).
  double circle_jump[kMaxBlendOrder + 1] = {};
};

// vA: n >= 1 sample parameters on A's circle (null: n parameters
// v = tan(pi (i + 1/2)/n - pi/2), which cover the whole circle). K <= kMaxBlendOrder.
Status continuity_report(const Surface& A, double uA, double lambda, const Surface& B,
                         double uB, int K, const double* vA, int n, ContinuityReport& out);
Status continuity_report(const Surface& A, double uA, const double* jet, const Surface& B,
                         double uB, int K, const double* vA, int n, ContinuityReport& out);

}  // namespace v0
}  // namespace cyclide
