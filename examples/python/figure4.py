"""Figure 4 of Arakawa & Krijt (2021) with matplotlib: V_stick against T_vis for several k,
CO2 grains of 60 um, with the experimental band of Musiolik et al. (2016a).

    pip install stickiness matplotlib
    python examples/python/figure4.py [OUTPUT.png]
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import stickiness as st  # noqa: E402

co2 = st.Material.co2()
t_vis = np.geomspace(1e-12, 1e-8, 33)
ks = np.array([0.005, 0.01, 0.02, 0.05])
# one call: (33, 1) against (4,) broadcasts to a (33, 4) grid, computed on all cores
r = st.v_stick(co2, radius=60e-6, t_vis=t_vis[:, None], k=ks)

fig, ax = plt.subplots(figsize=(6.4, 4.8))
ax.axhspan(0.02, 0.06, color="gold", alpha=0.4, label="experiment 0.04 ± 0.02 m/s")
ax.axhline(0.04, color="black", lw=1)
for j, k in enumerate(ks):
    ax.plot(t_vis, r.v_stick[:, j], label=f"k = {k}")
ax.plot([t_vis[0]], [r.v_stick_jkr[0, 0]], "k^", label="V_stick,JKR")
ax.set(xscale="log", yscale="log", xlabel="relaxation time T_vis (s)",
       ylabel="threshold velocity for sticking V_stick (m/s)", title="Figure 4: CO2, R1 = 60 um")
ax.legend()
out = sys.argv[1] if len(sys.argv) > 1 else "figure4.png"
fig.tight_layout()
fig.savefig(out, dpi=120)
print(f"wrote {out}")
