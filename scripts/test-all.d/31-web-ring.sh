#!/usr/bin/env bash
# The page's ring card (issue 24) against `rime ring`: builds www/ (cached after the web step),
# serves it on a free local port and runs tests/e2e/ring.mjs in headless Chromium (the card's
# printed numbers read back as the CLI's to their printed digits; the verdict in the CLI's words; a
# bad τ named; the ε_cr line, meeting point and impact-speed marker on the ε_N chart; the card's
# inputs in the link, a bad one named).
set -euo pipefail
cd "$(dirname "$0")/../.."

scripts/setup-web.sh # make test's setup steps did this; run alone, this step installs what it needs
scripts/build-www.sh >/dev/null
rime_bin=$(scripts/rime-bin.sh)
source scripts/serve-www.sh # sets port; the server stops on exit
out=$(mktemp)
rc=0
RIME_BIN=${RIME_BIN:-$rime_bin} node tests/e2e/ring.mjs "http://127.0.0.1:$port/" | tee "$out" || rc=$?
# Each check counts as one test of make test.
echo "count: $(grep -c '^PASS' "$out") passed, $(grep -c '^FAIL' "$out") failed"
rm -f "$out"
exit "$rc"
