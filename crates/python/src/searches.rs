//! The vectorised threshold functions of `stickiness._core`: V_stick, V_frag and the T_vis fit,
//! each element answered by the master tables or the exact search (`method`), with a
//! `"method"` column saying which answered (0: search, 1: table).

use crate::args::{columns, elementwise, method_code, or_nan, Elements, Warned};
use crate::error::Error;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use thresholds::{
    Contact, CrackLaw, FitWarning, Fragmentation, StickingThresholds, TVisFit, ThresholdMethod,
    ThresholdsError,
};

/// What a threshold function computes for one element.
trait Answer: Send {
    /// Which method answered.
    fn method(&self) -> ThresholdMethod;
    /// V_stick,JKR of the element's contact (m/s).
    fn v_stick_jkr(&self) -> f64;
}

/// [`Answer`] of each result type: its `method` and `v_stick_jkr` fields.
macro_rules! answer {
    ($($t:ty),*) => {$(
        impl Answer for $t {
            fn method(&self) -> ThresholdMethod {
                self.method
            }
            fn v_stick_jkr(&self) -> f64 {
                self.v_stick_jkr
            }
        }
    )*};
}
answer!(StickingThresholds, Fragmentation, TVisFit);

/// A column of a threshold function: its name and its value in an element's answer (NaN for
/// `None`).
type Column<T> = (&'static str, fn(&T) -> Option<f64>);

/// The elements of a threshold function: element `i` answers `f(i, contact, law)` (with its
/// warnings); a dict of the `columns`, `"method"` and `"warnings"`. Each element's answer is
/// reduced to its row of columns and method code where it is computed, so that a million
/// elements from the tables move a few tens of bytes each, not the whole answer.
fn per_element<'py, T: Answer, const N: usize>(
    py: Python<'py>,
    e: &Elements<'_>,
    cols: [Column<T>; N],
    f: impl Fn(usize, &Contact, &CrackLaw) -> Result<(T, Warned), ThresholdsError> + Sync + Send,
) -> PyResult<Bound<'py, PyDict>> {
    let found = e.map_rows(py, |i, c| {
        let (answer, w) = f(i, c, e.law(i)?).map_err(|err| Error::from_thresholds(err, i))?;
        let row = cols.map(|c| or_nan(c.1(&answer)));
        Ok(((row, method_code(answer.method())), w))
    })?;
    columns(py, &cols.map(|c| c.0), found, true, e.scalar)
}

/// `answer` of element `i` with its warning of a `v_max` below its V_stick,JKR (m/s), if any
/// ([`thresholds::SearchOptions::v_max_warning`]).
fn v_max_warned<T: Answer>(i: usize, opts: &thresholds::SearchOptions, answer: T) -> (T, Warned) {
    let w = opts.v_max_warning(answer.v_stick_jkr(), "v_max=");
    (answer, w.map(|m| (i, "v_max", m)).into_iter().collect())
}

/// The columns of [`v_stick`].
const V_STICK: [Column<StickingThresholds>; 5] = [
    ("v_stick", |t| t.v_stick),
    ("v_double_onset", |t| t.v_double_onset),
    ("v_stick_jkr", |t| Some(t.v_stick_jkr)),
    ("no_bouncing_below", StickingThresholds::no_bouncing_below),
    ("v_max", |t| Some(t.v_max)),
];

elementwise! {
    /// V_stick, V_double_onset, V_stick,JKR, no_bouncing_below and v_max (m/s; NaN where none);
    /// `gamma_sv` (J/m^2), if given, replaces the material's per element.
    fn v_stick(py, e: Elements[t_vis; k; gamma_sv], opts: SearchOptions) {
        per_element(py, &e, V_STICK, |i, c, law| {
            Ok(v_max_warned(i, &opts, thresholds::sticking_thresholds(c, law, t_vis[i], &opts)?))
        })
    }
}

/// The columns of [`v_frag`].
const V_FRAG: [Column<Fragmentation>; 6] = [
    ("v_frag", |f| f.v_frag),
    ("v_stick", |f| f.v_stick),
    ("t_vis", |f| Some(f.t_vis)),
    ("v_frag_jkr", |f| Some(f.v_frag_jkr)),
    ("v_stick_jkr", |f| Some(f.v_stick_jkr)),
    ("no_bouncing_below", |f| f.no_bouncing_below),
];

elementwise! {
    /// V_frag = 10 V_stick with V_stick, T_vis, V_frag,JKR, V_stick,JKR, no_bouncing_below.
    fn v_frag(py, e: Elements[t_vis; k; gamma_sv], opts: SearchOptions) {
        per_element(py, &e, V_FRAG, |i, c, law| {
            Ok(v_max_warned(i, &opts, thresholds::fragmentation(c, law, t_vis[i], &opts)?))
        })
    }
}

/// The columns of [`fit_t_vis`].
const FIT: [Column<TVisFit>; 4] = [
    ("t_vis", |f| Some(f.t_vis)),
    ("t_vis_min", |f| Some(f.t_vis_min)),
    ("t_vis_max", |f| Some(f.t_vis_max)),
    ("v_stick_jkr", |f| Some(f.v_stick_jkr)),
];

/// The Python warning kind of a fit's warning: one `StickinessWarning` per kind and call.
fn fit_kind(f: &FitWarning) -> &'static str {
    match f {
        FitWarning::AboveDefaultSearchLimit { .. } => "fit_v_max",
        FitWarning::AtJkrLimit { .. } => "fit_t_vis_zero",
        FitWarning::LowerEndAtJkr { .. } => "fit_jkr",
    }
}

elementwise! {
    /// T_vis (s) reproducing a measured V_stick, with the range for its uncertainty.
    fn fit_t_vis(py, e: Elements[v_stick, v_stick_err; k; gamma_sv], opts: SearchOptions) {
        per_element(py, &e, FIT, |i, c, law| {
            let fit = thresholds::fit_t_vis(c, law, v_stick[i], v_stick_err[i], &opts)?;
            let w = fit
                .warnings()
                .iter()
                .map(|f| (i, fit_kind(f), f.message_for("v_max=")))
                .collect();
            Ok((fit, w))
        })
    }
}
