// G1 surface design with parabolic Dupin cyclide patches (seed 004 §4.2);
// see cyclide_design.hpp.
#include "cyclide/cyclide_design.hpp"

#include <cmath>
#include <algorithm>
#include <cstdint>

#include "cyclide/config.hpp"
#include "cyclide/delaunay.hpp"
#include "cyclide/parabolic_cyclide.hpp"
#include "cyclide/powell_sabin.hpp"

namespace cyclide {
inline namespace v0 {

namespace {

bool normal_near_pole(const Vec3d& a) {
  // |a - W|^2 = (a1^2 + a2^2) + (1 - a3)^2 for unit a.
  return a[2] > 0 && std::hypot(a[0], a[1]) <= kPoleTol;
}

double cross(const Vec2d& p, const Vec2d& q) { return p[0] * q[1] - p[1] * q[0]; }

}  // namespace

Status isotropic_datum(const OrientedPoint& A, IsotropicDatum& out) noexcept {
  if (!A.point.allFinite() || !A.normal.allFinite()) return Status::not_finite;
  if (A.point.cwiseAbs().maxCoeff() > kMaxInputMagnitude) return Status::not_finite;
  // alpha: the plane through A with unit normal a, e0 = -a . A (3.1).
  OrientedPlane alpha;
  if (Status st = normalize_plane(0.0, A.normal, alpha); st != Status::ok) return st;
  alpha.e0 = -alpha.e.dot(A.point);
  if (normal_near_pole(alpha.e)) return Status::pole_in_gauss_image;
  IsotropicPoint B;
  if (Status st = laguerre_to_isotropic(alpha, B); st != Status::ok) return st;
  if (B.exceptional) return Status::pole_in_gauss_image;
  IsotropicDatum d;
  d.b = B.y.head<2>();
  d.z = B.y[2];
  // The tangent plane of the paraboloid (2.4) of the point cycle (A, 0).
  d.g = -(A.point[2] * d.b + A.point.head<2>());
  if (!d.b.allFinite() || !std::isfinite(d.z) || !d.g.allFinite())
    return Status::numerical_overflow;
  out = d;
  return Status::ok;
}

Status oriented_point_from_isotropic(const IsotropicDatum& d, OrientedPoint& out) noexcept {
  if (!d.b.allFinite() || !std::isfinite(d.z) || !d.g.allFinite()) return Status::not_finite;
  const double N = 1 + d.b.squaredNorm();
  if (!std::isfinite(N)) return Status::numerical_overflow;
  OrientedPoint A;
  A.normal = Vec3d(2 * d.b[0] / N, 2 * d.b[1] / N, 1 - 2 / N);
  const double e0 = 2 * d.z / N;
  const double A3 = e0 - A.normal[0] * d.g[0] - A.normal[1] * d.g[1];
  A.point = Vec3d(-d.g[0] - A3 * d.b[0], -d.g[1] - A3 * d.b[1], A3);
  if (!A.point.allFinite()) return Status::numerical_overflow;
  out = A;
  return Status::ok;
}

bool gauss_image_contains_pole(const OrientedPoint* data, int n) noexcept {
  if (!data || n <= 0) return false;
  // The smallest angular sector (lo, hi), narrower than pi, holding the
  // gnomonic projections p = (a1, a2)/a3 of the normals with a3 > 0, grown
  // one point at a time: a new point outside it fits on at most one side
  // (the two extensions' widths add up to 2 pi plus the old width). None
  // fits: the directions surround the origin, W is in the normals' cone.
  bool any = false;
  Vec2d lo, hi;
  for (int i = 0; i < n; ++i) {
    const Vec3d& a = data[i].normal;
    const double len = a.norm();
    if (!(len > 0) || !std::isfinite(len)) continue;
    const Vec3d u = a / len;
    if (normal_near_pole(u)) return true;
    if (!(u[2] > 0)) continue;  // below the equator: not in the cone test
    const Vec2d p = u.head<2>() / u[2];
    if (!any) {
      lo = hi = p;
      any = true;
      continue;
    }
    const double c_lo = cross(lo, p), c_hi = cross(p, hi);
    if (c_lo >= 0 && c_hi >= 0) {
      // Inside the sector, or on a ray of a zero-width one: opposite to it?
      if (c_lo == 0 && c_hi == 0 && lo.dot(p) < 0) return true;
      continue;
    }
    if (c_lo > 0) hi = p;        // beyond hi, within pi of lo
    else if (c_hi > 0) lo = p;   // before lo, within pi of hi
    else return true;            // in the opposite sector
  }
  return false;
}

GraphPointJet graph_point_jet(const Vec2d& y, double z, const Vec2d& g,
                              const Eigen::Matrix2d& H) noexcept {
  // The plane of (4.4) over the graph and its partials (P is quadratic in y).
  const Vec4d P(2 * z, 2 * y[0], 2 * y[1], y.squaredNorm() - 1);
  const Vec4d P1(2 * g[0], 2, 0, 2 * y[0]), P2(2 * g[1], 0, 2, 2 * y[1]);
  const Vec4d P11(2 * H(0, 0), 0, 0, 2), P12(2 * H(0, 1), 0, 0, 0), P22(2 * H(1, 1), 0, 0, 2);
  const Vec4d X = exterior_product(P, P1, P2);
  const Vec4d X1 = exterior_product(P, P11, P2) + exterior_product(P, P1, P12);
  const Vec4d X2 = exterior_product(P, P12, P2) + exterior_product(P, P1, P22);
  GraphPointJet J;
  J.x = X.tail<3>() / X[0];
  J.x_1 = (X1.tail<3>() - X1[0] * J.x) / X[0];
  J.x_2 = (X2.tail<3>() - X2[0] * J.x) / X[0];
  const double N = 1 + y.squaredNorm();
  J.n = Vec3d(2 * y[0] / N, 2 * y[1] / N, 1 - 2 / N);
  return J;
}

namespace {

// A carve-out of the caller's workspace, aligned for T.
template <class T>
T* carve(unsigned char*& at, std::size_t count) {
  auto addr = reinterpret_cast<std::uintptr_t>(at);
  addr = (addr + alignof(T) - 1) / alignof(T) * alignof(T);
  T* p = reinterpret_cast<T*>(addr);
  at = reinterpret_cast<unsigned char*>(p + count);
  return p;
}

// Bytes for count T's at worst alignment.
template <class T>
std::size_t room(std::size_t count) {
  return count * sizeof(T) + alignof(T);
}

// Ints shared by the triangulation, the peeling and the interpolation
// (one at a time); the peeling needs neighbours and vertex counts besides
// validate_triangulation's own.
std::size_t int_workspace(int n, int ntri) {
  const int tri_room = ntri > 0 ? ntri : delaunay_max_triangles(n);
  const std::size_t tri_ints =
      ntri > 0 ? 0
               : std::max(delaunay_workspace_size(n),
                          triangulation_workspace_size(tri_room) + 3 * std::size_t(tri_room) + n);
  return std::max(tri_ints, powell_sabin_workspace_size(tri_room));
}

// A boundary triangle whose angle opposite its boundary edge has a cosine
// below this (about 172 degrees) is a sliver.
constexpr double kSliverCos = -0.99;

// Delaunay triangulates the convex hull. Data whose border is straight up
// to rounding (a grid, a cut-off cap) give nearly collinear hull points,
// and Delaunay joins them by slivers, over which the Powell-Sabin split
// fails or its patches fold. Such boundary triangles are peeled off, pass
// after pass, unless that would leave a vertex in no triangle. Returns
// the new triangle count (tris compacted in place).
int peel_boundary_slivers(const Vec2d* b, int n, int (*tris)[3], int nt, int* work,
                          std::size_t work_len) {
  for (bool peeled = true; peeled && nt > 1;) {
    peeled = false;
    int* neighbor = work;
    int* uses = work + 3 * std::size_t(nt);
    int* vwork = uses + n;
    const std::size_t vlen = work_len - 3 * std::size_t(nt) - n;
    if (validate_triangulation(b, n, tris, nt, vwork, vlen, neighbor) != Status::ok) return nt;
    for (int i = 0; i < n; ++i) uses[i] = 0;
    for (int t = 0; t < nt; ++t)
      for (int k = 0; k < 3; ++k) ++uses[tris[t][k]];
    int kept = 0;
    for (int t = 0; t < nt; ++t) {
      bool sliver = false;
      for (int k = 0; k < 3 && !sliver; ++k) {
        if (neighbor[3 * t + k] >= 0) continue;  // edge k -> k+1 is interior
        const Vec2d& p = b[tris[t][k]];
        const Vec2d& r = b[tris[t][(k + 1) % 3]];
        const Vec2d& q = b[tris[t][(k + 2) % 3]];
        const Vec2d u = p - q, w = r - q;
        sliver = u.dot(w) < kSliverCos * u.norm() * w.norm();
      }
      for (int k = 0; k < 3 && sliver; ++k) sliver = uses[tris[t][k]] > 1;
      if (sliver && kept + (nt - t - 1) > 0) {
        for (int k = 0; k < 3; ++k) --uses[tris[t][k]];
        peeled = true;
        continue;
      }
      for (int k = 0; k < 3; ++k) tris[kept][k] = tris[t][k];
      ++kept;
    }
    nt = kept;
  }
  return nt;
}

// Layout: b, g, z of the data; the triangles; the ints; the micro-triangles.
std::size_t workspace_bytes(int n, int ntri) {
  const int tri_room = ntri > 0 ? ntri : delaunay_max_triangles(n);
  return room<Vec2d>(n) * 2 + room<double>(n) + room<int[3]>(tri_room) +
         room<int>(int_workspace(n, ntri)) + room<QuadraticGraphTriangle>(6 * std::size_t(tri_room));
}

// The orientation n . (x_1 x x_2) / (|x_1| |x_2|) of the cyclide patch over
// the micro-triangle q at the domain point p: a sine, 0 where the patch is
// singular.
double orientation_at(const QuadraticGraphTriangle& q, const Eigen::Matrix2d& H, const Vec2d& p) {
  double z;
  Vec2d g;
  if (quadratic_graph_eval(q, p, z, g) != Status::ok) return 0;
  const GraphPointJet J = graph_point_jet(p, z, g, H);
  const double len = J.x_1.norm() * J.x_2.norm();
  if (!(len > 0) || !std::isfinite(len)) return 0;
  return J.n.dot(J.x_1.cross(J.x_2)) / len;
}

// The Hessian of the quadratic of q (constant): differences of its exact
// gradients at vertex 0 and at vertex 0 + h e_j (exact up to rounding).
Eigen::Matrix2d hessian_of(const QuadraticGraphTriangle& q) {
  const Vec2d p = q.vertex[0];
  const double h =
      std::max((q.vertex[1] - p).cwiseAbs().maxCoeff(), (q.vertex[2] - p).cwiseAbs().maxCoeff());
  Eigen::Matrix2d H = Eigen::Matrix2d::Zero();
  double z;
  Vec2d g0, g;
  if (!(h > 0) || quadratic_graph_eval(q, p, z, g0) != Status::ok) return H;
  for (int j = 0; j < 2; ++j) {
    Vec2d e = Vec2d::Zero();
    e[j] = h;
    if (quadratic_graph_eval(q, p + e, z, g) != Status::ok) return Eigen::Matrix2d::Zero();
    H.col(j) = (g - g0) / h;
  }
  return 0.5 * (H + H.transpose());
}

// Below this |sine| a sample counts as singular (a cusp of the patch).
constexpr double kSingularSine = 1e-9;

// Signs of the 7 samples of a micro-triangle: +1 / -1 if all agree, 0 if
// they differ or one is singular.
int patch_orientation(const QuadraticGraphTriangle& q) {
  const Eigen::Matrix2d H = hessian_of(q);
  const Vec2d* v = q.vertex;
  const Vec2d samples[7] = {v[0], v[1], v[2], (v[0] + v[1]) / 2, (v[1] + v[2]) / 2,
                            (v[0] + v[2]) / 2, (v[0] + v[1] + v[2]) / 3};
  int sign = 0;
  for (const Vec2d& p : samples) {
    const double o = orientation_at(q, H, p);
    if (!(std::abs(o) > kSingularSine)) return 0;
    const int sg = o > 0 ? 1 : -1;
    if (sign != 0 && sg != sign) return 0;
    sign = sg;
  }
  return sign;
}

// The supported arguments: every size derived from them fits (6 kMaxTriangles
// micro-triangles in an int, their bytes in a 64-bit size_t), so the queries
// below compute nothing outside them.
bool supported(int n, int ntri) {
  return n >= 3 && n <= kMaxDelaunayPoints && ntri >= 0 && ntri <= kMaxTriangles;
}

}  // namespace

std::size_t cyclide_design_workspace_size(int n, int ntri) noexcept {
  return supported(n, ntri) ? workspace_bytes(n, ntri) : 0;
}

int cyclide_design_max_patches(int n, int ntri) noexcept {
  if (!supported(n, ntri)) return 0;
  return 6 * (ntri > 0 ? ntri : delaunay_max_triangles(n));
}

Status design_cyclide_surface(const OrientedPoint* data, int n, const int (*tri)[3], int ntri,
                              const CyclideDesignOptions& options, void* work,
                              std::size_t work_bytes, QuadraticGraphTriangle* isotropic,
                              RationalCubicTriangle* patches, int patch_cap, int& npatches,
                              CyclideDesignReport* report) noexcept {
  CyclideDesignReport rep;
  auto fail = [&](Status st) {
    if (report) *report = rep;
    return st;
  };
  if (!data || !work || !isotropic || !patches) return fail(Status::null_argument);
  if (!supported(n, ntri) || (ntri > 0 && !tri)) return fail(Status::invalid_argument);
  const bool given = tri && ntri > 0;
  const std::size_t need = workspace_bytes(n, given ? ntri : 0);
  if (work_bytes < need) {
    rep.work_needed = need;
    return fail(Status::buffer_too_small);
  }
  unsigned char* at = static_cast<unsigned char*>(work);
  Vec2d* b = carve<Vec2d>(at, n);
  Vec2d* g = carve<Vec2d>(at, n);
  double* z = carve<double>(at, n);
  const int tri_room = given ? ntri : delaunay_max_triangles(n);
  int(*tris)[3] = carve<int[3]>(at, tri_room);
  const std::size_t ints = int_workspace(n, given ? ntri : 0);
  const std::size_t ps_ints = powell_sabin_workspace_size(tri_room);
  int* iwork = carve<int>(at, ints);

  // (A_i, alpha_i) -> (B_i, beta_i), §4.2.
  for (int i = 0; i < n; ++i) {
    IsotropicDatum d;
    if (Status st = isotropic_datum(data[i], d); st != Status::ok) {
      rep.first_bad_datum = i;
      return fail(st);
    }
    b[i] = d.b;
    z[i] = d.z;
    g[i] = d.g;
  }
  if (gauss_image_contains_pole(data, n)) return fail(Status::pole_in_gauss_image);

  // Triangulate the projections b_i (or take the caller's triangles).
  int nt = ntri;
  if (given) {
    for (int t = 0; t < ntri; ++t)
      for (int k = 0; k < 3; ++k) tris[t][k] = tri[t][k];
  } else {
    DelaunayReport drep;
    const Status st = delaunay_triangulate(b, n, iwork, ints, tris, tri_room, nt, &drep);
    if (st == Status::numerical_overflow) rep.first_bad_datum = drep.first;  // b_i too small
    if (st != Status::ok)
      return fail(st == Status::buffer_too_small ? Status::internal_error : st);
    nt = peel_boundary_slivers(b, n, tris, nt, iwork, ints);
  }
  rep.triangles = nt;
  rep.patches = 6 * nt;
  if (patch_cap < 6 * nt) {
    rep.patches_needed = 6 * nt;
    return fail(Status::buffer_too_small);
  }

  // The Powell-Sabin interpolant of (B_i, beta_i), in the workspace first:
  // outputs stay untouched until every patch is known to be good.
  QuadraticGraphTriangle* micro = carve<QuadraticGraphTriangle>(at, std::size_t(6) * nt);
  int nout = 0;
  if (Status st = powell_sabin_interpolate(b, z, g, n, tris, nt, iwork, ps_ints, micro, 6 * nt,
                                           nout);
      st != Status::ok)
    return fail(st == Status::buffer_too_small ? Status::internal_error : st);

  // Lambda^{-1} patch by patch (§4.1), and the Fig. 3 check: every patch
  // keeps the orientation of the majority.
  int plus = 0, minus = 0;
  for (int k = 0; k < nout; ++k) {
    RationalCubicTriangle T;
    if (Status st = cyclide_cubic_triangle(micro[k], T); st != Status::ok) return fail(st);
    const int o = patch_orientation(micro[k]);
    plus += o > 0;
    minus += o < 0;
  }
  rep.orientation = plus >= minus ? 1 : -1;
  for (int k = 0; k < nout; ++k)
    if (patch_orientation(micro[k]) != rep.orientation) {
      if (rep.ridge_patches++ == 0) rep.first_ridge_patch = k;
    }
  if (rep.ridge_patches > 0 && !options.allow_ridges) return fail(Status::ridge);

  for (int k = 0; k < nout; ++k) {
    isotropic[k] = micro[k];
    cyclide_cubic_triangle(micro[k], patches[k]);  // succeeded above
  }
  npatches = nout;
  if (report) *report = rep;
  return Status::ok;
}

}  // namespace v0
}  // namespace cyclide
