//! The vectorised functions of `stickiness._core`.
//!
//! Each takes flat `float64` arrays of one length `n` (the broadcast arguments; the package
//! broadcasts them), computes the `n` elements with [`crate::parallel::map`], and returns a dict
//! of flat arrays (NaN where a value does not exist) with a `"warnings"` list of
//! `(index, kind, message)`. The search and solver settings are those of the CLI, so the numbers
//! are bit-identical to its `--json` output.

use crate::error::Error;
use crate::material::Material;
use crate::parallel;
use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::collections::HashMap;
use thresholds::{
    Collider, Contact, CrackLaw, FitWarning, Geometry, GreenwoodError, OutOfRange, SearchOptions,
    SolverOptions, StickingCriterion, TVisLaw, Warning,
};

type Array<'py> = PyReadonlyArray1<'py, f64>;

/// The contiguous data of a flat array argument.
fn data<'a>(a: &'a Array<'_>, name: &str) -> PyResult<&'a [f64]> {
    a.as_slice()
        .map_err(|_| PyValueError::new_err(format!("{name}: expected a contiguous float64 array")))
}

/// The common length of the flat arguments (the package broadcasts them first).
fn common_len(lens: &[(&str, usize)]) -> PyResult<usize> {
    let n = lens.first().map_or(0, |l| l.1);
    match lens.iter().find(|l| l.1 != n) {
        Some((name, len)) => Err(PyValueError::new_err(format!(
            "{name}: length {len} differs from {n} (the arguments must be broadcast to one shape)"
        ))),
        None => Ok(n),
    }
}

/// The geometry arguments: `radius`, optional `radius2`, `wall`.
struct Bodies<'a> {
    radius: &'a [f64],
    radius2: Option<&'a [f64]>,
    wall: bool,
}

impl<'a> Bodies<'a> {
    /// The geometry arguments, `radius2` (if given) as long as `radius`.
    fn new(radius: &'a Array<'_>, radius2: Option<&'a Array<'_>>, wall: bool) -> PyResult<Self> {
        let radius = data(radius, "radius")?;
        let radius2 = radius2.map(|r| data(r, "radius2")).transpose()?;
        if let Some(r2) = radius2 {
            common_len(&[("radius", radius.len()), ("radius2", r2.len())])?;
        }
        Ok(Self {
            radius,
            radius2,
            wall,
        })
    }

    fn geometry(&self, i: usize) -> Geometry {
        let r1 = self.radius[i];
        match (self.wall, self.radius2) {
            (true, _) => Geometry::wall(r1),
            (false, Some(r2)) => Geometry::spheres(r1, r2[i]),
            (false, None) => Geometry::identical(r1),
        }
    }

    fn contact(&self, material: &Material, i: usize) -> Result<Contact, Error> {
        Contact::new(material.inner, self.geometry(i)).map_err(|e| Error::from_contact(e, i))
    }
}

/// One `CrackLaw` per distinct k (each table takes 0.17 ms to build and is shared).
struct Laws(HashMap<u64, Result<CrackLaw, OutOfRange>>);

impl Laws {
    fn new(k: &[f64]) -> Self {
        let mut map = HashMap::new();
        for &x in k {
            map.entry(x.to_bits()).or_insert_with(|| {
                CrackLaw::new(x).map_err(|e| match e {
                    GreenwoodError::OutOfRange(bad) => bad,
                })
            });
        }
        Self(map)
    }

    fn get(&self, k: f64, i: usize) -> Result<&CrackLaw, Error> {
        match self.0.get(&k.to_bits()) {
            Some(Ok(law)) => Ok(law),
            Some(Err(bad)) => Err(Error::Input {
                bad: bad.clone(),
                index: i,
            }),
            // every k of the call was tabulated in `new`
            None => Err(Error::Input {
                bad: OutOfRange::new("k", k, "0 < k < 1", "dimensionless"),
                index: i,
            }),
        }
    }
}

