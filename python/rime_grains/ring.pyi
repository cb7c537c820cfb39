from typing import Any, Optional

from ._native import Scene

def equilibrium(scene: Scene, *, tau: float, omega: Optional[float] = ...,
                planet_mass: Optional[float] = ..., distance: Optional[float] = ...,
                radius: Optional[float] = ..., scale_damping: bool = ...,
                damping_set_for: Optional[float] = ...) -> dict[str, Any]: ...
def scaled_damping_time(damping_time: float, radius: float, new_radius: float) -> float: ...
