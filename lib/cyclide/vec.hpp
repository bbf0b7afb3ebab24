// Vectors and quaternions over a generic scalar (double, Taylor, Jet).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "cyclide/taylor.hpp"

namespace cyclide {
inline namespace v0 {

template <class S>
using Vec3 = Eigen::Matrix<S, 3, 1>;
using Vec3d = Eigen::Vector3d;

// Truncation and derivative of vector-valued series (see taylor.hpp).
template <int M, int N, class S>
Vec3<Taylor<S, M>> truncate(const Vec3<Taylor<S, N>>& v) {
  return {truncate<M>(v[0]), truncate<M>(v[1]), truncate<M>(v[2])};
}
template <int N, class S>
Vec3<Taylor<S, N - 1>> derivative(const Vec3<Taylor<S, N>>& v) {
  return {derivative(v[0]), derivative(v[1]), derivative(v[2])};
}

// A quaternion a + a written as scalar part plus vector part, with the
// product of seed 000, eq. (12):
//   (a + a) * (b + b) = ab - a.b + a b + b a + a x b.
// Hand-written rather than Eigen::Quaternion because the constructions use
// non-unit quaternions (f +- s') over Taylor/Jet scalars, and the sandwich
// q * d * conj(q) / |q|^2 is expanded below for speed.
template <class S>
struct Quat {
  S w;
  Vec3<S> v;
  Quat conj() const { return {w, -v}; }
  S norm2() const { return w * w + v.dot(v); }
  friend Quat operator*(const Quat& a, const Quat& b) {
    return {a.w * b.w - a.v.dot(b.v), a.w * b.v + b.w * a.v + a.v.cross(b.v)};
  }
};

// The rotation q d conj(q) / |q|^2 of a vector d (scalar part 0): the
// rotation about v by the angle theta with tan(theta/2) = |v| / w, eq. (13).
// Expanded: ((w^2 - |v|^2) d + 2 (v.d) v + 2 w (v x d)) / (w^2 + |v|^2).
template <class S>
Vec3<S> rotate(const Quat<S>& q, const Vec3<S>& d) {
  const S vv = q.v.dot(q.v);
  const Vec3<S> r = (q.w * q.w - vv) * d + (S(2) * q.v.dot(d)) * q.v +
                    (S(2) * q.w) * q.v.cross(d);
  return r / (q.w * q.w + vv);
}

}  // namespace v0
}  // namespace cyclide
