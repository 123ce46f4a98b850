"""A disc with grain physics: one DustPy disc run four ways, V_frag by hand against V_frag from
the laboratory data through the viscoelastic model (Arakawa & Krijt 2021, Sections 5-7).

The runs (everything else is DustPy's default disc, see MMAX below):

- ``constant``: V_frag = 10 m/s everywhere, the common choice of dust-evolution models;
- ``median``: V_frag from grain physics (``stickiness.dustpy.set_vfrag``): 0.1 um monomers,
  bare refractory grains inside the H2O snow line (V_frag = ``--v-frag-refractory``, the model
  has no T_vis for them), H2O ice between the snow lines and CO2 ice outside, with T_vis from
  the posteriors of the laboratory data (``st.infer``, the data of ``infer_ice.py``), the
  posterior median of V_frag = 10 V_stick;
- ``q16``, ``q84``: the same with the 16 % and 84 % posterior quantiles: the data's
  uncertainty carried to the disc.

Writes two figures (the dust surface density over radius and particle size, side by side for
the runs, with DustPy's drift and fragmentation limits and the snow lines; the size carrying
most mass, its Stokes number, the dust-to-gas ratio and V_frag against r with the posterior
band, beside V_frag the fastest collision between populated bins) and an .npz of the final
states, and prints the numbers the documentation quotes.

    python examples/dustpy/case_study.py [--years 1e5] [--out-dir docs/figures]
    python examples/dustpy/case_study.py --replot     # the figures from the saved .npz
    python examples/dustpy/case_study.py --resume     # go on from the runs' last checkpoints
    python examples/dustpy/case_study.py --nr 50 --checkpoints data/dustpy_case_study --resume
        # the documentation's 1e5-year figures, from the committed checkpoints (seconds)
    python examples/dustpy/case_study.py --years 1e4 --mmax 1e15   # 1e4 years from scratch

Needs DustPy (``pip install dustpy``, which needs gfortran), pandas and matplotlib. DustPy
works in cgs: V_frag enters it in cm/s (``stickiness.dustpy`` converts). The cost on 2 cores
is in docs/performance.md ("DustPy case study").
"""

import argparse
import concurrent.futures as cf
import json
import math
import multiprocessing
import time
import warnings
from pathlib import Path

import numpy as np

import stickiness as st
from stickiness import dustpy as sd

#: Monomer radius (m): 0.1 um, the monomers of Arakawa & Krijt (2021, Section 6).
MONOMER_RADIUS = 1e-7
#: V_frag (m/s) of the constant run: the common choice of dust-evolution models.
CONSTANT_V_FRAG = 10.0
#: V_frag (m/s) of bare refractory (silicate) aggregates inside the H2O snow line: the model
#: has no T_vis for them, so it is an input; 1 m/s is the laboratory value for silicate
#: aggregates (Blum & Wurm 2008) and stickiness.dustpy's default.
V_FRAG_REFRACTORY = 1.0
#: The runs: name -> posterior quantile of V_frag (None: the constant V_frag).
RUNS = {"constant": None, "q16": 0.16, "median": 0.5, "q84": 0.84}
#: DustPy's default disc (Simulation() as it comes: 1 M_sun star, 0.05 M_sun of gas with
#: Sigma ~ r^-1 exp(-r/60 au), alpha = 1e-3, dust-to-gas 0.01, passive irradiated temperature,
#: 100 radial cells from 1 to 1000 au, 7 mass bins a decade) except the mass grid's top, raised
#: from 1e5 g so that nothing piles up at its end: H2O aggregates that do not fragment grow
#: through St = 1 just outside the H2O snow line, sweep up the pebbles drifting in and reach
#: 100 m within 1e4 yr. Measured with 50 radial cells: with 1e12 g (50 m) 4.6e-3 of the dust
#: sat in the grid's top decade at 1e4 yr; with 1e15 g (500 m) none (floor values only), but the
#: boulders at 2.5 au reached 1e15 g at 2.2e4 yr and 46 % of that cell's dust sat in the last
#: bin at 7e4 yr. Their mean radius grows by about 10 m every 1000 yr (107 m at 2e4 yr, 132 m
#: at 2.25e4 yr), so about 1 km (5e15 g) at 1e5 yr, with a tail two decades above the mean
#: (so forecast; the runs put most mass at 3 km and the largest bodies at 6.5 km at 1e5 yr):
#: 1e20 g (24 km) leaves the tail two decades of room. Each decade costs 7 bins, and a step
#: costs about bins^3 (DustPy's sparse LU): 1.5 times as much with 1e20 g as with 1e15 g
#: (0.96 against 0.63 s a step at 2e4 yr, measured one after the other).
MMAX = 1e20  # g


