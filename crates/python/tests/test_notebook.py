"""The tutorial notebook runs from top to bottom (nbclient, a fresh kernel of this Python), and
its committed outputs are those of a run of the present package: no cell left unexecuted or
failed, and every number and word a cell prints or displays the same as a fresh run gives (the
site shows the committed outputs without running them, so stale ones would be shown as ours)."""

import copy
import pathlib
import re

import nbformat
from nbclient import NotebookClient

NOTEBOOK = pathlib.Path(__file__).resolve().parents[3] / "examples" / "tutorial.ipynb"

# a decimal number in a cell's text output (an int, a float, an exponent), not the digits of a
# name such as int64
NUMBER = re.compile(r"(?<![A-Za-z_\d.])[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?")

# the numbers are those of a deterministic run (a seeded sampler, the same core), equal on this
# platform to the last digit; the bound leaves room for the last bits of another build's libm
# in the closed-form values (a platform whose sampler draws differ would show here: run the
# notebook there and commit, as for a stale output), and still finds the stale T_vis fit of
# 2026-11-28 (2.5e-7 off)
REL_TOL = 1e-7


# matplotlib's text for a figure, whose size and whether it is shown at all depend on the
# backend (inline in Jupyter, Agg under the test command), not on the package
FIGURE = re.compile(r"<Figure size [^>]*>")


def text(cell):
    """A code cell's printed (stdout) and displayed (text/plain) outputs, figures left out."""
    return FIGURE.sub("", "".join(
        o.get("text", "") if o.output_type == "stream" and o.get("name") == "stdout"
        else o.get("data", {}).get("text/plain", "")
        for o in cell.outputs
    ))


def numbers(cell):
    """The numbers of a code cell's outputs ([`text`])."""
    return [float(x) for x in NUMBER.findall(text(cell))]


def words(cell):
    """A code cell's outputs ([`text`]) with every number replaced by `#`: its labels (an
    outcome, a method, a column name)."""
    return NUMBER.sub("#", text(cell))


def test_the_committed_notebook_has_its_outputs():
    nb = nbformat.read(NOTEBOOK, as_version=4)
    code = [c for c in nb.cells if c.cell_type == "code"]
    assert code and all(c.execution_count for c in code), "run the notebook before committing it"
    for c in code:
        assert not any(o.output_type == "error" for o in c.outputs)


def test_the_notebook_runs_and_its_committed_outputs_are_current(tmp_path):
    nb = nbformat.read(NOTEBOOK, as_version=4)
    committed = copy.deepcopy(nb)
    client = NotebookClient(nb, timeout=600, kernel_name="python3",
                            resources={"metadata": {"path": str(tmp_path)}})
    client.execute()  # raises CellExecutionError on the first failing cell
    outputs = "".join(
        o.get("text", "") for c in nb.cells if c.cell_type == "code" for o in c.outputs
    )
    assert "bouncing" in outputs and "P(T_vis < 1e-10 s)" in outputs
    for i, (old, new) in enumerate(zip(committed.cells, nb.cells)):
        if new.cell_type != "code":
            continue
        was, now = numbers(old), numbers(new)
        stale = len(was) != len(now) or any(
            abs(a - b) > REL_TOL * max(abs(a), abs(b)) for a, b in zip(was, now)
        )
        assert not stale, (
            f"cell {i} of {NOTEBOOK.name} shows {was}, a fresh run gives {now}: run the "
            "notebook and commit its outputs"
        )
        assert words(old) == words(new), (
            f"cell {i} of {NOTEBOOK.name} shows {words(old)!r}, a fresh run gives "
            f"{words(new)!r}: run the notebook and commit its outputs"
        )
