/* The C host of the CMake consumers (find_package, add_subdirectory): common/checks.h. */
#include "checks.h"

#ifndef EXPECTED_VERSION
#error "EXPECTED_VERSION (the package version) must be defined"
#endif

int main(void) { return run_checks(EXPECTED_VERSION) != 0; }
