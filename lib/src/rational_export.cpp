// Exact rational Bezier export of circle-family surfaces; the math (E1)-(E6)
// is in rational_export.hpp.
#include "cyclide/rational_export.hpp"

#include <algorithm>
#include <cmath>

#include "cyclide/exact.hpp"
#include "export_pieces.hpp"

namespace cyclide {
inline namespace v0 {

namespace {
template <class R, class C>
void bernstein_from_power_t(const C* c, int n, R t0, R t1, R* b) {
  // Horner p = c0 + t (c1 + t (c2 + ...)) with every partial result kept in
  // the Bernstein basis of its degree d on [t0, t1]: t has the coefficients
  // (t0, t1), so (t B)_k = (1 - k/(d+1)) t0 B_k + (k/(d+1)) t1 B_{k-1} (degree
  // d + 1), and a constant has all coefficients equal.
  b[0] = c[n];
  for (int d = 0; d < n; ++d) {  // b holds degree d; make degree d + 1
    const R inv = R(1) / R(d + 1);
    const R cj = c[n - 1 - d];
    R prev = 0;  // B_{k-1}
    for (int k = 0; k <= d + 1; ++k) {
      const R bk = k <= d ? b[k] : R(0);
      const R fk = R(k) * inv;
      b[k] = (R(1) - fk) * t0 * bk + fk * t1 * prev + cj;
      prev = bk;
    }
  }
}
}  // namespace

void bernstein_from_power(const double* c, int n, double t0, double t1, double* b) {
  bernstein_from_power_t<double>(c, n, t0, t1, b);
}

namespace {

constexpr int kCap = kMaxExportDegree;
constexpr int kSamples = 65;  // values of u for the arc test (E5) and the pole test

// The products run in extended precision where long double has it (x86:
// 64-bit mantissa): the numerators O wp Q + N are differences of terms of
// the frame's size |o| + |p - o|, which may exceed |x| many times.
using Real = long double;

// A polynomial in Bernstein form on the local u-interval [0, 1].
struct BPoly {
  int deg = 0;
  Real c[kCap + 1];
  BPoly() { c[0] = 0.0; }
  explicit BPoly(Real v) { c[0] = v; }
};

void binomial_row(int n, Real* row) {
  row[0] = 1.0;
  for (int k = 1; k <= n; ++k) row[k] = row[k - 1] * Real(n - k + 1) / Real(k);
}

double eval(const BPoly& p, double s) {  // de Casteljau
  Real t[kCap + 1] = {};  // (zeroed: GCC -O3 cannot see the loop fill it)
  for (int i = 0; i <= p.deg; ++i) t[i] = p.c[i];
  for (int r = p.deg; r > 0; --r)
    for (int i = 0; i < r; ++i) t[i] = (1.0 - s) * t[i] + s * t[i + 1];
  return double(t[0]);
}

// c[0..n] restricted to [a, b] subset [0, 1] by two de Casteljau splits.
template <class R>
void restrict_to(const R* c, int n, double a, double b, R* r) {
  R t[kCap + 1] = {};  // (zeroed: GCC -O3 cannot see the loop fill it)
  for (int i = 0; i <= n; ++i) t[i] = c[i];
  if (b < 1.0) {  // left part [0, b]
    R left[kCap + 1];
    left[0] = t[0];
    for (int lev = 1; lev <= n; ++lev) {
      for (int i = 0; i <= n - lev; ++i) t[i] = (1.0 - b) * t[i] + b * t[i + 1];
      left[lev] = t[0];
    }
    for (int i = 0; i <= n; ++i) t[i] = left[i];
  }
  if (a > 0.0) {  // right part [a/b, 1] of [0, b]
    const double s = a / b;
    R right[kCap + 1];
    right[n] = t[n];
    for (int lev = 1; lev <= n; ++lev) {
      for (int i = 0; i <= n - lev; ++i) t[i] = (1.0 - s) * t[i] + s * t[i + 1];
      right[n - lev] = t[n - lev];
    }
    for (int i = 0; i <= n; ++i) t[i] = right[i];
  }
  for (int i = 0; i <= n; ++i) r[i] = t[i];
}

// Bernstein arithmetic that remembers a degree overflow (E6).
struct Arith {
  bool too_high = false;

  // (a b)_k = sum_{i+j=k} C(m,i) C(n,j) / C(m+n,k) a_i b_j: positive weights
  // summing to 1, so the product is as stable as its factors.
  BPoly mul(const BPoly& a, const BPoly& b) {
    BPoly r;
    const int m = a.deg, n = b.deg;
    if (m + n > kCap) {
      too_high = true;
      return r;
    }
    Real cm[kCap + 1], cn[kCap + 1], cr[kCap + 1];
    binomial_row(m, cm);
    binomial_row(n, cn);
    binomial_row(m + n, cr);
    r.deg = m + n;
    for (int k = 0; k <= m + n; ++k) {
      Real s = 0.0;
      for (int i = std::max(0, k - n); i <= std::min(m, k); ++i)
        s += cm[i] * cn[k - i] * a.c[i] * b.c[k - i];
      r.c[k] = s / cr[k];
    }
    return r;
  }
  BPoly elevate(const BPoly& a, int n) {
    if (a.deg >= n) return a;
    BPoly one(1.0);
    one.deg = n - a.deg;
    for (int k = 0; k <= one.deg; ++k) one.c[k] = 1.0;
    return mul(a, one);
  }
  BPoly lin(Real x, const BPoly& a, Real y, const BPoly& b) {  // x a + y b
    const int n = std::max(a.deg, b.deg);
    const BPoly ea = elevate(a, n), eb = elevate(b, n);
    BPoly r;
    r.deg = n;
    for (int k = 0; k <= n; ++k) r.c[k] = x * ea.c[k] + y * eb.c[k];
    return r;
  }
  BPoly add(const BPoly& a, const BPoly& b) { return lin(1.0, a, 1.0, b); }
  BPoly sub(const BPoly& a, const BPoly& b) { return lin(1.0, a, -1.0, b); }
};

// Scale polynomials jointly by a power of two so that the largest
// coefficient is in [0.5, 1) (a homogeneous group's ratios are unchanged).
void normalize(BPoly* const* ps, int count) {
  double big = 0.0;
  for (int i = 0; i < count; ++i)
    for (int k = 0; k <= ps[i]->deg; ++k) big = std::max(big, double(std::abs(ps[i]->c[k])));
  if (!(big > 0.0) || !std::isfinite(big)) return;
  int e = 0;
  std::frexp(big, &e);
  for (int i = 0; i < count; ++i)
    for (int k = 0; k <= ps[i]->deg; ++k) ps[i]->c[k] = std::ldexp(ps[i]->c[k], -e);
}

// The homogeneous (w, x, y, z) of an exact vector in Bernstein form on
// t in [-1, 1] (the export interval), all of the same degree; returns it.
int homogeneous(Arith& A, const ExactVec3& e, BPoly (&h)[4]) {
  const ExactPoly* src[4] = {&e.w, &e.x, &e.y, &e.z};
  int n = 0;
  for (const ExactPoly* p : src) n = std::max(n, p->deg);
  for (int i = 0; i < 4; ++i) {
    BPoly b;
    b.deg = src[i]->deg;
    bernstein_from_power_t<Real>(src[i]->c, src[i]->deg, -1.0, 1.0, b.c);
    h[i] = A.elevate(b, n);
  }
  BPoly* ps[4] = {&h[0], &h[1], &h[2], &h[3]};
  normalize(ps, 4);
  return n;
}

// Everything the pieces need: X_k (E4) for v^k, k = 0..2, component 0 the
// weight and 1..3 the numerators, in Bernstein form on [u0, u1]; the
// weight factor wo wp; samples of (E5)'s quaternion data.
struct Data {
  int m = 0;
  BPoly X[3][4];
  BPoly wowp;
  double Wa0[kSamples], Wa1[kSamples], g[kSamples], d[kSamples], na[kSamples];
};

double sample_s(int k) { return double(k) / double(kSamples - 1); }

// A quadratic in u as a quadratic in t, u = mid + half t (E7).
void quadratic_in_t(Real c0, Real c1, Real c2, Real mid, Real half, Real (&t)[3]) {
  t[0] = c0 + (c1 + c2 * mid) * mid;
  t[1] = (c1 + 2 * c2 * mid) * half;
  t[2] = c2 * half * half;
}

// (E7)/(E8): the closed forms of bidegree (2, 2) of kinds dupin and
// parabolic. H[k][c][i]: component c (0 the weight) of X_h, the coefficient
// of v^k t^i, t in [-1, 1] over [ua, ub].
void closed_form(const Surface& S, double ua, double ub, Real (&H)[3][4][3]) {
  const Real mid = 0.5L * (Real(ua) + Real(ub)), half = 0.5L * (Real(ub) - Real(ua));
  for (auto& k : H)
    for (auto& c : k)
      for (Real& x : c) x = 0;
  if (S.kind == SurfaceKind::parabolic) {
    // (E7): (4.1) phi = (1 + u^2 + v^2, a u + (a - b) u v^2, b v + (b - a) u^2 v,
    // a u^2 + b v^2) as sum_k phi_k(u) v^k, placed: x = origin + frame phi/phi0.
    const ParabolicCyclide& C = S.parabolic;
    const Real a = C.a, b = C.b;
    Real phi[3][4][3] = {};  // [v^k][component][u^i]
    phi[0][0][0] = 1;
    phi[0][0][2] = 1;
    phi[0][1][1] = a;
    phi[0][3][2] = a;
    phi[1][2][0] = b;
    phi[1][2][2] = b - a;
    phi[2][0][0] = 1;
    phi[2][1][1] = a - b;
    phi[2][3][0] = b;
    for (int k = 0; k < 3; ++k) {
      Real t[4][3];
      for (int c = 0; c < 4; ++c)
        quadratic_in_t(phi[k][c][0], phi[k][c][1], phi[k][c][2], mid, half, t[c]);
      for (int i = 0; i < 3; ++i) {
        H[k][0][i] = t[0][i];
        for (int r = 0; r < 3; ++r) {
          Real x = Real(C.origin[r]) * t[0][i];
          for (int j = 0; j < 3; ++j) x += Real(C.frame(r, j)) * t[1 + j][i];
          H[k][1 + r][i] = x;
        }
      }
    }
    return;
  }
  // (E8): Dupin. xi = x0 : x1 and zeta = z0 : z1 with x0 = xm0 u + xm1,
  // x1 = xm2 u + xm3 (dupin_frame), z0 = zm0 v + zm1, z1 = zm2 v + zm3.
  // (29), (30): a = theta(2 x0 x1 e1 + (x1^2 - x0^2) e2 + (x1^2 + x0^2) e-),
  // b = theta(2 z0 z1 e3 + (z1^2 - z0^2) e+ + (z1^2 + z0^2) er), quadratics
  // in t and in v; (25) c^ = (er . a) b - (er . b) a (er . x = -x_r), and
  // (26)-(27) x = unit c^_123 / w + origin, w = -c^ . n_inf = c^_- - c^_+.
  const DupinCyclide& D = S.dupin.cyclide;
  const double* xm = S.dupin.xi_map;
  const double* zm = S.dupin.zeta_map;
  // family(t0, t1) with t0 = p + q s, t1 = r + w s: the coefficients of s^i
  // of 2 t0 t1, t1^2 - t0^2, t1^2 + t0^2.
  auto family = [&D](Real p, Real q, Real r, Real w, int ci, int cj, int ck, Real (&out)[6][3]) {
    const Real cross[3] = {2 * p * r, 2 * (p * w + q * r), 2 * q * w};
    const Real diff[3] = {r * r - p * p, 2 * (r * w - p * q), w * w - q * q};
    const Real sum[3] = {r * r + p * p, 2 * (r * w + p * q), w * w + q * q};
    for (int row = 0; row < 6; ++row)
      for (int i = 0; i < 3; ++i)
        out[row][i] = cross[i] * Real(D.theta(row, ci)) + diff[i] * Real(D.theta(row, cj)) +
                      sum[i] * Real(D.theta(row, ck));
  };
  Real A[6][3], B[6][3];  // A[row][t^i], B[row][v^k]
  family(Real(xm[0]) * mid + Real(xm[1]), Real(xm[0]) * half, Real(xm[2]) * mid + Real(xm[3]),
         Real(xm[2]) * half, kE1, kE2, kEMinus, A);
  family(zm[1], zm[0], zm[3], zm[2], kE3, kEPlus, kER, B);
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) {
      Real c[6];
      for (int row = 0; row < 6; ++row) c[row] = B[kER][k] * A[row][i] - A[kER][i] * B[row][k];
      const Real w = c[kEMinus] - c[kEPlus];
      H[k][0][i] = w;
      for (int r = 0; r < 3; ++r) H[k][1 + r][i] = Real(D.unit) * c[r] + Real(D.origin[r]) * w;
    }
}

// Kinds dupin and parabolic: X from the closed form (m = 2), the arc data
// from Surface::frame at the samples (its status where it fails: a pole
// there is point_at_infinity), wowp = X_h's weight at v = 1, which has the
// sign of lambda(u) in X_h = lambda(u) (Q, Q o + N) (E9).
Status build_closed(const Surface& S, double ua, double ub, Data& X) {
  Real H[3][4][3];
  closed_form(S, ua, ub, H);
  Arith A;
  X.m = 2;
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 4; ++c) {
      BPoly& b = X.X[k][c];
      b.deg = 2;
      bernstein_from_power_t<Real>(H[k][c], 2, -1.0, 1.0, b.c);
    }
  BPoly* xs[12];
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 4; ++c) xs[4 * k + c] = &X.X[k][c];
  normalize(xs, 12);
  X.wowp = A.add(A.add(X.X[0][0], X.X[1][0]), X.X[2][0]);
  for (int i = 0; i < kSamples; ++i) {
    const double u = i == kSamples - 1 ? ub : ua + sample_s(i) * (ub - ua);
    CircleFrame<Taylor<double, 0>> F;
    if (Status st = S.frame<0>(u, F); st != Status::ok) return st;
    X.Wa0[i] = F.beta.c[0];
    X.Wa1[i] = F.alpha.c[0];
    X.g[i] = F.gamma.c[0];
    X.d[i] = F.delta.c[0];
    X.na[i] = std::sqrt(F.a[0].c[0] * F.a[0].c[0] + F.a[1].c[0] * F.a[1].c[0] +
                        F.a[2].c[0] * F.a[2].c[0]);
  }
  return Status::ok;
}

