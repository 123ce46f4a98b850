"""The Python face: broadcasting, types, errors, warnings, pickling."""

import dataclasses
import math
import pathlib
import pickle
import re
import subprocess
import sys
import warnings

import numpy as np
import pytest

import stickiness as st

CO2 = st.Material.co2()


def same(a, b):
    """Results equal field by field, NaN equal to NaN (numbers), strings equal."""
    return all(
        x == y if isinstance(x, str) else np.array_equal(x, y, equal_nan=True)
        for x, y in zip(dataclasses.astuple(a), dataclasses.astuple(b))
    )


def test_scalars_give_floats_and_arrays_give_broadcast_shapes():
    r = st.v_stick(CO2, radius=60e-6, t_vis=1e-10)
    assert type(r.v_stick) is float and type(r.v_stick_jkr) is float
    t = np.geomspace(1e-12, 1e-9, 3)
    radius = np.array([[30e-6], [60e-6]])
    r = st.v_stick(CO2, radius=radius, t_vis=t)
    assert r.v_stick.shape == (2, 3) and r.v_stick_jkr.shape == (2, 3)
    # each element equals the scalar call
    assert r.v_stick[1, 2] == st.v_stick(CO2, radius=60e-6, t_vis=t[2]).v_stick
    j = st.jkr(CO2, radius=[1e-6, 2e-6, 3e-6])
    assert j.a_eq.shape == (3,)
    v = st.crack_speed(np.array([0.01, 0.02]), np.array([[0.5], [2.0]]))
    assert v.shape == (2, 2)
    c = st.collide(CO2, t_vis=1e-9, v_in=[0.035, 0.045])
    assert list(c.outcome) == ["sticking", "bouncing"]
    assert math.isnan(c.contact_time[0]) and c.contact_time[1] > 0
    assert st.t_vis_law("co2", np.array([1e-6, 2e-6])).shape == (2,)


def test_empty_arrays():
    r = st.v_stick(CO2, t_vis=np.array([]))
    assert r.v_stick.shape == (0,)


@pytest.mark.parametrize("bad", [(0, 1), (5, 250_000), (3000, 299_999), (299_998, 299_999)])
def test_of_two_bad_elements_the_first_is_named(bad):
    # the elements are computed in parallel chunks and blocks (crates/python/src/parallel.rs):
    # whichever finishes first, the error names the lowest index, as a loop would
    r = np.full(300_000, 60e-6)
    r[bad[1]], r[bad[0]] = -1.0, -2.0
    first = rf"^radius\[{bad[0]}\] = -2\.0: must be > 0"
    for f in (st.v_stick, st.v_frag, st.jkr):
        with pytest.raises(ValueError, match=first):
            f(CO2, r, 1e-9) if f is not st.jkr else f(CO2, r)
    t = np.full(300_000, 1e-9)
    t[bad[1]], t[bad[0]] = -1.0, -2.0
    with pytest.raises(ValueError, match=rf"^t_vis\[{bad[0]}\] = -2\.0"):
        st.dimensionless(CO2, 60e-6, t)


