"""The likelihood of the data of :func:`stickiness.infer` (:class:`Data`, in :mod:`._data`): a
measured threshold, individual sticking outcomes, coefficients of restitution. The model's
numbers come from the compiled core (V_stick from the master table or the search, e from single
collisions); nothing here integrates a collision.
"""

from __future__ import annotations

import math
from typing import Any, Dict, Optional, Sequence, Tuple

import numpy as np

from . import _args, _core
from ._core import Material
from ._data import Data
from ._mixture import Mixture, _phi
from ._sizes import SizeDistribution, weighted_quantile

#: The free parameters :func:`stickiness.infer` knows, and their SI units.
PARAMETERS: Dict[str, str] = {"t_vis": "s", "gamma_sv": "J/m^2"}

#: Default prior of T_vis (s): log-uniform over the whole range the model is used in, from the
#: JKR plateau (1e-16 s) past the no-bouncing cliff of every grain of the paper (1e-6 s).
DEFAULT_T_VIS_PRIOR: Tuple[float, float] = (1e-16, 1e-6)
#: Default prior of gamma_SV: log-uniform from this factor below to this factor above the
#: material's value (the H2O literature spans 0.02-0.19 J/m^2, Section 5.2).
DEFAULT_GAMMA_FACTOR = 2.0


#: Collisions for restitution data are integrated at a crack-speed number c_a of at most this:
#: below the T_vis where c_a reaches it, e has converged to the elastic (JKR) limit (3 mm CO2
#: grains at 1.5-10 V_stick,JKR: e moves by 3e-6 from c_a = 1e8 to 1e9 and by 7e-7 from 1e9 to
#: 1e10), while the collider refuses c_a > 3e10 (millions of steps). The master table clamps
#: its nodes at the same value.
C_A_MAX = 1e8
#: e is computed by collisions at this many radii of a polydisperse sample by default, equally
#: spaced in ln R over the sample's range (a collision for each per walker and datum: the cost
#: of e is what limits them), and interpolated linearly in ln R to the sample's radii, over which
#: the likelihood integrates in closed form (:mod:`._mixture`). Coarse where e bends between
#: them by more than a datum's sigma (:func:`stickiness.infer` warns then: ``restitution_nodes``).
#: 16 over a lognormal's +-3.5 widths lie 0.47 widths apart: over 200 model-made sets of 30 e
#: measured to 0.01 the 95 % interval held the truth in 94.5 % (8 radii, a width apart: 93 %,
#: and the warning fired for nearly every set; ``examples/python/restitution_coverage.py``).
RESTITUTION_NODES = 16
#: A sample of more radii enters the restitution likelihood through this many equal-weight
#: quantile radii (whose extremes, not the sample's, then bound the radii e is computed at):
#: each costs an interpolated e per walker, datum and step.
RESTITUTION_MIXTURE_MAX = 1024


def priors(free: Sequence[str], given: Any, material: Material) -> Dict[str, Tuple[float, float]]:
    """The log-uniform bounds of each free parameter (SI), defaults filled in."""
    out: Dict[str, Tuple[float, float]] = {
        "t_vis": DEFAULT_T_VIS_PRIOR,
        "gamma_sv": (
            material.gamma_sv / DEFAULT_GAMMA_FACTOR,
            material.gamma_sv * DEFAULT_GAMMA_FACTOR,
        ),
    }
    unknown = "{key!r} is not a free parameter (free = {keys!r})"
    for name, bounds in _args.keyed("priors", given, "{name: (lo, hi)}", free, unknown):
        if not isinstance(bounds, (tuple, list)) or len(bounds) != 2:
            raise ValueError(f"priors: {name}: expected (lo, hi) in {PARAMETERS[name]}")
        lo = _args.scalar(f"priors[{name!r}]", _args.si(name, bounds[0]))
        hi = _args.scalar(f"priors[{name!r}]", _args.si(name, bounds[1]))
        if not (math.isfinite(lo) and math.isfinite(hi) and 0 < lo < hi):
            raise ValueError(
                f"priors: {name} = ({_args.shown(lo)}, {_args.shown(hi)}): must be 0 < lo < hi, finite "
                f"({PARAMETERS[name]}; log-uniform bounds)"
            )
        out[name] = (lo, hi)
    return {name: out[name] for name in free}


