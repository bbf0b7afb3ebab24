// cyclide core: named bounds and tolerances (SPEC.md §"Bounds and tolerances").
#pragma once

#include <cstddef>

namespace cyclide {
inline namespace v0 {

// Largest degree of an input rational curve (numerator and denominator).
// Two-point C^K Hermite interpolation has degree 2K+1, so K <= 7 fits.
constexpr int kMaxCurveDegree = 15;

// Largest degree of a polynomial coefficient of the circle parameter
// f(u,v) = (alpha(u) v + beta(u)) / (gamma(u) v + delta(u)).
constexpr int kMaxMobiusDegree = 15;

// Capacity of the exact (symbolic) forms: PRCS with two rational curves of
// degree d gives a spine with numerator and denominator degree <= 10d - 4
// (SPEC.md derives it); 10*15 - 4 = 146 <= 160.
constexpr int kMaxExactDegree = 160;

// Relative determinant below which three planes count as dependent
// (PRCS M, N, B; PRRS M, B1, B2): |det| / (|r1| |r2| |r3|).
constexpr double kDependentPlanesTol = 1e-10;

// A tangent (PRCS normal-plane normal) shorter than this, relative to the
// scale of the input, counts as zero.
constexpr double kZeroTangentTol = 1e-12;

// The circle parameter f(u, .) = (alpha v + beta) / (gamma v + delta) is
// degenerate (nearly constant) where |alpha delta - beta gamma| <= this
// times |alpha delta| + |beta gamma|: relative to the products it is the
// difference of, so rescaling v or f (as similarities do) changes nothing.
constexpr double kMobiusDegenerateTol = 1e-12;
// ... and, with f normalized to max |coefficient| = 1, where |alpha delta -
// beta gamma| <= this: a bound of the floating-point range, not of the
// geometry (it keeps W^2 + G^2 |a|^2 >= ~1e-260, SPEC §3).
constexpr double kMobiusDeterminantFloor = 1e-100;

// Samples of the domain scanned at creation for degenerate parameters.
constexpr int kDomainSamples = 257;

// The canal test's default tolerance (eq. (2)'s residual is scale-free) and
// the factor of its rounding floor eps max |c| / rho added to it: a canal
// surface 10^7 radii from the origin leaves residuals ~1e-9 from positions
// rounded to eps |c| (measured below 4500 eps |c| / rho), so the default
// decides the same for a model moved anywhere.
constexpr double kCanalTolerance = 1e-9;
constexpr double kCanalFloorFactor = 8192;

// Largest finite magnitude accepted for input numbers; larger values are
// rejected as non-finite input so that products of a few of them stay finite.
constexpr double kMaxInputMagnitude = 1e100;

// Largest magnitude a frame value may have; beyond it evaluation reports
// numerical_overflow instead of risking Inf in the products of up to five
// frame values that the rotation formula of evaluator.hpp forms.
constexpr double kMaxFrameMagnitude = 1e30;
constexpr double kMinAxisLength = 1e-30;

// Seed 004 §3 (pn_surface.hpp): largest bidegree of a rational Bezier
// surface Psi of the isotropic model (fixed-capacity control net).
constexpr int kMaxPnDegree = 8;

// Relative size of the exterior product X = P ^ P_u ^ P_v below which the
// plane and its partials count as dependent (Phi developable, Thm. 3.2).
constexpr double kPnDevelopableTol = 1e-10;

// Relative size of X0 below which
// Psi counts as touched by an isotropic line (point of Phi at infinity);
// X0 = 4 N det J, J the Jacobian of (u, v) -> (y1, y2).
constexpr double kPnAtInfinityTol = 1e-10;

// A control net whose extent (in y, or in (y1, y2)) is below this times
// (1 + its largest coordinate) is a point (or an isotropic line): no
// envelope (developable everywhere).
constexpr double kPnMinExtent = 1e-9;

}  // namespace v0
}  // namespace cyclide