def test_bad_values_name_the_argument_and_element():
    with pytest.raises(ValueError, match=r"^radius\[1\] = nan: must be > 0 and finite \(m\)$"):
        st.v_stick(CO2, radius=[60e-6, np.nan], t_vis=1e-9)
    with pytest.raises(ValueError, match=r"^radius = -1\.0: must be > 0 and finite \(m\)$"):
        st.jkr(CO2, radius=-1.0)
    with pytest.raises(ValueError, match=r"^t_vis\[0, 1\] = -1e-9: must be >= 0"):
        st.v_stick(CO2, radius=[60e-6, 30e-6], t_vis=[[1e-9, -1e-9]])
    # every function of a collision states the collisions' range of k, whichever check refuses it
    with pytest.raises(ValueError, match=r"^k = 1\.5: must be 0 < k <= 0\.9 for a collision"):
        st.v_stick(CO2, t_vis=1e-9, k=1.5)
    with pytest.raises(ValueError, match=r"^k = 0\.0: must be 0 < k <= 0\.9 for a collision"):
        st.collide(CO2, 60e-6, 1e-9, 0.001, k=0.0)
    # the crack law alone holds for any k below 1
    with pytest.raises(ValueError, match=r"^k = 1\.5: must be 0 < k < 1"):
        st.crack_speed(1.5, 1.0)
    # a collision needs k <= 0.9 (dynamics::K_MAX): the search refuses k = 0.95 by name
    with pytest.raises(ValueError, match=r"^k = 0\.95: must be 0 < k <= 0\.9 for a collision"):
        st.v_stick(CO2, t_vis=1e-9, k=0.95)
    with pytest.raises(ValueError, match=r"^k = 0\.99: must be 0 < k <= 0\.9"):
        st.collide(CO2, 60e-6, 1e-9, 0.001, k=0.99)
    with pytest.raises(ValueError, match=r"^beta\[2\] = 200\.0"):
        st.crack_speed(0.01, [0.5, 1.0, 200.0])
    with pytest.raises(ValueError, match=r"^v_in = 0\.0"):
        st.collide(CO2, t_vis=1e-9, v_in=0.0)
    with pytest.raises(ValueError, match=r"^t_vis = 0\.0: must be > 0"):
        st.collide(CO2, t_vis=0.0, v_in=1.0)
    # a Poisson ratio of 0 is no collision (the drag A = T_vis/nu^2 of Section 2.5 is infinite)
    flat = st.Material(gamma_sv=0.1, young=7e9, poisson=0.0, density=930.0)
    assert np.isfinite(st.jkr(flat).v_stick_jkr)
    nonzero = r"^poisson = 0\.0: must be .* nonzero for a collision"
    with pytest.raises(ValueError, match=nonzero):
        st.v_stick(flat, t_vis=1e-9)
    with pytest.raises(ValueError, match=nonzero):
        st.collide(flat, t_vis=1e-9, v_in=0.01)
    with pytest.raises(ValueError, match=r"^young = -1\.0: must be > 0"):
        st.Material(gamma_sv=0.1, young=-1.0, poisson=0.25, density=930.0)
    # a preset's name or a file given to the constructor points to Material.named
    with pytest.raises(TypeError, match=r"Material\.named\('iron'\)"):
        st.Material("iron")
    with pytest.raises(TypeError, match=r"Material\.from_json\("):
        st.Material(pathlib.Path("ice.json"))
    with pytest.raises(TypeError, match=r"missing poisson, density: it takes the four constants"):
        st.Material(0.1, 7e9)
    with pytest.raises(TypeError, match=r"^gamma_sv: expected a number, got str"):
        st.Material("0.1", 7e9, 0.25, 930.0)
    with pytest.raises(ValueError, match="radius2 and wall"):
        st.jkr(CO2, radius2=1e-6, wall=True)
    with pytest.raises(ValueError, match="cannot be broadcast"):
        st.v_stick(CO2, radius=[1e-6, 2e-6], t_vis=[1e-9, 1e-10, 1e-11])


def test_fit_below_jkr_gives_v_stick_jkr():
    # Section 5.1: V_stick > V_stick,JKR (1.66e-2 m/s for CO2, R1 = 60 um) for every T_vis > 0,
    # so a value below it is refused with V_stick,JKR as `jkr` gives it
    jkr = st.jkr(CO2, 60e-6).v_stick_jkr
    assert jkr == pytest.approx(1.66e-2, abs=5e-5)
    message = rf"^v_stick = 0\.016: must be > V_stick,JKR = {re.escape(repr(jkr))} "
    with pytest.raises(ValueError, match=message):
        st.fit_t_vis(CO2, v_stick=0.016)


def test_wrong_types():
    with pytest.raises(TypeError, match=r"^radius: expected real numbers, got text \('sixty'\)"):
        st.jkr(CO2, radius="sixty")
    with pytest.raises(TypeError, match=r"^t_vis: expected real numbers, got complex numbers"):
        st.v_stick(CO2, t_vis=[1e-9 + 1j])
    with pytest.raises(TypeError, match="material"):
        st.jkr(42)
    with pytest.raises(TypeError, match="v_in"):
        st.collide(CO2, t_vis=1e-9)
    with pytest.raises(TypeError, match="t_vis"):
        st.v_stick(CO2)
    # the argument by its name in the signature, t_vis_law(law, radius)
    with pytest.raises(ValueError, match=r"^law = 'co3': must be 'co2' or 'h2o'"):
        st.t_vis_law("co3", 1e-6)
    # integers and lists of numbers are numbers (1 and 2 m earn a warning)
    with pytest.warns(st.StickinessWarning):
        assert st.jkr(CO2, radius=[1, 2]).a_eq.shape == (2,)


def test_no_bouncing_is_nan_with_the_limit():
    r = st.v_stick(CO2, t_vis=[1e-9, 1e-6], v_max=2.0)
    assert not math.isnan(r.v_stick[0]) and math.isnan(r.no_bouncing_below[0])
    assert math.isnan(r.v_stick[1]) and r.no_bouncing_below[1] == 2.0


