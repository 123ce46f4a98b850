//! The vectorised threshold functions of `stickiness._core`: V_stick, V_frag and the T_vis fit,
//! each element answered by the master tables or the exact search (`method`), with a
//! `"method"` column saying which answered (0: search, 1: table).

use crate::args::{method_code, or_nan, search_options, warned, Array, Elements, Warned};
use crate::error::Error;
use crate::material::Material;
use crate::parallel;
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use thresholds::{Contact, CrackLaw, FitWarning, ThresholdMethod, ThresholdsError};

/// What one element gives: its values (in the order of the call's names), the method that
/// answered, and its warnings.
type Answer<const N: usize> = ([f64; N], ThresholdMethod, Warned);

/// The elements of a threshold function: element `i` is `f(i, contact, law)`; a dict of the
/// columns `names`, `"method"` and `"warnings"`.
fn per_element<'py, const N: usize>(
    py: Python<'py>,
    e: &Elements<'_>,
    names: [&str; N],
    f: impl Fn(usize, &Contact, &CrackLaw) -> Result<Answer<N>, ThresholdsError> + Sync + Send,
) -> PyResult<Bound<'py, PyDict>> {
    let rows = parallel::map(py, e.n, |i| {
        let c = e.contact(i)?;
        let (values, method, mut w) =
            f(i, &c, e.law(i)?).map_err(|err| Error::from_thresholds(err, i))?;
        let mut all = warned(i, c.warnings());
        all.append(&mut w);
        Ok((values, method, all))
    })?;
    let dict = PyDict::new(py);
    for (j, name) in names.iter().enumerate() {
        let col: Vec<f64> = rows.iter().map(|r| r.0[j]).collect();
        dict.set_item(*name, PyArray1::from_vec(py, col))?;
    }
    let methods: Vec<u8> = rows.iter().map(|r| method_code(r.1)).collect();
    dict.set_item("method", PyArray1::from_vec(py, methods))?;
    let warnings: Warned = rows.into_iter().flat_map(|r| r.2).collect();
    dict.set_item("warnings", warnings)?;
    Ok(dict)
}

/// V_stick, V_double_onset, V_stick,JKR, no_bouncing_below and v_max (m/s; NaN where none);
/// `gamma_sv` (J/m^2), if given, replaces the material's per element.
#[pyfunction]
#[pyo3(signature = (material, radius, radius2, wall, t_vis, k, v_max, rel_tol, method, gamma_sv=None))]
#[allow(clippy::too_many_arguments)]
pub fn v_stick<'py>(
    py: Python<'py>,
    material: Material,
    radius: Array<'py>,
    radius2: Option<Array<'py>>,
    wall: bool,
    t_vis: Array<'py>,
    k: Array<'py>,
    v_max: Option<f64>,
    rel_tol: f64,
    method: &str,
    gamma_sv: Option<Array<'py>>,
) -> PyResult<Bound<'py, PyDict>> {
    let t_vis = crate::args::data(&t_vis, "t_vis")?;
    let e = Elements::new(
        &material,
        gamma_sv.as_ref(),
        &radius,
        radius2.as_ref(),
        wall,
        Some(&k),
        &[("t_vis", t_vis)],
    )?;
    let opts = search_options(v_max, rel_tol, method)?;
    let names = [
        "v_stick",
        "v_double_onset",
        "v_stick_jkr",
        "no_bouncing_below",
        "v_max",
    ];
    per_element(py, &e, names, |i, c, law| {
        let th = thresholds::sticking_thresholds(c, law, t_vis[i], &opts)?;
        let values = [
            or_nan(th.v_stick),
            or_nan(th.v_double_onset),
            th.v_stick_jkr,
            or_nan(th.no_bouncing_below()),
            th.v_max,
        ];
        Ok((values, th.method, Vec::new()))
    })
}

/// V_frag = 10 V_stick with V_stick, T_vis, V_frag,JKR, V_stick,JKR, no_bouncing_below.
#[pyfunction]
#[pyo3(signature = (material, radius, radius2, wall, t_vis, k, v_max, rel_tol, method, gamma_sv=None))]
#[allow(clippy::too_many_arguments)]
pub fn v_frag<'py>(
    py: Python<'py>,
    material: Material,
    radius: Array<'py>,
    radius2: Option<Array<'py>>,
    wall: bool,
    t_vis: Array<'py>,
    k: Array<'py>,
    v_max: Option<f64>,
    rel_tol: f64,
    method: &str,
    gamma_sv: Option<Array<'py>>,
) -> PyResult<Bound<'py, PyDict>> {
    let t_vis = crate::args::data(&t_vis, "t_vis")?;
    let e = Elements::new(
        &material,
        gamma_sv.as_ref(),
        &radius,
        radius2.as_ref(),
        wall,
        Some(&k),
        &[("t_vis", t_vis)],
    )?;
    let opts = search_options(v_max, rel_tol, method)?;
    let names = [
        "v_frag",
        "v_stick",
        "t_vis",
        "v_frag_jkr",
        "v_stick_jkr",
        "no_bouncing_below",
    ];
    per_element(py, &e, names, |i, c, law| {
        let f = thresholds::fragmentation(c, law, t_vis[i], &opts)?;
        let values = [
            or_nan(f.v_frag),
            or_nan(f.v_stick),
            f.t_vis,
            f.v_frag_jkr,
            f.v_stick_jkr,
            or_nan(f.no_bouncing_below),
        ];
        Ok((values, f.method, Vec::new()))
    })
}

/// T_vis (s) reproducing a measured V_stick, with the range for its uncertainty.
#[pyfunction]
#[pyo3(signature = (material, radius, radius2, wall, v_stick, v_stick_err, k, v_max, rel_tol, method, gamma_sv=None))]
#[allow(clippy::too_many_arguments)]
pub fn fit_t_vis<'py>(
    py: Python<'py>,
    material: Material,
    radius: Array<'py>,
    radius2: Option<Array<'py>>,
    wall: bool,
    v_stick: Array<'py>,
    v_stick_err: Array<'py>,
    k: Array<'py>,
    v_max: Option<f64>,
    rel_tol: f64,
    method: &str,
    gamma_sv: Option<Array<'py>>,
) -> PyResult<Bound<'py, PyDict>> {
    let (v, dv) = (
        crate::args::data(&v_stick, "v_stick")?,
        crate::args::data(&v_stick_err, "v_stick_err")?,
    );
    let e = Elements::new(
        &material,
        gamma_sv.as_ref(),
        &radius,
        radius2.as_ref(),
        wall,
        Some(&k),
        &[("v_stick", v), ("v_stick_err", dv)],
    )?;
    let opts = search_options(v_max, rel_tol, method)?;
    let names = ["t_vis", "t_vis_min", "t_vis_max", "v_stick_jkr"];
    per_element(py, &e, names, |i, c, law| {
        let fit = thresholds::fit_t_vis(c, law, v[i], dv[i], &opts)?;
        let w = fit
            .warnings()
            .iter()
            .map(|f| {
                let kind = match f {
                    FitWarning::AboveDefaultSearchLimit { .. } => "fit_v_max",
                    FitWarning::LowerEndAtJkr { .. } => "fit_jkr",
                };
                (i, kind, f.message_for("v_max="))
            })
            .collect();
        let values = [fit.t_vis, fit.t_vis_min, fit.t_vis_max, fit.v_stick_jkr];
        Ok((values, fit.method, w))
    })
}
