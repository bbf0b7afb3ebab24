// Similarity properties of the circle-family constructions (SPEC §9b.4,
// "PRCS, PRRS, ringed, Darboux, blends, n-way"): PRCS (seed 000 §3), PRRS
// (§4), ringed surfaces (d, n, c) and (d, n, rho) (seed 001 §2-3), and the
// surfaces carried through an inversion (seed 000 §5). Inputs moved by a
// random similarity g(x) = s R x + t (tests/hardening/similarity.hpp) must
// be accepted exactly when the originals are, and give the moved outputs to
// the bounds of canal_similarity_common.hpp.
//
// How the circle parameter moves (eq. (13): f = v is compared with the
// length of the rotation axis a): PRCS has a = s', scaled by s, so the same
// point has parameter s v; PRRS has a = n = (p1 - p2) x (p1 - p3), scaled
// by s^2, parameter s^2 v; (d, n, c) and (d, n, rho) take the caller's n,
// which is only rotated here, parameter v.

#include "canal_similarity_common.hpp"

using namespace canal_similarity;

namespace {

// ------------------------------------------------------------ conditioning
// The generators keep the models away from the degenerate configurations
// the builders refuse (which a similarity must not change either, but near
// them the outputs are ill-conditioned): the planes' relative determinant
// at least kMinDet on the scan, circles of radius at least kMinRadius L,
// spines and directrices within kMaxExtent L of the inputs.
constexpr double kMinDet = 2e-2;
constexpr double kMinRadius = 1e-2;
constexpr double kMaxExtent = 1e2;
constexpr int kScan = 33;

double scan_u(double u0, double u1, int k) { return u0 + (u1 - u0) * k / double(kScan - 1); }

double rel_det(const Vector3d& a, const Vector3d& b, const Vector3d& c) {
  const double den = a.norm() * b.norm() * c.norm();
  return den > 0 ? std::abs(a.dot(b.cross(c))) / den : 0.0;
}

void gen_domain(double& u0, double& u1) {
  static const double kLength[4] = {0.25, 0.5, 0.5, 1.0};
  u0 = gen_int(-2, 0) / 2.0;
  u1 = u0 + kLength[gen_int(0, 3)];
}

// An inversion of the model (center at least L/4 from the surface point)
// moved with it: g(x)^-1 at (g c, s r) = g(x^-1 at (c, r)).
void compare_inversion(Scene& A, cyc_surface* S, Scene& M, cyc_surface* T, const Similarity& g,
                       double L, const Vector3d& c0, double kv, double u, double v) {
  double x[3];
  RC_ASSERT(cyc_surface_eval(A.ctx, S, u, v, x, nullptr, nullptr, nullptr) == CYC_OK);
  const Vector3d center = c0 + L * gen_vec(8, 8);
  const double dist = (v3(x) - center).norm();
  if (!(dist >= 0.25 * L)) return;
  cyc_inversion i0{{center[0], center[1], center[2]}, L * (0.5 + gen_int(0, 8) / 8.0)};
  cyc_inversion i1;
  g.point(i0.center, i1.center);
  i1.radius = g.s * i0.radius;
  double y0[3], y1[3];
  RC_ASSERT(cyc_surface_eval_inverted(A.ctx, S, &i0, u, v, y0, nullptr, nullptr, nullptr) ==
            CYC_OK);
  RC_ASSERT(cyc_surface_eval_inverted(M.ctx, T, &i1, u, kv * v, y1, nullptr, nullptr,
                                      nullptr) == CYC_OK);
  // The inversion magnifies errors near its center by (r / dist)^2.
  const double mag = std::max(1.0, i0.radius * i0.radius / (dist * dist));
  check_point("inverted x' = g(inverted x)", y1, g.point(v3(y0)), Bounds(g, L), mag);
  cyc_circle_or_line k0, k1;
  const int sk0 = cyc_surface_circle_inverted(A.ctx, S, &i0, u, &k0);
  const int sk1 = cyc_surface_circle_inverted(M.ctx, T, &i1, u, &k1);
  RC_ASSERT(sk0 == sk1);
  if (sk0 == CYC_OK && !k0.is_line && !k1.is_line && k0.radius <= 10 * L) {
    check_point("inverted circle point' = g(point)", k1.point, g.point(v3(k0.point)),
                Bounds(g, L), mag * std::max(1.0, k0.radius / L));
  }
}

}  // namespace

