"""A sample of radii read as a continuous distribution, for the likelihoods of
:func:`stickiness.infer`.

A :class:`~stickiness.SizeDistribution` of radii R_1 < ... < R_n with weights w_i is read as its
quantile function, as :meth:`~stickiness.SizeDistribution.quantile` reads it: radius i sits at
the cumulative weight u_i = w_1 + ... + w_(i-1) + w_i / 2 (its mid-weight), a quantity of the
radius known at the radii (here e) is linear in u between them, and it keeps its end values
over the outer half-weights w_1 / 2 and w_n / 2. A probability over the sample is the integral
over u, done in closed form on each segment:

- the density of a measured e with Gaussian error s, int N(e; e(u), s) du: on a segment where
  z = (e(u) - e) / s runs linearly from z_a to z_b it is
  du (Phi(z_b) - Phi(z_a)) / (z_b - z_a) / s (:meth:`Mixture.log_density`);
- the probability integral transform of e, int Phi((e - e(u)) / s) du, with the antiderivative
  of Phi, x Phi(x) + phi(x) (:meth:`Mixture.deviate`).

The radii as points (the sample as exactly these grains) make the density of e a comb of
Gaussians, one a radius: where e changes between neighbouring radii by more than s the comb's
gaps, not the data, shape the posterior (``docs/model.md``, "Limits of the likelihood").
Sticking outcomes keep the radii as points (:class:`._likelihood.Outcomes`): a step of a
radius's weight in P(stuck | v), which moved no measured coverage at 64 radii, at a sixth of the
cost of the continuous reading (85 against 520 us a call of 16 walkers, 64 radii and 300
outcomes).
"""

from __future__ import annotations

import math
from typing import Any, Tuple

import numpy as np

from ._sizes import mid_weights

#: A segment over which z changes by less than this is taken at its midpoint, with the
#: second-order term of the mean of phi over it (the next term, (z dz)^4 / 1920, below 1e-13 out
#: to 36 sigma): the difference quotient of Phi loses digits as z_b - z_a -> 0.
FLAT_SEGMENT = 1e-4
#: Densities below this (relative to the Gaussian's peak; 35.9 sigma) are recomputed from
#: logs (``log_ndtr``), term by term, where the fast sum underflows or loses its digits.
TINY_DENSITY = 1e-280
#: The normal deviate of a probability integral transform is clipped at this tail probability
#: (37 sigma): beyond it ``ndtri`` has no digits left.
TINY_TAIL = 1e-300

_SQRT_2PI = math.sqrt(2.0 * math.pi)


