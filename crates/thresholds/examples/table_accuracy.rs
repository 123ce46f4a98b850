//! The master tables over the whole domain of the "Instant everywhere" issue: how many random
//! points they answer, how fast, and how close to the exact search (`docs/performance.md`,
//! "Master tables").
//!
//! ```sh
//! cargo run --release -p thresholds --example table_accuracy -- 20000 2000
//! cargo run --release -p thresholds --example table_accuracy -- 20000 2000 answered
//! ```
//! With `answered`, k is drawn from what the committed tables answer (log-uniform over their
//! range once the k checks cover it, else one of the tables' own k), to measure the tables
//! where they exist; without it, the tables' coverage of the whole k range 0.005-0.05 is
//! counted first (without searching the points they decline); with `TABLE_DECLINED=1` in the
//! environment each declined point is printed to stderr (`D x y k x_s` and where it lies);
//! `TABLE_SEED=n` draws other points (2026 by default, the draw of the numbers quoted).
//! Each point draws gamma_SV (0.01-0.3 J/m^2), E (0.5-200 GPa), the density (500-5000 kg/m^3),
//! the reduced radius R (5 nm - 1 cm) and k (0.005-0.05) log-uniformly, nu (0.1-0.45)
//! uniformly, two identical spheres (R1 = 2R) or a sphere on a wall (R1 = R), and T_vis
//! log-uniformly from 1e-16 s to 1e-3 s (beyond the cliff for every grain). The first number
//! of points is answered with the default method (the tables, the search where they decline);
//! on the second number of them (a sample), the tables' answers are compared with the exact
//! search: both thresholds, and the "no bouncing" verdicts.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use rayon::prelude::*;
use std::time::Instant;
use thresholds::{
    sticking_thresholds, CrackLaw, MasterTables, SearchOptions, StickingThresholds, ThresholdMethod,
};

// (shared with tests/master_table.rs, which reads the fields this example does not)
#[allow(dead_code)]
#[path = "common/domain.rs"]
mod domain;

use domain::{draw, Point, Rng};

fn percentile(sorted: &[f64], p: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    sorted[((sorted.len() - 1) as f64 * p).round() as usize]
}

