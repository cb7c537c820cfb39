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
    """DustPy without its network check (the package's `rime_grains.dustpy.import_offline`)."""
    from rime_grains.dustpy import import_offline

    return import_offline()


import_dustpy_offline()