def posteriors(steps: int, seed: int) -> dict:
    """T_vis posteriors of CO2 and H2O from the laboratory data (as in infer_ice.py)."""
    # CO2: Musiolik et al. (2016a), grains on a CO2-covered target, 80 % within 40-120 um
    width = math.log(120 / 40) / (2 * 1.2816)  # the lognormal's 10-90 % range
    sizes = st.SizeDistribution.lognormal(median=math.sqrt(40e-6 * 120e-6), width=width)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", st.StickinessWarning)
        co2 = st.infer("co2", sizes, wall=True, v_stick=(0.04, 0.02), steps=steps, seed=seed)
        # H2O: Gundlach & Blum (2015), 1.5 um, gamma_SV free over the literature's spread
        h2o = st.infer("h2o", 1.5e-6, v_stick=(9.6, 0.3), free=("t_vis", "gamma_sv"),
                       priors={"gamma_sv": (0.02, 0.19)}, steps=4 * steps, seed=seed)
    return {"co2": co2, "h2o": h2o}


#: The file in the checkpoint directory that keeps the runs' V_frag of the ices (m/s), computed
#: once from the posteriors: a sampler or table that changes between sittings must not change a
#: run's input halfway.
V_FRAG_FILE = "v_frag.json"


def ice_v_frags(args) -> dict:
    """``{quantile: {'co2': V_frag, 'h2o': V_frag}}`` (m/s) of the 0.1 um monomers: from the
    checkpoint directory's V_FRAG_FILE when resuming (made with the same --steps and --seed),
    else from the posteriors (``st.infer``), then written there."""
    path = Path(args.checkpoints) / V_FRAG_FILE
    made_with = {"steps": args.steps, "seed": args.seed, "monomer_radius": MONOMER_RADIUS}
    if args.resume and path.exists():
        saved = json.loads(path.read_text())
        for key, value in made_with.items():
            if saved[key] != value:
                raise SystemExit(f"{path}: made with {key} = {saved[key]}, not {value}")
        print(f"V_frag of the ices from {path} ({saved['note']})")
        return {float(q): v for q, v in saved["v_frag"].items()}
    start = time.perf_counter()
    post = posteriors(args.steps, args.seed)
    found = {}
    for q in sorted({q for q in RUNS.values() if q is not None}):
        profile = sd.VFragProfile(MONOMER_RADIUS, posteriors=post, quantile=q)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", st.StickinessWarning)
            found[q] = {ice: profile.ice_v_frag(ice, MONOMER_RADIUS) for ice in post}
    for ice in post:
        print(f"{ice}: V_frag (m/s) of 0.1 um monomers, 16/50/84 %: "
              + ", ".join(f"{found[q][ice]:.3g}" for q in sorted(found)))
    print(f"posteriors: {time.perf_counter() - start:.1f} s")
    path.parent.mkdir(parents=True, exist_ok=True)
    note = f"st.infer of stickiness {st.__version__}, {time.strftime('%Y-%m-%d')}"
    path.write_text(json.dumps({**made_with, "note": note,
                                "v_frag": {repr(q): v for q, v in found.items()}}, indent=1))
    return found


