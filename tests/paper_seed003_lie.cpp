// Seed 003 (Lávička–Vršek, Lie sphere geometry and Dupin cyclides): the
// quadratic space R^{4,2} (§2.1–2.2, Table 1 as corrected in ERRATA.md), Lie
// spheres (§2.3, eqs. (4)–(9), Lemma 2.7), Dupin cyclides from three spheres
// (§3.1, Algorithm 1, (23)–(32)), the Laguerre classes (Lemma 3.10) and the
// cyclide as a circle-family surface.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "cyclide/dupin.hpp"
#include "cyclide/lie.hpp"
#include "cyclide/surface.hpp"

using namespace cyclide;

namespace {

Lie6d vec(const LieSphere& s) {
  Lie6d x;
  EXPECT_EQ(lie_vector(s, x), Status::ok);
  return x;
}

// A torus about the z axis: core radius R, tube radius r (quartic).
double torus_residual(const Vec3d& x, double R, double r) {
  const double rho = std::hypot(x[0], x[1]) - R;
  return std::abs(std::hypot(rho, x[2]) - r);
}

DupinCyclide torus(double R, double r) {
  const LieSphere s[3] = {oriented_sphere({R, 0, 0}, r), oriented_sphere({0, R, 0}, r),
                          oriented_sphere({-R, 0, 0}, r)};
  DupinCyclide D;
  EXPECT_EQ(dupin_from_spheres(s, D), Status::ok);
  return D;
}

// The same torus stored with origin 0 (dupin_from_local_vectors): theta's
// own coordinates are the global ones, for tests of theta's algebra.
DupinCyclide torus_at_zero(double R, double r) {
  const Lie6d a[3] = {vec(oriented_sphere({R, 0, 0}, r)), vec(oriented_sphere({0, R, 0}, r)),
                      vec(oriented_sphere({-R, 0, 0}, r))};
  DupinCyclide D;
  EXPECT_EQ(dupin_from_local_vectors(a, D), Status::ok);
  return D;
}

}  // namespace

// ------------------------------------------------------------ Table 1

// ERRATA.md: A = R^{p,r,q} => A^perp = R^{4-p-r, r, 2-q-r}, and there are
// exactly 15 pairs of nontrivial subspaces and complements (Prop. 2.5).
TEST(Seed003Table1, FifteenPairsByTheComplementRule) {
  // Counted as the paper does: one entry (A, A^perp) per signature of A with
  // dim A <= 3 (3 + 6 + 6); for dim A = 3 both orders appear.
  int entries = 0;
  for (int p = 0; p <= 4; ++p)
    for (int r = 0; r <= 2; ++r)
      for (int q = 0; q <= 2; ++q) {
        const Signature s{p, r, q};
        if (s.dim() == 0 || s.dim() == 6 || !signature_exists(s)) continue;
        const Signature c = complement_signature(s);
        ASSERT_TRUE(signature_exists(c));
        EXPECT_EQ(c.dim(), 6 - s.dim());
        EXPECT_EQ(complement_signature(c), s);  // Thm. 2.4 (1)
        entries += s.dim() <= 3;
      }
  EXPECT_EQ(entries, 15);
  // The corrected table, (a)-(c).
  const Signature table[15][2] = {
      {{1, 0, 0}, {3, 0, 2}}, {{0, 1, 0}, {3, 1, 1}}, {{0, 0, 1}, {4, 0, 1}},
      {{2, 0, 0}, {2, 0, 2}}, {{0, 2, 0}, {2, 2, 0}}, {{0, 0, 2}, {4, 0, 0}},
      {{1, 0, 1}, {3, 0, 1}}, {{1, 1, 0}, {2, 1, 1}}, {{0, 1, 1}, {3, 1, 0}},
      {{3, 0, 0}, {1, 0, 2}}, {{2, 1, 0}, {1, 1, 1}}, {{2, 0, 1}, {2, 0, 1}},
      {{1, 2, 0}, {1, 2, 0}}, {{1, 0, 2}, {3, 0, 0}}, {{1, 1, 1}, {2, 1, 0}}};
  for (const auto& row : table) {
    EXPECT_EQ(complement_signature(row[0]), row[1]);
    EXPECT_EQ(complement_signature(row[1]), row[0]);
  }
}

// The extracted Table 1 pairs R^{1,1} with R^{2,1} and R^{1,2,0} with R^3;
// neither survives the dimension count or a computed complement.
TEST(Seed003Table1, ExtractedTableErrorsAreWrong) {
  EXPECT_NE(complement_signature({1, 0, 1}), (Signature{2, 0, 1}));
  EXPECT_EQ(complement_signature({1, 0, 1}), (Signature{3, 0, 1}));
  EXPECT_NE(complement_signature({1, 2, 0}), (Signature{3, 0, 0}));
  // Computed: span(e1, e-) = R^{1,1} has complement span(e2, e3, e+, er) = R^{3,1}.
  const Lie6d v[2] = {lie_basis(kE1), lie_basis(kEMinus)};
  LieSubspace A;
  ASSERT_EQ(lie_span(v, 2, A), Status::ok);
  EXPECT_EQ(A.signature, (Signature{1, 0, 1}));
  const LieSubspace C = lie_complement(A);
  EXPECT_EQ(C.dim, 4);
  EXPECT_EQ(C.signature, (Signature{3, 0, 1}));
}

