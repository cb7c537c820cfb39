#!/usr/bin/env bash
# Builds the web explorer: the wasm module into www/pkg (wasm-bindgen --target web). `make www`.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --target wasm32-unknown-unknown --release -p rime-wasm
# Honour CARGO_TARGET_DIR (a worktree may build into its own target directory).
target_dir=${CARGO_TARGET_DIR:-target}
wasm-bindgen --target web --no-typescript --out-dir www/pkg \
  "$target_dir/wasm32-unknown-unknown/release/rime_wasm.wasm"
raw=$(stat -c %s www/pkg/rime_wasm_bg.wasm)
gz=$(gzip -9 -c www/pkg/rime_wasm_bg.wasm | wc -c)
echo "www/pkg/rime_wasm_bg.wasm: $raw bytes raw, $gz bytes gzipped"
