#!/usr/bin/env bash
# fric_'s per-call cost in instructions (callgrind: the same count on a loaded machine, Intel or
# AMD), the figure the instruction budget of issue 19 is kept in (docs/performance.md).
#
# Rows: bench/bench_fric.f90 cases 1..4 (NFDIR 1 stick, NFDIR 1 slip, NFDIR 2 stick, NFDIR 2
# slip: fric_ inclusive, the difference of an NREP = 3 and an NREP = 1 run over 8192 points,
# so start-up is not counted) and bench/bench_adhesive.f90 laws 2..5 (whole program per call,
# same difference). Usage: scripts/bench-fric-count.sh   (builds the library, release, and the
# two benchmarks in $BENCH_BUILD_DIR, default /tmp/build-bench-fric). Needs gfortran, valgrind.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BENCH_BUILD_DIR:-/tmp/build-bench-fric}"
native_libs=(-lgcc_s -lutil -lrt -lpthread -lm -ldl -lc)
for tool in gfortran valgrind callgrind_annotate cargo; do
  command -v "$tool" >/dev/null 2>&1 || { echo "bench-fric-count.sh: $tool is not installed" >&2; exit 2; }
done
(cd "$root" && cargo build --release --locked --lib) >&2
lib="${CARGO_TARGET_DIR:-$root/target}/release/libinterfacial.a"
mkdir -p "$build"
cd "$build"
gfortran -O2 -I"$root/bench" -c "$root/bench/fric_ref.f" -o fric_ref.o
gfortran -O2 -I"$root/bench" -c "$root/bench/fric_nop.f" -o fric_nop.o
gfortran -O2 -o bench_fric "$root/bench/bench_fric.f90" fric_ref.o fric_nop.o "$lib" "${native_libs[@]}"
gfortran -O2 -o bench_adhesive "$root/bench/bench_adhesive.f90" fric_nop.o "$lib" "${native_libs[@]}"
names=("" "NFDIR 1 stick" "NFDIR 1 slip" "NFDIR 2 stick" "NFDIR 2 slip")
echo "| bench_fric case | fric_ instructions per call |"
echo "|---|---|"
for c in 1 2 3 4; do
  for n in 1 3; do
    valgrind --tool=callgrind --callgrind-out-file="cg.f$c.$n" ./bench_fric "$n" 1 "$c" >/dev/null 2>&1
  done
  a=$(callgrind_annotate --inclusive=yes "cg.f$c.1" | grep -E ':fric_ \[' | awk '{gsub(",","",$1); print $1}')
  b=$(callgrind_annotate --inclusive=yes "cg.f$c.3" | grep -E ':fric_ \[' | awk '{gsub(",","",$1); print $1}')
  echo "| $c ${names[$c]} | $(((b - a) / 8192)) |"
done
echo
echo "| bench_adhesive law | instructions per call (whole program) |"
echo "|---|---|"
for l in 2 3 4 5; do
  for n in 1 3; do
    valgrind --tool=callgrind --callgrind-out-file="cg.a$l.$n" ./bench_adhesive "$n" 1 "$l" >/dev/null 2>&1
  done
  a=$(grep -m1 '^summary' "cg.a$l.1" | awk '{print $2}')
  b=$(grep -m1 '^summary' "cg.a$l.3" | awk '{print $2}')
  echo "| $l | $(((b - a) / 16384)) |"
done
