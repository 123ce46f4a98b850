"""Sweeps over a grid as a pandas DataFrame, in process or on a Dask cluster.

The grid is the product of its axes in the order material, gamma_sv, radius, radius2, t_vis, k
(outermost first), computed in chunks: one chunk holds every T_vis of one combination of the
other axes, each search seeded by its neighbour's thresholds. The chunks are those of the CLI's
``stickiness sweep`` (both come from the Rust ``thresholds::sweep``), so the values are the
same. With a ``dask.distributed.Client`` the chunks are mapped over its workers: a lost worker
costs a recomputed chunk, never a row, and the result equals the in-process one.

``pandas`` is needed (``pip install 'stickiness[sweep]'``); ``dask.distributed`` only for
``client=``.
"""

from __future__ import annotations

import sys
import warnings
from dataclasses import dataclass
from typing import Any, Dict, Iterable, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _args, _core
from ._args import StickinessWarning
from ._core import Material
from ._docs import shared

#: The DataFrame's columns, as the CLI's CSV header (stated once, in the Rust library).
COLUMNS: Tuple[str, ...] = tuple(_core.SWEEP_COLUMNS)




def _axis(name: str, values: Any) -> Tuple[float, ...]:
    a = _args.float_array(name, values)
    if a.ndim > 1:
        raise ValueError(f"{name}: an axis is a value or a 1-d list of values, got shape {a.shape}")
    a = a.reshape(-1)
    if a.size == 0:
        raise ValueError(f"{name}: an axis needs at least one value")
    return tuple(float(x) for x in a)


def _materials(material: Any) -> Tuple[Tuple[str, Material], ...]:
    """``(name, Material)`` pairs: a preset name or path, a Material, or a list of these."""
    items = material if isinstance(material, (list, tuple)) else [material]
    if not items:
        raise ValueError("material: at least one material")
    out = []
    for m in items:
        if isinstance(m, str):
            out.append((m, _args.material(m)))
        elif isinstance(m, Material):
            preset = {Material.co2(): "co2", Material.h2o(): "h2o"}.get(m)
            out.append((preset or repr(m), m))
        elif isinstance(m, tuple) and len(m) == 2 and isinstance(m[1], Material):
            out.append((str(m[0]), m[1]))
        else:
            raise TypeError(
                f"material: expected preset names, paths or stickiness.Material, got {type(m).__name__}"
            )
    return tuple(out)


@dataclass(frozen=True)
class SweepSpec:
    """A sweep grid and its search options (SI); picklable, so it travels to Dask workers."""

    materials: Tuple[Tuple[str, Material], ...]
    gamma_sv: Optional[Tuple[float, ...]]
    radius: Tuple[float, ...]
    radius2: Optional[Tuple[float, ...]]
    wall: bool
    t_vis: Optional[Tuple[float, ...]]
    t_vis_law: Optional[str]
    k: Tuple[float, ...]
    v_max: Optional[float]
    rel_tol: float
    method: str = "table"

    @property
    def n_chunks(self) -> int:
        """Chunks of the grid: one per combination of every axis but T_vis."""
        return int(self.compute([])["n_chunks"])

    def compute(self, chunks: Optional[Sequence[int]] = None) -> Dict[str, Any]:
        """The rows of ``chunks`` (all by default) as columns, with their ``index`` in grid order."""
        try:
            return dict(
                _core.sweep(
                    list(self.materials),
                    None if self.gamma_sv is None else list(self.gamma_sv),
                    list(self.radius),
                    None if self.radius2 is None else list(self.radius2),
                    self.wall,
                    None if self.t_vis is None else list(self.t_vis),
                    self.t_vis_law,
                    list(self.k),
                    self.v_max,
                    self.rel_tol,
                    None if chunks is None else list(chunks),
                    self.method,
                )
            )
        except _core._InputError as e:
            raise ValueError(str(e)) from None


def compute_chunks(spec: SweepSpec, chunks: Sequence[int]) -> Dict[str, Any]:
    """One task of a distributed sweep: the rows of ``chunks`` (a top-level, picklable function)."""
    return spec.compute(chunks)


def _frame(parts: Iterable[Dict[str, Any]]) -> Any:
    import pandas as pd  # type: ignore[import-untyped,unused-ignore]

    parts = list(parts)
    if not parts:
        return pd.DataFrame({c: [] for c in COLUMNS})
    columns = {c: np.concatenate([np.asarray(p[c]) for p in parts]) for c in ("index",) + COLUMNS}
    df = pd.DataFrame(columns).sort_values("index", kind="stable")
    df["warnings"] = df["warnings"].astype(str)
    return df.drop(columns="index").reset_index(drop=True)


def _warned(df: Any) -> Any:
    """``df``, after one ``StickinessWarning`` (at the caller of :func:`sweep`) if any of its
    rows carries warnings: how many, and the first row's, so that a slip of units (a radius of
    60 m) is not left to be found in the ``warnings`` column."""
    warned = (df["warnings"] != "").to_numpy()
    if warned.any():
        first = int(np.argmax(warned))
        warnings.warn(
            f"rows with warnings: {int(warned.sum())} of {len(df)} (the 'warnings' column); "
            f"the first, row {first}: {df['warnings'].iloc[first]}",
            StickinessWarning,
            stacklevel=3,
        )
    return df


