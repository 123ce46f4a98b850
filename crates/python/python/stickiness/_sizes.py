"""The sizes of a grain sample: a weighted set of radii, e.g. a lognormal on nodes in ln R."""

from __future__ import annotations

import math
from statistics import NormalDist
from typing import Any, Dict, Optional, Tuple

import numpy as np

from . import _args

#: Nodes of :meth:`SizeDistribution.lognormal` by default: the 64 radii of the issue's speed
#: target; the sample's quantile function then lies within 0.003 standard deviations of ln R of
#: the lognormal's between its 2 % and 98 % quantiles.
DEFAULT_NODES = 64
#: :meth:`SizeDistribution.lognormal` places its nodes over this many standard deviations of ln
#: R either side of the median: a sample counts grains beyond its extreme radii as at them, and
#: 4.7e-4 of a lognormal's grains lie beyond 3.5 (equal-weight quantile nodes, 64 of them, had
#: ended at 2.4, beyond which lie 1.6 %: 1000 sticking outcomes then had the truth impossible in
#: 33 of 40 model-made sets, with these nodes in 1; ``docs/model.md``, "Limits of the
#: likelihood").
LOGNORMAL_Z_MAX = 3.5
#: Fewer nodes than this sit at the equal-weight quantiles (i + 1/2)/nodes instead: spread over
#: +-3.5 standard deviations they would leave the middle of the distribution empty (the
#: sample's quantile function between 2 and 98 % off by up to 1.0 standard deviation with 5
#: nodes, against 0.77 at the quantiles; with 6 nodes 0.58 against 0.67).
LOGNORMAL_MIN_SPREAD = 6
#: At most this many nodes: every likelihood evaluation asks V_stick at each of them.
MAX_NODES = 100_000


