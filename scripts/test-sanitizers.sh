#!/usr/bin/env bash
# Memory checks (docs/threads-and-sanitizers.md); scripts/test.sh runs this after CTest.
#
#  1. build-asan: libinterfacial built with AddressSanitizer (rustc -Zsanitizer=address on the
#     stable toolchain through RUSTC_BOOTSTRAP=1, target/asan*), every C harness compiled with
#     gcc -fsanitize=address,undefined; all C harnesses (CTest label "c") at full size, with
#     LeakSanitizer on and every report fatal.
#  2. build-valgrind: the ordinary release library, every Fortran harness (label "fortran") run
#     under valgrind memcheck (INTERFACIAL_TEST_LAUNCHER) with --leak-check=full and
#     --error-exitcode=1; the thread harnesses shrunk 16-fold (INTERFACIAL_TEST_SHRINK=16).
#     scripts/valgrind.supp names the only blocks allowed to be "possibly lost" at exit.
# Before each, a canary proves the tool reports on this machine (a deliberate heap overrun must
# be caught), and the ASan library must really be instrumented.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
jobs=${INTERFACIAL_JOBS:-2}
shrink=${INTERFACIAL_VALGRIND_SHRINK:-16}
canary_dir=$(mktemp -d)
trap 'rm -rf "$canary_dir"' EXIT

# A C program that writes one double past a malloc'ed block of n.
cat >"$canary_dir/overrun.c" <<'EOF'
#include <stdlib.h>
int main(int argc, char **argv)
{
    (void)argv;
    double *p = malloc(4 * sizeof *p);
    volatile int n = 4 + (argc > 0); /* not known to the compiler */
    if (p == NULL) {
        return 2;
    }
    p[n - 1] = 1.0;
    free(p);
    return 0;
}
EOF

# Expects `$@` to fail with `pattern` in its output.
expect_caught() {
  local pattern=$1 out
  shift
  if out=$("$@" 2>&1); then
    echo "test-sanitizers: canary NOT caught by: $*" >&2
    exit 1
  fi
  if ! grep -q "$pattern" <<<"$out"; then
    echo "test-sanitizers: canary failed without '$pattern':" >&2
    echo "$out" >&2
    exit 1
  fi
  echo "canary caught ($pattern): $*"
}

echo "== AddressSanitizer + UndefinedBehaviorSanitizer: C harnesses"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
cc=${CC:-cc}
"$cc" -fsanitize=address,undefined -g "$canary_dir/overrun.c" -o "$canary_dir/overrun_asan"
expect_caught "heap-buffer-overflow" "$canary_dir/overrun_asan"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Release -DINTERFACIAL_SANITIZE=ON >/dev/null
cmake --build build-asan -j"$jobs" --target c_harnesses
host=$(rustc -vV | sed -n 's/^host: //p')
cargo_dir=$(sed -n 's/^INTERFACIAL_CARGO_TARGET_DIR:PATH=//p' build-asan/CMakeCache.txt)
asan_lib=$cargo_dir/asan/$host/release/libinterfacial.a
# The crate's own object code must carry the instrumentation (calls into the ASan runtime).
# (readelf, not nm: binutils' nm stops at the archive's LLVM bitcode sections.)
instrumented=$(readelf -sW "$asan_lib" 2>/dev/null |
  awk '/^File: /{f=$2} /UND __asan_report_store8$/{print f}')
if ! grep -q '(interfacial\.' <<<"$instrumented"; then
  echo "test-sanitizers: $asan_lib is not instrumented by AddressSanitizer" >&2
  exit 1
fi
ctest --test-dir build-asan -L c -j"$jobs" --output-on-failure

echo "== valgrind memcheck: Fortran harnesses (INTERFACIAL_TEST_SHRINK=$shrink)"
command -v valgrind >/dev/null || { echo "test-sanitizers: valgrind missing (scripts/deps.sh)" >&2; exit 1; }
launcher="valgrind;--error-exitcode=1;--leak-check=full;--suppressions=$root/scripts/valgrind.supp"
"$cc" -g "$canary_dir/overrun.c" -o "$canary_dir/overrun"
expect_caught "Invalid write of size 8" valgrind --error-exitcode=1 "$canary_dir/overrun"
cmake -S . -B build-valgrind -DCMAKE_BUILD_TYPE=Release "-DINTERFACIAL_TEST_LAUNCHER=$launcher" \
  >/dev/null
cmake --build build-valgrind -j"$jobs" --target fortran_harnesses
INTERFACIAL_TEST_SHRINK=$shrink ctest --test-dir build-valgrind -L fortran -j"$jobs" \
  --output-on-failure
echo "test-sanitizers: no AddressSanitizer, UndefinedBehaviorSanitizer, LeakSanitizer or memcheck reports"