Status build(const Surface& S, double ua, double ub, Data& X) {
  if (S.kind == SurfaceKind::dupin || S.kind == SurfaceKind::parabolic)
    return build_closed(S, ua, ub, X);
  const double mid = 0.5 * (ua + ub), half = 0.5 * (ub - ua);
  ExactFrame E;
  Status st = Status::internal_error;
  switch (S.kind) {
    case SurfaceKind::prcs: st = exact_prcs_frame(S.curve[0], S.curve[1], E, mid, half); break;
    case SurfaceKind::prrs:
      st = exact_prrs_frame(S.curve[0], S.curve[1], S.curve[2], E, mid, half);
      break;
    case SurfaceKind::ringed:
      st = exact_ringed_frame(S.curve[0], S.curve[1], S.curve[2], E, mid, half);
      break;
    case SurfaceKind::dupin:
    case SurfaceKind::parabolic: return Status::internal_error;  // build_closed
  }
  if (st != Status::ok) return st;
  Arith A;
  // o = O / wo, a = Av / wa, p = P / wp (index 0 the weight).
  BPoly O[4], Av[4], P[4];
  const int no = homogeneous(A, E.o, O), na = homogeneous(A, E.a, Av),
            np = homogeneous(A, E.p, P);
  // f's coefficients (power form in u) on [ua, ub], one common degree.
  const MobiusPoly* fp[4] = {&S.f.alpha, &S.f.beta, &S.f.gamma, &S.f.delta};
  BPoly f[4];
  int nf = 0;
  for (const MobiusPoly* p : fp) nf = std::max(nf, p->deg);
  for (int i = 0; i < 4; ++i) {
    BPoly b;
    b.deg = fp[i]->deg;
    bernstein_from_power_t<Real>(fp[i]->c, fp[i]->deg, ua, ub, b.c);
    f[i] = A.elevate(b, nf);
  }
  BPoly* fs[4] = {&f[0], &f[1], &f[2], &f[3]};
  normalize(fs, 4);
  const int m = no + np + 2 * (na + nf);  // (E4)
  if (m > kCap) return Status::degree_too_high;
  X.m = m;
  // (E1): q' = W wa + G A with W' = Wa1 v + Wa0, G = gamma v + delta.
  const BPoly Wa1 = A.mul(f[0], Av[0]), Wa0 = A.mul(f[1], Av[0]);
  const BPoly& ga = f[2];
  const BPoly& de = f[3];
  // (E2): D = P wo - O wp; (E3)'s A.A, A.D and A x D.
  BPoly D[3], Owp[3];
  for (int j = 0; j < 3; ++j) {
    D[j] = A.sub(A.mul(P[1 + j], O[0]), A.mul(O[1 + j], P[0]));
    Owp[j] = A.mul(O[1 + j], P[0]);
  }
  const BPoly aa = A.add(A.add(A.mul(Av[1], Av[1]), A.mul(Av[2], Av[2])), A.mul(Av[3], Av[3]));
  const BPoly ad = A.add(A.add(A.mul(Av[1], D[0]), A.mul(Av[2], D[1])), A.mul(Av[3], D[2]));
  BPoly axd[3];
  for (int j = 0; j < 3; ++j) {
    const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
    axd[j] = A.sub(A.mul(Av[1 + j1], D[j2]), A.mul(Av[1 + j2], D[j1]));
  }
  X.wowp = A.mul(O[0], P[0]);
  // v-coefficients of W'^2, G^2 and W' G.
  const BPoly W2[3] = {A.mul(Wa0, Wa0), A.lin(2.0, A.mul(Wa0, Wa1), 0.0, BPoly()),
                       A.mul(Wa1, Wa1)};
  const BPoly G2[3] = {A.mul(de, de), A.lin(2.0, A.mul(ga, de), 0.0, BPoly()), A.mul(ga, ga)};
  const BPoly WG[3] = {A.mul(Wa0, de), A.add(A.mul(Wa1, de), A.mul(Wa0, ga)), A.mul(Wa1, ga)};
  for (int k = 0; k < 3; ++k) {
    const BPoly G2aa = A.mul(G2[k], aa);
    const BPoly Q = A.add(W2[k], G2aa);   // (E3)
    const BPoly cd = A.sub(W2[k], G2aa);
    const BPoly ca = A.lin(2.0, A.mul(G2[k], ad), 0.0, BPoly());
    const BPoly cx = A.lin(2.0, WG[k], 0.0, BPoly());
    X.X[k][0] = A.elevate(A.mul(X.wowp, Q), m);  // (E4)
    for (int j = 0; j < 3; ++j) {
      const BPoly N = A.add(A.add(A.mul(cd, D[j]), A.mul(ca, Av[1 + j])), A.mul(cx, axd[j]));
      X.X[k][1 + j] = A.elevate(A.add(A.mul(Owp[j], Q), N), m);
    }
  }
  if (A.too_high) return Status::degree_too_high;
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 4; ++c)
      if (X.X[k][c].deg != m) return Status::internal_error;
  BPoly* xs[12];
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 4; ++c) xs[4 * k + c] = &X.X[k][c];
  normalize(xs, 12);
  for (int i = 0; i < kSamples; ++i) {
    const double s = sample_s(i);
    X.Wa0[i] = eval(Wa0, s);
    X.Wa1[i] = eval(Wa1, s);
    X.g[i] = eval(ga, s);
    X.d[i] = eval(de, s);
    X.na[i] = std::sqrt(std::max(0.0, eval(aa, s)));
  }
  return Status::ok;
}

