#!/usr/bin/env bash
# Prints the path of the `rime` binary that make test's build step built (CARGO_TARGET_DIR honoured).
# Run alone, a step builds it as that step does (`cargo test --no-run`), so no second feature set of
# the core and the terminal is compiled.
set -euo pipefail
cd "$(dirname "$0")/.."
bin="${CARGO_TARGET_DIR:-target}/release/rime"
[ -x "$bin" ] || cargo test --locked --release --workspace --no-run >&2
realpath "$bin"
