// Powell-Sabin 6-split C^1 piecewise quadratic interpolation (Powell & Sabin
// 1977), for seed 004 §4.2: the isotropic data (B_i, beta_i) = points
// (b_i, z_i) with tangent planes z = z_i + g_i . (y - b_i) are interpolated
// by the graph of a C^1 piecewise quadratic over a triangulation of the b_i.
// The paper's invariance under translations (2.5) and offsets (2.6) - both
// add a quadratic to the graph - rests on the quadratic precision of this
// interpolant: data sampled from a quadratic give that quadratic back.
//
// The split of a macro triangle V0 V1 V2 (counter-clockwise):
//   Z    its incenter (inside, and the segment joining the incenters of two
//        neighbours crosses their common edge inside it);
//   R_k  on the edge V_k V_{k+1}: for an interior edge the intersection of
//        the edge with the segment Z Z' to the neighbour's incenter (so Z,
//        R_k, Z' are collinear: the C^1 condition across the macro edge
//        is then met by the rule for R_k's ordinate below); for a boundary
//        edge its midpoint. R_k = (1 - l_k) V_k + l_k V_{k+1}.
// Bezier ordinates (P(u, w) = the ordinate at the midpoint of u and w):
//   at V_k                     z_k
//   P(V_k, R), P(V_k, Z)       the tangent plane of vertex k there
//   at R_k                     (1 - l_k) P(V_k, R_k) + l_k P(V_{k+1}, R_k)
//   P(R_k, Z)                  (1 - l_k) P(V_k, Z) + l_k P(V_{k+1}, Z)
//   at Z                       sum a_i P(V_i, Z), (a_0, a_1, a_2) the
//                              barycentric coordinates of Z (the plane
//                              through the three P(V_i, Z), evaluated at Z)
// For data from a quadratic f each ordinate is f's polar form f[u, w]
// (affine in each argument), hence quadratic precision.
//
// Output order: 6 micro-triangles per macro triangle t, at 6t + 2k the
// triangle (V_k, R_k, Z) and at 6t + 2k + 1 the triangle (R_k, V_{k+1}, Z),
// k = 0, 1, 2, V_k = b[tri[t][k]] (all counter-clockwise).
#pragma once

#include <cstddef>

#include "cyclide/bezier_triangle.hpp"
#include "cyclide/delaunay.hpp"
#include "cyclide/status.hpp"

namespace cyclide {
inline namespace v0 {

// Ints of workspace powell_sabin_interpolate needs for ntri triangles
// (the sorted edges and the adjacency: 6 ntri), ntri in 1..kMaxTriangles
// (0 for any other ntri).
std::size_t powell_sabin_workspace_size(int ntri) noexcept;

// The interpolant of values z[i] and gradients g[i] at the points b[i]
// over the triangulation tri[0..ntri) (e.g. from delaunay_triangulate), as
// 6 ntri QuadraticGraphTriangles in out[0..nout). Statuses:
//   invalid_argument  null pointers, n < 3, ntri outside 1..kMaxTriangles
//                     (delaunay.hpp: 6 ntri fits in an int), or a bad triangulation
//                     (see validate_triangulation: index out of range,
//                     clockwise or zero-area triangle, non-manifold edge)
//   not_finite        a NaN/Inf or |x| > 1e100 among b, z, g
//   buffer_too_small  work_len < powell_sabin_workspace_size(ntri), or
//                     out_cap < 6 ntri (nout gets 6 ntri)
//   numerical_overflow  a non-finite ordinate (a guard: inputs within 1e100
//                       keep every ordinate below ~1e201)
// On error out is untouched.
Status powell_sabin_interpolate(const Vec2d* b, const double* z, const Vec2d* g, int n,
                                const int (*tri)[3], int ntri, int* work, std::size_t work_len,
                                QuadraticGraphTriangle* out, int out_cap, int& nout) noexcept;

// The incenter of the triangle a, b, c (the split point Z).
Vec2d triangle_incenter(const Vec2d& a, const Vec2d& b, const Vec2d& c) noexcept;

// Barycentric coordinates (r, s, t) of p with respect to the triangle's
// vertices; invalid_argument for a zero-area triangle.
Status quadratic_graph_barycentric(const QuadraticGraphTriangle& q, const Vec2d& p,
                                   double bary[3]) noexcept;

// Value and gradient (d/dy1, d/dy2) of the quadratic at the point p (any p:
// the polynomial is extended beyond the triangle); invalid_argument for a
// zero-area triangle.
Status quadratic_graph_eval(const QuadraticGraphTriangle& q, const Vec2d& p, double& value,
                            Vec2d& gradient) noexcept;

// The first of patches[0..count) whose triangle contains p, with a
// tolerance tol on the barycentric coordinates (each >= -tol); index = -1
// and bad_domain if none. A linear scan, meant for tests and small inputs.
Status quadratic_graph_locate(const QuadraticGraphTriangle* patches, int count, const Vec2d& p,
                              double tol, int& index) noexcept;

}  // namespace v0
}  // namespace cyclide
