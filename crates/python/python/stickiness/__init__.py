"""Do two colliding dust or ice grains stick or bounce?

The viscoelastic contact model of Krijt et al. (2013) as reviewed and applied by Arakawa &
Krijt (2021, "On the stickiness of CO2 and H2O ice particles"), compiled from the Rust
reference implementation. Every input and output is SI: radii in m, times in s, speeds in
m/s, gamma_sv in J/m^2, young in Pa, density in kg/m^3; astropy quantities are converted.

Quick start::

    import numpy as np, stickiness as st
    co2 = st.Material.co2()
    st.v_stick(co2, 60e-6, 1e-9).v_stick                     # 0.04137... m/s (Section 4.4)
    r = st.v_stick(co2, 60e-6, np.geomspace(1e-12, 1e-8, 33), method="table")
    r.v_stick                                                 # ndarray of shape (33,), microseconds

Functions: :func:`crack_speed`, :func:`jkr`, :func:`dimensionless`, :func:`collide`,
:func:`v_stick`, :func:`fit_t_vis`, :func:`v_frag`, :func:`t_vis_law`, :func:`sweep`; inference
from laboratory data: :func:`infer` (with :class:`SizeDistribution`, giving a
:class:`Posterior`; needs ``pip install 'stickiness[infer]'``); the material:
:class:`Material`; results: :class:`JKR`, :class:`Dimensionless`, :class:`Collision`,
:class:`VStick`, :class:`TVisFit`, :class:`VFrag`. Leading arguments are positional (``material, radius``, then
``t_vis``, ``v_in`` or ``v_stick``), every other one keyword-only, in one order across the
functions: ``k, radius2, wall, t_vis_law, v_max, rel_tol, method``.

Arguments that are numbers broadcast like numpy: scalars in give Python floats out, arrays in
give ndarrays of the broadcast shape. Array calls release the GIL, run on all cores, and stop
on Ctrl-C within about a second.

Where a threshold does not exist, its value is NaN: ``v_stick`` (and ``v_double_onset``,
``v_frag``) when no collision bounces up to the search limit, which ``no_bouncing_below``
then holds (NaN where bouncing was found); ``contact_time`` of a sticking collision (``None``
for a single one) and of every other collision the restitution tables answered
(``collide(..., method="table")``: they hold e and V_out only). No other result is ever NaN.

Errors: bad input raises ``ValueError`` naming the argument and, for arrays, the element
(``radius[1] = nan: must be > 0 and finite (m)``); arguments of the wrong type raise
``TypeError``; a failed computation raises :class:`SolverError` (a ``RuntimeError``) naming the
parameters. A Tabor parameter below 1 (JKR theory outside its validity), a radius outside
10 nm - 1 cm, impact speeds above 1 km/s and fits reaching V_stick,JKR give a
:class:`StickinessWarning`.
"""

from . import _core
from ._args import StickinessWarning
from ._core import Material, SolverError, __version__
from ._contact import crack_speed, dimensionless, jkr, t_vis_law
from ._functions import collide, fit_t_vis, v_frag, v_stick
from ._results import JKR, Collision, Dimensionless, TVisFit, VFrag, VStick
from ._infer import infer
from ._posterior import Posterior
from ._sizes import SizeDistribution
from .sweeps import sweep

__all__ = [
    "Material",
    "SolverError",
    "StickinessWarning",
    "JKR",
    "Dimensionless",
    "Collision",
    "VStick",
    "TVisFit",
    "VFrag",
    "crack_speed",
    "jkr",
    "dimensionless",
    "collide",
    "v_stick",
    "fit_t_vis",
    "v_frag",
    "t_vis_law",
    "sweep",
    "infer",
    "SizeDistribution",
    "Posterior",
    "DEFAULT_RADIUS",
    "DEFAULT_K",
    "DEFAULT_REL_TOL",
    "__version__",
]

#: Default radius R1 (m): the typical CO2 grain of Musiolik et al. (2016a), as the CLI's default.
DEFAULT_RADIUS: float = _core.DEFAULT_RADIUS
#: Default modulus ratio k (dimensionless): the paper's fiducial value (Section 2.3).
DEFAULT_K: float = _core.DEFAULT_K
#: Default relative tolerance of the threshold searches, as the CLI's.
DEFAULT_REL_TOL: float = _core.DEFAULT_REL_TOL
