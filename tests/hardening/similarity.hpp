// Random similarities of R^3 for the scale / translation / rotation
// properties (SPEC §9b): g(x) = s R x + t with
//   s = 2^k, k uniform in [-30, 30]  (exact in binary),
//   R a random rotation (a unit quaternion from four uniform components),
//   t of length 0 or 10^e * s * L, e uniform in [-3, 6], random direction,
// where L is the size of the model being moved (the caller's measure, e.g.
// the largest distance of its inputs from their centroid).
//
// How each kind of quantity moves:
//   point     x -> s R x + t          (centres, points of a surface)
//   vector    v -> s R v              (tangents, derivatives, offsets)
//   direction n -> R n                (unit normals, axes)
//   length    r -> s r                (radii, distances)
// Angles, parameters (u, v, t) and dimensionless numbers do not move.
//
// A moved output is compared with the moved original to a tolerance
// relative to the moved model: |F(g x) - g F(x)| <= tol * (s L + |t|) for
// points (the translation's own rounding is eps |t|), tol * s L for vectors
// and lengths, tol for directions.
#pragma once

#include <rapidcheck.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <ostream>

namespace similarity {

struct Similarity {
  double s = 1;                                // 2^k
  int k = 0;                                   // the scale's exponent
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();

  Eigen::Vector3d point(const Eigen::Vector3d& x) const { return s * (R * x) + t; }
  Eigen::Vector3d vector(const Eigen::Vector3d& v) const { return s * (R * v); }
  Eigen::Vector3d direction(const Eigen::Vector3d& n) const { return R * n; }
  double length(double r) const { return s * r; }

  // Raw double[3] versions, for C ABI structs.
  void point(const double* x, double* out) const { put(point(get(x)), out); }
  void vector(const double* v, double* out) const { put(vector(get(v)), out); }
  void direction(const double* n, double* out) const { put(direction(get(n)), out); }

  // The scale a moved point's error is judged against: s L + |t|.
  double point_scale(double L) const { return s * L + t.norm(); }

  static Eigen::Vector3d get(const double* x) { return {x[0], x[1], x[2]}; }
  static void put(const Eigen::Vector3d& v, double* out) {
    out[0] = v[0];
    out[1] = v[1];
    out[2] = v[2];
  }
};

inline std::ostream& operator<<(std::ostream& os, const Similarity& g) {
  return os << "Similarity{s = 2^" << g.k << ", |t| = " << g.t.norm() << ", t = (" << g.t[0]
            << ", " << g.t[1] << ", " << g.t[2] << "), R row 0 = (" << g.R(0, 0) << ", "
            << g.R(0, 1) << ", " << g.R(0, 2) << ")}";
}

// A unit quaternion's rotation from four components in [-1, 1] (not all ~0).
inline Eigen::Matrix3d rotation_of(double a, double b, double c, double d) {
  Eigen::Quaterniond q(a, b, c, d);
  if (q.norm() < 1e-3) q = Eigen::Quaterniond(1, 0, 0, 0);
  return q.normalized().toRotationMatrix();
}

// A random similarity for a model of size L (L > 0). One case in eight is
// a pure scaling, one in eight a pure translation at the largest distance
// (10^6 s L), one in eight the identity rotation: the extremes are always
// exercised.
inline rc::Gen<Similarity> gen_similarity(double L) {
  return rc::gen::exec([L] {
    Similarity g;
    const int mode = *rc::gen::inRange(0, 8);
    g.k = mode == 1 ? 0 : *rc::gen::inRange(-30, 31);
    g.s = std::ldexp(1.0, g.k);
    auto unit = [] { return double(*rc::gen::inRange(-1000000, 1000001)) / 1e6; };
    if (mode != 2) {
      const double a = unit(), b = unit(), c = unit(), d = unit();
      g.R = rotation_of(a, b, c, d);
    }
    if (mode != 0) {
      Eigen::Vector3d dir(unit(), unit(), unit());
      if (dir.norm() < 1e-3) dir = Eigen::Vector3d(1, 0, 0);
      const double e = mode == 1 ? 6.0 : double(*rc::gen::inRange(-3000, 6001)) / 1000.0;
      g.t = dir.normalized() * (std::pow(10.0, e) * g.s * L);
    }
    return g;
  });
}

}  // namespace similarity