class Model:
    """V_stick over the radii of the sample and e at the restitution speeds, for arrays of
    parameters; and the log-likelihood of the data.

    ``t_vis`` and ``gamma_sv`` are arrays of one length (one entry per walker); ``gamma_sv``
    None means the material's.
    """

    def __init__(
        self,
        material: Material,
        sizes: SizeDistribution,
        radius2: Optional[float],
        wall: bool,
        k: float,
        data: Data,
        method: str,
        rel_tol: float,
        v_stick_quantile: float,
        restitution_nodes: int = RESTITUTION_NODES,
    ) -> None:
        self.material = material
        self.sizes = sizes
        self.radius2 = radius2
        self.wall = wall
        self.k = k
        self.data = data
        self.method = method
        self.rel_tol = rel_tol
        self.quantile = v_stick_quantile
        # the thresholds are searched up to the fastest speed the data need (None: only
        # restitution data, no threshold needed)
        self.v_max = data.fastest() or None
        self.outcomes = None if data.sticking is None else Outcomes(
            *data.sticking, sizes.weights, data.sticking_err
        )
        self._fixed_by_walkers: Dict[int, Tuple[np.ndarray, Optional[np.ndarray], np.ndarray]] = {}
        # the restitution likelihood's radii (the sample's, or its quantiles where they are
        # many) and the fewer radii e is computed at, interpolated to them in ln R. Each radius
        # once, with its weight: the reading would otherwise depend on how the sample is written
        # ([60, 60, 90] um against [60, 90] with weights [2, 1]); a SizeDistribution has no
        # radius of weight 0
        fine, at = np.unique(sizes.radii, return_inverse=True)
        weights = np.bincount(at, weights=sizes.weights)
        if fine.size > RESTITUTION_MIXTURE_MAX:
            # the sample's (tied radii merged) equal-weight quantiles
            q = (np.arange(RESTITUTION_MIXTURE_MAX) + 0.5) / RESTITUTION_MIXTURE_MAX
            fine = SizeDistribution(fine, weights).quantile(q)
            weights = np.full(q.size, 1.0 / q.size)
        self.e_mixture = Mixture(weights)
        #: The radii (m) of the restitution likelihood's mixture.
        self.e_mixture_radii: np.ndarray = fine
        # one radius where the sample's radii are all one (nothing to space them over)
        nodes = min(restitution_nodes, fine.size) if fine[-1] > fine[0] else 1
        #: The radii (m) e is computed at, and the matrix that interpolates e from them to the
        #: mixture's radii (None: they are the mixture's radii).
        self.e_radii: np.ndarray = fine
        self.e_interpolation: Optional[np.ndarray] = None
        if nodes < fine.size:
            self.e_radii = (np.array([sizes.median]) if nodes == 1 else
                            np.exp(np.linspace(np.log(fine[0]), np.log(fine[-1]), nodes)))
            self.e_interpolation = np.stack(
                [np.interp(np.log(fine), np.log(self.e_radii), row) for row in np.eye(nodes)],
                axis=1,
            )
            if nodes > 1:  # the sample's own extremes, not their exp(ln) roundings
                self.e_radii[[0, -1]] = fine[[0, -1]]
        if data.restitution is not None and fine.size > 1:
            _phi()  # scipy, or an ImportError saying how to get it, before the chain

    def _second(self, n: int) -> Optional[np.ndarray]:
        return None if self.radius2 is None else np.full(n, self.radius2)

    def _call(self, core: Any, *args: Any) -> Any:
        """A core call, its bad input (a walker's gamma_SV, say) as a ``ValueError`` naming the
        argument."""
        try:
            return core(*args)
        except _core._InputError as e:
            raise ValueError(str(e)) from None

    def v_stick(self, t_vis: np.ndarray, gamma_sv: Optional[np.ndarray]) -> np.ndarray:
        """V_stick (m/s) of shape (walkers, radii); ``inf`` where it lies beyond the search
        limit (no bouncing up to it). One core call for every walker and radius."""
        n, r = t_vis.size, self.sizes.radii.size
        # radius-major: the walkers at one radius follow each other, so that the core makes
        # each radius's contact once (a contact costs a quarter of a table answer)
        g = None if gamma_sv is None else np.tile(gamma_sv, r)
        radii, second, k = self._fixed(n)
        d = self._call(
            _core.v_stick, self.material, radii, second, self.wall,
            np.ascontiguousarray(t_vis) if r == 1 else np.tile(t_vis, r), k,
            self.v_max, self.rel_tol, self.method, g,
        )
        vs = np.asarray(d["v_stick"]).reshape(r, n).T
        return np.where(np.isnan(vs), np.inf, vs)

    def _fixed(self, n: int) -> Tuple[np.ndarray, Optional[np.ndarray], np.ndarray]:
        """The arguments of :meth:`v_stick`'s core call that do not change between a sampler's
        steps, for ``n`` walkers (kept; read only): the radii, each repeated n times, the
        second radius and k."""
        fixed = self._fixed_by_walkers.get(n)
        if fixed is None:
            r = self.sizes.radii.size
            fixed = self._fixed_by_walkers.setdefault(n, (
                np.repeat(self.sizes.radii, n), self._second(n * r), np.full(n * r, self.k),
            ))
        return fixed

    def e_observed(self, t_vis: np.ndarray, gamma_sv: Optional[np.ndarray],
                   radii: Optional[np.ndarray] = None) -> np.ndarray:
        """The observed e (0 for sticking and double collisions, Section 4.4) at
        :attr:`e_radii` (or ``radii``, m), of shape (walkers, radii, speeds): one core call
        for every walker, radius and speed, answered by the restitution tables where they vouch
        (``method='table'``), by the ODE elsewhere."""
        assert self.data.restitution is not None
        v = self.data.restitution[0]
        radii = self.e_radii if radii is None else radii
        n, r, s = t_vis.size, radii.size, v.size
        rad = np.tile(np.repeat(radii, s), n)
        g = None if gamma_sv is None else np.repeat(gamma_sv, r * s)
        second = self._second(rad.size)
        c_a = self._call(
            _core.dimensionless, self.material, rad, second, self.wall, np.ones(rad.size), g
        )["c_a"]
        # c_a ~ 1/T_vis: below c_a(1 s)/C_A_MAX the elastic limit has been reached
        t = np.maximum(np.repeat(t_vis, r * s), c_a / C_A_MAX)
        c = self._call(
            _core.collide, self.material, rad, second, self.wall, t, np.tile(v, n * r),
            np.full(rad.size, self.k), None, False, self.method, g,
        )
        return np.asarray(c["e_observed"]).reshape(n, r, s)

    def log_likelihood(self, t_vis: np.ndarray, gamma_sv: Optional[np.ndarray]) -> np.ndarray:
        """ln L of the data for each walker (``-inf`` where the data are impossible)."""
        total = np.zeros(t_vis.size)
        if self.data.v_stick is not None or self.outcomes is not None:
            vs = self.v_stick(t_vis, gamma_sv)
            if self.data.v_stick is not None:
                total += -0.5 * self._threshold_z(vs) ** 2
            if self.outcomes is not None:
                total += self.outcomes.log_likelihood(vs)
        if self.data.restitution is not None:
            # the radius of each collision is unknown: the mixture over the sample's radii
            _, e, e_err = self.data.restitution
            e_model = self.e_interpolated(self.e_observed(t_vis, gamma_sv))
            total += self.e_mixture.log_density(e_model, e, e_err).sum(axis=1)
        return total

    def misfit(
        self,
        t_vis: np.ndarray,
        gamma_sv: Optional[np.ndarray],
        v_stick: Optional[np.ndarray] = None,
        e_model: Optional[np.ndarray] = None,
    ) -> Tuple[np.ndarray, int]:
        """chi^2 of the Gaussian data for each walker, and their number (0: sticking outcomes
        alone, chi^2 0): the threshold's z^2, and for each coefficient of restitution the z^2
        of its probability integral transform under the mixture over the sample's radii, z =
        Phi^-1(int Phi((e - e(u)) / sigma) du) (:meth:`Mixture.deviate`), which is (e -
        e_model) / sigma for one radius and a standard normal deviate for data the model made
        whatever the sample.
        ``v_stick`` (:meth:`v_stick`) and ``e_model`` (:meth:`e_observed`) at these parameters
        where the caller has them already, else computed."""
        chi2 = np.zeros(t_vis.size)
        n = 0
        if self.data.v_stick is not None:
            vs = self.v_stick(t_vis, gamma_sv) if v_stick is None else v_stick
            chi2 += self._threshold_z(vs) ** 2
            n += 1
        if self.data.restitution is not None:
            _, e, e_err = self.data.restitution
            if e_model is None:
                e_model = self.e_observed(t_vis, gamma_sv)
            deviate = self.e_mixture.deviate(self.e_interpolated(e_model), e, e_err)
            chi2 += (deviate**2).sum(axis=1)
            n += e.size
        return chi2, n

    def _threshold_z(self, vs: np.ndarray) -> np.ndarray:
        """(V_stick - V) / sigma of the measured threshold for each walker (rows of ``vs``):
        V_stick of the one radius, or its ``v_stick_quantile`` over the sample."""
        assert self.data.v_stick is not None
        value, sigma = self.data.v_stick
        clipped = vs if self.v_max is None else np.minimum(vs, self.v_max)
        q = (clipped[:, 0] if clipped.shape[1] == 1
             else weighted_quantile(clipped, self.sizes.weights, self.quantile))
        return (np.asarray(q) - value) / sigma

    def e_interpolated(self, e_model: np.ndarray) -> np.ndarray:
        """e at the mixture's radii from e at :attr:`e_radii` (walkers, radii, speeds),
        linear in ln R between them."""
        if self.e_interpolation is None:
            return e_model
        return (e_model.transpose(0, 2, 1) @ self.e_interpolation.T).transpose(0, 2, 1)


