#!/usr/bin/env bash
# Installs the page's end-to-end test tools (playwright-core, axe-core) into tests/e2e from its lock
# file, unless they are there.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ ! -d tests/e2e/node_modules/playwright-core ] || [ ! -d tests/e2e/node_modules/axe-core ]; then
  (cd tests/e2e && { npm ci --no-audit --no-fund || npm install --no-audit --no-fund; })
fi
