#!/usr/bin/env bash
# A million positions of the four-bar (fixtures/four_bar.json), end to end
# into CSV files, in one run: mechplan's compiled route (a), the
# hand-written closed form, pylinkage's numba sweep, and mechplan's
# checked command-line path.
#
#   bash benches/peers/million.sh [N]        (default N = 1000000)
#
# - mechplan, compiled route (a), library API: benches/peers/million.rs
#   (the example peers_million) solves each position by
#   `compiled::Program::solve_one` and writes it as a CSV row as it goes
#   (A, B, M: place, velocity, acceleration; links 2, 3: angle, ω, ε);
#   then the closed form (benches/peers/closed_form.rs, the limit of
#   benches/speed.rs) writes the same rows. Both also timed without writing.
# - pylinkage 1.3.0 with numba (PyPI, in target/peers-venv):
#   `step_fast_with_kinematics` over the same N crank angles (numba's
#   compilation not timed), then its joints' places, velocities and
#   accelerations written with numpy's savetxt ("%.17g"); its B is checked
#   against mechplan's before its time is printed.
# - mechplan's command line, the checked fast path (`want.plans: []`,
#   route (a) with every position cross-checked by route (b)'s equations,
#   docs/sweeps.md): `mechplan solve --format csv -o FILE` at the largest
#   count a scene may ask (100 000), per position.
set -euo pipefail
N="${1:-1000000}"
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$ROOT"
VENV="$ROOT/target/peers-venv"
OUT="$ROOT/target/peers/million"
mkdir -p "$OUT"

if [ ! -x "$VENV/bin/python" ]; then
    python3 -m venv "$VENV"
fi
"$VENV/bin/pip" install --quiet --disable-pip-version-check "pylinkage[numba]==1.3.0"

cargo build --release --quiet --example peers_million --bin mechplan
echo "machine: $(lscpu | grep 'Model name' | sed 's/.*: *//'), $(nproc) cores; load average $(cut -d' ' -f1-3 /proc/loadavg)"
MP="$("$ROOT/target/release/examples/peers_million" "$N" "$OUT")"

# The checked command-line path at the largest count a scene may ask.
CLI_N=100000
python3 - "$ROOT/fixtures/four_bar.json" "$OUT/four_bar_cli.json" "$CLI_N" <<'PY'
import json, sys
v = json.load(open(sys.argv[1]))
v["positions"] = {"count": int(sys.argv[3])}
v["want"] = {"plans": [], "rates": ["velocity", "acceleration"]}
json.dump(v, open(sys.argv[2], "w"))
PY
T0=$(date +%s.%N)
"$ROOT/target/release/mechplan" solve "$OUT/four_bar_cli.json" --format csv -o "$OUT/cli.csv"
T1=$(date +%s.%N)
CLI_S=$(python3 -c "print($T1 - $T0)")

"$VENV/bin/python" - "$N" "$ROOT" "$OUT" "$MP" "$CLI_N" "$CLI_S" <<'PY'
import json, math, sys, time
import numpy as np

N = int(sys.argv[1]); root, out = sys.argv[2], sys.argv[3]
mp = json.loads(sys.argv[4]); cli_n = int(sys.argv[5]); cli_s = float(sys.argv[6])
from pylinkage.mechanism import fourbar

v = json.load(open(f"{root}/fixtures/four_bar.json"))
p = v["points"]; L = v["lengths"]; i = v["input"]
phi0 = math.radians(i["angle"])
ref_b = np.fromfile(f"{out}/b.f64", dtype="<f8").reshape(N, 6)

def build(branch, n):
    m = fourbar(crank=L["O1-A"], coupler=L["A-B"], rocker=L["O3-B"],
                ground=p["O3"][0] - p["O1"][0], omega=math.tau / n,
                initial_angle=phi0 - math.tau / n, branch=branch)
    m.set_input_velocity(m._driver_links[0], i["omega"], i.get("epsilon", 0.0))
    return m

def rel_err(got, ref):
    return max(np.abs(got[:, a:b] - ref[:, a:b]).max() / np.abs(ref[:, a:b]).max()
               for a, b in ((0, 2), (2, 4), (4, 6)))

# The branch and the joint that is mechplan's B, read off a short sweep.
best = None
for branch in (1, 0):
    m = build(branch, N)
    pos, vel, acc = m.step_fast_with_kinematics(iterations=64)
    for j in range(pos.shape[1]):
        got = np.concatenate([pos[:, j], vel[:, j], acc[:, j]], axis=1)
        e = rel_err(got, ref_b[:64])
        if best is None or e < best[0]:
            best = (e, branch, j)
_, branch, jb = best
m = build(branch, N)
m.step_fast_with_kinematics(iterations=8)  # numba's compilation, not timed
m = build(branch, N)
t = time.perf_counter()
pos, vel, acc = m.step_fast_with_kinematics(iterations=N)
t_py = time.perf_counter() - t
got = np.concatenate([pos[:, jb], vel[:, jb], acc[:, jb]], axis=1)
err = rel_err(got, ref_b)
J = pos.shape[1]
t = time.perf_counter()
rows = np.concatenate([np.arange(1, N + 1)[:, None].astype(float),
                       np.concatenate([pos, vel, acc], axis=2).reshape(N, J * 6)], axis=1)
names = [j.id for j in m.joints]
head = "position," + ",".join(f"{q}_{n}" for n in names for q in ("x", "y", "vx", "vy", "ax", "ay"))
# (the columns: per joint its place, then velocity, then acceleration)
np.savetxt(f"{out}/pylinkage.csv", rows, fmt="%.17g", delimiter=",", header=head, comments="")
t_py_csv = t_py + time.perf_counter() - t

us = lambda s, n=N: s / n * 1e6
lim = mp["closed_s"]; lim_csv = mp["closed_csv_s"]
print(f"{N} positions of the four-bar, positions + velocities + accelerations, one full turn")
print(f"{'':44} {'compute':>14} {'to CSV':>14}   compute/limit  CSV/limit's CSV")
def line(name, c, w, n=N, note=""):
    cs = f"{us(c, n):9.3f} µs" if c is not None else " " * 12
    ws = f"{us(w, n):9.3f} µs" if w is not None else " " * 12
    rc = f"{(c / n) / (lim / N):11.2f}×" if c is not None else " " * 12
    rw = f"{(w / n) / (lim_csv / N):11.2f}×" if w is not None else " " * 12
    print(f"  {name:<42} {cs:>14} {ws:>14}   {rc}   {rw}{note}")
line("closed form (the limit)", mp["closed_s"], mp["closed_csv_s"])
line("mechplan, compiled route (a), library API", mp["compiled_s"], mp["compiled_csv_s"])
line("pylinkage 1.3.0, numba", t_py, t_py_csv)
line(f"mechplan solve --format csv (checked, {cli_n})", None, cli_s, cli_n,
     "  (whole command: load, route (a), route (b)'s check)")
print(f"mechplan against the closed form: max rel. difference {mp['max_rel_diff']:.1e}; "
      f"pylinkage's B against mechplan's: {err:.1e}")
print(f"CSV sizes: mechplan {mp['csv_bytes'] / 1e6:.0f} MB (A, B, M, links 2 and 3: 26 columns); "
      f"pylinkage {__import__('os').path.getsize(out + '/pylinkage.csv') / 1e6:.0f} MB "
      f"({J} joints' places, v, a: {1 + 6 * J} columns)")
PY
