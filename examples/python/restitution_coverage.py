"""How often the 95 % interval of T_vis from coefficients of restitution (or sticking outcomes)
holds the truth, for grains of a lognormal size distribution (docs/model.md, "Limits of the
likelihood").

Each data set is made with the model: T_vis log-uniform in 10^-10.5 - 10^-8.5 s, 60 um CO2
grains of a lognormal of width 0.3 (radii drawn from the continuous distribution, each collision's
radius unknown to the likelihood), speeds log-uniform in 0.03-0.3 m/s, e from `st.collide` plus a
Gaussian error (clipped at 0, as a measured e is). The posterior is computed exactly on a grid of
log10 T_vis 0.01 apart over the range the truths are drawn from (the prior, log-uniform), from
the likelihood `st.infer` uses (`stickiness._likelihood.Model`), so no sampler error enters: for
data the model made, 95 % of the intervals should hold the truth. With `--sticking N` each set
is N sticking outcomes instead, at speeds within a factor 2 of each grain's own V_stick, T_vis
in 10^-10 - 10^-8.5 s; `--within` keeps the radii within the sample's extreme radii.

    pip install 'stickiness[infer]'
    python examples/python/restitution_coverage.py [--sets 200] [--points 30] [--e-err 0.01]
        [--restitution-nodes 16] [--nodes 64] [--v-min 0.03] [--sticking N [--within]]
"""

import argparse

import numpy as np

import stickiness as st
from stickiness._likelihood import Data, Model

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--sets", type=int, default=200, help="data sets (default 200)")
parser.add_argument("--points", type=int, default=30, help="values of e a set (default 30)")
parser.add_argument("--e-err", type=float, default=0.01, help="1-sigma of e (default 0.01)")
parser.add_argument("--restitution-nodes", type=int, default=16,
                    help="radii e is computed at (st.infer's restitution_nodes; default 16)")
parser.add_argument("--nodes", type=int, default=64,
                    help="radii of the lognormal sample (SizeDistribution.lognormal; default 64)")
parser.add_argument("--v-min", type=float, default=0.03,
                    help="slowest speed of the restitution data (m/s; default 0.03)")
parser.add_argument("--sticking", type=int, default=0,
                    help="sticking outcomes a set instead of restitution data (default: none)")
parser.add_argument("--within", action="store_true",
                    help="radii within the sample's extreme radii (sticking outcomes)")
parser.add_argument("--seed", type=int, default=1, help="seed of the data sets (default 1)")
args = parser.parse_args()

co2 = st.Material.co2()
median, width = 60e-6, 0.3
sizes = st.SizeDistribution.lognormal(median, width, nodes=args.nodes)
# the prior of log10 T_vis (s), from which the truths are drawn, and the grid over it
prior = (-10.0, -8.5) if args.sticking else (-10.5, -8.5)
grid = np.linspace(*prior, int(round((prior[1] - prior[0]) / 0.01)) + 1)
rng = np.random.default_rng(args.seed)
inside, widths = 0, []
impossible = 0
for _ in range(args.sets):
    if args.sticking:
        truth = rng.uniform(*prior)
        radii = median * np.exp(width * rng.standard_normal(args.sticking))
        if args.within:
            radii = np.clip(radii, sizes.radii[0], sizes.radii[-1])
        own = st.v_stick(co2, radii, 10**truth).v_stick
        v = own * 10 ** rng.uniform(-0.3, 0.3, args.sticking)
        data = Data.parse(None, (v, v < own), None)
    else:
        truth = rng.uniform(*prior)
        v = 10 ** rng.uniform(np.log10(args.v_min), np.log10(0.3), args.points)
        radii = median * np.exp(width * rng.standard_normal(args.points))
        e = st.collide(co2, radii, t_vis=10**truth, v_in=v, method="table").e_observed
        e = np.clip(e + args.e_err * rng.standard_normal(args.points), 0.0, 1.0)
        data = Data.parse(None, None, (v, e, args.e_err))
    model = Model(co2, sizes, None, False, 0.01, data, "table", 1e-6, 0.5,
                  args.restitution_nodes)
    if not np.isfinite(model.log_likelihood(np.array([10**truth]), None)[0]):
        impossible += 1  # the data impossible at the truth itself
    ln_l = model.log_likelihood(10**grid, None)
    if not np.isfinite(ln_l).any():
        continue
    p = np.exp(ln_l - ln_l.max())
    lo, hi = np.interp([0.025, 0.975], np.cumsum(p) / p.sum(), grid)
    inside += lo <= truth <= hi
    widths.append(hi - lo)
what = (f"{args.sticking} sticking outcomes" if args.sticking else
        f"{args.points} values of e +- {args.e_err:g}, {args.restitution_nodes} restitution radii")
print(f"{args.sets} data sets of {what} over a {args.nodes}-radius sample: the truth inside the "
      f"95 % interval in {inside} ({100 * inside / args.sets:.1f} %), median width "
      f"{np.median(widths):.3f} dex; the data impossible at the truth in {impossible}")
