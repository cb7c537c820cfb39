#!/usr/bin/env bash
# Installs the wasm32 target and wasm-bindgen-cli at Cargo.lock's wasm-bindgen version, unless they are
# there. No prebuilt binary of the pinned version is reachable from this network, so the first run
# builds it (`cargo install`, about 4 minutes); every later run finds it and returns at once.
set -euo pipefail
cd "$(dirname "$0")/.."
rustup target list --installed 2>/dev/null | grep -qx wasm32-unknown-unknown ||
  rustup target add wasm32-unknown-unknown
want=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/"/, "", $3); print $3; exit }' Cargo.lock)
if [ -z "$want" ]; then
  echo "setup-wasm-bindgen: no wasm-bindgen in Cargo.lock" >&2
  exit 1
fi
have=$(wasm-bindgen --version 2>/dev/null | awk '{ print $2 }' || true)
if [ "$have" != "$want" ] || ! command -v wasm-bindgen-test-runner >/dev/null; then
  echo "setup-wasm-bindgen: installing wasm-bindgen-cli $want (have: ${have:-none})"
  cargo install wasm-bindgen-cli --version "$want"
fi
