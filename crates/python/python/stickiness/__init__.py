"""Do two colliding dust or ice grains stick or bounce?

The viscoelastic contact model of Krijt et al. (2013) as reviewed and applied by Arakawa &
Krijt (2021, "On the stickiness of CO2 and H2O ice particles"), compiled from the Rust
reference implementation. Every input and output is SI: radii in m, times in s, speeds in
m/s, gamma_sv in J/m^2, young in Pa, density in kg/m^3.

Quick start::

    import numpy as np, stickiness as st
    co2 = st.Material.co2()
    st.v_stick(co2, radius=60e-6, t_vis=1e-9).v_stick        # 0.04137... m/s (Section 4.4)
    r = st.v_stick(co2, radius=60e-6, t_vis=np.geomspace(1e-12, 1e-8, 33))
    r.v_stick                                                 # ndarray of shape (33,)

Arguments that are numbers (``radius``, ``radius2``, ``t_vis``, ``v_in``, ``k``, ``beta``,
``v_stick``, ``v_stick_err``) broadcast like numpy: scalars in give Python floats out, arrays
in give ndarrays of the broadcast shape. Array calls release the GIL, run on all cores, and
stop on Ctrl-C within about a second.

Where a threshold does not exist, its value is NaN: ``v_stick`` (and ``v_double_onset``,
``v_frag``) when no collision bounces up to the search limit, which ``no_bouncing_below``
then holds (NaN where bouncing was found); in arrays, ``contact_time`` of a sticking
collision (``None`` for a single one). No other result is ever NaN.

Errors: bad input raises ``ValueError`` naming the argument and, for arrays, the element
(``radius[1] = nan: must be > 0 and finite (m)``); arguments of the wrong type raise
``TypeError``; a failed computation raises :class:`SolverError` (a ``RuntimeError``) naming the
parameters. A Tabor parameter below 1 (JKR theory outside its validity), a radius outside
10 nm - 1 cm and impact speeds above 1 km/s give a :class:`StickinessWarning`.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _core
from ._core import Material, SolverError, __version__

__all__ = [
    "Material",
    "SolverError",
    "StickinessWarning",
    "JKR",
    "Collision",
    "VStick",
    "TVisFit",
    "VFrag",
    "crack_speed",
    "jkr",
    "collide",
    "v_stick",
    "fit_t_vis",
    "v_frag",
    "t_vis_law",
    "sweep",
    "__version__",
]

#: A number or an array of numbers (anything ``numpy.asarray`` turns into real numbers).
ArrayLike = Union[float, int, Sequence[float], np.ndarray]
#: A Python float for scalar inputs, an ndarray of the broadcast shape for array inputs.
FloatOrArray = Union[float, np.ndarray]

#: Default radius R1 (m): the typical CO2 grain of Musiolik et al. (2016a), as the CLI's default.
DEFAULT_RADIUS: float = _core.DEFAULT_RADIUS
#: Default modulus ratio k (dimensionless): the paper's fiducial value (Section 2.3).
DEFAULT_K: float = _core.DEFAULT_K
#: Default relative tolerance of the threshold searches, as the CLI's.
DEFAULT_REL_TOL: float = _core.DEFAULT_REL_TOL


class StickinessWarning(UserWarning):
    """Valid input for which the model's results should be read with care.

    Raised for a Tabor parameter below 1 (JKR theory, on which the model stands, is outside
    its validity; Section 2.2), a radius outside 10 nm - 1 cm (likely a unit slip) and impact
    speeds above 1 km/s.
    """


# ---------------------------------------------------------------------------------------------
# arguments


def _float_array(name: str, value: Any) -> np.ndarray:
    """``value`` as a float64 array; ``TypeError`` naming ``name`` for anything not real numbers."""
    if isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name}: expected a number or an array of numbers, got a bool")
    try:
        a = np.asarray(value)
    except Exception as e:  # ragged lists and the like
        raise TypeError(f"{name}: expected a number or an array of numbers ({e})") from None
    if a.dtype.kind not in "iuf":
        raise TypeError(
            f"{name}: expected real numbers, got {type(value).__name__} of dtype {a.dtype}"
        )
    return a.astype(np.float64, copy=False)


class _Broadcast:
    """Number arguments broadcast together and flattened for the compiled core."""

    def __init__(self, **args: Any) -> None:
        arrays = {k: _float_array(k, v) for k, v in args.items() if v is not None}
        self.shapes: Dict[str, Tuple[int, ...]] = {k: a.shape for k, a in arrays.items()}
        try:
            views = np.broadcast_arrays(*arrays.values())
        except ValueError:
            shapes = ", ".join(f"{k} {s}" for k, s in self.shapes.items())
            raise ValueError(f"the arguments cannot be broadcast together: {shapes}") from None
        self.shape: Tuple[int, ...] = views[0].shape if views else ()
        self.flat: Dict[str, np.ndarray] = {
            k: np.ascontiguousarray(v, dtype=np.float64).reshape(-1)
            for k, v in zip(arrays, views)
        }
        self.scalar = all(len(s) == 0 for s in self.shapes.values())

    @property
    def size(self) -> int:
        return int(np.prod(self.shape)) if self.shape else 1

    def out(self, flat: Any) -> Any:
        """A flat result as a Python scalar (scalar inputs) or an array of the broadcast shape."""
        a = np.asarray(flat)
        if self.scalar:
            v = a.reshape(-1)[0]
            return v.item() if hasattr(v, "item") else v
        return a.reshape(self.shape)

    def name_at(self, field: str, flat: int) -> str:
        """``field`` with the index, in its own shape, of element ``flat`` of the broadcast."""
        shape = self.shapes.get(field, ())
        if not shape or not self.shape:
            return field
        full = np.unravel_index(flat, self.shape)
        offset = len(self.shape) - len(shape)
        own = [0 if shape[j] == 1 else int(full[offset + j]) for j in range(len(shape))]
        return f"{field}[{', '.join(map(str, own))}]"

    def call(self, fn: Any, *args: Any) -> Any:
        """Calls the core, turning its bad-input errors into ``ValueError`` naming the element."""
        try:
            return fn(*args)
        except _core._InputError as e:
            field, flat, rest = e.args
            raise ValueError(self.name_at(field, flat) + rest) from None

    def warn(self, found: List[Tuple[int, str, str]]) -> None:
        """One ``StickinessWarning`` per kind of warning found, naming the first element."""
        kinds: Dict[str, List[Tuple[int, str]]] = {}
        for index, kind, text in found:
            kinds.setdefault(kind, []).append((index, text))
        for items in kinds.values():
            index, text = items[0]
            if not self.scalar:
                where = np.unravel_index(index, self.shape) if self.shape else ()
                text += (
                    f" [first at element {tuple(int(i) for i in where)}; "
                    f"{len(items)} of {self.size} elements]"
                )
            # warnings.warn <- _Broadcast.warn <- st.<function> <- the user's line
            warnings.warn(text, StickinessWarning, stacklevel=3)


def _material(material: Any) -> Material:
    """A :class:`Material`; a string is a preset name (``"co2"``) or a JSON file's path."""
    if isinstance(material, Material):
        return material
    if isinstance(material, str):
        return Material.named(material)
    raise TypeError(
        f"material: expected a stickiness.Material or a preset name, got {type(material).__name__}"
    )


