#!/usr/bin/env bash
# Every test: formatting and lints, the Rust tests, then the C and Fortran harnesses (CTest).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
echo "== cargo fmt / clippy"
cargo fmt --all -- --check
cargo clippy --locked --workspace --all-targets -- -D warnings
cargo clippy --locked --all-targets --features calculix -- -D warnings
echo "== cargo doc (no warnings)"
RUSTDOCFLAGS=-Dwarnings cargo doc --locked --workspace --no-deps
echo "== Rust tests (and nothing left in their own TMPDIR)"
tmp=$(mktemp -d)
TMPDIR=$tmp cargo test --locked --workspace
[ -z "$(ls -A "$tmp")" ] || { echo "cargo test left in TMPDIR:" "$tmp"/*; exit 1; }
rmdir "$tmp"
echo "== Rust tests of the CalculiX variant (gapcon_ with AREA, fricheat_)"
cargo test --locked --features calculix --test gapcon_abi --test header --test last_error --test fricheat
echo "== Rust tests of the single-precision Explicit build (vfric_ with REAL*4, docs/vfric.md)"
cargo clippy --locked --all-targets --features explicit-single -- -D warnings
cargo test --locked --features explicit-single --test vfric
echo "== C and Fortran harnesses (forced on; zero tests run is a failure)"
scripts/test-harnesses.sh build
echo "== instruction counts: the docs' figures (within 2 %) and the rate law's bound (< 3x)"
scripts/count-instructions.sh --check
echo "== binary packages (DEB, tarball): lintian, then the consumer suite on each, without cargo"
scripts/test-packages.sh
echo "== CalculiX host: ccx 2.20 with the library, decks against Debian's stock ccx" && hosts/calculix/test.sh
# Optional stages, each owned by its own script: run when present.
for stage in scripts/test-consumers.sh scripts/test-sanitizers.sh scripts/fuzz-ci.sh; do
  if [ -x "$stage" ]; then
    echo "== $stage"
    "$stage"
  fi
done