def test_warnings():
    with pytest.warns(st.StickinessWarning, match="Tabor"):
        st.jkr(CO2, radius=1e-8)
    with pytest.warns(st.StickinessWarning, match="did you mean 60e-6 m"):
        st.jkr(CO2, radius=60.0)
    with pytest.warns(st.StickinessWarning, match=r"2 of 3 elements"):
        st.jkr(CO2, radius=[60.0, 60e-6, 70.0])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        st.jkr(CO2, radius=60e-6)  # no warning for the paper's grains
    # CO2's constants of Section 3 in cgs (80 erg/cm^2, 1.56 g/cm^3): named, with the SI value
    cgs = CO2.replace(gamma_sv=80.0, density=1.56)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        st.v_stick(cgs, [60e-6, 30e-6], 1e-9)
    messages = [str(w.message) for w in caught]
    assert any("gamma_sv = 80.0 J/m^2" in m and "that is 0.08 J/m^2" in m for m in messages)
    assert any("density = 1.56 kg/m^3" in m and "that is 1560.0 kg/m^3" in m for m in messages)
    assert issubclass(st.StickinessWarning, UserWarning)
    assert issubclass(st.SolverError, RuntimeError)


def test_a_search_limit_below_the_jkr_threshold_is_warned_of():
    """V_stick >= V_stick,JKR at every T_vis (Section 5.1), so a ``v_max`` below V_stick,JKR
    (here a slip of cm/s for m/s) finds no bouncing whatever the grains: the answer stands, with
    a warning naming both speeds, in ``v_stick`` and ``v_frag``, per element in arrays; the
    default limit and any ``v_max`` above V_stick,JKR give none."""
    jkr = st.jkr(CO2, 60e-6).v_stick_jkr
    with pytest.warns(st.StickinessWarning, match=r"v_max=0\.01 m/s is below V_stick,JKR"):
        r = st.v_stick(CO2, 60e-6, 1e-9, v_max=0.01)
    assert math.isnan(r.v_stick) and r.no_bouncing_below == 0.01 < jkr
    with pytest.warns(st.StickinessWarning, match=r"1 of 2 elements"):
        st.v_frag(CO2, [60e-6, 1e-6], 1e-9, v_max=0.1)  # 1 um: V_stick,JKR 0.50 m/s; 60 um 0.017
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        st.v_stick(CO2, 60e-6, 1e-9)
        st.v_stick(CO2, 60e-6, 1e-9, v_max=2 * jkr)


