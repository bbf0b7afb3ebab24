// Seed 001 §7.a: approximate parameterization of an implicit ringed blend
// (73) by exact rational ringed surfaces. Three contour branches c_vi are
// Ferguson cubics p_i -> q_i with tangents alpha_i t_pi, beta_i t_qi (80);
// Ceres chooses alpha_i, beta_i minimizing Omega (81)-(83); the directrix
// is the circumcentre of c_v1, c_v2, c_v3 and the surface make_ringed(d,
// n, c_v1) (implicit_blend.hpp: ringed_through_cubics). Refinement (84):
// pieces between planes perpendicular to the auxiliary directrix.
// Optimizer tier: allocates (Ceres); only in libcyclide_optim.
#pragma once

#include "cyclide/implicit_blend.hpp"

namespace cyclide {
inline namespace v0 {
namespace optim {

constexpr int kMaxImplicitPieces = 8;

struct ImplicitApproxOptions {
  int pieces = 1;             // 1..kMaxImplicitPieces: cut planes (84) at tau = k/pieces
  double psi_weight = 0.01;   // w of (81); Psi is scaled by L^2 (L = |s2 - s1|)
  int nodes = 16;             // Gauss-Legendre nodes of (82), (83) (2..64)
  double length_min_ratio = 0.1;  // alpha, beta in [min, max] |q_i - p_i|
  double length_max_ratio = 4.0;
  int max_iterations = 50;
  double function_tolerance = 1e-12;
  double gradient_tolerance = 1e-14;
  double parameter_tolerance = 1e-12;
  int error_nodes_t = 16;     // (87): Gauss-Legendre in t (1..64)
  int error_nodes_u = 32;     // (87): trapezoid on the circle (4..1024)
  bool two_curves = false;    // Remark 7.5: both branches of v[0]'s contour curve
                              // and one of v[1]'s (v[2] unused)
};

struct ImplicitApproxPiece {
  double omega_initial = 0;  // Omega (81) at alpha = beta = |q - p|
  double omega = 0;          // Omega at the result
  double error87 = 0;        // (87) of this piece's surface (t in [0, 1])
  double alpha[3] = {0, 0, 0}, beta[3] = {0, 0, 0};
  int iterations = 0;
  bool reverted = false;     // the solve did not lower Omega: the start kept
};

struct ImplicitApproxReport {
  int pieces = 0;
  double omega = 0;     // sum over the pieces
  double error87 = 0;   // (87) of the piecewise surface on I = [0, 1]: piece k
                        // on [k/m, (k+1)/m], i.e. sum_k piece[k].error87 / m
  double seconds = 0;
  ImplicitApproxPiece piece[kMaxImplicitPieces];
  ContourPiece data[kMaxImplicitPieces];  // end points, tangents, centres, dbar per piece
};

// Approximates B by options.pieces exact ringed surfaces (pieces[0 ..
// count-1], written only on success, with the report). Statuses:
// invalid_argument (options out of range, v_i = 0 or two v_i parallel),
// not_finite, and those of contour_piece, plane_contour_newton (cut-plane
// points), ringed_through_cubics and blend_error_87.
Status approximate_implicit_blend(const ImplicitBlend& B, const Vec3d (&v)[3],
                                  const ImplicitApproxOptions& options,
                                  Surface (&pieces)[kMaxImplicitPieces], int& count,
                                  ImplicitApproxReport& report);

}  // namespace optim
}  // namespace v0
}  // namespace cyclide
