// Independent checks shared by the Delaunay / Powell-Sabin tests: a
// triangulation's validity (own convex hull, long double areas), the empty
// circumcircle property (circumcircles in long double), and C^1 continuity
// across shared edges of quadratic pieces. None calls the code under test
// except quadratic_graph_eval (checked itself against finite differences
// and the Bernstein form in powell_sabin_test.cpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cyclide/delaunay.hpp"
#include "cyclide/powell_sabin.hpp"

namespace ps_checks {

using cyclide::Vec2d;
using Tri = std::array<int, 3>;
using ld = long double;

inline ld cross_ld(const Vec2d& o, const Vec2d& a, const Vec2d& b) {
  return (ld(a.x()) - o.x()) * (ld(b.y()) - o.y()) - (ld(a.y()) - o.y()) * (ld(b.x()) - o.x());
}

// Area of the convex hull (Andrew's monotone chain).
inline ld hull_area(std::vector<Vec2d> p) {
  std::sort(p.begin(), p.end(), [](const Vec2d& a, const Vec2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  std::vector<Vec2d> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross_ld(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross_ld(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  ld area = 0;  // a fan from h[0]: differences, not absolute coordinates
  for (std::size_t i = 1; i + 1 < h.size(); ++i) area += cross_ld(h[0], h[i], h[i + 1]) / 2;
  return area;
}

// "" if tri is a valid triangulation of the convex hull of pts using every
// point: CCW, each undirected edge in at most two triangles with opposite
// orientations, areas summing to the hull's (relative area_tol).
inline std::string check_triangulation(const std::vector<Vec2d>& pts, const std::vector<Tri>& tri,
                                       double area_tol = 1e-12) {
  std::ostringstream why;
  std::map<std::pair<int, int>, int> directed;
  std::vector<int> used(pts.size(), 0);
  ld area = 0;
  for (std::size_t t = 0; t < tri.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int v = tri[t][k];
      if (v < 0 || v >= static_cast<int>(pts.size())) return "index out of range";
      used[v] = 1;
      if (++directed[{v, tri[t][(k + 1) % 3]}] > 1) {
        why << "directed edge twice in triangle " << t;
        return why.str();
      }
    }
    const ld a2 = cross_ld(pts[tri[t][0]], pts[tri[t][1]], pts[tri[t][2]]);
    if (!(a2 > 0)) {
      why << "triangle " << t << " not counter-clockwise";
      return why.str();
    }
    area += a2 / 2;
  }
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (!used[i]) {
      why << "point " << i << " unused";
      return why.str();
    }
  const ld hull = hull_area(pts);
  if (std::fabs(static_cast<double>((area - hull) / hull)) > area_tol) {
    why << "area " << static_cast<double>(area) << " vs hull " << static_cast<double>(hull);
    return why.str();
  }
  // Euler: a triangulation of the hull with h boundary edges has
  // 2n - 2 - h triangles; the boundary edges are the unmatched ones.
  int boundary = 0;
  for (const auto& e : directed)
    if (directed.find({e.first.second, e.first.first}) == directed.end()) ++boundary;
  if (static_cast<int>(tri.size()) != 2 * static_cast<int>(pts.size()) - 2 - boundary)
    return "Euler count violated";
  return "";
}

// "" if no point lies inside a circumcircle by more than tol (relative to
// the squared radius).
inline std::string check_empty_circles(const std::vector<Vec2d>& pts, const std::vector<Tri>& tri,
                                       double tol) {
  for (std::size_t t = 0; t < tri.size(); ++t) {
    const Vec2d& a = pts[tri[t][0]];
    const Vec2d& b = pts[tri[t][1]];
    const Vec2d& c = pts[tri[t][2]];
    const ld bx = ld(b.x()) - a.x(), by = ld(b.y()) - a.y();
    const ld cx = ld(c.x()) - a.x(), cy = ld(c.y()) - a.y();
    const ld d = 2 * (bx * cy - by * cx);
    const ld ux = (cy * (bx * bx + by * by) - by * (cx * cx + cy * cy)) / d;
    const ld uy = (bx * (cx * cx + cy * cy) - cx * (bx * bx + by * by)) / d;
    const ld r2 = ux * ux + uy * uy;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const ld px = ld(pts[i].x()) - a.x() - ux, py = ld(pts[i].y()) - a.y() - uy;
      if (px * px + py * py < r2 * (1 - tol)) {
        std::ostringstream why;
        why << "point " << i << " inside the circumcircle of triangle " << t;
        return why.str();
      }
    }
  }
  return "";
}

struct Continuity {
  int shared_edges = 0;
  double max_value_gap = 0;     // relative to 1 + |value|
  double max_gradient_gap = 0;  // relative to 1 + |gradient|
};

// Value and gradient gaps at 7 points of every edge shared by two pieces
// (edges matched by their exact vertex coordinates).
inline Continuity continuity(const std::vector<cyclide::QuadraticGraphTriangle>& patches) {
  using Key = std::pair<std::pair<double, double>, std::pair<double, double>>;
  std::map<Key, std::vector<int>> edges;
  for (std::size_t i = 0; i < patches.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      Vec2d u = patches[i].vertex[k], w = patches[i].vertex[(k + 1) % 3];
      std::pair<double, double> pu{u.x(), u.y()}, pw{w.x(), w.y()};
      if (pw < pu) std::swap(pu, pw);
      edges[{pu, pw}].push_back(static_cast<int>(i));
    }
  Continuity c;
  for (const auto& e : edges) {
    if (e.second.size() != 2) continue;
    ++c.shared_edges;
    const Vec2d u(e.first.first.first, e.first.first.second);
    const Vec2d w(e.first.second.first, e.first.second.second);
    for (int s = 0; s <= 6; ++s) {
      const Vec2d p = u + (w - u) * (s / 6.0);
      double v0 = 0, v1 = 0;
      Vec2d g0, g1;
      cyclide::quadratic_graph_eval(patches[e.second[0]], p, v0, g0);
      cyclide::quadratic_graph_eval(patches[e.second[1]], p, v1, g1);
      c.max_value_gap = std::max(c.max_value_gap, std::fabs(v0 - v1) / (1 + std::fabs(v0)));
      c.max_gradient_gap = std::max(c.max_gradient_gap, (g0 - g1).norm() / (1 + g0.norm()));
    }
  }
  return c;
}

// delaunay_triangulate into vectors (status returned).
inline cyclide::Status triangulate(const std::vector<Vec2d>& pts, std::vector<Tri>& tri,
                                   cyclide::DelaunayReport* report = nullptr) {
  const int n = static_cast<int>(pts.size());
  std::vector<int> work(cyclide::delaunay_workspace_size(n));
  std::vector<Tri> out(std::max(1, cyclide::delaunay_max_triangles(n)));
  int ntri = -1;
  const cyclide::Status s =
      cyclide::delaunay_triangulate(pts.data(), n, work.data(), work.size(),
                                    reinterpret_cast<int(*)[3]>(out.data()),
                                    static_cast<int>(out.size()), ntri, report);
  if (s == cyclide::Status::ok) {
    out.resize(ntri);
    tri = out;
  }
  return s;
}

// powell_sabin_interpolate into a vector.
inline cyclide::Status interpolate(const std::vector<Vec2d>& b, const std::vector<double>& z,
                                   const std::vector<Vec2d>& g, const std::vector<Tri>& tri,
                                   std::vector<cyclide::QuadraticGraphTriangle>& out) {
  const int ntri = static_cast<int>(tri.size());
  std::vector<int> work(cyclide::powell_sabin_workspace_size(ntri));
  std::vector<cyclide::QuadraticGraphTriangle> patches(6 * tri.size());
  int nout = 0;
  const cyclide::Status s = cyclide::powell_sabin_interpolate(
      b.data(), z.data(), g.data(), static_cast<int>(b.size()),
      reinterpret_cast<const int(*)[3]>(tri.data()), ntri, work.data(), work.size(),
      patches.data(), static_cast<int>(patches.size()), nout);
  if (s == cyclide::Status::ok) {
    patches.resize(nout);
    out = patches;
  }
  return s;
}

// A quadratic f(y) = c + l . y + y^T Q y / 2 with its gradient.
struct Quadratic {
  double c = 0;
  Vec2d l = Vec2d::Zero();
  double qxx = 0, qxy = 0, qyy = 0;
  double value(const Vec2d& y) const {
    return c + l.dot(y) + 0.5 * (qxx * y.x() * y.x() + 2 * qxy * y.x() * y.y() + qyy * y.y() * y.y());
  }
  Vec2d gradient(const Vec2d& y) const {
    return l + Vec2d(qxx * y.x() + qxy * y.y(), qxy * y.x() + qyy * y.y());
  }
};

}  // namespace ps_checks