fn main() {
    let mut args = std::env::args().skip(1);
    let n: usize = args.next().map_or(20000, |s| s.parse().unwrap());
    let sample: usize = args.next().map_or(2000, |s| s.parse().unwrap());
    let answered = args.next().as_deref() == Some("answered");
    // the draw's seed: that of the numbers in docs/performance.md unless TABLE_SEED says another
    let seed = std::env::var("TABLE_SEED").map_or(2026, |s| s.parse().unwrap());
    let mut rng = Rng(seed);
    let points: Vec<Point> = (0..n).map(|_| draw(&mut rng, answered)).collect();
    if !answered {
        // coverage of the whole domain, without searching what the tables decline
        let tables = MasterTables::standard();
        let start = Instant::now();
        // what the tables decline, by where it lies: k outside the tables, below their lowest
        // row (y < Y_LOW), next to the kink of the end curves (where the cliff changes regime),
        // or by the distance to the cliff x_s (bins of one decade in x = log10 c_D)
        const Y_LOW: f64 = -4.5;
        let mut declined = std::collections::BTreeMap::<String, usize>::new();
        let covered = points
            .iter()
            .filter(|p| {
                let d = p.contact.dimensionless(p.t_vis);
                let jkr = p.contact.v_stick_jkr();
                let f_max = SearchOptions::default().v_max_for(jkr) / jkr;
                let answered = tables.ratios(d.c_d, d.c_a, p.k, f_max).is_some();
                if !answered {
                    let (x, y) = (d.c_d.log10(), (d.c_d * d.c_a).log10());
                    let end = tables.ends().and_then(|e| e.at(y, p.k));
                    let ks = tables.table_k();
                    let outside = p.k < ks[0] || p.k > ks[ks.len() - 1];
                    let key = match end {
                        _ if outside => "k outside the tables".to_string(),
                        _ if y < Y_LOW => format!("y < {Y_LOW}"),
                        Some(e) => format!(
                            "{} the cliff, |x - x_s| in [1e{1:.0}, 1e{2:.0})",
                            if x < e.x_s { "below" } else { "beyond" },
                            (e.x_s - x).abs().log10().floor(),
                            (e.x_s - x).abs().log10().floor() + 1.0
                        ),
                        None => "no end curve (next to the kink of the cliff)".to_string(),
                    };
                    if std::env::var_os("TABLE_DECLINED").is_some() {
                        eprintln!(
                            "D {x:.6} {y:.6} {:.6} {} {}",
                            p.k,
                            end.map_or(f64::NAN, |e| e.x_s),
                            key
                        );
                    }
                    *declined.entry(key).or_default() += 1;
                }
                answered
            })
            .count();
        println!(
            "coverage: the tables answer {covered} of {n} points of the whole domain ({:.3} %), k 0.005-0.05 ({:.2} s, one thread); committed tables at k = {:?}, k checks: {}",
            100.0 * covered as f64 / n as f64,
            start.elapsed().as_secs_f64(),
            tables.table_k(),
            tables.k_checked()
        );
        for (key, count) in &declined {
            println!("  declined, {key}: {count}");
        }
        return;
    }
    let laws: Vec<CrackLaw> = points.iter().map(|p| CrackLaw::new(p.k).unwrap()).collect();
    let start = Instant::now();
    let answers: Vec<Option<StickingThresholds>> = points
        .par_iter()
        .zip(&laws)
        .map(|(p, law)| {
            sticking_thresholds(&p.contact, law, p.t_vis, &SearchOptions::default()).ok()
        })
        .collect();
    let elapsed = start.elapsed().as_secs_f64();
    let by_table = answers
        .iter()
        .filter(|a| a.is_some_and(|a| a.method == ThresholdMethod::Table))
        .count();
    let refused = answers.iter().filter(|a| a.is_none()).count();
    let no_bounce = answers
        .iter()
        .filter(|a| a.is_some_and(|a| a.method == ThresholdMethod::Table && a.v_stick.is_none()))
        .count();
    println!(
        "{n} points in {elapsed:.2} s with the default method: the tables answered {by_table} ({:.3} %, {no_bounce} of them 'no bouncing'), the search {} , refused or failed {refused}",
        100.0 * by_table as f64 / n as f64,
        n - by_table - refused
    );
    // the sample: the first `sample` points the tables answered, against the exact search
    let compared: Vec<(usize, Option<StickingThresholds>)> = answers
        .iter()
        .enumerate()
        .filter(|(_, a)| a.is_some_and(|a| a.method == ThresholdMethod::Table))
        .take(sample)
        .map(|(i, _)| i)
        .collect::<Vec<_>>()
        .par_iter()
        .map(|&i| {
            let p = &points[i];
            (
                i,
                sticking_thresholds(&p.contact, &laws[i], p.t_vis, &SearchOptions::exact()).ok(),
            )
        })
        .collect();
    let (mut d_stick, mut d_onset) = (Vec::new(), Vec::new());
    let (mut verdicts, mut verdicts_differ, mut failed) = (0, 0, 0);
    let mut worst = (0.0, String::new());
    for (i, s) in &compared {
        let Some(s) = s else {
            failed += 1;
            continue;
        };
        let t = answers[*i].unwrap();
        let mut rel = |a: Option<f64>, b: Option<f64>, into: &mut Vec<f64>| match (a, b) {
            (Some(a), Some(b)) => {
                into.push((a / b - 1.0).abs());
                (a / b - 1.0).abs()
            }
            (None, None) => {
                verdicts += 1;
                0.0
            }
            _ => {
                verdicts_differ += 1;
                f64::INFINITY
            }
        };
        let e = rel(t.v_stick, s.v_stick, &mut d_stick).max(rel(
            t.v_double_onset,
            s.v_double_onset,
            &mut d_onset,
        ));
        if e > worst.0 {
            let d = points[*i].contact.dimensionless(points[*i].t_vis);
            worst = (
                e,
                format!(
                    "k = {:.5}, x = {:.4}, y = {:.4}: table {:?} / {:?}, search {:?} / {:?}",
                    points[*i].k,
                    d.c_d.log10(),
                    (d.c_d * d.c_a).log10(),
                    t.v_stick,
                    t.v_double_onset,
                    s.v_stick,
                    s.v_double_onset
                ),
            );
        }
    }
    d_stick.sort_by(f64::total_cmp);
    d_onset.sort_by(f64::total_cmp);
    println!(
        "sample of {}: the search refused or failed at {failed}; 'none below v_max' verdicts: {verdicts} the same, {verdicts_differ} different",
        compared.len()
    );
    for (name, d) in [("V_stick", &d_stick), ("V_double_onset", &d_onset)] {
        println!(
            "{name} ({} values): median {:.1e}, 90 % {:.1e}, 99 % {:.1e}, 99.9 % {:.1e}, max {:.1e}",
            d.len(),
            percentile(d, 0.5),
            percentile(d, 0.9),
            percentile(d, 0.99),
            percentile(d, 0.999),
            d.last().copied().unwrap_or(f64::NAN)
        );
    }
    println!("largest difference {:.1e} at {}", worst.0, worst.1);
}
