"""astropy quantities as arguments: converted to SI, the same numbers as plain SI floats; a
quantity of the wrong dimension is a ValueError naming the argument and the unit it needs."""

import astropy.units as u
import numpy as np
import pytest

import stickiness as st

CO2 = st.Material.co2()


def test_quantities_give_the_numbers_of_si_floats():
    # the same numbers, to the rounding of the unit conversion (60 um is 6e-5 m to 1 ulp)
    plain = st.v_stick(CO2, 60e-6, 1e-9)
    quantities = st.v_stick(CO2, 60 * u.um, 1 * u.ns)
    assert quantities.v_stick == pytest.approx(plain.v_stick, rel=1e-9)
    fit = st.fit_t_vis(CO2, 0.06 * u.mm, 4 * u.cm / u.s, v_stick_err=2 * u.cm / u.s)
    assert fit.t_vis == pytest.approx(st.fit_t_vis(CO2, 60e-6, 0.04, v_stick_err=0.02).t_vis, rel=1e-5)
    arrays = st.jkr(CO2, np.array([30.0, 60.0]) * u.um)
    np.testing.assert_allclose(arrays.a_eq, st.jkr(CO2, [30e-6, 60e-6]).a_eq, rtol=1e-12)
    c = st.collide(CO2, 60 * u.um, 1e-9 * u.s, 45 * u.mm / u.s)
    assert c.outcome == "bouncing"


def test_materials_take_quantities():
    m = st.Material(gamma_sv=80 * u.mJ / u.m**2, young=CO2.young * u.Pa, poisson=CO2.poisson,
                    density=1.56 * u.g / u.cm**3)
    for field in ("gamma_sv", "young", "poisson", "density"):
        assert getattr(m, field) == pytest.approx(getattr(CO2, field), rel=1e-12)
    assert CO2.replace(density=1650 * u.kg / u.m**3).density == 1650.0


@pytest.mark.parametrize(
    "call, argument, unit",
    [
        (lambda: st.jkr(CO2, 60 * u.s), "radius", "m"),
        (lambda: st.v_stick(CO2, 60e-6, 1 * u.m), "t_vis", "s"),
        (lambda: st.collide(CO2, 60e-6, 1e-9, 1 * u.kg), "v_in", "m/s"),
        (lambda: st.v_stick(CO2, 60e-6, 1e-9, v_max=1 * u.s), "v_max", "m/s"),
        (lambda: st.Material(gamma_sv=1 * u.m, young=1e9, poisson=0.3, density=900), "gamma_sv", "J/m2"),
        (lambda: st.v_stick(CO2, 60e-6, 1e-9, k=0.01 * u.m), "k", "dimensionless"),
    ],
)
def test_wrong_dimensions_name_the_argument(call, argument, unit):
    with pytest.raises((ValueError, TypeError), match=argument):
        call()


def test_dimensionless_quantities_are_plain_numbers():
    # k is a ratio of moduli: a dimensionless Quantity is its plain number (1 percent is 0.01)
    plain = st.v_stick(CO2, 60e-6, 1e-9, k=0.01).v_stick
    assert st.v_stick(CO2, 60e-6, 1e-9, k=0.01 * u.dimensionless_unscaled).v_stick == plain
    assert st.v_stick(CO2, 60e-6, 1e-9, k=1 * u.percent).v_stick == plain
