"""What a user should know before citing a posterior of :func:`stickiness.infer`: where it is
the prior's rather than the data's (a 95 % interval reaching a bound of its prior), data the
model does not fit within the priors (a unit slip, a threshold below V_stick,JKR), and a mixture
over a sample's radii too coarse for the restitution data."""

from __future__ import annotations

import math
from typing import Callable, List, Optional, Tuple

import numpy as np

from ._likelihood import PARAMETERS, Model
from ._mixture import interleaved

#: A 95 % interval that reaches into this outer share of a prior's range (in log10, where the
#: prior is uniform) at one end is bounded there by the prior, not by the data: a flat
#: posterior puts 5 % of its samples in each such share, one the data confine puts none.
PRIOR_EDGE = 0.05
#: The Gaussian data (threshold, coefficients of restitution; each of these by its probability
#: integral transform under the mixture over the sample's radii, ``Model.misfit``) at the
#: chain's best point more than this many standard deviations (of chi^2 with their number of
#: degrees of freedom, by the Wilson-Hilferty transform) from the model: they are not fitted
#: within the priors (p < 1.3e-3 for data the model made).
MISFIT_SIGMAS = 3.0
#: The restitution log-likelihood at the chain's best point moving by more than this (each
#: datum's change by size, summed) when e is computed at twice the radii
#: (``_coarse_restitution``): a posterior's shape changes visibly with a change of ln L of
#: order 1 across it.
COARSE_LN_L = 1.0
#: A sticking outcome whose probability at the chain's best point is below this is not fitted:
#: about 5 sigma of a Gaussian's one tail (a speed error larger than given, a mislabel).
OUTCOME_P_MIN = 1e-6


def judged(
    model: Model,
    chain: np.ndarray,
    log_prob: np.ndarray,
    burn: int,
    free: Tuple[str, ...],
    lo: np.ndarray,
    hi: np.ndarray,
    model_args: Callable[[np.ndarray], Tuple[np.ndarray, Optional[np.ndarray]]],
) -> List[str]:
    """What a user should know before citing the posterior: each parameter whose 95 % interval
    reaches a bound of its prior (:data:`PRIOR_EDGE`), Gaussian data the chain's best point
    leaves more than :data:`MISFIT_SIGMAS` from the model, and restitution radii too few for
    the data (``_coarse_restitution``). ``chain`` (steps, walkers, free) is
    in log10 of the parameters, ``log_prob`` (steps, walkers) its ln-likelihood."""
    out: List[str] = []
    after = chain[burn:].reshape(-1, len(free))
    for i, p in enumerate(free):
        low, high = np.quantile((after[:, i] - lo[i]) / (hi[i] - lo[i]), [0.025, 0.975])
        bounds = [f"{10.0 ** b:.3g} {PARAMETERS[p]}" for b in (lo[i], hi[i])]
        if low < PRIOR_EDGE and high > 1.0 - PRIOR_EDGE:
            out.append(
                f"the posterior of {p} reaches both bounds of its prior ({bounds[0]} and "
                f"{bounds[1]}): the data hardly constrain it, and its quantiles are the prior's"
            )
        elif low < PRIOR_EDGE or high > 1.0 - PRIOR_EDGE:
            # the bound reached, and the limit the data set at the other end
            bound, limit = (
                (f"lower bound of its prior ({bounds[0]})", "an upper limit (its 97.5 % quantile)")
                if low < PRIOR_EDGE
                else (f"upper bound of its prior ({bounds[1]})", "a lower limit (its 2.5 % quantile)")
            )
            out.append(
                f"the posterior of {p} reaches the {bound}: its quantiles there are the prior's, "
                f"not the data's; the data set {limit}, or widen priors={{'{p}': (lo, hi)}}"
            )
    best = chain.reshape(-1, len(free))[int(np.argmax(log_prob))]
    args = model_args(10.0 ** best[None, :])
    point = ", ".join(f"{p} = {10.0 ** best[i]:.3g} {PARAMETERS[p]}" for i, p in enumerate(free))
    # where the best point lies at a prior's bound, the priors hold the posterior there
    at_bound = bool(np.any(((best - lo) / (hi - lo) < PRIOR_EDGE)
                           | ((best - lo) / (hi - lo) > 1.0 - PRIOR_EDGE)))
    why = (
        "check their units (m/s) and the priors: the posterior follows the priors' bounds, not "
        "the data" if at_bound else
        "the data sets may disagree with each other, or with the model as set up (a unit, k, "
        "the geometry, a size distribution)"
    )
    # V_stick and e at the best point, once for every check below
    vs = None if model.data.v_stick is None and model.outcomes is None else model.v_stick(*args)
    e_best = None if model.data.restitution is None else model.e_observed(*args)
    chi2, n = model.misfit(*args, v_stick=vs, e_model=e_best)
    if n and _chi2_sigmas(float(chi2[0]), n) > MISFIT_SIGMAS:
        kinds = [w for w, given in (
            ("the measured threshold", model.data.v_stick is not None),
            ("the coefficients of restitution", model.data.restitution is not None),
        ) if given]
        verb = "lies" if kinds == ["the measured threshold"] else "lie"
        values = "1 value" if n == 1 else f"{n} values"
        out.append(
            f"the data are not fitted: at the chain's best point ({point}) {' and '.join(kinds)} "
            f"{verb} chi^2 = {float(chi2[0]):.3g} from the model ({values}, more than "
            f"{MISFIT_SIGMAS:g} sigma); {why}"
        )
    if model.outcomes is not None:
        assert vs is not None
        lp = model.outcomes.log_observed(vs)[0]
        worst = int(np.argmin(lp))
        if lp[worst] < math.log(OUTCOME_P_MIN):
            o = model.outcomes
            v, stuck = o.sorted_v[worst], bool(o.stuck[worst])
            out.append(
                f"the data are not fitted: at the chain's best point ({point}) the collision "
                f"that {'stuck' if stuck else 'bounced'} at {v:.4g} m/s has probability "
                f"{math.exp(lp[worst]):.2g} (the least of the sticking outcomes'; a mislabel, a "
                f"speed error larger than given, or a unit); {why}"
            )
    coarse = _coarse_restitution(model, args, e_best)
    if coarse:
        out.append(coarse)
    return out


