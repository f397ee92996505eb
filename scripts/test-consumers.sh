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
#
#   scripts/test-consumers.sh                 build and install from the source tree first
#   scripts/test-consumers.sh --prefix DIR    an existing installation (an unpacked package,
#                                             scripts/test-packages.sh): no build, no cargo, and
#                                             none of the source-tree steps
set -euo pipefail
given=
if [ "${1:-}" = --prefix ]; then
  given=$(cd "${2:?--prefix needs a directory}" && pwd)
fi
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

if [ -n "$given" ]; then
  step "the installation in $given (cargo on PATH: $(command -v cargo || echo none))"
  prefix=$given
else
  step "build and install (build-consumers/ -> $work/stage, then moved to $work/prefix)"
  cmake -S . -B build-consumers -DCMAKE_BUILD_TYPE=Release -DINTERFACIAL_BUILD_TESTS=OFF \
    -DINTERFACIAL_FORTRAN_MODULE=ON -DINTERFACIAL_INSTALL=ON >/dev/null
  cmake --build build-consumers -j"$jobs" >/dev/null
  cmake --install build-consumers --prefix "$work/stage" >/dev/null
  mv "$work/stage" "$work/prefix"
  prefix=$work/prefix
fi
pcdir=$(dirname "$(find "$prefix" -name interfacial.pc)")
libdir=$(dirname "$pcdir")
for f in include/interfacial.h include/interfacial.mod share/interfacial/fortran/interfacial.f90; do
  [ -f "$prefix/$f" ] || { echo "not installed: $f"; exit 1; }
done
# Every page the library's messages name (docs/<page>.md) is installed, under share/doc/interfacial.
pages=$(strings "$libdir/libinterfacial.so.$version" "$libdir/libinterfacial_calculix.so.$version" |
  grep -o 'docs/[a-z-]*\.md' | sort -u)
[ -n "$pages" ] || { echo "no docs/*.md named in the library's strings"; exit 1; }
for page in $pages; do
  [ -f "$prefix/share/doc/interfacial/$page" ] || { echo "messages name $page: not installed"; exit 1; }
done
echo "pages named by messages, installed under share/doc/interfacial:" $pages
# The installed archive is plain object code: binutils' nm lists its entry points (weak) with no
# LTO-plugin error, and its debug information is gone (cmake/cargo_build.cmake).
syms=$(nm "$libdir/libinterfacial.a" 2>&1)
if grep -qi plugin <<<"$syms"; then grep -i plugin <<<"$syms"; exit 1; fi
for sym in fric_ gapcon_ uinter_ fric_coef_ vfric_; do
  grep -qx "[0-9a-f]* W $sym" <<<"$syms" || { echo "nm: $sym is not a weak definition"; exit 1; }
done
grep -qx '[0-9a-f]* T ifl_fric_batch' <<<"$syms" || { echo "nm: no ifl_fric_batch"; exit 1; }
if readelf -S "$libdir/libinterfacial.a" | grep -q '\.debug_\|\.llvmbc'; then
  echo "libinterfacial.a keeps debug information or bitcode"; exit 1
fi
if readelf -S "$libdir/libinterfacial.so.$version" | grep -q '\.debug_\|\.symtab'; then
  echo "libinterfacial.so.$version is not stripped"; exit 1
fi
echo "nm libinterfacial.a: entry points listed, weak; no debug information, no bitcode"
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

step "find_package(Interfacial COMPONENTS ...): per-component _FOUND, and what is missing named"
mkdir "$work/comp"
cat >"$work/comp/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.21)
project(components LANGUAGES C)
find_package(Interfacial 0.1 REQUIRED ${HOW} ${COMPS})
foreach(c Fortran static shared calculix)
  message(STATUS "found ${c}: ${Interfacial_${c}_FOUND}")
endforeach()
CMAKE
components() { # PREFIX HOW COMPS: prints cmake's output, one line per message (wraps joined)
  cmake -S "$work/comp" -B "$work/comp/b-$RANDOM" -DCMAKE_PREFIX_PATH="$1" -DHOW="$2" \
    -DCOMPS="$3" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF 2>&1 | tr -s ' \n' ' '
}
out=$(components "$prefix" COMPONENTS "Fortran;static;shared;calculix")
for c in Fortran static shared calculix; do
  echo "$out" | grep -q "found $c: TRUE" || { echo "$out"; echo "component $c not found"; exit 1; }
done
cp -a "$prefix" "$work/prefix-nofortran"
rm "$(find "$work/prefix-nofortran" -name libinterfacial_fortran.a)" \
  "$work/prefix-nofortran/include/interfacial.mod"
out=$(components "$work/prefix-nofortran" COMPONENTS Fortran) &&
  { echo "$out"; echo "found without the Fortran module"; exit 1; }
echo "$out" | grep -q "Component Fortran is not in this installation: .*libinterfacial_fortran.a, .*interfacial.mod missing" ||
  { echo "$out"; echo "no message naming the missing module files"; exit 1; }
out=$(components "$work/prefix-nofortran" OPTIONAL_COMPONENTS Fortran) || { echo "$out"; exit 1; }
echo "$out" | grep -q "found Fortran: FALSE" || { echo "$out"; exit 1; }
out=$(components "$prefix" COMPONENTS Python) && { echo "$out"; exit 1; }
echo "$out" | grep -q "Unknown component 'Python'" || { echo "$out"; exit 1; }
rm -rf "$work/prefix-nofortran" "$work/comp"
echo "components: all found when installed; a missing Fortran module and an unknown one named"

if [ -n "$given" ]; then
  echo "consumers: all passed"
  exit 0
fi

