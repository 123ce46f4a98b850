"""The numbers Arakawa & Krijt (2021) state, through the Python package (as the Rust tests)."""

import math

import numpy as np
import pytest

import stickiness as st

CO2 = st.Material.co2()
H2O = st.Material.h2o()


def test_co2_constants_from_sound_speeds():
    # Section 3.2: v_lg = 2900, v_ts = 1650 m/s (rho = 1560 kg/m^3) give E = 10.7 GPa, nu = 0.26
    # as printed; the isotropic relations v_ts^2 = E / (2 rho (1 + nu)) and
    # v_lg^2 / v_ts^2 = 2 (1 - nu) / (1 - 2 nu), solved here, give them to every digit
    v_lg, v_ts, rho = 2900.0, 1650.0, 1560.0
    nu = (v_lg**2 - 2 * v_ts**2) / (2 * (v_lg**2 - v_ts**2))
    young = 2 * rho * v_ts**2 * (1 + nu)
    assert abs(young / 1e9 - 10.7) < 0.05 and abs(nu - 0.26) < 0.005
    assert CO2.young == pytest.approx(young, rel=1e-12)
    assert CO2.poisson == pytest.approx(nu, rel=1e-12)
    assert (CO2.gamma_sv, CO2.density) == (0.08, 1560.0)


def test_jkr_numbers():
    j = st.jkr(CO2, radius=60e-6)
    assert abs(j.v_stick_jkr - 1.66e-2) < 5e-5  # Section 5.1
    assert abs(j.tabor - 9.5) < 0.05  # Section 2.2
    # Section 6: E_stick = m* V^2/2 = 0.9355 F_crit delta_crit to the rounding of 14.18
    assert abs(j.e_stick / (0.9355 * j.f_crit * j.delta_crit) - 1) < 0.005 / 14.18


def test_section_4_outcomes():
    # Figure 2: 3.5, 4.05 and 4.5 cm/s stick, double-collide and bounce (CO2, 60 um, 1e-9 s)
    got = [st.collide(CO2, radius=60e-6, t_vis=1e-9, v_in=v).outcome for v in (0.035, 0.0405, 0.045)]
    assert got == ["sticking", "double", "bouncing"]
    bounce = st.collide(CO2, radius=60e-6, t_vis=1e-9, v_in=0.045)
    assert 0 < bounce.e < 1 and bounce.v_out < 0 and bounce.contact_time > 0
    assert st.collide(CO2, radius=60e-6, t_vis=1e-9, v_in=0.035).contact_time is None


def test_section_4_4_thresholds():
    # 4.04 and 4.14 cm/s are the first points of a 0.01 cm/s scan in the new regime
    r = st.v_stick(CO2, radius=60e-6, t_vis=1e-9)
    assert 0.0413 < r.v_stick <= 0.0414
    assert 0.0403 < r.v_double_onset <= 0.0404
    assert math.isnan(r.no_bouncing_below)


def test_section_5_1_fit():
    f = st.fit_t_vis(CO2, radius=60e-6, v_stick=0.04, v_stick_err=0.02)
    assert 8.4e-11 < f.t_vis_min <= 8.5e-11
    assert 1.97e-9 <= f.t_vis_max < 1.98e-9
    assert f.t_vis_min < f.t_vis < f.t_vis_max


def test_section_5_3_size_law_and_7_1_v_frag_jkr():
    assert abs(st.t_vis_law("h2o", 90e-6) / 9.4e-9 - 1) < 0.005
    assert abs(st.t_vis_law("CO2", 1e-6) - 1e-11) < 1e-25
    v = st.v_frag(CO2, radius=30e-6)
    assert v.t_vis == 0.0
    assert abs(v.v_frag / 0.296 - 1) < 0.0005 / 0.296  # the paper's rounding
    assert v.v_frag == 10 * v.v_stick  # the definition (Section 7.1), as the result reports it


def test_jkr_limit_and_growth_with_t_vis():
    # Section 5.1 / Figure 4: V_stick -> V_stick,JKR as T_vis -> 0 and grows with T_vis
    r = st.v_stick(CO2, radius=60e-6, t_vis=np.array([0.0, 1e-14, 1e-11, 1e-9, 1e-8]))
    assert r.v_stick[0] == r.v_stick_jkr[0]  # T_vis = 0: answered so by definition (plumbing)
    assert abs(r.v_stick[1] / r.v_stick_jkr[1] - 1) < 1e-3
    assert np.all(np.diff(r.v_stick) > 0)


def test_crack_law_signs():
    # Appendix A / Figure 1: v > 0 below beta = 1, v < 0 above, v(k, 1) = 0
    v = st.crack_speed(0.01, np.array([0.5, 1.0, 2.0]))
    assert v[0] > 0 and v[1] == 0 and v[2] < 0


def test_wall_ratio_is_two_to_the_sixth():
    # V_stick,JKR ∝ m*^(-1/2) R^(2/3): (R1, m1) against (R1/2, m1/2) gives 2^(1/6)
    w = st.jkr(CO2, radius=60e-6, wall=True).v_stick_jkr
    i = st.jkr(CO2, radius=60e-6).v_stick_jkr
    assert abs(w / i - 2 ** (1 / 6)) < 1e-12
