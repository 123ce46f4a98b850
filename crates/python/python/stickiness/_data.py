"""The measurements of :func:`stickiness.infer`, checked and in SI units (:class:`Data`): a
measured threshold, individual sticking outcomes, coefficients of restitution."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Optional, Tuple

import numpy as np

from . import _args

#: A measured threshold V +- sigma is searched up to V + this many sigma (and sticking outcomes
#: up to their fastest speed): where V_stick lies beyond, it counts as lying at that speed, whose
#: Gaussian likelihood is below exp(-50) of the peak; the searches stop early instead of
#: chasing V_stick to 1000 V_stick,JKR.
V_MAX_SIGMAS = 10.0
#: Margin of the search limit over the fastest sticking outcome, so that no outcome sits on it.
V_MAX_MARGIN = 2.0


def _columns(name: str, value: Any, names: str, or_also: str = "") -> None:
    """``value`` is a tuple of ``len(names.split(', '))`` columns ``(names)``, else a
    ``ValueError`` naming ``name`` (a list is refused: a list of rows, one collision a row,
    would be read as columns when there are as many rows as columns)."""
    n = len(names.split(", "))
    if isinstance(value, tuple) and len(value) == n:
        return
    if isinstance(value, np.ndarray) and value.ndim == 2 and n in value.shape:
        how = {
            (True, False): "tuple(a.T), its columns",
            (False, True): "tuple(a), its rows",
            (True, True): "tuple(a.T) if a row is a collision, tuple(a) if a row is a quantity",
        }[(value.shape[1] == n, value.shape[0] == n)]
        got = f"an array of shape {value.shape}: pass {how}"
    elif isinstance(value, list):
        got = "a list: a table of rows (one collision a row) goes in as tuple(np.transpose(rows))"
    elif isinstance(value, tuple):
        got = f"a tuple of length {len(value)}"
    else:
        got = type(value).__name__
    also = f" (or {or_also})" if or_also else ""
    raise ValueError(
        f"{name}: expected a tuple ({names}) of {n} arrays{also}, one a column; got {got}"
    )


def _pair(name: str, value: Any) -> Tuple[np.ndarray, ...]:
    """A tuple of 1-d float arrays of one length, the last (a sigma) one number for all data or
    one each (``ValueError`` naming ``name``)."""
    arrays = [np.atleast_1d(_args.float_array(name, v)).astype(float) for v in value]
    if arrays[-1].shape == (1,) and arrays[0].ndim == 1:
        arrays[-1] = np.full(arrays[0].shape, arrays[-1][0])
    lengths = {a.shape for a in arrays}
    if len(lengths) != 1 or arrays[0].ndim != 1:
        shapes = ", ".join(str(a.shape) for a in arrays)
        raise ValueError(f"{name}: the arrays must be 1-d and of one length, got shapes {shapes}")
    if arrays[0].size == 0:
        raise ValueError(f"{name}: no data (empty arrays)")
    return tuple(arrays)


def _check(name: str, what: str, values: np.ndarray, ok: np.ndarray, rule: str) -> None:
    if not np.all(ok):
        i = int(np.argmin(ok))
        raise ValueError(f"{name}: {what}[{i}] = {_args.shown(values[i])}: must be {rule}")


#: Speeds this close (relative) are taken as one when pairing restitution points with sticking
#: outcomes (:meth:`Data.counted_twice`): the roundings of one number written twice
#: (``np.linspace(0.01, 0.1, 10)[2]`` is 0.030000000000000006).
SAME_SPEED = 1e-9


@dataclass(frozen=True)
class Data:
    """The measurements, checked and in SI units."""

    #: A measured threshold and its 1-sigma (m/s), or None.
    v_stick: Optional[Tuple[float, float]]
    #: Speeds (m/s) and outcomes (True: stuck) of individual collisions, or None.
    sticking: Optional[Tuple[np.ndarray, np.ndarray]]
    #: Speeds (m/s), e and its 1-sigma of bouncing collisions, or None.
    restitution: Optional[Tuple[np.ndarray, np.ndarray, np.ndarray]]
    #: The 1-sigma of each sticking outcome's speed (m/s), or None: exact speeds.
    sticking_err: Optional[np.ndarray] = None

    @classmethod
    def parse(cls, v_stick: Any, sticking: Any, restitution: Any) -> "Data":
        if v_stick is None and sticking is None and restitution is None:
            raise ValueError("data: give at least one of v_stick, sticking, restitution")
        threshold = None
        if v_stick is not None:
            if not isinstance(v_stick, (tuple, list)) or len(v_stick) != 2:
                raise ValueError("v_stick: expected (value, sigma) in m/s")
            value = _args.scalar("v_stick", _args.si("v_stick", v_stick[0]))
            sigma = _args.scalar("v_stick", _args.si("v_stick", v_stick[1]))
            if not (math.isfinite(value) and value > 0):
                raise ValueError(f"v_stick: value = {_args.shown(value)}: must be > 0 and finite (m/s)")
            if not (math.isfinite(sigma) and sigma > 0):
                raise ValueError(f"v_stick: sigma = {_args.shown(sigma)}: must be > 0 and finite (m/s)")
            threshold = (value, sigma)
        outcomes = v_err = None
        if sticking is not None:
            if isinstance(sticking, tuple) and len(sticking) == 3:
                # the optional third column: each speed's 1-sigma
                v_err = np.atleast_1d(
                    _args.float_array("sticking: v_in_err", _args.si("v_in_err", sticking[2]))
                )
                sticking = sticking[:2]
            _columns("sticking", sticking, "v_in, stuck", or_also="(v_in, stuck, v_in_err)")
            v = np.atleast_1d(_args.float_array("sticking", _args.si("v_in", sticking[0])))
            stuck = np.atleast_1d(np.asarray(sticking[1]))
            # empty arrays (float64 by default) are named as such by the shape check below
            kind_ok = stuck.size == 0 or stuck.dtype.kind in "biuf"
            if not kind_ok or not np.all((stuck == 0) | (stuck == 1)):
                raise ValueError("sticking: stuck must be booleans (or 0/1)")
            if v.ndim != 1 or v.shape != stuck.shape or v.size == 0:
                raise ValueError(
                    f"sticking: v_in and stuck must be 1-d, non-empty and of one length, "
                    f"got shapes {v.shape} and {stuck.shape}"
                )
            _check("sticking", "v_in", v, np.isfinite(v) & (v > 0), "> 0 and finite (m/s)")
            outcomes = (v.astype(float), stuck.astype(bool))
            if v_err is not None:
                if v_err.shape == (1,):
                    v_err = np.full(v.shape, v_err[0])
                if v_err.shape != v.shape:
                    raise ValueError(
                        f"sticking: v_in_err must be one number or one a speed, got shape "
                        f"{v_err.shape} for {v.size} speeds"
                    )
                _check("sticking", "v_in_err", v_err, np.isfinite(v_err) & (v_err > 0),
                       "> 0 and finite (m/s)")
        bounces = None
        if restitution is not None:
            _columns("restitution", restitution, "v_in, e, e_err")
            restitution = (_args.si("v_in", restitution[0]),) + restitution[1:]
            v, e, e_err = _pair("restitution", restitution)
            _check("restitution", "v_in", v, np.isfinite(v) & (v > 0), "> 0 and finite (m/s)")
            _check("restitution", "e", e, np.isfinite(e) & (e >= 0) & (e <= 1),
                   "within 0 .. 1, |V_out|/V_in as measured (a double collision's Collision.e is "
                   "negative, its e_observed 0)")
            _check("restitution", "e_err", e_err, np.isfinite(e_err) & (e_err > 0), "> 0 and finite")
            bounces = (v, e, e_err)
        return cls(threshold, outcomes, bounces, v_err)

    def counted_twice(self) -> Optional[str]:
        """A warning where collisions seem given both as sticking outcomes and as restitution
        data: e = 0 at the speed of an outcome that stuck (to :data:`SAME_SPEED`, each outcome
        paired once). Each datum is taken as independent, so such a collision counts twice."""
        if self.sticking is None or self.restitution is None:
            return None
        v, e, _ = self.restitution
        zero = np.sort(v[e == 0.0])
        stuck = np.sort(self.sticking[0][self.sticking[1]])
        pairs, first, i, j = 0, 0.0, 0, 0
        while i < zero.size and j < stuck.size:
            if math.isclose(zero[i], stuck[j], rel_tol=SAME_SPEED):
                first = first or float(zero[i])
                pairs, i, j = pairs + 1, i + 1, j + 1
            elif zero[i] < stuck[j]:
                i += 1
            else:
                j += 1
        if pairs == 0:
            return None
        return (
            f"restitution: {pairs} of its {v.size} points ha{'ve' if pairs > 1 else 's'} e = 0 "
            f"at the speed of a sticking outcome that stuck (the first at v_in = {first:.6g} "
            f"m/s): each datum is taken as independent, so a collision given both ways counts "
            f"twice; give each collision once"
        )

    def fastest(self) -> float:
        """The highest speed (m/s) the threshold data need V_stick up to."""
        speeds = [0.0]
        if self.v_stick is not None:
            speeds.append(self.v_stick[0] + V_MAX_SIGMAS * self.v_stick[1])
        if self.sticking is not None:
            speeds.append(V_MAX_MARGIN * float(self.sticking[0].max()))
            if self.sticking_err is not None:
                speeds.append(float((self.sticking[0] + V_MAX_SIGMAS * self.sticking_err).max()))
        return max(speeds)
