"""The result of :func:`stickiness.infer`: posterior samples of T_vis (and gamma_SV), their
summary, intervals and corner plot, and the V_frag of monomers they imply."""

from __future__ import annotations

import re
import warnings
from typing import Any, Dict, Optional, Sequence, Tuple

import numpy as np

from . import _args, _core
from ._args import StickinessWarning
from ._core import Material
from ._functions import v_frag as _v_frag
from ._likelihood import PARAMETERS
from ._sizes import SizeDistribution

#: The quantiles of :meth:`Posterior.summary` and :meth:`Posterior.v_frag`: the median, the
#: 68 % interval (16/84 %) and the 95 % interval (2.5/97.5 %).
SUMMARY_QUANTILES: Tuple[float, ...] = (0.5, 0.16, 0.84, 0.025, 0.975)
#: The exponent of the size law of T_vis (Section 5.3, Gundlach et al. 2015): T_vis ~ R1^1.11,
#: the library's (``thresholds::T_VIS_EXPONENT``).
SIZE_LAW_EXPONENT: float = _core.T_VIS_EXPONENT
#: :meth:`Posterior.v_frag` uses at most this many posterior samples (evenly thinned): the
#: quantiles then move by about 1 / sqrt(4000) of their spread.
V_FRAG_MAX_SAMPLES = 4000
#: Stands for "no bouncing up to the search limit" while quantiles are taken (finite, so that
#: interpolation next to it stays defined); quantiles within a factor 1e6 of it become inf.
_BEYOND = 1e300


def quantile_label(q: float) -> str:
    """``'median'`` for 0.5, else the percentage (``'16%'``, ``'97.5%'``)."""
    return "median" if q == 0.5 else f"{100 * q:g}%"


