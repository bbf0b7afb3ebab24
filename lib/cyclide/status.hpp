// Status codes of the core. The numbers are frozen: they equal the C ABI's
// CYC_* codes (capi static_asserts it). New codes are added, never renumbered.
#pragma once

namespace cyclide {
inline namespace v0 {

enum class Status : int {
  ok = 0,
  // 1..99: invalid input (the caller can fix the call)
  null_argument = 1,
  invalid_argument = 2,
  not_finite = 3,
  degree_too_high = 4,
  bad_domain = 5,
  // 100..199: degenerate geometry named by the papers
  dependent_planes = 100,   // PRCS/PRRS planes (near) dependent; Remark 1
  zero_tangent = 101,       // p'(u) = 0: normal plane undefined
  collinear_points = 102,   // PRRS: p1, p2, p3 collinear
  degenerate_circle_parameter = 103,  // f(u,.) not a Mobius map (ad-bc = 0)
  not_canal = 104,          // canal-only query on a non-canal surface
  singular_point = 105,     // normal undefined (x_u x x_v = 0)
  degenerate_ringed = 106,  // eq. (3): n . c' = 0, sphere family undefined
  parallel_lines = 107,     // DCMC: two of the input lines are parallel
  no_common_normal = 108,   // DCMC: the line directions do not share a normal
  rank_deficient = 109,     // a linear system has more freedom than expected
  at_inversion_center = 110,  // a point at the inversion center (image at infinity)
  not_parabolic = 111,      // a query for parabolic (cubic, irreducible) cyclides only
  empty_real_locus = 112,   // the requested real object (circle, surface) is empty
  too_few_lines = 113,      // Props. 3, 5: the cyclide lacks the lines they need
  no_normal_form = 114,     // Props. 2, 8, 9: the input has no normal form (coplanar, ...)
  not_pythagorean = 115,    // seed 001 §3-4: no P-curve (a norm is not a polynomial square)
  intersecting_circles = 116,  // seed 001 §6: two joining circles on the auxiliary sphere meet
  nested_spheres = 117,        // seed 002: one sphere inside (or equal to) the other
  curvature_radius_too_large = 118,  // seed 002 Remark 2: kappa r >= 1 at an end (a c <= 0)
  sphere_pencil = 119,  // seed 003 §3.1 Case I: dim span(a1,a2,a3) = 2, a pencil of touching spheres (no envelope)
  no_touching_sphere = 120,  // seed 003 §3.1 Case II.1: A = R^{1,2}, no Lie sphere touches all three
  single_touching_sphere = 121,  // seed 003 §3.1 Case II.2: A = R^{1,1,1}, exactly one sphere touches all three
  degenerate_cyclide = 122,  // seed 003 §3.3: A or its complement lies in e_r-perp (all spheres are points): a curve, not a surface
  not_isometric = 123,  // seed 003 Thm. 2.3: Gram matrices or signatures differ, no orthogonal map exists
  not_on_lie_quadric = 124,  // seed 003 (2): the vector is not neutral (not a Lie sphere)
  point_at_infinity = 125,  // seed 003 (26): the point sphere is n_inf (the point lies at infinity)
  tangent_generating_spheres = 126,  // seed 003 Lemma 4.6 (i): r0 . s0 = 0, the cones' generating spheres touch
  blend_folds = 127,  // seed 003 Alg. 2: a cyclide patch meets a glued circle from the wrong side (the blend folds back)
  developable = 128,  // seed 004 Thm. 3.2: the plane and its two partials are dependent (Psi degenerates to a curve: no envelope point)
  pole_in_gauss_image = 129,  // seed 004 §4.2: an oriented plane has unit normal W = (0,0,1), the projection centre (no point of the isotropic model)
  ridge = 130,  // seed 004 Fig. 3: adjacent patches share tangent planes along an edge but meet in an edge of regression
  // 200..299: numerical failure
  numerical_overflow = 200,
  // 300..399: resources
  buffer_too_small = 300,
  out_of_memory = 301,
  io_error = 302,  // a file or stream could not be written (the C library's errno tells why)
  // 400..499: misuse / unsupported
  unsupported = 400,
  internal_error = 401,
};

// Static name of a status ("CYC_E_DEPENDENT_PLANES"), never NULL.
const char* status_name(Status s) noexcept;

}  // namespace v0
}  // namespace cyclide