// ------------------------------------------------------------ PRCS
namespace {

// p1, p2 with PRCS's conditioning (planes M, N, B of eqs. (8)-(10)) on
// the domain, and the model's extent.
bool prcs_conditioned(Scene& A, cyc_curve* p1, cyc_curve* p2, const CurveSpec& c2,
                      cyc_surface* S, double u0, double u1, Extent& E) {
  for (int k = 0; k < kScan; ++k) {
    const double u = scan_u(u0, u1, k);
    Vector3d q1, d1, q2, d2;
    curve_jet(A, p1, u, q1, d1);
    if (c2.kind == CurveSpec::line_element) {
      q2 = v3(c2.P);
      d2 = v3(c2.T);
    } else {
      curve_jet(A, p2, u, q2, d2);
    }
    if (!(rel_det(d1, d2, q1 - q2) >= kMinDet)) return false;
    cyc_sphere q;
    if (cyc_surface_sphere(A.ctx, S, u, &q) != CYC_OK) return false;
    E.add(q1);
    E.add(q2);
    E.add(v3(q.center));
    E.radius(std::sqrt(q.radius2));
  }
  return E.L <= kMaxExtent && E.min_radius >= kMinRadius * E.L;
}

}  // namespace

// PRCS(cubic, cubic) and PRCS(cubic, line element): the moved inputs give
// the moved canal surface, x'(u, s v) = g(x(u, v)), with its spheres,
// circles, ringed data (eq. (1)), canal test (eq. (2)) and inversions.
RC_GTEST_PROP(CanalSimilarity, PrcsMovesWithItsInputs, ()) {
  const bool element = gen_int(0, 3) == 0;
  const CurveSpec c1 = gen_cubic(), c2 = element ? gen_line_element() : gen_cubic();
  double u0, u1;
  gen_domain(u0, u1);
  Scene A;
  cyc_curve* p1 = A.curve(c1);
  cyc_curve* p2 = A.curve(c2);
  cyc_surface* S = nullptr;
  const int made_st = cyc_prcs_create(A.ctx, p1, p2, nullptr, u0, u1, &S);
  S = A.keep(made_st, S);
  RC_PRE(made(S));
  Extent E;
  RC_PRE(prcs_conditioned(A, p1, p2, c2, S, u0, u1, E));
  const Similarity g = *similarity::gen_similarity(E.L);
  RC_TAG(g.k < -10 ? "small" : g.k > 10 ? "large" : "unit");
  Scene M;
  cyc_surface* T = nullptr;
  const int st = cyc_prcs_create(M.ctx, M.curve(moved_points(c1, g)), M.curve(moved_points(c2, g)),
                                 nullptr, u0, u1, &T);
  RC_ASSERT(st == CYC_OK);
  M.keep(st, T);
  const double u = gen_u(u0, u1), v = gen_v();
  compare_surfaces(A, S, M, T, g, E.L, g.s, true, u, v);
  compare_canal_test(A, S, M, T, true, g, E.min_radius);
  compare_inversion(A, S, M, T, g, E.L, E.c0, g.s, u, v);
}

// ------------------------------------------------------------ PRRS
namespace {

bool prrs_conditioned(Scene& A, cyc_curve* const (&p)[3], cyc_surface* S, double u0,
                      double u1, Extent& E) {
  for (int k = 0; k < kScan; ++k) {
    const double u = scan_u(u0, u1, k);
    Vector3d q[3], d;
    for (int i = 0; i < 3; ++i) curve_jet(A, p[i], u, q[i], d);
    const Vector3d a = q[0] - q[1], b = q[0] - q[2];
    if (!(rel_det(a.cross(b), a, b) >= kMinDet)) return false;
    cyc_circle c;
    if (cyc_surface_circle(A.ctx, S, u, &c) != CYC_OK) return false;
    for (const Vector3d& x : q) E.add(x);
    E.add(v3(c.center));
    E.radius(std::sqrt(c.radius2));
  }
  return E.L <= kMaxExtent && E.min_radius >= kMinRadius * E.L;
}

}  // namespace

