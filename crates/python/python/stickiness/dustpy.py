"""The fragmentation velocity of a DustPy disc from grain physics (Arakawa & Krijt 2021, Sec. 6-7).

UNITS: inputs are SI and kelvin (``monomer_radius`` in m, ``v_frag_refractory`` in m/s,
temperatures in K); the OUTPUT IS IN cm/s, because DustPy works in cgs
(``sim.dust.v.frag`` is in cm/s). 1 m/s = 100 cm/s.

Dust-evolution codes take V_frag as a number chosen by hand. Here it follows from the ice that
coats the monomers at each radius of the disc, by temperature:

- ``T > t_h2o``: refractory (silicate) grains. The model has no relaxation time for them, so
  V_frag is the user's ``v_frag_refractory`` (m/s);
- ``t_co2 < T <= t_h2o``: H2O ice, V_frag = 10 V_stick with T_vis,H2O(R1) = 1e-10 s
  (R1/1.5 um)^1.11 (Section 5.3, Gundlach et al. 2015) and the H2O constants of Section 5.2;
- ``T <= t_co2``: CO2 ice, V_frag = 10 V_stick with T_vis,CO2(R1) = 1e-11 s (R1/1 um)^1.11
  (Section 5.3) and the CO2 constants of Section 3.

V_stick is that of two identical monomers of radius ``monomer_radius``, with k = 0.01, from
the master table (``method="table"``: microseconds a radius, the exact search where the table
does not vouch). Each (ice, monomer radius) is computed once and mapped onto the grid, so an
updater on a grid of 1000 cells costs 0.1-0.2 ms a call with one monomer radius, a few ms
with a different radius in every cell. ``width`` (K) replaces the steps at the snow lines by
smooth transitions (tanh, in log V_frag) over that width.

Usage with DustPy (``pip install dustpy``; it is not needed to import :mod:`stickiness`)::

    from dustpy import Simulation
    from stickiness import dustpy as sd
    sim = Simulation()
    sim.initialize()
    sd.set_vfrag(sim, monomer_radius=1e-7)      # sim.dust.v.frag now follows sim.gas.T
    sim.run()

With T_vis inferred from laboratory data (:func:`stickiness.infer`), a run bracketed by the
data's uncertainty: ``sd.set_vfrag(sim, 1e-7, posteriors={"co2": post_co2, "h2o": post_h2o},
quantile=0.84)`` (and 0.16).
"""

from __future__ import annotations

import math
from typing import Any, Callable, Dict, Optional, Tuple, Union

import numpy as np

from . import _args
from ._core import Material
from ._functions import v_frag
from ._posterior import Posterior

__all__ = ["CM_PER_M", "T_CO2", "T_H2O", "VFragProfile", "set_vfrag", "vfrag_profile"]

#: Temperature (K) above which the monomers are bare refractory grains: the H2O snow line,
#: 150 K (the condensation temperature of water ice in protoplanetary discs; Lecar et al. 2006).
T_H2O = 150.0
#: Temperature (K) below which the monomers are coated with CO2 ice: 70 K, the condensation
#: temperature of CO2 ice quoted by Arakawa & Krijt (2021, Section 1) after Okuzumi et al. (2016).
T_CO2 = 70.0
#: Centimetres per metre: V_frag leaves here in cm/s, DustPy's unit.
CM_PER_M = 100.0

#: The ices and how their V_frag is computed: (material, T_vis size law).
_ICES: Dict[str, Tuple[Callable[[], Material], str]] = {
    "h2o": (Material.h2o, "h2o"),
    "co2": (Material.co2, "co2"),
}


