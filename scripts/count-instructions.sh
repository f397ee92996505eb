#!/usr/bin/env bash
# Instructions per call of the hot entry points, counted with callgrind (the same count on a
# loaded machine and on any x86-64 CPU for one toolchain), and the guard of the figures the
# docs quote: the table between the `counts:begin` / `counts:end` markers of
# docs/performance.md.
#
#   scripts/count-instructions.sh           print the table
#   scripts/count-instructions.sh --check   fail (exit 1) when a row differs from the committed
#                                           table by more than 2 % (either way: a slower call, or
#                                           a figure the docs quote that the code no longer has;
#                                           10 % on another CPU vendor than the table's)
#   scripts/count-instructions.sh --write   rewrite the committed table from this count
#
# Counts depend on the compilers (rustc, gfortran, cc): the table records the rustc it was
# counted with, and --check compares only under that rustc (otherwise it says so and exits 0:
# re-count with --write after a toolchain change, and look at the diff).
#
# Rows: bench/bench_fric.f90 cases 1..4 (fric_ inclusive, and the hand-written FRICREF of the
# same runs); bench/bench_adhesive.f90 laws 2..5
# (whole program); uinter_ inclusive (bench_adhesive law 5); ifl_pore_pressure inclusive
# (bench/bench_pore_pressure.c); ifl_fric_batch per point (bench/bench_batch.c); the rate law's rows of scripts/bench-rate-count.sh. Each is the difference of a run with more repeats and one with
# fewer, divided by the extra calls, so start-up and set-up cancel. Builds the library (cargo,
# release) and the benchmarks in $BENCH_BUILD_DIR (default /tmp/build-count). Needs gfortran,
# cc, valgrind.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
mode="${1:-print}"
case "$mode" in print | --check | --write) ;; *)
  echo "usage: scripts/count-instructions.sh [--check | --write]" >&2
  exit 2
  ;;
esac
doc="$root/docs/performance.md"
tolerance_percent=2
# shellcheck source=scripts/bench-setup.sh
. "$root/scripts/bench-setup.sh" count-instructions.sh /tmp/build-count gfortran cc valgrind \
  callgrind_annotate rustc
gfortran -O2 -I"$root/bench" -c "$root/bench/fric_ref.f" -o fric_ref.o
gfortran -O2 -I"$root/bench" -c "$root/bench/fric_nop.f" -o fric_nop.o
gfortran -O2 -o bench_fric "$root/bench/bench_fric.f90" fric_ref.o fric_nop.o "$lib" "${native_libs[@]}"
gfortran -O2 -o bench_adhesive "$root/bench/bench_adhesive.f90" fric_nop.o "$lib" "${native_libs[@]}"
"$cc" "${cflags[@]}" -D_POSIX_C_SOURCE=199309L -I"$root/include" "$root/bench/bench_batch.c" \
  -o bench_batch "$lib" "${native_libs[@]}"
"$cc" -O2 -c "$root/bench/pore_pressure_ref.c" -o pore_pressure_ref.o
"$cc" -O2 -D_POSIX_C_SOURCE=199309L -I"$root/include" "$root/bench/bench_pore_pressure.c" \
  pore_pressure_ref.o -o bench_pore_pressure "$lib" "${native_libs[@]}" -lm

# cg FILE PROGRAM ARGS...: one callgrind run.
cg() {
  local out=$1
  shift
  valgrind --tool=callgrind --callgrind-out-file="$out" "$@" >/dev/null 2>&1
}
# inclusive FILE FUNCTION: the function's inclusive instruction count.
inclusive() {
  callgrind_annotate --inclusive=yes "$1" | grep -E ":$2 \[" | head -n1 | awk '{gsub(",","",$1); print $1}'
}
# whole FILE: the whole program's count.
whole() { grep -m1 '^summary' "$1" | awk '{print $2}'; }
# per_call A B CALLS: (B - A) / CALLS with one decimal.
per_call() { awk -v a="$1" -v b="$2" -v n="$3" 'BEGIN { printf "%.1f", (b - a) / n }'; }

rows=()
names=("" "fric_, NFDIR 1 stick" "fric_, NFDIR 1 slip" "fric_, NFDIR 2 stick" "fric_, NFDIR 2 slip")
for c in 1 2 3 4; do
  cg "f$c.1" ./bench_fric 1 1 "$c"
  cg "f$c.3" ./bench_fric 3 1 "$c"
  rows+=("| ${names[$c]} (bench_fric case $c) | $(per_call "$(inclusive "f$c.1" fric_)" "$(inclusive "f$c.3" fric_)" 8192) |")
done
for c in 1 2 3 4; do
  rows+=("| FRICREF (hand-written Fortran), ${names[$c]#fric_, } | $(per_call "$(inclusive "f$c.1" fricref_)" "$(inclusive "f$c.3" fricref_)" 8192) |")
