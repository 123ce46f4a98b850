"""What stickiness.infer says before a posterior is cited (stickiness._judge): where it is the
prior's rather than the data's, and data the model cannot fit. Each test names its truth: the
JKR limit of Section 5.1, data the model made, a chi^2 table."""

import math
import warnings

import numpy as np
import pytest

import stickiness as st

CO2 = st.Material.co2()
R = 60e-6  # the CO2 grains of Musiolik et al. (2016a), Section 5.1


def _warned(**kwargs):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        st.infer(CO2, R, walkers=16, steps=400, seed=5, **kwargs)
    return [str(w.message) for w in caught if issubclass(w.category, st.StickinessWarning)]


def test_data_the_model_cannot_fit_are_warned_of():
    # V_stick exceeds V_stick,JKR = 0.0166 m/s at every T_vis (Section 5.1): a threshold of
    # 0.005 +- 0.0005 m/s lies 23 sigma below any the model gives
    below = _warned(v_stick=(0.005, 0.0005))
    assert any("not fitted" in w and "priors' bounds" in w for w in below), below
    # e cannot exceed the elastic limit (1 - (V_stick,JKR/V_in)^2)^(1/2) (Section 5.1, the
    # JKR limit; about 0.56 at 0.02 m/s and 0.83 at 0.03 m/s): e = 0.99 +- 0.001 is not fitted
    elastic = _warned(restitution=([0.02, 0.03], [0.99, 0.99], [0.001, 0.001]))
    assert any("not fitted" in w for w in elastic), elastic
    # the paper's threshold, 0.04 +- 0.02 m/s, is fitted (V_stick,JKR only 1.2 sigma below)
    assert not any("not fitted" in w for w in _warned(v_stick=(0.04, 0.02)))


def test_a_posterior_bounded_by_its_prior_is_warned_of():
    # the paper's threshold: the JKR plateau (every T_vis below ~1e-11 s gives V_stick,JKR,
    # 1.2 sigma below 0.04 m/s; Section 5.1) is not rejected, so the posterior runs down to
    # the prior's lower bound and only its upper end is the data's
    paper = _warned(v_stick=(0.04, 0.02))
    assert any("reaches the lower bound of its prior (1e-16 s)" in w for w in paper), paper
    # data made by the model at T_vis = 3e-10 s confine it far inside the prior: no warning
    v = np.array([0.03, 0.05, 0.08, 0.12, 0.2])
    e = st.collide(CO2, R, 3e-10, v).e_observed
    inside = _warned(restitution=(v, e, np.full(5, 0.01)))
    assert not any("prior" in w for w in inside), inside


def test_the_misfit_deviate_reads_the_chi2_table():
    # the 0.1 % points of chi^2 (Abramowitz & Stegun, Table 26.8) lie 3.09 sigma out (the
    # normal's 0.1 % point); Wilson & Hilferty's transform gives that within 0.05
    from stickiness._judge import _chi2_sigmas

    for n, point in ((1, 10.828), (10, 29.588), (100, 149.449)):
        assert _chi2_sigmas(point, n) == pytest.approx(3.090, abs=0.05)


def test_the_misfit_of_restitution_is_a_normal_deviate():
    # one radius: z = (e - e_model) / sigma, so chi^2 is the sum of squares (its definition);
    # two radii of equal weight and e midway between theirs: the mixture's median, z = 0
    from stickiness._likelihood import Data, Model

    v = np.array([0.05, 0.08, 0.12])
    t = np.array([3e-10])
    model_e = st.collide(CO2, R, 3e-10, v, method="table").e_observed  # as the likelihood's
    e = np.clip(model_e + np.array([0.01, -0.02, 0.03]), 0, 1)
    one = Model(CO2, st.SizeDistribution([R]), None, False, 0.01,
                Data.parse(None, None, (v, e, 0.01)), "table", 1e-6, 0.5)
    chi2, n = one.misfit(t, None)
    assert n == 3 and chi2[0] == pytest.approx((((e - model_e) / 0.01) ** 2).sum(), rel=1e-9)
    pair = st.SizeDistribution([40e-6, 90e-6])
    e2 = st.collide(CO2, pair.radii, 3e-10, 0.08, method="table").e_observed
    mid = Model(CO2, pair, None, False, 0.01,
                Data.parse(None, None, (np.array([0.08]), np.array([e2.mean()]), 0.001)),
                "table", 1e-6, 0.5)
    assert mid.misfit(t, None)[0][0] == pytest.approx(0.0, abs=1e-12)


