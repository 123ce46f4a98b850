"""The speed targets of inference (docs/performance.md, "Inference"): 32 walkers x 1000 steps over a
64-radius size distribution (CO2 on a wall, 80 % within 40-120 um, V_stick = 0.04 +- 0.02 m/s).
With --sticking: 300 sticking outcomes (speeds log-uniform over 5 mm/s - 0.2 m/s, stuck below
0.04 m/s) over the same 64 radii, not on a wall, instead of the threshold."""
import math, sys, time, warnings
import numpy as np
import stickiness as st
sizes = st.SizeDistribution.lognormal(median=math.sqrt(40e-6 * 120e-6), width=math.log(3) / (2 * 1.2816))
warnings.simplefilter("ignore", st.StickinessWarning)   # 1000 steps are fewer than 50 autocorrelation times
t0 = time.perf_counter()
if "--sticking" in sys.argv[1:]:
    v = 10 ** np.random.default_rng(0).uniform(math.log10(0.005), math.log10(0.2), 300)
    post = st.infer("co2", sizes, sticking=(v, v < 0.04), walkers=32, steps=1000, seed=1)
    data = "300 sticking outcomes"
else:
    post = st.infer("co2", sizes, wall=True, v_stick=(0.04, 0.02), walkers=32, steps=1000, seed=1)
    data = "a threshold, on a wall"
dt = time.perf_counter() - t0
print(f"32 walkers x 1000 steps over {len(sizes)} radii, {data}: {dt:.1f} s (with infer's lazy import of pandas); {post}")
