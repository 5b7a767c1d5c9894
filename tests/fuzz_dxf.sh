#!/usr/bin/env bash
# The DXF answer reader fuzzed for a bounded time (docs/fuzzing.md): a
# panic, an abort, a timeout or running out of memory fails. Usage:
# tests/fuzz_dxf.sh [SECONDS] (default 60). Installs cargo-fuzz when
# missing; libFuzzer is C++, so without a C++ compiler it says so and
# skips.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
if ! command -v c++ > /dev/null && ! command -v g++ > /dev/null && ! command -v clang++ > /dev/null; then
    echo "fuzz_dxf: skipped, no C++ compiler to build libFuzzer with" >&2
    exit 0
fi
if ! cargo fuzz --version > /dev/null 2>&1; then
    cargo install --locked cargo-fuzz
fi
# Seeds: the plan sheets mechplan writes as DXF.
cargo build --release --bin mechplan
corpus=fuzz/corpus/dxf_answer
mkdir -p "$corpus"
seeds=$(mktemp -d)
trap 'rm -rf "$seeds"' EXIT
for scene in four_bar six_link_fig2_10 shaper_fig2_11; do
    target/release/mechplan draw "fixtures/$scene.json" --format dxf -o "$seeds/$scene" > /dev/null
    for f in "$seeds/$scene"/velocity_*.dxf "$seeds/$scene"/acceleration_*.dxf; do
        cp "$f" "$corpus/$scene-$(basename "$f")"
    done
done
cd fuzz
RUSTC_BOOTSTRAP=1 cargo fuzz run dxf_answer "corpus/dxf_answer" -- \
    -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 -max_len=65536
