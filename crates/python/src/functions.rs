//! The vectorised functions of `stickiness._core` that are no threshold search: the crack law,
//! the JKR contact, single collisions and the size laws (the conversions: [`crate::args`]).

use crate::args::{
    columns, common_len, data, elementwise, method_code, or_nan, warned, Array, Laws, Warned,
};
use crate::error::Error;
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

elementwise! {
    /// JKR contact: a_eq, delta_eq (m), tabor, f_crit (N), delta_crit (m), e_stick, e_break (J),
    /// v_stick_jkr (m/s).
    fn jkr(py, e: Elements[;;]) {
        let found = e.map_rows(py, |_, c| Ok(((c.jkr_values(), 0), Vec::new())))?;
        let names = thresholds::JKR_QUANTITIES.map(|q| q.0);
        columns(py, &names, found, false, e.scalar)
    }
}

elementwise! {
    /// The two dimensionless numbers of a collision (`Contact::dimensionless`): the drag number
    /// c_d and the crack-speed number c_a, and the JKR time unit t0 (s).
    fn dimensionless(py, e: Elements[t_vis;; gamma_sv]) {
        let found = e.map_rows(py, |i, c| {
            numerics::positive("t_vis", t_vis[i], "s").map_err(|bad| Error::Input { bad, index: i })?;
            let d = c.dimensionless(t_vis[i]);
            Ok((([d.c_d, d.c_a, c.t0()], 0), Vec::new()))
        })?;
        columns(py, &["c_d", "c_a", "t0"], found, false, e.scalar)
    }
}

/// What one collision gives: the run, V_stick,JKR and which method answered.
type Run = (thresholds::Collision, f64, ThresholdMethod);

elementwise! {
    /// One head-on collision per element: outcome, e, v_out (m/s), contact_time (s; NaN for
    /// sticking, and where the restitution tables answered), v_stick_jkr (m/s), method (0: the ODE,
    /// 1: the tables); with `trajectory` (one element only, always the ODE) the recorded states.
    fn collide(
        py,
        e: Elements[t_vis, v_in; k; gamma_sv],
        t_end: Option<f64>,
        trajectory: bool,
        method: &str = "search",
    ) {
        if trajectory && e.n != 1 {
            return Err(PyValueError::new_err(
                "trajectory: only for one collision (scalar arguments)",
            ));
        }
        let method = crate::args::method(method)?;
        let opts = SolverOptions {
            record_trajectory: trajectory,
            decide_after: t_end.unwrap_or(0.0),
            ..SolverOptions::default()
        };
        let runs = e.map(py, |i, c| {
            let (run, answered) =
                thresholds::restitution::collision(c, e.law(i)?, t_vis[i], v_in[i], &opts, method)
                    .map_err(|err| Error::from_thresholds(err, i))?;
            let w = warned(i, Warning::for_speed("v_in", v_in[i]));
            Ok(((run, c.v_stick_jkr(), answered), w))
        })?;
        collision_columns(py, &runs, trajectory)
    }
}

/// The dict of [`collide`]'s columns.
fn collision_columns<'py>(
    py: Python<'py>,
    runs: &[(Run, Warned)],
    trajectory: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    let outcomes: Vec<&str> = runs.iter().map(|r| r.0 .0.outcome.as_str()).collect();
    dict.set_item("outcome", outcomes)?;
    let column = |f: &dyn Fn(&Run) -> f64| -> Vec<f64> { runs.iter().map(|r| f(&r.0)).collect() };
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
    let methods: Vec<u8> = runs.iter().map(|r| method_code(r.0 .2)).collect();
    dict.set_item("method", PyArray1::from_vec(py, methods))?;
    let sticking: Vec<Option<&str>> = runs
        .iter()
        .map(|r| {
            r.0 .0.sticking_criterion.map(|c| match c {
                StickingCriterion::EnergyBound => "energy_bound",
                StickingCriterion::Oscillations => "oscillations",
            })
        })
        .collect();
    dict.set_item("sticking_criterion", sticking)?;
    let warnings: Warned = runs.iter().flat_map(|r| r.1.iter().cloned()).collect();
    dict.set_item("warnings", warnings)?;
    if trajectory {
        if let Some(run) = runs.first() {
            let traj = PyDict::new(py);
            let pts = &run.0 .0.trajectory;
            type Pick = fn(&thresholds::TrajectoryPoint) -> f64;
            // the columns of the CLI's trajectory CSV, in its order
            let fields: [(&str, Pick); 6] = [
                ("t", |p| p.t),
                ("a", |p| p.a),
                ("delta", |p| p.delta),
                ("delta_dot", |p| p.delta_dot),
                ("energy", |p| p.energy),
                ("beta", |p| p.beta),
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

/// The caution of `TVisLaw::mismatch`: `law` (`co2` or `h2o`) with the constants of the other
/// ice; `None` for the law's own ice, any other material or an unknown law (refused elsewhere).
#[pyfunction]
pub fn t_vis_law_mismatch(law: &str, material: &crate::material::Material) -> Option<String> {
    TVisLaw::from_name(law)?.mismatch(&material.inner())
}
