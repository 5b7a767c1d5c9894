#!/usr/bin/env bash
# The checked command-line path against the hand-written closed form, in
# one run (issue 26, Show 2): `mechplan solve --format csv -o FILE` of the
# four-bar (fixtures/four_bar.json) at N positions (default 100 000),
# every position cross-checked, and the
# closed form (benches/peers/closed_form.rs, through the example
# peers_million) writing the rows of the same positions' A, B, M (place,
# velocity, acceleration) and links 2, 3 (angle, ω, ε) to a CSV file.
# Three command-line runs: without plans (`want.plans: []`, the fast path;
# aim at most 1.5× the closed form in wall time on a quiet machine, issue
# 41; 3× before) and with both plans built numbers-only for every position
# (aim at most 12×), and the first again replacing an existing file
# (below). Wall and CPU times (user + system; the command checks
# on the pool's two threads, a third finds the positions, the main one
# writes), the best of three runs each, the closed form's the best of two
# in its own process; prints the machine, the load before and after, the
# times and the ratios.
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
read -r CLOSED CLOSED_CPU < <("$ROOT/target/release/examples/peers_million" "$N" "$OUT" | python3 -c 'import json, sys; j = json.load(sys.stdin); print(j["closed_csv_s"], j["closed_csv_cpu_s"])')
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
# Best of three runs of each scene: wall and CPU (user + system, of the
# process and all its threads) each the least of the three; the disk
# synced before each run (not in its time), as the closed form's files
# are, so that no run pays for the write-back of the one before; and the
# output removed before each run, as the closed form's is: each writes a
# new file. A third line times the fast path replacing the file of the run
# before (`-o` writes a temporary and renames it over the old file, and
# ext4 then writes the new one back at once, in the rename: about 35 ms of
# waiting for these 50 MB, the price of a replacement that survives a
# crash).
TIMES="$(python3 - "$ROOT/target/release/mechplan" "$OUT" <<'PY'
import os, resource, subprocess, sys, time
exe, out = sys.argv[1:]
res = []
for scene, replace in (("fast", False), ("numbers", False), ("fast", True)):
    wall, cpu = float("inf"), float("inf")
    for _ in range(3):
        if replace:
            if not os.path.exists(f"{out}/cli.csv"):
                open(f"{out}/cli.csv", "w").write("the run before's\n")
        elif os.path.exists(f"{out}/cli.csv"):
            os.remove(f"{out}/cli.csv")
        os.sync()
        r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        subprocess.run([exe, "solve", f"{out}/{scene}.json", "--format", "csv",
                        "-o", f"{out}/cli.csv"], check=True)
        t = time.perf_counter() - t0
        r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
        c = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
        wall, cpu = min(wall, t), min(cpu, c)
    res += [wall, cpu]
print(*res)
PY
)"
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
python3 - "$N" "$CLOSED" "$CLOSED_CPU" $TIMES <<'PY'
import sys
n = int(sys.argv[1])
closed, closed_cpu, fast, fast_cpu, numbers, numbers_cpu, over, over_cpu = map(float, sys.argv[2:])
print(f"positions: {n}")
print(f"closed form to CSV:                     {closed:6.3f} s wall, {closed_cpu:6.3f} s CPU  ({1e6 * closed / n:.2f} µs a position)")
for what, t, c, aim in (("checked, no plans (want.plans: [])", fast, fast_cpu, 1.5),
                        ("checked, plans numbers-only", numbers, numbers_cpu, 12.0),
                        ("checked, no plans, replacing the file", over, over_cpu, 1.5)):
    r, rc = t / closed, c / closed_cpu
    verdict = "within" if r <= aim else "OVER"
    print(f"{what:38s} {t:6.3f} s wall, {c:6.3f} s CPU  ({1e6 * t / n:.2f} µs): "
          f"{r:4.2f}× the closed form in wall time ({verdict} the aim {aim:g}×), {rc:4.2f}× in CPU time")
PY
