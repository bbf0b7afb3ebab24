// Similarity properties of the blends (SPEC §9b.4, "PRCS, PRRS, ringed,
// Darboux, blends, n-way"): canal and ringed blends (seed 000 §9), the
// P-curve blend of two ringed jets (seed 001 §4) and the n-way blend
// through an auxiliary sphere (seed 001 §6). The ends are moved by a random
// similarity g; the blend of the moved ends must be built exactly when the
// original is (the same status) and be the moved blend, to the bounds of
// canal_similarity_common.hpp.
//
// How the ends' data move: surfaces with their inputs, the end parameter u
// and the tangent length lambda = phi' not at all (they are parameters),
// the circle parameters v like the surface's (s v for PRCS, s^2 v for
// PRRS); jets (d, d') as a point and a vector, (n, n') rotated (n is an
// orientation, its length a parameter), (rho, rho') scaled by s.

#include "canal_similarity_common.hpp"

using namespace canal_similarity;

namespace {

// A blend is compared only where it is well conditioned: its circles turn
// by at most kMaxTurn radians and |rho rho'| stays below kMaxTurn L^2 per
// unit of its parameter (a blend whose radius or plane changes faster than
// that over [t0, t1] amplifies the rounding of its data beyond the bounds;
// cf. kMaxAxisTurn of tests/properties_test.cpp).
constexpr double kMaxTurn = 20;

// The extent of a blend surface from its circles on [t0, t1]; *ok = false
// where it is not well conditioned (above).
Extent blend_extent(Scene& A, cyc_surface* S, double t0, double t1, bool* ok = nullptr) {
  Extent E;
  double turn = 0, rate = 0, speed = 0;
  Vector3d prev = Vector3d::Zero();
  for (int k = 0; k <= 8; ++k) {
    const double u = t0 + (t1 - t0) * k / 8.0;
    cyc_circle c;
    RC_ASSERT(cyc_surface_circle(A.ctx, S, u, &c) == CYC_OK);
    E.add(v3(c.center));
    E.radius(std::sqrt(c.radius2));
    if (k > 0) turn += std::acos(std::max(-1.0, std::min(1.0, prev.dot(v3(c.normal)))));
    prev = v3(c.normal);
    double rr = 0;
    RC_ASSERT(cyc_surface_ringed_data(A.ctx, S, u, nullptr, nullptr, nullptr, &rr) == CYC_OK);
    rate = std::max(rate, std::abs(rr) * std::abs(t1 - t0));
    // Near a stationary point of the spine (s' -> 0) the axis flips within
    // a short interval and x_u is huge: the speed |x_u| bounds that.
    for (const double v : {-1.0, 0.0, 1.0, 1e8}) {
      double x[3], xu[3];
      RC_ASSERT(cyc_surface_eval(A.ctx, S, u, v, x, xu, nullptr, nullptr) == CYC_OK);
      speed = std::max(speed, v3(xu).norm() * std::abs(t1 - t0));
    }
  }
  if (ok)
    *ok = turn <= kMaxTurn && rate <= kMaxTurn * E.L * E.L && speed <= kMaxTurn * E.L;
  return E;
}

// Two surfaces to blend: PRCS of two random lines (canal) or PRRS of three
// (ringed) on [0, 1], the second moved apart by 4 along a random direction.
struct Pair {
  CurveSpec c[2][3];
  int curves = 2;
};

// The two cones of seed 000 Fig. 6 (apex 0 and (4, 0, 4), axes z and -x;
// PRRS of three rulings on [1/2, 1]), each apex moved by up to 1/4: the
// canal blend of random lines is mostly ill-conditioned (its planes M, N
// near dependent somewhere), the cones' blend is the paper's.
Pair fig6_cones() {
  Pair P;
  P.curves = 3;
  const Vector3d apex[2] = {gen_vec(2, 8), Vector3d(4, 0, 4) + gen_vec(2, 8)};
  const Vector3d e[2][3] = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 1, 0}, {0, 0, 1}, {-1, 0, 0}}};
  for (int i = 0; i < 2; ++i)
    for (int k = 0; k < 3; ++k) {
      const double t = 2 * 3.14159265358979323846 * k / 3 + 0.3;
      const Vector3d d = std::cos(t) * e[i][0] + std::sin(t) * e[i][1] + e[i][2];
      CurveSpec& c = P.c[i][k];
      c.degree = 1;
      for (int j = 0; j < 3; ++j) {
        c.h[j] = apex[i][j];
        c.h[4 + j] = d[j];
      }
      c.h[3] = 1;
    }
  return P;
}

