"""The Python blocks of README.md and of the documentation site run as a reader would run them,
and the numbers their comments give hold; the "this code" column of the paper-vs-ours tables
(README.md, "Validation") is what the package gives, at the digits written.

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
import functools
import io
import math
import pathlib
import re
import warnings

import pytest

import stickiness as st

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
    # within half a unit of the last digit written
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


@functools.cache
def _results():
    """What the package gives for each row of the paper-vs-ours tables (README.md, "Validation"),
    by the start of the row's quantity: the values of the "this code" column, in its units."""
    co2 = st.Material.co2()

    def h2o(gamma_sv):
        return st.Material.h2o().replace(gamma_sv=gamma_sv)

    def search(m, r, t):
        return st.v_stick(m, r, t, method="search")

    fit = st.fit_t_vis(co2, 60e-6, 0.04, v_stick_err=0.02, method="search")
    at_1e9 = search(co2, 60e-6, 1e-9)
    rows = {
        "CO2 E, nu from sound speeds": lambda: [co2.young / 1e9, co2.poisson],
        "CO2 Tabor parameter": lambda: [st.jkr(co2, 60e-6).tabor],
        "CO2 V_stick,JKR, R1 = 60 um": lambda: [st.jkr(co2, 60e-6).v_stick_jkr],
        "CO2 V_frag,JKR": lambda: [st.v_frag(co2, 30e-6, 0.0).v_frag_jkr],
        "same: sticking -> double": lambda: [100 * at_1e9.v_double_onset],
        "same: V_stick, double -> bouncing": lambda: [100 * at_1e9.v_stick],
        "CO2 60 um, T_vis = 1e-9 s: V_stick, double -> bouncing": lambda: [100 * at_1e9.v_stick],
        "CO2 60 um: V_stick at T_vis = 8.5e-11 s": lambda: [search(co2, 60e-6, 8.5e-11).v_stick],
        "CO2 60 um: V_stick at T_vis = 1.97e-9 s": lambda: [search(co2, 60e-6, 1.97e-9).v_stick],
        "CO2 60 um: T_vis for 0.04": lambda: [fit.t_vis_min, fit.t_vis_max],
        "CO2 60 um: V_stick at T_vis = 1e-14 s": lambda: [search(co2, 60e-6, 1e-14).v_stick],
        "H2O 90 um, gamma_SV = 0.19: T_vis for 0.73": lambda: [
            st.fit_t_vis(h2o(0.19), 90e-6, 0.73, method="search").t_vis],
        "H2O 90 um, gamma_SV = 0.02: T_vis for 0.73": lambda: [
            st.fit_t_vis(h2o(0.02), 90e-6, 0.73, method="search").t_vis],
        "H2O 90 um: V_stick at 5.3e-9 s / 2.37e-8 s": lambda: [
            search(h2o(0.19), 90e-6, 5.3e-9).v_stick, search(h2o(0.02), 90e-6, 2.37e-8).v_stick],
        "T_vis,H2O(90 um)": lambda: [st.t_vis_law("h2o", 90e-6)],
    }
    # each row's values computed at most once, where a table shows that row
    return {key: functools.cache(values) for key, values in rows.items()}


NUMBER = re.compile(r"[-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?")


@pytest.mark.parametrize("page", ["README.md", "docs/site/validation.md"])
def test_the_results_tables_say_what_the_package_gives(page):
    results = _results()
    rows = [r for r in (ROOT / page).read_text().splitlines() if r.startswith("| ")]
    checked = 0
    for row in rows:
        cells = [c.strip() for c in row.strip("|").split("|")]
        if len(cells) < 3:
            continue
        key = next((k for k in results if cells[0].startswith(k)), None)
        if key is None:
            continue
        ours = cells[2].split("(")[0]  # "(*)", "(2e-4 above)": notes, not values
        values = results[key]()
        written = NUMBER.findall(ours)[: len(values)]
        assert len(written) == len(values), f"{page}: {row}"
        for value, w in zip(values, written):
            assert agrees(value, w), f"{page}: {cells[0]}: the package gives {value!r}, not {w}"
        checked += 1
    assert checked >= (4 if page == "README.md" else 14), f"{page}: {checked} rows checked"
