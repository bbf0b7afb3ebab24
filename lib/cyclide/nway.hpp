// n-way blends of seed 001 §6, eqs. (62)-(67): n >= 3 ringed surfaces R_i
// are joined through an auxiliary sphere S (center s, radius r). The sphere
// is seen from each R_i as the ringed surface S_i (66) whose circles are
// perpendicular to the line from s to R_i's end center; a two-surface blend
// of §4 (make_ringed_pcurve_blend, eqs. (36)-(47)) joins R_i's end circle to
// the circle c_i = S_i(lambda_i) (Hermite data (67)). The joining circles
// must not intersect each other (checked exactly: circles on one sphere).
// Allocation-free; at most kMaxNwayEnds ends.
#pragma once

#include "cyclide/pcurve.hpp"
#include "cyclide/surface.hpp"

namespace cyclide {
inline namespace v0 {

constexpr int kMaxNwayEnds = 8;

// Where the sphere's center s comes from.
enum class NwayCenter : int {
  automatic = 0,  // s = y + alpha N (63) with alpha chosen from the end tangents
  alpha = 1,      // s = y + alpha N (63) with the caller's alpha
  given = 2,      // s = options.s (Example 6.2 gives s directly, (69))
};

// On which side of s the joining circle c_i = S_i(lambda_i) lies.
//  facing:  S_i runs from the pole facing R_i's end (t = 0) to the far pole
//           (t = 1): d*(t) = s + r n*_i - 2 r t n*_i, i.e. (66) with n*_i
//           replaced by m_i = -n*_i. The blend arrives moving into the
//           sphere, as R_i's end moves towards it: no turn-back (default).
//  printed: (66) exactly as printed, d*(t) = s - r n*_i + 2 r t n*_i: small
//           lambda lies on the side of s opposite R_i's end, and the jet
//           (67) moves towards R_i (the blend has to pass the sphere and
//           turn back). Kept to reproduce the paper's numbers.
// printed at lambda is the facing circle at 1 - lambda (reversed in t).
enum class NwaySide : int { facing = 0, printed = 1 };

struct NwayOptions {
  NwayCenter center = NwayCenter::automatic;
  double alpha = 0.0;        // center == alpha: the factor of N in (63)
  Vec3d s = Vec3d::Zero();   // center == given
  double r = 0.0;            // > 0: the radius (65); 0: r_fraction * bound
  double r_fraction = 0.5;   // in (0, 1), used when r == 0
  double lambda[kMaxNwayEnds] = {0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5};  // in (0, 1)
  NwaySide side = NwaySide::facing;
  bool require_disjoint = true;  // intersecting joining circles are an error
  // Choose the lambda_i ("lambda_i chosen so that the circles c_i do not
  // intersect", §6) instead of taking options.lambda: theta_i = 0.45 min_j
  // angle(axis_i, axis_j), so theta_i + theta_j <= 0.9 angle(axis_i,
  // axis_j) and every gap is at least a tenth of its axes' angle;
  // lambda_i = (1 - cos theta_i) / 2. (The largest caps with that margin;
  // their size is not otherwise optimized.)
  bool auto_lambda = false;
  bool auto_v = true;  // each blend's projection direction v = n_a x n_b (normalized),
                       // else blend.v for every blend
  RingedBlendOptions blend;  // sign, tau (degree 6 or P-biarc), v, bump of every blend
};

// The auxiliary sphere and the joining circles (steps (63)-(66)).
struct NwaySphere {
  int n = 0;
  Vec3d y = Vec3d::Zero();  // (64) the incentre (n = 3); the centroid (n > 3)
  Vec3d N = Vec3d::Zero();  // (63) the normal: Newell's sum_k d_k x d_{k+1}
                            // (= (d1 - d2) x (d1 - d3) for n = 3)
  double alpha = 0.0;       // the alpha used (0 when s was given)
  Vec3d s = Vec3d::Zero();
  double r = 0.0;
  double bound = 0.0;       // (65): min_i |d_i - s|; r in (0, bound)
  double clear_bound = 0.0; // min_i (|d_i - s| - rho_i): r below it keeps the
                            // end circles off the sphere (reported, not enforced)
  Vec3d n_star[kMaxNwayEnds] = {};      // (66): (d_i - s) / |d_i - s|
  double distance[kMaxNwayEnds] = {};   // |d_i - s|
  double lambda[kMaxNwayEnds] = {};     // the lambda_i used (options' or chosen)
  double theta[kMaxNwayEnds] = {};      // angular radius of c_i: cos = 1 - 2 lambda_i
  // Signed angular gap between c_i and c_j (radians): > 0 disjoint (the
  // geodesic distance between the circles), <= 0 intersecting. nested: the
  // circles are disjoint with one cap inside the other.
  double gap[kMaxNwayEnds][kMaxNwayEnds] = {};
  bool nested[kMaxNwayEnds][kMaxNwayEnds] = {};
  double min_gap = 0.0;
  int worst_i = -1, worst_j = -1;  // the pair of min_gap
};

// The jet of S_i at lambda (67) on the given side: d*, d*' = -+2 r n*, n =
// orientation * (unit travel direction), n' = 0, rho* = 2 r sqrt(l (1 - l)),
// rho*' = r (1 - 2 l) / sqrt(l (1 - l)). orientation is +1 or -1.
RingedJet nway_sphere_jet(const Vec3d& s, double r, const Vec3d& n_star, double lambda,
                          NwaySide side, int orientation);

// (63)-(66) and the circle test from the end jets (d_i = ends[i].d, the end
// tangents ends[i].dd pointing away from R_i). Statuses: invalid_argument
// for n outside [3, kMaxNwayEnds], r_fraction outside (0, 1) or r < 0;
// not_finite for non-finite data; collinear_points when the end centers are
// collinear or coincident (|N| <= 1e-12 L^2, L their largest distance:
// the incentre (64) and the plane of (63) are undefined); bad_domain for a
// lambda outside (0, 1) or r outside (0, bound) (the sphere would contain an
// end center, (65)); intersecting_circles when two joining circles meet and
// options.require_disjoint; numerical_overflow if s leaves 1e100. out is
// written on success, bad_domain and intersecting_circles (for the report),
// untouched otherwise.
Status nway_sphere(const RingedJet* ends, int n, const NwayOptions& options, NwaySphere& out);

struct NwayReport {
  NwaySphere sphere;
  RingedJet end_jet[kMaxNwayEnds];     // R_i at its end, oriented away from R_i
  RingedJet sphere_jet[kMaxNwayEnds];  // S_i at lambda_i (67), as interpolated
  Vec3d v[kMaxNwayEnds] = {};          // the projection direction of each blend
  int failed_end = -1;                 // the blend that failed (-1: none)
};

// The n-way blend: ends[i] is R_i, end_u[i] its end parameter (the end of
// [u0, u1] nearer to end_u[i] says which way R_i leaves: at u1 the jet is
// taken as is, at u0 reversed). blends[i][0..count[i]-1] = B_i from R_i's end
// (t = 0) to c_i (t = 1), C^1 in (d, n, rho) at both ends. n of S_i is the
// unit travel direction signed like n_i . d_i' at R_i's end (n_i . m_i if
// that is ~0), so that n does not turn over along B_i. Statuses of
// nway_sphere, ringed_jet (bad_domain for end_u outside [u0, u1]) and
// make_ringed_pcurve_blend (with *bad_u; report->failed_end says which;
// its not_finite — data valid, a jet beyond 1e100 — as numerical_overflow,
// also for end jets beyond 1e100). Nothing is written to blends/count on error; report (may be null) is
// filled as far as the construction got.
Status make_ringed_nway_blend(const Surface* const* ends, const double* end_u, int n,
                              const NwayOptions& options, Surface (&blends)[kMaxNwayEnds][2],
                              int (&count)[kMaxNwayEnds], NwayReport* report = nullptr,
                              double* bad_u = nullptr);

// The sphere (s, r) as a ringed surface for display: circles perpendicular
// to the unit axis m, centers on s + r (2t - 1)/(1 - 2t + 2t^2) m, t in
// [0, 1] (c(t) = s + r ((2t - 1) m + 2t(1 - t) e) / (1 - 2t + 2t^2), e
// perpendicular to m, a rational quadratic meridian), trimmed to [eps,
// 1 - eps] (eps = 1e-3) away from the poles, where the circles vanish.
Status nway_sphere_surface(const Vec3d& s, double r, const Vec3d& m, Surface& out);

}  // namespace v0
}  // namespace cyclide
