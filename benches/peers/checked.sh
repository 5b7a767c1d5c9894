#!/usr/bin/env bash
# The checked command-line path against the hand-written closed form, in
# one run (issue 26, Show 2): `mechplan solve --format csv -o FILE` of the
# four-bar (fixtures/four_bar.json) at N positions (default 100 000, the
# largest count a scene may ask), every position cross-checked, and the
# closed form (benches/peers/closed_form.rs, through the example
# peers_million) writing the rows of the same positions' A, B, M (place,
# velocity, acceleration) and links 2, 3 (angle, ω, ε) to a CSV file.
# Two command-line runs: without plans (`want.plans: []`, the fast path;
# target at most 3× the closed form) and with both plans built numbers-only
# for every position (target at most 12×). Wall times, the best of three
# runs each; prints the machine, the load, the times and the ratios.
#
#   bash benches/peers/checked.sh [N]
#
# The command writes links 0 (the frame) and 1 (the crank) too: 32 columns
# against the closed form's 26.
set -euo pipefail
N="${1:-100000}"
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$ROOT"
OUT="$ROOT/target/peers/checked"
mkdir -p "$OUT"
cargo build --release --quiet --example peers_million --bin mechplan
echo "machine: $(lscpu | grep 'Model name' | sed 's/.*: *//'), $(nproc) cores; load average $(cut -d' ' -f1-3 /proc/loadavg)"
CLOSED="$("$ROOT/target/release/examples/peers_million" "$N" "$OUT" | python3 -c 'import json, sys; print(json.load(sys.stdin)["closed_csv_s"])')"
for plans in fast numbers; do
python3 - "$ROOT/fixtures/four_bar.json" "$OUT/$plans.json" "$N" "$plans" <<'PY'
import json, sys
v = json.load(open(sys.argv[1]))
v["positions"] = {"count": int(sys.argv[3])}
want = {"rates": ["velocity", "acceleration"], "points": ["A", "B", "M"]}
if sys.argv[4] == "fast":
    want["plans"] = []
v["want"] = want
json.dump(v, open(sys.argv[2], "w"))
PY
done
best() {
    local scene="$1" best=""
    for _ in 1 2 3; do
        local t0 t1
        t0=$(date +%s.%N)
        "$ROOT/target/release/mechplan" solve "$scene" --format csv -o "$OUT/cli.csv"
        t1=$(date +%s.%N)
        best=$(python3 -c "b='$best'; t=$t1-$t0; print(t if not b else min(float(b), t))")
    done
    echo "$best"
}
FAST="$(best "$OUT/fast.json")"
NUMBERS="$(best "$OUT/numbers.json")"
python3 - "$N" "$CLOSED" "$FAST" "$NUMBERS" <<'PY'
import sys
n, closed, fast, numbers = int(sys.argv[1]), *map(float, sys.argv[2:])
print(f"positions: {n}")
print(f"closed form to CSV:                   {closed:8.3f} s  ({1e6 * closed / n:.2f} µs a position)")
for what, t, aim in (("checked, no plans (want.plans: [])", fast, 3.0),
                     ("checked, plans numbers-only", numbers, 12.0)):
    r = t / closed
    verdict = "within" if r <= aim else "OVER"
    print(f"{what:38s} {t:8.3f} s  ({1e6 * t / n:.2f} µs)  {r:5.2f}× the closed form ({verdict} {aim:g}×)")
PY