// A v-piece (E5): the circle parameter x = v (or w = 1/v if rec) runs
// linearly from x0 to x1 while v runs from v0 to v1 (increasing).
using detail::VPiece;

// (E5): the piece is an arc of less than 120 degrees of the circle at every
// sampled u: cos(arc/2) = <q(x0), q(x1)> / (|q(x0)| |q(x1)|) > 1/2.
bool arc_ok(const Data& X, const VPiece& p) {
  for (int i = 0; i < kSamples; ++i) {
    auto q = [&](double x, double& a, double& b) {
      if (p.rec) {
        a = X.Wa1[i] + X.Wa0[i] * x;
        b = (X.g[i] + X.d[i] * x) * X.na[i];
      } else {
        a = X.Wa1[i] * x + X.Wa0[i];
        b = (X.g[i] * x + X.d[i]) * X.na[i];
      }
    };
    double a0, b0, a1, b1;
    q(p.x0, a0, b0);
    q(p.x1, a1, b1);
    const double n2 = (a0 * a0 + b0 * b0) * (a1 * a1 + b1 * b1);
    const double dot = a0 * a1 + b0 * b1;
    if (!(n2 > 0.0) || !(dot > 0.5 * std::sqrt(n2))) return false;
  }
  return true;
}

bool split_v(const Data& X, const VPiece& p, int depth, VPiece* out, int& n) {
  if (arc_ok(X, p)) {
    if (n == kMaxExportVPieces) return false;
    out[n++] = p;
    return true;
  }
  if (depth == kMaxExportDepth) return false;
  const double xm = 0.5 * (p.x0 + p.x1);
  const double vm = p.rec ? 1.0 / xm : xm;
  return split_v(X, {p.rec, p.x0, xm, p.v0, vm}, depth + 1, out, n) &&
         split_v(X, {p.rec, xm, p.x1, vm, p.v1}, depth + 1, out, n);
}

