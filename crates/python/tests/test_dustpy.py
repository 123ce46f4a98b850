"""stickiness.dustpy with the real DustPy (installed by `cargo xtask test`; never skipped)."""

import json
import math
import subprocess
import sys

import numpy as np
import pytest

import stickiness as st
from stickiness import dustpy as sd


def test_zones_and_the_factor_100():
    T = np.array([300.0, sd.T_H2O + 1e-9, sd.T_H2O, 100.0, sd.T_CO2, 20.0])
    v = sd.vfrag_profile(T, monomer_radius=1e-7, v_frag_refractory=1.0)
    # refractory: the user's 1 m/s, in cm/s
    assert v[0] == 100.0 and v[1] == 100.0
    # H2O ice at and below the H2O line, CO2 ice at and below the CO2 line (Section 5.3 laws),
    # from the master table: the table's V_frag to the bit, the exact search's to 1e-5
    for ice, at in (("h2o", 2), ("co2", 4)):
        m = st.Material.named(ice)
        table = st.v_frag(m, 1e-7, t_vis_law=ice, method="table")
        assert table.method == "table"
        assert math.isclose(v[at], 100 * table.v_frag, rel_tol=1e-15) and v[at + 1] == v[at]
        search = st.v_frag(m, 1e-7, t_vis_law=ice)
        assert math.isclose(v[at], 100 * search.v_frag, rel_tol=1e-5)


def test_a_given_v_frag_replaces_an_ices_law():
    # given V_frag for CO2 (20 m/s): 2000 cm/s at every radius of the CO2 zone; H2O keeps its
    # law; a wrong value or a posterior for the same ice is refused, naming the argument
    T = np.array([300.0, 100.0, 50.0, 20.0])
    radius = np.array([1e-7, 1e-7, 1e-7, 1e-6])
    v = sd.vfrag_profile(T, monomer_radius=radius, v_frag={"co2": 20.0})
    law = sd.vfrag_profile(T, monomer_radius=radius)
    np.testing.assert_allclose(v[2:], 2000.0, rtol=1e-14)  # through exp(ln V_frag)
    assert v[0] == law[0] and v[1] == law[1]
    with pytest.raises(ValueError, match=r"v_frag\['co2'\]"):
        sd.vfrag_profile(T, v_frag={"co2": -1.0})
    with pytest.raises(ValueError, match="unknown ice"):
        sd.vfrag_profile(T, v_frag={"co": 1.0})


def test_per_cell_radius_and_smooth_transitions():
    T = np.array([200.0, 100.0, 50.0, 40.0])
    radius = np.array([1e-7, 1e-6, 1e-7, 1e-6])
    v = sd.vfrag_profile(T, monomer_radius=radius)
    for Ti, ri, vi in zip(T, radius, v):
        assert vi == sd.vfrag_profile(np.array([Ti]), monomer_radius=ri)[0]
    T = np.linspace(40.0, 250.0, 400)
    smooth = sd.vfrag_profile(T, width=5.0)
    step = sd.vfrag_profile(T)
    far = (np.abs(T - sd.T_H2O) > 40) & (np.abs(T - sd.T_CO2) > 40)
    np.testing.assert_allclose(smooth[far], step[far], rtol=1e-6)
    assert np.all(np.isfinite(smooth)) and np.all(smooth > 0)
    with pytest.raises(ValueError, match="t_co2"):
        sd.vfrag_profile(T, t_h2o=50.0, t_co2=70.0)
    with pytest.raises(ValueError, match="monomer_radius"):
        sd.vfrag_profile(T, monomer_radius=-1.0)


def test_wrong_types_and_a_quantile_without_posteriors_are_named():
    T = np.array([200.0, 100.0, 50.0])
    with pytest.raises(TypeError, match=r"posteriors\['co2'\]: expected a stickiness.Posterior"):
        sd.vfrag_profile(T, posteriors={"co2": 3})
    with pytest.raises(TypeError, match="v_frag: expected a dict"):
        sd.vfrag_profile(T, v_frag=700.0)
    with pytest.raises(TypeError, match="sim: expected a dustpy.Simulation"):
        sd.set_vfrag(object())
    # a quantile of the posteriors' V_frag without posteriors would be ignored: refused
    with pytest.raises(ValueError, match="quantile = 0.84: .* needs posteriors="):
        sd.vfrag_profile(T, quantile=0.84)


def test_importing_stickiness_needs_no_dustpy():
    code = "import sys; sys.modules['dustpy'] = None; import stickiness, stickiness.dustpy; print('ok')"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert out.stdout.strip() == "ok", out.stderr


def small_sim():
    from dustpy import Simulation

    sim = Simulation()
    sim.ini.grid.Nr = 30
    sim.ini.grid.mmax = 1e3
    sim.initialize()
    sim.writer = None
    sim.verbosity = 0
    return sim