class VFragProfile:
    """V_frag (cm/s) against temperature for monomers of ``monomer_radius`` (m).

    A callable: ``profile(T)`` with T in K (an array, such as DustPy's ``sim.gas.T``) gives
    V_frag in cm/s of the same shape. ``monomer_radius`` is one radius or one per cell (an array
    of the shape of T). The V_frag of each (ice, radius) is computed once, on first use. The
    keyword options are those of :func:`vfrag_profile`.
    """

    def __init__(
        self,
        monomer_radius: Union[float, np.ndarray] = 1e-7,
        *,
        t_h2o: float = T_H2O,
        t_co2: float = T_CO2,
        v_frag_refractory: float = 1.0,
        width: Optional[float] = None,
        posteriors: Optional[Dict[str, Any]] = None,
        quantile: float = 0.5,
        v_frag: Optional[Dict[str, float]] = None,
    ) -> None:
        radius = _args.float_array("monomer_radius", monomer_radius)
        t_h2o = _args.scalar("t_h2o", t_h2o)
        t_co2 = _args.scalar("t_co2", t_co2)
        v_frag_refractory = _args.scalar("v_frag_refractory", v_frag_refractory)
        width = _args.scalar_option("width", width)
        if radius.size == 0 or not np.all(np.isfinite(radius) & (radius > 0)):
            raise ValueError(f"monomer_radius = {monomer_radius!r}: must be > 0 and finite (m)")
        for name, value in (("t_h2o", t_h2o), ("t_co2", t_co2)):
            if not (math.isfinite(value) and value > 0):
                raise ValueError(f"{name} = {value!r}: must be > 0 and finite (K)")
        if not t_co2 < t_h2o:
            raise ValueError(f"t_co2 = {t_co2!r} K must be below t_h2o = {t_h2o!r} K")
        if not (math.isfinite(v_frag_refractory) and v_frag_refractory > 0):
            raise ValueError(
                f"v_frag_refractory = {v_frag_refractory!r}: must be > 0 and finite (m/s)"
            )
        if width is not None and not (math.isfinite(width) and width > 0):
            raise ValueError(f"width = {width!r}: must be > 0 and finite (K), or None")
        form, unknown = "{'co2' | 'h2o': Posterior}", "unknown ice {key!r}; allowed: {keys}"
        for ice, post in _args.keyed("posteriors", posteriors, form, tuple(_ICES), unknown):
            if not isinstance(post, Posterior):
                raise TypeError(f"posteriors[{ice!r}]: expected a stickiness.Posterior, got {type(post).__name__}")
        quantile = _args.scalar("quantile", quantile)
        if not 0.0 <= quantile <= 1.0:
            raise ValueError(f"quantile = {quantile!r}: must be within 0 .. 1")
        if quantile != 0.5 and not posteriors:
            raise ValueError(
                f"quantile = {quantile!r}: the quantile of the posteriors' V_frag, so it needs "
                "posteriors= (without them V_frag follows the Section 5.3 laws)"
            )
        given: Dict[str, float] = {}
        form = "{'co2' | 'h2o': V_frag in m/s}"
        for ice, value in _args.keyed("v_frag", v_frag, form, tuple(_ICES), unknown):
            value = _args.scalar(f"v_frag[{ice!r}]", _args.si("v_frag", value))
            if not (math.isfinite(value) and value > 0):
                raise ValueError(f"v_frag[{ice!r}] = {value!r}: must be > 0 and finite (m/s)")
            if ice in (posteriors or {}):
                raise ValueError(f"v_frag[{ice!r}]: give {ice} a posterior or a V_frag, not both")
            given[ice] = value
        self.monomer_radius = radius
        #: Posteriors of T_vis per ice (``'co2'``, ``'h2o'``) replacing the Section 5.3 laws.
        self.posteriors: Dict[str, Posterior] = dict(posteriors or {})
        #: The posterior quantile of V_frag used for the ices in :attr:`posteriors`.
        self.quantile = float(quantile)
        self.t_h2o = float(t_h2o)
        self.t_co2 = float(t_co2)
        self.v_frag_refractory = float(v_frag_refractory)
        self.width = width
        #: V_frag (m/s) given per ice, replacing its size law or posterior at every radius.
        self.v_frag: Dict[str, float] = given
        self._cache: Dict[Tuple[str, float], float] = {}

    def ice_v_frag(self, ice: str, radius: float) -> float:
        """V_frag (m/s) of aggregates of ``ice`` ('h2o' or 'co2') monomers of ``radius`` (m)."""
        return float(self._ice_v_frags(ice, np.array([float(radius)]))[0])

    def _ice_v_frags(self, ice: str, radii: np.ndarray) -> np.ndarray:
        """V_frag (m/s) of ``ice`` monomers of each of ``radii`` (m), from the cache, computing
        the missing ones in one call."""
        missing = [r for r in radii if (ice, float(r)) not in self._cache]
        if missing:
            material, law = _ICES[ice]
            try:
                if ice in self.v_frag:
                    values = np.full(len(missing), self.v_frag[ice])
                    limits = np.full(len(missing), np.nan)
                elif ice in self.posteriors:
                    # the posterior's T_vis carried to each monomer size by the size law
                    post = self.posteriors[ice]
                    q = post.v_frag(np.array(missing), quantiles=(self.quantile,))
                    values = q.iloc[:, 0].to_numpy()
                    limits = np.full(len(missing), np.nan)
                else:
                    r = v_frag(material(), np.array(missing), t_vis_law=law, method="table")
                    values = np.atleast_1d(r.v_frag)
                    limits = np.atleast_1d(r.no_bouncing_below)
            except ValueError as e:  # the core names its own argument, radius
                raise ValueError(f"monomer_radius: {e}") from None
            bad = ~np.isfinite(values)
            if bad.any():
                i = int(np.argmax(bad))
                raise ValueError(
                    f"monomer_radius = {missing[i]} m: {ice} monomers of this size show no "
                    f"bouncing up to "
                    f"{limits[i]} m/s (the search limit), so V_frag exceeds every "
                    "collision speed searched"
                )
            for radius, value in zip(missing, values):
                self._cache[(ice, float(radius))] = float(value)
        return np.array([self._cache[(ice, float(r))] for r in radii])

    def _zone_values(self, ice: str, shape: Tuple[int, ...]) -> np.ndarray:
        """ln V_frag (m/s) of one ice on the grid (per distinct radius)."""
        if self.monomer_radius.ndim == 0:
            return np.full(shape, math.log(self.ice_v_frag(ice, float(self.monomer_radius))))
        radius = np.broadcast_to(self.monomer_radius, shape)
        distinct, where = np.unique(radius, return_inverse=True)
        logs = np.log(self._ice_v_frags(ice, distinct))
        return logs[where.reshape(shape)]

    def __call__(self, T: Any) -> np.ndarray:
        """V_frag in cm/s at temperatures ``T`` (K)."""
        T = _args.float_array("T", T)
        if not np.all(np.isfinite(T) & (T > 0)):
            raise ValueError("T: temperatures must be > 0 and finite (K)")
        shape = T.shape
        try:
            fits = np.broadcast_shapes(self.monomer_radius.shape, shape) == shape
        except ValueError:
            fits = False
        if not fits:
            raise ValueError(
                f"monomer_radius: shape {self.monomer_radius.shape} does not broadcast to the "
                f"temperatures' shape {shape} (one radius, or one per cell)"
            )
        co2 = self._zone_values("co2", shape)
        h2o = self._zone_values("h2o", shape)
        refractory = math.log(self.v_frag_refractory)
        if self.width is None:
            warm = T > self.t_co2  # H2O or refractory
            hot = T > self.t_h2o
            log_v = np.where(hot, refractory, np.where(warm, h2o, co2))
        else:
            warm = 0.5 * (1.0 + np.tanh((T - self.t_co2) / self.width))
            hot = 0.5 * (1.0 + np.tanh((T - self.t_h2o) / self.width))
            log_v = (1.0 - warm) * co2 + warm * ((1.0 - hot) * h2o + hot * refractory)
        return CM_PER_M * np.exp(log_v)