# From here on, the source tree.
for fetch in OFF ON; do
  step "C host, the source tree as a subproject (FetchContent: $fetch; add_subdirectory otherwise)"
  cmake -S examples/consumers/c_add_subdirectory -B "$work/sub-$fetch" \
    -DINTERFACIAL_SOURCE_DIR="$root" -DEXPECTED_VERSION="$version" -DUSE_FETCHCONTENT=$fetch \
    >/dev/null
  cmake --build "$work/sub-$fetch" -j"$jobs" >/dev/null
  run "$work/sub-$fetch/host"
done
step "the staged archive's machine code is cargo's: fric_ and ifl_fric_batch disassembled alike"
cargo_dir=$(sed -n 's/^INTERFACIAL_CARGO_TARGET_DIR:PATH=//p' build-consumers/CMakeCache.txt)
for fn in fric_ ifl_fric_batch; do
  a=$(objdump -d --no-show-raw-insn --disassemble="$fn" "$cargo_dir/release/libinterfacial.a" 2>/dev/null |
    sed -n "/<$fn>:/,\$p")
  b=$(objdump -d --no-show-raw-insn --disassemble="$fn" "$libdir/libinterfacial.a" |
    sed -n "/<$fn>:/,\$p")
  [ "$(echo "$a" | wc -l)" -gt 20 ] && [ "$a" = "$b" ] ||
    { echo "$fn: staged code differs from cargo's (or was not found)"; exit 1; }
done
echo "fric_, ifl_fric_batch: same instructions as cargo's archive"

# The staged libraries must be the files cargo built in DIR: each stamp (cmake/cargo_build.cmake)
# names its source file and that file's SHA-256.
stamp_is() { [ "$(cut -d' ' -f1,2 "$1.source")" = "$(sha256sum "$2" | cut -d' ' -f1) $2" ]; }
staged_from() { # BUILD_DIR CARGO_DIR
  stamp_is "$1/lib/libinterfacial.a" "$2/release/libinterfacial.a" &&
    stamp_is "$1/lib/libinterfacial.so.$version" "$2/release/libinterfacial.so" &&
    stamp_is "$1/lib/libinterfacial_calculix.a" "$2/calculix/release/libinterfacial.a" ||
    { echo "$1/lib was not staged from $2:"; cat "$1"/lib/*.source; exit 1; }
}
step "cargo's target directory from an exported CARGO_TARGET_DIR, then from the option"
tdir=$(sed -n 's/^INTERFACIAL_CARGO_TARGET_DIR:PATH=//p' build-consumers/CMakeCache.txt)
mkdir "$work/cargo-env"
cp -a "$tdir/release" "$tdir/calculix" "$work/cargo-env/" # copies that cargo finds fresh
td_opts=(-DCMAKE_BUILD_TYPE=Release -DINTERFACIAL_BUILD_TESTS=OFF -DINTERFACIAL_FORTRAN_MODULE=OFF
  -DINTERFACIAL_INSTALL=OFF)
CARGO_TARGET_DIR=$work/cargo-env cmake -S . -B "$work/td" "${td_opts[@]}" >/dev/null
CARGO_TARGET_DIR=$work/cargo-env cmake --build "$work/td" >/dev/null
staged_from "$work/td" "$work/cargo-env"
echo "CARGO_TARGET_DIR: built and staged from $work/cargo-env"
# The option wins over a variable exported at build time, whose directory holds a newer decoy
# library where the staging used to look: cargo must not build there, nor the decoy be staged.
mv "$work/cargo-env" "$work/cargo-opt"
mkdir -p "$work/cargo-env/release"
echo decoy >"$work/cargo-env/release/libinterfacial.a"
touch -d tomorrow "$work/cargo-env/release/libinterfacial.a"
CARGO_TARGET_DIR=$work/cargo-env cmake -S . -B "$work/td" "${td_opts[@]}" \
  -DINTERFACIAL_CARGO_TARGET_DIR="$work/cargo-opt" >/dev/null
out=$(CARGO_TARGET_DIR=$work/cargo-env cmake --build "$work/td" 2>&1) || { echo "$out"; exit 1; }
staged_from "$work/td" "$work/cargo-opt"
grep -q "CARGO_TARGET_DIR=$work/cargo-env is ignored" <<<"$out" ||
  { echo "$out"; echo "no note that the exported CARGO_TARGET_DIR is ignored"; exit 1; }
[ "$(ls -A "$work/cargo-env/release")" = libinterfacial.a ] ||
  { echo "cargo wrote into the exported CARGO_TARGET_DIR:"; ls -A "$work/cargo-env/release"; exit 1; }
echo "INTERFACIAL_CARGO_TARGET_DIR: built and staged from $work/cargo-opt; decoy left alone"
rm -rf "$work/cargo-env" "$work/cargo-opt" "$work/td"

step "scripts/test-harnesses.sh on a build directory configured with the harnesses OFF"
cmake -S . -B "$work/h" -DCMAKE_BUILD_TYPE=Release -DINTERFACIAL_BUILD_TESTS=OFF >/dev/null
if ctest --test-dir "$work/h" --no-tests=error >/dev/null 2>&1; then
  echo "ctest --no-tests=error passed with no test"; exit 1
fi
out=$(scripts/test-harnesses.sh "$work/h" -R '^(c_f1|f_f1|cargo_build_stages_what_cargo_reported)$' 2>&1) ||
  { echo "$out"; exit 1; }
echo "$out" | grep -x '100% tests passed, 0 tests failed out of 3' ||
  { echo "$out"; echo "the harnesses did not run"; exit 1; }
if scripts/test-harnesses.sh "$work/h" -R '^no_such_test$' >/dev/null 2>&1; then
  echo "scripts/test-harnesses.sh passed with no test run"; exit 1
fi
echo "no test run: scripts/test-harnesses.sh fails"
rm -rf "$work/h"
echo "consumers: all passed"
