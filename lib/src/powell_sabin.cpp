// Powell-Sabin 6-split interpolation (see powell_sabin.hpp for the split and
// the ordinates; the C^1 argument is spelled out at each rule below).
#include "cyclide/powell_sabin.hpp"

#include <algorithm>
#include <cmath>

#include "cyclide/config.hpp"

namespace cyclide {
inline namespace v0 {
namespace {

double cross2(const Vec2d& u, const Vec2d& w) noexcept { return u.x() * w.y() - u.y() * w.x(); }

bool finite_input(double x) noexcept { return std::isfinite(x) && std::fabs(x) <= kMaxInputMagnitude; }

// The data of one vertex: its point, value and tangent plane.
struct VertexData {
  Vec2d b;
  double z;
  Vec2d g;
  // The tangent plane at p: the ordinate at the midpoint of b and w is the
  // plane's value at that midpoint (the degree-2 polar form f[b, w]).
  double plane(const Vec2d& p) const noexcept { return z + g.dot(p - b); }
  double half_way(const Vec2d& w) const noexcept { return plane(0.5 * (b + w)); }
};

// A macro edge's split point R = (1 - l) P + l Q and its ordinate, computed
// in one canonical orientation (P the vertex of smaller index) so that both
// triangles sharing the edge get identical bits.
struct EdgeSplit {
  Vec2d r;
  double lambda;  // from P towards Q
  double value;   // (1 - l) f[P, R] + l f[Q, R]
};

EdgeSplit split_edge(const VertexData& p, const VertexData& q, const Vec2d* z_left,
                     const Vec2d* z_right) noexcept {
  double lambda = 0.5;  // boundary edge: the midpoint
  if (z_left != nullptr && z_right != nullptr) {
    // Z_left + mu (Z_right - Z_left) on the line PQ: signed distances.
    const Vec2d d = q.b - p.b;
    const double sl = cross2(d, *z_left - p.b), sr = cross2(d, *z_right - p.b);
    const double mu = sl / (sl - sr);
    const Vec2d x = *z_left + mu * (*z_right - *z_left);
    lambda = d.dot(x - p.b) / d.squaredNorm();
  }
  EdgeSplit s;
  s.lambda = lambda;
  s.r = (1 - lambda) * p.b + lambda * q.b;
  // R lies between the midpoints of P R and R Q in the ratio l : 1 - l, so
  // the edge's two quadratic pieces join C^1 there (and for a quadratic f
  // this is f[R, R] = (1 - l) f[P, R] + l f[Q, R]).
  s.value = (1 - lambda) * p.half_way(s.r) + lambda * q.half_way(s.r);
  return s;
}

QuadraticGraphTriangle micro(const Vec2d& a, const Vec2d& b, const Vec2d& c, double o200,
                             double o110, double o101, double o020, double o011,
                             double o002) noexcept {
  QuadraticGraphTriangle m;
  m.vertex[0] = a;
  m.vertex[1] = b;
  m.vertex[2] = c;
  const double o[6] = {o200, o110, o101, o020, o011, o002};
  std::copy(o, o + 6, m.ordinate);
  return m;
}

bool finite_patch(const QuadraticGraphTriangle& m) noexcept {
  for (const double o : m.ordinate)
    if (!std::isfinite(o)) return false;
  for (const auto& v : m.vertex)
    if (!std::isfinite(v.x()) || !std::isfinite(v.y())) return false;
  return true;
}

}  // namespace

Vec2d triangle_incenter(const Vec2d& a, const Vec2d& b, const Vec2d& c) noexcept {
  // Weights are the lengths of the opposite sides.
  const double la = (b - c).norm(), lb = (c - a).norm(), lc = (a - b).norm();
  return (la * a + lb * b + lc * c) / (la + lb + lc);
}

std::size_t powell_sabin_workspace_size(int ntri) noexcept {
  return ntri <= 0 || ntri > kMaxTriangles ? 0 : 6 * static_cast<std::size_t>(ntri);
}

Status powell_sabin_interpolate(const Vec2d* b, const double* z, const Vec2d* g, int n,
                                const int (*tri)[3], int ntri, int* work, std::size_t work_len,
                                QuadraticGraphTriangle* out, int out_cap, int& nout) noexcept {
  if (b == nullptr || z == nullptr || g == nullptr || tri == nullptr || work == nullptr ||
      out == nullptr || n < 3 || ntri < 1 || ntri > kMaxTriangles)
    return Status::invalid_argument;
  for (int i = 0; i < n; ++i)
    if (!finite_input(b[i].x()) || !finite_input(b[i].y()) || !finite_input(z[i]) ||
        !finite_input(g[i].x()) || !finite_input(g[i].y()))
      return Status::not_finite;
  if (work_len < powell_sabin_workspace_size(ntri)) return Status::buffer_too_small;
  if (out_cap < 6 * ntri) {
    nout = 6 * ntri;
    return Status::buffer_too_small;
  }
  // The adjacency (neighbor[3t + k] across tri[t][k] -> tri[t][k+1]).
  int* neighbor = work + 3 * static_cast<std::size_t>(ntri);
  const Status valid = validate_triangulation(b, n, tri, ntri, work,
                                              3 * static_cast<std::size_t>(ntri), neighbor);
  if (valid != Status::ok) return valid;

  // Every ordinate is checked before out is written: a first pass computes
  // and checks, the second stores (the work is cheap; out stays untouched
  // on error).
  for (int pass = 0; pass < 2; ++pass) {
    for (int t = 0; t < ntri; ++t) {
      VertexData v[3];
      for (int k = 0; k < 3; ++k) v[k] = {b[tri[t][k]], z[tri[t][k]], g[tri[t][k]]};
      const Vec2d zc = triangle_incenter(v[0].b, v[1].b, v[2].b);
      // Barycentric coordinates of the incenter: side lengths over the perimeter.
      const double la = (v[1].b - v[2].b).norm(), lb = (v[2].b - v[0].b).norm(),
                   lc = (v[0].b - v[1].b).norm();
      const double alpha[3] = {la / (la + lb + lc), lb / (la + lb + lc), lc / (la + lb + lc)};
      // P(V_k, Z): tangent plane of vertex k at the midpoint of V_k and Z.
      double pz[3];
      for (int k = 0; k < 3; ++k) pz[k] = v[k].half_way(zc);
      // At Z: the plane through the three P(V_k, Z) (placed at the midpoints
      // (V_k + Z)/2, whose barycentric combination with weights alpha is Z)
      // evaluated at Z, so the three micro-edges Z V_k are crossed C^1.
      const double oz = alpha[0] * pz[0] + alpha[1] * pz[1] + alpha[2] * pz[2];
      for (int k = 0; k < 3; ++k) {
        const int k1 = (k + 1) % 3;
        const int nt = neighbor[3 * t + k];
        const bool forward = tri[t][k] < tri[t][k1];
        const VertexData& p = forward ? v[k] : v[k1];
        const VertexData& q = forward ? v[k1] : v[k];
        Vec2d zn;
        const Vec2d* z_left = nullptr;
        const Vec2d* z_right = nullptr;
        if (nt >= 0) {
          zn = triangle_incenter(b[tri[nt][0]], b[tri[nt][1]], b[tri[nt][2]]);
          // This triangle lies left of V_k -> V_{k+1}.
          z_left = forward ? &zc : &zn;
          z_right = forward ? &zn : &zc;
        }
        const EdgeSplit s = split_edge(p, q, z_left, z_right);
        // The incenters' segment crosses the edge inside (a theorem);
        // numerically it may fail only for near-degenerate triangles.
        if (!(s.lambda > 0 && s.lambda < 1)) return Status::invalid_argument;
        const double lk = forward ? s.lambda : 1 - s.lambda;
        // P(R_k, Z) lies on the segment of P(V_k, Z) and P(V_{k+1}, Z)
        // (the midpoint (R_k + Z)/2 divides theirs as R_k divides the edge):
        // the plane at Z contains it, and across Z R_k the two micro-triangles
        // meet C^1 (the three edge controls P(V_k,R), R, P(R,V_{k+1}) are collinear).
        const double prz = (1 - lk) * pz[k] + lk * pz[k1];
        const QuadraticGraphTriangle first =
            micro(v[k].b, s.r, zc, v[k].z, v[k].half_way(s.r), pz[k], s.value, prz, oz);
        const QuadraticGraphTriangle second =
            micro(s.r, v[k1].b, zc, s.value, v[k1].half_way(s.r), prz, v[k1].z, pz[k1], oz);
        if (pass == 0) {
          if (!finite_patch(first) || !finite_patch(second)) return Status::numerical_overflow;
        } else {
          out[6 * t + 2 * k] = first;
          out[6 * t + 2 * k + 1] = second;
        }
      }
    }
  }
  nout = 6 * ntri;
  return Status::ok;
}

Status quadratic_graph_barycentric(const QuadraticGraphTriangle& q, const Vec2d& p,
                                   double bary[3]) noexcept {
  const Vec2d& a = q.vertex[0];
  const double d = cross2(q.vertex[1] - a, q.vertex[2] - a);
  if (!(d != 0) || !std::isfinite(d)) return Status::invalid_argument;
  const double s = cross2(p - a, q.vertex[2] - a) / d;
  const double t = cross2(q.vertex[1] - a, p - a) / d;
  bary[0] = 1 - s - t;
  bary[1] = s;
  bary[2] = t;
  return Status::ok;
}

Status quadratic_graph_eval(const QuadraticGraphTriangle& q, const Vec2d& p, double& value,
                            Vec2d& gradient) noexcept {
  double w[3];
  const Status st = quadratic_graph_barycentric(q, p, w);
  if (st != Status::ok) return st;
  const double* o = q.ordinate;  // 200, 110, 101, 020, 011, 002
  const double r = w[0], s = w[1], t = w[2];
  const double val = o[0] * r * r + 2 * o[1] * r * s + 2 * o[2] * r * t + o[3] * s * s +
                     2 * o[4] * s * t + o[5] * t * t;
  // Partial derivatives in (r, s, t), then the chain rule with the constant
  // gradients of the barycentric coordinates.
  const double dr = 2 * (o[0] * r + o[1] * s + o[2] * t);
  const double ds = 2 * (o[1] * r + o[3] * s + o[4] * t);
  const double dt = 2 * (o[2] * r + o[4] * s + o[5] * t);
  const Vec2d& a = q.vertex[0];
  const Vec2d e1 = q.vertex[1] - a, e2 = q.vertex[2] - a;
  const double d = cross2(e1, e2);
  const Vec2d grad_s(e2.y() / d, -e2.x() / d);
  const Vec2d grad_t(-e1.y() / d, e1.x() / d);
  const Vec2d grad = (ds - dr) * grad_s + (dt - dr) * grad_t;
  if (!std::isfinite(val) || !std::isfinite(grad.x()) || !std::isfinite(grad.y()))
    return Status::numerical_overflow;
  value = val;
  gradient = grad;
  return Status::ok;
}

Status quadratic_graph_locate(const QuadraticGraphTriangle* patches, int count, const Vec2d& p,
                              double tol, int& index) noexcept {
  index = -1;
  if (patches == nullptr || count < 0) return Status::invalid_argument;
  for (int i = 0; i < count; ++i) {
    double w[3];
    if (quadratic_graph_barycentric(patches[i], p, w) != Status::ok) continue;
    if (w[0] >= -tol && w[1] >= -tol && w[2] >= -tol) {
      index = i;
      return Status::ok;
    }
  }
  return Status::bad_domain;
}

}  // namespace v0
}  // namespace cyclide
