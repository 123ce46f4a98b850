"""1e5 coefficients of restitution with ``method="table"`` (docs/performance.md, "Restitution
tables"): random materials (gamma_sv 0.01-0.3 J/m^2, E 0.5-200 GPa, nu 0.1-0.45, density
500-5000 kg/m^3), reduced radii 5 nm - 1 cm (two identical spheres or a sphere on a wall), T_vis
1e-16 - 1e-3 s and k 0.005 - 0.05 log-uniform, as in the Rust example
``restitution_accuracy -- 100000 0 wide``; of the points with bouncing below the search limit,
impact speeds log-uniform from V_stick/2 to 100 V_stick, as an experiment's would be. The tables
answer nearly all of them; the ODE the rest, and ``.method`` says which answered each."""
import time
import warnings

import numpy as np

import stickiness as st

# random materials and sizes stray outside JKR's validity (Tabor parameter) and the plausible
# radii: the warnings say so once a call; here they would drown the timings
warnings.simplefilter("ignore", st.StickinessWarning)
rng = np.random.default_rng(2030)
n_materials, per_material = 20, 5000
print("drawing the 1e5 collisions (V_stick of each material and size first: 10-30 s)...")


def log_uniform(lo, hi, size=None):
    return lo * (hi / lo) ** rng.uniform(size=size)


cases = []
for _ in range(n_materials):
    m = st.Material(gamma_sv=log_uniform(0.01, 0.3), young=log_uniform(0.5e9, 200e9),
                    poisson=rng.uniform(0.1, 0.45), density=log_uniform(500.0, 5000.0))
    for wall in (False, True):
        n = 4 * per_material  # drawn; about a third bounces below the search limit
        r = log_uniform(5e-9, 1e-2, n)
        radius = r if wall else 2 * r
        t = log_uniform(1e-16, 1e-3, n)
        k = log_uniform(0.005, 0.05, n)
        th = st.v_stick(m, radius, t, k=k, wall=wall)
        keep = np.flatnonzero(np.isfinite(th.v_stick) & np.isfinite(th.v_double_onset))
        keep = keep[: per_material // 2]
        vs = th.v_stick[keep]
        v = vs * np.exp(rng.uniform(np.log(0.5), np.log(np.minimum(100.0, th.v_max[keep] / vs))))
        cases.append((m, radius[keep], t[keep], k[keep], v, wall))

total = sum(len(c[1]) for c in cases)
m, radius, t, k, v, wall = cases[0]
st.collide(m, radius[:10], t[:10], v[:10], k=k[:10], wall=wall, method="table")  # loads tables
for _ in range(3):
    t0 = time.perf_counter()
    by_table = 0
    for m, radius, t, k, v, wall in cases:
        res = st.collide(m, radius, t, v, k=k, wall=wall, method="table")
        by_table += np.count_nonzero(res.method == "table")
    dt = time.perf_counter() - t0
    print(f"{total} collisions: {dt:.2f} s; the tables answered {100 * by_table / total:.2f} %")
