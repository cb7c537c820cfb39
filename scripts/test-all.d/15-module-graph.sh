#!/usr/bin/env bash
# The core has no import circle (issue 36): modules at every depth up to 3 (core/src/a/b/c).
set -euo pipefail
cd "$(dirname "$0")/../.."
for depth in 1 2 3; do
  python3 scripts/module-graph.py core/src "$depth"
done
