//! Would stencils of one kind of bouncing answer where the two kinds meet? At the points of
//! `table_accuracy`'s draw (`TABLE_SEED`, default 2026; `TABLE_N` points, default 2e4) the
//! tables still decline, each kind as a surface of its
//! own, read off the tables' nodes of that kind only: in each table of the k stencil, the four
//! rows nearest y whose four nodes around x (in u = ln(x_s - x), shifted towards the kind by
//! up to `shift` nodes) are all of that kind (first: F_on < F; second: F_on = F), the cubic in
//! u on each, the cubic in y through them (y at most `reach` row steps outside them), then the
//! polynomial in ln k through the tables as the answer takes it; F is the smaller of the two
//! kinds where both have a value. Against the reference search at the point
//! (`docs/performance.md`, "What is left" (7)). A probe: nothing here is vouched for.
//!
//! ```sh
//! cargo run --release -p thresholds --example kind_stencil -- 0 0.5   # shift, reach
//! cargo run --release -p thresholds --example kind_stencil -- 0 0.5 2000   # random band points
//! ```
//! With a third number, that many random points of the band around the kink (x -1.6 to 2.4,
//! y -6 to -3, k log-uniform 0.005-0.05) that the tables decline at f_max = 1000 instead.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use rayon::prelude::*;
use thresholds::master::binary::{Row, Table};
use thresholds::master::build::{node, BuildConfig, Point};
use thresholds::master::interp::lagrange_weight;
use thresholds::master::{K_STENCIL, K_STENCIL_EDGE};
use thresholds::{CrackLaw, MasterTables};

#[allow(dead_code)]
#[path = "common/domain.rs"]
mod domain;
#[path = "common/misses.rs"]
mod misses;

/// Whether body node `q` of `r` is of the first kind (a window of double collisions: F_on < F).
fn first_kind(r: &Row, q: usize) -> bool {
    r.body.g[1][q] < r.body.g[0][q] - 1e-12
}

/// g = ln(F - 1) on row `r` at `x` from the four nodes around it if all are of `kind` (true:
/// the first), shifted by up to `shift` nodes towards it; `None` otherwise.
fn row_g(r: &Row, x: f64, shift: usize, kind: bool) -> Option<f64> {
    let (u, g) = (&r.body.u, &r.body.g[0]);
    let n = u.len();
    let u_x = (r.x_s - x).ln();
    if !(u_x >= u[0] && u_x <= u[n - 1]) || n < 4 {
        return None;
    }
    let q = u.partition_point(|&v| v <= u_x).clamp(1, n - 1) - 1;
    (0..=shift).find_map(|d| {
        // the first kind lies towards larger u (smaller x), the second towards smaller u
        let at = if kind { q + d } else { q.saturating_sub(d) };
        let s = at.saturating_sub(1).min(n - 4);
        (s..s + 4).all(|i| first_kind(r, i) == kind).then(|| {
            (0..4)
                .map(|j| lagrange_weight(&u[s..s + 4], j, u_x) * g[s + j])
                .sum()
        })
    })
}

/// g at (x, y) in table `t` from the four rows nearest y that read x with `kind`, y at most
/// `reach` row steps outside them.
fn table_g(t: &Table, x: f64, y: f64, shift: usize, kind: bool, reach: f64) -> Option<f64> {
    let mut near: Vec<usize> = (0..t.rows.len()).collect();
    near.sort_by(|&a, &b| (t.ys[a] - y).abs().total_cmp(&(t.ys[b] - y).abs()));
    let rows: Vec<(f64, f64)> = near
        .iter()
        .filter_map(|&i| row_g(&t.rows[i], x, shift, kind).map(|g| (t.ys[i], g)))
        .take(4)
        .collect();
    if rows.len() < 4 {
        return None;
    }
    let ys: Vec<f64> = rows.iter().map(|r| r.0).collect();
    let (lo, hi) = ys
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), &v| (a.min(v), b.max(v)));
    let step = (hi - lo) / 3.0;
    if y < lo - reach * step || y > hi + reach * step {
        return None;
    }
    Some((0..4).map(|j| lagrange_weight(&ys, j, y) * rows[j].1).sum())
}

fn main() {
    let mut args = std::env::args().skip(1);
    let shift: usize = args.next().map_or(0, |s| s.parse().unwrap());
    let reach: f64 = args.next().map_or(0.5, |s| s.parse().unwrap());
    let tables = MasterTables::standard();
    let ks = tables.table_k().to_vec();
    let box_points: usize = args.next().map_or(0, |s| s.parse().unwrap());
    let points: Vec<[f64; 3]> = if box_points == 0 {
        domain::declined_draw(tables)
    } else {
        // random points of the band around the kink that the tables decline (f_max 1000)
        let mut rng = domain::Rng(2026);
        std::iter::repeat_with(|| {
            let x = -1.6 + 4.0 * rng.next();
            let y = -6.0 + 3.0 * rng.next();
            [x, y, rng.log_uniform(0.005, 0.05)]
        })
        .filter(|&[x, y, k]| tables.ratios_at(x, y, k, 1000.0).is_none())
        .take(box_points)
        .collect()
    };
    let cfg = BuildConfig::standard();
    let lines: Vec<(String, Option<f64>)> = points
        .par_iter()
        .map(|&[x, y, k]| {
            let Point::Bounce {
                f_stick: f,
                f_onset,
            } = node(&cfg, &CrackLaw::new(k).unwrap(), x, y)
            else {
                return (format!("{x:.4} {y:.4} {k:.5}: no F"), None);
            };
            let kind = if f_onset < f * (1.0 - 1e-9) {
                "first"
            } else {
                "second"
            };
            // the k stencil as the answer takes it
            let n = ks.len();
            let i = (1..n).find(|&i| ks[i] > k).map_or(n - 2, |i| i - 1);
            let width = if i == 0 || i == n - 2 {
                K_STENCIL_EDGE
            } else {
                K_STENCIL
            };
            let s = (i + 1).saturating_sub(width / 2).min(n - width);
            let lk: Vec<f64> = ks[s..s + width].iter().map(|k| k.ln()).collect();
            // each kind as its own surface: its tables' values, the polynomial in ln k
            let of_kind = |first: bool| -> Option<f64> {
                let g: Option<f64> = (0..width)
                    .map(|j| {
                        let t = tables.table(s + j)?;
                        Some(
                            lagrange_weight(&lk, j, k.ln())
                                * table_g(t, x, y, shift, first, reach)?,
                        )
                    })
                    .sum();
                g.map(|g| 1.0 + g.exp())
            };
            let (f1, f2) = (of_kind(true), of_kind(false));
            let est = match (f1, f2) {
                (Some(a), Some(b)) => Some(a.min(b)),
                (a, b) => a.or(b),
            };
            let miss = est.map(|e| (e / f - 1.0).abs());
            (
                format!(
                    "{x:.4} {y:.4} {k:.5}: {kind} F {f:.2}; F1 {f1:?} F2 {f2:?}; miss {}",
                    miss.map_or("-".into(), |m| format!("{m:.1e}"))
                ),
                miss,
            )
        })
        .collect();
    let (with, tight, loose) = misses::tally(&lines);
    println!(
        "shift {shift}, reach {reach}: {} points declined, {with} with an estimate; within 2e-6: {tight}, within 1e-5: {loose}",
        lines.len()
    );
}
