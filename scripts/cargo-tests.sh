#!/usr/bin/env bash
# Runs a `cargo test` command (native or wasm32) and prints "count: N passed, M failed" from its
# "test result:" lines, so that make test counts each Rust test; a failed run ends with its failing
# tests. Exits with cargo's status.
set -uo pipefail
out=$(mktemp)
"$@" 2>&1 | tee "$out"
rc=${PIPESTATUS[0]}
awk '/^test result:/ { for (i = 1; i < NF; i++) { if ($(i+1) ~ /^passed/) p += $i; if ($(i+1) ~ /^failed/) f += $i } }
     END { printf "count: %d passed, %d failed\n", p, f }' "$out"
if [ "$rc" -ne 0 ]; then
  echo "--- failures"
  grep -E 'FAILED|panicked|error(\[|:)' -A12 "$out" | head -n 120
fi
rm -f "$out"
exit "$rc"
