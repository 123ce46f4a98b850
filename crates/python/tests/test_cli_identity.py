"""The Python package and the CLI give the same numbers, to the bit, and the same warnings for the
same inputs."""

import json
import math
import subprocess
import warnings

import pytest

import stickiness as st

CO2, H2O = st.Material.co2(), st.Material.h2o()


def cli_json(cli, *args):
    out = subprocess.run([cli, *args, "--json"], capture_output=True, text=True, check=True)
    return json.loads(out.stdout)


def same(json_value, py_value):
    """JSON null is NaN (or None) in Python; numbers must be equal as floats, bit for bit."""
    if json_value is None:
        return py_value is None or (isinstance(py_value, float) and math.isnan(py_value))
    return json_value == py_value


CASES = [
    (
        ["v-stick", "--t-vis", "1e-9"],
        lambda: st.v_stick(CO2, t_vis=1e-9),
        ["v_stick", "v_double_onset", "v_stick_jkr", "no_bouncing_below"],
    ),
    (
        ["v-stick", "--material", "h2o", "--radius", "9e-5", "--t-vis", "1e-9", "--k", "0.02"],
        lambda: st.v_stick(H2O, radius=9e-5, t_vis=1e-9, k=0.02),
        ["v_stick", "v_double_onset", "v_stick_jkr"],
    ),
    (
        ["v-stick", "--wall", "--t-vis-law", "co2", "--rel-tol", "1e-8"],
        lambda: st.v_stick(CO2, wall=True, t_vis_law="co2", rel_tol=1e-8),
        ["v_stick", "v_double_onset", "v_stick_jkr"],
    ),
    (
        ["v-stick", "--t-vis", "1e-6", "--v-max", "2"],
        lambda: st.v_stick(CO2, t_vis=1e-6, v_max=2.0),
        ["v_stick", "v_double_onset", "no_bouncing_below"],
    ),
    (
        ["jkr", "--radius", "6e-5", "--radius2", "3e-5"],
        lambda: st.jkr(CO2, radius=6e-5, radius2=3e-5),
        ["a_eq", "delta_eq", "tabor", "f_crit", "delta_crit", "e_stick", "e_break", "v_stick_jkr"],
    ),
    (
        ["collide", "--t-vis", "1e-9", "--v-in", "0.045", "--radius2", "1e-4"],
        lambda: st.collide(CO2, t_vis=1e-9, v_in=0.045, radius2=1e-4),
        ["outcome", "e", "v_out", "contact_time", "v_stick_jkr"],
    ),
    (
        ["fit-t-vis", "--v-stick", "0.04", "--v-stick-err", "0.02"],
        lambda: st.fit_t_vis(CO2, v_stick=0.04, v_stick_err=0.02),
        ["t_vis", "t_vis_min", "t_vis_max", "v_stick_jkr"],
    ),
    (
        ["fit-t-vis", "--v-stick", "0.03", "--v-stick-err", "0.02"],
        lambda: st.fit_t_vis(CO2, v_stick=0.03, v_stick_err=0.02),
        ["t_vis", "t_vis_min", "t_vis_max", "v_stick_jkr"],
    ),
    (
        ["fit-t-vis", "--v-stick", "20"],
        lambda: st.fit_t_vis(CO2, v_stick=20.0),
        ["t_vis", "t_vis_min", "t_vis_max", "v_stick_jkr"],
    ),
    (
        ["v-stick", "--radius", "5e-9", "--t-vis", "1e-12"],
        lambda: st.v_stick(CO2, radius=5e-9, t_vis=1e-12),
        ["v_stick", "v_double_onset", "v_stick_jkr", "no_bouncing_below"],
    ),
    (
        ["v-frag", "--material", "h2o", "--radius", "1e-7", "--t-vis-law", "h2o"],
        lambda: st.v_frag(H2O, radius=1e-7, t_vis_law="h2o"),
        ["v_frag", "v_stick", "t_vis", "v_frag_jkr", "v_stick_jkr", "no_bouncing_below"],
    ),
    (
        ["crack-law", "--k", "0.02", "--beta", "1.7"],
        lambda: {"v": st.crack_speed(0.02, 1.7)},
        ["v"],
    ),
]


# The one place where the two front ends word a warning differently: how they name the search
# limit (the CLI's flag, Python's argument).
CLI_TO_PYTHON = [("--v-max ", "v_max=")]


@pytest.mark.parametrize("args,python,keys", CASES, ids=[" ".join(c[0]) for c in CASES])
def test_python_equals_cli(cli, args, python, keys):
    j = cli_json(cli, *args)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        r = python()
    for key in keys:
        value = r[key] if isinstance(r, dict) else getattr(r, key)
        assert same(j[key], value), f"{key}: CLI {j[key]!r} != Python {value!r}"
    expected = list(j.get("warnings", []))
    for cli_name, py_name in CLI_TO_PYTHON:
        expected = [w.replace(cli_name, py_name) for w in expected]
    got = [str(w.message) for w in caught if issubclass(w.category, st.StickinessWarning)]
    assert sorted(got) == sorted(expected)


def test_material_file_identity(cli, tmp_path):
    p = tmp_path / "ice.json"
    p.write_text('{"gamma_sv": 0.19, "young": 7e9, "poisson": 0.25, "density": 930}')
    j = cli_json(cli, "v-stick", "--material", str(p), "--radius", "9e-5", "--t-vis", "5.3e-9")
    r = st.v_stick(st.Material.from_json(p), radius=9e-5, t_vis=5.3e-9)
    assert j["v_stick"] == r.v_stick
    m = cli_json(cli, "material", str(p))
    assert (m["gamma_sv"], m["young"], m["poisson"], m["density"]) == (
        0.19, 7e9, 0.25, 930.0
    )


def test_trajectory_columns_are_the_cli_s(cli, tmp_path):
    # collide's trajectory: the dict's keys are the CLI CSV's columns, in its order, and the
    # numbers the same to the bit
    path = tmp_path / "path.csv"
    subprocess.run([cli, "collide", "--t-vis", "1e-9", "--v-in", "0.1", "--trajectory", str(path)],
                   capture_output=True, text=True, check=True)
    lines = [line for line in path.read_text().splitlines() if not line.startswith("#")]
    header = lines[0].split(",")
    traj = st.collide(CO2, 60e-6, 1e-9, 0.1, trajectory=True).trajectory
    assert list(traj) == header
    first = [float(x) for x in lines[1].split(",")]
    assert first == [float(traj[name][0]) for name in header]
    assert len(lines) - 1 == traj["t"].size
