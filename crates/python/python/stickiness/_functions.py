"""The collision functions: one collision, the thresholds, the T_vis fit and V_frag. Each
converts its arguments (:mod:`stickiness._args`), calls the compiled core and builds its result
(:mod:`stickiness._results`); SI units in and out.
"""

from __future__ import annotations

import math
from typing import Any, Optional, Union

import numpy as np

from . import _args, _core
from ._args import ArrayLike, Broadcast
from ._core import DEFAULT_K, DEFAULT_RADIUS, DEFAULT_REL_TOL, Material
from ._docs import shared
from ._results import Collision, TVisFit, VFrag, VStick


@shared
def collide(
    material: Union[Material, str],
    radius: ArrayLike = DEFAULT_RADIUS,
    t_vis: Optional[ArrayLike] = None,
    v_in: Optional[ArrayLike] = None,
    *,
    k: ArrayLike = DEFAULT_K,
    radius2: Optional[ArrayLike] = None,
    wall: bool = False,
    t_vis_law: Optional[str] = None,
    trajectory: bool = False,
    t_end: Optional[float] = None,
    method: str = "ode",
) -> Collision:
    """One head-on collision at impact speed ``v_in`` (Sections 2.5, 4).

    Parameters
    ----------
    {material}
    {radius}
    t_vis : float, array_like or Quantity
        Viscoelastic relaxation time T_vis (s, > 0). Give it or ``t_vis_law``.
    v_in : float, array_like or Quantity
        Impact speed V_in (m/s, > 0).
    {k}
    {partner}
    {t_vis_law}
    trajectory : bool, optional
        Record every solver step (scalar arguments only). Default False.
    t_end : float or Quantity, optional
        Keep integrating a sticking collision up to this time (s) before deciding that it
        sticks, to record the whole spiral towards the JKR point (Figure 2).
    method : {{'ode', 'table'}}, optional
        ``'ode'`` (default): integrate the collision (milliseconds; everything, including the
        contact time). ``'table'``: the outcome, e and V_out from the restitution tables, within
        1e-4 of the ODE in e, in microseconds, where they vouch for it (k from 0.005 to
        0.050397 = 0.005 2^(10/3); not within a thin band at the cliff or the onset of double
        collisions; at most 1.3e4 V_stick; beyond the cliff, sticking below the search limit); the ODE elsewhere
        (with BDF where the tables cover k: e within 1.3e-6 of ``'ode'`` at a third of its
        time), and with ``trajectory`` or ``t_end``. The result's ``method`` says which
        answered; a table answer has no contact time (NaN; None for a sticking scalar, as from
        the ODE) or sticking criterion.

    Returns
    -------
    Collision
        The outcome (``'sticking'``, ``'double'``, ``'bouncing'``), e, the observed e, V_out
        (m/s), the contact time (s), which method answered and, with ``trajectory``, the
        states.

    Raises
    ------
    {raises}

    Notes
    -----
    Start at delta = 0, delta_dot = V_in, beta = (1 + eps) k; end when beta = (1 - eps)/k,
    eps = 0.01 (Section 2.5), or when the contact is proved never to end (sticking).

    {broadcast}

    Examples
    --------
    >>> import stickiness as st
    >>> st.collide("co2", 60e-6, 1e-9, 0.045).outcome  # Section 4: 4.5 cm/s bounces
    'bouncing'
    """
    m = _args.material(material)
    wall = _args.geometry(radius2, wall)
    trajectory = _args.flag("trajectory", trajectory)
    table = _args.choice("method", method, ("ode", "table")) == "table"
    core_method = "table" if table else "search"
    if v_in is None:
        raise TypeError("collide() missing required argument: 'v_in' (m/s)")
    t = _args.t_vis(t_vis, t_vis_law, radius, None, material)
    t_end = _args.scalar_option("t_end", t_end)
    if t_end is not None and not (math.isfinite(t_end) and t_end >= 0):
        raise ValueError(f"t_end = {_args.shown(t_end)}: must be >= 0 and finite (s)")
    b = Broadcast(radius=radius, radius2=radius2, t_vis=t, v_in=v_in, k=k)
    if trajectory and not b.scalar:
        raise ValueError("trajectory=True records one collision: give scalar arguments")
    f = b.flat
    args = (f["radius"], f.get("radius2"), wall, f["t_vis"], f["v_in"], f["k"], t_end)
    d = b.call(_core.collide, m, *args, trajectory, core_method)
    b.warn(d["warnings"], stacklevel=3)
    contact_time = b.out(d["contact_time"])
    # str or None each: an object array of the broadcast shape, like the other fields
    criterion: Any = np.array(d["sticking_criterion"], dtype=object).reshape(b.shape)
    outcome: Any = np.asarray(d["outcome"]).reshape(b.shape)
    e = b.out(d["e"])
    observed = b.out(d["e_observed"])
    if b.scalar:
        outcome = str(d["outcome"][0])
        contact_time = None if outcome == "sticking" else contact_time
        criterion = d["sticking_criterion"][0]
    return Collision(
        outcome=outcome,
        e=e,
        v_out=b.out(d["v_out"]),
        contact_time=contact_time,
        v_stick_jkr=b.out(d["v_stick_jkr"]),
        sticking_criterion=criterion,
        e_observed=observed,
        trajectory=d.get("trajectory"),
        method=b.names(("ode", "table"), d["method"]),
    )


