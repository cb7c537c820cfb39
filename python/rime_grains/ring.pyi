from typing import Any, Optional, Sequence

from ._native import Scene

def equilibrium(scene: Scene, *, tau: float, omega: Optional[float] = ...,
                planet_mass: Optional[float] = ..., distance: Optional[float] = ...,
                radius: Optional[float] = ..., scale_damping: bool = ...,
                damping_set_for: Optional[float] = ..., radius_min: Optional[float] = ...,
                radius_max: Optional[float] = ..., q: Optional[float] = ..., bins: int = ...,
                radii: Optional[Sequence[float]] = ..., fractions: Optional[Sequence[float]] = ...,
                damping_rule: str = ...) -> dict[str, Any]: ...
def scaled_damping_time(damping_time: float, radius: float, new_radius: float) -> float: ...
