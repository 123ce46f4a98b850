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
use thresholds::MasterTables;

#[path = "common/domain.rs"]
#[allow(dead_code)]
mod domain;
#[path = "common/own_k.rs"]
mod own_k;

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
    let ks = tables.table_k().to_vec();
    let points = own_k::draw(&mut Rng(seed as u64), n as usize, (x0, x1), (y0, y1), &ks);
    // (point, how far off) where the tables give values
    let off: Vec<([f64; 3], f64)> = points
        .par_iter()
        .filter_map(|&p| Some((p, own_k::off(tables, p)?)))
        .collect();
    let mut bad: Vec<_> = off.iter().filter(|o| o.1 > 5e-6).collect();
    bad.sort_by(|a, b| b.1.total_cmp(&a.1));
    for ([x, y, k], d) in &bad {
        println!("x = {x:.3}, y = {y:.3}, k = {k:.5}: {d:.1e} off");
    }
    println!(
        "{} of {} points answered with values; {} more than 5e-6 off, {} more than 1e-5",
        off.len(),
        points.len(),
        bad.len(),
        bad.iter().filter(|o| o.1 > 1e-5).count()
    );
}
