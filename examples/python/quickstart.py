"""Quick start: do two grains stick? (run: python examples/python/quickstart.py)

Every input and output is SI: radii in m, times in s, speeds in m/s.
"""

import numpy as np

import stickiness as st

co2 = st.Material.co2()  # Arakawa & Krijt (2021), Section 3

# one collision of two CO2 grains of 60 um at 4.5 cm/s (Section 4, Figure 2)
c = st.collide(co2, radius=60e-6, t_vis=1e-9, v_in=0.045)
print(f"collision at 4.5 cm/s: {c.outcome}, e = {c.e:.3f}")

# the threshold velocity for sticking (Section 4.4: 4.14 cm/s)
r = st.v_stick(co2, radius=60e-6, t_vis=1e-9)
print(f"V_stick = {r.v_stick * 100:.4f} cm/s (V_stick,JKR = {r.v_stick_jkr * 100:.4f} cm/s)")

# the same grain on a CO2 wall, as in the laboratory
w = st.v_stick(co2, radius=60e-6, t_vis=1e-9, wall=True)
print(f"V_stick on a wall = {w.v_stick * 100:.4f} cm/s")

# arrays broadcast like numpy: V_stick over relaxation times, all cores
t_vis = np.geomspace(1e-12, 1e-8, 9)
print("T_vis (s):  ", np.array2string(t_vis, precision=1))
# (radius left out: the default, 60 um)
print("V_stick (m/s):", np.array2string(st.v_stick(co2, t_vis=t_vis).v_stick, precision=4))

# the relaxation time for a measured V_stick of 0.04 +- 0.02 m/s (Section 5.1)
f = st.fit_t_vis(co2, radius=60e-6, v_stick=0.04, v_stick_err=0.02)
print(f"T_vis = {f.t_vis:.3g} s ({f.t_vis_min:.3g} .. {f.t_vis_max:.3g} s)")

# V_frag = 10 V_stick for aggregates of 0.1 um monomers with the CO2 size law (Section 6)
v = st.v_frag(co2, radius=0.1e-6, t_vis_law="co2")
print(f"V_frag (0.1 um CO2 monomers) = {v.v_frag:.1f} m/s")
