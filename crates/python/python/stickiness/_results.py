"""The result types of the public functions: frozen dataclasses, every field in SI units.

Fields hold a Python ``float`` (or ``str``) when the call's arguments were scalars, and an
``ndarray`` of the broadcast shape when they were arrays.
"""

from __future__ import annotations

from dataclasses import dataclass, fields
from typing import Any, Dict, Optional, Union

import numpy as np

from . import _args
from ._args import FloatOrArray

#: A string for scalar calls, an array of strings for array calls.
StrOrArray = Union[str, np.ndarray]


class _Columns:
    """What every result can do: give its fields as a table, one row an element."""

    def to_frame(self, **inputs: Any) -> Any:
        """The fields as a ``pandas.DataFrame``: one column a field (SI units, as the
        attributes), one row an element of the call, flattened in C order (one row for a call
        of scalars); a scalar call's ``contact_time`` of ``None`` becomes NaN, as in arrays. A
        recorded ``trajectory`` is left out (its arrays have one row a solver step).

        Parameters
        ----------
        **inputs : array_like
            Columns to put first, each broadcast to the result's shape like the call's
            arguments (``k=[0.01, 0.02]``, ``radius=r``): the inputs that tell the rows of a
            broadcast call apart (SI units, as the call took them; a ``Quantity`` is
            converted to SI).

        Raises
        ------
        ImportError
            pandas missing: ``pip install 'stickiness[infer]'`` (or pandas alone).
        ValueError
            An input that does not broadcast to the result's shape, or that shares a field's
            name.

        Examples
        --------
        >>> import numpy as np, stickiness as st
        >>> df = st.v_stick("co2", [30e-6, 60e-6], 1e-9).to_frame()
        >>> list(df.columns[:2]), len(df)
        (['v_stick', 'v_double_onset'], 2)
        >>> r = st.v_stick("co2", 60e-6, [[1e-10], [1e-9]], k=[0.01, 0.02])
        >>> list(r.to_frame(k=[0.01, 0.02])["k"])
        [0.01, 0.02, 0.01, 0.02]
        """
        try:
            import pandas as pd  # type: ignore[import-untyped,unused-ignore]
        except ImportError:
            raise ImportError(
                "to_frame needs pandas: pip install 'stickiness[infer]' (or pandas)"
            ) from None
        names = [f.name for f in fields(self)]  # type: ignore[arg-type]
        shape = np.shape(getattr(self, names[0]))
        columns = {}
        for name, value in inputs.items():
            if name in names:
                raise ValueError(f"to_frame: {name!r} is a field of the result already")
            if _args.is_quantity(value):
                # in the unit the call takes under that name (a wrong dimension named), else SI
                value = _args.si(name, value) if name in _args.UNITS else value.si.value
            try:
                arr = np.asarray(value)
            except ValueError:
                raise ValueError(f"to_frame: {name} is ragged, not an array") from None
            try:
                columns[name] = np.broadcast_to(arr, shape).ravel()
            except ValueError:
                raise ValueError(
                    f"to_frame: {name} of shape {arr.shape} does not broadcast to the result's "
                    f"shape {shape}"
                ) from None
        for name in names:
            if name == "trajectory":
                continue
            value = getattr(self, name)
            if name == "contact_time" and value is None:
                value = np.nan
            columns[name] = np.ravel(value)
        return pd.DataFrame(columns)


@dataclass(frozen=True)
class JKR(_Columns):
    """The JKR contact of two bodies (Arakawa & Krijt 2021, Sections 2.2, 5.1, 6).

    Attributes
    ----------
    a_eq : float or ndarray
        Equilibrium contact radius a_eq (m).
    delta_eq : float or ndarray
        Equilibrium mutual approach delta_eq (m).
    tabor : float or ndarray
        Tabor parameter mu (dimensionless); JKR theory needs mu >> 1.
    f_crit : float or ndarray
        Pull-off force F_crit = 3 pi gamma R / 2 (N).
    delta_crit : float or ndarray
        Critical pulling length delta_crit (m).
    e_stick : float or ndarray
        E_stick,JKR = m* V_stick,JKR^2 / 2 (J).
    e_break : float or ndarray
        E_break,JKR = 1.54 F_crit delta_crit (J).
    v_stick_jkr : float or ndarray
        V_stick,JKR = (14.18/m*)^(1/2) (gamma^5 R^4/E*^2)^(1/6) (m/s).
    """

    a_eq: FloatOrArray
    delta_eq: FloatOrArray
    tabor: FloatOrArray
    f_crit: FloatOrArray
    delta_crit: FloatOrArray
    e_stick: FloatOrArray
    e_break: FloatOrArray
    v_stick_jkr: FloatOrArray


@dataclass(frozen=True)
class Dimensionless(_Columns):
    """The two dimensionless numbers of a collision and the JKR time unit (Arakawa & Krijt 2021,
    Section 2.5, in the units of ``docs/model.md``).

    Attributes
    ----------
    c_d : float or ndarray
        Drag number c_D = 2 (T_vis/nu^2) E* a_eq t0/m* (dimensionless); grows with T_vis.
    c_a : float or ndarray
        Crack-speed number c_a = E* gamma t0/(sigma0^2 T_vis a_eq) (dimensionless).
    t0 : float or ndarray
        Time unit t0 = sqrt(m* delta_eq/(3 pi gamma R)) (s).
    """

    c_d: FloatOrArray
    c_a: FloatOrArray
    t0: FloatOrArray


