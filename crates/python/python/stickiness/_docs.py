"""The parameter descriptions that several public functions share, written once.

A public function's docstring names a shared parameter as ``{name}``; :func:`shared` fills
it in at import, so that ``help()``, Jupyter and Sphinx show the whole numpydoc text while the
sources state each description once.
"""

from __future__ import annotations

from typing import Any, Callable, Dict, TypeVar

F = TypeVar("F", bound=Callable[..., Any])

#: numpydoc entries of the parameters shared by the public functions (SI units throughout).
PARAMETERS: Dict[str, str] = {
    "material": """material : Material or str
        The grains' material: a :class:`Material`, a preset name (``'co2'``, ``'h2o'``) or the
        path of a JSON file with ``gamma_sv``, ``young``, ``poisson``, ``density`` (SI).""",
    "radius": """radius : float, array_like or Quantity, optional
        Radius R1 of the (first) sphere (m). Default 60e-6, the CO2 grains of Musiolik et al.
        (2016a).""",
    "t_vis": """t_vis : float, array_like or Quantity
        Viscoelastic relaxation time T_vis (s, >= 0; 0 is the JKR limit). Give it or
        ``t_vis_law``.""",
    "k": """k : float or array_like, optional
        Ratio of the relaxed to the instantaneous modulus (dimensionless, 0 < k <= 0.9: as
        k -> 1 the window of beta a contact crosses closes). Default 0.01, the paper's fiducial
        value (Section 2.3); the master tables cover 0.005-0.05.""",
    "radius2": """radius2 : float, array_like or Quantity, optional
        Radius R2 of the second sphere (m). Default None: two identical spheres.""",
    "wall": """wall : bool, optional
        A sphere on a flat wall of the same material (R2 -> infinity), the laboratory geometry
        of Musiolik et al. (2016a). Excludes ``radius2``. Default False.""",
    "t_vis_law": """t_vis_law : {'co2', 'h2o'}, optional
        Take T_vis from the size law of Section 5.3 at ``radius``: T_vis,CO2 = 1e-11 s
        (R1/1 um)^1.11, T_vis,H2O = 1e-10 s (R1/1.5 um)^1.11. Excludes ``t_vis``. A law
        with the other ice's constants (``"co2"`` grains, ``t_vis_law="h2o"``) is warned of
        (``StickinessWarning``).""",
    "v_max": """v_max : float or Quantity, optional
        Highest impact speed searched for bouncing (m/s, at most 1e4). Default 1000
        V_stick,JKR.""",
    "v_max_fit": """v_max : float or Quantity, optional
        Highest impact speed searched for bouncing (m/s, at most 1e4). Default twice each
        trial's target V_stick, raised to ``v_max`` where that is higher (a ``v_max`` below
        V_stick + dV is an error).""",
    "rel_tol": """rel_tol : float, optional
        Relative width of the final brackets of the search (dimensionless, 1e-15 < rel_tol <
        0.5). Default 1e-6.""",
    "monomer_radius": """radius : float, array_like or Quantity, optional
        Radius of the aggregates' monomers (m): R1 of the two identical spheres whose V_stick
        sets V_frag (Section 6; with ``radius2`` or ``wall``, R1 of that pair). Default 60e-6.""",
    "method": """method : {'table', 'search'}, optional
        ``'table'`` (default): the master tables of V_stick / V_stick,JKR over the two
        dimensionless numbers and k, about a microsecond a point and within 1e-5 of the search
        where they vouch for their accuracy; elsewhere (a thin band at the no-bouncing cliff, k
        outside 0.005-0.05, a ``rel_tol`` below 1e-5 other than the default 1e-6) the search
        answers.
        ``'search'``: the exact search, 20-100 collisions, milliseconds a point. The result's
        ``method`` says which answered.""",
    "broadcast": """Every number argument broadcasts like numpy: scalars in give Python floats out,
    arrays in give ndarrays of the broadcast shape, computed on all cores with the GIL released
    (Ctrl-C stops them within about a second). Dimensional arguments accept
    ``astropy.units.Quantity`` and are converted to SI.""",
    "raises": """TypeError
        An argument of the wrong type (a string for a number, a complex number, ...).
    ValueError
        An argument out of its range, naming the argument and, for arrays, the element
        (``radius[1] = nan: must be > 0 and finite (m)``); a quantity of the wrong dimension.
    SolverError
        A computation failed (the ODE solver); the message names the parameters.""",
}

#: Parameters that always come together, under one name: the second body (``radius2``,
#: ``wall``) and the search settings (``v_max``, ``rel_tol``, ``method``; ``fit_t_vis``'s
#: ``v_max`` has its own default).
PARAMETERS.update(
    {
        group: "\n    ".join(PARAMETERS[name] for name in names)
        for group, names in (
            ("partner", ("radius2", "wall")),
            ("search", ("v_max", "rel_tol", "method")),
            ("search_fit", ("v_max_fit", "rel_tol", "method")),
        )
    }
)


def shared(fn: F) -> F:
    """Fills the ``{name}`` fields of ``fn``'s docstring from :data:`PARAMETERS`."""
    if fn.__doc__:
        fn.__doc__ = fn.__doc__.format(**PARAMETERS)
    return fn
