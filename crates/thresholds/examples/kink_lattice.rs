//! Would a lattice of its own answer where the master tables decline? At each point of the
//! whole domain the tables decline (the draw of `table_accuracy`, mostly next to the kink where
//! the two kinds of bouncing meet), the tricubic in (x, y, ln k) through the 4 x 4 x 4
//! reference nodes of a lattice around it, against the reference search at the point
//! (`docs/performance.md`, "What is left", (5)).
//!
//! ```sh
//! cargo run --release -p thresholds --example kink_lattice -- 0.02 32 24   # dx, 1/dy, k steps an octave
//! ```
//! Prints each point (x, y, k), the reference F and the lattice's miss (`-` where a node has
//! no F), then how many are within 2e-6 and 1e-5. About 65 reference searches a point (55 ms
//! of one core each there): a minute and a half on two cores.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use rayon::prelude::*;
use thresholds::master::build::{node, BuildConfig};
use thresholds::master::interp::lagrange_weight;
use thresholds::{CrackLaw, MasterTables, SearchOptions};

#[allow(dead_code)]
#[path = "common/domain.rs"]
mod domain;

#[path = "common/misses.rs"]
mod misses;

use domain::{draw, Rng};
use misses::tally;

/// The points drawn, as `table_accuracy` draws them (its seed), of which the declined are probed.
const POINTS: usize = 20000;

/// The Lagrange weights of the four nodes `xs` at `x`, as the tables weigh their nodes.
fn weights4(xs: [f64; 4], x: f64) -> [f64; 4] {
    std::array::from_fn(|j| lagrange_weight(&xs, j, x))
}

/// The four lattice nodes of spacing `h` around `x` (x in the middle interval).
fn around(x: f64, h: f64) -> [f64; 4] {
    std::array::from_fn(|i| ((x / h).floor() + i as f64 - 1.0) * h)
}

fn main() {
    let args: Vec<f64> = std::env::args()
        .skip(1)
        .map(|s| s.parse().unwrap())
        .collect();
    let (hx, hy, hk) = match args[..] {
        [dx, per_y, per_octave] => (dx, 1.0 / per_y, std::f64::consts::LN_2 / per_octave),
        _ => (0.02, 1.0 / 32.0, std::f64::consts::LN_2 / 24.0),
    };
    let tables = MasterTables::standard();
    let mut rng = Rng(2026);
    let declined: Vec<[f64; 3]> = (0..POINTS)
        .map(|_| draw(&mut rng, false))
        .filter_map(|p| {
            let d = p.contact.dimensionless(p.t_vis);
            let jkr = p.contact.v_stick_jkr();
            let f_max = SearchOptions::default().v_max_for(jkr) / jkr;
            let (x, y) = (d.c_d.log10(), (d.c_d * d.c_a).log10());
            tables
                .ratios(d.c_d, d.c_a, p.k, f_max)
                .is_none()
                .then_some([x, y, p.k])
        })
        .collect();
    let cfg = BuildConfig::standard();
    let misses: Vec<(String, Option<f64>)> = declined
        .par_iter()
        .map(|&[x, y, k]| {
            let ln_k = k.ln();
            let (ax, ay, ak) = (around(x, hx), around(y, hy), around(ln_k, hk));
            let (wx, wy, wk) = (weights4(ax, x), weights4(ay, y), weights4(ak, ln_k));
            // g = ln(F - 1), as the tables interpolate it
            let mut g = Some(0.0);
            for (c, &lk) in ak.iter().enumerate() {
                let law = CrackLaw::new(lk.exp()).unwrap();
                for (b, &yy) in ay.iter().enumerate() {
                    for (a, &xx) in ax.iter().enumerate() {
                        let f = node(&cfg, &law, xx, yy).stick();
                        g = g
                            .zip(f)
                            .map(|(g, f)| g + wx[a] * wy[b] * wk[c] * (f - 1.0).ln());
                    }
                }
            }
            let reference = node(&cfg, &CrackLaw::new(k).unwrap(), x, y).stick();
            let miss = g
                .zip(reference)
                .map(|(g, f)| ((1.0 + g.exp()) / f - 1.0).abs());
            let line = format!(
                "{x:.4} {y:.4} {k:.5} F {} miss {}",
                reference.map_or("-".into(), |f| format!("{f:.3}")),
                miss.map_or("-".into(), |m| format!("{m:.1e}"))
            );
            (line, miss)
        })
        .collect();
    let (with, tight, loose) = tally(&misses);
    println!(
        "lattice dx = {hx}, dy = {hy:.5}, d ln k = {hk:.5}: of {} declined points, {with} with every node bouncing; within 2e-6: {tight}, within 1e-5: {loose}",
        declined.len()
    );
}