def _batches(n: int, size: int) -> List[List[int]]:
    return [list(range(i, min(i + size, n))) for i in range(0, n, size)]


@shared
def sweep(
    material: Union[str, Material, Sequence[Union[str, Material]]] = "co2",
    radius: Any = _core.DEFAULT_RADIUS,
    t_vis: Any = None,
    *,
    gamma_sv: Any = None,
    k: Any = _core.DEFAULT_K,
    radius2: Any = None,
    wall: bool = False,
    t_vis_law: Optional[str] = None,
    v_max: Optional[float] = None,
    rel_tol: float = _core.DEFAULT_REL_TOL,
    method: str = "table",
    client: Any = None,
    progress: bool = False,
    chunks_per_task: int = 1,
) -> Any:
    """V_stick, V_double_onset, V_stick,JKR and V_frag = 10 V_stick over a grid, as a pandas
    DataFrame.

    Parameters
    ----------
    material : str, Material or sequence of them, optional
        The materials (outermost axis): preset names, JSON paths or :class:`Material`.
        Default ``'co2'``.
    radius : float, array_like or Quantity, optional
        Radii R1 (m). Default 60e-6.
    t_vis : float, array_like or Quantity
        Relaxation times T_vis (s). Give it or ``t_vis_law``.
    gamma_sv : float, array_like or Quantity, optional
        Surface free energies gamma_SV (J/m^2) replacing each material's. Default None: the
        material's.
    k : float or array_like, optional
        Modulus ratios k (dimensionless; innermost axis). Default 0.01.
    {partner}
    {t_vis_law}
    {search}
    client : dask.distributed.Client, optional
        Map the grid's chunks over its workers (a LocalCluster or a Slurm cluster alike), with
        the same result. Default None: all cores of this process.
    progress : bool, optional
        Show progress on stderr (Dask's progress bar with a client). Default False.
    chunks_per_task : int, optional
        Chunks of the grid in one Dask task. Default 1.

    Returns
    -------
    pandas.DataFrame
        One row a point, in grid order (material, gamma_sv, radius, radius2, t_vis, k;
        outermost first), with the columns of the CLI's ``stickiness sweep`` (SI; NaN where a
        value does not exist; ``method`` says which answered).

    Raises
    ------
    {raises}

    Notes
    -----
    Each chunk holds every T_vis of one combination of the other axes, each search seeded by
    its neighbours' thresholds; the chunks are those of the CLI (both come from the Rust
    ``thresholds::sweep``), so the values are the same. With a client a lost worker costs a
    recomputed chunk, never a row. ``pandas`` is needed (``pip install 'stickiness[sweep]'``),
    ``dask.distributed`` only for ``client=``.

    Examples
    --------
    >>> import stickiness as st
    >>> df = st.sweep("co2", 60e-6, [1e-10, 1e-9], method="table")
    >>> list(df["v_stick"].round(5)), list(df["method"])
    ([0.0205, 0.04138], ['table', 'table'])
    """
    wall = _args.geometry(radius2, wall)
    _args.t_vis_or_law(t_vis, t_vis_law, required=True)
    if not isinstance(chunks_per_task, int) or isinstance(chunks_per_task, bool) or chunks_per_task < 1:
        raise ValueError(f"chunks_per_task = {chunks_per_task!r}: must be an integer >= 1")
    progress = _args.flag("progress", progress)
    if client is not None and not callable(getattr(client, "map", None)):
        raise TypeError(
            f"client: expected a dask.distributed.Client, got {type(client).__name__} "
            "(a scheduler address is Client('tcp://...'))"
        )
    spec = SweepSpec(
        materials=_materials(material),
        gamma_sv=None if gamma_sv is None else _axis("gamma_sv", gamma_sv),
        radius=_axis("radius", radius),
        radius2=None if radius2 is None else _axis("radius2", radius2),
        wall=wall,
        t_vis=None if t_vis is None else _axis("t_vis", t_vis),
        t_vis_law=_args.law_name("t_vis_law", t_vis_law),
        k=_axis("k", k),
        v_max=_args.scalar_option("v_max", v_max),
        rel_tol=_args.scalar("rel_tol", rel_tol),
        method=_args.method(method),
    )
    # check the whole grid before any work (the core validates the axes on every call)
    spec.compute([])
    batches = _batches(spec.n_chunks, chunks_per_task)
    if client is None:
        parts = []
        done = 0
        for group in _batches(len(batches), _core.parallel_batch()):
            chunks = [c for b in group for c in batches[b]]
            parts.append(spec.compute(chunks))
            done += len(chunks)
            if progress:
                print(f"\rsweep: {done}/{spec.n_chunks} chunks", end="", file=sys.stderr)
        if progress:
            print(file=sys.stderr)
        return _warned(_frame(parts))
    futures = client.map(
        compute_chunks,
        [spec] * len(batches),
        batches,
        pure=True,
        retries=3,
    )
    if progress:
        from distributed import progress as dask_progress  # type: ignore[import-untyped,unused-ignore]

        dask_progress(futures)
    return _warned(_frame(client.gather(futures)))
