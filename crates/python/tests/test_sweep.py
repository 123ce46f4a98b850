"""st.sweep: the CLI's columns and values, in process and on a Dask LocalCluster alike."""

import pickle
import subprocess

import numpy as np
import pandas as pd
import pytest

import stickiness as st
from stickiness.sweeps import COLUMNS, SweepSpec

GRID = dict(
    material=["co2", "h2o"],
    radius=np.geomspace(1e-6, 1e-5, 3),
    t_vis=[1e-12, 1e-10, 1e-9],
)


def read_cli(path):
    df = pd.read_csv(path, comment="#")
    # an empty field is NaN to read_csv; the sweep's DataFrame holds "" there
    df["warnings"] = pd.Series(["" if pd.isna(w) else w for w in df["warnings"]]).astype(str)
    return df


def test_columns_order_and_single_points():
    df = st.sweep(**GRID, k=[0.01, 0.02])
    assert tuple(df.columns) == COLUMNS
    assert len(df) == 2 * 3 * 3 * 2
    # grid order: material, radius, t_vis, k (outermost first)
    assert list(df["material"][:18]) == ["co2"] * 18
    assert list(df["k"][:4]) == [0.01, 0.02, 0.01, 0.02]
    assert list(df["t_vis"][:4]) == [1e-12, 1e-12, 1e-10, 1e-10]
    # the first T_vis of each chunk is an unseeded search: equal to st.v_stick
    first = df[(df["t_vis"] == 1e-12)]
    for _, row in first.iterrows():
        r = st.v_stick(row["material"], radius=row["radius"], t_vis=row["t_vis"], k=row["k"])
        assert row["v_stick"] == r.v_stick and row["v_double_onset"] == r.v_double_onset
    np.testing.assert_array_equal(df["v_frag"], 10 * df["v_stick"])


def test_equals_the_cli(cli, tmp_path):
    out = tmp_path / "s.csv"
    subprocess.run(
        [cli, "sweep", "--material", "co2,h2o", "--radius", "1e-6:1e-5:3",
         "--t-vis", "1e-12,1e-10,1e-9", "--out", str(out)],
        check=True, capture_output=True,
    )
    df = st.sweep(**GRID)
    assert read_cli(out).equals(df)


def test_wall_law_and_gamma_axes(cli, tmp_path):
    out = tmp_path / "w.csv"
    subprocess.run(
        [cli, "sweep", "--material", "co2", "--radius", "6e-5,1e-6", "--wall",
         "--t-vis-law", "co2", "--gamma-sv", "0.07,0.08", "--out", str(out)],
        check=True, capture_output=True,
    )
    df = st.sweep(material="co2", radius=[6e-5, 1e-6], wall=True, t_vis_law="co2", gamma_sv=[0.07, 0.08])
    assert read_cli(out).equals(df)
    assert df["radius2"].isna().all() and df["wall"].all()


def test_dask_local_cluster_equals_in_process():
    import distributed  # installed by `cargo xtask test`; never skipped
    with distributed.LocalCluster(n_workers=2, processes=True, threads_per_worker=1) as cluster:
        with distributed.Client(cluster) as client:
            on_cluster = st.sweep(**GRID, client=client)
    in_process = st.sweep(**GRID)
    assert on_cluster.equals(in_process)


def test_pickles_and_bad_axes():
    spec = SweepSpec(
        materials=(("co2", st.Material.co2()),), gamma_sv=None, radius=(1e-6,), radius2=None,
        wall=False, t_vis=(1e-9,), t_vis_law=None, k=(0.01,), v_max=None, rel_tol=1e-6,
    )
    assert pickle.loads(pickle.dumps(spec)) == spec
    assert spec.n_chunks == 1
    with pytest.raises(ValueError, match=r"^radius = -1\.0: must be > 0"):
        st.sweep(radius=[1e-6, -1.0], t_vis=1e-9)
    with pytest.raises(ValueError, match=r"^k = 1\.5"):
        st.sweep(t_vis=1e-9, k=[0.01, 1.5])
    with pytest.raises(ValueError, match="co3"):
        st.sweep(material=["co2", "co3"], t_vis=1e-9)
    with pytest.raises(TypeError, match="missing argument: t_vis"):
        st.sweep()
    # both, as st.v_stick says it
    with pytest.raises(ValueError, match="give t_vis or t_vis_law, not both"):
        st.sweep(t_vis=1e-9, t_vis_law="co2")
    # a grid too large names its longest axis and the product, before any work
    with pytest.raises(ValueError, match=r"^k: 1001 values make a grid of 1001000000 points"):
        st.sweep(radius=np.geomspace(1e-6, 1e-4, 1000), t_vis=np.geomspace(1e-12, 1e-8, 1000),
                 k=np.linspace(0.005, 0.05, 1001))
    # an axis is a list: a 2-d array is not flattened silently
    with pytest.raises(ValueError, match=r"^radius: an axis is a value or a 1-d list"):
        st.sweep(radius=np.ones((2, 2)) * 1e-5, t_vis=1e-9)
    # a scheduler's address is no client
    with pytest.raises(TypeError, match="client: expected a dask.distributed.Client"):
        st.sweep(t_vis=1e-9, client="tcp://127.0.0.1:8786")


def test_rows_with_warnings_are_summed_up():
    """A row's warning (a radius of 60 m, most often meant in um) is raised once as a
    StickinessWarning at the caller's line, with the count and the first row's text, not only
    left in the ``warnings`` column; plausible grains give none."""
    import warnings

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        df = st.sweep("co2", [60e-6, 60.0], 1e-9)
    assert [w.filename for w in caught] == [__file__]
    text = str(caught[0].message)
    assert text.startswith("rows with warnings: 1 of 2") and "row 1: radius = 60.0 m" in text
    assert list(df["warnings"] != "") == [False, True]
    with pytest.warns(st.StickinessWarning, match=r"1 of 2 .* row 0: t_vis_law = 'h2o'"):
        st.sweep(["co2", "h2o"], 1e-6, t_vis_law="h2o")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        st.sweep("co2", 60e-6, [1e-10, 1e-9])
