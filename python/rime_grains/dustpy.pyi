"""Type stubs of rime_grains.dustpy (DustPy's side in cgs; the scene and fit in SI)."""
from typing import Any, Literal, Optional, TypedDict, Union

import numpy as np
import numpy.typing as npt

from . import Scene

DUSTPY_VERSION: str
NOT_MODELLED: tuple[str, ...]

class DensityWarning(UserWarning): ...
class GammaRangeWarning(UserWarning): ...

class Fit(TypedDict):
    radius: float
    temperature: float
    speed: float
    source: str

class CacheInfo(TypedDict):
    updates: int
    tables: int
    hits: int
    misses: int
    maxsize: int
    seconds: float

class Attachment:
    provenance: dict[str, Any]
    temperatures: npt.NDArray[np.float64]
    gamma_ranges: list[str]
    @property
    def density(self) -> float: ...
    def p_stick(self, sim: Any) -> npt.NDArray[np.float64]: ...
    def p_frag_step(self, sim: Any) -> npt.NDArray[np.float64]: ...
    def v_stick(self, temperature: float) -> npt.NDArray[np.float64]: ...
    def cache_info(self) -> CacheInfo: ...
    def detach(self) -> None: ...

def import_offline() -> Any: ...

def attach(sim: Any, scene: Optional[Scene], *,
           a_rule: Literal["given", "keep_epsilon", "fit_measured"] = ...,
           fit: Optional[Fit] = ...,
           temperature_rule: Literal["hold", "refuse"] = ...,
           convention: Literal["surface", "adhesion"] = ...,
           accuracy: str = ...,
           velocity_distribution: Literal["maxwell", "none"] = ...,
           v_frag: Optional[Union[float, npt.ArrayLike]] = ...,
           v_frag_source: Optional[str] = ...,
           v_stick: Optional[float] = ...,
           temperature_step: float = ...,
           cache_size: int = ...) -> Attachment: ...
