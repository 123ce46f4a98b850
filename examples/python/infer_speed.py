"""The speed target of inference (docs/performance.md, "Inference"): 32 walkers x 1000 steps over a
64-radius size distribution (CO2 on a wall, 80 % within 40-120 um, V_stick = 0.04 +- 0.02 m/s)."""
import math, time, warnings, stickiness as st
sizes = st.SizeDistribution.lognormal(median=math.sqrt(40e-6 * 120e-6), width=math.log(3) / (2 * 1.2816))
warnings.simplefilter("ignore", st.StickinessWarning)   # 1000 steps are fewer than 50 autocorrelation times
t0 = time.perf_counter()
post = st.infer("co2", sizes, wall=True, v_stick=(0.04, 0.02), walkers=32, steps=1000, seed=1)
dt = time.perf_counter() - t0
print(f"32 walkers x 1000 steps over {len(sizes)} radii: {dt:.1f} s; {post}")
