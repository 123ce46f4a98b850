"""Type stubs of the compiled core ``stickiness._core`` (see the package for the documented API).

Every vectorised function takes flat float64 arrays of one length (the broadcast arguments) and
returns flat arrays (NaN where a value does not exist) with a ``"warnings"`` list of
``(index, kind, message)``; ``crack_speed`` and ``t_vis_law`` return a bare array. A number
argument may also be one Python float (an array of one element); a call of ``jkr``,
``dimensionless``, ``v_stick``, ``v_frag`` or ``fit_t_vis`` whose number arguments are all floats
returns floats (and an int ``method``) instead of arrays. All quantities are SI.
"""

from os import PathLike
from typing import Any, Dict, List, Optional, Tuple, TypedDict, Union, final

import numpy as np
import numpy.typing as npt

__all__ = [
    "DEFAULT_K",
    "DEFAULT_RADIUS",
    "DEFAULT_REL_TOL",
    "Material",
    "SWEEP_COLUMNS",
    "SolverError",
    "T_VIS_EXPONENT",
    "_InputError",
    "__version__",
    "collide",
    "crack_speed",
    "dimensionless",
    "fit_t_vis",
    "jkr",
    "parallel_batch",
    "sweep",
    "t_vis_law",
    "t_vis_law_mismatch",
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
#: Exponent of the size laws T_vis ~ R1^1.11 (Section 5.3, Gundlach et al. 2015).
T_VIS_EXPONENT: float
#: The columns of a sweep's rows, as the CLI's CSV header.
SWEEP_COLUMNS: List[str]

_F = npt.NDArray[np.float64]
#: A number argument: a flat float64 array, or one float (an array of one element).
_N = Union[float, _F]
#: A column of a result: an array, or a float when every number argument was a float.
_C = Union[float, _F]
#: A "method" column likewise (an int for a call of floats).
_M = Union[int, npt.NDArray[np.uint8]]
_Warnings = List[Tuple[int, str, str]]

class SolverError(RuntimeError):
    """A computation failed; the message names the parameters and where the solver stopped."""

class _InputError(ValueError):
    """Bad input at one element: the message names the argument; ``field``, ``index`` (flat)
    and ``rest`` (the message after the name) let the package name the element."""

    field: str
    index: int
    rest: str

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

class JkrColumns(TypedDict):
    """The columns of :func:`jkr` (flat arrays, SI)."""

    a_eq: _C  # equilibrium contact radius (m)
    delta_eq: _C  # equilibrium mutual approach (m)
    tabor: _C  # Tabor parameter (dimensionless)
    f_crit: _C  # pull-off force (N)
    delta_crit: _C  # critical pulling length (m)
    e_stick: _C  # E_stick,JKR (J)
    e_break: _C  # E_break,JKR (J)
    v_stick_jkr: _C  # V_stick,JKR (m/s)
    warnings: _Warnings

class DimensionlessColumns(TypedDict):
    """The columns of :func:`dimensionless` (flat arrays)."""

    c_d: _C  # drag number c_D (dimensionless)
    c_a: _C  # crack-speed number c_a (dimensionless)
    t0: _C  # JKR time unit (s)
    warnings: _Warnings

class CollisionColumns(TypedDict, total=False):
    """The columns of :func:`collide` (flat, SI)."""

    outcome: List[str]  # 'sticking', 'double' or 'bouncing'
    e: _F  # -V_out/V_in (dimensionless)
    e_observed: _F  # e as observed: e of bouncing, 0 for sticking and double collisions
    v_out: _F  # approach speed at the end of contact (m/s)
    contact_time: _F  # duration of the contact (s; NaN for sticking)
    v_stick_jkr: _F  # V_stick,JKR (m/s)
    sticking_criterion: List[Optional[str]]  # 'energy_bound', 'oscillations' or None
    warnings: _Warnings
    trajectory: Dict[str, _F]  # t (s), a, delta (m), delta_dot (m/s), energy (J), beta
    method: npt.NDArray[np.uint8]  # 0: the ODE, 1: the restitution tables

class VStickColumns(TypedDict):
    """The columns of :func:`v_stick` (flat, m/s; NaN where none)."""

    v_stick: _C  # V_stick (m/s)
    v_double_onset: _C  # V_double_onset (m/s)
    v_stick_jkr: _C  # V_stick,JKR (m/s)
    no_bouncing_below: _C  # the search limit without bouncing (m/s)
    v_max: _C  # the highest speed searched (m/s)
    method: _M  # 0: the search answered, 1: the table
    warnings: _Warnings

class VFragColumns(TypedDict):
    """The columns of :func:`v_frag` (flat; NaN where none)."""

    v_frag: _C  # V_frag = 10 V_stick (m/s)
    v_stick: _C  # V_stick (m/s)
    t_vis: _C  # the relaxation time used (s)
    v_frag_jkr: _C  # V_frag,JKR (m/s)
    v_stick_jkr: _C  # V_stick,JKR (m/s)
    no_bouncing_below: _C  # the search limit without bouncing (m/s)
    method: _M  # 0: the search answered, 1: the table
    warnings: _Warnings

class FitColumns(TypedDict):
    """The columns of :func:`fit_t_vis` (flat)."""

    t_vis: _C  # T_vis for V_stick (s)
    t_vis_min: _C  # T_vis for V_stick - dV (s; 0 at or below V_stick,JKR)
    t_vis_max: _C  # T_vis for V_stick + dV (s)
    v_stick_jkr: _C  # V_stick,JKR (m/s)
    method: _M  # 1 when the table gave every V_stick, else 0
    warnings: _Warnings

def crack_speed(k: _N, beta: _N) -> _F: ...
def t_vis_law(law: str, radius: _N) -> _F: ...
def t_vis_law_mismatch(law: str, material: Material) -> Optional[str]: ...
def parallel_batch() -> int: ...
def jkr(material: Material, radius: _N, radius2: Optional[_N], wall: bool) -> JkrColumns: ...
def dimensionless(
    material: Material,
    radius: _N,
    radius2: Optional[_N],
    wall: bool,
    t_vis: _N,
    gamma_sv: Optional[_N] = None,
) -> DimensionlessColumns: ...
def collide(
    material: Material,
    radius: _N,
    radius2: Optional[_N],
    wall: bool,
    t_vis: _N,
    v_in: _N,
    k: _N,
    t_end: Optional[float],
    trajectory: bool,
    method: str = "search",
    gamma_sv: Optional[_N] = None,
) -> CollisionColumns: ...
def v_stick(
    material: Material,
    radius: _N,
    radius2: Optional[_N],
    wall: bool,
    t_vis: _N,
    k: _N,
    v_max: Optional[float],
    rel_tol: float,
    method: str,
    gamma_sv: Optional[_N] = None,
) -> VStickColumns: ...
def fit_t_vis(
    material: Material,
    radius: _N,
    radius2: Optional[_N],
    wall: bool,
    v_stick: _N,
    v_stick_err: _N,
    k: _N,
    v_max: Optional[float],
    rel_tol: float,
    method: str,
    gamma_sv: Optional[_N] = None,
) -> FitColumns: ...
def v_frag(
    material: Material,
    radius: _N,
    radius2: Optional[_N],
    wall: bool,
    t_vis: _N,
    k: _N,
    v_max: Optional[float],
    rel_tol: float,
    method: str,
    gamma_sv: Optional[_N] = None,
) -> VFragColumns: ...
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
    method: str = "table",
) -> Dict[str, Any]: ...
