// The optimizer tier's C entry points. Built with or without Ceres; the
// symbol set is the same in every build (SPEC.md "Optimizer tier").
#include "cyclide/cyclide.h"

#ifndef CYCLIDE_HAVE_CERES
#define CYCLIDE_HAVE_CERES 0
#endif

#if CYCLIDE_HAVE_CERES
#include <ceres/version.h>
#endif

extern "C" int cyc_optimizer_available(void) { return CYCLIDE_HAVE_CERES; }
