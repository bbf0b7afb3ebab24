// Seed 001 §3.d, Theorem 3.6: ringed surfaces R : (d, n, rho = sqrt(R))
// with R a non-negative rational function that is not a square. We need a
// rational f with n.f = 0 and f.f = R (25); c = d + f (26) is then a
// rational curve on R and (3) parameterizes it.
//
// Route. Take a rational unit field u = U / omega perpendicular to n (the
// methods of ringed_field: exact projections, else the SOS of (20)-(23)).
// u and n x u span the circle's plane, so f = (a u + b n x u) / c for
// polynomials a, b, c with
//     a^2 + N b^2 = P c^2,   N = |n|^2,  P = R_num R_den          (*)
// (f = (a U + b n x U) / (omega c R_den)). (*) is a conic over R(t), the
// paper's (34)-(35) in other coordinates; the paper cites [33] for its
// solution. We solve it the way Legendre's equation is solved over Q,
// transplanted to R[t] (a Cremona/van Hoeij lattice argument):
//  1. Factor N and P over C (companion matrix, poly_roots), cluster
//     numerically repeated roots, and split each into a square part and a
//     squarefree part F of simple non-real roots (real roots of N, P >= 0
//     have even multiplicity; odd ones mean R < 0 somewhere).
//  2. Divide out the common roots G = gcd(F_N, F_P): a = G a1 turns (*)
//     into the diagonal conic G x^2 + N1 y^2 = P1 z^2 with G, N1, P1
//     positive on R, squarefree and pairwise coprime.
//  3. At each root zeta of one coefficient the conic forces one linear
//     condition, e.g. at a root of P1: x(zeta) = sqrt(-N1/G)(zeta) y(zeta)
//     (either square root). With deg x <= m + k, deg y <= g + k, deg z <=
//     g + m (deg G = 2g, N1 = 2m, P1 = 2k), every solution of the 2(g+m+k)
//     real conditions makes G x^2 + N1 y^2 - P1 z^2 a constant multiple
//     kappa of G N1 P1. The solutions form a space V of dimension >= 3 and
//     kappa is a quadratic form on V, indefinite (the form is unimodular
//     over R[t], so by Harder's theorem it is extended from R, where it has
//     the signature (2, 1) of (G, N1, -P1) at any real t); an isotropic
//     vector of kappa on V solves the conic.
//  4. Lower all three degree bounds while the conditions keep a null
//     vector (below the full degrees every null vector is a solution): the
//     lowest solution has no common real factor, so z has no real root and
//     f no 0/0 on R. Undo the substitutions, polish a, b, c by
//     Gauss-Newton on (*) itself (the roots of mixed magnitudes make the
//     conditions lose digits) and report the relative remainder of (*).
// The roots are numerical, so (*) holds to the reported residual (like the
// SOS step of (20)-(23)); f.n = 0 holds exactly whenever u is exact.
#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

#include "cyclide/pcurve.hpp"
#include "poly_roots.hpp"
#include "power_form.hpp"