/// `(index, kind, message)` of each warning of element `i`.
type Warned = Vec<(usize, &'static str, String)>;

fn warned(i: usize, warnings: impl IntoIterator<Item = Warning>) -> Warned {
    warnings
        .into_iter()
        .map(|w| {
            let kind = match w {
                Warning::JkrOutsideValidity { .. } => "tabor",
                Warning::ImplausibleRadius { .. } => "radius",
                Warning::ImplausibleSpeed { .. } => "speed",
            };
            (i, kind, w.to_string())
        })
        .collect()
}

/// Columns of f64 results and the warnings, as a dict of flat arrays.
fn columns<'py, const N: usize>(
    py: Python<'py>,
    names: [&str; N],
    rows: &[([f64; N], Warned)],
) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    for (j, name) in names.iter().enumerate() {
        let col: Vec<f64> = rows.iter().map(|r| r.0[j]).collect();
        dict.set_item(*name, PyArray1::from_vec(py, col))?;
    }
    let warnings: Warned = rows.iter().flat_map(|r| r.1.iter().cloned()).collect();
    dict.set_item("warnings", warnings)?;
    Ok(dict)
}

fn or_nan(v: Option<f64>) -> f64 {
    v.unwrap_or(f64::NAN)
}

fn search_options(v_max: Option<f64>, rel_tol: f64) -> SearchOptions {
    // as the CLI's: only rel_tol and v_max differ from the defaults
    SearchOptions {
        rel_tol,
        v_max,
        ..SearchOptions::default()
    }
}

/// Greenwood's crack speed v(k, beta), elementwise (dimensionless).
#[pyfunction]
pub fn crack_speed<'py>(
    py: Python<'py>,
    k: Array<'py>,
    beta: Array<'py>,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let (k, beta) = (data(&k, "k")?, data(&beta, "beta")?);
    let n = common_len(&[("k", k.len()), ("beta", beta.len())])?;
    let laws = Laws::new(k);
    let v = parallel::map(py, n, |i| {
        laws.get(k[i], i)?.v(beta[i]).map_err(|e| match e {
            GreenwoodError::OutOfRange(bad) => Error::Input { bad, index: i },
        })
    })?;
    Ok(PyArray1::from_vec(py, v))
}

/// JKR contact: a_eq, delta_eq (m), tabor, f_crit (N), delta_crit (m), e_stick, e_break (J),
/// v_stick_jkr (m/s).
#[pyfunction]
#[pyo3(signature = (material, radius, radius2, wall))]
pub fn jkr<'py>(
    py: Python<'py>,
    material: Material,
    radius: Array<'py>,
    radius2: Option<Array<'py>>,
    wall: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let bodies = Bodies::new(&radius, radius2.as_ref(), wall)?;
    let n = bodies.radius.len();
    let rows = parallel::map(py, n, |i| {
        let c = bodies.contact(&material, i)?;
        Ok((c.jkr_values(), warned(i, c.warnings())))
    })?;
    columns(py, thresholds::JKR_QUANTITIES.map(|q| q.0), &rows)
}

