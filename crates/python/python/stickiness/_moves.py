"""The proposals of :func:`stickiness.infer`'s sampler (:mod:`._sampler`): differential evolution
and its snooker update (ter Braak & Vrugt 2008, Statistics and Computing 18, 435), each for a
whole sub-ensemble of walkers in one numpy expression.

- :func:`de_proposal` is emcee's ``DEMove`` (ter Braak 2006; Nelson et al. 2013): x' = x +
  gamma (z1 - z2), z1 != z2 drawn from the other walkers, gamma = gamma0 (1 + s e) with gamma0 =
  2.38 / sqrt(2 d), e a standard normal and s = :data:`DE_SIGMA`; symmetric, so no acceptance
  factor.
- :func:`snooker_proposal` is the snooker update (Section 3): anchor z, unit vector
  u = (x - z) / |x - z|, proposal x' = x + gamma u (u . (z1 - z2)), acceptance factor
  (|x' - z| / |x - z|)^(d - 1). emcee 3.1.6 (the newest release) scales its ``DESnookerMove``
  by ``delta / sqrt(|delta|)`` instead of the unit vector: its step then grows with the
  distance to the anchor, the proposal is no longer symmetric, and the chain does not keep its
  target (a standard normal in one dimension, 32 walkers x 20000 steps of it alone: variance
  1.088 and P(|x| < 1) = 0.655 instead of 0.683). The fix is merged upstream (dfm/emcee#531)
  but not released.

``random`` is a :class:`numpy.random.Generator`.
"""

from __future__ import annotations

import math
from typing import Any, List, Tuple

import numpy as np

#: emcee's ``DEMove`` default: the relative width of the normal jitter of each differential
#: evolution step's length (ter Braak 2006: a jitter small against the target's width keeps
#: the chain from being confined to the walkers' differences).
DE_SIGMA = 1e-5

#: The snooker's step factor gamma: ter Braak & Vrugt (2008) draw it from U(1.2, 2.2); 1.7, its
#: mean, is emcee's default.
SNOOKER_GAMMA = 1.7

#: The sub-ensembles a differential-evolution step updates in turn (red-blue: the other half
#: proposes).
DE_SPLITS = 2

#: The sub-ensembles a snooker step updates in turn: z, z1 and z2 come from the three others.
SNOOKER_SPLITS = 4


def de_proposal(
    s: np.ndarray, c: List[np.ndarray], random: Any
) -> Tuple[np.ndarray, np.ndarray]:
    """Differential-evolution proposals for the walkers ``s`` (n x d) from the walkers of the
    other sub-ensembles ``c``, and the log of their acceptance factors (zero: symmetric)."""
    n, ndim = s.shape
    others = np.concatenate(c, axis=0) if len(c) > 1 else c[0]
    m = len(others)
    # two distinct other walkers for every walker, in random order (their difference's sign);
    # integers from one draw of uniforms (numpy's integers() costs more than the whole step)
    u = random.random((2, n))
    i = (u[0] * m).astype(np.intp)
    j = (u[1] * (m - 1)).astype(np.intp)
    j += j >= i
    gamma = 2.38 / math.sqrt(2.0 * ndim) * (1.0 + DE_SIGMA * random.standard_normal((n, 1)))
    q = s + gamma * (others[i] - others[j])
    return q, np.zeros(n)


def snooker_proposal(
    s: np.ndarray, c: List[np.ndarray], random: Any
) -> Tuple[np.ndarray, np.ndarray]:
    """Snooker proposals for the walkers ``s`` (n x d) from three other sub-ensembles ``c``, and
    the log of their acceptance factors."""
    n, ndim = s.shape
    # one walker of each of three other sub-ensembles for every walker, in random order
    u = random.random((6, n))
    picks = np.stack([cj[(uj * len(cj)).astype(np.intp)] for cj, uj in zip(c[:3], u)], axis=1)
    order = np.argsort(u[3:].T, axis=1)
    picks = picks[np.arange(n)[:, None], order]
    z, z1, z2 = picks[:, 0], picks[:, 1], picks[:, 2]
    delta = s - z
    norm = np.linalg.norm(delta, axis=1)
    # a walker on its anchor has no direction: its NaN proposal is rejected
    with np.errstate(invalid="ignore", divide="ignore"):
        u = delta / norm[:, None]
        q = s + SNOOKER_GAMMA * u * np.sum(u * (z1 - z2), axis=1, keepdims=True)
        factor = (ndim - 1.0) * (np.log(np.linalg.norm(q - z, axis=1)) - np.log(norm))
    return q, factor