Pair gen_pair(bool canal) {
  if (canal) return fig6_cones();
  Pair P;
  P.curves = 3;
  Vector3d off = gen_vec();
  if (off.norm() < 0.5) off = Vector3d(1, 1, 0);
  off = 4 * off.normalized();
  for (int i = 0; i < 2; ++i)
    for (int k = 0; k < P.curves; ++k) {
      P.c[i][k] = gen_line();
      if (i == 1)
        for (int j = 0; j < 3; ++j) P.c[i][k].h[j] += off[j];
    }
  return P;
}

cyc_surface* build(Scene& A, const CurveSpec (&c)[3], int curves, double u0 = 0) {
  cyc_surface* S = nullptr;
  const int st = curves == 2
                     ? cyc_prcs_create(A.ctx, A.curve(c[0]), A.curve(c[1]), nullptr, u0, 1, &S)
                     : cyc_prrs_create(A.ctx, A.curve(c[0]), A.curve(c[1]), A.curve(c[2]),
                                       nullptr, u0, 1, &S);
  return A.keep(st, S);
}

// A blend of the two (canal: cyc_blend_canal, ringed: cyc_blend_ringed or
// the matched one) and the same of the moved pair.
void blend_property(bool canal, bool matched) {
  const Pair P = gen_pair(canal);
  Scene A;
  // Both cones end at u = 1 (their base circles) on [1/2, 1]; the random
  // lines' surfaces run on [0, 1], the first ends at 1, the second starts.
  const double u0 = canal ? 0.5 : 0.0;
  cyc_surface* S[2] = {build(A, P.c[0], P.curves, u0), build(A, P.c[1], P.curves, u0)};
  RC_PRE(made(S[0]) && made(S[1]));
  // The ends' extent: their circles at the ends.
  Extent E0;
  for (int i = 0; i < 2; ++i) {
    cyc_circle c;
    RC_ASSERT(cyc_surface_circle(A.ctx, S[i], canal || i == 0 ? 1.0 : 0.0, &c) == CYC_OK);
    E0.add(v3(c.center));
    E0.radius(std::sqrt(c.radius2));
  }
  RC_PRE(E0.min_radius >= 1e-2 * E0.L && E0.L <= 1e2);
  // K = 3 (degree-7 Hermite curves, a PRCS spine of degree ~66) costs most
  // of the property's time: one case in four.
  const int K = canal ? (gen_int(0, 3) == 0 ? 3 : 2) : gen_int(1, 3);
  cyc_blend_end e[2] = {};
  for (int i = 0; i < 2; ++i) {
    e[i].surface = S[i];
    e[i].u = canal || i == 0 ? 1.0 : 0.0;
    for (int j = 0; j < 3; ++j) e[i].v[j] = std::tan(-1.2 + 1.1 * j + gen_int(-20, 20) / 100.0);
    // Cones: the blend leaves the first at its base and enters the second
    // at its base, against its u (Fig. 6).
    e[i].lambda = (1 + gen_int(0, 8) / 4.0) * (canal && i == 1 ? -1 : 1);
  }
  auto make = [&](Scene& X, const cyc_blend_end* ends, cyc_surface** out) {
    return canal ? cyc_blend_canal(X.ctx, &ends[0], &ends[1], K, 0, 1, out)
           : matched ? cyc_blend_ringed_matched(X.ctx, &ends[0], &ends[1], K, 0, 1, out)
                     : cyc_blend_ringed(X.ctx, &ends[0], &ends[1], K, 0, 1, out);
  };
  cyc_surface* B = nullptr;
  const int s0 = make(A, e, &B);
  A.keep(s0, B);
  RC_TAG(s0 == CYC_OK ? "built" : "refused");
  const Similarity g = *similarity::gen_similarity(E0.L);
  // The ends are PRRS (v -> s^2 v); the canal blend is a PRCS (v -> s v).
  const double kv_end = g.s * g.s, kv = canal ? g.s : g.s * g.s;
  Scene M;
  Pair Q = P;
  for (int i = 0; i < 2; ++i)
    for (int k = 0; k < P.curves; ++k) Q.c[i][k] = moved_points(P.c[i][k], g);
  cyc_surface* T[2] = {build(M, Q.c[0], Q.curves, u0), build(M, Q.c[1], Q.curves, u0)};
  RC_ASSERT(made(T[0]) && made(T[1]));
  cyc_blend_end f[2] = {e[0], e[1]};
  for (int i = 0; i < 2; ++i) {
    f[i].surface = T[i];
    for (int j = 0; j < 3; ++j) f[i].v[j] = kv_end * e[i].v[j];
  }
  cyc_surface* C = nullptr;
  const int s1 = make(M, f, &C);
  M.keep(s1, C);
  RC_ASSERT(s1 == s0);
  if (s0 != CYC_OK) return;
  bool conditioned = false;
  Extent E = blend_extent(A, B, 0, 1, &conditioned);
  RC_PRE(conditioned && E.min_radius >= 1e-2 * E.L && E.L <= 1e3 * E0.L);
  if (canal) {
    // The canal blend's planes M, N, B (PRCS of its Hermite curves) near
    // dependent send the spine s away: touching spheres of radius r far
    // beyond their circles' rho. Kept to r <= kMaxTurn rho (the PRCS
    // property filters the planes' relative determinant directly).
    for (int k = 0; k <= 8; ++k) {
      cyc_sphere q;
      cyc_circle c;
      RC_ASSERT(cyc_surface_sphere(A.ctx, B, k / 8.0, &q) == CYC_OK);
      RC_ASSERT(cyc_surface_circle(A.ctx, B, k / 8.0, &c) == CYC_OK);
      RC_PRE(q.radius2 <= kMaxTurn * kMaxTurn * c.radius2);
    }
  }
  E.L = std::max(E.L, E0.L);
  // The blend is PRCS (canal) or PRRS (ringed) of Hermite curves of the
  // moved points and derivatives: the same v scaling as its ends. The
  // matched blend's f interpolates the ends' Mobius maps, which scale the
  // same way.
  const double t = gen_int(0, 16) / 16.0, v = gen_v();
  // The blend's curves are Hermite curves of degree 2K + 1 through the
  // moved end data: their Bernstein derivatives (the PRCS normal planes)
  // carry the rounding eps |t| of the moved control points times up to
  // 2K + 1.
  compare_surfaces(A, B, M, C, g, E.L, kv, canal, t, v, 2 * K + 1);
  // The joins: continuity reports of the moved blend equal the original's
  // (gaps as lengths, angles and relative jumps as numbers).
  for (int i = 0; i < 2; ++i) {
    cyc_continuity r0, r1;
    const double ua = 1.0, ub = i == 1 && canal ? 1.0 : 0.0;  // S0(1) -> B(0), B(1) -> S1
    const cyc_surface* a0 = i == 0 ? S[0] : B;
    const cyc_surface* b0 = i == 0 ? B : S[1];
    const cyc_surface* a1 = i == 0 ? T[0] : C;
    const cyc_surface* b1 = i == 0 ? C : T[1];
    const double lam = i == 0 ? e[0].lambda : 1.0 / e[1].lambda;  // du_a / du_b (signed)
    const int k0 = cyc_continuity_report(A.ctx, a0, ua, lam, b0, ub, 1, nullptr, 8, &r0);
    const int k1 = cyc_continuity_report(M.ctx, a1, ua, lam, b1, ub, 1, nullptr, 8, &r1);
    RC_ASSERT(k0 == k1);
    if (k0 != CYC_OK) continue;
    const Bounds Bd(g, E.L);
    SIM_CHECK("join gap' = s gap", std::abs(r1.max_gap - g.s * r0.max_gap),
              4 * (2 * K + 1) * Bd.point());
    SIM_CHECK("join angle' = angle", std::abs(r1.max_normal_angle - r0.max_normal_angle),
              1e3 * Bd.rel());
  }
}

}  // namespace

