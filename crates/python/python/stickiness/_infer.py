"""The posterior of T_vis (and gamma_SV) from laboratory data: :func:`infer`.

Bayes' theorem with the likelihood of :mod:`._likelihood`, log-uniform priors, and an ensemble
sampler (:mod:`._sampler`: emcee's red-blue scheme with differential-evolution and snooker
moves) walking in log10 of the parameters; the integrated autocorrelation time (as emcee
computes it) judges the chain. pandas (and corner, for plots) are the optional extra
``stickiness[infer]``; importing :mod:`stickiness` never needs them.
"""

from __future__ import annotations

import math
import warnings
from typing import Any, Callable, Dict, Optional, Sequence, Tuple, Union

import numpy as np

from . import _args, _core
from ._args import StickinessWarning
from ._core import DEFAULT_K, DEFAULT_RADIUS, DEFAULT_REL_TOL
from ._data import Data
from ._judge import judged
from ._likelihood import PARAMETERS, RESTITUTION_NODES, Model, priors as _priors
from ._posterior import Posterior
from ._sampler import MIN_WALKERS, integrated_time, sample
from ._sizes import SizeDistribution

#: Default ensemble size: 32 walkers, the issue's speed target (at least twice the number of
#: free parameters, so that the differences of walkers span the parameter space).
DEFAULT_WALKERS = 32
#: Default chain length (steps per walker); a quarter is discarded as burn-in by default.
DEFAULT_STEPS = 2000
#: At most this many walkers: each step evaluates all of them (an ensemble of 1e5 already costs
#: seconds a step), and an absurd count is a typo, not a request.
MAX_WALKERS = 100_000
#: At most this many restitution radii: each is a collision per walker, datum and step.
MAX_RESTITUTION_NODES = 1024
#: emcee's rule of thumb (its documentation, "Autocorrelation analysis"): a chain shorter than
#: 50 integrated autocorrelation times gives an unreliable estimate of the time itself.
MIN_AUTOCORR_TIMES = 50.0

#: The share of snooker moves among the differential-evolution moves (emcee's
#: documentation, "Using different moves", uses 20 %).
SNOOKER_SHARE = 0.2

#: Starting the walkers: prior draws per round (at least; 8 per walker for large ensembles).
INIT_DRAWS = 256
#: ... at most this many rounds (the first from the prior, the rest around the best points).
INIT_ROUNDS = 12
#: ... done when the walkers' starting points lie within this many units of ln-posterior of the
#: best one (a ball the burn-in forgets in a few autocorrelation times).
INIT_SPREAD = 10.0
#: ... the smallest kernel width of a refinement round, as a fraction of the prior's width in
#: log10 (so that one point of a narrow allowed band still spreads its neighbours).
INIT_MIN_WIDTH = 1e-3
#: Starting points read off the data: sticking speeds used (their quantiles) ...
SEED_SPEEDS = 5
#: ... and gamma_SV values across its prior when it is free.
SEED_GAMMAS = 8
#: T_vis (s) of the one V_stick computed before sampling to check the arguments (k, rel_tol,
#: the geometry) with the core's messages: the paper's CO2 value.
DEFAULT_T_VIS_CHECK = 1e-9


def _require_pandas() -> None:
    """pandas, which the posterior's samples are, or an ``ImportError`` saying how to get it."""
    try:
        import pandas  # type: ignore[import-untyped,unused-ignore]  # noqa: F401
    except ImportError:
        raise ImportError(
            "stickiness.infer needs pandas: pip install 'stickiness[infer]'"
        ) from None


