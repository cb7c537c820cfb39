#!/usr/bin/env bash
# rime's exported REBOUND collision handler (the `rime export` C route) checked inside REBOUND
# (pinned in python/requirements-test.txt, in the shared test venv target/venv).
set -euo pipefail
cd "$(dirname "$0")/../.."
scripts/setup-python.sh
venv=target/venv
rime="${CARGO_TARGET_DIR:-target}/release/rime"
# make test's build step built it; run alone, build it the same way (nothing is built twice)
[ -x "$rime" ] || cargo build --locked -q --release --workspace
out=target/rebound-check
rm -rf "$out"
"$rime" export --preset ice --accuracy precise --out "$out/ice" >/dev/null
"$rime" export --preset ice-sticky --accuracy precise --out "$out/sticky" >/dev/null
exec "$venv/bin/python" tests/rebound/check.py "$rime" "$out/ice" "$out/sticky"
