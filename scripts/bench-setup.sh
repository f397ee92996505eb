# scripts/bench-setup.sh -- sourced (not run) by the benchmark and instruction-count scripts
# (bench-batch.sh, bench-pore-pressure.sh, bench-rate-count.sh, count-instructions.sh): checks
# that cargo and the tools the caller names are installed, builds the library (release) and
# enters the build directory. The caller has `set -euo pipefail` and `root` (the checkout) set;
# arguments: the script's name (for messages), its default build directory, which
# $BENCH_BUILD_DIR overrides (never inside the repository), then the tools it needs (`cc` stands
# for $CC). A missing tool or library ends the caller with exit 2 (nothing measured), which the
# callers keep apart from exit 1 (a measurement failed its bound). Progress goes to stderr, so a
# caller's stdout holds only its table. Sets build, cc (from $CC, default cc), cflags,
# native_libs and lib (the static library).
# shellcheck shell=bash
bench_script="$1"
build="${BENCH_BUILD_DIR:-$2}"
shift 2
cc="${CC:-cc}"
cflags=(-O2 -std=c11 -Wall -Wextra -Wpedantic -Werror)
native_libs=(-lgcc_s -lutil -lrt -lpthread -lm -ldl -lc)

for tool in cargo "$@"; do
  [ "$tool" = cc ] && tool="$cc"
  command -v "$tool" >/dev/null 2>&1 || {
    echo "$bench_script: $tool is not installed; nothing measured" >&2
    exit 2
  }
done

echo "== cargo build --release --locked --lib" >&2
(cd "$root" && cargo build --release --locked --lib) >&2
lib="${CARGO_TARGET_DIR:-$root/target}/release/libinterfacial.a"
[ -f "$lib" ] || {
  echo "$bench_script: $lib was not built" >&2
  exit 2
}

mkdir -p "$build"
cd "$build"
echo "== building in $build" >&2
