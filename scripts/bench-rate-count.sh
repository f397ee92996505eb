#!/usr/bin/env bash
# The rate law's cost guard (issue 4, issue 16): instructions per fric_ call of each
# bench/bench_rate.f90 row, counted with callgrind (deterministic: the same count on a loaded
# machine), and the ratio to constant μ. Fails (exit 1) when the decay law (cold or warm start)
# or the decay law with μ frozen reaches 3× constant μ, the bound of issues 4 and 16.
#
# Each row runs alone (`bench_rate NREP 1 ROW`) and only `run_loop` is counted
# (--collect-atstart=no --toggle-collect), so start-up and the points' set-up are not in the
# figures; a count includes the host loop's copies and the call (as the constant row does).
#
# Usage: scripts/bench-rate-count.sh [NREP]   (default 3). Builds the library (cargo, release)
# and bench_rate in $BENCH_BUILD_DIR (default /tmp/build-bench), as scripts/bench.sh does.
# Prints a Markdown table on stdout (scripts/bench.sh puts it into docs/benchmarks.md).
# Installs nothing; needs gfortran and valgrind (exit 2 without them, scripts/bench-setup.sh).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
nrep="${1:-3}"
# The bound; BENCH_RATE_LIMIT only to see the guard fail (e.g. 2.5), never to pass it.
limit="${BENCH_RATE_LIMIT:-3}"
npoints=4096 # bench_rate's npoints
# shellcheck source=scripts/bench-setup.sh
. "$root/scripts/bench-setup.sh" bench-rate-count.sh /tmp/build-bench gfortran valgrind
gfortran -O2 -o bench_rate "$root/bench/bench_rate.f90" "$lib" "${native_libs[@]}"

# Rows of bench_rate, in its order.
names=("constant" "decay (cold start)" "frozen" "decay (warm start)"
  "constant, general path (HHT on)" "constant, anisotropic")
declare -a per_call
for row in 1 2 3 4 5 6; do
  out="callgrind.rate.$row"
  rm -f "$out"
  valgrind --tool=callgrind --callgrind-out-file="$out" --collect-atstart=no \
    --toggle-collect='__bench_rate_data_MOD_run_loop' ./bench_rate "$nrep" 1 "$row" \
    >/dev/null 2>"$out.log"
  total="$(sed -n 's/^summary:[[:space:]]*//p' "$out" | head -n1)"
  if [ -z "$total" ] || [ "$total" -eq 0 ]; then
    echo "bench-rate-count.sh: no count for row $row (see $build/$out.log)" >&2
    exit 2
  fi
  per_call[$row]="$(awk -v t="$total" -v n="$((nrep * npoints))" 'BEGIN { printf "%.1f", t / n }')"
done

status=0
echo "| PROPS | instructions per call | ratio to constant | bound |"
echo "|---|---:|---:|---|"
for row in 1 2 3 4 5 6; do
  ratio="$(awk -v a="${per_call[$row]}" -v b="${per_call[1]}" 'BEGIN { printf "%.2f", a / b }')"
  bound=""
  case "$row" in
  2 | 3 | 4)
    if awk -v r="$ratio" -v l="$limit" 'BEGIN { exit !(r < l) }'; then
      bound="< ${limit}×: ok"
    else
      bound="< ${limit}×: **FAILED**"
      status=1
    fi
    ;;
  esac
  echo "| ${names[$((row - 1))]} | ${per_call[$row]} | $ratio | $bound |"
done
if [ "$status" -ne 0 ]; then
  echo "bench-rate-count.sh: a rate law row reached ${limit}× constant μ" >&2
fi
exit "$status"
