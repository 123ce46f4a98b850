//! The master table against the exact search at random points over the whole domain of the
//! "Instant V_stick" issue: `docs/performance.md`, "Master table".
//!
//! ```sh
//! cargo run --release -p thresholds --example table_accuracy -- 2000
//! ```
//! Each point draws gamma_SV (0.01-0.3 J/m^2), E (0.5-200 GPa), the density (500-5000 kg/m^3)
//! and the reduced radius R (5 nm - 1 cm) log-uniformly, nu (0.1-0.45) uniformly, two identical
//! spheres (R1 = 2R) or a sphere on a wall (R1 = R), k = 0.01 or 0.02, and T_vis log-uniformly
//! from 1e-16 s to 1e-3 s (beyond the cliff for every grain), until the table has answered at
//! the given number of points. There its V_stick and V_double_onset are compared with the
//! default exact search; prints how many points were drawn, how many the search refused or
//! failed at, and the percentiles of the relative differences.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use thresholds::{
    sticking_thresholds, Contact, CrackLaw, Geometry, Material, SearchOptions, ThresholdMethod,
};

/// A small deterministic generator (SplitMix64), so that a run is repeatable.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        (z ^ (z >> 31)) as f64 / u64::MAX as f64
    }
    fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo * (hi / lo).powf(self.next())
    }
}

fn percentile(sorted: &[f64], p: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    sorted[((sorted.len() - 1) as f64 * p).round() as usize]
}

fn main() {
    let n: usize = std::env::args().nth(1).map_or(2000, |s| s.parse().unwrap());
    let laws = [CrackLaw::new(0.01).unwrap(), CrackLaw::new(0.02).unwrap()];
    let mut rng = Rng(2026);
    let (mut answered, mut failed, mut wall_points) = (0, 0, 0);
    let (mut d_stick, mut d_onset) = (Vec::new(), Vec::new());
    let mut worst = (0.0, String::new());
    let mut drawn = 0;
    while answered < n {
        drawn += 1;
        let m = Material {
            gamma_sv: rng.log_uniform(0.01, 0.3),
            young: rng.log_uniform(0.5e9, 200e9),
            poisson: 0.1 + 0.35 * rng.next(),
            density: rng.log_uniform(500.0, 5000.0),
        };
        let r = rng.log_uniform(5e-9, 1e-2);
        let wall = rng.next() < 0.5;
        let geometry = if wall {
            Geometry::wall(r)
        } else {
            Geometry::identical(2.0 * r)
        };
        let law = &laws[usize::from(rng.next() < 0.5)];
        let t_vis = rng.log_uniform(1e-16, 1e-3);
        let c = Contact::new(m, geometry).unwrap();
        let table = SearchOptions {
            method: ThresholdMethod::Table,
            ..SearchOptions::default()
        };
        let from_table = sticking_thresholds(&c, law, t_vis, &table).ok();
        let Some(t) = from_table.filter(|t| t.method == ThresholdMethod::Table) else {
            continue;
        };
        answered += 1;
        wall_points += usize::from(wall);
        let Ok(s) = sticking_thresholds(&c, law, t_vis, &SearchOptions::default()) else {
            failed += 1;
            continue;
        };
        let rel = |a: Option<f64>, b: Option<f64>| match (a, b) {
            (Some(a), Some(b)) => (a / b - 1.0).abs(),
            (None, None) => 0.0,
            _ => f64::INFINITY,
        };
        let (ds, d_o) = (
            rel(t.v_stick, s.v_stick),
            rel(t.v_double_onset, s.v_double_onset),
        );
        if ds.max(d_o) > worst.0 {
            let d = c.dimensionless(t_vis);
            worst = (
                ds.max(d_o),
                format!(
                    "k = {}, x = {:.3}, y = {:.3}: table {:?} / {:?}, search {:?} / {:?}",
                    law.k(),
                    d.c_d.log10(),
                    (d.c_d * d.c_a).log10(),
                    t.v_stick,
                    t.v_double_onset,
                    s.v_stick,
                    s.v_double_onset
                ),
            );
        }
        d_stick.push(ds);
        d_onset.push(d_o);
    }
    d_stick.sort_by(f64::total_cmp);
    d_onset.sort_by(f64::total_cmp);
    println!(
        "{drawn} points drawn: the table answered {answered} ({wall_points} on a wall), the search refused or failed at {failed} of those"
    );
    for (name, d) in [("V_stick", &d_stick), ("V_double_onset", &d_onset)] {
        println!(
            "{name}: median {:.1e}, 90 % {:.1e}, 99 % {:.1e}, 99.9 % {:.1e}, max {:.1e}",
            percentile(d, 0.5),
            percentile(d, 0.9),
            percentile(d, 0.99),
            percentile(d, 0.999),
            d.last().copied().unwrap_or(f64::NAN)
        );
    }
    println!("largest difference {:.1e} at {}", worst.0, worst.1);
}