def _coarse_restitution(
    model: Model,
    args: Tuple[np.ndarray, Optional[np.ndarray]],
    e_best: Optional[np.ndarray] = None,
) -> Optional[str]:
    """Where the sample's restitution radii are too few for the data: at the chain's best point
    the restitution log-likelihood of each datum as the chain saw it (e at the restitution
    radii, interpolated in ln R) and with e computed at twice as many radii of the sample (its
    radii and their midpoints) differ by more than :data:`COARSE_LN_L` summed over the data:
    the posterior may be shifted or too narrow. ``e_best``: e at the restitution radii and
    ``args``, where the caller has it."""
    if model.data.restitution is None or model.e_mixture_radii.size < 2:
        return None
    v, e, e_err = model.data.restitution
    e_model = model.e_observed(*args) if e_best is None else e_best
    used = model.e_mixture.log_density(model.e_interpolated(e_model), e, e_err)[0]
    radii = model.e_mixture_radii
    # e at the mixture's radii (known already where they are the restitution radii) and at
    # their midpoints in ln R, in the order of Mixture.refined
    at_radii = e_model if model.e_interpolation is None else model.e_observed(*args, radii=radii)
    between = model.e_observed(*args, radii=np.sqrt(radii[:-1] * radii[1:]))
    e_finer = interleaved(at_radii, between, axis=1)
    reference = model.e_mixture.refined().log_density(e_finer, e, e_err)[0]
    # summed by size, so that shifts of opposite sign do not hide each other
    moved = float(np.abs(used - reference).sum())
    if not moved > COARSE_LN_L:
        return None
    worst = int(np.argmax(np.abs(used - reference)))
    n, interpolated = model.e_radii.size, model.e_interpolation is not None
    more = (
        f"raise restitution_nodes (at most the sample's {radii.size} radii; a collision each "
        f"per walker, datum and step)" if interpolated else
        f"give the sample more radii (SizeDistribution.lognormal(..., nodes=N)) and raise "
        f"restitution_nodes with them"
    )
    where = ("e at the median radius alone" if n == 1 else
             f"e computed at {n} radii and interpolated" if interpolated else
             f"the sample's {n} radii")
    return (
        f"the restitution likelihood at the chain's best point moves by {moved:.2g} in ln L "
        f"(summed over the data, most at v_in = {v[worst]:.3g} m/s) when e is computed at "
        f"{2 * radii.size - 1} radii of the sample instead of {where}: too coarse for data "
        f"this precise (e_err down to {float(e_err.min()):.2g}), and the posterior may be "
        f"shifted or too narrow; {more}"
    )


def _chi2_sigmas(chi2: float, n: int) -> float:
    """The normal deviate of ``chi2`` with ``n`` degrees of freedom (Wilson & Hilferty 1931:
    (chi2/n)^(1/3) is nearly normal with mean 1 - 2/(9n) and variance 2/(9n))."""
    v = 2.0 / (9.0 * n)
    return float(((chi2 / n) ** (1.0 / 3.0) - (1.0 - v)) / math.sqrt(v))
