//! How accurate are the searches where the master tables decline? At the points of
//! `table_accuracy`'s draw that the tables decline (`TABLE_SEED`, default 2026; `TABLE_N`
//! points, default 2e4), three searches of both thresholds: the default search (what
//! `method="search"` runs: collisions at rtol 1e-8, brackets of 1e-6), a node of the tables'
//! build (collisions at rtol 1e-10, brackets of 1e-8) and a converged one (BDF at rtol 1e-12,
//! atol 1e-15, brackets of 1e-10; BDF at 1e-13 moved it by at most 9e-7 at five points of the
//! second kind). Each point is told apart by its kind of bouncing (first: a window of double
//! collisions below V_stick, F_on < F; second: none, F_on = F); the misses of the default search
//! and of the node against the converged search are printed, then their largest and median by
//! kind (`docs/performance.md`, "What is left" (15)). A probe: nothing here is vouched for.
//!
//! ```sh
//! cargo run --release -p thresholds --example second_kind_accuracy
//! TABLE_SEED=7 TABLE_N=100000 cargo run --release -p thresholds --example second_kind_accuracy
//! cargo run --release -p thresholds --example second_kind_accuracy -- band 400
//! ```
//! With `band N`: N random points of the band around the kink where the tables give F, each
//! against the converged search (how many of the second kind: the tables should give none).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use rayon::prelude::*;
use thresholds::master::build::{default_search, node, BuildConfig, Point};
use thresholds::{CrackLaw, MasterTables};

#[allow(dead_code)]
#[path = "common/domain.rs"]
mod domain;

/// `(F, F_on)` of a search (`F` NaN where nothing bounces below its limit).
fn ratios(p: Point) -> Option<(f64, f64)> {
    match p {
        Point::Bounce { f_stick, f_onset } => Some((f_stick, f_onset)),
        Point::OnsetOnly { f_onset } => Some((f64::NAN, f_onset)),
        _ => None,
    }
}

/// The largest and the median of `v` (NaN-free), `(0, 0)` if empty.
fn max_median(mut v: Vec<f64>) -> (f64, f64) {
    v.sort_by(f64::total_cmp);
    (
        v.last().copied().unwrap_or(0.0),
        v.get(v.len() / 2).copied().unwrap_or(0.0),
    )
}

/// Where the tables answer with a value in the band of the second kind: `n` random points of x
/// -1 to 1.5, y -6 to -3.3, k log-uniform 0.005-0.05 (f_max 1000) at which the tables give F,
/// each against the converged search: how many are of the second kind, and the largest miss.
fn band(n: usize, converged: &BuildConfig) {
    let tables = MasterTables::standard();
    let mut rng = domain::Rng(11);
    let points: Vec<([f64; 3], f64)> = std::iter::repeat_with(|| {
        let (x, y) = (-1.0 + 2.5 * rng.next(), -6.0 + 2.7 * rng.next());
        [x, y, rng.log_uniform(0.005, 0.05)]
    })
    .filter_map(|[x, y, k]| {
        let f = tables.ratios_at(x, y, k, 1000.0)?.v_stick?;
        Some(([x, y, k], f))
    })
    .take(n)
    .collect();
    let rows: Vec<(bool, f64)> = points
        .par_iter()
        .filter_map(|&([x, y, k], f)| {
            let (fc, oc) = ratios(node(converged, &CrackLaw::new(k).unwrap(), x, y))?;
            Some(((oc - fc).abs() <= 1e-9 * fc, (f / fc - 1.0).abs()))
        })
        .collect();
    let second = rows.iter().filter(|r| r.0).count();
    let worst = rows.iter().map(|r| r.1).fold(0.0, f64::max);
    println!(
        "band: the tables give F at {} points; against the converged search {second} of the second kind, the largest miss {worst:.1e}",
        rows.len()
    );
}

fn main() {
    let converged = BuildConfig::converged();
    if let Some(n) = std::env::args()
        .nth(2)
        .filter(|_| std::env::args().nth(1).as_deref() == Some("band"))
    {
        return band(n.parse().unwrap(), &converged);
    }
    let tables = MasterTables::standard();
    let points = domain::declined_draw(tables);
    let cfg = BuildConfig::standard();
    // per point: its kind (true: the second) and the misses [default F, default F_on, node F,
    // node F_on] against the converged search (NaN where a ratio has no value)
    let rows: Vec<Option<(bool, [f64; 4])>> = points
        .par_iter()
        .map(|&[x, y, k]| {
            let law = CrackLaw::new(k).unwrap();
            let (fc, oc) = ratios(node(&converged, &law, x, y))?;
            let (fd, od) = ratios(default_search(&cfg, &law, x, y))?;
            let (fn_, on) = ratios(node(&cfg, &law, x, y))?;
            let second = (oc - fc).abs() <= 1e-9 * fc;
            let miss = [fd / fc - 1.0, od / oc - 1.0, fn_ / fc - 1.0, on / oc - 1.0];
            println!(
                "{x:.9} {y:.9} {k:.9} {} F {fc:.6} F_on {oc:.6}: default {:+.1e} {:+.1e}, node {:+.1e} {:+.1e}",
                if second { "second" } else { "first " },
                miss[0],
                miss[1],
                miss[2],
                miss[3]
            );
            Some((second, miss))
        })
        .collect();
    println!(
        "{} points declined; {} without both converged ratios",
        points.len(),
        rows.iter().filter(|r| r.is_none()).count()
    );
    for (second, name) in [(false, "first kind"), (true, "second kind")] {
        let of: Vec<[f64; 4]> = rows
            .iter()
            .flatten()
            .filter(|r| r.0 == second)
            .map(|r| r.1)
            .collect();
        let stat = |j: usize| {
            max_median(
                of.iter()
                    .map(|m| m[j].abs())
                    .filter(|m| m.is_finite())
                    .collect(),
            )
        };
        let (d, dn, o) = (stat(0), stat(2), stat(1));
        println!(
            "{name}: {} points; |default - converged| F: max {:.1e}, median {:.1e}; F_on: max {:.1e}; |node - converged| F: max {:.1e}, median {:.1e}",
            of.len(), d.0, d.1, o.0, dn.0, dn.1
        );
    }
}
