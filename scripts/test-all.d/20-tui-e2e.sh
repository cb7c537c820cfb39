#!/usr/bin/env bash
# End-to-end test of the terminal explorer: the real binary (make test's release build) driven in tmux.
set -euo pipefail
cd "$(dirname "$0")/../.."
scripts/setup-apt.sh
bin=${CARGO_TARGET_DIR:-target}/release/rime
# Run alone, build what make test's build step builds (the same features, so nothing is built twice).
[ -x "$bin" ] || cargo build --locked -q --release --workspace
exec tui/tests/e2e_tmux.sh "$PWD/$bin"
