#!/usr/bin/env bash
# Installs the Rust targets (no_std, wasm32) and components (clippy, rustfmt) make test needs;
# skips what is already there. The other setup-*.sh scripts install the rest.
set -euo pipefail
have_target() { rustup target list --installed 2>/dev/null | grep -qx "$1"; }
for t in thumbv7em-none-eabihf wasm32-unknown-unknown; do
  have_target "$t" || rustup target add "$t"
done
rustup component list --installed 2>/dev/null | grep -q '^clippy' || rustup component add clippy
rustup component list --installed 2>/dev/null | grep -q '^rustfmt' || rustup component add rustfmt