def vfrag_profile(
    T: Any,
    monomer_radius: Union[float, np.ndarray] = 1e-7,
    *,
    t_h2o: float = T_H2O,
    t_co2: float = T_CO2,
    v_frag_refractory: float = 1.0,
    width: Optional[float] = None,
    posteriors: Optional[Dict[str, Any]] = None,
    quantile: float = 0.5,
    v_frag: Optional[Dict[str, float]] = None,
) -> np.ndarray:
    """V_frag IN cm/s at temperatures ``T`` (K) for monomers of ``monomer_radius`` (m).

    Parameters
    ----------
    T : array_like
        Temperatures (K, > 0), e.g. DustPy's ``sim.gas.T``.
    monomer_radius : float or array_like, optional
        Monomer radius (m): one, or one per cell (the shape of ``T``). Default 1e-7.
    t_h2o, t_co2 : float, optional
        Snow lines (K): refractory above ``t_h2o``, H2O ice down to ``t_co2``, CO2 ice below.
        Defaults 150 and 70.
    v_frag_refractory : float, optional
        V_frag of bare refractory grains (m/s; the output is 100 times it). Default 1.
    width : float, optional
        Width (K) of smooth (tanh) transitions at the snow lines; default: steps.
    posteriors : dict, optional
        ``{'co2': Posterior, 'h2o': Posterior}`` from :func:`stickiness.infer`: for those ices
        V_frag is the ``quantile`` of the posterior's V_frag, each T_vis sample carried to the
        monomer size by the size law T_vis ~ R1^1.11 (:meth:`~stickiness.Posterior.v_frag`). The other ices
        keep the laws of Section 5.3.
    quantile : float, optional
        The posterior quantile (0..1), e.g. 0.16 and 0.84 to bracket a disc run by the data's
        uncertainty. Default 0.5.
    v_frag : dict, optional
        ``{'co2': V_frag, 'h2o': V_frag}`` (m/s): a given V_frag for those ices at every
        monomer radius, replacing their laws (not with a posterior for the same ice). For a
        run that goes on over several sittings: the posterior's quantile computed once and
        kept with the run, so that a sampler or table that changes between sittings cannot
        change the run's input.

    Returns
    -------
    ndarray
        V_frag in cm/s, the shape of ``T``.
    """
    return VFragProfile(
        monomer_radius, t_h2o=t_h2o, t_co2=t_co2, v_frag_refractory=v_frag_refractory,
        width=width, posteriors=posteriors, quantile=quantile, v_frag=v_frag,
    )(T)