// ------------------------------------------------------------ (28)-(30)

// (28)-(30): the reference pair A0 = span(e1, e2, e-), A0^perp = span(e3, e+,
// er) are PE-subspaces, and (29), (30) with ERRATA's "+" parameterize their
// neutral conics; every a0(xi) touches every a0_perp(zeta) (Lemma 2.7).
TEST(Seed003Eq28to30, ReferenceConicsAreNeutralAndTouch) {
  const Lie6d a0[3] = {lie_basis(kE1), lie_basis(kE2), lie_basis(kEMinus)};
  LieSubspace A0;
  ASSERT_EQ(lie_span(a0, 3, A0), Status::ok);
  EXPECT_EQ(A0.signature, (Signature{2, 0, 1}));
  EXPECT_EQ(lie_complement(A0).signature, (Signature{2, 0, 1}));
  const DupinCyclide ref;  // theta = id: the reference pair itself
  for (double xi : {-3.0, -1.0, 0.0, 0.25, 2.0})
    for (double zeta : {-2.0, 0.0, 0.5, 1.0, 7.0}) {
      const Lie6d a = ref.sphere_xi(xi, 1.0), b = ref.sphere_zeta(zeta, 1.0);
      EXPECT_NEAR(lie_dot(a, a), 0.0, 1e-12);
      EXPECT_NEAR(lie_dot(b, b), 0.0, 1e-12);
      EXPECT_NEAR(lie_dot(a, b), 0.0, 1e-12);
      EXPECT_NEAR(a[kE3], 0.0, 0.0);  // a in A0
      EXPECT_NEAR(b[kE1], 0.0, 0.0);  // b in A0^perp
    }
  // Homogeneous parameters: xi = infinity is (1 : 0), a0 = -e2 + e-.
  const Lie6d inf = ref.sphere_xi(1.0, 0.0);
  EXPECT_EQ(inf, (lie_basis(kEMinus) - lie_basis(kE2)));
}

// ------------------------------------------------------------ Lie spheres

// (4) and (6): a sphere's normalized representative is neutral and reads
// back; (7) as corrected: n + lambda n_inf - er is the plane x . n = lambda.
TEST(Seed003Eq4to9, RepresentativesRoundTrip) {
  const LieSphere s = oriented_sphere({1, -2, 0.5}, -0.75);
  const Lie6d x = vec(s);
  EXPECT_NEAR(lie_dot(x, x), 0.0, 1e-14);
  EXPECT_NEAR(dot_n_infinity(x), -2.0, 1e-15);  // normalized: x . n_inf = -2
  LieSphere back;
  ASSERT_EQ(lie_sphere(-3.5 * x, back), Status::ok);  // any scale, (6)
  EXPECT_EQ(back.kind, LieSphereKind::sphere);
  EXPECT_NEAR((back.m - s.m).norm(), 0.0, 1e-14);
  EXPECT_NEAR(back.rho, s.rho, 1e-14);

  const LieSphere pl = oriented_plane({0, 0, 2}, 3);  // z = 1.5
  const Lie6d y = vec(pl);
  EXPECT_NEAR(lie_dot(y, y), 0.0, 1e-15);
  EXPECT_NEAR(dot_e_r(y), 1.0, 0.0);  // normalized by (9)
  ASSERT_EQ(lie_sphere(7.0 * y, back), Status::ok);
  EXPECT_EQ(back.kind, LieSphereKind::plane);
  EXPECT_NEAR(back.lambda, 1.5, 1e-15);
  EXPECT_NEAR((back.n - Vec3d(0, 0, 1)).norm(), 0.0, 1e-15);
  // ERRATA (7): the points of x . n = lambda touch it, those of x . n = -lambda do not.
  EXPECT_TRUE(in_oriented_contact(vec(lie_point({4, -1, 1.5})), y));
  EXPECT_FALSE(in_oriented_contact(vec(lie_point({4, -1, -1.5})), y));
  // A sphere touching the plane from below with outward normal (0,0,1) at
  // the contact point: m . n + rho = lambda, the contact point m + rho n.
  EXPECT_TRUE(in_oriented_contact(vec(oriented_sphere({0, 0, 1}, 0.5)), y));
  EXPECT_FALSE(in_oriented_contact(vec(oriented_sphere({0, 0, 1}, -0.5)), y));
  // n_inf is the point at infinity; a non-neutral vector is no Lie sphere.
  ASSERT_EQ(lie_sphere(n_infinity(), back), Status::ok);
  EXPECT_EQ(back.kind, LieSphereKind::point_at_infinity);
  EXPECT_EQ(lie_sphere(lie_basis(kE1), back), Status::not_on_lie_quadric);
}

