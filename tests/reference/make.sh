#!/bin/sh
# Regenerates fixtures/stress/reference/NAME.json for every fixtures/stress/NAME.json
# with the independent high-precision reference (tests/reference/mpref.py).
#   tests/reference/make.sh            regenerate (dps 50, 4 sensitivity draws, seed 1)
#   tests/reference/make.sh --compare  also compare every position with mechplan
#                                      (target/release/mechplan, built if missing)
#   tests/reference/make.sh --compare-only   compare the existing references only
# Extra arguments after --compare (or alone) are passed to mpref.py (e.g. --dps 60).
set -eu
cd "$(dirname "$0")/../.."
compare=0; generate=1
if [ "${1:-}" = "--compare" ]; then compare=1; shift; fi
if [ "${1:-}" = "--compare-only" ]; then compare=1; generate=0; shift; fi
out=fixtures/stress/reference
mkdir -p "$out"
start=$(date +%s)
[ $generate = 1 ] && for scene in fixtures/stress/*.json; do
    name=$(basename "$scene" .json)
    t0=$(date +%s.%N)
    rc=0
    python3 tests/reference/mpref.py "$scene" -q -o "$out/$name.json" "$@" || rc=$?
    t1=$(date +%s.%N)
    case $rc in
        0) status=ok ;;
        3) status=rejected ;;
        *) echo "mpref failed on $scene (exit $rc)" >&2; exit 1 ;;
    esac
    printf '%-55s %-8s %6.1f s\n' "$name" "$status" "$(echo "$t1 - $t0" | bc)"
done
[ $generate = 1 ] && echo "total $(( $(date +%s) - start )) s"
if [ $compare = 1 ]; then
    [ -x target/release/mechplan ] || cargo build --release --quiet
    for scene in fixtures/stress/*.json; do
        name=$(basename "$scene" .json)
        echo "== $name"
        python3 tests/reference/mpref.py --against-mechplan "$scene" "$out/$name.json" \
            --mechplan target/release/mechplan > "/tmp/mpref_vs_$name.json"
        python3 - "/tmp/mpref_vs_$name.json" <<'PY'
import json, sys
rep = json.load(open(sys.argv[1]))
if isinstance(rep, dict):
    print("  rejected by mpref:", rep['rejected']); sys.exit()
for r in rep:
    flag = ''
    if r['mechplan'] == 'ok' and r['ours'] == 'ok':
        if r['worst'] > 1e-9: flag = '  <-- DISAGREE'
        if r['bound'] is not None and r['worst'] > r['bound']: flag += '  <-- OUTSIDE mechplan BOUND'
        sens = float(r['sensitivity']) if r['sensitivity'] else float('nan')
        print(f"  pos {r['position']:2d} {r['input']:>22s}  worst {r['worst']:.2e} ({r['where']})"
              f"  sens {sens:.2e}  mechplan bound {r['bound']:.2e}{flag}")
    else:
        if (r['ours'] == 'ok') != (r['mechplan'] == 'ok') and 'assembled' in r.get('message', ''):
            flag = '  <-- ASSEMBLY DIFFERS'
        print(f"  pos {r['position']:2d} {r['input']:>22s}  ours: {r['ours']}  mechplan: {r['mechplan']}"
              f" {r.get('message', '')}{flag}")
PY
    done
fi