// PRRS(cubic, cubic, cubic) and PRRS(line, point, point) (canal, ERRATA):
// x'(u, s^2 v) = g(x(u, v)), circles, ringed data, canal test, inversions.
RC_GTEST_PROP(CanalSimilarity, PrrsMovesWithItsInputs, ()) {
  const bool lpp = gen_int(0, 3) == 0;
  CurveSpec c[3];
  if (lpp) {
    c[0] = gen_line();
    c[1] = gen_point();
    c[2] = gen_point();
  } else {
    for (CurveSpec& x : c) x = gen_cubic();
  }
  double u0, u1;
  gen_domain(u0, u1);
  Scene A;
  cyc_curve* p[3] = {A.curve(c[0]), A.curve(c[1]), A.curve(c[2])};
  cyc_surface* S = nullptr;
  const int made_st = cyc_prrs_create(A.ctx, p[0], p[1], p[2], nullptr, u0, u1, &S);
  S = A.keep(made_st, S);
  RC_PRE(made(S));
  Extent E;
  RC_PRE(prrs_conditioned(A, p, S, u0, u1, E));
  const Similarity g = *similarity::gen_similarity(E.L);
  Scene M;
  cyc_surface* T = nullptr;
  const int st = cyc_prrs_create(M.ctx, M.curve(moved_points(c[0], g)),
                                 M.curve(moved_points(c[1], g)), M.curve(moved_points(c[2], g)),
                                 nullptr, u0, u1, &T);
  RC_ASSERT(st == CYC_OK);
  M.keep(st, T);
  const double u = gen_u(u0, u1), v = gen_v();
  compare_surfaces(A, S, M, T, g, E.L, g.s * g.s, false, u, v);
  compare_canal_test(A, S, M, T, lpp, g, E.min_radius);
  compare_inversion(A, S, M, T, g, E.L, E.c0, g.s * g.s, u, v);
}

// ------------------------------------------------------------ (d, n, c)
// cyc_ringed_create: directrix d (cubic), orientation n (a cubic vector
// field, only rotated), the curve c (cubic); x'(u, v) = g(x(u, v)).
RC_GTEST_PROP(CanalSimilarity, RingedDncMovesWithItsInputs, ()) {
  CurveSpec d = gen_cubic(), n = gen_cubic(), c = gen_cubic();
  for (int k = 0; k <= 3; ++k) n.h[4 * k + 3] = k == 0 ? 1.0 : 0.0;  // polynomial n
  double u0, u1;
  gen_domain(u0, u1);
  Scene A;
  cyc_curve* cd = A.curve(d);
  cyc_curve* cn = A.curve(n);
  cyc_curve* cc = A.curve(c);
  cyc_surface* S = nullptr;
  const int made_st = cyc_ringed_create(A.ctx, cd, cn, cc, nullptr, u0, u1, &S);
  S = A.keep(made_st, S);
  RC_PRE(made(S));
  Extent E;
  double nmin = HUGE_VAL, nmax = 0;
  for (int k = 0; k < kScan; ++k) {
    const double u = scan_u(u0, u1, k);
    Vector3d x, dx;
    curve_jet(A, cd, u, x, dx);
    E.add(x);
    curve_jet(A, cc, u, x, dx);
    E.add(x);
    curve_jet(A, cn, u, x, dx);
    nmin = std::min(nmin, x.norm());
    nmax = std::max(nmax, x.norm());
    cyc_circle ci;
    RC_PRE(cyc_surface_circle(A.ctx, S, u, &ci) == CYC_OK);
    E.add(v3(ci.center));
    E.radius(std::sqrt(ci.radius2));
  }
  RC_PRE(nmin >= 0.1 * nmax && E.min_radius >= kMinRadius * E.L);
  const Similarity g = *similarity::gen_similarity(E.L);
  Scene M;
  cyc_surface* T = nullptr;
  const int st = cyc_ringed_create(M.ctx, M.curve(moved_points(d, g)),
                                   M.curve(moved_directions(n, g)), M.curve(moved_points(c, g)),
                                   nullptr, u0, u1, &T);
  RC_ASSERT(st == CYC_OK);
  M.keep(st, T);
  const double u = gen_u(u0, u1), v = gen_v();
  compare_surfaces(A, S, M, T, g, E.L, 1.0, false, u, v);
  compare_inversion(A, S, M, T, g, E.L, E.c0, 1.0, u, v);
}