// Lemma 2.7: two spheres touch in oriented contact iff x . y = 0:
// internally tangent spheres with equal orientation, externally tangent
// with opposite orientation.
TEST(Seed003Lemma27, OrientedContact) {
  const Lie6d a = vec(oriented_sphere({0, 0, 0}, 2));
  EXPECT_TRUE(in_oriented_contact(a, vec(oriented_sphere({1, 0, 0}, 1))));    // inside, same
  EXPECT_FALSE(in_oriented_contact(a, vec(oriented_sphere({1, 0, 0}, -1))));  // inside, opposite
  EXPECT_TRUE(in_oriented_contact(a, vec(oriented_sphere({3, 0, 0}, -1))));   // outside, opposite
  EXPECT_FALSE(in_oriented_contact(a, vec(oriented_sphere({3, 0, 0}, 1))));
  EXPECT_TRUE(in_oriented_contact(a, vec(lie_point({0, 2, 0}))));  // incidence
}

// Lie, Laguerre and Mobius transformations: elements of O(4,2); Laguerre
// ones fix n_inf, Mobius ones fix er; the offset moves rho by d and planes
// by d; the inversion maps a sphere through its center to a plane.
TEST(Seed003Transformations, SubgroupsAndActions) {
  const LieTransform tr = lie_translation({1, 2, 3});
  const LieTransform dil = lie_dilatation(0.5);
  const LieTransform inv = lie_inversion({0, 0, 0}, 2);
  for (const LieTransform* T : {&tr, &dil, &inv})
    EXPECT_LE(lie_orthogonality_residual(*T), 1e-14);
  EXPECT_TRUE(is_laguerre(tr) && is_mobius(tr));
  EXPECT_TRUE(is_laguerre(dil));
  EXPECT_FALSE(is_mobius(dil));
  EXPECT_TRUE(is_mobius(inv));
  EXPECT_FALSE(is_laguerre(inv));
  LieSphere out;
  ASSERT_EQ(apply(dil, oriented_sphere({1, 1, 1}, 2), out), Status::ok);
  EXPECT_NEAR(out.rho, 2.5, 1e-14);
  ASSERT_EQ(apply(dil, oriented_plane({0, 1, 0}, 1), out), Status::ok);
  EXPECT_NEAR(out.lambda, 1.5, 1e-14);
  ASSERT_EQ(apply(inv, lie_point({1, 0, 0}), out), Status::ok);
  EXPECT_NEAR((out.m - Vec3d(4, 0, 0)).norm(), 0.0, 1e-14);
  ASSERT_EQ(apply(inv, oriented_sphere({0, 0, 1}, 1), out), Status::ok);  // through 0
  EXPECT_EQ(out.kind, LieSphereKind::plane);
  EXPECT_NEAR(std::abs(out.lambda), 2.0, 1e-14);  // z = 2 (4 / diameter 2)
}

// Witt's extension theorem (Thm. 2.3) with neutral spanning vectors and a
// degenerate subspace R^{1,1,0} (ERRATA: no division by x . x).
TEST(Seed003Witt, ExtendsIsometriesOfDegenerateSubspaces) {
  // R = span(r0, r+): r0 a sphere, r+ positive with r0 . r+ = 0.
  const Lie6d r0 = vec(oriented_sphere({0, 0, 0}, 1));
  const Lie6d rp = lie_basis(kE3);  // e3 . r0 = 0
  const LieTransform M = lie_translation({1, -2, 0.5})
                             .then(lie_dilatation(0.7))
                             .then(lie_inversion({3, 1, 0}, 1.5));
  const Lie6d u[2] = {r0, rp};
  const Lie6d w[2] = {M.M * r0, M.M * rp};
  LieSubspace R;
  ASSERT_EQ(lie_span(u, 2, R), Status::ok);
  EXPECT_EQ(R.signature, (Signature{1, 1, 0}));
  Matrix6d T;
  double res = 1;
  ASSERT_EQ(witt_extension(u, w, 2, T, &res), Status::ok);
  EXPECT_LE(res, 1e-10);
  // Not isometric: scale one image.
  const Lie6d w2[2] = {M.M * r0, 2.0 * (M.M * rp)};
  EXPECT_EQ(witt_extension(u, w2, 2, T, &res), Status::not_isometric);
  // Three neutral vectors of a PE-subspace onto three of another.
  const Lie6d a[3] = {vec(oriented_sphere({3, 0, 0}, 1)), vec(oriented_sphere({0, 3, 0}, 1)),
                      vec(oriented_sphere({-3, 0, 0}, 1))};
  const Lie6d b[3] = {M.M * a[0], M.M * a[1], M.M * a[2]};
  ASSERT_EQ(witt_extension(a, b, 3, T, &res), Status::ok);
  EXPECT_LE(res, 1e-9);
}