namespace cyclide {
inline namespace v0 {

namespace {

using detail::max_abs;
using detail::kMaxRootsDegree;

constexpr int kWideCap = 2 * kMaxCurveDegree;  // room for a^2, N b^2, P c^2
using WidePoly = Poly<double, kWideCap>;
constexpr double kClusterTol = 1e-6;      // roots closer than this (relative) are one root
constexpr double kMaxConicResidual = 1e-8;

bool mul(const WidePoly& a, const WidePoly& b, WidePoly& r) { return multiply(a, b, r); }
WidePoly widen(const CurvePoly& p) {
  WidePoly w;
  w.assign(p);
  return w;
}

// p = lead * S(t)^2 * F(t) for p >= 0 on R. F = prod |t - z|^2 over its
// roots z (upper half plane, simple); S = prod over its roots: (t - r) for
// real r, |t - z|^2 for z in the upper half plane.
struct Factored {
  double lead = 0.0;
  Complex F[kMaxRootsDegree];
  int nF = 0;
  Complex S[kMaxRootsDegree];
  int nS = 0;
};

// Factor p >= 0 (Factored). empty_real_locus if p < 0 somewhere (negative
// lead, odd degree, a real root of odd multiplicity); not_pythagorean if the
// clustered roots do not account for the degree (too ill-conditioned).
Status factor_nonnegative(const CurvePoly& p_in, Factored& out) {
  CurvePoly p = p_in;
  p.trim_relative(1e-15);
  out = Factored();
  out.lead = p.c[p.deg];
  if (!(out.lead > 0)) return out.lead == 0 ? Status::invalid_argument : Status::empty_real_locus;
  if (p.deg == 0) return Status::ok;
  if (p.deg % 2 == 1) return Status::empty_real_locus;
  if (p.deg > kMaxRootsDegree) return Status::degree_too_high;
  Complex z[kMaxRootsDegree];
  if (detail::poly_roots(p, z) != p.deg) return Status::not_pythagorean;
  Complex sum[kMaxRootsDegree];
  int mult[kMaxRootsDegree], nc = 0;
  for (int i = 0; i < p.deg; ++i) {
    int j = 0;
    for (; j < nc; ++j) {
      const Complex c = sum[j] / double(mult[j]);
      if (std::abs(z[i] - c) <= kClusterTol * (1 + std::abs(c))) break;
    }
    if (j == nc) {
      sum[nc] = 0;
      mult[nc++] = 0;
    }
    sum[j] += z[i];
    ++mult[j];
  }
  int degree = 0;
  for (int j = 0; j < nc; ++j) {
    const Complex c = sum[j] / double(mult[j]);
    if (std::abs(c.imag()) <= kClusterTol * (1 + std::abs(c))) {  // a real root
      if (mult[j] % 2 == 1) return Status::empty_real_locus;      // p changes sign
      for (int k = 0; k < mult[j] / 2; ++k) out.S[out.nS++] = Complex(c.real(), 0.0);
      degree += mult[j];
    } else if (c.imag() > 0) {  // with its conjugate
      if (mult[j] % 2 == 1) out.F[out.nF++] = c;
      for (int k = 0; k < mult[j] / 2; ++k) out.S[out.nS++] = c;
      degree += 2 * mult[j];
    }
  }
  return degree == p.deg ? Status::ok : Status::not_pythagorean;
}

// prod over the roots r: (t - r) if r is real, |t - r|^2 otherwise.
WidePoly from_roots(const Complex* r, int n) {
  WidePoly p(1.0), q;
  for (int i = 0; i < n; ++i) {
    WidePoly f;
    if (r[i].imag() == 0.0) {
      f = WidePoly::linear(-r[i].real(), 1.0);
    } else {
      f.deg = 2;
      f.c[0] = std::norm(r[i]);
      f.c[1] = -2 * r[i].real();
      f.c[2] = 1.0;
    }
    multiply(p, f, q);  // degrees stay below the capacity: n <= 14 roots
    p = q;
  }
  return p;
}

// lead * prod |zeta - r|^2 (complex: zeta is a root of another factor).
Complex eval_roots(double lead, const Complex* r, int n, Complex zeta) {
  Complex s = lead;
  for (int i = 0; i < n; ++i) s *= (zeta - r[i]) * (zeta - std::conj(r[i]));
  return s;
}

// The diagonal conic A x^2 + B y^2 = C z^2 with A = prod|t - a_i|^2 (lead
// 1), B = bl prod|t - b_i|^2, C = cl prod|t - c_i|^2: coprime, squarefree,
// positive on R.
struct DiagonalConic {
  const Complex* a;
  int na;
  double bl;
  const Complex* b;
  int nb;
  double cl;
  const Complex* c;
  int nc;
  Complex A(Complex z) const { return eval_roots(1.0, a, na, z); }
  Complex B(Complex z) const { return eval_roots(bl, b, nb, z); }
  Complex C(Complex z) const { return eval_roots(cl, c, nc, z); }
};

constexpr int kMaxConicCols = 2 * kMaxRootsDegree + 3;  // 31
using ConicMatrix =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxConicCols, kMaxConicCols>;
using ConicVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxConicCols, 1>;

// The unknowns x, y, z of degrees <= dx, dy, dz as one coefficient vector
// (x's first), in tau = t / rho: rho = max(1, |roots|) keeps the
// Vandermonde rows of order one.
struct ConicLayout {
  int dx, dy, dz;
  double rho;
  int oy() const { return dx + 1; }
  int oz() const { return dx + dy + 2; }
  int cols() const { return dx + dy + dz + 3; }
};

// Step 3's conditions u(zeta) - s w(zeta) = 0, two normalized real rows
// per root (its conjugate gives the conjugate condition); rows beyond the
// conditions are zero (padding to a square matrix). Returns the row count,
// -1 for non-finite entries.
int conic_conditions(const DiagonalConic& Q, const ConicLayout& L, ConicMatrix& M) {
  const int cols = L.cols();
  M = ConicMatrix::Zero(std::max(cols, 2 * (Q.na + Q.nb + Q.nc)), cols);
  int row = 0;
  auto condition = [&](Complex zeta, int ou, int du, Complex s, int ow, int dw) {
    const Complex zh = zeta / L.rho;
    Complex r[kMaxConicCols];
    for (int j = 0; j < cols; ++j) r[j] = 0;
    Complex p = 1;
    for (int j = 0; j <= std::max(du, dw); ++j, p *= zh) {
      if (j <= du) r[ou + j] += p;
      if (j <= dw) r[ow + j] -= s * p;
    }
    double scale = 0;
    for (int j = 0; j < cols; ++j) scale = std::max(scale, std::abs(r[j]));
    for (int j = 0; j < cols; ++j) {
      M(row, j) = r[j].real() / scale;
      M(row + 1, j) = r[j].imag() / scale;
    }
    row += 2;
  };
  for (int i = 0; i < Q.na; ++i) {  // a root of A: B y^2 = C z^2
    const Complex z0 = Q.a[i];
    condition(z0, L.oy(), L.dy, std::sqrt(Q.C(z0) / Q.B(z0)), L.oz(), L.dz);
  }
  for (int i = 0; i < Q.nb; ++i) {  // a root of B: A x^2 = C z^2
    const Complex z0 = Q.b[i];
    condition(z0, 0, L.dx, std::sqrt(Q.C(z0) / Q.A(z0)), L.oz(), L.dz);
  }
  for (int i = 0; i < Q.nc; ++i) {  // a root of C: A x^2 = -B y^2
    const Complex z0 = Q.c[i];
    condition(z0, 0, L.dx, std::sqrt(-Q.B(z0) / Q.A(z0)), L.oy(), L.dy);
  }
  return M.allFinite() ? row : -1;
}

void unpack(const ConicLayout& L, const ConicVector& v, WidePoly& x, WidePoly& y, WidePoly& z) {
  x = WidePoly(), y = WidePoly(), z = WidePoly();
  x.deg = L.dx, y.deg = L.dy, z.deg = L.dz;
  for (int j = 0; j <= L.dx; ++j) x.c[j] = v(j) / std::pow(L.rho, j);
  for (int j = 0; j <= L.dy; ++j) y.c[j] = v(L.oy() + j) / std::pow(L.rho, j);
  for (int j = 0; j <= L.dz; ++j) z.c[j] = v(L.oz() + j) / std::pow(L.rho, j);
}

// Step 3 at the full degrees: an isotropic vector of kappa on the null space.
Status isotropic_solution(const DiagonalConic& Q, const ConicLayout& L, ConicVector& out) {
  ConicMatrix M;
  if (conic_conditions(Q, L, M) < 0) return Status::not_pythagorean;
  const int cols = L.cols();
  Eigen::JacobiSVD<ConicMatrix> svd(M, Eigen::ComputeFullV);
  const auto& sv = svd.singularValues();
  int dim = 0;  // the null space: at least the 3 padding dimensions
  for (int j = 0; j < cols; ++j)
    if (sv(j) <= 1e-9 * std::max(sv(0), 1.0)) ++dim;
  dim = std::max(dim, 3);
  const ConicMatrix V = svd.matrixV().rightCols(dim);
  // kappa: the leading coefficient of A x^2 + B y^2 - C z^2 on V, in tau
  // (t = rho tau scales A's leading coefficient by rho^(2g), x's by
  // rho^(-dx), ...), times rho^(2(g + m + k)).
  const double wa = std::pow(L.rho, 2 * Q.na), wb = Q.bl * std::pow(L.rho, 2 * Q.nb),
               wc = Q.cl * std::pow(L.rho, 2 * Q.nc);
  ConicMatrix K(dim, dim);
  const int ix = L.dx, iy = L.oy() + L.dy, iz = L.oz() + L.dz;
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j)
      K(i, j) = wa * V(ix, i) * V(ix, j) + wb * V(iy, i) * V(iy, j) - wc * V(iz, i) * V(iz, j);
  Eigen::SelfAdjointEigenSolver<ConicMatrix> es(K);
  if (es.info() != Eigen::Success) return Status::not_pythagorean;
  const double lmin = es.eigenvalues()(0), lmax = es.eigenvalues()(dim - 1);
  // A (numerically) zero eigenvalue: its vector has no leading terms, a
  // solution of lower degree (the reduction below lowers it further).
  const double tiny = 1e-10 * std::max(std::abs(lmin), std::abs(lmax));
  ConicVector v;
  if (std::abs(lmin) <= tiny) {
    v = es.eigenvectors().col(0);
  } else if (std::abs(lmax) <= tiny) {
    v = es.eigenvectors().col(dim - 1);
  } else if (lmin < 0 && lmax > 0) {  // an isotropic combination: kappa(v) = 0
    v = std::sqrt(lmax) * es.eigenvectors().col(0) +
        std::sqrt(-lmin) * es.eigenvectors().col(dim - 1);
  } else {
    return Status::not_pythagorean;  // definite contradicts Harder's theorem: rounding
  }
  out = V * v;
  return Status::ok;
}

// Below the full degrees (all lowered by j >= 1) the remainder's degree is
// below deg(A B C), so every null vector solves the conic: a solution
// times (t - t0) lies in the bounds of j - 1. The lowest j with a null
// vector gives a solution without a common real factor (z has no real root,
// so f has no 0/0 on R). False if none exists at j.
bool reduced_solution(const DiagonalConic& Q, const ConicLayout& L, ConicVector& out) {
  ConicMatrix M;
  if (conic_conditions(Q, L, M) < 0) return false;
  Eigen::JacobiSVD<ConicMatrix> svd(M, Eigen::ComputeFullV);
  const auto& sv = svd.singularValues();
  const int cols = L.cols();
  if (!(sv(cols - 1) <= 1e-10 * std::max(sv(0), 1.0))) return false;
  out = svd.matrixV().col(cols - 1);
  return true;
}

// The relative remainder of A x^2 + B y^2 - C z^2 (A, B, C from their roots).
double diagonal_remainder(const DiagonalConic& Q, const WidePoly& x, const WidePoly& y,
                          const WidePoly& z) {
  const WidePoly A = from_roots(Q.a, Q.na), B = from_roots(Q.b, Q.nb).scaled(Q.bl),
                 C = from_roots(Q.c, Q.nc).scaled(Q.cl);
  WidePoly x2, y2, z2, Ax2, By2, Cz2;
  if (!mul(x, x, x2) || !mul(y, y, y2) || !mul(z, z, z2) || !mul(A, x2, Ax2) ||
      !mul(B, y2, By2) || !mul(C, z2, Cz2))
    return HUGE_VAL;
  const double scale = std::max({max_abs(Ax2), max_abs(By2), max_abs(Cz2)});
  return scale > 0 ? max_abs(Ax2 + By2 - Cz2) / scale : HUGE_VAL;
}

Status solve_diagonal_conic(const DiagonalConic& Q, WidePoly& x, WidePoly& y, WidePoly& z) {
  ConicLayout L{Q.nb + Q.nc, Q.na + Q.nc, Q.na + Q.nb, 1.0};
  if (L.cols() > kMaxConicCols) return Status::degree_too_high;
  for (int i = 0; i < Q.na; ++i) L.rho = std::max(L.rho, std::abs(Q.a[i]));
  for (int i = 0; i < Q.nb; ++i) L.rho = std::max(L.rho, std::abs(Q.b[i]));
  for (int i = 0; i < Q.nc; ++i) L.rho = std::max(L.rho, std::abs(Q.c[i]));
  ConicVector v;
  if (Status st = isotropic_solution(Q, L, v); st != Status::ok) return st;
  unpack(L, v, x, y, z);
  // A small singular value can also be poor scaling (roots of mixed
  // magnitudes): a lowered solution is kept only if it solves the conic.
  for (ConicLayout R = L; R.dx > 0 && R.dy > 0 && R.dz > 0;) {
    --R.dx, --R.dy, --R.dz;
    ConicVector w;
    if (!reduced_solution(Q, R, w)) break;
    WidePoly x1, y1, z1;
    unpack(R, w, x1, y1, z1);
    if (!(diagonal_remainder(Q, x1, y1, z1) <= 1e-9)) break;
    x = x1, y = y1, z = z1;
  }
  return Status::ok;
}

bool narrow(const WidePoly& p, CurvePoly& out) {
  WidePoly q = p;
  q.trim();
  return out.assign(q);
}


// The relative remainder of (*): max|coef(a^2 + N b^2 - P c^2)| over the
// largest coefficient of the three terms; E receives the remainder.
double conic_remainder(const WidePoly& a, const WidePoly& b, const WidePoly& c, const WidePoly& N,
                       const WidePoly& P, WidePoly& E) {
  WidePoly a2, b2, c2, Nb2, Pc2;
  if (!mul(a, a, a2) || !mul(b, b, b2) || !mul(N, b2, Nb2) || !mul(c, c, c2) ||
      !mul(P, c2, Pc2))
    return HUGE_VAL;
  E = a2 + Nb2 - Pc2;
  const double scale = std::max({max_abs(a2), max_abs(Nb2), max_abs(Pc2)});
  return scale > 0 ? max_abs(E) / scale : HUGE_VAL;
}

// a, b, c = fa x, fb y, fc z (step 4's substitutions).
struct ConicFactors {
  WidePoly fa, fb, fc;
  bool compose(const WidePoly& x, const WidePoly& y, const WidePoly& z, WidePoly& a, WidePoly& b,
               WidePoly& c) const {
    return mul(fa, x, a) && mul(fb, y, b) && mul(fc, z, c);
  }
};

// Gauss-Newton on the coefficients of x, y, z against the given N and P:
// the roots (hence the conditions) are only as good as the companion
// eigenvalues, poor for roots of mixed magnitudes. The linearized identity
// 2 a fa dx + 2 N b fb dy - 2 P c fc dz = -E is solved in the least-squares,
// minimum-norm sense (Eigen's JacobiSVD) while it lowers the remainder; the
// factors fa, fb, fc (the square parts and G) stay exact.
constexpr int kMaxRefineCols = 3 * (kMaxCurveDegree + 1);  // 48
using RefineMatrix =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxRefineCols, kMaxRefineCols>;
using RefineVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxRefineCols, 1>;

// The state (x, y, z), its composition (a, b, c), remainder E and relative
// residual is carried from step to step (each accepted step was evaluated).
struct ConicIterate {
  WidePoly x, y, z, a, b, c, E;
  double residual = HUGE_VAL;
};

void refine_conic(const ConicFactors& F, const WidePoly& N, const WidePoly& P,
                  ConicIterate& s) {
  const WidePoly &x = s.x, &y = s.y, &z = s.z, &a = s.a, &b = s.b, &c = s.c, &E = s.E;
  const int cols = x.deg + y.deg + z.deg + 3;
  if (cols > kMaxRefineCols) return;
  for (int it = 0; it < 4 && s.residual > 1e-15; ++it) {
    WidePoly ga, gb, gc, t;
    // dE/dx_i = 2 a fa t^i, dE/dy_i = 2 N b fb t^i, dE/dz_i = -2 P c fc t^i.
    if (!mul(a, F.fa, ga) || !mul(N, b, t) || !mul(t, F.fb, gb) || !mul(P, c, t) ||
        !mul(t, F.fc, gc))
      return;
    const int rows = std::max(E.deg + 1, cols);
    if (rows > kMaxRefineCols) return;
    RefineMatrix J = RefineMatrix::Zero(rows, cols);
    RefineVector rhs = RefineVector::Zero(rows);
    for (int k = 0; k <= E.deg; ++k) rhs(k) = -E.c[k];
    auto column = [&](int col, const WidePoly& p, int shift, double f) {
      for (int k = 0; k <= p.deg && k + shift < rows; ++k) J(k + shift, col) += f * p.c[k];
    };
    for (int i = 0; i <= x.deg; ++i) column(i, ga, i, 2.0);
    for (int i = 0; i <= y.deg; ++i) column(x.deg + 1 + i, gb, i, 2.0);
    for (int i = 0; i <= z.deg; ++i) column(x.deg + y.deg + 2 + i, gc, i, -2.0);
    Eigen::JacobiSVD<RefineMatrix> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const RefineVector d = svd.solve(rhs);
    if (!d.allFinite()) return;
    ConicIterate next = s;
    for (int i = 0; i <= x.deg; ++i) next.x.c[i] += d(i);
    for (int i = 0; i <= y.deg; ++i) next.y.c[i] += d(x.deg + 1 + i);
    for (int i = 0; i <= z.deg; ++i) next.z.c[i] += d(x.deg + y.deg + 2 + i);
    if (!F.compose(next.x, next.y, next.z, next.a, next.b, next.c)) return;
    next.residual = conic_remainder(next.a, next.b, next.c, N, P, next.E);
    if (!(next.residual < s.residual)) return;
    s = next;
  }
}

// Steps 1-4: a, b, c with a^2 + N b^2 = P c^2; *residual its relative
// remainder, *conic_degree = deg(G N1 P1).
Status solve_norm_conic(const CurvePoly& N, const CurvePoly& P, WidePoly& a, WidePoly& b,
                        WidePoly& c, double& residual, int& conic_degree) {
  Factored fN, fP;
  if (Status st = factor_nonnegative(N, fN); st != Status::ok)
    return st == Status::empty_real_locus ? Status::not_pythagorean : st;
  if (Status st = factor_nonnegative(P, fP); st != Status::ok) return st;
  // Step 2: the common roots G of the squarefree parts.
  Complex G[kMaxRootsDegree], N1[kMaxRootsDegree], P1[kMaxRootsDegree];
  int ng = 0, nn = 0, np = 0;
  bool used[kMaxRootsDegree] = {};
  for (int i = 0; i < fN.nF; ++i) {
    int j = 0;
    for (; j < fP.nF; ++j)
      if (!used[j] && std::abs(fN.F[i] - fP.F[j]) <= kClusterTol * (1 + std::abs(fN.F[i])))
        break;
    if (j < fP.nF) {
      used[j] = true;
      G[ng++] = 0.5 * (fN.F[i] + fP.F[j]);
    } else {
      N1[nn++] = fN.F[i];
    }
  }
  for (int j = 0; j < fP.nF; ++j)
    if (!used[j]) P1[np++] = fP.F[j];
  conic_degree = 2 * (ng + nn + np);
  WidePoly x, y, z;
  const DiagonalConic Q{G, ng, fN.lead, N1, nn, fP.lead, P1, np};
  if (Status st = solve_diagonal_conic(Q, x, y, z); st != Status::ok) return st;
  // Undo: N = lead_N S_N^2 G N1', P = lead_P S_P^2 G P1' (primes: monic),
  // so a = G S_N S_P x, b = S_P y, c = S_N z.
  ConicFactors F;
  F.fb = from_roots(fP.S, fP.nS);
  F.fc = from_roots(fN.S, fN.nS);
  WidePoly t1;
  if (!mul(from_roots(G, ng), F.fc, t1) || !mul(t1, F.fb, F.fa)) return Status::degree_too_high;
  z.trim();
  const double s = max_abs(z);
  if (!(s > 0) || !std::isfinite(s)) return Status::not_pythagorean;
  x = x.scaled(1 / s), y = y.scaled(1 / s), z = z.scaled(1 / s);
  // The remainder of (*) with the given N and P, polished.
  ConicIterate it{x, y, z, {}, {}, {}, {}};
  if (!F.compose(x, y, z, it.a, it.b, it.c)) return Status::degree_too_high;
  const WidePoly Nw = widen(N), Pw = widen(P);
  it.residual = conic_remainder(it.a, it.b, it.c, Nw, Pw, it.E);
  refine_conic(F, Nw, Pw, it);
  a = it.a, b = it.b, c = it.c;
  residual = it.residual;
  a.trim(), b.trim(), c.trim();
  if (!(residual <= kMaxConicResidual)) return Status::not_pythagorean;
  return Status::ok;
}

Status sqrt_field_from_conic(const CurvePoly (&Nv)[3], const RationalField& u,
                             const CurvePoly& R_den, const WidePoly& a, const WidePoly& b,
                             const WidePoly& c, RationalField& f) {
  // n x U (U = u.F, |U| = |omega|).
  WidePoly nxU[3];
  for (int j = 0; j < 3; ++j) {
    const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
    WidePoly p, q;
    if (!mul(widen(Nv[j1]), widen(u.F[j2]), p) || !mul(widen(Nv[j2]), widen(u.F[j1]), q))
      return Status::degree_too_high;
    nxU[j] = p - q;
  }
  RationalField out;
  for (int j = 0; j < 3; ++j) {
    WidePoly p, q;
    if (!mul(a, widen(u.F[j]), p) || !mul(b, nxU[j], q)) return Status::degree_too_high;
    if (!narrow(p + q, out.F[j])) return Status::degree_too_high;
  }
  WidePoly w1, w2;
  if (!mul(widen(u.w), c, w1) || !mul(w1, widen(R_den), w2) || !narrow(w2, out.w))
    return Status::degree_too_high;
  f = out;
  return Status::ok;
}

}  // namespace

Status sqrt_radius_field(const RationalCurve& n, const CurvePoly& R_num, const CurvePoly& R_den,
                         const RingedFieldOptions& options, RationalField& f,
                         RingedSqrtReport* report) {
  if (!detail::finite(R_num) || !detail::finite(R_den)) return Status::not_finite;
  if (R_num.is_zero() || R_den.is_zero()) return Status::invalid_argument;
  if (n.kind != CurveKind::rational) return Status::invalid_argument;
  RingedSqrtReport rep;
  CurvePoly P;
  if (!multiply(R_num, R_den, P)) return Status::degree_too_high;
  // A square R_num R_den: rho = sqrt(R_num R_den) / R_den is rational.
  CurvePoly q;
  RationalField u;
  if (Status st = ringed_field(n, options, u, &rep.field); st != Status::ok) return st;
  if (poly_sqrt(P, q, 1e-12)) {
    RationalField out;
    for (int j = 0; j < 3; ++j)
      if (!multiply(q, u.F[j], out.F[j])) return Status::degree_too_high;
    if (!multiply(u.w, R_den, out.w)) return Status::degree_too_high;
    rep.exact_square = true;
    f = out;
    if (report) *report = rep;
    return Status::ok;
  }
  CurvePoly Nv[3], wn;
  detail::power_form(n, Nv, wn);
  for (const CurvePoly& p : Nv)
    if (2 * p.deg > kMaxCurveDegree) return Status::degree_too_high;
  CurvePoly N = detail::square_norm(Nv);
  N.trim();
  if (N.is_zero()) return Status::invalid_argument;
  WidePoly a, b, c;
  if (Status st = solve_norm_conic(N, P, a, b, c, rep.residual, rep.conic_degree);
      st != Status::ok)
    return st;
  RationalField out;
  if (Status st = sqrt_field_from_conic(Nv, u, R_den, a, b, c, out); st != Status::ok)
    return st;
  f = out;
  if (report) *report = rep;
  return Status::ok;
}

Status make_ringed_sqrt(const RationalCurve& d, const RationalCurve& n, const CurvePoly& R_num,
                        const CurvePoly& R_den, const RingedFieldOptions& options,
                        const Mobius* circle_f, double u0, double u1, Surface& out,
                        RingedSqrtReport* report, double* bad_u) {
  RationalField f;
  RingedSqrtReport rep;
  if (Status st = sqrt_radius_field(n, R_num, R_den, options, f, &rep); st != Status::ok)
    return st;
  RationalCurve c;
  const CurvePoly one(1.0);
  if (Status st = ringed_curve(d, one, one, f, c); st != Status::ok) return st;  // (26)
  Surface S;
  if (Status st = make_ringed(d, n, c, circle_f, u0, u1, S, bad_u); st != Status::ok) return st;
  out = S;
  if (report) *report = rep;
  return Status::ok;
}

}  // namespace v0
}  // namespace cyclide
