// Lines and circle families of a parabolic Darboux cyclide (seed 000 §6–8,
// App. A–B), and its parameterization by PRCS or PRRS (Props. 3 and 5).
//
// A parabolic cyclide F = (l.X)(X.X) + X.QX + b.X + c (phi0 = 0, l != 0)
// contains the line l0 at infinity of the planes l.X = t: its cubic part
// factors into l.X and the absolute conic. Every finite real line on F is
// orthogonal to l (along P + s d the s^3 term is (l.d)(d.d)), so it lies in
// one plane n.X = t, n = l/|l|, through l0. That plane cuts F in l0 and a
// conic; the line is a component of a degenerate conic. In plane
// coordinates X = t n + E eta (E = [e1 e2] orthonormal, orthogonal to n),
//   |l|^-1 F = eta^T A(t) eta + 2 eta . beta(t) + gamma(t),
//   A = t I + S,  beta = t g + h,  gamma = t^3 + q t^2 + bn t + c0,
// and the conic degenerates where the quintic r(t) = det [[A, beta],
// [beta^T, gamma]] vanishes. Where A(t) is regular the degenerate conic is a
// pair of lines through p = -A^{-1} beta (real iff A is indefinite); where
// A(t) is singular (t = -eigenvalue of S, found in closed form) it is a pair
// of parallel lines, or a double line (the conic has rank 1), or one finite
// line plus l0 (A = 0).
//
// F contains the absolute conic, so every other plane through a finite line
// L cuts F in L and a circle: each line carries one family of circles, a
// double line a family of multiplicity two (the characteristic circles of a
// canal surface: Example 2 continued, Props. 2, 8, 9). If the quadratic part
// restricted to the planes n.X = t is a multiple of the identity, those
// planes cut circles too (one more family, through l0).
#pragma once

#include "cyclide/darboux.hpp"
#include "cyclide/surface.hpp"