def _free(value: Any) -> Tuple[str, ...]:
    names = (value,) if isinstance(value, str) else value
    try:
        names = tuple(names)
    except TypeError:
        raise ValueError(f"free = {value!r}: expected names among {tuple(PARAMETERS)}") from None
    if not names:
        raise ValueError(f"free: empty; give at least one of {tuple(PARAMETERS)}")
    for n in names:
        if not isinstance(n, str) or n not in PARAMETERS:
            raise ValueError(f"free: unknown parameter {n!r}; allowed: {tuple(PARAMETERS)}")
    if len(set(names)) != len(names):
        raise ValueError(f"free = {names!r}: a parameter is named twice")
    return tuple(p for p in PARAMETERS if p in names)


def _count(name: str, value: Any, least: int, most: Optional[int] = None) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < least \
            or (most is not None and value > most):
        within = f">= {least}" if most is None else f"within {least} .. {most}"
        raise ValueError(f"{name} = {_args.shown(value)}: must be an integer {within}")
    return int(value)


def _sizes(radius: Any) -> SizeDistribution:
    if isinstance(radius, SizeDistribution):
        return radius
    try:
        r = _args.scalar("radius", _args.si("radius", radius))
    except TypeError as e:
        if "got an array" not in str(e):
            raise
        # one radius a collision is not modelled: the sample's radii are its distribution
        raise TypeError(
            f"{e}; for grains of several sizes pass st.SizeDistribution(radii) (the data's "
            f"collisions then each have a radius drawn from it; one radius a collision is not "
            f"supported)"
        ) from None
    if not (math.isfinite(r) and r > 0):
        raise ValueError(f"radius = {_args.shown(r)}: must be > 0 and finite (m), or a SizeDistribution")
    return SizeDistribution([r])


def _contradiction(sizes: SizeDistribution, data: Data) -> None:
    """One radius: a collision that stuck faster than one that bounced has probability 0."""
    if len(sizes) != 1 or data.sticking is None or data.sticking_err is not None:
        return
    v, stuck = data.sticking
    if stuck.any() and (~stuck).any() and v[stuck].max() >= v[~stuck].min():
        raise ValueError(
            f"sticking: a collision stuck at {v[stuck].max():g} m/s and one bounced at "
            f"{v[~stuck].min():g} m/s; for one radius the model sticks below V_stick and "
            f"bounces above it (give the speeds' errors as a third column, (v_in, stuck, "
            f"v_in_err), or a SizeDistribution as radius for a polydisperse sample)"
        )


def _seeds(model: Model, free: Tuple[str, ...], fixed: Dict[str, float], lo: np.ndarray,
           hi: np.ndarray) -> np.ndarray:
    """Candidate starting points (log10 coordinates) read off the data: the T_vis whose V_stick
    (at the sample's median radius) equals the measured threshold and its +-1, 2 sigma, or the
    speeds of the sticking outcomes, at a few gamma_SV across the prior when that is free.
    Sharp data make the posterior a needle that prior draws miss; these land in it."""
    data = model.data
    speeds = []
    if data.v_stick is not None:
        value, sigma = data.v_stick
        speeds += [value + j * sigma for j in (-2, -1, 0, 1, 2)]
    if data.sticking is not None:
        speeds += list(np.quantile(data.sticking[0], np.linspace(0, 1, SEED_SPEEDS)))
    if "t_vis" not in free or not speeds:
        return np.empty((0, lo.size))
    column = {p: i for i, p in enumerate(free)}
    gammas = (
        np.geomspace(10 ** lo[column["gamma_sv"]], 10 ** hi[column["gamma_sv"]], SEED_GAMMAS)
        if "gamma_sv" in column else [fixed["gamma_sv"]]
    )
    second = None if model.radius2 is None else np.array([model.radius2])
    found = []
    for g in gammas:
        m = model.material.replace(gamma_sv=float(g))
        for v in speeds:
            try:  # speeds below V_stick,JKR have no T_vis: skipped
                t = np.asarray(_core.fit_t_vis(
                    m, np.array([model.sizes.median]), second, model.wall, np.array([v]),
                    np.zeros(1), np.array([model.k]), None, model.rel_tol, model.method,
                )["t_vis"])[0]
            except (ValueError, RuntimeError):
                continue
            point = np.empty(lo.size)
            point[column["t_vis"]] = math.log10(t) if t > 0 else -np.inf
            if "gamma_sv" in column:
                point[column["gamma_sv"]] = math.log10(g)
            found.append(point)
    points = np.array(found).reshape(-1, lo.size)
    return points[np.all((points >= lo) & (points <= hi), axis=1)]


