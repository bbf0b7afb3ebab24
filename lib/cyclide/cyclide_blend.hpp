// Blending two cones (canal surfaces) with one or two Dupin cyclides in Lie
// sphere geometry (seed 003 §4, Algorithm 2).
//
// A cone is the tangent cone of a canal surface along a composing circle:
// the subspace R = span(r0, r+) = R^{1,1,0} of R^{4,2} (Remark 3.1), r0 the
// sphere touching along the circle and r+ the derivative of the sphere
// family (33). Gluing is tangency of the sphere curves, so
//   dim(R + S) = 3: one cyclide, A = R + S (Case I);
//   dim(R + S) = 4: two cyclides A = R + T, B = S + T for every T =
//     span(alpha r0 + r+, beta s0 + s+) with (alpha, beta) on one of the two
//     hyperbolas (43), glued along the circle of t0 (44) (Case II).
// The output is the blend itself: each piece is a cyclide anchored so that
// xi = 0 is the sphere of its first glued circle, xi = infinity that of its
// second, and the patch is xi in [0, infinity] through xi = 1 (as a surface:
// u in [0, 1], xi = u / (1 - u)).
//
// Sides. r+ points into the blend: the normalized sphere family of the cone,
// continued past the circle, moves along +r+ (r0 normalized by (6) so that
// r0 . n_inf = -2, or by (9) for a plane, and r+ with the same functional
// zero). The first piece leaves r0 along +r+ by construction; a piece that
// reaches its second circle from the wrong side would fold the blend back
// over the cone or over the other piece: blend_folds.
#pragma once

#include "cyclide/dupin.hpp"
#include "cyclide/lie.hpp"
#include "cyclide/status.hpp"
#include "cyclide/surface.hpp"