def run(name: str, quantile, v_frags: dict, args) -> dict:
    """One DustPy run to ``args.years``; returns its final state (cgs, as DustPy keeps it)."""
    from dustpy import Simulation
    from dustpy import constants as c
    from dustpy.utils import read_data

    start = time.perf_counter()
    sim = Simulation()
    sim.ini.grid.Nr = args.nr
    sim.ini.grid.mmax = args.mmax
    sim.ini.dust.vFrag = CONSTANT_V_FRAG * sd.CM_PER_M  # cm/s
    sim.initialize()
    if quantile is not None:
        sd.set_vfrag(sim, MONOMER_RADIUS, v_frag_refractory=args.v_frag_refractory,
                     v_frag=v_frags[quantile])
    sim.writer = None
    sim.verbosity = 0
    settings = {"nr": args.nr, "mmax": args.mmax, "v_frag_refractory": args.v_frag_refractory,
                "quantile": -1.0 if quantile is None else quantile, "steps": args.steps,
                "seed": args.seed}
    checkpoint = Path(args.checkpoints) / f"{name}.npz"
    spent, widened = resume(sim, checkpoint, settings) if args.resume else (0.0, NOT_WIDENED)
    # run from milestone to milestone, reporting progress and cost, saving a checkpoint at each
    for years in milestones(args.years):
        if float(sim.t) >= years * c.year * (1 - 1e-12):
            continue
        sim.t.snapshots = np.array([years]) * c.year
        sim.run()
        seconds = spent + time.perf_counter() - start
        save_checkpoint(sim, checkpoint, settings, seconds, widened)
        print(f"  {name}: {years:.3g} yr after {seconds:.0f} s", flush=True)
    data = read_data(sim)
    state = {
        "r": data.grid.r[0] / c.au,  # au
        "m": data.grid.m[0],  # g
        "a": sim.dust.a,  # cm, (r, m)
        "sigma": data.dust.sigma[0],  # g/cm^2 per unit ln m, (r, m)
        "Sigma_dust": sim.dust.Sigma,  # g/cm^2 per bin, (r, m)
        # DustPy's floor: less than one body of the bin's mass in the annulus
        "Sigma_floor": sim.dust.SigmaFloor,  # g/cm^2 per bin, (r, m)
        "St": data.dust.St[0],
        "St_drift": data.dust.St_limits.drift[0],
        "St_frag": data.dust.St_limits.frag[0],
        "Sigma_gas": data.gas.Sigma[0],  # g/cm^2
        "T": sim.gas.T,  # K
        "v_frag": data.dust.v.frag[0] / sd.CM_PER_M,  # m/s
        "v_rel_max": fastest_collision(sim.dust.Sigma, sim.gas.Sigma,
                                       sim.dust.v.rel.tot) / sd.CM_PER_M,  # m/s
    }
    # plain arrays (DustPy's fields carry their updaters, which do not pickle)
    state = {k: np.array(v, dtype=float) for k, v in state.items()}
    state.update(name=name, years=float(sim.t) / c.year,
                 seconds=spent + time.perf_counter() - start, grid_widened=widened)
    return state


def save_checkpoint(sim, path: Path, settings: dict, seconds: float,
                    widened: np.ndarray) -> None:
    """What a DustPy run needs to go on (time, dust and gas surface densities; everything else
    follows from them) with the settings that made it and its grid widenings (``resume``),
    written atomically."""
    path.parent.mkdir(parents=True, exist_ok=True)
    partial = path.with_suffix(".partial.npz")
    np.savez(partial, t=float(sim.t), Sigma_dust=np.array(sim.dust.Sigma),
             Sigma_gas=np.array(sim.gas.Sigma), seconds=seconds, grid_widened=widened,
             **settings)
    partial.replace(path)


#: A run whose mass grid was never widened: no rows of (time (yr), mmax before (g)).
NOT_WIDENED = np.empty((0, 2))