def test_dustpy_follows_the_temperature():
    sim = small_sim()
    profile = sd.set_vfrag(sim, monomer_radius=1e-7)
    np.testing.assert_array_equal(np.asarray(sim.dust.v.frag), sd.vfrag_profile(sim.gas.T))
    sim.update()
    np.testing.assert_array_equal(np.asarray(sim.dust.v.frag), profile(sim.gas.T))
    # the zones move with the temperature: a disc twice as hot
    sim.gas.T.updater = lambda s: 2.0 * np.asarray(s.gas.T)
    sim.gas.T.update()
    sim.dust.v.frag.update()
    np.testing.assert_array_equal(np.asarray(sim.dust.v.frag), sd.vfrag_profile(np.asarray(sim.gas.T)))
    assert len(np.unique(np.asarray(sim.dust.v.frag))) == 3  # refractory, H2O, CO2


def test_a_short_run_stays_finite():
    from dustpy import constants as c

    sim = small_sim()
    sd.set_vfrag(sim, monomer_radius=1e-7)
    sim.t.snapshots = np.array([20.0]) * c.year
    sim.run()
    for field in (sim.dust.Sigma, sim.dust.v.frag, sim.gas.Sigma):
        assert np.all(np.isfinite(np.asarray(field)))
    assert np.all(np.asarray(sim.dust.Sigma) >= 0)


def test_case_study_runs(tmp_path, root):
    # the smoke test of examples/dustpy/case_study.py: a tiny grid, a few years, short chains
    data = tmp_path / "runs.npz"
    script = [sys.executable, str(root / "examples" / "dustpy" / "case_study.py")]
    tiny = ["--nr", "12", "--mmax", "1e3", "--steps", "60", "--processes", "2", "--out-dir",
            str(tmp_path), "--data", str(data), "--checkpoints", str(tmp_path / "runs")]
    done = subprocess.run(script + ["--years", "10"] + tiny, capture_output=True, text=True,
                          cwd=tmp_path, timeout=900)
    assert done.returncode == 0, done.stderr
    assert "fastest collision between populated bins" in done.stdout
    # a run goes on from its checkpoint (10 yr) instead of starting again
    more = subprocess.run(script + ["--years", "20", "--resume"] + tiny, capture_output=True,
                          text=True, cwd=tmp_path, timeout=900)
    assert more.returncode == 0, more.stderr
    assert "constant: 20 yr after" in more.stdout and ": 10 yr after" not in more.stdout
    # ... with the ices' V_frag kept from the start (not inferred again)
    assert "V_frag of the ices from" in more.stdout and "posteriors:" not in more.stdout
    frozen = json.loads((tmp_path / "runs" / "v_frag.json").read_text())["v_frag"]
    year = 365.25 * 86400.0
    for name in ("constant", "q16", "median", "q84"):
        assert float(np.load(tmp_path / "runs" / f"{name}.npz")["t"]) / year == pytest.approx(20)
    # ... and refuses a checkpoint made with other settings, naming the setting
    other = subprocess.run(script + ["--years", "30", "--resume"] + tiny + ["--nr", "13"],
                           capture_output=True, text=True, cwd=tmp_path, timeout=900)
    assert other.returncode != 0 and "made with nr = 12" in other.stderr
    # ... but goes on onto a wider mass grid of the same spacing (7 bins a decade: 1e4 g is 7
    # bins more than 1e3 g), saying since when (test_resume_widens_the_mass_grid: the bins)
    before = np.load(tmp_path / "runs" / "median.npz")["Sigma_dust"]
    wider = subprocess.run(script + ["--years", "30", "--resume"] + tiny + ["--mmax", "1e4"],
                           capture_output=True, text=True, cwd=tmp_path, timeout=900)
    assert wider.returncode == 0, wider.stderr
    assert "median: mass grid widened at 20 yr from 1e+03 g (now to 1e+04 g)" in wider.stdout
    after = np.load(tmp_path / "runs" / "median.npz")
    assert after["Sigma_dust"].shape == (before.shape[0], before.shape[1] + 7)
    assert np.allclose(after["grid_widened"], [[20.0, 1e3]])
    assert float(after["t"]) / year == pytest.approx(30)
    for figure in ("dustpy_case_study.png", "dustpy_case_study_profiles.png"):
        assert (tmp_path / figure).stat().st_size > 10_000
    # the constant run has V_frag = 10 m/s everywhere; the physics runs the refractory value
    # inside the H2O snow line (the script's --v-frag-refractory, 1 m/s)
    saved = np.load(data, allow_pickle=True)
    assert set(saved.files) == {"constant", "q16", "median", "q84"}
    assert np.allclose(saved["constant"].item()["v_frag"], 10.0)
    median = saved["median"].item()
    hot = median["T"] > sd.T_H2O
    assert hot.any() and np.allclose(median["v_frag"][hot], 1.0)
    cold = median["T"] <= sd.T_CO2
    assert cold.any() and np.allclose(median["v_frag"][cold], frozen["0.5"]["co2"], rtol=1e-12)
    replot = subprocess.run(
        [sys.executable, str(root / "examples" / "dustpy" / "case_study.py"), "--replot",
         "--out-dir", str(tmp_path), "--data", str(data)],
        capture_output=True, text=True, cwd=tmp_path, timeout=300,
    )
    assert replot.returncode == 0, replot.stderr