def _start(
    log_prob: Callable[[np.ndarray], np.ndarray],
    lo: np.ndarray,
    hi: np.ndarray,
    seeds: np.ndarray,
    walkers: int,
    rng: np.random.Generator,
) -> Tuple[np.ndarray, np.ndarray]:
    """Starting points (log10 coordinates) and their ln-posterior: prior draws and ``seeds``,
    refined by kernels around the points within ``INIT_SPREAD`` of the best until ``walkers``
    distinct points lie there (a cross-entropy search for the posterior's bulk)."""
    n = max(INIT_DRAWS, 8 * walkers)
    theta = np.concatenate([seeds, rng.uniform(lo, hi, size=(n, lo.size))])
    lp = log_prob(theta)
    for _ in range(INIT_ROUNDS - 1):
        finite = np.flatnonzero(np.isfinite(lp))
        if finite.size == 0:  # nothing explains the data yet: more prior draws
            new = rng.uniform(lo, hi, size=(n, lo.size))
        else:
            good = finite[lp[finite] >= lp[finite].max() - INIT_SPREAD]
            if np.unique(theta[good], axis=0).shape[0] >= walkers:
                break
            elite = good if good.size >= 2 else finite[np.argsort(-lp[finite])][:walkers]
            width = np.maximum(theta[elite].std(axis=0), INIT_MIN_WIDTH * (hi - lo))
            centres = theta[rng.choice(elite, size=n)]
            new = np.clip(centres + rng.normal(size=centres.shape) * width, lo, hi)
        theta = np.concatenate([theta, new])
        lp = np.concatenate([lp, log_prob(new)])
    finite = np.flatnonzero(np.isfinite(lp))
    if finite.size == 0:
        raise ValueError(
            f"data: no parameters within the priors explain them ({theta.shape[0]} draws, all "
            f"of probability 0); check the sticking outcomes against the priors' bounds"
        )
    _, distinct = np.unique(theta[finite], axis=0, return_index=True)
    finite = finite[distinct]
    best = finite[np.argsort(-lp[finite])][:walkers]
    if best.size < walkers:  # a very narrow allowed band: its points, slightly spread
        pick = rng.choice(best, size=walkers)
        jitter = rng.normal(size=(walkers, lo.size)) * 1e-6 * (hi - lo)
        start = np.clip(theta[pick] + jitter, lo, hi)
        return start, log_prob(start)
    return theta[best], lp[best]