namespace cyclide {
inline namespace v0 {

// A cubic surface has 27 lines; at most 10 of them meet l0 (two in each of
// the five planes through l0 whose conic degenerates).
constexpr int kMaxSectionPlanes = 5;
constexpr int kMaxCyclideLines = 10;

// Resolution of the analysis, in units of the cyclide's own length scale
// (SPEC §8c): degenerate planes closer than this are one plane, a conic
// whose discriminant is below it is a double line.
constexpr double kLineAnalysisTol = 1e-9;

enum class SectionKind : int {
  line_pair = 1,       // two distinct real lines (meeting, or parallel)
  double_line = 2,     // one real line counted twice
  imaginary_pair = 3,  // complex conjugate lines: one real point or none
  line_and_l0 = 4,     // one finite line; l0 is a double component
};

// A plane n.X = t through l0 whose conic is degenerate.
struct SectionPlane {
  double t = 0;
  SectionKind kind = SectionKind::line_pair;
};

struct CyclideLine {
  Line line;             // P nearest the origin, d unit (orthogonal to n)
  double t = 0;          // the plane n.X = t that contains it
  int multiplicity = 1;  // 2 for a double line
};

struct ParabolicLines {
  Vec3d n = Vec3d::UnitZ();  // unit normal of the planes through l0
  int plane_count = 0;
  SectionPlane planes[kMaxSectionPlanes];
  int line_count = 0;  // distinct real finite lines
  CyclideLine lines[kMaxCyclideLines];
  bool l0_circles = false;  // the planes n.X = t cut circles

  // Real families of circles: one per line, plus the planes through l0.
  int circle_families() const { return line_count + (l0_circles ? 1 : 0); }
  // Families of multiplicity two (double lines): a canal surface has one,
  // a Dupin cyclide two.
  int double_families() const;
};

// The lines of a parabolic cyclide. not_parabolic unless darboux_type(D)
// is parabolic (a quartic is inverted first; see SPEC §8c).
Status parabolic_lines(const Darboux& D, ParabolicLines& out);

// The circle cut from F by the plane through the line L (on F) with unit
// normal m (m orthogonal to L.d), besides L itself; for the plane through
// l0 the residual is the other line of the pair (is_line). invalid_argument
// if L is not on F or m not orthogonal to L.d; empty_real_locus if the
// residual circle is imaginary, or if in the plane through l0 nothing
// finite is left (the section is L and l0 counted twice).
Status pencil_circle(const Darboux& D, const Line& L, const Vec3d& m, CircleOrLine& out);

// ------------------------------------------------ Props. 3 and 5 (§7, §8)

// The pencil of planes through the axis line L1 = (P1, d1), parameterized
// linearly as in the proofs of Props. 3 and 5: normal k + u n, k = n x d1,
// so that u -> +-inf gives the plane through l0. A line Lj of F in another
// plane meets the pencil's plane at Lj(u) = P + u d, linear in u.
Status pencil_line(const Vec3d& n, const Line& axis, const Line& Lj, Line& out);

// The inputs of Prop. 3 (PRCS: a double line as axis and two further lines,
// pairwise skew) and Prop. 5 (PRRS: a line as axis and three further lines,
// not all in one plane), as linearly parameterized lines. not_canal if F has
// no double line (Prop. 3); too_few_lines if F lacks the lines the
// proposition needs.
struct PencilInput {
  int axis = -1;       // index into ParabolicLines::lines
  int used[3] = {-1, -1, -1};
  Line curves[3];      // the linearly parameterized input lines
  int count = 0;       // 2 (PRCS) or 3 (PRRS)
};
Status prcs_input_from_lines(const ParabolicLines& A, PencilInput& out);
Status prrs_input_from_lines(const ParabolicLines& A, PencilInput& out);

// Parameterize the parabolic cyclide D over u in [u0, u1] (f = v) whose
// circles are cut by the pencil of the chosen axis. Candidates (axis and
// lines) are tried in order until PRCS/PRRS is regular on the whole domain:
// a pencil plane through the common point of two input lines (PRRS points
// coincide there) or with parallel normal planes (PRCS) fails a candidate;
// if all fail, the first failure's status is returned.
Status parameterize_parabolic_prcs(const Darboux& D, double u0, double u1, Surface& out,
                                   PencilInput* input = nullptr);
Status parameterize_parabolic_prrs(const Darboux& D, double u0, double u1, Surface& out,
                                   PencilInput* input = nullptr);

// ------------------------------------------------ §8: PRRS of three lines

// Three lines l_i(u) = P_i + u d_i with a common normal (51). Prop. 4: PRRS
// gives a parabolic cyclide iff, in the normal form (52) (l1, l2 in one
// plane meeting at one parameter; l3 in the plane z = 1), (55) and (56)
// hold. Values are those of the normal form.
struct PrrsLinesAnalysis {
  bool coplanar_pair = false;   // l1, l2 in one plane (else: not a cyclide)
  bool common_parameter = false;  // l1(u0) = l2(u0) for one u0
  double a2 = 0, b2 = 0, a3 = 0, b3 = 0, x3 = 0, y3 = 0;  // normal form (52)
  double cond55 = 0;  // b2 (1 - a3) - b3 (1 - a2): != 0 for a pencil
  double cond56 = 0;  // b2 (a3^2+b3^2) - b3 (a2^2+b2^2) + a2 b3 - a3 b2
  bool pencil = false;   // (55) holds
  bool cyclide = false;  // (55) and (56) hold: Prop. 4
  // The nonzero root of (56) with d3 -> mu d3 (0 if there is none).
  double mu = 0;
  Line l4;  // the axis of the pencil Sigma (59), in the input coordinates
};
// Needs l1, l2 of the normal form as lines[0], lines[1] (in one plane);
// parallel_lines / no_common_normal as DCMC.
Status prrs_lines_analysis(const Line (&lines)[3], PrrsLinesAnalysis& out);

// §8's construction: DCMC on l1, l3, l4, and the member containing l2
// (the linear equation for alpha). The cyclide is returned normalized;
// `residual` is the largest relative residual of l2 on it (~0 iff (56)).
// invalid_argument unless (55) holds.
Status prrs_lines_cyclide(const Line (&lines)[3], Darboux& out, double* residual = nullptr);

}  // namespace v0
}  // namespace cyclide