def resume(sim, path: Path, settings: dict):
    """Puts a run's checkpoint into ``sim``, initialised with the same settings or a wider mass
    grid; returns the wall time (s) spent on the run so far and its grid widenings, rows of
    (time (yr), mmax before (g)); ``(0, NOT_WIDENED)`` without a checkpoint.

    A checkpoint made on a lower mass grid of the same spacing (the same bins, fewer at the top)
    is carried onto ``sim``'s wider grid, the new bins at DustPy's value of an empty bin (0.1 of
    its floor, as ``dustpy.std.dust.enforce_floor_value`` sets it): a run whose largest bodies
    approach the grid's end goes on from a checkpoint taken before they reached it."""
    from dustpy import constants as c

    if not path.exists():
        return 0.0, NOT_WIDENED
    saved = np.load(path)
    for key, value in settings.items():
        if key == "mmax" and float(saved[key]) <= value:
            continue
        if not np.isclose(float(saved[key]), float(value), rtol=1e-12):
            raise SystemExit(f"{path}: made with {key} = {float(saved[key]):g}, not {value:g}; "
                             "give the same settings or another --checkpoints directory")
    old = saved["Sigma_dust"]
    mass = np.array(sim.grid.m)
    low = np.logspace(np.log10(mass[0]), np.log10(float(saved["mmax"])), old.shape[1])
    if old.shape[1] > mass.size or not np.allclose(mass[:old.shape[1]], low, rtol=1e-9, atol=0):
        raise SystemExit(f"{path}: its mass grid (to {float(saved['mmax']):g} g) is not the "
                         f"bottom of this one (to {mass[-1]:g} g)")
    sigma = 0.1 * np.array(sim.dust.SigmaFloor, dtype=float)
    sigma[:, :old.shape[1]] = old
    sim.t[...] = float(saved["t"])
    sim.dust.Sigma[...] = sigma
    sim.gas.Sigma[...] = saved["Sigma_gas"]
    sim.update()
    widened = saved["grid_widened"] if "grid_widened" in saved else NOT_WIDENED
    if old.shape[1] < mass.size:
        widened = np.vstack([widened, [[float(saved["t"]) / c.year, float(saved["mmax"])]]])
    return float(saved["seconds"]), widened


#: Checkpoint spacing (yr) after the first 5e3 years: what a kill (the end of a sitting) can cost a
#: run that goes on over several sittings. 2.5e3 years was about 5 minutes of a core early on
#: (time steps of 3 yr, 0.35 s each); past 4e4 years the grain-physics runs' steps fall below a
#: year and 2.5e3 years took 45 minutes of wall time with four runs on two cores, so every
#: 500 years (about ten minutes there; a checkpoint costs milliseconds).
CHECKPOINT_YEARS = 500.0


def milestones(years: float) -> list:
    """The times (yr) a run reports and saves a checkpoint at: 1e3, 2e3, 5e3, then every
    CHECKPOINT_YEARS below ``years``, then ``years``."""
    every = [CHECKPOINT_YEARS * i for i in range(1, int(years / CHECKPOINT_YEARS) + 1)]
    marks = [1e3, 2e3, 5e3] + every
    return sorted({m for m in marks if m < years}) + [years]


#: Below this dust-to-gas ratio a cell holds only DustPy's floor values (the outer disc, emptied
#: by drift): its "size carrying most mass" means nothing and is not drawn or reported.
EMPTY_D2G = 1e-5

#: A bin is populated when it holds at least this share of its cell's dust. DustPy defines a
#: relative velocity between every two bins, empty ones included (a 1e20 g body against a
#: micron grain), so the fastest collisions that carry a cell's evolution are those between
#: populated bins; V_frag is to be compared with them. The fastest collision depends on how
#: rare the bins counted may be, because the largest pebbles are the fastest: in the CO2 zone
#: of the median run at 2.5e4 yr it is 29.8 / 34.7 / 39.9 / 42.4 m/s counting bins that hold
#: 1e-3 / 1e-4 / 1e-5 / 1e-6 of the dust (57.1 m/s between the snow lines at each), so read
#: it as "the largest pebbles collide at about this speed", not as a sharp edge.
POPULATED = 1e-4


def populated_bins(sigma, sigma_gas) -> np.ndarray:
    """Which bins (r, m) are populated (POPULATED) in a cell that holds dust (EMPTY_D2G);
    ``sigma`` (r, m) and ``sigma_gas`` (r) in the same units."""
    sigma = np.asarray(sigma, dtype=float)
    dust = sigma.sum(axis=1)
    holds_dust = dust / np.asarray(sigma_gas, dtype=float) >= EMPTY_D2G
    with np.errstate(invalid="ignore", divide="ignore"):  # 0/0 in a cell without dust: False
        return (sigma / dust[:, None] >= POPULATED) & holds_dust[:, None]


