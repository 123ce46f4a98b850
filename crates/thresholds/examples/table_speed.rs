//! What one array element costs inside Rust when the master tables answer it: 1e6 CO2 grains
//! of R1 = 0.1 um - 1 mm and T_vis = 1e-14 - 1e-6 s (both log-uniform, the domain of
//! `examples/python/table_speed.py`), each its contact (as a Python array element makes it) and
//! the tables' ratios at k = 0.01 up to the default search limit, on one thread.
//!
//! ```sh
//! cargo run --release -p thresholds --example table_speed
//! ```
//! prints the time a point over five passes, how many the tables answered and the sum of their
//! V_stick / V_stick,JKR (the same digits before and after a change that keeps the numbers).

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::time::Instant;
use thresholds::master::MasterTables;
use thresholds::{Contact, Geometry, Material, SearchOptions};

#[path = "common/domain.rs"]
#[allow(dead_code)] // the examples of the tables' accuracy read the rest
mod domain;

/// Points drawn.
const POINTS: usize = 1_000_000;

fn main() {
    // the same points on every run (the examples' deterministic generator)
    let mut rng = domain::Rng(12345);
    let points: Vec<(f64, f64)> = (0..POINTS)
        .map(|_| (rng.log_uniform(1e-7, 1e-3), rng.log_uniform(1e-14, 1e-6)))
        .collect();
    let tables = MasterTables::standard();
    let opts = SearchOptions::default();
    for _ in 0..5 {
        let start = Instant::now();
        let (mut answered, mut sum) = (0, 0.0);
        for &(r1, t_vis) in &points {
            let c = Contact::new(Material::co2(), Geometry::identical(r1)).unwrap();
            let v_jkr = c.v_stick_jkr();
            let (x, y) = (c.drag_number(t_vis).log10(), c.drag_crack_product().log10());
            if let Some(r) = tables.ratios_at(x, y, 0.01, opts.v_max_for(v_jkr) / v_jkr) {
                answered += 1;
                sum += r.v_stick.unwrap_or(0.0);
            }
        }
        let ns = start.elapsed().as_secs_f64() * 1e9 / POINTS as f64;
        println!(
            "{ns:.1} ns a point, one thread ({answered} of {POINTS} answered; sum of F {sum:.12e})"
        );
    }
}