def _geometry(radius2: Any, wall: bool) -> None:
    if not isinstance(wall, (bool, np.bool_)):
        raise TypeError(f"wall: expected a bool, got {type(wall).__name__}")
    if wall and radius2 is not None:
        raise ValueError("radius2 and wall=True exclude each other (a wall is R2 -> infinity)")


def _t_vis(t_vis: Any, law: Optional[str], radius: Any, default: Optional[float]) -> Any:
    """T_vis as given, from a size law of ``radius``, or ``default`` (None: required)."""
    if law is not None:
        if t_vis is not None:
            raise ValueError("give t_vis or t_vis_law, not both")
        return t_vis_law(law, radius)
    if t_vis is None:
        if default is None:
            raise TypeError("missing argument: t_vis (s) or t_vis_law ('co2' or 'h2o')")
        return default
    return t_vis


def _scalar(name: str, value: Any) -> float:
    """One number; ``TypeError`` naming ``name`` for an array or a non-number."""
    a = _float_array(name, value)
    if a.ndim != 0:
        raise TypeError(f"{name}: expected one number, got an array of shape {a.shape}")
    return float(a)


def _scalar_option(name: str, value: Any) -> Optional[float]:
    return None if value is None else _scalar(name, value)


# ---------------------------------------------------------------------------------------------
# results


