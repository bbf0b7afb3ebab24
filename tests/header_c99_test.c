/* The public header compiles as strict C99 (-std=c99 -pedantic-errors), and
 * the header's version macros agree with the library linked. */
#include "cyclide/cyclide.h"

#include <stdio.h>
#include <string.h>

int main(void) {
  int failed = 0;
  if (cyc_version_number() != CYC_VERSION_NUMBER) failed++;
  if (strcmp(cyc_version_string(), CYC_VERSION_STRING) != 0) failed++;
  if (cyc_abi_version() != CYC_ABI_VERSION) failed++;
  if (CYC_VERSION_NUMBER !=
      CYC_VERSION_MAJOR * 10000 + CYC_VERSION_MINOR * 100 + CYC_VERSION_PATCH)
    failed++;
  printf("%d passed, %d failed\n", 4 - failed, failed);
  return failed != 0;
}
