#!/usr/bin/env bash
# rime's exported REBOUND collision handler (the `rime export` C route) checked inside REBOUND
# (pinned in python/requirements-test.txt, in the shared test venv target/venv).
set -euo pipefail
cd "$(dirname "$0")/../.."
scripts/setup-python.sh
venv=target/venv
rime=$(scripts/rime-bin.sh)
out=target/rebound-check
rm -rf "$out"
"$rime" export --preset ice --accuracy precise --out "$out/ice" >/dev/null
"$rime" export --preset ice-sticky --accuracy precise --out "$out/sticky" >/dev/null
exec "$venv/bin/python" tests/rebound/check.py "$rime" "$out/ice" "$out/sticky"
