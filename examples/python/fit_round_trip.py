"""T_vis fits that give back their V_stick (docs/site/guide/thresholds.md): random materials,
sizes and k of the "Instant everywhere" domain (gamma_SV 0.01-0.3 J/m^2, E 0.5-200 GPa,
nu 0.1-0.45, rho 500-5000 kg/m^3, R1 10 nm - 2 cm, k 0.005-0.05, two identical spheres or a
sphere on a wall) and a target V_stick of 1.001-500 V_stick,JKR, each fitted with
`st.fit_t_vis` (default method), then `st.v_stick` at the fitted T_vis: how far it lies from
the target. Next to the no-bouncing cliff V_stick climbs steeply with T_vis, so a T_vis
bracketed to 1e-5 alone is not enough."""
import sys
import warnings

import numpy as np

import stickiness as st

n = int(sys.argv[1]) if len(sys.argv) > 1 else 2000
rng = np.random.default_rng(5)


def log_uniform(lo, hi):
    return 10 ** rng.uniform(np.log10(lo), np.log10(hi))


misses, by_search, refused = [], 0, 0
with warnings.catch_warnings():
    warnings.simplefilter("ignore", st.StickinessWarning)  # Tabor, implausible radii
    for _ in range(n):
        m = st.Material(gamma_sv=log_uniform(0.01, 0.3), young=log_uniform(5e8, 2e11),
                        poisson=rng.uniform(0.1, 0.45), density=log_uniform(500, 5000))
        r, k, wall = log_uniform(1e-8, 2e-2), log_uniform(0.005, 0.05), bool(rng.integers(2))
        target = st.jkr(m, r, wall=wall).v_stick_jkr * log_uniform(1.001, 500)
        try:
            fit = st.fit_t_vis(m, r, v_stick=target, k=k, wall=wall)
        except ValueError:  # above the largest V_stick a fit takes (5000 m/s)
            refused += 1
            continue
        by_search += fit.method == "search"
        back = st.v_stick(m, r, fit.t_vis, k=k, wall=wall).v_stick
        misses.append(abs(back / target - 1))
e = np.array(misses)
print(f"{len(e)} fits ({by_search} by the search, {refused} refused): |V_stick(T_vis fitted) / "
      f"target - 1| median {np.median(e):.1e}, 99.9 % {np.percentile(e, 99.9):.1e}, "
      f"max {e.max():.1e}; above 1e-6: {np.mean(e > 1e-6):.2%}, "
      f"above 1e-5: {np.mean(e > 1e-5):.2%}")
