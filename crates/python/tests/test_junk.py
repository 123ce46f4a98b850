"""Junk in, a clear exception out: every public function fed None, strings, complex numbers,
dicts, nested and ragged lists, NaN, infinities, huge and tiny numbers, bools and arrays of the
wrong shape raises only TypeError or ValueError naming the argument (or SolverError for a
computation that failed), never another exception, a crash or a hang (hypothesis)."""

import math
import os

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as s

import stickiness as st
from stickiness import dustpy as sd

JUNK = s.one_of(
    s.none(),
    s.text(max_size=6),
    s.complex_numbers(allow_nan=True, allow_infinity=True),
    s.dictionaries(s.text(max_size=2), s.integers(), max_size=2),
    s.lists(s.lists(s.floats(allow_nan=True), max_size=3), max_size=3),
    s.sampled_from([math.nan, math.inf, -math.inf, 1e300, -1e300, 1e-300, 0.0, -1.0, True]),
    s.builds(lambda n: np.zeros((n, 7)), s.integers(0, 3)),
    s.floats(allow_nan=True, allow_infinity=True),
    s.integers(min_value=-(10**30), max_value=10**30),
)

CO2 = st.Material.co2()

#: Each public function with valid arguments; one of them at a time is replaced by junk.
CALLS = {
    "crack_speed": (st.crack_speed, {"k": 0.01, "beta": 0.5}),
    "t_vis_law": (st.t_vis_law, {"law": "co2", "radius": 1e-6}),
    "jkr": (st.jkr, {"material": CO2, "radius": 60e-6, "radius2": None, "wall": False}),
    "collide": (
        st.collide,
        {"material": CO2, "radius": 60e-6, "t_vis": 1e-9, "v_in": 0.045, "k": 0.01,
         "radius2": None, "wall": False, "t_vis_law": None, "trajectory": False, "t_end": None},
    ),
    "v_stick": (
        st.v_stick,
        {"material": CO2, "radius": 60e-6, "t_vis": 1e-9, "k": 0.01, "radius2": None,
         "wall": False, "t_vis_law": None, "v_max": None, "rel_tol": 1e-6, "method": "table"},
    ),
    "v_frag": (
        st.v_frag,
        {"material": CO2, "radius": 1e-7, "t_vis": 1e-12, "k": 0.01, "radius2": None,
         "wall": False, "t_vis_law": None, "v_max": None, "rel_tol": 1e-6, "method": "table"},
    ),
    "fit_t_vis": (
        st.fit_t_vis,
        {"material": CO2, "radius": 60e-6, "v_stick": 0.04, "v_stick_err": 0.02, "k": 0.01,
         "radius2": None, "wall": False, "v_max": None, "rel_tol": 1e-6, "method": "table"},
    ),
    "sweep": (
        st.sweep,
        {"material": "co2", "radius": 60e-6, "t_vis": 1e-9, "gamma_sv": None, "k": 0.01,
         "radius2": None, "wall": False, "t_vis_law": None, "v_max": None, "rel_tol": 1e-6,
         "method": "table", "progress": False, "chunks_per_task": 1},
    ),
    "Material": (st.Material, {"gamma_sv": 0.08, "young": 1e10, "poisson": 0.26, "density": 1560.0}),
    "Material.replace": (CO2.replace, {"density": 1650.0}),
    "dimensionless": (
        st.dimensionless,
        {"material": CO2, "radius": 60e-6, "t_vis": 1e-9, "radius2": None, "wall": False},
    ),
    "SizeDistribution": (st.SizeDistribution, {"samples": [40e-6, 60e-6], "weights": [1.0, 3.0]}),
    "SizeDistribution.lognormal": (
        st.SizeDistribution.lognormal, {"median": 60e-6, "width": 0.3, "nodes": 8}
    ),
    "infer": (
        st.infer,
        {"material": CO2, "radius": 60e-6, "v_stick": (0.04, 0.02), "sticking": None,
         "restitution": None, "free": ("t_vis",), "priors": None, "t_vis": None, "k": 0.01,
         "radius2": None, "wall": False, "walkers": 4, "steps": 3, "burn": None, "seed": 1,
         "progress": False, "method": "table", "rel_tol": 1e-6, "v_stick_quantile": 0.5},
    ),
    "vfrag_profile": (
        sd.vfrag_profile,
        {"T": np.array([50.0, 100.0]), "monomer_radius": 1e-7, "t_h2o": 150.0, "t_co2": 70.0,
         "v_frag_refractory": 1.0, "width": None},
    ),
}


#: Junk calls per function: 40 on every run (each run draws new ones); `JUNK_EXAMPLES=1000` for
#: a deeper search before a release.
EXAMPLES = int(os.environ.get("JUNK_EXAMPLES", "40"))
#: Arguments whose valid values include "run for ever" (a chain of 10**30 steps): not fed junk.
LENGTHS = {"steps"}


@pytest.mark.parametrize("name", sorted(CALLS))
@pytest.mark.filterwarnings("ignore::stickiness.StickinessWarning")
def test_junk_gives_clear_errors(name):
    fn, valid = CALLS[name]

    @settings(max_examples=EXAMPLES, deadline=None, suppress_health_check=[HealthCheck.too_slow])
    @given(argument=s.sampled_from(sorted(set(valid) - LENGTHS)), junk=JUNK)
    def one(argument, junk):
        kwargs = dict(valid, **{argument: junk})
        try:
            fn(**kwargs)
        except (TypeError, ValueError) as e:
            # the message names the argument (the law of Material.named by its name)
            assert argument in str(e) or (argument == "law" and "t_vis_law" in str(e)), (
                f"{name}({argument}={junk!r}): {type(e).__name__}: {e}"
            )
        except st.SolverError:
            pass

    one()


@pytest.mark.parametrize(
    "call, message",
    [
        # numbers drawn from arrays are shown as Python shows them, not as np.float64(...)
        (lambda: st.SizeDistribution([1e-5, -2e-5], [1, 1]), "samples[1] = -2e-05: must be > 0"),
        (lambda: st.infer(CO2, 60e-6, sticking=([0.01, -0.02], [1, 0])), "v_in[1] = -0.02: must"),
        (lambda: st.infer(CO2, 60e-6, restitution=([0.05], [1.5], [0.01])), "e[0] = 1.5: must"),
        # empty outcomes are named as such, not as outcomes that are no booleans
        (lambda: st.infer(CO2, 60e-6, sticking=([], [])), "non-empty"),
        # the size law's argument by the name the function gives it
        (lambda: st.t_vis_law("xx", 1e-6), "law = 'xx': must be 'co2' or 'h2o'"),
        (lambda: st.v_stick(CO2, 60e-6, t_vis_law="xx"), "t_vis_law = 'xx': must be"),
    ],
)
def test_messages_name_the_argument_and_show_plain_numbers(call, message):
    with pytest.raises(ValueError) as e:
        call()
    assert message in str(e.value) and "np." not in str(e.value)


def test_none_and_a_dimensionless_quantity_are_named_as_such():
    # from a review as a new user: "got objects (None)" and "got " (astropy's empty unit name)
    with pytest.raises(TypeError, match="rel_tol: expected a number or an array of numbers, got None"):
        st.v_stick(CO2, 60e-6, 1e-9, rel_tol=None)
    u = pytest.importorskip("astropy.units")
    with pytest.raises(ValueError, match="expected a quantity in m .*got a dimensionless number$"):
        st.v_stick(CO2, 60e-6 * u.dimensionless_unscaled, 1e-9)