// ------------------------------------------------------------ (d, n, rho)
// cyc_ringed_dnr_create with the projection field f = n x v / sigma (Prop.
// 3.2): n = (p^2 - q^2, 2 p q, r) (p, q, r linear) is Pythagorean for
// v = z; moved, n' = R n, v' = R v, rho' = s rho, and x'(u, v) = g(x(u, v)).
RC_GTEST_PROP(CanalSimilarity, RingedDnrMovesWithItsInputs, ()) {
  const CurveSpec d = gen_cubic();
  const double p0 = gen_signed(16, 8), p1 = gen_signed(16, 8), q0 = gen_signed(16, 8),
               q1 = gen_signed(16, 8), r0 = gen_signed(16, 8), r1 = gen_signed(16, 8);
  CurveSpec n;
  n.degree = 2;
  const double nc[3][3] = {{p0 * p0 - q0 * q0, 2 * (p0 * p1 - q0 * q1), p1 * p1 - q1 * q1},
                           {2 * p0 * q0, 2 * (p0 * q1 + p1 * q0), 2 * p1 * q1},
                           {r0, r1, 0}};
  for (int k = 0; k <= 2; ++k) {
    for (int j = 0; j < 3; ++j) n.h[4 * k + j] = nc[j][k];
    n.h[4 * k + 3] = k == 0 ? 1.0 : 0.0;
  }
  const double rho[2] = {1 + gen_int(0, 16) / 8.0, gen_signed(4, 8)};
  double u0, u1;
  gen_domain(u0, u1);
  Scene A;
  cyc_curve* cd = A.curve(d);
  cyc_curve* cn = A.curve(n);
  cyc_ringed_field_options fo;
  cyc_ringed_field_options_init(&fo);
  fo.method = CYC_RINGED_FIELD_PROJECTION;
  fo.v[0] = fo.v[1] = 0;
  fo.v[2] = 1;
  cyc_surface* S = nullptr;
  const int made_st = cyc_ringed_dnr_create(A.ctx, cd, cn, 1, rho, 0, nullptr, &fo, nullptr, u0, u1, &S,
                                   nullptr);
  S = A.keep(made_st, S);
  RC_PRE(made(S));
  Extent E;
  double smin = HUGE_VAL, smax = 0;
  for (int k = 0; k < kScan; ++k) {
    const double u = scan_u(u0, u1, k);
    Vector3d x, dx;
    curve_jet(A, cd, u, x, dx);
    E.add(x);
    E.radius(rho[0] + rho[1] * u);
    curve_jet(A, cn, u, x, dx);
    const double sigma = std::hypot(x[0], x[1]);
    smin = std::min(smin, sigma);
    smax = std::max(smax, x.norm());
  }
  RC_PRE(smin >= 0.1 * smax);
  const Similarity g = *similarity::gen_similarity(E.L);
  Scene M;
  cyc_ringed_field_options fm = fo;
  g.direction(fo.v, fm.v);
  const double rho_m[2] = {g.s * rho[0], g.s * rho[1]};
  cyc_surface* T = nullptr;
  const int st = cyc_ringed_dnr_create(M.ctx, M.curve(moved_points(d, g)),
                                       M.curve(moved_directions(n, g)), 1, rho_m, 0, nullptr,
                                       &fm, nullptr, u0, u1, &T, nullptr);
  RC_ASSERT(st == CYC_OK);
  M.keep(st, T);
  const double u = gen_u(u0, u1), v = gen_v();
  compare_surfaces(A, S, M, T, g, E.L, 1.0, false, u, v);
}