namespace cyclide {
inline namespace v0 {

struct LieCone {
  Lie6d r0 = Lie6d::Zero();      // the sphere touching along the circle (normalized)
  Lie6d r_plus = Lie6d::Zero();  // the family's derivative, into the blend
};

// The cone of the spheres (m + h dm, rho + h drho): r0 the sphere (m, rho)
// by (4), r+ = d/dh of (4) = 2 dm + 2 (m . dm - rho drho) n_inf + 2 drho er.
// invalid_argument unless rho != 0 and |dm| > |drho| (r+ positive: a real
// cone, (11) strict); not_finite.
Status cone_from_spheres(const Vec3d& m, double rho, const Vec3d& dm, double drho,
                         LieCone& out);

// The cone (or cylinder) through the circle (center c, unit normal n,
// radius rho > 0) whose circles' radius changes by `slope` per unit length
// along +n (0: a cylinder; the apex, if any, is c - (rho / slope) n), with
// the blend leaving the circle along +n. orientation = +1: the normals
// point away from the axis; -1: towards it.
Status cone_from_circle(const Vec3d& c, const Vec3d& n, double rho, double slope,
                        int orientation, LieCone& out);
// The same from the apex (on the axis through c along n, not in the
// circle's plane: invalid_argument).
Status cone_from_circle_apex(const Vec3d& c, const Vec3d& n, double rho, const Vec3d& apex,
                             int orientation, LieCone& out);

// The tangent cone of a canal surface (kinds prcs and dupin) along its
// circle at u: its touching sphere and derivative, direction = +1 if the
// blend continues in +u (the surface ends at u), -1 if in -u; orientation
// as above (+1: the sphere's radius as the surface gives it, -1: reversed).
// not_canal for other kinds; the statuses of the surface's frame.
Status cone_from_surface(const Surface& S, double u, int direction, int orientation,
                         LieCone& out);

// The cone's circle (the characteristic circle of r0 along r+): center,
// unit plane normal (along the spine's motion) and radius.
Status cone_circle(const LieCone& R, Vec3d& center, Vec3d& normal, double& radius);

// The cone as a circle-family surface: the spheres (m + h dm, rho + h drho)
// for h in [h0, h1] (a cone or cylinder of revolution; h = 0 is the glued
// circle, h > 0 the blend's side). For continuity reports.
Status cone_surface(const LieCone& R, double h0, double h1, Surface& out);

// One patch of a blend: the cyclide with xi = 0 at its first glued sphere
// and xi = infinity at its second (see above).
struct CyclideBlendPiece {
  DupinCyclide cyclide;
  Lie6d first = Lie6d::Zero(), second = Lie6d::Zero();  // the glued spheres
};

struct CyclideBlend {
  int pieces = 0;  // 1: single cyclide (Case I), 2: double (Case II)
  CyclideBlendPiece piece[2];
  int branch = 0;            // double: the hyperbola (43), +1 or -1
  double alpha = 0, beta = 0;  // double: T = span(alpha r0 + r+, beta s0 + s+)
  Lie6d joint = Lie6d::Zero();  // double: t0 (44), the sphere of the joint circle
};

// dim(R + S) (3 or 4) after validating both cones: invalid_argument unless
// r0 is neutral, r+ positive and orthogonal to r0 (relative 1e-9);
// tangent_generating_spheres when r0 . s0 = 0 (Lemma 4.6 (i), omitted by the
// paper); invalid_argument when R = S.
Status cyclide_blend_dimension(const LieCone& R, const LieCone& S, int& dim);

// The points of (43): beta on branch +-1 for a given alpha, i.e.
// (alpha beta g00 + alpha g0+ + beta g+0 + g++) = branch sqrt(r+^2 s+^2)
// with g = r . s. invalid_argument at the asymptote alpha = -g+0/g00 (45)
// or for branch not +-1.
Status cyclide_blend_beta(const LieCone& R, const LieCone& S, int branch, double alpha,
                          double& beta);

// Algorithm 2. Case I (dim R + S = 3): the single cyclide, branch and alpha
// ignored. Case II: the double blend at (alpha, beta(alpha)) on `branch`.
// Statuses: those of cyclide_blend_dimension and cyclide_blend_beta;
// blend_folds (a piece reaches a glued circle from the wrong side); the
// statuses of dupin_from_vectors. `out` is written only on success.
Status cyclide_blend(const LieCone& R, const LieCone& S, int branch, double alpha,
                     CyclideBlend& out);

// A circle of a blend's patch (quality measures and the optimizer tier).
struct BlendCircle {
  Vec3d center = Vec3d::Zero();
  Vec3d normal = Vec3d::UnitZ();  // unit
  double radius = 0;
};

// Circle s of piece i's patch, defined geometrically (independent of how
// the Witt extension happened to parameterize the second family):
//   family 0: the circle at u = s in [0, 1] (xi = s / (1 - s)), a whole
//             zeta-circle of the patch (u = 0 and 1 are the glued circles);
//   family 1: the circle of the second family through the point of the
//             first glued circle (u = 0) at angle s (radians) from the
//             direction normal.unitOrthogonal() of that circle; its arc
//             xi in [0, infinity] lies in the patch, the rest does not.
// Family 1 is found by inverting the circle's Mobius parameter f(zeta) of
// dupin_frame at the point, then through the points at xi = 0, 1, infinity.
// Normals are unit with their largest component (by magnitude) positive, so
// that the angles s mean the same points however the construction oriented
// the circle.
// Allocation-free. Statuses: invalid_argument (piece, family, s outside
// [0, 1] for family 0), not_finite (s), point_at_infinity (a circle through
// infinity: a line), those of dupin_frame and dupin_eval_homogeneous.
Status cyclide_blend_circle(const CyclideBlend& B, int piece, int family, double s,
                            BlendCircle& out);

// The unit of the blend's frame: the power of 2 nearest to the cones' size
// (their circle centres' distance from their midpoint and the generating
// spheres' radii). alpha' = unit alpha is the scale-free family parameter:
// the cones of a model scaled by a power of 2 have the same blends at the
// same alpha' (alpha' . r0' + r+' in the frame, SPEC §8h.11).
Status cyclide_blend_unit(const LieCone& R, const LieCone& S, double& unit);

// Algorithm 2 with its free parameter chosen: Case I as above; Case II
// scans phi in (-pi/2, pi/2), alpha = tan(phi) / unit (unit: the power of 2
// nearest to the cones' size, common_frame; so that the scan samples the
// same blends of the model at every scale), at `samples` points on both
// branches (45's asymptote and failing points skipped), keeps the blend whose
// circles vary least (quality = min radius / max radius over 17 circles of
// the first family and 16 of the second per piece: both principal
// curvatures of a cyclide are constant along its circles) and refines phi
// by golden-section search between the best sample's neighbours. A sample
// becomes the best only if its pieces also build as surfaces
// (cyclide_blend_surface), so the result always does. *quality (may be
// null) receives the chosen blend's quality. The optimizer tier's
// optimize_cyclide_blend (optim/cyclide_blend_optimizer.hpp) chooses phi
// against a user objective instead.
// When no sample gives a valid blend: blend_folds if some sample folded,
// otherwise singular_point (every sample pinched). samples in [8, 4096].
Status cyclide_blend_auto(const LieCone& R, const LieCone& S, CyclideBlend& out,
                          int samples = 64, double* quality = nullptr);
// The quality measure above (min / max circle radius of the patches over
// cyclide_blend_circle's family 0 at u = k/16, k = 0..16, and family 1 at
// the angles 2 pi (k + 1/2) / 16; 0 if a family-1 circle runs through
// infinity). Errors of family-0 circles are returned.
Status cyclide_blend_quality(const CyclideBlend& B, double& quality);

// The patch of piece i as a circle-family surface (u in [0, 1] -> xi in
// [0, infinity], v = zeta).
Status cyclide_blend_surface(const CyclideBlend& B, int i, Surface& out);

// Whether every piece of B builds as a circle-family surface
// (cyclide_blend_surface OK): the validity test of the scans of
// cyclide_blend_auto and optimize_cyclide_blend.
bool cyclide_blend_pieces_build(const CyclideBlend& B);

// G1 at the three (two) glued circles: the largest gap and tangent-plane
// angle from continuity reports (blend.hpp) at n samples of each circle:
// the cone R's circle against piece 0 at u = 0, the joint (piece 0 at
// u = 1 against piece 1 at u = 1), and piece (pieces - 1) at u = 0 ... the
// cone S's circle against the last piece at its end.
struct CyclideBlendContinuity {
  double gap[3] = {};    // R end, joint (double blends), S end
  double angle[3] = {};  // radians
  double scale = 0;      // the largest circle radius + center norm (for relative gaps)
};
Status cyclide_blend_continuity(const LieCone& R, const LieCone& S, const CyclideBlend& B,
                                int n, CyclideBlendContinuity& out);

}  // namespace v0
}  // namespace cyclide
