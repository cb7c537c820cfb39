"""The native module (use the rime_grains package instead)."""
from typing import Any
from . import Scene as Scene

REBOUND_VERSION: str
__version__: str
def __getattr__(name: str) -> Any: ...
