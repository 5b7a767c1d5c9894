#!/usr/bin/env bash
# Times mechplan against two Python peers on the same sweep: the four-bar
# (fixtures/four_bar.json) and the offset slider-crank
# (fixtures/offset_slider_crank.json), each over N crank positions (one
# full turn; default 3600), positions + velocities + accelerations.
#
#   bash benches/peers/run.sh [N]
#
# Peers (PyPI, in a virtual environment under target/peers-venv):
#   pylinkage 1.3.0 with numba: Mechanism.step_fast_with_kinematics (the
#     numba-compiled solver; compilation is not timed);
#   mechanism 1.1.10: Mechanism.iterate (scipy's fsolve on the loop
#     equations for positions, velocities and accelerations).
# mechplan: benches/peers/sweep.rs (the example peers_sweep), timing only the solve (positions and
# route (a), compiled for the mechanism), plus the whole Analysis::run for reference.
# Each peer's result is checked against mechplan's before its time counts
# (the relative difference is printed).
set -euo pipefail
N="${1:-3600}"
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$ROOT"
VENV="$ROOT/target/peers-venv"
OUT="$ROOT/target/peers"
mkdir -p "$OUT"

if [ ! -x "$VENV/bin/python" ]; then
    python3 -m venv "$VENV"
fi
"$VENV/bin/pip" install --quiet --disable-pip-version-check \
    "pylinkage[numba]==1.3.0" "mechanism==1.1.10"

cargo build --release --quiet --example peers_sweep
RESULTS="{"
sep=""
for f in four_bar offset_slider_crank; do
    line="$("$ROOT/target/release/examples/peers_sweep" "fixtures/$f.json" "$N" "$OUT/$f.csv")"
    RESULTS="$RESULTS$sep\"$f\": $line"
    sep=", "
done
RESULTS="$RESULTS}"

echo "machine: $(lscpu | grep 'Model name' | sed 's/.*: *//'), $(nproc) cores"
# Matplotlib (a dependency of mechanism) must not look for a display.
MPLBACKEND=Agg "$VENV/bin/python" - "$N" "$ROOT" "$RESULTS" <<'PY'
import csv, json, math, statistics, sys, time
import numpy as np

N = int(sys.argv[1])
root = sys.argv[2]
results = json.loads(sys.argv[3])  # mechplan's figures, keyed by fixture
REPEATS = 5

def fixture(name):
    with open(f"{root}/fixtures/{name}.json") as f:
        return json.load(f)

def mechplan_points(path):
    """{point: array (N, 6)} of x, y, vx, vy, ax, ay from the Rust sweep."""
    rows = {}
    with open(path) as f:
        for r in csv.DictReader(f):
            rows.setdefault(r["point"], []).append(
                [float(r[k]) for k in ("x", "y", "vx", "vy", "ax", "ay")])
    return {k: np.array(v) for k, v in rows.items()}

def median_time(run, repeats=REPEATS):
    ts = []
    for _ in range(repeats):
        t = time.perf_counter()
        out = run()
        ts.append(time.perf_counter() - t)
    return statistics.median(ts), out

def rel_err(got, ref):
    """Largest difference of (x, y), (v), (a) each relative to the largest magnitude of its kind."""
    errs = []
    for a, b in ((0, 2), (2, 4), (4, 6)):
        if got.shape[1] < b:
            continue
        scale = np.abs(ref[:, a:b]).max()
        errs.append(np.abs(got[:, a:b] - ref[:, a:b]).max() / scale)
    return max(errs)

def ratio_line(peer, what, t_peer, t_mp, err, note=""):
    print(f"  {peer:<26} {what:<13} {t_peer / N * 1e6:10.3f} µs/position;  "
          f"mechplan's time / peer's {t_mp / t_peer:9.2g}  "
          f"(max rel. difference from mechplan {err:.1e}){note}")

