// Darboux cyclides (seed 000 §5–6): the implicit surfaces
//   phi0 (X.X)^2 + phi1(X) (X.X) + phi2(X) = 0,                         (31)
// with phi0 a constant, phi1 = l . X linear homogeneous and phi2 a full
// quadratic polynomial; Mobius inversion at a sphere (exact closed forms on
// points, generalized spheres, circles and cyclide coefficients); and DCMC,
// the parabolic cyclides through three lines with a common normal.
//
// A cyclide is stored by the coefficients of its monomials, in the order of
// DarbouxCoeff (14 numbers). A constant part of phi1 would be a multiple of
// X.X, which belongs to phi2; so (31) with homogeneous phi1 is the whole
// class, closed under inversion.
#pragma once

#include "cyclide/status.hpp"
#include "cyclide/vec.hpp"

namespace cyclide {
inline namespace v0 {

// Monomial coefficients of (31): phi0, phi1 = lx x + ly y + lz z, and
// phi2 = qxx x^2 + qyy y^2 + qzz z^2 + qxy xy + qxz xz + qyz yz
//        + bx x + by y + bz z + c.
enum DarbouxCoeff : int {
  kPhi0 = 0, kLx, kLy, kLz, kQxx, kQyy, kQzz, kQxy, kQxz, kQyz, kBx, kBy, kBz, kC,
  kDarbouxCoeffs
};

enum class DarbouxType : int {
  zero = 0,       // every coefficient vanishes: not a surface
  quartic = 1,    // phi0 != 0 (a general Darboux cyclide; may be reducible)
  parabolic = 2,  // phi0 = 0, phi1 != 0: a cubic
  quadric = 3,    // phi0 = phi1 = 0, quadratic part != 0
  plane = 4,      // only the linear part (and constant)
  constant = 5,   // only a nonzero constant: no real point
  reducible = 6,  // detected factorization (sphere x plane, plane pair, ...)
};

struct Darboux {
  double k[kDarbouxCoeffs] = {};

  double phi0() const { return k[kPhi0]; }
  Vec3d l() const { return {k[kLx], k[kLy], k[kLz]}; }
  // The quadratic part of phi2 as a symmetric matrix: X.Q X.
  Eigen::Matrix3d Q() const;
  Vec3d b() const { return {k[kBx], k[kBy], k[kBz]}; }
  double c() const { return k[kC]; }
  void set(double phi0, const Vec3d& l, const Eigen::Matrix3d& Q, const Vec3d& b, double c);

  // F(X) and grad F(X).
  double value(const Vec3d& X) const;
  Vec3d gradient(const Vec3d& X) const;
  // The largest |coefficient| (for relative tolerances).
  double scale() const;
  // Divide by scale() (the equation is only defined up to a factor): false,
  // and nothing changed, unless scale() is finite and positive.
  bool normalize();
  // Divided exactly by the power of two nearest below scale(), so that
  // 1 <= scale() < 2: products of coefficients neither underflow nor
  // overflow, and no rounding changes the equation (scale() > 0 required).
  Darboux exponent_normalized() const;
};

// Relative size below which a coefficient group counts as zero for the
// type: |group| <= kDarbouxZeroTol * scale().
constexpr double kDarbouxZeroTol = 1e-12;

DarbouxType darboux_type(const Darboux& D);

// The same surface in coordinates Y = X - m: G(Y) = F(Y + m).
Darboux translate(const Darboux& D, const Vec3d& m);

// ------------------------------------------------------------ inversion

// Inversion at the sphere with center m and radius rho:
//   X' = m + rho^2 (X - m) / |X - m|^2,  an involution.
struct Inversion {
  Vec3d m = Vec3d::Zero();
  double rho = 1.0;
};

// A generalized sphere A (X.X) + B.X + C = 0: a sphere for A != 0, a plane
// for A = 0 (and B != 0). Inversion maps generalized spheres linearly.
struct GeneralSphere {
  double A = 1.0;
  Vec3d B = Vec3d::Zero();
  double C = -1.0;
};

// A circle, or (is_line) the line through `point` with direction `axis`.
struct CircleOrLine {
  bool is_line = false;
  Vec3d point = Vec3d::Zero();  // center (circle) or a point (line)
  Vec3d axis = Vec3d::UnitZ();  // unit plane normal (circle) or unit direction (line)
  double radius = 0.0;          // circle only
};

Status check_inversion(const Inversion& inv);  // finite, rho > 0
// X' (at_inversion_center if X = m: its image is the point at infinity).
Status invert_point(const Inversion& inv, const Vec3d& X, Vec3d& out);
// Sphere <-> sphere or plane (through m).
Status invert_sphere(const Inversion& inv, const GeneralSphere& S, GeneralSphere& out);
// Circle <-> circle, or line (if the circle passes through m). A line
// through m maps to itself; a line not through m to a circle through m.
Status invert_circle(const Inversion& inv, const CircleOrLine& c, CircleOrLine& out);
// The cyclide's image, in closed form: with k = rho^2 and coordinates
// centered at m, (phi0, l, Q, b, c) -> (c, k b, k^2 Q, k^3 l, k^4 phi0).
// Normalized so that the largest coefficient is 1 (the equation is only
// defined up to a factor).
Status invert_darboux(const Inversion& inv, const Darboux& D, Darboux& out);

// The image of a surface point under the inversion, with the partials
// pushed forward by the differential J = (rho^2/|Y|^2)(I - 2 Yh Yh^T),
// Y = x - m, and the normal by its reflection (I - 2 Yh Yh^T) n (J is
// conformal, so J n is normal to the image). Any of du/dv/normal may be
// null. at_inversion_center if x = m. Carries every circle-family surface
// (PRCS/PRRS outputs) to the general (quartic) case as §5 describes.
struct SurfacePoint {
  Vec3d x = Vec3d::Zero(), du = Vec3d::Zero(), dv = Vec3d::Zero(), normal = Vec3d::Zero();
};
Status invert_surface_point(const Inversion& inv, const SurfacePoint& p, bool du, bool dv,
                            bool normal, SurfacePoint& out);

// ------------------------------------------------------------ DCMC

// A line P + t d.
struct Line {
  Vec3d P = Vec3d::Zero();
  Vec3d d = Vec3d::UnitX();
};

// DCMC (seed 000 §6) on three lines: the family base + alpha * quadric of
// parabolic Darboux cyclides containing the lines (phi0 = 0, phi1 = n . X
// with the common normal n, |n| = 1). `quadric` is a quadric through the
// three lines (the null direction of the 9x10 system; ERRATA: alpha is not
// canonical, so families are compared by membership); `base` is the member
// orthogonal to it. Statuses: parallel_lines (two directions parallel),
// no_common_normal (directions not in one plane), rank_deficient (the
// family has more than one free parameter), not_finite.
struct DcmcFamily {
  Vec3d n = Vec3d::UnitZ();
  Darboux base, quadric;
  Darboux member(double alpha) const;
};
Status dcmc(const Line (&lines)[3], DcmcFamily& out);

}  // namespace v0
}  // namespace cyclide