def _thresholds(core: Any, material: Any, radius: Any, t: Any, k: Any, radius2: Any, wall: Any,
                v_max: Any, rel_tol: Any, method: Any) -> Any:
    """The call of a threshold function of the core, and the broadcast it was made on."""
    m = _args.material(material)
    wall = _args.geometry(radius2, wall)
    b = Broadcast(radius=radius, radius2=radius2, t_vis=t, k=k)
    options = (
        _args.scalar_option("v_max", v_max),
        _args.scalar("rel_tol", rel_tol),
        _args.method(method),
    )
    f = b.flat
    d = b.call(core, m, f["radius"], f.get("radius2"), wall, f["t_vis"], f["k"], *options)
    b.warn(d["warnings"])
    return b, d


@shared
def v_stick(
    material: Union[Material, str],
    radius: ArrayLike = DEFAULT_RADIUS,
    t_vis: Optional[ArrayLike] = None,
    *,
    k: ArrayLike = DEFAULT_K,
    radius2: Optional[ArrayLike] = None,
    wall: bool = False,
    t_vis_law: Optional[str] = None,
    v_max: Optional[float] = None,
    rel_tol: float = DEFAULT_REL_TOL,
    method: str = "table",
) -> VStick:
    """The threshold velocity for sticking V_stick and the onset of double collisions
    (Sections 4.4, 5).

    Parameters
    ----------
    {material}
    {radius}
    {t_vis}
    {k}
    {partner}
    {t_vis_law}
    {search}

    Returns
    -------
    VStick
        V_stick (double collision -> bouncing) and V_double_onset (sticking -> double
        collision), in m/s; NaN without bouncing up to ``no_bouncing_below``; the method that
        answered.

    Raises
    ------
    {raises}

    Notes
    -----
    V_stick is where V_out, the approach speed when the contact ends, crosses zero; V_stick >=
    V_stick,JKR for every T_vis, with equality in the limit T_vis -> 0 (to 1.5e-4: the paper's
    rounded 14.18). The numbers equal those of the CLI's ``stickiness v-stick``.

    {broadcast}

    Examples
    --------
    >>> import stickiness as st
    >>> round(st.v_stick("co2", 60e-6, 1e-9).v_stick, 5)  # Section 4.4: 4.14 cm/s
    0.04138
    >>> r = st.v_stick("co2", 60e-6, 1e-9, method="table")
    >>> r.method, round(r.v_stick, 5)
    ('table', 0.04138)
    """
    t = _args.t_vis(t_vis, t_vis_law, radius, None, material)
    b, d = _thresholds(_core.v_stick, material, radius, t, k, radius2, wall, v_max, rel_tol, method)
    return VStick(
        v_stick=b.out(d["v_stick"]),
        v_double_onset=b.out(d["v_double_onset"]),
        v_stick_jkr=b.out(d["v_stick_jkr"]),
        no_bouncing_below=b.out(d["no_bouncing_below"]),
        t_vis=b.out(b.flat["t_vis"]),
        v_max=b.out(d["v_max"]),
        method=b.methods(d["method"]),
    )


@shared
def v_frag(
    material: Union[Material, str],
    radius: ArrayLike = DEFAULT_RADIUS,
    t_vis: Optional[ArrayLike] = None,
    *,
    k: ArrayLike = DEFAULT_K,
    radius2: Optional[ArrayLike] = None,
    wall: bool = False,
    t_vis_law: Optional[str] = None,
    v_max: Optional[float] = None,
    rel_tol: float = DEFAULT_REL_TOL,
    method: str = "table",
) -> VFrag:
    """The fragmentation velocity V_frag = 10 V_stick of aggregates of monomers of ``radius``
    (Section 6).

    Parameters
    ----------
    {material}
    {monomer_radius}
    t_vis : float, array_like or Quantity, optional
        Relaxation time T_vis (s, >= 0). Default 0: the JKR limit, V_frag,JKR.
    {k}
    {partner}
    {t_vis_law}
    {search}

    Returns
    -------
    VFrag
        V_frag and the monomers' V_stick (m/s), T_vis (s), V_frag,JKR and V_stick,JKR (m/s),
        the method that answered.

    Raises
    ------
    {raises}

    Notes
    -----
    V_frag = 10 V_stick (Eq. vfrag of Section 6, from the energy to break a contact, about
    1.54 F_crit delta_crit, and the number of contacts broken).

    {broadcast}

    Examples
    --------
    >>> import stickiness as st
    >>> round(st.v_frag("co2", 30e-6).v_frag, 3)  # Section 7.1: V_frag,JKR = 0.296 m/s
    0.296
    """
    t = _args.t_vis(t_vis, t_vis_law, radius, 0.0, material)
    b, d = _thresholds(_core.v_frag, material, radius, t, k, radius2, wall, v_max, rel_tol, method)
    fields = [f for f in VFrag.__dataclass_fields__ if f != "method"]
    return VFrag(**{f: b.out(d[f]) for f in fields}, method=b.methods(d["method"]))


