// The seed 003 conversions shared by lie_c.cpp and the optimizer tier's
// optimizer_c.cpp (cones in, blends out, the cone statuses' messages).
#pragma once

#include "capi_internal.hpp"
#include "cyclide/cyclide_blend.hpp"

namespace cyclide {
namespace capi {

// The caller's cone as the core's, unchecked (see cone_check).
LieCone cone_in(const cyc_lie_cone* c);
// The caller's cone validated: every entry of name.r0 and name.r_plus
// through the shared input checks, then the core's cone conditions (r0 a
// sphere, r_plus positive and orthogonal to r0), each failure named.
Outcome cone_check(const char* fn, const char* name, const cyc_lie_cone* c, LieCone& out);
// The message of a cone or blend status (planar cones, invalid cones, ...).
Outcome cone_status(const char* fn, Status s);
// The caller's blend from the core's (every piece checked as a cyc_dupin).
Outcome blend_out(const char* fn, const CyclideBlend& B, cyc_cyclide_blend* out);

}  // namespace capi
}  // namespace cyclide