# ---------------------------------------------------------------- pylinkage
def pylinkage_fourbar(v, omega, eps):
    from pylinkage.mechanism import fourbar
    p = v["points"]; L = v["lengths"]
    phi0 = math.radians(v["input"]["angle"])
    for branch in (1, 0):
        m = fourbar(crank=L["O1-A"], coupler=L["A-B"], rocker=L["O3-B"],
                    ground=p["O3"][0] - p["O1"][0], omega=math.tau / N,
                    initial_angle=phi0 - math.tau / N, branch=branch)
        m.set_input_velocity(m._driver_links[0], omega, eps)
        m.step_fast_with_kinematics(iterations=N)  # numba's compilation, not timed
        yield m, [j.id for j in m.joints]

def pylinkage_slider(v, omega, eps):
    # The factory `slider_crank` sets no branch: built here with the sketch's
    # (the slider on the far side of the crank). pylinkage 1.3.0 cannot give
    # a slider's rates: step_with_derivatives leaves its velocity and
    # acceleration None, and the numba path (step_fast*) leaves the
    # prismatic joint unsolved; so only positions, by the Python `step`.
    from pylinkage.mechanism.builder import MechanismBuilder
    L = v["lengths"]; s = v["sliders"][0]["line"]
    mm = 1e-3 if v["units"]["length"] == "mm" else 1.0
    phi0 = math.radians(v["input"]["angle"])
    for branch in (1, 0):
        b = MechanismBuilder(name="slider-crank")
        b.add_ground_link("ground", ports={"O": (0.0, 0.0)})
        b.add_driver_link("crank", length=L["O-A"] * mm, motor_port="O",
                          omega=math.tau / N, initial_angle=phi0 - math.tau / N)
        b.add_link("rod", length=L["A-B"] * mm)
        b.add_slide_axis("rail", through=(0.0, s.get("offset", 0.0) * mm), direction=(1.0, 0.0))
        b.connect("crank.tip", "rod.0")
        b.connect_prismatic("rod.1", "rail")
        b.set_branch("rod.1", branch)
        m = b.build()
        names = [j.id for j in m.joints]
        def run(m=m):
            return np.array(list(m.step(iterations=N)))
        def split(pos, names=names):
            return {n: pos[:, i, :] for i, n in enumerate(names)}
        yield run, split

def pylinkage_fourbar_runs(v, omega, eps):
    for m, names in pylinkage_fourbar(v, omega, eps):
        def run(m=m):
            return m.step_fast_with_kinematics(iterations=N)
        def split(r, names=names):
            pos, vel, acc = r
            return {n: np.concatenate([pos[:, i, :], vel[:, i, :], acc[:, i, :]], axis=1)
                    for i, n in enumerate(names)}
        yield run, split

def run_pylinkage(label, what, builds, ref, t_mp, note=""):
    last = None
    for run, split in builds:
        # One turn lands back at the start, so each timed call sweeps the same N positions.
        t, r = median_time(run)
        got = split(r)
        # Match the peer's joints to mechplan's points by their values.
        err = 0.0
        for name in ("A", "B"):
            err = max(err, min(rel_err(g, ref[name][:, :g.shape[1]]) for g in got.values()))
        last = (t, err)
        if err < 1e-6:
            break
    t, err = last
    ratio_line(label, what, t, t_mp, err, note)

# ---------------------------------------------------------------- mechanism
def run_mechanism_fourbar(v, omega, eps, ref, t_mp):
    from mechanism import Mechanism, Vector, get_joints
    p = v["points"]; L = v["lengths"]
    O, A, B, C = get_joints("O A B C")
    a = Vector((O, A), r=L["O1-A"])
    b = Vector((A, B), r=L["A-B"])
    c = Vector((O, C), r=p["O3"][0], theta=0, style="ground")
    d = Vector((C, B), r=L["O3-B"])
    phi = math.radians(v["input"]["angle"]) + np.arange(N) * math.tau / N
    def loop(x, i):
        return a(i) + b(x[0]) - c() - d(x[1])
    ab = math.atan2(p["B"][1] - p["A"][1], p["B"][0] - p["A"][0])
    cb = math.atan2(p["B"][1] - p["O3"][1], p["B"][0] - p["O3"][0])
    def run():
        m = Mechanism(vectors=(a, b, c, d), origin=O, loops=loop, pos=phi,
                      vel=np.full(N, omega), acc=np.full(N, eps),
                      guess=(np.array([ab, cb]), np.array([1.0, 1.0]), np.array([1.0, 1.0])))
        m.iterate()
        return m
    t, _ = median_time(run, repeats=1)
    got = np.stack([B.x_positions, B.y_positions, B.x_velocities, B.y_velocities,
                    B.x_accelerations, B.y_accelerations], axis=1)
    ratio_line("mechanism 1.1.10 (fsolve)", "four-bar", t, t_mp, rel_err(got, ref["B"]))

