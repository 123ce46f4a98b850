"""A sample of radii read as a continuous distribution (stickiness._mixture): the closed forms
of the restitution likelihood and its probability integral transform against brute force over
u, and the likelihood of model-made restitution data against a quadrature over the continuous
lognormal they were drawn from. Each test names its truth."""

import math
from statistics import NormalDist

import numpy as np
import pytest

import stickiness as st
from stickiness._likelihood import Data, Model
from stickiness._mixture import Mixture

CO2 = st.Material.co2()
CELLS = (np.arange(200_000) + 0.5) / 200_000


def _curve(mixture, values):
    """The reading of ``values`` (at the mixture's radii) at the midpoints of 2e5 cells of u."""
    return np.interp(CELLS, mixture.positions, values)


@pytest.mark.parametrize("radii", [2, 7, 64])
def test_the_density_is_the_integral_over_the_sample(radii):
    # ln int exp(-z(u)^2 / 2) du, z = (e(u) - e) / s, e(u) linear in u between the radii's
    # mid-weights and constant beyond: scipy's adaptive quadrature segment by segment (relative
    # error 1e-12, scaled by the largest value of the integrand); data from inside the model's
    # range to 60 sigma outside (the logs' branch), and a sample whose e is flat over a segment
    # (its limit)
    from scipy.integrate import quad

    rng = np.random.default_rng(radii)
    w = rng.random(radii)
    w /= w.sum()
    mixture = Mixture(w)
    u = mixture.positions
    e_model = rng.uniform(0.2, 0.8, (3, radii, 1)) * np.ones((1, 1, 4))
    e_model[1, : radii // 2 + 1, :] = 0.5  # flat segments
    # nearly flat ones: z changes by 5e-5 over each, below FLAT_SEGMENT, at 60 sigma too
    e_model[2, : radii // 2 + 1, :] = 0.5 + 1e-6 * np.arange(radii // 2 + 1)[:, None]
    e = np.array([0.3, 0.55, 0.95, -1.0])
    sigma = np.array([0.05, 0.01, 0.02, 0.02])
    got = mixture.log_density(e_model, e, sigma)
    for walker in range(3):
        for j in range(4):
            z = (e_model[walker, :, j] - e[j]) / sigma[j]
            top = -0.5 * np.min(z**2)
            total = u[0] * math.exp(-0.5 * z[0] ** 2 - top)
            total += (1.0 - u[-1]) * math.exp(-0.5 * z[-1] ** 2 - top)
            for i in range(radii - 1):
                def f(x, i=i):
                    zz = z[i] + (z[i + 1] - z[i]) * (x - u[i]) / (u[i + 1] - u[i])
                    return math.exp(-0.5 * zz**2 - top)
                total += quad(f, u[i], u[i + 1], epsabs=0.0, epsrel=1e-12, limit=200)[0]
            want = top + math.log(total)
            assert got[walker, j] == pytest.approx(want, rel=1e-10, abs=1e-9), (walker, j)


@pytest.mark.parametrize("radii", [2, 64])
def test_the_deviate_is_the_probability_integral_transform(radii):
    # Phi^-1(int Phi((e - e(u)) / s) du) by the midpoint rule, from both tails
    rng = np.random.default_rng(10 + radii)
    w = rng.random(radii)
    w /= w.sum()
    mixture = Mixture(w)
    e_model = rng.uniform(0.2, 0.8, (2, radii, 1)) * np.ones((1, 1, 4))
    e = np.array([0.25, 0.5, 0.85, 0.1])
    sigma = np.array([0.05, 0.02, 0.02, 0.03])
    got = mixture.deviate(e_model, e, sigma)
    phi = np.vectorize(lambda x: 0.5 * math.erfc(-x / math.sqrt(2.0)))
    for walker in range(2):
        for j in range(4):
            r = (e[j] - _curve(mixture, e_model[walker, :, j])) / sigma[j]
            lower, upper = np.mean(phi(r)), np.mean(phi(-r))
            want = (NormalDist().inv_cdf(lower) if lower < upper
                    else -NormalDist().inv_cdf(upper))
            assert got[walker, j] == pytest.approx(want, rel=1e-6, abs=1e-6), (walker, j)


def test_the_restitution_likelihood_is_the_lognormal_s():
    # 30 values of e measured to 0.01 (e by st.collide at radii drawn from a lognormal of width
    # 0.3 about 60 um, T_vis = 1e-9 s): each datum's ln L as the chain computes it over the
    # 64-radius sample read as continuous (e at every radius of the sample:
    # restitution_nodes=64) against its likelihood over the continuous lognormal itself, a
    # mean over 4096 quantile radii; the absolute differences summed over the data stay below 1
    # (0.69). The radii as points, 8 equal-weight quantile radii (the likelihood before
    # 2026-11-29), miss it by 172
    sizes = st.SizeDistribution.lognormal(60e-6, 0.3)
    rng = np.random.default_rng(2)
    z = rng.standard_normal(30)
    v = 10 ** rng.uniform(-1.5, -0.5, 30)
    t = np.array([1e-9])
    e = st.collide(CO2, 60e-6 * np.exp(0.3 * z), 1e-9, v, method="table").e_observed
    e = np.abs(e + 0.01 * rng.standard_normal(30))
    sigma = np.full(30, 0.01)
    model = Model(CO2, sizes, None, False, 0.01, Data.parse(None, None, (v, e, sigma)), "table",
                  1e-6, 0.5, 64)
    got = model.e_mixture.log_density(model.e_interpolated(model.e_observed(t, None)), e,
                                      sigma)[0]
    q = (np.arange(4096) + 0.5) / 4096
    fine = 60e-6 * np.exp(0.3 * np.array([NormalDist().inv_cdf(x) for x in q]))
    e_fine = model.e_observed(t, None, radii=fine)[0]
    want = np.log(np.exp(-0.5 * ((e_fine - e) / 0.01) ** 2).mean(axis=0))
    assert np.abs(got - want).sum() < 1.0, got - want
    q8 = 60e-6 * np.exp(0.3 * np.array([NormalDist().inv_cdf((i + 0.5) / 8) for i in range(8)]))
    comb = model.e_observed(t, None, radii=q8)[0]
    points = np.log(np.exp(-0.5 * ((comb - e) / 0.01) ** 2).mean(axis=0))
    assert np.abs(points - want).sum() > 50.0, points - want


def test_a_sample_is_read_by_its_radii_and_weights_not_how_it_is_written():
    # synthetic truths: a radius of weight 0 is no grain of the sample, and a radius written
    # twice is one radius of twice the weight
    v = np.array([0.05, 0.1, 0.2])
    data = Data.parse(None, None, (v, np.array([0.3, 0.5, 0.6]), 0.02))
    t = np.array([1e-9])

    def ln_l(sizes):
        return Model(CO2, sizes, None, False, 0.01, data, "table", 1e-6, 0.5, 8) \
            .log_likelihood(t, None)[0]

    dropped = st.SizeDistribution([40e-6, 60e-6, 90e-6], weights=[0, 1, 0])
    assert dropped.radii.tolist() == [60e-6] and dropped.weights.tolist() == [1.0]
    assert ln_l(st.SizeDistribution([60e-6, 60e-6, 90e-6])) == pytest.approx(
        ln_l(st.SizeDistribution([60e-6, 90e-6], weights=[2, 1])), rel=1e-14)


def test_a_large_sample_is_read_at_its_quantiles():
    # numpy.percentile's "hazen" method reads sample i at (i + 1/2)/n, as the mixture does: a
    # sample of more radii than RESTITUTION_MIXTURE_MAX stands as that many equal-weight
    # quantiles of it
    from stickiness._likelihood import RESTITUTION_MIXTURE_MAX as n

    radii = np.random.default_rng(8).lognormal(np.log(60e-6), 0.3, 5000)
    data = Data.parse(None, None, (np.array([0.1]), np.array([0.5]), 0.02))
    model = Model(CO2, st.SizeDistribution(radii), None, False, 0.01, data, "table", 1e-6, 0.5,
                  16)
    q = (np.arange(n) + 0.5) / n
    want = np.exp(np.percentile(np.log(radii), 100 * q, method="hazen"))
    # (the cumulative weights' rounding: 1e-11 at the top)
    np.testing.assert_allclose(model.e_mixture_radii, want, rtol=1e-9)
    np.testing.assert_allclose(model.e_mixture.positions, q, rtol=1e-12)
