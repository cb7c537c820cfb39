#!/usr/bin/env bash
# The Python test environment: one virtual environment at target/venv with every package of
# python/requirements-test.txt at its pinned version. Idempotent: installs only what is missing or
# at another version (pip is not even started when everything matches).
set -euo pipefail
cd "$(dirname "$0")/.."
venv=target/venv
requirements=python/requirements-test.txt
if [ ! -x "$venv/bin/python" ]; then
  python3 -m venv "$venv"
fi
missing=$("$venv/bin/python" - "$requirements" <<'PY'
import sys
from importlib import metadata
wanted = []
for line in open(sys.argv[1], encoding="utf-8"):
    line = line.split("#", 1)[0].strip()
    if line:
        name, version = line.split("==")
        wanted.append((name.strip(), version.strip()))
for name, version in wanted:
    try:
        ok = metadata.version(name) == version
    except metadata.PackageNotFoundError:
        ok = False
    if not ok:
        print(f"{name}=={version}")
PY
)
if [ -n "$missing" ]; then
  # DustPy ships as source only and its build needs a Fortran compiler: install it (as root) or
  # say what is missing, before pip fails deep inside meson.
  if echo "$missing" | grep -q '^dustpy==' && ! command -v gfortran >/dev/null; then
    scripts/setup-apt.sh
  fi
  echo "setup-python: installing $(echo $missing | tr '\n' ' ')"
  # REBOUNDx links librebound through a run path to the site-packages it was built for: a wheel
  # from pip's cache, built for another virtual environment, cannot load it. So REBOUNDx is built
  # here for this one (about 5 s), after rebound is in place, and never taken from the cache.
  others=$(echo "$missing" | grep -v '^reboundx==' || true)
  reboundx=$(echo "$missing" | grep '^reboundx==' || true)
  if [ -n "$others" ]; then
    # shellcheck disable=SC2086
    "$venv/bin/python" -m pip install -q --disable-pip-version-check $others
  fi
  if [ -n "$reboundx" ]; then
    "$venv/bin/python" -m pip install -q --disable-pip-version-check --no-binary reboundx \
      --no-cache-dir "$reboundx"
  fi
fi
