// Rational Bezier export of sphere skins; the math (K1)-(K4) is in
// skin_export.hpp.
#include "cyclide/skin_export.hpp"

#include "export_pieces.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace cyclide {
inline namespace v0 {

namespace {

constexpr int kQ = kMaxSkinExportDegree;
constexpr int kDegU = kQ + 3;

// Fixed-capacity matrices: Eigen keeps them on the stack (no allocation).
using NodeMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kQ + 1, kQ + 1>;

double binomial(int n, int k) {
  double b = 1.0;
  for (int i = 1; i <= k; ++i) b = b * double(n - k + i) / double(i);
  return b;
}

// B_j^n(s), j = 0..n, by the recurrence B_j^d = (1 - s) B_j^{d-1} + s B_{j-1}^{d-1}.
void bernstein_basis(int n, double s, double* B) {
  B[0] = 1.0;
  for (int d = 1; d <= n; ++d) {
    double prev = 0.0;
    for (int j = 0; j < d; ++j) {
      const double b = B[j];
      B[j] = prev + (1.0 - s) * b;
      prev = s * b;
    }
    B[d] = prev;
  }
}

// The product of Bernstein polynomials f (degree m) and g (degree n) on
// the same interval: h_k = sum_{i+j=k} C(m,i) C(n,j) / C(m+n,k) f_i g_j.
void bernstein_product(const double* f, int m, const double* g, int n, double* h) {
  for (int k = 0; k <= m + n; ++k) h[k] = 0.0;
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= n; ++j)
      h[i + j] += binomial(m, i) * binomial(n, j) / binomial(m + n, i + j) * f[i] * g[j];
}

// (K3): Chebyshev-Lobatto nodes of degree q on [0, 1] and the inverse of
// the Bernstein collocation matrix there (node values -> coefficients).
struct Interpolator {
  int q = 0;
  double node[kQ + 1];
  NodeMatrix inverse;
};

void make_interpolator(int q, Interpolator& I) {
  I.q = q;
  for (int k = 0; k <= q; ++k) I.node[k] = 0.5 * (1.0 - std::cos(M_PI * k / q));
  I.node[0] = 0.0;
  I.node[q] = 1.0;
  NodeMatrix M(q + 1, q + 1);
  double B[kQ + 1];
  for (int k = 0; k <= q; ++k) {
    bernstein_basis(q, I.node[k], B);
    for (int j = 0; j <= q; ++j) M(k, j) = B[j];
  }
  I.inverse = Eigen::PartialPivLU<NodeMatrix>(M).inverse();
}

// V1, V2 interpolated on the t-interval [ta, tb] of one skin: Bernstein
// coefficients V[b][j] (b = 0: V1, 1: V2).
struct FrameFit {
  Vec3d V[2][kQ + 1];
};

void fit_frame(const SphereSkin& S, const Interpolator& I, double ta, double tb, FrameFit& F) {
  const int q = I.q;
  Vec3d val[2][kQ + 1];
  for (int k = 0; k <= q; ++k) {
    const double t = k == 0 ? ta : k == q ? tb : ta + I.node[k] * (tb - ta);
    skin_directions(S, t, val[0][k], val[1][k]);
  }
  for (int b = 0; b < 2; ++b) {
    for (int j = 0; j <= q; ++j) {
      Vec3d c = Vec3d::Zero();
      for (int k = 0; k <= q; ++k) c += I.inverse(j, k) * val[b][k];
      F.V[b][j] = c;
    }
    // The ends are the values themselves, so neighbours meet exactly.
    F.V[b][0] = val[b][0];
    F.V[b][q] = val[b][q];
  }
}

// (K4): the sampled bound of the interval, and the largest |lambda| seen.
double fit_error(const SphereSkin& S, const double (&L)[3][4], const Interpolator& I, double ta,
                 double tb, const FrameFit& F, double& lambda_max) {
  const int q = I.q;
  double err = 0.0, B[kQ + 1];
  for (int m = 0; m < q; ++m)
    for (double f : {0.25, 0.5, 0.75}) {
      const double s = I.node[m] + f * (I.node[m + 1] - I.node[m]);
      const double t = ta + s * (tb - ta);
      Vec3d V[2];
      skin_directions(S, t, V[0], V[1]);
      bernstein_basis(q, s, B);
      double d2 = 0.0;
      for (int b = 0; b < 2; ++b) {
        Vec3d y = Vec3d::Zero();
        for (int j = 0; j <= q; ++j) y += B[j] * F.V[b][j];
        d2 += (V[b] - y).squaredNorm();
      }
      const double lam = skin_lambda_max(L, t);
      lambda_max = std::max(lambda_max, lam);
      err = std::max(err, lam * std::sqrt(d2));
    }
  if (!std::isfinite(err)) return HUGE_VAL;
  return err;
}

// (K2): the v-pieces (export_pieces.hpp).
using detail::VPiece;

int v_pieces(const ExportDomain& D, VPiece (&p)[4]) {
  if (D.whole_circle) {
    p[0] = {true, -0.0, -1.0, -HUGE_VAL, -1.0};
    p[1] = {false, -1.0, 0.0, -1.0, 0.0};
    p[2] = {false, 0.0, 1.0, 0.0, 1.0};
    p[3] = {true, 1.0, 0.0, 1.0, HUGE_VAL};
    return 4;
  }
  double cut[5] = {D.v0};
  int nc = 1;
  for (double c : {-1.0, 0.0, 1.0})
    if (D.v0 < c && c < D.v1) cut[nc++] = c;
  cut[nc++] = D.v1;
  int n = 0;
  for (int i = 0; i + 1 < nc; ++i) {
    const double a = cut[i], b = cut[i + 1];
    const bool rec = b <= -1.0 || a >= 1.0;
    p[n++] = rec ? VPiece{true, 1.0 / a, 1.0 / b, a, b} : VPiece{false, a, b, a, b};
  }
  return n;
}

bool straight_spine(const SkinSpine& a) {
  const double n1 = a.c[1].norm();
  return a.c[1].cross(a.c[2]).norm() <= 1e-14 * n1 * a.c[2].norm() &&
         a.c[1].cross(a.c[3]).norm() <= 1e-14 * n1 * a.c[3].norm();
}

// A u-interval [ua, ub] of patch k (t = u - k).
struct Interval {
  int k;
  double ua, ub;
};

struct Plan {
  Interval iv[kMaxExportUPieces];
  int nu = 0;
  VPiece v[4];
  int nv = 0;
  double error = 0.0, lambda_max = 0.0;
};

Status check_input(const SphereSkin* skins, int n, const ExportDomain& D,
                   const SkinExportOptions& o) {
  if (!skins) return Status::null_argument;
  if (n < 1 || !(o.tolerance > 0.0) || !std::isfinite(o.tolerance) || o.degree < 1 ||
      o.degree > kQ)
    return Status::invalid_argument;
  if (!std::isfinite(D.u0) || !std::isfinite(D.u1) ||
      (!D.whole_circle && (!std::isfinite(D.v0) || !std::isfinite(D.v1))))
    return Status::not_finite;
  if (!(D.u0 >= 0.0 && D.u0 < D.u1 && D.u1 <= double(n))) return Status::bad_domain;
  if (!D.whole_circle && !(D.v0 < D.v1)) return Status::bad_domain;
  return Status::ok;
}

// The u-intervals: each patch's part of [u0, u1], bisected depth first
// (left first, so they come out in order) until the bound (K4) holds.
Status plan(const SphereSkin* skins, int n, const ExportDomain& D, const SkinExportOptions& o,
            const Interpolator& I, Plan& L) {
  L.nv = v_pieces(D, L.v);
  L.nu = 0;
  const int k0 = std::min(n - 1, int(std::floor(D.u0)));
  for (int k = k0; k < n && double(k) < D.u1; ++k) {
    const SphereSkin& S = skins[k];
    double Lp[3][4];
    skin_lambda_polynomials(S, Lp);
    struct Item {
      double a, b;
      int depth;
    } stack[kMaxExportDepth + 2];
    int top = 0;
    stack[top++] = {std::max(D.u0, double(k)), std::min(D.u1, double(k + 1)), 0};
    while (top > 0) {
      const Item it = stack[--top];
      FrameFit F;
      fit_frame(S, I, it.a - k, it.b - k, F);
      const double err = fit_error(S, Lp, I, it.a - k, it.b - k, F, L.lambda_max);
      if (err <= o.tolerance) {
        if (L.nu == kMaxExportUPieces) return Status::numerical_overflow;
        L.iv[L.nu++] = {k, it.a, it.b};
        L.error = std::max(L.error, err);
        continue;
      }
      if (it.depth == kMaxExportDepth) return Status::numerical_overflow;
      const double mid = 0.5 * (it.a + it.b);
      stack[top++] = {mid, it.b, it.depth + 1};
      stack[top++] = {it.a, mid, it.depth + 1};
    }
  }
  return Status::ok;
}

// The patch of interval I on v-piece p: (K1) with the fit (K3).
void build_patch(const SphereSkin& S, const Interval& J, const FrameFit& F, int q, const VPiece& p,
                 RationalBezierPatch& P) {
  const int n = q + 3;
  const double ta = J.ua - J.k, tb = J.ub - J.k;
  // u: alpha elevated to degree n, and the products L_a V_b (degree n).
  double L[3][4], Lb[3][4];
  skin_lambda_polynomials(S, L);
  for (int a = 0; a < 3; ++a) bernstein_from_power(L[a], 3, ta, tb, Lb[a]);
  double A[3][kDegU + 1], ones[kQ + 1];
  std::fill(ones, ones + q + 1, 1.0);
  for (int c = 0; c < 3; ++c) {
    double pw[4], al[4];
    for (int i = 0; i < 4; ++i) pw[i] = S.spine.c[i][c];
    bernstein_from_power(pw, 3, ta, tb, al);
    bernstein_product(al, 3, ones, q, A[c]);
  }
  double PV[3][2][3][kDegU + 1];
  for (int b = 0; b < 2; ++b)
    for (int c = 0; c < 3; ++c) {
      double v[kQ + 1];
      for (int j = 0; j <= q; ++j) v[j] = F.V[b][j][c];
      for (int a = 0; a < 3; ++a) bernstein_product(Lb[a], 3, v, q, PV[a][b][c]);
    }
  // v: omega, C, S and their products (degree 4).
  double T[3][3];
  detail::v_controls<double>(p, 1.0, 0.0, 1.0, T[0]);   // omega = 1 + v^2
  detail::v_controls<double>(p, 1.0, 0.0, -1.0, T[1]);  // C = 1 - v^2
  detail::v_controls<double>(p, 0.0, 2.0, 0.0, T[2]);   // S = 2 v
  double TT[3][2][5], ww[5];
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 2; ++b) bernstein_product(T[a], 2, T[1 + b], 2, TT[a][b]);
  bernstein_product(T[0], 2, T[0], 2, ww);
  P.deg_u = n;
  P.deg_v = 4;
  P.u0 = J.ua;
  P.u1 = J.ub;
  P.v0 = p.v0;
  P.v1 = p.v1;
  P.reciprocal_v = p.rec;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= 4; ++j) {
      double* h = P.cp[i * 5 + j];
      h[0] = ww[j];
      for (int c = 0; c < 3; ++c) {
        double x = A[c][i] * ww[j];
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 2; ++b) x += PV[a][b][c][i] * TT[a][b][j];
        h[1 + c] = x;
      }
    }
  // The largest weight in [0.5, 1) (a power of two: exact).
  double big = 0.0;
  for (int j = 0; j <= 4; ++j) big = std::max(big, ww[j]);
  int e = 0;
  std::frexp(big, &e);
  for (int i = 0; i < (n + 1) * 5; ++i)
    for (int c = 0; c < 4; ++c) P.cp[i][c] = std::ldexp(P.cp[i][c], -e);
}