// ------------------------------------------------------------ DCMC
// Seed 000 §6: three lines with a common normal n (directions in the plane
// orthogonal to n, random points). The moved lines must be accepted or
// refused with the same status (parallel_lines, rank_deficient, ...), and
// the family's normal is R n. (The family's coefficients are a polynomial
// in absolute coordinates; they are compared by the status and normal, the
// membership of the lines is the construction's own check.)
RC_GTEST_PROP(CanalSimilarity, DcmcMovesWithItsLines, ()) {
  Vector3d n = gen_vec(8, 4);
  if (n.norm() < 0.5) n = Vector3d(0, 0, 1);
  n.normalize();
  const Vector3d e1 = n.unitOrthogonal(), e2 = n.cross(e1);
  cyc_line L[3], M[3];
  for (cyc_line& l : L) {
    const double a = gen_int(0, 179) * 3.14159265358979323846 / 180;
    const Vector3d d = std::cos(a) * e1 + std::sin(a) * e2, p = gen_vec();
    for (int j = 0; j < 3; ++j) {
      l.point[j] = p[j];
      l.direction[j] = d[j];
    }
  }
  Scene A, B;
  double n0[3], n1[3];
  cyc_darboux b0, q0, b1, q1;
  const int s0 = cyc_dcmc(A.ctx, L, n0, &b0, &q0);
  RC_TAG(s0 == CYC_OK ? "family" : "refused");
  Extent E;
  for (const cyc_line& l : L) E.add(v3(l.point));
  E.L = std::max(E.L, 1.0 / 8);
  const Similarity g = *similarity::gen_similarity(E.L);
  for (int i = 0; i < 3; ++i) {
    g.point(L[i].point, M[i].point);
    g.direction(L[i].direction, M[i].direction);
  }
  const int s1 = cyc_dcmc(B.ctx, M, n1, &b1, &q1);
  RC_ASSERT(s1 == s0);
  if (s0 != CYC_OK) return;
  const Bounds Bd(g, E.L);
  check_vector("dcmc normal' = R normal", n1, g.direction(v3(n0)), 1.0, Bd);
}

// ------------------------------------------------------------ regressions
// The findings of the properties, kept as deterministic cases.

namespace {

// Two cubics of the PRCS generator (a well-conditioned pair).
const double kP1[16] = {0, 0, 0, 1, 1, 0.5, 0, 0, 0, 0.25, 0.5, 0, 0.125, 0, 0, 0};
const double kP2[16] = {0, 1.5, 1, 1, 0.75, 0, -0.5, 0, 0, 0.5, 0, 0, 0, 0, 0.25, 0};

CurveSpec spec(const double (&h)[16]) {
  CurveSpec c;
  c.degree = 3;
  for (int k = 0; k < 16; ++k) c.h[k] = h[k];
  return c;
}

}  // namespace

// A PRCS moved 10^6 of its size from the origin keeps its touching spheres:
// the bisector plane (10) is formed about p1(u) (prcs_local_planes), where
// |p1|^2 - |p2|^2 in world coordinates lost eps |t|^2 / L (a radius off by
// ~1e-4 of itself at |t| = 10^6 L, against the bound 1e-6 here).
TEST(CanalSimilarityRegression, PrcsFarFromTheOriginKeepsItsSpheres) {
  for (const double far : {1e3, 1e6, 3e7}) {
    Similarity g;
    g.t = Vector3d(1, -2, 2) / 3.0 * far;
    Scene A, M;
    cyc_surface *S = nullptr, *T = nullptr;
    ASSERT_EQ(cyc_prcs_create(A.ctx, A.curve(spec(kP1)), A.curve(spec(kP2)), nullptr, 0, 1, &S),
              CYC_OK);
    A.keep(CYC_OK, S);
    ASSERT_EQ(cyc_prcs_create(M.ctx, M.curve(moved_points(spec(kP1), g)),
                              M.curve(moved_points(spec(kP2), g)), nullptr, 0, 1, &T),
              CYC_OK);
    M.keep(CYC_OK, T);
    const Bounds B(g, 2.0);
    for (int k = 0; k <= 8; ++k) {
      cyc_sphere a, b;
      ASSERT_EQ(cyc_surface_sphere(A.ctx, S, k / 8.0, &a), CYC_OK);
      ASSERT_EQ(cyc_surface_sphere(M.ctx, T, k / 8.0, &b), CYC_OK);
      EXPECT_LE((v3(b.center) - g.point(v3(a.center))).norm(), B.point()) << far;
      EXPECT_LE(std::abs(std::sqrt(b.radius2) - std::sqrt(a.radius2)), B.point()) << far;
    }
  }
}