// ------------------------------------------------------------ §3.1

// The case analysis of §3.1 on concrete triples.
TEST(Seed003Section31, CasesOfThreeSpheres) {
  // Pencil: three spheres touching at one point with one normal (Case I).
  const Lie6d pencil[3] = {vec(oriented_sphere({0, 0, 1}, 1)), vec(oriented_sphere({0, 0, 2}, 2)),
                           vec(oriented_sphere({0, 0, -1}, -1))};
  EXPECT_EQ(classify_sphere_triple(pencil), Status::sphere_pencil);
  // A torus' spheres: a cyclide (R^{2,1}).
  Signature sig;
  const Lie6d tor[3] = {vec(oriented_sphere({3, 0, 0}, 1)), vec(oriented_sphere({0, 3, 0}, 1)),
                        vec(oriented_sphere({-3, 0, 0}, 1))};
  EXPECT_EQ(classify_sphere_triple(tor, &sig), Status::ok);
  EXPECT_EQ(sig, (Signature{2, 0, 1}));
  // ERRATA's criterion: (a1.a2)(a1.a3)(a2.a3) < 0.
  EXPECT_LT(lie_dot(tor[0], tor[1]) * lie_dot(tor[0], tor[2]) * lie_dot(tor[1], tor[2]), 0.0);
  // Three nested spheres of one orientation, |m_i - m_j| < |rho_i - rho_j|
  // for every pair: all products positive (R^{1,2}), no sphere touches all.
  const Lie6d none[3] = {vec(oriented_sphere({0, 0, 0}, 10)),
                         vec(oriented_sphere({0.5, 0, 0}, 5)),
                         vec(oriented_sphere({-0.3, 0, 0}, 1))};
  EXPECT_GT(lie_dot(none[0], none[1]) * lie_dot(none[0], none[2]) * lie_dot(none[1], none[2]),
            0.0);
  EXPECT_EQ(classify_sphere_triple(none, &sig), Status::no_touching_sphere);
  EXPECT_EQ(sig, (Signature{1, 0, 2}));
  EXPECT_EQ(complement_signature(sig), (Signature{3, 0, 0}));
  // Two touching inputs (a1 . a2 = 0): R^{1,1,1}, exactly one touching sphere.
  const Lie6d one[3] = {vec(oriented_sphere({0, 0, 0}, 1)), vec(oriented_sphere({3, 0, 0}, -2)),
                        vec(oriented_sphere({0, 5, 0}, 1))};
  EXPECT_EQ(classify_sphere_triple(one, &sig), Status::single_touching_sphere);
  EXPECT_EQ(sig, (Signature{1, 1, 1}));
  EXPECT_EQ(complement_signature(sig), (Signature{2, 1, 0}));
  // Equal spheres and non-neutral vectors.
  const Lie6d same[3] = {tor[0], 2.0 * tor[0], tor[2]};
  EXPECT_EQ(classify_sphere_triple(same), Status::invalid_argument);
  const Lie6d bad[3] = {tor[0], lie_basis(kE1), tor[2]};
  EXPECT_EQ(classify_sphere_triple(bad), Status::not_on_lie_quadric);
}

// ------------------------------------------------------------ Algorithm 1

// Algorithm 1 (corrected) on the torus' three spheres: every point lies on
// the torus, on a(xi) and on a_perp(zeta); the inputs are a(0), a(inf),
// a(1); n is unit and the tangent plane is x . n = lambda (ERRATA (7), (32)).
TEST(Seed003Algorithm1, TorusFromThreeSpheres) {
  const DupinCyclide D = torus(3, 1);
  EXPECT_EQ(D.type, DupinLaguerreType::quartic);
  LieSphere s;
  const HomogeneousParameter anchors[3] = {{0, 1}, {1, 0}, {1, 1}};
  const Vec3d centers[3] = {{3, 0, 0}, {0, 3, 0}, {-3, 0, 0}};
  for (int i = 0; i < 3; ++i) {
    ASSERT_EQ(dupin_sphere_xi(D, anchors[i], s), Status::ok);
    EXPECT_EQ(s.kind, LieSphereKind::sphere);
    EXPECT_NEAR((s.m - centers[i]).norm(), 0.0, 1e-12);
    EXPECT_NEAR(s.rho, 1.0, 1e-12);
  }
  for (double xi : {-2.0, -0.5, 0.0, 0.3, 1.0, 4.0})
    for (double zeta : {-3.0, -1.0, 0.0, 0.2, 2.0}) {
      DupinPoint P;
      ASSERT_EQ(dupin_eval(D, xi, zeta, 0.0, P), Status::ok);
      EXPECT_LE(torus_residual(P.point, 3, 1), 1e-12);
      EXPECT_NEAR(P.normal.norm(), 1.0, 1e-13);
      EXPECT_NEAR(P.point.dot(P.normal), P.lambda, 1e-12);
      EXPECT_NEAR(P.normal.dot(P.d_xi), 0.0, 1e-11 * (1 + P.d_xi.norm()));
      EXPECT_NEAR(P.normal.dot(P.d_zeta), 0.0, 1e-11 * (1 + P.d_zeta.norm()));
      // Touching spheres: c - rho n = m for both families (ERRATA).
      LieSphere a, b;
      ASSERT_EQ(dupin_sphere_xi(D, {xi, 1}, a), Status::ok);
      ASSERT_EQ(dupin_sphere_zeta(D, {zeta, 1}, b), Status::ok);
      EXPECT_NEAR((P.point - a.rho * P.normal - a.m).norm(), 0.0, 1e-11);
      if (b.kind == LieSphereKind::sphere) {
        EXPECT_NEAR((P.point - b.rho * P.normal - b.m).norm(), 0.0,
                    1e-10 * (1 + std::abs(b.rho)));
      } else if (b.kind == LieSphereKind::plane) {
        EXPECT_NEAR(P.point.dot(b.n), b.lambda, 1e-11);
      }
    }
}