@dataclass(frozen=True)
class JKR:
    """JKR contact (Sections 2.2, 5.1, 6), SI."""

    #: Equilibrium contact radius a_eq (m).
    a_eq: FloatOrArray
    #: Equilibrium mutual approach delta_eq (m).
    delta_eq: FloatOrArray
    #: Tabor parameter mu (dimensionless); JKR theory needs mu >> 1.
    tabor: FloatOrArray
    #: Pull-off force F_crit = 3 pi gamma R / 2 (N).
    f_crit: FloatOrArray
    #: Critical pulling length delta_crit (m).
    delta_crit: FloatOrArray
    #: E_stick,JKR = m* V_stick,JKR^2 / 2 (J).
    e_stick: FloatOrArray
    #: E_break,JKR = 1.54 F_crit delta_crit (J).
    e_break: FloatOrArray
    #: V_stick,JKR = (14.18/m*)^(1/2) (gamma^5 R^4/E*^2)^(1/6) (m/s).
    v_stick_jkr: FloatOrArray


@dataclass(frozen=True)
class Collision:
    """One head-on collision (Sections 2.6, 4), SI."""

    #: ``'sticking'``, ``'double'`` or ``'bouncing'`` (an array of these for array inputs).
    outcome: Union[str, np.ndarray]
    #: Coefficient of restitution e = -V_out/V_in (0 for sticking, negative for double collisions).
    e: FloatOrArray
    #: Approach speed when the contact ends (m/s): < 0 the grains separate, > 0 a second contact follows.
    v_out: FloatOrArray
    #: Duration of the contact (s); None for a sticking collision (NaN in arrays).
    contact_time: Union[None, float, np.ndarray]
    #: V_stick,JKR of the contact (m/s).
    v_stick_jkr: FloatOrArray
    #: How sticking was decided: ``'energy_bound'`` or ``'oscillations'``; None otherwise.
    sticking_criterion: Union[None, str, List[Optional[str]]]
    #: With ``trajectory=True``: arrays ``t`` (s), ``a``, ``delta`` (m), ``delta_dot`` (m/s),
    #: ``beta`` and ``energy`` (J) at every solver step; None otherwise.
    trajectory: Optional[Dict[str, np.ndarray]] = None


@dataclass(frozen=True)
class VStick:
    """Sticking thresholds (Sections 4.4, 5), m/s."""

    #: V_stick: double collision -> bouncing (m/s); NaN without bouncing up to ``no_bouncing_below``.
    v_stick: FloatOrArray
    #: Sticking -> double collision (m/s); NaN when every collision up to the limit sticks.
    v_double_onset: FloatOrArray
    #: V_stick,JKR, the T_vis -> 0 limit (m/s).
    v_stick_jkr: FloatOrArray
    #: The search limit where no collision bounced (m/s); NaN where bouncing was found.
    no_bouncing_below: FloatOrArray
    #: The relaxation time used (s).
    t_vis: FloatOrArray
    #: The highest impact speed searched (m/s).
    v_max: FloatOrArray


@dataclass(frozen=True)
class TVisFit:
    """Relaxation times reproducing a measured V_stick (Sections 5.1-5.2), s."""

    #: T_vis for the measured V_stick (s).
    t_vis: FloatOrArray
    #: T_vis for V_stick - dV (s); 0 when that is at or below V_stick,JKR.
    t_vis_min: FloatOrArray
    #: T_vis for V_stick + dV (s).
    t_vis_max: FloatOrArray
    #: V_stick,JKR of the contact (m/s).
    v_stick_jkr: FloatOrArray


@dataclass(frozen=True)
class VFrag:
    """Fragmentation velocity of aggregates V_frag = 10 V_stick (Section 6), m/s."""

    #: V_frag (m/s); NaN without bouncing up to ``no_bouncing_below``.
    v_frag: FloatOrArray
    #: V_stick of the monomers (m/s); NaN as ``v_frag``.
    v_stick: FloatOrArray
    #: The relaxation time used (s); 0 is the JKR limit.
    t_vis: FloatOrArray
    #: V_frag,JKR = 10 V_stick,JKR (m/s).
    v_frag_jkr: FloatOrArray
    #: V_stick,JKR (m/s).
    v_stick_jkr: FloatOrArray
    #: The search limit where no collision bounced (m/s); NaN where bouncing was found.
    no_bouncing_below: FloatOrArray


# ---------------------------------------------------------------------------------------------
# functions


def crack_speed(k: ArrayLike, beta: ArrayLike) -> FloatOrArray:
    """Greenwood's normalized crack speed v(k, beta) (Appendix A), dimensionless.

    ``0 < k < 1`` is the ratio of relaxed to instantaneous modulus and ``k < beta < 1/k`` the
    normalized apparent surface energy; v > 0 (the contact grows) for beta < 1, v < 0 above,
    v(k, 1) = 0. Broadcasts like numpy.
    """
    b = _Broadcast(k=k, beta=beta)
    return b.out(b.call(_core.crack_speed, b.flat["k"], b.flat["beta"]))


