"""The Python blocks of README.md and of the documentation site run as a reader would run them,
and the numbers their comments give hold.

Each page's blocks run in order in one namespace that starts with ``np``, ``st`` and ``co2``
(the names the pages take as known), in a scratch directory that sees the repository's
``data/``. A statement whose comment starts with a number (``st.v_stick(co2, 60e-6,
1e-9).v_stick  # 0.041376 m/s``) and whose value is a float must round to that number at the
digits shown. This keeps the pages true to the package; the physics behind those numbers is
tested against the paper and closed forms elsewhere (``test_paper.py``, the Rust tests).

Two kinds of block are left to their own tests: DustPy runs (``test_dustpy.py``; a run writes
snapshots of 0.3 GB) and Dask clusters (``test_dask_example_runs``: a cluster started from
code that is not a script's ``__main__`` cannot start its worker processes).
"""

import ast
import contextlib
import io
import math
import pathlib
import re
import warnings

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[3]

PAGES = [ROOT / "README.md"] + sorted((ROOT / "docs" / "site").rglob("*.md"))

BLOCK = re.compile(r"```python\n(.*?)```", re.S)

# a comment that states a number first: "# 0.041376 m/s (Section 4.4: 4.14 cm/s)"
STATED = re.compile(r"#\s*([-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?)(?![\d.eE-])")

# blocks left to their own tests (see the module's docstring)
LEFT = ("from dustpy", "LocalCluster")

PRELUDE = "import numpy as np, stickiness as st\nco2 = st.Material.co2()\n"


def blocks(page):
    """The page's Python blocks with the line each starts on, but those in `LEFT`."""
    text = page.read_text()
    for m in BLOCK.finditer(text):
        if not any(s in m.group(1) for s in LEFT):
            yield text[: m.start()].count("\n") + 2, m.group(1)


def agrees(value, stated):
    """Whether `value` rounds to `stated` (a number as written) at the digits written."""
    mantissa = stated.lower().split("e")[0].lstrip("+-")
    digits = len(mantissa.replace(".", "").lstrip("0")) or 1
    want = float(stated)
    if want == 0:
        return value == 0
    # half a unit of the last digit written, relative
    return abs(value - want) <= 0.5 * 10 ** (math.floor(math.log10(abs(want))) - digits + 1)


PAGES_WITH_BLOCKS = [p for p in PAGES if any(blocks(p))]


def test_the_pages_hold_python_blocks():
    names = {p.relative_to(ROOT).as_posix() for p in PAGES_WITH_BLOCKS}
    assert {"README.md", "docs/site/getting-started.md", "docs/site/guide/python.md"} <= names


@pytest.mark.parametrize("page", PAGES_WITH_BLOCKS, ids=lambda p: p.relative_to(ROOT).as_posix())
def test_the_python_blocks_run_and_their_numbers_hold(page, tmp_path, monkeypatch):
    (tmp_path / "data").symlink_to(ROOT / "data")
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    names = {"__name__": "__docs__"}
    exec(PRELUDE, names)
    checked = 0
    for start, code in blocks(page):
        lines = code.split("\n")
        for stmt in ast.parse(code).body:
            where = f"{page.relative_to(ROOT)}:{start + stmt.lineno - 1}"
            with contextlib.redirect_stdout(io.StringIO()), warnings.catch_warnings():
                warnings.simplefilter("ignore")
                if isinstance(stmt, ast.Expr):
                    value = eval(compile(ast.Expression(stmt.value), where, "eval"), names)
                else:
                    exec(compile(ast.Module([stmt], []), where, "exec"), names)
                    value = None
            last = lines[stmt.end_lineno - 1]
            stated = STATED.search(last[last.find("#"):]) if "#" in last else None
            if stated and isinstance(value, float):
                assert agrees(value, stated.group(1)), f"{where}: {value!r}, the page says {last}"
                checked += 1
    if page.name in ("README.md", "getting-started.md", "python.md"):
        assert checked >= 1, f"{page}: no number checked"


@pytest.mark.parametrize(
    "value, stated, ok",
    [
        (0.04137623, "0.041376", True),
        (0.04137723, "0.041376", False),
        (1.9755875e-9, "1.9756e-9", True),
        (1.9757e-9, "1.9756e-9", False),
        (8.49e-11, "8.5e-11", True),
        (1234.4, "1234", True),
    ],
)
def test_agrees_reads_the_digits_written(value, stated, ok):
    assert agrees(value, stated) is ok
