"""Sphinx configuration of the documentation site: `cargo xtask docs` builds it into target/site/.

The API reference renders the docstrings of the installed package (numpydoc), the CLI reference
runs the `stickiness` binary ($STICKINESS_CLI, default target/debug/stickiness) at build time,
the tutorial notebook is shown with its committed outputs (never executed here), and every public
name of `stickiness` and `stickiness.dustpy` must be documented (see `setup` below).
"""

from __future__ import annotations

import sys
from pathlib import Path

import stickiness

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent
sys.path.insert(0, str(HERE / "_ext"))

project = "stickiness"
author = "The stickiness developers"
copyright = "2026, The stickiness developers"
release = version = stickiness.__version__

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.mathjax",
    "numpydoc",
    "myst_nb",
    "clihelp",
]

exclude_patterns = ["_build", "**.ipynb_checkpoints"]
source_suffix = {".md": "myst-nb", ".ipynb": "myst-nb"}
root_doc = "index"

# every cross-reference must resolve (references to the standard library are not checked)
nitpicky = True
nitpick_ignore_regex = [("py:.*", r"(numpy|np|pandas|pd|dask|distributed|dustpy|astropy)\..*")]

# Markdown (MyST) and the notebook: committed outputs, no execution
myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence", "deflist"]
myst_heading_anchors = 3
nb_execution_mode = "off"

# the API reference: numpydoc sections; types are in the docstrings, not in the signatures
autodoc_typehints = "none"
autodoc_member_order = "bysource"
numpydoc_show_class_members = False
numpydoc_xref_param_type = False

html_theme = "furo"
html_title = f"stickiness {release}"
html_static_path: list = []
pygments_style = "sphinx"


def _documented(app, env) -> None:
    """Warn (an error under -W) for a public name of `stickiness` or `stickiness.dustpy` that no
    page documents: a new or renamed function cannot slip past the reference."""
    from sphinx.util import logging

    import stickiness.dustpy as sd

    log = logging.getLogger("stickiness.apicheck")
    objects = env.get_domain("py").objects
    public = [f"stickiness.{n}" for n in stickiness.__all__]
    public += [
        f"stickiness.dustpy.{n}"
        for n, v in vars(sd).items()
        if not n.startswith("_")
        and (getattr(v, "__module__", None) == sd.__name__ or n.isupper())
    ]
    for name in public:
        if name not in objects:
            log.warning("the public name %s is in no page of the API reference", name)


def setup(app):
    app.connect("env-check-consistency", _documented)