@shared
def fit_t_vis(
    material: Union[Material, str],
    radius: ArrayLike = DEFAULT_RADIUS,
    v_stick: Optional[ArrayLike] = None,
    *,
    v_stick_err: Optional[ArrayLike] = None,
    k: ArrayLike = DEFAULT_K,
    radius2: Optional[ArrayLike] = None,
    wall: bool = False,
    v_max: Optional[float] = None,
    rel_tol: float = DEFAULT_REL_TOL,
    method: str = "table",
) -> TVisFit:
    """The relaxation time whose V_stick equals a measured one, and the range for its
    uncertainty (Sections 5.1-5.2).

    Parameters
    ----------
    {material}
    {radius}
    v_stick : float, array_like or Quantity
        The measured V_stick (m/s), above V_stick,JKR; V_stick + ``v_stick_err`` at most 5000
        m/s (each trial T_vis is searched up to twice it, within the 1e4 m/s search limit).
    v_stick_err : float, array_like or Quantity, optional
        Its uncertainty dV (m/s, 0 <= dV < V_stick). Default 0.
    {k}
    {partner}
    {search_fit}

    Returns
    -------
    TVisFit
        T_vis for V_stick, V_stick - dV and V_stick + dV (s), V_stick,JKR (m/s), the method.

    Raises
    ------
    {raises}

    Notes
    -----
    V_stick grows monotonically with T_vis from V_stick,JKR, so ln V_stick(T_vis) = ln V has
    one root in ln T_vis (Illinois). A V_stick at or below V_stick,JKR is reached by no T_vis
    (``ValueError`` giving V_stick,JKR); one within the model's T_vis -> 0 limit of V_stick
    (1.55e-4 above V_stick,JKR, whose 14.18 the paper rounds) gives ``t_vis = 0``, the JKR
    limit, and a range whose lower end is below that limit starts at ``t_vis_min = 0``, each
    with a warning. Near the JKR limit V_stick hardly depends on T_vis
    (CO2 at 60 um: d ln V_stick / d ln T_vis is 4e-3 at T_vis = 1e-12 s, 6e-5 at 1e-14 s),
    and the fitted T_vis is only as sharp as the threshold (1e-5 from the tables, about 1e-7
    from the search) divided by that slope: ``method="table"`` and ``method="search"`` may
    then differ by percents to tens of percent in T_vis while both reproduce the measured
    V_stick to 1e-5; ``v_stick_err`` gives the range that matters. The T_vis returned is the
    one tried whose V_stick came closest to V: within ``rel_tol`` of it (1e-6 by default) unless
    the bracket reached 1e-9 in ln T_vis first, also next to the no-bouncing cliff, where V_stick
    climbs steeply with T_vis (``examples/python/fit_round_trip.py``: 99.9 % within 1e-6, all
    within 7.4e-6).

    {broadcast}

    Examples
    --------
    >>> import stickiness as st
    >>> f = st.fit_t_vis("co2", 60e-6, 0.04, v_stick_err=0.02)  # Section 5.1
    >>> f"{{f.t_vis_min:.2e}} .. {{f.t_vis_max:.2e}} s"
    '8.49e-11 .. 1.98e-09 s'
    """
    m = _args.material(material)
    wall = _args.geometry(radius2, wall)
    if v_stick is None:
        raise TypeError("fit_t_vis() missing required argument: 'v_stick' (m/s)")
    err = 0.0 if v_stick_err is None else v_stick_err
    b = Broadcast(radius=radius, radius2=radius2, v_stick=v_stick, v_stick_err=err, k=k)
    f = b.flat
    options = (
        _args.scalar_option("v_max", v_max),
        _args.scalar("rel_tol", rel_tol),
        _args.method(method),
    )
    inputs = (f["radius"], f.get("radius2"), wall, f["v_stick"], f["v_stick_err"], f["k"])
    d = b.call(_core.fit_t_vis, m, *inputs, *options)
    b.warn(d["warnings"], stacklevel=3)
    fields = [x for x in TVisFit.__dataclass_fields__ if x != "method"]
    return TVisFit(**{x: b.out(d[x]) for x in fields}, method=b.methods(d["method"]))
