// Rational Bezier export of seed 002's sphere skins (issue 9 item 1: "the
// sphere skins where exact, else with a stated tolerance"), into the same
// RationalBezierPatch as the circle families (rational_export.hpp), so the
// NURBS assembly, the JSON writer and the C ABI's export handle serve both.
//
// (K1) theta is exact. sphere_skin.hpp's skin_lambda_polynomials writes
//        s(theta, t) = alpha(t) + (L0 + Lc c + Ls s)(c V1(t) + s V2(t)),
//      c = cos theta, s = sin theta: a trigonometric polynomial of degree 2
//      in theta. The export's v is v = tan(theta / 2) (theta = 2 atan v;
//      v = +-inf is theta = pi), the rational circle parameter, so that
//      c = C / omega, s = S / omega with C = 1 - v^2, S = 2 v,
//      omega = 1 + v^2, and
//        X_h(t, v) = (omega^2, alpha omega^2 + (L0 omega + Lc C + Ls S)
//                                              (C V1 + S V2)),
//      of degree 4 in v, with the weight omega^2 independent of t.
// (K2) v-pieces: [v0, v1] is split at -1, 0 and 1 (a whole circle gives
//      (-inf, -1], [-1, 0], [0, 1], [1, inf)), so no piece spans more than
//      90 degrees; |v| >= 1 is written in w = 1/v (X_h w^4, as (E5) of
//      rational_export.hpp, reciprocal_v). On a piece [x0, x1] (x = v or w,
//      x0 x1 >= 0) omega has the Bernstein coefficients (1 + x0^2,
//      1 + x0 x1, 1 + x1^2) > 0, so every weight (a coefficient of omega^2)
//      is positive.
// (K3) t is approximated where the skin is not rational. alpha and the L's
//      are cubics (exact), but V1, V2 are the rotation-minimizing frame,
//      which is not rational -- except when the spine is a straight line
//      and delta = 0 (the RMF pairing): then V1, V2 are constant and the
//      export is exact (report.exact). On each t-interval V1 and V2 are
//      interpolated by polynomials of degree q at the q + 1 Chebyshev-
//      Lobatto points of the interval, which include its ends, so
//      neighbouring intervals (and the patches of a chain, which share
//      their circles and theta-curves) meet exactly. Bidegree (q + 3, 4).
// (K4) Error. X - X_approx = lambda (c dV1 + s dV2), dV the interpolation
//      errors, so for every theta
//        |X - X_approx| <= (|L0| + hypot(Lc, Ls)) sqrt(|dV1|^2 + |dV2|^2);
//      this bound is sampled at 3 q points of an interval (between the
//      nodes, where interpolation errors peak) and the interval bisected
//      until it is <= tolerance. Every patch is then compared with
//      skin_eval at 5 x 5 points (deviation <= 2 tolerance + 1e-12 |x|,
//      else numerical_overflow). The report's error_estimate is the larger
//      of the sampled bound and the measured deviation. The skin's own RMF
//      table is accurate to rmf.error_estimate (a unit vector), i.e. to
//      rmf_error = that times the largest |lambda|, also reported: the
//      distance to the exact rotation-minimizing skin is at most
//      error_estimate + rmf_error.
//
// Chains: skins[0..n) with u = k + t on patch k (u in [0, n]); each
// t-interval lies in one patch, u-intervals in increasing u.
// Allocation: none (evaluation tier; ~40 KB of stack).
// Work per t-interval: (q + 1) + 3 q frame evaluations (skin_directions),
// 6 (3 + q)-degree products; per patch 25 skin_eval.
#pragma once

#include "cyclide/rational_export.hpp"
#include "cyclide/sphere_skin.hpp"

namespace cyclide {
inline namespace v0 {

constexpr int kMaxSkinExportDegree = 24;  // q (deg_u = q + 3)

struct SkinExportOptions {
  double tolerance = 1e-9;  // absolute (model units), > 0
  int degree = 7;           // q in 1..kMaxSkinExportDegree
};

struct SkinExportReport {
  double error_estimate = 0.0;  // (K4): max sampled bound and measured deviation
  double rmf_error = 0.0;       // (K4): the RMF table's error times max |lambda|
  bool exact = false;           // (K3): every spine straight and delta = 0
  int t_intervals = 0;          // u-intervals of the export
};

// The patches of the chain skins[0..n) over D (u in [0, n], v = tan(theta/2)
// in [v0, v1] or the whole circle) into out[0..cap), u-major (all v-pieces
// of the first u-interval, then the next), each of bidegree
// (options.degree + 3, 4). Statuses: null_argument (skins null; out null
// with cap >= count); invalid_argument (n < 1, tolerance not > 0 or not
// finite, degree outside 1..kMaxSkinExportDegree); not_finite (a NaN or
// infinite bound); bad_domain (not 0 <= u0 < u1 <= n, not v0 < v1);
// numerical_overflow (the tolerance not met after kMaxExportDepth
// bisections or within kMaxExportUPieces intervals -- e.g. below the
// rounding of a large skin -- or a patch failing the check (K4));
// buffer_too_small (count = the number needed, nothing written; out may be
// null with cap = 0). out (and report) are written only on ok, after every
// patch was built and checked (two passes).
Status export_sphere_skin(const SphereSkin* skins, int n, const ExportDomain& D,
                          const SkinExportOptions& options, RationalBezierPatch* out, int cap,
                          int& count, SkinExportReport* report = nullptr);

}  // namespace v0
}  // namespace cyclide