// The circle parameter's own scale c (E5): at every sample u the half-angle
// vector q(v) = A v + B, A = (alpha, |a| gamma), B = (beta, |a| delta),
// turns by 90 degrees over v in [-c_i, c_i] about c_i = |B| / |A| (f = v:
// q = (v, |a|), c_i = |a|, the length of the rotation axis of eq. (13)), and
// c is their geometric mean. A model scaled by s has PRCS's v -> s v and
// c -> s c, so the pieces split at +-c follow the surface, not the number 1.
// 1 if a sample is degenerate (no scale to follow).
double parameter_scale(const Data& X) {
  double sum = 0.0;
  for (int i = 0; i < kSamples; ++i) {
    const double A = std::hypot(X.Wa1[i], X.na[i] * X.g[i]);
    const double B = std::hypot(X.Wa0[i], X.na[i] * X.d[i]);
    const double l = std::log(B) - std::log(A);
    if (!std::isfinite(l)) return 1.0;
    sum += l;
  }
  return std::exp(sum / kSamples);
}

// The initial pieces: [v0, v1] split at -1 and 1 (E5), the charts v and
// w = 1/v (the evaluator's convention, and the NURBS form's tau), and
// further at +-c when the parameter's scale c is far from 1 (|log2 c| > 3:
// inside the chart that holds it), so that no piece needs more than a few
// bisections (E5) to become an arc below 120 degrees however the model is
// scaled: without it a PRCS scaled by 2^-20 squeezes almost its whole
// circle into |v| < 2^-20 and exceeds kMaxExportDepth.
int initial_pieces(const ExportDomain& D, double c, VPiece (&p)[5]) {
  double cuts[4];
  int nc = 0;
  // Not beyond 2^+-48: the NURBS form's tau = 2 sign(v) - 1/v could no
  // longer tell the pieces at +-c from those at infinity (N1).
  const double e = std::abs(std::log2(c));
  const bool far = e > 3.0 && e < 48.0;
  if (far && c < 1.0) cuts[nc++] = -1.0, cuts[nc++] = -c, cuts[nc++] = c, cuts[nc++] = 1.0;
  else if (far) cuts[nc++] = -c, cuts[nc++] = -1.0, cuts[nc++] = 1.0, cuts[nc++] = c;
  else cuts[nc++] = -1.0, cuts[nc++] = 1.0;
  const double lo = D.whole_circle ? -HUGE_VAL : D.v0, hi = D.whole_circle ? HUGE_VAL : D.v1;
  int n = 0;
  double a = lo;
  for (int k = 0; k <= nc; ++k) {
    const double b = k < nc ? std::min(cuts[k], hi) : hi;
    if (a < b) {
      // |v| >= 1 throughout (the cuts include +-1): the w = 1/v chart.
      const bool rec = a >= 1.0 || b <= -1.0;
      if (rec)
        p[n++] = {true, a == -HUGE_VAL ? -0.0 : 1.0 / a, b == HUGE_VAL ? 0.0 : 1.0 / b, a, b};
      else
        p[n++] = {false, a, b, a, b};
    }
    a = std::max(a, b);
  }
  return n;
}

