//! Points at the master tables' own k, where no check between tables of k stands behind an
//! answer, and how far the tables' values lie from the reference search their nodes are
//! (`examples/own_k_accuracy.rs`, `tests/master_own_k.rs`).

use super::domain::Rng;
use thresholds::master::build::{node, BuildConfig};
use thresholds::{CrackLaw, MasterTables};

/// `n` points `(x, y, k)`, x and y uniform over `xs` and `ys`, k one of `ks` at random.
pub fn draw(rng: &mut Rng, n: usize, xs: (f64, f64), ys: (f64, f64), ks: &[f64]) -> Vec<[f64; 3]> {
    (0..n)
        .map(|_| {
            let x = xs.0 + (xs.1 - xs.0) * rng.next();
            let y = ys.0 + (ys.1 - ys.0) * rng.next();
            [x, y, rng.pick(ks)]
        })
        .collect()
}

/// Where the tables give F at `[x, y, k]` (default search limit, 1000 V_stick,JKR): the larger
/// relative difference of F and F_on from the reference search (`master::build::node`), F_on
/// infinitely off where only one of the two has it.
pub fn off(tables: &MasterTables, [x, y, k]: [f64; 3]) -> Option<f64> {
    let ours = tables.ratios_at(x, y, k, 1000.0)?;
    let exact = node(&BuildConfig::standard(), &CrackLaw::new(k).ok()?, x, y);
    let d_f = (ours.v_stick? / exact.stick()? - 1.0).abs();
    let d_on = match (ours.v_double_onset, exact.onset()) {
        (Some(a), Some(b)) => (a / b - 1.0).abs(),
        _ => f64::INFINITY,
    };
    Some(d_f.max(d_on))
}
