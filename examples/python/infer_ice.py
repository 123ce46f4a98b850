"""From laboratory data to T_vis and V_frag: the posteriors of CO2 and H2O ice (Section 5 of
Arakawa & Krijt 2021 as an inference), drawn to docs/figures/infer_ice.png.

- CO2: Musiolik et al. (2016a), grains hitting a CO2-covered target (a sphere on a wall), 80 %
  of them within 40-120 um (a lognormal), V_stick = 0.04 +- 0.02 m/s; T_vis free.
- H2O: Gundlach & Blum (2015), 1.5 um grains, V_stick = 9.6 +- 0.3 m/s; T_vis free, and
  gamma_SV free over 0.02-0.19 J/m^2, the spread of the literature (Section 5.2).

Each T_vis posterior is carried to monomers by the size law T_vis ~ R1^1.11 (Section 5.3), and
gives the band of V_frag = 10 V_stick of aggregates of 0.1 um monomers (Section 6). The paper's
conclusion, H2O's T_vis an order of magnitude above CO2's (Section 5.3), becomes a posterior
probability at one size, 1 um.

    pip install 'stickiness[infer]'
    python examples/python/infer_ice.py [OUTPUT.png] [--steps N] [--seed S]
"""

import argparse
import math
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import stickiness as st  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
# the committed figure of the repository this script lies in, wherever it is run from
FIGURE = pathlib.Path(__file__).resolve().parents[2] / "docs" / "figures" / "infer_ice.png"
parser.add_argument("output", nargs="?", default=str(FIGURE),
                    help="the figure (default: the repository's docs/figures/infer_ice.png)")
parser.add_argument("--steps", type=int, default=2000, help="steps per walker (default 2000)")
parser.add_argument("--seed", type=int, default=1)
args = parser.parse_args()

# CO2: 80 % of the grains within 40-120 um, i.e. the 10 and 90 % quantiles of a lognormal
# (the normal's 90 % quantile is 1.2816 sigma)
width = math.log(120 / 40) / (2 * 1.2816)
co2_sizes = st.SizeDistribution.lognormal(median=math.sqrt(40e-6 * 120e-6), width=width)
co2 = st.infer("co2", co2_sizes, wall=True, v_stick=(0.04, 0.02), steps=args.steps,
               seed=args.seed)
# T_vis and gamma_SV trade off along a curved ridge (V_stick = 9.6 m/s): autocorrelation times
# of 70-95 steps (with the differential-evolution moves), so four times the chain (at the
# default 2000: 6000 steps after the burn-in, more than the 50 autocorrelation times below
# which `infer` warns)
h2o = st.infer("h2o", 1.5e-6, v_stick=(9.6, 0.3), free=("t_vis", "gamma_sv"),
               priors={"gamma_sv": (0.02, 0.19)}, steps=4 * args.steps, seed=args.seed)
posteriors = {"CO2": co2, "H2O": h2o}
for name, post in posteriors.items():
    print(f"{name}: {post}; autocorrelation times {post.autocorr_time}")
    print(post.summary().to_string(float_format="{:.3g}".format))

# what the one-sigma reading of Section 5.1 hides: the JKR plateau is not rejected
below = float((co2.samples["t_vis"] < 1e-10).mean())
print(f"CO2: P(T_vis < 1e-10 s) = {below:.2f}; 97.5 % quantile "
      f"{co2.summary().loc['t_vis', '97.5%']:.3g} s (R1 = {co2.reference_radius * 1e6:.3g} um)")

# the paper's comparison (Section 5.3) at one size, R1 = 1 um, by the size law T_vis ~ R1^1.11
at_1um = {name: post.t_vis_at(1e-6) for name, post in posteriors.items()}
rng = np.random.default_rng(args.seed)
ratio = rng.choice(at_1um["H2O"], 100_000) / rng.choice(at_1um["CO2"], 100_000)
above = float(np.mean(ratio > 1))
tenfold = float(np.mean(ratio > 10))
print(f"at 1 um: P(T_vis,H2O > T_vis,CO2) = {above:.3f}, P(T_vis,H2O > 10 T_vis,CO2) = "
      f"{tenfold:.3f}; H2O median {np.median(at_1um['H2O']):.3g} s, CO2 97.5 % "
      f"{np.quantile(at_1um['CO2'], 0.975):.3g} s")

levels = (0.025, 0.16, 0.5, 0.84, 0.975)
# a fifth of the H2O samples have a small gamma_SV, for which 0.1 um monomers have a Tabor
# parameter just below 1 (JKR theory at the edge of its validity, Section 2.2): V_frag warns of
# them once (docs/site/guide/disc.md)
bands = {name: post.v_frag(1e-7, quantiles=levels) for name, post in posteriors.items()}
laws = {"CO2": st.v_frag("co2", 1e-7, t_vis_law="co2", method="table").v_frag,
        "H2O": st.v_frag("h2o", 1e-7, t_vis_law="h2o", method="table").v_frag}
for name, band in bands.items():
    print(f"V_frag (m/s) of {name} aggregates of 0.1 um monomers: "
          + ", ".join(f"{q} {v:.3g}" if np.isfinite(v) else f"{q} beyond the search limit"
                      for q, v in band.items())
          + f" (the Section 5.3 law: {laws[name]:.3g})")

fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.4))
colours = {"CO2": "tab:blue", "H2O": "tab:red"}
bins = np.linspace(-19, -8, 111)
for name, post in posteriors.items():
    x = np.log10(at_1um[name])
    where = "on a CO2 wall, 40-120 um" if name == "CO2" else "1.5 um, gamma_SV free"
    left.hist(x, bins=bins, density=True, histtype="stepfilled", alpha=0.4,
              color=colours[name], label=f"{name} ({where})")
    left.axvline(math.log10(np.quantile(at_1um[name], 0.975)), color=colours[name], ls="--",
                 lw=1)
left.set(xlabel=r"$\log_{10}\,T_{\rm vis}$ (s) at $R_1$ = 1 um", ylabel="posterior density",
         title=f"T_vis posteriors (dashed: 97.5 %); P(H2O > 10 CO2) = {tenfold:.2f}")
left.legend(loc="upper left", fontsize=8)

top = 1e4  # m/s: where V_frag beyond the search limit is drawn
for row, (name, band) in enumerate(bands.items()):
    c = colours[name]
    finite = {q: min(v, top) for q, v in band.items()}
    right.plot([finite["2.5%"], finite["97.5%"]], [row, row], color=c, lw=2)
    right.plot([finite["16%"], finite["84%"]], [row, row], color=c, lw=8, alpha=0.6,
               label=f"{name}: median, 68 % and 95 %")
    right.plot([band["median"]], [row], "o", color="black", ms=5)
    right.plot([laws[name]], [row + 0.15], "v", color=c, ms=7)
    if not np.isfinite(band["97.5%"]):
        right.annotate("beyond the search limit", (top, row), xytext=(-4, 6),
                       textcoords="offset points", ha="right", fontsize=8, color=c)
right.plot([], [], "v", color="grey", label="Section 5.3 size laws")
right.set(xscale="log", xlim=(10, 1.5 * top), ylim=(-0.7, 1.7), yticks=[0, 1],
          yticklabels=list(bands), xlabel="V_frag = 10 V_stick (m/s)",
          title="V_frag of aggregates of 0.1 um monomers")
right.legend(fontsize=8, loc="lower right")
fig.tight_layout()
fig.savefig(args.output, dpi=110)
print(f"wrote {args.output}")
