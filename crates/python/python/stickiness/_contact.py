"""The contact, before any collision: Greenwood's crack law, the size laws of T_vis, the JKR
contact and the two dimensionless numbers of a collision. Each converts its arguments
(:mod:`stickiness._args`), calls the compiled core and builds its result; SI units in and out.
"""

from __future__ import annotations

from typing import Optional, Union

from . import _args, _core
from ._args import ArrayLike, Broadcast, FloatOrArray
from ._core import DEFAULT_RADIUS, Material
from ._docs import shared
from ._results import JKR, Dimensionless


def crack_speed(k: ArrayLike, beta: ArrayLike) -> FloatOrArray:
    """Greenwood's normalized crack speed v(k, beta) (Appendix A).

    Parameters
    ----------
    k : float or array_like
        Ratio of the relaxed to the instantaneous modulus (dimensionless, 0 < k < 1).
    beta : float or array_like
        Normalized apparent surface energy G_eff / gamma (dimensionless, k < beta < 1/k).

    Returns
    -------
    float or ndarray
        v = sigma0^2 T_vis a_dot / (E* gamma) (dimensionless): > 0 (the contact grows) for
        beta < 1, < 0 above, v(k, 1) = 0. Broadcasts like numpy.

    Raises
    ------
    TypeError, ValueError
        Arguments that are not real numbers, or out of their ranges (naming them).

    Notes
    -----
    The parametric form in the transit time alpha (Appendix A) is tabulated once per k and
    interpolated to 1e-8.

    Examples
    --------
    >>> import stickiness as st
    >>> st.crack_speed(0.01, 1.0)
    0.0
    >>> bool(st.crack_speed(0.01, 0.5) > 0 > st.crack_speed(0.01, 2.0))
    True
    """
    b = Broadcast(k=k, beta=beta)
    return b.out(b.call(_core.crack_speed, b.flat["k"], b.flat["beta"]))


def t_vis_law(law: str, radius: ArrayLike) -> FloatOrArray:
    """The relaxation time T_vis (s) of the size laws of Section 5.3, at radius R1 (m).

    Parameters
    ----------
    law : {'co2', 'h2o'}
        ``'co2'``: T_vis = 1e-11 s (R1/1 um)^1.11; ``'h2o'``: T_vis = 1e-10 s (R1/1.5 um)^1.11
        (Gundlach et al. 2015). Any case.
    radius : float, array_like or Quantity
        Grain radius R1 (m).

    Returns
    -------
    float or ndarray
        T_vis (s).

    Raises
    ------
    TypeError, ValueError
        An unknown law, or a radius that is not > 0 and finite.

    Examples
    --------
    >>> import stickiness as st
    >>> round(st.t_vis_law("h2o", 90e-6), 11)  # Section 5.3: 9.4e-9 s
    9.41e-09
    """
    _args.law_name("law", law, required=True)
    b = Broadcast(radius=radius)
    return b.out(b.call(_core.t_vis_law, law, b.flat["radius"]))


@shared
def jkr(
    material: Union[Material, str],
    radius: ArrayLike = DEFAULT_RADIUS,
    *,
    radius2: Optional[ArrayLike] = None,
    wall: bool = False,
) -> JKR:
    """The JKR contact of two bodies of one material (Sections 2.2, 5.1, 6).

    Parameters
    ----------
    {material}
    {radius}
    {partner}

    Returns
    -------
    JKR
        a_eq, delta_eq (m), the Tabor parameter, F_crit (N), delta_crit (m), E_stick,JKR,
        E_break,JKR (J) and V_stick,JKR (m/s).

    Raises
    ------
    {raises}

    Notes
    -----
    V_stick,JKR = (14.18/m*)^(1/2) (gamma^5 R^4/E*^2)^(1/6) with the reduced radius R and mass
    m* of the two bodies and the work of adhesion gamma = 2 gamma_SV.

    {broadcast}

    Examples
    --------
    >>> import stickiness as st
    >>> round(st.jkr("co2", 60e-6).v_stick_jkr, 5)  # Section 5.1: 1.66e-2 m/s
    0.01659
    """
    m = _args.material(material)
    wall = _args.geometry(radius2, wall)
    b = Broadcast(radius=radius, radius2=radius2)
    d = b.call(_core.jkr, m, b.flat["radius"], b.flat.get("radius2"), wall)
    b.warn(d["warnings"], stacklevel=3)
    return JKR(**{f: b.out(d[f]) for f in JKR.__dataclass_fields__})


@shared
def dimensionless(
    material: Union[Material, str],
    radius: ArrayLike = DEFAULT_RADIUS,
    t_vis: Optional[ArrayLike] = None,
    *,
    radius2: Optional[ArrayLike] = None,
    wall: bool = False,
) -> Dimensionless:
    """The two numbers a collision depends on: the drag number c_D and the crack-speed number
    c_a (with k and eps = 0.01), and the JKR time unit t0.

    Parameters
    ----------
    {material}
    {radius}
    t_vis : float, array_like or Quantity
        Viscoelastic relaxation time T_vis (s, > 0).
    {partner}

    Returns
    -------
    Dimensionless
        c_d, c_a (dimensionless) and t0 (s).

    Raises
    ------
    {raises}

    Notes
    -----
    In the JKR units (a/a_eq, delta/delta_eq, time t0 = sqrt(m* delta_eq/(3 pi gamma R))) a
    collision is ``D'' = -(A D - A^3) - c_D A D'``, ``A' = c_a v(k, beta)`` with
    ``c_D = 2 (T_vis/nu^2) E* a_eq t0/m*`` and ``c_a = E* gamma t0/(sigma0^2 T_vis a_eq)``, so
    V_stick/V_stick,JKR is one function of (c_D, c_a; k) for every material, size and
    geometry: the master table's coordinates are log10 c_D and log10(c_D c_a).

    {broadcast}

    Examples
    --------
    >>> import stickiness as st
    >>> a = st.dimensionless("co2", 60e-6, 1e-9)
    >>> b = st.dimensionless(st.Material.co2().replace(density=4 * 1560.0), 60e-6, 2e-9)
    >>> abs(a.c_d / b.c_d - 1) < 1e-12 and abs(a.c_a / b.c_a - 1) < 1e-12  # same collision
    True
    """
    m = _args.material(material)
    wall = _args.geometry(radius2, wall)
    if t_vis is None:
        raise TypeError("dimensionless() missing required argument: 't_vis' (s)")
    b = Broadcast(radius=radius, radius2=radius2, t_vis=t_vis)
    f = b.flat
    d = b.call(_core.dimensionless, m, f["radius"], f.get("radius2"), wall, f["t_vis"])
    b.warn(d["warnings"], stacklevel=3)
    return Dimensionless(c_d=b.out(d["c_d"]), c_a=b.out(d["c_a"]), t0=b.out(d["t0"]))
