#!/usr/bin/env bash
# The web explorer's checks (one step of `make test`): builds www/, runs the wasm-bindgen tests of the
# binding in headless Chromium, serves www/ on a free local port and runs the end-to-end test
# (tests/e2e/e2e.mjs) against it. Everything is built in the release profile, which make test builds
# anyway (the wasm tests too: a debug build of them would compile every dependency a second time).
set -euo pipefail
cd "$(dirname "$0")/../.."

scripts/setup-web.sh # make test's setup steps did this; run alone, this step installs what it needs

echo "--- clippy (wasm32)"
cargo clippy --locked -p rime-wasm --target wasm32-unknown-unknown --all-targets -- -D warnings

echo "--- build www"
scripts/build-www.sh

echo "--- wasm-bindgen-test in headless Chromium"
# WASM_BINDGEN_TEST_TIMEOUT is a hang guard, not a speed check: the whole wasm test binary runs in
# about 2 s on an idle machine (its slowest test, a frame at precise, well under 1 s), and the
# guard is 120 s, over 50× that.
t0=$(date +%s.%N)
# Each wasm test counts as one test of make test (as the native Rust tests do).
CHROMEDRIVER=${CHROMEDRIVER:-$(command -v chromedriver || echo /usr/bin/chromedriver)} \
  CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUNNER=wasm-bindgen-test-runner \
  WASM_BINDGEN_TEST_TIMEOUT=${WASM_BINDGEN_TEST_TIMEOUT:-120} \
  scripts/cargo-tests.sh cargo test --locked --release -p rime-wasm --target wasm32-unknown-unknown
echo "report: wasm-bindgen tests (build + run) took $(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }') s"

echo "--- end-to-end"
rime_bin=$(scripts/rime-bin.sh)
source scripts/serve-www.sh # sets port; the server stops on exit
RIME_BIN=${RIME_BIN:-$rime_bin} node tests/e2e/e2e.mjs "http://127.0.0.1:$port/"
