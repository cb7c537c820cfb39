#!/usr/bin/env bash
# Installs what the web tests need on a fresh machine; skips what is already there:
# the wasm32 target, wasm-bindgen-cli at Cargo.lock's wasm-bindgen version, chromium + chromedriver
# (apt, when root), and playwright-core and axe-core in tests/e2e (npm).
set -euo pipefail
cd "$(dirname "$0")/.."

rustup target list --installed 2>/dev/null | grep -qx wasm32-unknown-unknown ||
  rustup target add wasm32-unknown-unknown

want=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/"/, "", $3); print $3; exit }' Cargo.lock)
if [ -z "$want" ]; then
  echo "setup-web: no wasm-bindgen in Cargo.lock" >&2
  exit 1
fi
have=$(wasm-bindgen --version 2>/dev/null | awk '{ print $2 }' || true)
if [ "$have" != "$want" ] || ! command -v wasm-bindgen-test-runner >/dev/null; then
  echo "setup-web: installing wasm-bindgen-cli $want (have: ${have:-none})"
  cargo install wasm-bindgen-cli --version "$want"
fi

if ! command -v chromium >/dev/null || ! command -v chromedriver >/dev/null; then
  if [ "$(id -u)" -eq 0 ] && command -v apt-get >/dev/null; then
    export DEBIAN_FRONTEND=noninteractive
    apt-get install -y chromium chromium-driver ||
      { apt-get update && apt-get install -y chromium chromium-driver; }
  else
    echo "setup-web: chromium and chromedriver are missing; install them (apt-get install chromium chromium-driver)" >&2
    exit 1
  fi
fi

if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  if [ "$(id -u)" -eq 0 ] && command -v apt-get >/dev/null; then
    export DEBIAN_FRONTEND=noninteractive
    apt-get install -y nodejs npm || { apt-get update && apt-get install -y nodejs npm; }
  else
    echo "setup-web: node and npm are missing" >&2
    exit 1
  fi
fi
if [ ! -d tests/e2e/node_modules/playwright-core ] || [ ! -d tests/e2e/node_modules/axe-core ]; then
  (cd tests/e2e && { npm ci --no-audit --no-fund || npm install --no-audit --no-fund; })
fi
