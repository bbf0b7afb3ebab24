// Closed-form classification of the three simplest PRCS/PRRS inputs
// (issue 3, item 6; seed 000 §7 Prop. 2, Appendix A Prop. 8, Appendix B
// Prop. 9; SPEC.md §12b): the similarity and reparameterization to the
// paper's normal form, the case of the proposition, circle-family counts,
// and the closed forms (46), (47), (50), (69), (70).
//
// Normal forms (input u = alpha u' + beta, X' = T(X) a similarity):
//   two lines       (44)->(45): l1 = u' e1, l2 = e3 + u' (a, b, c), b != 0;
//   line + element  (67),(68):  l1 = u' e1, (P2, w) = (e3, (a, 1, c));
//   line + 2 points (76)->(77): l1 = u' e1, P2 = e3, P3 = (a, b, c), b != 0.
#pragma once

#include <Eigen/Core>

#include "cyclide/darboux.hpp"
#include "cyclide/status.hpp"
#include "cyclide/vec.hpp"

namespace cyclide {
inline namespace v0 {

// Relative tolerance of the equalities of Props. 2, 8, 9 (a = 1,
// w.w = 1, a = c = 0, b^2 + c^2 = 1, ...) and of the degeneracy tests
// (parallel, coplanar); the quantities compared are dimensionless.
constexpr double kClassifyTol = 1e-9;

// X' = scale R (X - origin), R a rotation (det +1), scale > 0.
struct Similarity {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  double scale = 1.0;
  Vec3d origin = Vec3d::Zero();
  Vec3d apply(const Vec3d& X) const { return scale * (R * (X - origin)); }
  Vec3d inverse(const Vec3d& Y) const { return origin + R.transpose() * Y / scale; }
};

// The equation of the preimage T^-1(C): G(X) = F(T(X)), again of form (31):
// (phi0, l, Q, b, c) -> (s^4 phi0, s^3 R^T l, s^2 R^T Q R, s R^T b, c),
// then translated by the origin.
Darboux pullback(const Darboux& D, const Similarity& T);

enum class CyclideKind : int {
  hyperboloid = 1,        // Prop. 2, w.w = 1: a hyperboloid of one sheet
  parabolic_darboux = 2,  // case (II)
  parabolic_dupin = 3,    // case (I)
};

struct NormalForm {
  Similarity T;                // input coordinates -> normal form
  double alpha = 1, beta = 0;  // input parameter u = alpha u' + beta
  double a = 0, b = 0, c = 0;  // w (45), w = (a, 1, c) (68), or P3 (77)
  bool swapped = false;        // two lines only: l1 and l2 exchanged
  double to_normal_parameter(double u) const { return (u - beta) / alpha; }
};

struct LinesClassification {
  CyclideKind kind = CyclideKind::parabolic_darboux;
  int paper_case = 2;        // 1 = (I), 2 = (II), 0 = hyperboloid
  int circle_families = 0;   // distinct real families (0: not stated, hyperboloid)
  int double_families = 0;   // of which of multiplicity two
  bool pn = false;           // x(u, v) is a PN parameterization
  NormalForm nf;
};

// Prop. 2: PRCS of l1 = P1 + u v and l2 = P2 + u w. Statuses: not_finite,
// zero_tangent (v or w = 0), parallel_lines, no_normal_form (the lines
// intersect: coplanar, b = 0). Where (45) needs a = 1 with (P2 - P1).v != 0
// (no normal form in the given order) the lines are exchanged (PRCS is
// symmetric in p1, p2) and nf.swapped is set. Case (I) also covers
// c = 0, a = w.w (l1 a double line; the paper's Prop. 2 misses it).
Status classify_two_lines(const Vec3d& P1, const Vec3d& v, const Vec3d& P2, const Vec3d& w,
                          LinesClassification& out);
// Prop. 8 (ERRATA: (II) is (a, c) != (0, 0)): PRCS of l1 = P1 + u v and the
// line element (P2, w). Statuses: not_finite, zero_tangent (v or w = 0),
// no_normal_form ( P2 on l1, or w in the plane of l1 and P2).
Status classify_line_element(const Vec3d& P1, const Vec3d& v, const Vec3d& P2, const Vec3d& w,
                             LinesClassification& out);
// Prop. 9: PRRS of l1 = P1 + u v and the points P2, P3. Statuses:
// not_finite, zero_tangent (v = 0), no_normal_form ( line and points in one
// plane).
Status classify_line_two_points(const Vec3d& P1, const Vec3d& v, const Vec3d& P2,
                                const Vec3d& P3, LinesClassification& out);

// Closed forms in normal-form coordinates and parameter u'. Map to the
// input with nf.T.inverse(s), r2 / nf.T.scale^2, u' = nf.to_normal_parameter(u).
// (46), (47): spine and squared radius of PRCS(two lines); invalid_argument
// if b = 0.
Status two_lines_sphere(const NormalForm& nf, double u, Vec3d& s, double& r2);
// (50): r^2 = (b^2 + c^2) / (4 b^2) [(b^2 + c^2) u^2 + 2 u c + 1]^2, only for
// a = 1 (invalid_argument otherwise).
Status two_lines_dupin_r2(const NormalForm& nf, double u, double& r2);
// (69): the spine of PRCS(line, line element).
Status line_element_spine(const NormalForm& nf, double u, Vec3d& s);
// (70): (cy - z)(X.X) + (1 - a^2 - c^2) y^2 + 2axy + 2z^2 - cy - z, in the
// normal form (normal) and pulled back to the input coordinates (input,
// normalized to largest |coefficient| 1).
Status line_element_cyclide(const NormalForm& nf, Darboux& normal, Darboux& input);

}  // namespace v0
}  // namespace cyclide
