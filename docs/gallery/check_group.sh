#!/usr/bin/env bash
# The summary page of a group graded at once (part of make.sh; on its own
# it writes only docs/gallery/check_group_summary.png, when a headless
# Chromium is at hand): a class's answers for the six-link with loads —
# plans read off the construction, a point moved, the crank's velocity
# reversed, force plans, a plan that cannot be judged, a broken file —
# checked by `mechplan check SCENE DIR` and the page photographed. Prints
# its section of the gallery's README. Usage: bash docs/gallery/check_group.sh [TMPDIR]
set -euo pipefail
cd "$(dirname "$0")/../.."
tmp=${1:-$(mktemp -d)}
scene=fixtures/dynamics/six_link_fig2_10.json
answers="$tmp/group/answers"
rm -rf "$tmp/group"
mkdir -p "$answers"
./target/release/mechplan solve "$scene" --format json > "$tmp/group/solved.json"
python3 - "$tmp/group/solved.json" "$answers" <<'PY'
import json, math, random, sys
doc, out = json.load(open(sys.argv[1])), sys.argv[2]
random.seed(3)
def at(k):
    # Position k by its number, as the sheets and the result file give it.
    return next(p for p in doc["positions"] if p["position"] == k)
def points(kind, k, names, move=None, turn=False):
    plan = at(k)["plans"][kind]
    pts = {}
    for n in names:
        x, y = (c + random.uniform(-0.1, 0.1) for c in plan["points"][n])
        if turn:
            x, y = -x, -y
        if n == move:
            x += 15
        pts[n] = [round(x, 2), round(y, 2)]
    return {"plan": kind, "position": k, "mu": plan["mu"], "points": pts}
def force(k, mu, factor=1.0):
    values = {}
    for p in at(k)["dynamics"]["pairs"]:
        if p.get("slider") == "5":
            values["R_05"] = math.hypot(*p["N"])
        elif p.get("point") == "C":
            values["R_34"] = math.hypot(*p["R"]) * factor
        elif p.get("point") == "D":
            values["R_54"] = math.hypot(*p["R"])
    return {"plan": "force", "position": k, "links": ["4", "5"], "mu": mu, "values": values}
abcd = ["a", "b", "c", "d"]
answers = {
    "bondar-v04.json": points("velocity", 4, abcd + ["s2", "s3", "s4"]),
    "hrytsenko-v07.json": points("velocity", 7, abcd),
    "kovalenko-a03.json": points("acceleration", 3, abcd),
    "lysenko-v05.json": points("velocity", 5, abcd, move="d"),
    "melnyk-v09.json": points("velocity", 9, abcd, turn=True),
    "o'brien & sons-v10.json": points("velocity", 10, abcd),
    "petrenko-f02.json": force(2, 2.0),
    "savchenko-f04.json": force(4, 2.0, factor=1.5),
    "shevchenko-f09.json": force(9, 200.0),
    "tkachenko-a11.json": points("acceleration", 11, abcd),
    "zinchenko-v08.json": {"plan": "velocity", "position": 8, "mu": 0.01, "points": {"q": [12.5, 40.1]}},
}
for name, a in answers.items():
    json.dump(a, open(f"{out}/{name}", "w"))
open(f"{out}/yurchenko-v02.json", "w").write('{"plan": "velocity", "mu": 0.01, "points": {"b": [1')
PY
# Status 2: one answer is unreadable (the gradebook is written all the same).
./target/release/mechplan check "$scene" "$answers" -o "$tmp/group/graded" > /dev/null || [ $? -eq 2 ]
browser=$(command -v chromium || command -v chromium-browser || command -v google-chrome || true)
echo "## A group graded at once"
echo
echo "\`mechplan check SCENE DIR\` ([docs/check.md](../check.md#a-group-at-once)): the"
echo "summary page of twelve answers for the six-link with loads, each file"
echo "linked to its overlay."
echo
if [ -n "$browser" ]; then
  "$browser" --headless --no-sandbox --disable-gpu --no-first-run --disable-background-networking \
    --hide-scrollbars --window-size=1200,900 \
    --screenshot="$PWD/docs/gallery/check_group_summary.png" \
    "file://$tmp/group/graded/summary.html" > /dev/null 2>&1
  echo "![the summary page of a group](check_group_summary.png)"
  echo
fi
