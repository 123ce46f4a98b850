"""The ensemble sampler of :func:`stickiness.infer`: emcee's red-blue scheme (Foreman-Mackey et
al. 2013, PASP 125, 306) with differential-evolution and snooker moves (:mod:`._moves`), written
out so that a step costs what its likelihood costs.

Each step picks one move (snooker with probability ``snooker_share``), splits the walkers at
random into sub-ensembles (two for differential evolution, four for the snooker) and updates
them in turn: proposals for one sub-ensemble from the others, one call of the vectorised
log-probability for all its walkers, Metropolis-Hastings acceptance with the move's factor.
That is emcee's ``EnsembleSampler.run_mcmc`` with its ``DEMove`` and our snooker move, step for
step; emcee's own loop costs 0.5-0.75 ms a step on this machine (32 walkers, one parameter, no
likelihood: 1.05-1.48 s for 2000 steps), more than the paper's CO2 posterior asks of its whole
run (`docs/performance.md`, "Inference"), and this one a quarter of it. The chain is judged by
its integrated autocorrelation time, computed as emcee computes it (:func:`integrated_time`),
so that sampling needs no emcee (whose import, through scipy.stats, costs 1.5 s).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, List, Tuple

import numpy as np

from ._moves import DE_SPLITS, SNOOKER_SPLITS, de_proposal, snooker_proposal

#: The fewest walkers the moves work with: each of the snooker's four sub-ensembles needs one.
MIN_WALKERS = SNOOKER_SPLITS

#: Sokal's window for the integrated autocorrelation time: the smallest M with M >= c tau(M),
#: c = 5 (Sokal 1997; emcee's ``autocorr.integrated_time`` default, which this follows).
AUTOCORR_WINDOW = 5.0

Proposal = Callable[[np.ndarray, List[np.ndarray], Any], Tuple[np.ndarray, np.ndarray]]


@dataclass
class Chains:
    """What a run gives: the walkers' positions and log-probabilities at every step, and the
    fraction of proposals each walker accepted."""

    #: (steps, walkers, parameters)
    chain: np.ndarray
    #: (steps, walkers)
    log_prob: np.ndarray
    #: (walkers,)
    acceptance_fraction: np.ndarray


def _update(
    log_prob: Callable[[np.ndarray], np.ndarray],
    x: np.ndarray,
    lp: np.ndarray,
    splits: int,
    propose: Proposal,
    random: np.random.Generator,
    accepted: np.ndarray,
) -> None:
    """One step of one move: every sub-ensemble in turn, ``x``, ``lp`` and ``accepted`` in place."""
    # a random partition into `splits` sub-ensembles of (nearly) equal size, as emcee's
    order = random.permutation(len(x))
    bounds = [len(x) * j // splits for j in range(splits + 1)]
    groups = [order[bounds[j] : bounds[j + 1]] for j in range(splits)]
    for split, mine in enumerate(groups):
        others = [x[g] for j, g in enumerate(groups) if j != split]
        q, factor = propose(x[mine], others, random)
        new = log_prob(q)
        # NaN (a rejected snooker proposal) compares False: the caller's errstate silences it
        take = factor + new - lp[mine] > np.log(random.random(len(mine)))
        chosen = mine[take]
        x[chosen] = q[take]
        lp[chosen] = new[take]
        accepted[chosen] += 1


def sample(
    log_prob: Callable[[np.ndarray], np.ndarray],
    start: np.ndarray,
    lp0: np.ndarray,
    steps: int,
    random: np.random.Generator,
    snooker_share: float,
    progress: bool = False,
) -> Chains:
    """Runs the walkers from ``start`` (walkers x parameters, at least :data:`MIN_WALKERS`) with
    log-probabilities ``lp0`` for ``steps`` steps. ``log_prob`` takes an (n, parameters) array
    and returns n values (``-inf`` outside the support); ``progress`` shows tqdm's bar on
    stderr."""
    walkers, ndim = start.shape
    if walkers < MIN_WALKERS:
        raise ValueError(f"walkers = {walkers}: must be at least {MIN_WALKERS}")
    x = np.array(start, dtype=float)
    lp = np.array(lp0, dtype=float)
    chain = np.empty((steps, walkers, ndim))
    lps = np.empty((steps, walkers))
    accepted = np.zeros(walkers)
    bar = None
    if progress:
        from tqdm.auto import tqdm  # type: ignore[import-untyped,unused-ignore]

        bar = tqdm(total=steps)
    # the acceptance tests' NaN and -inf - -inf silenced once for the run, not once a
    # sub-ensemble (entering an errstate costs a few microseconds, a tenth of a step)
    with np.errstate(invalid="ignore"):
        for i in range(steps):
            if random.random() < snooker_share:
                _update(log_prob, x, lp, SNOOKER_SPLITS, snooker_proposal, random, accepted)
            else:
                _update(log_prob, x, lp, DE_SPLITS, de_proposal, random, accepted)
            chain[i] = x
            lps[i] = lp
            if bar is not None:
                bar.update(1)
    if bar is not None:
        bar.close()
    return Chains(chain, lps, accepted / max(steps, 1))


def integrated_time(chain: np.ndarray) -> np.ndarray:
    """The integrated autocorrelation time (steps) of each parameter of ``chain`` (steps x
    walkers x parameters): the normalised autocorrelation function of each walker (by FFT,
    zero-padded to a power of two), averaged over the walkers, summed as tau(M) = 1 + 2
    sum_{t=1}^{M} rho(t) up to Sokal's window (the smallest M >= :data:`AUTOCORR_WINDOW`
    tau(M)); emcee's ``autocorr.integrated_time`` (Foreman-Mackey et al. 2013, Section 3 of
    its documentation's "Autocorrelation analysis"), with a walker that never moved counted
    as perfectly correlated (``inf``) instead of dividing by zero. Where no window is reached
    within the chain (tau(M) > M / 5 at every lag) the whole chain's sum is returned, a lower
    bound, where emcee returns tau(0) = 1."""
    steps = chain.shape[0]
    n = 1 << max(steps - 1, 1).bit_length()
    x = chain - chain.mean(axis=0)
    f = np.fft.rfft(x, n=2 * n, axis=0)
    acf = np.fft.irfft(f * np.conjugate(f), axis=0)[:steps]
    var = acf[0]
    # a walker that never moved (its mean need not be exact, its spread is)
    frozen = np.ptp(chain, axis=0) == 0.0
    with np.errstate(invalid="ignore", divide="ignore"):
        rho = np.where(frozen, 1.0, acf / np.where(frozen, 1.0, var))
    # averaged over the walkers: steps x parameters
    taus = 2.0 * np.cumsum(rho.mean(axis=1), axis=0) - 1.0
    out = np.empty(taus.shape[1])
    for d in range(taus.shape[1]):
        if np.all(frozen[:, d]):
            out[d] = np.inf
            continue
        short = np.arange(steps) < AUTOCORR_WINDOW * taus[:, d]
        window = int(np.argmin(short)) if np.any(short) and not np.all(short) else steps - 1
        out[d] = taus[window, d]
    return out
