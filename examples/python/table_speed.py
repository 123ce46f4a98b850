"""1e6 V_stick in one array call with the default method (docs/performance.md, "Master tables"):
CO2 grains of R1 = 0.1 um - 1 mm and T_vis = 1e-14 - 1e-6 s (both log-uniform), the domain of the
"Instant everywhere" issue, up to and beyond the no-bouncing cliff. The master tables answer
almost every point (beyond the cliff: NaN and `no_bouncing_below`, at once); the exact search
answers the thin band at the cliff, and `.method` says which answered each point."""
import time

import numpy as np

import stickiness as st

rng = np.random.default_rng(1)
n = 1_000_000
r = 10 ** rng.uniform(-7, -3, n)  # R1 (m)
t = 10 ** rng.uniform(-14, -6, n)  # T_vis (s)
st.v_stick("co2", 60e-6, 1e-9)  # the first call loads the tables (microseconds)
for _ in range(3):
    t0 = time.perf_counter()
    res = st.v_stick("co2", r, t)
    dt = time.perf_counter() - t0
    by_table = np.mean(res.method == "table")
    no_bouncing = np.mean(np.isnan(res.v_stick))
    print(f"{n} points: {dt:.2f} s; the tables answered {100 * by_table:.3f} % "
          f"(no bouncing below v_max: {100 * no_bouncing:.1f} %)")
