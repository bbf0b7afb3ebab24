// The public header compiles as C++ and its types are usable there.
#include "cyclide/cyclide.h"

#include <cstdio>
#include <type_traits>

static_assert(std::is_standard_layout<cyc_mobius>::value, "frozen POD");
static_assert(std::is_standard_layout<cyc_buffer3>::value, "frozen POD");
static_assert(sizeof(cyc_sphere) == 4 * sizeof(double), "frozen layout");
static_assert(sizeof(cyc_circle) == 7 * sizeof(double), "frozen layout");

int main() {
  const bool ok = cyc_version_number() == CYC_VERSION_NUMBER &&
                  cyc_abi_version() == CYC_ABI_VERSION;
  std::printf("%d passed, %d failed\n", ok ? 1 : 0, ok ? 0 : 1);
  return ok ? 0 : 1;
}