// The degree-2 v-coefficients (E5) of one u-coefficient (export_pieces.hpp).
using detail::v_controls;

// True if, on the u-interval [a, b] (local), every v-piece has weights of
// one strict sign (made positive when the patch is written).
bool weights_ok(const Data& X, double a, double b, const VPiece* pieces, int np) {
  const int m = X.m;
  Real w[3][kCap + 1];
  for (int k = 0; k < 3; ++k) restrict_to(X.X[k][0].c, m, a, b, w[k]);
  for (int p = 0; p < np; ++p) {
    int pos = 0, neg = 0;
    for (int i = 0; i <= m; ++i) {
      Real c[3];
      v_controls(pieces[p], w[0][i], w[1][i], w[2][i], c);
      for (Real x : c) {
        pos += x > 0.0;
        neg += x < 0.0;
      }
    }
    if (!(pos == 3 * (m + 1) || neg == 3 * (m + 1))) return false;
  }
  return true;
}

struct Plan {
  VPiece v[kMaxExportVPieces];
  int nv = 0;
  double ua[kMaxExportUPieces], ub[kMaxExportUPieces];  // local s in [0, 1]
  int nu = 0;
};

Status check_domain(const Surface& S, const ExportDomain& D) {
  if (S.kind != SurfaceKind::prcs && S.kind != SurfaceKind::prrs &&
      S.kind != SurfaceKind::ringed && S.kind != SurfaceKind::dupin &&
      S.kind != SurfaceKind::parabolic)
    return Status::invalid_argument;
  // NaN and infinities are not_finite, as everywhere (the whole circle's
  // v-range is implied, not given).
  if (!std::isfinite(D.u0) || !std::isfinite(D.u1) ||
      (!D.whole_circle && (!std::isfinite(D.v0) || !std::isfinite(D.v1))))
    return Status::not_finite;
  if (!(D.u0 < D.u1) || !(D.u0 >= S.u0) || !(D.u1 <= S.u1)) return Status::bad_domain;
  if (!D.whole_circle &&
      (!(D.v0 < D.v1) || !std::isfinite(D.v0) || !std::isfinite(D.v1)))
    return Status::bad_domain;
  return Status::ok;
}

// The pieces: v first (arcs, E5), then u-intervals with positive weights
// (E6), in increasing u.
Status plan(const Surface& S, const ExportDomain& D, Data& X, Plan& L) {
  if (Status st = check_domain(S, D); st != Status::ok) return st;
  if (Status st = build(S, D.u0, D.u1, X); st != Status::ok) return st;
  // A zero of wo wp on [u0, u1] is a point at infinity of every circle there.
  double prev = 0.0;
  for (int i = 0; i < kSamples; ++i) {
    const double w = eval(X.wowp, sample_s(i));
    if (!(w != 0.0) || (i > 0 && (w > 0) != (prev > 0))) return Status::point_at_infinity;
    prev = w;
  }
  VPiece init[5];
  const int ni = initial_pieces(D, parameter_scale(X), init);
  L.nv = 0;
  for (int i = 0; i < ni; ++i)
    if (!split_v(X, init[i], 0, L.v, L.nv)) return Status::numerical_overflow;
  // Depth-first over u-intervals, left first, so they come out in order.
  struct Item {
    double a, b;
    int depth;
  } stack[kMaxExportDepth + 2];
  int top = 0;
  stack[top++] = {0.0, 1.0, 0};
  L.nu = 0;
  while (top > 0) {
    const Item it = stack[--top];
    if (weights_ok(X, it.a, it.b, L.v, L.nv)) {
      if (L.nu == kMaxExportUPieces) return Status::numerical_overflow;
      L.ua[L.nu] = it.a;
      L.ub[L.nu] = it.b;
      ++L.nu;
      continue;
    }
    if (it.depth == kMaxExportDepth) {
      const double wa = eval(X.wowp, it.a), wb = eval(X.wowp, it.b);
      return (wa > 0) != (wb > 0) ? Status::point_at_infinity : Status::numerical_overflow;
    }
    const double mid = 0.5 * (it.a + it.b);
    stack[top++] = {mid, it.b, it.depth + 1};
    stack[top++] = {it.a, mid, it.depth + 1};
  }
  return Status::ok;
}

}  // namespace

