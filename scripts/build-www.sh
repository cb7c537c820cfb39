#!/usr/bin/env bash
# Builds the web explorer: the wasm module into www/pkg (wasm-bindgen --target web) and the physics
# notes into www/physics.html. `make www`.
set -euo pipefail
cd "$(dirname "$0")/.."
# The wasm-release profile (Cargo.toml): the release profile with LTO, one codegen unit and no debug
# info, so the module is smaller and as fast; the function-name section is not shipped either.
# Without the `batch` feature: the page does not call `epsNBatch`, whose table is 98 KB of the module.
cargo build --locked --target wasm32-unknown-unknown --profile wasm-release -p rime-wasm --no-default-features
# Honour CARGO_TARGET_DIR (a worktree may build into its own target directory).
target_dir=${CARGO_TARGET_DIR:-target}
wasm-bindgen --target web --no-typescript --remove-name-section --remove-producers-section \
  --out-dir www/pkg "$target_dir/wasm32-unknown-unknown/wasm-release/rime_wasm.wasm"
raw=$(stat -c %s www/pkg/rime_wasm_bg.wasm)
gz=$(gzip -9 -c www/pkg/rime_wasm_bg.wasm | wc -c)
echo "www/pkg/rime_wasm_bg.wasm: $raw bytes raw, $gz bytes gzipped"
# The physics notes, served beside the page: its "Eq. (N)" and "decision N" links point at their
# anchors (www/physics.html#decision-2), so they work on any static server, offline included.
cargo run --locked -q --release -p rime-docs-page -- docs/physics.md www/physics.html
echo "www/physics.html: $(grep -c '<a id=' www/physics.html) anchors"
