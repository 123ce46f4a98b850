"""The type stubs match the module (mypy's stubtest), and the examples run."""

import os
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[3]


def test_stubs_match_the_module():
    allow = pathlib.Path(__file__).with_name("stubtest_allowlist.txt")
    out = subprocess.run(
        [sys.executable, "-m", "mypy.stubtest", "stickiness", "--allowlist", str(allow)],
        capture_output=True,
        text=True,
    )
    assert out.returncode == 0, out.stdout + out.stderr


def run_example(name, *args, tmp):
    env = dict(os.environ, MPLBACKEND="Agg")
    return subprocess.run(
        [sys.executable, str(ROOT / "examples" / "python" / name), *args],
        capture_output=True,
        text=True,
        env=env,
        cwd=tmp,
        timeout=600,
    )


def test_quickstart_runs(tmp_path):
    out = run_example("quickstart.py", tmp=tmp_path)
    assert out.returncode == 0, out.stderr
    assert "V_stick" in out.stdout


def test_figure4_redraws(tmp_path):
    out = run_example("figure4.py", str(tmp_path / "fig4.png"), tmp=tmp_path)
    assert out.returncode == 0, out.stderr
    assert (tmp_path / "fig4.png").stat().st_size > 10_000


def test_dask_example_runs(tmp_path):
    out = run_example("dask_sweep.py", "--out", str(tmp_path / "s.csv"), tmp=tmp_path)
    assert out.returncode == 0, out.stderr
    assert (tmp_path / "s.csv").stat().st_size > 1000


def test_infer_example_runs(tmp_path):
    # short chains: the committed figure is made with the defaults (docs/figures/infer_ice.png)
    out = run_example("infer_ice.py", str(tmp_path / "ice.png"), "--steps", "150", tmp=tmp_path)
    assert out.returncode == 0, out.stderr
    assert "P(T_vis,H2O > T_vis,CO2)" in out.stdout
    assert (tmp_path / "ice.png").stat().st_size > 10_000


def test_infer_prior_example_runs(tmp_path):
    # short chains: what the docs quote comes from the defaults (docs/model.md)
    out = run_example("infer_prior.py", "--steps", "100", tmp=tmp_path)
    assert out.returncode == 0, out.stderr
    assert out.stdout.count("P(T_vis < 1e-10 s)") == 4, out.stdout


def test_restitution_coverage_example_runs(tmp_path):
    # 40 model-made data sets of 10 e +- 0.02 (seed 1): the 95 % interval holds the truth in 39
    # (the sample read as continuous, 16 restitution radii; 30 with 8 radii as points, the
    # likelihood before 2026-11-29); a calibrated binomial(40, 0.95) falls below 34 in 0.3 % of
    # draws
    out = run_example("restitution_coverage.py", "--sets", "40", "--points", "10", "--e-err",
                      "0.02", tmp=tmp_path)
    assert out.returncode == 0, out.stderr
    inside = int(out.stdout.split("95 % interval in ")[1].split()[0])
    assert inside >= 34, out.stdout


def test_fit_round_trip_example_runs(tmp_path):
    # synthetic truth: each target V_stick is given back by v_stick at its fitted T_vis, next to
    # the no-bouncing cliff too (before 2026-11-28: 18 % of such fits off by more than 1e-5)
    out = run_example("fit_round_trip.py", "200", tmp=tmp_path)
    assert out.returncode == 0, out.stderr
    assert "above 1e-5: 0.00%" in out.stdout, out.stdout