// Canal blend (§9.1, Prop. 6) of two PRCS of lines, K = 2, 3.
RC_GTEST_PROP(CanalSimilarity, CanalBlendMovesWithItsEnds, ()) { blend_property(true, false); }

// Ringed blend (§9.2, Prop. 7) of two PRRS of lines, K = 1..3, with f = v
// or matched to the ends' circle parameters.
RC_GTEST_PROP(CanalSimilarity, RingedBlendMovesWithItsEnds, ()) {
  blend_property(false, gen_int(0, 1) == 1);
}

// ------------------------------------------------------------ P-curve blend
namespace {

// The amplification of the moved jets' rounding eps |t| by the P-curve
// blend: the degree of its P-curve (6, eq. (43)).
constexpr double kPcurveAmp = 6;

cyc_ringed_jet gen_jet(const Vector3d& at) {
  cyc_ringed_jet J;
  const Vector3d d = at + gen_vec(8, 8), dd = gen_vec(16, 4);
  Vector3d n = gen_vec(8, 4);
  if (n.norm() < 0.5) n = Vector3d(0.5, 1, 0.25);
  const Vector3d dn = gen_vec(8, 8);
  for (int j = 0; j < 3; ++j) {
    J.d[j] = d[j];
    J.dd[j] = dd[j];
    J.n[j] = n[j];
    J.dn[j] = dn[j];
  }
  J.rho = 0.5 + gen_int(0, 8) / 8.0;
  J.drho = gen_signed(8, 16);
  return J;
}

cyc_ringed_jet moved_jet(const cyc_ringed_jet& J, const Similarity& g) {
  cyc_ringed_jet K;
  g.point(J.d, K.d);
  g.vector(J.dd, K.dd);
  g.direction(J.n, K.n);
  g.direction(J.dn, K.dn);
  K.rho = g.s * J.rho;
  K.drho = g.s * J.drho;
  return K;
}

}  // namespace