/// One head-on collision per element: outcome, e, v_out (m/s), contact_time (s; NaN for
/// sticking), v_stick_jkr (m/s); with `trajectory` (one element only) the recorded states.
#[pyfunction]
#[pyo3(signature = (material, radius, radius2, wall, t_vis, v_in, k, t_end, trajectory))]
#[allow(clippy::too_many_arguments)]
pub fn collide<'py>(
    py: Python<'py>,
    material: Material,
    radius: Array<'py>,
    radius2: Option<Array<'py>>,
    wall: bool,
    t_vis: Array<'py>,
    v_in: Array<'py>,
    k: Array<'py>,
    t_end: Option<f64>,
    trajectory: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let bodies = Bodies::new(&radius, radius2.as_ref(), wall)?;
    let (t_vis, v_in, k) = (data(&t_vis, "t_vis")?, data(&v_in, "v_in")?, data(&k, "k")?);
    let n = common_len(&[
        ("radius", bodies.radius.len()),
        ("t_vis", t_vis.len()),
        ("v_in", v_in.len()),
        ("k", k.len()),
    ])?;
    if trajectory && n != 1 {
        return Err(PyValueError::new_err(
            "trajectory: only for one collision (scalar arguments)",
        ));
    }
    let laws = Laws::new(k);
    let opts = SolverOptions {
        record_trajectory: trajectory,
        decide_after: t_end.unwrap_or(0.0),
        ..SolverOptions::default()
    };
    let runs = parallel::map(py, n, |i| {
        let c = bodies.contact(&material, i)?;
        let law = laws.get(k[i], i)?;
        let fail = |e: thresholds::DynamicsError| Error::from_thresholds(e.into(), i);
        let collider = Collider::new(c, law, t_vis[i])
            .and_then(|col| col.with_options(opts))
            .map_err(fail)?;
        let run = collider.collide(v_in[i]).map_err(fail)?;
        let mut w = warned(i, c.warnings());
        w.extend(warned(i, Warning::for_speed("v_in", v_in[i])));
        Ok((run, c.v_stick_jkr(), w))
    })?;
    let dict = PyDict::new(py);
    let outcomes: Vec<&str> = runs.iter().map(|r| r.0.outcome.as_str()).collect();
    dict.set_item("outcome", outcomes)?;
    let column = |f: &dyn Fn(&(thresholds::Collision, f64, Warned)) -> f64| -> Vec<f64> {
        runs.iter().map(f).collect()
    };
    dict.set_item("e", PyArray1::from_vec(py, column(&|r| r.0.e)))?;
    dict.set_item("v_out", PyArray1::from_vec(py, column(&|r| r.0.v_out)))?;
    dict.set_item(
        "contact_time",
        PyArray1::from_vec(py, column(&|r| or_nan(r.0.contact_time))),
    )?;
    dict.set_item("v_stick_jkr", PyArray1::from_vec(py, column(&|r| r.1)))?;
    let sticking: Vec<Option<&str>> = runs
        .iter()
        .map(|r| {
            r.0.sticking_criterion.map(|c| match c {
                StickingCriterion::EnergyBound => "energy_bound",
                StickingCriterion::Oscillations => "oscillations",
            })
        })
        .collect();
    dict.set_item("sticking_criterion", sticking)?;
    let warnings: Warned = runs.iter().flat_map(|r| r.2.iter().cloned()).collect();
    dict.set_item("warnings", warnings)?;
    if trajectory {
        if let Some(run) = runs.first() {
            let traj = PyDict::new(py);
            let pts = &run.0.trajectory;
            type Pick = fn(&thresholds::TrajectoryPoint) -> f64;
            let fields: [(&str, Pick); 6] = [
                ("t", |p| p.t),
                ("a", |p| p.a),
                ("delta", |p| p.delta),
                ("delta_dot", |p| p.delta_dot),
                ("beta", |p| p.beta),
                ("energy", |p| p.energy),
            ];
            for (name, pick) in fields {
                let col: Vec<f64> = pts.iter().map(pick).collect();
                traj.set_item(name, PyArray1::from_vec(py, col))?;
            }
            dict.set_item("trajectory", traj)?;
        }
    }
    Ok(dict)
}

/// V_stick, V_double_onset, V_stick,JKR and no_bouncing_below (m/s; NaN where none).
#[pyfunction]
#[pyo3(signature = (material, radius, radius2, wall, t_vis, k, v_max, rel_tol))]
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
) -> PyResult<Bound<'py, PyDict>> {
    let bodies = Bodies::new(&radius, radius2.as_ref(), wall)?;
    let (t_vis, k) = (data(&t_vis, "t_vis")?, data(&k, "k")?);
    let n = common_len(&[
        ("radius", bodies.radius.len()),
        ("t_vis", t_vis.len()),
        ("k", k.len()),
    ])?;
    let laws = Laws::new(k);
    let opts = search_options(v_max, rel_tol);
    let rows = parallel::map(py, n, |i| {
        let c = bodies.contact(&material, i)?;
        let law = laws.get(k[i], i)?;
        let th = thresholds::sticking_thresholds(&c, law, t_vis[i], &opts)
            .map_err(|e| Error::from_thresholds(e, i))?;
        Ok((
            [
                or_nan(th.v_stick),
                or_nan(th.v_double_onset),
                th.v_stick_jkr,
                or_nan(th.no_bouncing_below()),
                th.v_max,
            ],
            warned(i, c.warnings()),
        ))
    })?;
    columns(
        py,
        [
            "v_stick",
            "v_double_onset",
            "v_stick_jkr",
            "no_bouncing_below",
            "v_max",
        ],
        &rows,
    )
}

