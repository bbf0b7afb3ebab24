// The image of a circle-family surface under a Mobius inversion (seed 000
// §5): again a rational family of circles, x'(u, v) = inv(x(u, v)), whose
// circle at u is the image of the circle at u (a line where that circle
// passes through the center). This is how every PRCS/PRRS construction is
// carried to the general (quartic) Darboux case; single points are
// `invert_surface_point` (darboux.hpp), this adds the circles and grids.
#pragma once

#include <cstddef>

#include "cyclide/darboux.hpp"
#include "cyclide/surface.hpp"

namespace cyclide {
inline namespace v0 {

// The image of the circle v -> x(u, v).
Status inverted_circle(const Surface& S, const Inversion& inv, double u, CircleOrLine& out);

// eval_grid of the inverted surface: points, partials pushed forward by the
// inversion's differential, reflected unit normals (singular normals stay
// (0,0,0) and are counted). All or nothing: a grid point at the inversion
// center (at_inversion_center) or whose image overflows leaves every
// buffer untouched. Rows are evaluated by the grid kernels in chunks of
// kChunk values of v on the stack (no allocation), twice: once to validate
// and once to write (the kernels are deterministic).
Status eval_grid_inverted(const Surface& S, const Inversion& inv, const double* us,
                          std::size_t nu, const double* vs, std::size_t nv,
                          const Strided3& points, const Strided3& du, const Strided3& dv,
                          const Strided3& normals, std::size_t* singular);

}  // namespace v0
}  // namespace cyclide
