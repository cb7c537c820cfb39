#!/usr/bin/env bash
# End-to-end test of the terminal explorer: the real binary (make test's release build) driven in tmux.
set -euo pipefail
cd "$(dirname "$0")/../.."
scripts/setup-apt.sh
exec tui/tests/e2e_tmux.sh "$(scripts/rime-bin.sh)"
