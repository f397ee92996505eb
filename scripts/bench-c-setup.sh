# scripts/bench-c-setup.sh -- sourced (not run) by the C benchmark scripts, bench-batch.sh and
# bench-pore-pressure.sh: checks for cargo and the C compiler, builds the library (release),
# and enters the build directory. The caller has `set -euo pipefail` and `root` (the checkout)
# set; arguments: the script's name (for messages) and its default build directory, which
# $BENCH_BUILD_DIR overrides (never inside the repository). Sets build, cc (from $CC, default
# cc), cflags, native_libs and lib (the static library).
# shellcheck shell=bash
bench_script="$1"
build="${BENCH_BUILD_DIR:-$2}"
cc="${CC:-cc}"
cflags=(-O2 -std=c11 -Wall -Wextra -Wpedantic -Werror)
native_libs=(-lgcc_s -lutil -lrt -lpthread -lm -ldl -lc)

command -v cargo >/dev/null 2>&1 || { echo "$bench_script: cargo is not installed" >&2; exit 1; }
command -v "$cc" >/dev/null 2>&1 || { echo "$bench_script: no C compiler ($cc)" >&2; exit 1; }

echo "== cargo build --release --locked --lib"
(cd "$root" && cargo build --release --locked --lib)
lib="${CARGO_TARGET_DIR:-$root/target}/release/libinterfacial.a"
[ -f "$lib" ] || { echo "$bench_script: $lib was not built" >&2; exit 1; }

mkdir -p "$build"
cd "$build"
echo "== $cc ${cflags[*]} (in $build)"