def _case_study(root):
    import importlib.util

    spec = importlib.util.spec_from_file_location(
        "case_study", root / "examples" / "dustpy" / "case_study.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_resume_widens_the_mass_grid(tmp_path, root):
    # truth by construction of the grids: DustPy's mass grid is 7 bins a decade from 1e-12 g,
    # so a checkpoint to 1e3 g is the bottom 106 bins of a grid to 1e4 g (113 bins): they come
    # back bin for bin, the 7 new ones at DustPy's empty-bin value (0.1 of its floor); a
    # narrower grid or one of another spacing is refused
    from dustpy import Simulation
    from dustpy import constants as c

    cs = _case_study(root)

    def sim(mmax):
        s = Simulation()
        s.ini.grid.Nr, s.ini.grid.mmax = 12, mmax
        s.initialize()
        return s

    settings = {"nr": 12, "mmax": 1e3, "v_frag_refractory": 1.0, "quantile": 0.5,
                "steps": 60, "seed": 1}
    small = sim(1e3)
    small.t[...] = 7.0 * c.year
    sigma = np.array(small.dust.Sigma) * np.linspace(1.0, 2.0, small.grid.Nm)  # not DustPy's
    small.dust.Sigma[...] = sigma
    path = tmp_path / "median.npz"
    cs.save_checkpoint(small, path, settings, 5.0, cs.NOT_WIDENED)
    wide = sim(1e4)
    seconds, widened = cs.resume(wide, path, {**settings, "mmax": 1e4})
    assert seconds == 5.0 and np.allclose(widened, [[7.0, 1e3]])
    assert wide.grid.Nm == small.grid.Nm + 7
    assert np.array_equal(np.array(wide.dust.Sigma)[:, :small.grid.Nm], sigma)
    assert np.array_equal(np.array(wide.dust.Sigma)[:, small.grid.Nm:],
                          0.1 * np.array(wide.dust.SigmaFloor)[:, small.grid.Nm:])
    with pytest.raises(SystemExit, match="made with mmax = 1000"):
        cs.resume(sim(1e2), path, {**settings, "mmax": 1e2})
    with pytest.raises(SystemExit, match="is not the bottom"):
        cs.resume(sim(3e3), path, {**settings, "mmax": 3e3})


def test_fastest_collision_counts_populated_bins_only(root):
    # truth by hand: two populated bins (shares 0.5) and an empty one (1e-6 of the dust) whose
    # collisions are faster; a cell emptied by drift (dust/gas 1e-7) has none
    case_study = _case_study(root)
    sigma = np.array([[1.0, 1e-6, 1.0], [1e-7, 1e-7, 1e-7]])
    v_rel = np.array([[[0.0, 90.0, 3.0], [90.0, 0.0, 80.0], [3.0, 80.0, 2.0]]] * 2)
    fastest = case_study.fastest_collision(sigma, np.array([100.0, 3.0]), v_rel)
    assert fastest[0] == 3.0 and np.isnan(fastest[1])


def test_largest_size_ignores_floor_values(root):
    # truth by hand: a cell holding dust in its two small bins and one beyond the dust whose
    # bins all sit at the floor (it would otherwise count as populated up to the grid's top)
    case_study = _case_study(root)
    floor = np.full((2, 3), 1e-10)
    state = {"Sigma_dust": np.array([[1.0, 1.0, 1e-10], [1e-10, 1e-10, 1e-10]]),
             "Sigma_floor": floor, "Sigma_gas": np.array([100.0, 1e-7]),
             "a": np.array([[1.0, 10.0, 1e6]] * 2)}
    assert case_study.largest_size(state) == 0.1  # 10 cm, in m
    assert case_study.largest_size({**state, "Sigma_floor": 0.0}) == 1e4


def test_posteriors_bracket_the_disc():
    # truth: Posterior.v_frag, the posterior's T_vis carried to the monomer by the size law
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", st.StickinessWarning)
        post = st.infer("co2", 60e-6, v_stick=(0.04, 0.02), walkers=8, steps=200, seed=3)
    T = np.array([200.0, 100.0, 50.0])
    default = sd.vfrag_profile(T, monomer_radius=1e-7)
    bands = {}
    for q in (0.16, 0.84):
        v = sd.vfrag_profile(T, monomer_radius=1e-7, posteriors={"co2": post}, quantile=q)
        assert v[0] == default[0] and v[1] == default[1]  # refractory and H2O: unchanged
        expected = post.v_frag(1e-7, quantiles=(q,)).iloc[0]
        assert math.isclose(v[2], 100 * expected, rel_tol=1e-12)
        bands[q] = v[2]
    assert bands[0.16] <= bands[0.84]
    with pytest.raises(ValueError, match="posteriors"):
        sd.vfrag_profile(T, posteriors={"co": post})
    with pytest.raises(TypeError, match="posteriors"):
        sd.vfrag_profile(T, posteriors={"co2": 1e-10})
    with pytest.raises(ValueError, match="quantile"):
        sd.vfrag_profile(T, posteriors={"co2": post}, quantile=1.5)