// (K4): the patch against skin_eval at 5 x 5 points.
Status check_patch(const SphereSkin& S, int k, const RationalBezierPatch& P, double tolerance,
                   double& deviation) {
  double dev = 0.0, size = 0.0;
  for (double s : {0.0, 0.25, 0.5, 0.75, 1.0})
    for (double r : {0.0, 0.25, 0.5, 0.75, 1.0}) {
      double u, v;
      patch_parameters(P, s, r, u, v);
      const double t = std::min(1.0, std::max(0.0, u - k));
      double x[3];
      if (Status st = skin_eval(S, 2.0 * std::atan(v), t, x, nullptr, nullptr, nullptr);
          st != Status::ok)
        return st;
      const Vec3d xv(x[0], x[1], x[2]);
      const Vec3d y = patch_point(P, s, r);
      dev = std::max(dev, (y - xv).norm());
      size = std::max(size, xv.norm());
    }
  if (!(dev <= 2.0 * tolerance + 1e-12 * size)) return Status::numerical_overflow;
  deviation = std::max(deviation, dev);
  return Status::ok;
}

}  // namespace

Status export_sphere_skin(const SphereSkin* skins, int n, const ExportDomain& D,
                          const SkinExportOptions& options, RationalBezierPatch* out, int cap,
                          int& count, SkinExportReport* report) {
  count = 0;
  if (Status st = check_input(skins, n, D, options); st != Status::ok) return st;
  Interpolator I;
  make_interpolator(options.degree, I);
  Plan L;
  if (Status st = plan(skins, n, D, options, I, L); st != Status::ok) return st;
  const int need = L.nu * L.nv;
  if (need > cap) {
    count = need;
    return Status::buffer_too_small;
  }
  if (!out) return Status::null_argument;
  // Pass 0 builds and checks every patch in a scratch patch; pass 1 writes
  // (the same arithmetic), so out is never left half-written.
  RationalBezierPatch scratch;
  double deviation = 0.0;
  for (int pass = 0; pass < 2; ++pass) {
    int m = 0;
    for (int iu = 0; iu < L.nu; ++iu) {
      const Interval& J = L.iv[iu];
      const SphereSkin& S = skins[J.k];
      FrameFit F;
      fit_frame(S, I, J.ua - J.k, J.ub - J.k, F);
      for (int iv = 0; iv < L.nv; ++iv) {
        RationalBezierPatch& P = pass == 0 ? scratch : out[m];
        ++m;
        build_patch(S, J, F, options.degree, L.v[iv], P);
        if (pass == 0)
          if (Status st = check_patch(S, J.k, P, options.tolerance, deviation); st != Status::ok)
            return st;
      }
    }
  }
  if (report) {
    report->error_estimate = std::max(L.error, deviation);
    double rmf = 0.0;
    bool exact = true;
    for (int iu = 0; iu < L.nu; ++iu) {
      const SphereSkin& S = skins[L.iv[iu].k];
      rmf = std::max(rmf, S.rmf.error_estimate);
      exact = exact && S.delta == 0.0 && straight_spine(S.spine);
    }
    report->rmf_error = rmf * L.lambda_max;
    report->exact = exact;
    report->t_intervals = L.nu;
  }
  count = need;
  return Status::ok;
}

}  // namespace v0
}  // namespace cyclide