void patch_parameters(const RationalBezierPatch& P, double s, double t, double& u, double& v) {
  u = P.u0 + s * (P.u1 - P.u0);
  if (!P.reciprocal_v) {
    v = P.v0 + t * (P.v1 - P.v0);
    return;
  }
  const double w = (1.0 - t) / P.v0 + t / P.v1;  // 1/inf = 0
  v = w != 0.0 ? 1.0 / w : (std::isinf(P.v0) ? P.v0 : P.v1);
}

void patch_eval_homogeneous(const RationalBezierPatch& P, double s, double t, double (&h)[4]) {
  const int m = P.deg_u, nv = P.deg_v + 1;
  double col[kMaxExportDegreeV + 1][4];
  double tmp[kCap + 1][4];
  for (int j = 0; j < nv && j <= kMaxExportDegreeV; ++j) {
    for (int i = 0; i <= m; ++i)
      for (int c = 0; c < 4; ++c) tmp[i][c] = P.cp[i * nv + j][c];
    for (int r = m; r > 0; --r)
      for (int i = 0; i < r; ++i)
        for (int c = 0; c < 4; ++c) tmp[i][c] = (1.0 - s) * tmp[i][c] + s * tmp[i + 1][c];
    for (int c = 0; c < 4; ++c) col[j][c] = tmp[0][c];
  }
  for (int r = nv - 1; r > 0; --r)
    for (int j = 0; j < r; ++j)
      for (int c = 0; c < 4; ++c) col[j][c] = (1.0 - t) * col[j][c] + t * col[j + 1][c];
  for (int c = 0; c < 4; ++c) h[c] = col[0][c];
}

Vec3d patch_point(const RationalBezierPatch& P, double s, double t) {
  double h[4];
  patch_eval_homogeneous(P, s, t, h);
  return Vec3d(h[1] / h[0], h[2] / h[0], h[3] / h[0]);
}

Status rational_bezier_patch_count(const Surface& S, const ExportDomain& D, int& count) {
  count = 0;
  Data X;
  Plan L;
  if (Status st = plan(S, D, X, L); st != Status::ok) return st;
  count = L.nu * L.nv;
  return Status::ok;
}

namespace {

// The patch (iu, iv) of the plan from the u-restricted homogeneous
// coefficients r[k][c] (v^k, component c): (E5)/(E6).
void build_patch(const ExportDomain& D, const Plan& L, int iu, int iv, int m,
                 const Real (&r)[3][4][kCap + 1], RationalBezierPatch& P) {
  const VPiece& p = L.v[iv];
  // A family with one circle for every u (m = 0, e.g. a ringed surface of
  // constant data) is written with degree 1 (the row twice): a NURBS needs
  // degree >= 1 in u.
  const int mu = std::max(m, 1);
  P.deg_u = mu;
  P.deg_v = 2;
  P.u0 = D.u0 + L.ua[iu] * (D.u1 - D.u0);
  P.u1 = iu == L.nu - 1 ? D.u1 : D.u0 + L.ub[iu] * (D.u1 - D.u0);
  P.v0 = p.v0;
  P.v1 = p.v1;
  P.reciprocal_v = p.rec;
  for (int i = 0; i <= mu; ++i)
    for (int c = 0; c < 4; ++c) {
      const int ri = std::min(i, m);
      Real v[3];
      v_controls(p, r[0][c][ri], r[1][c][ri], r[2][c][ri], v);
      for (int j = 0; j < 3; ++j) P.cp[3 * i + j][c] = double(v[j]);
    }
  // Positive weights (plan checked they share one sign), the largest in
  // [0.5, 1) (scaled by a power of two: exact).
  const double sign = P.cp[0][0] > 0 ? 1.0 : -1.0;
  double big = 0.0;
  for (int i = 0; i < 3 * (mu + 1); ++i) big = std::max(big, std::abs(P.cp[i][0]));
  int e = 0;
  std::frexp(big, &e);
  for (int i = 0; i < 3 * (mu + 1); ++i)
    for (int c = 0; c < 4; ++c) P.cp[i][c] = sign * std::ldexp(P.cp[i][c], -e);
}

// The check against the evaluator at 3 x 3 points of the patch.
Status check_patch(const Surface& S, const RationalBezierPatch& P) {
  double err = 0.0, size = 0.0;
  for (double s : {0.0, 0.5, 1.0})
    for (double t : {0.0, 0.5, 1.0}) {
      double u, v;
      patch_parameters(P, s, t, u, v);
      if (std::isinf(v)) v = std::copysign(1e300, v);
      double x[3];
      if (Status st = S.eval(u, v, {x, nullptr, nullptr, nullptr}); st != Status::ok) return st;
      const Vec3d y = patch_point(P, s, t), xv(x[0], x[1], x[2]);
      err = std::max(err, (y - xv).norm());
      size = std::max(size, xv.norm());
    }
  return err <= kExportCheckTol * size ? Status::ok : Status::numerical_overflow;
}

}  // namespace

