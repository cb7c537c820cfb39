"""Shared helpers: the `rime` command-line binary (an independent path to the core's numbers)."""
import json
import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


def rime_binary():
    path = pathlib.Path(os.environ.get("RIME_BIN", ROOT / "target" / "release" / "rime"))
    if not path.exists():
        pytest.fail(f"the rime binary {path} is missing: cargo build --release -p rime-tui")
    return str(path)


def cli(*args):
    """Runs `rime ARGS --format json` and returns the parsed JSON."""
    out = subprocess.run([rime_binary(), *map(str, args), "--format", "json"], check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out)


@pytest.fixture
def rime_cli():
    return cli


def import_dustpy_offline():
    """Imports DustPy without its network check: `import dustpy` (1.0.9) opens a socket to
    8.8.8.8 and asks PyPI for a newer version, leaves that socket unclosed (a ResourceWarning) and
    the process's default socket timeout at 0.5 s. Here the connection is refused (DustPy then
    skips the check), and the default timeout is put back."""
    import socket
    import sys
    import warnings

    if "dustpy" in sys.modules:
        return sys.modules["dustpy"]
    connect, timeout = socket.socket.connect, socket.getdefaulttimeout()

    def refuse(self, address):
        raise OSError("tests: no network for DustPy's version check")

    socket.socket.connect = refuse
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ResourceWarning)
            import dustpy
    finally:
        socket.socket.connect = connect
        socket.setdefaulttimeout(timeout)
    return dustpy


import_dustpy_offline()
