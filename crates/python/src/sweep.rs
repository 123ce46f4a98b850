//! `stickiness._core.sweep`: chunks of a sweep grid (`thresholds::sweep`), the same chunks the
//! CLI's `stickiness sweep` computes, so both give the same numbers.

use crate::error::Error;
use crate::material::Material;
use crate::parallel;
use numpy::PyArray1;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use thresholds::sweep::{
    Cell, Grid, GridError, Laws, NamedMaterial, Partner, Row, TVisAxis, COLUMNS, WARNINGS_SEPARATOR,
};
use thresholds::{OutOfRange, TVisLaw};

/// Rows of the chunks `chunks` (all when None) of the grid, as columns: `index` (grid order),
/// then each of `thresholds::sweep::COLUMNS` (NaN where a number does not exist, `radius2` on
/// a wall; `warnings` joined by "; "), and `n_chunks`, the grid's number of chunks.
#[pyfunction]
#[pyo3(signature = (materials, gamma_sv, radius, radius2, wall, t_vis, t_vis_law, k, v_max, rel_tol, chunks=None, method="table"))]
#[allow(clippy::too_many_arguments)]
pub fn sweep<'py>(
    py: Python<'py>,
    materials: Vec<(String, Material)>,
    gamma_sv: Option<Vec<f64>>,
    radius: Vec<f64>,
    radius2: Option<Vec<f64>>,
    wall: bool,
    t_vis: Option<Vec<f64>>,
    t_vis_law: Option<String>,
    k: Vec<f64>,
    v_max: Option<f64>,
    rel_tol: f64,
    chunks: Option<Vec<usize>>,
    method: &str,
) -> PyResult<Bound<'py, PyDict>> {
    let t_vis = match (t_vis, t_vis_law) {
        (Some(t), None) => TVisAxis::Values(t),
        (None, Some(name)) => TVisAxis::Law(TVisLaw::from_name(&name).ok_or_else(|| {
            PyValueError::new_err(format!(
                "t_vis_law = '{name}': must be one of {}",
                thresholds::T_VIS_LAWS
            ))
        })?),
        _ => {
            return Err(PyValueError::new_err(
                "give exactly one of t_vis and t_vis_law",
            ))
        }
    };
    let grid = Grid {
        materials: materials
            .into_iter()
            .map(|(name, m)| NamedMaterial {
                name,
                material: m.inner(),
            })
            .collect(),
        gamma_sv,
        radius,
        partner: match (radius2, wall) {
            (Some(r), false) => Partner::Radii(r),
            (None, true) => Partner::Wall,
            (None, false) => Partner::Same,
            (Some(_), true) => {
                return Err(PyValueError::new_err(
                    "radius2 and wall=True exclude each other (a wall is R2 -> infinity)",
                ))
            }
        },
        t_vis,
        k,
    };
    let input = |bad: OutOfRange| -> PyErr { Error::Input { bad, index: 0 }.into() };
    grid.validate().map_err(|e| match e {
        GridError::OutOfRange(bad) => input(bad),
        too_large => PyValueError::new_err(too_large.to_string()),
    })?;
    let opts = crate::args::search_options(v_max, rel_tol, method)?;
    opts.validate().map_err(input)?;
    let all = grid.chunks();
    let picked: Vec<usize> = chunks.unwrap_or_else(|| (0..all.len()).collect());
    if let Some(&bad) = picked.iter().find(|&&c| c >= all.len()) {
        return Err(PyValueError::new_err(format!(
            "chunk {bad}: the grid has {} chunks",
            all.len()
        )));
    }
    let laws = Laws::new(&grid.k).map_err(|e| Error::from_thresholds(e, 0))?;
    let law = |k: f64| laws.get(k);
    let computed: Vec<Vec<Row>> = parallel::map(py, picked.len(), |i| {
        all[picked[i]]
            .compute(&law, &opts)
            .map_err(|e| Error::from_thresholds(e, 0))
    })?;
    let rows: Vec<&Row> = computed.iter().flatten().collect();
    let dict = PyDict::new(py);
    dict.set_item("n_chunks", all.len())?;
    let index: Vec<i64> = rows.iter().map(|r| r.point.index as i64).collect();
    dict.set_item("index", PyArray1::from_vec(py, index))?;
    let cells: Vec<[Cell; COLUMNS.len()]> = rows.iter().map(|r| r.cells(&grid)).collect();
    for (j, name) in COLUMNS.iter().enumerate() {
        let column = cells.iter().map(|c| &c[j]);
        match cells.first().map(|c| &c[j]) {
            Some(Cell::Number(_)) | None => {
                let values: Vec<f64> = column
                    .map(|c| match c {
                        Cell::Number(v) => v.unwrap_or(f64::NAN),
                        _ => f64::NAN,
                    })
                    .collect();
                dict.set_item(*name, PyArray1::from_vec(py, values))?;
            }
            Some(Cell::Flag(_)) => {
                let values: Vec<bool> = column.map(|c| matches!(c, Cell::Flag(true))).collect();
                dict.set_item(*name, PyArray1::from_vec(py, values))?;
            }
            Some(Cell::Text(_) | Cell::List(_)) => {
                let values: Vec<String> = column
                    .map(|c| match c {
                        Cell::Text(s) => s.clone(),
                        Cell::List(l) => l.join(WARNINGS_SEPARATOR),
                        _ => String::new(),
                    })
                    .collect();
                dict.set_item(*name, values)?;
            }
        }
    }
    Ok(dict)
}