class Mixture:
    """The sample of radii with ``weights`` (sum 1, the radii increasing) read as a continuous
    distribution: the weight of each segment between neighbouring mid-weights and of the two
    outer half-weights. :meth:`at` makes one from the radii's cumulative weights instead."""

    def __init__(self, weights: np.ndarray) -> None:
        self._place(mid_weights(weights))

    @classmethod
    def at(cls, positions: np.ndarray) -> "Mixture":
        """The reading with radii at the cumulative weights ``positions`` (increasing, within
        0 .. 1)."""
        mixture = cls.__new__(cls)
        mixture._place(np.asarray(positions, dtype=float))
        return mixture

    def _place(self, u: np.ndarray) -> None:
        #: Each radius's cumulative weight u (its mid-weight), increasing within 0 .. 1.
        self.positions = u
        #: The weight (a length in u) of each segment between neighbouring radii.
        self.segments = np.diff(u)
        #: The weights of the values kept beyond the first and last radius.
        self.ends = np.array([u[0], 1.0 - u[-1]]) if u.size > 1 else np.ones(1)

    def refined(self) -> "Mixture":
        """The same reading with a radius added in the middle of each segment (in u; in ln R,
        where ln R is linear in u between the radii)."""
        u = self.positions
        return Mixture.at(interleaved(u, 0.5 * (u[:-1] + u[1:]), axis=0))

    def log_density(self, e_model: np.ndarray, e: np.ndarray, sigma: np.ndarray) -> np.ndarray:
        """ln of int exp(-z(u)^2 / 2) du, z = (e(u) - e) / sigma, for each walker and datum:
        the log-density of the measured ``e`` (one a datum) given e at the radii ``e_model``
        (walkers, radii, data), up to the datum's constant -ln(sigma sqrt(2 pi)); shape
        (walkers, data). For one radius -z^2 / 2."""
        if e_model.shape[1] == 1:
            return -0.5 * ((e_model[:, 0, :] - e) / sigma) ** 2
        # (walkers, data, radii): the radii the contiguous axis of the differences and sums
        z = (e_model.transpose(0, 2, 1) - e[None, :, None]) / sigma[None, :, None]
        _, ndtr = _phi()
        # Phi at each radius from both sides, from one normal CDF of its smaller tail (scipy's
        # ndtr is most of the cost): Phi(z_b) - Phi(z_a) is taken from the tail both lie in,
        # without digits lost to 1 - tiny
        tail = ndtr(-np.abs(z))
        lower = np.where(z < 0.0, tail, 1.0 - tail)
        upper = np.where(z > 0.0, tail, 1.0 - tail)
        dz = np.diff(z)
        diff = np.where(np.minimum(z[..., :-1], z[..., 1:]) > 0.0,
                        -np.diff(upper), np.diff(lower))
        with np.errstate(divide="ignore", invalid="ignore"):
            mean = _SQRT_2PI * diff / dz
        flat = np.abs(dz) < FLAT_SEGMENT
        if flat.any():
            mid = 0.5 * (z[..., :-1] + z[..., 1:])[flat]
            mean[flat] = np.exp(-0.5 * mid**2) * (1.0 + (mid**2 - 1.0) * dz[flat] ** 2 / 24.0)
        density = mean @ self.segments + np.exp(-0.5 * z[..., [0, -1]] ** 2) @ self.ends
        with np.errstate(divide="ignore"):
            out = np.log(density)
        tiny = density < TINY_DENSITY
        if tiny.any():
            w, j = np.nonzero(tiny)
            out[w, j] = self._log_density_from_logs(z[w, j, :])
        return out

    def _log_density_from_logs(self, z: np.ndarray) -> np.ndarray:
        """:meth:`log_density` of rows of ``z`` (rows, radii) far in a tail, term by term in
        logs: ln(Phi(t1) - Phi(t2)) = ln Phi(t1) + ln(1 - exp(ln Phi(t2) - ln Phi(t1))) with
        t2 < t1 the segment's ends mirrored into the lower tail."""
        log_ndtr, ndtr = _phi()
        za, zb = z[:, :-1], z[:, 1:]
        near, far = np.minimum(np.abs(za), np.abs(zb)), np.maximum(np.abs(za), np.abs(zb))
        straddle = za * zb < 0.0
        near = np.where(straddle, 0.0, near)
        dz = np.abs(zb - za)
        with np.errstate(divide="ignore", invalid="ignore"):
            l1, l2 = log_ndtr(-near), log_ndtr(-far)
            # a segment across zero: |Phi(z_b) - Phi(z_a)| is at least Phi(0) - Phi(-|dz|)
            across = np.log(np.abs(ndtr(zb) - ndtr(za)))
            segment = np.where(
                straddle, across,
                l1 + np.log(-np.expm1(l2 - l1)),
            ) + 0.5 * math.log(2.0 * math.pi) - np.log(dz)
            flat = dz < FLAT_SEGMENT
            mid = 0.5 * (za + zb)
            segment = np.where(flat, -0.5 * mid**2 + np.log1p((mid**2 - 1.0) * dz**2 / 24.0),
                               segment)
            terms = np.concatenate([
                segment + np.log(self.segments)[None, :],
                -0.5 * z[:, [0, -1]] ** 2 + np.log(self.ends)[None, :],
            ], axis=1)
        top = terms.max(axis=1)
        return top + np.log(np.exp(terms - top[:, None]).sum(axis=1))

    def deviate(self, e_model: np.ndarray, e: np.ndarray, sigma: np.ndarray) -> np.ndarray:
        """Phi^-1 of the probability integral transform of each measured ``e`` under the
        mixture, F = int Phi((e - e(u)) / sigma) du, for each walker (e at the radii
        ``e_model``, shape (walkers, radii, data)); shape (walkers, data). (e - e_model) /
        sigma for one radius; a standard normal deviate for data the model made. Each tail is
        computed from its own side and clipped at :data:`TINY_TAIL`."""
        r = (e[None, None, :] - e_model) / sigma[None, None, :]
        if r.shape[1] == 1:
            return r[:, 0, :]
        lower = self._mean_phi(r)  # F
        upper = self._mean_phi(-r)  # 1 - F
        from scipy.special import ndtri  # type: ignore[import-untyped,unused-ignore]

        return np.where(
            lower < upper,
            ndtri(np.clip(lower, TINY_TAIL, 0.5)),
            -ndtri(np.clip(upper, TINY_TAIL, 0.5)),
        )

    def _mean_phi(self, r: np.ndarray) -> np.ndarray:
        """int Phi(r(u)) du over the mixture, r (walkers, radii, data) at the radii, linear in u
        between them: on a segment (H(r_b) - H(r_a)) / (r_b - r_a) with H(x) = x Phi(x) +
        phi(x), the antiderivative of Phi (Phi at the midpoint where the segment is flat)."""
        _, ndtr = _phi()
        ra, rb = r[:, :-1, :], r[:, 1:, :]
        dr = rb - ra
        flat = np.abs(dr) < FLAT_SEGMENT
        with np.errstate(divide="ignore", invalid="ignore"):
            mean = np.where(flat, ndtr(0.5 * (ra + rb)), (_h(rb) - _h(ra)) / dr)
        ends = ndtr(r[:, [0, -1], :])
        return (np.einsum("wms,m->ws", np.maximum(mean, 0.0), self.segments)
                + np.einsum("wms,m->ws", ends, self.ends))


def interleaved(at: np.ndarray, between: np.ndarray, axis: int) -> np.ndarray:
    """``at`` with ``between`` (one fewer along ``axis``) placed between its entries along
    ``axis``: the order of :meth:`Mixture.refined`'s radii."""
    shape = list(at.shape)
    shape[axis] = 2 * at.shape[axis] - 1
    out = np.empty(shape, dtype=np.result_type(at, between))
    lead = (slice(None),) * (axis % at.ndim)
    out[lead + (slice(0, None, 2),)] = at
    out[lead + (slice(1, None, 2),)] = between
    return out


def _h(x: np.ndarray) -> np.ndarray:
    """x Phi(x) + phi(x), the antiderivative of Phi; for x < 0 written as phi(x) - |x| Phi(x),
    which loses about x^2 of the digits far in the lower tail (1e-13 at x = -30)."""
    _, ndtr = _phi()
    return x * ndtr(x) + np.exp(-0.5 * x**2) / _SQRT_2PI


def _phi() -> Tuple[Any, Any]:
    """``scipy.special``'s ``log_ndtr`` and ``ndtr``, ln Phi and Phi, or an ``ImportError``
    saying how to get them."""
    try:
        from scipy.special import log_ndtr, ndtr  # type: ignore[import-untyped,unused-ignore]
    except ImportError:
        raise ImportError(
            "the likelihood of sticking outcomes with speed errors, and of restitution data over "
            "a sample of radii, needs scipy: pip install 'stickiness[infer]'"
        ) from None
    return log_ndtr, ndtr