def fastest_collision(sigma, sigma_gas, v_rel) -> np.ndarray:
    """Per radial cell, the largest relative velocity (units of ``v_rel``) between two
    populated bins (``populated_bins``); NaN in the cells emptied by drift. ``v_rel`` (r, m,
    m)."""
    populated = populated_bins(sigma, sigma_gas)
    both = populated[:, :, None] & populated[:, None, :]
    fastest = np.where(both, np.asarray(v_rel, dtype=float), 0.0).max(axis=(1, 2))
    return np.where(populated.any(axis=1), fastest, np.nan)


def above_floor(state: dict) -> np.ndarray:
    """The dust surface density (r, m) above DustPy's floor value (less than one body in the
    annulus): bins at the floor hold nothing, though in the cells beyond the dust they are
    all the dust there is."""
    return np.clip(state["Sigma_dust"] - state.get("Sigma_floor", 0.0), 0.0, None)


def largest_size(state: dict) -> float:
    """The radius (m) of the largest bodies in a populated bin (``populated_bins``, floor
    values apart)."""
    populated = populated_bins(above_floor(state), state["Sigma_gas"])
    return float(np.max(np.where(populated, state["a"], 0.0))) * 1e-2


def peak(state: dict) -> dict:
    """Per radius: the size carrying most mass (m), its Stokes number, the dust-to-gas ratio."""
    S = state["Sigma_dust"]
    i = S.argmax(axis=1)
    rows = np.arange(S.shape[0])
    d2g = S.sum(axis=1) / state["Sigma_gas"]
    empty = d2g < EMPTY_D2G
    return {"a": np.where(empty, np.nan, state["a"][rows, i] * 1e-2),
            "St": np.where(empty, np.nan, state["St"][rows, i]), "d2g": d2g}


def snow_lines(state: dict) -> dict:
    """Radius (au) where the gas temperature crosses each snow line (T falls outwards)."""
    r, T = state["r"], state["T"]
    return {name: float(np.interp(-t, -T, r)) for name, t in
            (("H2O", sd.T_H2O), ("CO2", sd.T_CO2))}