class SizeDistribution:
    """Radii R1 (m) of a grain sample with their weights (fractions of the grains).

    Parameters
    ----------
    samples : array_like or Quantity
        Radii R1 (m, > 0 and finite), e.g. measured grains or quadrature nodes.
    weights : array_like, optional
        Their weights (>= 0, not all 0; normalised to sum 1; radii of weight 0 are dropped).
        Default: equal weights.

    Raises
    ------
    TypeError, ValueError
        Radii or weights that are not numbers, not positive, of different lengths, or empty.

    Notes
    -----
    In :func:`stickiness.infer` the probability that a collision at speed v sticks is the
    weight of the radii with v < V_stick(R); a measured threshold is compared with a weighted
    quantile of V_stick(R); a coefficient of restitution's likelihood integrates its Gaussian
    over the sample read as its quantile function (radius i at its mid-weight u_i, as
    :meth:`quantile` reads it; e linear in u between the radii, constant beyond the first and
    last). Grains beyond the extreme radii count as at them: :meth:`lognormal`'s nodes reach 3.5
    standard deviations of ln R (4.7e-4 of the grains beyond).

    Examples
    --------
    >>> import stickiness as st
    >>> d = st.SizeDistribution.lognormal(median=60e-6, width=0.3)
    >>> len(d.radii), round(d.median * 1e6, 3)
    (64, 60.0)
    >>> st.SizeDistribution([40e-6, 60e-6], weights=[1, 3]).weights.tolist()
    [0.25, 0.75]
    """

    def __init__(self, samples: Any, weights: Optional[Any] = None) -> None:
        radii = np.atleast_1d(_args.float_array("samples", samples)).astype(float)
        if radii.ndim != 1 or radii.size == 0:
            raise ValueError(f"samples: expected a non-empty 1-d array of radii, got shape {radii.shape}")
        bad = ~(np.isfinite(radii) & (radii > 0))
        if bad.any():
            i = int(np.argmax(bad))
            raise ValueError(f"samples[{i}] = {_args.shown(radii[i])}: must be > 0 and finite (m)")
        if weights is None:
            w = np.full(radii.size, 1.0 / radii.size)
        else:
            w = np.atleast_1d(_args.float_array("weights", weights)).astype(float)
            if w.shape != radii.shape:
                raise ValueError(
                    f"weights: expected one weight per radius of samples ({radii.size}), got shape {w.shape}"
                )
            if not (np.all(np.isfinite(w)) and np.all(w >= 0) and w.sum() > 0):
                raise ValueError("weights: must be >= 0 and finite, and not all 0")
            w = w / w.sum()
            # a radius of weight 0 is no grain of the sample: kept, it would stand at a
            # cumulative weight of its own in the quantiles (stretching the sample to it)
            radii, w = radii[w > 0], w[w > 0]
        order = np.argsort(radii, kind="stable")
        #: The radii R1 (m), increasing.
        self.radii: np.ndarray = radii[order]
        #: Their weights (sum 1).
        self.weights: np.ndarray = w[order]

    @classmethod
    def lognormal(
        cls, median: Any, width: Any, *, nodes: int = DEFAULT_NODES
    ) -> "SizeDistribution":
        """A lognormal distribution of radii on ``nodes`` radii equally spaced in ln R.

        Parameters
        ----------
        median : float or Quantity
            Median radius (m, > 0).
        width : float
            Standard deviation of ln R1 (dimensionless, > 0): 80 % of the grains lie within a
            factor exp(1.2816 width) of the median.
        nodes : int, optional
            Number of radii, equally spaced in ln R over +-3.5 ``width`` about the median and
            weighted by the normal density of ln R there (fewer than 6: at the quantiles (i +
            1/2)/nodes, with equal weights). Default 64. A wide distribution reaches far: width
            2 spans radii from 1/1100 to 1100 times the median.

        Returns
        -------
        SizeDistribution

        Examples
        --------
        >>> import math, stickiness as st
        >>> # Musiolik et al. (2016a): 80 % of the CO2 grains between 40 and 120 um
        >>> w = math.log(120 / 40) / (2 * 1.2816)
        >>> d = st.SizeDistribution.lognormal(median=math.sqrt(40e-6 * 120e-6), width=w)
        >>> round(d.quantile(0.1) * 1e6), round(d.quantile(0.9) * 1e6)
        (40, 120)
        """
        median = _args.scalar("median", median)
        width = _args.scalar("width", width)
        if not (math.isfinite(median) and median > 0):
            raise ValueError(f"median = {_args.shown(median)}: must be > 0 and finite (m)")
        if not (math.isfinite(width) and width > 0):
            raise ValueError(f"width = {_args.shown(width)}: must be > 0 and finite (sigma of ln R)")
        if isinstance(nodes, bool) or not isinstance(nodes, (int, np.integer)) \
                or not 1 <= nodes <= MAX_NODES:
            raise ValueError(f"nodes = {_args.shown(nodes)}: must be an integer within 1 .. {MAX_NODES}")
        if nodes < LOGNORMAL_MIN_SPREAD:
            z = np.array([NormalDist().inv_cdf((i + 0.5) / nodes) for i in range(int(nodes))])
            weights = None
        else:
            z = np.linspace(-LOGNORMAL_Z_MAX, LOGNORMAL_Z_MAX, int(nodes))
            weights = np.exp(-0.5 * z**2)
        with np.errstate(over="ignore", under="ignore"):
            radii = median * np.exp(width * z)
        if not np.all(np.isfinite(radii) & (radii > 0)):
            raise ValueError(
                f"width = {width!r}: with median = {median!r} m the extreme nodes leave the "
                f"floating-point range (radii of {radii.min():g} .. {radii.max():g} m)"
            )
        return cls(radii, weights)

    def quantile(self, q: Any) -> Any:
        """The radius (m) below which a fraction ``q`` of the grains lie: ln R interpolated
        linearly in the cumulative weight between the radii's mid-weights (for equal weights
        ``numpy.percentile(ln R, 100 q, method="hazen")``), the extreme radii beyond them.

        Parameters
        ----------
        q : float or array_like
            Fractions of the grains (0 .. 1).

        Returns
        -------
        float or numpy.ndarray
            A float for one ``q``, an array of its shape otherwise.

        Examples
        --------
        >>> import stickiness as st
        >>> d = st.SizeDistribution([40e-6, 60e-6, 90e-6])
        >>> (d.quantile([0.0, 0.5, 2 / 3, 1.0]) * 1e6).round(2).tolist()
        [40.0, 60.0, 73.48, 90.0]
        """
        q = _args.float_array("q", q)
        if not np.all((q >= 0.0) & (q <= 1.0)):  # False for NaN too
            bad = q.ravel()[int(np.argmax(~((q >= 0.0) & (q <= 1.0)).ravel()))]
            raise ValueError(f"q = {_args.shown(bad)}: must be within 0 .. 1")
        out = np.exp(np.interp(q, mid_weights(self.weights), np.log(self.radii)))
        return float(out) if out.ndim == 0 else out

    @property
    def median(self) -> float:
        """The median radius (m)."""
        return self.quantile(0.5)

    def __len__(self) -> int:
        return int(self.radii.size)

    def __repr__(self) -> str:
        return (
            f"SizeDistribution({len(self)} radii, median {self.median:.3g} m, "
            f"{self.radii[0]:.3g} .. {self.radii[-1]:.3g} m)"
        )


