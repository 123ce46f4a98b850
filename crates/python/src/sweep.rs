//! `stickiness._core.sweep`: chunks of a sweep grid (`thresholds::sweep`), the same chunks the
//! CLI's `stickiness sweep` computes, so both give the same numbers.

use crate::error::Error;
use crate::material::Material;
use crate::parallel;
use numpy::PyArray1;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use thresholds::sweep::{Grid, Laws, NamedMaterial, Partner, Row, TVisAxis};
use thresholds::{OutOfRange, SearchOptions, TVisLaw};

/// Rows of the chunks `chunks` (all when None) of the grid, as columns: `index` (grid order),
/// the inputs and the results of `thresholds::sweep::COLUMNS` (NaN where none; `radius2` NaN
/// on a wall; `warnings` joined by "; ").
#[pyfunction]
#[pyo3(signature = (materials, gamma_sv, radius, radius2, wall, t_vis, t_vis_law, k, v_max, rel_tol, chunks=None))]
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
                material: m.inner,
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
    grid.validate().map_err(input)?;
    let opts = SearchOptions {
        rel_tol,
        v_max,
        ..SearchOptions::default()
    };
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
    let f = |pick: &dyn Fn(&Row) -> f64| -> Vec<f64> { rows.iter().map(|r| pick(r)).collect() };
    let nan = |v: Option<f64>| v.unwrap_or(f64::NAN);
    let index: Vec<i64> = rows.iter().map(|r| r.point.index as i64).collect();
    dict.set_item("index", PyArray1::from_vec(py, index))?;
    let names: Vec<&str> = rows
        .iter()
        .map(|r| grid.materials[r.point.material].name.as_str())
        .collect();
    dict.set_item("material", names)?;
    type Column<'a> = (&'a str, Box<dyn Fn(&Row) -> f64 + 'a>);
    let columns: Vec<Column> = vec![
        ("gamma_sv", Box::new(|r| r.point.constants.gamma_sv)),
        ("young", Box::new(|r| r.point.constants.young)),
        ("poisson", Box::new(|r| r.point.constants.poisson)),
        ("density", Box::new(|r| r.point.constants.density)),
        ("radius", Box::new(|r| r.point.geometry.r1())),
        ("radius2", Box::new(move |r| nan(r.point.geometry.r2()))),
    ];
    for (name, pick) in &columns {
        dict.set_item(*name, PyArray1::from_vec(py, f(pick.as_ref())))?;
    }
    let walls: Vec<bool> = rows.iter().map(|r| r.point.geometry.is_wall()).collect();
    dict.set_item("wall", PyArray1::from_vec(py, walls))?;
    let results: Vec<Column> = vec![
        ("t_vis", Box::new(|r| r.point.t_vis)),
        ("k", Box::new(|r| r.point.k)),
        ("v_stick", Box::new(move |r| nan(r.v_stick))),
        ("v_double_onset", Box::new(move |r| nan(r.v_double_onset))),
        ("v_stick_jkr", Box::new(|r| r.v_stick_jkr)),
        ("v_frag", Box::new(move |r| nan(r.v_frag))),
        (
            "no_bouncing_below",
            Box::new(move |r| nan(r.no_bouncing_below)),
        ),
    ];
    for (name, pick) in &results {
        dict.set_item(*name, PyArray1::from_vec(py, f(pick.as_ref())))?;
    }
    let warnings: Vec<String> = rows.iter().map(|r| r.warnings.join("; ")).collect();
    dict.set_item("warnings", warnings)?;
    Ok(dict)
}

/// The number of chunks of a grid of these axis lengths (one per combination of every axis
/// but T_vis).
#[pyfunction]
pub fn sweep_chunk_count(
    materials: usize,
    gamma_sv: usize,
    radius: usize,
    radius2: usize,
    k: usize,
) -> usize {
    materials * gamma_sv * radius * radius2 * k
}