def test_a_size_law_of_the_other_ice_is_warned_of():
    """The size laws of Section 5.3 belong to their ices: CO2's constants with H2O's law (or the
    reverse) are warned of at the caller's line, naming the law probably meant; each ice with
    its own law, another material, and T_vis given outright are not."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        st.v_frag(CO2, 1e-7, t_vis_law="h2o")
    assert [w.filename for w in caught] == [__file__]
    assert "t_vis_law = 'co2' was probably meant" in str(caught[0].message)
    with pytest.warns(st.StickinessWarning, match=r"t_vis_law = 'co2' \(the size law of CO2 ice"):
        st.v_stick("h2o", 1e-6, t_vis_law="co2")
    with pytest.warns(st.StickinessWarning, match="constants of H2O ice"):
        st.collide(st.Material.h2o(), 1e-6, t_vis_law="co2", v_in=1.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        st.v_stick(CO2, 1e-6, t_vis_law="co2")
        st.v_stick("h2o", 1e-6, t_vis_law="h2o")
        st.v_stick(CO2.replace(density=1000.0), 1e-6, t_vis_law="h2o")  # a material of one's own
        st.v_stick(CO2, 1e-6, st.t_vis_law("h2o", 1e-6))


def test_material_value_semantics(tmp_path):
    assert st.Material.co2() == CO2 and st.Material.h2o() != CO2
    assert hash(st.Material.co2()) == hash(CO2)
    assert pickle.loads(pickle.dumps(CO2)) == CO2
    assert repr(st.Material.h2o()) == "Material(gamma_sv=0.1, young=7000000000.0, poisson=0.25, density=930.0)"
    m = eval(repr(CO2), {"Material": st.Material})
    assert m == CO2
    assert CO2.replace(density=1650.0).density == 1650.0
    p = tmp_path / "ice.json"
    p.write_text('{"gamma_sv": 0.1, "young": 7e9, "poisson": 0.25, "density": 930}')
    assert st.Material.from_json(p) == st.Material.h2o()
    p.write_text('{"gamma_sv": 0.1, "young": 7e9, "poisson": 0.25, "density": -930}')
    with pytest.raises(ValueError, match=r"ice\.json: density = -930\.0"):
        st.Material.from_json(p)
    with pytest.raises(FileNotFoundError):
        st.Material.from_json(tmp_path / "missing.json")
    # a preset name works wherever a material does
    assert st.jkr("h2o", radius=90e-6) == st.jkr(st.Material.h2o(), radius=90e-6)


def test_trajectory():
    c = st.collide(CO2, t_vis=1e-9, v_in=0.045, trajectory=True)
    t = c.trajectory
    assert set(t) >= {"t", "a", "delta", "delta_dot", "beta"}
    assert t["delta"][0] == 0.0 and t["delta_dot"][0] == 0.045  # Section 2.5
    assert abs(t["beta"][0] / 0.0101 - 1) < 1e-9  # beta = (1 + eps) k
    assert np.all(np.diff(t["t"]) > 0)
    assert st.collide(CO2, t_vis=1e-9, v_in=0.045).trajectory is None
    with pytest.raises(ValueError, match="scalar"):
        st.collide(CO2, t_vis=1e-9, v_in=[0.04, 0.05], trajectory=True)


def test_geometry_arguments():
    a = st.v_stick(CO2, radius=60e-6, radius2=30e-6, t_vis=1e-9)
    b = st.v_stick(CO2, radius=30e-6, radius2=60e-6, t_vis=1e-9)
    assert same(a, b)  # swapping the spheres changes nothing, to the bit
    equal = st.v_stick(CO2, radius=60e-6, radius2=60e-6, t_vis=1e-9)
    assert same(equal, st.v_stick(CO2, radius=60e-6, t_vis=1e-9))
    law = st.v_stick(CO2, radius=60e-6, t_vis_law="co2")
    assert law.t_vis == st.t_vis_law("co2", 60e-6)
    with pytest.raises(ValueError, match="not both"):
        st.v_stick(CO2, t_vis=1e-9, t_vis_law="co2")


def test_core_refuses_arrays_of_other_lengths():
    # the package broadcasts its arguments; the compiled core, called directly, checks them
    from stickiness import _core

    one, two = np.array([60e-6]), np.array([60e-6, 30e-6])
    with pytest.raises(ValueError, match="radius2: length 2 differs from 1"):
        _core.jkr(CO2, one, two, False)


def test_the_core_answers_floats_with_floats_and_arrays_with_arrays():
    # a call of floats (the package's scalar calls) makes no arrays; the numbers are those of
    # the same call with arrays of one element, bit for bit, and a 1-element array stays one
    from stickiness import _core

    args = (CO2, 60e-6, None, False, 1e-9, 0.01, None, 1e-6, "table")
    arrays = (CO2, np.array([60e-6]), None, False, np.array([1e-9]), np.array([0.01]),
              None, 1e-6, "table")
    floats, ones = _core.v_stick(*args), _core.v_stick(*arrays)
    assert type(floats["v_stick"]) is float and type(floats["method"]) is int
    assert isinstance(ones["v_stick"], np.ndarray) and ones["v_stick"].shape == (1,)
    for key in ("v_stick", "v_double_onset", "v_stick_jkr", "v_max"):
        assert floats[key] == ones[key][0], key
    assert floats["method"] == ones["method"][0] == 1
    # one array among floats: arrays out
    mixed = _core.v_stick(CO2, np.array([60e-6]), None, False, 1e-9, 0.01, None, 1e-6, "table")
    assert mixed["v_stick"].shape == (1,)
    j = _core.jkr(CO2, 60e-6, None, False)
    one = _core.jkr(CO2, np.array([60e-6]), None, False)
    assert type(j["a_eq"]) is float and j["a_eq"] == one["a_eq"][0]


def test_version():
    assert isinstance(st.__version__, str) and st.__version__.count(".") == 2


def test_the_public_names_are_those_of_all():
    # what tab completion shows a user after `import stickiness` (a fresh interpreter: other
    # tests import `stickiness.dustpy`, which then shows too): the documented API (`__all__`)
    # and the `sweeps` module (imported by `sweep`), nothing imported along the way
    code = "import stickiness as st; print(*[n for n in dir(st) if not n.startswith('_')])"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert set(out.stdout.split()) == set(st.__all__) - {"__version__"} | {"sweeps"}


def test_warnings_point_at_the_callers_line():
    # Python's convention for library warnings: the location is the user's call, so that the
    # default filter shows each one once per calling line
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        st.jkr(CO2, radius=60.0)
        st.v_stick(CO2, radius=60.0, t_vis=1e-9)
    assert [w.filename for w in caught] == [__file__, __file__]


def test_results_as_data_frames():
    """``to_frame()``: one row an element (flattened in C order), one column a field, the values
    the attributes' own; a scalar call one row; a trajectory left out."""
    pytest.importorskip("pandas")
    t = np.geomspace(1e-10, 1e-8, 6).reshape(2, 3)
    r = st.v_stick(CO2, 60e-6, t, k=[0.01, 0.02, 0.03])
    df = r.to_frame()
    assert len(df) == 6
    assert list(df.columns) == ["v_stick", "v_double_onset", "v_stick_jkr", "no_bouncing_below",
                                "t_vis", "v_max", "method"]
    np.testing.assert_array_equal(df["v_stick"].to_numpy(), r.v_stick.ravel())
    np.testing.assert_array_equal(df["t_vis"].to_numpy(), t.ravel())
    assert list(df["method"]) == list(r.method.ravel())
    one = st.collide(CO2, 60e-6, 1e-9, 0.01).to_frame()  # sticks: no contact time
    assert len(one) == 1 and one["outcome"][0] == "sticking" and np.isnan(one["contact_time"][0])
    traj = st.collide(CO2, 60e-6, 1e-9, 0.045, trajectory=True)
    assert "trajectory" not in traj.to_frame().columns
    assert len(st.jkr(CO2, [[1e-6, 2e-6], [3e-6, 4e-6]]).to_frame()) == 4