def draw(states: dict, out_dir: Path, years: float) -> list:
    """The two figures; returns their paths."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    titles = {"constant": f"constant V_frag = {CONSTANT_V_FRAG:g} m/s",
              "q16": "grain physics, 16 % quantile", "median": "grain physics, median",
              "q84": "grain physics, 84 % quantile"}
    names = [n for n in RUNS if n in states]
    top = max(np.nanmax(s["sigma"]) for s in states.values())
    # the size axis up to ten times the largest populated bodies of any run (the grid reaches
    # far beyond them: MMAX)
    largest = max(largest_size(s) for s in states.values())
    levels = np.arange(np.ceil(np.log10(top)) - 6, np.ceil(np.log10(top)) + 0.01, 0.5)
    fig, axes = plt.subplots(1, len(names), figsize=(4.1 * len(names), 4.0), sharey=True,
                             squeeze=False)
    for ax, name in zip(axes[0], names):
        s = states[name]
        r2 = np.broadcast_to(s["r"][:, None], s["a"].shape)
        size = s["a"] * 1e-2  # m
        img = ax.contourf(r2, size, np.log10(np.maximum(s["sigma"], 1e-300)), levels=levels,
                          cmap="magma", extend="both")
        limits = (("St_drift", "C2", "drift limit"), ("St_frag", "C0", "fragmentation limit"))
        for key, colour, _ in limits:
            lim = np.where(np.isfinite(s[key]), s[key], np.inf)  # NaN: no fragmentation limit
            ax.contour(r2, size, s["St"] - lim[:, None], levels=[0.0], colors=colour,
                       linewidths=1.2)
        ax.contour(r2, size, s["St"], levels=[1.0], colors="white", linewidths=0.8,
                   linestyles="--")
        for line, r_line in snow_lines(s).items():
            ax.axvline(r_line, color="0.8", ls=":", lw=1)
            ax.text(r_line, 1.01, line, transform=ax.get_xaxis_transform(), ha="center",
                    fontsize=8)
        ax.set(xscale="log", yscale="log", xlim=(s["r"][0], s["r"][-2]),
               ylim=(1e-5, min(size.max(), 10 * largest)), xlabel="r (au)")
        ax.set_title(titles[name], fontsize=9, pad=14)
    axes[0][0].set_ylabel("particle radius a (m)")
    for colour, label in (("C2", "drift limit"), ("C0", "fragmentation limit"),
                          ("white", "St = 1")):
        axes[0][0].plot([], [], color=colour, label=label)
    axes[0][0].legend(fontsize=7, loc="upper right", facecolor="0.3", labelcolor="white")
    bar = fig.colorbar(img, ax=axes[0].tolist(), pad=0.01)
    bar.set_label(r"$\log_{10}\,\sigma_{\rm d}$ (g/cm$^2$ per unit ln m)")
    fig.suptitle(f"DustPy's default disc after {years:.3g} yr: the dust over radius and size",
                 fontsize=11, y=1.04)
    maps = out_dir / "dustpy_case_study.png"
    fig.savefig(maps, dpi=110, bbox_inches="tight")
    plt.close(fig)

    fig, axes = plt.subplots(2, 2, figsize=(10, 7), sharex=True)
    panels = (("v_frag", "V_frag, collision speeds (m/s)"), ("a", "size carrying most mass (m)"),
              ("St", "its Stokes number"), ("d2g", "dust-to-gas ratio"))
    for ax, (key, label) in zip(axes.flat, panels):
        series = {n: (states[n]["v_frag"] if key == "v_frag" else peak(states[n])[key])
                  for n in names}
        r = states[names[0]]["r"][:-1]  # the outermost cell is DustPy's boundary
        if "constant" in series:
            ax.plot(r, series["constant"][:-1], color="0.4", label=titles["constant"])
        if "q16" in series and "q84" in series:
            lo = np.minimum(series["q16"], series["q84"])[:-1]
            hi = np.maximum(series["q16"], series["q84"])[:-1]
            ax.fill_between(r, lo, hi, color="C3", alpha=0.3, lw=0,
                            label="grain physics, 16-84 % posterior")
        if "median" in series:
            ax.plot(r, series["median"][:-1], color="C3", label=titles["median"])
        if key == "v_frag":
            # what V_frag is compared with: where the fastest collision stays below it,
            # nothing fragments
            for n, colour in (("constant", "0.4"), ("median", "C3")):
                if n in states and "v_rel_max" in states[n]:
                    ax.plot(r, states[n]["v_rel_max"][:-1], color=colour, ls="--", lw=1,
                            label=f"fastest collision between populated bins ({n})")
        for line, r_line in snow_lines(states[names[0]]).items():
            ax.axvline(r_line, color="0.6", ls=":", lw=1)
        ax.set(xscale="log", yscale="log", ylabel=label)
    axes[1][1].set_ylim(bottom=EMPTY_D2G)
    axes[0][0].legend(fontsize=8)
    for ax in axes[1]:
        ax.set_xlabel("r (au)")
    fig.suptitle(f"After {years:.3g} yr (dotted: the H2O and CO2 snow lines)", fontsize=11)
    fig.tight_layout()
    profiles = out_dir / "dustpy_case_study_profiles.png"
    fig.savefig(profiles, dpi=110)
    plt.close(fig)
    return [maps, profiles]


def report(states: dict) -> None:
    """The numbers the documentation quotes, read off the runs."""
    for name in RUNS:
        if name not in states:
            continue
        s = states[name]
        p = peak(s)
        lines = snow_lines(s)
        zones = {"refractory": s["r"] < lines["H2O"],
                 "H2O": (s["r"] >= lines["H2O"]) & (s["r"] < lines["CO2"]),
                 "CO2 (to 100 au)": (s["r"] >= lines["CO2"]) & (s["r"] < 100)}
        dust = np.pi * np.diff(s["r"] ** 2)  # annulus areas up to a constant (au^2)
        text = []
        for zone, where in zones.items():
            where = where[:-1] & np.isfinite(p["a"][:-1])
            if not where.any():
                continue
            vf = s["v_frag"][:-1][where]
            fastest = (f", fastest collision between populated bins "
                       f"{s['v_rel_max'][:-1][where].max():.3g} m/s" if "v_rel_max" in s else "")
            text.append(f"{zone}: V_frag {vf.min():.3g}-{vf.max():.3g} m/s{fastest}, a_peak "
                        f"{p['a'][:-1][where].min():.2g}-{p['a'][:-1][where].max():.2g} m, St "
                        f"{p['St'][:-1][where].min():.2g}-{p['St'][:-1][where].max():.2g}")
        mass = (s["Sigma_dust"].sum(axis=1)[:-1] * dust).sum()
        gas = (s["Sigma_gas"][:-1] * dust).sum()
        # bodies, not floor values, in the grid's top decade
        above = above_floor(s)
        top = above[:, s["m"] > s["m"][-1] / 10].sum() / above.sum()
        for when, before in s.get("grid_widened", NOT_WIDENED):
            print(f"{name}: mass grid widened at {when:.3g} yr from {before:.0e} g "
                  f"(now to {s['m'][-1]:.0e} g)")
        print(f"{name} ({s['years']:.3g} yr, {s['seconds']:.0f} s): snow lines H2O "
              f"{lines['H2O']:.2f} au, CO2 {lines['CO2']:.2f} au; dust/gas in the disc "
              f"{mass / gas:.2e}; mass in the top decade of the grid {top:.1e}")
        for t in text:
            print("    " + t)


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--years", type=float, default=1e5, help="length of each run (yr)")
    p.add_argument("--nr", type=int, default=100, help="radial cells (DustPy's default 100)")
    p.add_argument("--mmax", type=float, default=MMAX, help="top of the mass grid (g)")
    p.add_argument("--v-frag-refractory", type=float, default=V_FRAG_REFRACTORY,
                   help="V_frag of bare refractory grains inside the H2O snow line (m/s)")
    p.add_argument("--steps", type=int, default=2000, help="MCMC steps a walker (st.infer)")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--processes", type=int, default=2, help="runs at once")
    p.add_argument("--out-dir", default="docs/figures", help="where the figures go")
    p.add_argument("--data", default="target/dustpy_case_study.npz",
                   help="the runs' final states (written; read with --replot)")
    p.add_argument("--replot", action="store_true", help="draw from --data, run nothing")
    p.add_argument("--checkpoints", default="target/dustpy_case_study",
                   help="where each run's state is saved at every milestone (one .npz a run)")
    p.add_argument("--resume", action="store_true",
                   help="go on from the checkpoints (same settings) instead of from t = 0: a "
                        "long run over several sittings")
    args = p.parse_args()
    out_dir = Path(args.out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    if args.replot:
        saved = np.load(args.data, allow_pickle=True)
        states = {k: saved[k].item() for k in saved.files}
    else:
        start = time.perf_counter()
        v_frags = ice_v_frags(args)
        # spawn: fresh workers (fork after the core's threads have started is unsafe)
        ctx = multiprocessing.get_context("spawn")
        Path(args.data).parent.mkdir(parents=True, exist_ok=True)
        states = {}
        with cf.ProcessPoolExecutor(args.processes, mp_context=ctx) as pool:
            jobs = [pool.submit(run, n, q, v_frags, args) for n, q in RUNS.items()]
            for job in cf.as_completed(jobs):
                state = job.result()
                states[state["name"]] = state
                # saved as each run ends: the finished runs survive an interrupted batch
                np.savez(args.data, **{n: np.array(s, dtype=object) for n, s in states.items()})
        print(f"all runs: {time.perf_counter() - start:.0f} s on {args.processes} processes")
    report(states)
    years = min(s["years"] for s in states.values())
    for path in draw(states, out_dir, years):
        print(f"wrote {path}")


if __name__ == "__main__":
    main()
