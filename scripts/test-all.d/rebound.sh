#!/usr/bin/env bash
# rime's exported REBOUND collision handler checked inside REBOUND (pinned, in a local venv).
set -euo pipefail
cd "$(dirname "$0")/../.."
venv=target/venv-rebound
version=5.2.2
if ! "$venv/bin/python" -c "import rebound, sys; sys.exit(rebound.__version__ != '$version')" 2>/dev/null; then
  python3 -m venv "$venv"
  "$venv/bin/pip" install -q "rebound==$version"
fi
rime="${CARGO_TARGET_DIR:-target}/release/rime"
# make test's build step built it; run alone, build it the same way (nothing is built twice)
[ -x "$rime" ] || cargo build --locked -q --release --workspace
out=target/rebound-check
rm -rf "$out"
"$rime" export --preset ice --accuracy precise --out "$out/ice" >/dev/null
"$rime" export --preset ice-sticky --accuracy precise --out "$out/sticky" >/dev/null
exec "$venv/bin/python" tests/rebound/check.py "$rime" "$out/ice" "$out/sticky"
