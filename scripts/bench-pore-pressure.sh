#!/usr/bin/env bash
# ns per call of ifl_pore_pressure against a hand-written C version of the closed-contact,
# small-sliding form (bench/bench_pore_pressure.c, bench/pore_pressure_ref.c). Builds the library
# (cargo, release), compiles the benchmark with the system C compiler in $BENCH_BUILD_DIR (default
# /tmp/build-bench-pore-pressure, never inside the repository) and runs it. Installs nothing. Not
# a test: timings are measurements (record them in docs/pore-pressure.md with the CPU model).
#
# Usage: scripts/bench-pore-pressure.sh [NREP [NRUN]]   (defaults 2000, 15)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
# shellcheck source=scripts/bench-setup.sh
. "$root/scripts/bench-setup.sh" bench-pore-pressure.sh /tmp/build-bench-pore-pressure cc
"$cc" "${cflags[@]}" -c "$root/bench/pore_pressure_ref.c" -o pore_pressure_ref.o
"$cc" "${cflags[@]}" -D_POSIX_C_SOURCE=199309L -I"$root/include" \
  "$root/bench/bench_pore_pressure.c" pore_pressure_ref.o -o bench_pore_pressure "$lib" \
  "${native_libs[@]}" -lm
lscpu | grep 'Model name' || true
echo "== bench_pore_pressure ${*:-}"
./bench_pore_pressure "$@"