@dataclass(frozen=True)
class Collision(_Columns):
    """One head-on collision (Sections 2.5, 4).

    Attributes
    ----------
    outcome : str or ndarray of str
        ``'sticking'``, ``'double'`` or ``'bouncing'``.
    e : float or ndarray
        Coefficient of restitution of the first contact, e = -V_out/V_in (dimensionless; 0 for
        sticking, negative for double collisions).
    e_observed : float or ndarray
        The coefficient of restitution an experiment observes (dimensionless): e for bouncing,
        0 for sticking and double collisions, whose second contact sticks (Section 4.4).
    v_out : float or ndarray
        Approach speed when the contact ends (m/s): < 0 the grains separate, > 0 a second
        contact follows.
    contact_time : float, ndarray or None
        Duration of the contact (s); None for a sticking collision (NaN in arrays), and NaN
        where the restitution tables answered (``method='table'``: they hold e and V_out only).
    v_stick_jkr : float or ndarray
        V_stick,JKR of the contact (m/s).
    sticking_criterion : str, ndarray of object or None
        How sticking was decided: ``'energy_bound'`` or ``'oscillations'``; None otherwise (in
        arrays, an object array of the broadcast shape holding those).
    trajectory : dict of ndarray or None
        With ``trajectory=True``: ``t`` (s), ``a``, ``delta`` (m), ``delta_dot`` (m/s),
        ``energy`` (J) and ``beta`` (dimensionless) at every solver step, the columns of the
        CLI's ``--trajectory`` CSV in its order; None otherwise.
    method : str or ndarray of str
        Which answered: ``'ode'`` (the collision integrated) or ``'table'`` (the restitution
        tables: outcome, e and V_out only; no contact time or criterion).
    """

    outcome: StrOrArray
    e: FloatOrArray
    v_out: FloatOrArray
    contact_time: Union[None, float, np.ndarray]
    v_stick_jkr: FloatOrArray
    sticking_criterion: Union[None, str, np.ndarray]
    e_observed: FloatOrArray
    trajectory: Optional[Dict[str, np.ndarray]] = None
    method: StrOrArray = "ode"


@dataclass(frozen=True)
class VStick(_Columns):
    """The sticking thresholds (Sections 4.4, 5).

    Attributes
    ----------
    v_stick : float or ndarray
        V_stick, the double collision -> bouncing transition (m/s); NaN without bouncing up to
        ``no_bouncing_below``.
    v_double_onset : float or ndarray
        The sticking -> double collision transition (m/s); NaN when every collision up to the
        limit sticks.
    v_stick_jkr : float or ndarray
        V_stick,JKR, the T_vis -> 0 limit (m/s).
    no_bouncing_below : float or ndarray
        The search limit where no collision bounced (m/s); NaN where bouncing was found.
    t_vis : float or ndarray
        The relaxation time used (s).
    v_max : float or ndarray
        The highest impact speed searched (m/s).
    method : str or ndarray of str
        Which answered: ``'search'`` (the exact search) or ``'table'`` (the master table).
    """

    v_stick: FloatOrArray
    v_double_onset: FloatOrArray
    v_stick_jkr: FloatOrArray
    no_bouncing_below: FloatOrArray
    t_vis: FloatOrArray
    v_max: FloatOrArray
    method: StrOrArray


@dataclass(frozen=True)
class TVisFit(_Columns):
    """Relaxation times reproducing a measured V_stick (Sections 5.1-5.2).

    Attributes
    ----------
    t_vis : float or ndarray
        T_vis for the measured V_stick (s); 0 (the JKR limit) when it lies within the T_vis -> 0
        limit of V_stick, 1.55e-4 above V_stick,JKR.
    t_vis_min : float or ndarray
        T_vis for V_stick - dV (s); 0 when that is at or below the T_vis -> 0 limit.
    t_vis_max : float or ndarray
        T_vis for V_stick + dV (s).
    v_stick_jkr : float or ndarray
        V_stick,JKR of the contact (m/s).
    method : str or ndarray of str
        ``'table'`` when the master table gave every V_stick the fit needed, else ``'search'``.
    """

    t_vis: FloatOrArray
    t_vis_min: FloatOrArray
    t_vis_max: FloatOrArray
    v_stick_jkr: FloatOrArray
    method: StrOrArray


@dataclass(frozen=True)
class VFrag(_Columns):
    """The fragmentation velocity of aggregates, V_frag = 10 V_stick (Section 6).

    Attributes
    ----------
    v_frag : float or ndarray
        V_frag (m/s); NaN without bouncing up to ``no_bouncing_below``.
    v_stick : float or ndarray
        V_stick of the monomers (m/s); NaN as ``v_frag``.
    t_vis : float or ndarray
        The relaxation time used (s); 0 is the JKR limit.
    v_frag_jkr : float or ndarray
        V_frag,JKR = 10 V_stick,JKR (m/s).
    v_stick_jkr : float or ndarray
        V_stick,JKR (m/s).
    no_bouncing_below : float or ndarray
        The search limit where no collision bounced (m/s); NaN where bouncing was found.
    method : str or ndarray of str
        Which answered: ``'search'`` or ``'table'``.
    """

    v_frag: FloatOrArray
    v_stick: FloatOrArray
    t_vis: FloatOrArray
    v_frag_jkr: FloatOrArray
    v_stick_jkr: FloatOrArray
    no_bouncing_below: FloatOrArray
    method: StrOrArray