// Seed 001 §4: the P-curve blend (43) or P-biarc (47) of two random jets
// along a projection direction v: moved jets and R v give the moved pieces
// (the circles; f = n x v / sigma moves with them).
RC_GTEST_PROP(CanalSimilarity, PcurveBlendMovesWithItsJets, ()) {
  const cyc_ringed_jet a = gen_jet(Vector3d::Zero()), b = gen_jet(Vector3d(3, 1, 0));
  cyc_pcurve_blend_options o;
  cyc_pcurve_blend_options_init(&o);
  o.sign = gen_int(0, 1) ? 1 : -1;
  if (gen_int(0, 3) == 0) o.tau = gen_int(1, 7) / 8.0;
  Vector3d v = gen_vec(8, 4);
  if (v.norm() < 0.5) v = Vector3d(0, 0, 1);
  for (int j = 0; j < 3; ++j) o.v[j] = v[j];
  // (43) and (47) pair the square roots of the end data p0, p1 (n projected
  // on the plane of v) so that the P-curve turns by less than half a turn;
  // where p1 is nearly opposite to p0 the two pairings tie and the
  // rounding of the moved jets may pick either: a decision boundary of the
  // construction, kept 10 degrees away.
  {
    const Vector3d vu = v.normalized(), na = v3(a.n), nb = v3(b.n);
    const Vector3d pa = na - na.dot(vu) * vu, pb = nb - nb.dot(vu) * vu;
    RC_PRE(pa.dot(pb) >= -std::cos(10.0 * 3.14159265358979323846 / 180) * pa.norm() * pb.norm());
  }
  Scene A;
  cyc_surface* P[2] = {};
  int count = 0;
  const int s0 = cyc_blend_ringed_pcurve(A.ctx, &a, &b, &o, P, &count);
  if (s0 == CYC_OK)
    for (int i = 0; i < count; ++i) A.keep(s0, P[i]);
  RC_TAG(s0 == CYC_OK ? "built" : "refused");
  const double L = 3 + 2 * std::max(a.rho, b.rho);
  const Similarity g = *similarity::gen_similarity(L);
  const cyc_ringed_jet a1 = moved_jet(a, g), b1 = moved_jet(b, g);
  cyc_pcurve_blend_options o1 = o;
  g.direction(o.v, o1.v);
  Scene M;
  cyc_surface* Q[2] = {};
  int count1 = 0;
  const int s1 = cyc_blend_ringed_pcurve(M.ctx, &a1, &b1, &o1, Q, &count1);
  if (s1 == CYC_OK)
    for (int i = 0; i < count1; ++i) M.keep(s1, Q[i]);
  RC_ASSERT(s1 == s0);
  if (s0 != CYC_OK) return;
  RC_ASSERT(count1 == count);
  const int piece = gen_int(0, count - 1);
  double u0, u1;
  RC_ASSERT(cyc_surface_domain(A.ctx, P[piece], &u0, &u1) == CYC_OK);
  bool conditioned = false;
  Extent E = blend_extent(A, P[piece], u0, u1, &conditioned);
  RC_PRE(conditioned && E.min_radius >= 1e-2 * E.L && E.L <= 1e2 * L);
  E.L = std::max(E.L, L);
  // The moved jets' rounding passes through the Ferguson cubics and the
  // degree-6 P-curve (Bernstein to power form): up to kPcurveAmp.
  compare_surfaces(A, P[piece], M, Q[piece], g, E.L, 1.0, false, gen_u(u0, u1), gen_v(),
                   kPcurveAmp);
}