// ERRATA, Algorithm 1 line 6: with "+2 c^/(c^ . n_inf)" the point comes out
// reflected through the origin, off the surface.
TEST(Seed003Algorithm1, PrintedSignReflectsThroughTheOrigin) {
  const DupinCyclide D = torus_at_zero(3, 1);
  const Lie6d a = D.sphere_xi(0.4, 1.0), b = D.sphere_zeta(0.7, 1.0);
  // Line 5 as printed lost its minus: (er.a) a_perp + (er.a_perp) a.
  const Lie6d printed5 = dot_e_r(a) * b + dot_e_r(b) * a;
  const Lie6d c5 = dupin_point_vector(a, b);
  EXPECT_GT(std::abs(dot_e_r(printed5)), 1e-3);  // not a point sphere
  EXPECT_NEAR(dot_e_r(c5), 0.0, 1e-14);          // (5): a point
  const Vec3d good = c5.head<3>() / -dot_n_infinity(c5);
  const Vec3d printed6 = c5.head<3>() / dot_n_infinity(c5);  // "+2 c^ / (c^ . n_inf)" halved
  EXPECT_LE(torus_residual(good, 3, 1), 1e-13);
  EXPECT_NEAR((printed6 + good).norm(), 0.0, 1e-14);
  EXPECT_GT(torus_residual(printed6 + Vec3d(1, 0, 0), 3, 1), 1e-3);
}

// The local origin (SPEC §8h.3): the torus of TorusFromThreeSpheres moved
// by D = 1e2 .. 1e5. Stored globally it lost about eps D^4 (9e-10 at D =
// 100, not_isometric from D ~ 430); with the origin at the spheres' mean
// centre every point lies on its two touching spheres and on the moved
// torus to 1e-12 (1 + D), through dupin_from_spheres and through the
// global vectors (dupin_from_vectors decodes them with the robust weight).
// Three spheres of the torus (3, 1) about the x3-axis, moved by t, and
// their vectors (4).
void torus_spheres_moved_by(const Vec3d& t, LieSphere (&s)[3], Lie6d (&a)[3]) {
  const Vec3d m[3] = {Vec3d(3, 0, 0), Vec3d(0, 3, 0), Vec3d(-3, 0, 0)};
  for (int i = 0; i < 3; ++i) {
    s[i] = oriented_sphere(m[i] + t, 1);
    a[i] = vec(s[i]);
  }
}

