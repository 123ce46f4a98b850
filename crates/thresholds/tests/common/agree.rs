//! The tables' answer against the exact search at one point: the check the tests of the
//! master tables share.

use greenwood::CrackLaw;
use thresholds::{sticking_thresholds, SearchOptions, StickingThresholds, ThresholdMethod};

/// The table's answer and the search's agree: both thresholds within 1e-5, and the same
/// verdict where there is no bouncing (or no double collision) below the search limit.
pub fn assert_agree(t: &StickingThresholds, s: &StickingThresholds, what: &str) {
    let close = |a: Option<f64>, b: Option<f64>| match (a, b) {
        (Some(a), Some(b)) => (a / b - 1.0).abs() < 1e-5,
        (a, b) => a == b,
    };
    assert!(close(t.v_stick, s.v_stick), "{what}: {t:?} vs {s:?}");
    assert!(
        close(t.v_double_onset, s.v_double_onset),
        "{what}: {t:?} vs {s:?}"
    );
}

/// The tables' answer at the synthetic point `(x, y)` of `k`, if they give one, once it is
/// checked against the exact search there ([`assert_agree`]).
pub fn checked_table_answer(x: f64, y: f64, k: f64) -> Option<StickingThresholds> {
    let (c, t_vis) = thresholds::master::build::synthetic(x, y, 1.0).unwrap();
    let law = CrackLaw::new(k).unwrap();
    let t = sticking_thresholds(&c, &law, t_vis, &SearchOptions::default()).unwrap();
    if t.method != ThresholdMethod::Table {
        return None;
    }
    let s = sticking_thresholds(&c, &law, t_vis, &SearchOptions::exact()).unwrap();
    assert_agree(&t, &s, &format!("x = {x}, y = {y}, k = {k}"));
    Some(t)
}
