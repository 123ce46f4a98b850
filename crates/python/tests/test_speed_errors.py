"""Sticking outcomes with speed errors (stickiness.infer, sticking=(v_in, stuck, v_in_err)):
P(stuck | v) is the chance that the true speed, Gaussian about the measured one, lay below
V_stick. Each test names its truth: that definition in closed form, the limit of exact speeds,
and data made with the model at a known T_vis."""

import math
import warnings

import numpy as np
import pytest

import stickiness as st
from stickiness._likelihood import Outcomes

CO2 = st.Material.co2()
R = 60e-6  # the CO2 grains of Musiolik et al. (2016a), Section 5.1


def phi(x):
    return 0.5 * math.erfc(-x / math.sqrt(2.0))


def test_the_likelihood_is_its_definition():
    # ln L = sum_j ln sum_i w_i Phi(+-(V_stick(R_i) - v_j) / s_j), + for a collision that stuck
    v = np.array([0.035, 0.02, 0.05, 0.031])
    stuck = np.array([True, True, False, False])
    err = np.array([0.003, 0.002, 0.004, 0.001])
    for w, V in ((np.array([1.0]), np.array([[0.03]])),
                 (np.array([0.25, 0.75]), np.array([[0.03, 0.04], [0.05, 0.02]]))):
        got = Outcomes(v, stuck, w, err).log_likelihood(V)
        for row, g in zip(V, got):
            want = sum(
                math.log(sum(wi * phi((Vi - x) / s if k else (x - Vi) / s)
                             for wi, Vi in zip(w, row)))
                for x, k, s in zip(v, stuck, err)
            )
            assert g == pytest.approx(want, rel=1e-12)


def test_exact_speeds_are_the_limit():
    # as the speeds' errors vanish, P(stuck | v) becomes the weight of the radii with
    # v < V_stick(R): the step of exact speeds, wherever no speed sits on a threshold
    v = np.array([0.012, 0.025, 0.033, 0.047])
    stuck = np.array([True, True, False, False])
    w = np.array([0.2, 0.3, 0.5])
    V = np.array([[0.03, 0.02, 0.04], [0.05, 0.045, 0.026]])
    step = Outcomes(v, stuck, w).log_likelihood(V)
    tiny = Outcomes(v, stuck, w, np.full(4, 1e-9)).log_likelihood(V)
    np.testing.assert_allclose(tiny, step, rtol=1e-12)


def test_outcomes_whose_speeds_overlap_give_back_the_truth():
    # one radius, 60 collisions at 0.5-1.5 V_stick with 5 % speed errors (the model's V_stick
    # at T_vis = 3e-10 s): exact speeds cannot explain a collision that stuck faster than one
    # that bounced (ValueError); with the errors given, the 95 % interval holds the truth
    t_true = 3e-10
    v_stick = st.v_stick(CO2, R, t_true).v_stick
    rng = np.random.default_rng(3)
    v_true = rng.uniform(0.5 * v_stick, 1.5 * v_stick, 60)
    v = v_true * (1 + 0.05 * rng.standard_normal(60))
    stuck = v_true < v_stick
    with pytest.raises(ValueError, match=r"\(v_in, stuck, v_in_err\)"):
        st.infer(CO2, R, sticking=(v, stuck))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", st.StickinessWarning)
        post = st.infer(CO2, R, sticking=(v, stuck, 0.05 * v), walkers=16, steps=600, seed=1)
    lo, hi = post.interval("t_vis", level=0.95)
    assert lo < t_true < hi and hi / lo < 3, (lo, hi)


@pytest.mark.parametrize(
    "err, match",
    [(0.0, r"v_in_err\[0\] = 0.0"), (-0.01, "v_in_err"), (np.nan, "v_in_err"),
     (np.ones(3), "v_in_err must be one number or one a speed")],
)
def test_bad_speed_errors_name_the_column(err, match):
    with pytest.raises(ValueError, match=match):
        st.infer(CO2, R, sticking=([0.02, 0.03], [True, False], err))


def test_speed_errors_take_quantities():
    # astropy quantities in any speed unit: 2 mm/s is 0.002 m/s (the same chain), a length is
    # named as the column's wrong unit
    u = pytest.importorskip("astropy.units")
    v, stuck = np.array([0.02, 0.03]), np.array([True, False])
    kw = dict(walkers=8, steps=20, seed=1)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", st.StickinessWarning)
        a = st.infer(CO2, R, sticking=(v, stuck, 2 * u.mm / u.s), **kw)
        b = st.infer(CO2, R, sticking=(v, stuck, 0.002), **kw)
    np.testing.assert_array_equal(a.chain, b.chain)
    with pytest.raises(ValueError, match="v_in_err: expected a quantity in m/s"):
        st.infer(CO2, R, sticking=(v, stuck, 2 * u.mm))
