#!/usr/bin/env bash
# Installs what the web tests need on a fresh machine; skips what is already there: the wasm32
# target and wasm-bindgen-cli (setup-wasm-bindgen.sh), chromium, chromedriver, node and npm
# (setup-apt.sh, as root), playwright-core and axe-core (setup-npm.sh). `make test` runs these as
# its setup steps; the web step calls this again so that it also runs on its own.
set -euo pipefail
cd "$(dirname "$0")"
./setup-wasm-bindgen.sh
./setup-apt.sh
./setup-npm.sh
