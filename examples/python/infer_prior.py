"""How much of the CO2 posterior is the prior's: the example of infer_ice.py (Musiolik et al.
2016a, 0.04 +- 0.02 m/s on a CO2 wall, 80 % of the grains within 40-120 um) with the lower bound
of the log-uniform T_vis prior moved from 1e-20 to 1e-11 s (docs/model.md, "Limits of the
likelihood"). The share of the posterior on the JKR plateau, its median and the probability
that H2O's T_vis at 1 um exceeds ten times CO2's follow the bound; the 97.5 % upper limit and the
V_frag band of 0.1 um monomers hardly do.

    pip install 'stickiness[infer]'
    python examples/python/infer_prior.py [--steps N]
"""

import argparse
import math
import warnings

import numpy as np

import stickiness as st

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--steps", type=int, default=2000, help="steps per walker (default 2000)")
args = parser.parse_args()
# each posterior reaches its prior's lower bound: that is what this example shows
warnings.simplefilter("ignore", st.StickinessWarning)

width = math.log(120 / 40) / (2 * 1.2816)  # 80 % within 40-120 um
sizes = st.SizeDistribution.lognormal(median=math.sqrt(40e-6 * 120e-6), width=width)
h2o = st.infer("h2o", 1.5e-6, v_stick=(9.6, 0.3), free=("t_vis", "gamma_sv"),
               priors={"gamma_sv": (0.02, 0.19)}, steps=2 * args.steps, seed=1)
t_h2o = h2o.t_vis_at(1e-6)
rng = np.random.default_rng(0)
for lo in (1e-20, 1e-16, 1e-13, 1e-11):
    co2 = st.infer("co2", sizes, wall=True, v_stick=(0.04, 0.02), priors={"t_vis": (lo, 1e-6)},
                   steps=args.steps, seed=1)
    t = co2.samples["t_vis"]
    ratio = rng.choice(t_h2o, 100_000) / rng.choice(co2.t_vis_at(1e-6), 100_000)
    band = co2.v_frag(1e-7, quantiles=(0.025, 0.975))
    print(f"T_vis prior from {lo:g} s: P(T_vis < 1e-10 s) = {np.mean(t < 1e-10):.2f}, "
          f"median {t.median():.2g} s, 97.5 % {t.quantile(0.975):.2g} s; "
          f"P(T_vis,H2O > 10 T_vis,CO2 at 1 um) = {np.mean(ratio > 10):.2f}; "
          f"V_frag of 0.1 um monomers, 95 %: {band.iloc[0]:.1f} - {band.iloc[1]:.1f} m/s")
