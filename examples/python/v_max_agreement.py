"""The master tables against the exact search at random search limits (docs/performance.md, "At a
glance"): 40 random materials (gamma_sv 0.01-0.3 J/m^2, E 0.5-200 GPa, nu 0.1-0.45, density
500-5000 kg/m^3), each with two identical spheres or a sphere on a wall and one ``v_max``
log-uniform from 1e-3 to 100 m/s, and 80 points each (reduced radius 5 nm - 1 cm, T_vis 1e-16 -
1e-3 s, k 0.005-0.05, log-uniform). Where the tables answer (the default method), the same points
are searched (``method="search"``) at the same ``v_max``. The tables promise V_stick and the
onset within 1e-5 of the search and the same "no bouncing below v_max" (NaN) verdicts: the
script prints the largest relative difference and how many verdicts differ."""
import time
import warnings

import numpy as np

import stickiness as st

# random materials and sizes stray outside JKR's validity (Tabor parameter) and the plausible
# radii: the warnings say so once a call; here they would drown the result
warnings.simplefilter("ignore", st.StickinessWarning)
rng = np.random.default_rng(11)
n_materials, per_material = 40, 80


def log_uniform(lo, hi, size=None):
    return lo * (hi / lo) ** rng.uniform(size=size)


worst, verdicts_differ, by_table, total = 0.0, 0, 0, 0
t0 = time.perf_counter()
for _ in range(n_materials):
    m = st.Material(gamma_sv=log_uniform(0.01, 0.3), young=log_uniform(0.5e9, 200e9),
                    poisson=rng.uniform(0.1, 0.45), density=log_uniform(500.0, 5000.0))
    wall = rng.uniform() < 0.5
    r = log_uniform(5e-9, 1e-2, per_material)  # reduced radius (m)
    radius = r if wall else 2 * r
    t = log_uniform(1e-16, 1e-3, per_material)
    k = log_uniform(0.005, 0.05, per_material)
    v_max = log_uniform(1e-3, 1e2)  # m/s, one search limit a call
    table = st.v_stick(m, radius, t, k=k, wall=wall, v_max=v_max)
    sel = table.method == "table"
    search = st.v_stick(m, radius[sel], t[sel], k=k[sel], wall=wall, v_max=v_max,
                        method="search")
    for a, b in ((table.v_stick[sel], search.v_stick),
                 (table.v_double_onset[sel], search.v_double_onset)):
        both = np.isfinite(a) & np.isfinite(b)
        if both.any():
            worst = max(worst, float(np.max(np.abs(a[both] / b[both] - 1.0))))
        verdicts_differ += int(np.count_nonzero(np.isfinite(a) != np.isfinite(b)))
    by_table += int(sel.sum())
    total += per_material
print(f"{total} points, {by_table} answered by the tables; against the search at the same "
      f"v_max: largest relative difference {worst:.2e}, verdicts differing {verdicts_differ} "
      f"({time.perf_counter() - t0:.0f} s)")