def infer(
    material: Any,
    radius: Any = DEFAULT_RADIUS,
    *,
    v_stick: Optional[Tuple[Any, Any]] = None,
    sticking: Optional[Union[Tuple[Any, Any], Tuple[Any, Any, Any]]] = None,
    restitution: Optional[Tuple[Any, Any, Any]] = None,
    free: Sequence[str] = ("t_vis",),
    priors: Optional[Dict[str, Tuple[float, float]]] = None,
    t_vis: Optional[float] = None,
    k: float = DEFAULT_K,
    radius2: Optional[float] = None,
    wall: bool = False,
    walkers: int = DEFAULT_WALKERS,
    steps: int = DEFAULT_STEPS,
    burn: Optional[int] = None,
    seed: Optional[int] = None,
    progress: bool = False,
    method: str = "table",
    rel_tol: float = DEFAULT_REL_TOL,
    v_stick_quantile: float = 0.5,
    restitution_nodes: int = RESTITUTION_NODES,
) -> Posterior:
    """The posterior of T_vis (and gamma_SV) given measured thresholds, sticking outcomes and
    coefficients of restitution (SI units throughout).

    Parameters
    ----------
    material : Material or str
        The grains' material (a preset name such as ``'co2'``, or a JSON file's path).
    radius : float, Quantity or SizeDistribution, optional
        Radius R1 (m) of the grains, or the distribution of the sample's radii. Default 60e-6.
    v_stick : (float, float), optional
        A measured sticking threshold and its 1-sigma (m/s); Gaussian. For a sample of sizes it
        is compared with the ``v_stick_quantile`` (default: the median) of V_stick over the
        radii.
    sticking : (array_like, array_like of bool[, array_like]), optional
        Individual collisions, a tuple of columns: impact speeds (m/s), whether each stuck, and
        optionally each speed's 1-sigma (m/s, one for all or one each; Gaussian; needs scipy).
        With exact speeds P(stuck | v) is the weight of the radii with v < V_stick(R); with
        speed errors, the chance that the true speed lay below V_stick, so that outcomes of one
        radius may overlap.
    restitution : (array_like, array_like, array_like), optional
        Bouncing collisions, a tuple of columns: impact speeds (m/s), measured e and its
        1-sigma (one for all or one each); Gaussian. The
        model's e comes from the collision itself; a collision that sticks or hits twice is
        observed as e = 0 (Section 4.4). For a sample of sizes the likelihood integrates
        over the sample read as its quantile function, e computed at ``restitution_nodes``
        (default 16) radii and interpolated in ln R (needs scipy).
    free : sequence of {'t_vis', 'gamma_sv'}, optional
        The parameters to infer. Default ``('t_vis',)``.
    priors : dict, optional
        Log-uniform bounds ``{name: (lo, hi)}`` (SI) of free parameters. Defaults: T_vis over
        1e-16 - 1e-6 s; gamma_SV from half to twice the material's value (J/m^2).
    t_vis : float, optional
        T_vis (s) when it is not free (required then).
    k : float, optional
        Modulus ratio k (dimensionless). Default 0.01.
    radius2 : float, optional
        Radius R2 (m) of a second sphere of another size; default: two equal spheres.
    wall : bool, optional
        A sphere hitting a flat wall of the same material. Default False.
    walkers : int, optional
        Walkers of the ensemble (at least 4, and 2 per free parameter). Default 32.
    steps : int, optional
        Steps per walker. Default 2000.
    burn : int, optional
        Steps discarded as burn-in (0 <= burn < steps). Default ``steps // 4``.
    seed : int, optional
        Seed of the starting points and the sampler: the same seed, the same chain.
    progress : bool, optional
        Show a progress bar (tqdm's, on stderr). Default False.
    method : {'table', 'search'}, optional
        How V_stick is computed: the master table (microseconds; the exact search where the
        table cannot vouch for 1e-5) or always the search. Default ``'table'``.
    rel_tol : float, optional
        Relative tolerance of the searches (where the table does not answer). Default 1e-6.
    v_stick_quantile : float, optional
        The quantile of V_stick over a sample's radii a measured threshold stands for (0..1).
        Default 0.5.
    restitution_nodes : int, optional
        The radii of a ``SizeDistribution`` at which e is computed for each coefficient of
        restitution, equally spaced in ln R over the sample's range and interpolated to its
        radii (1-1024, at most the sample's own radii, which it then uses; 1: the median; a
        collision for each per walker and datum). Default 16; warned of where e computed at
        twice the sample's radii moves ln L at the chain's best point by more than 1.

    Returns
    -------
    Posterior
        Samples (``.samples``, a pandas DataFrame), ``.summary()``, ``.interval()``,
        ``.plot()``, ``.v_frag()``; the autocorrelation times in ``.autocorr_time``.

    Raises
    ------
    ValueError
        No data, a negative sigma, mismatched lengths, an unknown free parameter, bounds in
        the wrong order, ... (the message names the argument); data impossible for every
        parameter within the priors.
    ImportError
        pandas missing: ``pip install 'stickiness[infer]'``.

    Warns
    -----
    StickinessWarning
        A chain (after burn-in) shorter than 50 autocorrelation times; a 95 % interval reaching
        a bound of its prior (the data then set only a one-sided limit there; the prior sets
        the other end); Gaussian data (a threshold, coefficients of restitution) more than 3
        sigma (of their chi^2) from the model at the chain's best point, or a sticking outcome
        with probability below 1e-6 there (not fitted: a unit, a prior, or data sets that
        disagree); for a ``SizeDistribution``, restitution radii too few for the data (ln L at the
        chain's best point moving by more than 1 with e computed at twice the sample's radii:
        raise ``restitution_nodes``); restitution data with e = 0 at the speed of a sticking
        outcome that stuck (the same collision given twice: each datum counts as independent).

    Notes
    -----
    The walkers move in log10 of the parameters, where the priors are uniform. They start at
    the best of a few hundred prior draws and of points read off the data (the T_vis whose
    V_stick is the measured threshold or a sticking outcome's speed), refined around the best
    points until ``walkers`` distinct points lie within 10 of the best ln-posterior; the
    burn-in then forgets the start.
    V_stick is only needed up to the fastest speed the data can tell apart: 10 sigma above a
    measured threshold, twice the fastest sticking outcome; beyond, V_stick counts as lying
    there.

    Examples
    --------
    >>> import stickiness as st
    >>> post = st.infer("co2", 60e-6, v_stick=(0.04, 0.02), steps=300, seed=1)  # doctest: +SKIP
    >>> post.interval("t_vis", level=0.95)                                      # doctest: +SKIP
    (1.5e-16, 1.9e-09)
    """
    _require_pandas()
    material = _args.material(material)
    sizes = _sizes(radius)
    wall = _args.geometry(radius2, wall)
    radius2 = _args.scalar_option("radius2", _args.si("radius2", radius2))
    if radius2 is not None and not (math.isfinite(radius2) and radius2 > 0):
        raise ValueError(f"radius2 = {_args.shown(radius2)}: must be > 0 and finite (m)")
    # the contact's warnings (a radius of 60 m, most often meant in um; a Tabor parameter below
    # 1) at the caller's line, as every function gives them, before the chain hides them
    one = sizes.radii.size == 1
    b = _args.Broadcast(radius=float(sizes.radii[0]) if one else sizes.radii, radius2=radius2)
    found = b.call(_core.jkr, material, b.flat["radius"], b.flat.get("radius2"), wall)
    b.warn(found["warnings"], stacklevel=3)
    k = _args.scalar("k", k)
    method = _args.method(method)
    rel_tol = _args.scalar("rel_tol", rel_tol)
    quantile = _args.scalar("v_stick_quantile", v_stick_quantile)
    if not 0.0 <= quantile <= 1.0:
        raise ValueError(f"v_stick_quantile = {_args.shown(quantile)}: must be within 0 .. 1")
    free = _free(free)
    bounds = _priors(free, priors, material)
    fixed: Dict[str, float] = {}
    if "t_vis" not in free:
        if t_vis is None:
            raise ValueError("t_vis: give its value (s) when it is not free")
        fixed["t_vis"] = _args.scalar("t_vis", _args.si("t_vis", t_vis))
        if not (math.isfinite(fixed["t_vis"]) and fixed["t_vis"] > 0):
            raise ValueError(f"t_vis = {_args.shown(fixed['t_vis'])}: must be > 0 and finite (s)")
    elif t_vis is not None:
        raise ValueError("t_vis: a fixed value and free=('t_vis', ...) exclude each other")
    if "gamma_sv" not in free:
        fixed["gamma_sv"] = material.gamma_sv
    walkers = _count("walkers", walkers, max(MIN_WALKERS, 2 * len(free)), MAX_WALKERS)
    steps = _count("steps", steps, 1)
    burn = steps // 4 if burn is None else _count("burn", burn, 0)
    if burn >= steps:
        raise ValueError(f"burn = {burn}: must be < steps = {steps}")
    progress = _args.flag("progress", progress)
    if seed is not None:
        seed = _count("seed", seed, 0)
    data = Data.parse(v_stick, sticking, restitution)
    twice = data.counted_twice()
    if twice is not None:
        warnings.warn(twice, StickinessWarning, stacklevel=2)
    _contradiction(sizes, data)
    # checks k, rel_tol and the geometry once, with the core's messages
    nodes = _count("restitution_nodes", restitution_nodes, 1, MAX_RESTITUTION_NODES)
    model = Model(material, sizes, radius2, wall, k, data, method, rel_tol, quantile, nodes)
    model.v_stick(np.array([DEFAULT_T_VIS_CHECK]), None)

    lo = np.log10([bounds[p][0] for p in free])
    hi = np.log10([bounds[p][1] for p in free])
    column = {p: i for i, p in enumerate(free)}

    def log_prob(theta: np.ndarray) -> np.ndarray:
        theta = np.atleast_2d(theta)
        inside = ((theta >= lo) & (theta <= hi)).all(axis=1)
        if inside.all():
            # the common case, every proposal inside the priors: no masks
            return model.log_likelihood(*model_args(10.0 ** theta))
        out = np.full(theta.shape[0], -np.inf)
        if inside.any():
            out[inside] = model.log_likelihood(*model_args(10.0 ** theta[inside]))
        return out

    def model_args(x: np.ndarray) -> Tuple[np.ndarray, Optional[np.ndarray]]:
        """T_vis and gamma_SV (None: the material's) of the parameter rows ``x``."""
        t = x[:, column["t_vis"]] if "t_vis" in column else np.full(x.shape[0], fixed["t_vis"])
        g = x[:, column["gamma_sv"]] if "gamma_sv" in column else None
        return t, g

    rng = np.random.default_rng(seed)
    seeds = _seeds(model, free, fixed, lo, hi)
    start, lp0 = _start(log_prob, lo, hi, seeds, walkers, rng)
    # differential evolution with snooker updates (ter Braak & Vrugt 2008): on the curved
    # ridge along which T_vis and gamma_SV trade off (H2O, 9.6 m/s at 1.5 um; 32 walkers, 3000
    # steps) its autocorrelation times are 55 steps against 150 for emcee's default stretch
    # move, and 1-d posteriors lose nothing. Our own loop and snooker (_sampler, _moves): emcee's
    # loop costs more than the likelihood, its snooker is biased
    run = sample(log_prob, start, lp0, steps, rng, SNOOKER_SHARE, progress)
    chain = run.chain
    tau = integrated_time(chain[burn:])
    if steps - burn < MIN_AUTOCORR_TIMES * float(np.max(tau)):
        warnings.warn(
            f"the chain after burn-in ({steps - burn} steps) is shorter than "
            f"{MIN_AUTOCORR_TIMES:g} autocorrelation times ({float(np.max(tau)):.3g} steps "
            f"each): its quantiles are uncertain; raise steps",
            StickinessWarning,
            stacklevel=2,
        )
    for message in judged(model, chain, run.log_prob, burn, free, lo, hi, model_args):
        warnings.warn(message, StickinessWarning, stacklevel=2)
    return Posterior(
        chain=10.0 ** chain,
        log_prob_chain=run.log_prob,
        burn=burn,
        free=free,
        priors=bounds,
        fixed=fixed,
        material=material,
        sizes=sizes,
        k=k,
        method=method,
        autocorr_time={p: float(tau[i]) for i, p in enumerate(free)},
        acceptance_fraction=float(np.mean(run.acceptance_fraction)),
    )