class Outcomes:
    """Sticking outcomes (speeds ``v`` in m/s, ``stuck`` booleans) prepared once for the
    likelihood of a sample of radii with ``weights``: the speeds sorted, the outcomes in that
    order, the walkers' offsets and weights of each number of walkers kept (a sampler asks with
    the same few shapes thousands of times)."""

    def __init__(self, v: np.ndarray, stuck: np.ndarray, weights: np.ndarray,
                 v_err: Optional[np.ndarray] = None) -> None:
        self.order = np.argsort(v, kind="stable")
        self.sorted_v = v[self.order]
        self.stuck = stuck[self.order]
        self.weights = weights
        self._shaped: Dict[int, Tuple[np.ndarray, np.ndarray]] = {}
        # with speed errors: the speeds' sigmas, in the speeds' order
        self.v_err = None if v_err is None else v_err[self.order]
        if self.v_err is not None:
            _phi()  # scipy, or an ImportError saying how to get it, before the chain

    def sorted_probability(self, v_stick: np.ndarray) -> np.ndarray:
        """P(stuck | v): for each walker (row of ``v_stick``, its V_stick at each radius, m/s)
        and each sorted speed, the weight of the radii with ``v < V_stick(R)``; shape (walkers,
        speeds). Each V_stick is placed among the sorted speeds once (one search for the whole
        array) and its weight added from there down: comparing every speed with every radius
        costs a sampler a millisecond a step at 300 speeds and 64 radii, a search a row a third
        of that."""
        rows, radii = v_stick.shape
        n = self.sorted_v.size
        shaped = self._shaped.get(rows)
        if shaped is None:
            shaped = self._shaped.setdefault(rows, (
                np.arange(rows)[:, None] * (n + 1),
                np.ascontiguousarray(np.broadcast_to(self.weights, (rows, radii))).ravel(),
            ))
        offsets, weights = shaped
        # the speeds strictly below each V_stick: they stick at that radius
        below = np.searchsorted(self.sorted_v, v_stick, side="left")
        # the weight of the radii with exactly p speeds below, per row; then summed from p = j + 1
        # up
        at = np.bincount((offsets + below).ravel(), weights=weights,
                         minlength=rows * (n + 1)).reshape(rows, n + 1)
        # summed from the top, each over the sum of all weights: where every radius sticks that
        # is the same sum in the same order, so P = 1 exactly and 1 - P = 0 (as P = 0 exactly
        # where none does), whatever the weights' sum rounds to
        above = np.cumsum(at[:, ::-1], axis=1)[:, ::-1]
        return np.minimum(above[:, 1:] / above[:, :1], 1.0)

    def log_likelihood(self, v_stick: np.ndarray) -> np.ndarray:
        """ln L of the outcomes for each walker: the sum of ln P(stuck | v) over the collisions
        that stuck and ln(1 - P) over those that bounced (``-inf`` where one is impossible)."""
        return self.log_observed(v_stick).sum(axis=1)

    def log_observed(self, v_stick: np.ndarray) -> np.ndarray:
        """ln P of each observed outcome (walkers, speeds in sorted order). With speed errors s:
        P(stuck | v) = sum_i w_i Phi((V_stick(R_i) - v) / s), the chance that the true speed
        lay below V_stick (Gaussian), and 1 - P from each term's other tail; a mixture takes Phi
        itself (half log_ndtr's cost) and logs only where that underflows (beyond 38 sigma)."""
        if self.v_err is not None:
            sign = np.where(self.stuck, 1.0, -1.0)
            z = sign * (v_stick[:, :, None] - self.sorted_v[None, None, :]) / self.v_err
            log_ndtr, ndtr = _phi()
            if self.weights.size == 1:
                return np.asarray(log_ndtr(z[:, 0, :]))
            p = np.einsum("wrs,r->ws", ndtr(z), self.weights)
            with np.errstate(divide="ignore"):
                out = np.log(p)
            tiny = p == 0.0
            if tiny.any():
                w, j = np.nonzero(tiny)
                terms = log_ndtr(z[w, :, j]) + np.log(self.weights)
                top = terms.max(axis=1)
                out[w, j] = top + np.log(np.exp(terms - top[:, None]).sum(axis=1))
            return out
        p = self.sorted_probability(v_stick)
        with np.errstate(divide="ignore"):
            return np.log(np.where(self.stuck, p, 1.0 - p))


def stuck_probability(v_stick: np.ndarray, weights: np.ndarray, v: np.ndarray) -> np.ndarray:
    """P(stuck | v) for each walker (row of ``v_stick``, m/s) and each speed of ``v`` (m/s, in
    its order): the weight of the radii with ``v < V_stick(R)`` (``Outcomes``)."""
    o = Outcomes(v, np.zeros(v.size, dtype=bool), weights)
    p = np.empty((v_stick.shape[0], v.size))
    p[:, o.order] = o.sorted_probability(v_stick)
    return p