class Posterior:
    """Posterior samples of the free parameters from :func:`stickiness.infer` (SI units).

    Attributes
    ----------
    samples : pandas.DataFrame
        One column per free parameter (``t_vis`` in s, ``gamma_sv`` in J/m^2), one row per
        sample (all walkers, after the burn-in).
    log_prob : ndarray
        Log-posterior of each sample (up to a constant).
    chain : ndarray
        The whole chain, shape (steps, walkers, free parameters), SI.
    autocorr_time : dict
        Integrated autocorrelation time of each parameter (steps), after the burn-in.
    acceptance_fraction : float
        Mean acceptance fraction of the walkers.
    free : tuple of str
        The free parameters.
    priors : dict
        Their log-uniform bounds ``(lo, hi)`` (SI).
    fixed : dict
        The parameters held fixed (SI): ``t_vis`` or ``gamma_sv`` when not free.
    material : Material
        The material (with its own gamma_SV).
    sizes : SizeDistribution
        The radii the data refer to.
    reference_radius : float
        The radius (m) the inferred T_vis belongs to: the median of ``sizes``; the size law
        carries T_vis from it to other sizes.
    k : float
        Modulus ratio k.
    method : str
        How V_stick was computed: ``'table'`` or ``'search'``.
    """

    def __init__(self, *, chain: np.ndarray, log_prob_chain: np.ndarray, burn: int,
                 free: Sequence[str], priors: Dict[str, Tuple[float, float]],
                 fixed: Dict[str, float], material: Material, sizes: SizeDistribution,
                 k: float, method: str, autocorr_time: Dict[str, float],
                 acceptance_fraction: float) -> None:
        import pandas as pd  # type: ignore[import-untyped,unused-ignore]

        self.chain = chain
        self.free = tuple(free)
        self.priors = dict(priors)
        self.fixed = dict(fixed)
        self.material = material
        self.sizes = sizes
        self.reference_radius = sizes.median
        self.k = k
        self.method = method
        self.autocorr_time = dict(autocorr_time)
        self.acceptance_fraction = float(acceptance_fraction)
        flat = chain[burn:].reshape(-1, chain.shape[-1])
        self.samples = pd.DataFrame(flat, columns=list(self.free))
        self.log_prob = log_prob_chain[burn:].reshape(-1)

    def __repr__(self) -> str:
        parts = ", ".join(
            f"{p} median {self.samples[p].median():.3g} {PARAMETERS[p]}" for p in self.free
        )
        return f"Posterior({len(self.samples)} samples: {parts})"

    def _parameter(self, name: str) -> np.ndarray:
        if name in self.free:
            return self.samples[name].to_numpy()
        if name in self.fixed:
            return np.full(len(self.samples), self.fixed[name])
        raise ValueError(f"name = {name!r}: must be one of {self.free}")

    def summary(self) -> Any:
        """Median, 16/84 % and 2.5/97.5 % quantiles of each free parameter (SI).

        Returns
        -------
        pandas.DataFrame
            Index: the free parameters; columns ``median``, ``16%``, ``84%``, ``2.5%``,
            ``97.5%``.
        """
        import pandas as pd  # type: ignore[import-untyped,unused-ignore]

        rows = {
            p: [float(np.quantile(self.samples[p], q)) for q in SUMMARY_QUANTILES]
            for p in self.free
        }
        columns = [quantile_label(q) for q in SUMMARY_QUANTILES]
        return pd.DataFrame.from_dict(rows, orient="index", columns=columns)

    def interval(self, name: str, level: float = 0.68) -> Tuple[float, float]:
        """The central credible interval of ``name`` holding ``level`` of the posterior.

        Parameters
        ----------
        name : {'t_vis', 'gamma_sv'}
            A free parameter.
        level : float, optional
            Probability inside (0 < level < 1). Default 0.68.

        Returns
        -------
        (float, float)
            The (1 - level)/2 and (1 + level)/2 quantiles (SI).
        """
        if name not in self.free:
            raise ValueError(f"name = {name!r}: must be a free parameter, one of {self.free}")
        level = _args.scalar("level", level)
        if not 0.0 < level < 1.0:
            raise ValueError(f"level = {_args.shown(level)}: must be within 0 < level < 1")
        x = self.samples[name].to_numpy()
        lo, hi = np.quantile(x, [(1 - level) / 2, (1 + level) / 2])
        return float(lo), float(hi)

    def plot(self, **kwargs: Any) -> Any:
        """Corner plot of the free parameters in log10 (``corner.corner``).

        Parameters
        ----------
        **kwargs
            Passed to ``corner.corner`` (e.g. ``truths=[np.log10(t_true)]``, ``fig=``).

        Returns
        -------
        matplotlib.figure.Figure
        """
        try:
            import corner  # type: ignore[import-untyped,unused-ignore]
        except ImportError:
            raise ImportError(
                "Posterior.plot needs corner: pip install 'stickiness[infer]'"
            ) from None
        labels = {"t_vis": r"$\log_{10} T_{\rm vis}$ (s)",
                  "gamma_sv": r"$\log_{10} \gamma_{\rm SV}$ (J/m$^2$)"}
        kwargs.setdefault("labels", [labels[p] for p in self.free])
        kwargs.setdefault("quantiles", [0.16, 0.5, 0.84])
        kwargs.setdefault("show_titles", True)
        return corner.corner(np.log10(self.samples.to_numpy()), **kwargs)

    def t_vis_at(self, monomer_radius: Any, *, exponent: float = SIZE_LAW_EXPONENT) -> np.ndarray:
        """The posterior T_vis samples (s) carried to ``monomer_radius`` (m) by the size law
        T_vis ~ R1^exponent (Section 5.3) from ``reference_radius``; shape (samples,) or
        (samples, radii)."""
        r = _args.float_array("monomer_radius", monomer_radius)
        if not np.all(np.isfinite(r) & (r > 0)):
            raise ValueError(f"monomer_radius = {_args.shown(monomer_radius)}: must be > 0 and finite (m)")
        exponent = _args.scalar("exponent", exponent)
        if not np.isfinite(exponent):
            raise ValueError(f"exponent = {_args.shown(exponent)}: must be finite")
        t = self._parameter("t_vis")
        scale = (r / self.reference_radius) ** exponent
        return t[:, None] * np.atleast_1d(scale)[None, :] if r.ndim else t * float(scale)

    def v_frag(
        self,
        monomer_radius: Any = 1e-7,
        *,
        exponent: float = SIZE_LAW_EXPONENT,
        quantiles: Sequence[float] = (0.025, 0.16, 0.5, 0.84, 0.975),
        max_samples: int = V_FRAG_MAX_SAMPLES,
    ) -> Any:
        """Quantiles of V_frag = 10 V_stick (m/s) of aggregates of monomers of
        ``monomer_radius`` (m) over the posterior (Section 6).

        Each posterior T_vis is carried from ``reference_radius`` to the monomer size by the
        size law T_vis ~ R1^exponent (Section 5.3), with its gamma_SV when that is free; the
        monomers are two identical spheres.

        Parameters
        ----------
        monomer_radius : float, array_like or Quantity, optional
            Monomer radius (m). Default 1e-7 (0.1 um).
        exponent : float, optional
            Exponent of the size law. Default 1.11.
        quantiles : sequence of float, optional
            The quantiles (0..1). Default 2.5, 16, 50, 84 and 97.5 %.
        max_samples : int, optional
            At most this many posterior samples (evenly thinned). Default 4000.

        Returns
        -------
        pandas.Series or pandas.DataFrame
            For one radius, a Series indexed by quantile (``'2.5%'``, ..., ``'median'``, ...);
            for an array of radii, a DataFrame with one row per radius. ``inf`` where the
            quantile lies beyond the search limit (no collision bounces up to 1000 V_stick,JKR).
        """
        import pandas as pd  # type: ignore[import-untyped,unused-ignore]

        qs = [float(q) for q in np.atleast_1d(_args.float_array("quantiles", quantiles))]
        if not all(0.0 <= q <= 1.0 for q in qs):
            raise ValueError(f"quantiles = {_args.shown(quantiles)}: must be within 0 .. 1")
        if isinstance(max_samples, bool) or not isinstance(max_samples, (int, np.integer)) \
                or max_samples < 1:
            raise ValueError(f"max_samples = {_args.shown(max_samples)}: must be an integer >= 1")
        t = self.t_vis_at(monomer_radius, exponent=exponent)
        radii = np.atleast_1d(_args.float_array("monomer_radius", monomer_radius))
        t = t.reshape(len(self.samples), -1)
        n = len(self.samples)
        pick = np.unique(np.linspace(0, n - 1, min(int(max_samples), n)).astype(int))
        t = t[pick]
        gamma = self._parameter("gamma_sv")[pick] if "gamma_sv" in self.free else None
        values = np.empty_like(t)
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            if gamma is None:
                r = _v_frag(self.material, radii[None, :], t, k=self.k, method=self.method)
                values[:] = r.v_frag
            else:
                for i, g in enumerate(gamma):
                    m = self.material.replace(gamma_sv=float(g))
                    values[i] = _v_frag(m, radii, t[i], k=self.k, method=self.method).v_frag
        if caught:  # one warning, not one per posterior sample
            message = str(caught[0].message)
            if len(caught) > 1:  # one per sample's call: count them, drop the call's element
                first = re.sub(r"\s*\[first at element.*\]$", "", message)
                message = (f"{len(caught)} warnings over the {len(pick)} posterior samples' "
                           f"V_frag; the first: {first}")
            warnings.warn(
                message,
                StickinessWarning,
                stacklevel=2,
            )
        labels = [quantile_label(q) for q in qs]
        # no bouncing up to the search limit: V_frag lies above every speed searched, and a
        # quantile that reaches such samples is inf (np.quantile would give inf - inf = nan)
        values = np.where(np.isnan(values), _BEYOND, values)
        table = np.quantile(values, qs, axis=0).T
        table = np.where(table >= _BEYOND / 1e6, np.inf, table)
        if np.ndim(monomer_radius) == 0:
            return pd.Series(table[0], index=labels, name="v_frag")
        return pd.DataFrame(table, index=pd.Index(radii, name="monomer_radius"), columns=labels)