Status export_rational_bezier(const Surface& S, const ExportDomain& D, RationalBezierPatch* out,
                              int cap, int& count) {
  count = 0;
  Data X;
  Plan L;
  if (Status st = plan(S, D, X, L); st != Status::ok) return st;
  const int need = L.nu * L.nv;
  if (need > cap) {
    count = need;
    return Status::buffer_too_small;
  }
  if (!out) return Status::null_argument;
  const int m = X.m;
  // Pass 0 builds every patch into a scratch patch and checks it against
  // the evaluator; pass 1 writes them (the same arithmetic), so out is
  // never left half-written.
  RationalBezierPatch scratch;  // ~15.5 KB of stack
  Real r[3][4][kCap + 1];
  for (int pass = 0; pass < 2; ++pass) {
    int n = 0;
    for (int iu = 0; iu < L.nu; ++iu) {
      for (int k = 0; k < 3; ++k)
        for (int c = 0; c < 4; ++c) restrict_to(X.X[k][c].c, m, L.ua[iu], L.ub[iu], r[k][c]);
      for (int iv = 0; iv < L.nv; ++iv) {
        RationalBezierPatch& P = pass == 0 ? scratch : out[n];
        ++n;
        build_patch(D, L, iu, iv, m, r, P);
        if (pass == 1) continue;
        if (Status st = check_patch(S, P); st != Status::ok) return st;
      }
    }
  }
  count = need;
  return Status::ok;
}

// ------------------------------------------------ NURBS assembly (N1)-(N4)

double export_tau_of_v(double v) {
  if (std::abs(v) <= 1.0) return v;
  return std::copysign(2.0, v) - 1.0 / v;  // (N1); 1/inf = 0
}

double export_v_of_tau(double tau) {
  tau = std::min(2.0, std::max(-2.0, tau));
  if (std::abs(tau) <= 1.0) return tau;
  const double w = std::copysign(2.0, tau) - tau;  // 1/v
  return w == 0.0 ? std::copysign(HUGE_VAL, tau) : 1.0 / w;
}

Status nurbs_size(const RationalBezierPatch* patches, int count, NurbsSize& size) {
  size = NurbsSize{};
  if (!patches) return Status::null_argument;
  if (count <= 0) return Status::invalid_argument;
  const RationalBezierPatch& P0 = patches[0];
  int nv = 0;
  while (nv < count && patches[nv].u0 == P0.u0 && patches[nv].u1 == P0.u1) ++nv;
  if (nv > kMaxExportVPieces || count % nv != 0) return Status::invalid_argument;
  const int nu = count / nv;
  if (P0.deg_u < 1 || P0.deg_u > kMaxExportDegree || P0.deg_v < 1 ||
      P0.deg_v > kMaxExportDegreeV || (P0.deg_u + 1) * (P0.deg_v + 1) > kPatchControlPoints)
    return Status::invalid_argument;
  for (int iu = 0; iu < nu; ++iu)
    for (int iv = 0; iv < nv; ++iv) {
      const RationalBezierPatch& P = patches[iu * nv + iv];
      const RationalBezierPatch& R = patches[iu * nv];  // the row's first
      const RationalBezierPatch& C = patches[iv];       // the column's first
      if (P.deg_u != P0.deg_u || P.deg_v != P0.deg_v) return Status::invalid_argument;
      if (!(P.u0 < P.u1) || P.u0 != R.u0 || P.u1 != R.u1) return Status::invalid_argument;
      if (iv == 0 && iu > 0 && P.u0 != patches[(iu - 1) * nv].u1) return Status::invalid_argument;
      if (P.v0 != C.v0 || P.v1 != C.v1 || P.reciprocal_v != C.reciprocal_v)
        return Status::invalid_argument;
      // (N1): a reciprocal piece lies in |v| >= 1, a piece in v in |v| <= 1.
      const bool in_v = std::abs(P.v0) <= 1.0 && std::abs(P.v1) <= 1.0;
      const bool out_v = (P.v0 >= 1.0 && P.v1 >= 1.0) || (P.v0 <= -1.0 && P.v1 <= -1.0);
      if (!(P.reciprocal_v ? out_v : in_v)) return Status::invalid_argument;
      if (!(export_tau_of_v(P.v0) < export_tau_of_v(P.v1))) return Status::invalid_argument;
      if (iu == 0 && iv > 0 && P.v0 != patches[iv - 1].v1) return Status::invalid_argument;
    }
  size.deg_u = P0.deg_u;
  size.deg_v = P0.deg_v;
  size.nu = nu;
  size.nv = nv;
  size.cp_u = nu * P0.deg_u + 1;
  size.cp_v = nv * P0.deg_v + 1;
  return Status::ok;
}

namespace {

// Shared edge of two patches (N3): `a` scaled by sa against `b` scaled by
// sb, n points at a[ia + k * da], b[ib + k * db]. The scale that makes b's
// weights match a's (ratio of sums), and whether they agree after it.
double edge_ratio(const RationalBezierPatch& A, int ia, int da, double sa,
                  const RationalBezierPatch& Bp, int ib, int db, int n) {
  double wa = 0.0, wb = 0.0;
  for (int k = 0; k < n; ++k) {
    wa += sa * A.cp[ia + k * da][0];
    wb += Bp.cp[ib + k * db][0];
  }
  return wa / wb;
}
bool edge_agrees(const RationalBezierPatch& A, int ia, int da, double sa,
                 const RationalBezierPatch& Bp, int ib, int db, double sb, int n) {
  double err = 0.0, big = 0.0;
  for (int k = 0; k < n; ++k)
    for (int c = 0; c < 4; ++c) {
      const double x = sa * A.cp[ia + k * da][c], y = sb * Bp.cp[ib + k * db][c];
      err = std::max(err, std::abs(x - y));
      big = std::max(big, std::max(std::abs(x), std::abs(y)));
    }
  return err <= kNurbsJoinTol * big;
}

}  // namespace