def set_vfrag(
    sim: Any,
    monomer_radius: Union[float, np.ndarray] = 1e-7,
    *,
    t_h2o: float = T_H2O,
    t_co2: float = T_CO2,
    v_frag_refractory: float = 1.0,
    width: Optional[float] = None,
    posteriors: Optional[Dict[str, Any]] = None,
    quantile: float = 0.5,
    v_frag: Optional[Dict[str, float]] = None,
) -> VFragProfile:
    """Installs an updater on ``sim.dust.v.frag`` (an initialised DustPy Simulation) so that it
    follows ``sim.gas.T`` (in cm/s), and applies it at once.

    The options are those of :func:`vfrag_profile` (``posteriors=`` and ``quantile=`` bracket
    the run by the uncertainty of inferred T_vis). Returns the :class:`VFragProfile` it uses.
    """
    if not hasattr(sim, "dust") or not hasattr(sim, "gas"):
        raise TypeError(f"sim: expected a dustpy.Simulation, got {type(sim).__name__}")
    frag = getattr(getattr(sim.dust, "v", None), "frag", None)
    if frag is None:
        raise ValueError("sim.dust.v.frag does not exist yet: call sim.initialize() first")
    profile = VFragProfile(
        monomer_radius, t_h2o=t_h2o, t_co2=t_co2, v_frag_refractory=v_frag_refractory,
        width=width, posteriors=posteriors, quantile=quantile, v_frag=v_frag,
    )

    def updater(s: Any) -> np.ndarray:
        return profile(s.gas.T)

    frag.updater = updater
    frag.update()
    return profile
