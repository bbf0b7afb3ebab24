#include "cyclide/blend.hpp"

#include <cmath>
#include <type_traits>
#include <utility>

namespace cyclide {
inline namespace v0 {

namespace {

bool finite3(const Vec3d& x) {
  return std::isfinite(x.x()) && std::isfinite(x.y()) && std::isfinite(x.z());
}

// x(u, v) as a u-series of order N (blend.hpp's point_series on the frame
// at u). (s1, s0) = (v, 1) for |v| <= 1, (1, 1/v) else.
template <int N>
Status point_series(const Surface& S, double u, double v, Vec3<Taylor<double, N>>& x) {
  CircleFrame<Taylor<double, N>> F;
  if (Status st = S.frame<N>(u, F); st != Status::ok) return st;
  const bool small = std::abs(v) <= 1.0;
  if (!point_series(F, small ? v : 1.0, small ? 1.0 : 1.0 / v, x))
    return Status::degenerate_circle_parameter;
  return Status::ok;
}

// Circle geometry as u-series: center, unit normal, radius^2.
template <int N>
Status circle_series(const Surface& S, double u, Vec3<Taylor<double, N>>& c,
                     Vec3<Taylor<double, N>>& n, Taylor<double, N>& r2) {
  using T = Taylor<double, N>;
  CircleFrame<T> F;
  if (Status st = S.frame<N>(u, F); st != Status::ok) return st;
  const CircleGeometry<T> G = circle_geometry(F);
  const T len = sqrt(F.a.dot(F.a));
  c = G.center;
  for (int j = 0; j < 3; ++j) n[j] = F.a[j] / len;
  r2 = G.radius2;
  return Status::ok;
}

// l-th derivative of a series (0 <= l <= N; written without
// Taylor::derivative, whose bounds GCC cannot see through the dispatch).
template <int N>
double deriv(const Taylor<double, N>& t, int l) {
  double f = 1.0, r = 0.0;
  for (int k = 0; k <= N; ++k) {
    if (k > 1) f *= double(k);
    if (k == l) r = f * t.c[k];
  }
  return r;
}

template <int N>
Vec3d coeff(const Vec3<Taylor<double, N>>& x, int l) {
  return Vec3d(deriv(x[0], l), deriv(x[1], l), deriv(x[2], l));
}

}  // namespace

Status derivatives_u(const Surface& S, double u, double v, int K, Vec3d* out) {
  if (!out) return Status::null_argument;
  if (K < 0) return Status::invalid_argument;
  if (K > kMaxBlendOrder) return Status::degree_too_high;
  if (!input_ok(u) || std::isnan(v)) return Status::not_finite;
  Vec3d tmp[kMaxBlendOrder + 1];
  const Status st = detail::with_order(K, [&](auto n) -> Status {
    constexpr int N = decltype(n)::value;
    Vec3<Taylor<double, N>> x;
    if (Status s = point_series<N>(S, u, v, x); s != Status::ok) return s;
    for (int l = 0; l <= N; ++l) {
      tmp[l] = coeff(x, l);
      if (!finite3(tmp[l])) return Status::numerical_overflow;
    }
    return Status::ok;
  });
  if (st != Status::ok) return st;
  for (int l = 0; l <= K; ++l) out[l] = tmp[l];
  return Status::ok;
}

double blend_lambda(const BlendEnd& e, int index) {
  if (e.lambda != 0.0 || !e.surface) return e.lambda;
  const double to_upper = std::abs(e.surface->u1 - e.u), to_lower = std::abs(e.u - e.surface->u0);
  // Start: continue the surface (forward if u is its upper end); end: lead
  // into it (forward if u is its lower end).
  if (index == 0) return to_upper <= to_lower ? 1.0 : -1.0;
  return to_lower <= to_upper ? 1.0 : -1.0;
}

void blend_jet(const BlendEnd& e, int index, int K, double* jet) {
  if (K < 1) return;
  jet[0] = blend_lambda(e, index);
  for (int m = 2; m <= K; ++m) jet[m - 1] = e.phi[m - 2];
}

namespace {

Status blend_curves(const BlendEnd& start, const BlendEnd& end, int K, double t0, double t1,
                    int count, RationalCurve* curves) {
  if (!start.surface || !end.surface) return Status::null_argument;
  if (K > kMaxBlendOrder) return Status::degree_too_high;
  if (!input_ok(start.u) || !input_ok(end.u) || !input_ok(t0) || !input_ok(t1) ||
      !input_ok(start.lambda) || !input_ok(end.lambda))
    return Status::not_finite;
  for (int m = 2; m <= K; ++m)
    if (!input_ok(start.phi[m - 2]) || !input_ok(end.phi[m - 2])) return Status::not_finite;
  if (!(t1 > t0)) return Status::bad_domain;
  for (int j = 0; j < count; ++j)
    if (std::isnan(start.v[j]) || std::isnan(end.v[j])) return Status::not_finite;
  const BlendEnd* ends[2] = {&start, &end};
  Vec3d d[2][3][kMaxBlendOrder + 1];
  for (int e = 0; e < 2; ++e) {
    double jet[kMaxBlendOrder];
    blend_jet(*ends[e], e, K, jet);
    for (int j = 0; j < count; ++j) {
      Vec3d dx[kMaxBlendOrder + 1];
      if (Status st = derivatives_u(*ends[e]->surface, ends[e]->u, ends[e]->v[j], K, dx);
          st != Status::ok)
        return st;
      reparameterize(K, dx, jet, d[e][j]);
      // lambda^l x^(l) beyond the input range of the Hermite solve (e.g.
      // lambda = 1e60, K = 2): an overflow, not a non-finite input (fuzz_blend
      // regress-blend-huge-lambda).
      for (int l = 1; l <= K; ++l)
        if (!input_ok(d[e][j][l])) return Status::numerical_overflow;
    }
  }
  for (int j = 0; j < count; ++j)
    if (Status st = make_hermite_curve(K, t0, t1, d[0][j], d[1][j], curves[j]); st != Status::ok)
      return st == Status::not_finite ? Status::numerical_overflow : st;
  return Status::ok;
}

}  // namespace

Status make_canal_blend(const BlendEnd& start, const BlendEnd& end, int K, double t0,
                        double t1, Surface& out, double* bad_u, RationalCurve* curves) {
  if (K < 2) return Status::invalid_argument;  // Prop. 6: K > 1
  RationalCurve p[2];
  if (Status st = blend_curves(start, end, K, t0, t1, 2, p); st != Status::ok) return st;
  Surface S;
  // Inputs are validated above: a non-finite value from here on is an
  // overflow of the construction (e.g. t1 = 2^192: power-form Hermite
  // coefficients beyond 1e100), not a non-finite input.
  if (Status st = make_prcs(p[0], p[1], nullptr, t0, t1, S, bad_u); st != Status::ok)
    return st == Status::not_finite ? Status::numerical_overflow : st;
  out = S;
  if (curves)
    for (int j = 0; j < 2; ++j) curves[j] = p[j];
  return Status::ok;
}

namespace {

// The circle parameter of a point X of the circle of frame F (f = v), as
// the homogeneous pair [W : G] of the quaternion q = W + G a that rotates
// the generator p to X (eq. (13): W / G = |a| cot(theta / 2)). With d, e the
// generator and X relative to o, projected on the circle's plane, and rho
// the radius (|e| = rho: X lies on the circle),
//   rho^2 cos theta = d.e,   |a| rho^2 sin theta = a.(d x e),
// and cot(theta/2) = (1 + cos theta)/sin theta = sin theta/(1 - cos theta):
//   [W : G] = [|a|^2 (rho^2 + d.e) : a.(d x e)] = [a.(d x e) : rho^2 - d.e],
// rational in the frame, so it carries series. The first form is used on
// the generator's half of the circle (d.e >= 0), the second on the other
// half, so that neither is 0/0.
template <int N>
void circle_parameter(const CircleFrame<Taylor<double, N>>& F,
                      const Vec3<Taylor<double, N>>& X, Taylor<double, N> (&wg)[2]) {
  using T = Taylor<double, N>;
  const T aa = F.a.dot(F.a);
  const Vec3<T> d0 = F.p - F.o, e0 = X - F.o;
  const Vec3<T> d = d0 - (F.a.dot(d0) / aa) * F.a;
  const Vec3<T> e = e0 - (F.a.dot(e0) / aa) * F.a;
  const T rho2 = d.dot(d), de = d.dot(e), sine = F.a.dot(d.cross(e));
  if (de.c[0] >= 0) {
    wg[0] = aa * (rho2 + de);
    wg[1] = sine;
  } else {
    wg[0] = sine;
    wg[1] = rho2 - de;
  }
}

// The Mobius matrix M = [[a, b], [c, d]] (x -> (a x + b) / (c x + d) on
// homogeneous x) that takes the points z[0], z[1], z[2] to 0, infinity, 1:
// its rows vanish on z[0] and z[1], scaled so that z[2] goes to 1.
template <class T>
void to_zero_infinity_one(const T (&z)[3][2], T (&M)[2][2]) {
  const T k0 = z[1][1] * z[2][0] - z[1][0] * z[2][1];
  const T k1 = z[0][1] * z[2][0] - z[0][0] * z[2][1];
  M[0][0] = k0 * z[0][1];
  M[0][1] = -(k0 * z[0][0]);
  M[1][0] = k1 * z[1][1];
  M[1][1] = -(k1 * z[1][0]);
}

// The jet at t = te (end `index` of the blend S, built with f = v from the
// curves p) of the Mobius map m(t) that carries the input's circle
// parameter v to the blend's: m(v_j) = w_j(t), j = 0..2, where v_j = e.v[j]
// and w_j(t) is the blend's parameter of p_j(t), which continues
// x(phi(t), v_j) to order K (blend_curves). Both parameterize the same
// circle to order K, so m(t, v) matches them for every v, not only the
// three. m = M_w^-1 M_v with M_z the map taking the z_j to 0, infinity, 1
// (M_w^-1 as the adjugate: homogeneous, no division).
// jet[k][l] = l-th t-derivative of alpha, beta, gamma, delta (k = 0..3).
template <int N>
Status end_mobius(const RationalCurve* p, const BlendEnd& e, double te,
                  double (&jet)[4][kMaxBlendOrder + 1]) {
  using T = Taylor<double, N>;
  CircleFrame<T> F;  // the blend's frame with f = v, straight from its curves
  if (Status st = prrs_frame<N>(p[0], p[1], p[2], te, F); st != Status::ok) return st;
  T w[3][2], v[3][2];
  for (int j = 0; j < 3; ++j) {
    circle_parameter<N>(F, p[j].taylor<N>(te), w[j]);
    // [W : G] is homogeneous of degree up to 6 in the model's size (|a|^2
    // rho^2 with a = (p1 - p2) x (p1 - p3)), and M_w^-1 M_v multiplies
    // four such pairs: a blend scaled by 2^-30 underflowed to det = 0. One
    // constant factor per pair (the same point, the same derivatives).
    const double big = std::max(std::abs(w[j][0].c[0]), std::abs(w[j][1].c[0]));
    if (big > 0 && std::isfinite(1.0 / big)) {
      const T inv(1.0 / big);
      w[j][0] *= inv;
      w[j][1] *= inv;
    }
    // v_j as the homogeneous constant (v, 1), or (1, 1/v) for |v| > 1
    // (v = +-infinity is the input's generator).
    const bool small = std::abs(e.v[j]) <= 1.0;
    v[j][0] = T(small ? e.v[j] : 1.0);
    v[j][1] = T(small ? 1.0 : 1.0 / e.v[j]);
  }
  T Mw[2][2], Mv[2][2];
  to_zero_infinity_one(w, Mw);
  to_zero_infinity_one(v, Mv);
  const T adj[2][2] = {{Mw[1][1], -Mw[0][1]}, {-Mw[1][0], Mw[0][0]}};
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 2; ++c) {
      const T m = adj[r][0] * Mv[0][c] + adj[r][1] * Mv[1][c];
      for (int l = 0; l <= kMaxBlendOrder; ++l) jet[2 * r + c][l] = l <= N ? deriv(m, l) : 0.0;
    }
  return Status::ok;
}

// f(t, v) of a matched ringed blend (BlendCircles::matched): the end jets of
// m, each scaled to |det| = 1 at its end (m is homogeneous) with signs that
// make the two end matrices point the same way, Hermite-interpolated
// coefficient by coefficient (degree 2K+1, power form for Mobius). The
// determinant's sign is the sense in which the input runs its circles
// relative to the blend: a continuous family of Mobius maps cannot change
// it, so different signs are degenerate_circle_parameter (at t1). Whether
// the interpolant stays regular inside is checked by make_prrs' domain scan.
Status matched_circles(const RationalCurve* p, const BlendEnd& start,
                       const BlendEnd& end, int K, double t0, double t1, Mobius& f,
                       double* bad_u) {
  const BlendEnd* ends[2] = {&start, &end};
  const double te[2] = {t0, t1};
  double jet[2][4][kMaxBlendOrder + 1];
  double det[2];
  for (int e = 0; e < 2; ++e) {
    const Status st = detail::with_order(K, [&](auto n) -> Status {
      return end_mobius<decltype(n)::value>(p, *ends[e], te[e], jet[e]);
    });
    if (st != Status::ok) {
      if (bad_u) *bad_u = te[e];
      return st;
    }
    det[e] = jet[e][0][0] * jet[e][3][0] - jet[e][1][0] * jet[e][2][0];
    if (!std::isfinite(det[e]) || !(std::abs(det[e]) > 0)) {
      if (bad_u) *bad_u = te[e];
      return Status::degenerate_circle_parameter;
    }
  }
  if ((det[0] > 0) != (det[1] > 0)) {
    if (bad_u) *bad_u = t1;
    return Status::degenerate_circle_parameter;
  }
  double dot = 0;
  for (int k = 0; k < 4; ++k) dot += jet[0][k][0] * jet[1][k][0];
  const double scale[2] = {1.0 / std::sqrt(std::abs(det[0])),
                           (dot < 0 ? -1.0 : 1.0) / std::sqrt(std::abs(det[1]))};
  const int n = 2 * K + 1;
  double coeff[4][kMaxMobiusDegree + 1];
  for (int k = 0; k < 4; ++k) {
    double ends_jet[2][kMaxBlendOrder + 1];
    for (int e = 0; e < 2; ++e)
      for (int l = 0; l <= K; ++l) ends_jet[e][l] = scale[e] * jet[e][k][l];
    double b[kMaxCurveDegree + 1];
    hermite_bernstein(K, t1 - t0, ends_jet[0], ends_jet[1], b);
    MobiusPoly poly;
    if (!from_bernstein(b, n, t0, t1, poly)) return Status::degree_too_high;
    for (int i = 0; i <= n; ++i) coeff[k][i] = i <= poly.deg ? poly.c[i] : 0.0;
  }
  const Status st = make_mobius(n, coeff[0], coeff[1], coeff[2], coeff[3], f);
  return st == Status::not_finite ? Status::numerical_overflow : st;
}

}  // namespace

Status make_ringed_blend(const BlendEnd& start, const BlendEnd& end, int K, double t0,
                         double t1, Surface& out, double* bad_u, RationalCurve* curves,
                         BlendCircles circles) {
  if (K < 1) return Status::invalid_argument;  // §9.2: K >= 1
  if (circles != BlendCircles::generator && circles != BlendCircles::matched)
    return Status::invalid_argument;
  RationalCurve p[3];
  if (Status st = blend_curves(start, end, K, t0, t1, 3, p); st != Status::ok) return st;
  // Matched: the same circles, reparameterized by f(t, v); the end maps are
  // measured in the frames of f = v, taken straight from the curves, so the
  // surface is built (scanned, compiled) once.
  Mobius f;
  const bool matched = circles == BlendCircles::matched;
  if (matched)
    if (Status st = matched_circles(p, start, end, K, t0, t1, f, bad_u); st != Status::ok)
      return st;
  Surface S;
  if (Status st = make_prrs(p[0], p[1], p[2], matched ? &f : nullptr, t0, t1, S, bad_u);
      st != Status::ok)
    return st == Status::not_finite ? Status::numerical_overflow : st;
  out = S;
  if (curves)
    for (int j = 0; j < 3; ++j) curves[j] = p[j];
  return Status::ok;
}

namespace {

template <class Make>
Status blend_spline(const BlendEnd* ends, int n, int K, const double* knots,
                    Surface* const* pieces, int* bad_piece, double* bad_u, Make&& make) {
  if (!ends || !knots || !pieces) return Status::null_argument;
  if (n < 2 || n > kMaxSplineKnots) return Status::invalid_argument;
  for (int i = 0; i + 1 < n; ++i)
    if (!pieces[i]) return Status::null_argument;
  for (int i = 1; i + 1 < n; ++i)
    if (ends[i].lambda == 0.0) return Status::invalid_argument;  // no default inside
  // Interior ends act as the end of piece i-1 and the start of piece i; the
  // data are the same, so the curves are C^K splines (make_hermite_spline).
  // Two passes keep the output all-or-nothing without n surfaces (6 KB
  // each) on the stack: the first validates every piece in one scratch
  // surface, the second (deterministic, so it succeeds) writes them.
  Surface scratch;
  for (int i = 0; i + 1 < n; ++i) {
    if (Status st = make(ends[i], ends[i + 1], K, knots[i], knots[i + 1], scratch, bad_u);
        st != Status::ok) {
      if (bad_piece) *bad_piece = i;
      return st;
    }
  }
  for (int i = 0; i + 1 < n; ++i)
    if (Status st = make(ends[i], ends[i + 1], K, knots[i], knots[i + 1], *pieces[i], nullptr);
        st != Status::ok)
      return Status::internal_error;  // unreachable: the first pass built the same piece
  return Status::ok;
}

}  // namespace

Status make_canal_blend_spline(const BlendEnd* ends, int n, int K, const double* knots,
                               Surface* const* pieces, int* bad_piece, double* bad_u) {
  return blend_spline(ends, n, K, knots, pieces, bad_piece, bad_u,
                      [](const BlendEnd& a, const BlendEnd& b, int k, double t0, double t1,
                         Surface& S, double* bad) {
                        return make_canal_blend(a, b, k, t0, t1, S, bad);
                      });
}

Status make_ringed_blend_spline(const BlendEnd* ends, int n, int K, const double* knots,
                                Surface* const* pieces, int* bad_piece, double* bad_u,
                                BlendCircles circles) {
  return blend_spline(ends, n, K, knots, pieces, bad_piece, bad_u,
                      [circles](const BlendEnd& a, const BlendEnd& b, int k, double t0,
                                double t1, Surface& S, double* bad) {
                        return make_ringed_blend(a, b, k, t0, t1, S, bad, nullptr, circles);
                      });
}

Status continuity_report(const Surface& A, double uA, double lambda, const Surface& B,
                         double uB, int K, const double* vA, int n, ContinuityReport& out) {
  if (!input_ok(lambda)) return Status::not_finite;
  const double jet[kMaxBlendOrder] = {lambda};
  return continuity_report(A, uA, jet, B, uB, K, vA, n, out);
}

namespace {

// A's series (in u_A) as series in u_B: composed with the jet of
// u_A = phi(u_B) (Faa di Bruno).
template <int N>
Taylor<double, N> composed(const Taylor<double, N>& f, const double* jet) {
  return compose(f, reparameterization_series<N>(jet, N));
}
template <int N>
Vec3<Taylor<double, N>> composed(const Vec3<Taylor<double, N>>& f, const double* jet) {
  return {composed(f[0], jet), composed(f[1], jet), composed(f[2], jet)};
}

}  // namespace

Status continuity_report(const Surface& A, double uA, const double* jet, const Surface& B,
                         double uB, int K, const double* vA, int n, ContinuityReport& out) {
  if (K < 0 || n < 1) return Status::invalid_argument;
  if (K > kMaxBlendOrder) return Status::degree_too_high;
  if (!jet) return Status::null_argument;
  if (!input_ok(uA) || !input_ok(uB)) return Status::not_finite;
  for (int m = 1; m <= K; ++m)
    if (!input_ok(jet[m - 1])) return Status::not_finite;
  if (vA)
    for (int i = 0; i < n; ++i)
      if (std::isnan(vA[i])) return Status::not_finite;
  ContinuityReport R;
  R.K = K;
  R.samples = n;

  // The circle families.
  const Status cs = detail::with_order(K, [&](auto order) -> Status {
    constexpr int N = decltype(order)::value;
    Vec3<Taylor<double, N>> ca, na, cb, nb;
    Taylor<double, N> ra, rb;
    if (Status s = circle_series<N>(A, uA, ca, na, ra); s != Status::ok) return s;
    if (Status s = circle_series<N>(B, uB, cb, nb, rb); s != Status::ok) return s;
    ca = composed(ca, jet);
    na = composed(na, jet);
    ra = composed(ra, jet);
    const double sign = coeff(na, 0).dot(coeff(nb, 0)) < 0 ? -1.0 : 1.0;
    const double rad2 = std::abs(ra.c[0]);
    const double cscale = coeff(ca, 0).norm() + std::sqrt(rad2);
    for (int l = 0; l <= N; ++l) {
      const double jc = (coeff(cb, l) - coeff(ca, l)).norm() / cscale;
      const double jn = (sign * coeff(nb, l) - coeff(na, l)).norm();
      const double jr = std::abs(deriv(rb, l) - deriv(ra, l)) / rad2;
      R.circle_jump[l] = std::max(jc, std::max(jn, jr));
      if (!std::isfinite(R.circle_jump[l])) return Status::numerical_overflow;
    }
    R.point_scale = std::sqrt(rad2);
    return Status::ok;
  });
  if (cs != Status::ok) return cs;

  const double pi = std::acos(-1.0);
  for (int i = 0; i < n; ++i) {
    const double v = vA ? vA[i] : std::tan(pi * (i + 0.5) / n - pi / 2);
    Vec3d da[kMaxBlendOrder + 1], db[kMaxBlendOrder + 1];
    Vec3d xa[kMaxBlendOrder + 1];
    if (Status s = derivatives_u(A, uA, v, K, xa); s != Status::ok) return s;
    reparameterize(K, xa, jet, da);
    double vb = 0;
    if (Status s = B.parameter_of(uB, da[0], vb); s != Status::ok) return s;
    if (Status s = derivatives_u(B, uB, vb, K, db); s != Status::ok) return s;
    R.point_scale = std::max(R.point_scale, std::max(da[0].norm(), db[0].norm()));
    R.max_gap = std::max(R.max_gap, (da[0] - db[0]).norm());
    for (int l = 0; l <= K; ++l) {
      const Vec3d& a = da[l];
      R.point_jump[l] = std::max(R.point_jump[l], (db[l] - a).norm());
      R.point_scale_l[l] = std::max(R.point_scale_l[l], std::max(a.norm(), db[l].norm()));
    }
    // Normals (eval wants finite v: 1e300 is the generator to rounding).
    auto fin = [](double w) { return std::isfinite(w) ? w : std::copysign(1e300, w); };
    double na[3], nb[3];
    EvalOut oa, ob;
    oa.normal = na;
    ob.normal = nb;
    const Status sa = A.eval(uA, fin(v), oa);
    const Status sb = B.eval(uB, fin(vb), ob);
    if (sa == Status::singular_point || sb == Status::singular_point) {
      ++R.singular_samples;
      continue;
    }
    if (sa != Status::ok) return sa;
    if (sb != Status::ok) return sb;
    const Vec3d a(na[0], na[1], na[2]), b(nb[0], nb[1], nb[2]);
    R.max_normal_angle =
        std::max(R.max_normal_angle, std::atan2(a.cross(b).norm(), std::abs(a.dot(b))));
  }
  // |lambda^l x^(l)| beyond ~1e154 overflows the norms (fuzz_blend
  // regress-continuity-huge-lambda): no infinite measure is reported as ok.
  bool finite = std::isfinite(R.max_gap) && std::isfinite(R.point_scale);
  for (int l = 0; l <= K; ++l)
    finite = finite && std::isfinite(R.point_jump[l]) && std::isfinite(R.point_scale_l[l]);
  if (!finite) return Status::numerical_overflow;
  out = R;
  return Status::ok;
}

}  // namespace v0
}  // namespace cyclide