#: The row offsets of :func:`_row_starts` by shape; a sampler asks with the same few.
_ROW_STARTS: Dict[Tuple[int, int], np.ndarray] = {}

#: The most shapes :data:`_ROW_STARTS` keeps (cleared when full).
_ROW_STARTS_KEPT = 64


def _row_starts(rows: int, n: int) -> np.ndarray:
    """The flat index of each row's first element, as a column: ``rows`` rows of ``n`` (kept:
    read only)."""
    starts = _ROW_STARTS.get((rows, n))
    if starts is None:
        if len(_ROW_STARTS) >= _ROW_STARTS_KEPT:
            _ROW_STARTS.clear()
        starts = _ROW_STARTS.setdefault((rows, n), (np.arange(rows) * n)[:, None])
    return starts


def mid_weights(weights: Any) -> np.ndarray:
    """Each radius's mid-weight along the last axis, w_1 + ... + w_(i-1) + w_i / 2: where a
    sample's quantile function (:meth:`SizeDistribution.quantile`, :func:`weighted_quantile`,
    the restitution mixture) places radius i, (i + 1/2)/n for equal weights."""
    w = np.asarray(weights, dtype=float)
    return np.cumsum(w, axis=-1) - 0.5 * w


def weighted_quantile(values: Any, weights: Any, q: float) -> Any:
    """The quantile ``q`` of ``values`` along the last axis with ``weights`` (sum 1): linear
    interpolation between the nodes' mid-weights (i + 1/2)/n for equal weights, clamped to the
    end values; an infinite value (a V_stick beyond the search limit) sorts last and is returned
    as it is once reached. A float for 1-d ``values``, an array of the leading shape otherwise."""
    v = np.asarray(values, dtype=float)
    lead = v.shape[:-1]
    n = v.shape[-1]
    v = v.reshape(-1, n)
    w = np.asarray(weights, dtype=float)
    # each row sorted by one flat take with the rows' offsets, and the ufuncs themselves, not
    # np.clip or take_along_axis (Python wrappers of a few microseconds each): a sampler calls
    # this at every step for all walkers
    starts = _row_starts(v.shape[0], n)
    order = np.argsort(v, axis=-1, kind="stable")
    flat = order + starts
    v = v.ravel()[flat]
    w = w[order] if w.ndim == 1 else np.broadcast_to(w, lead + (n,)).reshape(-1, n).ravel()[flat]
    mid = mid_weights(w)
    j = np.minimum(np.maximum(np.count_nonzero(mid < q, axis=-1), 1), max(n - 1, 1))
    lo, hi = np.maximum(j - 1, 0), np.minimum(j, n - 1)
    at_lo, at_hi = starts[:, 0] + lo, starts[:, 0] + hi
    a, b = v.ravel()[at_lo], v.ravel()[at_hi]
    ma, mb = mid.ravel()[at_lo], mid.ravel()[at_hi]
    with np.errstate(invalid="ignore", divide="ignore"):
        f = np.minimum(np.maximum(np.where(mb > ma, (q - ma) / (mb - ma), 0.0), 0.0), 1.0)
        out = np.where(f == 0.0, a, np.where(f == 1.0, b, a + f * (b - a))).reshape(lead)
    return float(out) if out.ndim == 0 else out
