#!/usr/bin/env bash
# The consumer suite (examples/consumers/, docs/install.md): installs the library into a
# temporary prefix, moves the prefix elsewhere (the CMake package and the .pc files must be
# relocatable), and builds and runs, from that prefix only:
#   - a C host via find_package(Interfacial), static and shared, and the CalculiX-style host
#     against both variants (the Abaqus build must refuse it, naming libinterfacial_calculix);
#   - a Fortran 2008 host via `use interfacial`;
#   - a Fortran 77 host via a Makefile and pkg-config, shared and static, and the same host
#     keeping its own FRIC next to the library's GAPCON (static and shared);
#   - docs/install.md's CalculiX steps on a stand-in for a stock CalculiX build;
# and, from the source tree, a C host via add_subdirectory and via FetchContent. Each host
# asserts closed forms and error texts and prints "N passed, M failed".
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
version=$(sed -n 's/^version = "\([0-9.]*\)"$/\1/p' Cargo.toml | head -n 1)
work=$(mktemp -d "${TMPDIR:-/tmp}/interfacial-consumers.XXXXXX")
trap 'rm -rf "$work"' EXIT
jobs=${INTERFACIAL_JOBS:-2}

step() { echo "-- $*"; }
# Runs a host; its last line must be "N passed, 0 failed" with N > 0.
run() {
  local out
  out=$("$@" 2>&1) || { echo "$out"; echo "FAILED: $*"; exit 1; }
  echo "$out" | tail -n 1
  echo "$out" | tail -n 1 | grep -Eq '^[1-9][0-9]* passed, 0 failed$' ||
    { echo "$out"; echo "FAILED: $*"; exit 1; }
}
needed() { readelf -d "$1" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p'; }
expect_needed() {
  needed "$1" | grep -qx "$2" || { echo "$1 does not load $2:"; needed "$1"; exit 1; }
}
expect_not_needed() {
  if needed "$1" | grep -q "$2"; then echo "$1 loads $2 (should be static)"; exit 1; fi
}

step "build and install (build-consumers/ -> $work/stage, then moved to $work/prefix)"
cmake -S . -B build-consumers -DCMAKE_BUILD_TYPE=Release -DINTERFACIAL_BUILD_TESTS=OFF \
  -DINTERFACIAL_FORTRAN_MODULE=ON -DINTERFACIAL_INSTALL=ON >/dev/null
cmake --build build-consumers -j"$jobs" >/dev/null
cmake --install build-consumers --prefix "$work/stage" >/dev/null
mv "$work/stage" "$work/prefix"
prefix=$work/prefix
pcdir=$(dirname "$(find "$prefix" -name interfacial.pc)")
libdir=$(dirname "$pcdir")
for f in include/interfacial.h include/interfacial.mod share/interfacial/fortran/interfacial.f90; do
  [ -f "$prefix/$f" ] || { echo "not installed: $f"; exit 1; }
done
[ "$(readlink "$libdir/libinterfacial.so")" = libinterfacial.so.0 ] &&
  [ "$(readlink "$libdir/libinterfacial.so.0")" = "libinterfacial.so.$version" ] ||
  { echo "libinterfacial.so link chain:"; ls -l "$libdir"; exit 1; }
readelf -d "$libdir/libinterfacial.so.$version" | grep -q 'SONAME.*\[libinterfacial\.so\.0\]'
readelf -d "$libdir/libinterfacial_calculix.so.$version" |
  grep -q 'SONAME.*\[libinterfacial_calculix\.so\.0\]'

printf '[interactions.SI1.conductance]\nlaw = "constant"\nk = 2.0\n' >"$work/gapcon.toml"
export INTERFACIAL_CONFIG=$work/gapcon.toml INTERFACIAL_LOG=$work/messages.log

step "C host, find_package(Interfacial)"
cmake -S examples/consumers/c_find_package -B "$work/c" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF >/dev/null
cmake --build "$work/c" -j"$jobs" >/dev/null
run "$work/c/host_static"
expect_not_needed "$work/c/host_static" libinterfacial
run "$work/c/host_shared"
expect_needed "$work/c/host_shared" libinterfacial.so.0
step "wrong variant: CalculiX's gapcon argument list against the Abaqus build, then the CalculiX one"
run "$work/c/wrong_variant"
run "$work/c/right_variant"

step "Fortran 2008 host, use interfacial"
cmake -S examples/consumers/fortran2008 -B "$work/f" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF >/dev/null
cmake --build "$work/f" -j"$jobs" >/dev/null
run "$work/f/host" "$version"

step "Fortran 77 host, Makefile + pkg-config"
cp -r examples/consumers/f77_pkgconfig "$work/f77"
PKG_CONFIG_PATH=$pcdir make -s -C "$work/f77" all >/dev/null
run "$work/f77/host_shared"
expect_needed "$work/f77/host_shared" libinterfacial.so.0
run "$work/f77/host_static"
expect_not_needed "$work/f77/host_static" libinterfacial
step "keeping its own FRIC with the library's GAPCON, static and shared"
run "$work/f77/host_own_static" own-fric
run "$work/f77/host_own_shared" own-fric

step "CalculiX: docs/install.md's steps on a stand-in for a stock build (ccx_2.22.a)"
run examples/consumers/calculix_recipe/recipe.sh "$prefix" "$work/ccx"

for fetch in OFF ON; do
  step "C host, the source tree as a subproject (FetchContent: $fetch; add_subdirectory otherwise)"
  cmake -S examples/consumers/c_add_subdirectory -B "$work/sub-$fetch" \
    -DINTERFACIAL_SOURCE_DIR="$root" -DEXPECTED_VERSION="$version" -DUSE_FETCHCONTENT=$fetch \
    >/dev/null
  cmake --build "$work/sub-$fetch" -j"$jobs" >/dev/null
  run "$work/sub-$fetch/host"
done
echo "consumers: all passed"