// The same for PRRS: bisectors (25), (26) about p1(u).
TEST(CanalSimilarityRegression, PrrsFarFromTheOriginKeepsItsCircles) {
  const double kP3[16] = {1, -1, 0.5, 1, 0, 0.25, 1, 0, -0.5, 0, 0, 0, 0, 0.125, 0, 0};
  Similarity g;
  g.t = Vector3d(-2, 1, 2) / 3.0 * 2e6;
  Scene A, M;
  cyc_surface *S = nullptr, *T = nullptr;
  ASSERT_EQ(cyc_prrs_create(A.ctx, A.curve(spec(kP1)), A.curve(spec(kP2)), A.curve(spec(kP3)),
                            nullptr, 0, 1, &S),
            CYC_OK);
  A.keep(CYC_OK, S);
  ASSERT_EQ(cyc_prrs_create(M.ctx, M.curve(moved_points(spec(kP1), g)),
                            M.curve(moved_points(spec(kP2), g)),
                            M.curve(moved_points(spec(kP3), g)), nullptr, 0, 1, &T),
            CYC_OK);
  M.keep(CYC_OK, T);
  const Bounds B(g, 2.0);
  for (int k = 0; k <= 8; ++k) {
    cyc_circle a, b;
    ASSERT_EQ(cyc_surface_circle(A.ctx, S, k / 8.0, &a), CYC_OK);
    ASSERT_EQ(cyc_surface_circle(M.ctx, T, k / 8.0, &b), CYC_OK);
    EXPECT_LE((v3(b.center) - g.point(v3(a.center))).norm(), B.point());
    EXPECT_LE(std::abs(std::sqrt(b.radius2) - std::sqrt(a.radius2)), B.point());
  }
}

// DCMC of three lines 10^6 of their size away, or scaled by 2^30: the
// monomial system is solved in the lines' own normalized frame; in world
// coordinates its columns (1, |X|, |X|^2) were 10^12 apart and the lines
// looked rank deficient.
TEST(CanalSimilarityRegression, DcmcFarAwayOrLargeIsTheSameFamily) {
  const cyc_line L[3] = {{{0, 0, 0}, {1, 0, 0}}, {{0, 1, 0.5}, {0.6, 0.8, 0}},
                         {{1, 0, -0.5}, {0, 1, 0}}};
  Scene A;
  double n0[3];
  cyc_darboux b0, q0;
  ASSERT_EQ(cyc_dcmc(A.ctx, L, n0, &b0, &q0), CYC_OK);
  for (const int k : {-30, 0, 30})
    for (const double far : {0.0, 1e6}) {
      Similarity g;
      g.k = k;
      g.s = std::ldexp(1.0, k);
      g.R = similarity::rotation_of(0.3, -0.5, 0.7, 0.2);
      g.t = Vector3d(1, 2, -2) / 3.0 * far * g.s;
      cyc_line M[3];
      for (int i = 0; i < 3; ++i) {
        g.point(L[i].point, M[i].point);
        g.direction(L[i].direction, M[i].direction);
      }
      double n1[3];
      cyc_darboux b1, q1;
      ASSERT_EQ(cyc_dcmc(A.ctx, M, n1, &b1, &q1), CYC_OK) << k << " " << far;
      EXPECT_LE((v3(n1) - g.direction(v3(n0))).norm(), 1e-12) << k << " " << far;
    }
}