// ------------------------------------------------------------ n-way
namespace {

// Example 6.2's ends (68): normal ringed surfaces (n = d') of cubic d.
const double kD[3][12] = {{-9, -7, 0, 12, 4, 0, -23, 0, 0, 14, 0, 0},
                          {6, -8, 0, 4, 4, 0, 0, 3, 0, -4, -2, 0},
                          {0, 8, -8, 0, 0, 4, 0, -5, -3, 0, 2, 2}};
const double kRho[3][3] = {{4.0 / 6, 1.0 / 6, 0}, {1, 0, -0.5}, {9.0 / 6, -4.0 / 6, 0}};
const int kRhoDegree[3] = {1, 2, 1};

// End i of Example 6.2 moved by g, with the first field method that works
// (the quadratic field of Example 3.3, either direction; then automatic).
cyc_surface* nway_end(Scene& X, int i, const Similarity& g) {
  CurveSpec d, n;
  d.degree = 3;
  n.degree = 2;
  for (int k = 0; k <= 3; ++k) {
    for (int j = 0; j < 3; ++j) {
      d.h[4 * k + j] = kD[i][3 * k + j];
      if (k >= 1) n.h[4 * (k - 1) + j] = k * kD[i][3 * k + j];
    }
    d.h[4 * k + 3] = k == 0 ? 1.0 : 0.0;
    if (k <= 2) n.h[4 * k + 3] = k == 0 ? 1.0 : 0.0;
  }
  cyc_curve* cd = X.curve(moved_points(d, g));
  cyc_curve* cn = X.curve(moved_directions(n, g));
  double rho[3];
  for (int k = 0; k < 3; ++k) rho[k] = g.s * kRho[i][k];
  for (int attempt = 0; attempt < 3; ++attempt) {
    cyc_ringed_field_options fo;
    cyc_ringed_field_options_init(&fo);
    fo.method = attempt < 2 ? CYC_RINGED_FIELD_QUADRATIC : CYC_RINGED_FIELD_AUTO;
    fo.which = attempt == 1;
    cyc_surface* S = nullptr;
    const int st = cyc_ringed_dnr_create(X.ctx, cd, cn, kRhoDegree[i], rho, 0, nullptr, &fo,
                                         nullptr, 0, 1, &S, nullptr);
    if (st == CYC_OK) return X.keep(st, S);
  }
  return nullptr;
}

}  // namespace

