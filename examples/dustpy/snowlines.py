"""The same short DustPy disc twice: a constant V_frag of 10 m/s, and V_frag from grain physics
with 0.1 um monomers (stickiness.dustpy.set_vfrag), with a figure of both.

    python examples/dustpy/snowlines.py [--years 1e4] [--out docs/figures/dustpy_snowlines.png]

Needs DustPy (`pip install dustpy`; its build needs gfortran) and matplotlib. Each run of the
default 1e4 yr takes about half a minute on 2 cores.
"""

import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from dustpy import Simulation  # noqa: E402
from dustpy import constants as c  # noqa: E402

from stickiness import dustpy as sd  # noqa: E402

MONOMER_RADIUS = 1e-7  # m: 0.1 um monomers (Arakawa & Krijt 2021, Section 6)
CONSTANT_V_FRAG = 10.0  # m/s: a common choice in dust-evolution models


def run(years: float, physics: bool):
    sim = Simulation()
    sim.ini.grid.Nr = 30
    sim.ini.grid.mmax = 1e3
    sim.ini.dust.vFrag = CONSTANT_V_FRAG * sd.CM_PER_M  # DustPy works in cgs: cm/s
    sim.initialize()
    if physics:
        sd.set_vfrag(sim, monomer_radius=MONOMER_RADIUS)
    sim.writer = None
    sim.verbosity = 0
    sim.t.snapshots = np.array([years]) * c.year
    sim.run()
    r = np.asarray(sim.grid.r) / c.au
    v_frag = np.asarray(sim.dust.v.frag) / sd.CM_PER_M  # m/s
    # the particle size that carries most of the dust mass at each radius
    sigma = np.asarray(sim.dust.Sigma)
    a_peak = np.asarray(sim.dust.a)[np.arange(len(r)), sigma.argmax(axis=1)]
    # the outermost cell is DustPy's boundary: leave it out
    return r[:-1], v_frag[:-1], a_peak[:-1], np.asarray(sim.gas.T)[:-1]


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--years", type=float, default=1e4, help="length of each run (yr)")
    p.add_argument("--out", default="docs/figures/dustpy_snowlines.png", help="the figure")
    args = p.parse_args()
    r, v_const, a_const, T = run(args.years, physics=False)
    _, v_phys, a_phys, _ = run(args.years, physics=True)
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    left.plot(r, v_const, label="constant 10 m/s")
    left.plot(r, v_phys, label="grain physics, 0.1 um monomers")
    right.plot(r, a_const * 1e-2, label="constant 10 m/s")  # cm -> m
    right.plot(r, a_phys * 1e-2, label="grain physics, 0.1 um monomers")
    for ax in (left, right):
        for T_line, name in ((sd.T_H2O, "H2O"), (sd.T_CO2, "CO2")):
            i = np.argmin(np.abs(T - T_line))
            ax.axvline(r[i], color="grey", ls=":", lw=1)
            ax.text(r[i], 1.02, f"{name} snow line", transform=ax.get_xaxis_transform(),
                    ha="center", fontsize=8, color="grey")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("distance from the star r (au)")
        ax.legend(fontsize=8)
    left.set_ylabel("fragmentation velocity V_frag (m/s)")
    right.set_ylabel("size carrying most dust mass (m)")
    a_cap = (3 * 1e3 / (4 * np.pi * 1.67)) ** (1 / 3) * 1e-2  # m: mmax = 1e3 g at DustPy's density
    right.axhline(a_cap, color="grey", lw=0.8)
    right.text(1.05, a_cap, "mass grid limit (mmax = 1e3 g)", fontsize=7, color="grey", va="bottom")
    fig.suptitle(f"DustPy, {args.years:g} yr: V_frag from the ice that coats the monomers", y=1.0)
    fig.tight_layout()
    fig.savefig(args.out, dpi=110)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
