"""Type stubs of the compiled core ``stickiness._core`` (see the package for the documented API).

Every vectorised function takes flat float64 arrays of one length (the broadcast arguments) and
returns flat arrays (NaN where a value does not exist) with a ``"warnings"`` list of
``(index, kind, message)``; ``crack_speed`` and ``t_vis_law`` return a bare array. All quantities
are SI.
"""

from os import PathLike
from typing import Any, Dict, List, Optional, Tuple, Union, final

import numpy as np
import numpy.typing as npt

__all__ = [
    "DEFAULT_K",
    "DEFAULT_RADIUS",
    "DEFAULT_REL_TOL",
    "Material",
    "SWEEP_COLUMNS",
    "SolverError",
    "_InputError",
    "__version__",
    "collide",
    "crack_speed",
    "fit_t_vis",
    "jkr",
    "parallel_batch",
    "sweep",
    "t_vis_law",
    "v_frag",
    "v_stick",
]
__version__: str
#: Default radius R1 (m): the typical CO2 grain of Musiolik et al. (2016a).
DEFAULT_RADIUS: float
#: Default modulus ratio k (dimensionless): the paper's fiducial value.
DEFAULT_K: float
#: Default relative width of the threshold brackets (dimensionless).
DEFAULT_REL_TOL: float
#: The columns of a sweep's rows, as the CLI's CSV header.
SWEEP_COLUMNS: List[str]

_F = npt.NDArray[np.float64]
_Warnings = List[Tuple[int, str, str]]

class SolverError(RuntimeError):
    """A computation failed; the message names the parameters and where the solver stopped."""

class _InputError(ValueError):
    """Bad input at one element: args are (argument, flat index, message after the name)."""

@final
class Material:
    """The four material constants (SI): gamma_sv (J/m^2), young (Pa), poisson, density (kg/m^3)."""

    def __new__(cls, gamma_sv: float, young: float, poisson: float, density: float) -> Material: ...
    @staticmethod
    def co2() -> Material: ...
    @staticmethod
    def h2o() -> Material: ...
    @staticmethod
    def named(name: str) -> Material: ...
    @staticmethod
    def from_json(path: Union[str, PathLike[str]]) -> Material: ...
    def replace(
        self,
        *,
        gamma_sv: Optional[float] = None,
        young: Optional[float] = None,
        poisson: Optional[float] = None,
        density: Optional[float] = None,
    ) -> Material: ...
    @property
    def gamma_sv(self) -> float: ...
    @property
    def young(self) -> float: ...
    @property
    def poisson(self) -> float: ...
    @property
    def density(self) -> float: ...
    def __eq__(self, value: object, /) -> bool: ...
    def __hash__(self) -> int: ...
    def __reduce__(self) -> Tuple[type, Tuple[float, float, float, float]]: ...

def crack_speed(k: _F, beta: _F) -> _F: ...
def t_vis_law(law: str, radius: _F) -> _F: ...
def jkr(material: Material, radius: _F, radius2: Optional[_F], wall: bool) -> Dict[str, Any]: ...
def collide(
    material: Material,
    radius: _F,
    radius2: Optional[_F],
    wall: bool,
    t_vis: _F,
    v_in: _F,
    k: _F,
    t_end: Optional[float],
    trajectory: bool,
) -> Dict[str, Any]: ...
def v_stick(
    material: Material,
    radius: _F,
    radius2: Optional[_F],
    wall: bool,
    t_vis: _F,
    k: _F,
    v_max: Optional[float],
    rel_tol: float,
) -> Dict[str, Any]: ...
def fit_t_vis(
    material: Material,
    radius: _F,
    radius2: Optional[_F],
    wall: bool,
    v_stick: _F,
    v_stick_err: _F,
    k: _F,
    v_max: Optional[float],
    rel_tol: float,
) -> Dict[str, Any]: ...
def v_frag(
    material: Material,
    radius: _F,
    radius2: Optional[_F],
    wall: bool,
    t_vis: _F,
    k: _F,
    v_max: Optional[float],
    rel_tol: float,
) -> Dict[str, Any]: ...
def sweep(
    materials: List[Tuple[str, Material]],
    gamma_sv: Optional[List[float]],
    radius: List[float],
    radius2: Optional[List[float]],
    wall: bool,
    t_vis: Optional[List[float]],
    t_vis_law: Optional[str],
    k: List[float],
    v_max: Optional[float],
    rel_tol: float,
    chunks: Optional[List[int]] = None,
) -> Dict[str, Any]: ...

def parallel_batch() -> int: ...