/// T_vis (s) reproducing a measured V_stick, with the range for its uncertainty.
#[pyfunction]
#[pyo3(signature = (material, radius, radius2, wall, v_stick, v_stick_err, k, v_max, rel_tol))]
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
) -> PyResult<Bound<'py, PyDict>> {
    let bodies = Bodies::new(&radius, radius2.as_ref(), wall)?;
    let (v, dv, k) = (
        data(&v_stick, "v_stick")?,
        data(&v_stick_err, "v_stick_err")?,
        data(&k, "k")?,
    );
    let n = common_len(&[
        ("radius", bodies.radius.len()),
        ("v_stick", v.len()),
        ("v_stick_err", dv.len()),
        ("k", k.len()),
    ])?;
    let laws = Laws::new(k);
    let opts = search_options(v_max, rel_tol);
    let rows = parallel::map(py, n, |i| {
        let c = bodies.contact(&material, i)?;
        let law = laws.get(k[i], i)?;
        let fit = thresholds::fit_t_vis(&c, law, v[i], dv[i], &opts)
            .map_err(|e| Error::from_thresholds(e, i))?;
        let mut w = warned(i, c.warnings());
        w.extend(fit.warnings().iter().map(|f| {
            let kind = match f {
                FitWarning::AboveDefaultSearchLimit { .. } => "fit_v_max",
                FitWarning::LowerEndAtJkr { .. } => "fit_jkr",
            };
            (i, kind, f.message_for("v_max="))
        }));
        Ok((
            [fit.t_vis, fit.t_vis_min, fit.t_vis_max, fit.v_stick_jkr],
            w,
        ))
    })?;
    columns(
        py,
        ["t_vis", "t_vis_min", "t_vis_max", "v_stick_jkr"],
        &rows,
    )
}

/// V_frag = 10 V_stick with V_stick, T_vis, V_frag,JKR, V_stick,JKR, no_bouncing_below.
#[pyfunction]
#[pyo3(signature = (material, radius, radius2, wall, t_vis, k, v_max, rel_tol))]
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
) -> PyResult<Bound<'py, PyDict>> {
    let bodies = Bodies::new(&radius, radius2.as_ref(), wall)?;
    let (t_vis, k) = (data(&t_vis, "t_vis")?, data(&k, "k")?);
    let n = common_len(&[
        ("radius", bodies.radius.len()),
        ("t_vis", t_vis.len()),
        ("k", k.len()),
    ])?;
    let laws = Laws::new(k);
    let opts = search_options(v_max, rel_tol);
    let rows = parallel::map(py, n, |i| {
        let c = bodies.contact(&material, i)?;
        let law = laws.get(k[i], i)?;
        let f = thresholds::fragmentation(&c, law, t_vis[i], &opts)
            .map_err(|e| Error::from_thresholds(e, i))?;
        Ok((
            [
                or_nan(f.v_frag),
                or_nan(f.v_stick),
                f.t_vis,
                f.v_frag_jkr,
                f.v_stick_jkr,
                or_nan(f.no_bouncing_below),
            ],
            warned(i, c.warnings()),
        ))
    })?;
    columns(
        py,
        [
            "v_frag",
            "v_stick",
            "t_vis",
            "v_frag_jkr",
            "v_stick_jkr",
            "no_bouncing_below",
        ],
        &rows,
    )
}

/// T_vis (s) from the size law `law` (`co2` or `h2o`, any case) at each radius (m) (Section 5.3).
#[pyfunction]
pub fn t_vis_law<'py>(
    py: Python<'py>,
    law: &str,
    radius: Array<'py>,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let Some(l) = TVisLaw::from_name(law) else {
        return Err(PyValueError::new_err(format!(
            "t_vis_law = '{law}': must be one of {}",
            thresholds::T_VIS_LAWS
        )));
    };
    let r = data(&radius, "radius")?;
    let t = parallel::map(py, r.len(), |i| {
        numerics::positive("radius", r[i], "m").map_err(|bad| Error::Input { bad, index: i })?;
        Ok(l.t_vis(r[i]))
    })?;
    Ok(PyArray1::from_vec(py, t))
}