TEST(Seed003Algorithm1, TranslatedTorusKeepsItsAccuracy) {
  const Vec3d dir = Vec3d(0.6, -0.48, 0.64);  // |dir| = 1
  for (double dist : {1e2, 1e3, 1e4, 1e5}) {
    const Vec3d t = dist * dir;
    LieSphere s[3];
    Lie6d a[3];
    torus_spheres_moved_by(t, s, a);
    DupinCyclide built[2];
    ASSERT_EQ(dupin_from_spheres(s, built[0]), Status::ok) << dist;
    ASSERT_EQ(dupin_from_vectors(a, built[1]), Status::ok) << dist;
    const double tol = 1e-12 * (1 + dist);
    for (const DupinCyclide& D : built) {
      EXPECT_EQ(D.type, DupinLaguerreType::quartic);
      // The local origin is at the spheres (their best frame: the mean of
      // the centres or one of them, SPEC §8h.3), not at 0.
      EXPECT_LE((D.origin - t).norm(), 3 + tol);
      for (double xi : {-2.0, -0.5, 0.0, 0.3, 1.0, 4.0})
        for (double zeta : {-3.0, -1.0, 0.0, 0.2, 2.0}) {
          DupinPoint P;
          ASSERT_EQ(dupin_eval(D, xi, zeta, 0.0, P), Status::ok);
          EXPECT_LE(torus_residual(P.point - t, 3, 1), tol) << dist;
          EXPECT_NEAR(P.normal.norm(), 1.0, 1e-13);
          EXPECT_NEAR(P.point.dot(P.normal), P.lambda, tol);
          LieSphere sa, sb;
          ASSERT_EQ(dupin_sphere_xi(D, {xi, 1}, sa), Status::ok);
          ASSERT_EQ(dupin_sphere_zeta(D, {zeta, 1}, sb), Status::ok);
          EXPECT_NEAR((P.point - sa.rho * P.normal - sa.m).norm(), 0.0, tol) << dist;
          if (sb.kind == LieSphereKind::sphere) {
            EXPECT_NEAR((P.point - sb.rho * P.normal - sb.m).norm(), 0.0,
                        10 * tol * (1 + std::abs(sb.rho)))
                << dist;
          } else if (sb.kind == LieSphereKind::plane) {
            EXPECT_NEAR(P.point.dot(sb.n), sb.lambda, tol) << dist;
          }
        }
      // The inputs come back as a(0), a(inf), a(1), centred globally.
      const HomogeneousParameter anchors[3] = {{0, 1}, {1, 0}, {1, 1}};
      for (int i = 0; i < 3; ++i) {
        LieSphere b;
        ASSERT_EQ(dupin_sphere_xi(D, anchors[i], b), Status::ok);
        EXPECT_NEAR((b.m - s[i].m).norm(), 0.0, tol) << dist;
        EXPECT_NEAR(b.rho, 1.0, 1e-12);
      }
      // The view and Surface::sphere are global too.
      DupinView V;
      V.cyclide = D;
      Surface S;
      ASSERT_EQ(make_dupin_surface(V, -2, 2, S), Status::ok);
      for (double u : {-1.0, 0.5}) {
        Vec3d center;
        double r2;
        ASSERT_EQ(S.sphere(u, center, r2), Status::ok);
        for (double v : {-2.0, 0.0, 1.5}) {
          double x[3];
          ASSERT_EQ(S.eval(u, v, EvalOut{x, nullptr, nullptr, nullptr}), Status::ok);
          const Vec3d X(x[0], x[1], x[2]);
          EXPECT_LE(torus_residual(X - t, 3, 1), tol) << dist;
          EXPECT_NEAR((X - center).norm(), 1.0, tol) << dist;
        }
      }
    }
  }
}

// dupin_from_subspace works at the mean centre of its spanning spheres too:
// they are read back as spheres and moved geometrically (a Lie translation
// of the stored vectors restored no digits: 5e-10 at D = 1e2 before).
TEST(Seed003Algorithm1, SubspaceFarFromTheOriginKeepsItsAccuracy) {
  const Vec3d dir = Vec3d(0.6, -0.48, 0.64);
  for (double dist : {1e2, 1e3, 1e4, 1e5}) {
    const Vec3d t = dist * dir;
    LieSphere s[3];
    Lie6d a[3];
    torus_spheres_moved_by(t, s, a);
    DupinCyclide D;
    Signature sig;
    ASSERT_EQ(dupin_from_subspace(a, 3, D, &sig), Status::ok) << dist;
    EXPECT_EQ(sig, (Signature{2, 0, 1}));
    const double tol = 1e-12 * (1 + dist);
    EXPECT_LE((D.origin - t).norm(), 3 + tol);  // at the spheres (best frame)
    for (double xi : {-2.0, 0.0, 1.0, 4.0})
      for (double zeta : {-3.0, 0.0, 2.0}) {
        DupinPoint P;
        ASSERT_EQ(dupin_eval(D, xi, zeta, 0.0, P), Status::ok);
        EXPECT_LE(torus_residual(P.point - t, 3, 1), tol) << dist;
      }
  }
}

// fuzz_lie finding (2026-11-23, corpus regress-far-pencil-subspace): three
// spheres on the line x = y = z near (-85, -85, -85), each in oriented
// contact with the next (|m_i - m_j| = rho_i - rho_j): a pencil. The Lie
// translation of their vectors to the local origin left rounding that
// read as R^{2,0,1}, and a "cyclide" 2e-8 off its own spheres was built.
// Read back as spheres and moved geometrically, the span is the pencil
// that classify_sphere_triple sees.
TEST(Seed003Algorithm1, RegressionFarPencilSpanIsNotACyclide) {
  const double c[3] = {-81.580090473279427, -83.422649730810377, -89.193897148217616};
  const double rho[3] = {4.19140625, 1, -8.99609375};
  LieSphere s[3];
  Lie6d a[3];
  for (int i = 0; i < 3; ++i) {
    s[i] = oriented_sphere(c[i] * Vec3d(1, 1, 1), rho[i]);
    a[i] = vec(s[i]);
  }
  EXPECT_EQ(classify_sphere_triple(a), Status::sphere_pencil);
  DupinCyclide D;
  Signature sig;
  EXPECT_EQ(dupin_from_subspace(a, 3, D, &sig), Status::not_isometric);
  EXPECT_EQ(sig, (Signature{0, 2, 0}));
}

