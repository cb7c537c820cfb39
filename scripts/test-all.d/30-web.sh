#!/usr/bin/env bash
# The web explorer's checks (one step of `make test`): installs what is missing, builds www/,
# runs the wasm-bindgen tests of the binding in headless Chromium, serves www/ on a free local port
# and runs the end-to-end test (tests/e2e/e2e.mjs) against it.
set -euo pipefail
cd "$(dirname "$0")/../.."

scripts/setup-web.sh

echo "--- clippy (wasm32)"
cargo clippy -p rime-wasm --target wasm32-unknown-unknown --all-targets -- -D warnings

echo "--- build www"
scripts/build-www.sh
wasm=www/pkg/rime_wasm_bg.wasm
echo "wasm size: $(stat -c %s "$wasm") bytes raw, $(gzip -9 -c "$wasm" | wc -c) bytes gzipped"

echo "--- wasm-bindgen-test in headless Chromium"
CHROMEDRIVER=${CHROMEDRIVER:-$(command -v chromedriver || echo /usr/bin/chromedriver)} \
  CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUNNER=wasm-bindgen-test-runner \
  WASM_BINDGEN_TEST_TIMEOUT=${WASM_BINDGEN_TEST_TIMEOUT:-120} \
  cargo test -p rime-wasm --target wasm32-unknown-unknown

echo "--- end-to-end"
rime_bin=${CARGO_TARGET_DIR:-target}/release/rime
[ -x "$rime_bin" ] || cargo build --release -p rime-tui
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server "$port" --bind 127.0.0.1 --directory www >/dev/null 2>&1 &
server=$!
trap 'kill "$server" 2>/dev/null || true' EXIT
for _ in $(seq 50); do
  python3 -c "import urllib.request; urllib.request.urlopen('http://127.0.0.1:$port/')" 2>/dev/null && break
  sleep 0.1
done
RIME_BIN=${RIME_BIN:-$rime_bin} node tests/e2e/e2e.mjs "http://127.0.0.1:$port/"
