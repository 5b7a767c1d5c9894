#!/usr/bin/env bash
# The step-by-step handout (`mechplan draw --html`) in a real browser.
#
# For three fixtures (the six-link with its dynamics among them: its
# force analysis beside the plans): build the handout, open it in
# headless Chromium and
#  1. load it plainly and at #step=5: no console output at all (the page
#     logs nothing, so any CONSOLE line is an error or a warning), the
#     first (fifth) step shown;
#  2. open it at #selftest: the page's own test clicks Next through every
#     step of every plan, checks that each step shows its own elements
#     (and no later ones) with its sentence, then Previous, the arrow keys,
#     Home/End and the position tabs, and writes "SELFTEST PASS …" or
#     "SELFTEST FAIL …" into the title (window errors included);
#  3. take screenshots (1400×1000) at a few steps: target/html_handout/,
#     or with UPDATE_GOLDEN=1 the gallery's docs/gallery/handout-*.png
#     (a test run leaves the repository's files as they were).
# Installs Chromium (Debian package `chromium`) when it is missing.
# Run from anywhere: bash tests/html_handout.sh
set -euo pipefail
cd "$(dirname "$0")/.."

if [ ! -x /usr/bin/chromium ]; then
  echo "html_handout: installing chromium"
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo=sudo; fi
  # A registry that cannot be reached is not a failing test: say so, skip.
  if ! { $sudo apt-get update -qq && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq chromium > /dev/null; }; then
    echo "html_handout: SKIPPED: chromium could not be installed (no package registry?)"
    exit 0
  fi
fi

cargo build --release -q
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# chromium ARGS…: headless, offline, a fresh profile each time.
browse() {
  local profile
  profile=$(mktemp -d -p "$out")
  timeout 180 /usr/bin/chromium --headless --no-sandbox --disable-gpu --no-first-run \
    --disable-background-networking --disable-component-update --disable-sync \
    --user-data-dir="$profile" "$@"
}

# Console lines of a Chromium log (console.log/error, uncaught errors).
console_lines() {
  grep -E ':CONSOLE|Uncaught' "$1" || true
}

fail=0
bad() {
  echo "html_handout: FAIL: $*"
  fail=1
}

shots=(
  "six_link_fig2_10 pos=1&step=9 velocity"
  "six_link_fig2_10 pos=1&step=28 acceleration"
  "shaper_fig2_11 pos=2&step=5 velocity"
  "shaper_fig2_11 pos=2&step=27 acceleration"
)

for name in six_link_fig2_10 shaper_fig2_11 dynamics/six_link_fig2_10; do
  ./target/release/mechplan draw "fixtures/$name.json" -o "$out/$name" --html > /dev/null
  page="file://$out/$name/handout.html"
  size=$(wc -c < "$out/$name/handout.html")

  # 1. Plain load and #step=5.
  for hash in "" "#step=5"; do
    log="$out/$name.load.log"
    browse --enable-logging=stderr --v=0 --log-level=0 --virtual-time-budget=10000 \
      --dump-dom "$page$hash" > "$out/$name.load.dom" 2> "$log" || true
    want="1 / "
    if [ -n "$hash" ]; then want="5 / "; fi
    if ! grep -q "<span id=\"counter\">$want" "$out/$name.load.dom"; then
      bad "$name$hash: the page did not show step ${want% / }"
    fi
    if ! grep -q '<div class="sentence" id="sentence" aria-live="polite">[^<]' "$out/$name.load.dom"; then
      bad "$name$hash: no sentence on the board"
    fi
    if [ -n "$(console_lines "$log")" ]; then
      bad "$name$hash: console output:"
      console_lines "$log" | head -5
    fi
  done

  # 2. Self-test.
  log="$out/$name.selftest.log"
  browse --enable-logging=stderr --v=0 --log-level=0 --virtual-time-budget=60000 \
    --dump-dom "$page#selftest" > "$out/$name.selftest.dom" 2> "$log" || true
  # The result is the page's title (the script's own text is in the DOM too).
  result=$(grep -o '<title>[^<]*' "$out/$name.selftest.dom" | head -1 | sed 's/^<title>//' || true)
  echo "html_handout: $name ($size bytes): ${result:-no self-test result}"
  case "$result" in
    "SELFTEST PASS"*) ;;
    *) bad "$name: self-test did not pass" ;;
  esac
  if [ -n "$(console_lines "$log")" ]; then
    bad "$name#selftest: console output:"
    console_lines "$log" | head -5
  fi
done

# 3. Screenshots: into the gallery only when asked.
shots_dir=target/html_handout
if [ "${UPDATE_GOLDEN:-}" = 1 ]; then shots_dir=docs/gallery; fi
mkdir -p "$shots_dir"
for s in "${shots[@]}"; do
  read -r name hash plan <<< "$s"
  png="$shots_dir/handout-$name-$plan.png"
  browse --hide-scrollbars --window-size=1400,1000 --virtual-time-budget=10000 \
    --screenshot="$out/shot.png" "file://$out/$name/handout.html#$hash" > /dev/null 2>&1 || true
  if [ -s "$out/shot.png" ]; then
    mv "$out/shot.png" "$png"
    echo "html_handout: wrote $png"
  else
    bad "$name: no screenshot at #$hash"
  fi
done

if [ "$fail" -ne 0 ]; then
  echo "html_handout: FAILED"
  exit 1
fi
echo "html_handout: ok"