// A hand-set origin is a plain translation of theta's cyclide, also for
// offsets and swapped families (which keep it).
TEST(Seed003Algorithm1, OriginTranslatesTheCyclide) {
  const DupinCyclide D0 = torus_at_zero(3, 1);
  DupinCyclide D = D0;
  D.origin = Vec3d(5, -7, 11);
  for (const auto& pair : {std::make_pair(D0, D), std::make_pair(dupin_offset(D0, 0.5),
                                                                 dupin_offset(D, 0.5)),
                           std::make_pair(swap_families(D0), swap_families(D))}) {
    for (double xi : {-1.0, 0.5})
      for (double zeta : {0.0, 2.0}) {
        DupinPoint P, Q;
        ASSERT_EQ(dupin_eval(pair.first, xi, zeta, 0.25, P), Status::ok);
        ASSERT_EQ(dupin_eval(pair.second, xi, zeta, 0.25, Q), Status::ok);
        EXPECT_NEAR((Q.point - P.point - D.origin).norm(), 0.0, 1e-13);
        EXPECT_NEAR((Q.normal - P.normal).norm(), 0.0, 1e-15);
        EXPECT_NEAR((Q.d_xi - P.d_xi).norm(), 0.0, 1e-15);
        EXPECT_NEAR(Q.lambda, P.lambda + P.normal.dot(D.origin), 1e-13);
      }
    EXPECT_EQ(pair.second.origin, D.origin);
  }
  EXPECT_EQ(dupin_laguerre_type(D), dupin_laguerre_type(D0));
}

// The robust weight (lie_sphere_weight): x . n_inf of (4) is -2 to a few
// eps also where x_+ - x_- cancels (|m| = 1e6), and lie_sphere reads the
// centre back to relative eps (it lost eps |m|^3 through x_+ - x_-).
TEST(Seed003Algorithm1, RobustSphereWeight) {
  for (double dist : {0.0, 1.0, 1e3, 1e6}) {
    const Lie6d x = vec(oriented_sphere(Vec3d(0.6, 0.8, 0) * dist + Vec3d(0.1, 0.2, 0.3), 0.7));
    EXPECT_NEAR(lie_sphere_weight(x), -2.0, 8e-16 * 2) << dist;
    EXPECT_NEAR(lie_sphere_weight(-3.0 * x), 6.0, 8e-16 * 6) << dist;
    LieSphere s;
    ASSERT_EQ(lie_sphere(-3.0 * x, s), Status::ok);
    const Vec3d m = Vec3d(0.6, 0.8, 0) * dist + Vec3d(0.1, 0.2, 0.3);
    EXPECT_NEAR((s.m - m).norm(), 0.0, 4e-16 * (1 + m.norm())) << dist;
    EXPECT_NEAR(s.rho, 0.7, 4e-16 * (1 + m.norm())) << dist;
  }
}

// Homogeneous parameters reach the spheres at xi = infinity (the second
// input) and points with zeta = infinity.
TEST(Seed003Algorithm1, InfiniteParameters) {
  const DupinCyclide D = torus(3, 1);
  DupinPoint P, Q;
  ASSERT_EQ(dupin_eval_homogeneous(D, {1, 0}, {1, 0}, 0.0, P), Status::ok);
  EXPECT_LE(torus_residual(P.point, 3, 1), 1e-12);
  // The limit xi -> infinity along affine parameters.
  ASSERT_EQ(dupin_eval(D, 1e7, 1e7, 0.0, Q), Status::ok);
  EXPECT_NEAR((P.point - Q.point).norm(), 0.0, 1e-5);
  EXPECT_NEAR((P.point - Vec3d(0, 3, 0)).norm(), 1.0, 1e-12);  // on a(inf)
}

// Offsets (Thm. 3.13: PN): the offset cyclide (Laguerre dilatation of the
// families) is c + d n at the same parameters, again a torus.
TEST(Seed003Theorem313, OffsetsAreCyclides) {
  const DupinCyclide D = torus(3, 1);
  const DupinCyclide O = dupin_offset(D, 0.25);
  for (double xi : {-1.0, 0.5, 3.0})
    for (double zeta : {-0.5, 0.0, 2.0}) {
      DupinPoint P, Q;
      ASSERT_EQ(dupin_eval(D, xi, zeta, 0.25, P), Status::ok);
      ASSERT_EQ(dupin_eval(O, xi, zeta, 0.0, Q), Status::ok);
      EXPECT_NEAR((P.point - Q.point).norm(), 0.0, 1e-12);
      EXPECT_NEAR((P.normal - Q.normal).norm(), 0.0, 1e-12);
      EXPECT_LE(torus_residual(P.point, 3, 1.25), 1e-12);
    }
}

