#!/usr/bin/env bash
# The binary packages (cmake/package.cmake; docs/install.md, "Packages without Rust"):
#   - builds them with cpack in build-packages/: the Debian runtime, development and debug
#     packages and the relocatable tarballs;
#   - checks the Debian packages with lintian (no error) and what each holds;
#   - unpacks the Debian runtime + development packages into one fresh prefix, and the tarball
#     into another, and runs the consumer suite (scripts/test-consumers.sh --prefix) on each with
#     cargo and rustc off PATH (stand-ins that record a call and fail);
#   - checks that the debug package's files belong to the runtime libraries (build IDs) and the
#     sizes against the bounds docs/install.md quotes.
set -euo pipefail
cd "$(dirname "$0")/.."
version=$(sed -n 's/^version = "\([0-9.]*\)"$/\1/p' Cargo.toml | head -n 1)
work=$(mktemp -d "${TMPDIR:-/tmp}/interfacial-packages.XXXXXX")
trap 'rm -rf "$work"' EXIT
step() { echo "-- $*"; }

step "build the packages (build-packages/, cpack)"
cmake -S . -B build-packages -DCMAKE_BUILD_TYPE=Release -DINTERFACIAL_BUILD_TESTS=OFF \
  -DINTERFACIAL_FORTRAN_MODULE=ON -DINTERFACIAL_INSTALL=ON >/dev/null
cmake --build build-packages -j"${INTERFACIAL_JOBS:-2}" >/dev/null
rm -rf build-packages/packages
(cd build-packages && cpack --config CPackConfig.cmake >"$work/cpack.log" 2>&1) ||
  { cat "$work/cpack.log"; exit 1; }
pk=build-packages/packages
arch=$(dpkg --print-architecture)
runtime=$pk/libinterfacial0_${version}_$arch.deb
dev=$pk/libinterfacial-dev_${version}_$arch.deb
dbg=$pk/libinterfacial0-dbg_${version}_$arch.deb
top=interfacial-$version-linux-$(uname -m)
tgz=$pk/$top.tar.gz
tgz_debug=$pk/$top-debug.tar.gz
for f in "$runtime" "$dev" "$dbg" "$tgz" "$tgz_debug"; do
  [ -f "$f" ] || { echo "cpack made no $f:"; ls "$pk"; exit 1; }