// Seed 001 §6, Example 6.2 (sphere (69), lambda chosen automatically) moved
// by random similarities: the report (incentre, N, sphere, distances, n*_i,
// angular gaps) and every blend move with the ends.
RC_GTEST_PROP(CanalSimilarity, NwayBlendMovesWithItsEnds, ()) {
  const double L = 30;  // Example 6.2's ends lie within about 30 of each other
  const Similarity id;
  const Similarity g = *similarity::gen_similarity(L);
  Scene A, M;
  const cyc_surface* R0[3];
  const cyc_surface* R1[3];
  for (int i = 0; i < 3; ++i) {
    R0[i] = nway_end(A, i, id);
    R1[i] = nway_end(M, i, g);
    RC_ASSERT(made(R0[i]));
    RC_ASSERT(made(R1[i]));
  }
  const double u[3] = {1, 1, 1};
  cyc_nway_options o0;
  cyc_nway_options_init(&o0);
  o0.center = CYC_NWAY_CENTER_GIVEN;
  o0.s[0] = 0.5;
  o0.s[1] = 0.3;
  o0.s[2] = -0.25;
  o0.r = 2.6;
  o0.auto_lambda = 1;
  cyc_nway_options o1 = o0;
  g.point(o0.s, o1.s);
  o1.r = g.s * o0.r;
  cyc_surface* B0[2 * CYC_NWAY_MAX_ENDS] = {};
  cyc_surface* B1[2 * CYC_NWAY_MAX_ENDS] = {};
  int c0[CYC_NWAY_MAX_ENDS] = {}, c1[CYC_NWAY_MAX_ENDS] = {};
  cyc_nway_report r0, r1;
  const int s0 = cyc_blend_ringed_nway(A.ctx, R0, u, 3, &o0, B0, c0, &r0);
  const int s1 = cyc_blend_ringed_nway(M.ctx, R1, u, 3, &o1, B1, c1, &r1);
  RC_ASSERT(s0 == CYC_OK);
  RC_ASSERT(s1 == CYC_OK);
  for (cyc_surface* b : B0)
    if (b) A.keep(CYC_OK, b);
  for (cyc_surface* b : B1)
    if (b) M.keep(CYC_OK, b);
  const Bounds Bd(g, L);
  check_point("nway incentre y", r1.y, g.point(v3(r0.y)), Bd);
  check_vector("nway N' = s^2 R N", r1.normal, g.s * g.s * g.direction(v3(r0.normal)),
               g.s * g.s * v3(r0.normal).norm(), Bd);
  check_point("nway sphere center", r1.s, g.point(v3(r0.s)), Bd);
  check_scalar("nway r' = s r", r1.r, g.s * r0.r, g.s * L, Bd);
  check_scalar("nway bound' = s bound", r1.bound, g.s * r0.bound, g.s * L, Bd);
  for (int i = 0; i < 3; ++i) {
    check_vector("nway n*_i' = R n*_i", r1.n_star[i], g.direction(v3(r0.n_star[i])), 1.0, Bd);
    check_scalar("nway distance_i' = s distance_i", r1.distance[i], g.s * r0.distance[i],
                 g.s * L, Bd);
    check_scalar("nway lambda_i' = lambda_i", r1.lambda[i], r0.lambda[i], 1.0, Bd, 10);
    for (int j = 0; j < 3; ++j)
      check_scalar("nway gap_ij' = gap_ij", r1.gap[i][j], r0.gap[i][j], 1.0, Bd, 10);
    RC_ASSERT(c1[i] == c0[i]);
  }
  // Every blend piece: its circles (and points) move with the ends.
  const int i = gen_int(0, 2), piece = gen_int(0, c0[i] - 1);
  cyc_surface* P = B0[2 * i + piece];
  cyc_surface* Q = B1[2 * i + piece];
  double u0, u1;
  RC_ASSERT(cyc_surface_domain(A.ctx, P, &u0, &u1) == CYC_OK);
  compare_surfaces(A, P, M, Q, g, L, 1.0, false, gen_u(u0, u1), gen_v(), kPcurveAmp);
}

// ------------------------------------------------------------ regressions