def t_vis_law(law: str, radius: ArrayLike) -> FloatOrArray:
    """T_vis (s) from the size laws of Section 5.3 at radius R1 (m).

    ``law`` is ``'co2'`` (1e-11 s (R1/1 um)^1.11) or ``'h2o'`` (1e-10 s (R1/1.5 um)^1.11,
    Gundlach et al. 2015), any case.
    """
    if not isinstance(law, str):
        raise TypeError(f"law: expected 'co2' or 'h2o', got {type(law).__name__}")
    b = _Broadcast(radius=radius)
    return b.out(b.call(_core.t_vis_law, law, b.flat["radius"]))


def jkr(
    material: Union[Material, str],
    radius: ArrayLike = DEFAULT_RADIUS,
    radius2: Optional[ArrayLike] = None,
    wall: bool = False,
) -> JKR:
    """JKR contact of a sphere of ``radius`` (m) with one of ``radius2`` (m; default equal) or
    a wall (``wall=True``), all of ``material``: a_eq, delta_eq, Tabor parameter, F_crit,
    delta_crit, E_stick, E_break, V_stick,JKR (SI; Sections 2.2, 5.1, 6)."""
    m = _material(material)
    _geometry(radius2, wall)
    b = _Broadcast(radius=radius, radius2=radius2)
    d = b.call(_core.jkr, m, b.flat["radius"], b.flat.get("radius2"), bool(wall))
    b.warn(d["warnings"])
    return JKR(**{f: b.out(d[f]) for f in JKR.__dataclass_fields__})


def collide(
    material: Union[Material, str],
    radius: ArrayLike = DEFAULT_RADIUS,
    t_vis: Optional[ArrayLike] = None,
    v_in: Optional[ArrayLike] = None,
    k: ArrayLike = DEFAULT_K,
    radius2: Optional[ArrayLike] = None,
    wall: bool = False,
    trajectory: bool = False,
    t_vis_law: Optional[str] = None,
    t_end: Optional[float] = None,
) -> Collision:
    """One head-on collision at impact speed ``v_in`` (m/s) with relaxation time ``t_vis``
    (s, > 0; or from ``t_vis_law``): outcome, e, v_out, contact time (Sections 2.6, 4).

    ``trajectory=True`` (scalar arguments only) records every solver step; ``t_end`` (s) keeps
    integrating a sticking collision up to that time first (the spiral of Figure 2).
    """
    m = _material(material)
    _geometry(radius2, wall)
    if v_in is None:
        raise TypeError("collide() missing required argument: 'v_in' (m/s)")
    t = _t_vis(t_vis, t_vis_law, radius, None)
    t_end = _scalar_option("t_end", t_end)
    b = _Broadcast(radius=radius, radius2=radius2, t_vis=t, v_in=v_in, k=k)
    if trajectory and not b.scalar:
        raise ValueError("trajectory=True records one collision: give scalar arguments")
    f = b.flat
    d = b.call(
        _core.collide,
        m,
        f["radius"],
        f.get("radius2"),
        bool(wall),
        f["t_vis"],
        f["v_in"],
        f["k"],
        t_end,
        bool(trajectory),
    )
    b.warn(d["warnings"])
    contact_time = b.out(d["contact_time"])
    criterion = d["sticking_criterion"]
    if b.scalar:
        outcome: Any = d["outcome"][0]
        if outcome == "sticking":
            contact_time = None
        crit: Any = criterion[0]
    else:
        outcome = np.asarray(d["outcome"]).reshape(b.shape)
        crit = criterion
    return Collision(
        outcome=outcome,
        e=b.out(d["e"]),
        v_out=b.out(d["v_out"]),
        contact_time=contact_time,
        v_stick_jkr=b.out(d["v_stick_jkr"]),
        sticking_criterion=crit,
        trajectory=d.get("trajectory"),
    )


