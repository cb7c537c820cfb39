"""Type stubs of rime_grains (SI units throughout)."""
from typing import Any, Literal, Optional, Sequence, TypedDict, Union, overload

import numpy as np
import numpy.typing as npt

from . import data as data
from . import dustpy as dustpy
from . import rebound as rebound
from . import ring as ring

Accuracy = Union[Literal["fast", "balanced", "precise", "integrated"], str]
ArrayLike = npt.ArrayLike
Speeds = npt.NDArray[np.float64]

ACCURACY_LEVELS: tuple[str, ...]
__version__: str

class Scene:
    """A collision scene: two grains, the bulk, optional layer, adhesion and friction."""
    def __init__(self) -> None: ...
    @staticmethod
    def preset(name: str) -> Scene: ...
    @staticmethod
    def presets() -> list[str]: ...
    @staticmethod
    def from_json(text: str) -> Scene: ...
    @staticmethod
    def keys() -> list[tuple[str, str]]: ...
    def to_json(self) -> str: ...
    def set(self, key: str, value: Union[float, int, str, bool]) -> None: ...
    def get(self, key: str) -> Union[float, str, bool, None]: ...
    def copy(self) -> Scene: ...
    def __copy__(self) -> Scene: ...
    def __eq__(self, other: object) -> bool: ...

@overload
def eps_n(g: float, scene: Scene, accuracy: Accuracy = ...) -> float: ...
@overload
def eps_n(g: ArrayLike, scene: Scene, accuracy: Accuracy = ...) -> Union[float, Speeds]: ...
def eps_t(g_n: ArrayLike, g_t: ArrayLike, scene: Scene, accuracy: Accuracy = ...) -> Union[float, Speeds]: ...


def tangential(g_n: ArrayLike, g_t: ArrayLike, scene: Scene, accuracy: Accuracy = ...) -> dict[str, Any]: ...
def collision(g: float, scene: Scene, g_t: Optional[float] = ..., points: int = ...,
              accuracy: Accuracy = ...) -> dict[str, Any]: ...

class Thresholds(TypedDict):
    layer: Optional[float]
    adhesion: Optional[float]
    stick: Optional[float]

def thresholds(scene: Scene, accuracy: Accuracy = ...) -> Thresholds: ...
def compare(models: Sequence[str], g: ArrayLike, scene: Scene,
            accuracy: Accuracy = ...) -> dict[str, Union[float, Speeds]]: ...

class Kernel(TypedDict):
    radii: npt.NDArray[np.float64]
    temperatures: npt.NDArray[np.float64]
    v_stick: npt.NDArray[np.float64]
    status: npt.NDArray[np.str_]
    gammas: list[dict[str, Any]]
    a_rule: str
    damping_time: float
    fit: Optional[dict[str, Any]]
    convention: str
    temperature_rule: str
    method: str
    gamma_entry: str
    measured_range: list[float]

def kernel(radii: ArrayLike, temperatures: ArrayLike, scene: Scene, *,
           a_rule: Literal["given", "keep_epsilon", "fit_measured"] = ...,
           fit: Optional[dict[str, Union[float, str]]] = ...,
           temperature_rule: Literal["hold", "refuse"] = ...,
           convention: Literal["surface", "adhesion"] = ...,
           accuracy: Accuracy = ...) -> Kernel: ...
