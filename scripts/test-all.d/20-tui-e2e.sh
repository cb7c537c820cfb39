#!/usr/bin/env bash
# End-to-end test of the terminal explorer: the real binary driven in tmux.
set -euo pipefail
cd "$(dirname "$0")/../.."
if ! command -v tmux >/dev/null 2>&1; then
  if [ "$(id -u)" = 0 ]; then
    apt-get install -y tmux >/dev/null 2>&1 || { apt-get update >/dev/null && apt-get install -y tmux >/dev/null; }
  else
    echo "tmux is not installed and we are not root" >&2; exit 1
  fi
fi
cargo build -q --release -p rime-tui
exec tui/tests/e2e_tmux.sh "$PWD/target/release/rime"
