"""What stickiness.infer says before a posterior is cited (stickiness._judge): where it is the
prior's rather than the data's, and data the model cannot fit. Each test names its truth: the
JKR limit of Section 5.1, data the model made, a chi^2 table."""

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
    assert any("not fitted within the priors" in w for w in below), below
    # e cannot exceed the elastic limit (1 - (V_stick,JKR/V_in)^2)^(1/2) (Section 5.1, the
    # JKR limit; about 0.56 at 0.02 m/s and 0.83 at 0.03 m/s): e = 0.99 +- 0.001 is not fitted
    elastic = _warned(restitution=([0.02, 0.03], [0.99, 0.99], [0.001, 0.001]))
    assert any("not fitted within the priors" in w for w in elastic), elastic
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