def test_too_few_restitution_radii_are_warned_of():
    # each datum's restitution ln L as the chain sees it (e by st.collide at the restitution
    # radii, interpolated in ln R to the sample's radii) against the same with e computed at the
    # sample's 64 radii and their 63 midpoints (127 collisions a speed), both integrated by
    # brute force over 1e5 cells of u (the sample read as its quantile function): warned of
    # where they differ by more than 1 in ln L, summed by size over the data. The model's own e
    # (lognormal of width 0.3 about 60 um, T_vis = 3e-10 s) changes by 0.6 over the sample at
    # 0.05-0.1 m/s: the median radius alone is coarse against e_err = 0.05, no number of radii
    # against 0.5
    from stickiness._judge import _coarse_restitution
    from stickiness._likelihood import Data, Model

    sizes = st.SizeDistribution.lognormal(median=R, width=0.3)
    v = np.array([0.05, 0.07, 0.1])
    e = np.array([0.2, 0.5, 0.6])
    mid = np.cumsum(sizes.weights) - 0.5 * sizes.weights
    cells = (np.arange(100_000) + 0.5) / 100_000

    def ln_l(u, e_at, e_err):
        # per datum: ln of the mean over the cells of exp(-z^2/2), e linear in u between radii
        return np.array([
            math.log(np.mean(np.exp(-0.5 * ((np.interp(cells, u, e_at[:, j]) - e[j])
                                            / e_err) ** 2)))
            for j in range(v.size)
        ])

    finer = np.sort(np.concatenate([sizes.radii, np.sqrt(sizes.radii[1:] * sizes.radii[:-1])]))
    u_finer = np.sort(np.concatenate([mid, 0.5 * (mid[1:] + mid[:-1])]))
    e_finer = st.collide(CO2, finer[:, None], 3e-10, v, method="table").e_observed
    assert np.ptp(e_finer[:, 0]) > 0.5
    seen = set()
    for nodes, e_err in ((1, 0.05), (1, 0.5), (8, 0.05), (8, 0.5), (8, 0.01)):
        data = Data.parse(None, None, (v, e, e_err))
        model = Model(CO2, sizes, None, False, 0.01, data, "table", 1e-6, 0.5, nodes)
        e_nodes = st.collide(CO2, model.e_radii[:, None], 3e-10, v, method="table").e_observed
        e_used = np.stack([np.interp(np.log(sizes.radii), np.log(model.e_radii), e_nodes[:, j])
                           for j in range(v.size)], axis=1)
        moved = np.abs(ln_l(mid, e_used, e_err) - ln_l(u_finer, e_finer, e_err)).sum()
        message = _coarse_restitution(model, (np.array([3e-10]), None))
        assert (message is not None) == (moved > 1.0), (nodes, e_err, moved, message)
        if message:
            assert f"moves by {moved:.2g} in ln L" in message and "restitution_nodes" in message
        seen.add(message is not None)
        if e_err == 0.5:
            assert message is None
    assert seen == {True, False}
    with pytest.raises(ValueError, match="restitution_nodes"):
        st.infer(CO2, sizes, restitution=(v, np.full(3, 0.5), 0.15), restitution_nodes=0)


def test_data_that_disagree_are_told_apart_from_the_priors():
    # a threshold of 0.08 +- 0.005 m/s against outcomes that stuck at 0.035 and bounced at
    # 0.045 m/s (60 um CO2: V_stick = 0.08 m/s needs T_vis = 2.9e-9 s, the outcomes 0.68-1.19e-9
    # s, fit_t_vis of each speed): the chain settles between them, inside the prior, and the
    # warning says the data disagree rather than blaming the priors
    w = _warned(v_stick=(0.08, 0.005), sticking=([0.03, 0.035, 0.045, 0.05], [1, 1, 0, 0]))
    misfit = [m for m in w if "not fitted" in m]
    assert misfit and "disagree" in misfit[0] and "lies chi^2" in misfit[0], w


def test_an_improbable_outcome_is_warned_of_with_speed_errors_too():
    # a collision that bounced at 0.01 m/s, below V_stick,JKR = 0.0166 m/s (Section 5.1: no
    # collision bounces below it at any T_vis), with speed errors of 0.1 mm/s: 66 sigma off,
    # for one radius (ln Phi) and a sample of two (Phi, then logs where it underflows) alike
    for radius in (R, st.SizeDistribution([55e-6, 65e-6])):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            st.infer(CO2, radius, sticking=([0.01, 0.03, 0.035, 0.045, 0.05],
                                            [False, True, True, False, False], 1e-4),
                     walkers=16, steps=200, seed=1)
        messages = [str(c.message) for c in caught]
        assert any("bounced at 0.01 m/s has probability" in m for m in messages), messages
