"""Type stubs of rime_grains.data."""
from typing import Any, Callable, Optional, Union

import numpy as np
import numpy.typing as npt

def laws() -> list[dict[str, Any]]: ...
def law(id: str) -> Callable[..., Union[float, npt.NDArray[np.float64]]]:
    """law(id)(g, radius=None): ε_N of the measured law at speeds g [m/s]."""
