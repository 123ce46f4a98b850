//! The vectorised functions of `stickiness._core` that are no threshold search: the crack law,
//! the JKR contact, single collisions and the size laws (the conversions: [`crate::args`]).

use crate::args::{
    columns, common_len, data, method, method_code, or_nan, warned, Array, Elements, Laws, Warned,
};
use crate::error::Error;
use crate::material::Material;
use crate::parallel;
use numpy::PyArray1;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use thresholds::{
    GreenwoodError, SolverOptions, StickingCriterion, TVisLaw, ThresholdMethod, Warning,
};

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
    let e = Elements::new(&material, None, &radius, radius2.as_ref(), wall, None, &[])?;
    let rows = parallel::map(py, e.n, |i| {
        let c = e.contact(i)?;
        Ok((c.jkr_values(), warned(i, c.warnings())))
    })?;
    columns(py, thresholds::JKR_QUANTITIES.map(|q| q.0), &rows)
}

/// The two dimensionless numbers of a collision (`Contact::dimensionless`): the drag number
/// c_d and the crack-speed number c_a, and the JKR time unit t0 (s).
#[pyfunction]
#[pyo3(signature = (material, radius, radius2, wall, t_vis, gamma_sv=None))]
pub fn dimensionless<'py>(
    py: Python<'py>,
    material: Material,
    radius: Array<'py>,
    radius2: Option<Array<'py>>,
    wall: bool,
    t_vis: Array<'py>,
    gamma_sv: Option<Array<'py>>,
) -> PyResult<Bound<'py, PyDict>> {
    let t_vis = data(&t_vis, "t_vis")?;
    let e = Elements::new(
        &material,
        gamma_sv.as_ref(),
        &radius,
        radius2.as_ref(),
        wall,
        None,
        &[("t_vis", t_vis)],
    )?;
    let rows = parallel::map(py, e.n, |i| {
        let c = e.contact(i)?;
        numerics::positive("t_vis", t_vis[i], "s").map_err(|bad| Error::Input { bad, index: i })?;
        let d = c.dimensionless(t_vis[i]);
        Ok(([d.c_d, d.c_a, c.t0()], warned(i, c.warnings())))
    })?;
    columns(py, ["c_d", "c_a", "t0"], &rows)
}

/// One head-on collision per element: outcome, e, v_out (m/s), contact_time (s; NaN for
/// sticking, and where the restitution tables answered), v_stick_jkr (m/s), method (0: the ODE,
/// 1: the tables); with `trajectory` (one element only, always the ODE) the recorded states.
#[pyfunction]
#[pyo3(signature = (material, radius, radius2, wall, t_vis, v_in, k, t_end, trajectory, method="search", gamma_sv=None))]
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
    method: &str,
    gamma_sv: Option<Array<'py>>,
) -> PyResult<Bound<'py, PyDict>> {
    let (t_vis, v_in) = (data(&t_vis, "t_vis")?, data(&v_in, "v_in")?);
    let e = Elements::new(
        &material,
        gamma_sv.as_ref(),
        &radius,
        radius2.as_ref(),
        wall,
        Some(&k),
        &[("t_vis", t_vis), ("v_in", v_in)],
    )?;
    if trajectory && e.n != 1 {
        return Err(PyValueError::new_err(
            "trajectory: only for one collision (scalar arguments)",
        ));
    }
    let method = self::method(method)?;
    let opts = SolverOptions {
        record_trajectory: trajectory,
        decide_after: t_end.unwrap_or(0.0),
        ..SolverOptions::default()
    };
    let runs = parallel::map(py, e.n, |i| {
        let c = e.contact(i)?;
        let mut w = warned(i, c.warnings());
        w.extend(warned(i, Warning::for_speed("v_in", v_in[i])));
        let (run, answered) =
            thresholds::restitution::collision(&c, e.law(i)?, t_vis[i], v_in[i], &opts, method)
                .map_err(|err| Error::from_thresholds(err, i))?;
        Ok((run, c.v_stick_jkr(), w, answered))
    })?;
    let dict = PyDict::new(py);
    let outcomes: Vec<&str> = runs.iter().map(|r| r.0.outcome.as_str()).collect();
    dict.set_item("outcome", outcomes)?;
    type Run = (thresholds::Collision, f64, Warned, ThresholdMethod);
    let column = |f: &dyn Fn(&Run) -> f64| -> Vec<f64> { runs.iter().map(f).collect() };
    dict.set_item("e", PyArray1::from_vec(py, column(&|r| r.0.e)))?;
    // what an experiment sees: e = 0 for sticking and double collisions (Section 4.4)
    dict.set_item(
        "e_observed",
        PyArray1::from_vec(py, column(&|r| r.0.observed_e())),
    )?;
    dict.set_item("v_out", PyArray1::from_vec(py, column(&|r| r.0.v_out)))?;
    dict.set_item(
        "contact_time",
        PyArray1::from_vec(py, column(&|r| or_nan(r.0.contact_time))),
    )?;
    dict.set_item("v_stick_jkr", PyArray1::from_vec(py, column(&|r| r.1)))?;
    let methods: Vec<u8> = runs.iter().map(|r| method_code(r.3)).collect();
    dict.set_item("method", PyArray1::from_vec(py, methods))?;
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
