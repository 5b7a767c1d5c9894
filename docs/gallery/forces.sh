#!/usr/bin/env bash
# The force sheets of the gallery (part of make.sh; on its own it writes
# only these PNGs): the third position (else the first) of every dynamics
# fixture and the six-link's position 1 in Ukrainian, into
# docs/gallery/forces/, and prints their
# section of the gallery's README. Usage: bash docs/gallery/forces.sh [TMPDIR]
set -euo pipefail
cd "$(dirname "$0")/../.."
tmp=${1:-$(mktemp -d)}
out=docs/gallery/forces
mkdir -p "$out"
rm -f "$out"/*.png
echo "## Force sheets"
echo
echo "The force analysis of a position (\`forces_<k>\`, drawn with a \`dynamics\`"
echo "scene; [docs/kinetostatics.md](../kinetostatics.md), \"On paper\"): per Assur"
echo "group and the input link, the free body at μ_l and the force polygon at μ_F."
echo
for f in fixtures/dynamics/*.json; do
  n=$(basename "$f" .json)
  ./target/release/mechplan draw "$f" -o "$tmp/$n" --format png --dpi 100 > /dev/null
  # The third position where there is one (the first, position 0 of a
  # count, is often a dead centre, every force on one line), else the
  # first: by its number, as the manifest gives it.
  k=$(python3 -c 'import json, sys; ks = sorted(s["position"] for s in json.load(open(sys.argv[1]))["sheets"] if s["file"].startswith("forces_")); print(ks[2] if len(ks) > 2 else ks[0])' "$tmp/$n/sheets.json")
  cp "$tmp/$n/forces_$k.png" "$out/$n.png"
  echo "![$n forces_$k](forces/$n.png)"
done
./target/release/mechplan draw fixtures/dynamics/six_link_fig2_10.json --lang uk -o "$tmp/six_uk" --format png --dpi 100 > /dev/null
cp "$tmp/six_uk/forces_1.png" "$out/six_link_fig2_10_uk_1.png"
echo "![six_link_fig2_10 forces_1, uk](forces/six_link_fig2_10_uk_1.png)"
echo
