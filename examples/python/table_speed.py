"""1e6 V_stick in one array call through the master table (docs/performance.md, "Master table"):
CO2 grains of 1-100 um (log-uniform) at T_vis 1e-14-1e-10 s (log-uniform), all answered by the table."""
import time, numpy as np, stickiness as st
rng = np.random.default_rng(1)
n = 1_000_000
r = 10 ** rng.uniform(-6, -4, n)
t = 10 ** rng.uniform(-14, -10, n)
st.v_stick("co2", 60e-6, 1e-9, method="table")
t0 = time.perf_counter()
res = st.v_stick("co2", r, t, method="table")
dt = time.perf_counter() - t0
print(f"{n} points: {dt:.2f} s; table answered {np.mean(res.method == 'table'):.4f}")
