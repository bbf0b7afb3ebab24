#include "cyclide/inverted_surface.hpp"

#include <algorithm>
#include <cmath>

namespace cyclide {
inline namespace v0 {

Status inverted_circle(const Surface& S, const Inversion& inv, double u, CircleOrLine& out) {
  if (Status st = check_inversion(inv); st != Status::ok) return st;
  Vec3d c, n;
  double r2;
  if (Status st = S.circle(u, c, n, r2); st != Status::ok) return st;
  CircleOrLine C;
  C.point = c;
  C.axis = n;
  C.radius = std::sqrt(r2);
  return invert_circle(inv, C, out);
}

namespace {

// One pass over the grid: evaluate each row in chunks into stack buffers,
// invert, and (if write) store. Returns the first failure.
Status grid_pass(const Surface& S, const Inversion& inv, const double* us, std::size_t nu,
                 const double* vs, std::size_t nv, const Strided3& points, const Strided3& du,
                 const Strided3& dv, const Strided3& normals, bool write, std::size_t& singular) {
  double px[3 * kChunk], pu[3 * kChunk], pv[3 * kChunk], pn[3 * kChunk];
  const Strided3 P{px, 3}, U{du.data ? pu : nullptr, 3}, V{dv.data ? pv : nullptr, 3},
      N{normals.data ? pn : nullptr, 3};
  singular = 0;
  for (std::size_t i = 0; i < nu; ++i)
    for (std::size_t j0 = 0; j0 < nv; j0 += kChunk) {
      const std::size_t n = std::min<std::size_t>(kChunk, nv - j0);
      std::size_t sing = 0;
      if (Status st = S.eval_grid(us + i, 1, vs + j0, n, P, U, V, N, &sing); st != Status::ok)
        return st;
      singular += sing;
      for (std::size_t j = 0; j < n; ++j) {
        SurfacePoint p, r;
        p.x = Vec3d(px + 3 * j);
        if (U.data) p.du = Vec3d(pu + 3 * j);
        if (V.data) p.dv = Vec3d(pv + 3 * j);
        if (N.data) p.normal = Vec3d(pn + 3 * j);
        if (Status st = invert_surface_point(inv, p, U.data, V.data, N.data, r); st != Status::ok)
          return st;
        if (!write) continue;
        const std::size_t k = i * nv + j0 + j;
        auto put = [k](const Strided3& b, const Vec3d& x) {
          if (b.data) std::copy(x.data(), x.data() + 3, b.at(k));
        };
        put(points, r.x);
        put(du, r.du);
        put(dv, r.dv);
        put(normals, r.normal);
      }
    }
  return Status::ok;
}

}  // namespace

Status eval_grid_inverted(const Surface& S, const Inversion& inv, const double* us,
                          std::size_t nu, const double* vs, std::size_t nv,
                          const Strided3& points, const Strided3& du, const Strided3& dv,
                          const Strided3& normals, std::size_t* singular) {
  if ((nu && !us) || (nv && !vs)) return Status::null_argument;
  if (Status st = check_inversion(inv); st != Status::ok) return st;
  for (const Strided3* b : {&points, &du, &dv, &normals})
    if (b->data && b->stride < 3) return Status::invalid_argument;
  std::size_t count = 0;
  if (Status st = grid_pass(S, inv, us, nu, vs, nv, points, du, dv, normals, false, count);
      st != Status::ok)
    return st;
  grid_pass(S, inv, us, nu, vs, nv, points, du, dv, normals, true, count);
  if (singular) *singular = count;
  return Status::ok;
}

}  // namespace v0
}  // namespace cyclide