Status assemble_nurbs(const RationalBezierPatch* patches, int count, const NurbsBuffers& B,
                      NurbsSize& size) {
  if (Status st = nurbs_size(patches, count, size); st != Status::ok) return st;
  if (B.cap_knots_u < size.knots_u() || B.cap_knots_v < size.knots_v() ||
      B.cap_cp < size.cp_count())
    return Status::buffer_too_small;
  if (!B.knots_u || !B.knots_v || !B.cp) return Status::null_argument;
  const int p = size.deg_u, q = size.deg_v, nu = size.nu, nv = size.nv, cv = size.cp_v;
  const int row = q + 1;  // patch cp stride in i
  // Pass 0: the patch scales (N3) and the checks; pass 1 writes.
  double prev[kMaxExportVPieces], cur[kMaxExportVPieces];
  double big = 0.0, norm = 1.0;
  for (int pass = 0; pass < 2; ++pass) {
    for (int iu = 0; iu < nu; ++iu) {
      for (int iv = 0; iv < nv; ++iv) {
        const RationalBezierPatch& P = patches[iu * nv + iv];
        double s = 1.0;
        if (iv > 0) {  // left: its column j = q against our j = 0
          const RationalBezierPatch& L = patches[iu * nv + iv - 1];
          s = edge_ratio(L, q, row, cur[iv - 1], P, 0, row, p + 1);
        } else if (iu > 0) {  // below: its row i = p against our i = 0
          s = edge_ratio(patches[(iu - 1) * nv], p * row, 1, prev[0], P, 0, 1, q + 1);
        }
        if (!(s > 0.0) || !std::isfinite(s)) return Status::numerical_overflow;
        cur[iv] = s;
        if (pass == 0) {
          if (iv > 0 &&
              !edge_agrees(patches[iu * nv + iv - 1], q, row, cur[iv - 1], P, 0, row, s, p + 1))
            return Status::numerical_overflow;
          if (iu > 0 &&
              !edge_agrees(patches[(iu - 1) * nv + iv], p * row, 1, prev[iv], P, 0, 1, s, q + 1))
            return Status::numerical_overflow;
          for (int k = 0; k < (p + 1) * row; ++k) {
            const double w = s * P.cp[k][0];
            if (!(w > 0.0) || !std::isfinite(w)) return Status::numerical_overflow;
            big = std::max(big, w);
          }
          continue;
        }
        for (int i = 0; i <= p; ++i)
          for (int j = 0; j <= q; ++j) {
            if ((i == 0 && iu > 0) || (j == 0 && iv > 0)) continue;  // the earlier patch's
            double* out = B.cp[(iu * p + i) * cv + iv * q + j];
            for (int c = 0; c < 4; ++c) out[c] = norm * s * P.cp[i * row + j][c];
          }
      }
      std::copy(cur, cur + nv, prev);
    }
    if (pass == 0) {
      int e = 0;
      std::frexp(big, &e);
      norm = std::ldexp(1.0, -e);
    }
  }
  // (N2): clamped knots, multiplicity = degree inside.
  int k = 0;
  for (int iu = 0; iu <= nu; ++iu) {
    const double u = iu < nu ? patches[iu * nv].u0 : patches[(nu - 1) * nv].u1;
    for (int r = 0; r < (iu == 0 || iu == nu ? p + 1 : p); ++r) B.knots_u[k++] = u;
  }
  k = 0;
  for (int iv = 0; iv <= nv; ++iv) {
    const double t = export_tau_of_v(iv < nv ? patches[iv].v0 : patches[nv - 1].v1);
    for (int r = 0; r < (iv == 0 || iv == nv ? q + 1 : q); ++r) B.knots_v[k++] = t;
  }
  return Status::ok;
}

namespace {

// The span k (U[k] <= x < U[k + 1], the last one closed) of a clamped knot
// vector with n control points and degree p; x clamped.
int find_span(const double* U, int n, int p, double& x) {
  x = std::min(U[n], std::max(U[p], x));
  const int k = int(std::upper_bound(U + p, U + n, x) - U) - 1;
  return std::min(n - 1, std::max(p, k));
}

// de Boor on d[0..p] (the points k - p .. k) at x.
void de_boor(const double* U, int p, int k, double x, double (*d)[4]) {
  for (int r = 1; r <= p; ++r)
    for (int j = p; j >= r; --j) {
      const double den = U[j + 1 + k - r] - U[j + k - p];
      const double al = den > 0.0 ? (x - U[j + k - p]) / den : 0.0;
      for (int c = 0; c < 4; ++c) d[j][c] = (1.0 - al) * d[j - 1][c] + al * d[j][c];
    }
}

}  // namespace

void nurbs_eval_homogeneous(const NurbsView& N, double u, double tau, double (&h)[4]) {
  const int p = N.size.deg_u, q = N.size.deg_v;
  const int ku = find_span(N.knots_u, N.size.cp_u, p, u);
  const int kv = find_span(N.knots_v, N.size.cp_v, q, tau);
  double col[kMaxExportDegreeV + 1][4];
  double d[kMaxExportDegree + 1][4];
  for (int jv = 0; jv <= q; ++jv) {
    const int c = kv - q + jv;
    for (int i = 0; i <= p; ++i)
      for (int m = 0; m < 4; ++m) d[i][m] = N.cp[(ku - p + i) * N.size.cp_v + c][m];
    de_boor(N.knots_u, p, ku, u, d);
    for (int m = 0; m < 4; ++m) col[jv][m] = d[p][m];
  }
  de_boor(N.knots_v, q, kv, tau, col);
  for (int m = 0; m < 4; ++m) h[m] = col[q][m];
}

Vec3d nurbs_point(const NurbsView& N, double u, double tau) {
  double h[4];
  nurbs_eval_homogeneous(N, u, tau, h);
  return Vec3d(h[1] / h[0], h[2] / h[0], h[3] / h[0]);
}

}  // namespace v0
}  // namespace cyclide