def test_the_inputs_that_tell_rows_apart_go_first():
    """``to_frame(k=..., v_in=...)``: each input broadcast to the result's shape as the call
    broadcast it (numpy's rules, the source), flattened in the same C order; an input that does
    not broadcast, or that repeats a field, is refused by name."""
    pytest.importorskip("pandas")
    t, k = np.geomspace(1e-10, 1e-8, 2)[:, None], [0.01, 0.02, 0.03]
    r = st.v_stick(CO2, 60e-6, t, k=k)
    df = r.to_frame(k=k)
    assert list(df.columns[:2]) == ["k", "v_stick"]
    np.testing.assert_array_equal(df["k"].to_numpy(), np.broadcast_to(k, (2, 3)).ravel())
    # each row's V_stick is that of its own k: the same row of a call of that k alone
    for row in (1, 5):
        one = st.v_stick(CO2, 60e-6, df["t_vis"][row], k=df["k"][row])
        assert one.v_stick == df["v_stick"][row]
    v = np.linspace(0.03, 0.1, 4)
    c = st.collide(CO2, 60e-6, 1e-9, v).to_frame(v_in=v)
    np.testing.assert_array_equal(c["v_in"].to_numpy(), v)
    with pytest.raises(ValueError, match=r"k of shape \(2,\) does not broadcast"):
        r.to_frame(k=[0.01, 0.02])
    with pytest.raises(ValueError, match="'t_vis' is a field"):
        r.to_frame(t_vis=t)
    with pytest.raises(ValueError, match="k is ragged"):
        r.to_frame(k=[[0.01], [0.02, 0.03]])
    u = pytest.importorskip("astropy.units")
    df = st.jkr(CO2, [30e-6, 60e-6]).to_frame(radius=[30, 60] * u.um)  # in SI, as the call
    np.testing.assert_allclose(df["radius"].to_numpy(), [30e-6, 60e-6], rtol=1e-15)


def test_sticking_criteria_have_the_broadcast_shape():
    """An array call's ``sticking_criterion`` is an object array shaped like ``outcome``: a
    criterion exactly where the collision sticks (Section 4.4: sticking is decided by the energy
    bound or the oscillations), None elsewhere; a scalar call's a str or None."""
    c = st.collide(CO2, [[60e-6], [30e-6]], 1e-9, [0.03, 0.05, 0.2])
    assert c.sticking_criterion.shape == c.outcome.shape == (2, 3)
    sticks = c.outcome == "sticking"
    assert sticks.any() and not sticks.all()
    assert all(x in ("energy_bound", "oscillations") for x in c.sticking_criterion[sticks])
    assert all(x is None for x in c.sticking_criterion[~sticks])
    assert st.collide(CO2, 60e-6, 1e-9, 0.2).sticking_criterion is None
