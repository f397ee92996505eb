#!/usr/bin/env bash
# The C, Fortran and MPI harnesses (CTest), as scripts/test.sh runs them:
#   scripts/test-harnesses.sh [BUILD_DIR [CTEST_ARGS...]]     (BUILD_DIR defaults to build/)
# The harnesses are switched on whatever the build directory's cache says (a build/ first
# configured with -DINTERFACIAL_BUILD_TESTS=OFF, as docs/install.md shows, keeps OFF), and
# running no test is a failure, not "No tests were found!!!" and exit 0.
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-build}
shift || true
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DINTERFACIAL_BUILD_TESTS=ON >/dev/null
cmake --build "$dir" -j"${INTERFACIAL_JOBS:-2}"
ctest --test-dir "$dir" --output-on-failure --no-tests=error -j"${INTERFACIAL_JOBS:-2}" "$@"
