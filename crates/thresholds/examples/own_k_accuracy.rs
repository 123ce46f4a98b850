//! The master tables at their own k, where no check between tables of k stands behind an
//! answer, against the reference search their nodes are (`master::build::node`: rel_tol 1e-8,
//! collisions at rtol 1e-10): random points of a box in x = log10 c_D and y = log10(c_D c_a),
//! each at a random table's own k, default search limit (1000 V_stick,JKR).
//!
//! ```sh
//! cargo run --release -p thresholds --example own_k_accuracy -- 15000 -2.5 1 -6 -3 5   # the band of the kink
//! cargo run --release -p thresholds --example own_k_accuracy -- 4000 -8 3 -6 5.5 2    # most of the domain
//! ```
//! (points, x from, x to, y from, y to, seed) prints each answer more than 5e-6 off, then how
//! many the tables answered with values and how many of them lie more than 5e-6 and 1e-5 off.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use rayon::prelude::*;
use thresholds::master::build::{node, BuildConfig};
use thresholds::{CrackLaw, MasterTables};

#[path = "common/domain.rs"]
#[allow(dead_code)]
mod domain;

use domain::Rng;

fn main() {
    let a: Vec<f64> = std::env::args()
        .skip(1)
        .map(|s| s.parse().expect("six numbers"))
        .collect();
    let [n, x0, x1, y0, y1, seed] = a[..] else {
        panic!("usage: own_k_accuracy POINTS X_FROM X_TO Y_FROM Y_TO SEED");
    };
    let tables = MasterTables::standard();
    let cfg = BuildConfig::standard();
    let ks = tables.table_k().to_vec();
    let mut rng = Rng(seed as u64);
    let points: Vec<(f64, f64, f64)> = (0..n as usize)
        .map(|_| {
            let x = x0 + (x1 - x0) * rng.next();
            let y = y0 + (y1 - y0) * rng.next();
            let i = ((rng.next() * ks.len() as f64) as usize).min(ks.len() - 1);
            (x, y, ks[i])
        })
        .collect();
    // (x, y, k, the larger relative difference of F and F_on) where the tables give values
    let off: Vec<(f64, f64, f64, f64)> = points
        .par_iter()
        .filter_map(|&(x, y, k)| {
            let ours = tables.ratios_at(x, y, k, 1000.0)?;
            let f = ours.v_stick?;
            let exact = node(&cfg, &CrackLaw::new(k).unwrap(), x, y);
            let d_f = (f / exact.stick()? - 1.0).abs();
            let d_on = match (ours.v_double_onset, exact.onset()) {
                (Some(a), Some(b)) => (a / b - 1.0).abs(),
                _ => f64::INFINITY,
            };
            Some((x, y, k, d_f.max(d_on)))
        })
        .collect();
    let mut bad: Vec<_> = off.iter().filter(|o| o.3 > 5e-6).collect();
    bad.sort_by(|a, b| b.3.total_cmp(&a.3));
    for (x, y, k, d) in &bad {
        println!("x = {x:.3}, y = {y:.3}, k = {k:.5}: {d:.1e} off");
    }
    println!(
        "{} of {} points answered with values; {} more than 5e-6 off, {} more than 1e-5",
        off.len(),
        points.len(),
        bad.len(),
        bad.iter().filter(|o| o.3 > 1e-5).count()
    );
}