done
for l in 2 3 4 5; do
  cg "a$l.1" ./bench_adhesive 1 1 "$l"
  cg "a$l.3" ./bench_adhesive 3 1 "$l"
  rows+=("| bench_adhesive law $l, whole program | $(per_call "$(whole "a$l.1")" "$(whole "a$l.3")" 16384) |")
done
rows+=("| uinter_ (bench_adhesive law 5) | $(per_call "$(inclusive a5.1 uinter_)" "$(inclusive a5.3 uinter_)" 16384) |")
# ifl_fric_batch per point (bench_batch CASE 1..4: NFDIR 1 stick, slip, NFDIR 2 stick, slip; 4096
# points a sweep, so NREP 3 minus NREP 1 is 8192 points). Under valgrind the chunk loop is the
# AVX2 build (valgrind's CPU has AVX2, not AVX-512).
for c in 1 2 3 4; do
  cg "b$c.1" ./bench_batch 1 1 "$c"
  cg "b$c.3" ./bench_batch 3 1 "$c"
  rows+=("| ifl_fric_batch per point, ${names[$c]#fric_, } (bench_batch case $c) | $(per_call "$(inclusive "b$c.1" ifl_fric_batch)" "$(inclusive "b$c.3" ifl_fric_batch)" 8192) |")
done
# bench_pore_pressure NREP NRUN: 1024 points x (NREP + 1) calls per run and path (41 984 calls
# at NREP 20, NRUN 2); the difference of NREP 40 and NREP 20 is 20 x 1024 x NRUN calls.
cg p.20 ./bench_pore_pressure 20 1
cg p.40 ./bench_pore_pressure 40 1
rows+=("| ifl_pore_pressure (bench_pore_pressure) | $(per_call "$(inclusive p.20 ifl_pore_pressure)" "$(inclusive p.40 ifl_pore_pressure)" 20480) |")
# The rate law's rows, from scripts/bench-rate-count.sh (which fails when a rate row reaches 3x
# constant mu; set -e makes that a failure here too).
rate="$(BENCH_BUILD_DIR="$build/rate" "$root/scripts/bench-rate-count.sh" 2>/dev/null)"
while IFS='|' read -r _ name count _; do
  name="$(sed 's/^ *//; s/ *$//' <<<"$name")"
  rows+=("| bench_rate: $name | $(tr -d ' ' <<<"$count") |")
done < <(tail -n +3 <<<"$rate")

toolchain="$(rustc --version), $(gfortran --version | head -n1), $("$cc" --version | head -n1)"
vendor="$(sed -n 's/^vendor_id[[:space:]]*:[[:space:]]*//p' /proc/cpuinfo | head -n1)"
table() {
  echo "Counted with $toolchain on a ${vendor:-unknown} CPU by \`scripts/count-instructions.sh --write\`."
  echo
  echo "| call | instructions per call |"
  echo "|---|---:|"
  printf '%s\n' "${rows[@]}"
}

case "$mode" in
print) table ;;
--write)
  new="$(table)"
  awk -v new="$new" '
    /<!-- counts:begin -->/ { print; print new; skip = 1; next }
    /<!-- counts:end -->/ { skip = 0 }
    !skip { print }' "$doc" >"$doc.tmp"
  mv "$doc.tmp" "$doc"
  echo "count-instructions.sh: wrote the table of $doc"
  ;;
--check)
  committed="$(sed -n '/<!-- counts:begin -->/,/<!-- counts:end -->/p' "$doc")"
  if ! grep -qF "$(rustc --version)" <<<"$committed"; then
    echo "count-instructions.sh: not checked: the table in docs/performance.md was counted with another rustc than $(rustc --version)" >&2
    exit 0
  fi
  # The C library picks some routines (exp, memcpy) by the processor: on another vendor's CPU
  # than the table's, a row may differ by that alone, so the check widens to 10 % there (still
  # a failure for a real regression of that size).
  if [ -n "$vendor" ] && ! grep -qF "on a $vendor CPU" <<<"$committed"; then
    tolerance_percent=10
    echo "count-instructions.sh: the table was counted on another vendor's CPU than this $vendor: checking within $tolerance_percent %" >&2
  fi
  status=0
  for row in "${rows[@]}"; do
    name="$(cut -d'|' -f2 <<<"$row" | sed 's/^ *//; s/ *$//')"
    now="$(cut -d'|' -f3 <<<"$row" | tr -d ' ')"
    was="$(grep -F "| $name |" <<<"$committed" | cut -d'|' -f3 | tr -d ' ' || true)"
    if [ -z "$was" ]; then
      echo "FAIL $name: no row in docs/performance.md (count $now)"
      status=1
    elif awk -v a="$now" -v b="$was" -v t="$tolerance_percent" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d > b * t / 100) }'; then
      echo "FAIL $name: $now instructions per call, docs/performance.md says $was (more than $tolerance_percent % apart)"
      status=1
    else
      echo "ok   $name: $now (docs: $was)"
    fi
  done
  exit "$status"
  ;;
esac
