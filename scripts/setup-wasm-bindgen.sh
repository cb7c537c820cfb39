#!/usr/bin/env bash
# Installs the wasm32 target and wasm-bindgen-cli at Cargo.lock's wasm-bindgen version, unless they are
# there. No prebuilt binary of the pinned version is reachable from this network, so the first run
# builds it (`cargo install`); every later run finds it and returns at once. Without its default
# features: they add TLS (rustls and ring, with its C build), and the test runner only talks to a
# chromedriver on this machine over plain HTTP (issue 34: 257 s of CPU instead of 291 s, user+sys;
# the same bytes from `wasm-bindgen` on the page's wasm, the same wasm tests passing). A debug build
# (`--debug`, 135 s of CPU) was measured too and not taken: it runs about 3× slower (the page's
# bindgen 4.5 s instead of 1.5 s, the wasm tests' runner about 20 s more), which every later
# `make test` would pay.
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
  cargo install wasm-bindgen-cli --version "$want" --no-default-features
fi
