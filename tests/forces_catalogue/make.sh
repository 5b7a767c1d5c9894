#!/bin/sh
# Regenerates tests/forces_catalogue/ (the force-plan answers and labels.json)
# from the independent reference tests/reference/forceref.py (Python 3 +
# mpmath), after checking the reference against mechplan's reactions on
# every fixture it covers (agreement to 1e-9 of the largest force, or stop;
# the two-cylinder arm's kinematics are mechplan's own, its forces the
# reference's: tests/reference/README.md).
#   tests/forces_catalogue/make.sh        (target/release/mechplan built if missing)
set -eu
cd "$(dirname "$0")/../.."
[ -x target/release/mechplan ] || cargo build --release
for scene in fixtures/dynamics/*.json; do
    python3 tests/reference/forceref.py --against-mechplan "$scene"
done
python3 tests/forces_catalogue/make.py
