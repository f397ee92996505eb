#!/usr/bin/env bash
# One fuzz target for a longer run (docs/fuzzing.md): builds the cargo-fuzz targets in fuzz/ with
# AddressSanitizer and runs TARGET for SECONDS (default 300) in one process, keeping its corpus in
# fuzz/corpus/TARGET (git-ignored; reused by the next run). Any crash stops the run and is
# written to fuzz/artifacts/TARGET; this script then exits non-zero.
#
# Usage: scripts/fuzz.sh TARGET [SECONDS]      TARGET: fric | gapcon | config | uinter | batch |
#                                             fric_coef | vfric
# Needs cargo-fuzz (cargo install cargo-fuzz --locked). The toolchain is stable: RUSTC_BOOTSTRAP=1
# lets cargo-fuzz pass its nightly-only sanitizer flags. Extra libFuzzer flags: FUZZ_FLAGS.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
target="${1:?usage: scripts/fuzz.sh fric|gapcon|config|uinter|batch|fric_coef|vfric [SECONDS]}"
seconds="${2:-300}"
case "$target" in
  fric | gapcon | config | uinter | batch | fric_coef | vfric) ;;
  *) echo "fuzz.sh: unknown target '$target' (fric, gapcon, config, uinter, batch, fric_coef, vfric)" >&2
    exit 2 ;;
esac
command -v cargo-fuzz >/dev/null 2>&1 || {
  echo "fuzz.sh: cargo-fuzz is not installed: cargo install cargo-fuzz --locked" >&2
  exit 1
}
export RUSTC_BOOTSTRAP=1
cd "$root/fuzz"
corpus="corpus/$target"
mkdir -p "$corpus"
extra=()
if [ "$target" = config ]; then
  extra=(-dict=config.dict -max_len=4096)
  seeds=(seeds/config)
else
  seeds=()
fi
# shellcheck disable=SC2086 # FUZZ_FLAGS is a list of flags
cargo fuzz run --release "$target" "$corpus" "${seeds[@]}" -- \
  -max_total_time="$seconds" -print_final_stats=1 "${extra[@]}" ${FUZZ_FLAGS:-}
