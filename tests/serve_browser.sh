#!/usr/bin/env bash
# `mechplan serve` in a real browser: tests/serve_browser.py drives
# headless Chromium over the DevTools protocol (open a photographed plan,
# click its frame and points, press Check) and compares the page's verdict
# with `mechplan check` of the same plan typed as JSON; a screenshot goes
# to docs/gallery/serve-page.png. Installs Chromium (Debian's `chromium`)
# when it is missing, and websocket-client by pip into target/pydeps.
# Run from anywhere: bash tests/serve_browser.sh
set -euo pipefail
cd "$(dirname "$0")/.."

if [ ! -x /usr/bin/chromium ]; then
  echo "serve_browser: installing chromium"
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo=sudo; fi
  # A registry that cannot be reached is not a failing test: say so, skip.
  if ! { $sudo apt-get update -qq && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq chromium > /dev/null; }; then
    echo "serve_browser: SKIPPED: chromium could not be installed (no package registry?)"
    exit 0
  fi
fi

deps=target/pydeps
if ! PYTHONPATH="$deps" python3 -c "import websocket" 2> /dev/null; then
  python3 -m pip install --quiet --target "$deps" websocket-client
fi

cargo build --release -q
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
PYTHONPATH="$deps" timeout 300 python3 tests/serve_browser.py "$PWD/target/release/mechplan" "$out"