done
ls -l "$pk"/*.deb "$pk"/*.tar.gz

step "lintian (no error)"
lintian --fail-on error "$runtime" "$dev" "$dbg" 2>&1 | grep -v 'running with root privileges' || true
lintian --fail-on error "$runtime" "$dev" "$dbg" >/dev/null 2>&1 ||
  { echo "lintian reports errors"; exit 1; }
echo "lintian: no errors"

step "what each package holds"
files() { dpkg-deb -c "$1" | awk '{print $6}' | sed 's|^\./|/|' | grep -v '/$'; }
expect_files() { # PACKAGE PATTERN...: every pattern matches a file of the package
  local list pkg=$1
  list=$(files "$pkg")
  shift
  for p in "$@"; do
    grep -qx "$p" <<<"$list" || { echo "$pkg has no $p:"; echo "$list"; exit 1; }
  done
}
expect_files "$runtime" "/usr/lib/libinterfacial.so.$version" /usr/lib/libinterfacial.so.0 \
  "/usr/lib/libinterfacial_calculix.so.$version" /usr/lib/libinterfacial_calculix.so.0 \
  /usr/share/doc/libinterfacial0/copyright
if files "$runtime" | grep -q '\.a$\|\.h$\|/libinterfacial\.so$\|\.debug$'; then
  echo "the runtime package holds development or debug files:"; files "$runtime"; exit 1
fi
expect_files "$dev" /usr/include/interfacial.h /usr/include/interfacial.mod \
  /usr/lib/libinterfacial.a /usr/lib/libinterfacial_calculix.a /usr/lib/libinterfacial_fortran.a \
  /usr/lib/libinterfacial.so /usr/lib/cmake/Interfacial/InterfacialConfig.cmake \
  /usr/lib/pkgconfig/interfacial.pc /usr/lib/pkgconfig/interfacial-fortran.pc \
  /usr/share/doc/interfacial/docs/config.md /usr/share/doc/libinterfacial-dev/copyright
dpkg-deb -f "$dev" Depends | grep -qx "libinterfacial0 (= $version)" ||
  { echo "libinterfacial-dev does not depend on libinterfacial0 (= $version)"; exit 1; }
dpkg-deb -f "$runtime" Depends | grep -q 'libc6' ||
  { echo "libinterfacial0 has no Depends on libc6"; exit 1; }
echo "runtime: the SONAME'd libraries; dev: header, module, archives, CMake and pkg-config files"

step "the debug package: one .debug file per runtime library, by its build ID"
mkdir "$work/dbg" "$work/rt"
dpkg-deb -x "$dbg" "$work/dbg"
dpkg-deb -x "$runtime" "$work/rt"
for so in "$work/rt/usr/lib/libinterfacial.so.$version" \
  "$work/rt/usr/lib/libinterfacial_calculix.so.$version"; do
  id=$(readelf -n "$so" | sed -n 's/.*Build ID: \([0-9a-f]*\)/\1/p')
  d=$work/dbg/usr/lib/debug/.build-id/${id:0:2}/${id:2}.debug
  [ -f "$d" ] || { echo "no debug file for $so (build ID $id)"; exit 1; }
  readelf -S "$d" | grep -q '\.debug_info' || { echo "$d has no .debug_info"; exit 1; }
  readelf -S "$so" | grep -q '\.gnu_debuglink' || { echo "$so has no .gnu_debuglink"; exit 1; }
  if readelf -S "$so" | grep -q '\.debug_'; then echo "$so is not stripped"; exit 1; fi
done
echo "each runtime library is stripped and its debug file is in the debug package"

step "sizes, against the bounds docs/install.md quotes"
# A row of docs/install.md's size table: | `NAME` | size | < BOUND MB |
check_size() { # NAME FILE
  local row bound size
  row=$(grep -F "| \`$1\` |" docs/install.md) || { echo "docs/install.md has no size row for $1"; exit 1; }
  bound=$(grep -o '< [0-9.]* MB' <<<"$row" | tr -dc '0-9.')
  size=$(stat -c %s "$2")
  awk -v s="$size" -v b="$bound" 'BEGIN { exit !(b > 0 && s < b * 1000000) }' ||
    { echo "$1: $size bytes, docs/install.md says < $bound MB"; exit 1; }
  printf '%-44s %9d bytes  (< %s MB)\n' "$1" "$size" "$bound"
}
mkdir "$work/dev"
dpkg-deb -x "$dev" "$work/dev"
check_size "libinterfacial.so.<version>" "$work/rt/usr/lib/libinterfacial.so.$version"
check_size "libinterfacial.a" "$work/dev/usr/lib/libinterfacial.a"
check_size "<build-id>.debug" "$(find "$work/dbg" -name '*.debug' | head -n 1)"
check_size "libinterfacial0_<version>_<arch>.deb" "$runtime"
check_size "libinterfacial-dev_<version>_<arch>.deb" "$dev"
check_size "libinterfacial0-dbg_<version>_<arch>.deb" "$dbg"
check_size "interfacial-<version>-linux-<machine>.tar.gz" "$tgz"

# cargo and rustc replaced by stand-ins that record the call and fail; the directories holding
# the real ones left out of PATH.
mkdir "$work/nocargo"
for tool in cargo rustc; do
  printf '#!/bin/sh\necho "%s called: $*" >>"%s"\nexit 127\n' "$tool" "$work/nocargo/calls" \
    >"$work/nocargo/$tool"
  chmod +x "$work/nocargo/$tool"
done
nocargo_path=$work/nocargo
IFS=: read -ra dirs <<<"$PATH"
for d in "${dirs[@]}"; do
  if [ ! -x "$d/cargo" ] && [ ! -x "$d/rustc" ]; then nocargo_path=$nocargo_path:$d; fi
done
consume() { # PREFIX
  PATH=$nocargo_path scripts/test-consumers.sh --prefix "$1"
  [ ! -e "$work/nocargo/calls" ] || { echo "the consumers called:"; cat "$work/nocargo/calls"; exit 1; }
}

step "the Debian runtime + development packages unpacked into a fresh prefix, without cargo"
mkdir "$work/deb"
dpkg-deb -x "$runtime" "$work/deb"
dpkg-deb -x "$dev" "$work/deb"
consume "$work/deb/usr"

step "the tarball unpacked into a fresh prefix, without cargo"
mkdir "$work/tgz"
tar -xzf "$tgz" -C "$work/tgz"
consume "$work/tgz/$top"
tar -tzf "$tgz_debug" | grep "^$top/lib/debug/\.build-id/.*\.debug$" >/dev/null ||
  { echo "$tgz_debug holds no .debug file"; exit 1; }
echo "packages: all passed"