def v_stick(
    material: Union[Material, str],
    radius: ArrayLike = DEFAULT_RADIUS,
    t_vis: Optional[ArrayLike] = None,
    k: ArrayLike = DEFAULT_K,
    radius2: Optional[ArrayLike] = None,
    wall: bool = False,
    t_vis_law: Optional[str] = None,
    v_max: Optional[float] = None,
    rel_tol: float = DEFAULT_REL_TOL,
) -> VStick:
    """The threshold velocity for sticking V_stick (double collision -> bouncing) and the onset
    of double collisions, in m/s, at relaxation time ``t_vis`` (s, >= 0; 0 is the JKR limit; or
    from ``t_vis_law``) (Sections 4.4, 5).

    Searched up to ``v_max`` (m/s; default 1000 V_stick,JKR, at most 1e4) to a relative
    tolerance ``rel_tol``; where nothing bounces up to it, ``v_stick`` is NaN and
    ``no_bouncing_below`` holds the limit. The numbers equal the CLI's ``stickiness v-stick``.
    """
    m = _material(material)
    _geometry(radius2, wall)
    t = _t_vis(t_vis, t_vis_law, radius, None)
    b = _Broadcast(radius=radius, radius2=radius2, t_vis=t, k=k)
    d = b.call(
        _core.v_stick,
        m,
        b.flat["radius"],
        b.flat.get("radius2"),
        bool(wall),
        b.flat["t_vis"],
        b.flat["k"],
        _scalar_option("v_max", v_max),
        _scalar("rel_tol", rel_tol),
    )
    b.warn(d["warnings"])
    return VStick(
        v_stick=b.out(d["v_stick"]),
        v_double_onset=b.out(d["v_double_onset"]),
        v_stick_jkr=b.out(d["v_stick_jkr"]),
        no_bouncing_below=b.out(d["no_bouncing_below"]),
        t_vis=b.out(b.flat["t_vis"]),
        v_max=b.out(d["v_max"]),
    )


def fit_t_vis(
    material: Union[Material, str],
    radius: ArrayLike = DEFAULT_RADIUS,
    v_stick: Optional[ArrayLike] = None,
    v_stick_err: Optional[ArrayLike] = None,
    k: ArrayLike = DEFAULT_K,
    radius2: Optional[ArrayLike] = None,
    wall: bool = False,
    v_max: Optional[float] = None,
    rel_tol: float = DEFAULT_REL_TOL,
) -> TVisFit:
    """The relaxation time (s) whose V_stick equals a measured ``v_stick`` (m/s), and the range
    for its uncertainty ``v_stick_err`` (m/s) (Sections 5.1-5.2).

    V_stick exceeds V_stick,JKR for every T_vis > 0, so ``v_stick`` at or below V_stick,JKR
    raises ``ValueError`` (giving V_stick,JKR); a range whose lower end is below it starts at
    ``t_vis_min = 0``.
    """
    m = _material(material)
    _geometry(radius2, wall)
    if v_stick is None:
        raise TypeError("fit_t_vis() missing required argument: 'v_stick' (m/s)")
    err = 0.0 if v_stick_err is None else v_stick_err
    b = _Broadcast(radius=radius, radius2=radius2, v_stick=v_stick, v_stick_err=err, k=k)
    d = b.call(
        _core.fit_t_vis,
        m,
        b.flat["radius"],
        b.flat.get("radius2"),
        bool(wall),
        b.flat["v_stick"],
        b.flat["v_stick_err"],
        b.flat["k"],
        _scalar_option("v_max", v_max),
        _scalar("rel_tol", rel_tol),
    )
    b.warn(d["warnings"])
    return TVisFit(**{f: b.out(d[f]) for f in TVisFit.__dataclass_fields__})


def v_frag(
    material: Union[Material, str],
    radius: ArrayLike = DEFAULT_RADIUS,
    t_vis: Optional[ArrayLike] = None,
    t_vis_law: Optional[str] = None,
    k: ArrayLike = DEFAULT_K,
    radius2: Optional[ArrayLike] = None,
    wall: bool = False,
    v_max: Optional[float] = None,
    rel_tol: float = DEFAULT_REL_TOL,
) -> VFrag:
    """The fragmentation velocity V_frag = 10 V_stick (m/s) of aggregates of monomers of
    ``radius`` (m) at relaxation time ``t_vis`` (s; or from ``t_vis_law``; default 0, the JKR
    limit) (Section 6)."""
    m = _material(material)
    _geometry(radius2, wall)
    t = _t_vis(t_vis, t_vis_law, radius, 0.0)
    b = _Broadcast(radius=radius, radius2=radius2, t_vis=t, k=k)
    d = b.call(
        _core.v_frag,
        m,
        b.flat["radius"],
        b.flat.get("radius2"),
        bool(wall),
        b.flat["t_vis"],
        b.flat["k"],
        _scalar_option("v_max", v_max),
        _scalar("rel_tol", rel_tol),
    )
    b.warn(d["warnings"])
    return VFrag(**{f: b.out(d[f]) for f in VFrag.__dataclass_fields__})


# the sweep needs pandas only when it runs; importing it here costs nothing
from .sweeps import sweep  # noqa: E402
