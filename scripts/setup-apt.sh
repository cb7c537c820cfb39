#!/usr/bin/env bash
# Installs the Debian packages the checks need when they are missing (as root, with apt): chromium and
# chromium-driver (the page's tests), tmux (the terminal's end-to-end test), nodejs and npm (the
# page's end-to-end test), gfortran (DustPy 1.0.9 is built from its source by setup-python.sh, issue
# 39). Skips what is there; without root it names what is missing and fails.
set -euo pipefail
missing=()
command -v chromium >/dev/null || missing+=(chromium)
command -v chromedriver >/dev/null || missing+=(chromium-driver)
command -v tmux >/dev/null || missing+=(tmux)
command -v node >/dev/null || missing+=(nodejs)
command -v npm >/dev/null || missing+=(npm)
command -v gfortran >/dev/null || missing+=(gfortran)
[ "${#missing[@]}" -eq 0 ] && exit 0
if [ "$(id -u)" -ne 0 ] || ! command -v apt-get >/dev/null; then
  echo "setup-apt: missing ${missing[*]}; install them (apt-get install ${missing[*]})" >&2
  exit 1
fi
echo "setup-apt: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get install -y "${missing[@]}" || { apt-get update && apt-get install -y "${missing[@]}"; }