// The P-curve blend of two jets and of the same jets turned by 170 degrees
// about the projection direction v = z: p1 (at 24 degrees) then crosses the
// branch cut of the principal square root and p0 (at -79) does not, so with
// principal roots the
// turned blend took the other interpolant of (43) (an O(1) different
// surface); the roots are now paired by the data (r1 conj(r0) in the
// right half-plane) and the turned blend is the turned surface.
TEST(CanalSimilarityRegression, PcurveBlendTurnedAboutVIsTheTurnedBlend) {
  cyc_ringed_jet a = {{0, 0, 0}, {1, 0.5, 0.25}, {0.2, -1, 0.5}, {0.25, 0.5, 0}, 0.75, 0.125};
  cyc_ringed_jet b = {{3, 1, 0}, {1, -0.5, 0.5}, {0.9, 0.4, -0.25}, {0, 0.25, 0.5}, 1.0, -0.25};
  Similarity g;
  g.R = Eigen::AngleAxisd(170.0 * 3.14159265358979323846 / 180, Vector3d::UnitZ()).toRotationMatrix();
  for (const int tau8 : {0, 3}) {
    cyc_pcurve_blend_options o;
    cyc_pcurve_blend_options_init(&o);
    o.tau = tau8 / 8.0;
    Scene A, M;
    cyc_surface *P[2] = {}, *Q[2] = {};
    int n0 = 0, n1 = 0;
    ASSERT_EQ(cyc_blend_ringed_pcurve(A.ctx, &a, &b, &o, P, &n0), CYC_OK);
    for (int i = 0; i < n0; ++i) A.keep(CYC_OK, P[i]);
    const cyc_ringed_jet a1 = moved_jet(a, g), b1 = moved_jet(b, g);
    ASSERT_EQ(cyc_blend_ringed_pcurve(M.ctx, &a1, &b1, &o, Q, &n1), CYC_OK);
    for (int i = 0; i < n1; ++i) M.keep(CYC_OK, Q[i]);
    ASSERT_EQ(n0, n1);
    for (int i = 0; i < n0; ++i) {
      double u0, u1;
      ASSERT_EQ(cyc_surface_domain(A.ctx, P[i], &u0, &u1), CYC_OK);
      for (int k = 0; k <= 8; ++k) {
        const double u = u0 + (u1 - u0) * k / 8.0;
        for (const double v : {-2.0, 0.0, 0.5}) {
          double x[3], y[3];
          ASSERT_EQ(cyc_surface_eval(A.ctx, P[i], u, v, x, nullptr, nullptr, nullptr), CYC_OK);
          ASSERT_EQ(cyc_surface_eval(M.ctx, Q[i], u, v, y, nullptr, nullptr, nullptr), CYC_OK);
          EXPECT_LE((v3(y) - g.point(v3(x))).norm(), 1e-12 * 5) << "tau " << o.tau << " u " << u;
        }
      }
    }
  }
}

// The matched ringed blend of two PRRS of lines scaled by 2^-30: its f
// carries the inputs' v to the blend's, both scaled by s^2, so f is the
// original conjugated by diag(s^2, 1) and |alpha delta - beta gamma| was
// ~s^4 of the largest coefficient squared, under the old absolute 1e-12:
// degenerate_circle_parameter for a valid blend. The Mobius test is now
// relative to |alpha delta| + |beta gamma| (kMobiusDegenerateTol).
TEST(CanalSimilarityRegression, MatchedRingedBlendAtAnyScale) {
  const double lines[2][3][6] = {
      {{0, 0, 0, 1, 0, 0.25}, {0, 1, 0, 1, 0.5, 0}, {1, 0, 1, 0.5, 1, 0}},
      {{4, 0, 0, 1, 0.25, 0}, {4, 1, 0.5, 0.5, 1, 0}, {5, 0, 1, 1, 0, 0.5}}};
  for (const int k : {-30, 0, 30}) {
    Similarity g;
    g.k = k;
    g.s = std::ldexp(1.0, k);
    Scene A;
    cyc_surface* S[2];
    for (int i = 0; i < 2; ++i) {
      CurveSpec c[3];
      for (int j = 0; j < 3; ++j) {
        c[j].degree = 1;
        for (int m = 0; m < 3; ++m) {
          c[j].h[m] = lines[i][j][m];
          c[j].h[4 + m] = lines[i][j][3 + m];
        }
        c[j].h[3] = 1;
        c[j] = moved_points(c[j], g);
      }
      S[i] = build(A, c, 3);
      ASSERT_TRUE(made(S[i]));
    }
    cyc_blend_end e[2] = {};
    for (int i = 0; i < 2; ++i) {
      e[i].surface = S[i];
      e[i].u = i == 0 ? 1.0 : 0.0;
      for (int j = 0; j < 3; ++j) e[i].v[j] = g.s * g.s * (j - 1.0);
      e[i].lambda = 1;
    }
    cyc_surface* B = nullptr;
    EXPECT_EQ(cyc_blend_ringed_matched(A.ctx, &e[0], &e[1], 2, 0, 1, &B), CYC_OK) << k;
    A.keep(B ? CYC_OK : CYC_E_INTERNAL, B);
  }
}