def run_mechanism_slider(v, omega, eps, ref, t_mp):
    from mechanism import Mechanism, Vector, get_joints
    L = v["lengths"]; s = v["sliders"][0]["line"]
    mm = 1e-3 if v["units"]["length"] == "mm" else 1.0
    off = s.get("offset", 0.0) * mm
    O, A, B, P = get_joints("O A B P")
    a = Vector((O, A), r=L["O-A"] * mm)
    b = Vector((A, B), r=L["A-B"] * mm)
    c = Vector((O, P), r=abs(off), theta=math.copysign(math.pi / 2, off), style="ground")
    d = Vector((P, B), theta=0, style="dotted")
    phi = math.radians(v["input"]["angle"]) + np.arange(N) * math.tau / N
    def loop(x, i):
        return a(i) + b(x[0]) - c() - d(x[1])
    pt = v["points"]
    ab = math.atan2(pt["B"][1] - pt["A"][1], pt["B"][0] - pt["A"][0])
    def run():
        m = Mechanism(vectors=(a, b, c, d), origin=O, loops=loop, pos=phi,
                      vel=np.full(N, omega), acc=np.full(N, eps),
                      guess=(np.array([ab, pt["B"][0] * mm]), np.array([1.0, 1.0]), np.array([1.0, 1.0])))
        m.iterate()
        return m
    t, _ = median_time(run, repeats=1)
    got = np.stack([B.x_positions, B.y_positions, B.x_velocities, B.y_velocities,
                    B.x_accelerations, B.y_accelerations], axis=1)
    ratio_line("mechanism 1.1.10 (fsolve)", "slider-crank", t, t_mp, rel_err(got, ref["B"]))

def rates(v):
    i = v["input"]
    omega = i["omega"] if "omega" in i else i["rpm"] * math.tau / 60
    return omega, i.get("epsilon", 0.0)

print(f"Sweep of {N} positions (one full turn), positions + velocities + accelerations;"
      " times are medians, per position.")
print("mechplan: compiled::Program::solve_one (positions and route (a)) and reading every point's"
      " place, velocity, acceleration; the whole Analysis::run (both routes, plans, cross-check):")
for name, r in results.items():
    print(f"  {name:<28} route (a) {r['route_a_per_position_s'] * 1e6:8.3f} µs/position   "
          f"Analysis::run {r['run_per_position_s'] * 1e6:8.1f} µs/position")
print("peers (the same mechanism, crank angles, ω1, ε1; each checked against mechplan's result):")
fb = fixture("four_bar"); sc = fixture("offset_slider_crank")
fb_ref = mechplan_points(f"{root}/target/peers/four_bar.csv")
sc_ref = mechplan_points(f"{root}/target/peers/offset_slider_crank.csv")
t_fb = results["four_bar"]["route_a_s"]; t_sc = results["offset_slider_crank"]["route_a_s"]
run_pylinkage("pylinkage 1.3.0 (numba)", "four-bar", pylinkage_fourbar_runs(fb, *rates(fb)), fb_ref, t_fb)
run_pylinkage("pylinkage 1.3.0 (Python)", "slider-crank", pylinkage_slider(sc, *rates(sc)), sc_ref, t_sc,
              "\n    (positions only: pylinkage 1.3.0 gives no slider velocity or acceleration, and its numba path leaves the slider unsolved)")
run_mechanism_fourbar(fb, *rates(fb), fb_ref, t_fb)
run_mechanism_slider(sc, *rates(sc), sc_ref, t_sc)
print("Neither peer gives angular velocities or accelerations of the links with the points'"
      " (pylinkage: joints only; mechanism: only its loop vectors), nor plans of velocities"
      " or accelerations; the four-bar's coupler point M is left out of the peers' models.")
PY