// ------------------------------------------------------------ Lemma 3.10

// Laguerre classes: a torus is quartic (no plane in one family, two in the
// other), its inversion at a point on it is parabolic (cubic: one plane per
// family), at a point off it quartic again; spheres inscribed in a cone or
// a cylinder give class I.
TEST(Seed003Lemma310, LaguerreClasses) {
  EXPECT_EQ(torus(3, 1).type, DupinLaguerreType::quartic);
  const LieSphere s[3] = {oriented_sphere({3, 0, 0}, 1), oriented_sphere({0, 3, 0}, 1),
                          oriented_sphere({-3, 0, 0}, 1)};
  auto inverted = [&](const Vec3d& center) {
    const LieTransform T = lie_inversion(center, 1.5);
    LieSphere t[3];
    for (int i = 0; i < 3; ++i) EXPECT_EQ(apply(T, s[i], t[i]), Status::ok);
    DupinCyclide D;
    EXPECT_EQ(dupin_from_spheres(t, D), Status::ok);
    return D;
  };
  EXPECT_EQ(inverted({4, 0, 0}).type, DupinLaguerreType::parabolic);   // on the torus
  EXPECT_EQ(inverted({0, 0, 5}).type, DupinLaguerreType::quartic);     // off it
  // A cone: apex 0, axis z, half-angle with sin = 1/2: rho = z/2.
  const LieSphere cone[3] = {oriented_sphere({0, 0, 1}, 0.5), oriented_sphere({0, 0, 2}, 1.0),
                             oriented_sphere({0, 0, 4}, 2.0)};
  DupinCyclide C;
  // Three spheres of one cone span a pencil? No: a conic through n_inf.
  ASSERT_EQ(dupin_from_spheres(cone, C), Status::ok);
  EXPECT_EQ(C.type, DupinLaguerreType::degenerate);
  const LieSphere cyl[3] = {oriented_sphere({0, 0, 0}, 1), oriented_sphere({0, 0, 2}, 1),
                            oriented_sphere({0, 0, 5}, 1)};
  ASSERT_EQ(dupin_from_spheres(cyl, C), Status::ok);
  EXPECT_EQ(C.type, DupinLaguerreType::degenerate);
}

// ------------------------------------------------------------ circle family

// The cyclide as a circle-family surface: Surface::eval(u, v) = c(xi(u),
// zeta(v)) with partials, for both families (Cor. 3.6).
TEST(Seed003CircleFamily, SurfaceEvaluatesTheCyclide) {
  const DupinCyclide D = torus(3, 1);
  for (int family = 0; family < 2; ++family) {
    DupinView V;
    V.cyclide = family == 0 ? D : swap_families(D);
    Surface S;
    ASSERT_EQ(make_dupin_surface(V, -2, 2, S), Status::ok);
    for (double u : {-1.5, -0.2, 0.0, 0.7, 2.0})
      for (double v : {-4.0, -1.0, 0.0, 0.5, 3.0}) {
        double x[3], xu[3], xv[3], n[3];
        ASSERT_EQ(S.eval(u, v, EvalOut{x, xu, xv, n}), Status::ok);
        DupinPoint P;
        ASSERT_EQ(dupin_eval(V.cyclide, u, v, 0.0, P), Status::ok);
        EXPECT_NEAR((Vec3d(x[0], x[1], x[2]) - P.point).norm(), 0.0, 1e-12);
        EXPECT_NEAR((Vec3d(xu[0], xu[1], xu[2]) - P.d_xi).norm(), 0.0, 1e-10);
        EXPECT_NEAR((Vec3d(xv[0], xv[1], xv[2]) - P.d_zeta).norm(), 0.0, 1e-10);
        EXPECT_NEAR(std::abs(Vec3d(n[0], n[1], n[2]).dot(P.normal)), 1.0, 1e-10);
      }
    // The circle at u lies on the sphere a(xi(u)) (its characteristic circle).
    for (double u : {-1.0, 0.5}) {
      Vec3d center;
      double r2;
      ASSERT_EQ(S.sphere(u, center, r2), Status::ok);
      if (family == 0) {
        EXPECT_NEAR(r2, 1.0, 1e-12);
      }
      for (double v : {-2.0, 0.0, 1.5}) {
        double x[3];
        ASSERT_EQ(S.eval(u, v, EvalOut{x, nullptr, nullptr, nullptr}), Status::ok);
        EXPECT_NEAR((Vec3d(x[0], x[1], x[2]) - center).squaredNorm(), r2, 1e-10 * (1 + r2));
      }
    }
  }
}
