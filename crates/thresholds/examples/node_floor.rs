//! Is the nodes' floor (`master::floor`) below the threshold wherever it is high enough to
//! answer? At random points where the floor of both ratios exceeds `floor_min` (and is at most
//! `floor_max`, if given: above 9000 a floor is mostly a row's level beyond its end), the reference
//! search of the nodes at the point against the floor: a floor above its F or F_on (by more
//! than 1e-6) is a failure. (Not the default search: beyond the cliff, at F near F_TOP, it
//! finds spurious bouncing now and then, e.g. F = 9607 at x = 2.281, y = -5.212, k = 0.033,
//! where the reference search finds none up to 2e4.) Two draws: the box around the kink
//! where the interpolation declines most (x -1.5 to 2.3, y -5.6 to -3, k log-uniform
//! 0.005-0.05), and the whole domain of `table_accuracy` (its random materials and sizes).
//! Also counts, of the points the interpolation declines in `table_accuracy`'s draw, those the
//! floor answers ("nothing below v_max") and whether the default search agrees (`docs/performance.md`,
//! "What is left").
//!
//! ```sh
//! cargo run --release -p thresholds --example node_floor -- 400 500   # points a draw, floor_min
//! cargo run --release -p thresholds --example node_floor -- 400 500 9000   # and floor_max
//! ```
#![allow(clippy::unwrap_used, clippy::expect_used)]

use rayon::prelude::*;
use thresholds::master::build::{default_search, node, BuildConfig, Point};
use thresholds::{CrackLaw, MasterTables};

#[allow(dead_code)]
#[path = "common/domain.rs"]
mod domain;

use domain::{draw, Rng};

/// (F, F_on) at (x, y, k) from the reference search of the nodes (`reference`) or the default
/// search, infinite where nothing bounces (double-collides) below twice F_TOP.
fn search(x: f64, y: f64, k: f64, reference: bool) -> (f64, f64) {
    let cfg = BuildConfig::standard();
    let law = CrackLaw::new(k).unwrap();
    let point = if reference {
        node(&cfg, &law, x, y)
    } else {
        default_search(&cfg, &law, x, y)
    };
    match point {
        Point::Failed => (f64::NAN, f64::NAN),
        p => (
            p.ratio(0).unwrap_or(f64::INFINITY),
            p.ratio(1).unwrap_or(f64::INFINITY),
        ),
    }
}

/// How many of `points` (x, y, k) have a floor above the search's ratios.
fn failures(points: &[[f64; 3]], label: &str) -> usize {
    let tables = MasterTables::standard();
    let bad: Vec<String> = points
        .par_iter()
        .filter_map(|&[x, y, k]| {
            let [f, f_on] = tables.node_floor(x, y, k);
            let (s, o) = search(x, y, k, true);
            let above = |floor: Option<f64>, r: f64| {
                floor.is_some_and(|l| r.is_nan() || l > r * (1.0 + 1e-6))
            };
            (above(f, s) || above(f_on, o))
                .then(|| format!("  {x:.5} {y:.5} {k:.5}: floor {f:?} {f_on:?}, search {s} {o}"))
        })
        .collect();
    // a floor above 9000 is mostly a row's level beyond its end, not a node's ratio
    let from_nodes = points
        .iter()
        .filter(|&&[x, y, k]| {
            let [f, f_on] = tables.node_floor(x, y, k);
            f.zip(f_on).is_some_and(|(f, o)| f.max(o) <= 9000.0)
        })
        .count();
    println!(
        "{label}: {} points ({from_nodes} with both floors from nodes, at most 9000), the floor above the search at {}",
        points.len(),
        bad.len()
    );
    for b in &bad {
        println!("{b}");
    }
    bad.len()
}

fn main() {
    let mut args = std::env::args().skip(1);
    let n: usize = args.next().map_or(400, |s| s.parse().unwrap());
    let floor_min: f64 = args.next().map_or(500.0, |s| s.parse().unwrap());
    let floor_max: f64 = args.next().map_or(f64::INFINITY, |s| s.parse().unwrap());
    let tables = MasterTables::standard();
    let high = |x: f64, y: f64, k: f64| {
        let [f, f_on] = tables.node_floor(x, y, k);
        f.zip(f_on)
            .is_some_and(|(f, o)| f.min(o) >= floor_min && f.max(o) <= floor_max)
    };
    // the box around the kink
    let mut rng = Rng(12345);
    let boxed: Vec<[f64; 3]> = std::iter::repeat_with(|| {
        let x = -1.5 + 3.8 * rng.next();
        let y = -5.6 + 2.6 * rng.next();
        let k = 0.005 * 10f64.powf(rng.next());
        [x, y, k]
    })
    .filter(|&[x, y, k]| high(x, y, k))
    .take(n)
    .collect();
    let mut bad = failures(&boxed, "box x -1.5..2.3, y -5.6..-3");
    // the whole domain
    let mut rng = Rng(2027);
    let whole: Vec<[f64; 3]> = std::iter::repeat_with(|| {
        let p = draw(&mut rng, false);
        let (x, y, _) = p.table_coordinates();
        [x, y, p.k]
    })
    .take(200 * n)
    .filter(|&[x, y, k]| high(x, y, k))
    .take(n)
    .collect();
    bad += failures(&whole, "the whole domain");
    // table_accuracy's draw: what the floor answers where the interpolation declines
    let mut rng = Rng(2026);
    let verdicts: Vec<bool> = (0..20000)
        .map(|_| draw(&mut rng, false))
        .filter_map(|p| {
            let (x, y, f_max) = p.table_coordinates();
            // declined by the interpolation, answered by the floor
            let floor = tables.interpolated_at(x, y, p.k, f_max).is_none()
                && tables.ratios_at(x, y, p.k, f_max).is_some();
            floor.then_some([x, y, p.k, f_max])
        })
        .collect::<Vec<_>>()
        .par_iter()
        .map(|&[x, y, k, f_max]| {
            let (s, o) = search(x, y, k, false);
            s > f_max && o > f_max
        })
        .collect();
    println!(
        "table_accuracy's draw (seed 2026): the floor answers {} of the points the interpolation declines, {} of them as the default search ('nothing below v_max')",
        verdicts.len(),
        verdicts.iter().filter(|&&v| v).count()
    );
    assert_eq!(bad, 0, "the floor is above the search somewhere");
}
